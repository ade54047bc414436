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
//  3. The containment test (BoundaryIndex). A uniform grid over dU's edges (each
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
//  4. Sources make the pieces on demand (SumSource merges two convex pieces), so the
//     1.6 M sums of the stars never exist at once; only kept pieces enter the geometry.
//     One thread's geometry and buffers are reused between calls (Workspace).
//  5. Work limits. max_crossings bounds the crossings noded by all overlay runs together
//     (each is a new vertex: the memory), max_pairs the candidate pairs classified (the
//     time): beyond either the result is Status RESOURCE and no rings (the caller raises
//     ResourceLimitError).
#pragma once

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>
#include <vector>

#include "convex.hpp"
#include "exact.hpp"
#include "exactnum.hpp"
#include "overlay.hpp"

namespace mk {
namespace un {

using ov::BEdge;
using ov::DD;
using ov::EdgeIn;
using ov::Geo;
using ov::P;
using ov::Rings;

// sign of (q - p) x (v - p) for a vertex v of g (a point or a crossing of two lines)
inline int side_pq(const Geo& g, const P& p, const P& q, i64 v) {
  const ov::Vert& V = g.verts[v];
  if (V.p >= 0) return ov::orient(p, q, g.pts[V.p]);
  FE px = ov::fe(p.x), py = ov::fe(p.y);
  int s = fe_sign(ov::cross(ov::fe(q.x) - px, ov::fe(q.y) - py, V.x - px, V.y - py));
  if (s != UNSURE) return s;
  Dy X, Y, W;
  g.exact(v, X, Y, W);
  Dy Px = ov::dy(p.x), Py = ov::dy(p.y);
  return ov::cross(ov::dy(q.x) - Px, ov::dy(q.y) - Py, X - Px * W, Y - Py * W).sign();
}

// sign of (y(v) - y) for a vertex v and a double y
// sign of (coordinate axis of v) - c for a vertex v and an exact c = hi + lo (DD)
inline int vc_cmp(const Geo& g, i64 v, DD c, int axis) {
  const ov::Vert& V = g.verts[v];
  if (V.p >= 0) return ov::dd_cmp(axis == 0 ? g.pts[V.p].x : g.pts[V.p].y, c);
  int s = fe_sign((axis == 0 ? V.x : V.y) - ov::fe(c));
  if (s != UNSURE) return s;
  Dy X, Y, W;
  g.exact(v, X, Y, W);
  return ((axis == 0 ? X : Y) - ov::dy(c) * W).sign();
}
inline int vy_cmp(const Geo& g, i64 v, double y) { return vc_cmp(g, v, ov::dd(y), 1); }

// ------------------------------------------------------------------------------------
// the boundary of the union so far, indexed for containment tests

// cells along one axis: n cells between n + 1 nondecreasing double bounds
struct Axis {
  std::vector<double> v;
  i64 n = 1;
  double a = 0, inv = 0;
  void set(double lo, double hi, i64 cells) {
    n = cells;
    a = lo;
    v.resize(n + 1);
    const double d = hi - lo;
    for (i64 i = 0; i <= n; ++i) v[i] = std::min(hi, lo + d * ((double)i / (double)n));
    v[0] = lo;
    v[n] = hi;
    inv = d > 0 ? (double)n / d : 0.0;
  }
  i64 guess(double x) const {
    double t = (x - a) * inv;
    if (!(t > 0)) return 0;
    if (t >= (double)(n - 1)) return n - 1;
    return (i64)t;
  }
  // the first cell whose closed span reaches x (v[c + 1] >= x), clamped
  i64 first(double x) const {
    i64 c = guess(x);
    while (c > 0 && v[c] >= x) --c;
    while (c < n - 1 && v[c + 1] < x) ++c;
    return c;
  }
  // the last cell whose closed span starts at or before x (v[c] <= x), clamped
  i64 last(double x) const {
    i64 c = guess(x);
    while (c < n - 1 && v[c + 1] <= x) ++c;
    while (c > 0 && v[c] > x) --c;
    return c;
  }
  // a cell whose closed span holds x exactly, or -1
  i64 exact(DD x) const {
    i64 c = last(x.hi);
    if (ov::dd_less(x, ov::dd(v[c])) || ov::dd_less(ov::dd(v[c + 1]), x)) return -1;
    return c;
  }
};

class BoundaryIndex {
 public:
  explicit BoundaryIndex(const Geo& g) : g_(g) {}

