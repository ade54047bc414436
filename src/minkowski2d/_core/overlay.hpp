// overlay.hpp -- the exact overlay: node a set of directed, weighted segments, give every
// face its winding numbers, keep the faces a rule selects, and return the regularized
// result as rings with holes whose vertices are the correctly rounded exact vertices.
//
// Input: points whose coordinates are exact sums of two doubles (DD; a plain double has
// lo = 0, the vertex a + b of a convex piece sum is TwoSum(a, b)), and segments between
// them, each with an integer weight and a layer (0 or 1). A closed counter-clockwise ring
// of weight-1 segments has winding number 1 inside; the winding numbers of a face are the
// sums over the rings of each layer. The rule maps (w0, w1) to inside/outside: the union
// of layer 0 is w0 >= 1, a difference w0 >= 1 && w1 <= 0.
//
// Steps (n segments, k intersecting pairs, m vertices of the arrangement):
//  1. points deduplicated (exact DD comparisons), zero-length segments dropped;
//  2. candidate pairs: boxes swept along x (boxes.hpp); each pair classified by four
//     orientation signs (degree 2): disjoint, touching (an endpoint on the other
//     segment), collinear overlap, or a proper crossing (a new rational point);
//  3. every segment's split points sorted by their parameter t = N / D along it (degree
//     4 for two crossings), equal ones united (union-find): identical points found by
//     different pairs become one vertex, with no global hashing of rational points;
//  4. the pieces between consecutive split points are the arrangement's edges; edges
//     joining the same two vertices (collinear overlaps) are merged, their weights added;
//  5. one plane sweep over the edges (which no longer cross) gives each edge the winding
//     numbers below and above it: below the lowest edge starting at a vertex is what lies
//     above the edge just under that vertex. Vertices are ordered by (x, y), exactly
//     (degree 5 for two crossings); the sweep status by the side of a vertex against a
//     supporting line (degree 4);
//  6. edges whose sides the rule classifies differently form the boundary, directed with
//     the inside on the left; rings are traced (at a vertex with several, the next edge
//     is the first clockwise from the way back, so rings are split at pinch points),
//     collinear vertices dropped (parallel supporting segments: degree 2), each ring's
//     orientation read at its lowest vertex (degree 2), and each hole given its exterior
//     by a second sweep over the boundary edges alone (the nearest boundary edge below a
//     hole's first vertex belongs to its exterior or to a sibling hole);
//  7. vertices rounded to the nearest double (ties to even), certified by an extended-
//     precision filter or by exact comparisons with the neighbouring midpoints.
// Every decision is the sign of a polynomial in the input coordinates, evaluated in FE
// (filtered double) and, only when that cannot tell, in Dy (exact) -- exactnum.hpp.
// Time O((n + k) log n) apart from candidate pairs whose boxes overlap without meeting.
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
inline FE fe(double a) { return {a, 0.0}; }
inline Dy dy(DD a) { return a.lo == 0 ? Dy(a.hi) : Dy(a.hi) + Dy(a.lo); }

struct P {
  DD x, y;
};
inline bool p_eq(const P& a, const P& b) { return dd_eq(a.x, b.x) && dd_eq(a.y, b.y); }
inline bool p_less(const P& a, const P& b) {
  int c = dd_cmp(a.x, b.x);
  return c < 0 || (c == 0 && dd_less(a.y, b.y));
}

template <class T>
inline T cross(const T& ax, const T& ay, const T& bx, const T& by) {
  return ax * by - ay * bx;
}

// sign of (q - p) x (r - p) for input points
inline int orient(const P& p, const P& q, const P& r) {
  if (p.x.lo == 0 && p.y.lo == 0 && q.x.lo == 0 && q.y.lo == 0 && r.x.lo == 0 && r.y.lo == 0)
    return cross_sign(p.x.hi, p.y.hi, q.x.hi, q.y.hi, p.x.hi, p.y.hi, r.x.hi, r.y.hi);
  FE f = cross(fe(q.x) - fe(p.x), fe(q.y) - fe(p.y), fe(r.x) - fe(p.x), fe(r.y) - fe(p.y));
  int s = fe_sign(f);
  if (s != UNSURE) return s;
  Dy px = dy(p.x), py = dy(p.y);
  return cross(dy(q.x) - px, dy(q.y) - py, dy(r.x) - px, dy(r.y) - py).sign();
}

// sign of (q1 - p1) x (q2 - p2): the turn from one direction to another
inline int dir_cross(const P& p1, const P& q1, const P& p2, const P& q2) {
  if (p1.x.lo == 0 && p1.y.lo == 0 && q1.x.lo == 0 && q1.y.lo == 0 && p2.x.lo == 0 &&
      p2.y.lo == 0 && q2.x.lo == 0 && q2.y.lo == 0)
    return cross_sign(p1.x.hi, p1.y.hi, q1.x.hi, q1.y.hi, p2.x.hi, p2.y.hi, q2.x.hi, q2.y.hi);
  FE f = cross(fe(q1.x) - fe(p1.x), fe(q1.y) - fe(p1.y), fe(q2.x) - fe(p2.x),
               fe(q2.y) - fe(p2.y));
  int s = fe_sign(f);
  if (s != UNSURE) return s;
  return cross(dy(q1.x) - dy(p1.x), dy(q1.y) - dy(p1.y), dy(q2.x) - dy(p2.x),
               dy(q2.y) - dy(p2.y))
      .sign();
}

