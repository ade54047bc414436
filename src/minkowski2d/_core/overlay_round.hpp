// overlay_round.hpp -- the overlay's output contract after rounding (the rounded rings
// are valid, else the rounded polygon is overlaid again), the cascaded union, and the
// helpers that feed an overlay. Part of overlay.hpp (include that).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "overlay_trace.hpp"

namespace mk {
namespace ov {

// ------------------------------------------------------------------------------------
// the output contract after rounding

// Drops repeated vertices (neighbours rounded to the same double pair) from every ring of
// `r`, and rings left with fewer than three. A polygon whose exterior vanished loses its
// holes too. A vertex that rounding puts exactly on the line through its neighbours is
// kept: the output is the rounded exact vertices, no more and no fewer (an exactly
// collinear *exact* vertex never reaches it).
inline void clean_rounded(Rings& r) {
  // nothing to drop (no neighbours rounded together): the rings stand as they are (they
  // start at their smallest vertex already, assemble)
  bool repeats = false;
  for (std::size_t k = 0; k + 1 < r.ring_off.size() && !repeats; ++k) {
    const i64 r0 = r.ring_off[k], r1 = r.ring_off[k + 1];
    for (i64 i = r0; i < r1; ++i) {
      const i64 j = i + 1 < r1 ? i + 1 : r0;
      if (r1 - r0 > 1 && r.xy[2 * i] == r.xy[2 * j] && r.xy[2 * i + 1] == r.xy[2 * j + 1]) {
        repeats = true;
        break;
      }
    }
  }
  if (!repeats) return;
  Rings out;
  out.status = r.status;
  out.exact_vertices = r.exact_vertices;
  // the supporting lines follow their vertices (a dropped repeat's zero-length edge goes)
  const bool lines = r.want_lines && r.line.size() * 2 == r.xy.size();
  out.want_lines = r.want_lines;
  std::vector<double> x, y;
  std::vector<i64> ln;
  for (std::size_t p = 0; p + 1 < r.poly_off.size(); ++p) {
    bool ext_kept = false;
    for (i64 k = r.poly_off[p]; k < r.poly_off[p + 1]; ++k) {
      x.clear();
      y.clear();
      ln.clear();
      const i64 r0 = r.ring_off[k], r1 = r.ring_off[k + 1], m = r1 - r0;
      for (i64 i = r0; i < r1; ++i) {
        i64 j = i + 1 < r1 ? i + 1 : r0;
        if (m > 1 && r.xy[2 * i] == r.xy[2 * j] && r.xy[2 * i + 1] == r.xy[2 * j + 1]) continue;
        x.push_back(r.xy[2 * i]);
        y.push_back(r.xy[2 * i + 1]);
        if (lines) ln.push_back(r.line[i]);
      }
      if (x.size() < 3) continue;
      // start again at the smallest vertex (x, then y)
      std::size_t s0 = 0;
      for (std::size_t i = 1; i < x.size(); ++i)
        if (x[i] < x[s0] || (x[i] == x[s0] && y[i] < y[s0])) s0 = i;
      std::rotate(x.begin(), x.begin() + s0, x.end());
      std::rotate(y.begin(), y.begin() + s0, y.end());
      if (lines) std::rotate(ln.begin(), ln.begin() + s0, ln.end());
      bool is_ext = k == r.poly_off[p];
      if (is_ext)
        ext_kept = true;
      else if (!ext_kept)
        continue;
      for (std::size_t i = 0; i < x.size(); ++i) {
        out.xy.push_back(x[i]);
        out.xy.push_back(y[i]);
        if (lines) out.line.push_back(ln[i]);
      }
      out.ring_off.push_back((i64)out.xy.size() / 2);
    }
    if (ext_kept) out.poly_off.push_back((i64)out.ring_off.size() - 1);
  }
  r = std::move(out);
}

// True when the rounded rings are a valid polygon set (exact signs on the doubles): no
// two edges cross or overlap; a ring meets itself only where consecutive edges share
// their vertex; two rings may touch at points -- a vertex of one on the other, or a
// common vertex -- without crossing there. That is OGC validity up to the connectedness
// of interiors, which rounding cannot break without one of these events.
inline bool valid_rounded(const Rings& r) {
  const i64 nr = (i64)r.ring_off.size() - 1;
  const i64 n = (i64)r.xy.size() / 2;
  std::vector<i64> ring_of;
  ring_of.reserve(n);
  for (i64 k = 0; k < nr; ++k)
    for (i64 i = r.ring_off[k]; i < r.ring_off[k + 1]; ++i) ring_of.push_back(k);
  auto nxt = [&](i64 i) {
    return i + 1 < r.ring_off[ring_of[i] + 1] ? i + 1 : r.ring_off[ring_of[i]];
  };
  auto prv = [&](i64 i) { return i > r.ring_off[ring_of[i]] ? i - 1 : r.ring_off[ring_of[i] + 1] - 1; };
  auto X = [&](i64 i) { return r.xy[2 * i]; };
  auto Y = [&](i64 i) { return r.xy[2 * i + 1]; };
  auto same = [&](i64 a, i64 b) { return X(a) == X(b) && Y(a) == Y(b); };
  auto orient = [&](i64 a, i64 b, i64 c) {
    return mk::orient(X(a), Y(a), X(b), Y(b), X(c), Y(c));
  };
  // directions v -> a in angle order
  auto angle_less = [&](i64 v, i64 a, i64 b) {
    auto up = [&](i64 w) {
      return Y(w) > Y(v) || (Y(w) == Y(v) && X(w) > X(v));
    };
    bool ua = up(a), ub = up(b);
    if (ua != ub) return ua;
    return orient(v, a, b) > 0;
  };
  // is direction v -> q strictly inside the counter-clockwise arc from v -> a to v -> b?
  auto in_arc = [&](i64 v, i64 a, i64 b, i64 q) {
    if (angle_less(v, a, b)) return angle_less(v, a, q) && angle_less(v, q, b);
    return angle_less(v, a, q) || angle_less(v, q, b);
  };
  // rings i and j cross at their common vertex when j's two edges are separated by i's
  auto cross_at = [&](i64 i, i64 j) {
    bool in1 = in_arc(i, prv(i), nxt(i), prv(j)), in2 = in_arc(i, prv(i), nxt(i), nxt(j));
    return in1 != in2;
  };
  std::vector<double> x0(n), x1(n), y0(n), y1(n);
  for (i64 i = 0; i < n; ++i) {
    i64 j = nxt(i);
    x0[i] = std::min(X(i), X(j));
    x1[i] = std::max(X(i), X(j));
    y0[i] = std::min(Y(i), Y(j));
    y1[i] = std::max(Y(i), Y(j));
  }
  bool ok = true;
  // the check of one candidate pair; false (and ok = false) at the first violation
  // (consecutive edges of a ring that do not turn back: one orientation)
  auto check = [&](i64 e, i64 f) -> bool {
    if (!ok) return false;
    const i64 a = e, b = nxt(e), c = f, d = nxt(f);
    const bool one_ring = ring_of[e] == ring_of[f];
    if ((b == c && orient(a, b, d) != 0) || (d == a && orient(c, d, b) != 0)) return true;
    int o1 = orient(a, b, c), o2 = orient(a, b, d);
    if (o1 * o2 > 0) return true;
    int o3 = orient(c, d, a), o4 = orient(c, d, b);
    if (o3 * o4 > 0) return true;
    if (o1 == 0 && o2 == 0) {
      // collinear: they may only share an end point, as consecutive edges of one ring
      // or edges of two rings
      auto key = [&](i64 i) { return X(a) != X(b) ? X(i) : Y(i); };
      double lo1 = std::min(key(a), key(b)), hi1 = std::max(key(a), key(b));
      double lo2 = std::min(key(c), key(d)), hi2 = std::max(key(c), key(d));
      if (hi1 < lo2 || hi2 < lo1) return true;
      if (hi1 == lo2 || hi2 == lo1) {
        bool consecutive = one_ring && (b == c || d == a);
        if (consecutive || !one_ring) return true;
      }
      ok = false;
      return false;
    }
    if (o1 && o2 && o3 && o4) return ok = false;  // a proper crossing
    // one common point
    if (one_ring && (b == c || d == a)) return true;  // consecutive edges at their vertex
    if (one_ring) {
      ok = false;  // a ring touching itself
      return false;
    }
    // two rings touch: a common vertex, or a vertex of one inside an edge of the other
    i64 v = -1, w = -1;  // a vertex of each at the point, if any
    for (i64 p : {a, b})
      for (i64 q : {c, d})
        if (same(p, q)) v = p, w = q;
    if (v >= 0) {
      if (cross_at(v, w)) ok = false;
      return ok;
    }
    // a vertex u of one ring inside edge (s, t) of the other: its neighbours must not lie
    // strictly on both sides of that edge
    i64 u, s0, t0;
    if (o1 == 0) u = c, s0 = a, t0 = b;
    else if (o2 == 0) u = d, s0 = a, t0 = b;
    else if (o3 == 0) u = a, s0 = c, t0 = d;
    else u = b, s0 = c, t0 = d;
    if (orient(s0, t0, prv(u)) * orient(s0, t0, nxt(u)) < 0) ok = false;
    return ok;
  };
  // Candidate pairs: a uniform grid over the exact segments (tolerance 0: they are plain
  // doubles) from 512 edges on -- a box sweep keeps a whole column of a grid-like result
  // active -- and the sweep below that or when the grid declines (its memory budget).
  bool done = false;
  if (n >= 512) {
    std::vector<double> ax(n), ay(n), bx(n), by(n), tol(n, 0.0);
    std::vector<int> grp(n, -1);
    for (i64 i = 0; i < n; ++i) {
      const i64 j = nxt(i);
      ax[i] = X(i);
      ay[i] = Y(i);
      bx[i] = X(j);
      by[i] = Y(j);
    }
    GridScratch scratch;
    done = segment_pairs(n, ax.data(), ay.data(), bx.data(), by.data(), tol.data(), x0.data(),
                         x1.data(), y0.data(), y1.data(), grp.data(), scratch, check);
  }
  if (!done)
    box_pairs(n, x0.data(), x1.data(), y0.data(), y1.data(), [&](i64 e, i64 f) { check(e, f); });
  return ok;
}

// The remedy when rounding alone broke validity (exact features closer than an ulp):
// the rounded rings, now plain doubles, are overlaid again (union of their winding
// numbers: exteriors +1 inside, holes -1), which nodes the new crossings exactly and
// rounds them in turn; repeated until valid (Halperin and Packer's iterated snap
// rounding plays this role on an integer grid). The result is the exact regularized set
// of the rounded polygon: every vertex within an ulp or two of the exact result.
inline void rerun_rounded(Rings& r);

// ------------------------------------------------------------------------------------
// the cascaded union

// Union (layer 0, w >= 1) of parts given as edge lists: groups of up to `leaf` parts are
// overlaid together, then the results pairwise up a balanced tree, so that edges inside
// the union disappear early and the crossings of heavily overlapping parts are never all
// computed at once (GEOS's cascaded union, exact).
class Cascade {
 public:
  explicit Cascade(Geo& g, i64 leaf = 4) : g_(g), o_(g), leaf_(leaf < 1 ? 1 : leaf) {}
  i64 n_crossings = 0, n_runs = 0;
  i64 max_crossings = NO_LIMIT;  // over all runs; then RESOURCE

