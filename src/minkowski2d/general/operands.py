"""Reading an operand of the general sum: types checked, coordinates kept raw, then validated
exactly in the core (no GEOS); convex decomposition."""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any

import numpy as np

from .._engine import core
from .._engine import options as _options
from .._engine.coerce import as_array, fits_float64, is_shapely, to_float
from ..batch import Ragged
from ..errors import (
    GeometryError,
    OverflowGeometryError,
    ShapeError,
)

SUM_METHODS = ("decomposition", "convolution")
DECOMPOSITIONS = ("hertel-mehlhorn", "triangulation")


# --------------------------------------------------------------------------------------
# input
#
# Reading an operand is two passes: _parse checks the types and keeps the raw
# coordinates, _build validates them exactly in the core (no GEOS). Nothing is scaled:
# the core decides exactly at every magnitude and rounds each result vertex once.


class _Operand:
    """A validated operand: polygons as ``_polygon.Rings`` (validated exactly, any
    orientation: ``orientation[r]`` is +1 for a ring given counter-clockwise), or a
    degenerate convex set (point or segment) held as a (k, 2) float64 array."""

    __slots__ = ("rings", "orientation", "flat", "name", "_geom")

    def __init__(self, rings: Any, orientation: Any, flat: np.ndarray | None, name: str) -> None:
        self.rings = rings
        self.orientation = orientation
        self.flat = flat
        self.name = name
        self._geom = None

    @property
    def geom(self) -> Any:
        """The operand as a shapely Polygon / MultiPolygon (exteriors CCW, holes CW)."""
        if self._geom is None:
            from .._engine.polygon import oriented, to_geometry

            multi = len(self.rings.polygon_offsets) > 2
            self._geom = to_geometry(oriented(self.rings, self.orientation), multi)
        return self._geom

    @property
    def convex_ring(self) -> np.ndarray | None:
        """The ring of a single convex polygon without holes (or the flat set), else None."""
        if self.flat is not None:
            return self.flat
        ro = self.rings.ring_offsets
        if len(ro) != 2:
            return None
        from .._engine.dispatch import check_convex

        ring = self.rings.coords[ro[0] : ro[1]]
        if len(ring) > 1 and (ring[0] == ring[-1]).all():
            ring = ring[:-1]
        return ring if check_convex(ring, self.name) else None

    def hull(self) -> np.ndarray:
        """Convex hull of the operand (exact, normalized)."""
        if self.flat is not None:
            return self.flat
        from .._engine import dispatch as D

        return np.asarray(D.hull(self.rings.coords, "points"), dtype=np.float64)


class _Raw:
    """A parsed, not yet validated operand: a shapely Polygon/MultiPolygon (``geom``),
    float64 coordinates (``coords``), exact coordinates (``exact``: Fractions, rounded
    only after the exact scale) or a collection of them (``items``)."""

    __slots__ = ("kind", "value", "name")

    def __init__(self, kind: str, value: Any, name: str) -> None:
        self.kind = kind
        self.value = value
        self.name = name


_EXACT_INT = core.FLOAT_EXACT_INT


def _int_coords(arr: np.ndarray, name: str) -> np.ndarray:
    """float64 copy of int coordinates; refuse an int that float64 cannot hold exactly."""
    big = np.abs(arr.astype(np.float64)) >= _EXACT_INT
    if big.any():
        for k in np.flatnonzero(big.any(axis=1)):
            for v in arr[k].tolist():
                _check_int(int(v), name, int(k))
    return arr.astype(np.float64)


def _check_int(v: int, name: str, vertex: int) -> None:
    if not fits_float64(v):
        raise GeometryError(
            f"{name}: vertex {vertex} has the integer coordinate {v}, which float64 "
            "cannot hold exactly (more than 53 significant bits, or beyond its range); the "
            "general routines "
            "compute in float64 and would round it",
            argument=name,
            vertex=vertex,
            hint="round or scale the coordinates to at most 53 significant bits, "
            "or use the exact convex routines",
        )


