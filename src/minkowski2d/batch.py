"""Many polygons at once: the ragged representation and batched Minkowski sums.

A :class:`Ragged` holds P polygons in one (N, 2) coordinate array and P + 1 offsets:
polygon ``k`` is ``coords[offsets[k]:offsets[k + 1]]``. It converts to and from a list
of arrays and a numpy array of shapely geometries, and is what the batched functions
take and return.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from fractions import Fraction
from functools import partial
from typing import Any, SupportsIndex, overload

import numpy as np

from ._engine import core
from ._engine import dispatch as D
from ._engine import options as _options
from ._engine.coerce import is_shapely
from ._engine.containers import apply, boxed, is_many
from ._engine.reader import read
from ._types import ArrayLike2, Coordinate, GeometryLike, PolygonsLike, ProgressLike
from .errors import (
    CoordinateTypeError,
    EmptyGeometryError,
    NotConvexError,
    ShapeError,
)

__all__ = ["Ragged", "minkowski_sum_many", "as_ragged_pair"]


def _is_real(v: Any) -> bool:
    return isinstance(v, (int, float, Fraction, np.integer, np.floating)) and not isinstance(
        v, (bool, np.bool_)
    )


class Ragged:
    """P polygons stored flat: ``coords`` (N, 2) and ``offsets`` (P + 1,).

    ``r[k]`` is polygon k (a view); ``r[2:9]`` (a view), ``r[[4, 0]]`` and ``r[mask]`` are
    Raggeds; :meth:`concat` joins them; ``==`` compares values; ``sys.getsizeof`` counts
    the arrays; pickling (protocol 5) passes the arrays out of band; :meth:`to_shapely`,
    :meth:`from_shapely`, :meth:`to_ragged_array` and :meth:`from_ragged_array` convert to
    and from shapely (the GeoArrow layout of :func:`shapely.to_ragged_array`).

    Parameters
    ----------
    coords : (N, 2) int64 or float64 ndarray
    offsets : (P + 1,) int64 ndarray, starting at 0, non-decreasing, ending at N

    Examples
    --------
    >>> from minkowski2d import Ragged
    >>> r = Ragged.from_list([[(0, 0), (1, 0), (0, 1)], [(5, 5)]])
    >>> len(r), r.offsets.tolist(), r[1].tolist()
    (2, [0, 3, 4], [[5, 5]])
    """

    __slots__ = ("coords", "offsets")

    def __init__(self, coords: np.ndarray, offsets: np.ndarray) -> None:
        coords = np.asarray(coords)
        if coords.dtype.kind not in "iuf" and not (
            coords.dtype.kind == "O" and all(_is_real(v) for v in coords.ravel().tolist())
        ):
            raise CoordinateTypeError(
                f"Ragged: coords of dtype {coords.dtype} are not real numbers",
                argument="coords",
                hint="give an (N, 2) int64 or float64 array",
            )
        raw = np.asarray(offsets)
        if raw.dtype.kind not in "iu":
            finite = raw.dtype.kind == "f" and np.isfinite(raw).all()
            whole = finite and (raw == np.floor(raw)).all()
            if not (whole or raw.size == 0):
                raise ShapeError(
                    f"Ragged: offsets must be integers, got dtype {raw.dtype}",
                    argument="offsets",
                    hint="offsets are vertex indices: 0, then each polygon's end",
                )
        offsets = raw.astype(np.int64) if raw.size else np.zeros(0, np.int64)
        if coords.ndim != 2 or coords.shape[1] != 2:
            raise ShapeError(f"Ragged: coords must have shape (N, 2), got {coords.shape}")
        if offsets.ndim != 1 or offsets.size == 0 or offsets[0] != 0 or offsets[-1] != len(coords):
            raise ShapeError("Ragged: offsets must start at 0 and end at len(coords)")
        if (np.diff(offsets) < 0).any():
            raise ShapeError("Ragged: offsets must be non-decreasing")
        self.coords = coords
        self.offsets = offsets

    # construction ------------------------------------------------------------------
    @classmethod
    def from_list(cls, polygons: Sequence[ArrayLike2], name: str = "polygons") -> Ragged:
        """Build from a sequence of (n_k, 2) array-likes (or shapely geometries)."""
        if isinstance(polygons, Ragged):
            return polygons
        coords, offsets = read(polygons, name, accept="many")
        return cls(coords, offsets)

    @classmethod
    def from_shapely(cls, geoms: Any, name: str = "polygons") -> Ragged:
        """Build from an array of shapely Polygons (holes not allowed), rings or points."""
        import shapely

        geoms = np.asarray(geoms, dtype=object).ravel()
        types = shapely.get_type_id(geoms)
        if (types >= 5).any() or (types < 0).any():
            k = int(np.flatnonzero((types >= 5) | (types < 0))[0])
            what = "None" if types[k] < 0 else geoms[k].geom_type
            raise ShapeError(
                f"{name}[{k}]: a {what} is not one polygon, ring or point set",
                argument=f"{name}[{k}]",
                hint="pass a numpy object array or a GeoSeries to keep None members"
                if types[k] < 0
                else "split multi-part geometries into their parts first",
            )
        polys = types == 3
        if polys.any():
            nh = shapely.get_num_interior_rings(geoms[polys])
            if (nh > 0).any():
                k = int(np.flatnonzero(polys)[np.flatnonzero(nh > 0)[0]])
                raise ShapeError(f"{name}[{k}]: polygon has holes; Ragged holds simple rings")
        # without holes a polygon's coordinates are its exterior ring's: no ring objects
        coords, index = shapely.get_coordinates(geoms, return_index=True)
        counts = np.bincount(index, minlength=len(geoms)).astype(np.int64)
        closed = np.isin(types, (2, 3)) & (counts > 1)
        # drop the closing vertex of each ring
        ends = np.cumsum(counts)
        drop = np.zeros(len(coords), bool)
        drop[ends[closed] - 1] = True
        coords = coords[~drop]
        counts = counts - closed
        if (counts == 0).any():
            raise EmptyGeometryError(
                f"{name}[{int(np.flatnonzero(counts == 0)[0])}]: empty geometry"
            )
        offsets = np.zeros(len(geoms) + 1, np.int64)
        np.cumsum(counts, out=offsets[1:])
        return cls(coords, offsets)

    # access --------------------------------------------------------------------------
    def __len__(self) -> int:
        return len(self.offsets) - 1

    @overload
    def __getitem__(self, k: int | np.integer) -> np.ndarray: ...
    @overload
    def __getitem__(self, k: slice | Sequence[int] | np.ndarray) -> Ragged: ...
    def __getitem__(self, k: Any) -> Any:
        """Polygon ``k`` as an (n_k, 2) view; a slice, an index array or a boolean mask
        gives a :class:`Ragged` (a slice shares the coordinates, zero-copy).

        Examples
        --------
        >>> from minkowski2d import Ragged
        >>> r = Ragged.from_list([[(0, 0)], [(1, 1), (2, 2)], [(3, 3), (4, 3), (3, 4)]])
        >>> r[1:].lengths.tolist(), r[[2, 0]].lengths.tolist(), r[r.lengths > 1].offsets.tolist()
        ([2, 3], [3, 1], [0, 2, 5])
        """
        if isinstance(k, (int, np.integer)) and not isinstance(k, bool):
            n = len(self)
            k = int(k)
            if k < 0:
                k += n
            if not 0 <= k < n:
                raise IndexError(k)
            return self.coords[self.offsets[k] : self.offsets[k + 1]]
        return _take(self, k)

    @classmethod
    def concat(cls, parts: Sequence[Ragged]) -> Ragged:
        """One Ragged holding the polygons of ``parts`` in order (coordinates are
        promoted as numpy promotes: int64 with float64 gives float64).

        Examples
        --------
        >>> from minkowski2d import Ragged
        >>> a = Ragged.from_list([[(0, 0), (1, 0)]])
        >>> Ragged.concat([a, a[:0], a]).offsets.tolist()
        [0, 2, 4]
        """
        parts = [p if isinstance(p, Ragged) else Ragged.from_list(p) for p in parts]
        if not parts:
            return cls(np.empty((0, 2), np.int64), np.zeros(1, np.int64))
        coords = np.concatenate([p.coords for p in parts])
        starts = np.cumsum([0] + [len(p.coords) for p in parts[:-1]])
        offsets = np.concatenate(
            [[0]] + [p.offsets[1:] + s for p, s in zip(parts, starts.tolist())]
        ).astype(np.int64)
        return cls(coords, offsets)

    def __eq__(self, other: object) -> bool:
        """Value equality: the same offsets and the same coordinate values."""
        if not isinstance(other, Ragged):
            return NotImplemented
        return bool(
            np.array_equal(self.offsets, other.offsets)
            and np.array_equal(self.coords, other.coords)
        )

    __hash__ = None  # type: ignore[assignment]  # mutable arrays inside: unhashable

    def __sizeof__(self) -> int:
        """True size in bytes: the object plus its two arrays' data (what ``sys.getsizeof``
        and Dask's memory accounting read)."""
        return object.__sizeof__(self) + int(self.coords.nbytes) + int(self.offsets.nbytes)

    def __reduce_ex__(self, protocol: SupportsIndex) -> Any:
        """Pickling: with protocol 5 the arrays travel as out-of-band buffers
        (:class:`pickle.PickleBuffer`), so Dask and multiprocessing need not copy them."""
        coords = np.ascontiguousarray(self.coords)
        offsets = np.ascontiguousarray(self.offsets)
        if int(protocol) >= 5 and coords.dtype != object:
            import pickle

            return (
                _from_buffers,
                (
                    # ndarray is a buffer; numpy's stubs say so for Python >= 3.12 only
                    pickle.PickleBuffer(coords),  # type: ignore[arg-type]
                    coords.dtype.str,
                    len(coords),
                    pickle.PickleBuffer(offsets),  # type: ignore[arg-type]
                ),
            )
        return (_from_arrays, (coords, offsets))

    def __iter__(self) -> Iterator[np.ndarray]:
        for k in range(len(self)):
            yield self[k]

    def __repr__(self) -> str:
        return (
            f"Ragged({len(self)} polygons, {len(self.coords)} vertices, dtype={self.coords.dtype})"
        )

    @property
    def lengths(self) -> np.ndarray:
        """Vertex count of each polygon, (P,) int64."""
        return np.diff(self.offsets)

    def to_list(self) -> list[np.ndarray]:
        """A list of (n_k, 2) arrays (copies)."""
        return [a.copy() for a in np.split(self.coords, self.offsets[1:-1])]

    def to_ragged_array(self) -> tuple[Any, np.ndarray, tuple[np.ndarray, np.ndarray]]:
        """The GeoArrow polygon layout of :func:`shapely.to_ragged_array`:
        ``(GeometryType.POLYGON, coords, (ring_offsets, geom_offsets))`` with each ring
        closed (first vertex repeated), float64 coordinates.

        Examples
        --------
        >>> from minkowski2d import Ragged
        >>> r = Ragged.from_list([[(0, 0), (1, 0), (0, 1)]])
        >>> t, coords, (rings, geoms) = r.to_ragged_array()
        >>> t.name, coords.tolist(), rings.tolist(), geoms.tolist()
        ('POLYGON', [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [0.0, 0.0]], [0, 4], [0, 1])
        """
        import shapely

        n = len(self)
        if (self.lengths == 0).any():
            k = int(np.flatnonzero(self.lengths == 0)[0])
            raise EmptyGeometryError(f"polygons[{k}]: no vertices", argument=f"polygons[{k}]")
        closed_off = self.offsets + np.arange(n + 1)
        coords = np.empty((len(self.coords) + n, 2), np.float64)
        ends = closed_off[1:] - 1
        keep = np.ones(len(coords), bool)
        keep[ends] = False
        coords[keep] = self.coords
        coords[ends] = self.coords[self.offsets[:-1]]
        return shapely.GeometryType.POLYGON, coords, (closed_off, np.arange(n + 1, dtype=np.int64))

    @classmethod
    def from_ragged_array(
        cls, geometry_type: Any, coords: np.ndarray, offsets: Any = None
    ) -> Ragged:
        """From the output of :func:`shapely.to_ragged_array` for polygons (one ring
        each: no holes), linestrings or points; closing vertices are dropped.

        Examples
        --------
        >>> import shapely
        >>> g = [shapely.box(0, 0, 2, 1)]
        >>> Ragged.from_ragged_array(*shapely.to_ragged_array(g))[0].tolist()
        [[2.0, 0.0], [2.0, 1.0], [0.0, 1.0], [0.0, 0.0]]
        """
        import shapely

        gt = shapely.GeometryType(geometry_type)
        coords = np.asarray(coords)[:, :2]
        if gt == shapely.GeometryType.POINT:
            return cls(np.ascontiguousarray(coords), np.arange(len(coords) + 1, dtype=np.int64))
        if gt == shapely.GeometryType.LINESTRING:
            return cls(np.ascontiguousarray(coords), np.asarray(offsets[0], np.int64))
        if gt != shapely.GeometryType.POLYGON:
            raise ShapeError(f"Ragged.from_ragged_array: {gt.name} is not a polygon layout")
        rings, geoms = (np.asarray(o, np.int64) for o in offsets)
        if len(rings) != len(geoms) or not np.array_equal(geoms, np.arange(len(geoms))):
            k = int(np.flatnonzero(np.diff(geoms) != 1)[0]) if len(geoms) > 1 else 0
            raise NotConvexError(
                f"polygons[{k}]: polygon has holes; Ragged holds simple rings",
                argument=f"polygons[{k}]",
            )
        L = np.diff(rings)
        closed = L > 1
        drop = np.zeros(len(coords), bool)
        drop[rings[1:][closed] - 1] = True
        new_off = np.zeros(len(L) + 1, np.int64)
        np.cumsum(L - closed, out=new_off[1:])
        return cls(np.ascontiguousarray(coords[~drop]), new_off)

    def to_shapely(self) -> np.ndarray:
        """A (P,) object array of shapely geometries: Polygon for three or more vertices,
        LineString for two, Point for one."""
        import shapely

        lengths = self.lengths
        if len(self) and (lengths >= 3).all():
            return shapely.from_ragged_array(*self.to_ragged_array())
        coords = self.coords.astype(np.float64)
        out = np.empty(len(self), dtype=object)
        idx = np.repeat(np.arange(len(self)), lengths)
        for sel, make in ((lengths >= 3, "poly"), (lengths == 2, "line"), (lengths == 1, "point")):
            if not sel.any():
                continue
            rows = sel[idx]
            sub_idx = np.cumsum(sel)[idx[rows]] - 1
            g: shapely.Geometry | np.ndarray
            if make == "poly":
                g = shapely.polygons(shapely.linearrings(coords[rows], indices=sub_idx))
            elif make == "line":
                g = shapely.linestrings(coords[rows], indices=sub_idx)
            else:
                g = shapely.points(coords[rows])
            out[np.flatnonzero(sel)] = g
        return out


