"""Exact polygon booleans and line clipping: union, intersection, difference, symmetric
difference, the union of many polygons, and polylines clipped by polygons.

One pipeline for all of them, in the compiled core (``_core/boolean.hpp`` on the exact
overlay): every segment noded against every other (exact crossings), each piece given the
winding numbers of its two sides by a plane sweep, the pieces kept where the rule changes
across them, rings traced and holes assigned. Every decision is an exact sign; every
vertex of the result is the correctly rounded exact vertex (an input vertex bit for bit, a
crossing rounded once). GEOS decides nothing; shapely only carries geometries in and out.

Operands are polygons: a shapely Polygon or MultiPolygon (a GeometryCollection of them),
an (n, 2) array-like ring, a list of such (their union), or a
:class:`~minkowski2d.Ragged` of rings. A GeoSeries, GeometryArray or object array of
geometries is computed member by member (against a single operand or pairwise against a
second container), in one compiled call for the whole batch.

Examples
--------
>>> import minkowski2d as mk
>>> a = [(0, 0), (4, 0), (4, 4), (0, 4)]
>>> b = [(2, 2), (6, 2), (6, 6), (2, 6)]
>>> mk.union(a, b).area, mk.intersection(a, b).area, mk.difference(a, b).area
(28.0, 4.0, 12.0)
>>> mk.symmetric_difference(a, b).geom_type
'MultiPolygon'
"""

from __future__ import annotations

from typing import Any, cast

import numpy as np

from ._engine import core
from ._engine import options as _options
from ._engine.coerce import is_shapely
from ._engine.containers import unbox
from ._engine.overlay import check as _check_overlay
from ._engine.overlay import closed_geometries
from ._engine.polygon import Rings, polygon_arrays, problem_error
from ._engine.reader import read
from .batch import Ragged
from .errors import ShapeError

__all__ = [
    "union",
    "intersection",
    "difference",
    "symmetric_difference",
    "union_all",
    "clip_lines",
    "FILL_RULES",
]

#: The fill rules that resolve self-intersecting input (as Clipper and iOverlay do): a
#: point is inside an operand when the winding number of its rings, each counted as
#: given (counter-clockwise +1), is nonzero, odd, positive or negative.
FILL_RULES: tuple[str, ...] = tuple(core.FILL_RULES)

_NO_LIMIT = core.NO_LIMIT  # a work limit that never stops a run
_HINT = (
    "repair it (shapely.make_valid) or pass fill_rule='nonzero' or 'evenodd' to resolve "
    "self-intersecting rings by a fill rule"
)
_POLYGONAL = ("Polygon", "MultiPolygon")


# --------------------------------------------------------------------------------------
# reading operands


def _polygonal(obj: Any, name: str) -> Any:
    """One operand as a shapely Polygon or MultiPolygon (possibly empty): the one reader,
    coordinates exactly float64, a flat ring kept (the core gives it no area)."""
    if is_shapely(obj) and obj.geom_type in _POLYGONAL:
        return obj
    got = read(obj, name, accept="polygons", numbers="float64", degenerate="keep")
    return got.geometry()


def _paired(
    box: Any, ga: Any, gb: Any, read_a: Any, read_b: Any, names: tuple[str, str]
) -> tuple[np.ndarray, np.ndarray, list | None]:
    """The operands of a pairwise call as two equal-length object arrays and the pairs'
    labels: two single operands (no container: one pair, no labels), or containers
    paired member by member, a single operand repeated against a container."""
    if box is None:
        return np.array([read_a()], dtype=object), np.array([read_b()], dtype=object), None
    n = len(box.geoms)
    if ga is None:
        ga = np.full(n, read_a(), dtype=object)
    if gb is None:
        gb = np.full(n, read_b(), dtype=object)
    if len(ga) != len(gb):
        raise ShapeError(
            f"{names[0]} has {len(ga)} members but {names[1]} has {len(gb)}; pairs need "
            "equal counts",
            argument=names[1],
        )
    return ga, gb, [box.label(k) for k in range(n)]


