// planning.hpp -- exact translational motion planning on overlapping convex C-obstacle
// pieces: a reduced visibility graph (tangent at both ends), exact visibility through a
// uniform-grid index, connected components, and A* per query.
//
// The reference point must avoid the OPEN interior of the union of the pieces of each
// group (one group per obstacle; the pieces of a non-convex obstacle or robot overlap or
// share edges) and stay in an optional closed box. Every decision is an exact sign
// (mk::cross_sign) or an exact coordinate comparison; doubles are used only to find
// grid cells (conservatively, with a slack) and for path lengths.
//
// Facts the code relies on (argued in docs/planning.md):
//  * a closed segment s = [p, q], p != q, meets int(P) for a convex polygon P iff no edge
//    line of P has p and q weakly outside it and the vertices of P are not weakly on one
//    side of the line pq (separating axes of P (+) (-s));
//  * s meets the open interior of a union of convex pieces iff it meets the interior of
//    one piece, or it overlaps (positive length) a "seam": the overlap of two antiparallel
//    collinear edges of two pieces of the union;
//  * a point x is in the open interior of the union iff it is inside one piece, or the
//    closed tangent cones at x of the pieces containing x cover every direction;
//  * a shortest path bends only at a vertex v of a piece P, and both of its segments at
//    v are tangent to P at v (the neighbours of v in P lie weakly on one side of them).
#pragma once

#include <algorithm>
#include <cstdlib>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

#include "boxes.hpp"
#include "convex.hpp"
#include "exact.hpp"
#include "parallel.hpp"

namespace mk {

template <class T>
inline int orient3(T ax, T ay, T bx, T by, T cx, T cy) {  // sign of (b - a) x (c - a)
  return cross_sign(ax, ay, bx, by, ax, ay, cx, cy);
}

// The status of a query, for both planners (this one and navmesh.hpp's); exported to
// Python by the bindings.
enum PlanStatus : int {
  PLAN_OK = 0,            // the path is in out
  PLAN_START_BAD = 1,     // the start is outside the box or inside a group (grp says)
  PLAN_GOAL_BAD = 2,      // the goal likewise
  PLAN_NO_PATH = 3,       // the goal cannot be reached
  PLAN_OUTSIDE_MESH = 4,  // (navmesh) a point outside the meshed box: mesh a larger one
};

// The slack of the uniform grids' cell lookups (the planner's below and the navigation
// mesh's): points and boxes find their cells in floating point (with int64 -> double
// conversion and, in Planner::blocked, interpolation along a segment), with an error far
// below this slack; every cell within it of the computed position is visited too. big:
// the largest |coordinate| of the grid's boxes, ext: their extent.
inline double grid_slack(double big, double ext) { return (big + ext) * 0x1p-36; }

// Per-thread scratch: stamps deduplicate items met in several grid cells.
struct PlanScratch {
  std::vector<std::uint32_t> stamp;
  std::uint32_t tick = 0;
  void init(std::size_t n) {
    stamp.assign(n, 0);
    tick = 0;
  }
  std::uint32_t next() {
    if (++tick == 0) {
      std::fill(stamp.begin(), stamp.end(), 0);
      tick = 1;
    }
    return tick;
  }
};

template <class T>
struct Planner {
  // ---- input: solid pieces (k >= 3), CCW, no collinear vertices
  std::vector<T> pc;      // 2 per vertex
  std::vector<i64> poff;  // P + 1
  std::vector<int> pgrp;  // P
  i64 P = 0;
  // ---- seams: (cx, cy, dx, dy) and group
  std::vector<T> sm;
  std::vector<int> sgrp;
  // ---- box for the reference point: closed, or open (a polygon workspace's frame, which
  // lies strictly outside workspace (-) robot: no point of its boundary is valid)
  bool has_box = false;
  bool open_box = false;
  T bx0{}, by0{}, bx1{}, by1{};
  // ---- lengths: every distance is computed in units of 1 / lscale (a power of two, so
  // scaling is exact), chosen so that no coordinate difference, edge length or path sum
  // overflows (1 unless a coordinate reaches 2^990)
  double lscale = 1.0;
  double magnitude_cache = 0.0;
  // ---- grid over items (pieces 0..P-1, seams P..P+S-1)
  double gx0 = 0, gy0 = 0, cs = 1, slack = 0;
  i64 nx = 1, ny = 1;
  std::vector<i64> cell_off;
  std::vector<int> cell_items;
  std::vector<T> tbox;  // exact bbox per item (xmin, ymin, xmax, ymax)
  // ---- candidates (bend points) and their corners (u, w) = (prev, next) in a piece
  std::vector<T> cv;
  std::vector<i64> coff;
  std::vector<T> corner;
  // ---- graph (CSR), components
  std::vector<i64> aoff;
  std::vector<int> adj;
  std::vector<double> aw;
  std::vector<int> comp;

  i64 items() const { return P + (i64)sgrp.size(); }
  i64 ncand() const { return (i64)cv.size() / 2; }

