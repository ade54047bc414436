"""Offsetting by a disk: minkowski2d against shapely (GEOS) buffer, pyclipper (Clipper 1)
and pyclipr (Clipper 2), at tolerances 1e-2·r, 1e-4·r and 1e-6·r.

For each input and tolerance ε, every tool is asked for the same offset with its own
accuracy knob set to ε: shapely's ``quad_segs`` from ε (sagitta ≤ ε per quarter-circle
chord), Clipper's ``arc_tolerance`` = ε (coordinates scaled to integers by 2⁴⁰ / max |x|).
Reported per tool: the best time of a few runs, the vertex count and its ratio to the
minimum (``Σ ceil(θ / 2·acos(1 − ε/r))`` over the arcs of the exact offset, from
``mk.offset_arcs``), the error on each side in units of ε (``out``: how far the result
reaches beyond the true offset's boundary, ``in``: how far it falls inside; measured at
the vertices and, for ``in``, along every edge, with GEOS distances), whether it contains
the true set (``in`` ≤ 0 up to 1e-9·r) and whether it is a valid polygon.

CGAL: ``approximated_offset_2`` / ``approximated_inset_2`` with the same ε (one-sided
outer by construction; its result is arcs with rational end points, reported as the
number of pieces), through ``cgal_offset_driver.cpp`` built once with g++ -O2 against
Debian's libcgal-dev into ``build/cgal_offset_driver``; simple polygons only, the time
excludes reading the file and process start.

Run: ``python benchmarks/bench_offset.py [--repeat 5] [--quick] [--no-cgal]``

**The ESICUP row** (issue 16), ``--esicup``: every part (piece type) of every ESICUP
instance in ``../shared/data/esicup``, grown and shrunk by 3 % of its bounding-box
diagonal, ``r = 0.03·diag``, at the tolerance ``ε = --esicup-rel · r`` (default 1e-3):
``mk.offset(part, ±r, tolerance=ε)`` (``approx="outer"``, the default, and ``"inner"``)
against ``shapely.buffer(part, ±r, quad_segs=q)`` at equal error. Equal error, matched by
measurement: shapely's chords are inscribed in the true arcs, so its error is the
sagitta, ``r(1 − cos(α/2))`` for a chord of angle α; ``quad_segs`` sets α ≈ 90°/q, but
GEOS *rounds* the number of chords of each fillet (``round(θ / (90°/q))``), so a fillet
can get chords up to 1.5× longer and up to 2.25× the nominal error. For each part and
sign, ``q`` is the smallest value whose result's measured maximum deviation from the
true offset (both sides, in units of ε, with the GEOS distances of ``errors``) is at
most ε, searched from the nominal ``ceil(90° / 2·acos(1 − ε/r))``; ours is built to be
within ε (one-sided) and its measured deviation is printed too. Times: best of
``--repeat``; ``ratio`` = ours / shapely (sum over the parts of an instance; the total
line also gives the geometric mean of per-part ratios). Run: ``python
benchmarks/bench_offset.py --esicup [--instances albano ...] [--esicup-rel 1e-3]``.
"""

from __future__ import annotations

import argparse
import math
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
ESICUP = ROOT.parent / "shared" / "data" / "esicup"


def build_driver() -> str | None:
    """Path of the CGAL driver, building it if needed (see ``_cgal.py``)."""
    return _cgal.build_driver("cgal_offset_driver", "approximated_offset_2.h")


def run_cgal(driver: str, g, d: float, eps: float, repeat: int):
    """(seconds, pieces, components, holes) of CGAL's approximated offset / inset of a
    simple polygon (None for polygons with holes or on failure)."""
    if g.geom_type != "Polygon" or len(g.interiors):
        return None
    c = shapely.get_coordinates(g.exterior)[:-1]
    with tempfile.TemporaryDirectory() as tmp:
        f = Path(tmp) / "p.dat"
        f.write_text(f"{len(c)}\n" + "\n".join(f"{x!r} {y!r}" for x, y in c.tolist()) + "\n")
        res = subprocess.run(
            [driver, "approx", str(f), repr(d), repr(eps), str(repeat)],
            capture_output=True,
            text=True,
            timeout=600,
        )
    if res.returncode:
        return None
    t, pieces, comps, holes = res.stdout.split()
    return float(t), int(pieces), int(comps), int(holes)


