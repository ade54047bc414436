// collision.hpp -- collision, distance, penetration and point location for convex
// polygons.
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

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "convex.hpp"
#include "exact.hpp"
#include "filter.hpp"
#include "parallel.hpp"

namespace mk {
namespace coll {

// mode of the pair kernel
enum Mode : int { INTERSECTS = 0, DISTANCE = 1, PENETRATION = 2, GJK = 3, AUTO = 4 };
constexpr i64 AUTO_SUM_MAX = 64;  // vertex total up to which the walk beats GJK (measured)
constexpr int NCOL = 7;           // result row: value, normal (2), point_a (2), point_b (2)

constexpr double I_LIM = (double)FLOAT_EXACT_INT;  // ints convert to double exactly
// Every 2-term sign here is exact.hpp's cross_sign, or its filter alone (filter.hpp) with
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
// walking the boundary of A + (-B)

// Per-thread scratch for a run of pairs with at most `big` vertices together.
struct Scratch {
  std::vector<std::int8_t> kind, vis;
  std::vector<i64> ii, jj;
  std::vector<double> cv, AX, AY, BX, BY;
  explicit Scratch(i64 big)
      : kind(big), vis(big), ii(big), jj(big), cv(big), AX(big + 2), AY(big + 2),
        BX(big + 2), BY(big + 2) {}
};

// One normalized polygon: coordinates, normalized indices, count, split, inverse lengths.
struct Poly {
  const double* p;
  const i64* ix;
  i64 n, s;
  const double* inv;
  double x(i64 t) const { return p[2 * ix[t]]; }
  double y(i64 t) const { return p[2 * ix[t] + 1]; }
};

// Whether the next edge of D comes from A (edge i) rather than -B (edge t, which is B's
// edge j reversed). sbm is -B's split.
inline bool take_a(const Poly& A, i64 i, const Poly& B, i64 sbm, i64 t, i64 j) {
  bool ha = i >= A.s, hb = t >= sbm;
  if (ha != hb) return !ha;
  const double* pa = A.p;
  const double* pb = B.p;
  i64 a0 = A.ix[i], a1 = i + 1 < A.n ? A.ix[i + 1] : A.ix[0];
  i64 b0 = B.ix[j], b1 = j + 1 < B.n ? B.ix[j + 1] : B.ix[0];
  int c = cross_sign(pa[2 * a0], pa[2 * a0 + 1], pa[2 * a1], pa[2 * a1 + 1], pb[2 * b1],
                     pb[2 * b1 + 1], pb[2 * b0], pb[2 * b0 + 1]);
  return c >= 0;
}

// Copy A's normalized vertices (from its first) and B's from its top vertex (-B's
// first), each with two wrap-around entries, into contiguous scratch.
inline void gather(const Poly& A, const Poly& B, Scratch& S) {
  for (i64 t = 0; t < A.n + 2; ++t) {
    i64 v = A.ix[t % A.n];
    S.AX[t] = A.p[2 * v];
    S.AY[t] = A.p[2 * v + 1];
  }
  i64 s = B.s % B.n;
  for (i64 t = 0; t < B.n + 2; ++t) {
    i64 v = B.ix[(s + t) % B.n];
    S.BX[t] = B.p[2 * v];
    S.BY[t] = B.p[2 * v + 1];
  }
}

// Write D's sub-edges in order: kind (0 = A edge, 1 = B edge), A position, B position.
inline i64 subedges(const Poly& A, const Poly& B, std::int8_t* kind, i64* ii, i64* jj) {
  i64 na = A.n, nb = B.n;
  i64 ea = na > 1 ? na : 0, eb = nb > 1 ? nb : 0;
  i64 sbm = nb > 1 ? nb - B.s : 0;
  i64 i = 0, t = 0, j = B.s % nb, k = 0;
  while (i < ea || t < eb) {
    bool ta;
    if (i == ea)
      ta = false;
    else if (t == eb)
      ta = true;
    else
      ta = take_a(A, i, B, sbm, t, j);
    kind[k] = ta ? 0 : 1;
    ii[k] = i < na ? i : 0;
    jj[k] = j;
    ++k;
    if (ta) {
      ++i;
    } else {
      ++t;
      j = j + 1 < nb ? j + 1 : 0;
    }
  }
  return k;
}

// A sub-edge as a feature: the edge p0 -> p1 of X and the vertex q of Y (row indices).
struct Feat {
  const double* X;
  i64 p0, p1;
  const double* Y;
  i64 q;
};

inline Feat feature(const Poly& A, const Poly& B, const std::int8_t* kind, const i64* ii,
                    const i64* jj, i64 k) {
  i64 i = ii[k], j = jj[k];
  if (kind[k] == 0) return {A.p, A.ix[i], i + 1 < A.n ? A.ix[i + 1] : A.ix[0], B.p, B.ix[j]};
  return {B.p, B.ix[j], j + 1 < B.n ? B.ix[j + 1] : B.ix[0], A.p, A.ix[i]};
}

// sign dot(q - p0, p1 - p0)
inline int fdot0(const Feat& f) {
  const double *X = f.X, *Y = f.Y;
  return dot_sign(X[2 * f.p0], X[2 * f.p0 + 1], Y[2 * f.q], Y[2 * f.q + 1], X[2 * f.p0],
                  X[2 * f.p0 + 1], X[2 * f.p1], X[2 * f.p1 + 1]);
}

// sign dot(q - p1, p1 - p0)
inline int fdot1(const Feat& f) {
  const double *X = f.X, *Y = f.Y;
  return dot_sign(X[2 * f.p1], X[2 * f.p1 + 1], Y[2 * f.q], Y[2 * f.q + 1], X[2 * f.p0],
                  X[2 * f.p0 + 1], X[2 * f.p1], X[2 * f.p1 + 1]);
}

inline bool on_edge(const Feat& f) { return fdot0(f) >= 0 && fdot1(f) <= 0; }

// Origin on D, when D is a segment whose line passes through the origin.
inline int on_degenerate(const Poly& A, const Poly& B, Scratch& S) {
  i64 K = subedges(A, B, S.kind.data(), S.ii.data(), S.jj.data());
  for (i64 k = 0; k < K; ++k)
    if (on_edge(feature(A, B, S.kind.data(), S.ii.data(), S.jj.data(), k))) return 1;
  return 0;
}

// The merge decision of the walk at A edge i, -B edge t over gathered coordinates: the
// float filter when it certifies (a select, no data-dependent branch), the exact
// predicate otherwise (rare).
inline bool walk_take_a(const Scratch& S, i64 i, i64 t, i64 sa, i64 sbm, i64 ea, i64 eb) {
  const double* AX = S.AX.data();
  const double* AY = S.AY.data();
  const double* BX = S.BX.data();
  const double* BY = S.BY.data();
  double ax0 = AX[i], ay0 = AY[i], ax1 = AX[i + 1], ay1 = AY[i + 1];
  double bx0 = BX[t], by0 = BY[t], bx1 = BX[t + 1], by1 = BY[t + 1];
  // cross(a1 - a0, b0 - b1): > 0 when -B's edge is CCW of A's (A first)
  FilterSign f = filter_sign((ax1 - ax0) * (by0 - by1), (ay1 - ay0) * (bx0 - bx1));
  bool ha = i >= sa, hb = t >= sbm, same = ha == hb;
  bool ta = same ? f.sign > 0 : !ha;
  if (__builtin_expect(same & !f.certain & (i < ea) & (t < eb), 0))
    ta = cross_sign(ax0, ay0, ax1, ay1, bx1, by1, bx0, by0) >= 0;
  return (ta | (t >= eb)) & (i < ea);
}

// The sub-edge chosen by the merge: p0 -> p1 of X and the vertex q of Y, selected by
// index and pointer (no data-dependent branch).
struct Sub {
  double p0x, p0y, p1x, p1y, qx, qy;
};

inline Sub pick(const Scratch& S, bool ta, i64 i, i64 t) {
  const double* PX = ta ? S.AX.data() : S.BX.data();
  const double* PY = ta ? S.AY.data() : S.BY.data();
  const double* QX = ta ? S.BX.data() : S.AX.data();
  const double* QY = ta ? S.BY.data() : S.AY.data();
  i64 u = ta ? i : t, w = ta ? t : i;
  return Sub{PX[u], PY[u], PX[u + 1], PY[u + 1], QX[w], QY[w]};
}

// 1 when the origin lies in D = A + (-B) (closed), else 0. Exact; stops at the first
// separating edge. The walk of walk() without storing anything.
inline int intersects(const Poly& A, const Poly& B, Scratch& S) {
  i64 na = A.n, nb = B.n;
  i64 ea = na > 1 ? na : 0, eb = nb > 1 ? nb : 0;
  if (ea + eb == 0) {
    i64 a = A.ix[0], b = B.ix[0];
    return A.p[2 * a] == B.p[2 * b] && A.p[2 * a + 1] == B.p[2 * b + 1] ? 1 : 0;
  }
  gather(A, B, S);
  i64 sa = A.s, sbm = nb > 1 ? nb - B.s : 0;
  i64 i = 0, t = 0;
  bool zero = true;
  for (i64 s = 0; s < ea + eb; ++s) {
    bool ta = walk_take_a(S, i, t, sa, sbm, ea, eb);
    Sub e = pick(S, ta, i, t);
    FilterSign f =
        filter_sign((e.p1x - e.p0x) * (e.qy - e.p0y), (e.p1y - e.p0y) * (e.qx - e.p0x));
    int o = f.sign;
    if (__builtin_expect(!f.certain, 0))
      o = cross_sign(e.p0x, e.p0y, e.p1x, e.p1y, e.p0x, e.p0y, e.qx, e.qy);
    if (o < 0) return 0;
    zero &= o == 0;
    i += ta ? 1 : 0;
    t += ta ? 0 : 1;
  }
  if (!zero) return 1;
  // every edge line passes through the origin: D is a segment on a line through it
  return on_degenerate(A, B, S);
}

// The sub-edges of D and each one's accurate cross value cv in one pass over gathered
// coordinates. Returns the number of sub-edges. (Value range.)
inline i64 walk(const Poly& A, const Poly& B, Scratch& S) {
  gather(A, B, S);
  i64 na = A.n, nb = B.n;
  i64 ea = na > 1 ? na : 0, eb = nb > 1 ? nb : 0;
  i64 s = B.s % nb, sa = A.s, sbm = nb > 1 ? nb - B.s : 0;
  i64 i = 0, t = 0;
  for (i64 k = 0; k < ea + eb; ++k) {
    bool ta = walk_take_a(S, i, t, sa, sbm, ea, eb);
    Sub e = pick(S, ta, i, t);
    S.cv[k] = cross_value(e.p0x, e.p0y, e.p1x, e.p1y, e.p0x, e.p0y, e.qx, e.qy);
    S.kind[k] = ta ? 0 : 1;
    S.ii[k] = i < na ? i : 0;
    i64 w = s + t;
    S.jj[k] = w < nb ? w : w - nb;
    i += ta ? 1 : 0;
    t += ta ? 0 : 1;
  }
  return ea + eb;
}

// Result row for a sub-edge feature at signed depth: point on Y = q, point on X =
// q +- depth * normal (D's outward unit normal along the sub-edge).
inline void write_edge(double* out, int kind, const Feat& f, double depth, double inv) {
  const double *X = f.X, *Y = f.Y;
  double ex = (X[2 * f.p1] - X[2 * f.p0]) * inv;
  double ey = (X[2 * f.p1 + 1] - X[2 * f.p0 + 1]) * inv;
  double nx, ny;
  if (kind == 0) {
    nx = ey;
    ny = -ex;
  } else {
    nx = -ey;
    ny = ex;
  }
  out[0] = depth;
  out[1] = nx + 0.0;  // no -0.0
  out[2] = ny + 0.0;
  double qx = Y[2 * f.q], qy = Y[2 * f.q + 1], fx, fy;
  if (depth == 0.0) {
    fx = qx;
    fy = qy;
  } else if (kind == 0) {
    fx = qx + depth * nx;
    fy = qy + depth * ny;
  } else {
    fx = qx - depth * nx;
    fy = qy - depth * ny;
  }
  if (kind == 0) {
    out[3] = fx;
    out[4] = fy;
    out[5] = qx;
    out[6] = qy;
  } else {
    out[3] = qx;
    out[4] = qy;
    out[5] = fx;
    out[6] = fy;
  }
}

// Result row for a vertex feature a - b of D with the origin outside (or at it).
inline void write_vertex(double* out, const double* pa, i64 a, const double* pb, i64 b) {
  double dx = pb[2 * b] - pa[2 * a], dy = pb[2 * b + 1] - pa[2 * a + 1];
  double d = len(dx, dy);
  out[0] = -d;
  if (d > 0.0) {
    out[1] = dx / d + 0.0;
    out[2] = dy / d + 0.0;
  } else {
    out[1] = 0.0;
    out[2] = 0.0;
  }
  out[3] = pa[2 * a];
  out[4] = pa[2 * a + 1];
  out[5] = pb[2 * b];
  out[6] = pb[2 * b + 1];
}

inline double inv_len(const Feat& f) {
  return 1.0 / len(f.X[2 * f.p1] - f.X[2 * f.p0], f.X[2 * f.p1 + 1] - f.X[2 * f.p0 + 1]);
}

// Whether the origin lies in the normal cone of D's vertex k (start of sub-edge k):
// dot(-v_k, e_k) <= 0 and dot(-v_k, e_{k-1}) >= 0.
inline bool vertex_ok(const Poly& A, const Poly& B, const Scratch& S, i64 K, i64 k) {
  const std::int8_t* kind = S.kind.data();
  if (fdot0(feature(A, B, kind, S.ii.data(), S.jj.data(), k)) > 0) return false;
  i64 km = k > 0 ? k - 1 : K - 1;
  return fdot1(feature(A, B, kind, S.ii.data(), S.jj.data(), km)) >= 0;
}

// Nearest point of D to the origin, which lies outside D; vis[k] is the exact sign of
// orient for sub-edge k. Writes the result row (signed depth = -distance).
inline void separated(const Poly& A, const Poly& B, const Scratch& S, i64 K, double* out) {
  const std::int8_t* kind = S.kind.data();
  const i64* ii = S.ii.data();
  const i64* jj = S.jj.data();
  bool any_vis = false;
  for (i64 k = 0; k < K; ++k) {
    if (S.vis[k] >= 0) continue;
    any_vis = true;
    Feat f = feature(A, B, kind, ii, jj, k);
    int d0 = fdot0(f), d1 = fdot1(f);
    if (d0 > 0 && d1 < 0) {
      double inv = inv_len(f);
      write_edge(out, kind[k], f, S.cv[k] * inv, inv);
      return;
    }
    if (d0 <= 0 && vertex_ok(A, B, S, K, k)) {
      write_vertex(out, A.p, A.ix[ii[k]], B.p, B.ix[jj[k]]);
      return;
    }
    i64 k1 = k + 1 < K ? k + 1 : 0;
    if (d1 >= 0 && vertex_ok(A, B, S, K, k1)) {
      write_vertex(out, A.p, A.ix[ii[k1]], B.p, B.ix[jj[k1]]);
      return;
    }
  }
  if (!any_vis) {
    // D is a segment and the origin on its line, beyond one end
    for (i64 k = 0; k < K; ++k)
      if (vertex_ok(A, B, S, K, k)) {
        write_vertex(out, A.p, A.ix[ii[k]], B.p, B.ix[jj[k]]);
        return;
      }
  }
  out[0] = std::numeric_limits<double>::quiet_NaN();  // unreachable for valid input
}

// A point of A and B when the origin is strictly inside D: the fan triangle
// (v_0, v_m, v_m+1) of D holding the origin, found by exact binary search, and the
// origin's barycentric weights (float) applied to the vertices of A and of B. The two
// weighted points agree up to rounding; their midpoint is computed once and written as
// both witnesses (so point_a == point_b exactly, as documented).
inline void common_point(const Poly& A, const Poly& B, const Scratch& S, i64 K, double* out) {
  const double* pa = A.p;
  const double* pb = B.p;
  const i64* ii = S.ii.data();
  const i64* jj = S.jj.data();
  double c[16];
  i64 a0 = A.ix[ii[0]], b0 = B.ix[jj[0]];
  i64 lo = 1, hi = K - 1;
  // f(m) = orient(v0, v_m, origin) = cross(v_m - v0, b0 - a0): + at m = 1, - at m = K - 1
  while (hi - lo > 1) {
    i64 mid = (lo + hi) / 2;
    i64 am = A.ix[ii[mid]], bm = B.ix[jj[mid]];
    c[0] = pa[2 * am];
    c[1] = pa[2 * am + 1];
    c[2] = pa[2 * a0];
    c[3] = pa[2 * a0 + 1];
    c[4] = pb[2 * b0];
    c[5] = pb[2 * b0 + 1];
    c[6] = pb[2 * bm];
    c[7] = pb[2 * bm + 1];
    c[8] = pb[2 * b0];
    c[9] = pb[2 * b0 + 1];
    c[10] = pa[2 * a0];
    c[11] = pa[2 * a0 + 1];
    c[12] = c[13] = c[14] = c[15] = 0.0;
    if (cross44(c) >= 0)
      lo = mid;
    else
      hi = mid;
  }
  i64 a1 = A.ix[ii[lo]], b1 = B.ix[jj[lo]];
  i64 a2 = A.ix[ii[hi]], b2 = B.ix[jj[hi]];
  // The weights are cross products of D's vertices w_i = a_i - b_i. On a thin D a float
  // evaluation cancels catastrophically, so each is the accurate cross value of the two
  // differences.
  auto X = [](const double* p, i64 v) { return p[2 * v]; };
  auto Y = [](const double* p, i64 v) { return p[2 * v + 1]; };
  double l0 = std::max(cross_value(X(pb, b1), Y(pb, b1), X(pa, a1), Y(pa, a1), X(pb, b2),
                                   Y(pb, b2), X(pa, a2), Y(pa, a2)),
                       0.0);
  double l1 = std::max(cross_value(X(pb, b2), Y(pb, b2), X(pa, a2), Y(pa, a2), X(pb, b0),
                                   Y(pb, b0), X(pa, a0), Y(pa, a0)),
                       0.0);
  double l2 = std::max(cross_value(X(pb, b0), Y(pb, b0), X(pa, a0), Y(pa, a0), X(pb, b1),
                                   Y(pb, b1), X(pa, a1), Y(pa, a1)),
                       0.0);
  double s = l0 + l1 + l2;
  if (!(s > 0.0)) {
    l0 = 1.0;
    l1 = 0.0;
    l2 = 0.0;
    s = 1.0;
  }
  l0 /= s;
  l1 /= s;
  l2 /= s;
  double xa = l0 * X(pa, a0) + l1 * X(pa, a1) + l2 * X(pa, a2);
  double ya = l0 * Y(pa, a0) + l1 * Y(pa, a1) + l2 * Y(pa, a2);
  double xb = l0 * X(pb, b0) + l1 * X(pb, b1) + l2 * X(pb, b2);
  double yb = l0 * Y(pb, b0) + l1 * Y(pb, b1) + l2 * Y(pb, b2);
  // (halving is exact in the value range)
  double x = 0.5 * xa + 0.5 * xb, y = 0.5 * ya + 0.5 * yb;
  out[3] = x;
  out[4] = y;
  out[5] = x;
  out[6] = y;
}

// Distance (mode DISTANCE) or penetration (mode PENETRATION) of one pair; writes the
// result row and returns 1 when the polygons intersect (touching included).
inline int collide(const Poly& A, const Poly& B, int mode, Scratch& S, double* out) {
  if (A.n == 1 && B.n == 1) {
    write_vertex(out, A.p, A.ix[0], B.p, B.ix[0]);
    if (out[0] == 0.0) {
      out[0] = 0.0;  // no -0.0
      return 1;
    }
    return 0;
  }
  i64 K = walk(A, B, S);
  const std::int8_t* kind = S.kind.data();
  const i64* ii = S.ii.data();
  const i64* jj = S.jj.data();
  bool neg = false, allzero = true;
  for (i64 k = 0; k < K; ++k) {
    int o = sgnd(S.cv[k]);
    S.vis[k] = (std::int8_t)o;
    neg |= o < 0;
    allzero &= o == 0;
  }
  if (!neg && allzero) {
    // D is a segment on a line through the origin: on it or beyond an end?
    for (i64 k = 0; k < K; ++k) {
      Feat f = feature(A, B, kind, ii, jj, k);
      if (on_edge(f)) {
        write_edge(out, kind[k], f, 0.0, inv_len(f));
        return 1;
      }
    }
    neg = true;
  }
  if (neg) {
    separated(A, B, S, K, out);
    return 0;
  }
  // the origin is in D, which has an interior
  i64 best = -1;
  for (i64 k = 0; k < K; ++k) {
    if (S.vis[k] == 0 && on_edge(feature(A, B, kind, ii, jj, k))) {
      best = k;
      break;
    }
  }
  if (best >= 0) {  // touching: the origin is on D's boundary
    Feat f = feature(A, B, kind, ii, jj, best);
    write_edge(out, kind[best], f, 0.0, inv_len(f));
    return 1;
  }
  if (mode == DISTANCE) {
    out[0] = 0.0;
    out[1] = 0.0;
    out[2] = 0.0;
    common_point(A, B, S, K, out);
    return 1;
  }
  // penetration: the nearest edge line (its foot is on the edge)
  auto inv_of = [&](i64 k) { return kind[k] == 0 ? A.inv[ii[k]] : B.inv[jj[k]]; };
  double bd = std::numeric_limits<double>::infinity();
  for (i64 k = 0; k < K; ++k) {
    double d = S.cv[k] * inv_of(k);
    if (d < bd) {
      bd = d;
      best = k;
    }
  }
  Feat f = feature(A, B, kind, ii, jj, best);
  if (!on_edge(f)) {
    // a near tie picked an edge whose foot is off it: take the nearest edge among those
    // whose foot is on them (the true nearest is one of these)
    bd = std::numeric_limits<double>::infinity();
    for (i64 k = 0; k < K; ++k) {
      if (on_edge(feature(A, B, kind, ii, jj, k))) {
        double d = S.cv[k] * inv_of(k);
        if (d < bd) {
          bd = d;
          best = k;
        }
      }
    }
    f = feature(A, B, kind, ii, jj, best);
  }
  write_edge(out, kind[best], f, bd, inv_of(best));
  return 1;
}

// ------------------------------------------------------------------------------------
// GJK: support functions only, never the boundary of D

struct GjkCtx {
  const double* pa;
  const double* pb;
  const i64* ia;
  const i64* ib;
  double c[16];
  double ax(i64 t) const { return pa[2 * ia[t]]; }
  double ay(i64 t) const { return pa[2 * ia[t] + 1]; }
  double bx(i64 t) const { return pb[2 * ib[t]]; }
  double by(i64 t) const { return pb[2 * ib[t] + 1]; }
};

// c[0:8] = U = w1 - w0 = (a1 - a0) + (b0 - b1)
inline void set_u(GjkCtx& g, i64 w0a, i64 w0b, i64 w1a, i64 w1b) {
  double* c = g.c;
  c[0] = g.ax(w1a);
  c[1] = g.ay(w1a);
  c[2] = g.ax(w0a);
  c[3] = g.ay(w0a);
  c[4] = g.bx(w0b);
  c[5] = g.by(w0b);
  c[6] = g.bx(w1b);
  c[7] = g.by(w1b);
}

// sign of dot(p[v] - p[u], D) for the direction's unsigned form D:
// mode 0: D = b[w0b] - a[w0a]; mode 1: D = leftperp(w1 - w0), dot(X, D) = cross(w1 - w0, X).
inline int dir_sign(GjkCtx& g, const double* p, i64 u, i64 v, int mode, i64 w0a, i64 w0b,
                    i64 w1a, i64 w1b) {
  if (mode == 0)
    return dot_sign(p[2 * u], p[2 * u + 1], p[2 * v], p[2 * v + 1], g.ax(w0a), g.ay(w0a),
                    g.bx(w0b), g.by(w0b));
  set_u(g, w0a, w0b, w1a, w1b);
  double* c = g.c;
  c[8] = p[2 * v];
  c[9] = p[2 * v + 1];
  c[10] = p[2 * u];
  c[11] = p[2 * u + 1];
  c[12] = c[13] = c[14] = c[15] = 0.0;
  return cross44(c);
}

// Position of the vertex of polygon (p, ix[:n]) extreme in direction sign * d. A float
// scan proposes a vertex; exact hill-climbing on the (strictly convex) polygon then moves
// it to the exact maximizer (local = global on a convex polygon).
inline i64 support(GjkCtx& g, const double* p, const i64* ix, i64 n, double dx, double dy,
                   int sg, int mode, i64 w0a, i64 w0b, i64 w1a, i64 w1b, int sign) {
  i64 best = 0;
  double bv = -std::numeric_limits<double>::infinity();
  for (i64 t = 0; t < n; ++t) {
    double v = sign * (p[2 * ix[t]] * dx + p[2 * ix[t] + 1] * dy);
    if (v > bv) {
      bv = v;
      best = t;
    }
  }
  if (n == 1) return 0;
  while (true) {
    bool moved = false;
    for (i64 step : {(i64)1, n - 1}) {
      i64 nb_ = (best + step) % n;
      if (dir_sign(g, p, ix[best], ix[nb_], mode, w0a, w0b, w1a, w1b) * (sign * sg) > 0) {
        best = nb_;
        moved = true;
        break;
      }
    }
    if (!moved) return best;
  }
}

// sign of cross(U, X) (or of dot(U, X) when rot) with U = w(ua1, ub1) - w(ua0, ub0) and
// X = w(xa1, xb1) - w(xa0, xb0); w(i, j) = a_i - b_j; xa0 < 0 means X = w(xa1, xb1).
inline int wcross(GjkCtx& g, i64 ua0, i64 ub0, i64 ua1, i64 ub1, i64 xa1, i64 xb1, i64 xa0,
                  i64 xb0, bool rot) {
  double* c = g.c;
  if (rot) {
    c[0] = g.ay(ua1);
    c[1] = -g.ax(ua1);
    c[2] = g.ay(ua0);
    c[3] = -g.ax(ua0);
    c[4] = g.by(ub0);
    c[5] = -g.bx(ub0);
    c[6] = g.by(ub1);
    c[7] = -g.bx(ub1);
  } else {
    c[0] = g.ax(ua1);
    c[1] = g.ay(ua1);
    c[2] = g.ax(ua0);
    c[3] = g.ay(ua0);
    c[4] = g.bx(ub0);
    c[5] = g.by(ub0);
    c[6] = g.bx(ub1);
    c[7] = g.by(ub1);
  }
  c[8] = g.ax(xa1);
  c[9] = g.ay(xa1);
  c[10] = g.bx(xb1);
  c[11] = g.by(xb1);
  if (xa0 < 0) {
    c[12] = c[13] = c[14] = c[15] = 0.0;
  } else {
    c[12] = g.bx(xb0);
    c[13] = g.by(xb0);
    c[14] = g.ax(xa0);
    c[15] = g.ay(xa0);
  }
  return cross44(c);
}

// sign dot(-w_f, w_t - w_f) with w = a - b: the origin projects past w_f toward w_t.
inline int seg_dot(GjkCtx& g, i64 fa, i64 fb, i64 ta, i64 tb) {
  // dot(w_t - w_f, -w_f) = dot(U, X) with U = w_t - w_f, X = 0 - w_f = b_f - a_f
  double* c = g.c;
  c[0] = g.ay(ta);
  c[1] = -g.ax(ta);
  c[2] = g.ay(fa);
  c[3] = -g.ax(fa);
  c[4] = g.by(fb);
  c[5] = -g.bx(fb);
  c[6] = g.by(tb);
  c[7] = -g.bx(tb);
  c[8] = g.bx(fb);
  c[9] = g.by(fb);
  c[10] = g.ax(fa);
  c[11] = g.ay(fa);
  c[12] = c[13] = c[14] = c[15] = 0.0;
  return cross44(c);
}

// sign cross(w_t - w_f, -w_f): the origin is left (+1) of the line w_f -> w_t.
inline int side(GjkCtx& g, i64 fa, i64 fb, i64 ta, i64 tb) {
  double* c = g.c;
  c[0] = g.ax(ta);
  c[1] = g.ay(ta);
  c[2] = g.ax(fa);
  c[3] = g.ay(fa);
  c[4] = g.bx(fb);
  c[5] = g.by(fb);
  c[6] = g.bx(tb);
  c[7] = g.by(tb);
  c[8] = g.bx(fb);
  c[9] = g.by(fb);
  c[10] = g.ax(fa);
  c[11] = g.ay(fa);
  c[12] = c[13] = c[14] = c[15] = 0.0;
  return cross44(c);
}

// Exact 2-D GJK on A + (-B) through support functions. Returns 1 (origin in D, touching
// included), 0 (separated), or -1 (iteration cap: a bug). Simplex points are index
// pairs (i, j) standing for a_i - b_j, so every test is an exact sign; the direction is
// -w (point simplex) or the normal of the segment simplex facing the origin, both kept
// symbolically; "separated" is claimed only on an exact certificate; the origin on a
// simplex edge or vertex counts as contained; triangles are never degenerate; the
// distance to the simplex strictly decreases (the cap is only a guard).
inline int gjk(const Poly& A, const Poly& B) {
  GjkCtx g{A.p, B.p, A.ix, B.ix, {}};
  const i64 na = A.n, nb = B.n;
  i64 sa_[3] = {0, 0, 0}, sb_[3] = {0, 0, 0};
  int m = 1;
  if (g.ax(0) == g.bx(0) && g.ay(0) == g.by(0)) return 1;
  int mode = 0;  // 0: d = -w0; 1: d = sgn * leftperp(w1 - w0)
  int sgn = 1;
  i64 cap = na * nb + 8;
  for (i64 it = 0; it < cap; ++it) {
    double dx, dy;
    i64 w0a, w0b, w1a, w1b;
    if (mode == 0) {
      w0a = sa_[0];
      w0b = sb_[0];
      dx = g.bx(w0b) - g.ax(w0a);
      dy = g.by(w0b) - g.ay(w0a);
      w1a = w0a;
      w1b = w0b;
    } else {
      w0a = sa_[0];
      w0b = sb_[0];
      w1a = sa_[1];
      w1b = sb_[1];
      double ux = (g.ax(w1a) - g.ax(w0a)) + (g.bx(w0b) - g.bx(w1b));
      double uy = (g.ay(w1a) - g.ay(w0a)) + (g.by(w0b) - g.by(w1b));
      dx = -uy * sgn;
      dy = ux * sgn;
    }
    int sg = mode == 1 ? sgn : 1;
    i64 sA = support(g, A.p, A.ix, na, dx, dy, sg, mode, w0a, w0b, w1a, w1b, 1);
    i64 sB = support(g, B.p, B.ix, nb, dx, dy, sg, mode, w0a, w0b, w1a, w1b, -1);
    // exact sign of dot(w, d), w = a[sA] - b[sB]
    int h;
    if (mode == 0)
      h = dot_sign(g.bx(sB), g.by(sB), g.ax(sA), g.ay(sA), g.ax(w0a), g.ay(w0a), g.bx(w0b),
                   g.by(w0b));
    else
      h = sgn * wcross(g, w0a, w0b, w1a, w1b, sA, sB, -1, -1, false);
    if (h < 0) return 0;
    if (g.ax(sA) == g.bx(sB) && g.ay(sA) == g.by(sB)) return 1;  // the origin is a vertex
    if (m == 1) {
      // segment {w0, w}
      int t1 = seg_dot(g, sA, sB, sa_[0], sb_[0]);
      if (t1 <= 0) {
        sa_[0] = sA;
        sb_[0] = sB;
        mode = 0;
        continue;
      }
      int t0 = seg_dot(g, sa_[0], sb_[0], sA, sB);
      if (t0 <= 0) {
        mode = 0;
        continue;
      }
      int s = side(g, sa_[0], sb_[0], sA, sB);
      if (s == 0) return 1;
      sa_[1] = sA;
      sb_[1] = sB;
      m = 2;
      mode = 1;
      sgn = s;
      continue;
    }
    // triangle {w0, w1, w2 = w}
    i64 i0 = sa_[0], j0 = sb_[0], i1 = sa_[1], j1 = sb_[1];
    // tau = orientation of (w0, w1, w2) = cross(w1 - w0, w2 - w0)
    int tau = wcross(g, i0, j0, i1, j1, sA, sB, i0, j0, false);
    if (tau == 0) return -1;
    bool outa = side(g, i0, j0, sA, sB) == tau;
    bool outb = side(g, i1, j1, sA, sB) == -tau;
    if (!outa && !outb) return 1;
    bool done = false;
    for (int e = 0; e < 2; ++e) {
      if ((e == 0 && !outa) || (e == 1 && !outb)) continue;
      i64 fi = e == 0 ? i0 : i1, fj = e == 0 ? j0 : j1;
      if (seg_dot(g, fi, fj, sA, sB) > 0 && seg_dot(g, sA, sB, fi, fj) > 0) {
        sa_[0] = fi;
        sb_[0] = fj;
        sa_[1] = sA;
        sb_[1] = sB;
        sgn = side(g, fi, fj, sA, sB);
        mode = 1;
        m = 2;
        done = true;
        break;
      }
    }
    if (done) continue;
    // a vertex region: the new point's (the others are guards)
    i64 vi = sA, vj = sB;
    if (!(seg_dot(g, sA, sB, i0, j0) <= 0 && seg_dot(g, sA, sB, i1, j1) <= 0)) {
      if (seg_dot(g, i0, j0, i1, j1) <= 0 && seg_dot(g, i0, j0, sA, sB) <= 0) {
        vi = i0;
        vj = j0;
      } else {
        vi = i1;
        vj = j1;
      }
    }
    sa_[0] = vi;
    sb_[0] = vj;
    m = 1;
    mode = 0;
  }
  return -1;
}

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

}  // namespace coll
}  // namespace mk
