"""Hypothesis strategies for convex polygons and point sets (ints, floats, degenerate)."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import strategies as st

from . import oracle


def regular_star(n: int, outer: float, inner: float, phase: float = 0.0) -> np.ndarray:
    """A regular star of n vertices, radii alternating outer (even) and inner (odd), turned
    by phase, rounded to integer values (float64)."""
    k = np.arange(n)
    th = 2 * np.pi * k / n + phase
    rad = np.where(k % 2, inner, outer)
    return np.rint(np.c_[rad * np.cos(th), rad * np.sin(th)])


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


# --------------------------------------------------------------------------------------
# polygons with holes, valid or not (the tests compare with tests/polygon_oracle.py)


@st.composite
def star_ring(draw, center=(0, 0), rmin: int = 2, rmax: int = 30, max_n: int = 12) -> list:
    """A ring star-shaped around ``center`` with integer vertices (rounding may make it
    touch itself or lose its area: the oracle decides), counter-clockwise."""
    import math

    n = draw(st.integers(3, max_n))
    angles = sorted(draw(st.lists(st.integers(0, 359), min_size=n, max_size=n, unique=True)))
    radii = draw(st.lists(st.integers(rmin, rmax), min_size=n, max_size=n))
    cx, cy = center
    return [
        (cx + round(r * math.cos(math.radians(t))), cy + round(r * math.sin(math.radians(t))))
        for t, r in zip(angles, radii, strict=True)
    ]


@st.composite
def ring_presentation(draw, ring: list) -> list:
    """The same ring as the caller may give it: any start, either orientation, maybe a
    closing repeat, maybe a duplicated vertex."""
    return draw(presentation(list(ring)))


@st.composite
def holey_polygon(draw, max_holes: int = 4) -> list:
    """A star-shaped shell with small star-shaped holes at random places (they may stick
    out or overlap: valid or not, the oracle decides). A list of rings."""
    shell = draw(star_ring(rmin=40, rmax=100, max_n=14))
    holes = []
    for _ in range(draw(st.integers(0, max_holes))):
        c = (draw(st.integers(-60, 60)), draw(st.integers(-60, 60)))
        holes.append(draw(star_ring(center=c, rmin=2, rmax=15, max_n=7)))
    return [draw(ring_presentation(r)) for r in [shell, *holes]]


@st.composite
def grid_polygon(draw, size: int = 4, max_holes: int = 2) -> list:
    """Random rings on a small integer grid: equal coordinates, collinear runs, touching
    and crossing everywhere (mostly invalid)."""
    c = st.integers(0, size)
    rings = []
    for _ in range(1 + draw(st.integers(0, max_holes))):
        rings.append(draw(st.lists(st.tuples(c, c), min_size=3, max_size=8)))
    return rings


@st.composite
def diamond_polygon(draw, k: int = 4) -> list:
    """Valid by construction and full of touching: the shell is the square [0, 2k]^2
    (maybe with every integer point of its boundary as a vertex: collinear runs), the
    holes are diamonds of radius 1 (or triangles on three of a diamond's corners) centred
    at odd lattice points; neighbours touch at a corner, border holes touch the shell at
    a point (a vertex, or inside an edge), rings of holes split the interior."""
    m = 2 * k
    if draw(st.booleans()):
        shell = (
            [(x, 0) for x in range(m)]
            + [(m, y) for y in range(m)]
            + [(m - x, m) for x in range(m)]
            + [(0, m - y) for y in range(m)]
        )
    else:
        shell = [(0, 0), (m, 0), (m, m), (0, m)]
    cells = [(2 * i + 1, 2 * j + 1) for i in range(k) for j in range(k)]
    chosen = draw(st.lists(st.sampled_from(cells), unique=True, max_size=len(cells)))
    holes = []
    for cx, cy in chosen:
        d = [(cx + 1, cy), (cx, cy + 1), (cx - 1, cy), (cx, cy - 1)]
        drop = draw(st.integers(-1, 3))
        if drop >= 0:
            d.pop(drop)
        holes.append(d)
    return [draw(ring_presentation(r)) for r in [shell, *holes]]


SCALES = [1.0, 3e-200, 1e300, 2.0**-1074, 1e-310, 2.0**-1000, 0.1, 2.0**1000]


def scaled(poly: list, s: float) -> list:
    """Every coordinate times s (rounded to float64 when s is not a power of two: the
    oracle sees the rounded values)."""
    return [[(x * s, y * s) for x, y in ring] for ring in poly]


@st.composite
def checkerboard_polygon(draw, k: int = 3) -> list:
    """Unit-square holes on the black cells of a checkerboard strictly inside the square
    [0, 2k + 2]^2: neighbours touch at corners (four edges of two holes at one point),
    every edge horizontal or vertical (equal y's everywhere), rings of touching squares
    split the interior."""
    m = 2 * k + 2
    cells = [(i, j) for i in range(1, m - 1) for j in range(1, m - 1) if (i + j) % 2 == 0]
    chosen = draw(st.lists(st.sampled_from(cells), unique=True, min_size=1))
    shell = [(0, 0), (m, 0), (m, m), (0, m)]
    holes = [[(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)] for i, j in chosen]
    return [draw(ring_presentation(r)) for r in [shell, *holes]]
