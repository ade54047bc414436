"""Tests for minkowski2d.collision against a brute-force exact reference.

The reference builds D = A ⊕ (−B) as the exact convex hull of all pairwise differences
(Fractions) and reads intersection, distance and penetration off it by definition; it
shares no code with the implementation.
"""

from __future__ import annotations

import math
from fractions import Fraction as F

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import minkowski2d as mk
from minkowski2d import collision as C
from minkowski2d._engine import dispatch as D
from minkowski2d.batch import Ragged
from minkowski2d.errors import (
    EmptyGeometryError,
    NonFiniteError,
    NotConvexError,
    ShapeError,
)

from . import oracle
from .strategies import convex_float, convex_int, convex_tiny_offsets

SETTINGS = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
REL = 1e-12

# --------------------------------------------------------------------------------------
# the exact reference


def d_hull(a, b) -> list:
    """D = A ⊕ (−B), exact, CCW, no collinear points."""
    return oracle.hull([(F(p[0]) - F(q[0]), F(p[1]) - F(q[1])) for p in a for q in b])


def seg_d2(p, q, x=(0, 0)) -> F:
    """Exact squared distance from x to the segment p q."""
    ex, ey = q[0] - p[0], q[1] - p[1]
    L = ex * ex + ey * ey
    if L == 0:
        return (p[0] - x[0]) ** 2 + (p[1] - x[1]) ** 2
    t = F((x[0] - p[0]) * ex + (x[1] - p[1]) * ey) / L
    t = min(max(t, F(0)), F(1))
    dx, dy = p[0] + t * ex - x[0], p[1] + t * ey - x[1]
    return dx * dx + dy * dy


def ref_inside(H, x=(0, 0)) -> bool:
    """x in the closed convex polygon H (exact)."""
    if len(H) == 1:
        return H[0] == tuple(F(v) for v in x)
    if len(H) == 2:
        return seg_d2(H[0], H[1], x) == 0
    return all(oracle.cross(H[k], H[(k + 1) % len(H)], x) >= 0 for k in range(len(H)))


def ref_d2(H, x=(0, 0)) -> F:
    """Exact squared distance from x to the convex polygon H."""
    if ref_inside(H, x):
        return F(0)
    if len(H) == 1:
        return (H[0][0] - x[0]) ** 2 + (H[0][1] - x[1]) ** 2
    return min(seg_d2(H[k], H[(k + 1) % len(H)], x) for k in range(len(H)))


def ref_boundary_d2(H, x) -> F:
    if len(H) == 1:
        return (H[0][0] - x[0]) ** 2 + (H[0][1] - x[1]) ** 2
    return min(seg_d2(H[k], H[(k + 1) % len(H)], x) for k in range(len(H)))


def ref_signed_depth2(H) -> F:
    """Signed squared penetration depth: depth^2 when overlapping, -distance^2 apart."""
    if not ref_inside(H):
        return -ref_d2(H)
    if len(H) < 3:
        return F(0)
    best = None
    for k in range(len(H)):
        p, q = H[k], H[(k + 1) % len(H)]
        c = oracle.cross(p, q, (0, 0))
        v = F(c * c) / ((q[0] - p[0]) ** 2 + (q[1] - p[1]) ** 2)
        best = v if best is None else min(best, v)
    return best


def rel_err2(x: float, exact2: F) -> float:
    """Relative error of x against sqrt(|exact2|) with sign, measured on squares (the
    relative error of x is half of it)."""
    x = F(x)
    s = x * x if x >= 0 else -x * x
    if exact2 == 0:
        return float(abs(s))
    if abs(exact2) < F(2) ** -2044:
        # the exact value is below float64's normal range: a subnormal result carries an
        # absolute error up to 2**-1074 (a value under 2**-1075 rounds to 0.0), so only
        # its tininess can be asked for
        return 0.0 if abs(x) <= F(2) ** -1021 else 1.0
    return float(abs(s - exact2) / abs(exact2))


def scale_of(*polys) -> float:
    return 1.0 + max(abs(float(v)) for p in polys for pt in p for v in pt)


