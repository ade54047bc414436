"""The exact certificate of a layout: :func:`verify_layout`, trusting no no-fit polygon.

A placement's polygon is ``rotate_part(part, rotation)`` (float64 coordinates) plus the
translation, added exactly: every placed vertex is a double-double ``hi + lo`` (TwoSum).
Per sheet, on those exact vertices:

1. **Candidates.** The boxes of all edges (one ulp wider than the float ``hi``) go into one
   STRtree and are queried with boxes grown by ``max(spacing, margin)``: the pairs of edges
   of two placements, or of a placement and its sheet.
2. **Edge pairs.** Each pair is classified by the exact signs of four orientations: a proper
   crossing, a shared piece (collinear overlap), a contact (an end point of one on the
   other), or apart.
3. **Interiors.** Two valid polygons' interiors meet exactly when their boundaries cross
   properly, or share a piece with both interiors on its same side, or a boundary enters the
   other's interior. The last is decided arc by arc: each boundary ring, cut at its contacts
   with the other boundary, falls into arcs that do not meet that boundary, so one point of
   each arc (a vertex, or the midpoint of a piece between two contacts) is located by exact
   ray casting. Containment in the sheet is the same test against the sheet's complement
   (its rings reversed): a part is inside iff its interior misses the complement's.
4. **Distances.** Two segments that do not cross are at least ``s`` apart iff each end point
   ``a`` is at least ``s`` from the other segment ``b -> c``: with ``w = a - b``,
   ``e = c - b``, ``|w|² >= s²``, ``|a - c|² >= s²`` and (``w·e <= 0`` or ``w·e >= |e|²`` or
   ``(e × w)² >= s² |e|²``). Spacing is checked between parts whose interiors are disjoint,
   the margin between a contained part and every ring of its sheet.

Every sign is an exact sign. It is first computed in float64 from the ``hi`` parts (each
the rounding of the exact value) and certified when ``|v| > 2**-48 · A + 2**-640``, ``A``
being the same expression on absolute values: a polynomial evaluated through at most 7
roundings is within ``γ_7 A`` of its exact value (Higham, *Accuracy and Stability of
Numerical Algorithms*, 2nd ed., §3.1), and ``2**-48 > γ_7 (1 + γ_7)``. Coordinates and
distances above ``2**190`` skip the filter (nothing then overflows, and underflow adds less
than ``2**-660``). What the filter leaves is evaluated in Python integers (every double is
an integer times a power of two: one scale per sheet), or Fractions for spacing and
midpoints. No tolerance anywhere else, no angle.

Time: ``O((n + k) log n)`` for ``n`` edges on a sheet and ``k`` candidate pairs, plus one
``O(m)`` ray cast per arc (vectorized); memory ``O(n + k)``.

Examples
--------
>>> from types import SimpleNamespace as NS
>>> import shapely
>>> sq = shapely.box(0, 0, 1, 1)
>>> at = lambda x, y: NS(part=0, sheet=0, rotation=0, translation=(x, y))
>>> lay = NS(parts=[sq], placements=[at(0.0, 0.0), at(1.0, 0.0), at(2.5, 0.5)],
...          sheets=[shapely.box(0, 0, 3, 2)], spacing=0.0, margin=0.0)
>>> [(v.kind, v.a, v.b) for v in verify_layout(lay)]
[('container', 2, None)]
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any, NamedTuple, cast

import numpy as np

from .._engine import core
from .._engine.polygon import probe, rings_of
from ..errors import GeometryError, OverflowGeometryError
from .nfp import rotate_part

__all__ = ["KINDS", "Violation", "verify_layout"]

#: The kinds of :class:`Violation`, in the order they are listed for one placement.
KINDS = ("overlap", "spacing", "container", "margin")

_REL = 2.0**-48  # 32 u >= γ_7 (1 + γ_7): the filter's relative bound
_ABS = 2.0**-640  # what underflow can add below _CAP (see the module notes)
_CAP = 2.0**190  # the filter's range of magnitudes; beyond it, exact


class Violation(NamedTuple):
    """One failure of the certificate.

    Attributes
    ----------
    kind : str
        ``"overlap"`` (interiors meet), ``"spacing"`` (two parts closer than the spacing),
        ``"container"`` (a part not inside its sheet, or over a keep-out zone) or
        ``"margin"`` (a part closer than the margin to its sheet's boundary).
    a : int
        The placement at fault (its index in ``layout.placements``).
    b : int or None
        The other placement (``a < b``), None for a part against its sheet.
    detail : str
        What was found, with an approximate place or distance (for people; the decision
        is exact).

    Examples
    --------
    >>> v = Violation("overlap", 3, 7, "their boundaries cross near (1, 2)")
    >>> v.argument
    'placements[3], placements[7]'
    >>> str(v)
    'placements[3], placements[7]: overlap: their boundaries cross near (1, 2)'
    """

    kind: str
    a: int
    b: int | None
    detail: str

    @property
    def argument(self) -> str:
        """The placements at fault, as a :class:`~minkowski2d.errors.LayoutError` names
        them."""
        if self.b is None:
            return f"placements[{self.a}]"
        return f"placements[{self.a}], placements[{self.b}]"

    def __str__(self) -> str:
        return f"{self.argument}: {self.kind}: {self.detail}"


# --------------------------------------------------------------------------------------
# numbers


def _two_sum(a: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``hi + lo == a + b`` exactly, ``hi = fl(a + b)`` (Knuth's TwoSum; finite sums)."""
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


def _sign(v: np.ndarray, a: np.ndarray, big: np.ndarray) -> np.ndarray:
    """Certified signs (+1, -1) of float values ``v`` whose expressions on absolute values
    are ``a``; 0 where the filter cannot tell (also where ``big``: beyond ``_CAP``)."""
    bound = _REL * a + _ABS
    s = np.where(v > bound, 1, np.where(v < -bound, -1, 0)).astype(np.int8)
    s[big] = 0
    return s


def _cmp_dd(hu: np.ndarray, lu: np.ndarray, hv: np.ndarray, lv: np.ndarray) -> np.ndarray:
    """Exact signs of ``(hu + lu) - (hv + lv)`` for normalized double-doubles: the ``hi``
    parts decide when they differ (each is the rounding of its value), else the ``lo``."""
    return np.where(hu != hv, np.sign(hu - hv), np.sign(lu - lv)).astype(np.int8)


def _fsign(x: Any) -> int:
    return (x > 0) - (x < 0)


def _i_orient(p: tuple, q: tuple, r: tuple) -> int:
    return _fsign((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]))


