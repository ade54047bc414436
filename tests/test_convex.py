"""minkowski2d.convex: the sum against the exact brute-force oracle, properties, the three
speeds, degenerate inputs, huge and near-parallel coordinates, and every error."""

from __future__ import annotations

from contextlib import contextmanager
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import minkowski2d as mk
from minkowski2d._engine import dispatch as D
from minkowski2d.errors import (
    CoordinateTypeError,
    EmptyGeometryError,
    GeometryError,
    NonFiniteError,
    NotConvexError,
    ShapeError,
)

from . import oracle
from .strategies import convex_float, convex_int

SETTINGS = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@contextmanager
def kernels_forced():
    """Arrays always take the compiled core now (no size threshold); kept so the tests
    below read as before."""
    yield


@contextmanager
def exact_forced():
    """Everything goes through the exact Python path (ints and Fractions) while inside."""
    D.FORCE_EXACT, old = True, D.FORCE_EXACT
    try:
        yield
    finally:
        D.FORCE_EXACT = old


@pytest.fixture
def kernel_path():
    """Arrays take the compiled core (the default)."""


def exact_rows(arr):
    return oracle.as_exact_list(arr)


def assert_matches_oracle(result, a, b):
    """A float result must equal the exact sum's vertices each rounded once; an int or
    Fraction result must equal them exactly."""
    expected = oracle.minkowski_sum(a, b)
    if result.dtype == np.float64:
        assert result.tolist() == [list(p) for p in oracle.rounded(expected)]
    else:
        assert exact_rows(result) == expected


# -- the seed's example ------------------------------------------------------------------
def test_seed_triangle_plus_square():
    a = [(0, 0), (2, 0), (0, 2)]
    b = [(0, 0), (1, 0), (1, 1), (0, 1)]
    s = mk.minkowski_sum(a, b)
    assert s.dtype == np.int64
    # The seed lists (0,1) too, but it lies on the edge (0,3)-(0,0): the contract drops
    # collinear vertices, so the sum has 5 vertices.
    assert s.tolist() == [[0, 0], [3, 0], [3, 1], [1, 3], [0, 3]]
    assert mk.signed_area(s) == 7.0


def test_seed_example_all_paths_agree(kernel_path):
    a = np.array([(0, 0), (2, 0), (0, 2)])
    b = np.array([(0, 0), (1, 0), (1, 1), (0, 1)])
    assert mk.minkowski_sum(a, b).tolist() == [[0, 0], [3, 0], [3, 1], [1, 3], [0, 3]]


# -- against the oracle ------------------------------------------------------------------
@SETTINGS
@given(convex_int(), convex_int())
def test_int_lists_match_oracle(a, b):
    assert_matches_oracle(mk.minkowski_sum(a, b), a, b)


@SETTINGS
@given(convex_int(max_size=60), convex_int(max_size=60))
def test_int_kernel_matches_oracle(a, b):
    with kernels_forced():
        r = mk.minkowski_sum(np.array(a), np.array(b))
    assert r.dtype == np.int64
    assert_matches_oracle(r, a, b)


@SETTINGS
@given(convex_float(), convex_float())
def test_float_lists_match_oracle(a, b):
    assert_matches_oracle(mk.minkowski_sum(a, b), a, b)


@SETTINGS
@given(convex_float(max_size=60), convex_float(max_size=60))
def test_float_kernel_matches_oracle(a, b):
    with kernels_forced():
        r = mk.minkowski_sum(np.array(a, dtype=float), np.array(b, dtype=float))
    assert_matches_oracle(r, a, b)


def _near_collinear_polygon(rng, n, slope, scale):
    """Convex-in-exact-arithmetic polygons whose vertices lie within rounding of a line
    or of each other: every predicate lands near zero, exercising the exact fallbacks."""
    t = np.sort(rng.uniform(0, 1, n)) * scale
    x = t
    y = t * slope
    pts = [(float(xi), float(yi)) for xi, yi in zip(x, y)]
    pts.append((float(scale) / 2, float(scale) * slope / 2 + scale * 1e-15))
    return oracle.hull(pts)


