"""The nesting problem as the compiled search takes it: oriented shapes, their exact no-fit
polygons (one table for every ordered pair of orientations), items, bins and obstacles.

One rule per fact:

* an item is one copy of a part; its allowed orientations are the part's rotations;
* spacing ``s`` between parts: every part is grown by ``s/2`` (:func:`minkowski2d.offset`,
  ``approx="outer"``: the grown part contains ``part ⊕ D(s/2)``) before its no-fit
  polygons are taken, so a placement outside the grown NFP keeps the parts ``s`` apart;
* margin ``m``: a part's box stays ``m`` inside its sheet's rectangle; a keep-out zone (a
  hole of a sheet, or what a non-rectangular sheet leaves of its bounding box) is grown by
  ``m`` and becomes a fixed obstacle of that sheet;
* translations live on a dyadic grid (:func:`grid_for`) so that every difference of two
  translations the search forms is exact;
* a safety gap (:data:`GAP`, relative to the layout's extent) is added to the spacing:
  the no-fit polygons' vertices are correctly rounded, not exact, so two parts that
  touch exactly on a rounded NFP may overlap by a rounding in truth; with the gap they
  are apart by at least the gap less that rounding.

The certificate (:mod:`.verify`) checks the result on the parts themselves, not on any
of these polygons.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import numpy as np

from .._engine import options as _options
from ..errors import GeometryError, OptionError
from .nfp import _quarter_turns, _rotate, no_fit_polygons

__all__ = ["Problem", "Bin", "build_problem", "grid_for", "GAP"]

#: The safety gap between parts, relative to the largest sheet or part extent (2**-30:
#: far above the NFPs' rounding, far below any measurable loss of density).
GAP = 2.0**-30


@dataclass
class Bin:
    """One sheet the search may use: its rectangle and the obstacles inside it."""

    kind: int | None  # the index in sheets= (None: the strip)
    width: float
    height: float
    origin: tuple[float, float]  # the sheet polygon's lower-left corner
    polygon: Any  # shapely Polygon in sheet coordinates
    obstacles: list = field(default_factory=list)  # shapely polygons, grown by the margin


@dataclass
class Problem:
    parts: list  # shapely Polygons as given
    ids: list
    quantities: list
    rotations: list  # one tuple per part
    bins: list  # Bin
    strip_height: float | None
    spacing: float
    margin: float
    # oriented shapes: (part, rotation index) -> ot; obstacles after the parts
    ot_of: dict = field(default_factory=dict)
    ot_part: list = field(default_factory=list)  # part index or -1 (obstacle)
    ot_angle: list = field(default_factory=list)
    # (n_ot, 4) of the part itself (container test); both set by build_problem
    box: np.ndarray = field(default_factory=lambda: np.zeros((0, 4)))
    area: np.ndarray = field(default_factory=lambda: np.zeros(0))
    items: list = field(default_factory=list)  # (part, copy)
    fixed_items: dict = field(default_factory=dict)  # item -> (bin, ot, x, y)
    obstacle_items: list = field(default_factory=list)  # (bin, ot)
    grid: float = 0.0
    gap: float = 0.0
    nfps: Any = None  # NfpTable


def _polygon(p: Any, name: str) -> Any:
    """A part as a shapely Polygon (holes kept); specific errors name the part. Shapely
    input and None are read as a Layout reads them (layout._polygon); a ring is rounded
    to float64 once and checked by the core's exact polygon test."""
    import shapely

    from .._engine.coerce import is_shapely
    from .._engine.reader import read
    from .layout import _polygon as layout_polygon

    if p is None or is_shapely(p):
        return layout_polygon(p, name)
    poly = shapely.Polygon(read(p, name, accept="coords", numbers="round"))
    if not poly.is_valid or poly.area == 0:
        from ..general import convex_decomposition

        convex_decomposition(poly)  # raises the specific error for a ring that is not simple
    return poly


def grid_for(extent: float) -> float:
    """The dyadic grid of translations for coordinates up to ``extent``: the power of two
    that leaves 2**44 grid steps across it (differences of two translations, and sums of
    a translation and a vertex on that grid, are then exact in float64)."""
    e = math.frexp(max(extent, 1e-300))[1]
    return math.ldexp(1.0, e - 44)


