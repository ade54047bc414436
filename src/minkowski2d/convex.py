"""Convex polygons: normalization, convexity, hull, and the O(n + m) Minkowski sum.

The algorithm has one definition and three speeds:

* tiny inputs (and exact numbers numpy cannot hold: ints beyond 2**53, Fractions) run
  the pure-Python functions below, avoiding numpy's per-call overhead;
* larger arrays run the compiled kernels in :mod:`minkowski2d._kernels`;
* many pairs run :func:`minkowski2d.batch.minkowski_sum_many`, the same kernels in a loop.

All three make the same exact decisions and return identical results.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ._coerce import EXACT, FLOAT, INT, INT64_MIN, coerce, py_points
from ._types import ArrayLike2, Polygon
from .errors import NotConvexError, OverflowGeometryError
from .predicates import ERRBOUND, MINBOUND, _cross_exact, _cross_float

__all__ = [
    "normalize",
    "is_convex",
    "convex_hull",
    "signed_area",
    "minkowski_sum",
    "translate",
    "reflect",
    "cspace_obstacle",
]

#: Polygons with at most this many vertices (both operands) take the pure-Python path.
TINY = 24

# numba's float kernels are exact while nonzero |coordinates| stay in this range
_F_HI = 2.0**400
_F_LO = 2.0**-400
_I_HI = 1 << 53

_TURNS_BOTH_WAYS, _SPIKE, _WINDS_TWICE, _NOT_FINITE, _RANGE = 1, 2, 3, 4, 5


def _not_convex(name: str, code: int, vertex: int) -> NotConvexError:
    if code == _TURNS_BOTH_WAYS:
        msg = f"{name}: not convex: the boundary turns the other way at vertex {vertex}"
    elif code == _SPIKE:
        msg = f"{name}: not convex: the boundary doubles back on itself at vertex {vertex}"
    else:
        msg = (
            f"{name}: not convex: the edges wind around more than once "
            f"(a star polygon?), detected at vertex {vertex}"
        )
    return NotConvexError(msg + " (pass hull=True to use the convex hull)", vertex)


# --------------------------------------------------------------------------------------
# pure-Python path


def _py_fast(pts: Any, kind: str, raw: bool = False) -> tuple[list, list, int] | None:
    """The common case of :func:`_py_normalize` in one loop: distinct vertices, every turn
    strictly the same way (certain under the float filter), edges winding once (one
    upper-to-lower half-plane transition). Returns None to defer to the general pass,
    which decides everything else exactly.

    With ``raw`` the caller's own sequence is read unvalidated: every vertex must then be
    a pair of Python ints (``kind`` "int") or of finite Python floats ("float"), else None
    (and the caller validates properly, raising the right error).
    """
    n = len(pts)
    try:
        cx, cy = pts[-1]
        px, py = pts[-2]
    except (TypeError, ValueError):
        return None
    T = float if kind == FLOAT else int
    if raw and not (type(cx) is type(cy) is type(px) is type(py) is T):
        return None
    ux = cx - px
    uy = cy - py
    upu = uy > 0 or (uy == 0 and ux > 0)
    pos = neg = trans = 0
    fl = kind == FLOAT
    b = 0
    bx, by = pts[0]
    k = 0
    for p in pts:
        try:
            nx, ny = p
        except (TypeError, ValueError):
            return None
        # (a NaN or inf coordinate needs no check here: it makes this vertex's turn NaN or
        # inf, which no comparison below certifies, so the full validation reports it)
        if raw and (type(nx) is not T or type(ny) is not T):
            return None
        vx = nx - cx
        vy = ny - cy
        if fl:
            lft = ux * vy
            rgt = uy * vx
            d = lft - rgt
            bound = ERRBOUND * abs(lft + rgt)  # = (|l| + |r|) when l, r share a sign; else sure
            if abs(d) <= bound or bound < MINBOUND:
                return None
        else:
            d = ux * vy - uy * vx
        if d > 0:
            pos += 1
        elif d < 0:
            neg += 1
        else:
            return None
        upv = vy > 0 or (vy == 0 and vx > 0)
        if upu and not upv:
            trans += 1
        if ny < by or (ny == by and nx < bx):
            b, bx, by = k, nx, ny
        upu, ux, uy, cx, cy = upv, vx, vy, nx, ny
        k += 1
    if trans != 1 or (pos and neg):
        return None
    if pos:
        order = list(range(b, n)) + list(range(b))
    else:
        order = list(range(b, -1, -1)) + list(range(n - 1, b, -1))
    q = [pts[t] for t in order]
    x0, y0 = bx, by
    split = 0
    for x1, y1 in q[1:]:
        if y1 < y0 or (y1 == y0 and x1 <= x0):
            break
        x0, y0 = x1, y1
        split += 1
    return q, order, split


def _py_normalize(pts: list, kind: str, name: str) -> tuple[list, list, int]:
    """Normalize a convex polygon given as a list of tuples.

    Returns ``(vertices, original_indices, split)``: CCW, bottom-most first, without
    duplicate or collinear vertices; ``split`` is the index of the first edge that points
    into the lower half-plane. Raises NotConvexError naming the caller's vertex.
    """
    if len(pts) >= 3:
        fast = _py_fast(pts, kind)
        if fast is not None:
            return fast
    xs = _cross_float if kind == FLOAT else _cross_exact
    n = len(pts)
    idx = [0]
    last = pts[0]
    for i in range(1, n):
        p = pts[i]
        if p != last:
            idx.append(i)
            last = p
    while len(idx) > 1 and pts[idx[-1]] == pts[idx[0]]:
        idx.pop()
    m = len(idx)
    if m == 1:
        return [pts[idx[0]]], idx, 1
    q = [pts[i] for i in idx]
    b = 0
    bx, by = q[0]
    for t in range(1, m):
        x, y = q[t]
        if y < by or (y == by and x < bx):
            b, bx, by = t, x, y
    if b:
        q = q[b:] + q[:b]
        idx = idx[b:] + idx[:b]
    turns = []
    s = 0
    prv = q[-1]
    for t in range(m):
        cur = q[t]
        nxt = q[t + 1] if t + 1 < m else q[0]
        o = xs(prv, cur, prv, nxt)
        turns.append(o)
        if o:
            if not s:
                s = o
            elif o != s:
                raise _not_convex(name, _TURNS_BOTH_WAYS, idx[t])
        prv = cur
    if not s:
        top = max(range(m), key=lambda t: (q[t][1], q[t][0]))
        return [q[0], q[top]], [idx[0], idx[top]], 1
    if s < 0:
        q = q[:1] + q[:0:-1]
        idx = idx[:1] + idx[:0:-1]
        turns = turns[:1] + turns[:0:-1]
    if 0 in turns:
        vq = []
        vi = []
        for t in range(m):
            if turns[t]:
                vq.append(q[t])
                vi.append(idx[t])
                continue
            p0, p1, p2 = q[t - 1], q[t], q[(t + 1) % m]
            if ((p1[0] > p0[0]) - (p1[0] < p0[0]) != (p2[0] > p1[0]) - (p2[0] < p1[0])) or (
                (p1[1] > p0[1]) - (p1[1] < p0[1]) != (p2[1] > p1[1]) - (p2[1] < p1[1])
            ):
                raise _not_convex(name, _SPIKE, idx[t])
        q, idx = vq, vi
    k = len(q)
    split = k
    py0 = q[0]
    for t in range(k):
        p1 = q[t + 1] if t + 1 < k else q[0]
        up = p1[1] > py0[1] or (p1[1] == py0[1] and p1[0] > py0[0])
        if split == k:
            if not up:
                split = t
        elif up:
            raise _not_convex(name, _WINDS_TWICE, idx[t])
        py0 = p1
    return q, idx, split


def _py_merge(
    A: list, sa: int, B: list, sb: int, kind: str, record: list | None = None, flat: bool = False
) -> list:
    """Merge the edges of two normalized polygons by angle; return the sum's vertices.

    With ``flat`` the result is one flat list ``[x0, y0, x1, y1, ...]`` (cheaper to turn
    into an array). When ``record`` is a list, one entry per step is appended:
    ``(source, i, j, cross)`` where source is ``"A"``, ``"B"`` or ``"AB"``, ``i``/``j`` the
    edge indices compared (None once a list is exhausted) and ``cross`` the sign of
    ``a_i x b_j`` that decided (None when the half-planes or exhaustion decided).
    """
    na = len(A)
    nb = len(B)
    ea = na if na > 1 else 0
    eb = nb if nb > 1 else 0
    A2 = A + A[:1]
    B2 = B + B[:1]
    fl = kind == FLOAT
    i = j = 0
    ax, ay = A[0]
    bx, by = B[0]
    out = [ax + bx, ay + by]
    append = out.append
    # Every upper-half-plane edge precedes every lower one, so merge the two halves in
    # turn: inside a half only the cross product decides.
    for ie, je in ((min(sa, ea), min(sb, eb)), (ea, eb)):
        while i < ie or j < je:
            c = None
            if i == ie:
                step = 1
            elif j == je:
                step = -1
            else:
                a1x, a1y = A2[i + 1]
                b1x, b1y = B2[j + 1]
                ux = a1x - ax
                uy = a1y - ay
                vx = b1x - bx
                vy = b1y - by
                if fl:
                    lft = ux * vy
                    rgt = uy * vx
                    d = lft - rgt
                    bound = ERRBOUND * abs(
                        lft + rgt
                    )  # = (|l| + |r|) when l, r share a sign; else sure
                    if abs(d) <= bound or bound < MINBOUND:
                        d = _cross_float((ax, ay), (a1x, a1y), (bx, by), (b1x, b1y))
                else:
                    d = ux * vy - uy * vx
                c = (d > 0) - (d < 0)
                step = -c
            if record is not None:
                src = "A" if step < 0 else "B" if step > 0 else "AB"
                record.append((src, i if i < ea else None, j if j < eb else None, c))
            if step <= 0:
                i += 1
                ax, ay = A2[i]
            if step >= 0:
                j += 1
                bx, by = B2[j]
            append(ax + bx)
            append(ay + by)
    if len(out) > 2:
        del out[-2:]  # the last step returned to the start vertex
    if flat:
        return out
    return list(zip(out[::2], out[1::2]))


def _py_hull(pts: list, kind: str) -> list:
    """Andrew's monotone chain with exact orientation; CCW, collinear points dropped."""
    xs = _cross_float if kind == FLOAT else _cross_exact
    s = sorted(set(pts))
    if len(s) <= 2:
        return s
    h: list = []
    for p in s:
        while len(h) >= 2 and xs(h[-2], h[-1], h[-2], p) <= 0:
            h.pop()
        h.append(p)
    lower = len(h) + 1
    for p in reversed(s[:-1]):
        while len(h) >= lower and xs(h[-2], h[-1], h[-2], p) <= 0:
            h.pop()
        h.append(p)
    h.pop()
    return h


