// polygon.hpp -- exact validity checks of polygons with holes, and the planar structure
// (points, boundary edges, a monotone partition) that triangulate.hpp builds on.
//
// Input: float64 coordinates (N, 2), ring offsets (R + 1) into them and polygon offsets
// (P + 1) into the rings; the first ring of a polygon is its shell, the others its
// holes. Rings come in any orientation, with or without a closing repeat; consecutive
// duplicate vertices are dropped.
//
// A polygon is valid when
//  * each ring has >= 3 distinct vertices and does not lie on one line,
//  * each ring is simple: two edges meet only when they are consecutive, and then only
//    at their shared vertex (a spike doubling back is an overlap),
//  * rings of the polygon do not cross and share no segment; they may touch at isolated
//    points (a hole touching the shell at two points is valid: CGAL accepts it, GEOS
//    calls its interior "disconnected"),
//  * every hole lies inside the shell (closed) and the holes' interiors are disjoint.
// Polygons of a collection are not checked against each other unless asked
// (check_disjoint: then they may touch at points, as in a valid MultiPolygon).
//
// Every decision is an exact sign: lexicographic comparisons of coordinates and
// orient(a, b, c) = sign((b - a) x (c - a)) through mk::cross_sign (degree 2, exact for
// all finite doubles, subnormals to DBL_MAX). Nothing computes a new coordinate.
//
// How (per polygon, n vertices):
//  1. rings: drop consecutive duplicates, count distinct vertices, test collinearity;
//     the orientation of a ring is the turn at its lowest vertex (straight there means
//     the ring doubles back);
//  2. points: equal coordinates become one point; points are numbered in (y, x) order;
//  3. one plane sweep over the points in that order (the sweep line tilted infinitely
//     little, so equal y's are no special case) with a balanced tree (std::set) of the
//     edges it meets, ordered by orient. At each point v:
//     - the edges through v are one run of the tree (an equal_range): those ending at
//       v, and those passing through it -- a vertex of another ring touching the inside
//       of an edge (a T-junction: the edge is split at v) or of the same ring (invalid);
//     - two corners of one ring at v: the ring touches itself; two edges leaving v in
//       one direction: a spike (same ring) or rings sharing a segment; around v the
//       edges must alternate out, in, out, in counter-clockwise (rings oriented with the
//       interior on their left), else two rings cross at v;
//     - every pair of edges that becomes adjacent in the tree is tested for a proper
//       crossing (Shamos & Hoey 1976): the first crossing in sweep order is always found
//       this way, before the tree's order could be wrong;
//     - the regions between consecutive edges must alternate outside / inside, i.e. the
//       winding number is 0 or 1 everywhere: holes inside the shell, none inside another;
//     - the diagonals of a monotone partition are recorded (de Berg et al., Computational
//       Geometry, ch. 3), generalized to points where several edges meet: each region
//       between two edges keeps a helper (its last point) and whether it is a merge.
//  The first problem in sweep order is reported, with the ring and the caller's vertex
//  that starts the offending edge. Time O((n + t) log n) for t T-junctions, memory O(n).
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

#include "exact.hpp"

namespace mk {
namespace polygon {

struct Problem {
  int status = OK;  // Status
  int reason = 0;   // Invalid (for INVALID_POLYGON)
  i64 ring = -1;    // global ring index
  i64 vertex = -1;  // index inside that ring, in the caller's numbering
  bool ok() const { return status == OK; }
};

// One group of rings (a polygon, or every polygon of a collection for check_disjoint)
// turned into points, boundary edges and a monotone partition.
template <class T>
struct Work {
  const T* xy;
  const i64* ring_off;
  int cross_reason = 0;  // nonzero: every problem between rings is reported with it

  // rings of the group
  std::vector<i64> rings;           // global ring index
  std::vector<std::uint8_t> shell;  // 1 for a shell
  std::vector<i64> rfirst;          // first corner of each ring (rfirst[nr] = #corners)
  std::vector<int> rorient;         // +1: the ring as given is counter-clockwise, -1: clockwise

