"""Exact polygon checks in the compiled core (polygon.hpp) against a brute-force Fraction
oracle (tests/polygon_oracle.py): random, degenerate and scaled polygons with holes, named
hard cases, the CGAL corpus and the ESICUP parts, and the errors raised."""

from __future__ import annotations

import math

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import minkowski2d as mk
from minkowski2d._core import _ext
from minkowski2d._engine import polygon as _polygon
from minkowski2d._engine.dispatch import Status
from minkowski2d._engine.polygon import Invalid, Rings
from minkowski2d.errors import EmptyGeometryError, NonFiniteError, SelfIntersectionError

from . import polygon_oracle as oracle
from .corpus import corpus_files, requires_corpus
from .strategies import SCALES, diamond_polygon, grid_polygon, holey_polygon, scaled, star_ring


def rings(*polys) -> Rings:
    """Rings from polygons given as lists of rings (lists of points)."""
    coords, ro, po = [], [0], [0]
    for poly in polys:
        for ring in poly:
            coords += [tuple(p) for p in ring]
            ro.append(len(coords))
        po.append(len(ro) - 1)
    c = np.array(coords, dtype=np.float64).reshape(-1, 2)
    return Rings(c, np.array(ro, np.int64), np.array(po, np.int64))


def core_check(*polys, disjoint=False):
    r = rings(*polys)
    return _ext.check_polygons_f(r.coords, r.ring_offsets, r.polygon_offsets, disjoint)


def agrees(*polys) -> bool:
    """Core and oracle agree on the verdict (and the core's reason is one of the oracle's
    kinds); returns the verdict."""
    status, reason, ring, vertex, _, _ = core_check(*polys)
    expected = oracle.problems(list(polys))
    if not expected:
        assert status == Status.OK, (Invalid(reason).name, ring, vertex, expected)
        return True
    assert status == Status.INVALID_POLYGON, expected
    kinds = oracle.REASON_KINDS[Invalid(reason).name]
    assert kinds & expected, (Invalid(reason).name, expected)
    # the ring and vertex exist
    n_rings = sum(len(p) for p in polys)
    assert 0 <= ring < n_rings
    flat = [r for p in polys for r in p]
    assert 0 <= vertex < max(len(flat[ring]), 1)
    return False


SQ = [(0, 0), (10, 0), (10, 10), (0, 10)]


# --------------------------------------------------------------------------------------
# named cases


@pytest.mark.parametrize(
    ("polys", "reason"),
    [
        ([[[(0, 0), (2, 2), (2, 0), (0, 2)]]], "RING_CROSSES"),  # bow-tie
        ([[[(0, 0), (4, 0), (4, 4), (2, 4), (2, 6), (2, 4), (0, 4)]]], "RING_SPIKE|RING_TOUCHES"),
        (
            [[[(0, 0), (2, 0), (2, 2), (2, 0), (4, 0), (4, 4), (0, 4)]]],
            "RING_SPIKE|RING_TOUCHES",
        ),  # slit
        ([[[(0, 0), (4, 0), (4, 4), (2, 0), (0, 4)]]], "RING_TOUCHES"),  # vertex on an edge
        ([[[(0, 0), (4, 0), (2, 2), (4, 4), (0, 4), (2, 2)]]], "RING_TOUCHES"),  # pinched
        (
            [[[(0, 0), (4, 0), (4, 1), (0, 1), (0, 3), (4, 3), (4, 4), (0, 4)]]],
            "RING_OVERLAPS|RING_TOUCHES",
        ),
        ([[[(0, 0), (3, 0), (3, 3), (4, 3), (3, 3), (0, 3)]]], "RING_SPIKE|RING_TOUCHES"),
        ([[[(0, 0), (1, 0), (1, 1), (0, 1), (1, 1)]]], "RING_SPIKE|RING_TOUCHES"),
        ([[[(0, 0), (1, 1), (2, 2)]]], "RING_NO_AREA"),
        ([[[(0, 0), (1, 1), (0, 0), (1, 1)]]], "RING_NO_AREA"),
        ([[[(0, 0), (1, 1), (1, 1), (0, 0)]]], "RING_FEW_VERTICES"),
        ([[SQ, [(2, 2), (12, 2), (12, 4)]]], "RINGS_CROSS"),
        ([[SQ, [(0, 2), (0, 4), (3, 3)]]], "RINGS_OVERLAP"),
        ([[SQ, [(20, 2), (24, 2), (24, 4)]]], "HOLE_OUTSIDE"),
        ([[SQ, [(1, 1), (9, 1), (9, 9), (1, 9)], [(2, 2), (3, 2), (3, 3)]]], "HOLE_IN_HOLE"),
        ([[[(2, 2), (3, 2), (3, 3)], SQ]], "HOLE_OUTSIDE"),  # the hole holds the shell
        # a hole through the shell's corner: crosses it at a shared vertex
        ([[SQ, [(0, 0), (3, -2), (3, 2)]]], "RINGS_CROSS|HOLE_OUTSIDE"),
        # two holes crossing at a shared vertex
        ([[SQ, [(5, 5), (7, 3), (7, 7)], [(5, 5), (7, 5), (8, 9)]]], "RINGS_CROSS"),
    ],
)
def test_invalid_cases(polys, reason):
    status, got, ring, vertex, _, _ = core_check(*polys)
    assert status == Status.INVALID_POLYGON
    assert Invalid(got).name in reason.split("|")
    assert not agrees(*polys)