def _i_point_seg_far(a: tuple, b: tuple, c: tuple, S: Any) -> bool:
    """Exactly: is point ``a`` at distance² >= ``S`` from segment ``b -> c``?"""
    wx, wy, ex, ey = a[0] - b[0], a[1] - b[1], c[0] - b[0], c[1] - b[1]
    if wx * wx + wy * wy < S or (a[0] - c[0]) ** 2 + (a[1] - c[1]) ** 2 < S:
        return False
    dot, ee = wx * ex + wy * ey, ex * ex + ey * ey
    if dot <= 0 or dot >= ee:
        return True
    cr = ex * wy - ey * wx
    return cr * cr >= S * ee


def _exact(x: Any, name: str) -> Fraction:
    try:
        f = Fraction(x)
    except (TypeError, ValueError, OverflowError) as exc:
        raise GeometryError(f"{name}: not a finite number ({x!r})", argument=name) from exc
    return f


# --------------------------------------------------------------------------------------
# polygons


def _oriented_rings(poly: Any) -> list[np.ndarray]:
    """The rings of a shapely polygon as float64 (m, 2) arrays without closing or repeated
    vertices, each with the interior on its left (shells counter-clockwise, holes
    clockwise; orientation decided exactly)."""
    rings = rings_of(poly)
    ro, po = rings.ring_offsets, rings.polygon_offsets
    shell = np.zeros(len(ro) - 1, bool)
    shell[po[:-1]] = True
    status, _, _, _, orientation, _ = probe(rings)
    out = []
    for r in range(len(ro) - 1):
        c = rings.coords[ro[r] : ro[r + 1]]
        if len(c) > 1 and (c[0] == c[-1]).all():
            c = c[:-1]
        if len(c) > 1:
            c = c[(c != np.roll(c, 1, axis=0)).any(axis=1)]
        if len(c) < 3:
            continue
        o = int(orientation[r]) if status == core.Status.OK else _shoelace_sign(c)
        if o == 0:
            continue
        if (o > 0) != bool(shell[r]):
            c = c[::-1]
        out.append(np.ascontiguousarray(c, dtype=np.float64))
    return out


def _shoelace_sign(c: np.ndarray) -> int:
    """Exact sign of a ring's signed area (rings the validity check rejects)."""
    pts = [(Fraction(x), Fraction(y)) for x, y in c.tolist()]
    return _fsign(sum(p[0] * q[1] - p[1] * q[0] for p, q in zip(pts, pts[1:] + pts[:1])))


