"""Drawing with matplotlib: ``mk.plot(obj, ax=None, **kwargs)``.

matplotlib (the ``plot`` extra) is imported when something is drawn, never by
``import minkowski2d``. ``plot`` draws

* one polygon: an (n, 2) array-like (a point as a dot, a segment as a line);
* many: a :class:`~minkowski2d.Ragged`, a list of polygons, a GeoSeries, a GeometryArray or
  a numpy array of shapely geometries (``None`` members are skipped);
* shapely geometries: polygons with holes, multi-polygons, lines, points, collections;
* a :class:`~minkowski2d.MergeTrace`: its operands, faint, and the sum's edges coloured by
  the polygon they come from (A, B, or both for a parallel pair), numbered in merge
  order;
* a nesting :class:`~minkowski2d.Layout`: its sheets side by side, outlined (keep-out
  zones hatched), the parts filled in one colour per part (``**kwargs`` style the parts);
* anything with a ``_plot_(ax, **kwargs)`` method (planner scenes and paths, offsets with
  arcs, ...): ``plot`` hands it the Axes; that is how other classes plug in.

It returns the Axes (a new figure's when ``ax`` is None), with equal aspect.
``**kwargs`` go to matplotlib (``facecolor``, ``edgecolor``, ``alpha``, ``label``,
``linewidth``, ...).

The module object is itself callable, so ``mk.plot(obj)`` works whether ``mk.plot`` is
this module (after ``import minkowski2d.plot``) or the function.

Examples
--------
>>> import matplotlib
>>> matplotlib.use("Agg")
>>> import minkowski2d as mk
>>> ax = mk.plot([(0, 0), (2, 0), (0, 2)], facecolor="tab:blue")
>>> ax = mk.plot(mk.minkowski_sum([(0, 0), (2, 0), (0, 2)], [(0, 0), (1, 0), (1, 1)]), ax=ax)
>>> len(ax.patches), ax.get_aspect()
(2, 1.0)
"""

from __future__ import annotations

import sys
import types
from typing import Any

import numpy as np

from ._engine.coerce import is_shapely

__all__ = ["plot", "SOURCE_COLORS"]

#: colours of the merge trace's edges by source
SOURCE_COLORS = {"A": "#1f77b4", "B": "#ff7f0e", "AB": "#9467bd"}
_FACE = "#4a90d9"
_EDGE = "#1f4e79"


def _axes(ax: Any) -> Any:
    if ax is not None:
        return ax
    import matplotlib.pyplot as plt

    _, ax = plt.subplots()
    return ax


def _finish(ax: Any) -> Any:
    ax.set_aspect("equal", adjustable="datalim")
    ax.autoscale_view()
    return ax


def plot(obj: Any, ax: Any = None, **kwargs: Any) -> Any:
    """Draw ``obj`` on ``ax`` (a new Axes when None) and return the Axes.

    Parameters
    ----------
    obj : polygon, Ragged, list of polygons, shapely geometry, GeoSeries, MergeTrace,
        Layout, or an object with a ``_plot_(ax, **kwargs)`` method
        What to draw (see the module docs).
    ax : matplotlib Axes, optional
        Where to draw; a new figure's Axes by default.
    **kwargs
        Passed to matplotlib: for polygons ``facecolor``, ``edgecolor``, ``alpha``,
        ``linewidth``, ``label``...

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import minkowski2d as mk
    >>> ax = mk.plot(mk.merge_trace([(0, 0), (2, 0), (0, 2)], [(0, 0), (1, 0), (1, 1), (0, 1)]))
    >>> sorted(t.get_text() for t in ax.get_legend().get_texts())
    ['A', 'A ⊕ B', 'B', 'edge of A', 'edge of B', 'parallel: both']
    """
    method = getattr(type(obj), "_plot_", None)
    if method is not None:
        ax = _axes(ax)
        res = method(obj, ax, **kwargs)
        return _finish(res if res is not None else ax)
    from .nesting.layout import Layout
    from .trace import MergeTrace

    if isinstance(obj, MergeTrace):
        new = ax is None
        ax = _axes(ax)
        _trace(obj, ax, **kwargs)
        if new:
            ax.figure.tight_layout()
        return _finish(ax)
    if isinstance(obj, Layout):
        ax = _axes(ax)
        _layout(obj, ax, **kwargs)
        return _finish(ax)
    ax = _axes(ax)
    for g in _geometries(obj):
        _draw_geom(g, ax, **kwargs)
        kwargs.pop("label", None)  # one legend entry for a collection
    return _finish(ax)


