"""Reliability: one regression test per reproducer of the library's
classes 1, 2, 4, 5, 7 and 8 (the command line, the server and the overlay have their own
files), plus property tests where a class is open-ended."""

from __future__ import annotations

import math
import warnings
from fractions import Fraction

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from shapely.geometry import LineString, Point, Polygon

import minkowski2d as mk
from minkowski2d.errors import (
    EmptyGeometryError,
    GeometryError,
    NonFiniteError,
    NoPathError,
    OptionError,
    OverflowGeometryError,
    ShapeError,
)

L = [(0, 0), (3, 0), (3, 1), (1, 1), (1, 3), (0, 3)]
SQ = [(0, 0), (1, 0), (1, 1), (0, 1)]
#: the issue's L-shaped workspace
W_L = [(0, 0), (10, 0), (10, 5), (5, 5), (5, 10), (0, 10)]

SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])


# --------------------------------------------------------------------------------------
# class 1: the planner's workspace is honoured exactly, for every robot


def test_point_robot_path_stays_in_a_polygon_workspace():
    pl = mk.MotionPlanner([], workspace=W_L)
    with pytest.raises(GeometryError, match="outside the workspace") as e:
        pl.shortest_path((20, 20), (-10, 20))
    assert e.value.argument == "start" and not isinstance(e.value, NoPathError)


def test_locate_calls_the_frame_corner_outside():
    pl = mk.MotionPlanner([], workspace=W_L)
    # -2 outside the box (the frame's corner), 0 (n_obstacles) in the workspace's outside
    assert pl.locate([(20, 20), (15, 15), (7, 7), (5, 5), (2, 2)]).tolist() == [-2, 0, 0, -1, -1]
    assert pl.is_free([(20, 20), (-10, 20), (10, 0)]).tolist() == [False, False, True]


def test_goal_outside_the_workspace_is_named_not_no_path():
    pl = mk.MotionPlanner([], workspace=W_L)
    with pytest.raises(GeometryError, match="outside the workspace") as e:
        pl.shortest_path((9, 1), (20, 20))
    assert e.value.argument == "goal" and not isinstance(e.value, NoPathError)
    # around the corner inside the L: a path, bending at the reflex vertex
    assert pl.shortest_path((9, 2), (2, 9)).points.tolist() == [[9, 2], [5, 5], [2, 9]]


def test_corridor_exactly_as_wide_as_the_robot_is_open():
    # two rooms joined by a corridor exactly one unit wide; a unit square robot slides
    # through it (its reference point, the lower left corner, on the line x = 2)
    W = [(0, 0), (5, 0), (5, 2), (3, 2), (3, 6), (5, 6), (5, 8), (0, 8), (0, 6), (2, 6)]
    W += [(2, 2), (0, 2)]
    pl = mk.MotionPlanner([], robot=SQ, workspace=W)
    assert pl.shortest_path((0, 0), (0, 7)).points.tolist() == [[0, 0], [2, 1], [2, 6], [0, 7]]
    assert pl.is_free([(2, 3), (2.5, 3), (1.5, 3)]).tolist() == [True, False, False]


ROBOTS = [
    None,
    [(0, 0), (1, 0)],
    [(0, 0), (0, 1)],
    [(0, 0), (1, 1)],
    [(0, 0), (1, 0), (0, 1)],
    SQ,
    [(1, 1), (2, 1), (2, 2)],  # the reference point outside the robot
    [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)],  # not convex
]


def _robot_at(R, p):
    if R is None:
        return Point(p)
    pts = [(x + p[0], y + p[1]) for x, y in R]
    return LineString(pts) if len(pts) == 2 else Polygon(pts)


def _swept(R, a, b):
    """The robot's trace along the segment ab, as convex pieces."""
    if R is None:
        return [LineString([a, b]) if tuple(a) != tuple(b) else Point(a)]
    pieces = (
        [R]
        if mk.is_convex(R)
        else [[(0, 0), (2, 0), (2, 1), (0, 1)], [(0, 0), (1, 0), (1, 2), (0, 2)]]
    )
    return [
        shapely.MultiPoint([(x + p[0], y + p[1]) for x, y in q for p in (a, b)]).convex_hull
        for q in pieces
    ]