def _take(r: Ragged, k: Any) -> Ragged:
    """``r[k]`` for a slice, an index array or a boolean mask."""
    n = len(r)
    if isinstance(k, slice):
        start, stop, step = k.indices(n)
        if step == 1:
            stop = max(stop, start)
            lo, hi = int(r.offsets[start]), int(r.offsets[stop])
            return Ragged(r.coords[lo:hi], r.offsets[start : stop + 1] - lo)
        idx = np.arange(start, stop, step)
    else:
        idx = np.asarray(k)
        if idx.dtype == bool:
            if idx.shape != (n,):
                raise IndexError(f"boolean index of shape {idx.shape} for {n} polygons")
            idx = np.flatnonzero(idx)
        elif idx.size == 0:
            idx = idx.astype(np.int64)
        elif idx.dtype.kind not in "iu" or idx.ndim != 1:
            raise IndexError(f"Ragged indices must be ints, slices or masks, not {k!r}")
        idx = np.where(idx < 0, idx + n, idx)
        if idx.size and (idx.min() < 0 or idx.max() >= n):
            raise IndexError(f"index out of range for {n} polygons")
    L = r.lengths[idx]
    off = np.zeros(len(idx) + 1, np.int64)
    np.cumsum(L, out=off[1:])
    rows = np.arange(off[-1]) - np.repeat(off[:-1] - r.offsets[idx], L)
    return Ragged(r.coords[rows], off)