def _sheets(sheets: Any) -> list[tuple[Any, int]]:
    """``sheets=`` as (shapely Polygon, count) pairs."""
    import shapely

    from .._engine.coerce import is_shapely

    out = []
    seq = _options.sequence(sheets, "sheets", "a list of sheets: (W, H), polygons, (sheet, count)")
    if not seq:
        raise OptionError("sheets: no sheet given", argument="sheets", allowed="at least one sheet")
    for k, s in enumerate(seq):
        name = f"sheets[{k}]"
        count = 1
        if (
            isinstance(s, (tuple, list))
            and len(s) == 2
            and not all(isinstance(v, (int, float, Fraction, np.number)) for v in s)
        ):
            s, count = s
            if not _options.is_int(count) or int(count) < 1:
                raise OptionError(
                    f"{name}: count must be a positive int, got {count!r}",
                    argument=name,
                    allowed="(sheet, count) with count >= 1",
                )
            count = int(count)
        if (
            isinstance(s, (tuple, list))
            and len(s) == 2
            and all(isinstance(v, (int, float, Fraction, np.number)) for v in s)
        ):
            w, h = (_options.real(v, name) for v in s)
            if not (w > 0 and h > 0) or not (math.isfinite(w) and math.isfinite(h)):
                raise OptionError(
                    f"{name}: a sheet needs a positive width and height, got {s!r}",
                    argument=name,
                    allowed="(W, H) with W, H > 0",
                )
            poly = shapely.box(0, 0, float(w), float(h))
        elif is_shapely(s):
            poly = _polygon(s, name)
        else:
            poly = _polygon(s, name)
        out.append((poly, count))
    return out


def _bins(sheets: Any, height: Any, length: float, margin: float) -> tuple[list, float | None]:
    import shapely

    from ..offset import offset

    if sheets is None:
        h = float(_options.real(height, "height"))
        if not (h > 0) or not math.isfinite(h):
            raise OptionError(
                f"height: the strip height must be positive, got {height!r}",
                argument="height",
                allowed="a number > 0",
            )
        box = shapely.box(0, 0, length, h)
        return [Bin(None, length, h, (0.0, 0.0), box)], h
    bins = []
    for kind, (poly, count) in enumerate(_sheets(sheets)):
        x0, y0, x1, y1 = poly.bounds
        # keep-out zones: the holes, and what the sheet leaves of its box
        from .._engine.overlay import overlay

        rect = shapely.box(x0, y0, x1, y1)
        rings = [np.asarray(rect.exterior.coords)[:-1]]
        op = shapely.orient_polygons(poly)  # shell counter-clockwise, holes clockwise
        rings += [np.asarray(r.coords)[:-1] for r in [op.exterior, *op.interiors]]
        outside = overlay(rings, layers=[0] + [1] * (len(rings) - 1), rule="difference")
        zones = [] if outside.is_empty else list(shapely.get_parts(outside))
        if margin > 0 and zones:
            zones = [g for z in zones for g in shapely.get_parts(offset(z, margin))]
        for _ in range(count):
            bins.append(Bin(kind, x1 - x0, y1 - y0, (x0, y0), poly, list(zones)))
    return bins, None


def _grown(parts: list, spacing: float) -> list:
    """Each part grown by spacing / 2 (outer approximation), holes shrinking."""
    if spacing <= 0:
        return parts
    from ..offset import offset

    return [offset(p, spacing / 2) for p in parts]


