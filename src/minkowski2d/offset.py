"""Offsetting by a disk: growing and shrinking a polygon by a tool radius.

:func:`offset` returns a polygon with a **one-sided, guaranteed** error;
:func:`offset_arcs` returns the exact boundary as segments and circular arcs (for CAD/CAM,
SVG and DXF).

The exact offset by ``r > 0`` is ``P ⊕ D(r) = {x : dist(x, P) ≤ r}``; the exact shrink (a
negative ``distance``) is the erosion ``P ⊖ D(r) = {x ∈ P : dist(x, ∂P) ≥ r}``. Both are
bounded by segments (the edges moved by ``r``) and circular arcs of radius ``r`` centred at
the vertices (the convex ones for a grow, the reflex ones for a shrink).

Construction
------------
Every edge ``ab`` gives one *piece*: ``a``, ``b``, the edge moved out by ``r`` and, when
``b`` is convex on that side, a polygon around the arc of ``b``, which spans exactly the
exterior angle ``θ`` of ``b`` from tangent to tangent. ``approx="outer"`` uses a
circumscribed polygon (``k = ceil(θ / φ)`` corners at distance ``r / cos(φ/2)``, with
``r (1/cos(φ/2) − 1) ≤ ε``), ``approx="inner"`` an inscribed one (``k`` chords, sagitta
``r (1 − cos(φ/2)) ≤ ε``); choosing ``k`` with ``ceil`` is what keeps the error within
``ε``. A grow is ``P ∪ pieces``; a shrink is ``P \\ pieces`` with the pieces built on the
inner side. Every outer piece contains the part of the true offset whose nearest point of
``∂P`` lies on its edge or at its end vertex, and lies within ``r + ε`` of that edge, so

* grow, outer: ``P ⊕ D(r) ⊆ result ⊆ P ⊕ D(r + ε)``; inner: ``P ⊕ D(r − ε) ⊆ result ⊆ P ⊕ D(r)``;
* shrink, outer: ``P ⊖ D(r) ⊆ result ⊆ P ⊖ D(r − ε)``; inner: ``P ⊖ D(r + ε) ⊆ result ⊆ P ⊖ D(r)``.

For a grow ``P ⊕ D(r + ε) = (P ⊕ D(r)) ⊕ D(ε)``, so "within ε" is the Hausdorff distance.
An erosion is not continuous in ``r`` (a neck of width ``2r`` closes), so for a shrink the
guarantee is stated, as above, as a sandwich between the erosions by ``r`` and ``r ∓ ε``.

The unions are computed by GEOS in float64. Their vertices are rounded, so the pieces are
built for the radius ``r ± m`` with the *rounding margin* ``m = ROUNDING_MARGIN · (max |x| +
r)`` (:data:`ROUNDING_MARGIN` = 2⁻⁴²): a vertex moved by rounding can never cross the
true boundary, and the arcs get the budget ``ε − 2m``. A tolerance below ``4m`` cannot be
met in float64 and raises :class:`~minkowski2d.errors.GeometryError`. The input is
rescaled by a power of two (exact) into GEOS's comfortable range and back; Fractions and
integers beyond 2⁵³ are rounded to float64 once (also within the margin).

Examples
--------
>>> import minkowski2d as mk
>>> sq = [(0, 0), (2, 0), (2, 2), (0, 2)]
>>> g = mk.offset(sq, 1.0, tolerance=0.01)
>>> round(g.area, 2), g.area > 4 + 8 + 3.14159
(15.15, True)
>>> mk.offset(sq, -0.5, tolerance=0.01).bounds  # doctest: +ELLIPSIS
(0.49999999..., 0.49999999..., 1.50000000..., 1.50000000...)
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any

import numpy as np

from ._coerce import as_array
from .errors import (
    EmptyGeometryError,
    GeometryError,
    NonFiniteError,
    SelfIntersectionError,
    ShapeError,
)
from .predicates import orient_array

__all__ = ["offset", "offset_arcs", "OffsetArcs", "ROUNDING_MARGIN", "APPROX", "JOINS"]

#: Relative size of the rounding margin ``m = ROUNDING_MARGIN · (max |coordinate| + r)``
#: by which the pieces are pushed away from the true boundary, so that float64 rounding
#: of the union's vertices (a few units in the last place) cannot cross it.
ROUNDING_MARGIN = 2.0**-42

#: The tolerance actually used is at most this fraction of the radius (a coarser one is
#: met by a finer approximation).
_MAX_REL_TOLERANCE = 0.5

APPROX = ("outer", "inner")
JOINS = ("round", "miter", "square")

#: Largest arc angle one corner of an outer (circumscribed) approximation may cover; a
#: coarse tolerance gives no fewer corners than this (quarter-turn) allows.
_MAX_STEP_OUTER = math.pi / 2
_MAX_STEP_INNER = math.pi


# --------------------------------------------------------------------------------------
# input


def _is_many(x: Any) -> bool:
    """True when ``x`` is a collection of polygons rather than one polygon."""
    name = type(x).__name__
    if name in ("GeoSeries", "GeometryArray"):
        return True
    if isinstance(x, np.ndarray):
        return x.dtype == object and x.ndim == 1 and (len(x) == 0 or not np.isscalar(x[0]))
    if type(x).__module__.startswith("shapely"):
        return False
    if isinstance(x, (list, tuple)):
        if len(x) == 0:
            return False
        first = x[0]
        return first is None or np.ndim(first) == 2 or type(first).__module__.startswith("shapely")
    return False


def _finite_float(v: Any, name: str) -> float:
    if isinstance(v, bool) or not isinstance(v, (int, float, Fraction, np.integer, np.floating)):
        raise GeometryError(
            f"{name}: expected a real number, got {type(v).__name__}",
            argument=name,
            hint=f"give {name} as an int, float or Fraction",
        )
    f = float(v)
    if not math.isfinite(f):
        raise NonFiniteError(
            f"{name}: must be finite, got {v!r}", argument=name, hint=f"give a finite {name}"
        )
    return f


def _check_shapely(geom: Any, name: str) -> Any:
    import shapely

    gt = geom.geom_type
    if gt == "LinearRing":
        geom = shapely.Polygon(geom)
        gt = "Polygon"
    if gt == "GeometryCollection":
        parts = shapely.get_parts(geom)
        if not np.isin(shapely.get_type_id(parts), (3, 6)).all():
            raise ShapeError(
                f"{name}: a GeometryCollection may hold only polygons",
                argument=name,
                hint="pass the polygons only",
            )
        geom = shapely.union_all(parts)
        gt = geom.geom_type
    if gt not in ("Polygon", "MultiPolygon"):
        raise ShapeError(
            f"{name}: cannot offset a {gt} here (give a polygon, a ring or an (n, 2) array)",
            argument=name,
            hint="pass the coordinates as an (n, 2) array for a point or a segment",
        )
    if geom.is_empty:
        raise EmptyGeometryError(f"{name}: empty {gt}", argument=name)
    c = shapely.get_coordinates(geom)
    if not np.isfinite(c).all():
        raise NonFiniteError(
            f"{name}: a coordinate is not finite", argument=name, hint="remove NaN and inf"
        )
    if not shapely.is_valid(geom):
        reason = shapely.is_valid_reason(geom)
        if not reason.startswith("Interior is disconnected"):
            raise SelfIntersectionError(
                f"{name}: not a valid polygon ({reason})",
                argument=name,
                hint="repair it first, e.g. shapely.make_valid",
            )
        geom = shapely.make_valid(geom, method="structure")
    return shapely.orient_polygons(geom)


def _read(obj: Any, name: str) -> tuple[list[np.ndarray], Any]:
    """``(rings, geom)``: float64 rings with the interior on their left (exteriors
    counter-clockwise, holes clockwise; a point or a segment is a ring of one or two
    vertices), and the shapely geometry (None for a point or a segment)."""
    import shapely

    if type(obj).__module__.startswith("shapely"):
        if obj.geom_type in ("Point", "LineString", "MultiPoint"):
            obj = shapely.get_coordinates(obj)
        else:
            geom = _check_shapely(obj, name)
            return _geom_rings(geom), geom
    data, _kind = as_array(obj, name)
    if isinstance(data, list):  # Fractions or huge ints: rounded to float64 once
        data = np.array([(float(Fraction(x)), float(Fraction(y))) for x, y in data])
        if not np.isfinite(data).all():
            raise NonFiniteError(
                f"{name}: a coordinate does not fit in float64",
                argument=name,
                hint="scale the input down",
            )
    data = np.asarray(data, dtype=np.float64)
    if len(data) > 1 and (data[0] == data[-1]).all():
        data = data[:-1]
    from .convex import convex_hull

    hull = np.asarray(convex_hull(data), dtype=np.float64)
    if len(hull) <= 2:
        return [hull], None
    geom = _check_shapely(shapely.Polygon(data), name)
    return _geom_rings(geom), geom


def _geom_rings(geom: Any) -> list[np.ndarray]:
    import shapely

    rings = shapely.get_rings(shapely.get_parts(geom))
    return [shapely.get_coordinates(r)[:-1] for r in rings]


def _clean(ring: np.ndarray) -> np.ndarray:
    """Drop repeated and exactly collinear vertices (exact orientation); a spike (a turn
    of a half-turn) is kept: it is a convex vertex of exterior angle π."""
    if len(ring) <= 2:
        return ring
    keep = np.ones(len(ring), bool)
    same = (ring == np.roll(ring, -1, 0)).all(axis=1)
    ring = ring[~same]
    while True:  # removing a vertex can make its neighbours collinear: repeat
        if len(ring) <= 2:
            return ring
        prv = np.roll(ring, 1, 0)
        nxt = np.roll(ring, -1, 0)
        o = orient_array(prv, ring, nxt)
        dot = ((ring - prv) * (nxt - ring)).sum(axis=1)
        keep = ~((o == 0) & (dot > 0))
        if keep.all():
            break
        ring = ring[keep]
    return ring


# --------------------------------------------------------------------------------------
# pieces


def _step(r: float, eps: float, m: float, kind: str) -> float:
    """The largest arc angle one corner (outer) or chord (inner) may span."""
    if kind == "outer":
        # corners at (r + m) / cos(φ/2), rounded by up to m: need that ≤ r + ε
        c = (r + m) / (r + eps - m)
        return min(2.0 * math.acos(min(c, 1.0)), _MAX_STEP_OUTER)
    # chords of the circle r − m: the sagitta plus rounding, r − (r − m) cos(φ/2) + m ≤ ε
    c = (r - eps + m) / (r - m)
    if c <= -1.0:
        return _MAX_STEP_INNER
    return min(2.0 * math.acos(min(c, 1.0)), _MAX_STEP_INNER)


class _Curve:
    """The offset curve of one ring whose outside is on its right.

    Per vertex ``j`` (between edge ``j - 1`` and edge ``j``): ``convex[j]`` (exact),
    ``chain[j]`` the corner points of its arc (circumscribed corners, inscribed chord
    points with both tangent points, or miter/square corners), ``T[j]`` the tangent point
    of edge ``j`` at its start and ``E[j]`` that of edge ``j - 1`` at its end (both at
    distance ``rho``), and for a reflex vertex ``X[j]``, the crossing of the two moved
    edges, with ``trim[j]`` when it lies on both of them.
    """

    __slots__ = ("ring", "n", "convex", "chain", "T", "E", "X", "trim", "S")

    def __init__(self, ring, rho, step, kind, join, limit):
        self.ring = ring
        n = self.n = len(ring)
        nxt = np.roll(ring, -1, 0)
        d = nxt - ring  # edge i: ring[i] -> ring[i + 1]
        L = np.hypot(d[:, 0], d[:, 1])
        u = d / L[:, None]
        nrm = np.column_stack([u[:, 1], -u[:, 0]])  # right of the edge: the outside
        uin = np.roll(u, 1, 0)
        nin = np.roll(nrm, 1, 0)  # normal of the incoming edge, where the arc starts
        cr = uin[:, 0] * u[:, 1] - uin[:, 1] * u[:, 0]
        dt = (uin * u).sum(axis=1)
        if n == 2:
            sgn = np.zeros(2, np.int8)
        else:
            sgn = orient_array(np.roll(ring, 1, 0), ring, nxt)
        spike = (sgn == 0) & (dt < 0)
        convex = (sgn > 0) | spike
        theta = np.where(convex, np.arctan2(np.abs(cr), dt), 0.0)
        theta[spike] = math.pi
        self.convex = convex
        self.T = ring + rho * nrm
        self.E = ring + rho * nin
        # chains
        chain: list = [None] * n
        if join == "round":
            alpha = np.arctan2(nin[:, 1], nin[:, 0])
            k = np.where(convex, np.maximum(1, np.ceil(theta / step)), 0).astype(np.int64)
            for j in np.flatnonzero(convex):
                kj = int(k[j])
                phi = theta[j] / kj
                if kind == "outer":
                    a = alpha[j] + (np.arange(kj) + 0.5) * phi
                    R = rho / math.cos(phi / 2)
                    chain[j] = ring[j] + R * np.column_stack([np.cos(a), np.sin(a)])
                else:
                    a = alpha[j] + np.arange(kj + 1) * phi
                    c = ring[j] + rho * np.column_stack([np.cos(a), np.sin(a)])
                    c[0] = self.E[j]
                    c[-1] = self.T[j]
                    chain[j] = c
        else:
            half = theta / 2
            bis = nin + nrm
            with np.errstate(all="ignore"):
                mit = ring + rho * bis / (1.0 + (nin * nrm).sum(axis=1))[:, None]
                h = rho * (limit if join == "miter" else 1.0)
                t = (h - rho * np.cos(half)) / np.sin(half)
            for j in np.flatnonzero(convex):
                if join == "miter" and math.cos(half[j]) * limit >= 1.0:
                    chain[j] = mit[j][None, :]
                else:
                    q1 = self.E[j] + t[j] * uin[j]
                    q2 = self.T[j] - t[j] * u[j]
                    chain[j] = np.vstack([q1, q2])
        self.chain = chain
        # S[i]: where the moved edge i starts on the curve
        S = self.T.copy()
        for j in np.flatnonzero(convex):
            S[j] = chain[j][-1]
        self.S = S
        # trimming at reflex vertices
        reflex = sgn < 0
        with np.errstate(all="ignore"):
            X = ring + rho * (nin + nrm) / (1.0 + (nin * nrm).sum(axis=1))[:, None]
            tau = rho * np.tan(np.arctan2(np.abs(cr), dt) / 2)
        self.X = X
        # extent of moved edge i along u_i, measured from ring[i]
        p0 = ((S - ring) * u).sum(axis=1)
        first = np.array([c[0] if c is not None else [np.nan, np.nan] for c in chain])
        cb = np.roll(convex, -1)[:, None]
        endpt = np.where(cb, np.roll(first, -1, 0), np.roll(self.E, -1, 0))
        p1 = ((endpt - ring) * u).sum(axis=1)
        trim = reflex & np.isfinite(tau)
        for _ in range(n + 1):
            a0 = p0 + np.where(trim, tau, 0.0)
            a1 = p1 - np.where(np.roll(trim, -1), np.roll(tau, -1), 0.0)
            bad = ~(a0 <= a1)
            if not bad.any():
                break
            trim &= ~(bad | np.roll(bad, 1))
        self.trim = trim

    def closed(self) -> np.ndarray:
        """The whole curve, trimmed at every trimmable reflex vertex."""
        out = []
        n, conv, trim = self.n, self.convex, self.trim
        for i in range(n):
            if not conv[i] and not trim[i]:
                out.append(self.T[i][None, :])
            b = (i + 1) % n
            if conv[b]:
                out.append(self.chain[b])
            elif trim[b]:
                out.append(self.X[b][None, :])
            else:
                out.append(np.vstack([self.E[b], self.ring[b]]))
        return np.concatenate(out)

    def chunk(self, i0: int, i1: int) -> np.ndarray:
        """The ring of edges ``i0..i1`` (inclusive, cyclic): from ``ring[i0]`` along the
        curve and back along the polygon. Its interior is the union of the edges' pieces
        when it is simple and counter-clockwise."""
        n, conv, trim = self.n, self.convex, self.trim
        out = [self.ring[i0][None, :], self.S[i0][None, :]]
        cnt = (i1 - i0) % n
        for q in range(cnt + 1):
            i = (i0 + q) % n
            if q > 0 and not conv[i] and not trim[i]:
                out.append(self.T[i][None, :])
            b = (i + 1) % n
            if conv[b]:
                out.append(self.chain[b])
            elif trim[b] and q < cnt:
                out.append(self.X[b][None, :])
            elif q < cnt:
                out.append(np.vstack([self.E[b], self.ring[b]]))
            else:
                out.append(self.E[b][None, :])
        idx = (i0 + np.arange(cnt + 1, 0, -1)) % n
        out.append(self.ring[idx])
        return np.concatenate(out)


def _point_disk(c: np.ndarray, rho: float, step: float, kind: str) -> np.ndarray:
    t = 2.0 * math.pi
    k = max(3, math.ceil(t / step))
    if kind == "outer":
        a = (np.arange(k) + 0.5) * (t / k)
        R = rho / math.cos(t / k / 2)
    else:
        a = np.arange(k) * (t / k)
        R = rho
    return c + R * np.column_stack([np.cos(a), np.sin(a)])


def _linearrings(rings: list[np.ndarray]) -> np.ndarray:
    import shapely

    lens = np.fromiter((len(c) for c in rings), np.int64, len(rings))
    ids = np.repeat(np.arange(len(rings)), lens)
    return shapely.linearrings(np.concatenate(rings), indices=ids)


def _assemble(rings: list[np.ndarray]) -> Any:
    """The polygon whose winding number is that of the closed curves ``rings``, or None
    when they are not disjoint simple rings that nest into a valid (multi)polygon."""
    import shapely

    lr = _linearrings(rings) if rings else []
    if not len(lr) or not shapely.is_simple(lr).all():
        return None
    ccw = shapely.is_ccw(lr)
    shells = [shapely.Polygon(x) for x, c in zip(lr, ccw) if c]
    holes = [x for x, c in zip(lr, ccw) if not c]
    if not shells:
        return None
    if len(shells) == 1:
        g = shapely.Polygon(lr[ccw][0], holes)
    else:
        own: list[list] = [[] for _ in shells]
        areas = shapely.area(shells)
        for h in holes:
            p = shapely.Point(shapely.get_coordinates(h)[0])
            inside = [k for k, s in enumerate(shells) if s.contains(p)]
            if not inside:
                return None
            own[min(inside, key=lambda k: areas[k])].append(h)
        g = shapely.MultiPolygon([shapely.Polygon(s.exterior, hs) for s, hs in zip(shells, own)])
    return g if shapely.is_valid(g) else None


def _chunks_union(curves: list[_Curve], size: int = 64) -> Any:
    """Union of every edge's piece, computed from chunks of consecutive pieces whose
    rings are simple and counter-clockwise (each then bounds exactly the union of its
    pieces); a chunk that is not is split until single pieces remain."""
    import shapely

    polys = []
    for cv in curves:
        todo = [(i, min(i + size, cv.n) - 1) for i in range(0, cv.n, size)]
        while todo:
            rings = [cv.chunk(i0, i1) for i0, i1 in todo]
            lr = _linearrings(rings)
            pg = shapely.polygons(lr)
            ok = shapely.is_valid(pg) & shapely.is_ccw(lr)
            single = np.array([i0 == i1 for i0, i1 in todo])
            polys.extend(pg[ok | single])
            nxt = []
            for (i0, i1), good in zip(todo, ok):
                if not good and i1 > i0:
                    mid = (i0 + i1) // 2
                    nxt += [(i0, mid), (mid + 1, i1)]
            todo = nxt
    return polys


# --------------------------------------------------------------------------------------
# the offset


def _result(geom: Any) -> Any:
    import shapely

    parts = shapely.get_parts(geom)
    polys = parts[(shapely.get_type_id(parts) == 3) & (shapely.area(parts) > 0)]
    if len(polys) == 0:
        return shapely.Polygon()
    g = polys[0] if len(polys) == 1 else shapely.multipolygons(polys)
    return shapely.orient_polygons(g)


def _drop_slivers(out: Any, geom: Any, gap: float, grow: bool) -> Any:
    """Remove the zero-width slivers that float noding can leave where pieces share an
    edge: a hole of a grow (or a part of a shrink) nearer than ``gap`` to the polygon (its
    boundary). Every true hole (part) lies at least ``gap`` away: that is the guarantee
    itself (``gap`` is its lower distance bound less twice the rounding margin)."""
    import shapely

    if out.is_empty or geom is None:
        return out
    polys = list(shapely.get_parts(out))
    bnd = shapely.boundary(geom)
    keep = []
    changed = False
    for p in polys:
        if not grow:
            if shapely.distance(p, bnd) < gap:
                changed = True
                continue
            keep.append(p)
            continue
        if len(p.interiors):
            hs = shapely.polygons(list(p.interiors))
            ok = shapely.distance(hs, geom) >= gap
            if not ok.all():
                changed = True
                p = shapely.Polygon(p.exterior, [h for h, k in zip(p.interiors, ok) if k])
        keep.append(p)
    if not changed:
        return out
    if not keep:
        return shapely.Polygon()
    return keep[0] if len(keep) == 1 else shapely.MultiPolygon(keep)


def _scale_exponent(rings: list[np.ndarray], r: float) -> int:
    big = max([float(np.abs(x).max()) for x in rings] + [r])
    return -math.frexp(big)[1]


def _offset_one(
    obj: Any, distance: float, tolerance: float | None, approx: str, join: str, limit: float
) -> Any:
    import shapely

    rings, geom = _read(obj, "polygon")
    rings = [_clean(x) for x in rings]
    if distance == 0:
        return _result(geom) if geom is not None else shapely.Polygon()
    r0 = abs(distance)
    e = _scale_exponent(rings, r0)
    s = math.ldexp(1.0, e)
    rings = [x * s for x in rings]
    r = r0 * s
    big = max(float(np.abs(x).max()) for x in rings)
    m = ROUNDING_MARGIN * (big + r)
    grow = distance > 0
    if join == "round":
        # a tolerance beyond half the radius is met by a finer approximation
        eps = min(tolerance * s, r * _MAX_REL_TOLERANCE)
        if eps < 4 * m:
            raise GeometryError(
                f"tolerance: {tolerance!r} is below what float64 can guarantee at these "
                f"magnitudes (about {math.ldexp(4 * m, -e):.3g})",
                argument="tolerance",
                hint="raise the tolerance, or move the polygon nearer to the origin",
            )
        # the pieces' side of the error: grow outer and shrink inner use circumscribed
        # pieces pushed out by m; the other two inscribed pieces pulled in by m
        circ = (approx == "outer") == grow
        kind = "outer" if circ else "inner"
        rho = r + m if circ else r - m
        step = _step(r, eps, m, kind)
    else:
        kind = "sharp"
        rho = r
        step = eps = 0.0
    if geom is not None:
        geom = shapely.affinity.scale(geom, s, s, origin=(0, 0))
    if len(rings) == 1 and len(rings[0]) == 1:
        if not grow:
            return shapely.Polygon()
        if kind == "sharp":
            kind, step = "outer", _MAX_STEP_OUTER
        disk = shapely.Polygon(_point_disk(rings[0][0], rho, step, kind))
        return shapely.transform(disk, lambda c: c / s)
    if not grow:
        if geom is None:
            return shapely.Polygon()
        rings = [x[::-1] for x in rings]
    ckind = "outer" if kind == "sharp" else kind
    curves = [_Curve(x, rho, step, ckind, join, limit) for x in rings]
    closed = [c.closed() for c in curves]
    if not grow:
        closed = [c[::-1] for c in closed]
    out = _assemble(closed)
    if out is None:
        polys = _chunks_union(curves)
        if grow:
            if geom is not None:
                polys = [geom, *polys]
            out = shapely.union_all(polys)
        else:
            out = shapely.difference(geom, shapely.union_all(polys))
    # the least distance of the result's boundary from the polygon('s boundary)
    near = r if (join != "round" or (approx == "outer") == grow) else r - eps
    out = _drop_slivers(_result(out), geom, near - 2 * m, grow)
    if e:
        out = shapely.transform(out, lambda c: c / s)
    return out


def _map(fn: Any, polygon: Any) -> Any:
    """Apply ``fn`` to one polygon, or to each polygon of a container (same kind out)."""
    if not _is_many(polygon):
        return fn(polygon)
    tname = type(polygon).__name__
    items = list(polygon)
    res = [None if g is None else fn(g) for g in items]
    if tname == "GeoSeries":
        return type(polygon)(res, index=polygon.index, crs=polygon.crs)
    if tname == "GeometryArray":
        from geopandas.array import from_shapely

        return from_shapely(res, crs=polygon.crs)
    if isinstance(polygon, np.ndarray):
        out = np.empty(len(res), dtype=object)
        out[:] = res
        return out
    return type(polygon)(res) if isinstance(polygon, tuple) else res


def _check_options(distance, tolerance, approx, join, miter_limit):
    d = _finite_float(distance, "distance")
    if approx not in APPROX:
        raise ValueError(f"approx must be one of {APPROX}, got {approx!r}")
    if join not in JOINS:
        raise ValueError(f"join must be one of {JOINS}, got {join!r}")
    lim = _finite_float(miter_limit, "miter_limit")
    if lim < 1.0:
        raise GeometryError(
            f"miter_limit: must be at least 1, got {miter_limit!r}",
            argument="miter_limit",
            hint="a miter limit of 1 bevels every corner at the offset distance",
        )
    tol = None
    if tolerance is not None:
        tol = _finite_float(tolerance, "tolerance")
        if tol <= 0:
            raise GeometryError(
                f"tolerance: must be positive, got {tolerance!r}",
                argument="tolerance",
                hint="e.g. 1e-3 times the distance",
            )
    elif join == "round":
        raise GeometryError(
            "tolerance: a round join needs a tolerance",
            argument="tolerance",
            hint="e.g. tolerance=1e-3 * abs(distance)",
        )
    return d, tol, lim


def offset(
    polygon: Any,
    distance: float,
    *,
    tolerance: float | None,
    approx: str = "outer",
    join: str = "round",
    miter_limit: float = 2.0,
) -> Any:
    """Grow (``distance > 0``) or shrink (``distance < 0``) a polygon by a disk, with a
    guaranteed one-sided error.

    Parameters
    ----------
    polygon : (n, 2) array_like, shapely Polygon / MultiPolygon, or a container of them
        A convex or simple ring (either orientation), a polygon with holes, or a
        multipolygon; ints, floats or Fractions. A point or a segment (an array of one or
        two points, or collinear points) grows into a disk or a stadium. A list, tuple,
        numpy object array, GeometryArray or GeoSeries of polygons is offset member by
        member and the same kind of container is returned (None stays None).
    distance : float
        The tool radius ``r = |distance|``: positive grows, negative shrinks (a shrink
        may erase parts or split a polygon into several), zero returns the polygon.
    tolerance : float
        The largest error ``ε > 0`` (in the input's units) of a round join. Required for
        ``join="round"``; unused by miter and square joins (pass None).
    approx : {"outer", "inner"}
        Which side of the true set the result lies on (see Returns).
    join : {"round", "miter", "square"}
        ``"round"``: the disk offset. ``"miter"``: the moved edges are extended to meet;
        a corner whose miter point lies farther than ``miter_limit · r`` from its vertex
        is cut off there, square to the bisector. ``"square"``: every convex corner is
        cut off at distance ``r`` from its vertex, square to the bisector.
    miter_limit : float
        See ``join``; at least 1.

    Returns
    -------
    shapely.Polygon or shapely.MultiPolygon
        Valid, exteriors counter-clockwise and holes clockwise; an empty Polygon when a
        shrink erases everything. For ``join="round"`` and ``approx="outer"``: a grow
        satisfies ``P ⊕ D(r) ⊆ result ⊆ P ⊕ D(r + ε)`` and a shrink
        ``P ⊖ D(r) ⊆ result ⊆ P ⊖ D(r − ε)``; for ``approx="inner"``:
        ``P ⊕ D(r − ε) ⊆ result ⊆ P ⊕ D(r)`` and ``P ⊖ D(r + ε) ⊆ result ⊆ P ⊖ D(r)``.
        Each arc of exterior angle ``θ`` gets ``ceil(θ / φ)`` corners (outer; ``φ`` from
        ``r (1/cos(φ/2) − 1) ≤ ε``) or ``ceil(θ / φ) + 1`` vertices (inner; ``φ`` from
        ``r (1 − cos(φ/2)) ≤ ε``), tangent at both ends of the arc. Miter and square
        joins are exact up to the rounding margin; ``approx`` then says on which side of
        the exact polygon the margin puts the result.

    Raises
    ------
    GeometryError
        ``distance``, ``tolerance`` or ``miter_limit`` is not a finite number in range
        (``argument`` names which), or the tolerance is below what float64 can guarantee
        at the input's magnitude (see the module notes on the rounding margin).
    SelfIntersectionError, ShapeError, EmptyGeometryError, NonFiniteError
        Bad polygon.

    See Also
    --------
    offset_arcs : the exact boundary as segments and circular arcs.

    Notes
    -----
    One piece per edge (the moved edge and the arc polygon of its end vertex), then one
    GEOS union (grow) or difference (shrink): O(n + V) pieces' vertices with V the arc
    vertices, union O((n + V) log(n + V)) in GEOS. Every convex/reflex decision is an
    exact orientation; the coordinates are float64 with the rounding margin described in
    the module notes.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> tri = [(0, 0), (4, 0), (0, 3)]
    >>> g = mk.offset(tri, 1, tolerance=1e-3)
    >>> h = mk.offset(tri, 1, tolerance=1e-3, approx="inner")
    >>> h.within(g), 6 + 12 + 3.14159 < g.area < 6 + 12 + 3.1425
    (True, True)
    >>> mk.offset(tri, -0.5, tolerance=1e-3).geom_type
    'Polygon'
    >>> mk.offset([(0, 0), (2, 0), (2, 2), (0, 2)], 1, tolerance=None, join="miter").wkt
    'POLYGON ((-1 -1, 3 -1, 3 3, -1 3, -1 -1))'
    """
    d, tol, lim = _check_options(distance, tolerance, approx, join, miter_limit)
    return _map(lambda p: _offset_one(p, d, tol, approx, join, lim), polygon)


# placeholder until the arc code lands
def offset_arcs(polygon: Any, distance: float) -> Any:  # pragma: no cover
    raise NotImplementedError


class OffsetArcs:  # pragma: no cover
    pass
