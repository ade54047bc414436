"""mk.plot with matplotlib (the 'plot' extra) and MergeTrace's inline SVG. The PNGs go to
test-artifacts/ so a person can look at them."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import shapely

import minkowski2d as mk

ART = Path(__file__).resolve().parents[1] / "test-artifacts"
SQ = [(0, 0), (1, 0), (1, 1), (0, 1)]


@pytest.fixture
def plt():
    matplotlib = pytest.importorskip(
        "matplotlib", reason="matplotlib is not installed (extra 'plot')"
    )
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    yield plt
    plt.close("all")


def _pixel(ax, x, y):
    """RGBA of the rendered figure at data point (x, y)."""
    fig = ax.figure
    fig.canvas.draw()
    px, py = ax.transData.transform((x, y))
    img = np.asarray(fig.canvas.buffer_rgba())
    return img[img.shape[0] - int(round(py)), int(round(px))]


def test_polygon_with_hole_ragged_points_segments(plt):
    ART.mkdir(exist_ok=True)
    holed = shapely.box(0, 0, 10, 10).difference(shapely.box(3, 3, 6, 6))
    ax = mk.plot(holed, label="holed", facecolor="tab:blue", alpha=1.0)
    r = mk.minkowski_sum_many([[(12, 0), (14, 0), (13, 2)], [(12, 5), (15, 5), (15, 8)]], SQ)
    assert mk.plot(r, ax=ax, facecolor="tab:orange", label="sums") is ax
    mk.plot([(20, 0), (22, 3)], ax=ax)
    mk.plot([(20, 5)], ax=ax)
    ax.legend()
    ax.figure.savefig(ART / "plot_shapes.png", dpi=80)
    assert len(ax.patches) == 3 and ax.get_aspect() == 1.0
    # the hole is not filled, the ring is
    assert _pixel(ax, 4.5, 4.5)[:3].tolist() == [255, 255, 255]
    assert _pixel(ax, 1.5, 1.5)[:3].tolist() != [255, 255, 255]
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["holed", "sums"]


def test_geoseries_and_object_arrays(plt):
    gpd = pytest.importorskip("geopandas", reason="geopandas is not installed (extra 'geo')")
    gs = gpd.GeoSeries([shapely.box(0, 0, 1, 1), None, shapely.box(2, 0, 3, 1)], crs=3857)
    ax = mk.plot(mk.minkowski_sum_many(gs, SQ))
    assert len(ax.patches) == 2
    ax = mk.plot(
        np.array([shapely.box(0, 0, 1, 1), shapely.MultiPolygon([shapely.box(5, 5, 6, 6)])])
    )
    assert len(ax.patches) == 2


def test_merge_trace_edges_by_source(plt):
    ART.mkdir(exist_ok=True)
    t = mk.merge_trace([(0, 0), (4, 0), (5, 2), (1, 3)], [(0, 0), (2, 0), (2, 1), (0, 1)])
    ax = mk.plot(t)
    ax.figure.savefig(ART / "plot_merge_trace.png", dpi=80)
    labels = [x.get_text() for x in ax.get_legend().get_texts()]
    assert {"A", "B", "A ⊕ B", "edge of A", "edge of B", "parallel: both"} == set(labels)
    colors = {
        ln.get_label(): ln.get_color() for ln in ax.lines if not ln.get_label().startswith("_")
    }
    assert colors["edge of A"] != colors["edge of B"] != colors["parallel: both"]
    # every step of the merge is drawn: one numbered label per step
    nums = sorted(int(a.get_text()) for a in ax.texts if a.get_text().isdigit())
    assert nums == list(range(1, len(t.steps) + 1))


def test_repr_html_is_inline_svg():
    t = mk.merge_trace([(0, 0), (2, 0), (0, 2)], SQ)
    html = t._repr_html_()
    assert html.startswith("<div><svg") and "</svg>" in html
    assert html.count("<line") == sum(len(s.path) - 1 for s in t.steps)
    assert "step 2: a1 × b1 = -2 &lt; 0" in html  # the merge's own explanation, escaped


class _Scene:
    """Stands for the planner's scenes and the offsets with arcs (built elsewhere)."""

    def __init__(self):
        self.calls = []

    def _plot_(self, ax, **kw):
        self.calls.append(kw)
        ax.plot([0, 1], [0, 1])
        return ax


def test_objects_plug_in_with_plot_method(plt):
    s = _Scene()
    ax = mk.plot(s, color="red")
    assert s.calls == [{"color": "red"}] and len(ax.lines) == 1


def test_plot_is_callable_after_importing_the_module(plt):
    import minkowski2d.plot as module

    assert mk.plot is module and callable(mk.plot)
    assert mk.plot(SQ) is not None and module.plot(SQ) is not None
    with pytest.raises(mk.errors.ShapeError):
        mk.plot("not a polygon")


def test_offset_arcs_and_planner_plot_through_mk_plot(plt, tmp_path):
    L = [(0, 0), (4, 0), (4, 1), (1, 1), (1, 3), (0, 3)]
    ax = mk.plot(mk.offset_arcs(L, 0.6))
    colors = {
        tuple(line.get_color()) if not isinstance(line.get_color(), str) else line.get_color()
        for line in ax.get_lines()
    }
    assert {"C0", "C3"} <= colors  # straight pieces and arcs drawn apart
    ax.figure.savefig(tmp_path / "arcs.png")
    obstacles = [[(2, 0), (4, 0), (4, 3), (2, 3)], [(2, 4), (4, 4), (4, 8), (2, 8)]]
    planner = mk.MotionPlanner(obstacles, [(0, 0), (1, 0), (1, 1), (0, 1)], workspace=(0, 0, 8, 8))
    path = planner.shortest_path((0, 2), (6, 2))
    ax = mk.plot(planner, path=path)
    assert ax.get_lines()  # the path
    assert len(ax.patches) + len(ax.collections) >= 2  # obstacles and C-obstacles
    ax.figure.savefig(tmp_path / "planner.png")
    assert mk.plot(path).get_lines()
