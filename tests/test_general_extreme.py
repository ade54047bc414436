"""General sums, erosion and decomposition at extreme magnitudes, GEOS failures turned
into GeometryError, integers beyond 2**53, and the bounds on work.

The reference is exact: the L-shape's sums and erosions have vertices that are integer
multiples of the scale ``s``, so every result is compared coordinate for coordinate with
the result at ``s = 1`` times ``s``, and its area with a Fraction shoelace."""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
import shapely
import shapely.errors
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import minkowski2d as mk
from minkowski2d import general
from minkowski2d.errors import (
    GeometryError,
    OverflowGeometryError,
    ResourceLimitError,
    ShapeError,
)

from .strategies import regular_star
from .test_general import star_ring

L = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
SCALES = [2.0**-1000, 1e-200, 1e-20, 1.0, 1e20, 1e155, 1e200, 2.0**344, 2.0**900]
METHODS = [*general.SUM_METHODS, None]  # None: the default (may switch)


def scaled(ring, s):
    return [(x * s, y * s) for x, y in ring]


def exact_area(g) -> Fraction:
    """Area of a Polygon / MultiPolygon from its float coordinates, exactly."""

    def ring_area(r):
        c = [(Fraction(x), Fraction(y)) for x, y in shapely.get_coordinates(r).tolist()]
        return sum(c[i][0] * c[i + 1][1] - c[i + 1][0] * c[i][1] for i in range(len(c) - 1)) / 2

    total = Fraction(0)
    for p in shapely.get_parts(g):
        total += abs(ring_area(p.exterior)) - sum(abs(ring_area(h)) for h in p.interiors)
    return total


def times(v, s) -> float:
    """v * s rounded once (what a float result at scale s must hold)."""
    return float(Fraction(v) * Fraction(s))


def same_times(r, ref, s):
    """r has the coordinates of ref times s (each rounded once), in the same structure."""
    assert r.geom_type == ref.geom_type
    assert shapely.get_num_coordinates(r) == shapely.get_num_coordinates(ref)
    got = shapely.get_coordinates(r).tolist()
    want = [[times(x, s), times(y, s)] for x, y in shapely.get_coordinates(ref).tolist()]
    assert got == want


def close(x: Fraction, y: Fraction, rel=1e-9) -> bool:
    return abs(x - y) <= Fraction(rel) * abs(y)


@pytest.mark.parametrize("s", SCALES, ids=[f"s={s:g}" for s in SCALES])
@pytest.mark.parametrize("method", METHODS)
def test_sum_of_L_at_every_scale(s, method):
    ref = mk.minkowski_sum_general(L, L, method=method)
    assert ref.area == 13
    r = mk.minkowski_sum_general(scaled(L, s), scaled(L, s), method=method)
    assert close(exact_area(r), 13 * Fraction(s) ** 2)
    same_times(r, ref, s)
    if 1e-150 < s < 1e150:  # where float64 represents the area itself
        assert r.area == pytest.approx(13 * s * s, rel=1e-9)
        assert r.is_valid


@pytest.mark.parametrize("s", SCALES, ids=[f"s={s:g}" for s in SCALES])
@pytest.mark.parametrize("decomposition", general.DECOMPOSITIONS)
def test_decomposition_at_every_scale(s, decomposition):
    ref = mk.convex_decomposition(L, method=decomposition)
    pieces = mk.convex_decomposition(scaled(L, s), method=decomposition)
    assert len(pieces) == len(ref)
    for p, q in zip(pieces, ref, strict=True):
        assert p.tolist() == [[times(x, s), times(y, s)] for x, y in q.tolist()]
    total = sum(exact_area(shapely.Polygon(p)) for p in pieces)
    assert close(total, 3 * Fraction(s) ** 2)


