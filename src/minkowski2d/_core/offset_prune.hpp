// offset_prune.hpp -- swallowed loops cut out of an offset curve before the overlay (see
// offset.hpp, which includes it; include that).
//
// Where the offset closes a slot, rounds a concave corner tighter than the radius or
// merges the arcs of close convex vertices, the curve of offset.hpp runs in loops that
// lie inside the result: the moved edges of a concave run cross in a swallowtail, the
// detours of its reflex vertices reach back to the polygon, and the arcs of two convex
// vertices closer than 2r overlap for most of their length. The exact overlay would
// node every crossing of them. Pruning cuts such a loop at the crossing X of the two
// curve segments A and B that bound it and joins A to B at X (as the trims of
// offset_curve.hpp do for one reflex vertex), in one pass over the curve with a stack.
//
// Pieces. With the anchors of Curve (point k attached to ring vertex anc[k]), the piece
// of segment p -> q is the polygon anc(p), p, q, anc(q) closed along the ring back to
// anc(p), and curve = boundary of P + the sum of the pieces' boundaries (chains that
// telescope, as in offset.hpp). A cut at X replaces the pieces of A, of every segment
// between A and B and of B by two: A's piece up to X (anchors of A) and the piece of the
// new segment X -> end of B, whose ring path runs from A's end anchor to B's. The chain
// identity holds again, so the region of the new curve is P plus the new pieces
// (grow; a shrink removes them). Each new piece is certified exactly before the cut is
// made: its boundary must be the sum of the boundaries of triangles that each turn
// counter-clockwise (or are flat) and whose three corners lie within t_up of one convex
// feature of the ring (an edge, or a vertex and so its two edges; the features kept with
// each point and segment say which are known, the others are checked). Then the piece's
// winding number is a sum of 0s and 1s: never negative, and nonzero only inside a
// triangle, within t_up of the polygon. Three decompositions are tried: the fan from the
// float centroid O (triangles O, g_m, g_m+1); the zipper (zip_ok: the ring path walked
// from its middle towards both ends, cut by rungs whose middles are extra corners, for a
// strip narrower than 2 t_up that no triangulation of its vertices alone certifies);
// ear clipping. A triangle at a short edge may take an edge a few along the ring
// (tri_near).
// X itself is a double right of both segments (outwards: the region only grows by the
// sliver) checked within t_up of both segments' features. So the pruned result still
// lies within t_up of the polygon: the upper half of the guarantee holds by
// construction.
//
// The lower half (the result covers the band of width t_cov) is not local any more: the
// removed pieces covered parts of it. It is verified on the result (Offsetter::covers):
// every output edge at distance >= r_lo + delta from the polygon (exact), which with the
// polygon inside the result (grow; outside it for a shrink) puts every point within
// r_lo of the polygon in the result: a point of the band outside it would see the
// result's boundary on the segment to its nearest point of the polygon, nearer than
// r_lo. When the check fails the offset is computed again without pruning; no
// heuristic decides a result.
//
// Which loops: segments are taken in order, by the local pass from a point of the
// curve's convex hull (on the result's outer boundary, so never inside a loop), each
// against the last stack segments near it, then by the global pass from the middle of the
// longest run without crossings, each against its crossing partners still on the stack
// (the deepest first): a segment is cut at the deepest crossing whose certificate holds
// (a few tried, ring paths up to PRUNE_PATH edges), which removes the largest loop.
// Crossings that remain (the curve closing a hole, two rings meeting, a loop whose piece
// is not certified) are the overlay's.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "boxes.hpp"
#include "exact.hpp"

