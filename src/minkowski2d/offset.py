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

The pieces' boundaries telescope into the *offset curve* (moved edges, arc polygons at
convex vertices, a detour through each reflex vertex) plus ``∂P``, so a grow is where the
curve's winding number is positive. Trimmed at every reflex vertex where the two moved
edges cross (the cut-off loop lies inside both neighbouring pieces), the curve is usually
a set of disjoint simple rings: then, checked by one GEOS validity test, they *are* the
result and no Boolean operation runs. Otherwise (a gap, slot or hole closes, a shrink
splits or erases parts) GEOS unions the pieces, merged first into chunks of consecutive
pieces whose rings are simple (each then bounds exactly its pieces' union).

The unions are computed by GEOS in float64. Their vertices are rounded, so the pieces are
built for the radius ``r ± m`` with the *rounding margin* ``m = ROUNDING_MARGIN · (max |x| +
r)`` (:data:`ROUNDING_MARGIN` = 2⁻⁴²): a vertex moved by rounding can never cross the
true boundary, and the arcs get the budget ``ε − 2m``. A tolerance below ``4m`` cannot be
met in float64 and raises :class:`~minkowski2d.errors.GeometryError`. An input whose
magnitude lies outside ``[2**-256, 2**256]`` is rescaled by a power of two (exact) into
GEOS's comfortable range and back; Fractions and
integers beyond 2⁵³ are rounded to float64 once (also within the margin).

Examples
--------
>>> import minkowski2d as mk
>>> sq = [(0, 0), (2, 0), (2, 2), (0, 2)]
>>> g = mk.offset(sq, 1.0, tolerance=0.01)
>>> g.area > 4 + 8 + 3.14159, g.area - (4 + 8 + 3.14159) < 2 * 3.1416 * 0.01
(True, True)
>>> mk.offset(sq, -0.5, tolerance=0.01).bounds  # doctest: +ELLIPSIS
(0.49999999..., 0.49999999..., 1.50000000..., 1.50000000...)
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any

import numpy as np

from . import _options
from ._coerce import as_array
from ._geos import area_parts, checked_polygonal
from .errors import (
    GeometryError,
    OverflowGeometryError,
    ShapeError,
)
from .predicates import orient_array

__all__ = ["offset", "offset_arcs", "OffsetArcs", "ROUNDING_MARGIN", "APPROX", "JOINS"]

#: Relative size of the rounding margin ``m = ROUNDING_MARGIN · (max |coordinate| + r)``
#: by which the pieces are pushed away from the true boundary, so that float64 rounding
#: of the union's vertices (a few units in the last place) cannot cross it.
ROUNDING_MARGIN = 2.0**-42

#: The default ``tolerance`` of :func:`offset`, relative to the radius: ``1e-3 · |r|``
#: (raised to the least tolerance float64 can guarantee at the input's magnitude, see
#: :data:`ROUNDING_MARGIN`, when that is larger).
DEFAULT_TOLERANCE = 1e-3

#: The tolerance actually used is at most this fraction of the radius (a coarser one is
#: met by a finer approximation).
_MAX_REL_TOLERANCE = 0.5

#: Magnitudes GEOS handles without underflow or overflow in its intersection arithmetic;
#: outside this range the input is scaled by a power of two (exactly) and back.
_COMFORT_LO, _COMFORT_HI = 2.0**-256, 2.0**256

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
    return _options.real(v, name)


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
    if not geom.is_empty and not shapely.is_valid(geom) and gt == "MultiPolygon":
        parts = shapely.get_parts(geom)
        if shapely.is_valid(parts).all():
            # parts that touch or overlap: their union has the same offset
            geom = shapely.union_all(parts)
    return checked_polygonal(
        geom,
        name,
        hint="repair it first, e.g. shapely.make_valid",
        nonfinite_hint="remove NaN and inf",
    )


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
        try:
            data = np.array([(float(Fraction(x)), float(Fraction(y))) for x, y in data])
        except OverflowError:
            data = None
        if data is None or not np.isfinite(data).all():
            raise OverflowGeometryError(
                f"{name}: a coordinate does not fit in float64",
                argument=name,
                hint="scale the input down",
            )
    data = np.asarray(data, dtype=np.float64)
    if len(data) > 1 and (data[0] == data[-1]).all():
        data = data[:-1]
    if len(data) >= 3:
        # the common case: a valid ring with area (the float shoelace only picks this
        # path; GEOS's robust orientation test decides the direction)
        x, y = data[:, 0], data[:, 1]
        with np.errstate(all="ignore"):
            area2 = float(x @ np.roll(y, -1) - y @ np.roll(x, -1))
        if area2 != 0.0 and math.isfinite(area2):
            geom = shapely.Polygon(data)
            if shapely.is_valid(geom):
                if not shapely.is_ccw(geom.exterior):
                    data = data[::-1].copy()
                    geom = shapely.Polygon(data)
                return [data], geom
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


def _clean(ring: np.ndarray) -> tuple[np.ndarray, np.ndarray | None]:
    """Drop repeated and exactly collinear vertices (exact orientation); a spike (a turn
    of a half-turn) is kept: it is a convex vertex of exterior angle π. Returns the ring
    and the exact orientation of each vertex's turn (None for fewer than 3 vertices)."""
    if len(ring) <= 2:
        return ring, None
    same = (ring == ring[np.arange(1, len(ring) + 1) % len(ring)]).all(axis=1)
    if same.any():
        ring = ring[~same]
    while True:  # removing a vertex can make its neighbours collinear: repeat
        n = len(ring)
        if n <= 2:
            return ring, None
        prv = ring[np.arange(-1, n - 1) % n]
        nxt = ring[np.arange(1, n + 1) % n]
        o = orient_array(prv, ring, nxt)
        if not (o == 0).any():
            return ring, o
        dot = ((ring - prv) * (nxt - ring)).sum(axis=1)
        keep = ~((o == 0) & (dot > 0))
        if keep.all():
            return ring, o
        ring = ring[keep]


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


_DETOUR = -(2**62)


class _Curve:
    """The offset curve of one ring whose outside is on its right.

    Per vertex ``j`` (between edge ``j - 1`` and edge ``j``): ``convex[j]`` (exact),
    ``chain[j]`` the corner points of its arc (circumscribed corners, inscribed chord
    points with both tangent points, or miter/square corners), ``T[j]`` the tangent point
    of edge ``j`` at its start and ``E[j]`` that of edge ``j - 1`` at its end (both at
    distance ``rho``), and for a reflex vertex ``X[j]``, the crossing of the two moved
    edges, with ``trim[j]`` when it lies on both of them.
    """

    __slots__ = (
        "ring",
        "n",
        "convex",
        "chain",
        "T",
        "E",
        "X",
        "trim",
        "S",
        "allc",
        "cstart",
        "ccnt",
    )

    def __init__(self, ring, rho, step, kind, join, limit, sgn=None):
        self.ring = ring
        n = self.n = len(ring)
        NX = np.arange(1, n + 1) % n
        PV = np.arange(-1, n - 1) % n
        nxt = ring[NX]
        d = nxt - ring  # edge i: ring[i] -> ring[i + 1]
        L = np.hypot(d[:, 0], d[:, 1])
        u = d / L[:, None]
        nrm = np.column_stack([u[:, 1], -u[:, 0]])  # right of the edge: the outside
        uin = u[PV]
        nin = nrm[PV]  # normal of the incoming edge, where the arc starts
        cr = uin[:, 0] * u[:, 1] - uin[:, 1] * u[:, 0]
        dt = (uin * u).sum(axis=1)
        if n == 2:
            sgn = np.zeros(2, np.int8)
        elif sgn is None:
            sgn = orient_array(ring[PV], ring, nxt)
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
            cnt = k if kind == "outer" else np.where(convex, k + 1, 0)
            vid = np.repeat(np.arange(n), cnt)
            start = np.cumsum(cnt) - cnt
            jj = np.arange(int(cnt.sum())) - start[vid]
            phi = theta / np.maximum(k, 1)
            if kind == "outer":
                a = alpha[vid] + (jj + 0.5) * phi[vid]
                R = (rho / np.cos(phi / 2))[vid]
            else:
                a = alpha[vid] + jj * phi[vid]
                R = np.full(len(vid), rho)
            allc = ring[vid] + R[:, None] * np.column_stack([np.cos(a), np.sin(a)])
            if kind == "inner":
                allc[start[convex]] = self.E[convex]
                allc[(start + cnt - 1)[convex]] = self.T[convex]
            for j in np.flatnonzero(convex):
                chain[j] = allc[start[j] : start[j] + cnt[j]]
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
        if join != "round":
            ccnt = np.array([0 if c is None else len(c) for c in chain], np.int64)
            cstart = np.cumsum(ccnt) - ccnt
            allc = np.concatenate([c for c in chain if c is not None] or [np.empty((0, 2))])
        else:
            ccnt, cstart = cnt, start
        self.allc, self.cstart, self.ccnt = allc, cstart, ccnt
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
        cb = convex[NX][:, None]
        endpt = np.where(cb, first[NX], self.E[NX])
        p1 = ((endpt - ring) * u).sum(axis=1)
        trim = reflex & np.isfinite(tau)
        for _ in range(n + 1):
            a0 = p0 + np.where(trim, tau, 0.0)
            a1 = p1 - np.where(trim[NX], tau[NX], 0.0)
            bad = ~(a0 <= a1)
            if not bad.any():
                break
            trim &= ~(bad | bad[PV])
        self.trim = trim

    def closed(self) -> tuple[np.ndarray, np.ndarray]:
        """The whole curve, trimmed at every trimmable reflex vertex, and a label for
        each of its segments (point ``k`` to ``k + 1``): edge ``i`` moved (``i``), the arc
        of vertex ``j`` (``-1 - j``), or a detour through a vertex (:data:`_DETOUR`)."""
        n, conv, trim = self.n, self.convex, self.trim
        b = np.arange(1, n + 1) % n
        head = (~conv & ~trim).astype(np.int64)  # T_i before the edge's tail
        cb, tb = conv[b], trim[b]
        tcnt = np.where(cb, self.ccnt[b], np.where(tb, 1, 2))
        per = head + tcnt
        off = np.cumsum(per) - per
        total = int(per.sum())
        # every point's source: T (n), chain corners, X (n), E (n), ring (n)
        nc = len(self.allc)
        src = np.concatenate([self.T, self.allc, self.X, self.E, self.ring])
        bT, bC, bX, bE, bR = 0, n, n + nc, 2 * n + nc, 3 * n + nc
        idx = np.empty(total, np.int64)
        lab = np.empty(total, np.int64)
        hi = np.flatnonzero(head)
        idx[off[hi]] = bT + hi
        lab[off[hi]] = hi
        # tails: position within the tail j, edge e
        e = np.repeat(np.arange(n), tcnt)
        j = np.arange(int(tcnt.sum())) - np.repeat(np.cumsum(tcnt) - tcnt, tcnt)
        pos = off[e] + head[e] + j
        be = b[e]
        isc = cb[e]
        ist = ~isc & tb[e]
        isd = ~isc & ~tb[e]
        idx[pos[isc]] = bC + self.cstart[be[isc]] + j[isc]
        last = j == self.ccnt[be] - 1
        lab[pos[isc]] = np.where(last[isc], be[isc], -1 - be[isc])
        idx[pos[ist]] = bX + be[ist]
        lab[pos[ist]] = be[ist]
        idx[pos[isd]] = np.where(j[isd] == 0, bE, bR) + be[isd]
        lab[pos[isd]] = _DETOUR
        return src[idx], lab

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


def _assemble(rings: list[np.ndarray]) -> tuple[Any, list] | None:
    """The polygon whose winding number is that of the closed curves ``rings``, and its
    polygons as lists of ring indices (shell first); None when the rings are not disjoint
    simple rings that nest into a valid (multi)polygon."""
    import shapely

    if not rings:
        return None
    lr = _linearrings(rings)
    ccw = shapely.is_ccw(lr)
    si = np.flatnonzero(ccw)
    hi = np.flatnonzero(~ccw)
    if len(si) == 0:
        return None
    if len(si) == 1:
        groups = [[int(si[0]), *hi.tolist()]]
    else:
        shells = shapely.polygons(lr[si])
        areas = shapely.area(shells)
        groups = [[int(k)] for k in si]
        for h in hi:
            pt = shapely.points(rings[h][0])
            inside = np.flatnonzero(shapely.contains(shells, pt))
            if not len(inside):
                return None
            groups[int(inside[np.argmin(areas[inside])])].append(int(h))
    polys = [shapely.Polygon(lr[g[0]], lr[g[1:]]) for g in groups]
    geom = polys[0] if len(polys) == 1 else shapely.MultiPolygon(polys)
    return (geom, groups) if shapely.is_valid(geom) else None


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

    g = area_parts(geom)
    if g.is_empty:
        return g
    # each ring from its least (x, y) vertex; exteriors counter-clockwise, holes clockwise
    return shapely.orient_polygons(shapely.normalize(g))


def _drop_slivers(out: Any, geom: Any, gap: float, grow: bool) -> Any:
    """Remove the zero-width slivers that float noding can leave where pieces share an
    edge: a hole of a grow (or a part of a shrink) nearer than ``gap`` to the polygon (its
    boundary). Every true hole (part) lies at least ``gap`` away: that is the guarantee
    itself (``gap`` is its lower distance bound less twice the rounding margin)."""
    import shapely

    if out.is_empty or geom is None:
        return out
    polys = list(shapely.get_parts(out))
    bnd = shapely.boundary(geom) if not grow else geom
    shapely.prepare(bnd)  # an indexed distance test
    keep = []
    changed = False
    for p in polys:
        if not grow:
            if shapely.dwithin(bnd, p, gap):
                changed = True
                continue
            keep.append(p)
            continue
        if len(p.interiors):
            hs = shapely.polygons(list(p.interiors))
            ok = ~shapely.dwithin(bnd, hs, gap)
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
    """The power of two that brings the largest magnitude near 1, or 0 when it already
    lies in GEOS's comfortable range ``[2**-256, 2**256]``."""
    big = max([float(np.abs(x).max()) for x in rings] + [r])
    if _COMFORT_LO <= big <= _COMFORT_HI:
        return 0
    # at most 2**1000 either way, so that the factor itself is a finite float
    return max(-1000, min(1000, -math.frexp(big)[1]))


def _offset_one(
    obj: Any,
    distance: float,
    tolerance: float | None,
    approx: str,
    join: str,
    limit: float,
    read: tuple | None = None,
    info: dict | None = None,
) -> Any:
    import shapely

    rings, geom = read if read is not None else _read(obj, "polygon")
    cleaned = [_clean(x) for x in rings]
    rings = [c[0] for c in cleaned]
    sgns = [c[1] for c in cleaned]
    if distance == 0:
        return _result(geom) if geom is not None else shapely.Polygon()
    r0 = abs(distance)
    e = _scale_exponent(rings, r0)
    s = math.ldexp(1.0, e)
    if e:
        rings = [x * s for x in rings]
    r = r0 * s
    big = max(float(np.abs(x).max()) for x in rings)
    m = ROUNDING_MARGIN * (big + r)
    grow = distance > 0
    if join == "round":
        # a tolerance beyond half the radius is met by a finer approximation
        if tolerance is None:  # the default: relative to r, at least what float64 can meet
            eps = min(max(DEFAULT_TOLERANCE * r, 4 * m * (1 + 2.0**-20)), r * _MAX_REL_TOLERANCE)
        else:
            eps = min(tolerance * s, r * _MAX_REL_TOLERANCE)
        if eps < 4 * m and tolerance is None:
            raise GeometryError(
                f"distance: {distance!r} is too small for float64 at these magnitudes (the "
                f"least tolerance it can guarantee, about {math.ldexp(4 * m, -e):.3g}, is "
                "more than half of it)",
                argument="distance",
                hint="move the polygon nearer to the origin, or offset by more",
            )
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
    if geom is not None and e:
        geom = shapely.transform(geom, lambda c: c * s)
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
        sgns = [None if o is None else -o[::-1] for o in sgns]
    ckind = "outer" if kind == "sharp" else kind
    curves = [_Curve(x, rho, step, ckind, join, limit, o) for x, o in zip(rings, sgns)]
    closed, labels = [], []
    for c in curves:
        pts, lab = c.closed()
        if not grow:  # the curve of the reversed rings, reversed back
            pts, lab = pts[::-1], np.roll(lab[::-1], -1)
        # start each ring at its least (x, y) vertex, as shapely.normalize does
        k = int(np.lexsort((pts[:, 1], pts[:, 0]))[0])
        closed.append(np.roll(pts, -k, 0))
        labels.append(np.roll(lab, -k))
    asm = _assemble(closed)
    fast = asm is not None
    if fast:
        out = asm[0]
    else:
        polys = _chunks_union(curves)
        if grow:
            if geom is not None:
                polys = [geom, *polys]
            out = shapely.union_all(polys)
        else:
            out = shapely.difference(geom, shapely.union_all(polys))
        # the least distance of the result's boundary from the polygon('s boundary)
        near = r if (join != "round" or (approx == "outer") == grow) else r - eps
        # slivers come from GEOS noding only
        out = _drop_slivers(_result(out), geom, near - 2 * m, grow)
    if info is not None:
        info.update(
            scale=s, rings=rings, r=r, grow=grow, fast=fast, scaled=out,
            closed=closed, labels=labels, groups=asm[1] if fast else None,
        )  # fmt: skip
    if e:
        out = shapely.transform(out, lambda c: c / s)
    return out


def _list_result(res: list) -> np.ndarray:
    out = np.empty(len(res), dtype=object)
    out[:] = res
    return out


def _map(fn: Any, polygon: Any) -> Any:
    """Apply ``fn`` to one polygon, or to each polygon of a container (same kind out)."""
    if not _is_many(polygon):
        return fn(polygon)
    from ._containers import apply, boxed

    if boxed(polygon):
        # GeoSeries / GeometryArray / object arrays: the shared container rules
        return apply(
            lambda ps: _list_result([None if g is None else fn(g) for g in ps]),
            polygon,
            convex=False,
            names=("polygon",),
        )
    # lists and tuples of polygons (containers went through _containers above)
    res = [None if g is None else fn(g) for g in polygon]
    if isinstance(polygon, np.ndarray):
        return _list_result(res)
    return tuple(res) if isinstance(polygon, tuple) else res


def _check_options(distance, tolerance, approx, join, miter_limit):
    d = _finite_float(distance, "distance")
    _options.choice(approx, "approx", APPROX)
    _options.choice(join, "join", JOINS)
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
    return d, tol, lim


def offset(
    polygon: Any,
    distance: float,
    *,
    tolerance: float | None = None,
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
    tolerance : float, optional
        The largest error ``ε > 0`` (in the input's units) of a round join; unused by
        miter and square joins. Default (None): :data:`DEFAULT_TOLERANCE` ``· |r|`` =
        ``1e-3 · |r|``, or the least tolerance float64 can guarantee at the input's
        magnitude when that is larger (about ``2**-40 · (max |x| + r)``, see
        :data:`ROUNDING_MARGIN`). The one-sided guarantee below holds for the tolerance
        used, given or default.
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
    >>> h.within(g), h.area < 6 + 12 + 3.14159 < g.area  # area + perimeter + π r²
    (True, True)
    >>> mk.offset(tri, -0.5, tolerance=1e-3).geom_type
    'Polygon'
    >>> mk.offset([(0, 0), (2, 0), (2, 2), (0, 2)], 1, tolerance=None, join="miter").wkt
    'POLYGON ((-1 -1, 3 -1, 3 3, -1 3, -1 -1))'
    """
    d, tol, lim = _check_options(distance, tolerance, approx, join, miter_limit)
    return _map(lambda p: _finite_result(_offset_one, p, d, tol, approx, join, lim), polygon)


def _finite_result(fn: Any, *args: Any) -> Any:
    """``fn(*args)``, a shapely result, refused when a coordinate overflowed float64
    (an OverflowGeometryError, never inf)."""
    import shapely

    with np.errstate(over="ignore", invalid="ignore"):
        out = fn(*args)
    if not out.is_empty:
        big = float(np.abs(shapely.get_coordinates(out)).max())
        if not math.isfinite(big):
            raise OverflowGeometryError(
                "result: the offset does not fit in float64 (a coordinate is infinite)",
                argument="result",
                hint="scale the input down (or offset by a smaller distance)",
            )
        _check_underflow(big)
    return out


def _check_underflow(big: float) -> None:
    """Refuse results whose magnitude ``big`` is so small that rounding them to float64
    (to multiples of 2**-1074) may exceed the rounding margin, which keeps the error on
    its side: an OverflowGeometryError (an underflow), never a result off its side."""
    if 0.0 < big < _UNDERFLOW:
        raise OverflowGeometryError(
            f"result: the offset underflows float64 (magnitude {big!r}: rounding to float64 "
            "may exceed the guaranteed tolerance)",
            argument="result",
            hint="scale the input up by a power of two, and the result down",
        )


#: Results of a smaller magnitude cannot keep the one-sided guarantee in float64.
_UNDERFLOW = 2.0**-1020


# --------------------------------------------------------------------------------------
# exact arcs

#: An arc whose sagitta is at most this many units in the last place of the largest
#: coordinate is written as a straight segment (it cannot be told from one in float64).
ARC_STRAIGHT_ULPS = 4

#: A traced junction nearer to the polygon than ``r − _JUNCTION_SLACK · (max |x| + r)``
#: is not on the true boundary (a piece was too short for the trace): the nearest feature
#: is inserted there, at most ``_MAX_REPAIRS`` rounds.
_JUNCTION_SLACK = 2.0**-30
_MAX_REPAIRS = 8

#: The relative tolerances of the polygons that :func:`offset_arcs` traces to find which
#: moved edges and arcs bound the offset, and in which order: the next one is tried when
#: a junction of the result is not at distance r (± the slack) from the polygon, or a
#: piece runs backwards.
_TRACE_TOLERANCES = (1e-2, 1e-4, 1e-6)


class OffsetArcs:
    """The exact boundary of an offset: rings of straight segments and circular arcs.

    Attributes
    ----------
    polygons : list of list of (k, 5) float64 ndarray
        One entry per polygon: its exterior ring (counter-clockwise), then its holes
        (clockwise). Row ``i`` of a ring is ``(x, y, bulge, cx, cy)``: the start point of
        piece ``i`` (the piece runs to the start of row ``i + 1``, cyclically), its bulge
        ``tan(sweep / 4)`` (positive counter-clockwise, 0 for a straight piece: the DXF
        LWPOLYLINE convention) and the arc's centre (NaN for a straight piece).
    radius : float
        ``|distance|``: the radius of every arc.
    distance : float
        The signed offset distance.
    verified : bool
        True when every junction was checked to lie at distance ``r`` from the polygon
        (to ``2**-30`` of the coordinates' magnitude), every piece to run forwards within
        its moved edge or its vertex's normal cone, and the area and topology to agree
        with the traced polygon. False (rare, near critical radii of several merging
        parts) means the best plausible tracing is returned unverified.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> arcs = mk.offset_arcs([(0, 0), (2, 0), (2, 1), (0, 1)], 1)
    >>> ring = arcs.polygons[0][0]
    >>> ring.shape, round(float(ring[:, 2].max()), 6)  # tan(90° / 4) for quarter arcs
    ((8, 5), 0.414214)
    >>> round(arcs.area, 6) == round(2 + 6 + 3.141592653589793, 6)
    True
    """

    __slots__ = ("polygons", "radius", "distance", "verified", "_source")

    def __init__(
        self, polygons: list, distance: float, source: Any = None, verified: bool = True
    ) -> None:
        self.polygons = polygons
        self.distance = float(distance)
        self.radius = abs(float(distance))
        self.verified = verified
        self._source = source

    def __repr__(self) -> str:
        n = sum(len(r) for p in self.polygons for r in p)
        a = sum(int((~np.isnan(r[:, 3])).sum()) for p in self.polygons for r in p)
        return f"OffsetArcs({len(self.polygons)} polygons, {n} pieces, {a} arcs)"

    def __len__(self) -> int:
        return len(self.polygons)

    @property
    def rings(self) -> list:
        """Every ring, exteriors and holes, in order."""
        return [r for p in self.polygons for r in p]

    @property
    def area(self) -> float:
        """The exact area (shoelace over the chords plus each arc's circular segment),
        computed at a power-of-two scale (exact) so that no product overflows; an area
        beyond float64 raises :class:`~minkowski2d.errors.OverflowGeometryError`."""
        rings = self.rings
        big = max([float(np.abs(r[:, :2]).max()) for r in rings if len(r)] + [self.radius])
        k = -math.frexp(big)[1] if big > 0 else 0
        rad = math.ldexp(self.radius, k)
        total = 0.0
        for ring in rings:
            x, y = np.ldexp(ring[:, 0], k), np.ldexp(ring[:, 1], k)
            b = ring[:, 2]
            x1, y1 = np.roll(x, -1), np.roll(y, -1)
            total += 0.5 * float((x * y1 - x1 * y).sum())
            arc = b != 0
            if arc.any():
                sweep = 4.0 * np.arctan(b[arc])
                seg = 0.5 * rad**2 * (sweep - np.sin(sweep))
                total += float(seg.sum())
        try:
            return math.ldexp(total, -2 * k)
        except OverflowError:
            raise OverflowGeometryError(
                f"area: {total!r} * 2**{-2 * k} does not fit in float64",
                argument="area",
                hint="scale the polygon down",
            ) from None

    def _plot_(self, ax: Any, **kwargs: Any) -> Any:
        """Draw for :func:`minkowski2d.plot`: the straight pieces and the arcs in two
        colours (arcs sampled for display only, every 2 degrees), arc centres as dots."""
        line = kwargs.pop("linewidth", 1.5)
        for ring in self.rings:
            n = len(ring)
            for i in range(n):
                x0, y0, b, cx, cy = (float(v) for v in ring[i])
                x1, y1 = float(ring[(i + 1) % n, 0]), float(ring[(i + 1) % n, 1])
                if b == 0.0:
                    ax.plot([x0, x1], [y0, y1], color="C0", linewidth=line)
                    continue
                sweep = 4.0 * np.arctan(b)
                t0 = np.arctan2(y0 - cy, x0 - cx)  # display only: no decision here
                ts = t0 + np.linspace(0.0, sweep, max(2, int(abs(sweep) / 0.035) + 2))
                ax.plot(
                    cx + self.radius * np.cos(ts),
                    cy + self.radius * np.sin(ts),
                    color="C3",
                    linewidth=line,
                )
                ax.plot([cx], [cy], ".", color="C3", markersize=3)
        if self._source is not None:
            from .plot import plot as _draw

            _draw(self._source, ax=ax, facecolor="0.85", edgecolor="0.4", **kwargs)
        ax.set_aspect("equal", adjustable="datalim")
        return ax

    def to_polygon(self, tolerance: float | None = None, approx: str = "outer") -> Any:
        """A polygon within ``tolerance`` of this boundary, on the side ``approx`` says:
        the same as :func:`offset` with these arguments (and its guarantee).

        Examples
        --------
        >>> import minkowski2d as mk
        >>> arcs = mk.offset_arcs([(0, 0), (2, 0), (1, 2)], 0.5)
        >>> arcs.to_polygon(1e-3).area > arcs.area > arcs.to_polygon(1e-3, "inner").area
        True
        """
        return offset(self._source, self.distance, tolerance=tolerance, approx=approx)

    def svg_path(self, flip_y: bool = False) -> str:
        """SVG path data: ``M``, ``L`` and ``A`` commands, one closed subpath per ring.

        With ``flip_y`` the y coordinates are negated (SVG's y axis points down), which
        also flips every arc's sweep flag. Fill with ``fill-rule="evenodd"`` or
        ``"nonzero"`` (holes run the other way).

        Examples
        --------
        >>> import minkowski2d as mk
        >>> print(mk.offset_arcs([(0, 0)], 1).svg_path())
        M 1 0 A 1 1 0 0 1 -1 0 A 1 1 0 0 1 1 0 Z
        """
        out = []
        sy = -1.0 if flip_y else 1.0
        r = _num(self.radius)
        for ring in self.rings:
            parts = [f"M {_num(ring[0, 0])} {_num(sy * ring[0, 1])}"]
            k = len(ring)
            for i in range(k):
                x, y = ring[(i + 1) % k, 0], sy * ring[(i + 1) % k, 1]
                b = ring[i, 2]
                if b == 0:
                    if i + 1 < k:
                        parts.append(f"L {_num(x)} {_num(y)}")
                    continue
                sweep = 4.0 * math.atan(b)
                large = 1 if abs(sweep) > math.pi else 0
                pos = (sweep > 0) != flip_y
                parts.append(f"A {r} {r} 0 {large} {1 if pos else 0} {_num(x)} {_num(y)}")
            parts.append("Z")
            out.append(" ".join(parts))
        return " ".join(out)

    def to_svg(self) -> str:
        """A standalone SVG document (y up, as in the input).

        Examples
        --------
        >>> import minkowski2d as mk
        >>> mk.offset_arcs([(0, 0), (1, 0), (0, 1)], 0.2).to_svg().startswith("<svg")
        True
        """
        pts = np.concatenate([r[:, :2] for r in self.rings]) if self.rings else np.zeros((1, 2))
        x0, y0 = pts.min(axis=0) - self.radius
        x1, y1 = pts.max(axis=0) + self.radius
        w, h = max(x1 - x0, 1e-300), max(y1 - y0, 1e-300)
        pad = 0.05 * max(w, h)
        vb = f"{x0 - pad} {-(y1 + pad)} {w + 2 * pad} {h + 2 * pad}"
        stroke = 0.01 * max(w, h)
        return (
            f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{vb}" width="400" '
            f'height="400">\n  <path d="{self.svg_path(flip_y=True)}" fill="#4a90d9" '
            f'fill-opacity="0.4" fill-rule="evenodd" stroke="#1f4e79" '
            f'stroke-width="{stroke}"/>\n</svg>'
        )

    def to_dxf(self, path: Any = None, *, layer: str = "OFFSET") -> Any:
        """The rings as closed LWPOLYLINE entities with bulges (ezdxf).

        Exteriors are counter-clockwise and holes clockwise. Needs the optional
        dependency ezdxf (``pip install minkowski2d[dxf]``).

        Parameters
        ----------
        path : str or path-like, optional
            Where to save the drawing; without it, nothing is written.
        layer : str
            The entities' layer.

        Returns
        -------
        ezdxf.document.Drawing

        Examples
        --------
        >>> import minkowski2d as mk
        >>> doc = mk.offset_arcs([(0, 0), (2, 0), (2, 2), (0, 2)], 1).to_dxf()
        >>> [e.dxftype() for e in doc.modelspace()]
        ['LWPOLYLINE']
        """
        try:
            import ezdxf
        except ImportError as exc:  # pragma: no cover - depends on the environment
            raise ImportError("DXF output needs ezdxf: pip install 'minkowski2d[dxf]'") from exc
        doc = ezdxf.new("R2010")
        msp = doc.modelspace()
        for ring in self.rings:
            pts = [(float(x), float(y), float(b)) for x, y, b in ring[:, :3]]
            msp.add_lwpolyline(pts, format="xyb", close=True, dxfattribs={"layer": layer})
        if path is not None:
            doc.saveas(path)
        return doc


def _num(v: float) -> str:
    v = float(v) + 0.0  # no "-0"
    return repr(v).removesuffix(".0") if v.is_integer() else repr(v)


def _junctions(labels, near, MA0, MA1, U, V, VS, VE, r, sign) -> np.ndarray:
    """Where piece ``labels[q - 1]`` meets piece ``labels[q]`` (moved edge ``i >= 0`` or
    the arc of vertex ``-1 - i``): the tangent point, or the crossing of the two carriers
    (line/line, line/circle, circle/circle) nearest to ``near[q]``; a near-miss (the
    carriers do not quite meet in float64) gives the closest point."""
    a = np.roll(labels, 1)
    b = labels
    J = near.astype(np.float64).copy()
    la, lb = a >= 0, b >= 0
    ia, ib = np.where(la, a, 0), np.where(lb, b, 0)
    va, vb = np.where(la, 0, -1 - a), np.where(lb, 0, -1 - b)
    # line -> its end vertex's arc, arc -> its vertex's next line: tangent points (a
    # shrink's rings run backwards along the rings' edges)
    if sign > 0:
        t1 = la & ~lb & (VE[ia] == vb)
        t2 = ~la & lb & (VS[ib] == va)
        J[t1] = MA1[ia[t1]]
        J[t2] = MA0[ib[t2]]
    else:
        t1 = la & ~lb & (VS[ia] == vb)
        t2 = ~la & lb & (VE[ib] == va)
        J[t1] = MA0[ia[t1]]
        J[t2] = MA1[ib[t2]]
    rest = ~(t1 | t2)
    # line / line
    ll = rest & la & lb
    if ll.any():
        p, u = MA0[ia[ll]], U[ia[ll]]
        q, v = MA0[ib[ll]], U[ib[ll]]
        den = u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]
        with np.errstate(all="ignore"):
            t = ((q[:, 0] - p[:, 0]) * v[:, 1] - (q[:, 1] - p[:, 1]) * v[:, 0]) / den
            X = p + t[:, None] * u
        ok = den != 0
        J[np.flatnonzero(ll)[ok]] = X[ok]
    # line / circle (either order)
    lc = rest & (la != lb)
    if lc.any():
        li = np.where(la, ia, ib)[lc]
        ci = np.where(la, vb, va)[lc]
        p, u, c = MA0[li], U[li], V[ci]
        w = p - c
        bb = (w * u).sum(axis=1)
        disc = bb * bb - ((w * w).sum(axis=1) - r * r)
        h = np.sqrt(np.maximum(disc, 0.0))
        P1 = p + (-bb - h)[:, None] * u
        P2 = p + (-bb + h)[:, None] * u
        nr = near[lc]
        pick = ((P1 - nr) ** 2).sum(axis=1) <= ((P2 - nr) ** 2).sum(axis=1)
        J[lc] = np.where(pick[:, None], P1, P2)
    # circle / circle
    cc = rest & ~la & ~lb
    if cc.any():
        c1, c2 = V[va[cc]], V[vb[cc]]
        dv = c2 - c1
        dd = np.hypot(dv[:, 0], dv[:, 1])
        with np.errstate(all="ignore"):
            e = dv / dd[:, None]
        m = c1 + (dd / 2)[:, None] * e
        h = np.sqrt(np.maximum(r * r - (dd / 2) ** 2, 0.0))
        perp = np.column_stack([-e[:, 1], e[:, 0]])
        P1 = m + h[:, None] * perp
        P2 = m - h[:, None] * perp
        nr = near[cc]
        pick = ((P1 - nr) ** 2).sum(axis=1) <= ((P2 - nr) ** 2).sum(axis=1)
        X = np.where(pick[:, None], P1, P2)
        ok = dd > 0
        J[np.flatnonzero(cc)[ok]] = X[ok]
    return J


def _trace(
    items: list, rings: list[np.ndarray], r: float, sign: float, repairs: int = _MAX_REPAIRS
) -> tuple[list, bool]:
    """Exact rings of segments and arcs.

    ``items``: polygons, each a list of rings ``(coords, labels)`` tracing the offset
    (``labels`` per segment as in :meth:`_Curve.closed`, local to ring ``k`` of ``rings``
    as ``(k, labels)``, or None to label each segment by the nearest feature). ``rings``:
    the polygon's rings with the offset side on their right (moved by ``r``); ``sign``:
    +1 when the arcs turn counter-clockwise (a grow), -1 (a shrink).
    """
    import shapely

    starts, ends, vid_s, vid_e, ebase = [], [], [], [], []
    base = 0
    for ring in rings:
        n = len(ring)
        ebase.append(base)
        idx = np.arange(n)
        if n >= 2:
            starts.append(ring)
            ends.append(np.roll(ring, -1, 0))
            vid_s.append(base + idx)
            vid_e.append(base + (idx + 1) % n)
        base += n
    V = np.concatenate(rings)
    A0, A1 = np.concatenate(starts), np.concatenate(ends)
    VS, VE = np.concatenate(vid_s), np.concatenate(vid_e)
    D = A1 - A0
    L = np.hypot(D[:, 0], D[:, 1])
    U = D / L[:, None]
    N = np.column_stack([U[:, 1], -U[:, 0]])
    MA0, MA1 = A0 + r * N, A1 + r * N  # the moved edges
    # exterior angle of each vertex on the offset side (0 where it is not convex)
    ein = np.empty(len(V), np.int64)
    eout = np.empty(len(V), np.int64)
    ein[VE] = np.arange(len(VE))
    eout[VS] = np.arange(len(VS))
    ui, uo = U[ein], U[eout]
    theta = np.maximum(
        np.arctan2(ui[:, 0] * uo[:, 1] - ui[:, 1] * uo[:, 0], (ui * uo).sum(axis=1)), 0.0
    )
    alpha_in = np.arctan2(N[ein, 1], N[ein, 0])  # where each vertex's arc starts
    tree = None
    verified = [True]
    big = max(float(np.abs(V).max()), r)
    tiny = ARC_STRAIGHT_ULPS * math.ulp(big)
    slack = _JUNCTION_SLACK * (big + r)

    def extents(la, J, strict=False):
        """Each piece's extent, negative when it runs backwards: along its moved edge
        (a shrink's rings run against the reversed rings' edges), or the room left in
        its vertex's exterior angle for an arc. ``strict``: also negative when the piece
        leaves its moved edge's segment or its arc's normal cone."""
        J1 = np.roll(J, -1, 0)
        ext = np.full(len(la), np.inf)
        ln = la >= 0
        e = la[ln]
        t0 = ((J[ln] - MA0[e]) * U[e]).sum(axis=1)
        t1 = ((J1[ln] - MA0[e]) * U[e]).sum(axis=1)
        ext[ln] = sign * (t1 - t0) + slack
        if strict:
            lo, hi = np.minimum(t0, t1), np.maximum(t0, t1)
            ext[ln] = np.minimum(ext[ln], np.minimum(lo + slack, L[e] + slack - hi))
        ar = ~ln
        if ar.any():
            v = -1 - la[ar]
            ctr = V[v]
            a0 = np.arctan2(J[ar, 1] - ctr[:, 1], J[ar, 0] - ctr[:, 0])
            a1 = np.arctan2(J1[ar, 1] - ctr[:, 1], J1[ar, 0] - ctr[:, 0])
            sw = np.mod(sign * (a1 - a0), 2 * math.pi)
            # a closed full turn (one arc alone) has sweep 0 here: fine
            ext[ar] = theta[v] + slack / r - sw
            if strict:
                first = a0 if sign > 0 else a1  # the end nearer the incoming normal
                off = np.mod(first - alpha_in[v] + slack / r, 2 * math.pi) - slack / r
                ext[ar] = np.minimum(ext[ar], theta[v] + slack / r - (off + sw))
        return ext

    def nearest(pts):
        """Label of the nearest feature (edge interior or vertex) and its distance."""
        qi, ei = tree.query_nearest(shapely.points(pts), all_matches=False)
        e = np.empty(len(pts), np.int64)
        e[qi] = ei
        t = ((pts - A0[e]) * U[e]).sum(axis=1)
        lab = np.where(t <= 0, -1 - VS[e], np.where(t >= L[e], -1 - VE[e], e))
        foot = A0[e] + np.clip(t, 0, L[e])[:, None] * U[e]
        return lab, np.hypot(*(pts - foot).T)

    polys = []
    for item in items:
        out_rings = []
        for c, lab in item:
            if lab is not None:
                ring_k, loc = lab
                if (loc == _DETOUR).any():
                    lab = None
                else:
                    b0 = ebase[ring_k]
                    lab = np.where(loc >= 0, loc + b0, loc - b0)
            traced = lab is None
            if traced:
                if tree is None:
                    tree = shapely.STRtree(shapely.linestrings(np.stack([A0, A1], 1)))
                lab, _ = nearest((c + np.roll(c, -1, 0)) / 2)
            chg = np.flatnonzero(lab != np.roll(lab, 1))
            if len(chg) == 0:
                if lab[0] >= 0:
                    continue
                ctr = V[-1 - lab[0]]
                out_rings.append(
                    np.array(
                        [
                            [ctr[0] + r, ctr[1], sign, ctr[0], ctr[1]],
                            [ctr[0] - r, ctr[1], sign, ctr[0], ctr[1]],
                        ]
                    )
                )
                continue
            labels = lab[chg].tolist()
            near = c[chg]
            # two moved edges that meet at a convex vertex meet through its arc (a
            # one-corner arc polygon has no segment of its own to carry the label)
            la = np.array(labels)
            lp = np.roll(la, 1)
            # in the rings' own order, edge e0 comes before e1 (a shrink runs backwards)
            e0, e1 = (lp, la) if sign > 0 else (la, lp)
            e0c, e1c = np.maximum(e0, 0), np.maximum(e1, 0)
            adj = np.flatnonzero((la >= 0) & (lp >= 0) & (VE[e0c] == VS[e1c]))
            if len(adj):
                turn = orient_array(A0[e0c[adj]], A1[e0c[adj]], A1[e1c[adj]])
                for q in adj[turn > 0][::-1]:
                    labels.insert(int(q), int(-1 - VS[e1c[q]]))
                    near = np.insert(near, q, near[q], axis=0)
            J = _junctions(np.array(labels), near, MA0, MA1, U, V, VS, VE, r, sign)
            for _ in range(repairs):
                # a piece whose exact extent is negative (a moved edge run backwards, an
                # arc beyond its vertex's normals) is not on the true boundary: the trace
                # was too coarse to see its neighbours meet first; drop it
                la = np.array(labels)
                if len(la) > 2:
                    ext = extents(la, J)
                    worst = int(np.argmin(ext))
                    if ext[worst] < 0:
                        del labels[worst]
                        near = np.delete(near, worst, axis=0)
                        J = _junctions(np.array(labels), near, MA0, MA1, U, V, VS, VE, r, sign)
                        continue
                # a junction nearer than r to the polygon is not on the true boundary: a
                # piece too short for the trace lies between; insert the nearest feature
                if tree is None:
                    tree = shapely.STRtree(shapely.linestrings(np.stack([A0, A1], 1)))
                f, dist = nearest(J)
                bad = np.flatnonzero(dist < r - slack)
                changed = False
                for q in bad[::-1]:
                    if f[q] in (labels[q - 1], labels[q]):
                        continue
                    labels.insert(int(q), int(f[q]))
                    near = np.insert(near, q, J[q], axis=0)
                    changed = True
                if not changed:
                    break
                J = _junctions(np.array(labels), near, MA0, MA1, U, V, VS, VE, r, sign)
            # verify: every junction on the true boundary, every piece of positive extent
            if tree is None:
                tree = shapely.STRtree(shapely.linestrings(np.stack([A0, A1], 1)))
            _, dist = nearest(J)
            ext = extents(np.array(labels), J, strict=True)
            if (np.abs(dist - r) > slack).any() or (ext < 0).any():
                verified[0] = False
            g = len(labels)
            rows = np.empty((g, 5))
            rows[:, :2] = J
            rows[:, 2] = 0.0
            rows[:, 3:] = np.nan
            lab_arr = np.array(labels)
            arc = np.flatnonzero(lab_arr < 0)
            if len(arc):
                ctr = V[-1 - lab_arr[arc]]
                s0 = J[arc]
                s1 = J[(arc + 1) % g]
                a0 = np.arctan2(s0[:, 1] - ctr[:, 1], s0[:, 0] - ctr[:, 0])
                a1 = np.arctan2(s1[:, 1] - ctr[:, 1], s1[:, 0] - ctr[:, 0])
                if sign > 0:
                    sw = np.mod(a1 - a0, 2 * math.pi)
                else:
                    sw = -np.mod(a0 - a1, 2 * math.pi)
                real = (r * (1 - np.cos(sw / 2)) > tiny) & ~(s0 == s1).all(axis=1)
                arc, ctr, sw = arc[real], ctr[real], sw[real]
                rows[arc, 2] = np.tan(sw / 4)
                rows[arc, 3:] = ctr
            # drop repeated points (a zero-length piece)
            keep = ~((rows[:, :2] == np.roll(rows[:, :2], -1, 0)).all(axis=1))
            if keep.sum() >= 2:
                rows = rows[keep]
                first = np.lexsort((rows[:, 0], rows[:, 1]))[0]  # bottom-most, then left-most
                out_rings.append(np.roll(rows, -first, 0))
        if out_rings:
            polys.append(out_rings)
    return polys, verified[0]


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported, not warned about
def offset_arcs(polygon: Any, distance: float) -> OffsetArcs:
    """The exact boundary of a polygon grown (or shrunk) by a disk: segments and arcs.

    Parameters
    ----------
    polygon : (n, 2) array_like, shapely Polygon or MultiPolygon
        As for :func:`offset` (one polygon, not a container).
    distance : float
        Positive grows, negative shrinks, by ``r = |distance|``.

    Returns
    -------
    OffsetArcs
        Rings of moved edges and arcs of radius ``r`` centred at the polygon's vertices
        (convex ones for a grow, reflex ones for a shrink), with SVG and DXF output.
        Each junction is computed from the two pieces that meet there (the tangent point,
        or the crossing of two lines / a line and a circle / two circles) in float64; an
        arc too flat to tell from its chord in float64 is written as a segment
        (:data:`ARC_STRAIGHT_ULPS`).

    Raises
    ------
    GeometryError
        As for :func:`offset`; also ``distance == 0``.

    Notes
    -----
    Which pieces bound the offset, and in which order, is read from an outer polygon
    approximation at ``1e-2 · r`` (each of its edges is labelled with the nearest feature
    of the polygon: an edge's interior or a vertex); the junctions are then computed
    exactly from the pieces. An arc shorter than that approximation resolves, at a
    crossing, is not seen (its end points differ from the crossing by less than
    ``1e-2 · r``).

    Examples
    --------
    >>> import minkowski2d as mk
    >>> a = mk.offset_arcs([(0, 0), (4, 0), (4, 4), (0, 4)], -1)
    >>> a.polygons[0][0][:, :3].tolist()
    [[1.0, 1.0, 0.0], [3.0, 1.0, 0.0], [3.0, 3.0, 0.0], [1.0, 3.0, 0.0]]
    >>> mk.offset_arcs([(0, 0), (4, 0), (4, 4), (0, 4)], 1).svg_path()[:37]
    'M 0 -1 L 4 -1 A 1 1 0 0 1 5 0 L 5 4 A'
    """
    d = _finite_float(distance, "distance")
    if d == 0:
        raise GeometryError(
            "distance: must not be zero for offset_arcs",
            argument="distance",
            hint="give a positive (grow) or negative (shrink) distance",
        )
    rings, geom = _read(polygon, "polygon")
    _check_underflow(max([float(np.abs(x).max()) for x in rings] + [abs(d)]))
    if len(rings) == 1 and len(rings[0]) == 1:
        if d < 0:
            return OffsetArcs([], d, polygon)
        cx, cy = (float(v) for v in rings[0][0])
        r = abs(d)
        ring = np.array([[cx + r, cy, 1.0, cx, cy], [cx - r, cy, 1.0, cx, cy]])
        return OffsetArcs([[ring]], d, polygon)
    import shapely

    best = None
    for rel in _TRACE_TOLERANCES:
        info: dict = {}
        region = _offset_one(
            polygon, d, rel * abs(d), "outer", "round", 2.0, read=(rings, geom), info=info
        )
        if region.is_empty:
            return OffsetArcs([], d, polygon)
        if info["fast"]:
            closed, labels = info["closed"], info["labels"]
            # each closed curve came from ring k of the rings (same order)
            items = [[(closed[k], (k, labels[k])) for k in g] for g in info["groups"]]
        else:
            items = [
                [(shapely.get_coordinates(x)[:-1], None) for x in [p.exterior, *p.interiors]]
                for p in shapely.get_parts(info["scaled"])
            ]
        # the exact set lies inside the traced outer polygon, within a band of width
        # rel·r along its boundary, and it has the traced polygon's topology
        reg = info["scaled"]
        parts = shapely.get_parts(reg)
        holes = int(shapely.get_num_interior_rings(parts).sum())
        band = reg.length * rel * info["r"]
        slack_a = _JUNCTION_SLACK * reg.area
        for repairs in (0, _MAX_REPAIRS):
            polys, ok = _trace(items, info["rings"], info["r"], 1.0 if d > 0 else -1.0, repairs)
            area = OffsetArcs(polys, info["r"]).area
            plausible = (
                len(polys) == len(parts)
                and sum(len(p) - 1 for p in polys) == holes
                and reg.area - band - slack_a <= area <= reg.area + slack_a
            )
            if plausible and best is None:
                best = (polys, info)
            if ok and plausible:
                break
        if ok and plausible:
            best = (polys, info)
            break
    verified = bool(ok and plausible)
    if best is not None:
        polys, info = best
    s = info["scale"]
    if s != 1.0:
        for p in polys:
            for ring in p:
                ring[:, [0, 1, 3, 4]] /= s
    out = OffsetArcs(polys, d, polygon, verified)
    if not all(np.isfinite(ring[:, :3]).all() for ring in out.rings):
        raise OverflowGeometryError(
            "result: the offset does not fit in float64 (a coordinate is infinite)",
            argument="result",
            hint="scale the input down (or offset by a smaller distance)",
        )
    return out
