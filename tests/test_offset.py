"""Tests of :mod:`minkowski2d.offset`: the one-sided error guarantee, checked exactly.

Every output vertex is a float, so its exact value is a Fraction. For each boundary
segment of the result and each boundary edge of the input, the squared distance between
the two segments (zero if they cross, else the least endpoint-to-segment distance, with
the foot of the perpendicular) is compared exactly with ``(r ± ε)²``. Float distances are
used only to skip pairs that are farther apart than the bound by a wide margin.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import minkowski2d as mk
from minkowski2d.errors import GeometryError, SelfIntersectionError

from .corpus import CORPUS

DATA = CORPUS


# --------------------------------------------------------------------------------------
# exact distances


def _F(p):
    return (Fraction(p[0]), Fraction(p[1]))


def _pt_seg2(p, a, b):
    """Exact squared distance from point p to segment ab."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    L = dx * dx + dy * dy
    px, py = p[0] - a[0], p[1] - a[1]
    if L == 0:
        return px * px + py * py
    t = (px * dx + py * dy) / L
    t = min(max(t, Fraction(0)), Fraction(1))
    qx, qy = px - t * dx, py - t * dy
    return qx * qx + qy * qy


def _orient(a, b, c):
    v = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (v > 0) - (v < 0)


def _cross(a, b, c, d):
    """True when the closed segments ab and cd meet (exact)."""
    o1, o2, o3, o4 = _orient(a, b, c), _orient(a, b, d), _orient(c, d, a), _orient(c, d, b)
    if o1 * o2 < 0 and o3 * o4 < 0:
        return True
    return (
        (o1 == 0 and _pt_seg2(c, a, b) == 0)
        or (o2 == 0 and _pt_seg2(d, a, b) == 0)
        or (o3 == 0 and _pt_seg2(a, c, d) == 0)
        or (o4 == 0 and _pt_seg2(b, c, d) == 0)
    )


def _seg_seg2(a, b, c, d):
    if _cross(a, b, c, d):
        return Fraction(0)
    return min(_pt_seg2(a, c, d), _pt_seg2(b, c, d), _pt_seg2(c, a, b), _pt_seg2(d, a, b))


def _segments(geom):
    """Boundary segments of a polygonal geometry, (k, 2, 2) float64."""
    out = []
    for ring in shapely.get_rings(shapely.get_parts(geom)):
        c = shapely.get_coordinates(ring)
        out.append(np.stack([c[:-1], c[1:]], 1))
    return np.concatenate(out) if out else np.empty((0, 2, 2))


def _float_seg_seg(S, T):
    """Float segment-to-segment distances, (len(S), len(T)) (for pruning only)."""
    a, b = S[:, None, 0], S[:, None, 1]
    c, d = T[None, :, 0], T[None, :, 1]

    def ps(p, q0, q1):
        v = q1 - q0
        L = (v * v).sum(-1)
        t = np.clip(((p - q0) * v).sum(-1) / np.where(L > 0, L, 1), 0, 1)
        w = p - q0 - t[..., None] * v
        return np.sqrt((w * w).sum(-1))

    return np.minimum.reduce([ps(a, c, d), ps(b, c, d), ps(c, a, b), ps(d, a, b)])


def check_lower(out_geom, in_geom, r_low):
    """Exact: every point of the result's boundary is at distance ≥ r_low from the input's
    boundary."""
    S = _segments(out_geom)
    T = _segments(in_geom)
    D = _float_seg_seg(S, T)
    scale = max(1.0, float(np.abs(T).max()), float(r_low))
    R2 = Fraction(r_low) ** 2
    for i, j in zip(*np.nonzero(D < float(r_low) + 1e-6 * scale)):
        d2 = _seg_seg2(_F(S[i, 0]), _F(S[i, 1]), _F(T[j, 0]), _F(T[j, 1]))
        assert d2 >= R2, (S[i], T[j], math.sqrt(d2), r_low)


