"""minkowski2d.cli: the demo, sum/inflate/hull, formats, stdin, and error handling."""

from __future__ import annotations

import io
import json
import os
import stat
import subprocess
import sys
from pathlib import Path

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


# --------------------------------------------------------------------------------------
# "Files a user can lose"

SQUARE = "[[0, 0], [4, 0], [4, 4], [0, 4]]"
UNIT = "[[0, 0], [1, 0], [1, 1], [0, 1]]"


def _commands(a, b):
    """Every command that writes a file, with its inputs (the output is added after)."""
    return [
        ["sum", a, b],
        ["inflate", a, b],
        ["hull", a],
        ["collide", a, b],
        ["sum-general", a, b],
        ["erode", a, b],
        ["decompose", a],
        ["animate", a, b],
    ]


def _listing(d):
    return sorted(p.name for p in d.iterdir())


class TestFilesAUserCanLose:
    """Outputs go through one O_EXCL temporary file renamed into place; inputs are
    compared with the output by device and inode, selectors stripped."""

    def test_dat_selector_output_guard(self, capsys, tmp_path):
        two = tmp_path / "two.dat"
        text = "4 0 0 2 0 2 2 0 2\n3 0 0 1 0 0 1\n"
        two.write_text(text)
        rc, _, err = run(["sum", f"{two}#1", f"{two}#2", "-o", str(two)], capsys)
        assert rc == 2 and "refusing to overwrite the input file" in err
        assert two.read_text() == text and _listing(tmp_path) == ["two.dat"]
        # the same file named another way: ./, a symlink, a hard link
        (tmp_path / "link.dat").symlink_to(two)
        os.link(two, tmp_path / "hard.dat")
        for out in (tmp_path / "." / "two.dat", tmp_path / "link.dat", tmp_path / "hard.dat"):
            rc, _, err = run(["sum", f"{two}#1", f"{two}#2", "-o", str(out)], capsys)
            assert rc == 2 and "refusing" in err, out
        assert two.read_text() == text
        rc, out, _ = run(["sum", f"{two}#1", f"{two}#2"], capsys)
        assert rc == 0 and json.loads(out)

    @pytest.mark.parametrize("cmd", range(8))
    def test_every_command_refuses_to_overwrite_an_input(self, capsys, tmp_path, cmd):
        a, b = tmp_path / "a.json", tmp_path / "b.json"
        a.write_text(SQUARE)
        b.write_text(UNIT)
        argv = _commands(str(a), str(b))[cmd]
        rc, _, err = run([*argv, "-o", str(argv[-1])], capsys)
        assert rc == 2 and "refusing to overwrite the input file" in err, argv
        assert a.read_text() == SQUARE and b.read_text() == UNIT
        assert _listing(tmp_path) == ["a.json", "b.json"]

    @pytest.mark.parametrize("cmd", range(8))
    def test_an_existing_tmp_name_is_never_opened(self, capsys, tmp_path, cmd):
        a, b = tmp_path / "a.json", tmp_path / "b.json"
        a.write_text(SQUARE)
        b.write_text(UNIT)
        # an input named like the old fixed temporary file, and a planted symlink
        (tmp_path / "res.json.tmp").write_text("precious")
        victim = tmp_path / "victim.json"
        victim.write_text("victim")
        (tmp_path / "out.json.tmp").symlink_to(victim)
        argv = _commands(str(a), str(b))[cmd]
        for out in ("res.json", "out.json"):
            rc, _, err = run([*argv, "-o", str(tmp_path / out)], capsys)
            assert rc == 0, err
            assert (tmp_path / out).stat().st_size > 0
        assert (tmp_path / "res.json.tmp").read_text() == "precious"
        assert victim.read_text() == "victim"
        assert _listing(tmp_path) == sorted(
            [
                "a.json",
                "b.json",
                "res.json",
                "res.json.tmp",
                "out.json",
                "out.json.tmp",
                "victim.json",
            ]
        )

    @pytest.mark.parametrize("cmd", [*range(8), "demo"])
    def test_a_directory_output_leaves_nothing_behind(self, capsys, tmp_path, cmd):
        a, b = tmp_path / "a.json", tmp_path / "b.json"
        a.write_text(SQUARE)
        b.write_text(UNIT)
        adir = tmp_path / "adir"
        adir.mkdir()
        argv = ["demo"] if cmd == "demo" else _commands(str(a), str(b))[cmd]
        rc, _, err = run([*argv, "-o", str(adir)], capsys)
        assert rc == 2 and err.count("\n") == 1
        assert "it is a directory" in err
        assert _listing(tmp_path) == ["a.json", "adir", "b.json"] and _listing(adir) == []

    def test_failures_while_writing_remove_the_temporary_file(
        self, capsys, files, tmp_path, monkeypatch
    ):
        a, b = files
        out = tmp_path / "out.json"
        out.write_text("old")
        before = _listing(tmp_path)

        def boom(*_args, **_kw):
            raise OSError(28, "No space left on device")

        monkeypatch.setattr(os, "replace", boom)
        rc, _, err = run(["sum", str(a), str(b), "-o", str(out)], capsys)
        assert rc == 2 and "cannot write" in err and "No space left" in err
        assert out.read_text() == "old" and _listing(tmp_path) == before

        def interrupt(*_args, **_kw):
            raise KeyboardInterrupt

        monkeypatch.setattr(os, "replace", interrupt)
        rc, _, _ = run(["sum", str(a), str(b), "-o", str(out)], capsys)
        assert rc == 130 and out.read_text() == "old" and _listing(tmp_path) == before

    def test_output_file_mode_and_content(self, capsys, files, tmp_path):
        a, b = files
        out = tmp_path / "out.wkt"
        old = os.umask(0o022)
        try:
            rc, _, _ = run(["sum", str(a), str(b), "-o", str(out)], capsys)
        finally:
            os.umask(old)
        assert rc == 0 and out.read_text() == "POLYGON ((0 0, 3 0, 3 1, 1 3, 0 3, 0 0))\n"
        assert stat.S_IMODE(out.stat().st_mode) == 0o644
        out.chmod(0o600)  # an existing output keeps its mode
        rc, _, _ = run(["sum", str(a), str(b), "-o", str(out)], capsys)
        assert rc == 0 and stat.S_IMODE(out.stat().st_mode) == 0o600

    def test_a_device_is_refused(self, capsys, files):
        a, b = files
        rc, _, err = run(["sum", str(a), str(b), "-o", os.devnull], capsys)
        assert rc == 2 and "not a regular file" in err and "-o -" in err

    def test_plugins_do_not_import_cli(self):
        root = Path(__file__).resolve().parents[1] / "src" / "minkowski2d"
        for f in ("collision", "general", "animation", "features", "offset", "nesting", "planning"):
            text = (root / "cli" / f"{f}.py").read_text()
            assert "from . import" not in text and "from ..cli import" not in text, f
