"""merge_trace: the merge of minkowski_sum, step by step, checked against the sum itself
and the brute-force oracle."""

from __future__ import annotations

import json
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import minkowski2d as mk
from minkowski2d import trace as trace_mod
from minkowski2d.errors import EmptyGeometryError, NonFiniteError, NotConvexError

from . import oracle
from .strategies import convex_float, convex_int

TRIANGLE = [(0, 0), (2, 0), (0, 2)]
SQUARE = [(0, 0), (1, 0), (1, 1), (0, 1)]


def _same_array(x: np.ndarray, y: np.ndarray) -> bool:
    return x.dtype == y.dtype and x.shape == y.shape and x.tolist() == y.tolist()


def _check(a, b) -> mk.trace.MergeTrace:
    """Every invariant a trace must satisfy, for any input."""
    t = mk.merge_trace(a, b)
    expected = mk.minkowski_sum(a, b)
    a = a.tolist() if isinstance(a, np.ndarray) else a  # the oracle wants Python numbers
    b = b.tolist() if isinstance(b, np.ndarray) else b
    assert _same_array(t.result, expected)
    if t.kind == "float":
        assert t.result.tolist() == [list(p) for p in oracle.rounded(oracle.minkowski_sum(a, b))]
    else:
        assert oracle.as_exact_list(t.result) == oracle.minkowski_sum(a, b)
    # the normalized inputs are what normalize() returns
    assert oracle.as_exact_list(np.array(t.a, dtype=object)) == oracle.hull(a)
    assert oracle.as_exact_list(np.array(t.b, dtype=object)) == oracle.hull(b)
    # steps: one per output vertex (a point plus a point has none)
    n = len(t.steps)
    assert n == (0 if len(t.a) == len(t.b) == 1 else len(t.result))
    assert t.vertices == [tuple(p) for p in t.result.tolist()] or t.kind != "int"
    # each edge of A and of B is taken exactly once, in order
    ta = [k for s in t.steps for src, k in s.taken if src == "A"]
    tb = [k for s in t.steps for src, k in s.taken if src == "B"]
    assert ta == list(range(len(t.edges_a)))
    assert tb == list(range(len(t.edges_b)))
    cur = oracle.exact(t.start)
    for s in t.steps:
        assert s.source in ("A", "B", "AB")
        assert s.source == "".join(src for src, _ in s.taken)
        assert oracle.exact(s.start) == oracle.exact(s.path[0])
        assert oracle.exact(s.vertex) == oracle.exact(s.path[-1])
        assert len(s.path) == len(s.taken) + 1
        if s.reason == "cross":
            assert s.i is not None and s.j is not None
            a0, a1 = oracle.exact(t.a[s.i]), oracle.exact(t.a[(s.i + 1) % len(t.a)])
            b0, b1 = oracle.exact(t.b[s.j]), oracle.exact(t.b[(s.j + 1) % len(t.b)])
            exact_value = (a1[0] - a0[0]) * (b1[1] - b0[1]) - (a1[1] - a0[1]) * (b1[0] - b0[0])
            assert s.cross_value == exact_value
            assert (exact_value > 0) - (exact_value < 0) == s.cross
            # the decision the merge made agrees with the sign
            assert s.source == ("A" if s.cross > 0 else "B" if s.cross < 0 else "AB")
            assert f"= {mk.trace.format_number(s.cross_value)}" in s.why
        else:
            assert s.cross is None and s.cross_value is None
            if s.reason == "exhausted":
                assert (s.i is None) != (s.j is None)
            else:
                assert s.reason == "half-plane"
                assert (s.i >= t.split_a) != (s.j >= t.split_b)
        # with exact numbers the vertex reached is the vertex before plus the edges taken
        if t.kind != "float":
            for src, k in s.taken:
                e = (t.edges_a if src == "A" else t.edges_b)[k]
                cur = (cur[0] + e[0], cur[1] + e[1])
            assert cur == oracle.exact(s.vertex)
    if n:
        assert oracle.exact(t.steps[-1].vertex) == oracle.exact(t.start)
    d = t.to_dict()
    back = json.loads(json.dumps(d, allow_nan=False))
    assert len(back["steps"]) == n
    assert len(back["result"]) == len(t.result)
    return t


