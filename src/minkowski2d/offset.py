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

import math
from fractions import Fraction
from typing import Any, NamedTuple

import numpy as np

from . import _options
from ._coerce import as_array
from .errors import (
    EmptyGeometryError,
    GeometryError,
    NonFiniteError,
    OverflowGeometryError,
    ResourceLimitError,
    ShapeError,
)
from .predicates import orient_array

__all__ = [
    "offset",
    "offset_arcs",
    "OffsetArcs",
    "DEFAULT_TOLERANCE",
    "VERIFY_RESOLUTION",
    "APPROX",
    "JOINS",
]

#: The default ``tolerance`` of :func:`offset`, relative to the radius: ``1e-3 · |r|``
#: (raised to the least tolerance float64 can guarantee at the input's magnitude when
#: that is larger).
DEFAULT_TOLERANCE = 1e-3

APPROX = ("outer", "inner")
JOINS = ("round", "miter", "square")
_JOIN_CODE = {"round": 0, "miter": 1, "square": 2}


# --------------------------------------------------------------------------------------
# input


class _Input(NamedTuple):
    """One polygonal set for the core: rings (closing repeats allowed), which rings are
    holes, whether overlapping parts must be united first, and a bound on the distance
    between these float64 rings and the caller's exact input."""

    xy: np.ndarray  # (N, 2) float64
    ring_off: np.ndarray  # (R + 1,) int64
    hole: np.ndarray  # (R,) int64
    unite: bool
    delta: float


def _is_many(x: Any) -> bool:
    """True when ``x`` is a collection of polygons rather than one polygon."""
    if type(x) in (list, tuple) and x and type(x[0]) in (list, tuple) and len(x[0]) == 2:
        if not isinstance(x[0][0], (list, tuple, np.ndarray)):
            return False  # a list of points: one polygon
    name = type(x).__name__
    if name in ("GeoSeries", "GeometryArray"):
        return True
    if isinstance(x, np.ndarray):
        return x.dtype == object and x.ndim == 1 and (len(x) == 0 or not np.isscalar(x[0]))
    if type(x).__module__.startswith("shapely"):
        return False
    if isinstance(x, (list, tuple)):
        if len(x) == 0:
            return False
        first = x[0]
        return first is None or np.ndim(first) == 2 or type(first).__module__.startswith("shapely")
    return False


def _finite_float(v: Any, name: str) -> float:
    return _options.real(v, name)


_HINT = "repair it: the boundary must not cross itself, holes must lie inside"
_NONFINITE_HINT = "remove NaN and inf"


