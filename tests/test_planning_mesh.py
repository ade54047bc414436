"""Planning at map scale: the navigation mesh and its interval search against the exact
brute-force reference of test_planning.py, a robot per query, grid maps and .map files.

Every scene here is planned with ``method="mesh"`` where the mesh can be built (the
scenes with zero-width passages or inexact crossings fall back to the visibility graph
under ``"auto"``: those are checked too, and that ``"mesh"`` refuses them with an
OptionError).
"""

from __future__ import annotations

import math
import os
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import minkowski2d as mk
import minkowski2d.io  # noqa: F401 - mk.io
from minkowski2d.errors import GeometryError, InputFormatError, OptionError

from . import oracle as O
from .test_planning import Oracle, check_against, convex_int, l_shapes, oracle_of, sq

_X = int(os.environ.get("PLAN_EXAMPLES_SCALE", "1"))


def planner(obs, robot=None, workspace=None):
    """The mesh planner for the scene, or (where the mesh refuses it) the visibility
    graph, with ``planned_by`` telling which."""
    try:
        return mk.MotionPlanner(obs, robot=robot, workspace=workspace, method="mesh")
    except OptionError as exc:
        assert "cannot plan this scene" in str(exc)
        pl = mk.MotionPlanner(obs, robot=robot, workspace=workspace, method="auto")
        assert pl.planned_by == "visibility"
        return pl


def check_many(pl, orc, pairs):
    for s, g in pairs:
        check_against(pl, orc, s, g)


pairs10 = st.lists(
    st.tuples(
        st.tuples(st.integers(-2, 10), st.integers(-2, 10)),
        st.tuples(st.integers(-2, 10), st.integers(-2, 10)),
    ),
    min_size=1,
    max_size=6,
)
robots = st.sampled_from(
    [None, [(0, 0), (1, 0), (0, 1)], [(-1, 0), (1, 0), (0, 1)], [(0, 0), (1, 0), (1, 1), (0, 1)]]
)


# --------------------------------------------------------------------------------------
# named scenes


def test_mesh_is_chosen_and_agrees_on_a_maze_of_blocks():
    obs = [sq(x, y, x + 1, y + 1) for x in range(0, 12, 2) for y in range(0, 12, 3)]
    pl = mk.MotionPlanner(obs, workspace=(-1, -1, 13, 13), method="mesh")
    assert pl.planned_by == "mesh"
    orc = oracle_of(pl)
    check_many(pl, orc, [((-1, -1), (13, 13)), ((0, 2), (11, 1)), ((1, 1), (1, 12))])


def test_pinch_points_are_passages():
    # squares touching at corners (one obstacle each): the free space pinches there
    obs = [sq(0, 0, 2, 2), sq(2, 2, 4, 4), sq(4, 0, 6, 2), sq(2, -2, 4, 0)]
    pl = mk.MotionPlanner(obs, workspace=(-2, -4, 8, 6), method="mesh")
    assert pl.planned_by == "mesh"
    assert (pl.navmesh.flags == 2).sum() >= 4  # the four pinches are junctions
    orc = oracle_of(pl)
    # through the pinch at (2, 2): the straight line from the hole's centre
    check_many(pl, orc, [((3, 1), (-1, 5)), ((3, 1), (7, 5)), ((3, 1), (3, 5)), ((1, 3), (5, -1))])
    assert pl.shortest_path((3, 1), (-1, 5)).points.tolist() == [[3, 1], [-1, 5]]
    assert pl.shortest_path((3, 1), (-1, 4)).points.tolist() == [[3, 1], [2, 2], [-1, 4]]


def test_seam_of_one_obstacle_blocks_and_touching_obstacles_do_not():
    L = [(0, 0), (3, 0), (3, 1), (1, 1), (1, 3), (0, 3)]
    pl = mk.MotionPlanner([L], workspace=(-2, -2, 5, 5), method="mesh")
    orc = oracle_of(pl)
    check_many(pl, orc, [((2, 2), (-1, -1)), ((4, 4), (0.5, -1))])
    # two obstacles sharing an edge: a zero-width passage, on the mesh's network
    pl = mk.MotionPlanner([sq(0, 0, 1, 1), sq(1, 0, 2, 1)], method="mesh")
    assert pl.planned_by == "mesh"
    assert pl._core.zero_width().tolist() == [[1, 0, 1, 1]]
    assert pl.shortest_path((1, -1), (1, 2)).points.tolist() == [[1, -1], [1, 2]]
    orc = oracle_of(pl)
    check_many(pl, orc, [((0.5, -1), (1.5, 2)), ((1, 0.5), (1.5, 2)), ((-1, 0.5), (1, 0.7))])


def test_inexact_crossing_falls_back():
    # two triangles whose edges cross at (1/3, 1/3)-like points that are not doubles
    obs = [[(0, 0), (3, 1), (0, 2)], [(1, -1), (2, 3), (0, 3)]]
    with pytest.raises(OptionError, match="not a float64"):
        mk.MotionPlanner(obs, method="mesh")
    pl = mk.MotionPlanner(obs, method="auto")
    assert pl.planned_by == "visibility"


