"""Test configuration: under CI (CI=true) hypothesis runs derandomized, so a CI run draws
exactly the examples a local `CI=true python -m pytest` does (reproducible results);
locally it keeps exploring new examples on every run.

Tests of the CGAL corpus (``../shared/data``) skip when it is absent, and the terminal
summary says so in one line, so a run without the corpus cannot pass for a full one.
"""

from __future__ import annotations

import os

from hypothesis import settings

# mypy's samples (tests/test_typing.py runs mypy on them; sample_bad.py fails on purpose)
collect_ignore_glob = ["typing/*"]

settings.register_profile("ci", derandomize=True, print_blob=True)
if os.environ.get("CI", "").lower() in ("1", "true", "yes"):
    settings.load_profile("ci")

# words by which a skip reason says the corpus is missing (tests/corpus.py uses the
# first; older tests name the ../shared path)
_CORPUS_WORDS = ("CGAL corpus missing", "shared/data", "../shared")


def _skip_reason(report) -> str:
    longrepr = report.longrepr
    if isinstance(longrepr, tuple) and len(longrepr) == 3:
        return str(longrepr[2])
    return str(longrepr)


def pytest_terminal_summary(terminalreporter, exitstatus, config):
    skipped = terminalreporter.stats.get("skipped", [])
    n = sum(1 for r in skipped if any(w in _skip_reason(r) for w in _CORPUS_WORDS))
    if n:
        from tests.corpus import CORPUS

        terminalreporter.write_sep("=", "CGAL corpus", yellow=True, bold=True)
        terminalreporter.write_line(
            f"{n} corpus test(s) SKIPPED for lack of ../shared/data: {CORPUS} does not "
            "exist. This run did not check the CGAL corpus.",
            yellow=True,
            bold=True,
        )
