"""minkowski2d.predicates and the compiled core's predicate: exact signs."""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from minkowski2d._core import _ext
from minkowski2d.errors import GeometryError, NonFiniteError
from minkowski2d.predicates import cross_sign, orient, orient_array

F = Fraction
finite = st.floats(-1e6, 1e6, allow_nan=False, allow_infinity=False)
pt = st.tuples(finite, finite)


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
def test_orient_exact_python_and_core(tri):
    p, q, r = tri
    expect = exact_cross(p, q, p, r)
    assert orient(p, q, r) == expect
    assert _ext.cross_sign_f(p[0], p[1], q[0], q[1], p[0], p[1], r[0], r[1]) == expect
    assert orient_array([p], [q], [r]).tolist() == [expect]


@settings(max_examples=300, deadline=None)
@given(pt, pt, pt, pt, st.integers(-1000, 1000))
def test_cross_sign_two_vectors(a0, a1, b0, b1, e):
    scale = 2.0 ** (e % 2000 - 1050)  # exponents across the whole float range
    a0, a1, b0, b1 = [(x * scale, y * scale) for x, y in (a0, a1, b0, b1)]
    expect = exact_cross(a0, a1, b0, b1)
    assert cross_sign(a0, a1, b0, b1) == expect
    assert _ext.cross_sign_f(*a0, *a1, *b0, *b1) == expect


def test_the_issue_example():
    u = (2.0**27 + 1, 2.0**27)
    v = (2.0**27, 2.0**27 - 1)
    z = (0.0, 0.0)
    assert u[0] * v[1] - u[1] * v[0] == 0.0
    assert cross_sign(z, u, z, v) == -1 == exact_cross(z, u, z, v)
    assert _ext.cross_sign_f(0.0, 0.0, *u, 0.0, 0.0, *v) == -1


def test_integers_and_fractions_exact():
    assert orient((0, 0), (10**30, 1), (2 * 10**30, 2)) == 0
    assert orient((0, 0), (10**30, 1), (2 * 10**30, 3)) == 1
    assert orient((F(1, 3), 0), (F(2, 3), 0), (1, 0)) == 0
    assert orient_array([[0, 0]], [[1 << 40, 1]], [[1 << 41, 2]]).tolist() == [0]
    assert orient_array([[0, 0]], [[1 << 60, 1]], [[1 << 61, 3]]).tolist() == [1]


@settings(max_examples=300, deadline=None)
@given(near_collinear(), st.integers(-1074, -500))
def test_predicate_exact_where_products_underflow(tri, e):
    """Coordinates so small that the cross-product terms are subnormal: the relative
    float bound no longer holds, and the predicate must still be exact."""
    p, q, r = ((x * 2.0**e, y * 2.0**e) for x, y in tri)
    expect = exact_cross(p, q, p, r)
    assert orient(p, q, r) == expect
    assert orient_array([p], [q], [r]).tolist() == [expect]


def test_tiny_polygon_sums_exact_below_the_kernel_range():
    import minkowski2d as mk

    from . import oracle

    for e in (-540, -560, -600, -1000):
        s = 2.0**e
        a = [(0.0, 0.0), (3 * s, s), (s, 3 * s)]
        b = [(0.0, 0.0), (3 * s, s + 2.0**-1074), (-s, s)]
        got = mk.minkowski_sum(a, b)
        assert got.tolist() == [list(v) for v in oracle.rounded(oracle.minkowski_sum(a, b))]


def test_ints_around_the_core_limit():
    """|x| < 2**62 goes to the core's int64 predicate, beyond to exact Python ints."""
    for m in ((1 << 62) - 1, 1 << 62, (1 << 62) + 1, 1 << 63, 1 << 64, 10**40):
        assert orient((0, 0), (m, 1), (2 * m, 2)) == 0
        assert orient((-m, -m), (m, m), (m - 1, m)) == 1
        assert cross_sign((-m, m), (m, -m), (0, 0), (m, -m + 1)) == exact_cross(
            (-m, m), (m, -m), (0, 0), (m, -m + 1)
        )
        # (dtype=object: numpy itself would round [[2**63, 2**63 - 1]] to float64)
        p, q, r = (np.array(v, dtype=object) for v in ([[-m, -m]], [[m, m]], [[m, m - 1]]))
        assert orient_array(p, q, r).tolist() == [-1]
        if m < 1 << 63:
            assert orient_array(
                p.astype(np.int64), q.astype(np.int64), r.astype(np.int64)
            ).tolist() == [-1]
    # numpy ints, including the most negative int64
    lo = np.int64(np.iinfo(np.int64).min)
    assert orient((lo, np.int64(0)), (np.int64(0), np.int64(0)), (np.int64(1), np.int64(1))) == 1
    assert orient_array(np.array([[lo, 0]]), [[0, 0]], [[1, 1]]).tolist() == [1]
    u = np.array([[2**64 - 1, 1]], np.uint64)
    assert orient_array(
        np.array([[0, 0]], np.uint64), u, np.array([[1, 0]], np.uint64)
    ).tolist() == [-1]


