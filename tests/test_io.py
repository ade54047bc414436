"""minkowski2d.io: readers (JSON, GeoJSON, WKT, CGAL .dat) and writers."""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

from minkowski2d.errors import (
    EmptyGeometryError,
    InputFormatError,
    OverflowGeometryError,
    ShapeError,
)
from minkowski2d.io import (
    UnboundedPolygon,
    format_geometry,
    parse_cgal_dat,
    parse_geometry,
    read_cgal_dat,
    read_geometry,
)

from .corpus import CORPUS as DATA
from .corpus import requires_corpus


def test_json_points_keep_ints_exact():
    p = parse_geometry("[[0, 0], [18446744073709551617, 1], [0, 2]]")
    assert p.dtype == object and p[1, 0] == 2**64 + 1
    assert parse_geometry("[[0, 0.5], [1, 2]]").dtype == np.float64
    assert parse_geometry("[[0, 0], [1, 2]]").dtype == np.int64


def test_geojson_and_wkt():
    gj = {
        "type": "Feature",
        "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [2, 0], [0, 2], [0, 0]]]},
    }
    assert parse_geometry(json.dumps(gj)).tolist() == [[0, 0], [2, 0], [0, 2]]
    assert parse_geometry("POLYGON ((0 0, 2 0, 0 2, 0 0))").tolist() == [[0, 0], [2, 0], [0, 2]]
    assert parse_geometry("POLYGON ((0 0, 2.5 0, 0 2, 0 0))").dtype == np.float64
    holes = parse_geometry("POLYGON ((0 0, 9 0, 9 9, 0 9, 0 0), (1 1, 1 2, 2 2, 1 1))")
    assert holes.geom_type == "Polygon" and len(holes.interiors) == 1
    assert parse_geometry("MULTIPOINT ((0 0), (1 1))").tolist() == [[0, 0], [1, 1]]


@pytest.mark.parametrize(
    "text, exc",
    [
        ("", EmptyGeometryError),
        ("[]", EmptyGeometryError),
        ("[[0, 0], [1]]", ShapeError),
        ("[[0, 0], [1, true]]", ShapeError),
        ("[[0, 0", InputFormatError),
        ("POLYGON ((0 0, 1", InputFormatError),
        ('{"type": "Nope"}', InputFormatError),
        ("LINESTRING EMPTY", EmptyGeometryError),
    ],
)
def test_parse_errors(text, exc):
    with pytest.raises(exc, match="input"):
        parse_geometry(text)


def test_missing_file(tmp_path):
    with pytest.raises(InputFormatError, match="no such file"):
        read_geometry(tmp_path / "nope.json")


def test_cgal_formats():
    assert parse_cgal_dat("5 0 0 4 0 4 4 2 4 0 4")[0].tolist() == [
        [0, 0],
        [4, 0],
        [4, 4],
        [2, 4],
        [0, 4],
    ]
    (p,) = parse_cgal_dat("4 0 0 3 0 3 3 0 3\n1\n4\n1 1 1 2 2 2 2 1\n")
    assert p.area == 8.0
    (u,) = parse_cgal_dat("0\n1\n4\n0 0 0 1 1 1 1 0\n")
    assert isinstance(u, UnboundedPolygon) and len(u.holes) == 1
    two = parse_cgal_dat("3 0 0 1 0 0 1\n3 5 5 6 5 5 6")
    assert len(two) == 2 and two[1].tolist() == [[5, 5], [6, 5], [5, 6]]
    assert parse_cgal_dat("3 7/2 0 1 0 0 5/2")[0].tolist() == [[3.5, 0.0], [1.0, 0.0], [0.0, 2.5]]
    with pytest.raises(InputFormatError, match="ends early"):
        parse_cgal_dat("4 0 0 1 0")


@requires_corpus
def test_every_shared_cgal_file_parses():
    files = sorted(DATA.glob("*.dat"))
    assert len(files) >= 40
    for f in files:
        items = read_cgal_dat(f)
        assert items, f
        for it in items:
            if isinstance(it, np.ndarray):
                assert it.ndim == 2 and it.shape[1] == 2 and len(it) >= 3, f
    assert len(read_cgal_dat(DATA / "comb.dat")) == 2
    assert read_cgal_dat(DATA / "comb_part1.dat")[0].shape == (53, 2)
    assert read_cgal_dat(DATA / "pwh3.dat")[0].geom_type == "Polygon"
    assert len(read_cgal_dat(DATA / "pwh3.dat")[0].interiors) == 3


