// boxes.hpp -- pairs of overlapping axis-parallel boxes (a sort-and-sweep).
//
// box_pairs(n, xmin, xmax, ymin, ymax, on_pair) calls on_pair(i, j), i < j, once for every
// pair of boxes whose closed boxes overlap (touching counts). The boxes are sorted by
// their lower end along one axis and swept with an active list: a box stays active while
// the sweep has not passed its upper end, and each new box is tested against the active
// ones on the other axis. The axis is the one along which the boxes are thinner relative
// to their spread (fewer boxes active at once). Time O(n log n + a), a the number of
// (box, active box) tests -- in practice close to the number of overlapping pairs for the
// edges of a polygon (a few per edge); the worst case is quadratic (n long boxes that all
// overlap along the sweep axis). If on_pair returns bool, false stops the sweep.
//
// Comparisons only (no arithmetic decides anything): exact for every double, and the
// same for int64 coordinates. Reused by the polygon checks and the overlay.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <type_traits>
#include <vector>

#include "exact.hpp"

namespace mk {

// The neighbouring doubles (std::nextafter without the library call): +-inf and NaN
// stay, the neighbours of zero are the smallest subnormals.
inline double next_up(double x) {
  if (!(x - x == 0)) return x;
  if (x == 0) return 0x1p-1074;
  u64 b;
  std::memcpy(&b, &x, sizeof b);
  b = x > 0 ? b + 1 : b - 1;
  std::memcpy(&x, &b, sizeof b);
  return x;
}
inline double next_down(double x) { return -next_up(-x); }

// The slack of a span computed in double near coordinates of magnitude M: the part of a
// segment within a band of rows (a clip by interpolation, a few roundings) and the cells
// it reaches are widened by this much, far more than their rounding errors (a few ulps of
// M, 2^-52 M each) and than the low part of a DD coordinate (half an ulp); the 1e-300
// keeps it positive at M = 0. Used only to gather candidates (cells, segment pairs, edges
// to test) for exact tests, where a wider span only adds candidates: the grid of
// segment_pairs and the coverage test of union.hpp (which widened by 1e-14 M before; the
// larger of the two is safe for both).
inline double span_slack(double M) { return 1e-12 * M + 1e-300; }

template <class F, class C = double>
void box_pairs(i64 n, const C* xmin, const C* xmax, const C* ymin, const C* ymax, F&& on_pair) {
  if (n < 2) return;
  // the sweep axis: sum of extents over total spread, per axis (a heuristic: any choice
  // is correct; NaN or inf from extreme doubles falls back to x)
  double wx = 0, wy = 0, x0 = (double)xmin[0], x1 = (double)xmax[0], y0 = (double)ymin[0],
         y1 = (double)ymax[0];
  for (i64 i = 0; i < n; ++i) {
    wx += (double)xmax[i] - (double)xmin[i];
    wy += (double)ymax[i] - (double)ymin[i];
    x0 = std::min(x0, (double)xmin[i]);
    x1 = std::max(x1, (double)xmax[i]);
    y0 = std::min(y0, (double)ymin[i]);
    y1 = std::max(y1, (double)ymax[i]);
  }
  bool use_y = (wy / (y1 - y0)) < (wx / (x1 - x0));  // false for NaN
  const C* lo = use_y ? ymin : xmin;
  const C* hi = use_y ? ymax : xmax;
  const C* olo = use_y ? xmin : ymin;
  const C* ohi = use_y ? xmax : ymax;
  std::vector<i64> order(n);
  std::iota(order.begin(), order.end(), i64(0));
  std::sort(order.begin(), order.end(), [&](i64 a, i64 b) {
    return lo[a] < lo[b] || (lo[a] == lo[b] && a < b);
  });
  std::vector<i64> active;
  for (i64 t = 0; t < n; ++t) {
    const i64 i = order[t];
    const C li = lo[i], oli = olo[i], ohi_i = ohi[i];
    std::size_t keep = 0;
    for (std::size_t q = 0; q < active.size(); ++q) {
      const i64 j = active[q];
      if (hi[j] < li) continue;  // passed: drop it
      active[keep++] = j;
      if (olo[j] <= ohi_i && oli <= ohi[j]) {
        const i64 a = i < j ? i : j, b = i < j ? j : i;
        if constexpr (std::is_same_v<decltype(on_pair(a, b)), bool>) {
          if (!on_pair(a, b)) return;
        } else {
          on_pair(a, b);
        }
      }
    }
    active.resize(keep);
    active.push_back(i);
  }
}

}  // namespace mk

