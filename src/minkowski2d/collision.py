"""Collision, distance and penetration between convex polygons, and point location.

Two convex sets A and B intersect exactly when the origin lies in D = A ⊕ (−B) (the
"Minkowski difference" of collision detection; not the erosion A ⊖ B). Everything here
reads D:

* :func:`intersects` — is the origin in D (boundary included, so touching counts)?
* :func:`distance` — the distance from the origin to D, with a witness point on each
  polygon;
* :func:`penetration` — the nearest point of D's boundary to the origin: the minimum
  translation that separates overlapping polygons (signed: minus the distance when they
  are apart);
* :func:`contains` — point-in-convex-polygon for many points, O(log n) each.

Exactness: every yes/no decision (inside, outside, which edge or vertex is nearest) is an
exact sign computed on the input's own values — filtered floating point with an exact
fallback for floats, exact arithmetic for ints, Python ints and Fractions. Distances and
depths are real numbers: they are evaluated after the exact choice of feature, from a
cross product accurate to 2**-44 and a correctly rounded length, so their relative error
is below 1e-13 (tested against Fractions).

Methods: ``method="sum"`` (default) walks the boundary of D, merging the edges of A and
−B by angle without storing it, O(n + m). ``method="gjk"`` never forms D's boundary:
an exact Gilbert–Johnson–Keerthi iteration on support functions (see
:func:`intersects`). Both give the same answer on every input.

Many pairs go through :func:`intersects_many`, :func:`distance_many` and
:func:`penetration_many` on the ragged representation of :mod:`minkowski2d.batch`.
"""

from __future__ import annotations

from functools import partial
from typing import Any, NamedTuple

import numpy as np

from ._engine import core
from ._engine import dispatch as D
from ._engine import options as _options
from ._engine.coerce import INT
from ._engine.containers import apply, boxed
from ._engine.exact_collision import _py_contains, _py_pair
from ._engine.reader import read
from ._types import ArrayLike2, PolygonsLike, ProgressLike
from .errors import ShapeError

__all__ = [
    "Distance",
    "Penetration",
    "intersects",
    "distance",
    "penetration",
    "contains",
    "intersects_many",
    "distance_many",
    "penetration_many",
]

_INTERSECTS, _DISTANCE, _PENETRATION, _GJK, _AUTO = (
    core.COLL_INTERSECTS,
    core.COLL_DISTANCE,
    core.COLL_PENETRATION,
    core.COLL_GJK,
    core.COLL_AUTO,
)
_OUT_OF_RANGE = core.Status.RANGE  # values the kernels cannot take exactly: exact path
_METHODS = {"auto": _AUTO, "sum": _INTERSECTS, "gjk": _GJK}


class Distance(NamedTuple):
    """Result of :func:`distance` (arrays of results for :func:`distance_many`).

    Attributes
    ----------
    distance : float
        The minimum Euclidean distance between the polygons; 0.0 when they intersect
        (touching included).
    point_a, point_b : (2,) float64 ndarray
        Witnesses: ``point_a`` on A and ``point_b`` on B with
        ``|point_a - point_b| == distance`` (up to rounding of the witness coordinates).
        When the polygons intersect both are the same point of A ∩ B, bit for bit
        (``point_a.tolist() == point_b.tolist()``): an exact common point when they only
        touch; a floating-point one, from barycentric weights, when their interiors
        overlap.
    """

    distance: Any
    point_a: np.ndarray
    point_b: np.ndarray


class Penetration(NamedTuple):
    """Result of :func:`penetration` (arrays of results for :func:`penetration_many`).

    Attributes
    ----------
    depth : float
        Signed penetration depth: positive when the interiors overlap (the length of the
        minimum translation vector), 0.0 when the polygons touch, and minus their
        distance when they are apart.
    normal : (2,) float64 ndarray
        Unit outward normal of A ⊕ (−B) at its boundary point nearest the origin.
        Translating B by ``t * normal`` leaves the polygons with overlapping interiors
        for ``t < depth``, touching at ``t == depth`` and apart for ``t > depth``
        (equivalently, translate A by ``-t * normal``). (0, 0) when both are the same
        single point.
    point_a, point_b : (2,) float64 ndarray
        Witnesses on the boundaries of A and B with
        ``point_a - point_b == depth * normal``: after B moves by ``depth * normal``,
        ``point_b`` lands on ``point_a``.
    """

    depth: Any
    normal: np.ndarray
    point_a: np.ndarray
    point_b: np.ndarray


