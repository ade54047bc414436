"""The exact Python path: the compiled core's normalization and merge, step for step, on
Python ints of any size and Fractions.

The dispatcher (:mod:`minkowski2d._engine.dispatch`) sends here only what the core cannot take
exactly: ints at or beyond 2**62, Fractions (also mixed with floats: a float is an exact
dyadic rational, so ``Fraction(x)`` loses nothing), and ints beyond 2**53 mixed with
floats. Every value here is an int or a Fraction, so ``ux * vy - uy * vx`` is exact as
written; no float arithmetic decides anything. Tests check that this path and the core
give identical results (``tests/test_convex.py``).

Examples
--------
>>> from minkowski2d._engine.exact import normalize_list
>>> normalize_list([(0, 2), (2, 0), (1, 0), (0, 0)], "p")[0]
[(0, 0), (2, 0), (0, 2)]
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

import numpy as np

from ..errors import NotConvexError
from .core import Status

__all__ = ["normalize_list", "merge_lists", "hull_list", "to_array", "not_convex", "cross"]


_HINT = "pass hull=True to use the convex hull"


def not_convex(name: str, code: int, vertex: int) -> NotConvexError:
    """The error for a convexity status code, naming the argument and vertex."""
    if code == Status.TURNS_BOTH_WAYS:
        msg = f"{name}: not convex: the boundary turns the other way at vertex {vertex}"
    elif code == Status.SPIKE:
        msg = f"{name}: not convex: the boundary doubles back on itself at vertex {vertex}"
    else:
        msg = (
            f"{name}: not convex: the edges wind around more than once "
            f"(a star polygon?), detected at vertex {vertex}"
        )
    return NotConvexError(f"{msg} ({_HINT})", vertex, argument=name, hint=_HINT)


def cross(a0: Any, a1: Any, b0: Any, b1: Any) -> int:
    """Exact sign of ``(a1 - a0) x (b1 - b0)`` for ints and Fractions."""
    d = (a1[0] - a0[0]) * (b1[1] - b0[1]) - (a1[1] - a0[1]) * (b1[0] - b0[0])
    return (d > 0) - (d < 0)


def normalize_list(pts: list, name: str) -> tuple[list, list, int]:
    """Normalize a convex polygon given as a list of exact (x, y) tuples.

    Returns ``(vertices, original_indices, split)``: CCW, bottom-most first, without
    duplicate or collinear vertices; ``split`` is the index of the first edge that points
    into the lower half-plane. Raises NotConvexError naming the caller's vertex.
    """
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
    # the far end of a segment: the first top-most vertex in input order (as the core)
    top0 = max(range(m), key=lambda t: (q[t][1], q[t][0]))
    top_pt, top_idx = q[top0], idx[top0]
    if b:
        q = q[b:] + q[:b]
        idx = idx[b:] + idx[:b]
    turns = []
    s = 0
    prv = q[-1]
    for t in range(m):
        cur = q[t]
        nxt = q[t + 1] if t + 1 < m else q[0]
        o = cross(prv, cur, prv, nxt)
        turns.append(o)
        if o:
            if not s:
                s = o
            elif o != s:
                raise not_convex(name, Status.TURNS_BOTH_WAYS, idx[t])
        prv = cur
    if not s:
        return [q[0], top_pt], [idx[0], top_idx], 1
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
                raise not_convex(name, Status.SPIKE, idx[t])
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
            raise not_convex(name, Status.WINDS_TWICE, idx[t])
        py0 = p1
    return q, idx, split


def merge_lists(A: list, sa: int, B: list, sb: int, record: list | None = None) -> list:
    """Merge the edges of two normalized polygons by angle; return the sum's vertices.

    When ``record`` is a list, one entry per step is appended: ``(source, i, j, cross)``
    where source is ``"A"``, ``"B"`` or ``"AB"``, ``i``/``j`` the edge indices compared
    (None once a list is exhausted) and ``cross`` the sign of ``a_i x b_j`` that decided
    (None when the half-planes or exhaustion decided) -- the same steps the core records.
    """
    na = len(A)
    nb = len(B)
    ea = na if na > 1 else 0
    eb = nb if nb > 1 else 0
    A2 = A + A[:1]
    B2 = B + B[:1]
    i = j = 0
    ax, ay = A[0]
    bx, by = B[0]
    out = [(ax + bx, ay + by)]
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
                d = (a1x - ax) * (b1y - by) - (a1y - ay) * (b1x - bx)
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
            out.append((ax + bx, ay + by))
    if len(out) > 1:
        out.pop()  # the last step returned to the start vertex
    return out


def hull_list(pts: list) -> list:
    """Andrew's monotone chain with exact orientation; CCW, collinear points dropped."""
    s = sorted(set(pts))
    if len(s) <= 2:
        return s
    h: list = []
    for p in s:
        while len(h) >= 2 and cross(h[-2], h[-1], h[-2], p) <= 0:
            h.pop()
        h.append(p)
    lower = len(h) + 1
    for p in reversed(s[:-1]):
        while len(h) >= lower and cross(h[-2], h[-1], h[-2], p) <= 0:
            h.pop()
        h.append(p)
    h.pop()
    return h


def to_array(pts: list, out_kind: str) -> np.ndarray:
    """Exact vertices to the output array of ``out_kind``: ``"int"`` (int64, or an
    object array of Python ints beyond int64), ``"float"`` (each coordinate the correctly
    rounded value of the exact one; OverflowGeometryError beyond float64), or
    ``"exact"`` (an object array of Fractions)."""
    if out_kind == "float":
        try:
            out = np.array([(float(x), float(y)) for x, y in pts], dtype=np.float64)
        except OverflowError:
            out = np.array([np.inf])
        if not np.isfinite(out).all():
            from .status import status_error  # (status imports this module)

            raise status_error(Status.OVERFLOW)
        return out.reshape(-1, 2)
    if out_kind == "int":
        try:
            return np.array(pts, dtype=np.int64).reshape(-1, 2)
        except OverflowError:
            pass
    out = np.empty((len(pts), 2), dtype=object)
    for k, (x, y) in enumerate(pts):
        if out_kind == "exact":
            x, y = Fraction(x), Fraction(y)
        out[k, 0] = x
        out[k, 1] = y
    return out
