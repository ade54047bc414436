// offset_curve.hpp -- the pieces of the offset (see offset.hpp, which includes it; include
// that): the exact predicates on doubles the construction decides with, the setup of
// one run, the offset curve of one ring (Curve: the segments and arcs around each edge
// and vertex, trimmed and certified), and the filling of shallow notches.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "boxes.hpp"
#include "exact.hpp"
#include "exactnum.hpp"
#include "minkowski.hpp"

namespace mk {
namespace off {

enum Join : int { ROUND = 0, MITER = 1, SQUARE = 2 };

// What went wrong with one polygon (beyond the Status codes of exact.hpp).
enum Code : int {
  FINE = 0,
  TOLERANCE = 1,    // the given tolerance is below `least`
  DISTANCE = 2,     // the default tolerance cannot be met: r / 2 < least
  UNDERFLOW = 3,    // a result of magnitude below 2^-1020 (rounding may exceed the margin)
  UNCERTIFIED = 4,  // a piece failed its exact certificate (never expected: a bug)
  OVERFLOWS = 5,    // a result coordinate beyond float64
  INPUT = 6,        // offset_polygons: not a valid polygonal set here (the reader decides)
};

// How the region of an offset was found (reported with each result, for the tests and the
// benchmark): the one curve itself (or nothing to offset), the resolver of a few
// crossings (offset_resolve.hpp), the overlay.
enum Path : int { DIRECT = 0, RESOLVED = 1, OVERLAID = 2 };

// label of a curve segment that is a detour through a vertex of the polygon
constexpr i64 DETOUR = -(i64(1) << 62);

struct Pt {
  double x, y;
};

// ------------------------------------------------------------------------------------
// exact predicates on doubles: filtered (FE), exact (Dy) when the filter cannot tell

inline FE num(FE, double x) { return FE{x, 0.0}; }
inline Dy num(const Dy&, double x) { return Dy(x); }

template <class F>
inline int sign_of(F&& f) {
  int s = fe_sign(f(FE{0.0, 0.0}));
  if (s != UNSURE) return s;
  return f(Dy()).sign();
}

// orientation of (a, b, c): +1 counter-clockwise
inline int orient(Pt a, Pt b, Pt c) { return mk::orient(a.x, a.y, b.x, b.y, c.x, c.y); }

// sign of (b - a) . (d - c): the cross product of b - a with d - c turned by 90 degrees
// (the points (-y, x): exact), so exact.hpp's filtered cross sign decides it
inline int dot_sign(Pt a, Pt b, Pt c, Pt d) {
  return mk::cross_sign(a.x, a.y, b.x, b.y, -c.y, c.x, -d.y, d.x);
}

// sign of dist(p, line ab)^2 - t^2, i.e. of cross(b - a, p - a)^2 - t^2 |b - a|^2
inline int line_dist_cmp(Pt a, Pt b, Pt p, double t) {
  return sign_of([&](auto z) {
    auto dx = num(z, b.x) - num(z, a.x), dy = num(z, b.y) - num(z, a.y);
    auto c = dx * (num(z, p.y) - num(z, a.y)) - dy * (num(z, p.x) - num(z, a.x));
    auto tt = num(z, t);
    return c * c - tt * tt * (dx * dx + dy * dy);
  });
}

// sign of |p - v|^2 - t^2
inline int dist_cmp(Pt v, Pt p, double t) {
  return sign_of([&](auto z) {
    auto dx = num(z, p.x) - num(z, v.x), dy = num(z, p.y) - num(z, v.y);
    auto tt = num(z, t);
    return dx * dx + dy * dy - tt * tt;
  });
}

// sign of dist(p, segment ab) - t (a segment of one point is that point)
inline int seg_dist_cmp(Pt a, Pt b, Pt p, double t) {
  if (dot_sign(a, p, a, b) <= 0) return dist_cmp(a, p, t);
  if (dot_sign(b, p, b, a) <= 0) return dist_cmp(b, p, t);
  return line_dist_cmp(a, b, p, t);
}

// x * 2^k as ldexp does (exact unless the result is subnormal), by at most two
// multiplications with normal powers of two: cheaper than ldexp in a loop
struct Pow2 {
  double a = 1, b = 1;
  explicit Pow2(int k) {
    int k1 = k / 2, k2 = k - k1;
    a = std::ldexp(1.0, k1);
    b = std::ldexp(1.0, k2);
  }
  double operator()(double x) const { return x * a * b; }
};

// rounded up / down (one step past the rounded value: an upper / lower bound)
inline double up(double x) { return std::nextafter(x, INFINITY); }
inline double down(double x) { return std::nextafter(x, -INFINITY); }

// The next and previous index around a ring of n, for 0 <= i < n, and i modulo n for
// -n <= i < 2n: without a division (the loops over curves take one per point)
template <class I>
inline I next_of(I i, I n) {
  return i + 1 == n ? 0 : i + 1;
}
template <class I>
inline I prev_of(I i, I n) {
  return i == 0 ? n - 1 : i - 1;
}
inline i64 wrap(i64 i, i64 n) { return i < 0 ? i + n : (i >= n ? i - n : i); }

// The index of the least (x, y) point of a nonempty list: on its hull (for a closed curve,
// on the outer boundary of the region it winds around), the first of equals.
inline i64 least_point(const std::vector<Pt>& p) {
  i64 h = 0;
  for (i64 k = 1; k < (i64)p.size(); ++k)
    if (p[k].x < p[h].x || (p[k].x == p[h].x && p[k].y < p[h].y)) h = k;
  return h;
}

// ------------------------------------------------------------------------------------
// parameters of one offset (scaled so that every coordinate is below 2)

struct Setup {
  bool grow = true;
  int join = ROUND;
  bool circ = true;   // circumscribed pieces (grow outer, shrink inner)
  double r = 0;       // radius
  double t_cov = 0;   // the pieces cover the band of this width
  double t_up = 0;    // ... and stay within this distance
  double mc = 0;      // construction margin
  double rho = 0;     // circ: moved edges' distance; inscribed: the points' radius
  double phimax = 0;  // largest angle of one corner (circ) or chord (inscribed)
  double eta = 0;     // inscribed: angle of the first/last point past the normals
  double limit = 2;   // miter limit
  double r_check = 0; // a pruned result's edges keep this distance from the polygon
  bool resolve = true; // a curve with a few crossings left resolved without the overlay
};

// ------------------------------------------------------------------------------------
// rings: cleaned and oriented

// Removes consecutive duplicates (done by make_ring) and vertices where the ring runs
// straight on (exactly collinear, between their neighbours); a spike stays (a convex
// vertex of exterior angle pi).
inline void drop_straight(std::vector<Pt>& v) {
  std::size_t n = v.size();
  if (n < 3) return;
  std::vector<char> alive(n, 1);
  std::vector<std::size_t> prv(n), nxt(n), stack;
  for (std::size_t i = 0; i < n; ++i) {
    prv[i] = prev_of(i, n);
    nxt[i] = next_of(i, n);
    stack.push_back(i);
  }
  std::size_t left = n;
  auto straight = [&](std::size_t i) {
    const Pt &p = v[prv[i]], &q = v[i], &s = v[nxt[i]];
    if (orient(p, q, s) != 0) return false;
    // collinear: straight on when q - p and s - q point the same way (signs suffice)
    auto sg = [](double d) { return (d > 0) - (d < 0); };
    int d = sg(q.x - p.x) * sg(s.x - q.x) + sg(q.y - p.y) * sg(s.y - q.y);
    return d > 0;
  };
  while (!stack.empty() && left > 2) {
    std::size_t i = stack.back();
    stack.pop_back();
    if (!alive[i] || !straight(i)) continue;
    alive[i] = 0;
    --left;
    std::size_t a = prv[i], b = nxt[i];
    nxt[a] = b;
    prv[b] = a;
    stack.push_back(a);
    stack.push_back(b);
  }
  std::vector<Pt> out;
  out.reserve(left);
  for (std::size_t i = 0; i < n; ++i)
    if (alive[i]) out.push_back(v[i]);
  v.swap(out);
}

inline void to_pts(const ms::Ring& r, std::vector<Pt>& v) {
  v.resize((std::size_t)r.n());
  for (i64 i = 0; i < r.n(); ++i) v[i] = Pt{r.x(i), r.y(i)};
}

// ------------------------------------------------------------------------------------
// the curve of one ring

// Features of a ring, for the pruning (offset_prune.hpp): edge j (v_j -> v_{j+1}) is 2j,
// vertex j is 2j + 1.
inline i64 edge_feature(i64 j) { return 2 * j; }
inline i64 vertex_feature(i64 j) { return 2 * j + 1; }

class Curve {
 public:
  std::vector<Pt> pts;   // the closed curve
  std::vector<i64> lab;  // label of segment k -> k + 1: edge e (>= 0), -1 - vertex, DETOUR
  // Bookkeeping of the pieces (round joins): point k is attached to ring vertex anc[k]
  // (nondecreasing along the curve, by 0 or 1 per segment) and lies within t_up of the
  // feature pf[k], which contains that vertex; segment k -> k + 1 lies within t_up of
  // sf[k], which contains anc[k + 1]. The piece of segment k is the polygon anc[k], pts[k],
  // pts[k + 1], anc[k + 1] closed along the ring back to anc[k].
  std::vector<i64> anc, pf, sf;
  bool certified = true;

