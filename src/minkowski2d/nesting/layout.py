"""The result of :func:`~minkowski2d.nesting.nester.nest`: a :class:`Layout` of
:class:`Placement` records, its measures, its exact certificate, and its files.

A placement puts one copy of a part on a sheet: the part rotated counter-clockwise about
its origin (:func:`~minkowski2d.nesting.nfp.rotate_part`: exact for multiples of 90
degrees), then translated. The layout keeps the parts unrotated, as given, and the sheets
in their own coordinates; :meth:`Layout.polygons` gives the placed polygons and
:meth:`Layout.verify` the exact certificate (:mod:`.verify`).

Files: :meth:`Layout.write` writes JSON (every value exact: JSON floats round-trip),
GeoJSON (one feature per placement and per sheet), SVG and DXF (the sheets side by side,
:mod:`.drawing`); :func:`read_layout` reads JSON and GeoJSON back to an equal layout.

Examples
--------
>>> import shapely, minkowski2d as mk
>>> lay = mk.Layout([shapely.box(0, 0, 2, 1)],
...                 [mk.Placement(0, 0, 0, 0, (0.0, 0.0)), mk.Placement(0, 1, 0, 90, (3.0, 0.0))],
...                 [shapely.box(0, 0, 3, 2)], strip_height=2)
>>> lay.length, lay.density, [g.bounds for g in lay.polygons()]
(3.0, 0.6666666666666666, [(0.0, 0.0, 2.0, 1.0), (2.0, 0.0, 3.0, 2.0)])
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path
from typing import Any

import numpy as np

from .._engine import options as _options
from ..errors import GeometryError, InputFormatError, OptionError

__all__ = ["Placement", "Layout", "read_layout", "FORMATS"]

#: What :meth:`Layout.write` writes (chosen by the file's suffix).
FORMATS = ("json", "geojson", "svg", "dxf")
#: ``type`` of a layout's JSON document (and of the GeoJSON's ``layout`` member).
JSON_TYPE = "minkowski2d.Layout"


# --------------------------------------------------------------------------------------
# the data model


def _float_value(v: Any, name: str) -> float:
    """``v`` as a Python float, refused when it is not exactly a float64 value (a
    translation is stored as floats: nothing is rounded silently)."""
    f = _options.real(v, name)
    if not isinstance(v, (float, np.floating)) and Fraction(v) != Fraction(f):
        raise OptionError(
            f"{name}: {v!r} is not a float64 value",
            argument=name,
            allowed="a float (or an int or Fraction equal to one)",
            hint=f"round it first: float({name})",
        )
    return f


@dataclass(frozen=True)
class Placement:
    """One copy of a part on a sheet.

    Parameters
    ----------
    part : int
        Index into :attr:`Layout.parts`.
    copy : int
        Which copy of that part, 0-based.
    sheet : int
        Index into :attr:`Layout.sheets` (always 0 for a strip).
    rotation : int, float or Fraction
        Degrees counter-clockwise about the part's origin, kept as given (numpy numbers
        become Python ones); multiples of 90 are exact.
    translation : (2,) float
        ``(x, y)`` added after the rotation, stored as Python floats (an int or Fraction
        must equal a float64 value exactly).
    fixed : bool, default False
        A pre-placed part (``nest(fixed=...)``), not moved by the search.

    Raises
    ------
    OptionError
        A negative or non-integer index, a rotation that is not a finite number, a
        translation that is not two float64 values.

    Examples
    --------
    >>> Placement(0, 1, 0, 90, (2, 0.5))
    Placement(part=0, copy=1, sheet=0, rotation=90, translation=(2.0, 0.5), fixed=False)
    """

    part: int
    copy: int
    sheet: int
    rotation: Any
    translation: tuple
    fixed: bool = False

    def __post_init__(self) -> None:
        put = object.__setattr__
        for field in ("part", "copy", "sheet"):
            put(self, field, _options.integer(getattr(self, field), field, 0))
        put(self, "rotation", _options.angle(self.rotation, "rotation"))
        t = self.translation
        if isinstance(t, (str, bytes)) or np.ndim(t) != 1 or len(t) != 2:
            raise OptionError(
                f"translation: must be a pair (x, y), got {t!r:.60}",
                argument="translation",
                allowed="two float64 values (x, y)",
            )
        put(self, "translation", tuple(_float_value(v, "translation") for v in t))
        if not isinstance(self.fixed, (bool, np.bool_)):
            raise OptionError(
                f"fixed: must be True or False, got {self.fixed!r:.40}",
                argument="fixed",
                allowed="a bool",
            )
        put(self, "fixed", bool(self.fixed))


class Layout:
    """Parts placed on a strip or on sheets: the result of :func:`~minkowski2d.nest`.

    Parameters
    ----------
    parts : sequence of polygons
        The parts as given to nest: shapely Polygons (holes allowed) or (n, 2) rings,
        unrotated.
    placements : sequence of Placement
        One per placed copy.
    sheets : sequence of polygons
        One per used sheet, each in its own coordinates (keep-out zones are its holes).
        A strip is ``[shapely.box(0, 0, length, strip_height)]``.
    kinds : sequence of int, optional
        Per sheet, the index of the entry of nest's ``sheets=`` it is a copy of (None
        for a strip).
    strip_height : float, optional
        The strip's height: the layout is a strip (one sheet).
    spacing, margin : float, default 0
        The least distance between two parts, and between a part and its sheet's
        boundary (what :meth:`verify` certifies).
    ids : sequence of str, optional
        One name per part (default ``"0"``, ``"1"``, ...).
    name : str, optional
        The instance's name.

    Raises
    ------
    GeometryError
        A part or sheet that is not a polygon (naming ``parts[i]`` or ``sheets[k]``).
    OptionError
        A placement naming a part or sheet that does not exist, ``kinds`` or ``ids`` of
        the wrong length, a strip with other than one sheet, a negative spacing.

    Examples
    --------
    >>> import shapely, minkowski2d as mk
    >>> lay = mk.Layout([shapely.box(0, 0, 1, 1)], [mk.Placement(0, 0, 1, 0, (0.5, 0.5))],
    ...                 [shapely.box(0, 0, 4, 2), shapely.box(0, 0, 4, 2)], kinds=[0, 0],
    ...                 margin=0.5)
    >>> lay.n_sheets, lay.length, lay.densities
    (2, 2.0, [0.0, 0.125])
    """

    def __init__(
        self,
        parts: Any,
        placements: Any,
        sheets: Any,
        *,
        kinds: Any = None,
        strip_height: float | None = None,
        spacing: float = 0.0,
        margin: float = 0.0,
        ids: Any = None,
        name: str | None = None,
    ) -> None:
        seq = _options.sequence
        self._parts = tuple(
            _polygon(p, f"parts[{i}]") for i, p in enumerate(seq(parts, "parts", "polygons"))
        )
        self._sheets = tuple(
            _polygon(s, f"sheets[{k}]") for k, s in enumerate(seq(sheets, "sheets", "polygons"))
        )
        self._placements = tuple(self._checked(seq(placements, "placements", "Placements")))
        self._strip_height = None
        if strip_height is not None:
            self._strip_height = _positive(strip_height, "strip_height")
            if len(self._sheets) != 1 or kinds is not None:
                raise OptionError(
                    f"strip_height: a strip is one sheet without a kind, got "
                    f"{len(self._sheets)} sheets",
                    argument="strip_height",
                    allowed="sheets=[shapely.box(0, 0, length, strip_height)], kinds=None",
                )
        self._kinds = None if kinds is None else tuple(self._indexes(kinds))
        self._spacing = _nonnegative(spacing, "spacing")
        self._margin = _nonnegative(margin, "margin")
        n = len(self._parts)
        if ids is None:
            self._ids = tuple(str(i) for i in range(n))
        else:
            self._ids = tuple(str(v) for v in seq(ids, "ids", "one name per part"))
            if len(self._ids) != n:
                raise OptionError(
                    f"ids: {len(self._ids)} names for {n} parts",
                    argument="ids",
                    allowed=f"one name per part ({n})",
                )
        if name is not None and not isinstance(name, str):
            raise OptionError(
                f"name: must be a str, got {name!r:.40}", argument="name", allowed="a str or None"
            )
        self._name = name
        self._placed: np.ndarray | None = None

    def _checked(self, placements: list) -> list[Placement]:
        n, m = len(self._parts), len(self._sheets)
        for k, p in enumerate(placements):
            if not isinstance(p, Placement):
                raise OptionError(
                    f"placements[{k}]: must be a Placement, got {type(p).__name__}",
                    argument=f"placements[{k}]",
                    allowed="minkowski2d.Placement(part, copy, sheet, rotation, (x, y))",
                )
            if p.part >= n or p.sheet >= m:
                what = f"part {p.part} of {n}" if p.part >= n else f"sheet {p.sheet} of {m}"
                raise OptionError(
                    f"placements[{k}]: there is no {what} (indexes are 0-based)",
                    argument=f"placements[{k}]",
                    allowed=f"part < {n}, sheet < {m}",
                )
        return placements

    def _indexes(self, kinds: Any) -> list[int]:
        ks = _options.sequence(kinds, "kinds", "one int per sheet")
        if len(ks) != len(self._sheets):
            raise OptionError(
                f"kinds: {len(ks)} kinds for {len(self._sheets)} sheets",
                argument="kinds",
                allowed=f"one int >= 0 per sheet ({len(self._sheets)})",
            )
        return [_options.integer(k, f"kinds[{i}]", 0) for i, k in enumerate(ks)]

    # ---------------------------------------------------------------- what it holds

    @property
    def parts(self) -> tuple:
        """The parts (shapely Polygons), unrotated, as given."""
        return self._parts

    @property
    def placements(self) -> tuple[Placement, ...]:
        """The placements, in order."""
        return self._placements

    @property
    def sheets(self) -> tuple:
        """The used sheets (shapely Polygons, each in its own coordinates)."""
        return self._sheets

    @property
    def kinds(self) -> tuple[int, ...] | None:
        """Per sheet, the index of nest's ``sheets=`` entry it is a copy of (None: strip)."""
        return self._kinds

    @property
    def strip_height(self) -> float | None:
        """The strip's height (None for sheets)."""
        return self._strip_height

    @property
    def spacing(self) -> float:
        """The least distance between two parts."""
        return self._spacing

    @property
    def margin(self) -> float:
        """The least distance between a part and its sheet's boundary."""
        return self._margin

    @property
    def ids(self) -> tuple[str, ...]:
        """One name per part."""
        return self._ids

    @property
    def name(self) -> str | None:
        """The instance's name."""
        return self._name

    # ---------------------------------------------------------------- measures

    @property
    def n_sheets(self) -> int:
        """The number of sheets used (1 for a strip)."""
        return len(self._sheets)

    @property
    def length(self) -> float:
        """A strip's length (its sheet's x extent); for sheets, the x extent used on the
        last one: the largest x of its parts plus the margin, less the sheet's least x,
        at most the sheet's width (0 when no part is on it)."""
        if not self._sheets:
            return 0.0
        x0, _, x1, _ = self._sheets[-1].bounds
        if self._strip_height is not None:
            return x1 - x0
        last = len(self._sheets) - 1
        g = self._polygons()
        xs = [g[k].bounds[2] for k, p in enumerate(self._placements) if p.sheet == last]
        if not xs:
            return 0.0
        return min(max(xs) + self._margin - x0, x1 - x0)

    def _sheet_areas(self) -> list[float]:
        if self._strip_height is not None:
            return [self.length * self._strip_height]
        return [s.area for s in self._sheets]

    @property
    def densities(self) -> list[float]:
        """Per sheet, the area of its parts over its area (a strip: length × height)."""
        used = [0.0] * len(self._sheets)
        for p in self._placements:
            used[p.sheet] += self._parts[p.part].area
        return [u / a if a > 0 else 0.0 for u, a in zip(used, self._sheet_areas(), strict=True)]

    @property
    def density(self) -> float:
        """The area of all placed parts over the area of all sheets."""
        total = sum(self._sheet_areas())
        used = sum(self._parts[p.part].area for p in self._placements)
        return used / total if total > 0 else 0.0

    # ---------------------------------------------------------------- geometry

    def _polygons(self) -> np.ndarray:
        if self._placed is None:
            import shapely

            from .nfp import rotate_part

            turned: dict = {}
            rows = []
            for p in self._placements:
                key = (p.part, type(p.rotation), p.rotation)
                if key not in turned:
                    turned[key] = rotate_part(self._parts[p.part], p.rotation)
                rows.append(turned[key])
            geoms = np.empty(len(rows), dtype=object)
            geoms[:] = rows
            t = np.array([p.translation for p in self._placements], dtype=np.float64)
            counts = shapely.get_num_coordinates(geoms)
            shift = np.repeat(t.reshape(-1, 2), counts, axis=0)
            # one float64 addition per coordinate: the correct rounding of the exact sum
            self._placed = shapely.transform(geoms, lambda c: c + shift)
        return self._placed

    def polygons(self) -> np.ndarray:
        """The placed parts as a numpy object array of shapely Polygons, in placement
        order: each part rotated (:func:`~minkowski2d.nesting.nfp.rotate_part`), then
        translated (each coordinate the float64 rounding of the exact sum).

        Examples
        --------
        >>> import shapely, minkowski2d as mk
        >>> lay = mk.Layout([shapely.box(0, 0, 2, 1)], [mk.Placement(0, 0, 0, 90, (1.0, 0.0))],
        ...                 [shapely.box(0, 0, 1, 2)], strip_height=2)
        >>> lay.polygons()[0].bounds
        (0.0, 0.0, 1.0, 2.0)
        """
        return self._polygons().copy()

    def frame(self) -> Any:
        """The placements as a GeoDataFrame (columns ``part``, ``id``, ``copy``,
        ``sheet``, ``rotation``, ``x``, ``y``, ``fixed``, ``geometry``).

        Raises
        ------
        ImportError
            geopandas is not installed.

        Examples
        --------
        >>> import shapely, minkowski2d as mk
        >>> lay = mk.Layout([shapely.box(0, 0, 1, 1)], [mk.Placement(0, 0, 0, 0, (0.0, 0.0))],
        ...                 [shapely.box(0, 0, 1, 1)], strip_height=1)
        >>> lay.frame()[["id", "x", "y"]].values.tolist()
        [['0', 0.0, 0.0]]
        """
        try:
            import geopandas
        except ImportError:
            raise ImportError(
                "Layout.frame needs geopandas (hint: pip install geopandas, or use "
                "Layout.polygons() for a numpy array of shapely Polygons)"
            ) from None
        ps = self._placements
        data = {
            "part": [p.part for p in ps],
            "id": [self._ids[p.part] for p in ps],
            "copy": [p.copy for p in ps],
            "sheet": [p.sheet for p in ps],
            "rotation": [p.rotation for p in ps],
            "x": [p.translation[0] for p in ps],
            "y": [p.translation[1] for p in ps],
            "fixed": [p.fixed for p in ps],
        }
        return geopandas.GeoDataFrame(data, geometry=list(self._polygons()))

    def verify(self) -> bool:
        """The exact certificate: True when no two parts overlap (and keep ``spacing``
        apart) and every part lies inside its sheet (``margin`` from its boundary and its
        keep-out zones), decided on the exact values (:func:`.verify.verify_layout`).

        Raises
        ------
        LayoutError
            Naming the first violation (the placements by index and part id).

        Examples
        --------
        >>> import shapely, minkowski2d as mk
        >>> lay = mk.Layout([shapely.box(0, 0, 1, 1)], [mk.Placement(0, 0, 0, 0, (0.0, 0.0))],
        ...                 [shapely.box(0, 0, 1, 1)], strip_height=1)
        >>> lay.verify()
        True
        """
        from .verify import verify_layout

        violations = verify_layout(self)
        if not violations:
            return True
        raise _layout_error(self, violations[0], len(violations))

    # ---------------------------------------------------------------- out

    def to_dict(self) -> dict[str, Any]:
        """The layout as JSON-ready data; :meth:`from_dict` reads it back to an equal
        layout (floats round-trip through JSON exactly).

        Keys: ``type``, ``version``, ``name``, ``strip_height``, ``spacing``, ``margin``,
        ``parts`` (``id`` and a GeoJSON ``geometry`` each), ``sheets`` (``kind`` and
        ``geometry``), ``placements`` (``part``, ``copy``, ``sheet``, ``rotation``: a
        number, or a Fraction as the string ``"p/q"``; ``translation``, ``fixed``), and,
        for information only, ``length``, ``density`` and ``densities``.

        Examples
        --------
        >>> import shapely, minkowski2d as mk
        >>> lay = mk.Layout([shapely.box(0, 0, 1, 1)], [mk.Placement(0, 0, 0, 0, (0.0, 0.0))],
        ...                 [shapely.box(0, 0, 1, 1)], strip_height=1)
        >>> d = lay.to_dict()
        >>> d["placements"], mk.Layout.from_dict(d) == lay
        ([{'part': 0, 'copy': 0, 'sheet': 0, 'rotation': 0, 'translation': [0.0, 0.0], \
'fixed': False}], True)
        """
        from .layout_files import layout_dict

        return layout_dict(self)

    @classmethod
    def from_dict(cls, d: Mapping, *, name: str = "layout") -> Layout:
        """The layout of :meth:`to_dict`'s data (``name``: how errors name the source).

        Raises
        ------
        InputFormatError
            A missing or malformed field (named: ``placements[3]: 'part' ...``).
        """
        from .layout_files import from_dict

        return from_dict(d, name)

    def to_geojson(self) -> dict[str, Any]:
        """A GeoJSON FeatureCollection: one feature per sheet (``kind`` "sheet",
        ``sheet``, ``sheet_kind``, ``density``), then one per placement (``kind`` "part",
        ``placement``, ``part``, ``id``, ``copy``, ``sheet``, ``rotation``, ``x``, ``y``,
        ``fixed``; the placed polygon in its sheet's coordinates). The member ``layout``
        holds the rest (parts, spacing, margin, strip height) for :func:`read_layout`.

        Examples
        --------
        >>> import shapely, minkowski2d as mk
        >>> lay = mk.Layout([shapely.box(0, 0, 1, 1)], [mk.Placement(0, 0, 0, 0, (0.0, 0.0))],
        ...                 [shapely.box(0, 0, 1, 1)], strip_height=1)
        >>> [f["properties"]["kind"] for f in lay.to_geojson()["features"]]
        ['sheet', 'part']
        """
        from .layout_files import layout_geojson

        return layout_geojson(self)

    def svg(self, width: int = 800) -> str:
        """A standalone SVG document: the sheets side by side, outlined (keep-out zones
        grey), the parts filled, one colour per part (:mod:`.drawing`).

        Examples
        --------
        >>> import shapely, minkowski2d as mk
        >>> lay = mk.Layout([shapely.box(0, 0, 1, 1)], [mk.Placement(0, 0, 0, 0, (0.0, 0.0))],
        ...                 [shapely.box(0, 0, 2, 1)], strip_height=1)
        >>> s = lay.svg()
        >>> s.startswith("<svg"), s.count('class="part"')
        (True, 1)
        """
        from .drawing import layout_svg

        return layout_svg(self, width=width)

    def _repr_html_(self) -> str:
        from html import escape

        return (
            f"<div>{self.svg(width=640)}<div style='font-size:12px'>"
            f"{escape(self._summary())}</div></div>"
        )

    def to_text(self, format: str = "json") -> str:
        """The text :meth:`write` writes for ``format`` (one of :data:`FORMATS`).

        Raises
        ------
        OptionError
            An unknown format.
        ImportError
            DXF without ezdxf.

        Examples
        --------
        >>> import shapely, minkowski2d as mk
        >>> lay = mk.Layout([shapely.box(0, 0, 1, 1)], [], [shapely.box(0, 0, 1, 1)],
        ...                 strip_height=1)
        >>> lay.to_text("json")[:29]
        '{"type": "minkowski2d.Layout"'
        """
        fmt = _options.choice(format, "format", FORMATS)
        if fmt == "json":
            return json.dumps(self.to_dict(), allow_nan=False) + "\n"
        if fmt == "geojson":
            return json.dumps(self.to_geojson(), allow_nan=False) + "\n"
        if fmt == "svg":
            return self.svg() + "\n"
        from .drawing import layout_dxf

        return layout_dxf(self)

    def write(self, path: str | Path, format: str | None = None) -> Path:
        """Write the layout to ``path``: JSON, GeoJSON, SVG or DXF (``format``, or the
        suffix ``.json``, ``.geojson``, ``.svg``, ``.dxf``).

        The file is written whole or not at all: the text goes to a new temporary file
        beside it, renamed into place once complete (the command line's safe writer).

        Returns
        -------
        pathlib.Path

        Raises
        ------
        InputFormatError
            An unknown suffix, a directory, a path that cannot be written.
        OptionError
            An unknown ``format``.
        ImportError
            DXF without ezdxf.

        Examples
        --------
        >>> import os, tempfile, shapely, minkowski2d as mk
        >>> lay = mk.Layout([shapely.box(0, 0, 1, 1)], [mk.Placement(0, 0, 0, 0, (0.0, 0.0))],
        ...                 [shapely.box(0, 0, 1, 1)], strip_height=1)
        >>> p = lay.write(os.path.join(tempfile.mkdtemp(), "layout.json"))
        >>> mk.read_layout(p) == lay
        True
        """
        from ..cli.common import CLIError, write_output

        name = str(path)
        fmt = _format_of(name, format)
        text = self.to_text(fmt)
        try:
            return write_output(text, path)
        except CLIError as exc:
            raise InputFormatError(str(exc), argument=name, hint=exc.hint) from None

    # ---------------------------------------------------------------- comparisons

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Layout):
            return NotImplemented
        import shapely

        def same(a: tuple, b: tuple) -> bool:
            return len(a) == len(b) and all(
                shapely.to_wkb(x) == shapely.to_wkb(y) for x, y in zip(a, b, strict=True)
            )

        return (
            self._key() == other._key()
            and same(self._parts, other._parts)
            and same(self._sheets, other._sheets)
        )

    __hash__ = None  # type: ignore[assignment]

    def _key(self) -> tuple:
        rots = tuple((type(p.rotation), p.rotation) for p in self._placements)
        return (
            self._placements,
            rots,
            self._kinds,
            self._strip_height,
            self._spacing,
            self._margin,
            self._ids,
            self._name,
        )

    def _summary(self) -> str:
        where = (
            f"a strip {self.length:g} x {self._strip_height:g}"
            if self._strip_height is not None
            else f"{self.n_sheets} sheet{'s' if self.n_sheets != 1 else ''}"
        )
        n = len(self._placements)
        return (
            f"{n} placement{'s' if n != 1 else ''} of {len(self._parts)} part"
            f"{'s' if len(self._parts) != 1 else ''} on {where}, density {self.density:.4f}"
        )

    def __repr__(self) -> str:
        head = f"{self._name!r}: " if self._name else ""
        return f"<Layout {head}{self._summary()}>"


