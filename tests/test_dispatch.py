"""minkowski2d._engine.dispatch and the compiled core: the routing rules, the status codes, and
regression tests for the classes of silent wrong answers the core replaced (issue
"Compiled exact core"): overflowing float products, Fractions next to floats, ints
beyond 2**53 next to floats, OverflowError escaping, nan areas. Hypothesis checks that
the core and the exact Python path agree on random, degenerate and extreme inputs."""

from __future__ import annotations

import math
import subprocess
import sys
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import minkowski2d as mk
from minkowski2d._core import _ext
from minkowski2d._engine import dispatch as D
from minkowski2d.errors import GeometryError, NonFiniteError, OverflowGeometryError

from . import oracle
from .strategies import convex_int, presentation

SETTINGS = settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def exact_sum_rounded(a, b):
    return [list(p) for p in oracle.rounded(oracle.minkowski_sum(a, b))]


def run_exact(fn, *args, **kw):
    D.FORCE_EXACT, old = True, D.FORCE_EXACT
    try:
        return fn(*args, **kw)
    finally:
        D.FORCE_EXACT = old


# -- the examples, one per class ---------------------------------------------------
def test_overflowing_float_products_keep_every_vertex():
    a = [(0.0, 0.0), (1e160, 1e160), (0.0, 1e160)]
    b = [(0.0, 0.0), (1e160, 2e160), (0.0, 2e160)]
    s = mk.minkowski_sum(a, b)
    assert [1e160, 1e160] in s.tolist()
    assert s.tolist() == exact_sum_rounded(a, b)
    assert mk.minkowski_sum(np.array(a), np.array(b)).tolist() == s.tolist()


def test_fraction_next_to_float_stays_exact():
    p = mk.normalize([(Fraction(1, 3), 0.5), (1, 0), (1, 1)])
    assert p.dtype == object
    assert Fraction(1, 3) in [x for row in p.tolist() for x in row]
    assert all(isinstance(v, Fraction) for row in p.tolist() for v in row)


def test_big_ints_next_to_a_float_are_decided_exactly():
    A = [(0, 0), (2**60 + 100, 1), (3 * 2**60 + 299, 3), (0, 3)]
    assert mk.is_convex(A)
    s = mk.minkowski_sum(A, [(0.5, 0.0)])
    assert s.dtype == np.float64
    # each coordinate the correctly rounded exact sum
    assert s.tolist() == exact_sum_rounded(A, [(0.5, 0.0)])
    s2 = mk.minkowski_sum(np.array(A), np.array([(0.5, 0.0)]))
    assert s2.tolist() == s.tolist()


def test_no_overflow_error_escapes():
    with pytest.raises(OverflowGeometryError):
        mk.normalize([(10**400, 0.5), (0, 0), (0, 1)])
    # exact output kinds keep huge values
    assert mk.normalize([(10**400, 1), (0, 0), (0, 1)]).dtype == object


def test_signed_area_at_extreme_magnitudes():
    sq = [(0.0, 0.0), (1e150, 0.0), (1e150, 1e150), (0.0, 1e150)]
    assert mk.signed_area(sq) == pytest.approx(1e300, rel=1e-15)
    with pytest.raises(OverflowGeometryError):
        mk.signed_area([(0.0, 0.0), (1e200, 0.0), (1e200, 1e200), (0.0, 1e200)])
    tiny = [(0.0, 0.0), (1e-160, 0.0), (1e-160, 1e-160), (0.0, 1e-160)]
    assert mk.signed_area(tiny) == pytest.approx(1e-320, rel=1e-3)


def test_float_result_overflow_is_an_error_in_every_path():
    a = [(0.0, 0.0), (1.7e308, 0.0), (0.0, 1.0)]
    for f in (list, np.array):
        with pytest.raises(OverflowGeometryError) as ei:
            mk.minkowski_sum(f(a), f(a))
        assert ei.value.argument == "result"
    with pytest.raises(OverflowGeometryError):
        mk.minkowski_sum_many([np.array(a)], [np.array(a)])


def test_errors_carry_fields():
    with pytest.raises(mk.errors.NotConvexError) as ei:
        mk.minkowski_sum([(0, 0), (2, 0), (1, 1), (2, 2), (0, 2)], [(0, 0)])
    e = ei.value
    assert (e.argument, e.vertex) == ("a", 2) and e.hint
    with pytest.raises(NonFiniteError) as ei:
        mk.minkowski_sum([(0, 0), (1, 0)], [(0.0, 0.0), (math.nan, 1.0)])
    assert (ei.value.argument, ei.value.vertex) == ("b", 1)
    with pytest.raises(NonFiniteError) as ei:
        mk.minkowski_sum(np.array([(0.0, 0.0), (1.0, math.inf)]), np.zeros((1, 2)))
    assert (ei.value.argument, ei.value.vertex) == ("a", 1)