class NfpTable:
    """The no-fit polygons as flat arrays: entry k = a * n_ot + b (NFP of oriented shape a
    fixed, b moving) has rings ``nring[k] .. nring[k + 1]``, ring r the vertices
    ``xy[ring_off[r] : ring_off[r + 1]]`` (no closing repeat), and the box ``nbox[k]``."""

    def __init__(self, geoms: np.ndarray) -> None:
        import shapely

        K = len(geoms)
        ok = np.array([g is not None and not g.is_empty for g in geoms], dtype=bool)
        idx = np.flatnonzero(ok)
        polys, pidx = shapely.get_parts(geoms[idx], return_index=True)
        keep = shapely.get_type_id(polys) == 3
        polys, pidx = polys[keep], pidx[keep]
        rings, ridx = shapely.get_rings(polys, return_index=True)
        coords, cidx = shapely.get_coordinates(rings, return_index=True)
        counts = np.bincount(cidx, minlength=len(rings)) - 1  # without the closing repeat
        last = np.cumsum(counts + 1) - 1
        mask = np.ones(len(coords), dtype=bool)
        mask[last] = False
        self.xy = np.ascontiguousarray(coords[mask], dtype=np.float64)
        self.ring_off = np.concatenate([[0], np.cumsum(counts)]).astype(np.int64)
        entry_of_ring = idx[pidx[ridx]]
        per_entry = np.bincount(entry_of_ring, minlength=K)
        self.nring = np.concatenate([[0], np.cumsum(per_entry)]).astype(np.int64)
        self.nbox = np.zeros((K, 4), dtype=np.float64)
        if len(self.xy):
            # per entry: the box of its first ring's vertices through its last ring's
            starts = self.ring_off[self.nring[:-1][per_entry > 0]]
            xs, ys = self.xy[:, 0], self.xy[:, 1]
            sel = per_entry > 0
            self.nbox[sel, 0] = np.minimum.reduceat(xs, starts)
            self.nbox[sel, 1] = np.minimum.reduceat(ys, starts)
            self.nbox[sel, 2] = np.maximum.reduceat(xs, starts)
            self.nbox[sel, 3] = np.maximum.reduceat(ys, starts)

    def rings(self, k: int) -> list[np.ndarray]:
        ro = self.ring_off
        return [self.xy[ro[r] : ro[r + 1]] for r in range(self.nring[k], self.nring[k + 1])]


def build_problem(
    parts: Sequence[Any],
    quantities: Sequence[int],
    rotations: Sequence[tuple],
    *,
    height: Any,
    sheets: Any,
    spacing: float,
    margin: float,
    ids: Sequence[str],
    fixed: Sequence[Any],
    threads: int,
) -> Problem:
    """Everything the search needs, NFPs included (one batch of exact sums)."""
    import shapely

    n = len(parts)
    areas = [p.area for p in parts]
    # the strip's starting length: every part side by side (the search only shrinks it)
    big = (
        sum(
            q * (max(p.bounds[2] - p.bounds[0], p.bounds[3] - p.bounds[1]) + spacing)
            for p, q in zip(parts, quantities, strict=True)
        )
        + 2 * margin
    )
    big = 1.01 * big + 2 * margin  # room for the safety gaps
    bins, strip_h = _bins(sheets, height, big, margin)
    pb = Problem(
        list(parts), list(ids), list(quantities), list(rotations), bins, strip_h, spacing, margin
    )
    # oriented shapes of the parts
    boxes, ars = [], []
    for i, p in enumerate(parts):
        for k, a in enumerate(rotations[i]):
            pb.ot_of[(i, k)] = len(pb.ot_part)
            pb.ot_part.append(i)
            pb.ot_angle.append(a)
            rp = _rotate(p, a)
            boxes.append(rp.bounds)
            ars.append(areas[i])
    # fixed placements at rotations not listed get their own oriented shape
    fixed_ots = []
    for f in fixed:
        i, a = f.part, f.rotation
        ks = [k for k, b in enumerate(pb.rotations[i]) if _same_angle(a, b)]
        if not ks:
            pb.rotations[i] = tuple(pb.rotations[i]) + (a,)
            k = len(pb.rotations[i]) - 1
            pb.ot_of[(i, k)] = len(pb.ot_part)
            pb.ot_part.append(i)
            pb.ot_angle.append(a)
            boxes.append(_rotate(parts[i], a).bounds)
            ars.append(areas[i])
        fixed_ots.append(pb.ot_of[(i, ks[0] if ks else len(pb.rotations[i]) - 1)])
    n_part_ot = len(pb.ot_part)
    # obstacles (keep-out zones), one oriented shape each, already in sheet coordinates
    obstacles = []
    for b, bn in enumerate(bins):
        ox, oy = bn.origin
        for z in bn.obstacles:
            zz = shapely.affinity.translate(z, -ox, -oy) if (ox or oy) else z
            pb.obstacle_items.append((b, len(pb.ot_part)))
            pb.ot_part.append(-1)
            pb.ot_angle.append(0)
            boxes.append(zz.bounds)
            ars.append(zz.area)
            obstacles.append(zz)
    pb.box = np.asarray(boxes, dtype=np.float64).reshape(-1, 4)
    pb.area = np.asarray(ars, dtype=np.float64)
    # items
    for i in range(n):
        for c in range(quantities[i]):
            pb.items.append((i, c))
    taken: dict[int, int] = {}
    for f, ot in zip(fixed, fixed_ots, strict=True):
        c = taken.get(f.part, 0)
        taken[f.part] = c + 1
        item = pb.items.index((f.part, c))
        pb.fixed_items[item] = (f.sheet, ot, float(f.translation[0]), float(f.translation[1]))
    extent = max([b.width for b in bins] + [b.height for b in bins])
    extent = max(extent, float(np.abs(pb.box).max()) if len(pb.box) else 0.0)
    pb.grid = grid_for(4 * extent)
    pb.gap = 0.0 if _exact_data(pb, obstacles) else GAP * extent
    pb.nfps = _nfp_table(pb, n_part_ot, obstacles, threads)
    return pb


