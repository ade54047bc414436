"""verify_layout (the exact certificate of a layout) against the brute-force oracle of
tests/nesting_oracle.py, on random layouts of small polygons (ints, floats, holes, turned
by 90 degrees or not, touching exactly, overlapping or apart by one ulp, parts in holes,
spacing and margin exactly met or missed by the least amount), with the float filter on
and off; plus named hand cases."""

from __future__ import annotations

import math
from fractions import Fraction as F
from unittest import mock

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from minkowski2d.errors import GeometryError, LayoutError
from minkowski2d.nesting import verify as V
from minkowski2d.nesting.layout import Layout, Placement
from minkowski2d.nesting.nfp import rotate_part
from minkowski2d.nesting.verify import Violation, verify_layout

from . import nesting_oracle as O
from .strategies import star_ring

# --------------------------------------------------------------------------------------
# helpers


def layout(parts, places, sheets=None, spacing=0.0, margin=0.0):
    """``places``: (part, rotation, (x, y)[, sheet]) per placement."""
    pl = [Placement(p[0], k, p[3] if len(p) > 3 else 0, p[1], p[2]) for k, p in enumerate(places)]
    sheets = sheets or [shapely.box(-100, -100, 100, 100)]
    return Layout(parts, pl, sheets, kinds=list(range(len(sheets))), spacing=spacing,
                  margin=margin)  # fmt: skip


def exact_polygon(part, rotation, t):
    g = rotate_part(part, rotation)
    tx, ty = F(t[0]), F(t[1])
    rings = [g.exterior.coords, *[r.coords for r in g.interiors]]
    return [[(F(x) + tx, F(y) + ty) for x, y in r] for r in rings]


def oracle(lay) -> set:
    polys = [exact_polygon(lay.parts[p.part], p.rotation, p.translation) for p in lay.placements]
    sheets = [O.ex([s.exterior.coords, *[r.coords for r in s.interiors]]) for s in lay.sheets]
    return O.violations(polys, [p.sheet for p in lay.placements], sheets, F(lay.spacing),
                        F(lay.margin))  # fmt: skip


def got(lay) -> set:
    vs = verify_layout(lay)
    assert vs == sorted(vs, key=lambda v: (v.a, -1 if v.b is None else v.b))
    return {(v.kind, v.a, v.b) for v in vs}


def kinds(lay) -> list:
    return [(v.kind, v.a, v.b) for v in verify_layout(lay)]


def exact_only():
    """The float filter switched off: every sign from the exact integer path."""
    return mock.patch.object(V, "_REL", math.inf)


def up(x, k=1):
    for _ in range(k):
        x = float(np.nextafter(x, np.inf))
    return x


def down(x, k=1):
    for _ in range(k):
        x = float(np.nextafter(x, -np.inf))
    return x


SQ = shapely.box(0, 0, 1, 1)
FRAME = shapely.Polygon([(0, 0), (4, 0), (4, 4), (0, 4)], [[(1, 1), (3, 1), (3, 3), (1, 3)]])
TRI = shapely.Polygon([(0, 0), (3, 0), (0, 2)])
ELL = shapely.Polygon([(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)])
ARROW = shapely.Polygon([(0, 0), (2, 1), (0, 2), (1, 1)])
SHAPES = [SQ, FRAME, TRI, ELL, ARROW, shapely.box(0, 0, 2, 1)]

# --------------------------------------------------------------------------------------
# random layouts


@st.composite
def shapes(draw):
    if draw(st.integers(0, 4)) == 0:
        ring = draw(star_ring(rmin=2, rmax=6, max_n=7))
        p = shapely.Polygon(ring)
        if not p.is_valid:
            p = p.convex_hull
        if p.geom_type != "Polygon" or not p.is_valid:
            p = TRI
    else:
        p = draw(st.sampled_from(SHAPES))
    s = draw(st.sampled_from([1.0, 0.5, 0.1, 3.0]))
    return shapely.affinity.scale(p, s, s, origin=(0, 0)) if s != 1 else p


def _bounds(part, rot, t=(0.0, 0.0)):
    b = rotate_part(part, rot).bounds
    return (b[0] + t[0], b[1] + t[1], b[2] + t[0], b[3] + t[1])


