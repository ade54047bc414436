"""The edge merge of :func:`minkowski2d.minkowski_sum`, step by step.

:func:`merge_trace` runs the very merge that ``minkowski_sum`` runs: the compiled
core's recording variant of its merge for int64 and float64 input
(``core.merge_record_*``), or :mod:`minkowski2d._engine.exact` with its ``record`` hook for
exact numbers and turns what it recorded into a list of
:class:`MergeStep`. Nothing here decides an angle order a second time: the step's source
and the sign that decided it are the merge's own. The trace only adds explanations: the
exact value of the cross product whose sign the merge used, the edge vectors, and the
vertex reached.

The trace is what the animation page (:mod:`minkowski2d.animation`) plays back.

JSON form
---------
:meth:`MergeTrace.to_dict` returns plain JSON types. Coordinates are JSON numbers: ints
stay ints, floats stay floats, and :class:`fractions.Fraction` values (and ints beyond
2**53, which a browser cannot hold exactly) are given as the nearest float, for drawing.
Every value shown to a reader also comes as exact text (``"1/3"``, ``"12345678901234567"``)
in the ``*_text`` fields, so nothing is lost in the explanation.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, cast

import numpy as np

from ._engine import core
from ._engine import dispatch as D
from ._engine import exact as _exact
from ._types import ArrayLike2, Polygon
from .errors import OverflowGeometryError

__all__ = [
    "MergeStep",
    "MergeTrace",
    "merge_trace",
    "format_number",
    "format_point",
    "json_point",
]

_JS_SAFE = core.FLOAT_EXACT_INT

Point = tuple[Any, Any]


# --------------------------------------------------------------------------------------
# formatting (exact text for the reader)


def format_number(v: Any) -> str:
    """Exact, short text of one coordinate or value.

    ints print as ints, floats with their shortest round-trip repr (so a float keeps its
    ``.0``; ``-0.0`` prints as ``0.0``), Fractions as ``p/q``.

    Examples
    --------
    >>> from fractions import Fraction
    >>> format_number(3), format_number(0.1), format_number(Fraction(2, 6)), format_number(-0.0)
    ('3', '0.1', '1/3', '0.0')
    """
    if isinstance(v, Fraction):
        return str(v.numerator) if v.denominator == 1 else f"{v.numerator}/{v.denominator}"
    if isinstance(v, float):
        return "0.0" if v == 0.0 else repr(v)
    return str(int(v))


def format_point(p: Point) -> str:
    """``(x, y)`` text of a point, exact.

    Examples
    --------
    >>> format_point((3, -1))
    '(3, -1)'
    """
    return f"({format_number(p[0])}, {format_number(p[1])})"


def _json_number(v: Any) -> int | float:
    if isinstance(v, float):
        return 0.0 if v == 0.0 else v
    try:
        if isinstance(v, Fraction):
            return v.numerator if v.denominator == 1 and abs(v) <= _JS_SAFE else float(v)
        v = int(v)
        return v if -_JS_SAFE <= v <= _JS_SAFE else float(v)
    except OverflowError:
        raise OverflowGeometryError(
            "a coordinate is beyond the float range (float64) of JSON numbers, so it cannot "
            "be drawn",
            argument="trace",
            hint="scale the polygons down; the exact values are in the *_text fields",
        ) from None


def json_point(p: Point) -> list:
    """A point as JSON numbers, for drawing: ints within 2**53 stay ints, everything
    else is the nearest float.

    Raises
    ------
    OverflowGeometryError
        A coordinate beyond float64.

    Examples
    --------
    >>> from fractions import Fraction
    >>> json_point((3, Fraction(1, 4)))
    [3, 0.25]
    """
    return [_json_number(p[0]), _json_number(p[1])]


_json_point = json_point


# --------------------------------------------------------------------------------------
# the trace


@dataclass(frozen=True)
class MergeStep:
    """One step of the edge merge.

    Attributes
    ----------
    index : int
        1-based step number.
    source : {"A", "B", "AB"}
        Whose edge was taken; ``"AB"`` when the two current edges are parallel (same
        direction) and were taken together.
    i, j : int or None
        The edge of A and the edge of B that were compared (``None`` once that polygon's
        edges are used up).
    reason : {"cross", "half-plane", "exhausted"}
        What decided: the sign of the cross product ``a_i x b_j``; the two edges pointing
        into different half-planes (an edge with angle in [0°, 180°) comes before one in
        [180°, 360°), no arithmetic needed); or one edge list being used up.
    cross : int or None
        The sign of ``a_i x b_j`` the merge used (``1``: ``b_j`` is counter-clockwise of
        ``a_i``, so ``a_i`` comes first; ``-1``: ``b_j`` first; ``0``: parallel, both).
        ``None`` unless ``reason == "cross"``.
    cross_value : int, Fraction or None
        The exact value of ``a_i x b_j`` (a Fraction for float input: floats are exact
        dyadic rationals). Its sign equals ``cross``.
    taken : tuple of (str, int)
        The edges appended to the sum, e.g. ``(("A", 0), ("B", 0))``.
    start, vertex : (x, y)
        The sum's vertex before and after the step (vertices of A plus vertices of B,
        as the merge computes them).
    path : tuple of (x, y)
        The points the step's arrows pass through: ``(start, vertex)``, or
        ``(start, A[i+1] + B[j], vertex)`` for a parallel pair.
    why : str
        One-sentence explanation of the decision, with exact numbers.
    """

    index: int
    source: str
    i: int | None
    j: int | None
    reason: str
    cross: int | None
    cross_value: Any
    taken: tuple
    start: Point
    vertex: Point
    path: tuple
    why: str

    def to_dict(self, edges_a: list, edges_b: list) -> dict:
        """JSON-ready form (see the module docstring for how numbers are written)."""
        op_a = edges_a[self.i] if self.i is not None else None
        op_b = edges_b[self.j] if self.j is not None else None
        return {
            "index": self.index,
            "source": self.source,
            "i": self.i,
            "j": self.j,
            "reason": self.reason,
            "cross": self.cross,
            "cross_value": None if self.cross_value is None else _json_number(self.cross_value),
            "cross_text": None if self.cross_value is None else format_number(self.cross_value),
            "operand_a": None if op_a is None else _json_point(op_a),
            "operand_b": None if op_b is None else _json_point(op_b),
            "taken": [{"source": s, "index": k} for s, k in self.taken],
            "start": _json_point(self.start),
            "vertex": _json_point(self.vertex),
            "vertex_text": format_point(self.vertex),
            "path": [_json_point(p) for p in self.path],
            "path_sources": [s for s, _ in self.taken],
            "why": self.why,
            "log": _log_line(self),
        }


@dataclass(frozen=True)
class MergeTrace:
    """The merge of two normalized convex polygons, step by step.

    Attributes
    ----------
    a, b : list of (x, y)
        The normalized inputs: CCW, bottom-most vertex first, no duplicate or collinear
        vertices (a point has 1 vertex, a segment 2). Numbers of the common kind.
    kind : {"int", "float", "exact"}
        The number kind both operands were brought to (as in ``minkowski_sum``).
    edges_a, edges_b : list of (dx, dy)
        Edge vectors ``a_i = A[i+1] - A[i]`` (cyclic), in angular order from the
        direction of +x: the merge needs no sort. Empty for a point. For float input
        these are the rounded differences, for display; decisions are made on vertices.
    split_a, split_b : int
        Index of the first edge pointing into the lower half-plane (angle >= 180°).
    start : (x, y)
        ``A[0] + B[0]``, the sum's bottom-most vertex and the first vertex of the merge.
    steps : list of MergeStep
        One per edge (or parallel pair) appended; ``len(steps) == len(result)`` except
        for a point plus a point (no step).
    result : (k, 2) ndarray
        The sum, identical (values and dtype) to ``minkowski_sum(a, b)``.
    """

    a: list
    b: list
    kind: str
    edges_a: list
    edges_b: list
    split_a: int
    split_b: int
    start: Point
    steps: list = field(default_factory=list)
    result: Polygon = field(default_factory=lambda: np.empty((0, 2)))

    def _repr_html_(self) -> str:
        """Inline SVG of the merge for Jupyter (edges coloured by source)."""
        from ._svg import trace_svg

        return trace_svg(self)

    @property
    def vertices(self) -> list:
        """The sum's vertices as a list of exact ``(x, y)`` tuples, in merge order."""
        return [self.start] + [s.vertex for s in self.steps[:-1]]

    def to_dict(self) -> dict:
        """JSON-serializable form of the trace.

        Coordinates are JSON numbers (Fractions and ints beyond 2**53 as the nearest
        float); the exact values are in the ``*_text`` fields.

        Examples
        --------
        >>> import json, minkowski2d as mk
        >>> d = mk.merge_trace([(0, 0), (2, 0), (0, 2)], [(0, 0), (1, 0), (1, 1), (0, 1)]).to_dict()
        >>> d["result"], len(d["steps"])
        ([[0, 0], [3, 0], [3, 1], [1, 3], [0, 3]], 5)
        >>> d["steps"][0]["why"]
        'a0 × b0 = 0: the edges are parallel (same direction), so both are taken together'
        >>> len(json.dumps(d)) > 0
        True
        """
        verts = self.vertices
        return {
            "kind": self.kind,
            "a": [_json_point(p) for p in self.a],
            "b": [_json_point(p) for p in self.b],
            "a_text": [format_point(p) for p in self.a],
            "b_text": [format_point(p) for p in self.b],
            "edges_a": [_json_point(e) for e in self.edges_a],
            "edges_b": [_json_point(e) for e in self.edges_b],
            "edges_a_text": [format_point(e) for e in self.edges_a],
            "edges_b_text": [format_point(e) for e in self.edges_b],
            "split_a": self.split_a,
            "split_b": self.split_b,
            "start": _json_point(self.start),
            "start_text": format_point(self.start),
            "steps": [s.to_dict(self.edges_a, self.edges_b) for s in self.steps],
            "result": [_json_point(p) for p in verts],
            "result_text": [format_point(p) for p in verts],
        }