def test_query_outside_the_meshed_box_meshes_a_larger_one():
    obs = [sq(x, 0, x + 1, 5) for x in range(0, 40, 2)]
    pl = mk.MotionPlanner(obs, method="mesh")
    box0 = list(pl._mesh_box)
    orc = oracle_of(pl)
    check_against(pl, orc, (0.5, -1000), (39.5, 1e4))
    assert pl._mesh_box != box0 and pl.planned_by == "mesh"
    check_against(pl, orc, (1.5, 2), (3.5, 2))


def test_int_queries_beyond_2_53_use_the_graph():
    obs = [sq(x, 0, x + 1, 5) for x in range(0, 140, 2)]
    pl = mk.MotionPlanner(obs, method="mesh")
    big = 2**60
    path = pl.shortest_path((1, 1), (big, 1))
    assert path.points.dtype == np.int64 and path.points[-1].tolist() == [big, 1]


def test_float_query_on_int_mesh_scene():
    obs = [sq(x, 0, x + 1, 5) for x in range(0, 16, 2)]
    pl = mk.MotionPlanner(obs, method="mesh")
    orc = oracle_of(pl)
    p = check_against(pl, orc, (1.5, 1.25), (9.5, 1.0))
    assert p.points.dtype == np.float64
    p = check_against(pl, orc, (1, -1), (9, 1))
    assert p.points.dtype == np.int64


# --------------------------------------------------------------------------------------
# property tests against the exact reference


