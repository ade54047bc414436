"""The union of the convex piece sums of an NFP: ours against shapely.union_all (issue 16).

A non-convex sum by decomposition is the union of all piece sums ``P_k ⊕ Q_l`` (convex
pieces of A and of −B); those pieces overlap heavily, and their union is where GEOS
spends the time (and where it loses regions: see tests/test_cgal_crosscheck.py). This
row measures that union alone, on real piece sets: per instance (the 15 classic ESICUP
ones by default), parts rotated by a seeded pair of free angles (``bench_nfp_free.py``'s,
not multiples of 90) and a seeded sample of ``--pairs`` NFPs ``(i, ri, j, rj)``:

* pieces: ``mk.convex_decomposition`` of ``A`` and of ``−B`` (Hertel–Mehlhorn), all
  piece sums in one ``mk.minkowski_sum_many`` call (timed apart: ``sums ms``);
* **shapely**: ``shapely.union_all`` of those piece sums (as shapely polygons, built
  before the clock starts);
* **ours**: :func:`ours_union`: the core's exact union of exactly those piece sums
  (``_ext.union_convex``; pieces already inside the union are dropped before noding,
  see ``src/minkowski2d/_core/union.hpp``), arrays out (shapely's side gives its native
  geometry; the conversion of ours to shapely, for the area check, is not timed).

Times: CPU time of the process (``time.process_time``), best of ``--reps``, summed over
the sample. ``ratio`` = ours / shapely (the goal
of issue 16: ≤ 0.2, i.e. ≥ 5× faster); the total line adds the geometric mean of the
per-NFP ratios (the sum is dominated by the largest piece sets). ``agree``: areas within
1e-9 relative.

Run: ``python benchmarks/bench_union.py [--instances dagli ...] [--pairs 40] [--reps 3]``
(about 10 s with the defaults).
"""

from __future__ import annotations

import argparse
import math
import sys

import numpy as np
import shapely
from _timing import best
from bench_nfp import CLASSIC, DATA, REL
from bench_nfp_free import free_angles, rotated_rings

import minkowski2d as mk
from minkowski2d._core import _ext


def ours_union(A: np.ndarray, negB: np.ndarray, sums: mk.Ragged):
    """OURS: the union of ``sums``, the convex piece sums of ``A ⊕ negB``: the core's exact
    union of exactly those convex polygons (``_ext.union_convex``: pieces inside the
    union so far are dropped before noding, the rest united by the exact overlay;
    vertices rounded once at the end). Returns the core's arrays (coordinates, ring
    offsets, polygon offsets), as ``shapely.union_all`` returns its native geometry;
    :func:`as_shapely` converts them (outside the clock). ``A`` and ``negB`` are unused.
    """
    xy = np.ascontiguousarray(sums.coords, dtype=np.float64)
    off = np.ascontiguousarray(sums.offsets, dtype=np.int64)
    out, ring_off, poly_off, status, _stats, _where = _ext.union_convex(xy, off)
    if status:
        raise RuntimeError(f"union_convex: status {status}")
    return out, ring_off, poly_off


def as_shapely(res):
    xy, ring_off, poly_off = res
    polys = []
    for p in range(len(poly_off) - 1):
        rings = [xy[ring_off[r] : ring_off[r + 1]] for r in range(poly_off[p], poly_off[p + 1])]
        polys.append(shapely.Polygon(rings[0], rings[1:]))
    if len(polys) == 1:
        return polys[0]
    return shapely.MultiPolygon(polys)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--instances", nargs="*", default=CLASSIC)
    ap.add_argument("--angles", type=int, default=2, help="free angles per instance")
    ap.add_argument("--pairs", type=int, default=40, help="sampled NFPs per instance")
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--seed", type=int, default=16)
    args = ap.parse_args(argv)
    print(
        f"python {sys.version.split()[0]}, shapely {shapely.__version__} "
        f"(GEOS {shapely.geos_version_string}), best of {args.reps}; ours = ours_union "
        "(the core's exact union of the same piece sums, _ext.union_convex)"
    )
    print(
        f"{'instance':9} {'angles':>9} {'NFPs':>5} {'pieces':>7} {'sums ms':>8} "
        f"{'shapely ms':>10} {'ours ms':>8} {'ratio':>6} {'agree':>6}"
    )
    tot = {"n": 0, "pieces": 0, "sums": 0.0, "shapely": 0.0, "ours": 0.0, "ok": 0}
    bad = []
    logs = []
    for name in args.instances:
        parts = mk.read_esicup(DATA / f"{name}.json")["parts"]
        n = len(parts)
        angles = free_angles(name, args.angles, args.seed)
        rings = rotated_rings(parts, angles)
        keys = [(i, a, j, b) for i in range(n) for j in range(n) for a in angles for b in angles]
        rng = np.random.default_rng([args.seed, 2, *map(ord, name)])
        pick = sorted(rng.choice(len(keys), min(args.pairs, len(keys)), replace=False))
        row = {"pieces": 0, "sums": 0.0, "shapely": 0.0, "ours": 0.0, "ok": 0}
        for k in pick:
            i, a, j, b = keys[k]
            A, negB = rings[(i, a)], mk.reflect(rings[(j, b)])
            PA, PB = mk.convex_decomposition(A), mk.convex_decomposition(negB)
            la, lb = PA.to_list(), PB.to_list()
            As = [p for p in la for _ in lb]
            Bs = [q for _ in la for q in lb]
            ts, sums = best(lambda As=As, Bs=Bs: mk.minkowski_sum_many(As, Bs), args.reps)
            polys = sums.to_shapely()
            tg, ug = best(lambda polys=polys: shapely.union_all(polys), args.reps)
            to, uo = best(lambda A=A, negB=negB, sums=sums: ours_union(A, negB, sums), args.reps)
            uo = as_shapely(uo)
            row["pieces"] += len(polys)
            row["sums"] += ts
            row["shapely"] += tg
            row["ours"] += to
            logs.append(math.log(to / tg))
            if abs(uo.area - ug.area) <= REL * ug.area:
                row["ok"] += 1
            else:
                bad.append((name, keys[k], uo.area, ug.area))
        for key in row:
            tot[key] += row[key]
        tot["n"] += len(pick)
        print(
            f"{name:9} {','.join(map(str, angles)):>9} {len(pick):5d} {row['pieces']:7d} "
            f"{row['sums'] * 1e3:8.2f} {row['shapely'] * 1e3:10.2f} {row['ours'] * 1e3:8.2f} "
            f"{row['ours'] / row['shapely']:6.2f} {row['ok']:>3d}/{len(pick):<2d}",
            flush=True,
        )
    print(
        f"\ntotal: {tot['n']} NFPs, {tot['pieces']} piece sums; piece sums "
        f"{tot['sums']:.3f} s; shapely.union_all {tot['shapely']:.3f} s; ours "
        f"{tot['ours']:.3f} s; ratio ours/shapely {tot['ours'] / tot['shapely']:.2f}x "
        f"(geometric mean per NFP {math.exp(np.mean(logs)):.2f}x; goal ≤ 0.2); areas agree "
        f"{tot['ok']}/{tot['n']}"
    )
    for name, key, ao, ag in bad:
        print(f"  area differs ({name}, {key}): ours {ao!r}, union_all {ag!r}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
