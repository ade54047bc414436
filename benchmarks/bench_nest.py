"""Nesting layouts: minkowski2d.nest against spyrrow (sparrow) on the ESICUP instances.

Per instance, sequentially in one run and at the same wall-time budget, seed and thread
count:

* spyrrow (the Python binding of sparrow, Gardeyn et al. 2025): ``StripPackingInstance``
  of the parts with their quantities and allowed rotations, solved with
  ``StripPackingConfig(total_computation_time=T, num_workers=threads, seed=seed,
  early_termination=False)`` (so that it uses its whole budget, as ours does; 80 % of T
  exploration, 20 % compression, its own split);
* minkowski2d: ``mk.nest(instance, time_limit=T, threads=threads, seed=seed)``.

Times are wall clock and CPU time of this process (``time.process_time``, every thread):
the machine may be shared. Density is Σ part area / (strip length x strip height), from the
exact areas of the parts (spyrrow's own figure agrees to float32 rounding).

Verification, of both layouts alike:

* exact: ``Layout.verify()`` (the certificate of minkowski2d.nesting.verify). spyrrow's
  placements become a ``minkowski2d.Layout``: spyrrow reports each placed item as a
  counter-clockwise rotation by ``rotation`` degrees about the item's own origin (0, 0)
  followed by the translation ``translation`` (checked on albano, fu and jakobs1: that
  convention gives zero overlap inside the strip; clockwise, or rotation about the
  centroid, gives overlaps of 1-2 % of the part area and parts outside the strip). Its
  angles come in (-180, 180]; they are taken modulo 360 (so -90 is the exact quarter
  turn 270). The strip is ``[0, width] x [0, H]`` with spyrrow's reported width.
* shapely, a second opinion: the summed area of pairwise intersections of the placed
  polygons, the area outside the container (the sheet shrunk by the margin) and, with
  spacing, the number of pairs closer than the spacing.

Sets (``--set``, comma-separated): ``classic`` (the 12 instances of the sparrow paper's
table; its published means over 100 runs of 1200 s on 3 threads are printed alongside as
context, not as a run of ours), ``dighe`` (jigsaws whose optimum density is 100 %),
``gardeyn`` (gardeyn0..9, real parts), ``sheets`` (the classic parts on fixed H x H sheets,
H the instance's strip height, spacing 1 % and margin 2 % of H, a stock of 2 LB + 1 sheets
(``--stock``): sheets used against the lower bounds ceil(Σ part area / sheet area) and
LB = ceil(Σ part area / area inside the margins); spyrrow has no bin packing, so
minkowski2d only).

Usage::

    python benchmarks/bench_nest.py                                   # classic, 60 s, 2 threads
    python benchmarks/bench_nest.py --time 5 --set classic --only albano,fu --json out.json
    python benchmarks/bench_nest.py --set dighe,gardeyn,sheets --time 60 --threads 2
"""

from __future__ import annotations

import argparse
import json
import math
import os
import platform
import statistics
import time
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import shapely

import minkowski2d as mk

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT.parent / "shared" / "data" / "esicup"
CLASSIC = [
    "albano", "dagli", "fu", "jakobs1", "jakobs2", "mao", "marques", "shapes0", "shapes1",
    "shirts", "swim", "trousers",
]  # fmt: skip
SETS = {
    "classic": CLASSIC,
    "dighe": ["dighe1", "dighe2"],
    "gardeyn": [f"gardeyn{k}" for k in range(10)],
    "sheets": CLASSIC,
}
# sparrow's published densities (%): Gardeyn, Vanden Berghe & Wauters 2025 (arXiv:2509.13329),
# means over 100 runs of 1200 s on 3 threads
PUBLISHED = {
    "albano": 89.47, "dagli": 89.26, "fu": 92.23, "jakobs1": 89.08, "jakobs2": 84.76,
    "mao": 86.14, "marques": 90.93, "shapes0": 68.59, "shapes1": 75.68, "shirts": 89.66,
    "swim": 78.26, "trousers": 91.73,
}  # fmt: skip
KNOWN_OPTIMUM = {"dighe1": 100.0, "dighe2": 100.0}
# shapely's verdict: overlap and outside area up to this fraction of Σ part area count as
# float64 rounding of touching edges (the figures themselves go to --json)
SHAPELY_TOL = 1e-12


def timed(fn, *args, **kwargs):
    """(result, wall seconds, CPU seconds of this process, all threads)."""
    w0, c0 = time.perf_counter(), time.process_time()
    r = fn(*args, **kwargs)
    return r, time.perf_counter() - w0, time.process_time() - c0


