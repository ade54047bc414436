"""CLI plugin: union, intersection, difference, xor (minkowski2d.cli.boolean)."""

from __future__ import annotations

import json

import pytest
import shapely

from minkowski2d.cli import main

A = [[0, 0], [4, 0], [4, 4], [0, 4]]
B_WKT = "POLYGON ((2 2, 6 2, 6 6, 2 6, 2 2))"
BOW = [[0, 0], [2, 2], [2, 0], [0, 2]]


@pytest.fixture
def files(tmp_path):
    a = tmp_path / "a.json"
    a.write_text(json.dumps(A))
    b = tmp_path / "b.wkt"
    b.write_text(B_WKT)
    bow = tmp_path / "bow.json"
    bow.write_text(json.dumps(BOW))
    fc = tmp_path / "parts.geojson"
    fc.write_text(json.dumps({"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"name": "p"},
         "geometry": {"type": "Polygon", "coordinates": [[[1, 1], [3, 1], [3, 3], [1, 3]]]}},
        {"type": "Feature", "properties": {"name": "none"}, "geometry": None},
    ]}))  # fmt: skip
    return {"a": str(a), "b": str(b), "bow": str(bow), "fc": str(fc)}


@pytest.mark.parametrize(
    ("command", "op"),
    [
        ("union", shapely.union),
        ("intersection", shapely.intersection),
        ("difference", shapely.difference),
        ("xor", shapely.symmetric_difference),
    ],
)
def test_each_command_matches_the_exact_result(files, capsys, command, op):
    assert main([command, files["a"], files["b"], "--format", "wkt"]) == 0
    got = shapely.from_wkt(capsys.readouterr().out)
    want = op(shapely.Polygon(A), shapely.from_wkt(B_WKT))
    # integer grid input: every vertex is exact, so the results are equal as point sets
    assert got.is_valid and got.normalize().equals_exact(want.normalize(), 0)


def test_output_file_and_refusal(files, tmp_path, capsys):
    out = tmp_path / "u.geojson"
    assert main(["union", files["a"], files["b"], "-o", str(out)]) == 0
    assert shapely.from_geojson(out.read_text()).area == 28
    assert main(["union", files["a"], files["b"], "-o", files["a"]]) == 2
    assert "refusing to overwrite" in capsys.readouterr().err
    assert json.loads(open(files["a"]).read()) == A


def test_invalid_input_is_one_line_naming_the_file_and_the_option(files, capsys, tmp_path):
    out = tmp_path / "never.json"
    assert main(["union", files["bow"], files["a"], "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"minkowski2d: error: {files['bow']}: not a valid polygon")
    assert "vertex 2" in err and "--fill-rule" in err and err.count("\n") == 1
    assert not out.exists()


@pytest.mark.parametrize(("rule", "area"), [("nonzero", 14), ("evenodd", 14), ("positive", 15)])
def test_fill_rule_resolves_a_bowtie(files, capsys, rule, area):
    # the bowtie's lobes (area 1 each, winding +1 on the left, -1 on the right) lie inside
    # A: the union is A; the xor with A removes the lobes the rule fills
    assert main(["union", files["bow"], files["a"], "--fill-rule", rule, "--format", "wkt"]) == 0
    assert shapely.from_wkt(capsys.readouterr().out).area == 16
    assert main(["xor", files["a"], files["bow"], "--fill-rule", rule, "--format", "wkt"]) == 0
    assert shapely.from_wkt(capsys.readouterr().out).area == area


def test_feature_collection_one_result_per_feature(files, capsys):
    assert main(["difference", files["fc"], files["b"]]) == 0
    fc = json.loads(capsys.readouterr().out)
    first, second = fc["features"]
    assert first["properties"] == {"name": "p"} and second["geometry"] is None
    assert shapely.geometry.shape(first["geometry"]).area == 3
