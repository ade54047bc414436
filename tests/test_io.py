"""minkowski2d.io: readers (JSON, GeoJSON, WKT, CGAL .dat) and writers."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from minkowski2d.errors import EmptyGeometryError, InputFormatError, ShapeError
from minkowski2d.io import (
    UnboundedPolygon,
    format_geometry,
    parse_cgal_dat,
    parse_geometry,
    read_cgal_dat,
    read_geometry,
)

DATA = Path(__file__).resolve().parents[2] / "shared" / "data" / "cgal-minkowski"


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


@pytest.mark.skipif(
    not DATA.is_dir(), reason="../shared/data/cgal-minkowski is not beside the repo"
)
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


@pytest.mark.skipif(
    not DATA.is_dir(), reason="../shared/data/cgal-minkowski is not beside the repo"
)
def test_two_polygon_dat_needs_a_selector():
    with pytest.raises(InputFormatError, match=r"holds 2 polygons; name one as .*comb.dat#1"):
        read_geometry(DATA / "comb.dat")
    first, second = read_cgal_dat(DATA / "comb.dat")
    assert read_geometry(f"{DATA / 'comb.dat'}#2").tolist() == second.tolist()
    with pytest.raises(InputFormatError, match="use #1..#2"):
        read_geometry(f"{DATA / 'comb.dat'}#3")
    assert read_geometry(DATA / "comb_part1.dat").shape == (53, 2)