class _Arrays:
    """Polygons of T tasks as flat arrays: xy (N, 2), ring offsets, polygon offsets, task
    offsets (T + 1) into the polygons (empty polygons dropped)."""

    __slots__ = ("xy", "ro", "po", "to")

    def __init__(self, geoms: np.ndarray | None = None) -> None:
        if geoms is not None:
            self.xy, self.ro, self.po, self.to = polygon_arrays(geoms)

    def tasks(self, first: int, count: int) -> _Arrays:
        """Tasks [first, first + count) alone (the same polygon arrays): one operand of
        operands read together."""
        part = _Arrays()
        part.xy, part.ro, part.po = self.xy, self.ro, self.po
        part.to = self.to[first : first + count + 1]
        return part

    def rings(self, t: int) -> Rings:
        """Task t's polygons as :class:`Rings` (for naming a ring in an error)."""
        p0, p1 = int(self.to[t]), int(self.to[t + 1])
        r0, r1 = int(self.po[p0]), int(self.po[p1])
        v0 = int(self.ro[r0])
        return Rings(self.xy, self.ro[r0 : r1 + 1] - v0, self.po[p0 : p1 + 1] - r0)


def _fill(fill_rule: Any) -> tuple[int, bool]:
    """(the core's fill code, validate): None validates and reads w >= 1."""
    if fill_rule is None:
        return core.FILL_RULES["positive"], True
    _options.choice(fill_rule, "fill_rule", FILL_RULES + (None,))
    return core.FILL_RULES[fill_rule], False


def _raise(info: np.ndarray, arrays: tuple, names: tuple, labels: Any = None) -> None:
    """The error of the first failed task (info rows: status, operand, reason, ring,
    vertex; operand -1: the overlay itself)."""
    bad = np.flatnonzero(info[:, 0] != core.Status.OK)
    if not len(bad):
        return
    t = int(bad[0])
    status, operand, reason, ring, vertex = (int(v) for v in info[t])
    k = max(operand, 0)
    name = names[k] if labels is None else f"{names[k]}[{labels[t]}]"
    if status in (core.Status.NONFINITE, core.Status.INVALID_POLYGON):
        raise problem_error(
            status, reason, ring, vertex, arrays[k].rings(t), name, _HINT,
            nonfinite_hint="drop or repair the vertex",
        )  # fmt: skip
    _check_overlay(status, name)


def _shapes(xy: np.ndarray, ro: np.ndarray, po: np.ndarray, to: np.ndarray) -> np.ndarray:
    """The core's closed rings as shapely geometries, one per task."""
    return closed_geometries(xy, ro, po, to)


# --------------------------------------------------------------------------------------
# the operations


def _members(obj: Any, name: str) -> tuple[Any, np.ndarray | None]:
    """(box, members) of a container operand, or (None, None)."""
    box = unbox(obj)
    if box is None:
        return None, None
    import shapely

    geoms = box.geoms.copy()
    null = np.equal(geoms, None)  # type: ignore[call-overload]  # numpy's stubs take no None
    for k in np.flatnonzero(~null):
        g = geoms[k]
        if g.geom_type not in _POLYGONAL:
            geoms[k] = _polygonal(g, f"{name}[{box.label(int(k))}]")
    geoms[null] = shapely.MultiPolygon()
    return box, geoms


def _binary(op: str, a: Any, b: Any, fill_rule: Any, threads: int) -> Any:
    fill, validate = _fill(fill_rule)
    threads = _options.threads(threads)
    rule = core.OVERLAY_OPS[op] + 4 * fill
    box_a, ga = _members(a, "a")
    box_b, gb = _members(b, "b")
    box = box_a if box_a is not None else box_b
    ga, gb, labels = _paired(
        box, ga, gb, lambda: _polygonal(a, "a"), lambda: _polygonal(b, "b"), ("a", "b")
    )
    T = len(ga)
    both = _Arrays(np.concatenate([ga, gb]))  # both operands in one reading
    A, B = both.tasks(0, T), both.tasks(T, T)
    xy, ro, po, to, info = core.boolean_f(
        both.xy, both.ro, both.po, A.to, B.to, rule, validate, threads, _NO_LIMIT, _NO_LIMIT
    )
    _raise(info, (A, B), ("a", "b"), labels)
    out = _shapes(xy, ro, po, to)
    if box is None:
        return out[0]
    return _boxed(out, box, box_a, box_b)


def _boxed(out: np.ndarray, box: Any, *boxes: Any) -> Any:
    """Members that were None in either container are None again; the container's kind,
    index and CRS kept."""
    from ._engine.containers import _wrap_geoms

    for bx in boxes:
        if bx is not None:
            out[np.equal(bx.geoms, None)] = None  # type: ignore[call-overload]  # as above
    return _wrap_geoms(out, box)