def test_status_enum_is_the_cores():
    assert D.Status.OK == 0
    for name in ("TURNS_BOTH_WAYS", "SPIKE", "WINDS_TWICE", "OVERFLOW", "NONFINITE"):
        assert int(getattr(D.Status, name)) == getattr(_ext, name)


# -- routing --------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "a, b, path, kind",
    [
        ([(0, 0), (1, 0)], [(1, 1)], "i", "int"),
        ([(0.5, 0), (1, 0)], [(1, 1)], "f", "float"),
        ([(2**61, 0), (1, 0)], [(1, 1)], "i", "int"),
        ([(2**62, 0), (1, 0)], [(1, 1)], "py", "int"),
        ([(2**54, 0), (1, 0)], [(0.5, 1)], "py", "float"),
        ([(Fraction(1, 3), 0)], [(0.5, 1)], "py", "exact"),
    ],
)
def test_routing(a, b, path, kind):
    _, _, out_kind, p = D.pair(a, b, ("a", "b"))
    assert (p, out_kind) == (path, kind)


@pytest.mark.parametrize(
    "dtype",
    [
        np.int8,
        np.int16,
        np.int32,
        np.int64,
        np.uint8,
        np.uint16,
        np.uint32,
        np.uint64,
        np.float16,
        np.float32,
        np.float64,
    ],
)
def test_numpy_dtypes(dtype):
    a = np.array([(0, 0), (4, 0), (4, 3), (0, 3)], dtype=dtype)
    b = np.array([(0, 0), (1, 0), (0, 1)], dtype=dtype)
    s = mk.minkowski_sum(a, b)
    assert s.dtype == (np.float64 if np.dtype(dtype).kind == "f" else np.int64)
    assert s.tolist() == [[0, 0], [5, 0], [5, 3], [4, 4], [0, 4], [0, 3]] or s.tolist() == [
        [0.0, 0.0],
        [5.0, 0.0],
        [5.0, 3.0],
        [4.0, 4.0],
        [0.0, 4.0],
    ]


def test_uint64_beyond_int64_is_exact():
    a = np.array([(0, 0), (2**64 - 1, 0), (0, 1)], dtype=np.uint64)
    s = mk.minkowski_sum(a, [(0, 0), (1, 1)])
    assert s.dtype == object
    assert oracle.as_exact_list(s) == oracle.minkowski_sum(a.tolist(), [(0, 0), (1, 1)])


# -- core vs exact Python path, on extreme and degenerate input -------------------------
SCALES = [2.0**-1074, 5e-324, 1e-300, 2.0**-600, 1.0, 2.0**600, 1e300, 2.0**1000]


@st.composite
def scaled_float_polygon(draw, max_size=12):
    pts = draw(
        st.lists(
            st.tuples(st.integers(-50, 50), st.integers(-50, 50)), min_size=1, max_size=max_size
        )
    )
    s = draw(st.sampled_from(SCALES))
    h = oracle.hull([(x * s, y * s) for x, y in pts])
    return draw(presentation([(float(x), float(y)) for x, y in h]))


@SETTINGS
@given(scaled_float_polygon(), scaled_float_polygon())
def test_core_and_exact_path_agree_at_every_magnitude(a, b):
    try:
        expected = exact_sum_rounded(a, b)
    except OverflowError:
        expected = None
    if expected is not None and all(math.isfinite(v) for p in expected for v in p):
        got = mk.minkowski_sum(a, b)
        assert got.tolist() == expected
        assert mk.minkowski_sum(np.array(a), np.array(b)).tolist() == expected
        assert run_exact(mk.minkowski_sum, a, b).tolist() == expected
    else:
        with pytest.raises(OverflowGeometryError):
            mk.minkowski_sum(a, b)


@st.composite
def near_degenerate(draw):
    """Vertices within an ulp of a line: every predicate is near zero."""
    n = draw(st.integers(3, 10))
    slope = draw(st.sampled_from([0.1, 1 / 3, 0.7, 3.0]))
    scale = draw(st.sampled_from([1e-200, 1.0, 1e200]))
    ts = sorted(draw(st.lists(st.floats(0, 1), min_size=n, max_size=n)))
    pts = []
    for t in ts:
        x = t * scale
        y = x * slope
        k = draw(st.integers(-1, 1))
        if k:
            y = float(np.nextafter(y, k * np.inf))
        pts.append((float(x), float(y)))
    h = oracle.hull(pts)
    return draw(presentation([(float(x), float(y)) for x, y in h]))


