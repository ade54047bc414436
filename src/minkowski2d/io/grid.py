"""Grid maps: the Moving AI pathfinding benchmarks' ``.map`` format, as an occupancy grid,
and their ``.scen`` scenario files."""

from __future__ import annotations

from pathlib import Path
from typing import NamedTuple

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


class ScenarioQuery(NamedTuple):
    """One line of a Moving AI ``.scen`` file (:func:`read_scenario`): the start and goal
    cells as (column, row), and the optimal 8-connected length between their centres
    without corner cutting, as the file gives it (rounded there)."""

    bucket: int
    map: str
    width: int
    height: int
    start: tuple[int, int]
    goal: tuple[int, int]
    optimal: float


def read_scenario(source: str | Path) -> list[ScenarioQuery]:
    r"""The queries of a Moving AI scenario file (``.scen``, version 1).

    Each line after ``version 1`` is ``bucket map width height sx sy gx gy optimal``
    (tab- or space-separated). Plan between the cell centres: ``(sx + 0.5, sy + 0.5)``
    on :meth:`minkowski2d.MotionPlanner.from_grid` of :func:`read_grid_map`'s grid; an
    any-angle path is never longer than ``optimal`` (up to the file's rounding).

    Raises
    ------
    InputFormatError
        The file cannot be read, or a line has not nine fields of these types: the
        message names the line.

    Examples
    --------
    >>> import tempfile, os
    >>> f = os.path.join(tempfile.mkdtemp(), "a.map.scen")
    >>> _ = open(f, "w").write("version 1\n0\ta.map\t3\t2\t0\t0\t2\t1\t2.41421\n")
    >>> q = read_scenario(f)[0]
    >>> q.start, q.goal, q.optimal
    ((0, 0), (2, 1), 2.41421)
    """
    return parse_scenario(_read_text(source), str(source))


def parse_scenario(text: str, name: str = "input") -> list[ScenarioQuery]:
    r""":func:`read_scenario` on the text of a ``.scen`` file (``name`` for messages).

    Examples
    --------
    >>> parse_scenario("version 1\n1 m.map 4 4 0 0 3 3 4.24264\n")[0].bucket
    1
    """
    hint = "a .scen file is 'version 1', then lines 'bucket map W H sx sy gx gy optimal'"
    out = []
    for k, line in enumerate(text.splitlines()):
        parts = line.split()
        if not parts or (k == 0 and parts[0].lower() == "version"):
            continue
        try:
            if len(parts) != 9:
                raise ValueError(f"{len(parts)} fields")
            b, w, h, sx, sy, gx, gy = (int(parts[i]) for i in (0, 2, 3, 4, 5, 6, 7))
            opt = float(parts[8])
        except ValueError as exc:
            raise InputFormatError(
                f"{name}: line {k + 1}: expected 'bucket map W H sx sy gx gy optimal' "
                f"(ints, then a number), got {_short(line)} ({exc})",
                argument=name,
                hint=hint,
            ) from None
        out.append(ScenarioQuery(b, parts[1], w, h, (sx, sy), (gx, gy), opt))
    return out
