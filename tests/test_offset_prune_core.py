"""Tests of the pruning of swallowed loops (``_core/offset_prune.hpp``) against the exact
oracle of ``test_offset``: outlines whose offset curves run in loops inside the result
(concave corners rounded tighter than the radius, keyholes and slits that close, combs of
close convex teeth, notches and bumps along an edge), grown and shrunk, both sides, tiny
and large radii, holes, magnitudes far from 1. Every result must lie on its stated side of
the true set, within the tolerance, exactly (``check_offset``), and equal the result of
the same polygon given another way (a list of pairs goes through the reader, a shapely
polygon through the core's own reading and checking).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import minkowski2d as mk

from .test_offset import check_offset


def arc(cx, cy, rad, a0, a1, k):
    """k + 1 points on a circle from angle a0 to a1 (rounded to 1e-9: exact floats)."""
    t = np.linspace(a0, a1, k + 1)
    return [(round(cx + rad * math.cos(a), 9), round(cy + rad * math.sin(a), 9)) for a in t]


def rounded_notch():
    """A square with a concave quarter-circle corner of 30 tiny edges (radius 2)."""
    return (
        [(0, 0), (10, 0), (10, 8)]
        + arc(10, 10, 2, -math.pi / 2, -math.pi, 30)[1:]
        + [
            (8, 10),
            (0, 10),
        ]
    )


def keyhole_polygon():
    """A block with a round cavity (radius 1.2, 40 edges) behind a neck 0.4 wide."""
    t0 = math.asin(0.2 / 1.2)
    cave = arc(5, 6, 1.2, math.pi / 2 - t0, math.pi / 2 + t0 - 2 * math.pi, 40)  # clockwise
    # from the neck's right side at the top, around the cave, to its left side
    ring = [(0, 0), (10, 0), (10, 10), (5.2, 10)] + cave + [(4.8, 10), (0, 10)]
    return shapely.Polygon(ring)


def slit():
    """A strip with a slit 0.3 wide ending in a round bottom of 12 edges."""
    bottom = arc(5, 1, 0.15, 0, -math.pi, 12)
    return shapely.Polygon([(0, 0), (10, 0), (10, 3), (5.15, 3)] + bottom + [(4.85, 3), (0, 3)])


def comb(n=40, width=0.1, gap=0.15, depth=2.0):
    """n thin teeth closer than the radius."""
    pts = [(0.0, 0.0)]
    x = 0.0
    for _ in range(n):
        pts += [(x, depth), (x + width, depth)]
        x += width + gap
        pts += [(x - gap, 0.5), (x, 0.5)]
    pts[-2:] = []
    pts += [(x - gap, -1.0), (0.0, -1.0)]
    return shapely.Polygon(pts)


def bumpy(seed, n=80, amp=0.4):
    """An outline of n vertices with random radial bumps and notches."""
    rng = np.random.default_rng(seed)
    a = np.linspace(0, 2 * math.pi, n, endpoint=False)
    rad = 5 + amp * rng.uniform(-1, 1, n)
    return shapely.Polygon(np.round(np.c_[rad * np.cos(a), rad * np.sin(a)], 6))


def finger(w=0.8, length=6.0, k=40):
    """A block with a finger w wide and `length` long, each side of k edges, a round tip."""
    right = [(4 + w / 2, 2 + length * i / k) for i in range(k + 1)]
    left = [(4 - w / 2, 2 + length * i / k) for i in range(k, -1, -1)]
    tip = arc(4, 2 + length, w / 2, 0, math.pi, 12)[1:-1]
    return shapely.Polygon([(0, 0), (8, 0), (8, 2)] + right + tip + left + [(0, 2)])


def rounded_slot(w=1.0, depth=2.0, rc=0.2, k=10):
    """A block with a slot w wide and `depth` deep, its corners rounded (radius rc, k
    edges each)."""
    x0, x1 = 4 - w / 2, 4 + w / 2
    pts = [(0, 0), (8, 0), (8, 4), (x1 + rc, 4)]
    pts += arc(x1 + rc, 4 - rc, rc, math.pi / 2, math.pi, k)[1:]
    pts += arc(x1 - rc, 4 - depth + rc, rc, 0, -math.pi / 2, k)
    pts += arc(x0 + rc, 4 - depth + rc, rc, -math.pi / 2, -math.pi, k)[1:]
    pts += arc(x0 - rc, 4 - rc, rc, 0, math.pi / 2, k)[1:]
    return shapely.Polygon(pts + [(0, 4)])


def band(r0=3.0, w=0.6, k=60):
    """A half ring w wide, both sides of k edges."""
    return shapely.Polygon(
        arc(0, 0, r0 + w / 2, 0, math.pi, k) + arc(0, 0, r0 - w / 2, math.pi, 0, k)
    )


NAMED = {
    "rounded_notch": shapely.Polygon(rounded_notch()),
    "keyhole": keyhole_polygon(),
    "slit": slit(),
    "comb": comb(),
    "bumpy": bumpy(1),
    "holed_bumpy": shapely.Polygon(
        bumpy(2).exterior.coords, [np.asarray(bumpy(3, 60, 0.3).exterior.coords)[::-1] * 0.5]
    ),
    "finger": finger(),
    "rounded_slot": rounded_slot(),
    "band": band(),
}


@pytest.mark.parametrize("name", sorted(NAMED))
@pytest.mark.parametrize("distance", [0.05, 0.6, 2.5, -0.05, -0.3, -1.0])
@pytest.mark.parametrize("approx", ["outer", "inner"])
def test_named_swallowtails_one_sided(name, distance, approx):
    g = NAMED[name]
    assert g.is_valid, name
    eps = 1e-2 * abs(distance)
    out = check_offset(g, distance, eps, approx)
    # the same polygon through the reader (a list of pairs) gives the same result
    if not len(g.interiors):
        ring = [tuple(p) for p in np.asarray(g.exterior.coords)[:-1]]
        assert out.equals(mk.offset(ring, distance, tolerance=eps, approx=approx))


@pytest.mark.parametrize(
    "name, distance",
    [("finger", -0.42), ("finger", -0.399), ("finger", -0.401), ("rounded_slot", 0.6),
     ("rounded_slot", 0.501), ("rounded_slot", 0.499), ("band", -0.301), ("band", -0.299),
     ("band", 0.6)],
)  # fmt: skip
@pytest.mark.parametrize("approx", ["outer", "inner"])
def test_strips_one_sided(name, distance, approx):
    """A strip narrower than 2r (a finger or band shrunk, a slot grown) is a loop whose
    piece only the zipper certifies (rungs with middles); just wider, it must stay."""
    check_offset(NAMED[name], distance, 1e-3 * abs(distance), approx)


@pytest.mark.parametrize("half", [0.5 - 1e-9, 0.5, 0.5 + 1e-9])
@pytest.mark.parametrize("approx", ["outer", "inner"])
def test_narrow_shrinks(half, approx):
    """A set whose box is narrower than 2r shrinks to nothing (decided from the box,
    before any curve); at 2r or just wider the offset runs as usual."""
    g = shapely.Polygon([(0, 0), (7, 0), (7, 0.4), (3, 0.4), (3, 1), (0, 1)])
    out = check_offset(g, -half, 1e-3 * half, approx)
    if half > 0.5:
        assert out.is_empty


@pytest.mark.parametrize("scale", [2.0**-500, 2.0**500])
@pytest.mark.parametrize("name", ["rounded_notch", "keyhole", "comb"])
def test_swallowtails_far_from_one(scale, name):
    g = shapely.affinity.scale(NAMED[name], scale, scale, origin=(0, 0))
    for d in (0.6 * scale, -0.3 * scale):
        out = mk.offset(g, d, tolerance=1e-2 * abs(d))
        ref = mk.offset(NAMED[name], d / scale, tolerance=1e-2 * abs(d) / scale)
        back = shapely.affinity.scale(out, 1 / scale, 1 / scale, origin=(0, 0))
        assert back.equals_exact(ref, 0), (name, scale, d)  # powers of two: exact


@st.composite
def wiggly(draw):
    """Outlines that make offset curves loop: bumps and notches of random size along a
    circle, a comb, a rounded concave corner, or a keyhole, scaled."""
    kind = draw(st.sampled_from(["bumpy", "comb", "notch", "keyhole", "finger", "slot"]))
    if kind == "bumpy":
        g = bumpy(draw(st.integers(0, 10**6)), draw(st.integers(12, 90)),
                  draw(st.floats(0.05, 1.5)))  # fmt: skip
    elif kind == "comb":
        g = comb(draw(st.integers(2, 12)), draw(st.floats(0.05, 0.5)), draw(st.floats(0.05, 0.5)))
    elif kind == "notch":
        g = NAMED["rounded_notch"]
    elif kind == "finger":
        g = finger(draw(st.floats(0.1, 2.0)), draw(st.floats(0.5, 8.0)), draw(st.integers(1, 60)))
    elif kind == "slot":
        g = rounded_slot(draw(st.floats(0.6, 2.0)), draw(st.floats(0.5, 3.5)),
                         draw(st.floats(0.01, 0.25)), draw(st.integers(1, 16)))  # fmt: skip
    else:
        g = NAMED["keyhole"]
    if not g.is_valid:
        g = NAMED["slit"]
    s = draw(st.sampled_from([1.0, 0.125, 64.0]))
    return shapely.affinity.scale(g, s, s, origin=(0, 0)), s


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    gs=wiggly(),
    r=st.floats(0.01, 4),
    grow=st.booleans(),
    rel=st.sampled_from([1e-2, 1e-3]),
    approx=st.sampled_from(["outer", "inner"]),
)
def test_random_swallowtails_one_sided(gs, r, grow, rel, approx):
    g, s = gs
    d = (r if grow else -r) * s
    check_offset(g, d, rel * abs(d), approx)


def test_batch_equals_single():
    geoms = list(NAMED.values())
    for d in (0.6, -0.3):
        many = mk.offset_many(geoms, d, tolerance=1e-2 * abs(d), threads=2)
        for g, o in zip(geoms, many):
            assert o.equals_exact(mk.offset(g, d, tolerance=1e-2 * abs(d)), 0)