namespace mk {
namespace off {

// the longest ring path of a new piece, and the cuts tried per segment
constexpr i64 PRUNE_PATH = 256;
constexpr int PRUNE_TRIES = 4;
constexpr i64 PRUNE_WINDOW = 24;  // the local pass: stack segments tested per segment
constexpr i64 PRUNE_BLOCK = 8;    // ... their boxes tested a block at a time first
constexpr i64 PRUNE_EARS = 128;  // ear clipping: pieces of at most this many points
constexpr i64 PRUNE_NEAR = 4;    // a triangle near a short edge: the edges this far along

// p within t of the feature f of the ring v (a vertex or a closed edge: convex sets)
inline bool near_feature(const std::vector<Pt>& v, i64 f, Pt p, double t) {
  const i64 n = (i64)v.size(), j = f >> 1;
  if (f & 1) return dist_cmp(v[j], p, t) <= 0;
  return seg_dist_cmp(v[j], v[next_of(j, n)], p, t) <= 0;
}

// Does feature k lie in edge feature e (k == e, or k is an end vertex of e)?
inline bool feature_in(i64 k, i64 e, i64 n) {
  if (k == e) return true;
  if (!(k & 1)) return false;
  const i64 j = k >> 1, ej = e >> 1;
  return j == ej || j == next_of(ej, n);
}

// Do the segments ab and cd cross properly (one point inside both, exactly)?
inline bool cross_properly(Pt a, Pt b, Pt c, Pt d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d);
  if (o1 * o2 >= 0) return false;
  const int o3 = orient(c, d, a), o4 = orient(c, d, b);
  return o3 * o4 < 0;
}

class Pruner {
 public:
  // Cuts the swallowed loops of cv (a curve of the ring v with its bookkeeping); true
  // when it cut any. crossings: the proper crossings of cv's segments (pairs i < j).
  // crossings null: the local pass (each segment against the last PRUNE_WINDOW segments
  // of the stack whose boxes meet its own).
  // affected: per ring vertex, set where a cut changed the pieces of the vertex or of the
  // edge that starts at it (the ring path from A's start to B's end anchor).
  bool run(Curve& cv, const std::vector<Pt>& v, const Setup& s,
           const std::vector<std::pair<i64, i64>>* crossings, std::vector<char>& affected) {
    const i64 m = (i64)cv.pts.size(), n = (i64)v.size();
    if (m < 4 || n < 3 || s.join != ROUND || (crossings && crossings->empty())) return false;
    affected_ = &affected;
    v_ = &v;
    t_up_ = s.t_up;
    t_lo_ = s.r_check * (1 - 0x1p-30);
    n_ = n;
    local_ = crossings == nullptr;
    const i64 s0 = local_ ? least_point(cv.pts) : far_start(m, *crossings);
    if (!local_) partners(m, s0, *crossings);
    where_.assign(m, -1);
    Q_.clear();
    qa_.clear();
    qpf_.clear();
    qsf_.clear();
    qorig_.clear();
    push_point(cv.pts[s0], cv.anc[s0], cv.pf[s0]);
    bool cut = false;
    for (i64 t = 0; t < m; ++t) {
      const i64 k = s0 + t < m ? s0 + t : s0 + t - m, k1 = next_of(k, m);
      // anchors unwrapped: they grow by 0 or 1 per segment of the curve
      const i64 da = cv.anc[k1] - cv.anc[k];
      const i64 ue = qa_.back() + (da < 0 ? da + n : da);
      start_segment(k, cv.sf[k]);
      for (int tries = PRUNE_TRIES; tries > 0 && candidates(k, cv.pts[k1]);)
        if (try_cuts(k, cv.pts[k1], ue, cv.pf[k1], cv.sf[k], tries)) {
          cut = true;
        } else {
          break;
        }
      push_point(cv.pts[k1], ue, cv.pf[k1]);
    }
    if (!cut) return false;
    // the last point is the start again
    Q_.pop_back();
    qa_.pop_back();
    qpf_.pop_back();
    cv.pts = Q_;
    cv.anc.resize(Q_.size());
    for (std::size_t i = 0; i < Q_.size(); ++i) cv.anc[i] = qa_[i] % n;
    cv.pf = qpf_;
    cv.sf.assign(qsf_.begin(), qsf_.begin() + (i64)Q_.size());
    cv.lab.assign(Q_.size(), DETOUR);  // labels are for offset_arcs, which does not prune
    return true;
  }

 private:
  // The middle of the longest run of segments without a crossing (a loop seldom spans
  // it, so a cut seldom has to wrap around the start).
  i64 far_start(i64 m, const std::vector<std::pair<i64, i64>>& crossings) {
    where_.assign(m, 0);  // (scratch: has a crossing)
    for (auto& c : crossings) where_[c.first] = where_[c.second] = 1;
    i64 first = -1, prev = -1, best = -1, at = 0;
    for (i64 k = 0; k < m; ++k) {
      if (!where_[k]) continue;
      if (first < 0) first = k;
      if (prev >= 0 && k - prev > best) {
        best = k - prev;
        at = (prev + (k - prev) / 2 + 1) % m;
      }
      prev = k;
    }
    if (first >= 0 && first + m - prev > best) at = (prev + (first + m - prev) / 2 + 1) % m;
    return at;
  }

  // crossing partners per segment (CSR), each segment's in the order the pass meets them
  // from s0 (the stack's order): the relation is symmetric, so taking the segments j in
  // that order and appending j to the lists of its partners sorts every list (linear)
  void partners(i64 m, i64 s0, const std::vector<std::pair<i64, i64>>& crossings) {
    part_off_.assign(m + 1, 0);
    for (auto& c : crossings) {
      ++part_off_[c.first + 1];
      ++part_off_[c.second + 1];
    }
    for (i64 k = 0; k < m; ++k) part_off_[k + 1] += part_off_[k];
    fill_.resize(part_off_[m]);  // unsorted lists
    cand_.assign(part_off_.begin(), part_off_.end() - 1);
    for (auto& c : crossings) {
      fill_[cand_[c.first]++] = c.second;
      fill_[cand_[c.second]++] = c.first;
    }
    part_.resize(part_off_[m]);
    cand_.assign(part_off_.begin(), part_off_.end() - 1);
    for (i64 t = 0; t < m; ++t) {
      const i64 j = s0 + t < m ? s0 + t : s0 + t - m;
      for (i64 q = part_off_[j]; q < part_off_[j + 1]; ++q) part_[cand_[fill_[q]]++] = j;
    }
  }

