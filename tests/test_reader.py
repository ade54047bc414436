"""The one polygon reader (_engine/reader.read): each option against an exact oracle
(Python ints and Fractions), and one error for one fault whichever option reads it."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
import shapely
from hypothesis import given
from hypothesis import strategies as st

from minkowski2d._engine.reader import PARTS, read
from minkowski2d.errors import (
    EmptyGeometryError,
    GeometryError,
    NonFiniteError,
    OverflowGeometryError,
    SelfIntersectionError,
    ShapeError,
)

TRI = [(0, 0), (4, 0), (0, 3)]
ints = st.integers(-(2**70), 2**70)
fracs = st.fractions(max_denominator=2**40).filter(lambda f: abs(f) < 2**60)


def _is_float64(v) -> bool:
    try:
        return Fraction(float(v)) == Fraction(v)
    except OverflowError:
        return False


@given(st.lists(st.tuples(ints, ints), min_size=3, max_size=6))
def test_float64_numbers_refuse_exactly_the_ints_float64_cannot_hold(pts):
    ok = all(_is_float64(v) for p in pts for v in p)
    if ok:
        got = read(pts, "a", accept="coords", numbers="float64")
        assert [tuple(map(Fraction, r)) for r in got.tolist()] == [
            (Fraction(x), Fraction(y)) for x, y in pts
        ]
    else:
        with pytest.raises(GeometryError, match="53 significant bits"):
            read(pts, "a", accept="coords", numbers="float64")
        with pytest.raises(GeometryError, match="53 significant bits"):
            read(pts, "a", accept="coords", numbers="fractions")


@given(st.lists(st.tuples(fracs, fracs), min_size=3, max_size=6))
def test_fractions_round_once_and_the_bound_holds(pts):
    got = read(pts, "a", accept="polygon", numbers="round")
    xy = got.rings.coords
    worst = Fraction(0)
    for (x, y), (fx, fy) in zip(pts, xy.tolist()):
        assert fx == float(x) and fy == float(y)  # correctly rounded, once
        worst = max(worst, abs(Fraction(fx) - x), abs(Fraction(fy) - y))
    assert Fraction(got.delta) >= worst * Fraction(141421356, 10**8)
    exact = all(_is_float64(v) for p in pts for v in p)
    assert (got.delta == 0) == exact
    r = read(pts, "a", accept="coords", numbers="fractions")
    assert r.tolist() == xy.tolist()
    if not exact:
        with pytest.raises(GeometryError, match="not a float64 value"):
            read(pts, "a", accept="coords", numbers="float64")


def test_round_bounds_the_rounding_of_wide_ints_in_an_int64_array():
    a = np.array([[0, 0], [2**60 + 1, 0], [0, 2**60 + 3]], np.int64)
    got = read(a, "a", accept="polygon", numbers="round")
    assert got.delta >= 3 and got.rings.coords.dtype == np.float64
    assert read(a[:, :] // 2**20, "a", accept="polygon", numbers="round").delta == 0


def test_points_take_their_path():
    assert read(TRI, "a").path == "i"
    assert read([(0.5, 0), (1, 0), (0, 1)], "a").path == "f"
    assert read([(Fraction(1, 3), 0), (1, 0), (0, 1)], "a").path == "py"
    assert read([(2**62, 0), (1, 0), (0, 1)], "a").path == "py"
    wide = np.array([[2**62, 0], [1, 0], [0, 1]], np.int64)
    assert read(wide, "a", numbers="int64").path == "i"
    with pytest.raises(ShapeError, match="int64"):
        read([(2**62, 0), (1, 0), (0, 1)], "a", numbers="core")


def test_a_batch_reads_as_one_array():
    coords, offsets = read([TRI, np.array(TRI) * 2], "p", accept="many")
    assert coords.tolist() == [list(p) for p in TRI] + [[2 * x, 2 * y] for x, y in TRI]
    assert offsets.tolist() == [0, 3, 6]
    with pytest.raises(NonFiniteError):
        read([TRI, [(0, 0), (float("nan"), 1), (1, 1)]], "p", accept="many")


def test_degenerate_sets():
    seg = [(0, 0), (1, 1), (3, 3)]
    assert read(seg, "a", accept="polygon", validate=True, degenerate="hull").flat.tolist() == [
        [0.0, 0.0], [3.0, 3.0],
    ]  # fmt: skip
    kept = read(seg, "a", accept="polygon", validate=True, degenerate="keep")
    assert kept.flat is None and kept.rings.coords.shape == (3, 2)
    with pytest.raises(SelfIntersectionError, match="no area"):
        read(seg, "a", accept="polygon", validate=True, degenerate="refuse")
    # a shapely point or line is a flat set only where flat sets are taken as hulls
    line = shapely.LineString(seg)
    assert read(line, "a", accept="polygon", validate=True, degenerate="hull").flat is not None
    with pytest.raises(ShapeError, match="not polygonal"):
        read(line, "a", accept="polygons", degenerate="keep")
    # an empty set is an operand only where degenerate sets are kept
    assert read(shapely.Polygon(), "a", accept="polygon", degenerate="keep").geometry().is_empty
    with pytest.raises(EmptyGeometryError):
        read(shapely.Polygon(), "a", accept="polygon", degenerate="hull")


def test_validation_names_the_ring_and_vertex_and_orients():
    bow = [(0, 0), (2, 2), (2, 0), (0, 2)]
    with pytest.raises(SelfIntersectionError) as e:
        read(bow, "a", accept="polygon", validate=True, hint="fix it")
    assert e.value.vertex == 2 and e.value.hint == "fix it"
    cw = read(TRI[::-1], "a", accept="polygon", validate=True)
    assert cw.orientation.tolist() == [-1]


def test_overlapping_parts_are_refused_or_left_to_the_caller():
    mp = shapely.MultiPolygon([shapely.box(0, 0, 2, 2), shapely.box(1, 1, 3, 3)])
    with pytest.raises(SelfIntersectionError, match="overlap"):
        read(mp, "a", accept="polygon", validate=True)
    got = read(mp, "a", accept="polygon", validate=PARTS)
    assert got.overlap and got.multi
    apart = shapely.MultiPolygon([shapely.box(0, 0, 1, 1), shapely.box(2, 2, 3, 3)])
    assert not read(apart, "a", accept="polygon", validate=PARTS).overlap


def test_lists_of_polygons_are_one_set_only_where_accepted():
    two = [shapely.box(0, 0, 1, 1), shapely.box(2, 0, 3, 1)]
    got = read(two, "a", accept="polygons", validate=True)
    assert len(got.parts) == 2 and got.overlap
    assert got.parts[1].name == "a[1]"
    with pytest.raises(ShapeError):
        read(two, "a", accept="polygon")
    with pytest.raises(ShapeError, match="a point or segment in a collection"):
        read([shapely.box(0, 0, 1, 1), [(0, 0), (1, 1)]], "a", accept="polygons",
             validate=True, degenerate="hull")  # fmt: skip


@pytest.mark.parametrize(
    "accept,numbers",
    [("points", "exact"), ("points", "core"), ("polygon", "round"), ("polygons", "float64"),
     ("coords", "fractions")],
)  # fmt: skip
def test_one_fault_one_error_whatever_the_options(accept, numbers):
    with pytest.raises(NonFiniteError, match="non-finite coordinate"):
        read([(0, 0), (float("inf"), 0), (0, 1)], "a", accept=accept, numbers=numbers)
    with pytest.raises(EmptyGeometryError):
        read([], "a", accept=accept, numbers=numbers)
    with pytest.raises(ShapeError):
        read([(0, 0, 1)], "a", accept=accept, numbers=numbers)
    if accept != "points":
        with pytest.raises(OverflowGeometryError, match="beyond float64"):
            read([(Fraction(10**400), 0), (0, 1), (1, 0)], "a", accept=accept, numbers=numbers)
