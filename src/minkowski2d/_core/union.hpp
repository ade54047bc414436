// union.hpp -- the exact union of many convex polygons (the piece sums of a decomposed
// Minkowski sum), with the pieces that cannot change the union dropped before noding.
//
// Why: the convex piece sums of a non-convex sum overlap heavily (of the 289 sums of one
// ESICUP no-fit polygon, 222 are found inside the union of the others and about 40 reach
// its boundary; of the 1.59 M sums of two 2048-vertex stars, 1.47 M); noding them costs
// far more than the answer (GEOS's CascadedPolygonUnion and a flat sweep pay for every
// crossing of overlapping pieces). Here:
//
//  1. Order (heuristics in double; they decide nothing): the first_k largest pieces by
//     area, then the others by their reach from the centre of all, farthest first.
//  2. Rounds. Pieces that survive the test below wait; when their edges reach
//     max(min_batch, round_factor * |dU|) they are united (a cascade over the Hilbert
//     order of their box centres, leaves of `leaf` pieces, each piece its own edge group;
//     few pieces go into one run with dU) with the union U so far, whose boundary dU is
//     kept as exact edges (lines and crossings of lines) with its vertices in sweep order
//     (merged, not re-sorted, by the next run). The last round gives the rings.
//  3. The containment test (BoundaryIndex, union_index.hpp). A uniform grid over dU's edges (each
//     registered in every cell its box meets; boxes widened by the vertices' certified
//     error bounds, so a cell without edges has no boundary point in it, closed). Empty
//     cells form 4-connected components, each wholly inside or wholly outside U: one
//     exact ray cast per component (from a cell corner, a plain double point, along its
//     row of cells) classifies it. A convex piece P (strictly convex, counter-clockwise,
//     exact DD vertices) lies in U (closed) when
//       (a) no boundary edge meets the interior of P -- by separating axes, exactly: an
//           edge misses int(P) iff both its end vertices lie on the closed outer side of
//           one edge line of P (side of a point: degree 2; of a line crossing: degree 4,
//           FE filter, Dy fallback), or all of P's vertices lie on one closed side of the
//           edge's line (degree 2); only edges registered in the cells that P's rows can
//           reach are tested (row spans in double, widened by an error bound; the spans
//           only choose candidates);
//       (b) some vertex of P lies (exactly: DD against the cell's double bounds) in a
//           closed empty cell of a component classified inside, or else some vertex of P
//           not on dU has winding number >= 1 (an exact ray along its row of cells): then
//           a neighbourhood of that vertex lies in int(U) and meets int(P); int(P) is
//           connected and misses dU by (a), so int(P), hence P, lies in U.
//     Anything else keeps the piece: keeping is always correct, dropping is proved.
//     The grid is built when a test first needs it.
//  4. Sources make the pieces on demand (SumSource merges two convex pieces), so the
//     1.7 M sums of the stars never exist at once; only kept pieces enter the geometry.
//     One thread's geometry and buffers are reused between calls (Workspace). One convex
//     piece of plain doubles is its own union (the overlay's arrays, without a run).
//  5. Work limits. max_crossings bounds the crossings noded by all overlay runs together
//     (each is a new vertex: the memory), max_pairs the candidate pairs classified (the
//     time): beyond either the result is Status RESOURCE and no rings (the caller raises
//     ResourceLimitError).
#pragma once

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <deque>
#include <memory>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

#include "buffer.hpp"
#include "convex.hpp"
#include "exact.hpp"
#include "exactnum.hpp"
#include "overlay.hpp"
#include "union_index.hpp"

namespace mk {
namespace un {

// (ov::BEdge, DD, EdgeIn, Geo, P, Rings are named in mk::un by union_index.hpp)

// ------------------------------------------------------------------------------------
// the union

struct UnionStats {
  i64 pieces = 0, culled = 0, kept = 0, rounds = 0, runs = 0, pairs = 0, crossings = 0;
};

// A source of convex pieces: size(), and get(k, v, p, m) pointing p at piece k's m
// vertices (DD points, strictly convex, counter-clockwise; v is scratch it may fill);
// fewer than 3 vertices: no area (the piece is skipped).
class ConvexUnion {
 public:
  explicit ConvexUnion(Geo& g) : g_(g), o_(g), idx_(g) {}
  // work limits over all runs (see 4. above)
  i64 max_crossings = NO_LIMIT, max_pairs = NO_LIMIT;

