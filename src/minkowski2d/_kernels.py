"""Compiled kernels (numba) for the large single call and the batch path.

One merge and one normalization serve both: ``sum_single`` and ``sum_batch`` call the
same ``_normalize`` and ``_merge``. Coordinates reach the kernels twice:

* ``p*`` arrays, float64, on which every decision is made. For int input they hold the
  same values (the caller guarantees ``|x| <= 2**53`` so the conversion is exact).
  Decisions use a float filter and, when it cannot tell, an exact evaluation with
  error-free transformations (TwoDiff, TwoProduct, expansion sums) — valid while every
  nonzero ``|coordinate|`` lies in ``[2**-400, 2**400]``, which the caller checks.
* ``v*`` arrays, int64 or float64, from which output coordinates are added.

This module imports numba; it is imported lazily, only when an input is large enough.
"""

from __future__ import annotations

import numpy as np
from numba import njit

ERRBOUND = 3.3306690738754716e-16  # (3 + 16 eps) eps, eps = 2**-53
SPLITTER = 134217729.0  # 2**27 + 1

# status codes shared with convex.py
OK = 0
TURNS_BOTH_WAYS = 1
SPIKE = 2
WINDS_TWICE = 3
NOT_FINITE = 4
RANGE = 5  # a value outside the kernels' exact range, or non-finite: Python decides

F_HI = 2.0**400
F_LO = 2.0**-400

_JIT = dict(cache=True, nogil=True, boundscheck=False)


@njit(inline="always", **_JIT)
def _sgn(v):
    return (v > 0.0) - (v < 0.0)


@njit(inline="always", **_JIT)
def _two_sum(a, b):
    x = a + b
    bv = x - a
    av = x - bv
    return x, (a - av) + (b - bv)


@njit(inline="always", **_JIT)
def _two_diff(a, b):
    x = a - b
    bv = a - x
    av = x + bv
    return x, (a - av) + (bv - b)


@njit(inline="always", **_JIT)
def _two_prod(a, b):
    x = a * b
    c = SPLITTER * a
    ahi = c - (c - a)
    alo = a - ahi
    c = SPLITTER * b
    bhi = c - (c - b)
    blo = b - bhi
    err = ((x - ahi * bhi) - alo * bhi) - ahi * blo
    return x, alo * blo - err


@njit(inline="always", **_JIT)
def _grow(e, m, b):
    """Add ``b`` to the nonoverlapping expansion ``e[:m]`` in place (zero-eliminating)."""
    q = b
    h = 0
    for k in range(m):
        q, hh = _two_sum(q, e[k])
        if hh != 0.0:
            e[h] = hh
            h += 1
    if q != 0.0 or h == 0:
        e[h] = q
        h += 1
    return h


@njit(**_JIT)
def cross_expansion(e, a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y):
    """Write (a1 - a0) x (b1 - b0) exactly into ``e`` (size >= 40) as a nonoverlapping
    expansion, smallest component first; returns its length. Its last component has
    the sign of the value; their sum (smallest first) is within a few ulps of it."""
    uxh, uxl = _two_diff(a1x, a0x)
    uyh, uyl = _two_diff(a1y, a0y)
    vxh, vxl = _two_diff(b1x, b0x)
    vyh, vyl = _two_diff(b1y, b0y)
    m = 0
    # + ux * vy
    for p, q in ((uxh, vyh), (uxh, vyl), (uxl, vyh), (uxl, vyl)):
        x, y = _two_prod(p, q)
        m = _grow(e, m, y)
        m = _grow(e, m, x)
    # - uy * vx
    for p, q in ((uyh, vxh), (uyh, vxl), (uyl, vxh), (uyl, vxl)):
        x, y = _two_prod(p, q)
        m = _grow(e, m, -y)
        m = _grow(e, m, -x)
    return m


