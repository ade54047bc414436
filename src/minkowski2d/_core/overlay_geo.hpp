// overlay_geo.hpp -- the geometry the overlay works on (see overlay.hpp, which includes
// every part of the overlay; include that): DD coordinates and points, the degree-2
// predicates on them (plain points through exact.hpp, DD ones in FE then Dy), lines and
// vertices (Geo: points, lines, crossings, their higher-degree predicates and the
// correct rounding of a crossing), the rules, and the edge and ring types of a run.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <set>
#include <vector>

#include "boxes.hpp"
#include "exact.hpp"
#include "exactnum.hpp"

namespace mk {
namespace ov {

// ------------------------------------------------------------------------------------
// coordinates

struct DD {
  double hi, lo;  // exact value hi + lo, hi = fl(hi + lo)
};
inline DD dd(double x) { return {x, 0.0}; }
inline DD dd_sum(double a, double b) {
  DD r;
  two_sum(a, b, r.hi, r.lo);
  if (r.hi - r.hi != 0) r.lo = 0;  // overflow: hi is +-inf (the caller checks)
  return r;
}
inline bool dd_eq(DD a, DD b) { return a.hi == b.hi && a.lo == b.lo; }
inline bool dd_less(DD a, DD b) { return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo); }
inline int dd_cmp(DD a, DD b) { return dd_less(a, b) ? -1 : (dd_less(b, a) ? 1 : 0); }
inline FE fe(DD a) { return {a.hi, std::fabs(a.lo)}; }
inline Dy dy(DD a) { return a.lo == 0 ? Dy(a.hi) : Dy(a.hi) + Dy(a.lo); }

struct P {
  DD x, y;
};
inline bool p_eq(const P& a, const P& b) { return dd_eq(a.x, b.x) && dd_eq(a.y, b.y); }
inline bool plain(const P& a) { return a.x.lo == 0 && a.y.lo == 0; }

template <class T>
inline T cross(const T& ax, const T& ay, const T& bx, const T& by) {
  return ax * by - ay * bx;
}

// sign of (q - p) x (r - p)
inline int orient(const P& p, const P& q, const P& r) {
  if (plain(p) && plain(q) && plain(r))
    return mk::orient(p.x.hi, p.y.hi, q.x.hi, q.y.hi, r.x.hi, r.y.hi);
  FE f = cross(fe(q.x) - fe(p.x), fe(q.y) - fe(p.y), fe(r.x) - fe(p.x), fe(r.y) - fe(p.y));
  int s = fe_sign(f);
  if (s != UNSURE) return s;
  Dy px = dy(p.x), py = dy(p.y);
  return cross(dy(q.x) - px, dy(q.y) - py, dy(r.x) - px, dy(r.y) - py).sign();
}

// sign of (q1 - p1) x (q2 - p2): the turn from one direction to another
inline int dir_cross(const P& p1, const P& q1, const P& p2, const P& q2) {
  if (plain(p1) && plain(q1) && plain(p2) && plain(q2))
    return cross_sign(p1.x.hi, p1.y.hi, q1.x.hi, q1.y.hi, p2.x.hi, p2.y.hi, q2.x.hi, q2.y.hi);
  FE f = cross(fe(q1.x) - fe(p1.x), fe(q1.y) - fe(p1.y), fe(q2.x) - fe(p2.x),
               fe(q2.y) - fe(p2.y));
  int s = fe_sign(f);
  if (s != UNSURE) return s;
  return cross(dy(q1.x) - dy(p1.x), dy(q1.y) - dy(p1.y), dy(q2.x) - dy(p2.x),
               dy(q2.y) - dy(p2.y))
      .sign();
}

// the direction p -> q points into the upper half-plane (y > 0, or y == 0 and x > 0)
inline bool upper_dir(const P& p, const P& q) {
  int c = dd_cmp(q.y, p.y);
  return c > 0 || (c == 0 && dd_less(p.x, q.x));
}
// angle order of directions from +x, counter-clockwise
inline bool angle_less(const P& p1, const P& q1, const P& p2, const P& q2) {
  bool u1 = upper_dir(p1, q1), u2 = upper_dir(p2, q2);
  if (u1 != u2) return u1;
  return dir_cross(p1, q1, p2, q2) > 0;
}

// ------------------------------------------------------------------------------------
// shared geometry of one operation

struct Line {
  i64 a, b;  // point ids, distinct points
};
struct Vert {
  i64 p;       // point id, or -1 for a crossing
  i64 l1, l2;  // the crossing of lines l1 and l2
  FE x, y;     // approximation
};

// A box holding the exact positions of two vertices: their approximations widened by
// their bounds, rounded outwards (one ulp beyond, so a DD point next to it tests safely).
inline void widened_box(const Vert& a, const Vert& b, double& x0, double& x1, double& y0,
                        double& y1) {
  const double up = 1 + 0x1p-50;
  x0 = next_down(std::min(a.x.v - a.x.e * up, b.x.v - b.x.e * up));
  x1 = next_up(std::max(a.x.v + a.x.e * up, b.x.v + b.x.e * up));
  y0 = next_down(std::min(a.y.v - a.y.e * up, b.y.v - b.y.e * up));
  y1 = next_up(std::max(a.y.v + a.y.e * up, b.y.v + b.y.e * up));
}

class Geo {
 public:
  std::vector<P> pts;
  std::vector<Line> lines;
  std::vector<Vert> verts;

