// overlay_trace.hpp -- steps 5 and 6 of an overlay run (overlay.hpp): the plane sweep
// over the pieces (winding numbers), the boundary, the rings traced along it, each
// hole's exterior, and the assembled polygons. Part of overlay.hpp (include that).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "overlay_run.hpp"

namespace mk {
namespace ov {

// The first index of [0, n) where p is false, p being true on a prefix (n when true
// everywhere), searched by galloping from the guess g: O(log d) tests for an answer d
// places away.
template <class Pred>
inline std::size_t first_false(std::size_t n, std::size_t g, Pred&& p) {
  if (n == 0) return 0;
  if (g >= n) g = n - 1;
  std::size_t lo = 0, hi = n;  // the answer is in [lo, hi]; p(hi) is false unless hi == n
  if (p(g)) {
    lo = g + 1;
    for (std::size_t step = 1; lo < n; step *= 2) {
      const std::size_t t = lo + step - 1;
      if (t >= n) break;
      if (!p(t)) {
        hi = t;
        break;
      }
      lo = t + 1;
    }
  } else {
    hi = g;
    for (std::size_t step = 1; hi > 0; step *= 2) {
      const std::size_t t = hi >= step ? hi - step : 0;
      if (p(t)) {
        lo = t + 1;
        break;
      }
      hi = t;
    }
  }
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (p(mid))
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo;
}

// a status of at most this many pieces (in one chunk) is scanned for the pieces that end
// at a vertex, which those that start there replace in place
constexpr std::size_t kSmallStatus = 64;

template <class F>
inline void Overlay::sweep(const std::vector<Piece>& ps, const std::vector<i64>& start,
                           F&& at_vertex) {
  const i64 nv = (i64)av_.size();
  std::vector<i64>& nend_at = sw_nend_;
  nend_at.assign(nv, 0);
  for (const Piece& e : ps) ++nend_at[e.r];
  SweepStatus& st = sw_st_;
  st.clear();
  auto& ch = st.ch;
  std::size_t fc = 0, fo = 0;  // the finger: chunk and place of the last change
  for (i64 v = 0; v < nv; ++v) {  // ids are sweep ranks
    const i64 nend = nend_at[v], nstart = start[v + 1] - start[v];
    if (nend == 0 && nstart == 0) continue;
    auto below = [&](i64 id) {
      const Piece& e = ps[id];
      return e.r != v && side(e, v) > 0;  // v is on the pieces that end at v
    };
    // the first piece not below v: its chunk c, then its place o in it, each searched
    // from the place of the last vertex (consecutive vertices are often close); in a
    // small status, the first of the pieces that end at v when there are any (no side
    // test: a piece below v does not end there)
    const std::size_t nc = st.size();
    if (nc == 1 && ch[0].size() <= kSmallStatus) {
      // a small status: the pieces that end at v replaced in place by those that start
      std::vector<i64>& cur = ch[0];
      std::size_t o = 0;
      if (nend > 0)
        while (ps[cur[o]].r != v) ++o;
      else
        o = first_false(cur.size(), fo, [&](std::size_t k) { return below(cur[k]); });
      const i64 pred = o > 0 ? cur[o - 1] : -1;
      if (nstart > nend)
        cur.insert(cur.begin() + (std::ptrdiff_t)(o + nend), (std::size_t)(nstart - nend), 0);
      else if (nstart < nend)
        cur.erase(cur.begin() + (std::ptrdiff_t)(o + nstart), cur.begin() + (std::ptrdiff_t)(o + nend));
      for (i64 q = 0; q < nstart; ++q) cur[o + (std::size_t)q] = start[v] + q;
      fc = 0;
      fo = o + (std::size_t)nstart;
      if (cur.empty()) {
        st.close(0);
        fo = 0;
      }
      if (nstart > 0) at_vertex(start[v], start[v + 1], pred);
      continue;
    }
    std::size_t c = first_false(nc, fc, [&](std::size_t k) { return below(ch[k].back()); });
    std::size_t o = 0;
    if (c < nc)
      o = first_false(ch[c].size(), c == fc ? fo : 0,
                      [&](std::size_t k) { return below(ch[c][k]); });
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
    fc = c;
    fo = o;
    if (nstart == 0) continue;
    // the predecessor of the place, then the fresh pieces inserted there
    i64 pred = -1;
    if (o > 0) pred = ch[c][o - 1];
    else if (c > 0) pred = ch[c - 1].back();
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
    cur.insert(cur.begin() + (std::ptrdiff_t)o, (std::size_t)nstart, 0);
    for (i64 q = 0; q < nstart; ++q) cur[o + (std::size_t)q] = start[v] + q;
    fc = c;
    fo = o + (std::size_t)nstart;
    if (cur.size() > 2 * SweepStatus::kChunk) {  // split in halves
      const std::size_t half = cur.size() / 2;
      st.open(c + 1);
      std::vector<i64>& a = ch[c];
      ch[c + 1].assign(a.begin() + (std::ptrdiff_t)half, a.end());
      a.resize(half);
    }
    at_vertex(start[v], start[v + 1], pred);
  }
}

inline void Overlay::group_pieces(std::vector<Piece>& ps, std::vector<i64>& val,
                                  std::vector<i64>& start) {
  const i64 nv = (i64)av_.size(), np = (i64)ps.size();
  start.assign(nv + 1, 0);
  for (const Piece& e : ps) ++start[e.l + 1];
  for (i64 v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<i64> fill(start.begin(), start.end() - 1), slot(np);
  for (i64 e = 0; e < np; ++e) slot[fill[ps[e].l]++] = e;
  std::vector<Piece> sp(np);
  std::vector<i64> sv(np);
  for (i64 k = 0; k < np; ++k) {
    sp[k] = ps[slot[k]];
    sv[k] = val[slot[k]];
  }
  for (i64 v = 0; v < nv; ++v) {
    const i64 a = start[v], b = start[v + 1];
    if (b - a < 2) continue;
    // a few pieces per vertex: insertion by slope, the values alongside
    for (i64 k = a + 1; k < b; ++k)
      for (i64 q = k; q > a && slope_below(sp[q], sp[q - 1]); --q) {
        std::swap(sp[q], sp[q - 1]);
        std::swap(sv[q], sv[q - 1]);
      }
  }
  ps.swap(sp);
  val.swap(sv);
}

inline void Overlay::windings() {
  sweep(pcs_, pstart_, [&](i64 first, i64 end, i64 pred) {
    int w0 = pred < 0 ? 0 : pcs_[pred].b0 + pcs_[pred].c0;
    int w1 = pred < 0 ? 0 : pcs_[pred].b1 + pcs_[pred].c1;
    for (i64 e = first; e < end; ++e) {
      pcs_[e].b0 = w0;
      pcs_[e].b1 = w1;
      w0 += pcs_[e].c0;
      w1 += pcs_[e].c1;
    }
  });
}

inline void Overlay::boundary() {
  bnd_.clear();
  bnd_.reserve(pcs_.size());  // the pages it does not fill are never touched
  for (const Piece& e : pcs_) {
    bool ib = rule_inside(rule_, e.b0, e.b1);
    bool ia = rule_inside(rule_, e.b0 + e.c0, e.b1 + e.c1);
    if (ib == ia) continue;
    // inside above (ia): from l to r; the line runs l -> r when s > 0
    bnd_.push_back(BPiece{e.line, ia ? e.l : e.r, ia ? e.r : e.l, e.src,
                          (std::int8_t)(ia ? e.s : -e.s)});
  }
  // boundary pieces reference arrangement vertices: map to global ids for run(out)
  vg_.assign(av_.begin(), av_.end());
}

inline void Overlay::trace(Rings& out) {
  out.clear();
  rv_.clear();
  rl_.clear();
  re_.clear();
  roff_.assign(1, 0);
  reoff_.assign(1, 0);
  ring_ccw_.clear();
  const i64 nv = (i64)av_.size(), nb = (i64)bnd_.size();
  std::vector<i64>& lo = tr_lo_;
  lo.assign(nv + 1, 0);
  for (const BPiece& b : bnd_) ++lo[b.from + 1];
  for (i64 v = 0; v < nv; ++v) lo[v + 1] += lo[v];
  std::vector<i64>& outs = tr_outs_;
  outs.resize(nb);
  {
    std::vector<i64>& f = tr_pos_;
    f.assign(lo.begin(), lo.end() - 1);
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
  junction_.resize(nv);
  for (i64 v = 0; v < nv; ++v) junction_[v] = lo[v + 1] - lo[v] > 1;
  std::vector<char>& used = tr_used_;
  used.assign(nb, 0);
  std::vector<i64>&walk_v = tr_walk_v_, &walk_e = tr_walk_e_, &pos = tr_pos_;
  pos.assign(nv, -1);
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
        const i64 p0 = pos[v], m = (i64)walk_v.size() - p0;
        for (i64 k = p0; k < (i64)walk_v.size(); ++k) pos[walk_v[k]] = -1;
        add_ring(walk_v.data() + p0, walk_e.data() + p0, m);
        walk_v.resize(p0);
        walk_e.resize(p0);
      }
      pos[v] = (i64)walk_v.size();
      walk_v.push_back(v);
      walk_e.push_back(b);
      b = next_of(b);
    }
    for (i64 v : walk_v) pos[v] = -1;
    if (!walk_v.empty()) add_ring(walk_v.data(), walk_e.data(), (i64)walk_v.size());
  }
  assemble(out);
}

inline void Overlay::add_ring(const i64* rv, const i64* re, i64 n) {
  const std::size_t k0 = rv_.size();
  i64 lowest = -1, lowest_i = 0;
  for (i64 i = 0; i < n; ++i) {
    // rv[i] sits between re[i - 1] (in) and re[i] (out)
    // straight on: dropped, unless other boundary edges meet there (a ring touching
    // this one at a point of its edge): the vertex stays in both, so rounding cannot
    // move the edge off the touching vertex
    if (!junction_[rv[i]] && bturn(bnd_[re[(i + n - 1) % n]], bnd_[re[i]]) == 0) continue;
    if (lowest < 0 || rv[i] < lowest) {  // ids are sweep ranks
      lowest = rv[i];
      lowest_i = i;
    }
    rv_.push_back(rv[i]);
    rl_.push_back(bnd_[re[i]].line);
  }
  if (rv_.size() - k0 < 3) {  // cannot happen for a boundary with area
    rv_.resize(k0);
    rl_.resize(k0);
    return;
  }
  // the turn at the lowest vertex is strict and its sign is the orientation
  int t = bturn(bnd_[re[(lowest_i + n - 1) % n]], bnd_[re[lowest_i]]);
  roff_.push_back((i64)rv_.size());
  re_.insert(re_.end(), re, re + n);
  reoff_.push_back((i64)re_.size());
  ring_ccw_.push_back(t > 0);
}

inline void Overlay::holes() {
  const i64 nr = (i64)ring_ccw_.size();
  owner_.assign(nr, -1);
  bool any = false;
  for (i64 k = 0; k < nr; ++k) any |= !ring_ccw_[k];
  if (!any) return;
  std::vector<Piece> ps;
  std::vector<i64> ring_of;
  ps.reserve(re_.size());
  ring_of.reserve(re_.size());
  for (i64 k = 0; k < nr; ++k)
    for (i64 q = reoff_[k]; q < reoff_[k + 1]; ++q) {
      const BPiece& b = bnd_[re_[q]];
      Piece pc{};
      const bool fwd = b.from < b.to;
      pc.l = fwd ? b.from : b.to;
      pc.r = fwd ? b.to : b.from;
      pc.src = b.src;
      pc.s = fwd ? b.d : (std::int8_t)-b.d;
      pc.line = b.line;
      ps.push_back(pc);
      ring_of.push_back(k);
    }
  std::vector<i64> start;
  group_pieces(ps, ring_of, start);
  std::vector<char> done(nr, 0);
  sweep(ps, start, [&](i64 first, i64 end, i64 pred) {
    i64 below = pred;
    for (i64 e = first; e < end; ++e) {
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

inline void Overlay::assemble(Rings& out) {
  holes();
  const i64 nr = (i64)ring_ccw_.size(), nv = (i64)av_.size();
  // each vertex rounded once: at its first use in ring order
  std::vector<double>& vxy = tr_xy_;
  vxy.resize(2 * nv);
  std::vector<char>& have = tr_used_;
  have.assign(nv, 0);
  out.exact_vertices = true;
  for (i64 v : rv_) {
    if (have[v]) continue;
    have[v] = 1;
    double& x = vxy[2 * v];
    double& y = vxy[2 * v + 1];
    // (whether it is v itself is asked only while every vertex so far was)
    if (!g_.round_vertex(av_[v], x, y, out.exact_vertices)) out.exact_vertices = false;
    if (!(x - x == 0 && y - y == 0)) out.status = OVERFLOW;
  }
  // a ring's smallest rounded vertex (x, then y): where it starts, and the sort key
  struct RKey {
    double x, y;
    i64 k;
    bool operator<(const RKey& o) const {
      return x < o.x || (x == o.x && (y < o.y || (y == o.y && k < o.k)));
    }
  };
  std::vector<RKey> key(nr);
  std::vector<i64> start(nr);
  for (i64 k = 0; k < nr; ++k) {
    double bx = INFINITY, by = INFINITY;
    for (i64 i = roff_[k]; i < roff_[k + 1]; ++i) {
      const double x = vxy[2 * rv_[i]], y = vxy[2 * rv_[i] + 1];
      if (x < bx || (x == bx && y < by)) {
        bx = x;
        by = y;
        start[k] = i - roff_[k];
      }
    }
    key[k] = RKey{bx, by, k};
  }
  std::sort(key.begin(), key.end());
  // each exterior's holes, in key order (CSR)
  std::vector<i64> kid_off(nr + 1, 0), kids;
  for (const RKey& kk : key) {
    const i64 k = kk.k;
    if (ring_ccw_[k]) continue;
    if (owner_[k] >= 0)
      ++kid_off[owner_[k] + 1];
    else
      out.status = INTERNAL;  // a hole without an exterior: never expected
  }
  for (i64 k = 0; k < nr; ++k) kid_off[k + 1] += kid_off[k];
  kids.resize(kid_off[nr]);
  {
    std::vector<i64> f(kid_off.begin(), kid_off.end() - 1);
    for (const RKey& kk : key)
      if (!ring_ccw_[kk.k] && owner_[kk.k] >= 0) kids[f[owner_[kk.k]]++] = kk.k;
  }
  out.xy.reserve(2 * rv_.size());
  if (out.want_lines) out.line.reserve(rv_.size());
  auto emit = [&](i64 k) {
    const i64 r0 = roff_[k], m = roff_[k + 1] - r0;
    for (i64 i = 0; i < m; ++i) {
      i64 q = r0 + (start[k] + i) % m;
      out.xy.push_back(vxy[2 * rv_[q]]);
      out.xy.push_back(vxy[2 * rv_[q] + 1]);
      if (out.want_lines) out.line.push_back(rl_[q]);
    }
    out.ring_off.push_back((i64)out.xy.size() / 2);
  };
  for (const RKey& kk : key) {
    const i64 k = kk.k;
    if (!ring_ccw_[k]) continue;
    emit(k);
    for (i64 q = kid_off[k]; q < kid_off[k + 1]; ++q) emit(kids[q]);
    out.poly_off.push_back((i64)out.ring_off.size() - 1);
  }
}

}  // namespace ov
}  // namespace mk
