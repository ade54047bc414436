"""``minkowski2d serve`` (animation/server.py) over real sockets on 127.0.0.1.

The local server: cross-site requests are refused, every malformed request is
answered with a JSON error, and a bounded worker pool answers bursts and survives stalled
uploads. Every test is bounded in connections and time.
"""

from __future__ import annotations

import http.client
import json
import socket
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import pytest

from minkowski2d.animation.server import BACKLOG, MAX_BODY, WORKERS, make_server

GOOD = json.dumps({"a": "0 0, 2 0, 0 2", "b": "0 0, 1 0, 1 1, 0 1"}).encode()


@pytest.fixture()
def server():
    srv = make_server(port=0)
    srv.start_thread()
    yield srv
    srv.shutdown()
    srv.server_close()


def post(srv, body: bytes, headers: dict | None = None, path: str = "/api/trace"):
    h = {"Host": f"127.0.0.1:{srv.server_address[1]}", "Content-Type": "application/json"}
    h.update(headers or {})
    h = {k: v for k, v in h.items() if v is not None}
    c = http.client.HTTPConnection("127.0.0.1", srv.server_address[1], timeout=20)
    try:
        c.request("POST", path, body=body, headers=h)
        r = c.getresponse()
        return r.status, r.getheader("Content-Type"), r.read()
    finally:
        c.close()


def error_of(body: bytes) -> dict:
    err = json.loads(body)["error"]
    assert isinstance(err, dict) and set(err) >= {"type", "message", "argument", "vertex", "hint"}
    assert err["message"]
    return err


