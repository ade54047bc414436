// collision_prep.hpp -- collision.hpp's first stage: the modes, the exact predicates the
// kernels share (dot_sign, cross_value, cross44), the range check and the normalization
// of every polygon of a ragged array (prep), and Poly, one prepared polygon.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "convex.hpp"
#include "exact.hpp"
#include "parallel.hpp"

namespace mk {
namespace coll {

// mode of the pair kernel
enum Mode : int { INTERSECTS = 0, DISTANCE = 1, PENETRATION = 2, GJK = 3, AUTO = 4 };
constexpr i64 AUTO_SUM_MAX = 64;  // vertex total up to which the walk beats GJK (measured)
constexpr int NCOL = 7;           // result row: value, normal (2), point_a (2), point_b (2)

constexpr double I_LIM = (double)FLOAT_EXACT_INT;  // ints convert to double exactly
// Every 2-term sign here is exact.hpp's cross_sign, or its filter alone (filter_sign) with
// cross_sign where that cannot tell. Two rules of this file differ from that filter, for
// a reason:
//  * REL (cross_value): a *value* is wanted, not a sign, so the float cross product is
//    kept only when exact.hpp's error bound (ERRBOUND (|l| + |r|)) is below 2^-45 of it
//    -- a relative error below 2^-44 for the distances and depths -- rather than merely
//    below it; otherwise the exact expansion is summed.
//  * GEN_BOUND, GEN_MIN (cross44): another expression, each factor a sum of four
//    coordinates, so its rounding error is bounded by 10 eps times the products of the
//    absolute coordinate sums, not by 3 eps (|l| + |r|); GEN_MIN is its MINBOUND (below
//    it a product may have underflowed and the exact accumulator decides).
constexpr double REL = 0x1p-45;               // relative accuracy demanded of a value
constexpr double GEN_BOUND = 10.0 * 0x1p-53;  // error bound factor of the 4-term cross
constexpr double GEN_MIN = 0x1p-900;          // below this bound: the exact accumulator

inline int sgnd(double v) { return (v > 0.0) - (v < 0.0); }

// |(x, y)|: no overflow or underflow for differences of coordinates in the value range.
inline double len(double x, double y) { return std::sqrt(x * x + y * y); }

// Exact sign of (a1 - a0) . (b1 - b0): the cross product with a0, a1 turned by -90 deg.
inline int dot_sign(double a0x, double a0y, double a1x, double a1y, double b0x, double b0y,
                    double b1x, double b1y) {
  return cross_sign(a0y, -a0x, a1y, -a1x, b0x, b0y, b1x, b1y);
}

// The exact (a1 - a0) x (b1 - b0) as an expansion, summed from the smallest component up
// (cross_value's fallback, out of line: the float test stays small enough to inline).
[[gnu::noinline]] inline double cross_value_exact(double a0x, double a0y, double a1x,
                                                  double a1y, double b0x, double b0y,
                                                  double b1x, double b1y) {
  double e[40];
  int m = cross_expansion(e, a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y);
  double s = 0.0;
  for (int t = 0; t < m; ++t) s += e[t];
  return s;
}

// (a1 - a0) x (b1 - b0) to a relative error below 2^-44; exactly 0.0 iff it is 0. The
// float value is kept when its error bound is below 2^-45 of it (REL); otherwise the
// exact expansion is summed. (Value range only.)
inline double cross_value(double a0x, double a0y, double a1x, double a1y, double b0x,
                          double b0y, double b1x, double b1y) {
  double ux = a1x - a0x, uy = a1y - a0y, vx = b1x - b0x, vy = b1y - b0y;
  double l = ux * vy, r = uy * vx, det = l - r;
  double bound = ERRBOUND * (std::fabs(l) + std::fabs(r));
  if (__builtin_expect(bound <= REL * std::fabs(det), 1)) return det;
  return cross_value_exact(a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y);
}

// Exact sign of cross((u1 - u2) + (u3 - u4), (v1 - v2) + (v3 - v4)) from the 16
// coordinates in c (u1x, u1y, ..., v4y): the 32 exact products in a Kulisch accumulator.
inline int cross44_exact(const double* c) {
  detail::Acc P, N;
  for (int s = 0; s < 4; ++s) {
    bool su = (s % 2) != 0;  // negated
    double ux = c[2 * s], uy = c[2 * s + 1];
    for (int t = 0; t < 4; ++t) {
      bool sv = su != ((t % 2) != 0);
      double vx = c[8 + 2 * t], vy = c[8 + 2 * t + 1];
      detail::add_product(P, N, ux, vy, sv);
      detail::add_product(P, N, uy, vx, !sv);
    }
  }
  return detail::compare(P, N);
}

// Exact sign of cross(U, V), U = (u1 - u2) + (u3 - u4), V = (v1 - v2) + (v3 - v4).
// Filtered: the float value decides when it exceeds a bound on its rounding error (and
// nothing can have underflowed or overflowed), the exact accumulator otherwise.
inline int cross44(const double* c) {
  double ux = (c[0] - c[2]) + (c[4] - c[6]);
  double uy = (c[1] - c[3]) + (c[5] - c[7]);
  double vx = (c[8] - c[10]) + (c[12] - c[14]);
  double vy = (c[9] - c[11]) + (c[13] - c[15]);
  double sxu = std::fabs(c[0]) + std::fabs(c[2]) + std::fabs(c[4]) + std::fabs(c[6]);
  double syu = std::fabs(c[1]) + std::fabs(c[3]) + std::fabs(c[5]) + std::fabs(c[7]);
  double sxv = std::fabs(c[8]) + std::fabs(c[10]) + std::fabs(c[12]) + std::fabs(c[14]);
  double syv = std::fabs(c[9]) + std::fabs(c[11]) + std::fabs(c[13]) + std::fabs(c[15]);
  double det = ux * vy - uy * vx;
  double bound = GEN_BOUND * (sxu * syv + syu * sxv);
  if (bound >= GEN_MIN) {  // false for NaN; an infinite bound certifies nothing below
    if (det > bound) return 1;
    if (-det > bound) return -1;
  }
  // every term has a zero factor: U.x = 0 or V.y = 0, and U.y = 0 or V.x = 0, exactly
  if ((sxu == 0.0 || syv == 0.0) && (syu == 0.0 || sxv == 0.0)) return 0;
  return cross44_exact(c);
}

// ------------------------------------------------------------------------------------
// range and normalization of every polygon of a ragged array

// First row of p[lo:hi] the kernels cannot take, relative to lo, or -1. Int input
// (converted to float64) must have |x| < 2^53; float input, when `values` is set,
// every nonzero |x| in [2^-400, 2^400] (signs alone take any finite float).
inline i64 out_of_range(const double* p, i64 lo, i64 hi, bool is_int, bool values) {
  if (!is_int && !values) return -1;
  for (i64 r = lo; r < hi; ++r)
    for (int c = 0; c < 2; ++c) {
      double x = std::fabs(p[2 * r + c]);
      if (is_int) {
        if (x >= I_LIM) return r - lo;
      } else if (x > X_HI || (x != 0.0 && x < X_LO)) {
        return r - lo;
      }
    }
  return -1;
}

inline bool mode_values(int mode) { return mode == DISTANCE || mode == PENETRATION; }

struct PrepResult {
  int code;
  i64 q, v;
};

// The implicit rotation of a normalized polygon (step != 0: all n vertices, from b, in
// direction step) as explicit indices: what r.at(t) gives, in two straight runs.
inline void write_rotation(const Norm& r, i64* out) {
  i64 k = 0;
  if (r.step > 0) {
    for (i64 v = r.b; v < r.lo + r.n; ++v) out[k++] = v;
    for (i64 v = r.lo; v < r.b; ++v) out[k++] = v;
  } else {
    for (i64 v = r.b; v >= r.lo; --v) out[k++] = v;
    for (i64 v = r.lo + r.n - 1; v > r.b; --v) out[k++] = v;
  }
}

// Normalize polygons q0 <= q < q1 of p (see prep(), which checked the range); returns
// the first failure.
inline PrepResult prep_range(const double* p, const i64* off, i64 q0, i64 q1, int mode,
                             i64* idx, i64* kk, i64* ss, double* inv) {
  bool need_len = mode == PENETRATION;
  i64 big = 1;
  for (i64 q = q0; q < q1; ++q) big = std::max(big, off[q + 1] - off[q]);
  std::vector<i64> keep(big);
  std::vector<std::int8_t> turn(big);
  for (i64 q = q0; q < q1; ++q) {
    i64 lo = off[q], hi = off[q + 1];
    if (hi <= lo) return {EMPTY, q, 0};
    Norm r = normalize(p, lo, hi, keep.data(), turn.data(), idx + lo);
    if (r.code != OK) return {r.code, q, r.vertex};
    if (r.step != 0) write_rotation(r, idx + lo);
    kk[q] = r.k;
    ss[q] = r.split;
    if (need_len && r.k > 1) {
      for (i64 t = 0; t < r.k; ++t) {
        i64 i = idx[lo + t];
        i64 j = t + 1 < r.k ? idx[lo + t + 1] : idx[lo];
        inv[lo + t] = 1.0 / len(p[2 * j] - p[2 * i], p[2 * j + 1] - p[2 * i + 1]);
      }
    }
  }
  return {OK, 0, 0};
}

// Normalize polygon q = p[off[q]:off[q+1]] for every q: its normalized vertex indices to
// idx[off[q]:off[q]+kk[q]], its split to ss[q] and, for PENETRATION, the inverse length
// of its normalized edge t to inv[off[q] + t]. Returns (code, polygon, vertex) of the
// first polygon out of range (all are checked first) or else
// the first that fails to normalize. `threads` contiguous chunks of polygons run in
// parallel; the result does not depend on it.
inline PrepResult prep(const double* p, i64 np_, const i64* off, i64 P, bool is_int, int mode,
                       i64* idx, i64* kk, i64* ss, double* inv, int threads = 1) {
  bool values = mode_values(mode);
  if (out_of_range(p, 0, np_, is_int, values) >= 0) {
    for (i64 q = 0; q < P; ++q) {
      i64 r = out_of_range(p, off[q], off[q + 1], is_int, values);
      if (r >= 0) return {RANGE, q, r};
    }
  }
  const int nt = thread_count(threads, P / 64);
  if (nt <= 1) return prep_range(p, off, 0, P, mode, idx, kk, ss, inv);
  std::vector<PrepResult> res(nt, PrepResult{OK, 0, 0});
  parallel_threads(nt, [&](int t) {
    res[t] = prep_range(p, off, P * t / nt, P * (t + 1) / nt, mode, idx, kk, ss, inv);
  });
  for (auto& r : res)
    if (r.code != OK) return r;
  return {OK, 0, 0};
}

// ------------------------------------------------------------------------------------
// one prepared polygon

// One normalized polygon: coordinates, normalized indices, count, split, inverse lengths.
struct Poly {
  const double* p;
  const i64* ix;
  i64 n, s;
  const double* inv;
  double x(i64 t) const { return p[2 * ix[t]]; }
  double y(i64 t) const { return p[2 * ix[t] + 1]; }
};

}  // namespace coll
}  // namespace mk