@pytest.mark.parametrize("s", SCALES, ids=[f"s={s:g}" for s in SCALES])
def test_erosion_at_every_scale(s):
    LL = [(0, 0), (4, 0), (4, 2), (3, 2), (3, 3), (2, 3), (2, 4), (0, 4)]  # L + L
    # non-convex A, non-convex B (the general path), B off the origin
    B = [(x + 10, y + 10) for x, y in L]
    ref = mk.minkowski_difference(LL, B)
    assert ref.area > 0
    r = mk.minkowski_difference(scaled(LL, s), scaled(B, s))
    assert close(exact_area(r), exact_area(ref) * Fraction(s) ** 2)
    if math.frexp(s)[0] == 0.5:  # a power of two: the inputs and the result scale exactly
        same_times(r, ref, s)
    else:  # the inputs are rounded (3 s, 11 s ...): the result is near ref times s
        back = shapely.transform(r, lambda c: c / s)
        assert back.hausdorff_distance(ref) <= 1e-14 * 12
    # the convex path: square by square, off the origin
    sq = [(0, 0), (4, 0), (4, 4), (0, 4)]
    unit = [(10, 10), (11, 10), (11, 11), (10, 11)]
    a, b = scaled(sq, s), scaled(unit, s)
    c = mk.minkowski_difference(a, b)
    # exact: the box [a0 - b0, a1 - b1]^2 of the float inputs, each corner rounded once
    lo = float(Fraction(a[0][0]) - Fraction(b[0][0]))
    hi = float(Fraction(a[1][0]) - Fraction(b[1][0]))
    assert shapely.get_coordinates(c).tolist() == [
        [lo, lo],
        [hi, lo],
        [hi, hi],
        [lo, hi],
        [lo, lo],
    ]


@pytest.mark.parametrize("method", METHODS)
def test_sum_overflow_is_a_clear_error(method):
    s = 2.0**1022  # L's coordinates fit, L + L reaches 4 s = 2**1024
    with pytest.raises(OverflowGeometryError) as e:
        mk.minkowski_sum_general(scaled(L, s), scaled(L, s), method=method)
    assert e.value.argument == "a, b" and e.value.hint
    # the largest sum that fits is computed exactly
    s = 2.0**1021
    r = mk.minkowski_sum_general(scaled(L, s), scaled(L, s), method=method)
    assert exact_area(r) == 13 * Fraction(s) ** 2


def test_erosion_overflow_is_a_clear_error():
    big = 1.2e308
    A = [(big, 0), (big + 1e307, 0), (big + 1e307, 1e307), (big, 1e307)]
    B = [(-big, 0), (-big + 1e306, 0), (-big + 1e306, 1e306), (-big, 1e306)]
    with pytest.raises(OverflowGeometryError):
        mk.minkowski_difference(A, B)  # the erosion lies near x = 2.4e308
    A_nc = [*A[:2], (big + 1e307, 1e306), (big + 5e306, 1e306), (big + 5e306, 1e307), A[3]]
    with pytest.raises(OverflowGeometryError):
        mk.minkowski_difference(A_nc, B)


def test_tiny_valid_triangle_is_valid():
    tri = [(0.0, 0.0), (3e-200, 0.0), (0.0, 3e-200)]
    r = mk.minkowski_sum_general(tri, tri)
    assert exact_area(r) == Fraction(3e-200) ** 2 * 2
    assert len(mk.convex_decomposition(tri)) == 1
    assert mk.minkowski_difference([(0, 0), (1e-199, 0), (0, 1e-199)], tri).geom_type == "Polygon"


def test_mixed_magnitudes_keep_the_large_coordinates_exact():
    # a huge square with a tiny notch: the notch is below the float64 resolution of the
    # square's extent, the result must still be exact at the scale of the square
    s = 1e300
    A = [(0, 0), (s, 0), (s, s), (0, s)]
    B = [(0, 0), (1e-300, 0), (0, 1e-300)]
    r = mk.minkowski_sum_general(A, B)
    assert shapely.get_coordinates(r).max() == s + 1e-300  # == s in float64
    assert exact_area(r) == Fraction(s) ** 2


# --------------------------------------------------------------------------------------
# GEOS failures, integers beyond 2**53