  // v: the ring (n >= 1), offset side on the right; base: global index of v[0]
  void build(const std::vector<Pt>& v, const Setup& s, i64 base) {
    pts.clear();
    lab.clear();
    anc.clear();
    pf.clear();
    sf.clear();
    certified = true;
    const std::size_t n = v.size();
    if (n == 1) {
      disk(v[0], s, base);
      return;
    }
    // edges: unit direction and right normal
    ex_.resize(n);
    ey_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Pt &a = v[i], &b = v[next_of(i, n)];
      double dx = b.x - a.x, dy = b.y - a.y, L = std::hypot(dx, dy);
      ex_[i] = dx / L;
      ey_[i] = dy / L;
    }
    cs_.assign(n + 1, 0);
    fan_.assign(n, 0);
    chain_.clear();
    for (std::size_t j = 0; j < n; ++j) {
      cs_[j] = chain_.size();
      vertex(v, j, s);
    }
    cs_[n] = chain_.size();
    if (s.join == ROUND) certify(v, s);
    if (!certified) return;
    trim(v, s);
    // the curve: chains joined by the moved edges
    for (std::size_t j = 0; j < n; ++j) {
      const i64 J = (i64)j;
      if (trim_[j]) {  // a trimmed detour: the crossing of the moved edges
        pts.push_back(tx_[j]);
        lab.push_back(base + J);
        anc.push_back(J);
        pf.push_back(edge_feature((J + (i64)n - 1) % (i64)n));  // within t_up of edge in
        sf.push_back(edge_feature(J));
        continue;
      }
      std::size_t k0 = cs_[j], k1 = cs_[j + 1];
      i64 vl = fan_[j] ? -1 - (base + J) : DETOUR;
      for (std::size_t k = k0; k < k1; ++k) {
        pts.push_back(chain_[k]);
        lab.push_back(k + 1 < k1 ? vl : base + J);  // the last: moved edge j
        anc.push_back(J);
        pf.push_back(vertex_feature(J));
        sf.push_back(k + 1 < k1 ? vertex_feature(J) : edge_feature(J));
      }
    }
  }

