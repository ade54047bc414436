// collision.hpp -- collision, distance, penetration and point location for convex
// polygons. The stages: collision_prep.hpp (modes, shared predicates, prep: range and
// normalization), collision_walk.hpp (the boundary walk: intersects, distance,
// penetration), collision_gjk.hpp (exact GJK); here the batch driver over pairs and
// point location.
//
// Coordinates are float64 (int input is passed as float64 when |x| < 2^53). Every
// decision is an exact sign:
//
//  * signs of cross/dot products of input differences go through mk::cross_sign, exact
//    at every finite magnitude;
//  * the generic 4-term cross product cross44 (GJK, the common point) is filtered and
//    falls back to the exact Kulisch accumulator, also at every magnitude.
//
// So intersects (walk and GJK) and contains take any finite float. The *values* (distance,
// depth, witnesses) use the expansion arithmetic of exact.hpp and square roots, which
// need every nonzero |coordinate| in [2^-400, 2^400]; prep() reports RANGE for
// such values only in the modes that compute them, and the caller takes its exact path.
//
// The boundary of D = A + (-B) is walked without being stored: merging the edges of A
// with the edges of -B by angle gives D's edges in order. Each edge of D is a sub-edge:
// an edge p0 -> p1 of one polygon (X) paired with a vertex q of the other (Y):
//  * kind 0: an edge of A with a vertex of B; D runs from a_i - b_j to a_{i+1} - b_j;
//  * kind 1: an edge of B with a vertex of A; D runs from a_i - b_j to a_i - b_{j+1}.
// Parallel edges of A and -B are kept as two collinear sub-edges (A's first). With
// e = p1 - p0: the origin is on the inner side iff orient(p0, p1, q) >= 0; its signed
// distance to the line is cross(e, q - p0) / |e|; its foot lies past the start iff
// dot(q - p0, e) > 0 and before the end iff dot(q - p1, e) < 0.
//
// Polygons arrive normalized by mk::normalize (CCW, bottom-most first, no duplicate or
// collinear vertex), as index lists into the (n, 2) row-major coordinate array.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

// the stages, in order: prepared polygons, the boundary walk, GJK
#include "collision_gjk.hpp"
#include "collision_prep.hpp"
#include "collision_walk.hpp"
#include "exact.hpp"
#include "parallel.hpp"