def load(name: str) -> dict:
    return mk.read_esicup(DATA / f"{name}.json")


def total_area(inst: dict) -> float:
    return math.fsum(p.area * q for p, q in zip(inst["parts"], inst["quantities"]))


# -- verification ---------------------------------------------------------------------------


def exact_check(layout) -> str:
    """'ok', or the first violation ``Layout.verify()`` names."""
    try:
        layout.verify()
    except mk.errors.GeometryError as exc:
        return f"FAIL: {exc}"
    return "ok"


def placed_polygons(parts: list, placements: list) -> np.ndarray:
    """The placed polygons, built here from the placements (not by ``Layout.polygons()``):
    ``rotate_part(part, rotation)`` (exact for quarter turns) translated in float64."""
    out = []
    for pl in placements:
        g = mk.rotate_part(parts[pl.part], pl.rotation)
        dx, dy = pl.translation
        out.append(shapely.transform(g, lambda c, dx=dx, dy=dy: c + (dx, dy)))
    return np.asarray(out, dtype=object)


def shapely_check(
    polys: np.ndarray, sheet_of: np.ndarray, sheets: list, margin: float, spacing: float
) -> dict:
    """Overlap, area outside the container (the sheet shrunk by the margin) and spacing
    breaches, by shapely in float64. Areas are relative to Σ part area."""
    out = 0.0
    for s, sheet in enumerate(sheets):
        box = sheet.buffer(-margin, join_style="mitre") if margin else sheet
        mine = polys[sheet_of == s]
        if len(mine):
            out += float(shapely.area(shapely.difference(mine, box)).sum())
    tree = shapely.STRtree(polys)
    i, j = tree.query(polys, predicate="intersects")
    keep = (i < j) & (sheet_of[i] == sheet_of[j])
    i, j = i[keep], j[keep]
    inter = shapely.area(shapely.intersection(polys[i], polys[j])) if len(i) else np.zeros(0)
    close = 0
    if spacing > 0:
        a, b = tree.query(polys, predicate="dwithin", distance=spacing)
        keep = (a < b) & (sheet_of[a] == sheet_of[b])
        d = shapely.distance(polys[a[keep]], polys[b[keep]])
        close = int((d < spacing * (1 - 1e-9)).sum())
    total = float(shapely.area(polys).sum())
    return {
        "overlap": float(inter.sum()) / total,
        "overlap_pairs": int((inter > SHAPELY_TOL * total).sum()),
        "outside": out / total,
        "too_close": close,
    }


def check_layout(layout) -> dict:
    return shapely_check(
        placed_polygons(layout.parts, layout.placements),
        np.array([pl.sheet for pl in layout.placements], dtype=np.int64),
        list(layout.sheets),
        float(layout.margin or 0.0),
        float(layout.spacing or 0.0),
    )


def shapely_label(c: dict) -> str:
    bad = []
    if c["overlap"] > SHAPELY_TOL:
        bad.append(f"overlap {c['overlap']:.1e} ({c['overlap_pairs']} pairs)")
    if c["outside"] > SHAPELY_TOL:
        bad.append(f"outside {c['outside']:.1e}")
    if c["too_close"]:
        bad.append(f"{c['too_close']} pairs < spacing")
    return "; ".join(bad) if bad else "ok"


# -- spyrrow --------------------------------------------------------------------------------


def spyrrow_items(inst: dict) -> list:
    import spyrrow

    items = []
    for pid, p, q, rots in zip(inst["ids"], inst["parts"], inst["quantities"], inst["rotations"]):
        c = shapely.get_coordinates(p.exterior)[:-1]
        c = c[(c != np.roll(c, 1, axis=0)).any(axis=1)]  # repeated vertices (gardeyn5, 6, 8)
        items.append(
            spyrrow.Item(
                str(pid), [(float(x), float(y)) for x, y in c], int(q), [float(r) for r in rots]
            )
        )
    return items


def spyrrow_placements(inst: dict, sol) -> list:
    """spyrrow's placed items as Placements: rotation counter-clockwise about the part's
    origin, then the translation; angles modulo 360 (-90 is the exact quarter turn 270)."""
    make = getattr(mk, "Placement", None) or _Placement
    index = {str(pid): k for k, pid in enumerate(inst["ids"])}
    copies: Counter = Counter()
    out = []
    for it in sol.placed_items:
        k = index[it.id]
        r = float(it.rotation) % 360.0
        r = int(r) if r.is_integer() else r
        t = (float(it.translation[0]), float(it.translation[1]))
        out.append(make(part=k, copy=copies[k], sheet=0, rotation=r, translation=t))
        copies[k] += 1
    return out


