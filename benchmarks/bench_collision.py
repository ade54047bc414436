"""Collision, distance and penetration of convex polygon pairs: minkowski2d vs peers.

Workloads: 100,000 pairs, about half overlapping, of (1) hulls of 8 random points
(5-6 vertices) and (2) random convex 64-gons (64 random angles on a circle).

Peers, each on the same pairs, from one run:
* shapely 2 (GEOS): vectorized ``shapely.intersects`` / ``shapely.distance`` over arrays;
* pymunk (Chipmunk2D): ``Shape.shapes_collide`` for penetration, in a Python loop (it is
  called per pair; pymunk 7.3.1 raises an AssertionError inside shapes_collide for some
  separated pairs, which is caught and counted as "no contact");
* coal (the maintained FCL successor): ``coal.distance`` and ``coal.collide`` (contacts
  on) with default tolerances, on tall prisms over the polygons (height 20x the
  polygons' size so the z direction never gives the minimum translation); a 20,000-pair
  slice because building the 3-D shapes is slow.

Times are the best of 3 (5 for ours) on a shared 2-core machine. Agreement: every
result on a sample of pairs is compared with an exact reference (the brute-force hull of
all pairwise differences in Fractions, from tests/test_collision.py): "agree" for
intersects, the largest relative error for distance (pairs apart; overlapping pairs must
give 0) and for penetration depth (overlapping pairs).

Run from the repository root:  python benchmarks/bench_collision.py [--pairs N]
"""

from __future__ import annotations

import argparse
import sys
import time
from fractions import Fraction
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

import minkowski2d as mk  # noqa: E402
from minkowski2d.batch import Ragged  # noqa: E402


def hulls8(rng, P):
    import shapely

    pts = rng.random((P, 8, 2))
    mp = shapely.multipoints(pts.reshape(-1, 2), indices=np.repeat(np.arange(P), 8))
    h = shapely.convex_hull(mp)
    coords, idx = shapely.get_coordinates(shapely.get_exterior_ring(h), return_index=True)
    counts = np.bincount(idx, minlength=P)
    keep = np.ones(len(coords), bool)
    keep[np.cumsum(counts) - 1] = False  # drop closing vertices
    off = np.zeros(P + 1, np.int64)
    np.cumsum(counts - 1, out=off[1:])
    return coords[keep] - 0.5, off


def ngons(rng, P, n=64):
    t = np.sort(rng.random((P, n)) * 2 * np.pi, axis=1)
    coords = 0.5 * np.stack([np.cos(t).ravel(), np.sin(t).ravel()], 1)
    return coords, np.arange(P + 1, dtype=np.int64) * n


def shifted(coords, off, shift):
    rep = np.repeat(shift, np.diff(off), axis=0)
    return Ragged(coords + rep, off)


def make(kind, rng, P):
    gen = hulls8 if kind == "hull8" else ngons
    ca, oa = gen(rng, P)
    cb, ob = gen(rng, P)
    ang = rng.random(P) * 2 * np.pi
    u = rng.random(P)
    # calibrate the shift radius so that about half the pairs overlap
    lo, hi = 0.0, 4.0
    m = min(P, 20000)
    for _ in range(20):
        R = (lo + hi) / 2
        r = R * np.sqrt(u[:m])
        s = np.stack([r * np.cos(ang[:m]), r * np.sin(ang[:m])], 1)
        sub_b = Ragged(cb[: ob[m]] + np.repeat(s, np.diff(ob[: m + 1]), axis=0), ob[: m + 1])
        sub_a = Ragged(ca[: oa[m]], oa[: m + 1])
        frac = mk.intersects_many(sub_a, sub_b).mean()
        lo, hi = (R, hi) if frac > 0.5 else (lo, R)
    r = R * np.sqrt(u)
    s = np.stack([r * np.cos(ang), r * np.sin(ang)], 1)
    return Ragged(ca, oa), shifted(cb, ob, s)


def best(f, reps):
    t = []
    out = None
    for _ in range(reps):
        t0 = time.perf_counter()
        out = f()
        t.append(time.perf_counter() - t0)
    return min(t), out


# ---- peers ------------------------------------------------------------------------------


