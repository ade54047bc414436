// navnet.hpp -- the zero-width part of the free space, as a graph beside the navigation
// mesh (navmesh.hpp).
//
// The free space of planning.hpp is closed: where two obstacles (groups) touch along an
// edge, or an obstacle touches a closed workspace box along an edge, the shared segment
// is free although no area lies on either side of it. A path may run along it. The mesh
// holds only the part with area (the overlay's regular difference), so these segments
// are kept here as a graph: its vertices are the segments' ends (piece or box vertices,
// exact doubles), its edges the segments. Where a segment's end lies on the boundary of
// the part with area it is a vertex of the mesh (the overlay splits every boundary edge
// at the piece vertices on it): a portal, where the search passes between the mesh and
// the graph; other ends (a bend or a branch of the network, a dead end) are vertices of
// the graph only.
//
// Finding them, exactly. The pieces' edges (and a closed box's four, with the outside as
// a group of its own) are sorted by their supporting line (signs of cross products).
// Along one line, the elementary intervals between consecutive edge ends are swept with,
// per group, the number of its edges covering the interval from the left and from the
// right. An interval covered from both sides, by different groups only, is a candidate:
// it is free unless some group's union covers it otherwise (a third obstacle across it,
// or a group on both sides through a seam), which Planner::blocked decides -- the one
// test of "the closed segment meets the open interior of a group's union". A candidate
// that a third obstacle covers in part is a stub: its free part is a dead end (no other
// zero-width segment leaves it: that would make a breakpoint there), whose far end is in
// general not a double. So is a candidate that leaves the workspace box: its part inside
// ends at the box's side. No path passes a stub; a start or goal on it reaches those of
// the stub's ends that the segment between them is free to (Planner::blocked again).
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "exact.hpp"
#include "planning.hpp"

namespace mk {

struct NavNet {
  int nv = 0;                  // mesh vertices: ids 0 .. nv - 1; extra vertices from nv
  std::vector<double> ex, ey;  // the extra vertices (not on the mesh)
  std::vector<int> ea, eb;     // the segments (vertex ids)
  std::vector<int> sa, sb;     // the stubs (vertex ids; no path runs along them)
  std::vector<int> off, adj;   // neighbours per vertex id (CSR over size())
  std::vector<int> comp;       // component per vertex id (-1: not on the graph)
  int ncomp = 0;

