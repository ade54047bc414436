"""Translational motion planning: exact shortest paths for a polygonal robot among
polygonal obstacles.

Every obstacle ``O`` is inflated by the reflected robot into its configuration-space
obstacle ``O ⊕ (−R)`` (pieces ``O_i ⊕ (−R_j)`` of convex pieces when either is not
convex); the robot's reference point must stay out of the *open* interior of each of
them and, with a workspace ``W``, inside ``W ⊖ R``. Touching is allowed: a passage
exactly as wide as the robot is open, and two C-obstacles that meet at one point leave
the gaps beside it open. The seams between the convex pieces of one obstacle are not
passages.

The compiled core (:mod:`minkowski2d._core`, ``planning.hpp``) builds a reduced
visibility graph directly on the overlapping convex pieces (no union: it would close
zero-width passages): bend points are piece vertices outside every
C-obstacle's open interior, edges are the mutually visible pairs whose segment is tangent
at both ends, and every visibility and containment decision is an exact sign. Queries
connect the start and the goal by the same exact visibility and run A*. Scenes of 64
or more pieces are planned on an exact navigation mesh (``navmesh.hpp``: convex cells
and Polyanya's interval search; zero-width passages as a network of segments beside the
cells). See ``docs/planning.md``.

Examples
--------
>>> import minkowski2d as mk
>>> planner = mk.MotionPlanner([[(2, -1), (4, -1), (4, 3), (2, 3)]],
...                            robot=[(-1, -1), (1, -1), (1, 1), (-1, 1)])
>>> path = planner.shortest_path((0, 0), (6, 0))
>>> path.points.tolist()
[[0, 0], [1, -2], [5, -2], [6, 0]]
>>> round(path.length, 6)
8.472136
"""

from __future__ import annotations

from .planner import METHODS as METHODS
from .planner import MotionPlanner
from .results import NavMesh, Path

__all__ = ["MotionPlanner", "Path", "NavMesh"]