def check_pair(a, b, *, witness_tol: float = 1e-9) -> None:
    """Every function on (a, b) against the reference."""
    H = d_hull(a, b)
    inside = ref_inside(H)
    for method in ("auto", "sum", "gjk"):
        assert mk.intersects(a, b, method=method) is inside, method
    tol = witness_tol * scale_of(a, b)
    A, B = oracle.hull(a), oracle.hull(b)

    d = mk.distance(a, b)
    assert rel_err2(d.distance, ref_d2(H)) <= 2 * REL
    pa, pb = (tuple(F(float(v)) for v in w) for w in (d.point_a, d.point_b))
    assert float(ref_d2(A, pa)) ** 0.5 <= tol
    assert float(ref_d2(B, pb)) ** 0.5 <= tol
    gap = math.hypot(*(d.point_a - d.point_b))
    assert abs(gap - d.distance) <= tol
    if inside:
        assert d.distance == 0.0

    p = mk.penetration(a, b)
    assert rel_err2(p.depth, ref_signed_depth2(H)) <= 2 * REL
    # positive exactly when the correctly rounded depth is: above half the least
    # subnormal, 2**-1075 (a sliver's depth below it rounds to 0.0)
    assert (p.depth > 0) == (inside and len(H) >= 3 and ref_signed_depth2(H) > F(1, 2**2150))
    pa, pb = (tuple(F(float(v)) for v in w) for w in (p.point_a, p.point_b))
    assert float(ref_boundary_d2(A, pa)) ** 0.5 <= tol
    assert float(ref_boundary_d2(B, pb)) ** 0.5 <= tol
    np.testing.assert_allclose(p.point_a - p.point_b, p.depth * p.normal, rtol=0, atol=tol)
    n = math.hypot(*p.normal)
    assert n == 0.0 and len(H) == 1 and H[0] == (0, 0) or abs(n - 1) <= 1e-15 * 4
    if p.depth != 0.0:
        # the normal is D's outward normal at p = point_a - point_b: every point of D is
        # on the inner side of the line through p (up to rounding)
        nx, ny = (F(float(v)) for v in p.normal)
        px, py = F(float(p.depth)) * nx, F(float(p.depth)) * ny
        worst = max(float((x - px) * nx + (y - py) * ny) for x, y in H)
        assert worst <= tol


# --------------------------------------------------------------------------------------
# properties against the reference


@SETTINGS
@given(convex_int(max_size=10, bound=6), convex_int(max_size=10, bound=6))
def test_small_ints_degenerate_rich(a, b):
    # tiny coordinate ranges make touching, collinear and identical cases common
    check_pair(a, b)


@SETTINGS
@given(convex_int(max_size=12, bound=1000), convex_int(max_size=12, bound=1000))
def test_ints(a, b):
    check_pair(a, b)


@SETTINGS
@given(convex_float(max_size=12), convex_float(max_size=12))
def test_floats(a, b):
    check_pair(a, b)


@SETTINGS
@given(
    convex_float(max_size=10),
    st.sampled_from([0.0, 1e-9, 1.0, 1e3]),
    st.integers(0, 7),
)
def test_floats_shifted_near_contact(a, gap, turn):
    """B = A moved along an axis by about its width, so touching and near-touching
    pairs are common (the float shift rounds)."""
    xs = [p[0] for p in a]
    ys = [p[1] for p in a]
    w = (max(xs) - min(xs), max(ys) - min(ys))
    v = [(w[0] + gap, 0.0), (0.0, w[1] + gap), (-w[0] - gap, 0.0), (w[0] / 2, w[1] / 2)][turn % 4]
    b = [(x + v[0], y + v[1]) for x, y in a]
    assume(mk.is_convex(b))  # the rounded shift can turn a near-straight vertex reflex
    check_pair(a, b)


@settings(max_examples=60, deadline=None)
@given(convex_int(max_size=10, bound=50), convex_int(max_size=10, bound=50))
def test_kernel_agrees_with_exact_python_path(a, b):
    for mode in (0, 1, 2, 3):
        h1, r1 = C._pair(a, b, mode, False)
        h2, r2 = C._py_pair(D.exact_rows(a), D.exact_rows(b), mode)
        assert h1 == h2
        if mode in (1, 2):
            assert abs(r1[0] - r2[0]) <= 1e-13 * max(1.0, abs(r2[0]))


@SETTINGS
@given(convex_tiny_offsets(), convex_tiny_offsets())
def test_tiny_offsets_from_a_grid(a, b):
    """Grid polygons with vertices moved or doubled by subnormal-to-1e-150 amounts:
    edges of length ~1e-170, parallel edges, and values the kernels leave to the exact
    path. Distance and penetration witnesses on the boundaries, as everywhere."""
    check_pair(a, b)


