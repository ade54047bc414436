"""Tests of :func:`minkowski2d.nest` (nesting/nester.py, problem.py, _core/nest.hpp).

Every layout is checked by the independent brute-force oracle of ``nesting_oracle.py``
(Fractions, trusting neither the NFPs nor the certificate), on the layout the nester
returns. Runs are bounded by iteration budgets, never by the clock.
"""

from __future__ import annotations

import math
from fractions import Fraction as F

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import minkowski2d as mk
from minkowski2d.errors import EmptyGeometryError, GeometryError, NonFiniteError, OptionError
from minkowski2d.nesting.nfp import rotate_part

from . import nesting_oracle as O
from .corpus import ESICUP


def oracle(lay) -> set:
    """The oracle's violations of a layout (empty: certified independently)."""
    polys = []
    for p in lay.placements:
        g = rotate_part(lay.parts[p.part], p.rotation)
        tx, ty = F(p.translation[0]), F(p.translation[1])
        rings = [g.exterior.coords, *[r.coords for r in g.interiors]]
        polys.append([[(F(x) + tx, F(y) + ty) for x, y in r[:-1]] for r in rings])
    sheets = [O.ex([s.exterior.coords, *[r.coords for r in s.interiors]]) for s in lay.sheets]
    return O.violations(polys, [p.sheet for p in lay.placements], sheets, F(lay.spacing),
                        F(lay.margin))  # fmt: skip


def run(parts, **kw):
    kw.setdefault("time_limit", None)
    kw.setdefault("iterations", 20)
    return mk.nest(parts, **kw)


L_PART = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]


def test_two_ls_interlock_exactly():
    lay = run([L_PART], quantities=[2], rotations=[0, 180], height=2, iterations=50)
    assert lay.length == 3 and lay.density == 1
    assert {p.rotation for p in lay.placements} == {0, 180}
    assert oracle(lay) == set()


def test_a_part_that_only_fits_in_a_hole_goes_there():
    frame = shapely.Polygon(
        [(0, 0), (10, 0), (10, 10), (0, 10)], [[(2, 2), (8, 2), (8, 8), (2, 8)]]
    )
    small = shapely.box(0, 0, 5, 5)
    lay = run([frame, small], sheets=[(10, 10)])
    assert lay.n_sheets == 1
    inner = lay.polygons()[1]
    assert shapely.box(2, 2, 8, 8).contains(inner)
    assert oracle(lay) == set()
    strip = run([frame, small], height=10)
    assert strip.length == 10 and oracle(strip) == set()


def test_several_sheets_are_used_when_needed():
    sq = shapely.box(0, 0, 6, 6)
    lay = run([sq], quantities=[5], sheets=[((10, 10), 6)])
    assert lay.n_sheets == 5 and lay.kinds == (0, 0, 0, 0, 0)
    assert sorted(p.sheet for p in lay.placements) == [0, 1, 2, 3, 4]
    assert oracle(lay) == set()
    # two kinds: the larger holds four, so two sheets
    lay = run([sq], quantities=[5], sheets=[(10, 10), ((12, 12), 2)], iterations=40)
    assert lay.n_sheets == 2 and oracle(lay) == set()


def test_the_last_sheet_is_emptied_when_the_parts_fit_on_fewer():
    tri = [(0, 0), (4, 0), (0, 4)]
    lay = run([tri], quantities=[8], rotations=[0, 90, 180, 270], sheets=[((8, 8), 3)],
              iterations=60)  # fmt: skip
    assert lay.n_sheets == 1 and oracle(lay) == set()


@pytest.mark.parametrize("spacing, margin", [(0.5, 0.0), (0.0, 0.75), (0.3, 0.4)])
def test_spacing_and_margin_are_kept(spacing, margin):
    parts = [shapely.box(0, 0, 3, 2), L_PART, [(0, 0), (3, 0), (1, 2)]]
    lay = run(parts, quantities=[2, 2, 2], rotations=[0, 90], sheets=[((10, 8), 3)],
              spacing=spacing, margin=margin)  # fmt: skip
    assert lay.spacing == spacing and lay.margin == margin
    assert lay.verify() and oracle(lay) == set()


def test_keep_out_zones_and_an_l_shaped_sheet():
    sheet = shapely.Polygon([(0, 0), (12, 0), (12, 6), (6, 6), (6, 12), (0, 12)],
                            [[(2, 2), (4, 2), (4, 4), (2, 4)]])  # fmt: skip
    lay = run([shapely.box(0, 0, 3, 3)], quantities=[6], sheets=[(sheet, 2)], margin=0.25)
    assert oracle(lay) == set()
    for g, p in zip(lay.polygons(), lay.placements, strict=True):
        assert not g.intersects(shapely.box(2, 2, 4, 4).buffer(0.2))
        assert shapely.Polygon(sheet.exterior).contains(g)
        assert p.sheet < lay.n_sheets


def test_fixed_parts_stay_and_the_rest_avoid_them():
    sq = shapely.box(0, 0, 4, 4)
    fixed = [mk.Placement(part=0, copy=0, sheet=0, rotation=0, translation=(3.0, 3.0))]
    lay = run([sq], quantities=[4], sheets=[((10, 10), 2)], fixed=fixed)
    pinned = [p for p in lay.placements if p.fixed]
    assert len(pinned) == 1 and pinned[0].translation == (3.0, 3.0)
    assert oracle(lay) == set()


