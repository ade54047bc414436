// planning_queries.hpp -- what the planners' bindings (planning.cpp, navmesh.cpp) run: the
// scene read into a Planner, and the loops over many queries, points or segments, each
// with its scratch (the bindings only convert arrays and wrap the results).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "exact.hpp"
#include "planning.hpp"

namespace mk {

// The scene of a planner: n pieces (coords: 2 per vertex, off: n + 1 offsets into the
// vertices, grp: one group each), the box (4 numbers, or nbox != 4: none) and whether it
// is open.
template <class T>
inline void set_scene(Planner<T>& pl, const T* coords, std::size_t nv, const i64* off,
                      std::size_t noff, const i64* grp, std::size_t ngrp, const T* box,
                      std::size_t nbox, bool open_box) {
  pl.open_box = open_box;
  pl.pc.assign(coords, coords + 2 * nv);
  pl.poff.assign(off, off + noff);
  pl.pgrp.resize(ngrp);
  for (std::size_t i = 0; i < ngrp; ++i) pl.pgrp[i] = (int)grp[i];
  pl.has_box = nbox == 4;
  if (pl.has_box) {
    pl.bx0 = box[0];
    pl.by0 = box[1];
    pl.bx1 = box[2];
    pl.by1 = box[3];
  }
}

// The answers to n queries: status and group per query, the paths' points one after
// the other, query i's from off[i] to off[i + 1] (points).
template <class T>
struct PlanAnswers {
  std::vector<int> st, gr;
  std::vector<T> pts;
  std::vector<i64> off;
};

// Query i from (s[2i], s[2i+1]) to (g[2i], g[2i+1]) for every i < n, by
// query(sx, sy, gx, gy, out, grp) (a planner's query with its scratch).
template <class T, class Query>
inline void query_loop(const T* s, const T* g, std::size_t n, Query&& query, PlanAnswers<T>& A) {
  A.st.assign(n, 0);
  A.gr.assign(n, 0);
  A.pts.clear();
  A.off.assign(n + 1, 0);
  std::vector<T> out;
  for (std::size_t i = 0; i < n; ++i) {
    A.st[i] = query(s[2 * i], s[2 * i + 1], g[2 * i], g[2 * i + 1], out, A.gr[i]);
    A.pts.insert(A.pts.end(), out.begin(), out.end());
    A.off[i + 1] = (i64)A.pts.size() / 2;
  }
}

// The visibility graph's queries, one scratch for all.
template <class T>
inline void query_many(const Planner<T>& pl, const T* s, const T* g, std::size_t n,
                       PlanAnswers<T>& A) {
  PlanScratch S;
  S.init((std::size_t)pl.items());
  query_loop(s, g, n, [&](T sx, T sy, T gx, T gy, std::vector<T>& out, int& grp) {
    return pl.query(sx, sy, gx, gy, out, grp, S);
  }, A);
}

// One query of the visibility graph with its own scratch.
template <class T>
inline int query_one(const Planner<T>& pl, T sx, T sy, T gx, T gy, std::vector<T>& out,
                     int& grp) {
  PlanScratch S;
  S.init((std::size_t)pl.items());
  return pl.query(sx, sy, gx, gy, out, grp, S);
}

// Per point: -2 outside the box, g >= 0 inside group g's C-obstacle, -1 free.
template <class T>
inline void locate_points(const Planner<T>& pl, const T* p, std::size_t n, int* res) {
  PlanScratch S;
  S.init((std::size_t)pl.items());
  for (std::size_t i = 0; i < n; ++i) {
    T x = p[2 * i], y = p[2 * i + 1];
    res[i] = !pl.in_box(x, y) ? -2 : pl.interior_group(x, y, S);
  }
}

// Is the closed segment free (no point in a C-obstacle's open interior)?
template <class T>
inline bool segment_free(const Planner<T>& pl, T px, T py, T qx, T qy) {
  PlanScratch S;
  S.init((std::size_t)pl.items());
  return !pl.blocked(px, py, qx, qy, S);
}

}  // namespace mk