def test_seed_triangle_square_step_by_step():
    t = mk.merge_trace(TRIANGLE, SQUARE)
    assert [(s.source, s.vertex) for s in t.steps] == [
        ("AB", (3, 0)),
        ("B", (3, 1)),
        ("A", (1, 3)),
        ("B", (0, 3)),
        ("AB", (0, 0)),
    ]
    assert [s.reason for s in t.steps] == ["cross", "cross", "half-plane", "cross", "cross"]
    assert [s.cross_value for s in t.steps] == [0, -2, None, -2, 0]
    assert t.edges_a == [(2, 0), (-2, 2), (0, -2)]
    assert t.edges_b == [(1, 0), (0, 1), (-1, 0), (0, -1)]
    assert t.start == (0, 0)
    assert t.steps[4].path == ((0, 3), (0, 1), (0, 0))
    assert t.steps[1].why == "a1 × b1 = -2 < 0: b1 is clockwise of a1, so b1 comes first"
    assert "so a1 comes first" in t.steps[2].why
    assert t.result.tolist() == [[0, 0], [3, 0], [3, 1], [1, 3], [0, 3]]
    _check(TRIANGLE, SQUARE)


def test_uses_the_algorithms_own_merge(monkeypatch):
    calls = []
    real = trace_mod.core.merge_record_i

    def spy(*args, **kw):
        out = real(*args, **kw)
        calls.append(out[1])
        return out

    monkeypatch.setattr(trace_mod.core, "merge_record_i", spy)
    t = mk.merge_trace(TRIANGLE, SQUARE)
    assert len(calls) == 1
    names = {-1: "A", 1: "B", 0: "AB"}
    assert [names[r[0]] for r in calls[0].tolist()] == [s.source for s in t.steps]


def test_exact_path_records_the_same_steps():
    from minkowski2d._engine import dispatch as D

    t = mk.merge_trace(TRIANGLE, SQUARE)
    D.FORCE_EXACT = True
    try:
        e = mk.merge_trace(TRIANGLE, SQUARE)
    finally:
        D.FORCE_EXACT = False
    assert [(s.source, s.i, s.j, s.cross, s.vertex) for s in t.steps] == [
        (s.source, s.i, s.j, s.cross, s.vertex) for s in e.steps
    ]


def test_to_dict_is_plain_json():
    d = mk.merge_trace(TRIANGLE, SQUARE).to_dict()
    s = json.dumps(d, allow_nan=False)
    assert json.loads(s) == d
    assert d["result_text"] == ["(0, 0)", "(3, 0)", "(3, 1)", "(1, 3)", "(0, 3)"]
    st0 = d["steps"][0]
    assert st0["taken"] == [{"source": "A", "index": 0}, {"source": "B", "index": 0}]
    assert st0["operand_a"] == [2, 0] and st0["operand_b"] == [1, 0]
    assert st0["cross_value"] == 0 and st0["cross_text"] == "0"
    assert st0["log"] == "1. take a0 + b0 (a0 × b0 = 0, parallel) → (3, 0)"


def test_fractions_and_huge_ints_keep_exact_text():
    a = [(Fraction(0), Fraction(0)), (Fraction(1, 3), Fraction(0)), (Fraction(0), Fraction(1, 3))]
    t = _check(a, SQUARE)
    d = t.to_dict()
    assert t.kind == "exact"
    assert "(4/3, 0)" in d["result_text"]
    assert all(isinstance(v, (int, float)) for p in d["result"] for v in p)
    big = 1 << 70
    t = _check([(big, 0), (big + 1, 0), (big, 1)], SQUARE)
    d = t.to_dict()
    assert d["result_text"][0] == f"({big}, 0)"
    assert isinstance(d["result"][0][0], float)


