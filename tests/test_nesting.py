"""No-fit polygons, inner-fit polygons and batched general sums.

References: a brute-force oracle (triangulate both parts with GEOS's constrained
Delaunay triangulation, sum every triangle pair as the hull of its nine vertex sums,
unite) on a sample of every classic ESICUP instance, and CGAL's exact
``minkowski_sum_2`` (through ``benchmarks/cgal_nfp_driver.cpp``, when it is built) on
every NFP of the classic instances.
"""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

import numpy as np
import pytest
import shapely

import minkowski2d as mk
from minkowski2d.cli import main
from minkowski2d.errors import GeometryError, ShapeError

from .corpus import ESICUP

ROOT = Path(__file__).resolve().parents[1]
DATA = ESICUP
DRIVER = ROOT / "build" / "cgal_nfp_driver"
CLASSIC = [
    "albano", "blaz", "dagli", "dighe1", "dighe2", "fu", "jakobs1", "jakobs2", "mao",
    "marques", "shapes0", "shapes1", "shirts", "swim", "trousers",
]  # fmt: skip
REL = 1e-9


def instance(name: str) -> dict:
    return mk.read_esicup(DATA / f"{name}.json")


def oracle(a, b) -> shapely.Geometry:
    """a ⊕ b by brute force: all triangle pairs, each the hull of its vertex sums."""
    ta = shapely.get_parts(shapely.constrained_delaunay_triangles(a))
    tb = shapely.get_parts(shapely.constrained_delaunay_triangles(b))
    ca = shapely.get_coordinates(shapely.get_exterior_ring(ta)).reshape(-1, 4, 2)[:, :3]
    cb = shapely.get_coordinates(shapely.get_exterior_ring(tb)).reshape(-1, 4, 2)[:, :3]
    s = (ca[:, None, :, None, :] + cb[None, :, None, :, :]).reshape(-1, 9, 2)
    hulls = shapely.convex_hull(shapely.multipoints(s))
    return shapely.union_all(hulls)


def same_set(g, ref) -> bool:
    area = ref.area
    return (
        abs(g.area - area) <= REL * area
        and shapely.symmetric_difference(g, ref).area <= REL * area
        and sum(len(p.interiors) for p in shapely.get_parts(g))
        == sum(len(p.interiors) for p in shapely.get_parts(ref))
    )


def oriented(part, angle):
    return shapely.Polygon(mk.rotate_part(shapely.get_coordinates(part.exterior)[:-1], angle))


# --------------------------------------------------------------------------------------
# every classic instance against the oracle (sample) and CGAL (all)


@pytest.mark.parametrize("name", CLASSIC)
def test_classic_sample_against_oracle(name):
    d = instance(name)
    nfps = mk.no_fit_polygons(d["parts"], rotations=d["rotations"])
    n = len(d["parts"])
    assert len(nfps) == sum(
        len(d["rotations"][i]) * len(d["rotations"][j]) for i in range(n) for j in range(n)
    )
    keys = list(nfps)
    rng = np.random.default_rng(sum(map(ord, name)))
    for k in rng.choice(len(keys), min(8, len(keys)), replace=False):
        i, ri, j, rj = keys[k]
        A = oriented(d["parts"][i], ri)
        negB = oriented(d["parts"][j], rj + 180)
        g = nfps[keys[k]]
        assert g.geom_type in ("Polygon", "MultiPolygon") and g.is_valid
        assert same_set(g, oracle(A, negB)), keys[k]


def _cgal_areas(rings: list, pairs: list) -> list:
    import tempfile

    with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
        f.write(f"{len(rings)}\n")
        for c in rings:
            f.write(f"{len(c)} " + " ".join(f"{int(x)} {int(y)}" for x, y in c) + "\n")
        f.write(f"{len(pairs)}\n" + "\n".join(f"{a} {b}" for a, b in pairs) + "\n")
    out = subprocess.run([str(DRIVER), "rc", f.name], capture_output=True, text=True, check=True)
    Path(f.name).unlink()
    return [
        (float(a), int(h)) for a, h in (ln.split() for ln in out.stdout.split("\n")[: len(pairs)])
    ]


