// offset.hpp -- offsetting polygons by a disk (grow and shrink) on the exact overlay, with
// a one-sided error that is certified by exact predicates.
//
// The offset curve. Every ring is oriented with the offset side on its right (a grow:
// exteriors counter-clockwise, holes clockwise; a shrink: the reverse). For each vertex V
// (between edge `in` = P -> V and edge `out` = V -> N) the curve has a *chain*: at a
// vertex that is convex on the offset side (and at a spike) the points of a polygon
// around V's arc, in angular order (a *fan*); elsewhere a *detour* F, V, S, where F lies
// on `in`'s moved edge just past V's normal and S on `out`'s just before it. Between the
// chain of V and that of N runs the moved edge of `out`. With the pieces
//     Q_e = (a, S, F, b)        for each edge e = a -> b (S: end of a's chain, F: start
//                               of b's chain),
//     J_V = (V, c_1, ..., c_K)  for each fan,
// the boundaries telescope: curve = ∂P + Σ ∂Q_e + Σ ∂J_V as chains, so the winding number
// of the curve is [x ∈ P] + #pieces containing x whenever every piece is a simple
// counter-clockwise polygon. A grow is then {winding >= 1} = P ∪ pieces: one overlay with
// the rule w >= 1. A shrink builds the pieces inside (reversed rings) and gives the curve
// weight -1: {[x ∈ P] - #pieces >= 1} = P \ pieces.
//
// The certificate. With r the radius, the coverage radius t_cov and the outer bound t_up
// (for a circumscribed construction t_cov = r + mu, t_up = r + eps - mu; inscribed:
// t_cov = r - eps + mu, t_up = r - mu; mu is the margin below), every piece is checked
// with exact predicates (filtered double, then exact dyadic arithmetic):
//  (E) for each edge a -> b: S and F strictly right of the line ab at distance >= t_cov
//      (cross(b - a, p - a) < 0, cross^2 >= t_cov^2 |b - a|^2), S behind a's normal
//      ((S - a).(b - a) <= 0) and F past b's ((F - b).(b - a) >= 0). Then Q_e is convex
//      and counter-clockwise and contains the rectangle of points whose nearest point of
//      the polygon lies inside the edge at distance <= t_cov, and the parts of the end
//      vertices' disks of radius t_cov between their normal and the rays a->S, b->F.
//  (F) for each fan: every point in the open half-plane ahead of V along `in`,
//      consecutive points turning counter-clockwise around V, every chord's line at
//      distance >= t_cov from V. Then J_V is simple and counter-clockwise and covers the
//      disk of radius t_cov around V between the rays to c_1 and c_K: with (E), the
//      sector of V's normal cone. A detour at a convex vertex (a turn too small for a fan
//      in float64) has F at or ahead of S around V, so Q_in and Q_out cover the sector.
//  (U) every chain point within t_up of its vertex (so every piece lies within t_up of
//      the polygon: a piece is in the convex hull of points within t_up of a convex part
//      of the polygon).
// Hence P ⊕ D(t_cov) ⊆ P ∪ pieces ⊆ P ⊕ D(t_up) (for a shrink, the erosions), exactly.
//
// Rounding. The overlay's output vertices are either curve points (doubles, exact) or
// crossings of two curve segments, rounded to the nearest double: each moves by at most
// sqrt(2)/2 ulp of its largest coordinate (when rounding made the rings invalid, the
// overlay re-nodes the rounded rings, at most 4 more times). The problem is scaled by a
// power of two so that every coordinate of the result is below 2 in magnitude: the
// moves are then below m = 2^-50 in all, and the margin mu = m + delta (delta: a bound
// on the error of the input the caller passed, e.g. Fractions rounded to float64) keeps
// the rounded boundary on its side: for a grow, P ⊕ D(r) ⊆ result ⊆ P ⊕ D(r + eps) (outer) and
// P ⊕ D(r - eps) ⊆ result ⊆ P ⊕ D(r) (inner); for a shrink the same with erosions.
// The construction aims mc beyond the certified bounds (mc covers its float64 error,
// about 45 u r + 1.5 u |x| for u = 2^-53; the certificate does not depend on it), so a
// tolerance must exceed least = 2 mu + 4 mc. Certification failing anyway is reported
// (UNCERTIFIED), never returned.
//
// Trims and the simple curve. At a reflex vertex the detour F, V, S is usually replaced
// by one point beyond the crossing of the two moved edges (certified below, Curve::trim).
// One ring whose trimmed curve is simple (checked exactly) is then the boundary itself:
// no overlay, nothing rounded. Otherwise the curves go to one exact overlay (rule
// w >= 1), which nodes them and returns rings with holes.
//
// Notches. Before the curves are built, shallow notches on the offset side (height below
// eps / 4 in all) are filled, and the construction runs on the filled set with a
// tolerance (and, inscribed, a radius) reduced by the height: see fill_notches.
//
// Miter and square joins are polygons by construction (no tolerance): built in float64
// with the same pieces, not certified.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "boxes.hpp"
#include "exact.hpp"
#include "exactnum.hpp"
#include "minkowski.hpp"
#include "offset_curve.hpp"
#include "offset_prune.hpp"
#include "offset_resolve.hpp"
#include "overlay.hpp"

