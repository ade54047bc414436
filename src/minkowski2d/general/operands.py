"""Reading an operand of the general sum: types checked, coordinates kept raw, then validated
exactly in the core (no GEOS); convex decomposition."""

from __future__ import annotations

from typing import Any

import numpy as np

from .._engine import options as _options
from .._engine.reader import Polygons, read
from ..batch import Ragged
from ..errors import ShapeError

SUM_METHODS = ("decomposition", "convolution")
DECOMPOSITIONS = ("hertel-mehlhorn", "triangulation")


# --------------------------------------------------------------------------------------
# input: the one reader (minkowski2d._engine.reader), validated exactly in the core (no
# GEOS). Nothing is scaled: the core decides exactly at every magnitude and rounds each
# result vertex once.


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


_HINT = "the boundary must not cross itself; holes must lie inside"


def _read(obj: Any, name: str) -> _Operand:
    """One operand through the one reader (polygons, collections united, flat sets as
    their hull; ints exact in float64, Fractions rounded once), validated exactly in the
    core (no GEOS)."""
    if type(obj).__name__ == "UnboundedPolygon":
        raise ShapeError(
            f"{name}: the polygon has an unbounded outer boundary (CGAL N = 0); "
            "its Minkowski sum is unbounded too",
            argument=name,
        )
    got = read(
        obj, name, accept="polygons", numbers="fractions", validate=True,
        degenerate="hull", hint=_HINT,
    )  # fmt: skip
    return _operand(got)


def _operand(got: Polygons) -> _Operand:
    if got.flat is not None:
        return _Operand(None, None, got.flat, got.name)
    if got.parts is None:
        return _Operand(got.rings, got.orientation, None, got.name)
    # a collection of polygons: the operand is their union (the exact overlay)
    from .._engine.overlay import overlay
    from .._engine.polygon import check_split, oriented, rings_of

    rings: list[np.ndarray] = []
    for part in got.parts:
        op = _operand(part)
        o = oriented(op.rings, op.orientation)
        ro = o.ring_offsets
        rings += [o.coords[ro[r] : ro[r + 1]] for r in range(len(ro) - 1)]
    g = overlay(rings, argument=got.name)
    if g.is_empty:
        raise ShapeError(f"{got.name}: the polygons have no area", argument=got.name)
    united, ck = check_split(rings_of(g), got.name, _HINT, disjoint=g.geom_type == "MultiPolygon")
    return _Operand(united, ck.orientation, None, got.name)


def _operands(*pairs: tuple[Any, str]) -> list[_Operand]:
    """Read and validate the operands."""
    return [_read(obj, name) for obj, name in pairs]


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