@pytest.mark.skipif(
    not DRIVER.exists(),
    reason="CGAL driver not built (python benchmarks/bench_nfp.py builds build/cgal_nfp_driver "
    "after apt-get install libcgal-dev)",
)
def test_every_classic_nfp_against_cgal():
    total = 0
    for name in CLASSIC:
        d = instance(name)
        parts, R = d["parts"], d["rotations"]
        nfps = mk.no_fit_polygons(parts, rotations=R)
        index, rings, pairs = {}, [], []
        for i, ri, j, rj in nfps:
            for key, ang in (((i, ri), ri), (("neg", j, rj), rj + 180)):
                if key not in index:
                    index[key] = len(rings)
                    p = parts[key[-2]]
                    rings.append(mk.rotate_part(shapely.get_coordinates(p.exterior)[:-1], ang))
            pairs.append((index[(i, ri)], index[("neg", j, rj)]))
        ref = _cgal_areas(rings, pairs)
        for (key, g), (area, holes) in zip(nfps.items(), ref, strict=True):
            assert abs(g.area - area) <= REL * area, (name, key, g.area, area)
            assert sum(len(p.interiors) for p in shapely.get_parts(g)) == holes, (name, key)
        total += len(nfps)
    assert total == 27724


def test_degenerate_placements_on_instances_are_feasible():
    found = 0
    for name in ("dighe2", "shapes0"):
        d = instance(name)
        nfps = mk.no_fit_polygons(d["parts"], rotations=d["rotations"], keep_degenerate=True)
        for (i, ri, j, rj), g in nfps.items():
            if g.geom_type != "GeometryCollection":
                continue
            A = mk.rotate_part(d["parts"][i], ri)
            B = mk.rotate_part(d["parts"][j], rj)
            poly = shapely.union_all([p for p in shapely.get_parts(g) if p.geom_type == "Polygon"])
            assert poly.equals(
                mk.no_fit_polygons(d["parts"], rotations=d["rotations"], pairs=[(i, j)])[
                    (i, ri, j, rj)
                ]
            )
            for p in shapely.get_parts(g):
                if p.geom_type == "Polygon":
                    continue
                found += 1
                for t in (0.25, 0.5, 0.75):
                    m = p.interpolate(t, normalized=True)
                    # m is rounded off the exact segment: allow that much overlap
                    over = A.intersection(shapely.affinity.translate(B, m.x, m.y)).area
                    assert over <= 1e-12 * A.area
                    assert poly.covers(m) or poly.distance(m) < 1e-12 * A.length
    # shapes0 2-3 and 3-2 (a dighe2 "slide" was a GEOS artefact: it runs along the exact
    # boundary of the NFP)
    assert found >= 2


# --------------------------------------------------------------------------------------
# API


L = [(0, 0), (3, 0), (3, 1), (1, 1), (1, 3), (0, 3)]
SQ = [(0, 0), (2, 0), (2, 2), (0, 2)]
U = [(0, 0), (3, 0), (3, 2), (2, 2), (2, 1), (1, 1), (1, 2), (0, 2)]
PEG = [(0, 0), (1, 0), (1, 1), (0, 1)]
FRAME = shapely.Polygon([(0, 0), (9, 0), (9, 9), (0, 9)], [[(3, 3), (3, 6), (6, 6), (6, 3)]])


def test_nfp_rotations_and_symmetries_match_direct_sums():
    parts = [L, U, SQ, FRAME]
    rots = [(0, 90, 180, 270), (0, 180), (0, 45), (0, 90)]
    nfps = mk.no_fit_polygons(parts, rotations=rots)
    assert len(nfps) == sum(len(a) * len(b) for a in rots for b in rots)
    for (i, ri, j, rj), g in nfps.items():
        A = mk.rotate_part(parts[i], ri)
        B = mk.rotate_part(mk.rotate_part(parts[j], rj), 180)
        ref = mk.minkowski_sum_general(A, B)
        assert same_set(g, ref), (i, ri, j, rj)
        if ri % 90 == 0 and rj % 90 == 0:
            assert g.equals_exact(ref, 0.0), (i, ri, j, rj)  # exact, same normal form


