// collision_walk.hpp -- collision.hpp's boundary walk: the boundary of D = A + (-B) in
// order without storing it (intersects), or stored with each sub-edge's cross value
// (walk) for distance and penetration (collide), and the result rows.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "collision_prep.hpp"
#include "exact.hpp"

namespace mk {
namespace coll {

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
  // exact.hpp's filter: +1 / -1 when certified, 0 when it cannot tell
  int f = filter_sign((ax1 - ax0) * (by0 - by1), (ay1 - ay0) * (bx0 - bx1));
  bool ha = i >= sa, hb = t >= sbm, same = ha == hb;
  bool ta = same ? f > 0 : !ha;
  if (__builtin_expect(same & (f == 0) & (i < ea) & (t < eb), 0))
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
    int o = filter_sign((e.p1x - e.p0x) * (e.qy - e.p0y), (e.p1y - e.p0y) * (e.qx - e.p0x));
    if (__builtin_expect(o == 0, 0))
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

}  // namespace coll
}  // namespace mk