  UnionStats st;
  BoundaryIndex& index() { return idx_; }
  ov::Overlay& overlay() { return o_; }
  bool cull = true;
  i64 leaf = 8;         // pieces per leaf of the cascades
  i64 min_batch = 32;   // edges waiting before a round (at least)
  i64 first_k = 4;     // pieces taken by area before the others (by reach)
  double round_factor = 1.0;  // a round when the waiting edges reach this times dU

  template <class Src>
  int unite(Src& src, Rings& out) {
    out.clear();
    const i64 n = src.size();
    st = UnionStats();
    st.pieces = n;
    idx_.reset();
    // 1. order (heuristics in double; they decide nothing): the first_k largest pieces,
    // then the others by their reach from the centre of all, farthest first (ties: input
    // order)
    std::vector<double>& area = area_;
    std::vector<double>& reach = reach_;
    area.resize(n);
    reach.resize(n);
    double cx0, cx1, cy0, cy1;
    src.bounds(cx0, cx1, cy0, cy1);
    const double cx = cx0 / 2 + cx1 / 2, cy = cy0 / 2 + cy1 / 2;
    const P* pv;
    i64 m;
    for (i64 k = 0; k < n; ++k) {
      if (src.get(k, v_, pv, m) != OK) return finish(out, OVERFLOW);
      double a = 0, r = 0;
      for (i64 i = 0; i < m; ++i) {
        const P &p = pv[i], &q = pv[i + 1 < m ? i + 1 : 0];
        a += (p.x.hi - pv[0].x.hi) * (q.y.hi - pv[0].y.hi) -
             (p.y.hi - pv[0].y.hi) * (q.x.hi - pv[0].x.hi);
        double dx = p.x.hi - cx, dy = p.y.hi - cy;
        r = std::max(r, dx * dx + dy * dy);
      }
      // -1: no area, skipped (an overflowing or NaN heuristic counts as large)
      area[k] = m < 3 ? -1.0 : (a >= 0 && a < INFINITY ? a : (a < 0 ? 0.0 : DBL_MAX));
      reach[k] = r == r ? r : DBL_MAX;
    }
    std::vector<std::pair<double, i64>>& key = key_;
    std::vector<i64>& order = order_;
    key.clear();
    order.clear();
    {
      for (i64 k = 0; k < n; ++k)
        if (area[k] >= 0) key.emplace_back(-area[k], k);
      const i64 K = std::min<i64>((i64)key.size(), first_k);
      std::partial_sort(key.begin(), key.begin() + K, key.end());
      for (i64 t = 0; t < K; ++t) {
        order.push_back(key[t].second);
        area[key[t].second] = -1;  // taken
      }
      key.clear();
      for (i64 k = 0; k < n; ++k)
        if (area[k] >= 0) key.emplace_back(-reach[k], k);
      std::sort(key.begin(), key.end());
      for (auto& kk : key) order.push_back(kk.second);
    }
    // one convex piece of plain doubles: the union is the piece, as the overlay gives it
    // (counter-clockwise from its smallest vertex, x then y; tests/test_union_core.py)
    if (order.size() == 1 && src.convex(order[0])) {
      src.get(order[0], v_, pv, m);
      if (one_piece(pv, m, out)) {
        st.kept = 1;
        return out.status;
      }
    }
    // 2. rounds
    ubnd_.clear();
    uverts_.clear();
    pend_.clear();
    i64 pend_edges = 0;
    for (std::size_t q = 0; q < order.size(); ++q) {
      const i64 k = order[q];
      src.get(k, v_, pv, m);
      const bool cvx = src.convex(k);
      if (cull && cvx && idx_.covers(pv, m)) {
        ++st.culled;
        continue;
      }
      ++st.kept;
      const i64 first = (i64)g_.pts.size(), e0 = (i64)pend_.e.size();
      for (i64 i = 0; i < m; ++i) g_.point(pv[i].x, pv[i].y);
      ov::add_ring(g_, first, m, 1, 0, pend_.e);
      if (!cvx)  // its edges may cross each other: no group
        for (std::size_t i = e0; i < pend_.e.size(); ++i) pend_.e[i].group = -2;
      pend_.close();
      pend_edges += (i64)pend_.e.size() - e0;
      // (after the last piece, the last round below gives the rings: no index)
      if (q + 1 < order.size() &&
          pend_edges >= std::max(min_batch, (i64)(round_factor * (double)ubnd_.size()))) {
        if (!round()) return finish_limit(out);
        pend_edges = 0;
      }
    }
    // 3. the last round, as rings
    if (!absorb(out)) return finish_limit(out);
    return out.status;
  }

