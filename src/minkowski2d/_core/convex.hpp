// convex.hpp -- normalization, convexity and the O(n + m) merge of convex polygons.
//
// One normalization and one merge serve the single call, the batch, the trace and the
// collision walks. Polygons are (n, 2) row-major coordinate arrays of T (int64_t with
// |x| < 2^62, or finite double); every decision goes through exact.hpp (cross_sign and
// orient; the turn pass counts the turns filter_sign certifies, the others go exact).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "exact.hpp"

namespace mk {

// The edge i -> j points into the half-plane y > 0, or along +x.
template <class T>
inline bool upper(const T* p, i64 i, i64 j) {
  return p[2 * j + 1] > p[2 * i + 1] || (p[2 * j + 1] == p[2 * i + 1] && p[2 * j] > p[2 * i]);
}

// A normalized polygon: k vertices, CCW from the bottom-most (lowest y, then lowest x),
// no duplicate or collinear vertex; `split` is the index of the first edge pointing into
// the lower half-plane. Position t is idx[t] (explicit) or, when step != 0, the implicit
// rotation b + step * t wrapped into [lo, lo + n) -- no index array is written then.
struct Norm {
  i64 k = 0, split = 0, b = 0, step = 0, lo = 0, n = 0;
  const i64* idx = nullptr;
  int code = OK;
  i64 vertex = 0;  // offending vertex (relative to lo) when code != OK
  u64 maxexp = ~u64(0);  // doubles: largest exponent field (all bits: unknown)
  inline i64 at(i64 t) const {
    if (step == 0) return t < k ? idx[t] : idx[0];
    i64 v = b + step * t;
    if (v >= lo + n)
      v -= n;
    else if (v < lo)
      v += n;
    return v;
  }
};

template <class T>
inline bool finite_coord(T v) {
  if constexpr (std::is_floating_point_v<T>)
    return v - v == 0;
  else
    return true;
}

// Start-independent test for the common case: every vertex distinct, every turn strictly
// the same way (certain under the filter), one upper->lower transition. +1 CCW, -1 CW,
// 0 unsure (the general pass decides), 2 a non-finite coordinate, 3 an int64 beyond the
// core's range (vertex in *bad).
template <class T>
inline int fast_check(const T* p, i64 lo, i64 hi, i64* bad, u64* maxexp, i64* lowup = nullptr,
                      i64* uplow = nullptr) {
  i64 n = hi - lo;
  // doubles: non-finite <=> all exponent bits set. The max over the exponent fields is
  // taken in the turn pass below (one pass over the data), or here for n < 3; the
  // verdicts of that pass are only used once every coordinate is known to be finite.
  constexpr u64 EXP = 0x7ff0000000000000ull;
  u64 mx = 0;
  auto expmax = [&](i64 i) {
    if constexpr (std::is_floating_point_v<T>) {
      u64 bx, by;
      std::memcpy(&bx, p + 2 * i, sizeof bx);
      std::memcpy(&by, p + 2 * i + 1, sizeof by);
      bx &= EXP;
      by &= EXP;
      bx = bx > by ? bx : by;
      mx = bx > mx ? bx : mx;
    } else {
      (void)i;
    }
  };
  auto finite_or_bad = [&]() -> bool {
    if constexpr (std::is_floating_point_v<T>) {
      *maxexp = mx;
      if (mx == EXP) {
        for (i64 i = lo; i < hi; ++i)
          if (!(p[2 * i] - p[2 * i] == 0.0 && p[2 * i + 1] - p[2 * i + 1] == 0.0)) {
            *bad = i - lo;
            return false;
          }
      }
    }
    return true;
  };
  // int64: the __int128 cross products need |x| < 2^62. The range is checked in the turn
  // pass too (differences taken modulo 2^64 there, so out-of-range values cannot
  // overflow; their verdicts are discarded); RANGE sends the caller to the exact path.
  u64 racc = 0;
  auto rangeacc = [&](i64 i) {
    if constexpr (!std::is_floating_point_v<T>) {
      u64 x = (u64)p[2 * i] + (u64)(INT_LIMIT - 1), y = (u64)p[2 * i + 1] + (u64)(INT_LIMIT - 1);
      racc |= (x | y);
    } else {
      (void)i;
    }
  };
  auto in_range_or_bad = [&]() -> bool {
    if constexpr (!std::is_floating_point_v<T>) {
      if (racc >= (u64)(2 * (INT_LIMIT - 1) + 1)) {
        for (i64 i = lo; i < hi; ++i)
          if (p[2 * i] >= INT_LIMIT || p[2 * i] <= -INT_LIMIT || p[2 * i + 1] >= INT_LIMIT ||
              p[2 * i + 1] <= -INT_LIMIT) {
            *bad = i - lo;
            return false;
          }
      }
    }
    return true;
  };
  if (n < 3) {
    for (i64 i = lo; i < hi; ++i) expmax(i), rangeacc(i);
    if (!in_range_or_bad()) return 3;
    return finite_or_bad() ? 0 : 2;
  }
  i64 pos = 0, neg = 0, trans = 0, ilu = lo, iul = lo;
  // the turn at vertex i, from the edges h -> i -> k (branch-free; the middle loop has
  // no wrap-around, so the compiler can vectorize it)
  auto diff = [](T a, T b) -> T {
    if constexpr (std::is_floating_point_v<T>)
      return a - b;
    else
      return (T)((u64)a - (u64)b);  // wraps for out-of-range input (then discarded)
  };
  auto turn_at = [&](i64 h, i64 i, i64 k) {
    T ux = diff(p[2 * i], p[2 * h]), uy = diff(p[2 * i + 1], p[2 * h + 1]);
    T vx = diff(p[2 * k], p[2 * i]), vy = diff(p[2 * k + 1], p[2 * i + 1]);
    if constexpr (std::is_floating_point_v<T>) {
      filter_count(ux * vy, uy * vx, pos, neg);  // undecided: neither counts
    } else {
      i128 l = (i128)ux * vy, r = (i128)uy * vx;
      pos += l > r;
      neg += l < r;
    }
    bool up1 = (uy > 0) | ((uy == 0) & (ux > 0));
    bool up2 = (vy > 0) | ((vy == 0) & (vx > 0));
    trans += up1 & !up2;
    // the vertices where the edge directions cross between the half-planes (selects):
    // for a strictly convex counter-clockwise polygon, lower->upper is the bottom-most
    // vertex and upper->lower starts the first lower edge
    ilu = (!up1 & up2) ? i : ilu;
    iul = (up1 & !up2) ? i : iul;
    expmax(i);
    rangeacc(i);
  };
  turn_at(hi - 1, lo, lo + 1);
  for (i64 i = lo + 1; i < hi - 1; ++i) turn_at(i - 1, i, i + 1);
  turn_at(hi - 2, hi - 1, lo);
  if (!in_range_or_bad()) return 3;
  if (!finite_or_bad()) return 2;
  if (trans != 1) return 0;
  if (lowup) *lowup = ilu;
  if (uplow) *uplow = iul;
  if (pos == n) return 1;
  if (neg == n) return -1;
  return 0;
}

// normalize's other common case: p[lo:hi] strictly convex, turning s (clockwise: -1) at
// every vertex; the bottom-most vertex, and the split by binary search (the halves run
// upper...upper lower...lower from it).
template <class T>
inline void normalize_strict(const T* p, i64 lo, i64 hi, int s, Norm& r) {
  i64 n = hi - lo, b = lo;
  for (i64 i = lo + 1; i < hi; ++i)
    if (p[2 * i + 1] < p[2 * b + 1] || (p[2 * i + 1] == p[2 * b + 1] && p[2 * i] < p[2 * b]))
      b = i;
  r.k = n;
  r.b = b;
  r.step = s;
  i64 t0 = 0, t1 = n - 1;
  while (t0 < t1) {
    i64 tm = (t0 + t1) / 2;
    if (upper(p, r.at(tm), r.at(tm + 1)))
      t0 = tm + 1;
    else
      t1 = tm;
  }
  r.split = t0;
}

// Normalize the convex polygon p[lo:hi] (any orientation and start). keep (i64) and turn
// (int8) are scratch of size >= hi - lo; out receives the vertex indices unless the
// common case held (then step != 0 and out is not written).
template <class T>
inline Norm normalize(const T* p, i64 lo, i64 hi, i64* keep, std::int8_t* turn, i64* out) {
  Norm r;
  r.lo = lo;
  r.n = hi - lo;
  r.idx = out;
  i64 bad = 0, lowup = lo, uplow = lo;
  int s = fast_check(p, lo, hi, &bad, &r.maxexp, &lowup, &uplow);
  if (s == 2 || s == 3) {
    r.code = s == 2 ? NONFINITE : RANGE;
    r.vertex = bad;
    return r;
  }
  if (s == 1) {
    // counter-clockwise: the bottom-most vertex and the split came out of the turn pass
    i64 n = hi - lo;
    r.k = n;
    r.b = lowup;
    r.step = 1;
    r.split = uplow >= lowup ? uplow - lowup : uplow - lowup + n;
    return r;
  }
  if (s != 0) {
    normalize_strict(p, lo, hi, s, r);
    return r;
  }
  i64 m = 0;
  for (i64 i = lo; i < hi; ++i) {
    if (m == 0 || p[2 * i] != p[2 * keep[m - 1]] || p[2 * i + 1] != p[2 * keep[m - 1] + 1])
      keep[m++] = i;
  }
  while (m > 1 && p[2 * keep[m - 1]] == p[2 * keep[0]] &&
         p[2 * keep[m - 1] + 1] == p[2 * keep[0] + 1])
    --m;
  if (m == 1) {
    out[0] = keep[0];
    r.k = 1;
    r.split = 1;
    return r;
  }
  i64 b = 0;
  for (i64 t = 1; t < m; ++t) {
    i64 i = keep[t], j = keep[b];
    if (p[2 * i + 1] < p[2 * j + 1] || (p[2 * i + 1] == p[2 * j + 1] && p[2 * i] < p[2 * j]))
      b = t;
  }
  int sg = 0;
  for (i64 t = 0; t < m; ++t) {
    i64 prv = keep[(b + t - 1 + m) % m], cur = keep[(b + t) % m], nxt = keep[(b + t + 1) % m];
    int o = orient(p, prv, cur, nxt);
    turn[t] = (std::int8_t)o;
    if (o != 0) {
      if (sg == 0)
        sg = o;
      else if (o != sg) {
        r.code = TURNS_BOTH_WAYS;
        r.vertex = cur - lo;
        return r;
      }
    }
  }
  if (sg == 0) {  // all collinear: the segment between the extreme points
    i64 top = keep[0];
    for (i64 t = 1; t < m; ++t) {
      i64 i = keep[t];
      if (p[2 * i + 1] > p[2 * top + 1] || (p[2 * i + 1] == p[2 * top + 1] && p[2 * i] > p[2 * top]))
        top = i;
    }
    out[0] = keep[b];
    out[1] = top;
    r.k = 2;
    r.split = 1;
    return r;
  }
  i64 k = 0;
  for (i64 t = 0; t < m; ++t) {
    i64 tt = sg > 0 ? t : (m - t) % m;
    i64 cur = keep[(b + tt) % m];
    if (turn[tt] == 0) {
      i64 prv = keep[(b + tt - 1 + m) % m], nxt = keep[(b + tt + 1) % m];
      // parallel: straight on when both coordinate differences keep their signs
      if (sgn(p[2 * cur] - p[2 * prv]) != sgn(p[2 * nxt] - p[2 * cur]) ||
          sgn(p[2 * cur + 1] - p[2 * prv + 1]) != sgn(p[2 * nxt + 1] - p[2 * cur + 1])) {
        r.code = SPIKE;
        r.vertex = cur - lo;
        return r;
      }
      continue;
    }
    out[k++] = cur;
  }
  // the edge directions must sweep exactly one turn: halves 0...0 1...1 from the bottom
  i64 split = k;
  for (i64 t = 0; t < k; ++t) {
    bool up = upper(p, out[t], out[(t + 1) % k]);
    if (split == k) {
      if (!up) split = t;
    } else if (up) {
      r.code = WINDS_TWICE;
      r.vertex = out[t] - lo;
      return r;
    }
  }
  r.k = k;
  r.split = split;
  return r;
}

// Called once per merge step when recording (the animation's trace): source -1 = A,
// +1 = B, 0 = both; i, j the edge indices compared (-1 once a list is exhausted); c the
// cross-product sign that decided, or 2 when the half-planes or exhaustion decided.
enum StepSource : int { FROM_A = -1, FROM_BOTH = 0, FROM_B = 1 };
constexpr std::int8_t NO_CROSS = 2;  // Step::cross when no cross product decided

struct Step {
  std::int8_t source;  // a StepSource
  i64 i, j;
  std::int8_t cross;
};

// Merge the edges of two normalized polygons by angle: emit(ai, bj) is called for each
// vertex A[ai] + B[bj] of the sum, in order (at most A.k + B.k of them), and returns false
// to stop (a float coordinate overflowed). Returns the count, or -1 when stopped. With
// `rec`, one Step per merge step is appended.
template <class T, class Emit>
inline i64 merge_ids(const T* pa, const Norm& A, const T* pb, const Norm& B, Emit&& emit,
                     std::vector<Step>* rec = nullptr) {
  const i64 na = A.k, nb = B.k;
  const i64 ea = na > 1 ? na : 0, eb = nb > 1 ? nb : 0;
  const i64 sa = A.split < ea ? A.split : ea, sb = B.split < eb ? B.split : eb;
  i64 i = 0, j = 0, k = 0;
  i64 ai = A.at(0), a1 = na > 1 ? A.at(1) : ai;
  i64 bj = B.at(0), b1 = nb > 1 ? B.at(1) : bj;
  while (true) {
    if (!emit(ai, bj)) return -1;
    ++k;
    if (i >= ea && j >= eb) break;
    int step;
    std::int8_t c = NO_CROSS;
    if (i < ea && j < eb) {
      bool ha = i >= sa, hb = j >= sb;
      if (ha != hb) {
        step = ha ? 1 : -1;
      } else {
        T ux = pa[2 * a1] - pa[2 * ai], uy = pa[2 * a1 + 1] - pa[2 * ai + 1];
        T vx = pb[2 * b1] - pb[2 * bj], vy = pb[2 * b1 + 1] - pb[2 * bj + 1];
        int d;
        if constexpr (std::is_floating_point_v<T>) {
          d = filter_sign(ux * vy, uy * vx);  // the certified fallback when it cannot tell
          if (d == 0)
            d = cross_sign(pa[2 * ai], pa[2 * ai + 1], pa[2 * a1], pa[2 * a1 + 1], pb[2 * bj],
                           pb[2 * bj + 1], pb[2 * b1], pb[2 * b1 + 1]);
        } else {
          i128 l = (i128)ux * vy, r = (i128)uy * vx;
          d = (l > r) - (l < r);
        }
        c = (std::int8_t)d;
        step = -d;
      }
    } else if (i < ea) {
      step = -1;
    } else {
      step = 1;
    }
    if (rec) rec->push_back(Step{(std::int8_t)step, i < ea ? i : -1, j < eb ? j : -1, c});
    if (step <= 0) {
      ++i;
      ai = a1;
      if (i + 1 <= na) a1 = A.at(i + 1);
    }
    if (step >= 0) {
      ++j;
      bj = b1;
      if (j + 1 <= nb) b1 = B.at(j + 1);
    }
    if (i >= ea && j >= eb) break;
  }
  return k;
}

// Merge the edges of two normalized polygons by angle; write the sum's vertices to out
// (row-major, room for A.k + B.k rows). Returns the count, or -1 if a float coordinate
// of the sum overflowed. With `rec`, one Step per merge step is appended.
template <class T>
inline i64 merge(const T* pa, const Norm& A, const T* pb, const Norm& B, T* out,
                 std::vector<Step>* rec = nullptr) {
  // |a| and |b| below 2^1022 each: no sum can overflow, skip the per-vertex check
  constexpr u64 SAFE = u64(0x7fd) << 52;
  const bool check = !(A.maxexp < SAFE && B.maxexp < SAFE);
  T* o = out;
  return merge_ids(
      pa, A, pb, B,
      [&](i64 ai, i64 bj) {
        T x = pa[2 * ai] + pb[2 * bj], y = pa[2 * ai + 1] + pb[2 * bj + 1];
        o[0] = x;
        o[1] = y;
        o += 2;
        if constexpr (std::is_floating_point_v<T>) {
          if (check && (x - x != 0 || y - y != 0)) return false;
        } else {
          (void)check;
        }
        return true;
      },
      rec);
}

// Andrew's monotone chain over p[order] (sorted by x, then y); writes hull indices CCW
// from the lowest-x point into h (size 2n + 1); returns their count. Collinear dropped.
template <class T>
inline i64 hull_sorted(const T* p, const i64* order, i64 n, i64* h) {
  i64 k = 0;
  for (i64 t = 0; t < n; ++t) {
    i64 i = order[t];
    while (k >= 2 && orient(p, h[k - 2], h[k - 1], i) <= 0) --k;
    h[k++] = i;
  }
  i64 lower = k + 1;
  for (i64 t = n - 2; t >= 0; --t) {
    i64 i = order[t];
    while (k >= lower && orient(p, h[k - 2], h[k - 1], i) <= 0) --k;
    h[k++] = i;
  }
  return k > 0 ? k - 1 : 0;
}

// The convex pieces (ragged: coordinates and offsets) of two operands normalized for the
// merge: A's norms (vertex ids in ia), B's (in ib).
struct PiecePair {
  std::vector<Norm> A, B;
  std::vector<i64> ia, ib;
};

// OK, or the code of the first piece that is not a proper convex polygon (*bad: its
// index, B's after A's).
inline int normalize_pieces(const double* pa, const i64* oa, i64 na, const double* pb,
                            const i64* ob, i64 nb, PiecePair& pp, i64* bad = nullptr) {
  pp.A.assign(na, Norm{});
  pp.B.assign(nb, Norm{});
  i64 big = 1;
  for (i64 k = 0; k < na; ++k) big = std::max(big, oa[k + 1] - oa[k]);
  for (i64 k = 0; k < nb; ++k) big = std::max(big, ob[k + 1] - ob[k]);
  std::vector<i64> keep(big);
  std::vector<std::int8_t> turn(big);
  pp.ia.assign(oa[na] > 0 ? oa[na] : 1, 0);
  pp.ib.assign(ob[nb] > 0 ? ob[nb] : 1, 0);
  for (i64 k = 0; k < na + nb; ++k) {
    const bool isa = k < na;
    const i64 q = isa ? k : k - na;
    Norm& N = isa ? pp.A[q] : pp.B[q];
    N = isa ? normalize(pa, oa[q], oa[q + 1], keep.data(), turn.data(), pp.ia.data() + oa[q])
            : normalize(pb, ob[q], ob[q + 1], keep.data(), turn.data(), pp.ib.data() + ob[q]);
    if (N.code) {
      if (bad) *bad = k;
      return N.code;
    }
  }
  return OK;
}

}  // namespace mk
