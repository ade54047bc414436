"""Exact triangulation in the compiled core (triangulate.hpp), checked by a brute-force
Fraction oracle (tests/polygon_oracle.py): every triangle counter-clockwise with input
vertices, inside the polygon, pairwise interior-disjoint, areas summing exactly to the
polygon's -- on random, degenerate (touching holes, collinear runs, equal y's) and scaled
polygons, the CGAL corpus and the ESICUP parts; and the decomposition built on it."""

from __future__ import annotations

import math
import time
from fractions import Fraction

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import minkowski2d as mk
from minkowski2d._core import _ext
from minkowski2d._engine import polygon as _polygon
from minkowski2d._engine.dispatch import Status
from minkowski2d._engine.polygon import Invalid
from minkowski2d.errors import SelfIntersectionError

from . import polygon_oracle as oracle
from .corpus import corpus_files, requires_corpus
from .strategies import (
    SCALES,
    checkerboard_polygon,
    diamond_polygon,
    grid_polygon,
    holey_polygon,
    scaled,
    star_ring,
)
from .test_polygon_core import SQ, esicup_parts, rings


def triangles(*polys):
    r = rings(*polys)
    status, reason, ring, vertex, tri = _ext.triangulate_polygons_f(
        r.coords, r.ring_offsets, r.polygon_offsets
    )
    return r, status, reason, tri


def locally_delaunay(coords, tri) -> bool:
    """No flippable edge left: for two triangles sharing an edge whose quadrilateral is
    strictly convex, the far vertex is not strictly inside the circumcircle (Fractions)."""
    pts = [(Fraction(x), Fraction(y)) for x, y in coords.tolist()]
    where = {}
    for t in tri.tolist():
        for k in range(3):
            where[(t[k], t[(k + 1) % 3])] = t[(k + 2) % 3]
    for (a, c), b in where.items():
        d = where.get((c, a))
        if d is None:
            continue
        A, B, C, D = (pts[i] for i in (a, b, c, d))
        if oracle.orient(B, A, D) <= 0 or oracle.orient(D, C, B) <= 0:
            continue
        if incircle_ref(A, C, B, D) > 0:
            return False
    return True


def incircle_ref(a, b, c, d) -> int:
    adx, ady, bdx, bdy = a[0] - d[0], a[1] - d[1], b[0] - d[0], b[1] - d[1]
    cdx, cdy = c[0] - d[0], c[1] - d[1]
    v = (
        (adx * adx + ady * ady) * (bdx * cdy - bdy * cdx)
        + (bdx * bdx + bdy * bdy) * (cdx * ady - cdy * adx)
        + (cdx * cdx + cdy * cdy) * (adx * bdy - ady * bdx)
    )
    return (v > 0) - (v < 0)


def check_tiles(poly, delaunay=True) -> np.ndarray:
    """Triangulate one polygon (a list of rings) and check it exactly; the triangles."""
    r = rings(poly)
    status, reason, _, _, tri = _ext.triangulate_polygons_f(
        r.coords, r.ring_offsets, r.polygon_offsets, delaunay
    )
    assert status == Status.OK, Invalid(reason).name
    assert tri.dtype == np.int64 and tri.shape[1:] == (3,)
    errs = oracle.triangulation_errors([poly], r.coords, tri)
    assert not errs, errs[:3]
    if delaunay:
        assert locally_delaunay(r.coords, tri)
    return tri


def check_if_valid(*polys) -> bool:
    r, status, reason, tri = triangles(*polys)
    if oracle.problems(list(polys)):
        assert status == Status.INVALID_POLYGON and len(tri) == 0
        return False
    assert status == Status.OK, Invalid(reason).name
    for p in polys:
        check_tiles(p)
        check_tiles(p, delaunay=False)  # the monotone partition's own triangles
    return True


# --------------------------------------------------------------------------------------
# named cases


