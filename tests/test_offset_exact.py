"""The one-sided guarantee of :func:`minkowski2d.offset` on the compiled core,
checked exactly on random and degenerate inputs.

``check_offset`` (tests/test_offset.py) compares every boundary segment of the result
with every edge of the input in exact rational arithmetic: the result's boundary lies in
the band ``[r, r + ε]`` (outer grow; the other sides likewise) and the result contains
(grow) or lies in (shrink) the polygon. Here it runs on what the construction finds
hardest: axis-parallel edges (exact zeros in every predicate, right-angle trims),
reflex vertices of every angle (trims up to 90 degrees and beyond), collinear runs,
spikes of segments, holes touching the exterior or each other at a point, overlapping
parts, magnitudes from 2**-1000 to 2**1000 and subnormal coordinates; batches against
single calls, threads against none, and the rule that no GEOS overlay runs.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import minkowski2d as mk
from minkowski2d.errors import GeometryError

from .test_offset import _F, _pt_seg2, _segments, check_lower, check_offset, counts

SIDES = ["outer", "inner"]


# --------------------------------------------------------------------------------------
# an exact check without GEOS predicates (for magnitudes where GEOS's own float
# arithmetic fails: containment by exact winding numbers)


def _winding(pt, ring) -> int:
    x, y = Fraction(pt[0]), Fraction(pt[1])
    w = 0
    c = [(Fraction(a), Fraction(b)) for a, b in ring]
    for (x0, y0), (x1, y1) in zip(c, c[1:] + c[:1]):
        cr = (x1 - x0) * (y - y0) - (y1 - y0) * (x - x0)
        if y0 <= y < y1 and cr > 0:
            w += 1
        elif y1 <= y < y0 and cr < 0:
            w -= 1
    return w


def _inside(pt, geom) -> bool:
    """pt in the closed-or-open region (never called on its boundary), any orientation."""
    for part in shapely.get_parts(geom):
        rings = [shapely.get_coordinates(r)[:-1] for r in shapely.get_rings(part)]
        if _winding(pt, rings[0]) != 0 and all(_winding(pt, h) == 0 for h in rings[1:]):
            return True
    return False


def check_upper(out_geom, in_geom, r_up, depth: int = 48):
    """Exact: every boundary segment of the result lies within r_up of the polygon. A
    segment whose two ends are within r_up of one edge is (the distance to a segment is
    convex); otherwise it is halved (exact midpoints) until its pieces are: the distance
    to the polygon is not convex where a segment passes several edges. A segment that
    runs at distance r_up - m along two edges meeting at a vertex needs pieces shorter
    than about sqrt(2 r_up m) around the vertex's normal: with the construction's margin
    m >= 2**-50 at a scale near 1, some 30 halvings (hence the depth)."""
    S = _segments(out_geom)
    T = [(_F(a), _F(b)) for a, b in _segments(in_geom)]
    R2 = Fraction(r_up) ** 2
    Tf = _segments(in_geom)

    def near(p):  # edges in order of float distance from p
        v = Tf[:, 1] - Tf[:, 0]
        L = (v * v).sum(-1)
        q = np.array([float(p[0]), float(p[1])])
        t = np.clip(((q - Tf[:, 0]) * v).sum(-1) / np.where(L > 0, L, 1), 0, 1)
        w = q - Tf[:, 0] - t[:, None] * v
        return np.argsort((w * w).sum(-1))[:6]

    def ok(p, q, k):
        for j in near(((p[0] + q[0]) / 2, (p[1] + q[1]) / 2)):
            if _pt_seg2(p, *T[j]) <= R2 and _pt_seg2(q, *T[j]) <= R2:
                return True
        if k == 0:
            return False
        m = ((p[0] + q[0]) / 2, (p[1] + q[1]) / 2)
        return ok(p, m, k - 1) and ok(m, q, k - 1)

    for a, b in S:
        assert ok(_F(a), _F(b), depth), (a, b, float(r_up))


def check_exact(P, d, eps, approx, out):
    """check_offset's bounds, with containment decided by exact winding numbers: the
    boundaries are apart (check_lower), so one vertex decides for each ring."""
    # at a power-of-two scale near 1 (exact), where the float pruning of check_lower and
    # check_upper works
    k = -math.frexp(float(np.abs(shapely.get_coordinates(P)).max()))[1]
    P = shapely.transform(P, lambda c: np.ldexp(c, k))
    out = shapely.transform(out, lambda c: np.ldexp(c, k))
    d, eps = math.ldexp(d, k), math.ldexp(eps, k)
    r, e = abs(Fraction(d)), Fraction(eps)
    outer, grow = approx == "outer", d > 0
    if grow:
        lo, hi = (r, r + e) if outer else (r - e, r)
    else:
        lo, hi = (r - e, r) if outer else (r, r + e)
    if out.is_empty:
        assert not grow
        return
    check_lower(out, P, lo)
    check_upper(out, P, hi)
    p0 = shapely.get_coordinates(P)[0]
    if grow:
        assert _inside(p0, out)  # P in the result, and no ring of the result inside P
        for ring in shapely.get_rings(shapely.get_parts(out)):
            assert not _inside(shapely.get_coordinates(ring)[0], P)
    else:
        for ring in shapely.get_rings(shapely.get_parts(out)):
            assert _inside(shapely.get_coordinates(ring)[0], P)


# --------------------------------------------------------------------------------------
# strategies


@st.composite
def orthogonal_polygon(draw):
    """A random rectilinear polygon: the union of a few grid rectangles (integer
    coordinates), taken when it is one polygon (holes allowed)."""
    k = draw(st.integers(2, 5))
    boxes = []
    for _ in range(k):
        x0 = draw(st.integers(0, 8))
        y0 = draw(st.integers(0, 8))
        boxes.append(
            shapely.box(x0, y0, x0 + draw(st.integers(1, 5)), y0 + draw(st.integers(1, 5)))
        )
    g = shapely.union_all(boxes)  # the test builds its input with GEOS: exact on a grid
    g = shapely.simplify(g, 0)
    assume(g.geom_type == "Polygon" and g.is_valid)
    return g


@st.composite
def star_with_angles(draw):
    """A star-shaped polygon whose radii vary a lot: reflex vertices of every turn, acute
    spikes, near-collinear vertices."""
    n = draw(st.integers(4, 14))
    ang = np.sort(np.array(draw(st.lists(st.floats(0, 2 * math.pi), min_size=n, max_size=n))))
    gaps = np.diff(np.concatenate([ang, [ang[0] + 2 * math.pi]]))
    assume(gaps.min() > 0.02 and gaps.max() < math.pi - 0.02)
    rad = np.array(draw(st.lists(st.floats(0.5, 10), min_size=n, max_size=n)))
    pts = np.c_[rad * np.cos(ang), rad * np.sin(ang)]
    g = shapely.Polygon(pts)
    assume(g.is_valid and g.area > 0.5)
    return g


def with_collinear(g: shapely.Polygon) -> list:
    """The exterior of ``g`` with the exact midpoint of every edge inserted (a collinear
    run at each edge; midpoints of floats are exact unless they underflow)."""
    c = shapely.get_coordinates(g.exterior)[:-1]
    out = []
    for a, b in zip(c, np.roll(c, -1, 0)):
        out.append(tuple(a))
        m = (Fraction(a[0]) + Fraction(b[0])) / 2, (Fraction(a[1]) + Fraction(b[1])) / 2
        if float(m[0]) == m[0] and float(m[1]) == m[1]:
            out.append((float(m[0]), float(m[1])))
    return out


# --------------------------------------------------------------------------------------
# the guarantee on random inputs


@settings(max_examples=40, deadline=None, suppress_health_check=list(HealthCheck))
@given(g=orthogonal_polygon(), r=st.sampled_from([0.25, 0.5, 1, 1.5, 2.5]),
       grow=st.booleans(), approx=st.sampled_from(SIDES))  # fmt: skip
def test_orthogonal(g, r, grow, approx):
    check_offset(g, r if grow else -r, 1e-2 * r, approx)


@settings(max_examples=40, deadline=None, suppress_health_check=list(HealthCheck))
@given(g=star_with_angles(), r=st.floats(0.05, 4), grow=st.booleans(),
       approx=st.sampled_from(SIDES), rel=st.sampled_from([1e-2, 1e-3]))  # fmt: skip
def test_reflex_of_every_angle(g, r, grow, approx, rel):
    check_offset(g, r if grow else -r, rel * r, approx)


@settings(max_examples=20, deadline=None, suppress_health_check=list(HealthCheck))
@given(g=star_with_angles(), r=st.floats(0.1, 3), grow=st.booleans(),
       approx=st.sampled_from(SIDES))  # fmt: skip
def test_collinear_runs(g, r, grow, approx):
    ring = with_collinear(g)
    out = mk.offset(ring, r if grow else -r, tolerance=1e-2 * r, approx=approx)
    check_offset(g, r if grow else -r, 1e-2 * r, approx, out=out)
    assert out.equals(mk.offset(g, r if grow else -r, tolerance=1e-2 * r, approx=approx))


@st.composite
def jagged_polygon(draw):
    """A star polygon digitized finely: every edge cut into pieces whose inner points are
    pushed off the edge by a fraction of the tolerance, either way: notches and bumps
    from 1/100 to 1/2 of eps on both sides (the shallow notches the core fills before
    offsetting), and collinear points (no push)."""
    g = draw(star_with_angles())
    r = draw(st.floats(0.2, 3))
    rel = draw(st.sampled_from([1e-2, 1e-3]))
    eps = rel * r
    c = shapely.get_coordinates(g.exterior)[:-1]
    pts = []
    for a, b in zip(c, np.roll(c, -1, 0)):
        pts.append(tuple(a))
        m = draw(st.integers(1, 6))
        t = np.sort(np.array(draw(st.lists(st.floats(0.05, 0.95), min_size=m, max_size=m))))
        d = b - a
        nrm = np.array([-d[1], d[0]]) / math.hypot(*d)
        for ti in t:
            f = draw(st.sampled_from([0.0, 0.01, 0.1, 0.2, 0.3, 0.5])) * draw(
                st.sampled_from([-1, 1])
            )
            pts.append(tuple(a + ti * d + f * eps * nrm))
    P = shapely.Polygon(pts)
    assume(P.is_valid)
    return P, r, rel


@settings(max_examples=40, deadline=None, suppress_health_check=list(HealthCheck))
@given(case=jagged_polygon(), grow=st.booleans(), approx=st.sampled_from(SIDES))
def test_shallow_notches(case, grow, approx):
    P, r, rel = case
    d = r if grow else -r
    out = mk.offset(P, d, tolerance=rel * r, approx=approx)
    assert out.is_valid
    check_exact(P, d, rel * r, approx, out)


@pytest.mark.parametrize("d", [0.5, 2.0, -0.5, -2.0])
@pytest.mark.parametrize("approx", SIDES)
def test_finely_rounded_corners(d, approx):
    """A rectangle whose corners are arcs of radius 0.05 digitized by 40 points each (so
    every corner point is a notch of height ~1e-6 on one side): offsets by 0.5 and 2."""
    pts = []
    for cx, cy, a0 in [(3.95, 0.05, -90), (3.95, 1.95, 0), (0.05, 1.95, 90), (0.05, 0.05, 180)]:
        for t in np.radians(np.linspace(a0, a0 + 90, 40)):
            pts.append((cx + 0.05 * math.cos(t), cy + 0.05 * math.sin(t)))
    P = shapely.Polygon(pts)
    if d < 0 and abs(d) >= 1:
        d = -0.9
    out = mk.offset(P, d, tolerance=1e-3 * abs(d), approx=approx)
    assert out.is_valid and out.geom_type == "Polygon"
    check_exact(P, d, 1e-3 * abs(d), approx, out)


@settings(max_examples=30, deadline=None, suppress_health_check=list(HealthCheck))
@given(e=st.integers(-1000, 1000), r=st.floats(0.1, 2), grow=st.booleans(),
       approx=st.sampled_from(SIDES))  # fmt: skip
def test_magnitudes(e, r, grow, approx):
    """The same L at every binary magnitude: exactly the scaled result (the core works at
    a power-of-two scale), and the guarantee in exact arithmetic."""
    L = np.array([(0, 0), (4, 0), (4, 1), (1, 1), (1, 4), (0, 4)], float)
    s = math.ldexp(1.0, e)
    d = r if grow else -r
    ref = mk.offset(L, d, tolerance=1e-2 * r, approx=approx)
    out = mk.offset(L * s, d * s, tolerance=1e-2 * r * s, approx=approx)
    assert np.array_equal(shapely.get_coordinates(out), shapely.get_coordinates(ref) * s)
    if abs(e) <= 300:
        check_exact(shapely.Polygon(L * s), d * s, 1e-2 * r * s, approx, out)


@pytest.mark.parametrize("scale", [1e-300, 3.7e-150, 1e150, 1e300])
@pytest.mark.parametrize("d", [0.7, -0.3])
@pytest.mark.parametrize("approx", SIDES)
def test_decimal_magnitudes(scale, d, approx):
    """Not a power of two: the coordinates are other floats, not scaled copies."""
    P = shapely.Polygon([(0, 0), (5, 0), (5, 3), (2, 1.3), (0, 3)])
    P = shapely.transform(P, lambda c: c * scale)
    eps = 1e-2 * abs(d) * scale
    check_exact(P, d * scale, eps, approx, mk.offset(P, d * scale, tolerance=eps, approx=approx))


def test_subnormal_coordinates():
    """A polygon of subnormal size is a point at the scale of a normal radius: a disk."""
    sq = [(0, 0), (1e-310, 0), (1e-310, 1e-310), (0, 1e-310)]
    for approx in SIDES:
        g = mk.offset(sq, 1, tolerance=1e-3, approx=approx)
        d = shapely.distance(shapely.Point(0, 0), shapely.points(shapely.get_coordinates(g)))
        assert (d <= 1 + 1e-3 + 1e-12).all() and (d >= 1 - 1e-3 - 1e-12).all()
        assert mk.offset(sq, -1, tolerance=1e-3, approx=approx).is_empty


# --------------------------------------------------------------------------------------
# named degenerate cases

TOUCH_SHELL = shapely.Polygon(
    [(0, 0), (10, 0), (10, 10), (0, 10)], [[(0, 5), (3, 3), (3, 7)]]
)  # a hole touching the exterior at (0, 5)
TOUCH_HOLES = shapely.Polygon(
    [(0, 0), (10, 0), (10, 10), (0, 10)],
    [[(2, 2), (5, 2), (5, 5), (2, 5)], [(5, 5), (8, 5), (8, 8), (5, 8)]],
)  # two holes touching at (5, 5)
SLIT = [(0, 0), (10, 0), (10, 10), (5.25, 10), (5.25, 3), (4.75, 3), (4.75, 10), (0, 10)]
SPIKES = [(0, 0), (6, 0), (6, 1), (3, 1.001), (6, 1.002), (6, 4), (0, 4)]  # a near spike
COMB = [(0, 0), (9, 0), (9, 5), (8, 5), (8, 1), (7, 1), (7, 5), (6, 5), (6, 1), (5, 1),
        (5, 5), (4, 5), (4, 1), (3, 1), (3, 5), (2, 5), (2, 1), (1, 1), (1, 5), (0, 5)]  # fmt: skip
ACUTE = [(0, 0), (10, 0), (10, 1), (1, 0.5), (10, 2), (10, 3), (0, 3)]  # a sharp notch
NAMED = {
    "touching shell": TOUCH_SHELL,
    "touching holes": TOUCH_HOLES,
    "slit": SLIT,
    "near spike": SPIKES,
    "comb": COMB,
    "acute notch": ACUTE,
}


@pytest.mark.parametrize("name", sorted(NAMED))
@pytest.mark.parametrize("d", [0.1, 0.24, 0.26, 0.8, -0.1, -0.24, -0.26, -0.6])
@pytest.mark.parametrize("approx", SIDES)
def test_named_degenerate(name, d, approx):
    P = NAMED[name] if hasattr(NAMED[name], "geom_type") else shapely.Polygon(NAMED[name])
    out = mk.offset(P, d, tolerance=1e-2 * abs(d), approx=approx)
    assert out.is_valid
    check_exact(P, d, 1e-2 * abs(d), approx, out)


def test_slit_closes_at_its_half_width():
    """The slit of width 0.5 closes exactly at r = 0.25: open below, closed above."""
    assert counts(mk.offset(shapely.Polygon(SLIT), 0.24, tolerance=1e-4)) == (1, 0)
    below = mk.offset(shapely.Polygon(SLIT), 0.24, tolerance=1e-4)
    above = mk.offset(shapely.Polygon(SLIT), 0.26, tolerance=1e-4)
    assert not below.contains(shapely.Point(5, 8)) and above.contains(shapely.Point(5, 8))


def test_segments_and_points():
    for approx in SIDES:
        s = mk.offset([(0, 0), (3, 1)], 1, tolerance=1e-2, approx=approx)
        c = shapely.get_coordinates(s)
        seg = shapely.LineString([(0, 0), (3, 1)])
        dist = shapely.distance(seg, shapely.points(c))
        lo, hi = (1, 1.01) if approx == "outer" else (0.99, 1)
        assert dist.min() >= lo - 1e-12 and dist.max() <= hi + 1e-12
        p = mk.offset([(2, 3)], 0.5, tolerance=1e-3, approx=approx)
        dist = shapely.distance(shapely.Point(2, 3), shapely.points(shapely.get_coordinates(p)))
        lo, hi = (0.5, 0.501) if approx == "outer" else (0.499, 0.5)
        assert dist.min() >= lo - 1e-12 and dist.max() <= hi + 1e-12


def test_overlapping_parts_are_united_exactly():
    """A GeometryCollection of overlapping squares and an invalid MultiPolygon of them:
    the core unites them (no GEOS union), so their shrink is the union's shrink."""
    a, b = shapely.box(0, 0, 4, 4), shapely.box(2, 0, 6, 4)
    union = shapely.box(0, 0, 6, 4)
    for g in (shapely.GeometryCollection([a, b]), shapely.MultiPolygon([a, b])):
        for d in (0.5, -1.5):
            for approx in SIDES:
                out = mk.offset(g, d, tolerance=1e-2, approx=approx)
                check_offset(union, d, 1e-2, approx, out=out)


