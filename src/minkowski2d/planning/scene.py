"""Reading a planning scene: obstacles and workspace into convex pieces of one kind (int64
or float64), points, grids; the checks and their messages."""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any

import numpy as np

from .._engine import core
from .._engine import dispatch as D
from .._engine.coerce import ints_fit_float64, is_shapely
from .._engine.reader import read
from .._engine.status import nonfinite
from ..errors import (
    EmptyGeometryError,
    NonFiniteError,
    OptionError,
    ShapeError,
)

_NOT_CONVEX = (D.Status.TURNS_BOTH_WAYS, D.Status.SPIKE, D.Status.WINDS_TWICE)
#: the end of every message about ints float64 cannot hold (coerce.fits_float64)
_NOT_F64 = "cannot be converted to float64 exactly (more than 53 significant bits)"
_INT_LIMIT = core.INT_LIMIT


# --------------------------------------------------------------------------------------
# input


def _triangulate(poly: Any, name: str) -> list[np.ndarray]:
    """Convex pieces (triangles) of a shapely polygon with holes: the core's exact
    triangulation (every decision an exact sign, every triangle vertex an input vertex,
    bit for bit, each triangle counter-clockwise); an invalid polygon raises
    SelfIntersectionError naming the ring and vertex."""
    from .._engine.polygon import rings_of, triangulate

    rings = rings_of(poly)
    tri = triangulate(rings, name, _SIMPLE_HINT, what="not a simple polygon")
    return list(rings.coords[tri])


_SIMPLE_HINT = "fix the ring (it must not cross itself)"


def _pieces(obj: Any, name: str) -> tuple[list[np.ndarray], str]:
    """Convex pieces of one polygon-like input and their kind ("int" or "float")."""
    if is_shapely(obj):
        gt = obj.geom_type
        if gt == "MultiPolygon" or gt == "GeometryCollection":
            if obj.is_empty:
                raise EmptyGeometryError(f"{name}: an empty {gt}", argument=name)
            out: list[np.ndarray] = []
            for k, part in enumerate(obj.geoms):
                out += _pieces(part, f"{name}.geoms[{k}]")[0]
            return out, "float"
        if gt == "Polygon":
            if obj.is_empty:
                raise EmptyGeometryError(f"{name}: empty Polygon", argument=name)
            if len(obj.interiors):
                return _triangulate(obj, name), "float"
    data, _, path = read(obj, name, numbers="core")
    kind = "int" if path == "i" else "float"
    idx, _, code, v = (core.normalize_i if path == "i" else core.normalize_f)(data)
    if code == D.Status.OK:
        return [np.ascontiguousarray(data[idx])], kind
    if code not in _NOT_CONVEX:
        D.raise_status(code, v, name, data)
    import shapely

    if kind == "int" and not ints_fit_float64(data):
        raise ShapeError(
            f"{name}: the coordinates of a non-convex polygon (triangulated in float64) "
            + _NOT_F64,
            argument=name,
            hint="scale the polygon down",
        )
    pieces = _triangulate(shapely.Polygon(data.astype(np.float64)), name)
    if kind == "int":
        pieces = [p.astype(np.int64) for p in pieces]
    return pieces, kind


def _as_kind(arrs: list[np.ndarray], kind: str, name: str) -> list[np.ndarray]:
    if kind == "int":
        return [np.ascontiguousarray(a, dtype=np.int64) for a in arrs]
    out = []
    for a in arrs:
        if a.dtype == np.int64 and not ints_fit_float64(a):
            raise ShapeError(
                f"{name}: ints next to floats {_NOT_F64}",
                argument=name,
                hint="pass all coordinates as ints, or scale down",
            )
        out.append(np.ascontiguousarray(a, dtype=np.float64))
    return out


def _is_box(workspace: Any) -> bool:
    if is_shapely(workspace) or isinstance(workspace, (str, bytes)):
        return False
    try:
        a = np.asarray(workspace, dtype=object)
    except Exception:  # noqa: BLE001
        return False
    return a.shape == (4,)


def _scalar(v: Any, name: str) -> int | float:
    if isinstance(v, (bool, np.bool_)):
        raise ShapeError(f"{name}: a coordinate must be a number, got a bool", argument=name)
    if isinstance(v, (int, np.integer)):
        return int(v)
    if isinstance(v, (float, np.floating)):
        f = float(v)
        if not math.isfinite(f):
            raise nonfinite(name, where=f"the value {f!r}")
        return f
    if isinstance(v, Fraction):
        f = float(v)
        if Fraction(f) != v:
            raise ShapeError(
                f"{name}: {v} is not a float64 value", argument=name, hint="pass floats"
            )
        return f
    raise ShapeError(f"{name}: a coordinate must be a number, got {type(v).__name__}")


def _point(p: Any, name: str) -> tuple[Any, Any]:
    if is_shapely(p):
        if p.geom_type != "Point":
            raise ShapeError(f"{name}: expected a point, got a {p.geom_type}", argument=name)
        if p.is_empty:
            raise EmptyGeometryError(f"{name}: an empty Point", argument=name)
        return (_scalar(p.x, name), _scalar(p.y, name))
    try:
        seq = list(p)
    except TypeError:
        raise ShapeError(f"{name}: expected a point (x, y)", argument=name) from None
    if len(seq) != 2:
        raise ShapeError(f"{name}: expected a point (x, y), got {len(seq)} values", argument=name)
    return (_scalar(seq[0], name), _scalar(seq[1], name))