@pytest.mark.parametrize(
    "polys",
    [
        [[SQ]],
        [[SQ[::-1]]],
        [[[*SQ, SQ[0]]]],  # closing repeat
        [[[(0, 0), (0, 0), (10, 0), (10, 10), (10, 10), (0, 10), (0, 0)]]],  # duplicates
        [[[(0, 0), (5, 0), (10, 0), (10, 5), (10, 10), (0, 10)]]],  # collinear runs
        [[SQ, [(2, 2), (4, 2), (4, 4), (2, 4)]]],
        [[SQ, [(0, 0), (3, 5), (5, 3)]]],  # a hole touching the shell at its vertex
        [[SQ, [(0, 5), (3, 4), (3, 6)]]],  # ... inside the shell's edge
        [[SQ, [(0, 5), (5, 2), (10, 5), (5, 8)]]],  # ... at two points (two parts)
        [[SQ, [(2, 2), (5, 2), (5, 5)], [(5, 5), (8, 5), (8, 8)]]],  # holes touching
        [[SQ, [(2, 2), (5, 2), (5, 5)], [(3, 2), (4, 1), (5, 1)]]],  # in an edge
        [[[(0.0, 0.0), (3e-200, 0.0), (0.0, 3e-200)]]],  # the tiny triangle
        [[[(0.0, 0.0), (1e300, 0.0), (0.0, 1e300)]]],
        [[[(0.0, 0.0), (5e-324, 0.0), (0.0, 5e-324)]]],  # subnormals
        [[[(-1.7e308, -1.7e308), (1.7e308, -1.7e308), (0.0, 1.7e308)]]],
        [[SQ], [[(20, 0), (30, 0), (30, 10)]]],  # a collection
        [[SQ], [[(2, 2), (5, 2), (5, 5)]]],  # overlapping polygons: not checked
    ],
)
def test_valid_cases(polys):
    status, reason, ring, vertex, orient, disconnected = core_check(*polys)
    assert status == Status.OK, (Invalid(reason).name, ring, vertex)
    assert agrees(*polys)
    assert set(orient.tolist()) <= {1, -1}


def test_orientation_and_disconnected_interior():
    _, _, _, _, orient, disc = core_check([SQ, [(2, 2), (2, 4), (4, 4), (4, 2)]])
    assert orient.tolist() == [1, -1] and disc.tolist() == [False]
    _, _, _, _, orient, disc = core_check([SQ[::-1], [(2, 2), (4, 2), (4, 4), (2, 4)]])
    assert orient.tolist() == [-1, 1]
    # one hole touching the shell at two points: two parts
    assert core_check([SQ, [(0, 5), (5, 2), (10, 5), (5, 8)]])[5].tolist() == [True]
    # touching at one point: connected; a ring of touching holes: disconnected
    assert core_check([SQ, [(0, 0), (3, 5), (5, 3)]])[5].tolist() == [False]
    chain = [SQ, [(0, 5), (3, 4), (5, 5), (3, 6)], [(5, 5), (7, 4), (10, 5), (7, 6)]]
    assert core_check(chain)[5].tolist() == [True]
    assert core_check(chain[:2])[5].tolist() == [False]


def test_reported_vertex_counts_duplicates_as_given():
    # the crossing edge starts at the caller's vertex 4 (duplicates and all)
    ring = [(0, 0), (0, 0), (2, 2), (2, 2), (2, 0), (0, 2)]
    status, reason, r, v, _, _ = core_check([ring])
    assert (Invalid(reason).name, r, v) == ("RING_CROSSES", 0, 4)
    # a hole's vertex is counted inside the hole
    status, reason, r, v, _, _ = core_check(
        [SQ, [(2, 2), (4, 2), (4, 4)], [(5, 5), (5, 5), (15, 6), (6, 7)]]
    )
    assert (Invalid(reason).name, r) == ("RINGS_CROSS", 2) and v in (1, 2)


