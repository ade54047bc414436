"""Convex decomposition of polygons with holes: triangulation and Hertel-Mehlhorn.

The triangulation comes from GEOS (``shapely.constrained_delaunay_triangles``: the holes
are joined to the shell and the result is ear-clipped and Delaunay-improved, using the
input vertices only, so every triangle vertex is an input vertex, bit for bit). The
Hertel-Mehlhorn merge then removes diagonals while both of their endpoints stay convex;
that runs in one compiled pass over a half-edge structure (``minkowski2d._core._ext``,
C++, GIL released), every turn decided by the exact ``cross_sign`` predicate -- exact at
every magnitude, subnormals to ``1.7e308``. The result has at most four times the optimal
number of convex pieces.

GEOS computes in floating point (squared distances, in-circle tests) and fails or goes
wrong far from unit scale (below about ``2**-530`` it cannot find a convex corner, above
about ``2**510`` its in-circle tests overflow and the triangles stop covering the
polygon). It is therefore handed the geometry scaled by a power of two that brings the
largest coordinate to ``[1, 2)`` whenever that scaling is exact (it is unless subnormals
would lose bits); the triangle vertices are mapped back to the caller's own vertices, bit
for bit, and every decision after that is made on them.
"""

from __future__ import annotations

import math

import numpy as np

from ._core import _ext


def _twins(ids: np.ndarray, nv: int) -> np.ndarray:
    """Opposite half-edge of each half-edge ``3 t + k`` (or -1), by sorting edge keys."""
    org = ids.ravel()
    dst = np.roll(ids, -1, axis=1).ravel()
    key = org * nv + dst
    rkey = dst * nv + org
    order = np.argsort(key, kind="stable")
    sk = key[order]
    pos = np.searchsorted(sk, rkey)
    pos_c = np.minimum(pos, len(sk) - 1)
    found = sk[pos_c] == rkey
    return np.where(found, order[pos_c], -1).astype(np.int64)


def _pow2_exponent(geom) -> int:
    """k such that scaling by ``2**k`` is exact and brings the largest |coordinate| to
    ``[1, 2)``; 0 when that is not possible (no coordinates, or subnormals would lose
    bits)."""
    import shapely

    c = shapely.get_coordinates(geom)
    if c.size == 0:
        return 0
    big = float(np.abs(c).max())
    if big == 0.0 or not math.isfinite(big):
        return 0
    k = 1 - math.frexp(big)[1]
    if k == 0:
        return 0
    with np.errstate(all="ignore"):
        exact = np.array_equal(np.ldexp(np.ldexp(c, k), -k), c)
    return k if exact else 0


def triangles_of(geom) -> np.ndarray:
    """GEOS triangulation of a Polygon / MultiPolygon as a (T, 3, 2) float64 array.

    The triangle vertices are input vertices, bit for bit (GEOS triangulates a copy
    scaled exactly by a power of two, see the module doc).
    """
    import shapely

    k = _pow2_exponent(geom)
    g = geom if k == 0 else shapely.transform(geom, lambda c: np.ldexp(c, k))
    parts = shapely.get_parts(shapely.constrained_delaunay_triangles(g))
    if len(parts) == 0:
        return np.empty((0, 3, 2), np.float64)
    coords = shapely.get_coordinates(shapely.get_exterior_ring(parts))
    tri = coords.reshape(len(parts), 4, 2)[:, :3]
    return tri if k == 0 else np.ldexp(tri, -k)


def decompose(geom, merge: bool) -> tuple[np.ndarray, np.ndarray]:
    """Convex pieces of a valid Polygon / MultiPolygon: ``(coords (N, 2) float64, offsets)``.

    ``merge=False`` gives the triangles, ``merge=True`` the Hertel-Mehlhorn pieces.
    """
    tri = triangles_of(geom)
    if len(tri) == 0:
        return np.empty((0, 2), np.float64), np.zeros(1, np.int64)
    # unique vertices: each (x, y) row viewed as one complex128 (the same bits; numpy
    # sorts complex numbers by real, then imaginary part, i.e. like rows) -- a 1-D
    # unique is four times faster than np.unique(axis=0)
    pts = np.ascontiguousarray(tri.reshape(-1, 2), dtype=np.float64).view(np.complex128)
    cverts, inv = np.unique(pts.ravel(), return_inverse=True)
    verts = np.ascontiguousarray(cverts).view(np.float64).reshape(-1, 2)
    ids = np.ascontiguousarray(inv.reshape(-1, 3), dtype=np.int64)
    keep = _ext.orient_triangles_f(verts, ids)
    ids = np.ascontiguousarray(ids[keep])
    if len(ids) == 0:
        return np.empty((0, 2), np.float64), np.zeros(1, np.int64)
    twin = _twins(ids, len(verts))
    vid, off = _ext.hertel_mehlhorn_f(verts, ids, twin, bool(merge))
    return verts[vid], off