def _from_arrays(coords: np.ndarray, offsets: np.ndarray) -> Ragged:
    r = Ragged.__new__(Ragged)
    r.coords = coords
    r.offsets = offsets
    return r


def _from_buffers(coords: Any, dtype: str, n: int, offsets: Any) -> Ragged:
    c = np.frombuffer(coords, dtype=np.dtype(dtype)).reshape(n, 2)
    return _from_arrays(c, np.frombuffer(offsets, dtype=np.int64))


def _as_ragged(x: Any, name: str) -> Ragged:
    if isinstance(x, Ragged):
        return x
    if isinstance(x, np.ndarray) and x.dtype == object:
        return Ragged.from_shapely(x, name)
    if isinstance(x, (list, tuple)) and x and is_shapely(x[0]):
        return Ragged.from_shapely(np.array(x, dtype=object), name)
    return Ragged.from_list(x, name)


def as_ragged_pair(
    As: Any, Bs: Any
) -> tuple[Ragged, np.ndarray, np.ndarray, Ragged, np.ndarray, np.ndarray, int, tuple[str, str]]:
    """Resolve pairwise or broadcast operands into two Raggeds and per-pair ranges.

    Returns ``(RA, a_lo, a_hi, RB, b_lo, b_hi, P, names)``: pair q is
    ``RA.coords[a_lo[q]:a_hi[q]]`` with ``RB.coords[b_lo[q]:b_hi[q]]``; ``names`` are the
    argument names used in error messages (``"As"``/``"a"``).
    """
    many_a, many_b = is_many(As), is_many(Bs)
    if not many_a and not many_b:
        raise ShapeError("give a collection of polygons for As or Bs (or use minkowski_sum)")
    RA = _as_ragged(As, "As") if many_a else Ragged.from_list([As], "a")
    RB = _as_ragged(Bs, "Bs") if many_b else Ragged.from_list([Bs], "b")
    P = len(RA) if many_a else len(RB)
    if many_a and many_b and len(RA) != len(RB):
        raise ShapeError(f"As has {len(RA)} polygons but Bs has {len(RB)}; pairs need equal counts")
    for R, nm in ((RA, "As" if many_a else "a"), (RB, "Bs" if many_b else "b")):
        L = R.lengths
        if (L == 0).any():
            raise EmptyGeometryError(
                f"{nm}[{int(np.flatnonzero(L == 0)[0])}]: empty input (no vertices)"
            )
    if many_a:
        a_lo, a_hi = RA.offsets[:-1], RA.offsets[1:]
    else:
        a_lo = np.zeros(P, np.int64)
        a_hi = np.full(P, len(RA.coords), np.int64)
    if many_b:
        b_lo, b_hi = RB.offsets[:-1], RB.offsets[1:]
    else:
        b_lo = np.zeros(P, np.int64)
        b_hi = np.full(P, len(RB.coords), np.int64)
    return RA, a_lo, a_hi, RB, b_lo, b_hi, P, ("As" if many_a else "a", "Bs" if many_b else "b")


