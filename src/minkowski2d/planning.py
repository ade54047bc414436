"""Translational motion planning: exact shortest paths for a polygonal robot among
polygonal obstacles.

Every obstacle ``O`` is inflated by the reflected robot into its configuration-space
obstacle ``O ⊕ (−R)`` (pieces ``O_i ⊕ (−R_j)`` of convex pieces when either is not
convex); the robot's reference point must stay out of the *open* interior of each of
them and, with a workspace ``W``, inside ``W ⊖ R``. Touching is allowed: a passage
exactly as wide as the robot is open, and two C-obstacles that meet at one point leave
the gaps beside it open. The seams between the convex pieces of one obstacle are not
passages.

The compiled core (:mod:`minkowski2d._core`, ``planning.hpp``) builds a reduced
visibility graph directly on the overlapping convex pieces (no union, no mesh: both
would close zero-width passages): bend points are piece vertices outside every
C-obstacle's open interior, edges are the mutually visible pairs whose segment is tangent
at both ends, and every visibility and containment decision is an exact sign. Queries
connect the start and the goal by the same exact visibility and run A*. See
``docs/planning.md``.

Examples
--------
>>> import minkowski2d as mk
>>> planner = mk.MotionPlanner([[(2, -1), (4, -1), (4, 3), (2, 3)]],
...                            robot=[(-1, -1), (1, -1), (1, 1), (-1, 1)])
>>> path = planner.shortest_path((0, 0), (6, 0))
>>> path.points.tolist()
[[0, 0], [1, -2], [5, -2], [6, 0]]
>>> round(path.length, 6)
8.472136
"""

from __future__ import annotations

import math
from collections import OrderedDict
from fractions import Fraction
from typing import Any, NamedTuple

import numpy as np

from ._engine import core
from ._engine import dispatch as D
from ._engine import options as _options
from ._engine.coerce import is_shapely
from ._engine.foreign import foreign_errors
from .errors import (
    EmptyGeometryError,
    GeometryError,
    NonFiniteError,
    NoPathError,
    OptionError,
    OverflowGeometryError,
    ShapeError,
)

__all__ = ["MotionPlanner", "Path", "NavMesh"]

_NOT_CONVEX = (D.Status.TURNS_BOTH_WAYS, D.Status.SPIKE, D.Status.WINDS_TWICE)
_F53 = core.FLOAT_EXACT_INT
_INT_LIMIT = core.INT_LIMIT
METHODS = ("auto", "mesh", "visibility")
_MESH_MIN_PIECES = 64  # "auto": smaller scenes keep the visibility graph (as fast there)
_MESH_RANGE = 2.0**500
_ROBOT_CACHE = 8  # planners kept for other robots (least recently used dropped)


# --------------------------------------------------------------------------------------
# results


class Path:
    """A collision-free path of the robot's reference point.

    Attributes
    ----------
    points : (k, 2) ndarray
        The start, the bend points (C-obstacle vertices) and the goal, in order; int64 when
        the scene and the query are integers (bend points exact), else float64. ``k`` is 1
        when start and goal coincide.
    length : float
        Euclidean length: each segment's exact length correctly rounded to float64,
        summed with fsum. A length beyond float64 raises
        :class:`~minkowski2d.errors.OverflowGeometryError` (never ``inf``); the points
        are valid all the same.

    Examples
    --------
    >>> import numpy as np
    >>> p = Path(np.array([[0, 0], [3, 4]]))
    >>> p.length, len(p)
    (5.0, 2)
    """

    __slots__ = ("points", "_length")

    def __init__(self, points: np.ndarray) -> None:
        self.points = points
        self._length: float | None = None

    @property
    def length(self) -> float:
        if self._length is None:
            pts = self.points.tolist()
            try:
                self._length = math.fsum(_segment_length(a, b) for a, b in zip(pts, pts[1:]))
            except OverflowError:
                raise OverflowGeometryError(
                    "length: the path is longer than float64 can hold (1.8e308)",
                    argument="length",
                    hint="the path itself is valid; scale the scene down to measure it",
                ) from None
        return self._length

    def __len__(self) -> int:
        return len(self.points)

    def __repr__(self) -> str:
        return f"Path({len(self.points)} points, length={self.length!r})"

    def _plot_(self, ax: Any, **kwargs: Any) -> Any:
        return self.plot(ax, **kwargs)

    def plot(self, ax: Any = None, **kwargs: Any) -> Any:
        """Draw the path with matplotlib (imported only here); returns the axes.

        Examples
        --------
        >>> import numpy as np
        >>> ax = Path(np.array([[0, 0], [1, 1]])).plot()  # doctest: +SKIP
        """
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots()
            ax.set_aspect("equal")
        kw = {"color": "tab:blue", "lw": 2, "marker": "o", "ms": 3}
        kw.update(kwargs)
        pts = self.points.astype(np.float64)
        ax.plot(pts[:, 0], pts[:, 1], **kw)
        return ax