@njit(**_JIT)
def _cross_sign_exact(a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y):
    e = np.empty(40)
    m = cross_expansion(e, a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y)
    return _sgn(e[m - 1])


@njit(**_JIT)
def cross_sign(a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y):
    """Exact sign of (a1 - a0) x (b1 - b0) for float64 coordinates (see module doc)."""
    ux = a1x - a0x
    uy = a1y - a0y
    vx = b1x - b0x
    vy = b1y - b0y
    if ux == 0.0 or vy == 0.0:
        return -(_sgn(uy) * _sgn(vx))
    if uy == 0.0 or vx == 0.0:
        return _sgn(ux) * _sgn(vy)
    lft = ux * vy
    rgt = uy * vx
    det = lft - rgt
    bound = ERRBOUND * (abs(lft) + abs(rgt))
    if det > bound:
        return 1
    if -det > bound:
        return -1
    return _cross_sign_exact(a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y)


@njit(inline="always", **_JIT)
def _orient(p, i, j, k):
    return cross_sign(p[i, 0], p[i, 1], p[j, 0], p[j, 1], p[i, 0], p[i, 1], p[k, 0], p[k, 1])


@njit(inline="always", **_JIT)
def _upper(p, i, j):
    """True when the edge i -> j points into the half-plane y > 0, or along +x."""
    return p[j, 1] > p[i, 1] or (p[j, 1] == p[i, 1] and p[j, 0] > p[i, 0])


@njit(inline="always", **_JIT)
def _at_implicit(t, b, step, lo, n):
    v = b + step * t
    if v >= lo + n:
        v -= n
    elif v < lo:
        v += n
    return v


@njit(inline="always", **_JIT)
def _at(ia, t, b, step, lo, n):
    """Vertex index of position t (0 <= t <= n) of a normalized polygon: ``ia[t]`` for an
    explicit index list (step == 0), else ``b + step * t`` wrapped into [lo, lo + n)."""
    if step == 0:
        return ia[t] if t < n else ia[0]
    return _at_implicit(t, b, step, lo, n)


@njit(**_JIT)
def _fast_check(p, lo, hi):
    """Start-independent convexity test for the common case, branch-free over the middle.

    Returns +1 (strictly convex, CCW), -1 (strictly convex, CW), 2 when a coordinate is
    non-finite or outside [F_LO, F_HI] (the caller decides in exact Python), or 0 when
    the float filter is unsure anywhere, a vertex repeats, or a turn is straight: the
    general pass decides those exactly. The edge directions wind once exactly when there is one
    upper-to-lower half-plane transition (every turn being less than half a turn).
    """
    n = hi - lo
    pos = 0
    neg = 0
    trans = 0
    big = 0.0
    small = np.inf
    for i in range(lo, hi):
        ax = abs(p[i, 0])
        ay = abs(p[i, 1])
        big = max(big, max(ax, ay))
        small = min(small, min(ax if ax != 0.0 else np.inf, ay if ay != 0.0 else np.inf))
    if not (big <= F_HI and small >= F_LO):  # also catches NaN and inf
        return 2
    if n < 3:
        return 0
    for t in range(n):
        i = lo + t
        h = i - 1 if t > 0 else hi - 1
        k = i + 1 if t + 1 < n else lo
        ux = p[i, 0] - p[h, 0]
        uy = p[i, 1] - p[h, 1]
        vx = p[k, 0] - p[i, 0]
        vy = p[k, 1] - p[i, 1]
        lft = ux * vy
        rgt = uy * vx
        det = lft - rgt
        bnd = ERRBOUND * (abs(lft) + abs(rgt))
        pos += det > bnd
        neg += det < -bnd
        up1 = (uy > 0.0) | ((uy == 0.0) & (ux > 0.0))
        up2 = (vy > 0.0) | ((vy == 0.0) & (vx > 0.0))
        trans += up1 & (not up2)
    if trans != 1:
        return 0
    if pos == n:
        return 1
    if neg == n:
        return -1
    return 0


