"""``minkowski2d serve``: the animation page in an editable mode, on 127.0.0.1 only.

``GET /`` returns the page (the same template as the static file, with the editor
shown); ``POST /api/trace`` takes the polygons as JSON and answers the new page data.

Every answer that is not page data is ``{"error": {...}}``, the fields of
:meth:`~minkowski2d.errors.GeometryError.to_dict` (``type``, ``message``, ``argument``,
``vertex``, ``hint``), which the page shows:

- polygons the geometry rejects (not convex, NaN, typed text it cannot read): status 200
  (the answer is "this input is not valid"; the page keeps the last good state);
- a malformed request: 400 (not JSON, nested too deeply, not an object, a polygon that
  is neither text nor a list), 403 (a cross-site ``Origin``), 404, 411 (no
  Content-Length), 413 (a body over :data:`MAX_BODY`), 415 (not ``application/json``),
  421 (another ``Host``: DNS rebinding), 408 (the body did not arrive in time).

At most :data:`WORKERS` requests are handled at once (more wait in the listen queue of
:data:`BACKLOG`), and each connection times out after :data:`TIMEOUT` idle seconds, so
neither a burst of requests nor stalled uploads can exhaust the process.
"""

from __future__ import annotations

import json
import socket
import sys
import threading
from http import HTTPStatus
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Any

from ..errors import GeometryError, InputFormatError, ShapeError
from .page import SEED_A, SEED_B, page_data, parse_points, render

__all__ = ["AnimationServer", "make_server", "polygons_from_request"]

HOST = "127.0.0.1"
MAX_BODY = 1 << 20  # bytes
WORKERS = 8  # requests handled at once
BACKLOG = 128  # connections the kernel queues while every worker is busy
TIMEOUT = 10.0  # seconds a connection may stay silent (headers, body, keep-alive)
LINGER = 2.0  # seconds an oversized upload may keep sending after its 413 (then closed)
_DRAIN_LIMIT = 16 * MAX_BODY  # at most this much of an oversized body is read and dropped


class RequestError(Exception):
    """A malformed request: answered with ``status`` and ``{"error": {...}}``."""

    def __init__(
        self, status: int, message: str, hint: str | None = None, argument: str | None = None
    ) -> None:
        super().__init__(message)
        self.status = status
        self.hint = hint
        self.argument = argument

    def to_dict(self) -> dict[str, object]:
        return {
            "type": "RequestError",
            "message": str(self),
            "argument": self.argument,
            "vertex": None,
            "hint": self.hint,
        }


_FIELDS = {"a": "A", "b": "B", "obstacle": "obstacle", "robot": "robot"}


def _check_body(body: Any) -> dict:
    """The request object, or a 400 RequestError naming the field of the wrong JSON type."""
    if not isinstance(body, dict):
        raise RequestError(
            HTTPStatus.BAD_REQUEST,
            "the request must be a JSON object",
            hint='send {"a": "0 0, 2 0, 0 2", "b": "0 0, 1 0, 1 1, 0 1"}',
        )
    for key, name in _FIELDS.items():
        v = body.get(key)
        if v is None and key in ("obstacle", "robot"):
            continue
        if key in ("a", "b") and key not in body:
            continue
        if not isinstance(v, (str, list)):
            raise RequestError(
                HTTPStatus.BAD_REQUEST,
                f"{name}: expected text or a list of (x, y) pairs, not {type(v).__name__}",
                argument=name,
            )
    return body


def _polygon(value: Any, name: str) -> Any:
    if value is None:
        return None
    if isinstance(value, str):
        return parse_points(value, name)
    if isinstance(value, list):
        return [tuple(p) if isinstance(p, list) else p for p in value]
    raise ShapeError(f"{name}: expected text or a list of (x, y) pairs", argument=name)