@pytest.mark.parametrize("seed", range(40))
def test_near_degenerate_floats_every_path(seed, monkeypatch):
    rng = np.random.default_rng(seed)
    a = [(float(x), float(y)) for x, y in _near_collinear_polygon(rng, 30, 0.1, 1.0)]
    b = [(float(x), float(y)) for x, y in _near_collinear_polygon(rng, 30, 0.1 + 1e-16, 3.0)]
    expected = mk.minkowski_sum(a, b)  # the core from lists
    assert_matches_oracle(expected, a, b)
    got = mk.minkowski_sum(np.array(a), np.array(b))  # the core from arrays
    with exact_forced():
        assert mk.minkowski_sum(a, b).tolist() == expected.tolist()
    assert got.tolist() == expected.tolist()
    many = mk.minkowski_sum_many([np.array(a)], [np.array(b)])
    assert many[0].tolist() == expected.tolist()


def test_near_parallel_edges_ordered_exactly(kernel_path):
    u = (2.0**27 + 1, 2.0**27)
    v = (2.0**27, 2.0**27 - 1)
    assert u[0] * v[1] - u[1] * v[0] == 0.0  # the float cross product rounds to zero
    # two segments: the sum is a parallelogram whose shape depends on the exact order
    a = [(0.0, 0.0), u]
    b = [(0.0, 0.0), v]
    for f in (lambda p: p, np.array):
        s = mk.minkowski_sum(f(a), f(b))
        assert_matches_oracle(s, a, b)
        assert len(s) == 4
    # and as triangles, in the kernels
    ta = np.array([(0.0, 0.0), u, (0.0, 2.0**28)])
    tb = np.array([(0.0, 0.0), v, (-(2.0**28), 2.0**27)])
    assert_matches_oracle(mk.minkowski_sum(ta, tb), ta.tolist(), tb.tolist())