  // (the fields are written in place: a temporary copied in stalls on its own stores)
  i64 point(DD x, DD y) {
    P& q = pts.emplace_back();
    q.x = x;
    q.y = y;
    return (i64)pts.size() - 1;
  }
  i64 line(i64 a, i64 b) {
    Line& L = lines.emplace_back();
    L.a = a;
    L.b = b;
    return (i64)lines.size() - 1;
  }
  i64 vert_point(i64 p) {
    Vert& V = verts.emplace_back();
    V.p = p;
    V.l1 = V.l2 = -1;
    V.x = fe(pts[p].x);
    V.y = fe(pts[p].y);
    return (i64)verts.size() - 1;
  }
  i64 vert_cross(i64 l1, i64 l2) {
    Vert v{-1, l1, l2, FE{0, 0}, FE{0, 0}};
    const P &a = pts[lines[l1].a], &b = pts[lines[l1].b];
    FE N, D;
    cross_nd<FE>(l1, l2, N, D, &cfe);
    FE t = fe_div(N, D);
    v.x = fe(a.x) + (fe(b.x) - fe(a.x)) * t;
    v.y = fe(a.y) + (fe(b.y) - fe(a.y)) * t;
    if (!(v.x.e <= 1e308 && v.y.e <= 1e308)) {
      // nearly parallel lines: the same in extended precision (else every comparison
      // with this vertex would redo that, and sorts place it by a meaningless value)
      FEL xl, yl;
      cross_l(l1, l2, xl, yl);
      v.x = fe_of(xl);
      v.y = fe_of(yl);
    }
    // an unbounded (or NaN) bound: no information, every decision goes exact
    if (!(v.x.e <= 1e308) || !(v.x.v - v.x.v == 0)) v.x = FE{0, INFINITY};
    if (!(v.y.e <= 1e308) || !(v.y.v - v.y.v == 0)) v.y = FE{0, INFINITY};
    // on a vertical (horizontal) line through points with double coordinates, the
    // crossing's x (y) is exactly that double: crossings along one such line then compare
    // equal in x without exact arithmetic (the sweep order meets them all; axis-parallel
    // edges with many crossings are common in offsets and CAD parts)
    for (i64 l : {l1, l2}) {
      const P &p0 = pts[lines[l].a], &p1 = pts[lines[l].b];
      if (p0.x.lo == 0 && p1.x.lo == 0 && p0.x.hi == p1.x.hi) v.x = FE{p0.x.hi, 0.0};
      if (p0.y.lo == 0 && p1.y.lo == 0 && p0.y.hi == p1.y.hi) v.y = FE{p0.y.hi, 0.0};
    }
    verts.push_back(v);
    return (i64)verts.size() - 1;
  }