def _segment_length(a: Any, b: Any) -> float:
    """|b - a| correctly rounded to float64 (exact arithmetic on the ints or floats);
    OverflowError beyond float64."""
    dx = Fraction(b[0]) - Fraction(a[0])
    dy = Fraction(b[1]) - Fraction(a[1])
    if dx.denominator == 1 and dy.denominator == 1 and abs(dx) < _F26 and abs(dy) < _F26:
        return math.sqrt(int(dx) ** 2 + int(dy) ** 2)  # exact square: one rounding
    q = dx * dx + dy * dy  # the exact square of the length
    num, den = q.numerator, q.denominator
    # r = floor(sqrt(q) * 2**k) with at least 55 bits; sqrt(q) in [r, r + 1) / 2**k: a
    # value strictly inside rounds like sqrt(q) (no float64 rounding boundary is there)
    k = max(0, (110 - (num.bit_length() - den.bit_length())) // 2 + 1)
    m = (num << (2 * k)) // den
    r = math.isqrt(m)
    if r * r == m and (num << (2 * k)) % den == 0:
        return float(Fraction(r, 1 << k))
    return float(Fraction(2 * r + 1, 1 << (k + 1)))


_F26 = 1 << 26


# --------------------------------------------------------------------------------------
# input


def _triangulate(poly: Any, name: str) -> list[np.ndarray]:
    """Convex pieces (triangles) of a shapely polygon with holes: the core's exact
    triangulation (every decision an exact sign, every triangle vertex an input vertex,
    bit for bit, each triangle counter-clockwise); an invalid polygon raises
    SelfIntersectionError naming the ring and vertex."""
    from ._engine.polygon import rings_of, triangulate

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
                raise ShapeError(f"{name}: empty polygon", argument=name)
            if len(obj.interiors):
                return _triangulate(obj, name), "float"
            import shapely

            obj = shapely.get_coordinates(obj.exterior)[:-1]
    data, out_kind, path = D.one(obj, name)
    if path == "py":
        raise ShapeError(
            f"{name}: the planner takes int64 (|x| < 2**62) or float64 coordinates",
            argument=name,
            hint="scale the scene or pass floats",
        )
    kind = "int" if path == "i" else "float"
    idx, _, code, v = (core.normalize_i if path == "i" else core.normalize_f)(data)
    if code == D.Status.OK:
        return [np.ascontiguousarray(data[idx])], kind
    if code not in _NOT_CONVEX:
        D.raise_status(code, v, name, data)
    import shapely

    if kind == "int" and np.abs(data).max() > _F53:
        raise ShapeError(
            f"{name}: a non-convex polygon needs |x| <= 2**53",
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
        if a.dtype == np.int64 and a.size and int(np.abs(a).max()) > _F53:
            raise ShapeError(
                f"{name}: ints beyond 2**53 next to floats cannot be converted exactly",
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
            raise NonFiniteError(
                f"{name}: a coordinate is not finite ({f!r})",
                argument=name,
                hint="remove NaN and infinite values",
            )
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


# --------------------------------------------------------------------------------------
# the planner


class MotionPlanner:
    """Exact shortest paths for a translating polygonal robot among polygonal obstacles.

    Parameters
    ----------
    obstacles : sequence of polygons, shapely (Multi)Polygon, GeoSeries
        Convex or simple polygons (shapely polygons may have holes): (n, 2) array-likes of
        int or float, or shapely geometries. A MultiPolygon is one obstacle.
    robot : polygon, optional
        Convex or simple polygon in its own frame; its reference point is the origin.
        ``None``: the robot is a point.
    workspace : (xmin, ymin, xmax, ymax) or polygon, optional
        The region the *whole robot* must stay inside (the reference point stays in
        ``workspace ⊖ robot``). ``None``: unbounded.
    threads : int, default 1
        Threads for building the visibility graph (the GIL is released).

    Notes
    -----
    A path is valid iff no point of it lies in the open interior of a C-obstacle
    ``O ⊕ (−R)`` (touching is allowed) and every point lies in ``workspace ⊖ robot``.
    Obstacles with no area (points, segments) block a point robot nowhere.

    Integer scenes (|x| < 2**62 after inflation) are planned in int64: bend points are
    exact C-obstacle vertices. Float scenes use the correctly rounded C-obstacle vertices;
    every decision on them is exact. Path lengths are floats: two paths whose lengths
    differ only by rounding may be chosen either way.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> L = [(1, -2), (3, -2), (3, 2), (2, 2), (2, -1), (1, -1)]   # an L-shaped obstacle
    >>> planner = mk.MotionPlanner([L], workspace=(-5, -5, 5, 5))
    >>> planner.shortest_path((0, 0), (4, 0)).points.tolist()
    [[0, 0], [2, 2], [3, 2], [4, 0]]
    >>> planner.is_free([(0, 0), (1.5, -1.5), (2, 0)]).tolist()
    [True, False, True]
    """

    def __init__(
        self,
        obstacles: Any,
        robot: Any = None,
        *,
        workspace: Any = None,
        threads: int = 1,
        method: str = "auto",
    ) -> None:
        self.threads = _options.threads(threads)
        self.method = _options.choice(method, "method", METHODS)
        obs = self._read_obstacles(obstacles)
        kinds = set()
        opieces: list[list[np.ndarray]] = []
        for k, o in enumerate(obs):
            with foreign_errors(f"obstacles[{k}]", "triangulating the polygon", magnitude=True):
                pcs, kind = _pieces(o, f"obstacles[{k}]")
            opieces.append(pcs)
            kinds.add(kind)
        self._obstacles = obs
        self._setup(opieces, kinds, robot, workspace)

    def _setup(self, opieces: list, okinds: set, robot: Any, workspace: Any) -> None:
        """Everything after the obstacles' pieces: the robot, the workspace, the
        C-obstacle pieces and the core (shared by the constructor, :meth:`from_grid` and
        the planners for other robots)."""
        self._raw = (opieces, set(okinds), workspace)
        self._robots: OrderedDict = OrderedDict()
        kinds = set(okinds)
        obs = self._obstacles
        if robot is None:
            rpieces, rkind = [np.zeros((1, 2), np.int64)], "int"
        else:
            with foreign_errors("robot", "triangulating the polygon", magnitude=True):
                rpieces, rkind = _pieces(robot, "robot")
            kinds.add(rkind)
        self._ws_kind = None
        wpieces: list[np.ndarray] = []
        box = None
        if workspace is not None:
            if _is_box(workspace):
                vals = [_scalar(v, "workspace") for v in workspace]
                kinds.add("float" if any(isinstance(v, float) for v in vals) else "int")
                if not (vals[0] <= vals[2] and vals[1] <= vals[3]):
                    raise ShapeError(
                        "workspace: expected (xmin, ymin, xmax, ymax) with xmin <= xmax "
                        "and ymin <= ymax",
                        argument="workspace",
                    )
                box = vals
            else:
                with foreign_errors("workspace", "triangulating the polygon", magnitude=True):
                    wp, wkind = _pieces(workspace, "workspace")
                kinds.add(wkind)
                allw = np.concatenate(wp)
                if len(wp) == 1 and len(wp[0]) < 3:
                    raise ShapeError(
                        f"workspace: a polygon workspace needs an area, got {len(wp[0])} "
                        "distinct point(s)",
                        argument="workspace",
                        hint="give (xmin, ymin, xmax, ymax) or a polygon with three or more "
                        "vertices",
                    )
                rect = self._rectangle(workspace, allw, len(wp))
                if rect is not None:
                    box = rect
                else:
                    with foreign_errors("workspace", "triangulating the polygon", magnitude=True):
                        wpieces = self._ring(workspace, allw, wkind)
        kind = "float" if "float" in kinds else "int"
        self.kind = kind
        opieces = [_as_kind(p, kind, f"obstacles[{k}]") for k, p in enumerate(opieces)]
        rpieces = _as_kind(rpieces, kind, "robot")
        wpieces = _as_kind(wpieces, kind, "workspace")
        self._robot_pieces = rpieces
        self._obstacle_pieces = opieces
        self.n_obstacles = len(obs)
        neg = [np.ascontiguousarray(-r) for r in rpieces]
        wgroup = _workspace_groups(wpieces, rpieces)
        As, Bs, groups = [], [], []
        for g, pcs in enumerate([*opieces, wpieces]):
            ws = g == len(opieces)
            k = 0
            for a in pcs:
                for b in neg:
                    As.append(a)
                    Bs.append(b)
                    groups.append(g + wgroup[k] if ws else g)
                    k += 1
        from .batch import Ragged, minkowski_sum_many

        if As:
            sums = minkowski_sum_many(As, Bs)
            coords = sums.coords
            offs = sums.offsets
        else:
            coords = np.zeros((0, 2), np.int64 if kind == "int" else np.float64)
            offs = np.zeros(1, np.int64)
        if kind == "int":
            if coords.dtype != np.int64 or (
                coords.size and int(np.abs(coords).max()) >= _INT_LIMIT
            ):
                raise ShapeError(
                    "obstacles: C-obstacle coordinates reach 2**62",
                    argument="obstacles",
                    hint="scale the scene down",
                )
        coords = np.ascontiguousarray(coords, np.int64 if kind == "int" else np.float64)
        self.pieces = Ragged(coords, offs)
        self.groups = np.asarray(groups, dtype=np.int64)
        # the reference point's box
        rall = np.concatenate(rpieces)
        if box is not None:
            rb = [rall[:, 0].min(), rall[:, 1].min(), rall[:, 0].max(), rall[:, 1].max()]
            box = [box[0] - rb[0], box[1] - rb[1], box[2] - rb[2], box[3] - rb[3]]
            box = [int(v) if kind == "int" else float(v) for v in box]
        elif self._frame is not None:
            rb = [rall[:, 0].min(), rall[:, 1].min(), rall[:, 0].max(), rall[:, 1].max()]
            f = self._frame
            box = [f[0] - rb[0], f[1] - rb[1], f[2] - rb[2], f[3] - rb[3]]
            box = [int(v) if kind == "int" else float(v) for v in box]
        self.box = box
        self._core = self._make_core(kind)
        self._twin: Any = None

    _frame: Any = None

    @classmethod
    def from_scene(cls, scene: Any, name: str = "scene") -> MotionPlanner:
        """A planner from a scene mapping (the CLI's scene file, parsed).

        Two layouts are accepted:

        * ``{"obstacles": [...], "robot": ..., "workspace": ...}``: each obstacle (and the
          robot, and a polygon workspace) is a list of ``[x, y]`` pairs or a GeoJSON
          geometry object; ``robot`` missing or null is a point; ``workspace`` missing or
          null is unbounded, ``[xmin, ymin, xmax, ymax]`` is a box.
        * a GeoJSON FeatureCollection whose features carry ``"role"`` in their properties:
          ``"obstacle"`` (the default), ``"robot"`` or ``"workspace"``.

        JSON integers stay integers (exact int planning); any float makes a float scene.

        Examples
        --------
        >>> scene = {"robot": [[-1, -1], [1, -1], [1, 1], [-1, 1]],
        ...          "obstacles": [[[2, -1], [4, -1], [4, 3], [2, 3]]],
        ...          "workspace": [-10, -10, 10, 10]}
        >>> MotionPlanner.from_scene(scene).shortest_path((0, 0), (6, 0)).points.tolist()
        [[0, 0], [1, -2], [5, -2], [6, 0]]
        """

        def geom(obj: Any, what: str) -> Any:
            if obj is None:
                return None
            if isinstance(obj, dict):
                import shapely.geometry

                try:
                    return shapely.geometry.shape(obj)
                except Exception as exc:  # noqa: BLE001 - foreign errors become ours
                    raise ShapeError(
                        f"{name}: {what} is not a GeoJSON geometry ({exc})", argument=name
                    ) from None
            return obj

        if not isinstance(scene, dict):
            raise ShapeError(f"{name}: a scene must be a JSON object", argument=name)
        if scene.get("type") == "FeatureCollection":
            obstacles, robot, workspace = [], None, None
            feats = scene.get("features", [])
            if not isinstance(feats, list):
                raise ShapeError(
                    f"{name}: 'features' must be a list, got {type(feats).__name__}",
                    argument=name,
                )
            for k, feat in enumerate(feats):
                if not isinstance(feat, dict) or not isinstance(feat.get("properties") or {}, dict):
                    raise ShapeError(
                        f"{name}: features[{k}] is not a GeoJSON Feature object",
                        argument=name,
                        hint='a feature is {"type": "Feature", "geometry": ..., "properties": '
                        '{"role": ...}}',
                    )
                role = (feat.get("properties") or {}).get("role", "obstacle")
                g = geom(feat.get("geometry"), f"features[{k}]")
                if role == "robot":
                    robot = g
                elif role == "workspace":
                    workspace = g
                elif role == "obstacle":
                    obstacles.append(g)
                else:
                    raise ShapeError(
                        f"{name}: features[{k}] has an unknown role {role!r}",
                        argument=name,
                        hint="use obstacle, robot or workspace",
                    )
        else:
            unknown = set(scene) - {"obstacles", "robot", "workspace"}
            if unknown:
                raise ShapeError(
                    f"{name}: unknown scene keys {sorted(unknown)}",
                    argument=name,
                    hint="a scene has obstacles, robot and workspace",
                )
            obs = scene.get("obstacles", [])
            if not isinstance(obs, list):
                raise ShapeError(f"{name}: obstacles must be a list", argument=name)
            obstacles = [geom(o, f"obstacles[{k}]") for k, o in enumerate(obs)]
            robot = geom(scene.get("robot"), "robot")
            workspace = geom(scene.get("workspace"), "workspace")
        return cls(obstacles, robot, workspace=workspace)

    # ------------------------------------------------------------------ construction
    @staticmethod
    def _read_obstacles(obstacles: Any) -> list:
        if obstacles is None:
            return []
        if is_shapely(obstacles):
            if obstacles.geom_type in ("MultiPolygon", "GeometryCollection"):
                return list(obstacles.geoms)
            return [obstacles]
        if hasattr(obstacles, "geometry") and hasattr(obstacles, "values"):  # GeoSeries/-Frame
            obstacles = obstacles.geometry
            return [g for g in obstacles.values if g is not None and not g.is_empty]
        if isinstance(obstacles, np.ndarray) and obstacles.dtype != object:
            if obstacles.ndim == 3:
                return list(obstacles)
            raise ShapeError(
                "obstacles: expected a sequence of polygons",
                argument="obstacles",
                hint="wrap a single polygon in a list: [polygon]",
            )
        try:
            obs = list(obstacles)
        except TypeError:
            raise ShapeError(
                f"obstacles: expected a sequence of polygons, got {type(obstacles).__name__}",
                argument="obstacles",
            ) from None
        if obs and isinstance(obs[0], (tuple, list)) and len(obs[0]) == 2:
            first = obs[0]
            if all(isinstance(v, (int, float, np.number, Fraction)) for v in first):
                raise ShapeError(
                    "obstacles: expected a sequence of polygons, got a sequence of points",
                    argument="obstacles",
                    hint="wrap a single polygon in a list: [polygon]",
                )
        return obs

    @staticmethod
    def _rectangle(workspace: Any, allw: np.ndarray, npieces: int) -> list | None:
        if npieces != 1:
            return None
        if len(allw) != 4:
            return None
        xs = sorted(set(allw[:, 0].tolist()))
        ys = sorted(set(allw[:, 1].tolist()))
        if len(xs) != 2 or len(ys) != 2:
            return None
        return [xs[0], ys[0], xs[1], ys[1]]

    def _ring(self, workspace: Any, allw: np.ndarray, wkind: str) -> list[np.ndarray]:
        """Convex pieces of (frame minus workspace): the workspace's outside as one
        obstacle group, inside a frame box strictly around it."""
        import shapely

        x0, y0 = allw[:, 0].min().item(), allw[:, 1].min().item()
        x1, y1 = allw[:, 0].max().item(), allw[:, 1].max().item()
        m = max(x1 - x0, y1 - y0, 1)  # Python numbers: an overflow is inf, checked below
        if wkind == "int":
            m = int(m)
            f = [int(x0) - m, int(y0) - m, int(x1) + m, int(y1) + m]
        else:
            m = float(m)
            f = [float(x0) - m, float(y0) - m, float(x1) + m, float(y1) + m]
            if not all(math.isfinite(v) for v in f):
                raise OverflowGeometryError(
                    "workspace: the frame around the workspace polygon overflows float64",
                    argument="workspace",
                    hint="scale the scene down (or use a box workspace)",
                )
        self._frame = f
        if is_shapely(workspace):
            inner = workspace
        else:
            inner = shapely.Polygon(_ring_coords(workspace))
        if inner.geom_type in ("Polygon", "MultiPolygon") and not inner.is_empty:
            from ._engine.polygon import check, rings_of

            check(rings_of(inner), "workspace", _SIMPLE_HINT, what="not a simple polygon")
        holes = [inner.exterior] if inner.geom_type == "Polygon" else []
        frame = shapely.Polygon(
            [(f[0], f[1]), (f[2], f[1]), (f[2], f[3]), (f[0], f[3])],
            holes=holes,
        )
        pieces = _triangulate(frame, "workspace")
        if inner.geom_type == "Polygon":
            # holes of the workspace are obstacles too
            for h in inner.interiors:
                pieces += _triangulate(shapely.Polygon(h), "workspace")
        if wkind == "int":
            pieces = [p.astype(np.int64) for p in pieces]
        return pieces

    def _make_core(self, kind: str) -> Any:
        self._mesh_box: Any = None
        if self.method != "visibility":
            planner = self._make_mesh(kind)
            if planner is not None:
                return planner
        return self._make_graph(kind)

    def _solid(self, dt: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The pieces with area (points and segments block nothing), their offsets and
        groups, as the cores take them."""
        coords = self.pieces.coords
        offs = self.pieces.offsets
        n = np.diff(offs)
        solid = n >= 3
        keep = np.repeat(solid, n)
        c = np.ascontiguousarray(coords[keep], dt)
        o = np.concatenate([[0], np.cumsum(n[solid])]).astype(np.int64)
        g = np.ascontiguousarray(self.groups[solid], np.int64)
        return c, o, g

    def _make_mesh(self, kind: str, cover: Any = None) -> Any:
        """The navigation-mesh core, or None where the visibility graph must plan (with
        ``method="mesh"``: an OptionError saying why)."""
        why = self._mesh_refused(kind)
        c = o = g = None
        if why is None:
            c, o, g = self._solid(np.float64)
            if self.method == "auto" and len(o) - 1 < _MESH_MIN_PIECES:
                return None
            box = self.box
            if box is not None:
                mb = [float(v) for v in box]
            else:
                pts = c if cover is None else np.concatenate([c, np.asarray(cover, np.float64)])
                if len(pts) == 0:
                    pts = np.zeros((1, 2))
                lo, hi = pts.min(axis=0), pts.max(axis=0)
                m = max(float((hi - lo).max()), 1.0)
                mb = [float(lo[0]) - m, float(lo[1]) - m, float(hi[0]) + m, float(hi[1]) + m]
                if not all(math.isfinite(v) and abs(v) < _MESH_RANGE for v in mb):
                    why = "the scene's magnitude is beyond the mesh's range (2**500)"
        if why is None:
            planner = core.MeshPlannerF()
            st = planner.build(
                c,
                o,
                g,
                np.asarray(self.box if self.box is not None else [], dtype=np.float64),
                self._frame is not None,
                np.asarray(mb, dtype=np.float64),
            )
            if st == core.MESH_OK:
                self._mesh_box = mb
                return planner
            why = {
                core.MESH_INEXACT: "a crossing of two C-obstacle edges on the free space's "
                "boundary is not a float64 value",
                core.MESH_ZERO_WIDTH: "the free space has zero-width passages (obstacles, or "
                "an obstacle and the workspace box, touching along an edge)",
            }.get(st, "the mesh could not be built")
        if self.method == "mesh":
            raise OptionError(
                f"method: 'mesh' cannot plan this scene: {why}",
                argument="method",
                allowed="'auto' or 'visibility' for this scene",
                hint="use method='auto' (it falls back to the visibility graph)",
            )
        return None

    def _mesh_refused(self, kind: str) -> str | None:
        """Why the mesh cannot take these numbers (None: it can)."""
        coords = self.pieces.coords
        vals = [np.abs(coords).max()] if coords.size else []
        if self.box is not None:
            vals += [abs(v) for v in self.box]
        big = max((float(v) for v in vals), default=0.0)
        if kind == "int" and big > _F53:
            return "int coordinates beyond 2**53"
        if big >= _MESH_RANGE:
            return "coordinates beyond 2**500"
        return None

    def _make_graph(self, kind: str) -> Any:
        coords = self.pieces.coords
        offs = self.pieces.offsets
        n = np.diff(offs)
        solid = n >= 3
        keep = np.repeat(solid, n)
        c = np.ascontiguousarray(coords[keep], np.int64 if kind == "int" else np.float64)
        o = np.concatenate([[0], np.cumsum(n[solid])]).astype(np.int64)
        g = np.ascontiguousarray(self.groups[solid], np.int64)
        dt = np.int64 if kind == "int" else np.float64
        box = np.asarray(self.box if self.box is not None else [], dtype=dt)
        planner = (core.PlannerI if kind == "int" else core.PlannerF)()
        # a polygon workspace's frame lies strictly outside workspace ⊖ robot: the box of
        # the reference point is then open (no point on the frame is valid)
        planner.build(c, o, g, np.ascontiguousarray(box), self.threads, self._frame is not None)
        return planner

    def _float_twin(self) -> Any:
        """The same planner on float64 coordinates (for float queries on an int scene)."""
        if self._twin is None:
            if self.pieces.coords.size and int(np.abs(self.pieces.coords).max()) > _F53:
                raise ShapeError(
                    "start: float queries on an int scene need |x| <= 2**53",
                    argument="start",
                    hint="pass int coordinates",
                )
            if self.box is not None and max(abs(v) for v in self.box) > _F53:
                raise ShapeError("start: the workspace needs |x| <= 2**53 for float queries")
            twin = object.__new__(MotionPlanner)
            twin.__dict__.update(self.__dict__)
            twin.pieces = type(self.pieces)(
                self.pieces.coords.astype(np.float64), self.pieces.offsets
            )
            twin.box = None if self.box is None else [float(v) for v in self.box]
            twin.kind = "float"
            twin._core = twin._make_core("float")
            self._twin = twin
        return self._twin

    # ------------------------------------------------------------------ other robots
    def _for_robot(self, robot: Any) -> MotionPlanner:
        """The planner for ``robot`` on the same obstacles, workspace and options (built
        once; the last ``_ROBOT_CACHE`` are kept, least recently used dropped)."""
        with foreign_errors("robot", "triangulating the polygon", magnitude=True):
            pieces, kind = _pieces(robot, "robot")
        key = (kind, tuple((p.dtype.str, p.shape, p.tobytes()) for p in pieces))
        pl = self._robots.get(key)
        if pl is not None:
            self._robots.move_to_end(key)
            return pl
        pl = object.__new__(type(self))
        pl.threads = self.threads
        pl.method = self.method
        pl._obstacles = self._obstacles
        pl._grid_box = self._grid_box
        opieces, okinds, workspace = self._raw
        pl._setup(opieces, okinds, robot, workspace)
        self._robots[key] = pl
        while len(self._robots) > _ROBOT_CACHE:
            self._robots.popitem(last=False)
        return pl

    # ------------------------------------------------------------------ grids
    _grid_box: Any = None

    @classmethod
    def from_grid(
        cls,
        occupancy: Any,
        *,
        cell_size: Any = 1,
        origin: Any = (0, 0),
        robot: Any = None,
        threads: int = 1,
        method: str = "auto",
    ) -> MotionPlanner:
        """A planner on an occupancy grid: ``occupancy[r, c]`` true where the cell is
        blocked.

        Cell ``(r, c)`` is the square ``[x0 + c s, x0 + (c + 1) s] × [y0 + r s,
        y0 + (r + 1) s]`` with ``(x0, y0) = origin`` and ``s = cell_size``: column is x,
        row is y, as in the Moving AI benchmarks' coordinates
        (:func:`minkowski2d.io.read_grid_map`). The blocked cells are merged into
        rectangles and, with the grid's outside, form one obstacle (``obstacles[0]``):
        the seams between cells block, so no path slips between two blocked cells that
        share an edge or along the grid's border; a path may pass where two blocked cells
        touch only at a corner (the free space is closed). The whole robot stays inside
        the grid; a point outside it is "outside the workspace".

        Parameters
        ----------
        occupancy : (H, W) array-like of bool
            True (or nonzero) for a blocked cell.
        cell_size : int or float, default 1
            Side of a cell (> 0). Ints (with an int origin) keep the planning exact in
            int64.
        origin : (x, y), default (0, 0)
            The corner of cell (0, 0).
        robot, threads, method
            As for :class:`MotionPlanner`.

        Examples
        --------
        >>> import numpy as np
        >>> import minkowski2d as mk
        >>> grid = np.array([[0, 0, 0, 0],
        ...                  [0, 1, 1, 0],
        ...                  [0, 0, 0, 0]], dtype=bool)
        >>> pl = mk.MotionPlanner.from_grid(grid)
        >>> pl.shortest_path((0, 0), (4, 2)).points.tolist()
        [[0, 0], [3, 1], [4, 2]]
        """
        occ = _occupancy(occupancy)
        s = _grid_scalar(cell_size, "cell_size")
        o = _point(origin, "origin")
        if not s > 0:
            raise OptionError(
                f"cell_size: must be > 0, got {_fmt(s)}", argument="cell_size", allowed="> 0"
            )
        H, W = occ.shape
        floats = any(isinstance(v, float) for v in (s, *o))
        xs = [o[0] + c * s for c in range(W + 1)]
        ys = [o[1] + r * s for r in range(H + 1)]
        if floats:
            xs, ys = [float(v) for v in xs], [float(v) for v in ys]
        x0, y0, x1, y1 = xs[0], ys[0], xs[-1], ys[-1]
        bx0, by0, bx1, by1 = x0 - s, y0 - s, x1 + s, y1 + s
        if floats and not all(math.isfinite(v) for v in (bx0, by0, bx1, by1)):
            raise OverflowGeometryError(
                "cell_size: the grid's extent overflows float64", argument="cell_size"
            )
        rects = [(xs[c0], ys[r0], xs[c1], ys[r1]) for r0, c0, r1, c1 in _grid_rectangles(occ)]
        rects += [(bx0, by0, x0, by1), (x1, by0, bx1, by1), (x0, by0, x1, y0), (x0, y1, x1, by1)]
        dt = np.float64 if floats else np.int64
        if not floats and max(abs(v) for v in (bx0, by0, bx1, by1)) >= _INT_LIMIT:
            raise ShapeError(
                "cell_size: the grid's coordinates reach 2**62",
                argument="cell_size",
                hint="use a smaller cell_size or origin",
            )
        pieces = [np.array([[a, b], [c, b], [c, d], [a, d]], dtype=dt) for a, b, c, d in rects]
        pl = object.__new__(cls)
        pl.threads = _options.threads(threads)
        pl.method = _options.choice(method, "method", METHODS)
        pl._obstacles = [occ]
        pl._grid_box = (x0, y0, x1, y1)
        pl._setup([pieces], {"float" if floats else "int"}, robot, None)
        return pl

    def _in_grid(self, pts: list[tuple]) -> np.ndarray:
        b = self._grid_box
        return np.array([b[0] <= p[0] <= b[2] and b[1] <= p[1] <= b[3] for p in pts], dtype=bool)

    def _check_grid(self, pts: list[tuple], names: list[str]) -> None:
        """A grid planner's queries must lie on the grid."""
        if self._grid_box is None:
            return
        for p, ok, name in zip(pts, self._in_grid(pts), names):
            if not ok:
                raise self._point_error(name, p, -2)

    # ------------------------------------------------------------------ naming
    def _group_name(self, g: int) -> str:
        return f"obstacles[{g}]" if g < self.n_obstacles else "workspace"

    def _point_error(self, which: str, p: tuple, grp: int) -> GeometryError:
        where = f"({_fmt(p[0])}, {_fmt(p[1])})"
        if grp == -2 or grp >= self.n_obstacles:
            e = GeometryError(
                f"{which}: {where} is outside the workspace (the robot does not fit there)",
                argument=which,
                hint="move it inside workspace ⊖ robot",
            )
            e.obstacle = None  # type: ignore[attr-defined]
            return e
        name = self._group_name(grp)
        e = GeometryError(
            f"{which}: {where} is in collision with {name} (inside its C-obstacle)",
            argument=which,
            hint="move it out of the C-obstacle; touching is allowed",
        )
        e.obstacle = grp  # type: ignore[attr-defined]
        return e

    # ------------------------------------------------------------------ queries
    def _graph_twin(self) -> Any:
        """The same planner on the visibility graph (for int queries beyond 2**53 on a
        meshed int scene: the mesh works on float64)."""
        if getattr(self, "_graph", None) is None:
            twin = object.__new__(MotionPlanner)
            twin.__dict__.update(self.__dict__)
            twin._twin = None
            twin._mesh_box = None
            twin._core = twin._make_graph(self.kind)
            self._graph = twin
        return self._graph

    def _route(self, pts: list[tuple]) -> tuple[Any, str]:
        """The core that takes these points exactly, and the output kind."""
        floats = any(isinstance(v, float) for p in pts for v in p)
        if self._mesh_box is not None:
            if any(isinstance(v, int) and abs(v) > _F53 for p in pts for v in p):
                if self.kind == "int" and not floats:
                    return self._graph_twin()._route(pts)
                raise ShapeError(
                    "start: ints beyond 2**53 next to floats cannot be converted exactly",
                    argument="start",
                )
            return self, "int" if self.kind == "int" and not floats else "float"
        if self.kind == "int" and not floats:
            if any(abs(v) >= _INT_LIMIT for p in pts for v in p):
                raise ShapeError(
                    "start: query coordinates must satisfy |x| < 2**62",
                    argument="start",
                )
            return self, "int"
        if self.kind == "int":
            if any(isinstance(v, int) and abs(v) > _F53 for p in pts for v in p):
                raise ShapeError("start: ints beyond 2**53 next to floats", argument="start")
            return self._float_twin(), "float"
        if any(isinstance(v, int) and abs(v) > _F53 for p in pts for v in p):
            raise ShapeError(
                "start: ints beyond 2**53 in a float scene cannot be converted exactly",
                argument="start",
            )
        return self, "float"

    def shortest_path(self, start: Any, goal: Any, *, robot: Any = None) -> Path:
        """The shortest valid path of the reference point from ``start`` to ``goal``.

        Parameters
        ----------
        start, goal : (x, y)
            Reference-point positions (ints, floats, or shapely Points).
        robot : polygon, optional
            Plan for this robot instead of the planner's own (``[(0, 0)]`` for a point).
            The answer is that of ``MotionPlanner(obstacles, robot, workspace=...)`` with
            the same options; the preparations for the last eight robots are kept.

        Returns
        -------
        Path
            ``points`` (k, 2): start first, goal last; bend points are C-obstacle vertices
            (exact ints for an int scene and int query); ``length``.

        Raises
        ------
        GeometryError
            The start or the goal is in collision (inside a C-obstacle's open interior, the
            message and the ``obstacle`` attribute say which) or outside the workspace.
        NoPathError
            The goal cannot be reached from the start.

        Examples
        --------
        >>> import minkowski2d as mk
        >>> walls = [[(-1, 1), (3, 1), (3, 2), (-1, 2)], [(-1, -1), (3, -1), (3, 1), (-1, 1)]]
        >>> mk.MotionPlanner(walls).shortest_path((-2, 1), (4, 1)).points.tolist()
        [[-2, 1], [4, 1]]
        >>> square = [(0, 0), (1, 0), (1, 1), (0, 1)]
        >>> mk.MotionPlanner(walls).shortest_path((-3, 1), (4, 1), robot=square).points.tolist()
        [[-3, 1], [-2, 2], [3, 2], [4, 1]]
        """
        if robot is not None:
            return self._for_robot(robot).shortest_path(start, goal)
        s = _point(start, "start")
        g = _point(goal, "goal")
        self._check_grid([s, g], ["start", "goal"])
        pl, out = self._route([s, g])
        st, grp, pts, _ = pl._query(np.array([s], dtype=object), np.array([g], dtype=object), out)
        st, grp, pts = int(st[0]), int(grp[0]), pts
        if st == 1:
            raise self._point_error("start", s, grp)
        if st == 2:
            raise self._point_error("goal", g, grp)
        if st == 3:
            raise NoPathError(
                f"goal: ({_fmt(g[0])}, {_fmt(g[1])}) cannot be reached from "
                f"({_fmt(s[0])}, {_fmt(s[1])})",
                argument="goal",
                hint="the free space between them is not connected",
            )
        return Path(pts)

    def _query(self, S: Any, G: Any, out: str) -> tuple:
        """The core's answers for the pairs (S[i], G[i]): status, group, points, offsets.
        A meshed scene takes float64; a query outside the meshed box meshes a larger box
        (once, kept)."""
        if self._mesh_box is None:
            dt = np.int64 if out == "int" else np.float64
            A = np.ascontiguousarray(np.array(S, dtype=dt).reshape(-1, 2))
            B = np.ascontiguousarray(np.array(G, dtype=dt).reshape(-1, 2))
            if len(A) == 1:
                st, grp, pts = self._core.query(dt(A[0, 0]), dt(A[0, 1]), dt(B[0, 0]), dt(B[0, 1]))
                return [st], [grp], pts, [0, len(pts)]
            return self._core.query_many(A, B)
        A = np.ascontiguousarray(np.array(S, dtype=np.float64).reshape(-1, 2))
        B = np.ascontiguousarray(np.array(G, dtype=np.float64).reshape(-1, 2))
        if len(A) == 1:
            st, grp, pts = self._core.query(A[0, 0], A[0, 1], B[0, 0], B[0, 1])
            res: tuple = ([st], [grp], pts, [0, len(pts)])
        else:
            res = self._core.query_many(A, B)
        if any(int(v) == 4 for v in res[0]):  # outside the meshed box
            self._core = self._make_mesh("float", cover=np.concatenate([A, B]))
            if self._core is None:
                self._core = self._make_graph(self.kind)
                self._twin = None
                pl, out2 = self._route([tuple(p) for p in np.concatenate([A, B]).tolist()])
                return pl._query(S, G, out2)
            return self._query(S, G, out)
        if out == "int":
            pts = res[2]
            ints = pts.astype(np.int64)
            if not np.array_equal(ints, pts):  # bend points are C-obstacle vertices
                raise GeometryError("internal error: a bend point is not an integer")
            res = (res[0], res[1], ints, res[3])
        return res

    def shortest_paths(self, starts: Any, goals: Any, *, robot: Any = None) -> list[Path | None]:
        """Many queries in one call: ``starts[i]`` to ``goals[i]``.

        Either argument may be a single point (used for every query). Returns a list of
        :class:`Path`, with ``None`` where the goal is unreachable; a start or goal in
        collision raises (the error names ``starts[i]`` or ``goals[i]``). ``robot``: as
        in :meth:`shortest_path`.

        Examples
        --------
        >>> import minkowski2d as mk
        >>> pl = mk.MotionPlanner([[(1, -1), (2, -1), (2, 1), (1, 1)]])
        >>> [p.points.tolist() for p in pl.shortest_paths([(0, 0), (0, 5)], (3, 0))]
        [[[0, 0], [1, -1], [2, -1], [3, 0]], [[0, 5], [3, 0]]]
        """
        if robot is not None:
            return self._for_robot(robot).shortest_paths(starts, goals)
        S = self._points(starts, "starts")
        G = self._points(goals, "goals")
        if len(S) == 1 and len(G) != 1:
            S = S * len(G)
        if len(G) == 1 and len(S) != 1:
            G = G * len(S)
        if len(S) != len(G):
            raise ShapeError(f"goals: {len(G)} goals for {len(S)} starts", argument="goals")
        if not S:
            return []
        self._check_grid(
            S + G, [f"starts[{i}]" for i in range(len(S))] + [f"goals[{i}]" for i in range(len(G))]
        )
        pl, out = self._route(S + G)
        st, grp, pts, off = pl._query(S, G, out)
        res: list[Path | None] = []
        for i in range(len(S)):
            if st[i] == 1:
                raise self._point_error(f"starts[{i}]", S[i], int(grp[i]))
            if st[i] == 2:
                raise self._point_error(f"goals[{i}]", G[i], int(grp[i]))
            res.append(None if st[i] == 3 else Path(pts[off[i] : off[i + 1]]))
        return res

    @staticmethod
    def _points(points: Any, name: str) -> list[tuple]:
        if is_shapely(points):
            return [_point(points, name)]
        arr = points
        if isinstance(arr, np.ndarray):
            if arr.ndim == 1:
                return [_point(arr.tolist(), name)]
            return [_point(r, f"{name}[{i}]") for i, r in enumerate(arr.tolist())]
        try:
            seq = list(arr)
        except TypeError:
            raise ShapeError(
                f"{name}: expected a point (x, y) or a sequence of points, got "
                f"{type(arr).__name__}",
                argument=name,
            ) from None
        if len(seq) == 2 and not hasattr(seq[0], "__len__") and not is_shapely(seq[0]):
            return [_point(seq, name)]
        return [_point(r, f"{name}[{i}]") for i, r in enumerate(seq)]

    def is_free(self, points: Any) -> np.ndarray:
        """May the reference point be at each point? (closed free space: touching counts
        as free). Returns an (n,) bool array (n = 1 for a single point).

        Examples
        --------
        >>> import minkowski2d as mk
        >>> pl = mk.MotionPlanner([[(0, 0), (2, 0), (2, 2), (0, 2)]])
        >>> pl.is_free([(1, 1), (2, 1), (3, 1)]).tolist()
        [False, True, True]
        """
        pts = self._points(points, "points")
        if not pts:
            return np.zeros(0, bool)
        return self.locate(pts) == -1

    def locate(self, points: Any) -> np.ndarray:
        """Per point: -1 free, ``k`` inside the C-obstacle of ``obstacles[k]`` (the
        lowest such ``k`` where C-obstacles overlap; ``n_obstacles`` for the workspace's
        outside), -2 outside the workspace box.

        Examples
        --------
        >>> import minkowski2d as mk
        >>> mk.MotionPlanner([[(0, 0), (2, 0), (2, 2), (0, 2)]]).locate([(1, 1), (3, 3)]).tolist()
        [0, -1]
        """
        pts = points if isinstance(points, list) else self._points(points, "points")
        if not pts:
            return np.zeros(0, np.int64)
        pl, out = self._route(pts)
        dt = np.int64 if out == "int" and pl._mesh_box is None else np.float64
        loc = pl._core.locate(np.ascontiguousarray(np.array(pts, dtype=dt).reshape(-1, 2)))
        loc = np.asarray(loc, dtype=np.int64)
        if self._grid_box is not None:
            loc[~self._in_grid(pts)] = -2
        return np.minimum(loc, self.n_obstacles)  # every workspace group is the workspace

    # ------------------------------------------------------------------ geometry
    @property
    def cspace_obstacles(self) -> list:
        """One shapely geometry per obstacle: its C-obstacle ``O ⊕ (−R)`` (the union of
        its pieces; display only: the planner never unions)."""
        groups = self.groups.tolist()
        return [
            _union_shapes([p for p, gg in zip(self.pieces, groups) if gg == g])
            for g in range(self.n_obstacles)
        ]

    @property
    def free_space(self) -> Any:
        """The closed free configuration space as a shapely geometry: the workspace box
        (without a workspace, a box around the C-obstacles) minus the union of the
        C-obstacle pieces, computed by the core's exact overlay (vertices correctly
        rounded). The result is regularized: zero-width passages, which the planner
        does use, are not shown."""
        from ._engine.overlay import overlay

        if self.box is not None:
            b = [float(v) for v in self.box]
        else:
            allc = self.pieces.coords.astype(np.float64)
            if len(allc) == 0:
                allc = np.zeros((1, 2))
            lo, hi = allc.min(axis=0), allc.max(axis=0)
            m = max(float((hi - lo).max()) * 0.1, 1.0)
            b = [lo[0] - m, lo[1] - m, hi[0] + m, hi[1] + m]
        region = [(b[0], b[1]), (b[2], b[1]), (b[2], b[3]), (b[0], b[3])]
        pieces = [np.asarray(p, dtype=np.float64) for p in self.pieces]
        pieces = [p for p in pieces if len(p) >= 3]  # points and segments have no area
        return overlay(
            [region, *pieces],
            layers=[0] + [1] * len(pieces),
            rule="difference",
            argument="free_space",
        )

    @property
    def obstacles(self) -> list:
        """The obstacles as shapely geometries (for display)."""
        return [_union_shapes(pcs) for pcs in self._obstacle_pieces]

    def _plot_(self, ax: Any, path: Path | None = None, **kwargs: Any) -> Any:
        return self.plot(ax, path=path, mesh=bool(kwargs.get("mesh", False)))

    def plot(self, ax: Any = None, path: Path | None = None, *, mesh: bool = False) -> Any:
        """Draw the obstacles, the C-obstacles and optionally a path with matplotlib
        (imported only here); returns the axes. ``mesh=True`` also draws the cells of
        the navigation mesh (when the mesh plans).

        Examples
        --------
        >>> import minkowski2d as mk
        >>> ax = mk.MotionPlanner([[(0, 0), (1, 0), (0, 1)]]).plot()  # doctest: +SKIP
        """
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots()
        ax.set_aspect("equal")
        for geom, style in (
            (self.cspace_obstacles, {"fc": "#f4b6b6", "ec": "#c44", "alpha": 0.6}),
            (self.obstacles, {"fc": "#777", "ec": "#333", "alpha": 0.9}),
        ):
            for g in geom:
                for poly in getattr(g, "geoms", [g]):
                    if poly.geom_type == "Polygon" and not poly.is_empty:
                        x, y = poly.exterior.xy
                        ax.fill(x, y, **style)
        if self.box is not None:
            b = [float(v) for v in self.box]
            ax.plot([b[0], b[2], b[2], b[0], b[0]], [b[1], b[1], b[3], b[3], b[1]], "k--", lw=1)
        m = self.navmesh if mesh else None
        if m is not None:
            for cell in m.cells:
                xy = m.vertices[np.append(cell, cell[0])]
                ax.plot(xy[:, 0], xy[:, 1], color="#6a9fd8", lw=0.5)
        if path is not None:
            path.plot(ax)
        return ax

    @property
    def planned_by(self) -> str:
        """``"mesh"`` (the navigation mesh and its interval search) or ``"visibility"``
        (the reduced visibility graph): which of the two answers this planner's queries
        (``method="auto"`` picks the mesh for scenes of 64 or more C-obstacle pieces
        where it can be built)."""
        return "mesh" if self._mesh_box is not None else "visibility"

    @property
    def navmesh(self) -> NavMesh | None:
        """The navigation mesh of the free space (None when the visibility graph plans):
        exact vertices and convex cells, counter-clockwise; ``flags`` marks corners (1,
        the free angle exceeds 180 degrees) and junctions (2, the free space pinches).

        Examples
        --------
        >>> import minkowski2d as mk
        >>> pl = mk.MotionPlanner([[(1, 1), (2, 1), (2, 2), (1, 2)]], workspace=(0, 0, 3, 3),
        ...                       method="mesh")
        >>> m = pl.navmesh
        >>> len(m.vertices), sum(len(c) for c in m.cells) >= 3 * 4
        (8, True)
        """
        if self._mesh_box is None:
            return None
        xy, off, pv, fl = self._core.mesh()
        cells = [pv[off[k] : off[k + 1]] for k in range(len(off) - 1)]
        return NavMesh(xy, cells, fl)

    def __repr__(self) -> str:
        return (
            f"MotionPlanner({self.n_obstacles} obstacles, {len(self.pieces)} C-pieces, "
            f"kind={self.kind!r}, method={self.planned_by!r})"
        )


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

    from ._engine.overlay import overlay

    arrs = [np.asarray(p, dtype=np.float64) for p in pieces]
    area = overlay([a for a in arrs if len(a) >= 3])
    low = [
        shapely.LineString(a) if len(a) == 2 else shapely.Point(a[0]) for a in arrs if len(a) < 3
    ]
    if not low:
        return area
    return shapely.GeometryCollection([*shapely.get_parts(area), *low])


def _ring_coords(workspace: Any) -> np.ndarray:
    data, _, path = D.one(workspace, "workspace")
    if path == "py":
        raise ShapeError("workspace: coordinates must be int64 or float64", argument="workspace")
    return np.asarray(data, dtype=np.float64)


class NavMesh(NamedTuple):
    """The navigation mesh of a planner's free space (:attr:`MotionPlanner.navmesh`).

    Attributes
    ----------
    vertices : (n, 2) float64 ndarray
        Exact vertices (every one a double: piece vertices and crossings that are).
    cells : list of (k,) int64 ndarrays
        Convex cells, counter-clockwise, as indices into ``vertices``.
    flags : (n,) int64 ndarray
        1 for a corner (the free angle exceeds 180 degrees), 2 for a junction (the
        free space pinches there), else 0.
    """

    vertices: np.ndarray
    cells: list
    flags: np.ndarray

    def polygons(self) -> Any:
        """The cells as shapely Polygons (for display; shapely imported here).

        Examples
        --------
        >>> import minkowski2d as mk
        >>> pl = mk.MotionPlanner([[(1, 1), (2, 1), (2, 2), (1, 2)]], workspace=(0, 0, 3, 3),
        ...                       method="mesh")
        >>> sum(p.area for p in pl.navmesh.polygons())
        8.0
        """
        import shapely

        return [shapely.Polygon(self.vertices[c]) for c in self.cells]


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
