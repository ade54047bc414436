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
clockwise, holes kept). Coordinates are float64 throughout: integer input up to 2**53
is represented exactly, piece sums are exact for it, and GEOS computes the crossings of
the final union in double precision.

:func:`minkowski_difference` is the erosion ``A ⊖ B = {c : c + B ⊆ A}``. It is *not*
``A ⊕ (−B)`` (that is :func:`minkowski2d.cspace_obstacle`, the set of translations
where ``B`` *touches* ``A``); the erosion is the set where ``B`` fits *inside* ``A``.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

import numpy as np

from ._coerce import as_array
from .batch import Ragged, minkowski_sum_many
from .errors import (
    EmptyGeometryError,
    NonFiniteError,
    SelfIntersectionError,
    ShapeError,
)

__all__ = ["minkowski_sum_general", "convex_decomposition", "minkowski_difference"]

SUM_METHODS = ("decomposition", "convolution")
DECOMPOSITIONS = ("hertel-mehlhorn", "triangulation")


# --------------------------------------------------------------------------------------
# input


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


def _float_coords(obj: Any, name: str) -> np.ndarray:
    data, kind = as_array(obj, name)
    if isinstance(data, list):  # exact kinds: Fractions or huge ints, rounded once
        data = np.array([(float(Fraction(x)), float(Fraction(y))) for x, y in data])
        if not np.isfinite(data).all():
            raise NonFiniteError(f"{name}: a coordinate does not fit in float64")
    return np.asarray(data, dtype=np.float64)


def _check_geom(geom: Any, name: str) -> Any:
    """Validate a Polygon / MultiPolygon and orient it (exteriors CCW, holes CW).

    A hole that touches the shell at two points (valid for CGAL, "interior is
    disconnected" for GEOS) is a well-defined region: it is split into its parts.
    """
    import shapely

    if geom.is_empty:
        raise EmptyGeometryError(f"{name}: empty {geom.geom_type}")
    c = shapely.get_coordinates(geom)
    if not np.isfinite(c).all():
        raise NonFiniteError(f"{name}: a coordinate is not finite")
    if not shapely.is_valid(geom):
        reason = shapely.is_valid_reason(geom)
        if not reason.startswith("Interior is disconnected"):
            raise SelfIntersectionError(f"{name}: not a valid polygon ({reason})")
        geom = shapely.make_valid(geom, method="structure")
    return shapely.orient_polygons(geom)


def _operand(obj: Any, name: str) -> _Operand:
    """Read one operand of a general sum or erosion (see :func:`minkowski_sum_general`)."""
    import shapely

    if isinstance(obj, _Operand):
        return obj
    if isinstance(obj, Ragged):
        obj = obj.to_list()
    mod = type(obj).__module__
    if mod.startswith("shapely"):
        gt = obj.geom_type
        if gt in ("Polygon", "MultiPolygon"):
            return _Operand(_check_geom(obj, name), None, name)
        if gt == "GeometryCollection":
            parts = shapely.get_parts(obj)
            if not np.isin(shapely.get_type_id(parts), (3, 6)).all():
                raise ShapeError(f"{name}: a GeometryCollection may hold only polygons")
            return _operand(list(parts), name)
        obj = _float_coords(obj, name)  # ring, line, points
    elif type(obj).__name__ == "UnboundedPolygon":
        raise ShapeError(
            f"{name}: the polygon has an unbounded outer boundary (CGAL N = 0); "
            "its Minkowski sum is unbounded too"
        )
    elif (
        isinstance(obj, (list, tuple))
        and obj
        and (type(obj[0]).__module__.startswith("shapely") or np.ndim(obj[0]) == 2)
    ):
        # a collection of polygons: their union is the operand
        geoms = []
        for k, item in enumerate(obj):
            op = _operand(item, f"{name}[{k}]")
            geoms.append(op.geom if op.flat is None else _flat_geom(op.flat))
        u = shapely.union_all(geoms)
        u = shapely.get_parts(u)
        polys = u[shapely.get_type_id(u) == 3]
        if len(polys) == 0:
            raise ShapeError(f"{name}: the polygons have no area")
        g = polys[0] if len(polys) == 1 else shapely.multipolygons(polys)
        return _Operand(_check_geom(g, name), None, name)
    from .convex import convex_hull

    ring = _float_coords(obj, name)
    hull = np.asarray(convex_hull(ring), dtype=np.float64)
    if len(hull) <= 2:
        # a point, a segment, or collinear points: a degenerate convex set
        return _Operand(None, hull, name)
    return _Operand(_check_geom(shapely.Polygon(ring), name), None, name)


def _flat_geom(flat: np.ndarray) -> Any:
    import shapely

    if len(flat) == 1:
        return shapely.Point(flat[0])
    return shapely.LineString(flat)


