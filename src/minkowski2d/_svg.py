"""A merge trace as a small inline SVG (``MergeTrace._repr_html_``, for Jupyter).

Plain text, no matplotlib: the operands faint, the sum's edges as arrows coloured by the
polygon they come from (the colours of :mod:`minkowski2d.plot`), numbered in merge order.

Examples
--------
>>> import minkowski2d as mk
>>> t = mk.merge_trace([(0, 0), (2, 0), (0, 2)], [(0, 0), (1, 0), (1, 1), (0, 1)])
>>> html = t._repr_html_()
>>> html.startswith("<div><svg"), html.count("<line"), "edge of B" in html
(True, 7, True)
"""

from __future__ import annotations

from html import escape
from typing import Any

__all__ = ["trace_svg"]

_COLORS = {"A": "#1f77b4", "B": "#ff7f0e", "AB": "#9467bd"}
_NAMES = {"A": "edge of A", "B": "edge of B", "AB": "parallel: both"}


def _fl(p: Any) -> tuple[float, float]:
    return float(p[0]), float(p[1])


def trace_svg(t: Any, size: int = 360) -> str:
    """The trace ``t`` as ``<div><svg>...</svg></div>`` (y up, equal aspect)."""
    a = [_fl(p) for p in t.a]
    b = [_fl(p) for p in t.b]
    verts = [_fl(p) for p in t.vertices] if t.steps else [_fl(t.start)]
    pts = a + b + verts
    xs = [p[0] for p in pts]
    ys = [p[1] for p in pts]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    span = max(x1 - x0, y1 - y0) or 1.0
    x0 -= (span - (x1 - x0)) / 2  # centre the drawing in the square
    y0 -= (span - (y1 - y0)) / 2
    pad = 0.08 * span
    scale = (size - 20) / (span + 2 * pad)

    def xy(p: tuple[float, float]) -> tuple[float, float]:
        return (10 + (p[0] - x0 + pad) * scale, size - 10 - (p[1] - y0 + pad) * scale)

    def poly(ps: list, fill: str, opacity: float) -> str:
        if len(ps) == 1:
            x, y = xy(ps[0])
            return f'<circle cx="{x:.2f}" cy="{y:.2f}" r="3" fill="{fill}"/>'
        d = " ".join(f"{x:.2f},{y:.2f}" for x, y in map(xy, ps))
        tag = "polyline" if len(ps) == 2 else "polygon"
        return (
            f'<{tag} points="{d}" fill="{fill if tag == "polygon" else "none"}" '
            f'fill-opacity="{opacity}" stroke="{fill}" stroke-opacity="0.6"/>'
        )

    parts = [poly(verts, "#bbbbbb", 0.35), poly(a, _COLORS["A"], 0.25), poly(b, _COLORS["B"], 0.25)]
    for s in t.steps:
        c = _COLORS[s.source]
        path = [xy(_fl(p)) for p in s.path]
        for (px, py), (qx, qy) in zip(path, path[1:]):
            parts.append(
                f'<line x1="{px:.2f}" y1="{py:.2f}" x2="{qx:.2f}" y2="{qy:.2f}" stroke="{c}" '
                f'stroke-width="2.5" marker-end="url(#mk-{s.source})">'
                f"<title>{escape(f'step {s.index}: {s.why}')}</title></line>"
            )
        mx = sum(p[0] for p in path) / len(path)
        my = sum(p[1] for p in path) / len(path)
        parts.append(
            f'<text x="{mx + 4:.2f}" y="{my - 4:.2f}" font-size="11" fill="{c}">{s.index}</text>'
        )
    markers = "".join(
        f'<marker id="mk-{k}" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="6" '
        f'markerHeight="6" orient="auto-start-reverse"><path d="M 0 0 L 10 5 L 0 10 z" '
        f'fill="{c}"/></marker>'
        for k, c in _COLORS.items()
    )
    legend = " ".join(
        f'<span style="color:{c}">&#9632; {_NAMES[k]}</span>' for k, c in _COLORS.items()
    )
    body = "\n".join(parts)
    return (
        f'<div><svg xmlns="http://www.w3.org/2000/svg" width="{size}" height="{size}" '
        f'viewBox="0 0 {size} {size}"><defs>{markers}</defs>\n{body}\n</svg>'
        f'<div style="font-size:12px">A ⊕ B by merging edges by angle: {legend}; '
        f"result {escape(str(t.result.tolist()))}</div></div>"
    )