  // corners: ring vertices without consecutive duplicates, in the caller's order
  std::vector<i64> corig;  // input index (the last of a run of duplicates)
  std::vector<i64> cmin;   // the smallest input index of that run
  std::vector<i64> cring;  // ring (index into rings)
  std::vector<i64> cpoint;

  // points: distinct coordinates, numbered in (y, x) order
  std::vector<i64> prep;            // input index of the point (the smallest one)
  std::vector<i64> pc_off, pc;      // corners at each point (CSR)

  // boundary edges, directed with the interior on the left; split at T-junctions
  std::vector<i64> efrom, eto, ecorner;  // ecorner: the caller's edge it lies on

  std::vector<std::pair<i64, i64>> diags;  // monotone partition (point ids)
  bool disconnected = false;               // touching rings split the interior

  Work(const T* xy_, const i64* ring_off_) : xy(xy_), ring_off(ring_off_) {}

  // --- primitives on input indices ---------------------------------------------------
  T X(i64 i) const { return xy[2 * i]; }
  T Y(i64 i) const { return xy[2 * i + 1]; }
  bool same(i64 i, i64 j) const { return X(i) == X(j) && Y(i) == Y(j); }
  bool lexless(i64 i, i64 j) const { return Y(i) < Y(j) || (Y(i) == Y(j) && X(i) < X(j)); }
  int orient(i64 a, i64 b, i64 c) const {
    return mk::orient(X(a), Y(a), X(b), Y(b), X(c), Y(c));
  }
  // orient on point ids; a repeated point is straight at once (the filter cannot certify
  // an exact zero: the exact fallback would decide every "v is an end of e")
  int orient_p(i64 a, i64 b, i64 c) const {
    if (c == a || c == b || a == b) return 0;
    return orient(prep[a], prep[b], prep[c]);
  }
  // direction p -> a before p -> b counter-clockwise from +x (a, b off p, not aligned)
  bool ccw_before(i64 p, i64 a, i64 b) const {
    bool ua = lexless(p, a), ub = lexless(p, b);
    if (ua != ub) return ua;
    return orient(p, a, b) > 0;
  }
  i64 cnext(i64 c) const {
    i64 r = cring[c];
    return c + 1 < rfirst[r + 1] ? c + 1 : rfirst[r];
  }
  i64 cprev(i64 c) const {
    i64 r = cring[c];
    return c > rfirst[r] ? c - 1 : rfirst[r + 1] - 1;
  }
  i64 nrings() const { return (i64)rings.size(); }
  i64 npoints() const { return (i64)prep.size(); }
  i64 nedges() const { return (i64)efrom.size(); }
  i64 ering(i64 e) const { return cring[ecorner[e]]; }

  Problem problem(int reason, i64 corner) const {
    Problem pr;
    pr.status = INVALID_POLYGON;
    pr.reason = reason;
    pr.ring = rings[cring[corner]];
    pr.vertex = corig[corner] - ring_off[pr.ring];
    return pr;
  }
  Problem between_rings(int reason, i64 corner) const {
    return problem(cross_reason ? cross_reason : reason, corner);
  }

  // --- 1. rings ----------------------------------------------------------------------
  Problem add_ring(i64 r, bool is_shell) {
    const i64 s = ring_off[r], e = ring_off[r + 1];
    const i64 lr = nrings();
    const i64 first = (i64)corig.size();
    rings.push_back(r);
    shell.push_back(is_shell ? 1 : 0);
    rfirst.push_back(first);
    for (i64 i = s; i < e; ++i) {
      i64 nx = i + 1 < e ? i + 1 : s;
      if (!same(i, nx)) {
        corig.push_back(i);
        cring.push_back(lr);
      }
    }
    const i64 m = (i64)corig.size() - first;
    for (i64 k = 0; k < m; ++k) cmin.push_back(k == 0 ? s : corig[first + k - 1] + 1);
    Problem pr;
    if (m < 3) {
      pr.status = INVALID_POLYGON;
      pr.reason = RING_FEW_VERTICES;
      pr.ring = r;
      pr.vertex = 0;
      return pr;
    }
    const i64 a = corig[first], b = corig[first + 1];
    for (i64 k = 2; k < m; ++k)
      if (orient(a, b, corig[first + k]) != 0) return pr;
    pr.status = INVALID_POLYGON;
    pr.reason = RING_NO_AREA;
    pr.ring = r;
    pr.vertex = 0;
    return pr;
  }
  void close_rings() { rfirst.push_back((i64)corig.size()); }