def star(n: int, R: float, r: float) -> np.ndarray:
    k = np.arange(n)
    rad = np.where(k % 2 == 0, R, r)
    th = 2 * np.pi * k / n
    return np.c_[rad * np.cos(th), rad * np.sin(th)]


def cases() -> list:
    """(name, polygon, distance)"""
    sq = [(0, 0), (4, 0), (4, 4), (0, 4)]
    L = [(0, 0), (4, 0), (4, 1), (1, 1), (1, 4), (0, 4)]
    frame = shapely.Polygon(sq, [[(1, 1), (1, 3), (3, 3), (3, 1)]])
    C = [(0, 0), (6, 0), (6, 6), (0, 6), (0, 3.5), (1, 3.5), (1, 5), (5, 5), (5, 1), (1, 1),
         (1, 2.5), (0, 2.5)]  # fmt: skip
    dumb = [(0, 0), (2, 0), (2, 0.5), (4, 0.5), (4, 0), (6, 0), (6, 2), (4, 2), (4, 1.5),
            (2, 1.5), (2, 2), (0, 2)]  # fmt: skip
    zig = [(0, 0), (1, 2), (2, 0), (3, 2), (4, 0), (5, 2), (6, 0), (6, -1), (0, -1)]
    out = [
        ("square", sq, 0.5),
        ("L", L, 0.3),
        ("frame", frame, 0.3),
        ("C", C, 0.7),
        ("dumbbell", dumb, 0.3),
        ("zigzag", zig, 0.3),
        ("star100", star(100, 1.0, 0.6), 0.02),
        ("star1000", star(1000, 1.0, 0.8), 0.002),
        ("star1000-wide", star(1000, 1.0, 0.6), 0.05),
    ]
    if DATA.exists():
        from minkowski2d.io import read_cgal_dat

        # radii as in CGAL's own test_approx_offset.cmd where given
        for name, r in (("comb_part1", 1.0), ("random_part1", 5.0), ("rooms_part1", 3.0),
                        ("pwh1", 0.3)):  # fmt: skip
            p = DATA / f"{name}.dat"
            if p.exists():
                out.append((name, read_cgal_dat(p)[0], r))
    res = []
    for name, p, r in out:
        res.append((name + "+", p, r))
        # rooms_part1's walls are thinner than r: a shrink by r / 2 erases it
        res.append((name + "-", p, -r / (12 if name == "rooms_part1" else 2)))
    return res


def as_shapely(p) -> shapely.Geometry:
    g = p if hasattr(p, "geom_type") else shapely.Polygon(np.asarray(p, float))
    return shapely.orient_polygons(g)


# --------------------------------------------------------------------------------------
# peers


def run_shapely(g, d, eps):
    r = abs(d)
    q = max(1, math.ceil((math.pi / 2) / (2 * math.acos(max(-1.0, 1 - eps / r)))))
    return lambda: shapely.buffer(g, d, quad_segs=q)


def _rings(g):
    return [shapely.get_coordinates(x)[:-1] for x in shapely.get_rings(shapely.get_parts(g))]


def _from_paths(paths):
    polys = [shapely.Polygon(p) for p in paths if len(p) >= 3]
    polys.sort(key=lambda x: -abs(x.area))
    if not polys:
        return shapely.Polygon()
    g = polys[0]
    for h in polys[1:]:
        g = shapely.symmetric_difference(g, h)
    return g


def run_pyclipper(g, d, eps):
    import pyclipper

    rings = _rings(g)
    S = 2.0**40 / max(float(np.abs(np.concatenate(rings)).max()), abs(d))
    paths = [np.rint(x * S).astype(np.int64).tolist() for x in rings]

    def f():
        co = pyclipper.PyclipperOffset(2.0, eps * S)
        co.AddPaths(paths, pyclipper.JT_ROUND, pyclipper.ET_CLOSEDPOLYGON)
        return co.Execute(d * S)

    return f, lambda res: _from_paths([np.asarray(p, float) / S for p in res])


