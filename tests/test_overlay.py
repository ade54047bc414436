"""The core's exact overlay against an exact Fraction oracle (tests/overlay_oracle.py).

Random rings with small integer coordinates make every degeneracy common (shared and
repeated vertices, collinear overlapping edges, rings touching at points, zero-width
slits, three or more edges through one point); random floats make rational crossings
that round. For each, with weights and two layers under the union, difference and
intersection rules, the core's result must be a valid polygon set whose vertices are
exactly the oracle's exact vertices, correctly rounded (``float(Fraction)``), and whose
area is the oracle's exact area up to that rounding. Where the oracle's result, rounded,
is itself invalid (exact features closer than an ulp), the core's remedy (re-noding the
rounded rings) must give a valid result with every vertex within 2 ulps of an exact one.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from minkowski2d._core import _ext
from tests.overlay_oracle import boundary, exact_area, ulps

RULES = {"union": 0, "difference": 1, "intersection": 2}


def overlay(rings, weights=None, layers=None, rule="union"):
    h = np.array([p for r in rings for p in r], float).reshape(-1, 2)
    off = np.cumsum([0] + [len(r) for r in rings]).astype(np.int64)
    w = np.array(weights if weights else [1] * len(rings), np.int64)
    ly = np.array(layers if layers else [0] * len(rings), np.int64)
    xy, ro, po, status, _ = _ext.overlay_rings(h, np.empty((0, 2)), off, w, ly, RULES[rule])
    assert status == 0
    return xy, ro, po


def valid(xy, ro, po) -> bool:
    """The core's exact polygon check (polygon.hpp, independent of the overlay's own);
    GEOS's is_valid is wrong near the bottom of the float64 range."""
    from minkowski2d._engine.polygon import Rings, probe

    if len(po) < 2:
        return True
    status = probe(
        Rings(np.ascontiguousarray(xy, np.float64), np.asarray(ro, np.int64),
              np.asarray(po, np.int64)),
        disjoint=True,
    )[0]  # fmt: skip
    return status == 0


def check(rings, weights=None, layers=None, rule="union"):
    xy, ro, po = overlay(rings, weights, layers, rule)
    verts, area = boundary(rings, weights, layers, rule)
    assert valid(xy, ro, po)
    # exteriors counter-clockwise, holes clockwise, no ring repeats a vertex
    for p in range(len(po) - 1):
        for r in range(po[p], po[p + 1]):
            ring = xy[ro[r] : ro[r + 1]]
            assert len({tuple(v) for v in ring.tolist()}) == len(ring)
            assert (exact_area(ring, [0, len(ring)]) > 0) == (r == po[p])  # exact
    ours = set(map(tuple, xy.tolist()))
    rounded = {(float(x), float(y)) for x, y in verts}
    if ours == rounded:
        assert abs(exact_area(xy, ro) - area) <= Fraction(1, 10**9) * (1 + abs(area))
        return
    # only where rounding the exact result breaks it: the remedy, within 2 ulps
    exact_rounded_valid = _rounded_oracle_valid(rings, weights, layers, rule)
    assert not exact_rounded_valid, (sorted(ours - rounded), sorted(rounded - ours))
    for v in ours - rounded:
        assert min(ulps(v, q) for q in rounded) <= 2


def _rounded_oracle_valid(rings, weights, layers, rule) -> bool:
    """Do the oracle's boundary edges, rounded, still meet only at their ends? (GEOS's
    is_simple decides; only consulted where ours and the oracle differ.)"""
    edges = boundary(rings, weights, layers, rule, edges_out=True)
    segs = [[tuple(map(float, a)), tuple(map(float, b))] for a, b in edges]
    segs = [s for s in segs if s[0] != s[1]]
    return len(segs) == len(edges) and bool(shapely.is_simple(shapely.MultiLineString(segs)))


small = st.integers(0, 5)
ring_int = st.lists(st.tuples(small, small), min_size=3, max_size=6)
ring_float = st.lists(
    st.tuples(st.floats(0, 6, allow_subnormal=False), st.floats(0, 6, allow_subnormal=False)),
    min_size=3,
    max_size=5,
)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(ring_int, min_size=1, max_size=4))
def test_union_of_integer_rings_equals_the_oracle(rings):
    check(rings)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    st.lists(
        st.tuples(ring_int, st.sampled_from([1, 1, 2, -1]), st.sampled_from([0, 0, 1])),
        min_size=1,
        max_size=4,
    ),
    st.sampled_from(sorted(RULES)),
)
def test_weights_layers_and_rules_equal_the_oracle(items, rule):
    rings = [r for r, _, _ in items]
    check(rings, [w for _, w, _ in items], [ly for _, _, ly in items], rule)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(ring_float, min_size=1, max_size=3))
def test_union_of_float_rings_equals_the_oracle(rings):
    check(rings)


