"""Drawing a :class:`~minkowski2d.nesting.layout.Layout`: the sheets side by side, outlined
(keep-out zones grey), the parts filled, one colour per part.

:func:`side_by_side` places the sheets (the first at its own coordinates, each next one to
the right of the one before, a gap between); :func:`layout_svg` and :func:`layout_dxf`
draw that, and so does :func:`minkowski2d.plot` (the same offsets and :func:`part_color`).

Examples
--------
>>> import shapely, minkowski2d as mk
>>> box = shapely.box(0, 0, 4, 2)
>>> lay = mk.Layout([shapely.box(0, 0, 1, 1)], [mk.Placement(0, 0, 1, 0, (0.0, 0.0))],
...                 [box, box], kinds=[0, 0])
>>> sheets, parts = side_by_side(lay)
>>> [s.bounds for s in sheets], parts[0].bounds
([(0.0, 0.0, 4.0, 2.0), (4.0625, 0.0, 8.0625, 2.0)], (4.0625, 0.0, 5.0625, 1.0))
"""

from __future__ import annotations

import colorsys
import io
import math
from html import escape
from typing import Any

import numpy as np

__all__ = ["part_color", "side_by_side", "sheet_offsets", "layout_svg", "layout_dxf"]

#: matplotlib's tab10: the first ten part colours
_TAB10 = (
    "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
    "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf",
)  # fmt: skip
SHEET_FILL = "#f7f7f2"
SHEET_EDGE = "#333333"
KEEPOUT_FILL = "#c8c8c8"
PART_EDGE = "#222222"


def part_color(i: int) -> str:
    """The colour of part ``i`` (``#rrggbb``): tab10 for the first ten, then hues a
    golden angle apart.

    Examples
    --------
    >>> part_color(0), part_color(10)
    ('#1f77b4', '#cad454')
    """
    if i < len(_TAB10):
        return _TAB10[i]
    h = (i * 0.6180339887498949) % 1.0
    r, g, b = colorsys.hls_to_rgb(h, 0.58, 0.6)
    return f"#{round(r * 255):02x}{round(g * 255):02x}{round(b * 255):02x}"


def sheet_offsets(lay: Any) -> list[float]:
    """Per sheet, the x offset that puts it to the right of the one before (the first at
    0), a gap between: a power of two near 1/40 of the largest sheet side."""
    b = [s.bounds for s in lay.sheets]
    if not b:
        return []
    size = max(max(y1 - y0 for _, y0, _, y1 in b), max(x1 - x0 for x0, _, x1, _ in b))
    gap = 2.0 ** math.floor(math.log2(size / 40)) if size > 0 else 1.0
    out = [0.0]
    right = b[0][2]
    for x0, _, x1, _ in b[1:]:
        out.append(right + gap - x0)
        right = x1 + out[-1]
    return out


def side_by_side(lay: Any) -> tuple[list, list]:
    """(sheets, placed parts) as shapely Polygons, each sheet and its parts moved by its
    :func:`sheet_offsets` offset."""
    import shapely

    dx = sheet_offsets(lay)
    sheets = [_shifted(s, d) for s, d in zip(lay.sheets, dx, strict=True)]
    polys = lay.polygons()
    if len(polys):
        shift = np.array([dx[p.sheet] for p in lay.placements], dtype=np.float64)
        counts = shapely.get_num_coordinates(polys)
        per = np.repeat(shift, counts)
        polys = shapely.transform(polys, lambda c: c + np.stack([per, 0 * per], axis=-1))
    return sheets, list(polys)


def _shifted(g: Any, dx: float) -> Any:
    import shapely

    return g if dx == 0 else shapely.transform(g, lambda c: c + (dx, 0.0))


# --------------------------------------------------------------------------------------
# SVG


def _n(v: float) -> str:
    r = repr(float(v) + 0.0)  # no "-0"
    return r[:-2] if r.endswith(".0") else r


def _path(g: Any) -> str:
    """The SVG path data of a polygon's rings (y negated: the drawing's y is up)."""
    out = []
    for ring in [g.exterior, *g.interiors]:
        c = np.asarray(ring.coords)[:-1, :2]
        out.append("M " + " L ".join(f"{_n(x)} {_n(-y)}" for x, y in c.tolist()) + " Z")
    return " ".join(out)


def _label(lay: Any, k: int) -> str:
    d = lay.densities[k]
    if lay.strip_height is not None:
        return f"strip {lay.length:g} x {lay.strip_height:g}: density {100 * d:.1f} %"
    return f"sheet {k}: density {100 * d:.1f} %"


