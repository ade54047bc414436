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
#include <numeric>
#include <type_traits>
#include <vector>

#include "exact.hpp"

namespace mk {

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