@st.composite
def rectilinear_workspace(draw):
    """A simple polygon (holes allowed) made of a few unit-grid rectangles."""
    rects = []
    for _ in range(draw(st.integers(1, 4))):
        x0, y0 = draw(st.integers(0, 8)), draw(st.integers(0, 8))
        rects.append(
            shapely.box(x0, y0, x0 + draw(st.integers(1, 5)), y0 + draw(st.integers(1, 5)))
        )
    W = shapely.union_all(rects)
    if W.geom_type != "Polygon":
        W = max(W.geoms, key=lambda g: g.area)
    return shapely.simplify(W, 0)


@SETTINGS
@given(W=rectilinear_workspace(), R=st.sampled_from(ROBOTS), data=st.data())
def test_workspace_honoured_exactly_for_every_robot(W, R, data):
    """is_free is exactly "the robot at p lies in W" (GEOS decides exactly on these small
    half-integers), and every path's sweep stays in W."""
    pl = mk.MotionPlanner([], robot=R, workspace=W)
    pts = [(x / 2, y / 2) for x in range(-4, 30, 1) for y in range(-4, 30, 3)]
    free = pl.is_free(pts)
    for p, f in zip(pts, free):
        assert bool(f) == W.covers(_robot_at(R, p)), (p, bool(f))
    fr = [p for p, f in zip(pts, free) if f]
    if len(fr) < 2:
        return
    s = data.draw(st.sampled_from(fr))
    g = data.draw(st.sampled_from(fr))
    try:
        path = pl.shortest_path(s, g)
    except NoPathError:
        return
    P = path.points.astype(float).tolist()
    for a, b in zip(P, P[1:]):
        assert all(W.covers(piece) for piece in _swept(R, a, b)), (a, b)


# --------------------------------------------------------------------------------------
# class 2: lengths never overflow into a wrong answer or inf

T300 = [(0.0, 0.0), (1e300, 0.0), (0.0, 1e300)]


def test_path_found_when_lengths_pass_float64():
    pl = mk.MotionPlanner([T300], T300)
    path = pl.shortest_path((-1e308, -1e308), (1e308, 1e308))
    pts = path.points.tolist()
    assert pts[0] == [-1e308, -1e308] and pts[-1] == [1e308, 1e308] and len(pts) == 3
    assert pts[1] in ([-1e300, 1e300], [1e300, -1e300])
    for a, b in zip(pts, pts[1:]):
        assert pl._core.segment_free(*a, *b)
    with pytest.raises(OverflowGeometryError, match="length"):
        path.length  # noqa: B018 - 2.8e308: no float64, and never inf


def test_length_beyond_float64_is_an_error_not_inf():
    pl = mk.MotionPlanner([], workspace=(-1e308, -1e308, 1e308, 1e308))
    path = pl.shortest_path((-1e308, -1e308), (1e308, 1e308))
    assert path.points.tolist() == [[-1e308, -1e308], [1e308, 1e308]]
    with pytest.raises(OverflowGeometryError):
        path.length  # noqa: B018
    path = pl.shortest_path((-1e308, 0.0), (1e308, 0.0))
    with pytest.raises(OverflowGeometryError):
        path.length  # noqa: B018 - 2e308
    assert pl.shortest_path((-8e307, 0.0), (8e307, 0.0)).length == 1.6e308


def test_shortest_route_chosen_at_huge_scale():
    # the same scene at 1 and at 2**1000: the same bends (lengths compared rescaled)
    obs = [[(2, -1), (4, -1), (4, 3), (2, 3)], [(6, -3), (7, -3), (7, 0), (6, 0)]]
    robot = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
    s, g = (0, 0), (9, 1)
    ref = mk.MotionPlanner(obs, robot).shortest_path(s, g).points.tolist()
    k = 2.0**1000
    big = [[(x * k, y * k) for x, y in o] for o in obs]
    out = mk.MotionPlanner(big, [(x * k, y * k) for x, y in robot]).shortest_path(
        (s[0] * k, s[1] * k), (g[0] * k, g[1] * k)
    )
    assert (out.points / k).tolist() == ref