namespace mk {
namespace coll {

// ------------------------------------------------------------------------------------
// batch driver

// The prepared polygons of one side of a batch (the output of prep()).
struct Side {
  const double* p;
  const i64* off;
  const i64* idx;
  const i64* kk;
  const i64* ss;
  const double* inv;
  Poly poly(i64 x) const {
    i64 o = off[x];
    return Poly{p, idx + o, kk[x], ss[x], inv + o};
  }
};

// Pairs q0 <= q < q1 of a batch; returns the first pair where GJK hit its cap, or -1.
inline i64 pairs_range(const Side& SA, const Side& SB, const i64* qa, const i64* qb, int mode,
                       std::int8_t* hit, double* res, i64 q0, i64 q1, i64 big) {
  Scratch S(big);
  for (i64 q = q0; q < q1; ++q) {
    Poly A = SA.poly(qa[q]), B = SB.poly(qb[q]);
    if (mode == INTERSECTS || (mode == AUTO && A.n + B.n <= AUTO_SUM_MAX)) {
      hit[q] = (std::int8_t)intersects(A, B, S);
    } else if (mode == GJK || mode == AUTO) {
      int r = gjk(A, B);
      if (r < 0) return q;
      hit[q] = (std::int8_t)r;
    } else {
      double* row = res + NCOL * q;
      hit[q] = (std::int8_t)collide(A, B, mode, S, row);
      if (mode == DISTANCE) row[0] = row[0] < 0.0 ? -row[0] : 0.0;
    }
  }
  return -1;
}

// Run `mode` on pair q = (polygon qa[q] of A, polygon qb[q] of B) for every q, over
// `threads` contiguous chunks (the same results for any thread count). hit[q] receives
// 1/0; for DISTANCE/PENETRATION res[q] the row. Returns the first pair where GJK hit its
// cap, or -1.
inline i64 pairs(const Side& SA, const Side& SB, const i64* qa, const i64* qb, i64 P, int mode,
                 std::int8_t* hit, double* res, int threads) {
  i64 big = 2;
  for (i64 q = 0; q < P; ++q) big = std::max(big, SA.kk[qa[q]] + SB.kk[qb[q]]);
  const int nt = thread_count(threads, P / 64);
  if (nt <= 1) return pairs_range(SA, SB, qa, qb, mode, hit, res, 0, P, big);
  std::vector<i64> fail(nt, -1);
  parallel_threads(nt, [&](int t) {
    i64 q0 = P * t / nt, q1 = P * (t + 1) / nt;
    fail[t] = pairs_range(SA, SB, qa, qb, mode, hit, res, q0, q1, big);
  });
  for (i64 f : fail)
    if (f >= 0) return f;
  return -1;
}

// ------------------------------------------------------------------------------------
// point location

// Exact sign of orient((x0, y0), (x1, y1), q).
inline int orient0(double x0, double y0, double x1, double y1, double qx, double qy) {
  return cross_sign(x0, y0, x1, y1, x0, y0, qx, qy);
}

// q (collinear with u, v) lies on the closed segment u v.
inline bool between(const double* p, i64 u, i64 v, double qx, double qy) {
  return dot_sign(p[2 * u], p[2 * u + 1], qx, qy, p[2 * u], p[2 * u + 1], p[2 * v],
                  p[2 * v + 1]) >= 0 &&
         dot_sign(p[2 * v], p[2 * v + 1], qx, qy, p[2 * u], p[2 * u + 1], p[2 * v],
                  p[2 * v + 1]) <= 0;
}

// out[t] = 1 when pts[t] lies in the normalized convex polygon (p, ix[:k]), boundary
// included; O(log k) per point by exact binary search over the fan from vertex 0.
inline void contains_points(const double* p, const i64* ix, i64 k, const double* pts, i64 npts,
                            bool* out) {
  std::vector<double> X(k), Y(k);
  for (i64 t = 0; t < k; ++t) {
    X[t] = p[2 * ix[t]];
    Y[t] = p[2 * ix[t] + 1];
  }
  double x0 = X[0], y0 = Y[0];
  for (i64 t = 0; t < npts; ++t) {
    double qx = pts[2 * t], qy = pts[2 * t + 1];
    if (k == 1) {
      out[t] = qx == x0 && qy == y0;
      continue;
    }
    int o1 = orient0(x0, y0, X[1], Y[1], qx, qy);
    if (o1 == 0) {
      // on the line of edge 0 (the whole polygon, for a segment): between its ends?
      out[t] = between(p, ix[0], ix[1], qx, qy);
      continue;
    }
    if (o1 < 0 || k == 2) {
      out[t] = false;
      continue;
    }
    int ol = orient0(x0, y0, X[k - 1], Y[k - 1], qx, qy);
    if (ol > 0) {
      out[t] = false;
      continue;
    }
    if (ol == 0) {
      out[t] = between(p, ix[0], ix[k - 1], qx, qy);
      continue;
    }
    i64 lo = 1, hi = k - 1;
    while (hi - lo > 1) {
      i64 mid = (lo + hi) >> 1;
      bool up = orient0(x0, y0, X[mid], Y[mid], qx, qy) >= 0;
      lo = up ? mid : lo;
      hi = up ? hi : mid;
    }
    out[t] = orient0(X[lo], Y[lo], X[hi], Y[hi], qx, qy) >= 0;
  }
}

// ------------------------------------------------------------------------------------
// one pair, one polygon (what the bindings' single calls run)

// The outcome of a single call: code 0 on success, else a Status (RANGE: values the
// kernels cannot compute exactly) for operand `which` at `vertex`; hit: the answer.
struct SingleResult {
  int code = 0, which = 0, hit = 0;
  i64 vertex = 0;
};

// One pair: prepare pa[0:na] (int_a: int input) and pb[0:nb], then run `mode` (its row
// to res for DISTANCE / PENETRATION); GJK's cap gives code INTERNAL.
inline SingleResult single(const double* pa, i64 na, const double* pb, i64 nb, int mode,
                           bool int_a, bool int_b, double* res) {
  SingleResult out;
  i64 offa[2] = {0, na}, offb[2] = {0, nb};
  std::vector<i64> ida(na > 0 ? na : 1), idb(nb > 0 ? nb : 1);
  bool need_len = mode == PENETRATION;
  std::vector<double> inva(need_len ? na : 1), invb(need_len ? nb : 1);
  i64 ka, kb, sa, sb;
  PrepResult r = prep(pa, na, offa, 1, int_a, mode, ida.data(), &ka, &sa, inva.data());
  if (r.code) {
    out.code = r.code;
    out.vertex = r.v;
    return out;
  }
  r = prep(pb, nb, offb, 1, int_b, mode, idb.data(), &kb, &sb, invb.data());
  if (r.code) {
    out.code = r.code;
    out.which = 1;
    out.vertex = r.v;
    return out;
  }
  Side A{pa, offa, ida.data(), &ka, &sa, inva.data()};
  Side B{pb, offb, idb.data(), &kb, &sb, invb.data()};
  i64 q0 = 0;
  std::int8_t h = 0;
  i64 g = pairs(A, B, &q0, &q0, 1, mode, &h, res, 1);
  if (g >= 0)
    out.code = INTERNAL;  // GJK did not terminate
  else
    out.hit = h;
  return out;
}

// Point location in one convex polygon p[0:n] (int_p: int input) of the m points pts
// (int_pts likewise) into out; which 0 = the polygon, 1 = the points.
inline SingleResult contains_single(const double* p, i64 n, bool int_p, const double* pts,
                                    i64 m, bool int_pts, bool* out) {
  SingleResult res;
  i64 off[2] = {0, n};
  std::vector<i64> ix(n > 0 ? n : 1);
  i64 kk, ss;
  double inv;
  PrepResult r = prep(p, n, off, 1, int_p, INTERSECTS, ix.data(), &kk, &ss, &inv);
  if (r.code) {
    res.code = r.code;
    res.vertex = r.v;
    return res;
  }
  i64 bad = out_of_range(pts, 0, m, int_pts, false);
  i64 badf = -1;
  for (i64 t = 0; t < 2 * m && badf < 0; ++t)
    if (!(pts[t] - pts[t] == 0.0)) badf = t / 2;
  if (bad >= 0) {
    res.code = RANGE;
    res.which = 1;
    res.vertex = bad;
  } else if (badf >= 0) {
    res.code = NONFINITE;
    res.which = 1;
    res.vertex = badf;
  } else {
    contains_points(p, ix.data(), kk, pts, m, out);
  }
  return res;
}

}  // namespace coll
}  // namespace mk
