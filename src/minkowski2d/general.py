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

from fractions import Fraction
from functools import partial
from typing import Any

import numpy as np

from ._coerce import as_array
from ._geos import area_parts, boundary, checked_polygonal
from .batch import Ragged, minkowski_sum_many
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

#: The operands are scaled by one power of two so that the largest |coordinate| lies in
#: ``[2**(SCALE_EXPONENT - 1), 2**SCALE_EXPONENT)`` while GEOS works on them.
SCALE_EXPONENT = 20
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


_boundary = boundary  # the GEOS boundary lives in _geos (shared with offset.py)


def _exponent(x: Any) -> int:
    """``e`` with ``2**(e-1) <= |x| < 2**e`` for a nonzero int or Fraction (exact)."""
    f = Fraction(x)
    p, q = abs(f.numerator), f.denominator
    e = p.bit_length() - q.bit_length()
    # p / q lies in (2**(e-1), 2**(e+1)): one exact comparison settles it
    return e + 1 if (p << max(-e, 0)) >= (q << max(e, 0)) else e


def _max_exponent(coords: np.ndarray) -> int | None:
    """frexp exponent of the largest finite |coordinate| (None if all are zero)."""
    c = np.abs(np.asarray(coords, dtype=np.float64)).ravel()
    c = c[np.isfinite(c)]
    if c.size == 0 or c.max() == 0:
        return None
    return int(np.frexp(c.max())[1])


# --------------------------------------------------------------------------------------
# input
#
# Reading an operand is two passes: _parse checks the types and keeps the raw
# coordinates (no GEOS call), _build scales them by 2**k and validates them with GEOS.
# The exponent k is chosen from both operands together (the sum scales by the same
# factor), so GEOS never sees coordinates whose products over- or underflow.


class _Operand:
    """A validated operand: a shapely Polygon/MultiPolygon with positive area, or a
    degenerate convex set (point or segment) held as a (k, 2) float64 array."""

    __slots__ = ("geom", "flat", "name")

    def __init__(self, geom: Any, flat: np.ndarray | None, name: str) -> None:
        self.geom = geom
        self.flat = flat
        self.name = name

    @property
    def convex_ring(self) -> np.ndarray | None:
        """The ring of a single convex polygon without holes (or the flat set), else None."""
        if self.flat is not None:
            return self.flat
        g = self.geom
        if g.geom_type != "Polygon" or len(g.interiors):
            return None
        import shapely

        from ._dispatch import check_convex

        ring = shapely.get_coordinates(g.exterior)[:-1]
        return ring if check_convex(ring, self.name) else None

    def hull(self) -> np.ndarray:
        """Convex hull of the operand (exact, normalized)."""
        if self.flat is not None:
            return self.flat
        import shapely

        from .convex import convex_hull

        return np.asarray(convex_hull(shapely.get_coordinates(self.geom)), dtype=np.float64)


class _Raw:
    """A parsed, not yet validated operand: a shapely Polygon/MultiPolygon (``geom``),
    float64 coordinates (``coords``), exact coordinates (``exact``: Fractions, rounded
    only after the exact scale) or a collection of them (``items``)."""

    __slots__ = ("kind", "value", "name")

    def __init__(self, kind: str, value: Any, name: str) -> None:
        self.kind = kind
        self.value = value
        self.name = name

    def exponent(self) -> int | None:
        """frexp exponent of the largest |coordinate| (None when all are zero)."""
        import shapely

        if self.kind == "geom":
            return _max_exponent(shapely.get_coordinates(self.value))
        if self.kind == "coords":
            return _max_exponent(self.value)
        if self.kind == "exact":
            es = [_exponent(v) for p in self.value for v in p if v != 0]
            return max(es) if es else None
        es = [e for item in self.value if (e := item.exponent()) is not None]
        return max(es) if es else None


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


def _scale_exponent(*raws: _Raw) -> int:
    """The k of the common scale 2**k: the largest |coordinate| of all operands lands in
    [2**(SCALE_EXPONENT - 1), 2**SCALE_EXPONENT). 0 when every coordinate is zero."""
    es = [e for r in raws if (e := r.exponent()) is not None]
    return SCALE_EXPONENT - max(es) if es else 0


def _ldexp_geom(geom: Any, k: int) -> Any:
    """``geom`` with every coordinate times 2**k (exact unless it under/overflows)."""
    import shapely

    if k == 0:
        return geom
    return shapely.transform(geom, lambda c: np.ldexp(c, k))


