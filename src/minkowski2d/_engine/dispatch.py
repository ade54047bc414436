"""The one router: what the caller gave -> (kind, data) -> the compiled core or the exact
Python path; status codes -> exceptions.

Status codes become exceptions in :mod:`minkowski2d._engine.status` (re-exported here).

Paths
-----
* ``"i"``: the core's int64 kernels. Ints with ``|x| < 2**62`` (``core.INT_LIMIT``), so
  every cross product of differences fits in ``__int128``.
* ``"f"``: the core's float64 kernels. Any finite float, subnormal to 1.7e308: the filter
  decides, an exact accumulator decides what the filter cannot. Ints with ``|x| <= 2**53``
  next to floats are converted exactly.
* ``"py"``: :mod:`minkowski2d._engine.exact`, on Python ints and Fractions. Ints at or beyond
  2**62, Fractions (also next to floats), and ints beyond 2**53 next to floats (then the
  output is float, each coordinate correctly rounded from the exact sum).

Output kinds: ``"int"`` (int64, or Python ints in an object array beyond int64),
``"float"`` (float64), ``"exact"`` (Fractions in an object array).

Examples
--------
>>> from minkowski2d._engine.dispatch import pair
>>> A, B, out_kind, path = pair([(0, 0), (1, 0)], [(0.5, 0.0)], ("a", "b"))
>>> out_kind, path, A.dtype
('float', 'f', dtype('float64'))
>>> pair([(2**70, 0)], [(1, 1)], ("a", "b"))[2:]
('int', 'py')
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

import numpy as np

from . import core
from . import exact as _exact
from .coerce import EXACT, FLOAT, XFLOAT
from .core import Status
from .reader import Operand, read
from .status import raise_status, status_error

__all__ = ["Status", "Operand", "pair", "status_error", "raise_status"]

INT_LIMIT = core.INT_LIMIT

#: Tests set this to send everything through the exact Python path, to check that it and
#: the core give identical results ("every speed identical").
FORCE_EXACT = False


def _out_kind(*kinds: str) -> str:
    if EXACT in kinds:
        return EXACT
    if FLOAT in kinds or XFLOAT in kinds:
        return "float"
    return "int"


def exact_rows(data: Any) -> list:
    """(n, 2) rows (an ndarray or a list of pairs) as a list of exact tuples: ints stay
    ints, floats become Fractions (exactly), Fractions stay."""
    rows = data.tolist() if isinstance(data, np.ndarray) else data
    return [
        (Fraction(x) if isinstance(x, float) else x, Fraction(y) if isinstance(y, float) else y)
        for x, y in rows
    ]


def exact_list(op: Operand) -> list:
    """The operand as a list of exact tuples (ints stay ints, floats become Fractions)."""
    if op.kind in (FLOAT, XFLOAT, EXACT) or op.path == "f":
        return exact_rows(op.data)
    return op.data if op.path == "py" else [tuple(r) for r in op.data.tolist()]


def unify(A: Operand, B: Operand) -> tuple[Any, Any, str, str]:
    """Two operands on one path: ``(data_a, data_b, out_kind, path)``."""
    out_kind = _out_kind(A.kind, B.kind)
    if FORCE_EXACT:
        return exact_list(A), exact_list(B), out_kind, "py"
    if A.path == B.path and A.path != "py":
        return A.data, B.data, out_kind, A.path
    if A.path != "py" and B.path != "py":
        # one int64, one float64: exact conversion when the ints stay within 2**53
        ia, fa = (A, B) if A.path == "i" else (B, A)
        if ia.data.size == 0 or int(np.abs(ia.data).max()) <= core.FLOAT_EXACT_INT:
            conv = ia.data.astype(np.float64)
            da, db = (conv, fa.data) if A.path == "i" else (fa.data, conv)
            return da, db, out_kind, "f"
    return exact_list(A), exact_list(B), out_kind, "py"


def pair(a: Any, b: Any, names: tuple[str, str]) -> tuple[Any, Any, str, str]:
    """Validate two polygons and bring them to one path: ``(A, B, out_kind, path)``."""
    return unify(read(a, names[0]), read(b, names[1]))


def one(p: Any, name: str) -> tuple[Any, str, str]:
    """Validate one polygon: ``(data, out_kind, path)`` with exact lists on path "py"."""
    op = read(p, name)
    if op.path == "py" or FORCE_EXACT:
        return exact_list(op), _out_kind(op.kind), "py"
    return op.data, _out_kind(op.kind), op.path


def check_convex(p: Any, name: str) -> bool:
    """Validate ``p`` (errors name it ``name``); True if convex, False if not."""
    from ..errors import NotConvexError

    data, _, path = one(p, name)
    if path == "py":
        try:
            _exact.normalize_list(data, name)
        except NotConvexError:
            return False
        return True
    fn = core.normalize_i if path == "i" else core.normalize_f
    _, _, code, v = fn(data)
    if code in (Status.TURNS_BOTH_WAYS, Status.SPIKE, Status.WINDS_TWICE):
        return False
    raise_status(code, v, name, data)
    return True


# --------------------------------------------------------------------------------------
# hull and normalize: the engine's own (public modules and the engine call these)


def hull_core(data: np.ndarray, path: str) -> np.ndarray:
    h = (core.hull_i if path == "i" else core.hull_f)(data)
    return np.ascontiguousarray(data[h])


def normalize_core(data: np.ndarray, path: str, name: str) -> np.ndarray:
    idx, _, code, v = (core.normalize_i if path == "i" else core.normalize_f)(data)
    if code == Status.RANGE:
        return _exact.to_array(
            _exact.normalize_list([tuple(r) for r in data.tolist()], name)[0], "int"
        )
    raise_status(code, v, name, data)
    return data[idx]


def normalized(p: Any, name: str, hull: bool = False) -> Any:
    """``p`` normalized (CCW, bottom-most first, no duplicate or collinear vertices); with
    ``hull``, its convex hull. Errors name ``name``."""
    data, out_kind, path = one(p, name)
    if path == "py":
        if hull:
            data = _exact.hull_list(data)
        return _exact.to_array(_exact.normalize_list(data, name)[0], out_kind)
    if hull:
        data = hull_core(data, path)
    return normalize_core(data, path, name)


def hull(points: Any, name: str) -> Any:
    """The convex hull of a point set, normalized. Errors name ``name``."""
    data, out_kind, path = one(points, name)
    if path == "py":
        q = _exact.normalize_list(_exact.hull_list(data), name)[0]
        return _exact.to_array(q, out_kind)
    return normalize_core(hull_core(data, path), path, name)
