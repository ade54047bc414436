"""Where the CGAL test polygons live (``../shared/data/cgal-minkowski`` beside the
repository), and the one skip every corpus test uses when they are absent.

The skip is loud: its reason says where the files were looked for, and
``tests/conftest.py`` adds a line to the terminal summary counting these skips.
"""

from __future__ import annotations

from pathlib import Path

import pytest

CORPUS = Path(__file__).resolve().parents[2] / "shared" / "data" / "cgal-minkowski"

#: every corpus skip's reason starts with this (the summary counts them by it)
SKIP_PREFIX = "CGAL corpus missing"
SKIP_REASON = (
    f"{SKIP_PREFIX}: {CORPUS} does not exist (put ../shared/data beside the repository "
    "to run the corpus tests)"
)

requires_corpus = pytest.mark.skipif(not CORPUS.is_dir(), reason=SKIP_REASON)

#: the ESICUP nesting instances, shipped with the package (minkowski2d.datasets)
ESICUP = Path(__file__).resolve().parents[1] / "src" / "minkowski2d" / "datasets" / "esicup"


def corpus_files(pattern: str = "*.dat") -> list[Path]:
    """The corpus files matching ``pattern`` (empty when the corpus is missing)."""
    return sorted(CORPUS.glob(pattern)) if CORPUS.is_dir() else []