def _exv(v: Any) -> Any:
    return Fraction(v) if isinstance(v, float) else v


def _cross_value(A: list, i: int, B: list, j: int) -> Any:
    """Exact ``(A[i+1] - A[i]) x (B[j+1] - B[j])`` (ints stay ints, floats go exact)."""
    a0 = A[i]
    a1 = A[(i + 1) % len(A)]
    b0 = B[j]
    b1 = B[(j + 1) % len(B)]
    ux = _exv(a1[0]) - _exv(a0[0])
    uy = _exv(a1[1]) - _exv(a0[1])
    vx = _exv(b1[0]) - _exv(b0[0])
    vy = _exv(b1[1]) - _exv(b0[1])
    return ux * vy - uy * vx


def _edges(P: list) -> list:
    n = len(P)
    if n == 1:
        return []
    return [(P[(k + 1) % n][0] - P[k][0], P[(k + 1) % n][1] - P[k][1]) for k in range(n)]


def _explain(
    src: str, i: int | None, j: int | None, reason: str, c: Any, value: Any, points: tuple
) -> str:
    if reason == "exhausted":
        other, mine, k = ("B", "a", i) if src == "A" else ("A", "b", j)
        if points[other == "B"]:
            why = f"{other} is a single point (it has no edges)"
        else:
            why = f"{other}'s edges are all used"
        return f"{why}, so the next edge {mine}{k} is taken"
    if reason == "half-plane":
        first, other = (f"a{i}", f"b{j}") if src == "A" else (f"b{j}", f"a{i}")
        return (
            f"{first} points into the upper half-plane (angle in [0°, 180°)) and {other} "
            f"into the lower one (angle in [180°, 360°)), so {first} comes first; "
            "no cross product needed"
        )
    v = format_number(value)
    if c > 0:
        return f"a{i} × b{j} = {v} > 0: b{j} is counter-clockwise of a{i}, so a{i} comes first"
    if c < 0:
        return f"a{i} × b{j} = {v} < 0: b{j} is clockwise of a{i}, so b{j} comes first"
    return f"a{i} × b{j} = {v}: the edges are parallel (same direction), so both are taken together"