namespace mk {
namespace off {

// ------------------------------------------------------------------------------------
// the rings' edges in a uniform grid (the distance check of a pruned result)

class EdgeGrid {
 public:
  // cells of side at least h (and not more cells than about four per edge); marked
  // (optional, one ring only: one per vertex): only the edges with a marked end
  void build(const std::vector<std::vector<Pt>>& rings, double h,
             const std::vector<char>* marked = nullptr) {
    a_.clear();
    b_.clear();
    for (const auto& v : rings)
      for (std::size_t i = 0; i < v.size(); ++i) {
        const std::size_t j = (i + 1) % v.size();
        if (marked && !(*marked)[i] && !(*marked)[j]) continue;  // one ring
        a_.push_back(v[i]);
        b_.push_back(v[j]);
      }
    const i64 n = (i64)a_.size();
    if (n == 0) {
      X0_ = Y0_ = 0;
      nx_ = ny_ = 1;
      start_.assign(2, 0);
      return;
    }
    X0_ = Y0_ = INFINITY;
    double X1 = -INFINITY, Y1 = -INFINITY;
    for (i64 i = 0; i < n; ++i) {
      X0_ = std::min({X0_, a_[i].x, b_[i].x});
      X1 = std::max({X1, a_[i].x, b_[i].x});
      Y0_ = std::min({Y0_, a_[i].y, b_[i].y});
      Y1 = std::max({Y1, a_[i].y, b_[i].y});
    }
    const double W = X1 - X0_, H = Y1 - Y0_;
    const double cs = std::max(h, std::sqrt(W * H / (4.0 * (double)n)));
    const double fx = W / cs, fy = H / cs;
    nx_ = fx < 1023 ? (i64)fx + 1 : 1024;  // also for NaN
    ny_ = fy < 1023 ? (i64)fy + 1 : 1024;
    ix_ = (double)nx_ / W;
    iy_ = (double)ny_ / H;
    if (!(std::isfinite(ix_) && std::isfinite(iy_) && W > 0 && H > 0)) {
      nx_ = ny_ = 1;  // degenerate extents: one cell
      ix_ = iy_ = 0;
    }
    grid_buckets(n, nx_, ny_, [&](i64 i, i64& xa, i64& xb, i64& ya, i64& yb) {
      xa = cx(std::min(a_[i].x, b_[i].x));
      xb = cx(std::max(a_[i].x, b_[i].x));
      ya = cy(std::min(a_[i].y, b_[i].y));
      yb = cy(std::max(a_[i].y, b_[i].y));
    }, start_, item_);
    stamp_.assign((std::size_t)n, -1);
    query_ = 0;
  }
  // f(c, d) for each edge c -> d registered in a cell that the box meets (once each);
  // false from f stops (returned)
  template <class F>
  bool query(double x0, double x1, double y0, double y1, F&& f) {
    ++query_;
    const i64 X0 = cx(x0), X1 = cx(x1), Y0 = cy(y0), Y1 = cy(y1);
    for (i64 y = Y0; y <= Y1; ++y)
      for (i64 x = X0; x <= X1; ++x)
        for (i64 q = start_[y * nx_ + x]; q < start_[y * nx_ + x + 1]; ++q) {
          const i64 i = item_[q];
          if (stamp_[i] == query_) continue;
          stamp_[i] = query_;
          if (!f(a_[i], b_[i])) return false;
        }
    return true;
  }