def run_pyclipr(g, d, eps):
    import pyclipr

    rings = _rings(g)
    S = 2.0**40 / max(float(np.abs(np.concatenate(rings)).max()), abs(d))

    def f():
        co = pyclipr.ClipperOffset()
        co.scaleFactor = int(S)
        co.arcTolerance = eps * int(S)
        co.addPaths(rings, pyclipr.JoinType.Round, pyclipr.EndType.Polygon)
        return co.execute(d)

    return f, lambda res: _from_paths([np.asarray(p, float) for p in res])


# --------------------------------------------------------------------------------------
# measurement


def best(f, repeat):
    """(the least CPU time of ``repeat`` runs, the result): CPU time, as the machine is
    shared (every call here runs on one thread)."""
    t = math.inf
    res = None
    for _ in range(repeat):
        t0 = time.process_time()
        res = f()
        t = min(t, time.process_time() - t0)
    return t, res


def errors(out, P, d):
    """(out, in): how far the boundary of ``out`` reaches beyond / falls inside the true
    offset's boundary (GEOS float distances). Vertices are measured by their distance to
    ``∂P``, edges by their least distance to it: that is where a chord is farthest from
    its arc, inside the true set for a grow (``in``) and beyond it for a shrink
    (``out``: a chord around a reflex vertex of ``P`` comes closer to it than ``r``)."""
    r = abs(d)
    if out.is_empty:
        return math.nan, math.nan
    ref = P if d > 0 else shapely.boundary(P)
    E = np.concatenate(
        [np.stack([c[:-1], c[1:]], 1) for c in
         (shapely.get_coordinates(x) for x in shapely.get_rings(shapely.get_parts(out)))]
    )  # fmt: skip
    tree = shapely.STRtree(
        np.concatenate(
            [shapely.linestrings(np.stack([c[:-1], c[1:]], 1)) for c in
             (shapely.get_coordinates(x) for x in shapely.get_rings(shapely.get_parts(P)))]
        )
    )  # fmt: skip
    _, dv = tree.query_nearest(shapely.points(E[:, 0]), return_distance=True, all_matches=False)
    _, de = tree.query_nearest(shapely.linestrings(E), return_distance=True, all_matches=False)
    del ref
    if d > 0:  # signed: positive = beyond the true boundary (outside the true set)
        s_vert, s_edge = dv - r, de - r
        beyond = float(s_vert.max())
    else:
        s_vert, s_edge = r - dv, r - de
        beyond = float(max(s_vert.max(), s_edge.max()))
    return max(0.0, beyond), max(0.0, float(-min(s_edge.min(), s_vert.min())))


def minimum(arcs, eps):
    """Σ ceil(θ / 2·acos(1 − ε/r)) over the arcs, plus one vertex per junction of two
    straight pieces (a corner no approximation can avoid)."""
    r = arcs.radius
    phi = 2 * math.acos(max(-1.0, 1 - eps / r))
    tot = 0
    for ring in arcs.rings:
        b = ring[:, 2]
        sw = np.abs(4 * np.arctan(b[b != 0]))
        tot += int(np.ceil(sw / phi).sum())
        tot += int(((b == 0) & (np.roll(b, 1) == 0)).sum())
    return tot


# --------------------------------------------------------------------------------------
# the ESICUP row


def deviation(out, P, d) -> float:
    """The measured maximum distance between the boundary of ``out`` and the true
    offset's, either side (see ``errors``). An empty result counts as exact: a shrink
    erases a part narrower than 2r (ours, one-sided outside, is empty only then)."""
    if out.is_empty:
        return 0.0
    eo, ei = errors(out, P, d)
    return max(eo, ei)