def check_upper(out_geom, in_geom, r_up):
    """Exact: each boundary segment of the result lies within r_up of one input edge
    (both its ends do; the distance to a segment is convex)."""
    S = _segments(out_geom)
    T = _segments(in_geom)
    R2 = Fraction(r_up) ** 2
    # float distances from each end to each edge, to order the candidates
    a, b = S[:, None, 0], S[:, None, 1]
    c, d = T[None, :, 0], T[None, :, 1]
    v = d - c
    L = (v * v).sum(-1)

    def ps(p):
        t = np.clip(((p - c) * v).sum(-1) / L, 0, 1)
        w = p - c - t[..., None] * v
        return (w * w).sum(-1)

    M = np.maximum(ps(a), ps(b))
    order = np.argsort(M, axis=1)[:, :4]
    FT = [(_F(t[0]), _F(t[1])) for t in T]

    def near_one(p, q, js):
        return any(_pt_seg2(p, *FT[j]) <= R2 and _pt_seg2(q, *FT[j]) <= R2 for j in js)

    def near(p, q, depth):
        # within r_up of the union of the edges: of one edge, or each half (exact
        # midpoints) of one edge -- a segment along two nearly collinear edges has its
        # ends near different ones; where it switches, within 1e-7 of the bound, the
        # halves must be short (depth 30: a few per segment, not 2**30)
        if near_one(p, q, range(len(FT))):
            return True
        if depth == 0:
            return False
        m = ((p[0] + q[0]) / 2, (p[1] + q[1]) / 2)
        return near(p, m, depth - 1) and near(m, q, depth - 1)

    for i in range(len(S)):
        p, q = _F(S[i, 0]), _F(S[i, 1])
        ok = near_one(p, q, order[i]) or near(p, q, 30)
        assert ok, (S[i], math.sqrt(M[i].min()), r_up)


def check_offset(poly, distance, eps, approx, out=None):
    """The result of ``mk.offset`` lies on the stated side of the true set, within eps."""
    P = shapely.orient_polygons(poly if hasattr(poly, "geom_type") else shapely.Polygon(poly))
    # merge exactly collinear edges (one output segment may run along both)
    P = shapely.simplify(P, 0.0)
    if out is None:
        out = mk.offset(poly, distance, tolerance=eps, approx=approx)
    assert out.is_valid
    r = abs(Fraction(distance))
    e = Fraction(eps)
    if out.is_empty:
        assert distance < 0
        return out
    grow = distance > 0
    if grow:
        assert out.contains(P)
    else:
        assert P.contains(out)
    outer = approx == "outer"
    # grow outer: P⊕D(r) ⊆ out ⊆ P⊕D(r+ε); grow inner: P⊕D(r−ε) ⊆ out ⊆ P⊕D(r)
    # shrink outer: P⊖D(r) ⊆ out ⊆ P⊖D(r−ε); shrink inner: P⊖D(r+ε) ⊆ out ⊆ P⊖D(r)
    if grow:
        lo, hi = (r, r + e) if outer else (r - e, r)
    else:
        lo, hi = (r - e, r) if outer else (r, r + e)
    check_lower(out, P, lo)
    check_upper(out, P, hi)
    return out


def counts(g):
    """(components, holes)."""
    parts = shapely.get_parts(g)
    parts = parts[~shapely.is_empty(parts)]
    return len(parts), int(sum(len(p.interiors) for p in parts))


# --------------------------------------------------------------------------------------
# named cases

SQUARE = [(0, 0), (4, 0), (4, 4), (0, 4)]
TRI = [(0, 0), (5, 0), (1, 3)]
L_SHAPE = [(0, 0), (4, 0), (4, 1), (1, 1), (1, 4), (0, 4)]
FRAME = shapely.Polygon(SQUARE, [[(1, 1), (1, 3), (3, 3), (3, 1)]])
DUMBBELL = [(0, 0), (2, 0), (2, 0.5), (4, 0.5), (4, 0), (6, 0), (6, 2), (4, 2), (4, 1.5),
            (2, 1.5), (2, 2), (0, 2)]  # fmt: skip
C_SHAPE = [(0, 0), (6, 0), (6, 6), (0, 6), (0, 3.5), (1, 3.5), (1, 5), (5, 5), (5, 1),
           (1, 1), (1, 2.5), (0, 2.5)]  # fmt: skip