  const std::vector<Pt>* v_ = nullptr;
  std::vector<char>* affected_ = nullptr;
  bool local_ = false;
  double t_up_ = 0, t_lo_ = 0;
  i64 n_ = 0;
  std::vector<i64> part_off_, part_, fill_, where_, cand_;
  // the stack: points, their anchors (unwrapped: ring vertex anchor mod n) and features;
  // segment e runs Q_[e] -> Q_[e + 1]
  std::vector<Pt> Q_;
  struct Box {
    double x0, x1, y0, y1;
  };
  std::vector<Box> qbox_;  // the box of stack segment e (Q_[e] -> Q_[e + 1])
  std::vector<Box> qblock_;  // a box holding those of segments PRUNE_BLOCK k ..
  std::vector<i64> qa_, qpf_, qsf_, qorig_;
  // scratch of the certificates
  std::vector<Pt> g_;
  std::vector<i64> gf_, gr_, gp_, nx_, pv_, fa_, fc_;
  void push_point(Pt p, i64 a, i64 f) {
    Q_.push_back(p);
    qa_.push_back(a);
    qpf_.push_back(f);
    const std::size_t e = Q_.size() - 1;  // segment e - 1 now ends at p: its box
    if (e == 0) return;
    const Pt q = Q_[e - 1];
    qbox_.resize(e);
    const Box b{std::min(q.x, p.x), std::max(q.x, p.x), std::min(q.y, p.y), std::max(q.y, p.y)};
    qbox_[e - 1] = b;
    // the block's box: reset by its first segment, else widened (a block cut back keeps
    // the boxes of its segments gone: a larger box, never a smaller one)
    const std::size_t k = (e - 1) / PRUNE_BLOCK;
    if (qblock_.size() <= k) qblock_.resize(k + 1);
    Box& B = qblock_[k];
    if ((e - 1) % PRUNE_BLOCK == 0) {
      B = b;
    } else {
      B = Box{std::min(B.x0, b.x0), std::max(B.x1, b.x1), std::min(B.y0, b.y0), std::max(B.y1, b.y1)};
    }
  }
  void start_segment(i64 k, i64 f) {
    const std::size_t e = Q_.size() - 1;
    qsf_.resize(e + 1);
    qorig_.resize(e + 1);
    qsf_[e] = f;
    qorig_[e] = k;
    where_[k] = (i64)e;
  }

  // The stack positions of k's alive crossing partners in cand_ (false: none): the
  // local pass the most recent first, the global pass the deepest first.
  bool candidates(i64 k, Pt end) {
    cand_.clear();
    const i64 top = (i64)Q_.size() - 1;
    if (local_) {
      const Pt c = Q_[top];
      const double x0 = std::min(c.x, end.x), x1 = std::max(c.x, end.x),
                   y0 = std::min(c.y, end.y), y1 = std::max(c.y, end.y);
      // (whole blocks apart skipped; the four tests without branches: a hit is rare, and
      // its one branch predicted)
      auto apart = [&](const Box& b) {
        return (b.x1 < x0) | (b.x0 > x1) | (b.y1 < y0) | (b.y0 > y1);
      };
      const Box* bx = qbox_.data();
      for (i64 e = top - 2, lo = std::max<i64>(0, top - PRUNE_WINDOW); e >= lo; --e) {
        if (e % PRUNE_BLOCK == PRUNE_BLOCK - 1 && apart(qblock_[e / PRUNE_BLOCK])) {
          e -= PRUNE_BLOCK - 1;
          continue;
        }
        if (!apart(bx[e])) cand_.push_back(e);
      }
      return !cand_.empty();
    }
    for (i64 q = part_off_[k]; q < part_off_[k + 1]; ++q) {  // deepest first
      const i64 e = where_[part_[q]];
      if (e >= 0 && e < top && qorig_[e] == part_[q]) cand_.push_back(e);
    }
    return !cand_.empty();
  }

  // Cuts the current segment (Q_.back() -> end, segment k) at its crossing with the
  // deepest stack segment whose certificate holds; true when cut.
  bool try_cuts(i64 k, Pt end, i64 end_anc, i64 end_pf, i64 fb, int& tries) {
    const i64 top = (i64)Q_.size() - 1;
    for (i64 e : cand_) {
      Pt X;
      if (tries <= 0) break;
      const Pt a = Q_[e], b = Q_[e + 1], c = Q_[top];
      const i64 fa = qsf_[e];
      // X on the result's boundary must keep r_lo from the polygon: a cut whose X comes
      // nearer to the features of A or B (a detour's spike cut near its vertex) would
      // fail the check of the result (a heuristic in double, first: most crossings inside
      // a swallowed loop are such; the check decides)
      if (!crossing_double(a, b, c, end, X)) continue;
      if (feature_d2(fa, X) < t_lo_ * t_lo_ || feature_d2(fb, X) < t_lo_ * t_lo_) continue;
      if (!cross_properly(a, b, c, end)) continue;
      if (!crossing_estimate(a, b, c, end, X)) continue;
      --tries;
      if (!outwards(a, b, c, end, X)) continue;
      // (rounded onto an end: the cut would leave a segment of no length)
      if ((X.x == a.x && X.y == a.y) || (X.x == end.x && X.y == end.y)) continue;
      if (!near_feature(*v_, fa, X, t_up_) || !near_feature(*v_, fb, X, t_up_)) continue;
      const i64 ea = qa_[e + 1];  // A's end anchor: X's anchor
      // A up to X: anchors of A
      if (!piece_ok(qa_[e], a, qpf_[e], X, fa, ea, fa)) continue;
      // the new segment X -> end, from A's end anchor to B's
      if (!piece_ok(ea, X, fa, end, fb, end_anc, end_pf)) continue;
      // cut: drop the stack above A, X on top with the current segment from it
      for (i64 u = qa_[e]; u <= end_anc; ++u) (*affected_)[u % n_] = 1;
      for (i64 q = e + 1; q <= top; ++q) where_[qorig_[q]] = -1;
      Q_.resize(e + 1);
      qa_.resize(e + 1);
      qpf_.resize(e + 1);
      push_point(X, ea, fa);
      start_segment(k, fb);
      return true;
    }
    return false;
  }