 private:
  std::vector<Pt> a_, b_;
  std::vector<i64> start_, stamp_;
  std::vector<int> item_;
  double X0_ = 0, Y0_ = 0, ix_ = 1, iy_ = 1;
  i64 nx_ = 1, ny_ = 1, query_ = 0;
  // cell indices: floor is monotone, so a box meets the cells of its two corners' range
  i64 cx(double x) const { return cell(std::floor((x - X0_) * ix_), nx_); }
  i64 cy(double y) const { return cell(std::floor((y - Y0_) * iy_), ny_); }
  static i64 cell(double t, i64 n) { return !(t >= 0) ? 0 : (t >= (double)n ? n - 1 : (i64)t); }
};

// ------------------------------------------------------------------------------------
// one polygonal set

struct Params {
  double distance = 0;     // signed
  double tolerance = NAN;  // NaN: the default
  double default_rel = 1e-3;
  bool outer = true;
  int join = ROUND;
  double limit = 2.0;
  bool resolve = true;  // false: every curve with crossings goes to the overlay (tests)
};

struct Result {
  int status = OK;   // Status of exact.hpp
  int code = FINE;   // Code above
  double least = 0;  // the least tolerance at this magnitude
  double eps = 0;    // the tolerance used
  int e0 = 0;        // the scale: coordinates were multiplied by 2^-e0
  int path = DIRECT;  // how the region was found (Path)
  ov::Rings rings;   // the result (unscaled unless keep_scaled)
  std::vector<double> used_xy;  // with labels: the rings offset (scaled), offset side right
  std::vector<i64> used_off{0};
  std::vector<i64> labels;      // with labels: per output vertex, the label of its edge
};

// rings: (xy, n, hole) of one polygonal set; unite: overlapping parts are united first;
// delta: a bound on the distance between the given rings and the true input.
class Offsetter {
 public:
  void run(const std::vector<ms::Ring>& input, bool unite, double delta, const Params& p,
           bool want_labels, Result& res) {
    res = Result();
    res.rings.want_lines = want_labels;
    const double r0 = std::fabs(p.distance);
    const bool grow = p.distance > 0;
    // rings with the inside on the left
    std::vector<std::vector<Pt>>& rings = rings_;
    for (auto& v : rings) v.clear();
    rings.resize(unite ? 0 : input.size());
    if (unite) {
      united(input, rings, delta);
    } else {
      for (std::size_t k = 0; k < input.size(); ++k) to_pts(input[k], rings[k]);
    }
    for (auto& v : rings) drop_straight(v);
    if (r0 == 0) {  // the polygon itself (regularized: the overlay of its rings)
      regularized(rings, res);
      return;
    }
    double big = 0;
    for (auto& v : rings)
      for (const Pt& q : v) big = std::max(big, std::max(std::fabs(q.x), std::fabs(q.y)));
    // scale: every coordinate of the problem below 1/2, of the result below 2
    double mx = std::max(big, r0);
    int e;
    std::frexp(mx, &e);
    const int e0 = e + 1;
    res.e0 = e0;
    Setup s;
    s.grow = grow;
    s.join = p.join;
    s.limit = p.limit;
    s.resolve = p.resolve;
    s.r = std::ldexp(r0, -e0);
    double dl = delta > 0 ? up(std::ldexp(delta, -e0)) : 0.0;
    if (e0 > 0) dl = up(dl + 0x1p-1073);  // scaling down may round subnormals
    // the overlay's rounding of a crossing (below sqrt(2)/2 ulp), up to 5 times when it
    // re-nodes rounded rings that came out invalid: below 4 ulp
    const double m = 0x1p-50;
    const double mu = up(m + dl);
    s.mc = up(std::ldexp(s.r, -45) + 0x1p-50);
    const double least = up(2 * mu + 4 * s.mc);
    res.least = std::ldexp(least, e0);
    // the rings, scaled (exact, but for coordinates that become subnormal: delta covers
    // them; then vertices may coincide or become collinear: cleaned again), in the curve's
    // frame (offset side on the right)
    const Pow2 down_scale(-e0);
    std::vector<std::vector<Pt>>& sc = sc_;
    std::size_t nsc = 0;
    for (auto& v0 : rings) {
      if (v0.empty()) continue;
      if (!grow && v0.size() < 3) continue;  // no area: nothing to shrink
      if (sc.size() <= nsc) sc.emplace_back();
      std::vector<Pt>& sv = sc[nsc];
      sv.clear();
      for (const Pt& q : v0) {
        Pt t{down_scale(q.x), down_scale(q.y)};
        if (sv.empty() || sv.back().x != t.x || sv.back().y != t.y) sv.push_back(t);
      }
      while (sv.size() > 1 && sv.front().x == sv.back().x && sv.front().y == sv.back().y)
        sv.pop_back();
      drop_straight(sv);
      if (!grow && sv.size() < 3) continue;
      if (!grow) std::reverse(sv.begin(), sv.end());
      ++nsc;
    }
    sc.resize(nsc);
    // a shrink of a set narrower than 2r (its box, the rings' error delta added) is empty:
    // a disk of radius r inside it would need a box of width 2r. The float width W and
    // dl are within a relative 2^-52 of the exact ones, the margins 2^-40 far above.
    bool narrow = false;
    if (!grow) {
      double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
      for (auto& v : sc)
        for (const Pt& q : v) {
          x0 = std::min(x0, q.x);
          x1 = std::max(x1, q.x);
          y0 = std::min(y0, q.y);
          y1 = std::max(y1, q.y);
        }
      const double W = std::min(x1 - x0, y1 - y0);
      narrow = (W + 2 * dl) * (1 + 0x1p-40) < 2 * s.r * (1 - 0x1p-40);
    }
    if (!set_tolerances(p, grow, want_labels, least, mu, e0, sc, s, res)) return;
    if (narrow) {  // every ring shrinks away: the empty set, on either side
      finish(e0, want_labels, res);
      return;
    }
    // the curves, pruned (round joins), one simple curve taken as it is, else the overlay;
    // a pruned result must pass the check of its lower bound, else it is computed again
    // unpruned
    const bool prune = p.join == ROUND && !want_labels;
    if (!curves(sc, s, want_labels, prune, res)) return;
    if (pruned_ && !covers(res.rings, sc, s.r_check, direct_ ? &affected_[0] : nullptr)) {
      res.rings.clear();
      if (!curves(sc, s, want_labels, false, res)) return;
    }
    finish(e0, want_labels, res);
  }

