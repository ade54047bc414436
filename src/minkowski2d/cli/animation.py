"""``minkowski2d animate`` and ``minkowski2d serve`` (a plugin of :mod:`minkowski2d.cli`)."""

from __future__ import annotations

import argparse
import re
import signal
import sys
from pathlib import Path
from typing import Any

__all__ = ["add_parser", "read_polygon"]

_INLINE = re.compile(r"^[\s\d.,;:()\[\]eE+\-/]+$")
_NAME_MAX = 255  # the longest file name (one path component) common file systems take


def _is_inline(arg: str) -> bool:
    """True when ``arg`` is a polygon typed inline rather than a file name: it is made of
    numbers and separators only, and no file has that name. A text longer than a file
    name can be (255 bytes) is never looked up as one."""
    if arg == "-" or not _INLINE.match(arg) or not re.search(r"\d", arg):
        return False
    if len(arg.encode("utf-8", "surrogateescape")) > _NAME_MAX:
        return True
    try:
        return not Path(arg).exists()
    except (OSError, ValueError):
        return True


def read_polygon(arg: str, name: str) -> Any:
    """A polygon from a file (JSON, GeoJSON, WKT, CGAL .dat), ``-`` for standard input,
    or written inline: ``"0,0 2,0 0,2"`` or ``"[[0,0],[2,0],[0,2]]"``.

    Examples
    --------
    >>> read_polygon("(0, 0), (2, 0), (0, 2)", "A")
    [(0, 0), (2, 0), (0, 2)]
    """
    if _is_inline(arg):
        from ..animation.page import parse_points

        return parse_points(arg, name)
    from ..io import read_geometry

    return read_geometry(arg)


def _cli_hint(exc: Exception) -> Exception:
    """The same error, pointing to --hull instead of the page's or library's advice."""
    from ..errors import GeometryError
    from .common import CLI_HULL_HINT, renamed_error

    if isinstance(exc, GeometryError):
        return renamed_error(exc, hull_hint=CLI_HULL_HINT)
    return exc


def _cspace_args(args: argparse.Namespace) -> dict:
    return {
        "obstacle": None if args.obstacle is None else read_polygon(args.obstacle, "obstacle"),
        "robot": None if args.robot is None else read_polygon(args.robot, "robot"),
        "hull": args.hull,
    }


def _cmd_animate(args: argparse.Namespace) -> int:
    from ..animation.page import render
    from ..errors import GeometryError
    from .common import emit

    a = read_polygon(args.a, "A")
    b = read_polygon(args.b, "B")
    try:
        page = render(a, b, title=args.title, **_cspace_args(args))
    except GeometryError as exc:
        raise _cli_hint(exc) from None
    inputs = [
        p
        for p in (args.a, args.b, args.obstacle, args.robot)
        if p is not None and not _is_inline(p)
    ]
    emit(page, args.output, inputs)
    if args.output not in (None, "-"):
        print(Path(args.output).resolve())
    return 0


def _cmd_serve(args: argparse.Namespace) -> int:
    from ..animation.page import SEED_A, SEED_B
    from ..animation.server import AnimationServer
    from ..errors import GeometryError
    from .common import CLIError

    if (args.a is None) != (args.b is None):
        raise CLIError("serve: give both polygons A and B, or neither (for the built-in example)")
    a = SEED_A if args.a is None else read_polygon(args.a, "A")
    b = SEED_B if args.b is None else read_polygon(args.b, "B")
    if not 0 <= args.port <= 65535:
        raise CLIError(f"--port {args.port}: not a port number (0 picks a free one)")
    try:
        srv = AnimationServer(a, b, port=args.port, verbose=args.verbose, **_cspace_args(args))
    except GeometryError as exc:
        raise _cli_hint(exc) from None
    except OSError as exc:
        raise CLIError(
            f"cannot listen on 127.0.0.1:{args.port} ({exc.strerror}); try --port 0"
        ) from None
    # Ctrl-C stops the server even when this process was started with SIGINT ignored
    # (a background job, nohup): the child inherits the ignored signal otherwise
    signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        print(f"Serving the editable animation at {srv.url}  (Ctrl-C to stop)", flush=True)
        srv.serve_forever()
    except KeyboardInterrupt:
        print("\nstopped", file=sys.stderr, flush=True)
    finally:
        srv.stop()  # at once: open connections are ended, workers are not waited for
    return 0


def add_parser(subparsers: Any) -> None:
    """Register ``animate`` and ``serve`` on the ``minkowski2d`` command's subparsers."""
    poly_help = "file (JSON, GeoJSON, WKT, .dat), - for stdin, or inline like '0,0 2,0 0,2'"

    p = subparsers.add_parser(
        "animate",
        help="write the interactive animation of the edge merge A ⊕ B (one HTML file)",
        description="Write a self-contained HTML page that steps through the merge of A "
        "and B, with the configuration-space scene obstacle ⊕ (−robot). No network needed.",
    )
    p.add_argument("a", help=f"convex polygon A: {poly_help}")
    p.add_argument("b", help=f"convex polygon B: {poly_help}")
    p.add_argument(
        "-o",
        "--output",
        default="animation.html",
        help="the page to write (default: animation.html; - for standard output)",
    )
    _add_common(p)
    p.add_argument("--title", help="page title")
    p.set_defaults(func=_cmd_animate)

    p = subparsers.add_parser(
        "serve",
        help="serve the animation on 127.0.0.1 with editable polygons",
        description="Serve the animation page in an editable mode on 127.0.0.1: drag or "
        "type vertices and the server computes the new trace. Ctrl-C stops it.",
    )
    p.add_argument("a", nargs="?", help=f"polygon A (default: the seed's triangle): {poly_help}")
    p.add_argument("b", nargs="?", help=f"polygon B (default: the seed's square): {poly_help}")
    p.add_argument("--port", type=int, default=8765, help="port (default 8765; 0 picks a free one)")
    p.add_argument("--verbose", action="store_true", help="log each request")
    _add_common(p)
    p.set_defaults(func=_cmd_serve)


def _add_common(p: argparse.ArgumentParser) -> None:
    p.add_argument("--obstacle", help="obstacle for the configuration-space scene (default: A)")
    p.add_argument("--robot", help="robot for the configuration-space scene (default: B)")
    p.add_argument("--hull", action="store_true", help="use the convex hulls of A and B")
