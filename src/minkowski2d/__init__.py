"""minkowski2d: exact, fast 2-D Minkowski sums of polygons, and what they power.

>>> import minkowski2d as mk
>>> mk.minkowski_sum([(0, 0), (2, 0), (0, 2)], [(0, 0), (1, 0), (1, 1), (0, 1)]).tolist()
[[0, 0], [3, 0], [3, 1], [1, 3], [0, 3]]
"""

from __future__ import annotations

from typing import Any

from . import errors
from ._version import __version__
from .batch import Ragged, minkowski_sum_many
from .boolean import (
    clip_lines,
    difference,
    intersection,
    symmetric_difference,
    union,
    union_all,
)
from .collision import (
    Distance,
    Penetration,
    contains,
    distance,
    distance_many,
    intersects,
    intersects_many,
    penetration,
    penetration_many,
)
from .convex import (
    convex_hull,
    cspace_obstacle,
    is_convex,
    minkowski_sum,
    normalize,
    reflect,
    signed_area,
    translate,
)
from .errors import GeometryError
from .general import (
    convex_decomposition,
    minkowski_difference,
    minkowski_sum_general,
    minkowski_sum_general_many,
)
from .nesting import (
    Layout,
    Placement,
    degenerate_placements,
    inner_fit_polygon,
    nest,
    no_fit_polygons,
    pair_blocks,
    read_esicup,
    read_layout,
    rotate_part,
    verify_layout,
)
from .offset import OffsetArcs, offset, offset_arcs, offset_many
from .planning import MotionPlanner, Path
from .trace import MergeTrace, merge_trace


def __getattr__(name: str) -> Any:
    # the page template and server load only when used (import time matters for CLIs)
    if name == "animate":
        from .animation import animate

        return animate
    if name in ("plot", "io", "datasets"):
        import importlib

        # plot: a callable module, mk.plot(obj, ax=None, **kwargs), matplotlib loads on
        # drawing; io: the readers and writers (mk.io.read_grid_map after import mk);
        # datasets: the built-in instances (mk.datasets.esicup("albano"))
        return importlib.import_module("." + name, __name__)
    raise AttributeError(f"module 'minkowski2d' has no attribute {name!r}")


__all__ = [
    "errors",
    "union",
    "intersection",
    "difference",
    "symmetric_difference",
    "union_all",
    "clip_lines",
    "GeometryError",
    "Ragged",
    "minkowski_sum",
    "minkowski_sum_many",
    "normalize",
    "is_convex",
    "convex_hull",
    "signed_area",
    "translate",
    "reflect",
    "cspace_obstacle",
    "merge_trace",
    "MergeTrace",
    "animate",
    "plot",
    "minkowski_sum_general",
    "convex_decomposition",
    "minkowski_difference",
    "minkowski_sum_general_many",
    "no_fit_polygons",
    "inner_fit_polygon",
    "degenerate_placements",
    "read_esicup",
    "pair_blocks",
    "rotate_part",
    "Layout",
    "Placement",
    "read_layout",
    "nest",
    "verify_layout",
    "intersects",
    "distance",
    "penetration",
    "contains",
    "intersects_many",
    "distance_many",
    "penetration_many",
    "offset",
    "offset_arcs",
    "offset_many",
    "OffsetArcs",
    "Distance",
    "Penetration",
    "MotionPlanner",
    "Path",
    "__version__",
]
