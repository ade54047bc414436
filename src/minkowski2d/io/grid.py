"""Grid maps: the Moving AI pathfinding benchmarks' ``.map`` format, as an occupancy grid."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..errors import InputFormatError
from .common import _read_text, _short

_MAP_FREE = frozenset(".GS")
_MAP_BLOCKED = frozenset("@OTW")


def read_grid_map(source: str | Path) -> np.ndarray:
    r"""An occupancy grid from a Moving AI ``.map`` file (the pathfinding benchmarks').

    The format is a header ``type <name>``, ``height <H>``, ``width <W>``, ``map``, then
    H lines of W characters: ``.``, ``G`` and ``S`` are free, ``@``, ``O``, ``T`` and
    ``W`` blocked. Returns an (H, W) bool array, True where blocked; row ``r`` is the
    file's ``r``-th map line, so that :meth:`minkowski2d.MotionPlanner.from_grid` puts
    cell (x, y) of the benchmarks' scenarios (column, row) at ``[x, x + 1] × [y, y + 1]``.

    Raises
    ------
    InputFormatError
        The file cannot be read, or is not in this format: the message names the line
        (and for a bad character, the column) and what was expected.

    Examples
    --------
    >>> import tempfile, os
    >>> d = tempfile.mkdtemp()
    >>> f = os.path.join(d, "a.map")
    >>> _ = open(f, "w").write("type octile\nheight 2\nwidth 3\nmap\n.@.\n...\n")
    >>> read_grid_map(f).astype(int).tolist()
    [[0, 1, 0], [0, 0, 0]]
    """
    return parse_grid_map(_read_text(source), str(source))


def parse_grid_map(text: str, name: str = "input") -> np.ndarray:
    r""":func:`read_grid_map` on the text of a ``.map`` file (``name`` for messages).

    Examples
    --------
    >>> parse_grid_map("type octile\nheight 1\nwidth 2\nmap\n@.\n").tolist()
    [[True, False]]
    """
    hint = "a .map file starts with 'type octile', 'height H', 'width W', 'map'"
    lines = text.splitlines()

    def fail(msg: str, line: int | None = None) -> InputFormatError:
        where = f" (line {line})" if line is not None else ""
        return InputFormatError(f"{name}: {msg}{where}", argument=name, hint=hint)

    k = 0
    while k < len(lines) and not lines[k].strip():
        k += 1
    if k == len(lines):
        raise fail("empty file, expected a grid map")
    head: dict[str, str] = {}
    for want in ("type", "height", "width"):
        if k >= len(lines):
            raise fail(f"the header ends before '{want}'")
        parts = lines[k].split()
        if len(parts) != 2 or parts[0].lower() != want:
            raise fail(f"expected '{want} <value>', got {_short(lines[k])}", k + 1)
        head[want] = parts[1]
        k += 1
    dims = {}
    for key in ("height", "width"):
        v = head[key]
        if not v.isdigit() or int(v) < 1:
            line = 2 if key == "height" else 3
            raise fail(f"{key} must be a positive integer, got {_short(v)}", line)
        dims[key] = int(v)
    H, W = dims["height"], dims["width"]
    if k >= len(lines) or lines[k].strip().lower() != "map":
        got = _short(lines[k]) if k < len(lines) else "the end of the file"
        raise fail(f"expected the line 'map' after the header, got {got}", k + 1)
    k += 1
    rows = [ln.rstrip("\r\n\t ") for ln in lines[k:]]
    while rows and not rows[-1]:
        rows.pop()
    if len(rows) != H:
        raise fail(f"height is {H} but the map has {len(rows)} rows")
    occ = np.zeros((H, W), dtype=bool)
    for r, row in enumerate(rows):
        if len(row) != W:
            raise fail(f"width is {W} but this row has {len(row)} characters", k + r + 1)
        for c, ch in enumerate(row):
            if ch in _MAP_BLOCKED:
                occ[r, c] = True
            elif ch not in _MAP_FREE:
                raise fail(
                    f"unknown terrain {ch!r} at column {c + 1}: free is one of '.GS', "
                    "blocked one of '@OTW'",
                    k + r + 1,
                )
    return occ
