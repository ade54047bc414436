"""CLI plugin: ``offset`` (grow or shrink by a disk; exact arcs for SVG and DXF).

Registered by :mod:`minkowski2d.cli` through :func:`add_parser`.
"""

from __future__ import annotations

import argparse
import io
import sys
from typing import Any

from .. import io as _io
from ..offset.curves import APPROX, DEFAULT_TOLERANCE, JOINS, MITER_LIMIT
from .common import output_format

#: the library's output formats, and DXF (written here, with exact arcs)
FORMATS = (*_io.FORMATS, "dxf")


def add_parser(subparsers: argparse._SubParsersAction) -> None:
    """Add the ``offset`` subcommand."""
    p = subparsers.add_parser(
        "offset",
        help="grow (r > 0) or shrink (r < 0) a polygon by a disk, with a guaranteed error",
        description="Offset a polygon by a disk of radius |r|. json/geojson/wkt write a "
        f"polygon within --tolerance (default {DEFAULT_TOLERANCE:g} |r|) of the true "
        "offset, on the side "
        "--approx names (outer: it contains the true set). svg and dxf write the exact "
        "boundary, with circular arcs (a round join), unless --tolerance is given. "
        "GeoJSON FeatureCollections and DXF drawings give one result per feature (part), "
        "properties kept. DXF input (polylines with arcs, circles, line and arc chains) "
        "needs the optional ezdxf package; its arcs are read within --arc-tolerance.",
    )
    p.add_argument("polygon", help="the polygon (file or -; .dxf files need ezdxf)")
    p.add_argument("-r", "--distance", type=float, required=True, help="offset distance")
    p.add_argument(
        "--tolerance",
        type=float,
        default=None,
        help=f"largest error of a round join (default: {DEFAULT_TOLERANCE:g} times |r|; "
        "svg and dxf then write exact arcs)",
    )
    p.add_argument("--approx", choices=APPROX, default=APPROX[0])
    p.add_argument("--join", choices=JOINS, default=JOINS[0])
    p.add_argument("--miter-limit", type=float, default=MITER_LIMIT)
    p.add_argument("-o", "--output", help="output file (default: standard output)")
    from .common import add_arc_option

    add_arc_option(p)
    p.add_argument(
        "--format",
        choices=FORMATS,
        default=None,
        help="output format (default: from the -o suffix, else json)",
    )
    p.set_defaults(func=_cmd_offset)


def _cmd_offset(args: argparse.Namespace) -> int:
    from ..errors import GeometryError
    from ..io import format_geometry, read_geometry
    from .common import emit
    from .features import run_collection

    src = args.polygon
    fmt = output_format(args, FORMATS)
    exact = fmt in ("svg", "dxf") and args.join == "round" and args.tolerance is None

    def op(g: list, names: list) -> Any:
        return _offset(g[0], args, exact)

    def writer(out: list, fmt: str) -> str | None:
        if fmt not in ("svg", "dxf"):
            return None
        done = [g for g, _, _ in out if g is not None]
        return _text(done, fmt, exact, args.distance)

    if (status := run_collection(args, [src], op, writer=writer, fmt=fmt)) is not None:
        return status
    try:
        result = _offset(read_geometry(src), args, exact)
    except GeometryError as exc:
        if exc.argument == "polygon":  # name the file
            raise exc.renamed(src) from None
        raise
    if fmt in ("svg", "dxf"):
        text = _text([result], fmt, exact, args.distance)
    else:
        text = format_geometry(result, fmt)
    emit(text, args.output, [src])
    return 0


def _offset(poly: Any, args: argparse.Namespace, exact: bool) -> Any:
    """The offset of one polygon: exact arcs (OffsetArcs) for an exact SVG or DXF, else
    a polygon within the tolerance (the default one when none is given)."""
    from ..offset import offset, offset_arcs

    if exact:
        arcs = offset_arcs(poly, args.distance)
        if not arcs.polygons:
            print("minkowski2d: note: the shrink erases the polygon", file=sys.stderr)
        return arcs
    result = offset(
        poly,
        args.distance,
        tolerance=args.tolerance,
        approx=args.approx,
        join=args.join,
        miter_limit=args.miter_limit,
    )
    if result.is_empty:
        print("minkowski2d: note: the shrink erases the polygon", file=sys.stderr)
    return result


def _text(results: list, fmt: str, exact: bool, distance: float) -> str:
    """SVG or DXF of offset results: exact arcs, or polygons."""
    import numpy as np
    import shapely

    if exact:
        from ..offset import OffsetArcs

        arcs = OffsetArcs([p for r in results for p in r.polygons], distance)
        if fmt == "svg":
            return arcs.to_svg()
        buf = io.StringIO()
        arcs.to_dxf().write(buf)
        return buf.getvalue()
    parts = shapely.get_parts(np.array(results, dtype=object))
    parts = parts[~shapely.is_empty(parts)]
    geom = parts[0] if len(parts) == 1 else shapely.MultiPolygon(list(parts))
    if fmt == "dxf":
        return _polygon_dxf(geom)
    from ..io import format_geometry

    return format_geometry(geom, fmt)


def _polygon_dxf(geom: Any) -> str:
    """A polygon result as closed LWPOLYLINEs (exteriors counter-clockwise)."""
    import shapely

    from ..errors import InputFormatError

    try:
        import ezdxf
    except ImportError:
        raise InputFormatError(
            "DXF output needs ezdxf", argument="--format", hint="pip install 'minkowski2d[dxf]'"
        ) from None
    doc = ezdxf.new("R2010")
    msp = doc.modelspace()
    for ring in shapely.get_rings(shapely.get_parts(geom)):
        c = shapely.get_coordinates(ring)[:-1]
        msp.add_lwpolyline([tuple(p) for p in c.tolist()], close=True)
    buf = io.StringIO()
    doc.write(buf)
    return buf.getvalue()
