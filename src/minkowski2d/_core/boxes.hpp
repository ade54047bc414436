// boxes.hpp -- pairs of overlapping axis-parallel boxes: sort by the left side, sweep an
// active list (dropping boxes whose right side is passed). O(n log n + n a) for an
// average of a boxes crossing a vertical line.
#pragma once

#include <algorithm>
#include <numeric>
#include <vector>

#include "exact.hpp"

namespace mk {

// Calls on_pair(i, j), i < j, for every pair of closed boxes that overlap.
template <class F>
inline void box_pairs(i64 n, const double* xmin, const double* xmax, const double* ymin,
                      const double* ymax, F&& on_pair) {
  std::vector<i64> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](i64 a, i64 b) { return xmin[a] < xmin[b]; });
  std::vector<i64> active;
  for (i64 t = 0; t < n; ++t) {
    const i64 i = order[t];
    const double x = xmin[i], y0 = ymin[i], y1 = ymax[i];
    std::size_t w = 0;
    for (std::size_t k = 0; k < active.size(); ++k) {
      const i64 j = active[k];
      if (xmax[j] < x) continue;
      active[w++] = j;
      if (ymin[j] <= y1 && y0 <= ymax[j]) on_pair(i < j ? i : j, i < j ? j : i);
    }
    active.resize(w);
    active.push_back(i);
  }
}

}  // namespace mk
