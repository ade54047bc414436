"""Compiled kernels (numba) for collision, distance, penetration and point location.

Every decision is an exact sign, taken on the input's own float64 values (int input is
passed as float64 when ``|x| <= 2**53``; floats must have every nonzero ``|x|`` in
``[2**-400, 2**400]``, as for :mod:`minkowski2d._kernels`, whose predicates these reuse).

The boundary of D = A ⊕ (−B) is walked without being stored: merging the edges of A with
the edges of −B by angle gives D's edges in order. Each edge of D is a *sub-edge*: an
edge ``p0 -> p1`` of one polygon (X) paired with a vertex ``q`` of the other (Y):

* ``kind 0``: an edge of A with a vertex of B; D runs from ``a_i - b_j`` to
  ``a_{i+1} - b_j``;
* ``kind 1``: an edge of B with a vertex of A; D runs from ``a_i - b_j`` to
  ``a_i - b_{j+1}``.

Parallel edges of A and −B are kept as two collinear sub-edges (A's first). For either
kind, with ``e = p1 - p0``:

* the origin is on the inner side of the sub-edge iff ``orient(p0, p1, q) >= 0``;
* its signed distance to the sub-edge's line is ``cross(e, q - p0) / |e|``;
* the origin's foot lies past the sub-edge's start iff ``dot(q - p0, e) > 0`` and before
  its end iff ``dot(q - p1, e) < 0``.

All of these are signs of a cross product of two differences of input points, which
``_kernels.cross_sign`` decides exactly (a dot product is a cross product with one
vector turned by 90 degrees, which is exact in floating point).

Polygons arrive normalized by ``_kernels._normalize`` (CCW, bottom-most first, no
duplicate or collinear vertices), as index lists into the coordinate array.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ._kernels import _JIT, ERRBOUND, _grow, _normalize, _two_prod, cross_expansion, cross_sign

# mode of the pair kernel
INTERSECTS = 0
DISTANCE = 1
PENETRATION = 2
GJK = 3
AUTO = 4  # INTERSECTS for small pairs, GJK for large ones (same answers, measured faster)
AUTO_SUM_MAX = 64  # vertex total up to which the boundary walk beats GJK (measured)

OUT_OF_RANGE = 10  # status: a coordinate the kernels cannot decide exactly on

_I_LIM = 2.0**53
_F_HI = 2.0**400
_F_LO = 2.0**-400

# columns of the float result rows
#   0 value (distance, or signed depth), 1-2 normal, 3-4 point_a, 5-6 point_b
NCOL = 7

_REL = 2.0**-45  # relative accuracy demanded of a float cross product before trusting it
_GEN_BOUND = 10.0 * 2.0**-53  # error bound factor of the generic 4-term cross product


# --------------------------------------------------------------------------------------
# predicates and accurate values


@njit(inline="always", **_JIT)
def _sgn(v):
    return (v > 0.0) - (v < 0.0)


@njit(inline="always", **_JIT)
def _len(x, y):
    """|(x, y)|: no overflow or underflow for differences of coordinates in the kernels'
    range (squares stay within [2**-904, 2**802]); within 2 ulps."""
    return math.sqrt(x * x + y * y)


@njit(inline="always", **_JIT)
def _dot_sign(a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y):
    """Exact sign of (a1 - a0) . (b1 - b0): the cross product with a0, a1 turned by -90°."""
    return cross_sign(a0y, -a0x, a1y, -a1x, b0x, b0y, b1x, b1y)


@njit(**_JIT)
def _cross_value(a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y):
    """(a1 - a0) x (b1 - b0) to a relative error below 2**-44; exactly 0.0 iff it is 0.

    The float evaluation is kept when its error bound is below 2**-45 of its value;
    otherwise the exact expansion (TwoDiff, TwoProduct) is summed from the smallest
    component up, which is within a few ulps of the exact value and has its sign.
    """
    ux = a1x - a0x
    uy = a1y - a0y
    vx = b1x - b0x
    vy = b1y - b0y
    lft = ux * vy
    rgt = uy * vx
    det = lft - rgt
    bound = ERRBOUND * (abs(lft) + abs(rgt))
    if bound <= _REL * abs(det):
        return det
    e = np.empty(40)
    m = cross_expansion(e, a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y)
    s = 0.0
    for t in range(m):
        s += e[t]
    return s


@njit(**_JIT)
def _cross44_exact(c):
    """Exact sign of cross((u1 - u2) + (u3 - u4), (v1 - v2) + (v3 - v4)) from the 16
    coordinates in ``c`` (u1x, u1y, ..., v4y), by expanding into 32 exact products."""
    e = np.empty(68)
    m = 0
    for s in range(4):
        su = 1.0 if s % 2 == 0 else -1.0
        ux = c[2 * s]
        uy = c[2 * s + 1]
        for t in range(4):
            sv = su if t % 2 == 0 else -su
            vx = c[8 + 2 * t]
            vy = c[8 + 2 * t + 1]
            x, y = _two_prod(ux, vy)
            m = _grow(e, m, sv * y)
            m = _grow(e, m, sv * x)
            x, y = _two_prod(uy, vx)
            m = _grow(e, m, -sv * y)
            m = _grow(e, m, -sv * x)
    return _sgn(e[m - 1])


@njit(**_JIT)
def _cross44(c):
    """Exact sign of cross(U, V), U = (u1 - u2) + (u3 - u4), V = (v1 - v2) + (v3 - v4),
    coordinates in ``c`` (16 float64). Filtered: the float value decides when it exceeds
    a bound on its rounding error, the exact expansion otherwise."""
    ux = (c[0] - c[2]) + (c[4] - c[6])
    uy = (c[1] - c[3]) + (c[5] - c[7])
    vx = (c[8] - c[10]) + (c[12] - c[14])
    vy = (c[9] - c[11]) + (c[13] - c[15])
    sxu = abs(c[0]) + abs(c[2]) + abs(c[4]) + abs(c[6])
    syu = abs(c[1]) + abs(c[3]) + abs(c[5]) + abs(c[7])
    sxv = abs(c[8]) + abs(c[10]) + abs(c[12]) + abs(c[14])
    syv = abs(c[9]) + abs(c[11]) + abs(c[13]) + abs(c[15])
    det = ux * vy - uy * vx
    bound = _GEN_BOUND * (sxu * syv + syu * sxv)
    if det > bound:
        return 1
    if -det > bound:
        return -1
    if bound == 0.0:
        return 0
    return _cross44_exact(c)


# --------------------------------------------------------------------------------------
# normalization of every polygon of a ragged array


@njit(**_JIT)
def _out_of_range(p, lo, hi, is_int):
    """First row of p[lo:hi] the exact predicates cannot take, relative to lo, or -1.

    Int input (converted to float64) must have |x| < 2**53; float input every nonzero
    |x| in [2**-400, 2**400]."""
    big = 0.0
    small = np.inf
    for r in range(lo, hi):
        for c in range(2):
            x = abs(p[r, c])
            big = max(big, x)
            small = min(small, x if x != 0.0 else np.inf)
    if (big < _I_LIM) if is_int else (big <= _F_HI and small >= _F_LO):
        return -1
    for r in range(lo, hi):
        for c in range(2):
            x = abs(p[r, c])
            if is_int:
                if x >= _I_LIM:
                    return r - lo
            elif x > _F_HI or (x != 0.0 and x < _F_LO):
                return r - lo
    return -1


@njit(**_JIT)
def prep(p, off, need_len, is_int, idx, kk, ss, inv):
    """Normalize polygon q = p[off[q]:off[q+1]] for every q.

    Writes its normalized vertex indices to ``idx[off[q]:off[q]+kk[q]]``, its split
    (first lower-half edge) to ``ss[q]`` and, when ``need_len``, the inverse length of its
    normalized edge t to ``inv[off[q] + t]``. Returns (code, polygon, vertex); code 0 is
    success, otherwise a ``_kernels`` status naming the first bad polygon and vertex.
    """
    P = off.shape[0] - 1
    if _out_of_range(p, 0, p.shape[0], is_int) >= 0:
        for q in range(P):
            r = _out_of_range(p, off[q], off[q + 1], is_int)
            if r >= 0:
                return OUT_OF_RANGE, q, r
    big = 1
    for q in range(P):
        big = max(big, off[q + 1] - off[q])
    keep = np.empty(big, np.int64)
    turn = np.empty(big, np.int8)
    for q in range(P):
        lo = off[q]
        hi = off[q + 1]
        k, split, code, v, b, step = _normalize(p, lo, hi, keep, turn, idx[lo:hi])
        if code != 0:
            return code, q, v
        if step != 0:
            w = b
            for t in range(k):
                idx[lo + t] = w
                w += step
                if w >= hi:
                    w = lo
                elif w < lo:
                    w = hi - 1
        kk[q] = k
        ss[q] = split
        if need_len and k > 1:
            for t in range(k):
                i = idx[lo + t]
                j = idx[lo + t + 1] if t + 1 < k else idx[lo]
                inv[lo + t] = 1.0 / _len(p[j, 0] - p[i, 0], p[j, 1] - p[i, 1])
    return 0, 0, 0


# --------------------------------------------------------------------------------------
# walking the boundary of A ⊕ (−B)


@njit(inline="always", **_JIT)
def _take_a(pa, ia, na, sa, i, pb, ib, nb, sbm, t, j):
    """Whether the next edge of D comes from A (edge i) rather than −B (edge t, which is
    B's edge j reversed). ``sbm`` is −B's split."""
    ha = i >= sa
    hb = t >= sbm
    if ha != hb:
        return not ha
    a0 = ia[i]
    a1 = ia[i + 1] if i + 1 < na else ia[0]
    b0 = ib[j]
    b1 = ib[j + 1] if j + 1 < nb else ib[0]
    c = cross_sign(
        pa[a0, 0], pa[a0, 1], pa[a1, 0], pa[a1, 1], pb[b1, 0], pb[b1, 1], pb[b0, 0], pb[b0, 1]
    )
    return c >= 0


@njit(**_JIT)
def _intersects(pa, ia, na, sa, pb, ib, nb, sb, AX, AY, BX, BY):
    """1 when the origin lies in D = A ⊕ (−B) (closed), else 0. Exact; stops at the first
    separating edge. The walk of ``_walk`` without storing anything."""
    ea = na if na > 1 else 0
    eb = nb if nb > 1 else 0
    if ea + eb == 0:
        a = ia[0]
        b = ib[0]
        return 1 if pa[a, 0] == pb[b, 0] and pa[a, 1] == pb[b, 1] else 0
    _gather(pa, ia, na, pb, ib, nb, sb, AX, AY, BX, BY)
    sbm = nb - sb if nb > 1 else 0
    i = 0
    t = 0
    zero = True
    for _ in range(ea + eb):
        ax0 = AX[i]
        ay0 = AY[i]
        ax1 = AX[i + 1]
        ay1 = AY[i + 1]
        bx0 = BX[t]
        by0 = BY[t]
        bx1 = BX[t + 1]
        by1 = BY[t + 1]
        uax = ax1 - ax0
        uay = ay1 - ay0
        ubx = bx0 - bx1
        uby = by0 - by1
        lft = uax * uby
        rgt = uay * ubx
        det = lft - rgt
        ha = i >= sa
        hb = t >= sbm
        same = ha == hb
        ta = det > 0.0 if same else not ha
        if same and abs(det) <= ERRBOUND * (abs(lft) + abs(rgt)) and i < ea and t < eb:
            ta = cross_sign(ax0, ay0, ax1, ay1, bx1, by1, bx0, by0) >= 0
        ta = (ta or t >= eb) and i < ea
        p0x = ax0 if ta else bx0
        p0y = ay0 if ta else by0
        p1x = ax1 if ta else bx1
        p1y = ay1 if ta else by1
        qx = bx0 if ta else ax0
        qy = by0 if ta else ay0
        lft = (p1x - p0x) * (qy - p0y)
        rgt = (p1y - p0y) * (qx - p0x)
        c = lft - rgt
        if abs(c) <= ERRBOUND * (abs(lft) + abs(rgt)):
            o = cross_sign(p0x, p0y, p1x, p1y, p0x, p0y, qx, qy)
        else:
            o = 1 if c > 0.0 else -1
        if o < 0:
            return 0
        zero &= o == 0
        i += 1 if ta else 0
        t += 0 if ta else 1
    if not zero:
        return 1
    # every edge line passes through the origin: D is a segment on a line through it
    return _on_degenerate(pa, ia, na, sa, pb, ib, nb, sb)


@njit(inline="always", **_JIT)
def _subedges(pa, ia, na, sa, pb, ib, nb, sb, kind, ii, jj):
    """Write D's sub-edges in order: kind (0 = A edge, 1 = B edge), A position, B
    position (positions index ``ia``/``ib``). Returns their number."""
    ea = na if na > 1 else 0
    eb = nb if nb > 1 else 0
    s = sb % nb
    sbm = nb - sb if nb > 1 else 0
    i = 0
    t = 0
    j = s
    k = 0
    while i < ea or t < eb:
        if i == ea:
            ta = False
        elif t == eb:
            ta = True
        else:
            ta = _take_a(pa, ia, na, sa, i, pb, ib, nb, sbm, t, j)
        kind[k] = 0 if ta else 1
        ii[k] = i if i < na else 0
        jj[k] = j
        k += 1
        if ta:
            i += 1
        else:
            t += 1
            j = j + 1 if j + 1 < nb else 0
    return k


@njit(**_JIT)
def _gather(pa, ia, na, pb, ib, nb, sb, AX, AY, BX, BY):
    """Copy A's normalized vertices (from its first) and B's from its top vertex (−B's
    first), each with two wrap-around entries, into contiguous scratch."""
    for t in range(na + 2):
        v = ia[t % na]
        AX[t] = pa[v, 0]
        AY[t] = pa[v, 1]
    s = sb % nb
    for t in range(nb + 2):
        v = ib[(s + t) % nb]
        BX[t] = pb[v, 0]
        BY[t] = pb[v, 1]


@njit(**_JIT)
def _walk(pa, ia, na, sa, pb, ib, nb, sb, AX, AY, BX, BY, kind, ii, jj, cv):
    """``_subedges`` and each sub-edge's accurate cross value ``cv`` in one pass over
    gathered coordinates, with the merge decision and the feature selection made
    without data-dependent branches (the float filter's rare misses branch to the exact
    evaluation). Returns the number of sub-edges."""
    _gather(pa, ia, na, pb, ib, nb, sb, AX, AY, BX, BY)
    ea = na if na > 1 else 0
    eb = nb if nb > 1 else 0
    s = sb % nb
    sbm = nb - sb if nb > 1 else 0
    i = 0
    t = 0
    for k in range(ea + eb):
        ax0 = AX[i]
        ay0 = AY[i]
        ax1 = AX[i + 1]
        ay1 = AY[i + 1]
        bx0 = BX[t]
        by0 = BY[t]
        bx1 = BX[t + 1]
        by1 = BY[t + 1]
        # c = cross(a1 - a0, b0 - b1): > 0 when −B's edge is CCW of A's (A first)
        uax = ax1 - ax0
        uay = ay1 - ay0
        ubx = bx0 - bx1
        uby = by0 - by1
        lft = uax * uby
        rgt = uay * ubx
        det = lft - rgt
        ha = i >= sa
        hb = t >= sbm
        same = ha == hb
        ta = det > 0.0 if same else not ha
        if same and abs(det) <= ERRBOUND * (abs(lft) + abs(rgt)) and i < ea and t < eb:
            ta = cross_sign(ax0, ay0, ax1, ay1, bx1, by1, bx0, by0) >= 0
        ta = (ta or t >= eb) and i < ea
        # the sub-edge p0 -> p1 with the other polygon's vertex q
        p0x = ax0 if ta else bx0
        p0y = ay0 if ta else by0
        p1x = ax1 if ta else bx1
        p1y = ay1 if ta else by1
        qx = bx0 if ta else ax0
        qy = by0 if ta else ay0
        ex = p1x - p0x
        ey = p1y - p0y
        fx = qx - p0x
        fy = qy - p0y
        lft = ex * fy
        rgt = ey * fx
        c = lft - rgt
        if ERRBOUND * (abs(lft) + abs(rgt)) > _REL * abs(c):
            c = _cross_value(p0x, p0y, p1x, p1y, p0x, p0y, qx, qy)
        cv[k] = c
        kind[k] = 0 if ta else 1
        ii[k] = i if i < na else 0
        w = s + t
        jj[k] = w if w < nb else w - nb
        i += 1 if ta else 0
        t += 0 if ta else 1
    return ea + eb


@njit(inline="always", **_JIT)
def _feature(pa, ia, na, pb, ib, nb, kind, ii, jj, k):
    """(X coords, p0, p1, Y coords, q) of sub-edge k: the edge p0 -> p1 of X, vertex q."""
    i = ii[k]
    j = jj[k]
    if kind[k] == 0:
        return pa, ia[i], ia[i + 1] if i + 1 < na else ia[0], pb, ib[j]
    return pb, ib[j], ib[j + 1] if j + 1 < nb else ib[0], pa, ia[i]


@njit(inline="always", **_JIT)
def _fdot0(X, p0, p1, Y, q):
    """sign dot(q - p0, p1 - p0)."""
    return _dot_sign(X[p0, 0], X[p0, 1], Y[q, 0], Y[q, 1], X[p0, 0], X[p0, 1], X[p1, 0], X[p1, 1])


@njit(inline="always", **_JIT)
def _fdot1(X, p0, p1, Y, q):
    """sign dot(q - p1, p1 - p0)."""
    return _dot_sign(X[p1, 0], X[p1, 1], Y[q, 0], Y[q, 1], X[p0, 0], X[p0, 1], X[p1, 0], X[p1, 1])


@njit(**_JIT)
def _on_degenerate(pa, ia, na, sa, pb, ib, nb, sb):
    """Origin on D, when D is a segment whose line passes through the origin."""
    K = na + nb
    kind = np.empty(K, np.int8)
    ii = np.empty(K, np.int64)
    jj = np.empty(K, np.int64)
    K = _subedges(pa, ia, na, sa, pb, ib, nb, sb, kind, ii, jj)
    for k in range(K):
        X, p0, p1, Y, q = _feature(pa, ia, na, pb, ib, nb, kind, ii, jj, k)
        if _fdot0(X, p0, p1, Y, q) >= 0 and _fdot1(X, p0, p1, Y, q) <= 0:
            return 1
    return 0


@njit(inline="always", **_JIT)
def _dnormal(kind, X, p0, p1, inv):
    """Outward unit normal of D along the sub-edge (A's outward normal for kind 0, minus
    B's for kind 1)."""
    ex = (X[p1, 0] - X[p0, 0]) * inv
    ey = (X[p1, 1] - X[p0, 1]) * inv
    if kind == 0:
        return ey, -ex
    return -ey, ex


@njit(**_JIT)
def _write_edge(out, kind, X, p0, p1, Y, q, depth, inv):
    """Result row for a sub-edge feature at signed depth: point on Y = q, point on X =
    q +- depth * normal."""
    nx, ny = _dnormal(kind, X, p0, p1, inv)
    out[0] = depth
    out[1] = nx + 0.0  # no -0.0
    out[2] = ny + 0.0
    qx = Y[q, 0]
    qy = Y[q, 1]
    if depth == 0.0:
        fx = qx
        fy = qy
    elif kind == 0:
        fx = qx + depth * nx
        fy = qy + depth * ny
    else:
        fx = qx - depth * nx
        fy = qy - depth * ny
    if kind == 0:
        out[3] = fx
        out[4] = fy
        out[5] = qx
        out[6] = qy
    else:
        out[3] = qx
        out[4] = qy
        out[5] = fx
        out[6] = fy


@njit(**_JIT)
def _write_vertex(out, pa, a, pb, b):
    """Result row for a vertex feature a - b of D with the origin outside (or at it)."""
    dx = pb[b, 0] - pa[a, 0]
    dy = pb[b, 1] - pa[a, 1]
    d = _len(dx, dy)
    out[0] = -d
    if d > 0.0:
        out[1] = dx / d + 0.0
        out[2] = dy / d + 0.0
    else:
        out[1] = 0.0
        out[2] = 0.0
    out[3] = pa[a, 0]
    out[4] = pa[a, 1]
    out[5] = pb[b, 0]
    out[6] = pb[b, 1]


@njit(**_JIT)
def _inv_len(X, p0, p1):
    return 1.0 / _len(X[p1, 0] - X[p0, 0], X[p1, 1] - X[p0, 1])


@njit(**_JIT)
def _vertex_ok(pa, ia, na, pb, ib, nb, kind, ii, jj, K, k):
    """Whether the origin lies in the normal cone of D's vertex k (start of sub-edge k):
    dot(-v_k, e_k) <= 0 and dot(-v_k, e_{k-1}) >= 0."""
    X, p0, p1, Y, q = _feature(pa, ia, na, pb, ib, nb, kind, ii, jj, k)
    if _fdot0(X, p0, p1, Y, q) > 0:
        return False
    km = k - 1 if k > 0 else K - 1
    X, p0, p1, Y, q = _feature(pa, ia, na, pb, ib, nb, kind, ii, jj, km)
    return _fdot1(X, p0, p1, Y, q) >= 0


@njit(**_JIT)
def _separated(pa, ia, na, pb, ib, nb, kind, ii, jj, K, vis, cv, out):
    """Nearest point of D to the origin, which lies outside D; ``vis[k]`` is the exact
    sign of orient for sub-edge k. Writes the result row (signed depth = -distance)."""
    any_vis = False
    for k in range(K):
        if vis[k] >= 0:
            continue
        any_vis = True
        X, p0, p1, Y, q = _feature(pa, ia, na, pb, ib, nb, kind, ii, jj, k)
        d0 = _fdot0(X, p0, p1, Y, q)
        d1 = _fdot1(X, p0, p1, Y, q)
        if d0 > 0 and d1 < 0:
            inv = _inv_len(X, p0, p1)
            _write_edge(out, kind[k], X, p0, p1, Y, q, cv[k] * inv, inv)
            return
        if d0 <= 0 and _vertex_ok(pa, ia, na, pb, ib, nb, kind, ii, jj, K, k):
            _write_vertex(out, pa, ia[ii[k]], pb, ib[jj[k]])
            return
        k1 = k + 1 if k + 1 < K else 0
        if d1 >= 0 and _vertex_ok(pa, ia, na, pb, ib, nb, kind, ii, jj, K, k1):
            _write_vertex(out, pa, ia[ii[k1]], pb, ib[jj[k1]])
            return
    if not any_vis:
        # D is a segment and the origin on its line, beyond one end
        for k in range(K):
            if _vertex_ok(pa, ia, na, pb, ib, nb, kind, ii, jj, K, k):
                _write_vertex(out, pa, ia[ii[k]], pb, ib[jj[k]])
                return
    out[0] = np.nan  # unreachable for valid input (kept to make a bug visible)


@njit(**_JIT)
def _common_point(pa, ia, na, pb, ib, nb, kind, ii, jj, K, out):
    """A point of A ∩ B when the origin is strictly inside D: the fan triangle
    (v_0, v_m, v_m+1) of D holding the origin, found by exact binary search, and the
    origin's barycentric weights (float) applied to the vertices of A and of B."""
    c = np.empty(16)
    a0 = ia[ii[0]]
    b0 = ib[jj[0]]
    lo = 1
    hi = K - 1
    # f(m) = orient(v0, v_m, origin) = cross(v_m - v0, b0 - a0): + at m = 1, - at m = K - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        am = ia[ii[mid]]
        bm = ib[jj[mid]]
        c[0] = pa[am, 0]
        c[1] = pa[am, 1]
        c[2] = pa[a0, 0]
        c[3] = pa[a0, 1]
        c[4] = pb[b0, 0]
        c[5] = pb[b0, 1]
        c[6] = pb[bm, 0]
        c[7] = pb[bm, 1]
        c[8] = pb[b0, 0]
        c[9] = pb[b0, 1]
        c[10] = pa[a0, 0]
        c[11] = pa[a0, 1]
        c[12] = 0.0
        c[13] = 0.0
        c[14] = 0.0
        c[15] = 0.0
        if _cross44(c) >= 0:
            lo = mid
        else:
            hi = mid
    a1 = ia[ii[lo]]
    b1 = ib[jj[lo]]
    a2 = ia[ii[hi]]
    b2 = ib[jj[hi]]
    # The weights are cross products of D's vertices w_i = a_i - b_i. On a thin D a float
    # evaluation cancels catastrophically (witnesses far from A ∩ B), so each is taken
    # from the accurate cross value of the two differences.
    l0 = max(
        _cross_value(
            pb[b1, 0], pb[b1, 1], pa[a1, 0], pa[a1, 1], pb[b2, 0], pb[b2, 1], pa[a2, 0], pa[a2, 1]
        ),
        0.0,
    )
    l1 = max(
        _cross_value(
            pb[b2, 0], pb[b2, 1], pa[a2, 0], pa[a2, 1], pb[b0, 0], pb[b0, 1], pa[a0, 0], pa[a0, 1]
        ),
        0.0,
    )
    l2 = max(
        _cross_value(
            pb[b0, 0], pb[b0, 1], pa[a0, 0], pa[a0, 1], pb[b1, 0], pb[b1, 1], pa[a1, 0], pa[a1, 1]
        ),
        0.0,
    )
    s = l0 + l1 + l2
    if not s > 0.0:
        l0 = 1.0
        l1 = 0.0
        l2 = 0.0
        s = 1.0
    l0 /= s
    l1 /= s
    l2 /= s
    out[3] = l0 * pa[a0, 0] + l1 * pa[a1, 0] + l2 * pa[a2, 0]
    out[4] = l0 * pa[a0, 1] + l1 * pa[a1, 1] + l2 * pa[a2, 1]
    out[5] = l0 * pb[b0, 0] + l1 * pb[b1, 0] + l2 * pb[b2, 0]
    out[6] = l0 * pb[b0, 1] + l1 * pb[b1, 1] + l2 * pb[b2, 1]


@njit(**_JIT)
def _collide(
    pa, ia, na, sa, inva, pb, ib, nb, sb, invb, mode, kind, ii, jj, vis, cv, AX, AY, BX, BY, out
):
    """Distance (mode 1) or penetration (mode 2) of one pair; writes the result row and
    returns 1 when the polygons intersect (touching included). ``cv`` receives each
    sub-edge's accurate cross value, ``vis`` its exact sign."""
    if na == 1 and nb == 1:
        a = ia[0]
        b = ib[0]
        _write_vertex(out, pa, a, pb, b)
        if out[0] == 0.0:
            out[0] = 0.0  # no -0.0
            return 1
        return 0
    K = _walk(pa, ia, na, sa, pb, ib, nb, sb, AX, AY, BX, BY, kind, ii, jj, cv)
    neg = False
    allzero = True
    for k in range(K):
        o = _sgn(cv[k])
        vis[k] = o
        neg |= o < 0
        allzero &= o == 0
    if not neg and allzero:
        # D is a segment on a line through the origin: on it or beyond an end?
        for k in range(K):
            X, p0, p1, Y, q = _feature(pa, ia, na, pb, ib, nb, kind, ii, jj, k)
            if _fdot0(X, p0, p1, Y, q) >= 0 and _fdot1(X, p0, p1, Y, q) <= 0:
                _write_edge(out, kind[k], X, p0, p1, Y, q, 0.0, _inv_len(X, p0, p1))
                return 1
        neg = True
    if neg:
        _separated(pa, ia, na, pb, ib, nb, kind, ii, jj, K, vis, cv, out)
        return 0
    # the origin is in D, which has an interior
    best = -1
    for k in range(K):
        if vis[k] == 0:
            X, p0, p1, Y, q = _feature(pa, ia, na, pb, ib, nb, kind, ii, jj, k)
            if _fdot0(X, p0, p1, Y, q) >= 0 and _fdot1(X, p0, p1, Y, q) <= 0:
                best = k
                break
    if best >= 0:  # touching: the origin is on D's boundary
        X, p0, p1, Y, q = _feature(pa, ia, na, pb, ib, nb, kind, ii, jj, best)
        _write_edge(out, kind[best], X, p0, p1, Y, q, 0.0, _inv_len(X, p0, p1))
        return 1
    if mode == DISTANCE:
        out[0] = 0.0
        out[1] = 0.0
        out[2] = 0.0
        _common_point(pa, ia, na, pb, ib, nb, kind, ii, jj, K, out)
        return 1
    # penetration: the nearest edge line (its foot is on the edge)
    bd = np.inf
    for k in range(K):
        inv = inva[ii[k]] if kind[k] == 0 else invb[jj[k]]
        d = cv[k] * inv
        if d < bd:
            bd = d
            best = k
    X, p0, p1, Y, q = _feature(pa, ia, na, pb, ib, nb, kind, ii, jj, best)
    if not (_fdot0(X, p0, p1, Y, q) >= 0 and _fdot1(X, p0, p1, Y, q) <= 0):
        # a near tie picked an edge whose foot is off it: take the nearest edge among
        # those whose foot is on them (the true nearest is one of these)
        bd = np.inf
        for k in range(K):
            X, p0, p1, Y, q = _feature(pa, ia, na, pb, ib, nb, kind, ii, jj, k)
            if _fdot0(X, p0, p1, Y, q) >= 0 and _fdot1(X, p0, p1, Y, q) <= 0:
                inv = inva[ii[k]] if kind[k] == 0 else invb[jj[k]]
                d = cv[k] * inv
                if d < bd:
                    bd = d
                    best = k
        X, p0, p1, Y, q = _feature(pa, ia, na, pb, ib, nb, kind, ii, jj, best)
    inv = inva[ii[best]] if kind[best] == 0 else invb[jj[best]]
    _write_edge(out, kind[best], X, p0, p1, Y, q, bd, inv)
    return 1


# --------------------------------------------------------------------------------------
# GJK: support functions only, never the boundary of D


@njit(**_JIT)
def _support(p, ix, n, dx, dy, sgn, c, mode, w0a, w0b, w1a, w1b, pa, pb, ia, ib, sign):
    """Position of the vertex of polygon (p, ix[:n]) extreme in direction ``sign * d``.

    A float scan proposes a vertex; exact hill-climbing on the (strictly convex)
    polygon then moves it to the exact maximizer (local = global on a convex polygon).
    ``mode`` 0: d = b[w0b] - a[w0a]. ``mode`` 1: d = sgn * leftperp(w1 - w0), where
    w = a[wa] - b[wb].
    """
    best = 0
    bv = -np.inf
    for t in range(n):
        v = sign * (p[ix[t], 0] * dx + p[ix[t], 1] * dy)
        if v > bv:
            bv = v
            best = t
    if n == 1:
        return 0
    while True:
        moved = False
        for step in (1, n - 1):
            nb_ = (best + step) % n
            if (
                _dir_sign(p, ix[best], ix[nb_], mode, w0a, w0b, w1a, w1b, pa, pb, ia, ib, c)
                * (sign * sgn)
                > 0
            ):
                best = nb_
                moved = True
                break
        if not moved:
            return best


@njit(**_JIT)
def _dir_sign(p, u, v, mode, w0a, w0b, w1a, w1b, pa, pb, ia, ib, c):
    """sign of dot(p[v] - p[u], D) for the direction's unsigned form D:
    mode 0: D = b[w0b] - a[w0a]; mode 1: D = leftperp(w1 - w0), dot(X, D) = cross(w1 - w0, X).
    """
    if mode == 0:
        a0 = ia[w0a]
        b0 = ib[w0b]
        return _dot_sign(
            p[u, 0], p[u, 1], p[v, 0], p[v, 1], pa[a0, 0], pa[a0, 1], pb[b0, 0], pb[b0, 1]
        )
    _set_u(c, pa, pb, ia, ib, w0a, w0b, w1a, w1b)
    c[8] = p[v, 0]
    c[9] = p[v, 1]
    c[10] = p[u, 0]
    c[11] = p[u, 1]
    c[12] = 0.0
    c[13] = 0.0
    c[14] = 0.0
    c[15] = 0.0
    return _cross44(c)


@njit(inline="always", **_JIT)
def _set_u(c, pa, pb, ia, ib, w0a, w0b, w1a, w1b):
    """c[0:8] = U = w1 - w0 = (a1 - a0) + (b0 - b1)."""
    a0 = ia[w0a]
    a1 = ia[w1a]
    b0 = ib[w0b]
    b1 = ib[w1b]
    c[0] = pa[a1, 0]
    c[1] = pa[a1, 1]
    c[2] = pa[a0, 0]
    c[3] = pa[a0, 1]
    c[4] = pb[b0, 0]
    c[5] = pb[b0, 1]
    c[6] = pb[b1, 0]
    c[7] = pb[b1, 1]


@njit(**_JIT)
def _wcross(c, pa, pb, ia, ib, ua0, ub0, ua1, ub1, xa1, xb1, xa0, xb0, rot):
    """sign of cross(U, X) (or of dot(U, X) when ``rot``) with U = w(ua1, ub1) - w(ua0, ub0)
    and X = w(xa1, xb1) - w(xa0, xb0); w(i, j) = a_i - b_j; xa0 < 0 means X = w(xa1, xb1)."""
    a0 = ia[ua0]
    a1 = ia[ua1]
    b0 = ib[ub0]
    b1 = ib[ub1]
    if rot:
        c[0] = pa[a1, 1]
        c[1] = -pa[a1, 0]
        c[2] = pa[a0, 1]
        c[3] = -pa[a0, 0]
        c[4] = pb[b0, 1]
        c[5] = -pb[b0, 0]
        c[6] = pb[b1, 1]
        c[7] = -pb[b1, 0]
    else:
        c[0] = pa[a1, 0]
        c[1] = pa[a1, 1]
        c[2] = pa[a0, 0]
        c[3] = pa[a0, 1]
        c[4] = pb[b0, 0]
        c[5] = pb[b0, 1]
        c[6] = pb[b1, 0]
        c[7] = pb[b1, 1]
    x1 = ia[xa1]
    y1 = ib[xb1]
    c[8] = pa[x1, 0]
    c[9] = pa[x1, 1]
    c[10] = pb[y1, 0]
    c[11] = pb[y1, 1]
    if xa0 < 0:
        c[12] = 0.0
        c[13] = 0.0
        c[14] = 0.0
        c[15] = 0.0
    else:
        x0 = ia[xa0]
        y0 = ib[xb0]
        c[12] = pb[y0, 0]
        c[13] = pb[y0, 1]
        c[14] = pa[x0, 0]
        c[15] = pa[x0, 1]
    return _cross44(c)


@njit(**_JIT)
def _seg_dot(c, pa, pb, ia, ib, fa, fb, ta, tb):
    """sign dot(-w_f, w_t - w_f) with w = a - b: the origin projects past w_f toward w_t."""
    # dot(w_t - w_f, -w_f) = dot(U, X) with U = w_t - w_f, X = 0 - w_f = b_f - a_f
    a0 = ia[fa]
    b0 = ib[fb]
    a1 = ia[ta]
    b1 = ib[tb]
    c[0] = pa[a1, 1]
    c[1] = -pa[a1, 0]
    c[2] = pa[a0, 1]
    c[3] = -pa[a0, 0]
    c[4] = pb[b0, 1]
    c[5] = -pb[b0, 0]
    c[6] = pb[b1, 1]
    c[7] = -pb[b1, 0]
    c[8] = pb[b0, 0]
    c[9] = pb[b0, 1]
    c[10] = pa[a0, 0]
    c[11] = pa[a0, 1]
    c[12] = 0.0
    c[13] = 0.0
    c[14] = 0.0
    c[15] = 0.0
    return _cross44(c)


@njit(**_JIT)
def _side(c, pa, pb, ia, ib, fa, fb, ta, tb):
    """sign cross(w_t - w_f, -w_f): the origin is left (+1) of the line w_f -> w_t."""
    a0 = ia[fa]
    b0 = ib[fb]
    a1 = ia[ta]
    b1 = ib[tb]
    c[0] = pa[a1, 0]
    c[1] = pa[a1, 1]
    c[2] = pa[a0, 0]
    c[3] = pa[a0, 1]
    c[4] = pb[b0, 0]
    c[5] = pb[b0, 1]
    c[6] = pb[b1, 0]
    c[7] = pb[b1, 1]
    c[8] = pb[b0, 0]
    c[9] = pb[b0, 1]
    c[10] = pa[a0, 0]
    c[11] = pa[a0, 1]
    c[12] = 0.0
    c[13] = 0.0
    c[14] = 0.0
    c[15] = 0.0
    return _cross44(c)


@njit(**_JIT)
def _gjk(pa, ia, na, pb, ib, nb):
    """Exact 2-D GJK on A ⊕ (−B) through support functions. Returns 1 (origin in D,
    touching included), 0 (separated), or -1 (iteration cap: a bug).

    Simplex points are index pairs (i, j) standing for a_i - b_j, so every test is an
    exact sign of a polynomial in the input coordinates:
    * the direction is -w (point simplex) or the normal of the segment simplex facing
      the origin, both kept symbolically;
    * "separated" is claimed only when the exact support value in that direction is
      below zero, which is a certificate (a separating line);
    * the origin on a simplex edge or vertex counts as contained (touching);
    * triangles are never degenerate: a new point is strictly beyond the old segment;
    * the distance to the simplex strictly decreases, so no pair repeats and the loop
      ends (the cap is only a guard).
    """
    c = np.empty(16)
    # simplex: up to 3 index pairs; sa_/sb_ hold them, m the count
    sa_ = np.empty(3, np.int64)
    sb_ = np.empty(3, np.int64)
    sa_[0] = 0
    sb_[0] = 0
    m = 1
    a = ia[0]
    b = ib[0]
    if pa[a, 0] == pb[b, 0] and pa[a, 1] == pb[b, 1]:
        return 1
    mode = 0  # 0: d = -w0; 1: d = sgn * leftperp(w1 - w0)
    sgn = 1
    cap = na * nb + 8
    for _ in range(cap):
        # float direction for the scan
        if mode == 0:
            a0 = ia[sa_[0]]
            b0 = ib[sb_[0]]
            dx = pb[b0, 0] - pa[a0, 0]
            dy = pb[b0, 1] - pa[a0, 1]
            w0a = sa_[0]
            w0b = sb_[0]
            w1a = w0a
            w1b = w0b
        else:
            w0a = sa_[0]
            w0b = sb_[0]
            w1a = sa_[1]
            w1b = sb_[1]
            ux = (pa[ia[w1a], 0] - pa[ia[w0a], 0]) + (pb[ib[w0b], 0] - pb[ib[w1b], 0])
            uy = (pa[ia[w1a], 1] - pa[ia[w0a], 1]) + (pb[ib[w0b], 1] - pb[ib[w1b], 1])
            dx = -uy * sgn
            dy = ux * sgn
        sg = sgn if mode == 1 else 1
        sA = _support(pa, ia, na, dx, dy, sg, c, mode, w0a, w0b, w1a, w1b, pa, pb, ia, ib, 1)
        sB = _support(pb, ib, nb, dx, dy, sg, c, mode, w0a, w0b, w1a, w1b, pa, pb, ia, ib, -1)
        # exact sign of dot(w, d), w = a[sA] - b[sB]
        if mode == 0:
            a0 = ia[w0a]
            b0 = ib[w0b]
            av = ia[sA]
            bv = ib[sB]
            h = _dot_sign(
                pb[bv, 0],
                pb[bv, 1],
                pa[av, 0],
                pa[av, 1],
                pa[a0, 0],
                pa[a0, 1],
                pb[b0, 0],
                pb[b0, 1],
            )
        else:
            h = sgn * _wcross(c, pa, pb, ia, ib, w0a, w0b, w1a, w1b, sA, sB, -1, -1, False)
        if h < 0:
            return 0
        if pa[ia[sA], 0] == pb[ib[sB], 0] and pa[ia[sA], 1] == pb[ib[sB], 1]:
            return 1  # the origin is a vertex of D
        if m == 1:
            # segment {w0, w}
            t1 = _seg_dot(c, pa, pb, ia, ib, sA, sB, sa_[0], sb_[0])
            if t1 <= 0:
                sa_[0] = sA
                sb_[0] = sB
                mode = 0
                continue
            t0 = _seg_dot(c, pa, pb, ia, ib, sa_[0], sb_[0], sA, sB)
            if t0 <= 0:
                mode = 0
                continue
            s = _side(c, pa, pb, ia, ib, sa_[0], sb_[0], sA, sB)
            if s == 0:
                return 1
            sa_[1] = sA
            sb_[1] = sB
            m = 2
            mode = 1
            sgn = s
            continue
        # triangle {w0, w1, w2 = w}
        i0 = sa_[0]
        j0 = sb_[0]
        i1 = sa_[1]
        j1 = sb_[1]
        # tau = orientation of (w0, w1, w2) = cross(w1 - w0, w2 - w0)
        tau = _wcross(c, pa, pb, ia, ib, i0, j0, i1, j1, sA, sB, i0, j0, False)
        if tau == 0:
            return -1
        outa = _side(c, pa, pb, ia, ib, i0, j0, sA, sB) == tau
        outb = _side(c, pa, pb, ia, ib, i1, j1, sA, sB) == -tau
        if not outa and not outb:
            return 1
        done = False
        for e in range(2):
            if (e == 0 and not outa) or (e == 1 and not outb):
                continue
            fi = i0 if e == 0 else i1
            fj = j0 if e == 0 else j1
            if (
                _seg_dot(c, pa, pb, ia, ib, fi, fj, sA, sB) > 0
                and _seg_dot(c, pa, pb, ia, ib, sA, sB, fi, fj) > 0
            ):
                sa_[0] = fi
                sb_[0] = fj
                sa_[1] = sA
                sb_[1] = sB
                sgn = _side(c, pa, pb, ia, ib, fi, fj, sA, sB)
                mode = 1
                m = 2
                done = True
                break
        if done:
            continue
        # a vertex region: the new point's (the others are guards)
        vi = sA
        vj = sB
        if not (
            _seg_dot(c, pa, pb, ia, ib, sA, sB, i0, j0) <= 0
            and _seg_dot(c, pa, pb, ia, ib, sA, sB, i1, j1) <= 0
        ):
            if (
                _seg_dot(c, pa, pb, ia, ib, i0, j0, i1, j1) <= 0
                and _seg_dot(c, pa, pb, ia, ib, i0, j0, sA, sB) <= 0
            ):
                vi = i0
                vj = j0
            else:
                vi = i1
                vj = j1
        sa_[0] = vi
        sb_[0] = vj
        m = 1
        mode = 0
    return -1


# --------------------------------------------------------------------------------------
# batch drivers


@njit(**_JIT)
def pairs(pa, offa, ida, ka, sa, inva, pb, offb, idb, kb, sb, invb, qa, qb, mode, hit, res):
    """Run ``mode`` on pair q = (polygon qa[q] of A, polygon qb[q] of B) for every q.

    ``hit[q]`` receives 1/0 (intersects); for DISTANCE/PENETRATION ``res[q]`` the row
    (value, normal, point_a, point_b). Returns the first pair where GJK hit its cap, or -1.
    """
    P = qa.shape[0]
    big = 2
    for q in range(P):
        big = max(big, ka[qa[q]] + kb[qb[q]])
    kind = np.empty(big, np.int8)
    ii = np.empty(big, np.int64)
    jj = np.empty(big, np.int64)
    vis = np.empty(big, np.int8)
    cv = np.empty(big)
    AX = np.empty(big + 2)
    AY = np.empty(big + 2)
    BX = np.empty(big + 2)
    BY = np.empty(big + 2)
    for q in range(P):
        x = qa[q]
        y = qb[q]
        oa = offa[x]
        ob = offb[y]
        ia = ida[oa : oa + ka[x]]
        ib = idb[ob : ob + kb[y]]
        if mode == INTERSECTS or (mode == AUTO and ka[x] + kb[y] <= AUTO_SUM_MAX):
            hit[q] = _intersects(pa, ia, ka[x], sa[x], pb, ib, kb[y], sb[y], AX, AY, BX, BY)
        elif mode == GJK or mode == AUTO:
            r = _gjk(pa, ia, ka[x], pb, ib, kb[y])
            if r < 0:
                return q
            hit[q] = r
        else:
            hit[q] = _collide(
                pa,
                ia,
                ka[x],
                sa[x],
                inva[oa : oa + ka[x]],
                pb,
                ib,
                kb[y],
                sb[y],
                invb[ob : ob + kb[y]],
                mode,
                kind,
                ii,
                jj,
                vis,
                cv,
                AX,
                AY,
                BX,
                BY,
                res[q],
            )
            if mode == DISTANCE:
                if res[q, 0] < 0.0:
                    res[q, 0] = -res[q, 0]
                else:
                    res[q, 0] = 0.0
    return -1


@njit(inline="always", **_JIT)
def _orient0(x0, y0, x1, y1, qx, qy):
    """Exact sign of orient((x0, y0), (x1, y1), q): the float filter inline, the exact
    predicate only when it cannot tell."""
    lft = (x1 - x0) * (qy - y0)
    rgt = (y1 - y0) * (qx - x0)
    det = lft - rgt
    if abs(det) > ERRBOUND * (abs(lft) + abs(rgt)):
        return 1 if det > 0.0 else -1
    return cross_sign(x0, y0, x1, y1, x0, y0, qx, qy)


@njit(**_JIT)
def contains_points(p, ix, k, pts, out):
    """out[t] = 1 when pts[t] lies in the normalized convex polygon (p, ix[:k]), boundary
    included; O(log k) per point by exact binary search over the fan from vertex 0 (over
    gathered coordinates, the search steps without data-dependent branches)."""
    X = np.empty(k)
    Y = np.empty(k)
    for t in range(k):
        X[t] = p[ix[t], 0]
        Y[t] = p[ix[t], 1]
    x0 = X[0]
    y0 = Y[0]
    for t in range(pts.shape[0]):
        qx = pts[t, 0]
        qy = pts[t, 1]
        if k == 1:
            out[t] = qx == x0 and qy == y0
            continue
        o1 = _orient0(x0, y0, X[1], Y[1], qx, qy)
        if o1 == 0:
            # on the line of edge 0 (the whole polygon, for a segment): between its ends?
            out[t] = _between(p, ix[0], ix[1], qx, qy)
            continue
        if o1 < 0 or k == 2:
            out[t] = False
            continue
        ol = _orient0(x0, y0, X[k - 1], Y[k - 1], qx, qy)
        if ol > 0:
            out[t] = False
            continue
        if ol == 0:
            out[t] = _between(p, ix[0], ix[k - 1], qx, qy)
            continue
        lo = 1
        hi = k - 1
        while hi - lo > 1:
            mid = (lo + hi) >> 1
            up = _orient0(x0, y0, X[mid], Y[mid], qx, qy) >= 0
            lo = mid if up else lo
            hi = hi if up else mid
        out[t] = _orient0(X[lo], Y[lo], X[hi], Y[hi], qx, qy) >= 0


@njit(inline="always", **_JIT)
def _between(p, u, v, qx, qy):
    """q (collinear with u, v) lies on the closed segment u v."""
    return (
        _dot_sign(p[u, 0], p[u, 1], qx, qy, p[u, 0], p[u, 1], p[v, 0], p[v, 1]) >= 0
        and _dot_sign(p[v, 0], p[v, 1], qx, qy, p[u, 0], p[u, 1], p[v, 0], p[v, 1]) <= 0
    )


@njit(**_JIT)
def single(pa, pb, mode, int_a, int_b, res):
    """One pair: normalize both (checking the range), then run ``mode``.

    Returns (code, which, vertex, hit): code 0 on success, else a ``_kernels`` status or
    OUT_OF_RANGE for operand ``which`` (0 = a, 1 = b) at ``vertex``; GJK's cap gives
    code -1.
    """
    na = pa.shape[0]
    nb = pb.shape[0]
    offa = np.zeros(2, np.int64)
    offa[1] = na
    offb = np.zeros(2, np.int64)
    offb[1] = nb
    ida = np.empty(na, np.int64)
    idb = np.empty(nb, np.int64)
    ka = np.empty(1, np.int64)
    kb = np.empty(1, np.int64)
    sa = np.empty(1, np.int64)
    sb = np.empty(1, np.int64)
    need = mode == PENETRATION
    inva = np.empty(na if need else 1)
    invb = np.empty(nb if need else 1)
    code, q, v = prep(pa, offa, need, int_a, ida, ka, sa, inva)
    if code != 0:
        return code, 0, v, 0
    code, q, v = prep(pb, offb, need, int_b, idb, kb, sb, invb)
    if code != 0:
        return code, 1, v, 0
    qa = np.zeros(1, np.int64)
    hit = np.zeros(1, np.int8)
    r = pairs(pa, offa, ida, ka, sa, inva, pb, offb, idb, kb, sb, invb, qa, qa, mode, hit, res)
    if r >= 0:
        return -1, 0, 0, 0
    return 0, 0, 0, hit[0]


@njit(**_JIT)
def contains_single(p, int_p, pts, int_pts, out):
    """Normalize polygon p (checking the range of p and pts) and locate every point.
    Returns (code, which, vertex) as ``single``: which 0 = poly, 1 = points."""
    n = p.shape[0]
    off = np.zeros(2, np.int64)
    off[1] = n
    ix = np.empty(n, np.int64)
    kk = np.empty(1, np.int64)
    ss = np.empty(1, np.int64)
    inv = np.empty(1)
    code, q, v = prep(p, off, False, int_p, ix, kk, ss, inv)
    if code != 0:
        return code, 0, v
    r = _out_of_range(pts, 0, pts.shape[0], int_pts)
    if r >= 0:
        return OUT_OF_RANGE, 1, r
    contains_points(p, ix, kk[0], pts, out)
    return 0, 0, 0
