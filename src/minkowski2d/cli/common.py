"""What every ``minkowski2d`` subcommand shares: writing its output safely, the output
options, and the one-line error report.

The plugin modules (:mod:`minkowski2d.cli.collision`, :mod:`minkowski2d.cli.general`,
:mod:`minkowski2d.cli.animation`) import from here, not from :mod:`minkowski2d.cli`.

Writing (:func:`emit`) never loses a file:

- the output is refused when it is one of the inputs: same file by device and inode
  (``os.stat``), or same resolved path, with ``.dat`` selectors (``two.dat#2``) stripped;
- the text goes to a new, uniquely named temporary file beside the output, created with
  ``O_EXCL`` (:func:`tempfile.mkstemp`), so neither an existing ``OUT.tmp`` nor a symlink
  planted there is ever opened; it is renamed into place with :func:`os.replace` only once
  it is complete, and removed on every error path;
- an output that is a directory is refused before anything is created.
"""

from __future__ import annotations

import argparse
import os
import stat
import sys
import tempfile
from collections.abc import Iterable, Iterator, Mapping
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from .._engine.arcs import DEFAULT_RELATIVE_TOLERANCE
from ..errors import GeometryError

__all__ = [
    "CLIError",
    "emit",
    "write_output",
    "add_io_options",
    "add_arc_option",
    "output_format",
    "format_error",
    "renamed_error",
    "same_file",
    "files_named",
]

#: the API hint the library puts in NotConvexError messages, and its command-line form
CLI_HULL_HINT = "use --hull to use the convex hull"


class CLIError(Exception):
    """A usage problem reported as one line (exit status 2)."""

    def __init__(self, message: str, *, hint: str | None = None) -> None:
        super().__init__(message)
        self.hint = hint


def _stat(path: str) -> os.stat_result | None:
    try:
        return os.stat(path)
    except (OSError, ValueError):
        return None


def _resolved(path: str) -> str | None:
    try:
        return str(Path(path).resolve())
    except (OSError, RuntimeError, ValueError):
        return None


def same_file(a: str, b: str) -> bool:
    """True when the paths ``a`` and ``b`` name one file: the same device and inode, or
    (for files that do not exist yet) the same resolved path. ``.dat`` selectors
    (``two.dat#1``) are stripped first.

    Examples
    --------
    >>> import tempfile, os
    >>> d = tempfile.mkdtemp(); f = os.path.join(d, "two.dat"); _ = open(f, "w").close()
    >>> same_file(f + "#1", os.path.join(d, ".", "two.dat"))
    True
    """
    from ..io import split_selector

    a, _ = split_selector(a)
    b, _ = split_selector(b)
    sa, sb = _stat(a), _stat(b)
    if sa is not None and sb is not None:
        return (sa.st_dev, sa.st_ino) == (sb.st_dev, sb.st_ino)
    ra, rb = _resolved(a), _resolved(b)
    return ra is not None and ra == rb


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def write_output(text: str, output: str | os.PathLike, inputs: Iterable[str] = ()) -> Path:
    """Write ``text`` (UTF-8) to the file ``output``, atomically; see the module docs.

    Raises :class:`CLIError` (nothing written, nothing left behind) when ``output`` is one
    of ``inputs``, is a directory, or cannot be written.
    """
    out = Path(output)
    name = str(output)
    for src in inputs:
        if src is None or str(src) == "-":
            continue
        if same_file(str(src), name):
            raise CLIError(
                f"refusing to overwrite the input file {src}",
                hint="choose another -o file",
            )
    st = _stat(name)
    if st is not None and stat.S_ISDIR(st.st_mode):
        raise CLIError(f"cannot write {name}: it is a directory", hint="give a file name")
    if st is not None and not stat.S_ISREG(st.st_mode):
        raise CLIError(
            f"cannot write {name}: not a regular file", hint="use -o - for standard output"
        )
    mode = stat.S_IMODE(st.st_mode) if st is not None else 0o666 & ~_umask()
    parent = out.parent
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{out.name[:64]}.", suffix=".tmp", dir=parent)
    except OSError as exc:
        raise CLIError(f"cannot write {name}: {exc.strerror or exc}") from None
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="") as f:
            f.write(text)
            f.flush()
            os.fchmod(f.fileno(), mode)
        os.replace(tmp, out)
    except BaseException as exc:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        if isinstance(exc, OSError):
            raise CLIError(f"cannot write {name}: {exc.strerror or exc}") from None
        raise
    return out


def emit(text: str, output: str | None, inputs: Iterable[str] = ()) -> None:
    """Write ``text`` to standard output, or to the file ``output`` (:func:`write_output`).

    A missing final newline is added.
    """
    if not text.endswith("\n"):
        text += "\n"
    if output in (None, "-"):
        sys.stdout.write(text)
        sys.stdout.flush()
        return
    write_output(text, output, list(inputs))


