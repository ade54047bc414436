"""Non-convex Minkowski sums: minkowski2d against Clipper (pyclipper) and CGAL.

Inputs: star polygons with alternating radii (integer coordinates), A: radii 10000/5000,
B: radii 9000/3000 turned by 0.3 rad, n = m = 32, 128, 512, 2048; and CGAL's own test
pairs from ../shared/data/cgal-minkowski. One run prints, per input, each tool's time,
the ratio to ours, and the relative area difference to ours.

Peers
-----
* Clipper 1 (pyclipper) ``MinkowskiSum``: it sums the boundary paths only (its result
  has spurious holes); "clipper+fill" unions that result with A + b0 and B + a0 (a
  NonZero union, also by Clipper), which gives the solid sum. Both are timed; the raw
  result's area difference is shown to say where raw Clipper differs.
* Clipper 2: pyclipr does not expose MinkowskiSum, so it is reported as unavailable.
* CGAL ``minkowski_sum_2`` (Epeck kernel), reduced convolution (``rc``) and
  Hertel-Mehlhorn decomposition (``hm``): ``cgal_driver.cpp`` built once with g++ -O2
  into ``build/cgal_driver`` (skipped, with a message, when g++ or libcgal-dev is
  missing). Its time excludes reading files and process start.

Run: ``python benchmarks/bench_general.py [--sizes 32 128 512 2048] [--no-cgal]``
(CGAL's reduced convolution is skipped above n = 512 unless ``--cgal-rc-max``).
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import _cgal
import numpy as np
import shapely

import minkowski2d as mk

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT.parent / "shared" / "data" / "cgal-minkowski"


def star(n: int, R: float, r: float, phase: float = 0.0) -> np.ndarray:
    k = np.arange(n)
    rad = np.where(k % 2 == 0, R, r)
    th = 2 * np.pi * k / n + phase
    return np.rint(np.c_[rad * np.cos(th), rad * np.sin(th)]).astype(np.int64)


def build_driver() -> str | None:
    """Path of the CGAL driver, building it if needed (see ``_cgal.py``)."""
    return _cgal.build_driver("cgal_driver", "minkowski_sum_2.h")


def cgal(driver: str, method: str, a: np.ndarray, b: np.ndarray) -> tuple[float, float] | None:
    with tempfile.TemporaryDirectory() as d:
        files = []
        for k, p in enumerate((a, b)):
            f = Path(d) / f"p{k}.dat"
            f.write_text(f"{len(p)}\n" + "\n".join(f"{x} {y}" for x, y in p.tolist()) + "\n")
            files.append(str(f))
        res = subprocess.run([driver, method, *files], capture_output=True, text=True)
        if res.returncode:
            return None
        t, area, _ = res.stdout.split()
        return float(t), float(area)


def clipper(a: np.ndarray, b: np.ndarray, fill: bool) -> shapely.Geometry:
    import pyclipper

    pa = a.tolist()
    pb = b.tolist()
    paths = pyclipper.MinkowskiSum(pa, pb, True)
    if fill:
        pc = pyclipper.Pyclipper()
        pc.AddPaths(paths, pyclipper.PT_SUBJECT, True)
        pc.AddPath((a + b[0]).tolist(), pyclipper.PT_SUBJECT, True)
        pc.AddPath((b + a[0]).tolist(), pyclipper.PT_SUBJECT, True)
        paths = pc.Execute(pyclipper.CT_UNION, pyclipper.PFT_NONZERO, pyclipper.PFT_NONZERO)
    return paths


def paths_area(paths) -> float:
    # signed areas: outers positive, holes negative (Clipper's orientation convention)
    tot = 0.0
    for p in paths:
        q = np.asarray(p, dtype=float)
        tot += 0.5 * float(np.sum(q[:, 0] * np.roll(q[:, 1], -1) - np.roll(q[:, 0], -1) * q[:, 1]))
    return abs(tot)


def best_of(f, reps: int) -> tuple[float, object]:
    best, out = float("inf"), None
    for _ in range(reps):
        t = time.perf_counter()
        out = f()
        best = min(best, time.perf_counter() - t)
    return best, out


def run_case(name, a, b, driver, rc_max, reps):
    rows = []
    t_ours, ours = best_of(lambda: mk.minkowski_sum_general(a, b), reps)
    area = ours.area
    rows.append(("minkowski2d decomposition", t_ours, 0.0))
    if len(a) + len(b) <= 200:
        t, c = best_of(lambda: mk.minkowski_sum_general(a, b, method="convolution"), 1)
        rows.append(("minkowski2d convolution", t, abs(c.area - area) / area))
    else:
        rows.append(("minkowski2d convolution", None, "skipped (arrangement too large)"))
    ai = np.asarray(a, dtype=np.int64) if np.all(np.asarray(a) == np.round(a)) else None
    bi = np.asarray(b, dtype=np.int64) if np.all(np.asarray(b) == np.round(b)) else None
    if ai is not None and bi is not None and len(a) * len(b) <= 128 * 128:
        reps_c = 1 if len(a) > 64 else reps  # Clipper takes ~95 s per call at n = m = 128
        t, p = best_of(lambda: clipper(ai, bi, False), reps_c)
        rows.append(("pyclipper MinkowskiSum (raw)", t, abs(paths_area(p) - area) / area))
        t, p = best_of(lambda: clipper(ai, bi, True), reps_c)
        rows.append(("pyclipper + fill", t, abs(paths_area(p) - area) / area))
    else:
        rows.append(("pyclipper", None, "skipped (needs integer coordinates, n*m <= 128^2)"))
    rows.append(("Clipper2 (pyclipr)", None, "unavailable (no MinkowskiSum in pyclipr)"))
    if driver and ai is not None and bi is not None:
        for m, label in (("hm", "CGAL Hertel-Mehlhorn"), ("rc", "CGAL reduced convolution")):
            if m == "rc" and len(a) > rc_max:
                rows.append((label, None, f"skipped (n > {rc_max})"))
                continue
            r = cgal(driver, m, ai, bi)
            if r is None:
                rows.append((label, None, "failed"))
            else:
                rows.append((label, r[0], abs(r[1] - area) / area))
    print(f"\n{name}: |A| = {len(a)}, |B| = {len(b)}, area = {area:.17g}")
    print(f"  {'tool':32s} {'time [s]':>10s} {'x ours':>8s}  area rel. diff")
    for label, t, d in rows:
        if t is None:
            print(f"  {label:32s} {'-':>10s} {'-':>8s}  {d}")
        else:
            print(f"  {label:32s} {t:10.4f} {t / t_ours:8.1f}  {d:.1e}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", type=int, nargs="*", default=[32, 128, 512, 2048])
    ap.add_argument("--no-cgal", action="store_true")
    ap.add_argument("--no-corpus", action="store_true")
    ap.add_argument("--cgal-rc-max", type=int, default=512)
    ap.add_argument("--reps", type=int, default=3)
    args = ap.parse_args()
    driver = None if args.no_cgal else build_driver()
    # warm up the compiled kernels
    mk.minkowski_sum_general(star(16, 100, 50), star(16, 90, 30))
    print(f"minkowski2d general sums; best of {args.reps} runs; python {sys.version.split()[0]}")
    for n in args.sizes:
        a = star(n, 10000, 5000)
        b = star(n, 9000, 3000, 0.3)
        run_case(f"stars n = m = {n}", a, b, driver, args.cgal_rc_max, args.reps if n <= 512 else 1)
    if not args.no_corpus:
        if not DATA.is_dir():
            print(f"\nCGAL corpus: skipped ({DATA} not found)")
            return
        from minkowski2d.io import read_cgal_dat

        for p, q in (
            ("comb_part1", "comb_part2"),
            ("fork_part1", "fork_part2"),
            ("knife_part1", "knife_part2"),
            ("random_part1", "random_part2"),
            ("rooms_part1", "rooms_part2"),
            ("wheels_part1", "wheels_part2"),
            ("star_200_1", "star_200_2"),
        ):
            a = read_cgal_dat(DATA / f"{p}.dat")[0]
            b = read_cgal_dat(DATA / f"{q}.dat")[0]
            run_case(f"{p} + {q}", a, b, driver, args.cgal_rc_max, args.reps)


if __name__ == "__main__":
    main()
