"""Tests for the ``minkowski2d collide`` subcommand (the _cli_collision plugin)."""

from __future__ import annotations

import io
import json
import subprocess
import sys

import pytest

import minkowski2d as mk
from minkowski2d.cli import main


@pytest.fixture()
def files(tmp_path):
    a = tmp_path / "a.json"
    a.write_text("[[0, 0], [4, 0], [4, 4], [0, 4]]")
    b = tmp_path / "b.wkt"
    b.write_text("POLYGON ((3 1, 6 1, 6 3, 3 3, 3 1))")
    far = tmp_path / "far.json"
    far.write_text("[[7, 0], [9, 0], [7, 4]]")
    star = tmp_path / "star.json"
    star.write_text("[[0, 0], [2, 6], [4, 0], [-1, 4], [5, 4]]")
    return tmp_path, a, b, far, star


def run(argv, capsys):
    rc = main(argv)
    cap = capsys.readouterr()
    return rc, cap.out, cap.err


def test_overlapping(files, capsys):
    _, a, b, _, _ = files
    rc, out, err = run(["collide", str(a), str(b)], capsys)
    assert rc == 0 and err == ""
    r = json.loads(out)
    assert r["intersects"] is True
    assert r["distance"]["distance"] == 0.0
    pen = r["penetration"]
    assert pen["depth"] == 1.0 and pen["normal"] == [1.0, 0.0]
    assert pen["point_a"] == [4.0, 3.0] and pen["point_b"] == [3.0, 3.0]


def test_apart_matches_library(files, capsys):
    _, a, _, far, _ = files
    for method in ("auto", "sum", "gjk"):
        rc, out, _ = run(["collide", str(a), str(far), "--method", method], capsys)
        assert rc == 0
        r = json.loads(out)
        assert r["intersects"] is False
        d = mk.distance([(0, 0), (4, 0), (4, 4), (0, 4)], [(7, 0), (9, 0), (7, 4)])
        assert r["distance"] == {
            "distance": d.distance,
            "point_a": d.point_a.tolist(),
            "point_b": d.point_b.tolist(),
        }
        assert r["distance"]["distance"] == 3.0
        assert r["penetration"]["depth"] == -3.0


def test_output_file_and_stdin(files, capsys, monkeypatch):
    tmp, a, b, _, _ = files
    monkeypatch.setattr(sys, "stdin", io.StringIO("[[3, 1], [6, 1], [6, 3], [3, 3]]"))
    out = tmp / "r.json"
    rc, stdout, _ = run(["collide", str(a), "-", "-o", str(out)], capsys)
    assert rc == 0 and stdout == ""
    assert json.loads(out.read_text())["penetration"]["depth"] == 1.0
    rc, _, err = run(["collide", str(a), str(b), "-o", str(a)], capsys)
    assert rc == 2 and "refusing to overwrite" in err


def test_errors_one_line(files, capsys):
    _, a, _, _, star = files
    rc, out, err = run(["collide", str(a), str(star)], capsys)
    assert rc == 2 and out == ""
    assert err.count("\n") == 1
    assert err.startswith(f"minkowski2d: error: {star}: not convex") and "--hull" in err
    rc, out, _ = run(["collide", str(a), str(star), "--hull"], capsys)
    assert rc == 0 and json.loads(out)["intersects"] is True
    rc, _, err = run(["collide", str(a), str(a.parent / "missing.json")], capsys)
    assert rc == 2 and "no such file" in err


def test_holes_rejected(files, capsys):
    tmp, a, _, _, _ = files
    h = tmp / "holes.wkt"
    h.write_text("POLYGON ((0 0, 9 0, 9 9, 0 9, 0 0), (3 3, 6 3, 6 6, 3 6, 3 3))")
    rc, _, err = run(["collide", str(a), str(h)], capsys)
    assert rc == 2 and "not a single convex polygon" in err


def test_entry_point_subprocess(files):
    _, a, b, _, _ = files
    r = subprocess.run(
        [sys.executable, "-m", "minkowski2d", "collide", str(a), str(b)],
        capture_output=True,
        text=True,
        check=True,
    )
    assert json.loads(r.stdout)["intersects"] is True