def to_shapely(R):
    import shapely

    idx = np.repeat(np.arange(len(R)), R.lengths)
    return shapely.polygons(shapely.linearrings(R.coords, indices=idx))


def pymunk_shapes(R):
    import pymunk

    body = pymunk.Body(body_type=pymunk.Body.STATIC)
    out = []
    for k in range(len(R)):
        s = pymunk.Poly(body, R[k].tolist())
        s.cache_bb()
        out.append(s)
    return out


def pymunk_pen(SA, SB):
    depth = np.full(len(SA), np.nan)
    for k in range(len(SA)):
        try:
            cs = SA[k].shapes_collide(SB[k])
        except AssertionError:
            continue
        if cs.points:
            depth[k] = -min(p.distance for p in cs.points)
    return depth


def coal_shapes(R, h):
    import coal

    out = []
    for k in range(len(R)):
        poly = R[k]
        n = len(poly)
        V = coal.StdVec_Vec3s()
        for z in (-h, h):
            for x, y in poly:
                V.append(np.array([x, y, z]))
        T = coal.StdVec_Triangle()
        for i in range(1, n - 1):
            T.append(coal.Triangle(0, i + 1, i))
            T.append(coal.Triangle(n, n + i, n + i + 1))
        for i in range(n):
            j = (i + 1) % n
            T.append(coal.Triangle(i, j, n + j))
            T.append(coal.Triangle(i, n + j, n + i))
        out.append(coal.Convex(V, T))
    return out


def coal_distance(CA, CB):
    import coal

    I = coal.Transform3s()
    req = coal.DistanceRequest()
    res = coal.DistanceResult()
    out = np.empty(len(CA))
    for k in range(len(CA)):
        res.clear()
        out[k] = coal.distance(CA[k], I, CB[k], I, req, res)
    return np.maximum(out, 0.0)


def coal_pen(CA, CB):
    import coal

    I = coal.Transform3s()
    req = coal.CollisionRequest()
    req.enable_contact = True
    out = np.full(len(CA), np.nan)
    for k in range(len(CA)):
        res = coal.CollisionResult()
        if coal.collide(CA[k], I, CB[k], I, req, res):
            out[k] = -res.getContact(0).penetration_depth
    return out


# ---- exact reference ----------------------------------------------------------------------


def reference(RA, RB, sample):
    from tests.test_collision import d_hull, ref_d2, ref_inside, ref_signed_depth2

    ref = {}
    for k in sample:
        H = d_hull(RA[k].tolist(), RB[k].tolist())
        ins = ref_inside(H)
        ref[k] = (ins, ref_d2(H), ref_signed_depth2(H))
    return ref


def rel(x, exact2):
    """Relative error of x against sqrt(exact2) (exact2 > 0), computed exactly."""
    e = float(exact2) ** 0.5
    x2 = Fraction(float(x)) ** 2
    # |x - e| / e = |x^2 - e^2| / (e (x + e))
    return float(abs(x2 - exact2)) / (e * (abs(float(x)) + e))


def agreement(ref, sample, inter=None, dist=None, depth=None):
    if inter is not None:
        ok = sum(bool(inter[k]) == ref[k][0] for k in sample)
        return f"{100.0 * ok / len(sample):.2f}% agree"
    if dist is not None:
        errs = [rel(dist[k], ref[k][1]) for k in sample if not ref[k][0]]
        bad0 = sum(dist[k] != 0.0 for k in sample if ref[k][0])
        s = f"max rel err {max(errs):.1e}"
        return s + (f", {bad0} overlapping pairs not 0" if bad0 else "")
    errs = []
    missing = 0
    for k in sample:
        if ref[k][0] and ref[k][2] > 0:
            if not np.isfinite(depth[k]):
                missing += 1
            else:
                errs.append(rel(depth[k], ref[k][2]))
    s = f"max rel err {max(errs):.1e}" if errs else "no overlapping pairs"
    return s + (f", {missing} overlaps missed" if missing else "")


# ---- main -----------------------------------------------------------------------------------