# --------------------------------------------------------------------------------------
# operands


def _operand(obj: Any, name: str, hull: bool) -> tuple[Any, str]:
    """``(data, kind)``: an (n, 2) int64/float64 ndarray, or a list of exact points."""
    if hull:
        obj = D.hull(obj, "points")
    op = read(obj, name, numbers="int64")
    return op.data, op.kind


def _kernel_view(data: np.ndarray) -> np.ndarray:
    return np.ascontiguousarray(data, dtype=np.float64)


def _raise(code: int, name: str, vertex: int) -> None:
    if code == core.Status.INTERNAL:  # pragma: no cover - a guard against a bug
        raise RuntimeError("GJK did not terminate; please report this input")
    raise D.status_error(code, vertex, name)


def _threads(threads: Any) -> int:
    return _options.threads(threads)


def _pair(a: Any, b: Any, mode: int, hull: bool) -> tuple[bool, np.ndarray]:
    """Run ``mode`` on one pair: the kernel when it can be exact on the values, else the
    exact Python path. Returns (hit, row) with row = (value, nx, ny, ax, ay, bx, by)."""
    da, ka = _operand(a, "a", hull)
    db, kb = _operand(b, "b", hull)
    if isinstance(da, np.ndarray) and isinstance(db, np.ndarray):
        row = np.zeros((1, 7))
        code, which, v, hit = core.coll_single(
            _kernel_view(da), _kernel_view(db), mode, ka == INT, kb == INT, row
        )
        if code == core.Status.OK:
            return bool(hit), row[0]
        if code != _OUT_OF_RANGE:
            _raise(int(code), ("a", "b")[which], int(v))
    return _py_pair(D.exact_rows(da), D.exact_rows(db), mode)


# --------------------------------------------------------------------------------------
# public single-pair API


def intersects(a: ArrayLike2, b: ArrayLike2, *, method: str = "auto", hull: bool = False) -> bool:
    """Whether two convex polygons intersect; touching (a shared boundary point) counts.

    Exact for int, float and Fraction input: no tolerance decides it.

    Parameters
    ----------
    a, b : (n, 2) array_like or shapely geometry
        Convex polygons in any orientation and start; points and segments are valid.
    method : {"auto", "sum", "gjk"}, keyword-only
        ``"sum"`` walks the boundary of A ⊕ (−B) (the angle merge, O(n + m), stopping at
        the first separating edge). ``"gjk"`` never forms that boundary: an exact GJK
        iteration on support functions (O(n + m) per iteration, few iterations). They
        agree on every input; ``"auto"`` (default) takes the sum walk when the two
        polygons have at most 64 vertices together and GJK otherwise, which measured
        fastest.
    hull : bool, default False
        Accept any point sets and use their convex hulls.

    Returns
    -------
    bool

    Raises
    ------
    NotConvexError
        An input is not convex (and ``hull`` is False).
    EmptyGeometryError, ShapeError, NonFiniteError, CoordinateTypeError
        Bad input; the message names the argument and vertex.

    Notes
    -----
    GJK's known failure modes and how they are avoided here: every simplex point is an
    index pair (i, j) standing for ``a_i - b_j`` and every test is an exact sign, so
    there is no tolerance to tune and no cycling (the distance to the simplex strictly
    decreases); the direction is kept symbolically (``-w`` or the segment's normal
    facing the origin) so the termination test ``max over D of d·x < 0`` is an exact
    separation certificate; the origin on a simplex edge or vertex is reported as
    touching; a new support point is strictly beyond the old segment, so a triangle is
    never degenerate; the support point is proposed by a float scan and then moved to
    the exact maximizer by hill-climbing (local = global on a convex polygon); points,
    segments, identical and nested shapes need no special case.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> square = [(0, 0), (2, 0), (2, 2), (0, 2)]
    >>> mk.intersects(square, [(2, 2), (3, 2), (3, 3)])  # touching at a corner
    True
    >>> mk.intersects(square, [(3, 0), (4, 0), (4, 1)], method="gjk")
    False
    """
    method = _options.choice(method, "method", tuple(_METHODS))
    hit, _ = _pair(a, b, _METHODS[method], hull)
    return hit