def equal_error_quad_segs(P, d: float, eps: float) -> int:
    """The smallest ``quad_segs`` whose ``shapely.buffer(P, d)`` deviates at most ``eps``
    from the true offset, as measured, searched from the nominal value (``run_shapely``'s
    formula: exact for chords of exactly 90°/q, which GEOS does not always use)."""
    r = abs(d)
    q0 = max(1, math.ceil((math.pi / 2) / (2 * math.acos(max(-1.0, 1 - eps / r)))))

    def ok(q):
        return deviation(shapely.buffer(P, d, quad_segs=q), P, d) <= eps

    q = q0
    if ok(q):
        while q > 1 and ok(q - 1):
            q -= 1
        return q
    while not ok(q):
        q += 1
        if q > 4 * q0 + 8:  # GEOS's rounding is bounded by 1.5x: never reached
            raise RuntimeError(f"no quad_segs up to {q} is within {eps}")
    return q


def esicup(args) -> int:
    names = args.instances or sorted(p.stem for p in ESICUP.glob("*.json"))
    if not names:
        print(f"no ESICUP instances at {ESICUP}")
        return 1
    rel = args.esicup_rel
    print(f"python {sys.version.split()[0]}, shapely {shapely.__version__} "
          f"(GEOS {shapely.geos_version_string}), CPU time, best of {args.repeat}")  # fmt: skip
    print(f"every ESICUP part, distance ±3 % of its bounding-box diagonal, ε = {rel:g}·r; "
          "shapely's quad_segs: the least within ε, as measured")  # fmt: skip
    print("per call: mk.offset / shapely.buffer on each part; batch: one mk.offset_many "
          "on the instance's parts (a distance and ε per part) / shapely.buffer on the "
          "same array (one call per quad_segs)")  # fmt: skip
    hdr = (f"{'instance':10s} {'sign':>4s} {'parts':>5s} {'outer ms':>9s} {'inner ms':>9s} "
           f"{'shapely ms':>10s} {'q':>7s} {'outer/shp':>9s} {'inner/shp':>9s} "
           f"{'batch/shp':>9s} {'ours dev/ε':>10s} {'shp dev/ε':>9s}")  # fmt: skip
    print(hdr)
    keys = ("outer", "inner", "shapely", "batch", "shapely_batch")
    tot = dict.fromkeys(keys, 0.0)
    logs: dict = {"outer": [], "inner": []}
    worst_ours = 0.0
    for name in names:
        parts = mk.read_esicup(ESICUP / f"{name}.json")["parts"]
        for sign in (1, -1):
            row, qs, dev_o, dev_s = _esicup_row(parts, sign, rel, args.repeat, logs)
            for k in tot:
                tot[k] += row[k]
            worst_ours = max(worst_ours, dev_o)
            qr = f"{min(qs)}-{max(qs)}" if min(qs) != max(qs) else str(qs[0])
            print(f"{name:10s} {'+' if sign > 0 else '-':>4s} {len(parts):5d} "
                  f"{row['outer'] * 1e3:9.2f} {row['inner'] * 1e3:9.2f} "
                  f"{row['shapely'] * 1e3:10.2f} {qr:>7s} "
                  f"{row['outer'] / row['shapely']:9.2f} {row['inner'] / row['shapely']:9.2f} "
                  f"{row['batch'] / row['shapely_batch']:9.2f} "
                  f"{dev_o:10.3f} {dev_s:9.3f}", flush=True)  # fmt: skip
    n = len(logs["outer"])
    print(f"\ntotal over {n} offsets, per call: ours (outer) {tot['outer']:.3f} s, ours (inner) "
          f"{tot['inner']:.3f} s, shapely {tot['shapely']:.3f} s; ratio outer/shapely "
          f"{tot['outer'] / tot['shapely']:.2f}x (geometric mean per offset "
          f"{math.exp(np.mean(logs['outer'])):.2f}x), inner/shapely "
          f"{tot['inner'] / tot['shapely']:.2f}x (geometric mean "
          f"{math.exp(np.mean(logs['inner'])):.2f}x); ours' largest measured deviation "
          f"{worst_ours:.4f} ε")  # fmt: skip
    print(f"batch (outer, one call per instance and sign): ours {tot['batch']:.3f} s, "
          f"shapely {tot['shapely_batch']:.3f} s; ratio "
          f"{tot['batch'] / tot['shapely_batch']:.2f}x")  # fmt: skip
    return 0