def _build(raw: _Raw, k: int) -> _Operand:
    """Scale a parsed operand by 2**k and validate it (GEOS runs on scaled values)."""
    import shapely

    name = raw.name
    if raw.kind == "items":
        geoms = []
        for item in raw.value:
            op = _build(item, k)
            if op.flat is not None:
                # uniting would drop it, yet {p} ⊕ B has area: refuse rather than lose it
                raise ShapeError(
                    f"{item.name}: a point or segment in a collection of polygons "
                    "(every member of a collection must have area)",
                    argument=item.name,
                    hint="pass the point or segment as an operand of its own",
                )
            geoms.append(op.geom)
        with _boundary(name, "uniting the polygons of the collection"):
            u = shapely.get_parts(shapely.union_all(geoms))
        polys = u[shapely.get_type_id(u) == 3]
        if len(polys) == 0:
            raise ShapeError(f"{name}: the polygons have no area", argument=name)
        g = polys[0] if len(polys) == 1 else shapely.multipolygons(polys)
        return _Operand(_check_geom(g, name), None, name)
    if raw.kind == "geom":
        c = shapely.get_coordinates(raw.value)
        if not np.isfinite(c).all():
            raise NonFiniteError(f"{name}: a coordinate is not finite", argument=name)
        return _Operand(_check_geom(_ldexp_geom(raw.value, k), name), None, name)
    if raw.kind == "exact":
        two = Fraction(2) ** k
        ring = np.array([(float(x * two), float(y * two)) for x, y in raw.value])
    else:
        ring = np.ldexp(raw.value, k)
    if _has_area(ring):
        # not all on one line: a polygon (GEOS validates it); no hull needed
        with _boundary(name, "building the polygon"):
            poly = shapely.Polygon(ring)
        return _Operand(_check_geom(poly, name), None, name)
    from .convex import convex_hull

    hull = np.asarray(convex_hull(ring), dtype=np.float64)
    if len(hull) <= 2:
        # a point, a segment, or collinear points: a degenerate convex set
        return _Operand(None, hull, name)
    with _boundary(name, "building the polygon"):
        poly = shapely.Polygon(ring)
    return _Operand(_check_geom(poly, name), None, name)


def _has_area(ring: np.ndarray) -> bool:
    """True when the finite points ``ring`` do not all lie on one line (exact signs)."""
    from ._core import _ext

    r = np.ascontiguousarray(ring, dtype=np.float64)
    if r.ndim != 2 or len(r) < 3 or not np.isfinite(r).all():
        return False
    far = np.flatnonzero((r != r[0]).any(axis=1))
    if len(far) == 0:
        return False
    p = np.broadcast_to(r[0], r.shape).copy()
    q = np.broadcast_to(r[far[0]], r.shape).copy()
    return bool(np.any(_ext.orient_f(p, q, r)))


def _operands(*pairs: tuple[Any, str]) -> tuple[int, list[_Operand]]:
    """Parse the operands, choose their common scale 2**k, build them scaled."""
    raws = [_parse(obj, name) for obj, name in pairs]
    k = _scale_exponent(*raws)
    return k, [_build(r, k) for r in raws]


def _check_geom(geom: Any, name: str) -> Any:
    """Validate a Polygon / MultiPolygon and orient it (see :func:`_geos.checked_polygonal`)."""
    return checked_polygonal(
        geom, name, hint="the boundary must not cross itself; holes must lie inside"
    )


def _flat_geom(flat: np.ndarray) -> Any:
    import shapely

    if len(flat) == 1:
        return shapely.Point(flat[0])
    return shapely.LineString(flat)


def _unscale(geom: Any, k: int, argument: str) -> Any:
    """Scale a result back by 2**-k; OverflowGeometryError if a coordinate overflows, or
    if the whole result lies below 2**-1022 and gradual underflow rounds it.

    The scale back is exact except where a coordinate falls below 2**-1022 (gradual
    underflow rounds it to a multiple of 2**-1074); while the result's largest
    |coordinate| is 2**-1022 or more, that is at most 2**-53 of its extent."""
    import shapely

    if k == 0 or geom.is_empty:
        return geom
    with np.errstate(over="ignore", under="ignore"):
        out = shapely.transform(geom, lambda c: np.ldexp(c, -k))
    c = shapely.get_coordinates(out)
    if not np.isfinite(c).all():
        raise OverflowGeometryError(
            f"{argument}: the result overflows float64 (a coordinate beyond ±1.8e308)",
            argument=argument,
            hint="scale the input down; the result's coordinates must fit in float64",
        )
    if np.abs(c).max() < 2.0**-1022 and not (np.ldexp(c, k) == shapely.get_coordinates(geom)).all():
        raise OverflowGeometryError(
            f"{argument}: the result underflows float64 (all its coordinates are below "
            "2**-1022 and would be rounded to multiples of 2**-1074)",
            argument=argument,
            hint="scale the input up; the result's coordinates must be float64 normals",
        )
    return out


def _result(geom: Any) -> Any:
    """Polygon or MultiPolygon, exterior CCW and holes CW; empty Polygon if nothing."""
    import shapely

    g = area_parts(geom)
    if g.is_empty:
        return g
    # drop the collinear vertices the union leaves, start each ring at a canonical vertex
    g = shapely.normalize(shapely.simplify(g, 0.0))
    return shapely.orient_polygons(g)


# --------------------------------------------------------------------------------------
# decomposition


def _pieces(op: _Operand, method: str = "hertel-mehlhorn") -> Ragged:
    if op.flat is not None:
        return Ragged(op.flat, np.array([0, len(op.flat)], np.int64))
    from ._decompose import decompose

    coords, off = decompose(op.geom, merge=method == "hertel-mehlhorn")
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
    if method not in DECOMPOSITIONS:
        raise ValueError(f"method must be one of {DECOMPOSITIONS}, got {method!r}")
    k, (P,) = _operands((poly, "poly"))
    with _boundary("poly", "decomposing the polygon"):
        R = _pieces(P, method)
    if k == 0:
        return R
    # the pieces' vertices are input vertices: scaling back is exact and cannot overflow
    return Ragged(np.ldexp(np.asarray(R.coords, dtype=np.float64), -k), R.offsets)


