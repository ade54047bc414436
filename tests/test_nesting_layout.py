"""Layout and Placement: the data model, its measures, the placed polygons, the
files (JSON and GeoJSON round trips, SVG, DXF) and the drawing, on hand-made layouts."""

from __future__ import annotations

import json
import os
import xml.etree.ElementTree as ET
from fractions import Fraction

import numpy as np
import pytest
import shapely

import minkowski2d as mk
from minkowski2d.errors import (
    EmptyGeometryError,
    GeometryError,
    InputFormatError,
    LayoutError,
    OptionError,
    ShapeError,
)
from minkowski2d.nesting.drawing import part_color, sheet_offsets, side_by_side

L_SHAPE = shapely.Polygon([(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)])
FRAME = shapely.Polygon(
    [(0, 0), (1, 0), (1, 1), (0, 1)], [[(0.25, 0.25), (0.75, 0.25), (0.75, 0.75), (0.25, 0.75)]]
)
P = mk.Placement


def strip_layout() -> mk.Layout:
    """An L, a second L turned 180 degrees, a framed square turned 90: a full 4 x 2 strip
    but the frame's hole and the square above it."""
    places = [P(0, 0, 0, 0, (0.0, 0.0)), P(0, 1, 0, 180, (3.0, 2.0)), P(1, 0, 0, 90, (4.0, 0.0))]
    return mk.Layout(
        [L_SHAPE, FRAME],
        places,
        [shapely.box(0, 0, 4, 2)],
        strip_height=2,
        ids=["L", "frame"],
        name="strip",
    )


def sheets_layout() -> mk.Layout:
    """Two sheets of two kinds (the second with a keep-out zone), a Fraction, a float and
    a free rotation, a fixed part, spacing and margin."""
    keepout = shapely.Polygon([(0, 0), (6, 0), (6, 3), (0, 3)], [[(4, 1), (5, 1), (5, 2), (4, 2)]])
    places = [
        P(0, 0, 0, 0, (0.5, 0.5)),
        P(0, 1, 0, Fraction(1, 3), (3.5, 0.5)),
        P(1, 0, 1, 90.0, (1.5, 0.5)),
        P(1, 1, 1, 30, (2.25, 1.5), fixed=True),
    ]
    return mk.Layout(
        [L_SHAPE, FRAME],
        places,
        [shapely.box(0, 0, 6, 3), keepout],
        kinds=[0, 1],
        spacing=0.125,
        margin=0.25,
        ids=["L", "frame"],
    )


def coords(g) -> list:
    return shapely.get_coordinates(g).tolist()


# --------------------------------------------------------------------------------------
# the data model


def test_placement_normalizes_numbers():
    p = P(np.int64(1), 0, np.int32(2), np.int64(90), (np.float64(0.5), 3))
    assert p == P(1, 0, 2, 90, (0.5, 3.0))
    assert type(p.part) is int and type(p.rotation) is int
    assert all(type(v) is float for v in p.translation)
    assert hash(p) == hash(P(1, 0, 2, 90, (0.5, 3.0)))
    assert P(0, 0, 0, Fraction(1, 3), (0, 0)).rotation == Fraction(1, 3)


@pytest.mark.parametrize(
    "kw, field",
    [
        ({"part": -1}, "part"),
        ({"copy": 1.0}, "copy"),
        ({"sheet": True}, "sheet"),
        ({"rotation": float("nan")}, "rotation"),
        ({"rotation": "90"}, "rotation"),
        ({"translation": (0.0,)}, "translation"),
        ({"translation": "xy"}, "translation"),
        ({"translation": (Fraction(1, 3), 0)}, "translation"),
        ({"translation": (2**53 + 1, 0)}, "translation"),
        ({"translation": (float("inf"), 0)}, "translation"),
        ({"fixed": 1}, "fixed"),
    ],
)
def test_placement_refuses_bad_fields(kw, field):
    args = {"part": 0, "copy": 0, "sheet": 0, "rotation": 0, "translation": (0.0, 0.0)}
    args.update(kw)
    with pytest.raises(GeometryError) as e:
        P(**args)
    assert e.value.argument == field


