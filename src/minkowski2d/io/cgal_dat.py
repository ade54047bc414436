"""CGAL ``.dat`` files: one polygon with holes, exact numbers (ints, rationals, decimals)."""

from __future__ import annotations

import math
import re
from fractions import Fraction
from pathlib import Path

import numpy as np

from ..errors import (
    EmptyGeometryError,
    InputFormatError,
)
from .common import UnboundedPolygon, _read_text, _short

# --------------------------------------------------------------------------------------
# CGAL .dat

_INT_TOKEN = re.compile(r"[+-]?\d+\Z", re.ASCII)
_RATIONAL_TOKEN = re.compile(r"([+-]?\d+)/([+-]?\d+)\Z", re.ASCII)
_DECIMAL_TOKEN = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?\Z", re.ASCII)
_CGAL_HINT = (
    "a CGAL .dat file holds N and N vertices x y (ints, p/q or decimals), then nothing, "
    "a second polygon, or H and H holes"
)


def _cgal_number(tok: str) -> int | float | Fraction:
    """One coordinate token: an int, a rational ``p/q`` or a finite decimal.

    Raises ``ValueError`` with the reason for anything else.
    """
    if _INT_TOKEN.match(tok):
        try:
            return int(tok)
        except ValueError:  # beyond Python's digit limit
            raise ValueError("an integer with too many digits") from None
    m = _RATIONAL_TOKEN.match(tok)
    if m:
        q = int(m.group(2))
        if q == 0:
            raise ValueError("a zero denominator")
        f = Fraction(int(m.group(1)), q)
        return int(f) if f.denominator == 1 else f
    if _DECIMAL_TOKEN.match(tok):
        v = float(tok)
        if not math.isfinite(v):
            raise ValueError("beyond the float range")
        return v
    raise ValueError("not a number (int, p/q or decimal)")


def parse_cgal_dat(text: str, name: str = "input", layout: str = "auto") -> list:
    """Parse CGAL ``Minkowski_sum_2`` test-file text.

    The file is a stream of whitespace-separated tokens: ``N`` and ``N`` vertices, then
    either nothing, a second simple polygon (``N2`` and ``N2`` vertices), or a hole count
    ``H`` followed by ``H`` rings (a polygon with holes). ``layout`` is ``"auto"``,
    ``"polygons"`` or ``"pwh"``. Numbers may be ints, rationals ``p/q`` or decimals.

    Returns
    -------
    list
        (n, 2) ndarrays for simple polygons (int64 when every coordinate is an integer
        that fits, exact Python ints beyond, float64 otherwise), a shapely Polygon for a
        polygon with holes, and an :class:`UnboundedPolygon` when the outer boundary is
        empty (``N = 0``).

    Raises
    ------
    InputFormatError
        For any malformed file, naming ``name``, the line and (for a coordinate) the
        vertex: a bad or negative count, a token that is not a number, a zero
        denominator, a number beyond the float range, a file ending early, extra tokens,
        a hole or boundary with fewer than 3 vertices.
    EmptyGeometryError
        When a polygon has no vertices.

    Examples
    --------
    >>> parse_cgal_dat("4 0 0 3 0 3 3 0 3  1  4 1 1 1 2 2 2 2 1")[0].area
    8.0
    >>> [p.tolist() for p in parse_cgal_dat("3 0/1 0/1 1/1 0 0 1  2 5 5 6 6")]
    [[[0, 0], [1, 0], [0, 1]], [[5, 5], [6, 6]]]
    """
    from .._engine import options as _options

    _options.choice(layout, "layout", ("auto", "polygons", "pwh"))
    t = _Tokens(text, name)
    n1 = t.count("the vertex count")
    first = t.ring(n1, "polygon 1")
    if t.left() == 0:
        if n1 == 0:
            raise EmptyGeometryError(f"{name}: no vertices", argument=name)
        return [first]
    k_at = t.pos
    k = t.count("the second polygon or the holes")
    if layout == "polygons" or (layout == "auto" and k > 0 and t.left() == 2 * k):
        second = t.ring(k, "polygon 2")
        t.at_end()
        for r, which in ((first, 1), (second, 2)):
            if len(r) == 0:
                raise EmptyGeometryError(f"{name}: polygon {which} has no vertices", argument=name)
        return [first, second]
    holes = []
    for h in range(k):
        at = t.pos
        hole = t.ring(t.count(f"hole {h} vertex count"), f"hole {h}")
        t.boundary(hole, f"hole {h}", at)
        holes.append(hole)
    t.at_end()
    if n1 == 0:
        return [UnboundedPolygon(holes)]
    t.boundary(first, "the outer boundary of a polygon with holes", 0)
    import shapely

    try:
        return [shapely.Polygon(first, holes)]
    except Exception as exc:  # shapely: a ring that closes on itself too early, ...
        raise t.fail(f"not a polygon with holes ({_short(str(exc))})", k_at) from None