  // The turn at the lowest vertex: both neighbours lie above it, so a straight turn
  // means they lie on one ray -- the ring doubles back.
  Problem orient_rings() {
    rorient.assign(nrings(), 0);
    for (i64 r = 0; r < nrings(); ++r) {
      i64 best = rfirst[r];
      for (i64 c = rfirst[r] + 1; c < rfirst[r + 1]; ++c)
        if (lexless(corig[c], corig[best])) best = c;
      int s = orient(corig[cprev(best)], corig[best], corig[cnext(best)]);
      if (s == 0) return problem(RING_SPIKE, best);
      rorient[r] = s;
    }
    return Problem();
  }

  // --- 2. points and edges -----------------------------------------------------------
  void make_points() {
    const i64 nc = (i64)corig.size();
    pc.resize(nc);
    std::iota(pc.begin(), pc.end(), i64(0));
    std::sort(pc.begin(), pc.end(), [&](i64 a, i64 b) {
      i64 ia = corig[a], ib = corig[b];
      if (lexless(ia, ib)) return true;
      if (lexless(ib, ia)) return false;
      return a < b;
    });
    cpoint.assign(nc, -1);
    prep.clear();
    pc_off.clear();
    for (i64 t = 0; t < nc; ++t) {
      i64 c = pc[t];
      if (t == 0 || !same(corig[pc[t - 1]], corig[c])) {
        prep.push_back(cmin[c]);
        pc_off.push_back(t);
      }
      cpoint[c] = npoints() - 1;
      prep.back() = std::min(prep.back(), cmin[c]);
    }
    pc_off.push_back(nc);
  }

  void make_edges() {
    const i64 nc = (i64)corig.size();
    efrom.resize(nc);
    eto.resize(nc);
    ecorner.resize(nc);
    for (i64 c = 0; c < nc; ++c) {
      const i64 a = cpoint[c], b = cpoint[cnext(c)];
      const i64 r = cring[c];
      const bool flip = (rorient[r] > 0) != (shell[r] != 0);
      efrom[c] = flip ? b : a;
      eto[c] = flip ? a : b;
      ecorner[c] = c;
    }
  }

  // incidence (CSR) of the boundary edges at each point (kept up to date by the splits)
  std::vector<i64> ioff, iedge;
  void make_incidence() {
    const i64 np = npoints(), ne = nedges();
    ioff.assign(np + 1, 0);
    for (i64 e = 0; e < ne; ++e) {
      ++ioff[efrom[e] + 1];
      ++ioff[eto[e] + 1];
    }
    for (i64 p = 0; p < np; ++p) ioff[p + 1] += ioff[p];
    iedge.assign(2 * ne, 0);
    std::vector<i64> fill(ioff.begin(), ioff.end() - 1);
    for (i64 e = 0; e < ne; ++e) {
      iedge[fill[efrom[e]]++] = e;
      iedge[fill[eto[e]]++] = e;
    }
  }

  // the corner at point p of ring r (or -1)
  i64 corner_of_ring(i64 p, i64 r) const {
    for (i64 k = pc_off[p]; k < pc_off[p + 1]; ++k)
      if (cring[pc[k]] == r) return pc[k];
    return -1;
  }
  // a corner at p to blame: of the ring with the highest index (a hole rather than the
  // shell), among those given, else any
  i64 blame(i64 p, const std::vector<i64>& edges) const {
    i64 best = -1;
    for (i64 k = pc_off[p]; k < pc_off[p + 1]; ++k) {
      i64 c = pc[k];
      bool listed = edges.empty();
      for (i64 e : edges) listed = listed || ering(e) == cring[c];
      if (listed && (best < 0 || cring[c] > cring[best])) best = c;
    }
    if (best < 0) best = pc[pc_off[p]];
    return best;
  }
  // the corner that starts the caller's edge that e lies on
  i64 edge_corner(i64 e) const { return ecorner[e]; }

