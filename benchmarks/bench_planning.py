"""Motion planning at map scale: minkowski2d.MotionPlanner against extremitypathfinder and
pyvisgraph.

Maps generated like game maps, seeded:

* ``maze N``: a perfect maze of N x N cells (recursive backtracker) on a (2N+1)^2 grid of
  unit blocks, walls one block thick (maze 64: 129 x 129 blocks);
* ``cave N``: an N x N cave (random fill 45 %, four smoothing steps of the 4-5 cellular
  automaton, border blocked);
* ``random K``: K convex obstacles (4-8 vertices, int coordinates) inside a square
  workspace, one per cell of a jittered grid (no two touch, which the peers require);
* ``K checkerboard``: unit squares touching at their corners only (pinch points);
* ``touching K``: K rectangles, one per cell of a grid, each side either on its cell's
  border (probability 0.3) or 5-30 % inside it: neighbours touch along parts of edges and
  the border ones touch the workspace box (zero-width passages, on the mesh's network).

Grids are planned with ``MotionPlanner.from_grid`` (blocked cells merged into rectangles,
one obstacle: walls have no gaps between blocks). A point robot; Q random start/goal pairs
on free cells (cell centres) or free points. Every time is measured as wall clock and as
CPU time of this process (``time.process_time``): the machine may be shared, and CPU time
is the figure that does not count other jobs. Preparation is the planner's constructor.

Columns: preparation (wall / CPU; for minkowski2d the median of ``--prep-reps`` builds, the
peers build once); median query (wall / CPU, one ``shortest_path`` call
each, from Python); invalid paths (a segment meets a C-obstacle's open interior or leaves
the workspace, or the endpoints are not the query's: checked with the exact predicates of
the core); false "no path" (none reported where minkowski2d found a valid path); length
over ours (largest relative excess over minkowski2d's path). The row ``minkowski2d
(visibility)`` is the same planner on its exact visibility graph (``method="visibility"``,
checked against a brute-force exact reference in tests/test_planning.py): its lengths
cross-check the mesh's optimality on the maps where it finishes in reasonable time.

Peers: extremitypathfinder and pyvisgraph on the random scenes up to ``--peer-max-k``
(default 100: their preparation grows to minutes beyond); extremitypathfinder also on the
mazes up to ``--peer-max-maze`` (the free space as one polygon; pyvisgraph takes no holes
or touching obstacles and is skipped on grids). ``pip install -e ".[bench]"`` installs
every peer but extremitypathfinder, whose metadata asks for numpy < 2 (which coal and
geopandas exclude); it runs under numpy 2 when installed without its pins:
``pip install --no-deps "extremitypathfinder>=2.7" "networkx>=3"``.

Real game maps (``--maps``, default: the six GPPC-2013 maps of ``../shared/data/maps``
when that folder exists, read from there): StarCraft (Archipelago, BigGameHunters,
Brushfire, 512 x 512) and Dragon Age 2 (ca_cave, dr_dungeon, ht_keep). ``--map-queries``
queries spread evenly over each map's scenario file (every bucket, short to long), cell
centre to cell centre; per map the preparation, the median, 95th percentile and largest
query time (CPU), every path validated exactly, and the largest excess of its length over
the scenario's octile optimum (rounded to 6 significant digits there: an any-angle path is
never longer, up to that rounding). Context, not run here: Polyanya's published figure is
about 1.5 ms per query averaged over the GPPC any-angle benchmark (Cui, Harabor and
Grastien, IJCAI 2017, on their machine).

Usage::

    python benchmarks/bench_planning.py            # the table of docs/planning.md
    python benchmarks/bench_planning.py --mazes --caves --ks --checker   # the maps only
    python benchmarks/bench_planning.py --mazes 20 --caves --ks 100 --checker
"""

from __future__ import annotations

import argparse
import math
import statistics
import time
from pathlib import Path

import numpy as np

import minkowski2d as mk
import minkowski2d.io  # noqa: F401 - mk.io

CELL = 1000


def grid_cells(K: int, seed: int):
    """The generator, the grid's side n and K distinct random cells (i, j) of n x n."""
    rng = np.random.default_rng(seed)
    n = math.ceil(math.sqrt(K))
    return rng, n, [divmod(int(c), n) for c in rng.permutation(n * n)[:K]]


def scene(K: int, seed: int) -> tuple[list[np.ndarray], tuple[int, int, int, int]]:
    rng, n, cells = grid_cells(K, seed)
    obs = []
    for i, j in cells:
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


