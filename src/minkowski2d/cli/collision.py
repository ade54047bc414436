"""CLI plugin: ``collide`` — intersection, distance and penetration of two convex polygons.

Registered by :mod:`minkowski2d.cli` through :func:`add_parser`.
"""

from __future__ import annotations

import argparse
import json
from typing import Any


def add_parser(subparsers: argparse._SubParsersAction) -> None:
    """Add the ``collide`` subcommand."""
    p = subparsers.add_parser(
        "collide",
        help="do two convex polygons intersect? distance, witnesses, penetration (JSON)",
        description="Prints JSON with: intersects (touching counts), distance with a "
        "witness point on each polygon, and the signed penetration (depth > 0 when the "
        "interiors overlap, 0 when touching, minus the distance when apart; translating "
        "B by depth * normal leaves them touching).",
    )
    p.add_argument("a", help="convex polygon A (file or -)")
    p.add_argument("b", help="convex polygon B (file or -)")
    p.add_argument("--hull", action="store_true", help="use the convex hulls of the inputs")
    p.add_argument(
        "--method",
        choices=("auto", "sum", "gjk"),
        default="auto",
        help="intersection test: boundary walk of A ⊕ (−B), exact GJK, or auto (default)",
    )
    p.add_argument("-o", "--output", help="output file (default: standard output)")
    from .common import add_arc_option

    add_arc_option(p)
    p.set_defaults(func=_cmd_collide)


def _xy(v: Any) -> list[float]:
    return [float(v[0]), float(v[1])]


def _convex_input(g: Any, name: str) -> Any:
    import numpy as np

    from ..errors import NotConvexError

    if not isinstance(g, np.ndarray):
        raise NotConvexError(
            f"{name}: not a single convex polygon (holes or several parts)",
            argument=name,
            hint="use sum-general for polygons with holes",
        )
    return g


def _collide(a: Any, b: Any, args: argparse.Namespace) -> dict:
    from ..collision import distance, intersects, penetration

    hit = intersects(a, b, method=args.method, hull=args.hull)
    d = distance(a, b, hull=args.hull)
    p = penetration(a, b, hull=args.hull)
    return {
        "intersects": hit,
        "distance": {
            "distance": d.distance,
            "point_a": _xy(d.point_a),
            "point_b": _xy(d.point_b),
        },
        "penetration": {
            "depth": p.depth,
            "normal": _xy(p.normal),
            "point_a": _xy(p.point_a),
            "point_b": _xy(p.point_b),
        },
    }


def _cmd_collide(args: argparse.Namespace) -> int:
    import numpy as np

    from ..errors import NotConvexError
    from ..io import read_geometry
    from .common import CLI_HULL_HINT, emit, renamed_error
    from .features import run_collection

    def op(geoms: list, names: list) -> Any:
        # one feature per pair: the properties of both, the results, and as geometry the
        # distance's witness segment (a point where the polygons meet)
        res = _collide(_convex_input(geoms[0], names[0]), _convex_input(geoms[1], names[1]), args)
        d = res["distance"]
        seg = np.array([d["point_a"], d["point_b"]])
        return (seg[:1] if d["point_a"] == d["point_b"] else seg), res

    files = [args.a, args.b]
    if (status := run_collection(args, files, op, fmt="geojson")) is not None:
        return status
    a = _convex_input(read_geometry(args.a), args.a)
    b = _convex_input(read_geometry(args.b), args.b)
    try:
        out = _collide(a, b, args)
    except NotConvexError as exc:
        # name the file and the option rather than the Python argument
        raise renamed_error(exc, {"a": args.a, "b": args.b}, hull_hint=CLI_HULL_HINT) from None
    emit(json.dumps(out, indent=2), args.output, [args.a, args.b])
    return 0
