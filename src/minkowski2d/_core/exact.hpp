// exact.hpp -- the one home of minkowski2d's exact predicates.
//
// Every combinatorial decision of the library is the sign of a 2x2 determinant
// (a1 - a0) x (b1 - b0). Two coordinate types reach it:
//
//  * int64_t, with |x| < 2^62 (the dispatcher routes larger ints to Python's exact path):
//    differences fit in int64 and their products in __int128, so the sign is exact.
//  * double, any finite value from subnormals to DBL_MAX: Shewchuk's filter decides when
//    |l - r| > (3 eps + 16 eps^2)(|l| + |r|) and no product underflowed or overflowed (an
//    inf or NaN anywhere means "undecided", never "zero"); otherwise the exact sign comes
//    from a fixed-point (Kulisch) accumulator that holds the 8 exact products
//    a_i * b_j of the expanded determinant at every magnitude -- no range limit, no rescale.
//
// One filter (filter_count, filter_sign) and one fallback (cross_sign_slow) serve every orientation
// sign: cross_sign, its point and index forms orient, and convex.hpp's turn pass.
// The expansion arithmetic below (two_sum, two_diff, two_prod, grow) is the one copy of
// the error-free transformations: the Sterbenz stage of cross_sign's fallback and the
// places where an exact *value* is needed (collision witnesses, the overlay's DD points);
// it is exact while every nonzero |coordinate| lies in [2^-400, 2^400] (see
// in_expansion_range). This file must be compiled without
// -ffast-math and with -ffp-contract=off: a fused multiply-add breaks the error-free
// transformations (tests/test_core.py checks the built module).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <limits>