TWO = shapely.MultiPolygon([shapely.box(0, 0, 2, 2), shapely.box(3, 0, 5, 2)])
ZIGZAG = [(0, 0), (1, 2), (2, 0), (3, 2), (4, 0), (5, 2), (6, 0), (6, -1), (0, -1)]
CASES = {
    "square": SQUARE,
    "triangle": TRI,
    "L": L_SHAPE,
    "frame": FRAME,
    "dumbbell": DUMBBELL,
    "C": C_SHAPE,
    "two": TWO,
    "zigzag": ZIGZAG,
}


@pytest.mark.parametrize("name", sorted(CASES))
@pytest.mark.parametrize("distance", [0.3, 0.7, 1.3, -0.2, -0.45, -0.6])
@pytest.mark.parametrize("approx", ["outer", "inner"])
def test_named_one_sided(name, distance, approx):
    for rel in (1e-2, 1e-4):
        check_offset(CASES[name], distance, rel * abs(distance), approx)


@pytest.mark.parametrize(
    "poly, distance, expect",
    [
        (FRAME, 0.5, (1, 1)),
        (FRAME, 1.5, (1, 0)),  # the 2 × 2 hole closes at r = 1
        (FRAME, -0.4, (1, 1)),
        (FRAME, -0.6, (0, 0)),  # walls of width 1 vanish at r = 0.5
        (DUMBBELL, -0.4, (1, 0)),
        (DUMBBELL, -0.6, (2, 0)),  # the neck (width 1) splits it at r = 0.5
        (DUMBBELL, -1.1, (0, 0)),  # the 2 × 2 ends vanish at r = 1
        (TWO, 0.4, (2, 0)),
        (TWO, 0.6, (1, 0)),  # the gap of 1 closes at r = 0.5
        (C_SHAPE, 0.3, (1, 0)),
        (C_SHAPE, 0.7, (1, 1)),  # the slot (width 1) closes, the 4 × 4 cavity stays
        (C_SHAPE, 2.1, (1, 0)),  # the cavity closes at r = 2
        (ZIGZAG, 0.6, (1, 0)),
    ],
)
@pytest.mark.parametrize("approx", ["outer", "inner"])
def test_topology(poly, distance, expect, approx):
    out = check_offset(poly, distance, 1e-3 * abs(distance), approx)
    assert counts(out) == expect


def test_exact_values():
    sq = mk.offset(SQUARE, 1, tolerance=None, join="miter")
    assert sq.equals(shapely.box(-1, -1, 5, 5))
    # the outer area exceeds the true one, the inner is below, both within the bound
    true = 16 + 16 + math.pi
    for tol in (1e-2, 1e-4, 1e-6):
        o = mk.offset(SQUARE, 1, tolerance=tol)
        i = mk.offset(SQUARE, 1, tolerance=tol, approx="inner")
        assert i.area < true < o.area
        assert o.area - true < 16 * tol + 2 * math.pi * tol
        assert true - i.area < 16 * tol + 2 * math.pi * tol


def test_vertex_count_near_minimum():
    # a square's offset has four quarter arcs: the minimum per arc is ceil(θ / 2acos(1 − ε/r))
    for tol in (1e-2, 1e-4, 1e-6):
        minimum = 4 * math.ceil((math.pi / 2) / (2 * math.acos(1 - tol)))
        o = mk.offset(SQUARE, 1, tolerance=tol)
        i = mk.offset(SQUARE, 1, tolerance=tol, approx="inner")
        no = shapely.get_num_coordinates(o) - 1
        ni = shapely.get_num_coordinates(i) - 1
        assert no <= 1.02 * minimum + 4 + 4
        assert ni <= minimum + 4 + 4


def test_ceil_not_round():
    # 1.5 chords' worth of angle: round() would give 1 or 2, ceil gives 2; the error holds
    r, tol = 1.0, 1e-2
    phi = 2 * math.acos(1 - tol)
    theta = 1.45 * phi  # an exterior angle just under 1.5 steps
    tri = [(0, 0), (10, 0), (10 - 10 * math.cos(theta), 10 * math.sin(theta))]
    for approx in ("outer", "inner"):
        check_offset(tri, r, tol, approx)


