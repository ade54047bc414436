"""Offsetting to a polygon with a one-sided, guaranteed error (:func:`offset`): the input
read, one compiled call per polygon or batch, its status codes as errors."""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any, NamedTuple

import numpy as np

from .._engine import core
from .._engine import options as _options
from .._engine.arcs import DEFAULT_RELATIVE_TOLERANCE
from .._engine.containers import is_many
from .._engine.polygon import polygon_arrays
from .._engine.reader import PARTS, read
from .._engine.status import status_error
from ..errors import (
    GeometryError,
    OverflowGeometryError,
    ShapeError,
)

#: The default ``tolerance`` of :func:`offset`, relative to the radius: ``1e-3 · |r|``
#: (raised to the least tolerance float64 can guarantee at the input's magnitude when
#: that is larger).
DEFAULT_TOLERANCE = DEFAULT_RELATIVE_TOLERANCE

APPROX = ("outer", "inner")
JOINS = ("round", "miter", "square")
#: The default ``miter_limit`` of :func:`offset` (a multiple of ``|r|``).
MITER_LIMIT = 2.0
_JOIN_CODE = core.OFFSET_JOINS


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


def _finite_float(v: Any, name: str) -> float:
    return _options.real(v, name)


_HINT = "repair it: the boundary must not cross itself, holes must lie inside"
_NONFINITE_HINT = "remove NaN and inf"


#: constant arrays of the single-polygon call
_ZERO1 = np.zeros(1, np.int64)
_ZEROF1 = np.zeros(1, np.float64)
_GEOM1 = np.array([0, 1], np.int64)


def _read(obj: Any, name: str) -> _Input:
    """The rings of a polygon through the one reader (any orientation: the core orients
    them exactly; exact values rounded to float64 once, the rounding bounded), or the
    hull of a point, a segment or collinear points; the parts of a collection, or of a
    MultiPolygon whose valid parts overlap, are united by the core first."""
    got = read(
        obj, name, accept="polygon", numbers="round", validate=PARTS, degenerate="hull",
        hint=_HINT, nonfinite_hint=_NONFINITE_HINT,
    )  # fmt: skip
    if got.flat is not None:
        return _one_ring(got.flat, got.delta)
    xy, ro, po = got.rings
    if len(ro) == 2:
        return _Input(np.ascontiguousarray(xy, np.float64), ro, _ZERO1, got.overlap, got.delta)
    hole = np.ones(len(ro) - 1, np.int64)
    hole[po[:-1]] = 0
    return _Input(xy, ro, hole, got.overlap, got.delta)


def _one_ring(data: np.ndarray, delta: float) -> _Input:
    return _Input(
        np.ascontiguousarray(data, np.float64),
        np.array([0, len(data)], np.int64),
        _ZERO1,
        False,
        delta,
    )


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
    threads: int = 1,
) -> tuple:
    """One compiled call for all ``inputs``: the raw result of ``core.offset_rings``."""
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
    return core.offset_rings(
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
        threads,
    )


#: shapely type ids the core reads and checks itself (offset_polygons)
_POLYGONAL_IDS = (3, 6)
#: a float64 ring as an (n, 2) ndarray: read as it is
_F64 = np.dtype(np.float64)


def _fast(obj: Any) -> bool:
    """Is ``obj`` a shapely Polygon or MultiPolygon (read and checked by the core)?"""
    import shapely

    return type(obj) in (shapely.Polygon, shapely.MultiPolygon) or (
        isinstance(obj, shapely.Geometry) and shapely.lib.get_type_id(obj) in _POLYGONAL_IDS
    )


def _polygon_type() -> type:
    import shapely

    return shapely.Polygon


def _one_polygon(
    polygon: Any, d: float, tol: float | None, approx: str, join: str, lim: float
) -> Any:
    """The offset of a shapely Polygon by the core's entry for one ring (its coordinates
    read by one GEOS call, the result built by one ``from_ragged_array``), or None: a
    polygon with holes, an invalid one, an error (the general path reads, offsets and
    reports it)."""
    import shapely

    got = core.offset_one(
        shapely.get_coordinates(polygon), d, math.nan if tol is None else tol,
        DEFAULT_TOLERANCE, approx == "outer", _JOIN_CODE[join], lim,
    )  # fmt: skip
    if got is None:
        return None
    polys = shapely.from_ragged_array(shapely.GeometryType.POLYGON, got[0], got[1:])
    if len(polys) == 1:
        return polys[0]
    return shapely.multipolygons(polys) if len(polys) else shapely.Polygon()


