"""The gateway to the compiled core: the only Python module that imports ``_ext``.

Everything Python asks of the core goes through the names below: the kernels, the limits,
the status codes and the reasons a polygon is invalid. Each is defined once, in the C++
headers (``exact.hpp`` for predicates, limits and :class:`Status`); Python reads them here,
so the two cannot drift. Kernels come in pairs by path: ``*_i`` (int64, ``|x| < INT_LIMIT``)
and ``*_f`` (float64, filtered then exact).

>>> from minkowski2d._engine import core
>>> core.INT_LIMIT == 2 ** 62, core.FLOAT_EXACT_INT == 2 ** 53
(True, True)
>>> core.cross_sign_f(0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0)
1
"""

from __future__ import annotations

import enum
from typing import TYPE_CHECKING

from .._core import _ext
from .._core._ext import (  # the kernels: the whole surface between Python and C++
    MeshPlannerF,
    Nester,
    PlannerF,
    PlannerI,
    boolean_f,
    check_polygons_f,
    clip_lines_f,
    coll_contains,
    coll_pairs,
    coll_prep,
    coll_single,
    cross_sign_f,
    cross_sign_i,
    degenerate_pieces,
    flatten,
    general_pair,
    general_sums,
    hertel_mehlhorn_f,
    hull_f,
    hull_i,
    merge_record_f,
    merge_record_i,
    normalize_f,
    normalize_i,
    offset_one,
    offset_polygons,
    offset_rings,
    orient_f,
    orient_i,
    overlay_rings,
    polygons_wkb_f,
    selftest,
    sum_batch_f,
    sum_batch_i,
    sum_f,
    sum_i,
    sum_lists,
    triangulate_polygons_f,
)

__all__ = [
    "Status",
    "Invalid",
    "INT_LIMIT",
    "FLOAT_EXACT_INT",
    "ERRBOUND",
    "MINBOUND",
    "MeshPlannerF",
    "Nester",
    "PlannerF",
    "PlannerI",
    "check_polygons_f",
    "coll_contains",
    "coll_pairs",
    "coll_prep",
    "coll_single",
    "cross_sign_f",
    "cross_sign_i",
    "degenerate_pieces",
    "flatten",
    "general_pair",
    "general_sums",
    "hertel_mehlhorn_f",
    "hull_f",
    "hull_i",
    "merge_record_f",
    "merge_record_i",
    "normalize_f",
    "normalize_i",
    "offset_one",
    "offset_polygons",
    "offset_rings",
    "orient_f",
    "orient_i",
    "overlay_rings",
    "polygons_wkb_f",
    "boolean_f",
    "clip_lines_f",
    "OVERLAY_XOR",
    "FILL_RULES",
    "NO_LIMIT",
    "selftest",
    "sum_batch_f",
    "sum_batch_i",
    "sum_f",
    "sum_i",
    "sum_lists",
    "triangulate_polygons_f",
]

#: int64 kernels take ``|x| < INT_LIMIT`` (2**62): every cross product fits in __int128.
INT_LIMIT: int = int(_ext.INT_LIMIT)
#: ints with ``|x| <= FLOAT_EXACT_INT`` (2**53) convert to float64 exactly.
FLOAT_EXACT_INT: int = int(_ext.FLOAT_EXACT_INT)
#: the float filter: Shewchuk's relative bound, and the floor below which it abstains.
ERRBOUND: float = float(_ext.ERRBOUND)
MINBOUND: float = float(_ext.MINBOUND)


class Status(enum.IntEnum):
    """Status codes of the compiled core (defined once, in exact.hpp)."""

    OK = _ext.OK
    TURNS_BOTH_WAYS = _ext.TURNS_BOTH_WAYS
    SPIKE = _ext.SPIKE
    WINDS_TWICE = _ext.WINDS_TWICE
    OVERFLOW = _ext.OVERFLOW
    NONFINITE = _ext.NONFINITE
    RANGE = _ext.RANGE
    UNHANDLED = _ext.UNHANDLED
    SHAPE = _ext.SHAPE
    EMPTY = _ext.EMPTY
    INTERNAL = _ext.INTERNAL
    RESOURCE = _ext.RESOURCE
    INVALID_POLYGON = _ext.INVALID_POLYGON