def _flat_to_array(flat: list, kind: str) -> np.ndarray:
    """A flat ``[x0, y0, x1, y1, ...]`` list to an (n, 2) array of the kind's dtype."""
    if kind == FLOAT:
        out = np.array(flat, dtype=np.float64).reshape(-1, 2)
        # a finite sum proves every term finite (cheaper than np.isfinite on tiny arrays)
        if not math.isfinite(sum(flat)) and not np.isfinite(out).all():
            raise OverflowGeometryError("result overflows float64 (a coordinate is infinite)")
        return out
    if kind == INT:
        try:
            return np.array(flat, dtype=np.int64).reshape(-1, 2)
        except OverflowError:
            pass
    return _to_array(list(zip(flat[::2], flat[1::2])), kind)


def _to_array(pts: list, kind: str) -> np.ndarray:
    if kind == FLOAT:
        out = np.array(pts, dtype=np.float64)
        if not np.isfinite(out).all():
            raise OverflowGeometryError("result overflows float64 (a coordinate is infinite)")
        return out.reshape(-1, 2)
    if kind == INT:
        try:
            return np.array(pts, dtype=np.int64).reshape(-1, 2)
        except OverflowError:
            pass
    out = np.empty((len(pts), 2), dtype=object)
    for k, (x, y) in enumerate(pts):
        out[k, 0] = x
        out[k, 1] = y
    return out


