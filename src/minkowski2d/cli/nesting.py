"""CLI plugin: ``nfp`` (no-fit and inner-fit polygons of an ESICUP instance) and ``nest``
(a layout of an instance's parts on a strip or on sheets).

Registered by :mod:`minkowski2d.cli` through :func:`add_parser`.
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from fractions import Fraction
from pathlib import Path
from typing import Any

from .common import CLIError

#: what ``nest`` writes (the layout's formats, :data:`minkowski2d.nesting.layout.FORMATS`)
NEST_FORMATS = ("json", "geojson", "svg", "dxf")


def add_parser(subparsers: argparse._SubParsersAction) -> None:
    """Add the ``nfp`` and ``nest`` subcommands."""
    _add_nest(subparsers)
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
    p.add_argument(
        "instance",
        help="instance file (ESICUP JSON, see docs/nesting.md) or a built-in instance's name "
        "(albano, shirts, ...: minkowski2d.datasets)",
    )
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
    inst = read_esicup(_instance_path(args.instance))
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


# --------------------------------------------------------------------------------------
# nest


def _add_nest(subparsers: argparse._SubParsersAction) -> None:
    from .common import add_arc_option

    p = subparsers.add_parser(
        "nest",
        help="place an instance's parts on a strip (shortest) or on sheets (fewest)",
        description="Nest the parts of INSTANCE without overlap: on a strip of height H "
        "(its length minimised) or on sheets W x H (the number used minimised, then the "
        "length used on the last). Every layout is checked by the exact certificate. "
        "INSTANCE: ESICUP JSON or a GeoJSON FeatureCollection (quantities and rotations "
        "per piece, see docs/nesting.md), or a DXF drawing (one copy of each closed "
        "outline). Without -o the layout's JSON goes to standard output; a summary line "
        "(sheets, length, density) goes to standard error.",
    )
    p.add_argument(
        "instance",
        help="INSTANCE.json, PARTS.geojson, PARTS.dxf or a built-in instance's name "
        "(albano, shirts, ...: minkowski2d.datasets)",
    )
    where = p.add_mutually_exclusive_group()
    where.add_argument("--height", type=float, help="strip packing: the strip's height")
    where.add_argument(
        "--sheet",
        action="append",
        metavar="WxH[:count]",
        help="bin packing: a sheet kind, W wide and H high, count sheets of it (default "
        "1); repeat for several kinds",
    )
    p.add_argument("--spacing", type=float, default=0.0, help="least distance between parts")
    p.add_argument("--margin", type=float, default=0.0, help="least distance to a sheet's edge")
    p.add_argument(
        "--rotations",
        metavar="A,B,...",
        help="allowed rotations in degrees for every part, e.g. 0,90,180,270 (default: "
        "the instance's, else 0)",
    )
    p.add_argument(
        "--time",
        type=float,
        default=None,
        metavar="SECONDS",
        help="wall-clock budget (default 10, or none with --iterations)",
    )
    p.add_argument(
        "--iterations",
        type=int,
        default=None,
        metavar="N",
        help="a budget of search steps (with --seed: the same layout every run)",
    )
    p.add_argument("--threads", type=int, default=1, help="searches run side by side")
    p.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    p.add_argument("-o", "--output", help="layout.json, .geojson, .svg or .dxf (default: stdout)")
    p.add_argument(
        "--format",
        choices=NEST_FORMATS,
        default=None,
        help="output format (default: from the -o suffix, else json)",
    )
    p.add_argument("--progress", action="store_true", help="show a progress bar (tqdm)")
    add_arc_option(p)
    p.set_defaults(func=_cmd_nest)


def _cmd_nest(args: argparse.Namespace) -> int:
    from ..nesting.nester import nest
    from .common import emit

    fmt = _nest_format(args)
    inst = _nest_instance(args)
    sheets = None if args.sheet is None else [_sheet(t) for t in args.sheet]
    height = args.height
    if sheets is None and height is None and (inst.get("strip") or {}).get("height") is None:
        raise CLIError(
            f"{args.instance}: the instance gives no strip height",
            hint="give --height H (a strip) or --sheet WxH (sheets)",
        )
    time_limit = args.time
    if time_limit is None and args.iterations is None:
        time_limit = 10.0
    layout = nest(
        inst,
        rotations=None if args.rotations is None else _rotations(args.rotations),
        height=height,
        sheets=sheets,
        spacing=args.spacing,
        margin=args.margin,
        time_limit=time_limit,
        iterations=args.iterations,
        threads=args.threads,
        seed=args.seed,
        progress=True if args.progress else None,
    )
    layout.verify()  # nest returns only layouts that pass: the summary says so checked
    try:
        text = layout.to_text(fmt)
    except ImportError as exc:
        raise CLIError(str(exc), hint="pip install 'minkowski2d[dxf]'") from None
    emit(text, args.output, [args.instance])
    print(f"minkowski2d: nest: {_summary(layout)}", file=sys.stderr)
    return 0


def _nest_format(args: argparse.Namespace) -> str:
    """The output format, checked before the search runs: a known -o suffix (or
    --format), an output that is not the instance, ezdxf present for DXF."""
    from .common import same_file

    fmt = args.format
    out = args.output if args.output not in (None, "-") else None
    if out is not None and Path(out).is_dir():
        raise CLIError(f"cannot write {out}: it is a directory", hint="give a file name")
    if fmt is None and out is not None:
        suffix = Path(out).suffix.lower()[1:]
        if suffix not in NEST_FORMATS:
            raise CLIError(
                f"{out}: cannot tell the format from the suffix",
                hint="name it .json, .geojson, .svg or .dxf, or give --format",
            )
        fmt = suffix
    if out is not None and same_file(args.instance, out):
        raise CLIError(
            f"refusing to overwrite the input file {args.instance}", hint="choose another -o file"
        )
    if fmt == "dxf":
        try:
            import ezdxf  # noqa: F401
        except ImportError:
            raise CLIError(
                "DXF output needs ezdxf", hint="pip install 'minkowski2d[dxf]'"
            ) from None
    return fmt or "json"


def _instance_path(text: str) -> Any:
    """The file ``text`` names, or the built-in instance of that name where no such file
    exists (``minkowski2d nest albano``)."""
    from .. import datasets

    if not Path(text).exists() and text in datasets.esicup_names():
        return datasets.esicup_path(text)
    return text


def _nest_instance(args: argparse.Namespace) -> dict:
    """The instance: :func:`~minkowski2d.read_esicup`'s, or one of a DXF drawing's
    closed outlines (one copy each, named by their handles)."""
    from ..nesting import read_esicup

    if not args.instance.lower().endswith(".dxf"):
        return read_esicup(_instance_path(args.instance))
    from ..io import read_dxf

    feats = read_dxf(args.instance, tolerance=args.arc_tolerance)
    return {
        "name": Path(args.instance).stem,
        "ids": [(f.properties or {}).get("handle", str(k)) for k, f in enumerate(feats)],
        "parts": [f.geometry for f in feats],
        "quantities": [1] * len(feats),
        "rotations": None,
        "strip": {},
    }


def _number(text: str, option: str) -> Any:
    """An int, float or Fraction ("p/q") from the command line, finite."""
    t = text.strip()
    try:
        if re.fullmatch(r"[+-]?\d+", t):
            return int(t)
        if "/" in t:
            return Fraction(t)
        v = float(t)
        if v - v == 0:  # finite
            return v
    except (ValueError, ZeroDivisionError):
        pass
    raise CLIError(f"{option}: {text!r} is not a finite number", hint=f"e.g. {option} 0,180")


def _rotations(text: str) -> tuple:
    return tuple(_number(t, "--rotations") for t in text.split(","))


def _sheet(text: str) -> Any:
    """``WxH`` or ``WxH:count`` as nest's sheet entry ``(W, H)`` or ``((W, H), count)``."""
    m = re.fullmatch(r"\s*([^xX:]+)[xX]([^xX:]+)(?::\s*(\d+))?\s*", text)
    if m is None:
        raise CLIError(
            f"--sheet: expected WxH or WxH:count, got {text!r}",
            hint="e.g. --sheet 120x60 or --sheet 120x60:3",
        )
    size = (_number(m.group(1), "--sheet"), _number(m.group(2), "--sheet"))
    return size if m.group(3) is None else (size, int(m.group(3)))


def _summary(layout: Any) -> str:
    n = len(layout.placements)
    if layout.strip_height is not None:
        where = f"a strip {layout.strip_height:g} high, length {layout.length:g}"
    else:
        k = layout.n_sheets
        where = f"{k} sheet{'s' if k != 1 else ''}, {layout.length:g} used on the last"
    return f"{n} parts on {where}, density {100 * layout.density:.2f} %, verified"
