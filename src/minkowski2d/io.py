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
import math
import re
import reprlib
import sys
from fractions import Fraction
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np

from .errors import (
    EmptyGeometryError,
    GeometryError,
    InputFormatError,
    OverflowGeometryError,
    ShapeError,
)

__all__ = [
    "read_geometry",
    "parse_geometry",
    "read_cgal_dat",
    "parse_cgal_dat",
    "UnboundedPolygon",
    "split_selector",
    "format_geometry",
    "FORMATS",
    "Feature",
    "read_features",
    "read_dxf",
    "read_grid_map",
    "parse_grid_map",
]

FORMATS = ("json", "geojson", "wkt", "svg")


class UnboundedPolygon(NamedTuple):
    """A CGAL polygon with holes whose outer boundary is unbounded (``N = 0``).

    ``holes`` are (n, 2) arrays, clockwise as in the file.
    """

    holes: list


def _read_text(source: str | Path) -> str:
    """The text of a file (UTF-8, a leading byte-order mark dropped) or of standard input.

    Every failure is an :class:`InputFormatError` naming the file: missing, unreadable,
    a directory, a name the system cannot take, or bytes that are not UTF-8 text.
    """
    name = str(source)
    hint = "give a JSON, GeoJSON, WKT or CGAL .dat text file"
    if name == "-":
        try:
            return sys.stdin.read()
        except UnicodeDecodeError as exc:
            raise InputFormatError(
                f"-: standard input is not UTF-8 text (byte {exc.start})",
                argument="-",
                hint=hint,
            ) from None
    try:
        data = Path(source).read_bytes()
    except FileNotFoundError:
        raise InputFormatError(f"{name}: no such file", argument=name) from None
    except IsADirectoryError:
        raise InputFormatError(f"{name}: is a directory, not a file", argument=name) from None
    except OSError as exc:
        raise InputFormatError(
            f"{name}: cannot read ({exc.strerror or exc})", argument=name
        ) from None
    except ValueError as exc:  # e.g. an embedded NUL byte in the name
        raise InputFormatError(f"{_short(name)}: not a usable file name ({exc})") from None
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise InputFormatError(
            f"{name}: not a text file (byte {exc.start} is not UTF-8)", argument=name, hint=hint
        ) from None


_REPR = reprlib.Repr()
_REPR.maxlevel = 3
_REPR.maxlist = 4
_REPR.maxdict = 4
_REPR.maxstring = 30
_REPR.maxother = 30
_REPR.maxlong = 30


def _short(v: Any) -> str:
    """A bounded repr: never huge, never deep (input data can be both)."""
    try:
        return _REPR.repr(v)
    except (RecursionError, ValueError):  # pragma: no cover - reprlib bounds the depth
        return f"<{type(v).__name__}>"


def split_selector(source: str | Path) -> tuple[str, str]:
    """``("comb.dat", "2")`` for ``comb.dat#2``; ``(source, "")`` for anything else.

    Examples
    --------
    >>> split_selector("comb.dat#2"), split_selector("a.json")
    (('comb.dat', '2'), ('a.json', ''))
    """
    s = str(source)
    if ".dat#" in s:
        path, _, sel = s.rpartition("#")
        if path.endswith(".dat"):
            return path, sel
    return s, ""


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


def _intify(c: np.ndarray) -> np.ndarray:
    """Whole-number float coordinates from GeoJSON/WKT become ints (exact path)."""
    with np.errstate(invalid="ignore"):
        if c.size and np.all(c == np.round(c)) and np.abs(c).max() < 2.0**53:
            return c.astype(np.int64)
    return c


# --------------------------------------------------------------------------------------
# CGAL .dat

_INT_TOKEN = re.compile(r"[+-]?\d+\Z", re.ASCII)
_RATIONAL_TOKEN = re.compile(r"([+-]?\d+)/([+-]?\d+)\Z", re.ASCII)
_DECIMAL_TOKEN = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?\Z", re.ASCII)
_CGAL_HINT = (
    "a CGAL .dat file holds N and N vertices x y (ints, p/q or decimals), then nothing, "
    "a second polygon, or H and H holes"
)