# --------------------------------------------------------------------------------------
# reading what to draw


def _is_shapely(x: Any) -> bool:
    return is_shapely(x)


def _geometries(obj: Any) -> list:
    """What to draw as a list of shapely geometries (or None)."""
    import shapely

    from .batch import Ragged

    if obj is None:
        return []
    if _is_shapely(obj):
        return [obj]
    if isinstance(obj, Ragged):
        return list(obj.to_shapely())
    mod = type(obj).__module__
    if mod.startswith(("geopandas", "pandas")):
        if hasattr(obj, "geometry"):
            obj = obj.geometry
        return [g for g in np.asarray(obj, dtype=object).ravel() if g is not None]
    if isinstance(obj, np.ndarray) and obj.dtype == object and obj.ndim != 2:
        return [g for g in obj.ravel() if g is not None]
    if isinstance(obj, (list, tuple)) and obj and (np.ndim(obj[0]) == 2 or _is_shapely(obj[0])):
        out = []
        for p in obj:
            out.extend(_geometries(p))
        return out
    a = np.asarray(obj, dtype=object)
    if a.ndim != 2 or a.shape[1] != 2 or not len(a):
        from .errors import ShapeError

        raise ShapeError(f"plot: cannot draw {type(obj).__name__} of shape {a.shape}")
    c = a.astype(np.float64)
    if len(c) == 1:
        return [shapely.Point(c[0])]
    if len(c) == 2:
        return [shapely.LineString(c)]
    return [shapely.Polygon(c)]


def _ring_path(poly: Any) -> Any:
    import shapely
    from matplotlib.path import Path

    poly = shapely.orient_polygons(poly) if hasattr(shapely, "orient_polygons") else poly
    verts = []
    codes = []
    for ring in [poly.exterior, *poly.interiors]:
        c = np.asarray(ring.coords)[:, :2]
        verts.append(c)
        codes.extend([Path.MOVETO] + [Path.LINETO] * (len(c) - 2) + [Path.CLOSEPOLY])
    return Path(np.concatenate(verts), codes)


def _draw_geom(g: Any, ax: Any, **kw: Any) -> None:
    if g is None or g.is_empty:
        return
    gt = g.geom_type
    if gt == "Polygon":
        from matplotlib.patches import PathPatch

        style = {"facecolor": _FACE, "edgecolor": _EDGE, "alpha": 0.6, "linewidth": 1.2}
        style.update(kw)
        ax.add_patch(PathPatch(_ring_path(g), **style))
    elif gt in ("LineString", "LinearRing"):
        c = np.asarray(g.coords)
        style = {"color": kw.pop("edgecolor", _EDGE), "linewidth": 1.5}
        style.update({k: v for k, v in kw.items() if k != "facecolor"})
        ax.plot(c[:, 0], c[:, 1], **style)
    elif gt == "Point":
        style = {"color": kw.pop("edgecolor", kw.pop("facecolor", _EDGE)), "s": 16}
        style.update({k: v for k, v in kw.items() if k not in ("facecolor", "linewidth")})
        ax.scatter([g.x], [g.y], zorder=3, **style)
    else:  # Multi* and collections
        for k, part in enumerate(g.geoms):
            _draw_geom(
                part, ax, **(kw if k == 0 else {x: v for x, v in kw.items() if x != "label"})
            )


# --------------------------------------------------------------------------------------
# the merge trace


def _fl(p: Any) -> tuple[float, float]:
    return float(p[0]), float(p[1])


