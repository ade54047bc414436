"""Reading one polygon: JSON point lists, GeoJSON, WKT, and by file suffix CGAL ``.dat`` and
DXF."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import (
    EmptyGeometryError,
    InputFormatError,
    OverflowGeometryError,
    ShapeError,
)
from .cgal_dat import (
    read_cgal_dat,
)
from .common import _intify, _read_text, _short, split_selector
from .dxf import (
    _one_dxf,
)


def read_geometry(source: str | Path, *, arc_tolerance: float | None = None) -> Any:
    """Read one polygon (or point set) from a file path, or ``"-"`` for standard input.

    The format is recognised from the content (JSON point list, GeoJSON, WKT) or the
    ``.dat`` suffix (CGAL's format). A ``.dat`` file holding two polygons needs a
    selector: ``comb.dat#1`` or ``comb.dat#2``.

    Returns
    -------
    (n, 2) ndarray or shapely geometry
        An array for a simple ring or point list, a shapely Polygon for a polygon with
        holes, a MultiPolygon for several polygons.

    Raises
    ------
    GeometryError
        For every input that is not a polygon (usually :class:`InputFormatError`), naming
        the file and, where it can, the line, item or vertex.

    A ``.dxf`` drawing must hold one part; its arcs are read within ``arc_tolerance``
    (see :func:`read_dxf`).
    """
    s = str(source)
    path, sel = split_selector(s)
    if path.lower().endswith(".dxf"):
        return _one_dxf(s, arc_tolerance)
    if path.endswith(".dat"):
        items = read_cgal_dat(path)
        if path != s:  # a selector, even an empty one
            if not (sel.isascii() and sel.isdigit()) or not 1 <= int(sel) <= len(items):
                raise InputFormatError(
                    f"{s}: the file holds {len(items)} polygon(s); use #1..#{len(items)}",
                    argument=s,
                )
            return items[int(sel) - 1]
        if len(items) > 1:
            raise InputFormatError(
                f"{s}: the file holds {len(items)} polygons; "
                f"name one as {s}#1 ... {s}#{len(items)}",
                argument=s,
                hint=f"name one polygon: {s}#1",
            )
        return items[0]
    return parse_geometry(_read_text(source), name=s)


def parse_geometry(text: str, name: str = "input") -> Any:
    """Parse polygon text (JSON point list, GeoJSON or WKT); see :func:`read_geometry`.

    Any malformed text raises a :class:`GeometryError` naming ``name`` (never another
    exception): invalid or too deeply nested JSON, numbers with too many digits or beyond
    the float range, GeoJSON with missing or mis-shaped coordinates, bad WKT.
    """
    s = text.strip()
    if not s:
        raise EmptyGeometryError(f"{name}: empty input", argument=name)
    if s[0] in "[{":
        try:
            data = json.loads(s)
        except json.JSONDecodeError as exc:
            raise InputFormatError(
                f"{name}: not valid JSON ({exc.msg} at line {exc.lineno}, column {exc.colno})",
                argument=name,
            ) from None
        except RecursionError:
            raise InputFormatError(
                f"{name}: JSON nested too deeply", argument=name, hint="a polygon is [[x, y], ...]"
            ) from None
        except ValueError as exc:  # e.g. an integer beyond Python's digit limit
            raise InputFormatError(
                f"{name}: unreadable JSON number ({exc})", argument=name
            ) from None
        if isinstance(data, list):
            return _json_points(data, name)
        return _from_geojson(data, name)
    import shapely

    try:
        with np.errstate(all="ignore"):  # 1e999 overflows quietly to inf (rejected later)
            geom = shapely.from_wkt(s)
    except Exception:  # shapely raises its own GEOSException subclasses
        geom = None
    if geom is None:
        raise InputFormatError(
            f"{name}: not a JSON point list, GeoJSON or WKT geometry",
            argument=name,
            hint="write [[x, y], ...], a GeoJSON Polygon or WKT (POLYGON ((0 0, 1 0, 0 1, 0 0)))",
        )
    return _simplify_geom(geom, name)


def _is_number(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _json_points(data: list, name: str) -> np.ndarray:
    if not data:
        raise EmptyGeometryError(f"{name}: empty point list", argument=name)
    for k, p in enumerate(data):
        if not (isinstance(p, list) and len(p) == 2):
            raise ShapeError(
                f"{name}: item {k} is {_short(p)}, not an [x, y] pair", argument=name, vertex=k
            )
        for v in p:
            if not _is_number(v):
                raise ShapeError(
                    f"{name}: item {k} has a non-numeric coordinate {_short(v)}",
                    argument=name,
                    vertex=k,
                )
    if all(type(v) is int for p in data for v in p):
        try:
            return np.array(data, dtype=np.int64)
        except OverflowError:
            arr = np.empty((len(data), 2), dtype=object)
            arr[:] = [tuple(p) for p in data]
            return arr
    for k, p in enumerate(data):
        for v in p:
            if type(v) is int:
                try:
                    float(v)
                except OverflowError:
                    raise OverflowGeometryError(
                        f"{name}: item {k} has an integer beyond the float range beside "
                        "float coordinates",
                        argument=name,
                        vertex=k,
                        hint="write every coordinate as an integer to keep it exact",
                    ) from None
    return np.array(data, dtype=np.float64)


# GeoJSON: how deep each geometry type nests its positions
_GEOJSON_DEPTH = {
    "Point": 0,
    "MultiPoint": 1,
    "LineString": 1,
    "LinearRing": 1,
    "Polygon": 2,
    "MultiLineString": 2,
    "MultiPolygon": 3,
}


def _check_coords(v: Any, depth: int, name: str, where: str) -> None:
    """Raise unless ``v`` is positions nested ``depth`` deep (a position: >= 2 numbers)."""
    if depth == 0:
        if not isinstance(v, list) or len(v) < 2:
            raise ShapeError(
                f"{name}: {where} is {_short(v)}, not a position [x, y]", argument=name
            )
        for c in v:
            if not _is_number(c):
                raise ShapeError(
                    f"{name}: {where} has a non-numeric coordinate {_short(c)}", argument=name
                )
            if type(c) is int:
                try:
                    float(c)
                except OverflowError:
                    raise OverflowGeometryError(
                        f"{name}: {where} has a coordinate beyond the float range", argument=name
                    ) from None
        return
    if not isinstance(v, list):
        raise ShapeError(f"{name}: {where} is {_short(v)}, not a list", argument=name)
    for k, item in enumerate(v):
        _check_coords(item, depth - 1, name, f"{where}[{k}]")


def _from_geojson(data: Any, name: str, where: str = "the JSON") -> Any:
    if not isinstance(data, dict):
        raise ShapeError(f"{name}: {where} is {_short(data)}, not a GeoJSON object", argument=name)
    t = data.get("type")
    if t == "FeatureCollection":
        feats = data.get("features")
        if not isinstance(feats, list):
            raise ShapeError(
                f"{name}: FeatureCollection 'features' is {_short(feats)}, not a list",
                argument=name,
            )
        if len(feats) != 1:
            raise ShapeError(
                f"{name}: FeatureCollection with {len(feats)} features; expected 1", argument=name
            )
        return _from_geojson(feats[0], name, "features[0]")
    if t == "Feature":
        geom = data.get("geometry")
        if geom is None:
            raise EmptyGeometryError(f"{name}: a Feature without a geometry", argument=name)
        return _from_geojson(
            geom, name, f"{where}'s geometry" if where != "the JSON" else "geometry"
        )
    if t == "GeometryCollection":
        raise ShapeError(f"{name}: a GeometryCollection is not a polygon", argument=name)
    if not isinstance(t, str) or t not in _GEOJSON_DEPTH:
        raise InputFormatError(
            f"{name}: not a GeoJSON geometry (type {_short(t)})",
            argument=name,
            hint="types: Polygon, MultiPolygon, LineString, MultiPoint, Point, Feature",
        )
    if "coordinates" not in data:
        raise InputFormatError(f"{name}: GeoJSON {t} without 'coordinates'", argument=name)
    coords = data["coordinates"]
    _check_coords(coords, _GEOJSON_DEPTH[t], name, "coordinates")
    import shapely

    try:
        geom = shapely.geometry.shape({"type": t, "coordinates": coords})
    except Exception as exc:  # shapely's own errors: a ring too short, and so on
        raise InputFormatError(
            f"{name}: not a valid GeoJSON {t} ({_short(str(exc))})", argument=name
        ) from None
    return _simplify_geom(geom, name)


def _simplify_geom(geom: Any, name: str) -> Any:
    import shapely

    if geom.is_empty:
        raise EmptyGeometryError(f"{name}: empty {geom.geom_type}", argument=name)
    gt = geom.geom_type
    if gt == "Polygon" and not len(geom.interiors):
        c = shapely.get_coordinates(geom.exterior)[:-1]
        return _intify(c)
    if gt in ("LineString", "MultiPoint", "Point"):
        return _intify(shapely.get_coordinates(geom))
    if gt == "LinearRing":
        return _intify(shapely.get_coordinates(geom)[:-1])
    if gt in ("Polygon", "MultiPolygon"):
        return geom
    raise ShapeError(f"{name}: a {gt} is not a polygon", argument=name)