  i64 n_tests = 0, n_edge_tests = 0, n_no_cell = 0, n_box = 0, n_meet = 0, n_out = 0;

  bool built() const { return built_; }
  void reset() { built_ = false; }

  void build(const std::vector<BEdge>& b) {
    built_ = false;
    e_ = &b;
    const i64 n = (i64)b.size();
    if (n == 0) return;
    bx0_.resize(n);
    bx1_.resize(n);
    by0_.resize(n);
    by1_.resize(n);
    X0_ = Y0_ = INFINITY;
    X1_ = Y1_ = -INFINITY;
    for (i64 i = 0; i < n; ++i) {
      ov::widened_box(g_.verts[b[i].from], g_.verts[b[i].to], bx0_[i], bx1_[i], by0_[i],
                      by1_[i]);
      X0_ = std::min(X0_, bx0_[i]);
      X1_ = std::max(X1_, bx1_[i]);
      Y0_ = std::min(Y0_, by0_[i]);
      Y1_ = std::max(Y1_, by1_[i]);
    }
    if (!(X1_ - X0_ < INFINITY) || !(Y1_ - Y0_ < INFINITY)) return;  // unbounded: no index
    // about two cells per edge, square-ish
    double W = X1_ - X0_, H = Y1_ - Y0_;
    double target = std::max(1.0, 2.0 * (double)n);
    double cell = std::sqrt(W * H / target);
    if (!(cell > 0)) cell = std::max(W, H) / target;
    i64 nx = cell > 0 ? (i64)std::min(2048.0, std::max(1.0, std::ceil(W / cell))) : 1;
    i64 ny = cell > 0 ? (i64)std::min(2048.0, std::max(1.0, std::ceil(H / cell))) : 1;
    xs_.set(X0_, X1_, nx);
    ys_.set(Y0_, Y1_, ny);
    // cells of each edge (CSR, row-major)
    const i64 nc = nx * ny;
    start_.assign(nc + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      if (pass == 1) {
        for (i64 c = 0; c < nc; ++c) start_[c + 1] += start_[c];
        cells_.resize(start_[nc]);
        fill_.assign(start_.begin(), start_.end() - 1);
      }
      for (i64 i = 0; i < n; ++i) {
        i64 c0 = xs_.first(bx0_[i]), c1 = xs_.last(bx1_[i]);
        i64 r0 = ys_.first(by0_[i]), r1 = ys_.last(by1_[i]);
        for (i64 r = r0; r <= r1; ++r)
          for (i64 c = c0; c <= c1; ++c) {
            if (pass == 0)
              ++start_[r * nx + c + 1];
            else
              cells_[fill_[r * nx + c]++] = i;
          }
      }
    }
    // registrations in the cells [0, r) x [0, c)
    sum_.assign((ny + 1) * (nx + 1), 0);
    for (i64 r = 0; r < ny; ++r)
      for (i64 c = 0; c < nx; ++c)
        sum_[(r + 1) * (nx + 1) + c + 1] = sum_[r * (nx + 1) + c + 1] + sum_[(r + 1) * (nx + 1) + c] -
                                           sum_[r * (nx + 1) + c] + cnt(r * nx + c);
    stamp_.assign(n, 0);
    epoch_ = 0;
    components();
    built_ = true;
  }

