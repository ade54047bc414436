"""The command line on collections: GeoJSON FeatureCollections and DXF drawings in, one
feature out per feature in (properties kept), and ``minkowski2d completion``.

``sum``, ``inflate`` and ``hull`` call :func:`run_features` first; it answers None when
no input is a collection, and the command goes on as before. Otherwise:

* ``minkowski2d inflate obstacles.geojson robot.json`` gives one feature per obstacle,
  ``obstacle ⊕ (−robot)``, with the obstacle's properties (and ``id``);
* ``sum A B`` with one collection pairs each feature with the other polygon, with two
  collections of equal length pairs them in order (properties of A, then B's under keys A
  does not have);
* ``hull`` gives each feature's convex hull.

A null geometry stays null. A non-convex or holed feature takes the general sum (``sum``,
``inflate``) as the single-polygon commands do. Every result is computed before anything
is written, so a bad feature (exit status 2, naming ``file: features[k]``) leaves no
partial output. The output is a FeatureCollection (``--format json`` or ``geojson``), one
WKT per line (``wkt``), or one SVG drawing (``svg``).
"""

from __future__ import annotations

import argparse
import json
from collections.abc import Callable
from typing import Any

from .common import emit, is_general, output_format

__all__ = ["run_features", "run_collection", "write_collection", "arc_tolerance"]


def _neg(g: Any) -> Any:
    import numpy as np

    if isinstance(g, np.ndarray):
        return -g
    import shapely

    return shapely.affinity.scale(g, -1, -1, origin=(0, 0))


def _op(cmd: str, a: Any, b: Any, hull: bool, names: tuple[str, str]) -> Any:
    import numpy as np

    from .. import convex, general

    if cmd == "hull":
        if not isinstance(a, np.ndarray):  # holes or several parts: the hull of all
            import shapely

            a = shapely.get_coordinates(a)
        return convex.convex_hull(a)
    if cmd == "inflate":
        if not hull and (is_general(a, names[0]) or is_general(b, names[1])):
            return general.minkowski_sum_general(a, _neg(b))
        return convex.cspace_obstacle(a, b, hull=hull)
    if not hull and (is_general(a, names[0]) or is_general(b, names[1])):
        return general.minkowski_sum_general(a, b)
    return convex.minkowski_sum(a, b, hull=hull)


def _inputs(args: argparse.Namespace, cmd: str) -> list[str]:
    if cmd == "sum":
        return [args.a, args.b]
    if cmd == "inflate":
        return [args.obstacle, args.robot]
    return [args.points]


def run_features(args: argparse.Namespace, cmd: str) -> int | None:
    """Run ``cmd`` (``sum``, ``inflate``, ``hull``) on collections; None when no input
    is a FeatureCollection or a DXF drawing."""
    hull = bool(getattr(args, "hull", False))

    def op(geoms: list, names: list) -> Any:
        b = geoms[1] if len(geoms) > 1 else None
        return _op(cmd, geoms[0], b, hull, (names[0], names[-1]))

    return run_collection(args, _inputs(args, cmd), op)


#: the Python argument names errors carry, by input position (first or second file)
_ARGS = (
    ("a", "obstacle", "points", "polygon", "poly", "container", "A"),
    ("b", "robot", "B", "part"),
)


def arc_tolerance(args: argparse.Namespace) -> float | None:
    """The ``--arc-tolerance`` of a command (None where it has none)."""
    return getattr(args, "arc_tolerance", None)