def polygons_from_request(body: dict) -> dict:
    """The keyword arguments of :func:`~minkowski2d.animation.page.page_data` from a
    request body ``{"a", "b", "obstacle"?, "robot"?, "hull"?, "view"?}``.

    Examples
    --------
    >>> polygons_from_request({"a": "0 0, 2 0, 0 2", "b": [[0, 0], [1, 1]]})["b"]
    [(0, 0), (1, 1)]
    """
    if not isinstance(body, dict):
        raise ShapeError(
            "the request must be a JSON object", hint='send {"a": "0 0, 2 0, 0 2", "b": ...}'
        )
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

    def setup(self) -> None:
        # every read and write on the socket (typeshed calls timeout a ClassVar; setup()
        # reads it from the instance)
        self.timeout = self.server.timeout_s  # type: ignore[misc]
        super().setup()

    def log_message(self, format: str, *args: Any) -> None:  # noqa: A002
        if self.server.verbose:
            super().log_message(format, *args)

    def _send(self, status: int, body: bytes, ctype: str) -> None:
        self.send_response(status)
        self.send_header("Content-Type", ctype)
        self.send_header("Content-Length", str(len(body)))
        self.send_header("Cache-Control", "no-store")
        self.send_header("X-Content-Type-Options", "nosniff")
        if self.close_connection:
            self.send_header("Connection", "close")
        self.end_headers()
        if self.command != "HEAD":
            self.wfile.write(body)

    def _json(self, status: int, obj: Any) -> None:
        self._send(status, json.dumps(obj, allow_nan=False).encode(), "application/json")

    def _error(self, status: int, exc: Any) -> None:
        self._json(status, {"error": exc.to_dict()})

    def _host_ok(self) -> bool:
        # refuse requests addressed to another host name (DNS rebinding)
        host = (self.headers.get("Host") or "").strip().lower()
        if host.startswith("["):
            host = host[1:].split("]", 1)[0]
        else:
            host = host.rsplit(":", 1)[0]
        return host in ("127.0.0.1", "localhost", "")

    def _origin_ok(self) -> bool:
        # a browser names the page a request comes from; only our own pages may post
        origin = self.headers.get("Origin")
        if origin is None:
            return True
        port = self.server.server_address[1]
        return origin.strip().lower() in (f"http://127.0.0.1:{port}", f"http://localhost:{port}")

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
        try:
            body = self._read_request()
        except RequestError as exc:
            if exc.status >= 408:
                self.close_connection = True  # the body may be unread
            self._error(exc.status, exc)
            if exc.status == HTTPStatus.REQUEST_ENTITY_TOO_LARGE:
                self._linger()
            return
        # Input the geometry rejects is an answer, not a protocol failure: status 200 with
        # {"error": ...}, which the page shows (a 4xx would also log a console error).
        try:
            data = page_data(**polygons_from_request(body))
        except GeometryError as exc:
            self._error(HTTPStatus.OK, exc)
            return
        except (ValueError, TypeError, ArithmeticError, RecursionError) as exc:
            err: Exception = InputFormatError(f"cannot use this input: {exc}")
            self._error(HTTPStatus.OK, err)
            return
        except Exception as exc:  # a bug: still answer, and keep the traceback in the log
            self.server.handle_error(self.request, self.client_address)
            err = RequestError(HTTPStatus.INTERNAL_SERVER_ERROR, f"internal error: {exc!r}")
            self._error(HTTPStatus.INTERNAL_SERVER_ERROR, err)
            return
        try:
            text = json.dumps(data, allow_nan=False)
        except ValueError:
            err = GeometryError("a coordinate is not finite after drawing; cannot render")
            self._error(HTTPStatus.OK, err)
            return
        self._send(HTTPStatus.OK, text.encode(), "application/json")

    def _linger(self) -> None:
        """After a 413 sent from the Content-Length alone: end our side of the connection
        (the client sees the whole answer), then read and drop what the client is still
        sending, at most :data:`_DRAIN_LIMIT` bytes or :data:`LINGER` idle seconds, so
        that closing does not reset the connection under the answer."""
        try:
            self.wfile.flush()
            self.connection.shutdown(socket.SHUT_WR)
            self.connection.settimeout(min(LINGER, self.server.timeout_s))
        except OSError:
            return
        self._drain(_DRAIN_LIMIT)

    def _drain(self, n: int) -> None:
        """Read and drop up to ``n`` bytes of an unwanted body."""
        try:
            while n > 0:
                chunk = self.rfile.read(min(n, 1 << 16))
                if not chunk:
                    return
                n -= len(chunk)
        except (OSError, ValueError):
            return

    def _read_request(self) -> Any:
        """The JSON body of a well-formed API request, or a RequestError."""
        if not self._host_ok():
            raise RequestError(HTTPStatus.MISDIRECTED_REQUEST, "wrong host")
        if not self._origin_ok():
            raise RequestError(HTTPStatus.FORBIDDEN, "cross-site requests are refused")
        if self.path.split("?", 1)[0] != "/api/trace":
            raise RequestError(HTTPStatus.NOT_FOUND, "not found", hint="POST /api/trace")
        ctype = (self.headers.get("Content-Type") or "").split(";", 1)[0].strip().lower()
        if ctype != "application/json":
            raise RequestError(
                HTTPStatus.UNSUPPORTED_MEDIA_TYPE,
                "the request must be application/json",
                hint="Content-Type: application/json",
            )
        if self.headers.get("Transfer-Encoding"):
            raise RequestError(HTTPStatus.LENGTH_REQUIRED, "Content-Length required")
        raw_len = (self.headers.get("Content-Length") or "").strip()
        if not (raw_len.isascii() and raw_len.isdigit()) or len(raw_len) > 12:
            raise RequestError(HTTPStatus.LENGTH_REQUIRED, "Content-Length required")
        n = int(raw_len)
        if n > MAX_BODY:  # answered at once; the body is drained after the answer
            raise RequestError(
                HTTPStatus.REQUEST_ENTITY_TOO_LARGE,
                f"request too large ({n} bytes; at most {MAX_BODY})",
            )
        try:
            raw = self.rfile.read(n)
        except TimeoutError:
            raise RequestError(
                HTTPStatus.REQUEST_TIMEOUT, "the request body did not arrive"
            ) from None
        if len(raw) < n:
            raise RequestError(HTTPStatus.BAD_REQUEST, "the request body ended early")
        try:
            return _check_body(json.loads(raw.decode("utf-8")))
        except RecursionError:
            raise RequestError(
                HTTPStatus.BAD_REQUEST, "the request JSON is nested too deeply"
            ) from None
        except (UnicodeDecodeError, ValueError):
            raise RequestError(HTTPStatus.BAD_REQUEST, "the request is not valid JSON") from None


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
    workers : int, default :data:`WORKERS`
        Requests handled at once; more connections wait in the listen queue.
    timeout : float, default :data:`TIMEOUT`
        Seconds a connection may stay silent before it is closed.
    """

    daemon_threads = True
    allow_reuse_address = True
    request_queue_size = BACKLOG

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
        workers: int = WORKERS,
        timeout: float = TIMEOUT,
    ) -> None:
        # compute (and validate) the first page before binding the port
        self._data = page_data(a, b, obstacle=obstacle, robot=robot, hull=hull, roomy=True)
        self.verbose = verbose
        self.timeout_s = float(timeout)
        self._slots = threading.BoundedSemaphore(max(1, int(workers)))
        self._active: set = set()  # the connections being served
        self._lock = threading.Lock()
        super().__init__((HOST, port), _Handler)

    def process_request(self, request: Any, client_address: Any) -> None:
        # a bounded pool: wait (accepting nothing more) until one of the workers is free
        self._slots.acquire()
        with self._lock:
            self._active.add(request)
        t = threading.Thread(target=self._work, args=(request, client_address), daemon=True)
        try:
            t.start()
        except RuntimeError:  # no thread could be started: this request is dropped
            with self._lock:
                self._active.discard(request)
            self._slots.release()
            self.shutdown_request(request)
            raise
        # (an interrupt inside start() leaves the request to the thread, which runs, and
        # to stop(), which ends its connection)

    def _work(self, request: Any, client_address: Any) -> None:
        try:
            self.process_request_thread(request, client_address)
        finally:
            with self._lock:
                self._active.discard(request)
            self._slots.release()

    def stop(self) -> None:
        """Stop at once, whatever the workers are doing: close the listening socket and
        end every open connection (a worker waiting on its client sees the end of the
        stream; one computing finishes into a closed socket). Workers are daemon threads,
        so the process can exit without waiting for them."""
        self.server_close()
        with self._lock:
            active = list(self._active)
        for request in active:
            try:
                request.shutdown(socket.SHUT_RDWR)
            except OSError:
                pass

    def handle_error(self, request: Any, client_address: Any) -> None:
        # a browser closing a kept-alive connection, a silent client timing out, or a
        # connection ended by stop(), is not an error worth a traceback
        if isinstance(sys.exc_info()[1], (ConnectionError, TimeoutError)):
            return
        if self.socket.fileno() == -1:  # stopped: the connection was ended under it
            return
        super().handle_error(request, client_address)

    @property
    def url(self) -> str:
        """``http://127.0.0.1:PORT/``."""
        return f"http://{HOST}:{self.server_address[1]}/"

    def page(self) -> str:
        # with data=, render does not read a and b
        return render(None, None, data=self._data, editable=True, api="/api/trace")  # type: ignore[arg-type]

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