  // Is the convex piece p[0..m) (strictly convex, counter-clockwise, m >= 3) inside the
  // union (closed)? true only when proved; false means "keep it".
  bool covers(const P* p, i64 m) {
    if (!built_) return false;
    ++n_tests;
    double px0 = INFINITY, px1 = -INFINITY, py0 = INFINITY, py1 = -INFINITY, M = 0;
    for (i64 k = 0; k < m; ++k) {
      px0 = std::min(px0, p[k].x.hi);
      px1 = std::max(px1, p[k].x.hi);
      py0 = std::min(py0, p[k].y.hi);
      py1 = std::max(py1, p[k].y.hi);
    }
    // a vertex on or beyond the index's box: not inside (conservative)
    if (!(px0 > X0_ && px1 < X1_ && py0 > Y0_ && py1 < Y1_)) {
      ++n_box;
      return false;
    }
    M = std::max(std::max(std::fabs(px0), std::fabs(px1)), std::max(std::fabs(py0), std::fabs(py1)));
    // the spans below are in double: widened by far more than their rounding errors
    // (a few ulps of M) and the DD parts (half an ulp), see span_slack
    const double tol = span_slack(M);
    const i64 nx = xs_.n;
    i64 c0 = xs_.first(px0 - tol), c1 = xs_.last(px1 + tol);
    i64 r0 = ys_.first(py0 - tol), r1 = ys_.last(py1 + tol);
    if (box_count(c0, c1, r0, r1) > 0) {
      // x-spans of P in the rows r0..r1, edge by edge
      const i64 nr = r1 - r0 + 1;
      s0_.assign(nr, INFINITY);
      s1_.assign(nr, -INFINITY);
      for (i64 k = 0; k < m; ++k) {
        const P &a = p[k], &c = p[k + 1 < m ? k + 1 : 0];
        double ax = a.x.hi, ay = a.y.hi, cx = c.x.hi, cy = c.y.hi;
        if (ay > cy) {
          std::swap(ax, cx);
          std::swap(ay, cy);
        }
        i64 e0 = std::max(r0, ys_.first(ay - tol)), e1 = std::min(r1, ys_.last(cy + tol));
        for (i64 r = e0; r <= e1; ++r) {
          double b0 = ys_.v[r] - tol, b1 = ys_.v[r + 1] + tol, lo_x, hi_x;
          if (cy == ay) {
            lo_x = std::min(ax, cx);
            hi_x = std::max(ax, cx);
          } else {
            double t0 = ay < b0 ? (b0 - ay) / (cy - ay) : 0.0;
            double t1 = cy > b1 ? (b1 - ay) / (cy - ay) : 1.0;
            double x0 = ax + (cx - ax) * t0, x1 = ax + (cx - ax) * t1;
            lo_x = std::min(x0, x1);
            hi_x = std::max(x0, x1);
          }
          s0_[r - r0] = std::min(s0_[r - r0], lo_x);
          s1_[r - r0] = std::max(s1_[r - r0], hi_x);
        }
      }
      if (++epoch_ == 0) {
        std::fill(stamp_.begin(), stamp_.end(), 0);
        epoch_ = 1;
      }
      const std::vector<BEdge>& E = *e_;
      for (i64 r = r0; r <= r1; ++r) {
        if (s0_[r - r0] > s1_[r - r0]) continue;
        i64 a0 = std::max(c0, xs_.first(s0_[r - r0] - tol));
        i64 a1 = std::min(c1, xs_.last(s1_[r - r0] + tol));
        if (a0 > a1 || start_[r * nx + a1 + 1] == start_[r * nx + a0]) continue;  // no edges
        for (i64 t = start_[r * nx + a0]; t < start_[r * nx + a1 + 1]; ++t) {
          i64 i = cells_[t];
          if (stamp_[i] == epoch_) continue;
          stamp_[i] = epoch_;
          if (bx1_[i] < px0 - tol || bx0_[i] > px1 + tol || by1_[i] < py0 - tol ||
              by0_[i] > py1 + tol)
            continue;
          ++n_edge_tests;
          if (meets_interior(E[i], p, m)) {
            ++n_meet;
            return false;
          }
        }
      }
    }
    // no boundary edge meets int(P): inside or outside as a whole; a vertex in an empty
    // cell tells which
    for (i64 k = 0; k < m; ++k) {
      i64 c = xs_.exact(p[k].x), r = ys_.exact(p[k].y);
      if (c < 0 || r < 0) continue;
      i64 comp = comp_[r * nx + c];
      if (comp < 0) continue;
      n_out += inside_[comp] == 0;
      return inside_[comp] != 0;
    }
    // else a vertex not on the boundary: its winding number (a ray along its row)
    for (i64 k = 0; k < m; ++k) {
      i64 c = xs_.exact(p[k].x), r = ys_.exact(p[k].y);
      if (c < 0 || r < 0) continue;
      int w = winding_at(p[k], c, r);
      if (w == ON_BOUNDARY) continue;
      n_out += w < 1;
      return w >= 1;
    }
    ++n_no_cell;
    return false;
  }

