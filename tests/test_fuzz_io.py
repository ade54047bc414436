"""Fuzzing the readers, the command line and the server API.

The property everywhere: any input gives either a valid result or a GeometryError, never
another exception, never a hang, and never a file written on error. Hypothesis runs
derandomized under ``CI`` (tests/conftest.py); the mutation fuzzing of the CGAL corpus is
seeded. The whole module runs in well under a minute.
"""

from __future__ import annotations

import contextlib
import http.client
import json
import os
import random
import re
import signal
import string
import tempfile
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from minkowski2d.cli import main
from minkowski2d.errors import GeometryError
from minkowski2d.io import UnboundedPolygon, parse_cgal_dat, parse_geometry, read_geometry

from .corpus import corpus_files, requires_corpus

FUZZ = settings(
    max_examples=300,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture],
)


@contextlib.contextmanager
def no_hang(seconds: float = 10.0):
    """Fail (instead of hanging) when the body runs longer than ``seconds``."""

    def alarm(*_):
        raise TimeoutError(f"no answer within {seconds} s: a hang")

    old = signal.signal(signal.SIGALRM, alarm)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


def check_result(r) -> None:
    """A reader's result: an (n, 2) array or a shapely polygon/multipolygon."""
    if isinstance(r, np.ndarray):
        assert r.ndim == 2 and r.shape[1] == 2 and len(r) >= 1, r
    else:
        assert r.geom_type in ("Polygon", "MultiPolygon") and not r.is_empty, r


def read_or_error(fn, *args, **kw):
    """``fn(*args)``: its result, or None for a GeometryError that names its input."""
    with no_hang():
        try:
            return fn(*args, **kw)
        except GeometryError as exc:
            assert str(exc) and exc.to_dict()["type"] == type(exc).__name__
            return None


# --------------------------------------------------------------------------------------
# strategies

numbers = st.one_of(
    st.integers(min_value=-(10**30), max_value=10**30),
    st.integers(min_value=-5, max_value=5),
    st.floats(allow_nan=True, allow_infinity=True),
)
json_values = st.recursive(
    st.none() | st.booleans() | numbers | st.text(max_size=5),
    lambda inner: st.lists(inner, max_size=5) | st.dictionaries(st.text(max_size=4), inner),
    max_leaves=30,
)
positions = st.lists(numbers, min_size=0, max_size=3)
geo_types = st.sampled_from(
    [
        "Point",
        "MultiPoint",
        "LineString",
        "LinearRing",
        "Polygon",
        "MultiLineString",
        "MultiPolygon",
        "GeometryCollection",
        "Feature",
        "FeatureCollection",
        "Nope",
        5,
        None,
    ]
)


@st.composite
def geojson(draw, depth=0):
    t = draw(geo_types)
    d = {"type": t}
    if t == "Feature":
        d["geometry"] = draw(geojson(depth + 1)) if depth < 2 else draw(json_values)
    elif t == "FeatureCollection":
        d["features"] = draw(st.lists(geojson(depth + 1), max_size=2) if depth < 2 else json_values)
    elif draw(st.booleans()):
        d["coordinates"] = draw(
            st.one_of(
                json_values,
                positions,
                st.lists(positions, max_size=5),
                st.lists(st.lists(positions, max_size=6), max_size=3),
                st.lists(st.lists(st.lists(positions, max_size=5), max_size=2), max_size=2),
            )
        )
    return d


def _wkt_number(draw) -> str:
    return draw(st.sampled_from(["0", "1", "-2", "3.5", "1e308", "1e999", "nan", "x", "9" * 40]))


@st.composite
def wkt(draw):
    kind = draw(
        st.sampled_from(
            [
                "POINT",
                "LINESTRING",
                "POLYGON",
                "MULTIPOINT",
                "MULTIPOLYGON",
                "GEOMETRYCOLLECTION",
                "LINEARRING",
                "BOGUS",
            ]
        )
    )
    n = draw(st.integers(0, 6))
    pts = ", ".join(f"{_wkt_number(draw)} {_wkt_number(draw)}" for _ in range(n))
    body = draw(st.sampled_from([f"({pts})", f"(({pts}))", f"((({pts})))", "EMPTY", "(", ""]))
    return f"{kind} {body}"


point_lists = st.lists(st.lists(numbers, min_size=2, max_size=2), min_size=0, max_size=8)

