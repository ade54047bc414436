"""Containers in and out of the batch functions, and progress for long batches.

The batch functions (``minkowski_sum_many``, ``intersects_many``, ``distance_many``,
``penetration_many``, and any later ``*_many``) call :func:`apply` at their entry when an
operand is a container of shapely geometries or ``progress`` is given::

    if progress is not None or boxed(As) or boxed(Bs):
        return apply(partial(this_function, threads=threads), As, Bs, progress=progress)

:func:`apply` then

1. *unboxes* each container — a geopandas ``GeoSeries`` (or a ``GeoDataFrame``'s active
   geometry), a ``GeometryArray``, or a numpy object array (any shape) of shapely
   geometries and ``None`` — into a flat list of the members that can be computed;
2. checks member types for convex batches (a MultiPolygon or a polygon with holes gets an
   error naming its index label, not "not convex" of a flattened ring);
3. calls the function on those members (one call, or about 64 chunks with progress
   reported after each), renaming errors from ``As[q]`` (position among the computed
   members, within a chunk) to ``As[label]`` (the caller's own index);
4. *boxes* the result as the first container came in: a GeoSeries keeps its index and CRS
   (scalar results become a pandas Series with that index), a GeometryArray stays one, an
   object array comes back with its shape. ``None`` in gives ``None`` out (NaN for
   numbers, ``<NA>`` in a pandas boolean Series, ``False`` in a numpy bool array as in
   shapely); an empty geometry gives an empty geometry (NaN / False for scalars).

Plain lists and :class:`~minkowski2d.Ragged` are not containers here: they keep their
fast path and come back as a ``Ragged`` (or arrays), also when chunked for progress.

Examples
--------
>>> import numpy as np, shapely
>>> from minkowski2d._engine.containers import apply
>>> from minkowski2d import minkowski_sum_many
>>> g = np.array([shapely.box(0, 0, 1, 1), None, shapely.Polygon()], dtype=object)
>>> [None if x is None else x.wkt for x in apply(minkowski_sum_many, g, [(0, 0), (1, 0)])]
['POLYGON ((0 0, 2 0, 2 1, 0 1, 0 0))', None, 'POLYGON EMPTY']
"""

from __future__ import annotations

import re
import sys
from collections.abc import Callable, Sequence
from typing import Any, NamedTuple, cast

import numpy as np

from ..errors import GeometryError, NotConvexError, ShapeError
from .coerce import is_shapely

__all__ = ["boxed", "unbox", "apply", "Box", "Progress", "check_progress"]

#: shapely type ids a convex routine reads as one polygon, ring, segment or point set
_CONVEX_TYPES = (0, 1, 2, 3, 4)
_TYPE_NAMES = {5: "MultiLineString", 6: "MultiPolygon", 7: "GeometryCollection"}
_ARG = re.compile(r"^(\w+)\[(\d+)\]$")
#: progress: how many chunks the pairs are cut into
CHUNKS = 64


class Box(NamedTuple):
    """One container, unboxed: ``geoms`` is a flat (n,) object array."""

    kind: str  # "geoseries", "geometryarray", "ndarray"
    geoms: np.ndarray
    shape: tuple
    index: Any
    crs: Any
    name: Any

    def label(self, pos: int) -> str:
        """The caller's name for member ``pos``: its index label (GeoSeries), its
        position (flat arrays) or its multi-index (arrays of 2 or more dimensions)."""
        if self.kind == "geoseries":
            lab = self.index[pos]
            return repr(lab) if isinstance(lab, str) else str(lab)
        if len(self.shape) > 1:
            return ", ".join(str(int(i)) for i in np.unravel_index(pos, self.shape))
        return str(pos)


def _geopandas_kind(x: Any) -> str | None:
    mod = type(x).__module__
    if not mod.startswith("geopandas"):
        return None
    name = type(x).__name__
    return {"GeoSeries": "geoseries", "GeoDataFrame": "geoseries"}.get(
        name, "geometryarray" if name == "GeometryArray" else None
    )