 private:
  Pruner pruner_;
  Resolver resolver_;
  bool pruned_ = false;
  bool direct_ = false;  // the result is the one pruned curve itself
  std::vector<const std::vector<Pt>*> ring_;
  std::vector<std::pair<i64, i64>> cross_;
  Chains cscr_;
  EdgeGrid grid_;
  std::vector<std::vector<char>> affected_;  // per curve, the cuts' ring vertices

  // Builds the curves of the rings sc (pruned when asked) and their region in
  // res.rings; false (res.code set) when a piece fails its certificate.
  bool curves(const std::vector<std::vector<Pt>>& sc, const Setup& s, bool want_labels,
              bool prune, Result& res) {
    i64 base = 0;
    std::size_t nc = 0;
    pruned_ = false;
    ring_.clear();
    for (const std::vector<Pt>& sv : sc) {
      if (sv.empty()) continue;
      if (curves_.size() <= nc) curves_.emplace_back();
      Curve& cv = curves_[nc++];
      cv.build(sv, s, base);
      if (!cv.certified) {
        res.code = UNCERTIFIED;
        return false;
      }
      ring_.push_back(&sv);
      if (want_labels) {
        for (const Pt& q : sv) {
          res.used_xy.push_back(q.x);
          res.used_xy.push_back(q.y);
        }
        res.used_off.push_back((i64)res.used_xy.size() / 2);
      }
      base += (i64)sv.size();
    }
    // crossings: a single curve without any is the boundary; swallowed loops pruned
    bool one_simple = false;
    bool listed = false;  // cross_ lists every crossing of the one curve, and nothing else meets
    for (std::size_t k = 0; k < nc && (prune || nc == 1); ++k) {
      Curve& cv = curves_[k];
      const bool clean = curve_crossings(cv.pts, cross_, cscr_, true);
      one_simple = clean && cross_.empty();
      if (one_simple || !prune) continue;
      if (affected_.size() <= k) affected_.resize(k + 1);
      affected_[k].assign(ring_[k]->size(), 0);
      bool pr = pruner_.run(cv, *ring_[k], s, nullptr, affected_[k]);
      listed = curve_crossings(cv.pts, cross_, cscr_);
      one_simple = listed && cross_.empty();
      // (a second pass starts away from the crossings the first left: a loop across its
      // start)
      for (int pass = 0; pass < 2 && !one_simple; ++pass) {
        bool pr2 = pruner_.run(cv, *ring_[k], s, &cross_, affected_[k]);
        if (!pr2) break;
        pr = true;
        listed = curve_crossings(cv.pts, cross_, cscr_);
        one_simple = listed && cross_.empty();
      }
      pruned_ = pruned_ || pr;
    }
    direct_ = nc == 1 && one_simple;
    if (direct_) {
      res.path = DIRECT;
      direct(curves_[0], s.grow, want_labels, res);
      return true;
    }
    // a few crossings left: resolved without the overlay (its result exactly)
    if (nc == 1 && listed && s.resolve && resolver_.run(curves_[0].pts, cross_, s.grow, res.rings)) {
      res.path = RESOLVED;
      return true;
    }
    res.path = OVERLAID;
    ov::Geo g;
    std::vector<ov::EdgeIn> in;
    std::vector<i64> line_label;
    const int w = s.grow ? 1 : -1;
    for (std::size_t k = 0; k < nc; ++k)
      add_curve(g, curves_[k].pts, curves_[k].lab, w, in, line_label);
    ov::Overlay o(g);
    o.run(in, ov::UNION, res.rings);
    if (want_labels) {
      // the lines of the output edges, unless the overlay had to re-node its rounded
      // rings (then they are unknown: DETOUR, and offset_arcs labels by distances)
      const std::size_t nv = res.rings.xy.size() / 2;
      res.labels.assign(nv, DETOUR);
      if (res.rings.line.size() == nv)
        for (std::size_t k = 0; k < nv; ++k) res.labels[k] = line_label[res.rings.line[k]];
    }
    return true;
  }