def _fmt(v: Any) -> str:
    return repr(v.item() if hasattr(v, "item") else v)


def _workspace_groups(wpieces: list, rpieces: list) -> list[int]:
    """The group (counted from the workspace's first, ``n_obstacles``) of each pair
    (outside piece, robot piece), in the order the pairs are built.

    A robot with area meets the outside of the workspace exactly when its reference
    point is in the open interior of one pair's sum: every pair is its own group, so
    that a corridor of the workspace exactly as wide as the robot stays open (the union
    of one group's pieces would close it). A point or a segment robot could also slip
    along a seam between two outside triangles (a point along any seam, a segment along
    one parallel to it): triangles sharing such an edge form one group, whose union it
    must avoid (seams blocking)."""
    nr = len(rpieces)
    if any(len(r) >= 3 for r in rpieces):
        return list(range(len(wpieces) * nr))
    F = Fraction
    d = None  # the segment robot's direction (exact); None for a point robot
    if len(rpieces[0]) == 2:
        (x0, y0), (x1, y1) = rpieces[0].tolist()
        d = (F(x1) - F(x0), F(y1) - F(y0))
    parent = list(range(len(wpieces)))

    def find(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    edges: dict = {}
    for i, t in enumerate(wpieces):
        pts = [tuple(v) for v in t.tolist()]
        for a, b in zip(pts, pts[1:] + pts[:1]):
            j = edges.pop((b, a), None)  # the same edge the other way round: shared
            if j is None:
                edges[(a, b)] = i
                continue
            e = (F(b[0]) - F(a[0]), F(b[1]) - F(a[1]))
            if d is None or e[0] * d[1] == e[1] * d[0]:
                parent[find(i)] = find(j)
    return [find(i) for i in range(len(wpieces)) for _ in range(nr)]


def _union_shapes(pieces: list) -> Any:
    """Union of convex pieces (arrays of 1, 2 or more vertices) for display: the areas by
    the core's exact overlay, points and segments beside them."""
    import shapely

    from .._engine.overlay import overlay

    arrs = [np.asarray(p, dtype=np.float64) for p in pieces]
    area = overlay([a for a in arrs if len(a) >= 3])
    low = [
        shapely.LineString(a) if len(a) == 2 else shapely.Point(a[0]) for a in arrs if len(a) < 3
    ]
    if not low:
        return area
    return shapely.GeometryCollection([*shapely.get_parts(area), *low])


def _ring_coords(workspace: Any) -> np.ndarray:
    return np.asarray(read(workspace, "workspace", numbers="core").data, dtype=np.float64)


def _occupancy(occupancy: Any) -> np.ndarray:
    """An (H, W) bool array from an array-like of bools or numbers (nonzero: blocked)."""
    try:
        a = np.asarray(occupancy)
    except Exception:  # noqa: BLE001 - foreign errors become ours
        raise ShapeError(
            "occupancy: expected an (H, W) array of bool", argument="occupancy"
        ) from None
    if a.ndim != 2 or a.shape[0] == 0 or a.shape[1] == 0:
        raise ShapeError(
            f"occupancy: expected an (H, W) array with H, W >= 1, got shape {a.shape}",
            argument="occupancy",
        )
    if a.dtype == bool:
        return a
    if a.dtype.kind not in "iuf":
        raise ShapeError(
            f"occupancy: expected bools or numbers, got dtype {a.dtype}", argument="occupancy"
        )
    if a.dtype.kind == "f" and not np.isfinite(a).all():
        raise NonFiniteError("occupancy: NaN or infinite values", argument="occupancy")
    return a != 0


def _grid_scalar(v: Any, name: str) -> int | float:
    if isinstance(v, (bool, np.bool_)) or not isinstance(
        v, (int, float, Fraction, np.integer, np.floating)
    ):
        raise OptionError(
            f"{name}: must be a positive number, got {v!r}", argument=name, allowed="> 0"
        )
    return _scalar(v, name)


def _grid_rectangles(occ: np.ndarray) -> list[tuple[int, int, int, int]]:
    """Blocked cells merged into rectangles (r0, c0, r1, c1), half-open: runs along each
    row, a run continued upwards while the next row has the same run."""
    H, W = occ.shape
    pad = np.zeros((H, W + 2), dtype=np.int8)
    pad[:, 1:-1] = occ
    d = np.diff(pad, axis=1)
    out: list[tuple[int, int, int, int]] = []
    open_: dict[tuple[int, int], int] = {}  # run (c0, c1) -> first row
    for r in range(H + 1):
        if r < H:
            starts = np.flatnonzero(d[r] == 1)
            ends = np.flatnonzero(d[r] == -1)
            runs = set(zip(starts.tolist(), ends.tolist()))
        else:
            runs = set()
        for run in [k for k in open_ if k not in runs]:
            out.append((open_.pop(run), run[0], r, run[1]))
        for run in runs:
            open_.setdefault(run, r)
    return out