# --------------------------------------------------------------------------------------
# array path


def _kernels():
    from . import _kernels

    return _kernels


def _fits_kernel(arr: np.ndarray, kind: str, name: str) -> bool:
    """True when the kernels decide exactly on ``arr`` (see ``_kernels``); raises for a
    non-finite float."""
    if arr.shape[0] == 0:
        return True
    if kind == INT:
        if arr.dtype != np.int64:
            return False
        code, row = _kernels().check_range(arr, False, _I_HI, 0)
    else:
        code, row = _kernels().check_range(arr, True, _F_HI, _F_LO)
    if code == 1:
        from .errors import NonFiniteError

        raise NonFiniteError(
            f"{name}: vertex {row} has a non-finite coordinate "
            f"({float(arr[row, 0])!r}, {float(arr[row, 1])!r})"
        )
    return code == 0


def _normalize_array(data: np.ndarray, kind: str, name: str) -> tuple[np.ndarray | None, int]:
    """Kernel normalization: (normalized vertex indices, split); raises NotConvexError.

    Returns ``(None, 0)`` when the values need the exact Python path."""
    n = data.shape[0]
    idx = np.empty(n, np.int64)
    k, split, code, v = _kernels().normalize_single(
        _pred_view(data, kind), np.empty(n, np.int64), np.empty(n, np.int8), idx
    )
    if code == _RANGE:
        return None, 0
    if code:
        _raise_kernel_error(code, 0, int(v), (name,))
    return idx[:k], split