def _exact_data(pb: Problem, obstacles: list) -> bool:
    """True when the NFPs' vertex sums are exact and no safety gap is needed: integer
    coordinates (|x| < 2**40), rotations by multiples of 90 degrees, no spacing and no
    grown keep-out zone. Their crossings are still rounded: the search then touches only
    at NFP vertices with integer coordinates (exact sums), never at a crossing."""
    import shapely

    if pb.spacing > 0 or (pb.margin > 0 and obstacles):
        return False
    if any(_quarter_turns(a) is None for a in pb.ot_angle):
        return False
    shapes = list(pb.parts) + list(obstacles)
    if pb.strip_height is None:
        shapes += [b.polygon for b in pb.bins]
    elif pb.strip_height != round(pb.strip_height):
        return False
    c = shapely.get_coordinates(np.array(shapes, dtype=object))
    return bool(np.all(c == np.round(c)) and np.all(np.abs(c) < 2.0**40))


def _same_angle(a: Any, b: Any) -> bool:
    qa, qb = _quarter_turns(a), _quarter_turns(b)
    if qa is not None or qb is not None:
        return qa == qb
    return Fraction(a) % 360 == Fraction(b) % 360


def _nfp_table(pb: Problem, n_part_ot: int, obstacles: list, threads: int) -> NfpTable:
    """Rings of NFP(a fixed, b moving) for every oriented shape a and part orientation b
    (entry a * n_ot + b); empty for pairs the search never asks for."""
    n_ot = len(pb.ot_part)
    grown = _grown(pb.parts, pb.spacing + pb.gap)
    shapes = list(grown) + list(obstacles)
    n = len(pb.parts)
    rots = [tuple(r) for r in pb.rotations] + [(0,)] * len(obstacles)
    pairs = [(i, j) for i in range(n) for j in range(n)]
    pairs += [(n + z, j) for z in range(len(obstacles)) for j in range(n)]
    try:
        nfps = no_fit_polygons(shapes, rotations=rots, pairs=pairs, threads=threads)
    except GeometryError as exc:
        raise exc.renamed(
            hint=(exc.hint or "") + " (while computing the no-fit polygons of the parts)"
        ) from exc
    table = np.empty(n_ot * n_ot, dtype=object)
    ot_key: dict[int, tuple[int, Any]] = {}  # (part, angle) of a part's oriented shape
    for ot in range(n_ot):
        i = pb.ot_part[ot]
        if i >= 0:
            ot_key[ot] = (i, pb.ot_angle[ot])
    z_of = {}
    for z, (_, ot) in enumerate(pb.obstacle_items):
        z_of[ot] = z
    for a in range(n_ot):
        ka = ot_key[a] if pb.ot_part[a] >= 0 else (n + z_of[a], 0)
        for b in range(n_part_ot):
            kb = ot_key[b]
            table[a * n_ot + b] = nfps.get((ka[0], ka[1], kb[0], kb[1]))
    return NfpTable(table)