def test_point_and_segment():
    d = mk.offset([(1, 1)], 2, tolerance=1e-3)
    assert math.pi * 4 < d.area < math.pi * 4 * 1.002
    s = mk.offset([(0, 0), (3, 0)], 1, tolerance=1e-3, approx="inner")
    assert 6 + math.pi * 0.998 < s.area < 6 + math.pi
    assert mk.offset([(0, 0), (3, 0)], -1, tolerance=1e-3).is_empty


def test_joins():
    tri = [(0, 0), (4, 0), (0, 4)]
    m = mk.offset(tri, 1, tolerance=None, join="miter", miter_limit=10)
    sq = mk.offset(tri, 1, tolerance=None, join="square")
    rd = mk.offset(tri, 1, tolerance=1e-4)
    assert rd.area < sq.area < m.area
    # the 45° corners' miter length is 1/sin(22.5°) = 2.61: a limit of 2 cuts them
    cut = mk.offset(tri, 1, tolerance=None, join="miter", miter_limit=2)
    assert sq.area < cut.area < m.area
    assert mk.offset(SQUARE, -1, tolerance=None, join="miter").equals(shapely.box(1, 1, 3, 3))


def test_containers_and_kinds():
    out = mk.offset([SQUARE, TRI], 0.5, tolerance=1e-3)
    assert isinstance(out, list) and len(out) == 2
    arr = np.array([shapely.Polygon(SQUARE), None], dtype=object)
    res = mk.offset(arr, 0.5, tolerance=1e-3)
    assert isinstance(res, np.ndarray) and res[1] is None
    # ints, floats and Fractions give the same result
    f = [(Fraction(x), Fraction(y)) for x, y in SQUARE]
    a = mk.offset(f, 0.5, tolerance=1e-3)
    b = mk.offset(np.array(SQUARE, float), 0.5, tolerance=1e-3)
    assert a.equals(b)
    # the input is not mutated
    arr2 = np.array(SQUARE, float)
    mk.offset(arr2, -0.5, tolerance=1e-3)
    assert arr2.tolist() == [list(map(float, p)) for p in SQUARE]


def test_offset_many_equals_single_calls():
    # shapely polygons (read and checked by the core), rings (the reader), a multipolygon
    # whose parts overlap (united first), a polygon with a hole, None
    geoms = [
        shapely.Polygon(L_SHAPE),
        SQUARE,
        FRAME,
        shapely.MultiPolygon([shapely.box(0, 0, 2, 2), shapely.box(1, 1, 3, 3)]),
        None,
        shapely.Polygon(C_SHAPE),
    ]
    for d in (0.4, -0.2):
        single = [None if g is None else mk.offset(g, d, tolerance=1e-3) for g in geoms]
        for threads in (1, 2):
            many = mk.offset_many(geoms, d, tolerance=1e-3, threads=threads)
            assert isinstance(many, list) and many[4] is None
            for a, b in zip(many, single):
                assert (a is None and b is None) or a.equals_exact(b, 0)
    out = mk.offset_many(tuple(geoms[:2]), 0.4, tolerance=1e-3)
    assert isinstance(out, tuple)
    # shapely polygons only: one compiled call, the same results in the same kind
    polys = [g for g in geoms if isinstance(g, shapely.Geometry)]
    for kind in (list, tuple, lambda x: np.array(x, dtype=object)):
        many = mk.offset_many(kind(polys), 0.4, tolerance=1e-3, threads=2)
        assert type(many) is type(kind(polys))
        for g, o in zip(polys, many):
            assert o.equals_exact(mk.offset(g, 0.4, tolerance=1e-3), 0)
    arr = mk.offset_many(np.array([shapely.Polygon(SQUARE), shapely.Polygon()], object), 0.5)
    assert isinstance(arr, np.ndarray) and arr[1].is_empty