def _ragged_polygons(coords: np.ndarray, off: np.ndarray) -> np.ndarray:
    """shapely Polygons of (closed-up) rings; every ring has three or more vertices."""
    import shapely

    n = np.diff(off)
    P = len(n)
    # insert the closing vertex after each ring
    total = len(coords) + P
    idx = np.arange(total) - np.repeat(np.arange(P), n + 1)
    ends = np.cumsum(n + 1) - 1
    idx[ends] = off[:-1]
    ring_id = np.repeat(np.arange(P), n + 1)
    return shapely.polygons(shapely.linearrings(coords[idx], indices=ring_id))


def _union_rounds(sums: Ragged, first: int) -> Any:
    """Union of many convex polygons, in rounds that drop what is already covered."""
    import shapely

    coords = np.asarray(sums.coords, dtype=np.float64)
    off = sums.offsets
    n = np.diff(off)
    poly_sel = n >= 3
    if not poly_sel.all():
        # degenerate sums (only when both operands are flat): they have no area
        keep = np.flatnonzero(poly_sel)
        if len(keep) == 0:
            return shapely.Polygon()
        sums = Ragged.from_list([sums[k] for k in keep])
        coords, off = np.asarray(sums.coords, dtype=np.float64), sums.offsets
    g = _ragged_polygons(coords, off)
    P = len(g)
    if P <= 64:
        return shapely.union_all(g)
    area = shapely.area(g)
    lo = coords.min(axis=0)
    hi = coords.max(axis=0)
    c = coords - (lo + hi) / 2
    reach = np.maximum.reduceat((c * c).sum(axis=1), off[:-1])
    k = min(max(first, 16), P)
    head = np.argpartition(-area, k - 1)[:k] if k < P else np.arange(P)
    U = shapely.union_all(g[head])
    mask = np.ones(P, bool)
    mask[head] = False
    rest = np.flatnonzero(mask)
    step = 2 * k
    while len(rest) > 4 * k:
        shapely.prepare(U)
        rest = rest[~shapely.contains_properly(U, g[rest])]
        if len(rest) <= 4 * k:
            break
        m = min(step, len(rest))
        top = np.argpartition(-reach[rest], m - 1)[:m]
        sel = np.zeros(len(rest), bool)
        sel[top] = True
        U = shapely.union_all(np.concatenate([[U], g[rest[sel]]]))
        rest = rest[~sel]
        step *= 2
    if len(rest):
        shapely.prepare(U)
        rest = rest[~shapely.contains_properly(U, g[rest])]
        U = shapely.union_all(np.concatenate([[U], g[rest]]))
    return U


def _all_pairs(RA: Ragged, RB: Ragged) -> Ragged:
    """``RA[i] ⊕ RB[j]`` for every pair, in one batched call."""
    na, nb = len(RA), len(RB)
    la, lb = RA.lengths, RB.lengths
    # As: piece i repeated nb times; Bs: all pieces of B, na times
    ia = np.repeat(np.arange(na), nb)
    ib = np.tile(np.arange(nb), na)
    a_len = la[ia]
    b_len = lb[ib]
    a_off = np.concatenate(([0], np.cumsum(a_len)))
    b_off = np.concatenate(([0], np.cumsum(b_len)))
    a_idx = np.arange(a_off[-1]) - np.repeat(a_off[:-1] - RA.offsets[ia], a_len)
    b_idx = np.arange(b_off[-1]) - np.repeat(b_off[:-1] - RB.offsets[ib], b_len)
    As = Ragged(RA.coords[a_idx], a_off)
    Bs = Ragged(RB.coords[b_idx], b_off)
    return minkowski_sum_many(As, Bs)


def _sum_decomposition(A: _Operand, B: _Operand, decomposition: str, switch: bool) -> Any:
    """The sum by convex pieces; None when the pieces product exceeds MAX_PIECE_PAIRS
    and ``switch`` lets the caller use the convolution instead."""
    import shapely

    from .convex import minkowski_sum

    ra, rb = A.convex_ring, B.convex_ring
    if ra is not None and rb is not None:
        s = np.asarray(minkowski_sum(ra, rb), dtype=np.float64)
        if len(s) < 3:
            raise ShapeError("both operands are points or segments: the sum has no area")
        return shapely.Polygon(s)
    RA = _pieces(A, decomposition)
    RB = _pieces(B, decomposition)
    pairs = len(RA) * len(RB)
    if pairs > MAX_PIECE_PAIRS:
        if switch:
            return None
        raise ResourceLimitError(
            f"{A.name}, {B.name}: {len(RA)} x {len(RB)} convex pieces give {pairs} piece "
            f"sums, above the limit MAX_PIECE_PAIRS = {MAX_PIECE_PAIRS}",
            argument=f"{A.name}, {B.name}",
            hint="leave method unset (it switches to the convolution), or simplify the polygons",
        )
    sums = _all_pairs(RA, RB)
    return _union_rounds(sums, len(RA) + len(RB))