@SETTINGS
@given(
    pts=st.lists(
        st.tuples(st.integers(-(2**70), 2**70), st.integers(-(2**70), 2**70)),
        min_size=2,
        max_size=6,
    ),
    e=st.integers(-1074, 900),
)
def test_path_length_is_the_exact_length_correctly_rounded(pts, e):
    """Each segment's exact length correctly rounded (coordinates from subnormals to
    2**970), summed with fsum; ints beyond 2**53 exactly."""
    for P in (
        np.array([[math.ldexp(x, e) for x in p] for p in pts]),
        np.array(pts, dtype=object),
    ):
        ref = []
        for a, b in zip(P.tolist(), P.tolist()[1:]):
            dx = Fraction(b[0]) - Fraction(a[0])
            dy = Fraction(b[1]) - Fraction(a[1])
            ref.append(_rounded_sqrt(dx * dx + dy * dy))
        assert mk.Path(P).length == math.fsum(ref)


def _rounded_sqrt(q: Fraction) -> float:
    """sqrt(q) rounded to nearest, ties to even: the candidate is moved until both
    midpoints to its neighbours bracket sqrt(q) (compared exactly, squared)."""
    if q == 0:
        return 0.0
    from decimal import Decimal, localcontext

    with localcontext() as ctx:  # a start near the answer, at any magnitude
        ctx.prec = 50
        c = float(Decimal(q.numerator).sqrt() / Decimal(q.denominator).sqrt())

    def even(x: float) -> bool:
        return int(Fraction(x) / Fraction(math.ulp(x))) % 2 == 0

    for _ in range(2000):
        lo, hi = math.nextafter(c, 0), math.nextafter(c, math.inf)
        mlo, mhi = (Fraction(lo) + Fraction(c)) / 2, (Fraction(c) + Fraction(hi)) / 2
        if q < mlo * mlo or (q == mlo * mlo and not even(c)):
            c = lo
        elif q > mhi * mhi or (q == mhi * mhi and not even(c)):
            c = hi
        else:
            return c
    raise AssertionError("no convergence")


# --------------------------------------------------------------------------------------
# class 4: offset never returns inf


def test_offset_overflow_is_an_error():
    big = [(0, 0), (1e308, 0), (1e308, 1e308), (0, 1e308)]
    with pytest.raises(OverflowGeometryError):
        mk.offset(big, 1e308, tolerance=1e305)
    with pytest.raises(OverflowGeometryError):
        mk.offset_arcs(big, 1e308)
    # a shrink at the same magnitude fits
    g = mk.offset(big, -1e307, tolerance=1e305)
    assert np.isfinite(shapely.get_coordinates(g)).all() and g.area > 0


# --------------------------------------------------------------------------------------
# the default offset tolerance: 1e-3 |r|, with the one-sided guarantee


@pytest.mark.parametrize("r", [2.0, -0.4, 3])
def test_offset_default_tolerance_keeps_the_guarantee(r):
    eps, a = 1e-3 * abs(r), abs(r)
    P = shapely.Polygon(L)
    ref = P if r > 0 else P.boundary
    for approx in ("outer", "inner"):
        g = mk.offset(L, r, approx=approx)
        assert g.equals(mk.offset(L, r, tolerance=eps, approx=approx))
        d = shapely.distance(ref, shapely.points(shapely.get_coordinates(g)))
        # the result's boundary is in the band on the side approx names: beyond the true
        # boundary for a grow's outer and a shrink's inner result, short of it otherwise
        lo, hi = (a, a + eps) if (approx == "outer") == (r > 0) else (a - eps, a)
        assert d.min() >= lo - 1e-12 and d.max() <= hi + 1e-12, (approx, d.min(), d.max())
    arcs = mk.offset_arcs(L, r)
    outer, inner = mk.offset(L, r), mk.offset(L, r, approx="inner")
    assert inner.area <= arcs.area <= outer.area


def test_offset_default_tolerance_far_from_the_origin():
    # 1e-3 * r is below what float64 guarantees at 1e12 (0.012 since the core certifies its
    # pieces exactly, docs/offset.md; at 1e9 when GEOS rounded): the default is raised
    far = [(x + 1e12, y) for x, y in L]
    g = mk.offset(far, 0.5)
    assert g.contains(shapely.Polygon(far).buffer(0.5 - 1e-3, quad_segs=64))
    with pytest.raises(GeometryError) as e:  # a given tolerance is not silently raised
        mk.offset(far, 0.5, tolerance=5e-4)
    assert e.value.argument == "tolerance"
    with pytest.raises(GeometryError) as e:  # nor can a radius below the rounding be met
        mk.offset(far, 1e-7)
    assert e.value.argument == "distance"


# --------------------------------------------------------------------------------------
# class 5: foreign exceptions become minkowski2d errors

