"""Turn what the caller gave into one of two internal forms, with every check in one place.

* ``PyPoints``: a Python list of ``(x, y)`` tuples plus a kind, for tiny inputs and for
  exact numbers that numpy cannot hold (Python ints beyond int64, Fractions).
* ``ndarray``: an (n, 2) int64 or float64 array for the compiled kernels.

The dtype policy
----------------
* ints (Python ``int``, numpy signed/unsigned integers) are exact: kind ``"int"``;
* any float among the coordinates makes the whole polygon float64: kind ``"float"``
  (the same upcast numpy does);
* ``fractions.Fraction`` (and ints mixed with them) stay exact: kind ``"exact"``;
* bools, complex numbers, strings and anything else are rejected.
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any

import numpy as np

from ..errors import (
    CoordinateTypeError,
    EmptyGeometryError,
    NotConvexError,
    ShapeError,
)
from . import core
from .status import nonfinite

INT, FLOAT, EXACT = "int", "float", "exact"
#: floats next to ints beyond 2**53: exact decisions (Fractions), float output
XFLOAT = "xfloat"

_F53 = core.FLOAT_EXACT_INT
INT64_MAX = (1 << 63) - 1
INT64_MIN = -(1 << 63)

_FLOAT_TYPES = (float, np.floating)
_INT_TYPES = (int, np.integer)


def fits_float64(v: int) -> bool:
    """Whether the int ``v`` converts to float64 exactly: at most 53 significant bits
    (trailing zeros do not count) and below the float range. Every ``|v| <= 2**53``
    does (``core.FLOAT_EXACT_INT``, the fast bound the kernels use); ``2**60`` does too.

    >>> fits_float64(2**53 + 1), fits_float64(2**60), fits_float64(-(2**53 - 1) << 900)
    (False, True, True)
    """
    if -_F53 <= v <= _F53:
        return True
    m = abs(v)
    return (m >> ((m & -m).bit_length() - 1)).bit_length() <= 53 and m.bit_length() <= 1024


def ints_fit_float64(values: Any) -> bool:
    """:func:`fits_float64` for every int of ``values``: an int ndarray (one comparison
    when all are within 2**53), or an iterable of numbers whose non-ints are ignored.

    >>> import numpy as np
    >>> ints_fit_float64(np.array([[3, 2**60]])), ints_fit_float64([0.5, 2**53 + 1])
    (True, False)
    """
    if isinstance(values, np.ndarray):
        if values.size == 0 or values.dtype.kind not in "iu":
            return True
        if max(int(values.max()), -int(values.min())) <= _F53:
            return True
        big = values[(values > _F53) | (values < -_F53)]
        return all(fits_float64(int(v)) for v in big.ravel().tolist())
    return all(fits_float64(v) for v in values if type(v) is int)


def to_float(v: Any) -> float:
    """The nearest float to an exact number; ``inf`` (with the sign) when it is beyond
    the float range (``float()`` raises OverflowError there)."""
    try:
        return float(v)
    except OverflowError:
        return math.inf if v > 0 else -math.inf


def is_shapely(x: Any) -> bool:
    """True for a shapely geometry (or any object of a shapely module), without
    importing shapely."""
    return type(x).__module__.startswith("shapely")


def _kind_of_scalar(v: Any, name: str, k: int) -> str:
    """Kind of one coordinate value; raise for anything that is not a real number."""
    t = type(v)
    if t is int:
        return INT
    if t is float:
        return FLOAT
    if t is bool or isinstance(v, np.bool_):
        raise CoordinateTypeError(f"{name}: vertex {k} has a bool coordinate ({v!r}); use numbers")
    if isinstance(v, _INT_TYPES):
        return INT
    if isinstance(v, _FLOAT_TYPES):
        return FLOAT
    if isinstance(v, Fraction):
        return EXACT
    raise CoordinateTypeError(
        f"{name}: vertex {k} has a coordinate of type {t.__name__} ({v!r}); "
        "expected int, float or Fraction"
    )


def _wide(v: Any) -> bool:
    """A numpy float wider than float64 (longdouble): it may hold values float64 cannot."""
    return isinstance(v, np.floating) and v.dtype.itemsize > 8


def _exact_wide(arr: np.ndarray, name: str) -> tuple[list, str] | None:
    """A longdouble array whose values float64 cannot all hold, as exact Fractions (kind
    ``"exact"``: never rounded); None when every value is a float64 value."""
    with np.errstate(all="ignore"):
        a = arr.astype(np.float64)
        same = (a.astype(arr.dtype) == arr) | ~np.isfinite(arr)
    if same.all():
        return None
    if not np.isfinite(arr).all():
        bad = int(np.flatnonzero(~np.isfinite(arr).all(axis=1))[0])
        raise nonfinite(name, bad, arr)
    F = Fraction
    return [(F(*x.as_integer_ratio()), F(*y.as_integer_ratio())) for x, y in arr], EXACT


def _shapely_coords(obj: Any, name: str) -> np.ndarray | None:
    """Vertices of a shapely geometry, or None if ``obj`` is not one."""
    mod = type(obj).__module__
    if not mod.startswith("shapely"):
        return None
    import shapely

    if obj.is_empty:
        raise EmptyGeometryError(f"{name}: empty input (empty {obj.geom_type})")
    gt = obj.geom_type
    if gt == "Polygon":
        if len(obj.interiors):
            raise NotConvexError(
                f"{name}: polygon has {len(obj.interiors)} hole(s), so it is not convex"
            )
        coords = shapely.get_coordinates(obj.exterior)
        return coords[:-1] if len(coords) > 1 else coords
    if gt in ("LinearRing", "LineString", "Point", "MultiPoint"):
        coords = shapely.get_coordinates(obj)
        if gt == "LinearRing" and len(coords) > 1:
            coords = coords[:-1]
        return coords
    raise ShapeError(f"{name}: a shapely {gt} is not a single polygon, ring or point set")


def py_points(seq: Any, name: str) -> tuple[list[tuple[Any, Any]], str]:
    """Validate a sequence of pairs in pure Python.

    Returns the list of ``(x, y)`` tuples and the kind:

    * ``"int"``: Python ints (numpy ints converted);
    * ``"float"``: Python floats (ints next to them are at most 2**53, converted exactly);
    * ``"xfloat"``: floats next to ints beyond 2**53: every value as an exact int or
      Fraction (no rounding before deciding), the output is float;
    * ``"exact"``: Fractions present: every value as an int or Fraction (a float next to
      a Fraction is converted exactly, never the Fraction to float).

    Raises the specific :mod:`minkowski2d.errors` exception otherwise.
    """
    out: list[tuple[Any, Any]] = []
    kinds = set()
    big_int = False
    append = out.append
    for k, p in enumerate(seq):
        try:
            x, y = p
        except (TypeError, ValueError):
            raise ShapeError(
                f"{name}: vertex {k} is {p!r}, not an (x, y) pair; expected shape (n, 2)",
                argument=name,
                vertex=k,
            ) from None
        tx = type(x)
        if tx is type(y) and (tx is int or tx is float):
            if tx is float and ((x - x) or (y - y)):  # nan for inf and nan, 0.0 otherwise
                raise nonfinite(name, k, point=(x, y))
            if tx is int:
                kinds.add(INT)
                if not (-_F53 <= x <= _F53 and -_F53 <= y <= _F53):
                    big_int = True
            else:
                kinds.add(FLOAT)
            append((x, y))
            continue
        kx = _kind_of_scalar(x, name, k)
        ky = _kind_of_scalar(y, name, k)
        vals = []
        for v, kv in ((x, kx), (y, ky)):
            if kv == FLOAT and _wide(v):
                # a longdouble (or wider) value float64 cannot hold: kept exact
                f = float(v)
                if f - f == 0 and f != v:
                    v, kv = Fraction(*v.as_integer_ratio()), EXACT
            if kv == FLOAT:
                v = float(v)
                if v - v:
                    raise nonfinite(name, k, point=(x, y))
            elif kv == INT:
                v = int(v)
                if not -_F53 <= v <= _F53:
                    big_int = True
            kinds.add(kv)
            vals.append(v)
        append((vals[0], vals[1]))
    if not out:
        raise EmptyGeometryError(f"{name}: empty input (no vertices)", argument=name)
    if EXACT in kinds:
        kind = EXACT
    elif FLOAT in kinds:
        kind = XFLOAT if (INT in kinds and big_int) else FLOAT
    else:
        return out, INT
    if kind == FLOAT:
        if INT in kinds:
            out = [(float(x), float(y)) for x, y in out]
        return out, FLOAT
    F = Fraction
    return [
        (F(x) if type(x) is not int else x, F(y) if type(y) is not int else y) for x, y in out
    ], kind


def as_array(obj: Any, name: str, check_finite: bool = True) -> tuple[np.ndarray | list, str]:
    """Coerce ``obj`` to an (n, 2) int64/float64 array, or to a Python list for exact kinds.

    Returns ``(data, kind)``; ``data`` is an ndarray for kinds ``"int"`` (values fit in
    int64) and ``"float"``, and a list of tuples where exact Python numbers are needed.
    The caller's array is never modified (a view is returned only when no conversion
    is needed, and callers treat it as read-only).
    """
    shp = _shapely_coords(obj, name)
    if shp is not None:
        obj = shp
    elif type(obj) is list or type(obj) is tuple:
        # read the Python values themselves: np.asarray would round ints beyond 2**53
        # next to floats, and float() a Fraction next to a float
        if len(obj) == 0:
            raise EmptyGeometryError(f"{name}: empty input (no vertices)", argument=name)
        pts, kind = py_points(obj, name)
        if kind == FLOAT:
            return np.array(pts, dtype=np.float64).reshape(-1, 2), FLOAT
        if kind == INT and all(INT64_MIN <= v <= INT64_MAX for p in pts for v in p):
            return np.array(pts, dtype=np.int64).reshape(-1, 2), INT
        return pts, kind
    try:
        arr = np.asarray(obj)
    except (ValueError, TypeError) as exc:
        raise ShapeError(
            f"{name}: cannot read as an (n, 2) array of coordinates ({exc})", argument=name
        ) from None
    if arr.size == 0:
        raise EmptyGeometryError(f"{name}: empty input (no vertices)", argument=name)
    if arr.ndim != 2 or arr.shape[1] != 2:
        raise ShapeError(
            f"{name}: expected shape (n, 2), got {arr.shape}",
            argument=name,
            hint="give a sequence of (x, y) pairs",
        )
    dk = arr.dtype.kind
    if dk == "f" and arr.dtype.itemsize > 8 and (wide := _exact_wide(arr, name)) is not None:
        return wide
    if dk == "f":
        a = arr.astype(np.float64, copy=False)
        # ``check_finite=False``: the caller's own range pass (convex._fits_kernel) checks
        if check_finite and not np.isfinite(a).all():
            bad = int(np.flatnonzero(~np.isfinite(a).all(axis=1))[0])
            raise nonfinite(name, bad, a)
        return a, FLOAT
    if dk == "i":
        return arr.astype(np.int64, copy=False), INT
    if dk == "u":
        if arr.dtype.itemsize < 8 or int(arr.max()) <= INT64_MAX:
            return arr.astype(np.int64), INT
        return py_points(arr.tolist(), name)
    if dk == "O":
        pts, kind = py_points(arr.tolist(), name)
        if kind == FLOAT:
            return np.array(pts, dtype=np.float64), FLOAT
        if kind == INT and all(INT64_MIN <= v <= INT64_MAX for p in pts for v in p):
            return np.array(pts, dtype=np.int64), INT
        return pts, kind
    if dk == "b":
        raise CoordinateTypeError(f"{name}: coordinates are bools; use numbers")
    raise CoordinateTypeError(f"{name}: coordinates of dtype {arr.dtype} are not real numbers")
