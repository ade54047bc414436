// overlay.hpp -- the exact overlay: node a set of directed, weighted edges, give every
// face its winding numbers, keep the faces a rule selects, and return the regularized
// result -- as exact boundary edges (to feed another overlay) or as rings with holes
// whose vertices are the correctly rounded exact vertices.
//
// Geometry (class Geo, shared by the overlays of one operation):
//  * points: exact sums of two doubles (DD; a plain double has lo = 0, the vertex a + b
//    of a convex piece sum is TwoSum(a, b));
//  * lines: through two points -- every edge lies on one (its supporting line);
//  * vertices: a point, or the crossing of two lines (a rational point; never rounded).
// An edge runs along its line from one vertex to another, with an integer weight and a
// layer (0 or 1). Closed counter-clockwise rings of weight-1 edges have winding number 1
// inside; the winding numbers (w0, w1) of a face sum the rings of each layer, and the
// rule keeps a face or not: the union of layer 0 is w0 >= 1, a difference w0 >= 1 and
// w1 <= 0. Because vertices are kept as line crossings, the boundary edges of one
// overlay are exact input for the next (the cascaded union) without any growth in the
// degree of the predicates.
//
// One run (n edges, k intersecting pairs):
//  1. the input vertices sorted by (x, y) and equal ones merged (exact);
//  2. candidate pairs: boxes swept along x (boxes.hpp); each pair classified by the
//     sides of its four endpoints against the other's line: disjoint, touching (an
//     endpoint on the other edge), collinear overlap, or a proper crossing (a new vertex);
//  3. every edge's split points sorted along it, equal ones united (union-find): the
//     same point found by different pairs becomes one vertex, with no global hashing of
//     rational points;
//  4. the pieces between consecutive split points are the arrangement's edges; pieces
//     joining the same two vertices (collinear overlaps) are merged, weights added;
//  5. one plane sweep over the pieces (which no longer cross) gives each the winding
//     numbers below and above it: below the lowest piece starting at a vertex lies what
//     is above the piece just under that vertex;
//  6. pieces whose sides the rule classifies differently are the boundary, directed with
//     the inside on the left. For the final result, rings are traced (at a vertex with
//     several, the next edge is the first clockwise from the way back, so rings split at
//     pinch points), collinear vertices dropped (parallel lines), each ring's orientation
//     read at its lowest vertex, each hole given its exterior by a second sweep over the
//     boundary alone (the nearest boundary edge below a hole's first vertex belongs to
//     its exterior or to a sibling hole), and the vertices rounded to the nearest double
//     (ties to even), certified by an extended-precision filter or exact comparisons
//     with the neighbouring midpoints.
// Predicates, by degree in the input coordinates: orientation of points and the turn
// between two lines, 2; side of a crossing against a line, 4; order of two vertices
// along a line or in the sweep, 5 (3 for a point against a crossing). Each is evaluated
// in FE (filtered double) and, only when that cannot tell, in Dy (exact): exactnum.hpp.
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

  i64 point(DD x, DD y) {
    pts.push_back(P{x, y});
    return (i64)pts.size() - 1;
  }
  i64 line(i64 a, i64 b) {
    lines.push_back(Line{a, b});
    return (i64)lines.size() - 1;
  }
  i64 vert_point(i64 p) {
    verts.push_back(Vert{p, -1, -1, fe(pts[p].x), fe(pts[p].y)});
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
  void rounded(i64 v, double& x, double& y) const {
    const Vert& V = verts[v];
    if (V.p >= 0) {
      x = pts[V.p].x.hi;
      y = pts[V.p].y.hi;
      return;
    }
    // the crossing of a vertical and a horizontal line through plain points: read off
    const Line &L1 = lines[V.l1], &L2 = lines[V.l2];
    const P &p1 = pts[L1.a], &q1 = pts[L1.b], &p2 = pts[L2.a], &q2 = pts[L2.b];
    if (plain(p1) && plain(q1) && plain(p2) && plain(q2)) {
      if (p1.x.hi == q1.x.hi && p2.y.hi == q2.y.hi) {
        x = p1.x.hi;
        y = p2.y.hi;
        return;
      }
      if (p1.y.hi == q1.y.hi && p2.x.hi == q2.x.hi) {
        x = p2.x.hi;
        y = p1.y.hi;
        return;
      }
    }
    // extended precision with a certified bound; exact when it cannot certify
    auto L = [](DD u) {
      long double s = (long double)u.hi + (long double)u.lo;
      return FEL{s, u.lo == 0 ? 0.0L : FEconst<long double>::U * std::fabs(s)};
    };
    const P &a = pts[lines[V.l1].a], &b = pts[lines[V.l1].b];
    const P &c = pts[lines[V.l2].a], &d = pts[lines[V.l2].b];
    FEL dx = L(d.x) - L(c.x), dyv = L(d.y) - L(c.y);
    FEL N = cross(L(c.x) - L(a.x), L(c.y) - L(a.y), dx, dyv);
    FEL D = cross(L(b.x) - L(a.x), L(b.y) - L(a.y), dx, dyv);
    FEL t = fe_div(N, D);
    x = certified(L(a.x) + (L(b.x) - L(a.x)) * t);
    y = certified(L(a.y) + (L(b.y) - L(a.y)) * t);
    if (x == x && y == y) return;
    Dy X, Y, W;
    exact(v, X, Y, W);
    if (x != x) x = round_exact(X, W);
    if (y != y) y = round_exact(Y, W);
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

class Overlay {
 public:
  explicit Overlay(Geo& g) : g_(g) {}

  // counters (for tests and limits)
  i64 n_pairs = 0, n_crossings = 0, n_vertices = 0, n_edges = 0;
  // work budget: a run that would node more crossings, or classify more candidate
  // pairs (box-overlapping edge pairs), stops (exceeded() is then true and the result is
  // empty); the caller reports RESOURCE
  i64 max_crossings = NO_LIMIT;
  i64 max_pairs = NO_LIMIT;
  bool exceeded() const { return over_; }
  // from this many edges on, candidate pairs come from a grid (boxes.hpp segment_pairs)
  i64 grid_min = 512;

  // The boundary of the selected region as exact edges (global vertex ids).
  void run(const std::vector<EdgeIn>& in, int rule, std::vector<BEdge>& out) {
    arrange(in, rule);
    out.clear();
    for (const Piece& b : bnd_) out.push_back(BEdge{b.line, vg_[b.from], vg_[b.to]});
  }
  // The same, with some vertices already in sweep order: each list in `sorted` holds
  // global vertex ids in the order of boundary_vertices() (one id per point, no id in
  // two lists); the vertices of `in` that no list holds are sorted here. Lists are merged
  // in linear time, so a cascade does not sort the same vertices at every level.
  void run(const std::vector<EdgeIn>& in, int rule, std::vector<BEdge>& out,
           const std::vector<const std::vector<i64>*>& sorted) {
    lists_ = &sorted;
    run(in, rule, out);
    lists_ = nullptr;
  }
  void run(const std::vector<EdgeIn>& in, int rule, Rings& out,
           const std::vector<const std::vector<i64>*>& sorted) {
    lists_ = &sorted;
    run(in, rule, out);
    lists_ = nullptr;
  }
  // After a run: its boundary's vertices (global ids, one per point) in sweep order.
  void boundary_vertices(std::vector<i64>& out) const {
    out.clear();
    if (bnd_.empty()) return;
    const i64 nv = (i64)av_.size();
    std::vector<char> used(nv, 0);
    for (const Piece& b : bnd_) used[b.from] = used[b.to] = 1;
    for (i64 t = 0; t < nv; ++t) {
      i64 v = sw_by_rank_[t];
      if (used[v]) out.push_back(av_[v]);
    }
  }
  // The selected region as rings with holes.
  void run(const std::vector<EdgeIn>& in, int rule, Rings& out) {
    run_raw(in, rule, out);
    if (out.status == OK) finish_rounded(out);
  }
  // as run, without the check after rounding (the check's own re-run uses it)
  void run_raw(const std::vector<EdgeIn>& in, int rule, Rings& out) {
    arrange(in, rule);
    if (over_) {
      out.clear();
      out.status = RESOURCE;
      return;
    }
    trace(out);
  }
  void finish_rounded(Rings& out);

  // Clipping polylines: `in` holds the polygons' edges (layers 0 and 1, as for `rule`)
  // and the polylines' edges on layer 2 (any nonzero weight; they change no winding
  // number). Keeps the parts of the polylines in the closed region the rule selects
  // (keep_inside), or in its open complement; where a polyline runs along the region's
  // boundary it is inside. The parts come out as polylines (rounded vertices, consecutive
  // equal ones dropped), each following the direction of its first input edge, joined
  // where exactly two parts meet; vertices where the part goes on along the same line are
  // dropped. RESOURCE when the work limits stop the run.
  int run_lines(const std::vector<EdgeIn>& in, int rule, bool keep_inside,
                std::vector<double>& xy, std::vector<i64>& off) {
    xy.clear();
    off.assign(1, 0);
    arrange(in, rule);
    if (over_) return RESOURCE;
    const i64 nv = (i64)av_.size();
    std::vector<i64> kept;
    for (i64 e = 0; e < (i64)pcs_.size(); ++e) {
      const Piece& p = pcs_[e];
      if (!p.nl) continue;
      bool ib = rule_inside(rule_, p.b0, p.b1), ia = rule_inside(rule_, p.b0 + p.c0, p.b1 + p.c1);
      if (keep_inside ? (ib || ia) : (!ib && !ia)) kept.push_back(e);
    }
    // incidence: kept pieces at each vertex
    std::vector<i64> lo(nv + 1, 0);
    for (i64 e : kept) {
      ++lo[pcs_[e].l + 1];
      ++lo[pcs_[e].r + 1];
    }
    for (i64 v = 0; v < nv; ++v) lo[v + 1] += lo[v];
    std::vector<i64> at(lo[nv]), fill(lo.begin(), lo.end() - 1);
    for (std::size_t k = 0; k < kept.size(); ++k) {
      at[fill[pcs_[kept[k]].l]++] = (i64)k;
      at[fill[pcs_[kept[k]].r]++] = (i64)k;
    }
    std::vector<char> used(kept.size(), 0);
    std::vector<i64> chain_v, chain_p;
    auto other = [&](i64 k, i64 v) { return pcs_[kept[k]].l == v ? pcs_[kept[k]].r : pcs_[kept[k]].l; };
    auto next_at = [&](i64 v, i64 k) -> i64 {  // the other kept piece at a vertex of degree 2
      if (lo[v + 1] - lo[v] != 2) return -1;
      i64 a = at[lo[v]], b = at[lo[v] + 1];
      i64 n = a == k ? b : a;
      return used[n] ? -1 : n;
    };
    auto tail_of = [&](i64 k) { return pcs_[kept[k]].ld > 0 ? pcs_[kept[k]].l : pcs_[kept[k]].r; };
    auto walk = [&](i64 k0, i64 v0) {
      chain_v.assign(1, v0);
      chain_p.clear();
      i64 k = k0, v = v0;
      while (k >= 0) {
        used[k] = 1;
        v = other(k, v);
        chain_v.push_back(v);
        chain_p.push_back(k);
        k = next_at(v, k);
      }
      emit_chain(chain_v, chain_p, kept, xy, off);
    };
    // open chains from their ends (vertices of degree != 2), forwards where the first
    // piece runs away from the end; then the closed ones
    for (int pass = 0; pass < 2; ++pass)
      for (std::size_t k = 0; k < kept.size(); ++k) {
        if (used[k]) continue;
        const Piece& p = pcs_[kept[k]];
        for (i64 v : {p.l, p.r}) {
          if (used[k] || lo[v + 1] - lo[v] == 2) continue;
          if (pass == 0 && tail_of((i64)k) != v) continue;
          walk((i64)k, v);
        }
      }
    for (std::size_t k = 0; k < kept.size(); ++k)
      if (!used[k]) walk((i64)k, tail_of((i64)k));
    return OK;
  }

  // Lower-dimensional parts of the union of rings (layer 0, weight 1, every ring convex
  // and counter-clockwise, e.g. piece sums): points inside the regularized union that
  // lie in no ring's interior. Pieces of such points (segments where rings meet from
  // both sides, continued along the union's boundary where the same line goes on) come
  // out as polylines, isolated points (an exact fit) as points; coordinates rounded.
  // `rings` are the input edge lists, one per ring (for the point test).
  void degenerate(const std::vector<std::vector<EdgeIn>>& rings, std::vector<double>& lines,
                  std::vector<i64>& line_off, std::vector<double>& points) {
    std::vector<EdgeIn> in;
    for (auto& r : rings) in.insert(in.end(), r.begin(), r.end());
    keep_zero_ = true;
    arrange(in, UNION);
    keep_zero_ = false;
    line_off.assign(1, 0);
    const i64 nv = (i64)av_.size(), np = (i64)pcs_.size();
    // classify pieces: 1 degenerate (inside on both sides, covered by no interior),
    // 2 on the boundary and covered by no interior (every boundary piece)
    std::vector<char> kind(np, 0);
    std::vector<char> at_boundary(nv, 0), at_degen(nv, 0);
    for (i64 e = 0; e < np; ++e) {
      const Piece& p = pcs_[e];
      bool ib = p.b0 >= 1, ia = p.b0 + p.c0 >= 1;
      if (ib && ia && p.b0 - p.n0 == 0) {
        kind[e] = 1;
        at_degen[p.l] = at_degen[p.r] = 1;
      } else if (ib != ia) {
        kind[e] = 2;
        at_boundary[p.l] = at_boundary[p.r] = 1;
      }
    }
    // adjacency of kinds 1 and 2
    std::vector<std::vector<i64>> inc(nv);
    for (i64 e = 0; e < np; ++e)
      if (kind[e]) {
        inc[pcs_[e].l].push_back(e);
        inc[pcs_[e].r].push_back(e);
      }
    auto other = [&](i64 e, i64 v) { return pcs_[e].l == v ? pcs_[e].r : pcs_[e].l; };
    // the same line going on: parallel and the other way round the vertex
    auto straight = [&](i64 e, i64 f) {
      return g_.turn(pcs_[e].line, 1, pcs_[f].line, 1) == 0;
    };
    std::vector<char> used(np, 0);
    auto emit_vertex = [&](std::vector<double>& out, i64 v) {
      double x, y;
      g_.rounded(av_[v], x, y);
      out.push_back(x);
      out.push_back(y);
    };
    for (i64 e0 = 0; e0 < np; ++e0) {
      if (kind[e0] != 1 || used[e0]) continue;
      // grow a chain both ways through degenerate pieces at vertices where exactly two
      // degenerate pieces meet, then continue along collinear boundary pieces
      std::vector<i64> chain{pcs_[e0].l, pcs_[e0].r};
      used[e0] = 1;
      for (int side = 0; side < 2; ++side) {
        i64 last = e0;
        while (true) {
          i64 v = side == 0 ? chain.back() : chain.front();
          i64 next = -1, cnt = 0;
          for (i64 f : inc[v])
            if (f != last && kind[f] == 1) {
              ++cnt;
              next = f;
            }
          if (cnt != 1 || used[next]) {
            // the line may go on along the boundary
            next = -1;
            if (cnt == 0)
              for (i64 f : inc[v])
                if (kind[f] == 2 && !used[f] && straight(last, f) && other(f, v) != other(last, v))
                  next = f;
            if (next < 0) break;
          }
          used[next] = 1;
          i64 w = other(next, v);
          if (side == 0)
            chain.push_back(w);
          else
            chain.insert(chain.begin(), w);
          last = next;
          if (kind[next] == 2) {
            // keep going straight along the boundary only
            while (true) {
              i64 nn = -1;
              for (i64 f : inc[w])
                if (f != next && kind[f] == 2 && !used[f] && straight(next, f)) nn = f;
              if (nn < 0) break;
              used[nn] = 1;
              w = other(nn, w);
              if (side == 0)
                chain.push_back(w);
              else
                chain.insert(chain.begin(), w);
              next = nn;
            }
            break;
          }
        }
      }
      // drop the chain's straight-on inner vertices
      std::vector<i64> keep{chain[0]};
      for (std::size_t k = 1; k + 1 < chain.size(); ++k) {
        // straight on when the two pieces' lines through the vertex are parallel
        i64 pe = -1, ne = -1;
        for (i64 f : inc[chain[k]]) {
          i64 o = other(f, chain[k]);
          if (o == chain[k - 1] && (kind[f])) pe = f;
          if (o == chain[k + 1] && (kind[f])) ne = f;
        }
        if (pe >= 0 && ne >= 0 && straight(pe, ne)) continue;
        keep.push_back(chain[k]);
      }
      keep.push_back(chain.back());
      for (i64 v : keep) emit_vertex(lines, v);
      line_off.push_back((i64)lines.size() / 2);
    }
    // isolated points: vertices away from the boundary and from degenerate pieces,
    // inside the union, in no ring's interior
    std::vector<double> bx0, bx1, by0, by1;
    std::vector<char> inside_all(nv, 1), touched(nv, 0);
    for (i64 e = 0; e < np; ++e) {
      const Piece& p = pcs_[e];
      bool ok = p.b0 >= 1 && p.b0 + p.c0 >= 1;
      for (i64 v : {p.l, p.r}) {
        touched[v] = 1;
        if (!ok) inside_all[v] = 0;
      }
    }
    for (i64 v = 0; v < nv; ++v) {
      if (!touched[v] || !inside_all[v] || at_degen[v] || at_boundary[v]) continue;
      if (covered(rings, av_[v])) continue;
      emit_vertex(points, v);
    }
  }

 private:
  // One polyline of clipped pieces: vertices chain_v (arrangement ids), pieces chain_p
  // (indices into kept) between them; a vertex where the line goes on is dropped.
  void emit_chain(const std::vector<i64>& cv, const std::vector<i64>& cp,
                  const std::vector<i64>& kept, std::vector<double>& xy, std::vector<i64>& off) {
    const std::size_t n0 = xy.size();
    const std::size_t m = cv.size();
    for (std::size_t i = 0; i < m; ++i) {
      bool inner = i > 0 && i + 1 < m;
      if (inner && pcs_[kept[cp[i - 1]]].line == pcs_[kept[cp[i]]].line) continue;
      double x, y;
      g_.rounded(av_[cv[i]], x, y);
      if (xy.size() > n0 && xy[xy.size() - 2] == x && xy[xy.size() - 1] == y) continue;
      xy.push_back(x);
      xy.push_back(y);
    }
    if (xy.size() - n0 < 4) {
      xy.resize(n0);
      return;
    }
    off.push_back((i64)(xy.size() / 2));
  }

  // Is global vertex v in the interior of one of the (convex, counter-clockwise) rings?
  bool covered(const std::vector<std::vector<EdgeIn>>& rings, i64 v) const {
    const Vert& V = g_.verts[v];
    for (const auto& r : rings) {
      // box test on the approximations first
      bool in_box = true;
      double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
      for (const EdgeIn& e : r) {
        const Vert& a = g_.verts[e.v0];
        x0 = std::min(x0, a.x.v - a.x.e);
        x1 = std::max(x1, a.x.v + a.x.e);
        y0 = std::min(y0, a.y.v - a.y.e);
        y1 = std::max(y1, a.y.v + a.y.e);
      }
      if (V.x.v + V.x.e < x0 || V.x.v - V.x.e > x1 || V.y.v + V.y.e < y0 || V.y.v - V.y.e > y1)
        in_box = false;
      if (!in_box) continue;
      bool inside = true;
      for (const EdgeIn& e : r) {
        // the edge runs along its line from v0 to v1: the side against that direction
        int s = g_.side(e.line, v) * g_.along(e.line, e.v1, e.v0);
        if (s <= 0) {
          inside = false;
          break;
        }
      }
      if (inside) return true;
    }
    return false;
  }

 public:

 private:
  Geo& g_;

  // ---- local state of a run (reused)
  std::vector<EdgeIn> ed_;        // input edges, local vertex ids
  std::vector<i64> vg_;           // local vertex -> global vertex (representative)
  std::vector<i64> rank_;         // local vertex -> sweep position
  struct Split {
    i64 edge, node;  // node: local vertex id, or nv0 + new crossing
    double k = 0, ke = 0;  // split(): position along the edge, approximate, and its bound
  };
  std::vector<Split> splits_;
  std::vector<i64> newv_;  // new crossing -> global vertex id
  std::vector<i64> uf_;
  struct Piece {
    i64 l, r;       // local vertices, rank l < rank r (boundary: from, to)
    i64 line;
    int s;          // +1 when the line runs from l's side to r's side
    int c0, c1;     // change of w0, w1 crossing upwards
    int b0, b1;     // winding numbers below
    i64 from, to;   // boundary direction (local ids)
    int n0;         // layer-0 weight of the edges with their inside below (for
                    // degenerate(): the rings covering the piece's own points)
    i64 src = -1;   // the input edge it comes from (its line's cached points: ll_)
    int nl = 0;     // layer-2 (line) edges along it: a piece of a clipped polyline
    int ld = 0;     // +1: the first such line edge runs l -> r, -1: r -> l
  };
  std::vector<Piece> pcs_, bnd_;
  int rule_ = UNION;
  bool over_ = false;
  bool keep_zero_ = false;

  i64 find(i64 a) {
    while (uf_[a] != a) {
      uf_[a] = uf_[uf_[a]];
      a = uf_[a];
    }
    return a;
  }
  void unite(i64 a, i64 b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (a < b)  // smaller ids (input vertices) stay roots
      uf_[b] = a;
    else
      uf_[a] = b;
  }

  const std::vector<const std::vector<i64>*>* lists_ = nullptr;

  void arrange(const std::vector<EdgeIn>& in, int rule) {
    rule_ = rule;
    n_pairs = n_crossings = n_vertices = n_edges = 0;
    over_ = false;
    local_vertices(in);
    intersect();
    if (over_) {
      splits_.clear();
      newv_.clear();
      ed_.clear();
      bnd_.clear();
      return;
    }
    split();
    order();
    pieces();
    windings();
    boundary();
  }

  // step 1: input vertices sorted and merged; edges in local ids
  std::vector<i64> tmp_;
  // sort keys: the vertex's approximation (exact for a plain point: e == 0)
  struct VKey {
    double x, ex, y, ey;
    i64 g;
  };
  std::vector<VKey> vk_;
  VKey vkey(i64 g) const {
    const Vert& V = g_.verts[g];
    return VKey{V.x.v, V.x.e, V.y.v, V.y.e, g};
  }
  // the sweep order (x, then y) of two vertices: by the approximations when they are
  // exact or certain, else exactly
  int vkcmp(const VKey& a, const VKey& b) const {
    if (a.g == b.g) return 0;
    if (a.ex == 0 && b.ex == 0 && a.ey == 0 && b.ey == 0) {
      if (a.x != b.x) return a.x < b.x ? -1 : 1;
      if (a.y != b.y) return a.y < b.y ? -1 : 1;
      return 0;
    }
    int s = fe_sign(FE{a.x, a.ex} - FE{b.x, b.ex});
    if (s == UNSURE) {
      if (same_vertex(a.g, b.g)) return 0;
      s = g_.coord_cmp(a.g, b.g, 0);
    }
    if (s != 0) return s;
    s = fe_sign(FE{a.y, a.ey} - FE{b.y, b.ey});
    if (s == UNSURE) s = g_.coord_cmp(a.g, b.g, 1);
    return s;
  }
  // certainly the same point without arithmetic: the same id, or crossings of the same
  // two lines (false: not known)
  bool same_vertex(i64 a, i64 b) const {
    if (a == b) return true;
    const Vert &A = g_.verts[a], &B = g_.verts[b];
    if (A.p >= 0 || B.p >= 0) return false;
    return (A.l1 == B.l1 && A.l2 == B.l2) || (A.l1 == B.l2 && A.l2 == B.l1);
  }
  // along(line, a, b) with that shortcut
  int along_s(i64 line, i64 a, i64 b) const {
    if (same_vertex(a, b)) return 0;
    return g_.along(line, a, b);
  }
  // global id -> local id of this run (valid when its stamp is the run's)
  struct G2L {
    std::uint32_t stamp;
    i64 local;
  };
  std::vector<G2L> g2l_;
  std::uint32_t run_stamp_ = 0;

  std::vector<VKey> vk2_, vk3_;
  // merges the sorted sequence b into a (sorted): the result in a
  void merge_keys(std::vector<VKey>& a, const std::vector<VKey>& b) {
    if (b.empty()) return;
    if (a.empty()) {
      a = b;
      return;
    }
    vk3_.resize(a.size() + b.size());
    std::merge(a.begin(), a.end(), b.begin(), b.end(), vk3_.begin(),
               [&](const VKey& x, const VKey& y) { return vkcmp(x, y) < 0; });
    a.swap(vk3_);
  }

  void local_vertices(const std::vector<EdgeIn>& in) {
    if (g2l_.size() < g_.verts.size()) g2l_.resize(g_.verts.size() + g_.verts.size() / 2, G2L{0, 0});
    if (++run_stamp_ == 0) {
      for (G2L& q : g2l_) q.stamp = 0;
      run_stamp_ = 1;
    }
    // the presorted lists, merged
    vk_.clear();
    if (lists_)
      for (const std::vector<i64>* L : *lists_) {
        vk2_.clear();
        for (i64 v : *L)
          if (g2l_[v].stamp != run_stamp_) {
            g2l_[v].stamp = run_stamp_;
            vk2_.push_back(vkey(v));
          }
        merge_keys(vk_, vk2_);
      }
    // the others, sorted
    vk2_.clear();
    for (const EdgeIn& e : in)
      for (i64 v : {e.v0, e.v1})
        if (g2l_[v].stamp != run_stamp_) {
          g2l_[v].stamp = run_stamp_;
          vk2_.push_back(vkey(v));
        }
    std::sort(vk2_.begin(), vk2_.end(),
              [&](const VKey& a, const VKey& b) { return vkcmp(a, b) < 0; });
    merge_keys(vk_, vk2_);
    vg_.clear();
    for (std::size_t t = 0; t < vk_.size(); ++t) {
      if (t == 0 || vkcmp(vk_[t - 1], vk_[t]) != 0) vg_.push_back(vk_[t].g);
      g2l_[vk_[t].g].local = (i64)vg_.size() - 1;
    }
    ed_.clear();
    ngroups_ = 0;
    for (const EdgeIn& e : in) {
      i64 a = g2l_[e.v0].local, b = g2l_[e.v1].local;
      if (a != b && e.w != 0) {
        ed_.push_back(EdgeIn{e.line, a, b, e.w, e.layer, e.group});
        if (e.group >= ngroups_) ngroups_ = e.group + 1;
      }
    }
    // approximations of the input vertices and of the edges' lines, cached
    lv_.resize(vg_.size());
    for (std::size_t t = 0; t < vg_.size(); ++t) lv_[t] = lvert(vg_[t]);
    ll_.resize(ed_.size());
    for (std::size_t i = 0; i < ed_.size(); ++i) {
      const Line& L = g_.lines[ed_[i].line];
      const P &a = g_.pts[L.a], &b = g_.pts[L.b];
      ll_[i] = LLine{fe(a.x), fe(a.y), fe(b.x), fe(b.y), plain(a) && plain(b)};
    }
  }
  int ngroups_ = 0;

  // step 2
  std::vector<double> bx0_, bx1_, by0_, by1_;
  std::vector<int> grp_;
  BoxScratch boxes_;
  std::vector<double> sx0_, sy0_, sx1_, sy1_, stol_;
  GridScratch grid_;
  TreeScratch tree_;
  void intersect() {
    const i64 n = (i64)ed_.size();
    splits_.clear();
    newv_.clear();
    bx0_.resize(n);
    bx1_.resize(n);
    by0_.resize(n);
    by1_.resize(n);
    grp_.resize(n);
    for (i64 i = 0; i < n; ++i) {
      const Vert &a = g_.verts[vg_[ed_[i].v0]], &b = g_.verts[vg_[ed_[i].v1]];
      grp_[i] = ed_[i].group;
      if (a.x.e == 0 && a.y.e == 0 && b.x.e == 0 && b.y.e == 0) {
        // exact coordinates: the box itself
        bx0_[i] = std::min(a.x.v, b.x.v);
        bx1_[i] = std::max(a.x.v, b.x.v);
        by0_[i] = std::min(a.y.v, b.y.v);
        by1_[i] = std::max(a.y.v, b.y.v);
        continue;
      }
      widened_box(a, b, bx0_[i], bx1_[i], by0_[i], by1_[i]);  // holds the exact vertices
    }
    auto on_pair = [&](i64 i, i64 j) {
      if (n_pairs >= max_pairs) over_ = true;
      if (over_) return false;
      classify(i, j);
      return true;
    };
    if (n >= grid_min) {
      // many edges: candidates from a grid over the segments themselves
      sx0_.resize(n);
      sy0_.resize(n);
      sx1_.resize(n);
      sy1_.resize(n);
      stol_.resize(n);
      for (i64 i = 0; i < n; ++i) {
        const Vert &a = g_.verts[vg_[ed_[i].v0]], &b = g_.verts[vg_[ed_[i].v1]];
        sx0_[i] = a.x.v;
        sy0_[i] = a.y.v;
        sx1_[i] = b.x.v;
        sy1_[i] = b.y.v;
        stol_[i] = std::max(std::max(a.x.e, a.y.e), std::max(b.x.e, b.y.e)) * (1 + 0x1p-40);
      }
      i64 resume = -1;
      if (segment_pairs(n, sx0_.data(), sy0_.data(), sx1_.data(), sy1_.data(), stol_.data(),
                        bx0_.data(), bx1_.data(), by0_.data(), by1_.data(), grp_.data(), grid_,
                        on_pair, &resume))
        return;
      // the grid gave up (long edges crowd its cells: finish from `resume`) or declined
      // (too many cell registrations: all of it): a packed R-tree, whose work follows the
      // overlapping boxes (a sweep keeps every long edge active: nested squares)
      if (!over_)
        box_tree_pairs(n, bx0_.data(), bx1_.data(), by0_.data(), by1_.data(), grp_.data(),
                       resume >= 0 ? resume : 0, tree_, on_pair);
      return;
    }
    if (n < 256)
      box_pairs_scan(n, bx0_.data(), bx1_.data(), by0_.data(), by1_.data(), grp_.data(), boxes_,
                     on_pair);
    else
      box_pairs_grouped(n, bx0_.data(), bx1_.data(), by0_.data(), by1_.data(), grp_.data(),
                        ngroups_, boxes_, on_pair);
  }

  // vertex p strictly between the ends of edge i (p on its line)
  bool inside_edge(i64 i, i64 p) const {
    const EdgeIn& e = ed_[i];
    i64 l = e.line;
    int s0 = g_.along(l, vg_[p], vg_[e.v0]), s1 = g_.along(l, vg_[p], vg_[e.v1]);
    return s0 * s1 < 0;
  }

  void classify(i64 i, i64 j) {
    if (over_) return;
    ++n_pairs;
    const EdgeIn &s = ed_[i], &t = ed_[j];
    const i64 p = s.v0, q = s.v1, r = t.v0, u = t.v1;
    auto sd = [&](i64 e, i64 v, i64 e0, i64 e1) {
      return (v == e0 || v == e1) ? 0 : side_ev(e, v);
    };
    int oa = sd(i, r, p, q), ob = sd(i, u, p, q);
    if (oa * ob > 0) return;
    if (oa == 0 && ob == 0) {
      // collinear: each endpoint strictly inside the other edge splits it
      if (r != p && r != q && inside_edge(i, r)) splits_.push_back(Split{i, r});
      if (u != p && u != q && inside_edge(i, u)) splits_.push_back(Split{i, u});
      if (p != r && p != u && inside_edge(j, p)) splits_.push_back(Split{j, p});
      if (q != r && q != u && inside_edge(j, q)) splits_.push_back(Split{j, q});
      return;
    }
    int oc = sd(j, p, r, u), od = sd(j, q, r, u);
    if (oc * od > 0) return;
    if (oa == 0 || ob == 0 || oc == 0 || od == 0) {
      // one common point, an endpoint of one of them
      if (oa == 0 && r != p && r != q) splits_.push_back(Split{i, r});
      if (ob == 0 && u != p && u != q) splits_.push_back(Split{i, u});
      if (oc == 0 && p != r && p != u) splits_.push_back(Split{j, p});
      if (od == 0 && q != r && q != u) splits_.push_back(Split{j, q});
      return;
    }
    // a proper crossing: a new vertex
    if (++n_crossings > max_crossings) {
      over_ = true;
      return;
    }
    i64 node = (i64)vg_.size() + (i64)newv_.size();
    newv_.push_back(g_.vert_cross(s.line, t.line));
    splits_.push_back(Split{i, node});
    splits_.push_back(Split{j, node});
  }

  i64 gid(i64 node) const {
    const i64 nv0 = (i64)vg_.size();
    return node < nv0 ? vg_[node] : newv_[node - nv0];
  }

  // step 3: splits sorted along their edges, equal ones united
  std::vector<std::int8_t> edir_;
  void split() {
    const i64 nv0 = (i64)vg_.size();
    uf_.resize(nv0 + newv_.size());
    std::iota(uf_.begin(), uf_.end(), 0);
    // each split edge's direction against its line (+1: v0 -> v1 runs along it)
    edir_.resize(ed_.size());
    for (std::size_t k = 0; k < splits_.size(); ++k)
      if (k == 0 || splits_[k].edge != splits_[k - 1].edge) {
        const EdgeIn& e = ed_[splits_[k].edge];
        edir_[splits_[k].edge] = (std::int8_t)g_.along(e.line, vg_[e.v1], vg_[e.v0]);
      }
    // the position along the edge: its line's axis coordinate (as along() compares),
    // times the sign that makes it grow from v0 to v1; certified apart -> no exact test
    for (Split& sp : splits_) {
      const EdgeIn& e = ed_[sp.edge];
      const P &p = g_.pts[g_.lines[e.line].a], &q = g_.pts[g_.lines[e.line].b];
      const bool ya = dd_eq(p.x, q.x);
      const int sg = (ya ? dd_cmp(q.y, p.y) : dd_cmp(q.x, p.x)) * edir_[sp.edge];
      const Vert& V = g_.verts[gid(sp.node)];
      const FE c = ya ? V.y : V.x;
      sp.k = sg > 0 ? c.v : -c.v;
      sp.ke = c.e;
    }
    std::sort(splits_.begin(), splits_.end(), [&](const Split& a, const Split& b) {
      if (a.edge != b.edge) return a.edge < b.edge;
      if (a.node == b.node) return false;
      const double gap = (a.ke + b.ke) * (1 + 0x1p-50);
      if (b.k - a.k > gap) return true;
      if (a.k - b.k > gap) return false;
      const EdgeIn& e = ed_[a.edge];
      // along the edge's own direction (v0 -> v1)
      int s = along_s(e.line, gid(a.node), gid(b.node));
      return s * edir_[a.edge] < 0;
    });
    for (std::size_t k = 1; k < splits_.size(); ++k) {
      const Split &a = splits_[k - 1], &b = splits_[k];
      if (a.edge == b.edge && a.node != b.node &&
          along_s(ed_[a.edge].line, gid(a.node), gid(b.node)) == 0)
        unite(a.node, b.node);
    }
    // representatives: roots; a new vertex united with an input one maps to it
  }

  // step 4 prelude: local vertices of the arrangement in sweep order
  std::vector<i64> lid_;  // node -> arrangement vertex (local), after union
  std::vector<i64> av_;   // arrangement vertex -> global vertex id
  void order() {
    const i64 nn = (i64)uf_.size(), nv0 = (i64)vg_.size();
    lid_.assign(nn, -1);
    av_.clear();
    for (i64 node = 0; node < nn; ++node) {
      i64 r = find(node);
      if (lid_[r] < 0) {
        lid_[r] = (i64)av_.size();
        av_.push_back(gid(r));
      }
      lid_[node] = lid_[r];
    }
    const i64 m = (i64)av_.size();
    n_vertices = m;
    lv_.resize(m);
    for (i64 t = nv0; t < m; ++t) lv_[t] = lvert(av_[t]);
    // the input vertices are roots, in sweep order (local_vertices); sort the new ones
    // and merge
    vk_.clear();
    for (i64 t = nv0; t < m; ++t) vk_.push_back(vkey(av_[t]));
    std::vector<i64>& tail = tmp_;
    tail.resize(m - nv0);
    std::iota(tail.begin(), tail.end(), nv0);
    std::sort(tail.begin(), tail.end(),
              [&](i64 a, i64 b) { return vkcmp(vk_[a - nv0], vk_[b - nv0]) < 0; });
    rank_.resize(m);
    i64 i = 0, j = 0, t = 0;
    VKey hk{};
    bool have = false;
    while (i < nv0 || j < m - nv0) {
      if (i < nv0 && !have) {
        hk = vkey(av_[i]);
        have = true;
      }
      bool take_head =
          j >= m - nv0 || (i < nv0 && vkcmp(hk, vk_[tail[j] - nv0]) < 0);
      if (take_head) {
        rank_[i++] = t++;
        have = false;
      } else {
        rank_[tail[j++]] = t++;
      }
    }
  }

  // step 4: pieces
  std::vector<Piece> raw_;
  std::vector<std::pair<u64, std::uint32_t>> pkey_;
  void pieces() {
    std::vector<Piece>& raw = raw_;
    raw.clear();
    raw.reserve(ed_.size() + splits_.size());  // the most there can be
    std::size_t k = 0;
    for (i64 i = 0; i < (i64)ed_.size(); ++i) {
      const EdgeIn& e = ed_[i];
      // the line's own direction against the edge's
      int es = g_.along(e.line, vg_[e.v1], vg_[e.v0]);
      i64 prev = lid_[e.v0];
      auto emit = [&](i64 nxt) {
        if (nxt == prev) return;
        Piece pc;
        bool fwd = rank_[prev] < rank_[nxt];
        pc.l = fwd ? prev : nxt;
        pc.r = fwd ? nxt : prev;
        pc.line = e.line;
        pc.src = i;
        // the line runs from l's side to r's side when the edge does (fwd) and the line
        // runs along the edge (es > 0), or neither
        pc.s = (fwd == (es > 0)) ? 1 : -1;
        int c = fwd ? e.w : -e.w;
        pc.c0 = e.layer == 0 ? c : 0;
        pc.c1 = e.layer == 1 ? c : 0;
        pc.nl = e.layer == 2 ? 1 : 0;
        pc.ld = e.layer == 2 ? (fwd ? 1 : -1) : 0;
        pc.b0 = pc.b1 = 0;
        raw.push_back(pc);
        prev = nxt;
      };
      while (k < splits_.size() && splits_[k].edge == i) {
        emit(lid_[splits_[k].node]);
        ++k;
      }
      emit(lid_[e.v1]);
    }
    // sorted by (l, r) through small keys; pieces joining the same two vertices merged
    pkey_.resize(raw.size());
    for (std::size_t i = 0; i < raw.size(); ++i)
      pkey_[i] = {((u64)raw[i].l << 32) | (u64)raw[i].r, (std::uint32_t)i};
    std::sort(pkey_.begin(), pkey_.end());
    pcs_.clear();
    pcs_.reserve(raw.size());
    for (std::size_t i = 0; i < pkey_.size();) {
      std::size_t j = i;
      Piece pc = raw[pkey_[i].second];
      pc.c0 = pc.c1 = pc.n0 = pc.nl = pc.ld = 0;
      for (; j < pkey_.size() && pkey_[j].first == pkey_[i].first; ++j) {
        const Piece& q = raw[pkey_[j].second];
        pc.c0 += q.c0;
        pc.c1 += q.c1;
        if (q.c0 < 0) pc.n0 -= q.c0;
        if (q.nl && !pc.nl) pc.ld = q.ld;
        pc.nl += q.nl;
      }
      // keep_zero_: a piece where rings meet from both sides stays (degenerate())
      if (pc.c0 != 0 || pc.c1 != 0 || pc.nl != 0 || (keep_zero_ && j > i + 1))
        pcs_.push_back(pc);
      i = j;
    }
    n_edges = (i64)pcs_.size();
  }

  // side of arrangement vertex v against the line of piece e (oriented l -> r)
  int side(const Piece& e, i64 v) const {
    return (e.src >= 0 ? side_ev(e.src, v) : g_.side(e.line, av_[v])) * e.s;
  }
  // Side of local vertex v (an input vertex, or an arrangement vertex once order() has
  // run: input vertices keep their ids) against the line of input edge i: from the
  // cached plain coordinates when both are plain (one orientation of doubles), else
  // Geo::side.
  struct LLine {
    FE ax, ay, bx, by;  // the line's two points (exact when e == 0)
    bool plain;
  };
  struct LVert {
    FE x, y;  // exact when plain (a point of two doubles)
    bool plain;
  };
  std::vector<LLine> ll_;
  std::vector<LVert> lv_;
  int side_ev(i64 i, i64 v) const {
    const LLine& L = ll_[i];
    const LVert& V = lv_[v];
    if (L.plain && V.plain)
      return mk::orient(L.ax.v, L.ay.v, L.bx.v, L.by.v, V.x.v, V.y.v);
    int s = fe_sign(cross(L.bx - L.ax, L.by - L.ay, V.x - L.ax, V.y - L.ay));
    if (s != UNSURE) return s;
    return g_.side(ed_[i].line, v < (i64)vg_.size() ? vg_[v] : av_[v]);
  }
  LVert lvert(i64 gv) const {
    const Vert& V = g_.verts[gv];
    return LVert{V.x, V.y, V.p >= 0 && V.x.e == 0 && V.y.e == 0};
  }
  // pieces from one vertex: e1 below e2 when the turn from e1 to e2 is left
  bool slope_below(const Piece& e1, const Piece& e2) const {
    if (e1.src >= 0 && e2.src >= 0 && ll_[e1.src].plain && ll_[e2.src].plain) {
      const LLine &a = ll_[e1.src], &b = ll_[e2.src];
      return cross_sign(a.ax.v, a.ay.v, a.bx.v, a.by.v, b.ax.v, b.ay.v, b.bx.v, b.by.v) * e1.s *
                 e2.s > 0;
    }
    return g_.turn(e1.line, e1.s, e2.line, e2.s) > 0;
  }

  // The sweep's status: piece ids bottom to top in chunks of at most 2 * kChunk, so that
  // replacing the pieces at one vertex costs a chunk, not the whole status (nested frames
  // keep 10^5 pieces active: a sorted vector spent most of their overlay moving memory).
  struct SweepStatus {
    static constexpr std::size_t kChunk = 256;
    std::vector<std::vector<i64>> ch;  // non-empty chunks, in order
    std::size_t spare = 0;             // chunks ch[size - spare ..) are empty spares
    void clear() {
      for (auto& c : ch) c.clear();
      spare = ch.size();
    }
    std::size_t size() const { return ch.size() - spare; }
    // a new empty chunk at index c (reusing a spare's memory)
    void open(std::size_t c) {
      if (spare > 0) {
        std::vector<i64> v;
        v.swap(ch.back());
        ch.pop_back();
        --spare;
        ch.insert(ch.begin() + (std::ptrdiff_t)c, std::move(v));
      } else {
        ch.insert(ch.begin() + (std::ptrdiff_t)c, std::vector<i64>());
      }
    }
    void close(std::size_t c) {  // chunk c is empty: it becomes a spare
      std::vector<i64> v;
      v.swap(ch[c]);
      ch.erase(ch.begin() + (std::ptrdiff_t)c);
      ch.push_back(std::move(v));
      ++spare;
    }
  };
  SweepStatus sw_st_;

  // Sweeps the pieces ps (which do not cross); after inserting the pieces that start at
  // a vertex calls at_vertex(new pieces bottom to top, predecessor of the lowest or -1).
  // The status is sorted bottom to top: at vertex v the pieces below v are a prefix (v is
  // strictly left of each, looking along it), then come the pieces that end at v (no
  // piece passes through a vertex: the pieces are noded); those are replaced by the
  // pieces that start at v, in slope order.
  std::vector<i64> sw_by_rank_, sw_lo_l_, sw_lo_r_, sw_at_l_, sw_at_r_, sw_fill_, sw_fresh_;
  template <class F>
  void sweep(const std::vector<Piece>& ps, F&& at_vertex) {
    const i64 nv = (i64)av_.size(), np = (i64)ps.size();
    std::vector<i64>&by_rank = sw_by_rank_, &lo_l = sw_lo_l_, &lo_r = sw_lo_r_,
    &at_l = sw_at_l_, &at_r = sw_at_r_, &fresh = sw_fresh_;
    by_rank.resize(nv);
    for (i64 v = 0; v < nv; ++v) by_rank[rank_[v]] = v;
    lo_l.assign(nv + 1, 0);
    lo_r.assign(nv + 1, 0);
    for (const Piece& e : ps) {
      ++lo_l[e.l + 1];
      ++lo_r[e.r + 1];
    }
    for (i64 v = 0; v < nv; ++v) {
      lo_l[v + 1] += lo_l[v];
      lo_r[v + 1] += lo_r[v];
    }
    at_l.resize(np);
    at_r.resize(np);
    sw_fill_.assign(lo_l.begin(), lo_l.end() - 1);
    for (i64 e = 0; e < np; ++e) at_l[sw_fill_[ps[e].l]++] = e;
    sw_fill_.assign(lo_r.begin(), lo_r.end() - 1);
    for (i64 e = 0; e < np; ++e) at_r[sw_fill_[ps[e].r]++] = e;
    SweepStatus& st = sw_st_;
    st.clear();
    auto& ch = st.ch;
    for (i64 t = 0; t < nv; ++t) {
      i64 v = by_rank[t];
      const i64 nend = lo_r[v + 1] - lo_r[v], nstart = lo_l[v + 1] - lo_l[v];
      if (nend == 0 && nstart == 0) continue;
      auto below = [&](i64 id) {
        const Piece& e = ps[id];
        return e.r != v && side(e, v) > 0;  // v is on the pieces that end at v
      };
      // the first piece not below v: its chunk c, then its place o in it
      const std::size_t nc = st.size();
      std::size_t c = 0, o = 0;
      {
        std::size_t lo = 0, hi = nc;
        while (lo < hi) {
          std::size_t mid = (lo + hi) / 2;
          if (below(ch[mid].back())) lo = mid + 1;
          else hi = mid;
        }
        c = lo;
        if (c < nc) {
          std::size_t a = 0, b = ch[c].size();
          while (a < b) {
            std::size_t mid = (a + b) / 2;
            if (below(ch[c][mid])) a = mid + 1;
            else b = mid;
          }
          o = a;
        }
      }
      // the nend pieces from there end at v: removed (they may span chunks)
      for (i64 k = nend; k > 0;) {
#ifdef MK_OVERLAY_CHECK
        if (c >= st.size() || ps[ch[c][o]].r != v) std::abort();
#endif
        std::vector<i64>& cur = ch[c];
        const std::size_t take = std::min<std::size_t>((std::size_t)k, cur.size() - o);
        cur.erase(cur.begin() + (std::ptrdiff_t)o, cur.begin() + (std::ptrdiff_t)(o + take));
        k -= (i64)take;
        if (cur.empty()) {
          st.close(c);  // the next chunk is now chunk c, from its start
          o = 0;
        } else if (o == cur.size() && k > 0) {
          ++c;
          o = 0;
        }
      }
      if (nstart == 0) continue;
      // the predecessor of the place, then the fresh pieces inserted there
      i64 pred = -1;
      if (o > 0) pred = ch[c][o - 1];
      else if (c > 0) pred = ch[c - 1].back();
      fresh.assign(at_l.begin() + lo_l[v], at_l.begin() + lo_l[v + 1]);
      if (fresh.size() > 1)
        std::sort(fresh.begin(), fresh.end(),
                  [&](i64 a, i64 b) { return slope_below(ps[a], ps[b]); });
      if (c == st.size()) {  // at the top: the last chunk's end, or a new chunk
        if (c > 0 && ch[c - 1].size() < 2 * SweepStatus::kChunk) {
          --c;
          o = ch[c].size();
        } else {
          st.open(c);
          o = 0;
        }
      }
      std::vector<i64>& cur = ch[c];
      cur.insert(cur.begin() + (std::ptrdiff_t)o, fresh.begin(), fresh.end());
      if (cur.size() > 2 * SweepStatus::kChunk) {  // split in halves
        const std::size_t half = cur.size() / 2;
        st.open(c + 1);
        std::vector<i64>& a = ch[c];
        ch[c + 1].assign(a.begin() + (std::ptrdiff_t)half, a.end());
        a.resize(half);
      }
      at_vertex(fresh, pred);
    }
  }

  // step 5
  void windings() {
    sweep(pcs_, [&](const std::vector<i64>& fresh, i64 pred) {
      int w0 = pred < 0 ? 0 : pcs_[pred].b0 + pcs_[pred].c0;
      int w1 = pred < 0 ? 0 : pcs_[pred].b1 + pcs_[pred].c1;
      for (i64 e : fresh) {
        pcs_[e].b0 = w0;
        pcs_[e].b1 = w1;
        w0 += pcs_[e].c0;
        w1 += pcs_[e].c1;
      }
    });
  }

  // step 6: the boundary, inside on the left
  void boundary() {
    bnd_.clear();
    for (const Piece& e : pcs_) {
      bool ib = rule_inside(rule_, e.b0, e.b1);
      bool ia = rule_inside(rule_, e.b0 + e.c0, e.b1 + e.c1);
      if (ib == ia) continue;
      Piece b = e;
      b.from = ia ? e.l : e.r;
      b.to = ia ? e.r : e.l;
      bnd_.push_back(b);
    }
    // boundary pieces reference arrangement vertices: map to global ids for run(out)
    vg_.assign(av_.begin(), av_.end());
  }

  // direction of boundary piece b (from -> to) as points of its line
  void bdir(const Piece& b, const P*& p, const P*& q) const {
    // the line runs l -> r when s > 0; from -> to is l -> r when from == l
    int s = b.from == b.l ? b.s : -b.s;
    g_.dir(b.line, s, p, q);
  }
  int bturn(const Piece& a, const Piece& b) const {
    const P *p1, *q1, *p2, *q2;
    bdir(a, p1, q1);
    bdir(b, p2, q2);
    return dir_cross(*p1, *q1, *p2, *q2);
  }

  // ---- rings
  std::vector<std::vector<i64>> rings_;       // arrangement vertices, inside on the left
  std::vector<std::vector<i64>> ring_edges_;  // boundary pieces of each ring
  std::vector<std::vector<i64>> ring_lines_;  // line of the edge leaving each kept vertex
  std::vector<char> ring_ccw_;
  std::vector<char> junction_;  // arrangement vertex where several boundary rings meet

  void trace(Rings& out) {
    out.clear();
    rings_.clear();
    ring_edges_.clear();
    ring_lines_.clear();
    ring_ccw_.clear();
    const i64 nv = (i64)av_.size(), nb = (i64)bnd_.size();
    std::vector<i64> lo(nv + 1, 0);
    for (const Piece& b : bnd_) ++lo[b.from + 1];
    for (i64 v = 0; v < nv; ++v) lo[v + 1] += lo[v];
    std::vector<i64> outs(nb);
    {
      std::vector<i64> f(lo.begin(), lo.end() - 1);
      for (i64 b = 0; b < nb; ++b) outs[f[bnd_[b].from]++] = b;
    }
    for (i64 v = 0; v < nv; ++v) {
      if (lo[v + 1] - lo[v] > 1)
        std::sort(outs.begin() + lo[v], outs.begin() + lo[v + 1], [&](i64 a, i64 b) {
          const P *p1, *q1, *p2, *q2;
          bdir(bnd_[a], p1, q1);
          bdir(bnd_[b], p2, q2);
          return angle_less(*p1, *q1, *p2, *q2);
        });
    }
    // the next boundary piece after b: the first outgoing one clockwise from the way back
    auto next_of = [&](i64 b) -> i64 {
      i64 v = bnd_[b].to;
      i64 k0 = lo[v], k1 = lo[v + 1];
      if (k1 - k0 == 1) return outs[k0];
      const P *p, *q;
      bdir(bnd_[b], p, q);  // the way back is q -> p
      i64 best = -1;
      for (i64 k = k0; k < k1; ++k) {
        const P *p2, *q2;
        bdir(bnd_[outs[k]], p2, q2);
        if (angle_less(*p2, *q2, *q, *p)) best = k;
      }
      return best >= 0 ? outs[best] : outs[k1 - 1];
    };
    junction_.assign(nv, 0);
    for (i64 v = 0; v < nv; ++v) junction_[v] = lo[v + 1] - lo[v] > 1;
    std::vector<char> used(nb, 0);
    std::vector<i64> walk_v, walk_e, pos(nv, -1);
    for (i64 b0 = 0; b0 < nb; ++b0) {
      if (used[b0]) continue;
      // one closed walk, split at repeated vertices into simple loops
      walk_v.clear();
      walk_e.clear();
      i64 b = b0;
      while (!used[b]) {
        used[b] = 1;
        i64 v = bnd_[b].from;
        if (pos[v] >= 0) {
          i64 p0 = pos[v];
          std::vector<i64> rv(walk_v.begin() + p0, walk_v.end());
          std::vector<i64> re(walk_e.begin() + p0, walk_e.end());
          for (i64 k = p0; k < (i64)walk_v.size(); ++k) pos[walk_v[k]] = -1;
          walk_v.resize(p0);
          walk_e.resize(p0);
          add_ring(rv, re);
        }
        pos[v] = (i64)walk_v.size();
        walk_v.push_back(v);
        walk_e.push_back(b);
        b = next_of(b);
      }
      for (i64 v : walk_v) pos[v] = -1;
      if (!walk_v.empty()) add_ring(walk_v, walk_e);
    }
    assemble(out);
  }

  // a simple loop: drop collinear vertices, record its orientation
  void add_ring(const std::vector<i64>& rv, const std::vector<i64>& re) {
    const i64 n = (i64)rv.size();
    std::vector<i64> kv, kl;
    kv.reserve(n);
    i64 lowest = -1, lowest_i = 0;
    for (i64 i = 0; i < n; ++i) {
      // rv[i] sits between re[i - 1] (in) and re[i] (out)
      // straight on: dropped, unless other boundary edges meet there (a ring touching
      // this one at a point of its edge): the vertex stays in both, so rounding cannot
      // move the edge off the touching vertex
      if (!junction_[rv[i]] && bturn(bnd_[re[(i + n - 1) % n]], bnd_[re[i]]) == 0) continue;
      if (lowest < 0 || rank_[rv[i]] < rank_[lowest]) {
        lowest = rv[i];
        lowest_i = i;
      }
      kv.push_back(rv[i]);
      kl.push_back(bnd_[re[i]].line);
    }
    if (kv.size() < 3) return;  // cannot happen for a boundary with area
    // the turn at the lowest vertex is strict and its sign is the orientation
    int t = bturn(bnd_[re[(lowest_i + n - 1) % n]], bnd_[re[lowest_i]]);
    rings_.push_back(std::move(kv));
    ring_lines_.push_back(std::move(kl));
    ring_edges_.push_back(re);
    ring_ccw_.push_back(t > 0);
  }

  // each hole's exterior (index into rings_), -1 for exteriors
  std::vector<i64> owner_;
  void holes() {
    const i64 nr = (i64)rings_.size();
    owner_.assign(nr, -1);
    bool any = false;
    for (i64 k = 0; k < nr; ++k) any |= !ring_ccw_[k];
    if (!any) return;
    std::vector<Piece> ps;
    std::vector<i64> ring_of;
    for (i64 k = 0; k < nr; ++k)
      for (i64 b : ring_edges_[k]) {
        ps.push_back(bnd_[b]);
        ring_of.push_back(k);
      }
    std::vector<char> done(nr, 0);
    sweep(ps, [&](const std::vector<i64>& fresh, i64 pred) {
      i64 below = pred;
      for (i64 e : fresh) {
        i64 k = ring_of[e];
        if (!done[k]) {
          done[k] = 1;
          if (!ring_ccw_[k] && below >= 0) {
            i64 rk = ring_of[below];
            owner_[k] = ring_ccw_[rk] ? rk : owner_[rk];
          }
        }
        below = e;
      }
    });
  }

  void assemble(Rings& out) {
    holes();
    const i64 nr = (i64)rings_.size(), nv = (i64)av_.size();
    std::vector<double> vx(nv), vy(nv);
    std::vector<char> have(nv, 0);
    out.exact_vertices = true;
    auto xy = [&](i64 v, double& x, double& y) {
      if (!have[v]) {
        g_.rounded(av_[v], vx[v], vy[v]);
        if (!(vx[v] - vx[v] == 0 && vy[v] - vy[v] == 0)) out.status = OVERFLOW;
        if (out.exact_vertices && !g_.rounds_exactly(av_[v], vx[v], vy[v]))
          out.exact_vertices = false;
        have[v] = 1;
      }
      x = vx[v];
      y = vy[v];
    };
    // a ring's smallest rounded vertex (x, then y): where it starts, and the sort key
    std::vector<std::pair<std::pair<double, double>, i64>> key(nr);
    std::vector<i64> start(nr);
    for (i64 k = 0; k < nr; ++k) {
      std::pair<double, double> best{INFINITY, INFINITY};
      for (std::size_t i = 0; i < rings_[k].size(); ++i) {
        double x, y;
        xy(rings_[k][i], x, y);
        if (std::make_pair(x, y) < best) {
          best = {x, y};
          start[k] = (i64)i;
        }
      }
      key[k] = {best, k};
    }
    std::sort(key.begin(), key.end());
    std::vector<std::vector<i64>> kids(nr);
    for (auto& kk : key) {
      i64 k = kk.second;
      if (ring_ccw_[k]) continue;
      if (owner_[k] >= 0)
        kids[owner_[k]].push_back(k);
      else
        out.status = INTERNAL;  // a hole without an exterior: never expected
    }
    auto emit = [&](i64 k) {
      const std::vector<i64>& r = rings_[k];
      const std::size_t m = r.size();
      for (std::size_t i = 0; i < m; ++i) {
        double x, y;
        xy(r[(start[k] + i) % m], x, y);
        out.xy.push_back(x);
        out.xy.push_back(y);
        if (out.want_lines) out.line.push_back(ring_lines_[k][(start[k] + i) % m]);
      }
      out.ring_off.push_back((i64)out.xy.size() / 2);
    };
    for (auto& kk : key) {
      i64 k = kk.second;
      if (!ring_ccw_[k]) continue;
      emit(k);
      for (i64 h : kids[k]) emit(h);
      out.poly_off.push_back((i64)out.ring_off.size() - 1);
    }
  }
};

// ------------------------------------------------------------------------------------
// the output contract after rounding

// Drops repeated vertices (neighbours rounded to the same double pair) from every ring of
// `r`, and rings left with fewer than three. A polygon whose exterior vanished loses its
// holes too. A vertex that rounding puts exactly on the line through its neighbours is
// kept: the output is the rounded exact vertices, no more and no fewer (an exactly
// collinear *exact* vertex never reaches it).
inline void clean_rounded(Rings& r) {
  Rings out;
  out.status = r.status;
  out.exact_vertices = r.exact_vertices;
  // the supporting lines follow their vertices (a dropped repeat's zero-length edge goes)
  const bool lines = r.want_lines && r.line.size() * 2 == r.xy.size();
  out.want_lines = r.want_lines;
  std::vector<double> x, y;
  std::vector<i64> ln;
  for (std::size_t p = 0; p + 1 < r.poly_off.size(); ++p) {
    bool ext_kept = false;
    for (i64 k = r.poly_off[p]; k < r.poly_off[p + 1]; ++k) {
      x.clear();
      y.clear();
      ln.clear();
      const i64 r0 = r.ring_off[k], r1 = r.ring_off[k + 1], m = r1 - r0;
      for (i64 i = r0; i < r1; ++i) {
        i64 j = i + 1 < r1 ? i + 1 : r0;
        if (m > 1 && r.xy[2 * i] == r.xy[2 * j] && r.xy[2 * i + 1] == r.xy[2 * j + 1]) continue;
        x.push_back(r.xy[2 * i]);
        y.push_back(r.xy[2 * i + 1]);
        if (lines) ln.push_back(r.line[i]);
      }
      if (x.size() < 3) continue;
      // start again at the smallest vertex (x, then y)
      std::size_t s0 = 0;
      for (std::size_t i = 1; i < x.size(); ++i)
        if (x[i] < x[s0] || (x[i] == x[s0] && y[i] < y[s0])) s0 = i;
      std::rotate(x.begin(), x.begin() + s0, x.end());
      std::rotate(y.begin(), y.begin() + s0, y.end());
      if (lines) std::rotate(ln.begin(), ln.begin() + s0, ln.end());
      bool is_ext = k == r.poly_off[p];
      if (is_ext)
        ext_kept = true;
      else if (!ext_kept)
        continue;
      for (std::size_t i = 0; i < x.size(); ++i) {
        out.xy.push_back(x[i]);
        out.xy.push_back(y[i]);
        if (lines) out.line.push_back(ln[i]);
      }
      out.ring_off.push_back((i64)out.xy.size() / 2);
    }
    if (ext_kept) out.poly_off.push_back((i64)out.ring_off.size() - 1);
  }
  r = std::move(out);
}

// True when the rounded rings are a valid polygon set (exact signs on the doubles): no
// two edges cross or overlap; a ring meets itself only where consecutive edges share
// their vertex; two rings may touch at points -- a vertex of one on the other, or a
// common vertex -- without crossing there. That is OGC validity up to the connectedness
// of interiors, which rounding cannot break without one of these events.
inline bool valid_rounded(const Rings& r) {
  const i64 nr = (i64)r.ring_off.size() - 1;
  const i64 n = (i64)r.xy.size() / 2;
  std::vector<i64> ring_of;
  ring_of.reserve(n);
  for (i64 k = 0; k < nr; ++k)
    for (i64 i = r.ring_off[k]; i < r.ring_off[k + 1]; ++i) ring_of.push_back(k);
  auto nxt = [&](i64 i) {
    return i + 1 < r.ring_off[ring_of[i] + 1] ? i + 1 : r.ring_off[ring_of[i]];
  };
  auto prv = [&](i64 i) { return i > r.ring_off[ring_of[i]] ? i - 1 : r.ring_off[ring_of[i] + 1] - 1; };
  auto X = [&](i64 i) { return r.xy[2 * i]; };
  auto Y = [&](i64 i) { return r.xy[2 * i + 1]; };
  auto same = [&](i64 a, i64 b) { return X(a) == X(b) && Y(a) == Y(b); };
  auto orient = [&](i64 a, i64 b, i64 c) {
    return mk::orient(X(a), Y(a), X(b), Y(b), X(c), Y(c));
  };
  // directions v -> a in angle order
  auto angle_less = [&](i64 v, i64 a, i64 b) {
    auto up = [&](i64 w) {
      return Y(w) > Y(v) || (Y(w) == Y(v) && X(w) > X(v));
    };
    bool ua = up(a), ub = up(b);
    if (ua != ub) return ua;
    return orient(v, a, b) > 0;
  };
  // is direction v -> q strictly inside the counter-clockwise arc from v -> a to v -> b?
  auto in_arc = [&](i64 v, i64 a, i64 b, i64 q) {
    if (angle_less(v, a, b)) return angle_less(v, a, q) && angle_less(v, q, b);
    return angle_less(v, a, q) || angle_less(v, q, b);
  };
  // rings i and j cross at their common vertex when j's two edges are separated by i's
  auto cross_at = [&](i64 i, i64 j) {
    bool in1 = in_arc(i, prv(i), nxt(i), prv(j)), in2 = in_arc(i, prv(i), nxt(i), nxt(j));
    return in1 != in2;
  };
  std::vector<double> x0(n), x1(n), y0(n), y1(n);
  for (i64 i = 0; i < n; ++i) {
    i64 j = nxt(i);
    x0[i] = std::min(X(i), X(j));
    x1[i] = std::max(X(i), X(j));
    y0[i] = std::min(Y(i), Y(j));
    y1[i] = std::max(Y(i), Y(j));
  }
  bool ok = true;
  // the check of one candidate pair; false (and ok = false) at the first violation
  auto check = [&](i64 e, i64 f) -> bool {
    if (!ok) return false;
    const i64 a = e, b = nxt(e), c = f, d = nxt(f);
    const bool one_ring = ring_of[e] == ring_of[f];
    int o1 = orient(a, b, c), o2 = orient(a, b, d);
    if (o1 * o2 > 0) return true;
    int o3 = orient(c, d, a), o4 = orient(c, d, b);
    if (o3 * o4 > 0) return true;
    if (o1 == 0 && o2 == 0) {
      // collinear: they may only share an end point, as consecutive edges of one ring
      // or edges of two rings
      auto key = [&](i64 i) { return X(a) != X(b) ? X(i) : Y(i); };
      double lo1 = std::min(key(a), key(b)), hi1 = std::max(key(a), key(b));
      double lo2 = std::min(key(c), key(d)), hi2 = std::max(key(c), key(d));
      if (hi1 < lo2 || hi2 < lo1) return true;
      if (hi1 == lo2 || hi2 == lo1) {
        bool consecutive = one_ring && (b == c || d == a);
        if (consecutive || !one_ring) return true;
      }
      ok = false;
      return false;
    }
    if (o1 && o2 && o3 && o4) {  // a proper crossing
      ok = false;
      return false;
    }
    // one common point
    if (one_ring && (b == c || d == a)) return true;  // consecutive edges at their vertex
    if (one_ring) {
      ok = false;  // a ring touching itself
      return false;
    }
    // two rings touch: a common vertex, or a vertex of one inside an edge of the other
    i64 v = -1, w = -1;  // a vertex of each at the point, if any
    for (i64 p : {a, b})
      for (i64 q : {c, d})
        if (same(p, q)) v = p, w = q;
    if (v >= 0) {
      if (cross_at(v, w)) ok = false;
      return ok;
    }
    // a vertex u of one ring inside edge (s, t) of the other: its neighbours must not lie
    // strictly on both sides of that edge
    i64 u, s0, t0;
    if (o1 == 0) u = c, s0 = a, t0 = b;
    else if (o2 == 0) u = d, s0 = a, t0 = b;
    else if (o3 == 0) u = a, s0 = c, t0 = d;
    else u = b, s0 = c, t0 = d;
    if (orient(s0, t0, prv(u)) * orient(s0, t0, nxt(u)) < 0) ok = false;
    return ok;
  };
  // Candidate pairs: a uniform grid over the exact segments (tolerance 0: they are plain
  // doubles) from 512 edges on -- a box sweep keeps a whole column of a grid-like result
  // active -- and the sweep below that or when the grid declines (its memory budget).
  bool done = false;
  if (n >= 512) {
    std::vector<double> ax(n), ay(n), bx(n), by(n), tol(n, 0.0);
    std::vector<int> grp(n, -1);
    for (i64 i = 0; i < n; ++i) {
      const i64 j = nxt(i);
      ax[i] = X(i);
      ay[i] = Y(i);
      bx[i] = X(j);
      by[i] = Y(j);
    }
    GridScratch scratch;
    done = segment_pairs(n, ax.data(), ay.data(), bx.data(), by.data(), tol.data(), x0.data(),
                         x1.data(), y0.data(), y1.data(), grp.data(), scratch, check);
  }
  if (!done)
    box_pairs(n, x0.data(), x1.data(), y0.data(), y1.data(), [&](i64 e, i64 f) { check(e, f); });
  return ok;
}

// The remedy when rounding alone broke validity (exact features closer than an ulp):
// the rounded rings, now plain doubles, are overlaid again (union of their winding
// numbers: exteriors +1 inside, holes -1), which nodes the new crossings exactly and
// rounds them in turn; repeated until valid (Halperin and Packer's iterated snap
// rounding plays this role on an integer grid). The result is the exact regularized set
// of the rounded polygon: every vertex within an ulp or two of the exact result.
inline void rerun_rounded(Rings& r);

// ------------------------------------------------------------------------------------
// the cascaded union

// Union (layer 0, w >= 1) of parts given as edge lists: groups of up to `leaf` parts are
// overlaid together, then the results pairwise up a balanced tree, so that edges inside
// the union disappear early and the crossings of heavily overlapping parts are never all
// computed at once (GEOS's cascaded union, exact).
class Cascade {
 public:
  explicit Cascade(Geo& g, i64 leaf = 4) : g_(g), o_(g), leaf_(leaf < 1 ? 1 : leaf) {}
  i64 n_crossings = 0, n_runs = 0;
  i64 max_crossings = NO_LIMIT;  // over all runs; then RESOURCE

  void unite(const std::vector<std::vector<EdgeIn>>& parts, Rings& out) {
    out.clear();
    if (parts.empty()) return;
    o_.max_crossings = max_crossings - n_crossings;
    std::vector<EdgeIn> in;
    if ((i64)parts.size() <= leaf_) {
      for (auto& p : parts) in.insert(in.end(), p.begin(), p.end());
    } else {
      std::size_t mid = split_point(0, parts.size());
      std::vector<BEdge> a, b;
      rec(parts, 0, mid, a);
      rec(parts, mid, parts.size(), b);
      if (o_.exceeded()) {
        out.status = RESOURCE;
        return;
      }
      add_boundary(a, 0, in);
      add_boundary(b, 0, in);
    }
    o_.run(in, UNION, out);
    count();
  }

 private:
  Geo& g_;
  Overlay o_;
  i64 leaf_;

  void count() {
    n_crossings += o_.n_crossings;
    ++n_runs;
    o_.max_crossings = max_crossings - n_crossings;
  }
  std::size_t split_point(std::size_t lo, std::size_t hi) const {
    // leaves of size leaf_: split at a multiple of leaf_ near the middle
    std::size_t n = hi - lo, groups = (n + leaf_ - 1) / leaf_;
    return lo + (groups / 2) * leaf_;
  }
  void rec(const std::vector<std::vector<EdgeIn>>& parts, std::size_t lo, std::size_t hi,
           std::vector<BEdge>& out) {
    if (o_.exceeded()) return;
    std::vector<EdgeIn> in;
    if ((i64)(hi - lo) <= leaf_) {
      for (std::size_t k = lo; k < hi; ++k) in.insert(in.end(), parts[k].begin(), parts[k].end());
    } else {
      std::size_t mid = split_point(lo, hi);
      std::vector<BEdge> a, b;
      rec(parts, lo, mid, a);
      rec(parts, mid, hi, b);
      add_boundary(a, 0, in);
      add_boundary(b, 0, in);
    }
    o_.run(in, UNION, out);
    count();
  }

  static void add_boundary(const std::vector<BEdge>& b, int layer, std::vector<EdgeIn>& in) {
    for (const BEdge& e : b) in.push_back(EdgeIn{e.line, e.from, e.to, 1, layer});
  }
};

inline void finish_rounded_impl(Rings& r, int depth);

// ------------------------------------------------------------------------------------
// helpers to feed an overlay

// Adds a closed ring of points (ids first .. first + n - 1) as edges.
inline void add_ring(Geo& g, i64 first, i64 n, int w, int layer, std::vector<EdgeIn>& out) {
  if (n < 2) return;
  i64 v0 = (i64)g.verts.size();
  for (i64 i = 0; i < n; ++i) g.vert_point(first + i);
  for (i64 i = 0; i < n; ++i) {
    i64 a = first + i, b = first + (i + 1) % n;
    if (p_eq(g.pts[a], g.pts[b])) continue;
    i64 l = g.line(a, b);
    out.push_back(EdgeIn{l, v0 + i, v0 + (i + 1) % n, w, layer});
  }
}

inline void rerun_rounded(Rings& r) {
  Geo g;
  std::vector<EdgeIn> in;
  for (std::size_t k = 0; k + 1 < r.ring_off.size(); ++k) {
    i64 first = (i64)g.pts.size(), m = r.ring_off[k + 1] - r.ring_off[k];
    for (i64 i = r.ring_off[k]; i < r.ring_off[k + 1]; ++i)
      g.point(dd(r.xy[2 * i]), dd(r.xy[2 * i + 1]));
    add_ring(g, first, m, 1, 0, in);
  }
  Overlay o(g);
  Rings out;
  o.run_raw(in, UNION, out);
  r = std::move(out);
}

// Cleans the rounded rings and checks them; re-nodes them (a few times at most) when
// rounding made them invalid.
inline void finish_rounded_impl(Rings& r, int depth) {
  clean_rounded(r);
  if (r.exact_vertices || valid_rounded(r)) return;
  if (depth >= 4) {
    r.status = INTERNAL;
    return;
  }
  rerun_rounded(r);
  if (r.status == OK) finish_rounded_impl(r, depth + 1);
}

inline void Overlay::finish_rounded(Rings& out) { finish_rounded_impl(out, 0); }

}  // namespace ov
}  // namespace mk