def _log_line(s: MergeStep) -> str:
    names = " + ".join(f"{'a' if src == 'A' else 'b'}{k}" for src, k in s.taken)
    if s.reason == "cross":
        c = cast(int, s.cross)  # set for every "cross" step
        rel = " > 0" if c > 0 else " < 0" if c < 0 else ", parallel"
        how = f"a{s.i} × b{s.j} = {format_number(s.cross_value)}{rel}"
    elif s.reason == "half-plane":
        how = "half-planes differ"
    else:
        how = ("B" if s.source == "A" else "A") + " used up"
    return f"{s.index}. take {names} ({how}) → {format_point(s.vertex)}"


_SOURCE = {code: name for name, code in core.TRACE_SOURCES.items()}


def _run(a: ArrayLike2, b: ArrayLike2, hull: bool) -> tuple[list, int, list, int, list, list, Any]:
    """Normalize and merge exactly as ``minkowski_sum`` does, recording the steps.

    Returns ``(qa, split_a, qb, split_b, out, record, result_array)`` with the vertices as
    lists of Python tuples and ``record`` entries ``(source, i, j, cross)``.
    """
    A, B, out_kind, path = D.pair(a, b, ("a", "b"))
    if path == "py":
        if hull:
            A = _exact.hull_list(A)
            B = _exact.hull_list(B)
        qa, _, sa = _exact.normalize_list(A, "a")
        qb, _, sb = _exact.normalize_list(B, "b")
        record: list = []
        out = _exact.merge_lists(qa, sa, qb, sb, record=record)
        return qa, sa, qb, sb, out, record, _exact.to_array(out, out_kind)
    if hull:
        hull_fn = core.hull_i if path == "i" else core.hull_f
        A = np.ascontiguousarray(A[hull_fn(A)])
        B = np.ascontiguousarray(B[hull_fn(B)])
    fn = core.merge_record_i if path == "i" else core.merge_record_f
    res, steps, ia, sa, ib, sb, code, which, v = fn(A, B)
    if code:
        raise D.status_error(code, v, ("a", "b", "result")[which], (A, B, None)[which])
    qa = [tuple(r) for r in A[ia].tolist()]
    qb = [tuple(r) for r in B[ib].tolist()]
    out = [tuple(r) for r in res.tolist()]
    record = [
        (
            _SOURCE[src],
            None if i < 0 else i,
            None if j < 0 else j,
            None if c == core.TRACE_NO_CROSS else c,
        )
        for src, i, j, c in steps.tolist()
    ]
    return qa, int(sa), qb, int(sb), out, record, res


