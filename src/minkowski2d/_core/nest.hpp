// nest.hpp -- the nester's search: overlap minimisation on exact no-fit polygons.
//
// A layout is an assignment of every item (a copy of a part) to a bin, an orientation
// and a translation. Two items i, j in one bin overlap exactly when p_i - p_j lies in the
// interior of NFP(ot_j, ot_i) (the no-fit polygon of j's oriented shape, fixed at the
// origin, and i's, moving); their overlap is measured by the penetration depth, the
// distance from p_i - p_j to that polygon's boundary (the shortest translation that
// separates them). Whether a point lies strictly inside, on the boundary or outside is an
// exact sign (mk::cross_sign on the given doubles); translations live on a dyadic grid so
// that the difference p_i - p_j is itself exact. The depth is a measure, not a decision.
//
// The search follows the guided local search of the strip-packing literature (Egeblad et
// al. 2007; Umetani et al. 2009; Gardeyn & Wauters 2025): the container shrinks, the items
// that no longer fit are reinserted, and the separator moves colliding items one at a time
// to the position of least weighted overlap (samples over the container, near the item,
// and at the vertices of its no-fit polygons with its neighbours, refined by coordinate
// descent); the weights of pairs that stay in collision grow, which pushes the search out
// of local minima. A separation that ends without overlap is a feasible layout at the
// shorter length.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "exact.hpp"

namespace mk {
namespace nest {

// The problem, as the Python layer prepares it (nesting/nester.py).
struct Problem {
  int n_ot = 0;                 // oriented shapes
  std::vector<double> box;      // per ot: x0, y0, x1, y1 of the part (container test)
  std::vector<double> ref;      // per ot: a reference length (sqrt of the area)
  // the no-fit polygons, entry k = a * n_ot + b: NFP(ot a fixed, ot b moving), rings
  // nring[k] .. nring[k + 1] of ring_off, vertices in xy; nbox its bounding box
  std::vector<double> xy;
  std::vector<i64> ring_off, nring;
  std::vector<double> nbox;
  // a slab index per NFP entry: its box's height cut in SLABS bands, each band listing
  // the edges (a, b vertex indices into xy) whose height range meets it
  // (bands per entry: about one per two edges, from 4 to 256)
  std::vector<i64> slab_base;  // entry k's bands: slab_off[slab_base[k] + s]
  std::vector<int> slab_n;     // entry k's number of bands
  std::vector<i64> slab_off;   // band: edges slab_off[..] .. slab_off[.. + 1]
  std::vector<i64> slab_edge;  // pairs (a, b)
  int n_items = 0;
  std::vector<i64> ots, ots_off;  // allowed ots of item i: ots[ots_off[i] .. ots_off[i + 1]]
  std::vector<char> fixed;        // fixed items (obstacles, pre-placed parts) never move
  int n_bins = 0;
  std::vector<double> width, height;  // full size of each bin
  double margin = 0;                  // every part this far inside its bin's rectangle
  double grid = 0;                    // translations are multiples of grid
  bool int_vertices = false;          // touch only at NFP vertices with integer coordinates
};

// Build the slab index of every NFP entry.
inline void build_slabs(Problem& P) {
  const std::size_t K = P.nring.size() - 1;
  P.slab_base.assign(K, 0);
  P.slab_n.assign(K, 1);
  P.slab_off.assign(1, 0);
  P.slab_edge.clear();
  std::vector<std::vector<i64>> band;
  for (std::size_t k = 0; k < K; ++k) {
    const i64 e0 = P.ring_off[(std::size_t)P.nring[k]], e1 = P.ring_off[(std::size_t)P.nring[k + 1]];
    const int S = (int)std::max<i64>(4, std::min<i64>(256, (e1 - e0) / 2));
    P.slab_n[k] = S;
    P.slab_base[k] = (i64)P.slab_off.size() - 1;
    band.assign((std::size_t)S, {});
    const double y0 = P.nbox[4 * k + 1], y1 = P.nbox[4 * k + 3];
    const double h = (y1 - y0) / S;
    for (i64 r = P.nring[k]; r < P.nring[k + 1]; ++r) {
      const i64 lo = P.ring_off[(std::size_t)r], hi = P.ring_off[(std::size_t)r + 1];
      for (i64 a = lo, b = hi - 1; a < hi; b = a++) {
        double ya = P.xy[2 * (std::size_t)b + 1], yb = P.xy[2 * (std::size_t)a + 1];
        double lo_y = std::min(ya, yb), hi_y = std::max(ya, yb);
        int s0 = h > 0 ? (int)std::floor((lo_y - y0) / h) : 0;
        int s1 = h > 0 ? (int)std::floor((hi_y - y0) / h) : 0;
        s0 = std::max(0, std::min(S - 1, s0 - 1));  // one band of slack each way: the
        s1 = std::max(0, std::min(S - 1, s1 + 1));  // band of a height is found in floats
        for (int q = s0; q <= s1; ++q) {
          band[(std::size_t)q].push_back(b);
          band[(std::size_t)q].push_back(a);
        }
      }
    }
    for (int q = 0; q < S; ++q) {
      P.slab_edge.insert(P.slab_edge.end(), band[(std::size_t)q].begin(), band[(std::size_t)q].end());
      P.slab_off.push_back((i64)P.slab_edge.size() / 2);
    }
  }
}

struct State {
  std::vector<int> bin, ot;
  std::vector<double> x, y;
  std::vector<double> length;  // the current length limit of each bin (<= width)
  int bins_used = 1;           // items live in bins 0 .. bins_used - 1
};

struct Params {
  int container_samples = 50;
  int focus_samples = 25;
  int vertex_samples = 16;
  int refine_top = 3;
  int max_strikes = 3;
  int max_no_improve = 40;
  long long max_rounds = 4000;  // rounds of moves per separation (an iteration budget)
  double floor_rel = 0.02;
  double min_step_rel = 5e-4;  // coordinate descent stops below this step (x item size)   // a minimum penalty for any overlap, relative to the item size
  double weight_lo = 1.2, weight_hi = 2.0, weight_decay = 0.95;
};

using Clock = std::chrono::steady_clock;

class Search {
 public:
  Search(const Problem& pb, const Params& pr, std::uint64_t seed)
      : P(pb), prm(pr), rng(seed) {
    const int n = P.n_items;
    w.assign((std::size_t)n * n, 1.0);
    ov.assign((std::size_t)n * n, 0.0);
    row.assign((std::size_t)n, 0.0);
  }

