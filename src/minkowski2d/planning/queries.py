"""The planner's queries: shortest paths, point tests, the free space, drawing."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from .._engine import core
from .._engine.coerce import ints_fit_float64, is_shapely
from ..errors import (
    GeometryError,
    NoPathError,
    ShapeError,
)
from .results import NavMesh, Path
from .scene import (
    _INT_LIMIT,
    _NOT_F64,
    _fmt,
    _point,
    _union_shapes,
)

if TYPE_CHECKING:
    from ..batch import Ragged
    from .planner import MotionPlanner


class _Queries:
    """The queries of a :class:`MotionPlanner` (paths, points, the free space, drawing),
    kept apart from its construction (planner.py)."""

    if TYPE_CHECKING:  # set and defined by MotionPlanner (planner.py)
        kind: str
        n_obstacles: int
        pieces: Ragged
        groups: np.ndarray
        box: list[Any] | None
        _obstacle_pieces: list[list[np.ndarray]]
        _grid_box: Any
        _mesh_box: Any
        _core: Any
        _twin: Any
        _graph: Any

        def _make_graph(self, kind: str) -> Any: ...
        def _make_mesh(self, kind: str, cover: Any = None) -> Any: ...
        def _float_twin(self) -> Any: ...
        def _for_robot(self, robot: Any) -> MotionPlanner: ...

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
            return e
        name = self._group_name(grp)
        e = GeometryError(
            f"{which}: {where} is in collision with {name} (inside its C-obstacle)",
            argument=which,
            hint="move it out of the C-obstacle; touching is allowed",
            obstacle=grp,
        )
        return e

    # ------------------------------------------------------------------ queries
    def _graph_twin(self) -> Any:
        """The same planner on the visibility graph (for int queries beyond 2**53 on a
        meshed int scene: the mesh works on float64)."""
        if getattr(self, "_graph", None) is None:
            twin = object.__new__(type(self))
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
            if not ints_fit_float64(v for p in pts for v in p):
                if self.kind == "int" and not floats:
                    return self._graph_twin()._route(pts)
                raise ShapeError(
                    f"start: ints next to floats {_NOT_F64}",
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
            if not ints_fit_float64(v for p in pts for v in p):
                raise ShapeError(f"start: ints next to floats {_NOT_F64}", argument="start")
            return self._float_twin(), "float"
        if not ints_fit_float64(v for p in pts for v in p):
            raise ShapeError(f"start: ints in a float scene {_NOT_F64}", argument="start")
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
        if st == core.PLAN_START_BAD:
            raise self._point_error("start", s, grp)
        if st == core.PLAN_GOAL_BAD:
            raise self._point_error("goal", g, grp)
        if st == core.PLAN_NO_PATH:
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
        if any(int(v) == core.PLAN_OUTSIDE_MESH for v in res[0]):
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
            if st[i] == core.PLAN_START_BAD:
                raise self._point_error(f"starts[{i}]", S[i], int(grp[i]))
            if st[i] == core.PLAN_GOAL_BAD:
                raise self._point_error(f"goals[{i}]", G[i], int(grp[i]))
            res.append(None if st[i] == core.PLAN_NO_PATH else Path(pts[off[i] : off[i + 1]]))
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
        from .._engine.overlay import overlay

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
