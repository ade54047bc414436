"""What the readers share: the text of a file or standard input, ``.dat`` selectors, short
reprs for messages, and the records they return (UnboundedPolygon, Feature)."""

from __future__ import annotations

import reprlib
import sys
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np

from ..errors import (
    InputFormatError,
)


class UnboundedPolygon(NamedTuple):
    """A CGAL polygon with holes whose outer boundary is unbounded (``N = 0``).

    ``holes`` are (n, 2) arrays, clockwise as in the file.
    """

    holes: list


def _read_text(source: str | Path) -> str:
    """The text of a file (UTF-8, a leading byte-order mark dropped) or of standard input.

    Every failure is an :class:`InputFormatError` naming the file: missing, unreadable,
    a directory, a name the system cannot take, or bytes that are not UTF-8 text.
    """
    name = str(source)
    hint = "give a JSON, GeoJSON, WKT or CGAL .dat text file"
    if name == "-":
        try:
            return sys.stdin.read()
        except UnicodeDecodeError as exc:
            raise InputFormatError(
                f"-: standard input is not UTF-8 text (byte {exc.start})",
                argument="-",
                hint=hint,
            ) from None
    try:
        data = Path(source).read_bytes()
    except FileNotFoundError:
        raise InputFormatError(f"{name}: no such file", argument=name) from None
    except IsADirectoryError:
        raise InputFormatError(f"{name}: is a directory, not a file", argument=name) from None
    except OSError as exc:
        raise InputFormatError(
            f"{name}: cannot read ({exc.strerror or exc})", argument=name
        ) from None
    except ValueError as exc:  # e.g. an embedded NUL byte in the name
        raise InputFormatError(f"{_short(name)}: not a usable file name ({exc})") from None
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise InputFormatError(
            f"{name}: not a text file (byte {exc.start} is not UTF-8)", argument=name, hint=hint
        ) from None


_REPR = reprlib.Repr()
_REPR.maxlevel = 3
_REPR.maxlist = 4
_REPR.maxdict = 4
_REPR.maxstring = 30
_REPR.maxother = 30
_REPR.maxlong = 30


def _short(v: Any) -> str:
    """A bounded repr: never huge, never deep (input data can be both)."""
    try:
        return _REPR.repr(v)
    except (RecursionError, ValueError):  # pragma: no cover - reprlib bounds the depth
        return f"<{type(v).__name__}>"


def split_selector(source: str | Path) -> tuple[str, str]:
    """``("comb.dat", "2")`` for ``comb.dat#2``; ``(source, "")`` for anything else.

    Examples
    --------
    >>> split_selector("comb.dat#2"), split_selector("a.json")
    (('comb.dat', '2'), ('a.json', ''))
    """
    s = str(source)
    if ".dat#" in s:
        path, _, sel = s.rpartition("#")
        if path.endswith(".dat"):
            return path, sel
    return s, ""


def _intify(c: np.ndarray) -> np.ndarray:
    """Whole-number float coordinates from GeoJSON/WKT become ints (exact path)."""
    with np.errstate(invalid="ignore"):
        if c.size and np.all(c == np.round(c)) and np.abs(c).max() < 2.0**53:
            return c.astype(np.int64)
    return c


# --------------------------------------------------------------------------------------
# many features: GeoJSON FeatureCollections and DXF drawings


class Feature(NamedTuple):
    """One feature of a collection: its geometry (as :func:`read_geometry` returns it, or
    None for a null geometry) and its properties (a dict; GeoJSON's ``id`` is kept under
    the key ``"id"`` of :attr:`extra`). ``arcs``: for a DXF part, its exact rings of
    segments and arcs, ``(k, 3)`` arrays ``(x, y, bulge)``, exterior first (None
    otherwise)."""

    geometry: Any
    properties: dict | None
    extra: dict
    arcs: list | None = None
