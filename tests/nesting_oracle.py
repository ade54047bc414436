"""A brute-force exact oracle for layouts, in Python Fractions (no core, no shapely
decisions): for tests of :func:`minkowski2d.nesting.verify.verify_layout`.

Polygons are lists of rings of exact points (Fraction pairs), the first ring the shell;
they must be valid (the callers draw valid ones). Every edge pair and every vertex is
looked at (O(n m) per test, plus O(m) per piece): for a few dozen vertices.

* :func:`interiors_meet`: a proper crossing of two edges; else each edge of one polygon,
  split at the other's vertices on it, has pieces that meet the other boundary only where
  they lie along it, so the midpoint of each piece tells: strictly inside the other means
  the interiors meet, and so does a piece along the other's edge in the same direction
  (both interiors on its left). This covers collinear overlaps and identical polygons.
* :func:`contains`: the same test against the container's complement: no crossing, no
  piece of the part strictly outside or along the container's edge the other way, no
  piece of the container's boundary strictly inside the part.
* :func:`min_dist2`: the exact squared distance of the boundaries (0 where they meet), the
  minimum over edge pairs of the clamped projections of the four end points.

Examples
--------
>>> sq = [[(0, 0), (2, 0), (2, 2), (0, 2)]]
>>> moved = lambda P, d: [[(x + d, y) for x, y in r] for r in P]
>>> interiors_meet(ex(sq), ex(moved(sq, 2))), interiors_meet(ex(sq), ex(moved(sq, 1)))
(False, True)
>>> min_dist2(ex(sq), ex(moved(sq, 3)))
Fraction(1, 1)
"""

from __future__ import annotations

from fractions import Fraction as F


def ex(poly) -> list:
    """A polygon (list of rings of number pairs) with Fraction coordinates."""
    return [[(F(x), F(y)) for x, y in ring] for ring in poly]


def _sgn(v) -> int:
    return (v > 0) - (v < 0)


def orient(p, q, r) -> int:
    return _sgn((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]))


def area2(ring):
    return sum(p[0] * q[1] - p[1] * q[0] for p, q in zip(ring, ring[1:] + ring[:1]))


def oriented(poly) -> list:
    """Closing and repeated vertices dropped, the shell counter-clockwise, the holes
    clockwise (the interior on the left of every edge)."""
    out = []
    for k, ring in enumerate(poly):
        r = list(ring)
        if len(r) > 1 and r[0] == r[-1]:
            r = r[:-1]
        r = [p for i, p in enumerate(r) if p != r[i - 1]] if len(r) > 1 else r
        if len(r) < 3 or area2(r) == 0:
            continue
        if (area2(r) > 0) != (k == 0):
            r = r[::-1]
        out.append(r)
    return out


def edges(poly):
    for ring in poly:
        for i in range(len(ring)):
            yield ring[i], ring[(i + 1) % len(ring)]


def on_segment(p, a, b) -> bool:
    return (
        orient(a, b, p) == 0
        and min(a[0], b[0]) <= p[0] <= max(a[0], b[0])
        and min(a[1], b[1]) <= p[1] <= max(a[1], b[1])
    )


def proper_cross(a, b, c, d) -> bool:
    return orient(a, b, c) * orient(a, b, d) < 0 and orient(c, d, a) * orient(c, d, b) < 0


def locate(p, poly) -> int:
    """+1 strictly inside, 0 on the boundary, -1 outside (crossing number)."""
    inside = False
    for a, b in edges(poly):
        if on_segment(p, a, b):
            return 0
        if (a[1] > p[1]) != (b[1] > p[1]):
            # x of the edge at height p[1], compared exactly
            x = a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
            if x > p[0]:
                inside = not inside
    return 1 if inside else -1