def touching(K: int, seed: int) -> tuple[list[np.ndarray], tuple[int, int, int, int]]:
    """K rectangles on a grid of cells, sides on the cell border with probability 0.3:
    neighbours share parts of edges, border cells share edges with the box."""
    rng, n, cells = grid_cells(K, seed)
    obs = []
    for i, j in cells:
        inset = np.where(rng.random(4) < 0.3, 0, rng.integers(CELL // 20, 3 * CELL // 10, 4))
        x0, y0 = i * CELL + inset[0], j * CELL + inset[1]
        x1, y1 = (i + 1) * CELL - inset[2], (j + 1) * CELL - inset[3]
        obs.append(np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]], np.int64))
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


def maze(n: int, seed: int) -> np.ndarray:
    """A perfect maze of n x n cells on a (2n+1) x (2n+1) occupancy grid (True: wall)."""
    rng = np.random.default_rng(seed)
    occ = np.ones((2 * n + 1, 2 * n + 1), bool)
    seen = np.zeros((n, n), bool)
    stack = [(0, 0)]
    seen[0, 0] = True
    occ[1, 1] = False
    while stack:
        i, j = stack[-1]
        nb = [
            (i + di, j + dj)
            for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1))
            if 0 <= i + di < n and 0 <= j + dj < n and not seen[i + di, j + dj]
        ]
        if not nb:
            stack.pop()
            continue
        a, b = nb[int(rng.integers(len(nb)))]
        seen[a, b] = True
        occ[2 * a + 1, 2 * b + 1] = False
        occ[i + a + 1, j + b + 1] = False
        stack.append((a, b))
    return occ


def cave(n: int, seed: int, fill: float = 0.45, steps: int = 4) -> np.ndarray:
    """An n x n cave: random fill, then ``steps`` rounds of "blocked iff at least 5 of the
    3 x 3 neighbourhood are" (outside the grid counts as blocked)."""
    rng = np.random.default_rng(seed)
    occ = rng.random((n, n)) < fill
    for _ in range(steps):
        pad = np.pad(occ, 1, constant_values=True).astype(np.int8)
        cnt = sum(
            pad[1 + dy : 1 + dy + n, 1 + dx : 1 + dx + n] for dy in (-1, 0, 1) for dx in (-1, 0, 1)
        )
        occ = cnt >= 5
    return occ


def grid_queries(occ: np.ndarray, Q: int, seed: int) -> list:
    """Q pairs of free cell centres (x = column + 0.5, y = row + 0.5)."""
    rng = np.random.default_rng(seed + 1)
    free = np.argwhere(~occ)
    idx = rng.integers(len(free), size=(Q, 2))
    c = [(float(free[k][1]) + 0.5, float(free[k][0]) + 0.5) for k in idx.ravel()]
    return list(zip(c[0::2], c[1::2]))


def timed(fn, *args, **kwargs):
    """(result, wall seconds, CPU seconds of this process)."""
    w0, c0 = time.perf_counter(), time.process_time()
    r = fn(*args, **kwargs)
    return r, time.perf_counter() - w0, time.process_time() - c0


def run_ours(make, qs, reps=1):
    """Preparation: the median of ``reps`` builds (the first build in a process pays for
    warming the allocator and the caches)."""
    runs = [timed(make) for _ in range(reps)]
    pl = runs[-1][0]
    pw = statistics.median(r[1] for r in runs)
    pc = statistics.median(r[2] for r in runs)
    tw, tc, paths = [], [], []
    for s, g in qs:
        w0, c0 = time.perf_counter(), time.process_time()
        try:
            p = pl.shortest_path(s, g).points.tolist()
        except mk.errors.NoPathError:
            p = None
        tc.append(time.process_time() - c0)
        tw.append(time.perf_counter() - w0)
        paths.append(p)
    return pl, (pw, pc), (tw, tc), paths


def run_epf(obs, box, qs, boundary=None):
    from extremitypathfinder import PolygonEnvironment

    if boundary is None:
        boundary = [(box[0], box[1]), (box[2], box[1]), (box[2], box[3]), (box[0], box[3])]
        holes = [[tuple(map(float, v)) for v in o[::-1]] for o in obs]  # clockwise
    else:
        holes = obs

    def prepare():
        env = PolygonEnvironment()
        env.store([tuple(map(float, v)) for v in boundary], holes, validate=False)
        env.prepare()
        return env

    env, pw, pc = timed(prepare)
    tw, tc, paths = [], [], []
    for s, g in qs:
        w0, c0 = time.perf_counter(), time.process_time()
        try:
            p, d = env.find_shortest_path(tuple(map(float, s)), tuple(map(float, g)))
            p = [list(v) for v in p] if p else None
        except Exception:  # noqa: BLE001 - the peer's own error: counted as no path
            p = None
        tc.append(time.process_time() - c0)
        tw.append(time.perf_counter() - w0)
        paths.append(p)
    return (pw, pc), (tw, tc), paths


