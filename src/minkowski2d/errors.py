"""Exceptions raised by minkowski2d.

Every error derives from :class:`GeometryError`, itself a :class:`ValueError`, so
``except ValueError`` keeps working for callers that do not care about the detail.
Each message names the argument (``a``, ``b``, ``As[3]``, ...) and, where it applies,
the vertex index in the caller's own input.

Examples
--------
>>> import minkowski2d as mk
>>> try:
...     mk.minkowski_sum([], [(0, 0)])
... except mk.errors.EmptyGeometryError as exc:
...     print(exc)
a: empty input (no vertices)
"""

from __future__ import annotations

__all__ = [
    "GeometryError",
    "EmptyGeometryError",
    "ShapeError",
    "NonFiniteError",
    "CoordinateTypeError",
    "NotConvexError",
    "SelfIntersectionError",
    "OverflowGeometryError",
    "InputFormatError",
    "NoPathError",
    "ResourceLimitError",
    "OptionError",
    "LayoutError",
]


class GeometryError(ValueError):
    """Base class of every input or result problem minkowski2d reports.

    Parameters
    ----------
    message : str
        The whole human-readable message (it already names the argument and vertex).
    argument : str, optional
        The argument, file or batch member at fault (``"a"``, ``"As[3]"``, a file name).
    vertex : int, optional
        Index of the offending vertex in the caller's own numbering.
    hint : str, optional
        What the caller can do about it.
    obstacle : int, optional
        For a motion-planning point in collision: the index of the obstacle (the lowest of
        overlapping ones) whose C-obstacle holds it; None otherwise (also outside the
        workspace).

    Callers (the CLI, the animation page) read these fields; nobody parses the message.

    Examples
    --------
    >>> e = GeometryError("a: vertex 2 is bad", argument="a", vertex=2, hint="drop it")
    >>> (e.argument, e.vertex, e.hint)
    ('a', 2, 'drop it')
    """

    def __init__(
        self,
        message: str = "",
        *args: object,
        argument: str | None = None,
        vertex: int | None = None,
        hint: str | None = None,
        obstacle: int | None = None,
    ) -> None:
        super().__init__(message, *args)
        if argument is None and isinstance(message, str) and ": " in message:
            head = message.split(": ", 1)[0]
            if head and " " not in head and len(head) <= 64:
                argument = head
        self.argument = argument
        self.vertex = vertex
        self.hint = hint
        self.obstacle = obstacle

    @property
    def detail(self) -> str:
        """The message without its leading ``argument: `` and trailing ``(hint)``.

        Examples
        --------
        >>> GeometryError("a: bad (do X)", argument="a", hint="do X").detail
        'bad'
        """
        msg = str(self.args[0]) if self.args else ""
        if self.argument and msg.startswith(f"{self.argument}: "):
            msg = msg[len(self.argument) + 2 :]
        if self.hint and msg.endswith(f" ({self.hint})"):
            msg = msg[: -len(self.hint) - 3]
        return msg

    def renamed(
        self, argument: str | None = None, hint: str | None = None, hint_in_message: bool = True
    ) -> GeometryError:
        """The same error (same class, vertex and detail) naming another argument and/or
        giving another hint: how the CLI names a file instead of ``a``, and how the page
        points to its own controls instead of ``hull=True``.

        Examples
        --------
        >>> e = NotConvexError("a: not convex at vertex 3 (use hull)", 3, argument="a",
        ...                    hint="use hull")
        >>> str(e.renamed("shape.json", "use --hull"))
        'shape.json: not convex at vertex 3 (use --hull)'
        """
        arg = argument if argument is not None else self.argument
        hint = hint if hint is not None else self.hint
        msg = self.detail
        if arg:
            msg = f"{arg}: {msg}"
        if hint and hint_in_message:
            msg = f"{msg} ({hint})"
        new = type(self).__new__(type(self))
        GeometryError.__init__(new, msg, argument=arg, vertex=self.vertex, hint=hint)
        for k, v in vars(self).items():  # extra fields (``allowed``, ``obstacle``, ...)
            if k not in ("argument", "vertex", "hint"):
                setattr(new, k, v)
        return new

    def to_dict(self) -> dict[str, object]:
        """The error as a JSON-ready mapping (``type``, ``message``, ``argument``,
        ``vertex``, ``hint``).

        Examples
        --------
        >>> GeometryError("b: empty", argument="b").to_dict()["argument"]
        'b'
        """
        return {
            "type": type(self).__name__,
            "message": str(self),
            "argument": self.argument,
            "vertex": self.vertex,
            "hint": self.hint,
        }