def run(kind, P, n_ref, n_coal, rng):
    RA, RB = make(kind, rng, P)
    rows = []
    sample = rng.choice(P, size=min(n_ref, P), replace=False)
    t0 = time.perf_counter()
    ref = reference(RA, RB, sample)
    print(
        f"\n## {kind}: {P} pairs, mean vertices {RA.lengths.mean():.2f} / "
        f"{RB.lengths.mean():.2f}, {100 * np.mean([ref[k][0] for k in sample]):.1f}% "
        f"overlapping (exact reference on {len(sample)} pairs, "
        f"{time.perf_counter() - t0:.0f} s)"
    )

    for m in ("intersects", "distance", "penetration"):
        f = {
            "intersects": mk.intersects_many,
            "distance": mk.distance_many,
            "penetration": mk.penetration_many,
        }[m]
        f(RA, RB)  # warm (compiled code is cached on disk)
        t, out = best(lambda f=f: f(RA, RB), 5)
        val = out if m == "intersects" else out.distance if m == "distance" else out.depth
        ag = agreement(
            ref,
            sample,
            **{{"intersects": "inter", "distance": "dist", "penetration": "depth"}[m]: val},
        )
        rows.append((m, "minkowski2d", t / P, ag))
        if m == "intersects":
            for meth in ("sum", "gjk"):
                t, out = best(lambda meth=meth: mk.intersects_many(RA, RB, method=meth), 3)
                ag = agreement(ref, sample, inter=out)
                rows.append((m, f"minkowski2d method={meth}", t / P, ag))

    import shapely

    GA, GB = to_shapely(RA), to_shapely(RB)
    t, out = best(lambda: shapely.intersects(GA, GB), 3)
    rows.append(("intersects", "shapely", t / P, agreement(ref, sample, inter=out)))
    t, out = best(lambda: shapely.distance(GA, GB), 3)
    rows.append(("distance", "shapely", t / P, agreement(ref, sample, dist=out)))

    SA, SB = pymunk_shapes(RA), pymunk_shapes(RB)
    t, out = best(lambda: pymunk_pen(SA, SB), 3)
    rows.append(("penetration", "pymunk", t / P, agreement(ref, sample, depth=out)))
    over = np.flatnonzero(mk.intersects_many(RA, RB))
    SAo = [SA[k] for k in over]
    SBo = [SB[k] for k in over]
    t_over, _ = best(lambda: pymunk_pen(SAo, SBo), 3)
    RAo = Ragged.from_list([RA[k] for k in over])
    RBo = Ragged.from_list([RB[k] for k in over])
    t_ours, _ = best(lambda: mk.penetration_many(RAo, RBo), 5)
    rows.append(("penetration (overlapping only)", "minkowski2d", t_ours / len(over), ""))
    rows.append(("penetration (overlapping only)", "pymunk", t_over / len(over), ""))

    nc = min(n_coal, P)
    h = 20.0 * float(np.abs(RA.coords).max() + np.abs(RB.coords).max())
    CA = coal_shapes(Ragged(RA.coords[: RA.offsets[nc]], RA.offsets[: nc + 1]), h)
    CB = coal_shapes(Ragged(RB.coords[: RB.offsets[nc]], RB.offsets[: nc + 1]), h)
    sub = np.array([k for k in sample if k < nc])
    t, out = best(lambda: coal_distance(CA, CB), 3)
    full = np.full(P, np.nan)
    full[:nc] = out
    rows.append(("distance", f"coal ({nc} pairs)", t / nc, agreement(ref, sub, dist=full)))
    t, out = best(lambda: coal_pen(CA, CB), 3)
    full[:nc] = out
    rows.append(("penetration", f"coal ({nc} pairs)", t / nc, agreement(ref, sub, depth=full)))

    ours = {m: t for m, who, t, _ in rows if who == "minkowski2d"}
    print(
        f"| {'query':<30} | {'library':<26} | {'µs/pair':>8} | {'peer/ours':>9} "
        "| agreement with exact |"
    )
    print(f"|{'-' * 32}|{'-' * 28}|{'-' * 10}|{'-' * 11}|{'-' * 22}|")
    for m, who, t, ag in sorted(rows, key=lambda r: (r[0], r[1] != "minkowski2d", r[1])):
        ratio = "" if who.startswith("minkowski2d") else f"{t / ours[m]:.2f}x"
        print(f"| {m:<30} | {who:<26} | {t * 1e6:8.3f} | {ratio:>9} | {ag} |")


