"""Convex polygons: normalization, convexity, hull, and the O(n + m) Minkowski sum.

One algorithm, one home: the compiled core (:mod:`minkowski2d._core`, C++) normalizes and
merges int64 and float64 input; :mod:`minkowski2d._engine.exact` runs the same steps on Python
ints beyond 2**62 and Fractions. :mod:`minkowski2d._engine.dispatch` chooses; tests check that
both give identical results.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ._engine import core
from ._engine import dispatch as D
from ._engine import exact as _exact
from ._types import ArrayLike2, Polygon
from .errors import OverflowGeometryError, ShapeError

__all__ = [
    "normalize",
    "is_convex",
    "convex_hull",
    "signed_area",
    "minkowski_sum",
    "translate",
    "reflect",
    "cspace_obstacle",
]

_UNHANDLED = int(D.Status.UNHANDLED)
_NAMES = ("a", "b", "result")


def _sum_core(A: np.ndarray, B: np.ndarray, path: str) -> np.ndarray:
    out = np.empty((len(A) + len(B), 2), A.dtype)
    k, code, which, v = (core.sum_i if path == "i" else core.sum_f)(A, B, out)
    if code:
        if code == D.Status.RANGE:  # int64 beyond 2**62: the exact path
            rows = [[tuple(r) for r in X.tolist()] for X in (A, B)]
            return _sum_exact(rows[0], rows[1], "int", False)
        raise D.status_error(code, v, _NAMES[which], (A, B, None)[which])
    return out[:k] if 2 * k >= len(out) else out[:k].copy()


def _sum_exact(A: list, B: list, out_kind: str, hull: bool) -> Polygon:
    if hull:
        A = _exact.hull_list(A)
        B = _exact.hull_list(B)
    qa, _, sa = _exact.normalize_list(A, "a")
    qb, _, sb = _exact.normalize_list(B, "b")
    return _exact.to_array(_exact.merge_lists(qa, sa, qb, sb), out_kind)


# --------------------------------------------------------------------------------------
# public API


def normalize(p: ArrayLike2, *, hull: bool = False) -> Polygon:
    """Normalize a convex polygon: CCW, bottom-most vertex first, no duplicate or collinear
    vertices.

    Parameters
    ----------
    p : (n, 2) array_like of int, float or Fraction, or a shapely geometry
        A convex polygon in either orientation, from any start vertex; a closing repeat
        of the first vertex, duplicate and collinear vertices are allowed. A point
        (one distinct vertex) and a segment (all vertices collinear) are valid.
    hull : bool, default False
        Accept any point set and use its convex hull.

    Returns
    -------
    (k, 2) ndarray
        int64 for int input (object array of Python ints beyond int64), float64 for float
        input, object array of Fractions for Fraction input. ``k`` is 1 for a point, 2 for
        a segment (lower end first).

    Raises
    ------
    NotConvexError
        The polygon turns both ways, doubles back, or winds around more than once.
    EmptyGeometryError, ShapeError, NonFiniteError, CoordinateTypeError
        Bad input.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.normalize([(0, 2), (2, 0), (1, 0), (0, 0)]).tolist()  # CW, collinear (1, 0)
    [[0, 0], [2, 0], [0, 2]]
    """
    return D.normalized(p, "p", hull=hull)


def is_convex(p: ArrayLike2) -> bool:
    """True when ``p`` is a convex polygon (points and segments count), in either
    orientation.

    Duplicate and collinear vertices are allowed; a star polygon (which turns left at every
    vertex but winds around twice) is not convex.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.is_convex([(0, 0), (4, 0), (4, 4), (0, 4)])
    True
    >>> star = [(0, 0), (2, 6), (4, 0), (-1, 4), (5, 4)]  # a pentagram
    >>> mk.is_convex(star)
    False
    """
    return D.check_convex(p, "p")


def convex_hull(points: ArrayLike2) -> Polygon:
    """Convex hull of a point set, normalized (CCW, bottom-most first, no collinear points).

    Exact: orientation decided by exact predicates (Andrew's monotone chain,
    O(n log n)).

    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.convex_hull([(0, 0), (2, 2), (2, 0), (1, 1), (0, 2), (1, 0)]).tolist()
    [[0, 0], [2, 0], [2, 2], [0, 2]]
    """
    return D.hull(points, "points")


def signed_area(p: ArrayLike2) -> float:
    """Signed area of a polygon as given (positive when counter-clockwise).

    Exact for int and Fraction input (the exact value rounded once to float); for float
    input the shoelace terms are summed with :func:`math.fsum`.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.signed_area([(0, 0), (2, 0), (0, 2)])
    2.0
    >>> mk.signed_area([(0, 0), (0, 2), (2, 0)])
    -2.0
    """
    data, out_kind, path = D.one(p, "p")
    if path == "i" and (data.size == 0 or int(np.abs(data).max()) < (1 << 30)):
        x = data[:, 0]
        y = data[:, 1]
        return int(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y)) / 2.0
    if path == "f":
        # exact: each shoelace term as an exact two-float sum after a power-of-two rescale
        # (no overflow, no underflow in the products), summed exactly by fsum, then scaled
        # back -- an area beyond float64 raises instead of returning inf or nan
        big = float(np.abs(data).max()) if data.size else 0.0
        if big == 0.0:
            return 0.0
        e = math.frexp(big)[1]
        xs = np.ldexp(data[:, 0], -e + 500)
        ys = np.ldexp(data[:, 1], -e + 500)
        terms = _exact_terms(xs, np.roll(ys, -1)) + _exact_terms(-np.roll(xs, -1), ys)
        s = math.fsum(terms) / 2.0
        try:
            return math.ldexp(s, 2 * (e - 500))
        except OverflowError:
            raise OverflowGeometryError(
                "p: the area overflows float64", argument="p", hint="scale the input down"
            ) from None
    pts = data if path == "py" else [tuple(r) for r in data.tolist()]
    s = sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1]))
    try:
        return float(s) / 2.0
    except OverflowError:
        raise OverflowGeometryError(
            "p: the area overflows float64", argument="p", hint="scale the input down"
        ) from None


def _exact_terms(x: np.ndarray, y: np.ndarray) -> list:
    """Products ``x * y`` as exact pairs (Dekker's TwoProduct; no overflow or underflow
    for the rescaled values of :func:`signed_area`, whose magnitudes are <= 2**500)."""
    with np.errstate(all="ignore"):
        p = x * y
        c = 134217729.0 * x
        xh = c - (c - x)
        xl = x - xh
        c = 134217729.0 * y
        yh = c - (c - y)
        yl = y - yh
        err = xl * yl - (((p - xh * yh) - xl * yh) - xh * yl)
    return p.tolist() + err.tolist()


def minkowski_sum(a: ArrayLike2, b: ArrayLike2, *, hull: bool = False) -> Polygon:
    """Minkowski sum A ⊕ B = {a + b} of two convex polygons, in O(n + m).

    The edges of both polygons, normalized to counter-clockwise order from their
    bottom-most vertices, are merged by angle (an exact cross-product test, never an
    angle); parallel edges are taken together.

    Parameters
    ----------
    a, b : (n, 2) array_like or shapely geometry
        Convex polygons in any orientation and from any start vertex. Duplicate,
        closing-repeat and collinear vertices are tolerated; points and segments are
        valid.
    hull : bool, default False
        Accept any point sets and use their convex hulls.

    Returns
    -------
    (k, 2) ndarray
        The sum: CCW, bottom-most vertex (lowest y, then lowest x) first, no duplicate or
        collinear vertices. int64 for int input (Python ints in an object array beyond
        int64), float64 if either input is float (each coordinate the correctly rounded
        sum of two input vertices), Fractions for Fraction input. ``k <= n + m``.

    Raises
    ------
    NotConvexError
        An input is not convex (and ``hull`` is False); the message names the vertex.
    EmptyGeometryError, ShapeError, NonFiniteError, CoordinateTypeError
        Bad input; the message names the argument and the vertex.
    OverflowGeometryError
        A float result coordinate would be infinite.

    See Also
    --------
    minkowski_sum_many : many pairs in one call.
    cspace_obstacle : obstacle ⊕ (−robot).

    Notes
    -----
    Integer input is exact at any size (int64 kernels up to 2**53, Python ints beyond).
    For float input every decision is exact on the given values (filtered predicate with
    an exact fallback); only the output additions round.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.minkowski_sum([(0, 0), (2, 0), (0, 2)], [(0, 0), (1, 0), (1, 1), (0, 1)]).tolist()
    [[0, 0], [3, 0], [3, 1], [1, 3], [0, 3]]
    """
    ta = type(a)
    if (
        (ta is list or ta is tuple)
        and (type(b) is list or type(b) is tuple)
        and not hull
        and not D.FORCE_EXACT
    ):
        # the tiny path: Python pairs straight into the core, validated as they are read
        out, code, which, v, _ = core.sum_lists(a, b)
        if code == core.Status.OK:
            return out
        if code != _UNHANDLED:
            raise D.status_error(code, v, _NAMES[which], (a, b, None)[which])
    A, B, out_kind, path = D.pair(a, b, ("a", "b"))
    if path == "py":
        return _sum_exact(A, B, out_kind, hull)
    if hull:
        A = D.hull_core(A, path)
        B = D.hull_core(B, path)
    return _sum_core(A, B, path)


def translate(p: ArrayLike2, v: Any) -> Polygon:
    """Translate a polygon by the vector ``v``: A ⊕ {v}, vertex order kept.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.translate([(0, 0), (1, 0), (0, 1)], (5, -2)).tolist()
    [[5, -2], [6, -2], [5, -1]]
    """
    vv = [v] if len(np.shape(v)) == 1 else v
    P, V, out_kind, path = D.pair(p, vv, ("p", "v"))
    if len(V) != 1:
        raise ShapeError("v: expected one (x, y) vector", argument="v")
    if path == "py":
        vx, vy = V[0]
        return _exact.to_array([(x + vx, y + vy) for x, y in P], out_kind)
    if path == "i":
        return P + V[0]
    with np.errstate(over="ignore", invalid="ignore"):
        out = P + V[0]
    if not np.isfinite(out).all():
        raise D.status_error(D.Status.OVERFLOW)
    return out


def reflect(p: ArrayLike2) -> Polygon:
    """Point reflection through the origin: −P = {−p}.

    A point reflection is a rotation by 180°, so it keeps the orientation: the vertices
    are negated in the same order (a CCW polygon stays CCW). Reversing the order as well
    would make it clockwise.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.reflect([(0, 0), (2, 0), (0, 1)]).tolist()
    [[0, 0], [-2, 0], [0, -1]]
    """
    data, out_kind, path = D.one(p, "p")
    if path == "py":
        return _exact.to_array([(-x, -y) for x, y in data], out_kind)
    return -data  # int64 here has |x| < 2**62: negation cannot overflow


def cspace_obstacle(obstacle: ArrayLike2, robot: ArrayLike2, *, hull: bool = False) -> Polygon:
    """Configuration-space obstacle ``obstacle ⊕ (−robot)`` for a translating robot.

    The robot, with its reference point at the origin of its own coordinates, collides
    with the obstacle exactly when the reference point lies in the returned polygon.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.cspace_obstacle([(0, 0), (4, 0), (4, 4), (0, 4)], [(0, 0), (1, 0), (0, 1)]).tolist()
    [[0, -1], [4, -1], [4, 4], [-1, 4], [-1, 0]]
    """
    return minkowski_sum(obstacle, reflect(robot), hull=hull)