geometry_texts = st.one_of(
    st.text(max_size=40),
    json_values.map(json.dumps),
    point_lists.map(json.dumps),
    geojson().map(json.dumps),
    wkt(),
    st.integers(1, 3000).map(lambda n: "[" * n),
    st.integers(1, 3000).map(lambda n: "[" * n + "]" * n),
)

dat_tokens = st.one_of(
    st.integers(-3, 12).map(str),
    st.integers(-(10**25), 10**25).map(str),
    st.sampled_from(
        [
            "0",
            "1",
            "3",
            "4",
            "1/2",
            "-3/4",
            "1/0",
            "1/2/3",
            "0.5",
            "1e999",
            "nan",
            "inf",
            "abc",
            "1_0",
            "+2",
            "-",
            "/",
            "9" * 30,
            "2/" + "9" * 30,
            "٣",
        ]
    ),
    st.text(alphabet=string.printable, min_size=1, max_size=4).filter(lambda s: not s.isspace()),
)
dat_texts = st.lists(
    st.tuples(dat_tokens, st.sampled_from([" ", "\n", "\t", "  \n"])), max_size=40
).map(lambda ts: "".join(t + sep for t, sep in ts))


# --------------------------------------------------------------------------------------
# the readers


@FUZZ
@given(geometry_texts)
def test_fuzz_parse_geometry(text):
    r = read_or_error(parse_geometry, text, name="fuzz.json")
    if r is not None:
        check_result(r)


@FUZZ
@given(dat_texts, st.sampled_from(["auto", "polygons", "pwh"]))
def test_fuzz_parse_cgal_dat(text, layout):
    r = read_or_error(parse_cgal_dat, text, name="fuzz.dat", layout=layout)
    if r is not None:
        assert 1 <= len(r) <= 2
        for item in r:
            if isinstance(item, UnboundedPolygon):
                assert all(len(h) >= 3 for h in item.holes)
            elif isinstance(item, np.ndarray):
                assert item.ndim == 2 and item.shape[1] == 2
            else:
                assert item.geom_type == "Polygon"


@FUZZ
@given(
    st.one_of(st.binary(max_size=200), geometry_texts.map(str.encode), dat_texts.map(str.encode)),
    st.sampled_from(["f.json", "f.wkt", "f.dat", "f.dat#1", "f.dat#2", "f.dat#x", "f.geojson"]),
)
def test_fuzz_read_geometry(data, name):
    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / name.split("#")[0]
        path.write_bytes(data)
        arg = str(Path(d) / name)
        r = read_or_error(read_geometry, arg)
        if r is not None and not isinstance(r, UnboundedPolygon):
            check_result(r)


# --------------------------------------------------------------------------------------
# seeded mutation fuzzing of the real CGAL files


def _mutate(data: bytes, rng: random.Random) -> bytes:
    b = bytearray(data)
    kind = rng.randrange(7)
    if kind == 0 and b:  # flip bytes
        for _ in range(rng.randint(1, 4)):
            b[rng.randrange(len(b))] = rng.randrange(256)
    elif kind == 1:  # truncate
        del b[rng.randrange(len(b) + 1) :]
    toks = re.split(rb"(\s+)", bytes(b))
    words = [k for k in range(0, len(toks), 2) if toks[k]]
    if kind == 2 and len(words) >= 2:  # swap two tokens
        i, j = rng.sample(words, 2)
        toks[i], toks[j] = toks[j], toks[i]
    elif kind == 3 and words:  # delete a token
        toks[rng.choice(words)] = b""
    elif kind == 4 and words:  # duplicate a token
        k = rng.choice(words)
        toks[k] = toks[k] + b" " + toks[k]
    elif kind == 5 and words:  # replace a token by a nasty one
        toks[rng.choice(words)] = rng.choice(
            [b"-1", b"0", b"1/0", b"1/2/3", b"abc", b"nan", b"1e999", b"9" * 25, b"2", b"\xff"]
        )
    elif kind == 6 and words:  # change a count
        k = rng.choice(words[:1] + words[-8:])
        toks[k] = str(rng.randint(-2, 500)).encode()
    if kind >= 2:
        b = bytearray(b"".join(toks))
    return bytes(b)