 private:
  std::vector<double> ex_, ey_;
  std::vector<std::size_t> cs_;  // chain of vertex j: chain_[cs_[j] .. cs_[j + 1])
  std::vector<char> fan_;        // 1: a fan, 0: a detour (F, V, S)
  std::vector<Pt> chain_;
  std::vector<char> trim_;       // 1: the detour of vertex j is trimmed at tx_[j]
  std::vector<Pt> tx_;

  // p inside or on the convex counter-clockwise quadrilateral (a, b, c, d)
  static bool in_quad(Pt a, Pt b, Pt c, Pt d, Pt p) {
    return orient(a, b, p) >= 0 && orient(b, c, p) >= 0 && orient(c, d, p) >= 0 &&
           orient(d, a, p) >= 0;
  }
  // p within t of the segment ab (exactly)
  static bool near_segment(Pt a, Pt b, Pt p, double t) {
    return dot_sign(a, p, a, b) >= 0 && dot_sign(b, p, b, a) >= 0 &&
           line_dist_cmp(a, b, p, t) <= 0;
  }

  // Trimming. At a detour of a reflex vertex V the moved edges S_in -> F_in and
  // S_out -> F_out usually cross at X; the loop X, F_in, V, S_out (the kite) is then cut
  // off. As chains, raw curve - trimmed curve = the kite (+ slivers, below), so the winding
  // number drops by one inside the kite: nothing changes where it was >= 2 there. With
  // beta the turn at V: if beta <= 90 degrees, the kite lies in both pieces
  // Q_in = (P, S_in, F_in, V) and Q_out = (V, S_out, F_out, N) (convex: F_in in Q_out and
  // S_out in Q_in, checked), so it was >= 2. If beta > 90 degrees, a kite point x with
  // winding 1 lies in Q_in (or Q_out) only, outside P, so its nearest feature would be
  // the interior of edge in, on the far side of the line VX; but there
  // s < h tan(beta / 2) (s back from V along in, h from in's line), and the foot of x on
  // out's line lies at s |cos beta| + h sin beta <= t_cov tan(beta / 2) <= |V X|
  // cos-projected <= that of X' (beyond both lines), which is checked to lie on the edge
  // out: so x is closer to out (at |s sin beta + h cos beta| < h), a contradiction. Such
  // points are not within t_cov of P: removing them keeps the guarantee (the same for
  // out, and for a shrink with the complement of P). X is rounded to a double X' on or beyond both moved edges (right of both lines),
  // so the sliver between S_in, X, F_out and S_in, X', F_out (a clockwise loop) is
  // *added*: the region only grows there, and X' is checked to lie within t_up of both
  // edges, so the sliver (the hull of points within t_up of them) stays within t_up.
  // Trims on the two ends of one edge must keep their order along it.
  void trim(const std::vector<Pt>& v, const Setup& s) {
    const std::size_t n = v.size();
    trim_.assign(n, 0);
    tx_.resize(n);
    if (n < 3) return;
    auto first = [&](std::size_t j) { return chain_[cs_[j]]; };
    auto last = [&](std::size_t j) { return chain_[cs_[j + 1] - 1]; };
    for (std::size_t j = 0; j < n; ++j) {
      if (fan_[j]) continue;
      const std::size_t jp = prev_of(j, n), jn = next_of(j, n);
      const Pt V = v[j], P = v[jp], N = v[jn];
      if (orient(P, V, N) >= 0) continue;  // a detour at a convex vertex: not trimmed
      const Pt Sin = last(jp), Fin = chain_[cs_[j]], Sout = chain_[cs_[j] + 2], Fout = first(jn);
      int o1 = orient(Sin, Fin, Sout), o2 = orient(Sin, Fin, Fout);
      int o3 = orient(Sout, Fout, Sin), o4 = orient(Sout, Fout, Fin);
      if (o1 * o2 >= 0 || o3 * o4 >= 0) continue;  // no proper crossing
      const bool obtuse = dot_sign(P, V, V, N) < 0;
      if (!obtuse && (!in_quad(V, Sout, Fout, N, Fin) || !in_quad(P, Sin, Fin, V, Sout)))
        continue;
      // X in extended precision, rounded (a guess; every check below is exact)
      using LD = long double;
      LD ux = (LD)Fin.x - Sin.x, uy = (LD)Fin.y - Sin.y, wx = (LD)Fout.x - Sout.x,
         wy = (LD)Fout.y - Sout.y;
      LD t = (((LD)Sout.x - Sin.x) * wy - ((LD)Sout.y - Sin.y) * wx) / (ux * wy - uy * wx);
      Pt X0{(double)(Sin.x + t * ux), (double)(Sin.y + t * uy)};
      if (!(X0.x - X0.x == 0) || !(X0.y - X0.y == 0)) continue;
      // X': a few units in the last place outwards along the bisector of the normals,
      // where the filtered orientations decide (on the lines they would go exact)
      bool found = false;
      Pt X = X0;
      const double bx = ey_[jp] + ey_[j], by = -ex_[jp] - ex_[j];  // n_in + n_out
      double step = std::max(std::fabs(X0.x), std::fabs(X0.y)) * 0x1p-50;
      for (int k = 0; k < 40 && !found; ++k, step *= 2) {
        Pt c = k == 0 ? X0 : Pt{X0.x + step * bx, X0.y + step * by};  // X0 first: often exact
        if (orient(Sin, Fin, c) <= 0 && orient(Sout, Fout, c) <= 0) {
          X = c;
          found = true;
        }
      }
      if (!found) continue;
      if (s.join == ROUND && (!near_segment(P, V, X, s.t_up) || !near_segment(V, N, X, s.t_up)))
        continue;
      if (obtuse && (dot_sign(P, X, P, V) < 0 || dot_sign(V, X, V, P) < 0 ||
                     dot_sign(V, X, V, N) < 0 || dot_sign(N, X, N, V) < 0))
        continue;
      trim_[j] = 1;
      tx_[j] = X;
    }
    // order along each edge with trims at both ends
    for (std::size_t i = 0; i < n; ++i) {
      std::size_t j = (i + 1) % n;
      if (!trim_[i] || !trim_[j]) continue;
      const Pt S = chain_[cs_[i] + 2], F = chain_[cs_[j]];  // the raw moved edge i
      if (dot_sign(tx_[i], tx_[j], S, F) <= 0) trim_[i] = trim_[j] = 0;
    }
  }