def _cgal_number(tok: str) -> int | float | Fraction:
    """One coordinate token: an int, a rational ``p/q`` or a finite decimal.

    Raises ``ValueError`` with the reason for anything else.
    """
    if _INT_TOKEN.match(tok):
        try:
            return int(tok)
        except ValueError:  # beyond Python's digit limit
            raise ValueError("an integer with too many digits") from None
    m = _RATIONAL_TOKEN.match(tok)
    if m:
        q = int(m.group(2))
        if q == 0:
            raise ValueError("a zero denominator")
        f = Fraction(int(m.group(1)), q)
        return int(f) if f.denominator == 1 else f
    if _DECIMAL_TOKEN.match(tok):
        v = float(tok)
        if not math.isfinite(v):
            raise ValueError("beyond the float range")
        return v
    raise ValueError("not a number (int, p/q or decimal)")


def parse_cgal_dat(text: str, name: str = "input", layout: str = "auto") -> list:
    """Parse CGAL ``Minkowski_sum_2`` test-file text.

    The file is a stream of whitespace-separated tokens: ``N`` and ``N`` vertices, then
    either nothing, a second simple polygon (``N2`` and ``N2`` vertices), or a hole count
    ``H`` followed by ``H`` rings (a polygon with holes). ``layout`` is ``"auto"``,
    ``"polygons"`` or ``"pwh"``. Numbers may be ints, rationals ``p/q`` or decimals.

    Returns
    -------
    list
        (n, 2) ndarrays for simple polygons (int64 when every coordinate is an integer
        that fits, exact Python ints beyond, float64 otherwise), a shapely Polygon for a
        polygon with holes, and an :class:`UnboundedPolygon` when the outer boundary is
        empty (``N = 0``).

    Raises
    ------
    InputFormatError
        For any malformed file, naming ``name``, the line and (for a coordinate) the
        vertex: a bad or negative count, a token that is not a number, a zero
        denominator, a number beyond the float range, a file ending early, extra tokens,
        a hole or boundary with fewer than 3 vertices.
    EmptyGeometryError
        When a polygon has no vertices.

    Examples
    --------
    >>> parse_cgal_dat("4 0 0 3 0 3 3 0 3  1  4 1 1 1 2 2 2 2 1")[0].area
    8.0
    >>> [p.tolist() for p in parse_cgal_dat("3 0/1 0/1 1/1 0 0 1  2 5 5 6 6")]
    [[[0, 0], [1, 0], [0, 1]], [[5, 5], [6, 6]]]
    """
    from . import _options

    _options.choice(layout, "layout", ("auto", "polygons", "pwh"))
    matches = list(re.finditer(r"\S+", text))
    toks = [m.group() for m in matches]
    pos = 0

    def line(k: int) -> int:
        return (
            text.count("\n", 0, matches[k].start()) + 1
            if k < len(matches)
            else (text.count("\n") + 1)
        )

    def fail(msg: str, k: int | None = None, vertex: int | None = None) -> InputFormatError:
        where = f"line {line(k)}: " if k is not None else ""
        return InputFormatError(
            f"{name}: {where}{msg}", argument=name, vertex=vertex, hint=_CGAL_HINT
        )

    def take(what: str) -> str:
        nonlocal pos
        if pos >= len(toks):
            raise fail(f"file ends early (expected {what})")
        pos += 1
        return toks[pos - 1]

    def count(what: str) -> int:
        t = take(what)
        if not _INT_TOKEN.match(t) or t.startswith("-"):
            raise fail(f"expected a count for {what}, found {_short(t)}", pos - 1)
        try:
            return int(t)
        except ValueError:
            raise fail(f"the count for {what} has too many digits", pos - 1) from None

    def ring(n: int, what: str) -> np.ndarray:
        nonlocal pos
        left = len(toks) - pos
        if 2 * n > left:
            raise fail(
                f"file ends early: {what} has {n} vertices but only {left} numbers follow",
                pos - 1,
            )
        vals: list = []
        for j in range(2 * n):
            t = toks[pos + j]
            try:
                vals.append(_cgal_number(t))
            except ValueError as exc:
                raise fail(
                    f"{what} vertex {j // 2}: {_short(t)} is {exc}", pos + j, vertex=j // 2
                ) from None
        start = pos
        pos += 2 * n
        if any(isinstance(v, (float, Fraction)) for v in vals):
            out = []
            for j, v in enumerate(vals):
                try:
                    out.append(float(v))
                except OverflowError:
                    raise fail(
                        f"{what} vertex {j // 2}: {_short(toks[start + j])} is beyond the float "
                        "range (the ring has non-integer coordinates, so it is read as floats)",
                        start + j,
                        vertex=j // 2,
                    ) from None
            return np.array(out, dtype=np.float64).reshape(n, 2)
        try:
            return np.array(vals, dtype=np.int64).reshape(n, 2)
        except OverflowError:
            arr = np.empty((n, 2), dtype=object)
            arr[:] = [(vals[2 * i], vals[2 * i + 1]) for i in range(n)]
            return arr

    def boundary(r: np.ndarray, what: str, k: int) -> None:
        if len(r) < 3:
            raise fail(f"{what} has {len(r)} vertices; a ring needs at least 3", k)

    n1 = count("the vertex count")
    first = ring(n1, "polygon 1")
    rest = len(toks) - pos
    if rest == 0:
        if n1 == 0:
            raise EmptyGeometryError(f"{name}: no vertices", argument=name)
        return [first]
    k_at = pos
    k = count("the second polygon or the holes")
    rest = len(toks) - pos
    if layout == "polygons" or (layout == "auto" and k > 0 and rest == 2 * k):
        second = ring(k, "polygon 2")
        if pos != len(toks):
            raise fail(f"{len(toks) - pos} unexpected tokens at the end", pos)
        for r, which in ((first, 1), (second, 2)):
            if len(r) == 0:
                raise EmptyGeometryError(f"{name}: polygon {which} has no vertices", argument=name)
        return [first, second]
    holes = []
    for h in range(k):
        at = pos
        hole = ring(count(f"hole {h} vertex count"), f"hole {h}")
        boundary(hole, f"hole {h}", at)
        holes.append(hole)
    if pos != len(toks):
        raise fail(f"{len(toks) - pos} unexpected tokens at the end", pos)
    if n1 == 0:
        return [UnboundedPolygon(holes)]
    boundary(first, "the outer boundary of a polygon with holes", 0)
    import shapely

    try:
        return [shapely.Polygon(first, holes)]
    except Exception as exc:  # shapely: a ring that closes on itself too early, ...
        raise fail(f"not a polygon with holes ({_short(str(exc))})", k_at) from None


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
    if not isinstance(fmt, str) or fmt not in FORMATS:
        from .errors import OptionError

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
    polys = [g]
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


