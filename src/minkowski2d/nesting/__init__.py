"""Nesting: no-fit and inner-fit polygons, and the layout optimizer built on them.

:mod:`.nfp` holds the no-fit polygons (:func:`no_fit_polygons`, :func:`inner_fit_polygon`,
:func:`degenerate_placements`, :func:`read_esicup`); :mod:`.nester` the layout optimizer
:func:`nest`; :mod:`.layout` its result :class:`Layout`; :mod:`.verify` the exact
certificate every returned layout passes.
"""

from .layout import Layout, Placement, read_layout
from .nester import nest
from .nfp import (
    MAX_PAIRS,
    degenerate_placements,
    inner_fit_polygon,
    no_fit_polygons,
    pair_blocks,
    read_esicup,
    rotate_part,
)
from .verify import Violation, verify_layout

__all__ = [
    "no_fit_polygons",
    "inner_fit_polygon",
    "degenerate_placements",
    "read_esicup",
    "pair_blocks",
    "rotate_part",
    "MAX_PAIRS",
    "Layout",
    "Placement",
    "read_layout",
    "nest",
    "verify_layout",
    "Violation",
]
