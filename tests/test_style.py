"""The house rule "ruff-clean", enforced in CI (ruff is in the test extras)."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def test_ruff_clean():
    ruff = shutil.which("ruff")
    cmd = [ruff] if ruff else [sys.executable, "-m", "ruff"]
    try:
        p = subprocess.run(
            [*cmd, "check", "src", "tests", "benchmarks"],
            cwd=ROOT,
            capture_output=True,
            text=True,
            timeout=120,
        )
    except FileNotFoundError:
        pytest.skip("ruff is not installed (pip install -e '.[test]')")
    assert p.returncode == 0, p.stdout + p.stderr