@st.composite
def layouts(draw):
    n = draw(st.integers(2, 4))
    parts = [draw(shapes()) for _ in range(draw(st.integers(1, 3)))]
    spacing = draw(st.sampled_from([0.0, 0.0, 0.5, 0.1, 1.0]))
    margin = draw(st.sampled_from([0.0, 0.0, 0.5, 0.25]))
    step = draw(st.sampled_from([1.0, 0.5, 0.25]))
    places = []
    for k in range(n):
        p = draw(st.integers(0, len(parts) - 1))
        rot = draw(st.sampled_from([0, 90, 180, 270, 0, 30, 45]))
        mode = draw(st.sampled_from(["grid", "next", "above", "hole"])) if k else "grid"
        b = _bounds(parts[p], rot)
        if mode == "grid":
            t = [draw(st.integers(-2, 10)) * step, draw(st.integers(-2, 10)) * step]
        else:
            q, qrot, qt = places[draw(st.integers(0, k - 1))]
            qb = _bounds(parts[q], qrot, qt)
            gap = draw(st.sampled_from([0.0, spacing, margin, step]))
            if mode == "next":  # to the right of placement q: touching or `gap` apart
                t = [qb[2] - b[0] + gap, qt[1] + draw(st.integers(-1, 1)) * step]
            elif mode == "above":
                t = [qt[0] + draw(st.integers(-1, 1)) * step, qb[3] - b[1] + gap]
            else:  # inside q's box, at its lower left corner (in a frame: in its hole?)
                t = [
                    qb[0] - b[0] + draw(st.sampled_from([0, 1, 0.5])) * (qb[2] - qb[0]) / 4,
                    qb[1] - b[1] + draw(st.sampled_from([0, 1, 0.5])) * (qb[3] - qb[1]) / 4,
                ]
            axis = draw(st.integers(0, 1))
            nudge = draw(st.sampled_from([0, 0, 1, -1, 2]))
            t[axis] = up(t[axis], nudge) if nudge >= 0 else down(t[axis], -nudge)
        places.append((p, rot, (float(t[0]), float(t[1]))))
    W = draw(st.sampled_from([12.0, 6.0, 9.5]))
    holes = []
    if draw(st.booleans()):
        x, y = draw(st.integers(0, 8)) * 1.0, draw(st.integers(0, 8)) * 1.0
        holes = [[(x, y), (x + 1.5, y), (x + 1.5, y + 1), (x, y + 1)]]
    sheet = shapely.Polygon([(-1, -1), (W, -1), (W, W), (-1, W)], holes)
    sheets = [sheet] if sheet.is_valid else [shapely.box(-1, -1, W, W)]
    if draw(st.booleans()):
        sheets.append(shapely.box(0, 0, 5, 5))
        places = [(*pl, draw(st.integers(0, 1))) for pl in places]
    return layout(parts, places, sheets, spacing, margin)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(layouts())
def test_random_layouts_agree_with_the_oracle(lay):
    want = oracle(lay)
    assert got(lay) == want
    with exact_only():
        assert got(lay) == want


# --------------------------------------------------------------------------------------
# hand cases: contacts


def test_touching_squares_pass_and_one_ulp_overlap_fails():
    parts = [SQ]
    assert kinds(layout(parts, [(0, 0, (0.0, 0.0)), (0, 0, (1.0, 0.0))])) == []
    assert kinds(layout(parts, [(0, 0, (0.0, 0.0)), (0, 0, (down(1.0), 0.0))])) == [
        ("overlap", 0, 1)
    ]
    assert kinds(layout(parts, [(0, 0, (0.0, 0.0)), (0, 0, (up(1.0), 0.0))])) == []
    # corner to corner, and a corner one ulp inside
    assert kinds(layout(parts, [(0, 0, (0.0, 0.0)), (0, 0, (1.0, 1.0))])) == []
    assert kinds(layout(parts, [(0, 0, (0.0, 0.0)), (0, 0, (down(1.0), down(1.0)))])) == [
        ("overlap", 0, 1)
    ]


