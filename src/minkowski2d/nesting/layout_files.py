"""A :class:`~minkowski2d.nesting.layout.Layout` as JSON and GeoJSON, and read back.

Every number is written exactly: coordinates and translations as Python floats (JSON
writes the shortest text that reads back to the same float), rotations as given (a
Fraction as the string ``"p/q"``). Reading checks every field and names the one at fault
in an :class:`~minkowski2d.errors.InputFormatError`.
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from fractions import Fraction
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import GeometryError, InputFormatError
from .layout import JSON_TYPE, Layout, Placement

__all__ = ["layout_dict", "layout_geojson", "from_dict", "load"]


def _meta(lay: Layout) -> dict[str, Any]:
    return {
        "name": lay.name,
        "strip_height": lay.strip_height,
        "spacing": lay.spacing,
        "margin": lay.margin,
        "parts": [
            {"id": i, "geometry": _geometry_json(p)}
            for i, p in zip(lay.ids, lay.parts, strict=True)
        ],
    }


def layout_dict(lay: Layout) -> dict[str, Any]:
    """:meth:`Layout.to_dict`."""
    kinds = lay.kinds or (None,) * lay.n_sheets
    return {
        "type": JSON_TYPE,
        "version": 1,
        **_meta(lay),
        "sheets": [
            {"kind": k, "geometry": _geometry_json(s)}
            for k, s in zip(kinds, lay.sheets, strict=True)
        ],
        "placements": [_placement_json(p) for p in lay.placements],
        "length": lay.length,
        "density": lay.density,
        "densities": lay.densities,
    }


def layout_geojson(lay: Layout) -> dict[str, Any]:
    """:meth:`Layout.to_geojson`."""
    kinds = lay.kinds or (None,) * lay.n_sheets
    feats = [
        _feature(s, {"kind": "sheet", "sheet": k, "sheet_kind": kinds[k], "density": d})
        for k, (s, d) in enumerate(zip(lay.sheets, lay.densities, strict=True))
    ]
    for k, (p, g) in enumerate(zip(lay.placements, lay.polygons(), strict=True)):
        props = {"kind": "part", "placement": k, "part": p.part, "id": lay.ids[p.part]}
        props.update(copy=p.copy, sheet=p.sheet, rotation=_angle_json(p.rotation))
        props.update(x=p.translation[0], y=p.translation[1], fixed=p.fixed)
        feats.append(_feature(g, props))
    out: dict[str, Any] = {"type": "FeatureCollection"}
    if lay.name is not None:
        out["name"] = lay.name
    out["layout"] = {"type": JSON_TYPE, "version": 1, **_meta(lay)}
    out["features"] = feats
    return out


def _angle_json(r: Any) -> Any:
    return f"{r.numerator}/{r.denominator}" if isinstance(r, Fraction) else r


def _rings(g: Any) -> list:
    """A polygon's rings as lists of [x, y] Python floats, closed (GeoJSON)."""
    rings = [g.exterior, *g.interiors]
    return [np.asarray(r.coords, dtype=np.float64)[:, :2].tolist() for r in rings]


def _geometry_json(g: Any) -> dict:
    """A Polygon as a GeoJSON geometry, every coordinate exact (Python floats: JSON
    writes the shortest text that reads back to the same float)."""
    return {"type": "Polygon", "coordinates": _rings(g)}


def _feature(g: Any, props: dict) -> dict:
    return {"type": "Feature", "properties": props, "geometry": _geometry_json(g)}


def _placement_json(p: Placement) -> dict:
    return {
        "part": p.part,
        "copy": p.copy,
        "sheet": p.sheet,
        "rotation": _angle_json(p.rotation),
        "translation": list(p.translation),
        "fixed": p.fixed,
    }


class _Bad(Exception):
    """A malformed field (turned into an InputFormatError naming the file)."""

    def __init__(self, where: str, what: str) -> None:
        super().__init__(f"{where}: {what}")


def _field(d: Any, key: str, where: str, kinds: tuple) -> Any:
    if not isinstance(d, Mapping):
        raise _Bad(where, f"must be an object, got {type(d).__name__}")
    if key not in d:
        raise _Bad(where, f"no {key!r}")
    v = d[key]
    if not isinstance(v, kinds) or (isinstance(v, bool) and bool not in kinds):
        raise _Bad(f"{where}.{key}", f"must be {kinds[0].__name__}, got {type(v).__name__}")
    return v


def _polygon_of(g: Any, where: str) -> Any:
    import shapely

    from .nfp import _coords

    if _field(g, "type", where, (str,)) != "Polygon":
        raise _Bad(where, f"must be a Polygon, got {str(g['type'])[:30]}")
    rings = _field(g, "coordinates", where, (list,))
    if not rings:
        raise _Bad(where, "a Polygon without rings")
    try:
        cs = [_coords(r) for r in rings]
        return shapely.Polygon(cs[0], cs[1:])
    except (TypeError, ValueError, shapely.errors.ShapelyError) as exc:
        raise _Bad(f"{where}.coordinates", str(exc)) from None


def _rotation_of(v: Any, where: str) -> Any:
    if isinstance(v, str):
        try:
            return Fraction(v)
        except (ValueError, ZeroDivisionError):
            raise _Bad(where, f"not a number or fraction 'p/q': {v[:30]!r}") from None
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise _Bad(where, f"must be a number of degrees, got {type(v).__name__}")
    return v