  // ---- geometry -------------------------------------------------------------------

  double snap(double v) const {
    if (!(P.grid > 0)) return v;
    return std::nearbyint(v / P.grid) * P.grid;
  }

  // The translations that keep ot inside bin b of length L: [x0, x1] x [y0, y1].
  bool ifp(int ot, int b, double L, double& x0, double& y0, double& x1, double& y1) const {
    const double* bx = &P.box[4 * (std::size_t)ot];
    const double m = P.margin;
    x0 = m - bx[0];
    x1 = L - m - bx[2];
    y0 = m - bx[1];
    y1 = P.height[(std::size_t)b] - m - bx[3];
    // snapped inwards (the grid is far finer than any part)
    x0 = std::ceil(x0 / P.grid) * P.grid;
    y0 = std::ceil(y0 / P.grid) * P.grid;
    x1 = std::floor(x1 / P.grid) * P.grid;
    y1 = std::floor(y1 / P.grid) * P.grid;
    return x0 <= x1 && y0 <= y1;
  }

  // Penetration depth of t into NFP entry k: 0 unless t is strictly inside (exact sign).
  // The parity of the crossings of a ray to the right decides inside; only the edges of
  // t's band can meet the ray (the index keeps a band of slack on each side, so a band
  // found with a rounded division still holds every edge at t's height).
  double depth(i64 k, double tx, double ty) const {
    const double* nb = &P.nbox[4 * (std::size_t)k];
    if (!(tx > nb[0] && tx < nb[2] && ty > nb[1] && ty < nb[3])) return 0.0;
    const int S = P.slab_n[(std::size_t)k];
    const double h = (nb[3] - nb[1]) / S;
    int q = h > 0 ? (int)std::floor((ty - nb[1]) / h) : 0;
    q = std::max(0, std::min(S - 1, q));
    const std::size_t base = (std::size_t)P.slab_base[(std::size_t)k];
    const double* v = P.xy.data();
    const i64* E = P.slab_edge.data();
    bool inside = false;
    for (i64 e = P.slab_off[base + q]; e < P.slab_off[base + q + 1]; ++e) {
      const i64 ia = E[2 * e], ib = E[2 * e + 1];
      const double ax = v[2 * ia], ay = v[2 * ia + 1], bx = v[2 * ib], by = v[2 * ib + 1];
      if ((ay > ty) == (by > ty)) {  // no crossing; on the edge only when it is level
        if (ay == ty && by == ty && tx >= std::min(ax, bx) && tx <= std::max(ax, bx))
          return 0.0;
        if ((ay == ty && ax == tx) || (by == ty && bx == tx)) return 0.0;
        continue;
      }
      if (tx > std::max(ax, bx)) continue;  // the edge is left of t: no crossing, not on it
      const int o = mk::orient(ax, ay, bx, by, tx, ty);
      if (o == 0) return 0.0;  // strictly between the endpoints' heights: on the edge
      // half-open rule: an upward edge counts when t is to its left
      if ((by > ay) == (o > 0)) inside = !inside;
    }
    if (!inside) return 0.0;
    // the nearest edge: bands outwards from t's, until a band is farther than the best
    double best = std::numeric_limits<double>::infinity();
    auto scan = [&](int b) {
      for (i64 e = P.slab_off[base + b]; e < P.slab_off[base + b + 1]; ++e) {
        const i64 ia = E[2 * e], ib = E[2 * e + 1];
        const double ax = v[2 * ia], ay = v[2 * ia + 1];
        const double ex = v[2 * ib] - ax, ey = v[2 * ib + 1] - ay;
        const double px = tx - ax, py = ty - ay;
        const double ee = ex * ex + ey * ey;
        double u = ee > 0 ? (px * ex + py * ey) / ee : 0.0;
        u = u < 0 ? 0 : (u > 1 ? 1 : u);
        const double dx = px - u * ex, dy = py - u * ey;
        best = std::min(best, dx * dx + dy * dy);
      }
    };
    scan(q);
    for (int d = 1; d < S; ++d) {
      // bands q +- d lie at least (d - 2) * h away (one band of slack in the index)
      const double gap = (d - 2) * h;
      if (gap > 0 && gap * gap > best) break;
      if (q - d >= 0) scan(q - d);
      if (q + d < S) scan(q + d);
    }
    return std::sqrt(best);
  }

