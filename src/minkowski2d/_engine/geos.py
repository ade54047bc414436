"""The boundary with GEOS (shapely), shared by the modules that use it for booleans
(general sums, erosion, nesting, offsetting): failures translated into GeometryErrors,
polygon validation (exact, by the compiled core: GEOS does not decide it), and the shape
of a polygonal result. One place for each rule.

Examples
--------
>>> import shapely
>>> from minkowski2d._engine.geos import checked_polygonal, area_parts
>>> checked_polygonal(shapely.box(0, 0, 1, 1), "a", hint="fix it").area
1.0
>>> area_parts(shapely.GeometryCollection([shapely.box(0, 0, 1, 1), shapely.Point(5, 5)])).wkt
'POLYGON ((1 0, 1 1, 0 1, 0 0, 1 0))'
"""

from __future__ import annotations

from contextlib import contextmanager
from typing import Any

import numpy as np

from ..errors import (
    EmptyGeometryError,
    GeometryError,
    OverflowGeometryError,
    ResourceLimitError,
)

__all__ = ["boundary", "checked_polygonal", "area_parts"]


@contextmanager
def boundary(argument: str, what: str, overflow_raises: bool = True) -> Any:
    """Context manager: turn a shapely / GEOS / numpy failure into a GeometryError that
    names ``argument`` (a GeometryError passes through unchanged). With
    ``overflow_raises`` a float overflow inside is an OverflowGeometryError (for work on
    rescaled coordinates, where none may happen); without, numpy's default applies."""
    import shapely.errors

    try:
        with np.errstate(over="raise" if overflow_raises else "ignore", invalid="ignore"):
            yield
    except GeometryError:
        raise
    except MemoryError as exc:
        raise ResourceLimitError(
            f"{argument}: out of memory while {what}",
            argument=argument,
            hint="reduce the number of vertices (or of non-convex vertices)",
        ) from exc
    except (OverflowError, FloatingPointError) as exc:
        raise OverflowGeometryError(
            f"{argument}: a coordinate overflows float64 while {what} ({exc})",
            argument=argument,
            hint="the result does not fit in float64; scale the input down",
        ) from exc
    except (shapely.errors.ShapelyError, ValueError) as exc:
        raise GeometryError(
            f"{argument}: GEOS failed while {what} ({type(exc).__name__}: {exc})",
            argument=argument,
            hint="check that the input is a valid polygon; please report it if it is",
        ) from exc


def checked_polygonal(geom: Any, name: str, hint: str, nonfinite_hint: str | None = None) -> Any:
    """Validate a Polygon / MultiPolygon exactly and orient it (exteriors CCW, holes CW).

    The checks are the compiled core's (:func:`minkowski2d._engine.polygon.check`: exact signs at
    every magnitude, no GEOS). Empty → EmptyGeometryError; NaN/inf → NonFiniteError; a
    boundary that crosses or touches itself, rings that cross or overlap, a hole outside
    the shell or inside another hole, parts of a MultiPolygon that overlap →
    SelfIntersectionError with ``hint``, naming the ring and vertex. A hole that touches
    the shell at two points (valid for CGAL, "interior is disconnected" for GEOS) is a
    well-defined region: it is split into its parts (by the core's exact overlay: the
    union of its rings, traced ring by ring, splits at the touching points).
    """
    from .polygon import check_split, oriented, rings_of, to_geometry

    if geom.is_empty:
        raise EmptyGeometryError(f"{name}: empty {geom.geom_type}", argument=name)
    multi = geom.geom_type == "MultiPolygon"
    given = rings_of(geom)
    rings, ck = check_split(given, name, hint, disjoint=multi, nonfinite_hint=nonfinite_hint)
    if rings is not given:  # split into its parts: one Polygon, or a MultiPolygon of them
        multi = len(rings.polygon_offsets) > 2
    return to_geometry(oriented(rings, ck.orientation), multi)


def area_parts(geom: Any) -> Any:
    """The parts of ``geom`` with area, as one Polygon or MultiPolygon (an empty Polygon
    when there are none): what a boolean of polygons means as a region."""
    import shapely

    parts = shapely.get_parts(geom)
    polys = parts[(shapely.get_type_id(parts) == 3) & (shapely.area(parts) > 0)]
    if len(polys) == 0:
        return shapely.Polygon()
    return polys[0] if len(polys) == 1 else shapely.multipolygons(polys)