@overload
def minkowski_sum_many(
    As: Ragged | Sequence[ArrayLike2],
    Bs: Ragged | Sequence[ArrayLike2] | Sequence[Sequence[Coordinate]] | GeometryLike,
    *,
    threads: int = 1,
    progress: ProgressLike = None,
) -> Ragged: ...
@overload
def minkowski_sum_many(
    As: PolygonsLike, Bs: PolygonsLike, *, threads: int = 1, progress: ProgressLike = None
) -> Any: ...
def minkowski_sum_many(
    As: PolygonsLike, Bs: PolygonsLike, *, threads: int = 1, progress: ProgressLike = None
) -> Any:
    """Minkowski sums of many pairs of convex polygons in one call.

    Parameters
    ----------
    As, Bs : Ragged, sequence of (n, 2) array_like, GeoSeries, GeometryArray, numpy
        object array of shapely geometries, or one polygon
        Pairwise (equal counts) or one-against-many (one side a single polygon, which is
        broadcast).
    threads : int, default 1
        Worker threads for the compiled kernel (the GIL is released); results are
        identical for every value (see ``docs/scale-out.md`` for measured speed-ups).
    progress : None, True or callable, keyword-only
        ``True`` draws a tqdm progress bar on stderr; a callable is called as
        ``cb(done, total)`` after each of about 64 chunks of pairs, last with
        ``done == total``.

    Returns
    -------
    Ragged, GeoSeries, GeometryArray or object ndarray
        Sum ``k`` is ``As[k] ⊕ Bs[k]``, exactly what :func:`minkowski_sum` returns for that
        pair. Lists and Raggeds give a ``Ragged``; a container of shapely geometries
        gives the same kind of container back (a GeoSeries keeps its index and CRS, an
        object array its shape) holding shapely geometries; a ``None`` member gives
        ``None``, an empty one an empty polygon.

    Raises
    ------
    NotConvexError
        Naming the polygon (``As[k]``; for a GeoSeries ``k`` is its index label) and
        its vertex.
    ShapeError, EmptyGeometryError, NonFiniteError
        Bad input, or unequal counts.
    OverflowGeometryError
        A float result coordinate would be infinite.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> tri = [(0, 0), (2, 0), (0, 2)]
    >>> r = mk.minkowski_sum_many([tri, tri], [[(0, 0), (1, 0), (1, 1), (0, 1)], [(3, 3)]])
    >>> r[0].tolist()
    [[0, 0], [3, 0], [3, 1], [1, 3], [0, 3]]
    >>> r[1].tolist()
    [[3, 3], [5, 3], [3, 5]]
    >>> import geopandas, shapely
    >>> gs = geopandas.GeoSeries([shapely.box(0, 0, 2, 1), None], index=[7, 9], crs=3857)
    >>> out = mk.minkowski_sum_many(gs, [(0, 0), (1, 1)])
    >>> out.index.tolist(), out.crs.to_epsg(), out[7].wkt, out[9]
    ([7, 9], 3857, 'POLYGON ((0 0, 2 0, 3 1, 3 2, 1 2, 0 1, 0 0))', None)
    """
    threads = _options.threads(threads)
    if progress is not None or boxed(As) or boxed(Bs):
        return apply(partial(minkowski_sum_many, threads=threads), As, Bs, progress=progress)
    RA, a_lo, a_hi, RB, b_lo, b_hi, P, names = as_ragged_pair(As, Bs)
    ca, cb = RA.coords, RB.coords
    ka = "i" if ca.dtype.kind in "iu" else "f"
    kb = "i" if cb.dtype.kind in "iu" else "f"
    if ka == kb == "i":
        path = "i"  # the core's first pass checks the range (RANGE: the exact path)
    else:
        ints = [c for c, k in ((ca, ka), (cb, kb)) if k == "i"]
        path = (
            "f"
            if all(c.size == 0 or int(np.abs(c).max()) <= core.FLOAT_EXACT_INT for c in ints)
            else "py"
        )
    if path == "py":
        return _exact_pairs(ca, a_lo, a_hi, cb, b_lo, b_hi)
    dt = np.int64 if path == "i" else np.float64
    pa = np.ascontiguousarray(ca, dtype=dt)
    pb = pa if cb is ca else np.ascontiguousarray(cb, dtype=dt)
    fn = core.sum_batch_i if path == "i" else core.sum_batch_f
    a_lo = np.ascontiguousarray(a_lo, np.int64)
    a_hi = np.ascontiguousarray(a_hi, np.int64)
    b_lo = np.ascontiguousarray(b_lo, np.int64)
    b_hi = np.ascontiguousarray(b_hi, np.int64)
    coords, off, code, q, which, v = fn(pa, a_lo, a_hi, pb, b_lo, b_hi, threads)
    if code:
        nm = names[which] if which < 2 else "result"
        if which < 2 and nm in ("As", "Bs"):
            nm = f"{nm}[{q}]"
        if code == D.Status.RANGE:
            return _exact_pairs(ca, a_lo, a_hi, cb, b_lo, b_hi)
        raise D.status_error(code, v, nm)
    return Ragged(coords, off)


def _exact_pairs(
    ca: np.ndarray,
    a_lo: np.ndarray,
    a_hi: np.ndarray,
    cb: np.ndarray,
    b_lo: np.ndarray,
    b_hi: np.ndarray,
) -> Ragged:
    """Pair by pair through minkowski_sum (ints beyond the core's range)."""
    from .convex import minkowski_sum

    res = [minkowski_sum(ca[a_lo[q] : a_hi[q]], cb[b_lo[q] : b_hi[q]]) for q in range(len(a_lo))]
    if not res:
        return Ragged(np.empty((0, 2), ca.dtype), np.zeros(1, np.int64))
    return Ragged.from_list(res)