  // Overlap measure of item i (ot, at x, y) with item j as it stands.
  double pair_cost(int i, int ot, double x, double y, int j) const {
    const int oj = S.ot[(std::size_t)j];
    const i64 k = (i64)oj * P.n_ot + ot;
    double d = depth(k, x - S.x[(std::size_t)j], y - S.y[(std::size_t)j]);
    if (d <= 0) return 0.0;
    const double rmin = std::min(P.ref[(std::size_t)ot], P.ref[(std::size_t)oj]);
    (void)i;
    return (d + prm.floor_rel * rmin) * rmin;
  }

  // Weighted overlap of item i placed at (b, ot, x, y) with every other item of bin b;
  // stops early once above `cap`.
  double eval(int i, int b, int ot, double x, double y, double cap) const {
    double sum = 0;
    const int n = P.n_items;
    const double* bx = &P.box[4 * (std::size_t)ot];
    const double ix0 = x + bx[0], iy0 = y + bx[1], ix1 = x + bx[2], iy1 = y + bx[3];
    for (int j = 0; j < n; ++j) {
      if (j == i || S.bin[(std::size_t)j] != b) continue;
      const double* jb = &P.box[4 * (std::size_t)S.ot[(std::size_t)j]];
      const double jx = S.x[(std::size_t)j], jy = S.y[(std::size_t)j];
      // the NFP's box decides; this is only a quick reject with slack for the spacing
      if (ix1 + pad < jx + jb[0] || jx + jb[2] + pad < ix0 || iy1 + pad < jy + jb[1] ||
          jy + jb[3] + pad < iy0)
        continue;
      const double c = pair_cost(i, ot, x, y, j);
      if (c > 0) {
        sum += c * w[(std::size_t)i * n + j];
        if (sum > cap) return sum;
      }
    }
    return sum;
  }

