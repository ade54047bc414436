"""Convex Minkowski sums: minkowski2d against its peers, measured side by side in one run.

Run:  python benchmarks/bench_convex.py [--quick]

Prints a Markdown table: median time of each implementation on the same input and the
ratio peer / ours (> 1 means we are faster). Peers:

* the seed's pure-Python merge (the reference O(n + m) algorithm, as published);
* scipy.spatial.ConvexHull (Qhull) of all n·m pairwise vertex sums;
* shapely.convex_hull (GEOS) of all pairwise sums (vectorized over pairs in the batch row);
* pyclipper.MinkowskiSum (Clipper 1), which returns the swept boundary of one polygon
  along the other's path, not the solid sum (the table says so); its solid sum needs a
  union afterwards, which is not counted here;
* np.copy of an array the size of the output: the memory-bandwidth floor for the large row.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from collections.abc import Callable
from typing import Any

import numpy as np

import minkowski2d as mk

SEED = 20261122


# -- the seed's published merge, verbatim in behaviour ---------------------------------
def _seed_add(a, b):
    return (a[0] + b[0], a[1] + b[1])


def _seed_sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def _seed_cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def _seed_reorder(p):
    k = min(range(len(p)), key=lambda i: (p[i][1], p[i][0]))
    return p[k:] + p[:k]


def seed_minkowski(a, b):
    a = _seed_reorder(a)
    b = _seed_reorder(b)
    a = a + [a[0], a[1]]
    b = b + [b[0], b[1]]
    res = []
    i = j = 0
    while i < len(a) - 2 or j < len(b) - 2:
        res.append(_seed_add(a[i], b[j]))
        c = _seed_cross(_seed_sub(a[i + 1], a[i]), _seed_sub(b[j + 1], b[j]))
        if c > 0:
            i += 1
        elif c < 0:
            j += 1
        else:
            i += 1
            j += 1
    return res


# -- inputs ------------------------------------------------------------------------------
def regular_ngon(n: int, r: float, phase: float, integer: bool) -> np.ndarray:
    """A convex n-gon. With ``integer`` the vertices are rounded to the integer grid; the
    radius is raised so the sagitta between neighbours (r·π²/2n²) stays far above the
    rounding, which keeps all n vertices strictly convex (checked)."""
    t = phase + 2 * np.pi * np.arange(n) / n
    if integer:
        r = max(r, 40.0 * n * n)
    p = np.c_[r * np.cos(t), r * np.sin(t)]
    if integer:
        p = np.round(p).astype(np.int64)
        if len(mk.convex_hull(p)) != n:
            raise RuntimeError("rounded polygon lost vertices; raise the radius")
    return p


def random_hull(rng: np.random.Generator, k: int) -> np.ndarray:
    return mk.convex_hull(rng.integers(-1000, 1000, size=(k, 2)))


# -- timing ------------------------------------------------------------------------------
def median_time(f: Callable[[], Any], repeat: int, number: int = 1) -> float:
    f()  # warm up (allocations, caches)
    ts = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        for _ in range(number):
            f()
        ts.append((time.perf_counter() - t0) / number)
    return statistics.median(ts)


def fmt(t: float) -> str:
    if t >= 1:
        return f"{t:.2f} s"
    if t >= 1e-3:
        return f"{t * 1e3:.1f} ms"
    return f"{t * 1e6:.1f} µs"


def pairwise_sums(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return (a[:, None, :] + b[None, :, :]).reshape(-1, 2).astype(np.float64)


def row(name: str, ours: float, peers: list[tuple[str, float, str]]) -> list[str]:
    lines = [f"| {name} | minkowski2d | {fmt(ours)} | 1.00 | |"]
    for pname, t, note in peers:
        lines.append(f"| | {pname} | {fmt(t)} | {t / ours:.2f} | {note} |")
    return lines


def bench_single(n: int, integer: bool, repeat: int) -> list[str]:
    import pyclipper
    import shapely
    from scipy.spatial import ConvexHull

    a = regular_ngon(n, 1e6 if integer else 1.0, 0.1, integer)
    b = regular_ngon(n, 7e5 if integer else 0.7, 0.37, integer)
    la = [tuple(p) for p in a.tolist()]
    lb = [tuple(p) for p in b.tolist()]
    number = max(1, 4000 // n)
    peers = []
    if n <= 64:
        # the seed's merge takes lists of tuples: ours is timed on the same lists (and, as a
        # second row, on the numpy arrays)
        ours = median_time(lambda: mk.minkowski_sum(la, lb), repeat, number)
        t_arr = median_time(lambda: mk.minkowski_sum(a, b), repeat, number)
        peers.append(("minkowski2d on numpy arrays", t_arr, ""))
    else:
        ours = median_time(lambda: mk.minkowski_sum(a, b), repeat, number)
    t_seed = median_time(lambda: seed_minkowski(la, lb), repeat, number)
    peers.append(("seed's pure-Python merge (no validation)", t_seed, ""))
    if n * n <= 300_000:
        peers.append(
            (
                "scipy ConvexHull of n·m sums",
                median_time(lambda: ConvexHull(pairwise_sums(a, b)), repeat),
                "",
            )
        )
        peers.append(
            (
                "shapely convex_hull of n·m sums",
                median_time(
                    lambda: shapely.convex_hull(shapely.multipoints(pairwise_sums(a, b))), repeat
                ),
                "",
            )
        )
        if integer:
            pa = a.tolist()
            pb = b.tolist()
            peers.append(
                (
                    "pyclipper.MinkowskiSum",
                    median_time(lambda: pyclipper.MinkowskiSum(pa, pb, True), repeat),
                    "boundary sweep, not the solid sum",
                )
            )
    label = f"n = m = {n}, {'int' if integer else 'float'}"
    if n >= 1 << 16:
        out = mk.minkowski_sum(a, b)
        copy = median_time(lambda: np.copy(out), repeat)
        peers.insert(0, ("np.copy of the output", copy, f"ours = {ours / copy:.1f}× the copy"))
    return row(label, ours, peers)


def bench_batch(P: int, repeat: int) -> list[str]:
    import shapely

    rng = np.random.default_rng(SEED)
    As = [random_hull(rng, int(k)) for k in rng.integers(3, 13, P)]
    Bs = [random_hull(rng, int(k)) for k in rng.integers(3, 13, P)]
    RA = mk.Ragged.from_list(As)
    RB = mk.Ragged.from_list(Bs)
    ours = median_time(lambda: mk.minkowski_sum_many(RA, RB), repeat)
    ours_t2 = median_time(lambda: mk.minkowski_sum_many(RA, RB, threads=2), repeat)
    ours_list = median_time(lambda: mk.minkowski_sum_many(As, Bs), repeat)
    la = [[tuple(p) for p in a.tolist()] for a in As]
    lb = [[tuple(p) for p in b.tolist()] for b in Bs]
    ours_tuples = median_time(lambda: mk.minkowski_sum_many(la, lb), repeat)
    seed = median_time(lambda: [seed_minkowski(x, y) for x, y in zip(la, lb)], max(1, repeat // 3))
    loop = median_time(
        lambda: [mk.minkowski_sum(x, y) for x, y in zip(la, lb)], max(1, repeat // 3)
    )

    def shp():
        sums = [pairwise_sums(x, y) for x, y in zip(As, Bs)]
        idx = np.repeat(np.arange(P), [len(s) for s in sums])
        return shapely.convex_hull(shapely.multipoints(np.concatenate(sums), indices=idx))

    shp_t = median_time(shp, max(1, repeat // 3))
    peers = [
        ("minkowski_sum_many from a Ragged, threads=2", ours_t2, ""),
        ("minkowski_sum_many on lists of tuples", ours_tuples, "includes packing to Ragged"),
        ("minkowski_sum_many on lists of arrays", ours_list, "includes packing to Ragged"),
        ("Python loop of minkowski_sum", loop, ""),
        ("Python loop of the seed's merge", seed, ""),
        ("shapely convex_hull of pairwise sums (vectorized)", shp_t, ""),
    ]
    return row(f"{P:,} pairs of 3–12-gons", ours, peers)


def bench_threads(P: int, repeat: int) -> list[str]:
    """threads=1 against threads=2 on P pairs from a Ragged (the GIL is released)."""
    rng = np.random.default_rng(SEED + 1)
    RA = mk.Ragged.from_list([random_hull(rng, int(k)) for k in rng.integers(3, 13, P)])
    RB = mk.Ragged.from_list([random_hull(rng, int(k)) for k in rng.integers(3, 13, P)])
    t1 = median_time(lambda: mk.minkowski_sum_many(RA, RB, threads=1), repeat)
    t2 = median_time(lambda: mk.minkowski_sum_many(RA, RB, threads=2), repeat)
    return row(f"{P:,} pairs, threads=1", t1, [("threads=2", t2, f"speed-up {t1 / t2:.2f}×")])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--quick", action="store_true", help="smaller sizes, fewer repeats")
    args = ap.parse_args()
    repeat = 3 if args.quick else 9
    big = 1 << (16 if args.quick else 20)
    lines = [
        "| input | implementation | median time | ratio (peer / ours) | note |",
        "|---|---|---:|---:|---|",
    ]
    for n, integer in ((8, True), (8, False), (64, True), (512, False), (big, True), (big, False)):
        lines += bench_single(n, integer, repeat)
        print(f"... n={n} done", file=sys.stderr)
    lines += bench_batch(10_000 if args.quick else 100_000, repeat)
    lines += bench_threads(100_000 if args.quick else 1_000_000, max(3, repeat // 2))
    print("\n".join(lines))
    print(
        f"\nnumpy {np.__version__}, python {sys.version.split()[0]}; medians of {repeat} runs; "
        "ratio > 1: the peer is slower than minkowski2d.",
    )


if __name__ == "__main__":
    main()
