"""The Minkowski difference (erosion) ``A ⊖ B = {c : c + B ⊆ A}``: exact for a convex A, one
compiled call otherwise."""

from __future__ import annotations

import math
from collections.abc import Callable
from fractions import Fraction
from typing import Any

import numpy as np

from .._engine import core
from .._engine.coerce import to_float
from .._engine.overlay import geometries
from ..errors import (
    ShapeError,
)
from . import limits
from .operands import (
    _Operand,
    _operands,
)
from .sums import (
    _Prepared,
    _status_error,
    _table,
    _Wrapped,
)

# --------------------------------------------------------------------------------------
# erosion


def _exact(v: float) -> Fraction:
    return Fraction(v)


def _cr(ux, uy, vx, vy):
    return ux * vy - uy * vx


def _upper(dx, dy):
    return dy > 0 or (dy == 0 and dx > 0)


def _before(u, v):
    """True when direction u comes strictly before v in the angle order from +x."""
    hu, hv = _upper(*u), _upper(*v)
    if hu != hv:
        return hu
    return _cr(u[0], u[1], v[0], v[1]) > 0


def _inter(l1, l2):
    (p1, d1), (p2, d2) = l1, l2
    den = _cr(d1[0], d1[1], d2[0], d2[1])
    t = Fraction(_cr(p2[0] - p1[0], p2[1] - p1[1], d2[0], d2[1])) / den
    return (p1[0] + d1[0] * t, p1[1] + d1[1] * t)


def _side(ln, p):
    (q, d) = ln
    return _cr(d[0], d[1], p[0] - q[0], p[1] - q[1])  # > 0 inside (left), 0 on the line


def _support_lines(Ae: list, Be: list) -> list:
    """A's edge lines pushed inward by B's support vertex, as (point, direction) with the
    half-plane on the left. Edges of both are in angle order from the bottom-most vertex,
    so one pointer walks B while A's edges turn (a merge)."""
    n, m = len(Ae), len(Be)
    Bedges = (
        [(Be[(j + 1) % m][0] - Be[j][0], Be[(j + 1) % m][1] - Be[j][1]) for j in range(m)]
        if m > 1
        else []
    )
    lines = []
    j = 0
    for i in range(n):
        ex = Ae[(i + 1) % n][0] - Ae[i][0]
        ey = Ae[(i + 1) % n][1] - Ae[i][1]
        # advance j while B's edge j comes before A's edge i (support moves on)
        while m > 1 and j < m and _before(Bedges[j], (ex, ey)):
            j += 1
        b = Be[j % m] if m > 1 else Be[0]
        lines.append(((Ae[i][0] - b[0], Ae[i][1] - b[1]), (ex, ey)))
    return lines


def _boxed(lines: list, Ae: list, Be: list) -> list:
    """The lines with the four sides of a box around A - B[0] (which contains the
    erosion) merged into the angle order: the deque algorithm is only correct while the
    partial intersection stays bounded."""
    xs = [p[0] - Be[0][0] for p in Ae]
    ys = [p[1] - Be[0][1] for p in Ae]
    x0, x1, y0, y1 = min(xs) - 1, max(xs) + 1, min(ys) - 1, max(ys) + 1
    box = [((x0, y0), (1, 0)), ((x1, y0), (0, 1)), ((x1, y1), (-1, 0)), ((x0, y1), (0, -1))]
    merged: list = []
    k = 0
    for ln in lines:
        while k < 4 and not _before(ln[1], box[k][1]):
            merged.append(box[k])
            k += 1
        merged.append(ln)
    merged.extend(box[k:])
    return merged


