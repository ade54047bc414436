"""Rings of segments and circular arcs (CAD outlines), and their one-sided polygons.

A ring is a list of rows ``(x, y, bulge)``: piece ``i`` runs from point ``i`` to point
``i + 1`` (cyclically); ``bulge = tan(sweep / 4)`` is 0 for a segment and positive for an
arc turning counter-clockwise (the DXF LWPOLYLINE convention, as in
:class:`minkowski2d.OffsetArcs`).

:func:`approximate` replaces every arc by a polyline on one stated side:

* where the region lies inside the arc's circle (a convex arc), by the circumscribed
  polyline: the arc's end points and ``k`` corners at distance ``(r + m) / cos(φ/2)`` from
  the centre, ``φ = θ / k``, so each piece is tangent to (and outside) the circle;
* where the region lies outside the circle (a concave arc), by the inscribed polyline:
  the end points and ``k − 1`` points at distance ``r − m``, so each chord lies inside
  the circle;

so the polygon contains the region ("parts grow, holes shrink") and lies within the
tolerance ``ε`` of it: ``k = ceil(θ / φ_max)`` with ``φ_max`` from
``(r + m) / cos(φ/2) − r ≤ ε − m`` (circumscribed) or ``r − (r − m) cos(φ/2) ≤ ε − m``
(inscribed). ``m = 2**-42 · (max |centre| + r)`` is a rounding margin: the corners are
computed in float64, and a corner moved by rounding cannot cross the arc. A tolerance
``ε ≤ 4m`` cannot be met in float64 and raises a GeometryError. The end points of every
piece are kept exactly.

Examples
--------
>>> import numpy as np
>>> from minkowski2d._engine.arcs import approximate, ring_area
>>> half = [(1.0, 0.0, 1.0), (-1.0, 0.0, 0.0)]   # a half disk: an arc, then its diameter
>>> round(ring_area(half), 12) == round(np.pi / 2, 12)
True
>>> poly = approximate(half, region_left=True, tolerance=1e-3)
>>> bool(np.hypot(poly[:, 0], poly[:, 1]).min() >= 1 - 1e-12)  # the polygon contains it
True
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..errors import GeometryError

__all__ = [
    "DEFAULT_RELATIVE_TOLERANCE",
    "ROUNDING_MARGIN",
    "arc_of",
    "ring_area",
    "approximate",
    "circle_ring",
]

#: Default tolerance of an arc's approximation, relative to its radius: the one default
#: for every arc made a polygon (DXF arcs read, round joins of offsets, CLI defaults).
DEFAULT_RELATIVE_TOLERANCE = 1e-3
#: Relative size of the rounding margin (see the module notes).
ROUNDING_MARGIN = 2.0**-42

_MAX_STEP_OUTER = math.pi / 2
_MAX_STEP_INNER = math.pi


def arc_of(x0: float, y0: float, x1: float, y1: float, b: float) -> tuple[float, ...]:
    """``(cx, cy, r, a0, sweep)`` of the arc from ``(x0, y0)`` to ``(x1, y1)`` with bulge
    ``b != 0``: its centre, radius, the angle of its start from the centre and its signed
    sweep (radians, positive counter-clockwise)."""
    dx, dy = x1 - x0, y1 - y0
    half = math.hypot(dx, dy) / 2
    sweep = 4.0 * math.atan(b)
    # the centre is on the left of the chord for a counter-clockwise arc
    k = (1.0 - b * b) / (2.0 * b)
    mx, my = (x0 + x1) / 2, (y0 + y1) / 2
    cx, cy = mx - dy / 2 * k, my + dx / 2 * k
    r = half * (1.0 + b * b) / (2.0 * abs(b))
    return cx, cy, r, math.atan2(y0 - cy, x0 - cx), sweep


def circle_ring(cx: float, cy: float, r: float) -> list[tuple[float, float, float]]:
    """A full circle as two counter-clockwise half arcs."""
    return [(cx + r, cy, 1.0), (cx - r, cy, 1.0)]


def ring_area(rows: Any) -> float:
    """Signed area of a ring of segments and arcs (positive counter-clockwise)."""
    rows = [tuple(map(float, r)) for r in rows]
    n = len(rows)
    total = 0.0
    for i, (x0, y0, b) in enumerate(rows):
        x1, y1 = rows[(i + 1) % n][:2]
        total += 0.5 * (x0 * y1 - x1 * y0)
        if b != 0.0 and (x0, y0) != (x1, y1):
            _, _, r, _, sweep = arc_of(x0, y0, x1, y1, b)
            total += 0.5 * r * r * (sweep - math.sin(sweep))
    return total


def _step(r: float, eps: float, m: float, circumscribed: bool) -> float:
    if circumscribed:
        c = (r + m) / (r + eps - m)
        return min(2.0 * math.acos(min(c, 1.0)), _MAX_STEP_OUTER)
    c = (r - eps + m) / (r - m)
    if c <= -1.0:
        return _MAX_STEP_INNER
    return min(2.0 * math.acos(min(c, 1.0)), _MAX_STEP_INNER)


def approximate(
    rows: Any, region_left: bool, tolerance: float | None = None, name: str = "ring"
) -> np.ndarray:
    """The polygon (k, 2) of a ring of segments and arcs, containing the region on the
    ``region_left`` side of the ring and within ``tolerance`` of it (default
    :data:`DEFAULT_RELATIVE_TOLERANCE` times each arc's radius, raised to what float64
    can guarantee); see the module notes."""
    rows = [tuple(map(float, r)) for r in rows]
    n = len(rows)
    out: list[tuple[float, float]] = []
    for i, (x0, y0, b) in enumerate(rows):
        out.append((x0, y0))
        x1, y1 = rows[(i + 1) % n][:2]
        if b == 0.0 or (x0, y0) == (x1, y1):
            continue
        cx, cy, r, a0, sweep = arc_of(x0, y0, x1, y1, b)
        m = ROUNDING_MARGIN * (max(abs(cx), abs(cy)) + r)
        eps = DEFAULT_RELATIVE_TOLERANCE * r if tolerance is None else float(tolerance)
        if tolerance is None:
            eps = max(eps, 4 * m * (1 + 2.0**-20))
        if eps <= 4 * m:
            raise GeometryError(
                f"{name}: the arc tolerance {tolerance!r} is below what float64 can "
                f"guarantee at these magnitudes (about {4 * m:.3g})",
                argument=name,
                hint="raise the tolerance",
            )
        eps = min(eps, r)
        # the region is inside the circle when the centre is on its side of the arc
        circumscribed = (sweep > 0) == region_left
        phi_max = _step(r, eps, m, circumscribed)
        k = max(1, math.ceil(abs(sweep) / phi_max))
        phi = sweep / k
        if circumscribed:
            rr = (r + m) / math.cos(phi / 2)
            ang = a0 + (np.arange(k) + 0.5) * phi
        else:
            rr = r - m
            ang = a0 + np.arange(1, k) * phi
        out.extend(zip((cx + rr * np.cos(ang)).tolist(), (cy + rr * np.sin(ang)).tolist()))
    return np.array(out, dtype=np.float64).reshape(-1, 2)