 private:
  const Geo& g_;
  const std::vector<BEdge>* e_ = nullptr;
  bool built_ = false;
  std::vector<double> bx0_, bx1_, by0_, by1_;
  double X0_ = 0, X1_ = 0, Y0_ = 0, Y1_ = 0;
  Axis xs_, ys_;
  std::vector<i64> start_, cells_, fill_, sum_;
  std::vector<double> s0_, s1_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t epoch_ = 0;
  std::vector<i64> comp_;     // component of an empty cell, -1 for a cell with edges
  std::vector<char> inside_;  // per component

  i64 cnt(i64 cell) const { return start_[cell + 1] - start_[cell]; }
  i64 box_count(i64 c0, i64 c1, i64 r0, i64 r1) const {
    const i64 w = xs_.n + 1;
    return sum_[(r1 + 1) * w + c1 + 1] - sum_[r0 * w + c1 + 1] - sum_[(r1 + 1) * w + c0] +
           sum_[r0 * w + c0];
  }

  // does the closed boundary edge e meet the open interior of P?
  bool meets_interior(const BEdge& e, const P* p, i64 m) const {
    // P's edge lines: both ends of e on the closed outer side of one of them -> no
    for (i64 k = 0; k < m; ++k) {
      const P &a = p[k], &c = p[k + 1 < m ? k + 1 : 0];
      if (side_pq(g_, a, c, e.from) <= 0 && side_pq(g_, a, c, e.to) <= 0) return false;
    }
    // e's line: P on one closed side -> no
    const ov::Line& L = g_.lines[e.line];
    const P &la = g_.pts[L.a], &lb = g_.pts[L.b];
    bool pos = false, neg = false;
    for (i64 k = 0; k < m; ++k) {
      int s = ov::orient(la, lb, p[k]);
      pos |= s > 0;
      neg |= s < 0;
      if (pos && neg) return true;
    }
    return false;
  }

  // winding number of the boundary around the double point (x, y) (not on it): a ray to
  // +x along row r of cells, from cell c
  int winding(double x, double y, i64 c, i64 r) {
    if (++epoch_ == 0) {
      std::fill(stamp_.begin(), stamp_.end(), 0);
      epoch_ = 1;
    }
    const std::vector<BEdge>& E = *e_;
    const P q{ov::dd(x), ov::dd(y)};
    int w = 0;
    for (i64 cc = c; cc < xs_.n; ++cc) {
      i64 cell = r * xs_.n + cc;
      for (i64 t = start_[cell]; t < start_[cell + 1]; ++t) {
        i64 i = cells_[t];
        if (stamp_[i] == epoch_) continue;
        stamp_[i] = epoch_;
        if (bx1_[i] < x || by1_[i] < y || by0_[i] > y) continue;
        const BEdge& e = E[i];
        int sf = vy_cmp(g_, e.from, y), st = vy_cmp(g_, e.to, y);
        bool upward = sf <= 0 && st > 0, downward = st <= 0 && sf > 0;
        if (!upward && !downward) continue;
        // side of q against the edge (from -> to)
        const ov::Line& L = g_.lines[e.line];
        int dir = g_.along(e.line, e.to, e.from);  // +1: the edge runs along its line
        int s = ov::orient(g_.pts[L.a], g_.pts[L.b], q) * dir;
        if (upward && s > 0) ++w;
        if (downward && s < 0) --w;
      }
    }
    return w;
  }