# named degenerate cases
SQ = [(0, 0), (2, 0), (2, 2), (0, 2)]


@pytest.mark.parametrize(
    "rings, weights",
    [
        ([SQ, [(2, 0), (4, 0), (4, 2), (2, 2)]], None),  # sharing an edge
        ([SQ, [(2, 2), (4, 2), (4, 4), (2, 4)]], None),  # touching at a corner
        ([SQ, [(1, 0), (3, 0), (3, 2), (1, 2)]], None),  # overlapping collinear edges
        ([SQ, SQ, SQ], None),  # identical rings
        ([[(0, 0), (4, 0), (4, 4), (0, 4)], [(1, 0), (2, 1), (3, 0)]], [1, -1]),  # hole
        # touching the outer ring at a point
        ([[(0, 0), (4, 0), (4, 4), (0, 4)], [(1, 0), (1, 1), (3, 1), (3, 0)]], [1, -1]),  # notch
        ([[(0, 0), (4, 0), (4, 4), (0, 4)], [(2, 0), (2, 4)]], [1, 1]),  # a zero-width slit
        ([[(0, 0), (4, 0), (2, 2)], [(0, 4), (2, 2), (4, 4)]], None),  # bow tie at a point
        ([[(0, 0), (6, 0), (0, 6)], [(0, 0), (0, 6), (-6, 0)], [(0, 0), (-6, 0), (0, -6)]], None),
        ([[(0, 0), (3, 3), (0, 3), (3, 0)]], None),  # a self-crossing ring
        # a hole and a polygon touching the exterior inside one of its (straight) edges:
        # the exterior keeps the touching vertex, or rounding would break the touch
        (
            [
                [(0, 0), (2, 3), (1, 0)],
                [(5, 0), (0, 5), (0, 3)],
                [(5, 1), (0, 1), (0, 2)],
                [(0, 2), (5, 0), (0, 5), (2, 0), (3, 2)],
            ],
            None,
        ),  # fmt: skip
    ],
)
def test_degenerate_cases(rings, weights):
    check(rings, weights)


def test_huge_and_tiny_coordinates_are_exact():
    # no rescale: the filter defers to exact arithmetic at every magnitude
    for s in (1e-300, 5e-324 * 2**40, 2.2e-308, 1e300, 2.0**1000):
        rings = [
            [(x * s, y * s) for x, y in r]
            for r in ([(0, 0), (3, 0), (0, 3)], [(1, -1), (2, 2), (-1, 1)])
        ]
        xy, ro, po = overlay(rings)
        verts, area = boundary(rings)
        assert set(map(tuple, xy.tolist())) == {(float(x), float(y)) for x, y in verts}


def test_overflowing_crossing_is_reported():
    big = 1.7e308
    rings = [[(-big, 0), (big, 1), (big, 2)], [(-big, 2), (big, 0), (0, -big)]]
    h = np.array([p for r in rings for p in r], float)
    xy, ro, po, status, _ = _ext.overlay_rings(
        h,
        np.empty((0, 2)),
        np.array([0, 3, 6], np.int64),
        np.ones(2, np.int64),
        np.zeros(2, np.int64),
        0,
    )
    assert status in (0, _ext.OVERFLOW)
    if status == 0:
        assert np.isfinite(xy).all()


def _pencil(k, cx, cy, r, seed):
    """k thin triangles through a common centre (cx, cy) with float vertices: their
    crossings cluster within a few ulps of it, where the approximations cannot order the
    vertices and the exact comparisons repair the sweep order."""
    rng = np.random.default_rng(seed)
    rings = []
    for a in rng.uniform(0, np.pi, k):
        dx, dy = r * np.cos(a), r * np.sin(a)
        ex, ey = -dy * 1e-9, dx * 1e-9  # a sliver: its two long edges pass by the centre
        tip = (cx - dx, cy - dy)
        rings.append([tip, (cx + dx + ex, cy + dy + ey), (cx + dx - ex, cy + dy - ey)])
    return rings


@pytest.mark.parametrize("seed", range(4))
def test_crossings_within_ulps_of_each_other_equal_the_oracle(seed):
    check(_pencil(7, 1 / 3, 1 / 7, 2.0, seed))


def test_a_net_of_strips_equals_the_oracle():
    # many vertices on each vertical line, visited bottom to top by the sweep: its search
    # starts from the last vertex's place (gallops), then jumps back down at the next line
    n = 5
    vert = [[(3 * i, 0), (3 * i + 1, 0), (3 * i + 1, 3 * n), (3 * i, 3 * n)] for i in range(n)]
    horz = [[(-1, 3 * j), (3 * n, 3 * j), (3 * n, 3 * j + 2), (-1, 3 * j + 2)] for j in range(n)]
    for rule in RULES:
        check(vert + horz, None, [0] * n + [1] * n, rule)