def _pred_view(arr: np.ndarray, kind: str) -> np.ndarray:
    return np.ascontiguousarray(arr, dtype=np.float64)


def _prepare(obj: Any, name: str, tiny: int | None = None) -> tuple[Any, str, bool]:
    """Coerce; route to the list form when the kernels cannot be exact on the values."""
    data, kind, is_list = coerce(obj, name, TINY if tiny is None else tiny)
    if not is_list and kind == INT and not _fits_kernel(data, kind, name):
        return [tuple(r) for r in data.tolist()], kind, True
    # float arrays: the kernels' first pass checks finiteness and range (code _RANGE)
    return data, kind, is_list


def _range_fallback(data: np.ndarray, kind: str, name: str) -> list:
    """After a kernel reported _RANGE: raise for non-finite input, else the exact list."""
    _fits_kernel(data, kind, name)
    return [tuple(r) for r in data.tolist()]


def _unify(da: Any, ka: str, la: bool, db: Any, kb: str, lb: bool, names=("a", "b")):
    """Bring two operands to a common kind and form."""
    kind = ka if ka == kb else (EXACT if EXACT in (ka, kb) else FLOAT)
    if la or lb or kind == EXACT:
        # an array about to leave the kernels' path still needs its finiteness check
        if not la and ka == FLOAT:
            _fits_kernel(da, ka, names[0])
        if not lb and kb == FLOAT:
            _fits_kernel(db, kb, names[1])
        A = da if la else [tuple(r) for r in da.tolist()]
        B = db if lb else [tuple(r) for r in db.tolist()]
        if ka != kind:
            A = _convert_list(A, kind)
        if kb != kind:
            B = _convert_list(B, kind)
        return A, B, kind, True
    if kind == FLOAT:
        da = da.astype(np.float64, copy=False)
        db = db.astype(np.float64, copy=False)
    return da, db, kind, False


def _convert_list(pts: list, kind: str) -> list:
    if kind == FLOAT:
        return [(float(x), float(y)) for x, y in pts]
    from fractions import Fraction

    return [(Fraction(x), Fraction(y)) for x, y in pts]


def _raise_kernel_error(code: int, which: int, vertex: int, names: tuple[str, ...]) -> None:
    if code == _NOT_FINITE:
        raise OverflowGeometryError("result overflows float64 (a coordinate is infinite)")
    raise _not_convex(names[which], code, vertex)


# --------------------------------------------------------------------------------------
# public API


