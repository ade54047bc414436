"""A brute-force exact oracle for overlays of rings, in Python Fractions.

``boundary(rings, weights, layers, rule)`` computes, with no floating point anywhere, the
regularized region ``{x : rule(w0(x), w1(x))}`` where ``w0``/``w1`` are the winding numbers
of the rings of layer 0 / 1 (each ring counted ``weight`` times): its boundary vertices
(points where the boundary turns, exact) and its area (exact). O(n^2) intersections and an
O(n) winding number per noded edge: for a few dozen segments.

Independent of the core: every segment is split at every point where another one meets
it, the pieces are merged by their exact endpoints, and each piece's two sides are
classified by the winding number of a point just beside its midpoint, found by exact ray
casting (the side offset is half the distance to the nearest other piece along the
normal, so no piece lies between the point and the edge).

Examples
--------
>>> sq = [(0, 0), (2, 0), (2, 2), (0, 2)]
>>> v, a = boundary([sq, [(1, 1), (3, 1), (3, 3), (1, 3)]])
>>> a, [tuple(map(int, p)) for p in sorted(v)[:3]]
(Fraction(7, 1), [(0, 0), (0, 2), (1, 2)])
"""

from __future__ import annotations

import math
from fractions import Fraction as F


def _cross(ax, ay, bx, by):
    return ax * by - ay * bx


def _orient(p, q, r):
    return _cross(q[0] - p[0], q[1] - p[1], r[0] - p[0], r[1] - p[1])


def _param(p, q, z):
    """t of z on segment p -> q (z on its line)."""
    if p[0] != q[0]:
        return (z[0] - p[0]) / (q[0] - p[0])
    return (z[1] - p[1]) / (q[1] - p[1])


def _segments(rings, weights, layers):
    segs = []
    for k, ring in enumerate(rings):
        pts = [(F(x), F(y)) for x, y in ring]
        w = 1 if weights is None else weights[k]
        ly = 0 if layers is None else layers[k]
        for i in range(len(pts)):
            p, q = pts[i], pts[(i + 1) % len(pts)]
            if p != q and w != 0:
                segs.append((p, q, w, ly))
    return segs


def _splits(segs):
    """Noded pieces (p, q, w, layer) of every segment."""
    out = []
    for i, (p, q, w, ly) in enumerate(segs):
        ts = {F(0), F(1)}
        for j, (r, s, _, _) in enumerate(segs):
            if i == j:
                continue
            o1, o2 = _orient(p, q, r), _orient(p, q, s)
            if o1 == 0 and o2 == 0:
                for z in (r, s):
                    t = _param(p, q, z)
                    if 0 < t < 1:
                        ts.add(t)
                continue
            if (o1 > 0 and o2 > 0) or (o1 < 0 and o2 < 0):
                continue
            o3, o4 = _orient(r, s, p), _orient(r, s, q)
            if (o3 > 0 and o4 > 0) or (o3 < 0 and o4 < 0):
                continue
            d = _cross(q[0] - p[0], q[1] - p[1], s[0] - r[0], s[1] - r[1])
            t = _cross(r[0] - p[0], r[1] - p[1], s[0] - r[0], s[1] - r[1]) / d
            if 0 < t < 1:
                ts.add(t)
        ts = sorted(ts)
        pts = [(p[0] + (q[0] - p[0]) * t, p[1] + (q[1] - p[1]) * t) for t in ts]
        for a, b in zip(pts, pts[1:]):
            out.append((a, b, w, ly))
    return out


def _winding(segs, z):
    w = [0, 0]
    for p, q, wt, ly in segs:
        if p[1] <= z[1] < q[1] and _orient(p, q, z) > 0:
            w[ly] += wt
        elif q[1] <= z[1] < p[1] and _orient(p, q, z) < 0:
            w[ly] -= wt
    return w


RULES = {
    "union": lambda w0, w1: w0 >= 1 or w1 >= 1,
    "difference": lambda w0, w1: w0 >= 1 and w1 <= 0,
    "intersection": lambda w0, w1: w0 >= 1 and w1 >= 1,
    "xor": lambda w0, w1: (w0 >= 1) != (w1 >= 1),
}


def boundary(rings, weights=None, layers=None, rule="union", edges_out=False):
    """(set of exact boundary vertices, exact area) of the region the rule selects; with
    ``edges_out``, the exact boundary edges (inside on the left) instead."""
    inside = RULES[rule]
    segs = _segments(rings, weights, layers)
    pieces = {}
    for a, b, w, ly in _splits(segs):
        key = (a, b) if a < b else (b, a)
        sgn = 1 if a < b else -1
        acc = pieces.setdefault(key, [0, 0])
        acc[ly] += sgn * w
    keys = [k for k, v in pieces.items() if v != [0, 0]]
    directed = []
    for a, b in keys:
        m = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
        n = (a[1] - b[1], b[0] - a[0])  # left normal of a -> b
        # nearest other piece along the line m + s n
        best = None
        for c, d in keys:
            if (c, d) == (a, b):
                continue
            den = _cross(n[0], n[1], d[0] - c[0], d[1] - c[1])
            if den == 0:
                continue
            s = _cross(c[0] - m[0], c[1] - m[1], d[0] - c[0], d[1] - c[1]) / den
            u = _cross(c[0] - m[0], c[1] - m[1], n[0], n[1]) / den
            if 0 <= u <= 1 and s != 0 and (best is None or abs(s) < best):
                best = abs(s)
        delta = F(1) if best is None else best / 2
        left = (m[0] + n[0] * delta, m[1] + n[1] * delta)
        right = (m[0] - n[0] * delta, m[1] - n[1] * delta)
        il, ir = inside(*_winding(segs, left)), inside(*_winding(segs, right))
        if il and not ir:
            directed.append((a, b))
        elif ir and not il:
            directed.append((b, a))
    if edges_out:
        return directed
    area = sum(_cross(a[0], a[1], b[0], b[1]) for a, b in directed) / 2
    outs, ins = {}, {}
    for a, b in directed:
        outs.setdefault(a, []).append(b)
        ins.setdefault(b, []).append(a)
    verts = set()
    for v, nb in outs.items():
        if len(nb) != 1:
            verts.add(v)
            continue
        (u,) = ins[v]
        (w,) = nb
        if _orient(u, v, w) != 0:
            verts.add(v)
    return verts, F(area)


# --------------------------------------------------------------------------------------
# measures of a computed result (rings as coordinates and ring offsets)


def exact_area(xy, ro) -> F:
    """The signed area of rings (counter-clockwise positive), exactly, at every magnitude."""
    a = F(0)
    for r in range(len(ro) - 1):
        pts = [tuple(map(F, p)) for p in xy[ro[r] : ro[r + 1]].tolist()]
        for i, p in enumerate(pts):
            q = pts[(i + 1) % len(pts)]
            a += (p[0] * q[1] - p[1] * q[0]) / 2
    return a


def ulps(p, q) -> float:
    """How many ulps of the points' largest coordinate p and q are apart (a re-noded
    crossing is within ulps of the data's magnitude; an ulp of a tiny coordinate next to
    a large one is no measure of a rounding)."""
    m = max(abs(v) for v in (*p, *q)) or 5e-324
    return max(abs(a - b) for a, b in zip(p, q)) / math.ulp(m)