  static Pt at(Pt V, double R, double nx, double ny, double exx, double eyy, double a) {
    double c = std::cos(a), sn = std::sin(a);
    return Pt{V.x + R * (nx * c + exx * sn), V.y + R * (ny * c + eyy * sn)};
  }

  void vertex(const std::vector<Pt>& v, std::size_t j, const Setup& s) {
    const std::size_t n = v.size();
    const std::size_t ji = prev_of(j, n), jn = next_of(j, n);  // edge in, next vertex
    const Pt V = v[j];
    double eix = ex_[ji], eiy = ey_[ji], eox = ex_[j], eoy = ey_[j];
    double nix = eiy, niy = -eix, nox = eoy, noy = -eox;  // right normals
    int o = n == 2 ? 0 : orient(v[ji], V, v[jn]);
    bool convex = o >= 0;  // o == 0 after cleaning: a spike (exterior angle pi)
    double theta = 0;
    if (convex) {
      double cr = eix * eoy - eiy * eox, dt = eix * eox + eiy * eoy;
      theta = o == 0 ? M_PI : std::atan2(std::fabs(cr), dt);
    }
    if (convex && s.join != ROUND) {
      sharp(V, nix, niy, nox, noy, eix, eiy, eox, eoy, theta, s);
      fan_[j] = 1;
      return;
    }
    if (convex && s.circ) {
      // k corners at angles (i - 1/2) phi, radius rho / cos(phi / 2): tangent chords
      double k = std::max(1.0, std::ceil(theta / s.phimax));
      double phi = theta / k, R = s.rho / std::cos(phi / 2);
      if (R * std::sin(phi / 2) >= s.mc) {
        for (double i = 1; i <= k; ++i)
          chain_.push_back(at(V, R, nix, niy, eix, eiy, (i - 0.5) * phi));
        fan_[j] = 1;
        return;
      }
    } else if (convex) {
      // k + 1 points on the circle rho, from eta past in's normal to eta before out's
      double span = theta - 2 * s.eta;
      if (span >= 2 * s.eta) {
        double k = std::max(1.0, std::ceil(span / s.phimax)), step = span / k;
        for (double i = 0; i <= k; ++i)
          chain_.push_back(at(V, s.rho, nix, niy, eix, eiy, s.eta + i * step));
        fan_[j] = 1;
        return;
      }
    }
    // a detour: F past V's normal on in's side, S before it on out's (at a convex vertex
    // of a turn too small for a fan, F must end up at or ahead of S around V). The points
    // on the normals, rounded, are kept when they already lie on the right side (axis-
    // parallel edges: exactly on it); else they are pushed along the edge by mc.
    const double rho = s.join == ROUND ? s.rho : s.r;
    const Pt P = v[ji], N = v[jn];
    Pt F{V.x + rho * nix, V.y + rho * niy}, S{V.x + rho * nox, V.y + rho * noy};
    if (s.join == ROUND) {
      if (dot_sign(V, F, P, V) < 0) F = Pt{F.x + s.mc * eix, F.y + s.mc * eiy};
      if (dot_sign(V, S, V, N) > 0) S = Pt{S.x - s.mc * eox, S.y - s.mc * eoy};
      for (double f = 2 * s.mc; convex && orient(V, S, F) < 0 && f < 0x1p1000; f *= 2) {
        F = Pt{V.x + rho * nix + f * eix, V.y + rho * niy + f * eiy};
        S = Pt{V.x + rho * nox - f * eox, V.y + rho * noy - f * eoy};
      }
    }
    chain_.push_back(F);
    chain_.push_back(V);
    chain_.push_back(S);
    fan_[j] = 0;
  }

