"""Type aliases used in the public signatures."""

from __future__ import annotations

from typing import Any

import numpy as np
import numpy.typing as npt

__all__ = ["ArrayLike2", "Polygon"]

#: Anything that reads as an (n, 2) array of coordinates: a list of pairs, an ndarray,
#: a shapely Polygon / LinearRing / LineString / MultiPoint / Point.
ArrayLike2 = npt.ArrayLike | Any

#: A polygon result: an (n, 2) ndarray (int64, float64, or object for exact numbers).
Polygon = np.ndarray