 private:
  // pieces waiting for a round, as one list of edges: part k is e[off[k] .. off[k + 1])
  struct Parts {
    std::vector<EdgeIn> e;
    std::vector<i64> off{0};
    std::size_t size() const { return off.size() - 1; }
    void clear() {
      e.clear();
      off.assign(1, 0);
    }
    void close() { off.push_back((i64)e.size()); }
  };
  // the buffers of one level of a cascade (reused between calls)
  struct Level {
    std::vector<EdgeIn> in;
    std::vector<BEdge> a, b;
    std::vector<i64> av, bv;
  };

  Geo& g_;
  ov::Overlay o_;
  BoundaryIndex idx_;
  std::vector<BEdge> ubnd_, nb_;  // the boundary of the union so far, the next one
  std::vector<i64> uverts_;       // its vertices in sweep order
  Parts pend_;
  std::vector<P> v_;
  std::vector<double> area_, reach_, mx_, my_;
  std::vector<std::pair<double, i64>> key_;
  std::vector<std::pair<u64, i64>> hk_;
  std::vector<i64> order_, ord_;
  std::deque<Level> levels_;  // (references stay valid as it grows)

  static bool one_piece(const P* p, i64 m, Rings& out) {
    i64 s = 0;
    for (i64 i = 0; i < m; ++i) {
      if (!ov::plain(p[i])) return false;
      if (p[i].x.hi < p[s].x.hi || (p[i].x.hi == p[s].x.hi && p[i].y.hi < p[s].y.hi)) s = i;
    }
    out.clear();
    for (i64 i = 0; i < m; ++i) {
      const P& q = p[s + i < m ? s + i : s + i - m];
      out.xy.push_back(q.x.hi);
      out.xy.push_back(q.y.hi);
    }
    out.ring_off.push_back(m);
    out.poly_off.push_back(1);
    out.exact_vertices = true;
    return true;
  }

  Level& level(std::size_t d) {
    if (levels_.size() <= d) levels_.resize(d + 1);
    return levels_[d];
  }

  int finish(Rings& out, int code) {
    out.clear();
    out.status = code;
    return code;
  }
  int finish_limit(Rings& out) { return finish(out, RESOURCE); }

  static void add_boundary(const std::vector<BEdge>& b, int group, std::vector<EdgeIn>& in) {
    for (const BEdge& e : b) {
      EdgeIn& x = in.emplace_back();  // written in place (see Geo::point)
      x.line = e.line;
      x.v0 = e.from;
      x.v1 = e.to;
      x.w = 1;
      x.layer = 0;
      x.group = group;
    }
  }

  template <class Out>
  bool run(const std::vector<EdgeIn>& in, Out& out,
           const std::vector<const std::vector<i64>*>& sorted = {}) {
    o_.max_crossings = std::max<i64>(0, max_crossings - st.crossings);
    o_.max_pairs = std::max<i64>(0, max_pairs - st.pairs);
    o_.run(in, ov::UNION, out, sorted);
    ++st.runs;
    st.pairs += o_.n_pairs;
    st.crossings += o_.n_crossings;
    return !o_.exceeded();
  }

  // pending pieces united with U: the new U (and its index)
  bool round() {
    ++st.rounds;
    if (!absorb(nb_)) return false;
    ubnd_.swap(nb_);
    o_.boundary_vertices(uverts_);
    if (cull) idx_.build(ubnd_);
    return true;
  }

  // U united with the pending pieces, as boundary edges or rings: few pieces in one run
  // with dU, more by a cascade first
  template <class Out>
  bool absorb(Out& out) {
    if constexpr (std::is_same_v<Out, Rings>) {
      if (pend_.size() == 0 && !ubnd_.empty()) {
        // nothing new since the last round: the rings of its run, which gave dU
        o_.rings(out);
        return true;
      }
    }
    Level& L = level(0);
    std::vector<EdgeIn>& in = L.in;
    in.clear();
    bool ok;
    if ((i64)pend_.size() <= leaf) {
      add_boundary(ubnd_, 0, in);
      ord_.resize(pend_.size());
      std::iota(ord_.begin(), ord_.end(), 0);
      leaf_edges(pend_, ord_, 0, ord_.size(), in, ubnd_.empty() ? 0 : 1);
      ok = ubnd_.empty() ? run(in, out) : run(in, out, {&uverts_});
    } else if (ubnd_.empty()) {
      ok = cascade(pend_, out);
    } else {
      ok = cascade(pend_, L.a, L.av);
      if (ok) {
        in.clear();
        add_boundary(ubnd_, 0, in);
        add_boundary(L.a, 1, in);
        ok = run(in, out, {&uverts_, &L.av});
      }
    }
    pend_.clear();
    return ok;
  }