  // the squared distance from x to feature f, in double
  double feature_d2(i64 f, Pt x) const {
    const std::vector<Pt>& v = *v_;
    const i64 j = f >> 1;
    const Pt a = v[j], b = (f & 1) ? v[j] : v[next_of(j, n_)];
    const double dx = b.x - a.x, dy = b.y - a.y, px = x.x - a.x, py = x.y - a.y;
    const double L = dx * dx + dy * dy, u = L > 0 ? std::clamp((px * dx + py * dy) / L, 0.0, 1.0) : 0.0;
    const double ex = px - u * dx, ey = py - u * dy;
    return ex * ex + ey * ey;
  }

  // The crossing of the lines ab and cd, roughly (double; false when parallel or not
  // finite)
  static bool crossing_double(Pt a, Pt b, Pt c, Pt d, Pt& X) {
    const double ux = b.x - a.x, uy = b.y - a.y, wx = d.x - c.x, wy = d.y - c.y;
    const double den = ux * wy - uy * wx;
    const double t = ((c.x - a.x) * wy - (c.y - a.y) * wx) / den;
    X = Pt{a.x + t * ux, a.y + t * uy};
    return X.x - X.x == 0 && X.y - X.y == 0;
  }

  // The crossing of the lines ab and cd, rounded (long double; false when parallel or
  // not finite)
  static bool crossing_estimate(Pt a, Pt b, Pt c, Pt d, Pt& X) {
    using LD = long double;
    const LD ux = (LD)b.x - a.x, uy = (LD)b.y - a.y, wx = (LD)d.x - c.x, wy = (LD)d.y - c.y;
    const LD den = ux * wy - uy * wx;
    if (den == 0) return false;
    const LD t = (((LD)c.x - a.x) * wy - ((LD)c.y - a.y) * wx) / den;
    X = Pt{(double)(a.x + t * ux), (double)(a.y + t * uy)};
    return X.x - X.x == 0 && X.y - X.y == 0;
  }

  // X moved to a double right of (or on) both lines ab and cd: a few units in the last
  // place outwards, along the sum of their right normals (false when none is found)
  static bool outwards(Pt a, Pt b, Pt c, Pt d, Pt& X) {
    if (orient(a, b, X) <= 0 && orient(c, d, X) <= 0) return true;
    const double ux = b.x - a.x, uy = b.y - a.y, wx = d.x - c.x, wy = d.y - c.y;
    const double lu = std::sqrt(ux * ux + uy * uy), lw = std::sqrt(wx * wx + wy * wy);
    const double nx = uy / lu + wy / lw, ny = -ux / lu - wx / lw;
    const double nn = std::sqrt(nx * nx + ny * ny);
    if (!(nn > 0)) return false;
    const Pt X0 = X;
    double step = std::max(std::fabs(X0.x), std::fabs(X0.y)) * 0x1p-50 + 0x1p-1060;
    for (int i = 1; i < 40; ++i, step *= 2) {
      const Pt c2{X0.x + step * nx / nn, X0.y + step * ny / nn};
      if (orient(a, b, c2) <= 0 && orient(c, d, c2) <= 0) {
        X = c2;
        return true;
      }
    }
    return false;
  }

