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
Computed by the compiled core (``_core/offset.hpp``) in one call per polygon, or per
batch: every ring, with the offset side on its right, gives a closed *offset curve* —
the moved edges joined, at each vertex that is convex on that side, by a polygon around
its arc (``approx="outer"``: ``k = ceil(θ / φ)`` circumscribed corners, ``r (1/cos(φ/2) −
1) ≤ ε``; ``approx="inner"``: ``k`` inscribed chords, ``r (1 − cos(φ/2)) ≤ ε``), and by a
detour through the vertex elsewhere. The curve is the polygon's boundary plus the
boundaries of one *piece* per edge (the edge and its moved copy) and per arc, so its
winding number is ``[x ∈ P] + #pieces containing x``: a grow is where it is at least 1,
one exact overlay (a shrink builds the pieces inside and keeps ``P \\ pieces``). Every
piece is checked with exact predicates to cover the band of width ``r`` (outer) and to
stay within ``r + ε`` of the polygon, so

* grow, outer: ``P ⊕ D(r) ⊆ result ⊆ P ⊕ D(r + ε)``; inner: ``P ⊕ D(r − ε) ⊆ result ⊆ P ⊕ D(r)``;
* shrink, outer: ``P ⊖ D(r) ⊆ result ⊆ P ⊖ D(r − ε)``; inner: ``P ⊖ D(r + ε) ⊆ result ⊆ P ⊖ D(r)``.

For a grow ``P ⊕ D(r + ε) = (P ⊕ D(r)) ⊕ D(ε)``, so "within ε" is the Hausdorff distance.
An erosion is not continuous in ``r`` (a neck of width ``2r`` closes), so for a shrink the
guarantee is stated, as above, as a sandwich between the erosions by ``r`` and ``r ∓ ε``.

The overlay's vertices are exact until its output, where each crossing is rounded to the
nearest float64; the pieces are certified with a margin of that rounding (below one unit
in the last place of the result's largest coordinate), so the rounded result keeps the
guarantee. The least tolerance this allows is about ``2**-43 · r + 2**-46 · max |x|``
(``docs/offset.md``); a smaller one raises a :class:`~minkowski2d.errors.GeometryError`.
Fractions and integers beyond 2⁵³ are rounded to float64 once, and that rounding is part
of the margin.

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

from .arcs import ARC_STRAIGHT_ULPS as ARC_STRAIGHT_ULPS
from .arcs import VERIFY_RESOLUTION, OffsetArcs, offset_arcs
from .curves import APPROX, DEFAULT_TOLERANCE, JOINS, offset, offset_many

__all__ = [
    "offset",
    "offset_many",
    "offset_arcs",
    "OffsetArcs",
    "DEFAULT_TOLERANCE",
    "VERIFY_RESOLUTION",
    "APPROX",
    "JOINS",
]