_PARAMS = """
    Parameters
    ----------
    a, b : polygons
        A shapely Polygon or MultiPolygon (or a GeometryCollection of polygons), an
        (n, 2) array-like ring (any orientation), a list of them (their union), or a
        Ragged of rings. A GeoSeries, GeometryArray or object array of geometries is
        computed member by member, against the other operand or pairwise with a second
        container of the same length (``None`` members give ``None``).
    fill_rule : {None, "nonzero", "evenodd", "positive", "negative"}
        ``None`` (the default): each polygon must be valid (simple rings, holes inside
        their shell; the polygons of one operand may overlap or touch: the operand is
        their union); an invalid one raises an error naming the ring and vertex. A fill
        rule instead resolves any input, self-intersecting rings included, by the winding
        number of its rings as given (counter-clockwise +1), as Clipper and iOverlay do.
    threads : int, default 1
        Worker threads for a batch (the GIL is released).

    Returns
    -------
    shapely Polygon or MultiPolygon
        OGC-valid (rings simple, holes touching their shell at points at most; an empty
        result is an empty Polygon), or a container of them for container input. The
        vertices are the correctly rounded exact ones.

    Raises
    ------
    SelfIntersectionError
        A polygon is not valid (with ``fill_rule=None``).
    NonFiniteError, ShapeError, GeometryError
        Bad input (a coordinate not finite, a non-polygonal operand, containers of
        different lengths, integers beyond float64).
    OverflowGeometryError
        A vertex of the result beyond float64.
"""


def union(a: Any, b: Any, *, fill_rule: str | None = None, threads: int = 1) -> Any:
    """The union of two polygonal operands, exactly.
    {params}
    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.union([(0, 0), (2, 0), (2, 2), (0, 2)], [(1, 1), (3, 1), (3, 3), (1, 3)]).wkt
    'POLYGON ((0 0, 2 0, 2 1, 3 1, 3 3, 1 3, 1 2, 0 2, 0 0))'
    """
    return _binary("union", a, b, fill_rule, threads)


def intersection(a: Any, b: Any, *, fill_rule: str | None = None, threads: int = 1) -> Any:
    """The intersection of two polygonal operands (its regularized closure: where they
    only touch, nothing), exactly.
    {params}
    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.intersection([(0, 0), (3, 0), (0, 3)], [(0, 0), (2, 0), (2, 2), (0, 2)]).wkt
    'POLYGON ((0 0, 2 0, 2 1, 1 2, 0 2, 0 0))'
    """
    return _binary("intersection", a, b, fill_rule, threads)


def difference(a: Any, b: Any, *, fill_rule: str | None = None, threads: int = 1) -> Any:
    """``a`` minus ``b`` (the closure of what is in ``a`` and not in ``b``), exactly.
    {params}
    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.difference([(0, 0), (4, 0), (4, 4), (0, 4)], [(1, 1), (3, 1), (3, 3), (1, 3)]).wkt
    'POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))'
    """
    return _binary("difference", a, b, fill_rule, threads)


def symmetric_difference(a: Any, b: Any, *, fill_rule: str | None = None, threads: int = 1) -> Any:
    """What lies in exactly one of ``a`` and ``b`` (xor), exactly.
    {params}
    Examples
    --------
    >>> import minkowski2d as mk
    >>> a, b = [(0, 0), (2, 0), (2, 2), (0, 2)], [(1, 0), (3, 0), (3, 2), (1, 2)]
    >>> r = mk.symmetric_difference(a, b)
    >>> r.geom_type, r.area
    ('MultiPolygon', 4.0)
    """
    return _binary("xor", a, b, fill_rule, threads)


for _f in (union, intersection, difference, symmetric_difference):
    _f.__doc__ = (_f.__doc__ or "").replace("{params}", _PARAMS.replace("\n    ", "\n    "))