  // ------------------------------------------------------------------ primitives
  void piece_bbox(i64 p, T* b) const {
    T x0 = pc[2 * poff[p]], y0 = pc[2 * poff[p] + 1], x1 = x0, y1 = y0;
    for (i64 v = poff[p] + 1; v < poff[p + 1]; ++v) {
      x0 = std::min(x0, pc[2 * v]);
      x1 = std::max(x1, pc[2 * v]);
      y0 = std::min(y0, pc[2 * v + 1]);
      y1 = std::max(y1, pc[2 * v + 1]);
    }
    b[0] = x0;
    b[1] = y0;
    b[2] = x1;
    b[3] = y1;
  }

  bool in_box(T x, T y) const {
    if (!has_box) return true;
    if (open_box) return bx0 < x && x < bx1 && by0 < y && y < by1;
    return bx0 <= x && x <= bx1 && by0 <= y && y <= by1;
  }

  // segment [p, q] (p != q) meets the open interior of piece k
  bool piece_blocks(i64 k, T px, T py, T qx, T qy) const {
    const i64 lo = poff[k], hi = poff[k + 1];
    const T* v = pc.data();
    for (i64 i = lo; i < hi; ++i) {
      i64 j = i + 1 < hi ? i + 1 : lo;
      if (orient3(v[2 * i], v[2 * i + 1], v[2 * j], v[2 * j + 1], px, py) <= 0 &&
          orient3(v[2 * i], v[2 * i + 1], v[2 * j], v[2 * j + 1], qx, qy) <= 0)
        return false;
    }
    bool pos = false, neg = false;
    for (i64 i = lo; i < hi; ++i) {
      int o = orient3(px, py, qx, qy, v[2 * i], v[2 * i + 1]);
      pos |= o > 0;
      neg |= o < 0;
      if (pos && neg) return true;
    }
    return false;
  }

  // segment [p, q] (p != q) overlaps seam s with positive length
  bool seam_blocks(i64 s, T px, T py, T qx, T qy) const {
    const T* m = sm.data() + 4 * s;
    if (orient3(m[0], m[1], m[2], m[3], px, py) != 0) return false;
    if (orient3(m[0], m[1], m[2], m[3], qx, qy) != 0) return false;
    int ax = m[0] != m[2] ? 0 : 1;
    T a0 = ax ? py : px, a1 = ax ? qy : qx, b0 = m[ax], b1 = m[2 + ax];
    T lo = std::max(std::min(a0, a1), std::min(b0, b1));
    T hi = std::min(std::max(a0, a1), std::max(b0, b1));
    return lo < hi;
  }

  bool item_blocks(i64 it, T px, T py, T qx, T qy) const {
    const T* b = tbox.data() + 4 * it;
    if (std::max(px, qx) < b[0] || std::min(px, qx) > b[2] || std::max(py, qy) < b[1] ||
        std::min(py, qy) > b[3])
      return false;
    if (it < P) return piece_blocks(it, px, py, qx, qy);
    return seam_blocks(it - P, px, py, qx, qy);
  }

  i64 cellx(double x) const {
    double c = std::floor((x - gx0) / cs);
    if (!(c >= 0)) return 0;  // also NaN
    if (c >= (double)nx) return nx - 1;
    return (i64)c;
  }
  i64 celly(double y) const {
    double c = std::floor((y - gy0) / cs);
    if (!(c >= 0)) return 0;
    if (c >= (double)ny) return ny - 1;
    return (i64)c;
  }

  // the closed segment [p, q] meets the open interior of some group's union
  bool blocked(T px, T py, T qx, T qy, PlanScratch& S, int* blocker = nullptr) const {
    if (px == qx && py == qy) return interior_group(px, py, S) >= 0;
    const std::uint32_t tk = S.next();
    const double dpx = (double)px, dpy = (double)py, dqx = (double)qx, dqy = (double)qy;
    const bool alongx = std::fabs(dqx - dpx) >= std::fabs(dqy - dpy);
    // walk along the major axis u; the minor axis w varies by at most one unit per unit
    const double pu = alongx ? dpx : dpy, pw = alongx ? dpy : dpx;
    const double qu = alongx ? dqx : dqy, qw = alongx ? dqy : dqx;
    auto cu = [&](double u) { return alongx ? cellx(u) : celly(u); };
    auto cw = [&](double w) { return alongx ? celly(w) : cellx(w); };
    const double umin = std::min(pu, qu), umax = std::max(pu, qu);
    const double wmin = std::min(pw, qw) - slack, wmax = std::max(pw, qw) + slack;
    const double slope = (qw - pw) / (qu - pu);
    i64 c0 = cu(umin - slack), c1 = cu(umax + slack);
    const int du = qu >= pu ? 1 : -1, dw = qw >= pw ? 1 : -1;
    for (i64 t = 0; t <= c1 - c0; ++t) {
      i64 c = du > 0 ? c0 + t : c1 - t;
      double ua = (alongx ? gx0 : gy0) + (double)c * cs, ub = ua + cs;
      if (c == c0) ua = -std::numeric_limits<double>::infinity();
      if (c == c1) ub = std::numeric_limits<double>::infinity();
      ua = std::max(ua, umin);
      ub = std::min(ub, umax);
      double wa = pw + (ua - pu) * slope, wb = pw + (ub - pu) * slope;
      double lo = std::max(std::min(wa, wb) - slack, wmin);
      double hi = std::min(std::max(wa, wb) + slack, wmax);
      i64 r0 = cw(lo), r1 = cw(hi);
      for (i64 s = 0; s <= r1 - r0; ++s) {
        i64 r = dw > 0 ? r0 + s : r1 - s;
        i64 cell = alongx ? r * nx + c : c * nx + r;
        for (i64 e = cell_off[cell]; e < cell_off[cell + 1]; ++e) {
          int it = cell_items[e];
          if (S.stamp[it] == tk) continue;
          S.stamp[it] = tk;
          if (item_blocks(it, px, py, qx, qy)) {
            if (blocker) *blocker = it;
            return true;
          }
        }
      }
    }
    return false;
  }