def _polygon(p: Any, name: str) -> Any:
    """A part or sheet as a shapely Polygon: a Polygon as given, an (n, 2) ring as a
    float64 one (refused when a coordinate is not a float64 value); errors name it."""
    import shapely

    from .._engine.coerce import is_shapely
    from .._engine.reader import read
    from ..errors import EmptyGeometryError, ShapeError

    if p is None:
        raise EmptyGeometryError(f"{name}: None is not a polygon", argument=name)
    if is_shapely(p):
        if p.is_empty:
            raise EmptyGeometryError(f"{name}: empty {p.geom_type}", argument=name)
        if p.geom_type != "Polygon":
            raise ShapeError(
                f"{name}: a {p.geom_type} is not a Polygon",
                argument=name,
                hint="give each connected part as its own Polygon",
            )
        return p
    rows = read(p, name, accept="coords", numbers="float64")
    if len(rows) < 3:
        raise ShapeError(
            f"{name}: {len(rows)} vertices are not a polygon",
            argument=name,
            hint="a polygon has at least 3 vertices",
        )
    return shapely.Polygon(rows)


def _positive(v: Any, name: str) -> float:
    f = _options.real(v, name)
    if not f > 0:
        raise OptionError(f"{name}: must be > 0, got {v!r}", argument=name, allowed="a number > 0")
    return f