  int size() const { return nv + (int)ex.size(); }
  bool empty() const { return ea.empty(); }
  bool on(int id) const { return id >= 0 && !off.empty() && off[id + 1] > off[id]; }
};

// The zero-width segments of B's free space inside its box, as (ax, ay, bx, by) each,
// and the stubs (candidates partly covered by a third obstacle) likewise.
inline void zero_width_segments(const Planner<double>& B, std::vector<double>& seg,
                                std::vector<double>& stub) {
  seg.clear();
  stub.clear();
  struct E {
    double ax, ay, bx, by;
    int grp;
    bool fwd;  // the piece lies on the left of a -> b (a before b along the line)
  };
  auto lexless = [](double ax, double ay, double bx, double by) {
    return ay < by || (ay == by && ax < bx);
  };
  std::vector<E> es;
  const double* v = B.pc.data();
  auto add = [&](double ax, double ay, double bx, double by, int grp) {
    if (lexless(ax, ay, bx, by))
      es.push_back(E{ax, ay, bx, by, grp, true});
    else
      es.push_back(E{bx, by, ax, ay, grp, false});
  };
  for (i64 p = 0; p < B.P; ++p)
    for (i64 i = B.poff[p]; i < B.poff[p + 1]; ++i) {
      i64 j = i + 1 < B.poff[p + 1] ? i + 1 : B.poff[p];
      add(v[2 * i], v[2 * i + 1], v[2 * j], v[2 * j + 1], B.pgrp[p]);
    }
  if (B.has_box && !B.open_box) {  // the outside of a closed box: on the left of these
    const double x0 = B.bx0, y0 = B.by0, x1 = B.bx1, y1 = B.by1;
    if (x0 < x1) {
      add(x1, y0, x0, y0, -1);
      add(x0, y1, x1, y1, -1);
    }
    if (y0 < y1) {
      add(x1, y1, x1, y0, -1);
      add(x0, y0, x0, y1, -1);
    }
  }
  auto orient_pts = [](double ax, double ay, double bx, double by, double cx, double cy) {
    return cross_sign(ax, ay, bx, by, ax, ay, cx, cy);
  };
  auto same_line = [&](const E& e, const E& f) {
    return cross_sign(e.ax, e.ay, e.bx, e.by, f.ax, f.ay, f.bx, f.by) == 0 &&
           orient_pts(e.ax, e.ay, e.bx, e.by, f.ax, f.ay) == 0;
  };
  std::sort(es.begin(), es.end(), [&](const E& e, const E& f) {
    int c = cross_sign(e.ax, e.ay, e.bx, e.by, f.ax, f.ay, f.bx, f.by);
    if (c != 0) return c > 0;
    int o = orient_pts(e.ax, e.ay, e.bx, e.by, f.ax, f.ay);
    if (o != 0) return o > 0;
    return lexless(e.ax, e.ay, f.ax, f.ay);
  });
  PlanScratch S;
  S.init((std::size_t)B.items());
  struct Ev {
    double x, y;
    int g, d;  // local group, +1 / -1 from the left (fwd) or +2 / -2 from the right
  };
  std::vector<Ev> ev;
  std::vector<int> groups, cl, cr;
  const std::size_t n = es.size();
  for (std::size_t s = 0; s < n;) {
    std::size_t e = s + 1;
    bool f = es[s].fwd, b = !es[s].fwd;
    while (e < n && same_line(es[s], es[e])) {
      f |= es[e].fwd;
      b |= !es[e].fwd;
      ++e;
    }
    if (!(f && b)) {  // covered from one side only: no candidate on this line
      s = e;
      continue;
    }
    groups.clear();
    for (std::size_t k = s; k < e; ++k) groups.push_back(es[k].grp);
    std::sort(groups.begin(), groups.end());
    groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
    ev.clear();
    for (std::size_t k = s; k < e; ++k) {
      const int g = (int)(std::lower_bound(groups.begin(), groups.end(), es[k].grp) -
                          groups.begin());
      const int d = es[k].fwd ? 1 : 2;
      ev.push_back(Ev{es[k].ax, es[k].ay, g, d});
      ev.push_back(Ev{es[k].bx, es[k].by, g, -d});
    }
    std::sort(ev.begin(), ev.end(),
              [&](const Ev& a, const Ev& c) { return lexless(a.x, a.y, c.x, c.y); });
    cl.assign(groups.size(), 0);
    cr.assign(groups.size(), 0);
    int nl = 0, nr = 0, both = 0;  // groups covering from the left, the right, both
    for (std::size_t t = 0; t < ev.size();) {
      const double px = ev[t].x, py = ev[t].y;
      for (; t < ev.size() && ev[t].x == px && ev[t].y == py; ++t) {
        const Ev& E0 = ev[t];
        const int g = E0.g;
        const bool wasl = cl[g] > 0, wasr = cr[g] > 0;
        (E0.d == 1 || E0.d == -1 ? cl[g] : cr[g]) += E0.d > 0 ? 1 : -1;
        const bool isl = cl[g] > 0, isr = cr[g] > 0;
        nl += (int)isl - (int)wasl;
        nr += (int)isr - (int)wasr;
        both += (int)(isl && isr) - (int)(wasl && wasr);
      }
      if (t == ev.size() || !(nl > 0 && nr > 0 && both == 0)) continue;
      const double qx = ev[t].x, qy = ev[t].y;
      // a candidate leaving the box: its part inside is a dead end at the box's side (a
      // stub); wholly outside, or across the box (no end a path reaches): dropped
      const bool inp = B.in_box(px, py), inq = B.in_box(qx, qy);
      if (!inp && !inq) continue;
      std::vector<double>& to = !(inp && inq) || B.blocked(px, py, qx, qy, S) ? stub : seg;
      to.insert(to.end(), {px, py, qx, qy});
    }
    s = e;
  }
}

// The graph of the zero-width segments: mesh vertices (vx, vy, sorted by (y, x)) keep
// their ids, other ends become extra vertices.
inline void build_navnet(const Planner<double>& B, const std::vector<double>& vx,
                         const std::vector<double>& vy, NavNet& N) {
  N = NavNet{};
  N.nv = (int)vx.size();
  std::vector<double> seg, stub;
  zero_width_segments(B, seg, stub);
  const std::size_t ns = seg.size() / 4, nst = stub.size() / 4;
  auto mesh_id = [&](double x, double y) {
    int lo = 0, hi = N.nv;  // the first vertex not below (x, y) in (y, x) order
    while (lo < hi) {
      const int mid = (lo + hi) / 2;
      if (vy[mid] < y || (vy[mid] == y && vx[mid] < x))
        lo = mid + 1;
      else
        hi = mid;
    }
    return lo < N.nv && vx[lo] == x && vy[lo] == y ? lo : -1;
  };
  std::vector<std::pair<double, double>> extra;
  for (const std::vector<double>* L : {&seg, &stub})
    for (std::size_t k = 0; 2 * k < L->size(); ++k)
      if (mesh_id((*L)[2 * k], (*L)[2 * k + 1]) < 0)
        extra.push_back({(*L)[2 * k + 1], (*L)[2 * k]});
  std::sort(extra.begin(), extra.end());
  extra.erase(std::unique(extra.begin(), extra.end()), extra.end());
  for (const auto& [y, x] : extra) {
    N.ex.push_back(x);
    N.ey.push_back(y);
  }
  auto id_of = [&](double x, double y) {
    const int m = mesh_id(x, y);
    if (m >= 0) return m;
    return N.nv + (int)(std::lower_bound(extra.begin(), extra.end(), std::make_pair(y, x)) -
                        extra.begin());
  };
  std::vector<std::pair<int, int>> arcs;
  for (std::size_t k = 0; k < ns; ++k) {
    const int a = id_of(seg[4 * k], seg[4 * k + 1]), b = id_of(seg[4 * k + 2], seg[4 * k + 3]);
    N.ea.push_back(a);
    N.eb.push_back(b);
    arcs.push_back({a, b});
    arcs.push_back({b, a});
  }
  for (std::size_t k = 0; k < nst; ++k) {
    N.sa.push_back(id_of(stub[4 * k], stub[4 * k + 1]));
    N.sb.push_back(id_of(stub[4 * k + 2], stub[4 * k + 3]));
  }
  const int V = N.size();
  N.off.assign(V + 1, 0);
  for (const auto& pr : arcs) ++N.off[pr.first + 1];
  for (int r = 0; r < V; ++r) N.off[r + 1] += N.off[r];
  N.adj.resize(arcs.size());
  {
    std::vector<int> fill(N.off.begin(), N.off.end() - 1);
    for (const auto& pr : arcs) N.adj[fill[pr.first]++] = pr.second;
  }
  // components (union-find over the segments)
  std::vector<int> rep(V);
  for (int i = 0; i < V; ++i) rep[i] = i;
  auto find = [&](int a) {
    while (rep[a] != a) a = rep[a] = rep[rep[a]];
    return a;
  };
  for (std::size_t k = 0; k < ns; ++k) rep[find(N.ea[k])] = find(N.eb[k]);
  N.comp.assign(V, -1);
  std::vector<int> cid(V, -1);
  for (int i = 0; i < V; ++i) {
    if (!N.on(i)) continue;
    const int r = find(i);
    if (cid[r] < 0) cid[r] = N.ncomp++;
    N.comp[i] = cid[r];
  }
}

}  // namespace mk
