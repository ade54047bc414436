"""Reading and writing polygons: JSON point lists, GeoJSON, WKT, CGAL ``.dat``, SVG.

:func:`read_geometry` returns an (n, 2) ndarray for a simple ring or point list (ints stay
ints, exactly), or a shapely geometry for a polygon with holes or a multi-polygon.
:func:`format_geometry` turns a result back into text.

Examples
--------
>>> from minkowski2d.io import parse_geometry, format_geometry
>>> p = parse_geometry("[[0, 0], [2, 0], [0, 2]]")
>>> p.tolist()
[[0, 0], [2, 0], [0, 2]]
>>> format_geometry(p, "wkt")
'POLYGON ((0 0, 2 0, 0 2, 0 0))'
"""

from __future__ import annotations

import json
import sys
from fractions import Fraction
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np

from .errors import EmptyGeometryError, InputFormatError, ShapeError

__all__ = [
    "read_geometry",
    "parse_geometry",
    "read_cgal_dat",
    "parse_cgal_dat",
    "UnboundedPolygon",
    "format_geometry",
    "FORMATS",
]

FORMATS = ("json", "geojson", "wkt", "svg")


class UnboundedPolygon(NamedTuple):
    """A CGAL polygon with holes whose outer boundary is unbounded (``N = 0``).

    ``holes`` are (n, 2) arrays, clockwise as in the file.
    """

    holes: list


def _read_text(source: str | Path) -> str:
    if str(source) == "-":
        return sys.stdin.read()
    try:
        return Path(source).read_text()
    except FileNotFoundError:
        raise InputFormatError(f"{source}: no such file") from None
    except OSError as exc:
        raise InputFormatError(f"{source}: cannot read ({exc.strerror})") from None


def read_geometry(source: str | Path) -> Any:
    """Read one polygon (or point set) from a file path, or ``"-"`` for standard input.

    The format is recognised from the content (JSON point list, GeoJSON, WKT) or the
    ``.dat`` suffix (CGAL's format). A ``.dat`` file holding two polygons needs a
    selector: ``comb.dat#1`` or ``comb.dat#2``.

    Returns
    -------
    (n, 2) ndarray or shapely geometry
        An array for a simple ring or point list, a shapely Polygon for a polygon with
        holes, a MultiPolygon for several polygons.
    """
    s = str(source)
    path, _, sel = s.rpartition("#") if ".dat#" in s else (s, "", "")
    if path.endswith(".dat"):
        items = read_cgal_dat(path)
        if sel:
            if not sel.isdigit() or not 1 <= int(sel) <= len(items):
                raise InputFormatError(
                    f"{s}: the file holds {len(items)} polygon(s); use #1..#{len(items)}"
                )
            return items[int(sel) - 1]
        if len(items) > 1:
            raise InputFormatError(
                f"{s}: the file holds {len(items)} polygons; name one as {s}#1 ... {s}#{len(items)}"
            )
        return items[0]
    return parse_geometry(_read_text(source), name=s)


def parse_geometry(text: str, name: str = "input") -> Any:
    """Parse polygon text (JSON point list, GeoJSON or WKT); see :func:`read_geometry`."""
    s = text.strip()
    if not s:
        raise EmptyGeometryError(f"{name}: empty input")
    if s[0] in "[{":
        try:
            data = json.loads(s)
        except json.JSONDecodeError as exc:
            raise InputFormatError(
                f"{name}: not valid JSON ({exc.msg} at line {exc.lineno})"
            ) from None
        if isinstance(data, list):
            return _json_points(data, name)
        return _from_geojson(data, name)
    import shapely

    try:
        geom = shapely.from_wkt(s)
    except Exception:  # shapely raises its own GEOSException subclasses
        raise InputFormatError(f"{name}: not a JSON point list, GeoJSON or WKT geometry") from None
    return _simplify_geom(geom, name)


def _json_points(data: list, name: str) -> np.ndarray:
    if not data:
        raise EmptyGeometryError(f"{name}: empty point list")
    for k, p in enumerate(data):
        if not (isinstance(p, list) and len(p) == 2):
            raise ShapeError(f"{name}: item {k} is {p!r}, not an [x, y] pair")
        for v in p:
            if isinstance(v, bool) or not isinstance(v, (int, float)):
                raise ShapeError(f"{name}: item {k} has a non-numeric coordinate {v!r}")
    if all(type(v) is int for p in data for v in p):
        try:
            return np.array(data, dtype=np.int64)
        except OverflowError:
            arr = np.empty((len(data), 2), dtype=object)
            arr[:] = [tuple(p) for p in data]
            return arr
    return np.array(data, dtype=np.float64)


