// offset_resolve.hpp -- the region of an offset curve with a few crossings, exactly as the
// overlay gives it, without the overlay (see offset.hpp, which includes it; include that).
//
// After the pruning (offset_prune.hpp) a curve often keeps a few proper crossings: a
// loop whose piece no certificate covers, a shrink that splits a part. The overlay would
// sort, node and sweep the whole curve for them (on a 400-point curve with 3 crossings,
// about 250 us). With one closed curve whose segments meet only in k <= RESOLVE_MAX
// proper crossings (ordered along each segment by exact comparisons), the arrangement
// is known without a sweep: the curve splits at the crossings into 2k arcs, and walking it once from its
// least (x, y) point -- on the unbounded face, so the winding number on its outer side is
// 0 -- gives the winding number on each arc's sides (passing a crossing along segment s,
// both sides of s cross segment o: the winding changes by w * sign(dir o x dir s), w the
// curve's weight, +1 for a grow, -1 for a shrink). An arc bounds the region
// {w * winding >= 1} when exactly one of its sides is in it: right side 0 for a grow
// (kept forwards), 1 for a shrink (kept backwards, the inside on the left). Arcs join at
// crossings into rings.
//
// The rings are then those of Overlay::run(.., UNION, ..) step for step (overlay.hpp
// step 6 and overlay_round.hpp): vertices where the ring goes straight on dropped (the
// turn between the lines of its two pieces: a curve point's two segments), each ring's
// orientation the turn at its lowest vertex in the sweep order (Geo::vcmp, exact), the
// crossings rounded by Geo::round_vertex (the overlay's rounding, certified or exact),
// each ring started at its least rounded vertex, rings in the order of those, holes after
// their exterior, and the same check after rounding (finish_rounded_impl, which re-nodes
// rounded rings that came out invalid). Whatever the overlay would decide from its
// internal numbering is refused instead (false: the caller runs the overlay): a crossing
// where the boundary meets itself (four boundary arcs), three segments through one point,
// two rings whose least rounded vertices are equal, a ring whose least rounded vertex is
// repeated, holes with several exteriors. tests/test_offset_resolve.py compares the two
// on hypothesis cases and named ones, vertex for vertex.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "exact.hpp"
#include "offset_curve.hpp"
#include "overlay.hpp"

namespace mk {
namespace off {

// the most crossings the resolver takes (more go to the overlay)
constexpr i64 RESOLVE_MAX = 64;

class Resolver {
 public:
  // The region {w * winding >= 1} of the closed curve p (w = +1 for a grow, -1 for a
  // shrink) whose segments meet only in the proper crossings `cross` (pairs of segment
  // indices, segment i from p[i] to p[i + 1]) into out, as the overlay gives it; false
  // (out undefined) when the resolver does not take the case.
  bool run(const std::vector<Pt>& p, const std::vector<std::pair<i64, i64>>& cross, bool grow,
           ov::Rings& out) {
    const i64 m = (i64)p.size(), k = (i64)cross.size();
    if (k == 0 || k > RESOLVE_MAX || m < 4) return false;
    p_ = &p;
    m_ = m;
    const int w = grow ? 1 : -1;
    geo(cross);
    if (!occurrences(cross, w)) return false;
    if (!arcs(w)) return false;
    if (!rings(grow)) return false;
    return assemble(out);
  }

 private:
  struct Occ {
    i64 seg, c;  // crossing c on segment seg
    int delta;   // the change of the winding number along seg at the crossing
    i64 line;    // the line of seg in g_
  };
  const std::vector<Pt>* p_ = nullptr;
  i64 m_ = 0;
  std::vector<Occ> occ_;       // by segment, rotated to start at the least point's segment
  std::vector<int> wr_;        // arc t (occurrence t to t + 1): winding on its right
  std::vector<i64> out_, in_;  // per crossing: the boundary arc leaving / entering it
  std::vector<char> sel_, used_;
  // rings: vertex ids (curve point i >= 0, crossing c as -1 - c), their in/out segments
  std::vector<i64> rv_, rin_, rout_, roff_;
  std::vector<char> ccw_;
  ov::Geo g_;
  std::vector<i64> cvert_;  // crossing c -> its vertex in g_
  std::vector<i64> cl_;     // crossing c -> the lines of its two segments in g_

