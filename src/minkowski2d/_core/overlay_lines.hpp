// overlay_lines.hpp -- the overlay's outputs of lower dimension: polylines clipped by
// a region (run_lines) and the segments and points where the rings of a union meet
// without area (degenerate). Part of overlay.hpp (include that).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "overlay_run.hpp"

namespace mk {
namespace ov {

// Puts polylines (vertices xy, offsets off) in a canonical order: lexicographic by their
// vertices (x, then y, first vertex first), shorter first on a common start. The order
// is then independent of the arrangement's internal numbering.
inline void sort_polylines(std::vector<double>& xy, std::vector<i64>& off) {
  const std::size_t n = off.size() - 1;
  if (n < 2) return;
  std::vector<std::size_t> ord(n);
  for (std::size_t k = 0; k < n; ++k) ord[k] = k;
  std::sort(ord.begin(), ord.end(), [&](std::size_t a, std::size_t b) {
    const double* p = xy.data();
    return std::lexicographical_compare(p + 2 * off[a], p + 2 * off[a + 1], p + 2 * off[b],
                                        p + 2 * off[b + 1]);
  });
  std::vector<double> sx;
  std::vector<i64> so{0};
  sx.reserve(xy.size());
  so.reserve(off.size());
  for (std::size_t k : ord) {
    sx.insert(sx.end(), xy.begin() + 2 * off[k], xy.begin() + 2 * off[k + 1]);
    so.push_back((i64)sx.size() / 2);
  }
  xy.swap(sx);
  off.swap(so);
}

inline int Overlay::run_lines(const std::vector<EdgeIn>& in, int rule, bool keep_inside,
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
  auto other = [&](i64 k, i64 v) {
    return pcs_[kept[k]].l == v ? pcs_[kept[k]].r : pcs_[kept[k]].l;
  };
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
  sort_polylines(xy, off);
  return OK;
}

inline void Overlay::degenerate(const std::vector<std::vector<EdgeIn>>& rings,
                                std::vector<double>& lines, std::vector<i64>& line_off,
                                std::vector<double>& points) {
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
  degenerate_points(rings, at_degen, at_boundary, points);
  sort_polylines(lines, line_off);
  // the points too (x, then y)
  std::vector<i64> poff(points.size() / 2 + 1);
  for (std::size_t k = 0; k < poff.size(); ++k) poff[k] = (i64)k;
  sort_polylines(points, poff);
}

// The isolated points of degenerate(): vertices away from the boundary and from
// degenerate pieces, inside the union, in no ring's interior.
inline void Overlay::degenerate_points(const std::vector<std::vector<EdgeIn>>& rings,
                                       const std::vector<char>& at_degen,
                                       const std::vector<char>& at_boundary,
                                       std::vector<double>& points) {
  const i64 nv = (i64)av_.size(), np = (i64)pcs_.size();
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
    double x, y;
    g_.rounded(av_[v], x, y);
    points.push_back(x);
    points.push_back(y);
  }
}

inline void Overlay::emit_chain(const std::vector<i64>& cv, const std::vector<i64>& cp,
                                const std::vector<i64>& kept, std::vector<double>& xy,
                                std::vector<i64>& off) {
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

inline bool Overlay::covered(const std::vector<std::vector<EdgeIn>>& rings, i64 v) const {
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

}  // namespace ov
}  // namespace mk
