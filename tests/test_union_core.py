"""The core's union of many convex polygons (``_core/union.hpp``): pieces dropped when they
lie inside the union so far (tested exactly), the rest united by the exact overlay.

Dropping is the only thing the union adds to the overlay, so its results must be exactly
the flat overlay's (``_ext.overlay_rings`` of the same rings: the same exact region, the
same rounding), with culling on or off, and agree with the Fraction oracle
(tests/overlay_oracle.py). Convex pieces on a small integer grid make every degeneracy
common: shared vertices, collinear overlapping edges, pieces touching at a point or along
an edge, nested and repeated pieces; the pieces are also given in either orientation,
from any start, with repeated and collinear vertices. The decomposition method of the
sums (``_ext.sum_pieces_union``) must give the convolution's vertices on the benchmark
stars, and the work limits must give Status RESOURCE, never a partial result.
"""

from __future__ import annotations

import sys
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import minkowski2d as mk
from minkowski2d._core import _ext
from tests.corpus import ESICUP
from tests.overlay_oracle import boundary, exact_area, ulps

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))


# --------------------------------------------------------------------------------------
# helpers


def hull(points):
    """Convex hull (counter-clockwise, no collinear vertices) of exact points, or None
    when they are collinear."""
    pts = sorted(set((Fraction(x), Fraction(y)) for x, y in points))
    if len(pts) < 3:
        return None

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    h = lower[:-1] + upper[:-1]
    return h if len(h) >= 3 else None


def ragged(polys):
    xy = np.array([[float(x), float(y)] for p in polys for x, y in p], float).reshape(-1, 2)
    off = np.cumsum([0] + [len(p) for p in polys]).astype(np.int64)
    return xy, off


def union(polys, **kw):
    xy, off = ragged(polys)
    out, ro, po, status, stats, where = _ext.union_convex(xy, off, **kw)
    return out, ro, po, status, stats


def flat(rings):
    """The flat overlay (the reference) of counter-clockwise rings."""
    xy, off = ragged(rings)
    n = len(rings)
    out, ro, po, status, _ = _ext.overlay_rings(
        xy, np.empty((0, 2)), off, np.ones(n, np.int64), np.zeros(n, np.int64), 0
    )
    assert status == 0
    return out, ro, po


def same(a, b):
    return all(np.array_equal(x, y) for x, y in zip(a, b))


def presented(piece, data):
    """The same convex polygon as the caller may give it: any start, either orientation,
    a repeated vertex, a collinear midpoint, a closing repeat."""
    p = list(piece)
    k = data.draw(st.integers(0, len(p) - 1))
    p = p[k:] + p[:k]
    mid = data.draw(st.booleans())
    if mid:
        a, b = p[0], p[1]
        p.insert(1, ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2))
    if data.draw(st.booleans()):
        p.insert(0, p[0])
    if data.draw(st.booleans()):
        p.append(p[0])
    if data.draw(st.booleans()):
        p.reverse()
    return p


grid = st.tuples(st.integers(0, 6), st.integers(0, 6))


@st.composite
def pieces(draw, max_pieces=8, coord=grid):
    """Convex pieces with many degeneracies: hulls of grid points, repeated pieces,
    pieces cut along a diagonal (sharing an edge), translates (touching)."""
    out = []
    for _ in range(draw(st.integers(1, max_pieces))):
        h = hull(draw(st.lists(coord, min_size=3, max_size=7)))
        if h is None:
            continue
        op = draw(st.sampled_from(["plain", "plain", "repeat", "cut", "shift"]))
        if op == "repeat" and out:
            out.append(out[draw(st.integers(0, len(out) - 1))])
        elif op == "cut" and len(h) >= 4:
            j = draw(st.integers(2, len(h) - 2))
            out.append(h[: j + 1])
            out.append([h[0]] + h[j:])
        elif op == "shift":
            dx, dy = draw(st.tuples(st.integers(-3, 3), st.integers(-3, 3)))
            out.append(h)
            out.append([(x + dx, y + dy) for x, y in h])
        else:
            out.append(h)
    return out


def check_against_oracle(polys, presented_polys=None):
    given_polys = presented_polys if presented_polys is not None else polys
    ours = union(given_polys)
    assert ours[3] == 0
    xy, ro, po = ours[:3]
    # the flat overlay of the same region, culling on and off: the same arrays
    assert same((xy, ro, po), flat(polys))
    assert same((xy, ro, po), union(given_polys, cull=False)[:3])
    # the oracle: the exact vertices, correctly rounded, and the exact area. Where the
    # overlay's output contract after rounding (design.md) changes the rounded result,
    # its vertices stay within a few ulps of exact ones: that contract is the overlay's
    # and tested in test_overlay.py; the union must not add to it (it equals the flat
    # overlay above), so here only a loose bound
    verts, area = boundary([[(x, y) for x, y in p] for p in polys])
    got = set(map(tuple, xy.tolist()))
    want = {(float(x), float(y)) for x, y in verts}
    assert abs(exact_area(xy, ro) - area) <= Fraction(1, 10**9) * (1 + abs(area))
    for v in got - want:
        assert min(ulps(v, q) for q in want) <= 4