def _flat(geoms: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Coordinates (closing repeats kept), ring offsets and polygon offsets of shapely
    Polygons (empty ones dropped)."""
    import shapely

    if len(geoms) == 1 and shapely.lib.get_num_interior_rings(geoms[0]) == 0:
        xy = shapely.get_coordinates(geoms[0])
        return xy, np.array([0, len(xy)], np.int64), _GEOM1
    rings, part = shapely.get_rings(geoms, return_index=True)
    xy = shapely.get_coordinates(rings)
    ring_off = np.zeros(len(rings) + 1, np.int64)
    np.cumsum(shapely.get_num_coordinates(rings), out=ring_off[1:])
    starts = np.r_[0, np.flatnonzero(np.diff(part)) + 1]  # each polygon's shell
    poly_off = np.r_[starts, len(rings)].astype(np.int64)
    return np.ascontiguousarray(xy, np.float64), ring_off, poly_off


def _validated(xy, ring_off, poly_off, name: str, unite: bool) -> _Input:
    """Rings checked exactly by the core (the check of ``_polygon.check``: simple rings,
    holes inside, no crossing; no GEOS). Parts of a collection that overlap are united
    by the core before offsetting (``unite``; for a MultiPolygon, found by the same
    check)."""
    from ._core import _ext

    verdict = _ext.check_polygons_f(xy, ring_off, poly_off, False)
    if verdict[0]:
        from ._polygon import Rings, problem_error

        raise problem_error(
            *verdict[:4], Rings(xy, ring_off, poly_off), name, _HINT,
            nonfinite_hint=_NONFINITE_HINT,
        )  # fmt: skip
    if not unite and len(poly_off) > 2 and _ext.check_polygons_f(xy, ring_off, poly_off, True)[0]:
        unite = True  # a MultiPolygon whose valid parts overlap or share edges
    if len(ring_off) == 2:
        return _Input(xy, ring_off, _ZERO1, unite, 0.0)
    hole = np.ones(len(ring_off) - 1, np.int64)
    hole[poly_off[:-1]] = 0
    return _Input(xy, ring_off, hole, unite, 0.0)


def _shapely_input(geom: Any, name: str) -> _Input:
    """A shapely ring, polygon, multipolygon or collection of them, validated."""
    import shapely

    gt = geom.geom_type
    if gt == "LinearRing":
        geom = shapely.Polygon(geom)
        gt = "Polygon"
    unite = False
    if gt == "GeometryCollection":
        parts = shapely.get_parts(geom)
        if not np.isin(shapely.get_type_id(parts), (3, 6)).all():
            raise ShapeError(
                f"{name}: a GeometryCollection may hold only polygons",
                argument=name,
                hint="pass the polygons only",
            )
        polys = shapely.get_parts(parts)
        unite = len(polys) > 1
    elif gt == "Polygon":
        if geom.is_empty:
            raise EmptyGeometryError(f"{name}: empty Polygon", argument=name)
        return _validated(*_flat([geom]), name, False)
    elif gt == "MultiPolygon":
        polys = shapely.get_parts(geom)
    else:
        raise ShapeError(
            f"{name}: cannot offset a {gt} here (give a polygon, a ring or an (n, 2) array)",
            argument=name,
            hint="pass the coordinates as an (n, 2) array for a point or a segment",
        )
    polys = polys[~shapely.is_empty(polys)]
    if len(polys) == 0:
        raise EmptyGeometryError(f"{name}: empty {gt}", argument=name)
    return _validated(*_flat(polys), name, unite)


#: constant arrays of the single-polygon call
_ZERO1 = np.zeros(1, np.int64)
_ZEROF1 = np.zeros(1, np.float64)
_GEOM1 = np.array([0, 1], np.int64)
_POLYGON = 3  # shapely.GeometryType.POLYGON


def _one_ring(data: np.ndarray, delta: float) -> _Input:
    return _Input(
        np.ascontiguousarray(data, np.float64),
        np.array([0, len(data)], np.int64),
        _ZERO1,
        False,
        delta,
    )


def _rounding_error(exact: list, data: np.ndarray) -> float:
    """An upper bound on the distance between each exact vertex and its float64 value."""
    worst = Fraction(0)
    for (x, y), (fx, fy) in zip(exact, data.tolist()):
        worst = max(worst, abs(Fraction(x) - Fraction(fx)), abs(Fraction(y) - Fraction(fy)))
    # sqrt(2) < 1.5, and float() of a Fraction rounds to nearest
    return float(worst) * 1.5


def _read(obj: Any, name: str) -> _Input:
    """The rings of a polygon (any orientation: the core orients them exactly), or a ring
    of one or two vertices for a point or a segment."""
    import shapely

    if type(obj).__module__.startswith("shapely"):
        if obj.geom_type in ("Point", "LineString", "MultiPoint"):
            obj = shapely.get_coordinates(obj)
        else:
            return _shapely_input(obj, name)
    data, _kind = as_array(obj, name)
    delta = 0.0
    if isinstance(data, list):  # Fractions or huge ints: rounded to float64 once
        exact = data
        try:
            data = np.array([(float(Fraction(x)), float(Fraction(y))) for x, y in data])
        except OverflowError:
            data = None
        if data is None or not np.isfinite(data).all():
            raise OverflowGeometryError(
                f"{name}: a coordinate does not fit in float64",
                argument=name,
                hint="scale the input down",
            )
        delta = _rounding_error(exact, data)
    data = np.asarray(data, dtype=np.float64)
    if len(data) > 1 and (data[0] == data[-1]).all():
        data = data[:-1]
    if not np.isfinite(data).all():
        raise NonFiniteError(
            f"{name}: a coordinate is not finite", argument=name, hint=_NONFINITE_HINT
        )
    from ._polygon import Invalid, probe, rings_of_array

    rings = rings_of_array(data)
    if len(data) >= 3:
        status, reason = probe(rings)[:2]
        if status == 0:
            return _one_ring(data, delta)  # the common case: a valid ring (exact check)
        if reason not in (Invalid.RING_FEW_VERTICES, Invalid.RING_NO_AREA):
            _validated(*rings, name, False)  # raises the core's verdict
    # a point, a segment, or collinear points: a degenerate convex set
    from .convex import convex_hull

    return _one_ring(np.asarray(convex_hull(data), dtype=np.float64), delta)


# --------------------------------------------------------------------------------------
# the core call


def _distance_error(distance: Any, d: float) -> float:
    """How far the float64 distance is from the caller's exact one (ints, Fractions)."""
    if isinstance(distance, (float, np.floating)) or d == 0:
        return 0.0
    try:
        return float(abs(Fraction(distance) - Fraction(d))) * 1.5
    except (TypeError, ValueError):
        return 0.0


def _run(
    inputs: list[_Input],
    d: float,
    tol: float | None,
    approx: str,
    join: str,
    lim: float,
    extra_delta: float = 0.0,
    labels: bool = False,
) -> tuple:
    """One compiled call for all ``inputs``: the raw result of ``_ext.offset_rings``."""
    from ._core import _ext

    if len(inputs) == 1:
        a = inputs[0]
        xy, ro, hole = a.xy, a.ring_off, a.hole
        go = _GEOM1 if len(ro) == 2 else np.array([0, len(ro) - 1], np.int64)
    else:
        xy = np.concatenate([a.xy for a in inputs]) if inputs else np.empty((0, 2))
        nv = np.cumsum([0] + [len(a.xy) for a in inputs[:-1]])
        ro = np.concatenate([[0]] + [a.ring_off[1:] + s for a, s in zip(inputs, nv)])
        hole = np.concatenate([a.hole for a in inputs]) if inputs else np.empty(0, np.int64)
        go = np.cumsum([0] + [len(a.ring_off) - 1 for a in inputs])
    if len(inputs) == 1 and not inputs[0].unite and inputs[0].delta + extra_delta == 0:
        unite, delta = _ZERO1, _ZEROF1
    else:
        unite = np.fromiter((a.unite for a in inputs), np.int64, len(inputs))
        delta = np.fromiter((a.delta + extra_delta for a in inputs), np.float64, len(inputs))
    if xy.dtype != np.float64 or not xy.flags.c_contiguous:
        xy = np.ascontiguousarray(xy, np.float64)
    return _ext.offset_rings(
        xy,
        ro,
        hole,
        go,
        unite,
        delta,
        d,
        math.nan if tol is None else tol,
        DEFAULT_TOLERANCE,
        approx == "outer",
        _JOIN_CODE[join],
        lim,
        labels,
        1,
    )


def _raise_for(code: int, status: int, least: float, distance: Any, tolerance: Any) -> None:
    """Turn the core's verdict on one polygon into the documented error."""
    from ._core import _ext

    if code == _ext.OFFSET_TOLERANCE:
        raise GeometryError(
            f"tolerance: {tolerance!r} is below what float64 can guarantee at these "
            f"magnitudes (about {least:.3g})",
            argument="tolerance",
            hint="raise the tolerance, or move the polygon nearer to the origin",
        )
    if code == _ext.OFFSET_DISTANCE:
        raise GeometryError(
            f"distance: {distance!r} is too small for float64 at these magnitudes (the "
            f"least tolerance it can guarantee, about {least:.3g}, is more than half of it)",
            argument="distance",
            hint="move the polygon nearer to the origin, or offset by more",
        )
    if code == _ext.OFFSET_UNDERFLOW:
        raise OverflowGeometryError(
            "result: the offset underflows float64 (magnitude below 2**-1020: rounding to "
            "float64 may exceed the guaranteed tolerance)",
            argument="result",
            hint="scale the input up by a power of two, and the result down",
        )
    if status == _ext.RESOURCE:
        raise ResourceLimitError(
            "polygon: the offset's overlay would exceed its work limit",
            argument="polygon",
            hint="offset fewer vertices at once, or with a coarser tolerance",
        )
    if code == _ext.OFFSET_OVERFLOWS or status == _ext.OVERFLOW:
        raise OverflowGeometryError(
            "result: the offset does not fit in float64 (a coordinate is infinite)",
            argument="result",
            hint="scale the input down (or offset by a smaller distance)",
        )
    if code != _ext.OFFSET_FINE or status != _ext.OK:
        raise GeometryError(
            f"polygon: the offset could not be certified (code {code}, status {status})",
            argument="polygon",
            hint="this is a bug: please report the input",
        )


def _shapes(res: tuple, distance: Any, tolerance: Any) -> list:
    """Shapely results, one per polygonal set of the call (errors raised in order)."""
    import shapely

    xy, ro, po, go, info, _extra = res
    if info[:, :2].any():
        for g in range(len(go) - 1):
            st, cd, least = info[g, :3].tolist()
            _raise_for(int(cd), int(st), least, distance, tolerance)
    if len(go) == 2 and len(po) == 2:  # one polygon of one ring or more
        return [shapely.from_ragged_array(shapely.GeometryType.POLYGON, xy, (ro, po))[0]]
    polys = (
        shapely.from_ragged_array(shapely.GeometryType.POLYGON, xy, (ro, po))
        if len(po) > 1
        else np.empty(0, object)
    )
    out = []
    for g in range(len(go) - 1):
        k0, k1 = int(go[g]), int(go[g + 1])
        if k1 == k0:
            out.append(shapely.Polygon())
        elif k1 == k0 + 1:
            out.append(polys[k0])
        else:
            out.append(shapely.MultiPolygon(list(polys[k0:k1])))
    return out


# --------------------------------------------------------------------------------------
# the offset


def _list_result(res: list) -> np.ndarray:
    out = np.empty(len(res), dtype=object)
    out[:] = res
    return out


def _batch(polys: list, fn_args: tuple) -> list:
    """Offsets of a list of polygons (None stays None): one compiled call."""
    d, tol, approx, join, lim, distance, tolerance = fn_args
    idx = [k for k, g in enumerate(polys) if g is not None]
    inputs = [_read(polys[k], "polygon") for k in idx]
    out: list = [None] * len(polys)
    if inputs:
        res = _run(inputs, d, tol, approx, join, lim, _distance_error(distance, d))
        for k, g in zip(idx, _shapes(res, distance, tolerance)):
            out[k] = g
    return out


def _map(polygon: Any, fn_args: tuple) -> Any:
    """Offset one polygon, or each polygon of a container (same kind out)."""
    if not _is_many(polygon):
        return _batch([polygon], fn_args)[0]
    from ._containers import apply, boxed

    if boxed(polygon):
        # GeoSeries / GeometryArray / object arrays: the shared container rules
        return apply(
            lambda ps: _list_result(_batch(list(ps), fn_args)),
            polygon,
            convex=False,
            names=("polygon",),
        )
    # lists and tuples of polygons (containers went through _containers above)
    res = _batch(list(polygon), fn_args)
    if isinstance(polygon, np.ndarray):
        return _list_result(res)
    return tuple(res) if isinstance(polygon, tuple) else res


def _check_options(distance, tolerance, approx, join, miter_limit):
    if (
        type(distance) is float
        and (tolerance is None or type(tolerance) is float)
        and approx in APPROX
        and join in JOINS
        and type(approx) is str
        and type(join) is str
        and math.isfinite(distance)
        and (tolerance is None or (math.isfinite(tolerance) and tolerance > 0))
        and (type(miter_limit) in (float, int) and math.isfinite(miter_limit) and miter_limit >= 1)
    ):
        return distance, tolerance, float(miter_limit)  # the common case, already checked
    d = _finite_float(distance, "distance")
    _options.choice(approx, "approx", APPROX)
    _options.choice(join, "join", JOINS)
    lim = _finite_float(miter_limit, "miter_limit")
    if lim < 1.0:
        raise GeometryError(
            f"miter_limit: must be at least 1, got {miter_limit!r}",
            argument="miter_limit",
            hint="a miter limit of 1 bevels every corner at the offset distance",
        )
    tol = None
    if tolerance is not None:
        tol = _finite_float(tolerance, "tolerance")
        if tol <= 0:
            raise GeometryError(
                f"tolerance: must be positive, got {tolerance!r}",
                argument="tolerance",
                hint="e.g. 1e-3 times the distance",
            )
        if not isinstance(tolerance, (float, np.floating)) and Fraction(tol) > Fraction(tolerance):
            tol = math.nextafter(tol, 0.0)  # never a looser tolerance than the one asked for
    return d, tol, lim


def offset(
    polygon: Any,
    distance: float,
    *,
    tolerance: float | None = None,
    approx: str = "outer",
    join: str = "round",
    miter_limit: float = 2.0,
) -> Any:
    """Grow (``distance > 0``) or shrink (``distance < 0``) a polygon by a disk, with a
    guaranteed one-sided error.

    Parameters
    ----------
    polygon : (n, 2) array_like, shapely Polygon / MultiPolygon, or a container of them
        A convex or simple ring (either orientation), a polygon with holes, or a
        multipolygon; ints, floats or Fractions. A point or a segment (an array of one or
        two points, or collinear points) grows into a disk or a stadium. A list, tuple,
        numpy object array, GeometryArray or GeoSeries of polygons is offset member by
        member in one compiled call and the same kind of container is returned (None
        stays None).
    distance : float
        The tool radius ``r = |distance|``: positive grows, negative shrinks (a shrink
        may erase parts or split a polygon into several), zero returns the polygon.
    tolerance : float, optional
        The largest error ``ε > 0`` (in the input's units) of a round join; unused by
        miter and square joins. Default (None): :data:`DEFAULT_TOLERANCE` ``· |r|`` =
        ``1e-3 · |r|``, or the least tolerance float64 can guarantee at the input's
        magnitude when that is larger (about ``2**-43 · r + 2**-46 · max |x|``). The
        one-sided guarantee below holds for the tolerance used, given or default.
    approx : {"outer", "inner"}
        Which side of the true set the result lies on (see Returns).
    join : {"round", "miter", "square"}
        ``"round"``: the disk offset. ``"miter"``: the moved edges are extended to meet;
        a corner whose miter point lies farther than ``miter_limit · r`` from its vertex
        is cut off there, square to the bisector. ``"square"``: every convex corner is
        cut off at distance ``r`` from its vertex, square to the bisector.
    miter_limit : float
        See ``join``; at least 1.

    Returns
    -------
    shapely.Polygon or shapely.MultiPolygon
        Valid, exteriors counter-clockwise and holes clockwise, each ring from its least
        (x, y) vertex; an empty Polygon when a shrink erases everything. For
        ``join="round"`` and ``approx="outer"``: a grow satisfies
        ``P ⊕ D(r) ⊆ result ⊆ P ⊕ D(r + ε)`` and a shrink
        ``P ⊖ D(r) ⊆ result ⊆ P ⊖ D(r − ε)``; for ``approx="inner"``:
        ``P ⊕ D(r − ε) ⊆ result ⊆ P ⊕ D(r)`` and ``P ⊖ D(r + ε) ⊆ result ⊆ P ⊖ D(r)``.
        Each arc of exterior angle ``θ`` gets ``ceil(θ / φ)`` corners (outer; ``φ`` from
        ``r (1/cos(φ/2) − 1) ≤ ε``) or ``ceil(θ / φ) + 1`` vertices (inner; ``φ`` from
        ``r (1 − cos(φ/2)) ≤ ε``). Miter and square joins are polygons computed in
        float64 (``approx`` and ``tolerance`` unused).

    Raises
    ------
    GeometryError
        ``distance``, ``tolerance`` or ``miter_limit`` is not a finite number in range
        (``argument`` names which), or the tolerance is below what float64 can guarantee
        at the input's magnitude.
    OverflowGeometryError
        The result does not fit in float64, or its magnitude is below ``2**-1020``.
    SelfIntersectionError, ShapeError, EmptyGeometryError, NonFiniteError
        Bad polygon.

    See Also
    --------
    offset_arcs : the exact boundary as segments and circular arcs.

    Notes
    -----
    One compiled call: O(n + V) curve vertices (V the arc vertices), certified by exact
    predicates in O(n + V), then one exact overlay, O((n + V + k) log(n + V)) for k
    crossings of the curve (where gaps, slots and holes close). Every decision is an
    exact sign; see ``docs/offset.md``.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> tri = [(0, 0), (4, 0), (0, 3)]
    >>> g = mk.offset(tri, 1, tolerance=1e-3)
    >>> h = mk.offset(tri, 1, tolerance=1e-3, approx="inner")
    >>> h.within(g), h.area < 6 + 12 + 3.14159 < g.area  # area + perimeter + π r²
    (True, True)
    >>> mk.offset(tri, -0.5, tolerance=1e-3).geom_type
    'Polygon'
    >>> mk.offset([(0, 0), (2, 0), (2, 2), (0, 2)], 1, tolerance=None, join="miter").wkt
    'POLYGON ((-1 -1, 3 -1, 3 3, -1 3, -1 -1))'
    """
    d, tol, lim = _check_options(distance, tolerance, approx, join, miter_limit)
    if not _is_many(polygon):
        # one polygon: the shortest way through
        res = _run([_read(polygon, "polygon")], d, tol, approx, join, lim,
                   _distance_error(distance, d))  # fmt: skip
        return _shapes(res, distance, tolerance)[0]
    return _map(polygon, (d, tol, approx, join, lim, distance, tolerance))


def _check_underflow(big: float) -> None:
    """Refuse results whose magnitude ``big`` is so small that rounding them to float64
    (to multiples of 2**-1074) may exceed the margin that keeps the error on its side:
    an OverflowGeometryError (an underflow), never a result off its side."""
    if 0.0 < big < _UNDERFLOW:
        raise OverflowGeometryError(
            f"result: the offset underflows float64 (magnitude {big!r}: rounding to float64 "
            "may exceed the guaranteed tolerance)",
            argument="result",
            hint="scale the input up by a power of two, and the result down",
        )


#: Results of a smaller magnitude cannot keep the one-sided guarantee in float64.
_UNDERFLOW = 2.0**-1020


# --------------------------------------------------------------------------------------
# exact arcs

#: An arc whose sagitta is at most this many units in the last place of the largest
#: coordinate is written as a straight segment (it cannot be told from one in float64).
ARC_STRAIGHT_ULPS = 4

#: The resolution of :func:`offset_arcs`' verification, relative to ``r``: a junction is
#: on the exact boundary when its distance from the polygon is ``r`` to within
#: ``VERIFY_RESOLUTION · r`` (or the least tolerance float64 guarantees at the input's
#: magnitude, when that is larger), and a piece runs forwards when its extent is not
#: negative by more than that. It judges junctions computed in float64 from exact
#: features; which features bound the offset comes from the exact overlay.
VERIFY_RESOLUTION = 2.0**-30
#: At most this many rounds of repairs (a feature inserted where a junction is nearer
#: than ``r`` to the polygon, a piece that runs backwards dropped).
_MAX_REPAIRS = 8

#: The relative tolerances of the polygons that :func:`offset_arcs` traces to find which
#: moved edges and arcs bound the offset, and in which order: the next one is tried when
#: a junction of the result is not at distance r (± the slack) from the polygon, or a
#: piece runs backwards.
_TRACE_TOLERANCES = (1e-2, 1e-4, 1e-6)


class OffsetArcs:
    """The exact boundary of an offset: rings of straight segments and circular arcs.

    Attributes
    ----------
    polygons : list of list of (k, 5) float64 ndarray
        One entry per polygon: its exterior ring (counter-clockwise), then its holes
        (clockwise). Row ``i`` of a ring is ``(x, y, bulge, cx, cy)``: the start point of
        piece ``i`` (the piece runs to the start of row ``i + 1``, cyclically), its bulge
        ``tan(sweep / 4)`` (positive counter-clockwise, 0 for a straight piece: the DXF
        LWPOLYLINE convention) and the arc's centre (NaN for a straight piece).
    radius : float
        ``|distance|``: the radius of every arc.
    distance : float
        The signed offset distance.
    verified : bool
        True when every junction was checked to lie at distance ``r`` from the polygon
        (to ``2**-30`` of the coordinates' magnitude), every piece to run forwards within
        its moved edge or its vertex's normal cone, and the area and topology to agree
        with the traced polygon. False (rare, near critical radii of several merging
        parts) means the best plausible tracing is returned unverified.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> arcs = mk.offset_arcs([(0, 0), (2, 0), (2, 1), (0, 1)], 1)
    >>> ring = arcs.polygons[0][0]
    >>> ring.shape, round(float(ring[:, 2].max()), 6)  # tan(90° / 4) for quarter arcs
    ((8, 5), 0.414214)
    >>> round(arcs.area, 6) == round(2 + 6 + 3.141592653589793, 6)
    True
    """

    __slots__ = ("polygons", "radius", "distance", "verified", "_source")

    def __init__(
        self, polygons: list, distance: float, source: Any = None, verified: bool = True
    ) -> None:
        self.polygons = polygons
        self.distance = float(distance)
        self.radius = abs(float(distance))
        self.verified = verified
        self._source = source

    def __repr__(self) -> str:
        n = sum(len(r) for p in self.polygons for r in p)
        a = sum(int((~np.isnan(r[:, 3])).sum()) for p in self.polygons for r in p)
        return f"OffsetArcs({len(self.polygons)} polygons, {n} pieces, {a} arcs)"

    def __len__(self) -> int:
        return len(self.polygons)

    @property
    def rings(self) -> list:
        """Every ring, exteriors and holes, in order."""
        return [r for p in self.polygons for r in p]

    @property
    def area(self) -> float:
        """The exact area (shoelace over the chords plus each arc's circular segment),
        computed at a power-of-two scale (exact) so that no product overflows; an area
        beyond float64 raises :class:`~minkowski2d.errors.OverflowGeometryError`."""
        rings = self.rings
        big = max([float(np.abs(r[:, :2]).max()) for r in rings if len(r)] + [self.radius])
        k = -math.frexp(big)[1] if big > 0 else 0
        rad = math.ldexp(self.radius, k)
        total = 0.0
        for ring in rings:
            x, y = np.ldexp(ring[:, 0], k), np.ldexp(ring[:, 1], k)
            b = ring[:, 2]
            x1, y1 = np.roll(x, -1), np.roll(y, -1)
            total += 0.5 * float((x * y1 - x1 * y).sum())
            arc = b != 0
            if arc.any():
                sweep = 4.0 * np.arctan(b[arc])
                seg = 0.5 * rad**2 * (sweep - np.sin(sweep))
                total += float(seg.sum())
        try:
            return math.ldexp(total, -2 * k)
        except OverflowError:
            raise OverflowGeometryError(
                f"area: {total!r} * 2**{-2 * k} does not fit in float64",
                argument="area",
                hint="scale the polygon down",
            ) from None

    def _plot_(self, ax: Any, **kwargs: Any) -> Any:
        """Draw for :func:`minkowski2d.plot`: the straight pieces and the arcs in two
        colours (arcs sampled for display only, every 2 degrees), arc centres as dots."""
        line = kwargs.pop("linewidth", 1.5)
        for ring in self.rings:
            n = len(ring)
            for i in range(n):
                x0, y0, b, cx, cy = (float(v) for v in ring[i])
                x1, y1 = float(ring[(i + 1) % n, 0]), float(ring[(i + 1) % n, 1])
                if b == 0.0:
                    ax.plot([x0, x1], [y0, y1], color="C0", linewidth=line)
                    continue
                sweep = 4.0 * np.arctan(b)
                t0 = np.arctan2(y0 - cy, x0 - cx)  # display only: no decision here
                ts = t0 + np.linspace(0.0, sweep, max(2, int(abs(sweep) / 0.035) + 2))
                ax.plot(
                    cx + self.radius * np.cos(ts),
                    cy + self.radius * np.sin(ts),
                    color="C3",
                    linewidth=line,
                )
                ax.plot([cx], [cy], ".", color="C3", markersize=3)
        if self._source is not None:
            from .plot import plot as _draw

            _draw(self._source, ax=ax, facecolor="0.85", edgecolor="0.4", **kwargs)
        ax.set_aspect("equal", adjustable="datalim")
        return ax

    def to_polygon(self, tolerance: float | None = None, approx: str = "outer") -> Any:
        """A polygon within ``tolerance`` of this boundary, on the side ``approx`` says:
        the same as :func:`offset` with these arguments (and its guarantee).

        Examples
        --------
        >>> import minkowski2d as mk
        >>> arcs = mk.offset_arcs([(0, 0), (2, 0), (1, 2)], 0.5)
        >>> arcs.to_polygon(1e-3).area > arcs.area > arcs.to_polygon(1e-3, "inner").area
        True
        """
        return offset(self._source, self.distance, tolerance=tolerance, approx=approx)

    def svg_path(self, flip_y: bool = False) -> str:
        """SVG path data: ``M``, ``L`` and ``A`` commands, one closed subpath per ring.

        With ``flip_y`` the y coordinates are negated (SVG's y axis points down), which
        also flips every arc's sweep flag. Fill with ``fill-rule="evenodd"`` or
        ``"nonzero"`` (holes run the other way).

        Examples
        --------
        >>> import minkowski2d as mk
        >>> print(mk.offset_arcs([(0, 0)], 1).svg_path())
        M 1 0 A 1 1 0 0 1 -1 0 A 1 1 0 0 1 1 0 Z
        """
        out = []
        sy = -1.0 if flip_y else 1.0
        r = _num(self.radius)
        for ring in self.rings:
            parts = [f"M {_num(ring[0, 0])} {_num(sy * ring[0, 1])}"]
            k = len(ring)
            for i in range(k):
                x, y = ring[(i + 1) % k, 0], sy * ring[(i + 1) % k, 1]
                b = ring[i, 2]
                if b == 0:
                    if i + 1 < k:
                        parts.append(f"L {_num(x)} {_num(y)}")
                    continue
                sweep = 4.0 * math.atan(b)
                large = 1 if abs(sweep) > math.pi else 0
                pos = (sweep > 0) != flip_y
                parts.append(f"A {r} {r} 0 {large} {1 if pos else 0} {_num(x)} {_num(y)}")
            parts.append("Z")
            out.append(" ".join(parts))
        return " ".join(out)

    def to_svg(self) -> str:
        """A standalone SVG document (y up, as in the input).

        Examples
        --------
        >>> import minkowski2d as mk
        >>> mk.offset_arcs([(0, 0), (1, 0), (0, 1)], 0.2).to_svg().startswith("<svg")
        True
        """
        pts = np.concatenate([r[:, :2] for r in self.rings]) if self.rings else np.zeros((1, 2))
        x0, y0 = pts.min(axis=0) - self.radius
        x1, y1 = pts.max(axis=0) + self.radius
        w, h = max(x1 - x0, 1e-300), max(y1 - y0, 1e-300)
        pad = 0.05 * max(w, h)
        vb = f"{x0 - pad} {-(y1 + pad)} {w + 2 * pad} {h + 2 * pad}"
        stroke = 0.01 * max(w, h)
        return (
            f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{vb}" width="400" '
            f'height="400">\n  <path d="{self.svg_path(flip_y=True)}" fill="#4a90d9" '
            f'fill-opacity="0.4" fill-rule="evenodd" stroke="#1f4e79" '
            f'stroke-width="{stroke}"/>\n</svg>'
        )

    def to_dxf(self, path: Any = None, *, layer: str = "OFFSET") -> Any:
        """The rings as closed LWPOLYLINE entities with bulges (ezdxf).

        Exteriors are counter-clockwise and holes clockwise. Needs the optional
        dependency ezdxf (``pip install minkowski2d[dxf]``).

        Parameters
        ----------
        path : str or path-like, optional
            Where to save the drawing; without it, nothing is written.
        layer : str
            The entities' layer.

        Returns
        -------
        ezdxf.document.Drawing

        Examples
        --------
        >>> import minkowski2d as mk
        >>> doc = mk.offset_arcs([(0, 0), (2, 0), (2, 2), (0, 2)], 1).to_dxf()
        >>> [e.dxftype() for e in doc.modelspace()]
        ['LWPOLYLINE']
        """
        try:
            import ezdxf
        except ImportError as exc:  # pragma: no cover - depends on the environment
            raise ImportError("DXF output needs ezdxf: pip install 'minkowski2d[dxf]'") from exc
        doc = ezdxf.new("R2010")
        msp = doc.modelspace()
        for ring in self.rings:
            pts = [(float(x), float(y), float(b)) for x, y, b in ring[:, :3]]
            msp.add_lwpolyline(pts, format="xyb", close=True, dxfattribs={"layer": layer})
        if path is not None:
            doc.saveas(path)
        return doc


def _num(v: float) -> str:
    v = float(v) + 0.0  # no "-0"
    return repr(v).removesuffix(".0") if v.is_integer() else repr(v)


def _junctions(labels, near, MA0, MA1, U, V, VS, VE, r, sign) -> np.ndarray:
    """Where piece ``labels[q - 1]`` meets piece ``labels[q]`` (moved edge ``i >= 0`` or
    the arc of vertex ``-1 - i``): the tangent point, or the crossing of the two carriers
    (line/line, line/circle, circle/circle) nearest to ``near[q]``; a near-miss (the
    carriers do not quite meet in float64) gives the closest point."""
    a = np.roll(labels, 1)
    b = labels
    J = near.astype(np.float64).copy()
    la, lb = a >= 0, b >= 0
    ia, ib = np.where(la, a, 0), np.where(lb, b, 0)
    va, vb = np.where(la, 0, -1 - a), np.where(lb, 0, -1 - b)
    # line -> its end vertex's arc, arc -> its vertex's next line: tangent points (a
    # shrink's rings run backwards along the rings' edges)
    if sign > 0:
        t1 = la & ~lb & (VE[ia] == vb)
        t2 = ~la & lb & (VS[ib] == va)
        J[t1] = MA1[ia[t1]]
        J[t2] = MA0[ib[t2]]
    else:
        t1 = la & ~lb & (VS[ia] == vb)
        t2 = ~la & lb & (VE[ib] == va)
        J[t1] = MA0[ia[t1]]
        J[t2] = MA1[ib[t2]]
    rest = ~(t1 | t2)
    # line / line
    ll = rest & la & lb
    if ll.any():
        p, u = MA0[ia[ll]], U[ia[ll]]
        q, v = MA0[ib[ll]], U[ib[ll]]
        den = u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]
        with np.errstate(all="ignore"):
            t = ((q[:, 0] - p[:, 0]) * v[:, 1] - (q[:, 1] - p[:, 1]) * v[:, 0]) / den
            X = p + t[:, None] * u
        ok = den != 0
        J[np.flatnonzero(ll)[ok]] = X[ok]
    # line / circle (either order)
    lc = rest & (la != lb)
    if lc.any():
        li = np.where(la, ia, ib)[lc]
        ci = np.where(la, vb, va)[lc]
        p, u, c = MA0[li], U[li], V[ci]
        w = p - c
        bb = (w * u).sum(axis=1)
        disc = bb * bb - ((w * w).sum(axis=1) - r * r)
        h = np.sqrt(np.maximum(disc, 0.0))
        P1 = p + (-bb - h)[:, None] * u
        P2 = p + (-bb + h)[:, None] * u
        nr = near[lc]
        pick = ((P1 - nr) ** 2).sum(axis=1) <= ((P2 - nr) ** 2).sum(axis=1)
        J[lc] = np.where(pick[:, None], P1, P2)
    # circle / circle
    cc = rest & ~la & ~lb
    if cc.any():
        c1, c2 = V[va[cc]], V[vb[cc]]
        dv = c2 - c1
        dd = np.hypot(dv[:, 0], dv[:, 1])
        with np.errstate(all="ignore"):
            e = dv / dd[:, None]
        m = c1 + (dd / 2)[:, None] * e
        h = np.sqrt(np.maximum(r * r - (dd / 2) ** 2, 0.0))
        perp = np.column_stack([-e[:, 1], e[:, 0]])
        P1 = m + h[:, None] * perp
        P2 = m - h[:, None] * perp
        nr = near[cc]
        pick = ((P1 - nr) ** 2).sum(axis=1) <= ((P2 - nr) ** 2).sum(axis=1)
        X = np.where(pick[:, None], P1, P2)
        ok = dd > 0
        J[np.flatnonzero(cc)[ok]] = X[ok]
    return J