  // Is every edge of the result R (scaled) at distance >= t from the rings sc? Exact:
  // segment pairs whose boxes come within t, then orientations and distances. marked
  // (the one ring's cut vertices, when R is the pruned curve itself, unrounded): from
  // the edges at marked vertices only (see the header of offset_prune.hpp).
  bool covers(const ov::Rings& R, const std::vector<std::vector<Pt>>& sc, double t,
              const std::vector<char>* marked) {
    if (R.status != OK) return true;  // an error is reported as it is
    // the output's edges widened by t (and more than the rounding of the widening)
    double M = 0;
    for (double c : R.xy) M = std::max(M, std::fabs(c));
    const double w = t * (1 + 0x1p-40) + span_slack(M);
    grid_.build(sc, w, marked);
    for (std::size_t k = 0; k + 1 < R.ring_off.size(); ++k) {
      const i64 r0 = R.ring_off[k], r1 = R.ring_off[k + 1];
      for (i64 i = r0; i < r1; ++i) {
        const i64 j = i + 1 < r1 ? i + 1 : r0;
        const Pt p{R.xy[2 * i], R.xy[2 * i + 1]}, q{R.xy[2 * j], R.xy[2 * j + 1]};
        const double x0 = std::min(p.x, q.x) - w, x1 = std::max(p.x, q.x) + w,
                     y0 = std::min(p.y, q.y) - w, y1 = std::max(p.y, q.y) + w;
        const bool ok = grid_.query(x0, x1, y0, y1, [&](Pt c, Pt d) {
          if (std::max(c.x, d.x) < x0 || std::min(c.x, d.x) > x1 || std::max(c.y, d.y) < y0 ||
              std::min(c.y, d.y) > y1)
            return true;
          return far_apart(p, q, c, d, t);
        });
        if (!ok) return false;
      }
    }
    return true;
  }

