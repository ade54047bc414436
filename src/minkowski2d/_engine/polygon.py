"""Exact validity checks and triangulation of polygons with holes (the compiled core's
``polygon.hpp`` and ``triangulate.hpp``), and the errors they raise.

Polygons travel as :class:`Rings`: float64 coordinates (N, 2), ring offsets (R + 1) into
them and polygon offsets (P + 1) into the rings -- the first ring of a polygon is its
shell, the others its holes; any orientation, closing repeats and consecutive duplicates
allowed (shapely's ragged layout is one such value). Every decision is an exact sign
(``mk::cross_sign``), at every magnitude: a valid 3e-200 triangle is valid, a 1e300 one
too. GEOS is not asked.

Examples
--------
>>> from minkowski2d._engine.polygon import check, rings_of_array, triangulate
>>> L = rings_of_array([(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)])
>>> check(L, "a").orientation.tolist()
[1]
>>> len(triangulate(L, "a"))
4
>>> try:
...     check(rings_of_array([(0, 0), (2, 2), (2, 0), (0, 2)]), "a")
... except ValueError as e:
...     print(type(e).__name__, e.vertex, e)
SelfIntersectionError 2 a: not a valid polygon (the boundary crosses itself at vertex 2)
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

from ..errors import EmptyGeometryError, GeometryError, ShapeError
from . import core
from .core import Invalid, Status
from .status import status_error

__all__ = [
    "Rings",
    "Checked",
    "Invalid",
    "rings_of",
    "rings_of_array",
    "FLAT",
    "is_flat",
    "Polygonal",
    "polygon_parts",
    "check",
    "check_split",
    "triangulate",
    "oriented",
    "to_geometry",
    "problem_error",
]


_TEXT = {
    Invalid.RING_FEW_VERTICES: "fewer than 3 distinct vertices",
    Invalid.RING_NO_AREA: "no area: all vertices lie on one line",
    Invalid.RING_SPIKE: "the boundary doubles back on itself",
    Invalid.RING_CROSSES: "the boundary crosses itself",
    Invalid.RING_OVERLAPS: "two edges of the boundary overlap",
    Invalid.RING_TOUCHES: "the boundary touches itself",
    Invalid.RINGS_CROSS: "two rings cross",
    Invalid.RINGS_OVERLAP: "two rings share a segment",
    Invalid.HOLE_OUTSIDE: "a hole is not inside the shell",
    Invalid.HOLE_IN_HOLE: "a hole lies inside another hole",
    Invalid.POLYGONS_OVERLAP: "two polygons of the collection overlap",
}


#: the verdicts of a flat ring (a point, a segment, collinear points): the readers that
#: accept degenerate convex sets take its convex hull instead of refusing it
FLAT = (Invalid.RING_FEW_VERTICES, Invalid.RING_NO_AREA)


def is_flat(status: int, reason: int) -> bool:
    """Whether the core's verdict on a ring says it is flat (see :data:`FLAT`)."""
    return status == Status.INVALID_POLYGON and reason in FLAT


class Rings(NamedTuple):
    """Polygons as flat arrays (shapely's ragged layout for polygons)."""

    coords: np.ndarray  # (N, 2) float64, C-contiguous
    ring_offsets: np.ndarray  # (R + 1,) int64
    polygon_offsets: np.ndarray  # (P + 1,) int64


class Checked(NamedTuple):
    """What a successful check learned: ``orientation[r]`` is +1 for a ring given
    counter-clockwise, -1 for clockwise; ``disconnected[p]`` is True for a polygon whose
    interior touching rings split into parts (a hole touching the shell twice)."""

    orientation: np.ndarray  # (R,) int8
    disconnected: np.ndarray  # (P,) bool


def rings_of_array(points: Any) -> Rings:
    """One polygon without holes from an (n, 2) array-like of floats."""
    c = np.ascontiguousarray(points, dtype=np.float64).reshape(-1, 2)
    return Rings(c, np.array([0, len(c)], np.int64), np.array([0, 1], np.int64))


def rings_of(geom: Any) -> Rings:
    """The rings of a shapely Polygon or MultiPolygon (empty parts dropped)."""
    if geom.geom_type not in ("Polygon", "MultiPolygon"):
        raise TypeError(f"rings_of: a Polygon or MultiPolygon, not a {geom.geom_type}")
    xy, ro, po, _ = polygon_arrays(np.array([geom], dtype=object))
    return Rings(xy, ro, po)


#: the offsets of one polygon in one geometry (read-only: shared by every call)
_ONE = np.array([0, 1], np.int64)
_ONE.flags.writeable = False


class Polygonal(NamedTuple):
    """The polygons of one polygonal shapely geometry (see :func:`polygon_parts`)."""

    parts: np.ndarray  # (P,) object array of non-empty shapely Polygons, in order
    collection: bool  # a GeometryCollection (its parts may overlap: united by the caller)
    multi: bool  # a MultiPolygon (its parts must be disjoint)


