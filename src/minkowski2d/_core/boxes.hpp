// boxes.hpp -- pairs of overlapping axis-parallel boxes: sort by the left side, sweep an
// active list (dropping boxes whose right side is passed). O(n log n + n a) for an
// average of a boxes crossing a vertical line.
#pragma once

#include <algorithm>
#include <numeric>
#include <type_traits>
#include <vector>

#include "exact.hpp"

namespace mk {

// Calls on_pair(i, j), i < j, for every pair of closed boxes that overlap. An on_pair
// that returns bool stops the sweep by returning false (box_pairs then returns false).
template <class F>
inline bool box_pairs(i64 n, const double* xmin, const double* xmax, const double* ymin,
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
      if (ymin[j] <= y1 && y0 <= ymax[j]) {
        if constexpr (std::is_same_v<decltype(on_pair(i, j)), bool>) {
          if (!on_pair(i < j ? i : j, i < j ? j : i)) return false;
        } else {
          on_pair(i < j ? i : j, i < j ? j : i);
        }
      }
    }
    active.resize(w);
    active.push_back(i);
  }
  return true;
}

}  // namespace mk

namespace mk {

// Scratch of box_pairs_grouped, reusable across calls (no allocation once grown).
struct BoxScratch {
  std::vector<i64> order;
  std::vector<std::vector<i64>> active;
};

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
