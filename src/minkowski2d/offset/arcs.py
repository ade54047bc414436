"""The exact boundary of an offset as segments and circular arcs (:func:`offset_arcs`,
:class:`OffsetArcs`): traced from the core's overlay, verified, repaired."""

from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np

from ..errors import (
    GeometryError,
    OverflowGeometryError,
)
from ..predicates import orient_array
from .curves import (
    _check_underflow,
    _distance_error,
    _finite_float,
    _raise_for,
    _read,
    _run,
    offset,
)

# --------------------------------------------------------------------------------------
# exact arcs

#: An arc whose sagitta is at most this many units in the last place of the largest
#: coordinate is written as a straight segment (it cannot be told from one in float64).
ARC_STRAIGHT_ULPS = 4

#: The resolution of :func:`offset_arcs`' verification, relative to ``r``: a junction is
#: on the exact boundary when its distance from the polygon is ``r`` to within
#: ``VERIFY_RESOLUTION · r`` (or the least tolerance float64 guarantees at the input's
#: magnitude, when that is larger), and a piece runs forwards when its extent is not
#: negative by more than that. It judges junctions computed in float64 from exact
#: features; which features bound the offset comes from the exact overlay.
VERIFY_RESOLUTION = 2.0**-30
#: At most this many rounds of repairs (a feature inserted where a junction is nearer
#: than ``r`` to the polygon, a piece that runs backwards dropped).
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
            from ..plot import plot as _draw

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


def _junctions(
    labels: np.ndarray,
    near: np.ndarray,
    MA0: np.ndarray,
    MA1: np.ndarray,
    U: np.ndarray,
    V: np.ndarray,
    VS: np.ndarray,
    VE: np.ndarray,
    r: float,
    sign: float,
) -> np.ndarray:
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


def _nearest(
    pts: np.ndarray,
    A0: np.ndarray,
    U: np.ndarray,
    L: np.ndarray,
    VS: np.ndarray,
    VE: np.ndarray,
    reach: float,
    chunk: int = 64,
) -> tuple:
    """Label of the nearest feature of the polygon (edge ``e`` >= 0 for its interior,
    ``-1 - v`` for vertex ``v``) and the distance, for each point (float64: a
    construction for the repairs and the verification, not a decision of the offset).
    The points come in boundary order, so consecutive ones are close: a chunk of them
    looks at the edges whose boxes come within ``R`` of the chunk's box (``R`` from
    ``reach`` up, doubled until every point has found an edge within ``R``: no other
    edge can then be nearer)."""
    n = len(pts)
    lab = np.empty(n, np.int64)
    dist = np.empty(n)
    A1 = A0 + L[:, None] * U
    lo, hi = np.minimum(A0, A1), np.maximum(A0, A1)
    span = float(np.ptp(np.concatenate([pts, A0]), axis=0).max()) + 1.0
    for s in range(0, n, chunk):
        P = pts[s : s + chunk]
        p0, p1 = P.min(axis=0), P.max(axis=0)
        R = max(reach, 1e-300)
        while True:
            cand = np.flatnonzero(((hi >= p0 - R) & (lo <= p1 + R)).all(axis=1))
            if len(cand):
                w = P[:, None, :] - A0[None, cand, :]
                t = np.clip((w * U[None, cand]).sum(-1), 0.0, L[None, cand])
                q = w - t[..., None] * U[None, cand]
                d2 = (q * q).sum(-1)
                k = d2.argmin(axis=1)
                rows = np.arange(len(P))
                best = np.sqrt(d2[rows, k])
                if best.max() <= R or len(cand) == len(L) or R > span:
                    e = cand[k]
                    te = t[rows, k]
                    lab[s : s + chunk] = np.where(
                        te <= 0, -1 - VS[e], np.where(te >= L[e], -1 - VE[e], e)
                    )
                    dist[s : s + chunk] = best
                    break
            R *= 2
    return lab, dist


class _Frame(NamedTuple):
    """The polygon's features for tracing: vertices ``V``; edges from ``A0`` to ``A1``
    (vertex ids ``VS``, ``VE``; length ``L``, unit direction ``U``) moved by ``r`` to
    ``MA0``-``MA1``; each vertex's exterior angle on the offset side (``theta``, 0 where
    it is not convex) and the angle where its arc starts (``alpha_in``)."""

    V: np.ndarray
    A0: np.ndarray
    A1: np.ndarray
    VS: np.ndarray
    VE: np.ndarray
    L: np.ndarray
    U: np.ndarray
    MA0: np.ndarray
    MA1: np.ndarray
    theta: np.ndarray
    alpha_in: np.ndarray
    r: float
    sign: float
    slack: float


