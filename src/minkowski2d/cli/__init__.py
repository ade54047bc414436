"""The ``minkowski2d`` command (also ``python -m minkowski2d``).

Subcommands: ``demo``, ``sum``, ``inflate``, ``hull``, and those that feature modules
register through ``add_parser(subparsers)`` (animation, collision, general sums, booleans,
offsets, nesting, planning).

Bad input prints one line, ``minkowski2d: error: <what and where> (hint: ...)``, on
standard error (built from the error's fields, :func:`.common.format_error`) and
exits with status 2; no output file is written then. Every command writes through
:func:`.common.write_output`: an output that is one of the inputs (same device and
inode, ``.dat#k`` selectors stripped) or a directory is refused, and the text goes to a
unique ``O_EXCL`` temporary file renamed into place, removed on every error path.
"""

from __future__ import annotations

import argparse
import importlib
import sys
from collections.abc import Sequence

from .common import CLIError, add_io_options, emit, format_error, is_general, output_format
from .features import run_features

__all__ = ["main", "emit", "build_parser", "CLIError", "output_format"]

#: The one plugin table: each module's ``add_parser(subparsers)`` registers its commands.
_PLUGINS = (
    "minkowski2d.cli.animation",
    "minkowski2d.cli.collision",
    "minkowski2d.cli.general",
    "minkowski2d.cli.boolean",
    "minkowski2d.cli.offset",
    "minkowski2d.cli.nesting",
    "minkowski2d.cli.planning",
)


def _cmd_demo(args: argparse.Namespace) -> int:
    from ..animation.page import DEMO_TITLE, SEED_A, SEED_B, render
    from ..convex import minkowski_sum
    from .common import write_output

    s = minkowski_sum(SEED_A, SEED_B)
    print("A (triangle):", [list(p) for p in SEED_A])
    print("B (square):  ", [list(p) for p in SEED_B])
    print("A ⊕ B:       ", s.tolist())
    path = write_output(render(SEED_A, SEED_B, title=DEMO_TITLE), args.output or "animation.html")
    print(f"animation:    {path.resolve()}")
    return 0


def _cmd_sum(args: argparse.Namespace) -> int:
    if (status := run_features(args, "sum")) is not None:  # FeatureCollections, DXF
        return status
    from ..convex import minkowski_sum
    from ..io import format_geometry, read_geometry

    a = read_geometry(args.a)
    b = read_geometry(args.b)
    if not args.hull and (is_general(a, args.a) | is_general(b, args.b)):
        from ..general import minkowski_sum_general

        print(
            "minkowski2d: note: an input is not convex or has holes; using the general sum",
            file=sys.stderr,
        )
        result = minkowski_sum_general(a, b)
    else:
        result = minkowski_sum(a, b, hull=args.hull)
    emit(format_geometry(result, output_format(args)), args.output, [args.a, args.b])
    return 0


def _cmd_inflate(args: argparse.Namespace) -> int:
    if (status := run_features(args, "inflate")) is not None:  # FeatureCollections, DXF
        return status
    from ..convex import cspace_obstacle
    from ..io import format_geometry, read_geometry

    result = cspace_obstacle(
        read_geometry(args.obstacle), read_geometry(args.robot), hull=args.hull
    )
    emit(format_geometry(result, output_format(args)), args.output, [args.obstacle, args.robot])
    return 0


def _cmd_hull(args: argparse.Namespace) -> int:
    if (status := run_features(args, "hull")) is not None:  # FeatureCollections, DXF
        return status
    from ..convex import convex_hull
    from ..io import format_geometry, read_geometry

    result = convex_hull(read_geometry(args.points))
    emit(format_geometry(result, output_format(args)), args.output, [args.points])
    return 0


def build_parser() -> argparse.ArgumentParser:
    """The argument parser with every subcommand registered."""
    from .. import __version__

    parser = argparse.ArgumentParser(
        prog="minkowski2d",
        description="Exact 2-D Minkowski sums of polygons. Inputs are JSON point lists, "
        "GeoJSON (FeatureCollections: one result per feature, properties kept), WKT, CGAL "
        ".dat or DXF files, or - for standard input.",
    )
    parser.add_argument("--version", action="version", version=f"minkowski2d {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    sub.required = True

    p = sub.add_parser("demo", help="the built-in example: triangle ⊕ square (and its animation)")
    p.add_argument("-o", "--output", help="where to write the animation page (animation.html)")
    p.set_defaults(func=_cmd_demo)

    p = sub.add_parser("sum", help="Minkowski sum A ⊕ B")
    p.add_argument("a", help="polygon A (file or -)")
    p.add_argument("b", help="polygon B (file or -)")
    p.add_argument("--hull", action="store_true", help="use the convex hulls of the inputs")
    add_io_options(p)
    p.set_defaults(func=_cmd_sum)

    p = sub.add_parser("inflate", help="configuration-space obstacle: obstacle ⊕ (−robot)")
    p.add_argument("obstacle", help="obstacle polygon (file or -)")
    p.add_argument("robot", help="robot polygon, reference point at its origin (file or -)")
    p.add_argument("--hull", action="store_true", help="use the convex hulls of the inputs")
    add_io_options(p)
    p.set_defaults(func=_cmd_inflate)

    p = sub.add_parser("hull", help="convex hull of a point set")
    p.add_argument("points", help="points (file or -)")
    add_io_options(p)
    p.set_defaults(func=_cmd_hull)

    for name in _PLUGINS:
        importlib.import_module(name).add_parser(sub)
    p = sub.add_parser(
        "completion",
        help="print a shell completion script (bash or zsh)",
        description='Print a completion script: eval "$(minkowski2d completion bash)" '
        "in ~/.bashrc, or minkowski2d completion zsh > ~/.zfunc/_minkowski2d.",
    )
    p.add_argument("shell", choices=("bash", "zsh"), help="the shell")
    p.set_defaults(func=_cmd_completion)
    return parser


def _cmd_completion(args: argparse.Namespace) -> int:
    try:
        import shtab
    except ImportError:
        raise CLIError(
            "shell completion needs shtab", hint="pip install shtab (or minkowski2d[test])"
        ) from None
    sys.stdout.write(shtab.complete(build_parser(), shell=args.shell))
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit status.

    Examples
    --------
    >>> main(["demo", "-o", "/tmp/minkowski2d-doctest.html"])  # doctest: +ELLIPSIS
    A (triangle): [[0, 0], [2, 0], [0, 2]]
    B (square):   [[0, 0], [1, 0], [1, 1], [0, 1]]
    A ⊕ B:        [[0, 0], [3, 0], [3, 1], [1, 3], [0, 3]]
    ...
    0
    """
    from ..errors import GeometryError

    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return int(args.func(args) or 0)
    except BrokenPipeError:
        return 0
    except (GeometryError, CLIError, OSError) as exc:  # OSError: e.g. an unreadable stdin
        print(format_error(exc), file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        return 130
    except Exception as exc:  # the last line of defence: foreign errors from bad data
        from .._engine.foreign import translate

        err = translate(exc, "", "running the command")
        if err is None:
            raise  # a bug: keep the traceback
        print(format_error(err), file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
