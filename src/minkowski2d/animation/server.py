"""``minkowski2d serve``: the animation page in an editable mode, on 127.0.0.1 only.

``GET /`` returns the page (the same template as the static file, with the editor
shown); ``POST /api/trace`` takes the polygons as JSON and answers the new page data,
or ``{"error": message}`` for input the geometry rejects (status 200: the answer is
"this input is not valid"; 4xx is kept for malformed requests). All geometry
runs here, in Python; the page only plays back what it is sent.
"""

from __future__ import annotations

import json
import sys
import threading
from http import HTTPStatus
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Any

from ..errors import GeometryError, ShapeError
from .page import SEED_A, SEED_B, page_data, parse_points, render

__all__ = ["AnimationServer", "make_server", "polygons_from_request"]

HOST = "127.0.0.1"
MAX_BODY = 1 << 20  # bytes


def _polygon(value: Any, name: str) -> Any:
    if value is None:
        return None
    if isinstance(value, str):
        return parse_points(value, name)
    if isinstance(value, list):
        return [tuple(p) if isinstance(p, list) else p for p in value]
    raise ShapeError(f"{name}: expected text or a list of (x, y) pairs")


def polygons_from_request(body: dict) -> dict:
    """The keyword arguments of :func:`~minkowski2d.animation.page.page_data` from a
    request body ``{"a", "b", "obstacle"?, "robot"?, "hull"?, "view"?}``.

    Examples
    --------
    >>> polygons_from_request({"a": "0 0, 2 0, 0 2", "b": [[0, 0], [1, 1]]})["b"]
    [(0, 0), (1, 1)]
    """
    if not isinstance(body, dict):
        raise ShapeError("the request must be a JSON object")
    view = body.get("view")
    if not isinstance(view, dict):
        view = None
    return {
        "a": _polygon(body.get("a", ""), "A"),
        "b": _polygon(body.get("b", ""), "B"),
        "obstacle": _polygon(body.get("obstacle"), "obstacle"),
        "robot": _polygon(body.get("robot"), "robot"),
        "hull": bool(body.get("hull", False)),
        "hold_view": view,
        "roomy": True,
    }


class _Handler(BaseHTTPRequestHandler):
    server: AnimationServer
    server_version = "minkowski2d"
    protocol_version = "HTTP/1.1"
    timeout = 60  # seconds an idle keep-alive connection is kept

    def log_message(self, format: str, *args: Any) -> None:  # noqa: A002
        if self.server.verbose:
            super().log_message(format, *args)

    def _send(self, status: int, body: bytes, ctype: str) -> None:
        self.send_response(status)
        self.send_header("Content-Type", ctype)
        self.send_header("Content-Length", str(len(body)))
        self.send_header("Cache-Control", "no-store")
        self.send_header("X-Content-Type-Options", "nosniff")
        self.end_headers()
        if self.command != "HEAD":
            self.wfile.write(body)

    def _json(self, status: int, obj: Any) -> None:
        self._send(status, json.dumps(obj, allow_nan=False).encode(), "application/json")

    def _host_ok(self) -> bool:
        # refuse requests addressed to another host name (DNS rebinding)
        host = (self.headers.get("Host") or "").rsplit(":", 1)[0].strip("[]")
        return host in ("127.0.0.1", "localhost", "")

    def do_GET(self) -> None:  # noqa: N802
        if not self._host_ok():
            self._send(HTTPStatus.MISDIRECTED_REQUEST, b"wrong host\n", "text/plain")
            return
        path = self.path.split("?", 1)[0]
        if path in ("/", "/index.html", "/animation.html"):
            page = self.server.page().encode("utf-8")
            self._send(HTTPStatus.OK, page, "text/html; charset=utf-8")
        elif path == "/favicon.ico":
            self._send(HTTPStatus.NO_CONTENT, b"", "image/x-icon")
        else:
            self._send(HTTPStatus.NOT_FOUND, b"not found\n", "text/plain")

    do_HEAD = do_GET

    def do_POST(self) -> None:  # noqa: N802
        if not self._host_ok():
            self._send(HTTPStatus.MISDIRECTED_REQUEST, b"wrong host\n", "text/plain")
            return
        if self.path.split("?", 1)[0] != "/api/trace":
            self._json(HTTPStatus.NOT_FOUND, {"error": "not found"})
            return
        try:
            n = int(self.headers.get("Content-Length", ""))
        except ValueError:
            self._json(HTTPStatus.LENGTH_REQUIRED, {"error": "Content-Length required"})
            return
        if n < 0 or n > MAX_BODY:
            self.close_connection = True
            self._json(HTTPStatus.REQUEST_ENTITY_TOO_LARGE, {"error": "request too large"})
            return
        raw = self.rfile.read(n)
        try:
            body = json.loads(raw.decode("utf-8"))
        except (UnicodeDecodeError, ValueError):
            self._json(HTTPStatus.BAD_REQUEST, {"error": "the request is not valid JSON"})
            return
        # Input the geometry rejects is an answer, not a protocol failure: status 200 with
        # {"error": ...}, which the page shows (a 4xx would also log a console error).
        try:
            data = page_data(**polygons_from_request(body))
        except GeometryError as exc:
            self._json(HTTPStatus.OK, {"error": str(exc)})
            return
        except (ValueError, TypeError, OverflowError) as exc:
            self._json(HTTPStatus.OK, {"error": f"cannot use this input: {exc}"})
            return
        self._json(HTTPStatus.OK, data)


class AnimationServer(ThreadingHTTPServer):
    """The editable animation page and its trace API, bound to 127.0.0.1.

    Parameters
    ----------
    a, b, obstacle, robot : (n, 2) array_like
        The polygons the page starts with.
    port : int, default 0
        0 picks a free port; see :attr:`url`.
    verbose : bool, default False
        Log each request to stderr.
    """

    daemon_threads = True
    allow_reuse_address = True

    def __init__(
        self,
        a: Any = SEED_A,
        b: Any = SEED_B,
        *,
        obstacle: Any = None,
        robot: Any = None,
        hull: bool = False,
        port: int = 0,
        verbose: bool = False,
    ) -> None:
        # compute (and validate) the first page before binding the port
        self._data = page_data(a, b, obstacle=obstacle, robot=robot, hull=hull, roomy=True)
        self.verbose = verbose
        super().__init__((HOST, port), _Handler)

    def handle_error(self, request: Any, client_address: Any) -> None:
        # a browser closing a kept-alive connection is not an error worth a traceback
        if isinstance(sys.exc_info()[1], (ConnectionError, TimeoutError)):
            return
        super().handle_error(request, client_address)

    @property
    def url(self) -> str:
        """``http://127.0.0.1:PORT/``."""
        return f"http://{HOST}:{self.server_address[1]}/"

    def page(self) -> str:
        return render(None, None, data=self._data, editable=True, api="/api/trace")

    def start_thread(self) -> threading.Thread:
        """Serve from a daemon thread (for tests and notebooks); stop with ``shutdown()``."""
        t = threading.Thread(target=self.serve_forever, name="minkowski2d-serve", daemon=True)
        t.start()
        return t


def make_server(a: Any = SEED_A, b: Any = SEED_B, *, port: int = 0, **kw: Any) -> AnimationServer:
    """A ready :class:`AnimationServer` (not yet serving).

    Examples
    --------
    >>> srv = make_server(port=0)
    >>> srv.url.startswith("http://127.0.0.1:")
    True
    >>> srv.server_close()
    """
    return AnimationServer(a, b, port=port, **kw)