def test_square_l_and_comb():
    assert len(check_tiles([SQ])) == 2
    L = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    assert len(check_tiles([L])) == 4
    comb = [(0, 0), (7, 0), (7, 3), (6, 3), (6, 1), (5, 1), (5, 3), (4, 3), (4, 1), (3, 1),
            (3, 3), (2, 3), (2, 1), (1, 1), (1, 3), (0, 3)]  # fmt: skip
    assert len(check_tiles([comb])) == len(comb) - 2


@pytest.mark.parametrize(
    "poly",
    [
        [SQ, [(2, 2), (4, 2), (4, 4), (2, 4)]],
        [SQ, [(2, 2), (4, 2), (4, 4), (2, 4)], [(6, 6), (8, 6), (8, 8), (6, 8)]],
        [SQ, [(0, 0), (3, 5), (5, 3)]],  # a hole touching the shell at its vertex
        [SQ, [(0, 5), (3, 4), (3, 6)]],  # ... inside the shell's edge
        [SQ, [(5, 0), (6, 3), (4, 3)]],  # ... at the bottom (a split in the sweep)
        [SQ, [(5, 10), (4, 7), (6, 7)]],  # ... at the top (a merge)
        [SQ, [(0, 5), (5, 2), (10, 5), (5, 8)]],  # at two points: two parts
        [SQ, [(5, 0), (10, 5), (5, 10), (0, 5)]],  # a diamond touching all four sides
        [SQ, [(2, 2), (5, 2), (5, 5)], [(5, 5), (8, 5), (8, 8)]],  # holes touching
        [SQ, [(2, 2), (5, 2), (5, 5)], [(3, 2), (4, 1), (5, 1)]],  # inside an edge
        [SQ, [(5, 5), (7, 3), (7, 7)], [(5, 5), (3, 7), (3, 3)]],  # a bow-tie of holes
        [[(0, 0), (2, 0), (4, 0), (4, 2), (4, 4), (2, 4), (0, 4), (0, 2)]],  # collinear runs
        [[(0, 0), (1, 0), (2, 0), (3, 0), (3, 1), (0, 1)]],  # equal y's everywhere
        [[(0, 0), (4, 0), (4, 4), (3, 1), (2, 4), (1, 1), (0, 4)]],  # a W
        [[(0, 0), (4, 2), (0, 4), (1, 2)]],  # a dart
        [[(0.0, 0.0), (3e-200, 0.0), (0.0, 3e-200)]],
        [[(0.0, 0.0), (1e300, 0.0), (1e300, 1e300), (5e299, 1e299), (0.0, 1e300)]],
        [[(0.0, 0.0), (5e-324, 0.0), (1e-323, 5e-324), (0.0, 1e-323)]],  # subnormals
    ],
)
def test_named_cases(poly):
    check_tiles(poly)


def test_hole_touching_inside_edge_uses_the_hole_vertex():
    tri = check_tiles([SQ, [(0, 5), (3, 4), (3, 6)]])
    # the shell edge is split at the hole's vertex (0, 5): id 4, used by triangles on
    # both sides of it
    assert (tri == 4).sum() >= 2


def test_duplicates_map_to_one_id():
    poly = [[(0, 0), (0, 0), (10, 0), (10, 10), (0, 10), (0, 0)], [(0, 0), (3, 5), (5, 3)]]
    tri = check_tiles(poly)
    used = set(tri.ravel().tolist())
    assert 0 in used and not used & {1, 5, 6}  # (0, 0): the smallest id, not its repeats


def test_collection_is_triangulated_polygon_by_polygon():
    a, b = [SQ], [[(2, 2), (5, 2), (5, 5)]]  # overlapping: each tiled on its own
    r, status, _, tri = triangles(a, b)
    assert status == Status.OK
    ta = check_tiles(a)
    assert tri[: len(ta)].tolist() == ta.tolist() and len(tri) == len(ta) + 1