# --------------------------------------------------------------------------------------
# many features: GeoJSON FeatureCollections and DXF drawings


class Feature(NamedTuple):
    """One feature of a collection: its geometry (as :func:`read_geometry` returns it, or
    None for a null geometry) and its properties (a dict; GeoJSON's ``id`` is kept under
    the key ``"id"`` of :attr:`extra`). ``arcs``: for a DXF part, its exact rings of
    segments and arcs, ``(k, 3)`` arrays ``(x, y, bulge)``, exterior first (None
    otherwise)."""

    geometry: Any
    properties: dict | None
    extra: dict
    arcs: list | None = None


def read_features(
    source: str | Path, *, arc_tolerance: float | None = None
) -> list[Feature] | None:
    """The features of a GeoJSON FeatureCollection or a DXF drawing, in order; None for
    any other input (a single geometry: use :func:`read_geometry`).

    Raises a :class:`GeometryError` naming the file and the feature
    (``obstacles.geojson: features[3]: ...``) for a feature that is not a polygon.

    Examples
    --------
    >>> import json, tempfile, os
    >>> fc = {"type": "FeatureCollection", "features": [
    ...     {"type": "Feature", "properties": {"name": "a"},
    ...      "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [2, 0], [0, 2], [0, 0]]]}},
    ...     {"type": "Feature", "properties": {"name": "b"}, "geometry": None}]}
    >>> path = os.path.join(tempfile.mkdtemp(), "fc.geojson")
    >>> _ = open(path, "w").write(json.dumps(fc))
    >>> [(f.geometry if f.geometry is None else f.geometry.tolist(), f.properties)
    ...  for f in read_features(path)]
    [([[0, 0], [2, 0], [0, 2]], {'name': 'a'}), (None, {'name': 'b'})]
    """
    s = str(source)
    if s.lower().endswith(".dxf"):
        return read_dxf(s, tolerance=arc_tolerance)
    if s.endswith(".dat") or ".dat#" in s:
        return None
    text = _read_text(source)
    t = text.lstrip()
    if not t.startswith("{") or '"FeatureCollection"' not in t:
        return None
    try:
        data = json.loads(t)
    except (ValueError, RecursionError):
        return None  # read_geometry reports the problem
    if not isinstance(data, dict) or data.get("type") != "FeatureCollection":
        return None
    feats = data.get("features")
    if not isinstance(feats, list):
        return None
    if not feats:
        raise EmptyGeometryError(f"{s}: a FeatureCollection without features", argument=s)
    out = []
    for k, f in enumerate(feats):
        where = f"{s}: features[{k}]"
        if not isinstance(f, dict) or f.get("type") != "Feature":
            raise ShapeError(f"{where}: {_short(f)} is not a GeoJSON Feature", argument=where)
        props = f.get("properties")
        if props is not None and not isinstance(props, dict):
            raise ShapeError(f"{where}: properties must be an object or null", argument=where)
        extra = {"id": f["id"]} if "id" in f else {}
        geom = f.get("geometry")
        if geom is None:
            out.append(Feature(None, props, extra))
            continue
        try:
            out.append(Feature(_from_geojson(geom, s, "geometry"), props, extra))
        except GeometryError as exc:
            raise exc.renamed(where) from None
    return out