  // Are the segments pq and cd at distance >= t (exactly)? They must not cross (boxes
  // apart, or the orientations), and each end must be at distance >= t from the other
  // segment: first in double -- with every coordinate below 2 in magnitude (the scaled
  // problem) a squared point-segment distance computed as in seg_d2 is within 2^-44 of
  // the exact one (differences and products below 64, a few roundings each; a projection
  // outside its segment taken as inside or the reverse changes it by the square of the
  // rounding of the dot product, far less), so one at least t^2 + 2^-40 decides -- else
  // exactly (seg_dist_cmp).
  static bool far_apart(Pt p, Pt q, Pt c, Pt d, double t) {
    const bool apart = std::max(p.x, q.x) < std::min(c.x, d.x) ||
                       std::max(c.x, d.x) < std::min(p.x, q.x) ||
                       std::max(p.y, q.y) < std::min(c.y, d.y) ||
                       std::max(c.y, d.y) < std::min(p.y, q.y);
    if (!apart && cross_properly(p, q, c, d)) return false;
    const double big = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(q.x), std::fabs(q.y),
                                 std::fabs(c.x), std::fabs(c.y), std::fabs(d.x), std::fabs(d.y)});
    const bool fl = big < 2 && t < 2;
    const double lim = t * t + 0x1p-40;
    auto far = [&](Pt a, Pt b, Pt x) {
      if (fl && seg_d2(a, b, x) >= lim) return true;
      return seg_dist_cmp(a, b, x, t) >= 0;
    };
    return far(c, d, p) && far(c, d, q) && far(p, q, c) && far(p, q, d);
  }

  static double seg_d2(Pt a, Pt b, Pt p) {
    const double dx = b.x - a.x, dy = b.y - a.y, px = p.x - a.x, py = p.y - a.y;
    const double dot = px * dx + py * dy;
    if (dot <= 0) return px * px + py * py;
    const double L = dx * dx + dy * dy;
    if (dot >= L) {
      const double qx = p.x - b.x, qy = p.y - b.y;
      return qx * qx + qy * qy;
    }
    const double cr = px * dy - py * dx;
    return cr * cr / L;
  }



  // The polygon itself, regularized: the overlay of its rings (distance 0).
  static void regularized(const std::vector<std::vector<Pt>>& rings, Result& res) {
    ov::Geo g;
    std::vector<ov::EdgeIn> in;
    for (auto& v : rings) {
      if (v.size() < 3) continue;
      i64 first = (i64)g.pts.size();
      for (const Pt& q : v) g.point(ov::dd(q.x), ov::dd(q.y));
      ov::add_ring(g, first, (i64)v.size(), 1, 0, in);
    }
    ov::Overlay o(g);
    o.run(in, ov::UNION, res.rings);
    res.status = res.rings.status;
  }