  // 0 outside, 1 on edge i (from vertex i to i + 1), 2 at vertex i, 3 strictly inside
  int classify(i64 k, T x, T y, i64& where) const {
    const i64 lo = poff[k], hi = poff[k + 1];
    const T* v = pc.data();
    i64 z0 = -1, z1 = -1;
    for (i64 i = lo; i < hi; ++i) {
      i64 j = i + 1 < hi ? i + 1 : lo;
      int o = orient3(v[2 * i], v[2 * i + 1], v[2 * j], v[2 * j + 1], x, y);
      if (o < 0) return 0;
      if (o == 0) {
        if (z0 < 0)
          z0 = i;
        else
          z1 = i;
      }
    }
    if (z0 < 0) return 3;
    if (z1 < 0) {
      where = z0;
      return 1;
    }
    // on two edge lines: the shared vertex (z1 follows z0, or z0 = lo and z1 = hi - 1)
    where = (z1 == z0 + 1) ? z1 : z0;
    return 2;
  }

  struct Cone {
    T ax, ay, bx, by;  // from direction a - x counter-clockwise to b - x (angle <= 180)
    int grp;
  };

  // The group whose union has x in its open interior, or -1.
  int interior_group(T x, T y, PlanScratch& S) const {
    if (cell_off.empty()) return -1;
    std::vector<Cone> cones;
    const T* v = pc.data();
    // a point within `slack` of a cell border may belong to the neighbour's items too
    i64 cxa = cellx((double)x - slack), cxb = cellx((double)x + slack);
    i64 cya = celly((double)y - slack), cyb = celly((double)y + slack);
    const std::uint32_t tk = S.next();
    // several obstacles may overlap at x: the answer is the lowest group whose C-obstacle
    // has x in its open interior (the same whatever the order of the grid's cells)
    int best = -1;
    for (i64 r = cya; r <= cyb; ++r)
      for (i64 cc = cxa; cc <= cxb; ++cc) {
        i64 cell = r * nx + cc;
        for (i64 e = cell_off[cell]; e < cell_off[cell + 1]; ++e) {
          int it = cell_items[e];
          if (it >= P || S.stamp[it] == tk) continue;
          S.stamp[it] = tk;
          const T* b = tbox.data() + 4 * it;
          if (x < b[0] || x > b[2] || y < b[1] || y > b[3]) continue;
          i64 w = 0;
          int cl = classify(it, x, y, w);
          if (cl == 3) {  // strictly inside a piece: its group (the lowest such, below)
            if (best < 0 || pgrp[it] < best) best = pgrp[it];
            continue;
          }
          if (cl == 0) continue;
          i64 lo = poff[it], hi = poff[it + 1];
          if (cl == 1) {
            i64 j = w + 1 < hi ? w + 1 : lo;
            cones.push_back(Cone{v[2 * j], v[2 * j + 1], v[2 * w], v[2 * w + 1], pgrp[it]});
          } else {
            i64 j = w + 1 < hi ? w + 1 : lo, h = w > lo ? w - 1 : hi - 1;
            cones.push_back(Cone{v[2 * j], v[2 * j + 1], v[2 * h], v[2 * h + 1], pgrp[it]});
          }
        }
      }
    if (cones.size() < 2) return best;
    std::sort(cones.begin(), cones.end(), [](const Cone& a, const Cone& b) { return a.grp < b.grp; });
    for (std::size_t g0 = 0; g0 < cones.size();) {
      std::size_t g1 = g0;
      while (g1 < cones.size() && cones[g1].grp == cones[g0].grp) ++g1;
      if (best >= 0 && cones[g0].grp >= best) break;
      if (g1 - g0 >= 2 && covers(x, y, cones.data() + g0, g1 - g0)) return cones[g0].grp;
      g0 = g1;
    }
    return best;
  }