def read_dxf(
    source: str | Path, *, tolerance: float | None = None, name: str | None = None
) -> list[Feature]:
    """The closed outlines of a DXF drawing's model space as polygons, one feature per
    part, with properties ``layer``, ``handle`` and ``entity`` (of the part's outline) and
    ``holes`` (the handles of its holes, when it has some). Needs ezdxf (the ``dxf``
    extra).

    Outlines are closed LWPOLYLINEs and 2-D POLYLINEs (their arcs, given as bulges,
    included), CIRCLEs, and closed chains of LINE and ARC entities (end points joined
    within ``1e-9`` of the drawing's size). An outline inside another is a hole of it
    (and one inside a hole is a part again). Open polylines and chains are skipped.

    Arcs are read with a one-sided approximation (see :mod:`minkowski2d._arcs`): the
    polygon contains the part (parts grow, holes shrink) and lies within ``tolerance``
    of it. ``tolerance``: the largest error, in drawing units; default (None) ``1e-3``
    times each arc's radius. The exact outline is kept on the feature (``arcs``: one
    ``(k, 3)`` array ``(x, y, bulge)`` per ring, exterior first). A part without arcs is
    read exactly (an (n, 2) array, ints where the coordinates are whole numbers).

    Raises
    ------
    InputFormatError
        ezdxf missing, a file that is not DXF, ELLIPSE or SPLINE entities (not read: a
        curve that is not an arc would be dropped), an entity out of the drawing's plane,
        or a drawing without closed outlines.
    """
    name = str(source) if name is None else name
    try:
        import ezdxf
    except ImportError:
        raise InputFormatError(
            f"{name}: reading DXF needs ezdxf",
            argument=name,
            hint="pip install 'minkowski2d[dxf]'",
        ) from None
    tol = None
    if tolerance is not None:
        from . import _options

        tol = _options.real(tolerance, "arc_tolerance")
        if tol <= 0:
            raise _options_error("arc_tolerance", tolerance)
    try:
        doc = ezdxf.readfile(str(source))
    except OSError as exc:
        raise InputFormatError(
            f"{name}: cannot read ({exc.strerror or exc})", argument=name
        ) from None
    except Exception as exc:  # ezdxf.DXFStructureError and friends
        raise InputFormatError(
            f"{name}: not a readable DXF file ({_short(str(exc))})", argument=name
        ) from None
    rings = _dxf_rings(doc.modelspace(), name)
    if not rings:
        raise EmptyGeometryError(
            f"{name}: no closed outlines (LWPOLYLINE, POLYLINE, CIRCLE, or LINE and ARC "
            "chains) in the model space",
            argument=name,
            hint="close the outlines in the CAD program",
        )
    return _dxf_parts(rings, name, tol)


def _options_error(option: str, value: Any) -> GeometryError:
    from .errors import OptionError

    return OptionError(
        f"{option}: must be a positive number, got {value!r}",
        argument=option,
        allowed="a positive number (drawing units)",
    )


class _Ring(NamedTuple):
    rows: list  # (x, y, bulge)
    props: dict