def _coords_raw(obj: Any, name: str) -> _Raw:
    data, kind = as_array(obj, name)
    if isinstance(data, list):  # exact kinds: Fractions or huge ints
        for k, p in enumerate(data):
            for v in p:
                if isinstance(v, int):
                    _check_int(v, name, k)
        return _Raw("exact", [(Fraction(x), Fraction(y)) for x, y in data], name)
    if data.dtype.kind == "i":
        return _Raw("coords", _int_coords(data, name), name)
    return _Raw("coords", np.asarray(data, dtype=np.float64), name)


def _parse(obj: Any, name: str) -> _Raw:
    """Check the type of one operand (see :func:`minkowski_sum_general`); no GEOS call."""

    if isinstance(obj, Ragged):
        obj = obj.to_list()
    if is_shapely(obj):
        from .._engine.polygon import polygon_parts

        got = None if obj.geom_type == "LinearRing" else polygon_parts(obj, name)
        if got is None:
            return _coords_raw(obj, name)  # ring, line, points
        if got.collection:  # a collection of polygons: their union is the operand
            parts = [_Raw("geom", p, f"{name}[{k}]") for k, p in enumerate(got.parts)]
            return _Raw("items", parts, name)
        return _Raw("geom", obj, name)
    if type(obj).__name__ == "UnboundedPolygon":
        raise ShapeError(
            f"{name}: the polygon has an unbounded outer boundary (CGAL N = 0); "
            "its Minkowski sum is unbounded too",
            argument=name,
        )
    if isinstance(obj, (list, tuple)) and obj and (is_shapely(obj[0]) or np.ndim(obj[0]) == 2):
        # a collection of polygons: their union is the operand
        return _Raw("items", [_parse(item, f"{name}[{k}]") for k, item in enumerate(obj)], name)
    return _coords_raw(obj, name)


def _float_ring(raw: _Raw) -> np.ndarray:
    """float64 coordinates of a parsed ring; exact values (Fractions, big ints) rounded
    once, correctly; a value beyond float64, or one that would lose bits below 2**-1022,
    is an OverflowGeometryError naming the vertex."""
    if raw.kind == "coords":
        return raw.value
    name = raw.name
    out = np.empty((len(raw.value), 2))
    for k, p in enumerate(raw.value):
        for j, v in enumerate(p):
            f = to_float(v)
            if math.isinf(f):
                raise OverflowGeometryError(
                    f"{name}: vertex {k} has a coordinate beyond float64 (±1.8e308)",
                    argument=name,
                    vertex=k,
                    hint="scale the input down; coordinates must fit in float64",
                )
            if v != 0 and abs(f) < 2.0**-1022:
                raise OverflowGeometryError(
                    f"{name}: vertex {k} has a coordinate that underflows float64 (a "
                    "nonzero value below 2**-1022 would be rounded to a multiple of "
                    "2**-1074)",
                    argument=name,
                    vertex=k,
                    hint="scale the input up; coordinates must be float64 normals",
                )
            out[k, j] = f
    return out


_HINT = "the boundary must not cross itself; holes must lie inside"


def _checked(rings: Any, name: str, multi: bool) -> _Operand:
    """An operand of validated rings (a polygon whose hole touches its shell twice is
    split into its parts by the exact overlay)."""
    from .._engine.polygon import check_split

    rings, ck = check_split(rings, name, _HINT, disjoint=multi)
    return _Operand(rings, ck.orientation, None, name)