def test_no_geos_overlay_on_the_computing_path(monkeypatch):
    # the sum, the erosion and the union of a collection are computed by the core's exact
    # overlay: GEOS's overlay, noding and polygonizing are never called
    def boom(*args, **kwargs):
        raise AssertionError("a GEOS overlay was called")

    for f in (
        "union_all",
        "union",
        "unary_union",
        "difference",
        "intersection",
        "node",
        "polygonize",
        "coverage_union_all",
        "make_valid",
        "simplify",
        "buffer",
        "is_valid",
        "is_valid_reason",
        "constrained_delaunay_triangles",
    ):
        monkeypatch.setattr(shapely, f, boom)
    for method in (None, "decomposition", "convolution"):
        assert mk.minkowski_sum_general(L, L, method=method).area == 13.0
    assert mk.minkowski_sum_general([L, [(5, 5), (6, 5), (6, 6)]], L).area > 13.0
    assert mk.minkowski_difference(L, [(0, 0), (1, 0), (0, 1)]).area > 0
    comb = [(0, 0), (6, 0), (6, 3), (5, 3), (5, 1), (4, 1), (4, 3), (3, 3), (3, 1), (2, 1),
            (2, 3), (1, 3), (1, 1), (0, 1)]  # fmt: skip
    assert mk.minkowski_difference(comb, [(0, 0), (0.5, 0), (0.5, 0.5)]).area > 0


def test_ints_beyond_2_53_are_refused_unless_exact():
    big = 2**53 + 1  # float64 would round it
    with pytest.raises(GeometryError) as e:
        mk.minkowski_sum_general([(0, 0), (big, 0), (0, 5)], L)
    assert (e.value.argument, e.value.vertex) == ("a", 1) and e.value.hint
    with pytest.raises(GeometryError) as e:
        mk.minkowski_difference(L, np.array([(0, 0), (3, 0), (0, 2**62 + 1)], dtype=np.int64))
    assert (e.value.argument, e.value.vertex) == ("b", 2)
    with pytest.raises(GeometryError):
        mk.convex_decomposition([(0, 0), (10**30 + 1, 0), (0, 1)])
    # huge ints with at most 53 significant bits are exact: accepted, results exact
    s = 2**344
    r = mk.minkowski_sum_general(scaled(L, s), scaled(L, s))
    assert exact_area(r) == 13 * s * s
    r = mk.minkowski_sum_general(np.array(scaled(L, 2**60), dtype=np.int64), L)
    assert exact_area(r) == exact_area(
        mk.minkowski_sum_general(np.array(scaled(L, 2**60), dtype=np.float64), L)
    )


def test_fractions_are_scaled_exactly_then_rounded_once():
    t = Fraction(1, 3) / 2**900  # not a float: rounded once, after the exact scale
    tri = [(0, 0), (t, 0), (0, t)]
    r = mk.minkowski_sum_general(tri, tri)
    assert shapely.get_coordinates(r).max() == 2 * float(t)
    # Fractions beyond the float64 range are scaled exactly too: the operands are read,
    # and it is the result that does not fit
    s = Fraction(10**400)
    with pytest.raises(OverflowGeometryError):
        mk.minkowski_sum_general([(x * s, y * s) for x, y in L], L)
    with pytest.raises(OverflowGeometryError, match="underflow"):
        mk.minkowski_sum_general([(x / s, y / s) for x, y in L], [(x / s, y / s) for x, y in L])


# --------------------------------------------------------------------------------------
# bounded work


def test_decomposition_limit_switches_the_default(monkeypatch):
    comb = [(0, 0), (6, 0), (6, 3), (5, 3), (5, 1), (4, 1), (4, 3), (3, 3), (3, 1), (2, 1)]
    comb += [(2, 3), (1, 3), (1, 1), (0, 1)]
    ref = mk.minkowski_sum_general(comb, L)
    unit = [(0, 0), (1, 0), (1, 1), (0, 1)]
    comb2 = [(2 * x, 2 * y) for x, y in comb]
    E_ref = mk.minkowski_difference(comb2, L)
    assert E_ref.area == 2.0
    monkeypatch.setattr(general, "MAX_PIECE_PAIRS", 1)
    with pytest.raises(ResourceLimitError) as e:
        mk.minkowski_sum_general(comb, L, method="decomposition")
    assert e.value.argument == "a, b" and "MAX_PIECE_PAIRS" in str(e.value) and e.value.hint
    r = mk.minkowski_sum_general(comb, L)  # default: the convolution takes over
    assert r.symmetric_difference(ref).area <= 1e-12 * ref.area
    # the erosion's inner sum switches too
    E = mk.minkowski_difference(comb2, L)
    assert E.symmetric_difference(E_ref).area <= 1e-12 * E_ref.area
    assert mk.minkowski_difference(comb, unit).is_empty  # teeth and base are 1 wide


