"""Exact polygon booleans on the iOverlay performance suite: ours against GEOS, Clipper2 and
Clipper1, in one run (issue 23).

The six tests of the public suite iShape-Rust/iOverlayPerformance, rebuilt here from the
description of its generators (the same shapes, sizes and operations; no code copied):

====  ================  ===========  ==========================================================
test  name              operation    input (n is the size parameter)
====  ================  ===========  ==========================================================
0     checkerboard      XOR          n² squares 20 wide at pitch 30 against (n−1)² offset by 15
1     not overlap       union        n² squares 10 wide at pitch 30 and (n−1)² offset by 15
2     lines net         intersection n vertical strips 10 wide against n horizontal ones
3     spiral            self-union   one self-overlapping strip along a zigzag spiral, n points
4     windows           difference   n² squares 20 wide minus n² centred squares 10 wide
5     nested squares    XOR          2n horizontal bars against 2n vertical bars of n frames
====  ================  ===========  ==========================================================

Fill rule nonzero (test 5: even-odd), as the suite runs Clipper. Input is built before the
clock starts, in each library's own form: one shapely geometry per operand for GEOS and for
ours (``mk.union`` / ``intersection`` / ``difference`` / ``symmetric_difference`` with the
same fill rule, shapely in and shapely out: the public path a user calls), numpy paths for
pyclipr (Clipper2, ``scaleFactor`` 1 on the integer tests, 100 on the spiral as the suite's
precision 2) and integer lists for pyclipper (Clipper1; spiral scaled by 100 likewise).
Clipper's time includes adding the paths (the suite's ``BooleanOp`` does too). GEOS: the
matching ``shapely`` function; the spiral is one invalid polygon for GEOS, so its row is
``shapely.make_valid(method="structure")`` and is marked when its area disagrees (GEOS has
no nonzero rule).

Times: CPU time of the process (``time.process_time``), best of ``--reps`` (one run at the
largest sizes), all single-threaded. A peer whose previous size took more than ``--budget``
seconds is not run at the larger sizes (``-``). ``ratio`` columns: ours / peer (below 1:
ours is faster). ``area``: ours against the exact closed form (tests 0, 1, 2, 4, 5: integer
areas, equal bit for bit) or, for the spiral, against Clipper2's on a 1e-6 grid (relative
1e-6; outside the clock); ``valid``: ``shapely.is_valid`` of our result (checked outside the clock).

iOverlay's own published figures (its README, Apple M-series, not this machine) are printed
after the table as context: checkerboard with 32,513 squares iOverlay 0.092 s, Clipper2
0.154 s; spiral with 1.05M points iOverlay 3.19 s, Clipper2 260 s.

Run: ``python benchmarks/bench_boolean.py [--tests 0 1 2 3 4 5] [--max-edges 1100000]
[--reps 3] [--budget 30] [--no-clipper1]`` (about 4 minutes with the defaults).
"""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import shapely
from _timing import best as timed

import minkowski2d as mk

# --------------------------------------------------------------------------------------
# the generators (integer squares as (k, 4, 2) int64 arrays, clockwise as the suite's)


def squares(x0: int, y0: int, size: int, pitch: int, n: int) -> np.ndarray:
    """n × n squares ``size`` wide at ``pitch``, the first at (x0, y0)."""
    ij = np.arange(n) * pitch
    X, Y = np.meshgrid(ij + x0, ij + y0)
    x, y = X.ravel(), Y.ravel()
    corner = np.array([[0, 0], [0, size], [size, size], [size, 0]], dtype=np.int64)
    return np.stack([x, y], axis=1)[:, None, :].astype(np.int64) + corner[None]


def lines_x(a: int, n: int) -> np.ndarray:
    w, s = a // 2, a * n // 2
    x = -s + w // 2 + a * np.arange(n, dtype=np.int64)
    out = np.empty((n, 4, 2), np.int64)
    out[:, 0] = np.stack([x, np.full(n, -s)], 1)
    out[:, 1] = np.stack([x, np.full(n, s)], 1)
    out[:, 2] = np.stack([x + w, np.full(n, s)], 1)
    out[:, 3] = np.stack([x + w, np.full(n, -s)], 1)
    return out


def lines_y(a: int, n: int) -> np.ndarray:
    h, s = a // 2, a * n // 2
    y = -s + h // 2 + a * np.arange(n, dtype=np.int64)
    out = np.empty((n, 4, 2), np.int64)
    out[:, 0] = np.stack([np.full(n, -s), y], 1)
    out[:, 1] = np.stack([np.full(n, s), y], 1)
    out[:, 2] = np.stack([np.full(n, s), y - h], 1)
    out[:, 3] = np.stack([np.full(n, -s), y - h], 1)
    return out