@dataclass(frozen=True)
class _Placement:
    """Stand-in for minkowski2d.Placement while it does not exist (the shapely check only)."""

    part: int
    copy: int
    sheet: int
    rotation: object
    translation: tuple


def run_spyrrow(inst: dict, args) -> dict:
    import spyrrow

    H = float(inst["strip"]["height"])
    problem = spyrrow.StripPackingInstance(inst["name"], H, spyrrow_items(inst))
    cfg = spyrrow.StripPackingConfig(
        early_termination=False,
        total_computation_time=args.time,
        num_workers=args.threads,
        seed=args.seed,
    )
    sol, wall, cpu = timed(problem.solve, cfg)
    placed = len(sol.placed_items)
    row = {
        "length": float(sol.width),
        "density": total_area(inst) / (float(sol.width) * H),
        "own_density": float(sol.density),
        "wall": wall,
        "cpu": cpu,
        "placed": placed,
    }
    if placed != sum(inst["quantities"]):
        row["exact"] = f"FAIL: {placed} of {sum(inst['quantities'])} parts placed"
        return row
    placements = spyrrow_placements(inst, sol)
    strip = shapely.box(0.0, 0.0, float(sol.width), H)
    polys = placed_polygons(inst["parts"], placements)
    row["shapely"] = shapely_check(polys, np.zeros(len(polys), np.int64), [strip], 0.0, 0.0)
    if hasattr(mk, "Layout"):
        layout = mk.Layout(inst["parts"], placements, [strip], strip_height=H,
                           ids=list(inst["ids"]), name=inst["name"])  # fmt: skip
        row["exact"] = exact_check(layout)
        row["layout"] = layout
    else:
        row["exact"] = "n/a: minkowski2d.Layout does not exist yet"
    return row


# -- minkowski2d ----------------------------------------------------------------------------


def run_ours(inst: dict, args, **kw) -> dict:
    layout, wall, cpu = timed(
        mk.nest, inst, time_limit=args.time, threads=args.threads, seed=args.seed, **kw
    )
    row = {
        "length": float(layout.length),
        "density": float(layout.density),
        "n_sheets": int(layout.n_sheets),
        "wall": wall,
        "cpu": cpu,
        "placed": len(layout.placements),
        "exact": exact_check(layout),
        "shapely": check_layout(layout),
        "layout": layout,
    }
    if kw.get("sheets") is None:
        H = float(inst["strip"]["height"])
        row["density_check"] = total_area(inst) / (row["length"] * H)
    return row


# -- tables ---------------------------------------------------------------------------------


def pct(v) -> str:
    return "-" if v is None else f"{100 * v:.2f}"


def num(v) -> str:
    if v is None:
        return "-"
    return f"{v:.6g}" if abs(v) < 1e5 else f"{v:.0f}"


def verdict(r: dict | None) -> str:
    if r is None or "error" in r:
        return "-"
    ex = {"ok": "ok", "n/a": "n/a"}.get(r["exact"][:3].rstrip(":"), "FAIL")
    sh = "ok" if "shapely" in r and shapely_label(r["shapely"]) == "ok" else "FAIL"
    return f"{ex} / {sh}"