  Pt pt(i64 i) const { return (*p_)[wrap(i, m_)]; }  // -m <= i < 2m

  // The occurrences of the crossings along the curve from the segment of its least
  // point, each with its change of the winding number; those on one segment in order
  // along it (exactly: Geo::along); false when two coincide (three segments through one
  // point).
  bool occurrences(const std::vector<std::pair<i64, i64>>& cross, int w) {
    occ_.clear();
    const i64 k = (i64)cross.size();
    for (i64 c = 0; c < k; ++c) {
      const i64 a = cross[c].first, b = cross[c].second;
      if (a < 0 || b < 0 || a >= m_ || b >= m_) return false;
      occ_.push_back(Occ{a, c, w * delta(b, a), cl_[2 * c]});
      occ_.push_back(Occ{b, c, w * delta(a, b), cl_[2 * c + 1]});
    }
    bool tie = false;
    std::sort(occ_.begin(), occ_.end(), [&](const Occ& x, const Occ& y) {
      if (x.seg != y.seg) return x.seg < y.seg;
      if (x.c == y.c) return false;
      const int s = g_.along(x.line, cvert_[x.c], cvert_[y.c]);
      tie = tie || s == 0;
      return s < 0;
    });
    if (tie) return false;
    const i64 h = least_point(*p_);
    std::size_t t0 = 0;
    while (t0 < occ_.size() && occ_[t0].seg < h) ++t0;
    std::rotate(occ_.begin(), occ_.begin() + (std::ptrdiff_t)(t0 % occ_.size()), occ_.end());
    // the winding on the right of segment h at p[h]: p[h] is extreme, so the side of the
    // wider angle there is the unbounded face (0); o = 0 is a fold back (never here)
    const int o = orient(pt(h - 1), pt(h), pt(h + 1));
    if (o == 0) return false;
    wr0_ = o > 0 ? 0 : -w;
    return true;
  }
  int wr0_ = 0;

  // sign of dir(o) x dir(s): +1 when segment o crosses s from s's left to its right,
  // i.e. moving along s one passes from o's right to its left
  int delta(i64 o, i64 s) const {
    const Pt a = pt(o), b = pt(o + 1), c = pt(s), d = pt(s + 1);
    return cross_sign(a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y);
  }

  // The winding on each arc's right, the boundary arcs, and at each crossing the one
  // leaving and the one entering it (false when a crossing has two or none of one kind
  // but the other: the boundary would meet itself there).
  bool arcs(int w) {
    const i64 na = (i64)occ_.size(), k = na / 2;
    wr_.resize(na);
    int wr = wr0_;
    for (i64 t = 0; t < na; ++t) {
      wr += occ_[t].delta;
      wr_[t] = wr;
    }
    if (wr != wr0_) return false;  // (never: the changes of a crossing cancel)
    sel_.assign(na, 0);
    out_.assign(k, -1);
    in_.assign(k, -1);
    for (i64 t = 0; t < na; ++t) {
      if (wr_[t] != (w > 0 ? 0 : 1)) continue;
      sel_[t] = 1;
      const i64 c0 = occ_[t].c, c1 = occ_[(t + 1) % na].c;
      const i64 from = w > 0 ? c0 : c1, to = w > 0 ? c1 : c0;
      if (out_[from] >= 0 || in_[to] >= 0) return false;
      out_[from] = t;
      in_[to] = t;
    }
    for (i64 c = 0; c < k; ++c)
      if ((out_[c] < 0) != (in_[c] < 0)) return false;
    return true;
  }

