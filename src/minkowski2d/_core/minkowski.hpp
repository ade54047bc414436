// minkowski.hpp -- non-convex Minkowski sums on the exact overlay.
//
// An operand is a set of polygons with holes (float64 rings, exteriors and holes in any
// orientation; validated by the caller). Two methods, both ending in one overlay whose
// rule is "winding number >= 1":
//
//  * pieces (decomposition): the sums P_k + Q_l of all pairs of convex pieces, each
//    from the merge of convex.hpp (merge_ids: the vertex A[i] + B[j] is kept exact as a
//    TwoSum), united by the cascaded union (overlay.hpp). Every piece sum is a counter-
//    clockwise ring with winding number 1 inside, so the union is w >= 1.
//  * convolution: the full convolution of the boundaries (Guibas, Ramshaw and Stolfi's
//    kinetic framework): for an edge e of one ring and a vertex v of the other, the
//    segment e + v when e's direction lies in the range of directions the other ring
//    turns through at v -- forwards when v turns left (convex), backwards when it turns
//    right (reflex). The winding number of these segments around x is the Euler
//    characteristic of P ∩ (x − Q): the number of its components when that intersection
//    has no holes. Holes are made harmless first (Baram, Fogel, Halperin, Hemmer and
//    Morr 2015): a hole of P that Q cannot fit into (Q's box is not strictly smaller
//    in both directions) is filled -- it changes nothing -- and a hole Q can fit into
//    can never be surrounded by x − Q; at most one operand keeps holes. Then w >= 1 is
//    exactly the sum.
// A point operand translates the other; a segment operand s gives the union of P, P + d
// and the parallelograms e + s of P's edges (no decomposition needed).
#pragma once

#include <algorithm>
#include <vector>

#include "convex.hpp"
#include "decompose.hpp"
#include "exact.hpp"
#include "exactnum.hpp"
#include "overlay.hpp"
#include "polygon.hpp"
#include "triangulate.hpp"
#include "union.hpp"