// ------------------------------------------------------------------------------------
// the overlay

enum RuleKind : int {
  UNION = 0,       // w0 >= 1
  DIFFERENCE = 1,  // w0 >= 1 and w1 <= 0
  INTERSECTION = 2,  // w0 >= 1 and w1 >= 1
};

inline bool rule_inside(int rule, int w0, int w1) {
  switch (rule) {
    case DIFFERENCE:
      return w0 >= 1 && w1 <= 0;
    case INTERSECTION:
      return w0 >= 1 && w1 >= 1;
    default:
      return w0 >= 1;
  }
}

struct Seg {
  i64 a, b;   // point ids
  int w;      // weight
  int layer;  // 0 or 1
};

class Overlay {
 public:
  // ---- input
  std::vector<P> pts;
  std::vector<Seg> segs;

  i64 add_point(DD x, DD y) {
    pts.push_back(P{x, y});
    return (i64)pts.size() - 1;
  }
  void add_seg(i64 a, i64 b, int w = 1, int layer = 0) {
    if (a != b) segs.push_back(Seg{a, b, w, layer});
  }
  // a closed ring through points first..first+n-1 (already added)
  void add_ring(i64 first, i64 n, int w = 1, int layer = 0) {
    for (i64 i = 0; i < n; ++i) add_seg(first + i, first + (i + 1) % n, w, layer);
  }

  // ---- output: rings of rounded vertices, grouped into polygons (exterior first)
  std::vector<double> out_xy;
  std::vector<i64> ring_off{0}, poly_off{0};

  // Runs the overlay; returns OK, or OVERFLOW when a rounded vertex is not finite.
  int run(int rule) {
    rule_ = rule;
    dedupe();
    find_intersections();
    split_and_unite();
    make_vertices();
    make_edges();
    sweep_windings();
    trace_boundary();
    return assemble();
  }

  // counters (for tests and limits)
  i64 n_pairs = 0, n_crossings = 0, n_vertices = 0, n_edges = 0;

 private:
  int rule_ = UNION;

