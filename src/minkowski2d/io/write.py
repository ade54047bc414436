"""Writing results: JSON, GeoJSON, WKT, SVG (:data:`FORMATS`, the one table of formats)."""

from __future__ import annotations

import json
from fractions import Fraction
from typing import Any

import numpy as np

from ..errors import (
    OverflowGeometryError,
)

FORMATS = ("json", "geojson", "wkt", "svg")


# --------------------------------------------------------------------------------------
# output


def _num(v: Any) -> Any:
    if isinstance(v, (np.integer, int)):
        return int(v)
    if isinstance(v, Fraction):
        return float(v) if v.denominator != 1 else int(v)
    return float(v)


def _rows(a: np.ndarray) -> list:
    return [[_num(x), _num(y)] for x, y in a.tolist()]


def _wkt_num(v: Any) -> str:
    v = _num(v)
    if isinstance(v, int):
        return str(v)
    r = repr(v)
    return r[:-2] if r.endswith(".0") else r


def _array_wkt(a: np.ndarray) -> str:
    pts = a.tolist()
    if len(pts) == 1:
        return f"POINT ({_wkt_num(pts[0][0])} {_wkt_num(pts[0][1])})"
    body = ", ".join(f"{_wkt_num(x)} {_wkt_num(y)}" for x, y in pts)
    if len(pts) == 2:
        return f"LINESTRING ({body})"
    x0, y0 = pts[0]
    return f"POLYGON (({body}, {_wkt_num(x0)} {_wkt_num(y0)}))"


def _array_geojson(a: np.ndarray) -> dict:
    rows = _rows(a)
    if len(rows) == 1:
        return {"type": "Point", "coordinates": rows[0]}
    if len(rows) == 2:
        return {"type": "LineString", "coordinates": rows}
    return {"type": "Polygon", "coordinates": [rows + [rows[0]]]}


def format_geometry(geom: Any, fmt: str = "json") -> str:
    """Text for a result: ``json`` (a point list, or GeoJSON for shapely geometries),
    ``geojson``, ``wkt`` or ``svg`` (a standalone SVG document).

    Integer coordinates are written as integers, exactly.

    Examples
    --------
    >>> import numpy as np
    >>> format_geometry(np.array([[0, 0], [3, 0], [0, 3]]), "json")
    '[[0, 0], [3, 0], [0, 3]]'
    >>> format_geometry(np.array([[1, 2]]), "geojson")
    '{"type": "Point", "coordinates": [1, 2]}'
    """
    if not isinstance(fmt, str) or fmt not in FORMATS:
        from ..errors import OptionError

        raise OptionError(
            f"fmt: unknown format {fmt!r}; choose one of {', '.join(FORMATS)}",
            argument="fmt",
            allowed=f"one of {', '.join(FORMATS)}",
        )
    is_array = isinstance(geom, np.ndarray)
    if fmt == "json":
        if is_array:
            return json.dumps(_rows(geom))
        fmt = "geojson"
    if fmt == "geojson":
        if is_array:
            return json.dumps(_array_geojson(geom))
        import shapely

        return shapely.to_geojson(geom)
    if fmt == "wkt":
        if is_array:
            return _array_wkt(geom)
        import shapely

        return shapely.to_wkt(geom, rounding_precision=-1, trim=True)
    return _svg(geom)


def _svg(geom: Any) -> str:
    import shapely

    if isinstance(geom, np.ndarray):
        try:
            a = geom.astype(np.float64)
        except OverflowError:
            raise OverflowGeometryError(
                "svg: a coordinate is beyond float64; the drawing cannot be made",
                argument="--format",
                hint="use json, geojson or wkt (they write integers exactly)",
            ) from None
        g = (
            shapely.Point(a[0])
            if len(a) == 1
            else shapely.LineString(a)
            if len(a) == 2
            else shapely.Polygon(a)
        )
    else:
        g = geom
    x0, y0, x1, y1 = g.bounds
    w = max(x1 - x0, 1e-9)
    h = max(y1 - y0, 1e-9)
    pad = 0.05 * max(w, h)
    vb = f"{x0 - pad} {-(y1 + pad)} {w + 2 * pad} {h + 2 * pad}"
    stroke = 0.01 * max(w, h)
    parts = []
    polys: list[Any] = [g]  # any shapely geometries, flattened below
    while any(hasattr(p, "geoms") for p in polys):  # collections of multi-parts: flat
        polys = [q for p in polys for q in (p.geoms if hasattr(p, "geoms") else [p])]
    for p in polys:
        if p.geom_type == "Polygon":
            rings = [p.exterior, *p.interiors]
            d = " ".join(
                "M " + " L ".join(f"{x} {-y}" for x, y in np.asarray(r.coords)[:-1]) + " Z"
                for r in rings
            )
            parts.append(
                f'<path d="{d}" fill="#4a90d9" fill-opacity="0.4" fill-rule="evenodd" '
                f'stroke="#1f4e79" stroke-width="{stroke}"/>'
            )
        elif p.geom_type == "LineString":
            pts = " ".join(f"{x},{-y}" for x, y in p.coords)
            parts.append(
                f'<polyline points="{pts}" fill="none" stroke="#1f4e79" stroke-width="{stroke}"/>'
            )
        else:
            parts.append(f'<circle cx="{p.x}" cy="{-p.y}" r="{2 * stroke}" fill="#1f4e79"/>')
    body = "\n  ".join(parts)
    return (
        f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{vb}" width="400" height="400">\n'
        f"  {body}\n</svg>"
    )