def _nearest(pts, A0, U, L, VS, VE, reach: float, chunk: int = 64) -> tuple:
    """Label of the nearest feature of the polygon (edge ``e`` >= 0 for its interior,
    ``-1 - v`` for vertex ``v``) and the distance, for each point (float64: a
    construction for the repairs and the verification, not a decision of the offset).
    The points come in boundary order, so consecutive ones are close: a chunk of them
    looks at the edges whose boxes come within ``R`` of the chunk's box (``R`` from
    ``reach`` up, doubled until every point has found an edge within ``R``: no other
    edge can then be nearer)."""
    n = len(pts)
    lab = np.empty(n, np.int64)
    dist = np.empty(n)
    A1 = A0 + L[:, None] * U
    lo, hi = np.minimum(A0, A1), np.maximum(A0, A1)
    span = float(np.ptp(np.concatenate([pts, A0]), axis=0).max()) + 1.0
    for s in range(0, n, chunk):
        P = pts[s : s + chunk]
        p0, p1 = P.min(axis=0), P.max(axis=0)
        R = max(reach, 1e-300)
        while True:
            cand = np.flatnonzero(((hi >= p0 - R) & (lo <= p1 + R)).all(axis=1))
            if len(cand):
                w = P[:, None, :] - A0[None, cand, :]
                t = np.clip((w * U[None, cand]).sum(-1), 0.0, L[None, cand])
                q = w - t[..., None] * U[None, cand]
                d2 = (q * q).sum(-1)
                k = d2.argmin(axis=1)
                rows = np.arange(len(P))
                best = np.sqrt(d2[rows, k])
                if best.max() <= R or len(cand) == len(L) or R > span:
                    e = cand[k]
                    te = t[rows, k]
                    lab[s : s + chunk] = np.where(
                        te <= 0, -1 - VS[e], np.where(te >= L[e], -1 - VE[e], e)
                    )
                    dist[s : s + chunk] = best
                    break
            R *= 2
    return lab, dist