def merge_trace(a: ArrayLike2, b: ArrayLike2, *, hull: bool = False) -> MergeTrace:
    """The Minkowski-sum edge merge of two convex polygons, step by step.

    Runs the same normalization and merge as :func:`minkowski2d.minkowski_sum` and
    records, for every step, which edge(s) were taken, the cross-product comparison that
    decided (its sign and exact value) and the vertex reached.

    Parameters
    ----------
    a, b : (n, 2) array_like or shapely geometry
        Convex polygons (points and segments too), any orientation and start vertex.
    hull : bool, default False
        Accept any point sets and use their convex hulls.

    Returns
    -------
    MergeTrace
        ``trace.result`` equals ``minkowski_sum(a, b, hull=hull)`` exactly;
        ``trace.to_dict()`` is JSON-serializable.

    Raises
    ------
    NotConvexError, EmptyGeometryError, ShapeError, NonFiniteError, CoordinateTypeError
        As :func:`minkowski2d.minkowski_sum`.

    Notes
    -----
    O(n + m) steps, recorded by the compiled merge; the explanations are built in
    Python: meant for teaching and for the animation, not for
    speed (use ``minkowski_sum`` for that).

    Examples
    --------
    >>> import minkowski2d as mk
    >>> t = mk.merge_trace([(0, 0), (2, 0), (0, 2)], [(0, 0), (1, 0), (1, 1), (0, 1)])
    >>> [(s.source, s.vertex) for s in t.steps]
    [('AB', (3, 0)), ('B', (3, 1)), ('A', (1, 3)), ('B', (0, 3)), ('AB', (0, 0))]
    >>> t.steps[1].why
    'a1 × b1 = -2 < 0: b1 is clockwise of a1, so b1 comes first'
    >>> t.result.tolist()
    [[0, 0], [3, 0], [3, 1], [1, 3], [0, 3]]
    """
    qa, sa, qb, sb, out, record, result = _run(a, b, hull)
    kind = "int" if result.dtype.kind == "i" else "float" if result.dtype.kind == "f" else "exact"
    na, nb = len(qa), len(qb)
    steps = []
    n = len(record)
    i = j = 0
    for k, (src, ri, rj, c) in enumerate(record):
        if c is not None:
            reason = "cross"
        elif ri is None or rj is None:
            reason = "exhausted"
        else:
            reason = "half-plane"
        value = _cross_value(qa, ri, qb, rj) if reason == "cross" else None
        before = out[k]
        after = out[(k + 1) % n]
        path: tuple
        taken: tuple[tuple[str, int], ...]
        if src == "AB":
            a1 = qa[(i + 1) % na]
            b0 = qb[j % nb]
            path = (before, (a1[0] + b0[0], a1[1] + b0[1]), after)
            taken = (("A", i), ("B", j))
        else:
            path = (before, after)
            taken = (("A", i),) if src == "A" else (("B", j),)
        steps.append(
            MergeStep(
                index=k + 1,
                source=src,
                i=ri,
                j=rj,
                reason=reason,
                cross=c,
                cross_value=value,
                taken=taken,
                start=before,
                vertex=after,
                path=path,
                why=_explain(src, ri, rj, reason, c, value, (na == 1, nb == 1)),
            )
        )
        if src != "B":
            i += 1
        if src != "A":
            j += 1
    return MergeTrace(
        a=qa,
        b=qb,
        kind=kind,
        edges_a=_edges(qa),
        edges_b=_edges(qb),
        split_a=sa,
        split_b=sb,
        start=out[0],
        steps=steps,
        result=result,
    )
