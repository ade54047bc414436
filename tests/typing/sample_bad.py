"""Calls that must be type errors under `mypy --strict` (tests/test_typing.py)."""

from __future__ import annotations

import minkowski2d as mk

mk.minkowski_sum(1, 2)  # E: numbers are not polygons
mk.minkowski_sum([(0, 0)], [(1, 1)], hull="yes")  # E: hull is a bool
mk.intersects("abc", [(0, 0)])  # E: a string is not a polygon
mk.minkowski_sum_many([[(0, 0)]], [(1, 1)], threads="2")  # E: threads is an int
wrong: int = mk.minkowski_sum_many([[(0, 0)]], [(1, 1)])  # E: lists in give a Ragged
