"""Reproducers that the exact overlay in the core fixes: class 3 (GEOS
``simplify`` never returns on 5e-324 coordinates) and the class-8 "valid 3e-200 triangle
called self-intersecting by general sums".

The hang runs in a child process under a CPU-time limit (RLIMIT_CPU): the limit counts the
child's own work, not the wall clock, so a busy machine neither fails a fixed sum nor
passes a hung one, and the suite cannot hang; the test waits for the child to exit."""

from __future__ import annotations

import subprocess
import sys

import pytest

import minkowski2d as mk

L = [(0, 0), (3, 0), (3, 1), (1, 1), (1, 3), (0, 3)]
T200 = [(0.0, 0.0), (3e-200, 0.0), (0.0, 3e-200)]
#: CPU seconds the child may spend on one 6-vertex sum (the fixed code needs
#: milliseconds; importing the package is part of it)
CPU_LIMIT = 3


def _run_limited(code: str) -> subprocess.CompletedProcess:
    resource = pytest.importorskip("resource", reason="RLIMIT_CPU needs a POSIX system")

    def limit() -> None:
        resource.setrlimit(resource.RLIMIT_CPU, (CPU_LIMIT, CPU_LIMIT + 1))

    return subprocess.run(
        [sys.executable, "-c", code], preexec_fn=limit, capture_output=True, text=True
    )


_SUB = f"""
import minkowski2d as mk
L = {L!r}
A = [(x * 5e-324, y * 5e-324) for x, y in L]
g = {{call}}
print(g.wkt if hasattr(g, "wkt") else [x.wkt for x in g])
"""


def test_general_sum_of_5e_324_coordinates_returns():
    p = _run_limited(_SUB.replace("{call}", "mk.minkowski_sum_general(A, L)"))
    assert p.returncode == 0, f"killed after {CPU_LIMIT} CPU seconds (status {p.returncode})"
    assert p.stdout.startswith("POLYGON ((0 0")  # A is a point at this scale: A ⊕ L ≈ L


def test_general_sum_many_of_5e_324_coordinates_returns():
    p = _run_limited(_SUB.replace("{call}", "mk.minkowski_sum_general_many([A, L], L)"))
    assert p.returncode == 0, f"killed after {CPU_LIMIT} CPU seconds (status {p.returncode})"


def test_valid_3e_200_triangle_is_not_self_intersecting():
    import shapely

    g = mk.minkowski_sum_general(T200, L)
    assert g.covers(shapely.Polygon(L)) and g.bounds == (0.0, 0.0, 3.0, 3.0)
    assert mk.minkowski_sum_general(T200, T200).bounds == (0.0, 0.0, 6e-200, 6e-200)
    out = mk.minkowski_sum_general_many([T200, T200], [L, T200])
    assert out[1].bounds == (0.0, 0.0, 6e-200, 6e-200)