class EmptyGeometryError(GeometryError):
    """The input has no vertices."""


class ShapeError(GeometryError):
    """The input is not an array-like of shape (n, 2)."""


class NonFiniteError(GeometryError):
    """A coordinate is NaN or infinite."""


class CoordinateTypeError(GeometryError):
    """A coordinate is not a real number (int, float or Fraction)."""


class NotConvexError(GeometryError):
    """A convex routine was given a non-convex polygon.

    Attributes
    ----------
    vertex : int or None
        Index, in the caller's input, of the vertex where convexity fails.
    """

    def __init__(
        self,
        message: str = "",
        vertex: int | None = None,
        *,
        argument: str | None = None,
        hint: str | None = None,
    ) -> None:
        super().__init__(message, argument=argument, vertex=vertex, hint=hint)


class SelfIntersectionError(GeometryError):
    """A simple polygon was required but the boundary crosses itself."""


class OverflowGeometryError(GeometryError):
    """A float result does not fit in float64: it would be infinite, or (for results
    computed at a power-of-two scale and scaled back) it would underflow."""


class InputFormatError(GeometryError):
    """A file or text could not be read as any supported polygon format."""


class NoPathError(GeometryError):
    """A motion-planning query has no collision-free path."""


class ResourceLimitError(GeometryError):
    """The computation would exceed a stated bound on work or memory."""


class LayoutError(GeometryError):
    """A layout fails its certificate: two parts overlap or are closer than the spacing,
    or a part leaves its sheet or comes closer to its boundary than the margin.

    ``argument`` names the placements at fault (``"placements[3], placements[7]"``, or
    ``"placements[3]"`` for a part against its sheet).

    Examples
    --------
    >>> e = LayoutError("placements[3], placements[7]: the interiors overlap",
    ...                 argument="placements[3], placements[7]")
    >>> (e.argument, e.detail)
    ('placements[3], placements[7]', 'the interiors overlap')
    """


class OptionError(GeometryError, TypeError):
    """An option (a keyword argument such as ``threads``, ``method``, ``join``,
    ``rotations``, ``progress``) has a value of the wrong type or out of range.

    Like numpy's ``AxisError`` (a ValueError and an IndexError), it is both a
    :class:`ValueError` (through :class:`GeometryError`) and a :class:`TypeError`, so
    ``except GeometryError``, ``except ValueError`` and ``except TypeError`` all catch it.
    ``argument`` (also ``option``) names the option and ``allowed`` says what it takes.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> try:
    ...     mk.minkowski_sum_many([[(0, 0)]], [[(1, 1)]], threads=0)
    ... except mk.errors.OptionError as exc:
    ...     print(exc.option, "|", exc.allowed)
    threads | an int from 1 to 1024
    """

    allowed: str | None = None

    def __init__(
        self,
        message: str = "",
        *args: object,
        argument: str | None = None,
        allowed: str | None = None,
        hint: str | None = None,
        vertex: int | None = None,
    ) -> None:
        super().__init__(message, *args, argument=argument, vertex=vertex, hint=hint)
        self.allowed = allowed

    @property
    def option(self) -> str | None:
        """The option at fault (the same as ``argument``)."""
        return self.argument