# --------------------------------------------------------------------------------------
# reduced convolution


def _rings(op: _Operand) -> list[np.ndarray]:
    """Boundary rings with the interior on their left (exteriors CCW, holes CW)."""
    import shapely

    if op.flat is not None:
        f = op.flat
        return [f if len(f) == 1 else np.vstack([f, f[::-1][1:-1]]) if len(f) > 2 else f]
    rings = shapely.get_rings(shapely.get_parts(op.geom))
    out = []
    for r in rings:
        c = shapely.get_coordinates(r)[:-1]
        out.append(c)
    return out


def _cross(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    return u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]


def _rc_segments(P: np.ndarray, Q: np.ndarray) -> np.ndarray:
    """Reduced-convolution segments ``e + v``: ``e`` an edge of ring P, ``v`` a convex
    vertex of ring Q whose (closed) normal cone holds the normal of ``e``.

    A segment with ``v`` any point of ``Q`` lies in the sum and has the sum just left of
    it, so the tests are made inclusive (a superset is harmless, a missing segment not).
    """
    if len(P) < 2 or len(Q) < 1:
        return np.empty((0, 2, 2))
    e = np.roll(P, -1, 0) - P
    P1 = np.roll(P, -1, 0)
    if len(Q) == 1:
        return np.stack([P + Q[0], P1 + Q[0]], 1)
    f = np.roll(Q, -1, 0) - Q
    fin = np.roll(f, 1, 0)
    scale = np.abs(e).max() * np.abs(f).max() * CONE_SLACK
    turn = _cross(fin, f)
    k = np.flatnonzero(turn >= -scale)
    c1 = _cross(fin[k][None, :], e[:, None]) >= -scale
    c2 = _cross(e[:, None], f[k][None, :]) >= -scale
    # a convex vertex's cone is less than a half-turn: both tests together select it
    jj, kk = np.nonzero(c1 & c2)
    # endpoints as vertex sums (not start + edge), so that segments meet exactly
    return np.stack([P[jj] + Q[k[kk]], P1[jj] + Q[k[kk]]], 1)


def _convolution_faces(segs: np.ndarray) -> tuple[Any, np.ndarray]:
    """Polygonized faces of the segments' arrangement, and for each face whether one of
    its boundary edges carries a segment with the face on its left."""
    import shapely

    L = np.linalg.norm(segs[:, 1] - segs[:, 0], axis=1)
    segs = segs[L > 0]
    lines = shapely.linestrings(segs)
    noded = shapely.get_parts(shapely.node(shapely.multilinestrings(lines)))
    ec = shapely.get_coordinates(noded).reshape(-1, 2, 2)
    faces = shapely.get_parts(shapely.polygonize(noded))
    if len(faces) == 0:
        return faces, np.zeros(0, bool)
    # provenance: the segments each noded edge lies on, and their directions
    scale = max(np.abs(segs).max(), 1.0)
    tol = scale * PROVENANCE_TOLERANCE
    mid = (ec[:, 0] + ec[:, 1]) / 2
    tree = shapely.STRtree(lines)
    ei, si = tree.query(shapely.points(mid), predicate="dwithin", distance=tol)
    de = ec[ei, 1] - ec[ei, 0]
    ds = segs[si, 1] - segs[si, 0]
    norm = np.linalg.norm(de, axis=1) * np.linalg.norm(ds, axis=1)
    par = np.abs(_cross(de, ds)) <= PROVENANCE_TOLERANCE * norm
    dot = (de * ds).sum(axis=1)
    fwd = np.zeros(len(ec), bool)
    bwd = np.zeros(len(ec), bool)
    fwd[ei[par & (dot > 0)]] = True
    bwd[ei[par & (dot < 0)]] = True
    # directed edges that carry a segment in their own direction
    dkeys = np.concatenate([ec[fwd].reshape(-1, 4), ec[bwd][:, ::-1].reshape(-1, 4)]) + 0.0
    faces = shapely.orient_polygons(faces)
    rings, ridx = shapely.get_rings(faces, return_index=True)
    rc, rci = shapely.get_coordinates(rings, return_index=True)
    nxt = np.arange(1, len(rc) + 1)
    valid = np.ones(len(rc), bool)
    last = np.flatnonzero(np.diff(rci, append=-1) != 0)  # closing vertex of each ring
    valid[last] = False
    nxt[last] = last
    fkeys = np.concatenate([rc, rc[np.minimum(nxt, len(rc) - 1)]], axis=1)[valid] + 0.0
    fface = ridx[rci[valid]]
    v = np.dtype((np.void, 32))
    hit = np.isin(
        np.ascontiguousarray(fkeys).view(v).ravel(), np.ascontiguousarray(dkeys).view(v).ravel()
    )
    inside = np.bincount(fface[hit], minlength=len(faces)) > 0
    return faces, inside


def _convolution_limit(A: _Operand, B: _Operand, what: str, count: int, limit: int, name: str):
    return ResourceLimitError(
        f"{A.name}, {B.name}: the convolution would need at least {count} {what}, above "
        f"the limit {name} = {limit}",
        argument=f"{A.name}, {B.name}",
        hint="use method='decomposition' (or leave method unset), or simplify the polygons",
    )


