"""The layout optimizer: :func:`nest` places copies of parts on a strip or on sheets.

1. **Construction** (:func:`_construct`, in the core): the parts, largest first, each
   at the point of its feasible region (the inner-fit rectangle minus the no-fit
   polygons of the parts already placed, decided by exact signs) that ends furthest
   left, found among samples and the vertices of its NFPs with its neighbours (touching
   placements), then pushed left and down; the holes of an NFP are free, so a small part
   goes into a large part's hole when that is where it fits. Milliseconds for the
   classic instances.
2. **Improvement** (the compiled core, ``_core/nest.hpp``): the strip (or the last
   sheet) shrinks by a ratio, the parts that no longer fit are reinserted, and a guided
   local search moves colliding parts to the position of least weighted penetration
   depth until no two overlap; a success is the new best, a failure shrinks the ratio.
   For sheets the search first tries to empty the last sheet. ``threads`` searches run
   side by side from the same layout (the lowest-numbered success wins, so a fixed seed
   and an iteration budget give the same layout).
3. **Compaction** (:func:`_compact`): each part, rightmost first, moves to the vertex
   of its exact feasible region that ends furthest left (one exact overlay, the
   inner-fit rectangle minus the union of the translated NFPs, per part and orientation).
4. **Certificate**: the layout is checked by :func:`~minkowski2d.nesting.verify.verify_layout`
   on the parts themselves (exact, trusting no NFP); only a verified layout is returned.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from .._engine import options as _options
from ..errors import GeometryError, OptionError
from .problem import Problem, _polygon, build_problem

__all__ = ["nest"]

#: Shrink ratios of the strip in the exploration: the first step, and the smallest.
RATIO_START = 0.02
#: The separator's settings (_core/nest.hpp Params): samples over the container, near
#: the part and at NFP vertices; candidates refined; strikes; rounds without improvement;
#: rounds per separation; the least overlap penalty and the last descent step (relative
#: to the part's size).
SEARCH_PARAMS = {
    "container_samples": 50,
    "focus_samples": 25,
    "vertex_samples": 16,
    "refine_top": 3,
    "max_strikes": 3,
    "max_no_improve": 40,
    "max_rounds": 4000,
    "floor_rel": 0.02,
    "min_step_rel": 5e-4,
}
#: Samples per part of the construction (half uniform, half NFP vertices).
CONSTRUCT_SAMPLES = 400
RATIO_MIN = 0.001
#: Separations retried (from disrupted failures) at one target length before the step halves.
MAX_RETRIES = 8
#: The share of the budget spent exploring; the rest compresses by ratios shrinking
#: (geometrically, with the time) through COMPRESS_RANGE, reverting on failure.
EXPLORE_SHARE = 0.8
#: Sheets: after three failures to empty the last sheet, one more try every this many
#: attempts (the others shrink the last sheet's used length).
CLOSE_EVERY = 6
#: The share of the budget kept for the final exact compaction.
COMPACT_SHARE = 0.05
COMPRESS_RANGE = (0.0005, 0.00001)


def _read_parts(parts: Any, quantities: Any, rotations: Any) -> tuple:
    """(parts, quantities, rotations, ids, strip height or None, name) from a list of
    polygons or an instance of :func:`~minkowski2d.read_esicup`."""
    height = None
    name = None
    ids = None
    if isinstance(parts, dict) and "parts" in parts:
        inst = parts
        parts = inst["parts"]
        quantities = inst.get("quantities") if quantities is None else quantities
        rotations = inst.get("rotations") if rotations is None else rotations
        height = (inst.get("strip") or {}).get("height")
        ids = inst.get("ids")
        name = inst.get("name")
    if hasattr(parts, "geometry") and hasattr(parts, "values"):
        parts = list(parts.geometry.values)
    seq = _options.sequence(parts, "parts", "a sequence of polygons")
    if not seq:
        raise OptionError("parts: no part to nest", argument="parts", allowed="at least one part")
    polys = [_polygon(p, f"parts[{i}]") for i, p in enumerate(seq)]
    n = len(polys)
    if quantities is None:
        qty = [1] * n
    else:
        qs = _options.sequence(quantities, "quantities", "one count per part")
        if len(qs) != n:
            raise OptionError(
                f"quantities: {len(qs)} counts for {n} parts",
                argument="quantities",
                allowed=f"one int >= 0 per part ({n})",
            )
        qty = []
        for i, q in enumerate(qs):
            if not _options.is_int(q) or int(q) < 0:
                raise OptionError(
                    f"quantities[{i}]: must be an int >= 0, got {q!r}",
                    argument=f"quantities[{i}]",
                    allowed="an int >= 0",
                )
            qty.append(int(q))
    from .nfp import _rotations_per_part

    rot = _rotations_per_part((0,) if rotations is None else rotations, n)
    ids = [str(i) for i in range(n)] if ids is None else [str(v) for v in ids]
    return polys, qty, rot, ids, height, name


def _check_fit(pb: Problem) -> None:
    """Every part fits some sheet in some orientation (else a GeometryError naming it)."""
    m = pb.margin
    for i in range(len(pb.parts)):
        if pb.quantities[i] == 0:
            continue
        ok = False
        for k in range(len(pb.rotations[i])):
            x0, y0, x1, y1 = pb.box[pb.ot_of[(i, k)]]
            for b in pb.bins:
                if x1 - x0 + 2 * m <= b.width and y1 - y0 + 2 * m <= b.height:
                    ok = True
        if not ok:
            where = "the strip" if pb.strip_height is not None else "any sheet"
            raise GeometryError(
                f"parts[{i}] ({pb.ids[i]}): larger than {where} in every allowed rotation",
                argument=f"parts[{i}]",
                hint="allow more rotations, or use a larger sheet or a smaller margin",
            )


# --------------------------------------------------------------------------------------
# the compiled search


def _engine(pb: Problem) -> Any:
    from .._engine import core

    T = pb.nfps
    ref = np.sqrt(np.maximum(pb.area, 1e-300))
    ots, ots_off, fixed = [], [0], []
    items = pb.items
    for it, (i, _) in enumerate(items):
        if it in pb.fixed_items:
            ots.append(pb.fixed_items[it][1])
            fixed.append(1)
        else:
            ots.extend(pb.ot_of[(i, k)] for k in range(len(pb.rotations[i])) if (i, k) in pb.ot_of)
            fixed.append(0)
        ots_off.append(len(ots))
    for _, ot in pb.obstacle_items:
        ots.append(ot)
        fixed.append(1)
        ots_off.append(len(ots))
    eng = core.Nester(
        np.ascontiguousarray(pb.box.reshape(-1), np.float64),
        np.ascontiguousarray(ref, np.float64),
        T.xy,
        T.ring_off,
        T.nring,
        np.ascontiguousarray(T.nbox.reshape(-1)),
        np.asarray(ots, np.int64),
        np.asarray(ots_off, np.int64),
        np.asarray(fixed, np.uint8),
        np.asarray([b.width for b in pb.bins], np.float64),
        np.asarray([b.height for b in pb.bins], np.float64),
        float(pb.margin),
        float(pb.grid),
        pb.gap == 0,
    )
    eng.set_params(*SEARCH_PARAMS.values())
    return eng


class _Sol:
    """A layout of the search: per engine item (parts' items, then obstacles) its bin,
    orientation and translation, and each bin's length limit."""

    def __init__(self, bin_, ot, x, y, length, used):
        self.bin, self.ot, self.x, self.y = (np.array(v) for v in (bin_, ot, x, y))
        self.length = np.array(length, dtype=np.float64)
        self.used = int(used)

    @classmethod
    def empty(cls, pb: Problem, n_engine: int, obstacle_ids: list, unplaced: int) -> _Sol:
        """Every part on bin ``unplaced`` at the origin, the obstacles on their bins."""
        sol = cls(
            [unplaced] * n_engine,
            [0] * n_engine,
            [0.0] * n_engine,
            [0.0] * n_engine,
            [b.width for b in pb.bins],
            1,
        )
        for z, (b, ot) in enumerate(pb.obstacle_items):
            sol.bin[obstacle_ids[z]], sol.ot[obstacle_ids[z]] = b, ot
        return sol

    @classmethod
    def of(cls, eng: Any) -> _Sol:
        return cls(*eng.state())

    def load(self, eng: Any) -> None:
        eng.set_state(
            self.bin.astype(np.int64), self.ot.astype(np.int64),
            self.x.astype(np.float64), self.y.astype(np.float64),
            self.length.astype(np.float64), self.used,
        )  # fmt: skip


def _used_length(pb: Problem, sol: _Sol, b: int) -> float:
    """The x extent the parts of bin b take (plus the margin), on the grid."""
    n = len(pb.items)
    sel = [i for i in range(n) if sol.bin[i] == b]
    if not sel:
        return 0.0
    ext = max(sol.x[i] + pb.box[sol.ot[i], 2] for i in sel) + pb.margin
    return math.ceil(ext / pb.grid) * pb.grid


# --------------------------------------------------------------------------------------
# exact construction and compaction


def _feasible_region(
    pb: Problem, sol: _Sol, item: int, ot: int, b: int, L: float, others: Sequence[int]
) -> Any:
    """The translations of item (orientation ot) inside bin b of length L overlapping no
    item of ``others``: the inner-fit rectangle minus the union of the translated NFPs
    (exact overlay)."""
    from .._engine.overlay import overlay

    m = pb.margin
    x0, y0, x1, y1 = pb.box[ot]
    bh = pb.bins[b].height
    fx0, fy0, fx1, fy1 = m - x0, m - y0, L - m - x1, bh - m - y1
    if fx0 > fx1 or fy0 > fy1:
        return None
    rect = np.array([[fx0, fy0], [fx1, fy0], [fx1, fy1], [fx0, fy1]], np.float64)
    rings, layers = [rect], [0]
    n_ot = len(pb.ot_part)
    for j in others:
        if j == item or sol.bin[j] != b:
            continue
        rs = pb.nfps.rings(int(sol.ot[j]) * n_ot + ot)
        if not rs:
            continue
        jx0, jy0, jx1, jy1 = pb.box[int(sol.ot[j])]
        tx, ty = float(sol.x[j]), float(sol.y[j])
        for r in rs:
            rr = r + (tx, ty)
            if rr[:, 0].max() <= fx0 or rr[:, 0].min() >= fx1:
                continue
            if rr[:, 1].max() <= fy0 or rr[:, 1].min() >= fy1:
                continue
            rings.append(rr)
            layers.append(1)
    if len(rings) == 1:
        import shapely

        return shapely.Polygon(rect)
    # NFP rings come normalized (exteriors counter-clockwise, holes clockwise), so
    # their winding numbers are 1 inside and 0 in their holes
    return overlay(rings, layers=layers, rule="difference")


def _vertices(g: Any, key: Callable, tiny: float = 0.0) -> np.ndarray:
    """The vertices of g's polygons of area above ``tiny`` (slivers the safety gap leaves
    are no room), best first by (key, y)."""
    import shapely

    if g is None or g.is_empty:
        return np.empty((0, 2))
    parts = shapely.get_parts(g)
    parts = parts[shapely.area(parts) > tiny]
    if len(parts) == 0:
        return np.empty((0, 2))
    pts = shapely.get_coordinates(parts)
    return pts[np.lexsort((pts[:, 1], key(pts)))]


_DIRS = [(0, 0), (1, 0), (0, 1), (1, 1), (-1, 1), (1, -1), (-1, 0), (0, -1), (-1, -1)]


def _settle(pb: Problem, eng: Any, it: int, b: int, ot: int, v: Any, L: float) -> tuple | None:
    """A grid point at or next to v (a rounded vertex of a feasible region) that the
    engine's exact test finds free, inside the bin; None when the nearest few are not."""
    g = pb.grid
    m = pb.margin
    x0, y0, x1, y1 = pb.box[ot]
    lo_x, hi_x = m - x0, L - m - x1
    lo_y, hi_y = m - y0, pb.bins[b].height - m - y1
    bx, by = round(v[0] / g) * g, round(v[1] / g) * g
    for k in range(0, 30, 3):
        d = g * 2.0**k
        for dx, dy in _DIRS if k else _DIRS[:1] + _DIRS[1:]:
            x, y = bx + dx * d, by + dy * d
            if not (lo_x <= x <= hi_x and lo_y <= y <= hi_y):
                continue
            if eng.probe(it, b, ot, x, y) == 0:
                return x, y
    return None


def _place_best(
    pb: Problem,
    eng: Any,
    sol: _Sol,
    it: int,
    b: int,
    L: float,
    others: Sequence[int],
    tries: int = 12,
) -> tuple | None:
    """(right end, y, ot, x, y) of the best settled bottom-left vertex of item it."""
    i = pb.items[it][0]
    cands = []
    for k in range(len(pb.rotations[i])):
        ot = pb.ot_of[(i, k)]
        F = _feasible_region(pb, sol, it, ot, b, L, others)
        x1 = pb.box[ot, 2]
        tiny = pb.gap * math.sqrt(pb.area[ot])
        for v in _vertices(F, lambda p, x1=x1: p[:, 0] + x1, tiny)[:tries]:
            cands.append((v[0] + x1, v[1], ot, v))
    cands.sort(key=lambda c: c[:2])
    for c in cands[: tries * 2]:
        s = _settle(pb, eng, it, b, c[2], c[3], L)
        if s is not None:
            return (s[0] + pb.box[c[2], 2], s[1], c[2], s[0], s[1])
    return None


def _construct(
    pb: Problem,
    eng: Any,
    n_engine: int,
    obstacle_ids: list,
    seed: int,
    samples: int = CONSTRUCT_SAMPLES,
) -> _Sol:
    """The construction in the core: parts by decreasing area, each on the first bin
    where it fits, at the free position (exact test on the NFPs) that ends furthest
    left, among samples and the vertices of its NFPs with the parts already placed."""
    n = len(pb.items)
    sol = _Sol.empty(pb, n_engine, obstacle_ids, unplaced=-1)
    for it, (b, ot, x, y) in pb.fixed_items.items():
        sol.bin[it], sol.ot[it], sol.x[it], sol.y[it] = b, ot, x, y
        sol.used = max(sol.used, b + 1)
    for it in range(n):
        if sol.bin[it] < 0:
            sol.ot[it] = pb.ot_of[(pb.items[it][0], 0)]
    order = sorted(
        (it for it in range(n) if it not in pb.fixed_items),
        key=lambda it: (-pb.parts[pb.items[it][0]].area, pb.items[it]),
    )
    sol.load(eng)
    failed = eng.construct(np.asarray(order, np.int64), seed, samples)
    if failed >= 0:
        it = order[failed]
        i = pb.items[it][0]
        raise GeometryError(
            f"parts[{i}] ({pb.ids[i]}): no room found for copy {pb.items[it][1]} on the "
            f"{len(pb.bins)} sheet(s) given",
            argument=f"parts[{i}]",
            hint="give more sheets (a (sheet, count) pair), or fewer copies",
        )
    out = _Sol.of(eng)
    out.used = int(max(out.bin[:n].max() + 1, sol.used))
    if pb.strip_height is not None:
        out.length[0] = _used_length(pb, out, 0)
    return out


def _compact(pb: Problem, eng: Any, sol: _Sol, deadline: float) -> _Sol:
    """Each part of the last bin, rightmost first, to the vertex of its exact feasible
    region (any orientation) that ends furthest left, when that is further left."""
    b = sol.used - 1
    n = len(pb.items)
    L = float(sol.length[b])
    everyone = list(range(len(sol.bin)))
    order = sorted(
        (i for i in range(n) if sol.bin[i] == b and i not in pb.fixed_items),
        key=lambda i: -(sol.x[i] + pb.box[sol.ot[i], 2]),
    )
    for it in order:
        if time.monotonic() > deadline:
            break
        cur = sol.x[it] + pb.box[sol.ot[it], 2]
        keep = sol.bin[it]
        sol.bin[it] = -1  # not in its own way
        sol.load(eng)
        sol.bin[it] = keep
        best = _place_best(pb, eng, sol, it, b, L, everyone)
        if best is not None and best[0] < cur:
            sol.ot[it], sol.x[it], sol.y[it] = best[2], best[3], best[4]
    sol.length[b] = min(L, _used_length(pb, sol, b))
    return sol


# --------------------------------------------------------------------------------------
# the driver


def _layout(pb: Problem, sol: _Sol, name: Any) -> Any:
    import shapely

    from .layout import Layout, Placement

    places = []
    for it, (i, c) in enumerate(pb.items):
        ot = int(sol.ot[it])
        k = next(k for k in range(len(pb.rotations[i])) if pb.ot_of.get((i, k)) == ot)
        b = int(sol.bin[it])
        ox, oy = pb.bins[b].origin
        places.append(
            Placement(part=i, copy=c, sheet=b, rotation=pb.rotations[i][k],
                      translation=(float(sol.x[it]) + ox, float(sol.y[it]) + oy),
                      fixed=it in pb.fixed_items)
        )  # fmt: skip
    if pb.strip_height is not None:
        L = float(sol.length[0])
        sheets = [shapely.box(0, 0, L, pb.strip_height)]
        kinds = None
    else:
        used = sorted({p.sheet for p in places})
        remap = {b: k for k, b in enumerate(used)}
        places = [
            Placement(p.part, p.copy, remap[p.sheet], p.rotation, p.translation, p.fixed)
            for p in places
        ]
        sheets = [pb.bins[b].polygon for b in used]
        kinds = [pb.bins[b].kind for b in used]
    return Layout(
        pb.parts, places, sheets, kinds=kinds, strip_height=pb.strip_height,
        spacing=pb.spacing, margin=pb.margin, ids=pb.ids, name=name,
    )  # fmt: skip


def _density(pb: Problem, sol: _Sol) -> float:
    total = sum(pb.parts[i].area for i, _ in pb.items)
    if pb.strip_height is not None:
        return total / (float(sol.length[0]) * pb.strip_height)
    area = sum(pb.bins[b].polygon.area for b in range(sol.used - 1))
    area += float(sol.length[sol.used - 1]) * pb.bins[sol.used - 1].height
    return total / area


class _Progress:
    def __init__(self, progress: Any, callback: Any, total: float | None):
        self.bar = None
        self.cb = callback
        if progress is True:
            from tqdm.auto import tqdm

            self.bar = tqdm(total=total, unit="s" if total else "it", desc="nest")
        self.fn = progress if callable(progress) else None
        self.last = 0.0

    def step(self, done: float, density: float) -> None:
        if self.bar is not None:
            self.bar.update(done - self.last)
            self.bar.set_postfix(density=f"{100 * density:.2f}%")
        self.last = done

    def improved(self, layout_fn: Callable, density: float) -> None:
        if self.cb is not None:
            self.cb(layout_fn())
        if self.fn is not None:
            self.fn(density)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()


def nest(
    parts: Any,
    *,
    quantities: Sequence[int] | None = None,
    rotations: Any = None,
    height: float | None = None,
    sheets: Sequence[Any] | None = None,
    spacing: float = 0,
    margin: float = 0,
    time_limit: float | None = 10.0,
    iterations: int | None = None,
    threads: int = 1,
    seed: int = 0,
    progress: Any = None,
    callback: Callable[[Any], None] | None = None,
    initial: Any = None,
    fixed: Sequence[Any] | None = None,
) -> Any:
    """Place copies of parts on a strip (minimise its length) or on sheets (minimise the
    sheets used, then the length used on the last one), without overlap.

    Parameters
    ----------
    parts : sequence of polygons, GeoSeries, or an instance of :func:`~minkowski2d.read_esicup`
        Each an (n, 2) ring or a shapely Polygon (holes allowed: smaller parts may go
        into them). An instance gives its parts, quantities, rotations and strip height.
    quantities : sequence of int, optional
        Copies of each part (default one each, or the instance's).
    rotations : sequence of angles, or one sequence per part, optional
        Allowed rotations in degrees (default ``(0,)``, or the instance's); multiples of
        90 are exact.
    height : float, optional
        Strip packing: the strip's fixed height; its length is minimised.
    sheets : sequence, optional
        Bin packing instead: each entry a sheet ``(W, H)``, a polygon (its holes are
        keep-out zones), or a ``(sheet, count)`` pair for many of one kind.
    spacing : float, default 0
        Every two parts at least this far apart (guaranteed and certified).
    margin : float, default 0
        Every part at least this far inside its sheet (and from its keep-out zones).
    time_limit : float or None, default 10
        Wall seconds, preparation included (None: only ``iterations`` bounds the run).
    iterations : int, optional
        A budget of search attempts; with a fixed ``seed`` and no time limit the same
        layout every time.
    threads : int, default 1
        Searches run side by side (GIL released).
    seed : int, default 0
    progress : bool or callable, optional
        ``True``: a tqdm bar showing the best density; a callable: called with the best
        density on each improvement.
    callback : callable, optional
        Called with the new best :class:`~minkowski2d.nesting.layout.Layout` (not yet
        certified) on each improvement.
    initial : Layout, optional
        A warm start: the search starts from its placements.
    fixed : sequence of Placement, optional
        Pre-placed parts (each one copy of its part), never moved.

    Returns
    -------
    Layout
        Verified by :meth:`Layout.verify`: no two parts overlap, every part inside its
        sheet, spacing and margin kept (exact).

    Raises
    ------
    GeometryError
        A part is not a valid polygon, or larger than every sheet (naming ``parts[i]``);
        the parts need more sheets than given.
    OptionError
        A bad option (negative spacing, no height nor sheets, ...).

    Examples
    --------
    >>> import minkowski2d as mk
    >>> L = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    >>> lay = mk.nest([L], quantities=[2], rotations=[0, 180], height=2,
    ...               time_limit=None, iterations=50)
    >>> lay.length, lay.density
    (3.0, 1.0)
    """
    t0 = time.monotonic()
    polys, qty, rot, ids, inst_h, name = _read_parts(parts, quantities, rotations)
    if sheets is None and height is None:
        height = inst_h
    if (sheets is None) == (height is None):
        raise OptionError(
            "height, sheets: give exactly one (a strip height, or a list of sheets)",
            argument="height" if sheets is None else "sheets",
            allowed="height=H for a strip, or sheets=[(W, H), ...]",
        )
    spacing, margin, time_limit, iterations, threads, seed = _budget(
        spacing, margin, time_limit, iterations, threads, seed, progress
    )
    fixed_list = list(fixed or [])
    if sum(qty) == 0:
        raise OptionError(
            "quantities: no copy of any part to place",
            argument="quantities",
            allowed="at least one copy",
        )
    pb = build_problem(
        polys,
        qty,
        rot,
        height=height,
        sheets=sheets,
        spacing=spacing,
        margin=margin,
        ids=ids,
        fixed=fixed_list,
        threads=threads,
    )
    _check_fit(pb)
    deadline = math.inf if time_limit is None else t0 + time_limit
    eng, sol = _start(pb, initial, deadline, seed, threads)
    return _improve(
        pb, eng, sol, deadline, iterations, threads, seed, progress, callback, name, time_limit
    )


def _budget(
    spacing: Any,
    margin: Any,
    time_limit: Any,
    iterations: Any,
    threads: Any,
    seed: Any,
    progress: Any,
) -> tuple:
    """The numeric options, checked (each a specific OptionError naming it)."""
    spacing = _nonneg(spacing, "spacing")
    margin = _nonneg(margin, "margin")
    if time_limit is not None:
        time_limit = float(_options.real(time_limit, "time_limit"))
        if not time_limit > 0:
            raise OptionError(
                f"time_limit: must be > 0, got {time_limit!r}",
                argument="time_limit",
                allowed="seconds > 0, or None",
            )
    if iterations is not None:
        iterations = _options.integer(iterations, "iterations", 0)
    if time_limit is None and iterations is None:
        raise OptionError(
            "time_limit, iterations: one of them must bound the run",
            argument="time_limit",
            allowed="seconds > 0, or iterations=N",
        )
    threads = _options.threads(threads)
    seed = _options.integer(seed, "seed", 0)
    _options.progress(progress)
    return spacing, margin, time_limit, iterations, threads, seed


def _start(pb: Problem, initial: Any, deadline: float, seed: int, threads: int) -> tuple:
    """The engine and the first feasible layout (the warm start, or the construction)."""
    eng = _engine(pb)
    n = len(pb.items)
    obstacle_ids = list(range(n, n + len(pb.obstacle_items)))
    sol = _warm(pb, initial, n + len(obstacle_ids), obstacle_ids) if initial is not None else None
    if sol is None:
        sol = _construct(pb, eng, n + len(obstacle_ids), obstacle_ids, seed)
    sol.load(eng)
    feasible_total, _ = eng.overlap()
    if feasible_total > 0:  # a warm start with overlaps, or a rounding at a contact
        remaining = deadline - time.monotonic()
        ok, _ = eng.attempt(2, 0.0, seed, threads, max(remaining, 1e-3))
        if not ok:
            raise GeometryError(
                "initial: no feasible layout found from it",
                argument="initial",
                hint="give more time, or no initial layout",
            )
        sol = _Sol.of(eng)
    return eng, sol


def _nonneg(v: Any, name: str) -> float:
    x = float(_options.real(v, name))
    if not (x >= 0) or not math.isfinite(x):
        raise OptionError(
            f"{name}: must be a finite number >= 0, got {v!r}",
            argument=name,
            allowed="a number >= 0",
        )
    return x


def _warm(pb: Problem, initial: Any, n_engine: int, obstacle_ids: list) -> _Sol | None:
    """The search state of a warm start (placements matched by part and copy)."""
    places = getattr(initial, "placements", initial)
    sol = _Sol.empty(pb, n_engine, obstacle_ids, unplaced=0)
    index = {key: it for it, key in enumerate(pb.items)}
    seen = set()
    for k, p in enumerate(places):
        it = index.get((p.part, p.copy))
        if it is None or it in pb.fixed_items:
            continue
        ks = [
            q
            for q in range(len(pb.rotations[p.part]))
            if _same(pb.rotations[p.part][q], p.rotation)
        ]
        if not ks or not 0 <= p.sheet < len(pb.bins):
            raise OptionError(
                f"initial: placements[{k}] has a rotation or sheet not allowed",
                argument="initial",
                allowed="placements of this problem",
            )
        ox, oy = pb.bins[p.sheet].origin
        sol.bin[it], sol.ot[it] = p.sheet, pb.ot_of[(p.part, ks[0])]
        sol.x[it] = round((p.translation[0] - ox) / pb.grid) * pb.grid
        sol.y[it] = round((p.translation[1] - oy) / pb.grid) * pb.grid
        sol.used = max(sol.used, p.sheet + 1)
        seen.add(it)
    for it, (b, ot, x, y) in pb.fixed_items.items():
        sol.bin[it], sol.ot[it], sol.x[it], sol.y[it] = b, ot, x, y
        sol.used = max(sol.used, b + 1)
    if len(seen) + len(pb.fixed_items) < len(pb.items):
        return None  # not every copy placed: construct instead
    if pb.strip_height is not None:
        sol.length[0] = max(_used_length(pb, sol, 0), float(np.max(pb.box[:, 2] - pb.box[:, 0])))
    return sol


def _same(a: Any, b: Any) -> bool:
    from .problem import _same_angle

    return _same_angle(a, b)


def _improve(
    pb: Problem,
    eng: Any,
    sol: Any,
    deadline: float,
    iterations: int | None,
    threads: int,
    seed: int,
    progress: Any,
    callback: Callable[[Any], None] | None,
    name: str | None,
    time_limit: float | None,
) -> Any:
    """The improvement loop (exploration, then compression), compaction and the
    certificate."""
    best = sol
    history = [best]
    prog = _Progress(progress, callback, time_limit)
    t_start = time.monotonic()
    final = deadline
    deadline = t_start + (1 - COMPACT_SHARE) * (deadline - t_start)  # the rest: compaction
    total_time = deadline - t_start
    ratio = RATIO_START
    attempts = 0
    retries = 0
    fails_close = 0
    target = None
    b_min = _min_length(pb)
    try:
        while True:
            now = time.monotonic()
            if now >= deadline or (iterations is not None and attempts >= iterations):
                break
            attempts += 1
            s = seed * 1_000_003 + attempts
            remaining = deadline - now
            compress = (
                (now - t_start) > EXPLORE_SHARE * total_time
                if math.isfinite(total_time)
                else iterations is not None and attempts > EXPLORE_SHARE * iterations
            )
            best.load(eng)
            last = best.used - 1
            ok = False
            closing = fails_close < 3 or attempts % CLOSE_EVERY == 0
            if pb.strip_height is None and best.used > 1 and closing:
                ok, _ = eng.attempt(1, 0.0, s, threads, remaining)
                if ok:
                    new = _Sol.of(eng)
                    new.used = best.used - 1
                    new.length[new.used - 1] = min(
                        pb.bins[new.used - 1].width, _used_length(pb, new, new.used - 1)
                    )
                    best = new
                    fails_close = 0
                else:
                    fails_close += 1
                    eng.clear_pool()
            else:
                cur = float(best.length[last])
                if compress:
                    frac = (
                        0.0
                        if not math.isfinite(total_time)
                        else (((now - t_start) / total_time - EXPLORE_SHARE) / (1 - EXPLORE_SHARE))
                    )
                    ratio_c = COMPRESS_RANGE[0] * (COMPRESS_RANGE[1] / COMPRESS_RANGE[0]) ** frac
                    target, mode = cur * (1 - ratio_c), 0
                    retries = 0
                    eng.clear_pool()
                elif target is not None and retries < MAX_RETRIES and target < cur:
                    mode = 3
                else:
                    if target is not None:  # gave up on the last target: a smaller step
                        ratio = max(RATIO_MIN, ratio / 2)
                    target, mode, retries = cur * (1 - ratio), 0, 0
                    eng.clear_pool()
                target = math.floor(max(b_min[last], target) / pb.grid) * pb.grid
                if target >= cur:
                    if ratio <= RATIO_MIN and not compress:
                        break  # at the lower bound
                    ratio = max(RATIO_MIN, ratio / 2)
                    target = None
                    continue
                ok, _ = eng.attempt(mode, target, s, threads, remaining)
                if ok:
                    new = _Sol.of(eng)
                    new.length[last] = min(target, _used_length(pb, new, last))
                    best = new
                    target = None
                else:
                    retries += 1
            if ok:
                history.append(best)
                d = _density(pb, best)
                prog.improved(lambda b=best: _layout(pb, b, name), d)
            prog.step(time.monotonic() - t_start if time_limit else attempts, _density(pb, best))
        # the final exact compaction, in what is left of the budget
        comp = _compact(pb, eng, _copy(best), final)
        comp.load(eng)
        if eng.overlap()[0] == 0 and comp.length[comp.used - 1] <= best.length[best.used - 1]:
            history.append(comp)
    finally:
        prog.close()
    return _certified(pb, history, name)


def _copy(s: _Sol) -> _Sol:
    return _Sol(s.bin.copy(), s.ot.copy(), s.x.copy(), s.y.copy(), s.length.copy(), s.used)


def _min_length(pb: Problem) -> list[float]:
    """A lower bound of each bin's length: its widest part in its narrowest orientation."""
    widest = 0.0
    for i, _ in pb.items:
        w = min(
            pb.box[pb.ot_of[(i, k)], 2] - pb.box[pb.ot_of[(i, k)], 0]
            for k in range(len(pb.rotations[i]))
            if (i, k) in pb.ot_of
        )
        widest = max(widest, w)
    return [widest + 2 * pb.margin for _ in pb.bins]


def _certified(pb: Problem, history: list, name: Any) -> Any:
    """The best layout of ``history`` that passes the exact certificate."""
    from ..errors import LayoutError

    first_error = None
    for sol in reversed(history):
        lay = _layout(pb, sol, name)
        try:
            lay.verify()
        except LayoutError as exc:
            first_error = first_error or exc
            continue
        return lay
    raise GeometryError(
        f"nest: no layout passed the exact certificate ({first_error}); please report this",
        argument="parts",
        hint="a rounding at a contact; try spacing > 0",
    )
