"""CGAL as an independent peer for tests: exact Minkowski sums of float64 polygons.

The driver is ``benchmarks/cgal_nfp_driver.cpp`` (CGAL's ``minkowski_sum_2`` on the Epeck
kernel), built once into ``build/cgal_nfp_driver`` with g++ against Debian's libcgal-dev
and rebuilt when its source is newer (``.ci/run`` builds it before the suite, so a test
run does not pay the ~40 s compile). When it cannot be built here (no g++, no
libcgal-dev, a failed build) :func:`driver` calls ``pytest.skip`` with the reason.

What crosses the process boundary is exact both ways: each input coordinate is written as
``repr(float)`` and read back by ``strtod`` (the same float64, bit for bit), and the
driver prints every vertex of the result as the exact rational ``num/den`` that
``CGAL::exact`` gives. Python then rounds each coordinate with ``float(Fraction(num,
den))``, which is correctly rounded (round half to even), so the rings returned here are
the exact result's vertices rounded to float64: what minkowski2d's output contract
promises.

CGAL keeps vertices of its arrangement that lie exactly on the segment between their
neighbours (a collinear vertex, e.g. where two boundary pieces of the convolution meet
along one line). :func:`minkowski_sums` drops them, deciding exactly on the rationals
before any rounding (``keep_collinear=True`` keeps CGAL's rings as they are).

Example (the CGAL run only happens when the driver is available)::

    from tests import cgal_peer
    (r,) = cgal_peer.no_fit_polygons([(A, B)])      # A ⊕ (−B)
    r.area                                           # Fraction
    r.polygons[0][0]                                 # (n, 2) float64 exterior, CCW
    r.polygons[0][1:]                                # holes, CW
"""

from __future__ import annotations

import shutil
import subprocess
import tempfile
from collections import Counter
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
SOURCE = ROOT / "benchmarks" / "cgal_nfp_driver.cpp"
EXE = ROOT / "build" / "cgal_nfp_driver"
HEADER = Path("/usr/include/CGAL/minkowski_sum_2.h")

#: every skip's reason starts with this
SKIP_PREFIX = "CGAL peer unavailable"

Point = tuple[Fraction, Fraction]


@dataclass
class CgalResult:
    """One sum as CGAL computes it.

    ``polygons``: a list of polygons, each ``[exterior, *holes]``, every ring an (n, 2)
    float64 array of the exact vertices correctly rounded (no closing repeat; exterior
    counter-clockwise, holes clockwise, as CGAL orders them). CGAL returns one polygon
    with holes per sum (a sum of two connected sets is connected). ``exact``: the same
    rings as lists of ``(Fraction, Fraction)``. ``area``: the exact area (exterior minus
    holes). ``collinear_dropped``: how many exactly collinear vertices were removed;
    ``raw``: the rounded rings as CGAL gave them, those vertices included."""

    polygons: list[list[np.ndarray]]
    exact: list[list[list[Point]]]
    area: Fraction
    collinear_dropped: int = 0
    raw: list[list[np.ndarray]] = field(default_factory=list)
    holes: int = field(init=False)

    def __post_init__(self) -> None:
        self.holes = sum(len(p) - 1 for p in self.polygons)


def _build() -> tuple[Path | None, str]:
    if EXE.exists() and (not SOURCE.exists() or EXE.stat().st_mtime >= SOURCE.stat().st_mtime):
        return EXE, ""
    if not SOURCE.exists():
        return None, f"{SOURCE} is missing"
    if shutil.which("g++") is None:
        return None, "g++ is not installed"
    if not HEADER.exists():
        return None, "libcgal-dev is not installed (apt-get install -y libcgal-dev)"
    EXE.parent.mkdir(exist_ok=True)
    tmp = EXE.with_name(EXE.name + ".tmp")
    cmd = ["g++", "-O2", "-std=c++17", str(SOURCE), "-o", str(tmp), "-lgmp", "-lmpfr"]
    res = subprocess.run(cmd, capture_output=True, text=True)
    if res.returncode:
        tmp.unlink(missing_ok=True)
        return None, "the driver did not build: " + res.stderr[-300:]
    tmp.replace(EXE)  # atomic: a concurrent run never sees half a binary
    return EXE, ""


_DRIVER: tuple[Path | None, str] | None = None


def driver() -> Path:
    """Path of the built driver; ``pytest.skip`` (with the reason) when it cannot be
    built here. Built at most once per process."""
    global _DRIVER
    if _DRIVER is None:
        _DRIVER = _build()
    exe, why = _DRIVER
    if exe is None:
        import pytest

        pytest.skip(f"{SKIP_PREFIX}: {why}")
    return exe


def _ring_float(ring: list[Point]) -> np.ndarray:
    return np.array([(float(x), float(y)) for x, y in ring], dtype=np.float64).reshape(-1, 2)


