"""Public booleans and line clipping (minkowski2d.boolean) against the brute-force
Fraction oracle (tests/overlay_oracle.py): every rule and fill rule, valid and
self-intersecting input, containers, errors."""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

import minkowski2d as mk
from minkowski2d.errors import NonFiniteError, SelfIntersectionError, ShapeError

from . import overlay_oracle as oracle
from .strategies import grid_polygon, holey_polygon

FILL = {
    "positive": lambda w: w >= 1,
    "nonzero": lambda w: w != 0,
    "evenodd": lambda w: w % 2 == 1,
    "negative": lambda w: w <= -1,
}
OPS = {
    "union": (mk.union, lambda a, b: a or b),
    "intersection": (mk.intersection, lambda a, b: a and b),
    "difference": (mk.difference, lambda a, b: a and not b),
    "xor": (mk.symmetric_difference, lambda a, b: a != b),
}


def _oracle(rings_a, rings_b, op, fill):
    f = FILL[fill]
    comb = OPS[op][1]
    name = f"test-{op}-{fill}"
    oracle.RULES[name] = lambda w0, w1: comb(f(w0), f(w1))
    rings = list(rings_a) + list(rings_b)
    layers = [0] * len(rings_a) + [1] * len(rings_b)
    return oracle.boundary(
        [[tuple(map(Fraction, p)) for p in r] for r in rings], None, layers, name
    )


def _vertices(g):
    out = set()
    for p in shapely.get_parts(g):
        for ring in [p.exterior, *p.interiors]:
            out |= set(map(tuple, np.asarray(ring.coords)[:-1].tolist()))
    return out


def _area_exact(g):
    a = Fraction(0)
    for p in shapely.get_parts(g):
        for ring in [p.exterior, *p.interiors]:
            c = [tuple(map(Fraction, q)) for q in np.asarray(ring.coords).tolist()]
            a += sum(c[i][0] * c[i + 1][1] - c[i][1] * c[i + 1][0] for i in range(len(c) - 1)) / 2
    return a


def _signed_area_ok(g):
    # exteriors counter-clockwise, holes clockwise (shapely's orient would hide it)
    for p in shapely.get_parts(g):
        assert shapely.is_ccw(p.exterior) and all(not shapely.is_ccw(h) for h in p.interiors)


def _check(result, verts, area):
    assert result.is_empty or shapely.is_valid(result)
    if result.is_empty:
        assert area == 0
        return
    _signed_area_ok(result)
    rounded = {(float(x), float(y)) for x, y in verts}
    ours = _vertices(result)
    if ours == rounded:
        assert abs(_area_exact(result) - area) <= Fraction(1, 10**9) * (1 + abs(area))
    else:  # rounding broke the exact result; the core re-noded it: within 2 ulps
        for v in ours - rounded:
            assert min(oracle.ulps(v, q) for q in rounded) <= 2


@settings(max_examples=60, deadline=None)
@given(grid_polygon(size=5), grid_polygon(size=5), st.sampled_from(sorted(OPS)),
       st.sampled_from(sorted(FILL)))  # fmt: skip
def test_fill_rules_match_the_oracle(ra, rb, op, fill):
    verts, area = _oracle(ra, rb, op, fill)
    # each ring its own polygon: counted as given under a fill rule
    result = OPS[op][0](ra, rb, fill_rule=fill)
    _check(result, verts, area)


def _valid_polygon(rings):
    g = shapely.Polygon(rings[0], rings[1:])
    return g if g.is_valid else None


@settings(max_examples=60, deadline=None)
@given(holey_polygon(max_holes=2), holey_polygon(max_holes=2), st.sampled_from(sorted(OPS)),
       st.integers(-30, 30), st.integers(-30, 30))  # fmt: skip
def test_valid_polygons_match_the_oracle(pa, pb, op, dx, dy):
    ga = _valid_polygon(pa)
    gb = _valid_polygon([[(x + dx, y + dy) for x, y in r] for r in pb])
    if ga is None or gb is None:
        return
    # the oracle on the rings oriented (shell ccw, holes cw)
    ra = [
        np.asarray(r.coords)[:-1].tolist()
        for r in [
            shapely.geometry.polygon.orient(ga).exterior,
            *shapely.geometry.polygon.orient(ga).interiors,
        ]
    ]
    rb = [
        np.asarray(r.coords)[:-1].tolist()
        for r in [
            shapely.geometry.polygon.orient(gb).exterior,
            *shapely.geometry.polygon.orient(gb).interiors,
        ]
    ]
    verts, area = _oracle(ra, rb, op, "positive")
    result = OPS[op][0](ga, gb)
    _check(result, verts, area)
    # any orientation of the input gives the same result
    flipped = shapely.Polygon(ga.exterior.coords[::-1], [h.coords for h in ga.interiors])
    assert OPS[op][0](flipped, gb).equals_exact(result, 0) or OPS[op][0](flipped, gb).equals(result)