def _ocs(e: Any, where: str, name: str) -> float:
    """+1 for an entity in the drawing's plane, -1 for one seen from below (a mirrored
    extrusion: x is negated and arcs turn the other way)."""
    ext = tuple(float(v) for v in e.dxf.get("extrusion", (0.0, 0.0, 1.0)))
    if ext[0] == 0.0 and ext[1] == 0.0 and ext[2] != 0.0:
        return 1.0 if ext[2] > 0 else -1.0
    raise InputFormatError(
        f"{where}: the entity is not in the drawing's plane (extrusion {ext})",
        argument=name,
        hint="flatten the drawing to 2-D in the CAD program",
    )


def _finite_rows(rows: list, where: str, name: str) -> list:
    if not all(math.isfinite(v) for r in rows for v in r):
        raise InputFormatError(f"{where}: a non-finite coordinate", argument=name)
    return rows


def _dxf_rings(msp: Any, name: str) -> list[_Ring]:
    rings: list[_Ring] = []
    pieces = []  # open LINE / ARC pieces: (x0, y0, x1, y1, bulge, props)
    for e in msp:
        kind = e.dxftype()
        where = f"{name}: {kind} {e.dxf.handle}"
        props = {"layer": e.dxf.layer, "handle": e.dxf.handle, "entity": kind}
        if kind in ("ELLIPSE", "SPLINE", "HELIX"):
            raise InputFormatError(
                f"{where}: {kind} entities are not read (only segments and circular arcs)",
                argument=name,
                hint="convert it to a polyline or to arcs in the CAD program",
            )
        if kind == "LWPOLYLINE":
            s = _ocs(e, where, name)
            pts = [(s * x, y, s * b) for x, y, b in e.get_points("xyb")]
            closed = bool(e.closed)
        elif kind == "POLYLINE":
            if not (e.is_2d_polyline or e.is_3d_polyline):
                continue  # meshes and polyface meshes are not polygons
            s = _ocs(e, where, name) if e.is_2d_polyline else 1.0
            pts = [
                (s * v.dxf.location[0], v.dxf.location[1], s * v.dxf.get("bulge", 0.0))
                for v in e.vertices
            ]
            closed = bool(e.is_closed)
        elif kind == "CIRCLE":
            s = _ocs(e, where, name)
            c, r = e.dxf.center, float(e.dxf.radius)
            if r > 0:
                from ._arcs import circle_ring

                rows = circle_ring(s * float(c[0]), float(c[1]), r)
                rings.append(_Ring(_finite_rows(rows, where, name), props))
            continue
        elif kind == "LINE":
            a, b = e.dxf.start, e.dxf.end
            pieces.append((float(a[0]), float(a[1]), float(b[0]), float(b[1]), 0.0, props))
            continue
        elif kind == "ARC":
            s = _ocs(e, where, name)
            c, r = e.dxf.center, float(e.dxf.radius)
            a0, a1 = math.radians(e.dxf.start_angle), math.radians(e.dxf.end_angle)
            sweep = (a1 - a0) % (2 * math.pi) or 2 * math.pi
            x0, y0 = c[0] + r * math.cos(a0), c[1] + r * math.sin(a0)
            x1, y1 = c[0] + r * math.cos(a1), c[1] + r * math.sin(a1)
            if sweep >= 2 * math.pi:  # a closed arc: a circle
                from ._arcs import circle_ring

                rings.append(_Ring(circle_ring(s * float(c[0]), float(c[1]), r), props))
                continue
            bulge = math.tan(sweep / 4)
            pieces.append((s * x0, y0, s * x1, y1, s * bulge, props))
            continue
        else:
            continue
        pts = [(float(x), float(y), float(b)) for x, y, b in pts]
        if len(pts) > 1 and pts[0][:2] == pts[-1][:2]:
            pts = pts[:-1]
            closed = True
        if not closed or not pts:
            continue
        rings.append(_Ring(_finite_rows(pts, f"{where}", name), props))
    if pieces:
        rings.extend(_chains(pieces, name))
    return rings