def add_io_options(p: argparse.ArgumentParser) -> None:
    """``-o/--output``, ``--format`` and ``--arc-tolerance``."""
    from ..io import FORMATS

    p.add_argument("-o", "--output", help="output file (default: standard output)")
    p.add_argument(
        "--format",
        choices=FORMATS,
        default=None,
        help="output format (default: from the -o suffix, else json)",
    )
    add_arc_option(p)


def add_arc_option(p: argparse.ArgumentParser) -> None:
    """``--arc-tolerance``: how DXF arcs are read (see :func:`minkowski2d.io.read_dxf`)."""
    p.add_argument(
        "--arc-tolerance",
        type=float,
        default=None,
        metavar="EPS",
        help="DXF input: arcs become polygons containing the part (parts grow, holes "
        "shrink) within EPS drawing units (default: "
        f"{DEFAULT_RELATIVE_TOLERANCE:g} times each arc's radius)",
    )


def output_format(args: argparse.Namespace, formats: Iterable[str] | None = None) -> str:
    """The chosen format, or the one the output suffix names (among ``formats``, by
    default :data:`minkowski2d.io.FORMATS`), or json."""
    if getattr(args, "format", None):
        return args.format
    if formats is None:
        from ..io import FORMATS

        formats = FORMATS
    suffix = Path(args.output).suffix.lower() if args.output else ""
    return suffix[1:] if suffix[1:] in formats else "json"


def is_general(g: Any, name: str) -> bool:
    """True when ``g`` (as read by :func:`minkowski2d.io.read_geometry`) needs the
    general (non-convex / holes) sum; validates ``g``."""
    import numpy as np

    from .._engine.dispatch import check_convex

    if not isinstance(g, np.ndarray):
        return True  # shapely Polygon with holes or MultiPolygon
    return not check_convex(g, name)


def renamed_error(
    exc: GeometryError,
    names: Mapping[str, str] | None = None,
    *,
    prefix: str | None = None,
    hull_hint: str | None = None,
    hint_in_message: bool = False,
) -> GeometryError:
    """The same error (same class, same vertex) worded for a person at the command line or
    on the page, built from the error's fields.

    ``names`` renames the argument (``{"a": "poly.json"}``): ``argument`` says which name
    the message starts with. Otherwise ``prefix``, when given, is put in front. For a
    :class:`~minkowski2d.errors.NotConvexError`, ``hull_hint`` replaces the library's
    ``hull=True`` advice (or the error's own hint) as the ``hint``; with
    ``hint_in_message`` it is also written at the end of the message.

    Examples
    --------
    >>> from minkowski2d.errors import NotConvexError
    >>> e = NotConvexError("a: not convex at vertex 2 (pass hull=True)", 2, argument="a",
    ...                    hint="pass hull=True")
    >>> r = renamed_error(e, {"a": "star.json"}, hull_hint=CLI_HULL_HINT)
    >>> str(r), r.argument, r.vertex, r.hint
    ('star.json: not convex at vertex 2', 'star.json', 2, 'use --hull to use the convex hull')
    """
    from ..errors import NotConvexError

    hint = exc.hint
    if hull_hint is not None and isinstance(exc, NotConvexError):
        hint = hull_hint
    else:
        hint_in_message = False
    if names and exc.argument is not None and exc.argument in names:
        return exc.renamed(names[exc.argument], hint, hint_in_message)
    if prefix is not None:
        inner = exc.argument
        out = exc.renamed(f"{prefix}: {inner}" if inner else prefix, hint, hint_in_message)
        out.argument = prefix
        return out
    return exc.renamed(exc.argument, hint, hint_in_message)


@contextmanager
def files_named(names: Mapping[str, str]) -> Iterator[None]:
    """Context manager: a GeometryError whose ``argument`` is a Python argument name in
    ``names`` (``{"a": "part.json"}``) is raised naming the file instead."""
    try:
        yield
    except GeometryError as exc:
        if exc.argument in names:
            raise renamed_error(exc, names, hull_hint=CLI_HULL_HINT) from None
        raise


def _one_line(s: str) -> str:
    return " ".join(s.splitlines()) if ("\n" in s or "\r" in s) else s


def format_error(exc: BaseException) -> str:
    """The one line ``minkowski2d: error: ...`` for ``exc``, built from its fields
    (message, then the hint when there is one).

    Examples
    --------
    >>> format_error(GeometryError("a.json: empty", argument="a.json", hint="add vertices"))
    'minkowski2d: error: a.json: empty (hint: add vertices)'
    """
    if isinstance(exc, OSError) and not isinstance(exc, GeometryError):
        where = f": {exc.filename}" if getattr(exc, "filename", None) else ""
        msg = f"{exc.strerror or exc}{where}"
    else:
        msg = str(exc)
    hint = getattr(exc, "hint", None)
    if hint and hint not in msg:
        msg = f"{msg} (hint: {hint})"
    return f"minkowski2d: error: {_one_line(msg)}"