  static FE cfe(DD a) { return fe(a); }
  static Dy cdy(DD a) { return dy(a); }

  // the crossing of l1 = (a, b) and l2 = (c, d) is a + (b - a) N / D
  template <class T>
  void cross_nd(i64 l1, i64 l2, T& N, T& D, T (*conv)(DD)) const {
    const P &a = pts[lines[l1].a], &b = pts[lines[l1].b];
    const P &c = pts[lines[l2].a], &d = pts[lines[l2].b];
    T dx = conv(d.x) - conv(c.x), dy_ = conv(d.y) - conv(c.y);
    N = cross(conv(c.x) - conv(a.x), conv(c.y) - conv(a.y), dx, dy_);
    D = cross(conv(b.x) - conv(a.x), conv(b.y) - conv(a.y), dx, dy_);
  }
  // the crossing of lines l1 and l2 in extended precision, with certified bounds
  void cross_l(i64 l1, i64 l2, FEL& x, FEL& y) const {
    const P &a = pts[lines[l1].a], &b = pts[lines[l1].b];
    FEL N, D;
    cross_nd<FEL>(l1, l2, N, D, &cfel);
    const FEL t = fe_div(N, D);
    x = cfel(a.x) + (cfel(b.x) - cfel(a.x)) * t;
    y = cfel(a.y) + (cfel(b.y) - cfel(a.y)) * t;
  }

  // exact homogeneous coordinates (X / W, Y / W), W > 0
  void exact(i64 v, Dy& X, Dy& Y, Dy& W) const {
    const Vert& V = verts[v];
    if (V.p >= 0) {
      X = dy(pts[V.p].x);
      Y = dy(pts[V.p].y);
      W = Dy(1.0);
      return;
    }
    const P &a = pts[lines[V.l1].a], &b = pts[lines[V.l1].b];
    Dy N, D;
    cross_nd<Dy>(V.l1, V.l2, N, D, &cdy);
    if (D.sign() < 0) {
      N = -N;
      D = -D;
    }
    Dy ax = dy(a.x), ay = dy(a.y);
    X = ax * D + (dy(b.x) - ax) * N;
    Y = ay * D + (dy(b.y) - ay) * N;
    W = D;
  }

  // sign of (a - b) in x (axis 0) or y (axis 1)
  int coord_cmp(i64 a, i64 b, int axis) const {
    if (a == b) return 0;
    const Vert &A = verts[a], &B = verts[b];
    if (A.p >= 0 && B.p >= 0) {
      const P &pa = pts[A.p], &pb = pts[B.p];
      return axis == 0 ? dd_cmp(pa.x, pb.x) : dd_cmp(pa.y, pb.y);
    }
    int s = fe_sign(axis == 0 ? A.x - B.x : A.y - B.y);
    if (s != UNSURE) return s;
    {  // the homogeneous comparison in extended precision, certified
      FEL Xa, Ya, Wa, Xb, Yb, Wb;
      if (homog_l(a, Xa, Ya, Wa) && homog_l(b, Xb, Yb, Wb)) {
        s = fe_sign(axis == 0 ? Xa * Wb - Xb * Wa : Ya * Wb - Yb * Wa);
        if (s != UNSURE) return s;
      }
    }
    Dy Xa, Ya, Wa, Xb, Yb, Wb;
    exact(a, Xa, Ya, Wa);
    exact(b, Xb, Yb, Wb);
    return axis == 0 ? (Xa * Wb - Xb * Wa).sign() : (Ya * Wb - Yb * Wa).sign();
  }