  // do the closed cones cover every direction around x?
  bool covers(T x, T y, const Cone* cn, std::size_t n) const {
    struct Ray {
      T tx, ty;
    };
    std::vector<Ray> rays;
    rays.reserve(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
      rays.push_back(Ray{cn[i].ax, cn[i].ay});
      rays.push_back(Ray{cn[i].bx, cn[i].by});
    }
    auto half = [&](const Ray& r) { return (r.ty > y || (r.ty == y && r.tx > x)) ? 0 : 1; };
    auto cmp = [&](const Ray& a, const Ray& b) {  // -1 a first, 0 same direction, 1 b first
      int ha = half(a), hb = half(b);
      if (ha != hb) return ha < hb ? -1 : 1;
      return -cross_sign(x, y, a.tx, a.ty, x, y, b.tx, b.ty);
    };
    std::sort(rays.begin(), rays.end(), [&](const Ray& a, const Ray& b) { return cmp(a, b) < 0; });
    std::vector<Ray> u;
    for (const Ray& r : rays)
      if (u.empty() || cmp(u.back(), r) != 0) u.push_back(r);
    const std::size_t m = u.size();
    if (m < 2) return false;
    auto rank = [&](T tx, T ty) {
      Ray r{tx, ty};
      std::size_t a = 0, b = m;  // first position not before r
      while (a < b) {
        std::size_t h = (a + b) / 2;
        if (cmp(u[h], r) < 0)
          a = h + 1;
        else
          b = h;
      }
      return a;
    };
    std::vector<int> cnt(m + 1, 0);
    for (std::size_t i = 0; i < n; ++i) {
      std::size_t a = rank(cn[i].ax, cn[i].ay), b = rank(cn[i].bx, cn[i].by);
      // gaps a, a + 1, ..., b - 1 (cyclic); gap g lies between u[g] and u[g + 1]
      if (a < b) {
        cnt[a] += 1;
        cnt[b] -= 1;
      } else {
        cnt[a] += 1;
        cnt[m] -= 1;
        cnt[0] += 1;
        cnt[b] -= 1;
      }
    }
    int run = 0;
    for (std::size_t g = 0; g < m; ++g) {
      run += cnt[g];
      if (run <= 0) return false;
    }
    return true;
  }

  // is the segment from a to candidate v tangent at v to one of v's pieces?
  bool tangent(T ax, T ay, i64 v) const {
    const T vx = cv[2 * v], vy = cv[2 * v + 1];
    for (i64 c = coff[v]; c < coff[v + 1]; ++c) {
      const T* q = corner.data() + 4 * c;
      int o1 = orient3(ax, ay, vx, vy, q[0], q[1]);
      int o2 = orient3(ax, ay, vx, vy, q[2], q[3]);
      if (o1 * o2 >= 0) return true;
    }
    return false;
  }

  // |a - b| * s; s is a power of two <= 1 chosen by scale_for (see lscale)
  static double dist(T ax, T ay, T bx, T by, double s) {
    double dx = (double)ax - (double)bx, dy = (double)ay - (double)by;
    if (s != 1.0) {
      dx = std::isfinite(dx) ? dx * s : (double)ax * s - (double)bx * s;
      dy = std::isfinite(dy) ? dy * s : (double)ay * s - (double)by * s;
    }
    return std::hypot(dx, dy);
  }

  // the scale for coordinates of magnitude at most m: scaled coordinates stay below
  // 2^991, so differences, edge lengths and sums of up to 2^30 edges stay finite
  static double scale_for(double m) {
    if (!(m >= 0x1p990)) return 1.0;
    return std::ldexp(1.0, 990 - std::ilogb(m));
  }

  double magnitude() const {
    double m = 0.0;
    for (const T& v : pc) m = std::max(m, std::fabs((double)v));
    if (has_box)
      for (T v : {bx0, by0, bx1, by1}) m = std::max(m, std::fabs((double)v));
    return m;
  }

  // ------------------------------------------------------------------ build
  void build_grid() {
    const i64 I = items();
    tbox.assign(4 * I, T{});
    for (i64 p = 0; p < P; ++p) piece_bbox(p, tbox.data() + 4 * p);
    for (i64 s = 0; s < (i64)sgrp.size(); ++s) {
      const T* m = sm.data() + 4 * s;
      T* b = tbox.data() + 4 * (P + s);
      b[0] = std::min(m[0], m[2]);
      b[1] = std::min(m[1], m[3]);
      b[2] = std::max(m[0], m[2]);
      b[3] = std::max(m[1], m[3]);
    }
    double X0 = 0, Y0 = 0, X1 = 1, Y1 = 1, big = 0, area = 0;
    for (i64 i = 0; i < I; ++i) {
      const T* b = tbox.data() + 4 * i;
      double a0 = (double)b[0], a1 = (double)b[1], a2 = (double)b[2], a3 = (double)b[3];
      if (i == 0) {
        X0 = a0, Y0 = a1, X1 = a2, Y1 = a3;
      } else {
        X0 = std::min(X0, a0), Y0 = std::min(Y0, a1), X1 = std::max(X1, a2),
        Y1 = std::max(Y1, a3);
      }
      if (i < P) area += (a2 - a0) * (a3 - a1);
      big = std::max({big, std::fabs(a0), std::fabs(a1), std::fabs(a2), std::fabs(a3)});
    }
    double ext = std::max(X1 - X0, Y1 - Y0);
    if (!(ext > 0) || !std::isfinite(ext)) ext = std::max(1.0, big);
    // (and at least 2^-1000: a grid of tiny coordinates keeps a normal slack)
    slack = grid_slack(big, ext) + 0x1p-1000;
    double per = P > 0 ? area / (double)P : ext * ext;
    // about one piece per cell, at most ~4 cells per item (and 4096 per side)
    cs = std::sqrt(std::max(per, ext * ext / (4.0 * (double)I + 64.0)));
    if (!(cs > 0) || !std::isfinite(cs)) cs = ext;
    gx0 = X0 - slack;
    gy0 = Y0 - slack;
    const double wx = X1 - X0 + 2 * slack, wy = Y1 - Y0 + 2 * slack;
    if (!std::isfinite(wx + wy + 4 * big) || !(cs > 0) || !std::isfinite(cs)) {
      nx = ny = 1;  // one cell: every walk visits everything (no overflowing arithmetic)
      cs = std::numeric_limits<double>::max();
    } else {
      nx = (i64)std::max(1.0, std::min(4096.0, std::ceil(wx / cs)));
      ny = (i64)std::max(1.0, std::min(4096.0, std::ceil(wy / cs)));
      cs = std::max(wx / (double)nx, wy / (double)ny);
    }
    auto range = [&](i64 it, i64& xa, i64& xb, i64& ya, i64& yb) {
      const T* b = tbox.data() + 4 * it;
      xa = cellx((double)b[0] - slack);
      xb = cellx((double)b[2] + slack);
      ya = celly((double)b[1] - slack);
      yb = celly((double)b[3] + slack);
    };
    grid_buckets(I, nx, ny, range, cell_off, cell_items);
  }

