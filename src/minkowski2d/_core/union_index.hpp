// union_index.hpp -- the containment test of the convex union (step 3 of union.hpp):
// the side and coordinate predicates on the union's vertices, the cells of a grid axis,
// and BoundaryIndex (the grid over the union's boundary, its empty components
// classified inside or outside, and the proof that a convex piece lies in the union).
// Part of union.hpp (include that).
#pragma once

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include "boxes.hpp"
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
    // the grid when a test first needs it (the pieces tested before the next round may
    // all fall outside the box)
    grid_ready_ = false;
    built_ = true;
  }

 private:
  // the grid over the edges, its cells and its empty components
  void grid() {
    grid_ready_ = true;
    const i64 n = (i64)e_->size();
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
    span_.resize(n);
    for (i64 i = 0; i < n; ++i) {
      Span& sp = span_[i];
      sp.c0 = (std::int32_t)xs_.first(bx0_[i]);
      sp.c1 = (std::int32_t)xs_.last(bx1_[i]);
      sp.r0 = (std::int32_t)ys_.first(by0_[i]);
      sp.r1 = (std::int32_t)ys_.last(by1_[i]);
    }
    grid_buckets(n, nx, ny, [&](i64 i, i64& xa, i64& xb, i64& ya, i64& yb) {
      const Span& sp = span_[i];
      xa = sp.c0, xb = sp.c1, ya = sp.r0, yb = sp.r1;
    }, start_, cells_);
    // registrations in the cells [0, r) x [0, c)
    sum_.assign((ny + 1) * (nx + 1), 0);
    for (i64 r = 0; r < ny; ++r)
      for (i64 c = 0; c < nx; ++c)
        sum_[(r + 1) * (nx + 1) + c + 1] = sum_[r * (nx + 1) + c + 1] + sum_[(r + 1) * (nx + 1) + c] -
                                           sum_[r * (nx + 1) + c] + cnt(r * nx + c);
    stamp_.assign(n, 0);
    epoch_ = 0;
    components();
  }

 public:
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
    if (!grid_ready_) grid();
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
        const double inv = cy == ay ? 0.0 : 1.0 / (cy - ay);
        for (i64 r = e0; r <= e1; ++r) {
          double b0 = ys_.v[r] - tol, b1 = ys_.v[r + 1] + tol, lo_x, hi_x;
          if (cy == ay) {
            lo_x = std::min(ax, cx);
            hi_x = std::max(ax, cx);
          } else {
            double t0 = ay < b0 ? (b0 - ay) * inv : 0.0;
            double t1 = cy > b1 ? (b1 - ay) * inv : 1.0;
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
  bool built_ = false, grid_ready_ = false;
  std::vector<double> bx0_, bx1_, by0_, by1_;
  double X0_ = 0, X1_ = 0, Y0_ = 0, Y1_ = 0;
  Axis xs_, ys_;
  std::vector<i64> start_, sum_;
  std::vector<int> cells_;  // the edges of each cell (grid_buckets)
  std::vector<double> s0_, s1_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t epoch_ = 0;
  struct Span {
    std::int32_t c0, c1, r0, r1;  // an edge's cells: columns c0..c1, rows r0..r1
  };
  std::vector<Span> span_;
  std::vector<std::pair<i64, i64>> stack_;
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
    const i64 nx = xs_.n, ny = ys_.n;
    comp_.assign(nx * ny, -1);
    inside_.clear();
    std::vector<std::pair<i64, i64>>& stack = stack_;  // (row, column)
    for (i64 r = 0, s = 0; r < ny; ++r)
      for (i64 c = 0; c < nx; ++c, ++s) {
        if (cnt(s) != 0 || comp_[s] >= 0) continue;
        const i64 id = (i64)inside_.size();
        inside_.push_back(winding(xs_.v[c], ys_.v[r], c, r) >= 1 ? 1 : 0);
        comp_[s] = id;
        stack.assign(1, {r, c});
        while (!stack.empty()) {
          const auto [ur, uc] = stack.back();
          stack.pop_back();
          auto visit = [&](i64 vr, i64 vc) {
            const i64 v = vr * nx + vc;
            if (comp_[v] < 0 && cnt(v) == 0) {
              comp_[v] = id;
              stack.emplace_back(vr, vc);
            }
          };
          if (uc > 0) visit(ur, uc - 1);
          if (uc + 1 < nx) visit(ur, uc + 1);
          if (ur > 0) visit(ur - 1, uc);
          if (ur + 1 < ny) visit(ur + 1, uc);
        }
      }
  }
};

}  // namespace un
}  // namespace mk