  // The tolerance and the radii of the round join (with the notches of sc filled when
  // the budget allows, see fill_notches); false (res.code set) when the tolerance cannot
  // be met. Miter and square joins take the radius as it is.
  static bool set_tolerances(const Params& p, bool grow, bool want_labels, double least,
                             double mu, int e0, std::vector<std::vector<Pt>>& sc, Setup& s,
                             Result& res) {
    if (p.join == ROUND) {
      double eps;
      if (std::isnan(p.tolerance)) {
        eps = std::min(std::max(p.default_rel * s.r, least * (1 + 0x1p-20)), s.r / 2);
        if (eps < least) {
          res.code = DISTANCE;
          return false;
        }
      } else {
        eps = std::min(std::ldexp(p.tolerance, -e0), s.r / 2);
        if (eps < least) {
          res.code = TOLERANCE;
          return false;
        }
      }
      res.eps = std::ldexp(eps, e0);
      s.circ = p.outer == grow;
      // shallow notches filled (see fill_notches): the offset of the filled set P' with
      // radius r and tolerance eps - h (circumscribed), or r - h and eps - h (inscribed),
      // is within the bounds of P's offset with r and eps
      if (!want_labels && 0.75 * eps >= least * (1 + 0x1p-20)) {
        // passes while notches go and the budget eps / 4 lasts (each pass's bound adds)
        double h = 0;
        for (int pass = 0; pass < 8; ++pass) {
          const double room = down(eps / 4 - h);
          if (!(room > 0)) break;
          const double hk = fill_notches(sc, room);
          if (hk == 0) break;
          h = up(h + hk);
        }
        if (h > 0) {
          if (s.circ) {
            eps = down(eps - h);
          } else {
            const double inner = up(s.r - eps);  // P' (+) D(r' - eps') covers P (+) D(r - eps)
            s.r = down(s.r - h);
            eps = down(s.r - inner);
          }
        }
      }
      if (s.circ) {
        s.t_cov = up(s.r + mu);
        s.t_up = down(down(s.r + eps) - mu);
        s.rho = up(s.t_cov + s.mc);
        double Rmax = down(s.t_up - s.mc);
        s.phimax = std::min(2 * std::acos(s.rho / Rmax), M_PI / 2);
      } else {
        s.t_cov = up(up(s.r - eps) + mu);
        s.t_up = down(s.r - mu);
        s.rho = down(s.t_up - 2 * s.mc);
        double ct = up(s.t_cov + s.mc);
        s.phimax = std::min(2 * std::acos(ct / s.rho), M_PI);
        s.eta = 2 * s.mc / s.rho;
      }
      // the lower radius plus delta: t_cov - m >= r_lo + mu - m >= r_lo + delta
      s.r_check = up(s.t_cov - 0x1p-50);
    } else {
      s.circ = true;
      s.rho = s.r;
    }
    return true;
  }

  std::vector<Curve> curves_;
  std::vector<std::vector<Pt>> rings_, sc_;  // the rings read, scaled (reused)

 public:
  // about how many points its buffers hold (the curves')
  std::size_t footprint() const {
    std::size_t n = 0;
    for (const Curve& c : curves_) n += c.pts.capacity();
    return n;
  }

 private:
  // The region of one simple curve: its inside when it turns the way the rule selects
  // (counter-clockwise for a grow, clockwise for a shrink, whose curve has weight -1),
  // else nothing. Straight vertices dropped, from the least (x, y) vertex.
  static void direct(const Curve& cv, bool grow, bool want_labels, Result& res) {
    const std::vector<Pt>& p = cv.pts;
    const std::size_t n = p.size();
    const std::size_t lo = (std::size_t)least_point(p);
    int o = orient(p[(lo + n - 1) % n], p[lo], p[(lo + 1) % n]);  // nonzero: extreme
    ov::Rings& R = res.rings;
    R.clear();
    if ((o > 0) != grow) return;  // winding -1 inside (a shrink that erases everything)
    // from lo, forwards (grow) or backwards (shrink: the label of the edge from point i
    // to point i - 1 is that of the curve's edge i - 1), straight vertices dropped (lo is
    // extreme, never straight)
    R.xy.reserve(2 * n);
    i64 count = 0;
    for (std::size_t k = 0, i = lo; k < n; ++k, i = grow ? next_of(i, n) : prev_of(i, n)) {
      const std::size_t ip = prev_of(i, n);
      if (orient(p[ip], p[i], p[next_of(i, n)]) == 0) continue;  // straight on
      R.xy.push_back(p[i].x);
      R.xy.push_back(p[i].y);
      if (want_labels) res.labels.push_back(grow ? cv.lab[i] : cv.lab[ip]);
      ++count;
    }
    R.ring_off.push_back(count);
    R.poly_off.push_back(1);
  }