def normalize(p: ArrayLike2, *, hull: bool = False) -> Polygon:
    """Normalize a convex polygon: CCW, bottom-most vertex first, no duplicate or collinear
    vertices.

    Parameters
    ----------
    p : (n, 2) array_like of int, float or Fraction, or a shapely geometry
        A convex polygon in either orientation, from any start vertex; a closing repeat
        of the first vertex, duplicate and collinear vertices are allowed. A point
        (one distinct vertex) and a segment (all vertices collinear) are valid.
    hull : bool, default False
        Accept any point set and use its convex hull.

    Returns
    -------
    (k, 2) ndarray
        int64 for int input (object array of Python ints beyond int64), float64 for float
        input, object array of Fractions for Fraction input. ``k`` is 1 for a point, 2 for
        a segment (lower end first).

    Raises
    ------
    NotConvexError
        The polygon turns both ways, doubles back, or winds around more than once.
    EmptyGeometryError, ShapeError, NonFiniteError, CoordinateTypeError
        Bad input.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.normalize([(0, 2), (2, 0), (1, 0), (0, 0)]).tolist()  # CW, collinear (1, 0)
    [[0, 0], [2, 0], [0, 2]]
    """
    data, kind, is_list = _prepare(p, "p")
    if is_list:
        if hull:
            data = _py_hull(data, kind)
        q, _, _ = _py_normalize(data, kind, "p")
        return _to_array(q, kind)
    if hull:
        return convex_hull(data)
    idx, _ = _normalize_array(data, kind, "p")
    if idx is None:
        q, _, _ = _py_normalize(_range_fallback(data, kind, "p"), kind, "p")
        return _to_array(q, kind)
    return data[idx]


def _check_convex(p: ArrayLike2, name: str) -> bool:
    """Validate ``p`` (errors name it ``name``); True if convex, False if not."""
    data, kind, is_list = _prepare(p, name)
    if is_list:
        try:
            _py_normalize(data, kind, name)
        except NotConvexError:
            return False
        return True
    try:
        idx, _ = _normalize_array(data, kind, name)
    except NotConvexError:
        return False
    if idx is None:
        try:
            _py_normalize(_range_fallback(data, kind, name), kind, name)
        except NotConvexError:
            return False
    return True


def is_convex(p: ArrayLike2) -> bool:
    """True when ``p`` is a convex polygon (points and segments count), in either
    orientation.

    Duplicate and collinear vertices are allowed; a star polygon (which turns left at every
    vertex but winds around twice) is not convex.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.is_convex([(0, 0), (4, 0), (4, 4), (0, 4)])
    True
    >>> star = [(0, 0), (2, 6), (4, 0), (-1, 4), (5, 4)]  # a pentagram
    >>> mk.is_convex(star)
    False
    """
    return _check_convex(p, "p")


def convex_hull(points: ArrayLike2) -> Polygon:
    """Convex hull of a point set, normalized (CCW, bottom-most first, no collinear points).

    Exact: orientation decided by exact predicates (Andrew's monotone chain,
    O(n log n)).

    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.convex_hull([(0, 0), (2, 2), (2, 0), (1, 1), (0, 2), (1, 0)]).tolist()
    [[0, 0], [2, 0], [2, 2], [0, 2]]
    """
    data, kind, is_list = _prepare(points, "points")
    if is_list:
        q, _, _ = _py_normalize(_py_hull(data, kind), kind, "points")
        return _to_array(q, kind)
    if kind == FLOAT and not _fits_kernel(data, kind, "points"):
        pts = _range_fallback(data, kind, "points")
        return _to_array(_py_normalize(_py_hull(pts, kind), kind, "points")[0], kind)
    pf = _pred_view(data, kind)
    order = np.lexsort((pf[:, 1], pf[:, 0]))
    h = _kernels().convex_hull_sorted(pf, order)
    if h.size == 0:
        h = order[:1]
    idx, _ = _normalize_array(data[h], kind, "points")
    return data[h[idx]]