def _erode_convex(A: np.ndarray, B: np.ndarray) -> Any:
    """Exact erosion of convex A by convex B (both normalized CCW; B may be flat).

    A's edge lines pushed inward by B's support in each edge's outward normal, then
    intersected in angle order (one deque pass). Every decision is exact (Python
    integers / Fractions); O(n + m).
    """
    import shapely

    Ae = [(_exact(x), _exact(y)) for x, y in A.tolist()]
    Be = [(_exact(x), _exact(y)) for x, y in B.tolist()]
    if len(A) < 3:
        raise ShapeError("a: a convex polygon with area is needed")
    lines = _support_lines(Ae, Be)
    # half-plane intersection of the lines sorted by angle (the deque algorithm)
    dq: list = []
    for ln in _boxed(lines, Ae, Be):
        while len(dq) >= 2 and _side(ln, _inter(dq[-2], dq[-1])) < 0:
            dq.pop()
        while len(dq) >= 2 and _side(ln, _inter(dq[0], dq[1])) < 0:
            dq.pop(0)
        if dq:
            d0, d1 = dq[-1][1], ln[1]
            if _cr(d0[0], d0[1], d1[0], d1[1]) == 0:
                if d0[0] * d1[0] + d0[1] * d1[1] < 0:  # antiparallel after popping
                    s = _side(ln, dq[-1][0])
                    if s < 0:
                        return shapely.Polygon()  # the strip between them is empty
                    if s == 0:
                        return _on_line(ln, lines, _side, _cr)  # zero width: segment or point
                    return shapely.Polygon()
                # same direction: keep the more restrictive of the two
                if _side(ln, dq[-1][0]) < 0:
                    dq.pop()
                else:
                    continue
        dq.append(ln)
    while len(dq) >= 3 and _side(dq[0], _inter(dq[-2], dq[-1])) < 0:
        dq.pop()
    while len(dq) >= 3 and _side(dq[-1], _inter(dq[0], dq[1])) < 0:
        dq.pop(0)
    return _polygon_of(dq, lines)


def _polygon_of(dq: list, lines: list) -> Any:
    """The erosion from the deque's lines: a polygon, or (decided exactly against every
    half-plane) a segment, a point or nothing."""
    import shapely

    if len(dq) < 3:
        return shapely.Polygon()
    pts = []
    for k in range(len(dq)):
        l1, l2 = dq[k], dq[(k + 1) % len(dq)]
        if _cr(l1[1][0], l1[1][1], l2[1][0], l2[1][1]) == 0:
            s = _side(l2, l1[0])
            if s < 0:
                return shapely.Polygon()
            return _on_line(l1, lines, _side, _cr)
        pts.append(_inter(l1, l2))
    # A candidate without area (lines through one point, or all vertices on a line) can
    # survive the strict cleanup although other half-planes exclude it: decide those
    # exactly against every half-plane.
    uniq = list(dict.fromkeys(pts))
    p0 = uniq[0]
    far = max(uniq, key=lambda p: abs(p[0] - p0[0]) + abs(p[1] - p0[1]))
    if far == p0:
        if all(_side(ln, p0) >= 0 for ln in lines):
            return _from_exact_points([p0])
        return shapely.Polygon()
    d = (far[0] - p0[0], far[1] - p0[1])
    if all(_cr(d[0], d[1], p[0] - p0[0], p[1] - p0[1]) == 0 for p in uniq):
        return _on_line((p0, d), lines, _side, _cr)
    return _from_exact_points(pts)


def _on_line(ln: tuple, lines: list, side: Callable[..., Any], cr: Callable[..., Any]) -> Any:
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
    f = to_float(v)
    if math.isinf(f):
        from .._engine.status import Status, status_error

        raise status_error(Status.OVERFLOW, name="a, b")
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
    from .._engine import dispatch as D

    h = D.hull([(Fraction(x), Fraction(y)) for x, y in uniq], "points")
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
        An integer coordinate has more than 53 significant bits.
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
    ``b ∈ B``. ``G \\ ((F \\ A) ⊕ (−B))`` is one run of the exact overlay (its
    DIFFERENCE rule), decided exactly at every magnitude.

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
    """``A ⊖ B`` of validated operands."""
    ra = A.convex_ring
    if ra is not None:
        # c + B ⊆ A  ⟺  c + hull(B) ⊆ A for a convex A: the exact convex erosion
        from .._engine import dispatch as D

        na = np.asarray(D.normalized(ra, "p"), dtype=np.float64)
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

    preps: list[_Prepared] = [_Wrapped(A), _Wrapped(B)]
    T = _table(preps, [False, False], "hertel-mehlhorn")
    xy, ro, po, pair_off, status, _ = core.general_sums(
        *T,
        np.array([0], np.int64),
        np.array([1], np.int64),
        core.METHOD_ERODE,
        limits.MAX_CONVOLUTION_SEGMENTS,
        limits.MAX_PIECE_PAIRS,
        limits.MAX_CROSSINGS,
        1,
    )
    if status[0] != core.Status.OK:
        raise _status_error(int(status[0]), A.name, B.name, "convolution")
    return geometries(xy, ro, po, pair_off)[0]
