"""Root conftest: loaded for every collected item (README.md, docstrings in src/, tests/)."""

from __future__ import annotations

# Doctests (README.md, docstrings) that use an optional extra skip, with the reason, when
# it is absent; `pip install -e ".[test]"` installs every extra, so CI runs them for real.
_DOCTEST_EXTRAS = {"geopandas": "geo", "matplotlib": "plot"}


def pytest_collection_modifyitems(config, items):
    import importlib.util

    import pytest

    missing = {m: x for m, x in _DOCTEST_EXTRAS.items() if importlib.util.find_spec(m) is None}
    if not missing:
        return
    for item in items:
        dtest = getattr(item, "dtest", None)
        if dtest is None:
            continue
        source = "".join(ex.source for ex in dtest.examples)
        for mod, extra in missing.items():
            if f"import {mod}" in source:
                item.add_marker(
                    pytest.mark.skip(reason=f"{mod} is not installed (extra '{extra}')")
                )
                break
