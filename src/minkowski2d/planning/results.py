"""What the planner returns: :class:`Path` and :class:`NavMesh`."""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any, NamedTuple

import numpy as np

from ..errors import (
    OverflowGeometryError,
)

# --------------------------------------------------------------------------------------
# results


class Path:
    """A collision-free path of the robot's reference point.

    Attributes
    ----------
    points : (k, 2) ndarray
        The start, the bend points (C-obstacle vertices) and the goal, in order; int64 when
        the scene and the query are integers (bend points exact), else float64. ``k`` is 1
        when start and goal coincide.
    length : float
        Euclidean length: each segment's exact length correctly rounded to float64,
        summed with fsum. A length beyond float64 raises
        :class:`~minkowski2d.errors.OverflowGeometryError` (never ``inf``); the points
        are valid all the same.

    Examples
    --------
    >>> import numpy as np
    >>> p = Path(np.array([[0, 0], [3, 4]]))
    >>> p.length, len(p)
    (5.0, 2)
    """

    __slots__ = ("points", "_length")

    def __init__(self, points: np.ndarray) -> None:
        self.points = points
        self._length: float | None = None

    @property
    def length(self) -> float:
        if self._length is None:
            pts = self.points.tolist()
            try:
                self._length = math.fsum(_segment_length(a, b) for a, b in zip(pts, pts[1:]))
            except OverflowError:
                raise OverflowGeometryError(
                    "length: the path is longer than float64 can hold (1.8e308)",
                    argument="length",
                    hint="the path itself is valid; scale the scene down to measure it",
                ) from None
        return self._length

    def __len__(self) -> int:
        return len(self.points)

    def __repr__(self) -> str:
        return f"Path({len(self.points)} points, length={self.length!r})"

    def _plot_(self, ax: Any, **kwargs: Any) -> Any:
        return self.plot(ax, **kwargs)

    def plot(self, ax: Any = None, **kwargs: Any) -> Any:
        """Draw the path with matplotlib (imported only here); returns the axes.

        Examples
        --------
        >>> import numpy as np
        >>> ax = Path(np.array([[0, 0], [1, 1]])).plot()  # doctest: +SKIP
        """
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots()
            ax.set_aspect("equal")
        kw = {"color": "tab:blue", "lw": 2, "marker": "o", "ms": 3}
        kw.update(kwargs)
        pts = self.points.astype(np.float64)
        ax.plot(pts[:, 0], pts[:, 1], **kw)
        return ax


def _segment_length(a: Any, b: Any) -> float:
    """|b - a| correctly rounded to float64 (exact arithmetic on the ints or floats);
    OverflowError beyond float64."""
    dx = Fraction(b[0]) - Fraction(a[0])
    dy = Fraction(b[1]) - Fraction(a[1])
    if dx.denominator == 1 and dy.denominator == 1 and abs(dx) < _F26 and abs(dy) < _F26:
        return math.sqrt(int(dx) ** 2 + int(dy) ** 2)  # exact square: one rounding
    q = dx * dx + dy * dy  # the exact square of the length
    num, den = q.numerator, q.denominator
    # r = floor(sqrt(q) * 2**k) with at least 55 bits; sqrt(q) in [r, r + 1) / 2**k: a
    # value strictly inside rounds like sqrt(q) (no float64 rounding boundary is there)
    k = max(0, (110 - (num.bit_length() - den.bit_length())) // 2 + 1)
    m = (num << (2 * k)) // den
    r = math.isqrt(m)
    if r * r == m and (num << (2 * k)) % den == 0:
        return float(Fraction(r, 1 << k))
    return float(Fraction(2 * r + 1, 1 << (k + 1)))


_F26 = 1 << 26


class NavMesh(NamedTuple):
    """The navigation mesh of a planner's free space (:attr:`MotionPlanner.navmesh`).

    Attributes
    ----------
    vertices : (n, 2) float64 ndarray
        Exact vertices (every one a double: piece vertices and crossings that are).
    cells : list of (k,) int64 ndarrays
        Convex cells, counter-clockwise, as indices into ``vertices``.
    flags : (n,) int64 ndarray
        1 for a corner (the free angle exceeds 180 degrees), 2 for a junction (the
        free space pinches there), else 0.
    """

    vertices: np.ndarray
    cells: list
    flags: np.ndarray

    def polygons(self) -> Any:
        """The cells as shapely Polygons (for display; shapely imported here).

        Examples
        --------
        >>> import minkowski2d as mk
        >>> pl = mk.MotionPlanner([[(1, 1), (2, 1), (2, 2), (1, 2)]], workspace=(0, 0, 3, 3),
        ...                       method="mesh")
        >>> sum(p.area for p in pl.navmesh.polygons())
        8.0
        """
        import shapely

        return [shapely.Polygon(self.vertices[c]) for c in self.cells]