def _build(raw: _Raw) -> _Operand:
    """Validate a parsed operand exactly (the core's checks; no GEOS)."""
    from .._engine.polygon import Rings, rings_of, rings_of_array

    name = raw.name
    rings: list[np.ndarray] | Rings
    if raw.kind == "items":
        rings = []
        for item in raw.value:
            op = _build(item)
            if op.flat is not None:
                # uniting would drop it, yet {p} ⊕ B has area: refuse rather than lose it
                raise ShapeError(
                    f"{item.name}: a point or segment in a collection of polygons "
                    "(every member of a collection must have area)",
                    argument=item.name,
                    hint="pass the point or segment as an operand of its own",
                )
            from .._engine.polygon import oriented

            o = oriented(op.rings, op.orientation)
            ro = o.ring_offsets
            rings += [o.coords[ro[r] : ro[r + 1]] for r in range(len(ro) - 1)]
        from .._engine.overlay import overlay

        g = overlay(rings, argument=name)
        if g.is_empty:
            raise ShapeError(f"{name}: the polygons have no area", argument=name)
        return _checked(rings_of(g), name, g.geom_type == "MultiPolygon")
    if raw.kind == "geom":
        return _checked(rings_of(raw.value), name, raw.value.geom_type == "MultiPolygon")
    ring = _float_ring(raw)
    rings = rings_of_array(ring)
    if len(ring):
        from .._engine.polygon import is_flat, probe

        status, reason, _, _, orientation, disconnected = probe(rings)
        if status == core.Status.OK and not disconnected.any():
            return _Operand(rings, orientation, None, name)
        if is_flat(status, reason):
            # a point, a segment, or collinear points: a degenerate convex set
            from .._engine import dispatch as D

            return _Operand(None, None, np.asarray(D.hull(ring, "points"), dtype=np.float64), name)
    return _checked(rings, name, False)


def _operands(*pairs: tuple[Any, str]) -> list[_Operand]:
    """Parse and validate the operands."""
    return [_build(_parse(obj, name)) for obj, name in pairs]


def _pieces(op: _Operand, method: str = "hertel-mehlhorn") -> Ragged:
    if op.flat is not None:
        return Ragged(op.flat, np.array([0, len(op.flat)], np.int64))
    from .._engine.decompose import decompose_rings

    coords, off = decompose_rings(op.rings, op.name, merge=method == "hertel-mehlhorn")
    return Ragged(coords, off)


def convex_decomposition(poly: Any, *, method: str = "hertel-mehlhorn") -> Ragged:
    """Split a polygon (holes allowed) into convex pieces.

    Parameters
    ----------
    poly : (n, 2) array_like, shapely Polygon or MultiPolygon, or a list of them
        A simple polygon (any orientation), a polygon with holes, or a collection
        (their union is decomposed).
    method : {"hertel-mehlhorn", "triangulation"}
        ``"triangulation"``: the compiled core's exact triangulation (a monotone
        partition by a plane sweep; input vertices only, holes supported).
        ``"hertel-mehlhorn"``: the triangles merged across every diagonal whose removal
        keeps both its endpoints convex (at most four times the optimal number of
        pieces).

    Returns
    -------
    Ragged
        The pieces as float64 vertices, each counter-clockwise from its bottom-most
        vertex (lowest y, then x), without collinear vertices. They cover the polygon
        and overlap only along shared edges. A point or segment gives one piece.

    Raises
    ------
    SelfIntersectionError
        The polygon is not valid (its boundary crosses itself, a hole lies outside ...).
    ShapeError, EmptyGeometryError, NonFiniteError
        Bad input.
    GeometryError
        An integer coordinate has more than 53 significant bits.

    Notes
    -----
    Time O(n log n) for the triangulation and O(n) for the merge; every decision is an
    exact sign (no GEOS), so the pieces' vertices are the input vertices bit for bit at
    any magnitude.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> L = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    >>> for piece in mk.convex_decomposition(L):
    ...     print(piece.tolist())
    [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]]
    [[0.0, 0.0], [1.0, 1.0], [1.0, 2.0], [0.0, 2.0]]
    >>> len(mk.convex_decomposition(L, method="triangulation"))
    4
    """
    method = _options.choice(method, "method", DECOMPOSITIONS)
    (P,) = _operands((poly, "poly"))
    return _pieces(P, method)