def _trace(
    items: list,
    rings: list[np.ndarray],
    r: float,
    sign: float,
    slack: float,
    repairs: int = _MAX_REPAIRS,
) -> tuple[list, bool]:
    """Exact rings of segments and arcs.

    ``items``: polygons, each a list of rings ``(coords, labels)`` tracing the offset
    (``labels`` per segment: the moved edge ``e`` (>= 0) or the arc of vertex ``v``
    (``-1 - v``) it lies on, from the core's overlay; None to label each segment by the
    nearest feature). ``rings``: the polygon's rings with the offset side on their right
    (moved by ``r``); ``sign``: +1 when the arcs turn counter-clockwise (a grow), -1 (a
    shrink); ``slack``: the verification's resolution.
    """
    from ._core import _ext

    starts, ends, vid_s, vid_e = [], [], [], []
    base = 0
    for ring in rings:
        n = len(ring)
        idx = np.arange(n)
        if n >= 2:
            starts.append(ring)
            ends.append(np.roll(ring, -1, 0))
            vid_s.append(base + idx)
            vid_e.append(base + (idx + 1) % n)
        base += n
    V = np.concatenate(rings)
    A0, A1 = np.concatenate(starts), np.concatenate(ends)
    VS, VE = np.concatenate(vid_s), np.concatenate(vid_e)
    D = A1 - A0
    L = np.hypot(D[:, 0], D[:, 1])
    U = D / L[:, None]
    N = np.column_stack([U[:, 1], -U[:, 0]])
    MA0, MA1 = A0 + r * N, A1 + r * N  # the moved edges
    # exterior angle of each vertex on the offset side (0 where it is not convex)
    ein = np.empty(len(V), np.int64)
    eout = np.empty(len(V), np.int64)
    ein[VE] = np.arange(len(VE))
    eout[VS] = np.arange(len(VS))
    ui, uo = U[ein], U[eout]
    theta = np.maximum(
        np.arctan2(ui[:, 0] * uo[:, 1] - ui[:, 1] * uo[:, 0], (ui * uo).sum(axis=1)), 0.0
    )
    alpha_in = np.arctan2(N[ein, 1], N[ein, 0])  # where each vertex's arc starts
    verified = [True]
    big = max(float(np.abs(V).max()), r)
    tiny = ARC_STRAIGHT_ULPS * math.ulp(big)

    def extents(la, J, strict=False):
        """Each piece's extent, negative when it runs backwards: along its moved edge
        (a shrink's rings run against the reversed rings' edges), or the room left in
        its vertex's exterior angle for an arc. ``strict``: also negative when the piece
        leaves its moved edge's segment or its arc's normal cone."""
        J1 = np.roll(J, -1, 0)
        ext = np.full(len(la), np.inf)
        ln = la >= 0
        e = la[ln]
        t0 = ((J[ln] - MA0[e]) * U[e]).sum(axis=1)
        t1 = ((J1[ln] - MA0[e]) * U[e]).sum(axis=1)
        ext[ln] = sign * (t1 - t0) + slack
        if strict:
            lo, hi = np.minimum(t0, t1), np.maximum(t0, t1)
            ext[ln] = np.minimum(ext[ln], np.minimum(lo + slack, L[e] + slack - hi))
        ar = ~ln
        if ar.any():
            v = -1 - la[ar]
            ctr = V[v]
            a0 = np.arctan2(J[ar, 1] - ctr[:, 1], J[ar, 0] - ctr[:, 0])
            a1 = np.arctan2(J1[ar, 1] - ctr[:, 1], J1[ar, 0] - ctr[:, 0])
            sw = np.mod(sign * (a1 - a0), 2 * math.pi)
            # a closed full turn (one arc alone) has sweep 0 here: fine
            ext[ar] = theta[v] + slack / r - sw
            if strict:
                first = a0 if sign > 0 else a1  # the end nearer the incoming normal
                off = np.mod(first - alpha_in[v] + slack / r, 2 * math.pi) - slack / r
                ext[ar] = np.minimum(ext[ar], theta[v] + slack / r - (off + sw))
        return ext

    def nearest(pts):
        """Label of the nearest feature (edge interior or vertex) and its distance."""
        return _nearest(pts, A0, U, L, VS, VE, 2 * r)

    polys = []
    for item in items:
        out_rings = []
        for c, lab in item:
            if lab is not None and (lab == _ext.OFFSET_DETOUR).any():
                lab = None  # never expected: the overlay's boundary avoids detours
            if lab is None:
                lab, _ = nearest((c + np.roll(c, -1, 0)) / 2)
            chg = np.flatnonzero(lab != np.roll(lab, 1))
            if len(chg) == 0:
                if lab[0] >= 0:
                    continue
                ctr = V[-1 - lab[0]]
                out_rings.append(
                    np.array(
                        [
                            [ctr[0] + r, ctr[1], sign, ctr[0], ctr[1]],
                            [ctr[0] - r, ctr[1], sign, ctr[0], ctr[1]],
                        ]
                    )
                )
                continue
            labels = lab[chg].tolist()
            near = c[chg]
            # two moved edges that meet at a convex vertex meet through its arc (a
            # one-corner arc polygon has no segment of its own to carry the label)
            la = np.array(labels)
            lp = np.roll(la, 1)
            # in the rings' own order, edge e0 comes before e1 (a shrink runs backwards)
            e0, e1 = (lp, la) if sign > 0 else (la, lp)
            e0c, e1c = np.maximum(e0, 0), np.maximum(e1, 0)
            adj = np.flatnonzero((la >= 0) & (lp >= 0) & (VE[e0c] == VS[e1c]))
            if len(adj):
                turn = orient_array(A0[e0c[adj]], A1[e0c[adj]], A1[e1c[adj]])
                for q in adj[turn > 0][::-1]:
                    labels.insert(int(q), int(-1 - VS[e1c[q]]))
                    near = np.insert(near, q, near[q], axis=0)
            J = _junctions(np.array(labels), near, MA0, MA1, U, V, VS, VE, r, sign)
            for _ in range(repairs):
                # a piece whose exact extent is negative (a moved edge run backwards, an
                # arc beyond its vertex's normals) is not on the true boundary: the trace
                # was too coarse to see its neighbours meet first; drop it
                la = np.array(labels)
                if len(la) > 2:
                    ext = extents(la, J)
                    worst = int(np.argmin(ext))
                    if ext[worst] < 0:
                        del labels[worst]
                        near = np.delete(near, worst, axis=0)
                        J = _junctions(np.array(labels), near, MA0, MA1, U, V, VS, VE, r, sign)
                        continue
                # a junction nearer than r to the polygon is not on the true boundary: a
                # piece too short for the trace lies between; insert the nearest feature
                f, dist = nearest(J)
                bad = np.flatnonzero(dist < r - slack)
                changed = False
                for q in bad[::-1]:
                    if f[q] in (labels[q - 1], labels[q]):
                        continue
                    labels.insert(int(q), int(f[q]))
                    near = np.insert(near, q, J[q], axis=0)
                    changed = True
                if not changed:
                    break
                J = _junctions(np.array(labels), near, MA0, MA1, U, V, VS, VE, r, sign)
            # verify: every junction on the true boundary, every piece of positive extent
            _, dist = nearest(J)
            ext = extents(np.array(labels), J, strict=True)
            if (np.abs(dist - r) > slack).any() or (ext < 0).any():
                verified[0] = False
            g = len(labels)
            rows = np.empty((g, 5))
            rows[:, :2] = J
            rows[:, 2] = 0.0
            rows[:, 3:] = np.nan
            lab_arr = np.array(labels)
            arc = np.flatnonzero(lab_arr < 0)
            if len(arc):
                ctr = V[-1 - lab_arr[arc]]
                s0 = J[arc]
                s1 = J[(arc + 1) % g]
                a0 = np.arctan2(s0[:, 1] - ctr[:, 1], s0[:, 0] - ctr[:, 0])
                a1 = np.arctan2(s1[:, 1] - ctr[:, 1], s1[:, 0] - ctr[:, 0])
                if sign > 0:
                    sw = np.mod(a1 - a0, 2 * math.pi)
                else:
                    sw = -np.mod(a0 - a1, 2 * math.pi)
                real = (r * (1 - np.cos(sw / 2)) > tiny) & ~(s0 == s1).all(axis=1)
                arc, ctr, sw = arc[real], ctr[real], sw[real]
                rows[arc, 2] = np.tan(sw / 4)
                rows[arc, 3:] = ctr
            # drop repeated points (a zero-length piece)
            keep = ~((rows[:, :2] == np.roll(rows[:, :2], -1, 0)).all(axis=1))
            if keep.sum() >= 2:
                rows = rows[keep]
                first = np.lexsort((rows[:, 0], rows[:, 1]))[0]  # bottom-most, then left-most
                out_rings.append(np.roll(rows, -first, 0))
        if out_rings:
            polys.append(out_rings)
    return polys, verified[0]


