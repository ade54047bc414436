"""Exact geometric predicates: orientation and the cross-product sign of two edge vectors.

For ints and Fractions the arithmetic is exact as written. For floats the test is
*filtered*: the float value decides when it is larger than a proven error bound, and an
exact rational evaluation decides otherwise (a float is an exact dyadic rational, so
``Fraction(x)`` loses nothing). No angle is ever computed.

The error bound is Shewchuk's ``ccwerrboundA = (3 + 16 eps) eps`` with ``eps = 2**-53``,
which covers the rounding of the coordinate differences as well as of the products.

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

from fractions import Fraction
from typing import Any

import numpy as np

__all__ = ["orient", "cross_sign", "orient_array", "ERRBOUND", "MINBOUND"]

EPS = 2.0**-53
#: Relative error bound of the float cross product (Shewchuk's ccwerrboundA).
ERRBOUND = (3.0 + 16.0 * EPS) * EPS
#: The bound is relative: it holds while the products stay clear of underflow. Below this
#: value of ERRBOUND * (|l| + |r|) (that is, |l| + |r| < 2**-960) the float test is not
#: trusted and the exact evaluation decides.
MINBOUND = ERRBOUND * 2.0**-960


def _sgn(v: Any) -> int:
    return (v > 0) - (v < 0)


def _cross_exact(a0: Any, a1: Any, b0: Any, b1: Any) -> int:
    d = (a1[0] - a0[0]) * (b1[1] - b0[1]) - (a1[1] - a0[1]) * (b1[0] - b0[0])
    return (d > 0) - (d < 0)


def _cross_float(a0: Any, a1: Any, b0: Any, b1: Any) -> int:
    """Filtered sign of (a1 - a0) x (b1 - b0) for float coordinates."""
    ux = a1[0] - a0[0]
    uy = a1[1] - a0[1]
    vx = b1[0] - b0[0]
    vy = b1[1] - b0[1]
    # A zero difference is exact (x - y == 0 only when x == y), so is the sign of any
    # difference; a product with an exactly-zero factor is exactly zero.
    if ux == 0.0 or vy == 0.0:
        return -(_sgn(uy) * _sgn(vx))
    if uy == 0.0 or vx == 0.0:
        return _sgn(ux) * _sgn(vy)
    lft = ux * vy
    rgt = uy * vx
    det = lft - rgt
    bound = ERRBOUND * (abs(lft) + abs(rgt))
    if bound >= MINBOUND:
        if det > bound:
            return 1
        if -det > bound:
            return -1
    return _cross_fraction(a0, a1, b0, b1)


def _cross_fraction(a0: Any, a1: Any, b0: Any, b1: Any) -> int:
    F = Fraction
    d = (F(a1[0]) - F(a0[0])) * (F(b1[1]) - F(b0[1])) - (F(a1[1]) - F(a0[1])) * (
        F(b1[0]) - F(b0[0])
    )
    return (d > 0) - (d < 0)


def _has_float(*pts: Any) -> bool:
    return any(isinstance(v, (float, np.floating)) for p in pts for v in p)


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

    Examples
    --------
    >>> cross_sign((0, 0), (1, 0), (5, 5), (5, 6))
    1
    """
    if _has_float(a0, a1, b0, b1):
        f = [(float(p[0]), float(p[1])) for p in (a0, a1, b0, b1)]
        if all(np.isfinite(v) for p in f for v in p):
            return _cross_float(*f)
        raise ValueError("cross_sign: non-finite coordinate")
    return _cross_exact(a0, a1, b0, b1)


def orient(p: Any, q: Any, r: Any) -> int:
    """Exact orientation of the triangle ``p, q, r``.

    Returns ``1`` for a left turn (counter-clockwise), ``-1`` for a right turn, ``0`` when
    the three points are collinear.

    Examples
    --------
    >>> orient((0, 0), (1, 1), (2, 2))
    0
    >>> orient((0, 0.1), (1, 0.2), (2, 0.3))  # collinear in decimal, not as floats
    -1
    """
    return cross_sign(p, q, p, r)


def orient_array(p: Any, q: Any, r: Any) -> np.ndarray:
    """Vectorized exact orientation of many triangles.

    Parameters
    ----------
    p, q, r : (n, 2) int or float
        Triangle corners (broadcastable).

    Returns
    -------
    (n,) int8
        Sign of ``(q - p) x (r - p)`` for each row.

    Examples
    --------
    >>> orient_array([[0, 0], [0, 0]], [[1, 0], [1, 1]], [[0, 1], [2, 2]]).tolist()
    [1, 0]
    """
    p, q, r = (np.asarray(v) for v in (p, q, r))
    p, q, r = np.broadcast_arrays(p, q, r)
    if all(v.dtype.kind in "iu" for v in (p, q, r)) and max(
        int(np.abs(v).max(initial=0)) for v in (p, q, r)
    ) < (1 << 30):
        pi, qi, ri = (v.astype(np.int64) for v in (p, q, r))
        d = (qi[:, 0] - pi[:, 0]) * (ri[:, 1] - pi[:, 1]) - (qi[:, 1] - pi[:, 1]) * (
            ri[:, 0] - pi[:, 0]
        )
        return np.sign(d).astype(np.int8)
    if all(v.dtype.kind == "f" for v in (p, q, r)) or (
        all(v.dtype.kind in "iuf" for v in (p, q, r))
        and not any(
            v.dtype.kind in "iu" and int(np.abs(v).max(initial=0)) > (1 << 53) for v in (p, q, r)
        )
    ):
        pf, qf, rf = (v.astype(np.float64) for v in (p, q, r))
        with np.errstate(all="ignore"):
            lft = (qf[:, 0] - pf[:, 0]) * (rf[:, 1] - pf[:, 1])
            rgt = (qf[:, 1] - pf[:, 1]) * (rf[:, 0] - pf[:, 0])
            det = lft - rgt
            bound = ERRBOUND * (np.abs(lft) + np.abs(rgt))
        out = np.sign(det).astype(np.int8)
        sure = (np.abs(det) > bound) & (bound >= MINBOUND)
        for k in np.flatnonzero(~sure):
            out[k] = _cross_fraction(*(tuple(float(c) for c in v[k]) for v in (pf, qf, pf, rf)))
        return out
    return np.array(
        [
            orient(tuple(a), tuple(b), tuple(c))
            for a, b, c in zip(p.tolist(), q.tolist(), r.tolist())
        ],
        dtype=np.int8,
    )