def test_offset_many_per_member_distances():
    geoms = [shapely.Polygon(L_SHAPE), None, SQUARE, shapely.Polygon(C_SHAPE)]
    ds = [0.3, 9.0, -0.5, 0.7]
    for tol in (None, [1e-3, 1.0, 2e-3, 1e-2]):
        out = mk.offset_many(geoms, ds, tolerance=tol)
        for k, (g, d) in enumerate(zip(geoms, ds)):
            t = None if tol is None else tol[k]
            assert (g is None and out[k] is None) or out[k].equals_exact(
                mk.offset(g, d, tolerance=t), 0
            )
    # one compiled call whose results are empty, one polygon and two (a multipolygon)
    polys = [shapely.Polygon(SQUARE), shapely.Polygon(DUMBBELL), shapely.Polygon(L_SHAPE)]
    dv = [-2.5, -0.6, 0.2]
    res = mk.offset_many(polys, dv, tolerance=1e-3)
    assert [o.geom_type for o in res] == ["Polygon", "MultiPolygon", "Polygon"]
    assert res[0].is_empty
    for g, d, o in zip(polys, dv, res):
        assert o.equals_exact(mk.offset(g, d, tolerance=1e-3), 0)
    gpd = pytest.importorskip("geopandas")
    s = gpd.GeoSeries([shapely.Polygon(SQUARE), None, shapely.Polygon(), shapely.Polygon(TRI)])
    out = mk.offset_many(s, np.array([0.5, 1.0, 2.0, -0.25]), threads=2)
    assert out[1] is None and out[2].is_empty
    assert out[3].equals_exact(mk.offset(s[3], -0.25), 0)
    with pytest.raises(GeometryError, match="3 values for 4"):
        mk.offset_many(geoms, [0.1, 0.2, 0.3])
    with pytest.raises(GeometryError, match="not a float64"):
        mk.offset_many(geoms[:1], [Fraction(1, 3)])


def test_offset_many_geoseries():
    gpd = pytest.importorskip("geopandas")
    s = gpd.GeoSeries([shapely.Polygon(SQUARE), None, shapely.Polygon(L_SHAPE)],
                      index=[3, 7, 9], crs="EPSG:3857")  # fmt: skip
    out = mk.offset_many(s, 0.5, tolerance=1e-3, threads=2)
    assert isinstance(out, gpd.GeoSeries) and list(out.index) == [3, 7, 9]
    assert out.crs == s.crs and out[7] is None
    assert out[9].equals_exact(mk.offset(s[9], 0.5, tolerance=1e-3), 0)


def test_offset_many_errors_in_order():
    bowtie = shapely.Polygon([(0, 0), (2, 2), (2, 0), (0, 2)])
    # a reading error comes first (the reader names it), then the offsets' own
    with pytest.raises(SelfIntersectionError):
        mk.offset_many([shapely.Polygon(SQUARE), bowtie], 0.5, tolerance=1e-3)
    with pytest.raises(GeometryError, match="tolerance"):
        mk.offset_many([shapely.Polygon(SQUARE)], 0.5, tolerance=1e-30)
    # an offset's own error names the member: its position, or its index label
    far = shapely.box(0, 0, 1e9, 1e9)
    for polys in ([shapely.Polygon(SQUARE), far], [None, shapely.Polygon(SQUARE), far]):
        k = len(polys) - 1
        with pytest.raises(GeometryError, match=rf"^polygon\[{k}\]: tolerance: 1e-12 ") as e:
            mk.offset_many(polys, [0.5] * len(polys), tolerance=[1e-3] * k + [1e-12])
        assert e.value.argument == f"polygon[{k}]"
    gpd = pytest.importorskip("geopandas")
    with pytest.raises(GeometryError, match=r"^polygon\['b'\]: tolerance"):
        mk.offset_many(gpd.GeoSeries([shapely.Polygon(SQUARE), far], index=["a", "b"]), 0.5,
                       tolerance=1e-9)  # fmt: skip
    with pytest.raises(GeometryError, match="offset_many takes"):
        mk.offset_many(shapely.Polygon(SQUARE), 0.5)