def run_pvg(obs, box, qs):
    import pyvisgraph as vg

    def prepare():
        g_ = vg.VisGraph()
        pts = [[vg.Point(float(x), float(y)) for x, y in o] for o in obs]
        g_.build(pts, workers=1, status=False)
        return g_

    g_, pw, pc = timed(prepare)
    tw, tc, paths = [], [], []
    for s, g in qs:
        w0, c0 = time.perf_counter(), time.process_time()
        try:
            p = g_.shortest_path(vg.Point(*map(float, s)), vg.Point(*map(float, g)))
            p = [[q.x, q.y] for q in p] if p else None
        except Exception:  # noqa: BLE001
            p = None
        tc.append(time.process_time() - c0)
        tw.append(time.perf_counter() - w0)
        paths.append(p)
    return (pw, pc), (tw, tc), paths


def maze_free_polygon(occ: np.ndarray):
    """The free space of a maze as (boundary counter-clockwise, holes clockwise), or None
    when it is not one polygon."""
    import shapely

    free = np.argwhere(~occ)
    cells = shapely.box(free[:, 1], free[:, 0], free[:, 1] + 1, free[:, 0] + 1)
    u = shapely.union_all(cells).simplify(0)
    if u.geom_type != "Polygon":
        return None
    u = shapely.geometry.polygon.orient(u, 1.0)
    bnd = [tuple(map(float, c)) for c in u.exterior.coords[:-1]]
    holes = [[tuple(map(float, c)) for c in r.coords[:-1]] for r in u.interiors]
    return bnd, holes


def stats(name, label, n_obs, prep, times, paths, ref, check, qs):
    bad = nopath = 0
    excess = 0.0
    for p, r, (s, g) in zip(paths, ref, qs):
        if p is None:
            nopath += r is not None
            continue
        if not valid(check, p, s, g):
            bad += 1
            continue
        if r is not None and length(r) > 0:
            excess = max(excess, length(p) / length(r) - 1.0)
    n = len(qs)
    return (
        f"| {name} | {label} | {n_obs} | {prep[0] * 1e3:.1f} / {prep[1] * 1e3:.1f} | "
        f"{statistics.median(times[0]) * 1e3:.3f} / {statistics.median(times[1]) * 1e3:.3f} | "
        f"{bad}/{n} | {nopath}/{n} | {excess:.1e} |"
    )


MAPS = Path(__file__).resolve().parents[2] / "shared" / "data" / "maps"
GAME_MAPS = ["Archipelago", "BigGameHunters", "Brushfire", "ca_cave", "dr_dungeon", "ht_keep"]


def scenario(name: str, n: int) -> list:
    """n queries spread over the map's scenario file: (start, goal, octile optimum)."""
    rows = mk.io.read_scenario(MAPS / f"{name}.map.scen")
    pick = np.linspace(0, len(rows) - 1, n).astype(int)
    centre = lambda c: (c[0] + 0.5, c[1] + 0.5)  # noqa: E731
    return [(centre(rows[i].start), centre(rows[i].goal), rows[i].optimal) for i in pick]