  // Is the piece of the segment p -> q (anchors ap, aq; p within t_up of its feature fp
  // which contains ap, the segment of fs, q of fq which contains aq) a chain of
  // counter-clockwise triangles within t_up of the ring? See the header.
  bool piece_ok(i64 ap, Pt p, i64 fp, Pt q, i64 fs, i64 aq, i64 fq) {
    const std::vector<Pt>& v = *v_;
    const i64 len = aq - ap;  // anchors unwrapped: a path once around the ring is refused
    if (len < 0 || len > PRUNE_PATH || len >= n_) return false;
    ap %= n_;
    aq %= n_;
    g_.clear();
    gf_.clear();
    gr_.clear();
    gp_.clear();
    // x: a point with feature xf (ring vertex r >= 0: on the ring), f: the feature of the
    // edge from x to the next point
    auto add = [&](Pt x, i64 r, i64 xf, i64 f) {
      if (!g_.empty() && g_.back().x == x.x && g_.back().y == x.y) {
        gf_.back() = f;
        if (r >= 0) {
          gr_.back() = r;
          gp_.back() = xf;
        }
        return;
      }
      g_.push_back(x);
      gf_.push_back(f);
      gr_.push_back(r);
      gp_.push_back(xf);
    };
    add(v[ap], ap, vertex_feature(ap), fp);
    add(p, -1, fp, fs);
    add(q, -1, fq, fq);
    for (i64 i = 0; i <= len; ++i) {  // aq back to ap along the ring
      const i64 j = ((aq - i) % n_ + n_) % n_;
      add(v[j], j, vertex_feature(j), edge_feature((j + n_ - 1) % n_));
    }
    if (g_.size() > 1 && g_.back().x == g_[0].x && g_.back().y == g_[0].y) {
      g_.pop_back();
      gf_.pop_back();
      gr_.pop_back();
      gp_.pop_back();
    }
    const std::size_t k = g_.size();
    bool flat = true;  // no area (a spike): winding number 0 everywhere, nothing to show
    for (std::size_t i = 2; i < k && flat; ++i) flat = orient(g_[0], g_[1], g_[i]) == 0;
    if (flat) return true;
    if (fan_ok()) return true;
    if (zip_ok()) return true;
    return ears_ok();
  }

  // The fan from the centroid O: every triangle O, g_i, g_i+1 counter-clockwise or flat,
  // and O within t_up of the feature of the edge g_i -> g_i+1 (else the triangle within
  // t_up of another edge: tri_cert).
  bool fan_ok() {
    const std::size_t k = g_.size();
    double ox = 0, oy = 0;
    for (const Pt& x : g_) {
      ox += x.x;
      oy += x.y;
    }
    const Pt O{ox / (double)k, oy / (double)k};
    if (!(O.x - O.x == 0) || !(O.y - O.y == 0)) return false;
    for (std::size_t i = 0; i < k; ++i)
      if (orient(O, g_[i], g_[(i + 1) % k]) < 0) return false;
    for (std::size_t i = 0; i < k; ++i) {
      if (orient(O, g_[i], g_[(i + 1) % k]) == 0) continue;
      const i64 f = gf_[i], j = f >> 1;  // a vertex: either of its edges (they contain it)
      bool ok = (f & 1) ? near_feature(*v_, edge_feature(j), O, t_up_) ||
                              near_feature(*v_, edge_feature((j + n_ - 1) % n_), O, t_up_)
                        : near_feature(*v_, f, O, t_up_);
      // a sliver at a short edge: the longer edges beside it
      if (!ok) ok = tri_cert(-1, O, (i64)i, g_[i], (i64)((i + 1) % k), g_[(i + 1) % k]);
      if (!ok) return false;
    }
    return true;
  }

  // The zipper: the piece's ring path walked from its middle edge towards both ends at
  // once, the piece cut by rungs g_l -- g_r with a point M at each rung's middle (any
  // double: the chains telescope to the piece's boundary exactly). A step takes the
  // pentagon of the old rung (l, M, r), a boundary edge and the new rung in three
  // triangles; at the path's ends the rest (the cap: the curve points) is a fan from the
  // last M. Every triangle must turn counter-clockwise (or be flat) and lie within t_up of
  // one edge (tri_cert): a strip narrower than 2 t_up, which no triangulation of its
  // vertices alone certifies.
  bool zip_ok() {
    const i64 k = (i64)g_.size();
    i64 a0 = -1;  // the ring path: a0 .. b0 (cyclic), curve points after b0
    for (i64 i = 0; i < k && a0 < 0; ++i)
      if (gr_[i] < 0 && gr_[(i + 1) % k] >= 0) a0 = (i + 1) % k;
    if (a0 < 0) return false;
    i64 b0 = a0;
    while (gr_[(b0 + 1) % k] >= 0 && (b0 + 1) % k != a0) b0 = (b0 + 1) % k;
    const i64 len = (b0 - a0 + k) % k;
    auto mid = [](Pt a, Pt b) { return Pt{0.5 * a.x + 0.5 * b.x, 0.5 * a.y + 0.5 * b.y}; };
    auto d2 = [](Pt a, Pt b) { return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y); };
    i64 l = (a0 + len / 2) % k, r = l;
    Pt M = g_[l];
    if (len > 0) r = (l + 1) % k;
    while (l != a0 || r != b0) {
      const i64 l1 = (l + k - 1) % k, r1 = (r + 1) % k;
      const bool pref = r == b0 || (l != a0 && d2(g_[l1], g_[r]) <= d2(g_[l], g_[r1]));
      bool done = false;
      for (int side = 0; side < 2 && !done; ++side) {  // the shorter rung, else the other
        const bool left = side == 0 ? pref : !pref;
        if (left ? l == a0 : r == b0) break;
        if (left) {
          const Pt N = mid(g_[l1], g_[r]);
          done = tri_cert(l1, g_[l1], l, g_[l], -1, N) && tri_cert(l, g_[l], -1, M, -1, N) &&
                 tri_cert(-1, M, r, g_[r], -1, N);
          if (done) {
            l = l1;
            M = N;
          }
        } else {
          const Pt N = mid(g_[l], g_[r1]);
          done = tri_cert(r, g_[r], r1, g_[r1], -1, N) && tri_cert(-1, M, r, g_[r], -1, N) &&
                 tri_cert(l, g_[l], -1, M, -1, N);
          if (done) {
            r = r1;
            M = N;
          }
        }
      }
      if (!done) return false;
    }
    for (i64 t = len, i = b0; t < k; ++t, i = (i + 1) % k)  // the cap: edges b0 .. a0
      if (!tri_cert(-1, M, i, g_[i], (i + 1) % k, g_[(i + 1) % k])) return false;
    return true;
  }