def polygon_parts(
    geom: Any, name: str, *, empty_ok: bool = False, hint: str | None = None
) -> Polygonal | None:
    """The one reading of polygonal shapely input: a Polygon, a MultiPolygon, a
    LinearRing (the polygon it bounds) or a GeometryCollection of polygons, as its
    non-empty Polygons; None for a geometry that is not polygonal (points, lines: the
    caller reads their coordinates or refuses them).

    Raises EmptyGeometryError when nothing is left (unless ``empty_ok``), ShapeError
    for a GeometryCollection holding anything but polygons (``hint``: what to do).

    >>> import shapely
    >>> gc = shapely.GeometryCollection([shapely.box(0, 0, 1, 1), shapely.Polygon()])
    >>> r = polygon_parts(gc, "a")
    >>> len(r.parts), r.collection, r.multi
    (1, True, False)
    >>> polygon_parts(shapely.Point(0, 0), "a") is None
    True
    """
    import shapely

    gt = geom.geom_type
    if gt == "LinearRing":
        geom, gt = shapely.Polygon(geom), "Polygon"
    if gt == "Polygon":
        if not geom.is_empty:  # the common case, without the array calls below
            one = np.empty(1, object)
            one[0] = geom
            return Polygonal(one, False, False)
        parts = np.empty(0, object)
    elif gt == "MultiPolygon":
        parts = shapely.get_parts(geom)
    elif gt == "GeometryCollection":
        members = shapely.get_parts(geom)
        ids = shapely.get_type_id(members)
        bad = members[~np.isin(ids, (3, 6)) & ~shapely.is_empty(members)]
        if len(bad):
            raise ShapeError(
                f"{name}: a GeometryCollection holding a {bad[0].geom_type}: only polygons "
                "may be given here",
                argument=name,
                hint=hint,
            )
        parts = shapely.get_parts(members[np.isin(ids, (3, 6))])
    else:
        return None
    parts = parts[~shapely.is_empty(parts)]
    if not len(parts) and not empty_ok:
        raise EmptyGeometryError(f"{name}: empty {gt}", argument=name)
    return Polygonal(parts, gt == "GeometryCollection", gt == "MultiPolygon")


