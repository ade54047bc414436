"""Brute-force exact references for polygon validity and triangulations (Fractions,
O(n^2) pair tests, no numpy or GEOS decisions).

Validity, as the core defines it: rings of >= 3 distinct consecutive vertices with area;
each ring simple (edges meet only when consecutive, at their shared vertex, without
doubling back); rings of one polygon neither cross nor share a segment; and the winding
number of the oriented rings (shell counter-clockwise, holes clockwise) is 0 or 1 at every
point off the boundary -- holes inside the shell, not inside each other, no crossing
through a shared vertex. The winding number is sampled just left and right of the middle
of every piece of every edge (cut where other edges meet it), closer than any other
edge, which visits every bounded face of the arrangement.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

F = Fraction


def exact_ring(ring: Any) -> list[tuple[Fraction, Fraction]]:
    return [(F(x), F(y)) for x, y in ring]


def dedupe(ring: list) -> list:
    """Drop consecutive (cyclic) duplicates, keeping the last of each run."""
    n = len(ring)
    return [ring[i] for i in range(n) if ring[i] != ring[(i + 1) % n]]


def orient(a, b, c) -> int:
    d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (d > 0) - (d < 0)


def area2(ring: list) -> Fraction:
    """Twice the signed area."""
    n = len(ring)
    return sum(
        (ring[i][0] * ring[(i + 1) % n][1] - ring[(i + 1) % n][0] * ring[i][1] for i in range(n)),
        F(0),
    )


def relation(p0, p1, q0, q1) -> str:
    """'none', 'cross' (interiors cross at one point), 'overlap' (a common segment) or
    'touch' (common points, none of them interior to both)."""
    o1, o2 = orient(p0, p1, q0), orient(p0, p1, q1)
    o3, o4 = orient(q0, q1, p0), orient(q0, q1, p1)
    if o1 * o2 > 0 or o3 * o4 > 0:
        return "none"
    if o1 == 0 and o2 == 0:
        k = 0 if p0[0] != p1[0] else 1
        a, b = sorted((p0[k], p1[k]))
        c, d = sorted((q0[k], q1[k]))
        length = min(b, d) - max(a, c)
        return "overlap" if length > 0 else ("touch" if length == 0 else "none")
    if o1 * o2 < 0 and o3 * o4 < 0:
        return "cross"
    return "touch"


def on_segment(p, a, b) -> bool:
    return (
        orient(a, b, p) == 0
        and min(a[0], b[0]) <= p[0] <= max(a[0], b[0])
        and min(a[1], b[1]) <= p[1] <= max(a[1], b[1])
    )


def dist2(p, a, b) -> Fraction:
    """Squared distance from p to the segment ab."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    L = dx * dx + dy * dy
    t = ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L
    t = min(max(t, F(0)), F(1))
    qx, qy = a[0] + t * dx - p[0], a[1] + t * dy - p[1]
    return qx * qx + qy * qy


def winding(q, rings: list) -> int:
    """Winding number of the point q (off every edge) around the oriented rings."""
    w = 0
    for ring in rings:
        n = len(ring)
        for i in range(n):
            a, b = ring[i], ring[(i + 1) % n]
            if a[1] <= q[1] < b[1] and orient(a, b, q) > 0:
                w += 1
            elif b[1] <= q[1] < a[1] and orient(a, b, q) < 0:
                w -= 1
    return w


def _cut(a, b, c, d):
    """Parameters t along a -> b where the segment c-d meets it (None: they overlap)."""
    rel = relation(a, b, c, d)
    if rel == "none":
        return []
    if rel == "overlap":
        return None
    ux, uy = b[0] - a[0], b[1] - a[1]
    vx, vy = d[0] - c[0], d[1] - c[1]
    den = ux * vy - uy * vx
    if den != 0:
        return [((c[0] - a[0]) * vy - (c[1] - a[1]) * vx) / den]
    # collinear, touching at one end point
    L = ux * ux + uy * uy
    return [((p[0] - a[0]) * ux + (p[1] - a[1]) * uy) / L for p in (c, d) if on_segment(p, a, b)]


