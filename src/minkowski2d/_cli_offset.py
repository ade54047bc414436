"""CLI plugin: ``offset`` (grow or shrink by a disk; exact arcs for SVG and DXF).

Registered by :mod:`minkowski2d.cli` through :func:`add_parser`.
"""

from __future__ import annotations

import argparse
import io
import sys
from pathlib import Path
from typing import Any

FORMATS = ("json", "geojson", "wkt", "svg", "dxf")


def add_parser(subparsers: argparse._SubParsersAction) -> None:
    """Add the ``offset`` subcommand."""
    p = subparsers.add_parser(
        "offset",
        help="grow (r > 0) or shrink (r < 0) a polygon by a disk, with a guaranteed error",
        description="Offset a polygon by a disk of radius |r|. json/geojson/wkt write a "
        "polygon within --tolerance of the true offset, on the side --approx names (outer: "
        "it contains the true set). svg and dxf write the exact boundary, with circular "
        "arcs (a round join), unless --tolerance is given. DXF input (closed LWPOLYLINEs) "
        "needs the optional ezdxf package.",
    )
    p.add_argument("polygon", help="the polygon (file or -; .dxf files need ezdxf)")
    p.add_argument("-r", "--distance", type=float, required=True, help="offset distance")
    p.add_argument("--tolerance", type=float, default=None, help="largest error (round join)")
    p.add_argument("--approx", choices=("outer", "inner"), default="outer")
    p.add_argument("--join", choices=("round", "miter", "square"), default="round")
    p.add_argument("--miter-limit", type=float, default=2.0)
    p.add_argument("-o", "--output", help="output file (default: standard output)")
    p.add_argument(
        "--format",
        choices=FORMATS,
        default=None,
        help="output format (default: from the -o suffix, else json)",
    )
    p.set_defaults(func=_cmd_offset)


def _format(args: argparse.Namespace) -> str:
    if args.format:
        return args.format
    suffix = Path(args.output).suffix.lower() if args.output else ""
    return {".wkt": "wkt", ".geojson": "geojson", ".svg": "svg", ".dxf": "dxf"}.get(suffix, "json")


def read_dxf(source: str) -> Any:
    """Closed LWPOLYLINE / POLYLINE entities of a DXF file as one shapely geometry
    (nested rings alternate between outline and hole)."""
    import numpy as np
    import shapely

    from .errors import InputFormatError

    try:
        import ezdxf
    except ImportError:
        raise InputFormatError(
            f"{source}: reading DXF needs ezdxf",
            argument=source,
            hint="pip install 'minkowski2d[dxf]'",
        ) from None
    try:
        doc = ezdxf.readfile(source)
    except (OSError, ezdxf.DXFError) as exc:
        raise InputFormatError(f"{source}: cannot read DXF ({exc})", argument=source) from None
    rings = []
    for e in doc.modelspace().query("LWPOLYLINE POLYLINE"):
        if e.dxftype() == "LWPOLYLINE":
            pts = np.array([(x, y) for x, y, *_ in e.get_points("xyb")], float)
            bulges = [b for *_, b in e.get_points("xyb")]
            closed = e.closed
        else:
            pts = np.array([(v.dxf.location.x, v.dxf.location.y) for v in e.vertices], float)
            bulges = [v.dxf.bulge for v in e.vertices]
            closed = e.is_closed
        if any(b != 0 for b in bulges):
            raise InputFormatError(
                f"{source}: a polyline has arcs (bulges); only straight edges are read",
                argument=source,
                hint="flatten the arcs in your CAD program first",
            )
        if closed and len(pts) >= 3:
            rings.append(shapely.Polygon(pts))
    if not rings:
        raise InputFormatError(
            f"{source}: no closed polyline with three or more vertices", argument=source
        )
    rings.sort(key=lambda g: -abs(g.area))
    g = rings[0]
    for h in rings[1:]:
        g = shapely.symmetric_difference(g, h)
    return g


def _cmd_offset(args: argparse.Namespace) -> int:
    from .cli import CLIError, emit
    from .io import format_geometry, read_geometry
    from .offset import offset, offset_arcs

    src = args.polygon
    poly = read_dxf(src) if src.lower().endswith(".dxf") else read_geometry(src)
    fmt = _format(args)
    exact = fmt in ("svg", "dxf") and args.join == "round" and args.tolerance is None
    if exact:
        arcs = offset_arcs(poly, args.distance)
        if not arcs.polygons:
            print("minkowski2d: note: the shrink erases the polygon", file=sys.stderr)
        if fmt == "svg":
            text = arcs.to_svg()
        else:
            buf = io.StringIO()
            arcs.to_dxf().write(buf)
            text = buf.getvalue()
        emit(text, args.output, [src])
        return 0
    if args.join == "round" and args.tolerance is None:
        raise CLIError("--tolerance is needed for a polygon output with a round join")
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
    if fmt == "dxf":
        text = _polygon_dxf(result)
    else:
        text = format_geometry(result, fmt)
    emit(text, args.output, [src])
    return 0


def _polygon_dxf(geom: Any) -> str:
    """A polygon result as closed LWPOLYLINEs (exteriors counter-clockwise)."""
    import shapely

    from .errors import InputFormatError

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