def test_identical_and_nested_placements_overlap():
    lay = layout([SQ, shapely.box(0.25, 0.25, 0.5, 0.5)],
                 [(0, 0, (0.0, 0.0)), (0, 0, (0.0, 0.0)), (1, 0, (0.0, 0.0))])  # fmt: skip
    assert kinds(lay) == [("overlap", 0, 1), ("overlap", 0, 2), ("overlap", 1, 2)]
    assert "same side" in verify_layout(lay)[0].detail


def test_a_part_in_a_hole_is_no_overlap_but_keeps_the_spacing():
    lay = layout([FRAME, SQ], [(0, 0, (0.0, 0.0)), (1, 0, (1.0, 1.0))])
    assert kinds(lay) == []  # touching the hole's corner from inside
    lay = layout([FRAME, SQ], [(0, 0, (0.0, 0.0)), (1, 0, (1.5, 1.5))], spacing=0.5)
    assert kinds(lay) == []  # exactly 0.5 from the hole's boundary
    lay = layout([FRAME, SQ], [(0, 0, (0.0, 0.0)), (1, 0, (1.5, down(1.5)))], spacing=0.5)
    assert kinds(lay) == [("spacing", 0, 1)]
    lay = layout([FRAME, shapely.box(0, 0, 2.5, 1)], [(0, 0, (0.0, 0.0)), (1, 0, (1.0, 1.0))])
    assert kinds(lay) == [("overlap", 0, 1)]  # sticks through the hole's wall


def test_sub_ulp_overlap_of_the_exact_sums():
    # B's left edge is at 1 - 2**-60 exactly (a double-double: -2**-60 + 1.0); its
    # float64 rounding touches A. The compiled overlay's rounded output is empty here
    # (its vertices round onto one line); the certificate sees the overlap.
    B = shapely.box(-(2.0**-60), 0, 1, 1)
    lay = layout([SQ, B], [(0, 0, (0.0, 0.0)), (1, 0, (1.0, 0.0))])
    assert kinds(lay) == [("overlap", 0, 1)]
    assert lay.polygons()[1].bounds[0] == 1.0  # the rounded polygons only touch
    C = shapely.box(2.0**-60, 0, 1, 1)
    assert kinds(layout([SQ, C], [(0, 0, (0.0, 0.0)), (1, 0, (1.0, 0.0))])) == []
    lay = layout([SQ, C], [(0, 0, (0.0, 0.0)), (1, 0, (1.0, 0.0))], spacing=2.0**-60)
    assert kinds(lay) == []  # spacing met exactly, below the float resolution at 1
    lay = layout([SQ, C], [(0, 0, (0.0, 0.0)), (1, 0, (1.0, 0.0))], spacing=up(2.0**-60))
    assert kinds(lay) == [("spacing", 0, 1)]


def test_free_rotations_touching():
    # a unit square turned 45 degrees (float coordinates), its left corner on a square's
    # right edge
    d = rotate_part(SQ, 45)
    xmin = d.bounds[0]
    lay = layout([SQ], [(0, 0, (0.0, 0.0)), (0, 45, (1.0 - xmin, 0.25))])
    assert got(lay) == oracle(lay) == set()
    lay = layout([SQ], [(0, 0, (0.0, 0.0)), (0, 45, (down(1.0 - xmin), 0.25))])
    assert got(lay) == oracle(lay) == {("overlap", 0, 1)}


@pytest.mark.parametrize("scale", [1e200, 1e-200, 2.0**-1000, 1e300])
def test_extreme_magnitudes(scale):
    sq = shapely.box(0, 0, scale, scale)
    lay = layout([sq], [(0, 0, (0.0, 0.0)), (0, 0, (scale, 0.0))],
                 [shapely.box(-scale, -scale, 4 * scale, 4 * scale)])  # fmt: skip
    assert kinds(lay) == []
    lay = layout([sq], [(0, 0, (0.0, 0.0)), (0, 0, (down(scale), 0.0))],
                 [shapely.box(-scale, -scale, 4 * scale, 4 * scale)], spacing=scale)  # fmt: skip
    assert kinds(lay) == [("overlap", 0, 1)]
    lay = layout([sq], [(0, 0, (0.0, 0.0)), (0, 0, (2 * scale, 0.0))],
                 [shapely.box(-scale, -scale, 4 * scale, 4 * scale)], spacing=scale)  # fmt: skip
    assert kinds(lay) == []
    lay = layout([sq], [(0, 0, (0.0, 0.0)), (0, 0, (down(2 * scale), 0.0))],
                 [shapely.box(-scale, -scale, 4 * scale, 4 * scale)], spacing=scale)  # fmt: skip
    assert kinds(lay) == [("spacing", 0, 1)]


