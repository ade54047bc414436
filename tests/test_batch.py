"""minkowski2d.batch: the Ragged representation and minkowski_sum_many."""

from __future__ import annotations

import pickle
import sys

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import minkowski2d as mk
from minkowski2d.errors import EmptyGeometryError, NonFiniteError, NotConvexError, ShapeError

from .strategies import convex_float, convex_int

SETTINGS = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@SETTINGS
@given(
    st.lists(st.tuples(convex_int(max_size=15), convex_int(max_size=15)), min_size=1, max_size=20)
)
def test_pairwise_identical_to_single(pairs):
    As = [np.array(a) for a, _ in pairs]
    Bs = [np.array(b) for _, b in pairs]
    r = mk.minkowski_sum_many(As, Bs)
    assert len(r) == len(pairs)
    for k, (a, b) in enumerate(pairs):
        single = mk.minkowski_sum(a, b)
        assert r[k].tolist() == single.tolist()
        assert r[k].dtype == single.dtype


@SETTINGS
@given(
    st.lists(
        st.tuples(convex_float(max_size=15), convex_float(max_size=15)), min_size=1, max_size=10
    )
)
def test_pairwise_floats_identical_to_single(pairs):
    r = mk.minkowski_sum_many([np.array(a) for a, _ in pairs], [np.array(b) for _, b in pairs])
    for k, (a, b) in enumerate(pairs):
        assert r[k].tolist() == mk.minkowski_sum(a, b).tolist()


@SETTINGS
@given(convex_int(max_size=15), st.lists(convex_int(max_size=15), min_size=1, max_size=10))
def test_broadcast_both_sides(one, many):
    arrs = [np.array(m) for m in many]
    left = mk.minkowski_sum_many(np.array(one), arrs)
    right = mk.minkowski_sum_many(arrs, one)
    for k, m in enumerate(many):
        expect = mk.minkowski_sum(one, m).tolist()
        assert left[k].tolist() == expect
        assert right[k].tolist() == expect


def test_ragged_roundtrips():
    polys = [np.array([[0, 0], [2, 0], [0, 2]]), np.array([[5, 5]]), np.array([[0, 0], [1, 1]])]
    r = mk.Ragged.from_list(polys)
    assert r.offsets.tolist() == [0, 3, 4, 6]
    assert r.lengths.tolist() == [3, 1, 2]
    assert [a.tolist() for a in r.to_list()] == [p.tolist() for p in polys]
    assert [a.tolist() for a in r] == [p.tolist() for p in polys]
    assert r[-1].tolist() == [[0, 0], [1, 1]]
    g = r.to_shapely()
    assert [x.geom_type for x in g] == ["Polygon", "Point", "LineString"]
    back = mk.Ragged.from_shapely(g)
    assert back.offsets.tolist() == r.offsets.tolist()
    assert np.array_equal(back.coords, r.coords.astype(float))
    with pytest.raises(IndexError):
        r[3]
    assert "3 polygons" in repr(r)


def test_shapely_arrays_as_operands():
    shapely = pytest.importorskip("shapely")
    squares = shapely.box(np.arange(5.0), 0, np.arange(5.0) + 1, 1)
    r = mk.minkowski_sum_many(squares, [(0, 0), (1, 0), (0, 1)])
    # an object array in, an object array of shapely geometries out
    assert isinstance(r, np.ndarray) and r.dtype == object and r.shape == (5,)
    for k in range(5):
        want = mk.minkowski_sum(squares[k], [(0, 0), (1, 0), (0, 1)])
        assert shapely.get_coordinates(r[k])[:-1].tolist() == want.tolist()
    r = mk.minkowski_sum_many(list(squares), [(0, 0), (1, 0), (0, 1)])  # a list: a Ragged
    assert all(p.area > 0 for p in r.to_shapely())


def test_many_large_coordinates_fall_back_exactly():
    big = 1 << 60
    As = [np.array([[0, 0], [big, 0], [0, big]], dtype=np.int64)] * 3
    r = mk.minkowski_sum_many(As, [np.array([[0, 0], [1, 1], [0, 1]])] * 3)
    assert r[2].tolist() == mk.minkowski_sum(As[2], [(0, 0), (1, 1), (0, 1)]).tolist()