def test_nfp_pairs_and_per_part_rotations():
    nfps = mk.no_fit_polygons([L, SQ, U], rotations=[(0, 90), (0,), (180,)], pairs=[(0, 2), (1, 1)])
    assert sorted(nfps) == [(0, 0, 2, 180), (0, 90, 2, 180), (1, 0, 1, 0)]
    assert nfps[(1, 0, 1, 0)].equals(shapely.box(-2, -2, 2, 2))


def test_nfp_errors_name_the_part():
    bow = [(0, 0), (2, 2), (2, 0), (0, 2)]
    with pytest.raises(GeometryError) as e:
        mk.no_fit_polygons([SQ, bow])
    assert e.value.argument.startswith("parts[1]")
    with pytest.raises(ValueError):
        mk.no_fit_polygons([SQ], rotations=("x",))
    with pytest.raises(ValueError):
        mk.no_fit_polygons([SQ], pairs=[(0, 1)])
    with pytest.raises(ValueError):
        mk.no_fit_polygons([SQ, L], rotations=[(0,)])


def test_keep_degenerate_slide_and_exact_fit():
    # a peg slides in the U's slot: the slit x = 1, 1 <= y <= 2 is a valid placement
    nfps = mk.no_fit_polygons([U, PEG], pairs=[(0, 1)], keep_degenerate=True)
    g = nfps[(0, 0, 1, 0)]
    assert g.geom_type == "GeometryCollection"
    lines = [p for p in shapely.get_parts(g) if p.geom_type == "LineString"]
    assert [ln.wkt for ln in lines] == ["LINESTRING (1 1, 1 2)"]
    plain = mk.no_fit_polygons([U, PEG], pairs=[(0, 1)])[(0, 0, 1, 0)]
    assert plain.geom_type == "Polygon" and plain.covers(lines[0])
    # a dovetail that fits its slot exactly: only the point (0, 0), inside the NFP
    A = [(0, 0), (6, 0), (6, 4), (4, 4), (5, 2), (1, 2), (2, 4), (0, 4)]
    B = [(1, 2), (5, 2), (4, 4), (2, 4)]
    nfps = mk.no_fit_polygons([A, B], rotations=(0, 90), pairs=[(0, 1)], keep_degenerate=True)
    pts = [p for p in shapely.get_parts(nfps[(0, 0, 1, 0)]) if p.geom_type == "Point"]
    assert [p.wkt for p in pts] == ["POINT (0 0)"]
    # turned by 90 degrees, it slides exactly through the slot's mouth: x = 6, y in [1, 3];
    # above y = 2 it can leave to the left, so that part is on the NFP's boundary (the
    # segment is kept whole: every point of it is a placement)
    lines = [p for p in shapely.get_parts(nfps[(0, 0, 1, 90)]) if p.geom_type == "LineString"]
    assert [ln.wkt for ln in lines] == ["LINESTRING (6 1, 6 3)"]
    poly = shapely.get_parts(nfps[(0, 0, 1, 90)])[0]
    assert poly.boundary.covers(shapely.LineString([(6, 2), (6, 3)]))
    assert not poly.boundary.intersects(shapely.LineString([(6, 1.1), (6, 1.9)]))
    B90 = shapely.Polygon(mk.rotate_part(B, 90))
    for y in (1, 1.5, 2, 2.5, 3):
        assert shapely.Polygon(A).intersection(shapely.affinity.translate(B90, 6, y)).area == 0
    for y, dx in ((1.5, 0.01), (1.5, -0.01), (1.99, -0.001), (2.5, 0.01)):  # locked
        assert shapely.Polygon(A).intersection(shapely.affinity.translate(B90, 6 + dx, y)).area > 0
    assert shapely.Polygon(A).intersection(shapely.affinity.translate(B90, 5.99, 2.5)).area == 0
    pts = [p for p in shapely.get_parts(nfps[(0, 90, 1, 90)]) if p.geom_type == "Point"]
    assert [p.wkt for p in pts] == ["POINT (0 0)"]  # rotation of the fit (and exact)
    # parts with nothing degenerate: the polygon itself
    assert mk.no_fit_polygons([SQ], keep_degenerate=True)[(0, 0, 0, 0)].geom_type == "Polygon"