TINY = 2.0**-540


def test_planner_non_convex_obstacle_at_tiny_scale():
    # GEOS's triangulation failed at this scale (a GEOSException escaped); the core's
    # exact triangulation has no scale
    pl = mk.MotionPlanner([[(x * TINY, y * TINY) for x, y in L]])
    p = pl.shortest_path((-TINY, -TINY), (4 * TINY, 4 * TINY))
    assert len(p) == 3  # around the L's corner


def test_planner_non_convex_robot_at_tiny_scale():
    pl = mk.MotionPlanner([], robot=[(x * TINY, y * TINY) for x, y in L])
    assert pl.shortest_path((0, 0), (1, 1)).points.tolist() == [[0, 0], [1, 1]]


def test_empty_shapely_point_query():
    pl = mk.MotionPlanner([SQ])
    with pytest.raises(EmptyGeometryError) as e:
        pl.shortest_path(shapely.Point(), (5, 5))
    assert e.value.argument == "start"
    with pytest.raises(EmptyGeometryError):
        pl.shortest_path((5, 5), shapely.Point())


def test_one_point_workspace():
    with pytest.raises(ShapeError) as e:
        mk.MotionPlanner([], workspace=[(1, 1)])
    assert e.value.argument == "workspace"
    with pytest.raises(ShapeError):
        mk.MotionPlanner([], workspace=[(1, 1), (2, 2)])


def test_no_fit_polygons_with_a_none_part():
    out = mk.no_fit_polygons([L, None])
    assert out[(1, 0, 0, 0)] is None and out[(0, 0, 1, 0)] is None and out[(1, 0, 1, 0)] is None
    assert out[(0, 0, 0, 0)].equals(mk.no_fit_polygons([L])[(0, 0, 0, 0)])


def test_no_fit_polygons_with_an_empty_part():
    with pytest.raises(EmptyGeometryError) as e:
        mk.no_fit_polygons([L, []])
    assert e.value.argument == "parts[1]"


def test_no_fit_polygons_of_a_geoseries_holding_none():
    gpd = pytest.importorskip("geopandas")
    out = mk.no_fit_polygons(gpd.GeoSeries([shapely.Polygon(L), None]))
    assert out[(0, 0, 1, 0)] is None and out[(0, 0, 0, 0)].area > 0


def test_offset_distance_beyond_float():
    with pytest.raises(OverflowGeometryError) as e:
        mk.offset(L, 2**1100, tolerance=1)
    assert e.value.argument == "distance"


def test_offset_coordinates_beyond_float():
    with pytest.raises(OverflowGeometryError) as e:
        mk.offset([(x * 2**1030, y * 2**1030) for x, y in L], 1, tolerance=1)
    assert e.value.argument == "polygon"
    with pytest.raises(OverflowGeometryError):
        mk.offset([(Fraction(10**400) * x, y) for x, y in L], 1, tolerance=1)


def test_offset_of_a_subnormal_square():
    sq = [(0, 0), (5e-324, 0), (5e-324, 5e-324), (0, 5e-324)]
    for d in (5e-324, 1e-320):
        with pytest.raises(OverflowGeometryError, match="underflow"):
            mk.offset(sq, d, tolerance=5e-324)
        with pytest.raises(OverflowGeometryError, match="underflow"):
            mk.offset(sq, d, join="miter")
    assert mk.offset(sq, -5e-324, tolerance=5e-324).is_empty  # a shrink erases it
    with pytest.raises(OverflowGeometryError, match="underflow"):
        mk.offset_arcs(sq, 5e-324)
    # near 1 it is an ordinary offset (the square is a point at this scale)
    g = mk.offset(sq, 1, tolerance=0.01)
    assert g.contains(shapely.Point(0, 0).buffer(0.99))


def test_offset_arcs_area_at_1e300():
    arcs = mk.offset_arcs([(x * 1e300, y * 1e300) for x, y in L], 1e300)
    with pytest.raises(OverflowGeometryError):
        arcs.area  # noqa: B018 - about 2e601
    # computed rescaled: an area that fits comes out although x * y overflows on the way
    arcs = mk.offset_arcs([(x * 1e150, y * 1e150) for x, y in L], 1e150)
    ref = mk.offset_arcs(L, 1).area
    assert math.isclose(arcs.area, ref * 1e300, rel_tol=1e-12)


