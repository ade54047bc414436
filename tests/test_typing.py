"""mypy --strict on user code: the public API is typed (no ``Any`` for
polygons), so ``minkowski_sum(1, 2)`` and ``hull="yes"`` are flagged and ordinary calls
pass. The samples are in tests/typing/; lines that must fail carry ``# E:``."""

from __future__ import annotations

import importlib.metadata
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

import minkowski2d

HERE = Path(__file__).resolve().parent / "typing"


def _mypy(tmp_path, *files):
    pytest.importorskip("mypy", reason="mypy is not installed (pip install -e '.[test]')")
    env = dict(os.environ)
    src = Path(minkowski2d.__file__).resolve().parents[1]
    if src.name not in ("site-packages", "dist-packages"):  # an editable install's src/
        env["MYPYPATH"] = str(src)
    cmd = [sys.executable, "-m", "mypy", "--strict", "--follow-imports=silent"]
    cmd += ["--cache-dir", str(tmp_path / "cache"), "--no-color-output", "--no-error-summary"]
    p = subprocess.run(
        [*cmd, *map(str, files)], capture_output=True, text=True, env=env, timeout=300
    )
    return p.returncode, p.stdout + p.stderr


def test_public_api_type_checks(tmp_path):
    rc, out = _mypy(tmp_path, HERE / "sample_ok.py", HERE / "sample_bad.py")
    errors = {}
    for line in out.splitlines():
        m = re.match(r".*?(sample_\w+)\.py:(\d+): error: (.*)", line)
        if m:
            errors.setdefault((m.group(1), int(m.group(2))), []).append(m.group(3))
    assert not [k for k in errors if k[0] == "sample_ok"], out
    marked = {
        ("sample_bad", k)
        for k, line in enumerate((HERE / "sample_bad.py").read_text().splitlines(), 1)
        if "# E:" in line
    }
    assert set(errors) == marked, out
    assert any("hull" in e and '"bool"' in e for e in errors[("sample_bad", 8)])
    assert rc == 1


def test_the_package_passes_mypy(tmp_path):
    """The package itself type-checks with the project's configuration ([tool.mypy] in
    pyproject.toml: the untyped modules it names, the stubs of the test extra)."""
    pytest.importorskip("mypy", reason="mypy is not installed (pip install -e '.[test]')")
    root = HERE.parents[1]
    if not (root / "pyproject.toml").is_file() or not (root / "src" / "minkowski2d").is_dir():
        pytest.skip("needs the repository (pyproject.toml and src/minkowski2d)")
    for stubs in ("types-shapely", "types-tqdm"):
        try:
            importlib.metadata.version(stubs)
        except importlib.metadata.PackageNotFoundError:
            pytest.skip(f"{stubs} is not installed (pip install -e '.[test]')")
    cmd = [sys.executable, "-m", "mypy", "--config-file", "pyproject.toml"]
    cmd += ["--cache-dir", str(tmp_path / "cache"), "--no-color-output", "src/minkowski2d"]
    p = subprocess.run(cmd, capture_output=True, text=True, cwd=root, timeout=600)
    assert p.returncode == 0, p.stdout + p.stderr