  // The winding number of the boundary around the exact point q (a DD point in the
  // closed cell (c, r)): a ray to +x along row r, half-open in y; ON_BOUNDARY when q
  // lies on a boundary edge (or may: an edge whose line holds q and whose box holds it).
  static constexpr int ON_BOUNDARY = -1000000;
  int winding_at(const P& q, i64 c, i64 r) {
    if (++epoch_ == 0) {
      std::fill(stamp_.begin(), stamp_.end(), 0);
      epoch_ = 1;
    }
    const std::vector<BEdge>& E = *e_;
    const double qx = q.x.hi, qy = q.y.hi;
    int w = 0;
    for (i64 cc = c; cc < xs_.n; ++cc) {
      i64 cell = r * xs_.n + cc;
      for (i64 t = start_[cell]; t < start_[cell + 1]; ++t) {
        i64 i = cells_[t];
        if (stamp_[i] == epoch_) continue;
        stamp_[i] = epoch_;
        // boxes are widened: these skips are safe for the exact q (|lo| <= ulp / 2)
        if (bx1_[i] < next_down(qx) || by1_[i] < next_down(qy) ||
            by0_[i] > next_up(qy))
          continue;
        const BEdge& e = E[i];
        const ov::Line& L = g_.lines[e.line];
        int o = ov::orient(g_.pts[L.a], g_.pts[L.b], q);
        if (o == 0) {
          // q on the edge's line: on the edge when between its ends (exactly)
          int ax = g_.pts[L.a].x.hi != g_.pts[L.b].x.hi ? 0 : 1;
          DD qc = ax == 0 ? q.x : q.y;
          int s0 = vc_cmp(g_, e.from, qc, ax), s1 = vc_cmp(g_, e.to, qc, ax);
          if (s0 * s1 <= 0) return ON_BOUNDARY;
          continue;
        }
        int sf = vc_cmp(g_, e.from, q.y, 1), st = vc_cmp(g_, e.to, q.y, 1);
        bool upward = sf <= 0 && st > 0, downward = st <= 0 && sf > 0;
        if (!upward && !downward) continue;
        int dir = g_.along(e.line, e.to, e.from);
        int side = o * dir;
        if (upward && side > 0) ++w;
        if (downward && side < 0) --w;
      }
    }
    return w;
  }

