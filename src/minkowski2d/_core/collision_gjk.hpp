// collision_gjk.hpp -- collision.hpp's exact GJK: support functions only, never the
// boundary of D = A + (-B); every test an exact sign of index pairs a_i - b_j.
#pragma once

#include <cstdint>
#include <limits>

#include "collision_prep.hpp"
#include "exact.hpp"

namespace mk {
namespace coll {

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

}  // namespace coll
}  // namespace mk