@njit(**_JIT)
def _fast_normalize(p, lo, hi):
    """(b, step, split) for a polygon that passes ``_fast_check``; else (0, 0 or 2, 0)."""
    s = _fast_check(p, lo, hi)
    if s == 0 or s == 2:
        return 0, s, 0
    n = hi - lo
    b = lo
    by = p[lo, 1]
    bx = p[lo, 0]
    for i in range(lo + 1, hi):
        y = p[i, 1]
        if y < by or (y == by and p[i, 0] < bx):
            b = i
            by = y
            bx = p[i, 0]
    # halves run upper...upper lower...lower from the bottom vertex: binary search
    t0 = 0
    t1 = n - 1
    while t0 < t1:
        tm = (t0 + t1) // 2
        if _upper(p, _at_implicit(tm, b, s, lo, n), _at_implicit(tm + 1, b, s, lo, n)):
            t0 = tm + 1
        else:
            t1 = tm
    return b, s, t0


@njit(**_JIT)
def _normalize(p, lo, hi, keep, turn, out):
    """Normalize the polygon ``p[lo:hi]`` (convex, any orientation and start).

    Writes absolute vertex indices into ``out`` and returns ``(k, split, code, vertex)``:
    ``k`` vertices, ``split`` the index of the first edge pointing into the lower
    half-plane, and on failure a status code with the offending vertex (relative to lo).
    ``keep`` (int64) and ``turn`` (int8) are scratch of size >= hi - lo.

    Also returns ``(b, step)``: when ``step`` is nonzero the common case held and ``out``
    was NOT written: position t is vertex ``b + step * t`` (wrapped), see ``_at``.
    """
    b, step, split = _fast_normalize(p, lo, hi)
    if step == 2:
        return 0, 0, RANGE, 0, 0, 0
    if step != 0:
        return hi - lo, split, OK, 0, b, step
    m = 0
    for i in range(lo, hi):
        if m == 0 or p[i, 0] != p[keep[m - 1], 0] or p[i, 1] != p[keep[m - 1], 1]:
            keep[m] = i
            m += 1
    while m > 1 and p[keep[m - 1], 0] == p[keep[0], 0] and p[keep[m - 1], 1] == p[keep[0], 1]:
        m -= 1
    if m == 1:
        out[0] = keep[0]
        return 1, 1, OK, 0, 0, 0
    b = 0
    for t in range(1, m):
        i = keep[t]
        j = keep[b]
        if p[i, 1] < p[j, 1] or (p[i, 1] == p[j, 1] and p[i, 0] < p[j, 0]):
            b = t
    # turns, and the orientation from the first nonzero one
    s = 0
    for t in range(m):
        prv = keep[(b + t - 1) % m]
        cur = keep[(b + t) % m]
        nxt = keep[(b + t + 1) % m]
        o = _orient(p, prv, cur, nxt)
        turn[t] = o
        if o != 0:
            if s == 0:
                s = o
            elif o != s:
                return 0, 0, TURNS_BOTH_WAYS, cur - lo, 0, 0
    if s == 0:
        # all collinear: the segment between the extreme points
        top = keep[0]
        for t in range(1, m):
            i = keep[t]
            if p[i, 1] > p[top, 1] or (p[i, 1] == p[top, 1] and p[i, 0] > p[top, 0]):
                top = i
        out[0] = keep[b]
        out[1] = top
        return 2, 1, OK, 0, 0, 0
    k = 0
    for t in range(m):
        tt = t if s > 0 else (m - t) % m
        cur = keep[(b + tt) % m]
        if turn[tt] == 0:
            prv = keep[(b + tt - 1) % m]
            nxt = keep[(b + tt + 1) % m]
            # parallel: straight on when both coordinate differences keep their signs
            if _sgn(p[cur, 0] - p[prv, 0]) != _sgn(p[nxt, 0] - p[cur, 0]) or _sgn(
                p[cur, 1] - p[prv, 1]
            ) != _sgn(p[nxt, 1] - p[cur, 1]):
                return 0, 0, SPIKE, cur - lo, 0, 0
            continue
        out[k] = cur
        k += 1
    # the edge directions must sweep exactly one turn: halves 0...0 1...1 from the bottom
    split = k
    for t in range(k):
        up = _upper(p, out[t], out[(t + 1) % k])
        if split == k:
            if not up:
                split = t
        elif up:
            return 0, 0, WINDS_TWICE, out[t] - lo, 0, 0
    return k, split, OK, 0, 0, 0


