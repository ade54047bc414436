"""The CLI on collections: GeoJSON FeatureCollections of N features in, N out,
properties kept; DXF drawings through ezdxf; exit statuses; shell completion."""

from __future__ import annotations

import json

import pytest

import minkowski2d as mk
from minkowski2d.cli import main
from minkowski2d.io import read_features, read_geometry

ROBOT = [[0, 0], [1, 0], [0, 1]]


def _feature(coords, props, fid=None):
    f = {"type": "Feature", "properties": props}
    f["geometry"] = None if coords is None else {"type": "Polygon", "coordinates": [coords]}
    if fid is not None:
        f["id"] = fid
    return f


@pytest.fixture
def obstacles(tmp_path):
    fc = {
        "type": "FeatureCollection",
        "features": [
            _feature([[0, 0], [4, 0], [4, 4], [0, 4], [0, 0]], {"name": "rock", "h": 3}, "o1"),
            _feature(None, {"name": "nothing"}),
            _feature(
                [[10, 0], [12, 0], [12, 1], [11, 1], [11, 2], [10, 2], [10, 0]], {"name": "L"}
            ),
            _feature([[20, 0], [23, 0], [20, 3], [20, 0]], {"name": "tri"}),
        ],
    }
    p = tmp_path / "obstacles.geojson"
    p.write_text(json.dumps(fc))
    r = tmp_path / "robot.json"
    r.write_text(json.dumps(ROBOT))
    return p, r


def run(args, capsys):
    rc = main([str(a) for a in args])
    out, err = capsys.readouterr()
    return rc, out, err


def test_inflate_feature_collection_keeps_properties(obstacles, capsys):
    p, r = obstacles
    rc, out, err = run(["inflate", p, r], capsys)
    assert rc == 0, err
    fc = json.loads(out)
    assert fc["type"] == "FeatureCollection" and len(fc["features"]) == 4
    f0, f1, f2, f3 = fc["features"]
    assert f0["id"] == "o1" and f0["properties"] == {"name": "rock", "h": 3}
    want = mk.cspace_obstacle([(0, 0), (4, 0), (4, 4), (0, 4)], ROBOT).tolist()
    assert f0["geometry"]["coordinates"][0][:-1] == want
    assert f1["geometry"] is None and f1["properties"] == {"name": "nothing"}
    # the L-shaped obstacle is not convex: the general sum, as for one polygon
    assert f2["properties"] == {"name": "L"} and f2["geometry"]["type"] == "Polygon"
    assert (
        f3["geometry"]["coordinates"][0][:-1]
        == mk.cspace_obstacle([(20, 0), (23, 0), (20, 3)], ROBOT).tolist()
    )


def test_sum_hull_and_formats(obstacles, capsys, tmp_path):
    p, r = obstacles
    rc, out, _ = run(["hull", p, "--format", "wkt"], capsys)
    assert rc == 0
    lines = out.splitlines()
    assert len(lines) == 4 and lines[1] == "GEOMETRYCOLLECTION EMPTY"
    assert lines[2] == "POLYGON ((10 0, 12 0, 12 1, 11 2, 10 2, 10 0))"
    rc, out, _ = run(["sum", r, p, "--hull", "-o", tmp_path / "s.geojson"], capsys)
    assert rc == 0
    fc = json.loads((tmp_path / "s.geojson").read_text())
    assert [f["properties"]["name"] for f in fc["features"]] == ["rock", "nothing", "L", "tri"]
    rc, out, _ = run(["sum", p, p, "--hull", "--format", "svg"], capsys)  # pairwise
    assert rc == 0 and out.startswith("<svg")