  void build_seams() {
    // pieces of one group, pairwise: antiparallel collinear edges overlapping
    std::vector<i64> order(P);
    for (i64 p = 0; p < P; ++p) order[p] = p;
    std::stable_sort(order.begin(), order.end(), [&](i64 a, i64 b) { return pgrp[a] < pgrp[b]; });
    std::vector<T> bb(4 * P);
    for (i64 p = 0; p < P; ++p) piece_bbox(p, bb.data() + 4 * p);
    const T* v = pc.data();
    for (i64 g0 = 0; g0 < P;) {
      i64 g1 = g0;
      while (g1 < P && pgrp[order[g1]] == pgrp[order[g0]]) ++g1;
      for (i64 a = g0; a < g1; ++a)
        for (i64 b = a + 1; b < g1; ++b) {
          i64 A = order[a], B = order[b];
          const T *ba = bb.data() + 4 * A, *bq = bb.data() + 4 * B;
          if (ba[2] < bq[0] || bq[2] < ba[0] || ba[3] < bq[1] || bq[3] < ba[1]) continue;
          for (i64 i = poff[A]; i < poff[A + 1]; ++i) {
            i64 i2 = i + 1 < poff[A + 1] ? i + 1 : poff[A];
            for (i64 j = poff[B]; j < poff[B + 1]; ++j) {
              i64 j2 = j + 1 < poff[B + 1] ? j + 1 : poff[B];
              // antiparallel: every coordinate difference of opposite sign (or both 0)
              if (sgn(v[2 * i2] - v[2 * i]) != -sgn(v[2 * j2] - v[2 * j])) continue;
              if (sgn(v[2 * i2 + 1] - v[2 * i + 1]) != -sgn(v[2 * j2 + 1] - v[2 * j + 1]))
                continue;
              if (orient3(v[2 * i], v[2 * i + 1], v[2 * i2], v[2 * i2 + 1], v[2 * j],
                          v[2 * j + 1]) != 0)
                continue;
              if (orient3(v[2 * i], v[2 * i + 1], v[2 * i2], v[2 * i2 + 1], v[2 * j2],
                          v[2 * j2 + 1]) != 0)
                continue;
              int ax = v[2 * i] != v[2 * i2] ? 0 : 1;
              // overlap along axis ax: the larger of the lower ends, the smaller upper end
              auto key = [&](i64 t) { return v[2 * t + ax]; };
              i64 loA = key(i) < key(i2) ? i : i2, hiA = loA == i ? i2 : i;
              i64 loB = key(j) < key(j2) ? j : j2, hiB = loB == j ? j2 : j;
              i64 lo = key(loA) >= key(loB) ? loA : loB;
              i64 hi = key(hiA) <= key(hiB) ? hiA : hiB;
              if (!(key(lo) < key(hi))) continue;
              sm.insert(sm.end(), {v[2 * lo], v[2 * lo + 1], v[2 * hi], v[2 * hi + 1]});
              sgrp.push_back(pgrp[A]);
            }
          }
        }
      g0 = g1;
    }
  }

  void build_candidates(PlanScratch& S) {
    i64 V = poff[P];
    std::vector<i64> ord(V);
    for (i64 i = 0; i < V; ++i) ord[i] = i;
    const T* v = pc.data();
    std::sort(ord.begin(), ord.end(), [&](i64 a, i64 b) {
      return v[2 * a] < v[2 * b] || (v[2 * a] == v[2 * b] && v[2 * a + 1] < v[2 * b + 1]);
    });
    std::vector<i64> owner(V);  // vertex -> piece
    for (i64 p = 0; p < P; ++p)
      for (i64 i = poff[p]; i < poff[p + 1]; ++i) owner[i] = p;
    cv.clear();
    coff.assign(1, 0);
    corner.clear();
    for (i64 s = 0; s < V;) {
      i64 e = s;
      while (e < V && v[2 * ord[e]] == v[2 * ord[s]] && v[2 * ord[e] + 1] == v[2 * ord[s] + 1])
        ++e;
      T x = v[2 * ord[s]], y = v[2 * ord[s] + 1];
      if (in_box(x, y) && interior_group(x, y, S) < 0) {
        cv.push_back(x);
        cv.push_back(y);
        for (i64 t = s; t < e; ++t) {
          i64 i = ord[t], p = owner[i], lo = poff[p], hi = poff[p + 1];
          i64 h = i > lo ? i - 1 : hi - 1, j = i + 1 < hi ? i + 1 : lo;
          corner.insert(corner.end(), {v[2 * h], v[2 * h + 1], v[2 * j], v[2 * j + 1]});
        }
        coff.push_back((i64)corner.size() / 4);
      }
      s = e;
    }
  }