@SETTINGS
@given(convex_tiny_offsets(), st.integers(-6, 6), st.integers(-6, 6))
def test_tiny_offsets_shifted(a, dx, dy):
    """B = A moved by a multiple of a quarter grid step (its hull after the rounding):
    overlaps whose nearest boundary is a pair of parallel edges of A and B are common."""
    b = oracle.hull([(x + dx * 0.25, y + dy * 0.25) for x, y in a])
    check_pair(a, [(float(x), float(y)) for x, y in b])


@SETTINGS
@given(convex_int(max_size=10, bound=6), convex_int(max_size=10, bound=6))
def test_small_fractions_exact_path(a, b):
    """The degenerate-rich small-int pairs as Fractions: everything on the exact path."""
    check_pair([(F(x), F(y)) for x, y in a], [(F(x), F(y)) for x, y in b])


def test_penetration_witnesses_on_parallel_edges_regression():
    """The exact path chose the first sub-edge at the smallest exact depth; with parallel
    edges of A and -B that is one of two collinear sub-edges, and the origin's foot was on
    the other: point_a = (1, 1.5) was off A (the hypothesis example; its 1.5e-173 sends
    the pair to the exact path). The kernel already took an edge whose foot is on it."""
    a = [(1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (0.0, 1.4868162835879183e-173)]
    b = [(x + 0.5, y + 0.5) for x, y in a]
    p = mk.penetration(a, b)
    assert p.depth == 0.5
    assert p.normal.tolist() == [1.0, 0.0]
    assert p.point_a.tolist() == [1.0, 1.0]
    assert p.point_b.tolist() == [0.5, 1.0]
    check_pair(a, b)
    pm = mk.penetration_many([a], [b])
    assert pm.point_a[0].tolist() == [1.0, 1.0] and pm.point_b[0].tolist() == [0.5, 1.0]
    # the same on the exact path without tiny values: Fractions and ints beyond 2**53,
    # and on the kernel (plain floats), all four directions
    sq = [(0, 0), (2, 0), (2, 2), (0, 2)]
    for v in [(1, 1), (-1, 1), (-1, -1), (1, -1)]:
        other = [(x + v[0], y + v[1]) for x, y in sq]
        want = mk.penetration(sq, other)
        for conv, k in ((F, 1.0), (lambda t: t << 60, 2.0**60), (float, 1.0)):
            pa = [(conv(x), conv(y)) for x, y in sq]
            pb = [(conv(x), conv(y)) for x, y in other]
            check_pair(pa, pb)
            got = mk.penetration(pa, pb)
            assert got.depth == want.depth * k
            assert got.point_a.tolist() == (want.point_a * k).tolist()
            assert got.point_b.tolist() == (want.point_b * k).tolist()


# --------------------------------------------------------------------------------------
# named cases

SQ = [(0, 0), (2, 0), (2, 2), (0, 2)]


@pytest.mark.parametrize(
    "b, inside",
    [
        ([(2, 2), (3, 2), (3, 3)], True),  # touching at a vertex
        ([(2, 0), (4, 0), (4, 2), (2, 2)], True),  # sharing an edge
        ([(2, 1), (3, 0), (3, 3)], True),  # B's vertex on A's edge
        ([(1, 3), (3, 1), (3, 3)], True),  # its edge passes through the corner
        ([(1.5, 3), (3, 1.5), (3, 3)], False),  # across the corner, apart
        ([(1, 1)], True),  # a point inside
        ([(2, 1)], True),  # a point on the boundary
        ([(3, 1)], False),
        ([(0, 0), (2, 0), (2, 2), (0, 2)], True),  # identical
        ([(-1, -1), (3, -1), (3, 3), (-1, 3)], True),  # A nested in B
        ([(1, 1), (1.5, 1), (1, 1.5)], True),  # B nested in A
        ([(-1, 1), (3, 1)], True),  # a segment through A
        ([(2, -1), (2, 3)], True),  # a segment along A's edge line
        ([(3, -1), (3, 3)], False),
        ([(2, 3), (2, 5)], False),  # collinear with A's edge, beyond its end
        ([(2, 2), (2, 5)], True),  # collinear, touching the end
    ],
)
def test_named(b, inside):
    assert mk.intersects(SQ, b) is inside
    check_pair(SQ, b)


def test_segments_and_points():
    for a, b in [
        ([(0, 0), (4, 0)], [(2, 0), (6, 0)]),  # overlapping collinear segments
        ([(0, 0), (4, 0)], [(5, 0), (6, 0)]),  # collinear, apart
        ([(0, 0), (4, 0)], [(4, 0), (6, 0)]),  # collinear, touching at an end
        ([(0, 0), (4, 4)], [(0, 4), (4, 0)]),  # crossing
        ([(0, 0), (4, 4)], [(1, 0), (5, 4)]),  # parallel
        ([(0, 0)], [(0, 0)]),
        ([(0, 0)], [(3, 4)]),
        ([(0, 0)], [(1, -1), (1, 1)]),
    ]:
        check_pair(a, b)
        check_pair(b, a)
    assert mk.distance([(0, 0)], [(3, 4)]).distance == 5.0
    assert mk.penetration([(0, 0)], [(0, 0)]).normal.tolist() == [0.0, 0.0]


def test_one_ulp_apart_and_overlapping():
    u = math.ulp(1.0)
    a = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    apart = [(1.0 + u, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0 + u, 1.0)]
    over = [(1.0 - u / 2, 0.25), (2.0, 0.25), (2.0, 0.75), (1.0 - u / 2, 0.75)]
    assert not mk.intersects(a, apart)
    assert not mk.intersects(a, apart, method="gjk")
    assert mk.distance(a, apart).distance == u
    assert mk.penetration(a, apart).depth == -u
    assert mk.intersects(a, over) and mk.intersects(a, over, method="gjk")
    p = mk.penetration(a, over)
    assert p.depth == u / 2 and p.normal.tolist() == [1.0, 0.0]
    check_pair(a, apart)
    check_pair(a, over)


def test_near_touching_slanted_edge():
    """B's vertex is the float nearest to a point on A's slanted edge: the exact answer
    depends on bits far below the float filter's resolution."""
    a = [(0.1, 0.2), (10.3, 7.7), (-3.0, 5.0)]
    for t in (0.25, 0.5, 0.7, 1 / 3):
        x = 0.1 + t * (10.3 - 0.1)
        y = 0.2 + t * (7.7 - 0.2)
        for dx in (0.0, math.ulp(x), -math.ulp(x)):
            b = [(x + dx, y), (x + 5.0, y - 1.0), (x + 4.0, y - 6.0)]
            check_pair(a, b)


def test_huge_and_tiny_coordinates_take_the_exact_path():
    big = 1 << 62
    a = [(big, big), (big + 2, big), (big + 2, big + 2), (big, big + 2)]
    b = [(big + 3, big), (big + 5, big), (big + 5, big + 2)]
    assert not mk.intersects(a, b) and not mk.intersects(a, b, method="gjk")
    assert mk.distance(a, b).distance == 1.0
    check_pair(a, b)
    b2 = [(big + 1, big + 1), (big + 5, big), (big + 5, big + 2)]
    check_pair(a, b2)
    for s in (2.0**-1000, 2.0**1000, 2.0**450, 2.0**-450):
        fa = [(x * s, y * s) for x, y in [(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)]]
        fb = [(x * s, y * s) for x, y in [(3.0, 1.0), (4.0, 0.0), (4.0, 5.0)]]
        assert mk.distance(fa, fb).distance == s
        check_pair(fa, fb, witness_tol=1e-9)
        fb2 = [(x * s, y * s) for x, y in [(1.5, 1.0), (4.0, 0.0), (4.0, 5.0)]]
        assert mk.penetration(fa, fb2).depth == pytest.approx(0.5 * s, rel=1e-15)
    fr = [(F(1, 3), F(0)), (F(2, 3), F(0)), (F(1, 2), F(1, 7))]
    fr2 = [(F(2, 3), F(0)), (F(1), F(0)), (F(5, 6), F(1, 7))]
    assert mk.intersects(fr, fr2) and mk.intersects(fr, fr2, method="gjk")
    assert mk.penetration(fr, fr2).depth == 0.0


def test_nested_and_identical_many_sizes():
    t = np.linspace(0, 2 * np.pi, 65)[:-1]
    big = np.stack([np.cos(t), np.sin(t)], 1) * 10
    small = big / 10
    for a, b in ((big, big), (big, small), (small, big), (big, big + 1e-9)):
        for method in ("sum", "gjk"):
            assert mk.intersects(a, b, method=method)
    p = mk.penetration(big, small)
    # the small disk must move until it leaves the big one: about 11 (within polygon slack)
    assert 10.5 < p.depth < 11.0
    assert mk.distance(big, small).distance == 0.0


def test_gjk_origin_on_simplex_edge_and_cycling_shapes():
    # regular polygons touching edge to edge and vertex to vertex, many rotations
    t = np.linspace(0, 2 * np.pi, 9)[:-1]
    oct_ = np.stack([np.cos(t), np.sin(t)], 1)
    w = 2 * np.cos(np.pi / 8)  # flat-to-flat width
    for k in range(8):
        ang = k * np.pi / 4 + np.pi / 8
        v = (w * np.cos(ang), w * np.sin(ang))
        b = oct_ + v  # touches along a (float) edge: decided exactly either way
        assert mk.intersects(oct_, b, method="gjk") == mk.intersects(oct_, b, method="sum")
    ints = [(0, 0), (4, 0), (4, 4), (0, 4)]
    for v in [(4, 0), (4, 4), (0, -4), (2, 4), (4, 1), (5, 5), (-4, -4)]:
        b = [(x + v[0], y + v[1]) for x, y in ints]
        assert mk.intersects(ints, b, method="gjk") == mk.intersects(ints, b, method="sum")
        check_pair(ints, b)


@pytest.mark.parametrize("seed", range(6))
def test_large_polygons_take_gjk_under_auto(seed):
    """40-60 vertices each: ``auto`` runs GJK; every method against the reference."""
    rng = np.random.default_rng(seed)
    q = [None, 1000][seed % 2]

    def poly(n, c, r):
        t = np.sort(rng.random(n)) * 2 * np.pi
        p = np.stack([c[0] + r * np.cos(t), c[1] + r * np.sin(t)], 1)
        return mk.convex_hull(np.round(p * q).astype(np.int64)) if q else p

    a = poly(int(rng.integers(40, 60)), (0.0, 0.0), 1.0)
    b = poly(int(rng.integers(40, 60)), rng.normal(size=2) * 1.2, 0.2 + rng.random())
    assert len(a) + len(b) > 64
    check_pair(a.tolist(), b.tolist())


def test_gjk_cases_reported_against_other_libraries():
    """2-D analogues of GJK failures reported elsewhere: boxes stacked face to face
    (libccd issue 25: NaN direction), separated shapes ending on a collinear simplex
    (FCL issue 293: 0/0), a point against a hull hitting the iteration cap (dolfinx
    issue 3653)."""
    sq = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
    for dy in (1.9, 2.0, math.nextafter(2.0, 3.0), math.nextafter(2.0, 0.0)):
        for dx in (0.0, 0.5, 2.0):
            b = [(x + dx, y + dy) for x, y in sq]
            check_pair(sq, b)
    for a, b in (
        ([(0.0, 0.0), (1.0, 0.0)], [(2.0, 0.0), (3.0, 0.0)]),
        ([(0.0, 0.0), (1.0, 1.0)], [(2.0, 2.0), (3.0, 3.0)]),
        ([(0.0, 0.0), (2.0, 0.0), (1.0, 1e-9)], [(3.0, 0.0), (4.0, 0.0), (3.5, 1e-9)]),
    ):
        check_pair(a, b)
    hull = [
        (46.0659, 38.6251),
        (44.2764, 42.3867),
        (50.0397, 38.4649),
        (47.1963, 40.4563),
        (48.0266, 38.5593),
        (45.1735, 40.495),
        (48.0415, 40.4456),
    ]
    for p in ([(44.2919, 39.7508)], [(46.0659, 38.6251)], [(47.0, 40.0)]):
        assert mk.intersects(p, hull, hull=True, method="gjk") == mk.intersects(
            p, hull, hull=True, method="sum"
        )
        check_pair(p, [tuple(v) for v in mk.convex_hull(hull).tolist()])


# --------------------------------------------------------------------------------------
# contains


def test_contains_examples():
    tri = [(0, 0), (4, 0), (0, 4)]
    pts = [(1, 1), (2, 2), (0, 0), (4, 0), (0, 2), (3, 3), (-1, 0), (5, 0), (2, -1)]
    assert mk.contains(tri, pts).tolist() == [True, True, True, True, True] + [False] * 4
    assert mk.contains(tri, (2, 2)) is True
    assert mk.contains([(0, 0), (4, 4)], [(2, 2), (5, 5), (2, 3)]).tolist() == [True, False, False]
    assert mk.contains([(1, 1)], [(1, 1), (1, 2)]).tolist() == [True, False]
    assert mk.contains(tri, np.zeros((0, 2))).shape == (0,)


@SETTINGS
@given(
    convex_float(max_size=12) | convex_int(max_size=12, bound=8),
    st.lists(st.tuples(st.integers(-9, 9), st.integers(-9, 9)), min_size=1, max_size=20),
)
def test_contains_against_reference(poly, pts):
    H = oracle.hull(poly)
    # query grid points plus the polygon's own vertices and edge midpoints
    qs = list(pts) + [tuple(p) for p in poly]
    qs += [((p[0] + q[0]) / 2, (p[1] + q[1]) / 2) for p, q in zip(poly, poly[1:])]
    got = mk.contains(poly, qs)
    assert got.tolist() == [ref_inside(H, (F(x), F(y))) for x, y in qs]


def test_contains_exact_near_boundary_and_huge():
    a = [(0.1, 0.2), (10.3, 7.7), (-3.0, 5.0)]
    x = 0.1 + 0.3 * 10.2
    y = 0.2 + 0.3 * 7.5
    qs = [(x, y), (math.nextafter(x, 99), y), (math.nextafter(x, -99), y)]
    H = oracle.hull(a)
    assert mk.contains(a, qs).tolist() == [ref_inside(H, q) for q in qs]
    big = 1 << 70
    sq = [(big, big), (big + 4, big), (big + 4, big + 4), (big, big + 4)]
    assert mk.contains(sq, [(big + 4, big + 2), (big + 5, big + 2)]).tolist() == [True, False]


# --------------------------------------------------------------------------------------
# batches


def _pairs(rng, P, n):
    As, Bs = [], []
    for _ in range(P):
        for lst in (As, Bs):
            k = rng.integers(1, n + 1)
            pts = rng.integers(-6, 7, size=(k, 2))
            lst.append(mk.convex_hull(pts) + rng.integers(-4, 5, size=2))
    return As, Bs


@pytest.mark.parametrize("n", [8, 40])
def test_batch_identical_to_single(n):
    rng = np.random.default_rng(n)
    As, Bs = _pairs(rng, 150, n)
    fl = [a.astype(float) * 0.37 for a in As], [b.astype(float) * 0.37 for b in Bs]
    for A, B in ((As, Bs), fl, (Ragged.from_list(As), Ragged.from_list(Bs))):
        for method in ("auto", "sum", "gjk"):
            got = mk.intersects_many(A, B, method=method)
            assert got.tolist() == [mk.intersects(a, b, method=method) for a, b in zip(A, B)]
        d = mk.distance_many(A, B)
        p = mk.penetration_many(A, B)
        for k, (a, b) in enumerate(zip(A, B)):
            ds = mk.distance(a, b)
            assert d.distance[k] == ds.distance
            assert d.point_a[k].tolist() == ds.point_a.tolist()
            assert d.point_b[k].tolist() == ds.point_b.tolist()
            ps = mk.penetration(a, b)
            assert p.depth[k] == ps.depth
            assert p.normal[k].tolist() == ps.normal.tolist()
            assert p.point_a[k].tolist() == ps.point_a.tolist()
            assert p.point_b[k].tolist() == ps.point_b.tolist()


def test_batch_one_against_many():
    rng = np.random.default_rng(5)
    _, Bs = _pairs(rng, 60, 10)
    robot = [(0, 0), (3, 0), (3, 2), (0, 2)]
    for a_many, args in ((False, (robot, Bs)), (True, (Bs, robot))):
        hit = mk.intersects_many(*args)
        d = mk.distance_many(*args)
        p = mk.penetration_many(*args)
        for k, b in enumerate(Bs):
            pair = (b, robot) if a_many else (robot, b)
            assert hit[k] == mk.intersects(*pair)
            assert d.distance[k] == mk.distance(*pair).distance
            assert p.depth[k] == mk.penetration(*pair).depth


def test_batch_exact_fallback_and_shapely():
    big = 1 << 60
    As = Ragged.from_list([np.array([(big, 0), (big + 2, 0), (big, 2)], dtype=np.int64)] * 2)
    Bs = Ragged.from_list(
        [
            np.array([(big + 1, 1), (big + 3, 1), (big + 3, 3)], dtype=np.int64),
            np.array([(big + 3, 0), (big + 4, 0), (big + 4, 1)], dtype=np.int64),
        ]
    )
    assert mk.intersects_many(As, Bs).tolist() == [True, False]
    assert mk.distance_many(As, Bs).distance.tolist() == [0.0, 1.0]
    shapely = pytest.importorskip("shapely")
    g = [shapely.Polygon(SQ), shapely.Polygon([(3, 0), (4, 0), (4, 1)])]
    assert mk.intersects_many(g, [(2, 2), (3, 3), (2, 3)]).tolist() == [True, False]
    assert mk.intersects(shapely.Polygon(SQ), shapely.Point(2, 2))


# --------------------------------------------------------------------------------------
# bad input


def test_errors():
    star = [(0, 0), (2, 6), (4, 0), (-1, 4), (5, 4)]
    with pytest.raises(NotConvexError, match="b: not convex"):
        mk.intersects(SQ, star)
    with pytest.raises(NotConvexError, match="a: not convex"):
        mk.distance(star, SQ)
    with pytest.raises(NotConvexError, match="poly"):
        mk.contains(star, [(1, 1)])
    assert mk.intersects(star, SQ, hull=True)
    with pytest.raises(NotConvexError, match=r"Bs\[1\]"):
        mk.penetration_many(SQ, [SQ, star])
    with pytest.raises(EmptyGeometryError, match="a: empty"):
        mk.intersects([], SQ)
    with pytest.raises(NonFiniteError, match="b: vertex 1"):
        mk.distance(SQ, [(0.0, 0.0), (float("nan"), 1.0)])
    with pytest.raises(ShapeError):
        mk.intersects([(1, 2, 3)], SQ)
    with pytest.raises(ShapeError, match="points"):
        mk.contains(SQ, (1, 2, 3))
    with pytest.raises(ValueError, match="method"):
        mk.intersects(SQ, SQ, method="epa")
    with pytest.raises(ShapeError, match="equal counts"):
        mk.intersects_many([SQ, SQ], [SQ])
    with pytest.raises(TypeError):
        mk.intersects(SQ, SQ, "gjk")  # method is keyword-only


def test_common_point_on_a_thin_minkowski_difference():
    """Regression: two nearly parallel overlapping segments make A ⊕ (−B) a sliver; the
    witnesses of distance 0 must still be a common point (float barycentric weights had
    put them 524,289 apart)."""
    a = [(-1.0, 1e-09), (0.0, 349526.0)]
    w = (1.0, 349526.0 - 1e-09)  # the falsifying example: B = A moved by half its extent
    b = [(x + w[0] / 2, y + w[1] / 2) for x, y in a]
    check_pair(a, b)
    d = mk.distance(a, b)
    assert d.distance == 0.0
    assert math.hypot(*(d.point_a - d.point_b)) <= 1e-9


@SETTINGS
@given(convex_float(max_size=12), convex_float(max_size=12), st.floats(0.0, 1.0))
def test_overlapping_distance_witnesses_are_one_point(a, b, t):
    """When the polygons intersect, distance() documents point_a == point_b; the
    two witnesses must be the very same floats (they used to differ by an ulp)."""
    # move B so that its first vertex lands between A's centroid and A's first vertex:
    # the pair then overlaps (or touches) in most examples
    ca = np.mean(np.array(a, float), axis=0)
    tgt = ca + t * (np.array(a[0], float) - ca)
    b = [(x - b[0][0] + tgt[0], y - b[0][1] + tgt[1]) for x, y in b]
    assume(mk.is_convex(b) or len(b) < 3)
    d = mk.distance(a, b)
    if d.distance == 0.0:
        assert d.point_a.tolist() == d.point_b.tolist()
    dm = mk.distance_many([a], [b])
    assert dm.point_a[0].tolist() == d.point_a.tolist()
    assert dm.point_b[0].tolist() == d.point_b.tolist()


def test_overlapping_distance_witnesses_regression():
    """The reported shape of the bug: overlapping interiors (the common point
    comes from float barycentric weights), witnesses identical bit for bit, also on the
    exact path (Fractions) and in the batch."""
    tri = [(0.1, 0.2), (10.3, 7.7), (-3.0, 5.0)]
    for s in (0.3, 1.7, 2.9):
        other = [(x * 0.7 + s, y * 0.9 - s / 3) for x, y in tri]
        d = mk.distance(tri, other)
        assert d.distance == 0.0
        assert d.point_a.tolist() == d.point_b.tolist()
        fr = [(F(x), F(y)) for x, y in other]
        de = mk.distance([(F(x), F(y)) for x, y in tri], fr)
        assert de.distance == 0.0 and de.point_a.tolist() == de.point_b.tolist()
    a = [(-1.0, 1e-09), (0.0, 349526.0)]
    w = (1.0, 349526.0 - 1e-09)
    b = [(x + w[0] / 2, y + w[1] / 2) for x, y in a]
    d = mk.distance(a, b)
    assert d.point_a.tolist() == d.point_b.tolist()
    rng = np.random.default_rng(9)
    As, Bs = _pairs(rng, 300, 10)
    As = [x.astype(float) * 0.37 for x in As]
    Bs = [x.astype(float) * 0.41 for x in Bs]
    dm = mk.distance_many(As, Bs)
    hit = mk.intersects_many(As, Bs)
    assert hit.any()
    assert (dm.distance[hit] == 0.0).all()
    assert (dm.point_a[hit] == dm.point_b[hit]).all()


@pytest.mark.parametrize("threads", [2, 3, 8])
def test_batch_threads_identical(threads):
    """threads splits the pairs over std::threads; every result is bit-identical to the
    single-threaded run."""
    rng = np.random.default_rng(threads)
    As, Bs = _pairs(rng, 700, 12)
    fl = [a.astype(float) * 0.37 for a in As], [b.astype(float) * 0.53 for b in Bs]
    for A, B in ((As, Bs), fl, (Ragged.from_list(As), Ragged.from_list(Bs)), (As[0], Bs)):
        for method in ("auto", "sum", "gjk"):
            one = mk.intersects_many(A, B, method=method)
            many = mk.intersects_many(A, B, method=method, threads=threads)
            assert many.tolist() == one.tolist()
        d1, dn = mk.distance_many(A, B), mk.distance_many(A, B, threads=threads)
        p1, pn = mk.penetration_many(A, B), mk.penetration_many(A, B, threads=threads)
        for x, y in zip((*d1, *p1), (*dn, *pn)):
            assert np.array_equal(x, y)


def test_batch_threads_argument():
    for bad in (0, -1, 1.5, "2", True):
        with pytest.raises(ValueError, match="threads"):
            mk.intersects_many([SQ], [SQ], threads=bad)
    assert mk.distance_many([SQ], [SQ], threads=4).distance.tolist() == [0.0]
    # the normalization runs in chunks too: the first bad polygon is still the one named
    star = [(0, 0), (2, 6), (4, 0), (-1, 4), (5, 4)]
    Bs = [SQ] * 300 + [star] + [SQ] * 100 + [star] + [SQ] * 20
    for threads in (1, 2, 5):
        with pytest.raises(NotConvexError, match=r"^Bs\[300\]: not convex") as exc:
            mk.penetration_many(SQ, Bs, threads=threads)
        assert exc.value.argument == "Bs[300]" and exc.value.vertex is not None


@pytest.mark.parametrize(
    "scale", [2.0**-1070, 2.0**-1000, 2.0**-450, 2.0**450, 2.0**1000, 1e307, 5e307]
)
def test_signs_at_every_float_magnitude(scale):
    """intersects (walk and GJK, single and batch) and contains decide on the compiled
    path at any finite magnitude (subnormals, overflowing differences) and agree with the
    exact reference."""
    rng = np.random.default_rng(int(abs(math.log2(scale))))
    As, Bs = [], []
    for _ in range(60):
        for lst in (As, Bs):
            pts = rng.integers(-3, 4, size=(int(rng.integers(1, 7)), 2))
            lst.append(mk.convex_hull(pts).astype(float) * scale)
    want = [ref_inside(d_hull(a.tolist(), b.tolist())) for a, b in zip(As, Bs)]
    for method in ("auto", "sum", "gjk"):
        assert mk.intersects_many(As, Bs, method=method).tolist() == want
        assert [mk.intersects(a, b, method=method) for a, b in zip(As, Bs)] == want
    qs = [tuple(v) for v in (rng.integers(-3, 4, size=(40, 2)) * scale).tolist()]
    for a in As[:10]:
        H = oracle.hull(a.tolist())
        assert mk.contains(a, qs).tolist() == [ref_inside(H, (F(x), F(y))) for x, y in qs]


@settings(max_examples=300, deadline=None)
@given(st.lists(st.tuples(st.integers(-4, 4), st.integers(-4, 4)), min_size=1, max_size=9))
def test_exact_normalization_matches_the_core(pts):
    """The exact path normalizes through the core's int64 normalization; polygons wider
    than 2**62 take its exact-Python twin, which must agree on everything (indices,
    split, error kind and vertex) -- checked here on any point list, convex or not."""

    def run(f, p):
        try:
            return f(p, "a")
        except NotConvexError as exc:
            return (type(exc), exc.vertex, str(exc))

    from minkowski2d._engine import exact as _exact
    from minkowski2d._engine import exact_collision

    def exact_twin(p, name):
        _, idx, split = _exact.normalize_list(p, name)
        return idx, split

    core = run(exact_collision._exact_normalize, pts)
    assert run(exact_twin, pts) == core
    wide = [(x << 70, y << 70) for x, y in pts]
    assert run(exact_collision._exact_normalize, wide) == core