namespace mk {

using i64 = std::int64_t;
using u64 = std::uint64_t;
using i128 = __int128;
using u128 = unsigned __int128;

// Status codes shared with Python (minkowski2d._engine.core.Status mirrors these by name).
enum Status : int {
  OK = 0,
  TURNS_BOTH_WAYS = 1,  // a convex routine got a polygon that turns both ways
  SPIKE = 2,            // the boundary doubles back on itself
  WINDS_TWICE = 3,      // the edge directions wind around more than once
  OVERFLOW = 4,         // a float result coordinate is not finite
  NONFINITE = 5,        // an input coordinate is NaN or infinite
  RANGE = 6,            // values this path cannot take exactly: the caller goes exact-Python
  UNHANDLED = 7,        // input of a kind this fast path does not read (list path)
  SHAPE = 8,            // not an (n, 2) sequence of pairs
  EMPTY = 9,            // no vertices
  INVALID_POLYGON = 10,  // not a valid polygon: the reason (enum Invalid) says why
  INTERNAL = 11,         // an internal consistency check failed (a bug: please report it)
  RESOURCE = 12,         // the work would exceed a limit (crossings, segments, pieces)
};

// Why a polygon is invalid (Status INVALID_POLYGON), with the ring and the vertex that
// starts the offending edge (minkowski2d._engine.polygon turns these into messages).
enum Invalid : int {
  RING_FEW_VERTICES = 1,  // a ring has fewer than 3 distinct vertices
  RING_NO_AREA = 2,       // all vertices of a ring lie on one line
  RING_SPIKE = 3,         // a ring doubles back on itself at a vertex
  RING_CROSSES = 4,       // two edges of one ring cross
  RING_OVERLAPS = 5,      // two edges of one ring share a segment
  RING_TOUCHES = 6,       // two non-consecutive edges of one ring share a point
  RINGS_CROSS = 7,        // two rings of one polygon cross (also through a shared point)
  RINGS_OVERLAP = 8,      // two rings of one polygon share a segment
  HOLE_OUTSIDE = 9,       // a hole does not lie inside the shell
  HOLE_IN_HOLE = 10,      // a hole lies inside another hole
  POLYGONS_OVERLAP = 11,  // two polygons of a collection overlap (checked on request)
};

constexpr double EPS = 1.1102230246251565e-16;                 // 2^-53
constexpr double ERRBOUND = (3.0 + 16.0 * EPS) * EPS;          // Shewchuk's ccwerrboundA
// The filter's bound is relative; its proof assumes no product underflows. Below this
// bound value (|l| + |r| < 2^-960) the exact evaluation decides.
constexpr double MINBOUND = ERRBOUND * 0x1p-960;
// int64 coordinates must satisfy |x| < INT_LIMIT for the __int128 cross products.
constexpr i64 INT_LIMIT = (i64)1 << 62;
// "no limit" for the work budgets (crossings, candidate pairs, segments): a count no run
// reaches (the same value as INT_LIMIT, a different meaning).
constexpr i64 NO_LIMIT = (i64)1 << 62;
// ints with |x| <= FLOAT_EXACT_INT convert to float64 exactly (2^53).
constexpr i64 FLOAT_EXACT_INT = (i64)1 << 53;
constexpr double SPLITTER = 134217729.0;  // 2^27 + 1
constexpr double X_HI = 0x1p400;          // expansion range (values only, not signs)
constexpr double X_LO = 0x1p-400;

template <class T>
inline int sgn(T v) {
  return (v > 0) - (v < 0);
}

// ------------------------------------------------------------------------------------
// Kulisch accumulator: exact sums of products of doubles at every magnitude.

namespace detail {

struct Unpacked {
  u64 m;     // integer mantissa, < 2^53
  int e;     // exponent: |x| = m * 2^e
  bool neg;
};

inline Unpacked unpack(double x) {
  u64 bits;
  std::memcpy(&bits, &x, sizeof bits);
  Unpacked u;
  u.neg = (bits >> 63) != 0;
  int ex = (int)((bits >> 52) & 0x7ff);
  u64 frac = bits & ((u64(1) << 52) - 1);
  if (ex == 0) {
    u.m = frac;
    u.e = -1074;
  } else {
    u.m = frac | (u64(1) << 52);
    u.e = ex - 1075;
  }
  return u;
}

// A fixed-point accumulator of WORDS 64-bit words whose lowest bit weighs 2^EMIN: exact
// sums of products of doubles (the terms are unsigned; signs go to a P and an N one).
template <int EMIN, int WORDS>
struct FixedAcc {
  u64 w[WORDS];
  int lo = WORDS, hi = -1;  // touched word range
  FixedAcc() { std::memset(w, 0, sizeof w); }
  // w += (v[0] + v[1] 2^64 + ... ) * 2^e for NV words v, exactly
  template <int NV>
  void add_words(const u64 (&v)[NV], int e) {
    const int pos = e - EMIN;
    const int word = pos >> 6, sh = pos & 63;
    u64 parts[NV + 1];
    parts[0] = v[0] << sh;
    for (int t = 1; t < NV; ++t) parts[t] = (v[t] << sh) | (sh ? v[t - 1] >> (64 - sh) : 0);
    parts[NV] = sh ? v[NV - 1] >> (64 - sh) : 0;
    u64 carry = 0;
    int k = word;
    for (int t = 0; t <= NV; ++t, ++k) {
      u128 sum = (u128)w[k] + parts[t] + carry;
      w[k] = (u64)sum;
      carry = (u64)(sum >> 64);
    }
    while (carry) {
      u128 sum = (u128)w[k] + carry;
      w[k] = (u64)sum;
      carry = (u64)(sum >> 64);
      ++k;
    }
    if (word < lo) lo = word;
    if (k - 1 > hi) hi = k - 1;
  }
};

// sign(P - N) for two accumulators
template <int EMIN, int WORDS>
inline int compare(const FixedAcc<EMIN, WORDS>& P, const FixedAcc<EMIN, WORDS>& N) {
  int top = P.hi > N.hi ? P.hi : N.hi;
  int bot = P.lo < N.lo ? P.lo : N.lo;
  for (int k = top; k >= bot && k >= 0; --k) {
    if (P.w[k] != N.w[k]) return P.w[k] > N.w[k] ? 1 : -1;
  }
  return 0;
}

// Products of two finite doubles are m * 2^e with e in [-2148, 1942] and m < 2^106.
constexpr int ACC_EMIN = -2148;
constexpr int ACC_WORDS = 68;  // 4352 bits: 2148 + 1942 + 106 + carry room
using Acc = FixedAcc<ACC_EMIN, ACC_WORDS>;

inline void add_product(Acc& P, Acc& N, double x, double y, bool negate) {
  if (x == 0.0 || y == 0.0) return;
  Unpacked a = unpack(x), b = unpack(y);
  u128 m = (u128)a.m * b.m;
  bool neg = (a.neg != b.neg) != negate;
  const u64 v[2] = {(u64)m, (u64)(m >> 64)};
  (neg ? N : P).add_words(v, a.e + b.e);
}

}  // namespace detail

// ------------------------------------------------------------------------------------
// Error-free transformations and expansions (exact within [X_LO, X_HI], see above).

inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  double bv = x - a, av = x - bv;
  y = (a - av) + (b - bv);
}

