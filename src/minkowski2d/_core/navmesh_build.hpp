// navmesh_build.hpp -- the navigation mesh of navmesh.hpp: its building (the free space's
// boundary by the exact overlay, traced into rings, triangulated, merged into convex
// polygons) and point location on it. navmesh.hpp describes the mesh and its search.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "exact.hpp"
#include "exactnum.hpp"
#include "overlay.hpp"
#include "planning.hpp"
#include "polygon.hpp"
#include "triangulate.hpp"

namespace mk {

enum MeshStatus : int {
  MESH_OK = 0,
  MESH_INEXACT = 1,     // a boundary vertex (a crossing of piece edges) is not a double
  MESH_FAILED = 3,      // an internal check failed (the caller keeps the visibility graph)
};

// PORTAL: an end of a zero-width segment (navnet.hpp) on the mesh
enum MeshFlag : std::uint8_t { CORNER = 1, JUNCTION = 2, PORTAL = 4 };

inline int orient_d(double ax, double ay, double bx, double by, double cx, double cy) {
  return cross_sign(ax, ay, bx, by, ax, ay, cx, cy);
}

// (row, item) pairs as CSR: off (n + 1 offsets) and, per row, its items in the pairs' order
template <class T>
inline void csr_from_pairs(int n, const std::vector<std::pair<int, T>>& pairs,
                           std::vector<int>& off, std::vector<T>& items) {
  off.assign(n + 1, 0);
  for (const auto& pr : pairs) ++off[pr.first + 1];
  for (int r = 0; r < n; ++r) off[r + 1] += off[r];
  items.resize(pairs.size());
  std::vector<int> fill(off.begin(), off.end() - 1);
  for (const auto& pr : pairs) items[fill[pr.first]++] = pr.second;
}

struct NavMesh {
  std::vector<double> vx, vy;       // vertices (exact doubles)
  std::vector<std::uint8_t> vflag;  // CORNER, JUNCTION
  std::vector<int> vprev, vnext;    // a corner's neighbours along the boundary
  std::vector<int> poff{0}, pv;     // convex polygons, counter-clockwise (CSR)
  std::vector<int> pn, pe;          // per polygon edge: neighbour (-1: boundary), twin edge
  std::vector<int> vpoff, vp;       // polygons around each vertex (CSR)
  // a uniform grid over the polygons' boxes (for locate)
  std::vector<double> pbox;
  double gx0 = 0, gy0 = 0, gcs = 1, gslack = 0;
  i64 gnx = 1, gny = 1;
  std::vector<i64> goff;
  std::vector<int> gitems;

  int npoly() const { return (int)poff.size() - 1; }
  int nvert() const { return (int)vx.size(); }
  int orient(int a, int b, int c) const {
    return orient_d(vx[a], vy[a], vx[b], vy[b], vx[c], vy[c]);
  }

  i64 cellx(double x) const {
    double c = std::floor((x - gx0) / gcs);
    if (!(c >= 0)) return 0;
    if (c >= (double)gnx) return gnx - 1;
    return (i64)c;
  }
  i64 celly(double y) const {
    double c = std::floor((y - gy0) / gcs);
    if (!(c >= 0)) return 0;
    if (c >= (double)gny) return gny - 1;
    return (i64)c;
  }

