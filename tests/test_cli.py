"""minkowski2d.cli: the demo, sum/inflate/hull, formats, stdin, and error handling."""

from __future__ import annotations

import io
import json
import subprocess
import sys

import pytest

from minkowski2d.cli import main


def run(args, capsys, stdin=None, monkeypatch=None):
    if stdin is not None:
        monkeypatch.setattr(sys, "stdin", io.StringIO(stdin))
    rc = main(args)
    out, err = capsys.readouterr()
    return rc, out, err


@pytest.fixture
def files(tmp_path):
    a = tmp_path / "a.json"
    b = tmp_path / "b.json"
    a.write_text("[[0, 0], [2, 0], [0, 2]]")
    b.write_text("[[0, 0], [1, 0], [1, 1], [0, 1]]")
    return a, b


def test_demo(capsys, tmp_path):
    rc, out, err = run(["demo", "-o", str(tmp_path / "anim.html")], capsys)
    assert rc == 0
    assert "A ⊕ B:        [[0, 0], [3, 0], [3, 1], [1, 3], [0, 3]]" in out


def test_sum_formats(capsys, files, tmp_path):
    a, b = files
    rc, out, _ = run(["sum", str(a), str(b)], capsys)
    assert rc == 0 and json.loads(out) == [[0, 0], [3, 0], [3, 1], [1, 3], [0, 3]]
    rc, out, _ = run(["sum", str(a), str(b), "--format", "wkt"], capsys)
    assert out.strip() == "POLYGON ((0 0, 3 0, 3 1, 1 3, 0 3, 0 0))"
    o = tmp_path / "out.geojson"
    rc, out, _ = run(["sum", str(a), str(b), "-o", str(o)], capsys)
    assert rc == 0 and out == "" and json.loads(o.read_text())["type"] == "Polygon"
    rc, out, _ = run(["inflate", str(a), str(b)], capsys)
    assert json.loads(out) == [[-1, -1], [2, -1], [2, 0], [0, 2], [-1, 2]]
    rc, out, _ = run(["hull", str(b)], capsys)
    assert json.loads(out) == [[0, 0], [1, 0], [1, 1], [0, 1]]


def test_stdin(capsys, files, monkeypatch):
    _, b = files
    rc, out, _ = run(["sum", "-", str(b)], capsys, stdin="POINT (5 5)", monkeypatch=monkeypatch)
    assert rc == 0 and json.loads(out) == [[5, 5], [6, 5], [6, 6], [5, 6]]


@pytest.mark.parametrize(
    "text, msg",
    [
        ("[[0, 0], [NaN, 1]]", "vertex 1 has a non-finite coordinate"),
        ("[]", "empty point list"),
        ("[[0, 0], [1, 2, 3]]", "not an [x, y] pair"),
        ("not a polygon", "not a JSON point list, GeoJSON or WKT"),
    ],
)
def test_bad_input_one_line_exit_2(capsys, files, tmp_path, text, msg):
    _, b = files
    bad = tmp_path / "bad.json"
    bad.write_text(text)
    out_file = tmp_path / "never.json"
    rc, out, err = run(["sum", str(bad), str(b), "-o", str(out_file)], capsys)
    assert rc == 2
    assert err.count("\n") == 1 and err.startswith("minkowski2d: error: ") and msg in err
    assert str(bad) in err or msg in ("empty point list",) or "not a JSON" in msg
    assert not out_file.exists()


def test_never_overwrites_an_input(capsys, files):
    a, b = files
    before = a.read_text()
    rc, _, err = run(["sum", str(a), str(b), "-o", str(a)], capsys)
    assert rc == 2 and "refusing to overwrite the input file" in err
    assert a.read_text() == before


def test_missing_file(capsys, files):
    _, b = files
    rc, _, err = run(["sum", "/nonexistent/x.json", str(b)], capsys)
    assert rc == 2 and "no such file" in err


def test_python_dash_m_entry_point(files):
    a, b = files
    p = subprocess.run(
        [sys.executable, "-m", "minkowski2d", "sum", str(a), str(b), "--format", "wkt"],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert p.returncode == 0, p.stderr
    assert p.stdout.strip() == "POLYGON ((0 0, 3 0, 3 1, 1 3, 0 3, 0 0))"


def test_unwritable_output_is_one_line(capsys, files, tmp_path):
    a, b = files
    rc, _, err = run(["sum", str(a), str(b), "-o", str(tmp_path / "no" / "dir" / "x.json")], capsys)
    assert rc == 2 and err.count("\n") == 1 and "No such file or directory" in err
    rc, _, err = run(["demo", "-o", str(tmp_path / "no" / "dir" / "a.html")], capsys)
    assert rc == 2 and err.startswith("minkowski2d: error: ")
