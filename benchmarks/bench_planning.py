"""Motion planning: minkowski2d.MotionPlanner against extremitypathfinder and pyvisgraph.

Seeded scenes of K convex obstacles (4-8 vertices, int coordinates) inside a square
workspace, one per cell of a jittered grid (no two obstacles touch, which the peers
require); a point robot, so every tool plans on the same free space. Q random free
start/goal pairs per scene. One run; times are wall clock.

Columns: preparation time; median query time; invalid paths (a segment meets an
obstacle's open interior, or the endpoints are not the query's: checked with the exact
predicates of the core); false "no path" (the tool reports none where a valid path
exists); length over optimal (max relative excess over minkowski2d's exact shortest
path, which tests/test_planning.py checks against a brute-force exact reference).

Usage::

    python benchmarks/bench_planning.py                 # K = 10, 100, 1000 (peers to 100)
    python benchmarks/bench_planning.py --ks 10 100 1000 10000 --peer-max-k 100

Also a checkerboard scene (``--checker 50``): unit squares touching at their corners, so
the free space is connected only through pinch points -- the closed free space makes those
passages open, and the peers' handling of touching obstacles is what is measured there.
"""

from __future__ import annotations

import argparse
import math
import statistics
import time

import numpy as np

import minkowski2d as mk

CELL = 1000


def scene(K: int, seed: int) -> tuple[list[np.ndarray], tuple[int, int, int, int]]:
    rng = np.random.default_rng(seed)
    n = math.ceil(math.sqrt(K))
    cells = rng.permutation(n * n)[:K]
    obs = []
    for c in cells:
        i, j = divmod(int(c), n)
        r = rng.uniform(0.2, 0.45) * CELL
        jit = (0.5 * CELL - r) * 0.9
        cx = (i + 0.5) * CELL + rng.uniform(-jit, jit)
        cy = (j + 0.5) * CELL + rng.uniform(-jit, jit)
        m = int(rng.integers(4, 9))
        ang = np.sort(rng.uniform(0, 2 * np.pi, m))
        pts = np.stack([cx + r * np.cos(ang), cy + r * np.sin(ang)], axis=1)
        pts = np.round(pts).astype(np.int64)
        h = mk.convex_hull(pts)
        if len(h) < 3:
            h = np.array([[cx - 10, cy - 10], [cx + 10, cy - 10], [cx, cy + 10]], np.int64)
        obs.append(np.asarray(h, np.int64))
    return obs, (0, 0, n * CELL, n * CELL)


def checkerboard(K: int, seed: int) -> tuple[list[np.ndarray], tuple[int, int, int, int]]:
    """K unit squares (side CELL) on the black cells of a checkerboard: neighbours touch
    at corners only, so the free space is connected through pinch points alone (an
    ordinary tiled floor plan); seeded for the same interface as :func:`scene`."""
    n = max(2, math.ceil(math.sqrt(2 * K)))
    obs = []
    for i in range(n):
        for j in range(n):
            if (i + j) % 2 == 0 and len(obs) < K:
                x, y = i * CELL, j * CELL
                obs.append(np.array([[x, y], [x + CELL, y], [x + CELL, y + CELL], [x, y + CELL]]))
    return obs, (0, 0, n * CELL, n * CELL)


def queries(obs: list, box, Q: int, seed: int) -> list:
    """Q start/goal pairs not strictly inside any obstacle (shapely: the points are ints
    far from every boundary in these scenes; the planner checks them exactly anyway)."""
    import shapely

    tree = shapely.STRtree([shapely.Polygon(o) for o in obs])
    rng = np.random.default_rng(seed + 1)
    out: list = []
    while len(out) < 2 * Q:
        p = rng.integers(box[0] + 1, box[2], size=(4 * Q, 2))
        hit = tree.query(shapely.points(p), predicate="intersects")
        bad = set(hit[0].tolist())
        out += [tuple(int(v) for v in q) for i, q in enumerate(p) if i not in bad]
    return list(zip(out[:Q], out[Q : 2 * Q]))


def valid(check, path: list, s, g) -> bool:
    if not path or tuple(map(float, path[0])) != tuple(map(float, s)):
        return False
    if tuple(map(float, path[-1])) != tuple(map(float, g)):
        return False
    return all(
        check(float(a[0]), float(a[1]), float(b[0]), float(b[1])) for a, b in zip(path, path[1:])
    )


def length(path: list) -> float:
    return math.fsum(
        math.hypot(float(b[0]) - float(a[0]), float(b[1]) - float(a[1]))
        for a, b in zip(path, path[1:])
    )


