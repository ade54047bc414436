"""The compiled exact core (C++17, nanobind): the extension module ``_ext`` and its C++
sources. Private: Python reaches it through one gateway, :mod:`minkowski2d._engine.core`
(the only Python module that imports ``_ext``).

>>> from minkowski2d._engine import core
>>> core.cross_sign_f(0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0)
1
"""