def test_invalid_input_gives_no_triangles():
    r, status, reason, tri = triangles([[(0, 0), (2, 2), (2, 0), (0, 2)]])
    assert status == Status.INVALID_POLYGON and tri.shape == (0, 3)
    with pytest.raises(SelfIntersectionError):
        _polygon.triangulate(r, "a")


# --------------------------------------------------------------------------------------
# random and degenerate polygons

SETTINGS = settings(max_examples=50, deadline=None, suppress_health_check=list(HealthCheck))


@SETTINGS
@given(star_ring(max_n=16))
def test_random_simple_polygons(ring):
    check_if_valid([ring])


@SETTINGS
@given(holey_polygon())
def test_random_polygons_with_holes(poly):
    check_if_valid(poly)


@settings(max_examples=150, deadline=None, suppress_health_check=list(HealthCheck))
@given(grid_polygon(size=3))
def test_grid_polygons(poly):
    check_if_valid(poly)


@settings(max_examples=30, deadline=None, suppress_health_check=list(HealthCheck))
@given(st.integers(1, 3).flatmap(lambda k: diamond_polygon(k=k)))
def test_touching_holes(poly):
    assert check_if_valid(poly)


@settings(max_examples=30, deadline=None, suppress_health_check=list(HealthCheck))
@given(st.integers(1, 3).flatmap(lambda k: checkerboard_polygon(k=k)))
def test_checkerboard_holes(poly):
    assert check_if_valid(poly)


def test_pinwheel_of_holes_touching_at_one_point():
    """Six triangular holes meet at the centre (twelve edges at one point)."""
    c = (0, 0)
    pts = [(10, 0), (9, 5), (5, 9), (0, 10), (-5, 9), (-9, 5), (-10, 0), (-9, -5), (-5, -9),
           (0, -10), (5, -9), (9, -5)]  # fmt: skip
    holes = [[c, pts[2 * i], pts[2 * i + 1]] for i in range(6)]
    shell = [(-20, -20), (20, -20), (20, 20), (-20, 20)]
    tri = check_tiles([shell, *holes])
    # the region's angles: 2 pi at the shell's corners, 2 pi around each of the 12 outer
    # hole vertices and around the centre, less the holes' own 6 pi: 22 pi, 22 triangles
    assert len(tri) == 22
    r = rings([shell, *holes])
    assert _ext.check_polygons_f(r.coords, r.ring_offsets, r.polygon_offsets)[5].tolist() == [False]


@SETTINGS
@given(st.one_of(holey_polygon(max_holes=2), diamond_polygon(k=2)), st.sampled_from(SCALES))
def test_every_scale(poly, s):
    check_if_valid(scaled(poly, s))


@SETTINGS
@given(holey_polygon(max_holes=3), st.integers(0, 3))
def test_rotations_and_reflections(poly, quarter):
    """Quarter turns and a reflection move the equal-y cases around (exactly)."""

    def turn(p):
        x, y = p
        for _ in range(quarter):
            x, y = -y, x
        return (x, y)

    check_if_valid([[turn(p) for p in r] for r in poly])
    check_if_valid([[(-x, y) for x, y in r] for r in poly])


# --------------------------------------------------------------------------------------
# real data


def _rings_list(r):
    return [r.coords[a:b].tolist() for a, b in zip(r.ring_offsets[:-1], r.ring_offsets[1:])]


@requires_corpus
@pytest.mark.parametrize("path", corpus_files(), ids=lambda p: p.name)
def test_cgal_corpus(path):
    from minkowski2d.io import read_cgal_dat

    for g in read_cgal_dat(path):
        if type(g).__name__ == "UnboundedPolygon":
            continue
        r = _polygon.rings_of(g) if hasattr(g, "geom_type") else _polygon.rings_of_array(g)
        tri = _polygon.triangulate(r, path.name)
        poly = _rings_list(r)
        if len(r.coords) <= 150:
            errs = oracle.triangulation_errors([poly], r.coords, tri)
            assert not errs, errs[:3]
        else:
            tiles_by_area(r, tri)