  int threads = 1;

  // Structure-of-arrays doubles for the tangent pre-filter: the candidate and, when it
  // has exactly one corner, that corner (NaN otherwise: the filter then never decides).
  // Only used when every coordinate converts to double exactly and the products can
  // neither overflow nor underflow (fast = true); the exact test decides the rest.
  std::vector<double> fx, fy, fux, fuy, fwx, fwy;
  bool fast = false;

  void build_filter() {
    const i64 N = ncand();
    fast = true;
    const double NaN = std::numeric_limits<double>::quiet_NaN();
    fx.resize(N), fy.resize(N), fux.resize(N), fuy.resize(N), fwx.resize(N), fwy.resize(N);
    auto ok = [&](T v) {
      if constexpr (std::is_floating_point_v<T>) {
        double a = std::fabs((double)v);
        return a == 0.0 || (a >= 0x1p-400 && a <= 0x1p400);
      } else {
        return v <= ((T)1 << 53) && v >= -((T)1 << 53);
      }
    };
    for (i64 a = 0; a < N; ++a) {
      fx[a] = (double)cv[2 * a];
      fy[a] = (double)cv[2 * a + 1];
      fast = fast && ok(cv[2 * a]) && ok(cv[2 * a + 1]);
      if (coff[a + 1] - coff[a] == 1) {
        const T* q = corner.data() + 4 * coff[a];
        fux[a] = (double)q[0], fuy[a] = (double)q[1], fwx[a] = (double)q[2], fwy[a] = (double)q[3];
        fast = fast && ok(q[0]) && ok(q[1]) && ok(q[2]) && ok(q[3]);
      } else {
        fux[a] = fuy[a] = fwx[a] = fwy[a] = NaN;
      }
    }
  }

  // skip[j] = 1 when the pair (i, j) is certainly not tangent at i or at j
  void prefilter(i64 i, std::vector<std::uint8_t>& skip) const {
    const i64 N = ncand();
    const double vx = fx[i], vy = fy[i], ux = fux[i], uy = fuy[i], wx = fwx[i], wy = fwy[i];
    const double* __restrict X = fx.data();
    const double* __restrict Y = fy.data();
    const double* __restrict UX = fux.data();
    const double* __restrict UY = fuy.data();
    const double* __restrict WX = fwx.data();
    const double* __restrict WY = fwy.data();
    std::uint8_t* __restrict sk = skip.data();
    for (i64 j = i + 1; j < N; ++j) {
      const double ax = X[j], ay = Y[j];
      // the two corner points certainly on opposite sides of the line a v (exact.hpp's filter_apart)
      // at i: orient(a, v, u) and orient(a, v, w)
      const bool sep_i = filter_apart((vx - ax) * (uy - ay), (vy - ay) * (ux - ax),
                                      (vx - ax) * (wy - ay), (vy - ay) * (wx - ax));
      // at j: orient(v, a, U) and orient(v, a, W)
      const bool sep_j = filter_apart((ax - vx) * (UY[j] - vy), (ay - vy) * (UX[j] - vx),
                                      (ax - vx) * (WY[j] - vy), (ay - vy) * (WX[j] - vx));
      sk[j] = (std::uint8_t)(sep_i | sep_j);
    }
  }

  void pairs_of(i64 t, i64 nt, PlanScratch& S, std::vector<std::pair<int, int>>& edges) const {
    const i64 N = ncand();
    std::vector<std::uint8_t> skip(fast ? N : 0);
    for (i64 i = t; i < N; i += nt) {
      const T ix = cv[2 * i], iy = cv[2 * i + 1];
      if (fast) prefilter(i, skip);
      // the last blocker met from i in each of 128 direction bins: pairs in about the same
      // direction are often blocked by the same piece, and one exact test of it is
      // cheaper than a grid walk (the bin is a hint only; item_blocks decides exactly)
      constexpr int NB = 128;
      int cache[NB];
      std::fill(cache, cache + NB, -1);
      const double dix = (double)ix, diy = (double)iy;
      for (i64 j = i + 1; j < N; ++j) {
        if (fast && skip[j]) continue;
        const T jx = cv[2 * j], jy = cv[2 * j + 1];
        if (!tangent(jx, jy, i) || !tangent(ix, iy, j)) continue;
        const double ddx = (double)jx - dix, ddy = (double)jy - diy;
        const double den = std::fabs(ddx) + std::fabs(ddy);
        double pa = den > 0 ? ddy / den : 0.0;  // pseudo-angle in [0, 4)
        pa = ddx >= 0 ? (ddy >= 0 ? pa : 4.0 + pa) : 2.0 - pa;
        int bin = (int)(pa * (NB / 4));
        bin = bin < 0 ? 0 : (bin > NB - 1 ? NB - 1 : bin);
        const int b0 = cache[bin], b1 = cache[(bin + 1) % NB], b2 = cache[(bin + NB - 1) % NB];
        if (b0 >= 0 && item_blocks(b0, ix, iy, jx, jy)) continue;
        if (b1 >= 0 && b1 != b0 && item_blocks(b1, ix, iy, jx, jy)) continue;
        if (b2 >= 0 && b2 != b0 && b2 != b1 && item_blocks(b2, ix, iy, jx, jy)) continue;
        int b = -1;
        if (blocked(ix, iy, jx, jy, S, &b)) {
          cache[bin] = b;
          continue;
        }
        edges.emplace_back((int)i, (int)j);
      }
    }
  }