def test_bad_feature_exit_2_and_no_partial_file(obstacles, capsys, tmp_path):
    p, r = obstacles
    fc = json.loads(p.read_text())
    fc["features"][2]["geometry"]["coordinates"] = [[[1, 2]]]
    bad = tmp_path / "bad.geojson"
    bad.write_text(json.dumps(fc))
    out_file = tmp_path / "out.geojson"
    rc, out, err = run(["inflate", bad, r, "-o", out_file], capsys)
    assert rc == 2 and "bad.geojson: features[2]" in err and not out_file.exists()
    assert len(err.strip().splitlines()) == 1
    star = json.loads(p.read_text())
    star["features"][0]["geometry"]["coordinates"] = [[[0, 0], [1, 0], [0, 1], [1, 1], [0, 0]]]
    twisted = tmp_path / "twisted.geojson"
    twisted.write_text(json.dumps(star))
    rc, _, err = run(["hull", twisted, "--format", "json"], capsys)
    assert rc == 0  # a hull takes any point set
    two = tmp_path / "two.geojson"
    two.write_text(json.dumps({"type": "FeatureCollection", "features": fc["features"][:2]}))
    rc, _, err = run(["sum", two, p], capsys)
    assert rc == 2 and "2 features" in err and "4" in err
    with pytest.raises(SystemExit) as e:  # usage errors keep argparse's own status
        main(["inflate", str(p)])
    assert e.value.code == 2
    capsys.readouterr()


def test_dxf_closed_polylines_read_back(tmp_path, capsys):
    ezdxf = pytest.importorskip("ezdxf", reason="ezdxf is not installed (extra 'dxf')")
    doc = ezdxf.new()
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0), (3, 0), (3, 2)], close=True, dxfattribs={"layer": "parts"})
    msp.add_polyline2d([(5, 5), (6, 5), (6, 6), (5, 6)], close=True)
    msp.add_lwpolyline([(9, 9), (10, 10)])  # open: skipped
    msp.add_lwpolyline([(0.5, 0.5), (1.5, 0.5), (1.5, 1.25), (0.5, 0.5)])  # closed by repeat
    path = tmp_path / "parts.dxf"
    doc.saveas(path)
    feats = read_features(path)
    assert [f.geometry.tolist() for f in feats] == [
        [[0, 0], [3, 0], [3, 2]],
        [[5, 5], [6, 5], [6, 6], [5, 6]],
        [[0.5, 0.5], [1.5, 0.5], [1.5, 1.25]],
    ]
    assert feats[0].properties["layer"] == "parts"
    assert [f.properties["entity"] for f in feats] == ["LWPOLYLINE", "POLYLINE", "LWPOLYLINE"]
    rc, out, err = run(["inflate", path, path, "--format", "wkt"], capsys)  # pairwise
    assert rc == 0 and len(out.splitlines()) == 3
    with pytest.raises(mk.errors.InputFormatError, match="3 closed polylines"):
        read_geometry(path)  # where one polygon is needed
    (tmp_path / "robot.json").write_text(json.dumps(ROBOT))
    rc, out, err = run(["inflate", path, tmp_path / "robot.json"], capsys)
    assert rc == 0, err
    fc = json.loads(out)
    assert [f["properties"]["handle"] for f in fc["features"]] == [
        f.properties["handle"] for f in feats
    ]
    one = ezdxf.new()
    one.modelspace().add_lwpolyline([(0, 0), (2, 0), (0, 2)], close=True)
    one.saveas(tmp_path / "one.dxf")
    assert read_geometry(tmp_path / "one.dxf").tolist() == [[0, 0], [2, 0], [0, 2]]
    arcs = ezdxf.new()
    arcs.modelspace().add_lwpolyline([(0, 0, 0, 0, 0.5), (2, 0), (0, 2)], close=True)
    arcs.saveas(tmp_path / "arcs.dxf")
    rc, out, err = run(["hull", tmp_path / "arcs.dxf"], capsys)  # arcs are read
    ring = json.loads(out)["features"][0]["geometry"]["coordinates"][0]
    assert rc == 0 and len(ring) > 5, err  # the arc became several vertices
    (tmp_path / "junk.dxf").write_text("this is not DXF")
    rc, _, err = run(["hull", tmp_path / "junk.dxf"], capsys)
    assert rc == 2 and "junk.dxf" in err and len(err.strip().splitlines()) == 1


def test_completion_scripts(capsys):
    pytest.importorskip("shtab", reason="shtab is not installed")
    for shell, marker in (("bash", "complete"), ("zsh", "#compdef")):
        rc, out, _ = run(["completion", shell], capsys)
        assert rc == 0 and marker in out
        for cmd in ("inflate", "sum-general", "collide", "completion"):
            assert cmd in out
    with pytest.raises(SystemExit) as e:
        main(["completion", "fish"])
    assert e.value.code == 2
    capsys.readouterr()