def windows(n: int, a: int = 20, b: int = 10, pitch: int = 30) -> tuple[np.ndarray, np.ndarray]:
    x = n * pitch // 2
    c = (a - b) // 2
    return squares(-x, -x, a, pitch, n), squares(-x + c, -x + c, b, pitch, n)


def concentric(a: int, n: int) -> tuple[np.ndarray, np.ndarray]:
    """(horizontal bars, vertical bars) of n square frames, bar width a, spacing 2a."""
    r = 2 * a * np.arange(1, n + 1, dtype=np.int64)
    z = np.zeros((n, 4, 2), np.int64)
    top, bot, left, right = z.copy(), z.copy(), z.copy(), z.copy()
    for k, (px, py) in enumerate([(-r, r - a), (-r, r), (r, r), (r, r - a)]):
        top[:, k] = np.stack([px, py], 1)
    for k, (px, py) in enumerate([(-r, -r), (-r, -r + a), (r, -r + a), (r, -r)]):
        bot[:, k] = np.stack([px, py], 1)
    for k, (px, py) in enumerate([(-r, -r), (-r, r), (-r + a, r), (-r + a, -r)]):
        left[:, k] = np.stack([px, py], 1)
    for k, (px, py) in enumerate([(r - a, -r), (r - a, r), (r, r), (r, -r)]):
        right[:, k] = np.stack([px, py], 1)
    vert = np.stack([top, bot], 1).reshape(-1, 4, 2)
    horz = np.stack([left, right], 1).reshape(-1, 4, 2)
    return vert, horz


def spiral(count: int, radius: float = 100.0) -> np.ndarray:
    """The suite's spiral strip: a zigzag polyline along an Archimedean spiral offset by
    ±0.1·radius on both sides, the far side reversed: one closed, self-overlapping path of
    4·count vertices (float64)."""
    w = 0.1 * radius
    a, r = 0.0, radius
    p0 = (0.0, 0.0)
    left, right = [], []
    for i in range(count):
        rr = r + 0.2 * radius if i % 2 == 0 else r - 0.2 * radius
        p = (rr * math.cos(a), rr * math.sin(a))
        vx, vy = p[0] - p0[0], p[1] - p0[1]
        ln = math.sqrt(vx * vx + vy * vy)
        tx, ty = -w * vy / ln, w * vx / ln
        left += [(p0[0] + tx, p0[1] + ty), (p[0] + tx, p[1] + ty)]
        right += [(p0[0] - tx, p0[1] - ty), (p[0] - tx, p[1] - ty)]
        a += radius / r
        r = radius * (1.0 + a / (2.0 * math.pi))
        p0 = p
    return np.array(left + right[::-1], dtype=np.float64)


# --------------------------------------------------------------------------------------
# the tests


@dataclass
class Case:
    subject: list[np.ndarray]
    clip: list[np.ndarray]
    area: float | None  # the exact area, where a closed form is cheap
    edges: int


@dataclass
class Test:
    name: str
    op: str  # union, intersection, difference, xor
    fill: str  # nonzero, evenodd
    sizes: list[int]
    make: Callable[[int], Case]
    count: Callable[[int], int]  # the suite's "count" column
    edges: Callable[[int], int]  # input edges at size n (without building the case)


def _case(subj: np.ndarray, clip: np.ndarray, area: float | None) -> Case:
    return Case(list(subj), list(clip), area, 4 * (len(subj) + len(clip)))


TESTS = [
    Test(
        "checkerboard",
        "xor",
        "nonzero",
        [8, 32, 128, 362],
        lambda n: _case(
            squares(0, 0, 20, 30, n),
            squares(15, 15, 20, 30, n - 1),
            400 * (n * n + (n - 1) ** 2) - 200 * (n - 1) ** 2,
        ),
        lambda n: n * n + (n - 1) ** 2,
        lambda n: 4 * (n * n + (n - 1) ** 2),
    ),
    Test(
        "not overlap",
        "union",
        "nonzero",
        [8, 32, 128, 362],
        lambda n: _case(
            squares(0, 0, 10, 30, n),
            squares(15, 15, 10, 30, n - 1),
            100 * (n * n + (n - 1) ** 2),
        ),
        lambda n: n * n + (n - 1) ** 2,
        lambda n: 4 * (n * n + (n - 1) ** 2),
    ),
    Test(
        "lines net",
        "intersection",
        "nonzero",
        [8, 32, 128, 512],
        lambda n: _case(lines_x(20, n), lines_y(20, n), 100 * n * n - 50 * n),
        lambda n: 2 * n,
        lambda n: 8 * n,
    ),
    Test(
        "spiral",
        "union",
        "nonzero",
        [256, 4096, 65536, 262144],
        lambda n: Case([spiral(n)], [], None, 4 * n),
        lambda n: n,
        lambda n: 4 * n,
    ),
    Test(
        "windows",
        "difference",
        "nonzero",
        [8, 32, 128, 362],
        lambda n: _case(*windows(n), 300 * n * n),
        lambda n: 2 * n * n,
        lambda n: 8 * n * n,
    ),
    Test(
        "nested squares",
        "xor",
        "evenodd",
        [64, 1024, 16384, 65536],
        lambda n: _case(*concentric(4, n), 128 * n * n),
        lambda n: 2 * n,
        lambda n: 16 * n,
    ),
]