@pytest.mark.parametrize("limit, value", [("MAX_CONVOLUTION_SEGMENTS", 3), ("MAX_CROSSINGS", 0)])
def test_convolution_limits(monkeypatch, limit, value):
    monkeypatch.setattr(general, limit, value)
    star = [(3, 0), (1, 1), (0, 3), (-1, 1), (-3, 0), (-1, -1), (0, -3), (1, -1)]  # crossings
    with pytest.raises(ResourceLimitError, match=limit) as e:
        mk.minkowski_sum_general(star, L, method="convolution")
    assert e.value.argument == "a, b"
    monkeypatch.setattr(general, "MAX_PIECE_PAIRS", 1)
    with pytest.raises(ResourceLimitError, match="both methods") as e:
        mk.minkowski_sum_general(star, L)  # default: nothing left to switch to
    assert e.value.argument == "a, b" and e.value.hint


def test_large_stars_convolution_is_refused_not_a_crash():
    # two regular 2048-vertex stars: their convolution once ran the machine out of memory
    # (the grid of candidate pairs registered every long segment in ~sqrt(n) cells); the
    # decomposition computes the sum (benchmarks/bench_general.py)
    a = regular_star(2048, 10000, 5000).astype(np.int64)
    with pytest.raises(ResourceLimitError, match="MAX_CONVOLUTION_SEGMENTS") as e:
        mk.minkowski_sum_general(a, a, method="convolution")
    assert e.value.argument == "a, b" and e.value.hint


def test_point_in_a_collection_is_refused_not_dropped():
    # {p} ⊕ B has area: uniting the collection used to drop the point silently
    sq = [(0, 0), (1, 0), (1, 1), (0, 1)]
    with pytest.raises(ShapeError) as e:
        mk.minkowski_sum_general([sq, [(5, 5)]], sq)
    assert e.value.argument == "a[1]" and e.value.hint
    with pytest.raises(ShapeError):
        mk.minkowski_difference([sq, [(5, 5), (6, 5)]], [(0, 0)])
    # a point or segment on its own is an operand like any other
    r = mk.minkowski_sum_general([(5, 5)], sq)
    assert r.equals(shapely.Polygon([(5, 5), (6, 5), (6, 6), (5, 6)]))


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])
@given(star_ring(max_n=8), star_ring(max_n=8), st.integers(-900, 900))
def test_results_scale_exactly_by_powers_of_two(ra, rb, e):
    """At s = 2**e every result is the result at s = 1 times s, bit for bit: GEOS sees the
    same scaled operands either way."""
    s = 2.0**e
    for method in METHODS:
        ref = mk.minkowski_sum_general(ra, rb, method=method)
        r = mk.minkowski_sum_general(scaled(ra, s), scaled(rb, s), method=method)
        same_times(r, ref, s)
    ref = mk.minkowski_difference(ra, [(x + 7, y - 3) for x, y in rb])
    r = mk.minkowski_difference(scaled(ra, s), scaled([(x + 7, y - 3) for x, y in rb], s))
    if ref.is_empty:
        assert r.is_empty
    else:
        same_times(r, ref, s)


def test_a_large_arrangement_is_refused_before_it_is_built():
    # 256-vertex stars: over a million crossings (GEOS would need many GB and minutes);
    # the bound is checked first, in seconds, with the default limits
    A = regular_star(256, 10000, 5000)
    B = regular_star(256, 9000, 3000, 0.3)
    with pytest.raises(ResourceLimitError, match="MAX_CROSSINGS") as e:
        mk.minkowski_sum_general(A.astype(np.int64), B.astype(np.int64), method="convolution")
    assert e.value.argument == "a, b" and "decomposition" in e.value.hint