def _frame(rings: list[np.ndarray], r: float, sign: float, slack: float) -> _Frame:
    starts, ends, vid_s, vid_e = [], [], [], []
    base = 0
    for ring in rings:
        n = len(ring)
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
    return _Frame(V, A0, A1, VS, VE, L, U, MA0, MA1, theta, alpha_in, r, sign, slack)


def _extents(F: _Frame, la: np.ndarray, J: np.ndarray, strict: bool = False) -> np.ndarray:
    """Each piece's extent, negative when it runs backwards: along its moved edge (a
    shrink's rings run against the reversed rings' edges), or the room left in its
    vertex's exterior angle for an arc. ``strict``: also negative when the piece leaves
    its moved edge's segment or its arc's normal cone."""
    r, sign, slack = F.r, F.sign, F.slack
    J1 = np.roll(J, -1, 0)
    ext = np.full(len(la), np.inf)
    ln = la >= 0
    e = la[ln]
    t0 = ((J[ln] - F.MA0[e]) * F.U[e]).sum(axis=1)
    t1 = ((J1[ln] - F.MA0[e]) * F.U[e]).sum(axis=1)
    ext[ln] = sign * (t1 - t0) + slack
    if strict:
        lo, hi = np.minimum(t0, t1), np.maximum(t0, t1)
        ext[ln] = np.minimum(ext[ln], np.minimum(lo + slack, F.L[e] + slack - hi))
    ar = ~ln
    if ar.any():
        v = -1 - la[ar]
        ctr = F.V[v]
        a0 = np.arctan2(J[ar, 1] - ctr[:, 1], J[ar, 0] - ctr[:, 0])
        a1 = np.arctan2(J1[ar, 1] - ctr[:, 1], J1[ar, 0] - ctr[:, 0])
        sw = np.mod(sign * (a1 - a0), 2 * math.pi)
        # a closed full turn (one arc alone) has sweep 0 here: fine
        ext[ar] = F.theta[v] + slack / r - sw
        if strict:
            first = a0 if sign > 0 else a1  # the end nearer the incoming normal
            off = np.mod(first - F.alpha_in[v] + slack / r, 2 * math.pi) - slack / r
            ext[ar] = np.minimum(ext[ar], F.theta[v] + slack / r - (off + sw))
    return ext


def _nearest_feature(F: _Frame, pts: np.ndarray) -> tuple:
    """Label of the nearest feature (edge interior or vertex) and its distance."""
    return _nearest(pts, F.A0, F.U, F.L, F.VS, F.VE, 2 * F.r)


def _junctions_of(F: _Frame, labels: list, near: np.ndarray) -> np.ndarray:
    return _junctions(np.array(labels), near, F.MA0, F.MA1, F.U, F.V, F.VS, F.VE, F.r, F.sign)


def _trace(
    items: list,
    rings: list[np.ndarray],
    r: float,
    sign: float,
    slack: float,
    repairs: int = _MAX_REPAIRS,
) -> tuple[list, bool]:
    """Exact rings of segments and arcs.

    ``items``: polygons, each a list of rings ``(coords, labels)`` tracing the offset
    (``labels`` per segment: the moved edge ``e`` (>= 0) or the arc of vertex ``v``
    (``-1 - v``) it lies on, from the core's overlay; None to label each segment by the
    nearest feature). ``rings``: the polygon's rings with the offset side on their right
    (moved by ``r``); ``sign``: +1 when the arcs turn counter-clockwise (a grow), -1 (a
    shrink); ``slack``: the verification's resolution.
    """
    F = _frame(rings, r, sign, slack)
    tiny = ARC_STRAIGHT_ULPS * math.ulp(max(float(np.abs(F.V).max()), r))
    verified = True
    polys = []
    for item in items:
        out_rings = []
        for c, lab in item:
            rows, ok = _trace_ring(F, c, lab, repairs, tiny)
            verified = verified and ok
            if rows is not None:
                out_rings.append(rows)
        if out_rings:
            polys.append(out_rings)
    return polys, verified


