"""The exact twin of the collision kernels (collision.hpp) in Python ints and Fractions:
the same boundary walk, GJK and point tests with exact rational arithmetic, for the
values the kernels cannot take exactly (ints beyond 2**62 and Fractions)."""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any

import numpy as np

from . import core
from . import exact as _exact
from .coerce import to_float

_INTERSECTS, _DISTANCE, _GJK, _AUTO = (
    core.COLL_INTERSECTS,
    core.COLL_DISTANCE,
    core.COLL_GJK,
    core.COLL_AUTO,
)


#
# The same algorithm as the kernels, with exact rational arithmetic throughout: every
# value is exact until the final rounding to float (square roots via integer sqrt).


def _sub(p: tuple, q: tuple) -> tuple:
    return (p[0] - q[0], p[1] - q[1])


def _cr(u: tuple, v: tuple) -> Any:
    return u[0] * v[1] - u[1] * v[0]


def _dt(u: tuple, v: tuple) -> Any:
    return u[0] * v[0] + u[1] * v[1]


def _sg(v: Any) -> int:
    return (v > 0) - (v < 0)


def _fl(v: Any) -> float:
    f = to_float(v)
    if not math.isfinite(f):
        from .status import status_error

        raise status_error(core.Status.OVERFLOW)
    return f