  // polygons containing (x, y) (closed)
  void locate(double x, double y, std::vector<int>& out) const {
    out.clear();
    if (goff.empty()) return;
    // a point near a cell border may belong to the neighbour's polygons too
    const double sl = gslack;
    i64 xa = cellx(x - sl), xb = cellx(x + sl), ya = celly(y - sl), yb = celly(y + sl);
    for (i64 r = ya; r <= yb; ++r)
      for (i64 c = xa; c <= xb; ++c) {
        i64 cell = r * gnx + c;
        for (i64 e = goff[cell]; e < goff[cell + 1]; ++e) {
          int p = gitems[e];
          const double* b = pbox.data() + 4 * p;
          if (x < b[0] || x > b[2] || y < b[1] || y > b[3]) continue;
          bool in = true;
          for (int i = poff[p]; in && i < poff[p + 1]; ++i) {
            int a = pv[i], bb = pv[i + 1 < poff[p + 1] ? i + 1 : poff[p]];
            in = orient_d(vx[a], vy[a], vx[bb], vy[bb], x, y) >= 0;
          }
          if (in && std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
        }
      }
  }

  void build_grid() {
    const int P = npoly();
    pbox.assign(4 * (std::size_t)P, 0.0);
    double X0 = 0, Y0 = 0, X1 = 1, Y1 = 1;
    for (int p = 0; p < P; ++p) {
      double* b = pbox.data() + 4 * p;
      b[0] = b[2] = vx[pv[poff[p]]];
      b[1] = b[3] = vy[pv[poff[p]]];
      for (int i = poff[p]; i < poff[p + 1]; ++i) {
        b[0] = std::min(b[0], vx[pv[i]]);
        b[1] = std::min(b[1], vy[pv[i]]);
        b[2] = std::max(b[2], vx[pv[i]]);
        b[3] = std::max(b[3], vy[pv[i]]);
      }
      if (p == 0) {
        X0 = b[0], Y0 = b[1], X1 = b[2], Y1 = b[3];
      } else {
        X0 = std::min(X0, b[0]), Y0 = std::min(Y0, b[1]);
        X1 = std::max(X1, b[2]), Y1 = std::max(Y1, b[3]);
      }
    }
    double ext = std::max(X1 - X0, Y1 - Y0);
    if (!(ext > 0) || !std::isfinite(ext)) ext = 1.0;
    // planning.hpp's rule (without the planner's 2^-1000 floor, as before)
    const double big = std::max({std::fabs(X0), std::fabs(Y0), std::fabs(X1), std::fabs(Y1)});
    gslack = grid_slack(big, ext);
    gcs = ext / std::max(1.0, std::min(2048.0, std::ceil(std::sqrt((double)P))));
    gx0 = X0 - gcs * 0.5;
    gy0 = Y0 - gcs * 0.5;
    gnx = (i64)std::ceil((X1 - gx0) / gcs) + 1;
    gny = (i64)std::ceil((Y1 - gy0) / gcs) + 1;
    auto range = [&](i64 p, i64& xa, i64& xb, i64& ya, i64& yb) {
      const double* b = pbox.data() + 4 * p;
      const double sl = gslack;
      xa = cellx(b[0] - sl), xb = cellx(b[2] + sl), ya = celly(b[1] - sl), yb = celly(b[3] + sl);
    };
    grid_buckets(P, gnx, gny, range, goff, gitems);
  }

  // ------------------------------------------------------------------ build
  // From the solid pieces of B (convexified) and the meshed box mb (x0, y0, x1, y1).
  int build(const Planner<double>& B, const double* mb) {
    ov::Geo g;
    std::vector<ov::BEdge> be;
    if (!free_boundary(B, mb, g, be)) return MESH_FAILED;
    std::vector<int> efrom, eto;
    if (int st = boundary_vertices(g, be, efrom, eto); st != MESH_OK) return st;
    std::vector<int> ooff, oe, nxt;
    if (!next_edges(efrom, eto, ooff, oe, nxt)) return MESH_FAILED;
    std::vector<std::vector<int>> rings;
    if (!trace_rings(efrom, nxt, rings)) return MESH_FAILED;
    std::vector<double> xy;
    std::vector<i64> roff{0};
    std::vector<int> rv;  // mesh vertex of each ring point
    std::vector<char> ccw;
    if (!ring_points(rings, xy, roff, rv, ccw)) return MESH_FAILED;
    set_flags(efrom, eto, ooff, nxt);
    std::vector<i64> tri;
    if (!triangulate_rings(xy, roff, ccw, tri)) return MESH_FAILED;
    pv.clear();
    poff.assign(1, 0);
    for (std::size_t t = 0; t + 2 < tri.size(); t += 3) {
      for (int q = 0; q < 3; ++q) pv.push_back(rv[tri[t + q]]);
      poff.push_back((int)pv.size());
    }
    link();
    merge_convex();
    link();
    // polygons around each vertex
    std::vector<std::pair<int, int>> around;
    around.reserve(pv.size());
    for (int p = 0; p < npoly(); ++p)
      for (int i = poff[p]; i < poff[p + 1]; ++i) around.push_back({pv[i], p});
    csr_from_pairs(nvert(), around, vpoff, vp);
    build_grid();
    return MESH_OK;
  }

  // The boundary of the free space (box minus the pieces), inside on the left: exact
  // edges be over the points and vertices of g. False when the overlay gave up.
  static bool free_boundary(const Planner<double>& B, const double* mb, ov::Geo& g,
                            std::vector<ov::BEdge>& be) {
    namespace o = ov;
    std::vector<o::EdgeIn> in;
    const double* c = B.pc.data();
    for (i64 p = 0; p < B.P; ++p) {
      i64 first = (i64)g.pts.size(), n = B.poff[p + 1] - B.poff[p];
      for (i64 i = B.poff[p]; i < B.poff[p + 1]; ++i) g.point(o::dd(c[2 * i]), o::dd(c[2 * i + 1]));
      o::add_ring(g, first, n, 1, 1, in);
    }
    {
      i64 first = (i64)g.pts.size();
      g.point(o::dd(mb[0]), o::dd(mb[1]));
      g.point(o::dd(mb[2]), o::dd(mb[1]));
      g.point(o::dd(mb[2]), o::dd(mb[3]));
      g.point(o::dd(mb[0]), o::dd(mb[3]));
      o::add_ring(g, first, 4, 1, 0, in);
    }
    o::Overlay ovl(g);
    ovl.run(in, o::DIFFERENCE, be);
    return !ovl.exceeded();
  }

  // The mesh vertices (vx, vy: exact doubles, merged by coordinates, sorted by y then x)
  // and each boundary edge's ends among them. MESH_INEXACT when a vertex is no double.
  int boundary_vertices(const ov::Geo& g, const std::vector<ov::BEdge>& be,
                        std::vector<int>& efrom, std::vector<int>& eto) {
    std::vector<i64> used;
    used.reserve(2 * be.size());
    for (const ov::BEdge& e : be) {
      used.push_back(e.from);
      used.push_back(e.to);
    }
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    std::vector<double> ux(used.size()), uy(used.size());
    for (std::size_t k = 0; k < used.size(); ++k) {
      const ov::Vert& V = g.verts[used[k]];
      if (V.p >= 0) {
        ux[k] = g.pts[V.p].x.hi;
        uy[k] = g.pts[V.p].y.hi;
        continue;
      }
      double x, y;
      g.rounded(used[k], x, y);
      if (!(x - x == 0) || !(y - y == 0)) return MESH_INEXACT;
      Dy X, Y, W;
      g.exact(used[k], X, Y, W);
      if ((X - Dy(x) * W).sign() != 0 || (Y - Dy(y) * W).sign() != 0) return MESH_INEXACT;
      ux[k] = x;
      uy[k] = y;
    }
    std::vector<int> ord(used.size());
    for (std::size_t k = 0; k < ord.size(); ++k) ord[k] = (int)k;
    std::sort(ord.begin(), ord.end(), [&](int a, int b) {
      return uy[a] < uy[b] || (uy[a] == uy[b] && ux[a] < ux[b]);
    });
    std::vector<int> uid(used.size());
    vx.clear();
    vy.clear();
    for (std::size_t t = 0; t < ord.size(); ++t) {
      int k = ord[t];
      if (t == 0 || ux[k] != vx.back() || uy[k] != vy.back()) {
        vx.push_back(ux[k]);
        vy.push_back(uy[k]);
      }
      uid[k] = (int)vx.size() - 1;
    }
    auto mid = [&](i64 gv) {
      return uid[std::lower_bound(used.begin(), used.end(), gv) - used.begin()];
    };
    for (const ov::BEdge& e : be) {
      int a = mid(e.from), b = mid(e.to);
      if (a == b) return MESH_FAILED;
      efrom.push_back(a);
      eto.push_back(b);
    }
    return MESH_OK;
  }

  // Out-edges per vertex (CSR ooff, oe), in angle order where several leave, and each
  // edge's successor along the boundary: the first out-edge clockwise from the way back.
  bool next_edges(const std::vector<int>& efrom, const std::vector<int>& eto,
                  std::vector<int>& ooff, std::vector<int>& oe, std::vector<int>& nxt) const {
    const int nv = nvert(), ne = (int)efrom.size();
    ooff.assign(nv + 1, 0);
    oe.assign(ne, 0);
    for (int e = 0; e < ne; ++e) ++ooff[efrom[e] + 1];
    for (int q = 0; q < nv; ++q) ooff[q + 1] += ooff[q];
    {
      std::vector<int> fill(ooff.begin(), ooff.end() - 1);
      for (int e = 0; e < ne; ++e) oe[fill[efrom[e]]++] = e;
    }
    auto upper = [&](int p, int q) {
      return vy[q] > vy[p] || (vy[q] == vy[p] && vx[q] > vx[p]);
    };
    auto before = [&](int p, int a, int b) {  // direction p -> a before p -> b (ccw from +x)
      bool ua = upper(p, a), ub = upper(p, b);
      if (ua != ub) return ua;
      return orient(p, a, b) > 0;
    };
    for (int q = 0; q < nv; ++q)
      if (ooff[q + 1] - ooff[q] > 1)
        std::sort(oe.begin() + ooff[q], oe.begin() + ooff[q + 1],
                  [&](int e, int f) { return before(q, eto[e], eto[f]); });
    nxt.assign(ne, 0);
    for (int e = 0; e < ne; ++e) {
      const int q = eto[e], back = efrom[e], lo = ooff[q], hi = ooff[q + 1];
      if (hi - lo == 0) return false;
      if (hi - lo == 1) {
        nxt[e] = oe[lo];
        continue;
      }
      // the last out-edge before the back direction (in ccw order), cyclically
      int best = oe[hi - 1];
      for (int k = lo; k < hi; ++k)
        if (before(q, eto[oe[k]], back)) best = oe[k];
      nxt[e] = best;
    }
    return true;
  }

  // The boundary's rings (vertex lists), split where one would meet itself.
  bool trace_rings(const std::vector<int>& efrom, const std::vector<int>& nxt,
                   std::vector<std::vector<int>>& rings) const {
    const int nv = nvert(), ne = (int)efrom.size();
    std::vector<char> seen(ne, 0);
    std::vector<int> pos(nv, -1), st;
    for (int e0 = 0; e0 < ne; ++e0) {
      if (seen[e0]) continue;
      st.clear();
      int e = e0;
      while (!seen[e]) {
        seen[e] = 1;
        const int x = efrom[e];
        if (pos[x] >= 0) {
          const int p0 = pos[x];
          rings.emplace_back(st.begin() + p0, st.end());
          for (std::size_t t = p0 + 1; t < st.size(); ++t) pos[st[t]] = -1;
          st.resize(p0 + 1);
        } else {
          pos[x] = (int)st.size();
          st.push_back(x);
        }
        e = nxt[e];
      }
      if (e != e0) return false;
      rings.emplace_back(st.begin(), st.end());
      for (int x : st) pos[x] = -1;
    }
    return true;
  }

  // The rings' points (xy, ring offsets roff, mesh vertex rv) and their orientation at
  // each ring's lowest vertex: counter-clockwise rings bound a region.
  bool ring_points(const std::vector<std::vector<int>>& rings, std::vector<double>& xy,
                   std::vector<i64>& roff, std::vector<int>& rv, std::vector<char>& ccw) const {
    for (auto& r : rings) {
      const int k = (int)r.size();
      if (k < 3) return false;
      int lo = 0;
      for (int t = 1; t < k; ++t)
        if (vy[r[t]] < vy[r[lo]] || (vy[r[t]] == vy[r[lo]] && vx[r[t]] < vx[r[lo]])) lo = t;
      int s = orient(r[(lo + k - 1) % k], r[lo], r[(lo + 1) % k]);
      if (s == 0) return false;
      ccw.push_back(s > 0);
      for (int x : r) {
        xy.push_back(vx[x]);
        xy.push_back(vy[x]);
        rv.push_back(x);
      }
      roff.push_back((i64)rv.size());
    }
    return true;
  }

  // flags: pinch points (several out-edges) and right turns (corners)
  void set_flags(const std::vector<int>& efrom, const std::vector<int>& eto,
                 const std::vector<int>& ooff, const std::vector<int>& nxt) {
    const int nv = nvert(), ne = (int)efrom.size();
    vflag.assign(nv, 0);
    vprev.assign(nv, -1);
    vnext.assign(nv, -1);
    for (int e = 0; e < ne; ++e) {
      const int q = eto[e];
      if (ooff[q + 1] - ooff[q] > 1) {
        vflag[q] = JUNCTION;
      } else if (orient(efrom[e], q, eto[nxt[e]]) < 0) {
        vflag[q] = CORNER;
        vprev[q] = efrom[e];
        vnext[q] = eto[nxt[e]];
      }
    }
  }

  // The constrained Delaunay triangles of the rings (ring point indices, 3 per triangle).
  static bool triangulate_rings(const std::vector<double>& xy, const std::vector<i64>& roff,
                                const std::vector<char>& ccw, std::vector<i64>& tri) {
    if (ccw.empty()) return true;
    polygon::Work<double> w(xy.data(), roff.data());
    w.cross_reason = POLYGONS_OVERLAP;
    for (std::size_t r = 0; r < ccw.size(); ++r) {
      polygon::Problem pr = w.add_ring((i64)r, ccw[r] != 0);
      if (!pr.ok()) return false;
    }
    w.close_rings();
    polygon::Problem pr = w.run();
    if (!pr.ok()) return false;
    try {
      polygon::triangulate_work(w, tri, true);
    } catch (const std::exception&) {
      return false;
    }
    return true;
  }

  // neighbours and twin edges by sorting the edges on their unordered ends
  void link() {
    const int H = (int)pv.size();
    pn.assign(H, -1);
    pe.assign(H, -1);
    std::vector<int> owner(H);
    for (int p = 0; p < npoly(); ++p)
      for (int i = poff[p]; i < poff[p + 1]; ++i) owner[i] = p;
    auto nxt = [&](int i) { return i + 1 < poff[owner[i] + 1] ? i + 1 : poff[owner[i]]; };
    std::vector<std::pair<std::pair<int, int>, int>> key(H);
    for (int i = 0; i < H; ++i) {
      int a = pv[i], b = pv[nxt(i)];
      key[i] = {{std::min(a, b), std::max(a, b)}, i};
    }
    std::sort(key.begin(), key.end());
    for (int q = 0; q + 1 < H; ++q) {
      if (key[q].first != key[q + 1].first) continue;
      int x = key[q].second, y = key[q + 1].second;
      pn[x] = owner[y];
      pe[x] = y - poff[owner[y]];
      pn[y] = owner[x];
      pe[y] = x - poff[owner[x]];
      ++q;
    }
  }

  // Hertel-Mehlhorn: remove a diagonal when both of its ends stay strictly convex
  void merge_convex() {
    const int P = npoly();
    std::vector<std::vector<int>> poly(P);
    for (int p = 0; p < P; ++p) poly[p].assign(pv.begin() + poff[p], pv.begin() + poff[p + 1]);
    std::vector<int> alive(P, 1), rep(P);
    for (int p = 0; p < P; ++p) rep[p] = p;
    auto find = [&](int a) {
      while (rep[a] != a) a = rep[a] = rep[rep[a]];
      return a;
    };
    // diagonals in the original triangulation, each once
    for (int p = 0; p < P; ++p)
      for (int i = poff[p]; i < poff[p + 1]; ++i) {
        if (pn[i] < 0 || pn[i] < p) continue;
        const int a = pv[i], b = pv[i + 1 < poff[p + 1] ? i + 1 : poff[p]];
        int A = find(p), Bq = find(pn[i]);
        if (A == Bq) continue;
        std::vector<int>& X = poly[A];
        std::vector<int>& Y = poly[Bq];
        // X has a -> b, Y has b -> a
        int ia = -1, jb = -1;
        for (int t = 0; t < (int)X.size(); ++t)
          if (X[t] == a && X[(t + 1) % X.size()] == b) ia = t;
        for (int t = 0; t < (int)Y.size(); ++t)
          if (Y[t] == b && Y[(t + 1) % Y.size()] == a) jb = t;
        if (ia < 0 || jb < 0) continue;
        const int nX = (int)X.size(), nY = (int)Y.size();
        // merged ring: X from b around to a, then Y from a around to b (exclusive ends)
        std::vector<int> M;
        for (int t = 0; t < nX; ++t) M.push_back(X[(ia + 1 + t) % nX]);  // b ... a
        for (int t = 2; t < nY; ++t) M.push_back(Y[(jb + t) % nY]);       // after a ... before b
        // convex at a and b
        const int m = (int)M.size();
        bool ok = true;
        for (int t = 0; t < m && ok; ++t)
          if (M[t] == a || M[t] == b)
            ok = orient(M[(t + m - 1) % m], M[t], M[(t + 1) % m]) > 0;
        if (!ok) continue;
        poly[A] = std::move(M);
        poly[Bq].clear();
        alive[Bq] = 0;
        rep[Bq] = A;
      }
    pv.clear();
    poff.assign(1, 0);
    for (int p = 0; p < P; ++p)
      if (alive[p]) {
        pv.insert(pv.end(), poly[p].begin(), poly[p].end());
        poff.push_back((int)pv.size());
      }
  }
};

}  // namespace mk