def test_rotation_inf_is_an_option_error():
    with pytest.raises(OptionError) as e:
        mk.no_fit_polygons([L, L], rotations=(math.inf,))
    assert e.value.argument.startswith("rotations")


def test_huge_rotation_is_reduced_exactly():
    angle = 2**1100 + 1
    out = mk.no_fit_polygons([L, L], rotations=(angle,))
    ref = mk.no_fit_polygons([L, L], rotations=(angle % 360,))
    assert list(out) == [(i, angle, j, angle) for i in range(2) for j in range(2)]
    for (i, _, j, _), g in out.items():
        assert g.equals(ref[(i, angle % 360, j, angle % 360)])


# --------------------------------------------------------------------------------------
# class 7: options


@pytest.mark.parametrize("value", ["x", None, 3])
def test_bad_join(value):
    with pytest.raises(OptionError) as e:
        mk.offset(SQ, 1, join=value)
    assert e.value.argument == "join" and "'round'" in e.value.allowed
    assert isinstance(e.value, ValueError) and isinstance(e.value, TypeError)


@pytest.mark.parametrize("value", ["middle", None])
def test_bad_approx(value):
    with pytest.raises(OptionError) as e:
        mk.offset(SQ, 1, approx=value)
    assert e.value.argument == "approx" and "'outer'" in str(e.value)


@pytest.mark.parametrize(
    "call",
    [
        lambda m: mk.intersects(SQ, SQ, method=m),
        lambda m: mk.intersects_many([SQ], [SQ], method=m),
        lambda m: mk.minkowski_sum_general(L, L, method=m),
        lambda m: mk.minkowski_sum_general_many([L], [L], method=m),
        lambda m: mk.convex_decomposition(L, method=m),
    ],
)
def test_bad_method(call):
    with pytest.raises(OptionError) as e:
        call("fastest")
    assert e.value.argument == "method" and "fastest" in str(e.value)


BATCH = [
    lambda t: mk.minkowski_sum_many([SQ], [SQ], threads=t),
    lambda t: mk.intersects_many([SQ], [SQ], threads=t),
    lambda t: mk.distance_many([SQ], [SQ], threads=t),
    lambda t: mk.penetration_many([SQ], [SQ], threads=t),
    lambda t: mk.minkowski_sum_general_many([L], [L], threads=t),
    lambda t: mk.no_fit_polygons([L], threads=t),
    lambda t: mk.MotionPlanner([SQ], threads=t),
]


@pytest.mark.parametrize("call", BATCH)
@pytest.mark.parametrize("value", [0, -1, 2**40, "a", None, 2.0, True])
def test_bad_threads(call, value):
    with pytest.raises(OptionError) as e:
        call(value)
    assert e.value.argument == "threads" and e.value.allowed == "an int from 1 to 1024"


@pytest.mark.parametrize("call", BATCH)
@pytest.mark.parametrize("value", [np.int64(2), np.int32(1), np.uint8(2)])
def test_numpy_ints_are_ints(call, value):
    call(value)


@pytest.mark.parametrize(
    "call",
    [
        lambda p: mk.minkowski_sum_many([SQ], [SQ], progress=p),
        lambda p: mk.intersects_many([SQ], [SQ], progress=p),
        lambda p: mk.minkowski_sum_general_many([L], [L], progress=p),
        lambda p: mk.no_fit_polygons([L], progress=p),
    ],
)
def test_bad_progress(call):
    with pytest.raises(OptionError) as e:
        call(5)
    assert e.value.argument == "progress"
    assert isinstance(e.value, TypeError)  # as before: progress=5 was a TypeError


@pytest.mark.parametrize(
    "rotations, where",
    [
        ((math.nan,), "rotations[0]"),
        (("x",), "rotations[0]"),
        (None, "rotations"),
        ((), "rotations[0]"),
        ([(0,), (0,), (0,)], "rotations"),
        ([(0,), ()], "rotations[1]"),
        ([(0,), ("a",)], "rotations[1][0]"),
    ],
)
def test_bad_rotations(rotations, where):
    with pytest.raises(OptionError) as e:
        mk.no_fit_polygons([L, L], rotations=rotations)
    assert e.value.argument == where


