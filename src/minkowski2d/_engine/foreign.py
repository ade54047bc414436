"""Foreign exceptions become minkowski2d errors: the one map, used at every boundary
(the public functions that call shapely/GEOS, json, or float conversions, and the
command line as its last line of defence).

============================  ==========================================================
foreign exception             minkowski2d error
============================  ==========================================================
OverflowError,                OverflowGeometryError (a number does not fit in float64)
FloatingPointError
RecursionError                InputFormatError (data nested too deeply)
UnicodeDecodeError            InputFormatError (not UTF-8 text)
json.JSONDecodeError          InputFormatError (not JSON)
ValueError of int() digits    InputFormatError (an integer with too many digits)
MemoryError                   ResourceLimitError
shapely's GEOSException       GeometryError, or OverflowGeometryError where GEOS fails
                              because of the magnitude (``magnitude=True``)
============================  ==========================================================

Examples
--------
>>> from minkowski2d._engine.foreign import foreign_errors
>>> try:
...     with foreign_errors("distance", "reading the distance"):
...         float(2**1100)
... except ValueError as exc:
...     print(type(exc).__name__, "|", exc)
OverflowGeometryError | distance: a number does not fit in float64 while reading the \
distance (int too large to convert to float)
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from contextlib import contextmanager

from ..errors import (
    GeometryError,
    InputFormatError,
    OverflowGeometryError,
    ResourceLimitError,
)

__all__ = ["translate", "foreign_errors"]


def _geos_error(exc: BaseException) -> bool:
    mod = type(exc).__module__
    return mod.startswith("shapely")


def translate(
    exc: BaseException, argument: str, what: str, magnitude: bool = False
) -> GeometryError | None:
    """The minkowski2d error for a foreign exception ``exc`` raised while ``what``, naming
    ``argument``; None when ``exc`` is not one this module translates (a bug: let it
    propagate with its traceback)."""
    if isinstance(exc, GeometryError):
        return exc
    detail = str(exc) if len(str(exc)) <= 200 else str(exc)[:197] + "..."
    where = f"{argument}: " if argument else ""
    if isinstance(exc, (OverflowError, FloatingPointError)):
        return OverflowGeometryError(
            f"{where}a number does not fit in float64 while {what} ({detail})",
            argument=argument,
            hint="scale the input down",
        )
    if isinstance(exc, RecursionError):
        return InputFormatError(
            f"{where}nested too deeply while {what}",
            argument=argument,
            hint="a polygon is a list of [x, y] pairs",
        )
    if isinstance(exc, UnicodeDecodeError):
        return InputFormatError(
            f"{where}not UTF-8 text (byte {exc.start})", argument=argument, hint=None
        )
    if isinstance(exc, json.JSONDecodeError):
        return InputFormatError(
            f"{where}not JSON ({exc.msg} at line {exc.lineno}, column {exc.colno})",
            argument=argument,
        )
    if isinstance(exc, MemoryError):
        return ResourceLimitError(
            f"{where}out of memory while {what}",
            argument=argument,
            hint="reduce the number of vertices",
        )
    if _geos_error(exc):
        if magnitude:
            return OverflowGeometryError(
                f"{where}GEOS failed while {what} ({type(exc).__name__}: {detail}); its "
                "arithmetic underflows or overflows at this magnitude",
                argument=argument,
                hint="scale the coordinates by a power of two into [2**-500, 2**500]",
            )
        return GeometryError(
            f"{where}GEOS failed while {what} ({type(exc).__name__}: {detail})",
            argument=argument,
            hint="check that the input is a valid polygon; please report it if it is",
        )
    if isinstance(exc, ValueError) and "digits" in str(exc):
        return InputFormatError(
            f"{where}an integer with too many digits ({detail})",
            argument=argument,
            hint="integers are limited to 4300 digits",
        )
    return None


@contextmanager
def foreign_errors(argument: str, what: str, magnitude: bool = False) -> Iterator[None]:
    """Context manager: :func:`translate` every foreign exception raised inside (a
    GeometryError passes unchanged, and so does anything :func:`translate` does not
    know)."""
    try:
        yield
    except GeometryError:
        raise
    except Exception as exc:  # noqa: BLE001 - translated or re-raised as is
        err = translate(exc, argument, what, magnitude)
        if err is None:
            raise
        raise err from exc
