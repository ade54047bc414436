"""The suite sees what a new machine sees: the CI entry point, the README's test
command, and the loud skip of the CGAL corpus tests."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
TESTS = ROOT / "tests"


def readme_test_command() -> str:
    """The README's test command, extracted exactly as .ci/run extracts it."""
    script = (ROOT / ".ci" / "run").read_text()
    awk = script.split("cmd=$(awk '", 1)[1].split("' README.md)", 1)[0]
    out = subprocess.run(
        ["awk", awk, "README.md"], cwd=ROOT, capture_output=True, text=True, check=True
    )
    return out.stdout.strip()


class TestSuiteSeesANewMachine:
    def test_ci_run_builds_a_fresh_venv_and_fails_loudly(self):
        script = (ROOT / ".ci" / "run").read_text()
        subprocess.run(["bash", "-n", str(ROOT / ".ci" / "run")], check=True)
        assert os.access(ROOT / ".ci" / "run", os.X_OK)
        fresh = script.index("rm -rf .ci-venv")
        assert (
            fresh
            < script.index("python3 -m venv .ci-venv")
            < script.index(". .ci-venv/bin/activate")
            < script.index('bash -c "$cmd"')
        )
        assert '"$rc" -eq 5' in script and 'passed\' "$log"' in script
        assert "set -euo pipefail" in script
        assert ".ci-venv/" in (ROOT / ".gitignore").read_text().splitlines()

    def test_readme_commands(self):
        cmd = readme_test_command()
        assert cmd.endswith("python -m pytest -q")
        # on a fresh Debian (root, PEP 668, no venv module) it installs what it needs and
        # works in a virtual environment, an active one (.ci/run's) or its own .venv
        for part in (
            "apt-get install -y -qq chromium",
            "python3-venv",
            "python3 -m venv .venv",
            'pip install -q -e ".[test]"',
        ):
            assert part in cmd, part
        subprocess.run(["bash", "-n", "-c", cmd], check=True)
        top = (ROOT / "README.md").read_text().split("---", 1)[0]
        assert "pip install -e . && minkowski2d demo" in top

    def test_ci_run_fails_on_exit_5_and_on_silence(self, tmp_path):
        """Run .ci/run for real on a copy whose README test command is replaced: pytest's
        exit 5 and a silent success both fail. (python3 -m venv without pip: quick.)"""
        if shutil.which("awk") is None:
            pytest.skip("needs awk")
        repo = tmp_path / "repo"
        (repo / ".ci").mkdir(parents=True)
        script = (ROOT / ".ci" / "run").read_text()
        # the real script, with a venv made without pip (fast, offline)
        script = script.replace(
            "python3 -m venv .ci-venv", "python3 -m venv --without-pip .ci-venv"
        )
        (repo / ".ci" / "run").write_text(script)
        os.chmod(repo / ".ci" / "run", 0o755)
        (repo / "tests").mkdir()
        (repo / "tests" / "test_nothing.py").write_text("X = 1\n")

        def run_with(cmd: str) -> subprocess.CompletedProcess:
            (repo / "README.md").write_text(f"# x\n\n<!-- test-command -->\n```\n{cmd}\n```\n")
            return subprocess.run(
                ["bash", str(repo / ".ci" / "run")], capture_output=True, text=True, timeout=120
            )

        py = sys.executable
        r = run_with(f"{py} -m pytest -q -p no:cacheprovider tests")
        assert r.returncode == 1 and "collected no tests (exit status 5)" in r.stderr, r
        r = run_with("true")
        assert r.returncode == 1 and "no 'N passed' summary" in r.stderr, r
        (repo / "tests" / "test_one.py").write_text("def test_one():\n    pass\n")
        r = run_with(f"{py} -m pytest -q -p no:cacheprovider tests")
        assert r.returncode == 0 and ".ci/run: OK (1 passed" in r.stdout, r
        assert (repo / ".ci-venv" / "bin" / "python").exists()

    def test_missing_corpus_is_a_loud_skip(self, tmp_path):
        """A checkout without ../shared: the corpus tests skip with a reason naming the
        path, and the terminal summary counts them."""
        repo = tmp_path / "repo"
        (repo / "tests").mkdir(parents=True)
        for f in ("__init__.py", "conftest.py", "corpus.py"):
            shutil.copy(TESTS / f, repo / "tests" / f)
        (repo / "tests" / "test_c.py").write_text(
            "from .corpus import requires_corpus\n\n"
            "@requires_corpus\ndef test_a():\n    pass\n\n"
            "@requires_corpus\ndef test_b():\n    pass\n\n"
            "def test_c():\n    pass\n"
        )
        r = subprocess.run(
            [sys.executable, "-m", "pytest", "-rs", "-p", "no:cacheprovider", "tests"],
            cwd=repo,
            capture_output=True,
            text=True,
            timeout=120,
        )
        assert r.returncode == 0, r.stdout + r.stderr
        assert "2 corpus test(s) SKIPPED for lack of ../shared/data" in r.stdout
        assert "CGAL corpus missing" in r.stdout and str(tmp_path / "shared") in r.stdout
        assert "1 passed, 2 skipped" in r.stdout