  void components() {
    const i64 nx = xs_.n, nc = nx * ys_.n;
    comp_.assign(nc, -1);
    inside_.clear();
    std::vector<i64> stack;
    for (i64 s = 0; s < nc; ++s) {
      if (cnt(s) != 0 || comp_[s] >= 0) continue;
      const i64 id = (i64)inside_.size();
      i64 r = s / nx, c = s % nx;
      inside_.push_back(winding(xs_.v[c], ys_.v[r], c, r) >= 1 ? 1 : 0);
      comp_[s] = id;
      stack.assign(1, s);
      while (!stack.empty()) {
        i64 u = stack.back();
        stack.pop_back();
        i64 ur = u / nx, uc = u % nx;
        auto visit = [&](i64 v) {
          if (comp_[v] < 0 && cnt(v) == 0) {
            comp_[v] = id;
            stack.push_back(v);
          }
        };
        if (uc > 0) visit(u - 1);
        if (uc + 1 < nx) visit(u + 1);
        if (ur > 0) visit(u - nx);
        if (ur + 1 < ys_.n) visit(u + nx);
      }
    }
  }
};

// ------------------------------------------------------------------------------------
// the union

struct UnionStats {
  i64 pieces = 0, culled = 0, kept = 0, rounds = 0, runs = 0, pairs = 0, crossings = 0;
};

// A source of convex pieces: size(), and get(k, v) filling v with piece k's vertices
// (DD points, strictly convex, counter-clockwise); fewer than 3 vertices: no area (the
// piece is skipped).
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
    std::vector<double> area(n), reach(n);
    std::vector<P> v;
    double cx0, cx1, cy0, cy1;
    src.bounds(cx0, cx1, cy0, cy1);
    const double cx = cx0 / 2 + cx1 / 2, cy = cy0 / 2 + cy1 / 2;
    for (i64 k = 0; k < n; ++k) {
      if (src.get(k, v) != OK) return finish(out, OVERFLOW);
      double a = 0, r = 0;
      const i64 m = (i64)v.size();
      for (i64 i = 0; i < m; ++i) {
        const P &p = v[i], &q = v[i + 1 < m ? i + 1 : 0];
        a += (p.x.hi - v[0].x.hi) * (q.y.hi - v[0].y.hi) -
             (p.y.hi - v[0].y.hi) * (q.x.hi - v[0].x.hi);
        double dx = p.x.hi - cx, dy = p.y.hi - cy;
        r = std::max(r, dx * dx + dy * dy);
      }
      // -1: no area, skipped (an overflowing or NaN heuristic counts as large)
      area[k] = m < 3 ? -1.0 : (a >= 0 && a < INFINITY ? a : (a < 0 ? 0.0 : DBL_MAX));
      reach[k] = r == r ? r : DBL_MAX;
    }
    std::vector<std::pair<double, i64>> key;
    key.reserve(n);
    std::vector<i64> order;
    order.reserve(n);
    {
      for (i64 k = 0; k < n; ++k)
        if (area[k] >= 0) key.emplace_back(-area[k], k);
      const i64 K = std::min<i64>((i64)key.size(), first_k);
      std::partial_sort(key.begin(), key.begin() + K, key.end());
      std::vector<char> first(n, 0);
      for (i64 t = 0; t < K; ++t) {
        order.push_back(key[t].second);
        first[key[t].second] = 1;
      }
      key.clear();
      for (i64 k = 0; k < n; ++k)
        if (area[k] >= 0 && !first[k]) key.emplace_back(-reach[k], k);
      std::sort(key.begin(), key.end());
      for (auto& kk : key) order.push_back(kk.second);
    }
    std::vector<double>().swap(reach);
    std::vector<double>().swap(area);
    std::vector<std::pair<double, i64>>().swap(key);
    // 2. rounds
    ubnd_.clear();
    uverts_.clear();
    pending_.clear();
    i64 pend_edges = 0;
    for (i64 k : order) {
      src.get(k, v);
      const bool cvx = src.convex(k);
      if (cull && cvx && idx_.covers(v.data(), (i64)v.size())) {
        ++st.culled;
        continue;
      }
      ++st.kept;
      pending_.emplace_back();
      i64 first = (i64)g_.pts.size();
      for (const P& p : v) g_.point(p.x, p.y);
      ov::add_ring(g_, first, (i64)v.size(), 1, 0, pending_.back());
      if (!cvx)  // its edges may cross each other: no group
        for (EdgeIn& e : pending_.back()) e.group = -2;
      pend_edges += (i64)pending_.back().size();
      if (pend_edges >= std::max(min_batch, (i64)(round_factor * (double)ubnd_.size()))) {
        if (!round()) return finish_limit(out);
        pend_edges = 0;
      }
    }
    // 3. the last round, as rings
    if (!absorb(out)) return finish_limit(out);
    return out.status;
  }

 private:
  Geo& g_;
  ov::Overlay o_;
  BoundaryIndex idx_;
  std::vector<BEdge> ubnd_;   // the boundary of the union so far
  std::vector<i64> uverts_;   // its vertices in sweep order
  std::vector<std::vector<EdgeIn>> pending_;