namespace mk {

// Sorts a[0, n) by less (a strict total order) when it is nearly sorted already: by
// insertion while the elements moved stay within n, else by a full sort (the same
// order either way).
template <class T, class Less>
void insertion_or_sort(T* a, std::size_t n, Less&& less) {
  std::size_t moves = 0;
  for (std::size_t t = 1; t < n; ++t) {
    if (!less(a[t], a[t - 1])) continue;
    const T x = a[t];
    std::size_t q = t;
    for (; q > 0 && less(x, a[q - 1]); --q) a[q] = a[q - 1];
    a[q] = x;
    moves += t - q;
    if (moves > n) {  // far from sorted
      std::sort(a, a + n, less);
      return;
    }
  }
}

// Scratch of box_pairs_grouped, reusable across calls (no allocation once grown).
struct BoxScratch {
  std::vector<i64> order;
  std::vector<std::vector<i64>> active;
  struct Box {
    double x0, x1, y0, y1;
    i64 i;
    int g;
  };
  std::vector<Box> sorted;
  std::vector<i64> hits;
};

// box_pairs_grouped for few boxes: sorted by the lower side along one axis, each box scans
// forward over the boxes that start before it ends (contiguous, no active lists). The
// axis is box_pairs' (the thinner one relative to the spread: shorter scans).
template <class F>
inline bool box_pairs_scan(i64 n, const double* xmin, const double* xmax, const double* ymin,
                           const double* ymax, const int* group, BoxScratch& s, F&& on_pair,
                           const i64* x_hint = nullptr) {
  auto& b = s.sorted;
  b.resize(n);
  double wx = 0, wy = 0, X0 = INFINITY, X1 = -INFINITY, Y0 = INFINITY, Y1 = -INFINITY;
  for (i64 i = 0; i < n; ++i) {
    wx += xmax[i] - xmin[i];
    wy += ymax[i] - ymin[i];
    X0 = std::min(X0, xmin[i]);
    X1 = std::max(X1, xmax[i]);
    Y0 = std::min(Y0, ymin[i]);
    Y1 = std::max(Y1, ymax[i]);
  }
  const bool use_y = (wy / (Y1 - Y0)) < (x_hint ? 0.5 : 1.0) * (wx / (X1 - X0));  // false for NaN
  auto less = [](const BoxScratch::Box& p, const BoxScratch::Box& q) {
    return p.x0 < q.x0 || (p.x0 == q.x0 && p.i < q.i);
  };
  if (use_y) {  // the same scan with the axes swapped
    for (i64 i = 0; i < n; ++i) b[i] = {ymin[i], ymax[i], xmin[i], xmax[i], i, group[i]};
    std::sort(b.begin(), b.end(), less);
  } else if (x_hint) {
    // an order close to the sorted one: repaired by insertion (the same order as the
    // sort, which is unique), or sorted when far from it
    for (i64 t = 0; t < n; ++t) {
      const i64 i = x_hint[t];
      b[t] = {xmin[i], xmax[i], ymin[i], ymax[i], i, group[i]};
    }
    insertion_or_sort(b.data(), (std::size_t)n, less);
  } else {
    for (i64 i = 0; i < n; ++i) b[i] = {xmin[i], xmax[i], ymin[i], ymax[i], i, group[i]};
    std::sort(b.begin(), b.end(), less);
  }
  // the boxes that overlap b[t] further on, gathered without branches (most fail the
  // test: a branch on it is mispredicted often), then reported in order
  auto& hit = s.hits;
  for (i64 t = 0; t < n; ++t) {
    const BoxScratch::Box a = b[t];
    i64 u = t + 1, end = u;
    while (end < n && b[end].x0 <= a.x1) ++end;
    if ((i64)hit.size() < end - u) hit.resize(end - u);
    i64 k = 0;
    for (; u < end; ++u) {
      const BoxScratch::Box& c = b[u];
      hit[k] = u;
      k += (c.y0 <= a.y1) & (a.y0 <= c.y1) & ((a.g < 0) | (c.g != a.g));
    }
    for (i64 q = 0; q < k; ++q) {
      const BoxScratch::Box& c = b[hit[q]];
      const i64 i = a.i < c.i ? a.i : c.i, j = a.i < c.i ? c.i : a.i;
      if constexpr (std::is_same_v<decltype(on_pair(i, j)), bool>) {
        if (!on_pair(i, j)) return false;
      } else {
        on_pair(i, j);
      }
    }
  }
  return true;
}

// Like box_pairs, but a box of group g in [0, ngroups) is never paired with another box
// of group g (group -1: paired with every box). With few groups each keeps its own
// active list and a box scans only the others' (a red-blue sweep for two groups);
// otherwise one list and same-group pairs are skipped.
template <class F>
inline bool box_pairs_grouped(i64 n, const double* xmin, const double* xmax,
                              const double* ymin, const double* ymax, const int* group,
                              int ngroups, BoxScratch& s, F&& on_pair) {
  constexpr int LISTS = 16;
  const int G = ngroups <= LISTS ? ngroups : 0;  // G lists + one for group -1
  s.order.resize(n);
  std::iota(s.order.begin(), s.order.end(), 0);
  std::sort(s.order.begin(), s.order.end(), [&](i64 a, i64 b) { return xmin[a] < xmin[b]; });
  if ((int)s.active.size() < G + 1) s.active.resize(G + 1);
  for (int k = 0; k <= G; ++k) s.active[k].clear();
  auto pair = [&](i64 i, i64 j) -> bool {
    if constexpr (std::is_same_v<decltype(on_pair(i, j)), bool>) {
      return on_pair(i < j ? i : j, i < j ? j : i);
    } else {
      on_pair(i < j ? i : j, i < j ? j : i);
      return true;
    }
  };
  for (i64 t = 0; t < n; ++t) {
    const i64 i = s.order[t];
    const double x = xmin[i], y0 = ymin[i], y1 = ymax[i];
    const int gi = group[i];
    const int own = G > 0 ? (gi >= 0 && gi < G ? gi : G) : 0;
    for (int k = 0; k <= G; ++k) {
      if (G > 0 && k == own && own != G) continue;
      std::vector<i64>& act = s.active[k];
      std::size_t w = 0;
      for (std::size_t q = 0; q < act.size(); ++q) {
        const i64 j = act[q];
        if (xmax[j] < x) continue;
        act[w++] = j;
        if (ymin[j] <= y1 && y0 <= ymax[j] && (gi < 0 || group[j] != gi)) {
          if (!pair(i, j)) {
            // keep the list consistent for a later call (the scratch is reused)
            for (++q; q < act.size(); ++q) act[w++] = act[q];
            act.resize(w);
            return false;
          }
        }
      }
      act.resize(w);
    }
    s.active[own].push_back(i);
  }
  return true;
}

}  // namespace mk