  // miter and square joins at a convex vertex
  void sharp(Pt V, double nix, double niy, double nox, double noy, double eix, double eiy,
             double eox, double eoy, double theta, const Setup& s) {
    double half = theta / 2, r = s.r;
    if (s.join == MITER && std::cos(half) * s.limit >= 1.0) {
      double d = 1.0 + (nix * nox + niy * noy);
      chain_.push_back(Pt{V.x + r * (nix + nox) / d, V.y + r * (niy + noy) / d});
      return;
    }
    double h = r * (s.join == MITER ? s.limit : 1.0);
    double t = (h - r * std::cos(half)) / std::sin(half);
    chain_.push_back(Pt{V.x + r * nix + t * eix, V.y + r * niy + t * eiy});
    chain_.push_back(Pt{V.x + r * nox - t * eox, V.y + r * noy - t * eoy});
  }

  // a point grows into a disk
  void disk(Pt V, const Setup& s, i64 base) {
    bool circ = s.circ || s.join != ROUND;
    double step = s.join == ROUND ? s.phimax : M_PI / 2;
    double k = std::max(3.0, std::ceil(2 * M_PI / step)), phi = 2 * M_PI / k;
    double rho = s.join == ROUND ? s.rho : s.r;
    double R = circ ? rho / std::cos(phi / 2) : rho, a0 = circ ? 0.5 : 0.0;
    for (double i = 0; i < k; ++i) {
      double a = (i + a0) * phi;
      pts.push_back(Pt{V.x + R * std::cos(a), V.y + R * std::sin(a)});
      lab.push_back(-1 - base);
    }
    if (s.join != ROUND) return;
    // certificate: within t_up, chords at >= t_cov, turning once counter-clockwise
    const std::size_t m = pts.size();
    int down_turns = 0;
    for (std::size_t i = 0; i < m; ++i) {
      const Pt &p = pts[i], &q = pts[(i + 1) % m];
      if (dist_cmp(V, p, s.t_up) > 0 || orient(V, p, q) <= 0 ||
          line_dist_cmp(p, q, V, s.t_cov) < 0)
        certified = false;
      bool pu = p.y > V.y || (p.y == V.y && p.x > V.x);
      bool qu = q.y > V.y || (q.y == V.y && q.x > V.x);
      down_turns += pu && !qu;
    }
    if (down_turns != 1) certified = false;
  }