  // --- 3. the sweep ------------------------------------------------------------------
  // Status: the edges met by the sweep line, left to right, by id; elo / ehi: the lower
  // and upper end (point ids). The region right of an edge is inside exactly when the
  // edge runs downward.
  std::vector<i64> elo, ehi;
  struct PointKey {
    i64 p;
  };
  struct Cmp {
    using is_transparent = void;
    const Work* w;
    bool operator()(i64 a, i64 b) const {  // a left of b (both met by the sweep line)
      if (a == b) return false;
      const i64 la = w->elo[a], lb = w->elo[b];
      if (la == lb) return w->orient_p(la, w->ehi[b], w->ehi[a]) > 0;
      if (la > lb) {
        int s = w->orient_p(lb, w->ehi[b], la);
        if (s != 0) return s > 0;
        return w->orient_p(lb, w->ehi[b], w->ehi[a]) > 0;
      }
      int s = w->orient_p(la, w->ehi[a], lb);
      if (s != 0) return s < 0;
      return w->orient_p(la, w->ehi[a], w->ehi[b]) < 0;
    }
    bool operator()(i64 e, PointKey v) const {  // e left of v
      return w->orient_p(w->elo[e], w->ehi[e], v.p) < 0;
    }
    bool operator()(PointKey v, i64 e) const {  // v left of e
      return w->orient_p(w->elo[e], w->ehi[e], v.p) > 0;
    }
  };

  // the interiors of a and b cross at one point
  bool cross_properly(i64 a, i64 b) const {
    int o1 = orient_p(elo[a], ehi[a], elo[b]), o2 = orient_p(elo[a], ehi[a], ehi[b]);
    if (o1 * o2 >= 0) return false;
    int o3 = orient_p(elo[b], ehi[b], elo[a]), o4 = orient_p(elo[b], ehi[b], ehi[a]);
    return o3 * o4 < 0;
  }
  Problem crossing(i64 a, i64 b) const {
    i64 ca = edge_corner(a), cb = edge_corner(b);
    i64 c = cring[ca] > cring[cb] || (cring[ca] == cring[cb] && ca > cb) ? ca : cb;
    if (cring[ca] == cring[cb]) return problem(RING_CROSSES, c);
    return between_rings(RINGS_CROSS, c);
  }

  // The state of sweep() that its steps share.
  struct SweepState {
    std::vector<std::uint8_t> down;      // per edge: it runs from its upper end down
    std::vector<i64> helper, mark, uf;   // monotone-partition helpers, marks, ring union-find
    std::vector<std::uint8_t> is_merge;  // per edge: its helper is a merge vertex
    std::vector<i64> lows, upper, ring_seen;  // per point: edges through / leaving it
  };

  // sweep() at point v: the edges of S.lows passing through v (not ending there) are
  // split at v, unless their ring passes through v twice or has a corner there
  Problem split_through(i64 v, SweepState& S, i64& ne) {
    auto &down = S.down, &is_merge = S.is_merge;
    auto &helper = S.helper, &mark = S.mark, &lows = S.lows, &upper = S.upper;
    auto& ring_seen = S.ring_seen;
    ring_seen.clear();
    for (i64 e : lows) {
      if (mark[e] == v) continue;
      const i64 r = ering(e);
      for (i64 q : ring_seen)  // the ring passes through v twice: it crosses itself
        if (ering(q) == r) return problem(RING_CROSSES, std::max(ecorner[q], ecorner[e]));
      ring_seen.push_back(e);
      const i64 c = corner_of_ring(v, r);
      if (c >= 0) {
        // the ring runs back over itself (a spike) or touches one of its edges
        if (cnext(ecorner[e]) == cprev(c)) return problem(RING_SPIKE, cprev(c));
        if (ecorner[e] == cnext(c)) return problem(RING_SPIKE, cnext(c));
        return problem(RING_TOUCHES, c);
      }
      // e keeps its lower part (it ends at v), a new edge f takes the upper part
      const i64 f = ne++;
      const bool dn = down[e];
      const i64 top = ehi[e];
      efrom.push_back(dn ? top : v);
      eto.push_back(dn ? v : top);
      ecorner.push_back(ecorner[e]);
      if (dn) {
        efrom[e] = v;
      } else {
        eto[e] = v;
      }
      ehi[e] = v;
      elo.push_back(v);
      ehi.push_back(top);
      down.push_back(dn);
      helper.push_back(-1);
      is_merge.push_back(0);
      mark.push_back(-1);
      mark[e] = v;
      for (i64 q = ioff[top]; q < ioff[top + 1]; ++q)
        if (iedge[q] == e) iedge[q] = f;
      upper.push_back(f);
    }
    return Problem();
  }

