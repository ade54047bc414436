"""No-fit polygons of ESICUP instances: minkowski2d against CGAL and Clipper (SVGnest).

For every instance in ../shared/data/esicup (15 classic + 10 gardeyn), every ordered pair
of piece types and every pair of allowed rotations: NFP(rot A, rot B) = rot A ⊕ (−rot B).
The gardeyn instances are large, so only a sample of part pairs is taken there
(``--gardeyn-pairs``, all rotations of each).

* minkowski2d: ``mk.no_fit_polygons(parts, rotations=..., pairs=...)``, timed in process
  (everything: reading the parts, rotations, decomposition, sums, unions).
* CGAL ``minkowski_sum_2`` (Epeck, reduced convolution, its default): ``cgal_nfp_driver.cpp``
  built once into ``build/cgal_nfp_driver``; timed inside the driver (sums only). Two
  timings: every requested NFP (``CGAL all``, a loop as a user would write it) and only
  the distinct ones that minkowski2d computes (``CGAL distinct``: one per unordered pair
  and relative rotation; the others are exact rotations of them).
* pyclipper as SVGnest calls it: ``MinkowskiSum(A, −B, True)`` on the outer rings
  (coordinates times 1e7, rounded), keeping the largest path (SVGnest's NFP); timed on
  every requested NFP, once (not on gardeyn unless ``--clipper-gardeyn``: 43 s for
  the 192 NFPs of gardeyn0).

Agreement: an NFP agrees when its area is within 1e-9 relative of CGAL's exact area and it
has as many holes. Run: ``python benchmarks/bench_nfp.py [--instances albano fu ...]
[--gardeyn-pairs 12] [--no-cgal] [--no-clipper]``.
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
DATA = ROOT.parent / "shared" / "data" / "esicup"
CLASSIC = [
    "albano", "blaz", "dagli", "dighe1", "dighe2", "fu", "jakobs1", "jakobs2", "mao",
    "marques", "shapes0", "shapes1", "shirts", "swim", "trousers",
]  # fmt: skip
GARDEYN = [f"gardeyn{k}" for k in range(10)]
REL = 1e-9


def build_driver() -> str | None:
    """Path of the CGAL driver, building it if needed (see ``_cgal.py``)."""
    return _cgal.build_driver("cgal_nfp_driver", "minkowski_sum_2.h")


def rot(c: np.ndarray, angle: int) -> np.ndarray:
    """Exact rotation by a multiple of 90 degrees (as minkowski2d does)."""
    q = (int(angle) // 90) % 4
    x, y = c[:, 0], c[:, 1]
    return [c, np.stack([-y, x], 1), -c, np.stack([y, -x], 1)][q]


def canonical(key: tuple) -> tuple:
    """The distinct NFP a key is a rotation of (the rule of mk.no_fit_polygons)."""
    i, ri, j, rj = key
    d = ((rj - ri) // 90) % 4
    c1, c2 = (i, 0, j, d), (j, 0, i, (-d) % 4)
    return min(c1, c2)


def holes(g) -> int:
    return int(sum(len(p.interiors) for p in shapely.get_parts(g)))


def run_cgal(driver: str, rings: list, keys: list) -> tuple[float, list] | None:
    """CGAL's time and (area, holes) per key; rings[(i, r)] is part i rotated by r."""
    index: dict = {}
    polys = []

    def idx(k, c):
        if k not in index:
            index[k] = len(polys)
            polys.append(c)
        return index[k]

    lines = []
    for i, ri, j, rj in keys:
        a = idx(("A", i, ri), rings[(i, ri)])
        b = idx(("B", j, rj), -rings[(j, rj)])
        lines.append(f"{a} {b}")
    with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
        f.write(f"{len(polys)}\n")
        for c in polys:
            # CGAL needs a simple polygon: drop consecutive repeated vertices (gardeyn5,
            # gardeyn6 and gardeyn8 have them; the polygon is the same)
            c = c[(c != np.roll(c, 1, axis=0)).any(axis=1)]
            f.write(f"{len(c)} " + " ".join(f"{repr(float(x))} {repr(float(y))}" for x, y in c))
            f.write("\n")
        f.write(f"{len(lines)}\n" + "\n".join(lines) + "\n")
    res = subprocess.run([driver, "rc", f.name], capture_output=True, text=True)
    Path(f.name).unlink()
    if res.returncode:
        print("CGAL failed:", res.stderr[-300:])
        return None
    out = res.stdout.split("\n")
    vals = [(float(a), int(h)) for a, h in (ln.split() for ln in out[: len(keys)])]
    sec = float(out[len(keys)].split()[1])
    return sec, vals


