"""Checking options (keyword arguments), in one place for every public function.

Each checker returns the value in the form the kernels want (a Python ``int`` for
``threads``, ...) or raises :class:`~minkowski2d.errors.OptionError`, which is a
GeometryError, a ValueError and a TypeError, naming the option (``argument``) and what
it takes (``allowed``). numpy integers are accepted wherever Python ints are; bools are
not ints here.

Examples
--------
>>> import numpy as np
>>> threads(np.int64(2))
2
>>> choice("gjk", "method", ("auto", "sum", "gjk"))
'gjk'
>>> try:
...     choice("fast", "method", ("auto", "sum", "gjk"))
... except ValueError as exc:
...     print(exc)
method: must be one of 'auto', 'sum', 'gjk', got 'fast'
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from fractions import Fraction
from typing import Any

import numpy as np

from ..errors import NonFiniteError, OptionError, OverflowGeometryError

__all__ = [
    "MAX_THREADS",
    "is_int",
    "threads",
    "progress",
    "choice",
    "integer",
    "real",
    "angle",
    "sequence",
]

#: The largest ``threads=`` any function takes (the kernels start one OS thread each).
MAX_THREADS = 1024


def _repr(v: Any) -> str:
    r = repr(v)
    return r if len(r) <= 40 else r[:37] + "..."


def is_int(v: Any) -> bool:
    """A Python or numpy integer (not a bool)."""
    return isinstance(v, (int, np.integer)) and not isinstance(v, (bool, np.bool_))


def integer(value: Any, name: str, lo: int | None = None, hi: int | None = None) -> int:
    """An int (Python or numpy) within ``[lo, hi]``, as a Python int."""
    if lo is not None and hi is not None:
        allowed = f"an int from {lo} to {hi}"
    elif lo is not None:
        allowed = f"an int of at least {lo}"
    else:
        allowed = "an int"
    if not is_int(value):
        raise OptionError(
            f"{name}: must be {allowed}, got {_repr(value)}",
            argument=name,
            allowed=allowed,
        )
    v = int(value)
    if (lo is not None and v < lo) or (hi is not None and v > hi):
        raise OptionError(
            f"{name}: must be {allowed}, got {_repr(value)}", argument=name, allowed=allowed
        )
    return v


def threads(value: Any, name: str = "threads") -> int:
    """``threads=``: an int from 1 to :data:`MAX_THREADS`."""
    return integer(value, name, 1, MAX_THREADS)


def progress(value: Any, name: str = "progress") -> Any:
    """``progress=``: None, a bool, or a callable ``cb(done, total)``."""
    if value is None or isinstance(value, (bool, np.bool_)) or callable(value):
        return bool(value) if isinstance(value, np.bool_) else value
    allowed = "True, False, None or a callable cb(done, total)"
    raise OptionError(
        f"{name}: must be {allowed}, not {_repr(value)}", argument=name, allowed=allowed
    )


def choice(value: Any, name: str, allowed: Sequence[Any]) -> Any:
    """One of ``allowed`` (compared with ``==`` after a type check: no ``1 == True``)."""
    kinds = {type(a) for a in allowed}
    if type(value) in kinds or (value is None and None in allowed):
        for a in allowed:
            if value == a:
                return a
    text = ", ".join(repr(a) for a in allowed)
    raise OptionError(
        f"{name}: must be one of {text}, got {_repr(value)}",
        argument=name,
        allowed=f"one of {text}",
    )


_REAL = (int, float, Fraction, np.integer, np.floating)


def real(value: Any, name: str, what: str = "number") -> float:
    """A real number as a finite float64.

    Raises OptionError for a non-number, NonFiniteError for NaN and infinities, and
    OverflowGeometryError for an int or Fraction beyond the float range."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, _REAL):
        raise OptionError(
            f"{name}: expected a real number, got {type(value).__name__}",
            argument=name,
            allowed="an int, float or Fraction",
            hint=f"give {name} as an int, float or Fraction",
        )
    try:
        f = float(value)
    except OverflowError:
        raise OverflowGeometryError(
            f"{name}: {_repr(value)} does not fit in float64",
            argument=name,
            hint=f"give a {what} below 1.7e308 (scale the input down)",
        ) from None
    if not math.isfinite(f):
        raise NonFiniteError(
            f"{name}: must be finite, got {value!r}", argument=name, hint=f"give a finite {name}"
        )
    return f


def angle(value: Any, name: str) -> int | float | Fraction:
    """An angle in degrees: an int, a float or a Fraction (numpy numbers converted), finite.

    Returned as given (ints and Fractions stay exact); the caller reduces it."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, _REAL):
        raise OptionError(
            f"{name}: a rotation must be a number of degrees, got {_repr(value)}",
            argument=name,
            allowed="a finite number of degrees",
        )
    if isinstance(value, np.integer):
        return int(value)
    if isinstance(value, (float, np.floating)):
        f = float(value)
        if not math.isfinite(f):
            raise OptionError(
                f"{name}: a rotation must be a finite number of degrees, got {_repr(value)}",
                argument=name,
                allowed="a finite number of degrees",
            )
        return f
    return value


def sequence(value: Any, name: str, allowed: str) -> list:
    """``list(value)`` for a sequence option (not a string, not None)."""
    if value is None or isinstance(value, (str, bytes)) or not _iterable(value):
        raise OptionError(
            f"{name}: must be {allowed}, got {_repr(value)}", argument=name, allowed=allowed
        )
    return list(value)


def _iterable(v: Any) -> bool:
    try:
        iter(v)
    except TypeError:
        return False
    return True
