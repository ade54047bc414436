"""CLI plugin: sum-general, erode, decompose."""

from __future__ import annotations

import json

import pytest
import shapely

from minkowski2d.cli import main

SQ = [[0, 0], [4, 0], [4, 4], [0, 4]]
UNIT = [[0, 0], [1, 0], [1, 1], [0, 1]]
L = [[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]]


@pytest.fixture
def files(tmp_path):
    out = {}
    for name, pts in (("sq", SQ), ("unit", UNIT), ("L", L), ("big", [[0, 0], [5, 0], [0, 5]])):
        f = tmp_path / f"{name}.json"
        f.write_text(json.dumps(pts))
        out[name] = str(f)
    frame = tmp_path / "frame.wkt"
    frame.write_text("POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (3 3, 3 7, 7 7, 7 3, 3 3))")
    out["frame"] = str(frame)
    return out


def test_sum_general_keeps_holes(files, capsys):
    assert main(["sum-general", files["frame"], files["unit"], "--format", "wkt"]) == 0
    g = shapely.from_wkt(capsys.readouterr().out)
    assert g.area == 11 * 11 - 3 * 3 and len(g.interiors) == 1


@pytest.mark.parametrize("method", ["decomposition", "convolution"])
def test_sum_general_methods(files, capsys, method):
    assert main(["sum-general", files["L"], files["L"], "--method", method]) == 0
    g = shapely.geometry.shape(json.loads(capsys.readouterr().out))
    assert g.area == 13


def test_erode_and_empty(files, capsys, tmp_path):
    out = tmp_path / "e.wkt"
    assert main(["erode", files["sq"], files["unit"], "-o", str(out)]) == 0
    assert shapely.from_wkt(out.read_text()).equals(shapely.box(0, 0, 3, 3))
    assert main(["erode", files["sq"], files["big"], "--format", "wkt"]) == 0
    cap = capsys.readouterr()
    assert cap.out.strip() == "POLYGON EMPTY" and "erosion is empty" in cap.err


def test_decompose(files, capsys):
    assert main(["decompose", files["frame"], "--format", "wkt"]) == 0
    g = shapely.from_wkt(capsys.readouterr().out)
    assert g.geom_type == "MultiPolygon" and g.area == 100 - 16


def test_errors_are_one_line(files, capsys, tmp_path):
    bow = tmp_path / "bow.json"
    bow.write_text("[[0,0],[2,2],[2,0],[0,2]]")
    assert main(["erode", str(bow), files["unit"]]) == 2
    err = capsys.readouterr().err
    # the message names the file (the CLI names files, not Python arguments)
    assert err.startswith(f"minkowski2d: error: {bow}: not a valid polygon")
    assert err.count("\n") == 1


def test_refuses_to_overwrite_input(files, capsys):
    assert main(["sum-general", files["L"], files["unit"], "-o", files["L"]]) == 2
    assert "refusing to overwrite" in capsys.readouterr().err