def _nonnegative(v: Any, name: str) -> float:
    f = _options.real(v, name)
    if not f >= 0:
        raise OptionError(
            f"{name}: must be >= 0, got {v!r}", argument=name, allowed="a number >= 0"
        )
    return f


def _layout_error(lay: Layout, v: Any, n: int) -> GeometryError:
    """The LayoutError for the first violation ``v`` (a :class:`.verify.Violation`, of
    ``n``): the placements by index, with their part ids and copies."""
    from ..errors import LayoutError

    def who(k: int) -> str:
        p = lay.placements[k]
        return f"placements[{k}] (part {lay.ids[p.part]!r}, copy {p.copy})"

    pair = who(v.a) if v.b is None else f"{who(v.a)} and {who(v.b)}"
    more = f" ({n - 1} more violation{'s' if n > 2 else ''})" if n > 1 else ""
    return LayoutError(
        f"{v.argument}: {v.kind}: {pair}: {v.detail}{more}",
        argument=v.argument,
        hint="nest returns only layouts that pass; check placements made or edited by hand",
    )


def _format_of(name: str, format: str | None) -> str:
    if format is not None:
        return _options.choice(format, "format", FORMATS)
    suffix = Path(name).suffix.lower()[1:]
    if suffix not in FORMATS:
        raise InputFormatError(
            f"{name}: cannot tell the format from the suffix {('.' + suffix)!r}",
            argument=name,
            hint="name the file .json, .geojson, .svg or .dxf, or pass format=",
        )
    return suffix


def read_layout(path: str | Path) -> Layout:
    """Read a layout written by :meth:`Layout.write` as JSON or GeoJSON.

    The layout read is equal to the one written (every float exact). From GeoJSON, the
    placements come from the part features' properties (``placement``, ``part``,
    ``copy``, ``sheet``, ``rotation``, ``x``, ``y``, ``fixed``; their geometries are
    derived and not read) and the parts from the collection's ``layout`` member.

    Parameters
    ----------
    path : str or path-like

    Returns
    -------
    Layout

    Raises
    ------
    InputFormatError
        No such file, not JSON, an SVG or DXF file (drawings are not read back), a
        missing or malformed field (named).

    Examples
    --------
    >>> import os, tempfile, shapely, minkowski2d as mk
    >>> lay = mk.Layout([shapely.box(0, 0, 1, 1)], [mk.Placement(0, 0, 0, 0, (0.0, 0.0))],
    ...                 [shapely.box(0, 0, 1, 1)], strip_height=1)
    >>> p = lay.write(os.path.join(tempfile.mkdtemp(), "layout.geojson"))
    >>> mk.read_layout(p) == lay
    True
    """
    from .layout_files import load

    return load(path)