@pytest.mark.parametrize(
    "pairs, where",
    [
        ([(0, 5)], "pairs[0]"),
        ([("a", 0)], "pairs[0]"),
        ([None], "pairs[0]"),
        ([(0,)], "pairs[0]"),
        ([(0, 1), (math.nan, 0)], "pairs[1]"),
        ([(-1, 0)], "pairs[0]"),
        (5, "pairs"),
    ],
)
def test_bad_pairs(pairs, where):
    with pytest.raises(OptionError) as e:
        mk.no_fit_polygons([L, L], pairs=pairs)
    assert e.value.argument == where


def test_numpy_ints_in_pairs_and_rotations():
    out = mk.no_fit_polygons(
        [L, L], pairs=[(np.int64(0), np.int32(1))], rotations=np.array([0, 90])
    )
    assert len(out) == 4 and all(g.area > 0 for g in out.values())


def test_nan_query_point_and_workspace():
    pl = mk.MotionPlanner([SQ])
    for bad in ((math.nan, 0), (0, math.inf), (np.float32("nan"), 1)):
        with pytest.raises(NonFiniteError):
            pl.shortest_path(bad, (5, 5))
        with pytest.raises(NonFiniteError):
            pl.is_free([bad])
    with pytest.raises(NonFiniteError):
        mk.MotionPlanner([SQ], workspace=(math.nan, 0, 5, 5))
    with pytest.raises(NonFiniteError):
        mk.MotionPlanner([SQ], workspace=[(math.nan, 0), (5, 0), (5, 5)])


def test_ragged_offsets_must_be_integers():
    with pytest.raises(ShapeError, match="offsets must be integers"):
        mk.Ragged(np.zeros((3, 2)), [0, 1.5, 3])
    with pytest.raises(ShapeError):
        mk.Ragged(np.zeros((3, 2)), [0, math.nan, 3])
    with pytest.raises(ShapeError):
        mk.Ragged(np.zeros((3, 2)), np.array([0, 1, 3], dtype=bool))
    assert mk.Ragged(np.zeros((3, 2)), [0.0, 1.0, 3.0]).offsets.tolist() == [0, 1, 3]


def test_ragged_refuses_strings():
    with pytest.raises(mk.errors.CoordinateTypeError):
        mk.Ragged(np.array([["a", "b"], ["c", "d"]]), [0, 2])
    with pytest.raises(mk.errors.CoordinateTypeError):
        mk.Ragged(np.array([[1, "b"]], dtype=object), [0, 1])
    r = mk.Ragged(np.array([[Fraction(1, 3), 2]], dtype=object), [0, 1])
    assert len(r) == 1


def test_one_except_catches_every_bad_input():
    """Every option error is a GeometryError, and the conventional builtin."""
    for call in (
        lambda: mk.minkowski_sum_many([SQ], [SQ], threads="a"),
        lambda: mk.offset(SQ, 1, join="x"),
        lambda: mk.no_fit_polygons([L], rotations=["x"]),
        lambda: mk.no_fit_polygons([L], pairs=[(0, 3)]),
        lambda: mk.offset(SQ, "1"),
    ):
        with pytest.raises(GeometryError):
            call()
        with pytest.raises(TypeError):
            call()
        with pytest.raises(ValueError):
            call()


# --------------------------------------------------------------------------------------
# class 8: a longdouble vertex 1 + 2**-60 is kept exact


def test_longdouble_vertex_kept_exact():
    one = np.longdouble(1) + np.longdouble(2) ** -60
    if one == 1:
        pytest.skip("longdouble is float64 on this platform")
    tri = np.array([(one, 0), (2, 0), (1, 1)], dtype=np.longdouble)
    out = mk.minkowski_sum(tri, SQ)
    assert out[0].tolist() == [Fraction(2**60 + 1, 2**60), 0]
    assert len(out) == 6  # the vertex is not rounded onto (1, 0): one more vertex
    # the same through Python lists of numpy scalars
    assert mk.minkowski_sum([(one, 0), (2, 0), (1, 1)], SQ).tolist() == out.tolist()
    # values float64 holds stay float64
    plain = np.array([(1, 0), (2, 0), (1, 1)], dtype=np.longdouble)
    assert mk.minkowski_sum(plain, SQ).dtype == np.float64
    with pytest.raises(ShapeError):  # the batch path cannot be exact: refused, not rounded
        mk.minkowski_sum_many([tri], [SQ])