  void set_pad() {
    // the NFPs may be larger than the parts' boxes (spacing): the widest gap between an
    // NFP's box and the difference of the two parts' boxes bounds the slack needed
    pad = 0;
    for (int a = 0; a < P.n_ot; ++a)
      for (int b = 0; b < P.n_ot; ++b) {
        const i64 k = (i64)a * P.n_ot + b;
        if (P.nring[(std::size_t)k] == P.nring[(std::size_t)k + 1]) continue;
        const double* nb = &P.nbox[4 * (std::size_t)k];
        const double* A = &P.box[4 * (std::size_t)a];
        const double* B = &P.box[4 * (std::size_t)b];
        // t = p_b - p_a overlaps when t in (A0 - B1, A1 - B0)
        pad = std::max(pad, std::max(A[0] - B[2] - nb[0], nb[2] - (A[2] - B[0])));
        pad = std::max(pad, std::max(A[1] - B[3] - nb[1], nb[3] - (A[3] - B[1])));
      }
    pad = std::max(0.0, pad) * (1 + 1e-9) + P.grid;
  }

  // ---- state bookkeeping ----------------------------------------------------------

  void recompute() {
    const int n = P.n_items;
    std::fill(ov.begin(), ov.end(), 0.0);
    std::fill(row.begin(), row.end(), 0.0);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        if (i == j || S.bin[(std::size_t)i] != S.bin[(std::size_t)j]) continue;
        if (P.fixed[(std::size_t)i] || S.bin[(std::size_t)i] < 0) continue;  // rows stay 0
        double c = pair_cost(i, S.ot[(std::size_t)i], S.x[(std::size_t)i],
                             S.y[(std::size_t)i], j);
        ov[(std::size_t)i * n + j] = c;
      }
    // symmetric: the overlap of a pair is the larger of its two measures
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        double c = std::max(ov[(std::size_t)i * n + j], ov[(std::size_t)j * n + i]);
        ov[(std::size_t)i * n + j] = ov[(std::size_t)j * n + i] = c;
      }
    for (int i = 0; i < n; ++i) {
      double s = 0;
      for (int j = 0; j < n; ++j) s += ov[(std::size_t)i * n + j];
      row[(std::size_t)i] = s;
    }
  }