  // ---- step 1: unique points
  void dedupe() {
    const i64 n = (i64)pts.size();
    std::vector<i64> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](i64 i, i64 j) { return p_less(pts[i], pts[j]); });
    std::vector<i64> canon(n);
    std::vector<P> up;
    up.reserve(n);
    for (i64 t = 0; t < n; ++t) {
      i64 i = order[t];
      if (t == 0 || !p_eq(pts[i], up.back())) up.push_back(pts[i]);
      canon[i] = (i64)up.size() - 1;
    }
    pts.swap(up);
    std::vector<Seg> s2;
    s2.reserve(segs.size());
    for (const Seg& s : segs) {
      i64 a = canon[s.a], b = canon[s.b];
      if (a != b && s.w != 0) s2.push_back(Seg{a, b, s.w, s.layer});
    }
    segs.swap(s2);
  }

  // ---- step 2: intersections
  struct Split {
    i64 seg;   // the segment split
    i64 node;  // point id (< pts.size()) or pts.size() + crossing id
    FE num, den;  // parameter t = num / den along the segment, den > 0 (approximate)
  };
  struct Cross {
    i64 s, t;
  };
  std::vector<Split> splits;
  std::vector<Cross> crosses;

  // exact t of point id v on segment s (v lies on s): along x unless s is vertical
  template <class T>
  void t_point(i64 s, i64 v, T& num, T& den, T (*conv)(DD)) const {
    const P &a = pts[segs[s].a], &b = pts[segs[s].b], &p = pts[v];
    bool use_x = !dd_eq(a.x, b.x);
    DD pa = use_x ? a.x : a.y, pb = use_x ? b.x : b.y, pp = use_x ? p.x : p.y;
    num = conv(pp) - conv(pa);
    den = conv(pb) - conv(pa);
    if (dd_less(pb, pa)) {
      num = -num;
      den = -den;
    }
  }
  // t of the crossing of s with u along s: N / D, D > 0 (sign fixed by the exact D)
  template <class T>
  void t_cross(i64 s, i64 u, T& num, T& den, T (*conv)(DD), int dsign) const {
    const P &a = pts[segs[s].a], &b = pts[segs[s].b];
    const P &c = pts[segs[u].a], &d = pts[segs[u].b];
    T dx = conv(d.x) - conv(c.x), dy_ = conv(d.y) - conv(c.y);
    num = cross(conv(c.x) - conv(a.x), conv(c.y) - conv(a.y), dx, dy_);
    den = cross(conv(b.x) - conv(a.x), conv(b.y) - conv(a.y), dx, dy_);
    if (dsign < 0) {
      num = -num;
      den = -den;
    }
  }
  static FE cfe(DD a) { return fe(a); }
  static Dy cdy(DD a) { return dy(a); }

  // +1 when p lies strictly between a and b on their common line (p collinear)
  bool strictly_inside(i64 a, i64 b, i64 p) const {
    const P &A = pts[a], &B = pts[b], &Q = pts[p];
    bool use_x = !dd_eq(A.x, B.x);
    DD pa = use_x ? A.x : A.y, pb = use_x ? B.x : B.y, pq = use_x ? Q.x : Q.y;
    if (dd_less(pb, pa)) std::swap(pa, pb);
    return dd_less(pa, pq) && dd_less(pq, pb);
  }

  void add_point_split(i64 s, i64 v) {
    Split sp;
    sp.seg = s;
    sp.node = v;
    t_point<FE>(s, v, sp.num, sp.den, &cfe);
    splits.push_back(sp);
  }

  void find_intersections() {
    const i64 n = (i64)segs.size();
    std::vector<double> x0(n), x1(n), y0(n), y1(n);
    auto lo_of = [](DD v) { return v.lo == 0 ? v.hi : std::nextafter(v.hi, -INFINITY); };
    auto hi_of = [](DD v) { return v.lo == 0 ? v.hi : std::nextafter(v.hi, INFINITY); };
    for (i64 i = 0; i < n; ++i) {
      const P &a = pts[segs[i].a], &b = pts[segs[i].b];
      x0[i] = std::min(lo_of(a.x), lo_of(b.x));
      x1[i] = std::max(hi_of(a.x), hi_of(b.x));
      y0[i] = std::min(lo_of(a.y), lo_of(b.y));
      y1[i] = std::max(hi_of(a.y), hi_of(b.y));
    }
    box_pairs(n, x0.data(), x1.data(), y0.data(), y1.data(),
              [&](i64 i, i64 j) { classify(i, j); });
  }

  void classify(i64 i, i64 j) {
    ++n_pairs;
    const Seg &s = segs[i], &t = segs[j];
    const i64 p = s.a, q = s.b, r = t.a, u = t.b;
    const P &P_ = pts[p], &Q = pts[q], &R = pts[r], &U = pts[u];
    int oa = (r == p || r == q) ? 0 : orient(P_, Q, R);
    int ob = (u == p || u == q) ? 0 : orient(P_, Q, U);
    if (oa * ob > 0) return;
    if (oa == 0 && ob == 0) {
      // collinear: each endpoint strictly inside the other segment splits it
      if (r != p && r != q && strictly_inside(p, q, r)) add_point_split(i, r);
      if (u != p && u != q && strictly_inside(p, q, u)) add_point_split(i, u);
      if (p != r && p != u && strictly_inside(r, u, p)) add_point_split(j, p);
      if (q != r && q != u && strictly_inside(r, u, q)) add_point_split(j, q);
      return;
    }
    int oc = (p == r || p == u) ? 0 : orient(R, U, P_);
    int od = (q == r || q == u) ? 0 : orient(R, U, Q);
    if (oc * od > 0) return;
    // one common point
    if (oa == 0 || ob == 0 || oc == 0 || od == 0) {
      if (oa == 0 && r != p && r != q) add_point_split(i, r);
      if (ob == 0 && u != p && u != q) add_point_split(i, u);
      if (oc == 0 && p != r && p != u) add_point_split(j, p);
      if (od == 0 && q != r && q != u) add_point_split(j, q);
      return;
    }
    // a proper crossing
    ++n_crossings;
    i64 c = (i64)crosses.size();
    crosses.push_back(Cross{i, j});
    i64 node = (i64)pts.size() + c;
    // the sign of D = (b - a) x (d - c): oa and ob have opposite signs; D > 0 iff the
    // second segment goes from the right of the first to its left, i.e. ob > 0
    int d1 = ob > 0 ? 1 : -1;
    Split sp;
    sp.seg = i;
    sp.node = node;
    t_cross<FE>(i, j, sp.num, sp.den, &cfe, d1);
    splits.push_back(sp);
    // along t: D' = (d - c) x (b - a) = -D
    sp.seg = j;
    t_cross<FE>(j, i, sp.num, sp.den, &cfe, -d1);
    splits.push_back(sp);
  }

  // ---- step 3: sort the splits of each segment, unite equal points
  std::vector<i64> uf;
  i64 find(i64 a) {
    while (uf[a] != a) {
      uf[a] = uf[uf[a]];
      a = uf[a];
    }
    return a;
  }
  void unite(i64 a, i64 b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    // keep the smaller id as root: point ids (exact coordinates) win over crossings
    if (a < b)
      uf[b] = a;
    else
      uf[a] = b;
  }

  // exact (num, den) of a split
  void split_exact(const Split& sp, Dy& num, Dy& den) const {
    const i64 np = (i64)pts.size();
    if (sp.node < np) {
      t_point<Dy>(sp.seg, sp.node, num, den, &cdy);
    } else {
      const Cross& c = crosses[sp.node - np];
      i64 other = c.s == sp.seg ? c.t : c.s;
      // D's sign along this segment is the sign of the approximate den's origin: recompute
      t_cross<Dy>(sp.seg, other, num, den, &cdy, 1);
      if (den.sign() < 0) {
        num = -num;
        den = -den;
      }
    }
  }

  // sign(t1 - t2) for two splits of the same segment
  int cmp_t(const Split& a, const Split& b) const {
    if (a.node == b.node) return 0;
    FE f = a.num * b.den - b.num * a.den;
    int s = fe_sign(f);
    if (s != UNSURE) return s;
    Dy an, ad, bn, bd;
    split_exact(a, an, ad);
    split_exact(b, bn, bd);
    return (an * bd - bn * ad).sign();
  }

  void split_and_unite() {
    const i64 np = (i64)pts.size();
    uf.resize(np + crosses.size());
    std::iota(uf.begin(), uf.end(), 0);
    std::sort(splits.begin(), splits.end(), [&](const Split& a, const Split& b) {
      if (a.seg != b.seg) return a.seg < b.seg;
      return cmp_t(a, b) < 0;
    });
    for (std::size_t k = 1; k < splits.size(); ++k) {
      const Split &a = splits[k - 1], &b = splits[k];
      if (a.seg == b.seg && cmp_t(a, b) == 0) unite(a.node, b.node);
    }
  }

  // ---- step 4: vertices
  struct Vtx {
    i64 node;  // representative: a point id, or pts.size() + crossing id
    FE x, y;   // approximation
  };
  std::vector<Vtx> vtx;
  std::vector<i64> vid;   // node -> vertex id (-1 unused)
  std::vector<i64> rank;  // vertex -> position in (x, y) order

  // exact homogeneous coordinates of a vertex: (X / W, Y / W), W > 0
  void vtx_exact(i64 v, Dy& X, Dy& Y, Dy& W) const {
    const i64 np = (i64)pts.size();
    i64 node = vtx[v].node;
    if (node < np) {
      X = dy(pts[node].x);
      Y = dy(pts[node].y);
      W = Dy(1.0);
      return;
    }
    const Cross& c = crosses[node - np];
    const P &a = pts[segs[c.s].a], &b = pts[segs[c.s].b];
    Dy N, D;
    t_cross<Dy>(c.s, c.t, N, D, &cdy, 1);
    if (D.sign() < 0) {
      N = -N;
      D = -D;
    }
    Dy ax = dy(a.x), ay = dy(a.y);
    X = ax * D + (dy(b.x) - ax) * N;
    Y = ay * D + (dy(b.y) - ay) * N;
    W = D;
  }

  void make_vertices() {
    const i64 np = (i64)pts.size(), nn = np + (i64)crosses.size();
    vid.assign(nn, -1);
    // every node in use: segment endpoints and crossings
    auto touch = [&](i64 node) {
      i64 r = find(node);
      if (vid[r] < 0) {
        vid[r] = (i64)vtx.size();
        vtx.push_back(Vtx{r, FE{0, 0}, FE{0, 0}});
      }
    };
    for (const Seg& s : segs) {
      touch(s.a);
      touch(s.b);
    }
    for (i64 c = 0; c < (i64)crosses.size(); ++c) touch(np + c);
    for (i64 node = 0; node < nn; ++node) vid[node] = vid[find(node)];
    for (Vtx& v : vtx) {
      if (v.node < np) {
        v.x = fe(pts[v.node].x);
        v.y = fe(pts[v.node].y);
      } else {
        const Cross& c = crosses[v.node - np];
        const P &a = pts[segs[c.s].a], &b = pts[segs[c.s].b];
        FE N, D;
        t_cross<FE>(c.s, c.t, N, D, &cfe, 1);
        FE t = fe_div(N, D);
        v.x = fe(a.x) + (fe(b.x) - fe(a.x)) * t;
        v.y = fe(a.y) + (fe(b.y) - fe(a.y)) * t;
      }
    }
    n_vertices = (i64)vtx.size();
    // sweep order: by x, then y
    std::vector<i64> order(vtx.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](i64 a, i64 b) { return vcmp(a, b) < 0; });
    rank.resize(vtx.size());
    for (std::size_t t = 0; t < order.size(); ++t) rank[order[t]] = (i64)t;
  }

  // sign of (a - b) in the (x, y) order of vertices
  int vcmp(i64 a, i64 b) const {
    if (a == b) return 0;
    const i64 np = (i64)pts.size();
    i64 na = vtx[a].node, nb = vtx[b].node;
    if (na < np && nb < np) {
      int c = dd_cmp(pts[na].x, pts[nb].x);
      return c ? c : dd_cmp(pts[na].y, pts[nb].y);
    }
    int s = fe_sign(vtx[a].x - vtx[b].x);
    if (s == UNSURE || s == 0) {
      Dy Xa, Ya, Wa, Xb, Yb, Wb;
      vtx_exact(a, Xa, Ya, Wa);
      vtx_exact(b, Xb, Yb, Wb);
      s = (Xa * Wb - Xb * Wa).sign();
      if (s) return s;
      return (Ya * Wb - Yb * Wa).sign();
    }
    return s;
  }

  // ---- step 5: edges
  struct Edge {
    i64 l, r;         // vertices, rank[l] < rank[r]
    i64 seg;          // a supporting segment
    bool seg_lr;      // the segment runs from l's side to r's side
    int c0, c1;       // change of w0, w1 crossing the edge upwards
    int b0 = 0, b1 = 0;  // winding numbers below
  };
  std::vector<Edge> edges;

  void make_edges() {
    // per segment, its vertices in order: a, splits..., b
    std::vector<Edge> raw;
    raw.reserve(segs.size() + splits.size());
    std::size_t k = 0;
    for (i64 s = 0; s < (i64)segs.size(); ++s) {
      i64 prev = vid[segs[s].a];
      auto emit = [&](i64 nxt) {
        if (nxt == prev) return;
        Edge e;
        bool fwd = rank[prev] < rank[nxt];
        e.l = fwd ? prev : nxt;
        e.r = fwd ? nxt : prev;
        e.seg = s;
        e.seg_lr = fwd;
        int c = fwd ? segs[s].w : -segs[s].w;
        e.c0 = segs[s].layer == 0 ? c : 0;
        e.c1 = segs[s].layer == 1 ? c : 0;
        raw.push_back(e);
        prev = nxt;
      };
      while (k < splits.size() && splits[k].seg == s) {
        emit(vid[splits[k].node]);
        ++k;
      }
      emit(vid[segs[s].b]);
    }
    std::sort(raw.begin(), raw.end(), [](const Edge& a, const Edge& b) {
      return a.l != b.l ? a.l < b.l : a.r < b.r;
    });
    edges.clear();
    for (std::size_t i = 0; i < raw.size();) {
      std::size_t j = i;
      Edge e = raw[i];
      e.c0 = 0;
      e.c1 = 0;
      for (; j < raw.size() && raw[j].l == raw[i].l && raw[j].r == raw[i].r; ++j) {
        e.c0 += raw[j].c0;
        e.c1 += raw[j].c1;
      }
      if (e.c0 != 0 || e.c1 != 0) edges.push_back(e);
      i = j;
    }
    n_edges = (i64)edges.size();
  }

  // the supporting line of edge e, oriented from l's side to r's side
  void line_of(const Edge& e, const P*& a, const P*& b) const {
    const Seg& s = segs[e.seg];
    a = &pts[e.seg_lr ? s.a : s.b];
    b = &pts[e.seg_lr ? s.b : s.a];
  }

  // side of vertex v against the line of edge e: +1 above (left), -1 below
  int side(const Edge& e, i64 v) const {
    const P *a, *b;
    line_of(e, a, b);
    const i64 np = (i64)pts.size();
    i64 node = vtx[v].node;
    if (node < np) return orient(*a, *b, pts[node]);
    const Vtx& V = vtx[v];
    FE ax = fe(a->x), ay = fe(a->y);
    FE f = cross(fe(b->x) - ax, fe(b->y) - ay, V.x - ax, V.y - ay);
    int s = fe_sign(f);
    if (s != UNSURE) return s;
    Dy X, Y, W;
    vtx_exact(v, X, Y, W);
    Dy Ax = dy(a->x), Ay = dy(a->y);
    return cross(dy(b->x) - Ax, dy(b->y) - Ay, X - Ax * W, Y - Ay * W).sign();
  }

  // edges from one vertex: e1 below e2 when the turn from e1's direction to e2's is left
  bool slope_below(const Edge& e1, const Edge& e2) const {
    const P *a1, *b1, *a2, *b2;
    line_of(e1, a1, b1);
    line_of(e2, a2, b2);
    return dir_cross(*a1, *b1, *a2, *b2) > 0;
  }

  struct StatusLess {
    const Overlay* o;
    bool operator()(i64 i, i64 j) const {
      if (i == j) return false;
      const Edge &e1 = o->edges[i], &e2 = o->edges[j];
      if (e1.l == e2.l) return o->slope_below(e1, e2);
      if (o->rank[e1.l] > o->rank[e2.l]) {
        int s = o->side(e2, e1.l);
        if (s == 0) return o->slope_below(e1, e2);
        return s < 0;
      }
      int s = o->side(e1, e2.l);
      if (s == 0) return o->slope_below(e1, e2);
      return s > 0;
    }
  };

  // Sweeps the edges in `ids` (a subset of edges); calls at_vertex(v, new_edges sorted
  // bottom to top, predecessor edge of the lowest or -1) after inserting a vertex's edges.
  template <class F>
  void sweep(const std::vector<i64>& ids, F&& at_vertex) {
    const i64 nv = (i64)vtx.size();
    std::vector<i64> by_rank(nv);
    for (i64 v = 0; v < nv; ++v) by_rank[rank[v]] = v;
    // CSR: edges by left vertex, by right vertex
    std::vector<i64> lo_l(nv + 1, 0), lo_r(nv + 1, 0);
    for (i64 e : ids) {
      ++lo_l[edges[e].l + 1];
      ++lo_r[edges[e].r + 1];
    }
    for (i64 v = 0; v < nv; ++v) {
      lo_l[v + 1] += lo_l[v];
      lo_r[v + 1] += lo_r[v];
    }
    std::vector<i64> at_l(ids.size()), at_r(ids.size());
    {
      std::vector<i64> fl(lo_l.begin(), lo_l.end() - 1), fr(lo_r.begin(), lo_r.end() - 1);
      for (i64 e : ids) {
        at_l[fl[edges[e].l]++] = e;
        at_r[fr[edges[e].r]++] = e;
      }
    }
    using Status = std::set<i64, StatusLess>;
    Status status(StatusLess{this});
    std::vector<typename Status::iterator> where(edges.size());
    std::vector<i64> fresh;
    for (i64 t = 0; t < nv; ++t) {
      i64 v = by_rank[t];
      for (i64 k = lo_r[v]; k < lo_r[v + 1]; ++k) status.erase(where[at_r[k]]);
      if (lo_l[v] == lo_l[v + 1]) continue;
      fresh.assign(at_l.begin() + lo_l[v], at_l.begin() + lo_l[v + 1]);
      std::sort(fresh.begin(), fresh.end(),
                [&](i64 a, i64 b) { return slope_below(edges[a], edges[b]); });
      for (i64 e : fresh) where[e] = status.insert(e).first;
      auto it = where[fresh[0]];
      i64 pred = it == status.begin() ? -1 : *std::prev(it);
      at_vertex(v, fresh, pred);
    }
  }

  void sweep_windings() {
    std::vector<i64> all(edges.size());
    std::iota(all.begin(), all.end(), 0);
    sweep(all, [&](i64, const std::vector<i64>& fresh, i64 pred) {
      int w0 = pred < 0 ? 0 : edges[pred].b0 + edges[pred].c0;
      int w1 = pred < 0 ? 0 : edges[pred].b1 + edges[pred].c1;
      for (i64 e : fresh) {
        edges[e].b0 = w0;
        edges[e].b1 = w1;
        w0 += edges[e].c0;
        w1 += edges[e].c1;
      }
    });
  }

  // ---- step 6: boundary rings
  struct BEdge {
    i64 edge;  // index into edges
    i64 from, to;
    bool lr;   // directed from l to r
  };
  std::vector<BEdge> bed;
  std::vector<std::vector<i64>> rings;  // vertex ids, inside on the left
  std::vector<std::vector<i64>> ring_edges;  // boundary-edge ids: ring_edges[k][i] runs
                                             // from rings[k][i] to rings[k][i + 1]
  std::vector<int> ring_ccw;

  // direction of boundary edge b (from -> to) as a pair of points on its line
  void bdir(const BEdge& b, const P*& p, const P*& q) const {
    const P *a, *c;
    line_of(edges[b.edge], a, c);
    if (b.lr) {
      p = a;
      q = c;
    } else {
      p = c;
      q = a;
    }
  }
  // angle order of directions (p -> q): half-plane first (upper: y > 0 or y == 0, x > 0)
  static bool upper_dir(const P& p, const P& q) {
    int c = dd_cmp(q.y, p.y);
    return c > 0 || (c == 0 && dd_less(p.x, q.x));
  }
  bool angle_less(const P& p1, const P& q1, const P& p2, const P& q2) const {
    bool u1 = upper_dir(p1, q1), u2 = upper_dir(p2, q2);
    if (u1 != u2) return u1;
    return dir_cross(p1, q1, p2, q2) > 0;
  }

  void trace_boundary() {
    const i64 nv = (i64)vtx.size();
    for (i64 e = 0; e < (i64)edges.size(); ++e) {
      const Edge& E = edges[e];
      bool ib = rule_inside(rule_, E.b0, E.b1);
      bool ia = rule_inside(rule_, E.b0 + E.c0, E.b1 + E.c1);
      if (ib == ia) continue;
      // inside above: run left to right (inside on the left)
      bed.push_back(ia ? BEdge{e, E.l, E.r, true} : BEdge{e, E.r, E.l, false});
    }
    const i64 nb = (i64)bed.size();
    std::vector<i64> lo(nv + 1, 0);
    for (const BEdge& b : bed) ++lo[b.from + 1];
    for (i64 v = 0; v < nv; ++v) lo[v + 1] += lo[v];
    std::vector<i64> out(nb);
    {
      std::vector<i64> f(lo.begin(), lo.end() - 1);
      for (i64 b = 0; b < nb; ++b) out[f[bed[b].from]++] = b;
    }
    // outgoing edges of a vertex with several, in angle order
    for (i64 v = 0; v < nv; ++v) {
      if (lo[v + 1] - lo[v] > 1)
        std::sort(out.begin() + lo[v], out.begin() + lo[v + 1], [&](i64 a, i64 b) {
          const P *p1, *q1, *p2, *q2;
          bdir(bed[a], p1, q1);
          bdir(bed[b], p2, q2);
          return angle_less(*p1, *q1, *p2, *q2);
        });
    }
    // next boundary edge after b: the first outgoing edge clockwise from the way back
    auto next_of = [&](i64 b) -> i64 {
      i64 v = bed[b].to;
      i64 k0 = lo[v], k1 = lo[v + 1];
      if (k1 - k0 == 1) return out[k0];
      const P *p, *q;
      bdir(bed[b], p, q);  // the way back is q -> p
      // outgoing sorted CCW; find the last one strictly before the way back
      i64 best = -1;
      for (i64 k = k0; k < k1; ++k) {
        const P *p2, *q2;
        bdir(bed[out[k]], p2, q2);
        if (angle_less(*p2, *q2, *q, *p)) best = k;
      }
      return best >= 0 ? out[best] : out[k1 - 1];
    };
    std::vector<char> used(nb, 0);
    std::vector<i64> walk_v, walk_e;
    std::vector<i64> pos(nv, -1);
    for (i64 b0 = 0; b0 < nb; ++b0) {
      if (used[b0]) continue;
      // one closed walk; split it at repeated vertices into simple loops
      walk_v.clear();
      walk_e.clear();
      i64 b = b0;
      while (!used[b]) {
        used[b] = 1;
        i64 v = bed[b].from;
        if (pos[v] >= 0) {
          // a loop from pos[v] to here
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
      // the walk closes at b0's origin
      for (i64 v : walk_v) pos[v] = -1;
      if (!walk_v.empty()) add_ring(walk_v, walk_e);
    }
  }

  // a simple loop: drop collinear vertices, record its orientation
  void add_ring(const std::vector<i64>& rv, const std::vector<i64>& re) {
    const i64 n = (i64)rv.size();
    std::vector<i64> kv, ke;
    kv.reserve(n);
    ke.reserve(n);
    // vertex rv[i] sits between edges re[i - 1] (in) and re[i] (out)
    for (i64 i = 0; i < n; ++i) {
      const BEdge &bin = bed[re[(i + n - 1) % n]], &bout = bed[re[i]];
      const P *p1, *q1, *p2, *q2;
      bdir(bin, p1, q1);
      bdir(bout, p2, q2);
      if (dir_cross(*p1, *q1, *p2, *q2) == 0) continue;  // straight on
      kv.push_back(rv[i]);
      ke.push_back(re[i]);
    }
    if (kv.size() < 3) return;  // cannot happen for a boundary with area
    // orientation at the lowest vertex (in sweep order), a strict turn there
    i64 m = (i64)kv.size(), lowest = 0;
    for (i64 i = 1; i < m; ++i)
      if (rank[kv[i]] < rank[kv[lowest]]) lowest = i;
    // in-edge of kv[lowest] is the out-edge of the previous kept vertex's run: take the
    // boundary edge arriving at kv[lowest] in the original loop
    i64 orig = 0;
    for (i64 i = 0; i < n; ++i)
      if (rv[i] == kv[lowest]) orig = i;
    const P *p1, *q1, *p2, *q2;
    bdir(bed[re[(orig + n - 1) % n]], p1, q1);
    bdir(bed[re[orig]], p2, q2);
    int turn = dir_cross(*p1, *q1, *p2, *q2);
    rings.push_back(std::move(kv));
    ring_edges.push_back(re);
    ring_ccw.push_back(turn > 0);
  }

  // ---- step 7: holes to exteriors, rounding, output
  std::vector<i64> owner;

  void assign_holes() {
    const i64 nr = (i64)rings.size();
    owner.assign(nr, -1);
    bool any_hole = false;
    for (i64 k = 0; k < nr; ++k) any_hole |= !ring_ccw[k];
    if (!any_hole) return;
    std::vector<i64> ring_of(edges.size(), -1), ids;
    for (i64 k = 0; k < nr; ++k)
      for (i64 b : ring_edges[k]) {
        ring_of[bed[b].edge] = k;
        ids.push_back(bed[b].edge);
      }
    std::vector<char> done(nr, 0);
    sweep(ids, [&](i64, const std::vector<i64>& fresh, i64 pred) {
      i64 below = pred;
      for (i64 e : fresh) {
        i64 k = ring_of[e];
        if (!done[k]) {
          done[k] = 1;
          if (!ring_ccw[k] && below >= 0) {
            i64 rk = ring_of[below];
            owner[k] = ring_ccw[rk] ? rk : owner[rk];
          }
        }
        below = e;
      }
    });
  }

  // nearest double to X / W (W > 0), ties to even
  static double round_exact(const Dy& X, const Dy& W) {
    // a guess within a few ulps from the leading limbs, then exact comparisons of X
    // with W times the midpoints between neighbouring doubles
    if (X.n == 0) return 0.0;
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
      // midpoints (exact dyadics)
      Dy mu = dy_ldexp(Dy(r) + Dy(up), -1), md = dy_ldexp(Dy(r) + Dy(dn), -1);
      int su = (X - W * mu).sign();  // X/W vs upper midpoint
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
    if (r == 0) return true;
    u64 bits;
    std::memcpy(&bits, &r, sizeof bits);
    return (bits & 1) == 0;
  }

  // rounded coordinates of vertex v
  void vertex_xy(i64 v, double& x, double& y) const {
    const i64 np = (i64)pts.size();
    i64 node = vtx[v].node;
    if (node < np) {
      x = pts[node].x.hi;
      y = pts[node].y.hi;
      return;
    }
    // extended-precision approximation with a certified bound
    const Cross& c = crosses[node - np];
    const P &a = pts[segs[c.s].a], &b = pts[segs[c.s].b];
    const P &cc = pts[segs[c.t].a], &d = pts[segs[c.t].b];
    auto L = [](DD v) {
      long double s = (long double)v.hi + (long double)v.lo;
      return FEL{s, v.lo == 0 ? 0.0L : FEconst<long double>::U * std::fabs(s)};
    };
    FEL dx = L(d.x) - L(cc.x), dyv = L(d.y) - L(cc.y);
    FEL N = cross(L(cc.x) - L(a.x), L(cc.y) - L(a.y), dx, dyv);
    FEL D = cross(L(b.x) - L(a.x), L(b.y) - L(a.y), dx, dyv);
    FEL t = fe_div(N, D);
    FEL X = L(a.x) + (L(b.x) - L(a.x)) * t;
    FEL Y = L(a.y) + (L(b.y) - L(a.y)) * t;
    Dy Xe, Ye, We;
    bool have_exact = false;
    x = certified_round(X, have_exact, Xe, Ye, We, v, true);
    y = certified_round(Y, have_exact, Xe, Ye, We, v, false);
  }

  double certified_round(FEL a, bool& have_exact, Dy& X, Dy& Y, Dy& W, i64 v, bool is_x) const {
    double r = (double)a.v;
    if (r - r == 0 && a.e * FEconst<long double>::SAFE < INFINITY) {
      long double up = std::nextafter(r, INFINITY), dn = std::nextafter(r, -INFINITY);
      long double hu = (up - (long double)r) / 2, hd = ((long double)r - dn) / 2;
      long double lo = a.v - a.e * FEconst<long double>::SAFE,
                  hi = a.v + a.e * FEconst<long double>::SAFE;
      if (lo > (long double)r - hd && hi < (long double)r + hu) return r;
    }
    if (!have_exact) {
      vtx_exact(v, X, Y, W);
      have_exact = true;
    }
    return round_exact(is_x ? X : Y, W);
  }

  int assemble() {
    assign_holes();
    const i64 nr = (i64)rings.size();
    std::vector<double> rx, ry;
    // rounded coordinates per vertex, computed once
    std::vector<double> vx(vtx.size()), vy(vtx.size());
    std::vector<char> have(vtx.size(), 0);
    auto xy = [&](i64 v, double& x, double& y) {
      if (!have[v]) {
        vertex_xy(v, vx[v], vy[v]);
        have[v] = 1;
      }
      x = vx[v];
      y = vy[v];
    };
    // children of each exterior
    std::vector<std::vector<i64>> holes(nr);
    std::vector<i64> ext;
    for (i64 k = 0; k < nr; ++k) {
      if (ring_ccw[k])
        ext.push_back(k);
      else if (owner[k] >= 0)
        holes[owner[k]].push_back(k);
    }
    int status = OK;
    // one ring: rounded, started at its smallest (x, y)
    std::vector<std::pair<double, double>> buf;
    auto emit_ring = [&](i64 k) -> std::pair<double, double> {
      buf.clear();
      for (i64 v : rings[k]) {
        double x, y;
        xy(v, x, y);
        if (!(x - x == 0 && y - y == 0)) status = OVERFLOW;
        buf.emplace_back(x, y);
      }
      std::size_t s = 0;
      for (std::size_t i = 1; i < buf.size(); ++i)
        if (buf[i] < buf[s]) s = i;
      for (std::size_t i = 0; i < buf.size(); ++i) {
        auto& p = buf[(s + i) % buf.size()];
        out_xy.push_back(p.first);
        out_xy.push_back(p.second);
      }
      ring_off.push_back((i64)out_xy.size() / 2);
      return buf[s];
    };
    // polygons in the order of their smallest exterior vertex
    std::vector<std::pair<std::pair<double, double>, i64>> keyed;
    for (i64 k : ext) {
      double bx = INFINITY, by = INFINITY;
      for (i64 v : rings[k]) {
        double x, y;
        xy(v, x, y);
        if (x < bx || (x == bx && y < by)) {
          bx = x;
          by = y;
        }
      }
      keyed.push_back({{bx, by}, k});
    }
    std::sort(keyed.begin(), keyed.end());
    for (auto& kk : keyed) {
      i64 k = kk.second;
      emit_ring(k);
      std::vector<std::pair<std::pair<double, double>, i64>> hk;
      for (i64 h : holes[k]) {
        double bx = INFINITY, by = INFINITY;
        for (i64 v : rings[h]) {
          double x, y;
          xy(v, x, y);
          if (x < bx || (x == bx && y < by)) {
            bx = x;
            by = y;
          }
        }
        hk.push_back({{bx, by}, h});
      }
      std::sort(hk.begin(), hk.end());
      for (auto& h : hk) emit_ring(h.second);
      poly_off.push_back((i64)ring_off.size() - 1);
    }
    return status;
  }
};

}  // namespace ov
}  // namespace mk