@requires_corpus
def test_mutation_fuzz_of_the_cgal_corpus(tmp_path):
    files = corpus_files()
    assert len(files) >= 40
    rng = random.Random(9)  # seeded: the same mutations every run
    outcomes = {"result": 0, "error": 0}
    for f in files:
        original = f.read_bytes()
        for _ in range(40):
            data = _mutate(original, rng)
            path = tmp_path / f.name
            path.write_bytes(data)
            try:
                with no_hang():
                    items = parse_cgal_dat(data.decode("utf-8"), name=f.name)
            except UnicodeDecodeError:
                items = None  # the file reader reports these; checked below
            except GeometryError as exc:
                assert exc.argument == f.name, exc
                outcomes["error"] += 1
                continue
            r = read_or_error(read_geometry, f"{path}#1")
            if items is not None:
                outcomes["result"] += 1
            elif r is None:
                outcomes["error"] += 1
    # the mutations hit both sides
    assert outcomes["result"] > 100 and outcomes["error"] > 100, outcomes


# --------------------------------------------------------------------------------------
# the command line, in process


COMMANDS = [
    ["hull", "A"],
    ["sum", "A", "B", "--hull"],
    ["inflate", "A", "B", "--hull"],
    ["collide", "A", "B", "--hull"],
    ["animate", "A", "B", "--hull"],
    ["sum", "A", "B"],
]


@settings(FUZZ, max_examples=60)
@given(
    st.sampled_from(range(len(COMMANDS))),
    st.one_of(geometry_texts, dat_texts, point_lists.map(json.dumps)),
    st.sampled_from(["a.json", "a.wkt", "a.dat"]),
    st.sampled_from(["[[0, 0], [1, 0], [0, 1]]", "POINT (1 1)", "[[0, 0], [1, 1]]"]),
    st.sampled_from(["out.json", "out.wkt", "out.html"]),
)
def test_fuzz_cli(capsys, which, text, a_name, b_text, out_name):
    with tempfile.TemporaryDirectory() as d:
        d = Path(d)
        a = d / a_name
        a.write_text(text)
        (d / "b.json").write_text(b_text)
        out = d / out_name
        argv = [
            str(a) if x == "A" else str(d / "b.json") if x == "B" else x for x in COMMANDS[which]
        ]
        before = sorted(os.listdir(d))
        with no_hang(30):
            rc = main([*argv, "-o", str(out)])
        cap = capsys.readouterr()
        assert rc in (0, 2), (argv, cap.err)
        if rc == 2:
            lines = cap.err.splitlines()  # notes, then the one error line
            assert lines[-1].startswith("minkowski2d: error: "), cap.err
            assert all(line.startswith("minkowski2d: note: ") for line in lines[:-1]), cap.err
            assert sorted(os.listdir(d)) == before  # nothing written, no temporary left
        else:
            assert out.stat().st_size > 0
            assert sorted(os.listdir(d)) == sorted([*before, out_name])


# --------------------------------------------------------------------------------------
# the server API


@pytest.fixture(scope="module")
def server():
    from minkowski2d.animation.server import make_server

    srv = make_server(port=0, timeout=5.0)
    srv.start_thread()
    yield srv
    srv.shutdown()
    srv.server_close()


polygon_fields = st.one_of(
    geometry_texts,
    point_lists,
    json_values,
    st.sampled_from(["0 0, 2 0, 0 2", "0 0.2/45, 1 0", "nan 0, 1 1", "", "1/0 1"]),
)
bodies = st.one_of(
    st.fixed_dictionaries(
        {"a": polygon_fields, "b": polygon_fields},
        optional={
            "obstacle": polygon_fields,
            "robot": polygon_fields,
            "hull": json_values,
            "view": json_values,
        },
    ).map(lambda d: json.dumps(d).encode()),
    json_values.map(lambda v: json.dumps(v).encode()),
    st.binary(max_size=100),
)


@settings(FUZZ, max_examples=150)
@given(bodies)
def test_fuzz_server_api(server, body):
    c = http.client.HTTPConnection("127.0.0.1", server.server_address[1], timeout=30)
    try:
        c.request("POST", "/api/trace", body=body, headers={"Content-Type": "application/json"})
        r = c.getresponse()
        status, answer = r.status, r.read()
    finally:
        c.close()
    assert status in (200, 400), (status, body[:200], answer[:300])
    d = json.loads(answer)
    if status == 400 or "error" in d:
        err = d["error"]
        assert isinstance(err, dict) and err["message"] and err["type"], d
        assert err["type"] != "RequestError" or status == 400
    else:
        assert "trace" in d and "cspace" in d