  // an extended-precision value as a double with a certified bound (the distance to
  // the double, exact in long double, added; the bound rounded upwards); never exact
  static FE fe_of(FEL a) {
    const double v = (double)a.v;
    const long double d = std::fabs(a.v - (long double)v);
    return FE{v, next_up((double)((a.e + d) * FEconst<long double>::SAFE))};
  }
  // extended-precision value of a DD with a certified bound
  static FEL cfel(DD u) {
    long double s = (long double)u.hi + (long double)u.lo;
    return FEL{s, u.lo == 0 ? 0.0L : FEconst<long double>::U * std::fabs(s)};
  }
  // exact()'s homogeneous coordinates in extended precision (certified bounds); false
  // when the sign of W is not certain
  bool homog_l(i64 v, FEL& X, FEL& Y, FEL& W) const {
    const Vert& V = verts[v];
    if (V.p >= 0) {
      X = cfel(pts[V.p].x);
      Y = cfel(pts[V.p].y);
      W = FEL{1.0L, 0.0L};
      return true;
    }
    FEL N, D;
    cross_nd<FEL>(V.l1, V.l2, N, D, &cfel);
    int sd = fe_sign(D);
    if (sd == UNSURE || sd == 0) return false;
    if (sd < 0) {
      N = -N;
      D = -D;
    }
    const P &a = pts[lines[V.l1].a], &b = pts[lines[V.l1].b];
    FEL ax = cfel(a.x), ay = cfel(a.y);
    X = ax * D + (cfel(b.x) - ax) * N;
    Y = ay * D + (cfel(b.y) - ay) * N;
    W = D;
    return true;
  }
  // the sweep order: x, then y
  int vcmp(i64 a, i64 b) const {
    int c = coord_cmp(a, b, 0);
    return c ? c : coord_cmp(a, b, 1);
  }

  // side of vertex v against line l (a -> b): +1 left, -1 right, 0 on it
  int side(i64 l, i64 v) const {
    const P &a = pts[lines[l].a], &b = pts[lines[l].b];
    const Vert& V = verts[v];
    if (V.p >= 0) return orient(a, b, pts[V.p]);
    if (V.l1 == l || V.l2 == l) return 0;
    FE ax = fe(a.x), ay = fe(a.y);
    int s = fe_sign(cross(fe(b.x) - ax, fe(b.y) - ay, V.x - ax, V.y - ay));
    if (s != UNSURE) return s;
    {
      FEL X, Y, W;
      if (homog_l(v, X, Y, W)) {
        FEL Ax = cfel(a.x), Ay = cfel(a.y);
        s = fe_sign(cross(cfel(b.x) - Ax, cfel(b.y) - Ay, X - Ax * W, Y - Ay * W));
        if (s != UNSURE) return s;
      }
    }
    Dy X, Y, W;
    exact(v, X, Y, W);
    Dy Ax = dy(a.x), Ay = dy(a.y);
    return cross(dy(b.x) - Ax, dy(b.y) - Ay, X - Ax * W, Y - Ay * W).sign();
  }

  // lines l1 and l2 are one line (exact)
  bool same_line(i64 l1, i64 l2) const {
    if (l1 == l2) return true;
    const P &a = pts[lines[l1].a], &b = pts[lines[l1].b];
    return orient(a, b, pts[lines[l2].a]) == 0 && orient(a, b, pts[lines[l2].b]) == 0;
  }

  // turn from line l1's direction to line l2's (each a -> b, times its sign)
  int turn(i64 l1, int s1, i64 l2, int s2) const {
    const Line &L1 = lines[l1], &L2 = lines[l2];
    return dir_cross(pts[L1.a], pts[L1.b], pts[L2.a], pts[L2.b]) * s1 * s2;
  }
  // direction of line l times s as a pair of points (p -> q)
  void dir(i64 l, int s, const P*& p, const P*& q) const {
    p = &pts[s > 0 ? lines[l].a : lines[l].b];
    q = &pts[s > 0 ? lines[l].b : lines[l].a];
  }
  // position of vertex a against b along line l's direction: sign of (a - b) . dir
  int along(i64 l, i64 a, i64 b) const {
    const P &p = pts[lines[l].a], &q = pts[lines[l].b];
    int axis = dd_eq(p.x, q.x) ? 1 : 0;
    int s = axis == 0 ? dd_cmp(q.x, p.x) : dd_cmp(q.y, p.y);
    return coord_cmp(a, b, axis) * s;
  }