def _cross(o: Point, a: Point, b: Point) -> Fraction:
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def drop_collinear(ring: list[Point], keep: frozenset = frozenset()) -> list[Point]:
    """``ring`` without repeated vertices and without vertices lying exactly on the line
    through their neighbours (decided on the exact rationals; repeated until none is
    left, so a run of collinear vertices goes as a whole), except those in ``keep``:
    points where another ring of the result touches this one stay (the core keeps them,
    so that rounding cannot move an edge off a touching vertex)."""
    out = list(ring)
    changed = True
    while changed and len(out) >= 3:
        changed = False
        keep: list[Point] = []
        n = len(out)
        for i, p in enumerate(out):
            prev = keep[-1] if keep else out[i - 1]
            nxt = out[(i + 1) % n]
            if p == prev or (_cross(prev, p, nxt) == 0 and p not in keep):
                changed = True
                continue
            keep.append(p)
        # the first vertex was judged against the last one before the last was judged
        out = keep
    return out


def _parse(text: str, n_pairs: int, keep_collinear: bool) -> tuple[list[CgalResult], float]:
    tok = text.split()
    pos = 0

    def take() -> str:
        nonlocal pos
        pos += 1
        return tok[pos - 1]

    def ring(tag: str) -> list[Point]:
        t = take()
        if t != tag:
            raise ValueError(f"cgal_nfp_driver output: expected {tag!r}, got {t!r}")
        n = int(take())
        return [(Fraction(take()), Fraction(take())) for _ in range(n)]

    results = []
    for q in range(n_pairs):
        if take() != "nfp" or int(take()) != q:
            raise ValueError(f"cgal_nfp_driver output: pair {q} out of order")
        holes = int(take())
        area = Fraction(take())
        raw = [ring("outer")] + [ring("hole") for _ in range(holes)]
        seen: Counter = Counter(p for r in raw for p in set(r))
        touch = frozenset(p for p, c in seen.items() if c > 1)
        rings = raw if keep_collinear else [drop_collinear(r, touch) for r in raw]
        results.append(
            CgalResult(
                polygons=[[_ring_float(r) for r in rings]],
                exact=[rings],
                area=area,
                collinear_dropped=sum(len(r) - len(k) for r, k in zip(raw, rings)),
                raw=[[_ring_float(r) for r in raw]],
            )
        )
    if take() != "seconds":
        raise ValueError("cgal_nfp_driver output: no 'seconds' line")
    return results, float(take())


def _ring_of(p) -> np.ndarray:
    """The outer ring of a shapely Polygon or an (n, 2) array-like, as float64, without
    a closing repeat or repeated consecutive vertices (CGAL needs a simple polygon)."""
    if hasattr(p, "geom_type"):
        if p.geom_type != "Polygon" or len(p.interiors):
            raise ValueError("the CGAL peer takes simple polygons without holes")
        p = np.asarray(p.exterior.coords)[:-1]
    c = np.asarray(p, dtype=np.float64)
    if len(c) > 1 and (c[0] == c[-1]).all():
        c = c[:-1]
    return c[(c != np.roll(c, 1, axis=0)).any(axis=1)]


def run(
    pairs, *, method: str = "rc", keep_collinear: bool = False
) -> tuple[list[CgalResult], float]:
    """CGAL's ``A ⊕ B`` for every ``(A, B)`` in ``pairs`` and the driver's own time for
    the sums (seconds, reading and printing excluded). ``method``: ``"rc"`` (reduced
    convolution, CGAL's default) or ``"hm"`` (Hertel–Mehlhorn decomposition)."""
    if method not in ("rc", "hm"):
        raise ValueError(f"method must be 'rc' or 'hm', got {method!r}")
    exe = driver()
    index: dict[bytes, int] = {}
    polys: list[np.ndarray] = []

    def idx(c: np.ndarray) -> int:
        key = c.tobytes() + bytes([len(c) % 256])
        if key not in index:
            index[key] = len(polys)
            polys.append(c)
        return index[key]

    lines = [f"{idx(_ring_of(a))} {idx(_ring_of(b))}" for a, b in pairs]
    with tempfile.TemporaryDirectory() as tmp:
        f = Path(tmp) / "pairs.txt"
        with open(f, "w") as out:
            out.write(f"{len(polys)}\n")
            for c in polys:
                out.write(f"{len(c)} " + " ".join(repr(float(v)) for v in c.ravel()) + "\n")
            out.write(f"{len(lines)}\n" + "\n".join(lines) + "\n")
        res = subprocess.run(
            [str(exe), f"{method}-exact", str(f)], capture_output=True, text=True, timeout=600
        )
    if res.returncode:
        raise RuntimeError(f"cgal_nfp_driver failed ({res.returncode}): {res.stderr[-300:]}")
    return _parse(res.stdout, len(lines), keep_collinear)


def minkowski_sums(pairs, *, method: str = "rc", keep_collinear: bool = False):
    """CGAL's ``A ⊕ B`` for every ``(A, B)`` in ``pairs``: a list of :class:`CgalResult`."""
    return run(pairs, method=method, keep_collinear=keep_collinear)[0]


def no_fit_polygons(pairs, *, method: str = "rc", keep_collinear: bool = False):
    """CGAL's ``NFP(A, B) = A ⊕ (−B)`` for every ``(A, B)`` in ``pairs`` (``−B`` is the
    exact negation of B's float64 coordinates)."""
    neg = [(a, -_ring_of(b)) for a, b in pairs]
    return run(neg, method=method, keep_collinear=keep_collinear)[0]