def _ring_arrays(a: np.ndarray) -> tuple:
    """A float64 (n, 2) ring as the arrays of offset_polygons."""
    xy = np.ascontiguousarray(a)
    return xy, np.array([0, len(xy)], np.int64), _GEOM1, _GEOM1


def _run_polygons(
    arrays: tuple,
    d: Any,
    tol: Any,
    approx: str,
    join: str,
    lim: float,
    delta: float,
    threads: int,
) -> tuple:
    """One compiled call reading, checking and offsetting shapely polygons (the arrays of
    polygon_arrays); a geometry the core does not take has code OFFSET_INPUT. ``d`` and
    ``tol`` are one value for all or one per geometry (``tol`` NaN or None: the
    default)."""
    xy, ro, po, go = arrays
    g = len(go) - 1
    return core.offset_polygons(
        xy, ro, po, go, _per_geometry(d, g), _per_geometry(math.nan if tol is None else tol, g),
        DEFAULT_TOLERANCE, approx == "outer", _JOIN_CODE[join], lim, delta, threads,
    )  # fmt: skip


def _per_geometry(v: Any, g: int) -> np.ndarray:
    """``v`` (one float, or one per geometry) as g float64 values."""
    if type(v) is float or np.ndim(v) == 0:  # (type first: np.ndim costs a microsecond)
        return np.array((v,), np.float64) if g == 1 else np.full(g, v, np.float64)
    return np.ascontiguousarray(v, np.float64)


def _raise_for(code: int, status: int, least: float, distance: Any, tolerance: Any) -> None:
    """Turn the core's verdict on one polygon into the documented error."""
    if code == core.OFFSET_TOLERANCE:
        raise GeometryError(
            f"tolerance: {tolerance!r} is below what float64 can guarantee at these "
            f"magnitudes (about {least:.3g})",
            argument="tolerance",
            hint="raise the tolerance, or move the polygon nearer to the origin",
        )
    if code == core.OFFSET_DISTANCE:
        raise GeometryError(
            f"distance: {distance!r} is too small for float64 at these magnitudes (the "
            f"least tolerance it can guarantee, about {least:.3g}, is more than half of it)",
            argument="distance",
            hint="move the polygon nearer to the origin, or offset by more",
        )
    if code == core.OFFSET_UNDERFLOW:
        raise OverflowGeometryError(
            "result: the offset underflows float64 (magnitude below 2**-1020: rounding to "
            "float64 may exceed the guaranteed tolerance)",
            argument="result",
            hint="scale the input up by a power of two, and the result down",
        )
    if status == core.Status.RESOURCE:
        raise status_error(
            status,
            name="polygon",
            what="the offset",
            limits="its overlay's work limit allows",
            hint="offset fewer vertices at once, or with a coarser tolerance",
        )
    if code == core.OFFSET_OVERFLOWS or status == core.Status.OVERFLOW:
        raise status_error(
            core.Status.OVERFLOW,
            name="result",
            what="the offset",
            hint="scale the input down (or offset by a smaller distance)",
        )
    if status != core.Status.OK:
        raise status_error(status, name="polygon", what="the offset")
    if code != core.OFFSET_FINE:
        raise GeometryError(
            f"polygon: the offset could not be certified (code {code})",
            argument="polygon",
            hint="this is a bug: please report the input",
        )