def distance(a: ArrayLike2, b: ArrayLike2, *, hull: bool = False) -> Distance:
    """Minimum distance between two convex polygons, with a witness point on each.

    The nearest feature (vertex or edge of A ⊕ (−B)) is chosen by exact predicates; the
    distance is then evaluated to a relative error below 1e-13.

    Parameters
    ----------
    a, b : (n, 2) array_like or shapely geometry
        Convex polygons (points and segments too).
    hull : bool, default False
        Use the convex hulls of the inputs.

    Returns
    -------
    Distance
        ``(distance, point_a, point_b)``; distance 0.0 when they intersect, with
        ``point_a`` and ``point_b`` then a common point.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> d = mk.distance([(0, 0), (2, 0), (2, 2), (0, 2)], [(5, 1), (6, 0), (6, 5)])
    >>> d.distance, d.point_a.tolist(), d.point_b.tolist()
    (3.0, [2.0, 1.0], [5.0, 1.0])
    """
    hit, row = _pair(a, b, _DISTANCE, hull)
    return Distance(float(row[0]), row[3:5].copy(), row[5:7].copy())


def penetration(a: ArrayLike2, b: ArrayLike2, *, hull: bool = False) -> Penetration:
    """Signed penetration depth and the minimum translation separating two convex
    polygons.

    The boundary point p of A ⊕ (−B) nearest the origin gives it: translating B by p
    (or A by −p) makes overlapping polygons touch. ``depth`` is |p| when the interiors
    overlap, 0.0 when they touch and minus the distance when they are apart (then
    translating B by p brings them into contact).

    Parameters
    ----------
    a, b : (n, 2) array_like or shapely geometry
        Convex polygons (points and segments too).
    hull : bool, default False
        Use the convex hulls of the inputs.

    Returns
    -------
    Penetration
        ``(depth, normal, point_a, point_b)``, see :class:`Penetration`.

    Notes
    -----
    The depth is the smallest distance from the origin to an edge line of A ⊕ (−B),
    each evaluated to a relative error below 1e-13. When two edges are that close to a
    tie either direction may be returned; the depth is right either way.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> p = mk.penetration([(0, 0), (4, 0), (4, 4), (0, 4)], [(3, 1), (6, 1), (6, 3), (3, 3)])
    >>> p.depth, p.normal.tolist()  # move B by depth * normal to separate them
    (1.0, [1.0, 0.0])
    >>> p.point_a.tolist(), p.point_b.tolist()
    ([4.0, 3.0], [3.0, 3.0])
    """
    hit, row = _pair(a, b, _PENETRATION, hull)
    return Penetration(float(row[0]), row[1:3].copy(), row[3:5].copy(), row[5:7].copy())