  int finish(Rings& out, int code) {
    out.clear();
    out.status = code;
    return code;
  }
  int finish_limit(Rings& out) { return finish(out, RESOURCE); }

  static void add_boundary(const std::vector<BEdge>& b, int group, std::vector<EdgeIn>& in) {
    for (const BEdge& e : b) in.push_back(EdgeIn{e.line, e.from, e.to, 1, 0, group});
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
    std::vector<BEdge> nb;
    if (!absorb(nb)) return false;
    ubnd_.swap(nb);
    o_.boundary_vertices(uverts_);
    if (cull) idx_.build(ubnd_);
    return true;
  }

  // U united with the pending pieces, as boundary edges or rings: few pieces in one run
  // with dU, more by a cascade first
  template <class Out>
  bool absorb(Out& out) {
    std::vector<EdgeIn> in;
    bool ok;
    if ((i64)pending_.size() <= leaf) {
      add_boundary(ubnd_, 0, in);
      std::vector<i64> ord(pending_.size());
      std::iota(ord.begin(), ord.end(), 0);
      leaf_edges(pending_, ord, 0, ord.size(), in, ubnd_.empty() ? 0 : 1);
      ok = ubnd_.empty() ? run(in, out) : run(in, out, {&uverts_});
    } else if (ubnd_.empty()) {
      ok = cascade(pending_, out);
    } else {
      std::vector<BEdge> vb;
      std::vector<i64> vv;
      ok = cascade(pending_, vb, vv);
      if (ok) {
        add_boundary(ubnd_, 0, in);
        add_boundary(vb, 1, in);
        ok = run(in, out, {&uverts_, &vv});
      }
    }
    pending_.clear();
    return ok;
  }

