"""Non-convex Minkowski sums (polygons with holes) and the Minkowski difference (erosion).

Two methods compute ``A ⊕ B`` for simple polygons with holes and collections of them:

* ``method="decomposition"`` (default): both operands are cut into convex pieces
  (Hertel-Mehlhorn, see :func:`convex_decomposition`), every pair of pieces is summed in
  one batched call (:func:`minkowski2d.minkowski_sum_many`), and the convex sums are
  unioned by GEOS. The union is done in rounds: the largest sums first, then the sums
  reaching farthest from the centre; after each round every remaining sum that lies
  strictly inside the union so far is dropped. The order only changes the speed; the
  result is the union of all piece sums.
* ``method="convolution"``: the reduced convolution (Behar & Lien 2011): segments
  ``e + v`` for an edge ``e`` of one boundary and a convex vertex ``v`` of the other
  whose normal cone holds the edge's normal. Every boundary point of the sum lies on one
  of them, so each face of their arrangement (noded and polygonized by GEOS) is wholly
  inside or wholly outside the sum. The orientability filter: just left of every segment
  is inside the sum, so a face with a boundary edge carrying a segment that has the face
  on its left is inside. The remaining faces are hole candidates; the hole filter keeps
  one as a hole only if ``A`` does not meet ``x − B`` for a point ``x`` inside it.

Both return a shapely Polygon or MultiPolygon (exterior rings counter-clockwise, holes
clockwise, holes kept). Coordinates are float64 throughout: integers with at most 53
significant bits are represented exactly (others are refused), piece sums are exact for
them, and GEOS computes the crossings of the final union in double precision. GEOS only
ever sees the operands multiplied by one common power of two that puts their largest
|coordinate| in ``[2**19, 2**20)``; the result is multiplied back (both exact), so tiny
and huge magnitudes behave like magnitudes near 1. A shapely/GEOS failure surfaces as a
:class:`~minkowski2d.errors.GeometryError` naming the operand; the work is bounded by
``MAX_PIECE_PAIRS``, ``MAX_CONVOLUTION_TESTS`` and ``MAX_CONVOLUTION_CROSSINGS``
(:class:`~minkowski2d.errors.ResourceLimitError`).

:func:`minkowski_difference` is the erosion ``A ⊖ B = {c : c + B ⊆ A}``. It is *not*
``A ⊕ (−B)`` (that is :func:`minkowski2d.cspace_obstacle`, the set of translations
where ``B`` *touches* ``A``); the erosion is the set where ``B`` fits *inside* ``A``.
Neither operand needs to contain the origin.
"""

from __future__ import annotations

import math
from fractions import Fraction
from functools import partial
from typing import Any

import numpy as np

from . import _options
from ._coerce import as_array
from ._overlay import geometries
from .batch import Ragged
from .errors import (
    EmptyGeometryError,
    GeometryError,
    NonFiniteError,
    OverflowGeometryError,
    ResourceLimitError,
    ShapeError,
)

__all__ = [
    "minkowski_sum_general",
    "minkowski_sum_general_many",
    "convex_decomposition",
    "minkowski_difference",
]

SUM_METHODS = ("decomposition", "convolution")
DECOMPOSITIONS = ("hertel-mehlhorn", "triangulation")


# --------------------------------------------------------------------------------------
# limits and scale

#: ``method="decomposition"``: at most this many convex piece sums (pieces of A times
#: pieces of B). Beyond it the default method switches to the convolution, an explicit
#: ``method="decomposition"`` raises ResourceLimitError. (The 2048-vertex stars of the
#: benchmark need 1.59 M sums and 1.9 GB; the CGAL corpus at most 441.)
MAX_PIECE_PAIRS = 1 << 21
#: ``method="convolution"``: at most this many (edge, vertex) pairs tested (the sum of
#: ``n * m`` over the ring pairs) ...
MAX_CONVOLUTION_TESTS = 1 << 24
#: ... and at most this many pairs of convolution segments that meet (the arrangement:
#: 128-vertex stars have 0.5 M and take 1.9 GB and 80 s; the CGAL corpus at most 12 422).
MAX_CONVOLUTION_CROSSINGS = 1 << 20
#: The convolution's only float tolerances (relative to the operands' extent, which the
#: scale keeps near 2**20). CONE_SLACK widens the convex-vertex and normal-cone tests:
#: every extra segment e + v still lies in the sum with the sum on its left, so a larger
#: set is harmless. PROVENANCE_TOLERANCE matches a noded edge to the segments it lies on
#: (distance and direction): GEOS rounds the crossing points, so the match cannot be an
#: exact sign; two parallel segments closer than this could be confused.
CONE_SLACK = 1e-12
PROVENANCE_TOLERANCE = 1e-9


# --------------------------------------------------------------------------------------
# input
#
# Reading an operand is two passes: _parse checks the types and keeps the raw
# coordinates, _build validates them exactly in the core (no GEOS). Nothing is scaled:
# the core decides exactly at every magnitude and rounds each result vertex once.