PUBLISHED = (
    "iOverlay's published figures (iShape-Rust/iOverlay README, its machine, context only): "
    "checkerboard 32,513 squares: iOverlay 0.092 s, Clipper2 0.154 s; spiral 1.05M points: "
    "iOverlay 3.19 s, Clipper2 260 s"
)

# --------------------------------------------------------------------------------------
# the runners


def _geometry(rings: list[np.ndarray]):
    if not rings:
        return shapely.Polygon()
    if len({len(r) for r in rings}) == 1:
        polys = shapely.polygons(np.asarray(rings, dtype=np.float64))
    else:
        polys = np.array([shapely.Polygon(r) for r in rings], dtype=object)
    return polys[0] if len(polys) == 1 else shapely.MultiPolygon(list(polys))


OURS = {
    "union": mk.union,
    "intersection": mk.intersection,
    "difference": mk.difference,
    "xor": mk.symmetric_difference,
}
GEOS = {
    "union": shapely.union,
    "intersection": shapely.intersection,
    "difference": shapely.difference,
    "xor": shapely.symmetric_difference,
}


def runners(test: Test, case: Case, clipper1: bool) -> dict[str, Callable[[], object]]:
    A, B = _geometry(case.subject), _geometry(case.clip)
    out: dict[str, Callable[[], object]] = {}
    out["ours"] = lambda: OURS[test.op](A, B, fill_rule=test.fill)
    if test.name == "spiral":
        out["shapely"] = lambda: shapely.make_valid(A, method="structure")
    else:
        out["shapely"] = lambda: GEOS[test.op](A, B)

    import pyclipr

    scale = 100 if test.name == "spiral" else 1
    ct = {
        "union": pyclipr.Union,
        "intersection": pyclipr.Intersection,
        "difference": pyclipr.Difference,
        "xor": pyclipr.Xor,
    }[test.op]
    fr = pyclipr.FillRule.NonZero if test.fill == "nonzero" else pyclipr.FillRule.EvenOdd
    subj2 = [np.ascontiguousarray(r, dtype=np.float64) for r in case.subject]
    clip2 = [np.ascontiguousarray(r, dtype=np.float64) for r in case.clip]

    def clipper2():
        pc = pyclipr.Clipper()
        pc.scaleFactor = scale
        pc.addPaths(subj2, pyclipr.Subject)
        if clip2:
            pc.addPaths(clip2, pyclipr.Clip)
        return pc.execute(ct, fr), 1  # pyclipr scales back itself

    out["clipper2"] = clipper2
    if clipper1:
        import pyclipper

        ct1 = {
            "union": pyclipper.CT_UNION,
            "intersection": pyclipper.CT_INTERSECTION,
            "difference": pyclipper.CT_DIFFERENCE,
            "xor": pyclipper.CT_XOR,
        }[test.op]
        ft1 = pyclipper.PFT_NONZERO if test.fill == "nonzero" else pyclipper.PFT_EVENODD
        subj1 = [np.rint(r * scale).astype(np.int64).tolist() for r in case.subject]
        clip1 = [np.rint(r * scale).astype(np.int64).tolist() for r in case.clip]

        def clipper1_run():
            pc = pyclipper.Pyclipper()
            pc.AddPaths(subj1, pyclipper.PT_SUBJECT, True)
            if clip1:
                pc.AddPaths(clip1, pyclipper.PT_CLIP, True)
            return pc.Execute(ct1, ft1, ft1), scale

        out["clipper1"] = clipper1_run
    return out


def spiral_reference(case: Case):
    """Clipper2's nonzero self-union of the spiral on a grid of 1e-6 (its rounding moves
    the area by ~1e-8 relative): the area reference for the spiral rows."""
    import pyclipr

    pc = pyclipr.Clipper()
    pc.scaleFactor = 10**6
    pc.addPaths(case.subject, pyclipr.Subject)
    return pc.execute(pyclipr.Union, pyclipr.FillRule.NonZero), 1