  // status, scale back, range
  static void finish(int e0, bool want_labels, Result& res) {
    if (res.rings.status != OK) {
      res.status = res.rings.status;
      return;
    }
    if (want_labels) return;  // scaled
    double top = 0;
    const Pow2 up_scale(e0);
    for (double& c : res.rings.xy) {
      c = up_scale(c);
      top = std::max(top, std::fabs(c));
    }
    if (!(top <= 1.79769313486231570815e308)) res.code = OVERFLOWS;
    else if (top > 0 && top < 0x1p-1020) res.code = UNDERFLOW;
  }

 private:
  // the union of the rings (overlapping parts), rounded: delta grows by the rounding
  void united(const std::vector<ms::Ring>& input, std::vector<std::vector<Pt>>& rings,
              double& delta) {
    ov::Geo g;
    std::vector<ov::EdgeIn> in;
    double big = 0;
    std::vector<ms::Ring> pts_only;
    for (const ms::Ring& r : input) {
      if (r.n() < 3) {
        pts_only.push_back(r);
        continue;
      }
      i64 first = (i64)g.pts.size();
      for (i64 i = 0; i < r.n(); ++i) {
        g.point(ov::dd(r.x(i)), ov::dd(r.y(i)));
        big = std::max(big, std::max(std::fabs(r.x(i)), std::fabs(r.y(i))));
      }
      ov::add_ring(g, first, r.n(), 1, 0, in);
    }
    ov::Overlay o(g);
    ov::Rings out;
    o.run(in, ov::UNION, out);
    for (std::size_t k = 0; k + 1 < out.ring_off.size(); ++k) {
      std::vector<Pt> v;
      for (i64 i = out.ring_off[k]; i < out.ring_off[k + 1]; ++i)
        v.push_back(Pt{out.xy[2 * i], out.xy[2 * i + 1]});
      rings.push_back(std::move(v));
    }
    for (const ms::Ring& r : pts_only) {
      rings.emplace_back();
      to_pts(r, rings.back());
    }
    if (big > 0) {
      int e;
      std::frexp(big, &e);
      delta = up(delta + std::ldexp(1.0, std::max(e - 52, -1074)));
    }
  }

  static void add_curve(ov::Geo& g, const std::vector<Pt>& pts, const std::vector<i64>& lab,
                        int w, std::vector<ov::EdgeIn>& in, std::vector<i64>& line_label) {
    const i64 n = (i64)pts.size();
    if (n < 2) return;
    const i64 p0 = (i64)g.pts.size(), v0 = (i64)g.verts.size();
    for (const Pt& q : pts) g.point(ov::dd(q.x), ov::dd(q.y));
    for (i64 i = 0; i < n; ++i) g.vert_point(p0 + i);
    for (i64 i = 0; i < n; ++i) {
      i64 a = p0 + i, b = p0 + next_of(i, n);
      if (ov::p_eq(g.pts[a], g.pts[b])) continue;
      i64 l = g.line(a, b);
      line_label.resize((std::size_t)l + 1, DETOUR);
      line_label[l] = lab[i];
      in.push_back(ov::EdgeIn{l, v0 + i, v0 + next_of(i, n), w, 0});
    }
  }
};

}  // namespace off
}  // namespace mk