def test_layout_takes_rings_and_checks_its_arguments():
    lay = mk.Layout(
        [[(0, 0), (2, 0), (0, 2)]], [P(0, 0, 0, 0, (0, 0))], [[(0, 0), (3, 0), (3, 3), (0, 3)]]
    )
    assert lay.parts[0].geom_type == "Polygon" and coords(lay.parts[0])[:3] == [
        [0, 0],
        [2, 0],
        [0, 2],
    ]
    assert lay.ids == ("0",) and lay.kinds is None and lay.name is None
    sheet = [shapely.box(0, 0, 3, 3)]
    bad = [
        (dict(parts=[shapely.LineString([(0, 0), (1, 1)])]), ShapeError, "parts[0]"),
        (dict(parts=[shapely.Polygon()]), EmptyGeometryError, "parts[0]"),
        (dict(parts=[[(0, 0), (1, 0)]]), ShapeError, "parts[0]"),
        (dict(placements=[P(1, 0, 0, 0, (0, 0))]), OptionError, "placements[0]"),
        (dict(placements=[P(0, 0, 1, 0, (0, 0))]), OptionError, "placements[0]"),
        (dict(placements=[(0, 0, 0, 0, (0, 0))]), OptionError, "placements[0]"),
        (dict(sheets=sheet * 2, strip_height=3), OptionError, "strip_height"),
        (dict(strip_height=-1), OptionError, "strip_height"),
        (dict(kinds=[0, 1]), OptionError, "kinds"),
        (dict(ids=["a", "b"]), OptionError, "ids"),
        (dict(spacing=-0.5), OptionError, "spacing"),
        (dict(name=3), OptionError, "name"),
    ]
    for kw, cls, arg in bad:
        args = dict(parts=[L_SHAPE], placements=[], sheets=sheet)
        args.update(kw)
        with pytest.raises(cls) as e:
            mk.Layout(args.pop("parts"), args.pop("placements"), args.pop("sheets"), **args)
        assert e.value.argument == arg, kw


def test_measures_of_a_strip():
    lay = strip_layout()
    assert (lay.n_sheets, lay.length, lay.strip_height) == (1, 4.0, 2.0)
    # 2 L's of area 3, a frame of area 0.75, on 4 x 2
    assert lay.densities == [6.75 / 8] and lay.density == 6.75 / 8
    assert "strip 4 x 2" in repr(lay) and "'strip'" in repr(lay)


def test_measures_of_sheets():
    lay = sheets_layout()
    assert lay.n_sheets == 2 and lay.kinds == (0, 1)
    turned = mk.rotate_part(FRAME, 30)
    right = max(turned.bounds[2] + 2.25, 1.5)  # the free rotation, or the 90 at 0.5..1.5
    assert lay.length == right + 0.25
    assert lay.densities == [6 / 18, 1.5 / 17]
    assert lay.density == 7.5 / 35
    # the length is capped by the sheet, and 0 for an empty last sheet
    far = mk.Layout([L_SHAPE], [P(0, 0, 0, 0, (4.0, 1.0))], [shapely.box(0, 0, 6, 3)], margin=1)
    assert far.length == 6.0
    empty = mk.Layout([L_SHAPE], [P(0, 0, 0, 0, (0.0, 0.0))], [shapely.box(0, 0, 6, 3)] * 2)
    assert empty.length == 0.0 and empty.densities == [3 / 18, 0.0]


def test_a_layout_of_nothing():
    lay = mk.Layout([L_SHAPE], [], [])
    assert (lay.n_sheets, lay.length, lay.density, lay.densities) == (0, 0.0, 0.0, [])
    assert len(lay.polygons()) == 0
    assert mk.read_layout(lay.write(os.path.join(_tmp(), "empty.json"))) == lay
    ET.fromstring(lay.svg())


def _tmp() -> str:
    import tempfile

    return tempfile.mkdtemp()


# --------------------------------------------------------------------------------------
# placed polygons