  // The boundary arcs joined into rings (vertices, and the segments before and after
  // each), straight vertices dropped.
  bool rings(bool grow) {
    const i64 na = (i64)occ_.size();
    rv_.clear();
    rin_.clear();
    rout_.clear();
    roff_.assign(1, 0);
    ccw_.clear();
    used_.assign(na, 0);
    for (i64 t0 = 0; t0 < na; ++t0) {
      if (!sel_[t0] || used_[t0]) continue;
      for (i64 t = t0; !used_[t];) {
        used_[t] = 1;
        const Occ &a = occ_[t], &b = occ_[(t + 1) % na];
        const i64 len = ((b.seg - a.seg) % m_ + m_) % m_;  // curve points on the arc
        if (grow) {
          add(-1 - a.c, -1, a.seg);  // (its in-segment is set by the arc before)
          for (i64 q = 1; q <= len; ++q) add(wrap(a.seg + q, m_), wrap(a.seg + q - 1, m_), wrap(a.seg + q, m_));
          t = out_[b.c];
        } else {
          add(-1 - b.c, -1, b.seg);
          for (i64 q = len; q >= 1; --q) add(wrap(a.seg + q, m_), wrap(a.seg + q, m_), wrap(a.seg + q - 1, m_));
          t = out_[a.c];
        }
        if (t < 0) return false;
      }
      if (!close_ring()) return false;
    }
    return true;
  }
  // a ring vertex v reached along segment in (curve point: its segment before) and left
  // along out
  void add(i64 v, i64 in, i64 out) {
    rv_.push_back(v);
    rin_.push_back(in);
    rout_.push_back(out);
  }
  // The ring just added: each crossing's in-segment is the out-segment of the vertex
  // before it; straight curve points dropped; its orientation from the turn at its
  // lowest vertex (the sweep order: x, then y, exact).
  bool close_ring() {
    const i64 r0 = roff_.back(), n = (i64)rv_.size() - r0;
    for (i64 i = 0; i < n; ++i)
      if (rv_[r0 + i] < 0) rin_[r0 + i] = rout_[r0 + (i + n - 1) % n];
    i64 kept = r0;
    for (i64 i = r0; i < r0 + n; ++i) {
      if (rv_[i] >= 0 && turn(rin_[i], rout_[i]) == 0) continue;
      rv_[kept] = rv_[i];
      rin_[kept] = rin_[i];
      rout_[kept] = rout_[i];
      ++kept;
    }
    rv_.resize(kept);
    rin_.resize(kept);
    rout_.resize(kept);
    if (kept - r0 < 3) {  // (never for a boundary with area: the overlay drops it too)
      rv_.resize(r0);
      rin_.resize(r0);
      rout_.resize(r0);
      return true;
    }
    // the least curve point, then each crossing against the least so far
    i64 low = -1;
    for (i64 i = r0; i < kept; ++i) {
      if (rv_[i] < 0) continue;
      const Pt a = pt(rv_[i]);
      if (low < 0 || a.x < pt(rv_[low]).x || (a.x == pt(rv_[low]).x && a.y < pt(rv_[low]).y))
        low = i;
    }
    i64 glow = low >= 0 ? gvert(rv_[low]) : -1;
    for (i64 i = r0; i < kept; ++i) {
      if (rv_[i] >= 0) continue;
      const i64 gv = cvert_[-1 - rv_[i]];
      if (glow < 0 || g_.vcmp(gv, glow) < 0) {
        low = i;
        glow = gv;
      }
    }
    const int t = turn(rin_[low], rout_[low]);
    if (t == 0) return false;
    ccw_.push_back(t > 0);
    roff_.push_back(kept);
    return true;
  }
  // the turn from segment a's direction to segment b's (for a ring run backwards both
  // directions flip, and the sign stays)
  int turn(i64 a, i64 b) const {
    const Pt p = pt(a), q = pt(a + 1), r = pt(b), s = pt(b + 1);
    return cross_sign(p.x, p.y, q.x, q.y, r.x, r.y, s.x, s.y);
  }
  // a vertex of g_ at curve point v
  i64 gvert(i64 v) {
    const Pt a = pt(v);
    return g_.vert_point(g_.point(ov::dd(a.x), ov::dd(a.y)));
  }

