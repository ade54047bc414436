"""The compiled exact core (C++17, nanobind): predicates, normalization, the merge, the
batch, hull, collision walks and GJK. Private: the public modules reach it through
:mod:`minkowski2d._dispatch`.

>>> from minkowski2d._core import _ext
>>> _ext.cross_sign_f(0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0)
1
"""

from . import _ext

__all__ = ["_ext"]