@pytest.mark.parametrize(
    "angle, expected",
    [
        (0, [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]),
        (90, [(0, 0), (0, 2), (-1, 2), (-1, 1), (-2, 1), (-2, 0)]),
        (180, [(0, 0), (-2, 0), (-2, -1), (-1, -1), (-1, -2), (0, -2)]),
        (Fraction(-90), [(0, 0), (0, -2), (1, -2), (1, -1), (2, -1), (2, 0)]),
        (450.0, [(0, 0), (0, 2), (-1, 2), (-1, 1), (-2, 1), (-2, 0)]),
    ],
)
def test_polygons_are_exact_for_quarter_turns(angle, expected):
    t = (0.1, 1e-300)  # not dyadic, and tiny: each coordinate the float sum
    lay = mk.Layout([L_SHAPE], [P(0, 0, 0, angle, t)], [shapely.box(-5, -5, 5, 5)])
    got = shapely.get_coordinates(lay.polygons()[0])[:-1]
    want = np.array(expected, dtype=np.float64) + np.array(t)
    assert got.tolist() == want.tolist()


def test_polygons_of_free_rotations_and_holes():
    lay = sheets_layout()
    g = lay.polygons()
    assert g.dtype == object and len(g) == 4
    for p, poly in zip(lay.placements, g, strict=True):
        want = shapely.transform(
            mk.rotate_part(lay.parts[p.part], p.rotation), lambda c, p=p: c + p.translation
        )
        assert shapely.to_wkb(poly) == shapely.to_wkb(want)
    assert len(g[2].interiors) == 1
    g[0] = None  # a copy: the layout's own array is untouched
    assert lay.polygons()[0] is not None


def test_frame():
    pytest.importorskip("geopandas")
    df = sheets_layout().frame()
    assert list(df.columns) == [
        "part",
        "id",
        "copy",
        "sheet",
        "rotation",
        "x",
        "y",
        "fixed",
        "geometry",
    ]
    assert df["id"].tolist() == ["L", "L", "frame", "frame"] and df["fixed"].tolist()[-1]
    assert df.geometry.iloc[2].equals(sheets_layout().polygons()[2])


# --------------------------------------------------------------------------------------
# the certificate


def test_verify_passes_and_names_the_first_violation():
    assert strip_layout().verify() is True
    bad = mk.Layout(
        [L_SHAPE, FRAME],
        [P(0, 0, 0, 0, (0.0, 0.0)), P(1, 3, 0, 0, (0.5, 0.5))],
        [shapely.box(0, 0, 4, 2)],
        strip_height=2,
        ids=["L", "frame"],
    )
    with pytest.raises(LayoutError) as e:
        bad.verify()
    assert e.value.argument == "placements[0], placements[1]"
    assert "'L', copy 0" in str(e.value) and "'frame', copy 3" in str(e.value)
    assert isinstance(e.value, GeometryError)


# --------------------------------------------------------------------------------------
# files


@pytest.mark.parametrize("make", [strip_layout, sheets_layout])
@pytest.mark.parametrize("suffix", [".json", ".geojson"])
def test_round_trip_is_equal(tmp_path, make, suffix):
    lay = make()
    path = lay.write(tmp_path / f"layout{suffix}")
    back = mk.read_layout(path)
    assert back == lay
    assert [type(p.rotation) for p in back.placements] == [type(p.rotation) for p in lay.placements]
    assert back.length == lay.length and back.densities == lay.densities
    assert os.listdir(tmp_path) == [f"layout{suffix}"]  # no temporary file left


def test_round_trip_keeps_every_float(tmp_path):
    odd = [0.1 + 0.2, 5e-324, -0.0, 1.5e300, 2.0**-1074 * 3]
    lay = mk.Layout(
        [shapely.Polygon([(odd[0], 0), (1, odd[1]), (1, 1)])],
        [P(0, k, 0, 1e-7, (x, -x)) for k, x in enumerate(odd)],
        [shapely.box(-2e300, -2e300, 2e300, 2e300)],
        spacing=odd[0],
        margin=odd[4],
    )
    for suffix in (".json", ".geojson"):
        back = mk.read_layout(lay.write(tmp_path / f"odd{suffix}"))
        assert back == lay
        assert [p.translation for p in back.placements] == [p.translation for p in lay.placements]