def _chains(pieces: list, name: str) -> list[_Ring]:
    """Closed loops of LINE and ARC pieces joined end to end (within a slack of 1e-9 of
    the drawing's size); open chains are skipped."""
    P = np.array([p[:4] for p in pieces], dtype=np.float64)
    if not np.isfinite(P).all():
        raise InputFormatError(f"{name}: a LINE or ARC has a non-finite coordinate")
    slack = 1e-9 * max(float(np.abs(P).max()), 1e-300)
    ends = np.concatenate([P[:, 0:2], P[:, 2:4]])  # start points, then end points
    n = len(pieces)
    used = np.zeros(n, bool)
    loops = []
    for s0 in range(n):
        if used[s0]:
            continue
        used[s0] = True
        order = [(s0, False)]
        first = P[s0, 0:2]
        cur = P[s0, 2:4]
        closed = False
        for _ in range(n):
            if np.abs(cur - first).max() <= slack and len(order) > 1:
                closed = True
                break
            near = np.flatnonzero(np.abs(ends - cur).max(axis=1) <= slack)
            nxt = [(int(k % n), bool(k >= n)) for k in near if not used[k % n]]
            if not nxt:
                break
            k, rev = nxt[0]
            used[k] = True
            order.append((k, rev))
            cur = P[k, 0:2] if rev else P[k, 2:4]
        if not closed:
            continue
        rows = []
        for k, rev in order:
            x0, y0, x1, y1, b, _ = pieces[k]
            rows.append((x1, y1, -b) if rev else (x0, y0, b))
        props = dict(pieces[order[0][0]][5])
        props["entity"] = "LINE/ARC chain"
        props["handles"] = [pieces[k][5]["handle"] for k, _ in order]
        loops.append(_Ring(rows, props))
    return loops


def _dxf_parts(rings: list[_Ring], name: str, tol: float | None) -> list[Feature]:
    """Nest the rings (a ring inside an odd number of others is a hole of the innermost
    one around it), approximate their arcs on the side that grows the part, and build
    one feature per part."""
    import shapely

    from ._arcs import approximate, ring_area

    areas = [ring_area(r.rows) for r in rings]
    # a coarse polygon per ring for the nesting test: its vertices and arc midpoints
    coarse = []
    for r in rings:
        pts = approximate(r.rows, True, tol, name)
        coarse.append(shapely.Polygon(pts) if len(pts) >= 3 else shapely.Point(pts[0]))
    ok = [abs(a) > 0 and c.geom_type == "Polygon" for a, c in zip(areas, coarse)]
    depth = np.zeros(len(rings), np.int64)
    parent = np.full(len(rings), -1, np.int64)
    tree = shapely.STRtree([c if ok[i] else shapely.Point() for i, c in enumerate(coarse)])
    for i, r in enumerate(rings):
        pt = shapely.Point(r.rows[0][:2])
        cand = [int(j) for j in tree.query(pt, predicate="within") if j != i and ok[j]]
        cand = [j for j in cand if abs(areas[j]) > abs(areas[i])]
        depth[i] = len(cand)
        if cand:
            parent[i] = min(cand, key=lambda j: abs(areas[j]))
    feats = []
    for i, r in enumerate(rings):
        if depth[i] % 2:
            continue  # a hole: with its part
        holes = [j for j in range(len(rings)) if parent[j] == i and depth[j] % 2]
        shell = _ring_polygon(r, areas[i], True, tol, name)
        hs = [_ring_polygon(rings[j], areas[j], False, tol, name) for j in holes]
        exact = [np.array(r.rows)] + [np.array(rings[j].rows) for j in holes]
        props = dict(r.props)
        if holes:
            props["holes"] = [rings[j].props["handle"] for j in holes]
        if hs:
            geom: Any = shapely.Polygon(shell, hs)
        else:
            geom = _intify(shell) if not any(row[2] for row in r.rows) else shell
        feats.append(Feature(geom, props, {}, exact))
    return feats


def _ring_polygon(r: _Ring, area: float, outer: bool, tol: float | None, name: str) -> Any:
    """The ring as a polygon containing the part: the region is on the left of a
    counter-clockwise outline and on the right of a counter-clockwise hole."""
    from ._arcs import approximate

    region_left = (area > 0) == outer
    where = f"{name}: {r.props.get('entity')} {r.props.get('handle')}"
    return approximate(r.rows, region_left, tol, where)


