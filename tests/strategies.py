"""Hypothesis strategies for convex polygons and point sets (ints, floats, degenerate)."""

from __future__ import annotations

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
