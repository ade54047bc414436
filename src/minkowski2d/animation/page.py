"""Build the animation page: the trace and every coordinate drawn, computed in Python.

The page's JavaScript only plays this data back. It maps world coordinates to screen
pixels with the one affine view map given here (and back, to place a dragged vertex),
and computes no geometry: edge vectors, vertices, label and icon positions, the
configuration-space polygons and the robot's positions all come from Python.
"""

from __future__ import annotations

import html
import json
import math
import re
from fractions import Fraction
from importlib import resources
from pathlib import Path
from typing import Any

from .._types import ArrayLike2
from ..convex import cspace_obstacle, normalize, reflect, translate
from ..errors import GeometryError, OverflowGeometryError, ShapeError
from ..trace import format_point, merge_trace
from ..trace import json_point as _json_point

__all__ = [
    "SEED_A",
    "SEED_B",
    "MAX_VERTICES",
    "page_data",
    "render",
    "animate",
    "write_demo_page",
    "parse_points",
]

#: The seed's walkthrough: triangle A and unit square B.
SEED_A = [(0, 0), (2, 0), (0, 2)]
SEED_B = [(0, 0), (1, 0), (1, 1), (0, 1)]

#: The title of the demo page (``minkowski2d demo``, :func:`write_demo_page`).
DEMO_TITLE = "Minkowski sum of a triangle and a square: the edge merge, step by step"

#: Largest polygon (vertices, each operand) the page accepts: it draws every step.
MAX_VERTICES = 2000

_SCENE_PX = 400  # an SVG viewBox is _SCENE_PX wide and high (user units = CSS px of text)
_SMALL_PX = 240  # the pictures of A and B are drawn smaller: their text stays legible
_TOO_BIG = 1e150  # beyond this a view box would overflow float64

_STATIC_CSP = (
    "default-src 'none'; style-src 'unsafe-inline'; script-src 'unsafe-inline'; "
    "img-src data:; connect-src 'none'; base-uri 'none'; form-action 'none'"
)
_SERVED_CSP = (
    "default-src 'none'; style-src 'unsafe-inline'; script-src 'unsafe-inline'; "
    "img-src data:; connect-src 'self'; base-uri 'none'; form-action 'none'"
)


# --------------------------------------------------------------------------------------
# input text


_NUMBER = re.compile(
    r"[-+]?(?:nan|inf(?:inity)?|(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?(?:/\d+)?)", re.IGNORECASE
)


def _number(tok: str, name: str, k: int) -> Any:
    """One typed number; ``k`` is its vertex. Raises ShapeError for what is not one."""
    try:
        if "/" in tok:
            num, den = tok.split("/")
            if int(den) == 0:
                raise ShapeError(f"{name}: division by zero in {tok!r}", argument=name, vertex=k)
            return Fraction(int(num), int(den))
        try:
            return int(tok)
        except ValueError:
            if tok.lstrip("+-").isdigit():
                raise
            return float(tok)
    except ShapeError:
        raise
    except ValueError:
        raise ShapeError(
            f"{name}: cannot read the number {tok[:30]!r} (vertex {k}); a fraction is p/q "
            "with whole numbers p and q",
            argument=name,
            vertex=k,
        ) from None


def _json_vertices(obj: Any, name: str) -> list:
    """The vertices of a typed JSON polygon: a list of pairs, or a GeoJSON geometry."""
    if isinstance(obj, dict):
        t = obj.get("type")
        if t not in ("Polygon", "LineString", "MultiPoint"):
            raise ShapeError(
                f"{name}: expected a list of (x, y) pairs or a GeoJSON Polygon, LineString "
                "or MultiPoint",
                argument=name,
            )
        coords = obj.get("coordinates")
        if t == "Polygon":
            if not (isinstance(coords, list) and coords):
                raise ShapeError(f"{name}: a GeoJSON Polygon without coordinates", argument=name)
            coords = coords[0]
        if not isinstance(coords, list):
            raise ShapeError(f"{name}: a GeoJSON {t} without coordinates", argument=name)
        obj = coords
    if not isinstance(obj, list):
        raise ShapeError(f"{name}: expected a list of (x, y) pairs", argument=name)
    return [tuple(p) if isinstance(p, list) else p for p in obj]