def _esicup_row(parts, sign, rel, repeat, logs):
    """One instance and sign of the ESICUP row: per-call and batch times, quad_segs,
    the largest measured deviations."""
    row = dict.fromkeys(("outer", "inner", "shapely", "batch", "shapely_batch"), 0.0)
    qs, dev_o, dev_s, ds = [], 0.0, 0.0, []
    for P in parts:
        x0, y0, x1, y1 = P.bounds
        r = 0.03 * math.hypot(x1 - x0, y1 - y0)
        d, eps = sign * r, rel * r
        ds.append(d)
        t_o, res = best(lambda P=P, d=d, eps=eps: mk.offset(P, d, tolerance=eps), repeat)
        dev_o = max(dev_o, deviation(res, P, d) / eps)
        t_i, _ = best(
            lambda P=P, d=d, eps=eps: mk.offset(P, d, tolerance=eps, approx="inner"), repeat
        )
        q = equal_error_quad_segs(P, d, eps)
        qs.append(q)
        t_s, res = best(lambda P=P, d=d, q=q: shapely.buffer(P, d, quad_segs=q), repeat)
        dev_s = max(dev_s, deviation(res, P, d) / eps)
        row["outer"] += t_o
        row["inner"] += t_i
        row["shapely"] += t_s
        logs["outer"].append(math.log(t_o / t_s))
        logs["inner"].append(math.log(t_i / t_s))
    arr = np.array(parts, dtype=object)
    dv = np.array(ds)
    row["batch"], _ = best(lambda: mk.offset_many(arr, dv, tolerance=rel * np.abs(dv)), repeat)
    qa = np.array(qs)
    groups = [(np.flatnonzero(qa == q), q) for q in sorted(set(qs))]
    row["shapely_batch"], _ = best(
        lambda: [shapely.buffer(arr[k], dv[k], quad_segs=q) for k, q in groups], repeat
    )
    return row, qs, dev_o, dev_s


