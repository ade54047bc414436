"""Ecosystem figures (issue 13): the GeoSeries round-trip cost per polygon, the speed-up of
``threads=``, and a Dask LocalCluster against one process.

    python benchmarks/bench_ecosystem.py [--n 400000] [--no-dask]

Best of --repeat runs; on a shared machine the threads and Dask rows depend on how many
cores are free.
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time

import numpy as np
import shapely

import minkowski2d as mk

ROBOT = [(0, 0), (2, 0), (1, 2)]


def boxes(n: int, seed: int = 0) -> np.ndarray:
    rng = np.random.default_rng(seed)
    x = rng.uniform(0, 1e4, n)
    y = rng.uniform(0, 1e4, n)
    return shapely.box(x, y, x + rng.uniform(1, 9, n), y + rng.uniform(1, 9, n))


def polygons(n: int, k: int = 16, seed: int = 0) -> mk.Ragged:
    """n convex k-gons (regular, random centre, radius and phase)."""
    rng = np.random.default_rng(seed)
    t = np.linspace(0, 2 * np.pi, k, endpoint=False)[None, :] + rng.uniform(0, 1, (n, 1))
    r = rng.uniform(1, 9, (n, 1))
    c = rng.uniform(0, 1e4, (n, 2))
    xy = np.stack([c[:, :1] + r * np.cos(t), c[:, 1:] + r * np.sin(t)], axis=-1)
    return mk.Ragged(xy.reshape(-1, 2), np.arange(0, n * k + 1, k))


def best(f, repeat: int) -> float:
    out = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        out.append(time.perf_counter() - t0)
    return min(out)


def row(label: str, t: float, n: int, ref: float | None = None) -> None:
    extra = f"  ({t / ref:.1f}x the Ragged call)" if ref else ""
    print(f"| {label} | {t * 1e3:.1f} ms | {t / n * 1e6:.2f} µs |{extra}")


def part(k: int, folder: str, n: int) -> int:
    import geopandas as gpd

    idx = np.arange(n) + k * n
    df = gpd.GeoDataFrame({"k": k}, geometry=boxes(n, k), crs="EPSG:32633", index=idx)
    df.to_parquet(os.path.join(folder, f"part-{k:03d}.parquet"))
    return n


def inflate(df, robot):
    out = df.copy()
    out["geometry"] = mk.minkowski_sum_many(df.geometry, robot)
    out["clearance"] = mk.distance_many(df.geometry, [(5000.0, 5000.0)]).distance
    return out


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=400_000)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--no-dask", action="store_true")
    a = ap.parse_args()
    n = a.n
    import geopandas as gpd

    g = boxes(n)
    gs = gpd.GeoSeries(g, crs=32633)
    r = mk.Ragged.from_shapely(g)
    print(f"## GeoSeries round trip, {n} boxes ⊕ a triangle (best of {a.repeat})")
    print("| path | time | per polygon |")
    t_r = best(lambda: mk.minkowski_sum_many(r, ROBOT), a.repeat)
    row("Ragged -> Ragged", t_r, n)
    row("Ragged.from_shapely", best(lambda: mk.Ragged.from_shapely(g), a.repeat), n)
    s = mk.minkowski_sum_many(r, ROBOT)
    row("Ragged.to_shapely", best(lambda: s.to_shapely(), a.repeat), n)
    row(
        "object array -> object array",
        best(lambda: mk.minkowski_sum_many(g, ROBOT), a.repeat),
        n,
        t_r,
    )
    t_gs = best(lambda: mk.minkowski_sum_many(gs, ROBOT), a.repeat)
    row("GeoSeries -> GeoSeries (index, CRS)", t_gs, n, t_r)
    row("GeoSeries.buffer(1.0), for scale", best(lambda: gs.buffer(1.0), 1), n)
    t_d = best(lambda: mk.distance_many(r, [(5000.0, 5000.0)]), a.repeat)
    row("distance_many, Ragged", t_d, n)
    row(
        "distance_many, GeoSeries (Series + 2 GeoSeries of witnesses)",
        best(lambda: mk.distance_many(gs, [(5000.0, 5000.0)]), a.repeat),
        n,
    )

    print(f"\n## threads=, {n // 2} pairs of 16-gons (best of {a.repeat}; {os.cpu_count()} cores)")
    A, B = polygons(n // 2, 16, 1), polygons(n // 2, 16, 2)
    base = {}
    for name, f in (
        ("minkowski_sum_many", mk.minkowski_sum_many),
        ("distance_many", mk.distance_many),
        ("penetration_many", mk.penetration_many),
    ):
        for th in (1, 2):
            t = best(lambda f=f, th=th: f(A, B, threads=th), a.repeat)
            base.setdefault(name, t)
            print(f"| {name} | threads={th} | {t * 1e3:.1f} ms | {base[name] / t:.2f}x |")

    if a.no_dask:
        return
    import dask_geopandas
    from dask.distributed import Client, LocalCluster

    parts, per = 8, n // 8
    with tempfile.TemporaryDirectory() as tmp:
        src, dst = os.path.join(tmp, "in"), os.path.join(tmp, "out")
        os.mkdir(src)
        t0 = time.perf_counter()
        with (
            LocalCluster(
                n_workers=2,
                threads_per_worker=1,
                processes=True,
                host="127.0.0.1",
                dashboard_address=None,
            ) as cl,
            Client(cl) as c,
        ):
            t_start = time.perf_counter() - t0
            c.run(lambda: mk.minkowski_sum([(0, 0)], [(0, 0)]))
            c.gather(c.map(part, range(parts), folder=src, n=per))
            ddf = dask_geopandas.read_parquet(src)
            t1 = time.perf_counter()
            ddf.map_partitions(inflate, ROBOT, meta=inflate(ddf._meta, ROBOT)).to_parquet(dst)
            t_dask = time.perf_counter() - t1
        t1 = time.perf_counter()
        one = inflate(gpd.read_parquet(src), ROBOT)
        one.to_parquet(os.path.join(tmp, "one.parquet"))
        t_one = time.perf_counter() - t1
    print(
        f"\n## Dask, {parts} parquet partitions of {per} boxes: "
        "read -> inflate + clearance -> write"
    )
    print(f"| LocalCluster start (2 processes) | {t_start:.2f} s |")
    print(f"| Dask, 2 worker processes | {t_dask:.2f} s | {t_one / t_dask:.2f}x one process |")
    print(f"| one process (geopandas) | {t_one:.2f} s | |")


if __name__ == "__main__":
    main()