@SETTINGS
@given(k=st.integers(54, 63), sign=st.sampled_from([1, -1]))
def test_longdouble_never_rounded(k, sign):
    eps = np.longdouble(2) ** -k
    v = np.longdouble(1) + sign * eps
    if v == 1:
        pytest.skip("longdouble is float64 on this platform")
    out = mk.convex_hull(np.array([(v, 0), (3, 0), (0, 3)], dtype=np.longdouble))
    assert Fraction(*v.as_integer_ratio()) in [x for row in out.tolist() for x in row]


def test_io_and_helper_options():
    from minkowski2d.io import format_geometry, parse_cgal_dat

    with pytest.raises(OptionError, match="unknown format") as e:
        format_geometry(np.array(SQ), "pdf")
    assert e.value.argument == "fmt"
    with pytest.raises(OptionError) as e:
        parse_cgal_dat("3 0 0 1 0 0 1", layout="rings")
    assert e.value.argument == "layout"
    for bad in (1, "4", 2.5):
        with pytest.raises(OptionError):
            mk.pair_blocks(3, bad)
    assert mk.pair_blocks(np.int64(2), np.int64(2)) == mk.pair_blocks(2, 2)


# --------------------------------------------------------------------------------------
# classes 5 and 7, open-ended: any junk argument to a public function is a GeometryError

JUNK = [
    None,
    5,
    2.5,
    math.nan,
    "abc",
    b"x",
    [],
    [[]],
    [1, 2],
    [[1]],
    [[1, 2, 3]],
    {"a": 1},
    object(),
    True,
    np.array([]),
    np.zeros((3, 3)),
    np.array([[1, 2]], dtype=object),
    [[None, 1]],
    [["1", "2"]],
    shapely.Point(),
    shapely.GeometryCollection(),
    shapely.LineString([(0, 0), (1, 1)]),
    10**400,
    [(10**400, 0), (0, 1), (1, 1)],
    [(math.inf, 0), (1, 0), (0, 1)],
    Fraction(1, 3),
    [(1j, 0)],
    -1,
    0,
]

CALLS = {
    "minkowski_sum": lambda x: mk.minkowski_sum(x, SQ),
    "minkowski_sum_many": lambda x: mk.minkowski_sum_many(x, [SQ]),
    "convex_hull": lambda x: mk.convex_hull(x),
    "translate": lambda x: mk.translate(SQ, x),
    "intersects": lambda x: mk.intersects(x, SQ),
    "penetration": lambda x: mk.penetration(SQ, x),
    "contains": lambda x: mk.contains(SQ, x),
    "intersects_many": lambda x: mk.intersects_many(x, [SQ]),
    "distance_many": lambda x: mk.distance_many([SQ], x),
    "minkowski_sum_general": lambda x: mk.minkowski_sum_general(x, L),
    "minkowski_sum_general_many": lambda x: mk.minkowski_sum_general_many(x, [L]),
    "minkowski_difference": lambda x: mk.minkowski_difference(L, x),
    "convex_decomposition": lambda x: mk.convex_decomposition(x),
    "no_fit_polygons": lambda x: mk.no_fit_polygons(x),
    "no_fit_polygons part": lambda x: mk.no_fit_polygons([L, x]),
    "inner_fit_polygon": lambda x: mk.inner_fit_polygon(SQ, x),
    "rotate_part angle": lambda x: mk.rotate_part(SQ, x),
    "rotate_part part": lambda x: mk.rotate_part(x, 90),
    "pair_blocks": lambda x: mk.pair_blocks(x, 2),
    "offset": lambda x: mk.offset(x, 1),
    "offset distance": lambda x: mk.offset(SQ, x),
    "offset tolerance": lambda x: mk.offset(SQ, 1, tolerance=x),
    "offset miter_limit": lambda x: mk.offset(SQ, 1, join="miter", miter_limit=x),
    "offset_arcs": lambda x: mk.offset_arcs(x, 1),
    "MotionPlanner obstacles": lambda x: mk.MotionPlanner(x),
    "MotionPlanner obstacle": lambda x: mk.MotionPlanner([x]),
    "MotionPlanner robot": lambda x: mk.MotionPlanner([SQ], robot=x),
    "MotionPlanner workspace": lambda x: mk.MotionPlanner([SQ], workspace=x),
    "shortest_path": lambda x: mk.MotionPlanner([SQ]).shortest_path(x, (5, 5)),
    "shortest_paths": lambda x: mk.MotionPlanner([SQ]).shortest_paths(x, (5, 5)),
    "is_free": lambda x: mk.MotionPlanner([SQ]).is_free(x),
    "from_scene": lambda x: mk.MotionPlanner.from_scene(x),
    "from_scene obstacles": lambda x: mk.MotionPlanner.from_scene({"obstacles": x}),
    "merge_trace": lambda x: mk.merge_trace(x, SQ),
    "Ragged coords": lambda x: mk.Ragged(x, [0, 1]),
    "Ragged offsets": lambda x: mk.Ragged(np.zeros((1, 2)), x),
    "Ragged.from_list": lambda x: mk.Ragged.from_list(x),
}