  void build_graph(PlanScratch& S) {
    const i64 N = ncand();
    build_filter();
    std::vector<std::pair<int, int>> edges;
    const int nt = thread_count(threads, N / 256 + 1);
    if (nt == 1) {
      pairs_of(0, 1, S, edges);
    } else {
      std::vector<std::vector<std::pair<int, int>>> part(nt);
      parallel_threads(nt, [&](int t) {
        if (t == 0) return pairs_of(0, nt, S, part[0]);
        PlanScratch St;
        St.init((std::size_t)items());
        pairs_of(t, nt, St, part[t]);
      });
      for (auto& p : part) edges.insert(edges.end(), p.begin(), p.end());
    }
    aoff.assign(N + 1, 0);
    for (auto& e : edges) {
      aoff[e.first + 1]++;
      aoff[e.second + 1]++;
    }
    for (i64 i = 0; i < N; ++i) aoff[i + 1] += aoff[i];
    adj.assign(aoff[N], 0);
    aw.assign(aoff[N], 0.0);
    std::vector<i64> fill(aoff.begin(), aoff.end() - 1);
    for (auto& e : edges) {
      double d = dist(cv[2 * e.first], cv[2 * e.first + 1], cv[2 * e.second],
                      cv[2 * e.second + 1], lscale);
      adj[fill[e.first]] = e.second;
      aw[fill[e.first]++] = d;
      adj[fill[e.second]] = e.first;
      aw[fill[e.second]++] = d;
    }
    // components
    comp.assign(N, -1);
    int nc = 0;
    std::vector<int> stack;
    for (i64 s = 0; s < N; ++s) {
      if (comp[s] >= 0) continue;
      comp[s] = nc;
      stack.push_back((int)s);
      while (!stack.empty()) {
        int a = stack.back();
        stack.pop_back();
        for (i64 e = aoff[a]; e < aoff[a + 1]; ++e)
          if (comp[adj[e]] < 0) {
            comp[adj[e]] = nc;
            stack.push_back(adj[e]);
          }
      }
      ++nc;
    }
  }

  // Every piece must be strictly convex (CCW, no collinear vertex) for the primitives
  // above. Exact int sums are; correctly rounded float sums can fold by an ulp: such a
  // piece is replaced by the convex hull of its vertices (it only grows, by rounding).
  void convexify() {
    std::vector<T> npc;
    std::vector<i64> noff{0};
    std::vector<int> ngrp;
    const T* v = pc.data();
    for (i64 p = 0; p < (i64)pgrp.size(); ++p) {
      const i64 lo = poff[p], hi = poff[p + 1], k = hi - lo;
      bool ok = k >= 3;
      for (i64 t = 0; ok && t < k; ++t) {
        i64 h = lo + (t + k - 1) % k, i = lo + t, j = lo + (t + 1) % k;
        ok = orient(v, h, i, j) > 0;
      }
      if (ok) {
        npc.insert(npc.end(), v + 2 * lo, v + 2 * hi);
      } else {
        std::vector<i64> order(k), hull(2 * k + 1);
        for (i64 t = 0; t < k; ++t) order[t] = lo + t;
        std::sort(order.begin(), order.end(), [&](i64 a, i64 b) {
          return v[2 * a] < v[2 * b] || (v[2 * a] == v[2 * b] && v[2 * a + 1] < v[2 * b + 1]);
        });
        order.erase(std::unique(order.begin(), order.end(),
                                [&](i64 a, i64 b) {
                                  return v[2 * a] == v[2 * b] && v[2 * a + 1] == v[2 * b + 1];
                                }),
                    order.end());
        if (order.size() < 3) continue;
        i64 m = hull_sorted(v, order.data(), (i64)order.size(), hull.data());
        if (m < 3) continue;  // collinear: no interior, blocks nothing
        for (i64 t = 0; t < m; ++t) {
          npc.push_back(v[2 * hull[t]]);
          npc.push_back(v[2 * hull[t] + 1]);
        }
      }
      noff.push_back((i64)npc.size() / 2);
      ngrp.push_back(pgrp[p]);
    }
    pc.swap(npc);
    poff.swap(noff);
    pgrp.swap(ngrp);
  }

  // the exact tests only (pieces, seams, the grid): what the navigation mesh needs
  void build_base() {
    convexify();
    P = (i64)pgrp.size();
    magnitude_cache = magnitude();
    lscale = scale_for(magnitude_cache);
    build_seams();
    build_grid();
  }

