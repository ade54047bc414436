"""Reading collections: GeoJSON FeatureCollections and DXF drawings, one Feature per part."""

from __future__ import annotations

import json
from pathlib import Path

from ..errors import (
    EmptyGeometryError,
    GeometryError,
    ShapeError,
)
from .common import Feature, _read_text, _short
from .dxf import (
    read_dxf,
)
from .read import (
    _from_geojson,
)


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