def test_points_segments_and_parallel_edges():
    _check([(3, 4)], [(1, 1)])
    t = _check([(3, 4)], SQUARE)
    assert all(s.reason == "exhausted" for s in t.steps)
    assert "A is a single point" in t.steps[0].why
    _check([(0, 0), (2, 2)], [(0, 0), (2, 2)])
    _check([(0, 0), (2, 2)], SQUARE)
    t = _check(SQUARE, SQUARE)  # every edge parallel to its partner
    assert all(s.source == "AB" for s in t.steps)
    _check([(0, 0), (4, 0), (4, 4), (0, 4)], [(0, 0), (1, 0), (1, 1)])


def test_float_input_rounds_like_minkowski_sum():
    a = [(0.1, 0.2), (0.7, 0.2), (0.3, 0.9)]
    b = [(1e-3, 0.0), (1.0, 1e-9), (0.5, 0.5)]
    t = _check(a, b)
    assert t.kind == "float"
    _check(a, [(0, 0), (1, 0), (0, 1)])  # int with float: float


def test_large_arrays_match_the_compiled_path():
    k = np.arange(40)
    circle = np.stack(
        [np.round(1000 * np.cos(2 * np.pi * k / 40)), np.round(1000 * np.sin(2 * np.pi * k / 40))],
        axis=1,
    ).astype(np.int64)
    sq = np.array([(0, 0), (300, 0), (300, 300), (0, 300)] * 1, dtype=np.int64)
    _check(circle, sq)
    _check(circle.astype(np.float64) / 7, circle[::-1])


def test_hull_option():
    pts = [(0, 0), (2, 0), (1, 1), (0, 2), (2, 2)]
    t = mk.merge_trace(pts, SQUARE, hull=True)
    assert _same_array(t.result, mk.minkowski_sum(pts, SQUARE, hull=True))


def test_errors_match_minkowski_sum():
    with pytest.raises(NotConvexError, match="a: not convex"):
        mk.merge_trace([(0, 0), (2, 0), (1, 1), (2, 2), (0, 2)], SQUARE)
    with pytest.raises(NonFiniteError, match="b: vertex 1"):
        mk.merge_trace(SQUARE, [(0.0, 0.0), (float("nan"), 1.0)])
    with pytest.raises(EmptyGeometryError, match="a: empty"):
        mk.merge_trace([], SQUARE)


@settings(max_examples=150, deadline=None)
@given(convex_int(max_size=12, bound=50), convex_int(max_size=12, bound=50))
def test_int_traces(a, b):
    _check(a, b)


@settings(max_examples=60, deadline=None)
@given(convex_float(max_size=10), convex_float(max_size=10))
def test_float_traces(a, b):
    _check(a, b)


@settings(max_examples=60, deadline=None)
@given(convex_int(max_size=10, bound=6), st.integers(1, 3), st.integers(-5, 5), st.integers(-5, 5))
def test_parallel_edges_scaled_copies(a, s, dx, dy):
    # a scaled, shifted copy has every edge parallel to one of a's: all steps are pairs
    b = [(s * x + dx, s * y + dy) for x, y in a]
    t = _check(a, b)
    if len(t.a) > 1:
        assert all(st_.source == "AB" for st_ in t.steps)


def test_to_dict_beyond_float_range_is_a_geometry_error():
    t = mk.merge_trace([(0, 0), (10**400, 0), (0, 1)], [(0, 0), (1, 1)])
    assert t.result.dtype == object  # the trace itself stays exact
    with pytest.raises(mk.errors.OverflowGeometryError) as ei:
        t.to_dict()
    assert ei.value.argument == "trace" and ei.value.hint