def union_all(geoms: Any, *, fill_rule: str | None = None) -> Any:
    """The union of many polygons in one exact overlay.

    Parameters
    ----------
    geoms : sequence of polygons
        A list, GeoSeries, GeometryArray or object array of shapely Polygons or
        MultiPolygons (``None`` and empty members are skipped), or anything a single
        operand of :func:`union` is.
    fill_rule : {None, "nonzero", "evenodd", "positive", "negative"}
        ``None``: every polygon must be valid; the result is where at least one polygon
        is. A fill rule resolves the rings of all members together by their winding
        number (as Clipper's union of many paths does).

    Returns
    -------
    shapely Polygon or MultiPolygon
        OGC-valid, with correctly rounded exact vertices (an empty Polygon for no area).

    Raises
    ------
    SelfIntersectionError
        A polygon is not valid (``fill_rule=None``); the error names the member, ring and
        vertex.

    Examples
    --------
    >>> import minkowski2d as mk, shapely
    >>> boxes = [shapely.box(0, 0, 2, 1), shapely.box(1, 0, 3, 1), shapely.box(5, 0, 6, 1)]
    >>> mk.union_all(boxes).wkt
    'MULTIPOLYGON (((0 0, 3 0, 3 1, 0 1, 0 0)), ((5 0, 6 0, 6 1, 5 1, 5 0)))'
    """
    import shapely

    fill, validate = _fill(fill_rule)
    box, members = _members(geoms, "geoms")
    if box is None:
        if isinstance(geoms, (list, tuple)) and not geoms:
            return shapely.Polygon()
        if isinstance(geoms, (list, tuple)) and (
            is_shapely(geoms[0]) or geoms[0] is None or np.ndim(geoms[0]) == 2
        ):
            members = np.empty(len(geoms), dtype=object)
            members[:] = [
                shapely.MultiPolygon() if g is None else _polygonal(g, f"geoms[{k}]")
                for k, g in enumerate(geoms)
            ]
        else:
            members = np.array([_polygonal(geoms, "geoms")], dtype=object)
    # every member's polygons in one task, each member named in an error
    A = _Arrays(cast(np.ndarray, members))  # built above, or by _members with a box
    per_member = A.to.copy()
    A.to = np.array([0, per_member[-1]], np.int64)
    no_b = np.array([per_member[-1], per_member[-1]], np.int64)  # no polygons
    xy, ro, po, to, info = core.boolean_f(
        A.xy, A.ro, A.po, A.to, no_b,
        core.OVERLAY_UNION + 4 * fill, validate, 1, _NO_LIMIT, _NO_LIMIT,
    )  # fmt: skip
    status = int(info[0, 0])
    if status != core.Status.OK:
        if status in (core.Status.NONFINITE, core.Status.INVALID_POLYGON):
            # the ring is counted over all members: find its member
            ring = int(info[0, 3])
            pol = int(np.searchsorted(A.po, ring, side="right")) - 1
            m = int(np.searchsorted(per_member, pol, side="right")) - 1
            r0 = int(A.po[per_member[m]])
            label = box.label(m) if box is not None else str(m)
            info = info.copy()
            info[0, 3] = ring - r0
            A.to = per_member
            tasks = np.zeros((len(per_member) - 1, 5))
            tasks[m] = info[0]
            names = [label] * len(tasks)
            _raise(tasks, (A,), ("geoms",), names)
        _check_overlay(status, "geoms")
    return _shapes(xy, ro, po, to)[0]


# --------------------------------------------------------------------------------------
# lines


def _lineal(obj: Any, name: str) -> Any:
    """One lines operand as a shapely LineString or MultiLineString."""
    import shapely

    if is_shapely(obj):
        gt = obj.geom_type
        if gt in ("LineString", "MultiLineString"):
            return obj
        if gt == "LinearRing":
            return shapely.LineString(obj.coords)
        if gt == "GeometryCollection":
            return _multiline([_lineal(p, name) for p in shapely.get_parts(obj)])
        raise ShapeError(f"{name}: a {gt} is not a line", argument=name,
                         hint="pass LineStrings or (n, 2) polylines")  # fmt: skip
    if isinstance(obj, Ragged):
        obj = obj.to_list()
    if isinstance(obj, (list, tuple)) and obj and (is_shapely(obj[0]) or np.ndim(obj[0]) == 2):
        return _multiline([_lineal(item, f"{name}[{k}]") for k, item in enumerate(obj)])
    c = read(obj, name, accept="coords", numbers="float64")  # a polygon's number policy
    return shapely.LineString(c) if len(c) >= 2 else shapely.LineString()


def _multiline(parts: list) -> Any:
    import shapely

    lines: list[Any] = []  # shapely LineStrings
    for g in parts:
        lines.extend(shapely.get_parts(g).tolist() if g.geom_type == "MultiLineString" else [g])
    lines = [g for g in lines if not g.is_empty]
    return lines[0] if len(lines) == 1 else shapely.MultiLineString(lines)