inline void two_diff(double a, double b, double& x, double& y) {
  x = a - b;
  double bv = a - x, av = x + bv;
  y = (a - av) + (bv - b);
}

inline void two_prod(double a, double b, double& x, double& y) {
  x = a * b;
  double c = SPLITTER * a;
  double ahi = c - (c - a), alo = a - ahi;
  c = SPLITTER * b;
  double bhi = c - (c - b), blo = b - bhi;
  double err = ((x - ahi * bhi) - alo * bhi) - ahi * blo;
  y = alo * blo - err;
}

// Add b to the nonoverlapping expansion e[0:m] in place (zero-eliminating); new length.
inline int grow(double* e, int m, double b) {
  double q = b, hh;
  int h = 0;
  for (int k = 0; k < m; ++k) {
    two_sum(q, e[k], q, hh);
    if (hh != 0.0) e[h++] = hh;
  }
  if (q != 0.0 || h == 0) e[h++] = q;
  return h;
}

// ------------------------------------------------------------------------------------
// The orientation sign: the filter, its certified fallback, the point and index forms.

// Exact sign of (a1 - a0) x (b1 - b0) for finite doubles, at any magnitude.
inline int cross_sign_exact(double a0x, double a0y, double a1x, double a1y, double b0x,
                            double b0y, double b1x, double b1y) {
  using detail::add_product;
  detail::Acc P, N;
  // (a1x - a0x)(b1y - b0y) - (a1y - a0y)(b1x - b0x), expanded into 8 exact products
  add_product(P, N, a1x, b1y, false);
  add_product(P, N, a1x, b0y, true);
  add_product(P, N, a0x, b1y, true);
  add_product(P, N, a0x, b0y, false);
  add_product(P, N, a1y, b1x, true);
  add_product(P, N, a1y, b0x, false);
  add_product(P, N, a0y, b1x, false);
  add_product(P, N, a0y, b0x, true);
  return detail::compare(P, N);
}

// Filtered sign of (a1 - a0) x (b1 - b0) for finite doubles.
// Collinear points are common (shared and overlapping edges) and their exact zero is
// beyond any filter. Nearby coordinates have exact differences (Sterbenz), and then the
// determinant is exactly l + lt - (r + rt) with the products and their error-free tails
// (Dekker): its sign is that of the sum of four doubles, found exactly by an expansion
// (two_sum; nonoverlapping, zeros dropped; the last component is the largest). Applies
// when the four differences are exact (two_diff tails zero) and lie within
// [2^-450, 2^450] (no split overflows, no tail underflows); returns 2 otherwise.
inline int cross_sign_small(double a0x, double a0y, double a1x, double a1y, double b0x,
                            double b0y, double b1x, double b1y, double ux, double uy, double vx,
                            double vy) {
  auto exact_diff = [](double a, double b) {  // is a - b a double (a zero two_diff tail)?
    double x, y;
    two_diff(a, b, x, y);
    return y == 0.0;
  };
  auto in_range = [](double d) {
    double m = std::fabs(d);
    return m >= 0x1p-450 && m <= 0x1p450;
  };
  if (!(in_range(ux) && in_range(uy) && in_range(vx) && in_range(vy))) return 2;
  if (!(exact_diff(a1x, a0x) && exact_diff(a1y, a0y) && exact_diff(b1x, b0x) &&
        exact_diff(b1y, b0y)))
    return 2;
  double l, r, lt, rt;
  two_prod(ux, vy, l, lt);
  two_prod(uy, vx, r, rt);
  if (lt == 0.0 && rt == 0.0) return (l > r) - (l < r);
  // e = l - r as a nonoverlapping expansion, then + lt, then - rt (grow, zeros dropped)
  double e[4];
  int m = 0;
  {
    double x, y;
    two_sum(l, -r, x, y);
    if (y != 0.0) e[m++] = y;
    if (x != 0.0 || m == 0) e[m++] = x;
  }
  m = grow(e, m, lt);
  m = grow(e, m, -rt);
  const double top = e[m - 1];
  return (top > 0) - (top < 0);
}