def test_degenerate_placements_are_feasible_and_nothing_else():
    A = shapely.Polygon([(0, 0), (6, 0), (6, 4), (4, 4), (5, 2), (1, 2), (2, 4), (0, 4)])
    B = shapely.Polygon([(1, 2), (5, 2), (4, 4), (2, 4)])
    extra = mk.degenerate_placements(A, mk.rotate_part(B, 180))
    assert extra.wkt == "POINT (0 0)"
    moved = shapely.affinity.translate(B, 0, 0)
    assert A.intersection(moved).area == 0
    for dx, dy in ((0.01, 0), (0, 0.01), (-0.01, 0), (0, -0.01)):
        assert A.intersection(shapely.affinity.translate(B, dx, dy)).area > 0


def test_inner_fit_polygons_in_the_strip_are_exact():
    for name in CLASSIC:
        d = instance(name)
        H = d["strip"]["height"]
        W = d["strip"]["length"] or 1000
        sheet = [(0, 0), (W, 0), (W, H), (0, H)]
        for part, R in zip(d["parts"], d["rotations"], strict=True):
            for r in R:
                p = mk.rotate_part(part, r)
                x0, y0, x1, y1 = p.bounds
                ifp = mk.inner_fit_polygon(sheet, p)
                if y1 - y0 > H or x1 - x0 > W:
                    assert ifp.is_empty
                    continue
                box = shapely.box(-x0, -y0, W - x1, H - y1)
                corners = {(-x0, -y0), (W - x1, -y0), (W - x1, H - y1), (-x0, H - y1)}
                assert set(map(tuple, shapely.get_coordinates(ifp).tolist())) == corners
                if box.area > 0:
                    assert ifp.geom_type == "Polygon" and ifp.area == box.area
                else:
                    assert ifp.geom_type in ("LineString", "Point")


def test_inner_fit_polygon_general_container_and_errors():
    ifp = mk.inner_fit_polygon(FRAME, [(10, 10), (11, 10), (11, 11), (10, 11)])
    # the frame of width 3 around a 3x3 hole, shifted by (-10, -10), shrunk by the square
    assert ifp.area == pytest.approx(8 * 8 - 4 * 4)
    assert ifp.bounds == (-10.0, -10.0, -2.0, -2.0)
    with pytest.raises(GeometryError) as e:
        mk.inner_fit_polygon([(0, 0), (1, 1)], SQ)
    assert e.value.argument == "container"


# --------------------------------------------------------------------------------------
# minkowski_sum_general_many


def test_general_many_matches_single():
    As = [L, FRAME, [(0, 0), (2, 1)], shapely.Polygon(U), None, L]
    Bs = [U, SQ, L, [(5, 5)], SQ, np.array(L) * 2.0**-600]
    out = mk.minkowski_sum_general_many(As, Bs)
    assert out.dtype == object and len(out) == len(As)
    assert out[4] is None
    for a, b, g in zip(As, Bs, out, strict=True):
        if a is None:
            continue
        ref = mk.minkowski_sum_general(a, b)
        assert g.equals_exact(ref, 0.0)
    # one against many, and the convolution
    out = mk.minkowski_sum_general_many(L, [U, SQ], method="convolution")
    for b, g in zip([U, SQ], out, strict=True):
        assert same_set(g, mk.minkowski_sum_general(L, b))


def test_general_many_errors_and_progress():
    with pytest.raises(ShapeError):
        mk.minkowski_sum_general_many([L, L], [SQ])
    with pytest.raises(ShapeError):
        mk.minkowski_sum_general_many(L, SQ)
    with pytest.raises(GeometryError) as e:
        mk.minkowski_sum_general_many([L, [(0, 0), (2, 2), (2, 0), (0, 2)]], SQ)
    assert e.value.argument == "As[1]"
    with pytest.raises(ShapeError):
        mk.minkowski_sum_general_many([[(0, 0), (1, 0)]], [[(0, 0), (0, 1)]])
    with pytest.raises(ValueError):
        mk.minkowski_sum_general_many([L], SQ, method="nope")
    seen = []
    mk.minkowski_sum_general_many([L] * 5, U, progress=lambda d, t: seen.append((d, t)))
    assert seen[-1] == (5, 5)


