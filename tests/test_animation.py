"""The animation page without a browser: generation, embedded data, server API, CLI."""

from __future__ import annotations

import http.client
import json
import re
import signal
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import pytest

import minkowski2d as mk
from minkowski2d.animation import (
    MAX_VERTICES,
    SEED_A,
    SEED_B,
    page_data,
    parse_points,
    render,
    write_demo_page,
)
from minkowski2d.animation.server import make_server, polygons_from_request
from minkowski2d.cli import main
from minkowski2d.errors import NonFiniteError, NotConvexError, ShapeError

ANIM = Path(mk.__file__).parent / "animation"


def embedded(page: str) -> dict:
    m = re.search(r'<script type="application/json" id="mk-data">(.*?)</script>', page, re.S)
    assert m, "no embedded data"
    return json.loads(m.group(1))


# --------------------------------------------------------------------------------------
# the page


def test_page_is_self_contained():
    page = render(SEED_A, SEED_B)
    assert page.startswith("<!doctype html>")
    # nothing is loaded from anywhere: no external script, stylesheet, image or font
    assert not re.search(r"""(src|href)\s*=\s*["'](?!data:|#)""", page)
    assert "@import" not in page and "url(http" not in page
    assert re.search(r"connect-src 'none'", page)
    assert "/*MK:" not in page and "<!--MK:" not in page
    # the template files are inlined whole
    for name in ("style.css", "player.js"):
        assert (ANIM / name).read_text(encoding="utf-8").strip()[:200] in page


def test_embedded_trace_is_merge_trace():
    d = embedded(render(SEED_A, SEED_B))
    assert d["trace"] == json.loads(json.dumps(mk.merge_trace(SEED_A, SEED_B).to_dict()))
    assert d["editable"] is False and d["api"] is None
    assert d["trace"]["result_text"] == ["(0, 0)", "(3, 0)", "(3, 1)", "(1, 3)", "(0, 3)"]
    cs = d["cspace"]
    assert cs["inflated"] == mk.cspace_obstacle(SEED_A, SEED_B).tolist()
    assert cs["reflected"] == mk.reflect(mk.normalize(SEED_B)).tolist()
    for pos in cs["positions"]:
        assert pos["robot"] == mk.translate(mk.normalize(SEED_B), pos["ref"]).tolist()
    assert cs["linked"] is True
    # every edge drawn for A is an edge of the normalized A
    a = d["trace"]["a"]
    assert [e["from"] for e in d["edges_a"]] == a
    assert [e["to"] for e in d["edges_a"]] == a[1:] + a[:1]


def test_player_computes_no_geometry():
    js = (ANIM / "player.js").read_text(encoding="utf-8")
    for forbidden in ("atan", "hypot", "sqrt", "Math.cos", "Math.sin", "cross"):
        assert forbidden not in js.replace("cross product", ""), forbidden
    # outside the one view map (world -> pixels and back), coordinates are only read
    # from the data, never added to or subtracted from each other
    start = js.index("function mapper(")
    end = js.index("\n  }\n", start)
    rest = re.sub(r'"(?:[^"\\]|\\.)*"', '""', js[:start] + js[end:])  # drop string literals
    assert re.search(r"\[0\]\s*[-+]\s*\w+\[0\]", js[start:end])  # the map itself
    assert not re.search(r"\[[01]\]\s*[-+]\s*\w+\[[01]\]", rest)


def test_script_injection_is_escaped():
    page = render(SEED_A, SEED_B, title="</script><script>alert(1)</script>")
    assert "<script>alert(1)" not in page
    assert page.count("<script") == 2
    d = embedded(render([(0, 0), (1, 0)], [(0, 0)]))
    assert d["trace"]["result"] == [[0, 0], [1, 0]]


def test_explicit_cspace_and_exact_numbers():
    obstacle = [(4, 0), (8, 0), (8, 3), (4, 3)]
    robot = [(0, 0), (1, 0), (0, 1)]
    d = page_data(SEED_A, SEED_B, obstacle=obstacle, robot=robot)
    assert d["cspace"]["linked"] is False
    assert d["cspace"]["inflated"] == mk.cspace_obstacle(obstacle, robot).tolist()
    f = Fraction
    third = [(f(0), f(0)), (f(1, 3), f(0)), (f(0), f(1, 3))]
    d = page_data(third, [(0.5, 0.0), (1.0, 0.5)])
    json.dumps(d, allow_nan=False)
    assert d["trace"]["kind"] == "exact"
    assert "(1/3, 0)" in d["trace"]["a_text"]