  void build() {
    build_base();
    PlanScratch S;
    S.init((std::size_t)items());
    build_candidates(S);
    build_graph(S);
  }

  // ------------------------------------------------------------------ queries
  // What every query (of both planners) begins with: the start and the goal valid, the
  // same point, the straight segment free. A PlanStatus, or -1 when a search must answer;
  // grp: the group a point is inside (-2: outside the box).
  int query_front(T sx, T sy, T gx, T gy, std::vector<T>& out, int& grp,
                  PlanScratch& S) const {
    out.clear();
    grp = -1;
    for (int w = 0; w < 2; ++w) {
      T x = w ? gx : sx, y = w ? gy : sy;
      if (!in_box(x, y)) {
        grp = -2;
        return w ? PLAN_GOAL_BAD : PLAN_START_BAD;
      }
      int g = interior_group(x, y, S);
      if (g >= 0) {
        grp = g;
        return w ? PLAN_GOAL_BAD : PLAN_START_BAD;
      }
    }
    if (sx == gx && sy == gy) {
      out = {sx, sy};
      return PLAN_OK;
    }
    if (!blocked(sx, sy, gx, gy, S)) {
      out = {sx, sy, gx, gy};
      return PLAN_OK;
    }
    return -1;
  }

  // a PlanStatus (the path in out); grp as in query_front
  int query(T sx, T sy, T gx, T gy, std::vector<T>& out, int& grp, PlanScratch& S) const {
    if (int st = query_front(sx, sy, gx, gy, out, grp, S); st >= 0) return st;
    const i64 N = ncand();
    // query points may be larger than the scene: the query's own scale, and the factor
    // (a power of two) that brings the graph's edge lengths to it
    double qm = std::max({std::fabs((double)sx), std::fabs((double)sy), std::fabs((double)gx),
                          std::fabs((double)gy)});
    const double qs = std::min(lscale, scale_for(std::max(qm, magnitude_cache)));
    const double wf = qs / lscale;
    std::vector<std::pair<int, double>> se, ge;
    for (i64 v = 0; v < N; ++v) {
      const T vx = cv[2 * v], vy = cv[2 * v + 1];
      if (tangent(sx, sy, v) && !blocked(sx, sy, vx, vy, S))
        se.emplace_back((int)v, dist(sx, sy, vx, vy, qs));
    }
    if (se.empty()) return PLAN_NO_PATH;
    std::vector<char> sc;
    {
      int mc = 0;
      for (auto& e : se) mc = std::max(mc, comp[e.first]);
      sc.assign(mc + 1, 0);
      for (auto& e : se) sc[comp[e.first]] = 1;
    }
    for (i64 v = 0; v < N; ++v) {
      if (comp[v] >= (int)sc.size() || !sc[comp[v]]) continue;
      const T vx = cv[2 * v], vy = cv[2 * v + 1];
      if (tangent(gx, gy, v) && !blocked(gx, gy, vx, vy, S))
        ge.emplace_back((int)v, dist(gx, gy, vx, vy, qs));
    }
    if (ge.empty()) return PLAN_NO_PATH;
    // A*: nodes 0..N-1, N start, N + 1 goal
    const double INF = std::numeric_limits<double>::infinity();
    std::vector<double> g(N + 2, INF), togoal(N, INF);
    std::vector<int> parent(N + 2, -1);
    std::vector<char> done(N + 2, 0);
    for (auto& e : ge) togoal[e.first] = e.second;
    auto h = [&](i64 v) {
      if (v >= N) return v == N + 1 ? 0.0 : dist(sx, sy, gx, gy, qs);
      return dist(cv[2 * v], cv[2 * v + 1], gx, gy, qs);
    };
    using QE = std::pair<double, int>;
    std::priority_queue<QE, std::vector<QE>, std::greater<QE>> pq;
    g[N] = 0;
    pq.push({h(N), (int)N});
    while (!pq.empty()) {
      auto [f, a] = pq.top();
      pq.pop();
      if (done[a]) continue;
      done[a] = 1;
      if (a == N + 1) break;
      auto relax = [&](int b, double w) {
        double ng = g[a] + w;
        if (ng < g[b]) {
          g[b] = ng;
          parent[b] = a;
          pq.push({ng + h(b), b});
        }
      };
      if (a == N) {
        for (auto& e : se) relax(e.first, e.second);
        continue;
      }
      for (i64 e = aoff[a]; e < aoff[a + 1]; ++e) relax(adj[e], aw[e] * wf);
      if (togoal[a] < INF) relax((int)N + 1, togoal[a]);
    }
    if (!done[N + 1]) return PLAN_NO_PATH;
    std::vector<int> nodes;
    for (int a = (int)N + 1; a >= 0; a = parent[a]) nodes.push_back(a);
    std::reverse(nodes.begin(), nodes.end());
    for (int a : nodes) {
      if (a == N) {
        out.push_back(sx);
        out.push_back(sy);
      } else if (a == N + 1) {
        out.push_back(gx);
        out.push_back(gy);
      } else {
        out.push_back(cv[2 * a]);
        out.push_back(cv[2 * a + 1]);
      }
    }
    return PLAN_OK;
  }
};

}  // namespace mk