namespace mk {

// At most this many cell registrations in segment_pairs (two i64 arrays of this size).
constexpr i64 GRID_BUDGET = (i64)1 << 25;

// Scratch of segment_pairs (reused: no allocation once grown).
struct GridScratch {
  std::vector<i64> reg_start, reg_cell, cell_start, cell_edge, stamp;
};

// segment_pairs' inverse of its registrations: the segments of each of the nc cells,
// ascending (CSR: s.cell_start, s.cell_edge), from s.reg_start and s.reg_cell.
inline void grid_cells(i64 n, i64 nc, GridScratch& s) {
  const i64 nr = (i64)s.reg_cell.size();
  s.cell_start.assign(nc + 1, 0);
  for (i64 k = 0; k < nr; ++k) ++s.cell_start[s.reg_cell[k] + 1];
  for (i64 c = 0; c < nc; ++c) s.cell_start[c + 1] += s.cell_start[c];
  s.cell_edge.resize(nr);
  std::vector<i64>& fill = s.stamp;  // reused by segment_pairs as the stamps
  fill.assign(s.cell_start.begin(), s.cell_start.end() - 1);
  for (i64 i = 0; i < n; ++i)
    for (i64 k = s.reg_start[i]; k < s.reg_start[i + 1]; ++k)
      s.cell_edge[fill[s.reg_cell[k]]++] = i;
}

// Candidate pairs of segments by a uniform grid: segment i runs from (ax, ay) to (bx, by)
// up to tol[i] in each coordinate (the exact segment lies in the approximate one widened
// by a square of half-side tol[i]); it is registered in every cell its widened row spans
// reach, and on_pair(j, i), j < i, is called once for each pair of different groups
// (group -1: any) that share a cell and whose boxes (x0, x1, y0, y1) overlap. Every pair
// of segments with a common point is among them. on_pair may return false to stop.
// Long edges are cheap here (a box sweep keeps them active over their whole x-range).
//
// With `resume` given, the grid also gives up when long segments crowd its cells (a
// candidate test per cell neighbour far above the pairs found: nested squares put a few
// hundred long edges in every cell): it then returns false with *resume = i, every pair
// (j, i') with i' < i already reported, and the caller reports the rest (box_tree_pairs
// from i on). Without it, false means nothing was reported.
template <class F>
inline bool segment_pairs(i64 n, const double* ax, const double* ay, const double* bx,
                          const double* by, const double* tol, const double* x0,
                          const double* x1, const double* y0, const double* y1,
                          const int* group, GridScratch& s, F&& on_pair,
                          i64* resume = nullptr) {
  if (n < 2) return true;
  double X0 = INFINITY, X1 = -INFINITY, Y0 = INFINITY, Y1 = -INFINITY;
  for (i64 i = 0; i < n; ++i) {
    X0 = std::min(X0, x0[i]);
    X1 = std::max(X1, x1[i]);
    Y0 = std::min(Y0, y0[i]);
    Y1 = std::max(Y1, y1[i]);
  }
  const double W = X1 - X0, H = Y1 - Y0;
  if (!(W < INFINITY && H < INFINITY)) return false;  // the caller falls back
  const double target = (double)n;
  double cs = std::sqrt(W * H / target);
  if (!(cs > 0)) cs = std::max(W, H) / target;
  const i64 nx = cs > 0 ? (i64)std::min(4096.0, std::max(1.0, std::ceil(W / cs))) : 1;
  const i64 ny = cs > 0 ? (i64)std::min(4096.0, std::max(1.0, std::ceil(H / cs))) : 1;
  const double ix = W > 0 ? (double)nx / W : 0.0, iy = H > 0 ? (double)ny / H : 0.0;
  const double hy = H / (double)ny;
  // cell indices by floor, widened by DELTA cells (far above their rounding errors)
  constexpr double DELTA = 1e-6;
  auto cx_lo = [&](double x) {
    double t = std::floor((x - X0) * ix - DELTA);
    return t < 0 ? (i64)0 : (t >= (double)nx ? nx - 1 : (i64)t);
  };
  auto cx_hi = [&](double x) {
    double t = std::floor((x - X0) * ix + DELTA);
    return t < 0 ? (i64)0 : (t >= (double)nx ? nx - 1 : (i64)t);
  };
  auto cy_lo = [&](double y) {
    double t = std::floor((y - Y0) * iy - DELTA);
    return t < 0 ? (i64)0 : (t >= (double)ny ? ny - 1 : (i64)t);
  };
  auto cy_hi = [&](double y) {
    double t = std::floor((y - Y0) * iy + DELTA);
    return t < 0 ? (i64)0 : (t >= (double)ny ? ny - 1 : (i64)t);
  };
  // Memory: each segment is registered in the cells it crosses, about cols + rows of them.
  // Long segments over a fine grid (a star's convolution: n segments across the whole
  // sum) would need n * sqrt(n) registrations; beyond GRID_BUDGET the caller falls back
  // to the box scan, whose memory is O(n) (its work is bounded by the caller's limits).
  {
    double est = 0;
    for (i64 i = 0; i < n; ++i) {
      const double rows = (double)(cy_hi(y1[i]) - cy_lo(y0[i]) + 1);
      const double cols = (double)(cx_hi(x1[i]) - cx_lo(x0[i]) + 1);
      est += std::min(rows * cols, cols + 3 * rows);
      if (est > (double)GRID_BUDGET) return false;
    }
  }
  s.reg_start.assign(n + 1, 0);
  s.reg_cell.clear();
  for (i64 i = 0; i < n; ++i) {
    double px = ax[i], py = ay[i], qx = bx[i], qy = by[i];
    if (py > qy) {
      std::swap(px, qx);
      std::swap(py, qy);
    }
    const double M = std::max(std::max(std::fabs(px), std::fabs(qx)),
                              std::max(std::fabs(py), std::fabs(qy)));
    const double t = tol[i] + span_slack(M);
    const i64 r0 = cy_lo(py - t), r1 = cy_hi(qy + t);
    for (i64 r = r0; r <= r1; ++r) {
      double xl, xh;
      if (r0 == r1 || qy == py) {
        xl = std::min(px, qx);
        xh = std::max(px, qx);
      } else {
        // the part of the segment within the band (widened by t and a cell fraction)
        const double b0 = Y0 + (double)r * hy - t - hy * DELTA,
                     b1 = Y0 + (double)(r + 1) * hy + t + hy * DELTA;
        const double dy = qy - py;
        const double u0 = py < b0 ? (b0 - py) / dy : 0.0, u1 = qy > b1 ? (b1 - py) / dy : 1.0;
        const double xa = px + (qx - px) * std::min(std::max(u0, 0.0), 1.0),
                     xb = px + (qx - px) * std::min(std::max(u1, 0.0), 1.0);
        xl = std::min(xa, xb);
        xh = std::max(xa, xb);
      }
      const i64 c0 = cx_lo(xl - t), c1 = cx_hi(xh + t);
      for (i64 c = c0; c <= c1; ++c) s.reg_cell.push_back(r * nx + c);
    }
    s.reg_start[i + 1] = (i64)s.reg_cell.size();
  }
  grid_cells(n, nx * ny, s);  // cell -> segments, ascending
  s.stamp.assign(n, -1);
  double checks = 0, hits = 0;
  for (i64 i = 0; i < n; ++i) {
    if (resume && checks > 8 * (hits + (double)s.reg_start[i]) + 65536) {
      *resume = i;
      return false;
    }
    const int gi = group[i];
    for (i64 k = s.reg_start[i]; k < s.reg_start[i + 1]; ++k) {
      const i64 c = s.reg_cell[k];
      for (i64 q = s.cell_start[c]; q < s.cell_start[c + 1]; ++q) {
        const i64 j = s.cell_edge[q];
        if (j >= i) break;
        checks += 1;
        if (s.stamp[j] == i) continue;
        s.stamp[j] = i;
        if (gi >= 0 && group[j] == gi) continue;
        if (x1[j] < x0[i] || x1[i] < x0[j] || y1[j] < y0[i] || y1[i] < y0[j]) continue;
        hits += 1;
        if constexpr (std::is_same_v<decltype(on_pair(j, i)), bool>) {
          if (!on_pair(j, i)) return true;
        } else {
          on_pair(j, i);
        }
      }
    }
  }
  return true;
}

// Scratch of box_tree_pairs (reused: no allocation once grown).
struct TreeScratch {
  struct Node {
    double x0, x1, y0, y1;
    i64 first, count;  // leaves: items idx[first .. first + count); inner: child nodes
    bool leaf;
  };
  std::vector<Node> nodes;
  std::vector<i64> idx, tmp, stack;
  std::vector<double> key;
};

// Candidate pairs by a packed R-tree (sort-tile-recursive bulk load, GEOS's STRtree
// layout): on_pair(j, i), j < i, once for every pair of different groups (group -1: any)
// whose closed boxes overlap, for every i >= from (so it can finish what segment_pairs
// began). Output-sensitive where sweeps and grids are not: long thin boxes (the edges
// of nested squares) meet only the boxes they really overlap. on_pair may return false
// to stop; the result is then false.
template <class F>
inline bool box_tree_pairs(i64 n, const double* x0, const double* x1, const double* y0,
                           const double* y1, const int* group, i64 from, TreeScratch& s,
                           F&& on_pair) {
  using Node = TreeScratch::Node;
  constexpr i64 B = 8;
  s.nodes.clear();
  if (n < 2 || from >= n) return true;
  // leaves: slices by the x of the box centres, each sorted by y, runs of B
  s.idx.resize(n);
  std::iota(s.idx.begin(), s.idx.end(), 0);
  // centres (x, y); ties broken by the other coordinate, so that many boxes on one
  // centre line (the bars of nested squares) still tile it in order
  s.key.resize(2 * n);
  for (i64 i = 0; i < n; ++i) {
    s.key[2 * i] = x0[i] / 2 + x1[i] / 2;
    s.key[2 * i + 1] = y0[i] / 2 + y1[i] / 2;
  }
  std::sort(s.idx.begin(), s.idx.end(), [&](i64 a, i64 b) {
    const double xa = s.key[2 * a], xb = s.key[2 * b];
    return xa < xb || (xa == xb && s.key[2 * a + 1] < s.key[2 * b + 1]);
  });
  const i64 leaves = (n + B - 1) / B;
  const i64 slices = std::max<i64>(1, (i64)std::ceil(std::sqrt((double)leaves)));
  const i64 per = ((leaves + slices - 1) / slices) * B;
  for (i64 a = 0; a < n; a += per) {
    const i64 b = std::min(n, a + per);
    std::sort(s.idx.begin() + a, s.idx.begin() + b, [&](i64 p, i64 q) {
      const double yp = s.key[2 * p + 1], yq = s.key[2 * q + 1];
      return yp < yq || (yp == yq && s.key[2 * p] < s.key[2 * q]);
    });
  }
  for (i64 a = 0; a < n; a += B) {
    Node nd{INFINITY, -INFINITY, INFINITY, -INFINITY, a, std::min(B, n - a), true};
    for (i64 t = a; t < a + nd.count; ++t) {
      const i64 i = s.idx[t];
      nd.x0 = std::min(nd.x0, x0[i]);
      nd.x1 = std::max(nd.x1, x1[i]);
      nd.y0 = std::min(nd.y0, y0[i]);
      nd.y1 = std::max(nd.y1, y1[i]);
    }
    s.nodes.push_back(nd);
  }
  // inner levels: runs of B consecutive nodes (the leaves are in tile order)
  i64 lo = 0, hi = (i64)s.nodes.size();
  while (hi - lo > 1) {
    for (i64 a = lo; a < hi; a += B) {
      Node nd{INFINITY, -INFINITY, INFINITY, -INFINITY, a, std::min(B, hi - a), false};
      for (i64 t = a; t < a + nd.count; ++t) {
        const Node& c = s.nodes[t];
        nd.x0 = std::min(nd.x0, c.x0);
        nd.x1 = std::max(nd.x1, c.x1);
        nd.y0 = std::min(nd.y0, c.y0);
        nd.y1 = std::max(nd.y1, c.y1);
      }
      s.nodes.push_back(nd);
    }
    lo = hi;
    hi = (i64)s.nodes.size();
  }
  const i64 root = lo;
  for (i64 i = from; i < n; ++i) {
    const int gi = group[i];
    s.stack.clear();
    s.stack.push_back(root);
    while (!s.stack.empty()) {
      const Node& nd = s.nodes[s.stack.back()];
      s.stack.pop_back();
      if (nd.x1 < x0[i] || x1[i] < nd.x0 || nd.y1 < y0[i] || y1[i] < nd.y0) continue;
      if (!nd.leaf) {
        for (i64 t = nd.first; t < nd.first + nd.count; ++t) s.stack.push_back(t);
        continue;
      }
      for (i64 t = nd.first; t < nd.first + nd.count; ++t) {
        const i64 j = s.idx[t];
        if (j >= i) continue;
        if (gi >= 0 && group[j] == gi) continue;
        if (x1[j] < x0[i] || x1[i] < x0[j] || y1[j] < y0[i] || y1[i] < y0[j]) continue;
        if constexpr (std::is_same_v<decltype(on_pair(j, i)), bool>) {
          if (!on_pair(j, i)) return false;
        } else {
          on_pair(j, i);
        }
      }
    }
  }
  return true;
}

// The items of a uniform grid's cells (a CSR list): item it (of n) goes into every cell
// (c, r) with xa <= c <= xb, ya <= r <= yb, range(it, xa, xb, ya, yb) giving them; off
// has nx * ny + 1 entries, items the item ids cell after cell, in item order. The one
// bucketing of the uniform grids: the planner's and the mesh's (planning.hpp,
// navmesh_build.hpp), the union's containment index (union_index.hpp) and the offset's
// edge grid (offset.hpp).
template <class Range>
void grid_buckets(i64 n, i64 nx, i64 ny, Range&& range, std::vector<i64>& off,
                  std::vector<int>& items) {
  off.assign(nx * ny + 1, 0);
  for (i64 it = 0; it < n; ++it) {
    i64 xa, xb, ya, yb;
    range(it, xa, xb, ya, yb);
    for (i64 r = ya; r <= yb; ++r)
      for (i64 c = xa; c <= xb; ++c) off[r * nx + c + 1] += 1;
  }
  for (i64 c = 0; c < nx * ny; ++c) off[c + 1] += off[c];
  items.assign(off[nx * ny], 0);
  std::vector<i64> fill(off.begin(), off.end() - 1);
  for (i64 it = 0; it < n; ++it) {
    i64 xa, xb, ya, yb;
    range(it, xa, xb, ya, yb);
    for (i64 r = ya; r <= yb; ++r)
      for (i64 c = xa; c <= xb; ++c) items[fill[r * nx + c]++] = (int)it;
  }
}

}  // namespace mk