@np.errstate(over="ignore", invalid="ignore")  # an overflow is reported, not warned about
def offset_arcs(polygon: Any, distance: float) -> OffsetArcs:
    """The exact boundary of a polygon grown (or shrunk) by a disk: segments and arcs.

    Parameters
    ----------
    polygon : (n, 2) array_like, shapely Polygon or MultiPolygon
        As for :func:`offset` (one polygon, not a container).
    distance : float
        Positive grows, negative shrinks, by ``r = |distance|``.

    Returns
    -------
    OffsetArcs
        Rings of moved edges and arcs of radius ``r`` centred at the polygon's vertices
        (convex ones for a grow, reflex ones for a shrink), with SVG and DXF output.
        Each junction is computed from the two pieces that meet there (the tangent point,
        or the crossing of two lines / a line and a circle / two circles) in float64; an
        arc too flat to tell from its chord in float64 is written as a segment
        (:data:`ARC_STRAIGHT_ULPS`).

    Raises
    ------
    GeometryError
        As for :func:`offset`; also ``distance == 0``.

    Notes
    -----
    Which pieces bound the offset, and in which order, is read from the certified outer
    polygon approximation at ``1e-2 · r`` computed by the core: each of its edges lies on
    a moved edge or an arc polygon of one feature, which the exact overlay reports. The
    junctions are then computed from the pieces in float64 and verified to
    :data:`VERIFY_RESOLUTION` (refined at ``1e-4 · r`` and ``1e-6 · r`` when they do not
    verify). An arc shorter than that approximation resolves, at a crossing, is not seen
    (its end points differ from the crossing by less than ``1e-2 · r``).

    Examples
    --------
    >>> import minkowski2d as mk
    >>> a = mk.offset_arcs([(0, 0), (4, 0), (4, 4), (0, 4)], -1)
    >>> a.polygons[0][0][:, :3].tolist()
    [[1.0, 1.0, 0.0], [3.0, 1.0, 0.0], [3.0, 3.0, 0.0], [1.0, 3.0, 0.0]]
    >>> mk.offset_arcs([(0, 0), (4, 0), (4, 4), (0, 4)], 1).svg_path()[:37]
    'M 0 -1 L 4 -1 A 1 1 0 0 1 5 0 L 5 4 A'
    """
    d = _finite_float(distance, "distance")
    if d == 0:
        raise GeometryError(
            "distance: must not be zero for offset_arcs",
            argument="distance",
            hint="give a positive (grow) or negative (shrink) distance",
        )
    inp = _read(polygon, "polygon")
    _check_underflow(max(float(np.abs(inp.xy).max()) if len(inp.xy) else 0.0, abs(d)))
    if len(inp.ring_off) == 2 and inp.ring_off[1] == 1:
        if d < 0:
            return OffsetArcs([], d, polygon)
        cx, cy = (float(v) for v in inp.xy[0])
        r = abs(d)
        ring = np.array([[cx + r, cy, 1.0, cx, cy], [cx - r, cy, 1.0, cx, cy]])
        return OffsetArcs([[ring]], d, polygon)
    from ._core import _ext

    best = None
    ok = plausible = False
    for rel in _TRACE_TOLERANCES:
        res = _run([inp], d, rel * abs(d), "outer", "round", 2.0,
                   _distance_error(distance, d), labels=True)  # fmt: skip
        xy, ro, po, _go, info, extra = res
        status, code, least = int(info[0, 0]), int(info[0, 1]), float(info[0, 2])
        if code == _ext.OFFSET_TOLERANCE and best is not None:
            break  # finer than float64 allows at this magnitude: keep the best so far
        _raise_for(code, status, least, distance, rel * abs(d))
        if len(po) == 1:
            return OffsetArcs([], d, polygon)
        lab, uxy, uoff, e0 = extra
        r = math.ldexp(abs(d), -e0)
        rings = [uxy[uoff[k] : uoff[k + 1]] for k in range(len(uoff) - 1)]
        # the traced outer polygon (scaled by 2**-e0): rings with the label of each edge
        items = [
            [(xy[ro[k] : ro[k + 1] - 1], lab[ro[k] : ro[k + 1] - 1]) for k in range(a, b)]
            for a, b in zip(po[:-1].tolist(), po[1:].tolist())
        ]
        seg = xy[1:] - xy[:-1]
        closing = np.zeros(len(xy) - 1, bool)
        closing[ro[1:-1] - 1] = True  # no segment from one ring's end to the next's start
        seg = seg[~closing]
        length = float(np.hypot(seg[:, 0], seg[:, 1]).sum())
        x0, y0 = xy[:-1, 0][~closing], xy[:-1, 1][~closing]
        x1, y1 = xy[1:, 0][~closing], xy[1:, 1][~closing]
        reg_area = 0.5 * float((x0 * y1 - x1 * y0).sum())
        parts, holes = len(po) - 1, (len(ro) - 1) - (len(po) - 1)
        # the exact set lies inside the traced outer polygon, within a band of width
        # rel·r along its boundary, and it has the traced polygon's topology
        slack = max(VERIFY_RESOLUTION * r, math.ldexp(least, -e0))
        band = length * rel * r
        slack_a = slack * length
        sign = 1.0 if d > 0 else -1.0
        for repairs in (0, _MAX_REPAIRS):
            polys, ok = _trace(items, rings, r, sign, slack, repairs)
            area = OffsetArcs(polys, r).area
            plausible = (
                len(polys) == parts
                and sum(len(p) - 1 for p in polys) == holes
                and reg_area - band - slack_a <= area <= reg_area + slack_a
            )
            if plausible and best is None:
                best = (polys, e0)
            if ok and plausible:
                break
        if ok and plausible:
            best = (polys, e0)
            break
    verified = bool(ok and plausible)
    if best is not None:
        polys, e0 = best
    for p in polys:
        for ring in p:
            ring[:, [0, 1, 3, 4]] = np.ldexp(ring[:, [0, 1, 3, 4]], e0)
    out = OffsetArcs(polys, d, polygon, verified)
    if not all(np.isfinite(ring[:, :3]).all() for ring in out.rings):
        raise OverflowGeometryError(
            "result: the offset does not fit in float64 (a coordinate is infinite)",
            argument="result",
            hint="scale the input down (or offset by a smaller distance)",
        )
    return out