def test_nonfinite_names_ring_and_vertex():
    status, _, r, v, _, _ = core_check([SQ, [(2, 2), (4, 2), (np.nan, 4)]])
    assert (status, r, v) == (Status.NONFINITE, 1, 2)
    with pytest.raises(NonFiniteError) as e:
        _polygon.check(rings([SQ, [(2, 2), (4, 2), (np.inf, 4)]]), "a")
    assert e.value.vertex == 2 and "hole 0, vertex 2" in str(e.value)


def test_disjoint_collections():
    a = [SQ]
    assert core_check(a, [[(2, 2), (5, 2), (5, 5)]], disjoint=True)[0] == Status.INVALID_POLYGON
    assert core_check(a, [[(10, 10), (12, 10), (12, 12)]], disjoint=True)[0] == Status.OK  # touch
    assert core_check(a, [[(10, 0), (12, 0), (12, 10)]], disjoint=True)[0] == Status.OK  # a point
    shared_edge = [[(10, 0), (12, 0), (12, 10), (10, 10)]]
    assert core_check(a, shared_edge, disjoint=True)[0] == Status.INVALID_POLYGON
    # an island in a lake
    lake = [[(-5, -5), (15, -5), (15, 15), (-5, 15)], [(-1, -1), (-1, 11), (11, 11), (11, -1)]]
    assert core_check(lake, a, disjoint=True)[0] == Status.OK
    st_, reason, *_ = core_check(a, [[(2, 2), (5, 2), (5, 5)]], disjoint=True)
    assert Invalid(reason).name == "POLYGONS_OVERLAP"


def test_errors_raised():
    with pytest.raises(
        SelfIntersectionError,
        match=r"^a: not a valid polygon \(the boundary crosses itself at vertex 2\)$",
    ) as e:
        _polygon.check(rings([[(0, 0), (2, 2), (2, 0), (0, 2)]]), "a", hint="fix it")
    assert (e.value.argument, e.value.vertex, e.value.hint) == ("a", 2, "fix it")
    with pytest.raises(SelfIntersectionError, match="a hole is not inside the shell at hole 0"):
        _polygon.check(rings([SQ, [(20, 2), (24, 2), (24, 4)]]), "a")
    with pytest.raises(SelfIntersectionError, match="polygon 1, shell, vertex 0"):
        _polygon.check(rings([SQ], [[(0, 0), (1, 1), (2, 2)]]), "a")
    with pytest.raises(EmptyGeometryError):
        _polygon.check(Rings(np.empty((0, 2)), np.zeros(1, np.int64), np.zeros(1, np.int64)), "a")


def test_malformed_offsets_are_value_errors():
    c = np.zeros((4, 2))
    with pytest.raises(ValueError, match="ring offsets"):
        _ext.check_polygons_f(c, np.array([0, 5], np.int64), np.array([0, 1], np.int64))
    with pytest.raises(ValueError, match="polygon offsets"):
        _ext.check_polygons_f(c, np.array([0, 4], np.int64), np.array([0, 2], np.int64))
    with pytest.raises(ValueError, match="polygon offsets"):
        _ext.check_polygons_f(c, np.array([0, 4], np.int64), np.array([0, 0, 1], np.int64))
    with pytest.raises(TypeError):
        _ext.check_polygons_f(c.astype(np.float32), np.array([0, 4]), np.array([0, 1]))


# --------------------------------------------------------------------------------------
# random and degenerate polygons against the oracle

SETTINGS = settings(max_examples=60, deadline=None, suppress_health_check=list(HealthCheck))


@SETTINGS
@given(star_ring(max_n=14))
def test_random_simple_rings(ring):
    agrees([ring])


@SETTINGS
@given(holey_polygon())
def test_random_polygons_with_holes(poly):
    agrees(poly)


@settings(max_examples=200, deadline=None, suppress_health_check=list(HealthCheck))
@given(grid_polygon())
def test_grid_polygons(poly):
    agrees(poly)


@settings(max_examples=30, deadline=None, suppress_health_check=list(HealthCheck))
@given(st.integers(1, 3).flatmap(lambda k: diamond_polygon(k=k)))
def test_touching_holes_are_valid(poly):
    assert agrees(poly)


