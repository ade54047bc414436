"""Hypothesis strategies for convex polygons and point sets (ints, floats, degenerate)."""

from __future__ import annotations

import math

from hypothesis import strategies as st

from . import oracle


def int_points(max_size: int = 30, bound: int = 1000) -> st.SearchStrategy:
    c = st.integers(-bound, bound)
    return st.lists(st.tuples(c, c), min_size=1, max_size=max_size)


def float_points(max_size: int = 30) -> st.SearchStrategy:
    c = st.floats(-1e6, 1e6, allow_nan=False, allow_infinity=False, width=64)
    return st.lists(st.tuples(c, c), min_size=1, max_size=max_size)


@st.composite
def convex_int(draw, max_size: int = 30, bound: int = 1000) -> list:
    """A convex polygon (or point/segment) with int vertices, in a random presentation:
    random start vertex, random orientation, maybe a closing repeat or duplicates."""
    h = oracle.hull(draw(int_points(max_size, bound)))
    pts = [(int(x), int(y)) for x, y in h]
    return draw(presentation(pts))


@st.composite
def convex_float(draw, max_size: int = 30) -> list:
    h = oracle.hull(draw(float_points(max_size)))
    pts = [(float(x), float(y)) for x, y in h]
    return draw(presentation(pts))


def tiny() -> st.SearchStrategy:
    """A nonzero float of either sign with magnitude from the smallest subnormal up to
    about 1e-150 (below the compiled kernels' value range [2**-400, 2**400])."""
    mag = st.builds(math.ldexp, st.floats(1.0, 2.0, exclude_max=True), st.integers(-1074, -500))
    return st.builds(lambda m, neg: -m if neg else m, mag, st.booleans())


@st.composite
def convex_tiny_offsets(draw, max_size: int = 8, bound: int = 3, step: float = 0.5) -> list:
    """A convex polygon on a small grid (spacing `step`) whose points are moved, and
    sometimes doubled, by tiny amounts (:func:`tiny`). An offset survives the rounding
    only on a zero coordinate, so grid points on the axes become edges of length ~1e-170
    and nearly straight or nearly axis-parallel edges; parallel edges stay common (small
    grid), and the tiny values send the values' computation to the exact path."""
    g = st.integers(-bound, bound)
    grid = draw(st.lists(st.tuples(g, g), min_size=1, max_size=max_size))
    off = st.one_of(st.just(0.0), tiny())

    def moved(x: int, y: int) -> tuple[float, float]:
        return (x * step + draw(off), y * step + draw(off))

    pts = []
    for x, y in grid:
        pts.append(moved(x, y))
        if draw(st.booleans()):
            pts.append(moved(x, y))  # a twin a tiny step away
    h = oracle.hull(pts)
    return draw(presentation([(float(x), float(y)) for x, y in h]))


@st.composite
def presentation(draw, pts: list) -> list:
    k = draw(st.integers(0, len(pts) - 1))
    pts = pts[k:] + pts[:k]
    if draw(st.booleans()):
        pts = pts[::-1]
    if draw(st.booleans()) and len(pts) > 1:
        pts = pts + [pts[0]]  # closing repeat
    if draw(st.booleans()):
        j = draw(st.integers(0, len(pts) - 1))
        pts = pts[: j + 1] + [pts[j]] + pts[j + 1 :]  # duplicate vertex
    return pts