def run_collection(
    args: argparse.Namespace,
    files: list[str],
    op: Callable[[list, list], Any],
    *,
    writer: Callable[[list, str], str | None] | None = None,
    fmt: str | None = None,
) -> int | None:
    """Run ``op`` once per feature when an input is a GeoJSON FeatureCollection or a DXF
    drawing (else None: the command reads single polygons as before).

    ``op(geometries, names)`` gets one geometry per input file (a collection's feature,
    or the single polygon of the other file, broadcast) and their names
    (``file: features[k]``), and returns the result geometry, or ``(geometry, extra
    properties)``. Features are paired in order (two collections need equal lengths); a
    null geometry gives a null result; the properties (and ``id``) of the features are
    kept, the first file's winning. Every result is computed before anything is written
    (a bad feature: exit status 2, naming it; no partial output). ``writer(results,
    fmt)``, when given, writes formats of its own (``dxf``, an exact ``svg``; None: the
    default), else :func:`write_collection` does; ``fmt`` defaults to ``--format`` or
    the ``-o`` suffix."""
    from ..errors import GeometryError, ShapeError
    from ..io import Feature, read_features, read_geometry

    if any(f == "-" for f in files):
        return None  # standard input is read once, by the single-polygon path
    tol = arc_tolerance(args)
    feats = [read_features(f, arc_tolerance=tol) for f in files]
    if all(f is None for f in feats):
        return None
    counts = {len(f) for f in feats if f is not None}
    if len(counts) > 1:
        raise ShapeError(
            f"{files[0]} has {len(feats[0] or [])} features but {files[1]} has "
            f"{len(feats[1] or [])}; pairs need equal counts",
            hint="give one collection and one polygon, or two collections of equal length",
        )
    n = counts.pop()
    cols = [
        f if f is not None else [Feature(read_geometry(path, arc_tolerance=tol), None, {})] * n
        for f, path in zip(feats, files)
    ]
    out = []
    for k in range(n):
        parts = [c[k] for c in cols]
        names = [
            f"{path}: features[{k}]" if f is not None else path for f, path in zip(feats, files)
        ]
        props: dict | None = None
        extra: dict = {}
        for p, f in zip(parts, feats):
            if f is not None and p.properties is not None:
                props = {**p.properties, **(props or {})}
            if f is not None and not extra:
                extra = p.extra
        if any(p.geometry is None for p in parts):
            out.append((None, props, extra))
            continue
        try:
            res = op([p.geometry for p in parts], names)
        except GeometryError as exc:
            raise _name(exc, names) from None
        if isinstance(res, tuple):
            res, more = res
            props = {**(props or {}), **more}
        out.append((res, props, extra))
    fmt = fmt or output_format(args)
    text = writer(out, fmt) if writer is not None else None
    if text is None:
        text = write_collection(out, fmt)
    emit(text, args.output, files)
    return 0


def write_collection(out: list, fmt: str) -> str:
    """The results ``(geometry or None, properties, extra)`` as a FeatureCollection
    (``json``, ``geojson``), one WKT per line (``wkt``) or one SVG drawing (``svg``)."""
    from ..io import format_geometry

    return _format(out, fmt, format_geometry)


def _name(exc: Any, names: Any) -> Any:
    from .common import CLI_HULL_HINT, renamed_error

    mapping = dict.fromkeys(_ARGS[0], names[0])
    mapping.update(dict.fromkeys(_ARGS[1], names[-1]))
    mapping["a, b"] = ", ".join(dict.fromkeys(names))
    if exc.argument in names:  # already named
        return renamed_error(exc, hull_hint=CLI_HULL_HINT, hint_in_message=True)
    if exc.argument in mapping:
        return renamed_error(exc, mapping, hull_hint=CLI_HULL_HINT, hint_in_message=True)
    return renamed_error(exc, prefix=names[0], hull_hint=CLI_HULL_HINT, hint_in_message=True)


def _format(out: list, fmt: str, format_geometry: Any) -> str:
    if fmt == "wkt":
        return "\n".join(
            "GEOMETRYCOLLECTION EMPTY" if g is None else format_geometry(g, "wkt")
            for g, _, _ in out
        )
    if fmt == "svg":
        import numpy as np
        import shapely

        geoms = [
            shapely.from_geojson(format_geometry(g, "geojson")) for g, _, _ in out if g is not None
        ]
        gc = shapely.GeometryCollection(geoms)
        return format_geometry(gc, "svg") if geoms else format_geometry(np.zeros((1, 2)), "svg")
    feats = []
    for g, props, extra in out:
        geom = None if g is None else json.loads(format_geometry(g, "geojson"))
        feats.append({"type": "Feature", **extra, "geometry": geom, "properties": props})
    return json.dumps({"type": "FeatureCollection", "features": feats})
