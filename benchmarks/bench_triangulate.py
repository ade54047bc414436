"""Polygon checks and triangulation: the core (exact) against GEOS, side by side.

    python benchmarks/bench_triangulate.py [--esicup ../shared/data/esicup]

Cases: the 2048-vertex star of bench_general (``star(2048, 10000, 5000)``), a
100 000-vertex star, and every part of every ESICUP instance (one call per part, and all
parts in one call). Columns: GEOS ``is_valid`` vs the core's check, GEOS
``constrained_delaunay_triangles`` vs the core's triangulation (with and without the
Delaunay flips), and the Hertel-Mehlhorn piece counts on either triangulation. Times are
the best of several runs, in milliseconds.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np
import shapely

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_general import star  # noqa: E402

import minkowski2d as mk  # noqa: E402
from minkowski2d._core import _ext  # noqa: E402
from minkowski2d._engine import polygon as _polygon  # noqa: E402
from minkowski2d._engine.decompose import _twins, decompose  # noqa: E402


def best(f, reps: int = 5) -> float:
    ts = []
    for _ in range(reps):
        t = time.perf_counter()
        f()
        ts.append(time.perf_counter() - t)
    return 1e3 * min(ts)


def geos_pieces(g) -> int:
    t = shapely.get_parts(shapely.constrained_delaunay_triangles(g))
    c = shapely.get_coordinates(shapely.get_exterior_ring(t)).reshape(len(t), 4, 2)[:, :3]
    verts, inv = np.unique(c.reshape(-1, 2), axis=0, return_inverse=True)
    ids = np.ascontiguousarray(inv.reshape(-1, 3), dtype=np.int64)
    ids = np.ascontiguousarray(ids[_ext.orient_triangles_f(verts, ids)])
    return len(_ext.hertel_mehlhorn_f(verts, ids, _twins(ids, len(verts)), True)[1]) - 1


def row(name: str, geoms: list, reps: int) -> None:
    rings = [_polygon.rings_of(g) for g in geoms]
    n = sum(len(r.coords) for r in rings)

    def tri(delaunay: bool):
        return lambda: [
            _ext.triangulate_polygons_f(r.coords, r.ring_offsets, r.polygon_offsets, delaunay)
            for r in rings
        ]

    t = {
        "geos_valid": best(lambda: [shapely.is_valid(g) for g in geoms], reps),
        "core_check": best(lambda: [_polygon.check(r, "a") for r in rings], reps),
        "geos_cdt": best(lambda: [shapely.constrained_delaunay_triangles(g) for g in geoms], reps),
        "core_tri": best(tri(True), reps),
        "core_mono": best(tri(False), reps),
    }
    hm_core = sum(len(decompose(g, True)[1]) - 1 for g in geoms)
    hm_geos = sum(geos_pieces(g) for g in geoms)
    print(
        f"{name:<28} {n:>8} | {t['geos_valid']:>9.1f} {t['core_check']:>9.1f} | "
        f"{t['geos_cdt']:>9.1f} {t['core_tri']:>9.1f} {t['core_mono']:>9.1f} | "
        f"{hm_geos:>7} {hm_core:>7}"
    )


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    default = Path(__file__).resolve().parents[2] / "shared" / "data" / "esicup"
    ap.add_argument("--esicup", type=Path, default=default)
    args = ap.parse_args()
    print(
        f"{'case':<28} {'vertices':>8} | {'GEOS valid':>9} {'core chk':>9} | "
        f"{'GEOS CDT':>9} {'core tri':>9} {'no flips':>9} | {'HM GEOS':>7} {'HM core':>7}"
    )
    row("star(2048, 10000, 5000)", [shapely.Polygon(star(2048, 10000, 5000))], 7)
    row("star(100000, 1e6, 5e5)", [shapely.Polygon(star(100_000, 1e6, 5e5))], 2)
    if args.esicup.is_dir():
        parts = []
        for f in sorted(args.esicup.glob("*.json")):
            parts += mk.read_esicup(f)["parts"]
        row(f"ESICUP, {len(parts)} parts, 1 call each", parts, 3)
        allp = shapely.MultiPolygon(parts)  # one call (the parts are not checked together)
        r = _polygon.rings_of(allp)
        n = len(r.coords)
        a = (r.coords, r.ring_offsets, r.polygon_offsets)
        print(
            f"{'ESICUP, all in one call':<28} {n:>8} | {'':>9} "
            f"{best(lambda: _ext.check_polygons_f(*a), 3):>9.1f} | {'':>9} "
            f"{best(lambda: _ext.triangulate_polygons_f(*a), 3):>9.1f} "
            f"{best(lambda: _ext.triangulate_polygons_f(*a, False), 3):>9.1f} |"
        )
    else:
        print(f"(ESICUP data not found at {args.esicup})")


if __name__ == "__main__":
    main()