def test_views_hold_for_dragging():
    d = page_data(SEED_A, SEED_B)
    box = d["a_view"]["box"]
    d2 = page_data([(0, 0), (2, 0), (1, 1)], SEED_B, hold_view={"a": box, "b": None})
    assert d2["a_view"]["box"] == box
    d3 = page_data([(0, 0), (20, 0), (1, 1)], SEED_B, hold_view={"a": box})
    assert d3["a_view"]["box"][2] > 20  # grown to take the moved vertex
    d4 = page_data(SEED_A, SEED_B, hold_view={"a": [0, 0, float("nan"), 1]})
    assert d4["a_view"] == d["a_view"]


def test_errors_name_the_polygon_as_the_page_does():
    with pytest.raises(NotConvexError, match=r"^A: not convex.*or use the convex hull"):
        page_data([(0, 0), (2, 0), (1, 1), (2, 2), (0, 2)], SEED_B)
    with pytest.raises(NonFiniteError, match=r"^B: vertex 1 has a non-finite"):
        page_data(SEED_A, [(0.0, 0.0), (float("nan"), 1.0)])
    with pytest.raises(NotConvexError, match=r"^robot: not convex"):
        page_data(SEED_A, SEED_B, robot=[(0, 0), (2, 0), (1, 1), (2, 2), (0, 2)])
    with pytest.raises(ShapeError, match="more than the page draws"):
        page_data([(i, i * i) for i in range(MAX_VERTICES + 1)], SEED_B)
    assert page_data(SEED_A, [(0, 0), (2, 0), (1, 1), (2, 2), (0, 2)], hull=True)["hull"]


def test_parse_points():
    assert parse_points("0 0\n2 0\n0 2", "A") == [(0, 0), (2, 0), (0, 2)]
    assert parse_points("(0.5, -1e3); (1/4, 2)", "A") == [(0.5, -1000.0), (Fraction(1, 4), 2)]
    assert parse_points(
        '{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1], [0, 0]]]}', "A"
    ) == [(0, 0), (1, 0), (0, 1), (0, 0)]
    nan = parse_points("nan, 1", "A")[0][0]
    assert nan != nan
    with pytest.raises(ShapeError, match="do not make"):
        parse_points("1 2 3", "A")
    with pytest.raises(ShapeError, match="cannot read 'abc'"):
        parse_points("1 2 abc", "A")
    assert parse_points("", "A") == []


def test_animate_and_demo_page(tmp_path):
    p = mk.animate(SEED_A, SEED_B, path=tmp_path / "a.html")
    assert p == tmp_path / "a.html" and embedded(p.read_text("utf-8"))["trace"]["steps"]
    q = write_demo_page(tmp_path / "demo.html")
    d = embedded(q.read_text("utf-8"))
    assert d["trace"]["a"] == [list(v) for v in SEED_A] and len(d["trace"]["steps"]) == 5
    assert "triangle and a square" in q.read_text("utf-8")


# --------------------------------------------------------------------------------------
# the server, spoken to directly


@pytest.fixture()
def server():
    srv = make_server(port=0)
    srv.start_thread()
    yield srv
    srv.shutdown()
    srv.server_close()


def _post(srv, body: bytes, host: str = "127.0.0.1", path: str = "/api/trace"):
    c = http.client.HTTPConnection("127.0.0.1", srv.server_address[1], timeout=10)
    c.request("POST", path, body=body, headers={"Host": host, "Content-Type": "application/json"})
    r = c.getresponse()
    out = r.status, r.read()
    c.close()
    return out


def test_server_api(server):
    c = http.client.HTTPConnection("127.0.0.1", server.server_address[1], timeout=10)
    c.request("GET", "/")
    r = c.getresponse()
    page = r.read().decode()
    assert r.status == 200 and r.getheader("Content-Type").startswith("text/html")
    d = embedded(page)
    assert d["editable"] is True and d["api"] == "/api/trace"
    assert "connect-src 'self'" in page
    c.request("GET", "/nope")
    r = c.getresponse()
    r.read()
    assert r.status == 404
    c.close()

    st, body = _post(server, json.dumps({"a": "0 0, 4 0, 0 4", "b": [[0, 0], [1, 1]]}).encode())
    assert st == 200
    d = json.loads(body)
    expected = mk.minkowski_sum([(0, 0), (4, 0), (0, 4)], [(0, 0), (1, 1)])
    assert d["trace"]["result"] == expected.tolist()

    # errors are the GeometryError's fields (to_dict), which the page shows
    st, body = _post(server, json.dumps({"a": "0 0, 2 0, 1 1, 2 2, 0 2", "b": "0 0"}).encode())
    err = json.loads(body)["error"]
    assert st == 200 and err["message"].startswith("A: not convex")
    assert err["type"] == "NotConvexError" and err["argument"] == "A" and err["vertex"] == 2
    st, body = _post(server, json.dumps({"a": "nan 0, 1 1", "b": "0 0"}).encode())
    assert "non-finite" in json.loads(body)["error"]["message"]
    st, body = _post(server, json.dumps({"a": "", "b": "0 0"}).encode())
    assert json.loads(body)["error"]["message"] == "A: empty input (no vertices)"
    st, body = _post(server, b"{not json")
    assert st == 400 and "not valid JSON" in json.loads(body)["error"]["message"]
    st, body = _post(server, b"{}", host="evil.example")
    assert st == 421
    st, body = _post(server, b"{}", path="/other")
    assert st == 404