def test_equality_looks_at_everything():
    a = strip_layout()
    assert a == strip_layout() and a != "layout"
    other = mk.Layout(a.parts, a.placements[:2], a.sheets, strip_height=2, ids=a.ids, name="strip")
    assert a != other
    moved = [P(0, 0, 0, 0, (0.0, 0.0)), P(0, 1, 0, 180, (3.0, 2.0)), P(1, 0, 0, 90.0, (4.0, 0.0))]
    assert a != mk.Layout(a.parts, moved, a.sheets, strip_height=2, ids=a.ids, name="strip")


def test_json_document():
    d = sheets_layout().to_dict()
    text = json.dumps(d, allow_nan=False)
    assert d["type"] == "minkowski2d.Layout" and d["version"] == 1
    assert [p["rotation"] for p in d["placements"]] == [0, "1/3", 90.0, 30]
    assert d["sheets"][1]["kind"] == 1 and len(d["sheets"][1]["geometry"]["coordinates"]) == 2
    assert mk.Layout.from_dict(json.loads(text)) == sheets_layout()


def test_geojson_features():
    lay = sheets_layout()
    fc = lay.to_geojson()
    kinds = [f["properties"]["kind"] for f in fc["features"]]
    assert kinds == ["sheet", "sheet", "part", "part", "part", "part"]
    part = fc["features"][3]["properties"]
    assert part == {
        "kind": "part",
        "placement": 1,
        "part": 0,
        "id": "L",
        "copy": 1,
        "sheet": 0,
        "rotation": "1/3",
        "x": 3.5,
        "y": 0.5,
        "fixed": False,
    }
    g = shapely.from_geojson(json.dumps(fc["features"][4]["geometry"]))
    assert shapely.to_wkb(g) == shapely.to_wkb(lay.polygons()[2])
    assert fc["features"][1]["properties"]["sheet_kind"] == 1


def test_geojson_placements_are_read_in_their_order(tmp_path):
    lay = sheets_layout()
    fc = lay.to_geojson()
    fc["features"] = fc["features"][::-1]
    path = tmp_path / "shuffled.geojson"
    path.write_text(json.dumps(fc))
    assert mk.read_layout(path) == lay


@pytest.mark.parametrize(
    "text, where",
    [
        ("{not json", "not JSON"),
        ("[1, 2]", "type"),
        ('{"type": "minkowski2d.Layout"}', "'parts'"),
        ('{"type": "FeatureCollection", "features": []}', "'layout'"),
    ],
)
def test_read_layout_names_what_is_wrong(tmp_path, text, where):
    path = tmp_path / "bad.json"
    path.write_text(text)
    with pytest.raises(InputFormatError, match=where) as e:
        mk.read_layout(path)
    assert e.value.argument == str(path)


def test_read_layout_names_a_bad_field(tmp_path):
    d = sheets_layout().to_dict()
    cases = [
        (("placements", 2, "part"), "x", r"placements\[2\]\.part"),
        (("placements", 1, "rotation"), "1/0", r"placements\[1\]\.rotation"),
        (("placements", 0, "translation"), [0.0], "translation"),
        (("placements", 0, "part"), 7, r"placements\[0\]"),
        (("sheets", 0, "geometry", "coordinates"), [[[0, 0], [1]]], r"sheets\[0\]\.geometry"),
        (("parts", 1, "geometry", "type"), "Point", r"parts\[1\]"),
        (("spacing",), -1, "spacing"),
    ]
    for keys, value, pattern in cases:
        bad = json.loads(json.dumps(d))
        node = bad
        for k in keys[:-1]:
            node = node[k]
        node[keys[-1]] = value
        path = tmp_path / "bad.json"
        path.write_text(json.dumps(bad))
        with pytest.raises(InputFormatError, match=pattern):
            mk.read_layout(path)