@njit(**_JIT)
def _merge(pa, va, ia, na, sa, ba, ta, la, pb, vb, ib, nb, sb, bb, tb, lb, out, o0):
    """Merge two normalized polygons' edges by angle; write the sum's vertices at out[o0:].

    Each polygon is given as (indices, count, split, b, step, lo) from ``_normalize``.
    Returns the number of vertices written, or -1 if a float coordinate overflowed.
    The float filter is inlined (measured: 17 ms against 23 ms through the call for
    n = m = 2**20); only entries it cannot decide call the exact ``cross_sign``.
    """
    ea = na if na > 1 else 0
    eb = nb if nb > 1 else 0
    i = 0
    j = 0
    k = o0
    ai = _at(ia, 0, ba, ta, la, na)
    a1 = _at(ia, 1, ba, ta, la, na) if na > 1 else ai
    bj = _at(ib, 0, bb, tb, lb, nb)
    b1 = _at(ib, 1, bb, tb, lb, nb) if nb > 1 else bj
    while True:
        x = va[ai, 0] + vb[bj, 0]
        y = va[ai, 1] + vb[bj, 1]
        out[k, 0] = x
        out[k, 1] = y
        if x - x != 0 or y - y != 0:
            return -1
        k += 1
        if i < ea and j < eb:
            ha = i >= sa
            hb = j >= sb
            if ha != hb:
                step = 1 if ha else -1
            else:
                ux = pa[a1, 0] - pa[ai, 0]
                uy = pa[a1, 1] - pa[ai, 1]
                vx = pb[b1, 0] - pb[bj, 0]
                vy = pb[b1, 1] - pb[bj, 1]
                lft = ux * vy
                rgt = uy * vx
                det = lft - rgt
                bnd = ERRBOUND * (abs(lft) + abs(rgt))
                if det > bnd:
                    step = -1
                elif -det > bnd:
                    step = 1
                else:
                    step = -cross_sign(
                        pa[ai, 0],
                        pa[ai, 1],
                        pa[a1, 0],
                        pa[a1, 1],
                        pb[bj, 0],
                        pb[bj, 1],
                        pb[b1, 0],
                        pb[b1, 1],
                    )
        elif i < ea:
            step = -1
        else:
            step = 1
        if step <= 0:
            i += 1
            ai = a1
            a1 = _at(ia, i + 1, ba, ta, la, na) if i + 1 <= na else a1
        if step >= 0:
            j += 1
            bj = b1
            b1 = _at(ib, j + 1, bb, tb, lb, nb) if j + 1 <= nb else b1
        if i >= ea and j >= eb:
            break
    return k - o0


@njit(**_JIT)
def sum_single(pa, va, pb, vb, ia, ib, keep, turn, out):
    """Minkowski sum of two convex polygons into ``out``; returns (k, code, which, vertex).

    Buffers come from the caller (numpy's allocator reuses warm memory; numba's does
    not): ``ia``/``ib`` int64 of the polygons' sizes, ``keep``/``turn`` scratch of the
    larger size, ``out`` (na + nb, 2) in the output dtype.
    """
    na = pa.shape[0]
    nb = pb.shape[0]
    ka, sa, code, v, ba, ta = _normalize(pa, 0, na, keep, turn, ia)
    if code != OK:
        return 0, code, 0, v
    kb, sb, code, v, bb, tb = _normalize(pb, 0, nb, keep, turn, ib)
    if code != OK:
        return 0, code, 1, v
    k = _merge(pa, va, ia, ka, sa, ba, ta, 0, pb, vb, ib, kb, sb, bb, tb, 0, out, 0)
    if k < 0:
        return 0, NOT_FINITE, 2, 0
    return k, OK, 0, 0


