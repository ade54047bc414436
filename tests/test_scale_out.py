"""The Dask recipe of docs/scale-out.md on a real LocalCluster (2 worker processes on
127.0.0.1): data created on the workers, a warm core on every worker, read_parquet ->
map_partitions with minkowski2d -> to_parquet; results identical to one process, index
and CRS kept."""

from __future__ import annotations

import os
import time

import numpy as np
import pytest

import minkowski2d as mk

ROBOT = [(0, 0), (2, 0), (1, 2)]
HOME = [(5000.0, 5000.0)]
PARTS = 4
PER_PART = 5000


def make_part(k: int, folder: str) -> int:
    """Runs on a worker: builds partition k and writes it (no data crosses the client)."""
    import geopandas as gpd
    import shapely

    rng = np.random.default_rng(k)
    x = rng.uniform(0, 1e4, PER_PART)
    y = rng.uniform(0, 1e4, PER_PART)
    w = rng.uniform(1, 9, PER_PART)
    geom = shapely.box(x, y, x + w, y + rng.uniform(1, 9, PER_PART))
    geom[::997] = None  # a few missing geometries
    df = gpd.GeoDataFrame(
        {"part": k, "name": [f"o{k}-{i}" for i in range(PER_PART)]},
        geometry=geom,
        crs="EPSG:32633",
        index=np.arange(PER_PART) + k * PER_PART,
    )
    df.to_parquet(os.path.join(folder, f"part-{k:03d}.parquet"))
    return len(df)


def inflate(df, robot):
    """The per-partition step: C-space obstacles and the clearance to HOME."""
    out = df.copy()
    out["geometry"] = mk.minkowski_sum_many(df.geometry, robot)
    out["clearance"] = mk.distance_many(df.geometry, HOME).distance
    return out


def warm() -> int:
    """Import minkowski2d and run one small sum on a worker (a warm core)."""
    import minkowski2d

    minkowski2d.minkowski_sum_many([[(0, 0), (1, 0), (0, 1)]], [(0, 0), (1, 1)])
    return os.getpid()


def _warm_plugin():
    from distributed import WorkerPlugin

    class WarmCore(WorkerPlugin):
        """docs/scale-out.md's plugin: a warm core on every worker, also later ones."""

        def setup(self, worker):
            import minkowski2d

            minkowski2d.minkowski_sum([(0, 0), (1, 0), (0, 1)], [(0, 0), (1, 1)])
            worker.minkowski2d_warm = True

    return WarmCore()


def test_dask_local_cluster_matches_one_process(tmp_path):
    pytest.importorskip("distributed", reason="dask[distributed] is not installed (extra 'dask')")
    dask_geopandas = pytest.importorskip(
        "dask_geopandas", reason="dask-geopandas is not installed (extra 'dask')"
    )
    pytest.importorskip("pyarrow", reason="pyarrow is not installed (extra 'dask')")
    import geopandas as gpd
    import shapely
    from dask.distributed import Client, LocalCluster

    src, dst = tmp_path / "obstacles", tmp_path / "cspace"
    src.mkdir()
    t0 = time.perf_counter()
    with (
        LocalCluster(
            n_workers=2,
            threads_per_worker=1,
            processes=True,
            host="127.0.0.1",
            dashboard_address=None,
        ) as cluster,
        Client(cluster) as client,
    ):
        client.register_plugin(_warm_plugin())
        assert all(client.run(lambda dask_worker: dask_worker.minkowski2d_warm).values())
        pids = client.run(warm)
        assert len(set(pids.values())) == 2 and os.getpid() not in pids.values()
        sizes = client.gather(client.map(make_part, range(PARTS), folder=str(src)))
        assert sum(sizes) == PARTS * PER_PART
        ddf = dask_geopandas.read_parquet(str(src))
        assert ddf.npartitions == PARTS
        out = ddf.map_partitions(inflate, ROBOT, meta=inflate(ddf._meta, ROBOT))
        out.to_parquet(str(dst))
    elapsed = time.perf_counter() - t0
    back = gpd.read_parquet(dst).sort_index()
    one = inflate(gpd.read_parquet(src), ROBOT).sort_index()
    assert back.crs == one.crs and back.crs.to_epsg() == 32633
    assert back.index.equals(one.index) and back["name"].equals(one["name"])
    assert back.geometry.isna().sum() == one.geometry.isna().sum() > 0
    ok = one.geometry.notna()
    assert shapely.equals_exact(back.geometry[ok].values, one.geometry[ok].values, 0).all()
    assert np.array_equal(
        shapely.get_coordinates(back.geometry.values), shapely.get_coordinates(one.geometry.values)
    )
    assert np.array_equal(back["clearance"], one["clearance"], equal_nan=True)
    assert elapsed < 60, elapsed