# -- huge integers -----------------------------------------------------------------------
@pytest.mark.parametrize("bits", [31, 53, 54, 62, 63, 80, 200])
def test_huge_integers_exact(bits):
    M = 1 << bits
    a = [(-M, -M), (M - 1, -M + 2), (M, M), (-M + 3, M - 1)]
    b = [(0, 0), (M // 3, 1), (M // 3 - 1, 2), (-5, 1)]
    s = mk.minkowski_sum(a, b)
    assert exact_rows(s) == oracle.minkowski_sum(a, b)
    big = max(abs(v) for p in s.tolist() for v in p)
    assert s.dtype == (np.int64 if big < 2**63 else object)
    # as numpy arrays where they fit, through the array path
    if bits < 63:
        s2 = mk.minkowski_sum(np.array(a * 1 + a[:1], dtype=np.int64), np.array(b))
        assert exact_rows(s2) == oracle.minkowski_sum(a, b)


def test_huge_integer_large_polygons_take_exact_path():
    rng = np.random.default_rng(3)
    pts = rng.integers(-(2**40), 2**40, size=(200, 2))
    h = oracle.hull([(int(x) << 20, int(y) << 20) for x, y in pts])  # beyond 2**53
    a = np.array(h, dtype=object)
    b = [(0, 0), (1, 0), (0, 1)]
    s = mk.minkowski_sum(a, b)
    assert exact_rows(s) == oracle.minkowski_sum(h, b)


def test_fractions_stay_exact():
    a = [(Fraction(1, 3), 0), (1, 0), (0, 1)]
    b = [(0, 0), (Fraction(1, 7), Fraction(1, 7))]
    s = mk.minkowski_sum(a, b)
    assert s.dtype == object
    assert exact_rows(s) == oracle.minkowski_sum(a, b)


def test_extreme_float_exponents_are_exact():
    for scale in (1e-300, 1e300, 2.0**-1060, 5e-324, 2.0**1000):
        a = np.array([(0.0, 0.0), (3.0, 0.0), (0.0, 2.0)]) * scale
        b = np.array([(0.0, 0.0), (1.0, 1.0), (-1.0, 1.0)]) * scale
        assert_matches_oracle(mk.minkowski_sum(a, b), a.tolist(), b.tolist())


def test_float_overflow_is_an_error():
    a = [(0.0, 0.0), (1.7e308, 0.0), (0.0, 1.0)]
    with pytest.raises(mk.errors.OverflowGeometryError, match="overflows float64"):
        mk.minkowski_sum(a, a)


# -- properties --------------------------------------------------------------------------
@SETTINGS
@given(convex_int(), convex_int())
def test_commutative(a, b):
    assert mk.minkowski_sum(a, b).tolist() == mk.minkowski_sum(b, a).tolist()


@SETTINGS
@given(convex_int(), convex_int(), st.integers(-(10**6), 10**6), st.integers(-(10**6), 10**6))
def test_translation_invariant(a, b, dx, dy):
    s = mk.minkowski_sum(a, b)
    t = mk.minkowski_sum(mk.translate(a, (dx, dy)), b)
    assert t.tolist() == (s + [dx, dy]).tolist()


@SETTINGS
@given(convex_int(), convex_int(), st.integers(0, 50), st.booleans())
def test_presentation_invariant(a, b, k, rev):
    k %= len(a)
    a2 = a[k:] + a[:k]
    if rev:
        a2 = a2[::-1]
    assert mk.minkowski_sum(a2, b).tolist() == mk.minkowski_sum(a, b).tolist()


@SETTINGS
@given(convex_int(), convex_int())
def test_axis_swap_mirrors(a, b):
    s = mk.minkowski_sum(a, b)
    swap = [(y, x) for x, y in a], [(y, x) for x, y in b]
    t = mk.minkowski_sum(*swap)
    assert sorted(map(tuple, t.tolist())) == sorted((y, x) for x, y in s.tolist())


@SETTINGS
@given(convex_int(), convex_int(), convex_int())
def test_associative(a, b, c):
    left = mk.minkowski_sum(mk.minkowski_sum(a, b), c)
    right = mk.minkowski_sum(a, mk.minkowski_sum(b, c))
    assert left.tolist() == right.tolist()


@SETTINGS
@given(convex_int(max_size=40), convex_int(max_size=40))
def test_three_speeds_identical(a, b):
    tiny = mk.minkowski_sum(a, b)
    with kernels_forced():
        kern = mk.minkowski_sum(np.array(a), np.array(b))
    many = mk.minkowski_sum_many([np.array(a)], [np.array(b)])
    with exact_forced():
        ex = mk.minkowski_sum(a, b)
    assert tiny.tolist() == kern.tolist() == many[0].tolist() == ex.tolist()
    assert tiny.dtype == kern.dtype == many.coords.dtype == ex.dtype


def test_output_contract_on_a_large_float_pair():
    rng = np.random.default_rng(7)
    t = np.sort(rng.uniform(0, 2 * np.pi, 5000))
    a = np.c_[np.cos(t), np.sin(t)]
    b = np.c_[2 * np.cos(t + 0.3), np.sin(t + 0.3)] + [5.0, -1.0]
    s = mk.minkowski_sum(a[::-1], b)  # clockwise input
    # CCW, strictly convex, bottom-most first: every turn is a strict left turn
    assert mk.is_convex(s) and mk.signed_area(s) > 0
    from minkowski2d.predicates import orient_array

    assert (orient_array(np.roll(s, 1, 0), s, np.roll(s, -1, 0)) > 0).all()
    low = min(range(len(s)), key=lambda i: (s[i, 1], s[i, 0]))
    assert low == 0


def test_inputs_not_mutated():
    a = np.array([(2, 0), (0, 2), (0, 0), (1, 0)] * 10, dtype=np.int64)[:4]
    b = np.array([[0.0, 0.0], [0.0, 1.0], [1.0, 0.0]])
    a0, b0 = a.copy(), b.copy()
    mk.minkowski_sum(a, b)
    mk.normalize(a)
    mk.reflect(b)
    assert (a == a0).all() and (b == b0).all()


# -- degenerate inputs -------------------------------------------------------------------
def test_point_plus_polygon_is_translation():
    tri = [(0, 0), (4, 0), (1, 3)]
    assert mk.minkowski_sum([(5, 7)], tri).tolist() == [[5, 7], [9, 7], [6, 10]]
    assert mk.minkowski_sum([(1, 1)], [(2, 3)]).tolist() == [[3, 4]]


def test_segments():
    assert mk.minkowski_sum([(0, 0), (2, 0)], [(0, 0), (0, 3)]).tolist() == [
        [0, 0],
        [2, 0],
        [2, 3],
        [0, 3],
    ]
    # parallel segments sum to a segment
    assert mk.minkowski_sum([(0, 0), (2, 2)], [(5, 5), (4, 4)]).tolist() == [[4, 4], [7, 7]]
    # collinear points are a segment, reported lower end first
    assert mk.normalize([(3, 3), (1, 1), (2, 2)]).tolist() == [[1, 1], [3, 3]]
    # a segment and a triangle with a parallel edge
    s = mk.minkowski_sum([(0, 0), (1, 0)], [(0, 0), (2, 0), (0, 2)])
    assert s.tolist() == [[0, 0], [3, 0], [1, 2], [0, 2]]


def test_duplicates_closing_repeat_and_collinear_vertices_dropped():
    p = [(0, 0), (0, 0), (1, 0), (2, 0), (2, 2), (2, 2), (0, 2), (0, 1), (0, 0)]
    assert mk.normalize(p).tolist() == [[0, 0], [2, 0], [2, 2], [0, 2]]
    assert mk.normalize([(1, 1)] * 5).tolist() == [[1, 1]]


def test_shapely_inputs():
    shapely = pytest.importorskip("shapely")
    sq = shapely.Polygon([(0, 0), (1, 0), (1, 1), (0, 1)])
    tri = shapely.LinearRing([(0, 0), (2, 0), (0, 2)])
    s = mk.minkowski_sum(sq, tri)
    assert s.tolist() == [[0.0, 0.0], [3.0, 0.0], [3.0, 1.0], [1.0, 3.0], [0.0, 3.0]]
    assert mk.minkowski_sum(shapely.Point(1, 2), sq).tolist()[0] == [1.0, 2.0]


def test_hull_option_takes_any_point_set():
    pts = [(0, 0), (4, 0), (1, 1), (4, 4), (2, 1), (0, 4)]
    with pytest.raises(NotConvexError):
        mk.minkowski_sum(pts, [(0, 0)])
    assert mk.minkowski_sum(pts, [(0, 0)], hull=True).tolist() == [[0, 0], [4, 0], [4, 4], [0, 4]]


@SETTINGS
@given(st.lists(st.tuples(st.integers(-50, 50), st.integers(-50, 50)), min_size=1, max_size=80))
def test_convex_hull_matches_oracle(pts):
    expect = oracle.hull(pts)
    assert exact_rows(mk.convex_hull(pts)) == expect
    assert exact_rows(mk.convex_hull(np.array(pts * 3))) == expect  # the core


# -- helpers -----------------------------------------------------------------------------
def test_is_convex_and_pentagram():
    assert mk.is_convex([(0, 0), (1, 0), (0, 1)])
    assert mk.is_convex([(0, 0)])
    assert not mk.is_convex([(0, 0), (2, 0), (1, 1), (2, 2), (0, 2)])
    star = [(0, 0), (2, 6), (4, 0), (-1, 4), (5, 4)]  # turns left at every vertex
    assert not mk.is_convex(star)
    with pytest.raises(NotConvexError, match="wind around more than once"):
        mk.minkowski_sum(star, [(0, 0)])
    # the same in the kernels
    t = np.linspace(0, 4 * np.pi, 101)[:-1]  # a 50-gon traversed twice... as a star
    big_star = np.c_[np.cos(t * 2), np.sin(t * 2)]
    assert not mk.is_convex(big_star)


def test_not_convex_names_the_vertex(kernel_path):
    p = [(0, 0), (4, 0), (4, 4), (2, 1), (0, 4)]
    for data in (p, np.array(p)):
        with pytest.raises(NotConvexError, match=r"^b: not convex: .* vertex 3") as ei:
            mk.minkowski_sum([(0, 0), (1, 0), (0, 1)], data)
        assert ei.value.vertex == 3


def test_spike_is_not_convex():
    p = [(0, 0), (4, 0), (4, 4), (0, 4), (0, 2), (0, 3)]  # every real turn is left
    with pytest.raises(NotConvexError, match="doubles back on itself at vertex 4"):
        mk.normalize(p)
    with pytest.raises(NotConvexError, match="doubles back on itself at vertex 4"):
        mk.normalize(np.array(p * 10)[:6].repeat(1, axis=0).tolist() + [(0, 3)] * 30)
    # a polygon with a reflex vertex is reported as turning the other way
    with pytest.raises(NotConvexError, match="turns the other way at vertex 3"):
        mk.normalize([(0, 0), (4, 0), (4, 4), (4, 2), (0, 4)])


def test_signed_area_translate_reflect_cspace():
    tri = [(0, 0), (4, 0), (0, 3)]
    assert mk.signed_area(tri) == 6.0
    assert mk.signed_area(tri[::-1]) == -6.0
    assert mk.signed_area(np.array(tri, dtype=float) * 0.1) == pytest.approx(0.06)
    r = mk.reflect(tri)
    assert r.tolist() == [[0, 0], [-4, 0], [0, -3]]
    assert mk.signed_area(r) == 6.0  # a point reflection keeps the orientation
    assert mk.translate(tri, (1, 1)).tolist() == [[1, 1], [5, 1], [1, 4]]
    robot = [(0, 0), (1, 0), (0, 1)]
    c = mk.cspace_obstacle(tri, robot)
    assert c.tolist() == mk.minkowski_sum(tri, [(0, 0), (-1, 0), (0, -1)]).tolist()


@SETTINGS
@given(convex_int(max_size=12), convex_int(max_size=12), st.integers(-30, 30), st.integers(-30, 30))
def test_cspace_obstacle_is_the_collision_set(obstacle, robot, x, y):
    """The robot placed at (x, y) overlaps the obstacle exactly when (x, y) is in the
    C-space obstacle: checked with shapely on the placed robot."""
    shapely = pytest.importorskip("shapely")
    c = mk.cspace_obstacle(obstacle, robot)

    def geom(p):
        p = [tuple(map(float, q)) for q in p]
        if len(set(p)) == 1:
            return shapely.Point(p[0])
        if len(oracle.hull(p)) == 2:
            return shapely.LineString(oracle.hull(p))
        return shapely.Polygon(oracle.hull(p))

    placed = geom([(px + x, py + y) for px, py in robot])
    assume(not placed.is_empty)
    assert geom(c).intersects(shapely.Point(x, y)) == geom(obstacle).intersects(placed)


# -- errors ------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "bad, exc, match",
    [
        ([], EmptyGeometryError, "a: empty input"),
        (np.zeros((0, 2)), EmptyGeometryError, "a: empty input"),
        ([(0, 0, 1), (1, 1, 1)], ShapeError, "a: vertex 0 is"),
        (np.zeros((4, 3)), ShapeError, r"a: expected shape \(n, 2\), got \(4, 3\)"),
        (np.zeros(2), ShapeError, r"a: expected shape \(n, 2\), got \(2,\)"),
        ([(0, 0), (float("nan"), 1)], NonFiniteError, "a: vertex 1 has a non-finite"),
        (np.array([(0, 0), (1, np.inf)] * 20), NonFiniteError, "a: vertex 1 has a non-finite"),
        ([(0, 0), (True, 1)], CoordinateTypeError, "a: vertex 1 has a bool"),
        ([(0, 0), ("1", 1)], CoordinateTypeError, "a: vertex 1 has a coordinate of type str"),
        (
            [(0, 0), (1, 0), (0, "x")],
            CoordinateTypeError,
            "a: vertex 2 has a coordinate of type str",
        ),
        ([5, 6, 7], ShapeError, "a: vertex 0 is 5, not an"),
        ([(0, 0), (1, 0), (0, float("inf"))], NonFiniteError, "a: vertex 2 has a non-finite"),
        (np.array([[1 + 1j, 0]]), CoordinateTypeError, "not real numbers"),
        ("abc", ShapeError, "a: "),
    ],
)
def test_bad_input_errors(bad, exc, match):
    with pytest.raises(exc, match=match):
        mk.minkowski_sum(bad, [(0, 0), (1, 0), (0, 1)])
    assert issubclass(exc, GeometryError) and issubclass(exc, ValueError)


def test_mixed_int_and_float_coordinates_are_float():
    s = mk.minkowski_sum([(0, 0), (1, 0), (0, 1.5), (0, 1)], [(0, 0)])
    assert s.dtype == np.float64 and s.tolist() == [[0.0, 0.0], [1.0, 0.0], [0.0, 1.5]]


def test_polygon_with_holes_is_not_convex():
    shapely = pytest.importorskip("shapely")
    p = shapely.Polygon([(0, 0), (9, 0), (9, 9), (0, 9)], [[(1, 1), (2, 1), (2, 2)]])
    with pytest.raises(NotConvexError, match="hole"):
        mk.minkowski_sum(p, [(0, 0)])