  // sweep() at a point v where more than two edges meet: out, in, out, in counter-
  // clockwise (upper edges right to left, then the edges that ended here left to right);
  // the rings touching here join in S.uf (a cycle means the interior is disconnected)
  Problem around(i64 v, SweepState& S) {
    auto &uf = S.uf, &lows = S.lows, &upper = S.upper, &ring_seen = S.ring_seen;
    auto find = [&](i64 a) {
      while (uf[a] != a) {
        uf[a] = uf[uf[a]];
        a = uf[a];
      }
      return a;
    };
    std::vector<i64> ccw(upper.rbegin(), upper.rend());
    ccw.insert(ccw.end(), lows.begin(), lows.end());
    const i64 d = (i64)ccw.size();
    for (i64 t = 0; t < d; ++t) {
      const i64 a = ccw[t], b = ccw[(t + 1) % d];
      if ((efrom[a] == v) != (efrom[b] == v)) continue;
      return between_rings(RINGS_CROSS, blame(v, std::vector<i64>{a, b}));
    }
    ring_seen.clear();
    for (i64 e : ccw) ring_seen.push_back(ering(e));
    std::sort(ring_seen.begin(), ring_seen.end());
    ring_seen.erase(std::unique(ring_seen.begin(), ring_seen.end()), ring_seen.end());
    // a cycle in the graph of rings and their touching points splits the interior
    const i64 r0 = find(ring_seen[0]);
    for (std::size_t t = 1; t < ring_seen.size(); ++t) {
      i64 rt = find(ring_seen[t]);
      if (rt == r0) {
        disconnected = true;
      } else {
        uf[rt] = r0;
      }
    }
    return Problem();
  }

  // sweep() at point v, k edges ending and m leaving, between status edges A and ek:
  // the diagonals of the monotone partition
  void partition(i64 v, i64 k, i64 m, i64 A, i64 ek, bool RLin, bool RRin, SweepState& S) {
    auto &helper = S.helper;
    auto& is_merge = S.is_merge;
    if (k == 0) {
      if (RLin) {  // v splits the region (A, B): connect it below
        diags.emplace_back(v, helper[A]);
        helper[A] = v;
        is_merge[A] = 0;
      }
    } else if (m == 0) {
      if (RLin) {  // the regions left and right of v merge above it
        if (is_merge[A]) diags.emplace_back(v, helper[A]);
        if (is_merge[ek]) diags.emplace_back(v, helper[ek]);
        helper[A] = v;
        is_merge[A] = 1;
      }
    } else {
      if (RLin) {
        if (is_merge[A]) diags.emplace_back(v, helper[A]);
        helper[A] = v;
        is_merge[A] = 0;
      }
      if (RRin && is_merge[ek]) diags.emplace_back(v, helper[ek]);
    }
  }