def test_writers():
    tri = np.array([[0, 0], [3, 0], [0, 3]])
    assert format_geometry(tri, "json") == "[[0, 0], [3, 0], [0, 3]]"
    assert format_geometry(tri, "wkt") == "POLYGON ((0 0, 3 0, 0 3, 0 0))"
    assert json.loads(format_geometry(tri, "geojson"))["coordinates"][0][-1] == [0, 0]
    assert format_geometry(np.array([[0, 0], [1, 1]]), "wkt") == "LINESTRING (0 0, 1 1)"
    assert format_geometry(np.array([[0.5, 1.0]]), "wkt") == "POINT (0.5 1)"
    svg = format_geometry(tri, "svg")
    assert svg.startswith("<svg") and "<path" in svg
    big = np.array([[2**70, 0], [2**70 + 1, 0], [0, 1]], dtype=object)
    assert str(2**70 + 1) in format_geometry(big, "wkt")
    with pytest.raises(ValueError, match="unknown format"):
        format_geometry(tri, "xml")
    # round trips
    for fmt in ("json", "geojson", "wkt"):
        assert parse_geometry(format_geometry(tri, fmt)).tolist() == tri.tolist()


def test_shapely_output_keeps_full_precision():
    shapely = pytest.importorskip("shapely")
    g = shapely.Polygon([(0, 0), (1 / 3, 0), (0, 2 / 3)])
    for fmt in ("wkt", "geojson"):
        back = parse_geometry(format_geometry(g, fmt))
        assert back.tolist() == [[0.0, 0.0], [1 / 3, 0.0], [0.0, 2 / 3]]


@requires_corpus
def test_two_polygon_dat_needs_a_selector():
    with pytest.raises(InputFormatError, match=r"holds 2 polygons; name one as .*comb.dat#1"):
        read_geometry(DATA / "comb.dat")
    first, second = read_cgal_dat(DATA / "comb.dat")
    assert read_geometry(f"{DATA / 'comb.dat'}#2").tolist() == second.tolist()
    with pytest.raises(InputFormatError, match="use #1..#2"):
        read_geometry(f"{DATA / 'comb.dat'}#3")
    assert read_geometry(DATA / "comb_part1.dat").shape == (53, 2)


# --------------------------------------------------------------------------------------
# "Exceptions that are not GeometryErrors"