def stars(args) -> int:
    """The 1000-vertex stars at ε = 1e-6·r, grown by r and shrunk by r/2: ours against
    shapely.buffer at the nominal quad_segs (its error may exceed ε), and the ratio."""
    print(f"CPU time, best of {args.repeat}; ε = 1e-6·r")
    print(f"{'case':16s} {'ours ms':>9s} {'shapely ms':>10s} {'ratio':>7s} {'verts':>8s}")
    for name, p, r in (("star1000", star(1000, 1.0, 0.8), 0.002),
                       ("star1000-wide", star(1000, 1.0, 0.6), 0.05)):  # fmt: skip
        g = shapely.Polygon(p)
        for d in (r, -r / 2):
            eps = 1e-6 * abs(d)
            t, out = best(lambda g=g, d=d, eps=eps: mk.offset(g, d, tolerance=eps), args.repeat)
            ts, _ = best(run_shapely(g, d, eps), args.repeat)
            nv = int(shapely.get_num_coordinates(out))
            print(f"{name + ('+' if d > 0 else '-'):16s} {t * 1e3:9.1f} {ts * 1e3:10.1f} "
                  f"{t / ts:7.2f} {nv:8d}")  # fmt: skip
    return 0


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--quick", action="store_true", help="1e-2 and 1e-4 only")
    ap.add_argument("--no-cgal", action="store_true", help="skip CGAL")
    ap.add_argument("--esicup", action="store_true", help="only the ESICUP row (issue 16)")
    ap.add_argument("--esicup-rel", type=float, default=1e-3, help="ε / r of the ESICUP row")
    ap.add_argument("--instances", nargs="*", help="ESICUP instances (default: all)")
    ap.add_argument("--stars", action="store_true", help="only the 1000-vertex stars at 1e-6·r")
    args = ap.parse_args(argv)
    if args.esicup:
        return esicup(args)
    if args.stars:
        return stars(args)
    driver = None if args.no_cgal else build_driver()
    cgal_ratio = []
    rels = (1e-2, 1e-4) if args.quick else (1e-2, 1e-4, 1e-6)
    tools = ["mk-outer", "mk-inner", "shapely", "pyclipper", "pyclipr"]
    ratios = {t: [] for t in tools}
    goals = {}
    print(f"python {sys.version.split()[0]}, shapely {shapely.__version__} "
          f"(GEOS {shapely.geos_version_string}), best of {args.repeat}")  # fmt: skip
    hdr = (f"{'case':16s} {'tool':9s} {'ms':>8s} {'verts':>7s} {'/min':>5s} {'out/ε':>7s} "
           f"{'in/ε':>7s} {'⊇true':>5s} {'valid':>5s}")  # fmt: skip
    for rel in rels:
        print(f"\n=== ε = {rel:g}·r ===")
        print(hdr)
        for name, p, d in cases():
            g = as_shapely(p)
            r = abs(d)
            eps = rel * r
            ta, arcs = best(lambda p=p, d=d: mk.offset_arcs(p, d), args.repeat)
            mn = max(1, minimum(arcs, eps))
            if rel == rels[0]:
                print(
                    f"{name:16s} {'arcs':9s} {ta * 1e3:8.2f} {sum(len(x) for x in arcs.rings):7d}"
                )
            row = {}
            for tool in tools:
                if tool.startswith("mk"):
                    ap_ = tool[3:]
                    f = lambda p=p, d=d, eps=eps, ap_=ap_: mk.offset(  # noqa: E731
                        p, d, tolerance=eps, approx=ap_
                    )
                    conv = None
                elif tool == "shapely":
                    f, conv = run_shapely(g, d, eps), None
                elif tool == "pyclipper":
                    f, conv = run_pyclipper(g, d, eps)
                else:
                    f, conv = run_pyclipr(g, d, eps)
                t, res = best(f, args.repeat)
                out = conv(res) if conv else res
                eo, ei = errors(out, g, d)
                nv = int(shapely.get_num_coordinates(out)) - len(shapely.get_rings(
                    shapely.get_parts(out)))  # fmt: skip
                cont = bool(ei <= 1e-9 * r) if not math.isnan(ei) else None
                row[tool] = t
                print(f"{name:16s} {tool:9s} {t * 1e3:8.2f} {nv:7d} {nv / mn:5.2f} "
                      f"{eo / eps:7.2f} {ei / eps:7.2f} {str(cont):>5s} "
                      f"{str(bool(out.is_valid)):>5s}")  # fmt: skip
                if name.startswith("star1000+") or name.startswith("star1000-"):
                    if rel == 1e-4 and tool == "mk-outer":
                        goals[name] = t
            for tool in tools:
                ratios[tool].append(row[tool] / row["pyclipper"])
            cg = run_cgal(driver, g, d, eps, args.repeat) if driver else None
            if cg is not None:
                t, pieces, comps, holes = cg
                cgal_ratio.append(t / row["pyclipper"])
                print(f"{name:16s} {'cgal-apx':9s} {t * 1e3:8.2f} {pieces:7d} pieces, "
                      f"{comps} parts, {holes} holes (one-sided by construction)")  # fmt: skip
            if name.startswith("star1000+") and rel == 1e-4:
                goals["arcs"] = ta
    print("\n=== geometric mean of time / pyclipper's time, over all cases and tolerances ===")
    for tool in tools:
        print(f"{tool:10s} {math.exp(np.mean(np.log(ratios[tool]))):6.3f}")
    if cgal_ratio:
        print(f"{'cgal-apx':10s} {math.exp(np.mean(np.log(cgal_ratio))):6.3f}  "
              f"(its {len(cgal_ratio)} cases: simple polygons)")  # fmt: skip
    print("\n=== goals (1000-vertex star, radii 1/0.8, r = 0.002, ε = 1e-4·r) ===")
    for k, lim in (("star1000+", 50), ("star1000-", 20), ("arcs", 10)):
        if k in goals:
            print(f"{k:10s} {goals[k] * 1e3:7.2f} ms (goal ≤ {lim} ms)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