def boxed(x: Any) -> bool:
    """True for a GeoSeries, GeoDataFrame, GeometryArray, or a numpy object array whose
    members are all shapely geometries or None (cheap for lists: False at once)."""
    t = type(x)
    if t is list or t is tuple:
        return False
    if t is np.ndarray:
        if x.dtype != object:
            return False
        if x.size == 0:
            return x.ndim == 1
        import shapely

        flat = x.ravel()
        is_none = np.equal(flat, None)  # type: ignore[call-overload]  # numpy's stubs take no None
        return bool((shapely.is_geometry(flat) | is_none).all())
    return _geopandas_kind(x) is not None


def unbox(x: Any) -> Box | None:
    """The :class:`Box` of a container, or None when ``x`` is not one."""
    if not boxed(x):
        return None
    kind = _geopandas_kind(x)
    if kind == "geoseries":
        if type(x).__name__ == "GeoDataFrame":
            x = x.geometry
        return Box(kind, np.asarray(x.array, dtype=object), (len(x),), x.index, x.crs, x.name)
    if kind == "geometryarray":
        return Box(kind, np.asarray(x, dtype=object), (len(x),), None, x.crs, None)
    return Box("ndarray", x.ravel(), x.shape, None, None, None)


# --------------------------------------------------------------------------------------
# progress


class Progress:
    """Reports ``done`` out of ``total``: a tqdm bar on stderr, or a callback."""

    def __init__(self, progress: Any, total: int) -> None:
        self.total = total
        self.done = 0
        self.bar = None
        self.cb: Callable[[int, int], Any] | None = None
        if progress is True:
            try:
                from tqdm import tqdm
            except ImportError:
                raise ImportError(
                    "progress=True draws a tqdm bar: pip install tqdm "
                    "(or pass a callable cb(done, total))"
                ) from None
            self.bar = tqdm(total=total, file=sys.stderr, unit="pair", leave=False)
        elif callable(progress):
            self.cb = progress

    def update(self, n: int) -> None:
        self.done += n
        if self.bar is not None:
            self.bar.update(n)
        if self.cb is not None:
            self.cb(self.done, self.total)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()


def check_progress(progress: Any) -> None:
    """Raise for a ``progress=`` value that is not None, a bool or a callable."""
    from . import options as _options

    _options.progress(progress)


def is_many(x: Any, empty: bool = True) -> bool:
    """A collection of polygons (what the batch functions pair up), not one polygon: a
    Ragged, a GeoSeries or GeometryArray, a 1-D object array of geometries, or a list or
    tuple whose first item is a polygon (2-D), a shapely geometry or ``None``. ``empty``
    says what ``[]`` is: a collection of no polygons (the batch functions), or one empty
    polygon (offset, whose error then names it)."""
    if type(x).__name__ in ("Ragged", "GeoSeries", "GeometryArray"):
        return True
    if isinstance(x, np.ndarray):
        return x.dtype == object and x.ndim == 1 and (len(x) == 0 or not np.isscalar(x[0]))
    if is_shapely(x):
        return False
    if isinstance(x, (list, tuple)):
        if len(x) == 0:
            return empty
        first = x[0]
        return first is None or np.ndim(first) == 2 or is_shapely(first)
    return False


def _combine(parts: list) -> Any:
    first = parts[0]
    if len(parts) == 1:
        return first
    if type(first).__name__ == "Ragged":
        return type(first).concat(parts)
    if isinstance(first, tuple) and hasattr(first, "_fields"):
        return type(first)(*(_combine([p[k] for p in parts]) for k in range(len(first))))
    if isinstance(first, np.ndarray):
        return np.concatenate(parts)
    if isinstance(first, list):
        return [x for p in parts for x in p]
    raise TypeError(f"cannot combine chunk results of type {type(first).__name__}")


def _rename(exc: GeometryError, names: Sequence[str], shift: int, boxes: list) -> GeometryError:
    """``As[q]`` (q among the computed members of a chunk starting at ``shift``) -> the
    caller's ``As[label]``."""
    m = _ARG.match(exc.argument or "")
    if not m or m.group(1) not in names:
        return exc
    k = names.index(m.group(1))
    q = int(m.group(2)) + shift
    box, positions = boxes[k]
    if box is None:
        if not shift:
            return exc
        return exc.renamed(f"{m.group(1)}[{q}]")
    return exc.renamed(f"{m.group(1)}[{box.label(int(positions[q]))}]")