def _count_crossings(segs: np.ndarray, limit: int) -> int:
    """Pairs of distinct segments that meet, counted in chunks; stops above ``limit``.

    A chunk of ``c`` segments yields at most ``c * len(segs)`` pairs, so ``c`` is chosen
    to keep that near ``limit`` (the count itself never needs more memory than that)."""
    import shapely

    lines = shapely.linestrings(segs)
    tree = shapely.STRtree(lines)
    step = max(1, min(4096, limit // max(len(lines), 1)))
    total = 0
    for i in range(0, len(lines), step):
        chunk = lines[i : i + step]
        total += len(tree.query(chunk, predicate="intersects")[0]) - len(chunk)
        if total // 2 > limit:
            break
    return total // 2


def _sum_convolution(A: _Operand, B: _Operand) -> Any:
    import shapely

    ra, rb = _rings(A), _rings(B)
    tests = 2 * sum(len(p) * len(q) for p in ra for q in rb)
    if tests > MAX_CONVOLUTION_TESTS:
        raise _convolution_limit(
            A, B, "edge-vertex tests", tests, MAX_CONVOLUTION_TESTS, "MAX_CONVOLUTION_TESTS"
        )
    segs = [_rc_segments(p, q) for p in ra for q in rb] + [
        _rc_segments(q, p) for p in ra for q in rb
    ]
    segs = np.concatenate(segs)
    segs = segs[(segs[:, 1] != segs[:, 0]).any(axis=1)]
    crossings = _count_crossings(segs, MAX_CONVOLUTION_CROSSINGS)
    if crossings > MAX_CONVOLUTION_CROSSINGS:
        raise _convolution_limit(
            A,
            B,
            "segment crossings",
            crossings,
            MAX_CONVOLUTION_CROSSINGS,
            "MAX_CONVOLUTION_CROSSINGS",
        )
    faces, inside = _convolution_faces(segs)
    cand = np.flatnonzero(~inside)
    if len(cand):
        # hole filter: a candidate face is inside the sum when A meets x − B
        ga = _op_geom(A)
        nb = shapely.affinity.scale(_op_geom(B), -1.0, -1.0, origin=(0, 0))
        shapely.prepare(ga)
        x = shapely.get_coordinates(shapely.point_on_surface(faces[cand]))
        for q, (px, py) in zip(cand, x, strict=True):
            if ga.intersects(shapely.affinity.translate(nb, px, py)):
                inside[q] = True
    if not inside.any():
        return shapely.Polygon()
    return shapely.coverage_union_all(faces[inside])


def _op_geom(op: _Operand) -> Any:
    return op.geom if op.flat is None else _flat_geom(op.flat)


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
    if method is not None and method not in SUM_METHODS:
        raise ValueError(f"method must be one of {SUM_METHODS}, got {method!r}")
    if decomposition not in DECOMPOSITIONS:
        raise ValueError(f"decomposition must be one of {DECOMPOSITIONS}, got {decomposition!r}")
    k, (A, B) = _operands((a, "a"), (b, "b"))
    with _boundary("a, b", "computing the sum"):
        r = _result(_sum(A, B, method, decomposition))
    return _unscale(r, k, "a, b")


def _sum(A: _Operand, B: _Operand, method: str | None, decomposition: str) -> Any:
    """``A ⊕ B`` of validated (scaled) operands, not yet cleaned by :func:`_result`."""
    if A.flat is not None and B.flat is not None:
        raise ShapeError(
            "both operands are points or segments: the sum has no area", argument="a, b"
        )
    if method == "convolution":
        return _sum_convolution(A, B)
    r = _sum_decomposition(A, B, decomposition, switch=method is None)
    if r is not None:
        return r
    try:
        return _sum_convolution(A, B)
    except ResourceLimitError as exc:
        raise ResourceLimitError(
            f"{A.name}, {B.name}: both methods exceed their bounds: the decomposition "
            f"has more than MAX_PIECE_PAIRS = {MAX_PIECE_PAIRS} piece sums, and {exc}",
            argument=f"{A.name}, {B.name}",
            hint="simplify the polygons (fewer reflex vertices)",
        ) from exc


# --------------------------------------------------------------------------------------
# many sums at once

#: ``minkowski_sum_general_many``: a pair whose piece sums number at most this many is
#: unioned together with other pairs of similar size in one vectorized GEOS call
#: (``shapely.union_all(..., axis=1)``); larger ones go through the union in rounds.
GROUP_UNION_MAX = 256
#: Pairs are processed in chunks of at most this many piece sums (bounds the memory and
#: paces the progress bar).
CHUNK_SUMS = 1 << 16


class _Prepared:
    """One operand of a batch, validated and decomposed once: its exponent ``e`` (frexp
    of the largest |coordinate|, None when all are zero), its convex pieces in the
    caller's own units (float64, input vertices bit for bit), whether it is flat, and
    the operand itself (built at its own scale) for the per-pair fallback."""

    __slots__ = ("e", "pieces", "flat", "op", "k", "obj")

    def __init__(self, obj: Any, name: str) -> None:
        self.obj = obj
        raw = _parse(obj, name)
        self.e = raw.exponent()
        self.k = SCALE_EXPONENT - self.e if self.e is not None else 0
        self.op = _build(raw, self.k)
        self.flat = self.op.flat is not None
        ring = self.op.convex_ring
        with _boundary(name, "decomposing the polygon"):
            R = (
                Ragged(ring, np.array([0, len(ring)], np.int64))
                if ring is not None
                else _pieces(self.op)
            )
        self.pieces = Ragged(np.ldexp(np.asarray(R.coords, np.float64), -self.k), R.offsets)


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
    if method not in ("auto",) + SUM_METHODS:
        raise ValueError(f"method must be one of {('auto',) + SUM_METHODS}, got {method!r}")
    if isinstance(threads, bool) or not isinstance(threads, int) or threads < 1:
        raise ValueError(f"threads must be a positive int, got {threads!r}")
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

    # read every distinct operand once
    cache: dict[int, _Prepared] = {}

    def prep(obj: Any, name: str) -> _Prepared:
        key = id(obj)
        p = cache.get(key)
        if p is None:
            p = cache[key] = _Prepared(obj, name)
        return p

    todo = []
    for q in range(P):
        a, b = ga(q), gb(q)
        if a is None or b is None:
            continue
        pa, pb = prep(a, na(q)), prep(b, nb(q))
        if pa.flat and pb.flat:
            raise ShapeError(
                f"{na(q)}, {nb(q)}: both operands are points or segments: the sum has no area",
                argument=f"{na(q)}, {nb(q)}",
            )
        todo.append((q, pa, pb))
    bar = _progress_bar(progress, len(todo))
    try:
        fallback = []
        batch: list = []
        sums_in_batch = 0
        for item in todo:
            q, pa, pb = item
            npairs = len(pa.pieces) * len(pb.pieces)
            if method == "convolution" or npairs > MAX_PIECE_PAIRS:
                if method == "decomposition":
                    _sum_decomposition(pa.op, pb.op, "hertel-mehlhorn", switch=False)
                fallback.append(item)
                continue
            if method == "auto" and npairs > AUTO_MIN_SUMS and not (pa.flat or pb.flat):
                conv = _convolution_if_cheaper(pa, pb, npairs, f"{na(q)}, {nb(q)}")
                if conv is not None:
                    out[q] = conv
                    bar(1)
                    continue
            batch.append(item)
            sums_in_batch += npairs
            if sums_in_batch >= CHUNK_SUMS:
                _many_decomposition(batch, out, na, nb, threads)
                bar(len(batch))
                batch, sums_in_batch = [], 0
        if batch:
            _many_decomposition(batch, out, na, nb, threads)
            bar(len(batch))
        for q, _pa, _pb in fallback:
            m = "convolution" if method == "convolution" else None
            out[q] = _single(ga(q), gb(q), na(q), nb(q), method=m)
            bar(1)
    finally:
        bar(None)
    return out


#: ``method="auto"`` of :func:`minkowski_sum_general_many`: a pair with more than this
#: many piece sums is checked for the convolution being cheaper. The cost model (speed
#: only, both methods give the same set) counts, for the decomposition,
#: ``AUTO_COST_SUM`` seconds per piece sum, and for the convolution ``AUTO_COST_FIXED``
#: plus ``AUTO_COST_SEGMENT`` per reduced-convolution segment and per pair of segments
#: that meet (counted with an STRtree, stopping as soon as the convolution cannot win).
#: Calibrated on gardeyn0/1/3 samples and stars (a per-sum cost of 25 µs chose the
#: convolution too rarely: gardeyn0 1.3 s, 100 µs: 0.56 s): curved parts have many
#: convex pieces (a concave arc needs one per edge) but few crossings (an 81-vertex
#: gardeyn0 part with itself: 2 304 sums, 168 segments, 170 crossings, 88 ms against
#: 21 ms); stars have many crossings (32-stars: 1 089 sums, 27 808 crossings, 39 ms
#: against 2.7 s), and they stay with the decomposition.
AUTO_MIN_SUMS = 256
AUTO_COST_SUM = 1e-4
AUTO_COST_FIXED = 5e-3
AUTO_COST_SEGMENT = 5e-5
#: The convolution is taken when estimated at most this fraction of the decomposition.
AUTO_MARGIN = 1.0


def _convolution_if_cheaper(pa: _Prepared, pb: _Prepared, npairs: int, name: str) -> Any:
    """The sum by the convolution when the cost model prefers it, else None."""
    budget = AUTO_MARGIN * AUTO_COST_SUM * npairs - AUTO_COST_FIXED
    if budget <= 0:
        return None
    k = SCALE_EXPONENT - max(pa.e, pb.e)
    A = _Operand(_ldexp_geom(pa.op.geom, k - pa.k), None, pa.op.name)
    B = _Operand(_ldexp_geom(pb.op.geom, k - pb.k), None, pb.op.name)
    with _boundary(name, "estimating the cost of the convolution"):
        ra, rb = _rings(A), _rings(B)
        if 2 * sum(len(p) * len(q) for p in ra for q in rb) > MAX_CONVOLUTION_TESTS:
            return None
        segs = np.concatenate(
            [_rc_segments(p, q) for p in ra for q in rb]
            + [_rc_segments(q, p) for p in ra for q in rb]
        )
        segs = segs[(segs[:, 1] != segs[:, 0]).any(axis=1)]
        room = int(budget / AUTO_COST_SEGMENT) - len(segs)
        if room <= 0:
            return None
        if _count_crossings(segs, room) > room:
            return None
        r = _result(_sum_convolution(A, B))
    return _unscale(r, k, name)


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


def _many_decomposition(batch: list, out: np.ndarray, na, nb, threads: int) -> None:
    """Sums of the pairs ``(q, prepared a, prepared b)`` by pieces, into ``out[q]``."""
    import shapely

    from ._core import _ext

    # one coordinate array holding every operand's pieces
    ops: dict[int, tuple[int, _Prepared]] = {}
    chunks = []
    base = 0
    pbase = 0
    for _, pa, pb in batch:
        for p in (pa, pb):
            if id(p) not in ops:
                ops[id(p)] = (pbase, base, p)
                chunks.append(p.pieces)
                base += len(p.pieces.coords)
                pbase += len(p.pieces)
    C = np.ascontiguousarray(np.concatenate([np.asarray(r.coords, np.float64) for r in chunks]))
    lo = np.concatenate([r.offsets[:-1] + s for r, s in zip(chunks, _starts(chunks), strict=True)])
    hi = np.concatenate([r.offsets[1:] + s for r, s in zip(chunks, _starts(chunks), strict=True)])
    # piece index ranges of every pair; pair q has na_q * nb_q sums
    a0 = np.array([ops[id(pa)][0] for _, pa, _ in batch], np.int64)
    b0 = np.array([ops[id(pb)][0] for _, _, pb in batch], np.int64)
    ca = np.array([len(pa.pieces) for _, pa, _ in batch], np.int64)
    cb = np.array([len(pb.pieces) for _, _, pb in batch], np.int64)
    cnt = ca * cb
    pair_of = np.repeat(np.arange(len(batch)), cnt)
    local = np.arange(cnt.sum()) - np.repeat(np.cumsum(cnt) - cnt, cnt)
    ia = a0[pair_of] + local // cb[pair_of]
    ib = b0[pair_of] + local % cb[pair_of]
    coords, off, code, *_ = _ext.sum_batch_f(C, lo[ia], hi[ia], C, lo[ib], hi[ib], threads)
    if code:
        # a range or overflow problem: the one-pair path computes it or raises
        for q, pa, pb in batch:
            out[q] = _single(pa.obj, pb.obj, na(q), nb(q))
        return
    # each pair's common scale, as in minkowski_sum_general
    ks = np.array(
        [SCALE_EXPONENT - max(e for e in (pa.e, pb.e) if e is not None) for _, pa, pb in batch],
        np.int64,
    )
    nv = np.diff(off)
    kv = np.repeat(ks[pair_of], nv)
    with np.errstate(over="ignore", under="ignore"):
        scaled = np.ldexp(coords, kv[:, None])
    names = [f"{na(q)}, {nb(q)}" for q, _, _ in batch]
    with _boundary(names[0] if len(batch) == 1 else "As, Bs", "uniting the piece sums"):
        polys = _ragged_polygons(scaled, off)
        first = np.cumsum(cnt) - cnt
        res = np.empty(len(batch), dtype=object)
        single = cnt == 1
        res[single] = polys[first[single]]
        # pairs of similar size together: one vectorized union per size class
        mid = np.flatnonzero((cnt > 1) & (cnt <= GROUP_UNION_MAX))
        if len(mid):
            width = 1 << np.ceil(np.log2(cnt[mid])).astype(np.int64)
            for w in np.unique(width):
                sel = mid[width == w]
                grid = np.full((len(sel), int(w)), None, dtype=object)
                rows = np.repeat(np.arange(len(sel)), cnt[sel])
                cols = np.arange(cnt[sel].sum()) - np.repeat(
                    np.cumsum(cnt[sel]) - cnt[sel], cnt[sel]
                )
                grid[rows, cols] = polys[np.repeat(first[sel], cnt[sel]) + cols]
                res[sel] = shapely.union_all(grid, axis=1)
        for t in np.flatnonzero(cnt > GROUP_UNION_MAX):
            s0, c = int(first[t]), int(cnt[t])
            res[t] = _union_rounds_polys(polys[s0 : s0 + c])
        res = _result_many(res)
    for k in np.unique(ks):
        sel = np.flatnonzero(ks == k)
        for t, g in zip(sel, _unscale_many(res[sel], int(k), [names[t] for t in sel]), strict=True):
            out[batch[t][0]] = g


def _union_rounds_polys(g: np.ndarray) -> Any:
    """:func:`_union_rounds` of an array of convex shapely polygons."""
    import shapely

    coords, idx = shapely.get_coordinates(shapely.get_exterior_ring(g), return_index=True)
    n = np.bincount(idx, minlength=len(g)) - 1  # without the closing vertex
    keep = np.ones(len(coords), bool)
    keep[np.cumsum(n + 1) - 1] = False
    off = np.concatenate(([0], np.cumsum(n)))
    return _union_rounds(Ragged(coords[keep], off), 2 * int(np.sqrt(len(g))) + 1)


def _starts(chunks: list) -> np.ndarray:
    n = np.array([len(r.coords) for r in chunks], np.int64)
    return np.cumsum(n) - n


def _result_many(geoms: np.ndarray) -> np.ndarray:
    """:func:`_result` of many union results (vectorized where they are polygons)."""
    import shapely

    t = shapely.get_type_id(geoms)
    ok = (t == 3) | (t == 6)
    out = np.empty(len(geoms), dtype=object)
    if ok.any():
        g = shapely.normalize(shapely.simplify(geoms[ok], 0.0))
        out[ok] = shapely.orient_polygons(g)
    for i in np.flatnonzero(~ok):
        out[i] = _result(geoms[i])
    return out


def _unscale_many(geoms: np.ndarray, k: int, names: list) -> list:
    """:func:`_unscale` of many results sharing the exponent ``k``."""
    import shapely

    if k == 0:
        return list(geoms)
    with np.errstate(over="ignore", under="ignore"):
        out = shapely.transform(geoms, lambda c: np.ldexp(c, -k))
    c = shapely.get_coordinates(out)
    nz = np.abs(c[c != 0])
    if nz.size and (not np.isfinite(nz).all() or nz.min() < 2.0**-1022):
        return [_unscale(g, k, nm) for g, nm in zip(geoms, names, strict=True)]
    return list(out)


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


def _from_exact_points(pts: list) -> Any:
    """Point, LineString or Polygon from exact vertices in convex order (with repeats)."""
    import shapely

    uniq: list = []
    for p in pts:
        if p not in uniq:
            uniq.append(p)
    if len(uniq) == 1:
        return shapely.Point(float(uniq[0][0]), float(uniq[0][1]))
    from .convex import convex_hull

    h = convex_hull([(Fraction(x), Fraction(y)) for x, y in uniq])
    out = np.array([(float(x), float(y)) for x, y in h.tolist()], dtype=np.float64)
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
    k, (A, B) = _operands((a, "a"), (b, "b"))
    if A.flat is not None:
        raise ShapeError(
            "a: the region to erode must have area (got a point or segment)", argument="a"
        )
    with _boundary("a, b", "computing the erosion"):
        E = _erode(A, B)
    return _unscale(E, k, "a, b")


def _erode(A: _Operand, B: _Operand) -> Any:
    """``A ⊖ B`` of validated (scaled) operands."""
    ra = A.convex_ring
    if ra is not None:
        # c + B ⊆ A  ⟺  c + hull(B) ⊆ A for a convex A: the exact convex erosion
        from .convex import normalize

        na = np.asarray(normalize(ra), dtype=np.float64)
        return _erode_convex(na, B.hull())
    return _result(_erode_general(A, B))


def _erode_general(A: _Operand, B: _Operand) -> Any:
    """``A ⊖ B = G \\ (R ⊕ (−B))`` for any A and B (neither needs to hold the origin).

    ``G`` is the box ``bbox(A) ⊖ bbox(B)`` grown by a margin ``d``: the erosion lies in
    ``bbox(A) ⊖ bbox(B)``, because ``c + B ⊆ A`` puts ``c + bbox(B)`` inside ``bbox(A)``.
    ``R = F \\ A`` with ``F`` the box ``bbox(A)`` grown by ``4 d`` (A's complement
    within F). A point ``c`` of ``G`` is outside the erosion iff some ``c + b`` (b in B)
    is outside A; that point lies in ``G + B ⊆ bbox(A) ± d ⊆ F``, hence in ``R``, so
    ``c ∈ R ⊕ (−B)``. Conversely ``R ⊕ (−B)`` never meets the erosion. The margin only
    absorbs the rounding of the box corners (the operands are scaled to |x| < 2**20).
    """
    import shapely

    ga = A.geom
    gb = _op_geom(B)
    ax0, ay0, ax1, ay1 = shapely.bounds(ga).tolist()
    bx0, by0, bx1, by1 = shapely.bounds(gb).tolist()
    F_ = Fraction
    if F_(bx1) - F_(bx0) > F_(ax1) - F_(ax0) or F_(by1) - F_(by0) > F_(ay1) - F_(ay0):
        return shapely.Polygon()  # B is wider or taller than A: it fits nowhere
    d = 1.0
    G = shapely.box(ax0 - bx0 - d, ay0 - by0 - d, ax1 - bx1 + d, ay1 - by1 + d)
    F = shapely.box(ax0 - 4 * d, ay0 - 4 * d, ax1 + 4 * d, ay1 + 4 * d)
    R = _Operand(shapely.orient_polygons(shapely.difference(F, ga)), None, A.name)
    if B.flat is not None:
        nB = _Operand(None, -B.flat, B.name)
    else:
        nB = _Operand(shapely.orient_polygons(shapely.transform(gb, lambda c: -c)), None, B.name)
    grown = _result(_sum(R, nB, None, "hertel-mehlhorn"))
    return shapely.difference(G, grown)