def test_examples_and_degenerate_cases():
    sq = [(0, 0), (2, 0), (2, 2), (0, 2)]
    right = [(2, 0), (4, 0), (4, 2), (2, 2)]
    assert (
        mk.union(sq, right).wkt == "POLYGON ((0 0, 2 0, 4 0, 4 2, 2 2, 0 2, 0 0))"
        or mk.union(sq, right).area == 8
    )
    assert mk.intersection(sq, right).is_empty  # touching along an edge: no area
    assert mk.difference(sq, sq).is_empty
    assert mk.symmetric_difference(sq, sq).is_empty
    assert mk.union(sq, shapely.Polygon()).area == 4
    # a hole touching the shell at a point stays valid
    r = mk.difference([(0, 0), (4, 0), (4, 4), (0, 4)], [(0, 2), (2, 1), (2, 3)])
    assert shapely.is_valid(r) and r.area == 14
    # huge and tiny magnitudes: exact decisions
    for s in (1e-300, 1e300):
        a = [(x * s, y * s) for x, y in sq]
        b = [(x * s + s, y * s + s) for x, y in sq]
        assert mk.intersection(a, b).bounds == (s, s, 2 * s, 2 * s)


def test_bowtie_needs_a_fill_rule():
    bow = [(0, 0), (2, 2), (2, 0), (0, 2)]
    with pytest.raises(SelfIntersectionError, match="vertex"):
        mk.union(bow, [(5, 5), (6, 5), (6, 6)])
    assert mk.union(bow, [(5, 5), (6, 5), (6, 6)], fill_rule="evenodd").area == pytest.approx(2.5)
    assert mk.union(bow, [(5, 5), (6, 5), (6, 6)], fill_rule="nonzero").area == pytest.approx(2.5)
    # positive: only the counter-clockwise lobe
    assert mk.union(bow, [(5, 5), (6, 5), (6, 6)], fill_rule="positive").area == pytest.approx(1.5)


def test_errors():
    with pytest.raises(NonFiniteError):
        mk.union([(0, 0), (1, 0), (float("nan"), 1)], [(0, 0), (1, 0), (1, 1)])
    with pytest.raises(ShapeError):
        mk.union(shapely.LineString([(0, 0), (1, 1)]), [(0, 0), (1, 0), (1, 1)])
    with pytest.raises(mk.errors.OptionError):
        mk.union([(0, 0), (1, 0), (1, 1)], [(0, 0), (1, 0), (1, 1)], fill_rule="odd")
    with pytest.raises(mk.GeometryError, match="float64"):
        mk.union([(0, 0), (Fraction(1, 3), 0), (1, 1)], [(0, 0), (1, 0), (1, 1)])


def test_containers_elementwise_and_broadcast():
    gpd = pytest.importorskip("geopandas")
    a = gpd.GeoSeries([shapely.box(0, 0, 2, 2), None, shapely.box(5, 5, 6, 6)], index=[3, 4, 5])
    b = gpd.GeoSeries(
        [shapely.box(1, 1, 3, 3), shapely.box(0, 0, 1, 1), shapely.Polygon()], index=[3, 4, 5]
    )
    u = mk.union(a, b, threads=2)
    assert list(u.index) == [3, 4, 5] and u[4] is None
    assert u[3].area == 7 and u[5].area == 1
    i = mk.intersection(a, shapely.box(1, 1, 10, 10))
    assert [g.area for g in i[[3, 5]]] == [1, 1]
    bad = gpd.GeoSeries(
        [shapely.box(0, 0, 1, 1), shapely.Polygon([(0, 0), (2, 2), (2, 0), (0, 2)])],
        index=["x", "y"],
    )
    with pytest.raises(SelfIntersectionError, match=r"a\['y'\]"):
        mk.union(bad, shapely.box(0, 0, 1, 1))


def test_union_all_matches_the_oracle_and_names_the_member():
    boxes = [shapely.box(i, 0, i + 1.5, 1) for i in range(10)] + [shapely.box(20, 0, 21, 1)]
    r = mk.union_all(boxes)
    assert r.geom_type == "MultiPolygon" and r.area == 10.5 + 1
    assert shapely.is_valid(r)
    rings = [
        [(0, 0), (3, 0), (3, 3), (0, 3)],
        [(1, 1), (4, 1), (4, 4), (1, 4)],
        [(2, -1), (5, -1), (2, 2)],
    ]
    verts, area = oracle.boundary([[tuple(map(Fraction, p)) for p in q] for q in rings])
    _check(mk.union_all([shapely.Polygon(q) for q in rings]), verts, area)
    with pytest.raises(SelfIntersectionError, match=r"geoms\[1\]"):
        mk.union_all([shapely.box(0, 0, 1, 1), shapely.Polygon([(0, 0), (2, 2), (2, 0), (0, 2)])])
    assert mk.union_all([]).is_empty