  Problem sweep() {
    const i64 np = npoints();
    i64 ne = nedges();
    elo.resize(ne);
    ehi.resize(ne);
    std::vector<std::uint8_t> down(ne);
    for (i64 e = 0; e < ne; ++e) {
      elo[e] = std::min(efrom[e], eto[e]);
      ehi[e] = std::max(efrom[e], eto[e]);
      down[e] = efrom[e] > eto[e];
    }
    using Set = std::set<i64, Cmp>;
    Set status(Cmp{this});
    SweepState S;
    S.down = std::move(down);
    S.helper.assign(ne, -1);
    S.is_merge.assign(ne, 0);
    S.mark.assign(ne, -1);
    S.uf.resize(nrings());
    std::iota(S.uf.begin(), S.uf.end(), i64(0));
    auto &helper = S.helper, &mark = S.mark, &lows = S.lows, &upper = S.upper;
    auto& is_merge = S.is_merge;
    const auto& dn = S.down;
    diags.clear();
    auto inside_right = [&](i64 x) { return x >= 0 && dn[x]; };
    auto inside_left = [&](i64 y) { return y >= 0 && !dn[y]; };

    for (i64 v = 0; v < np; ++v) {
      // two corners of one ring here: the ring touches itself
      for (i64 k = pc_off[v] + 1; k < pc_off[v + 1]; ++k)
        for (i64 q = pc_off[v]; q < k; ++q)
          if (cring[pc[k]] == cring[pc[q]]) return problem(RING_TOUCHES, std::max(pc[k], pc[q]));
      upper.clear();
      i64 nlower = 0;
      for (i64 k = ioff[v]; k < ioff[v + 1]; ++k) {
        i64 e = iedge[k];
        if (ehi[e] == v) {
          mark[e] = v;
          ++nlower;
        } else {
          upper.push_back(e);
        }
      }
      // the edges through v: one run of the status
      auto range = status.equal_range(PointKey{v});
      lows.clear();
      for (auto it = range.first; it != range.second; ++it) lows.push_back(*it);
      i64 marked = 0;
      for (i64 e : lows) marked += mark[e] == v;
      if (marked != nlower) {  // unreachable unless a crossing went unseen
        return between_rings(RINGS_CROSS, blame(v, lows));
      }
      const i64 A = range.first == status.begin() ? -1 : *std::prev(range.first);
      auto itB = range.second;
      const i64 B = itB == status.end() ? -1 : *itB;
      const i64 k = (i64)lows.size();
      // edges passing through v: same ring -> invalid; another ring -> split at v
      if (Problem pr = split_through(v, S, ne); !pr.ok()) return pr;
      // regions between edges ending at v close here
      for (i64 t = 0; t + 1 < k; ++t)
        if (dn[lows[t]] && is_merge[lows[t]]) diags.emplace_back(v, helper[lows[t]]);
      const i64 ek = k > 0 ? lows[k - 1] : -1;
      const bool RLin = inside_right(A);
      const bool RRin = k > 0 ? inside_right(ek) : RLin;
      status.erase(range.first, range.second);
      // the edges leaving v, left to right
      const i64 m = (i64)upper.size();
      if (m > 1) {
        std::sort(upper.begin(), upper.end(),
                  [&](i64 a, i64 b) { return orient_p(v, ehi[b], ehi[a]) > 0; });
        for (i64 t = 0; t + 1 < m; ++t) {
          if (orient_p(v, ehi[upper[t]], ehi[upper[t + 1]]) != 0) continue;
          // two edges leave v in one direction
          const i64 a = upper[t], b = upper[t + 1];
          if (ering(a) == ering(b)) return problem(RING_SPIKE, corner_of_ring(v, ering(a)));
          return between_rings(RINGS_OVERLAP, blame(v, std::vector<i64>{a, b}));
        }
      }
      // around v: out, in, out, in counter-clockwise; and which rings touch here
      if (k + m > 2)
        if (Problem pr = around(v, S); !pr.ok()) return pr;
      // edges that become neighbours must not cross (Shamos-Hoey)
      if (m == 0) {
        if (A >= 0 && B >= 0 && cross_properly(A, B)) return crossing(A, B);
      } else {
        if (A >= 0 && cross_properly(A, upper[0])) return crossing(A, upper[0]);
        if (B >= 0 && cross_properly(upper[m - 1], B)) return crossing(upper[m - 1], B);
      }
      // the winding number stays 0 or 1: inside and outside alternate across edges
      {
        i64 left = A;
        for (i64 t = 0; t <= m; ++t) {
          i64 right = t < m ? upper[t] : B;
          if (inside_right(left) != inside_left(right)) return containment(v, left, right);
          left = right;
        }
      }
      partition(v, k, m, A, ek, RLin, RRin, S);  // the monotone partition
      for (i64 f : upper) {
        if (dn[f]) {
          helper[f] = v;
          is_merge[f] = 0;
        }
        status.emplace_hint(itB, f);
      }
    }
    return Problem();
  }

