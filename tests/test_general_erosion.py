"""Erosion ``A ⊖ B = {c : c + B ⊆ A}`` when B does not hold its own origin: the
named cases, the inner-fit polygon of a part in a rectangular sheet (exact),
and random small integer polygons against a brute-force oracle (``c + B ⊆ A`` decided
exactly for sampled rational c)."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import minkowski2d as mk

from . import oracle
from .strategies import convex_int
from .test_general import DATA, read_dat, star_ring

L_BIG = [(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)]


def square(x0, y0, s):
    return [(x0, y0), (x0 + s, y0), (x0 + s, y0 + s), (x0, y0 + s)]


def shift(ring, dx, dy):
    return [(x + dx, y + dy) for x, y in ring]


# --------------------------------------------------------------------------------------
# the named cases of the issue


def test_L_by_a_square_far_from_the_origin():
    E = mk.minkowski_difference(L_BIG, square(10, 10, 1))
    assert E.area == 5
    ref = shapely.Polygon([(-10, -10), (-7, -10), (-7, -9), (-9, -9), (-9, -7), (-10, -7)])
    assert E.symmetric_difference(ref).area == 0
    # the same with B at the origin, then translated: (A ⊖ (B + t)) = (A ⊖ B) - t
    E0 = mk.minkowski_difference(L_BIG, square(0, 0, 1))
    assert shapely.affinity.translate(E0, -10, -10).symmetric_difference(E).area == 0


def test_square_by_a_non_convex_part_off_the_origin():
    part = [(1, 1), (3, 1), (3, 2), (2, 2), (2, 3), (1, 3)]
    E = mk.minkowski_difference(square(0, 0, 10), part)
    assert E.equals(shapely.Polygon(square(-1, -1, 8)))
    assert shapely.get_coordinates(E).tolist() == [[-1, -1], [7, -1], [7, 7], [-1, 7], [-1, -1]]


def test_convex_path_off_the_origin():
    sq = square(0, 0, 10)
    assert mk.minkowski_difference(sq, square(1, 1, 2)).equals(shapely.Polygon(square(-1, -1, 8)))
    assert mk.minkowski_difference(sq, square(20, -30, 10)).equals(shapely.Point(-20, 30))
    assert mk.minkowski_difference(sq, [(5, 5), (5, 9)]).equals(
        shapely.Polygon([(-5, -5), (5, -5), (5, 1), (-5, 1)])
    )


def test_non_convex_a_with_a_hole_and_b_off_the_origin():
    frame = shapely.Polygon(square(0, 0, 10), [square(4, 4, 2)[::-1]])
    b0 = [(0, 0), (2, 0), (1, 1)]
    for dx, dy in [(0, 0), (7, -3), (-20, 50)]:
        E = mk.minkowski_difference(frame, shift(b0, dx, dy))
        E0 = mk.minkowski_difference(frame, b0)
        assert shapely.affinity.translate(E0, -dx, -dy).symmetric_difference(E).area <= 1e-12
        assert sum(len(p.interiors) for p in shapely.get_parts(E)) == 1


# --------------------------------------------------------------------------------------
# nesting: the inner-fit polygon of a part in a rectangular sheet is exact


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])
@given(
    star_ring(max_n=8),
    st.integers(-50, 50),
    st.integers(-50, 50),
    st.integers(1, 80),
    st.integers(1, 80),
    st.integers(-100, 100),
    st.integers(-100, 100),
    st.booleans(),
)
def test_inner_fit_polygon_in_a_rectangular_sheet(part, ox, oy, w, h, dx, dy, convex):
    if convex:
        part = [tuple(p) for p in oracle.hull(part)]
        part = [(int(x), int(y)) for x, y in part]
    part = shift(part, dx, dy)
    sheet = [(ox, oy), (ox + w, oy), (ox + w, oy + h), (ox, oy + h)]
    xs = [p[0] for p in part]
    ys = [p[1] for p in part]
    x0, x1 = ox - min(xs), ox + w - max(xs)
    y0, y1 = oy - min(ys), oy + h - max(ys)
    E = mk.minkowski_difference(sheet, part)
    if x0 > x1 or y0 > y1:
        assert E.is_empty
        return
    corners = {(x0, y0), (x1, y0), (x1, y1), (x0, y1)}
    assert {tuple(c) for c in shapely.get_coordinates(E).tolist()} == corners
    kind = {4: "Polygon", 2: "LineString", 1: "Point"}[len(corners)]
    assert E.geom_type == kind


# --------------------------------------------------------------------------------------
# random small integer polygons against the brute-force oracle


def fits(A, B, c) -> bool:
    """c + B ⊆ A: GEOS predicates are exact on these small dyadic coordinates."""
    return A.covers(shapely.affinity.translate(B, float(c[0]), float(c[1])))


def check_by_oracle(A, B, E, rng, n=120):
    """Every sampled candidate c (quarter-integers over bbox(A) ⊖ bbox(B), grown by 2, and
    points inside E) is in E exactly when c + B ⊆ A (points within 1e-9 of E's boundary
    are skipped: rounding, not the definition, decides them)."""
    ax0, ay0, ax1, ay1 = A.bounds
    bx0, by0, bx1, by1 = B.bounds
    lo = np.array([ax0 - bx0 - 2, ay0 - by0 - 2])
    hi = np.array([ax1 - bx1 + 2, ay1 - by1 + 2])
    hi = np.maximum(hi, lo + 1)
    cand = np.round(rng.uniform(lo, hi, (n, 2)) * 4) / 4
    if not E.is_empty and E.area > 0:
        reps = shapely.get_coordinates(shapely.point_on_surface(shapely.get_parts(E)))
        cand = np.vstack([cand, reps])
    edge = E if E.is_empty or E.area == 0 else E.boundary
    checked = 0
    for c in cand:
        p = shapely.Point(c)
        if not E.is_empty and edge.distance(p) < 1e-9:
            continue
        inside = not E.is_empty and E.covers(p)
        if fits(A, B, c) and not inside:
            # allowed only on a part of the erosion without area (the result is the
            # closure of the interior): then most nearby translations do not fit
            assert sum(fits(A, B, c + d) for d in NEAR) <= 2, (c, A.wkt, B.wkt, E.wkt)
        else:
            assert fits(A, B, c) == inside, (c, A.wkt, B.wkt, E.wkt)
        checked += 1
    return checked


# four directions that no line through integer or quarter-integer points follows
NEAR = [1e-4 * np.array([np.cos(t), np.sin(t)]) for t in 0.3 + np.arange(4) * np.pi / 2]


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])
@given(
    star_ring(max_n=9),
    st.lists(st.tuples(st.integers(-6, 6), st.integers(-6, 6)), min_size=3, max_size=7),
    st.integers(-30, 30),
    st.integers(-30, 30),
    st.integers(0, 2**32 - 1),
)
def test_erosion_against_the_oracle(ra, rb_pts, dx, dy, seed):
    # B: a small simple polygon (the star-shaped ordering of random points) off the origin
    pts = sorted(set(rb_pts), key=lambda p: (np.arctan2(p[1], p[0]), p[0] ** 2 + p[1] ** 2))
    B = shapely.Polygon(shift(pts, dx, dy)) if len(pts) >= 3 else None
    assume(B is not None and B.is_valid and B.area > 0)
    A = shapely.Polygon(ra)
    E = mk.minkowski_difference(A, B)
    assert E.is_empty or E.is_valid
    check_by_oracle(A, B, E, np.random.default_rng(seed))
    # translating B by t translates the erosion by -t
    E0 = mk.minkowski_difference(A, shapely.affinity.translate(B, -dx, -dy))
    moved = shapely.affinity.translate(E0, -dx, -dy)
    assert moved.is_empty == E.is_empty
    if not E.is_empty:
        # (not the symmetric difference: GEOS 3.14 overlays two triangles that differ by
        # one ulp into an empty intersection)
        assert moved.hausdorff_distance(E) <= 1e-12 * 64


@settings(max_examples=30, deadline=None)
@given(convex_int(max_size=8, bound=40), convex_int(max_size=6, bound=8), st.integers(0, 99))
def test_convex_erosion_against_the_oracle(a, b, seed):
    na, nb = mk.normalize(a), mk.normalize(b)
    assume(len(na) >= 3 and len(nb) >= 3)
    A, B = shapely.Polygon(na), shapely.Polygon(nb)
    E = mk.minkowski_difference(a, b)
    if E.geom_type == "Polygon" and not E.is_empty:
        check_by_oracle(A, B, E, np.random.default_rng(seed))
    # every vertex of E fits exactly (the vertices are exact rationals rounded once; on
    # these small integers the rounding is far below the 2**-20 slack allowed here)
    for x, y in shapely.get_coordinates(E).tolist():
        c = (Fraction(x), Fraction(y))
        Av = [oracle.exact(p) for p in na.tolist()]
        for bx, by in nb.tolist():
            q = (c[0] + Fraction(bx), c[1] + Fraction(by))
            for i in range(len(Av)):
                assert oracle.cross(Av[i], Av[(i + 1) % len(Av)], q) >= -Fraction(1, 2**20)


@pytest.mark.parametrize(
    "a",
    [
        L_BIG,
        [(0, 0), (10, 0), (10, 3), (4, 3), (4, 10), (0, 10)],
        shapely.Polygon(square(0, 0, 12), [square(5, 5, 2)[::-1]]),
    ],
)
@pytest.mark.parametrize(
    "b",
    [
        square(10, 10, 1),
        [(-7, 3), (-5, 3), (-5, 4), (-6, 4), (-6, 5), (-7, 5)],
        [(100, 100), (101, 100), (100, 101)],
        [(3, -40), (3, -38)],  # a segment
        [(-9, -9)],  # a point: the erosion is A translated
    ],
)
def test_erosion_named_grid(a, b):
    A = a if hasattr(a, "geom_type") else shapely.Polygon(a)
    B = shapely.Polygon(b) if len(b) >= 3 else shapely.LineString(b) if len(b) == 2 else None
    E = mk.minkowski_difference(a, b)
    if B is None:
        assert E.symmetric_difference(shapely.affinity.translate(A, 9, 9)).area == 0
        return
    assert check_by_oracle(A, B, E, np.random.default_rng(1), n=300) > 150


def test_b_with_a_hole_fits_around_a_hole_of_a():
    # a ring of width 1 around A's hole: it fits wherever its hole covers A's hole
    A = shapely.Polygon(square(0, 0, 10), [square(4, 4, 2)[::-1]])
    for dx, dy in [(0, 0), (-30, 17)]:
        B = shapely.Polygon(square(dx, dy, 6), [square(dx + 1, dy + 1, 4)[::-1]])
        E = mk.minkowski_difference(A, B)
        assert E.equals(shapely.Polygon(square(1 - dx, 1 - dy, 2)))
        assert check_by_oracle(A, B, E, np.random.default_rng(2), n=200) > 100


def test_b_in_two_parts():
    A = shapely.Polygon([(0, 0), (12, 0), (12, 3), (9, 3), (9, 8), (3, 8), (3, 3), (0, 3)])
    B = shapely.MultiPolygon(
        [shapely.Polygon(square(20, 20, 1)), shapely.Polygon(square(30, 20, 1))]
    )
    E = mk.minkowski_difference(A, B)
    assert E.area > 0
    assert check_by_oracle(A, B, E, np.random.default_rng(3), n=300) > 150


@pytest.mark.skipif(not DATA.is_dir(), reason="CGAL test polygons not found")
@pytest.mark.parametrize(
    ("p", "q"),
    [
        ("comb_part1", "small_robot"),
        ("rooms_part1", "small_convex_robot"),
        ("pwh4", "pwh2"),
        ("knife_part1", "small_convex_robot"),
    ],
)
def test_corpus_erosion_by_a_shifted_b(p, q):
    """The corpus robots moved far off their origin: the erosion moves the other way and
    still agrees with the oracle."""
    a, b = read_dat(p), read_dat(q)
    B = b if hasattr(b, "geom_type") else shapely.Polygon(b)
    A = a if hasattr(a, "geom_type") else shapely.Polygon(a)
    t = (1000.5, -731.25)
    Bt = shapely.affinity.translate(B, *t)
    E0 = mk.minkowski_difference(a, b)
    E = mk.minkowski_difference(a, Bt)
    assert E.is_empty == E0.is_empty
    if not E.is_empty:
        assert shapely.affinity.translate(E0, -t[0], -t[1]).hausdorff_distance(E) <= 1e-9 * 2000
    check_by_oracle(A, Bt, E, np.random.default_rng(4), n=150)