def area_of(result) -> float:
    """Area of a shapely result, or of Clipper's paths (signed ring areas summed)."""
    if isinstance(result, tuple):
        paths, scale = result
        tot = 0.0
        for p in paths:
            q = np.asarray(p, dtype=np.float64)
            if len(q) >= 3:
                x, y = q[:, 0], q[:, 1]
                tot += 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))
        return abs(tot) / (scale * scale)
    return float(result.area)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--tests", type=int, nargs="*", default=list(range(6)))
    ap.add_argument("--max-edges", type=int, default=1_100_000, help="largest input size")
    ap.add_argument("--sizes", type=int, nargs="*", help="size parameters n (all tests)")
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--budget", type=float, default=30.0, help="seconds; a slower peer stops")
    ap.add_argument("--no-clipper1", action="store_true", help="leave pyclipper out")
    args = ap.parse_args(argv)
    import pyclipr

    peers = ["shapely", "clipper2"] + ([] if args.no_clipper1 else ["clipper1"])
    print(
        f"python {sys.version.split()[0]}, minkowski2d {mk.__version__}, shapely "
        f"{shapely.__version__} (GEOS {shapely.geos_version_string}), pyclipr "
        f"{getattr(pyclipr, '__version__', '?')} (Clipper2 {pyclipr.clipperVersion})"
        + ("" if args.no_clipper1 else ", pyclipper (Clipper1)")
        + f"; CPU seconds, best of {args.reps} (1 above 200k edges); one thread each"
    )
    head = (
        f"{'test':15} {'n':>7} {'count':>8} {'edges':>8} {'ours s':>8} "
        + " ".join(f"{p + ' s':>10} {'ratio':>6}" for p in peers)
        + f" {'area':>6} {'valid':>5}"
    )
    print(head)
    sq = squares(0, 0, 2, 3, 2)  # one small call of each library first (lazy imports)
    mk.union(_geometry(list(sq)), _geometry(list(sq + 1)))
    failures = 0
    for t in args.tests:
        test = TESTS[t]
        slow: set[str] = set()
        last: dict[str, tuple[int, float]] = {}
        sizes = args.sizes or test.sizes
        for k, n in enumerate(sizes):
            if "ours" in slow:  # past the budget: the test stops here, every peer with it
                break
            case = test.make(n)
            if case.edges > args.max_edges:
                continue
            run = runners(test, case, not args.no_clipper1)
            reps = 1 if case.edges > 200_000 else args.reps
            times: dict[str, float] = {}
            results: dict[str, object] = {}
            for name in ["ours", *peers]:
                if name in slow:
                    continue
                times[name], results[name] = timed(run[name], reps)
                # stop a peer past the budget, or whose growth from its last size predicts
                # more than three budgets at the next size (GEOS's windows grow
                # quadratically; without a measured growth, quadratic is assumed)
                prev = last.get(name)
                grow = 2.0
                step = test.edges(sizes[k + 1]) / case.edges if k + 1 < len(sizes) else 1.0
                if prev and prev[1] > 0.05 and times[name] > 0:
                    ratio = math.log(times[name] / prev[1]) / math.log(case.edges / prev[0])
                    grow = max(1.0, ratio)
                last[name] = (case.edges, times[name])
                if times[name] > args.budget or times[name] * step**grow > 3 * args.budget:
                    slow.add(name)
            ours = results["ours"]
            got = area_of(ours)
            if case.area is not None:
                ok = got == case.area
            else:  # the spiral: Clipper2 on a 1e-6 grid (outside the clock)
                ref = area_of(spiral_reference(case))
                ok = abs(got - ref) <= 1e-6 * ref
            valid = bool(shapely.is_valid(ours))
            failures += (not ok) + (not valid)
            cols = []
            for p in peers:
                if p in times:
                    note = ""
                    if test.name == "spiral" and p == "shapely":
                        g = area_of(results[p])
                        note = "" if abs(g - got) <= 1e-6 * got else "*"
                    cols.append(f"{times[p]:9.3f}{note or ' '} {times['ours'] / times[p]:6.2f}")
                else:
                    cols.append(f"{'-':>10} {'-':>6}")
            print(
                f"{test.name:15} {n:7d} {test.count(n):8d} {case.edges:8d} "
                f"{times['ours']:8.3f} "
                + " ".join(cols)
                + f" {'ok' if ok else 'DIFF':>6} {'yes' if valid else 'NO':>5}",
                flush=True,
            )
            if not ok:
                print(f"  area: ours {got!r}, reference {case.area if case.area else ref!r}")
    print(
        "ratio = ours / peer (below 1: ours faster); * = GEOS's make_valid gives another area "
        "(no nonzero rule)"
    )
    print(PUBLISHED)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
