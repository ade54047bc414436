"""Non-convex Minkowski sums (polygons with holes) and the Minkowski difference (erosion).

Two methods compute ``A ⊕ B`` for simple polygons with holes and collections of them:

* ``method="decomposition"`` (default): both operands are cut into convex pieces
  (Hertel-Mehlhorn, see :func:`convex_decomposition`), every pair of pieces is summed in
  one batched call (:func:`minkowski2d.minkowski_sum_many`), and the convex sums are
  unioned by GEOS. The union is done in rounds: the largest sums first, then the sums
  reaching farthest from the centre; after each round every remaining sum that lies
  strictly inside the union so far is dropped. The order only changes the speed; the
  result is the union of all piece sums.
* ``method="convolution"``: the reduced convolution (Behar & Lien 2011): segments
  ``e + v`` for an edge ``e`` of one boundary and a convex vertex ``v`` of the other
  whose normal cone holds the edge's normal. Every boundary point of the sum lies on one
  of them, so each face of their arrangement (noded and polygonized by GEOS) is wholly
  inside or wholly outside the sum. The orientability filter: just left of every segment
  is inside the sum, so a face with a boundary edge carrying a segment that has the face
  on its left is inside. The remaining faces are hole candidates; the hole filter keeps
  one as a hole only if ``A`` does not meet ``x − B`` for a point ``x`` inside it.

Both return a shapely Polygon or MultiPolygon (exterior rings counter-clockwise, holes
clockwise, holes kept). Coordinates are float64 throughout: integers with at most 53
significant bits are represented exactly (others are refused), piece sums are exact for
them, and GEOS computes the crossings of the final union in double precision. GEOS only
ever sees the operands multiplied by one common power of two that puts their largest
|coordinate| in ``[2**19, 2**20)``; the result is multiplied back (both exact), so tiny
and huge magnitudes behave like magnitudes near 1. A shapely/GEOS failure surfaces as a
:class:`~minkowski2d.errors.GeometryError` naming the operand; the work is bounded by
``MAX_PIECE_PAIRS``, ``MAX_CONVOLUTION_SEGMENTS`` and ``MAX_CROSSINGS``
(:class:`~minkowski2d.errors.ResourceLimitError`; :mod:`.limits`).

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