# --------------------------------------------------------------------------------------
# batches, threads, no GEOS


def test_batch_equals_single_calls():
    polys = [shapely.Polygon(SLIT), TOUCH_HOLES, shapely.Polygon(COMB), None,
             shapely.Polygon(ACUTE), [(0, 0)], [(0, 0), (2, 2)]]  # fmt: skip
    for d in (0.3, -0.2):
        many = mk.offset(polys, d, tolerance=1e-3)
        for p, g in zip(polys, many):
            if p is None:
                assert g is None
            else:
                assert g.equals_exact(mk.offset(p, d, tolerance=1e-3), tolerance=0)


def test_threads_give_the_same_rings():
    from minkowski2d._core import _ext

    rng = np.random.default_rng(5)
    rings = []
    for _ in range(40):
        n = 12
        a = np.sort(rng.uniform(0, 2 * np.pi, n))
        rad = rng.uniform(2, 5, n)
        rings.append(np.c_[rad * np.cos(a), rad * np.sin(a)] + rng.uniform(-50, 50, 2))
    xy = np.ascontiguousarray(np.concatenate(rings))
    ro = np.arange(0, 12 * 41, 12, dtype=np.int64)
    go = np.arange(41, dtype=np.int64)
    args = (xy, ro, np.zeros(40, np.int64), go, np.zeros(40, np.int64), np.zeros(40), 0.7,
            1e-3, 1e-3, True, 0, 2.0, False)  # fmt: skip
    one = _ext.offset_rings(*args, 1)
    four = _ext.offset_rings(*args, 4)
    for x, y in zip(one[:5], four[:5]):
        assert np.array_equal(x, y)