  // the union of parts as boundary edges (and their vertices in sweep order), or as
  // rings: a balanced tree over the parts in the order of a Hilbert curve
  bool cascade(const Parts& parts, std::vector<BEdge>& out, std::vector<i64>& outv) {
    out.clear();
    outv.clear();
    if (parts.size() == 0) return true;
    spatial_order(parts, ord_);
    return rec(parts, ord_, 0, ord_.size(), out, outv, 1);
  }
  template <class Out>
  bool cascade(const Parts& parts, Out& out) {
    out.clear();
    if (parts.size() == 0) return true;
    spatial_order(parts, ord_);
    Level& L = level(0);
    std::vector<EdgeIn>& in = L.in;
    in.clear();
    if ((i64)parts.size() <= leaf) {
      leaf_edges(parts, ord_, 0, ord_.size(), in);
      return run(in, out);
    }
    std::size_t n = ord_.size(), groups = (n + leaf - 1) / leaf, mid = (groups / 2) * leaf;
    if (!rec(parts, ord_, 0, mid, L.a, L.av, 1) || !rec(parts, ord_, mid, n, L.b, L.bv, 1))
      return false;
    add_boundary(L.a, 0, in);
    add_boundary(L.b, 1, in);
    return run(in, out, {&L.av, &L.bv});
  }
  // the edges of parts ord[lo:hi], each part its own group (from `first`) unless it may
  // cross itself
  void leaf_edges(const Parts& parts, const std::vector<i64>& ord, std::size_t lo,
                  std::size_t hi, std::vector<EdgeIn>& in, int first = 0) const {
    for (std::size_t k = lo; k < hi; ++k)
      for (i64 t = parts.off[ord[k]]; t < parts.off[ord[k] + 1]; ++t) {
        EdgeIn& e = in.emplace_back();
        e = parts.e[t];
        e.group = e.group == -2 ? -1 : first + (int)(k - lo);
      }
  }
  void spatial_order(const Parts& parts, std::vector<i64>& ord) {
    // the parts along a Hilbert curve through their box centres (neighbours share leaves)
    const std::size_t np = parts.size();
    mx_.resize(np);
    my_.resize(np);
    double X0 = INFINITY, X1 = -INFINITY, Y0 = INFINITY, Y1 = -INFINITY;
    for (std::size_t k = 0; k < np; ++k) {
      double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
      for (i64 t = parts.off[k]; t < parts.off[k + 1]; ++t) {
        const ov::Vert& V = g_.verts[parts.e[t].v0];
        x0 = std::min(x0, V.x.v);
        x1 = std::max(x1, V.x.v);
        y0 = std::min(y0, V.y.v);
        y1 = std::max(y1, V.y.v);
      }
      mx_[k] = x0 / 2 + x1 / 2;
      my_[k] = y0 / 2 + y1 / 2;
      X0 = std::min(X0, mx_[k]);
      X1 = std::max(X1, mx_[k]);
      Y0 = std::min(Y0, my_[k]);
      Y1 = std::max(Y1, my_[k]);
    }
    std::vector<std::pair<u64, i64>>& cx = hk_;
    cx.resize(np);
    const double sx = X1 > X0 ? 65535.0 / (X1 - X0) : 0.0, sy = Y1 > Y0 ? 65535.0 / (Y1 - Y0) : 0.0;
    for (std::size_t k = 0; k < np; ++k) {
      double fx = (mx_[k] - X0) * sx, fy = (my_[k] - Y0) * sy;
      u64 ix = fx > 0 ? (u64)std::min(fx, 65535.0) : 0, iy = fy > 0 ? (u64)std::min(fy, 65535.0) : 0;
      cx[k] = {hilbert(ix, iy), (i64)k};
    }
    std::sort(cx.begin(), cx.end());
    ord.resize(np);
    for (std::size_t k = 0; k < np; ++k) ord[k] = cx[k].second;
  }
  // index of (x, y) (16 bits each) along the Hilbert curve
  static u64 hilbert(u64 x, u64 y) {
    const u64 n = 1u << 16;
    u64 d = 0;
    for (u64 s = n / 2; s > 0; s /= 2) {
      u64 rx = (x & s) > 0, ry = (y & s) > 0;
      d += s * s * ((3 * rx) ^ ry);
      if (ry == 0) {
        if (rx == 1) {
          x = n - 1 - x;
          y = n - 1 - y;
        }
        std::swap(x, y);
      }
    }
    return d;
  }
  // parts ord[lo:hi] united (level d of the cascade: its buffers)
  bool rec(const Parts& parts, const std::vector<i64>& ord, std::size_t lo, std::size_t hi,
           std::vector<BEdge>& out, std::vector<i64>& outv, std::size_t d) {
    std::vector<EdgeIn>& in = level(d).in;
    in.clear();
    if ((i64)(hi - lo) <= leaf) {
      leaf_edges(parts, ord, lo, hi, in);
      if (!run(in, out)) return false;
    } else {
      std::size_t n = hi - lo, groups = (n + leaf - 1) / leaf, mid = lo + (groups / 2) * leaf;
      // (levels_ may grow below: take the buffers by index after the calls)
      if (!rec(parts, ord, lo, mid, level(d).a, level(d).av, d + 1) ||
          !rec(parts, ord, mid, hi, level(d).b, level(d).bv, d + 1))
        return false;
      Level& L = level(d);
      L.in.clear();
      add_boundary(L.a, 0, L.in);
      add_boundary(L.b, 1, L.in);
      if (!run(L.in, out, {&L.av, &L.bv})) return false;
    }
    o_.boundary_vertices(outv);
    return true;
  }
};

// ------------------------------------------------------------------------------------
// one thread's buffers, kept between calls

// The geometry and the union (with its overlay's buffers) of one thread, reused by the
// next call: a small union then allocates almost nothing (allocation was a tenth of the
// work of the unions of bench_union.py). Dropped after a call whose geometry grew beyond
// KEEP vertices, so a large call does not pin its memory.
struct Workspace {
  static constexpr std::size_t KEEP = std::size_t(1) << 18;
  Geo g;
  ConvexUnion u{g};
  // union_rings' normalized rings
  std::vector<i64> keep, idx, po;
  std::vector<std::int8_t> turn;
  std::vector<P> pts;
  std::vector<char> convex;
  void clear() {
    g.pts.clear();
    g.lines.clear();
    g.verts.clear();
    u.cull = true;
    u.max_crossings = u.max_pairs = NO_LIMIT;
  }
};

// f(Workspace&) with this thread's workspace, cleared (buffer.hpp's
// with_thread_workspace)
template <class F>
inline auto with_workspace(F&& f) {
  return with_thread_workspace<Workspace>(
      [](const Workspace& w) { return w.g.verts.capacity() > Workspace::KEEP; },
      [&](Workspace& w) {
        w.clear();
        return f(w);
      });
}

// ------------------------------------------------------------------------------------
// sources: size(), and get(k, v, p, m) -> OK (p: piece k's m vertices, strictly convex,
// counter-clockwise, m = 0 when it has no area; v: scratch the source may fill and point
// p into) or OVERFLOW (a coordinate is not finite)

// Drops the vertices where a convex ring goes straight on (or doubles back: a ring of no
// area); clears v when fewer than 3 remain. Exact.
inline void strictly_convex(std::vector<P>& v) {
  const std::size_t m = v.size();
  if (m < 3) {
    v.clear();
    return;
  }
  std::vector<P> w;
  w.reserve(m);
  for (std::size_t i = 0; i < m; ++i) {
    const P &a = v[(i + m - 1) % m], &b = v[i], &c = v[(i + 1) % m];
    if (ov::orient(a, b, c) > 0) w.push_back(b);
  }
  if (w.size() < 3) w.clear();
  v.swap(w);
}

// Polygons given as DD points and offsets, each strictly convex and counter-clockwise,
// or (flag 0 in `convex`) any ring, counter-clockwise at its lowest vertex: united with
// the rest (winding number >= 1), never tested for containment.
struct PointSource {
  const std::vector<P>* pts;
  const std::vector<i64>* off;
  const std::vector<char>* convex_flags = nullptr;
  i64 size() const { return (i64)off->size() - 1; }
  bool convex(i64 k) const { return !convex_flags || (*convex_flags)[k]; }
  int get(i64 k, std::vector<P>&, const P*& p, i64& m) const {
    p = pts->data() + (*off)[k];
    m = (*off)[k + 1] - (*off)[k];
    if (m < 3) m = 0;
    return OK;
  }
  // a box around all pieces (approximate: for the order only)
  void bounds(double& x0, double& x1, double& y0, double& y1) const {
    x0 = y0 = INFINITY;
    x1 = y1 = -INFINITY;
    for (const P& p : *pts) {
      x0 = std::min(x0, p.x.hi);
      x1 = std::max(x1, p.x.hi);
      y0 = std::min(y0, p.y.hi);
      y1 = std::max(y1, p.y.hi);
    }
  }
};

// The sums of two sets of normalized convex pieces (all pairs), merged on demand; the
// vertex a + b is kept exact (TwoSum).
struct SumSource {
  const double *pa, *pb;
  const std::vector<Norm>*NA, *NB;
  i64 size() const { return (i64)NA->size() * (i64)NB->size(); }
  bool convex(i64) const { return true; }
  int get(i64 k, std::vector<P>& v, const P*& p, i64& m) const {
    int code = get(k, v);
    p = v.data();
    m = (i64)v.size();
    return code;
  }
  int get(i64 k, std::vector<P>& v) const {
    const i64 nb = (i64)NB->size();
    const Norm &A = (*NA)[k / nb], &B = (*NB)[k % nb];
    v.clear();
    bool bad = false;
    merge_ids(pa, A, pb, B, [&](i64 i, i64 j) {
      P p{ov::dd_sum(pa[2 * i], pb[2 * j]), ov::dd_sum(pa[2 * i + 1], pb[2 * j + 1])};
      if (!(p.x.hi - p.x.hi == 0 && p.y.hi - p.y.hi == 0)) bad = true;
      v.push_back(p);
      return true;
    });
    if (bad) return OVERFLOW;
    // the sum of two proper convex pieces is strictly convex; a point or a segment
    // piece may give collinear vertices or no area
    if (A.k < 3 || B.k < 3)
      strictly_convex(v);
    else if (v.size() < 3)
      v.clear();
    return OK;
  }
  // a box around all sums: the sum of the boxes around the pieces (approximate)
  void bounds(double& x0, double& x1, double& y0, double& y1) const {
    double b[2][4];
    for (int s = 0; s < 2; ++s) {
      const double* p = s == 0 ? pa : pb;
      double* q = b[s];
      q[0] = q[2] = INFINITY;
      q[1] = q[3] = -INFINITY;
      for (const Norm& N : s == 0 ? *NA : *NB)
        for (i64 t = 0; t < N.k; ++t) {
          i64 i = N.at(t);
          q[0] = std::min(q[0], p[2 * i]);
          q[1] = std::max(q[1], p[2 * i]);
          q[2] = std::min(q[2], p[2 * i + 1]);
          q[3] = std::max(q[3], p[2 * i + 1]);
        }
    }
    x0 = b[0][0] + b[1][0];
    x1 = b[0][1] + b[1][1];
    y0 = b[0][2] + b[1][2];
    y1 = b[0][3] + b[1][3];
  }
};

// The decomposition method: all sums of the convex pieces of A (pa, offsets oa, na
// pieces) and of B, united by u (whose geometry is g). Returns OK, a piece's normalize
// code (*bad: which piece, B's after A's), OVERFLOW or RESOURCE; the rings in out.
inline int sum_pieces_union(ConvexUnion& u, const double* pa, const i64* oa, i64 na,
                            const double* pb, const i64* ob, i64 nb, Rings& out,
                            i64* bad = nullptr) {
  out.clear();
  PiecePair pp;
  if (int code = normalize_pieces(pa, oa, na, pb, ob, nb, pp, bad)) {
    out.status = code;
    return code;
  }
  SumSource src{pa, pb, &pp.A, &pp.B};
  return u.unite(src, out);
}

// The same with this thread's workspace (see with_workspace).
inline int sum_pieces_union(const double* pa, const i64* oa, i64 na, const double* pb,
                            const i64* ob, i64 nb, Rings& out, UnionStats& st,
                            i64 max_crossings = NO_LIMIT, i64 max_pairs = NO_LIMIT,
                            bool cull = true, i64* bad = nullptr) {
  return with_workspace([&](Workspace& w) {
    w.u.cull = cull;
    w.u.max_crossings = max_crossings;
    w.u.max_pairs = max_pairs;
    int code = sum_pieces_union(w.u, pa, oa, na, pb, ob, nb, out, bad);
    st = w.u.st;
    return code;
  });
}

// A ring that is not convex, counter-clockwise at its lowest vertex (exact turn), with
// repeated points dropped; empty when it has no such vertex (no area).
inline std::vector<ov::P> general_ring(const double* xy, i64 lo, i64 hi) {
  std::vector<std::pair<double, double>> r;
  for (i64 i = lo; i < hi; ++i) {
    std::pair<double, double> p{xy[2 * i], xy[2 * i + 1]};
    if (r.empty() || r.back() != p) r.push_back(p);
  }
  while (r.size() > 1 && r.front() == r.back()) r.pop_back();
  std::vector<ov::P> out;
  while (r.size() >= 3) {
    const std::size_t n = r.size();
    std::size_t b = 0;
    for (std::size_t i = 1; i < n; ++i)
      if (r[i] < r[b]) b = i;
    const auto &p = r[(b + n - 1) % n], &c = r[b], &q = r[(b + 1) % n];
    int o = cross_sign(p.first, p.second, c.first, c.second, c.first, c.second, q.first,
                       q.second);
    if (o == 0) {  // the lowest vertex is a spike or straight on: drop it
      r.erase(r.begin() + (std::ptrdiff_t)b);
      continue;
    }
    if (o < 0) std::reverse(r.begin(), r.end());
    for (auto& v : r) out.push_back(ov::P{ov::dd(v.first), ov::dd(v.second)});
    break;
  }
  return out;
}

// The exact union (winding number >= 1) of rings meant to be convex (union_convex's
// binding): each normalized exactly (repeated and collinear vertices dropped; a point or a
// segment has no area and is skipped) and culled when inside the union so far; a ring that
// is not convex (a rounded convex sum can turn both ways by an ulp) is still united,
// counter-clockwise by its turn at the lowest vertex (general_ring), never culled. A
// non-finite coordinate or one out of range gives that status and (bad_poly, bad_vertex).
inline void union_rings(const double* xy, const i64* off, i64 np, bool cull, i64 max_crossings,
                        i64 max_pairs, ov::Rings& out, UnionStats& st, i64& bad_poly,
                        i64& bad_vertex) {
  with_workspace([&](Workspace& w) {
    i64 big = 1;
    for (i64 k = 0; k < np; ++k) big = std::max(big, off[k + 1] - off[k]);
    w.keep.resize(big);
    w.idx.resize(big);
    w.turn.resize(big);
    std::vector<ov::P>& pts = w.pts;
    std::vector<i64>& po = w.po;
    pts.clear();
    po.assign(1, 0);
    w.convex.clear();
    pts.reserve((std::size_t)off[np]);
    for (i64 k = 0; k < np && out.status == OK; ++k) {
      Norm N = normalize(xy, off[k], off[k + 1], w.keep.data(), w.turn.data(), w.idx.data());
      if (N.code == NONFINITE || N.code == RANGE) {
        out.status = N.code;
        bad_poly = k;
        bad_vertex = N.vertex;
        break;
      }
      if (N.code == OK) {
        if (N.k < 3) continue;  // a point or a segment: no area
        for (i64 t = 0; t < N.k; ++t) {
          i64 i = N.at(t);
          ov::P& q = pts.emplace_back();
          q.x = ov::dd(xy[2 * i]);
          q.y = ov::dd(xy[2 * i + 1]);
        }
        w.convex.push_back(1);
      } else {
        std::vector<ov::P> r = general_ring(xy, off[k], off[k + 1]);
        if (r.empty()) continue;
        pts.insert(pts.end(), r.begin(), r.end());
        w.convex.push_back(0);
      }
      po.push_back((i64)pts.size());
    }
    if (out.status == OK) {
      PointSource src{&pts, &po, &w.convex};
      w.u.cull = cull;
      w.u.max_crossings = max_crossings;
      w.u.max_pairs = max_pairs;
      w.u.unite(src, out);
      st = w.u.st;
    }
    return 0;
  });
}

}  // namespace un
}  // namespace mk

