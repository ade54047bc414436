"""CLI plugin: ``nfp`` (no-fit and inner-fit polygons of an ESICUP instance).

Registered by :mod:`minkowski2d.cli` through :func:`add_parser`.
"""

from __future__ import annotations

import argparse
import json


def add_parser(subparsers: argparse._SubParsersAction) -> None:
    """Add the ``nfp`` subcommand."""
    p = subparsers.add_parser(
        "nfp",
        help="no-fit polygons of every piece pair and rotation of an ESICUP instance",
        description="NFP(rot A, rot B) = rot A ⊕ (−rot B) for every ordered pair of piece "
        "types and every pair of allowed rotations, and the inner-fit polygon of every "
        "piece and rotation in the strip (its length, or when the instance gives none, "
        "the sum of quantity times the larger side of every piece's bounding box). "
        "json: {instance, strip, pieces, nfps: [{i, ri, j, rj, geometry}], ifps: [...]}; "
        "geojson: one FeatureCollection (properties kind, i, ri, j, rj).",
    )
    p.add_argument("instance", help="instance file (ESICUP JSON, see docs/nesting.md)")
    p.add_argument("-o", "--output", help="output file (default: standard output)")
    p.add_argument("--format", choices=("json", "geojson"), default=None)
    p.add_argument(
        "--keep-degenerate",
        action="store_true",
        help="keep exact fits and slides (zero-area placements) in the NFPs",
    )
    p.add_argument("--progress", action="store_true", help="show a progress bar (tqdm)")
    p.set_defaults(func=_cmd_nfp)


def _cmd_nfp(args: argparse.Namespace) -> int:
    import shapely

    from ..nesting import inner_fit_polygon, no_fit_polygons, read_esicup, rotate_part
    from .common import emit

    fmt = args.format
    if fmt is None:
        fmt = "geojson" if str(args.output or "").lower().endswith(".geojson") else "json"
    inst = read_esicup(args.instance)
    parts, rots = inst["parts"], inst["rotations"]
    props = inst.get("properties") or [None] * len(parts)
    nfps = no_fit_polygons(
        parts,
        rotations=rots,
        keep_degenerate=args.keep_degenerate,
        progress=True if args.progress else None,
    )
    strip = dict(inst["strip"] or {})
    H = strip.get("height")
    Lx = strip.get("length")
    if Lx is None and H is not None:
        b = shapely.bounds(parts)
        side = [max(x1 - x0, y1 - y0) for x0, y0, x1, y1 in b.tolist()]
        Lx = sum(q * s for q, s in zip(inst["quantities"], side, strict=True))
        strip["length_used"] = Lx
    ifps = []
    if H is not None:
        sheet = [(0, 0), (Lx, 0), (Lx, H), (0, H)]
        for i, part in enumerate(parts):
            for r in rots[i]:
                ifps.append((i, r, inner_fit_polygon(sheet, rotate_part(part, r))))
    if fmt == "geojson":
        feats = [
            {
                "type": "Feature",
                "properties": {
                    "kind": "nfp",
                    "i": i,
                    "ri": ri,
                    "j": j,
                    "rj": rj,
                    **_kept(props, i, "a"),
                    **_kept(props, j, "b"),
                },
                "geometry": json.loads(shapely.to_geojson(g)),
            }
            for (i, ri, j, rj), g in nfps.items()
        ] + [
            {
                "type": "Feature",
                "properties": {"kind": "ifp", "i": i, "r": r, **_kept(props, i, "part")},
                "geometry": json.loads(shapely.to_geojson(g)),
            }
            for i, r, g in ifps
        ]
        text = json.dumps({"type": "FeatureCollection", "features": feats})
    else:
        text = json.dumps(
            {
                "instance": inst["name"],
                "strip": strip,
                "pieces": inst["ids"],
                "nfps": [
                    {
                        "i": i,
                        "ri": ri,
                        "j": j,
                        "rj": rj,
                        "geometry": json.loads(shapely.to_geojson(g)),
                    }
                    for (i, ri, j, rj), g in nfps.items()
                ],
                "ifps": [
                    {"i": i, "r": r, "geometry": json.loads(shapely.to_geojson(g))}
                    for i, r, g in ifps
                ],
            }
        )
    emit(text, args.output, [args.instance])
    return 0


def _kept(props: list, i: int, key: str) -> dict:
    """The properties of part ``i`` (a FeatureCollection instance), under ``key``."""
    return {key: props[i]} if props[i] is not None else {}