class _Geo:
    """The placed rings of one sheet's placements (owners ``0 .. n-1``) and of the sheet's
    complement (owner ``n``: the sheet's rings reversed), as flat arrays. Vertex ``v``
    starts edge ``v``, which ends at ``nxt[v]``."""

    def __init__(self, rings: list[list[np.ndarray]], shifts: list[tuple], sheet: list):
        his, los, nxt, owner, rstart = [], [], [], [], []
        base = 0
        for k, (rs, t) in enumerate(zip([*rings, [c[::-1] for c in sheet]], [*shifts, None])):
            for c in rs:
                if t is None:
                    h, lo = np.array(c, np.float64), np.zeros_like(c, np.float64)
                else:
                    h, lo = _two_sum(c, np.asarray(t, np.float64)[None, :])
                m = len(c)
                his.append(h)
                los.append(lo)
                nxt.append(base + (np.arange(m) + 1) % m)
                owner.append(np.full(m, k, np.int64))
                rstart.append(base)
                base += m
        z2 = np.empty((0, 2))
        self.hi = np.concatenate(his) if his else z2
        self.lo = np.concatenate(los) if los else z2
        self.nxt = np.concatenate(nxt).astype(np.int64) if nxt else np.empty(0, np.int64)
        self.owner = np.concatenate(owner) if owner else np.empty(0, np.int64)
        self.n = len(rings)
        self.rstart = np.array([*rstart, base], np.int64)
        self.ring = np.repeat(np.arange(len(rstart)), np.diff(self.rstart))
        self.roff = np.searchsorted(self.owner[self.rstart[:-1]], np.arange(self.n + 2))
        self.finite = np.isfinite(self.hi).all(axis=1)
        self.big = ~cast(np.ndarray, (np.abs(self.hi) <= _CAP).all(axis=1))
        self.vlo = np.nextafter(self.hi, -np.inf)
        self.vhi = np.nextafter(self.hi, np.inf)
        self.off = np.searchsorted(self.owner, np.arange(self.n + 2))
        self.box = np.array([self._box(slice(self.off[k], self.off[k + 1]))
                             for k in range(self.n + 1)])  # fmt: skip
        rb = [self._box(slice(self.rstart[r], self.rstart[r + 1])) for r in range(len(rstart))]
        self.rbox = np.array(rb).reshape(-1, 4)
        self._scale()
        self._ints: dict[int, tuple[int, int]] = {}

    def _box(self, sl: slice) -> np.ndarray:
        if sl.stop <= sl.start:
            return np.array([np.inf, np.inf, -np.inf, -np.inf])
        lo, hi = self.vlo[sl], self.vhi[sl]
        return np.array([lo[:, 0].min(), lo[:, 1].min(), hi[:, 0].max(), hi[:, 1].max()])

    def _scale(self) -> None:
        """``K``: every coordinate (``hi`` and ``lo``) times ``2**K`` is an integer."""
        vals = np.concatenate([self.hi.ravel(), self.lo.ravel()])
        vals = vals[(vals != 0) & np.isfinite(vals)]
        self.K = int(53 - np.frexp(vals)[1].min()) if len(vals) else 0
        self.unit = Fraction(2) ** self.K  # a length times unit: the integer frame

    def _int(self, x: float) -> int:
        if x == 0:
            return 0
        m, e = math.frexp(x)
        return int(m * 2.0**53) << (e - 53 + self.K)

    def iv(self, v: int) -> tuple[int, int]:
        """Vertex ``v`` exactly, in units of ``2**-K``."""
        p = self._ints.get(v)
        if p is None:
            h, lo = self.hi[v].tolist(), self.lo[v].tolist()
            p = (self._int(h[0]) + self._int(lo[0]), self._int(h[1]) + self._int(lo[1]))
            self._ints[v] = p
        return p

    def approx(self, p: tuple) -> tuple[float, float]:
        """A point in units of ``2**-K`` as the nearest doubles."""
        return float(Fraction(p[0]) / self.unit), float(Fraction(p[1]) / self.unit)

    def at(self, e: int, t: Fraction) -> tuple:
        """The point at parameter ``t`` of edge ``e``, exactly (in units of ``2**-K``)."""
        p, q = self.iv(e), self.iv(int(self.nxt[e]))
        if t == 0:
            return p
        return (p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]))

    # ---------------------------------------------------------------- predicates

    def orient(self, p: np.ndarray, q: np.ndarray, r: np.ndarray) -> np.ndarray:
        """Exact signs of ``orient(p, q, r)`` for arrays of vertex ids."""
        H = self.hi
        px, py, qx, qy, rx, ry = H[p, 0], H[p, 1], H[q, 0], H[q, 1], H[r, 0], H[r, 1]
        with np.errstate(over="ignore", invalid="ignore"):  # big entries: 0, exact below
            v = (qx - px) * (ry - py) - (qy - py) * (rx - px)
            a = (abs(qx) + abs(px)) * (abs(ry) + abs(py)) + (abs(qy) + abs(py)) * (
                abs(rx) + abs(px)
            )
            s = _sign(v, a, self.big[p] | self.big[q] | self.big[r])
        for k in np.flatnonzero(s == 0).tolist():
            s[k] = _i_orient(self.iv(int(p[k])), self.iv(int(q[k])), self.iv(int(r[k])))
        return s

    def cmp(self, u: np.ndarray, v: np.ndarray, axis: int) -> np.ndarray:
        """Exact signs of ``u - v`` along ``axis`` (vertex id arrays)."""
        H, L = self.hi, self.lo
        return _cmp_dd(H[u, axis], L[u, axis], H[v, axis], L[v, axis])

    def within(self, p: np.ndarray, u: np.ndarray, v: np.ndarray) -> np.ndarray:
        """Is vertex ``p`` in the closed box of ``u`` and ``v``? (exact)"""
        inx = self.cmp(p, u, 0) * self.cmp(p, v, 0) <= 0
        return inx & (self.cmp(p, u, 1) * self.cmp(p, v, 1) <= 0)

    def equal(self, p: np.ndarray, q: np.ndarray) -> np.ndarray:
        return (self.cmp(p, q, 0) == 0) & (self.cmp(p, q, 1) == 0)

    def param(self, p: int, e: int) -> Fraction:
        """Parameter of vertex ``p`` (on edge ``e``'s line) along edge ``e``."""
        a, b, c = self.iv(e), self.iv(int(self.nxt[e])), self.iv(p)
        ax = 0 if a[0] != b[0] else 1
        return Fraction(c[ax] - a[ax], b[ax] - a[ax])

    def side(self, v: np.ndarray, P: tuple, pf: float, axis: int) -> np.ndarray:
        """Exact signs of ``vertex - P`` along ``axis`` (``pf``: P's coordinate rounded)."""
        h = self.hi[v, axis]
        s = _sign(h - pf, np.abs(h) + abs(pf), self.big[v] | (abs(pf) > _CAP))
        for k in np.flatnonzero(s == 0).tolist():
            s[k] = _fsign(self.iv(int(v[k]))[axis] - P[axis])
        return s

    def orient_pt(self, p: np.ndarray, q: np.ndarray, P: tuple, pf: tuple) -> np.ndarray:
        """Exact signs of ``orient(p, q, P)`` for vertex id arrays and one exact point."""
        H = self.hi
        px, py, qx, qy = H[p, 0], H[p, 1], H[q, 0], H[q, 1]
        rx, ry = pf
        big = self.big[p] | self.big[q] | (max(abs(rx), abs(ry)) > _CAP)
        with np.errstate(over="ignore", invalid="ignore"):  # big entries: 0, exact below
            v = (qx - px) * (ry - py) - (qy - py) * (rx - px)
            a = (abs(qx) + abs(px)) * (abs(ry) + abs(py)) + (abs(qy) + abs(py)) * (
                abs(rx) + abs(px)
            )
            s = _sign(v, a, big)
        for k in np.flatnonzero(s == 0).tolist():
            s[k] = _i_orient(self.iv(int(p[k])), self.iv(int(q[k])), P)
        return s

    def point_seg(self, a: np.ndarray, b: np.ndarray, c: np.ndarray, s: Fraction) -> np.ndarray:
        """Is vertex ``a`` at distance >= ``s`` from segment ``b -> c``? (exact, arrays)"""
        H = self.hi
        ax, ay, bx, by, cx, cy = H[a, 0], H[a, 1], H[b, 0], H[b, 1], H[c, 0], H[c, 1]
        wx, wy, ex, ey, vx, vy = ax - bx, ay - by, cx - bx, cy - by, ax - cx, ay - cy
        Awx, Awy, Aex = abs(ax) + abs(bx), abs(ay) + abs(by), abs(cx) + abs(bx)
        Aey, Avx, Avy = abs(cy) + abs(by), abs(ax) + abs(cx), abs(ay) + abs(cy)
        sf = float(s)
        S = sf * sf
        big = self.big[a] | self.big[b] | self.big[c] | (sf > _CAP)
        # where ``big`` holds the products may overflow: _sign answers 0 there (exact below)
        with np.errstate(over="ignore", invalid="ignore"):
            t1 = _sign(wx * wx + wy * wy - S, Awx * Awx + Awy * Awy + S, big)
            t2 = _sign(vx * vx + vy * vy - S, Avx * Avx + Avy * Avy + S, big)
            dot, Ad = wx * ex + wy * ey, Awx * Aex + Awy * Aey
            ee, Aee = ex * ex + ey * ey, Aex * Aex + Aey * Aey
            cr, Acr = ex * wy - ey * wx, Aex * Awy + Aey * Awx
            t3 = _sign(dot - ee, Ad + Aee, big)
            t4 = _sign(cr * cr - S * ee, Acr * Acr + S * Aee, big)
        # Kleene logic on +1 (true) / -1 (false) / 0 (the filter cannot tell)
        ok = np.minimum(np.minimum(t1, t2), np.maximum(np.maximum(-_sign(dot, Ad, big), t3), t4))
        Si = (s * self.unit) ** 2
        for k in np.flatnonzero(ok == 0).tolist():
            far = _i_point_seg_far(self.iv(int(a[k])), self.iv(int(b[k])), self.iv(int(c[k])), Si)
            ok[k] = 1 if far else -1
        return ok > 0

    def rings_of_owner(self, x: int) -> range:
        r = self.roff
        return range(int(r[x]), int(r[x + 1]))


