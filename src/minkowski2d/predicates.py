"""Exact geometric predicates: orientation and the cross-product sign of two edge vectors.

Floats and ints with ``|x| < 2**62`` are decided by the compiled core
(:mod:`minkowski2d._core`): ints with 128-bit products, floats with a filtered test -- the
float value decides when it is larger than a proven error bound (Shewchuk's
``ccwerrboundA = (3 + 16 eps) eps``, ``eps = 2**-53``, which covers the rounding of the
coordinate differences as well as of the products) -- and an exact fixed-point evaluation
otherwise, at every magnitude from subnormals to ``1.7e308``. Larger ints, Fractions and
mixtures (a Fraction next to a float, a large int next to a float) take an exact
pure-Python path: a float is an exact dyadic rational, so ``Fraction(x)`` loses nothing,
and a Fraction is never rounded to a float. No angle is ever computed. NaN and infinite
coordinates raise :class:`~minkowski2d.errors.NonFiniteError`.

Examples
--------
>>> from minkowski2d.predicates import orient, cross_sign
>>> orient((0, 0), (1, 0), (0, 1))
1
>>> u0, u1 = (0.0, 0.0), (2.0**27 + 1, 2.0**27)
>>> v0, v1 = (0.0, 0.0), (2.0**27, 2.0**27 - 1)
>>> (u1[0] * v1[1] - u1[1] * v1[0])  # the float cross product rounds to zero
0.0
>>> cross_sign(u0, u1, v0, v1)      # ... the exact sign is not
-1
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ._engine import core
from ._engine import dispatch as D
from ._engine.reader import read
from ._engine.status import nonfinite
from .errors import NonFiniteError, ShapeError

__all__ = ["orient", "cross_sign", "orient_array", "ERRBOUND", "MINBOUND"]

#: Relative error bound of the float cross product (Shewchuk's ccwerrboundA; exact.hpp).
ERRBOUND = core.ERRBOUND
#: The bound is relative: it holds while the products stay clear of underflow. Below this
#: value of ERRBOUND * (|l| + |r|) (that is, |l| + |r| < 2**-960) the float test is not
#: trusted and the exact evaluation decides.
MINBOUND = core.MINBOUND

_INT_LIMIT = core.INT_LIMIT  # the core's int64 predicate
_F64_EXACT_INT = core.FLOAT_EXACT_INT  # ints up to this convert to float64 exactly


def _cross(pts: tuple[Any, ...], names: tuple[str, ...]) -> int:
    """Exact sign of (pts[1] - pts[0]) x (pts[3] - pts[2]), on the path the dispatcher
    chooses for the four points (the one router: core int64, core float64, or exact)."""
    try:
        op = read(list(pts), "point")
    except NonFiniteError as exc:
        k = exc.vertex if isinstance(exc.vertex, int) and 0 <= exc.vertex < len(pts) else 0
        raise nonfinite(names[k], k, pts, where="the point") from None
    if op.path == "i":
        return core.cross_sign_i(*op.data.ravel().tolist())
    if op.path == "f":
        return core.cross_sign_f(*op.data.ravel().tolist())
    # ints beyond 2**62, large ints next to floats, Fractions: exact Python
    e = [c for p in D.exact_list(op) for c in p]
    d = (e[2] - e[0]) * (e[7] - e[5]) - (e[3] - e[1]) * (e[6] - e[4])
    return (d > 0) - (d < 0)


def cross_sign(a0: Any, a1: Any, b0: Any, b1: Any) -> int:
    """Exact sign of the cross product ``(a1 - a0) x (b1 - b0)``.

    Parameters
    ----------
    a0, a1, b0, b1 : (2,) int, float or Fraction
        The tails and heads of two vectors.

    Returns
    -------
    int
        ``1`` if ``b1 - b0`` is counter-clockwise of ``a1 - a0``, ``-1`` if clockwise,
        ``0`` if parallel.

    Raises
    ------
    NonFiniteError
        A coordinate is NaN or infinite (``argument`` names the point).

    Examples
    --------
    >>> cross_sign((0, 0), (1, 0), (5, 5), (5, 6))
    1
    >>> from fractions import Fraction
    >>> cross_sign((0.0, 0.0), (1.0, 0.1), (0, 0), (10, Fraction(1)))  # 0.1 is not 1/10
    -1
    """
    return _cross((a0, a1, b0, b1), ("a0", "a1", "b0", "b1"))


def orient(p: Any, q: Any, r: Any) -> int:
    """Exact orientation of the triangle ``p, q, r``.

    Returns ``1`` for a left turn (counter-clockwise), ``-1`` for a right turn, ``0`` when
    the three points are collinear.

    Raises
    ------
    NonFiniteError
        A coordinate is NaN or infinite (``argument`` is ``"p"``, ``"q"`` or ``"r"``).

    Examples
    --------
    >>> orient((0, 0), (1, 1), (2, 2))
    0
    >>> orient((0, 0.1), (1, 0.2), (2, 0.3))  # collinear in decimal, not as floats
    -1
    """
    return _cross((p, q, p, r), ("p", "q", "p", "r"))


def _int_span(v: np.ndarray) -> int:
    """max |x| over an int array, as a Python int (no overflow at -2**63)."""
    if v.size == 0:
        return 0
    return max(int(v.max()), -int(v.min()))


def orient_array(p: Any, q: Any, r: Any) -> np.ndarray:
    """Vectorized exact orientation of many triangles.

    Parameters
    ----------
    p, q, r : (n, 2) int, float or Fraction
        Triangle corners (broadcastable).

    Returns
    -------
    (n,) int8
        Sign of ``(q - p) x (r - p)`` for each row.

    Raises
    ------
    NonFiniteError
        A coordinate is NaN or infinite (``argument`` names the array, ``vertex`` the row).

    Examples
    --------
    >>> orient_array([[0, 0], [0, 0]], [[1, 0], [1, 1]], [[0, 1], [2, 2]]).tolist()
    [1, 0]
    """
    names = ("p", "q", "r")
    arrs = [np.asarray(v) for v in (p, q, r)]
    arrs = [v.reshape(0, 2) if v.size == 0 else v for v in arrs]
    arrs = list(np.broadcast_arrays(*arrs))
    if arrs[0].ndim != 2 or arrs[0].shape[1] != 2:
        raise ShapeError(
            f"orient_array: p, q and r must broadcast to shape (n, 2), got {arrs[0].shape}",
            argument="p",
        )
    kinds = [v.dtype.kind for v in arrs]
    for name, v in zip(names, arrs):
        if v.dtype.kind == "f":
            bad = ~np.isfinite(v).all(axis=1)
            if bad.any():
                row = int(np.flatnonzero(bad)[0])
                raise nonfinite(name, row, v, where=f"row {row}")
    if all(k in "iub" for k in kinds) and max(_int_span(v) for v in arrs) < _INT_LIMIT:
        pi, qi, ri = (np.ascontiguousarray(v, dtype=np.int64) for v in arrs)
        return core.orient_i(pi, qi, ri)
    if (
        all(k in "iubf" for k in kinds)
        and all(v.dtype.itemsize <= 8 for v in arrs if v.dtype.kind == "f")
        and all(_int_span(v) <= _F64_EXACT_INT for v in arrs if v.dtype.kind in "iub")
    ):
        pf, qf, rf = (np.ascontiguousarray(v, dtype=np.float64) for v in arrs)
        return core.orient_f(pf, qf, rf)
    # object arrays (Fractions, large ints), long doubles, large ints next to floats
    out = np.empty(len(arrs[0]), dtype=np.int8)
    for k, (a, b, c) in enumerate(zip(*(v.tolist() for v in arrs))):
        try:
            out[k] = _cross((a, b, a, c), ("p", "q", "p", "r"))
        except NonFiniteError as exc:
            exc.vertex = k
            raise
    return out
