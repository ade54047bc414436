"""No-fit polygons of ESICUP parts at free rotations: minkowski2d against CGAL (issue 16).

Rotations by multiples of 90 degrees are exact and let ``mk.no_fit_polygons`` skip most
NFPs by symmetry (``bench_nfp.py``); free rotations are what a nesting code with fine
rotation steps asks for, and every NFP is then computed. Per instance (the 15 classic
ones by default), a seeded set of ``--angles`` integer angles that are not multiples of
90 (the same every run; shown in the table), every part rotated by each with
``mk.rotate_part`` (float64; exactly the polygons ``mk.no_fit_polygons`` makes), and:

* **singles**: a seeded sample of ``--singles`` NFPs ``(i, ri, j, rj)``, each computed
  by one call ``mk.minkowski_sum_general(A, mk.reflect(B))`` in a loop (the rotated
  parts are prepared before the clock starts);
* **batch**: ``mk.no_fit_polygons(parts, rotations=angles)``: every ordered pair of
  parts and every pair of angles (``n² · k²`` NFPs), one call.

CGAL ``minkowski_sum_2`` (Epeck, reduced convolution, its default) computes the same
NFPs, from the same float64 coordinates (``cgal_nfp_driver.cpp``: read with strtod, so
bit for bit), timed inside the driver (the sums only: no reading, no printing, no
process start; best of ``--reps`` runs, as ours: the machine may be shared). Ours: in
process. ``ratio`` = ours / CGAL on the
same NFPs; below 1 is faster than CGAL. ``agree``: NFPs whose area is within 1e-9
relative of CGAL's exact area and with as many holes; ``err``: calls that raised.

Run: ``python benchmarks/bench_nfp_free.py [--instances dagli fu ...] [--angles 2]
[--singles 60] [--reps 3] [--no-cgal]`` (about a minute with the defaults).
"""

from __future__ import annotations

import argparse
import sys
import time
from collections import defaultdict

import numpy as np
import shapely
from bench_nfp import CLASSIC, DATA, REL, build_driver, holes, run_cgal

import minkowski2d as mk


def free_angles(name: str, k: int, seed: int) -> tuple[int, ...]:
    """``k`` distinct integer angles in (0, 360), none a multiple of 90 (seeded by the
    instance's name: the same every run)."""
    rng = np.random.default_rng([seed, *map(ord, name)])
    out: list[int] = []
    while len(out) < k:
        a = int(rng.integers(1, 360))
        if a % 90 and a not in out:
            out.append(a)
    return tuple(sorted(out))


def rotated_rings(parts: list, angles: tuple) -> dict:
    """(i, angle) -> the part's float64 ring rotated as ``mk.no_fit_polygons`` does."""
    return {
        (i, a): shapely.get_coordinates(mk.rotate_part(p, a).exterior)[:-1]
        for i, p in enumerate(parts)
        for a in angles
    }


def agreement(ours: list, ref: list, keys: list, bad: list) -> tuple[int, float]:
    """(NFPs agreeing with CGAL on area and holes, worst relative area difference);
    ``ours`` holds shapely geometries or None (the call raised). Disagreements are
    appended to ``bad`` as (key, our area, our holes, CGAL's area, CGAL's holes)."""
    ok, worst = 0, 0.0
    for k, g, (area, h) in zip(keys, ours, ref, strict=True):
        if g is None:
            continue
        rel = abs(g.area - area) / area
        worst = max(worst, rel)
        if rel <= REL and holes(g) == h:
            ok += 1
        else:
            bad.append((k, g.area, holes(g), area, h))
    return ok, worst


def cgal_best(driver: str, rings: dict, keys: list, reps: int):
    """``run_cgal`` ``reps`` times: the least time (the machine is shared) and the
    values (None if the driver failed)."""
    best = None
    for _ in range(reps):
        r = run_cgal(driver, rings, keys)
        if r is None:
            return None
        best = r if best is None or r[0] < best[0] else best
    return best