def _raise_all(
    info: np.ndarray, distance: Any, tolerance: Any, members: np.ndarray | None = None
) -> None:
    """The error of the first polygonal set whose offset failed (in order; ``distance``
    and ``tolerance`` as given, or one per row). ``members``: the rows' positions in a
    batch, named in the error (``polygon[k]``)."""
    if (info[0, 0] or info[0, 1]) if len(info) == 1 else info[:, :2].any():
        for k, (st, cd, least) in enumerate(info[:, :3].tolist()):
            dk = float(distance[k]) if np.ndim(distance) else distance
            tk = tolerance[k] if np.ndim(tolerance) else tolerance
            tk = None if tk is None or tk != tk else (float(tk) if np.ndim(tolerance) else tk)
            try:
                _raise_for(int(cd), int(st), least, dk, tk)
            except GeometryError as exc:
                if members is None:
                    raise
                exc.argument = None  # kept in the message: polygon[k]: tolerance: ...
                raise exc.renamed(f"polygon[{int(members[k])}]") from None


def _shapes(res: tuple, distance: Any, tolerance: Any) -> np.ndarray:
    """Shapely results, one per polygonal set of the call (errors raised in order)."""
    import shapely

    xy, ro, po, go, info, _extra = res
    _raise_all(info, distance, tolerance)
    polys = shapely.from_ragged_array(shapely.GeometryType.POLYGON, xy, (ro, po))
    if len(go) == 2 and len(po) == 2:  # one polygon of one ring or more
        return polys
    counts = np.diff(go)
    one = counts == 1
    if one.all():  # one polygon per set
        return polys
    out = np.empty(len(go) - 1, dtype=object)
    out[one] = polys[go[:-1][one]]
    out[counts == 0] = shapely.Polygon()
    many = np.flatnonzero(counts > 1)
    if len(many):
        members = np.concatenate([polys[go[g] : go[g + 1]] for g in many])
        which = np.repeat(np.arange(len(many)), counts[many])
        out[many] = shapely.multipolygons(members, indices=which)
    return out


# --------------------------------------------------------------------------------------
# the offset


def _list_result(res: list) -> np.ndarray:
    out = np.empty(len(res), dtype=object)
    out[:] = res
    return out


def _batch(polys: list, fn_args: tuple, threads: int = 1) -> list:
    """Offsets of a list of polygons (None stays None): shapely (multi)polygons in one
    compiled call that reads and checks them; the rest, and what that call leaves to the
    reader, through the reader (one call per distinct distance and tolerance). Reading
    errors first, then the offsets' own, each in member order (as if every member went
    through the reader). ``d``, ``tol`` (and ``distance``, ``tolerance``) are one value
    for all or one per member."""
    d, tol, approx, join, lim, distance, tolerance = fn_args
    per = np.ndim(d) or np.ndim(tol)
    idx = [k for k, g in enumerate(polys) if g is not None]
    fast = np.array([k for k in idx if _fast(polys[k])], np.int64)
    info = np.zeros((len(polys), 5))
    res_fast: Any = None
    if len(fast):
        geoms = np.empty(len(fast), dtype=object)
        geoms[:] = [polys[k] for k in fast]
        res_fast = _run_polygons(
            polygon_arrays(geoms), _pick(d, fast), _pick(tol, fast), approx, join, lim,
            _distance_error(distance, d) if not per else 0.0, threads,
        )  # fmt: skip
        took = res_fast[4][:, 1] != core.OFFSET_INPUT
        info[fast[took]] = res_fast[4][took]
        res_fast, fast = _part(res_fast, took), fast[took]
    slow = sorted(set(idx) - set(fast.tolist()))
    inputs = [_read(polys[k], "polygon") for k in slow]  # reading errors, in order
    groups: dict = {}
    for k, inp in zip(slow, inputs):
        tk = _pick(tol, k)
        key = (float(_pick(d, k)), None if tk is None or tk != tk else float(tk)) if per else None
        groups.setdefault(key, []).append((k, inp))
    res_slow = []
    for key, members in groups.items():
        dk, tk = key if per else (d, tol)
        res = _run([inp for _, inp in members], dk, tk, approx, join, lim,
                   _distance_error(distance, d) if not per else 0.0, threads=threads)  # fmt: skip
        info[[k for k, _ in members]] = res[4]
        res_slow.append(([k for k, _ in members], res))
    _raise_all(info, distance, tolerance, np.arange(len(polys)))  # the offsets' errors
    out: list = [None] * len(polys)
    for ks, res in [(fast.tolist(), res_fast)] + res_slow:
        if ks and res is not None:
            for k, g in zip(ks, _shapes(res, distance, tolerance)):
                out[k] = g
    return out