def test_errors_name_the_polygon():
    good = np.array([[0, 0], [1, 0], [0, 1]])
    bad = np.array([[0, 0], [4, 0], [4, 4], [2, 1], [0, 4]])
    with pytest.raises(NotConvexError, match=r"^Bs\[1\]: not convex: .*vertex 3"):
        mk.minkowski_sum_many([good, good], [good, bad])
    with pytest.raises(NotConvexError, match=r"^a: not convex"):
        mk.minkowski_sum_many(bad, [good, good])
    with pytest.raises(ShapeError, match="As has 2 polygons but Bs has 1"):
        mk.minkowski_sum_many([good, good], [good])
    with pytest.raises(NonFiniteError, match=r"As\[1\]: vertex 2"):
        mk.minkowski_sum_many([good, np.array([[0, 0], [1, 0], [np.nan, 1.0]])], good)
    with pytest.raises(EmptyGeometryError, match=r"Bs\[0\]"):
        mk.minkowski_sum_many(good, mk.Ragged(np.zeros((0, 2)), np.array([0, 0])))
    with pytest.raises(ShapeError, match="collection of polygons"):
        mk.minkowski_sum_many(good, good)
    with pytest.raises(ShapeError, match="offsets"):
        mk.Ragged(np.zeros((3, 2)), np.array([0, 2]))


def test_empty_batch():
    r = mk.minkowski_sum_many([], [])
    assert len(r) == 0


# --------------------------------------------------------------------------------------
# Ragged as a container: slicing, concat, equality, size, GeoArrow, pickling


def _ragged(n: int = 50, seed: int = 0) -> mk.Ragged:
    rng = np.random.default_rng(seed)
    return mk.Ragged.from_list(
        [rng.integers(-100, 100, (int(rng.integers(1, 9)), 2)) for _ in range(n)]
    )


def test_ragged_slicing_and_fancy_indexing():
    r = _ragged()
    lists = [a.tolist() for a in r]
    for key in (slice(3, 9), slice(None, None, -3), slice(40, 10), [4, 0, 4, -1], np.arange(0)):
        s = r[key]
        assert isinstance(s, mk.Ragged)
        want = [lists[i] for i in np.arange(len(r))[key]]
        assert [a.tolist() for a in s] == want
    mask = r.lengths > 4
    assert [a.tolist() for a in r[mask]] == [x for x, m in zip(lists, mask) if m]
    assert np.shares_memory(r[5:10].coords, r.coords)  # a slice is a view
    with pytest.raises(IndexError):
        r[[0, 50]]
    with pytest.raises(IndexError):
        r[np.ones(3, bool)]


def test_ragged_concat_equality_and_size():
    r = _ragged()
    assert mk.Ragged.concat([r[:20], r[20:20], r[20:]]) == r
    assert r != r[1:] and r != _ragged(seed=1)
    assert (r == "x") is False
    assert mk.Ragged.concat([]) == mk.Ragged.from_list([])
    big = mk.Ragged(np.zeros((800_000, 2)), np.arange(0, 800_001, 4))
    assert sys.getsizeof(big) >= big.coords.nbytes + big.offsets.nbytes  # 12.8 MB + 1.6 MB
    with pytest.raises(TypeError):
        hash(r)
    dask_sizeof = pytest.importorskip("dask.sizeof", reason="dask is not installed (extra 'dask')")
    assert dask_sizeof.sizeof(big) == sys.getsizeof(big) > 14_000_000


def test_ragged_geoarrow_round_trip():
    r = mk.Ragged.from_list([[(0, 0), (3, 0), (3, 1)], [(5, 5), (6, 5), (6, 6), (5, 6)]])
    t, coords, offsets = r.to_ragged_array()
    g = shapely.from_ragged_array(t, coords, offsets)
    assert [x.wkt for x in g] == [x.wkt for x in r.to_shapely()]
    assert shapely.to_ragged_array(g)[1].tolist() == coords.tolist()
    back = mk.Ragged.from_ragged_array(*shapely.to_ragged_array(g))
    assert back == r
    with pytest.raises(mk.errors.NotConvexError, match="holes"):
        mk.Ragged.from_ragged_array(
            *shapely.to_ragged_array([shapely.box(0, 0, 9, 9).difference(shapely.box(1, 1, 2, 2))])
        )


def test_ragged_pickle_is_zero_copy():
    r = _ragged()
    buffers: list = []
    data = pickle.dumps(r, protocol=5, buffer_callback=buffers.append)
    assert len(buffers) == 2 and len(data) < 300  # the arrays travel out of band
    back = pickle.loads(data, buffers=buffers)
    assert back == r and back.coords.dtype == r.coords.dtype
    assert np.shares_memory(back.coords, r.coords)
    for proto in (2, 4, 5):
        assert pickle.loads(pickle.dumps(r[3:7], protocol=proto)) == r[3:7]