  // A triangle of a piece's decomposition: corners (i, p) with i the point of g_ or -1
  // (an extra corner: a rung's middle); counter-clockwise or flat, and within t_up of one
  // edge: one that a corner is known to be near, or one beside those (tri_near).
  bool tri_cert(i64 i0, Pt p0, i64 i1, Pt p1, i64 i2, Pt p2) {
    const int o = orient(p0, p1, p2);
    if (o < 0) return false;
    if (o == 0) return true;
    const i64 id[3] = {i0, i1, i2};
    const Pt tp[3] = {p0, p1, p2};
    const i64 k = (i64)g_.size();
    i64 cand[18];
    int nc = 0;
    auto add = [&](i64 f) {
      if (f & 1) {
        cand[nc++] = edge_feature(f >> 1);
        cand[nc++] = edge_feature(((f >> 1) + n_ - 1) % n_);
      } else {
        cand[nc++] = f;
      }
    };
    for (int u = 0; u < 3; ++u) {
      const i64 y = id[u];
      if (y < 0) continue;
      if (gr_[y] >= 0) {
        add(vertex_feature(gr_[y]));
      } else {
        add(gp_[y]);
        add(gf_[y]);
        add(gf_[(y + k - 1) % k]);
      }
    }
    if (nc == 0) return false;
    std::sort(cand, cand + nc);
    nc = (int)(std::unique(cand, cand + nc) - cand);
    auto known = [&](int u, i64 e) {
      const i64 y = id[u];
      if (y < 0) return false;
      if (gr_[y] >= 0) return feature_in(vertex_feature(gr_[y]), e, n_);
      return feature_in(gp_[y], e, n_) || feature_in(gf_[y], e, n_) ||
             feature_in(gf_[(y + k - 1) % k], e, n_);
    };
    return tri_near(tp, cand, nc, known);
  }

  // Ear clipping (the ears chosen in float, each certified exactly): every triangle
  // counter-clockwise or flat and within t_up of the ring (tri_ok).
  bool ears_ok() {
    const i64 k = (i64)g_.size();
    if (k > PRUNE_EARS) return false;
    nx_.resize(k);
    pv_.resize(k);
    fa_.assign(k, -1);  // the neighbours with which an ear failed (it fails again)
    fc_.assign(k, -1);
    for (i64 i = 0; i < k; ++i) {
      nx_[i] = (i + 1) % k;
      pv_[i] = (i + k - 1) % k;
    }
    // first the ears of ring vertices only (the ring path), then any
    i64 left = k, i = 0;
    for (int phase = 0; phase < 2 && left > 3; ++phase) {
      for (i64 idle = 0; left > 3 && idle <= left;) {
        const i64 a = pv_[i], c = nx_[i];
        const bool ring = gr_[a] >= 0 && gr_[i] >= 0 && gr_[c] >= 0;
        bool ok = false;
        if ((phase == 1 || ring) && !(fa_[i] == a && fc_[i] == c)) {
          ok = ear(a, i, c) && tri_ok(a, i, c);
          if (!ok) {
            fa_[i] = a;
            fc_[i] = c;
          }
        }
        if (ok) {
          nx_[a] = c;
          pv_[c] = a;
          --left;
          idle = 0;
          i = a;
          continue;
        }
        i = c;
        ++idle;
      }
    }
    if (left > 3) return false;
    const i64 a = pv_[i], c = nx_[i];
    if (orient(g_[a], g_[i], g_[c]) < 0 || !tri_ok(a, i, c)) 
        return false;
    return true;
  }