def _trace_ring(F: _Frame, c: np.ndarray, lab: Any, repairs: int, tiny: float) -> tuple:
    """One traced ring as exact rows ``(x, y, bulge, cx, cy)`` (None: no ring), and
    whether it verified."""
    from .._engine import core

    r, sign, slack = F.r, F.sign, F.slack
    if lab is not None and (lab == core.OFFSET_DETOUR).any():
        lab = None  # never expected: the overlay's boundary avoids detours
    if lab is None:
        lab, _ = _nearest_feature(F, (c + np.roll(c, -1, 0)) / 2)
    chg = np.flatnonzero(lab != np.roll(lab, 1))
    if len(chg) == 0:
        if lab[0] >= 0:
            return None, True
        ctr = F.V[-1 - lab[0]]
        circle = [
            [ctr[0] + r, ctr[1], sign, ctr[0], ctr[1]],
            [ctr[0] - r, ctr[1], sign, ctr[0], ctr[1]],
        ]
        return np.array(circle), True
    labels = lab[chg].tolist()
    near = c[chg]
    # two moved edges that meet at a convex vertex meet through its arc (a one-corner arc
    # polygon has no segment of its own to carry the label)
    la = np.array(labels)
    lp = np.roll(la, 1)
    # in the rings' own order, edge e0 comes before e1 (a shrink runs backwards)
    e0, e1 = (lp, la) if sign > 0 else (la, lp)
    e0c, e1c = np.maximum(e0, 0), np.maximum(e1, 0)
    adj = np.flatnonzero((la >= 0) & (lp >= 0) & (F.VE[e0c] == F.VS[e1c]))
    if len(adj):
        turn = orient_array(F.A0[e0c[adj]], F.A1[e0c[adj]], F.A1[e1c[adj]])
        for q in adj[turn > 0][::-1]:
            labels.insert(int(q), int(-1 - F.VS[e1c[q]]))
            near = np.insert(near, q, near[q], axis=0)
    labels, J = _repaired(F, labels, near, repairs)
    # verify: every junction on the true boundary, every piece of positive extent
    _, dist = _nearest_feature(F, J)
    ext = _extents(F, np.array(labels), J, strict=True)
    ok = not ((np.abs(dist - r) > slack).any() or (ext < 0).any())
    return _rows(F, labels, J, tiny), ok


def _repaired(F: _Frame, labels: list, near: np.ndarray, repairs: int) -> tuple:
    """The labels and junctions after at most ``repairs`` rounds of repairs."""
    r, slack = F.r, F.slack
    J = _junctions_of(F, labels, near)
    for _ in range(repairs):
        # a piece whose exact extent is negative (a moved edge run backwards, an arc
        # beyond its vertex's normals) is not on the true boundary: the trace was too
        # coarse to see its neighbours meet first; drop it
        la = np.array(labels)
        if len(la) > 2:
            ext = _extents(F, la, J)
            worst = int(np.argmin(ext))
            if ext[worst] < 0:
                del labels[worst]
                near = np.delete(near, worst, axis=0)
                J = _junctions_of(F, labels, near)
                continue
        # a junction nearer than r to the polygon is not on the true boundary: a piece
        # too short for the trace lies between; insert the nearest feature
        f, dist = _nearest_feature(F, J)
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
        J = _junctions_of(F, labels, near)
    return labels, J