  // The winding number would leave {0, 1} between edges `left` and `right` at point v
  // (no crossing found so far). A simple ring has winding number 0 or 1 around every
  // point: when only one ring bounds the region, or only the shell, that ring crosses
  // itself farther on; else a hole lies outside the shell or inside another hole.
  Problem containment(i64 v, i64 left, i64 right) const {
    const i64 e = right >= 0 ? right : left;
    const i64 r = ering(e);
    i64 c = corner_of_ring(v, r);
    if (c < 0) c = edge_corner(e);
    if (cross_reason) return problem(cross_reason, c);
    const bool one_ring = left < 0 || right < 0 || ering(left) == ering(right);
    if (one_ring && (shell[r] || (left >= 0 && right >= 0))) return problem(RING_CROSSES, c);
    if (shell[r]) return problem(HOLE_OUTSIDE, c);  // a hole encloses the shell
    const i64 hole = shell[r] ? ering(left) : r;
    const i64 ch = corner_of_ring(v, hole) >= 0 ? corner_of_ring(v, hole) : c;
    bool in_hole = left >= 0 && !shell[ering(left)] && ering(left) != hole;
    return problem(in_hole ? HOLE_IN_HOLE : HOLE_OUTSIDE, ch);
  }

  // all steps for the rings already added (after close_rings)
  Problem run() {
    Problem pr = orient_rings();
    if (!pr.ok()) return pr;
    make_points();
    make_edges();
    make_incidence();
    return sweep();
  }
};

// Finite coordinates; the first non-finite one as NONFINITE with its ring and vertex.
template <class T>
Problem check_finite(const T* xy, const i64* ring_off, i64 R) {
  for (i64 r = 0; r < R; ++r)
    for (i64 i = ring_off[r]; i < ring_off[r + 1]; ++i)
      if (!(xy[2 * i] - xy[2 * i] == 0) || !(xy[2 * i + 1] - xy[2 * i + 1] == 0)) {
        Problem pr;
        pr.status = NONFINITE;
        pr.ring = r;
        pr.vertex = i - ring_off[r];
        return pr;
      }
  return Problem();
}

// The sweep of polygon p (its shell and holes) into w: the problem it finds, if any.
template <class T>
Problem sweep_polygon(Work<T>& w, const i64* poly_off, i64 p) {
  for (i64 r = poly_off[p]; r < poly_off[p + 1]; ++r) {
    Problem pr = w.add_ring(r, r == poly_off[p]);
    if (!pr.ok()) return pr;
  }
  w.close_rings();
  return w.run();
}

// Validate the polygons; orient[r] = +1 / -1 for a ring given counter-clockwise /
// clockwise (0 where not reached), disconnected[p] for a valid polygon whose interior
// touching rings split into parts. With check_disjoint, the polygons must also have
// disjoint interiors (they may touch at points).
template <class T>
Problem check(const T* xy, const i64* ring_off, i64 R, const i64* poly_off, i64 P,
              bool check_disjoint, int* orient, std::uint8_t* disconnected) {
  Problem pr = check_finite(xy, ring_off, R);
  if (!pr.ok()) return pr;
  for (i64 r = 0; r < R; ++r) orient[r] = 0;
  for (i64 p = 0; p < P; ++p) {
    disconnected[p] = 0;
    Work<T> w(xy, ring_off);
    pr = sweep_polygon(w, poly_off, p);
    if (!pr.ok()) return pr;
    for (i64 lr = 0; lr < w.nrings(); ++lr) orient[w.rings[lr]] = w.rorient[lr];
    disconnected[p] = w.disconnected ? 1 : 0;
  }
  if (check_disjoint && P > 1) {
    Work<T> w(xy, ring_off);
    w.cross_reason = POLYGONS_OVERLAP;
    for (i64 p = 0; p < P; ++p)
      for (i64 r = poly_off[p]; r < poly_off[p + 1]; ++r) w.add_ring(r, r == poly_off[p]);
    w.close_rings();
    pr = w.run();
    if (!pr.ok()) return pr;
  }
  return Problem();
}

}  // namespace polygon
}  // namespace mk
