"""Exceptions raised by minkowski2d.

Every error derives from :class:`GeometryError`, itself a :class:`ValueError`, so
``except ValueError`` keeps working for callers that do not care about the detail.
Each message names the argument (``a``, ``b``, ``As[3]``, ...) and, where it applies,
the vertex index in the caller's own input.

Examples
--------
>>> import minkowski2d as mk
>>> try:
...     mk.minkowski_sum([], [(0, 0)])
... except mk.errors.EmptyGeometryError as exc:
...     print(exc)
a: empty input (no vertices)
"""

from __future__ import annotations

__all__ = [
    "GeometryError",
    "EmptyGeometryError",
    "ShapeError",
    "NonFiniteError",
    "CoordinateTypeError",
    "NotConvexError",
    "SelfIntersectionError",
    "OverflowGeometryError",
    "InputFormatError",
]


class GeometryError(ValueError):
    """Base class of every input or result problem minkowski2d reports."""


class EmptyGeometryError(GeometryError):
    """The input has no vertices."""


class ShapeError(GeometryError):
    """The input is not an array-like of shape (n, 2)."""


class NonFiniteError(GeometryError):
    """A coordinate is NaN or infinite."""


class CoordinateTypeError(GeometryError):
    """A coordinate is not a real number (int, float or Fraction)."""


class NotConvexError(GeometryError):
    """A convex routine was given a non-convex polygon.

    Attributes
    ----------
    vertex : int or None
        Index, in the caller's input, of the vertex where convexity fails.
    """

    def __init__(self, message: str, vertex: int | None = None) -> None:
        super().__init__(message)
        self.vertex = vertex


class SelfIntersectionError(GeometryError):
    """A simple polygon was required but the boundary crosses itself."""


class OverflowGeometryError(GeometryError):
    """A float result does not fit in float64 (it would be infinite)."""


class InputFormatError(GeometryError):
    """A file or text could not be read as any supported polygon format."""
