"""Non-convex Minkowski sums (polygons with holes) and the Minkowski difference (erosion).

Every decision is made by the compiled core's exact overlay (``_core/overlay.hpp``):
exact signs (a float filter with a certified bound, exact dyadic arithmetic where it
cannot tell), intersection points kept exact and rounded once, so every output vertex is
the correctly rounded exact vertex. Two methods compute ``A ⊕ B`` for simple polygons
with holes and collections of them, and give the same vertices:

* ``method="decomposition"``: both operands cut into convex pieces (an exact
  triangulation merged by Hertel-Mehlhorn, see :func:`convex_decomposition`), every
  pair of pieces summed by the convex merge, the sums united by the exact overlay
  (sums inside another one culled first).
* ``method="convolution"``: the full convolution of the boundaries (segments ``e + v``
  where ``v``'s cone holds ``e``'s direction), noded by the overlay, winding number
  >= 1; holes of one operand that the other cannot fit into are filled first.

Unset, the core picks per pair: the convolution while it has at most a few segments per
input vertex, else the pieces. Both return a shapely Polygon or MultiPolygon (exterior
rings counter-clockwise, holes clockwise, holes kept). Nothing is scaled; integers with
at most 53 significant bits are exact (others are refused), Fractions are rounded to
float64 once. The work is bounded by ``MAX_PIECE_PAIRS``, ``MAX_CONVOLUTION_SEGMENTS``
and ``MAX_CROSSINGS`` (:class:`~minkowski2d.errors.ResourceLimitError`; :mod:`.limits`).

:func:`minkowski_difference` is the erosion ``A ⊖ B = {c : c + B ⊆ A}``. It is *not*
``A ⊕ (−B)`` (that is :func:`minkowski2d.cspace_obstacle`, the set of translations
where ``B`` *touches* ``A``); the erosion is the set where ``B`` fits *inside* ``A``.
Neither operand needs to contain the origin.
"""

from __future__ import annotations

import sys
import types
from typing import Any

from . import limits
from .erosion import minkowski_difference
from .limits import (  # noqa: F401 - the public knobs, set here (see _Package)
    MAX_CONVOLUTION_SEGMENTS,
    MAX_CROSSINGS,
    MAX_PIECE_PAIRS,
)
from .many import minkowski_sum_general_many
from .operands import DECOMPOSITIONS as DECOMPOSITIONS
from .operands import SUM_METHODS as SUM_METHODS
from .operands import convex_decomposition
from .sums import minkowski_sum_general

__all__ = [
    "minkowski_sum_general",
    "minkowski_sum_general_many",
    "convex_decomposition",
    "minkowski_difference",
]


class _Package(types.ModuleType):
    """Setting a work limit on the package sets it in :mod:`.limits`, where it is read."""

    def __setattr__(self, name: str, value: Any) -> None:
        if name in limits.__all__:
            setattr(limits, name, value)
        super().__setattr__(name, value)


sys.modules[__name__].__class__ = _Package
