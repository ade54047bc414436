"""Tests of the resolver of offset curves with a few crossings (``_core/offset_resolve.hpp``):
its region must be the overlay's, vertex for vertex (the same rounded crossings, the same
ring starts and order, holes after their exterior), and lie on its stated side of the true
set within the tolerance (``check_offset``, the exact oracle of ``test_offset``). The core
is asked twice, with the resolver and without it (every curve with crossings then goes to
the overlay); the cases are ESICUP parts whose pruned curves keep a few loops, outlines
whose shrinks split or whose grows close a hole (several exteriors, holes), crossings on
one segment, and hypothesis outlines.
"""

from __future__ import annotations

import math
from collections import Counter

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from minkowski2d import datasets
from minkowski2d._engine import core
from minkowski2d.offset import APPROX, curves

from .test_offset import check_offset
from .test_offset_prune_core import NAMED, wiggly


def _core(g, d, eps, approx, resolve):
    inp = curves._read(g, "polygon")
    go = np.array([0, len(inp.ring_off) - 1], np.int64)
    return core.offset_rings(
        inp.xy, inp.ring_off, inp.hole, go, np.array([int(inp.unite)], np.int64),
        np.array([inp.delta]), d, eps, curves.DEFAULT_TOLERANCE, approx == "outer",
        core.OFFSET_ROUND, 2.0, False, 1, resolve,
    )  # fmt: skip


def both(g, d, eps, approx="outer"):
    """The path the core took with the resolver; the results with and without it must
    be identical (bit for bit)."""
    a = _core(g, d, eps, approx, True)
    b = _core(g, d, eps, approx, False)
    for x, y in zip(a[:4], b[:4]):
        assert x.dtype == y.dtype and x.shape == y.shape and np.array_equal(x, y), (d, approx)
    assert np.array_equal(a[4][:, :4], b[4][:, :4])
    return int(a[4][0, 4])


def dumbbell(neck=0.5, k=24):
    """Two round blobs (k edges each) joined by a neck: a shrink by more than neck / 2
    splits it in two."""
    t = np.linspace(0.3, 2 * math.pi - 0.3, k)
    left = np.c_[-3 + 2 * np.cos(t[::-1] + math.pi), 2 * np.sin(t[::-1] + math.pi)]
    right = np.c_[3 + 2 * np.cos(t[::-1]), 2 * np.sin(t[::-1])]
    ring = np.r_[left[left[:, 1] <= 0][::-1], right, left[left[:, 1] > 0][::-1]]
    g = shapely.Polygon(np.round(ring, 9))
    return g if g.is_valid else shapely.make_valid(g).geoms[0]


def c_shape(gap=0.4):
    """A thick C whose gap closes when grown by more than gap / 2: a hole appears."""
    return shapely.Polygon(
        [(0, 0), (6, 0), (6, 6), (0, 6), (0, 3 + gap / 2), (1.5, 3 + gap / 2), (1.5, 4.5),
         (4.5, 4.5), (4.5, 1.5), (1.5, 1.5), (1.5, 3 - gap / 2), (0, 3 - gap / 2)]
    )  # fmt: skip


ESICUP_CASES = (
    [("gardeyn8", k) for k in (2, 14, 15, 50, 52, 67, 100, 105)]
    + [("gardeyn6", k) for k in (47, 65, 81, 82)]
    + [("gardeyn3", 63), ("gardeyn2", 18), ("gardeyn7", 14), ("gardeyn9", 33)]
)


@pytest.mark.parametrize("name, k", ESICUP_CASES)
@pytest.mark.parametrize("approx", ["outer", "inner"])
def test_esicup_parts_as_the_overlay(name, k, approx):
    """Parts whose shrink by 3 % of the diagonal keeps loops no certificate covers."""
    g = datasets.esicup(name)["parts"][k]
    x0, y0, x1, y1 = g.bounds
    d = -0.03 * math.hypot(x1 - x0, y1 - y0)
    path = both(g, d, 1e-3 * abs(d), approx)
    assert path in (core.OFFSET_RESOLVED, core.OFFSET_DIRECT, core.OFFSET_OVERLAID)
    if k in (14, 100) and name == "gardeyn8":
        assert path == core.OFFSET_RESOLVED
        check_offset(g, d, 1e-3 * abs(d), approx)


@pytest.mark.parametrize("neck", [0.3, 0.5, 0.9])
@pytest.mark.parametrize("approx", ["outer", "inner"])
def test_split_and_closed(neck, approx):
    """A shrink that splits a dumbbell (two exteriors); a grow that closes a C's gap (a
    hole inside the exterior)."""
    g = dumbbell(neck)
    for d in (-0.2, -0.35, -0.6):
        both(g, d, 1e-3 * abs(d), approx)
        check_offset(g, d, 1e-3 * abs(d), approx)
    c = c_shape(neck)
    for d in (0.1, 0.3, 0.6):
        both(c, d, 1e-2 * d, approx)
        out = check_offset(c, d, 1e-2 * d, approx)
        assert len(out.interiors) == (1 if d > neck / 2 else 0)


def test_paths_taken():
    """The named outlines and the cases above do reach the resolver (and the overlay
    for what it refuses)."""
    seen = Counter()
    for g in list(NAMED.values()) + [dumbbell(0.5), c_shape(0.4)]:
        for d in (0.3, 0.6, -0.2, -0.4):
            for approx in ("outer", "inner"):
                seen[both(g, d, 1e-2 * abs(d), approx)] += 1
    assert seen[core.OFFSET_RESOLVED] >= 5, seen


def test_crossings_on_one_segment():
    """A long straight edge whose moved copy is crossed by the loops of several teeth:
    the crossings along one segment are ordered exactly."""
    teeth = []
    for i in range(6):
        x = 1 + 1.3 * i
        teeth += [(x, 1), (x + 0.1, 1.6), (x + 0.2, 1)]
    g = shapely.Polygon([(0, 0), (9, 0), (9, 1)] + teeth[::-1] + [(0, 1)])
    assert g.is_valid
    for d in (-0.3, -0.45, 0.2, 0.4):
        for approx in ("outer", "inner"):
            both(g, d, 1e-3 * abs(d), approx)
            check_offset(g, d, 1e-3 * abs(d), approx)


@st.composite
def split_or_closed(draw):
    """A dumbbell (its shrinks split) or a C (its grows close a hole), scaled."""
    if draw(st.booleans()):
        g = dumbbell(draw(st.floats(0.2, 1.5)), draw(st.integers(6, 40)))
    else:
        g = c_shape(draw(st.floats(0.05, 1.0)))
    s = draw(st.sampled_from([1.0, 0.125, 64.0]))
    return shapely.affinity.scale(g, s, s, origin=(0, 0)), s


@st.composite
def offset_cases(draw):
    """(polygon, distance, tolerance, approx): an outline that loops or splits, a radius
    between 0.02 and 2.5 (times its scale), either sign and side."""
    g, s = draw(st.one_of(wiggly(), split_or_closed()))
    d = draw(st.floats(0.02, 2.5)) * s * draw(st.sampled_from([1, -1]))
    return g, d, draw(st.sampled_from([1e-2, 1e-3])) * abs(d), draw(st.sampled_from(APPROX))


@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case=offset_cases())
def test_random_as_the_overlay(case):
    both(*case)
    check_offset(*case)
