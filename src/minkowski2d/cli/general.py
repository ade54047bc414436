"""CLI plugin: ``sum-general``, ``erode`` and ``decompose`` (non-convex polygons, holes).

Registered by :mod:`minkowski2d.cli` through :func:`add_parser`.
"""

from __future__ import annotations

import argparse
import sys


def add_parser(subparsers: argparse._SubParsersAction) -> None:
    """Add the ``sum-general``, ``erode`` and ``decompose`` subcommands."""
    from ..general import DECOMPOSITIONS, SUM_METHODS
    from .common import add_io_options

    p = subparsers.add_parser(
        "sum-general",
        help="Minkowski sum of non-convex polygons (holes allowed)",
        description="A ⊕ B for simple polygons with holes; the result keeps its holes.",
    )
    p.add_argument("a", help="polygon A (file or -)")
    p.add_argument("b", help="polygon B (file or -)")
    p.add_argument("--method", choices=SUM_METHODS, default=None)
    p.add_argument(
        "--decomposition",
        choices=DECOMPOSITIONS,
        default="hertel-mehlhorn",
        help="convex pieces for --method decomposition",
    )
    add_io_options(p)
    p.set_defaults(func=_cmd_sum_general)

    p = subparsers.add_parser(
        "erode",
        help="Minkowski difference (erosion) A ⊖ B = {c : c + B inside A}",
        description="The translations c that put B wholly inside A (not A ⊕ (−B), "
        "which is what 'inflate' computes). An empty result is written as an empty "
        "polygon, with a note on standard error.",
    )
    p.add_argument("a", help="polygon A, the region (file or -)")
    p.add_argument("b", help="polygon B, the shape that must fit (file or -)")
    add_io_options(p)
    p.set_defaults(func=_cmd_erode)

    p = subparsers.add_parser(
        "decompose",
        help="split a polygon (holes allowed) into convex pieces",
        description="Convex pieces as a MultiPolygon (json/geojson/wkt/svg).",
    )
    p.add_argument("polygon", help="the polygon (file or -)")
    p.add_argument("--method", choices=DECOMPOSITIONS, default="hertel-mehlhorn")
    add_io_options(p)
    p.set_defaults(func=_cmd_decompose)


def _cmd_sum_general(args: argparse.Namespace) -> int:
    from ..general import minkowski_sum_general
    from ..io import format_geometry, read_geometry
    from .common import emit, files_named, output_format
    from .features import run_collection

    def op(g: list, names: list) -> object:
        return minkowski_sum_general(
            g[0], g[1], method=args.method, decomposition=args.decomposition
        )

    if (status := run_collection(args, [args.a, args.b], op)) is not None:
        return status
    a = read_geometry(args.a)
    b = read_geometry(args.b)
    with files_named({"a": args.a, "b": args.b, "a, b": f"{args.a}, {args.b}"}):
        result = minkowski_sum_general(a, b, method=args.method, decomposition=args.decomposition)
    emit(format_geometry(result, output_format(args)), args.output, [args.a, args.b])
    return 0


def _cmd_erode(args: argparse.Namespace) -> int:
    from ..general import minkowski_difference
    from ..io import format_geometry, read_geometry
    from .common import emit, files_named, output_format
    from .features import run_collection

    def op(g: list, names: list) -> object:
        return minkowski_difference(g[0], g[1])

    if (status := run_collection(args, [args.a, args.b], op)) is not None:
        return status
    a = read_geometry(args.a)
    b = read_geometry(args.b)
    with files_named({"a": args.a, "b": args.b, "a, b": f"{args.a}, {args.b}"}):
        result = minkowski_difference(a, b)
    if result.is_empty:
        print("minkowski2d: note: B fits nowhere inside A; the erosion is empty", file=sys.stderr)
    emit(format_geometry(result, output_format(args)), args.output, [args.a, args.b])
    return 0


def _pieces_geom(poly: object, method: str) -> object:
    import shapely

    from ..general import convex_decomposition

    pieces = convex_decomposition(poly, method=method)
    polys = [p for p in pieces.to_shapely() if p.geom_type == "Polygon"]
    return shapely.MultiPolygon(polys) if polys else shapely.MultiPolygon()


def _cmd_decompose(args: argparse.Namespace) -> int:
    from ..io import format_geometry, read_geometry
    from .common import emit, files_named, output_format
    from .features import run_collection

    def op(g: list, names: list) -> object:
        return _pieces_geom(g[0], args.method)

    if (status := run_collection(args, [args.polygon], op)) is not None:
        return status
    with files_named({"poly": args.polygon}):
        geom = _pieces_geom(read_geometry(args.polygon), args.method)
    emit(format_geometry(geom, output_format(args)), args.output, [args.polygon])
    return 0