  // nearest double to X / W (W > 0), ties to even
  static double round_exact(const Dy& X, const Dy& W) {
    if (X.n == 0) return 0.0;
    // a guess within an ulp or two from the leading limbs, then exact comparisons of X
    // with W times the midpoints between neighbouring doubles
    long ex, ew;
    long double mx = dy_approx_frexp(X, ex), mw = dy_approx_frexp(W, ew);
    long d = ex - ew;
    if (d > 4000) d = 4000;
    if (d < -4000) d = -4000;
    double r = (double)std::ldexp(mx / mw, (int)d);
    if (X.neg) r = -r;
    if (!(r - r == 0)) return r;  // beyond the range: +-inf (the caller reports it)
    for (int iter = 0; iter < 64; ++iter) {
      double up = std::nextafter(r, INFINITY), dn = std::nextafter(r, -INFINITY);
      Dy mu = dy_ldexp(Dy(r) + Dy(up), -1), md = dy_ldexp(Dy(r) + Dy(dn), -1);
      int su = (X - W * mu).sign();
      if (su > 0 || (su == 0 && !even(r))) {
        if (!(up - up == 0)) return up;
        r = up;
        continue;
      }
      int sd = (X - W * md).sign();
      if (sd < 0 || (sd == 0 && !even(r))) {
        if (!(dn - dn == 0)) return dn;
        r = dn;
        continue;
      }
      return r;
    }
    return r;
  }
  static bool even(double r) {
    u64 bits;
    std::memcpy(&bits, &r, sizeof bits);
    return (bits & 1) == 0;
  }
  static double certified(FEL a) {
    double r = (double)a.v;
    if (!(r - r == 0)) return NAN;
    long double up = std::nextafter(r, INFINITY), dn = std::nextafter(r, -INFINITY);
    long double hu = (up - (long double)r) / 2, hd = ((long double)r - dn) / 2;
    long double m = a.e * FEconst<long double>::SAFE;
    if (a.v - m > (long double)r - hd && a.v + m < (long double)r + hu) return r;
    return NAN;
  }

  // (x, y), vertex v rounded, is v itself: a point without a low part, or a crossing
  // that (x, y) lies on both lines of (the lines meet only there)
  bool rounds_exactly(i64 v, double x, double y) const {
    const Vert& V = verts[v];
    if (V.p >= 0) return plain(pts[V.p]);
    const P q{dd(x), dd(y)};
    return orient(pts[lines[V.l1].a], pts[lines[V.l1].b], q) == 0 &&
           orient(pts[lines[V.l2].a], pts[lines[V.l2].b], q) == 0;
  }