def _placement_of(p: Any, where: str) -> Placement:
    t = _field(p, "translation", where, (list,))
    part, copy, sheet = (_field(p, k, where, (int,)) for k in ("part", "copy", "sheet"))
    rotation = _rotation_of(p.get("rotation", 0), f"{where}.rotation")
    try:
        return Placement(part, copy, sheet, rotation, tuple(t), p.get("fixed", False))
    except GeometryError as exc:
        raise _Bad(where, str(exc)) from None


def _parts_of(meta: Mapping, where: str) -> tuple[list, list]:
    items = _field(meta, "parts", where, (list,))
    parts = [
        _polygon_of(
            _field(q, "geometry", f"{where}.parts[{i}]", (dict,)), f"{where}.parts[{i}].geometry"
        )
        for i, q in enumerate(items)
    ]
    ids = [str(q.get("id", i)) for i, q in enumerate(items)]
    return parts, ids


def _build(
    name: str, meta: Mapping, parts: list, ids: list, places: list, sheets: list, kinds: list
) -> Layout:
    """The Layout, any error of its checks worded as an input error of the file."""
    height = meta.get("strip_height")
    try:
        return Layout(
            parts,
            places,
            sheets,
            kinds=None if height is not None or all(k is None for k in kinds) else kinds,
            strip_height=height,
            spacing=meta.get("spacing", 0.0),
            margin=meta.get("margin", 0.0),
            ids=ids,
            name=meta.get("name"),
        )
    except GeometryError as exc:
        raise InputFormatError(
            f"{name}: not a valid layout ({exc})",
            argument=name,
            hint="a layout file as Layout.write writes it",
        ) from None


def from_dict(d: Any, name: str) -> Layout:
    """:meth:`Layout.from_dict`."""
    try:
        if not isinstance(d, Mapping) or d.get("type") != JSON_TYPE:
            raise _Bad("type", f"not {JSON_TYPE!r} (is it a layout file?)")
        parts, ids = _parts_of(d, "layout")
        sheets, kinds = [], []
        for k, s in enumerate(_field(d, "sheets", "layout", (list,))):
            sheets.append(
                _polygon_of(_field(s, "geometry", f"sheets[{k}]", (dict,)), f"sheets[{k}].geometry")
            )
            kinds.append(s.get("kind"))
        places = [
            _placement_of(p, f"placements[{k}]")
            for k, p in enumerate(_field(d, "placements", "layout", (list,)))
        ]
    except (_Bad, GeometryError) as exc:
        raise InputFormatError(
            f"{name}: {exc}", argument=name, hint="a layout file as Layout.write writes it"
        ) from None
    return _build(name, d, parts, ids, places, sheets, kinds)


def _from_geojson(fc: Mapping, name: str) -> Layout:
    try:
        meta = _field(fc, "layout", "FeatureCollection", (dict,))
        parts, ids = _parts_of(meta, "layout")
        feats = _field(fc, "features", "FeatureCollection", (list,))
        sheets, kinds, places = {}, {}, []
        for k, f in enumerate(feats):
            where = f"features[{k}]"
            props = _field(f, "properties", where, (dict,))
            kind = props.get("kind")
            if kind == "sheet":
                i = _field(props, "sheet", f"{where}.properties", (int,))
                geom = _field(f, "geometry", where, (dict,))
                sheets[i] = _polygon_of(geom, f"{where}.geometry")
                kinds[i] = props.get("sheet_kind")
            elif kind == "part":
                props = {"translation": [props.get("x"), props.get("y")], **props}
                at = props.get("placement")
                at = at if type(at) is int else len(feats) + k  # unnumbered: in file order
                places.append((at, _placement_of(props, where)))
        if sorted(sheets) != list(range(len(sheets))):
            raise _Bad("features", f"sheets numbered {sorted(sheets)[:8]}, not 0, 1, ...")
    except (_Bad, GeometryError) as exc:
        raise InputFormatError(
            f"{name}: {exc}",
            argument=name,
            hint="a GeoJSON layout as Layout.write writes it (its 'layout' member kept)",
        ) from None
    places.sort(key=lambda kp: kp[0])
    return _build(
        name,
        meta,
        parts,
        ids,
        [p for _, p in places],
        [sheets[k] for k in range(len(sheets))],
        [kinds[k] for k in range(len(sheets))],
    )


def load(path: str | Path) -> Layout:
    """:func:`~minkowski2d.nesting.layout.read_layout`."""
    from .._engine.foreign import foreign_errors

    name = str(path)
    if Path(name).suffix.lower() in (".svg", ".dxf"):
        raise InputFormatError(
            f"{name}: drawings are not read back as layouts",
            argument=name,
            hint="write the layout as .json or .geojson to read it again",
        )
    try:
        raw = Path(path).read_bytes()
    except FileNotFoundError:
        raise InputFormatError(f"{name}: no such file", argument=name) from None
    except IsADirectoryError:
        raise InputFormatError(f"{name}: is a directory, not a file", argument=name) from None
    except (OSError, ValueError) as exc:
        raise InputFormatError(
            f"{name}: cannot read ({getattr(exc, 'strerror', None) or exc})", argument=name
        ) from None
    with foreign_errors(name, "reading the layout"):
        d = json.loads(raw.decode("utf-8-sig"))
    if isinstance(d, Mapping) and d.get("type") == "FeatureCollection":
        return _from_geojson(d, name)
    return from_dict(d, name)