  // b is an ear of the remaining polygon: a, b, c counter-clockwise (or flat) with no
  // other remaining point inside (float: a choice; tri_ok decides)
  bool ear(i64 a, i64 b, i64 c) const {
    const int o = orient(g_[a], g_[b], g_[c]);
    if (o < 0) return false;
    if (o == 0) return true;
    const Pt A = g_[a], B = g_[b], C = g_[c];
    auto side = [](Pt p, Pt q, Pt r) { return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x); };
    for (i64 j = nx_[c]; j != a; j = nx_[j]) {
      const Pt P = g_[j];
      if (side(A, B, P) >= 0 && side(B, C, P) >= 0 && side(C, A, P) >= 0) return false;
    }
    return true;
  }

  // Is the triangle of g_ points a, b, c within t_up of the ring (it is counter-clockwise
  // or flat)? All three within t_up of one edge (those at its points and of its
  // points' features), or, three ring vertices, a circumradius of at most t_up (the
  // disks of radius t_up at the vertices then cover it).
  bool tri_ok(i64 a, i64 b, i64 c) {
    if (orient(g_[a], g_[b], g_[c]) == 0) return true;
    if (gr_[a] >= 0 && gr_[b] >= 0 && gr_[c] >= 0 && circum_ok(g_[a], g_[b], g_[c], t_up_))
      return true;
    return tri_cert(a, g_[a], b, g_[b], c, g_[c]);
  }

  // Is every corner of the triangle tp within t_up of one ring edge within PRUNE_NEAR
  // edges of the features base (along the ring)? known(u, e): corner u is known to be
  // (exact checks otherwise, after a float look that skips the edges far from any corner)
  template <class Known>
  bool tri_near(const Pt* tp, const i64* base, int nb, Known&& known) {
    const double lim = t_up_ * t_up_ * (1 + 0x1p-20);
    for (i64 w = 0; w <= PRUNE_NEAR; ++w)
      for (int q = 0; q < nb; ++q)
        for (int sg = -1; sg <= 1; sg += 2) {
          if (w == 0 && sg == 1) continue;
          const i64 j0 = (base[q] >> 1) + sg * w;
          const i64 j = n_ > PRUNE_NEAR ? wrap(j0, n_) : (j0 % n_ + n_) % n_, e = edge_feature(j);
          bool all = true;
          for (int u = 0; u < 3 && all; ++u) all = known(u, e) || feature_d2(e, tp[u]) <= lim;
          if (!all) continue;
          for (int u = 0; u < 3 && all; ++u) all = known(u, e) || near_feature(*v_, e, tp[u], t_up_);
          if (all) return true;
        }
    return false;
  }

  // the circumradius of a, b, c at most t: |ab|^2 |bc|^2 |ca|^2 <= 4 t^2 cross^2
  static bool circum_ok(Pt a, Pt b, Pt c, double t) {
    return sign_of([&](auto z) {
             auto abx = num(z, b.x) - num(z, a.x), aby = num(z, b.y) - num(z, a.y);
             auto bcx = num(z, c.x) - num(z, b.x), bcy = num(z, c.y) - num(z, b.y);
             auto cax = num(z, a.x) - num(z, c.x), cay = num(z, a.y) - num(z, c.y);
             auto cr = abx * cay - aby * cax;
             auto tt = num(z, t);
             return (abx * abx + aby * aby) * (bcx * bcx + bcy * bcy) * (cax * cax + cay * cay) -
                    num(z, 4.0) * tt * tt * cr * cr;
           }) <= 0;
  }
};

// Segments of closed rings grouped into chains along which x strictly increases or
// decreases (vertical segments alone) and y does not turn back: two segments of one
// chain meet only when consecutive, and a chain's segments are in order along both
// axes. Reused: no allocation once grown.
struct Chains {
  std::vector<Pt> a, b;                // segment i runs a[i] -> b[i]
  std::vector<i64> start;              // chain c: segments start[c] .. start[c + 1] - 1
  std::vector<int> dx, dy;             // +1 / -1: increasing / decreasing along x, y
  std::vector<double> x0, x1, y0, y1;  // the chains' boxes

  void clear() {
    a.clear();
    b.clear();
    start.clear();
    dx.clear();
    dy.clear();
    x0.clear();
    x1.clear();
    y0.clear();
    y1.clear();
  }
  // The segments p[i] -> p[(i + 1) % n] of a closed ring.
  void add_ring(const Pt* p, i64 n) {
    for (i64 i = 0; i < n; ++i) {
      const Pt &u = p[i], &w = p[next_of(i, n)];
      const int sx = (w.x > u.x) - (w.x < u.x), sy = (w.y > u.y) - (w.y < u.y);
      if (i == 0 || sx == 0 || sx != dx.back() || (sy != 0 && dy.back() != 0 && sy != dy.back())) {
        start.push_back((i64)a.size());
        dx.push_back(sx);
        dy.push_back(0);
        x0.push_back(INFINITY);
        x1.push_back(-INFINITY);
        y0.push_back(INFINITY);
        y1.push_back(-INFINITY);
      }
      if (sy != 0) dy.back() = sy;
      a.push_back(u);
      b.push_back(w);
      x0.back() = std::min({x0.back(), u.x, w.x});
      x1.back() = std::max({x1.back(), u.x, w.x});
      y0.back() = std::min({y0.back(), u.y, w.y});
      y1.back() = std::max({y1.back(), u.y, w.y});
    }
  }
  i64 chains() const { return (i64)dx.size(); }
  i64 size(i64 c) const { return (c + 1 < chains() ? start[c + 1] : (i64)a.size()) - start[c]; }
  // the k-th segment of chain c in increasing x (along y: in increasing y)
  i64 seg(i64 c, i64 k, bool y) const {
    return (y ? dy[c] : dx[c]) >= 0 ? start[c] + k : start[c] + size(c) - 1 - k;
  }
  double lo(i64 i, bool y) const { return y ? std::min(a[i].y, b[i].y) : std::min(a[i].x, b[i].x); }
  double hi(i64 i, bool y) const { return y ? std::max(a[i].y, b[i].y) : std::max(a[i].x, b[i].x); }
};