def _pick(v: Any, k: Any) -> Any:
    """``v[k]`` of a per-member array, or ``v`` itself (one value for all)."""
    return v[k] if np.ndim(v) else v


def _part(res: tuple, keep: np.ndarray) -> tuple:
    """The results of the geometries ``keep`` selects (a boolean mask over them) with
    their info rows: those left to the reader have no polygons."""
    xy, ro, po, go, info, extra = res
    if keep.all():
        return res
    counts = np.diff(go)[keep]
    return xy, ro, po, np.r_[0, np.cumsum(counts)], info[keep], extra


def _all_polygons(polygon: Any) -> np.ndarray | None:
    """The members of a list, tuple or 1-d object array when every one is a non-empty
    shapely Polygon or MultiPolygon (as an object array), else None."""
    import shapely

    if type(polygon) in (list, tuple):
        arr = np.empty(len(polygon), dtype=object)
        arr[:] = polygon
    elif type(polygon) is np.ndarray and polygon.dtype == object and polygon.ndim == 1:
        arr = polygon
    else:
        return None
    if not len(arr) or not shapely.is_geometry(arr).all():
        return None
    ids = shapely.get_type_id(arr)
    if not ((ids == 3) | (ids == 6)).all() or shapely.is_empty(arr).any():
        return None
    return arr


def _map(polygon: Any, fn_args: tuple, threads: int = 1, arr: Any = False) -> Any:
    """Offset each polygon of a container (same kind out; ``arr``: its _all_polygons, when
    known)."""
    from .._engine.containers import apply, boxed

    if arr is False:
        arr = _all_polygons(polygon)
    if arr is not None:  # shapely polygons only: the shortest way, one compiled call
        d, tol, approx, join, lim, distance, tolerance = fn_args
        per = np.ndim(d) or np.ndim(tol)
        got = _run_polygons(polygon_arrays(arr), d, tol, approx, join, lim,
                            0.0 if per else _distance_error(distance, d), threads)  # fmt: skip
        if not (got[4][:, 1] == core.OFFSET_INPUT).any():
            _raise_all(got[4], distance, tolerance, np.arange(len(arr)))
            out = _shapes(got, distance, tolerance)
            if type(polygon) is list:
                return out.tolist()
            return tuple(out.tolist()) if type(polygon) is tuple else out
    if boxed(polygon):
        # GeoSeries / GeometryArray / object arrays: the shared container rules
        return apply(
            lambda ps: _list_result(_batch(list(ps), fn_args, threads)),
            polygon,
            convex=False,
            names=("polygon",),
        )
    # lists and tuples of polygons (containers went through _engine.containers above)
    res = _batch(list(polygon), fn_args, threads)
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
    miter_limit: float = MITER_LIMIT,
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
    if not is_many(polygon, empty=False):
        # one polygon: the shortest way through (read and checked by the core itself when
        # shapely or a float64 ring, else by the reader)
        extra = _distance_error(distance, d)
        if extra == 0 and type(polygon) is _polygon_type():
            got = _one_polygon(polygon, d, tol, approx, join, lim)
            if got is not None:
                return got
        if _fast(polygon):
            one: Any = [polygon]  # a list: polygon_arrays reads its one member directly
            arrays = polygon_arrays(one)
        elif type(polygon) is np.ndarray and polygon.dtype == _F64 and polygon.shape[1:] == (2,):
            arrays = _ring_arrays(polygon)
        else:
            arrays = None
        if arrays is not None:
            res = _run_polygons(arrays, d, tol, approx, join, lim, extra, 1)
            if res[4][0, 1] != core.OFFSET_INPUT:
                return _shapes(res, distance, tolerance)[0]
        res = _run([_read(polygon, "polygon")], d, tol, approx, join, lim, extra)
        return _shapes(res, distance, tolerance)[0]
    return _map(polygon, (d, tol, approx, join, lim, distance, tolerance))