def test_no_geos_overlay_on_the_computing_path(monkeypatch):
    """union, difference, intersection, buffer, simplify, make_valid, STRtree, is_valid:
    none runs while offsetting (validity is the core's exact check)."""

    def refuse(*a, **k):
        raise AssertionError("a GEOS operation ran on the offset's computing path")

    for name in ("union_all", "union", "difference", "intersection", "buffer", "simplify",
                 "unary_union", "STRtree", "polygonize", "node", "make_valid", "is_valid",
                 "is_valid_reason", "orient_polygons", "normalize"):  # fmt: skip
        monkeypatch.setattr(shapely, name, refuse)
    monkeypatch.setattr(shapely.lib, "is_valid", refuse)
    cases = [SLIT, TOUCH_HOLES, COMB, ACUTE, [(0, 0)], [(0, 0), (3, 1)],
             shapely.GeometryCollection([shapely.box(0, 0, 2, 2), shapely.box(1, 1, 3, 3)]),
             shapely.MultiPolygon([shapely.box(0, 0, 2, 2), shapely.box(1, 1, 3, 3)])]  # fmt: skip
    for p in cases:
        for d in (0.4, -0.2):
            for join in ("round", "miter", "square"):
                mk.offset(p, d, join=join)
    for p in (SLIT, TOUCH_HOLES, COMB):
        mk.offset_arcs(p, 0.4)
        mk.offset_arcs(p, -0.2)