  void unite(const std::vector<std::vector<EdgeIn>>& parts, Rings& out) {
    out.clear();
    if (parts.empty()) return;
    o_.max_crossings = max_crossings - n_crossings;
    std::vector<EdgeIn> in;
    if ((i64)parts.size() <= leaf_) {
      for (auto& p : parts) in.insert(in.end(), p.begin(), p.end());
    } else {
      std::size_t mid = split_point(0, parts.size());
      std::vector<BEdge> a, b;
      rec(parts, 0, mid, a);
      rec(parts, mid, parts.size(), b);
      if (o_.exceeded()) {
        out.status = RESOURCE;
        return;
      }
      add_boundary(a, 0, in);
      add_boundary(b, 0, in);
    }
    o_.run(in, UNION, out);
    count();
  }

 private:
  Geo& g_;
  Overlay o_;
  i64 leaf_;

  void count() {
    n_crossings += o_.n_crossings;
    ++n_runs;
    o_.max_crossings = max_crossings - n_crossings;
  }
  std::size_t split_point(std::size_t lo, std::size_t hi) const {
    // leaves of size leaf_: split at a multiple of leaf_ near the middle
    std::size_t n = hi - lo, groups = (n + leaf_ - 1) / leaf_;
    return lo + (groups / 2) * leaf_;
  }
  void rec(const std::vector<std::vector<EdgeIn>>& parts, std::size_t lo, std::size_t hi,
           std::vector<BEdge>& out) {
    if (o_.exceeded()) return;
    std::vector<EdgeIn> in;
    if ((i64)(hi - lo) <= leaf_) {
      for (std::size_t k = lo; k < hi; ++k) in.insert(in.end(), parts[k].begin(), parts[k].end());
    } else {
      std::size_t mid = split_point(lo, hi);
      std::vector<BEdge> a, b;
      rec(parts, lo, mid, a);
      rec(parts, mid, hi, b);
      add_boundary(a, 0, in);
      add_boundary(b, 0, in);
    }
    o_.run(in, UNION, out);
    count();
  }