namespace mk {
namespace ms {

using ov::DD;
using ov::EdgeIn;
using ov::Geo;
using ov::Cascade;
using ov::Overlay;
using ov::Rings;

// A ring of an operand: vertex coordinates (x, y pairs), consecutive duplicates removed,
// inside on the left (exteriors counter-clockwise, holes clockwise).
struct Ring {
  std::vector<double> xy;
  bool hole = false;
  i64 n() const { return (i64)xy.size() / 2; }
  double x(i64 i) const { return xy[2 * i]; }
  double y(i64 i) const { return xy[2 * i + 1]; }
};

// A polygon: its exterior and holes.
struct Polygon {
  Ring ext;
  std::vector<Ring> holes;
};

// +1 counter-clockwise, -1 clockwise, 0 no area: the turn at the lowest vertex (x, then y)
inline int ring_orientation(const double* xy, i64 n) {
  if (n < 3) return 0;
  i64 lo = 0;
  for (i64 i = 1; i < n; ++i)
    if (xy[2 * i] < xy[2 * lo] || (xy[2 * i] == xy[2 * lo] && xy[2 * i + 1] < xy[2 * lo + 1]))
      lo = i;
  i64 p = (lo + n - 1) % n, q = (lo + 1) % n;
  return cross_sign(xy[2 * p], xy[2 * p + 1], xy[2 * lo], xy[2 * lo + 1], xy[2 * lo],
                    xy[2 * lo + 1], xy[2 * q], xy[2 * q + 1]);
}

// A ring from raw coordinates: drop a closing repeat and consecutive duplicates, orient.
inline Ring make_ring(const double* xy, i64 n, bool hole) {
  Ring r;
  r.hole = hole;
  for (i64 i = 0; i < n; ++i) {
    double x = xy[2 * i], y = xy[2 * i + 1];
    i64 m = r.n();
    if (m > 0 && r.x(m - 1) == x && r.y(m - 1) == y) continue;
    r.xy.push_back(x);
    r.xy.push_back(y);
  }
  while (r.n() > 1 && r.x(0) == r.x(r.n() - 1) && r.y(0) == r.y(r.n() - 1)) r.xy.resize(r.xy.size() - 2);
  int o = ring_orientation(r.xy.data(), r.n());
  if ((o < 0) != hole) {
    // reverse to put the inside on the left
    i64 m = r.n();
    for (i64 i = 0, j = m - 1; i < j; ++i, --j) {
      std::swap(r.xy[2 * i], r.xy[2 * j]);
      std::swap(r.xy[2 * i + 1], r.xy[2 * j + 1]);
    }
  }
  return r;
}

// bounding box of a ring
struct Box {
  double x0, x1, y0, y1;
};
inline Box ring_box(const Ring& r) {
  Box b{INFINITY, -INFINITY, INFINITY, -INFINITY};
  for (i64 i = 0; i < r.n(); ++i) {
    b.x0 = std::min(b.x0, r.x(i));
    b.x1 = std::max(b.x1, r.x(i));
    b.y0 = std::min(b.y0, r.y(i));
    b.y1 = std::max(b.y1, r.y(i));
  }
  return b;
}
// sign of (a1 - a0) - (b1 - b0), exactly
inline int width_cmp(double a0, double a1, double b0, double b1) {
  return ((Dy(a1) - Dy(a0)) - (Dy(b1) - Dy(b0))).sign();
}
// Can a translate of something with box q fit strictly inside box h? (necessary test)
inline bool may_fit(const Box& q, const Box& h) {
  return width_cmp(q.x0, q.x1, h.x0, h.x1) < 0 && width_cmp(q.y0, q.y1, h.y0, h.y1) < 0;
}

// The rings of polygon P for the convolution with a polygon whose box is `other`: the
// holes it cannot fit into are filled (dropped).
inline std::vector<const Ring*> conv_rings(const Polygon& p, const Box& other) {
  std::vector<const Ring*> out{&p.ext};
  for (const Ring& h : p.holes)
    if (may_fit(other, ring_box(h))) out.push_back(&h);
  return out;
}

inline Box operand_box(const std::vector<Polygon>& P) {
  Box b{INFINITY, -INFINITY, INFINITY, -INFINITY};
  for (const Polygon& p : P) {
    Box r = ring_box(p.ext);
    b.x0 = std::min(b.x0, r.x0);
    b.x1 = std::max(b.x1, r.x1);
    b.y0 = std::min(b.y0, r.y0);
    b.y1 = std::max(b.y1, r.y1);
  }
  return b;
}

// Is direction d (d0 -> d1) in the range a ring turns through at its vertex j (from the
// incoming edge u to the outgoing v)? `start_open`: the range excludes its start
// direction and includes its end (edges of the other ring at this ring's vertices use
// the opposite convention, so that parallel edges pair exactly once; the ends are fixed
// in angle, not in the order of traversal, so the count of a direction over a ring is
// its net number of turns through it, 1). Returns +1 for a left turn (the segment
// forwards), -1 for a right turn (backwards), 0 not in range.
struct Dir {
  double x0, y0, x1, y1;
};
inline int cr(const Dir& a, const Dir& b) {
  return cross_sign(a.x0, a.y0, a.x1, a.y1, b.x0, b.y0, b.x1, b.y1);
}
inline int in_range(const Dir& u, const Dir& v, const Dir& d, bool start_open) {
  int t = cr(u, v);
  if (t > 0) {
    // counter-clockwise from u to v (less than a half-turn)
    int a = cr(u, d), b = cr(d, v);
    bool in = start_open ? (a > 0 && b >= 0) : (a >= 0 && b > 0);
    return in ? 1 : 0;
  }
  if (t < 0) {
    // clockwise from u to v: the directions from v to u counter-clockwise. The open end
    // is the same end *in angle* as for a left turn (the low end for `start_open`), so
    // that a direction is counted once per net turn through it: here that is v.
    int a = cr(v, d), b = cr(d, u);
    bool in = start_open ? (a > 0 && b >= 0) : (a >= 0 && b > 0);
    return in ? -1 : 0;
  }
  return 0;  // straight on (collinear vertex): no turn
}

// The convolution's walk over ring R (edges) and ring S (vertices): f(i, j, s) for every
// edge i of R in the cone of vertex j of S (s: in_range's side); f returns false to stop
// (then so does the walk: false).
template <class F>
inline bool conv_ring_walk(const Ring& R, const Ring& S, bool start_open, F&& f) {
  const i64 n = R.n(), m = S.n();
  if (n < 2 || m < 1) return true;
  for (i64 j = 0; j < m; ++j) {
    i64 jp = (j + m - 1) % m, jn = (j + 1) % m;
    Dir u{S.x(jp), S.y(jp), S.x(j), S.y(j)}, v{S.x(j), S.y(j), S.x(jn), S.y(jn)};
    if (cr(u, v) == 0) continue;
    for (i64 i = 0; i < n; ++i) {
      i64 in = (i + 1) % n;
      Dir d{R.x(i), R.y(i), R.x(in), R.y(in)};
      int s = in_range(u, v, d, start_open);
      if (s && !f(i, j, s)) return false;
    }
  }
  return true;
}

// The full convolution's walk of two operands: of every polygon of A with every polygon
// of B, after filling the holes of each that the other cannot fit into (conv_rings);
// f(R, S, i, j, s) per segment (edge i of R at vertex j of S), false to stop.
template <class F>
inline void conv_walk(const std::vector<Polygon>& A, const std::vector<Polygon>& B, F&& f) {
  for (const Polygon& p : A)
    for (const Polygon& q : B) {
      std::vector<const Ring*> ra = conv_rings(p, ring_box(q.ext)), rb = conv_rings(q, ring_box(p.ext));
      for (const Ring* r : ra)
        for (const Ring* t : rb) {
          // edges of A at vertices of B, then edges of B at vertices of A
          if (!conv_ring_walk(*r, *t, true, [&](i64 i, i64 j, int s) { return f(*r, *t, i, j, s); }))
            return;
          if (!conv_ring_walk(*t, *r, false, [&](i64 i, i64 j, int s) { return f(*t, *r, i, j, s); }))
            return;
        }
    }
}

// The full convolution of two operands as overlay edges. The winding number around x is
// the sum over the polygon pairs of the number of components of P_k ∩ (x − Q_l): at
// least 1 exactly where x is in A ⊕ B.
inline void convolution(Geo& g, const std::vector<Polygon>& A, const std::vector<Polygon>& B,
                        std::vector<EdgeIn>& out) {
  conv_walk(A, B, [&](const Ring& R, const Ring& S, i64 i, i64 j, int s) {
    const i64 in = (i + 1) % R.n();
    i64 a = g.point(ov::dd_sum(R.x(i), S.x(j)), ov::dd_sum(R.y(i), S.y(j)));
    i64 b = g.point(ov::dd_sum(R.x(in), S.x(j)), ov::dd_sum(R.y(in), S.y(j)));
    if (ov::p_eq(g.pts[a], g.pts[b])) return true;
    i64 l = g.line(a, b);
    i64 va = g.vert_point(a), vb = g.vert_point(b);
    if (s > 0)
      out.push_back(EdgeIn{l, va, vb, 1, 0});
    else
      out.push_back(EdgeIn{l, vb, va, 1, 0});
    return true;
  });
}

// All rings of an operand as overlay edges (weight 1: winding 1 inside each polygon),
// translated by (tx, ty) (exact: DD).
inline void operand_edges(Geo& g, const std::vector<Polygon>& A, double tx, double ty,
                          std::vector<EdgeIn>& out) {
  auto ring = [&](const Ring& r) {
    i64 first = (i64)g.pts.size();
    for (i64 i = 0; i < r.n(); ++i) g.point(ov::dd_sum(r.x(i), tx), ov::dd_sum(r.y(i), ty));
    ov::add_ring(g, first, r.n(), 1, 0, out);
  };
  for (const Polygon& p : A) {
    ring(p.ext);
    for (const Ring& h : p.holes) ring(h);
  }
}

// A ⊕ segment [s0, s1]: A, A + (s1 - s0) (both from s0) and the parallelogram swept by
// every edge, each a region with winding 1 inside: their union.
inline void segment_sum(Geo& g, const std::vector<Polygon>& A, double s0x, double s0y,
                        double s1x, double s1y, std::vector<std::vector<EdgeIn>>& parts) {
  parts.emplace_back();
  operand_edges(g, A, s0x, s0y, parts.back());
  parts.emplace_back();
  operand_edges(g, A, s1x, s1y, parts.back());
  auto sweep_ring = [&](const Ring& r) {
    for (i64 i = 0; i < r.n(); ++i) {
      i64 in = (i + 1) % r.n();
      // parallelogram a + s0, b + s0, b + s1, a + s1 (oriented counter-clockwise below)
      double ax = r.x(i), ay = r.y(i), bx = r.x(in), by = r.y(in);
      int o = cross_sign(ax, ay, bx, by, s0x, s0y, s1x, s1y);
      if (o == 0) continue;  // the edge is parallel to the segment: no area
      i64 first = (i64)g.pts.size();
      g.point(ov::dd_sum(ax, s0x), ov::dd_sum(ay, s0y));
      g.point(ov::dd_sum(bx, s0x), ov::dd_sum(by, s0y));
      g.point(ov::dd_sum(bx, s1x), ov::dd_sum(by, s1y));
      g.point(ov::dd_sum(ax, s1x), ov::dd_sum(ay, s1y));
      parts.emplace_back();
      // (b - a) x (s1 - s0) > 0: a+s0, b+s0, b+s1, a+s1 runs counter-clockwise; else a
      // weight of -1 gives the clockwise ring winding number 1 inside
      ov::add_ring(g, first, 4, o > 0 ? 1 : -1, 0, parts.back());
    }
  };
  for (const Polygon& p : A) {
    sweep_ring(p.ext);
    for (const Ring& h : p.holes) sweep_ring(h);
  }
}

// Convex pieces (ragged: coordinates and offsets) of both operands: all piece sums as
// rings of exact vertices, one part each.
inline int piece_sums(Geo& g, const double* pa, const i64* oa, i64 na, const double* pb,
                      const i64* ob, i64 nb, std::vector<std::vector<EdgeIn>>& parts) {
  PiecePair pp;
  if (int code = normalize_pieces(pa, oa, na, pb, ob, nb, pp)) return code;
  const std::vector<Norm>&NA = pp.A, &NB = pp.B;
  for (i64 k = 0; k < na; ++k)
    for (i64 l = 0; l < nb; ++l) {
      i64 first = (i64)g.pts.size();
      merge_ids(pa, NA[k], pb, NB[l], [&](i64 i, i64 j) {
        g.point(ov::dd_sum(pa[2 * i], pb[2 * j]), ov::dd_sum(pa[2 * i + 1], pb[2 * j + 1]));
        return true;
      });
      i64 cnt = (i64)g.pts.size() - first;
      if (cnt < 3) continue;  // a point or a segment: no area
      parts.emplace_back();
      ov::add_ring(g, first, cnt, 1, 0, parts.back());
    }
  return OK;
}

// Polygons from ragged arrays: coordinates (N, 2), ring offsets (R + 1), polygon offsets
// (P + 1) into the rings (the first ring of each polygon is its exterior).
inline std::vector<Polygon> read_polygons(const double* xy, const i64* ro, const i64* po, i64 np) {
  std::vector<Polygon> out(np);
  for (i64 p = 0; p < np; ++p) {
    for (i64 r = po[p]; r < po[p + 1]; ++r) {
      Ring ring = make_ring(xy + 2 * ro[r], ro[r + 1] - ro[r], r != po[p]);
      if (r == po[p])
        out[p].ext = std::move(ring);
      else
        out[p].holes.push_back(std::move(ring));
    }
  }
  return out;
}

// ------------------------------------------------------------------------------------
// the batch driver: many pairs of operands from one table

// Operands in ragged arrays: coordinates (N, 2), ring offsets, polygon offsets, operand
// offsets (into the polygons); kind 0 polygons, 1 a point, 2 a segment (one ring of 1 or
// 2 vertices). Convex pieces (for the decomposition) likewise: coordinates, piece
// offsets, operand offsets into the pieces (an empty range: none given).
struct Table {
  const double* xy;
  const i64 *ring_off, *poly_off, *op_off;
  const std::int8_t* kind;
  const double* pc_xy;
  const i64 *pc_off, *op_pc_off;
  i64 n_ops;
};

enum Method : int { AUTO = 0, PIECES = 1, CONVOLUTION = 2 };

// The work limits of one pair, and their defaults: the one home of these numbers
// (exported as GENERAL_LIMITS; minkowski2d.general.limits starts from them, and a
// ResourceLimitError names them). About 800 bytes per convolution segment with its
// crossings, 150 per crossing: two 2048-vertex stars have over 2 M convolution
// segments and would need gigabytes, so they take the pieces.
struct Limits {
  i64 conv_segments = (i64)1 << 21;  // convolution segments of one pair
  i64 piece_pairs = (i64)1 << 21;    // piece sums of one pair
  i64 crossings = (i64)1 << 21;      // crossings noded for one pair (all runs)
};

inline std::vector<Polygon> operand(const Table& T, i64 op) {
  i64 p0 = T.op_off[op], p1 = T.op_off[op + 1];
  return read_polygons(T.xy, T.ring_off, T.poly_off + p0, p1 - p0);
}

inline i64 vertex_count(const std::vector<Polygon>& P) {
  i64 n = 0;
  for (const Polygon& p : P) {
    n += p.ext.n();
    for (const Ring& h : p.holes) n += h.n();
  }
  return n;
}

// The number of convolution segments (stops counting above limit).
inline i64 conv_count(const std::vector<Polygon>& A, const std::vector<Polygon>& B, i64 limit) {
  i64 cnt = 0;
  conv_walk(A, B, [&](const Ring&, const Ring&, i64, i64, int) { return ++cnt <= limit; });
  return cnt;
}

// The convex pieces of operand `op` (validated polygons): the exact triangulation of
// triangulate.hpp, merged by Hertel-Mehlhorn (decompose.hpp). Coordinates appended to
// pc_xy, piece offsets (absolute, into pc_xy's points) to pc_off (which starts at 0).
inline int operand_pieces(const Table& T, i64 op, std::vector<double>& pc_xy,
                          std::vector<i64>& pc_off) {
  const i64 p0 = T.op_off[op], p1 = T.op_off[op + 1];
  const i64 r0 = T.poly_off[p0], r1 = T.poly_off[p1];
  // rings of this operand, re-based at their first vertex
  const i64 v0 = T.ring_off[r0], v1 = T.ring_off[r1];
  std::vector<i64> ro(r1 - r0 + 1), po(p1 - p0 + 1);
  for (i64 r = r0; r <= r1; ++r) ro[r - r0] = T.ring_off[r] - v0;
  for (i64 p = p0; p <= p1; ++p) po[p - p0] = T.poly_off[p] - r0;
  const double* xy = T.xy + 2 * v0;
  std::vector<i64> tri;
  polygon::Problem pr = polygon::triangulate(xy, ro.data(), r1 - r0, po.data(), p1 - p0, tri, true);
  if (!pr.ok()) return pr.status;
  const i64 nt = (i64)tri.size() / 3, H = 3 * nt, nv = v1 - v0;
  if (nt == 0) return OK;
  // orient the triangles counter-clockwise, drop degenerate ones
  std::vector<char> keep(nt);
  decompose::orient_triangles(xy, tri.data(), nt, reinterpret_cast<bool*>(keep.data()));
  std::vector<i64> ids;
  ids.reserve(tri.size());
  for (i64 t = 0; t < nt; ++t)
    if (keep[t]) ids.insert(ids.end(), tri.begin() + 3 * t, tri.begin() + 3 * t + 3);
  const i64 mt = (i64)ids.size() / 3, M = 3 * mt;
  (void)H;
  // twins: the half-edge (b, a) of each (a, b)
  std::vector<std::pair<i64, i64>> key(M);
  for (i64 h = 0; h < M; ++h) {
    i64 a = ids[h], b = ids[3 * (h / 3) + (h % 3 + 1) % 3];
    key[h] = {a * nv + b, h};
  }
  std::sort(key.begin(), key.end());
  std::vector<i64> twin(M, -1);
  for (i64 h = 0; h < M; ++h) {
    i64 a = ids[h], b = ids[3 * (h / 3) + (h % 3 + 1) % 3];
    auto it = std::lower_bound(key.begin(), key.end(), std::make_pair(b * nv + a, (i64)-1));
    if (it != key.end() && it->first == b * nv + a) twin[h] = it->second;
  }
  std::vector<i64> outv(M > 0 ? M : 1), off(mt + 1);
  i64 np = decompose::hertel_mehlhorn(xy, ids.data(), mt, twin.data(), true, outv.data(), off.data());
  i64 base = (i64)pc_xy.size() / 2;
  for (i64 k = 0; k < off[np]; ++k) {
    pc_xy.push_back(xy[2 * outv[k]]);
    pc_xy.push_back(xy[2 * outv[k] + 1]);
  }
  for (i64 p = 1; p <= np; ++p) pc_off.push_back(base + off[p]);
  return OK;
}

// The method auto picks: the convolution when it has at most a few segments per input
// vertex (every convex pair has exactly n + m; spiky shapes have up to n m / 4 and far
// more crossings), else the pieces.
constexpr i64 AUTO_SEGMENTS_PER_VERTEX = 6;

// Sum of one pair into out (status in out.status): OK, RESOURCE (a limit), RANGE (auto
// or pieces needed the convex pieces of an operand and none were given), SHAPE (both
// operands are points or segments), OVERFLOW.
inline void sum_pair(const Table& T, i64 a, i64 b, int method, const Limits& L, Rings& out,
                     int* used = nullptr) {
  out.clear();
  Geo g;
  const int ka = T.kind[a], kb = T.kind[b];
  if (ka != 0 && kb != 0) {
    out.status = SHAPE;
    return;
  }
  std::vector<Polygon> A = operand(T, a), B = operand(T, b);
  if (ka != 0 || kb != 0) {
    // a point translates, a segment sweeps
    const std::vector<Polygon>& P = ka == 0 ? A : B;
    const Ring& f = (ka == 0 ? B : A)[0].ext;
    Overlay o(g);
    o.max_crossings = L.crossings;
    if (f.n() == 1) {
      std::vector<EdgeIn> in;
      operand_edges(g, P, f.x(0), f.y(0), in);
      o.run(in, ov::UNION, out);
    } else {
      std::vector<std::vector<EdgeIn>> parts;
      segment_sum(g, P, f.x(0), f.y(0), f.x(1), f.y(1), parts);
      Cascade c(g);
      c.max_crossings = L.crossings;
      c.unite(parts, out);
    }
    if (used) *used = 0;
    return;
  }
  if (method == AUTO || method == CONVOLUTION) {
    i64 nv = vertex_count(A) + vertex_count(B);
    i64 cap = method == AUTO ? std::min(L.conv_segments, AUTO_SEGMENTS_PER_VERTEX * nv + 64)
                             : L.conv_segments;
    i64 cnt = conv_count(A, B, cap);
    if (cnt <= cap) {
      std::vector<EdgeIn> in;
      in.reserve(cnt);
      convolution(g, A, B, in);
      Overlay o(g);
      o.max_crossings = L.crossings;
      o.run(in, ov::UNION, out);
      if (used) *used = CONVOLUTION;
      if (out.status != RESOURCE || method == CONVOLUTION) return;
      g = Geo();  // auto: too many crossings, try the pieces
    } else if (method == CONVOLUTION) {
      out.status = RESOURCE;
      return;
    }
  }
  // the pieces: the table's, or made here
  const double* pc_xy = T.pc_xy;
  i64 qa0 = T.op_pc_off[a], qa1 = T.op_pc_off[a + 1];
  i64 qb0 = T.op_pc_off[b], qb1 = T.op_pc_off[b + 1];
  std::vector<double> own_xy;
  std::vector<i64> own_off{0};
  if (qa1 == qa0 || qb1 == qb0) {
    int ca = operand_pieces(T, a, own_xy, own_off);
    qa0 = 0;
    qa1 = (i64)own_off.size() - 1;
    int cb = ca == OK ? operand_pieces(T, b, own_xy, own_off) : ca;
    qb0 = qa1;
    qb1 = (i64)own_off.size() - 1;
    if (cb != OK) {
      out.clear();
      out.status = cb;
      return;
    }
    pc_xy = own_xy.data();
  }
  const i64* pc_off = own_xy.empty() ? T.pc_off : own_off.data();
  if ((qa1 - qa0) * (qb1 - qb0) > L.piece_pairs) {
    out.clear();
    out.status = RESOURCE;
    return;
  }
  // piece offsets relative to the table's piece coordinates
  std::vector<i64> oa(pc_off + qa0, pc_off + qa1 + 1), ob(pc_off + qb0, pc_off + qb1 + 1);
  // --- union.hpp: the piece sums made on demand, the ones inside the union so far dropped
  // before noding, the rest united (this thread's reused buffers)
  un::with_workspace([&](un::Workspace& w) {
    w.u.max_crossings = L.crossings;
    return un::sum_pieces_union(w.u, pc_xy, oa.data(), qa1 - qa0, pc_xy, ob.data(),
                                qb1 - qb0, out);
  });
  // ---
  if (used) *used = PIECES;
}

// ------------------------------------------------------------------------------------
// erosion

// -P (a point reflection keeps every ring's orientation)
inline std::vector<Polygon> negated(std::vector<Polygon> P) {
  auto neg = [](Ring& r) {
    for (double& v : r.xy) v = -v;
  };
  for (Polygon& p : P) {
    neg(p.ext);
    for (Ring& h : p.holes) neg(h);
  }
  return P;
}

// A ⊖ B = {c : c + B ⊆ A} (A polygons, B any operand) into out: G \ (R ⊕ (−B)) with G
// the box bbox(A) ⊖ bbox(B) (exact corners) and R = F \ A for a box F around bbox(A):
// c ∈ G misses the erosion iff some c + b (b ∈ B) lies outside A, and that point lies
// in G + B ⊆ bbox(A) ⊆ F, so in R. R's rings are F, A's exteriors reversed (holes of R,
// filled when B cannot fit in them: it changes nothing) and A's holes reversed. One
// overlay: G on layer 0, the convolution (or the sweep of a segment, or the translate
// by a point) on layer 1, rule w0 >= 1 and w1 <= 0.
inline void erode_pair(const Table& T, i64 a, i64 b, const Limits& L, Rings& out) {
  out.clear();
  Geo g;
  std::vector<Polygon> A = operand(T, a), B = operand(T, b);
  const int kb = T.kind[b];
  Box ba = operand_box(A), bb = operand_box(B);
  if (width_cmp(bb.x0, bb.x1, ba.x0, ba.x1) > 0 || width_cmp(bb.y0, bb.y1, ba.y0, ba.y1) > 0)
    return;  // B is wider or taller than A: it fits nowhere
  // R = F \ A
  double span = (ba.x1 - ba.x0) + (ba.y1 - ba.y0) + 1.0;
  if (!(span - span == 0)) {
    out.status = OVERFLOW;
    return;
  }
  std::vector<Polygon> R(1);
  {
    double fx0 = ba.x0 - span, fx1 = ba.x1 + span, fy0 = ba.y0 - span, fy1 = ba.y1 + span;
    if (!(fx0 - fx0 == 0 && fx1 - fx1 == 0 && fy0 - fy0 == 0 && fy1 - fy1 == 0)) {
      out.status = OVERFLOW;
      return;
    }
    // rounding does not matter: F only has to contain bbox(A) strictly
    fx0 = std::min(fx0, std::nextafter(ba.x0, -INFINITY));
    fy0 = std::min(fy0, std::nextafter(ba.y0, -INFINITY));
    fx1 = std::max(fx1, std::nextafter(ba.x1, INFINITY));
    fy1 = std::max(fy1, std::nextafter(ba.y1, INFINITY));
    R[0].ext.xy = {fx0, fy0, fx1, fy0, fx1, fy1, fx0, fy1};
  }
  auto reversed = [](Ring r, bool hole) {
    i64 m = r.n();
    for (i64 i = 0, j = m - 1; i < j; ++i, --j) {
      std::swap(r.xy[2 * i], r.xy[2 * j]);
      std::swap(r.xy[2 * i + 1], r.xy[2 * j + 1]);
    }
    r.hole = hole;
    return r;
  };
  for (const Polygon& p : A) {
    R[0].holes.push_back(reversed(p.ext, true));
    for (const Ring& h : p.holes) {
      R.emplace_back();
      R.back().ext = reversed(h, false);
    }
  }
  std::vector<Polygon> nB = negated(B);
  // S = R ⊕ (−B) as exact boundary edges (layer 1)
  std::vector<EdgeIn> in;
  std::vector<ov::BEdge> S;
  Overlay o(g);
  o.max_crossings = L.crossings;
  if (kb == 1) {
    const Ring& f = nB[0].ext;
    operand_edges(g, R, f.x(0), f.y(0), in);
    for (EdgeIn& e : in) e.layer = 1;
  } else {
    std::vector<EdgeIn> sin;
    if (kb == 2) {
      const Ring& f = nB[0].ext;
      std::vector<std::vector<EdgeIn>> parts;
      segment_sum(g, R, f.x(0), f.y(0), f.x(1), f.y(1), parts);
      for (auto& p : parts) sin.insert(sin.end(), p.begin(), p.end());
    } else {
      if (conv_count(R, nB, L.conv_segments) > L.conv_segments) {
        out.status = RESOURCE;
        return;
      }
      convolution(g, R, nB, sin);
    }
    o.run(sin, ov::UNION, S);
    if (o.exceeded()) {
      out.status = RESOURCE;
      return;
    }
    for (const ov::BEdge& e : S) in.push_back(EdgeIn{e.line, e.from, e.to, 1, 1});
  }
  // G on layer 0
  {
    DD x0 = ov::dd_sum(ba.x0, -bb.x0), x1 = ov::dd_sum(ba.x1, -bb.x1);
    DD y0 = ov::dd_sum(ba.y0, -bb.y0), y1 = ov::dd_sum(ba.y1, -bb.y1);
    if (!(x0.hi - x0.hi == 0 && x1.hi - x1.hi == 0 && y0.hi - y0.hi == 0 && y1.hi - y1.hi == 0)) {
      out.status = OVERFLOW;
      return;
    }
    i64 first = (i64)g.pts.size();
    g.point(x0, y0);
    g.point(x1, y0);
    g.point(x1, y1);
    g.point(x0, y1);
    ov::add_ring(g, first, 4, 1, 0, in);
  }
  o.run(in, ov::DIFFERENCE, out);
}

}  // namespace ms
}  // namespace mk