def _pieces(a, b, other):
    """Edge a -> b split at the vertices of ``other`` lying on it."""
    d = (b[0] - a[0], b[1] - a[1])
    dd = d[0] * d[0] + d[1] * d[1]
    ts = {F(0), F(1)}
    for ring in other:
        for v in ring:
            if on_segment(v, a, b):
                ts.add(((v[0] - a[0]) * d[0] + (v[1] - a[1]) * d[1]) / dd)
    ts = sorted(ts)
    pts = [(a[0] + t * d[0], a[1] + t * d[1]) for t in ts]
    return list(zip(pts, pts[1:]))


def _along(p, q, m, poly) -> int:
    """For a piece p -> q whose midpoint m is on poly's boundary: +1 if an edge of poly
    through m runs the same way, -1 the other way."""
    for a, b in edges(poly):
        if on_segment(m, a, b):
            dot = (q[0] - p[0]) * (b[0] - a[0]) + (q[1] - p[1]) * (b[1] - a[1])
            return 1 if dot > 0 else -1
    raise AssertionError("midpoint on no edge")


def _mid(p, q):
    return ((p[0] + q[0]) / 2, (p[1] + q[1]) / 2)


def interiors_meet(A, B) -> bool:
    """Do the interiors of the valid polygons A and B meet?"""
    A, B = oriented(A), oriented(B)
    if any(proper_cross(a, b, c, d) for a, b in edges(A) for c, d in edges(B)):
        return True
    for X, Y in ((A, B), (B, A)):
        for a, b in edges(X):
            for p, q in _pieces(a, b, Y):
                m = _mid(p, q)
                loc = locate(m, Y)
                if loc > 0 or (loc == 0 and _along(p, q, m, Y) > 0):
                    return True
    return False


def contains(C, P) -> bool:
    """Is the valid polygon P inside the valid polygon C (C's holes excluded)?"""
    C, P = oriented(C), oriented(P)
    if any(proper_cross(a, b, c, d) for a, b in edges(P) for c, d in edges(C)):
        return False
    for a, b in edges(P):
        for p, q in _pieces(a, b, C):
            m = _mid(p, q)
            loc = locate(m, C)
            if loc < 0 or (loc == 0 and _along(p, q, m, C) < 0):
                return False
    for a, b in edges(C):
        for p, q in _pieces(a, b, P):
            if locate(_mid(p, q), P) > 0:
                return False
    return True


def _point_seg2(p, a, b):
    d = (b[0] - a[0], b[1] - a[1])
    dd = d[0] * d[0] + d[1] * d[1]
    t = F(0) if dd == 0 else ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / dd
    t = min(max(t, F(0)), F(1))
    c = (a[0] + t * d[0], a[1] + t * d[1])
    return (p[0] - c[0]) ** 2 + (p[1] - c[1]) ** 2


def seg_dist2(a, b, c, d):
    if proper_cross(a, b, c, d):
        return F(0)
    return min(_point_seg2(a, c, d), _point_seg2(b, c, d), _point_seg2(c, a, b),
               _point_seg2(d, a, b))  # fmt: skip


def min_dist2(A, B):
    """Exact squared distance between the boundaries of A and B."""
    A, B = oriented(A), oriented(B)
    return min(seg_dist2(a, b, c, d) for a, b in edges(A) for c, d in edges(B))


def violations(polys, sheet_of, sheets, spacing=0, margin=0) -> set:
    """The set of ``(kind, a, b)`` of a layout: ``polys[i]`` placement i's exact polygon,
    ``sheet_of[i]`` its sheet, ``sheets[k]`` the exact sheet polygons."""
    s2, m2 = F(spacing) ** 2, F(margin) ** 2
    out = set()
    n = len(polys)
    for i in range(n):
        for j in range(i + 1, n):
            if sheet_of[i] != sheet_of[j]:
                continue
            if interiors_meet(polys[i], polys[j]):
                out.add(("overlap", i, j))
            elif spacing > 0 and min_dist2(polys[i], polys[j]) < s2:
                out.add(("spacing", i, j))
        C = sheets[sheet_of[i]]
        if not contains(C, polys[i]):
            out.add(("container", i, None))
        elif margin > 0 and min_dist2(polys[i], C) < m2:
            out.add(("margin", i, None))
    return out
