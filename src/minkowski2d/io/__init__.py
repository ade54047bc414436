"""Reading and writing polygons: JSON point lists, GeoJSON, WKT, CGAL ``.dat``, SVG.

:func:`read_geometry` returns an (n, 2) ndarray for a simple ring or point list (ints stay
ints, exactly), or a shapely geometry for a polygon with holes or a multi-polygon.
:func:`format_geometry` turns a result back into text.

Examples
--------
>>> from minkowski2d.io import parse_geometry, format_geometry
>>> p = parse_geometry("[[0, 0], [2, 0], [0, 2]]")
>>> p.tolist()
[[0, 0], [2, 0], [0, 2]]
>>> format_geometry(p, "wkt")
'POLYGON ((0 0, 2 0, 0 2, 0 0))'
"""

from __future__ import annotations

from .cgal_dat import parse_cgal_dat, read_cgal_dat
from .common import Feature, UnboundedPolygon, split_selector
from .dxf import read_dxf
from .features import read_features
from .grid import ScenarioQuery, parse_grid_map, parse_scenario, read_grid_map, read_scenario
from .read import parse_geometry, read_geometry
from .write import FORMATS, format_geometry

__all__ = [
    "read_geometry",
    "parse_geometry",
    "read_cgal_dat",
    "parse_cgal_dat",
    "UnboundedPolygon",
    "split_selector",
    "format_geometry",
    "FORMATS",
    "Feature",
    "read_features",
    "read_dxf",
    "read_grid_map",
    "parse_grid_map",
    "read_scenario",
    "parse_scenario",
    "ScenarioQuery",
]
