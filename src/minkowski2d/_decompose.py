"""Convex decomposition of polygons with holes: triangulation and Hertel-Mehlhorn.

The triangulation comes from GEOS (``shapely.constrained_delaunay_triangles``: the holes
are joined to the shell and the result is ear-clipped and Delaunay-improved, using the
input vertices only, so every triangle vertex is an input vertex, bit for bit). The
Hertel-Mehlhorn merge then removes diagonals while both of their endpoints stay convex;
that runs in one compiled pass over a half-edge structure, every turn decided by the
exact ``cross_sign`` kernel. The result has at most four times the optimal number of
convex pieces.

This module imports numba; :mod:`minkowski2d.general` imports it lazily.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from ._kernels import cross_sign

_JIT = dict(cache=True, nogil=True, boundscheck=False)


@njit(inline="always", **_JIT)
def _turn(x, y, i, j, k):
    """Exact sign of the turn i -> j -> k (vertex ids into coordinate arrays x, y)."""
    return cross_sign(x[i], y[i], x[j], y[j], x[j], y[j], x[k], y[k])


@njit(inline="always", **_JIT)
def _convex_at(x, y, i, j, k):
    """True when the path i -> j -> k turns left or goes straight on at j."""
    s = _turn(x, y, i, j, k)
    if s > 0:
        return True
    if s < 0:
        return False
    # collinear: straight on (not a spike folding back)
    return (x[j] - x[i]) * (x[k] - x[j]) + (y[j] - y[i]) * (y[k] - y[j]) > 0.0


@njit(**_JIT)
def _find(parent, a):
    while parent[a] != a:
        parent[a] = parent[parent[a]]
        a = parent[a]
    return a


@njit(**_JIT)
def _orient_triangles(x, y, ids):
    """Make each triangle counter-clockwise; return a mask of the non-degenerate ones."""
    T = ids.shape[0]
    keep = np.ones(T, np.bool_)
    for t in range(T):
        s = _turn(x, y, ids[t, 0], ids[t, 1], ids[t, 2])
        if s == 0:
            keep[t] = False
        elif s < 0:
            tmp = ids[t, 1]
            ids[t, 1] = ids[t, 2]
            ids[t, 2] = tmp
    return keep


@njit(**_JIT)
def _hertel_mehlhorn(x, y, ids, twin, merge):
    """Merge triangles into convex pieces; return (piece vertex ids, offsets).

    ``ids`` (T, 3) CCW triangles as vertex ids; ``twin[h]`` the opposite half-edge of
    half-edge ``h = 3 t + k`` (from ``ids[t, k]`` to ``ids[t, k + 1]``) or -1 on the
    boundary. With ``merge`` false the triangles are returned as they are. Each piece is
    returned counter-clockwise from its bottom-most vertex without collinear vertices.
    """
    T = ids.shape[0]
    H = 3 * T
    nxt = np.empty(H, np.int64)
    prv = np.empty(H, np.int64)
    org = np.empty(H, np.int64)
    alive = np.ones(H, np.bool_)
    parent = np.arange(T)
    for t in range(T):
        for k in range(3):
            h = 3 * t + k
            org[h] = ids[t, k]
            nxt[h] = 3 * t + (k + 1) % 3
            prv[h] = 3 * t + (k + 2) % 3
    if merge:
        for h in range(H):
            t = twin[h]
            if t < h:  # boundary edge, or the pair was seen from the other side
                continue
            fa = _find(parent, h // 3)
            fb = _find(parent, t // 3)
            if fa == fb:
                continue
            pn = prv[h]
            nn = nxt[h]
            tp = prv[t]
            tn = nxt[t]
            u = org[h]
            v = org[t]
            # at u the merged face runs origin(pn) -> u -> dest(tn) = origin(next(tn))
            if not _convex_at(x, y, org[pn], u, org[nxt[tn]]):
                continue
            if not _convex_at(x, y, org[tp], v, org[nxt[nn]]):
                continue
            nxt[pn] = tn
            prv[tn] = pn
            nxt[tp] = nn
            prv[nn] = tp
            alive[h] = False
            alive[t] = False
            parent[fb] = fa
    # walk the faces
    seen = np.zeros(H, np.bool_)
    out = np.empty(H, np.int64)
    off = np.zeros(T + 1, np.int64)
    buf = np.empty(H, np.int64)
    P = 0
    n_out = 0
    for h0 in range(H):
        if not alive[h0] or seen[h0]:
            continue
        m = 0
        h = h0
        while True:
            seen[h] = True
            buf[m] = org[h]
            m += 1
            h = nxt[h]
            if h == h0:
                break
        # drop straight-on vertices (in a convex polygon a vertex is straight exactly when
        # it is collinear with its original neighbours), then start at the bottom-most one
        k = 0
        for i in range(m):
            if _turn(x, y, buf[(i - 1) % m], buf[i], buf[(i + 1) % m]) != 0:
                out[n_out + k] = buf[i]
                k += 1
        for i in range(k):
            buf[i] = out[n_out + i]
        best = 0
        for i in range(1, k):
            bi = buf[i]
            bb = buf[best]
            if y[bi] < y[bb] or (y[bi] == y[bb] and x[bi] < x[bb]):
                best = i
        for i in range(k):
            out[n_out] = buf[(best + i) % k]
            n_out += 1
        P += 1
        off[P] = n_out
    return out[:n_out], off[: P + 1]


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


def triangles_of(geom) -> np.ndarray:
    """GEOS triangulation of a Polygon / MultiPolygon as a (T, 3, 2) float64 array."""
    import shapely

    parts = shapely.get_parts(shapely.constrained_delaunay_triangles(geom))
    if len(parts) == 0:
        return np.empty((0, 3, 2), np.float64)
    coords = shapely.get_coordinates(shapely.get_exterior_ring(parts))
    return coords.reshape(len(parts), 4, 2)[:, :3]


def decompose(geom, merge: bool) -> tuple[np.ndarray, np.ndarray]:
    """Convex pieces of a valid Polygon / MultiPolygon: ``(coords (N, 2) float64, offsets)``.

    ``merge=False`` gives the triangles, ``merge=True`` the Hertel-Mehlhorn pieces.
    """
    tri = triangles_of(geom)
    if len(tri) == 0:
        return np.empty((0, 2), np.float64), np.zeros(1, np.int64)
    verts, inv = np.unique(tri.reshape(-1, 2), axis=0, return_inverse=True)
    ids = np.ascontiguousarray(inv.reshape(-1, 3), dtype=np.int64)
    x = np.ascontiguousarray(verts[:, 0])
    y = np.ascontiguousarray(verts[:, 1])
    keep = _orient_triangles(x, y, ids)
    ids = np.ascontiguousarray(ids[keep])
    if len(ids) == 0:
        return np.empty((0, 2), np.float64), np.zeros(1, np.int64)
    twin = _twins(ids, len(verts))
    vid, off = _hertel_mehlhorn(x, y, ids, twin, merge)
    return verts[vid], off