def strip_table(label: str, names: list, res: dict) -> list[str]:
    """Print the strip-packing table of a set; returns the notes (failures, errors)."""
    context = "sparrow published % (1200 s, 3 thr, mean of 100)" if label == "classic" else None
    if label == "dighe":
        context = "known optimum %"
    head = [
        "instance", "parts", "ours %", "ours length", "ours wall / CPU s",
        "ours verify (exact / shapely)", "spyrrow %", "spyrrow length", "spyrrow wall / CPU s",
        "spyrrow verify (exact / shapely)", "ours / spyrrow",
    ] + ([context] if context else [])  # fmt: skip
    print(f"\n### {label}\n")
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    notes = []
    cols: dict = {"ours": [], "spy": [], "ratio": [], "ctx": []}
    for name in names:
        r = res[name]
        o, s = r.get("ours"), r.get("spyrrow")
        od = o.get("density") if o and "error" not in o else None
        sd = s.get("density") if s and "error" not in s else None
        ratio = od / sd if od and sd else None
        ctx = PUBLISHED.get(name) if label == "classic" else KNOWN_OPTIMUM.get(name)
        # the mean row: over the instances where every tool that ran gave a layout
        if (od is not None or o is None) and (sd is not None or s is None):
            for k, v in (("ours", od), ("spy", sd), ("ratio", ratio), ("ctx", ctx)):
                if v is not None:
                    cols[k].append(v)
        cells = [
            name,
            str(r["parts"]),
            pct(od),
            num(o.get("length")) if od else "-",
            f"{o['wall']:.1f} / {o['cpu']:.1f}" if od else "-",
            verdict(o),
            pct(sd),
            num(s.get("length")) if sd else "-",
            f"{s['wall']:.1f} / {s['cpu']:.1f}" if sd else "-",
            verdict(s),
            f"{ratio:.3f}" if ratio else "-",
        ] + ([f"{ctx:.2f}" if ctx else "-"] if context else [])
        print("| " + " | ".join(cells) + " |")
        for who, x in (("minkowski2d", o), ("spyrrow", s)):
            if x is None:
                continue
            if "error" in x:
                notes.append(f"{name}: {who} raised {x['error']}")
                continue
            if x["exact"] != "ok":
                notes.append(f"{name}: {who} exact verify: {x['exact']}")
            if "shapely" in x and shapely_label(x["shapely"]) != "ok":
                notes.append(f"{name}: {who} shapely: {shapely_label(x['shapely'])}")
    m = {k: statistics.fmean(v) if v else None for k, v in cols.items()}
    k = len(cols["ours"] or cols["spy"])
    mean = [
        f"**mean** ({k})", "", pct(m["ours"]), "", "", "", pct(m["spy"]), "", "", "",
        f"{m['ratio']:.3f}" if m["ratio"] else "-",
    ] + ([f"{m['ctx']:.2f}" if m["ctx"] else "-"] if context else [])  # fmt: skip
    print("| " + " | ".join(mean) + " |")
    return notes


def sheets_table(names: list, res: dict) -> list[str]:
    head = [
        "instance", "parts", "sheet", "spacing / margin", "stock", "sheets used", "LB area",
        "LB inside margins", "density %", "last-sheet length", "wall / CPU s",
        "verify (exact / shapely)",
    ]  # fmt: skip
    print("\n### sheets (minkowski2d only: spyrrow has no bin packing)\n")
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    notes, dens, excess = [], [], []
    for name in names:
        r = res[name]
        o = r.get("ours")
        ok = o is not None and "error" not in o
        W = r["sheet"]
        if ok:
            dens.append(o["density"])
            excess.append(o["n_sheets"] - r["lb_margin"])
        cells = [
            name, str(r["parts"]), f"{num(W)} x {num(W)}",
            f"{num(r['spacing'])} / {num(r['margin'])}", str(r["stock"]),
            str(o["n_sheets"]) if ok else "-", str(r["lb"]), str(r["lb_margin"]),
            pct(o["density"]) if ok else "-", num(o["length"]) if ok else "-",
            f"{o['wall']:.1f} / {o['cpu']:.1f}" if ok else "-", verdict(o) if ok else "-",
        ]  # fmt: skip
        print("| " + " | ".join(cells) + " |")
        if o is not None and "error" in o:
            notes.append(f"{name}: minkowski2d raised {o['error']}")
        elif ok:
            if o["exact"] != "ok":
                notes.append(f"{name}: minkowski2d exact verify: {o['exact']}")
            if shapely_label(o["shapely"]) != "ok":
                notes.append(f"{name}: minkowski2d shapely: {shapely_label(o['shapely'])}")
    if dens:
        print(
            f"| **mean** | | | | | | | | {pct(statistics.fmean(dens))} | | | |\n\n"
            f"sheets above the inside-margins bound: {sum(excess)} over {len(excess)} instances"
        )
    return notes


# -- main -----------------------------------------------------------------------------------