def _sqrt(v: Any) -> float:
    """sqrt of a non-negative rational, rounded to float (relative error ~2**-60)."""
    v = Fraction(v)
    if v == 0:
        return 0.0
    n, d = v.numerator, v.denominator
    k = 64 - (n.bit_length() - d.bit_length()) // 2
    if k >= 0:
        r = Fraction(math.isqrt((n << (2 * k)) // d), 1 << k)
    else:
        r = Fraction(math.isqrt(n // (d << (-2 * k))) << (-k))
    return _fl(r)


def _unit(v: Any, L2: Any) -> float:
    """v / sqrt(L2), rounded to float."""
    return _sg(v) * _sqrt(Fraction(v) * v / L2) + 0.0


def _py_norm(pts: list, name: str) -> tuple[list, int]:
    """Normalize exact points (ints, Fractions): ``(vertices, split)`` as ``_ext``'s
    normalization gives them; raises NotConvexError naming the caller's vertex."""
    idx, split = _exact_normalize(pts, name)
    return [pts[i] for i in idx], split


def _exact_normalize(pts: list, name: str) -> tuple[list, int]:
    """Indices and split of the normalized polygon, through ``core.normalize_i``.

    Normalization reads only coordinate comparisons and orientation signs, which a
    translation and a positive scaling keep: the points become integer offsets from the
    first one in units of the common denominator. Those fit the core's int64 path
    (|x| < 2**62) unless the polygon's extent is beyond it; then the exact Python twin
    of the core's algorithm (:func:`minkowski2d._engine.exact.normalize_list`) decides."""
    den = 1
    for p in pts:
        for v in p:
            if type(v) is not int:
                den = math.lcm(den, Fraction(v).denominator)
    x0, y0 = pts[0]
    rel = [(int((x - x0) * den), int((y - y0) * den)) for x, y in pts]
    lim = core.INT_LIMIT
    if all(-lim < v < lim for p in rel for v in p):
        idx, split, code, v = core.normalize_i(np.array(rel, dtype=np.int64).reshape(-1, 2))
        if code:
            raise _exact.not_convex(name, int(code), int(v))
        return idx.tolist(), int(split)
    _, idx, split = _exact.normalize_list(rel, name)  # the core's twin in Python ints
    return idx, split


def _py_subedges(A: list, sa: int, B: list, sb: int) -> list:
    na, nb = len(A), len(B)
    ea = na if na > 1 else 0
    eb = nb if nb > 1 else 0
    sbm = nb - sb if nb > 1 else 0
    i = t = 0
    j = sb % nb
    out = []
    while i < ea or t < eb:
        if i == ea:
            ta = False
        elif t == eb:
            ta = True
        elif (i >= sa) != (t >= sbm):
            ta = i < sa
        else:
            ta = _cr(_sub(A[(i + 1) % na], A[i]), _sub(B[j], B[(j + 1) % nb])) >= 0
        out.append((0 if ta else 1, i % na, j))
        if ta:
            i += 1
        else:
            t += 1
            j = (j + 1) % nb
    return out


def _py_feature(A: list, B: list, f: tuple) -> tuple[tuple, tuple, tuple]:
    kind, i, j = f
    if kind == 0:
        return A[i], A[(i + 1) % len(A)], B[j]
    return B[j], B[(j + 1) % len(B)], A[i]


def _py_edge_row(kind: int, p0: tuple, p1: tuple, q: tuple, c: Any) -> list:
    """Row for a sub-edge feature with cross value c = cross(p1 - p0, q - p0)."""
    e = _sub(p1, p0)
    L2 = _dt(e, e)
    nd = (e[1], -e[0]) if kind == 0 else (-e[1], e[0])  # D's outward normal, unnormalized
    depth = _sg(c) * _sqrt(Fraction(c) * c / L2)
    normal = (_unit(nd[0], L2), _unit(nd[1], L2))
    # depth * normal = c * nd / L2 exactly
    off = (Fraction(c) * nd[0] / L2, Fraction(c) * nd[1] / L2)
    if kind == 0:
        pa = (q[0] + off[0], q[1] + off[1])
        pb = q
    else:
        pa = q
        pb = (q[0] - off[0], q[1] - off[1])
    return [depth, normal[0] + 0.0, normal[1] + 0.0, *pa, *pb]


def _py_vertex_row(a: tuple, b: tuple) -> list:
    d = _sub(b, a)
    L2 = _dt(d, d)
    if L2 == 0:
        return [0.0, 0.0, 0.0, *a, *b]
    dist = _sqrt(L2)
    n = (_unit(d[0], L2), _unit(d[1], L2))
    return [-dist, *n, *a, *b]


def _py_pair(a: list, b: list, mode: int) -> tuple[bool, np.ndarray]:
    A, sa = _py_norm(a, "a")
    B, sb = _py_norm(b, "b")
    if mode == _GJK:
        return _py_gjk(A, B), np.zeros(7)
    if mode == _AUTO:
        mode = _INTERSECTS
    hit, row = _py_collide(A, sa, B, sb, mode)
    out = np.array([_fl(v) for v in row]) if row is not None else np.zeros(7)
    if mode == _DISTANCE:
        out[0] = 0.0 if hit else -out[0]
    return hit, out


def _py_collide(A: list, sa: int, B: list, sb: int, mode: int) -> tuple[bool, list | None]:
    if len(A) == 1 and len(B) == 1:
        row = _py_vertex_row(A[0], B[0])
        return row[0] == 0, row
    F = _py_subedges(A, sa, B, sb)
    K = len(F)
    feats = [_py_feature(A, B, f) for f in F]
    cs = [_cr(_sub(p1, p0), _sub(q, p0)) for p0, p1, q in feats]

    def d0(k: int) -> int:
        p0, p1, q = feats[k]
        return _sg(_dt(_sub(q, p0), _sub(p1, p0)))

    def d1(k: int) -> int:
        p0, p1, q = feats[k]
        return _sg(_dt(_sub(q, p1), _sub(p1, p0)))

    def vertex(k: int) -> list:
        _, i, j = F[k]
        return _py_vertex_row(A[i], B[j])

    def vertex_ok(k: int) -> bool:
        return d0(k) <= 0 and d1(k - 1) >= 0

    def on(k: int) -> bool:
        return d0(k) >= 0 and d1(k) <= 0

    neg = any(c < 0 for c in cs)
    if not neg and all(c == 0 for c in cs):
        for k in range(K):
            if on(k):
                return True, _py_edge_row(F[k][0], *feats[k], 0)
        neg = True
    if neg:
        if mode == _INTERSECTS:
            return False, None
        for k in range(K):
            if cs[k] < 0 and d0(k) > 0 and d1(k) < 0:
                return False, _py_edge_row(F[k][0], *feats[k], cs[k])
        for k in range(K):
            if vertex_ok(k):
                return False, vertex(k)
        raise AssertionError("no nearest feature")  # pragma: no cover
    if mode == _INTERSECTS:
        return True, None
    for k in range(K):
        if cs[k] == 0 and on(k):
            return True, _py_edge_row(F[k][0], *feats[k], 0)
    if mode == _DISTANCE:
        return True, _py_common_point(A, B, F)

    # penetration: the nearest edge line, compared exactly (c^2 / |e|^2), among the
    # sub-edges whose foot is on them. Parallel edges of A and -B are two collinear
    # sub-edges at the same exact depth, and the origin's foot lies on only one of them
    # (or on their common vertex); the witnesses of the other are off the boundaries. The
    # nearest line's foot is on D's boundary, so some sub-edge at the minimum depth has
    # its foot on it: the restricted minimum is the depth.
    def depth2(k: int) -> Fraction:
        e = _sub(feats[k][1], feats[k][0])
        return Fraction(cs[k] * cs[k]) / _dt(e, e)

    best = min((k for k in range(K) if on(k)), key=depth2)
    return True, _py_edge_row(F[best][0], *feats[best], cs[best])


def _py_common_point(A: list, B: list, F: list) -> list:
    """A point of A ∩ B, exact: the fan triangle of D holding the origin, in barycentric
    coordinates applied to A's and to B's vertices."""
    v = [(A[i], B[j]) for _, i, j in F]
    w = [_sub(a, b) for a, b in v]
    K = len(w)
    lo, hi = 1, K - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if _cr(_sub(w[mid], w[0]), (-w[0][0], -w[0][1])) >= 0:
            lo = mid
        else:
            hi = mid
    tri = (0, lo, hi)
    l0 = _cr(w[lo], w[hi])
    l1 = _cr(w[hi], w[0])
    l2 = _cr(w[0], w[lo])
    s = Fraction(l0 + l1 + l2)
    lam = (l0 / s, l1 / s, l2 / s)
    pa = tuple(sum(lam[t] * v[tri[t]][0][c] for t in range(3)) for c in range(2))
    pb = tuple(sum(lam[t] * v[tri[t]][1][c] for t in range(3)) for c in range(2))
    return [0, 0, 0, *pa, *pb]


def _py_gjk(A: list, B: list) -> bool:
    """Exact GJK on A ⊕ (−B) (the kernel's algorithm, in exact arithmetic)."""

    def w(p: tuple) -> tuple:
        return _sub(A[p[0]], B[p[1]])

    def support(d: tuple) -> tuple:
        i = max(range(len(A)), key=lambda t: _dt(A[t], d))
        j = min(range(len(B)), key=lambda t: _dt(B[t], d))
        return (i, j)

    def seg_dot(f: tuple, t: tuple) -> int:  # dot(w_t - w_f, -w_f)
        wf = w(f)
        return _sg(_dt(_sub(w(t), wf), (-wf[0], -wf[1])))

    def side(f: tuple, t: tuple) -> int:  # cross(w_t - w_f, -w_f)
        wf = w(f)
        return _sg(_cr(_sub(w(t), wf), (-wf[0], -wf[1])))

    S = [(0, 0)]
    if w(S[0]) == (0, 0):
        return True
    for _ in range(len(A) * len(B) + 8):
        if len(S) == 1:
            w0 = w(S[0])
            d = (-w0[0], -w0[1])
        else:
            u = _sub(w(S[1]), w(S[0]))
            sgn = side(S[0], S[1])
            d = (-u[1] * sgn, u[0] * sgn)
        s = support(d)
        if _dt(w(s), d) < 0:
            return False
        if w(s) == (0, 0):
            return True
        if len(S) == 1:
            if seg_dot(s, S[0]) <= 0:
                S = [s]
                continue
            if side(S[0], s) == 0:
                return True
            S = [S[0], s]
            continue
        p0, p1 = S
        tau = _sg(_cr(_sub(w(p1), w(p0)), _sub(w(s), w(p0))))
        outa = side(p0, s) == tau
        outb = side(p1, s) == -tau
        if not outa and not outb:
            return True
        for f, out in ((p0, outa), (p1, outb)):
            if out and seg_dot(f, s) > 0 and seg_dot(s, f) > 0:
                S = [f, s]
                break
        else:
            S = [s]
    raise RuntimeError("GJK did not terminate")  # pragma: no cover


def _py_contains(poly: list, pts: list) -> list:
    P, _ = _py_norm(poly, "poly")
    k = len(P)
    v0 = P[0]
    out = []
    for q in pts:
        if k == 1:
            out.append(q == v0)
            continue
        o1 = _sg(_cr(_sub(P[1], v0), _sub(q, v0)))
        if o1 == 0 or k == 2:
            e = _sub(P[1], v0)
            out.append(o1 == 0 and _dt(_sub(q, v0), e) >= 0 and _dt(_sub(q, P[1]), e) <= 0)
            continue
        if o1 < 0:
            out.append(False)
            continue
        ol = _sg(_cr(_sub(P[-1], v0), _sub(q, v0)))
        if ol > 0:
            out.append(False)
            continue
        if ol == 0:
            e = _sub(P[-1], v0)
            out.append(_dt(_sub(q, v0), e) >= 0 and _dt(_sub(q, P[-1]), e) <= 0)
            continue
        lo, hi = 1, k - 1
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if _cr(_sub(P[mid], v0), _sub(q, v0)) >= 0:
                lo = mid
            else:
                hi = mid
        out.append(_cr(_sub(P[hi], P[lo]), _sub(q, P[lo])) >= 0)
    return out