class _Tokens:
    """The whitespace-separated tokens of a ``.dat`` text, read front to back; errors name
    the file (``name``), the line and the vertex."""

    def __init__(self, text: str, name: str) -> None:
        self.text = text
        self.name = name
        self.matches = list(re.finditer(r"\S+", text))
        self.toks = [m.group() for m in self.matches]
        self.pos = 0

    def left(self) -> int:
        return len(self.toks) - self.pos

    def line(self, k: int) -> int:
        if k < len(self.matches):
            return self.text.count("\n", 0, self.matches[k].start()) + 1
        return self.text.count("\n") + 1

    def fail(self, msg: str, k: int | None = None, vertex: int | None = None) -> InputFormatError:
        where = f"line {self.line(k)}: " if k is not None else ""
        return InputFormatError(
            f"{self.name}: {where}{msg}", argument=self.name, vertex=vertex, hint=_CGAL_HINT
        )

    def at_end(self) -> None:
        if self.pos != len(self.toks):
            raise self.fail(f"{len(self.toks) - self.pos} unexpected tokens at the end", self.pos)

    def take(self, what: str) -> str:
        if self.pos >= len(self.toks):
            raise self.fail(f"file ends early (expected {what})")
        self.pos += 1
        return self.toks[self.pos - 1]

    def count(self, what: str) -> int:
        t = self.take(what)
        if not _INT_TOKEN.match(t) or t.startswith("-"):
            raise self.fail(f"expected a count for {what}, found {_short(t)}", self.pos - 1)
        try:
            return int(t)
        except ValueError:
            raise self.fail(f"the count for {what} has too many digits", self.pos - 1) from None

    def boundary(self, r: np.ndarray, what: str, k: int) -> None:
        if len(r) < 3:
            raise self.fail(f"{what} has {len(r)} vertices; a ring needs at least 3", k)

    def ring(self, n: int, what: str) -> np.ndarray:
        """``n`` vertices: int64, exact Python ints beyond it, or float64 when a coordinate
        is not an integer."""
        left = self.left()
        if 2 * n > left:
            raise self.fail(
                f"file ends early: {what} has {n} vertices but only {left} numbers follow",
                self.pos - 1,
            )
        start = self.pos
        vals: list = []
        for j in range(2 * n):
            t = self.toks[start + j]
            try:
                vals.append(_cgal_number(t))
            except ValueError as exc:
                raise self.fail(
                    f"{what} vertex {j // 2}: {_short(t)} is {exc}", start + j, vertex=j // 2
                ) from None
        self.pos += 2 * n
        if any(isinstance(v, (float, Fraction)) for v in vals):
            out = []
            for j, v in enumerate(vals):
                try:
                    out.append(float(v))
                except OverflowError:
                    raise self.fail(
                        f"{what} vertex {j // 2}: {_short(self.toks[start + j])} is beyond the "
                        "float range (the ring has non-integer coordinates, so it is read as "
                        "floats)",
                        start + j,
                        vertex=j // 2,
                    ) from None
            return np.array(out, dtype=np.float64).reshape(n, 2)
        try:
            return np.array(vals, dtype=np.int64).reshape(n, 2)
        except OverflowError:
            arr = np.empty((n, 2), dtype=object)
            arr[:] = [(vals[2 * i], vals[2 * i + 1]) for i in range(n)]
            return arr


def read_cgal_dat(source: str | Path, layout: str = "auto") -> list:
    """Read a CGAL ``.dat`` file; see :func:`parse_cgal_dat`."""
    return parse_cgal_dat(_read_text(source), name=str(source), layout=layout)