def run_ours(obs, box, qs, threads=1):
    t0 = time.perf_counter()
    pl = mk.MotionPlanner(obs, workspace=box, threads=threads)
    prep = time.perf_counter() - t0
    times, paths = [], []
    for s, g in qs:
        t0 = time.perf_counter()
        try:
            p = pl.shortest_path(s, g).points.tolist()
        except mk.errors.NoPathError:
            p = None
        times.append(time.perf_counter() - t0)
        paths.append(p)
    return pl, prep, times, paths


def run_epf(obs, box, qs):
    from extremitypathfinder import PolygonEnvironment

    t0 = time.perf_counter()
    env = PolygonEnvironment()
    b = [(box[0], box[1]), (box[2], box[1]), (box[2], box[3]), (box[0], box[3])]
    holes = [[tuple(map(float, v)) for v in o[::-1]] for o in obs]  # clockwise
    env.store([tuple(map(float, v)) for v in b], holes, validate=False)
    env.prepare()
    prep = time.perf_counter() - t0
    times, paths = [], []
    for s, g in qs:
        t0 = time.perf_counter()
        try:
            p, d = env.find_shortest_path(tuple(map(float, s)), tuple(map(float, g)))
            p = [list(v) for v in p] if p else None
        except Exception:  # noqa: BLE001 - the peer's own error: counted as no path
            p = None
        times.append(time.perf_counter() - t0)
        paths.append(p)
    return prep, times, paths


def run_pvg(obs, box, qs):
    import pyvisgraph as vg

    t0 = time.perf_counter()
    g_ = vg.VisGraph()
    g_.build([[vg.Point(float(x), float(y)) for x, y in o] for o in obs], workers=1, status=False)
    prep = time.perf_counter() - t0
    times, paths = [], []
    for s, g in qs:
        t0 = time.perf_counter()
        try:
            p = g_.shortest_path(vg.Point(*map(float, s)), vg.Point(*map(float, g)))
            p = [[q.x, q.y] for q in p] if p else None
        except Exception:  # noqa: BLE001
            p = None
        times.append(time.perf_counter() - t0)
        paths.append(p)
    return prep, times, paths


def stats(name, K, prep, times, paths, ref, check, qs):
    bad = nopath = 0
    excess = 0.0
    for p, r, (s, g) in zip(paths, ref, qs):
        if p is None:
            nopath += r is not None
            continue
        if not valid(check, p, s, g):
            bad += 1
            continue
        if r is not None:
            excess = max(excess, length(p) / length(r) - 1.0)
    n = len(qs)
    return (
        f"| {name} | {K} | {prep * 1e3:.1f} | {statistics.median(times) * 1e3:.3f} | "
        f"{bad}/{n} | {nopath}/{n} | {excess:.2e} |"
    )


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ks", type=int, nargs="+", default=[10, 100, 1000])
    ap.add_argument("--queries", type=int, default=50)
    ap.add_argument(
        "--checker", type=int, nargs="*", default=[50], help="checkerboard scenes (pinch points)"
    )
    ap.add_argument("--threads", type=int, nargs="*", default=[2], help="extra rows: threads=")
    ap.add_argument("--threads-min-k", type=int, default=1000)
    ap.add_argument("--peer-max-k", type=int, default=100, help="skip the peers beyond this K")
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    print(
        "| tool | K | preparation ms | median query ms | invalid paths | false no-path "
        "| length over optimal |"
    )
    print("|---|---|---|---|---|---|---|")
    notes = []
    runs = [("convex", K) for K in args.ks] + [("checker", K) for K in args.checker]
    for kind, K in runs:
        obs, box = (scene if kind == "convex" else checkerboard)(K, args.seed + K)
        label = K if kind == "convex" else f"{K} checkerboard"
        qs = queries(obs, box, args.queries, args.seed + K)
        pl, prep, times, ours = run_ours(obs, box, qs)
        check = pl._float_twin()._core.segment_free
        print(stats("minkowski2d", label, prep, times, ours, ours, check, qs), flush=True)
        for th in args.threads:
            if th > 1 and K >= args.threads_min_k:
                _, prep, times, paths = run_ours(obs, box, qs, th)
                name = f"minkowski2d threads={th}"
                print(stats(name, label, prep, times, paths, ours, check, qs), flush=True)
        if K > args.peer_max_k:
            notes.append(f"K={K}: peers skipped (minutes per scene)")
            continue
        for name, fn in (("extremitypathfinder", run_epf), ("pyvisgraph", run_pvg)):
            try:
                prep, times, paths = fn(obs, box, qs)
            except ImportError:
                notes.append(f"{name} not installed")
                continue
            except Exception as exc:  # noqa: BLE001 - a peer refusing the scene
                notes.append(f"{name} failed on K={label}: {type(exc).__name__}: {exc}")
                continue
            print(stats(name, label, prep, times, paths, ours, check, qs), flush=True)
    for n in notes:
        print(f"note: {n}")


if __name__ == "__main__":
    main()
