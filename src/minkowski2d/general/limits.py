"""The work limits of one general sum (each a ResourceLimitError when exceeded). Set them on
the package (``minkowski2d.general.MAX_PIECE_PAIRS = n``): the package forwards the value
here, where the code reads it at each call."""

from .._engine import core

__all__ = ["MAX_PIECE_PAIRS", "MAX_CONVOLUTION_SEGMENTS", "MAX_CROSSINGS"]

#: the defaults, from their one home (the core's Limits in minkowski.hpp): 2**21 each
_DEFAULT = core.GENERAL_LIMITS

#: Work limits of one pair (each a ResourceLimitError when exceeded):
#: ``MAX_PIECE_PAIRS`` convex piece sums (pieces of A times pieces of B) for the
#: decomposition ...
MAX_PIECE_PAIRS = _DEFAULT["MAX_PIECE_PAIRS"]
#: ... ``MAX_CONVOLUTION_SEGMENTS`` segments of the convolution (about 800 bytes each
#: with their crossings: two 2048-vertex stars have over 2 M and would need gigabytes) ...
MAX_CONVOLUTION_SEGMENTS = _DEFAULT["MAX_CONVOLUTION_SEGMENTS"]
#: ... and ``MAX_CROSSINGS`` crossings noded by the exact overlay, over all its runs
#: (about 150 bytes each). The 2048-vertex stars of the benchmark need the decomposition;
#: their convolution has 10**6 segments and far more crossings.
MAX_CROSSINGS = _DEFAULT["MAX_CROSSINGS"]