def test_general_many_large_parts():
    rng = np.random.default_rng(3)

    def star(n, r0, r1):
        t = np.arange(n) * 2 * np.pi / n
        r = np.where(np.arange(n) % 2 == 0, r0, r1) * (1 + 0.1 * rng.random(n))
        return np.round(np.stack([r * np.cos(t), r * np.sin(t)], 1))

    a, b = star(60, 1000, 500), star(50, 700, 300)
    ref = oracle(shapely.Polygon(a), shapely.Polygon(b))
    for method in ("auto", "decomposition"):  # 1015 piece sums: the union in rounds
        g = mk.minkowski_sum_general_many([a], b, method=method)[0]
        assert same_set(g, ref)


def test_auto_switches_to_the_convolution_on_curved_parts(monkeypatch):
    import minkowski2d.general.sums as general

    d = instance("gardeyn0")
    A, B = d["parts"][3], mk.rotate_part(d["parts"][3], 180)  # 2 304 sums, 170 crossings
    used: list = []
    preps = [general._Prepared(A, "a"), general._Prepared(B, "b")]
    g = general._sums(preps, np.array([0]), np.array([1]), [("a", "b")], None, used=used)[0]
    assert used == ["convolution"]
    ref = mk.minkowski_sum_general(A, B, method="decomposition")
    assert same_set(g, ref)


# --------------------------------------------------------------------------------------
# CLI and distribution


@pytest.mark.parametrize("fmt", ["json", "geojson"])
def test_cli_nfp(tmp_path, fmt):
    out = tmp_path / f"out.{fmt}"
    assert main(["nfp", str(DATA / "shapes0.json"), "-o", str(out), "--format", fmt]) == 0
    data = json.loads(out.read_text())
    if fmt == "json":
        assert len(data["nfps"]) == 16 and len(data["ifps"]) == 4
        g = shapely.geometry.shape(data["nfps"][0]["geometry"])
        ref = mk.no_fit_polygons(instance("shapes0")["parts"])[(0, 0, 0, 0)]
        assert g.equals(ref)
    else:
        kinds = [f["properties"]["kind"] for f in data["features"]]
        assert kinds.count("nfp") == 16 and kinds.count("ifp") == 4


def test_cli_nfp_bad_instance(tmp_path, capsys):
    bad = tmp_path / "bad.json"
    bad.write_text('{"pieces": [{"outer": "x"}]}')
    assert main(["nfp", str(bad)]) == 2
    assert "pieces[0]" in capsys.readouterr().err


def test_pair_blocks_cover_every_pair_once():
    blocks = mk.pair_blocks(5, 6)
    flat = [p for b in blocks for p in b]
    assert sorted(flat) == [(i, j) for i in range(5) for j in range(5)]
    for b in blocks:
        assert all((j, i) in b for i, j in b)


def _nfp_block(parts, rotations, block):
    import minkowski2d as mk_

    return mk_.no_fit_polygons(parts, rotations=rotations, pairs=block)


def test_dask_recipe_on_a_local_cluster():
    distributed = pytest.importorskip("distributed", reason="dask[distributed] is not installed")
    d = instance("dagli")
    parts, R = d["parts"], d["rotations"]
    with (
        distributed.LocalCluster(
            n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
            dashboard_address=None,
        ) as cluster,
        distributed.Client(cluster) as client,
    ):  # fmt: skip
        fparts = client.scatter(parts, broadcast=True)
        futures = [
            client.submit(_nfp_block, fparts, R, block, pure=False)
            for block in mk.pair_blocks(len(parts), 16)
        ]
        nfps = {}
        for part in client.gather(futures):
            nfps.update(part)
    ref = mk.no_fit_polygons(parts, rotations=R)
    assert nfps.keys() == ref.keys()
    assert all(nfps[k].equals_exact(ref[k], 0.0) for k in ref)