def parse_points(text: str, name: str) -> list:
    """Read a polygon typed by a person: a JSON list of pairs, or numbers in pairs.

    Accepts ``[[0, 0], [2, 0], [0, 2]]``, ``(0, 0), (2, 0), (0, 2)``, ``0 0; 2 0; 0 2``
    or one vertex per line; ints stay ints, ``1/3`` is an exact Fraction, ``nan`` and
    ``inf`` are read (and then rejected by the geometry with a clear message).

    Examples
    --------
    >>> parse_points("(0, 0), (2, 0), (1/2, 3)", "A")
    [(0, 0), (2, 0), (Fraction(1, 2), 3)]
    >>> parse_points("[[0, 0.5], [1, 2]]", "A")
    [(0, 0.5), (1, 2)]
    """
    s = text.strip()
    if s.startswith("[") or s.startswith("{"):
        try:
            obj = json.loads(s)
        except RecursionError:
            raise ShapeError(f"{name}: JSON nested too deeply", argument=name) from None
        except ValueError:
            pass
        else:
            return _json_vertices(obj, name)
    toks = _NUMBER.findall(s)
    rest = _NUMBER.sub(" ", s)
    junk = re.sub(r"[\s,;()\[\]]+", "", rest)
    if junk:
        raise ShapeError(
            f"{name}: cannot read {junk[:20]!r}; type numbers in (x, y) pairs", argument=name
        )
    if len(toks) % 2:
        raise ShapeError(f"{name}: {len(toks)} numbers do not make (x, y) pairs", argument=name)
    nums = [_number(t, name, k // 2) for k, t in enumerate(toks)]
    return list(zip(nums[::2], nums[1::2], strict=True))


def _renamed(exc: GeometryError, name: str) -> GeometryError:
    """The same error with the argument named as the page names it (from the error's
    ``argument`` field), the ``hull=True`` advice worded for the page."""
    from ..cli.common import renamed_error

    arg = exc.argument
    return renamed_error(
        exc,
        {arg: name} if arg in ("a", "b", "p", "v") else None,
        prefix=None if arg in ("a", "b", "p", "v") else name,
        hull_hint="or use the convex hull",
        hint_in_message=True,
    )


def _call(name: str, fn: Any, *args: Any, **kw: Any) -> Any:
    try:
        return fn(*args, **kw)
    except GeometryError as exc:
        raise _renamed(exc, name) from None


# --------------------------------------------------------------------------------------
# views, grid and drawing lists


def _nice(x: float) -> float:
    """1, 2 or 5 times a power of ten, >= x."""
    e = math.floor(math.log10(x))
    base = 10.0**e
    for m in (1, 2, 5, 10):
        if m * base >= x * (1 - 1e-12):
            return m * base
    return 10 * base


def _tick_text(t: float, step: float) -> str:
    if abs(t) < step * 1e-9:
        return "0"
    if step >= 1 and abs(t) < 1e15:
        return str(round(t))
    if 1e-4 <= step < 1:
        return f"{t:.{max(0, -math.floor(math.log10(step)))}f}"
    return f"{t:.3g}"


def _view(
    points: list, kind: str, hold: list | None = None, px: int = _SCENE_PX, pad: float = 1.3
) -> dict:
    """A square view around ``points`` (floats), with grid ticks and a snap unit.

    With ``hold`` (a box ``[x0, y0, x1, y1]``) that box is kept as it is when every
    point is inside it, and grown to take them otherwise.
    """
    xs = [float(p[0]) for p in points]
    ys = [float(p[1]) for p in points]
    if max(max(map(abs, xs)), max(map(abs, ys))) > _TOO_BIG:
        raise GeometryError("coordinates too large to draw (beyond 1e150)")
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    if hold is not None:
        h0, g0, h1, g1 = (float(v) for v in hold)
        if not all(math.isfinite(v) for v in (h0, g0, h1, g1)) or h1 <= h0 or g1 <= g0:
            hold = None
        elif h0 <= x0 and x1 <= h1 and g0 <= y0 and y1 <= g1:
            vx0, vy0, size = h0, g0, max(h1 - h0, g1 - g0)
        else:
            x0, x1, y0, y1 = min(x0, h0), max(x1, h1), min(y0, g0), max(y1, g1)
            hold = None
    if hold is None:
        size = max(x1 - x0, y1 - y0)
        if size == 0:
            size = max(abs(x0), abs(y0)) * 0.2 or 1.0
            if kind != "float":
                size = max(size, 2.0)
        size = max(size * pad, 1e-290)
        vx0 = (x0 + x1) / 2 - size / 2
        vy0 = (y0 + y1) / 2 - size / 2
    step = _nice(size / 8)
    ticks_x = [k * step for k in range(math.ceil(vx0 / step), math.floor((vx0 + size) / step) + 1)]
    ticks_y = [k * step for k in range(math.ceil(vy0 / step), math.floor((vy0 + size) / step) + 1)]
    snap = _nice(step / 4)
    if kind != "float":
        snap = max(1.0, float(round(snap)))
    return {
        "box": [vx0, vy0, vx0 + size, vy0 + size],
        "px": px,
        "ticks_x": ticks_x,
        "ticks_y": ticks_y,
        "labels_x": [_tick_text(t, step) for t in ticks_x],
        "labels_y": [_tick_text(t, step) for t in ticks_y],
        "axis_x": vy0 <= 0 <= vy0 + size,
        "axis_y": vx0 <= 0 <= vx0 + size,
        "snap": snap,
        "snap_int": kind != "float",
    }


def _edge_marks(P: list, size: float, prefix: str, px: int) -> list:
    """Each edge of the normalized polygon ``P``: ends, label, label position, and whether
    the label fits (edges shorter than about two labels' width go unlabelled unless they
    are the ones being compared)."""
    n = len(P)
    if n == 1:
        return []
    min_len = 26.0 * size / px  # world length of 26 pixels
    out = []
    for k in range(n):
        p = P[k]
        q = P[(k + 1) % n]
        ax, ay, qx, qy = float(p[0]), float(p[1]), float(q[0]), float(q[1])
        dx, dy = qx - ax, qy - ay
        ln = math.hypot(dx, dy) or 1.0
        off = 0.05 * size
        lab = ((ax + qx) / 2 + dy / ln * off, (ay + qy) / 2 - dx / ln * off)
        out.append(
            {
                "from": _json_point(p),
                "to": _json_point(q),
                "label": f"{prefix}{k}",
                "label_at": [lab[0], lab[1]],
                "label_fits": n <= 12 or math.hypot(dx, dy) >= min_len,
            }
        )
    return out


def _icon(e: Any) -> list:
    """Endpoints of a direction arrow for the edge vector ``e`` in a 24×24 icon."""
    dx, dy = float(e[0]), float(e[1])
    ln = math.hypot(dx, dy) or 1.0
    ux, uy = dx / ln, dy / ln
    return [[12 - 8 * ux, 12 + 8 * uy], [12 + 8 * ux, 12 - 8 * uy]]


def _rows(arr: Any) -> list:
    return [tuple(r) for r in arr.tolist()]


def _cspace(obstacle: Any, robot: Any, obstacle_name: str, robot_name: str) -> dict:
    O = _rows(_call(obstacle_name, normalize, obstacle))
    R = _rows(_call(robot_name, normalize, robot))
    negR = _rows(_call(robot_name, reflect, R))
    C = _rows(_call("C-space obstacle", cspace_obstacle, O, R))
    positions = [_rows(translate(R, c)) for c in C]
    origin = [(0, 0)]
    fkind = "float" if any(isinstance(v, float) for p in O + R for v in p) else "int"
    frame = _view(R + negR + origin, fkind, None, 300)
    work = _view(O + C + [p for pos in positions for p in pos], fkind)
    return {
        "obstacle": [_json_point(p) for p in O],
        "robot": [_json_point(p) for p in R],
        "reflected": [_json_point(p) for p in negR],
        "inflated": [_json_point(p) for p in C],
        "obstacle_text": [format_point(p) for p in O],
        "robot_text": [format_point(p) for p in R],
        "reflected_text": [format_point(p) for p in negR],
        "inflated_text": [format_point(p) for p in C],
        "positions": [
            {
                "ref": _json_point(c),
                "ref_text": format_point(c),
                "robot": [_json_point(p) for p in pos],
            }
            for c, pos in zip(C, positions, strict=True)
        ],
        "frame_view": frame,
        "work_view": work,
        "linked": obstacle_name == "A",
    }


def _check_size(p: Any, name: str) -> None:
    try:
        n = len(p)
    except TypeError:
        return
    if n > MAX_VERTICES:
        raise ShapeError(f"{name}: {n} vertices is more than the page draws ({MAX_VERTICES})")


def page_data(
    a: ArrayLike2,
    b: ArrayLike2,
    *,
    obstacle: ArrayLike2 | None = None,
    robot: ArrayLike2 | None = None,
    hull: bool = False,
    hold_view: dict | None = None,
    roomy: bool = False,
) -> dict:
    """Everything the page draws, as JSON-ready data.

    Parameters
    ----------
    a, b : (n, 2) array_like
        The convex polygons whose merge is animated.
    obstacle, robot : (n, 2) array_like, optional
        The configuration-space scene; by default the obstacle is ``a`` and the robot
        ``b`` (so the scene shows ``a ⊕ (−b)``).
    hull : bool, default False
        Use the convex hulls of ``a`` and ``b``.
    hold_view : {"a": [x0, y0, x1, y1], "b": [...]}, optional
        Keep the view boxes of the pictures of A and B (grown if needed), so that a
        vertex being dragged stays under the pointer.
    roomy : bool, default False
        Leave room around A and B in their pictures, to drag vertices outwards (the
        editable page).

    Examples
    --------
    >>> d = page_data([(0, 0), (2, 0), (0, 2)], [(0, 0), (1, 0), (1, 1), (0, 1)])
    >>> d["trace"]["result_text"]
    ['(0, 0)', '(3, 0)', '(3, 1)', '(1, 3)', '(0, 3)']
    >>> d["cspace"]["inflated_text"]
    ['(-1, -1)', '(2, -1)', '(2, 0)', '(0, 2)', '(-1, 2)']
    """
    try:
        return _page_data(a, b, obstacle, robot, hull, hold_view, roomy)
    except (OverflowError, RecursionError, OverflowGeometryError) as exc:
        if isinstance(exc, OverflowGeometryError) and exc.argument != "trace":
            raise
        # exact integers beyond the float range: the page draws in floats
        raise OverflowGeometryError(
            "coordinates beyond the float range (about 1.8e308) cannot be drawn",
            hint="scale the polygons down",
        ) from None


def _page_data(
    a: Any,
    b: Any,
    obstacle: Any,
    robot: Any,
    hull: bool,
    hold_view: dict | None,
    roomy: bool,
) -> dict:
    _check_size(a, "A")
    _check_size(b, "B")
    t = _trace(a, b, hull)
    d = t.to_dict()
    kind = t.kind
    hold = hold_view if isinstance(hold_view, dict) else {}
    pad = 2.2 if roomy else 1.3
    v_a = _view(t.a, kind, _box(hold.get("a")), _SMALL_PX, pad)
    v_b = _view(t.b, kind, _box(hold.get("b")), _SMALL_PX, pad)
    v_sum = _view(list(t.result.tolist()) or [t.start], kind)
    if obstacle is None and robot is None:
        cs = _cspace(t.a, t.b, "A", "B")
    else:
        cs = _cspace(
            t.a if obstacle is None else obstacle,
            t.b if robot is None else robot,
            "A" if obstacle is None else "obstacle",
            "B" if robot is None else "robot",
        )
        cs["linked"] = False
    return {
        "trace": d,
        "a_view": v_a,
        "b_view": v_b,
        "sum_view": v_sum,
        "edges_a": _edge_marks(t.a, v_a["box"][2] - v_a["box"][0], "a", v_a["px"]),
        "edges_b": _edge_marks(t.b, v_b["box"][2] - v_b["box"][0], "b", v_b["px"]),
        "icons_a": [_icon(e) for e in t.edges_a],
        "icons_b": [_icon(e) for e in t.edges_b],
        "hull": bool(hull),
        "cspace": cs,
    }


def _box(v: Any) -> list | None:
    """A view box sent by the page, or None when it is not four finite numbers."""
    if not isinstance(v, (list, tuple)) or len(v) != 4:
        return None
    if not all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in v):
        return None
    return list(v) if all(math.isfinite(x) for x in v) else None


def _trace(a: Any, b: Any, hull: bool) -> Any:
    """merge_trace, with errors naming the operands as the page does (A, B)."""
    try:
        return merge_trace(a, b, hull=hull)
    except GeometryError as exc:
        if exc.argument in ("a", "b"):
            raise _renamed(exc, exc.argument.upper()) from None
        raise


# --------------------------------------------------------------------------------------
# the page


def _asset(name: str) -> str:
    return resources.files(__package__).joinpath(name).read_text(encoding="utf-8")


def _json_for_script(obj: Any) -> str:
    try:
        s = json.dumps(obj, allow_nan=False, separators=(",", ":"), ensure_ascii=False)
    except ValueError:
        raise GeometryError("a coordinate is not finite after drawing; cannot render") from None
    return s.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")


def render(
    a: ArrayLike2,
    b: ArrayLike2,
    *,
    obstacle: ArrayLike2 | None = None,
    robot: ArrayLike2 | None = None,
    hull: bool = False,
    editable: bool = False,
    api: str = "/api/trace",
    title: str | None = None,
    data: dict | None = None,
) -> str:
    """The animation page as one self-contained HTML string.

    CSS and JavaScript are inline and the trace is embedded as JSON; a Content Security
    Policy forbids every network request (the editable page may only talk to its own
    server, at ``api``).

    Parameters
    ----------
    a, b, obstacle, robot, hull
        As :func:`page_data`.
    editable : bool, default False
        The served mode: vertices can be dragged or typed and the page asks the server
        at ``api`` for the new trace.
    title : str, optional
        The page title.
    data : dict, optional
        Precomputed :func:`page_data` (then ``a`` and ``b`` are not used).

    Examples
    --------
    >>> page = render([(0, 0), (2, 0), (0, 2)], [(0, 0), (1, 0), (1, 1), (0, 1)])
    >>> page.startswith("<!doctype html>"), "<script src" in page, "stylesheet" in page
    (True, False, False)
    """
    if data is None:
        data = page_data(a, b, obstacle=obstacle, robot=robot, hull=hull)
    payload = dict(data, editable=bool(editable), api=api if editable else None)
    title = title or "Minkowski sum A ⊕ B: the edge merge, step by step"
    page = _asset("template.html")
    for marker, value in (
        ("<!--MK:CSP-->", _SERVED_CSP if editable else _STATIC_CSP),
        ("<!--MK:TITLE-->", html.escape(title)),
        ("/*MK:STYLE*/", _asset("style.css")),
        ("/*MK:SCRIPT*/", _asset("player.js")),
    ):
        page = page.replace(marker, value)
    return page.replace("<!--MK:DATA-->", _json_for_script(payload))


def animate(
    a: ArrayLike2,
    b: ArrayLike2,
    path: str | Path = "animation.html",
    *,
    obstacle: ArrayLike2 | None = None,
    robot: ArrayLike2 | None = None,
    hull: bool = False,
    title: str | None = None,
) -> Path:
    """Write the interactive animation of ``a ⊕ b`` to one self-contained HTML file.

    The page steps through the edge merge (Step, Back, Run/Pause with a speed, Reset, a
    slider, keys → ← space r), explains every decision with its cross product, logs the
    operations, lists the sum's vertices, and shows the configuration-space scene
    ``obstacle ⊕ (−robot)``. It needs no network and works opened from disk.

    Parameters
    ----------
    a, b : (n, 2) array_like
        Convex polygons (points and segments too).
    path : str or Path, default "animation.html"
        Where to write the page.
    obstacle, robot : (n, 2) array_like, optional
        The configuration-space scene (default: ``a`` and ``b``).
    hull : bool, default False
        Use the convex hulls of ``a`` and ``b``.
    title : str, optional
        The page title.

    Returns
    -------
    Path
        The file written. As the command line does, the page goes to a new, uniquely
        named temporary file beside ``path`` (``O_EXCL``), renamed into place once
        complete: an existing file is replaced whole or not at all, and a symlink
        planted at a temporary name is never followed.

    Raises
    ------
    GeometryError
        Bad or non-convex input, as :func:`minkowski2d.minkowski_sum`.
    OSError
        ``path`` is a directory or cannot be written (nothing is left behind).

    Examples
    --------
    >>> import minkowski2d as mk, tempfile, os
    >>> d = tempfile.mkdtemp()
    >>> p = mk.animate([(0, 0), (2, 0), (0, 2)], [(0, 0), (1, 0), (1, 1), (0, 1)],
    ...                path=os.path.join(d, "animation.html"))
    >>> p.name, p.stat().st_size > 10000
    ('animation.html', True)
    """
    from ..cli.common import CLIError, write_output

    page = render(a, b, obstacle=obstacle, robot=robot, hull=hull, title=title)
    try:
        return write_output(page, path)  # the command line's safe writer
    except CLIError as exc:
        raise OSError(f"{exc} ({exc.hint})" if exc.hint else str(exc)) from None


def write_demo_page(path: str | Path = "animation.html") -> Path:
    """Write the animation of the built-in example (triangle ⊕ unit square) to ``path``.

    Examples
    --------
    >>> import tempfile, os
    >>> write_demo_page(os.path.join(tempfile.mkdtemp(), "demo.html")).exists()
    True
    """
    return animate(
        SEED_A,
        SEED_B,
        path,
        title=DEMO_TITLE,
    )
