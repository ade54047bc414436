"""minkowski2d.predicates and the compiled kernels' predicate: exact signs."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from minkowski2d import _kernels
from minkowski2d.predicates import cross_sign, orient, orient_array

F = Fraction
finite = st.floats(-1e6, 1e6, allow_nan=False, allow_infinity=False)
pt = st.tuples(finite, finite)


def in_kernel_range(*pts):
    """The compiled predicate is exact for nonzero |x| in [2**-400, 2**400] (the wrappers
    send anything else to exact Python arithmetic)."""
    return all(v == 0 or 2.0**-400 <= abs(v) <= 2.0**400 for p in pts for v in p)


def exact_cross(a0, a1, b0, b1):
    d = (F(a1[0]) - F(a0[0])) * (F(b1[1]) - F(b0[1])) - (F(a1[1]) - F(a0[1])) * (
        F(b1[0]) - F(b0[0])
    )
    return (d > 0) - (d < 0)


@st.composite
def near_collinear(draw):
    """Three points on (or one ulp off) a line: the float test alone cannot decide."""
    p = draw(pt)
    d = draw(st.tuples(st.floats(-10, 10), st.floats(-10, 10)))
    s = draw(st.floats(0.1, 3.0))
    t = draw(st.floats(-3.0, 3.0))
    q = (p[0] + d[0] * s, p[1] + d[1] * s)
    r = (p[0] + d[0] * t, p[1] + d[1] * t)
    k = draw(st.integers(0, 2))
    r = (
        np.nextafter(r[0], np.inf) if k == 1 else r[0],
        np.nextafter(r[1], -np.inf) if k == 2 else r[1],
    )
    return p, q, (float(r[0]), float(r[1]))


@settings(max_examples=400, deadline=None)
@given(st.one_of(near_collinear(), st.tuples(pt, pt, pt)))
def test_orient_exact_python_and_kernel(tri):
    p, q, r = tri
    expect = exact_cross(p, q, p, r)
    assert orient(p, q, r) == expect
    if in_kernel_range(p, q, r):
        assert _kernels.cross_sign(p[0], p[1], q[0], q[1], p[0], p[1], r[0], r[1]) == expect
    assert orient_array([p], [q], [r]).tolist() == [expect]


@settings(max_examples=300, deadline=None)
@given(pt, pt, pt, pt, st.integers(-1000, 1000))
def test_cross_sign_two_vectors(a0, a1, b0, b1, e):
    scale = 2.0 ** (e % 700 - 350)  # exponents across the kernels' exact range
    a0, a1, b0, b1 = [(x * scale, y * scale) for x, y in (a0, a1, b0, b1)]
    expect = exact_cross(a0, a1, b0, b1)
    assert cross_sign(a0, a1, b0, b1) == expect
    if in_kernel_range(a0, a1, b0, b1):
        assert _kernels.cross_sign(*a0, *a1, *b0, *b1) == expect


def test_the_issue_example():
    u = (2.0**27 + 1, 2.0**27)
    v = (2.0**27, 2.0**27 - 1)
    z = (0.0, 0.0)
    assert u[0] * v[1] - u[1] * v[0] == 0.0
    assert cross_sign(z, u, z, v) == -1 == exact_cross(z, u, z, v)
    assert _kernels.cross_sign(0.0, 0.0, *u, 0.0, 0.0, *v) == -1


def test_integers_and_fractions_exact():
    assert orient((0, 0), (10**30, 1), (2 * 10**30, 2)) == 0
    assert orient((0, 0), (10**30, 1), (2 * 10**30, 3)) == 1
    assert orient((F(1, 3), 0), (F(2, 3), 0), (1, 0)) == 0
    assert orient_array([[0, 0]], [[1 << 40, 1]], [[1 << 41, 2]]).tolist() == [0]
    assert orient_array([[0, 0]], [[1 << 60, 1]], [[1 << 61, 3]]).tolist() == [1]


@settings(max_examples=300, deadline=None)
@given(near_collinear(), st.integers(-1074, -500))
def test_python_predicate_exact_where_products_underflow(tri, e):
    """Coordinates so small that the cross-product terms are subnormal: the relative
    float bound no longer holds, and the Python path must still be exact."""
    p, q, r = ((x * 2.0**e, y * 2.0**e) for x, y in tri)
    assert orient(p, q, r) == exact_cross(p, q, p, r)


def test_tiny_polygon_sums_exact_below_the_kernel_range():
    import minkowski2d as mk

    from . import oracle

    for e in (-540, -560, -600, -1000):
        s = 2.0**e
        a = [(0.0, 0.0), (3 * s, s), (s, 3 * s)]
        b = [(0.0, 0.0), (3 * s, s + 2.0**-1074), (-s, s)]
        got = mk.minkowski_sum(a, b)
        assert got.tolist() == [list(v) for v in oracle.rounded(oracle.minkowski_sum(a, b))]