def contains(poly: ArrayLike2, points: Any, *, hull: bool = False) -> Any:
    """Point-in-convex-polygon for one point or many; boundary points count as inside.

    Exact (no tolerance) and O(log n) per point: a binary search over the fan of
    triangles from the polygon's first vertex.

    Parameters
    ----------
    poly : (n, 2) array_like or shapely geometry
        A convex polygon (a point or a segment too).
    points : (2,) or (k, 2) array_like
        The query point(s).
    hull : bool, default False
        Use the convex hull of ``poly``.

    Returns
    -------
    bool or (k,) bool ndarray
        A bool for one point given as ``(x, y)``, else one entry per row.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> tri = [(0, 0), (4, 0), (0, 4)]
    >>> mk.contains(tri, [(1, 1), (2, 2), (3, 3), (0, 5)]).tolist()
    [True, True, False, False]
    >>> mk.contains(tri, (0.5, 0.5))
    True
    """
    one = np.ndim(points) == 1
    if one and np.shape(points) != (2,):
        raise ShapeError(
            f"points: expected one (x, y) point or shape (k, 2), got {np.shape(points)}"
        )
    if not one and np.shape(points)[:1] == (0,):
        return np.zeros(0, bool)
    dp, kp = _operand(poly, "poly", hull)
    dq, kq, _ = read([points] if one else points, "points", numbers="int64")
    if isinstance(dp, np.ndarray) and isinstance(dq, np.ndarray):
        out = np.zeros(len(dq), np.bool_)
        code, which, v = core.coll_contains(
            _kernel_view(dp), kp == INT, _kernel_view(dq), kq == INT, out
        )
        if code == core.Status.OK:
            return bool(out[0]) if one else out
        if code != _OUT_OF_RANGE:
            _raise(int(code), ("poly", "points")[which], int(v))
    res = _py_contains(D.exact_rows(dp), D.exact_rows(dq))
    return bool(res[0]) if one else np.array(res, dtype=np.bool_)


# --------------------------------------------------------------------------------------
# batches


def _batch(As: Any, Bs: Any, mode: int, threads: int = 1) -> tuple[np.ndarray, np.ndarray]:
    from .batch import as_ragged_pair

    threads = _threads(threads)
    RA, _, _, RB, _, _, P, names = as_ragged_pair(As, Bs)
    many_a, many_b = names[0] == "As", names[1] == "Bs"
    hit = np.zeros(P, np.int8)
    res = np.zeros((P if mode in (_DISTANCE, _PENETRATION) else 1, 7))
    need = mode == _PENETRATION
    prepared: list[tuple] | None  # None: the exact path
    prepared = []
    for R, nm, many in ((RA, names[0], many_a), (RB, names[1], many_b)):
        p = _kernel_view(R.coords)
        n = len(p)
        idx = np.empty(n, np.int64)
        kk = np.empty(len(R), np.int64)
        ss = np.empty(len(R), np.int64)
        inv = np.empty(n if need else 1)
        off = np.ascontiguousarray(R.offsets, dtype=np.int64)
        is_int = R.coords.dtype.kind in "iu"
        code, q, v = core.coll_prep(p, off, is_int, mode, idx, kk, ss, inv, threads)
        if code == _OUT_OF_RANGE:
            prepared = None
            break
        if code:
            _raise(int(code), f"{nm}[{q}]" if many else nm, int(v))
        prepared.append((p, off, idx, kk, ss, inv))
    if prepared is None:
        # coordinates the kernels cannot take exactly: the exact path, pair by pair
        res = np.zeros((P, 7))
        for q in range(P):
            a = RA[q if many_a else 0]
            b = RB[q if many_b else 0]
            h, row = _py_pair(D.exact_rows(a), D.exact_rows(b), mode)
            hit[q] = h
            res[q] = row
        return hit.astype(bool), res
    qa = np.arange(P, dtype=np.int64) if many_a else np.zeros(P, np.int64)
    qb = np.arange(P, dtype=np.int64) if many_b else np.zeros(P, np.int64)
    r = core.coll_pairs(*prepared[0], *prepared[1], qa, qb, mode, hit, res, threads)
    if r >= 0:  # pragma: no cover - guard
        _raise(core.Status.INTERNAL, "", 0)
    return hit.astype(bool), res