def test_fast_path_equals_reader():
    # a shapely polygon is read and checked by the core; the same ring as a list goes
    # through the reader: the same offset
    for poly in (L_SHAPE, C_SHAPE, DUMBBELL):
        for d in (0.3, -0.2):
            a = mk.offset(shapely.Polygon(poly), d, tolerance=1e-3)
            b = mk.offset([tuple(map(float, p)) for p in poly], d, tolerance=1e-3)
            c = mk.offset(np.array(poly, float), d, tolerance=1e-3)
            assert a.equals_exact(b, 0) and a.equals_exact(c, 0)
    # invalid shapely input still gets the reader's error
    with pytest.raises(SelfIntersectionError):
        mk.offset(shapely.Polygon([(0, 0), (2, 2), (2, 0), (0, 2)]), 0.5, tolerance=1e-3)


@pytest.mark.parametrize("scale", [2.0**-600, 2.0**-30, 2.0**40, 2.0**600])
def test_extreme_magnitudes(scale):
    P = np.array(L_SHAPE, float) * scale
    out = mk.offset(P, 0.3 * scale, tolerance=1e-3 * scale)
    assert out.is_valid and counts(out) == (1, 0)
    ratio = shapely.transform(out, lambda c: c / scale).area
    ref = mk.offset(L_SHAPE, 0.3, tolerance=1e-3).area
    assert abs(ratio - ref) < 1e-9 * ref


def test_errors():
    with pytest.raises(GeometryError) as e:
        mk.offset(SQUARE, 1, tolerance=0)
    assert e.value.argument == "tolerance" and e.value.hint
    # no tolerance: the documented default, 1e-3 * |r|, not an error
    assert mk.offset(SQUARE, 1).equals(mk.offset(SQUARE, 1, tolerance=1e-3))
    with pytest.raises(GeometryError) as e:
        mk.offset(SQUARE, float("nan"), tolerance=1)
    assert e.value.argument == "distance"
    with pytest.raises(GeometryError) as e:
        mk.offset(np.array(SQUARE) + 1e9, 1, tolerance=1e-9)
    assert e.value.argument == "tolerance" and "float64" in str(e.value)
    with pytest.raises(SelfIntersectionError) as e:
        mk.offset([(0, 0), (2, 2), (2, 0), (0, 2)], 1, tolerance=1e-3)
    assert e.value.argument == "polygon"
    with pytest.raises(GeometryError):
        mk.offset(SQUARE, 1, tolerance=None, join="miter", miter_limit=0.5)
    with pytest.raises(ValueError):
        mk.offset(SQUARE, 1, tolerance=1e-3, approx="middle")


# --------------------------------------------------------------------------------------
# CGAL corpus


def _cgal(name):
    from minkowski2d.io import read_cgal_dat

    p = DATA / f"{name}.dat"
    if not p.exists():
        pytest.skip(f"CGAL corpus missing: {p} not available")
    return read_cgal_dat(p)[0]


@pytest.mark.parametrize(
    "name, r",
    [("comb_part1", 1), ("deg_square", 1), ("random_part1", 5), ("rooms_part1", 3),
     ("pwh1", 0.3), ("knife_part1", 1)],
)  # fmt: skip
def test_cgal_corpus(name, r):
    P = _cgal(name)
    for d in (r, -r / 4):
        for approx in ("outer", "inner"):
            check_offset(P, d, 1e-3 * r, approx)


# --------------------------------------------------------------------------------------
# random inputs


@st.composite
def star_polygon(draw, convex=False, holed=False):
    n = draw(st.integers(3, 11))
    angles = sorted(draw(st.lists(st.floats(0, 2 * math.pi), min_size=n, max_size=n,
                                   unique=True)))  # fmt: skip
    gaps = np.diff(np.concatenate([angles, [angles[0] + 2 * math.pi]]))
    if gaps.min() < 0.05 or gaps.max() > math.pi - 0.05:
        angles = np.linspace(0, 2 * math.pi, n, endpoint=False) + angles[0]
    if convex:
        radii = [10.0] * n
    else:
        radii = draw(st.lists(st.floats(4, 10), min_size=n, max_size=n))
    pts = [(round(r * math.cos(a), 3), round(r * math.sin(a), 3)) for r, a in zip(radii, angles)]
    g = shapely.Polygon(pts)
    if holed:
        g = shapely.Polygon(pts, [[(x * 0.3, y * 0.3) for x, y in pts]])
    if not g.is_valid or g.area < 1:
        g = shapely.Polygon([(0, 0), (6, 0), (3, 5)])
    return g


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    g=st.one_of(star_polygon(convex=True), star_polygon(), star_polygon(holed=True)),
    r=st.floats(0.05, 6),
    grow=st.booleans(),
    rel=st.sampled_from([1e-2, 1e-3]),
    approx=st.sampled_from(["outer", "inner"]),
)
def test_random_one_sided(g, r, grow, rel, approx):
    check_offset(g, r if grow else -r, rel * r, approx)