def test_a_fixed_seed_and_budget_give_the_same_layout_also_with_threads():
    parts = [shapely.box(0, 0, 3, 2), L_PART, [(0, 0), (3, 0), (1, 2)]]
    a = run(parts, quantities=[3, 3, 3], rotations=[0, 90], height=5, seed=7, threads=2)
    b = run(parts, quantities=[3, 3, 3], rotations=[0, 90], height=5, seed=7, threads=2)
    assert a.placements == b.placements and a.length == b.length
    assert oracle(a) == set()


def test_warm_start_never_gets_worse():
    parts = [shapely.box(0, 0, 3, 2), L_PART]
    first = run(parts, quantities=[4, 4], rotations=[0, 90], height=5, iterations=5)
    again = run(parts, quantities=[4, 4], rotations=[0, 90], height=5, iterations=5,
                initial=first)  # fmt: skip
    assert again.length <= first.length and oracle(again) == set()


def test_progress_and_callback_see_each_improvement():
    seen, dens = [], []
    parts = [shapely.box(0, 0, 3, 2), L_PART]
    lay = run(parts, quantities=[5, 5], rotations=[0, 90], height=5, iterations=15,
              callback=seen.append, progress=dens.append)  # fmt: skip
    assert len(seen) == len(dens)
    assert all(isinstance(s, mk.Layout) for s in seen)
    assert all(d2 >= d1 for d1, d2 in zip(dens, dens[1:]))
    assert lay.density >= (dens[-1] if dens else 0) - 1e-12


@pytest.mark.parametrize("name", ["fu", "shapes0", "dighe2"])
def test_esicup_instances_give_certified_layouts(name):
    inst = mk.read_esicup(ESICUP / f"{name}.json")
    lay = run(inst, iterations=4)
    assert len(lay.placements) == sum(inst["quantities"])
    assert lay.strip_height == inst["strip"]["height"]
    assert lay.verify()
    area = sum(p.area * q for p, q in zip(inst["parts"], inst["quantities"], strict=True))
    assert math.isclose(lay.density, area / (lay.length * lay.strip_height))


@st.composite
def parts_with_holes(draw):
    n = draw(st.integers(1, 3))
    out = []
    for _ in range(n):
        w, h = draw(st.integers(2, 6)), draw(st.integers(2, 6))
        if draw(st.booleans()) and w >= 4 and h >= 4:
            out.append(
                shapely.Polygon(
                    [(0, 0), (w, 0), (w, h), (0, h)],
                    [[(1, 1), (w - 1, 1), (w - 1, h - 1), (1, h - 1)]],
                )
            )
        else:
            k = draw(st.integers(0, 2))
            pts = (
                [(0, 0), (w, 0), (w, h), (0, h)]
                if k == 0
                else (
                    [(0, 0), (w, 0), (0, h)]
                    if k == 1
                    else [(0, 0), (w, 0), (w, 1), (1, 1), (1, h), (0, h)]
                )
            )
            out.append(shapely.Polygon(pts))
    return out  # fmt: skip


@given(
    parts=parts_with_holes(),
    q=st.integers(1, 3),
    spacing=st.sampled_from([0, 0.25, 0.5]),
    margin=st.sampled_from([0, 0.5]),
    sheets=st.booleans(),
    seed=st.integers(0, 5),
)
@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
def test_random_problems_give_layouts_the_oracle_certifies(parts, q, spacing, margin, sheets,
                                                           seed):  # fmt: skip
    kw = dict(quantities=[q] * len(parts), rotations=[0, 90], spacing=spacing, margin=margin,
              seed=seed, iterations=6)  # fmt: skip
    if sheets:
        lay = run(parts, sheets=[((9, 9), 12)], **kw)
    else:
        lay = run(parts, height=9, **kw)
    assert len(lay.placements) == q * len(parts)
    assert oracle(lay) == set()


# ------------------------------------------------------------------------------------
# bad input


def test_bad_input_gets_a_specific_error_naming_the_part():
    big = shapely.box(0, 0, 20, 20)
    with pytest.raises(GeometryError, match=r"parts\[1\]") as e:
        run([shapely.box(0, 0, 1, 1), big], sheets=[(10, 10)])
    assert e.value.argument == "parts[1]"
    with pytest.raises(OptionError, match="spacing"):
        run([L_PART], height=3, spacing=-1)
    with pytest.raises(OptionError, match="parts"):
        run([], height=3)
    with pytest.raises(NonFiniteError):
        run([[(0, 0), (1, 0), (float("nan"), 1)]], height=3)
    with pytest.raises(EmptyGeometryError, match=r"parts\[0\]"):
        run([shapely.Polygon()], height=3)
    with pytest.raises(OptionError, match="height, sheets"):
        run([L_PART])
    with pytest.raises(OptionError, match="height, sheets"):
        run([L_PART], height=3, sheets=[(4, 4)])
    with pytest.raises(GeometryError, match=r"parts\[0\]"):
        run([L_PART], quantities=[3], sheets=[(2, 2)])
    with pytest.raises(OptionError, match="quantities"):
        run([L_PART], quantities=[1, 2], height=3)
    with pytest.raises(OptionError, match="time_limit"):
        mk.nest([L_PART], height=3, time_limit=None, iterations=None)
    with pytest.raises(OptionError, match="height"):
        run([L_PART], height=0)
    with pytest.raises(OptionError, match=r"sheets\[0\]"):
        run([L_PART], sheets=[(-1, 4)])


def test_the_grid_makes_differences_exact():
    from minkowski2d.nesting.problem import grid_for

    g = grid_for(1000.0)
    assert math.frexp(g)[0] == 0.5  # a power of two
    x = np.array([123.456, 987.654]) // g * g
    assert F(float(x[1] - x[0])) == F(float(x[1])) - F(float(x[0]))
