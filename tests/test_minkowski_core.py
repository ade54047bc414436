"""Non-convex sums and erosion in the core, against exact oracles.

* The two methods (full convolution, union of piece sums) give identical vertex sets, on
  random polygons with holes (integer and float coordinates).
* For integer coordinates every convex piece sum is exact in float64, so the exact
  Fraction oracle of tests/overlay_oracle.py applied to the piece sums is the exact sum:
  the core's vertices must be its vertices, correctly rounded.
* The erosion equals the oracle's ``G \\ ((box \\ A) ⊕ (−B))`` built the same way from
  exact integer pieces.
* Hole filling of the convolution (a hole the other operand cannot fit into changes
  nothing and is filled; one it can fit into cannot be surrounded) on named cases.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import minkowski2d as mk
from tests.overlay_oracle import boundary
from tests.strategies import regular_star


def vset(g):
    return set(map(tuple, shapely.get_coordinates(g).tolist()))


def star_polygon(draw, n, integer, scale=4):
    ang = sorted(draw(st.lists(st.floats(0, 2 * math.pi), min_size=n, max_size=n, unique=True)))
    rad = draw(st.lists(st.floats(1, scale), min_size=n, max_size=n))
    pts = [(r * math.cos(t), r * math.sin(t)) for r, t in zip(rad, ang, strict=True)]
    if integer:
        pts = [(round(x * 2), round(y * 2)) for x, y in pts]
    return pts


@st.composite
def polygon(draw, integer=True, holes=True):
    n = draw(st.integers(3, 8))
    pts = star_polygon(draw, n, integer)
    p = shapely.Polygon(pts)
    assume(p.is_valid and p.area > 0)
    if holes and draw(st.booleans()):
        f = draw(st.sampled_from([0.25, 0.4]))
        c = p.centroid
        h = shapely.affinity.scale(p, f, f, origin=c)
        if integer:
            h = shapely.Polygon(np.round(shapely.get_coordinates(h.exterior)[:-1]))
        q = shapely.Polygon(p.exterior, [h.exterior]) if h.is_valid and h.area > 0 else p
        if q.is_valid:
            p = q
    return p


@settings(max_examples=80, deadline=None, suppress_health_check=list(HealthCheck))
@given(polygon(integer=True), polygon(integer=True))
def test_both_methods_give_the_same_vertices_int(a, b):
    gc = mk.minkowski_sum_general(a, b, method="convolution")
    gp = mk.minkowski_sum_general(a, b, method="decomposition")
    assert shapely.is_valid(gc) and shapely.is_valid(gp)
    assert vset(gc) == vset(gp)


@settings(max_examples=60, deadline=None, suppress_health_check=list(HealthCheck))
@given(polygon(integer=False), polygon(integer=False))
def test_both_methods_give_the_same_vertices_float(a, b):
    gc = mk.minkowski_sum_general(a, b, method="convolution")
    gp = mk.minkowski_sum_general(a, b, method="decomposition")
    assert shapely.is_valid(gc) and shapely.is_valid(gp)
    assert vset(gc) == vset(gp)


def _piece_sum_rings(a, b):
    PA, PB = mk.convex_decomposition(a), mk.convex_decomposition(b)
    rings = []
    for p in PA.to_list():
        for q in PB.to_list():
            s = mk.minkowski_sum(p, q)  # exact: integer coordinates below 2**53
            if len(s) >= 3:
                rings.append([tuple(v) for v in s.tolist()])
    return rings


@settings(max_examples=25, deadline=None, suppress_health_check=list(HealthCheck))
@given(polygon(integer=True, holes=False), polygon(integer=True, holes=False))
def test_sum_equals_the_exact_oracle(a, b):
    verts, area = boundary(_piece_sum_rings(a, b))
    rounded = {(float(x), float(y)) for x, y in verts}
    for method in ("convolution", "decomposition"):
        g = mk.minkowski_sum_general(a, b, method=method)
        assert vset(g) == rounded
        assert abs(g.area - float(area)) <= 1e-12 * float(area)


def _erosion_oracle(a, b):
    """A ⊖ B with the oracle: G minus the union of the piece sums of (F minus A) and -B."""
    ax0, ay0, ax1, ay1 = a.bounds
    bx0, by0, bx1, by1 = b.bounds
    d = 1 + int(ax1 - ax0 + ay1 - ay0)
    F = shapely.box(ax0 - d, ay0 - d, ax1 + d, ay1 + d)
    R = shapely.Polygon(F.exterior, [a.exterior])
    nb = shapely.affinity.scale(b, -1, -1, origin=(0, 0))
    sums = _piece_sum_rings(R, nb)
    G = [
        (ax0 - bx0, ay0 - by0),
        (ax1 - bx1, ay0 - by0),
        (ax1 - bx1, ay1 - by1),
        (ax0 - bx0, ay1 - by1),
    ]
    return boundary([G, *sums], layers=[0] + [1] * len(sums), rule="difference")


@settings(max_examples=15, deadline=None, suppress_health_check=list(HealthCheck))
@given(polygon(integer=True, holes=False), st.sampled_from([1, 2]), st.sampled_from([1, 2]))
def test_erosion_equals_the_exact_oracle(a, w, h):
    b = shapely.Polygon([(0, 0), (w, 0), (w, h), (0, h)])
    assume(not mk.is_convex(shapely.get_coordinates(a.exterior)[:-1]))
    verts, area = _erosion_oracle(a, b)
    g = mk.minkowski_difference(a, b)
    assert vset(g) == {(float(x), float(y)) for x, y in verts}
    assert abs(g.area - float(area)) <= 1e-12 * (1 + float(area))


def square(x, y, s):
    return [(x, y), (x + s, y), (x + s, y + s), (x, y + s)]


@pytest.mark.parametrize(
    "a, b",
    [
        # B cannot fit in A's hole: the hole is filled (it changes nothing)
        (shapely.Polygon(square(0, 0, 10), [square(4, 4, 2)]), square(0, 0, 3)),
        # B can fit in A's hole: the hole stays, and the sum keeps a smaller hole
        (shapely.Polygon(square(0, 0, 10), [square(2, 2, 6)]), square(0, 0, 1)),
        # both have holes: a ring around a ring
        (
            shapely.Polygon(square(0, 0, 10), [square(2, 2, 6)]),
            shapely.Polygon(square(0, 0, 4), [square(1, 1, 2)]),
        ),
        # a collection of two polygons (their union is the operand)
        ([square(0, 0, 2), square(5, 5, 2)], square(0, 0, 1)),
        # points and segments
        (square(0, 0, 2), [(1, 1)]),
        (square(0, 0, 2), [(0, 0), (3, 1)]),
        (shapely.Polygon(square(0, 0, 10), [square(4, 4, 2)]), [(0, 0), (1, 0)]),
    ],
)
def test_named_cases_both_methods(a, b):
    gc = mk.minkowski_sum_general(a, b, method="convolution")
    gp = mk.minkowski_sum_general(a, b, method="decomposition")
    assert shapely.is_valid(gc) and gc.equals(gp) and vset(gc) == vset(gp)
    # the brute-force union of translates of A by B's vertices and of the piece sums
    # contains nothing else
    if hasattr(a, "geom_type"):
        ga = a
    elif np.ndim(a[0]) == 2:  # a collection
        ga = shapely.MultiPolygon([shapely.Polygon(p) for p in a])
    else:
        ga = shapely.Polygon(a)
    gb = b if hasattr(b, "geom_type") else shapely.MultiPoint(b).convex_hull
    for x, y in shapely.get_coordinates(gb).tolist():
        assert gc.buffer(1e-9).covers(shapely.affinity.translate(ga, x, y))


def test_hole_that_fits_is_kept():
    A = shapely.Polygon(square(0, 0, 10), [square(2, 2, 6)])
    g = mk.minkowski_sum_general(A, square(0, 0, 1))
    assert len(g.interiors) == 1 and g.area == 100 - 25 + 2 * 10 + 1 - 0


def test_stars_both_methods():
    A = regular_star(32, 10000, 5000)
    B = regular_star(32, 9000, 3000, 0.3)
    gc = mk.minkowski_sum_general(A, B, method="convolution")
    gp = mk.minkowski_sum_general(A, B, method="decomposition")
    assert vset(gc) == vset(gp) and shapely.is_valid(gc)