def tiles_by_area(r, tri) -> None:
    """The cheaper exact check for large inputs: counter-clockwise triangles, pairwise
    interior-disjoint (box-pruned), areas summing exactly to the polygon's."""
    pts, _ = oracle._as_ints([(Fraction(x), Fraction(y)) for x, y in r.coords.tolist()])
    T = [tuple(pts[i] for i in t) for t in tri.tolist()]
    assert all(oracle.orient(*t) > 0 for t in T)
    want = 0
    for k, (a, b) in enumerate(zip(r.ring_offsets[:-1], r.ring_offsets[1:])):
        ring = oracle.dedupe(pts[a:b])
        want += abs(oracle.area2(ring)) * (1 if k == 0 else -1)
    assert sum(oracle.area2(list(t)) for t in T) == want
    boxes = [oracle._box(t) for t in T]
    assert all(oracle._interiors_disjoint(T[i], T[j]) for i, j in oracle._pairs(boxes))


def test_esicup_parts():
    """Every part of every ESICUP instance: up to 30 vertices as given and rotated by 105
    degrees, through the full oracle; larger ones (for time) as given or rotated, in
    turn, through the area-and-overlap check."""
    parts = esicup_parts()
    if not parts:
        pytest.skip("ESICUP data not found")
    for k, (name, p) in enumerate(parts):
        small = len(p.exterior.coords) <= 31
        for angle in (0, 105) if small else ((0, 105)[k % 2],):
            g = shapely.affinity.rotate(p, angle, origin=(0, 0)) if angle else p
            r = _polygon.rings_of(g)
            tri = _polygon.triangulate(r, name)
            if len(r.coords) <= 30:
                errs = oracle.triangulation_errors([_rings_list(r)], r.coords, tri)
                assert not errs, (name, angle, errs[:3])
            else:
                tiles_by_area(r, tri)


def star(n: int, r1: float, r2: float) -> np.ndarray:
    k = np.arange(n)
    rad = np.where(k % 2 == 0, r1, r2)
    return np.c_[rad * np.cos(2 * math.pi * k / n), rad * np.sin(2 * math.pi * k / n)]


def test_large_star_quickly_and_exactly():
    s = star(2048, 10000, 5000)
    r = _polygon.rings_of_array(s)
    t = time.perf_counter()
    tri = _polygon.triangulate(r, "a")
    assert time.perf_counter() - t < 0.5
    assert len(tri) == len(s) - 2
    pts = [(Fraction(x), Fraction(y)) for x, y in s.tolist()]
    assert sum(oracle.area2([pts[i] for i in t]) for t in tri.tolist()) == oracle.area2(pts)


# --------------------------------------------------------------------------------------
# the in-circle predicate (exact.hpp), used by the Delaunay flips

coord = st.one_of(
    st.integers(-4, 4).map(float),
    st.floats(-1, 1, allow_nan=False, allow_infinity=False),
    st.floats(allow_nan=False, allow_infinity=False, min_value=-1e300, max_value=1e300),
)


@settings(max_examples=300, deadline=None)
@given(st.lists(st.tuples(coord, coord), min_size=4, max_size=4), st.sampled_from(SCALES))
def test_incircle_is_exact(pts, s):
    pts = [(x * s, y * s) for x, y in pts]
    assume(all(math.isfinite(v) for p in pts for v in p))
    want = incircle_ref(*[(Fraction(x), Fraction(y)) for x, y in pts])
    args = [v for p in pts for v in p]
    assert _ext.incircle_f(*args) == want
    assert _ext.incircle_exact_f(*args) == want


