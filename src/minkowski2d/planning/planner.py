"""The motion planner: construction (scenes, grids, robots) and the compiled core it
plans with (the navigation mesh or the visibility graph)."""

from __future__ import annotations

import math
from collections import OrderedDict
from fractions import Fraction
from typing import Any

import numpy as np

from .._engine import core
from .._engine import options as _options
from .._engine.coerce import ints_fit_float64, is_shapely
from .._engine.foreign import foreign_errors
from ..errors import (
    OptionError,
    OverflowGeometryError,
    ShapeError,
)
from .queries import _Queries
from .scene import (
    _INT_LIMIT,
    _NOT_F64,
    _SIMPLE_HINT,
    _as_kind,
    _fmt,
    _grid_rectangles,
    _grid_scalar,
    _is_box,
    _occupancy,
    _pieces,
    _point,
    _ring_coords,
    _scalar,
    _triangulate,
    _workspace_groups,
)

METHODS = ("auto", "mesh", "visibility")
_MESH_MIN_PIECES = 64  # "auto": smaller scenes keep the visibility graph (as fast there)
_MESH_RANGE = 2.0**500
_ROBOT_CACHE = 8  # planners kept for other robots (least recently used dropped)


class MotionPlanner(_Queries):
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
        from ..batch import Ragged, minkowski_sum_many

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
        f: list[float]  # ints for an int workspace
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
            from .._engine.polygon import check, rings_of

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
        if kind == "int" and not (
            ints_fit_float64(coords) and ints_fit_float64(self.box if self.box is not None else [])
        ):
            return "int coordinates with more than 53 significant bits"
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
            if not ints_fit_float64(self.pieces.coords):
                raise ShapeError(
                    f"start: float queries on an int scene whose {_NOT_F64}",
                    argument="start",
                    hint="pass int coordinates",
                )
            if self.box is not None and not ints_fit_float64(self.box):
                raise ShapeError(
                    f"start: float queries in an int workspace whose {_NOT_F64}",
                    argument="start",
                    hint="pass int coordinates",
                )
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
