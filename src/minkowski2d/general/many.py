"""Many general sums at once: :func:`minkowski_sum_general_many`."""

from __future__ import annotations

from collections.abc import Callable
from functools import partial
from typing import Any

import numpy as np

from .._engine import options as _options
from .._engine.containers import is_many
from ..batch import Ragged
from ..errors import (
    GeometryError,
    ShapeError,
)
from .operands import SUM_METHODS
from .sums import (
    _Prepared,
    _sums,
    minkowski_sum_general,
)

# --------------------------------------------------------------------------------------
# many sums at once


def _many_operands(X: Any) -> tuple[list, bool]:
    """The operands of a batch argument and whether it is a collection (else broadcast);
    what a collection is: :func:`minkowski2d._engine.containers.is_many`."""
    if not is_many(X):
        return [X], False
    return (X.to_list() if isinstance(X, Ragged) else list(X)), True


def minkowski_sum_general_many(
    As: Any,
    Bs: Any,
    *,
    method: str = "auto",
    progress: Any = None,
    threads: int = 1,
) -> np.ndarray:
    """Non-convex Minkowski sums of many pairs of polygons in one call.

    Parameters
    ----------
    As, Bs : sequence of operands, or one operand
        Pairwise (equal counts) or one against many (one side a single operand, which is
        broadcast). An operand is anything :func:`minkowski_sum_general` takes; ``None``
        gives ``None``. A sequence whose items are rings or shapely geometries is a
        collection of operands (one sum per item), unlike in
        :func:`minkowski_sum_general`, where a list of polygons is one operand.
    method : {"auto", "decomposition", "convolution"}
        ``"auto"``: per pair, the core's choice (the convolution while it has at most a
        few segments per input vertex, else the pieces; as :func:`minkowski_sum_general`
        unset). The other values force one method for every pair.
    progress : bool or callable, optional
        ``True`` shows a tqdm bar (when tqdm is installed) over the pairs; a callable is
        called as ``progress(done, total)`` after each chunk of pairs.
    threads : int, default 1
        Worker threads of the batched convex sums.

    Returns
    -------
    numpy.ndarray of object
        ``result[k]`` is ``minkowski_sum_general(As[k], Bs[k])`` (a Polygon or
        MultiPolygon, the same vertices: both methods give the correctly rounded exact
        vertices).

    Raises
    ------
    GeometryError
        As :func:`minkowski_sum_general`, naming the operand (``As[k]``, ``Bs[k]``).
    ShapeError
        Unequal counts, or neither argument is a collection.

    Notes
    -----
    Every distinct operand (the same Python object passed several times counts once) is
    read and validated once and put in one table with its convex pieces; each chunk of
    pairs is one compiled call (``threads`` splits the pairs): per pair the method, the
    sums and the exact overlay, rings out. Python only builds the shapely results.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> L = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    >>> sq = [(0, 0), (1, 0), (1, 1), (0, 1)]
    >>> out = mk.minkowski_sum_general_many([L, sq], L)
    >>> [g.area for g in out]
    [13.0, 8.0]
    """
    method = _options.choice(method, "method", ("auto", *SUM_METHODS))
    threads = _options.threads(threads)
    progress = _options.progress(progress)
    from .._engine.containers import apply, boxed

    if boxed(As) or boxed(Bs):
        # GeoSeries / GeometryArray / object arrays: the same container kind out
        run = partial(minkowski_sum_general_many, method=method, threads=threads)
        return apply(run, As, Bs, progress=progress, convex=False)
    la, many_a = _many_operands(As)
    lb, many_b = _many_operands(Bs)
    if not many_a and not many_b:
        raise ShapeError(
            "give a collection of polygons for As or Bs (or use minkowski_sum_general)",
            argument="As, Bs",
        )
    if many_a and many_b and len(la) != len(lb):
        raise ShapeError(
            f"As has {len(la)} polygons but Bs has {len(lb)}; pairs need equal counts",
            argument="As, Bs",
        )
    P = len(la) if many_a else len(lb)
    preps, todo, ia, ib, names = _pairs(la, lb, many_a, many_b, P)
    out = np.empty(P, dtype=object)
    m = None if method == "auto" else method
    bar = _progress_bar(progress, len(todo))
    try:
        step = max(1, -(-len(todo) // 64)) if progress else max(1, len(todo))
        A_, B_ = np.asarray(ia, np.int64), np.asarray(ib, np.int64)
        for s in range(0, len(todo), step):
            sel = slice(s, s + step)
            res = _sums(preps, A_[sel], B_[sel], names[sel], m, threads=threads)
            for q, g in zip(todo[sel], res, strict=True):
                out[q] = g
            bar(len(res))
    finally:
        bar(None)
    return out


def _pairs(la: list, lb: list, many_a: bool, many_b: bool, P: int) -> tuple:
    """Each distinct operand read once (the same Python object counts once): ``(preps,
    todo, ia, ib, names)``, the pairs to sum (``None`` on a side: skipped) as indices into
    ``preps`` with the names their errors use (``As[k]``, or ``a`` when broadcast)."""
    na = (lambda q: f"As[{q}]") if many_a else (lambda q: "a")
    nb = (lambda q: f"Bs[{q}]") if many_b else (lambda q: "b")
    ga = (lambda q: la[q]) if many_a else (lambda q: la[0])
    gb = (lambda q: lb[q]) if many_b else (lambda q: lb[0])
    index: dict[int, int] = {}
    preps: list[_Prepared] = []

    def prep(obj: Any, name: str) -> int:
        key = id(obj)
        if key not in index:
            index[key] = len(preps)
            preps.append(_Prepared(obj, name))
        return index[key]

    todo, ia, ib, names = [], [], [], []
    for q in range(P):
        a, b = ga(q), gb(q)
        if a is None or b is None:
            continue
        i, j = prep(a, na(q)), prep(b, nb(q))
        if preps[i].flat and preps[j].flat:
            raise ShapeError(
                f"{na(q)}, {nb(q)}: both operands are points or segments: the sum has no area",
                argument=f"{na(q)}, {nb(q)}",
            )
        todo.append(q)
        ia.append(i)
        ib.append(j)
        names.append((na(q), nb(q)))
    return preps, todo, ia, ib, names


def _single(a: Any, b: Any, name_a: str, name_b: str, method: str | None = None) -> Any:
    """:func:`minkowski_sum_general` of one pair of a batch; errors name the batch
    operands (``As[k]``, ``Bs[k]``) instead of ``a`` and ``b``."""
    try:
        return minkowski_sum_general(a, b, method=method)
    except GeometryError as exc:
        arg = exc.argument or ""
        ren = {"a": name_a, "b": name_b, "a, b": f"{name_a}, {name_b}"}
        if arg in ren:
            raise exc.renamed(ren[arg]) from exc
        raise


def _progress_bar(progress: Any, total: int) -> Callable[[int | None], Any]:
    """``update(n)`` (``None`` closes) for a tqdm bar, a callable, or nothing."""
    if progress is None or progress is False:
        return lambda n: None
    if callable(progress) and progress is not True:
        state = [0]

        def call(n):
            if n is not None:
                state[0] += n
                progress(state[0], total)

        return call
    try:
        from tqdm.auto import tqdm
    except ImportError:  # pragma: no cover - tqdm is optional
        return lambda n: None
    t = tqdm(total=total, unit="pair", leave=False)
    return lambda n: t.close() if n is None else t.update(n)
