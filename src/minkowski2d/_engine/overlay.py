"""The exact overlay of the compiled core, as the public modules use it: rings in (as
ragged float64 arrays), shapely geometries out. One place for the conversion of the
core's ragged results into shapely Polygons / MultiPolygons.

Examples
--------
>>> from minkowski2d._engine.overlay import overlay
>>> sq = [(0, 0), (2, 0), (2, 2), (0, 2)]
>>> overlay([sq, [(1, 1), (3, 1), (3, 3), (1, 3)]]).wkt
'POLYGON ((0 0, 2 0, 2 1, 3 1, 3 3, 1 3, 1 2, 0 2, 0 0))'
>>> overlay([sq, [(1, 1), (3, 1), (3, 3), (1, 3)]], layers=[0, 1], rule="difference").area
3.0
"""

from __future__ import annotations

from typing import Any

import numpy as np

from . import core
from .status import status_error

__all__ = ["overlay", "geometries", "closed_geometries"]


def geometries(xy: np.ndarray, ro: np.ndarray, po: np.ndarray, group_off: np.ndarray) -> np.ndarray:
    """shapely geometries of the core's ragged rings (each polygon's exterior first):
    per group a Polygon, a MultiPolygon, or an empty Polygon (vectorized)."""
    import shapely

    K = len(group_off) - 1
    out = np.empty(K, dtype=object)
    if len(xy) == 0:
        out[:] = [shapely.Polygon() for _ in range(K)]
        return out
    if K == 1 and len(po) <= 9:
        # one result of a few polygons: built directly (a third of the vectorized cost)
        polys = [
            shapely.Polygon(xy[ro[po[p]] : ro[po[p] + 1]],
                            [xy[ro[r] : ro[r + 1]] for r in range(po[p] + 1, po[p + 1])])
            for p in range(len(po) - 1)
        ]  # fmt: skip
        out[0] = (
            shapely.Polygon() if not polys else polys[0] if len(polys) == 1
            else shapely.MultiPolygon(polys)
        )  # fmt: skip
        return out
    # close the rings: the first vertex again after the last of each ring
    lens = np.diff(ro)
    idx = np.arange(len(xy) + len(lens)) - np.repeat(np.arange(len(lens)), lens + 1)
    ends = np.cumsum(lens + 1) - 1
    idx[ends] = ro[:-1]
    coords = xy[idx]
    rco = np.concatenate([[0], np.cumsum(lens + 1)]).astype(np.int64)
    return closed_geometries(coords, rco, po, group_off)


def closed_geometries(
    xy: np.ndarray, ro: np.ndarray, po: np.ndarray, group_off: np.ndarray
) -> np.ndarray:
    """As :func:`geometries`, for rings that already repeat their first vertex last."""
    import shapely

    K = len(group_off) - 1
    out = np.empty(K, dtype=object)
    if len(xy) == 0:
        out[:] = [shapely.Polygon() for _ in range(K)]
        return out
    if K == 1:  # one group (a single call): its Polygon or MultiPolygon directly
        P = len(po) - 1
        kind = shapely.GeometryType.POLYGON if P == 1 else shapely.GeometryType.MULTIPOLYGON
        out[0] = shapely.from_ragged_array(kind, xy, (ro, po) if P == 1 else (ro, po, group_off))[0]
        return out
    multi = shapely.from_ragged_array(shapely.GeometryType.MULTIPOLYGON, xy, (ro, po, group_off))
    parts = shapely.get_num_geometries(multi)
    one = parts == 1
    out[one] = shapely.get_geometry(multi[one], 0)
    many = parts > 1
    out[many] = multi[many]
    for k in np.flatnonzero(parts == 0):
        out[k] = shapely.Polygon()
    return out


def overlay(
    rings: list,
    weights: Any = None,
    layers: Any = None,
    rule: str = "union",
    argument: str = "result",
) -> Any:
    """The region ``rule`` selects from the winding numbers of ``rings`` (each an (n, 2)
    float64 array-like; counter-clockwise rings have winding number ``weight`` inside;
    ``layers`` 0 or 1 for the two winding numbers of the difference and intersection),
    as one shapely geometry. Every decision is exact; vertices are correctly rounded."""
    arrs = [np.asarray(r, dtype=np.float64).reshape(-1, 2) for r in rings]
    n = len(arrs)
    xy = np.ascontiguousarray(np.concatenate(arrs)) if arrs else np.empty((0, 2))
    off = np.concatenate([[0], np.cumsum([len(a) for a in arrs])]).astype(np.int64)
    w = np.ones(n, np.int64) if weights is None else np.asarray(weights, np.int64)
    ly = np.zeros(n, np.int64) if layers is None else np.asarray(layers, np.int64)
    code = core.OVERLAY_OPS[rule]
    out, ro, po, status, _ = core.overlay_rings(xy, np.empty((0, 2)), off, w, ly, code)
    check(int(status), argument)
    return geometries(out, ro, po, np.array([0, len(po) - 1], np.int64))[0]


def check(status: int, argument: str) -> None:
    """Raise the error a status of the overlay stands for (OK: nothing)."""
    if status != core.Status.OK:
        raise status_error(status, name=argument, what="the overlay")