# --------------------------------------------------------------------------------------
# hand cases: the sheet


def test_inside_the_sheet_touching_its_boundary():
    sheet = [shapely.box(0, 0, 3, 2)]
    assert kinds(layout([SQ], [(0, 0, (0.0, 0.0)), (0, 0, (2.0, 1.0))], sheet)) == []
    lay = layout([SQ], [(0, 0, (0.0, 0.0)), (0, 0, (up(2.0), 1.0))], sheet)
    assert kinds(lay) == [("container", 1, None)]
    lay = layout([SQ], [(0, 0, (5.0, 5.0))], sheet)
    assert kinds(lay) == [("container", 0, None)]  # far outside


def test_keep_out_zones():
    sheet = [shapely.Polygon([(0, 0), (6, 0), (6, 4), (0, 4)], [[(2, 1), (3, 1), (3, 2), (2, 2)]])]
    assert kinds(layout([SQ], [(0, 0, (1.0, 1.0)), (0, 0, (3.0, 2.0))], sheet)) == []
    lay = layout([SQ], [(0, 0, (up(1.0), 1.0))], sheet)
    assert kinds(lay) == [("container", 0, None)]
    big = shapely.box(0, 0, 3, 3)  # covers the keep-out zone entirely
    lay = layout([big], [(0, 0, (1.0, 0.5))], sheet)
    assert kinds(lay) == [("container", 0, None)]
    assert "passes inside it" in verify_layout(lay)[0].detail


def test_margin_met_exactly_and_missed_by_one_ulp():
    sheet = [shapely.Polygon([(0, 0), (6, 0), (6, 4), (0, 4)], [[(3, 1), (4, 1), (4, 2), (3, 2)]])]
    assert kinds(layout([SQ], [(0, 0, (0.5, 0.5))], sheet, margin=0.5)) == []
    assert kinds(layout([SQ], [(0, 0, (down(0.5), 0.5))], sheet, margin=0.5)) == [
        ("margin", 0, None)
    ]
    assert kinds(layout([SQ], [(0, 0, (1.5, 1.0))], sheet, margin=0.5)) == []  # from the hole
    assert kinds(layout([SQ], [(0, 0, (up(1.5), 1.0))], sheet, margin=0.5)) == [("margin", 0, None)]
    # outside the sheet: a container violation only
    assert kinds(layout([SQ], [(0, 0, (-0.5, 0.5))], sheet, margin=0.5)) == [("container", 0, None)]


def test_sheets_are_separate():
    sheets = [shapely.box(0, 0, 2, 2), shapely.box(0, 0, 2, 2)]
    lay = layout([SQ], [(0, 0, (0.0, 0.0), 0), (0, 0, (0.0, 0.0), 1)], sheets)
    assert kinds(lay) == []
    lay = layout([SQ], [(0, 0, (0.0, 0.0), 0), (0, 0, (0.5, 0.0), 1), (0, 0, (0.5, 0.5), 1)],
                 sheets)  # fmt: skip
    assert kinds(lay) == [("overlap", 1, 2)]


# --------------------------------------------------------------------------------------
# results and errors


def test_violation_and_layout_error():
    lay = layout([SQ], [(0, 0, (0.0, 0.0)), (0, 0, (0.5, 0.0))])
    (v,) = verify_layout(lay)
    assert isinstance(v, Violation) and v.kind in V.KINDS
    assert v.argument == "placements[0], placements[1]"
    with pytest.raises(LayoutError, match=r"^placements\[0\], placements\[1\]: overlap") as e:
        lay.verify()
    assert e.value.argument == "placements[0], placements[1]"
    assert isinstance(e.value, GeometryError)
    assert layout([SQ], [(0, 0, (0.0, 0.0))]).verify() is True


