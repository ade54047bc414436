"""Containers in and out of the batch functions: GeoSeries with index and CRS,
GeometryArray, numpy object arrays of any shape; None and empty members; errors naming the
caller's index; progress reporting."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

import minkowski2d as mk
from minkowski2d.errors import NotConvexError, ShapeError

ROBOT = [(0, 0), (1, 0), (0, 1)]


def _boxes(n: int, seed: int = 0) -> np.ndarray:
    rng = np.random.default_rng(seed)
    x = rng.uniform(0, 100, n)
    y = rng.uniform(0, 100, n)
    return shapely.box(x, y, x + rng.uniform(1, 3, n), y + rng.uniform(1, 3, n))


def _coords(g) -> list:
    return shapely.get_coordinates(g)[:-1].tolist()


def test_object_array_in_object_array_out_any_shape():
    g = _boxes(6).reshape(2, 3)
    g[1, 1] = None
    g[0, 2] = shapely.Polygon()
    out = mk.minkowski_sum_many(g, ROBOT)
    assert isinstance(out, np.ndarray) and out.dtype == object and out.shape == (2, 3)
    assert out[1, 1] is None
    assert out[0, 2].is_empty
    assert _coords(out[0, 0]) == mk.minkowski_sum(g[0, 0], ROBOT).tolist()
    hit = mk.intersects_many(g, g[0, 0])
    assert hit.shape == (2, 3) and hit.dtype == bool
    assert hit[0, 0] and not hit[1, 1] and not hit[0, 2]
    d = mk.distance_many(g, ROBOT)
    assert d.distance.shape == (2, 3) and np.isnan(d.distance[1, 1])
    assert np.isnan(d.distance[0, 2])
    assert d.point_a.shape == (2, 3) and d.point_a[1, 1] is None
    assert d.point_a[0, 0].equals(shapely.Point(mk.distance(g[0, 0], ROBOT).point_a))


def test_geoseries_keeps_index_crs_name():
    gpd = pytest.importorskip("geopandas", reason="geopandas is not installed (extra 'geo')")
    g = list(_boxes(5))
    g[2] = None
    g[3] = shapely.Polygon()
    gs = gpd.GeoSeries(g, index=list("vwxyz"), crs="EPSG:32633", name="parcels")
    out = mk.minkowski_sum_many(gs, ROBOT)
    assert isinstance(out, gpd.GeoSeries)
    assert out.index.tolist() == list("vwxyz") and out.name == "parcels"
    assert out.crs == gs.crs and out.crs.to_epsg() == 32633
    assert out["x"] is None and out["y"].is_empty
    for k in "vwz":
        assert _coords(out[k]) == mk.minkowski_sum(gs[k], ROBOT).tolist()
    # scalar results: pandas Series with that index
    hit = mk.intersects_many(gs, gs["v"])
    assert hit.index.tolist() == list("vwxyz") and str(hit.dtype) == "boolean"
    assert hit["v"] and hit.isna()["x"] and not hit["y"]
    d = mk.distance_many(gs, [(50, 50)])
    assert d.distance.index.tolist() == list("vwxyz") and np.isnan(d.distance["x"])
    assert d.distance["v"] == mk.distance(gs["v"], [(50, 50)]).distance
    assert isinstance(d.point_a, gpd.GeoSeries) and d.point_a.crs == gs.crs
    p = mk.penetration_many(gs, gs["v"])
    assert p.depth.index.tolist() == list("vwxyz")
    assert p.normal.columns.tolist() == ["x", "y"] and np.isnan(p.normal.loc["y", "x"])
    ref = mk.penetration(gs["w"], gs["v"])
    assert p.depth["w"] == ref.depth and p.normal.loc["w"].tolist() == ref.normal.tolist()


def test_pairwise_geoseries_and_geometryarray():
    gpd = pytest.importorskip("geopandas", reason="geopandas is not installed (extra 'geo')")
    a = gpd.GeoSeries(_boxes(4, 1), crs=3857)
    b = gpd.GeoSeries(_boxes(4, 2), crs=3857)
    out = mk.minkowski_sum_many(a, b)
    for k in range(4):
        assert _coords(out[k]) == mk.minkowski_sum(a[k], b[k]).tolist()
    arr = mk.minkowski_sum_many(a.array, ROBOT)
    assert type(arr).__name__ == "GeometryArray" and arr.crs == a.crs
    with pytest.raises(ShapeError, match="different CRS"):
        mk.minkowski_sum_many(a, b.set_crs(4326, allow_override=True))
    with pytest.raises(ShapeError, match="equal counts"):
        mk.intersects_many(a, b[:3])


def test_dataframe_uses_its_geometry():
    gpd = pytest.importorskip("geopandas", reason="geopandas is not installed (extra 'geo')")
    df = gpd.GeoDataFrame({"id": [1, 2]}, geometry=list(_boxes(2)), crs=3857)
    out = mk.minkowski_sum_many(df, ROBOT)
    assert isinstance(out, gpd.GeoSeries) and out.crs == df.crs


def test_bad_members_are_named_by_index_label():
    gpd = pytest.importorskip("geopandas", reason="geopandas is not installed (extra 'geo')")
    dent = shapely.Polygon([(0, 0), (4, 0), (2, 1), (4, 4), (0, 4)])
    g = list(_boxes(200))
    g[150] = dent
    gs = gpd.GeoSeries(g, index=np.arange(200) * 10)
    for fn in (mk.minkowski_sum_many, mk.intersects_many, mk.distance_many):
        with pytest.raises(NotConvexError) as e:
            fn(gs, ROBOT)
        assert e.value.argument == "As[1500]" and e.value.vertex == 2
        # also when chunked for progress: the index is the caller's, not the chunk's
        with pytest.raises(NotConvexError) as e:
            fn(gs, ROBOT, progress=lambda d, t: None)
        assert e.value.argument == "As[1500]"
    # a None before the bad member does not shift the name
    g[3] = None
    with pytest.raises(NotConvexError, match=r"As\[1500\]"):
        mk.minkowski_sum_many(gpd.GeoSeries(g, index=np.arange(200) * 10), ROBOT)
    mp = gpd.GeoSeries([g[0], shapely.MultiPolygon([g[0], g[1]])], index=["a", "b"])
    with pytest.raises(ShapeError, match=r"As\['b'\]: a MultiPolygon") as e:
        mk.minkowski_sum_many(mp, ROBOT)
    assert "explode" in e.value.hint
    holed = shapely.Polygon([(0, 0), (9, 0), (9, 9), (0, 9)], [[(3, 3), (4, 3), (4, 4)]])
    with pytest.raises(NotConvexError, match=r"Bs\[1\]: polygon has 1 hole"):
        mk.distance_many(ROBOT, np.array([g[0], holed], dtype=object))


def test_multipolygon_in_a_plain_list_is_not_flattened():
    with pytest.raises(ShapeError, match=r"As\[1\]: a MultiPolygon"):
        mk.minkowski_sum_many([shapely.box(0, 0, 1, 1), shapely.MultiPolygon(_boxes(2))], ROBOT)


def test_progress_callback_and_bar(capsys):
    polys = [np.array([[0, 0], [k + 1, 0], [0, 1]]) for k in range(1000)]
    calls = []
    r = mk.minkowski_sum_many(polys, ROBOT, progress=lambda d, t: calls.append((d, t)))
    assert r == mk.minkowski_sum_many(polys, ROBOT)
    assert len(calls) == 64 and calls[-1] == (1000, 1000)
    assert [d for d, _ in calls] == sorted(d for d, _ in calls)
    calls.clear()
    d = mk.distance_many(polys[:10], ROBOT, progress=lambda d, t: calls.append((d, t)))
    assert calls[-1] == (10, 10) and len(calls) == 10
    assert d.distance.tolist() == mk.distance_many(polys[:10], ROBOT).distance.tolist()
    calls.clear()
    mk.intersects_many([], ROBOT, progress=lambda d, t: calls.append((d, t)))
    assert calls[-1] == (0, 0)
    pytest.importorskip("tqdm", reason="tqdm is not installed")
    mk.penetration_many(polys, ROBOT, progress=True)
    err = capsys.readouterr().err
    assert "1000/1000" in err or "pair" in err
    with pytest.raises(TypeError, match="progress"):
        mk.minkowski_sum_many(polys, ROBOT, progress="yes")


def test_a_general_function_adopts_apply_in_one_call():
    """How minkowski_sum_general_many / offset (built elsewhere) plug in: ``convex=False``
    lets holes and MultiPolygons through; the result is boxed the same way."""
    gpd = pytest.importorskip("geopandas", reason="geopandas is not installed (extra 'geo')")
    from functools import partial

    from minkowski2d._engine.containers import apply

    def general_many(As, Bs, *, scale):
        return [shapely.affinity.scale(a, scale, scale) for a in As]

    holed = shapely.box(0, 0, 9, 9).difference(shapely.box(3, 3, 6, 6))
    multi = shapely.MultiPolygon(list(_boxes(2)))
    gs = gpd.GeoSeries([holed, None, multi], index=[3, 4, 5], crs=3857)
    out = apply(partial(general_many, scale=2.0), gs, ROBOT, convex=False)
    assert isinstance(out, gpd.GeoSeries) and out.crs == gs.crs and out.index.tolist() == [3, 4, 5]
    assert out[3].area == 4 * holed.area and out[4] is None and out[5].geom_type == "MultiPolygon"
    one = apply(lambda As: [a.buffer(1) for a in As], gs, convex=False, names=("polygons",))
    assert one[4] is None and one[3].area > holed.area


# -- the general batch and offset adopt the same rules --------------------------------------
def test_general_many_and_offset_keep_geoseries_index_and_crs():
    gpd = pytest.importorskip("geopandas", reason="the geo extra (geopandas) is not installed")
    s = gpd.GeoSeries(
        [shapely.box(0, 0, 2, 1), None, shapely.box(5, 5, 6, 6)], index=[10, 20, 30], crs=3857
    )
    L = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    r = mk.minkowski_sum_general_many(s, L)
    assert isinstance(r, gpd.GeoSeries)
    assert r.index.tolist() == [10, 20, 30] and r.crs == s.crs
    assert r.iloc[1] is None
    assert r.iloc[0].equals(mk.minkowski_sum_general(shapely.box(0, 0, 2, 1), L))
    o = mk.offset(s, 0.5, tolerance=1e-3)
    assert isinstance(o, gpd.GeoSeries) and o.index.tolist() == [10, 20, 30]
    assert o.crs == s.crs and o.iloc[1] is None
    assert o.iloc[2].equals(mk.offset(shapely.box(5, 5, 6, 6), 0.5, tolerance=1e-3))


def test_general_many_object_array_in_object_array_out():
    a = np.array([shapely.box(0, 0, 1, 1), None], dtype=object)
    r = mk.minkowski_sum_general_many(a, [(0, 0), (1, 0), (0, 1)])
    assert isinstance(r, np.ndarray) and r.dtype == object and r.shape == (2,)
    assert r[1] is None and r[0].area == pytest.approx(3.5)
