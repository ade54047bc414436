"""CLI plugin: ``union``, ``intersection``, ``difference`` and ``xor`` of two polygonal
inputs, exactly (:mod:`minkowski2d.boolean`).

Registered by :mod:`minkowski2d.cli` through :func:`add_parser`. A GeoJSON
FeatureCollection (or a DXF drawing) gives one result per feature, against the other
file's polygon or pairwise with a second collection, properties kept.
"""

from __future__ import annotations

import argparse
from collections.abc import Iterator
from contextlib import contextmanager

#: command name -> (function name in minkowski2d.boolean, help)
_COMMANDS = {
    "union": ("union", "A ∪ B, exactly"),
    "intersection": ("intersection", "A ∩ B, exactly"),
    "difference": ("difference", "A \\ B, exactly"),
    "xor": ("symmetric_difference", "the symmetric difference of A and B, exactly"),
}


def add_parser(subparsers: argparse._SubParsersAction) -> None:
    """Add the ``union``, ``intersection``, ``difference`` and ``xor`` subcommands."""
    from ..boolean import FILL_RULES
    from .common import add_io_options

    for name, (_, help_text) in _COMMANDS.items():
        p = subparsers.add_parser(
            name,
            help=help_text,
            description=f"{help_text[0].upper()}{help_text[1:]}: every vertex of the result "
            "the correctly rounded exact one, the result OGC-valid. Inputs must be valid "
            "polygons (holes allowed; the polygons of one file may overlap: the input is "
            "their union) unless --fill-rule resolves self-intersecting rings.",
        )
        p.add_argument("a", help="polygon A (file or -)")
        p.add_argument("b", help="polygon B (file or -)")
        p.add_argument(
            "--fill-rule",
            choices=FILL_RULES,
            default=None,
            help="resolve self-intersecting input by the winding number of its rings as "
            "given (default: the input must be valid)",
        )
        add_io_options(p)
        p.set_defaults(func=_cmd_boolean)


_CLI_HINT = (
    "repair it (shapely.make_valid), or pass --fill-rule nonzero or --fill-rule evenodd "
    "to resolve self-intersecting rings by a fill rule"
)


@contextmanager
def _cli_hints() -> Iterator[None]:
    """The library's ``fill_rule=`` advice worded as this command's option."""
    from ..errors import GeometryError

    try:
        yield
    except GeometryError as exc:
        if exc.hint and "fill_rule=" in exc.hint:
            raise exc.renamed(exc.argument, _CLI_HINT, False) from None
        raise


def _cmd_boolean(args: argparse.Namespace) -> int:
    from .. import boolean
    from ..io import format_geometry, read_geometry
    from .common import emit, files_named, output_format
    from .features import run_collection

    fn = getattr(boolean, _COMMANDS[args.command][0])

    def op(g: list, names: list) -> object:
        return fn(g[0], g[1], fill_rule=args.fill_rule)

    with _cli_hints():
        if (status := run_collection(args, [args.a, args.b], op)) is not None:
            return status
        a = read_geometry(args.a)
        b = read_geometry(args.b)
        with files_named({"a": args.a, "b": args.b}):
            result = fn(a, b, fill_rule=args.fill_rule)
    emit(format_geometry(result, output_format(args)), args.output, [args.a, args.b])
    return 0