@SETTINGS
@given(near_degenerate(), near_degenerate())
def test_core_and_exact_path_agree_near_degenerate(a, b):
    expected = exact_sum_rounded(a, b)
    assert mk.minkowski_sum(a, b).tolist() == expected
    assert run_exact(mk.minkowski_sum, a, b).tolist() == expected
    assert mk.minkowski_sum_many([np.array(a)], [np.array(b)])[0].tolist() == expected


@SETTINGS
@given(convex_int(max_size=12, bound=2**62 - 1), convex_int(max_size=12, bound=2**61))
def test_ints_at_2_62_and_beyond(a, b):
    got = mk.minkowski_sum(a, b)
    assert oracle.as_exact_list(got) == oracle.minkowski_sum(a, b)
    shifted = [(x * 4 + 3, y * 4) for x, y in a]  # beyond 2**62: the exact path
    got2 = mk.minkowski_sum(shifted, b)
    assert oracle.as_exact_list(got2) == oracle.minkowski_sum(shifted, b)


@SETTINGS
@given(convex_int(max_size=10, bound=100), st.integers(1, 9), st.booleans())
def test_fractions_mixed_with_floats(a, d, swap):
    a2 = [(Fraction(x, d), float(y) / 4) if swap else (float(x) / 4, Fraction(y, d)) for x, y in a]
    b = [(0.5, 0.25), (Fraction(1, 3), 2)]
    got = mk.minkowski_sum(a2, b)
    assert got.dtype == object
    assert oracle.as_exact_list(got) == oracle.minkowski_sum(a2, b)


def test_batch_threads_identical():
    rng = np.random.default_rng(5)
    polys = []
    for _ in range(3000):
        pts = rng.integers(-100, 100, size=(rng.integers(3, 12), 2))
        polys.append(np.array(oracle.hull([tuple(p) for p in pts.tolist()]), dtype=np.int64))
    r1 = mk.minkowski_sum_many(polys, polys[::-1], threads=1)
    r2 = mk.minkowski_sum_many(polys, polys[::-1], threads=2)
    r4 = mk.minkowski_sum_many(polys, polys[::-1], threads=4)
    assert np.array_equal(r1.coords, r2.coords) and np.array_equal(r1.offsets, r2.offsets)
    assert np.array_equal(r1.coords, r4.coords)
    with pytest.raises(ValueError):
        mk.minkowski_sum_many(polys, polys, threads=0)


def test_batch_error_names_the_lowest_failing_pair_with_threads():
    good = [(0, 0), (1, 0), (0, 1)]
    bad = [(0, 0), (2, 0), (1, 1), (2, 2), (0, 2)]
    As = [good] * 2000 + [bad] + [good] * 1000 + [bad]
    with pytest.raises(mk.errors.NotConvexError, match=r"^As\[2000\]"):
        mk.minkowski_sum_many(As, good, threads=2)


def test_selftest_expansions_exact_in_the_built_module():
    assert _ext.selftest()


def test_cold_start_no_jit(tmp_path):
    """A fresh process answers its first large call without compiling anything, with no
    writable cache folder (HOME unwritable, read-only cwd)."""
    code = (
        "import time, numpy as np; t=time.perf_counter(); import minkowski2d as mk; "
        "t1=time.perf_counter(); th=np.linspace(0,6.283,200,endpoint=False); "
        "a=np.c_[np.cos(th),np.sin(th)]; mk.minkowski_sum(a,a*2); "
        "print(t1-t, time.perf_counter()-t1)"
    )
    env = {"HOME": "/nonexistent", "PATH": "/usr/bin:/bin", "PYTHONDONTWRITEBYTECODE": "1"}
    out = subprocess.run(
        [sys.executable, "-c", code], env=env, cwd=tmp_path, capture_output=True, text=True
    )
    assert out.returncode == 0, out.stderr
    assert "numba" not in sys.modules


def test_geometry_errors_are_value_errors():
    assert issubclass(GeometryError, ValueError)


@given(st.integers(min_value=-(2**1100), max_value=2**1100), st.integers(0, 1060))
def test_fits_float64_is_exact_conversion(v, shift):
    # the one rule "this int converts to float64 exactly", against Python's exact
    # comparison of an int with the float it converts to
    from minkowski2d._engine.coerce import fits_float64, ints_fit_float64

    for x in (v, v << shift, (v | 1) << shift):
        try:
            exact = float(x) == x
        except OverflowError:
            exact = False
        assert fits_float64(x) == exact, x
        assert ints_fit_float64([x, 0.5]) == exact
        if -(2**63) <= x < 2**63:
            assert ints_fit_float64(np.array([[0, x]], np.int64)) == exact
