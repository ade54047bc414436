// boolean.hpp -- polygon booleans and line clipping on the exact overlay (overlay.hpp).
//
// An operand is a set of polygons (shells and holes, any orientation) as flat arrays.
// With `validate`, each polygon is checked exactly (polygon.hpp: simple rings, holes
// inside, no crossings) and its rings are weighted by their orientation so that every
// polygon has winding number 1 inside and 0 outside, whatever way its rings run; the
// polygons of one operand may overlap or touch (the operand is their union: the rule
// reads w >= 1). Without it (a fill rule resolves self-intersecting input, as Clipper
// and iOverlay do), every ring counts +1 around what it encloses counter-clockwise, as
// given, and only finiteness is checked. The two operands are the overlay's two layers;
// union_all puts every member on layer 0 (the union of valid members is w >= 1). Lines
// to clip are layer-2 edges. Every decision is an exact sign; vertices are the correctly
// rounded exact vertices (overlay.hpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "exact.hpp"
#include "overlay.hpp"
#include "polygon.hpp"

namespace mk {
namespace bop {

// polygons [p0, p1) of flat arrays (global offsets, shapely's ragged layout)
struct Polys {
  const double* xy;
  const i64* ro;  // ring offsets into xy rows
  const i64* po;  // polygon offsets into rings
  i64 p0, p1;
};

// where an operand failed: status (Status), the operand (0 or 1; for union_all the
// polygon's member), the ring (counted inside the operand) and vertex, the reason
struct Fault {
  int status = OK;
  int operand = -1;
  int reason = 0;
  i64 ring = -1, vertex = -1;
};

// the weight of each ring of `a` (appended to w); a Fault when a polygon is not valid
inline Fault ring_weights(const Polys& a, bool validate, int operand, std::vector<int>& w) {
  Fault f;
  const i64 r0 = a.po[a.p0], r1 = a.po[a.p1];
  if (!validate) {
    for (i64 r = r0; r < r1; ++r) {
      for (i64 i = a.ro[r]; i < a.ro[r + 1]; ++i)
        if (!(a.xy[2 * i] - a.xy[2 * i] == 0) || !(a.xy[2 * i + 1] - a.xy[2 * i + 1] == 0)) {
          f.status = NONFINITE;
          f.operand = operand;
          f.ring = r - r0;
          f.vertex = i - a.ro[r];
          return f;
        }
      w.push_back(1);
    }
    return f;
  }
  // local offsets: the check numbers rings from the operand's first
  const i64 R = r1 - r0, P = a.p1 - a.p0, v0 = a.ro[r0];
  std::vector<i64> ro(R + 1), po(P + 1);
  for (i64 r = 0; r <= R; ++r) ro[r] = a.ro[r0 + r] - v0;
  for (i64 p = 0; p <= P; ++p) po[p] = a.po[a.p0 + p] - r0;
  std::vector<int> orient(R > 0 ? R : 1);
  std::vector<std::uint8_t> disc(P > 0 ? P : 1);
  polygon::Problem pr =
      polygon::check(a.xy + 2 * v0, ro.data(), R, po.data(), P, false, orient.data(), disc.data());
  if (!pr.ok()) {
    f.status = pr.status;
    f.reason = pr.reason;
    f.operand = operand;
    f.ring = pr.ring;
    f.vertex = pr.vertex;
    return f;
  }
  for (i64 p = 0; p < P; ++p)
    for (i64 r = po[p]; r < po[p + 1]; ++r) w.push_back(r == po[p] ? orient[r] : -orient[r]);
  return f;
}

// the rings of `a` as overlay edges on `layer`, weighted by w (from w[k] on)
inline void add_polys(ov::Geo& g, const Polys& a, const std::vector<int>& w, std::size_t k,
                      int layer, std::vector<ov::EdgeIn>& in) {
  for (i64 r = a.po[a.p0]; r < a.po[a.p1]; ++r, ++k) {
    const i64 first = (i64)g.pts.size(), n0 = a.ro[r], n = a.ro[r + 1] - n0;
    for (i64 i = 0; i < n; ++i) g.point(ov::dd(a.xy[2 * (n0 + i)]), ov::dd(a.xy[2 * (n0 + i) + 1]));
    ov::add_ring(g, first, n, w[k], layer, in);
  }
}

struct Limits {
  i64 max_crossings = NO_LIMIT;
  i64 max_pairs = NO_LIMIT;
};

// One boolean: a (layer 0) op b (layer 1) under the rule (ov::make_rule), or, when b has
// no polygons and op is UNION, the region of a alone (union_all: every polygon on layer
// 0). Result rings in `out` (out.status RESOURCE / OVERFLOW / INTERNAL), faults in f.
inline void boolean(const Polys& a, const Polys& b, int rule, bool validate, const Limits& lim,
                    ov::Rings& out, Fault& f) {
  out.clear();
  std::vector<int> w;
  f = ring_weights(a, validate, 0, w);
  if (f.status != OK) return;
  const std::size_t na = w.size();
  f = ring_weights(b, validate, 1, w);
  if (f.status != OK) return;
  ov::Geo g;
  std::vector<ov::EdgeIn> in;
  const std::size_t nv = (std::size_t)(a.ro[a.po[a.p1]] - a.ro[a.po[a.p0]] +
                                       b.ro[b.po[b.p1]] - b.ro[b.po[b.p0]]);
  g.pts.reserve(nv);
  g.lines.reserve(nv);
  g.verts.reserve(nv);
  in.reserve(nv);
  add_polys(g, a, w, 0, 0, in);
  add_polys(g, b, w, na, 1, in);
  ov::Overlay o(g);
  o.max_crossings = lim.max_crossings;
  o.max_pairs = lim.max_pairs;
  o.run(in, rule, out);
}

// Polylines (vertices lxy, offsets loff [l0, l1]) clipped by the region of a under the
// rule's fill (layer 0, op UNION): the parts inside (closed) or outside (open).
inline int clip(const double* lxy, const i64* loff, i64 l0, i64 l1, const Polys& a, int fill,
                bool validate, bool keep_inside, const Limits& lim, std::vector<double>& xy,
                std::vector<i64>& off, Fault& f) {
  xy.clear();
  off.assign(1, 0);
  std::vector<int> w;
  f = ring_weights(a, validate, 1, w);
  if (f.status != OK) return f.status;
  for (i64 l = l0; l < l1; ++l)
    for (i64 i = loff[l]; i < loff[l + 1]; ++i)
      if (!(lxy[2 * i] - lxy[2 * i] == 0) || !(lxy[2 * i + 1] - lxy[2 * i + 1] == 0)) {
        f.status = NONFINITE;
        f.operand = 0;
        f.ring = l - l0;
        f.vertex = i - loff[l];
        return f.status;
      }
  ov::Geo g;
  std::vector<ov::EdgeIn> in;
  add_polys(g, a, w, 0, 0, in);
  for (i64 l = l0; l < l1; ++l) {
    const i64 first = (i64)g.pts.size(), n = loff[l + 1] - loff[l];
    const i64 v0 = (i64)g.verts.size();
    for (i64 i = 0; i < n; ++i) {
      g.point(ov::dd(lxy[2 * (loff[l] + i)]), ov::dd(lxy[2 * (loff[l] + i) + 1]));
      g.vert_point(first + i);
    }
    for (i64 i = 0; i + 1 < n; ++i) {
      if (ov::p_eq(g.pts[first + i], g.pts[first + i + 1])) continue;
      i64 ln = g.line(first + i, first + i + 1);
      in.push_back(ov::EdgeIn{ln, v0 + i, v0 + i + 1, 1, 2});
    }
  }
  ov::Overlay o(g);
  o.max_crossings = lim.max_crossings;
  o.max_pairs = lim.max_pairs;
  return o.run_lines(in, ov::make_rule(ov::UNION, fill), keep_inside, xy, off);
}

}  // namespace bop
}  // namespace mk