  // the exact checks (E), (F), (U) of the header
  void certify(const std::vector<Pt>& v, const Setup& s) {
    const std::size_t n = v.size();
    for (std::size_t i = 0; i < n && certified; ++i) {
      const std::size_t jb = next_of(i, n);
      const Pt &a = v[i], &b = v[jb];
      const Pt Sa = chain_[cs_[i + 1] - 1];  // the end of a's chain
      const Pt Fb = chain_[cs_[jb]];
      if (orient(a, b, Sa) >= 0 || line_dist_cmp(a, b, Sa, s.t_cov) < 0 ||
          dot_sign(a, Sa, a, b) > 0)
        certified = false;
      if (orient(a, b, Fb) >= 0 || line_dist_cmp(a, b, Fb, s.t_cov) < 0 ||
          dot_sign(b, Fb, a, b) < 0)
        certified = false;
    }
    for (std::size_t j = 0; j < n && certified; ++j) {
      const Pt V = v[j], P = v[prev_of(j, n)];
      std::size_t k0 = cs_[j], k1 = cs_[j + 1];
      if (!fan_[j]) {
        const Pt &F = chain_[k0], &S = chain_[k0 + 2];
        if (dist_cmp(V, F, s.t_up) > 0 || dist_cmp(V, S, s.t_up) > 0) certified = false;
        // at a convex vertex (or a spike) F must be at or ahead of S around V
        int o = n == 2 ? 0 : orient(P, V, v[next_of(j, n)]);
        if (o >= 0 && orient(V, S, F) < 0) certified = false;
        if (o == 0 && n >= 2) certified = false;  // a spike always gets a fan
        continue;
      }
      for (std::size_t k = k0; k < k1; ++k) {
        const Pt& c = chain_[k];
        if (dist_cmp(V, c, s.t_up) > 0 || dot_sign(P, V, V, c) <= 0) certified = false;
        if (k + 1 < k1) {
          const Pt& d = chain_[k + 1];
          if (orient(V, c, d) <= 0 || line_dist_cmp(c, d, V, s.t_cov) < 0) certified = false;
        }
      }
    }
  }
};

// ------------------------------------------------------------------------------------
// shallow notches filled
//
// A vertex V (neighbours P, N) of a ring in the curve's frame (offset side on the right)
// where the ring turns right, orient(P, V, N) < 0, is a notch on the offset side: for a
// grow a reflex vertex of the polygon, for a shrink a convex one (a notch of the
// complement). Removing it adds the triangle PVN to the set being grown (for a shrink:
// to the complement), and every point of that triangle lies within h = dist(V, line PN)
// of the edges PV and VN (split it at the foot of V: each half is a right triangle whose
// points are within its height h of its hypotenuse). So when the triangle holds no other
// vertex of any ring (exactly: then no edge enters it either, as edges do not cross, and
// the new ring is valid) and h <= t, the filled set P' satisfies P ⊆ P' ⊆ P ⊕ D(t), and
//     P ⊕ D(r) ⊆ P' ⊕ D(r),   P' ⊕ D(r + e - t) ⊆ P ⊕ D(r + e),
//     P ⊕ D(r - e) ⊆ P' ⊕ D((r - t) - (e - t)),   P' ⊕ D(r - t) ⊆ P ⊕ D(r),
// (for a shrink the same with the complements): offsetting P' with the tolerance e - t
// (and, inscribed, the radius r - t) keeps the bounds promised for P. Removed vertices are
// not adjacent (each triangle is one of P's, with an original base), and every ring keeps
// at least four vertices. Such notches are what make a curve fold on itself: the offset
// of a finely digitized outline has a detour to every one of them, and the detours of
// close notches cross each other's moved edges (their number grows with r / spacing);
// filled, the moved edges of the remaining vertices usually cross once and are trimmed.
// Returns the bound t used (0: nothing removed): the least double >= every removed
// notch's height if that is certified exactly, else t.
inline double fill_notches(std::vector<std::vector<Pt>>& rings, double t) {
  std::vector<double> x0, x1, y0, y1;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> who;  // (ring, vertex); tri: ring + big
  std::vector<char> cand;
  std::vector<std::size_t> first;
  std::size_t total = 0;
  for (const auto& v : rings) {
    first.push_back(total);
    total += v.size();
  }
  cand.assign(total, 0);
  bool any = false;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const auto& v = rings[r];
    const std::size_t n = v.size();
    if (n < 5) continue;
    for (std::size_t j = 0; j < n; ++j) {
      const Pt &P = v[prev_of(j, n)], &V = v[j], &N = v[next_of(j, n)];
      if (orient(P, V, N) >= 0 || line_dist_cmp(P, N, V, t) > 0) continue;
      cand[first[r] + j] = 1;
      any = true;
    }
  }
  if (!any) return 0;
  // boxes: every vertex (a point), then every candidate's triangle
  const std::uint32_t TRI = 0x80000000u;
  for (std::size_t r = 0; r < rings.size(); ++r)
    for (std::size_t j = 0; j < rings[r].size(); ++j) {
      const Pt& q = rings[r][j];
      x0.push_back(q.x);
      x1.push_back(q.x);
      y0.push_back(q.y);
      y1.push_back(q.y);
      who.emplace_back((std::uint32_t)r, (std::uint32_t)j);
    }
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const auto& v = rings[r];
    const std::size_t n = v.size();
    for (std::size_t j = 0; j < n; ++j) {
      if (!cand[first[r] + j]) continue;
      const Pt &P = v[prev_of(j, n)], &V = v[j], &N = v[next_of(j, n)];
      x0.push_back(std::min({P.x, V.x, N.x}));
      x1.push_back(std::max({P.x, V.x, N.x}));
      y0.push_back(std::min({P.y, V.y, N.y}));
      y1.push_back(std::max({P.y, V.y, N.y}));
      who.emplace_back((std::uint32_t)r | TRI, (std::uint32_t)j);
    }
  }
  box_pairs((i64)who.size(), x0.data(), x1.data(), y0.data(), y1.data(), [&](i64 a, i64 b) {
    const bool ta = who[a].first & TRI, tb = who[b].first & TRI;
    if (ta == tb) return;  // two points or two triangles
    const auto tri = ta ? who[a] : who[b], pt = ta ? who[b] : who[a];
    const std::size_t r = tri.first & ~TRI, j = tri.second;
    if (!cand[first[r] + j]) return;  // already refused
    const auto& v = rings[r];
    const std::size_t n = v.size();
    const std::size_t jp = prev_of(j, n), jn = next_of(j, n);
    if (pt.first == r && (pt.second == jp || pt.second == j || pt.second == jn)) return;
    const Pt &P = v[jp], &V = v[j], &N = v[jn], &q = rings[pt.first][pt.second];
    // the triangle P, V, N turns clockwise: q is in it (closed) when on no side's left
    if (orient(P, V, q) <= 0 && orient(V, N, q) <= 0 && orient(N, P, q) <= 0)
      cand[first[r] + j] = 0;
  });
  // removal: not adjacent, at least four vertices kept; the heights' bound
  double hb = 0;
  std::vector<std::vector<char>> del(rings.size());
  bool removed = false;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const auto& v = rings[r];
    const std::size_t n = v.size();
    if (n < 5) continue;
    auto& d = del[r];
    d.assign(n, 0);
    std::size_t left = n;
    for (std::size_t j = 0; j < n && left > 4; ++j) {
      if (!cand[first[r] + j] || (j > 0 && d[j - 1]) || (j + 1 == n && d[0])) continue;
      d[j] = 1;
      --left;
      removed = true;
      const Pt &P = v[prev_of(j, n)], &V = v[j], &N = v[next_of(j, n)];
      const double dx = N.x - P.x, dy = N.y - P.y;
      hb = std::max(hb, std::fabs(dx * (V.y - P.y) - dy * (V.x - P.x)) / std::hypot(dx, dy));
    }
  }
  if (!removed) return 0;
  // the float bound, a little up, certified exactly against every removed notch (else t)
  hb = std::min(t, up(up(hb * (1 + 0x1p-40)) + 0x1p-1070));
  for (std::size_t r = 0; r < rings.size() && hb < t; ++r) {
    const auto& v = rings[r];
    const std::size_t n = v.size();
    for (std::size_t j = 0; j < del[r].size(); ++j)
      if (del[r][j] && line_dist_cmp(v[(j + n - 1) % n], v[(j + 1) % n], v[j], hb) > 0) {
        hb = t;
        break;
      }
  }
  for (std::size_t r = 0; r < rings.size(); ++r) {
    if (del[r].empty()) continue;
    auto& v = rings[r];
    std::size_t k = 0;
    for (std::size_t j = 0; j < v.size(); ++j)
      if (!del[r][j]) v[k++] = v[j];
    v.resize(k);
    drop_straight(v);  // a neighbour may now lie straight between its own
  }
  return hb;
}

}  // namespace off
}  // namespace mk
