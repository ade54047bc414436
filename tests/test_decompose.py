"""Convex decomposition: pieces are convex, CCW, cover the polygon exactly, holes work."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings

import minkowski2d as mk
from minkowski2d.errors import SelfIntersectionError

from .test_general import star_ring


def reflex_count(ring):
    p = np.asarray(ring, dtype=float)
    e = np.roll(p, -1, 0) - p
    ein = np.roll(e, 1, 0)
    return int(((ein[:, 0] * e[:, 1] - ein[:, 1] * e[:, 0]) < 0).sum())


def check_cover(poly, pieces):
    assert len(pieces) > 0
    for q in pieces:
        assert mk.is_convex(q)
        assert mk.signed_area(q) > 0  # counter-clockwise, not flat
        assert mk.normalize(q).tolist() == q.tolist()  # bottom-first, no collinear
    polys = pieces.to_shapely()
    assert sum(shapely.area(polys)) == pytest.approx(poly.area, rel=1e-12)
    assert shapely.union_all(polys).symmetric_difference(poly).area <= 1e-12 * poly.area


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])
@given(star_ring(max_n=14))
def test_random_simple_polygons(ring):
    poly = shapely.Polygon(ring)
    hm = mk.convex_decomposition(ring)
    tri = mk.convex_decomposition(ring, method="triangulation")
    check_cover(poly, hm)
    check_cover(poly, tri)
    assert len(tri) <= len(ring) - 2  # fewer only when flat (collinear) triangles are dropped
    # Hertel-Mehlhorn: every kept diagonal is essential at a reflex vertex
    assert len(hm) <= 2 * reflex_count(ring) + 1
    # clockwise input is decomposed as well (the pieces may differ: another triangulation)
    check_cover(poly, mk.convex_decomposition(ring[::-1]))


def test_polygon_with_holes():
    poly = shapely.Polygon(
        [(0, 0), (10, 0), (10, 10), (0, 10)],
        [[(2, 2), (2, 4), (4, 4), (4, 2)], [(6, 6), (6, 8), (8, 8), (8, 6)]],
    )
    for m in ("hertel-mehlhorn", "triangulation"):
        check_cover(poly, mk.convex_decomposition(poly, method=m))


def test_convex_input_is_one_piece_and_star_is_core_plus_spikes():
    assert len(mk.convex_decomposition([(0, 0), (4, 0), (4, 1), (2, 3), (0, 1)])) == 1
    k = np.arange(64)
    rad = np.where(k % 2 == 0, 100, 50)
    st = np.c_[rad * np.cos(2 * np.pi * k / 64), rad * np.sin(2 * np.pi * k / 64)]
    assert len(mk.convex_decomposition(st)) == 33


def test_collinear_and_errors():
    check_cover(
        shapely.Polygon([(0, 0), (2, 0), (4, 0), (4, 4), (2, 4), (0, 4)]),
        mk.convex_decomposition([(0, 0), (2, 0), (4, 0), (4, 4), (2, 4), (0, 4)]),
    )
    with pytest.raises(SelfIntersectionError):
        mk.convex_decomposition([(0, 0), (2, 2), (2, 0), (0, 2)])
    with pytest.raises(ValueError, match="method"):
        mk.convex_decomposition([(0, 0), (1, 0), (0, 1)], method="greene")