def _result(geom: Any) -> Any:
    """Polygon or MultiPolygon, exterior CCW and holes CW; empty Polygon if nothing."""
    import shapely

    parts = shapely.get_parts(geom)
    polys = parts[(shapely.get_type_id(parts) == 3) & (shapely.area(parts) > 0)]
    if len(polys) == 0:
        return shapely.Polygon()
    g = polys[0] if len(polys) == 1 else shapely.multipolygons(polys)
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
        ``"triangulation"``: GEOS's constrained Delaunay triangulation (input vertices
        only, holes supported). ``"hertel-mehlhorn"``: the triangles merged across every
        diagonal whose removal keeps both its endpoints convex (at most four times the
        optimal number of pieces).

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

    Notes
    -----
    Time O(n log n) for the triangulation and O(n) for the merge; every turn is decided
    by the exact orientation predicate.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> L = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    >>> for piece in mk.convex_decomposition(L):
    ...     print(piece.tolist())
    [[0.0, 0.0], [1.0, 1.0], [1.0, 2.0], [0.0, 2.0]]
    [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]]
    >>> len(mk.convex_decomposition(L, method="triangulation"))
    4
    """
    if method not in DECOMPOSITIONS:
        raise ValueError(f"method must be one of {DECOMPOSITIONS}, got {method!r}")
    return _pieces(_operand(poly, "poly"), method)


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


def _sum_decomposition(A: _Operand, B: _Operand, decomposition: str) -> Any:
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
    scale = np.abs(e).max() * np.abs(f).max() * 1e-12
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
    tol = scale * 1e-9
    mid = (ec[:, 0] + ec[:, 1]) / 2
    tree = shapely.STRtree(lines)
    ei, si = tree.query(shapely.points(mid), predicate="dwithin", distance=tol)
    de = ec[ei, 1] - ec[ei, 0]
    ds = segs[si, 1] - segs[si, 0]
    norm = np.linalg.norm(de, axis=1) * np.linalg.norm(ds, axis=1)
    par = np.abs(_cross(de, ds)) <= 1e-9 * norm
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


def _sum_convolution(A: _Operand, B: _Operand) -> Any:
    import shapely

    ra, rb = _rings(A), _rings(B)
    segs = [_rc_segments(p, q) for p in ra for q in rb] + [
        _rc_segments(q, p) for p in ra for q in rb
    ]
    segs = np.concatenate(segs)
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
    a: Any, b: Any, *, method: str = "decomposition", decomposition: str = "hertel-mehlhorn"
) -> Any:
    """Minkowski sum of polygons that may be non-convex and have holes.

    Parameters
    ----------
    a, b : (n, 2) array_like, shapely Polygon / MultiPolygon / LinearRing, or a list
        A simple ring (either orientation), a polygon with holes, or a collection of
        polygons (a list of rings or shapely polygons; their union is the operand). A
        point, a segment or collinear points are taken as that degenerate convex set.
        Whatever :func:`minkowski2d.io.read_geometry` returns is accepted.
    method : {"decomposition", "convolution"}
        ``"decomposition"``: convex pieces, all pairs summed in one batch, GEOS union.
        ``"convolution"``: reduced convolution, GEOS arrangement, orientability and
        hole filters. Both give the same set.
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

    Notes
    -----
    Work in float64 (GEOS): integer coordinates up to 2**53 are exact, every convex
    piece sum is exact for them, and the union's crossing points are rounded once.
    Exact inputs (Fractions, huge ints) are rounded to float64 first.

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
    if method not in SUM_METHODS:
        raise ValueError(f"method must be one of {SUM_METHODS}, got {method!r}")
    if decomposition not in DECOMPOSITIONS:
        raise ValueError(f"decomposition must be one of {DECOMPOSITIONS}, got {decomposition!r}")
    A = _operand(a, "a")
    B = _operand(b, "b")
    if A.flat is not None and B.flat is not None:
        raise ShapeError("both operands are points or segments: the sum has no area")
    if method == "convolution":
        return _result(_sum_convolution(A, B))
    return _result(_sum_decomposition(A, B, decomposition))


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


def _erode_fallback(A: np.ndarray, B: np.ndarray) -> Any:
    """Erosion as the intersection of the translates A − b (used for rare degenerate
    configurations of the exact convex pass)."""
    import shapely

    pa = shapely.Polygon(A)
    pieces = [shapely.affinity.translate(pa, -x, -y) for x, y in B.tolist()]
    return shapely.intersection_all(pieces)


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
        * convex ``a`` and convex ``b`` (no holes): computed exactly in O(n + m) — a
          Polygon, or a LineString / Point when the erosion is a segment or a single
          point (``A ⊖ A`` is the point at the origin);
        * otherwise: ``A ⊖ B = complement(complement(A) ⊕ (−B))`` with the general sum,
          a Polygon or MultiPolygon (the closure of the erosion's interior: parts of
          zero width are not represented);
        * when ``B`` fits nowhere inside ``A``: an empty Polygon (``POLYGON EMPTY``,
          ``result.is_empty`` is True).

    Raises
    ------
    SelfIntersectionError, ShapeError, EmptyGeometryError, NonFiniteError
        Bad input (``a`` must have area).

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
    >>> mk.cspace_obstacle(sq, [(0, 0), (1, 0), (1, 1), (0, 1)]).tolist()  # not the same
    [[-1, -1], [4, -1], [4, 4], [-1, 4]]
    """
    import shapely

    A = _operand(a, "a")
    B = _operand(b, "b")
    if A.flat is not None:
        raise ShapeError("a: the region to erode must have area (got a point or segment)")
    ra, rb = A.convex_ring, B.convex_ring
    if ra is not None and rb is not None:
        from .convex import normalize

        na = np.asarray(normalize(ra), dtype=np.float64)
        nb = np.asarray(normalize(rb), dtype=np.float64)
        return _erode_convex(na, nb)
    ga = A.geom
    gb = _op_geom(B)
    lo = np.minimum(shapely.bounds(ga)[:2], shapely.bounds(gb)[:2])
    hi = np.maximum(shapely.bounds(ga)[2:], shapely.bounds(gb)[2:])
    span = float((hi - lo).max())
    pad = 2.0 * span + 1.0
    box = shapely.box(*(shapely.bounds(ga)[:2] - pad), *(shapely.bounds(ga)[2:] + pad))
    comp = shapely.difference(box, ga)
    nb = shapely.affinity.scale(gb, -1.0, -1.0, origin=(0, 0))
    grown = minkowski_sum_general(comp, nb if B.flat is None else -B.flat)
    return _result(shapely.difference(ga, grown))