class _Operand:
    """A validated operand: polygons as ``_polygon.Rings`` (validated exactly, any
    orientation: ``orientation[r]`` is +1 for a ring given counter-clockwise), or a
    degenerate convex set (point or segment) held as a (k, 2) float64 array."""

    __slots__ = ("rings", "orientation", "flat", "name", "_geom")

    def __init__(self, rings: Any, orientation: Any, flat: np.ndarray | None, name: str) -> None:
        self.rings = rings
        self.orientation = orientation
        self.flat = flat
        self.name = name
        self._geom = None

    @property
    def geom(self) -> Any:
        """The operand as a shapely Polygon / MultiPolygon (exteriors CCW, holes CW)."""
        if self._geom is None:
            from ._polygon import oriented, to_geometry

            multi = len(self.rings.polygon_offsets) > 2
            self._geom = to_geometry(oriented(self.rings, self.orientation), multi)
        return self._geom

    @property
    def convex_ring(self) -> np.ndarray | None:
        """The ring of a single convex polygon without holes (or the flat set), else None."""
        if self.flat is not None:
            return self.flat
        ro = self.rings.ring_offsets
        if len(ro) != 2:
            return None
        from ._dispatch import check_convex

        ring = self.rings.coords[ro[0] : ro[1]]
        if len(ring) > 1 and (ring[0] == ring[-1]).all():
            ring = ring[:-1]
        return ring if check_convex(ring, self.name) else None

    def hull(self) -> np.ndarray:
        """Convex hull of the operand (exact, normalized)."""
        if self.flat is not None:
            return self.flat
        from .convex import convex_hull

        return np.asarray(convex_hull(self.rings.coords), dtype=np.float64)


class _Raw:
    """A parsed, not yet validated operand: a shapely Polygon/MultiPolygon (``geom``),
    float64 coordinates (``coords``), exact coordinates (``exact``: Fractions, rounded
    only after the exact scale) or a collection of them (``items``)."""

    __slots__ = ("kind", "value", "name")

    def __init__(self, kind: str, value: Any, name: str) -> None:
        self.kind = kind
        self.value = value
        self.name = name


_EXACT_INT = 1 << 53


def _int_coords(arr: np.ndarray, name: str) -> np.ndarray:
    """float64 copy of int coordinates; refuse an int that float64 cannot hold exactly."""
    big = np.abs(arr.astype(np.float64)) >= _EXACT_INT
    if big.any():
        for k in np.flatnonzero(big.any(axis=1)):
            for v in arr[k].tolist():
                _check_int(int(v), name, int(k))
    return arr.astype(np.float64)


def _check_int(v: int, name: str, vertex: int) -> None:
    if abs(v) >= _EXACT_INT and (v >> ((v & -v).bit_length() - 1)).bit_length() > 53:
        raise GeometryError(
            f"{name}: vertex {vertex} has the integer coordinate {v}, which float64 "
            "cannot hold exactly (more than 53 significant bits); the general routines "
            "compute in float64 and would round it",
            argument=name,
            vertex=vertex,
            hint="round or scale the coordinates to at most 53 significant bits, "
            "or use the exact convex routines",
        )


def _coords_raw(obj: Any, name: str) -> _Raw:
    data, kind = as_array(obj, name)
    if isinstance(data, list):  # exact kinds: Fractions or huge ints
        for k, p in enumerate(data):
            for v in p:
                if isinstance(v, int):
                    _check_int(v, name, k)
        return _Raw("exact", [(Fraction(x), Fraction(y)) for x, y in data], name)
    if data.dtype.kind == "i":
        return _Raw("coords", _int_coords(data, name), name)
    return _Raw("coords", np.asarray(data, dtype=np.float64), name)


def _parse(obj: Any, name: str) -> _Raw:
    """Check the type of one operand (see :func:`minkowski_sum_general`); no GEOS call."""
    import shapely

    if isinstance(obj, Ragged):
        obj = obj.to_list()
    mod = type(obj).__module__
    if mod.startswith("shapely"):
        gt = obj.geom_type
        if gt in ("Polygon", "MultiPolygon"):
            if obj.is_empty:
                raise EmptyGeometryError(f"{name}: empty {gt}", argument=name)
            return _Raw("geom", obj, name)
        if gt == "GeometryCollection":
            parts = shapely.get_parts(obj)
            if not np.isin(shapely.get_type_id(parts), (3, 6)).all():
                raise ShapeError(
                    f"{name}: a GeometryCollection may hold only polygons", argument=name
                )
            return _parse(list(parts), name)
        return _coords_raw(obj, name)  # ring, line, points
    if type(obj).__name__ == "UnboundedPolygon":
        raise ShapeError(
            f"{name}: the polygon has an unbounded outer boundary (CGAL N = 0); "
            "its Minkowski sum is unbounded too",
            argument=name,
        )
    if (
        isinstance(obj, (list, tuple))
        and obj
        and (type(obj[0]).__module__.startswith("shapely") or np.ndim(obj[0]) == 2)
    ):
        # a collection of polygons: their union is the operand
        return _Raw("items", [_parse(item, f"{name}[{k}]") for k, item in enumerate(obj)], name)
    return _coords_raw(obj, name)


def _float_ring(raw: _Raw) -> np.ndarray:
    """float64 coordinates of a parsed ring; exact values (Fractions, big ints) rounded
    once, correctly; a value beyond float64, or one that would lose bits below 2**-1022,
    is an OverflowGeometryError naming the vertex."""
    if raw.kind == "coords":
        return raw.value
    name = raw.name
    out = np.empty((len(raw.value), 2))
    for k, p in enumerate(raw.value):
        for j, v in enumerate(p):
            try:
                f = float(v)
            except OverflowError:
                f = math.inf
            if math.isinf(f):
                raise OverflowGeometryError(
                    f"{name}: vertex {k} has a coordinate beyond float64 (±1.8e308)",
                    argument=name,
                    vertex=k,
                    hint="scale the input down; coordinates must fit in float64",
                )
            if v != 0 and abs(f) < 2.0**-1022:
                raise OverflowGeometryError(
                    f"{name}: vertex {k} has a coordinate that underflows float64 (a "
                    "nonzero value below 2**-1022 would be rounded to a multiple of "
                    "2**-1074)",
                    argument=name,
                    vertex=k,
                    hint="scale the input up; coordinates must be float64 normals",
                )
            out[k, j] = f
    return out