# --------------------------------------------------------------------------------------
# exact arcs


def _arc_rows(arcs):
    return [r for p in arcs.polygons for r in p]


def _ring_signed_area(ring, radius):
    x, y, b = ring[:, 0], ring[:, 1], ring[:, 2]
    a = 0.5 * float((x * np.roll(y, -1) - np.roll(x, -1) * y).sum())
    sw = 4 * np.arctan(b[b != 0])
    return a + float((0.5 * radius**2 * (sw - np.sin(sw))).sum())


@pytest.mark.parametrize("name", sorted(CASES))
@pytest.mark.parametrize("distance", [0.3, 1.3, -0.2, -0.45])
def test_arcs_exact_boundary(name, distance):
    poly = CASES[name]
    arcs = mk.offset_arcs(poly, distance)
    assert arcs.verified
    P = shapely.orient_polygons(poly if hasattr(poly, "geom_type") else shapely.Polygon(poly))
    verts = {tuple(v) for v in shapely.get_coordinates(P).tolist()}
    r = abs(distance)
    bnd = shapely.boundary(P)
    for ring in _arc_rows(arcs):
        # every junction lies on the true boundary: at distance r from the polygon
        d = shapely.distance(shapely.points(ring[:, :2]), bnd)
        assert np.allclose(d, r, rtol=0, atol=1e-12 * 8)
        arc = ~np.isnan(ring[:, 3])
        # arcs are centred at the polygon's vertices, bulging outwards for a grow
        assert all(tuple(c) in verts for c in ring[arc, 3:5].tolist())
        assert (np.sign(ring[arc, 2]) == np.sign(distance)).all()
        ends = np.roll(ring[:, :2], -1, 0)[arc]
        assert np.allclose(np.hypot(*(ends - ring[arc, 3:5]).T), r, atol=1e-12)
    # the exact area lies between the inner and the outer approximations
    outer = mk.offset(poly, distance, tolerance=1e-7 * r)
    inner = mk.offset(poly, distance, tolerance=1e-7 * r, approx="inner")
    assert inner.area - 1e-9 <= arcs.area <= outer.area + 1e-9
    assert counts(outer) == (len(arcs.polygons), sum(len(p) - 1 for p in arcs.polygons))
    # exteriors counter-clockwise, holes clockwise
    for p in arcs.polygons:
        assert _ring_signed_area(p[0], r) > 0
        assert all(_ring_signed_area(h, r) < 0 for h in p[1:])


def test_arcs_square_and_point():
    a = mk.offset_arcs(SQUARE, 1)
    ring = a.polygons[0][0]
    assert ring[:, :2].tolist() == [[0, -1], [4, -1], [5, 0], [5, 4], [4, 5], [0, 5], [-1, 4],
                                    [-1, 0]]  # fmt: skip
    assert np.allclose(ring[1::2, 2], math.tan(math.pi / 8))
    assert a.svg_path().count(" A ") == 4
    disk = mk.offset_arcs([(2, 3)], 1.5)
    assert abs(disk.area - math.pi * 2.25) < 1e-12
    assert mk.offset_arcs(SQUARE, -3).polygons == []


def test_arcs_flat_arc_is_straight():
    # a vertex that turns by 1e-13 rad: its arc has a sagitta far below one ulp
    P = [(0, 0), (1, 0), (2, 1e-13), (2, 5), (0, 5)]
    ring = mk.offset_arcs(P, 1).polygons[0][0]
    assert int((ring[:, 2] != 0).sum()) == 4