def test_incircle_extremes():
    for s in (1.0, 2.0**-1074, 1e-310, 1e300, 2.0**1000):
        a, b, c = (0.0, 0.0), (2 * s, 0.0), (0.0, 2 * s)
        assert _ext.incircle_f(*a, *b, *c, s, s) == 1  # the centre
        assert _ext.incircle_f(*a, *b, *c, 2 * s, 2 * s) == 0  # on the circle
        assert _ext.incircle_f(*a, *b, *c, 3 * s, 3 * s) == -1
    # mixed magnitudes in one call
    assert _ext.incircle_f(0.0, 0.0, 1e300, 0.0, 0.0, 1e300, 5e-324, 5e-324) == 1
    assert _ext.incircle_f(0.0, 0.0, 1e300, 0.0, 0.0, 1e300, -5e-324, 0.0) == -1


def boundary_edges(tri) -> set:
    """The directed edges of a triangulation that no other triangle shares."""
    e = {(t[k], t[(k + 1) % 3]) for t in tri.tolist() for k in range(3)}
    return {(a, b) for a, b in e if (b, a) not in e}


def test_flips_change_only_the_diagonals():
    """A U with long thin arms: the stack's fans are flipped, the boundary stays."""
    poly = [[(0, 0), (10, 0), (10, 9), (9, 9), (9, 1), (1, 1), (1, 9), (0, 9)]]
    plain, flipped = check_tiles(poly, delaunay=False), check_tiles(poly)
    assert len(plain) == len(flipped) == 6
    assert boundary_edges(plain) == boundary_edges(flipped)
    assert not locally_delaunay(rings(poly).coords, plain)


def test_hertel_mehlhorn_pieces_at_parity_with_geos():
    """Over every ESICUP part, Hertel-Mehlhorn on the exact (Delaunay-flipped) triangles
    gives no more than 1 % more pieces than on GEOS's constrained Delaunay triangles
    (the old path): the number of piece-pair sums of a general sum depends on it."""
    from minkowski2d._engine.decompose import _twins, decompose

    parts = [p for _, p in esicup_parts()]
    if not parts:
        pytest.skip("ESICUP data not found")

    def geos_pieces(g):
        t = shapely.get_parts(shapely.constrained_delaunay_triangles(g))
        c = shapely.get_coordinates(shapely.get_exterior_ring(t)).reshape(len(t), 4, 2)[:, :3]
        verts, inv = np.unique(c.reshape(-1, 2), axis=0, return_inverse=True)
        ids = np.ascontiguousarray(inv.reshape(-1, 3), dtype=np.int64)
        ids = np.ascontiguousarray(ids[_ext.orient_triangles_f(verts, ids)])
        return len(_ext.hertel_mehlhorn_f(verts, ids, _twins(ids, len(verts)), True)[1]) - 1

    ours = sum(len(decompose(p, True)[1]) - 1 for p in parts)
    geos = sum(geos_pieces(p) for p in parts)
    assert ours <= 1.01 * geos, (ours, geos)


# --------------------------------------------------------------------------------------
# the decomposition runs on these triangles, without GEOS


def test_decomposition_makes_no_geos_triangulation(monkeypatch):
    def boom(*args, **kwargs):
        raise AssertionError("GEOS triangulation called")

    monkeypatch.setattr(shapely, "constrained_delaunay_triangles", boom)
    poly = shapely.Polygon(SQ, [[(2, 2), (4, 2), (4, 4), (2, 4)]])
    tri = mk.convex_decomposition(poly, method="triangulation")
    assert len(tri) == 8
    assert sum(shapely.area(tri.to_shapely())) == poly.area
    hm = mk.convex_decomposition(poly)
    assert sum(shapely.area(hm.to_shapely())) == poly.area and len(hm) < 8


def test_decomposition_of_touching_holes():
    poly = shapely.Polygon(SQ, [[(0, 5), (5, 2), (10, 5), (5, 8)]])  # two parts
    for method in ("hertel-mehlhorn", "triangulation"):
        pieces = mk.convex_decomposition(poly, method=method)
        assert sum(shapely.area(pieces.to_shapely())) == poly.area