def _run(
    compute: Callable[..., Any],
    operands: list,
    progress: Any,
    names: Sequence[str],
    boxes: list,
) -> Any:
    many = [is_many(x) for x in operands]
    sizes = [len(x) for x, m in zip(operands, many) if m]
    if progress is None or progress is False or not sizes:
        try:
            return compute(*operands)
        except GeometryError as exc:
            raise _rename(exc, names, 0, boxes) from None
    total = sizes[0]
    nchunks = max(1, min(CHUNKS, total))
    bounds = np.linspace(0, total, nchunks + 1).astype(np.int64)
    report = Progress(progress, total)
    parts: list[Any] = []  # compute's result per chunk
    try:
        for lo, hi in zip(bounds[:-1].tolist(), bounds[1:].tolist()):
            if hi == lo and parts:
                continue
            args = [x[lo:hi] if m else x for x, m in zip(operands, many)]
            try:
                parts.append(compute(*args))
            except GeometryError as exc:
                raise _rename(exc, names, lo, boxes) from None
            report.update(hi - lo)
        if report.done != total:  # pragma: no cover - defensive: always reach total
            report.update(total - report.done)
    finally:
        report.close()
    return _combine(parts)


# --------------------------------------------------------------------------------------
# apply


def _check_convex_members(box: Box, valid: np.ndarray, name: str) -> None:
    import shapely

    g = box.geoms
    types = np.full(len(g), -1, np.int64)
    types[valid] = shapely.get_type_id(g[valid])
    bad = np.flatnonzero(valid & ~np.isin(types, _CONVEX_TYPES))
    if bad.size:
        pos = int(bad[0])
        what = _TYPE_NAMES.get(int(types[pos]), "geometry")
        arg = f"{name}[{box.label(pos)}]"
        raise ShapeError(
            f"{arg}: a {what} is not one convex polygon",
            argument=arg,
            hint="split it into its parts first (GeoSeries.explode()), or use "
            "minkowski_sum_general for non-convex shapes",
        )
    polys = np.flatnonzero(types == 3)
    if polys.size:
        holes = shapely.get_num_interior_rings(g[polys])
        if (holes > 0).any():
            pos = int(polys[np.flatnonzero(holes > 0)[0]])
            arg = f"{name}[{box.label(pos)}]"
            raise NotConvexError(
                f"{arg}: polygon has {int(holes[holes > 0][0])} hole(s), so it is not convex",
                argument=arg,
                hint="use minkowski_sum_general for polygons with holes",
            )


def apply(
    compute: Callable[..., Any],
    *operands: Any,
    progress: Any = None,
    convex: bool = True,
    names: Sequence[str] = ("As", "Bs"),
) -> Any:
    """Run a batch function on containers (see the module docs) and box its result.

    Parameters
    ----------
    compute : callable
        The batch function itself (with its keywords bound), called with the operands
        unboxed: lists of the members to compute (containers), or the operands as given.
        It returns a ``Ragged``, an object array or list of shapely geometries, a numpy
        array of per-pair values, or a NamedTuple of such arrays.
    *operands
        One or more operands (``As``, ``Bs``; a unary function passes one).
    progress : None, bool or callable
        ``True``: a tqdm bar on stderr; a callable: ``cb(done, total)`` after each chunk,
        last with ``done == total``.
    convex : bool
        Check that members are single polygons, rings or point sets without holes.
    names : sequence of str
        The argument names the function uses in its errors (``As[q]``).
    """
    check_progress(progress)
    boxes_: list[Box | None] = [unbox(x) for x in operands]
    out_box = next((b for b in boxes_ if b is not None), None)
    if out_box is None:
        return _run(compute, list(operands), progress, names, [(None, None)] * len(operands))
    import shapely

    n = len(out_box.geoms)
    for b, nm in zip(boxes_, names):
        if b is not None and len(b.geoms) != n:
            raise ShapeError(
                f"{names[0]} has {n} members but {nm} has {len(b.geoms)}; pairs need equal counts",
                argument=nm,
            )
    crss = [b.crs for b in boxes_ if b is not None and b.crs is not None]
    if any(c != crss[0] for c in crss[1:]):
        raise ShapeError(
            f"the operands have different CRS ({crss[0]} and {crss[1]})",
            hint="bring them to one CRS first (GeoSeries.to_crs)",
        )
    null = np.zeros(n, bool)
    empty = np.zeros(n, bool)
    for b in boxes_:
        if b is not None:
            isnull = np.equal(b.geoms, None)  # type: ignore[call-overload]  # numpy: no None
            null |= isnull
            empty |= ~isnull & shapely.is_empty(b.geoms)
    empty &= ~null
    valid = ~(null | empty)
    if convex:
        for b, nm in zip(boxes_, names):
            if b is not None:
                _check_convex_members(b, valid, nm)
    positions = np.flatnonzero(valid)
    args = [list(b.geoms[valid]) if b is not None else x for b, x in zip(boxes_, operands)]
    boxes = [(b, positions) for b in boxes_]
    value = _run(compute, args, progress, names, boxes)
    return _box(value, out_box, valid, null, empty)