def samples(rings: list) -> list:
    """Points just left and right of every piece of every edge (the edges cut where
    others meet them), closer than any other edge: a point in every face next to an
    edge, so in every bounded face. Edges overlapping another are skipped (the faces
    beside them have other edges too)."""
    edges = [(r[i], r[(i + 1) % len(r)]) for r in rings for i in range(len(r))]
    out = []
    for k, (a, b) in enumerate(edges):
        others = [e for j, e in enumerate(edges) if j != k]
        ts = {F(0), F(1)}
        for c, d in others:
            cut = _cut(a, b, c, d)
            if cut is None:
                ts = set()
                break
            ts.update(t for t in cut if 0 <= t <= 1)
        ts = sorted(ts)
        for t0, t1 in zip(ts, ts[1:]):
            t = (t0 + t1) / 2
            m = (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
            d2 = min((dist2(m, c, d) for c, d in others), default=F(1))
            nx, ny = -(b[1] - a[1]), b[0] - a[0]
            n2 = nx * nx + ny * ny
            delta = F(1)
            while delta * delta * n2 * 4 >= d2:
                delta /= 2
            out.append((m[0] + delta * nx, m[1] + delta * ny))
            out.append((m[0] - delta * nx, m[1] - delta * ny))
    return out


def polygon_problems(poly: list) -> set[str]:
    """The kinds of problem of one polygon (list of rings): empty when valid. Ring-level
    problems ('few', 'no_area') are reported alone, in ring order; else every pair
    problem ('ring' within a ring, 'rings' between rings) and 'winding' (a winding number
    other than 0 or 1 somewhere, rings oriented by their signed area)."""
    rings = [dedupe(exact_ring(r)) for r in poly]
    for r in rings:
        if len(r) < 3:
            return {"few"}
        if all(orient(r[0], r[1], p) == 0 for p in r[2:]):
            return {"no_area"}
    found = set()
    edges = []  # (ring, index, a, b)
    for ri, r in enumerate(rings):
        m = len(r)
        for i in range(m):
            edges.append((ri, i, r[i], r[(i + 1) % m]))
    for x in range(len(edges)):
        rx, ix, a, b = edges[x]
        for y in range(x + 1, len(edges)):
            ry, iy, c, d = edges[y]
            if rx == ry:
                m = len(rings[rx])
                if (ix + 1) % m == iy or (iy + 1) % m == ix:
                    # consecutive: s the shared vertex
                    if (ix + 1) % m == iy:
                        u, s, w = a, b, d
                    else:
                        u, s, w = c, d, b
                    dot = (s[0] - u[0]) * (w[0] - s[0]) + (s[1] - u[1]) * (w[1] - s[1])
                    if orient(u, s, w) == 0 and dot < 0:
                        found.add("ring")
                    continue
                if relation(a, b, c, d) != "none":
                    found.add("ring")
            else:
                rel = relation(a, b, c, d)
                if rel in ("cross", "overlap"):
                    found.add("rings")
    # rings oriented by their signed area; a ring that is not simple has no orientation,
    # so then also by the turn at its lowest vertex (the core's rule, the same for a
    # simple ring): 'winding' under either
    conventions = [[area2(r) > 0 for r in rings]]
    if "ring" in found:
        conventions.append([_lowest_turn(r) > 0 for r in rings])
    for ccws in conventions:
        oriented = [
            r if ccw == (k == 0) else r[::-1] for k, (r, ccw) in enumerate(zip(rings, ccws))
        ]
        if any(winding(q, oriented) not in (0, 1) for q in samples(oriented)):
            found.add("winding")
            break
    return found


def _lowest_turn(r: list) -> int:
    i = min(range(len(r)), key=lambda k: (r[k][1], r[k][0]))
    return orient(r[i - 1], r[i], r[(i + 1) % len(r)])


def problems(polys: list) -> set[str]:
    """The problems of the first invalid polygon of a collection (empty when all valid)."""
    for poly in polys:
        p = polygon_problems(poly)
        if p:
            return p
    return set()


#: the oracle's kinds that each core reason may stand for
REASON_KINDS = {
    "RING_FEW_VERTICES": {"few"},
    "RING_NO_AREA": {"no_area"},
    "RING_SPIKE": {"ring"},
    "RING_CROSSES": {"ring"},
    "RING_OVERLAPS": {"ring"},
    "RING_TOUCHES": {"ring"},
    "RINGS_CROSS": {"rings", "winding"},  # also a crossing through a shared vertex
    "RINGS_OVERLAP": {"rings"},
    "HOLE_OUTSIDE": {"winding"},  # a region with winding number -1 (or 2)
    "HOLE_IN_HOLE": {"winding"},
}


# --------------------------------------------------------------------------------------
# triangulations


def _as_ints(pts: list) -> tuple[list, int]:
    """The points times one integer (a multiple of 3, so that centroids stay integers):
    Python int arithmetic is far faster than Fractions, and every sign is the same."""
    import math

    d = 1
    for x, y in pts:
        d = math.lcm(d, x.denominator, y.denominator)
    d *= 3
    return [(int(x * d), int(y * d)) for x, y in pts], d


def _boxes_overlap(a, b) -> bool:
    return a[0] <= b[2] and b[0] <= a[2] and a[1] <= b[3] and b[1] <= a[3]


def _box(pts) -> tuple:
    xs = [p[0] for p in pts]
    ys = [p[1] for p in pts]
    return (min(xs), min(ys), max(xs), max(ys))


def _pairs(boxes_a, boxes_b=None):
    """Index pairs with overlapping boxes (a sweep over x; within one list: i < j)."""
    if boxes_b is None:
        order = sorted(range(len(boxes_a)), key=lambda i: boxes_a[i][0])
        active: list[int] = []
        for i in order:
            bi = boxes_a[i]
            active = [j for j in active if boxes_a[j][2] >= bi[0]]
            for j in active:
                if _boxes_overlap(bi, boxes_a[j]):
                    yield (min(i, j), max(i, j))
            active.append(i)
        return
    tagged = [(b[0], 0, i) for i, b in enumerate(boxes_a)] + [
        (b[0], 1, i) for i, b in enumerate(boxes_b)
    ]
    tagged.sort()
    act: tuple[list[int], list[int]] = ([], [])
    lists = (boxes_a, boxes_b)
    for x, side, i in tagged:
        for s in (0, 1):
            act[s][:] = [j for j in act[s] if lists[s][j][2] >= x]
        bi = lists[side][i]
        for j in act[1 - side]:
            if _boxes_overlap(bi, lists[1 - side][j]):
                yield (i, j) if side == 0 else (j, i)
        act[side].append(i)


def _interiors_disjoint(t, u) -> bool:
    """Two CCW triangles have disjoint interiors: some edge line of one has the other on
    its closed outer side (separating axes of convex polygons)."""
    for a, b in ((t, u), (u, t)):
        for i in range(3):
            p, q = a[i], a[(i + 1) % 3]
            if all(orient(p, q, r) <= 0 for r in b):
                return True
    return False


def _segment_misses_open_triangle(s0, s1, t) -> bool:
    for i in range(3):
        p, q = t[i], t[(i + 1) % 3]
        if orient(p, q, s0) <= 0 and orient(p, q, s1) <= 0:
            return True
    sides = [orient(s0, s1, r) for r in t]
    return all(s >= 0 for s in sides) or all(s <= 0 for s in sides)


def triangulation_errors(poly_rings: list, coords: Any, tris: Any) -> list[str]:
    """What is wrong with ``tris`` (vertex ids into ``coords``) as a triangulation of the
    polygons ``poly_rings`` (a list of polygons with disjoint interiors, each a list of
    rings): every triangle counter-clockwise and not flat, its centroid inside a polygon,
    no boundary edge entering it, the triangles of each polygon pairwise interior-disjoint
    with areas summing exactly to the polygon's. Returns messages (empty: a triangulation).
    """
    pts, scale = _as_ints([(F(x), F(y)) for x, y in coords])
    errs: list[str] = []
    T = [tuple(pts[int(i)] for i in t) for t in tris]
    for k, t in enumerate(T):
        if orient(*t) <= 0:
            errs.append(f"triangle {k} is not counter-clockwise (or flat)")
    if errs:
        return errs
    polys = []
    for poly in poly_rings:
        rings = [dedupe([(int(F(x) * scale), int(F(y) * scale)) for x, y in r]) for r in poly]
        oriented = [r if (area2(r) > 0) == (k == 0) else r[::-1] for k, r in enumerate(rings)]
        polys.append(oriented)
    # which polygon holds each triangle: its centroid has winding number 1
    owner = []
    for k, t in enumerate(T):
        c = ((t[0][0] + t[1][0] + t[2][0]) // 3, (t[0][1] + t[1][1] + t[2][1]) // 3)
        hits = []
        for p, rings in enumerate(polys):
            edges = [(r[i], r[(i + 1) % len(r)]) for r in rings for i in range(len(r))]
            if any(on_segment(c, a, b) for a, b in edges):
                continue
            if winding(c, rings) == 1:
                hits.append(p)
        if not hits:
            errs.append(f"triangle {k} has its centroid outside every polygon")
            owner.append(-1)
        else:
            owner.append(hits[0])
    if errs:
        return errs
    for p, rings in enumerate(polys):
        mine = [T[k] for k in range(len(T)) if owner[k] == p]
        total = sum((area2(r) for r in rings), F(0))
        got = sum((area2(list(t)) for t in mine), F(0))
        if got != total:
            errs.append(f"polygon {p}: triangle areas sum to {got}, not {total}")
        boxes = [_box(t) for t in mine]
        for i, j in _pairs(boxes):
            if not _interiors_disjoint(mine[i], mine[j]):
                errs.append(f"polygon {p}: triangles overlap: {mine[i]} {mine[j]}")
                break
        edges = [(r[i], r[(i + 1) % len(r)]) for r in rings for i in range(len(r))]
        eboxes = [_box(e) for e in edges]
        for i, j in _pairs(boxes, eboxes):
            a, b = edges[j]
            if not _segment_misses_open_triangle(a, b, mine[i]):
                errs.append(f"polygon {p}: the boundary enters triangle {mine[i]}")
                break
    return errs