@njit(**_JIT)
def normalize_single(p, keep, turn, out):
    """Normalize one polygon into ``out`` (int64, size n): (k, split, code, vertex)."""
    n = p.shape[0]
    k, split, code, v, b, step = _normalize(p, 0, n, keep, turn, out)
    if step != 0:
        for t in range(k):
            out[t] = _at_implicit(t, b, step, 0, n)
    return k, split, code, v


@njit(**_JIT)
def sum_batch(pa, va, a_lo, a_hi, pb, vb, b_lo, b_hi, out, out_off):
    """Sum pair q = A[a_lo[q]:a_hi[q]] (+) B[b_lo[q]:b_hi[q]] for every q.

    ``out`` must have room for sum(max(lenA + lenB, 1)) rows; ``out_off`` (P + 1) receives
    the offsets. Returns (code, pair, which, vertex); code 0 means success.
    """
    P = a_lo.shape[0]
    big = 1
    for q in range(P):
        big = max(big, a_hi[q] - a_lo[q], b_hi[q] - b_lo[q])
    keep = np.empty(big, np.int64)
    turn = np.empty(big, np.int8)
    ia = np.empty(big, np.int64)
    ib = np.empty(big, np.int64)
    o = 0
    out_off[0] = 0
    for q in range(P):
        ka, sa, code, v, ba, ta = _normalize(pa, a_lo[q], a_hi[q], keep, turn, ia)
        if code != OK:
            return code, q, 0, v
        kb, sb, code, v, bb, tb = _normalize(pb, b_lo[q], b_hi[q], keep, turn, ib)
        if code != OK:
            return code, q, 1, v
        k = _merge(pa, va, ia, ka, sa, ba, ta, a_lo[q], pb, vb, ib, kb, sb, bb, tb, b_lo[q], out, o)
        if k < 0:
            return NOT_FINITE, q, 2, 0
        o += k
        out_off[q + 1] = o
    return OK, 0, 0, 0


@njit(**_JIT)
def convex_hull_sorted(p, order):
    """Andrew's monotone chain over ``p[order]`` (sorted by x, then y); returns indices CCW
    from the lowest-x point. Exact orientation; collinear points dropped."""
    n = order.shape[0]
    h = np.empty(2 * n + 1, np.int64)
    k = 0
    for t in range(n):
        i = order[t]
        while k >= 2 and _orient(p, h[k - 2], h[k - 1], i) <= 0:
            k -= 1
        h[k] = i
        k += 1
    lower = k + 1
    for t in range(n - 2, -1, -1):
        i = order[t]
        while k >= lower and _orient(p, h[k - 2], h[k - 1], i) <= 0:
            k -= 1
        h[k] = i
        k += 1
    return h[: k - 1]


@njit(**_JIT)
def check_range(c, is_float, hi, lo):
    """One pass over the coordinates: (code, row). code 0: fine for the kernels;
    1: a non-finite float at ``row``; 2: a value outside the exact range (|x| > hi, or a
    nonzero |x| < lo) — the caller falls back to exact Python arithmetic."""
    bad = 0
    row = 0
    for i in range(c.shape[0]):
        for j in range(2):
            x = c[i, j]
            if is_float and x - x != 0:
                return 1, i
            ax = abs(x)
            if ax > hi or (ax != 0 and ax < lo):
                if bad == 0:
                    bad = 2
                    row = i
    return bad, row
