"""Test configuration: under CI (CI=true) hypothesis runs derandomized, so a CI run draws
exactly the examples a local `CI=true python -m pytest` does (reproducible results);
locally it keeps exploring new examples on every run."""

from __future__ import annotations

import os

from hypothesis import settings

settings.register_profile("ci", derandomize=True, print_blob=True)
if os.environ.get("CI", "").lower() in ("1", "true", "yes"):
    settings.load_profile("ci")