  // rounded coordinates of vertex v
  void rounded(i64 v, double& x, double& y) const { round_vertex(v, x, y, false); }
  // rounded(), returning rounds_exactly() when `check` (else false)
  bool round_vertex(i64 v, double& x, double& y, bool check) const {
    const Vert& V = verts[v];
    if (V.p >= 0) {
      x = pts[V.p].x.hi;
      y = pts[V.p].y.hi;
      return check && plain(pts[V.p]);
    }
    // the crossing of a vertical and a horizontal line through plain points: read off
    const Line &L1 = lines[V.l1], &L2 = lines[V.l2];
    const P &p1 = pts[L1.a], &q1 = pts[L1.b], &p2 = pts[L2.a], &q2 = pts[L2.b];
    if (plain(p1) && plain(q1) && plain(p2) && plain(q2)) {
      if (p1.x.hi == q1.x.hi && p2.y.hi == q2.y.hi) {
        x = p1.x.hi;
        y = p2.y.hi;
        return check;
      }
      if (p1.y.hi == q1.y.hi && p2.x.hi == q2.x.hi) {
        x = p2.x.hi;
        y = p1.y.hi;
        return check;
      }
    }
    // extended precision with a certified bound; exact when it cannot certify
    FEL xl, yl;
    cross_l(V.l1, V.l2, xl, yl);
    x = certified(xl);
    y = certified(yl);
    if (!(x == x && y == y)) {
      Dy X, Y, W;
      exact(v, X, Y, W);
      if (x != x) x = round_exact(X, W);
      if (y != y) y = round_exact(Y, W);
    }
    return check && rounds_exactly(v, x, y);
  }
};

// ------------------------------------------------------------------------------------
// one overlay run

// A rule is an operation and a fill rule: rule = op + 4 * fill. The fill rule says which
// winding numbers are inside one operand (layer): POSITIVE w >= 1 (valid polygons,
// shells counter-clockwise, and the default), NONZERO w != 0, EVENODD w odd, NEGATIVE
// w <= -1 (as Clipper and iOverlay resolve self-intersecting input). The operation
// combines the two layers: UNION a or b, DIFFERENCE a and not b, INTERSECTION a and b,
// XOR a or b but not both.
enum RuleKind : int {
  UNION = 0,
  DIFFERENCE = 1,
  INTERSECTION = 2,
  XOR = 3,
};
enum FillRule : int {
  FILL_POSITIVE = 0,
  FILL_NONZERO = 1,
  FILL_EVENODD = 2,
  FILL_NEGATIVE = 3,
};
inline int make_rule(int op, int fill) { return op + 4 * fill; }
inline bool rule_valid(int rule) { return rule >= 0 && rule < 16; }

inline bool fill_inside(int fill, int w) {
  switch (fill) {
    case FILL_NONZERO:
      return w != 0;
    case FILL_EVENODD:
      return (w & 1) != 0;
    case FILL_NEGATIVE:
      return w <= -1;
    default:
      return w >= 1;
  }
}

inline bool rule_inside(int rule, int w0, int w1) {
  const int fill = rule >> 2;
  const bool a = fill_inside(fill, w0), b = fill_inside(fill, w1);
  switch (rule & 3) {
    case DIFFERENCE:
      return a && !b;
    case INTERSECTION:
      return a && b;
    case XOR:
      return a != b;
    default:
      return a || b;
  }
}

// An input edge: along `line` from vertex v0 to vertex v1 (global vertex ids).
// `group`: edges of one group >= 0 meet only at common end vertices (the edges of one
// convex ring, or the boundary of one earlier result), so their pairs are not tested;
// -1 (the default): no such promise.
struct EdgeIn {
  i64 line, v0, v1;
  int w, layer;
  int group = -1;
};
// A boundary edge of a result: inside on the left.
struct BEdge {
  i64 line, from, to;
};

// The result as rings: rounded vertices, rings (exterior first, then its holes) and
// polygons; OVERFLOW when a rounded vertex is not finite.
struct Rings {
  std::vector<double> xy;
  std::vector<i64> ring_off{0}, poly_off{0};
  int status = OK;
  // with want_lines: line[k] is the supporting line of the edge from vertex k to the next
  // one of its ring (when collinear edges were merged, the line of the first)
  bool want_lines = false;
  std::vector<i64> line;
  // every vertex is its exact vertex (rounding moved none): the rings are the exact
  // result, valid by construction, and the check after rounding has nothing to find
  bool exact_vertices = false;
  void clear() {
    xy.clear();
    ring_off.assign(1, 0);
    poly_off.assign(1, 0);
    line.clear();
    status = OK;
    exact_vertices = false;
  }
};

}  // namespace ov
}  // namespace mk