# --------------------------------------------------------------------------------------
# against the oracle


@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(pieces(), st.data())
def test_union_of_grid_pieces_equals_the_oracle(polys, data):
    if not polys:
        return
    check_against_oracle(polys, [presented(p, data) for p in polys])


dyadic = st.tuples(st.integers(0, 48), st.integers(0, 48)).map(
    lambda p: (Fraction(p[0], 8), Fraction(p[1], 8))
)
floats = st.tuples(
    st.floats(0, 6, allow_subnormal=False, allow_nan=False),
    st.floats(0, 6, allow_subnormal=False, allow_nan=False),
)


@settings(max_examples=50, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(pieces(max_pieces=5, coord=dyadic))
def test_union_of_dyadic_pieces_equals_the_oracle(polys):
    if polys:
        check_against_oracle(polys)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(pieces(max_pieces=4, coord=floats))
def test_union_of_float_pieces_equals_the_oracle(polys):
    if polys:
        check_against_oracle(polys)


# --------------------------------------------------------------------------------------
# many pieces: culling and rounds (no oracle: the flat overlay is the reference)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(pieces(max_pieces=40), st.integers(-40, 40))
def test_many_pieces_cull_on_off_and_flat_agree(polys, e):
    if not polys:
        return
    s = Fraction(2) ** e  # exact at any scale
    polys = [[(x * s, y * s) for x, y in p] for p in polys]
    on = union(polys)
    off = union(polys, cull=False)
    assert on[3] == off[3] == 0
    assert same(on[:3], off[:3])
    assert same(on[:3], flat(polys))


@pytest.mark.parametrize("reverse", [False, True])
@pytest.mark.parametrize("start", [0, 2, 5])
def test_one_piece_is_what_the_overlay_gives(start, reverse):
    # one convex piece is its own union (no overlay run): the overlay's arrays, for a
    # piece given from any start, in either orientation, with a repeated and a collinear
    # vertex (dyadic coordinates: the midpoint is exact)
    hexagon = [(0.5, -1.25), (3.75, -0.5), (4.5, 1.75), (3.0, 3.5), (0.25, 2.75), (-0.5, 0.5)]
    p = hexagon[start:] + hexagon[:start]
    if reverse:
        p.reverse()
    given_ = [p[0], p[0], ((p[0][0] + p[1][0]) / 2, (p[0][1] + p[1][1]) / 2), *p[1:]]
    ours = union([given_])
    assert ours[3] == 0 and ours[4][:3] == (1, 0, 1) and ours[4][4] == 0  # no run
    assert same(ours[:3], flat([hexagon]))
    assert same(ours[:3], union([given_, [(0, 0), (0, 0), (1, 1)]])[:3])  # with a segment


def _esicup_piece_sums(name: str, k: int):
    """``k`` seeded NFPs of an ESICUP instance, parts turned by free angles (as
    benchmarks/bench_union.py): each the convex piece sums of A and -B, as rings."""
    from bench_nfp_free import free_angles, rotated_rings

    parts = mk.read_esicup(ESICUP / f"{name}.json")["parts"]
    angles = free_angles(name, 2, 16)
    rings = rotated_rings(parts, angles)
    rng = np.random.default_rng([5, *map(ord, name)])
    out = []
    for _ in range(k):
        i, j = rng.integers(0, len(parts), 2)
        a, b = rng.choice(angles, 2)
        la = mk.convex_decomposition(rings[(i, a)]).to_list()
        lb = mk.convex_decomposition(mk.reflect(rings[(j, b)])).to_list()
        sums = mk.minkowski_sum_many([p for p in la for _ in lb], [q for _ in la for q in lb])
        out.append(sums.to_list())
    return out


@pytest.mark.parametrize("name", ["swim", "shapes0", "albano"])
def test_nfp_piece_sums_cull_on_off_and_flat_agree(name):
    # the benchmark's input kind: rounded convex sums sharing vertices and collinear
    # edges, many inside others (swim: tens of pieces, several rounds)
    for sums in _esicup_piece_sums(name, 3):
        on = union(sums)
        assert on[3] == 0
        assert same(on[:3], union(sums, cull=False)[:3])
        assert same(on[:3], flat(sums))


def test_pieces_inside_a_large_one_are_culled():
    rng = np.random.default_rng(7)
    big = [(0, 0), (100, 0), (100, 100), (0, 100)]
    polys = [big] * 3
    for _ in range(300):
        c = rng.uniform(10, 90, 2)
        r = rng.uniform(1, 9)
        t = np.sort(rng.uniform(0, 2 * np.pi, 5))
        polys.append([(c[0] + r * np.cos(a), c[1] + r * np.sin(a)) for a in t])
    xy, ro, po, status, stats = union(polys)
    pieces_, culled, kept = stats[:3]
    assert status == 0 and pieces_ == len(polys)
    assert culled >= 290  # everything after the first round
    assert sorted(map(tuple, xy.tolist())) == sorted(map(tuple, np.array(big, float).tolist()))


def test_rings_that_are_not_convex_are_united_too():
    # a rounded convex sum may turn both ways by an ulp; and a plain L
    L = [(0, 0), (4, 0), (4, 1), (1, 1), (1, 4), (0, 4)]
    sq = [(0.5, 0.5), (3, 0.5), (3, 3), (0.5, 3)]
    xy, ro, po, status, stats = union([L, sq])
    assert status == 0
    assert same((xy, ro, po), flat([L, sq]))


def test_points_segments_and_empty_input():
    xy, ro, po, status, stats = union([[(0, 0)], [(0, 0), (1, 1)], [(0, 0), (1, 1), (2, 2)]])
    assert status == 0 and len(xy) == 0 and list(po) == [0]
    xy, ro, po, status, stats = union([])
    assert status == 0 and len(xy) == 0


def test_non_finite_coordinates_are_named():
    xy, off = ragged([[(0, 0), (1, 0), (0, 1)], [(0, 0), (float("nan"), 0), (0, 1)]])
    *_, status, stats, where = _ext.union_convex(xy, off)
    assert status == _ext.NONFINITE and where == (1, 1)


def test_work_limits_give_resource_and_no_rings():
    rng = np.random.default_rng(3)
    polys = []
    for _ in range(60):
        c = rng.uniform(0, 10, 2)
        t = np.sort(rng.uniform(0, 2 * np.pi, 6))
        polys.append([(c[0] + 3 * np.cos(a), c[1] + 3 * np.sin(a)) for a in t])
    xy, ro, po, status, stats = union(polys)
    assert status == 0 and stats[6] > 10
    for kw in ({"max_crossings": 10}, {"max_pairs": 100}):
        xy, ro, po, status, stats = union(polys, **kw)
        assert status == _ext.RESOURCE
        assert len(xy) == 0 and list(ro) == [0] and list(po) == [0]


# --------------------------------------------------------------------------------------
# the decomposition method of the sums


def decomposed(p):
    d = mk.convex_decomposition(p)
    return np.ascontiguousarray(d.coords, float), np.ascontiguousarray(d.offsets, np.int64)


@pytest.mark.parametrize("n", [32, 128])
def test_stars_pieces_equal_convolution(n):
    from bench_general import star

    a, b = star(n, 10000, 5000), star(n, 9000, 3000, 0.3)
    one = np.array([0, n], np.int64), np.array([0, 1], np.int64)
    conv = _ext.sum_convolution(np.asarray(a, float), *one, np.asarray(b, float), *one)
    assert conv[3] == 0
    pieces_ = _ext.sum_pieces_union(*decomposed(a), *decomposed(b))
    assert pieces_[3] == 0
    assert set(map(tuple, conv[0].tolist())) == set(map(tuple, pieces_[0].tolist()))
    assert pieces_[4][1] > pieces_[4][2]  # most piece sums culled
    off = _ext.sum_pieces_union(*decomposed(a), *decomposed(b), cull=False)
    assert same(pieces_[:3], off[:3])


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(pieces(max_pieces=4), pieces(max_pieces=4))
def test_sums_of_pieces_cull_on_off_and_flat_agree(pa, pb):
    if not pa or not pb:
        return
    xa, oa = ragged(pa)
    xb, ob = ragged(pb)
    on = _ext.sum_pieces_union(xa, oa, xb, ob)
    off = _ext.sum_pieces_union(xa, oa, xb, ob, cull=False)
    assert on[3] == off[3] == 0
    assert same(on[:3], off[:3])
    sums = [
        hull([(x + u, y + v) for x, y in p for u, v in q])  # exact sums of the vertices
        for p in pa
        for q in pb
    ]
    assert same(on[:3], flat([s for s in sums if s is not None]))


def test_sums_of_pieces_limit():
    from bench_general import star

    a, b = star(64, 10000, 5000), star(64, 9000, 3000, 0.3)
    r = _ext.sum_pieces_union(*decomposed(a), *decomposed(b), max_crossings=5)
    assert r[3] == _ext.RESOURCE and len(r[0]) == 0