def jsonable(r):
    if isinstance(r, dict):
        return {k: jsonable(v) for k, v in r.items() if k != "layout"}
    if isinstance(r, list | tuple):
        return [jsonable(v) for v in r]
    return r


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--time", type=int, default=60, help="seconds per run (whole: spyrrow's unit)")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--set", default="classic", help="comma-separated: " + ", ".join(SETS))
    ap.add_argument("--only", default=None, help="comma-separated instance names")
    ap.add_argument("--json", default=None, help="write every figure there")
    ap.add_argument("--layouts", default=None, help="folder: write each layout as .json, .svg")
    ap.add_argument("--no-spyrrow", action="store_true")
    ap.add_argument("--no-ours", action="store_true")
    ap.add_argument("--sheet", type=float, default=1.0, help="sheet side, times the strip H")
    ap.add_argument("--spacing", type=float, default=0.01, help="spacing, times H")
    ap.add_argument("--margin", type=float, default=0.02, help="margin, times H")
    ap.add_argument(
        "--stock", type=int, default=None,
        help="sheets available per instance (default: 2 x the inside-margins bound + 1)",
    )  # fmt: skip
    args = ap.parse_args()
    if args.time < 1:
        ap.error("--time: at least 1 s (spyrrow takes whole seconds)")
    sets = [s.strip() for s in args.set.split(",") if s.strip()]
    for s in sets:
        if s not in SETS:
            ap.error(f"--set: unknown set {s!r} (one of {', '.join(SETS)})")
    only = {s.strip() for s in args.only.split(",")} if args.only else None
    try:
        import spyrrow  # noqa: F401

        spy_version = _version("spyrrow")
    except ImportError:
        spy_version = None
        if not args.no_spyrrow:
            print("note: spyrrow not installed (pip install spyrrow): its columns are empty")
            args.no_spyrrow = True
    if not args.no_ours and not hasattr(mk, "nest"):
        print("note: minkowski2d.nest does not exist in this build: our columns are empty")
        args.no_ours = True
    print(
        f"minkowski2d {mk.__version__}, spyrrow {spy_version}; {args.time} s per run, "
        f"{args.threads} threads, seed {args.seed}; {os.cpu_count()} CPUs, load average "
        f"{os.getloadavg()[0]:.2f} at start; {platform.processor() or platform.machine()}"
    )
    out_dir = Path(args.layouts) if args.layouts else None
    if out_dir:
        out_dir.mkdir(parents=True, exist_ok=True)
    results: dict = {}
    notes: list[str] = []
    for s in sets:
        names = [n for n in SETS[s] if only is None or n in only]
        if not names:
            continue
        res: dict = {}
        for name in names:
            inst = load(name)
            H = float(inst["strip"]["height"])
            r: dict = {"parts": int(sum(inst["quantities"])), "height": H}
            res[name] = r
            if s == "sheets":
                W, sp, mg = args.sheet * H, args.spacing * H, args.margin * H
                A = total_area(inst)
                lbm = math.ceil(A / ((W - 2 * mg) ** 2))
                stock = args.stock or 2 * lbm + 1
                r.update(sheet=W, spacing=sp, margin=mg, lb=math.ceil(A / (W * W)),
                         lb_margin=lbm, stock=stock)  # fmt: skip
                if not args.no_ours:
                    r["ours"] = _guard(run_ours, inst, args, sheets=[((W, W), stock)],
                                       spacing=sp, margin=mg)  # fmt: skip
            else:
                if not args.no_spyrrow:
                    r["spyrrow"] = _guard(run_spyrrow, inst, args)
                if not args.no_ours:
                    r["ours"] = _guard(run_ours, inst, args)
            if out_dir:
                for who in ("ours", "spyrrow"):
                    lay = r.get(who, {}).get("layout")
                    if lay is not None:
                        for ext in ("json", "svg"):
                            lay.write(out_dir / f"{s}_{name}_{who}.{ext}")
            done = ", ".join(
                f"{who} {pct(r[who].get('density'))} % in {r[who].get('wall', 0):.1f} s"
                for who in ("spyrrow", "ours")
                if who in r
            )
            print(f"  {s}/{name}: {done}", flush=True)
        notes += sheets_table(names, res) if s == "sheets" else strip_table(s, names, res)
        results[s] = res
    for n in notes:
        print(f"note: {n}")
    if args.json:
        meta = {
            "time": args.time, "threads": args.threads, "seed": args.seed,
            "minkowski2d": mk.__version__, "spyrrow": spy_version, "cpus": os.cpu_count(),
        }  # fmt: skip
        Path(args.json).write_text(json.dumps({"meta": meta, **jsonable(results)}, indent=1))


def _guard(fn, *args, **kw) -> dict:
    """One run; a tool's exception is a row's note, not the end of the benchmark."""
    try:
        return fn(*args, **kw)
    except Exception as exc:  # noqa: BLE001 - reported in the table's notes
        return {"error": f"{type(exc).__name__}: {exc}"}


def _version(dist: str) -> str | None:
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version(dist)
    except PackageNotFoundError:
        return None


if __name__ == "__main__":
    main()