if TYPE_CHECKING:  # the members for type checkers; the names and values are the core's

    class Invalid(enum.IntEnum):
        RING_FEW_VERTICES = enum.auto()
        RING_NO_AREA = enum.auto()
        RING_SPIKE = enum.auto()
        RING_CROSSES = enum.auto()
        RING_OVERLAPS = enum.auto()
        RING_TOUCHES = enum.auto()
        RINGS_CROSS = enum.auto()
        RINGS_OVERLAP = enum.auto()
        HOLE_OUTSIDE = enum.auto()
        HOLE_IN_HOLE = enum.auto()
        POLYGONS_OVERLAP = enum.auto()

else:
    #: Why a polygon is invalid (``Status.INVALID_POLYGON``); defined once, in exact.hpp.
    Invalid = enum.IntEnum("Invalid", dict(_ext.INVALID_REASONS))

#: The merge trace's step sources, name -> code, and "no cross product decided"
#: (convex.hpp StepSource, NO_CROSS).
TRACE_SOURCES: dict[str, int] = dict(_ext.TRACE_SOURCES)
TRACE_NO_CROSS: int = _ext.TRACE_NO_CROSS
#: The collision walk's queries (collision.hpp).
COLL_INTERSECTS: int = _ext.COLL_INTERSECTS
COLL_DISTANCE: int = _ext.COLL_DISTANCE
COLL_PENETRATION: int = _ext.COLL_PENETRATION
COLL_GJK: int = _ext.COLL_GJK
COLL_AUTO: int = _ext.COLL_AUTO
#: The overlay's rules (overlay.hpp).
OVERLAY_UNION: int = _ext.OVERLAY_UNION
OVERLAY_DIFFERENCE: int = _ext.OVERLAY_DIFFERENCE
OVERLAY_INTERSECTION: int = _ext.OVERLAY_INTERSECTION
OVERLAY_XOR: int = _ext.OVERLAY_XOR
#: operation name -> the core's code (overlay.cpp; the overlay's and the booleans')
OVERLAY_OPS: dict[str, int] = dict(_ext.OVERLAY_OPS)
#: fill rule name -> the core's code (overlay.hpp FillRule)
FILL_RULES: dict[str, int] = dict(_ext.FILL_RULES)
#: the value of a work limit that never stops a run (boolean.hpp Limits)
NO_LIMIT: int = int(_ext.NO_LIMIT)
#: The general sum's methods (general.cpp; minkowski.hpp Method).
METHOD_ERODE: int = _ext.METHOD_ERODE
METHOD_AUTO: int = _ext.METHOD_AUTO
METHOD_PIECES: int = _ext.METHOD_PIECES
METHOD_CONVOLUTION: int = _ext.METHOD_CONVOLUTION
#: method name -> code, and the default work limits (minkowski.hpp Limits)
METHODS: dict[str, int] = dict(_ext.METHODS)
GENERAL_LIMITS: dict[str, int] = dict(_ext.GENERAL_LIMITS)
#: The offset's joins and codes (offset.hpp).
OFFSET_ROUND: int = _ext.OFFSET_ROUND
OFFSET_MITER: int = _ext.OFFSET_MITER
OFFSET_SQUARE: int = _ext.OFFSET_SQUARE
#: join name -> code (offset.hpp Join)
OFFSET_JOINS: dict[str, int] = dict(_ext.OFFSET_JOINS)
OFFSET_FINE: int = _ext.OFFSET_FINE
OFFSET_TOLERANCE: int = _ext.OFFSET_TOLERANCE
OFFSET_DISTANCE: int = _ext.OFFSET_DISTANCE
OFFSET_UNDERFLOW: int = _ext.OFFSET_UNDERFLOW
OFFSET_OVERFLOWS: int = _ext.OFFSET_OVERFLOWS
OFFSET_INPUT: int = _ext.OFFSET_INPUT
OFFSET_DETOUR: int = _ext.OFFSET_DETOUR
#: how an offset's region was found (info column 4): the one curve, the resolver, the overlay
OFFSET_DIRECT: int = _ext.OFFSET_DIRECT
OFFSET_RESOLVED: int = _ext.OFFSET_RESOLVED
OFFSET_OVERLAID: int = _ext.OFFSET_OVERLAID
#: The navigation mesh's build codes (navmesh.hpp).
MESH_OK: int = _ext.MESH_OK
PLAN_OK: int = _ext.PLAN_OK
PLAN_START_BAD: int = _ext.PLAN_START_BAD
PLAN_GOAL_BAD: int = _ext.PLAN_GOAL_BAD
PLAN_NO_PATH: int = _ext.PLAN_NO_PATH
PLAN_OUTSIDE_MESH: int = _ext.PLAN_OUTSIDE_MESH
MESH_INEXACT: int = _ext.MESH_INEXACT
MESH_FAILED: int = _ext.MESH_FAILED