@settings(max_examples=40 * _X, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(obs=st.lists(convex_int(), min_size=1, max_size=5), robot=robots, box=st.booleans(),
       pairs=pairs10)  # fmt: skip
def test_mesh_random_int_scenes_against_oracle(obs, robot, box, pairs):
    ws = (-2, -2, 10, 10) if box else None
    pl = planner(obs, robot=robot, workspace=ws)
    rob = robot if robot is not None else [(0, 0)]
    neg = [(-x, -y) for x, y in rob]
    exact = [O.minkowski_sum(o, neg) for o in obs]
    orc = Oracle(exact, list(range(len(obs))), pl.box)
    check_many(pl, orc, pairs)


@settings(max_examples=25 * _X, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(obs=st.lists(st.one_of(l_shapes(), convex_int()), min_size=1, max_size=4), box=st.booleans(),
       pairs=pairs10)  # fmt: skip
def test_mesh_non_convex_obstacles_against_oracle(obs, box, pairs):
    pl = planner(obs, workspace=(-3, -3, 11, 11) if box else None)
    check_many(pl, oracle_of(pl), pairs)


@settings(max_examples=15 * _X, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    obs=st.lists(convex_int(), min_size=1, max_size=3),
    pairs=pairs10,
    scale=st.sampled_from([0.1, 0.3, 1e-5, 1e-200, 1e200, 3.0**-40]),
)
def test_mesh_random_float_scenes_against_oracle(obs, pairs, scale):
    fobs = [np.array(o, dtype=float) * scale + 0.25 * scale for o in obs]
    pl = planner(fobs)
    orc = oracle_of(pl)
    check_many(pl, orc, [((s[0] * scale, s[1] * scale), (g[0] * scale, g[1] * scale))
                         for s, g in pairs])  # fmt: skip


@st.composite
def grids(draw):
    h = draw(st.integers(1, 6))
    w = draw(st.integers(1, 6))
    cells = draw(st.lists(st.booleans(), min_size=h * w, max_size=h * w))
    return np.array(cells, dtype=bool).reshape(h, w)


@settings(max_examples=40 * _X, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(occ=grids(), data=st.data(), robot=st.sampled_from([None, [(0, 0), (1, 0), (0, 1)]]))
def test_grids_against_oracle_and_cells_as_blocks(occ, data, robot):
    h, w = occ.shape
    pt = st.tuples(st.integers(0, w), st.integers(0, h))
    pairs = data.draw(st.lists(st.tuples(pt, pt), min_size=1, max_size=4))
    pl = mk.MotionPlanner.from_grid(occ, robot=robot, method="mesh")
    assert pl.planned_by == "mesh"
    orc = oracle_of(pl)
    for s, g in pairs:
        check_against(pl, orc, s, g)
    # the same with the visibility graph (every cell and the outside in one obstacle)
    vg = mk.MotionPlanner.from_grid(occ, robot=robot, method="visibility")
    for s, g in pairs:
        try:
            a = pl.shortest_path(s, g).length
        except GeometryError as exc:
            with pytest.raises(type(exc)):
                vg.shortest_path(s, g)
            continue
        assert math.isclose(a, vg.shortest_path(s, g).length, rel_tol=1e-12)


# --------------------------------------------------------------------------------------
# a robot per query


ROBOTS = [
    None,
    [(0, 0), (1, 0), (0, 1)],
    sq(-1, -1, 1, 1),
    [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)],
]


@settings(max_examples=25 * _X, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(obs=st.lists(convex_int(), min_size=1, max_size=4), robot=st.sampled_from(ROBOTS),
       s=st.tuples(st.integers(-3, 11), st.integers(-3, 11)),
       g=st.tuples(st.integers(-3, 11), st.integers(-3, 11)))  # fmt: skip
def test_robot_per_query_equals_a_planner_for_that_robot(obs, robot, s, g):
    base = mk.MotionPlanner(obs, workspace=(-3, -3, 11, 11))
    own = mk.MotionPlanner(obs, robot=robot, workspace=(-3, -3, 11, 11))
    r = [(0, 0)] if robot is None else robot
    try:
        want = own.shortest_path(s, g).points.tolist()
    except GeometryError as exc:
        with pytest.raises(type(exc)) as ei:
            base.shortest_path(s, g, robot=r)
        assert ei.value.argument == exc.argument
        return
    assert base.shortest_path(s, g, robot=r).points.tolist() == want
    assert [p.points.tolist() for p in base.shortest_paths([s], [g], robot=r)] == [want]
    check_against(base._for_robot(r), oracle_of(own), s, g)


def test_robot_cache_is_bounded_and_reused():
    pl = mk.MotionPlanner([sq(0, 0, 2, 2)])
    first = pl._for_robot(sq(0, 0, 1, 1))
    assert pl._for_robot(np.array(sq(0, 0, 1, 1))) is first
    for k in range(1, 12):
        pl.shortest_path((-5, -5), (5, 5), robot=sq(0, 0, k, 1))
    assert len(pl._robots) == 8
    assert first not in pl._robots.values()


# --------------------------------------------------------------------------------------
# grid maps and the Moving AI .map format


MAP = """type octile
height 4
width 6
map
......
.@@@T.
....@.
S..G.W
"""


def test_read_grid_map_and_plan(tmp_path):
    f = tmp_path / "tiny.map"
    f.write_text(MAP)
    occ = mk.io.read_grid_map(f)
    assert occ.dtype == bool and occ.shape == (4, 6)
    assert occ[1].tolist() == [False, True, True, True, True, False]
    assert occ[3].tolist() == [False] * 5 + [True]
    pl = mk.MotionPlanner.from_grid(occ)
    # (x, y) = (column, row): around the wall of row 1
    path = pl.shortest_path((0.5, 2.5), (5.5, 2.5))
    orc = oracle_of(pl)
    check_against(pl, orc, (0.5, 2.5), (5.5, 2.5))
    assert path.points.tolist()[1] == [1.0, 1.0] or path.points.tolist()[1] == [4.0, 3.0]
    with pytest.raises(GeometryError, match="outside the workspace"):
        pl.shortest_path((-1, 0), (1, 1))
    assert pl.locate([(-1, 0), (1.5, 1.5), (0.5, 0.5)]).tolist() == [-2, 0, -1]


@pytest.mark.parametrize(
    "text, match",
    [
        ("", "empty"),
        ("type octile\nheight 2\nwidth 2\n..\n..\n", "'map'"),
        ("type octile\nheight x\nwidth 2\nmap\n..\n..\n", "height"),
        ("type octile\nheight 2\nwidth 0\nmap\n\n\n", "width"),
        ("type octile\nheight 3\nwidth 2\nmap\n..\n..\n", "height is 3 but the map has 2 rows"),
        ("type octile\nheight 2\nwidth 2\nmap\n..\n...\n", "line 6"),
        ("type octile\nheight 2\nwidth 2\nmap\n..\n.x\n", "'x'"),
        ("height 2\nwidth 2\nmap\n..\n..\n", "type"),
    ],
)
def test_read_grid_map_errors(tmp_path, text, match):
    f = tmp_path / "bad.map"
    f.write_text(text)
    with pytest.raises(InputFormatError, match=match) as ei:
        mk.io.read_grid_map(f)
    assert ei.value.argument == str(f)


def test_from_grid_options():
    occ = np.zeros((3, 3), bool)
    occ[1, 1] = True
    pl = mk.MotionPlanner.from_grid(occ, cell_size=0.5, origin=(10, 20))
    p = pl.shortest_path((10, 20), (11.5, 21.5))
    assert p.points.tolist() == [[10.0, 20.0], [10.5, 21.0], [11.5, 21.5]] or math.isclose(
        p.length, math.hypot(0.5, 1) + math.hypot(1, 0.5)
    )
    with pytest.raises(OptionError, match="cell_size"):
        mk.MotionPlanner.from_grid(occ, cell_size=0)
    with pytest.raises(OptionError, match="cell_size"):
        mk.MotionPlanner.from_grid(occ, cell_size="1")
    with pytest.raises(GeometryError, match="occupancy"):
        mk.MotionPlanner.from_grid(np.zeros(3, bool))
    with pytest.raises(OptionError, match="method"):
        mk.MotionPlanner.from_grid(occ, method="fast")


def test_cli_plan_reads_a_map(tmp_path, capsys):
    import json

    from minkowski2d.cli import main

    f = tmp_path / "tiny.map"
    f.write_text(MAP)
    assert main(["plan", str(f), "--start", "0.5,2.5", "--goal", "5.5,2.5"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["path"][0] == [0.5, 2.5] and out["path"][-1] == [5.5, 2.5]
    assert main(["plan", str(f), "--start=-3,2", "--goal", "5.5,2.5"]) == 2
    assert "outside the workspace" in capsys.readouterr().err
    bad = tmp_path / "bad.map"
    bad.write_text("type octile\nheight 1\nwidth 2\nmap\n.?\n")
    assert main(["plan", str(bad), "--start", "0,0", "--goal", "1,1"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "'?'" in err
    # a robot on the command line
    assert main(["plan", str(f), "--start", "0.5,2.5", "--goal", "2.5,0.5",
                 "--robot", "[[0,0],[0.5,0],[0,0.5]]"]) == 0  # fmt: skip
    out = json.loads(capsys.readouterr().out)
    assert out["path"][-1] == [2.5, 0.5]


def test_navmesh_cells_cover_the_free_space():
    import shapely

    obs = [sq(x, y, x + 1, y + 2) for x in range(0, 10, 3) for y in range(0, 10, 4)]
    pl = mk.MotionPlanner(obs, workspace=(-1, -1, 11, 11), method="mesh")
    m = pl.navmesh
    cells = [shapely.Polygon(m.vertices[c]) for c in m.cells]
    assert all(c.is_valid and c.exterior.is_ccw for c in cells)
    free = shapely.box(-1, -1, 11, 11).difference(
        shapely.union_all([shapely.Polygon(o) for o in obs])
    )
    assert math.isclose(sum(c.area for c in cells), free.area)
    assert mk.MotionPlanner(obs, method="visibility").navmesh is None
    assert Fraction(m.vertices[0][0]) == m.vertices[0][0]


def _maze(n, seed):
    rng = np.random.default_rng(seed)
    occ = np.ones((2 * n + 1, 2 * n + 1), bool)
    seen = np.zeros((n, n), bool)
    stack = [(0, 0)]
    seen[0, 0] = occ[1, 1] = False
    seen[0, 0] = True
    while stack:
        i, j = stack[-1]
        nb = [(i + a, j + b) for a, b in ((1, 0), (-1, 0), (0, 1), (0, -1))
              if 0 <= i + a < n and 0 <= j + b < n and not seen[i + a, j + b]]  # fmt: skip
        if not nb:
            stack.pop()
            continue
        a, b = nb[int(rng.integers(len(nb)))]
        seen[a, b] = True
        occ[2 * a + 1, 2 * b + 1] = occ[i + a + 1, j + b + 1] = False
        stack.append((a, b))
    return occ


def same_as_visibility(mesh, vis, pairs):
    """The mesh planner's lengths equal the visibility graph's (the same errors where it
    has no path), and its paths are free."""
    for s, g in pairs:
        try:
            want = vis.shortest_path(s, g)
        except GeometryError as exc:
            with pytest.raises(type(exc)):
                mesh.shortest_path(s, g)
            continue
        got = mesh.shortest_path(s, g)
        assert math.isclose(got.length, want.length, rel_tol=1e-12), (s, g)
        assert all(mesh._core.segment_free(*a, *b) for a, b in zip(got.points, got.points[1:]))


def check_landmark_tables(pl, vis):
    """Every finite table entry is the visibility graph's length between the landmark and
    the search vertex; +inf only where no path joins them (or the vertex is the far end
    of a stub, inside a third obstacle). Vertices off a grid map's grid are skipped."""
    at, xy, d = pl._core.landmarks()
    if len(at) == 0:  # no free space with area: no tables
        assert d.size == 0 and len(pl.navmesh.cells) == 0
        return
    assert d.shape == (len(xy), len(at))
    for k, a in enumerate(at.tolist()):
        L = tuple(xy[a].tolist())
        assert d[a, k] == 0
        for v in range(len(xy)):
            P = tuple(xy[v].tolist())
            try:
                want = vis.shortest_path(L, P).length
            except (mk.errors.NoPathError, GeometryError) as exc:
                if "outside" in str(exc):  # the mesh's box beyond a grid map
                    continue
                assert d[v, k] == math.inf, (L, P, d[v, k])
                continue
            assert math.isclose(d[v, k], want, rel_tol=1e-12, abs_tol=1e-12), (L, P, d[v, k], want)


@pytest.mark.parametrize("kind", ["maze", "cave"])
def test_mesh_equals_visibility_on_game_maps(kind):
    # dead ends (mazes) and pinches between diagonal blocks (caves): the mesh's lengths
    # equal the visibility graph's (itself checked against the exact reference)
    rng = np.random.default_rng(5)
    if kind == "maze":
        occ = _maze(7, 3)
    else:
        occ = rng.random((24, 24)) < 0.42
    mesh = mk.MotionPlanner.from_grid(occ, method="mesh")
    vis = mk.MotionPlanner.from_grid(occ, method="visibility")
    h, w = occ.shape
    pts = [
        (int(x), int(y)) for x, y in zip(rng.integers(0, w + 1, 160), rng.integers(0, h + 1, 160))
    ]
    free = np.argwhere(~occ)
    pts += [(c + 0.5, r + 0.5) for r, c in free[rng.integers(len(free), size=80)].tolist()]
    same_as_visibility(mesh, vis, zip(pts[0::2], pts[1::2]))


def test_plot_and_polygons_show_the_mesh():
    plt = pytest.importorskip("matplotlib.pyplot")
    occ = np.zeros((4, 5), bool)
    occ[1:3, 2] = True
    pl = mk.MotionPlanner.from_grid(occ, method="mesh")
    import shapely

    cells = pl.navmesh.polygons()
    inside = [c.intersection(shapely.box(0, 0, 5, 4)).area for c in cells]  # the grid
    assert math.isclose(sum(inside), 4 * 5 - 2)  # (the mesh's box reaches beyond it)
    ax = pl.plot(path=pl.shortest_path((0, 2), (5, 2)), mesh=True)
    assert len(ax.lines) >= len(cells)
    plt.close(ax.figure)
    assert mk.MotionPlanner.from_grid(occ, method="visibility").navmesh is None


def test_mesh_locate_names_the_lowest_of_overlapping_obstacles():
    L = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    T = [(0, 0), (2, 0), (0, 1)]
    for obs in ([L, T], [T, L], [T, L, T]):
        pl = mk.MotionPlanner(obs, method="mesh")
        got = pl.locate([(0.5, 0.5), (1.0, 0.25), (1.5, 0.5), (0.5, 1.5), (3, 3)]).tolist()
        assert got == [0, 0, obs.index(L), obs.index(L), -1]
        with pytest.raises(GeometryError) as ei:
            pl.shortest_path((1.5, 0.5), (3, 3))
        assert ei.value.obstacle == obs.index(L)


# --------------------------------------------------------------------------------------
# real game maps (GPPC-2013 scenarios in ../shared/data/maps, read from there) and the
# search's pruning (the corners a shortest path can bend at, bridges of the mesh)

MAPS = Path(__file__).resolve().parents[2] / "shared" / "data" / "maps"
GAME_MAPS = ["Archipelago", "BigGameHunters", "Brushfire", "ca_cave", "dr_dungeon", "ht_keep"]
requires_maps = pytest.mark.skipif(
    not MAPS.is_dir(), reason=f"game maps missing: {MAPS} (../shared/data/maps) does not exist"
)


def scenario(name: str, n: int) -> list:
    """n queries spread over the map's scenario file: (start, goal, octile optimum)."""
    rows = mk.io.read_scenario(MAPS / f"{name}.map.scen")
    pick = np.linspace(0, len(rows) - 1, n).astype(int)
    centre = lambda c: (c[0] + 0.5, c[1] + 0.5)  # noqa: E731
    return [(centre(rows[i].start), centre(rows[i].goal), rows[i].optimal) for i in pick]


@requires_maps
@pytest.mark.parametrize("name", GAME_MAPS)
def test_game_map_paths_are_valid_and_within_the_octile_optimum(name):
    occ = mk.io.read_grid_map(MAPS / f"{name}.map")
    pl = mk.MotionPlanner.from_grid(occ, method="mesh")
    for s, g, octile in scenario(name, 60):
        path = pl.shortest_path(s, g)
        pts = path.points
        assert tuple(pts[0]) == s and tuple(pts[-1]) == g
        assert all(pl._core.segment_free(*a, *b) for a, b in zip(pts, pts[1:])), (s, g)
        # the scenario rounds the optimum to 6 significant digits
        assert path.length <= octile + 0.5 * 10.0 ** (math.floor(math.log10(octile)) - 5)


@requires_maps
@pytest.mark.parametrize("name", ["ca_cave", "ht_keep"])
def test_game_map_lengths_equal_the_visibility_graph(name):
    occ = mk.io.read_grid_map(MAPS / f"{name}.map")
    mesh = mk.MotionPlanner.from_grid(occ, method="mesh")
    vis = mk.MotionPlanner.from_grid(occ, method="visibility")
    for s, g, _ in scenario(name, 120):
        got, want = mesh.shortest_path(s, g).length, vis.shortest_path(s, g).length
        assert math.isclose(got, want, rel_tol=1e-12), (s, g)


@st.composite
def caves(draw):
    """Random grids dense enough for pockets (dead-end corridors, bays behind one mesh
    edge) and pinches (blocked cells touching at a corner only)."""
    h = draw(st.integers(4, 14))
    w = draw(st.integers(4, 14))
    p = draw(st.sampled_from([0.25, 0.35, 0.45]))
    seed = draw(st.integers(0, 2**32 - 1))
    return np.random.default_rng(seed).random((h, w)) < p


@settings(max_examples=40 * _X, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(occ=caves(), data=st.data())
def test_caves_mesh_equals_visibility(occ, data):
    # starts and goals at cell centres and lattice points (on mesh vertices and edges,
    # inside pockets and at their mouths)
    h, w = occ.shape
    free = np.argwhere(~occ)
    pt = st.one_of(
        st.tuples(st.integers(0, w), st.integers(0, h)),
        st.sampled_from([(c + 0.5, r + 0.5) for r, c in free.tolist()] or [(0, 0)]),
    )
    pairs = data.draw(st.lists(st.tuples(pt, pt), min_size=1, max_size=8))
    mesh = mk.MotionPlanner.from_grid(occ, method="mesh")
    vis = mk.MotionPlanner.from_grid(occ, method="visibility")
    same_as_visibility(mesh, vis, pairs)
    # with landmark tables whatever the detour (min_detour -1): exact distances, the same
    # lengths
    mesh._core.make_landmarks(data.draw(st.integers(1, 8)), -1.0)
    check_landmark_tables(mesh, vis)
    same_as_visibility(mesh, vis, pairs)


def _cave(n, seed):
    # cellular-automaton caves (the 4-5 rule): ragged walls with many bays
    occ = np.random.default_rng(seed).random((n, n)) < 0.45
    for _ in range(4):
        p = np.pad(occ, 1, constant_values=True).astype(int)
        walls = sum(p[1 + a : n + 1 + a, 1 + b : n + 1 + b] for a in (-1, 0, 1) for b in (-1, 0, 1))
        occ = walls >= 5
    return occ


# --------------------------------------------------------------------------------------
# zero-width passages: obstacles touching along edges, and the workspace box


@st.composite
def tiles(draw):
    """Rectangles and right triangles on a 0..6 lattice in the box (0, 0, 6, 6): edges
    shared between obstacles and with the box are the rule, overlaps (a third obstacle
    across a shared edge) and diagonal contacts common."""
    out = []
    for _ in range(draw(st.integers(2, 7))):
        x0, x1 = sorted(draw(st.lists(st.integers(0, 6), min_size=2, max_size=2, unique=True)))
        y0, y1 = sorted(draw(st.lists(st.integers(0, 6), min_size=2, max_size=2, unique=True)))
        shape = draw(st.integers(0, 4))
        if shape == 0 or shape == 4:
            out.append(sq(x0, y0, x1, y1))
        else:  # half a square, cut along a diagonal (crossings stay dyadic)
            d = min(x1 - x0, y1 - y0)
            x1, y1 = x0 + d, y0 + d
            c = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
            out.append([c[(shape + t) % 4] for t in range(3)])
    return out


@settings(max_examples=60 * _X, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(obs=tiles(), data=st.data(), robot=st.sampled_from([None, [(0, 0), (1, 0), (1, 1), (0, 1)]]))
def test_zero_width_passages_against_oracle_and_visibility(obs, data, robot):
    # starts and goals at lattice and half-lattice points: on the shared edges (inside
    # a segment and at its ends), at the box, inside obstacles, in the open
    pt = st.tuples(st.integers(-2, 14), st.integers(-2, 14)).map(lambda p: (p[0] / 2, p[1] / 2))
    pairs = data.draw(st.lists(st.tuples(pt, pt), min_size=1, max_size=6))
    ws = (0, 0, 6, 6)
    pl = mk.MotionPlanner(obs, robot=robot, workspace=ws, method="mesh")
    assert pl.planned_by == "mesh"
    check_many(pl, oracle_of(pl), pairs)
    vis = mk.MotionPlanner(obs, robot=robot, workspace=ws, method="visibility")
    same_as_visibility(pl, vis, pairs)
    # with landmark tables whatever the detour (min_detour -1)
    pl._core.make_landmarks(data.draw(st.integers(1, 6)), -1.0)
    check_landmark_tables(pl, vis)
    same_as_visibility(pl, vis, pairs)


def test_zero_width_network_bends_branches_and_meets_the_box():
    # a wall of blocks across the box, touching each other and the box: the only ways
    # through run along the shared edges and the box's sides
    obs = [sq(0, 4, 3, 5), sq(3, 4, 6, 6), sq(6, 3, 10, 6), sq(3, 2, 4, 4), sq(4, 2, 6, 4)]
    ws = (0, 0, 10, 10)
    pl = mk.MotionPlanner(obs, workspace=ws, method="mesh")
    segs = {tuple(map(float, s)) for s in pl._core.zero_width().tolist()}
    assert (3.0, 4.0, 3.0, 5.0) in segs and (0.0, 4.0, 0.0, 5.0) in segs  # block, box
    assert (4.0, 2.0, 4.0, 4.0) in segs and (10.0, 3.0, 10.0, 6.0) in segs
    orc = oracle_of(pl)
    pts = [(1, 1), (8, 8), (0, 4.5), (3, 4.5), (3.5, 4), (10, 4), (5, 9), (9, 1), (4, 3)]
    pairs = [(a, b) for a in pts for b in pts if a != b]
    check_many(pl, orc, pairs)
    same_as_visibility(pl, mk.MotionPlanner(obs, workspace=ws, method="visibility"), pairs)
    # along the box's left side under the first block, then along the block seam
    p = pl.shortest_path((1, 1), (8, 8))
    assert p.points.tolist()[1:3] == [[0, 4], [0, 5]] or len(p.points) > 2


def test_a_stub_ending_at_another_stubs_far_end():
    # the seam x = 2 between two blocks is covered above y = 2 by a third block (a stub
    # whose free part ends at (2, 2)); a triangle inside the left block puts the far end
    # of a second stub (along y = 2) exactly there: (2, 2) is a free point, reached up
    # the seam, although it is a vertex of no segment
    obs = [[(2, 2), (1, 2), (1, 1)], sq(0, 0, 2, 3), sq(0, 2, 3, 3), sq(2, 0, 3, 3)]
    ws = (0, 0, 6, 6)
    pl = mk.MotionPlanner(obs, workspace=ws, method="mesh")
    vis = mk.MotionPlanner(obs, workspace=ws, method="visibility")
    pairs = [((0, 0), (2, 2)), ((2, 2), (6, 0)), ((0, 6), (2, 2)), ((2, 2), (2, 1))]
    assert pl.shortest_path((0, 0), (2, 2)).points.tolist() == [[0, 0], [2, 0], [2, 2]]
    check_many(pl, oracle_of(pl), pairs)
    same_as_visibility(pl, vis, pairs)
    pl._core.make_landmarks(4, -1.0)  # the tables hold (2, 2) too
    check_landmark_tables(pl, vis)
    same_as_visibility(pl, vis, pairs)


def test_a_seam_leaving_the_box_is_a_dead_end_inside_it():
    # two blocks stacked against the box's left side, grown by the robot: their C-space
    # seam (y = 1, x from -1 to 1) leaves the box at x = 0; its part inside is free and
    # reaches the free space at (1, 1)
    robot = [(0, 0), (1, 0), (1, 1), (0, 1)]
    obs, ws = [sq(0, 0, 1, 1), sq(0, 2, 1, 3)], (0, 0, 6, 6)
    pl = mk.MotionPlanner(obs, robot=robot, workspace=ws, method="mesh")
    vis = mk.MotionPlanner(obs, robot=robot, workspace=ws, method="visibility")
    pairs = [((0, 1), (0, 3)), ((0.5, 1), (4, 4)), ((0, 1), (0.5, 1)), ((1, 1), (0, 1))]
    assert pl.shortest_path((0, 1), (0, 3)).length == 4.0
    check_many(pl, oracle_of(pl), pairs)
    same_as_visibility(pl, vis, pairs)
    pl._core.make_landmarks(4, -1.0)
    check_landmark_tables(pl, vis)
    same_as_visibility(pl, vis, pairs)


def touching_rectangles(n, rng):
    """n x n rectangles, one per cell of side 100, each side on the cell border with
    probability 0.3 (else 5-29 inside): neighbours and the box share parts of edges."""
    obs = []
    for i in range(n):
        for j in range(n):
            ins = np.where(rng.random(4) < 0.3, 0, rng.integers(5, 30, 4))
            obs.append(sq(100 * i + ins[0], 100 * j + ins[1],
                          100 * (i + 1) - ins[2], 100 * (j + 1) - ins[3]))  # fmt: skip
    return obs


def test_touching_rectangles_at_scale_equal_the_visibility_graph():
    # 400 rectangles, one per cell of a 20 x 20 grid, each side on the cell border with
    # probability 0.3: dozens of passages between neighbours and along the box
    rng = np.random.default_rng(5)
    obs = touching_rectangles(20, rng)
    ws = (0, 0, 2000, 2000)
    mesh = mk.MotionPlanner(obs, workspace=ws, method="mesh")
    assert len(mesh._core.zero_width()) > 50
    vis = mk.MotionPlanner(obs, workspace=ws, method="visibility")
    segs = mesh._core.zero_width()
    # queries in the open, and on the passages (inside segments and at their ends)
    free = [tuple(map(int, p)) for p in rng.integers(0, 2001, (200, 2))]
    free = [p for p in free if mesh.is_free([p]).all()][:60]
    on = [((a + c) / 2, (b + d) / 2) for a, b, c, d in segs[::7].tolist()]
    on += [(a, b) for a, b, _, _ in segs[3::11].tolist()]
    pts = free + on
    pairs = list(zip(pts, pts[::-1]))[: len(pts) // 2] + list(zip(on, free))
    same_as_visibility(mesh, vis, pairs)


def test_bridge_pruning_keeps_lengths_and_prunes():
    # no interval across a bridge of the mesh into a side without the target: the same
    # lengths as the search without it, and far fewer nodes
    occ = _cave(64, 3)
    core = mk.MotionPlanner.from_grid(occ, method="mesh")._core
    free = np.argwhere(~occ)
    rng = np.random.default_rng(4)
    pts = [(c + 0.5, r + 0.5) for r, c in free[rng.integers(len(free), size=120)].tolist()]
    nodes = {True: 0, False: 0}
    core.use_landmarks = core.use_dominance = False  # the bridges alone
    for s, g in zip(pts[0::2], pts[1::2]):
        res = {}
        for prune in (True, False):
            core.prune = prune
            st_, _, path = core.query(*s, *g)
            res[prune] = (st_, float(np.hypot(*np.diff(path, axis=0).T).sum()))
            nodes[prune] += core.counters()[0]
        assert res[True][0] == res[False][0]
        assert math.isclose(res[True][1], res[False][1], rel_tol=1e-12), (s, g)
    core.prune = core.use_landmarks = core.use_dominance = True
    assert nodes[False] > 1.4 * nodes[True], nodes


# --------------------------------------------------------------------------------------
# landmark lower bounds and dominated intervals: the tables are geodesic distances (the
# visibility graph's), and the search with them keeps the visibility graph's lengths


def test_landmarks_and_dominance_keep_lengths_and_prune():
    # touching rectangles in a 16 x 16 grid (streets with zero-width passages): the
    # search with the landmark bounds and the dominance pruning, with either, and with
    # neither gives the same lengths (those of the visibility graph), and the two cut the
    # nodes expanded
    rng = np.random.default_rng(7)
    obs = touching_rectangles(16, rng)
    ws = (0, 0, 1600, 1600)
    pl = mk.MotionPlanner(obs, workspace=ws, method="mesh")
    vis = mk.MotionPlanner(obs, workspace=ws, method="visibility")
    core = pl._core
    assert len(core.landmarks()[0]) == 8  # the streets' detour asks for the tables
    check_landmark_tables(pl, vis)
    free = [tuple(map(int, p)) for p in rng.integers(0, 1601, (300, 2))]
    free = [p for p in free if pl.is_free([p]).all()][:80]
    nodes = {}
    for lmk, dom in [(True, True), (True, False), (False, True), (False, False)]:
        core.use_landmarks, core.use_dominance = lmk, dom
        nodes[lmk, dom] = 0
        for s, g in zip(free[0::2], free[1::2]):
            st_, _, path = core.query(*map(float, s), *map(float, g))
            assert st_ == 0
            got = float(np.hypot(*np.diff(path, axis=0).T).sum())
            assert math.isclose(got, vis.shortest_path(s, g).length, rel_tol=1e-12), (s, g)
            nodes[lmk, dom] += core.counters()[0]
    core.use_landmarks = core.use_dominance = True
    assert nodes[False, False] > 2 * nodes[True, True], nodes
    assert nodes[False, False] > nodes[True, False] and nodes[False, False] > nodes[False, True]


def test_no_landmarks_where_they_would_not_pay():
    # small convex obstacles far apart: probe paths are barely longer than the distance,
    # so no tables are made; a perfect maze: long detours, but the bridges already keep
    # the search on the path, so the tables do not cut the probes' nodes and are dropped
    obs = [sq(100 * i + 40, 100 * j + 40, 100 * i + 50, 100 * j + 50)
           for i in range(10) for j in range(10)]  # fmt: skip
    pl = mk.MotionPlanner(obs, workspace=(0, 0, 1000, 1000), method="mesh")
    assert len(pl._core.landmarks()[0]) == 0
    maze = mk.MotionPlanner.from_grid(_maze(12, 3), method="mesh")
    assert len(maze._core.landmarks()[0]) == 0
    maze._core.make_landmarks(4, -1.0)  # forced: made and kept
    assert len(maze._core.landmarks()[0]) == 4


def test_read_scenario(tmp_path):
    f = tmp_path / "a.map.scen"
    f.write_text("version 1\n3\tmaps/a.map\t4\t5\t0\t1\t3\t4\t4.24264\n\n")
    (q,) = mk.io.read_scenario(f)
    assert q == (3, "maps/a.map", 4, 5, (0, 1), (3, 4), 4.24264)
    f.write_text("version 1\n3 a.map 4 5 0 1 3\n")
    with pytest.raises(InputFormatError, match=r"line 2: expected 'bucket map"):
        mk.io.read_scenario(f)
    f.write_text("version 1\n3 a.map 4 5 0 x 3 4 4.2\n")
    with pytest.raises(InputFormatError, match="line 2"):
        mk.io.read_scenario(f)


def test_io_after_import_minkowski2d_alone():
    # `import minkowski2d as mk` then mk.io.read_grid_map, as the README writes it
    import subprocess
    import sys

    code = (
        "import minkowski2d as mk; "
        "print(mk.io.read_grid_map.__name__, mk.io.read_scenario.__name__)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["read_grid_map", "read_scenario"]