// the certified fallback of cross_sign (out of line: the filter stays small enough to inline)
[[gnu::noinline]] inline int cross_sign_slow(double a0x, double a0y, double a1x, double a1y,
                                             double b0x, double b0y, double b1x, double b1y,
                                             double ux, double uy, double vx, double vy) {
  int s = cross_sign_small(a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y, ux, uy, vx, vy);
  if (s != 2) return s;
  return cross_sign_exact(a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y);
}

// The float filter of every orientation sign, for the products l = ux vy and r = uy vx
// of the rounded coordinate differences: l - r is certified positive (pos += 1) or
// negative (neg += 1) when Shewchuk's bound ERRBOUND (|l| + |r|) says so and no product
// underflowed (the bound is at least MINBOUND); neither when it cannot tell (near zero,
// tiny, inf or NaN: never "zero"). Branch-free counts, so loops over it vectorize
// (convex.hpp's turn pass).
template <class C>
[[gnu::always_inline]] inline void filter_count(double l, double r, C& pos, C& neg) {
  const double det = l - r, bound = ERRBOUND * (std::fabs(l) + std::fabs(r));
  pos += (det > bound) & (bound >= MINBOUND);  // false for NaN; inf bounds never certify
  neg += (det < -bound) & (bound >= MINBOUND);
}
// the same as a sign: +1 / -1 when certified, 0 when the filter cannot tell
[[gnu::always_inline]] inline int filter_sign(double l, double r) {
  int pos = 0, neg = 0;
  filter_count(l, r, pos, neg);
  return pos - neg;
}

// Whether l1 - r1 and l2 - r2 certainly have opposite signs, for a vectorized pre-test
// that only skips work on a certain answer (planning.hpp's tangent pre-filter). The same
// bound without the MINBOUND test, which is vacuous under its precondition: every
// coordinate 0 or in [2^-400, 2^400], or an int of at most 2^53 (so a nonzero product of
// differences is at least 2^-904 and none underflows; NaN certifies nothing). Measured:
// the test costs the visibility graph's build about 5%, for no change in any result.
[[gnu::always_inline]] inline bool filter_apart(double l1, double r1, double l2, double r2) {
  const double d1 = l1 - r1, b1 = ERRBOUND * (std::fabs(l1) + std::fabs(r1));
  const double d2 = l2 - r2, b2 = ERRBOUND * (std::fabs(l2) + std::fabs(r2));
  return ((d1 > b1) & (-d2 > b2)) | ((-d1 > b1) & (d2 > b2));
}

// Exact sign of (a1 - a0) x (b1 - b0) for finite doubles: filter_sign, then
// cross_sign_slow when it cannot tell.
[[gnu::always_inline]] inline int cross_sign(double a0x, double a0y, double a1x, double a1y,
                                             double b0x, double b0y, double b1x, double b1y) {
  double ux = a1x - a0x, uy = a1y - a0y, vx = b1x - b0x, vy = b1y - b0y;
  // A zero difference is exact (x - y == 0 only when x == y) and so is the sign of any
  // difference (also when it overflows to +-inf); a product with a zero factor is zero.
  if (ux == 0.0 || vy == 0.0) return -(sgn(uy) * sgn(vx));
  if (uy == 0.0 || vx == 0.0) return sgn(ux) * sgn(vy);
  if (int s = filter_sign(ux * vy, uy * vx)) return s;
  return cross_sign_slow(a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y, ux, uy, vx, vy);
}

