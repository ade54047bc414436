"""Brute-force exact references for the tests (Python ints / Fractions, no numpy decisions).

These are deliberately the slow, obviously-correct definitions: the Minkowski sum of two
convex polygons is the convex hull of all pairwise vertex sums.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

Point = tuple[Any, Any]


def exact(p: Any) -> Point:
    """A point with exact coordinates (floats become their exact Fraction)."""
    return (Fraction(p[0]), Fraction(p[1]))


def cross(o: Point, a: Point, b: Point) -> Any:
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def bottom_first(h: list[Point]) -> list[Point]:
    if not h:
        return h
    b = min(range(len(h)), key=lambda i: (h[i][1], h[i][0]))
    return h[b:] + h[:b]


def hull(points: list[Any]) -> list[Point]:
    """Exact convex hull: CCW, bottom-most first, no collinear points (Andrew's chain)."""
    s = sorted({exact(p) for p in points})
    if len(s) <= 2:
        return bottom_first(s)
    lo: list[Point] = []
    for p in s:
        while len(lo) >= 2 and cross(lo[-2], lo[-1], p) <= 0:
            lo.pop()
        lo.append(p)
    up: list[Point] = []
    for p in reversed(s):
        while len(up) >= 2 and cross(up[-2], up[-1], p) <= 0:
            up.pop()
        up.append(p)
    return bottom_first(lo[:-1] + up[:-1])


def minkowski_sum(a: list[Any], b: list[Any]) -> list[Point]:
    """Hull of all pairwise sums, exact."""
    return hull([(exact(p)[0] + exact(q)[0], exact(p)[1] + exact(q)[1]) for p in a for q in b])


def as_exact_list(arr: Any) -> list[Point]:
    """Rows of a result array as exact points (for comparing with the oracle)."""
    rows = arr.tolist() if hasattr(arr, "tolist") else list(arr)
    return [exact(r) for r in rows]


def rounded(points: list[Point]) -> list[tuple[float, float]]:
    """Each exact coordinate rounded once to float (what a float result must equal)."""
    return [(float(x), float(y)) for x, y in points]


def union_area(polys: list[list[Any]]) -> Fraction:
    """Exact area of the union of convex CCW polygons (Green's theorem over kept edges).

    Each edge a -> a + d contributes cross(a, d) / 2 times the fraction of it that is not
    strictly inside another polygon; where two polygons share a boundary stretch in the
    same direction it counts once (the lower index), in opposite directions both stay and
    cancel. Every clip is an exact rational parameter on the edge (kept as integer
    numerator and denominator: the tests' inputs are integers). The slow,
    obviously-correct reference that the tests certify GEOS's union_all by.
    """

    def num(v: Any) -> Any:
        f = Fraction(v)
        return f.numerator if f.denominator == 1 else f

    P = [[(num(x), num(y)) for x, y in poly] for poly in polys]
    P = [p for p in P if len(p) >= 3]
    box = [
        (min(x for x, _ in p), max(x for x, _ in p), min(y for _, y in p), max(y for _, y in p))
        for p in P
    ]
    total = Fraction(0)
    for i, p in enumerate(P):
        for k in range(len(p)):
            a, b = p[k], p[(k + 1) % len(p)]
            d0, d1 = b[0] - a[0], b[1] - a[1]
            if d0 == 0 and d1 == 0:
                continue
            cut: list[tuple[Fraction, Fraction]] = []  # removed parameter ranges
            ex0, ex1 = min(a[0], b[0]), max(a[0], b[0])
            ey0, ey1 = min(a[1], b[1]), max(a[1], b[1])
            for j, q in enumerate(P):
                if j == i:
                    continue
                bx0, bx1, by0, by1 = box[j]
                if bx1 < ex0 or ex1 < bx0 or by1 < ey0 or ey1 < by0:
                    continue
                # the range (ln / ld, hn / hd) of the edge strictly inside q; ld, hd > 0
                ln, ld, hn, hd = 0, 1, 1, 1
                on_edge = None
                for m in range(len(q)):
                    u, v = q[m], q[(m + 1) % len(q)]
                    w0, w1 = v[0] - u[0], v[1] - u[1]
                    c0 = w0 * (a[1] - u[1]) - w1 * (a[0] - u[0])
                    c1 = w0 * d1 - w1 * d0
                    if c1 == 0:
                        if c0 < 0:
                            ln, ld, hn, hd = 1, 1, 0, 1
                            break
                        if c0 == 0:
                            on_edge = (u, v, w0, w1)
                        continue
                    # f(t) = c0 + t c1 > 0
                    if c1 > 0:
                        if -c0 * ld > ln * c1:
                            ln, ld = -c0, c1
                    elif c0 * hd < hn * -c1:
                        hn, hd = c0, -c1
                    if ln * hd >= hn * ld:
                        break
                if on_edge is not None:
                    # the edge runs along q's boundary: removed only in the same direction
                    # and when q comes first; the stretch is the overlap with q's edge
                    u, v, w0, w1 = on_edge
                    if j > i or w0 * d0 + w1 * d1 <= 0:
                        continue
                    dd = d0 * d0 + d1 * d1
                    tu = (u[0] - a[0]) * d0 + (u[1] - a[1]) * d1
                    tv = (v[0] - a[0]) * d0 + (v[1] - a[1]) * d1
                    ln, ld, hn, hd = max(0, tu), dd, min(dd, tv), dd
                if ln * hd < hn * ld:
                    cut.append((Fraction(ln) / ld, Fraction(hn) / hd))
            cut.sort()
            t0, kept = Fraction(0), Fraction(0)
            for lo, hi in cut:
                if lo > t0:
                    kept += lo - t0
                t0 = max(t0, hi)
            if t0 < 1:
                kept += 1 - t0
            total += (a[0] * d1 - a[1] * d0) * kept / 2
    return total
