"""The compiled core's predicates (minkowski2d._core._ext) against exact rational
arithmetic: random, degenerate and extreme inputs.

Under CI (env var CI set) hypothesis runs derandomized: tests/conftest.py loads the
"ci" profile, and every @settings here inherits from it.
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from minkowski2d._core import _ext

F = Fraction
TINY = 5e-324  # the smallest subnormal
MAX = 1.7976931348623157e308
INT_MAX = (1 << 62) - 1


def exact_sign(a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y) -> int:
    d = (F(a1x) - F(a0x)) * (F(b1y) - F(b0y)) - (F(a1y) - F(a0y)) * (F(b1x) - F(b0x))
    return (d > 0) - (d < 0)


def test_selftest_no_fma_contraction():
    """two_prod is error-free in the built module (no FMA contraction, no fast-math)."""
    assert _ext.selftest() is True


# ---------------------------------------------------------------------------- strategies

# finite doubles over every magnitude, subnormals included
any_float = st.floats(allow_nan=False, allow_infinity=False, width=64)
# values that stress the filter and the exact fallback
special = st.sampled_from(
    [0.0, -0.0, TINY, -TINY, 2 * TINY, 1e-310, 2.2250738585072014e-308, 1e-300, 2.0**-1000,
     2.0**-537, 1.0, 3.0, 1e300, -1e300, 2.0**1000, 1.7e308, -1.7e308, MAX, -MAX]
)  # fmt: skip
coord = st.one_of(any_float, special, st.floats(-10.0, 10.0))


@st.composite
def scaled(draw):
    """Eight small-grid coordinates scaled by 2**e (exactly), e across the whole range."""
    e = draw(st.integers(-1074, 1000))
    ints = draw(st.lists(st.integers(-8, 8), min_size=8, max_size=8))
    return [math.ldexp(v, e) for v in ints]


@st.composite
def mixed(draw):
    """Every coordinate at its own magnitude: tiny, huge and ordinary in one call."""
    out = []
    for _ in range(8):
        m = draw(st.floats(-2.0, 2.0))
        e = draw(st.sampled_from([-1074, -1060, -1000, -600, -300, 0, 300, 600, 1000, 1022]))
        out.append(math.ldexp(m, e) if math.isfinite(math.ldexp(m, e)) else m)
    return out


ALL_EXPONENTS = [-1074, -1070, -1000, -540, -300, -20, 0, 20, 300, 900, 1000]


@st.composite
def collinear(draw, exponents=ALL_EXPONENTS):
    """a0, a1 and b0 = a0, b1 on one line (exactly, from a small-integer direction scaled by
    a power of two), then maybe one coordinate of a1 or b1 nudged by one ulp."""
    e = draw(st.sampled_from(exponents))
    px, py = (math.ldexp(draw(st.integers(-(2**20), 2**20)), e) for _ in range(2))
    dx, dy = draw(st.integers(-50, 50)), draw(st.integers(-50, 50))
    s, t = draw(st.integers(1, 40)), draw(st.integers(-40, 40))
    qx, qy = px + math.ldexp(dx * s, e), py + math.ldexp(dy * s, e)
    rx, ry = px + math.ldexp(dx * t, e), py + math.ldexp(dy * t, e)
    k = draw(st.integers(0, 4))
    if k == 1:
        rx = math.nextafter(rx, math.inf)
    elif k == 2:
        ry = math.nextafter(ry, -math.inf)
    elif k == 3:
        qx = math.nextafter(qx, -math.inf)
    elif k == 4:
        qy = math.nextafter(qy, math.inf)
    vals = [px, py, qx, qy, px, py, rx, ry]
    return vals if all(math.isfinite(v) for v in vals) else [0.0] * 8


@st.composite
def near_collinear_random(draw):
    """Three random points on a float line p + t d (rounded), then one ulp off."""
    p = (draw(st.floats(-1e6, 1e6)), draw(st.floats(-1e6, 1e6)))
    d = (draw(st.floats(-10, 10)), draw(st.floats(-10, 10)))
    s, t = draw(st.floats(0.1, 3.0)), draw(st.floats(-3.0, 3.0))
    e = draw(st.integers(-1000, 1000))
    q = (p[0] + d[0] * s, p[1] + d[1] * s)
    r = (p[0] + d[0] * t, p[1] + d[1] * t)
    r = (math.nextafter(r[0], math.inf), r[1]) if draw(st.booleans()) else r
    vals = [math.ldexp(v, e) for v in (*p, *q, *p, *r)]
    return vals if all(math.isfinite(v) for v in vals) else [0.0] * 8


eight = st.lists(coord, min_size=8, max_size=8)
float_inputs = st.one_of(eight, scaled(), mixed(), collinear(), near_collinear_random())


# ---------------------------------------------------------------------------- doubles


@settings(max_examples=1500, deadline=None)
@given(float_inputs)
def test_cross_sign_f_exact(v):
    expect = exact_sign(*v)
    assert _ext.cross_sign_f(*v) == expect
    assert _ext.cross_sign_exact_f(*v) == expect


@pytest.mark.parametrize(
    "v",
    [
        # 2**27-grid: the float cross product rounds to 0, the sign is -1
        [0.0, 0.0, 2.0**27 + 1, 2.0**27, 0.0, 0.0, 2.0**27, 2.0**27 - 1],
        [0.0, 0.0, TINY, 0.0, 0.0, 0.0, 0.0, TINY],  # products far below the subnormals
        [0.0, 0.0, TINY, TINY, 0.0, 0.0, 2 * TINY, 2 * TINY],  # collinear, subnormal
        [0.0, 0.0, TINY, TINY, 0.0, 0.0, 2 * TINY, 3 * TINY],
        [-MAX, -MAX, MAX, MAX, -MAX, MAX, MAX, -MAX],  # the differences overflow
        [-MAX, -MAX, MAX, MAX, -MAX, -MAX, MAX, math.nextafter(MAX, 0.0)],
        [1e300, 1e-300, -1e300, TINY, 1.7e308, 5e-324, 1e-300, -1.7e308],
        [1.0, 1.0, 1.0 + 2.0**-52, 1.0 + 2.0**-52, 1.0, 1.0, 2.0, math.nextafter(2.0, 3.0)],
    ],
)
def test_cross_sign_f_hand_picked(v):
    expect = exact_sign(*v)
    assert _ext.cross_sign_f(*v) == expect
    assert _ext.cross_sign_exact_f(*v) == expect


def test_cross_sign_f_every_power_of_two_scale():
    """One near-degenerate configuration at every binary exponent the format has."""
    base = [3.0, 1.0, 2.0**27 + 4, 2.0**27 + 1, 3.0, 1.0, 2.0**27 + 1, 2.0**27 - 2]
    expect = exact_sign(*base)
    assert expect != 0
    for e in range(-1074, 996):  # 2**27 * 2**996 is still finite
        v = [math.ldexp(x, e) for x in base]
        if all(math.ldexp(x, -e) == y for x, y in zip(v, base)):  # scaling was exact
            assert _ext.cross_sign_f(*v) == expect, e
        assert _ext.cross_sign_f(*v) == exact_sign(*v), e


# ---------------------------------------------------------------------------- int64

big_int = st.integers(-INT_MAX, INT_MAX)
int_coord = st.one_of(
    big_int,
    st.integers(-10, 10),
    st.sampled_from([INT_MAX, -INT_MAX, INT_MAX - 1, 1 << 61, -(1 << 61), 0]),
)


@st.composite
def int_collinear(draw):
    p = (draw(big_int) // 4, draw(big_int) // 4)
    d = (draw(st.integers(-(2**40), 2**40)), draw(st.integers(-(2**40), 2**40)))
    s, t = draw(st.integers(-(2**20), 2**20)), draw(st.integers(-(2**20), 2**20))
    q = (p[0] + d[0] * s, p[1] + d[1] * s)
    r = (p[0] + d[0] * t + draw(st.integers(-1, 1)), p[1] + d[1] * t)
    vals = [*p, *q, *p, *r]
    return vals if all(abs(v) <= INT_MAX for v in vals) else [0] * 8


@settings(max_examples=800, deadline=None)
@given(st.one_of(st.lists(int_coord, min_size=8, max_size=8), int_collinear()))
def test_cross_sign_i_exact(v):
    a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y = v
    d = (a1x - a0x) * (b1y - b0y) - (a1y - a0y) * (b1x - b0x)
    assert _ext.cross_sign_i(*v) == (d > 0) - (d < 0)


def test_cross_sign_i_extremes():
    M = INT_MAX
    assert _ext.cross_sign_i(-M, -M, M, M, -M, M, M, -M) == -1
    assert _ext.cross_sign_i(-M, -M, M, M, -M, -M, M, M) == 0
    assert _ext.cross_sign_i(-M, -M, M, M, -M, -M, M, M - 1) == -1
    assert _ext.cross_sign_i(M, -M, -M, M, M, -M, -M, M - 1) == 1


# ---------------------------------------------------------------------------- expansion

in_range = st.one_of(
    st.just(0.0),
    st.builds(
        lambda m, e: math.ldexp(m, e),
        st.floats(-2.0, 2.0).filter(lambda m: abs(m) >= 1.0 or m == 0.0),
        st.integers(-399, 398),
    ),
    st.floats(-1e6, 1e6),
).filter(lambda x: x == 0.0 or 2.0**-400 <= abs(x) <= 2.0**400)


@settings(max_examples=600, deadline=None)
@given(
    st.one_of(
        st.lists(in_range, min_size=8, max_size=8),
        collinear([-300, -20, 0, 20, 300]).filter(
            lambda v: all(x == 0.0 or 2.0**-400 <= abs(x) <= 2.0**400 for x in v)
        ),
    )
)
def test_cross_expansion_is_exact_in_range(v):
    e = _ext.cross_expansion(*v)
    assert sum(F(c) for c in e) == (F(v[2]) - F(v[0])) * (F(v[7]) - F(v[5])) - (
        F(v[3]) - F(v[1])
    ) * (F(v[6]) - F(v[4]))
    # nonoverlapping, smallest first: the last component carries the sign
    assert (e[-1] > 0) - (e[-1] < 0) == exact_sign(*v)
