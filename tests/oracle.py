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
