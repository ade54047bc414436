"""DXF drawings (the one DXF reader): closed polylines, circles, line and arc chains; nested
outlines are holes; arcs read with a one-sided approximation."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np

from ..errors import (
    EmptyGeometryError,
    GeometryError,
    InputFormatError,
)
from .common import Feature, _intify, _short


def read_dxf(
    source: str | Path, *, tolerance: float | None = None, name: str | None = None
) -> list[Feature]:
    """The closed outlines of a DXF drawing's model space as polygons, one feature per
    part, with properties ``layer``, ``handle`` and ``entity`` (of the part's outline) and
    ``holes`` (the handles of its holes, when it has some). Needs ezdxf (the ``dxf``
    extra).

    Outlines are closed LWPOLYLINEs and 2-D POLYLINEs (their arcs, given as bulges,
    included), CIRCLEs, and closed chains of LINE and ARC entities (end points joined
    within ``1e-9`` of the drawing's size). An outline inside another is a hole of it
    (and one inside a hole is a part again). Open polylines and chains are skipped.

    Arcs are read with a one-sided approximation (see :mod:`minkowski2d._engine.arcs`): the
    polygon contains the part (parts grow, holes shrink) and lies within ``tolerance``
    of it. ``tolerance``: the largest error, in drawing units; default (None)
    :data:`~minkowski2d._engine.arcs.DEFAULT_RELATIVE_TOLERANCE` (``1e-3``) times each
    arc's radius. The exact outline is kept on the feature (``arcs``: one
    ``(k, 3)`` array ``(x, y, bulge)`` per ring, exterior first). A part without arcs is
    read exactly (an (n, 2) array, ints where the coordinates are whole numbers).

    Raises
    ------
    InputFormatError
        ezdxf missing, a file that is not DXF, ELLIPSE or SPLINE entities (not read: a
        curve that is not an arc would be dropped), an entity out of the drawing's plane,
        or a drawing without closed outlines.
    """
    name = str(source) if name is None else name
    try:
        import ezdxf
    except ImportError:
        raise InputFormatError(
            f"{name}: reading DXF needs ezdxf",
            argument=name,
            hint="pip install 'minkowski2d[dxf]'",
        ) from None
    tol = None
    if tolerance is not None:
        from .._engine import options as _options

        tol = _options.real(tolerance, "arc_tolerance")
        if tol <= 0:
            raise _options_error("arc_tolerance", tolerance)
    try:
        doc = ezdxf.readfile(str(source))
    except OSError as exc:
        raise InputFormatError(
            f"{name}: cannot read ({exc.strerror or exc})", argument=name
        ) from None
    except Exception as exc:  # ezdxf.DXFStructureError and friends
        raise InputFormatError(
            f"{name}: not a readable DXF file ({_short(str(exc))})", argument=name
        ) from None
    rings = _dxf_rings(doc.modelspace(), name)
    if not rings:
        raise EmptyGeometryError(
            f"{name}: no closed outlines (LWPOLYLINE, POLYLINE, CIRCLE, or LINE and ARC "
            "chains) in the model space",
            argument=name,
            hint="close the outlines in the CAD program",
        )
    return _dxf_parts(rings, name, tol)


def _options_error(option: str, value: Any) -> GeometryError:
    from ..errors import OptionError

    return OptionError(
        f"{option}: must be a positive number, got {value!r}",
        argument=option,
        allowed="a positive number (drawing units)",
    )


class _Ring(NamedTuple):
    rows: list  # (x, y, bulge)
    props: dict


def _ocs(e: Any, where: str, name: str) -> float:
    """+1 for an entity in the drawing's plane, -1 for one seen from below (a mirrored
    extrusion: x is negated and arcs turn the other way)."""
    ext = tuple(float(v) for v in e.dxf.get("extrusion", (0.0, 0.0, 1.0)))
    if ext[0] == 0.0 and ext[1] == 0.0 and ext[2] != 0.0:
        return 1.0 if ext[2] > 0 else -1.0
    raise InputFormatError(
        f"{where}: the entity is not in the drawing's plane (extrusion {ext})",
        argument=name,
        hint="flatten the drawing to 2-D in the CAD program",
    )


def _finite_rows(rows: list, where: str, name: str) -> list:
    if not all(math.isfinite(v) for r in rows for v in r):
        raise InputFormatError(f"{where}: a non-finite coordinate", argument=name)
    return rows


def _dxf_rings(msp: Any, name: str) -> list[_Ring]:
    rings: list[_Ring] = []
    pieces = []  # open LINE / ARC pieces: (x0, y0, x1, y1, bulge, props)
    for e in msp:
        kind = e.dxftype()
        where = f"{name}: {kind} {e.dxf.handle}"
        props = {"layer": e.dxf.layer, "handle": e.dxf.handle, "entity": kind}
        if kind in ("ELLIPSE", "SPLINE", "HELIX"):
            raise InputFormatError(
                f"{where}: {kind} entities are not read (only segments and circular arcs)",
                argument=name,
                hint="convert it to a polyline or to arcs in the CAD program",
            )
        if kind == "LWPOLYLINE":
            s = _ocs(e, where, name)
            pts = [(s * x, y, s * b) for x, y, b in e.get_points("xyb")]
            closed = bool(e.closed)
        elif kind == "POLYLINE":
            if not (e.is_2d_polyline or e.is_3d_polyline):
                continue  # meshes and polyface meshes are not polygons
            s = _ocs(e, where, name) if e.is_2d_polyline else 1.0
            pts = [
                (s * v.dxf.location[0], v.dxf.location[1], s * v.dxf.get("bulge", 0.0))
                for v in e.vertices
            ]
            closed = bool(e.is_closed)
        elif kind == "CIRCLE":
            s = _ocs(e, where, name)
            c, r = e.dxf.center, float(e.dxf.radius)
            if r > 0:
                from .._engine.arcs import circle_ring

                rows = circle_ring(s * float(c[0]), float(c[1]), r)
                rings.append(_Ring(_finite_rows(rows, where, name), props))
            continue
        elif kind == "LINE":
            a, b = e.dxf.start, e.dxf.end
            pieces.append((float(a[0]), float(a[1]), float(b[0]), float(b[1]), 0.0, props))
            continue
        elif kind == "ARC":
            s = _ocs(e, where, name)
            c, r = e.dxf.center, float(e.dxf.radius)
            a0, a1 = math.radians(e.dxf.start_angle), math.radians(e.dxf.end_angle)
            sweep = (a1 - a0) % (2 * math.pi) or 2 * math.pi
            x0, y0 = c[0] + r * math.cos(a0), c[1] + r * math.sin(a0)
            x1, y1 = c[0] + r * math.cos(a1), c[1] + r * math.sin(a1)
            if sweep >= 2 * math.pi:  # a closed arc: a circle
                from .._engine.arcs import circle_ring

                rings.append(_Ring(circle_ring(s * float(c[0]), float(c[1]), r), props))
                continue
            bulge = math.tan(sweep / 4)
            pieces.append((s * x0, y0, s * x1, y1, s * bulge, props))
            continue
        else:
            continue
        pts = [(float(x), float(y), float(b)) for x, y, b in pts]
        if len(pts) > 1 and pts[0][:2] == pts[-1][:2]:
            pts = pts[:-1]
            closed = True
        if not closed or not pts:
            continue
        rings.append(_Ring(_finite_rows(pts, f"{where}", name), props))
    if pieces:
        rings.extend(_chains(pieces, name))
    return rings


def _chains(pieces: list, name: str) -> list[_Ring]:
    """Closed loops of LINE and ARC pieces joined end to end (within a slack of 1e-9 of
    the drawing's size); open chains are skipped."""
    P = np.array([p[:4] for p in pieces], dtype=np.float64)
    if not np.isfinite(P).all():
        raise InputFormatError(f"{name}: a LINE or ARC has a non-finite coordinate")
    slack = 1e-9 * max(float(np.abs(P).max()), 1e-300)
    ends = np.concatenate([P[:, 0:2], P[:, 2:4]])  # start points, then end points
    n = len(pieces)
    used = np.zeros(n, bool)
    loops = []
    for s0 in range(n):
        if used[s0]:
            continue
        used[s0] = True
        order = [(s0, False)]
        first = P[s0, 0:2]
        cur = P[s0, 2:4]
        closed = False
        for _ in range(n):
            if np.abs(cur - first).max() <= slack and len(order) > 1:
                closed = True
                break
            near = np.flatnonzero(np.abs(ends - cur).max(axis=1) <= slack)
            nxt = [(int(k % n), bool(k >= n)) for k in near if not used[k % n]]
            if not nxt:
                break
            k, rev = nxt[0]
            used[k] = True
            order.append((k, rev))
            cur = P[k, 0:2] if rev else P[k, 2:4]
        if not closed:
            continue
        rows = []
        for k, rev in order:
            x0, y0, x1, y1, b, _ = pieces[k]
            rows.append((x1, y1, -b) if rev else (x0, y0, b))
        props = dict(pieces[order[0][0]][5])
        props["entity"] = "LINE/ARC chain"
        props["handles"] = [pieces[k][5]["handle"] for k, _ in order]
        loops.append(_Ring(rows, props))
    return loops


def _dxf_parts(rings: list[_Ring], name: str, tol: float | None) -> list[Feature]:
    """Nest the rings (a ring inside an odd number of others is a hole of the innermost
    one around it), approximate their arcs on the side that grows the part, and build
    one feature per part."""
    import shapely

    from .._engine.arcs import approximate, ring_area

    areas = [ring_area(r.rows) for r in rings]
    # a coarse polygon per ring for the nesting test: its vertices and arc midpoints
    coarse = []
    for r in rings:
        pts = approximate(r.rows, True, tol, name)
        coarse.append(shapely.Polygon(pts) if len(pts) >= 3 else shapely.Point(pts[0]))
    ok = [abs(a) > 0 and c.geom_type == "Polygon" for a, c in zip(areas, coarse)]
    depth = np.zeros(len(rings), np.int64)
    parent = np.full(len(rings), -1, np.int64)
    tree = shapely.STRtree([c if ok[i] else shapely.Point() for i, c in enumerate(coarse)])
    for i, r in enumerate(rings):
        pt = shapely.Point(r.rows[0][:2])
        cand = [int(j) for j in tree.query(pt, predicate="within") if j != i and ok[j]]
        cand = [j for j in cand if abs(areas[j]) > abs(areas[i])]
        depth[i] = len(cand)
        if cand:
            parent[i] = min(cand, key=lambda j: abs(areas[j]))
    feats = []
    for i, r in enumerate(rings):
        if depth[i] % 2:
            continue  # a hole: with its part
        holes = [j for j in range(len(rings)) if parent[j] == i and depth[j] % 2]
        shell = _ring_polygon(r, areas[i], True, tol, name)
        hs = [_ring_polygon(rings[j], areas[j], False, tol, name) for j in holes]
        exact = [np.array(r.rows)] + [np.array(rings[j].rows) for j in holes]
        props = dict(r.props)
        if holes:
            props["holes"] = [rings[j].props["handle"] for j in holes]
        if hs:
            geom: Any = shapely.Polygon(shell, hs)
        else:
            geom = _intify(shell) if not any(row[2] for row in r.rows) else shell
        feats.append(Feature(geom, props, {}, exact))
    return feats


def _ring_polygon(r: _Ring, area: float, outer: bool, tol: float | None, name: str) -> Any:
    """The ring as a polygon containing the part: the region is on the left of a
    counter-clockwise outline and on the right of a counter-clockwise hole."""
    from .._engine.arcs import approximate

    region_left = (area > 0) == outer
    where = f"{name}: {r.props.get('entity')} {r.props.get('handle')}"
    return approximate(r.rows, region_left, tol, where)


def _one_dxf(name: str, arc_tolerance: float | None = None) -> Any:
    feats = read_dxf(name, tolerance=arc_tolerance)
    if len(feats) > 1:
        raise InputFormatError(
            f"{name}: the drawing holds {len(feats)} closed polylines (parts); this command "
            "takes one",
            argument=name,
            hint="sum, inflate and hull take the whole drawing, one result per polyline",
        )
    return feats[0].geometry
