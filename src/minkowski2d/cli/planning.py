"""CLI plugin: ``plan`` (exact shortest path of a translating robot among obstacles).

Registered by :mod:`minkowski2d.cli` through :func:`add_parser`. The scene file format is
documented in ``docs/planning.md`` and :meth:`minkowski2d.MotionPlanner.from_scene`.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from typing import Any

from .. import io as _io

#: what a plan is written as: the library's formats but WKT (a path is not a polygon)
_FORMATS = tuple(f for f in _io.FORMATS if f != "wkt")


def add_parser(subparsers: argparse._SubParsersAction) -> None:
    """Add the ``plan`` subcommand."""
    p = subparsers.add_parser(
        "plan",
        help="shortest path of a translating robot among polygonal obstacles",
        description="Exact shortest path of the robot's reference point from --start to "
        "--goal. SCENE is a JSON object {obstacles, robot, workspace} or a GeoJSON "
        "FeatureCollection with a 'role' property per feature (see docs/planning.md), or a "
        "grid map in the Moving AI .map format (cell (x, y) is [x, x+1] x [y, y+1]). "
        "Write negative coordinates as --start=-1,2.",
    )
    p.add_argument("scene", help="scene file (JSON, GeoJSON or a .map grid; - for standard input)")
    p.add_argument("--start", required=True, help="start position x,y")
    p.add_argument("--goal", required=True, help="goal position x,y")
    p.add_argument(
        "--robot",
        help="plan for this robot instead of the scene's: a JSON point list such as "
        "'[[0,0],[1,0],[0,1]]' (its reference point is the origin)",
    )
    p.add_argument("-o", "--output", help="output file (default: standard output)")
    p.add_argument(
        "--format",
        choices=_FORMATS,
        default=None,
        help="json (the path and its length), geojson (path, obstacles and C-obstacles) "
        "or svg (a picture); default: from the -o suffix, else json",
    )
    p.set_defaults(func=_cmd_plan)


def _number(text: str) -> int | float:
    t = text.strip()
    try:
        return int(t)
    except ValueError:
        return float(t)


def _xy(text: str, name: str) -> tuple[Any, Any]:
    from ..errors import ShapeError

    parts = text.split(",")
    try:
        if len(parts) != 2:
            raise ValueError
        x, y = _number(parts[0]), _number(parts[1])
    except ValueError:
        raise ShapeError(
            f"--{name}: expected x,y (two numbers), got {text!r}",
            argument=f"--{name}",
            hint="write e.g. --start=-1,2.5",
        ) from None
    return (x, y)


def _is_map(source: str) -> bool:
    """A Moving AI grid map: by its suffix, or (standard input aside) its first line."""
    if source.lower().endswith(".map"):
        return True
    if source == "-":
        return False
    try:
        with open(source, encoding="utf-8", errors="replace") as fh:
            first = fh.readline()
    except OSError:
        return False
    return first.split()[:1] == ["type"]


def _robot(text: str | None) -> Any:
    if text is None:
        return None
    from .._engine.foreign import foreign_errors
    from ..errors import InputFormatError
    from ..io import parse_geometry

    try:
        with foreign_errors("--robot", "reading the robot"):
            return parse_geometry(text, "--robot")
    except InputFormatError as exc:
        raise exc.renamed(
            hint="give the robot as a JSON point list, e.g. [[0,0],[1,0],[0,1]]"
        ) from None


def _read_scene(source: str) -> Any:
    from .._engine.foreign import foreign_errors
    from ..errors import InputFormatError

    try:
        text = sys.stdin.read() if source == "-" else open(source, encoding="utf-8").read()
    except UnicodeDecodeError:
        raise InputFormatError(f"{source}: not a UTF-8 text file", argument=source) from None
    try:
        with foreign_errors(source, "reading the scene"):
            return json.loads(text)
    except InputFormatError as exc:
        raise exc.renamed(
            hint="a scene is a JSON object with obstacles, robot and workspace"
        ) from None


def _cmd_plan(args: argparse.Namespace) -> int:
    from ..errors import GeometryError
    from ..planning import MotionPlanner
    from .common import emit

    fmt = args.format
    if fmt is None:
        suffix = (args.output or "").lower().rsplit(".", 1)[-1] if args.output else ""
        fmt = {"svg": "svg", "geojson": "geojson"}.get(suffix, "json")
    start = _xy(args.start, "start")
    goal = _xy(args.goal, "goal")
    robot = _robot(args.robot)
    if _is_map(args.scene):
        from ..io import read_grid_map

        scene: Any = None
        planner = MotionPlanner.from_grid(read_grid_map(args.scene))
    else:
        scene = _read_scene(args.scene)
        try:
            planner = MotionPlanner.from_scene(scene, name=args.scene)
        except GeometryError as exc:
            if exc.argument and exc.argument != args.scene:
                raise exc.renamed(f"{args.scene}: {exc.argument}") from None
            raise
    try:
        path = planner.shortest_path(start, goal, robot=robot)
    except GeometryError as exc:
        if exc.argument in ("start", "goal", "robot"):
            raise exc.renamed(f"--{exc.argument}") from None
        raise
    if fmt == "json":
        text = json.dumps({"path": path.points.tolist(), "length": _length(path)})
    elif fmt == "geojson":
        text = json.dumps(geojson(planner, path, start, goal, _obstacle_properties(scene)))
    else:
        text = svg(planner, path, start, goal)
    emit(text, args.output, [args.scene])
    return 0


def _length(path: Any, note: bool = True) -> float | None:
    """The path's length, or None (JSON null) when it does not fit in float64: the path
    is valid and is written all the same, with a note on standard error."""
    from ..errors import OverflowGeometryError

    try:
        return path.length
    except OverflowGeometryError:
        if note:
            print(
                "minkowski2d: note: the path is longer than float64 can hold; its length is "
                "written as null",
                file=sys.stderr,
            )
        return None


def _obstacle_properties(scene: Any) -> list | None:
    """The properties of a FeatureCollection scene's obstacle features, in the planner's
    obstacle order (None for other scenes)."""
    if not isinstance(scene, dict) or scene.get("type") != "FeatureCollection":
        return None
    out = []
    for f in scene.get("features") or []:
        props = (f.get("properties") if isinstance(f, dict) else None) or {}
        if props.get("role", "obstacle") == "obstacle":
            out.append({k: v for k, v in props.items() if k not in ("role", "index")})
    return out


def geojson(planner: Any, path: Any, start: Any, goal: Any, props: list | None = None) -> dict:
    """A FeatureCollection: obstacles, C-obstacles (role properties, and the scene
    features' own properties, kept) and the path."""
    import shapely

    def kept(k: int) -> dict:
        return props[k] if props is not None and k < len(props) else {}

    feats = []
    for k, g in enumerate(planner.obstacles):
        feats.append(
            {
                "type": "Feature",
                "properties": {**kept(k), "role": "obstacle", "index": k},
                "geometry": json.loads(shapely.to_geojson(g)),
            }
        )
    for k, g in enumerate(planner.cspace_obstacles):
        feats.append(
            {
                "type": "Feature",
                "properties": {**kept(k), "role": "c-obstacle", "index": k},
                "geometry": json.loads(shapely.to_geojson(g)),
            }
        )
    pts = path.points.tolist()
    geom = (
        {"type": "Point", "coordinates": pts[0]}
        if len(pts) == 1
        else {"type": "LineString", "coordinates": pts}
    )
    feats.append(
        {
            "type": "Feature",
            "properties": {"role": "path", "length": _length(path)},
            "geometry": geom,
        }
    )
    return {"type": "FeatureCollection", "features": feats}


def svg(planner: Any, path: Any, start: Any, goal: Any) -> str:
    """A standalone SVG picture: obstacles (grey), C-obstacles (red), the reference
    point's box (dashed), the path (blue), start and goal."""
    import numpy as np

    layers: list[tuple[Any, str]] = []
    for g in planner.cspace_obstacles:
        layers.append((g, 'fill="#e06666" fill-opacity="0.35" stroke="#c00"'))
    for g in planner.obstacles:
        layers.append((g, 'fill="#666" fill-opacity="0.85" stroke="#222"'))
    pts = path.points.astype(np.float64)
    xs = [pts[:, 0]]
    ys = [pts[:, 1]]
    for g, _ in layers:
        if not g.is_empty:
            b = g.bounds
            xs.append(np.array([b[0], b[2]]))
            ys.append(np.array([b[1], b[3]]))
    if planner.box is not None:
        b = [float(v) for v in planner.box]
        xs.append(np.array([b[0], b[2]]))
        ys.append(np.array([b[1], b[3]]))
    allx, ally = np.concatenate(xs), np.concatenate(ys)
    x0, x1, y0, y1 = (float(v) for v in (allx.min(), allx.max(), ally.min(), ally.max()))
    w, h = max(x1 - x0, 1e-9), max(y1 - y0, 1e-9)
    if not (math.isfinite(w) and math.isfinite(h) and math.isfinite(1.1 * max(w, h))):
        from ..errors import OverflowGeometryError

        raise OverflowGeometryError(
            "svg: the drawing's extent overflows float64",
            argument="--format",
            hint="use --format json or geojson at this scale",
        )
    L = _length(path, note=False)
    length = "beyond float64" if L is None else f"{L:.12g}"
    pad = 0.05 * max(w, h)
    sw = 0.004 * max(w, h)
    parts = []
    for g, style in layers:
        for poly in getattr(g, "geoms", [g]):
            if poly.geom_type != "Polygon" or poly.is_empty:
                continue
            d = " ".join(
                "M " + " L ".join(f"{x:.17g} {-y:.17g}" for x, y in list(r.coords)[:-1]) + " Z"
                for r in [poly.exterior, *poly.interiors]
            )
            parts.append(f'<path d="{d}" {style} fill-rule="evenodd" stroke-width="{sw:.6g}"/>')
    if planner.box is not None:
        b = [float(v) for v in planner.box]
        parts.append(
            f'<rect x="{b[0]:.17g}" y="{-b[3]:.17g}" width="{b[2] - b[0]:.17g}" '
            f'height="{b[3] - b[1]:.17g}" fill="none" stroke="#333" '
            f'stroke-dasharray="{3 * sw:.6g}" stroke-width="{sw:.6g}"/>'
        )
    line = " ".join(f"{x:.17g},{-y:.17g}" for x, y in pts)
    parts.append(
        f'<polyline points="{line}" fill="none" stroke="#1f5fbf" stroke-width="{2 * sw:.6g}"/>'
    )
    for (x, y), color in ((pts[0], "#2a2"), (pts[-1], "#a22")):
        parts.append(f'<circle cx="{x:.17g}" cy="{-y:.17g}" r="{4 * sw:.6g}" fill="{color}"/>')
    vb = f"{x0 - pad:.17g} {-(y1 + pad):.17g} {w + 2 * pad:.17g} {h + 2 * pad:.17g}"
    body = "\n  ".join(parts)
    return (
        f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{vb}" width="600" height="600">\n'
        f"  <title>minkowski2d plan: length {length}</title>\n  {body}\n</svg>"
    )