def run_contains(rng, n_pts=1_000_000, n_ref=2000):
    """contains: one random convex 64-gon, many points (about half inside), vs shapely's
    prepared ``intersects_xy`` (boundary counts there too)."""
    import shapely
    from tests.test_collision import ref_inside

    t = np.sort(rng.random(64)) * 2 * np.pi
    poly = np.stack([np.cos(t), np.sin(t)], 1)
    pts = rng.random((n_pts, 2)) * 2.4 - 1.2
    mk.contains(poly, pts[:10])
    t_ours, ours = best(lambda: mk.contains(poly, pts), 5)
    g = shapely.Polygon(poly)
    shapely.prepare(g)
    t_sh, sh = best(lambda: shapely.intersects_xy(g, pts[:, 0], pts[:, 1]), 5)
    H = [(Fraction(x), Fraction(y)) for x, y in mk.normalize(poly).tolist()]
    sample = rng.choice(n_pts, size=n_ref, replace=False)
    ref = {k: ref_inside(H, (Fraction(pts[k, 0]), Fraction(pts[k, 1]))) for k in sample}
    print(f"\n## contains: convex 64-gon, {n_pts} points, {100 * ours.mean():.1f}% inside")
    print("| library | ns/point | peer/ours | agreement with exact |")
    print("|---|---|---|---|")
    for who, tt, out in (("minkowski2d", t_ours, ours), ("shapely (prepared)", t_sh, sh)):
        ok = sum(bool(out[k]) == ref[k] for k in sample) / len(sample)
        ratio = "" if who == "minkowski2d" else f"{tt / t_ours:.2f}x"
        print(f"| {who} | {tt / n_pts * 1e9:.1f} | {ratio} | {100 * ok:.2f}% agree |")


def run_threads(rng, P=1_000_000, threads=2):
    """The batch with ``threads=1`` and ``threads=N`` on the same pairs (results checked
    identical)."""
    print(f"\n## threads: {P} pairs, threads=1 vs threads={threads}")
    print("| workload | query | threads=1 µs/pair | threads=N µs/pair | speed-up |")
    print("|---|---|---|---|---|")
    for kind in ("hull8", "ngon64"):
        RA, RB = make(kind, rng, P)
        for m, f in (
            ("intersects", mk.intersects_many),
            ("distance", mk.distance_many),
            ("penetration", mk.penetration_many),
        ):
            f(RA, RB)
            t1, o1 = best(lambda f=f, a=RA, b=RB: f(a, b, threads=1), 3)
            tn, on = best(lambda f=f, a=RA, b=RB: f(a, b, threads=threads), 3)
            parts = [(o1, on)] if isinstance(o1, np.ndarray) else list(zip(o1, on))
            same = all(np.array_equal(x, y) for x, y in parts)
            assert same, (kind, m)
            print(f"| {kind} | {m} | {t1 / P * 1e6:.3f} | {tn / P * 1e6:.3f} | {t1 / tn:.2f}x |")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--pairs", type=int, default=100_000)
    ap.add_argument("--ref", type=int, default=0, help="pairs checked exactly (default 1000/100)")
    ap.add_argument("--coal", type=int, default=20_000)
    ap.add_argument("--only", choices=("hull8", "ngon64", "contains", "threads"), default=None)
    ap.add_argument("--threads", type=int, default=2, help="threads for the threads section")
    args = ap.parse_args()
    rng = np.random.default_rng(2024)
    if args.only == "threads":
        run_threads(rng, 1_000_000 if args.pairs == 100_000 else args.pairs, args.threads)
        return
    for kind in ("hull8", "ngon64"):
        if args.only and kind != args.only:
            continue
        n_ref = args.ref or (1000 if kind == "hull8" else 100)
        run(kind, args.pairs, n_ref, args.coal, rng)
    if args.only in (None, "contains"):
        run_contains(rng)


if __name__ == "__main__":
    main()