// f(i, j) for the segments i of chain A of X and j of chain B of Y whose boxes come
// within w of each other: the chains halved while their parts' boxes (those of their
// end points: the chains are monotone along both axes) meet; false from f stops
// (returned).
template <class F>
inline bool chain_walk(const Chains& X, i64 A, const Chains& Y, i64 B, double w, F&& f) {
  struct Part {
    i64 a0, a1, b0, b1;  // segments [a0, a1) of X, [b0, b1) of Y (storage order)
  };
  auto meet = [&](const Part& q) {
    const Pt &p0 = X.a[q.a0], &p1 = X.b[q.a1 - 1], &q0 = Y.a[q.b0], &q1 = Y.b[q.b1 - 1];
    return std::max(p0.x, p1.x) + w >= std::min(q0.x, q1.x) &&
           std::max(q0.x, q1.x) >= std::min(p0.x, p1.x) - w &&
           std::max(p0.y, p1.y) + w >= std::min(q0.y, q1.y) &&
           std::max(q0.y, q1.y) >= std::min(p0.y, p1.y) - w;
  };
  Part stack[128];
  int top = 0;
  stack[top++] = Part{X.start[A], X.start[A] + X.size(A), Y.start[B], Y.start[B] + Y.size(B)};
  while (top > 0) {
    const Part q = stack[--top];
    if (!meet(q)) continue;
    const i64 la = q.a1 - q.a0, lb = q.b1 - q.b0;
    if (la <= 2 && lb <= 2) {
      for (i64 i = q.a0; i < q.a1; ++i)
        for (i64 j = q.b0; j < q.b1; ++j)
          if (!f(i, j)) return false;
      continue;
    }
    if (la >= lb) {
      const i64 m = q.a0 + la / 2;
      stack[top++] = Part{q.a0, m, q.b0, q.b1};
      stack[top++] = Part{m, q.a1, q.b0, q.b1};
    } else {
      const i64 m = q.b0 + lb / 2;
      stack[top++] = Part{q.a0, q.a1, q.b0, m};
      stack[top++] = Part{q.a0, q.a1, m, q.b1};
    }
  }
  return true;
}

// The proper crossings of a closed polyline's segments (pairs i < j, not consecutive) in
// `out`; false when two segments meet otherwise too (touch, overlap, a repeated point or
// a fold back): then the polyline is not simple whatever the pruning does. Pairs of
// chains whose boxes overlap are walked in x order; segments whose boxes overlap are
// decided exactly. With `first`, it stops at the first meeting (out then holds at most
// one pair).
inline bool curve_crossings(const std::vector<Pt>& p, std::vector<std::pair<i64, i64>>& out,
                            Chains& S, bool first = false) {
  out.clear();
  const i64 n = (i64)p.size();
  if (n < 3) return false;
  bool other = false;
  for (i64 i = 0; i < n; ++i) {
    const i64 i1 = next_of(i, n);
    const Pt &a = p[i], &b = p[i1], &c = p[next_of(i1, n)];
    if (a.x == b.x && a.y == b.y) return false;
    if (orient(a, b, c) == 0 && dot_sign(a, b, b, c) < 0) other = true;  // folds back
  }
  if (first && other) return false;
  S.clear();
  S.add_ring(p.data(), n);
  auto test = [&](i64 i, i64 j) {
    if (i > j) std::swap(i, j);
    if (j == i + 1 || (i == 0 && j == n - 1)) return true;  // consecutive: their common end
    const Pt &a = S.a[i], &b = S.b[i], &c = S.a[j], &d = S.b[j];
    if (std::max(a.y, b.y) < std::min(c.y, d.y) || std::max(c.y, d.y) < std::min(a.y, b.y))
      return true;
    const int o1 = orient(a, b, c), o2 = orient(a, b, d);
    if (o1 * o2 > 0) return true;
    const int o3 = orient(c, d, a), o4 = orient(c, d, b);
    if (o3 * o4 > 0) return true;
    if (o1 * o2 < 0 && o3 * o4 < 0) {
      out.emplace_back(i, j);
      return !first;
    }
    if (o1 == 0 && o2 == 0) {  // collinear: they meet when their extents overlap
      auto key = [&](const Pt& q) { return a.x != b.x ? q.x : q.y; };
      const double s0 = std::min(key(a), key(b)), s1 = std::max(key(a), key(b));
      const double t0 = std::min(key(c), key(d)), t1 = std::max(key(c), key(d));
      if (t0 > s1 || s0 > t1) return true;
    }
    other = true;
    return !first;
  };
  box_pairs(S.chains(), S.x0.data(), S.x1.data(), S.y0.data(), S.y1.data(),
            [&](i64 A, i64 B) { return chain_walk(S, A, S, B, 0.0, test); });
  return !other;
}

}  // namespace off
}  // namespace mk