def signed_area(p: ArrayLike2) -> float:
    """Signed area of a polygon as given (positive when counter-clockwise).

    Exact for int and Fraction input (the exact value rounded once to float); for float
    input the shoelace terms are summed with :func:`math.fsum`.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.signed_area([(0, 0), (2, 0), (0, 2)])
    2.0
    >>> mk.signed_area([(0, 0), (0, 2), (2, 0)])
    -2.0
    """
    data, kind, is_list = _prepare(p, "p", tiny=64)
    if is_list:
        pts = data
        if kind == FLOAT:
            terms = [x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1])]
            return math.fsum(terms) / 2.0
        s = sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1]))
        return float(s) / 2.0
    if kind == INT and int(np.abs(data).max()) < (1 << 30):
        x = data[:, 0]
        y = data[:, 1]
        s = int(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))
        return s / 2.0
    x = data[:, 0].astype(np.float64)
    y = data[:, 1].astype(np.float64)
    return math.fsum(x * np.roll(y, -1) - np.roll(x, -1) * y) / 2.0


def _sum_lists(A: list, B: list, kind: str, hull: bool) -> Polygon:
    """The pure-Python path of :func:`minkowski_sum` (tiny or exact inputs)."""
    if hull:
        A = _py_hull(A, kind)
        B = _py_hull(B, kind)
    qa, _, sa = _py_normalize(A, kind, "a")
    qb, _, sb = _py_normalize(B, kind, "b")
    return _flat_to_array(_py_merge(qa, sa, qb, sb, kind, flat=True), kind)


def minkowski_sum(a: ArrayLike2, b: ArrayLike2, *, hull: bool = False) -> Polygon:
    """Minkowski sum A ⊕ B = {a + b} of two convex polygons, in O(n + m).

    The edges of both polygons, normalized to counter-clockwise order from their
    bottom-most vertices, are merged by angle (an exact cross-product test, never an
    angle); parallel edges are taken together.

    Parameters
    ----------
    a, b : (n, 2) array_like or shapely geometry
        Convex polygons in any orientation and from any start vertex. Duplicate,
        closing-repeat and collinear vertices are tolerated; points and segments are
        valid.
    hull : bool, default False
        Accept any point sets and use their convex hulls.

    Returns
    -------
    (k, 2) ndarray
        The sum: CCW, bottom-most vertex (lowest y, then lowest x) first, no duplicate or
        collinear vertices. int64 for int input (Python ints in an object array beyond
        int64), float64 if either input is float (each coordinate the correctly rounded
        sum of two input vertices), Fractions for Fraction input. ``k <= n + m``.

    Raises
    ------
    NotConvexError
        An input is not convex (and ``hull`` is False); the message names the vertex.
    EmptyGeometryError, ShapeError, NonFiniteError, CoordinateTypeError
        Bad input; the message names the argument and the vertex.
    OverflowGeometryError
        A float result coordinate would be infinite.

    See Also
    --------
    minkowski_sum_many : many pairs in one call.
    cspace_obstacle : obstacle ⊕ (−robot).

    Notes
    -----
    Integer input is exact at any size (int64 kernels up to 2**53, Python ints beyond).
    For float input every decision is exact on the given values (filtered predicate with
    an exact fallback); only the output additions round.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.minkowski_sum([(0, 0), (2, 0), (0, 2)], [(0, 0), (1, 0), (1, 1), (0, 1)]).tolist()
    [[0, 0], [3, 0], [3, 1], [1, 3], [0, 3]]
    """
    ta = type(a)
    if ta is np.ndarray and type(b) is np.ndarray and not hull:
        # tiny int64/float64 arrays: the same fused path, on their Python values
        if (
            a.ndim == b.ndim == 2
            and a.shape[1] == b.shape[1] == 2
            and 3 <= a.shape[0] <= TINY
            and 3 <= b.shape[0] <= TINY
            and a.dtype == b.dtype
            and a.dtype in (np.int64, np.float64)
        ):
            a = a.tolist()
            b = b.tolist()
            ta = list
    if (ta is list or ta is tuple) and type(b) is ta and not hull:
        na, nb = len(a), len(b)
        if 3 <= na <= TINY and 3 <= nb <= TINY:
            # the tiny path: validation fused into the one-loop normalization (see _py_fast)
            try:
                k0 = INT if type(a[0][0]) is int else FLOAT
            except (TypeError, IndexError, KeyError):
                k0 = INT  # malformed: _py_fast gives None, py_points below raises
            fa = _py_fast(a, k0, raw=True)
            fb = _py_fast(b, k0, raw=True) if fa is not None else None
            if fb is not None:
                return _flat_to_array(_py_merge(fa[0], fa[2], fb[0], fb[2], k0, flat=True), k0)
        if na <= TINY and nb <= TINY:
            A, ka = py_points(a, "a")
            B, kb = py_points(b, "b")
            if ka == kb:
                return _sum_lists(A, B, ka, False)
    da, ka, la = _prepare(a, "a")
    db, kb, lb = _prepare(b, "b")
    A, B, kind, is_list = _unify(da, ka, la, db, kb, lb)
    if is_list:
        return _sum_lists(A, B, kind, hull)
    if hull:
        A = convex_hull(A)
        B = convex_hull(B)
    na, nb = A.shape[0], B.shape[0]
    out = np.empty((na + nb, 2), A.dtype)
    k, code, which, v = _kernels().sum_single(
        _pred_view(A, kind),
        A,
        _pred_view(B, kind),
        B,
        np.empty(na, np.int64),
        np.empty(nb, np.int64),
        np.empty(max(na, nb), np.int64),
        np.empty(max(na, nb), np.int8),
        out,
    )
    if code == _RANGE:
        return _sum_lists(_range_fallback(A, kind, "a"), _range_fallback(B, kind, "b"), kind, False)
    if code:
        _raise_kernel_error(code, which, int(v), ("a", "b"))
    return out[:k] if 2 * k >= na + nb else out[:k].copy()