def test_bad_paths(tmp_path):
    lay = strip_layout()
    with pytest.raises(InputFormatError, match="no such file"):
        mk.read_layout(tmp_path / "missing.json")
    with pytest.raises(InputFormatError, match="directory"):
        mk.read_layout(tmp_path)
    with pytest.raises(InputFormatError, match="drawings are not read back"):
        mk.read_layout(lay.write(tmp_path / "l.svg"))
    with pytest.raises(InputFormatError, match="suffix"):
        lay.write(tmp_path / "layout.png")
    with pytest.raises(InputFormatError, match="directory"):
        lay.write(tmp_path, format="json")
    with pytest.raises(InputFormatError, match="cannot write"):
        lay.write(tmp_path / "no" / "such" / "dir.json")
    with pytest.raises(OptionError) as e:
        lay.write(tmp_path / "layout.json", format="png")
    assert e.value.argument == "format"
    assert sorted(os.listdir(tmp_path)) == ["l.svg"]  # nothing else, no temporary file
    # the format argument wins over the suffix
    lay.write(tmp_path / "layout.txt", format="geojson")
    assert mk.read_layout(tmp_path / "layout.txt") == lay


def test_svg_is_xml_with_one_path_per_thing():
    ns = {"s": "http://www.w3.org/2000/svg"}
    lay = sheets_layout()
    root = ET.fromstring(lay.svg())
    paths = root.findall(".//s:path", ns)
    classes = [p.get("class") for p in paths]
    assert classes.count("sheet") == 2 and classes.count("keepout") == 1
    assert classes.count("part") == 4
    fills = [p.get("fill") for p in paths if p.get("class") == "part"]
    assert fills == [part_color(0), part_color(0), part_color(1), part_color(1)]
    titles = [p.find("s:title", ns).text for p in paths if p.get("class") == "part"]
    assert titles[1] == "L copy 1, rotation 1/3"
    assert [t.text for t in root.findall(".//s:text", ns)][1].startswith("sheet 1")
    assert float(root.get("width")) <= 800 and float(root.get("height")) <= 800
    html = lay._repr_html_()
    assert html.startswith("<div><svg") and "density" in html


def test_dxf_reads_back_with_ezdxf(tmp_path):
    ezdxf = pytest.importorskip("ezdxf")
    lay = sheets_layout()
    doc = ezdxf.readfile(str(lay.write(tmp_path / "layout.dxf")))
    lines = list(doc.modelspace().query("LWPOLYLINE"))
    assert all(e.closed for e in lines)
    by_layer = {"SHEETS": [], "PARTS": []}
    for e in lines:
        by_layer[e.dxf.layer].append(sorted((x, y) for x, y in e.get_points("xy")))
    sheets, polys = side_by_side(lay)
    want = {"SHEETS": sheets, "PARTS": polys}
    for layer, geoms in want.items():
        rings = [r for g in geoms for r in shapely.get_rings(g)]
        expected = sorted(
            sorted(map(tuple, shapely.get_coordinates(r)[:-1].tolist())) for r in rings
        )
        assert sorted(by_layer[layer]) == expected, layer
    assert len(by_layer["SHEETS"]) == 3 and len(by_layer["PARTS"]) == 6  # rings: 2 + 1, 2 + 2 * 2


def test_sheets_side_by_side():
    lay = sheets_layout()
    dx = sheet_offsets(lay)
    assert dx[0] == 0.0 and dx[1] == 6.0 + 0.125  # a gap of 2**-3 near 6 / 40
    sheets, polys = side_by_side(lay)
    assert sheets[1].bounds == (6.125, 0.0, 12.125, 3.0)
    assert polys[2].bounds[0] == lay.polygons()[2].bounds[0] + 6.125


def test_plot_returns_axes():
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    lay = sheets_layout()
    ax = mk.plot(lay)
    try:
        # two sheet outlines, one keep-out zone, four parts
        assert len(ax.patches) == 7
        assert [t.get_text() for t in ax.get_legend().get_texts()] == ["L", "frame"]
        assert "2 sheets" in ax.get_title()
        x0, x1 = ax.get_xlim()
        assert x0 <= 0 and x1 >= 12.125
        ax2 = mk.plot(strip_layout(), ax=plt.subplots()[1], facecolor="red")
        assert all(p.get_facecolor()[:3] == (1.0, 0.0, 0.0) for p in ax2.patches[1:])
    finally:
        plt.close("all")
