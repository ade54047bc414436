"""``minkowski2d nest``: instances in (ESICUP JSON, GeoJSON, DXF), a layout out
(JSON on standard output, or -o .json/.geojson/.svg/.dxf), a summary on standard error,
bad input as one line and exit status 2 with no file written. Small ``--iterations``
budgets, never the clock."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET

import pytest

import minkowski2d as mk
from minkowski2d.cli import main

#: a budget of search steps small enough for a test, and no wall-clock limit
FAST = ["--iterations", "20"]

RECT = [[0, 0], [2, 0], [2, 1], [0, 1]]
L_SHAPE = [[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]]


def _instance(tmp_path, height=2, name="inst.json", pieces=None):
    inst = {
        "name": "tiny",
        "strip": {"height": height, "length": None},
        "pieces": pieces
        or [
            {"id": "rect", "quantity": 3, "rotations": [0, 90], "outer": RECT, "holes": []},
            {"id": "L", "quantity": 2, "rotations": [0, 180], "outer": L_SHAPE, "holes": []},
        ],
    }
    f = tmp_path / name
    f.write_text(json.dumps(inst))
    return f


def _run(capsys, *argv):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def _one_error_line(err: str) -> str:
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("minkowski2d: error: "), err
    return lines[0]


def test_strip_json_to_stdout_and_a_summary(tmp_path, capsys):
    inst = _instance(tmp_path)
    code, out, err = _run(capsys, "nest", inst, *FAST)
    assert code == 0
    lay = mk.Layout.from_dict(json.loads(out))
    assert lay.verify() and lay.strip_height == 2.0 and lay.name == "tiny"
    assert len(lay.placements) == 5 and lay.ids == ("rect", "L")
    assert err.startswith("minkowski2d: nest: 5 parts on a strip 2 high, length ")
    assert err.rstrip().endswith("verified") and len(err.strip().splitlines()) == 1
    # the same seed and budget: the same layout
    code, again, _ = _run(capsys, "nest", inst, *FAST)
    assert again == out


def test_options_reach_nest(tmp_path, capsys):
    inst = _instance(tmp_path)
    args = ["--height", "3", "--spacing", "0.25", "--margin", "0.125", "--rotations", "0,90"]
    code, out, _ = _run(capsys, "nest", inst, *args, *FAST, "--seed", "3", "--threads", "1")
    assert code == 0
    lay = mk.Layout.from_dict(json.loads(out))
    assert (lay.strip_height, lay.spacing, lay.margin) == (3.0, 0.25, 0.125)
    assert {p.rotation for p in lay.placements} <= {0, 90}
    assert lay.verify()


@pytest.mark.parametrize("suffix", [".json", ".geojson"])
def test_output_files_read_back(tmp_path, capsys, suffix):
    inst = _instance(tmp_path)
    out = tmp_path / f"layout{suffix}"
    code, stdout, err = _run(capsys, "nest", inst, *FAST, "-o", out)
    assert code == 0 and stdout == "" and "verified" in err
    lay = mk.read_layout(out)
    assert lay.verify() and len(lay.placements) == 5


def test_svg_and_dxf_outputs(tmp_path, capsys):
    inst = _instance(tmp_path)
    code, _, _ = _run(capsys, "nest", inst, *FAST, "-o", tmp_path / "layout.svg")
    assert code == 0
    root = ET.parse(tmp_path / "layout.svg").getroot()
    parts = [e for e in root.iter() if e.get("class") == "part"]
    assert len(parts) == 5
    ezdxf = pytest.importorskip("ezdxf")
    code, _, _ = _run(capsys, "nest", inst, *FAST, "-o", tmp_path / "layout.dxf")
    assert code == 0
    msp = ezdxf.readfile(str(tmp_path / "layout.dxf")).modelspace()
    assert len(msp.query('LWPOLYLINE[layer=="PARTS"]')) == 5
    assert len(msp.query('LWPOLYLINE[layer=="SHEETS"]')) == 1
    # --format for standard output
    code, out, _ = _run(capsys, "nest", inst, *FAST, "--format", "geojson")
    assert code == 0 and json.loads(out)["type"] == "FeatureCollection"


def test_sheets(tmp_path, capsys):
    inst = _instance(tmp_path)
    code, out, err = _run(capsys, "nest", inst, "--sheet", "4x2:1", "--sheet", "3X3:3", *FAST)
    assert code == 0, err
    lay = mk.Layout.from_dict(json.loads(out))
    assert lay.strip_height is None and lay.verify()
    assert set(lay.kinds) <= {0, 1} and lay.kinds.count(0) <= 1
    assert f"{lay.n_sheets} sheet" in err and "used on the last" in err


def test_geojson_and_dxf_instances(tmp_path, capsys):
    fc = {
        "type": "FeatureCollection",
        "strip": {"height": 3},
        "features": [
            {
                "type": "Feature",
                "properties": {"id": "r", "quantity": 2},
                "geometry": {"type": "Polygon", "coordinates": [RECT + [RECT[0]]]},
            }
        ],
    }
    f = tmp_path / "parts.geojson"
    f.write_text(json.dumps(fc))
    code, out, _ = _run(capsys, "nest", f, *FAST)
    assert code == 0 and mk.Layout.from_dict(json.loads(out)).ids == ("r",)
    ezdxf = pytest.importorskip("ezdxf")
    doc = ezdxf.new()
    handles = [
        doc.modelspace().add_lwpolyline([(x + dx, y) for x, y in RECT], close=True).dxf.handle
        for dx in (0, 5)
    ]
    path = tmp_path / "parts.dxf"
    doc.saveas(path)
    code, out, err = _run(capsys, "nest", path, *FAST)  # no height: the drawing gives none
    assert code == 2 and "--height" in _one_error_line(err)
    code, out, _ = _run(capsys, "nest", path, "--height", "2.5", *FAST)
    assert code == 0
    lay = mk.Layout.from_dict(json.loads(out))
    assert len(lay.placements) == 2 and lay.name == "parts" and lay.verify()
    assert [lay.ids[p.part] for p in lay.placements] == [str(h) for h in handles]


@pytest.mark.parametrize(
    "extra, words",
    [
        (["--sheet", "4by2"], "--sheet"),
        (["--sheet", "4x2:many"], "--sheet"),
        (["--sheet", "0x2"], "sheet"),
        (["--rotations", "0,ninety"], "--rotations"),
        (["--rotations", "0,inf"], "--rotations"),
        (["--spacing", "-1"], "spacing"),
        (["--threads", "0"], "threads"),
        (["--height", "0.5"], "parts"),  # no part fits a strip 0.5 high
    ],
)
def test_bad_options_are_one_line(tmp_path, capsys, extra, words):
    inst = _instance(tmp_path)
    out = tmp_path / "layout.svg"
    code, _, err = _run(capsys, "nest", inst, *extra, *FAST, "-o", out)
    assert code == 2 and words in _one_error_line(err)
    assert not out.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["inst.json"]  # no partial file


def test_a_built_in_instance_by_name(tmp_path, capsys, monkeypatch):
    # no file of that name here: the packaged ESICUP instance of that name is read
    monkeypatch.chdir(tmp_path)
    code, out, err = _run(capsys, "nest", "shapes0", "--iterations", "2", "--threads", "1")
    assert code == 0
    lay = mk.Layout.from_dict(json.loads(out))
    assert lay.verify() and lay.name == "shapes0" and len(lay.placements) == 43
    assert err.startswith("minkowski2d: nest: 43 parts on a strip 40 high")
    code, out, _ = _run(capsys, "nfp", "shapes0")
    nfps = json.loads(out)
    assert code == 0 and nfps["instance"] == "shapes0" and len(nfps["nfps"]) == 16
    # a file of that name wins over the built-in instance
    (tmp_path / "shapes0").write_text("not json")
    code, _, err = _run(capsys, "nest", "shapes0", *FAST)
    assert code == 2 and "shapes0" in _one_error_line(err)
    # a name that is neither a file nor a built-in instance: the missing file
    code, _, err = _run(capsys, "nest", "albanoo", *FAST)
    assert code == 2 and "albanoo" in _one_error_line(err)


def test_bad_files_are_one_line(tmp_path, capsys):
    inst = _instance(tmp_path)
    before = inst.read_text()
    cases = [
        (["nest", tmp_path / "missing.json", "--height", "2"], "missing.json"),
        (["nest", inst, "-o", inst], "refusing to overwrite"),
        (["nest", inst, "-o", tmp_path / "layout.png"], "suffix"),
        (["nest", inst, "-o", tmp_path], "directory"),
    ]
    for argv, words in cases:
        code, out, err = _run(capsys, *argv, *FAST)
        assert code == 2 and words in _one_error_line(err), argv
        assert out == ""
    assert inst.read_text() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["inst.json"]
    bad = tmp_path / "bad.json"
    bad.write_text('{"pieces": [{"outer": "nope"}]}')
    code, _, err = _run(capsys, "nest", bad, "--height", "2", *FAST)
    assert code == 2 and "bad.json" in _one_error_line(err)
    no_height = _instance(tmp_path, height=None, name="noh.json")
    code, _, err = _run(capsys, "nest", no_height, *FAST)
    assert code == 2 and "--height H" in _one_error_line(err)


def test_height_and_sheet_together_is_a_usage_error(tmp_path, capsys):
    with pytest.raises(SystemExit) as e:
        main(["nest", str(_instance(tmp_path)), "--height", "2", "--sheet", "4x2"])
    assert e.value.code == 2
    assert "not allowed with" in capsys.readouterr().err