  void update_item(int i) {
    const int n = P.n_items;
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      double c = 0;
      if (S.bin[(std::size_t)i] == S.bin[(std::size_t)j] && S.bin[(std::size_t)j] >= 0) {
        c = pair_cost(i, S.ot[(std::size_t)i], S.x[(std::size_t)i], S.y[(std::size_t)i], j);
        if (!P.fixed[(std::size_t)j])
          c = std::max(c, pair_cost(j, S.ot[(std::size_t)j], S.x[(std::size_t)j],
                                    S.y[(std::size_t)j], i));
      }
      double old = ov[(std::size_t)i * n + j];
      ov[(std::size_t)i * n + j] = ov[(std::size_t)j * n + i] = c;
      row[(std::size_t)j] += c - old;
    }
    double s = 0;
    for (int j = 0; j < n; ++j) s += ov[(std::size_t)i * n + j];
    row[(std::size_t)i] = s;
  }

  double total() const {
    double s = 0;
    for (int i = 0; i < P.n_items; ++i) s += row[(std::size_t)i];
    return s / 2;
  }

  bool colliding(int i) const { return row[(std::size_t)i] > 0; }

  // ---- moves ----------------------------------------------------------------------

  struct Cand {
    int b, ot;
    double x, y, cost;
  };

  double uni(double a, double b) {
    return a + (b - a) * std::uniform_real_distribution<double>(0.0, 1.0)(rng);
  }
  int pick(int n) { return (int)std::uniform_int_distribution<int>(0, n - 1)(rng); }

  void consider(int i, Cand c, std::vector<Cand>& top) {
    c.x = snap(c.x);
    c.y = snap(c.y);
    double cap = top.size() < (std::size_t)prm.refine_top ? std::numeric_limits<double>::infinity()
                                                          : top.back().cost;
    c.cost = eval(i, c.b, c.ot, c.x, c.y, cap);
    if (c.cost >= cap) return;
    top.push_back(c);
    std::sort(top.begin(), top.end(), [](const Cand& a, const Cand& b) { return a.cost < b.cost; });
    if (top.size() > (std::size_t)prm.refine_top) top.pop_back();
  }

  bool clamp_into(int ot, int b, double& x, double& y) const {
    double x0, y0, x1, y1;
    if (!ifp(ot, b, S.length[(std::size_t)b], x0, y0, x1, y1)) return false;
    x = std::min(std::max(x, x0), x1);
    y = std::min(std::max(y, y0), y1);
    return true;
  }

  // Item i to bin b at (x, y) clamped into its inner-fit rectangle (on the grid); when
  // its orientation does not fit the bin at all, the first allowed one that does.
  void put_clamped(int i, int b, double x, double y) {
    S.bin[(std::size_t)i] = b;
    if (!clamp_into(S.ot[(std::size_t)i], b, x, y)) {
      for (i64 q = P.ots_off[(std::size_t)i]; q < P.ots_off[(std::size_t)i + 1]; ++q)
        if (clamp_into((int)P.ots[(std::size_t)q], b, x, y)) {
          S.ot[(std::size_t)i] = (int)P.ots[(std::size_t)q];
          break;
        }
    }
    S.x[(std::size_t)i] = snap(x);
    S.y[(std::size_t)i] = snap(y);
  }

  // A random touching translation of an item in orientation ot against item j: j's
  // translation plus a vertex of NFP(ot_j, ot) that may be touched (exact_vertex).
  bool nfp_vertex(int j, int ot, double& x, double& y) {
    const i64 k = (i64)S.ot[(std::size_t)j] * P.n_ot + ot;
    const i64 r0 = P.nring[(std::size_t)k], r1 = P.nring[(std::size_t)k + 1];
    if (r0 == r1) return false;
    const i64 v0 = P.ring_off[(std::size_t)r0], v1 = P.ring_off[(std::size_t)r1];
    const i64 v = v0 + pick((int)(v1 - v0));
    if (!exact_vertex(v)) return false;
    x = S.x[(std::size_t)j] + P.xy[2 * (std::size_t)v];
    y = S.y[(std::size_t)j] + P.xy[2 * (std::size_t)v + 1];
    return true;
  }

  // Coordinate descent from c: each step tries both ways along one axis (horizontal,
  // vertical or a diagonal), keeps the better when it is no worse, grows that axis's step
  // on success, halves it and draws another axis on failure; stops when both steps are
  // below the limit.
  void refine(int i, Cand& c) {
    const double r = P.ref[(std::size_t)c.ot];
    double sx = 0.25 * r, sy = 0.25 * r;
    const double limit = std::max(prm.min_step_rel * r, 4 * P.grid);
    int axis = pick(4);
    for (int guard = 0; (sx >= limit || sy >= limit) && c.cost > 0 && guard < 400; ++guard) {
      const double ux = axis == 1 ? 0.0 : sx, uy = axis == 0 ? 0.0 : (axis == 3 ? -sy : sy);
      Cand best = c;
      bool moved = false;
      for (int sgn = -1; sgn <= 1; sgn += 2) {
        double x = c.x + sgn * ux, y = c.y + sgn * uy;
        if (!clamp_into(c.ot, c.b, x, y)) continue;
        x = snap(x);
        y = snap(y);
        if (x == c.x && y == c.y) continue;
        double cost = eval(i, c.b, c.ot, x, y, best.cost);
        if (cost <= best.cost) {
          if (cost < best.cost || !moved) best = Cand{c.b, c.ot, x, y, cost};
          moved = true;
        }
      }
      const bool better = best.cost < c.cost;
      if (moved) c = best;
      const double m = better ? 1.1 : 0.5;
      if (axis == 0) sx *= m;
      else if (axis == 1) sy *= m;
      else {
        sx *= std::sqrt(m);
        sy *= std::sqrt(m);
      }
      if (!better) axis = pick(4);
    }
  }

  // Move item i to the least weighted overlap position found.
  void move_item(int i, bool global_only = false) {
    const int b_now = S.bin[(std::size_t)i];
    const i64 o0 = P.ots_off[(std::size_t)i], o1 = P.ots_off[(std::size_t)i + 1];
    const int nots = (int)(o1 - o0);
    std::vector<Cand> top;
    top.reserve(prm.refine_top + 1);
    if (!global_only) {
      double x = S.x[(std::size_t)i], y = S.y[(std::size_t)i];
      if (clamp_into(S.ot[(std::size_t)i], b_now, x, y))
        consider(i, Cand{b_now, S.ot[(std::size_t)i], x, y, 0}, top);
    }
    // samples over the container (any open bin)
    for (int s = 0; s < prm.container_samples; ++s) {
      int ot = (int)P.ots[(std::size_t)(o0 + pick(nots))];
      int b = S.bins_used > 1 ? pick(S.bins_used) : 0;
      double x0, y0, x1, y1;
      if (!ifp(ot, b, S.length[(std::size_t)b], x0, y0, x1, y1)) continue;
      consider(i, Cand{b, ot, uni(x0, x1), uni(y0, y1), 0}, top);
    }
    // samples near the item
    if (!global_only) {
      const double r = P.ref[(std::size_t)S.ot[(std::size_t)i]];
      for (int s = 0; s < prm.focus_samples; ++s) {
        int ot = (s % 3 == 0) ? (int)P.ots[(std::size_t)(o0 + pick(nots))]
                              : S.ot[(std::size_t)i];
        double x = S.x[(std::size_t)i] + uni(-r, r) * 0.5;
        double y = S.y[(std::size_t)i] + uni(-r, r) * 0.5;
        if (!clamp_into(ot, b_now, x, y)) continue;
        consider(i, Cand{b_now, ot, x, y, 0}, top);
      }
    }
    // samples at the vertices of NFPs with neighbours (touching placements)
    for (int s = 0; s < prm.vertex_samples; ++s) {
      int j = pick(P.n_items);
      if (j == i) continue;
      int b = S.bin[(std::size_t)j];
      if (b >= S.bins_used) continue;
      int ot = (int)P.ots[(std::size_t)(o0 + pick(nots))];
      double x, y;
      if (!nfp_vertex(j, ot, x, y)) continue;
      double x0, y0, x1, y1;
      if (!ifp(ot, b, S.length[(std::size_t)b], x0, y0, x1, y1)) continue;
      if (x < x0 || x > x1 || y < y0 || y > y1) continue;
      consider(i, Cand{b, ot, x, y, 0}, top);
    }
    if (top.empty()) return;
    for (auto& c : top) refine(i, c);
    std::sort(top.begin(), top.end(), [](const Cand& a, const Cand& b) { return a.cost < b.cost; });
    const Cand& c = top.front();
    S.bin[(std::size_t)i] = c.b;
    S.ot[(std::size_t)i] = c.ot;
    S.x[(std::size_t)i] = c.x;
    S.y[(std::size_t)i] = c.y;
    update_item(i);
  }

  void update_weights() {
    const int n = P.n_items;
    double mx = 0;
    for (double c : ov) mx = std::max(mx, c);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        double& wij = w[(std::size_t)i * n + j];
        double c = ov[(std::size_t)i * n + j];
        if (c > 0)
          wij *= prm.weight_lo + (prm.weight_hi - prm.weight_lo) * (c / mx);
        else
          wij = std::max(1.0, wij * prm.weight_decay);
      }
  }

  // Separate the current state (no overlap); true on success. Leaves the least
  // overlapping state found in S.
  bool separate(Clock::time_point deadline) {
    std::fill(w.begin(), w.end(), 1.0);
    recompute();
    double best = total();
    if (best == 0) return true;
    State best_s = S;
    std::vector<int> order;
    long long rounds = 0;
    for (int strike = 0; strike < prm.max_strikes; ++strike) {
      int no_imp = 0;
      bool improved_in_strike = false;
      while (no_imp < prm.max_no_improve) {
        if (++rounds > prm.max_rounds || Clock::now() > deadline) {
          S = best_s;
          recompute();
          return false;
        }
        order.clear();
        for (int i = 0; i < P.n_items; ++i)
          if (!P.fixed[(std::size_t)i] && colliding(i)) order.push_back(i);
        std::shuffle(order.begin(), order.end(), rng);
        for (int i : order)
          if (colliding(i)) move_item(i);
        ++moves;
        double t = total();
        if (t == 0) return true;
        if (t < best) {
          best = t;
          best_s = S;
          no_imp = 0;
          improved_in_strike = true;
        } else {
          ++no_imp;
        }
        update_weights();
      }
      S = best_s;
      recompute();
      if (improved_in_strike) strike = std::max(-1, strike - 1);
    }
    return false;
  }

  // Shrink bin b's length to L and move the items that no longer fit back in.
  void shrink_to(int b, double L) {
    S.length[(std::size_t)b] = L;
    recompute();
    for (int i = 0; i < P.n_items; ++i) {
      if (P.fixed[(std::size_t)i] || S.bin[(std::size_t)i] != b) continue;
      double x = S.x[(std::size_t)i], y = S.y[(std::size_t)i];
      double x0, y0, x1, y1;
      bool ok = ifp(S.ot[(std::size_t)i], b, L, x0, y0, x1, y1);
      if (ok && x >= x0 && x <= x1 && y >= y0 && y <= y1) continue;
      // cross the new edge: reinserted at the best place found
      move_item(i, true);
      if (S.bin[(std::size_t)i] == b) {
        put_clamped(i, b, S.x[(std::size_t)i], S.y[(std::size_t)i]);
        update_item(i);
      }
    }
  }

  // A vertex the search may touch at: with int_vertices, one with integer coordinates
  // (a sum of two vertices, exact; a crossing of two edges is rounded).
  bool exact_vertex(i64 v) const {
    if (!P.int_vertices) return true;
    const double x = P.xy[2 * (std::size_t)v], y = P.xy[2 * (std::size_t)v + 1];
    return x == std::nearbyint(x) && y == std::nearbyint(y);
  }

  // ---- construction -------------------------------------------------------------

  // Left-bottom cost of item i at (b, ot, x, y): where its box ends on the right, then
  // its height; infinite when it overlaps a placed item (exact test on the NFPs).
  double lbf_cost(int i, int b, int ot, double x, double y) const {
    if (eval(i, b, ot, x, y, 0.0) > 0) return std::numeric_limits<double>::infinity();
    const double* bx = &P.box[4 * (std::size_t)ot];
    return (x + bx[2]) + 1e-3 * (y + bx[1]);
  }

  // Place item i (not placed yet: bin -1) on the first bin, from `first`, where a
  // sampled free position is found, at the free position that ends furthest left
  // (samples over the bin, at the vertices of NFPs with the placed items, and the
  // corner right of everything), refined by coordinate descent. False when no bin has
  // room that the samples find.
  bool insert_lbf(int i, int first, int samples) {
    const i64 o0 = P.ots_off[(std::size_t)i], o1 = P.ots_off[(std::size_t)i + 1];
    const int nots = (int)(o1 - o0);
    for (int b = first; b < P.n_bins; ++b) {
      Cand best{b, -1, 0, 0, std::numeric_limits<double>::infinity()};
      auto try_at = [&](int ot, double x, double y) {
        double x0, y0, x1, y1;
        if (!ifp(ot, b, S.length[(std::size_t)b], x0, y0, x1, y1)) return;
        x = snap(std::min(std::max(x, x0), x1));
        y = snap(std::min(std::max(y, y0), y1));
        // cheap bound first: a candidate that ends further right cannot win
        const double* bx = &P.box[4 * (std::size_t)ot];
        if ((x + bx[2]) + 1e-3 * (y + bx[1]) >= best.cost) return;
        double c = lbf_cost(i, b, ot, x, y);
        if (c < best.cost) best = Cand{b, ot, x, y, c};
      };
      // right of everything placed in this bin
      double frontier = 0;
      for (int j = 0; j < P.n_items; ++j)
        if (S.bin[(std::size_t)j] == b)
          frontier = std::max(frontier, S.x[(std::size_t)j] + P.box[4 * (std::size_t)S.ot[(std::size_t)j] + 2]);
      for (int q = 0; q < nots; ++q) {
        int ot = (int)P.ots[(std::size_t)(o0 + q)];
        const double* bx = &P.box[4 * (std::size_t)ot];
        try_at(ot, frontier - bx[0] + pad, -1e300);
        try_at(ot, -1e300, -1e300);
      }
      for (int s = 0; s < samples; ++s) {
        int ot = (int)P.ots[(std::size_t)(o0 + pick(nots))];
        double x0, y0, x1, y1;
        if (!ifp(ot, b, std::min(S.length[(std::size_t)b], frontier + 2 * P.ref[(std::size_t)ot] + P.box[4 * (std::size_t)ot + 2] - P.box[4 * (std::size_t)ot]), x0, y0, x1, y1)) continue;
        if (s % 2 == 0) {
          try_at(ot, uni(x0, x1), uni(y0, y1));
          continue;
        }
        // a vertex of the NFP with a placed item of this bin
        int j = pick(P.n_items);
        if (S.bin[(std::size_t)j] != b) continue;
        double x, y;
        if (nfp_vertex(j, ot, x, y)) try_at(ot, x, y);
      }
      if (best.ot < 0) continue;
      // coordinate descent on the left-bottom cost (moves left and down until blocked)
      double step = 0.25 * P.ref[(std::size_t)best.ot];
      const double limit = std::max(prm.min_step_rel * P.ref[(std::size_t)best.ot], 4 * P.grid);
      static const int DX[4] = {-1, 0, -1, 1}, DY[4] = {0, -1, -1, -1};
      while (step >= limit) {
        bool moved = false;
        for (int d = 0; d < 4; ++d) {
          Cand c = best;
          double x = c.x + DX[d] * step, y = c.y + DY[d] * step;
          if (!clamp_into(c.ot, b, x, y)) continue;
          x = snap(x);
          y = snap(y);
          double cost = lbf_cost(i, b, c.ot, x, y);
          if (cost < best.cost) {
            best = Cand{b, c.ot, x, y, cost};
            moved = true;
          }
        }
        if (!moved) step *= 0.5;
      }
      S.bin[(std::size_t)i] = b;
      S.ot[(std::size_t)i] = best.ot;
      S.x[(std::size_t)i] = best.x;
      S.y[(std::size_t)i] = best.y;
      return true;
    }
    return false;
  }

  // Disrupt a layout: swap the places of two large items (different parts), each in an
  // orientation that fits there.
  void disrupt() {
    std::vector<int> mov;
    for (int i = 0; i < P.n_items; ++i)
      if (!P.fixed[(std::size_t)i] && S.bin[(std::size_t)i] >= 0) mov.push_back(i);
    if (mov.size() < 2) return;
    // large: the items whose size is in the top three quarters of the total
    std::vector<int> by = mov;
    std::sort(by.begin(), by.end(), [&](int a, int b) {
      return P.ref[(std::size_t)S.ot[(std::size_t)a]] > P.ref[(std::size_t)S.ot[(std::size_t)b]];
    });
    double tot = 0, acc = 0;
    for (int i : by) tot += sq(P.ref[(std::size_t)S.ot[(std::size_t)i]]);
    std::size_t cut = 0;
    while (cut < by.size() && acc <= 0.75 * tot) acc += sq(P.ref[(std::size_t)S.ot[(std::size_t)by[cut++]]]);
    cut = std::max<std::size_t>(cut, 2);
    int a = by[(std::size_t)pick((int)cut)];
    int b = -1;
    for (int tries = 0; tries < 16 && b < 0; ++tries) {
      int c = by[(std::size_t)pick((int)cut)];
      double ra = P.ref[(std::size_t)S.ot[(std::size_t)a]], rc = P.ref[(std::size_t)S.ot[(std::size_t)c]];
      if (c != a && std::fabs(ra - rc) > 0.01 * ra) b = c;
    }
    if (b < 0) {
      b = mov[(std::size_t)pick((int)mov.size())];
      if (b == a) return;
    }
    // swap reference corners: each item's box centre goes where the other's was
    auto centre = [&](int i, double& cx, double& cy) {
      const double* bx = &P.box[4 * (std::size_t)S.ot[(std::size_t)i]];
      cx = S.x[(std::size_t)i] + 0.5 * (bx[0] + bx[2]);
      cy = S.y[(std::size_t)i] + 0.5 * (bx[1] + bx[3]);
    };
    double ax, ay, bx_, by_;
    centre(a, ax, ay);
    centre(b, bx_, by_);
    const int ba = S.bin[(std::size_t)a], bb = S.bin[(std::size_t)b];
    auto put = [&](int i, int bin, double cx, double cy) {
      const double* bx = &P.box[4 * (std::size_t)S.ot[(std::size_t)i]];
      put_clamped(i, bin, cx - 0.5 * (bx[0] + bx[2]), cy - 0.5 * (bx[1] + bx[3]));
    };
    put(a, bb, bx_, by_);
    put(b, ba, ax, ay);
  }

  static double sq(double v) { return v * v; }

  // Close the last bin: its items go to the other open bins.
  void close_last() {
    int b = S.bins_used - 1;
    S.bins_used = b;
    recompute();
    for (int i = 0; i < P.n_items; ++i)
      if (!P.fixed[(std::size_t)i] && S.bin[(std::size_t)i] == b) move_item(i, true);
  }

  const Problem& P;
  Params prm;
  std::mt19937_64 rng;
  State S;
  std::vector<double> w, ov, row;
  double pad = 0;
  long long moves = 0;
};

}  // namespace nest
}  // namespace mk
