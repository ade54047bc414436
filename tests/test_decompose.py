"""Convex decomposition: pieces are convex, CCW, cover the polygon exactly, holes work."""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings

import minkowski2d as mk
from minkowski2d._core import _ext
from minkowski2d._engine.decompose import _twins
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


# --------------------------------------------------------------------------------------
# every magnitude: the silently dropped piece at tiny scales

L_SHAPE = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
COMB = [(0, 0), (7, 0), (7, 3), (6, 3), (6, 1), (5, 1), (5, 3), (4, 3), (4, 1), (3, 1),
        (3, 3), (2, 3), (2, 1), (1, 1), (1, 3), (0, 3)]  # fmt: skip
SQUARE_MIDPOINTS = [(0, 0), (2, 0), (4, 0), (4, 4), (2, 4), (0, 4)]  # collinear vertices


def exact_area2(ring):
    """Twice the signed area, exactly (Fractions: no overflow or underflow)."""
    F = Fraction
    p = [(F(x), F(y)) for x, y in ring]
    return sum(p[i - 1][0] * p[i][1] - p[i][0] * p[i - 1][1] for i in range(len(p)))


@pytest.mark.parametrize("scale", [2.0**-1000, 1e-200, 1e200, 2.0**900, 2.0**-1070, 1e-300])
@pytest.mark.parametrize("ring", [L_SHAPE, COMB, SQUARE_MIDPOINTS], ids=["L", "comb", "square"])
def test_decomposition_at_every_scale(ring, scale):
    base_hm = mk.convex_decomposition(ring)
    base_tri = mk.convex_decomposition(ring, method="triangulation")
    pts = [(x * scale, y * scale) for x, y in ring]
    total = exact_area2(pts)
    pow2 = math.frexp(scale)[0] == 0.5
    for method, base in (("hertel-mehlhorn", base_hm), ("triangulation", base_tri)):
        pieces = mk.convex_decomposition(pts, method=method)
        assert len(pieces) == len(base), method  # no piece dropped, none split
        areas = [exact_area2(q.tolist()) for q in pieces]
        assert all(a > 0 for a in areas)  # counter-clockwise, not flat
        got = sum(areas)
        if pow2:  # scaling by a power of two is exact: the same pieces, scaled
            assert got == total
            assert [q.tolist() for q in pieces] == [
                [[x * scale, y * scale] for x, y in q.tolist()] for q in base
            ]
        else:  # pieces have the polygon's own (rounded) vertices: the area is still exact
            assert got == total, (float(got), float(total))
        for q in pieces:  # CCW from the bottom-most vertex, no collinear vertex
            assert mk.normalize(q).tolist() == q.tolist()


def test_kernel_keeps_triangles_with_subnormal_products():
    """The compiled kernels decide on the caller's coordinates at every magnitude: a hand-
    built triangulation (no GEOS) of the L-shape at 2**-1070 keeps all four triangles and
    merges them into two pieces (the numba predicate saw every turn as 0 and dropped them)."""
    s = 2.0**-1070
    verts = np.array(L_SHAPE, dtype=np.float64) * s
    ids = np.array([[0, 1, 3], [1, 2, 3], [0, 3, 5], [3, 4, 5]], dtype=np.int64)
    ids[1] = ids[1, ::-1]  # one clockwise triangle: oriented in place
    keep = _ext.orient_triangles_f(verts, ids)
    assert keep.tolist() == [True] * 4
    for t in ids:
        assert _ext.cross_sign_f(*verts[t[0]], *verts[t[1]], *verts[t[1]], *verts[t[2]]) == 1
    twin = _twins(ids, len(verts))
    vid, off = _ext.hertel_mehlhorn_f(verts, ids, twin, True)
    assert len(off) - 1 == 2
    assert sum(exact_area2(verts[vid[a:b]].tolist()) for a, b in zip(off[:-1], off[1:])) == (
        exact_area2(verts.tolist())
    )
    vid, off = _ext.hertel_mehlhorn_f(verts, ids, twin, False)
    assert len(off) - 1 == 4
    # the int64 kernel agrees
    ids_i = np.array([[0, 1, 3], [3, 2, 1], [0, 3, 5], [3, 4, 5]], dtype=np.int64)
    assert _ext.orient_triangles_i(np.array(L_SHAPE, dtype=np.int64), ids_i).all()
    assert ids_i.tolist() == ids.tolist()


def test_kernel_straight_on_vertex_at_tiny_scale():
    """A vertex collinear with its neighbours is convex (straight on): the exact sign of
    the dot product decides, also where the float dot product underflows to 0."""
    for s in (1.0, 2.0**-1000, 2.0**-1072, 2.0**1000):
        verts = np.array([(0, 0), (2, 0), (4, 0), (4, 4), (0, 4)], dtype=np.float64) * s
        ids = np.array([[0, 1, 4], [1, 3, 4], [1, 2, 3]], dtype=np.int64)
        assert _ext.orient_triangles_f(verts, ids).all()
        vid, off = _ext.hertel_mehlhorn_f(verts, ids, _twins(ids, len(verts)), True)
        assert off.tolist() == [0, 4]  # one square, the straight-on vertex (2, 0) dropped
        assert (verts[vid] / s).tolist() == [[0, 0], [4, 0], [4, 4], [0, 4]]


def test_kernel_rejects_malformed_input():
    verts = np.array(L_SHAPE, dtype=np.float64)
    ids = np.array([[0, 1, 3], [1, 2, 3]], dtype=np.int64)
    twin = _twins(ids, len(verts))
    with pytest.raises(ValueError, match="twin"):
        _ext.hertel_mehlhorn_f(verts, ids, np.array([3, -1, -1, 0, 0, -1]), True)
    with pytest.raises(ValueError, match="twin"):
        _ext.hertel_mehlhorn_f(verts, ids, twin[:-1].copy(), True)
    with pytest.raises(ValueError, match="out of range"):
        _ext.orient_triangles_f(verts, np.array([[0, 1, 6]], dtype=np.int64))
    with pytest.raises(ValueError, match="non-finite"):
        _ext.orient_triangles_f(np.array([[0.0, np.nan]] * 3), np.array([[0, 1, 2]]))
    with pytest.raises(TypeError):  # float32, or a read-only ids array: no silent copy
        _ext.orient_triangles_f(verts.astype(np.float32), ids)
    with pytest.raises(TypeError):
        ro = ids.copy()
        ro.flags.writeable = False
        _ext.orient_triangles_f(verts, ro)


def test_decompose_module_is_numba_free():
    import subprocess
    import sys

    code = (
        "import sys, minkowski2d as mk; "
        "mk.convex_decomposition([(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]); "
        "import minkowski2d._engine.decompose, minkowski2d.predicates; "
        "assert 'numba' not in sys.modules, 'numba imported'"
    )
    subprocess.run([sys.executable, "-c", code], check=True)