def _one_dxf(name: str, arc_tolerance: float | None = None) -> Any:
    feats = read_dxf(name, tolerance=arc_tolerance)
    if len(feats) > 1:
        raise InputFormatError(
            f"{name}: the drawing holds {len(feats)} closed polylines (parts); this command "
            "takes one",
            argument=name,
            hint="sum, inflate and hull take the whole drawing, one result per polyline",
        )
    return feats[0].geometry


# --------------------------------------------------------------------------------------
# grid maps (the Moving AI pathfinding benchmarks' .map format)

_MAP_FREE = frozenset(".GS")
_MAP_BLOCKED = frozenset("@OTW")


def read_grid_map(source: str | Path) -> np.ndarray:
    r"""An occupancy grid from a Moving AI ``.map`` file (the pathfinding benchmarks').

    The format is a header ``type <name>``, ``height <H>``, ``width <W>``, ``map``, then
    H lines of W characters: ``.``, ``G`` and ``S`` are free, ``@``, ``O``, ``T`` and
    ``W`` blocked. Returns an (H, W) bool array, True where blocked; row ``r`` is the
    file's ``r``-th map line, so that :meth:`minkowski2d.MotionPlanner.from_grid` puts
    cell (x, y) of the benchmarks' scenarios (column, row) at ``[x, x + 1] × [y, y + 1]``.

    Raises
    ------
    InputFormatError
        The file cannot be read, or is not in this format: the message names the line
        (and for a bad character, the column) and what was expected.

    Examples
    --------
    >>> import tempfile, os
    >>> d = tempfile.mkdtemp()
    >>> f = os.path.join(d, "a.map")
    >>> _ = open(f, "w").write("type octile\nheight 2\nwidth 3\nmap\n.@.\n...\n")
    >>> read_grid_map(f).astype(int).tolist()
    [[0, 1, 0], [0, 0, 0]]
    """
    return parse_grid_map(_read_text(source), str(source))


def parse_grid_map(text: str, name: str = "input") -> np.ndarray:
    r""":func:`read_grid_map` on the text of a ``.map`` file (``name`` for messages).

    Examples
    --------
    >>> parse_grid_map("type octile\nheight 1\nwidth 2\nmap\n@.\n").tolist()
    [[True, False]]
    """
    hint = "a .map file starts with 'type octile', 'height H', 'width W', 'map'"
    lines = text.splitlines()

    def fail(msg: str, line: int | None = None) -> InputFormatError:
        where = f" (line {line})" if line is not None else ""
        return InputFormatError(f"{name}: {msg}{where}", argument=name, hint=hint)

    k = 0
    while k < len(lines) and not lines[k].strip():
        k += 1
    if k == len(lines):
        raise fail("empty file, expected a grid map")
    head: dict[str, str] = {}
    for want in ("type", "height", "width"):
        if k >= len(lines):
            raise fail(f"the header ends before '{want}'")
        parts = lines[k].split()
        if len(parts) != 2 or parts[0].lower() != want:
            raise fail(f"expected '{want} <value>', got {_short(lines[k])}", k + 1)
        head[want] = parts[1]
        k += 1
    dims = {}
    for key in ("height", "width"):
        v = head[key]
        if not v.isdigit() or int(v) < 1:
            line = 2 if key == "height" else 3
            raise fail(f"{key} must be a positive integer, got {_short(v)}", line)
        dims[key] = int(v)
    H, W = dims["height"], dims["width"]
    if k >= len(lines) or lines[k].strip().lower() != "map":
        got = _short(lines[k]) if k < len(lines) else "the end of the file"
        raise fail(f"expected the line 'map' after the header, got {got}", k + 1)
    k += 1
    rows = [ln.rstrip("\r\n\t ") for ln in lines[k:]]
    while rows and not rows[-1]:
        rows.pop()
    if len(rows) != H:
        raise fail(f"height is {H} but the map has {len(rows)} rows")
    occ = np.zeros((H, W), dtype=bool)
    for r, row in enumerate(rows):
        if len(row) != W:
            raise fail(f"width is {W} but this row has {len(row)} characters", k + r + 1)
        for c, ch in enumerate(row):
            if ch in _MAP_BLOCKED:
                occ[r, c] = True
            elif ch not in _MAP_FREE:
                raise fail(
                    f"unknown terrain {ch!r} at column {c + 1}: free is one of '.GS', "
                    "blocked one of '@OTW'",
                    k + r + 1,
                )
    return occ