def test_arcs_to_polygon_and_dxf(tmp_path):
    ezdxf = pytest.importorskip("ezdxf")
    arcs = mk.offset_arcs(FRAME, 0.4)
    assert arcs.to_polygon(1e-3).equals(mk.offset(FRAME, 0.4, tolerance=1e-3))
    path = tmp_path / "frame.dxf"
    arcs.to_dxf(path)
    doc = ezdxf.readfile(path)
    polys = list(doc.modelspace().query("LWPOLYLINE"))
    rings = _arc_rows(arcs)
    assert len(polys) == len(rings) == 2
    for e, ring in zip(polys, rings):
        assert e.closed
        pts = np.array([tuple(p) for p in e.get_points("xyb")], float)
        assert np.array_equal(pts, ring[:, :3])
    # outer ring counter-clockwise (positive bulges), the hole clockwise
    assert _ring_signed_area(rings[0], 0.4) > 0 > _ring_signed_area(rings[1], 0.4)
    assert arcs.to_svg().startswith("<svg")


# --------------------------------------------------------------------------------------
# command line


def test_cli_offset(tmp_path, capsys):
    from minkowski2d.cli import main

    src = tmp_path / "sq.json"
    src.write_text("[[0, 0], [4, 0], [4, 4], [0, 4]]")
    assert main(["offset", str(src), "-r", "1", "--tolerance", "0.01", "--format", "wkt"]) == 0
    g = shapely.from_wkt(capsys.readouterr().out)
    check_offset(SQUARE, 1, 0.01, "outer", out=g)
    assert main(["offset", str(src), "-r", "-1", "--join", "miter", "--format", "wkt"]) == 0
    assert shapely.from_wkt(capsys.readouterr().out).equals(shapely.box(1, 1, 3, 3))
    assert main(["offset", str(src), "-r", "1", "--format", "svg"]) == 0
    assert " A " in capsys.readouterr().out
    pytest.importorskip("ezdxf")
    out = tmp_path / "o.dxf"
    assert main(["offset", str(src), "-r", "-0.5", "-o", str(out)]) == 0
    # DXF in: the shrunk square read back and grown again
    assert main(["offset", str(out), "-r", "0.5", "--join", "miter", "--format", "wkt"]) == 0
    assert shapely.from_wkt(capsys.readouterr().out).equals(shapely.box(0, 0, 4, 4))
    # a round join without tolerance: the default tolerance, 1e-3 * |r|
    assert main(["offset", str(src), "-r", "1", "--format", "wkt"]) == 0
    got = shapely.from_wkt(capsys.readouterr().out)
    want = mk.offset([(0, 0), (4, 0), (4, 4), (0, 4)], 1, tolerance=1e-3)
    assert got.area == want.area and got.hausdorff_distance(want) < 1e-12


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    g=st.one_of(star_polygon(), star_polygon(holed=True)),
    r=st.floats(0.05, 6),
    grow=st.booleans(),
)
def test_random_arcs_area(g, r, grow):
    d = r if grow else -r
    arcs = mk.offset_arcs(g, d)
    outer = mk.offset(g, d, tolerance=1e-7 * r)
    inner = mk.offset(g, d, tolerance=1e-7 * r, approx="inner")
    if arcs.verified:
        assert inner.area - 1e-9 <= arcs.area <= outer.area + 1e-9


def test_touching_parts_and_degenerate_inputs():
    two = shapely.MultiPolygon([shapely.box(0, 0, 1, 1), shapely.box(1, 0, 2, 1)])
    out = mk.offset(two, 0.1, tolerance=1e-3)
    check_offset(shapely.box(0, 0, 2, 1), 0.1, 1e-3, "outer", out=out)  # their union
    assert counts(out) == (1, 0)
    # collinear points are the segment they span
    s = mk.offset([(0, 0), (1, 1), (2, 2)], 1, tolerance=1e-3, approx="inner")
    assert 4 * math.sqrt(2) + math.pi * 0.99 < s.area < 4 * math.sqrt(2) + math.pi
    assert mk.offset(SQUARE, 0, tolerance=1e-3).equals(shapely.Polygon(SQUARE))