def _txt(g: _Geo, P: tuple) -> str:
    x, y = g.approx(P)
    return f"({x:.9g}, {y:.9g})"


# --------------------------------------------------------------------------------------
# candidate edge pairs and their classification


def _candidates(g: _Geo, grow: Fraction) -> tuple[np.ndarray, np.ndarray]:
    """Edge pairs ``(ea, eb)``, ``owner[ea] < owner[eb]``, whose boxes come within
    ``grow`` (a superset: the boxes are widened outward)."""
    import shapely

    nx = g.nxt
    x0 = np.minimum(g.vlo[:, 0], g.vlo[nx, 0])
    y0 = np.minimum(g.vlo[:, 1], g.vlo[nx, 1])
    x1 = np.maximum(g.vhi[:, 0], g.vhi[nx, 0])
    y1 = np.maximum(g.vhi[:, 1], g.vhi[nx, 1])
    tree = shapely.STRtree(shapely.box(x0, y0, x1, y1))
    q = np.flatnonzero(g.owner < g.n)
    d = np.nextafter(float(grow), np.inf) if grow > 0 else 0.0
    lo_x, lo_y = np.nextafter(x0[q] - d, -np.inf), np.nextafter(y0[q] - d, -np.inf)
    hi_x, hi_y = np.nextafter(x1[q] + d, np.inf), np.nextafter(y1[q] + d, np.inf)
    qi, ti = tree.query(shapely.box(lo_x, lo_y, hi_x, hi_y))
    ea, eb = q[qi], ti.astype(np.int64)
    keep = g.owner[ea] < g.owner[eb]
    return ea[keep], eb[keep]