def test_polygons_from_request():
    kw = polygons_from_request({"a": "0 0, 1 0", "b": [[0, 0]], "hull": 1, "view": [1, 2]})
    assert kw["a"] == [(0, 0), (1, 0)] and kw["b"] == [(0, 0)]
    assert kw["hull"] is True and kw["hold_view"] is None and kw["obstacle"] is None
    with pytest.raises(ShapeError):
        polygons_from_request([1, 2])


# --------------------------------------------------------------------------------------
# the command line


def test_cli_animate(tmp_path, capsys):
    out = tmp_path / "anim.html"
    assert main(["animate", "0,0 2,0 0,2", "[[0,0],[1,0],[1,1],[0,1]]", "-o", str(out)]) == 0
    assert capsys.readouterr().out.strip() == str(out.resolve())
    assert embedded(out.read_text("utf-8"))["trace"]["result_text"][2] == "(3, 1)"
    f = tmp_path / "a.json"
    f.write_text("[[0, 0], [2, 0], [0, 2]]")
    assert main(["animate", str(f), "0,0 1,0 1,1 0,1", "-o", "-", "--robot", "0,0 1,0 0,1"]) == 0
    d = embedded(capsys.readouterr().out)
    assert d["cspace"]["robot_text"] == ["(0, 0)", "(1, 0)", "(0, 1)"]
    assert main(["animate", str(f), "0,0 1,0", "-o", str(f)]) == 2  # refuses to overwrite
    assert "refusing" in capsys.readouterr().err
    assert main(["animate", "0,0 2,0 1,1 2,2 0,2", "0,0", "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.startswith("minkowski2d: error: A: not convex") and "--hull" in err
    assert err.count("\n") == 1
    assert main(["animate", "0,0", "0,0", "-o", str(tmp_path / "no" / "dir.html")]) == 2
    assert "cannot write" in capsys.readouterr().err


def test_cli_serve_port_in_use(server, capsys):
    assert main(["serve", "--port", str(server.server_address[1])]) == 2
    assert "try --port 0" in capsys.readouterr().err
    assert main(["serve", "0,0 1,0"]) == 2


#: only a guard against a hung suite, never what the test waits for: every wait below
#: ends on an event (a line printed, an answer, the process's exit)
_GUARD = 600


def test_cli_serve_prints_url_and_stops_on_ctrl_c():
    """Ctrl-C stops the server at once whatever its workers are doing: here
    every worker is held by an upload that never comes, and one more waits in the
    queue. The test waits for the process to exit, not for a clock: the stalled
    connections are ended by the stop (their end of stream, no 408, which the server
    would send only after its 10-second timeout)."""
    import socket

    from minkowski2d.animation.server import WORKERS

    proc = subprocess.Popen(
        [sys.executable, "-m", "minkowski2d", "serve", "--port", "0"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    stalled = []
    try:
        line = proc.stdout.readline()  # the event: the server is listening
        m = re.search(r"http://127\.0\.0\.1:(\d+)/", line)
        assert m, line
        port = int(m.group(1))
        c = http.client.HTTPConnection("127.0.0.1", port, timeout=_GUARD)
        c.request("GET", "/")
        assert c.getresponse().status == 200
        c.close()
        for _ in range(WORKERS + 1):  # every worker busy, one more in the queue
            s = socket.create_connection(("127.0.0.1", port), timeout=_GUARD)
            s.sendall(
                b"POST /api/trace HTTP/1.1\r\nHost: 127.0.0.1\r\n"
                b"Content-Type: application/json\r\nContent-Length: 100\r\n\r\n{"
            )
            stalled.append(s)
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=_GUARD)  # returns when the process exits
        for s in stalled:  # ended by the stop (end of stream or reset), not answered 408
            try:
                got = s.recv(65536)
            except ConnectionError:
                got = b""
            assert not got.startswith(b"HTTP/1.1 408"), got
    finally:
        for s in stalled:
            s.close()
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode == 0
    assert "Traceback" not in err and "stopped" in err
