"""Packaging: what ``import minkowski2d`` loads, the version written once, the
SPDX license and the extras in the installed metadata."""

from __future__ import annotations

import json
import re
import subprocess
import sys
from importlib import metadata
from pathlib import Path

import minkowski2d as mk

ROOT = Path(__file__).resolve().parents[1]

#: nothing of these may load with ``import minkowski2d`` (page template, server, plotting,
#: the optional extras)
HEAVY = (
    "matplotlib",
    "minkowski2d.plot",
    "minkowski2d._svg",
    "minkowski2d.animation",
    "minkowski2d.animation.page",
    "minkowski2d.animation.server",
    "minkowski2d.cli",
    "http.server",
    "geopandas",
    "pandas",
    "dask",
    "tqdm",
    "ezdxf",
    "shtab",
    "pyarrow",
)


def _modules_after(code: str) -> set:
    out = subprocess.run(
        [sys.executable, "-c", f"{code}\nimport sys, json; print(json.dumps(list(sys.modules)))"],
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    ).stdout
    return set(json.loads(out.splitlines()[-1]))


def test_import_loads_no_template_server_or_plotting():
    mods = _modules_after("import minkowski2d")
    assert not mods & set(HEAVY), sorted(mods & set(HEAVY))
    # mk.plot is the module, matplotlib still waits for the first drawing
    mods = _modules_after("import minkowski2d as mk; mk.plot")
    assert "minkowski2d.plot" in mods and "matplotlib" not in mods


def test_importtime_reports_no_heavy_module():
    p = subprocess.run(
        [sys.executable, "-X", "importtime", "-c", "import minkowski2d"],
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    names = {line.rsplit("|", 1)[-1].strip() for line in p.stderr.splitlines() if "|" in line}
    assert not names & set(HEAVY)


def test_version_is_written_once():
    assert mk.__version__ == metadata.version("minkowski2d")
    text = (ROOT / "pyproject.toml").read_text()
    assert 'dynamic = ["version"]' in text and not re.search(r"^version\s*=", text, re.M)
    assert "scikit_build_core.metadata.regex" in text
    src = (ROOT / "src" / "minkowski2d" / "_version.py").read_text()
    assert re.search(r'^__version__ = "[^"]+"$', src, re.M)


def test_license_and_extras_in_metadata():
    md = metadata.metadata("minkowski2d")
    assert md["License-Expression"] == "MIT"
    extras = set(md.get_all("Provides-Extra"))
    assert {"geo", "dask", "plot", "dxf", "test"} <= extras
    reqs = metadata.requires("minkowski2d") or []
    test_reqs = {re.split(r"[\[<>=; ]", r)[0] for r in reqs if 'extra == "test"' in r}
    for name in ("geopandas", "matplotlib", "dask", "dask-geopandas", "tqdm", "ezdxf"):
        assert name in test_reqs, name  # CI (pip install -e ".[test]") runs their tests
    for name in ("shtab", "mypy", "pyarrow"):
        assert name in test_reqs, name