@SETTINGS
@given(st.one_of(holey_polygon(), diamond_polygon(k=2), grid_polygon()), st.sampled_from(SCALES))
def test_every_scale(poly, s):
    agrees(scaled(poly, s))


@SETTINGS
@given(holey_polygon(max_holes=2), grid_polygon(max_holes=1))
def test_collections_are_checked_polygon_by_polygon(a, b):
    agrees(a, b)


# --------------------------------------------------------------------------------------
# the box-pair finder


@settings(max_examples=100, deadline=None)
@given(
    st.lists(
        st.tuples(*[st.integers(-20, 20)] * 4),
        max_size=60,
    )
)
def test_box_pairs_against_all_pairs(raw):
    b = np.array([(min(a, c), max(a, c), min(d, e), max(d, e)) for a, c, d, e in raw], float)
    b = b.reshape(-1, 4)
    got = _ext.box_pairs_f(*[np.ascontiguousarray(b[:, k]) for k in range(4)])
    want = {
        (i, j)
        for i in range(len(b))
        for j in range(i + 1, len(b))
        if b[i, 0] <= b[j, 1] and b[j, 0] <= b[i, 1] and b[i, 2] <= b[j, 3] and b[j, 2] <= b[i, 3]
    }
    assert got.shape == (len(want), 2)
    pairs = list(map(tuple, got.tolist()))
    assert len(pairs) == len(set(pairs)) and set(pairs) == want


# --------------------------------------------------------------------------------------
# real data


@requires_corpus
@pytest.mark.parametrize("path", corpus_files(), ids=lambda p: p.name)
def test_cgal_corpus_is_valid(path):
    from minkowski2d.io import read_cgal_dat

    for g in read_cgal_dat(path):
        if type(g).__name__ == "UnboundedPolygon":
            continue
        r = _polygon.rings_of(g) if hasattr(g, "geom_type") else _polygon.rings_of_array(g)
        ck = _polygon.check(r, path.name)
        if len(r.coords) <= 60:  # the oracle is quadratic
            assert oracle.problems([_split(r)]) == set()
        assert set(ck.orientation.tolist()) <= {1, -1}


def _split(r: Rings) -> list:
    return [r.coords[a:b].tolist() for a, b in zip(r.ring_offsets[:-1], r.ring_offsets[1:])]


def esicup_parts():
    from .corpus import ESICUP as data

    out = []
    for f in sorted(data.glob("*.json")):
        inst = mk.read_esicup(f)
        out += [(f"{f.stem}[{k}]", p) for k, p in enumerate(inst["parts"])]
    return out


def test_esicup_parts_are_valid_at_every_rotation():
    parts = esicup_parts()
    if not parts:
        pytest.skip("ESICUP data not found")
    for name, p in parts:
        for angle in (0, 15, 90, 105, 315):
            g = shapely.affinity.rotate(p, angle, origin=(0, 0)) if angle else p
            ck = _polygon.check(_polygon.rings_of(g), name)
            assert set(ck.orientation.tolist()) <= {1, -1}


def test_geos_agrees_on_ordinary_polygons():
    """Away from the cases where the rules differ (touching rings that split the
    interior), GEOS's verdict on small integer polygons is the same."""
    rng = np.random.default_rng(7)
    n_valid = 0
    for _ in range(300):
        n = int(rng.integers(3, 9))
        ring = rng.integers(0, 6, size=(n, 2)).tolist()
        hole = rng.integers(0, 6, size=(3, 2)).tolist() if rng.random() < 0.3 else None
        poly = [ring] if hole is None else [ring, hole]
        status, _, _, _, _, disc = core_check(poly)
        g = shapely.Polygon(ring, [hole] if hole else None)
        geos = shapely.is_valid(g)
        if status == Status.OK and disc.any():
            assert not geos  # GEOS: "interior is disconnected"
            continue
        assert (status == Status.OK) == geos, (poly, shapely.is_valid_reason(g))
        n_valid += status == Status.OK
    assert n_valid > 10


def test_large_star_is_valid_quickly():
    import time

    n = 4096
    k = np.arange(n)
    rad = np.where(k % 2 == 0, 10000.0, 5000.0)
    star = np.c_[rad * np.cos(2 * math.pi * k / n), rad * np.sin(2 * math.pi * k / n)]
    t = time.perf_counter()
    _polygon.check(_polygon.rings_of_array(star), "a")
    assert time.perf_counter() - t < 0.5