def test_a_minimal_layout_object_is_enough():
    from types import SimpleNamespace as NS

    lay = NS(parts=[SQ], sheets=[shapely.box(0, 0, 2, 1)], spacing=0, margin=0,
             placements=[NS(part=0, sheet=0, rotation=0, translation=(0.0, 0.0)),
                         NS(part=0, sheet=0, rotation=0, translation=(1.0, 0.0))])  # fmt: skip
    assert verify_layout(lay) == []
    lay.placements[1].translation = (F(1, 3), 0.0)
    with pytest.raises(GeometryError, match=r"placements\[1\]: translation"):
        verify_layout(lay)


def test_grid_of_esicup_parts_passes(tmp_path):
    from minkowski2d.nesting import read_esicup

    from .corpus import ESICUP

    inst = read_esicup(ESICUP / "shirts.json")
    parts = inst["parts"]
    places, x = [], 0.0
    for p, part in enumerate(parts):
        for _ in range(inst["quantities"][p]):
            b = part.bounds
            places.append((p, 0, (x - b[0], -b[1])))
            x += b[2] - b[0] + 1.0
    lay = layout(parts, places, [shapely.box(0, 0, x, 40)], spacing=1.0)
    assert kinds(lay) == []
    places[5] = (places[5][0], 0, (places[5][2][0] - 0.5, places[5][2][1]))
    lay = layout(parts, places, [shapely.box(0, 0, x, 40)], spacing=1.0)
    assert {k for k, *_ in kinds(lay)} == {"spacing"}


# --------------------------------------------------------------------------------------
# the filtered predicates against exact arithmetic


MAGNITUDES = [1.0, 1e3, 0.1, 2.0**-60, 1e-300, 1e200, 2.0**189, 2.0**195]


@st.composite
def near_collinear(draw):
    """Points on a line, rounded to float64, a translation added exactly (double-double
    sums): orientations near zero at every magnitude."""
    mag = draw(st.sampled_from(MAGNITUDES))
    c = st.floats(-4, 4, allow_nan=False)
    px, py, dx, dy = (draw(c) * mag for _ in range(4))
    ks = draw(st.lists(st.floats(-3, 3, allow_nan=False), min_size=3, max_size=6))
    pts = np.array([(px + k * dx, py + k * dy) for k in ks], np.float64)
    tm = draw(st.sampled_from([0.0, *MAGNITUDES]))
    t = (draw(c) * tm, draw(c) * tm)
    return pts, t


def _exact_pts(pts, t):
    return [(F(x) + F(t[0]), F(y) + F(t[1])) for x, y in pts.tolist()]


@settings(max_examples=300, deadline=None)
@given(near_collinear())
def test_filtered_orientation_is_exact(case):
    pts, t = case
    g = V._Geo([[pts]], [t], [])
    P = _exact_pts(pts, t)
    m = len(P)
    idx = np.array([(i, j, k) for i in range(m) for j in range(m) for k in range(m)]).T
    got = g.orient(idx[0], idx[1], idx[2])
    want = [O.orient(P[i], P[j], P[k]) for i, j, k in idx.T.tolist()]
    assert got.tolist() == want


@settings(max_examples=300, deadline=None)
@given(near_collinear(), st.integers(0, 2), st.sampled_from([-1, 0, 1]))
def test_filtered_point_segment_distance_is_exact(case, which, nudge):
    pts, t = case
    g = V._Geo([[pts]], [t], [])
    P = _exact_pts(pts, t)
    a, b, c = 0, 1, 2
    d2 = O._point_seg2(P[a], P[b], P[c])
    if which and d2 > 0:
        # the largest float s with s² <= d², or one ulp either side of it
        s = math.exp((math.log(d2.numerator) - math.log(d2.denominator)) / 2)
        while F(s) ** 2 > d2:
            s = down(s)
        while F(up(s)) ** 2 <= d2:
            s = up(s)
    else:
        s = float(np.abs(pts).max() + 1) * 0.5
    s = up(s) if nudge > 0 else down(s) if nudge < 0 else s
    if not (0 < s < math.inf):
        return
    got = g.point_seg(np.array([a]), np.array([b]), np.array([c]), F(s))
    assert bool(got[0]) == (d2 >= F(s) ** 2)