class TestExceptionsThatAreNotGeometryErrors:
    """Every reader turns every malformed input into a specific GeometryError naming the
    file (``argument``) and, where it can, the position."""

    @pytest.mark.parametrize(
        "text, exc, words",
        [
            ("[" * 100_000, InputFormatError, "nested too deeply"),
            ("[[0, %s], [1, 1]]" % ("9" * 5000), InputFormatError, "JSON number"),
            ("[[0, %s], [1, 0.5]]" % ("9" * 400), OverflowGeometryError, "item 0"),
            ('{"type": "Feature", "geometry": [1, 2]}', ShapeError, "not a GeoJSON object"),
            ('{"type": "Feature", "geometry": null}', EmptyGeometryError, "without a geometry"),
            ('{"type": "FeatureCollection", "features": 5}', ShapeError, "not a list"),
            ('{"type": "Polygon"}', InputFormatError, "without 'coordinates'"),
            ('{"type": "Polygon", "coordinates": []}', EmptyGeometryError, "empty"),
            ('{"type": "Polygon", "coordinates": [[]]}', EmptyGeometryError, "empty"),
            ('{"type": "Polygon", "coordinates": 7}', ShapeError, "coordinates is 7"),
            ('{"type": "Polygon", "coordinates": [[[0, 0], [1, 0]]]}', InputFormatError, "valid"),
            ('{"type": "Point", "coordinates": ["a", 1]}', ShapeError, "non-numeric"),
            ('{"type": "LineString", "coordinates": [[0, 0], [1]]}', ShapeError, "coordinates[1]"),
            ('{"type": "GeometryCollection", "geometries": []}', ShapeError, "not a polygon"),
            ('{"no": "type"}', InputFormatError, "not a GeoJSON geometry"),
            ("[[0, 0], [1, 1],]", InputFormatError, "not valid JSON"),
            ("[[[[[[[[[[1]]]]]]]]]]", ShapeError, "item 0"),
        ],
    )
    def test_json_and_geojson(self, tmp_path, text, exc, words):
        with pytest.raises(exc, match=re.escape(words)) as info:
            parse_geometry(text, name="poly.json")
        assert info.value.argument == "poly.json"
        assert str(info.value).startswith("poly.json: ")
        f = tmp_path / "poly.json"
        f.write_text(text)
        with pytest.raises(exc) as info:
            read_geometry(f)
        assert info.value.argument == str(f)

    def test_reprs_in_messages_are_bounded(self):
        with pytest.raises(ShapeError) as info:
            parse_geometry("[" + "[" * 500 + "]" * 500 + "]")
        assert len(str(info.value)) < 200

    def test_binary_file(self, tmp_path):
        f = tmp_path / "image.json"
        f.write_bytes(b"\x89PNG\r\n\x1a\n\x00\x00\xff\xfe")
        with pytest.raises(InputFormatError, match=r"not a text file \(byte 0 is not UTF-8\)"):
            read_geometry(f)
        d = tmp_path / "poly.dat"
        d.write_bytes(b"3 0 0 1 0 \xff 1")
        with pytest.raises(InputFormatError, match="byte 10") as info:
            read_geometry(d)
        assert info.value.argument == str(d)

    def test_directory_and_bad_names(self, tmp_path):
        with pytest.raises(InputFormatError, match="is a directory"):
            read_geometry(tmp_path)
        with pytest.raises(InputFormatError, match="not a usable file name"):
            read_geometry("bad\0name.json")
        with pytest.raises(InputFormatError, match="cannot read"):
            read_geometry(tmp_path / ("x" * 300))

    @pytest.mark.parametrize(
        "text, words, line, vertex",
        [
            ("3\n0 0\n1/0 0\n0 1", "'1/0' is a zero denominator", 3, 1),
            ("3\n0 0\n1 0\n1/2/3 1", "'1/2/3' is not a number", 4, 2),
            ("3 0 0 abc 0 0 1", "'abc' is not a number", 1, 1),
            ("3 0 0 1 0 nan 1", "'nan' is not a number", 1, 2),
            ("3 0 0 1 0 1e999 1", "beyond the float range", 1, 2),
            ("3 0 0 1_0 0 0 1", "'1_0' is not a number", 1, 1),
            ("3 0 0 1 0 0.5 %s" % ("9" * 400), "beyond the float range", 1, 2),
            ("3 0 0 1 0 1/2 %s/1" % ("9" * 400), "beyond the float range", 1, 2),
            ("3 0 0 1 0 0 %s" % ("9" * 5000), "an integer with too many digits", 1, 2),
        ],
    )
    def test_dat_tokens(self, text, words, line, vertex):
        with pytest.raises(InputFormatError, match=re.escape(words)) as info:
            parse_cgal_dat(text, name="p.dat")
        e = info.value
        assert e.argument == "p.dat" and e.vertex == vertex and f"line {line}:" in str(e)
        assert e.hint

    @pytest.mark.parametrize(
        "text, exc, words",
        [
            ("-3 0 0", InputFormatError, "expected a count for the vertex count, found '-3'"),
            ("x 0 0", InputFormatError, "expected a count"),
            ("3 0 0 1 0 0 1 -2", InputFormatError, "found '-2'"),
            ("4 0 0 9 0 9 9 0 9\n1\n2 1 1 2 2", InputFormatError, "hole 0 has 2 vertices"),
            ("0\n1\n2 0 0 1 1", InputFormatError, "hole 0 has 2 vertices"),
            ("2 0 0 1 1\n1\n3 0 0 1 0 0 1", InputFormatError, "outer boundary"),
            ("3 0 0 9 0 0 9\n1\n0", InputFormatError, "hole 0 has 0 vertices"),
            ("0", EmptyGeometryError, "no vertices"),
            ("0 2 1 1 2 2", EmptyGeometryError, "polygon 1 has no vertices"),
            ("3 0 0 1 0", InputFormatError, "polygon 1 has 3 vertices but only 4 numbers"),
            ("99999999999999999999999 0 0", InputFormatError, "ends early"),
            ("3 0 0 1 0 0 1\n1\n3 0 0 1 0 0 1 7", InputFormatError, "1 unexpected tokens"),
        ],
    )
    def test_dat_structure(self, text, exc, words):
        with pytest.raises(exc, match=re.escape(words)) as info:
            parse_cgal_dat(text, name="p.dat")
        assert info.value.argument == "p.dat"

    def test_dat_integers_beyond_int64_stay_exact(self):
        (p,) = parse_cgal_dat("3 0 0 99999999999999999999 0 0 1")
        assert p.dtype == object and p[1, 0] == 99999999999999999999
        assert parse_cgal_dat("3 0 0 1 0 0 1")[0].dtype == np.int64

    def test_dat_selectors(self, tmp_path):
        f = tmp_path / "two.dat"
        f.write_text("3 0 0 1 0 0 1\n3 5 5 6 5 5 6\n")
        for sel in ("#0", "#3", "#x", "#", "#²"):
            with pytest.raises(InputFormatError, match="use #1..#2") as info:
                read_geometry(f"{f}{sel}")
            assert info.value.argument == f"{f}{sel}"
        assert read_geometry(f"{f}#2").tolist() == [[5, 5], [6, 5], [5, 6]]

    def test_stdin_that_is_not_text(self, monkeypatch):
        import io as _io
        import sys

        raw = _io.TextIOWrapper(_io.BytesIO(b"\xff\xfe[[0, 0]]"), encoding="utf-8")
        monkeypatch.setattr(sys, "stdin", raw)
        with pytest.raises(InputFormatError, match="standard input is not UTF-8") as info:
            read_geometry("-")
        assert info.value.argument == "-"

    def test_inline_points_and_long_inline_polygons(self, tmp_path, capsys):
        from minkowski2d.animation.page import parse_points
        from minkowski2d.cli import main
        from minkowski2d.cli.animation import read_polygon

        with pytest.raises(ShapeError, match="cannot read the number '0.2/45'") as info:
            parse_points("0 0.2/45, 1 0", "A")
        assert info.value.argument == "A" and info.value.vertex == 0
        with pytest.raises(ShapeError, match="division by zero"):
            parse_points("0 1/0", "A")
        with pytest.raises(ShapeError, match="without coordinates"):
            parse_points('{"type": "Polygon"}', "A")
        with pytest.raises(ShapeError, match="nested too deeply"):
            parse_points("[" * 100_000, "A")
        # a polygon typed inline, longer than a file name can be, is not looked up as a path
        long = ", ".join(f"{k} {k * k}" for k in range(80))
        assert len(long) > 255
        assert read_polygon(long, "A")[:3] == [(0, 0), (1, 1), (2, 4)]
        out = tmp_path / "a.html"
        assert main(["animate", "0 0, 0.2/45 1, 1 0", "0 0", "-o", str(out)]) == 2
        assert "cannot read the number" in capsys.readouterr().err and not out.exists()
        tri = ", ".join(f"{x} {y}" for x, y in [(0, 0)] + [(1000 + k, k) for k in range(60)])
        assert main(["animate", tri, "0 0, 1 0, 0 1", "--hull", "-o", str(out)]) == 0
        assert out.exists()

    def test_beyond_float_range_in_the_animation(self, tmp_path, capsys):
        import minkowski2d as mk
        from minkowski2d.cli import main
        from minkowski2d.errors import OverflowGeometryError as OGE

        big = [(0, 0), (10**400, 0), (0, 1)]
        with pytest.raises(OGE, match="beyond the float range") as info:
            mk.animate(big, [(0, 0), (1, 0), (0, 1)], tmp_path / "x.html")
        assert info.value.hint and not (tmp_path / "x.html").exists()
        f = tmp_path / "big.json"
        f.write_text(json.dumps([list(p) for p in big]))
        out = tmp_path / "big.html"
        assert main(["animate", str(f), "0 0, 1 0, 0 1", "-o", str(out)]) == 2
        err = capsys.readouterr().err
        assert err.startswith("minkowski2d: error: coordinates beyond the float range")
        assert err.count("\n") == 1 and not out.exists()
