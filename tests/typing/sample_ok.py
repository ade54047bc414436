"""User code calling the public API; `mypy --strict` must pass on it (tests/test_typing.py)."""

from __future__ import annotations

from fractions import Fraction

import numpy as np

import minkowski2d as mk

tri = [(0, 0), (2, 0), (0, 2)]
sq = np.array([[0, 0], [1, 0], [1, 1], [0, 1]])
s: np.ndarray = mk.minkowski_sum(tri, sq)
exact: list[tuple[Fraction, Fraction]] = [
    (Fraction(1, 2), Fraction(0)),
    (Fraction(1, 3), Fraction(2)),
]
h = mk.minkowski_sum(exact, tri, hull=True)
c: bool = mk.is_convex(tri)
area: float = mk.signed_area(sq)
r: mk.Ragged = mk.Ragged.from_list([tri, sq])
part: mk.Ragged = r[1:]
many = mk.minkowski_sum_many([tri, tri], sq, threads=2, progress=lambda done, total: None)
hit = mk.intersects_many(r, tri, method="gjk")
d: mk.Distance = mk.distance(tri, sq)
p: mk.Penetration = mk.penetration(tri, sq)
yes: bool = mk.intersects(tri, sq)
t: mk.MergeTrace = mk.merge_trace(tri, sq)
n = len(t.steps) + int(d.distance) + int(p.depth) + len(h) + len(s) + len(part)
d2: mk.Distance = mk.distance_many(r, tri, threads=2)
rag: mk.Ragged = mk.minkowski_sum_many([tri, tri], [(0, 0), (1, 1)])