def _length_inside(line, poly):
    return shapely.intersection(line, poly).length


@settings(max_examples=40, deadline=None)
@given(
    holey_polygon(max_holes=2),
    st.lists(st.tuples(st.integers(-120, 120), st.integers(-120, 120)), min_size=2, max_size=8),
)
def test_clip_lines_partition_the_lines(p, pts):
    g = _valid_polygon(p)
    if g is None:
        return
    # the parts are a point set: where a line runs over itself, it comes out once
    line = shapely.unary_union(shapely.LineString(pts))
    if line.length == 0:
        return
    inside = mk.clip_lines(line, g)
    outside = mk.clip_lines(line, g, keep="outside")
    # the two parts give back the line (lengths exact up to rounding of crossings)
    assert inside.length + outside.length == pytest.approx(line.length, rel=1e-12, abs=1e-9)
    # the inside parts lie in the closed polygon, the outside ones off its interior
    assert shapely.covers(g.buffer(1e-7), inside) or inside.is_empty
    assert not shapely.intersection(outside, g.buffer(-1e-7)).length > 1e-9
    assert inside.length == pytest.approx(_length_inside(line, g), rel=1e-9, abs=1e-9)
    # the parts in lexicographic order of their vertices (whatever the internal numbering)
    for parts in (inside, outside):
        seq = [np.asarray(q.coords).ravel().tolist() for q in shapely.get_parts(parts)]
        assert seq == sorted(seq)


def test_clip_lines_along_the_boundary_and_containers():
    sq = shapely.box(0, 0, 4, 4)
    assert mk.clip_lines([(-1, 0), (5, 0)], sq).wkt == "LINESTRING (0 0, 4 0)"
    assert mk.clip_lines([(-1, 0), (5, 0)], sq, keep="outside").length == 2
    assert mk.clip_lines([(5, 5), (6, 6)], sq).is_empty
    arr = np.array([shapely.LineString([(-1, 1), (5, 1)]), None], dtype=object)
    out = mk.clip_lines(arr, sq)
    assert out[0].wkt == "LINESTRING (0 1, 4 1)" and out[1] is None


@pytest.mark.parametrize("far_squares", [0, 200])
def test_rounding_that_breaks_validity_is_renoded(far_squares):
    # (A ∩ B) ∪ C exactly: a vertex (1, 1/3) a twelfth of an ulp above C's top edge, so
    # the rounded vertex (1, fl(1/3)) falls inside C; the core must see it (with 200 far
    # squares the result has > 512 edges: the check's grid, not its sweep) and re-node
    r, u = 1 / 3, math.ulp(1 / 3)
    a = shapely.Polygon([(0, 0), (3, 1), (0, 1)])
    b = shapely.box(1, -1, 2, 2)
    c = shapely.Polygon([(0, r), (0, -5), (4, -5), (4, r + u)])
    far = [shapely.box(10 * i, 10, 10 * i + 5, 15) for i in range(far_squares)]
    g = mk.intersection(
        shapely.MultiPolygon([a, c, *far]), shapely.MultiPolygon([b, c, *far]), fill_rule="nonzero"
    )
    assert shapely.is_valid(g) and len(g.geoms) == 2 + far_squares
    near = sorted((p for p in g.geoms if p.bounds[1] < 5), key=lambda p: p.bounds[1])
    # C gained the rounded vertex on its top edge; the two touch there, at one point
    assert (1.0, r) in list(near[0].exterior.coords) and (1.0, r) in list(near[1].exterior.coords)
    assert near[0].intersection(near[1]).geom_type == "Point"


def test_nested_frames_long_edges():
    # 1024 nested square frames (iOverlay's "nested squares", evenodd XOR of the bars):
    # long edges crowd the segment grid's cells, so the candidate pairs switch to the
    # packed R-tree part way; the exact area is 128 n^2 and the result valid
    n, a = 1024, 4
    r = 2 * a * np.arange(1, n + 1)
    bars_h, bars_v = [], []
    for k in range(n):
        q = int(r[k])
        bars_h += [shapely.box(-q, q - a, q, q), shapely.box(-q, -q, q, -q + a)]
        bars_v += [shapely.box(-q, -q, -q + a, q), shapely.box(q - a, -q, q, q)]
    g = mk.symmetric_difference(
        shapely.MultiPolygon(bars_h), shapely.MultiPolygon(bars_v), fill_rule="evenodd"
    )
    assert shapely.is_valid(g) and g.area == 128 * n * n
