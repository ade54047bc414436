"""Motion planning: the planner against an exact brute-force reference.

The reference (``Oracle``) is deliberately slow and independent of the core's tricks: a
segment is blocked iff the midpoint of one of its pieces between consecutive crossings
with piece edge lines lies in the open interior of one obstacle's union of pieces; a
point is in that open interior iff some direction test around it is covered (the
directions strictly between consecutive boundary rays). Everything in Python ints and
Fractions. The full visibility graph over every free C-obstacle vertex (no tangent
filter), Dijkstra.
"""

from __future__ import annotations

import functools
import heapq
import math
import os
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import minkowski2d as mk
from minkowski2d.errors import GeometryError, NoPathError, ShapeError

from . import oracle as O

#: scale the example counts for a long local run (PLAN_EXAMPLES_SCALE=20)
_X = int(os.environ.get("PLAN_EXAMPLES_SCALE", "1"))

# --------------------------------------------------------------------------------------
# the exact reference


def cross(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def _half(d):
    return 0 if (d[1] > 0 or (d[1] == 0 and d[0] > 0)) else 1


def _angle_cmp(a, b):
    ha, hb = _half(a), _half(b)
    if ha != hb:
        return -1 if ha < hb else 1
    c = a[0] * b[1] - a[1] * b[0]
    return -1 if c > 0 else (1 if c < 0 else 0)


class Oracle:
    """Exact reference planner on convex pieces (lists of exact CCW vertices)."""

    def __init__(self, pieces, groups, box=None):
        self.pieces = [[(Fraction(x), Fraction(y)) for x, y in p] for p in pieces]
        self.groups = list(groups)
        keep = [i for i, p in enumerate(self.pieces) if len(p) >= 3]
        self.pieces = [self.pieces[i] for i in keep]
        self.groups = [self.groups[i] for i in keep]
        self.bbox = [
            (min(x for x, _ in p), min(y for _, y in p), max(x for x, _ in p), max(y for _, y in p))
            for p in self.pieces
        ]
        self.box = None if box is None else [Fraction(v) for v in box]

    def in_box(self, x):
        b = self.box
        return b is None or (b[0] <= x[0] <= b[2] and b[1] <= x[1] <= b[3])

    def _containing(self, x):
        for i, p in enumerate(self.pieces):
            b = self.bbox[i]
            if not (b[0] <= x[0] <= b[2] and b[1] <= x[1] <= b[3]):
                continue
            if all(cross(p[k], p[(k + 1) % len(p)], x) >= 0 for k in range(len(p))):
                yield i

    def interior_group(self, x):
        """The group whose union has x in its open interior, or None."""
        x = (Fraction(x[0]), Fraction(x[1]))
        by_group: dict[int, list[int]] = {}
        for i in self._containing(x):
            by_group.setdefault(self.groups[i], []).append(i)
        for g, ids in by_group.items():
            rays = []
            for i in ids:
                p = self.pieces[i]
                for k in range(len(p)):
                    a, b = p[k], p[(k + 1) % len(p)]
                    if cross(a, b, x) == 0:
                        d = (b[0] - a[0], b[1] - a[1])
                        rays += [d, (-d[0], -d[1])]
                    if a != x:
                        rays.append((a[0] - x[0], a[1] - x[1]))
            rays.sort(key=functools.cmp_to_key(_angle_cmp))
            uniq = []
            for r in rays:
                if not uniq or _angle_cmp(uniq[-1], r) != 0:
                    uniq.append(r)
            if not uniq:  # x strictly inside a piece with no ray through it
                return g
            covered = True
            for k in range(len(uniq)):
                r1, r2 = uniq[k], uniq[(k + 1) % len(uniq)]
                c = r1[0] * r2[1] - r1[1] * r2[0]
                if len(uniq) > 1 and c > 0:
                    d = (r1[0] + r2[0], r1[1] + r2[1])
                else:
                    d = (-r1[1], r1[0])
                if not any(self._cone_has(self.pieces[i], x, d) for i in ids):
                    covered = False
                    break
            if covered:
                return g
        return None

    @staticmethod
    def _cone_has(p, x, d):
        for k in range(len(p)):
            a, b = p[k], p[(k + 1) % len(p)]
            if cross(a, b, x) == 0:
                e = (b[0] - a[0], b[1] - a[1])
                if e[0] * d[1] - e[1] * d[0] < 0:
                    return False
        return True

    def blocked(self, p, q):
        p = (Fraction(p[0]), Fraction(p[1]))
        q = (Fraction(q[0]), Fraction(q[1]))
        if p == q:
            return self.interior_group(p) is not None
        ts = {Fraction(0), Fraction(1)}
        lo = (min(p[0], q[0]), min(p[1], q[1]))
        hi = (max(p[0], q[0]), max(p[1], q[1]))
        near = [
            i
            for i, b in enumerate(self.bbox)
            if not (b[2] < lo[0] or b[0] > hi[0] or b[3] < lo[1] or b[1] > hi[1])
        ]
        if not near:
            return False
        dq = (q[0] - p[0], q[1] - p[1])
        for i in near:
            P = self.pieces[i]
            for k in range(len(P)):
                a, b = P[k], P[(k + 1) % len(P)]
                e = (b[0] - a[0], b[1] - a[1])
                den = e[0] * dq[1] - e[1] * dq[0]
                if den != 0:
                    t = Fraction(e[0] * (p[1] - a[1]) - e[1] * (p[0] - a[0])) / -den
                    if 0 < t < 1:
                        ts.add(t)
        ts = sorted(ts)
        for t0, t1 in zip(ts, ts[1:]):
            t = (t0 + t1) / 2
            m = (p[0] + t * dq[0], p[1] + t * dq[1])
            if self.interior_group(m) is not None:
                return True
        return False

    def shortest(self, s, g):
        """('start'|'goal', group) for a bad endpoint, None if unreachable, else the length."""
        for name, x in (("start", s), ("goal", g)):
            if not self.in_box((Fraction(x[0]), Fraction(x[1]))):
                return (name, -2)
            gi = self.interior_group(x)
            if gi is not None:
                return (name, gi)
        nodes = [(Fraction(s[0]), Fraction(s[1])), (Fraction(g[0]), Fraction(g[1]))]
        seen = set(nodes)
        for p in self.pieces:
            for v in p:
                if v not in seen and self.in_box(v) and self.interior_group(v) is None:
                    seen.add(v)
                    nodes.append(v)
        dist = [math.inf] * len(nodes)
        dist[0] = 0.0
        heap = [(0.0, 0)]
        done = [False] * len(nodes)
        while heap:
            d, a = heapq.heappop(heap)
            if done[a]:
                continue
            done[a] = True
            if a == 1:
                return d
            for b in range(len(nodes)):
                if done[b]:
                    continue
                w = math.hypot(float(nodes[a][0] - nodes[b][0]), float(nodes[a][1] - nodes[b][1]))
                if d + w < dist[b] and not self.blocked(nodes[a], nodes[b]):
                    dist[b] = d + w
                    heapq.heappush(heap, (d + w, b))
        return None


def oracle_of(planner, exact_pieces=None):
    pieces = exact_pieces
    if pieces is None:
        pieces = [p.tolist() for p in planner.pieces]
    return Oracle(pieces, planner.groups.tolist(), planner.box)


def check_against(planner, orc, s, g):
    ref = orc.shortest(s, g)
    if isinstance(ref, tuple):
        with pytest.raises(GeometryError) as ei:
            planner.shortest_path(s, g)
        assert ei.value.argument == ref[0]
        assert not isinstance(ei.value, NoPathError)
        if ref[1] >= 0 and ref[1] < planner.n_obstacles:
            assert ei.value.obstacle == ref[1]
        return None
    if ref is None:
        with pytest.raises(NoPathError):
            planner.shortest_path(s, g)
        return None
    path = planner.shortest_path(s, g)
    pts = path.points.tolist()
    assert [Fraction(v) for v in pts[0]] == [Fraction(v) for v in s]
    assert [Fraction(v) for v in pts[-1]] == [Fraction(v) for v in g]
    for a, b in zip(pts, pts[1:]):
        assert not orc.blocked(a, b), (a, b)
        assert orc.in_box((Fraction(a[0]), Fraction(a[1])))
    assert math.isclose(path.length, ref, rel_tol=1e-9, abs_tol=1e-12), (path.length, ref)
    return path


# --------------------------------------------------------------------------------------
# scenes


def sq(x0, y0, x1, y1):
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


ROBOT = sq(-1, -1, 1, 1)


def test_docstring_scene_exact_ints():
    pl = mk.MotionPlanner([sq(2, -1, 4, 3)], robot=ROBOT)
    p = pl.shortest_path((0, 0), (6, 0))
    assert p.points.dtype == np.int64
    assert p.points.tolist() == [[0, 0], [1, -2], [5, -2], [6, 0]]


def test_zero_width_passage_is_open():
    # two squares 2 apart, robot 2 wide: the reference point slides along y = 3
    pl = mk.MotionPlanner([sq(0, 0, 2, 2), sq(0, 4, 2, 6)], robot=ROBOT)
    p = pl.shortest_path((-3, 3), (5, 3))
    assert p.points.tolist() == [[-3, 3], [5, 3]]
    assert pl.is_free([(1, 3), (1, 2.5)]).tolist() == [True, False]


def test_pinch_point_gaps_beside_are_open():
    pl = mk.MotionPlanner([sq(0, 0, 2, 2), sq(2, 2, 4, 4)])
    assert pl.shortest_path((0, 4), (4, 0)).points.tolist() == [[0, 4], [4, 0]]
    assert pl.shortest_path((1, 3), (3, 1)).points.tolist() == [[1, 3], [3, 1]]
    orc = oracle_of(pl)
    check_against(pl, orc, (1, 3), (3, 1))


def test_seam_of_l_shape_is_not_a_passage():
    L = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    pl = mk.MotionPlanner([L])
    # the straight segment would run along an internal diagonal (0,0)-(1,1)
    p = pl.shortest_path((-1, -1), (2, 2))
    assert len(p.points) > 2
    assert pl.is_free([(0.5, 0.5), (1, 1), (0, 0), (1.5, 1.5)]).tolist() == [
        False,
        True,
        True,
        True,
    ]
    orc = oracle_of(pl)
    assert orc.blocked((0, 0), (1, 1))
    check_against(pl, orc, (-1, -1), (2, 2))
    check_against(pl, orc, (1, 1), (-1, 3))


def test_start_on_vertex_and_on_edge():
    pl = mk.MotionPlanner([sq(0, 0, 2, 2), sq(3, -1, 4, 3)])
    orc = oracle_of(pl)
    for s in [(2, 2), (2, 0), (1, 2), (2, 1), (0, 1)]:
        for g in [(5, 1), (3, 3), (-1, -1), (3, 1)]:
            check_against(pl, orc, s, g)


def test_start_inside_obstacle_names_it():
    pl = mk.MotionPlanner([sq(10, 10, 11, 11), sq(0, 0, 2, 2)])
    with pytest.raises(GeometryError) as ei:
        pl.shortest_path((1, 1), (5, 5))
    assert ei.value.argument == "start" and ei.value.obstacle == 1
    assert "obstacles[1]" in str(ei.value)
    with pytest.raises(GeometryError) as ei:
        pl.shortest_path((5, 5), (10.5, 10.5))
    assert ei.value.argument == "goal" and ei.value.obstacle == 0


def test_unreachable_pocket():
    ring = [sq(0, 0, 4, 1), sq(0, 3, 4, 4), sq(0, 0, 1, 4), sq(3, 0, 4, 4)]
    pl = mk.MotionPlanner(ring)
    with pytest.raises(NoPathError) as ei:
        pl.shortest_path((2, 2), (5, 5))
    assert isinstance(ei.value, GeometryError)
    assert pl.shortest_path((2, 2), (2.5, 1)).points.tolist() == [[2.0, 2.0], [2.5, 1.0]]
    assert pl.shortest_paths([(2, 2), (5, 5)], (6, 6))[0] is None


def test_workspace_box_and_robot():
    pl = mk.MotionPlanner([sq(4, 0, 6, 8)], robot=ROBOT, workspace=(0, 0, 10, 10))
    # reference box is [1, 9] x [1, 9]; the obstacle reaches the bottom wall
    assert pl.box == [1, 1, 9, 9]
    p = pl.shortest_path((2, 2), (8, 2))
    assert p.points.tolist() == [[2, 2], [3, 9], [7, 9], [8, 2]]
    with pytest.raises(GeometryError) as ei:
        pl.shortest_path((0, 0), (8, 2))
    assert ei.value.argument == "start" and "workspace" in str(ei.value)
    orc = oracle_of(pl)
    check_against(pl, orc, (2, 2), (8, 2))


def test_workspace_polygon():
    # an L-shaped room: the point robot goes around the inner corner
    room = [(0, 0), (10, 0), (10, 4), (4, 4), (4, 10), (0, 10)]
    pl = mk.MotionPlanner([], workspace=room)
    p = pl.shortest_path((8, 2), (2, 8))
    assert p.points.tolist() == [[8, 2], [4, 4], [2, 8]]
    assert pl.is_free([(5, 5), (3, 3), (11, 1), (4, 6)]).tolist() == [False, True, False, True]
    orc = oracle_of(pl)
    check_against(pl, orc, (8, 2), (2, 8))
    # with a square robot the corridor shrinks by the robot
    pl = mk.MotionPlanner([], robot=ROBOT, workspace=room)
    p = pl.shortest_path((8, 2), (2, 8))
    assert p.points.tolist() == [[8, 2], [3, 3], [2, 8]]


def test_non_convex_robot_and_obstacle():
    L = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    U = [(0, 0), (3, 0), (3, 3), (2, 3), (2, 1), (1, 1), (1, 3), (0, 3)]
    pl = mk.MotionPlanner([[(x + 5, y) for x, y in U]], robot=L)
    orc = oracle_of(pl)
    for s, g in [((-3, 0), (10, 1)), ((-3, -3), (9, 5)), ((6, 2), (10, 4))]:
        check_against(pl, orc, s, g)


def test_float_scene_and_float_query_on_int_scene():
    pl = mk.MotionPlanner([sq(2, -1, 4, 3)], robot=ROBOT)
    p = pl.shortest_path((0.5, 0), (6, 0))
    assert p.points.dtype == np.float64
    assert p.points.tolist() == [[0.5, 0.0], [1.0, -2.0], [5.0, -2.0], [6.0, 0.0]]
    plf = mk.MotionPlanner([np.array(sq(2, -1, 4, 3), float) * 0.1], robot=np.array(ROBOT) * 0.1)
    q = plf.shortest_path((0, 0), (0.6, 0))
    assert q.points.dtype == np.float64
    orc = oracle_of(plf)
    check_against(plf, orc, (0.0, 0.0), (0.6, 0.0))


def test_shapely_input_and_batch():
    shapely = pytest.importorskip("shapely")
    obs = [shapely.box(0, 0, 2, 2), shapely.Polygon(sq(3, 0, 5, 2), holes=[sq(3.5, 0.5, 4.5, 1.5)])]
    pl = mk.MotionPlanner(obs)
    paths = pl.shortest_paths([(-1, 1), (4, 1)], [(6, 1), (6, 1)])
    assert paths[0].points[0].tolist() == [-1.0, 1.0]
    assert paths[1] is None  # inside the hole: enclosed
    assert pl.is_free([(4, 1)]).tolist() == [True]
    assert pl.free_space.area > 0


def test_bad_input():
    with pytest.raises(ShapeError):
        mk.MotionPlanner([(0, 0), (1, 0), (0, 1)])  # a polygon, not a list of them
    pl = mk.MotionPlanner([sq(0, 0, 1, 1)])
    with pytest.raises(ShapeError):
        pl.shortest_path((0, 0, 0), (1, 1))
    with pytest.raises(GeometryError):
        mk.MotionPlanner([[(0, 0), (2, 2), (2, 0), (0, 2)]])  # bow tie


def test_same_start_and_goal_and_empty_scene():
    pl = mk.MotionPlanner([])
    assert pl.shortest_path((1, 1), (1, 1)).points.tolist() == [[1, 1]]
    assert pl.shortest_path((0, 0), (3, 4)).length == 5.0


# --------------------------------------------------------------------------------------
# property tests against the oracle

coord = st.integers(0, 8)


@st.composite
def convex_int(draw, lo=0, hi=8, max_n=5):
    pts = draw(
        st.lists(st.tuples(st.integers(lo, hi), st.integers(lo, hi)), min_size=3, max_size=max_n)
    )
    h = O.hull(pts)
    if len(h) < 3:
        x, y = pts[0]
        h = [(x, y), (x + 1, y), (x, y + 1)]
    return [(int(x), int(y)) for x, y in h]


robots = st.sampled_from(
    [None, [(0, 0), (1, 0), (0, 1)], [(-1, 0), (1, 0), (0, 1)], [(0, 0), (1, 0), (1, 1), (0, 1)]]
)


@settings(max_examples=40 * _X, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    obs=st.lists(convex_int(), min_size=1, max_size=4),
    robot=robots,
    box=st.booleans(),
    s=st.tuples(st.integers(-2, 10), st.integers(-2, 10)),
    g=st.tuples(st.integers(-2, 10), st.integers(-2, 10)),
)
def test_random_int_scenes_against_oracle(obs, robot, box, s, g):
    ws = (-2, -2, 10, 10) if box else None
    pl = mk.MotionPlanner(obs, robot=robot, workspace=ws)
    # C-pieces computed independently: the hull of all pairwise sums
    rob = robot if robot is not None else [(0, 0)]
    neg = [(-x, -y) for x, y in rob]
    exact = [O.minkowski_sum(o, neg) for o in obs]
    assert sorted(map(tuple, exact)) == sorted(
        tuple((Fraction(x), Fraction(y)) for x, y in p.tolist()) for p in pl.pieces
    )
    orc = Oracle(exact, list(range(len(obs))), pl.box)
    check_against(pl, orc, s, g)


@settings(max_examples=15 * _X, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    obs=st.lists(convex_int(), min_size=1, max_size=3),
    s=st.tuples(st.integers(-2, 10), st.integers(-2, 10)),
    g=st.tuples(st.integers(-2, 10), st.integers(-2, 10)),
    scale=st.sampled_from([0.1, 0.3, 1e-5, 1e-290, 1e250, 3.0**-40]),
)
def test_random_float_scenes_against_oracle(obs, s, g, scale):
    fobs = [np.array(o, dtype=float) * scale + 0.25 for o in obs]
    robot = np.array([(0.0, 0.0), (0.5, 0.0), (0.0, 0.5)]) * scale
    pl = mk.MotionPlanner(fobs, robot=robot)
    orc = oracle_of(pl)
    check_against(pl, orc, (s[0] * scale, s[1] * scale), (g[0] * scale, g[1] * scale))


@st.composite
def l_shapes(draw):
    x = draw(st.integers(0, 6))
    y = draw(st.integers(0, 6))
    a = draw(st.integers(2, 3))
    b = draw(st.integers(1, a - 1))
    L = [(0, 0), (a, 0), (a, b), (b, b), (b, a), (0, a)]
    k = draw(st.integers(0, 3))
    for _ in range(k):
        L = [(-yy, xx) for xx, yy in L]
    return [(xx + x, yy + y) for xx, yy in L]


@settings(max_examples=25 * _X, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    obs=st.lists(st.one_of(l_shapes(), convex_int()), min_size=1, max_size=3),
    s=st.tuples(st.integers(-3, 10), st.integers(-3, 10)),
    g=st.tuples(st.integers(-3, 10), st.integers(-3, 10)),
)
def test_non_convex_point_robot_against_oracle(obs, s, g):
    pl = mk.MotionPlanner(obs)
    orc = oracle_of(pl)
    check_against(pl, orc, s, g)


@settings(max_examples=60 * _X, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    obs=st.lists(st.one_of(l_shapes(), convex_int()), min_size=1, max_size=3),
    robot=robots,
    segs=st.lists(
        st.tuples(
            st.integers(-3, 10), st.integers(-3, 10), st.integers(-3, 10), st.integers(-3, 10)
        ),
        min_size=1,
        max_size=12,
    ),
)
def test_visibility_and_location_predicates_against_oracle(obs, robot, segs):
    pl = mk.MotionPlanner(obs, robot=robot)
    orc = oracle_of(pl)
    # segments between grid points and between C-obstacle vertices: many run along edges
    # and seams, through vertices and pinch points
    verts = pl.pieces.coords.tolist()
    for k, (a, b, c, d) in enumerate(segs):
        p, q = (a, b), (c, d)
        if verts:
            q2 = tuple(verts[(a * 31 + b * 7 + k) % len(verts)])
            p2 = tuple(verts[(c * 13 + d * 5 + k) % len(verts)])
        else:
            p2, q2 = p, q
        for u, v in ((p, q), (p, q2), (p2, q2)):
            got = pl._core.segment_free(*u, *v)
            assert got == (not orc.blocked(u, v)), (u, v)
        for x in (p, q2, ((a + c) / 2, (b + d) / 2)):
            want = orc.interior_group(x)
            loc = int(pl.locate([x])[0])
            assert loc == (-1 if want is None else want), x


# --------------------------------------------------------------------------------------
# CLI


@pytest.fixture
def scene_file(tmp_path):
    import json

    f = tmp_path / "scene.json"
    f.write_text(
        json.dumps(
            {
                "robot": ROBOT,
                "obstacles": [
                    sq(2, -1, 4, 3),
                    {"type": "Polygon", "coordinates": [sq(8, 8, 9, 9)]},
                ],
                "workspace": [-10, -10, 10, 10],
            }
        )
    )
    return str(f)


def test_cli_plan_json_geojson_svg(scene_file, capsys, tmp_path):
    import json

    from minkowski2d.cli import main

    assert main(["plan", scene_file, "--start", "0,0", "--goal", "6,0"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["path"] == [[0.0, 0.0], [1.0, -2.0], [5.0, -2.0], [6.0, 0.0]]
    assert math.isclose(out["length"], 4 + 2 * math.sqrt(5))
    assert main(["plan", scene_file, "--start=-1,0", "--goal", "6,0", "--format", "geojson"]) == 0
    fc = json.loads(capsys.readouterr().out)
    roles = [f["properties"]["role"] for f in fc["features"]]
    assert roles.count("obstacle") == 2 and roles.count("c-obstacle") == 2 and "path" in roles
    svg = tmp_path / "plan.svg"
    assert main(["plan", scene_file, "--start", "0,0", "--goal", "6,0", "-o", str(svg)]) == 0
    text = svg.read_text()
    assert text.startswith("<svg") and "<polyline" in text and text.count("<path") >= 4


def test_cli_plan_int_scene_and_errors(tmp_path, capsys):
    import json

    from minkowski2d.cli import main

    f = tmp_path / "ring.json"
    ring = [sq(0, 0, 4, 1), sq(0, 3, 4, 4), sq(0, 0, 1, 4), sq(3, 0, 4, 4)]
    f.write_text(json.dumps({"obstacles": ring}))
    assert main(["plan", str(f), "--start", "2,2", "--goal", "3,2"]) == 0
    assert json.loads(capsys.readouterr().out)["path"] == [[2, 2], [3, 2]]
    assert main(["plan", str(f), "--start", "2,2", "--goal", "5,5"]) == 2
    assert "cannot be reached" in capsys.readouterr().err
    assert main(["plan", str(f), "--start", "0.5,0.5", "--goal", "5,5"]) == 2
    err = capsys.readouterr().err
    assert "--start" in err and "obstacles[0]" in err
    assert main(["plan", str(f), "--start", "x", "--goal", "5,5"]) == 2
    bad = tmp_path / "bad.json"
    bad.write_text("{")
    assert main(["plan", str(bad), "--start", "0,0", "--goal", "5,5"]) == 2
    assert "not JSON" in capsys.readouterr().err
    bad.write_text(json.dumps({"obstacles": [[[0, 0], [2, 2], [2, 0], [0, 2]]]}))
    assert main(["plan", str(bad), "--start=-1,-1", "--goal", "5,5"]) == 2
    assert "obstacles[0]" in capsys.readouterr().err


def test_cli_plan_feature_collection(tmp_path, capsys):
    import json

    from minkowski2d.cli import main

    fc = {
        "type": "FeatureCollection",
        "features": [
            {
                "type": "Feature",
                "properties": {"role": "robot"},
                "geometry": {"type": "Polygon", "coordinates": [ROBOT]},
            },
            {
                "type": "Feature",
                "properties": {},
                "geometry": {"type": "Polygon", "coordinates": [sq(2, -1, 4, 3)]},
            },
        ],
    }
    f = tmp_path / "scene.geojson"
    f.write_text(json.dumps(fc))
    assert main(["plan", str(f), "--start", "0,0", "--goal", "6,0"]) == 0
    assert json.loads(capsys.readouterr().out)["path"][1] == [1.0, -2.0]


ROOMS = [
    None,
    (-3, -3, 11, 11),
    [(-3, -3), (11, -3), (11, 4), (4, 4), (4, 11), (-3, 11)],
    [(-3, -3), (11, -3), (11, 11), (6, 11), (6, 6), (2, 6), (2, 11), (-3, 11)],
]


@settings(max_examples=20 * _X, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    obs=st.lists(st.one_of(l_shapes(), convex_int()), min_size=0, max_size=3),
    robot=st.sampled_from(
        [None, [(0, 0), (1, 0), (1, 2), (0, 2)], [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]]
    ),
    room=st.sampled_from(ROOMS),
    s=st.tuples(st.integers(-3, 10), st.integers(-3, 10)),
    g=st.tuples(st.integers(-3, 10), st.integers(-3, 10)),
)
def test_non_convex_robot_and_workspace_against_oracle(obs, robot, room, s, g):
    pl = mk.MotionPlanner(obs, robot=robot, workspace=room)
    orc = oracle_of(pl)
    check_against(pl, orc, s, g)
    # the batch gives the same answers as single queries
    res = None
    try:
        res = pl.shortest_paths([s], [g])[0]
    except GeometryError:
        pass
    if res is not None:
        assert res.points.tolist() == pl.shortest_path(s, g).points.tolist()


def test_plot_is_lazy_and_works():
    plt = pytest.importorskip("matplotlib.pyplot")
    pl = mk.MotionPlanner([sq(2, -1, 4, 3)], robot=ROBOT, workspace=(-5, -5, 10, 10))
    ax = pl.plot(path=pl.shortest_path((0, 0), (6, 0)))
    assert len(ax.lines) >= 2
    plt.close("all")


def test_core_hulls_a_folded_piece():
    # a "piece" with a collinear and a reflex vertex (as a rounded float sum could be) is
    # replaced by its convex hull: the core's primitives need strictly convex pieces
    from minkowski2d._core import _ext

    core = _ext.PlannerF()
    piece = np.array([[0, 0], [1, 0], [2, 0], [2, 2], [1, 1.9], [0, 2]], dtype=np.float64)
    core.build(piece, np.array([0, 6]), np.array([0]), np.zeros(0))
    assert sorted(map(tuple, core.candidates().tolist())) == [(0, 0), (0, 2), (2, 0), (2, 2)]
    assert not core.segment_free(1.0, 1.95, 1.0, 3.0)  # inside the hull, outside the fold
    assert core.segment_free(-1.0, 2.0, 3.0, 2.0)  # along the hull's top edge


def test_threads_give_the_same_graph():
    rng = np.random.default_rng(5)
    obs = []
    for i in range(6):
        for j in range(6):
            c = np.array([i * 10 + 5, j * 10 + 5]) + rng.integers(-2, 3, 2)
            r = int(rng.integers(2, 5))
            obs.append([tuple(c + d) for d in [(-r, -r), (r, -r + 1), (r - 1, r), (-r, r - 2)]])
    a = mk.MotionPlanner(obs, threads=1)._core.adjacency()
    b = mk.MotionPlanner(obs, threads=2)._core.adjacency()
    ea = {(i, int(j)) for i in range(len(a[0]) - 1) for j in a[1][a[0][i] : a[0][i + 1]]}
    eb = {(i, int(j)) for i in range(len(b[0]) - 1) for j in b[1][b[0][i] : b[0][i + 1]]}
    assert ea == eb and len(ea) > 100


@pytest.mark.parametrize("shift", [0, 2**40, -(2**59)])
def test_large_int_coordinates_stay_exact(shift):
    k = 2**57
    obs = [[(x * k + shift, y * k + shift) for x, y in sq(2, -1, 4, 3)]]
    robot = [(x * k, y * k) for x, y in ROBOT]
    pl = mk.MotionPlanner(obs, robot=robot)
    s, g = (shift, shift), (6 * k + shift, shift)
    p = pl.shortest_path(s, g)
    assert p.points.dtype == np.int64
    want = [(0, 0), (1, -2), (5, -2), (6, 0)]
    assert p.points.tolist() == [[x * k + shift, y * k + shift] for x, y in want]
    orc = oracle_of(pl)
    for a, b in zip(p.points.tolist(), p.points.tolist()[1:]):
        assert not orc.blocked(a, b)
    with pytest.raises(ShapeError):
        mk.MotionPlanner([[(0, 0), (2**62, 0), (0, 1)]], robot=[(-1, 0), (0, 0), (0, -1)])


def test_geoseries_and_object_array_input():
    shapely = pytest.importorskip("shapely")
    geoms = np.array([shapely.box(2, -1, 4, 3), shapely.box(10, 10, 11, 11)], dtype=object)
    pl = mk.MotionPlanner(geoms, robot=ROBOT)
    assert pl.shortest_path((0, 0), (6, 0)).points.tolist()[1] == [1.0, -2.0]
    gpd = pytest.importorskip("geopandas")
    gs = gpd.GeoSeries(list(geoms), index=[7, 9])
    pl = mk.MotionPlanner(gs, robot=ROBOT)
    assert pl.shortest_path((0, 0), (6, 0)).points.tolist()[1] == [1.0, -2.0]


def test_locate_names_the_lowest_of_overlapping_obstacles():
    # (0.5, 0.5) is inside both C-obstacles: the answer does not depend on the grid's order
    L = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    T = [(0, 0), (2, 0), (0, 1)]
    for obs in ([L, T], [T, L], [T, L, T]):
        pl = mk.MotionPlanner(obs)
        got = pl.locate([(0.5, 0.5), (1.0, 0.25), (1.5, 0.5), (0.5, 1.5), (3, 3)]).tolist()
        assert got == [0, 0, obs.index(L), obs.index(L), -1]