def _position(g: _Geo, p: int, e: int) -> tuple[int, Fraction]:
    """Where vertex ``p``, lying on edge ``e``, is along ``e``'s ring: ``(edge, t)``."""
    q = int(g.nxt[e])
    if g.iv(p) == g.iv(e):
        return (e, Fraction(0))
    if g.iv(p) == g.iv(q):
        return (q, Fraction(0))
    return (e, g.param(p, e))


def _shared_same(
    g: _Geo, a0: np.ndarray, a1: np.ndarray, b0: np.ndarray, b1: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """For collinear edge pairs: (positive-length overlap, same direction)."""
    dx = g.cmp(a1, a0, 0)
    ax = np.where(dx != 0, 0, 1)

    def c(u, v):
        return np.where(ax == 0, g.cmp(u, v, 0), g.cmp(u, v, 1))

    da, db = c(a1, a0), c(b1, b0)
    la, ha = np.where(da > 0, a0, a1), np.where(da > 0, a1, a0)
    lb, hb = np.where(db > 0, b0, b1), np.where(db > 0, b1, b0)
    return (c(la, hb) < 0) & (c(lb, ha) < 0), da == db


def _classify(g: _Geo, ea: np.ndarray, eb: np.ndarray) -> tuple[dict, dict]:
    """Overlap evidence per owner pair (``{(x, y): text}``) from proper crossings and
    pieces shared from the same side, and the contacts (``{(x, y): (positions on x's
    rings, positions on y's rings)}``)."""
    a0, a1, b0, b1 = ea, g.nxt[ea], eb, g.nxt[eb]
    o1, o2 = g.orient(a0, a1, b0), g.orient(a0, a1, b1)
    o3, o4 = g.orient(b0, b1, a0), g.orient(b0, b1, a1)
    found: dict[tuple[int, int], tuple[str, Any]] = {}  # (why, an exact point)
    cross = np.flatnonzero((o1 * o2 < 0) & (o3 * o4 < 0))
    col = np.flatnonzero((o1 == 0) & (o2 == 0))
    overlap, same = _shared_same(g, a0[col], a1[col], b0[col], b1[col])
    for why, ks in (("cross", cross), ("share", col[overlap & same])):
        for k in ks.tolist():
            key = (int(g.owner[ea[k]]), int(g.owner[eb[k]]))
            found.setdefault(key, (why, g.iv(int(ea[k]))))
    on = [
        ((o1 == 0) & g.within(b0, a0, a1), b0, True),  # b0 on edge a
        ((o2 == 0) & g.within(b1, a0, a1), b1, True),
        ((o3 == 0) & g.within(a0, b0, b1), a0, False),  # a0 on edge b
        ((o4 == 0) & g.within(a1, b0, b1), a1, False),
    ]
    contacts: dict[tuple[int, int], tuple[set, set]] = {}
    for mask, pt, of_b in on:
        for k in np.flatnonzero(mask).tolist():
            key = (int(g.owner[ea[k]]), int(g.owner[eb[k]]))
            A, B = contacts.setdefault(key, (set(), set()))
            p, e, f = int(pt[k]), int(ea[k]), int(eb[k])
            if of_b:  # a vertex of y on x's edge e
                B.add((p, Fraction(0)))
                A.add(_position(g, p, e))
            else:
                A.add((p, Fraction(0)))
                B.add(_position(g, p, f))
    return found, contacts


# --------------------------------------------------------------------------------------
# interiors: arcs between contacts, located by ray casting


def _arc_points(g: _Geo, r: int, pos: list) -> list[tuple]:
    """One exact point of each arc of ring ``r`` between consecutive contacts ``pos``
    (``(edge, t)``): a vertex between them, else the midpoint of the piece."""
    start = int(g.rstart[r])
    if not pos:
        return [g.iv(start)]
    ps = sorted(set(pos), key=lambda p: (p[0] - start, p[1]))
    out = []
    for k, (e, t) in enumerate(ps):
        e2, t2 = ps[(k + 1) % len(ps)]
        nv = int(g.nxt[e])
        if e2 == e and t2 > t:
            out.append(g.at(e, (t + t2) / 2))
        elif (e2, t2) == (nv, 0):
            out.append(g.at(e, (t + 1) / 2))
        else:
            out.append(g.iv(nv))
    return out


def _locate(g: _Geo, P: tuple, y: int) -> int:
    """+1 if the exact point ``P`` is inside owner ``y``'s region, 0 on its boundary, -1
    outside (ray casting with exact signs; owner ``n`` is the sheet's complement)."""
    comp = y == g.n
    pf = g.approx(P)
    b = g.box[y]
    if pf[0] < b[0] or pf[0] > b[2] or pf[1] < b[1] or pf[1] > b[3]:
        return 1 if comp else -1
    e = np.arange(g.off[y], g.off[y + 1])
    f = g.nxt[e]
    s0, s1 = g.side(e, P, pf[1], 1), g.side(f, P, pf[1], 1)
    level = np.flatnonzero(s0 == 0)  # vertices at P's height, and horizontal edges there
    if len(level):
        x0 = g.side(e[level], P, pf[0], 0)
        if (x0 == 0).any():
            return 0
        hor = s1[level] == 0
        if hor.any():
            x1 = g.side(f[level[hor]], P, pf[0], 0)
            if (x0[hor] * x1 < 0).any():
                return 0
    up, down = (s0 <= 0) & (s1 > 0), (s1 <= 0) & (s0 > 0)
    st = np.flatnonzero(up | down)
    o = g.orient_pt(e[st], f[st], P, pf)
    if (o == 0).any():
        return 0
    n = np.count_nonzero((o > 0) & up[st]) + np.count_nonzero((o < 0) & down[st])
    res = 1 if n % 2 else -1
    return -res if comp else res


def _enters(g: _Geo, x: int, y: int, pos: set) -> tuple | None:
    """A point of owner ``x``'s boundary inside owner ``y``'s interior, or None."""
    by_ring: dict[int, list] = {}
    for p in pos:
        by_ring.setdefault(int(g.ring[p[0]]), []).append(p)
    bx = g.box[y]
    for r in g.rings_of_owner(x):
        rb = g.rbox[r]
        if y < g.n and (rb[0] > bx[2] or rb[2] < bx[0] or rb[1] > bx[3] or rb[3] < bx[1]):
            continue
        for P in _arc_points(g, r, by_ring.get(r, [])):
            if _locate(g, P, y) > 0:
                return P
    return None


def _owner_pairs(g: _Geo) -> list[tuple[int, int]]:
    """Pairs of placements whose boxes meet, and every placement with the sheet."""
    import shapely

    n = g.n
    b = g.box[:n]
    live = np.flatnonzero(b[:, 0] <= b[:, 2])
    pairs = [(int(x), n) for x in live]
    if len(live) > 1:
        boxes = shapely.box(b[live, 0], b[live, 1], b[live, 2], b[live, 3])
        qi, ti = shapely.STRtree(boxes).query(boxes)
        keep = qi < ti
        pairs += list(zip(live[qi[keep]].tolist(), live[ti[keep]].tolist()))
    return pairs


# --------------------------------------------------------------------------------------
# distances


def _approx_distance(g: _Geo, ea: np.ndarray, eb: np.ndarray) -> float:
    """The float distance of the closest of the segment pairs (for messages only)."""
    top = float(np.abs(g.hi[np.concatenate([ea, eb])]).max()) if len(ea) else 0.0
    unit = 2.0 ** -math.frexp(top)[1] if 0 < top < math.inf else 1.0
    H = g.hi * unit  # exact (a power of two), so that squares do not overflow

    def ps(a, b, c):
        e, w = H[c] - H[b], H[a] - H[b]
        ee = (e * e).sum(axis=1)
        t = np.clip(np.divide((w * e).sum(axis=1), ee, out=np.zeros(len(a)), where=ee > 0), 0, 1)
        return np.hypot(*(w - t[:, None] * e).T)

    na, nb = g.nxt[ea], g.nxt[eb]
    d = np.minimum.reduce([ps(ea, eb, nb), ps(na, eb, nb), ps(eb, ea, na), ps(nb, ea, na)])
    return float(d.min()) / unit if len(d) else math.inf


def _too_close(g: _Geo, ea: np.ndarray, eb: np.ndarray, s: Fraction) -> np.ndarray:
    """For segment pairs that do not cross properly: is their distance below ``s``?"""
    na, nb = g.nxt[ea], g.nxt[eb]
    a = np.concatenate([ea, na, eb, nb])
    b = np.concatenate([eb, eb, ea, ea])
    c = np.concatenate([nb, nb, na, na])
    far = cast(np.ndarray, g.point_seg(a, b, c, s).reshape(4, -1).all(axis=0))
    return ~far


def _distance_violations(
    g: _Geo, ea: np.ndarray, eb: np.ndarray, skip: set, s: Fraction, sheet: bool
) -> dict[tuple[int, int], float]:
    """Owner pairs (not in ``skip``) closer than ``s``: part pairs, or (``sheet``) parts
    and the sheet's rings; with the approximate distance."""
    ox, oy, w = g.owner[ea], g.owner[eb], g.n + 1
    keys = ox * w + oy
    sel = (oy == g.n) if sheet else (oy < g.n)
    sel &= ~np.isin(keys, np.array([x * w + y for x, y in skip], np.int64))
    k = np.flatnonzero(sel)
    close = k[_too_close(g, ea[k], eb[k], s)]
    out: dict[tuple[int, int], float] = {}
    for key in np.unique(keys[close]).tolist():
        m = close[keys[close] == key]
        out[(key // w, key % w)] = _approx_distance(g, ea[m], eb[m])
    return out


# --------------------------------------------------------------------------------------
# the certificate


def _placed(layout: Any, i: int, pl: Any, cache: dict) -> tuple[list, tuple]:
    """Placement ``i``'s oriented rings (rotated, untranslated) and its translation."""
    parts = layout.parts
    p = pl.part
    if not (isinstance(p, (int, np.integer)) and 0 <= p < len(parts)):
        raise GeometryError(f"placements[{i}]: part {p!r} is not an index into parts",
                            argument=f"placements[{i}]")  # fmt: skip
    key = (int(p), pl.rotation)
    if key not in cache:
        cache[key] = _oriented_rings(rotate_part(parts[p], pl.rotation))
    t = tuple(pl.translation)
    name = f"placements[{i}]"
    if len(t) != 2:
        raise GeometryError(f"{name}: translation must be (x, y), not {t!r}", argument=name)
    tf = (float(t[0]), float(t[1]))
    if any(_exact(v, name) != Fraction(w) for v, w in zip(t, tf)):
        raise GeometryError(f"{name}: translation {t!r} is not a pair of float64 values",
                            argument=name)  # fmt: skip
    return cache[key], tf


def _check_sheet(
    layout: Any, members: list[int], k: int, s: Fraction, m: Fraction, cache: dict
) -> list[Violation]:
    """The violations among the placements ``members`` of sheet ``k``."""
    placed = [_placed(layout, i, layout.placements[i], cache) for i in members]
    g = _Geo([r for r, _ in placed], [t for _, t in placed], _oriented_rings(layout.sheets[k]))
    if not g.finite.all():
        i = members[int(g.owner[np.flatnonzero(~g.finite)[0]])]
        raise OverflowGeometryError(
            f"placements[{i}]: a placed coordinate is beyond float64 (±1.8e308)",
            argument=f"placements[{i}]",
        )
    ea, eb = _candidates(g, max(s, m))
    found, contacts = _classify(g, ea, eb)
    for x, y in _owner_pairs(g):
        if (x, y) in found:
            continue
        A, B = contacts.get((x, y), (set(), set()))
        P = _enters(g, x, y, A)
        if P is not None:
            found[(x, y)] = ("inside", P)
            continue
        P = _enters(g, y, x, B)
        if P is not None:
            found[(x, y)] = ("around", P)
    out = [_overlap_violation(g, members, k, x, y, why, P) for (x, y), (why, P) in found.items()]
    if s > 0:
        for (x, y), d in _distance_violations(g, ea, eb, set(found), s, False).items():
            detail = f"distance ≈ {d:.9g} < spacing {float(s):.9g}"
            out.append(Violation("spacing", members[x], members[y], detail))
    if m > 0:
        for (x, _), d in _distance_violations(g, ea, eb, set(found), m, True).items():
            detail = f"distance ≈ {d:.9g} to the boundary of sheet {k} < margin {float(m):.9g}"
            out.append(Violation("margin", members[x], None, detail))
    return out


def _overlap_violation(
    g: _Geo, members: list[int], k: int, x: int, y: int, why: str, P: tuple
) -> Violation:
    at = _txt(g, P)
    if y == g.n:
        text = {
            "cross": f"it crosses the boundary of sheet {k} near {at}",
            "share": f"it lies outside sheet {k} along its boundary near {at}",
            "inside": f"a point of its boundary near {at} is outside sheet {k} or in a "
            "keep-out zone",
            "around": f"the boundary of sheet {k} (its outline or a keep-out zone) passes "
            f"inside it near {at}",
        }[why]
        return Violation("container", members[x], None, text)
    a, b = members[x], members[y]
    text = {
        "cross": f"their boundaries cross near {at}",
        "share": f"they share an edge from the same side near {at}",
        "inside": f"the boundary of placements[{a}] passes inside placements[{b}] near {at}",
        "around": f"the boundary of placements[{b}] passes inside placements[{a}] near {at}",
    }[why]
    return Violation("overlap", min(a, b), max(a, b), text)


def verify_layout(layout: Any) -> list[Violation]:
    """Every violation of a layout's exact certificate (an empty list: it passes).

    The certificate: parts on one sheet have disjoint interiors (touching is allowed; a
    part may lie in another's hole) and, with ``spacing > 0``, are at least ``spacing``
    apart (Euclidean, holes' boundaries included); every part lies inside its sheet and
    off its keep-out zones (the sheet's holes) and, with ``margin > 0``, at least
    ``margin`` from every ring of the sheet. Decided on the placed polygons themselves,
    exactly (module notes); no no-fit polygon is trusted. Parts and sheets are valid
    polygons (a ring's interior is the side on its left once oriented).

    Parameters
    ----------
    layout : Layout
        Anything with ``parts`` (shapely Polygons), ``placements`` (each with ``part``,
        ``sheet``, ``rotation`` in degrees, ``translation`` a pair of floats),
        ``sheets`` (shapely Polygons), ``spacing`` and ``margin``.

    Returns
    -------
    list of Violation
        Sorted by placement (``a``, then ``b``, then the order of :data:`KINDS`). A pair
        whose interiors overlap is not also listed for its spacing, nor a part outside its
        sheet for its margin.

    Raises
    ------
    GeometryError
        A placement names no part, or its translation is not a pair of float64 values.
    OverflowGeometryError
        A placed coordinate is beyond float64.

    See Also
    --------
    minkowski2d.nesting.nfp.rotate_part : the placed polygon's rotation.

    Notes
    -----
    Time ``O((n + k) log n)`` per sheet for ``n`` edges and ``k`` pairs of edges within
    ``max(spacing, margin)`` of each other, plus an ``O(m)`` ray cast per boundary arc.

    Examples
    --------
    >>> from types import SimpleNamespace as NS
    >>> import shapely
    >>> at = lambda x: NS(part=0, sheet=0, rotation=90, translation=(x, 0.0))
    >>> lay = NS(parts=[shapely.box(0, -1, 1, 0)], placements=[at(1.0), at(2.0), at(2.5)],
    ...          sheets=[shapely.box(0, 0, 4, 1)], spacing=0.0, margin=0.0)
    >>> for v in verify_layout(lay):
    ...     print(v)
    placements[1], placements[2]: overlap: they share an edge from the same side near (3, 1)
    """
    s = _exact(getattr(layout, "spacing", 0) or 0, "spacing")
    m = _exact(getattr(layout, "margin", 0) or 0, "margin")
    by_sheet: dict[int, list[int]] = {}
    n_sheets = len(layout.sheets)
    for i, pl in enumerate(layout.placements):
        b = pl.sheet
        if not (isinstance(b, (int, np.integer)) and 0 <= b < n_sheets):
            raise GeometryError(f"placements[{i}]: sheet {b!r} is not an index into sheets",
                                argument=f"placements[{i}]")  # fmt: skip
        by_sheet.setdefault(int(b), []).append(i)
    cache: dict = {}
    out: list[Violation] = []
    with np.errstate(over="ignore", invalid="ignore", under="ignore"):
        # the float filter: values out of its range are sent to the exact path
        for k, members in sorted(by_sheet.items()):
            out += _check_sheet(layout, members, k, s, m, cache)
    return sorted(out, key=lambda v: (v.a, -1 if v.b is None else v.b, KINDS.index(v.kind)))