def time_singles(rings: dict, keys: list, reps: int) -> tuple[float, list, int]:
    """Best-of-``reps`` time of one ``minkowski_sum_general(A, reflect(B))`` call per key,
    the results (None where the call raised) and the number of calls that raised."""
    pairs = [(rings[(i, a)], rings[(j, b)]) for i, a, j, b in keys]
    best, out = np.inf, []
    for _ in range(reps):
        res = []
        t0 = time.perf_counter()
        for A, B in pairs:
            try:
                res.append(mk.minkowski_sum_general(A, mk.reflect(B)))
            except mk.errors.GeometryError:
                res.append(None)
        best = min(best, time.perf_counter() - t0)
        out = res
    return best, out, sum(g is None for g in out)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--instances", nargs="*", default=CLASSIC)
    ap.add_argument("--angles", type=int, default=2, help="free angles per instance")
    ap.add_argument("--singles", type=int, default=60, help="sampled NFPs per instance")
    ap.add_argument("--reps", type=int, default=3, help="best of REPS for minkowski2d")
    ap.add_argument("--seed", type=int, default=16)
    ap.add_argument("--threads", type=int, default=1, help="no_fit_polygons threads")
    ap.add_argument("--no-cgal", action="store_true")
    args = ap.parse_args(argv)
    driver = None if args.no_cgal else build_driver()
    print(
        f"python {sys.version.split()[0]}, shapely {shapely.__version__} "
        f"(GEOS {shapely.geos_version_string}); best of {args.reps}"
    )
    hdr = (
        f"{'instance':9} {'angles':>9} | {'singles':>7} {'ours s':>7} {'CGAL s':>7} "
        f"{'ratio':>6} {'agree':>9} {'err':>3} | {'batch':>6} {'ours s':>7} {'CGAL s':>7} "
        f"{'ratio':>6} {'agree':>11}"
    )
    print(hdr)
    tot = {k: 0.0 for k in ("s_n", "s_ours", "s_cgal", "s_ok", "s_err", "b_n", "b_ours")}
    tot.update(b_cgal=0.0, b_ok=0, worst=0.0)
    have_cgal = driver is not None
    bad: dict = defaultdict(list)
    for name in args.instances:
        d = mk.read_esicup(DATA / f"{name}.json")
        parts = d["parts"]
        n = len(parts)
        angles = free_angles(name, args.angles, args.seed)
        rings = rotated_rings(parts, angles)
        keys = [(i, a, j, b) for i in range(n) for j in range(n) for a in angles for b in angles]
        rng = np.random.default_rng([args.seed, 1, *map(ord, name)])
        pick = sorted(rng.choice(len(keys), min(args.singles, len(keys)), replace=False))
        skeys = [keys[k] for k in pick]

        ts, sres, serr = time_singles(rings, skeys, args.reps)
        tb = np.inf
        for _ in range(args.reps):
            t0 = time.perf_counter()
            nfps = mk.no_fit_polygons(parts, rotations=angles, threads=args.threads)
            tb = min(tb, time.perf_counter() - t0)
        # CGAL reads (i, r) as part i rotated by r and (j, r) negated: the same rings
        cs = cgal_best(driver, rings, skeys, args.reps) if driver else None
        cb = cgal_best(driver, rings, keys, args.reps) if driver else None
        have_cgal = have_cgal and cs is not None and cb is not None
        s_ok = b_ok = None
        if cs and cb:
            s_ok, w1 = agreement(sres, cs[1], skeys, bad[("single", name)])
            b_ok, w2 = agreement([nfps[k] for k in keys], cb[1], keys, bad[("batch", name)])
            tot["worst"] = max(tot["worst"], w1, w2)
            tot["s_cgal"] += cs[0]
            tot["b_cgal"] += cb[0]
            tot["s_ok"] += s_ok
            tot["b_ok"] += b_ok
        tot["s_n"] += len(skeys)
        tot["s_ours"] += ts
        tot["s_err"] += serr
        tot["b_n"] += len(keys)
        tot["b_ours"] += tb

        def cg(c, t):
            return (f"{c[0]:7.3f}", f"{t / c[0]:6.2f}") if c else (f"{'-':>7}", f"{'-':>6}")

        (sc, sr), (bc, br) = cg(cs, ts), cg(cb, tb)
        sa = f"{s_ok}/{len(skeys)}" if s_ok is not None else "-"
        ba = f"{b_ok}/{len(keys)}" if b_ok is not None else "-"
        print(
            f"{name:9} {','.join(map(str, angles)):>9} | {len(skeys):7d} {ts:7.3f} {sc} {sr} "
            f"{sa:>9} {serr:3d} | {len(keys):6d} {tb:7.3f} {bc} {br} {ba:>11}",
            flush=True,
        )
    print(
        f"\nsingles: {int(tot['s_n'])} NFPs, ours {tot['s_ours']:.3f} s "
        f"({1e3 * tot['s_ours'] / tot['s_n']:.3f} ms per NFP), {int(tot['s_err'])} raised"
    )
    if have_cgal:
        print(
            f"  CGAL {tot['s_cgal']:.3f} s ({1e3 * tot['s_cgal'] / tot['s_n']:.3f} ms per "
            f"NFP); ratio ours/CGAL {tot['s_ours'] / tot['s_cgal']:.2f}x; agree "
            f"{int(tot['s_ok'])}/{int(tot['s_n'])}"
        )
    print(
        f"no_fit_polygons: {int(tot['b_n'])} NFPs, ours {tot['b_ours']:.3f} s "
        f"({1e3 * tot['b_ours'] / tot['b_n']:.3f} ms per NFP)"
    )
    if have_cgal:
        print(
            f"  CGAL {tot['b_cgal']:.3f} s ({1e3 * tot['b_cgal'] / tot['b_n']:.3f} ms per "
            f"NFP); ratio ours/CGAL {tot['b_ours'] / tot['b_cgal']:.2f}x; agree "
            f"{int(tot['b_ok'])}/{int(tot['b_n'])}; worst relative area difference "
            f"{tot['worst']:.1e}"
        )
    for (what, name), rows in bad.items():
        for k, a, h, ca, ch in rows[:5]:
            ours = f"area {a!r}, {h} holes"
            print(f"  disagrees ({what}, {name}) {k}: {ours}; CGAL {ca!r}, {ch} holes")
    return 0


if __name__ == "__main__":
    sys.exit(main())