def test_tolerance_floor():
    """The least tolerance is 0.0234 here (2**-43 r + 2**-47 2**42); below it, an error."""
    far = np.array([(0, 0), (4, 0), (4, 4), (0, 4)], float) + 2.0**40
    mk.offset(far, 1.0, tolerance=2.0**-5)  # 0.031 > 0.0234: fine
    with pytest.raises(GeometryError) as e:
        mk.offset(far, 1.0, tolerance=2.0**-6)
    assert e.value.argument == "tolerance" and "float64" in str(e.value)


def test_tiny_valid_triangle_and_invalid_rings():
    """Validity is decided exactly: a valid 3e-200 triangle (GEOS called it
    self-intersecting) offsets; a bow-tie is refused naming its vertex."""
    T = [(0.0, 0.0), (3e-200, 0.0), (0.0, 3e-200)]
    for d in (1e-200, -5e-201):
        for approx in SIDES:
            P = shapely.Polygon(T)
            out = mk.offset(T, d, tolerance=1e-2 * abs(d), approx=approx)
            check_exact(P, d, 1e-2 * abs(d), approx, out)
    with pytest.raises(mk.errors.SelfIntersectionError) as e:
        mk.offset([(0, 0), (2, 2), (2, 0), (0, 2)], 1)
    assert e.value.argument == "polygon" and e.value.vertex is not None
    with pytest.raises(mk.errors.SelfIntersectionError):
        mk.offset(shapely.Polygon([(0, 0), (4, 0), (4, 4), (0, 4)], [[(5, 1), (6, 1), (6, 2)]]), 1)
