"""No-fit and inner-fit polygons for nesting (cutting and packing).

The no-fit polygon of a fixed part ``A`` and a moving part ``B`` is
``NFP(A, B) = A ⊕ (−B)``: ``B`` translated by ``t`` overlaps ``A`` (interiors meet)
exactly when ``t`` lies in the interior of the NFP, and touches it on the boundary. The
inner-fit polygon of ``B`` in a container ``C`` is the erosion ``C ⊖ B``: the
translations that put ``B`` wholly inside ``C``.

:func:`no_fit_polygons` computes the NFPs of many parts, for every ordered pair and
every allowed rotation, in one batch (:func:`minkowski2d.minkowski_sum_general_many`):
each part is read and validated once per orientation, and each chunk of NFPs is one
compiled call on the exact overlay (every vertex the correctly rounded exact vertex).
Two symmetries, both exact for rotations by multiples of 90 degrees, cut the
work about fourfold:

* ``NFP(rot_r A, rot_s B) = rot_r NFP(A, rot_(s−r) B)`` (rotation is linear), and
* ``NFP(B, A) = −NFP(A, B)`` (``−`` is the rotation by 180 degrees),

so only one NFP per unordered pair of parts and relative rotation is computed; the
others are exact rotations of it ((x, y) → (−y, x) for 90 degrees).

:func:`inner_fit_polygon` is :func:`minkowski2d.minkowski_difference`, exact for convex
(e.g. rectangular) containers.
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable, Mapping, Sequence
from fractions import Fraction
from typing import Any

import numpy as np

from .._engine import options as _options
from .._engine.coerce import is_shapely
from .._engine.reader import read
from ..errors import (
    EmptyGeometryError,
    GeometryError,
    InputFormatError,
    OptionError,
    ResourceLimitError,
    ShapeError,
)
from ..general import convex_decomposition, minkowski_difference, minkowski_sum_general_many

__all__ = [
    "no_fit_polygons",
    "inner_fit_polygon",
    "degenerate_placements",
    "read_esicup",
    "pair_blocks",
    "rotate_part",
]


# --------------------------------------------------------------------------------------
# rotations


def _quarter_turns(angle: Any, name: str = "rotations") -> int | None:
    """Number of quarter turns (0..3) when ``angle`` (degrees) is a multiple of 90."""
    if type(angle) is int:  # the common case, without a Fraction
        return None if angle % 90 else (angle // 90) % 4
    f = Fraction(_options.angle(angle, name))
    if f.denominator != 1 or f.numerator % 90:
        return None
    return (f.numerator // 90) % 4


def _rot90_coords(c: np.ndarray, quarter: int) -> np.ndarray:
    """(x, y) rotated by ``quarter`` quarter turns counter-clockwise (exact)."""
    x, y = c[..., 0], c[..., 1]
    if quarter == 0:
        return c
    if quarter == 1:
        return np.stack([-y, x], axis=-1)
    if quarter == 2:
        return np.stack([-x, -y], axis=-1)
    return np.stack([y, -x], axis=-1)


def _rotate(part: Any, angle: Any) -> Any:
    """``part`` rotated counter-clockwise about the origin by ``angle`` degrees.

    Multiples of 90 are exact (ints stay ints, Fractions stay Fractions); other angles
    are rounded to float64 (the rotated part is a different polygon)."""
    import shapely

    q = _quarter_turns(angle)
    if is_shapely(part):
        if q == 0:
            return part
        if q is not None:
            return shapely.transform(part, lambda c: _rot90_coords(c, q))
        return shapely.transform(part, lambda c: _rot_float(c, angle))
    arr = np.asarray(part)
    if arr.dtype.kind not in "iuf":
        arr = np.asarray(part, dtype=object)
    if q == 0:
        return part
    if q is not None:
        return _rot90_coords(arr, q)
    return _rot_float(arr.astype(np.float64), angle)


def rotate_part(part: Any, angle: Any) -> Any:
    """A part rotated counter-clockwise about the origin by ``angle`` degrees.

    Parameters
    ----------
    part : (n, 2) array_like or shapely geometry
    angle : number
        Degrees. Multiples of 90 are exact: (x, y) → (−y, x) for 90, ints stay ints and
        Fractions stay Fractions. Other angles round the coordinates to float64.

    Returns
    -------
    ndarray or shapely geometry
        The same kind as ``part`` (an array for array-likes).

    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.rotate_part([(0, 0), (2, 0), (2, 1)], 90).tolist()
    [[0, 0], [0, 2], [-1, 2]]
    """
    if not is_shapely(part):
        # the specific error for a bad ring (the part is kept as is)
        read(part, "part", numbers="int64")
    if _quarter_turns(angle, "angle") == 0:
        return part if is_shapely(part) else np.asarray(part)
    return _rotate(part, angle)


def _rot_float(c: np.ndarray, angle: Any) -> np.ndarray:
    # reduced modulo a full turn first, exactly (math.fmod is exact for floats; ints and
    # Fractions as Fractions), so that huge angles neither overflow nor lose their value
    a = _options.angle(angle, "rotations")
    a = math.fmod(a, 360.0) if isinstance(a, float) else float(Fraction(a) % 360)
    t = math.radians(a)
    cs, sn = math.cos(t), math.sin(t)
    return np.stack([cs * c[:, 0] - sn * c[:, 1], sn * c[:, 0] + cs * c[:, 1]], axis=-1)


def _rotate_geoms(geoms: np.ndarray, quarter: int) -> np.ndarray:
    """Results rotated by quarter turns, normalized like every other result."""
    import shapely

    if quarter == 0 or len(geoms) == 0:
        return geoms
    g = shapely.transform(geoms, lambda c: _rot90_coords(c, quarter))
    return shapely.orient_polygons(shapely.normalize(g))


# --------------------------------------------------------------------------------------
# no-fit polygons


def _rotations_per_part(rotations: Any, n: int) -> list[tuple]:
    """One tuple of angles per part (``rotations`` is shared or given per part)."""
    allowed = "a sequence of angles in degrees, or one such sequence per part"
    if isinstance(rotations, (int, float, Fraction, np.number)) and not isinstance(
        rotations, (bool, np.bool_)
    ):
        rotations = (rotations,)
    rot = _options.sequence(rotations, "rotations", allowed)
    if rot and all(isinstance(r, (list, tuple, np.ndarray)) for r in rot):
        if len(rot) != n:
            raise OptionError(
                f"rotations: {len(rot)} sequences for {n} parts",
                argument="rotations",
                allowed=f"one sequence of angles per part ({n})",
            )
        out = [tuple(_options.sequence(r, f"rotations[{i}]", allowed)) for i, r in enumerate(rot)]
        names = [f"rotations[{i}]" for i in range(n)]
    else:
        out = [tuple(rot)] * n
        names = ["rotations"] * n
    if not out and not rot:
        raise OptionError(
            "rotations: no rotation allowed", argument="rotations", allowed="at least one angle"
        )
    for i, r in enumerate(out):
        if not r:
            raise OptionError(
                f"rotations[{i}]: no rotation allowed for part {i}",
                argument=f"rotations[{i}]",
                allowed="at least one angle",
            )
        for k, a in enumerate(r):
            _quarter_turns(a, f"{names[i]}[{k}]")  # type check
    return out


def _pair_index(pr: Any, k: int, n: int) -> tuple[int, int]:
    """One ``(i, j)`` of ``pairs=``: two part indices (ints, numpy ints too) in range."""
    allowed = f"(i, j) pairs of part indices from 0 to {n - 1}"
    try:
        i, j = pr
    except (TypeError, ValueError):
        raise OptionError(
            f"pairs[{k}]: expected an (i, j) pair of part indices, got {pr!r}",
            argument=f"pairs[{k}]",
            allowed=allowed,
        ) from None
    out = []
    for v in (i, j):
        if not _options.is_int(v) or not 0 <= int(v) < n:
            raise OptionError(
                f"pairs[{k}]: part index {v!r} out of range for {n} parts"
                if _options.is_int(v)
                else f"pairs[{k}]: part index {v!r} is not an int",
                argument=f"pairs[{k}]",
                allowed=allowed,
            )
        out.append(int(v))
    return out[0], out[1]


def no_fit_polygons(
    parts: Sequence[Any],
    *,
    rotations: Any = (0,),
    pairs: Iterable[tuple[int, int]] | None = None,
    keep_degenerate: bool = False,
    progress: Any = None,
    threads: int = 1,
) -> dict[tuple, Any]:
    """No-fit polygons of every ordered pair of parts, for every allowed rotation.

    Parameters
    ----------
    parts : sequence of polygons
        Each an (n, 2) ring (either orientation) or a shapely Polygon (holes allowed).
    rotations : sequence of angles, or one sequence per part
        Allowed rotations in degrees, counter-clockwise about the origin. Multiples of
        90 are exact ((x, y) → (−y, x) for 90); other angles round the rotated part to
        float64. Default: ``(0,)``.
    pairs : iterable of (i, j), optional
        The ordered part-index pairs wanted (default every ordered pair, ``i == j``
        included).
    keep_degenerate : bool, default False
        ``False``: each NFP is the regularized polygon (closure of its interior).
        ``True``: placements where ``B`` touches ``A`` without overlap but which lie
        inside that polygon (exact fits into a slot, slides along a channel exactly as
        wide as ``B``) are kept as lower-dimensional parts: the value is then a
        GeometryCollection of the polygon(s) and these segments and points (or the
        polygon alone when there are none), see :func:`degenerate_placements`.
    progress : bool or callable, optional
        Passed to :func:`minkowski2d.minkowski_sum_general_many` (``True``: a tqdm bar).
    threads : int, default 1
        Worker threads of the batched convex sums.

    Returns
    -------
    dict
        Keyed ``(i, ri, j, rj)`` (part indices and angles as given); the value is
        ``NFP(rot(parts[i], ri), rot(parts[j], rj)) = rot(A) ⊕ (−rot(B))``: part ``j``
        placed at ``t`` overlaps part ``i`` (at the origin) iff ``t`` is in the
        interior. A shapely Polygon / MultiPolygon (holes kept), normalized as
        :func:`minkowski2d.minkowski_sum_general` returns it.

    Raises
    ------
    GeometryError
        A part is not a valid polygon (``argument="parts[i]"``), or as
        :func:`minkowski2d.minkowski_sum_general`.
    ValueError
        A bad rotation or pair index.

    Notes
    -----
    Only one NFP per unordered pair ``{i, j}`` and relative rotation ``rj − ri`` is
    computed when both angles are multiples of 90 degrees; the others are exact
    rotations of it (see the module notes). Pairs with another angle are computed
    directly.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> sq = [(0, 0), (2, 0), (2, 2), (0, 2)]
    >>> L = [(0, 0), (3, 0), (3, 1), (1, 1), (1, 3), (0, 3)]
    >>> nfps = mk.no_fit_polygons([sq, L], rotations=(0, 90))
    >>> len(nfps)
    16
    >>> nfps[(0, 0, 1, 0)].wkt
    'POLYGON ((-3 -1, -1 -1, -1 -3, 2 -3, 2 2, -3 2, -3 -1))'
    >>> nfps[(1, 90, 0, 0)].area == nfps[(0, 0, 1, 90)].area
    True
    """
    parts = _parts(parts)
    n = len(parts)
    rot = _rotations_per_part(rotations, n)
    _options.threads(threads)
    _options.progress(progress)
    if pairs is None:
        pairs = [(i, j) for i in range(n) for j in range(n)]
    else:
        pairs = _options.sequence(pairs, "pairs", "an iterable of (i, j) part-index pairs")
    keys: list[tuple[int, Any, int, Any]] = []  # (part, rotation, part, rotation)
    missing = {i for i, p in enumerate(parts) if p is None}
    for k, pr in enumerate(pairs):
        i, j = _pair_index(pr, k, n)
        keys.extend((i, ri, j, rj) for ri in rot[i] for rj in rot[j])
    # None stays None: every NFP of a missing part
    todo = [key for key in keys if key[0] not in missing and key[2] not in missing]

    job_list, plan, oriented = _plan_jobs(parts, rot, todo)
    As = [a for a, _ in job_list]
    Bs = [b for _, b in job_list]
    if not job_list:
        return dict.fromkeys(keys)
    try:
        res = minkowski_sum_general_many(As, Bs, progress=progress, threads=threads)
    except GeometryError as exc:
        raise _rename(exc, As, Bs, oriented) from exc
    if keep_degenerate:
        res = np.array(
            [_with_degenerate(g, a, b) for g, a, b in zip(res, As, Bs, strict=True)],
            dtype=object,
        )
    out = _turned(res, plan)
    return {key: out.get(key) for key in keys}


def _plan_jobs(parts: list, rot: list, todo: list) -> tuple[list, list, dict]:
    """The distinct sums to compute, ``job_list`` ((A, −B) pairs), and for each requested
    key ``(i, ri, j, rj)`` its job and the quarter turns that take the job's NFP to it
    (``plan``). Multiples of 90 degrees share one canonical job per unordered pair and
    relative rotation; ``oriented`` caches the rotated (and reflected) parts."""
    # canonical jobs: (i, rotation of A, j, rotation of B's reflection) -> requests
    oriented: dict[tuple, Any] = {}

    def part_at(i: int, angle: Any) -> Any:
        q = _quarter_turns(angle)
        key = (i, q if q is not None else angle)
        if key not in oriented:
            oriented[key] = _rotate(parts[i], angle)
        return oriented[key]

    jobs: dict[tuple, int] = {}
    job_list: list[tuple] = []
    plan = []  # (key, job index, quarter turns to apply)
    qt = {a: _quarter_turns(a) for r in rot for a in r}
    for key in todo:
        i, ri, j, rj = key
        qi, qj = qt[ri], qt[rj]
        if qi is not None and qj is not None:
            d = (qj - qi) % 4
            c1, c2 = (i, 0, j, d), (j, 0, i, (-d) % 4)
            if c2 < c1:
                job, turn = c2, (qj + 2) % 4  # NFP = −rot_rj NFP(j, 0, i, −d)
            else:
                job, turn = c1, qi
            a_key, b_key = (job[0], job[1]), (job[2], (job[3] + 2) % 4)
            jk: tuple = ("q", a_key, b_key)
            if jk not in jobs:
                jobs[jk] = len(job_list)
                job_list.append((part_at(job[0], 90 * job[1]), part_at(job[2], 90 * b_key[1])))
            plan.append((key, jobs[jk], turn))
        else:
            jk = ("f", i, ri, j, rj)
            if jk not in jobs:
                jobs[jk] = len(job_list)
                if (j, "reflected", rj) not in oriented:
                    oriented[(j, "reflected", rj)] = _rotate(part_at(j, rj), 180)
                job_list.append((part_at(i, ri), oriented[(j, "reflected", rj)]))
            plan.append((key, jobs[jk], 0))

    return job_list, plan, oriented


def _turned(res: Any, plan: list) -> dict[tuple, Any]:
    """Each requested key's NFP: its job's result turned by its quarter turns."""
    out: dict[tuple, Any] = {}
    turns = np.array([t for _, _, t in plan], np.int64)
    idx = np.array([k for _, k, _ in plan], np.int64)
    for t in range(4):
        sel = np.flatnonzero(turns == t)
        if len(sel) == 0:
            continue
        g = _rotate_geoms(res[idx[sel]], t)
        for s, gg in zip(sel, g, strict=True):
            out[plan[s][0]] = gg
    return out


def _parts(parts: Any) -> list:
    """The parts as a list (a GeoSeries, an object array, any sequence), each checked:
    None stays None (its NFPs are None), an empty part is an EmptyGeometryError and
    anything that is not a polygon a specific GeometryError, naming ``parts[i]``."""
    if hasattr(parts, "geometry") and hasattr(parts, "values"):  # GeoSeries / GeoDataFrame
        parts = parts.geometry.values
    out = _options.sequence(parts, "parts", "a sequence of polygons")
    out = [None if p is None else p for p in out]
    for i, p in enumerate(out):
        if p is None:
            continue
        name = f"parts[{i}]"
        if is_shapely(p):
            if p.is_empty:
                raise EmptyGeometryError(f"{name}: empty {p.geom_type}", argument=name)
            if p.geom_type not in ("Polygon", "MultiPolygon", "LinearRing"):
                raise ShapeError(f"{name}: a {p.geom_type} is not a polygon", argument=name)
            continue
        # raises the specific error for a bad ring (not kept: exactness)
        read(p, name, numbers="int64")
    return out


def _rename(exc: GeometryError, As: list, Bs: list, oriented: dict) -> GeometryError:
    """Name the parts (``parts[i]``) instead of the batch operands (``As[k]``, ``Bs[k]``)."""
    import re

    arg = exc.argument or ""
    where = {id(v): f"parts[{key[0]}]" for key, v in oriented.items()}
    lists = {"As": As, "Bs": Bs}

    def sub(m: re.Match) -> str:
        k = int(m.group(2))
        L = lists[m.group(1)]
        return where.get(id(L[k]), m.group(0)) if k < len(L) else m.group(0)

    new = re.sub(r"\b(As|Bs)\[(\d+)\]", sub, arg)
    return exc if new == arg else exc.renamed(new)


# --------------------------------------------------------------------------------------
# exact fits and slides


def _with_degenerate(nfp: Any, a: Any, b: Any) -> Any:
    import shapely

    extra = degenerate_placements(a, b, nfp=nfp)
    if extra.is_empty:
        return nfp
    return shapely.GeometryCollection([*shapely.get_parts(nfp), *shapely.get_parts(extra)])


def degenerate_placements(a: Any, b: Any, *, nfp: Any = None) -> Any:
    """Zero-area placements inside the regularized sum ``a ⊕ b``.

    With ``b = −B`` this is the set of translations ``t`` where ``B + t`` touches ``A``
    without overlapping it (interiors disjoint) although ``t`` lies in the interior of
    the regularized no-fit polygon: exact fits (points) and slides (segments).

    Parameters
    ----------
    a, b : polygons
        As for :func:`minkowski2d.minkowski_sum_general` (both with area).
    nfp : shapely geometry, optional
        The regularized sum, if already computed.

    Returns
    -------
    shapely geometry
        A (Multi)LineString, (Multi)Point or GeometryCollection of them; empty when
        there is no such placement. Lines and points come in lexicographic order of
        their vertices.

    Notes
    -----
    ``int(A) ⊕ int(b)`` is the union of the interiors of the convex piece sums
    ``P ⊕ Q`` (an overlap of two open sets contains a point off every diagonal). So a
    placement ``t`` of the closed sum is feasible iff it lies in no piece sum's interior.
    The core's exact overlay of all piece sums gives every piece of the arrangement its
    winding numbers on both sides and the number of piece sums whose boundary runs
    along it with their inside below: a piece with the regularized sum on both sides and
    no piece interior on it is such a placement (a slide); so is a vertex with the sum
    all around it that no piece sum's interior holds (an exact fit, decided by exact
    sides). A slide that continues along the sum's boundary on the same line is kept
    whole (every point of it is a valid placement). Vertices are correctly rounded.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> U = [(0, 0), (3, 0), (3, 2), (2, 2), (2, 1), (1, 1), (1, 2), (0, 2)]
    >>> peg = [(0, 0), (1, 0), (1, 1), (0, 1)]
    >>> neg = [(-x, -y) for x, y in peg]
    >>> mk.degenerate_placements(U, neg).wkt  # the peg slides in the U's slot
    'LINESTRING (1 1, 1 2)'
    """

    import shapely

    from .._engine import core

    del nfp  # the core finds these placements from the piece sums alone
    RA = convex_decomposition(a)
    RB = convex_decomposition(b)
    lines, off, points = core.degenerate_pieces(
        np.ascontiguousarray(RA.coords, np.float64),
        np.asarray(RA.offsets, np.int64),
        np.ascontiguousarray(RB.coords, np.float64),
        np.asarray(RB.offsets, np.int64),
    )
    out: list[shapely.Geometry] = [
        shapely.LineString(lines[off[k] : off[k + 1]]) for k in range(len(off) - 1)
    ]
    out += [shapely.Point(p) for p in points.tolist()]
    if not out:
        return shapely.GeometryCollection()
    if len(out) == 1:
        return out[0]
    return shapely.GeometryCollection(out)


def inner_fit_polygon(container: Any, part: Any) -> Any:
    """Inner-fit polygon: the translations that put ``part`` wholly inside ``container``.

    This is the erosion ``container ⊖ part`` (:func:`minkowski2d.minkowski_difference`);
    the part need not contain its own origin.

    Parameters
    ----------
    container : polygon
        The sheet or bin (holes allowed).
    part : polygon
        The part to place.

    Returns
    -------
    shapely geometry
        A Polygon, or a LineString / Point when the part fits along a segment or at a
        single point only; an empty Polygon when it fits nowhere. Exact for a convex
        (e.g. rectangular) container; otherwise the regularized erosion (see
        :func:`minkowski2d.minkowski_difference`).

    Examples
    --------
    >>> import minkowski2d as mk
    >>> sheet = [(0, 0), (10, 0), (10, 4), (0, 4)]
    >>> mk.inner_fit_polygon(sheet, [(1, 1), (4, 1), (4, 3), (1, 3)]).wkt
    'POLYGON ((-1 -1, 6 -1, 6 1, -1 1, -1 -1))'
    >>> mk.inner_fit_polygon(sheet, [(0, 0), (3, 0), (3, 4), (0, 4)]).wkt
    'LINESTRING (0 0, 7 0)'
    """
    try:
        return minkowski_difference(container, part)
    except GeometryError as exc:
        arg = exc.argument or ""
        ren = {"a": "container", "b": "part", "a, b": "container, part"}
        if arg in ren:
            raise exc.renamed(ren[arg]) from exc
        raise


# --------------------------------------------------------------------------------------
# instances and distribution helpers


def read_esicup(path: Any) -> dict[str, Any]:
    """Read an instance in the compact ESICUP JSON format.

    Parameters
    ----------
    path : str or path-like
        A JSON file with ``name``, ``strip`` (``height``, ``length``) and ``pieces``
        (each with ``id``, ``quantity``, ``rotations``, ``outer`` and ``holes``), or a
        GeoJSON FeatureCollection of Polygon features (one piece each; ``id``,
        ``quantity`` and ``rotations`` from its properties; ``name`` and ``strip`` may
        be members of the collection).

    Returns
    -------
    dict
        ``name``, ``ids``, ``parts`` (shapely Polygons, holes kept, coordinates as given),
        ``rotations`` (one tuple per part), ``quantities``, ``strip`` and ``properties``
        (each piece's feature properties, or None).

    Raises
    ------
    InputFormatError
        The file is not such an instance (names the field: a piece, its rotations or
        quantity, the strip; JSON nested too deeply, a number beyond float64).

    Examples
    --------
    >>> import json, tempfile, minkowski2d as mk
    >>> inst = {"name": "t", "strip": {"height": 4, "length": None}, "pieces": [
    ...     {"id": "p", "quantity": 2, "rotations": [0, 90],
    ...      "outer": [[0, 0], [2, 0], [2, 1], [0, 1]], "holes": []}]}
    >>> with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
    ...     json.dump(inst, f)
    >>> d = mk.read_esicup(f.name)
    >>> d["parts"][0].wkt, d["rotations"]
    ('POLYGON ((0 0, 2 0, 2 1, 0 1, 0 0))', [(0, 90)])
    """
    import shapely

    from .._engine.foreign import foreign_errors

    name = str(path)
    try:
        with open(path, "rb") as f:
            raw = f.read()
    except OSError as exc:
        raise InputFormatError(
            f"{name}: cannot read ({exc.strerror or exc})", argument=name
        ) from None
    try:
        with foreign_errors(name, "reading the instance"):
            d = json.loads(raw.decode("utf-8-sig"))
    except InputFormatError as exc:
        raise exc.renamed(hint="see docs/nesting.md") from None
    if isinstance(d, Mapping) and d.get("type") == "FeatureCollection":
        d = _instance_from_features(d, name)
    if not isinstance(d, Mapping) or not isinstance(d.get("pieces"), list):
        raise InputFormatError(
            f"{name}: no 'pieces' list", argument=name, hint="an ESICUP instance in JSON"
        )
    strip = d.get("strip", {})
    if strip is None:
        strip = {}
    if not isinstance(strip, Mapping) or not all(
        strip.get(k) is None or _is_number(strip.get(k)) for k in ("height", "length")
    ):
        raise InputFormatError(
            f"{name}: 'strip' must be an object with numbers height and length (or null), "
            f"got {str(strip)[:60]}",
            argument=name,
            hint='e.g. "strip": {"height": 40, "length": null}',
        )
    parts, rots, qty, ids, props = [], [], [], [], []
    for k, p in enumerate(d["pieces"]):
        where = f"{name}: pieces[{k}]"
        try:
            if not isinstance(p, Mapping):
                raise TypeError(f"a piece is an object, not {type(p).__name__}")
            with foreign_errors(where, "reading the piece"):
                outer = _coords(p["outer"])
                holes = [_coords(h) for h in p.get("holes", None) or []]
                parts.append(shapely.Polygon(outer, holes))
            rot = p.get("rotations", [0])
            if not isinstance(rot, list) or not rot or not all(_is_number(r) for r in rot):
                raise TypeError(f"'rotations' must be a non-empty list of numbers, got {rot!r}")
            rots.append(tuple(rot))
            q = p.get("quantity", 1)
            if not isinstance(q, int) or isinstance(q, bool) or q < 0:
                raise TypeError(f"'quantity' must be a whole number, got {q!r}")
            qty.append(q)
            ids.append(str(p.get("id", k)))
            props.append(p.get("properties") if isinstance(p.get("properties"), Mapping) else None)
        except (KeyError, TypeError, ValueError, shapely.errors.ShapelyError) as exc:
            if isinstance(exc, GeometryError):
                raise exc.renamed(where) if exc.argument != where else exc from None
            raise InputFormatError(
                f"{where} is malformed ({type(exc).__name__}: {exc})",
                argument=where,
                vertex=None,
                hint="each piece needs an 'outer' list of [x, y] and a 'rotations' list",
            ) from exc
    return {
        "name": d.get("name", name),
        "ids": ids,
        "parts": parts,
        "rotations": rots,
        "quantities": qty,
        "strip": dict(strip),
        "properties": props,
    }


def _is_number(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def _coords(v: Any) -> np.ndarray:
    """An (n, 2) float64 array of JSON [x, y] pairs: numbers only, finite (an int beyond
    the float range is an OverflowError, translated by the caller)."""
    if not isinstance(v, list) or not all(
        isinstance(p, list) and len(p) == 2 and all(_is_number(c) for c in p) for p in v
    ):
        raise TypeError("coordinates must be a list of [x, y] number pairs")
    out = np.array([[float(x), float(y)] for x, y in v], dtype=np.float64).reshape(-1, 2)
    if not np.isfinite(out).all():
        raise ValueError("a coordinate does not fit in float64")
    return out


def _instance_from_features(fc: Mapping, name: str) -> dict:
    """An instance from a GeoJSON FeatureCollection: one piece per Polygon feature, whose
    properties may give ``id``, ``quantity`` and ``rotations`` (kept whole, as the
    piece's ``properties``); ``name`` and ``strip`` may be members of the collection."""
    feats = fc.get("features")
    if not isinstance(feats, list):
        raise InputFormatError(f"{name}: FeatureCollection 'features' is not a list", argument=name)
    pieces = []
    for k, f in enumerate(feats):
        where = f"{name}: features[{k}]"
        if not isinstance(f, Mapping) or not isinstance(f.get("geometry"), Mapping):
            raise InputFormatError(
                f"{where}: not a GeoJSON Feature with a geometry", argument=where
            )
        g = f["geometry"]
        if g.get("type") != "Polygon" or not isinstance(g.get("coordinates"), list):
            raise InputFormatError(
                f"{where}: a piece must be a Polygon, got {str(g.get('type'))[:30]}",
                argument=where,
            )
        rings = g["coordinates"]
        if not rings or not all(isinstance(r, list) and r for r in rings):
            raise InputFormatError(f"{where}: a Polygon without rings", argument=where)
        props = p if isinstance(p := f.get("properties"), Mapping) else {}
        pieces.append(
            {
                "id": props.get("id", f.get("id", k)),
                "quantity": props.get("quantity", 1),
                "rotations": props.get("rotations", [0]),
                "outer": rings[0][:-1] if rings[0][0] == rings[0][-1] else rings[0],
                "holes": [r[:-1] if r[0] == r[-1] else r for r in rings[1:]],
                "properties": dict(props),
            }
        )
    return {"name": fc.get("name", name), "strip": fc.get("strip", {}), "pieces": pieces}


#: :func:`pair_blocks` lists at most this many pairs (each a Python tuple in memory).
MAX_PAIRS = 1 << 32


def pair_blocks(n: int, size: int) -> list[list[tuple[int, int]]]:
    """All ordered part-index pairs of ``n`` parts in blocks of at most ``size``.

    Both ``(i, j)`` and ``(j, i)`` go to the same block, so each block profits from the
    symmetry ``NFP(B, A) = −NFP(A, B)`` (see the Dask recipe in docs/nesting.md).

    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.pair_blocks(3, 4)
    [[(0, 0), (0, 1), (1, 0)], [(0, 2), (2, 0), (1, 1)], [(1, 2), (2, 1), (2, 2)]]
    """
    n = _options.integer(n, "n", 0)
    size = _options.integer(size, "size", 2)
    if n * n > MAX_PAIRS:
        raise ResourceLimitError(
            f"n: {n} parts make {n * n} pairs, more than {MAX_PAIRS}",
            argument="n",
            hint="split the parts into groups first",
        )
    blocks: list[list[tuple[int, int]]] = [[]]
    for i in range(n):
        for j in range(i, n):
            group = [(i, j)] if i == j else [(i, j), (j, i)]
            if len(blocks[-1]) + len(group) > size:
                blocks.append([])
            blocks[-1].extend(group)
    return [b for b in blocks if b]
