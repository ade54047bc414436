"""Status -> exception: the one table. Every core status a public call can meet becomes
its exception here; callers give only the context (which argument, which operation,
where in the input, the limits and the hint that fit the call).

==================  ======================  =============================================
status              exception               message
==================  ======================  =============================================
TURNS_BOTH_WAYS,    NotConvexError          ``{name}: not convex: ... at vertex {v}``
SPIKE, WINDS_TWICE
NONFINITE           NonFiniteError          ``{name}: {where} has a non-finite coordinate``
OVERFLOW            OverflowGeometryError   ``{name}: {what} overflows float64 ...``
RESOURCE            ResourceLimitError      ``{name}: {what} needs more work than {limits}``
INVALID_POLYGON     SelfIntersectionError   ``{name}: not a valid polygon ({detail} at ...)``
SHAPE               ShapeError              ``{name}: {detail}``
anything else       GeometryError           ``{name}: internal error {status} in {what}``
==================  ======================  =============================================

Examples
--------
>>> from minkowski2d._engine.status import Status, status_error
>>> e = status_error(Status.RESOURCE, name="a", what="the overlay")
>>> type(e).__name__, e.hint
('ResourceLimitError', 'simplify the polygons')
>>> str(e)
'a: the overlay needs more work than its work limits allow'
>>> str(status_error(Status.NONFINITE, 1, "A", coords=[(0, 0), (float("nan"), 1.0)]))
'A: vertex 1 has a non-finite coordinate (nan, 1.0)'
"""

from __future__ import annotations

from typing import Any

from ..errors import (
    GeometryError,
    NonFiniteError,
    OverflowGeometryError,
    ResourceLimitError,
    SelfIntersectionError,
    ShapeError,
)
from . import exact as _exact
from .core import Status

__all__ = ["Status", "status_error", "raise_status", "nonfinite", "NOT_CONVEX"]

#: the convexity statuses (one message each, in :func:`exact.not_convex`)
NOT_CONVEX = (Status.TURNS_BOTH_WAYS, Status.SPIKE, Status.WINDS_TWICE)

_OVERFLOW_HINT = "scale the input down (the result is exact up to the final rounding)"
_NONFINITE_HINT = "remove NaN and infinite values"


def _values(vertex: int, coords: Any) -> str:
    """`` (x, y)``: the vertex's coordinates where the caller passed them, else nothing."""
    if coords is not None:
        try:
            x, y = coords[vertex]
            return f" ({float(x)!r}, {float(y)!r})"
        except Exception:  # noqa: BLE001 - the message is best effort
            pass
    return ""


def status_error(
    code: int,
    vertex: int = 0,
    name: str = "result",
    coords: Any = None,
    *,
    what: str | None = None,
    where: str | None = None,
    detail: str | None = None,
    limits: str = "its work limits allow",
    hint: str | None = None,
) -> GeometryError:
    """The exception for core status ``code`` (not OK).

    ``name``: the argument the fault is in (or "result"); ``vertex``: its vertex in the
    caller's numbering, ``coords`` its coordinates (to quote the vertex); ``where``: a
    location that replaces ``vertex k`` (ring-aware: "polygon 2, hole 0, vertex 5");
    ``what``: the operation or value ("the sum", "the overlay"; for an invalid polygon,
    what it is not); ``detail``: the specific reason (an invalid polygon's defect, a
    shape's fault); ``limits``: the work limits a RESOURCE exceeded; ``hint`` replaces
    the status's default hint.
    """
    code, vertex = int(code), int(vertex)
    at = f"vertex {vertex}" if where is None else where
    if code in NOT_CONVEX:
        return _exact.not_convex(name, code, vertex)
    if code == Status.NONFINITE:
        return NonFiniteError(
            f"{name}: {at} has a non-finite coordinate{_values(vertex, coords)}",
            argument=name,
            vertex=vertex,
            hint=_NONFINITE_HINT if hint is None else hint,
        )
    if code == Status.OVERFLOW:
        return OverflowGeometryError(
            f"{name}: {what or 'the result'} overflows float64 (a coordinate beyond ±1.8e308)",
            argument=name,
            hint=_OVERFLOW_HINT if hint is None else hint,
        )
    if code == Status.RESOURCE:
        return ResourceLimitError(
            f"{name}: {what or 'the operation'} needs more work than {limits}",
            argument=name,
            hint="simplify the polygons" if hint is None else hint,
        )
    if code == Status.INVALID_POLYGON:
        return SelfIntersectionError(
            f"{name}: {what or 'not a valid polygon'} ({detail or 'invalid'} at {at})",
            argument=name,
            vertex=vertex,
            hint=hint,
        )
    if code == Status.SHAPE:
        return ShapeError(f"{name}: {detail or 'cannot be read'}", argument=name, hint=hint)
    return GeometryError(
        f"{name}: internal error {code} in {what or 'the core'} (please report it)",
        argument=name,
        hint=hint,
    )


def nonfinite(
    name: str,
    vertex: int = 0,
    coords: Any = None,
    *,
    where: str | None = None,
    point: Any = None,
    hint: str | None = None,
) -> GeometryError:
    """``status_error(Status.NONFINITE, ...)``: the one message of a NaN or infinite
    coordinate, for the readers that find it before the core does (``point``: the bad
    vertex's coordinates, when the caller has them but no array of all)."""
    if point is not None:
        coords = {vertex: point}
    return status_error(Status.NONFINITE, vertex, name, coords, where=where, hint=hint)


def raise_status(code: int, vertex: int, name: str, coords: Any = None) -> None:
    """Raise :func:`status_error` unless ``code`` is OK."""
    if code != Status.OK:
        raise status_error(code, vertex, name, coords)