_HINT = "the boundary must not cross itself; holes must lie inside"


def _checked(rings: Any, name: str, multi: bool) -> _Operand:
    """An operand of validated rings (a polygon whose hole touches its shell twice is
    split into its parts by the exact overlay)."""
    from ._polygon import check, rings_of

    ck = check(rings, name, _HINT, disjoint=multi)
    if ck.disconnected.any():
        from ._polygon import oriented

        o = oriented(rings, ck.orientation)
        ro = o.ring_offsets
        g = _union_members_rings([o.coords[ro[r] : ro[r + 1]] for r in range(len(ro) - 1)], name)
        rings = rings_of(g)
        ck = check(rings, name, _HINT, disjoint=True)
    return _Operand(rings, ck.orientation, None, name)


def _build(raw: _Raw) -> _Operand:
    """Validate a parsed operand exactly (the core's checks; no GEOS)."""
    from ._polygon import rings_of, rings_of_array

    name = raw.name
    if raw.kind == "items":
        rings = []
        for item in raw.value:
            op = _build(item)
            if op.flat is not None:
                # uniting would drop it, yet {p} ⊕ B has area: refuse rather than lose it
                raise ShapeError(
                    f"{item.name}: a point or segment in a collection of polygons "
                    "(every member of a collection must have area)",
                    argument=item.name,
                    hint="pass the point or segment as an operand of its own",
                )
            from ._polygon import oriented

            o = oriented(op.rings, op.orientation)
            ro = o.ring_offsets
            rings += [o.coords[ro[r] : ro[r + 1]] for r in range(len(ro) - 1)]
        g = _union_members_rings(rings, name)
        if g.is_empty:
            raise ShapeError(f"{name}: the polygons have no area", argument=name)
        return _checked(rings_of(g), name, g.geom_type == "MultiPolygon")
    if raw.kind == "geom":
        import shapely

        c = shapely.get_coordinates(raw.value)
        if not np.isfinite(c).all():
            raise NonFiniteError(f"{name}: a coordinate is not finite", argument=name)
        return _checked(rings_of(raw.value), name, raw.value.geom_type == "MultiPolygon")
    ring = _float_ring(raw)
    rings = rings_of_array(ring)
    if len(ring):
        from ._polygon import Invalid, probe

        status, reason, _, _, orientation, disconnected = probe(rings)
        if status == 0 and not disconnected.any():
            return _Operand(rings, orientation, None, name)
        if status and reason in (Invalid.RING_FEW_VERTICES, Invalid.RING_NO_AREA):
            # a point, a segment, or collinear points: a degenerate convex set
            from .convex import convex_hull

            return _Operand(None, None, np.asarray(convex_hull(ring), dtype=np.float64), name)
    return _checked(rings, name, False)


def _union_members_rings(rings: list, name: str) -> Any:
    """The union of validated rings (exteriors CCW, holes CW), by the exact overlay;
    vertices where members cross are rounded to the nearest double."""
    from ._overlay import overlay

    return overlay(rings, argument=name)


def _operands(*pairs: tuple[Any, str]) -> list[_Operand]:
    """Parse and validate the operands."""
    return [_build(_parse(obj, name)) for obj, name in pairs]


def _pieces(op: _Operand, method: str = "hertel-mehlhorn") -> Ragged:
    if op.flat is not None:
        return Ragged(op.flat, np.array([0, len(op.flat)], np.int64))
    from ._decompose import decompose_rings

    coords, off = decompose_rings(op.rings, op.name, merge=method == "hertel-mehlhorn")
    return Ragged(coords, off)


def convex_decomposition(poly: Any, *, method: str = "hertel-mehlhorn") -> Ragged:
    """Split a polygon (holes allowed) into convex pieces.

    Parameters
    ----------
    poly : (n, 2) array_like, shapely Polygon or MultiPolygon, or a list of them
        A simple polygon (any orientation), a polygon with holes, or a collection
        (their union is decomposed).
    method : {"hertel-mehlhorn", "triangulation"}
        ``"triangulation"``: the compiled core's exact triangulation (a monotone
        partition by a plane sweep; input vertices only, holes supported).
        ``"hertel-mehlhorn"``: the triangles merged across every diagonal whose removal
        keeps both its endpoints convex (at most four times the optimal number of
        pieces).

    Returns
    -------
    Ragged
        The pieces as float64 vertices, each counter-clockwise from its bottom-most
        vertex (lowest y, then x), without collinear vertices. They cover the polygon
        and overlap only along shared edges. A point or segment gives one piece.

    Raises
    ------
    SelfIntersectionError
        The polygon is not valid (its boundary crosses itself, a hole lies outside ...).
    ShapeError, EmptyGeometryError, NonFiniteError
        Bad input.
    GeometryError
        An integer coordinate has more than 53 significant bits, or GEOS failed.

    Notes
    -----
    Time O(n log n) for the triangulation and O(n) for the merge; every decision is an
    exact sign (no GEOS), so the pieces' vertices are the input vertices bit for bit at
    any magnitude.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> L = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    >>> for piece in mk.convex_decomposition(L):
    ...     print(piece.tolist())
    [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]]
    [[0.0, 0.0], [1.0, 1.0], [1.0, 2.0], [0.0, 2.0]]
    >>> len(mk.convex_decomposition(L, method="triangulation"))
    4
    """
    method = _options.choice(method, "method", DECOMPOSITIONS)
    (P,) = _operands((poly, "poly"))
    return _pieces(P, method)