class TestLocalServer:
    """Regression tests for the local server."""

    def test_cross_site_post_is_refused(self, server):
        port = server.server_address[1]
        st, _, body = post(server, GOOD, {"Origin": "http://evil.example"})
        assert st == 403 and "cross-site" in error_of(body)["message"]
        # the form-like request a cross-site page can send without a preflight
        st, _, body = post(
            server, GOOD, {"Origin": "http://evil.example", "Content-Type": "text/plain"}
        )
        assert st == 403
        st, _, body = post(server, GOOD, {"Content-Type": "text/plain"})
        assert st == 415 and error_of(body)["hint"] == "Content-Type: application/json"
        st, _, body = post(server, GOOD, {"Origin": "null"})
        assert st == 403
        # the page's own origin, and a JSON content type with parameters, are fine
        for origin in (f"http://127.0.0.1:{port}", f"http://LOCALHOST:{port}"):
            st, _, body = post(
                server, GOOD, {"Origin": origin, "Content-Type": "Application/JSON; charset=utf-8"}
            )
            assert st == 200 and "trace" in json.loads(body), origin

    def test_host_check_is_case_insensitive(self, server):
        port = server.server_address[1]
        for host in (f"LOCALHOST:{port}", f"LocalHost:{port}", "127.0.0.1"):
            st, _, _ = post(server, GOOD, {"Host": host})
            assert st == 200, host
        for host in ("Evil.Example", f"evil.example:{port}", "127.0.0.1.evil.example"):
            st, _, _ = post(server, GOOD, {"Host": host})
            assert st == 421, host

    @pytest.mark.parametrize(
        "body, status, words",
        [
            (b"[" * 100_000 + b"]" * 100_000, 400, "nested too deeply"),
            (b"{not json", 400, "not valid JSON"),
            (b"\xff\xfe\x00binary", 400, "not valid JSON"),
            (b"[1, 2]", 400, "JSON object"),
            (b'{"a": 5, "b": "0 0"}', 400, "A: expected text"),
            (b'{"a": "0 0", "b": {"x": 1}}', 400, "B: expected text"),
            (b'{"a": {"type": "Polygon"}, "b": "0 0"}', 400, "A: expected text"),
            (b'{"a": "0 0", "b": "0 0", "robot": 7}', 400, "robot: expected text"),
            (b'{"a": "{\\"type\\": \\"Polygon\\"}", "b": "0 0"}', 200, "without coordinates"),
            (
                b'{"a": "{\\"type\\": \\"Polygon\\", \\"coordinates\\": []}", "b": "0 0"}',
                200,
                "without coordinates",
            ),
            (b'{"a": "0 0.2/45, 1 0", "b": "0 0"}', 200, "cannot read the number"),
            (b'{"a": "' + b"[" * 5000 + b'", "b": "0 0"}', 200, "nested too deeply"),
            (b'{"a": [[1e400, 0]], "b": "0 0"}', 200, "non-finite"),
            (b'{"a": [[' + b"9" * 400 + b', 0], [0, 1], [1, 0]], "b": "0 0"}', 200, "float range"),
        ],
    )
    def test_malformed_bodies_are_answered(self, server, body, status, words):
        st, ctype, answer = post(server, body)
        assert st == status and ctype == "application/json"
        assert words in error_of(answer)["message"]

    def test_body_size_and_length_are_capped(self, server):
        port = server.server_address[1]
        for size in (MAX_BODY + 1, 4 * MAX_BODY):  # read and dropped: the client sees the 413
            st, _, body = post(server, b" " * size)
            assert st == 413 and "too large" in error_of(body)["message"]
        # a declared length over the cap is refused before any body is read
        with socket.create_connection(("127.0.0.1", port), timeout=10) as s:
            s.sendall(
                b"POST /api/trace HTTP/1.1\r\nHost: 127.0.0.1\r\n"
                b"Content-Type: application/json\r\nContent-Length: 99999999999\r\n\r\n"
            )
            head = s.recv(65536)
        assert head.startswith(b"HTTP/1.1 413")
        with socket.create_connection(("127.0.0.1", port), timeout=10) as s:
            s.sendall(
                b"POST /api/trace HTTP/1.1\r\nHost: 127.0.0.1\r\n"
                b"Content-Type: application/json\r\n\r\n"
            )
            head = s.recv(65536)
        assert head.startswith(b"HTTP/1.1 411")

    def test_forty_simultaneous_requests_are_all_answered(self, server):
        assert BACKLOG >= 128 and server.request_queue_size >= 128
        barrier = threading.Barrier(40, timeout=20)

        def one(_):
            barrier.wait()
            return post(server, GOOD)[0]

        with ThreadPoolExecutor(40) as ex:
            statuses = list(ex.map(one, range(40), timeout=120))
        assert statuses == [200] * 40

    def test_stalled_uploads_use_a_bounded_pool_and_time_out(self):
        srv = make_server(port=0, workers=4, timeout=1.0)
        srv.start_thread()
        port = srv.server_address[1]
        before = threading.active_count()
        stalled = []
        try:
            for _ in range(16):  # each promises a body and sends nothing
                s = socket.create_connection(("127.0.0.1", port), timeout=30)
                s.sendall(
                    b"POST /api/trace HTTP/1.1\r\nHost: 127.0.0.1\r\n"
                    b"Content-Type: application/json\r\nContent-Length: 100\r\n\r\n"
                )
                stalled.append(s)
            time.sleep(0.3)
            # 16 stalled uploads, but at most 4 handler threads (+ slack for the pool's churn)
            assert threading.active_count() - before <= 4 + 1
            t0 = time.monotonic()
            st, _, _ = post(srv, GOOD)
            assert st == 200
            # the pool drains 4 stalled uploads a second: about 4 s, never unbounded
            assert time.monotonic() - t0 < 15
            for s in stalled:  # each stalled upload got an answer: 408, not silence
                s.settimeout(15)
                assert s.recv(65536).startswith(b"HTTP/1.1 408")
        finally:
            for s in stalled:
                s.close()
            srv.shutdown()
            srv.server_close()

    def test_413_from_content_length_alone(self):
        """A declared body over the cap is answered at once, before any byte of it is
        sent: the server does not wait for the body (here it would wait an
        hour); the client's socket guard is never what the test waits for."""
        srv = make_server(port=0, timeout=3600.0)
        srv.start_thread()
        port = srv.server_address[1]
        try:
            for n in (MAX_BODY + 1, 2 * MAX_BODY, 99 * MAX_BODY):
                with socket.create_connection(("127.0.0.1", port), timeout=600) as s:
                    s.sendall(
                        b"POST /api/trace HTTP/1.1\r\nHost: 127.0.0.1\r\n"
                        b"Content-Type: application/json\r\nContent-Length: %d\r\n\r\n" % n
                    )
                    head = b""
                    while b"\r\n\r\n" not in head:
                        chunk = s.recv(65536)
                        assert chunk, head
                        head += chunk
                    assert head.startswith(b"HTTP/1.1 413") and b"Connection: close" in head
            # a client still sending its (oversized) body also reads the 413
            st, _, body = post(srv, b" " * (3 * MAX_BODY))
            assert st == 413 and "too large" in error_of(body)["message"]
        finally:
            srv.shutdown()
            srv.server_close()

    def test_stop_ends_open_connections(self):
        """AnimationServer.stop ends every open connection at once, whatever the worker
        is doing (here: waiting for a body that never comes, for an hour)."""
        srv = make_server(port=0, timeout=3600.0)
        t = srv.start_thread()
        port = srv.server_address[1]
        s = socket.create_connection(("127.0.0.1", port), timeout=600)
        try:
            s.sendall(
                b"POST /api/trace HTTP/1.1\r\nHost: 127.0.0.1\r\n"
                b"Content-Type: application/json\r\nContent-Length: 100\r\n\r\n{"
            )
            # the worker holds the connection once the server answers a second client
            assert post(srv, GOOD)[0] == 200
            srv.shutdown()
            t.join()
            srv.stop()
            try:
                got = s.recv(65536)
            except ConnectionError:
                got = b""
            assert got == b""  # ended, not answered
        finally:
            s.close()

    def test_defaults(self):
        assert WORKERS <= 16
        srv = make_server(port=0)
        try:
            assert srv.timeout_s == 10.0 and srv.request_queue_size == 128
        finally:
            srv.server_close()