# --------------------------------------------------------------------------------------
# boxing the result


def _geoms_of(value: Any) -> np.ndarray:
    if type(value).__name__ == "Ragged":
        return value.to_shapely()
    return np.asarray(value, dtype=object).ravel() if not isinstance(value, list) else _obj(value)


def _obj(items: list) -> np.ndarray:
    out = np.empty(len(items), dtype=object)
    out[:] = items
    return out


def _scatter_geoms(g: np.ndarray, box: Box, valid: np.ndarray, empty: np.ndarray) -> Any:
    import shapely

    out = np.full(len(valid), None, dtype=object)
    out[valid] = g
    if empty.any():
        out[empty] = shapely.Polygon()
    return _wrap_geoms(out, box)


def _wrap_geoms(out: np.ndarray, box: Box) -> Any:
    if box.kind == "geoseries":
        import geopandas

        return geopandas.GeoSeries(out, index=box.index, crs=box.crs, name=box.name)
    if box.kind == "geometryarray":
        from geopandas.array import from_shapely

        return from_shapely(out, crs=box.crs)
    return out.reshape(box.shape)


def _scatter_values(v: np.ndarray, box: Box, valid: np.ndarray, null: np.ndarray) -> Any:
    n = len(valid)
    if v.dtype == bool:
        if box.kind == "geoseries":
            import pandas as pd

            arr = pd.array(np.zeros(n, bool), dtype="boolean")
            arr[valid] = v
            arr[null] = pd.NA
            return pd.Series(arr, index=box.index)
        out = np.zeros(n, bool)
        out[valid] = v
        return out.reshape(box.shape)
    tail = v.shape[1:]
    out = np.full((n, *tail), np.nan)
    out[valid] = v
    if box.kind == "geoseries":
        import pandas as pd

        if tail:
            return pd.DataFrame(out, index=box.index, columns=["x", "y"][: tail[0]])
        return pd.Series(out, index=box.index)
    return out.reshape(box.shape + tail) if box.kind == "ndarray" else out


def _box(value: Any, box: Box, valid: np.ndarray, null: np.ndarray, empty: np.ndarray) -> Any:
    if isinstance(value, tuple) and hasattr(value, "_fields"):
        fields = []
        for name, v in zip(value._fields, value):
            if name.startswith("point") and isinstance(v, np.ndarray) and v.ndim == 2:
                import shapely

                pts = cast(np.ndarray, shapely.points(v)) if len(v) else np.empty(0, dtype=object)
                fields.append(_scatter_geoms(pts, box, valid, np.zeros_like(empty)))
            else:
                fields.append(_box(v, box, valid, null, empty))
        return type(value)(*fields)
    if isinstance(value, np.ndarray) and value.dtype != object:
        return _scatter_values(value, box, valid, null)
    return _scatter_geoms(_geoms_of(value), box, valid, empty)
