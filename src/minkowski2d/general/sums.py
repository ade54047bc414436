"""The compiled general sums: one call for many pairs (decomposition or convolution), and
:func:`minkowski_sum_general`. The work limits are read from :mod:`.limits` at each call."""

from __future__ import annotations

from typing import Any

import numpy as np

from .._engine import core
from .._engine import options as _options
from .._engine.overlay import geometries
from .._engine.status import Status, status_error
from ..batch import Ragged
from ..errors import (
    GeometryError,
    ShapeError,
)
from . import limits
from .operands import (
    _HINT,
    DECOMPOSITIONS,
    SUM_METHODS,
    _Operand,
    _pieces,
    _read,
)

# --------------------------------------------------------------------------------------
# the compiled sums: one call for many pairs


class _Prepared:
    """One operand, read and validated once (``op``), and lazily its rings and convex
    pieces as the core's arrays (float64, input vertices bit for bit)."""

    __slots__ = ("op", "flat", "name", "_pieces")

    def __init__(self, obj: Any, name: str) -> None:
        self.op = _read(obj, name)
        self.flat = self.op.flat is not None
        self.name = name
        self._pieces: Ragged | None = None

    def rings(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(coordinates (N, 2), ring offsets, polygon offsets); a point or segment is one
        polygon of one ring of 1 or 2 vertices. Closing repeats may stay (the core drops
        them) and the rings may run either way (the core orients them)."""
        if self.flat:
            c = np.ascontiguousarray(self.op.flat, np.float64)
            return c, np.array([0, len(c)], np.int64), np.array([0, 1], np.int64)
        r = self.op.rings
        return r.coords, r.ring_offsets, r.polygon_offsets

    def pieces(self, decomposition: str = "hertel-mehlhorn") -> Ragged:
        """The convex pieces (a point or segment needs none)."""
        if self._pieces is None:
            if self.flat:
                self._pieces = Ragged(np.empty((0, 2)), np.zeros(1, np.int64))
            else:
                self._pieces = _pieces(self.op, decomposition)
        return self._pieces


#: the public method names -> the core's codes (minkowski.hpp Method), and back for
#: ``method_used`` (the core reports AUTO for a sum it did not need to decompose: "flat")
_METHOD_CODE = core.METHODS | {None: core.METHODS["auto"]}
#: the code of the method a sum used -> its name (AUTO: the sum needed no method, "flat")
_USED = {**{code: name for name, code in core.METHODS.items()}, core.METHODS["auto"]: "flat"}


_NO_PIECES = (np.empty((0, 2)), np.zeros(1, np.int64))


def _table(preps: list[_Prepared], with_pieces: list[bool], decomposition: str) -> tuple:
    """The operands (and the pieces of those flagged) as the core's ragged arrays."""
    rings = [p.rings() for p in preps]
    ns = np.array([len(c) for c, _, _ in rings], np.int64)
    nr = np.array([len(ro) - 1 for _, ro, _ in rings], np.int64)
    npo = np.array([len(po) - 1 for _, _, po in rings], np.int64)
    cn = np.concatenate(([0], np.cumsum(ns)))
    cr = np.concatenate(([0], np.cumsum(nr)))
    xy = np.concatenate([c for c, _, _ in rings]) if rings else np.empty((0, 2))
    ro = np.concatenate([[0]] + [r[1:] + cn[k] for k, (_, r, _) in enumerate(rings)])
    po = np.concatenate([[0]] + [p[1:] + cr[k] for k, (_, _, p) in enumerate(rings)])
    op_off = np.concatenate(([0], np.cumsum(npo)))
    kinds = np.array(
        [0 if not p.flat else (1 if n == 1 else 2) for p, n in zip(preps, ns)], np.int8
    )
    pcs = [
        p.pieces(decomposition) if want and not p.flat else None
        for p, want in zip(preps, with_pieces, strict=True)
    ]
    if not any(pc is not None for pc in pcs):
        pc_xy, pc_off = _NO_PIECES
        opc = np.zeros(len(preps) + 1, np.int64)
    else:
        counts = np.array([0 if pc is None else len(pc) for pc in pcs], np.int64)
        have = [pc for pc in pcs if pc is not None]
        pn = np.concatenate(([0], np.cumsum([len(pc.coords) for pc in have])))
        pc_xy = np.concatenate([np.asarray(pc.coords, np.float64) for pc in have])
        pc_off = np.concatenate([[0]] + [pc.offsets[1:] + pn[k] for k, pc in enumerate(have)])
        opc = np.concatenate(([0], np.cumsum(counts)))
    return (
        np.ascontiguousarray(xy, np.float64),
        ro.astype(np.int64),
        po.astype(np.int64),
        op_off.astype(np.int64),
        kinds,
        np.ascontiguousarray(pc_xy, np.float64),
        np.asarray(pc_off, np.int64),
        opc.astype(np.int64),
    )


def _status_error(code: int, name_a: str, name_b: str, method: str) -> GeometryError:
    both = f"{name_a}, {name_b}"
    limits_text = {
        "decomposition": f"MAX_PIECE_PAIRS = {limits.MAX_PIECE_PAIRS} piece sums or "
        f"MAX_CROSSINGS = {limits.MAX_CROSSINGS} crossings",
        "convolution": f"MAX_CONVOLUTION_SEGMENTS = {limits.MAX_CONVOLUTION_SEGMENTS} segments "
        f"or MAX_CROSSINGS = {limits.MAX_CROSSINGS} crossings",
    }.get(
        method,
        "the limits of both methods (MAX_CONVOLUTION_SEGMENTS, MAX_PIECE_PAIRS, MAX_CROSSINGS)",
    )
    hint = {
        "decomposition": "leave method unset (it switches to the convolution), or "
        "simplify the polygons",
        "convolution": "use method='decomposition' (or leave method unset), or simplify "
        "the polygons",
    }.get(method, "simplify the polygons (fewer reflex vertices)")
    return status_error(
        code,
        name=both,
        what="the sum",
        detail="both operands are points or segments: the sum has no area",
        limits=limits_text,
        hint=hint + "; the limits are module constants of minkowski2d.general"
        if code == Status.RESOURCE
        else None,
    )


def _sums(
    preps: list[_Prepared],
    ia: np.ndarray,
    ib: np.ndarray,
    names: list[tuple[str, str]],
    method: str | None,
    decomposition: str = "hertel-mehlhorn",
    threads: int = 1,
    used: list | None = None,
) -> np.ndarray:
    """``A ⊕ B`` of the operand pairs ``(preps[ia[k]], preps[ib[k]])`` in one compiled
    call (two when the default method finds that a pair needs the convex pieces). With
    ``used``, the method each pair was computed by is appended to it."""

    code = _METHOD_CODE[method]
    want = [method == "decomposition"] * len(preps)

    def call(sel: np.ndarray | slice, code: int) -> tuple:
        T = _table(preps, want, decomposition)
        return core.general_sums(
            *T,
            np.ascontiguousarray(ia[sel], np.int64),
            np.ascontiguousarray(ib[sel], np.int64),
            code,
            limits.MAX_CONVOLUTION_SEGMENTS,
            limits.MAX_PIECE_PAIRS,
            limits.MAX_CROSSINGS,
            threads,
        )

    xy, ro, po, pair_off, status, meth = call(slice(None), code)
    out = geometries(xy, ro, po, pair_off)
    if not status.any():
        if used is not None:
            used.extend(_USED[int(m)] for m in meth)
        return out
    redo = np.flatnonzero(status == core.Status.RANGE)
    if len(redo):
        # the default method found the convolution too large: the pieces, for these pairs
        for k in np.unique(np.concatenate([ia[redo], ib[redo]])):
            want[k] = True
        xy, ro, po, pair_off, st2, m2 = call(redo, _METHOD_CODE["decomposition"])
        out[redo] = geometries(xy, ro, po, pair_off)
        status[redo] = st2
        meth[redo] = m2
    if used is not None:
        used.extend(_USED[int(m)] for m in meth)
    bad = np.flatnonzero(status != core.Status.OK)
    if len(bad):
        k = int(bad[0])
        raise _status_error(int(status[k]), names[k][0], names[k][1], method or "auto")
    return out


def _plain_ring(x: Any) -> np.ndarray | None:
    """``x`` when it is a plain ring the core can take as it is: a float64 (n, 2) ndarray
    (n >= 3); None for anything else (the general reader decides)."""
    if type(x) is np.ndarray and x.dtype == np.float64 and x.ndim == 2 and x.shape[1] == 2:
        if x.shape[0] >= 3:
            return np.ascontiguousarray(x)
    return None


def _pair_fast(a: np.ndarray, b: np.ndarray, method: str | None) -> Any:
    """``A ⊕ B`` of two plain rings in one compiled call (validated there); None when a
    ring needs the general reader (no area, or a ring that pinches itself)."""
    from .._engine.polygon import is_flat, problem_error, rings_of_array

    status, which, reason, ring, vertex, xy, ro, po = core.general_pair(
        a,
        b,
        _METHOD_CODE[method],
        limits.MAX_CONVOLUTION_SEGMENTS,
        limits.MAX_PIECE_PAIRS,
        limits.MAX_CROSSINGS,
    )
    if status == core.Status.OK:
        return geometries(xy, ro, po, np.array([0, len(po) - 1], np.int64))[0]
    if status == core.Status.RANGE or is_flat(status, reason):
        return None
    if which >= 0:
        name = "ab"[which]
        raise problem_error(
            status, reason, ring, vertex, rings_of_array(a if which == 0 else b), name, _HINT
        )
    raise _status_error(int(status), "a", "b", method or "auto")


def minkowski_sum_general(
    a: Any, b: Any, *, method: str | None = None, decomposition: str = "hertel-mehlhorn"
) -> Any:
    """Minkowski sum of polygons that may be non-convex and have holes.

    Parameters
    ----------
    a, b : (n, 2) array_like, shapely Polygon / MultiPolygon / LinearRing, or a list
        A simple ring (either orientation), a polygon with holes, or a collection of
        polygons (a list of rings or shapely polygons; their union is the operand). A
        point, a segment or collinear points are taken as that degenerate convex set.
        Whatever :func:`minkowski2d.io.read_geometry` returns is accepted.
    method : {"decomposition", "convolution"}, optional
        ``"decomposition"``: convex pieces, all pairs summed, the sums united by the
        exact overlay. ``"convolution"``: the full convolution of the boundaries, noded
        by the exact overlay (winding number >= 1). Both give the same vertices. Unset
        (``None``): the core picks per pair (the convolution while it has at most a few
        segments per input vertex, else the pieces), within the work limits.
    decomposition : {"hertel-mehlhorn", "triangulation"}
        The pieces used by ``method="decomposition"``.

    Returns
    -------
    shapely.Polygon or shapely.MultiPolygon
        ``{p + q : p ∈ A, q ∈ B}``, exteriors counter-clockwise, holes clockwise and kept.
        A hole that closes to a single point (or a zero-width slit) is not represented:
        the result is the closure of the sum's interior.

    Raises
    ------
    SelfIntersectionError
        An operand is not a valid polygon (names the operand and the reason).
    ShapeError
        Both operands are points or segments, or an operand is unbounded.
    EmptyGeometryError, NonFiniteError, CoordinateTypeError
        Bad input.
    GeometryError
        An integer coordinate has more than 53 significant bits (float64 would round
        it); the message names the operand or ``"a, b"``.
    OverflowGeometryError
        The sum has a coordinate beyond the float64 range.
    ResourceLimitError
        The work exceeds ``MAX_PIECE_PAIRS`` (decomposition),
        ``MAX_CONVOLUTION_SEGMENTS`` (convolution) or ``MAX_CROSSINGS`` (either).

    Notes
    -----
    Every decision is an exact sign at every magnitude from 2**-1074 to the float64
    limit (nothing is scaled); every output vertex is the float64 nearest to the exact
    vertex (where rounding alone would make the result invalid, the rounded rings are
    re-noded: see docs/design.md, "The exact overlay"). Integer input whose exact
    vertices are integers gives those integers. Fractions are rounded to float64 once.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> L = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    >>> s = mk.minkowski_sum_general(L, [(0, 0), (1, 0), (1, 1), (0, 1)])
    >>> s.area, s.geom_type
    (8.0, 'Polygon')
    >>> mk.minkowski_sum_general(L, L, method="convolution").wkt
    'POLYGON ((0 0, 4 0, 4 2, 3 2, 3 3, 2 3, 2 4, 0 4, 0 0))'
    """
    method = _options.choice(method, "method", (None, *SUM_METHODS))
    decomposition = _options.choice(decomposition, "decomposition", DECOMPOSITIONS)
    if decomposition == "hertel-mehlhorn":
        ra, rb = _plain_ring(a), _plain_ring(b)
        if ra is not None and rb is not None:
            g = _pair_fast(ra, rb, method)
            if g is not None:
                return g
    pa, pb = _Prepared(a, "a"), _Prepared(b, "b")
    if pa.flat and pb.flat:
        raise ShapeError(
            "both operands are points or segments: the sum has no area", argument="a, b"
        )
    ia, ib = np.array([0]), np.array([1])
    return _sums([pa, pb], ia, ib, [("a", "b")], method, decomposition)[0]


class _Wrapped(_Prepared):
    """An operand already built."""

    def __init__(self, op: _Operand) -> None:
        self.op = op
        self.flat = op.flat is not None
        self.name = op.name
        self._pieces = None