def test_fractions_next_to_floats_are_never_rounded():
    """A Fraction is compared exactly with floats (float(F(1, 10)) would be 0.1)."""
    assert orient((0.0, 0.0), (1.0, F(1, 10)), (10, 1)) == 0
    assert orient((0.0, 0.0), (1.0, 0.1), (10, F(1))) == -1  # 0.1 > 1/10 as a float
    third = F(1, 3)
    assert orient((0.0, 0.0), (1.0, third), (3.0, 1.0)) == 0
    assert orient((0.0, 0.0), (1.0, float(third)), (3.0, 1.0)) == 1
    assert cross_sign((0.5, 0), (F(3, 2), 0), (0, F(1, 10**30)), (1.0, F(1, 10**30))) == 0
    # large ints next to floats: no float() of the int either
    big = (1 << 60) + 1
    assert float(big) == 2.0**60  # float(big) would make the next one collinear
    assert orient((0.0, 0.0), (big, 1), (1 << 61, 2.0)) == 1
    assert orient((0.5, 0.0), (big, 1), (2.0**61, 2)) == exact_cross(
        (0.5, 0.0), (big, 1), (0.5, 0.0), (2.0**61, 2)
    )
    obj = np.array([[0.0, 0.0], [0.0, 0.0]], dtype=object)
    q = np.array([[1.0, F(1, 10)], [1.0, 0.1]], dtype=object)
    r = np.array([[10, 1], [10, F(1)]], dtype=object)
    assert orient_array(obj, q, r).tolist() == [0, -1]


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf, np.float32("nan")])
def test_non_finite_raises_with_the_argument(bad):
    with pytest.raises(NonFiniteError) as exc:
        orient((0, 0), (1, bad), (2, 2))
    assert exc.value.argument == "q"
    assert isinstance(exc.value, GeometryError)
    with pytest.raises(NonFiniteError) as exc:
        orient((0, 0), (1, 1), (F(1), bad))  # next to a Fraction: the exact path
    assert exc.value.argument == "r"
    with pytest.raises(NonFiniteError) as exc:
        cross_sign((0.0, 0.0), (1.0, 1.0), (bad, 0.0), (1.0, 1.0))
    assert exc.value.argument == "b0"
    with pytest.raises(NonFiniteError) as exc:
        orient_array([[0, 0], [0, 0]], [[1, 1], [1, 1]], [[2, 2], [2, bad]])
    assert (exc.value.argument, exc.value.vertex) == ("r", 1)
    with pytest.raises(NonFiniteError) as exc:
        orient_array(
            np.array([[0, 0]], dtype=object), np.array([[F(1), bad]], dtype=object), [[2, 2]]
        )
    assert (exc.value.argument, exc.value.vertex) == ("q", 0)


def test_orient_array_paths_agree():
    rng = np.random.default_rng(7)
    pts = rng.integers(-5, 6, size=(500, 3, 2))
    expect = [exact_cross(a, b, a, c) for a, b, c in pts.tolist()]
    p, q, r = pts[:, 0], pts[:, 1], pts[:, 2]
    assert orient_array(p, q, r).tolist() == expect  # int64 core
    assert orient_array(p * 1.0, q * 1.0, r * 1.0).tolist() == expect  # float core
    assert orient_array(p, q * 1.0, r).tolist() == expect  # mixed, exact in float64
    assert orient_array(p.astype(object), q, r).tolist() == expect  # Python path
    scaled = [v * 2.0**-1070 for v in (p, q, r)]  # subnormal coordinates
    assert orient_array(*scaled).tolist() == expect
    big = [v * 2.0**1000 for v in (p, q, r)]
    assert orient_array(*big).tolist() == expect
    assert orient_array(np.zeros((0, 2)), np.zeros((0, 2)), np.zeros((0, 2))).tolist() == []