def run_clipper(rings: dict, keys: list) -> tuple[float, list]:
    """pyclipper as SVGnest calls it: the largest path of MinkowskiSum(A, −B, closed)."""
    import pyclipper

    S = 1e7
    ints = {k: [(round(x * S), round(y * S)) for x, y in c.tolist()] for k, c in rings.items()}
    neg = {k: [(-x, -y) for x, y in v] for k, v in ints.items()}
    areas = []
    t0 = time.perf_counter()
    for i, ri, j, rj in keys:
        paths = pyclipper.MinkowskiSum(ints[(i, ri)], neg[(j, rj)], True)
        best = max(paths, key=lambda p: abs(pyclipper.Area(p)))
        areas.append(abs(pyclipper.Area(best)) / (S * S))
    return time.perf_counter() - t0, areas


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--instances", nargs="*", default=CLASSIC + GARDEYN)
    ap.add_argument("--gardeyn-pairs", type=int, default=12, help="sampled part pairs")
    ap.add_argument("--no-cgal", action="store_true")
    ap.add_argument("--no-clipper", action="store_true")
    ap.add_argument(
        "--clipper-gardeyn",
        action="store_true",
        help="run Clipper on gardeyn too (slow: 43 s for 192 NFPs of gardeyn0)",
    )
    ap.add_argument("--reps", type=int, default=3, help="best of REPS for minkowski2d")
    ap.add_argument("--threads", type=int, default=1)
    args = ap.parse_args()
    driver = None if args.no_cgal else build_driver()
    hdr = (
        f"{'instance':10} {'NFPs':>6} {'dist.':>6} {'ours s':>8} {'CGAL all':>9} "
        f"{'ratio':>6} {'CGAL dist':>9} {'ratio':>6} {'agree':>11} "
        f"{'Clipper s':>9} {'Clip bad':>8}"
    )
    print(hdr)
    totals: dict = {}
    for name in args.instances:
        d = mk.read_esicup(DATA / f"{name}.json")
        parts, R = d["parts"], d["rotations"]
        n = len(parts)
        if name.startswith("gardeyn"):
            allp = [(i, j) for i in range(n) for j in range(n)]
            rng = np.random.default_rng([12, *map(ord, name)])  # the same sample every run
            pick = rng.choice(len(allp), min(args.gardeyn_pairs, len(allp)), replace=False)
            pairs = [allp[k] for k in sorted(pick)]
        else:
            pairs = [(i, j) for i in range(n) for j in range(n)]
        keys = [(i, ri, j, rj) for i, j in pairs for ri in R[i] for rj in R[j]]
        dist = sorted({canonical(k) for k in keys})
        best = np.inf
        for _ in range(args.reps):
            t0 = time.perf_counter()
            nfps = mk.no_fit_polygons(parts, rotations=R, pairs=pairs, threads=args.threads)
            best = min(best, time.perf_counter() - t0)
        rings = {
            (i, r): rot(shapely.get_coordinates(parts[i].exterior)[:-1], r)
            for i in range(n)
            for r in R[i]
        }
        row = {"n": len(keys), "dist": len(dist), "ours": best}
        agree = "-"
        if driver:
            ca = run_cgal(driver, rings, keys)
            # distinct job (i, 0, j, d): part i at 0 against part j turned by d quarters
            dkeys = [(i, 0, j, 90 * dd) for i, _, j, dd in dist]
            for i, _, j, rj in dkeys:
                for pi, r in ((i, 0), (j, rj)):
                    if (pi, r) not in rings:
                        rings[(pi, r)] = rot(shapely.get_coordinates(parts[pi].exterior)[:-1], r)
            cd = run_cgal(driver, rings, dkeys)
            if ca:
                row["cgal"], vals = ca
                ok = 0
                worst = 0.0
                for k, (ar, h) in zip(keys, vals, strict=True):
                    g = nfps[k]
                    rel = abs(g.area - ar) / ar
                    worst = max(worst, rel)
                    ok += rel <= REL and holes(g) == h
                row["agree"] = (ok, len(keys))
                row["worst"] = worst
                agree = f"{ok}/{len(keys)}"
            if cd:
                row["cgal_dist"] = cd[0]
        clip = ("-", "-")
        if not args.no_clipper and (args.clipper_gardeyn or not name.startswith("gardeyn")):
            try:
                tc, areas = run_clipper(rings, keys)
                if driver and ca:
                    bad = sum(
                        abs(a - ar) > REL * ar for a, (ar, _) in zip(areas, vals, strict=True)
                    )
                else:
                    bad = sum(
                        abs(a - nfps[k].area) > REL * nfps[k].area
                        for a, k in zip(areas, keys, strict=True)
                    )
                row["clip"], row["clip_bad"] = tc, bad
                clip = (f"{tc:.3f}", str(bad))
            except ImportError:
                pass
        totals[name] = row
        c = row.get("cgal")
        cdd = row.get("cgal_dist")
        print(
            f"{name:10} {row['n']:6d} {row['dist']:6d} {best:8.3f} "
            f"{(f'{c:.3f}' if c else '-'):>9} {(f'{best / c:.2f}' if c else '-'):>6} "
            f"{(f'{cdd:.3f}' if cdd else '-'):>9} {(f'{best / cdd:.2f}' if cdd else '-'):>6} "
            f"{agree:>11} {clip[0]:>9} {clip[1]:>8}",
            flush=True,
        )
    for label, group in (("classic", CLASSIC), ("gardeyn", GARDEYN)):
        rows = [totals[k] for k in group if k in totals]
        if not rows:
            continue
        ours = sum(r["ours"] for r in rows)
        line = f"{label} total: {sum(r['n'] for r in rows)} NFPs, ours {ours:.3f} s"
        if all("cgal" in r for r in rows):
            cg = sum(r["cgal"] for r in rows)
            cgd = sum(r.get("cgal_dist", np.nan) for r in rows)
            ok = sum(r["agree"][0] for r in rows)
            worst = max(r["worst"] for r in rows)
            line += (
                f", CGAL all {cg:.3f} s ({ours / cg:.2f}x), CGAL distinct {cgd:.3f} s "
                f"({ours / cgd:.2f}x); agree {ok}/{sum(r['n'] for r in rows)}, worst "
                f"relative area difference {worst:.1e}"
            )
        if all("clip" in r for r in rows):
            line += (
                f"; Clipper {sum(r['clip'] for r in rows):.3f} s, "
                f"{sum(r['clip_bad'] for r in rows)} wrong areas"
            )
        print(line)
    sys.stdout.flush()


if __name__ == "__main__":
    main()
