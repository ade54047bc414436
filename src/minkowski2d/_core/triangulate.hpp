// triangulate.hpp -- exact triangulation of valid polygons with holes.
//
// The checks of polygon.hpp leave each polygon as points (distinct coordinates, in (y, x)
// order), boundary edges with the interior on their left (split where a vertex of one
// ring touches the inside of another ring's edge) and the diagonals of a monotone
// partition from the same sweep. Here
//  1. the faces of edges + diagonals are walked: at a point where more than two of them
//     meet, the edge after an incoming one is the next one clockwise (exact angular
//     order: half-plane, then orient);
//  2. each face is monotone in (y, x) order: its two chains are merged and triangulated
//     with the stack algorithm (de Berg et al., ch. 3.3); a vertex whose turn is not
//     strictly convex (straight or reflex, decided by orient) stays on the stack, so
//     collinear vertices never make a flat triangle.
// Output: triangles as vertex ids into the input coordinates (for coordinates given
// several times, the smallest id), each counter-clockwise, together covering the polygon
// exactly with disjoint interiors; only input vertices are used. A triangle whose three
// vertices lie on one line would have no area and is never written. Time O(n log n).
#pragma once

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "exact.hpp"
#include "polygon.hpp"

namespace mk {
namespace polygon {

// Lawson's flips towards the constrained Delaunay triangulation: an edge between two
// triangles whose quadrilateral is strictly convex is flipped while the far vertex lies
// strictly inside the other triangle's circumcircle (exact incircle; cocircular: no
// flip). Boundary edges are never flipped. Each flip makes the sorted angle vector
// larger, so it ends; the triangles keep their vertices, orientation and union.
// Triangles as point ids, 3 per triangle, counter-clockwise.
template <class T>
void delaunay_flips(const Work<T>& w, std::vector<i64>& t) {
  const i64 ntri = (i64)t.size() / 3, H = 3 * ntri;
  if (ntri < 2) return;
  // twins by sorting the half-edges on their unordered end points (one i64 key each)
  const i64 np = w.npoints();
  std::vector<std::pair<i64, i64>> keyed(H);
  std::vector<i64> twin(H, -1);
  auto a_of = [&](i64 h) { return t[h]; };
  auto b_of = [&](i64 h) { return t[3 * (h / 3) + (h % 3 + 1) % 3]; };
  for (i64 h = 0; h < H; ++h) {
    const i64 a = a_of(h), b = b_of(h);
    keyed[h] = {a < b ? a * np + b : b * np + a, h};
  }
  std::sort(keyed.begin(), keyed.end());
  for (i64 q = 0; q + 1 < H; ++q) {
    if (keyed[q].first != keyed[q + 1].first) continue;
    const i64 x = keyed[q].second, y = keyed[q + 1].second;
    if (a_of(x) == b_of(y) && b_of(x) == a_of(y)) {
      twin[x] = y;
      twin[y] = x;
      ++q;
    }
  }
  auto P = [&](i64 p) { return w.prep[p]; };
  auto orient = [&](i64 a, i64 b, i64 c) { return w.orient(P(a), P(b), P(c)); };
  auto incircle_p = [&](i64 a, i64 b, i64 c, i64 d) {
    return incircle(w.X(P(a)), w.Y(P(a)), w.X(P(b)), w.Y(P(b)), w.X(P(c)), w.Y(P(c)),
                    w.X(P(d)), w.Y(P(d)));
  };
  std::vector<i64> stack;
  for (i64 h = 0; h < H; ++h)
    if (twin[h] > h) stack.push_back(h);
  while (!stack.empty()) {
    const i64 h = stack.back();
    stack.pop_back();
    const i64 g = twin[h];
    if (g < 0) continue;
    const i64 t1 = h / 3, k1 = h % 3, t2 = g / 3, k2 = g % 3;
    // t1 = (a, c, b) with h: a -> c; t2 = (c, a, d) with g: c -> a
    const i64 a = t[3 * t1 + k1], c = t[3 * t1 + (k1 + 1) % 3], b = t[3 * t1 + (k1 + 2) % 3];
    const i64 d = t[3 * t2 + (k2 + 2) % 3];
    if (incircle_p(a, c, b, d) <= 0) continue;
    if (orient(b, a, d) <= 0 || orient(d, c, b) <= 0) continue;  // not strictly convex
    const i64 h_cb = 3 * t1 + (k1 + 1) % 3, h_ba = 3 * t1 + (k1 + 2) % 3;
    const i64 h_ad = 3 * t2 + (k2 + 1) % 3, h_dc = 3 * t2 + (k2 + 2) % 3;
    const i64 o_cb = twin[h_cb], o_ba = twin[h_ba], o_ad = twin[h_ad], o_dc = twin[h_dc];
    // new t1 = (a, d, b), t2 = (c, b, d); the diagonal b - d
    t[3 * t1] = a;
    t[3 * t1 + 1] = d;
    t[3 * t1 + 2] = b;
    t[3 * t2] = c;
    t[3 * t2 + 1] = b;
    t[3 * t2 + 2] = d;
    auto link = [&](i64 x, i64 y) {
      twin[x] = y;
      if (y >= 0) twin[y] = x;
    };
    link(3 * t1, o_ad);
    link(3 * t1 + 2, o_ba);
    link(3 * t2, o_cb);
    link(3 * t2 + 2, o_dc);
    link(3 * t1 + 1, 3 * t2 + 1);
    for (i64 x : {3 * t1, 3 * t1 + 2, 3 * t2, 3 * t2 + 2})
      if (twin[x] >= 0) stack.push_back(x);
  }
}

// The half-edges of a checked Work and the face cycles through them: boundary edge e
// (from -> to), diagonal d as ne + 2d (u -> v) and ne + 2d + 1 (v -> u); org and dst
// their ends, nxt[h] the half-edge after h around its face.
template <class T>
void face_cycles(const Work<T>& w, std::vector<i64>& org, std::vector<i64>& dst,
                 std::vector<i64>& nxt) {
  const i64 np = w.npoints(), ne = w.nedges(), nd = (i64)w.diags.size();
  const i64 H = ne + 2 * nd;
  // half-edges: boundary edge e (from -> to), diagonal d as ne + 2d (u -> v) and
  // ne + 2d + 1 (v -> u)
  org.assign(H, 0);
  dst.assign(H, 0);
  for (i64 e = 0; e < ne; ++e) {
    org[e] = w.efrom[e];
    dst[e] = w.eto[e];
  }
  for (i64 d = 0; d < nd; ++d) {
    org[ne + 2 * d] = w.diags[d].first;
    dst[ne + 2 * d] = w.diags[d].second;
    org[ne + 2 * d + 1] = w.diags[d].second;
    dst[ne + 2 * d + 1] = w.diags[d].first;
  }
  // rays around each point: for every geometric edge one ray at each end, with the
  // half-edge leaving (or -1) and the half-edge arriving (or -1) along it
  std::vector<i64> off(np + 1, 0);
  for (i64 h = 0; h < ne; ++h) {
    ++off[org[h] + 1];
    ++off[dst[h] + 1];
  }
  for (i64 d = 0; d < nd; ++d) {
    ++off[org[ne + 2 * d] + 1];
    ++off[dst[ne + 2 * d] + 1];
  }
  for (i64 p = 0; p < np; ++p) off[p + 1] += off[p];
  struct Ray {
    i64 other, out, in;
  };
  std::vector<Ray> rays(off[np]);
  {
    std::vector<i64> fill(off.begin(), off.end() - 1);
    for (i64 e = 0; e < ne; ++e) {
      rays[fill[org[e]]++] = Ray{dst[e], e, -1};
      rays[fill[dst[e]]++] = Ray{org[e], -1, e};
    }
    for (i64 d = 0; d < nd; ++d) {
      i64 a = ne + 2 * d, b = a + 1;
      rays[fill[org[a]]++] = Ray{dst[a], a, b};
      rays[fill[org[b]]++] = Ray{dst[b], b, a};
    }
  }
  nxt.assign(H, -1);
  for (i64 p = 0; p < np; ++p) {
    Ray* r = rays.data() + off[p];
    const i64 deg = off[p + 1] - off[p];
    if (deg > 2) {
      const i64 pv = w.prep[p];
      std::sort(r, r + deg, [&](const Ray& a, const Ray& b) {
        return w.ccw_before(pv, w.prep[a.other], w.prep[b.other]);
      });
    }
    for (i64 k = 0; k < deg; ++k) {
      if (r[k].in < 0) continue;
      i64 o = r[(k + deg - 1) % deg].out;  // the next ray clockwise
      if (o < 0) throw std::logic_error("triangulate: inconsistent boundary at a point");
      nxt[r[k].in] = o;
    }
  }
}

// The triangles of one monotone face (its k >= 3 point ids in cycle order), by the
// stack algorithm over its two chains merged in point order; emit(a, b, c) for each.
// merged, mside, stack and side are scratch.
template <class T, class Emit>
void triangulate_face(const Work<T>& w, const std::vector<i64>& face, std::vector<i64>& merged,
                      std::vector<std::uint8_t>& mside, std::vector<i64>& stack,
                      std::vector<std::uint8_t>& side, Emit&& emit) {
  const i64 k = (i64)face.size();
  // the face is monotone in point order: lowest and highest, two chains between
  i64 lo = 0, hi = 0;
  for (i64 i = 1; i < k; ++i) {
    if (face[i] < face[lo]) lo = i;
    if (face[i] > face[hi]) hi = i;
  }
  // right chain: counter-clockwise from lo to hi (ascending); left chain: clockwise
  // from lo to hi (ascending as well)
  merged.clear();
  mside.clear();
  merged.push_back(face[lo]);
  mside.push_back(2);
  i64 i = (lo + 1) % k, j = (lo + k - 1) % k;
  while (i != hi || j != hi) {
    bool take_right;
    if (i == hi) {
      take_right = false;
    } else if (j == hi) {
      take_right = true;
    } else {
      take_right = face[i] < face[j];
    }
    i64 pnt = take_right ? face[i] : face[j];
    if (pnt <= merged.back()) throw std::logic_error("triangulate: face is not monotone");
    merged.push_back(pnt);
    mside.push_back(take_right ? 1 : 0);
    if (take_right) {
      i = (i + 1) % k;
    } else {
      j = (j + k - 1) % k;
    }
  }
  if (face[hi] <= merged.back()) throw std::logic_error("triangulate: face is not monotone");
  merged.push_back(face[hi]);
  mside.push_back(2);
  // the stack algorithm
  stack.clear();
  side.clear();
  stack.push_back(merged[0]);
  side.push_back(mside[0]);
  stack.push_back(merged[1]);
  side.push_back(mside[1]);
  for (i64 t = 2; t + 1 < k; ++t) {
    const i64 u = merged[t];
    const std::uint8_t su = mside[t];
    if (su != side.back()) {
      // opposite chains: u sees every vertex on the stack
      for (std::size_t q = stack.size() - 1; q > 0; --q) emit(u, stack[q], stack[q - 1]);
      i64 last = stack.back();
      std::uint8_t lside = side.back();
      stack.clear();
      side.clear();
      stack.push_back(last);
      side.push_back(lside);
      stack.push_back(u);
      side.push_back(su);
    } else {
      i64 last = stack.back();
      std::uint8_t lside = side.back();
      stack.pop_back();
      side.pop_back();
      while (!stack.empty()) {
        const i64 top = stack.back();
        // convex at `last` (strictly), seen along the chain's counter-clockwise order
        int s = su == 1 ? w.orient(w.prep[top], w.prep[last], w.prep[u])
                        : w.orient(w.prep[u], w.prep[last], w.prep[top]);
        if (s <= 0) break;
        emit(u, last, top);
        last = top;
        lside = side.back();
        stack.pop_back();
        side.pop_back();
      }
      stack.push_back(last);
      side.push_back(lside);
      stack.push_back(u);
      side.push_back(su);
    }
  }
  const i64 u = merged[k - 1];
  for (std::size_t q = stack.size() - 1; q > 0; --q) emit(u, stack[q], stack[q - 1]);
}

// Triangles of one checked Work (w.run() returned OK), appended to tri (3 input ids each);
// with delaunay, improved by Lawson's flips (delaunay_flips).
template <class T>
void triangulate_work(const Work<T>& w, std::vector<i64>& tri, bool delaunay) {
  const i64 H = w.nedges() + 2 * (i64)w.diags.size();
  std::vector<i64> org, dst, nxt;
  face_cycles(w, org, dst, nxt);
  // faces
  std::vector<std::uint8_t> seen(H, 0);
  std::vector<i64> face, merged, stack;
  std::vector<std::uint8_t> side, mside;
  std::vector<i64> pts;  // triangles as point ids
  auto emit = [&](i64 a, i64 b, i64 c) {
    int s = w.orient(w.prep[a], w.prep[b], w.prep[c]);
    if (s == 0) return;
    if (s < 0) std::swap(b, c);
    pts.push_back(a);
    pts.push_back(b);
    pts.push_back(c);
  };
  for (i64 h0 = 0; h0 < H; ++h0) {
    if (seen[h0]) continue;
    face.clear();
    i64 h = h0;
    do {
      if (h < 0 || seen[h]) throw std::logic_error("triangulate: broken face cycle");
      seen[h] = 1;
      face.push_back(org[h]);
      h = nxt[h];
    } while (h != h0);
    const i64 k = (i64)face.size();
    if (k < 3) throw std::logic_error("triangulate: face with fewer than 3 vertices");
    triangulate_face(w, face, merged, mside, stack, side, emit);
  }
  if (delaunay) delaunay_flips(w, pts);
  for (i64 p : pts) tri.push_back(w.prep[p]);
}

// Check and triangulate every polygon; triangles appended to tri.
template <class T>
Problem triangulate(const T* xy, const i64* ring_off, i64 R, const i64* poly_off, i64 P,
                    std::vector<i64>& tri, bool delaunay = true) {
  Problem pr = check_finite(xy, ring_off, R);
  if (!pr.ok()) return pr;
  for (i64 p = 0; p < P; ++p) {
    Work<T> w(xy, ring_off);
    pr = sweep_polygon(w, poly_off, p);
    if (!pr.ok()) return pr;
    triangulate_work(w, tri, delaunay);
  }
  return Problem();
}

}  // namespace polygon
}  // namespace mk
