"""Reliability on the command line: class 6 (one line on stderr, exit status 2, never a
traceback), the .dat integer beyond int64 (class 8), FeatureCollections with properties
kept for the plug-in commands, DXF input with arcs, and mk.animate's safe writer."""

from __future__ import annotations

import contextlib
import io
import json
import math
import os
from pathlib import Path

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import minkowski2d as mk
from minkowski2d.cli import main

L = [[0, 0], [3, 0], [3, 1], [1, 1], [1, 3], [0, 3]]
SQ = [[0, 0], [1, 0], [1, 1], [0, 1]]


def run(args) -> tuple[int, str, str]:
    """main() in this process; (status, stdout, stderr). No capsys: hypothesis reuses it."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            rc = main([str(a) for a in args])
        except SystemExit as e:  # argparse's own usage errors
            rc = e.code
    return rc, out.getvalue(), err.getvalue()


def one_line_error(rc: int, err: str, *words: str) -> None:
    assert rc == 2, err
    assert err.startswith("minkowski2d: error: ") and err.count("\n") == 1, err
    assert "Traceback" not in err
    for w in words:
        assert w in err, (w, err)


def write(tmp_path: Path, name: str, text: str) -> Path:
    p = tmp_path / name
    p.write_text(text)
    return p


def instance(**changes) -> dict:
    d = {
        "name": "t",
        "strip": {"height": 10, "length": None},
        "pieces": [{"id": "L", "quantity": 1, "rotations": [0], "outer": L, "holes": []}],
    }
    d.update(changes)
    return d


# --------------------------------------------------------------------------------------
# class 6: the reproducers


def test_plan_5000_digit_int(tmp_path):
    f = write(tmp_path, "s.json", '{"obstacles": [[[0, 0], [2, 0], [0, ' + "9" * 5000 + "]]]}")
    one_line_error(*run(["plan", f, "--start", "5,5", "--goal", "6,6"])[::2], "s.json", "digits")


def test_plan_feature_that_is_a_string(tmp_path):
    f = write(tmp_path, "s.json", json.dumps({"type": "FeatureCollection", "features": ["abc"]}))
    rc, _, err = run(["plan", f, "--start", "0,0", "--goal", "1,1"])
    one_line_error(rc, err, "s.json", "features[0]")


def test_plan_features_not_a_list(tmp_path):
    f = write(tmp_path, "s.json", json.dumps({"type": "FeatureCollection", "features": 5}))
    rc, _, err = run(["plan", f, "--start", "0,0", "--goal", "1,1"])
    one_line_error(rc, err, "s.json", "features")


def test_plan_one_point_workspace(tmp_path):
    f = write(tmp_path, "s.json", json.dumps({"obstacles": [], "workspace": [[1, 1]]}))
    rc, _, err = run(["plan", f, "--start", "0,0", "--goal", "1,1"])
    one_line_error(rc, err, "s.json", "workspace")


def test_nfp_int_beyond_float(tmp_path):
    d = instance()
    d["pieces"][0]["outer"] = [[0, 0], [2**1024, 0], [0, 1]]
    f = write(tmp_path, "i.json", json.dumps(d))
    one_line_error(*run(["nfp", f])[::2], "i.json", "pieces[0]", "float64")


def test_nfp_deeply_nested_json(tmp_path):
    f = write(tmp_path, "i.json", "[" * 100_000 + "]" * 100_000)
    one_line_error(*run(["nfp", f])[::2], "i.json", "nested")


def test_nfp_rotation_not_a_number(tmp_path):
    d = instance()
    d["pieces"][0]["rotations"] = ["x"]
    f = write(tmp_path, "i.json", json.dumps(d))
    one_line_error(*run(["nfp", f])[::2], "i.json", "pieces[0]", "rotations")


def test_nfp_strip_a_list(tmp_path):
    f = write(tmp_path, "i.json", json.dumps(instance(strip=[1, 2])))
    one_line_error(*run(["nfp", f])[::2], "i.json", "strip")


def test_offset_with_10_pow_400(tmp_path):
    f = write(tmp_path, "p.json", json.dumps([[0, 0], [10**400, 0], [0, 1]]))
    one_line_error(*run(["offset", f, "-r", "1"])[::2], "p.json", "float64")


def test_nfp_with_10_pow_400(tmp_path):
    d = instance()
    d["pieces"][0]["outer"] = [[0, 0], [10**400, 0], [0, 1]]
    f = write(tmp_path, "i.json", json.dumps(d))
    one_line_error(*run(["nfp", f])[::2], "i.json", "float64")


def test_foreign_errors_have_one_line_as_the_last_defence(tmp_path, monkeypatch):
    """Whatever command hits an OverflowError, a RecursionError or a GEOS error from bad
    data, the CLI says one line and exits 2 (a bug elsewhere keeps its traceback)."""
    import minkowski2d.convex as convex

    f = write(tmp_path, "t.json", json.dumps(SQ))
    for exc in (OverflowError("x"), RecursionError("y"), shapely.errors.GEOSException("z")):

        def boom(*a, _e=exc, **k):
            raise _e

        monkeypatch.setattr(convex, "convex_hull", boom)
        rc, _, err = run(["hull", f])
        one_line_error(rc, err)
    monkeypatch.setattr(convex, "convex_hull", lambda *a, **k: 1 / 0)
    with pytest.raises(ZeroDivisionError):
        main(["hull", str(f)])


# a fuzz over scene and instance files: any JSON value anywhere gives 0 or one line and 2

JUNK = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(-(10**400), 10**400),
    st.floats(allow_nan=True, allow_infinity=True),
    st.text(max_size=5),
    st.lists(st.integers(-5, 5), max_size=3),
    st.dictionaries(st.sampled_from(["type", "coordinates", "role"]), st.integers(), max_size=2),
)


def _mutate(obj, path, value):
    if not path:
        return value
    k, rest = path[0], path[1:]
    if isinstance(obj, dict) and obj:
        key = sorted(obj)[k % len(obj)]
        return {**obj, key: _mutate(obj[key], rest, value)}
    if isinstance(obj, list) and obj:
        i = k % len(obj)
        return [*obj[:i], _mutate(obj[i], rest, value), *obj[i + 1 :]]
    return value


SCENE = {
    "robot": [[-1, -1], [1, -1], [1, 1], [-1, 1]],
    "obstacles": [[[2, -1], [4, -1], [4, 3], [2, 3]], {"type": "Polygon", "coordinates": [L]}],
    "workspace": [-10, -10, 10, 10],
}
SCENE_FC = {
    "type": "FeatureCollection",
    "features": [
        {
            "type": "Feature",
            "properties": {"role": "robot"},
            "geometry": {"type": "Polygon", "coordinates": [SQ]},
        },
        {
            "type": "Feature",
            "properties": {"name": "L"},
            "geometry": {"type": "Polygon", "coordinates": [L]},
        },
    ],
}


@settings(max_examples=60, deadline=None, suppress_health_check=list(HealthCheck))
@given(
    base=st.sampled_from(["scene", "fc", "instance"]),
    path=st.lists(st.integers(0, 7), max_size=5),
    value=JUNK,
)
def test_fuzz_scene_and_instance_files(tmp_path_factory, base, path, value):
    doc = {"scene": SCENE, "fc": SCENE_FC, "instance": instance()}[base]
    text = json.dumps(_mutate(doc, path, value))
    f = tmp_path_factory.mktemp("fuzz") / "in.json"
    f.write_text(text)
    args = ["nfp", f] if base == "instance" else ["plan", f, "--start=-8,-8", "--goal", "8,8"]
    rc, _, err = run(args)
    assert rc in (0, 2), err
    if rc == 2:
        one_line_error(rc, err)


# class 2 on the command line: the plan CLI agrees with the library


def test_plan_when_lengths_pass_float64(tmp_path):
    T = [[0.0, 0.0], [1e300, 0.0], [0.0, 1e300]]
    f = write(tmp_path, "t.json", json.dumps({"obstacles": [T], "robot": T}))
    rc, out, err = run(["plan", f, "--start=-1e308,-1e308", "--goal", "1e308,1e308"])
    assert rc == 0, err
    got = json.loads(out)
    assert got["length"] is None and "null" in err  # valid path, its length beyond float64
    assert got["path"][0] == [-1e308, -1e308] and len(got["path"]) == 3
    rc, out, err = run(["plan", f, "--start=-1e307,-1e307", "--goal", "1e307,1e307"])
    assert rc == 0, err
    assert 2.8e307 < json.loads(out)["length"] < 2.9e307
    rc, _, err = run(
        ["plan", f, "--start=-1e308,-1e308", "--goal", "1e308,1e308", "--format", "svg"]
    )
    one_line_error(rc, err.splitlines()[-1] + "\n", "svg")


# --------------------------------------------------------------------------------------
# class 8: a .dat file with an integer beyond int64


def test_dat_int_beyond_int64(tmp_path):
    big = 10**30
    f = write(tmp_path, "big.dat", f"4 0 0 {big} 0 {big} {big} 0 {big}\n")
    g = write(tmp_path, "tri.dat", "3 0 0 1 0 0 1\n")
    rc, out, err = run(["sum", f, g])
    assert rc == 0, err
    assert json.loads(out) == [[0, 0], [big + 1, 0], [big + 1, big], [big, big + 1], [0, big + 1]]
    rc, out, err = run(["hull", f, "--format", "wkt"])
    assert rc == 0 and out.strip() == f"POLYGON ((0 0, {big} 0, {big} {big}, 0 {big}, 0 0))"
    for cmd in (["collide", f, g], ["inflate", f, g], ["animate", f, g, "-o", "-"]):
        rc, out, err = run(cmd)
        assert rc == 0, (cmd, err)
    # the general routines compute in float64: 2**70 is exact, 10**30 is refused (one line)
    f2 = write(tmp_path, "f2.dat", f"4 0 0 {2**70} 0 {2**70} {2**70} 0 {2**70}\n")
    for cmd in (["sum-general", f2, g], ["erode", f2, g], ["decompose", f2]):
        rc, out, err = run(cmd)
        assert rc == 0, (cmd, err)
    one_line_error(*run(["sum-general", f, g])[::2], "big.dat", "53 significant bits")
    huge = write(tmp_path, "huge.dat", f"3 0 0 {10**400} 0 0 1\n")
    for cmd in (
        ["sum", huge, g, "--format", "svg"],
        ["decompose", huge],
        ["offset", huge, "-r", "1"],
    ):
        rc, _, err = run(cmd)
        one_line_error(rc, err)
    assert "huge.dat" in run(["decompose", huge])[2]


# --------------------------------------------------------------------------------------
# FeatureCollections for the plug-in commands, properties kept


def feature(coords, props, fid=None):
    f = {"type": "Feature", "properties": props}
    f["geometry"] = (
        None if coords is None else {"type": "Polygon", "coordinates": [coords + [coords[0]]]}
    )
    if fid is not None:
        f["id"] = fid
    return f


@pytest.fixture
def fc(tmp_path):
    feats = [
        feature([[0, 0], [4, 0], [4, 4], [0, 4]], {"name": "rock"}, "o1"),
        feature(None, {"name": "nothing"}),
        feature(L, {"name": "L"}),
    ]
    p = write(
        tmp_path, "parts.geojson", json.dumps({"type": "FeatureCollection", "features": feats})
    )
    return p, write(tmp_path, "sq.json", json.dumps(SQ))


def _features(out: str) -> list:
    data = json.loads(out)
    assert data["type"] == "FeatureCollection"
    return data["features"]


def test_collide_feature_collection(fc):
    p, sq = fc
    rc, out, err = run(["collide", p, sq, "--hull"])
    assert rc == 0, err
    f0, f1, f2 = _features(out)
    assert f0["id"] == "o1" and f0["properties"]["name"] == "rock"
    assert f0["properties"]["intersects"] is True and f1["geometry"] is None
    assert f2["properties"]["name"] == "L" and "penetration" in f2["properties"]


def test_sum_general_erode_decompose_feature_collections(fc):
    p, sq = fc
    for cmd, check in (
        ("sum-general", lambda g: shapely.geometry.shape(g).area == 8 + 9 - 4 + 4 + 1),
        ("erode", lambda g: shapely.geometry.shape(g).area == 9),
    ):
        rc, out, err = run([cmd, p, sq])
        assert rc == 0, err
        f0, f1, f2 = _features(out)
        assert f0["properties"] == {"name": "rock"} and f0["id"] == "o1"
        assert f1["geometry"] is None and f2["properties"] == {"name": "L"}
        if cmd == "erode":
            assert check(f0["geometry"])
    rc, out, err = run(["decompose", p])
    assert rc == 0, err
    f0, _, f2 = _features(out)
    assert f2["geometry"]["type"] == "MultiPolygon" and f2["properties"] == {"name": "L"}
    assert shapely.geometry.shape(f2["geometry"]).area == 5


def test_offset_feature_collection(fc, tmp_path):
    p, _ = fc
    rc, out, err = run(["offset", p, "-r", "0.5"])
    assert rc == 0, err
    f0, f1, f2 = _features(out)
    assert f0["properties"] == {"name": "rock"} and f1["geometry"] is None
    want = mk.offset([(0, 0), (4, 0), (4, 4), (0, 4)], 0.5)
    assert shapely.geometry.shape(f0["geometry"]).hausdorff_distance(want) < 1e-12
    rc, out, err = run(["offset", p, "-r", "0.5", "--format", "svg"])  # exact arcs
    assert rc == 0 and out.count(" A ") >= 4
    rc, out, err = run(["offset", p, "-r", "0.5", "--format", "wkt"])
    assert rc == 0 and out.splitlines()[1] == "GEOMETRYCOLLECTION EMPTY"


def test_nfp_feature_collection_instance(tmp_path):
    feats = [
        feature(SQ, {"id": "sq", "quantity": 2, "rotations": [0, 90], "colour": "red"}),
        feature(L, {"id": "L", "colour": "blue"}),
    ]
    inst = {"type": "FeatureCollection", "strip": {"height": 5}, "features": feats}
    f = write(tmp_path, "parts.geojson", json.dumps(inst))
    rc, out, err = run(["nfp", f, "--format", "geojson"])
    assert rc == 0, err
    nfps = [x for x in _features(out) if x["properties"]["kind"] == "nfp"]
    ifps = [x for x in _features(out) if x["properties"]["kind"] == "ifp"]
    assert len(nfps) == 9 and len(ifps) == 3
    one = next(x for x in nfps if x["properties"]["i"] == 0 and x["properties"]["j"] == 1)
    assert one["properties"]["a"]["colour"] == "red" and one["properties"]["b"]["colour"] == "blue"
    assert ifps[0]["properties"]["part"]["id"] == "sq"


def test_plan_feature_collection_properties_kept(tmp_path):
    f = write(tmp_path, "scene.geojson", json.dumps(SCENE_FC))
    rc, out, err = run(["plan", f, "--start", "5,5", "--goal=-5,-5", "--format", "geojson"])
    assert rc == 0, err
    obs = [x for x in _features(out) if x["properties"]["role"] in ("obstacle", "c-obstacle")]
    assert [x["properties"]["name"] for x in obs] == ["L", "L"]


# --------------------------------------------------------------------------------------
# DXF with arcs: a one-sided approximation (parts grow, holes shrink) within a tolerance


@pytest.fixture
def part_dxf(tmp_path):
    ezdxf = pytest.importorskip("ezdxf", reason="ezdxf is not installed (extra 'dxf')")
    doc = ezdxf.new()
    msp = doc.modelspace()
    # a 10 x 10 plate, one corner rounded (radius 2, a bulge), a round hole (a CIRCLE) and
    # a slot made of LINE and ARC entities
    b = math.tan(math.radians(90) / 4)
    msp.add_lwpolyline(
        [(0, 0, 0), (10, 0, 0), (10, 8, b), (8, 10, 0), (0, 10, 0)], format="xyb", close=True
    )
    msp.add_circle((3, 3), 1)
    msp.add_line((6, 4), (8, 4))
    msp.add_arc((8, 5), 1, -90, 90)
    msp.add_line((8, 6), (6, 6))
    msp.add_arc((6, 5), 1, 90, 270)
    msp.add_circle((20, 20), 2)  # a second part: a disk
    path = tmp_path / "part.dxf"
    doc.saveas(path)
    return path


TRUE_PLATE = 100 - (4 - math.pi) - math.pi - (4 + math.pi)


def _circle_points(c, r, n=720):
    t = np.linspace(0, 2 * math.pi, n, endpoint=False)
    return np.column_stack([c[0] + r * np.cos(t), c[1] + r * np.sin(t)])


@pytest.mark.parametrize("tol", [None, 1e-2, 1e-5])
def test_dxf_arcs_one_sided(part_dxf, tol):
    from minkowski2d.io import read_dxf

    plate, disk = read_dxf(part_dxf, tolerance=tol)
    assert plate.properties["entity"] == "LWPOLYLINE" and len(plate.properties["holes"]) == 2
    assert disk.properties["entity"] == "CIRCLE"
    g = plate.geometry
    eps = 2e-3 if tol is None else tol  # 1e-3 times the radius (at most 2)
    # parts grow: the polygon contains the plate, within eps (area and the boundary)
    assert TRUE_PLATE <= g.area <= TRUE_PLATE + g.length * eps
    rounded = _circle_points((8, 8), 2)
    q = rounded[(rounded[:, 0] >= 8) & (rounded[:, 1] >= 8)]
    assert shapely.covers(g, shapely.points(q)).all()  # the rounded corner
    hole = _circle_points((3, 3), 1)  # holes shrink: the hole's boundary is in the polygon
    assert shapely.covers(g, shapely.points(hole)).all()
    d = np.hypot(*(shapely.get_coordinates(g.interiors[0]) - (3, 3)).T)
    assert d.min() >= 1 - eps - 1e-12 and d.max() <= 1 + 1e-12
    D = shapely.Polygon(disk.geometry)
    assert shapely.covers(D, shapely.points(_circle_points((20, 20), 2))).all()
    d = np.hypot(*(disk.geometry - (20, 20)).T)
    assert d.min() >= 2 - 1e-12 and d.max() <= 2 + (2e-3 if tol is None else tol) * 2
    # the exact rings are kept on the feature
    assert [len(r) for r in disk.arcs] == [2] and disk.arcs[0][:, 2].tolist() == [1.0, 1.0]


def test_dxf_arcs_on_the_command_line(part_dxf):
    rc, out, err = run(["hull", part_dxf, "--arc-tolerance", "1e-4"])
    assert rc == 0, err
    plate, disk = _features(out)
    assert shapely.geometry.shape(plate["geometry"]).area > 100 - (4 - math.pi) - 1e-9
    rc, out, err = run(["offset", part_dxf, "-r", "0.5", "--format", "geojson"])
    assert rc == 0, err
    plate, disk = _features(out)
    assert plate["properties"]["holes"] and disk["properties"]["entity"] == "CIRCLE"
    # a disk of radius 2 grown by 0.5 contains the disk of radius 2.5
    grown = shapely.geometry.shape(disk["geometry"])
    assert shapely.covers(grown, shapely.points(_circle_points((20, 20), 2.5))).all()
    rc, _, err = run(["hull", part_dxf, "--arc-tolerance", "-1"])
    one_line_error(rc, err, "arc_tolerance")


def test_dxf_ellipse_refused(tmp_path):
    ezdxf = pytest.importorskip("ezdxf", reason="ezdxf is not installed (extra 'dxf')")
    doc = ezdxf.new()
    doc.modelspace().add_ellipse((0, 0), (2, 0), 0.5)
    doc.modelspace().add_circle((5, 5), 1)
    doc.saveas(tmp_path / "e.dxf")
    one_line_error(*run(["hull", tmp_path / "e.dxf"])[::2], "ELLIPSE")


# --------------------------------------------------------------------------------------
# mk.animate writes through the safe writer


def test_animate_replaces_the_file_whole(tmp_path):
    out = tmp_path / "a.html"
    out.write_text("old")
    other = tmp_path / "link.html"
    os.link(out, other)  # a second name of the old file
    p = mk.animate([(0, 0), (2, 0), (0, 2)], SQ, path=out)
    assert p == out and "<html" in out.read_text()
    assert other.read_text() == "old"  # renamed into place, not written through
    assert sorted(x.name for x in tmp_path.iterdir()) == ["a.html", "link.html"]


def test_animate_into_a_directory_leaves_nothing(tmp_path):
    with pytest.raises(OSError, match="directory"):
        mk.animate([(0, 0), (2, 0), (0, 2)], SQ, path=tmp_path)
    assert list(tmp_path.iterdir()) == []


# --------------------------------------------------------------------------------------
# class 6, open-ended: every command on odd files exits 0, or 2 with one line


def _fc(*feats):
    return {"type": "FeatureCollection", "features": list(feats)}


def _feat(g, p=None):
    return {"type": "Feature", "geometry": g, "properties": p}


def _poly(ring):
    return {"type": "Polygon", "coordinates": [ring + [ring[0]]]}


ODD = [
    [],
    [[]],
    [[0, 0]],
    [[0, 0], [1, 1]],
    [[0, 1e308], [1e308, 0], [1, 1]],
    [[0, 0], [10**400, 0], [0, 1]],
    {"type": "Polygon", "coordinates": []},
    {"type": "Polygon", "coordinates": [[[0, 0], [1, 0]]]},
    _fc(),
    _fc(_feat(None)),
    _fc(_feat({"type": "Point", "coordinates": [0, 0]})),
    _fc(_feat(_poly(L), 5)),
    _fc(
        _feat(
            {
                "type": "MultiPolygon",
                "coordinates": [[L + [L[0]]], [[[9, 9], [10, 9], [9, 10], [9, 9]]]],
            }
        )
    ),
    _fc(_feat(_poly([[0, 0], [2, 2], [2, 0], [0, 2]]))),
    _fc(_feat({"type": "LineString", "coordinates": [[0, 0], [1, 1]]}), _feat(_poly(SQ))),
    _fc(_feat(_poly([[0, 0], [1e-320, 0], [0, 1e-320]]))),
    _fc(_feat(_poly([[0, 0], [1e308, 0], [0, 1e308]]))),
    "nan",
    "POLYGON EMPTY",
    "POLYGON ((0 0, 1 0, 0 1, 0 0))",
]


def test_commands_on_odd_files(tmp_path):
    sq = write(tmp_path, "sq.json", json.dumps(SQ))
    for k, doc in enumerate(ODD):
        name = f"odd{k}.wkt" if isinstance(doc, str) else f"odd{k}.json"
        f = write(tmp_path, name, doc if isinstance(doc, str) else json.dumps(doc))
        for cmd in (
            ["sum", f, sq],
            ["sum", f, f, "--format", "svg"],
            ["inflate", f, sq],
            ["hull", f, "--format", "wkt"],
            ["collide", f, sq],
            ["sum-general", f, sq],
            ["erode", f, sq],
            ["decompose", f],
            ["offset", f, "-r", "1"],
            ["offset", f, "-r", "-1", "--format", "svg"],
            ["offset", f, "-r", "1e308"],
            ["animate", f, sq, "-o", "-"],
            ["plan", f, "--start", "0,0", "--goal", "1,1"],
            ["nfp", f],
        ):
            rc, _, err = run(cmd)
            assert rc in (0, 2), (cmd, doc, err)
            if rc == 2:
                lines = [x for x in err.splitlines() if x.startswith("minkowski2d: error: ")]
                assert len(lines) == 1 and "Traceback" not in err, (cmd, doc, err)
