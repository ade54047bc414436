"""Convex decomposition of polygons with holes: triangulation and Hertel-Mehlhorn.

Both steps run in the compiled core (``minkowski2d._core._ext``, C++, GIL released) and
decide every turn with the exact ``cross_sign`` predicate, at every magnitude
(subnormals to ``1.7e308``), without GEOS:

* the triangulation (``triangulate.hpp``, through :mod:`minkowski2d._engine.polygon`): a plane
  sweep cuts the polygon into monotone pieces (de Berg et al., ch. 3), each is
  triangulated with a stack; O(n log n), input vertices only, holes and holes touching
  the shell or each other at points allowed;
* the Hertel-Mehlhorn merge removes diagonals while both of their endpoints stay convex,
  in one pass over a half-edge structure. The result has at most four times the optimal
  number of convex pieces.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from . import core
from .polygon import rings_of, triangulate


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


def triangles_of(geom: Any) -> tuple[np.ndarray, np.ndarray]:
    """Exact triangulation of a valid Polygon / MultiPolygon: ``(verts (n, 2) float64,
    ids (T, 3) int64)``, each triangle counter-clockwise, its vertices the input vertices
    (bit for bit; a repeated coordinate is always the same id)."""
    rings = rings_of(geom)
    return rings.coords, triangulate(rings, "polygon")


def decompose_rings(rings: Any, name: str, merge: bool) -> tuple[np.ndarray, np.ndarray]:
    """Convex pieces of valid polygons given as ``_polygon.Rings``: ``(coords (N, 2)
    float64, offsets)``; ``merge=False`` gives the triangles."""
    ids = triangulate(rings, name)
    if len(ids) == 0:
        return np.empty((0, 2), np.float64), np.zeros(1, np.int64)
    verts = rings.coords
    twin = _twins(ids, len(verts))
    vid, off = core.hertel_mehlhorn_f(verts, ids, twin, bool(merge))
    return verts[vid], off


def decompose(geom: Any, merge: bool) -> tuple[np.ndarray, np.ndarray]:
    """Convex pieces of a valid Polygon / MultiPolygon: ``(coords (N, 2) float64, offsets)``.

    ``merge=False`` gives the triangles, ``merge=True`` the Hertel-Mehlhorn pieces.
    """
    verts, ids = triangles_of(geom)
    if len(ids) == 0:
        return np.empty((0, 2), np.float64), np.zeros(1, np.int64)
    twin = _twins(ids, len(verts))
    vid, off = core.hertel_mehlhorn_f(verts, ids, twin, bool(merge))
    return verts[vid], off
