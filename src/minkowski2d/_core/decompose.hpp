// decompose.hpp -- Hertel-Mehlhorn convex decomposition of a triangulated polygon.
//
// Called by minkowski2d._engine.decompose (turn, convex_at, find, orient_triangles,
// hertel_mehlhorn). Vertices are an (n, 2)
// row-major array of T (finite double, or int64 with |x| < 2^62); triangles are (T, 3)
// int64 vertex ids. Every turn -- and the one dot-product sign -- goes through
// mk::cross_sign, exact at every magnitude (subnormals to DBL_MAX): no range check, no
// rescaling, so no piece is lost to an underflowing product. The callers (decompose.cpp)
// check ids and twins before these kernels index with them.
#pragma once

#include <cstdint>
#include <vector>

#include "exact.hpp"

namespace mk {
namespace decompose {

// True when the path i -> j -> k turns left or goes straight on at j.
template <class T>
inline bool convex_at(const T* p, i64 i, i64 j, i64 k) {
  int s = orient(p, i, j, k);
  if (s > 0) return true;
  if (s < 0) return false;
  // collinear: straight on (not a spike folding back), i.e. (j - i) . (k - j) > 0. The dot
  // product is the cross product of (j - i) turned clockwise, (dy, -dx), with (k - j);
  // negation is exact, so the sign is exact at every magnitude (a float dot product
  // underflows to 0 -- "folds back" -- for tiny coordinates).
  return cross_sign(p[2 * i + 1], -p[2 * i], p[2 * j + 1], -p[2 * j], p[2 * j], p[2 * j + 1],
                    p[2 * k], p[2 * k + 1]) > 0;
}

inline i64 find(i64* parent, i64 a) {
  while (parent[a] != a) {
    parent[a] = parent[parent[a]];
    a = parent[a];
  }
  return a;
}

// Make each triangle counter-clockwise (in place); keep[t] = 0 for the degenerate ones.
template <class T>
inline void orient_triangles(const T* p, i64* ids, i64 ntri, bool* keep) {
  for (i64 t = 0; t < ntri; ++t) {
    int s = orient(p, ids[3 * t], ids[3 * t + 1], ids[3 * t + 2]);
    keep[t] = s != 0;
    if (s < 0) {
      i64 tmp = ids[3 * t + 1];
      ids[3 * t + 1] = ids[3 * t + 2];
      ids[3 * t + 2] = tmp;
    }
  }
}

// Merge CCW triangles into convex pieces. twin[h] is the opposite half-edge of half-edge
// h = 3 t + k (from ids[t, k] to ids[t, k + 1]) or -1 on the boundary. With merge false
// the triangles come back as they are. Writes the pieces' vertex ids into out (size >= 3T)
// and the offsets into off (size >= T + 1); returns the number of pieces. Each piece is
// counter-clockwise from its bottom-most vertex (lowest y, then x), without collinear
// vertices.
template <class T>
inline i64 hertel_mehlhorn(const T* p, const i64* ids, i64 ntri, const i64* twin, bool merge,
                           i64* out, i64* off) {
  const i64 H = 3 * ntri;
  std::vector<i64> nxt(H), prv(H), org(H), parent(ntri);
  std::vector<std::uint8_t> alive(H, 1);
  for (i64 t = 0; t < ntri; ++t) {
    parent[t] = t;
    for (i64 k = 0; k < 3; ++k) {
      i64 h = 3 * t + k;
      org[h] = ids[3 * t + k];
      nxt[h] = 3 * t + (k + 1) % 3;
      prv[h] = 3 * t + (k + 2) % 3;
    }
  }
  // The order of the merges (a heuristic: any order gives convex pieces). Diagonals with
  // no reflex end first, then one, then two: a reflex vertex can absorb only so much
  // turning, better spent where it is needed. And two passes: first only the merges that
  // leave both ends strictly convex, then those that leave them straight. Over the 609
  // ESICUP parts (Delaunay-flipped triangles) this gives 13 744 pieces, one pass in
  // index order 13 867 (GEOS's triangles in index order: 13 722); the L-shape fanned from
  // its reflex corner gives 2 pieces, not 3.
  std::vector<i64> order;
  if (merge) {
    i64 nv = 0;
    for (i64 h = 0; h < H; ++h) nv = org[h] + 1 > nv ? org[h] + 1 : nv;
    // reflex polygon vertices: a boundary edge in and out whose turn is to the right
    // (where the boundary passes a vertex more than once, it counts as reflex)
    std::vector<i64> bin(nv, -1), bout(nv, -1);
    std::vector<std::uint8_t> reflex(nv, 0);
    for (i64 h = 0; h < H; ++h) {
      if (twin[h] >= 0) continue;
      i64 u = org[h], v = org[nxt[h]];
      if (bout[u] != -1) reflex[u] = 1;
      bout[u] = v;
      if (bin[v] != -1) reflex[v] = 1;
      bin[v] = u;
    }
    for (i64 v = 0; v < nv; ++v)
      if (bin[v] >= 0 && bout[v] >= 0 && !reflex[v]) reflex[v] = orient(p, bin[v], v, bout[v]) < 0;
    for (int want = 0; want <= 2; ++want)
      for (i64 h = 0; h < H; ++h)
        if (twin[h] > h && reflex[org[h]] + reflex[org[twin[h]]] == want) order.push_back(h);
  }
  for (int pass = merge ? 0 : 2; pass < 2; ++pass) {
    const bool strict = pass == 0;
    for (i64 h : order) {
      i64 t = twin[h];
      if (t < h || !alive[h]) continue;  // boundary edge, seen from the other side, gone
      i64 fa = find(parent.data(), h / 3);
      i64 fb = find(parent.data(), t / 3);
      if (fa == fb) continue;
      i64 pn = prv[h], nn = nxt[h], tp = prv[t], tn = nxt[t];
      i64 u = org[h], v = org[t];
      // at u the merged face runs origin(pn) -> u -> dest(tn) = origin(next(tn))
      if (strict) {
        if (orient(p, org[pn], u, org[nxt[tn]]) <= 0) continue;
        if (orient(p, org[tp], v, org[nxt[nn]]) <= 0) continue;
      } else {
        if (!convex_at(p, org[pn], u, org[nxt[tn]])) continue;
        if (!convex_at(p, org[tp], v, org[nxt[nn]])) continue;
      }
      nxt[pn] = tn;
      prv[tn] = pn;
      nxt[tp] = nn;
      prv[nn] = tp;
      alive[h] = 0;
      alive[t] = 0;
      parent[fb] = fa;
    }
  }
  // walk the faces
  std::vector<std::uint8_t> seen(H, 0);
  std::vector<i64> buf(H > 0 ? H : 1);
  i64 P = 0, n_out = 0;
  off[0] = 0;
  for (i64 h0 = 0; h0 < H; ++h0) {
    if (!alive[h0] || seen[h0]) continue;
    i64 m = 0, h = h0;
    while (true) {
      seen[h] = 1;
      buf[m++] = org[h];
      h = nxt[h];
      if (h == h0 || m == H) break;  // m == H only on a corrupt structure (checked upstream)
    }
    // drop straight-on vertices (in a convex polygon a vertex is straight exactly when it
    // is collinear with its original neighbours), then start at the bottom-most one
    i64 k = 0;
    for (i64 i = 0; i < m; ++i)
      if (orient(p, buf[(i + m - 1) % m], buf[i], buf[(i + 1) % m]) != 0) out[n_out + k++] = buf[i];
    for (i64 i = 0; i < k; ++i) buf[i] = out[n_out + i];
    i64 best = 0;
    for (i64 i = 1; i < k; ++i) {
      i64 bi = buf[i], bb = buf[best];
      if (p[2 * bi + 1] < p[2 * bb + 1] || (p[2 * bi + 1] == p[2 * bb + 1] && p[2 * bi] < p[2 * bb]))
        best = i;
    }
    for (i64 i = 0; i < k; ++i) out[n_out++] = buf[(best + i) % k];
    off[++P] = n_out;
  }
  return P;
}

}  // namespace decompose
}  // namespace mk