def _rows(F: _Frame, labels: list, J: np.ndarray, tiny: float) -> np.ndarray | None:
    """Rows ``(x, y, bulge, cx, cy)`` from the bottom-most junction (None when fewer than
    two distinct points remain); an arc too flat to tell from its chord is a segment."""
    r, sign = F.r, F.sign
    g = len(labels)
    rows = np.empty((g, 5))
    rows[:, :2] = J
    rows[:, 2] = 0.0
    rows[:, 3:] = np.nan
    lab_arr = np.array(labels)
    arc = np.flatnonzero(lab_arr < 0)
    if len(arc):
        ctr = F.V[-1 - lab_arr[arc]]
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
    if keep.sum() < 2:
        return None
    rows = rows[keep]
    first = np.lexsort((rows[:, 0], rows[:, 1]))[0]  # bottom-most, then left-most
    return np.roll(rows, -first, 0)


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
    Which pieces bound the offset, and in which order, is read from the certified outer
    polygon approximation at ``1e-2 · r`` computed by the core: each of its edges lies on
    a moved edge or an arc polygon of one feature, which the exact overlay reports. The
    junctions are then computed from the pieces in float64 and verified to
    :data:`VERIFY_RESOLUTION` (refined at ``1e-4 · r`` and ``1e-6 · r`` when they do not
    verify). An arc shorter than that approximation resolves, at a crossing, is not seen
    (its end points differ from the crossing by less than ``1e-2 · r``).

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
    inp = _read(polygon, "polygon")
    _check_underflow(max(float(np.abs(inp.xy).max()) if len(inp.xy) else 0.0, abs(d)))
    if len(inp.ring_off) == 2 and inp.ring_off[1] == 1:
        if d < 0:
            return OffsetArcs([], d, polygon)
        cx, cy = (float(v) for v in inp.xy[0])
        r = abs(d)
        ring = np.array([[cx + r, cy, 1.0, cx, cy], [cx - r, cy, 1.0, cx, cy]])
        return OffsetArcs([[ring]], d, polygon)
    from .._engine import core

    best = None
    ok = plausible = False
    for rel in _TRACE_TOLERANCES:
        res = _run([inp], d, rel * abs(d), "outer", "round", 2.0,
                   _distance_error(distance, d), labels=True)  # fmt: skip
        xy, ro, po, _go, info, extra = res
        status, code, least = int(info[0, 0]), int(info[0, 1]), float(info[0, 2])
        if code == core.OFFSET_TOLERANCE and best is not None:
            break  # finer than float64 allows at this magnitude: keep the best so far
        _raise_for(code, status, least, distance, rel * abs(d))
        if len(po) == 1:
            return OffsetArcs([], d, polygon)
        lab, uxy, uoff, e0 = extra
        r = math.ldexp(abs(d), -e0)
        rings = [uxy[uoff[k] : uoff[k + 1]] for k in range(len(uoff) - 1)]
        # the traced outer polygon (scaled by 2**-e0): rings with the label of each edge
        items = [
            [(xy[ro[k] : ro[k + 1] - 1], lab[ro[k] : ro[k + 1] - 1]) for k in range(a, b)]
            for a, b in zip(po[:-1].tolist(), po[1:].tolist())
        ]
        length, reg_area, parts, holes = _measures(xy, ro, po)
        # the exact set lies inside the traced outer polygon, within a band of width
        # rel·r along its boundary, and it has the traced polygon's topology
        slack = max(VERIFY_RESOLUTION * r, math.ldexp(least, -e0))
        band = length * rel * r
        slack_a = slack * length
        sign = 1.0 if d > 0 else -1.0
        for repairs in (0, _MAX_REPAIRS):
            polys, ok = _trace(items, rings, r, sign, slack, repairs)
            area = OffsetArcs(polys, r).area
            plausible = (
                len(polys) == parts
                and sum(len(p) - 1 for p in polys) == holes
                and reg_area - band - slack_a <= area <= reg_area + slack_a
            )
            if plausible and best is None:
                best = (polys, e0)
            if ok and plausible:
                break
        if ok and plausible:
            best = (polys, e0)
            break
    verified = bool(ok and plausible)
    if best is not None:
        polys, e0 = best
    return _scaled(polys, e0, d, polygon, verified)


def _measures(xy: np.ndarray, ro: np.ndarray, po: np.ndarray) -> tuple[float, float, int, int]:
    """The traced polygon's boundary length, area, and numbers of parts and holes."""
    seg = xy[1:] - xy[:-1]
    closing = np.zeros(len(xy) - 1, bool)
    closing[ro[1:-1] - 1] = True  # no segment from one ring's end to the next's start
    seg = seg[~closing]
    length = float(np.hypot(seg[:, 0], seg[:, 1]).sum())
    x0, y0 = xy[:-1, 0][~closing], xy[:-1, 1][~closing]
    x1, y1 = xy[1:, 0][~closing], xy[1:, 1][~closing]
    reg_area = 0.5 * float((x0 * y1 - x1 * y0).sum())
    return length, reg_area, len(po) - 1, (len(ro) - 1) - (len(po) - 1)


def _scaled(polys: list, e0: int, d: float, polygon: Any, verified: bool) -> OffsetArcs:
    """The traced rings scaled back by ``2**e0``; an infinite coordinate is an error."""
    for p in polys:
        for ring in p:
            ring[:, [0, 1, 3, 4]] = np.ldexp(ring[:, [0, 1, 3, 4]], e0)
    out = OffsetArcs(polys, d, polygon, verified)
    if not all(np.isfinite(ring[:, :3]).all() for ring in out.rings):
        raise OverflowGeometryError(
            "result: the offset does not fit in float64 (a coordinate is infinite)",
            argument="result",
            hint="scale the input down (or offset by a smaller distance)",
        )
    return out