def intersects_many(
    As: PolygonsLike,
    Bs: PolygonsLike,
    *,
    method: str = "auto",
    threads: int = 1,
    progress: ProgressLike = None,
) -> Any:
    """:func:`intersects` for many pairs: pairwise, or one polygon against many.

    Parameters
    ----------
    As, Bs : Ragged, sequence of (n, 2) array_like, array of shapely geometries, or one
        polygon
        Equal counts (pair k is ``As[k]``, ``Bs[k]``), or one side a single polygon.
    method : {"auto", "sum", "gjk"}, keyword-only
        As for :func:`intersects`.
    threads : int, default 1, keyword-only
        Split the pairs into this many contiguous chunks run in parallel (the GIL is
        released); the result does not depend on it.
    progress : None, True or callable, keyword-only
        ``True``: a tqdm bar on stderr; a callable: ``cb(done, total)`` after each of
        about 64 chunks, last with ``done == total``.

    Returns
    -------
    (P,) bool ndarray, or a pandas Series
        Entry k is exactly ``intersects(As[k], Bs[k])``. A GeoSeries operand gives a
        Series with its index (nullable ``boolean``: ``<NA>`` for a None member); a
        numpy object array of shapely geometries gives a bool array of its shape
        (``False`` for None, as in shapely). An empty member never intersects.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> robot = [(0, 0), (1, 0), (0, 1)]
    >>> mk.intersects_many(robot, [[(1, 0), (2, 0), (2, 1)], [(3, 3), (4, 3), (3, 4)]]).tolist()
    [True, False]
    """
    if progress is not None or boxed(As) or boxed(Bs):
        return apply(
            partial(intersects_many, method=method, threads=threads), As, Bs, progress=progress
        )
    method = _options.choice(method, "method", tuple(_METHODS))
    hit, _ = _batch(As, Bs, _METHODS[method], threads)
    return hit


def distance_many(
    As: PolygonsLike, Bs: PolygonsLike, *, threads: int = 1, progress: ProgressLike = None
) -> Distance:
    """:func:`distance` for many pairs (pairwise or one against many).

    ``threads`` splits the pairs over that many threads, and ``progress`` reports, as in
    :func:`intersects_many`.

    Returns
    -------
    Distance
        ``distance`` (P,), ``point_a`` and ``point_b`` (P, 2): row k equals
        ``distance(As[k], Bs[k])``. For a GeoSeries operand: a Series of distances and
        two GeoSeries of witness Points, with its index and CRS; for an object array:
        arrays of its shape (Points as shapely geometries). NaN and None for a None or
        empty member.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> d = mk.distance_many([(0, 0)], [[(3, 4)], [(0, 2), (5, 2)]])
    >>> d.distance.tolist(), d.point_b.tolist()
    ([5.0, 2.0], [[3.0, 4.0], [0.0, 2.0]])
    """
    if progress is not None or boxed(As) or boxed(Bs):
        return apply(partial(distance_many, threads=threads), As, Bs, progress=progress)
    hit, res = _batch(As, Bs, _DISTANCE, threads)
    return Distance(res[:, 0].copy(), res[:, 3:5].copy(), res[:, 5:7].copy())


def penetration_many(
    As: PolygonsLike, Bs: PolygonsLike, *, threads: int = 1, progress: ProgressLike = None
) -> Penetration:
    """:func:`penetration` for many pairs (pairwise or one against many).

    ``threads`` splits the pairs over that many threads, and ``progress`` reports, as in
    :func:`intersects_many`.

    Returns
    -------
    Penetration
        ``depth`` (P,), ``normal``, ``point_a``, ``point_b`` (P, 2): row k equals
        ``penetration(As[k], Bs[k])``. For a GeoSeries operand: Series of depths, a
        DataFrame of normals (columns x, y) and GeoSeries of witness Points, all with its
        index; NaN and None for a None or empty member.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> sq = [(0, 0), (4, 0), (4, 4), (0, 4)]
    >>> mk.penetration_many(sq, [[(3, 1), (6, 1), (6, 3)], [(6, 0), (7, 0), (7, 1)]]).depth.tolist()
    [1.0, -2.0]
    """
    if progress is not None or boxed(As) or boxed(Bs):
        return apply(partial(penetration_many, threads=threads), As, Bs, progress=progress)
    hit, res = _batch(As, Bs, _PENETRATION, threads)
    return Penetration(res[:, 0].copy(), res[:, 1:3].copy(), res[:, 3:5].copy(), res[:, 5:7].copy())
