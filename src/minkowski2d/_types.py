"""Type aliases used in the public signatures (what ``mypy --strict`` sees).

``ArrayLike2`` is what reads as one polygon: an (n, 2) ndarray, a sequence of (x, y)
pairs of real numbers (int, float, Fraction, numpy scalars), a sequence of (2,) arrays,
or a shapely geometry. A plain number or a string is not one, so ``minkowski_sum(1, 2)``
is a type error, as it is a run-time error. shapely ships no type information, so its
geometries are matched by shape (:class:`GeometryLike`: ``geom_type``, ``is_empty``,
``wkt``); under ``mypy --strict`` a shapely object is ``Any`` anyway.

``PolygonsLike`` is what the batch functions take: a :class:`~minkowski2d.Ragged`, a
sequence of polygons, a numpy object array of shapely geometries, a GeoSeries or
GeometryArray (matched by ``crs`` and ``__len__``), or one polygon (broadcast).

Examples
--------
>>> from minkowski2d._types import ArrayLike2
>>> "GeometryLike" in str(ArrayLike2), "Sequence" in str(ArrayLike2)
(True, True)
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from fractions import Fraction
from typing import TYPE_CHECKING, Any, Protocol, TypeAlias, Union

import numpy as np
import numpy.typing as npt

if TYPE_CHECKING:
    from .batch import Ragged

__all__ = [
    "ArrayLike2",
    "Polygon",
    "Coordinate",
    "GeometryLike",
    "GeoSeriesLike",
    "PolygonsLike",
    "ProgressLike",
]

#: One coordinate value: the dtype policy's real numbers (bools are rejected at run time).
Coordinate: TypeAlias = int | float | Fraction | np.integer[Any] | np.floating[Any]


class GeometryLike(Protocol):
    """A shapely geometry, matched by shape (shapely has no type information)."""

    @property
    def geom_type(self) -> str: ...

    @property
    def is_empty(self) -> bool: ...

    @property
    def wkt(self) -> str: ...


class GeoSeriesLike(Protocol):
    """A geopandas GeoSeries, GeoDataFrame or GeometryArray, matched by shape."""

    @property
    def crs(self) -> Any: ...

    def __len__(self) -> int: ...


#: Anything that reads as an (n, 2) array of coordinates: an ndarray, a sequence of
#: (x, y) pairs, a sequence of (2,) arrays, a shapely Polygon / LinearRing / LineString /
#: MultiPoint / Point.
ArrayLike2: TypeAlias = (
    npt.NDArray[Any] | Sequence[Sequence[Coordinate]] | Sequence[npt.NDArray[Any]] | GeometryLike
)

#: Many polygons (the batch functions' operands), or one polygon to broadcast.
PolygonsLike: TypeAlias = Union[  # noqa: UP007 - "Ragged" is a forward reference
    "Ragged",
    Sequence[ArrayLike2],
    Sequence[GeometryLike],
    npt.NDArray[Any],
    GeoSeriesLike,
    ArrayLike2,
]

#: ``progress=``: None/False (none), True (a tqdm bar), or ``cb(done, total)``.
ProgressLike: TypeAlias = bool | Callable[[int, int], object] | None

#: A polygon result: an (n, 2) ndarray (int64, float64, or object for exact numbers).
Polygon: TypeAlias = npt.NDArray[Any]