#: junk that no argument of CALLS accepts (the rest of JUNK is valid for some: None is a
#: default, 5 a distance, [] an empty batch, 10**400 an exact int)
NEVER_VALID = [
    "abc",
    b"x",
    {"a": 1},
    object(),
    [[None, 1]],
    [["1", "2"]],
    [(1j, 0)],
    math.nan,
    [(math.inf, 0), (1, 0), (0, 1)],
]


@pytest.mark.parametrize("name", list(CALLS))
def test_junk_arguments_are_geometry_errors(name):
    # any junk is accepted or refused with a GeometryError (never another exception);
    # what is never valid is refused
    import warnings

    for junk in JUNK + NEVER_VALID:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # numpy's own warnings on junk are not the point
            try:
                CALLS[name](junk)
            except GeometryError:
                continue
        assert not any(junk is j for j in NEVER_VALID), (name, junk)


def _readers():
    import shapely

    box = shapely.box(0, 0, 1, 1)
    sq = [(0, 0), (1, 0), (1, 1), (0, 1)]
    return {
        "minkowski_sum": lambda e: mk.minkowski_sum(e, sq),
        "intersects": lambda e: mk.intersects(e, sq),
        "minkowski_sum_general": lambda e: mk.minkowski_sum_general(e, sq),
        "offset": lambda e: mk.offset(e, 1.0),
        "MotionPlanner": lambda e: mk.MotionPlanner([e]),
        "no_fit_polygons": lambda e: mk.no_fit_polygons([e, box]),
        "minkowski_difference": lambda e: mk.minkowski_difference(sq, e),
    }


@pytest.mark.parametrize("reader", sorted(_readers()))
def test_one_fault_one_error_across_the_readers(reader):
    # every polygon reader names the same fault with the same exception
    import shapely

    call = _readers()[reader]
    with pytest.raises(mk.errors.EmptyGeometryError, match="empty"):
        call(shapely.Polygon())
    with warnings.catch_warnings():  # shapely warns when it builds a ring with a NaN
        warnings.simplefilter("ignore", RuntimeWarning)
        nan = shapely.Polygon([(0, 0), (1, 0), (float("nan"), 1)])
    with pytest.raises(mk.errors.NonFiniteError, match="non-finite coordinate"):
        call(nan)


@pytest.mark.parametrize("reader", ["minkowski_sum_general", "offset", "union"])
def test_a_collection_of_polygons_reads_the_same_everywhere(reader):
    # the one reading of polygonal shapely input (_engine.polygon.polygon_parts)
    import shapely

    sq = [(0, 0), (1, 0), (1, 1), (0, 1)]
    call = {
        "minkowski_sum_general": lambda g: mk.minkowski_sum_general(g, sq),
        "offset": lambda g: mk.offset(g, 1.0),
        "union": lambda g: mk.union(g, shapely.box(5, 5, 6, 6)),
    }[reader]
    mixed = shapely.GeometryCollection([shapely.box(0, 0, 2, 2), shapely.LineString(sq)])
    with pytest.raises(mk.errors.ShapeError, match="GeometryCollection holding a LineString"):
        call(mixed)
    # overlapping members are united, empty ones dropped: the same as their union
    gc = shapely.GeometryCollection(
        [shapely.box(0, 0, 2, 2), shapely.Polygon(), shapely.box(1, 1, 3, 3)]
    )
    same = shapely.Polygon([(0, 0), (2, 0), (2, 1), (3, 1), (3, 3), (1, 3), (1, 2), (0, 2)])
    got, want = call(gc), call(same)
    if reader == "offset":  # united in the core before the offset: chords cut elsewhere
        assert got.symmetric_difference(want).area < 1e-9 * want.area
    else:
        assert got.equals(want)