// Exact sign of (a1 - a0) x (b1 - b0) for int64 coordinates with |x| < 2^62.
inline int cross_sign(i64 a0x, i64 a0y, i64 a1x, i64 a1y, i64 b0x, i64 b0y, i64 b1x,
                      i64 b1y) {
  i128 l = (i128)(a1x - a0x) * (i128)(b1y - b0y);
  i128 r = (i128)(a1y - a0y) * (i128)(b1x - b0x);
  return (l > r) - (l < r);
}

// ------------------------------------------------------------------------------------
// The in-circle test (degree 4): used only to improve a triangulation (Delaunay flips),
// never to decide validity. Exact for all finite doubles.

namespace detail {

// Products of four finite doubles are m * 2^e with e in [-4296, 3884] and m < 2^212.
constexpr int ACC4_EMIN = -4296;
constexpr int ACC4_WORDS = 134;  // 8576 bits: 4296 + 3884 + 212 + carry room

using Acc4 = FixedAcc<ACC4_EMIN, ACC4_WORDS>;

// P or N += (a b c d), exactly
inline void add_product4(Acc4& P, Acc4& N, double a, double b, double c, double d, bool negate) {
  if (a == 0.0 || b == 0.0 || c == 0.0 || d == 0.0) return;
  Unpacked ua = unpack(a), ub = unpack(b), uc = unpack(c), ud = unpack(d);
  u128 m1 = (u128)ua.m * ub.m, m2 = (u128)uc.m * ud.m;  // each < 2^106
  u64 l1 = (u64)m1, h1 = (u64)(m1 >> 64), l2 = (u64)m2, h2 = (u64)(m2 >> 64);
  u128 p0 = (u128)l1 * l2, p1 = (u128)l1 * h2, p2 = (u128)h1 * l2, p3 = (u128)h1 * h2;
  u64 v[4];
  v[0] = (u64)p0;
  u128 t = (p0 >> 64) + (u64)p1 + (u64)p2;
  v[1] = (u64)t;
  t = (t >> 64) + (p1 >> 64) + (p2 >> 64) + (u64)p3;
  v[2] = (u64)t;
  t = (t >> 64) + (p3 >> 64);
  v[3] = (u64)t;
  bool neg = ((ua.neg != ub.neg) != (uc.neg != ud.neg)) != negate;
  (neg ? N : P).add_words(v, ua.e + ub.e + uc.e + ud.e);
}

}  // namespace detail

// Exact sign of the in-circle determinant: > 0 when d lies inside the circle through a, b,
// c (counter-clockwise), < 0 outside, 0 on it. The 4 x 4 determinant with rows
// (x, y, x^2 + y^2, 1) expanded into its 48 monomials of degree 4, each exact.
inline int incircle_exact(double ax, double ay, double bx, double by, double cx, double cy,
                          double dx, double dy) {
  const double X[4] = {ax, bx, cx, dx}, Y[4] = {ay, by, cy, dy};
  detail::Acc4 P, N;
  static const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  static const bool odd[6] = {false, true, true, false, false, true};
  for (int r = 0; r < 4; ++r) {  // Laplace along the column of ones: sign (-1)^(r + 3)
    int rows[3], q = 0;
    for (int i = 0; i < 4; ++i)
      if (i != r) rows[q++] = i;
    const bool neg_r = ((r + 3) & 1) != 0;
    for (int s = 0; s < 6; ++s) {
      const int i = rows[perm[s][0]], j = rows[perm[s][1]], k = rows[perm[s][2]];
      const bool neg = neg_r != odd[s];
      // x_i y_j (x_k^2 + y_k^2)
      detail::add_product4(P, N, X[i], Y[j], X[k], X[k], neg);
      detail::add_product4(P, N, X[i], Y[j], Y[k], Y[k], neg);
    }
  }
  return detail::compare(P, N);
}