def _from_geojson(data: dict, name: str) -> Any:
    t = data.get("type")
    if t == "FeatureCollection":
        feats = data.get("features") or []
        if len(feats) != 1:
            raise ShapeError(f"{name}: FeatureCollection with {len(feats)} features; expected 1")
        return _from_geojson(feats[0], name)
    if t == "Feature":
        return _from_geojson(data.get("geometry") or {}, name)
    import shapely

    try:
        geom = shapely.geometry.shape(data)
    except Exception:
        raise InputFormatError(f"{name}: not a GeoJSON geometry (type {t!r})") from None
    return _simplify_geom(geom, name)


def _simplify_geom(geom: Any, name: str) -> Any:
    import shapely

    if geom.is_empty:
        raise EmptyGeometryError(f"{name}: empty {geom.geom_type}")
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
    raise ShapeError(f"{name}: a {gt} is not a polygon")


def _intify(c: np.ndarray) -> np.ndarray:
    """Whole-number float coordinates from GeoJSON/WKT become ints (exact path)."""
    if c.size and np.all(c == np.round(c)) and np.abs(c).max() < 2.0**53:
        return c.astype(np.int64)
    return c


# --------------------------------------------------------------------------------------
# CGAL .dat


def _cgal_number(tok: str) -> int | float | Fraction:
    if "/" in tok:
        p, q = tok.split("/")
        f = Fraction(int(p), int(q))
        return int(f) if f.denominator == 1 else f
    try:
        return int(tok)
    except ValueError:
        return float(tok)


def parse_cgal_dat(text: str, name: str = "input", layout: str = "auto") -> list:
    """Parse CGAL ``Minkowski_sum_2`` test-file text.

    The file is a stream of whitespace-separated tokens: ``N`` and ``N`` vertices, then
    either nothing, a second simple polygon (``N2`` and ``N2`` vertices), or a hole count
    ``H`` followed by ``H`` rings (a polygon with holes). ``layout`` is ``"auto"``,
    ``"polygons"`` or ``"pwh"``. Numbers may be ints, rationals ``p/q`` or decimals.

    Returns
    -------
    list
        (n, 2) ndarrays for simple polygons (int64 when every coordinate is an integer,
        float64 otherwise), a shapely Polygon for a polygon with holes, and an
        :class:`UnboundedPolygon` when the outer boundary is empty (``N = 0``).

    Examples
    --------
    >>> parse_cgal_dat("4 0 0 3 0 3 3 0 3  1  4 1 1 1 2 2 2 2 1")[0].area
    8.0
    >>> [p.tolist() for p in parse_cgal_dat("3 0/1 0/1 1/1 0 0 1  2 5 5 6 6")]
    [[[0, 0], [1, 0], [0, 1]], [[5, 5], [6, 6]]]
    """
    toks = text.split()
    pos = 0

    def take(what: str) -> str:
        nonlocal pos
        if pos >= len(toks):
            raise InputFormatError(f"{name}: file ends early (expected {what})")
        pos += 1
        return toks[pos - 1]

    def count(what: str) -> int:
        t = take(what)
        try:
            return int(t)
        except ValueError:
            raise InputFormatError(f"{name}: expected a count for {what}, found {t!r}") from None

    def ring(n: int, what: str) -> np.ndarray:
        vals = [_cgal_number(take(f"{what} coordinates")) for _ in range(2 * n)]
        if any(isinstance(v, float) for v in vals):
            return np.array([float(v) for v in vals], dtype=np.float64).reshape(n, 2)
        if any(isinstance(v, Fraction) for v in vals):
            return np.array([float(v) for v in vals], dtype=np.float64).reshape(n, 2)
        return np.array(vals, dtype=np.int64).reshape(n, 2)

    n1 = count("the vertex count")
    first = ring(n1, "polygon 1")
    rest = len(toks) - pos
    if rest == 0:
        if n1 == 0:
            raise EmptyGeometryError(f"{name}: no vertices")
        return [first]
    k = count("a count")
    rest = len(toks) - pos
    if layout == "polygons" or (layout == "auto" and k > 0 and rest == 2 * k):
        second = ring(k, "polygon 2")
        return [first, second]
    holes = [ring(count(f"hole {h} vertex count"), f"hole {h}") for h in range(k)]
    if pos != len(toks):
        raise InputFormatError(f"{name}: {len(toks) - pos} unexpected tokens at the end")
    if n1 == 0:
        return [UnboundedPolygon(holes)]
    import shapely

    return [shapely.Polygon(first, holes)]


def read_cgal_dat(source: str | Path, layout: str = "auto") -> list:
    """Read a CGAL ``.dat`` file; see :func:`parse_cgal_dat`."""
    return parse_cgal_dat(_read_text(source), name=str(source), layout=layout)


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
    if fmt not in FORMATS:
        raise ValueError(f"unknown format {fmt!r}; choose one of {', '.join(FORMATS)}")
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
        a = geom.astype(np.float64)
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
    polys = getattr(g, "geoms", [g])
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