def game_maps(names: list[str], n: int, reps: int) -> None:
    print()
    print(
        "| map | cells (W x H) | mesh cells | preparation ms CPU | median query ms CPU "
        "| p95 ms CPU | max ms CPU | invalid paths | over the octile optimum |"
    )
    print("|---|---|---|---|---|---|---|---|---|")
    for name in names:
        occ = mk.io.read_grid_map(MAPS / f"{name}.map")
        sc = scenario(name, n)
        qs = [(s, g) for s, g, _ in sc]
        pl, prep, times, paths = run_ours(lambda occ=occ: mk.MotionPlanner.from_grid(occ), qs, reps)
        check = pl._core.segment_free
        bad = sum(p is None or not valid(check, p, s, g) for p, (s, g) in zip(paths, qs))
        # the scenario's optimum is rounded to 6 significant digits
        over = max(
            length(p) - (o + 0.5 * 10.0 ** (math.floor(math.log10(o)) - 5))
            for p, (_, _, o) in zip(paths, sc)
            if p is not None
        )
        tc = np.array(times[1]) * 1e3
        cells = len(pl.navmesh.cells) if pl.navmesh is not None else "-"
        print(
            f"| {name} | {occ.shape[1]} x {occ.shape[0]} | {cells} | {prep[1] * 1e3:.0f} | "
            f"{np.median(tc):.2f} | {np.percentile(tc, 95):.2f} | {tc.max():.2f} | {bad}/{n} | "
            f"{'none' if over <= 0 else f'{over:.1e}'} |",
            flush=True,
        )
    print(
        "context (published, not run here): Polyanya about 1.5 ms per query averaged over "
        "the GPPC any-angle benchmark (Cui, Harabor and Grastien, IJCAI 2017)"
    )


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--mazes", type=int, nargs="*", default=[20, 64], help="maze sizes (cells)")
    ap.add_argument("--caves", type=int, nargs="*", default=[256], help="cave sizes")
    ap.add_argument("--ks", type=int, nargs="*", default=[100, 1000, 10000], help="random K")
    ap.add_argument("--checker", type=int, nargs="*", default=[50], help="checkerboard K")
    ap.add_argument("--touching", type=int, nargs="*", default=[1000, 10000], help="touching K")
    ap.add_argument("--queries", type=int, default=100)
    ap.add_argument("--peer-max-k", type=int, default=100, help="peers on random K up to this")
    ap.add_argument("--peer-max-maze", type=int, default=20, help="extremitypathfinder mazes")
    ap.add_argument(
        "--vis-max", type=int, default=4000,
        help="our visibility-graph row (a cross-check) up to this many C-pieces",
    )  # fmt: skip
    ap.add_argument("--prep-reps", type=int, default=3, help="our builds per map (median)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument(
        "--maps", nargs="*", default=GAME_MAPS if MAPS.is_dir() else [],
        help="GPPC-2013 maps in ../shared/data/maps (default: all six there)",
    )  # fmt: skip
    ap.add_argument("--map-queries", type=int, default=200, help="queries per game map")
    args = ap.parse_args()
    print(
        "| tool | map | obstacles | preparation ms (wall / CPU) | median query ms (wall / CPU) "
        "| invalid paths | false no-path | length over ours |"
    )
    print("|---|---|---|---|---|---|---|---|")
    notes: list[str] = []
    runs = (
        [("maze", n) for n in args.mazes]
        + [("cave", n) for n in args.caves]
        + [("random", k) for k in args.ks]
        + [("checker", k) for k in args.checker]
        + [("touching", k) for k in args.touching]
    )
    for kind, n in runs:
        seed = args.seed + n
        occ = None
        if kind in ("maze", "cave"):
            occ = maze(n, seed) if kind == "maze" else cave(n, seed)
            qs = grid_queries(occ, args.queries, seed)
            label = f"{kind} {n}" + (f" ({occ.shape[0]}²)" if kind == "maze" else "")
            n_obs = f"{int(occ.sum())} blocked cells"

            def make(method="auto", occ=occ):
                return mk.MotionPlanner.from_grid(occ, method=method)
        else:
            gen = {"random": scene, "checker": checkerboard, "touching": touching}[kind]
            obs, box = gen(n, seed)
            qs = queries(obs, box, args.queries, seed)
            label = {"random": f"random {n}", "checker": f"checkerboard {n}"}.get(
                kind, f"touching {n}"
            )
            n_obs = str(len(obs))

            def make(method="auto", obs=obs, box=box):
                return mk.MotionPlanner(obs, workspace=box, method=method)

        pl, prep, times, ours = run_ours(make, qs, args.prep_reps)
        core = pl._core if pl.planned_by == "mesh" else pl._float_twin()._core
        check = core.segment_free
        name = f"minkowski2d ({pl.planned_by})"
        print(stats(name, label, n_obs, prep, times, ours, ours, check, qs), flush=True)
        if pl.planned_by == "mesh":
            if len(pl.pieces) <= args.vis_max:
                _, prep, times, paths = run_ours(lambda: make("visibility"), qs, args.prep_reps)
                row = stats("minkowski2d (visibility)", label, n_obs, prep, times, paths, ours,
                            check, qs)  # fmt: skip
                print(row, flush=True)
            else:
                notes.append(f"{label}: our visibility graph skipped ({len(pl.pieces)} C-pieces)")
        peers = []
        if kind == "maze" and n <= args.peer_max_maze:
            poly = maze_free_polygon(occ)
            if poly is not None:
                peers = [("extremitypathfinder", run_epf, (poly[1], None, qs, poly[0]))]
        elif kind in ("random", "checker", "touching") and n <= args.peer_max_k:
            peers = [
                ("extremitypathfinder", run_epf, (obs, box, qs)),
                ("pyvisgraph", run_pvg, (obs, box, qs)),
            ]
        else:
            notes.append(f"{label}: peers skipped (size cap)")
        for pname, fn, fargs in peers:
            try:
                prep, times, paths = fn(*fargs)
            except ImportError:
                notes.append(f"{pname} not installed")
                continue
            except Exception as exc:  # noqa: BLE001 - a peer refusing the scene
                notes.append(f"{pname} failed on {label}: {type(exc).__name__}: {exc}")
                continue
            print(stats(pname, label, n_obs, prep, times, paths, ours, check, qs), flush=True)
    for note in notes:
        print(f"note: {note}")
    if args.maps:
        game_maps(args.maps, args.map_queries, args.prep_reps)


if __name__ == "__main__":
    main()
