"""The one polygon reader: :func:`read` turns what a caller gave (an (n, 2) array-like, a
list of pairs, a shapely geometry, a list of polygons, a Ragged) into coordinates for the
compiled core, by four options. Every public function reads its polygons here; the
reading primitives (the dtype policy of :mod:`.coerce`, the shapely readings of
:mod:`.polygon`) are called from nowhere else (``tests/test_layers.py`` checks it).

Options
-------
``accept``
    ``"points"``: one point sequence (a convex polygon, a point set): an (n, 2)
    array-like, a list of pairs, or a shapely Polygon without holes, ring, line or
    point(s) read as its vertices; gives an :class:`Operand`.
    ``"polygon"``: one polygonal set: a shapely Polygon, MultiPolygon, LinearRing or
    GeometryCollection of polygons (its members may overlap: :attr:`Polygons.parts`), or
    a ring as an (n, 2) array-like; gives :class:`Polygons`.
    ``"polygons"``: as ``"polygon"``, and a list of polygons (or a Ragged) is one set, the
    union of its members (:attr:`Polygons.parts`).
    ``"many"``: a batch of point sequences (a list of them): one (N, 2) int64 or float64
    array and its offsets (N + 1), as a Ragged holds them.
    ``"coords"``: an (n, 2) float64 ndarray of the coordinates as given, by the number
    policy (a polyline, a ring kept as it is).
``numbers``
    ``"exact"``: ints, floats and Fractions at any magnitude, each on its path (the
    int64 and float64 kernels, or exact Python numbers: :class:`Operand`).
    ``"int64"``: as ``"exact"``, ints kept in int64 whenever they fit it.
    ``"core"``: int64 (``|x| < 2**62``) or float64 only (no exact Python path).
    ``"float64"``: every coordinate exactly a float64 value, else GeometryError.
    ``"fractions"``: ints must be float64 values; Fractions (and wide floats) are
    rounded to float64 once, correctly.
    ``"round"``: everything rounded to float64 once; :attr:`Polygons.delta` bounds the
    distance between the rounded rings and the exact input.
``validate``
    ``True``: check the rings exactly in the core (simple rings, holes inside, no
    crossing, the parts of a MultiPolygon disjoint; a hole touching its shell twice is
    split into its parts) and learn their orientation; the error names the ring and
    vertex, with the caller's ``hint``. ``"parts"``: the same, but the parts of a
    MultiPolygon may overlap (:attr:`Polygons.overlap`: the caller unites them).
``degenerate``
    What a flat input (a point, a segment, collinear points) becomes: ``"refuse"``
    (the validation's error), ``"hull"`` (its convex hull, :attr:`Polygons.flat`) or
    ``"keep"`` (the coordinates as given: the core gives them no area).

One fault, one error: an empty input is EmptyGeometryError, NaN or inf NonFiniteError,
an integer float64 cannot hold (under ``"float64"``/``"fractions"``) GeometryError, a
value beyond float64 OverflowGeometryError, a wrong shape ShapeError, each with one
sentence, whichever public function read it.

Examples
--------
>>> from minkowski2d._engine.reader import read
>>> read([(0, 0), (2, 0), (0, 2)], "a").path
'i'
>>> import shapely
>>> p = read(shapely.box(0, 0, 1, 1), "a", accept="polygon", numbers="float64", validate=True)
>>> p.rings.ring_offsets.tolist(), p.orientation.tolist(), p.flat
([0, 5], [1], None)
>>> read([(0, 0), (1, 1), (2, 2)], "a", accept="polygon", validate=True,
...      degenerate="hull").flat.tolist()
[[0.0, 0.0], [2.0, 2.0]]
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any, NamedTuple

import numpy as np

from ..errors import EmptyGeometryError, GeometryError, OverflowGeometryError, ShapeError
from . import core
from .coerce import FLOAT, INT, as_array, fits_float64, is_shapely, py_points, to_float
from .core import Status
from .polygon import (
    Rings,
    check_split,
    is_flat,
    polygon_arrays,
    polygon_parts,
    probe,
    rings_of,
    rings_of_array,
)
from .status import nonfinite, status_error

__all__ = ["ACCEPT", "NUMBERS", "DEGENERATE", "Operand", "Polygons", "read"]

ACCEPT = ("points", "many", "polygon", "polygons", "coords")
NUMBERS = ("exact", "int64", "core", "float64", "fractions", "round")
DEGENERATE = ("refuse", "hull", "keep")
#: ``validate="parts"``: each polygon valid, the parts of a MultiPolygon may overlap
PARTS = "parts"

INT_LIMIT = core.INT_LIMIT
_CORE_DTYPES = (np.dtype(np.int64), np.dtype(np.float64))
_ONE_POLYGON = np.array([0, 1], np.int64)


class Operand(NamedTuple):
    """One point sequence (``accept="points"``): ``data`` is a C-contiguous (n, 2)
    int64/float64 ndarray when ``path`` is ``"i"``/``"f"``, else a list of exact
    ``(x, y)`` tuples; ``kind`` is the dtype policy's kind of the input (``int``,
    ``float``, ``xfloat``, ``exact``)."""

    data: Any
    kind: str
    path: str


class Polygons:
    """One polygonal set (``accept="polygon"`` / ``"polygons"``).

    ``geom``: the caller's shapely Polygon / MultiPolygon when it gave one (else None);
    ``parts``: the members of a collection, each a :class:`Polygons`, whose union is the
    set (else None); ``rings``: the float64 rings (of ``geom`` or of the given ring; None
    for a collection); ``orientation``: +1 per ring given counter-clockwise (with
    ``validate``); ``flat``: the normalized convex hull of a flat input (with
    ``degenerate="hull"``); ``delta``: a bound on the distance between ``rings`` and the
    exact input (``numbers="round"``, else 0); ``overlap``: whether the parts may overlap
    (a collection, or with ``validate="parts"`` a MultiPolygon whose parts do), so that
    the caller unites them.
    """

    __slots__ = ("name", "geom", "parts", "orientation", "flat", "delta", "overlap", "_rings")

    def __init__(
        self, name: str, *, geom: Any = None, rings: Rings | None = None,
        parts: list[Polygons] | None = None, delta: float = 0.0,
    ) -> None:  # fmt: skip
        self.name = name
        self.geom = geom
        self.parts = parts
        self.orientation: np.ndarray | None = None
        self.flat: np.ndarray | None = None
        self.delta = delta
        self.overlap = False
        self._rings = rings

    @property
    def rings(self) -> Rings | None:
        if self._rings is None and self.geom is not None:
            self._rings = rings_of(self.geom)
        return self._rings

    @property
    def multi(self) -> bool:
        """Whether the set is several polygons (their interiors disjoint)."""
        r = self.rings
        return r is not None and len(r.polygon_offsets) > 2

    def geometry(self) -> Any:
        """The set as one shapely Polygon or MultiPolygon, as given (a flat ring kept as a
        degenerate shell; a collection as the MultiPolygon of its members' polygons)."""
        import shapely

        if self.parts is not None:
            polys: list[Any] = []
            for p in self.parts:
                g = p.geometry()
                multi = g.geom_type == "MultiPolygon"
                polys.extend(shapely.get_parts(g).tolist() if multi else [g])
            polys = [p for p in polys if not p.is_empty]
            return polys[0] if len(polys) == 1 else shapely.MultiPolygon(polys)
        if self.geom is not None:
            return self.geom
        assert self._rings is not None
        xy = self._rings.coords
        if len(xy) == 0:
            return shapely.Polygon()
        # a ring of fewer than 3 distinct points is a polygon shapely cannot build: keep its
        # coordinates as a degenerate shell (the core gives it no area)
        closed = np.vstack([xy, xy[:1]]) if len(xy) < 4 or (xy[0] != xy[-1]).any() else xy
        while len(closed) < 4:
            closed = np.vstack([closed, closed[-1:]])
        return shapely.Polygon(closed)


# --------------------------------------------------------------------------------------
# the reader


def read(
    obj: Any,
    name: str,
    *,
    accept: str = "points",
    numbers: str = "exact",
    validate: bool | str = False,
    degenerate: str = "refuse",
    hint: str | None = None,
    nonfinite_hint: str | None = None,
) -> Any:
    """Read one input (see the module doc for the options); errors name it ``name``.

    ``hint`` goes with a validation error (how to repair the polygon), ``nonfinite_hint``
    with a NaN or inf found by the validation.
    """
    if accept == "points":
        if numbers == "exact":
            return _operand(obj, name)
        if numbers == "core":
            op = _operand(obj, name)
            if op.path == "py":
                raise ShapeError(
                    f"{name}: coordinates must be int64 (|x| < 2**62) or float64 here",
                    argument=name,
                    hint="scale the input down or pass floats",
                )
            return op
        data, kind = as_array(obj, name)
        return Operand(data, kind, "py" if isinstance(data, list) else "i" if kind == INT else "f")
    if accept == "many":
        return _many(obj, name)
    if accept == "coords":
        return _coords(obj, name, numbers, check_finite=True)[0]
    got = _polygonal(obj, name, numbers, accept == "polygons", degenerate)
    if validate:
        _validate(got, validate, degenerate, hint, nonfinite_hint, member=False)
    return got


def _polygonal(obj: Any, name: str, numbers: str, lists: bool, degenerate: str) -> Polygons:
    """The polygonal set, its types and numbers read (no validation). With ``"keep"`` an
    empty set is an operand too; with ``"hull"`` a shapely point or line is read as its
    coordinates (a flat set), else refused."""
    keep, hull = degenerate == "keep", degenerate == "hull"
    if lists and type(obj).__name__ == "Ragged":
        obj = obj.to_list()
    if is_shapely(obj):
        gt = obj.geom_type
        if gt in ("Polygon", "MultiPolygon"):
            if obj.is_empty and not keep:
                raise EmptyGeometryError(f"{name}: empty {gt}", argument=name)
            return Polygons(name, geom=obj)
        if gt == "GeometryCollection":
            got = polygon_parts(obj, name, empty_ok=keep, hint="pass the polygons only")
            assert got is not None
            if len(got.parts) <= 1:
                import shapely

                return Polygons(name, geom=got.parts[0] if len(got.parts) else shapely.Polygon())
            xy, ro, po, _ = polygon_arrays(got.parts)
            parts = [Polygons(f"{name}[{k}]", geom=p) for k, p in enumerate(got.parts)]
            return Polygons(name, rings=Rings(xy, ro, po), parts=parts)
        if gt != "LinearRing" and not hull:
            raise ShapeError(
                f"{name}: a {gt} is not polygonal",
                argument=name,
                hint="pass polygons, rings or (n, 2) arrays; clip lines with mk.clip_lines",
            )
        # a ring, a line, point(s): their coordinates (a ring; flat ones are degenerate)
    elif (
        lists
        and isinstance(obj, (list, tuple))
        and obj
        and (is_shapely(obj[0]) or np.ndim(obj[0]) == 2)
    ):
        parts = [
            _polygonal(item, f"{name}[{k}]", numbers, True, degenerate)
            for k, item in enumerate(obj)
        ]
        return Polygons(name, parts=parts)
    xy, delta = _coords(obj, name, numbers, check_finite=True)
    return Polygons(name, rings=rings_of_array(xy), delta=delta)


def _validate(
    got: Polygons,
    how: Any,
    degenerate: str,
    hint: str | None,
    nonfinite_hint: str | None,
    member: bool,
) -> None:
    """Check ``got`` exactly (in place: orientation, flat, split rings, overlap)."""
    if got.parts is not None:
        for p in got.parts:
            _validate(p, how, degenerate, hint, nonfinite_hint, member=True)
        got.overlap = True
        return
    rings = got.rings
    assert rings is not None
    if got.geom is None and degenerate != "refuse":
        status, reason, _, _, orientation, disconnected = probe(rings)
        if status == Status.OK and not disconnected.any():
            got.orientation = orientation
            return
        if is_flat(status, reason):
            if member:  # uniting would drop it, yet it matters: refuse rather than lose it
                raise ShapeError(
                    f"{got.name}: a point or segment in a collection of polygons (every "
                    "member of a collection must have area)",
                    argument=got.name,
                    hint="pass the point or segment as an operand of its own",
                )
            if degenerate == "keep":
                return
            from . import dispatch as D

            got.flat = np.asarray(D.hull(rings.coords, "points"), dtype=np.float64)
            return
    multi = got.multi
    disjoint = multi and how != PARTS
    checked, ck = check_split(
        rings, got.name, hint, disjoint=disjoint, nonfinite_hint=nonfinite_hint
    )
    if checked is not rings:  # a hole touching its shell twice: split into its parts
        got.geom = None
        got._rings = checked
    got.orientation = ck.orientation
    if multi and how == PARTS:  # parts that overlap or share edges: the caller unites them
        got.overlap = bool(probe(checked, disjoint=True)[0])


# --------------------------------------------------------------------------------------
# points: the dtype policy's paths


def _int_in_core(arr: np.ndarray) -> bool:
    return arr.size == 0 or (int(arr.max()) < INT_LIMIT and int(arr.min()) > -INT_LIMIT)


def _operand(obj: Any, name: str) -> Operand:
    """The points on their path (``numbers="exact"``)."""
    t = type(obj)
    if t is list or t is tuple:
        res = core.flatten([obj])
        status = res[3]
        if status == Status.OK:
            arr = res[0]
            return Operand(arr, FLOAT if res[2] else INT, "f" if res[2] else "i")
        if status == Status.NONFINITE:
            raise status_error(status, res[5], name, obj)
        if len(obj) == 0:
            pass  # as_array raises the specific error
        else:
            pts, kind = py_points(obj, name)
            return _from_points(pts, kind)
    if (
        t is np.ndarray
        and obj.ndim == 2
        and obj.shape[1] == 2
        and obj.shape[0] > 0
        and obj.dtype in _CORE_DTYPES
        and obj.flags.c_contiguous
    ):
        # the common case, checked in the core's first pass: finiteness (floats) and the
        # int64 range (RANGE sends the caller to the exact path)
        return Operand(
            obj, INT if obj.dtype == np.int64 else FLOAT, "i" if obj.dtype == np.int64 else "f"
        )
    data, kind = as_array(obj, name, check_finite=True)
    if isinstance(data, list):
        return _from_points(data, kind)
    if kind == INT:
        if _int_in_core(data):
            return Operand(np.ascontiguousarray(data, dtype=np.int64), INT, "i")
        return Operand([tuple(r) for r in data.tolist()], INT, "py")
    return Operand(np.ascontiguousarray(data, dtype=np.float64), FLOAT, "f")


def _from_points(pts: list, kind: str) -> Operand:
    if kind == FLOAT:
        return Operand(np.array(pts, dtype=np.float64).reshape(-1, 2), FLOAT, "f")
    if kind == INT and all(-INT_LIMIT < v < INT_LIMIT for p in pts for v in p):
        return Operand(np.array(pts, dtype=np.int64).reshape(-1, 2), INT, "i")
    return Operand(pts, kind, "py")


def _many(polygons: Any, name: str) -> tuple[np.ndarray, np.ndarray]:
    """A batch of point sequences as one (N, 2) int64 or float64 array and its offsets
    (``accept="many"``: lists of pairs of Python ints/floats or (n, 2) int64/float64
    arrays in one pass in the core, else each member read as ``numbers="int64"``)."""
    if type(polygons) is list or type(polygons) is tuple:
        # lists of (x, y) pairs of Python ints/floats, or of (n, 2) int64/float64
        # arrays: one pass in the core
        coords, offsets, _, status, member, vertex = core.flatten(polygons)
        if status == Status.OK and len(coords) == offsets[-1]:
            if not (np.diff(offsets) == 0).any():
                return coords, offsets
        elif status == Status.NONFINITE:
            raise nonfinite(f"{name}[{member}]", int(vertex))
    if not hasattr(polygons, "__iter__") or isinstance(polygons, (str, bytes)):
        raise ShapeError(
            f"{name}: expected a sequence of polygons, got {type(polygons).__name__}",
            argument=name,
        )
    arrs: list[np.ndarray] = []
    for k, p in enumerate(polygons):
        a: np.ndarray | None = (
            p
            if type(p) is np.ndarray
            and p.ndim == 2
            and p.dtype.kind in "if"
            and p.dtype.itemsize <= 8
            else None
        )
        if a is None or a.shape[1] != 2 or a.shape[0] == 0:
            got, kind = as_array(p, f"{name}[{k}]")
            if isinstance(got, list):
                raise ShapeError(
                    f"{name}[{k}]: coordinates need exact Python numbers; "
                    "use the single-pair minkowski_sum for these"
                )
            a = got
        arrs.append(a)
    if not arrs:
        return np.empty((0, 2), np.int64), np.zeros(1, np.int64)
    lengths = np.fromiter((len(a) for a in arrs), np.int64, len(arrs))
    coords = np.concatenate(arrs)
    if coords.dtype.kind == "f":
        coords = coords.astype(np.float64, copy=False)
        if not np.isfinite(coords).all():
            row = int(np.flatnonzero(~np.isfinite(coords).all(axis=1))[0])
            offsets = np.concatenate(([0], np.cumsum(lengths)))
            k = int(np.searchsorted(offsets, row, side="right") - 1)
            raise nonfinite(f"{name}[{k}]", int(row - offsets[k]), arrs[k])
    elif coords.dtype.kind in "iu":
        coords = coords.astype(np.int64, copy=False)
    offsets = np.zeros(len(arrs) + 1, np.int64)
    np.cumsum(lengths, out=offsets[1:])
    return coords, offsets


# --------------------------------------------------------------------------------------
# float64 coordinates: the number policies of rings and lines


def _coords(obj: Any, name: str, numbers: str, check_finite: bool) -> tuple[np.ndarray, float]:
    """(n, 2) float64 coordinates by ``numbers`` and the rounding bound (``"round"``)."""
    data, kind = as_array(obj, name, check_finite=check_finite)
    if isinstance(data, list):  # exact kinds: Fractions, wide floats or ints beyond int64
        return _rounded(data, name, numbers, kind)
    if data.dtype.kind == "i":
        f = data.astype(np.float64)
        wide = np.flatnonzero((np.abs(f) >= 2.0**53).any(axis=1))
        if numbers == "round":
            return f, _rounding_error(data[wide].tolist(), f[wide]) if len(wide) else 0.0
        # float64 holds every int below 2**53; the others are checked one by one
        for k in wide:
            for v in data[k].tolist():
                _check_int(int(v), name, int(k))
        return f, 0.0
    return np.asarray(data, dtype=np.float64), 0.0


def _rounded(pts: list, name: str, numbers: str, kind: str) -> tuple[np.ndarray, float]:
    out = np.empty((len(pts), 2))
    for k, p in enumerate(pts):
        for j, v in enumerate(p):
            if isinstance(v, int) and numbers != "round":
                _check_int(v, name, k)
            f = to_float(v)
            if math.isinf(f):
                raise OverflowGeometryError(
                    f"{name}: vertex {k} has a coordinate beyond float64 (±1.8e308)",
                    argument=name,
                    vertex=k,
                    hint="scale the input down; coordinates must fit in float64",
                )
            if numbers == "float64" and Fraction(v) != Fraction(f):
                raise GeometryError(
                    f"{name}: vertex {k} is not a float64 value; this operation computes on "
                    "float64 coordinates exactly and would round it",
                    argument=name,
                    vertex=k,
                    hint="round the coordinates to float64 first (float(x))",
                )
            if numbers == "fractions" and v != 0 and abs(f) < 2.0**-1022:
                raise OverflowGeometryError(
                    f"{name}: vertex {k} has a coordinate that underflows float64 (a "
                    "nonzero value below 2**-1022 would be rounded to a multiple of "
                    "2**-1074)",
                    argument=name,
                    vertex=k,
                    hint="scale the input up; coordinates must be float64 normals",
                )
            out[k, j] = f
    return out, _rounding_error(pts, out) if numbers == "round" else 0.0


def _check_int(v: int, name: str, vertex: int) -> None:
    if not fits_float64(v):
        raise GeometryError(
            f"{name}: vertex {vertex} has the integer coordinate {v}, which float64 "
            "cannot hold exactly (more than 53 significant bits, or beyond its range); "
            "this operation computes on float64 coordinates exactly and would round it",
            argument=name,
            vertex=vertex,
            hint="round or scale the coordinates to at most 53 significant bits, "
            "or use the exact convex routines",
        )


def _rounding_error(exact: list, data: np.ndarray) -> float:
    """An upper bound on the distance between each exact vertex and its float64 value."""
    worst = Fraction(0)
    for (x, y), (fx, fy) in zip(exact, data.tolist()):
        if x != fx or y != fy:
            worst = max(worst, abs(Fraction(x) - Fraction(fx)), abs(Fraction(y) - Fraction(fy)))
    # sqrt(2) < 1.5, and float() of a Fraction rounds to nearest
    return float(worst) * 1.5