def _line_arrays(geoms: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    import shapely

    T = len(geoms)
    if T == 0 or bool(shapely.is_empty(geoms).all()):
        return np.empty((0, 2)), np.zeros(1, np.int64), np.zeros(T + 1, np.int64)
    typ, coords, offs = shapely.to_ragged_array(geoms)
    mo: np.ndarray
    if typ == shapely.GeometryType.LINESTRING:
        (lo,) = offs
        mo = np.arange(T + 1)
    else:
        lo, mo = offs
    return (np.ascontiguousarray(coords, dtype=np.float64), np.ascontiguousarray(lo, np.int64),
            np.ascontiguousarray(mo, np.int64))  # fmt: skip


def clip_lines(
    lines: Any,
    polygons: Any,
    *,
    keep: str = "inside",
    fill_rule: str | None = None,
    threads: int = 1,
) -> Any:
    """Polylines clipped by polygons, exactly.

    Parameters
    ----------
    lines : lines
        A shapely LineString, MultiLineString or LinearRing, an (n, 2) array-like
        polyline, a list of them, or a container (GeoSeries, object array) of them,
        clipped member by member.
    polygons : polygons
        The clipping region, as an operand of :func:`union` (or a container of them,
        paired with ``lines``).
    keep : {"inside", "outside"}
        ``"inside"``: the parts in the closed region (where a line runs along the
        boundary, it is kept); ``"outside"``: the parts in the open complement. The two
        together give back the lines.
    fill_rule : {None, "nonzero", "evenodd", "positive", "negative"}
        As for :func:`union`.
    threads : int, default 1
        Worker threads for a batch.

    Returns
    -------
    shapely LineString or MultiLineString
        The parts kept (a point set: where lines run over each other, that stretch comes
        out once), each following the direction of the input line, joined where two
        meet, in lexicographic order of their vertices; an empty LineString when nothing
        is kept. Points where a line only touches the region are not parts. Crossing
        vertices are the correctly rounded exact ones.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> sq = [(0, 0), (4, 0), (4, 4), (0, 4)]
    >>> mk.clip_lines([(-1, 1), (5, 1)], sq).wkt
    'LINESTRING (0 1, 4 1)'
    >>> mk.clip_lines([(-1, 1), (5, 1)], sq, keep="outside").wkt
    'MULTILINESTRING ((-1 1, 0 1), (4 1, 5 1))'
    """
    import shapely

    _options.choice(keep, "keep", ("inside", "outside"))
    fill, validate = _fill(fill_rule)
    threads = _options.threads(threads)
    box_l = unbox(lines)
    box_p, gp = _members(polygons, "polygons")
    box = box_l if box_l is not None else box_p
    gl = None
    if box_l is not None:
        gl = box_l.geoms.copy()
        null = np.equal(gl, None)  # type: ignore[call-overload]  # numpy's stubs take no None
        for k in np.flatnonzero(~null):
            gl[k] = _lineal(gl[k], f"lines[{box_l.label(int(k))}]")
        gl[null] = shapely.LineString()
    gl, gp, labels = _paired(
        box,
        gl,
        gp,
        lambda: _lineal(lines, "lines"),
        lambda: _polygonal(polygons, "polygons"),
        ("lines", "polygons"),
    )
    lxy, lo, lt = _line_arrays(gl)
    A = _Arrays(gp)
    xy, off, to, info = core.clip_lines_f(
        lxy, lo, lt, A.xy, A.ro, A.po, A.to, fill, validate, keep == "inside",
        threads, _NO_LIMIT, _NO_LIMIT,
    )  # fmt: skip
    if (info[:, 0] != core.Status.OK).any():
        t = int(np.flatnonzero(info[:, 0] != core.Status.OK)[0])
        if int(info[t, 1]) == 0:  # a line vertex that is not finite
            from ._engine.status import nonfinite

            name = "lines" if labels is None else f"lines[{labels[t]}]"
            line, vertex = int(info[t, 3]), int(info[t, 4])
            raise nonfinite(name, vertex, where=f"line {line}, vertex {vertex}")
        info = info.copy()
        info[:, 1] = 0
        _raise(info, (A,), ("polygons",), labels)
    T = len(to) - 1
    out = np.empty(T, dtype=object)
    if len(xy):
        multi = shapely.from_ragged_array(shapely.GeometryType.MULTILINESTRING, xy, (off, to))
        parts = shapely.get_num_geometries(multi)
        one = parts == 1
        out[one] = shapely.get_geometry(multi[one], 0)
        out[parts > 1] = multi[parts > 1]
        for k in np.flatnonzero(parts == 0):
            out[k] = shapely.LineString()
    else:
        out[:] = [shapely.LineString() for _ in range(T)]
    if box is None:
        return out[0]
    return _boxed(out, box, box_l, box_p)