def _trace(t: Any, ax: Any, **kw: Any) -> None:
    """Operands (A at its place, B at its place), the sum faint, the sum's edges as
    arrows coloured by source and numbered in merge order."""
    import shapely

    alpha = kw.pop("alpha", 0.25)
    for pts, color, name in ((t.a, SOURCE_COLORS["A"], "A"), (t.b, SOURCE_COLORS["B"], "B")):
        g = _geometries(np.array([_fl(p) for p in pts]))[0]
        _draw_geom(g, ax, facecolor=color, edgecolor=color, alpha=alpha, label=name)
    res = np.asarray([_fl(p) for p in t.vertices]) if t.steps else np.asarray([_fl(t.start)])
    if len(res) >= 3:
        _draw_geom(
            shapely.Polygon(res),
            ax,
            facecolor="#dddddd",
            edgecolor="none",
            alpha=0.5,
            label="A ⊕ B",
            zorder=0,
        )
    seen: set = set()
    for s in t.steps:
        color = SOURCE_COLORS[s.source]
        path = np.array([_fl(p) for p in s.path])
        label = {"A": "edge of A", "B": "edge of B", "AB": "parallel: both"}[s.source]
        for k in range(len(path) - 1):
            ax.annotate(
                "",
                xy=path[k + 1],
                xytext=path[k],
                arrowprops={
                    "arrowstyle": "-|>",
                    "color": color,
                    "lw": 2.2,
                    "shrinkA": 0,
                    "shrinkB": 0,
                },
            )
        ax.plot(
            path[:, 0], path[:, 1], color=color, lw=2.2, label=None if s.source in seen else label
        )
        seen.add(s.source)
        mid = (
            path[len(path) // 2 - 1 : len(path) // 2 + 1].mean(axis=0) if len(path) > 1 else path[0]
        )
        ax.annotate(
            str(s.index), mid, textcoords="offset points", xytext=(4, 4), fontsize=8, color=color
        )
    ax.plot(*_fl(t.start), "o", color="black", ms=4)
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=8, borderaxespad=0)
    ax.set_title(kw.pop("title", "merge of the edges of A and B, by angle"), fontsize=10)


# --------------------------------------------------------------------------------------
# a nesting layout


def _layout(lay: Any, ax: Any, **kw: Any) -> None:
    """The sheets side by side, outlined (keep-out zones grey, hatched), the parts filled
    in one colour per part (a legend of the part ids when there are at most 12); the
    offsets and colours of :mod:`minkowski2d.nesting.drawing` (the SVG's)."""
    import shapely

    from .nesting import drawing as dr

    sheets, polys = dr.side_by_side(lay)
    edge = {"edgecolor": dr.SHEET_EDGE, "alpha": 1.0, "linewidth": 1.2, "zorder": 0}
    keepout = {"facecolor": dr.KEEPOUT_FILL, "edgecolor": "#777777", "alpha": 1.0}
    keepout.update(linewidth=0.8, hatch="//", zorder=0.5)
    for k, s in enumerate(sheets):
        _draw_geom(shapely.Polygon(s.exterior), ax, facecolor=dr.SHEET_FILL, **edge)
        for ring in s.interiors:
            _draw_geom(shapely.Polygon(ring), ax, **keepout)
        if lay.strip_height is None:
            text = f"sheet {k}: {100 * lay.densities[k]:.1f} %"
            xy = s.bounds[:2]
            ax.annotate(text, xy, textcoords="offset points", xytext=(0, -12), fontsize=8)
    style = {"edgecolor": dr.PART_EDGE, "alpha": 0.85, "linewidth": 0.6}
    style.update(kw)
    legend = "label" not in kw and len({p.part for p in lay.placements}) <= 12
    seen: set = set()
    for p, g in zip(lay.placements, polys, strict=True):
        st = {"facecolor": dr.part_color(p.part), **style}
        if legend and p.part not in seen:
            st["label"] = lay.ids[p.part]
            seen.add(p.part)
        _draw_geom(g, ax, **st)
        style.pop("label", None)  # a label of the caller's: the first part only
    if legend and seen:
        ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=8, borderaxespad=0)
    if lay.strip_height is not None:
        where = f"strip {lay.length:g} x {lay.strip_height:g}"
    else:
        where = f"{lay.n_sheets} sheet{'s' if lay.n_sheets != 1 else ''}"
    ax.set_title(f"{where}, density {100 * lay.density:.1f} %", fontsize=10)


# the module is callable: ``mk.plot(obj)`` works even once ``mk.plot`` is this module


class _CallableModule(types.ModuleType):
    def __call__(self, obj: Any, ax: Any = None, **kwargs: Any) -> Any:
        return plot(obj, ax, **kwargs)


sys.modules[__name__].__class__ = _CallableModule