def translate(p: ArrayLike2, v: Any) -> Polygon:
    """Translate a polygon by the vector ``v``: A ⊕ {v}, vertex order kept.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.translate([(0, 0), (1, 0), (0, 1)], (5, -2)).tolist()
    [[5, -2], [6, -2], [5, -1]]
    """
    data, kind, is_list = _prepare(p, "p", tiny=64)
    dv, kv, lv = _prepare([v] if len(np.shape(v)) == 1 else v, "v", tiny=64)
    if (len(dv) if lv else dv.shape[0]) != 1:
        from .errors import ShapeError

        raise ShapeError("v: expected one (x, y) vector")
    P, V, kind, is_list = _unify(data, kind, is_list, dv, kv, lv, ("p", "v"))
    if is_list:
        vx, vy = V[0]
        return _to_array([(x + vx, y + vy) for x, y in P], kind)
    out = P + V[0]
    if kind == FLOAT and not np.isfinite(out).all():
        raise OverflowGeometryError("result overflows float64 (a coordinate is infinite)")
    return out


def reflect(p: ArrayLike2) -> Polygon:
    """Point reflection through the origin: −P = {−p}.

    A point reflection is a rotation by 180°, so it keeps the orientation: the vertices
    are negated in the same order (a CCW polygon stays CCW). Reversing the order as well
    would make it clockwise.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.reflect([(0, 0), (2, 0), (0, 1)]).tolist()
    [[0, 0], [-2, 0], [0, -1]]
    """
    data, kind, is_list = _prepare(p, "p", tiny=64)
    if is_list:
        return _to_array([(-x, -y) for x, y in data], kind)
    if kind == INT and data.dtype == np.int64 and (data == INT64_MIN).any():
        return _to_array([(-x, -y) for x, y in data.tolist()], kind)
    return -data


def cspace_obstacle(obstacle: ArrayLike2, robot: ArrayLike2, *, hull: bool = False) -> Polygon:
    """Configuration-space obstacle ``obstacle ⊕ (−robot)`` for a translating robot.

    The robot, with its reference point at the origin of its own coordinates, collides
    with the obstacle exactly when the reference point lies in the returned polygon.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.cspace_obstacle([(0, 0), (4, 0), (4, 4), (0, 4)], [(0, 0), (1, 0), (0, 1)]).tolist()
    [[0, -1], [4, -1], [4, 4], [-1, 4], [-1, 0]]
    """
    return minkowski_sum(obstacle, reflect(robot), hull=hull)