def layout_svg(lay: Any, width: int = 800) -> str:
    """:meth:`Layout.svg`: a standalone SVG document ``width`` pixels wide (at most as
    tall), one ``<path class="sheet">`` per sheet, ``class="keepout"`` per keep-out zone,
    ``class="part"`` per placement (its ``<title>``: part id, copy, rotation)."""
    import shapely

    sheets, polys = side_by_side(lay)
    geoms = [g for g in [*sheets, *polys] if not g.is_empty]
    if not geoms:
        return '<svg xmlns="http://www.w3.org/2000/svg" width="0" height="0"></svg>'
    x0, y0, x1, y1 = shapely.total_bounds(geoms).tolist()
    w, h = max(x1 - x0, 1e-300), max(y1 - y0, 1e-300)
    pad = 0.02 * max(w, h)
    vw = w + 2 * pad
    font = 13 * vw / width  # 13 pixels when the drawing is as wide as ``width``
    vh = h + 2 * pad + 1.6 * font
    px_w = float(width)
    px_h = px_w * vh / vw
    if px_h > width:
        px_w, px_h = px_w * width / px_h, float(width)
    unit = vw / px_w  # one pixel in drawing units
    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{_n(x0 - pad)} {_n(-(y1 + pad))} '
        f'{_n(vw)} {_n(vh)}" width="{px_w:.0f}" height="{px_h:.0f}" '
        'font-family="sans-serif">',
        f"<title>{escape(repr(lay))}</title>",
        f'<g fill="{SHEET_FILL}" fill-rule="evenodd" stroke="{SHEET_EDGE}" '
        f'stroke-width="{_n(1.5 * unit)}">',
    ]
    out += [f'<path class="sheet" d="{_path(s)}"/>' for s in sheets]
    out.append("</g>")
    holes = [shapely.Polygon(r) for s in sheets for r in s.interiors]
    if holes:
        out.append(
            f'<g fill="{KEEPOUT_FILL}" stroke="{SHEET_EDGE}" stroke-width="{_n(unit)}" '
            f'stroke-dasharray="{_n(4 * unit)} {_n(2 * unit)}">'
        )
        out += [f'<path class="keepout" d="{_path(g)}"/>' for g in holes]
        out.append("</g>")
    out.append(
        f'<g fill-rule="evenodd" fill-opacity="0.85" stroke="{PART_EDGE}" '
        f'stroke-width="{_n(0.6 * unit)}" stroke-linejoin="round">'
    )
    for p, g in zip(lay.placements, polys, strict=True):
        tip = f"{lay.ids[p.part]} copy {p.copy}, rotation {p.rotation}"
        out.append(
            f'<path class="part" fill="{part_color(p.part)}" d="{_path(g)}">'
            f"<title>{escape(tip)}</title></path>"
        )
    out.append(f'</g><g font-size="{_n(font)}" fill="{SHEET_EDGE}">')
    for k, s in enumerate(sheets):
        sx0, sy0 = s.bounds[0], s.bounds[1]
        out.append(
            f'<text x="{_n(sx0)}" y="{_n(-sy0 + 1.2 * font)}">{escape(_label(lay, k))}</text>'
        )
    out.append("</g></svg>")
    return "\n".join(out)


# --------------------------------------------------------------------------------------
# DXF


def layout_dxf(lay: Any) -> str:
    """The text of a DXF drawing (R2010): every ring a closed LWPOLYLINE, the sheets on
    layer ``SHEETS``, the parts on layer ``PARTS`` (each in its part's colour), the
    sheets side by side (:func:`side_by_side`); exteriors counter-clockwise, holes
    clockwise.

    Raises
    ------
    ImportError
        ezdxf is not installed.
    """
    import shapely

    try:
        import ezdxf
        from ezdxf import colors
    except ImportError:
        raise ImportError("DXF output needs ezdxf (hint: pip install 'minkowski2d[dxf]')") from None
    sheets, polys = side_by_side(lay)
    doc = ezdxf.new("R2010")
    doc.layers.add("SHEETS", color=7)
    doc.layers.add("PARTS", color=5)
    msp = doc.modelspace()

    def add(g: Any, attribs: dict) -> None:
        for ring in shapely.get_rings(shapely.orient_polygons(g)):
            c = shapely.get_coordinates(ring)[:-1]
            msp.add_lwpolyline([tuple(p) for p in c.tolist()], close=True, dxfattribs=attribs)

    for s in sheets:
        add(s, {"layer": "SHEETS"})
    for p, g in zip(lay.placements, polys, strict=True):
        c = part_color(p.part)
        rgb = (int(c[1:3], 16), int(c[3:5], 16), int(c[5:7], 16))
        add(g, {"layer": "PARTS", "true_color": colors.rgb2int(rgb)})
    buf = io.StringIO()
    doc.write(buf)
    return buf.getvalue()