  static void add_boundary(const std::vector<BEdge>& b, int layer, std::vector<EdgeIn>& in) {
    for (const BEdge& e : b) in.push_back(EdgeIn{e.line, e.from, e.to, 1, layer});
  }
};

inline void finish_rounded_impl(Rings& r, int depth);

// ------------------------------------------------------------------------------------
// helpers to feed an overlay

// Adds a closed ring of points (ids first .. first + n - 1) as edges.
inline void add_ring(Geo& g, i64 first, i64 n, int w, int layer, std::vector<EdgeIn>& out) {
  if (n < 2) return;
  i64 v0 = (i64)g.verts.size();
  for (i64 i = 0; i < n; ++i) g.vert_point(first + i);
  for (i64 i = 0; i < n; ++i) {
    const i64 j = i + 1 < n ? i + 1 : 0, a = first + i, b = first + j;
    if (p_eq(g.pts[a], g.pts[b])) continue;
    EdgeIn& e = out.emplace_back();
    e.line = g.line(a, b);
    e.v0 = v0 + i;
    e.v1 = v0 + j;
    e.w = w;
    e.layer = layer;
  }
}

inline void rerun_rounded(Rings& r) {
  Geo g;
  std::vector<EdgeIn> in;
  for (std::size_t k = 0; k + 1 < r.ring_off.size(); ++k) {
    i64 first = (i64)g.pts.size(), m = r.ring_off[k + 1] - r.ring_off[k];
    for (i64 i = r.ring_off[k]; i < r.ring_off[k + 1]; ++i)
      g.point(dd(r.xy[2 * i]), dd(r.xy[2 * i + 1]));
    add_ring(g, first, m, 1, 0, in);
  }
  Overlay o(g);
  Rings out;
  o.run_raw(in, UNION, out);
  r = std::move(out);
}

// Cleans the rounded rings and checks them; re-nodes them (a few times at most) when
// rounding made them invalid.
inline void finish_rounded_impl(Rings& r, int depth) {
  // exact vertices: no two neighbours rounded together, every ring already starts at its
  // smallest vertex (assemble), and the rings are the exact result
  if (r.exact_vertices) return;
  clean_rounded(r);
  if (valid_rounded(r)) return;
  if (depth >= 4) {
    r.status = INTERNAL;
    return;
  }
  rerun_rounded(r);
  if (r.status == OK) finish_rounded_impl(r, depth + 1);
}

inline void Overlay::finish_rounded(Rings& out) { finish_rounded_impl(out, 0); }

}  // namespace ov
}  // namespace mk