# --------------------------------------------------------------------------------------
# the compiled sums: one call for many pairs


class _Prepared:
    """One operand, read and validated once (``op``), and lazily its rings and convex
    pieces as the core's arrays (float64, input vertices bit for bit)."""

    __slots__ = ("op", "flat", "name", "_pieces")

    def __init__(self, obj: Any, name: str) -> None:
        self.op = _build(_parse(obj, name))
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


#: Work limits of one pair (each a ResourceLimitError when exceeded):
#: ``MAX_PIECE_PAIRS`` convex piece sums (pieces of A times pieces of B) for the
#: decomposition ...
MAX_PIECE_PAIRS = 1 << 21
#: ... ``MAX_CONVOLUTION_SEGMENTS`` segments of the convolution (about 800 bytes each
#: with their crossings: two 2048-vertex stars have over 2 M and would need gigabytes) ...
MAX_CONVOLUTION_SEGMENTS = 1 << 21
#: ... and ``MAX_CROSSINGS`` crossings noded by the exact overlay, over all its runs
#: (about 150 bytes each). The 2048-vertex stars of the benchmark need the decomposition;
#: their convolution has 10**6 segments and far more crossings.
MAX_CROSSINGS = 1 << 21

_METHOD_CODE = {"auto": 0, None: 0, "decomposition": 1, "convolution": 2}
_USED = {0: "flat", 1: "decomposition", 2: "convolution"}


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
    from ._dispatch import Status

    both = f"{name_a}, {name_b}"
    if code == Status.SHAPE:
        return ShapeError(
            f"{both}: both operands are points or segments: the sum has no area",
            argument=both,
        )
    if code == Status.OVERFLOW:
        return OverflowGeometryError(
            f"{both}: the result overflows float64 (a coordinate beyond ±1.8e308)",
            argument=both,
            hint="scale the input down; the result's coordinates must fit in float64",
        )
    if code == Status.RESOURCE:
        what = {
            "decomposition": f"MAX_PIECE_PAIRS = {MAX_PIECE_PAIRS} piece sums or "
            f"MAX_CROSSINGS = {MAX_CROSSINGS} crossings",
            "convolution": f"MAX_CONVOLUTION_SEGMENTS = {MAX_CONVOLUTION_SEGMENTS} segments "
            f"or MAX_CROSSINGS = {MAX_CROSSINGS} crossings",
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
        return ResourceLimitError(
            f"{both}: the sum needs more work than {what}",
            argument=both,
            hint=hint + "; the limits are module constants of minkowski2d.general",
        )
    return GeometryError(
        f"{both}: internal error {code} in the exact overlay (please report it)",
        argument=both,
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
    from ._core import _ext

    code = _METHOD_CODE[method]
    want = [method == "decomposition"] * len(preps)

    def call(sel: np.ndarray, code: int) -> tuple:
        T = _table(preps, want, decomposition)
        return _ext.general_sums(
            *T,
            np.ascontiguousarray(ia[sel], np.int64),
            np.ascontiguousarray(ib[sel], np.int64),
            code,
            MAX_CONVOLUTION_SEGMENTS,
            MAX_PIECE_PAIRS,
            MAX_CROSSINGS,
            threads,
        )

    xy, ro, po, pair_off, status, meth = call(slice(None), code)
    out = geometries(xy, ro, po, pair_off)
    if not status.any():
        if used is not None:
            used.extend(_USED[int(m)] for m in meth)
        return out
    redo = np.flatnonzero(status == _ext.RANGE)
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
    bad = np.flatnonzero(status != _ext.OK)
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
    from ._core import _ext
    from ._polygon import Invalid, problem_error, rings_of_array

    status, which, reason, ring, vertex, xy, ro, po = _ext.general_pair(
        a, b, _METHOD_CODE[method], MAX_CONVOLUTION_SEGMENTS, MAX_PIECE_PAIRS, MAX_CROSSINGS
    )
    if status == _ext.OK:
        return geometries(xy, ro, po, np.array([0, len(po) - 1], np.int64))[0]
    if status == _ext.RANGE or (
        status == _ext.INVALID_POLYGON
        and reason in (Invalid.RING_FEW_VERTICES, Invalid.RING_NO_AREA)
    ):
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
        ``"decomposition"``: convex pieces, all pairs summed in one batch, GEOS union.
        ``"convolution"``: reduced convolution, GEOS arrangement, orientability and
        hole filters. Both give the same set. Unset (``None``): the decomposition, or
        the convolution when the pieces product exceeds ``MAX_PIECE_PAIRS``.
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
        it), or GEOS failed (the message names the operand or ``"a, b"``).
    OverflowGeometryError
        The sum has a coordinate beyond the float64 range.
    ResourceLimitError
        The work exceeds ``MAX_PIECE_PAIRS`` (explicit decomposition) or
        ``MAX_CONVOLUTION_TESTS`` / ``MAX_CONVOLUTION_CROSSINGS`` (convolution).

    Notes
    -----
    Both operands are multiplied by one power of two, ``2**k``, chosen so that their
    largest |coordinate| lies in ``[2**19, 2**20)``; GEOS works on the scaled values and
    the result is multiplied by ``2**-k``. Both scalings are exact in binary floating
    point (barring gradual underflow below 2**-1022), so any magnitude from 2**-1074 to
    the float64 limit is computed as well as magnitudes near 1. Integer coordinates with
    at most 53 significant bits are exact, every convex piece sum is exact for them, and
    the union's crossing points are rounded once (relative error about 2**-52 of the
    result's extent). Fractions are rounded to float64 once, after the exact scale.

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


# --------------------------------------------------------------------------------------
# many sums at once


def _many_operands(X: Any) -> tuple[list, bool]:
    """The operands of a batch argument and whether it is a collection (else broadcast).

    A Ragged, an object array, or a list / tuple whose first item is a ring (2-D) or a
    shapely geometry (or None) is a collection; anything else is one operand."""
    if isinstance(X, Ragged):
        return X.to_list(), True
    if isinstance(X, np.ndarray):
        if X.dtype == object and X.ndim == 1:
            return list(X), True
        return [X], False
    if type(X).__module__.startswith("shapely"):
        return [X], False
    if isinstance(X, (list, tuple)):
        if len(X) == 0:
            return [], True
        x0 = X[0]
        if x0 is None or type(x0).__module__.startswith("shapely") or np.ndim(x0) == 2:
            return list(X), True
    return [X], False


def minkowski_sum_general_many(
    As: Any,
    Bs: Any,
    *,
    method: str = "auto",
    progress: Any = None,
    threads: int = 1,
) -> np.ndarray:
    """Non-convex Minkowski sums of many pairs of polygons in one call.

    Parameters
    ----------
    As, Bs : sequence of operands, or one operand
        Pairwise (equal counts) or one against many (one side a single operand, which is
        broadcast). An operand is anything :func:`minkowski_sum_general` takes; ``None``
        gives ``None``. A sequence whose items are rings or shapely geometries is a
        collection of operands (one sum per item), unlike in
        :func:`minkowski_sum_general`, where a list of polygons is one operand.
    method : {"auto", "decomposition", "convolution"}
        ``"auto"``: per pair, the decomposition, or the convolution when the pair has
        more than ``AUTO_MIN_SUMS`` piece sums and a cost model (piece sums against
        convolution segments and their crossings, see ``AUTO_COST_SUM``) estimates it
        at most half as costly, or when the pieces product exceeds ``MAX_PIECE_PAIRS``.
        The other values force one method for every pair.
    progress : bool or callable, optional
        ``True`` shows a tqdm bar (when tqdm is installed) over the pairs; a callable is
        called as ``progress(done, total)`` after each chunk of pairs.
    threads : int, default 1
        Worker threads of the batched convex sums.

    Returns
    -------
    numpy.ndarray of object
        ``result[k]`` is ``minkowski_sum_general(As[k], Bs[k])`` (a Polygon or
        MultiPolygon, the same set, normalized the same way; where ``"auto"`` picks
        the convolution, crossing points may differ in the last bit).

    Raises
    ------
    GeometryError
        As :func:`minkowski_sum_general`, naming the operand (``As[k]``, ``Bs[k]``).
    ShapeError
        Unequal counts, or neither argument is a collection.

    Notes
    -----
    Every distinct operand (the same Python object passed several times counts once) is
    read, validated and decomposed once. The convex sums of all piece pairs of all
    decomposed pairs are computed in one batched call on the caller's own coordinates
    (exact for integers up to 2**52). Each pair's sums are then scaled by the pair's
    power of two (as :func:`minkowski_sum_general` does) and unioned by GEOS: pairs of
    similar size together in one vectorized ``union_all``, pairs with more than
    ``GROUP_UNION_MAX`` sums in rounds that drop sums already covered (as
    :func:`minkowski_sum_general` does).

    Examples
    --------
    >>> import minkowski2d as mk
    >>> L = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    >>> sq = [(0, 0), (1, 0), (1, 1), (0, 1)]
    >>> out = mk.minkowski_sum_general_many([L, sq], L)
    >>> [g.area for g in out]
    [13.0, 8.0]
    """
    method = _options.choice(method, "method", ("auto", *SUM_METHODS))
    threads = _options.threads(threads)
    progress = _options.progress(progress)
    from ._containers import apply, boxed

    if boxed(As) or boxed(Bs):
        # GeoSeries / GeometryArray / object arrays: the same container kind out
        run = partial(minkowski_sum_general_many, method=method, threads=threads)
        return apply(run, As, Bs, progress=progress, convex=False)
    la, many_a = _many_operands(As)
    lb, many_b = _many_operands(Bs)
    if not many_a and not many_b:
        raise ShapeError(
            "give a collection of polygons for As or Bs (or use minkowski_sum_general)",
            argument="As, Bs",
        )
    if many_a and many_b and len(la) != len(lb):
        raise ShapeError(
            f"As has {len(la)} polygons but Bs has {len(lb)}; pairs need equal counts",
            argument="As, Bs",
        )
    P = len(la) if many_a else len(lb)
    out = np.empty(P, dtype=object)
    na = (lambda q: f"As[{q}]") if many_a else (lambda q: "a")
    nb = (lambda q: f"Bs[{q}]") if many_b else (lambda q: "b")
    ga = (lambda q: la[q]) if many_a else (lambda q: la[0])
    gb = (lambda q: lb[q]) if many_b else (lambda q: lb[0])

    cache: dict[int, _Prepared] = {}
    index: dict[int, int] = {}
    preps: list[_Prepared] = []

    def prep(obj: Any, name: str) -> int:
        key = id(obj)
        if key not in index:
            index[key] = len(preps)
            preps.append(_Prepared(obj, name))
        return index[key]

    todo, ia, ib, names = [], [], [], []
    for q in range(P):
        a, b = ga(q), gb(q)
        if a is None or b is None:
            continue
        i, j = prep(a, na(q)), prep(b, nb(q))
        if preps[i].flat and preps[j].flat:
            raise ShapeError(
                f"{na(q)}, {nb(q)}: both operands are points or segments: the sum has no area",
                argument=f"{na(q)}, {nb(q)}",
            )
        todo.append(q)
        ia.append(i)
        ib.append(j)
        names.append((na(q), nb(q)))
    del cache
    bar = _progress_bar(progress, len(todo))
    m = None if method == "auto" else method
    try:
        step = max(1, -(-len(todo) // 64)) if progress else max(1, len(todo))
        A_, B_ = np.asarray(ia, np.int64), np.asarray(ib, np.int64)
        for s in range(0, len(todo), step):
            sel = slice(s, s + step)
            res = _sums(preps, A_[sel], B_[sel], names[sel], m, threads=threads)
            for q, g in zip(todo[sel], res, strict=True):
                out[q] = g
            bar(len(res))
    finally:
        bar(None)
    return out


def _single(a: Any, b: Any, name_a: str, name_b: str, method: str | None = None) -> Any:
    """:func:`minkowski_sum_general` of one pair of a batch; errors name the batch
    operands (``As[k]``, ``Bs[k]``) instead of ``a`` and ``b``."""
    try:
        return minkowski_sum_general(a, b, method=method)
    except GeometryError as exc:
        arg = exc.argument or ""
        ren = {"a": name_a, "b": name_b, "a, b": f"{name_a}, {name_b}"}
        if arg in ren:
            raise exc.renamed(ren[arg]) from exc
        raise


def _progress_bar(progress: Any, total: int):
    """``update(n)`` (``None`` closes) for a tqdm bar, a callable, or nothing."""
    if progress is None or progress is False:
        return lambda n: None
    if callable(progress) and progress is not True:
        state = [0]

        def call(n):
            if n is not None:
                state[0] += n
                progress(state[0], total)

        return call
    try:
        from tqdm.auto import tqdm
    except ImportError:  # pragma: no cover - tqdm is optional
        return lambda n: None
    t = tqdm(total=total, unit="pair", leave=False)
    return lambda n: t.close() if n is None else t.update(n)


# --------------------------------------------------------------------------------------
# erosion


def _exact(v: float) -> Fraction:
    return Fraction(v)


def _erode_convex(A: np.ndarray, B: np.ndarray) -> Any:
    """Exact erosion of convex A by convex B (both normalized CCW; B may be flat).

    A's edge lines pushed inward by B's support in each edge's outward normal, then
    intersected in angle order (one deque pass). Every decision is exact (Python
    integers / Fractions); O(n + m).
    """
    import shapely

    n, m = len(A), len(B)
    Ae = [(_exact(x), _exact(y)) for x, y in A.tolist()]
    Be = [(_exact(x), _exact(y)) for x, y in B.tolist()]
    if n < 3:
        raise ShapeError("a: a convex polygon with area is needed")

    def cr(ux, uy, vx, vy):
        return ux * vy - uy * vx

    # support vertex of B for each edge of A: edges of both are in angle order from the
    # bottom-most vertex, so one pointer walks B while A's edges turn (a merge)
    def upper(dx, dy):
        return dy > 0 or (dy == 0 and dx > 0)

    def before(u, v):
        """True when direction u comes strictly before v in the angle order from +x."""
        hu, hv = upper(*u), upper(*v)
        if hu != hv:
            return hu
        return cr(u[0], u[1], v[0], v[1]) > 0

    Bedges = (
        [(Be[(j + 1) % m][0] - Be[j][0], Be[(j + 1) % m][1] - Be[j][1]) for j in range(m)]
        if m > 1
        else []
    )
    lines = []  # (point on line, direction): the half-plane is on the left
    j = 0
    for i in range(n):
        ex = Ae[(i + 1) % n][0] - Ae[i][0]
        ey = Ae[(i + 1) % n][1] - Ae[i][1]
        # advance j while B's edge j comes before A's edge i (support moves on)
        while m > 1 and j < m and before(Bedges[j], (ex, ey)):
            j += 1
        b = Be[j % m] if m > 1 else Be[0]
        lines.append(((Ae[i][0] - b[0], Ae[i][1] - b[1]), (ex, ey)))

    def inter(l1, l2):
        (p1, d1), (p2, d2) = l1, l2
        den = cr(d1[0], d1[1], d2[0], d2[1])
        t = Fraction(cr(p2[0] - p1[0], p2[1] - p1[1], d2[0], d2[1])) / den
        return (p1[0] + d1[0] * t, p1[1] + d1[1] * t)

    def side(ln, p):
        (q, d) = ln
        return cr(d[0], d[1], p[0] - q[0], p[1] - q[1])  # > 0 inside (left), 0 on the line

    # Half-plane intersection of lines sorted by angle (the deque algorithm). It is only
    # correct while the partial intersection stays bounded, so the four sides of a box
    # around A - B[0] (which contains the erosion) are merged into the angle order.
    xs = [p[0] - Be[0][0] for p in Ae]
    ys = [p[1] - Be[0][1] for p in Ae]
    x0, x1, y0, y1 = min(xs) - 1, max(xs) + 1, min(ys) - 1, max(ys) + 1
    box = [((x0, y0), (1, 0)), ((x1, y0), (0, 1)), ((x1, y1), (-1, 0)), ((x0, y1), (0, -1))]
    merged: list = []
    k = 0
    for ln in lines:
        while k < 4 and not before(ln[1], box[k][1]):
            merged.append(box[k])
            k += 1
        merged.append(ln)
    merged.extend(box[k:])

    dq: list = []
    for ln in merged:
        while len(dq) >= 2 and side(ln, inter(dq[-2], dq[-1])) < 0:
            dq.pop()
        while len(dq) >= 2 and side(ln, inter(dq[0], dq[1])) < 0:
            dq.pop(0)
        if dq:
            d0, d1 = dq[-1][1], ln[1]
            if cr(d0[0], d0[1], d1[0], d1[1]) == 0:
                if d0[0] * d1[0] + d0[1] * d1[1] < 0:  # antiparallel after popping
                    s = side(ln, dq[-1][0])
                    if s < 0:
                        return shapely.Polygon()  # the strip between them is empty
                    if s == 0:
                        return _on_line(ln, lines, side, cr)  # zero width: segment or point
                    return shapely.Polygon()
                # same direction: keep the more restrictive of the two
                if side(ln, dq[-1][0]) < 0:
                    dq.pop()
                else:
                    continue
        dq.append(ln)
    while len(dq) >= 3 and side(dq[0], inter(dq[-2], dq[-1])) < 0:
        dq.pop()
    while len(dq) >= 3 and side(dq[-1], inter(dq[0], dq[1])) < 0:
        dq.pop(0)
    if len(dq) < 3:
        return shapely.Polygon()
    pts = []
    for k in range(len(dq)):
        l1, l2 = dq[k], dq[(k + 1) % len(dq)]
        if cr(l1[1][0], l1[1][1], l2[1][0], l2[1][1]) == 0:
            s = side(l2, l1[0])
            if s < 0:
                return shapely.Polygon()
            return _on_line(l1, lines, side, cr)
        pts.append(inter(l1, l2))
    # A candidate without area (lines through one point, or all vertices on a line) can
    # survive the strict cleanup although other half-planes exclude it: decide those
    # exactly against every half-plane.
    uniq = list(dict.fromkeys(pts))
    p0 = uniq[0]
    far = max(uniq, key=lambda p: abs(p[0] - p0[0]) + abs(p[1] - p0[1]))
    if far == p0:
        if all(side(ln, p0) >= 0 for ln in lines):
            return _from_exact_points([p0])
        return shapely.Polygon()
    d = (far[0] - p0[0], far[1] - p0[1])
    if all(cr(d[0], d[1], p[0] - p0[0], p[1] - p0[1]) == 0 for p in uniq):
        return _on_line((p0, d), lines, side, cr)
    return _from_exact_points(pts)


def _on_line(ln, lines, side, cr) -> Any:
    """The erosion when it lies on the line ``ln``: clip the line by every half-plane."""
    import shapely

    (q, d) = ln
    lo, hi = None, None
    for other in lines:
        (p2, d2) = other
        # side(other, q + t d) = c0 + t c1 >= 0
        c1 = cr(d2[0], d2[1], d[0], d[1])
        c0 = side(other, q)
        if c1 == 0:
            if c0 < 0:
                return shapely.Polygon()
            continue
        t = Fraction(-c0) / c1
        if c1 > 0:
            lo = t if lo is None or t > lo else lo
        else:
            hi = t if hi is None or t < hi else hi
    if lo is None or hi is None or lo > hi:
        return shapely.Polygon()
    ends = [(q[0] + d[0] * t, q[1] + d[1] * t) for t in (lo, hi)]
    return _from_exact_points(ends)


def _to_float(v: Fraction) -> float:
    """The nearest double to an exact coordinate of a result."""
    try:
        f = float(v)
    except OverflowError:
        f = math.inf
    if math.isinf(f):
        raise OverflowGeometryError(
            "a, b: the result overflows float64 (a coordinate beyond ±1.8e308)",
            argument="a, b",
            hint="scale the input down; the result's coordinates must fit in float64",
        )
    return f


def _from_exact_points(pts: list) -> Any:
    """Point, LineString or Polygon from exact vertices in convex order (with repeats)."""
    import shapely

    uniq: list = []
    for p in pts:
        if p not in uniq:
            uniq.append(p)
    if len(uniq) == 1:
        return shapely.Point(_to_float(uniq[0][0]), _to_float(uniq[0][1]))
    from .convex import convex_hull

    h = convex_hull([(Fraction(x), Fraction(y)) for x, y in uniq])
    out = np.array([(_to_float(x), _to_float(y)) for x, y in h.tolist()], dtype=np.float64)
    if len(out) == 2:
        return shapely.LineString(out)
    return shapely.Polygon(out)


def minkowski_difference(a: Any, b: Any) -> Any:
    """Minkowski difference (erosion) ``A ⊖ B = {c : c + B ⊆ A}``.

    The set of translations ``c`` that put ``B`` wholly inside ``A``. This is **not**
    ``A ⊕ (−B)`` — that is :func:`minkowski2d.cspace_obstacle`, the translations where
    ``B`` *meets* ``A``. Erosion shrinks ``A``; ``A ⊕ (−B)`` grows it.

    Parameters
    ----------
    a : (n, 2) array_like, shapely Polygon / MultiPolygon, or a list of them
        The region to erode (holes allowed).
    b : (m, 2) array_like, shapely Polygon / MultiPolygon, point or segment
        The structuring element (holes allowed; a point or segment works).

    Returns
    -------
    shapely geometry
        * convex ``a`` (no holes), any ``b``: computed exactly (``c + B ⊆ A`` iff
          ``c + hull(B) ⊆ A``) in O(n + m log m) — a Polygon, or a LineString / Point
          when the erosion is a segment or a single point (``A ⊖ A`` is the point at
          the origin). This is the inner-fit polygon of a part in a convex sheet;
        * otherwise: ``A ⊖ B = complement(complement(A) ⊕ (−B))``, computed as
          ``G \\ ((F \\ A) ⊕ (−B))`` with the box ``G ⊇ bbox(A) ⊖ bbox(B)`` and the
          box ``F ⊇ G ⊕ B`` (see the notes), a Polygon or MultiPolygon (the closure of
          the erosion's interior: parts of zero width are not represented);
        * when ``B`` fits nowhere inside ``A``: an empty Polygon (``POLYGON EMPTY``,
          ``result.is_empty`` is True).

        Neither operand needs to contain the origin: ``A ⊖ (B + t) = (A ⊖ B) − t``.

    Raises
    ------
    SelfIntersectionError, ShapeError, EmptyGeometryError, NonFiniteError
        Bad input (``a`` must have area).
    GeometryError
        An integer coordinate has more than 53 significant bits, or GEOS failed.
    OverflowGeometryError
        The erosion has a coordinate beyond the float64 range (or lies wholly below
        2**-1022, where float64 cannot hold it to full precision).
    ResourceLimitError
        The inner sum exceeds the bounds of :func:`minkowski_sum_general`.

    Notes
    -----
    The erosion lies in ``bbox(A) ⊖ bbox(B)`` (``c + B ⊆ A`` puts ``c + bbox(B)`` in
    ``bbox(A)``). ``G`` is that box grown by a margin; every ``c + b`` with ``c ∈ G``
    lies in ``F``, so ``c`` misses the erosion exactly when ``c + b ∈ F \\ A`` for some
    ``b ∈ B``. Like the sum, the erosion is computed on operands scaled by one power of
    two (exact), so every magnitude representable in float64 works alike.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> sq = [(0, 0), (4, 0), (4, 4), (0, 4)]
    >>> mk.minkowski_difference(sq, [(0, 0), (1, 0), (1, 1), (0, 1)]).wkt
    'POLYGON ((0 0, 3 0, 3 3, 0 3, 0 0))'
    >>> mk.minkowski_difference(sq, [(0, 0), (4, 0), (4, 2)]).wkt
    'LINESTRING (0 0, 0 2)'
    >>> mk.minkowski_difference(sq, [(0, 0), (5, 0), (0, 5)]).is_empty
    True
    >>> L = [(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)]
    >>> mk.minkowski_difference(L, [(10, 10), (11, 10), (11, 11), (10, 11)]).area
    5.0
    >>> mk.cspace_obstacle(sq, [(0, 0), (1, 0), (1, 1), (0, 1)]).tolist()  # not the same
    [[-1, -1], [4, -1], [4, 4], [-1, 4]]
    """
    A, B = _operands((a, "a"), (b, "b"))
    if A.flat is not None:
        raise ShapeError(
            "a: the region to erode must have area (got a point or segment)", argument="a"
        )
    return _erode(A, B)


def _erode(A: _Operand, B: _Operand) -> Any:
    """``A ⊖ B`` of validated (scaled) operands."""
    ra = A.convex_ring
    if ra is not None:
        # c + B ⊆ A  ⟺  c + hull(B) ⊆ A for a convex A: the exact convex erosion
        from .convex import normalize

        na = np.asarray(normalize(ra), dtype=np.float64)
        return _erode_convex(na, B.hull())
    return _erode_general(A, B)


def _erode_general(A: _Operand, B: _Operand) -> Any:
    """``A ⊖ B = G \\ (R ⊕ (−B))`` for any A and B (neither needs to hold the origin), in
    one compiled call: ``G`` is the box ``bbox(A) ⊖ bbox(B)`` (exact corners), which
    holds the erosion because ``c + B ⊆ A`` puts ``c + bbox(B)`` inside ``bbox(A)``;
    ``R = F \\ A`` with ``F`` a box around ``bbox(A)``. A point ``c`` of ``G`` is outside
    the erosion iff some ``c + b`` (b in B) is outside A; that point lies in
    ``G + B ⊆ bbox(A) ⊆ F``, hence in ``R``, so ``c ∈ R ⊕ (−B)``. The exact overlay
    computes ``G`` minus the convolution of ``R`` and ``−B`` (holes of R that B cannot
    fit into filled first, see minkowski.hpp)."""
    from ._core import _ext

    preps = [_Wrapped(A), _Wrapped(B)]
    T = _table(preps, [False, False], "hertel-mehlhorn")
    xy, ro, po, pair_off, status, _ = _ext.general_sums(
        *T,
        np.array([0], np.int64),
        np.array([1], np.int64),
        _ext.METHOD_ERODE,
        MAX_CONVOLUTION_SEGMENTS,
        MAX_PIECE_PAIRS,
        MAX_CROSSINGS,
        1,
    )
    if status[0] != 0:
        raise _status_error(int(status[0]), A.name, B.name, "convolution")
    return geometries(xy, ro, po, pair_off)[0]