  // Rounded rings, started and ordered as the overlay's assemble() does, then its check
  // after rounding.
  bool assemble(ov::Rings& out);
  std::vector<double> rx_, ry_;
  std::vector<i64> order_, start_;
  // g_: the crossings as the overlay makes them, the lines through their segments
  void geo(const std::vector<std::pair<i64, i64>>& cross) {
    g_.pts.clear();
    g_.lines.clear();
    g_.verts.clear();
    cvert_.clear();
    cl_.clear();
    for (const auto& c : cross) {
      i64 l[2];
      for (int u = 0; u < 2; ++u) {
        const i64 s = u == 0 ? c.first : c.second;
        const Pt a = pt(s), b = pt(s + 1);
        const i64 pa = g_.point(ov::dd(a.x), ov::dd(a.y)), pb = g_.point(ov::dd(b.x), ov::dd(b.y));
        l[u] = g_.line(pa, pb);
        cl_.push_back(l[u]);
      }
      cvert_.push_back(g_.vert_cross(l[0], l[1]));
    }
  }
};

inline bool Resolver::assemble(ov::Rings& out) {
  out.clear();
  out.exact_vertices = true;
  const i64 nr = (i64)ccw_.size();
  rx_.resize(rv_.size());
  ry_.resize(rv_.size());
  for (std::size_t i = 0; i < rv_.size(); ++i) {
    const i64 v = rv_[i];
    if (v >= 0) {
      rx_[i] = pt(v).x;
      ry_[i] = pt(v).y;
      continue;
    }
    double x, y;
    if (!g_.round_vertex(cvert_[-1 - v], x, y, out.exact_vertices)) out.exact_vertices = false;
    if (!(x - x == 0 && y - y == 0)) out.status = OVERFLOW;
    rx_[i] = x;
    ry_[i] = y;
  }
  // each ring's least rounded vertex: its start, and the ring's key
  start_.assign(nr, 0);
  order_.resize(nr);
  i64 exteriors = 0, holes = 0;
  for (i64 r = 0; r < nr; ++r) {
    order_[r] = r;
    (ccw_[r] ? exteriors : holes)++;
    const i64 a = roff_[r], b = roff_[r + 1];
    i64 s = a;
    for (i64 i = a + 1; i < b; ++i)
      if (rx_[i] < rx_[s] || (rx_[i] == rx_[s] && ry_[i] < ry_[s])) s = i;
    for (i64 i = a; i < b; ++i)  // a repeated least vertex: the overlay's start is its own
      if (i != s && rx_[i] == rx_[s] && ry_[i] == ry_[s]) return false;
    start_[r] = s;
  }
  if (holes > 0 && exteriors != 1) return false;
  auto key_less = [&](i64 u, i64 v) {
    const i64 a = start_[u], b = start_[v];
    return rx_[a] < rx_[b] || (rx_[a] == rx_[b] && ry_[a] < ry_[b]);
  };
  std::sort(order_.begin(), order_.end(), key_less);
  for (i64 q = 1; q < nr; ++q)
    if (!key_less(order_[q - 1], order_[q])) return false;  // equal keys: ordered by ids
  auto emit = [&](i64 r) {
    const i64 a = roff_[r], n = roff_[r + 1] - a;
    for (i64 i = 0; i < n; ++i) {
      const i64 q = a + (start_[r] - a + i) % n;
      out.xy.push_back(rx_[q]);
      out.xy.push_back(ry_[q]);
    }
    out.ring_off.push_back((i64)out.xy.size() / 2);
  };
  out.xy.reserve(2 * rv_.size());
  for (i64 r : order_) {
    if (!ccw_[r]) continue;
    emit(r);
    for (i64 h : order_)
      if (!ccw_[h]) emit(h);
    out.poly_off.push_back((i64)out.ring_off.size() - 1);
  }
  if (out.status == OK) ov::finish_rounded_impl(out, 0);
  return true;
}

}  // namespace off
}  // namespace mk