def offset_many(
    polygons: Any,
    distance: Any,
    *,
    tolerance: Any = None,
    approx: str = "outer",
    join: str = "round",
    miter_limit: float = MITER_LIMIT,
    threads: int = 1,
) -> Any:
    """Offset every polygon of a batch: :func:`offset` member by member, in one compiled
    call.

    Parameters
    ----------
    polygons : list, tuple, numpy object array, GeometryArray or GeoSeries
        Polygons as :func:`offset` takes them (``None`` stays ``None``; in a GeoSeries,
        GeometryArray or object array an empty member gives an empty Polygon). Shapely
        polygons and multipolygons are read and checked by the compiled core itself,
        with the GIL released; other members go through the reader first.
    distance, tolerance : float or array_like of floats
        As for :func:`offset`: one value for every member, or one per member (in the
        container's order; ``tolerance`` None: the default for each).
    approx, join, miter_limit
        As for :func:`offset`.
    threads : int, default 1
        Worker threads of the compiled call (the GIL is released).

    Returns
    -------
    the container's kind
        A list, tuple or object array of shapely results, or a GeometryArray or GeoSeries
        (index and CRS kept), each member equal to ``offset(member, distance, ...)``.

    Raises
    ------
    GeometryError
        As :func:`offset`: the first bad member (reading errors first, then the offsets'
        own), its position or index label in the message.

    Examples
    --------
    >>> import minkowski2d as mk, shapely
    >>> parts = [shapely.box(0, 0, 2, 1), None, shapely.box(0, 0, 1, 1)]
    >>> out = mk.offset_many(parts, 0.5, tolerance=1e-3, threads=2)
    >>> out[1] is None, out[0].equals(mk.offset(parts[0], 0.5, tolerance=1e-3))
    (True, True)
    """
    threads = _options.threads(threads)
    if not is_many(polygons, empty=True):
        raise ShapeError(
            "polygons: offset_many takes a list, tuple, array or GeoSeries of polygons",
            argument="polygons",
            hint="mk.offset offsets one polygon",
        )
    if np.ndim(distance) == 0 and np.ndim(tolerance) == 0:
        d, tol, lim = _check_options(distance, tolerance, approx, join, miter_limit)
        return _map(polygons, (d, tol, approx, join, lim, distance, tolerance), threads)
    # one distance (and tolerance) per member
    n = len(polygons)
    ds = _member_values(distance, n, "distance")
    ts: Any = _member_values(tolerance, n, "tolerance") if np.ndim(tolerance) else tolerance
    _, _, lim = _check_options(1.0, None if np.ndim(ts) else ts, approx, join, miter_limit)
    from .._engine.containers import boxed, unbox

    arr = _all_polygons(polygons)
    box = unbox(polygons) if arr is None and boxed(polygons) else None
    if box is not None:  # the members apply() computes: not None, not empty
        import shapely

        geoms = box.geoms
        valid = ~np.equal(geoms, None) & ~shapely.is_empty(geoms)  # type: ignore[call-overload]
        ds = ds[valid]
        ts = ts[valid] if np.ndim(ts) else ts
    return _map(polygons, (ds, ts, approx, join, lim, ds, ts), threads, arr)


def _member_values(value: Any, n: int, name: str) -> np.ndarray:
    """One float64 value per member (a distance, or a positive tolerance), each exactly
    the value given."""
    if isinstance(value, np.ndarray) and value.dtype == np.float64 and value.shape == (n,):
        ok = np.isfinite(value).all() and (name != "tolerance" or (value > 0).all())
        if ok:
            return value.copy()
    vals = list(value) if not isinstance(value, np.ndarray) else value.tolist()
    if len(vals) != n:
        raise ShapeError(
            f"{name}: {len(vals)} values for {n} polygons", argument=name,
            hint=f"give one {name} for all, or one per polygon",
        )  # fmt: skip
    out = np.empty(n, np.float64)
    for k, v in enumerate(vals):
        f = _finite_float(v, name)
        if name == "tolerance" and f <= 0:
            raise GeometryError(f"tolerance: must be positive, got {v!r}", argument=name)
        if not isinstance(v, (float, np.floating)) and Fraction(f) != Fraction(v):
            raise GeometryError(
                f"{name}: {v!r} is not a float64 value", argument=name,
                hint="per-polygon values must be floats",
            )  # fmt: skip
        out[k] = f
    return out


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