def polygon_arrays(geoms: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The polygons of T shapely geometries as flat arrays, the one reader of them.

    Returns (xy (N, 2) float64, ring offsets, polygon offsets, geometry offsets (T + 1)
    into the polygons): the parts of multi-polygons in order, empty polygons dropped,
    each ring shell first and closed (its first vertex repeated), as given (no
    reorientation), z dropped. GEOS writes 2-D WKB and the core reads it
    (``shapely.to_ragged_array`` or ``get_parts`` copy every part and ring into a new
    Python geometry: 4x the time, half of a small boolean's).

    Examples
    --------
    >>> import shapely
    >>> xy, ro, po, to = polygon_arrays(np.array([shapely.box(0, 0, 1, 1)], dtype=object))
    >>> len(xy), ro.tolist(), po.tolist(), to.tolist()
    (5, [0, 5], [0, 1], [0, 1])
    """
    import shapely

    if len(geoms) == 1:  # one polygon without holes (the most common operand): its ring
        g = geoms[0]
        if shapely.lib.get_type_id(g) == 3 and shapely.lib.get_num_interior_rings(g) == 0:
            xy = np.ascontiguousarray(shapely.get_coordinates(g), np.float64)
            if len(xy):
                return xy, np.array([0, len(xy)], np.int64), _ONE, _ONE
    wkb = shapely.to_wkb(geoms, output_dimension=2, byte_order=1, flavor="iso")
    return core.polygons_wkb_f(wkb.tolist())


def _where(rings: Rings, ring: int, vertex: int) -> str:
    po = rings.polygon_offsets
    p = int(np.searchsorted(po, ring, side="right")) - 1
    hole = ring - int(po[p]) - 1
    P = len(po) - 1
    parts = []
    if P > 1:
        parts.append(f"polygon {p}")
    if hole >= 0:
        parts.append(f"hole {hole}")
    elif len(rings.ring_offsets) - 1 > 1:
        parts.append("shell")
    parts.append(f"vertex {vertex}")
    return ", ".join(parts)


def problem_error(
    status: int,
    reason: int,
    ring: int,
    vertex: int,
    rings: Rings,
    name: str,
    hint: str | None = None,
    *,
    nonfinite_hint: str | None = None,
    what: str = "not a valid polygon",
) -> GeometryError:
    """The exception for a status of the core's polygon checks (vertex: the first vertex
    of the offending edge, counted inside its ring as the caller gave it)."""
    status, reason, ring, vertex = int(status), int(reason), int(ring), int(vertex)
    detail = None
    if status == Status.INVALID_POLYGON:
        detail = _TEXT.get(Invalid(reason), f"reason {reason}")
    return status_error(
        status,
        vertex,
        name,
        what=what if status == Status.INVALID_POLYGON else "the polygon check",
        where=_where(rings, ring, vertex),
        detail=detail,
        hint=nonfinite_hint if status == Status.NONFINITE else hint,
    )


def _args(rings: Rings) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    return (
        np.ascontiguousarray(rings.coords, dtype=np.float64),
        np.ascontiguousarray(rings.ring_offsets, dtype=np.int64),
        np.ascontiguousarray(rings.polygon_offsets, dtype=np.int64),
    )


def check(
    rings: Rings,
    name: str,
    hint: str | None = None,
    *,
    disjoint: bool = False,
    nonfinite_hint: str | None = None,
    what: str = "not a valid polygon",
) -> Checked:
    """Check every polygon exactly; raise the GeometryError of the first problem.

    A polygon is valid when each ring has at least 3 distinct vertices and area, each
    ring is simple, rings do not cross or share a segment (touching at points is fine),
    every hole lies inside the shell and no hole inside another. Polygons of a collection
    are checked against each other only with ``disjoint`` (their interiors must then be
    disjoint; touching at points is fine, as in a valid MultiPolygon).
    Time O(n log n) in practice (see polygon.hpp).
    """
    if len(rings.polygon_offsets) < 2:
        raise EmptyGeometryError(f"{name}: empty polygon", argument=name)
    status, reason, ring, vertex, orientation, disconnected = core.check_polygons_f(
        *_args(rings), bool(disjoint)
    )
    if status:
        raise problem_error(
            status, reason, ring, vertex, rings, name, hint,
            nonfinite_hint=nonfinite_hint, what=what,
        )  # fmt: skip
    return Checked(orientation, disconnected)


def check_split(
    rings: Rings,
    name: str,
    hint: str | None = None,
    *,
    disjoint: bool = False,
    nonfinite_hint: str | None = None,
) -> tuple[Rings, Checked]:
    """:func:`check`, and a polygon whose hole touches its shell at two points (valid
    for CGAL, "interior is disconnected" for GEOS: a well-defined region) split into its
    parts by the exact overlay (the union of its rings, traced ring by ring, splits at
    the touching points) and checked again: ``(rings, checked)``, the rings as they
    were or the parts'."""
    ck = check(rings, name, hint, disjoint=disjoint, nonfinite_hint=nonfinite_hint)
    if not ck.disconnected.any():
        return rings, ck
    from .overlay import overlay

    o = oriented(rings, ck.orientation)
    ro = o.ring_offsets
    parts = rings_of(
        overlay([o.coords[ro[r] : ro[r + 1]] for r in range(len(ro) - 1)], argument=name)
    )
    return parts, check(parts, name, hint, disjoint=True, nonfinite_hint=nonfinite_hint)


def probe(rings: Rings, *, disjoint: bool = False) -> tuple:
    """The core's verdict without raising: ``(status, reason, ring, vertex,
    orientation, disconnected)`` (``status`` 0 when valid)."""
    return core.check_polygons_f(*_args(rings), bool(disjoint))


def triangulate(
    rings: Rings,
    name: str,
    hint: str | None = None,
    *,
    delaunay: bool = True,
    what: str = "not a valid polygon",
) -> np.ndarray:
    """Check and triangulate every polygon: (T, 3) int64 vertex ids into
    ``rings.coords``, each triangle counter-clockwise; together they cover each polygon
    exactly with disjoint interiors and use input vertices only (where coordinates repeat,
    the smallest id). Polygons of a collection are triangulated one by one (their
    triangles overlap where they do). A monotone partition by a plane sweep, each
    monotone face by a stack (de Berg et al., ch. 3), O(n log n); then, with
    ``delaunay``, Lawson's flips towards the constrained Delaunay triangulation (exact
    incircle test), which Hertel-Mehlhorn turns into fewer convex pieces."""
    if len(rings.polygon_offsets) < 2:
        raise EmptyGeometryError(f"{name}: empty polygon", argument=name)
    status, reason, ring, vertex, tri = core.triangulate_polygons_f(*_args(rings), bool(delaunay))
    if status:
        raise problem_error(status, reason, ring, vertex, rings, name, hint, what=what)
    return tri


def oriented(rings: Rings, orientation: np.ndarray) -> Rings:
    """``rings`` with every shell counter-clockwise and every hole clockwise (the rings
    that run the other way reversed, coordinates unchanged)."""
    ro = rings.ring_offsets
    shell = np.zeros(len(ro) - 1, bool)
    shell[rings.polygon_offsets[:-1]] = True
    flip = np.flatnonzero(np.where(shell, orientation < 0, orientation > 0))
    if len(flip) == 0:
        return rings
    c = rings.coords.copy()
    for r in flip.tolist():
        a, b = int(ro[r]), int(ro[r + 1])
        c[a:b] = c[a:b][::-1]
    return Rings(c, ro, rings.polygon_offsets)


def to_geometry(rings: Rings, multi: bool) -> Any:
    """A shapely Polygon (``multi`` False, one polygon) or MultiPolygon."""
    import shapely

    P = len(rings.polygon_offsets) - 1
    if not multi:
        return shapely.from_ragged_array(
            shapely.GeometryType.POLYGON, rings.coords, (rings.ring_offsets, rings.polygon_offsets)
        )[0]
    return shapely.from_ragged_array(
        shapely.GeometryType.MULTIPOLYGON,
        rings.coords,
        (rings.ring_offsets, rings.polygon_offsets, np.array([0, P], np.int64)),
    )[0]