// Filtered in-circle sign (Shewchuk's incircle, stage A), exact for all finite doubles.
// The filter's bound assumes no underflow or overflow: it is trusted only when every
// coordinate difference is 0 or within [2^-255, 2^255] (then every product of up to four
// of them is a normal double); otherwise the exact expansion decides.
inline int incircle(double ax, double ay, double bx, double by, double cx, double cy,
                    double dx, double dy) {
  const double adx = ax - dx, bdx = bx - dx, cdx = cx - dx;
  const double ady = ay - dy, bdy = by - dy, cdy = cy - dy;
  bool safe = true;
  for (double v : {adx, bdx, cdx, ady, bdy, cdy}) {
    double a = std::fabs(v);
    safe = safe && (a == 0.0 || (a >= 0x1p-255 && a <= 0x1p255));  // false for NaN
  }
  if (safe) {
    const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy, alift = adx * adx + ady * ady;
    const double cdxady = cdx * ady, adxcdy = adx * cdy, blift = bdx * bdx + bdy * bdy;
    const double adxbdy = adx * bdy, bdxady = bdx * ady, clift = cdx * cdx + cdy * cdy;
    const double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) +
                       clift * (adxbdy - bdxady);
    const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
                             (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
                             (std::fabs(adxbdy) + std::fabs(bdxady)) * clift;
    const double bound = (10.0 + 96.0 * EPS) * EPS * permanent;
    if (det > bound) return 1;
    if (-det > bound) return -1;
  }
  return incircle_exact(ax, ay, bx, by, cx, cy, dx, dy);
}

// (a1 - a0) x (b1 - b0) exactly into e (size >= 40), smallest component first.
inline int cross_expansion(double* e, double a0x, double a0y, double a1x, double a1y,
                           double b0x, double b0y, double b1x, double b1y) {
  double uxh, uxl, uyh, uyl, vxh, vxl, vyh, vyl, x, y;
  two_diff(a1x, a0x, uxh, uxl);
  two_diff(a1y, a0y, uyh, uyl);
  two_diff(b1x, b0x, vxh, vxl);
  two_diff(b1y, b0y, vyh, vyl);
  int m = 0;
  const double P[4][2] = {{uxh, vyh}, {uxh, vyl}, {uxl, vyh}, {uxl, vyl}};
  for (auto& pq : P) {
    two_prod(pq[0], pq[1], x, y);
    m = grow(e, m, y);
    m = grow(e, m, x);
  }
  const double Q[4][2] = {{uyh, vxh}, {uyh, vxl}, {uyl, vxh}, {uyl, vxl}};
  for (auto& pq : Q) {
    two_prod(pq[0], pq[1], x, y);
    m = grow(e, m, -y);
    m = grow(e, m, -x);
  }
  return m;
}

inline bool in_expansion_range(double x) {
  double a = std::fabs(x);
  return a == 0.0 || (a >= X_LO && a <= X_HI);
}

// Exact sign check used by the self-test: does the expansion machinery survive this build?
inline bool fp_contract_off_selftest() {
  // two_prod is exact only without FMA contraction; check on a value where it matters.
  volatile double a = 134217729.0 + 0.5, b = 134217727.0 - 0.25;  // 2^27 + ...
  double x, y;
  two_prod(a, b, x, y);
  // exact product via Kulisch
  detail::Acc P, N;
  detail::add_product(P, N, a, b, false);
  detail::add_product(P, N, x, 1.0, true);
  detail::add_product(P, N, y, 1.0, true);
  return detail::compare(P, N) == 0;
}

// Exact sign of the turn a -> b -> c, (b - a) x (c - a): +1 counter-clockwise, -1
// clockwise, 0 collinear (T: double or int64). The point form of cross_sign that every
// orientation test of the core goes through.
template <class T>
inline int orient(T ax, T ay, T bx, T by, T cx, T cy) {
  return cross_sign(ax, ay, bx, by, ax, ay, cx, cy);
}

// The same for the points i, j, k of a flat (n, 2) coordinate array (convex, decompose
// and triangulate use it).
template <class T>
inline int orient(const T* p, i64 i, i64 j, i64 k) {
  return orient(p[2 * i], p[2 * i + 1], p[2 * j], p[2 * j + 1], p[2 * k], p[2 * k + 1]);
}

}  // namespace mk