  // the union of parts as boundary edges (and their vertices in sweep order), or as
  // rings: a balanced tree over the parts in the order of a Hilbert curve
  bool cascade(std::vector<std::vector<EdgeIn>>& parts, std::vector<BEdge>& out,
               std::vector<i64>& outv) {
    out.clear();
    outv.clear();
    if (parts.empty()) return true;
    std::vector<i64> ord;
    spatial_order(parts, ord);
    return rec(parts, ord, 0, ord.size(), out, outv);
  }
  template <class Out>
  bool cascade(std::vector<std::vector<EdgeIn>>& parts, Out& out) {
    out.clear();
    if (parts.empty()) return true;
    std::vector<i64> ord;
    spatial_order(parts, ord);
    std::vector<EdgeIn> in;
    if ((i64)parts.size() <= leaf) {
      leaf_edges(parts, ord, 0, ord.size(), in);
      return run(in, out);
    }
    std::size_t n = ord.size(), groups = (n + leaf - 1) / leaf, mid = (groups / 2) * leaf;
    std::vector<BEdge> a, b;
    std::vector<i64> av, bv;
    if (!rec(parts, ord, 0, mid, a, av) || !rec(parts, ord, mid, n, b, bv)) return false;
    add_boundary(a, 0, in);
    add_boundary(b, 1, in);
    return run(in, out, {&av, &bv});
  }
  // the edges of parts ord[lo:hi], each part its own group (from `first`) unless it may
  // cross itself
  void leaf_edges(const std::vector<std::vector<EdgeIn>>& parts, const std::vector<i64>& ord,
                  std::size_t lo, std::size_t hi, std::vector<EdgeIn>& in, int first = 0) const {
    for (std::size_t k = lo; k < hi; ++k)
      for (EdgeIn e : parts[ord[k]]) {
        e.group = e.group == -2 ? -1 : first + (int)(k - lo);
        in.push_back(e);
      }
  }
  void spatial_order(const std::vector<std::vector<EdgeIn>>& parts, std::vector<i64>& ord) {
    // the parts along a Hilbert curve through their box centres (neighbours share leaves)
    std::vector<double> mx(parts.size()), my(parts.size());
    double X0 = INFINITY, X1 = -INFINITY, Y0 = INFINITY, Y1 = -INFINITY;
    for (std::size_t k = 0; k < parts.size(); ++k) {
      double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
      for (const EdgeIn& e : parts[k]) {
        const ov::Vert& V = g_.verts[e.v0];
        x0 = std::min(x0, V.x.v);
        x1 = std::max(x1, V.x.v);
        y0 = std::min(y0, V.y.v);
        y1 = std::max(y1, V.y.v);
      }
      mx[k] = x0 / 2 + x1 / 2;
      my[k] = y0 / 2 + y1 / 2;
      X0 = std::min(X0, mx[k]);
      X1 = std::max(X1, mx[k]);
      Y0 = std::min(Y0, my[k]);
      Y1 = std::max(Y1, my[k]);
    }
    std::vector<std::pair<u64, i64>> cx(parts.size());
    const double sx = X1 > X0 ? 65535.0 / (X1 - X0) : 0.0, sy = Y1 > Y0 ? 65535.0 / (Y1 - Y0) : 0.0;
    for (std::size_t k = 0; k < parts.size(); ++k) {
      double fx = (mx[k] - X0) * sx, fy = (my[k] - Y0) * sy;
      u64 ix = fx > 0 ? (u64)std::min(fx, 65535.0) : 0, iy = fy > 0 ? (u64)std::min(fy, 65535.0) : 0;
      cx[k] = {hilbert(ix, iy), (i64)k};
    }
    std::sort(cx.begin(), cx.end());
    ord.resize(parts.size());
    for (std::size_t k = 0; k < parts.size(); ++k) ord[k] = cx[k].second;
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
  bool rec(const std::vector<std::vector<EdgeIn>>& parts, const std::vector<i64>& ord,
           std::size_t lo, std::size_t hi, std::vector<BEdge>& out, std::vector<i64>& outv) {
    std::vector<EdgeIn> in;
    if ((i64)(hi - lo) <= leaf) {
      leaf_edges(parts, ord, lo, hi, in);
      if (!run(in, out)) return false;
    } else {
      std::size_t n = hi - lo, groups = (n + leaf - 1) / leaf, mid = lo + (groups / 2) * leaf;
      std::vector<BEdge> a, b;
      std::vector<i64> av, bv;
      if (!rec(parts, ord, lo, mid, a, av) || !rec(parts, ord, mid, hi, b, bv)) return false;
      add_boundary(a, 0, in);
      add_boundary(b, 1, in);
      if (!run(in, out, {&av, &bv})) return false;
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
  void clear() {
    g.pts.clear();
    g.lines.clear();
    g.verts.clear();
    u.cull = true;
    u.max_crossings = u.max_pairs = NO_LIMIT;
  }
};

// f(Workspace&) with this thread's workspace (a fresh one when called re-entrantly)
template <class F>
inline auto with_workspace(F&& f) {
  thread_local std::unique_ptr<Workspace> w;
  thread_local bool busy = false;
  if (busy) {
    auto tmp = std::make_unique<Workspace>();
    return f(*tmp);
  }
  struct Guard {
    bool& b;
    std::unique_ptr<Workspace>& w;
    ~Guard() {
      b = false;
      if (w && w->g.verts.capacity() > Workspace::KEEP) w.reset();
    }
  } guard{busy, w};
  busy = true;
  if (!w) w = std::make_unique<Workspace>();
  w->clear();
  return f(*w);
}

// ------------------------------------------------------------------------------------
// sources: size(), and get(k, v) -> OK (v: piece k's vertices, strictly convex, counter-
// clockwise, or empty when it has no area) or OVERFLOW (a coordinate is not finite)

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
  int get(i64 k, std::vector<P>& v) const {
    v.assign(pts->begin() + (*off)[k], pts->begin() + (*off)[k + 1]);
    if (v.size() < 3) v.clear();
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

}  // namespace un
}  // namespace mk
