// navmesh.hpp -- an exact navigation mesh of the closed free space and an optimal
// any-angle search on it (Polyanya: Cui, Harabor and Grastien, IJCAI 2017), beside the
// visibility graph of planning.hpp. minkowski2d.planning chooses between them.
//
// The mesh (navmesh_build.hpp). The free space of planning.hpp (the box minus the open
// interiors of the groups' unions) is, away from zero-width parts, the closure of (box
// minus every solid piece): the exact overlay (overlay.hpp) computes its boundary as exact
// edges, inside on the left. The mesh is made only when every boundary vertex is a double
// (piece vertices always are; a crossing of two piece edges must round to itself, which is
// decided exactly): otherwise build() says so and the caller keeps the visibility graph.
// The zero-width parts (segments shared by two groups, or a group and a closed box) are a
// graph beside the mesh (navnet.hpp), met at its portals (PORTAL). The boundary is traced
// into simple rings (split where a ring would meet itself), triangulated by polygon.hpp /
// triangulate.hpp (exact, constrained Delaunay), and the triangles are merged into convex
// polygons (Hertel-Mehlhorn, strictly convex merges only). Every decision is
// mk::cross_sign on doubles (exact) or a comparison.
//
// Vertices where the free space pinches (the boundary passes twice: two regions, or a
// region and a hole, touch at a point) are junctions; a vertex where the boundary turns
// right (the free angle exceeds 180 degrees) is a corner. Both are piece vertices.
//
// The search (per query; Polyanya's search nodes). A node is an interval on a mesh edge
// seen from a root (the start or a vertex where the path bends) and the polygon it
// enters; the interval is kept as two rays from the root (each through two exact
// points), so no intersection point is ever computed for a decision: the successors,
// the cone tests and the target test are signs of cross products of exact doubles.
// Expanding a node projects the cone through the polygon; intervals on the far edges
// keep the root. Where a cone reaches a corner, the path may bend there: a vertex node
// at the corner covers the side hidden from the root (the half-plane beyond the line
// root-corner, with that line), in the polygons around the corner that lie between the
// ray beyond the corner and the corner's nearer boundary edge -- Polyanya's
// non-observable successors, taken over the corner's whole fan so that a path passing
// exactly through a vertex is never lost. A shortest path bends at a corner only around
// its obstacle: where the line root-corner runs into the obstacle, or on along one of
// its edges, no node is made. A junction inside a cone is a vertex node in every
// direction (a path may pass the pinch). Root-level pruning (a vertex reached again at
// no smaller length is not expanded again), the pruning at the mesh's bridges (below,
// MeshPlanner) and the admissible heuristic of Polyanya (the shortest
// root-interval-target distance, the target mirrored across the edge when on the root's
// side) make it A*. On the network: a portal in sight is a vertex node (one that only
// goes on along the segments where no path bends there in the mesh); a node moves along
// a segment to its other end; a mesh vertex reached that way expands its whole fan; a
// start or goal on a segment attaches to its ends. Lengths are doubles: as in the
// visibility graph, two paths whose lengths differ only by rounding may be chosen
// either way; validity never depends on them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

#include "exact.hpp"
#include "navmesh_build.hpp"
#include "navnet.hpp"
#include "planning.hpp"
#include "planning_queries.hpp"

namespace mk {

// ------------------------------------------------------------------------------------
// the search

struct Lim {  // a ray from the root with direction (x2 - x1, y2 - y1)
  double x1, y1, x2, y2;
};

struct MeshRoot {
  double x, y, g;
  int parent, v;
};
struct MeshNode {
  double f, g;
  int kind;   // 0 interval, 1 vertex, 2 final
  int root;   // interval / final: its root; vertex: the parent root
  int poly, k, v;
  int restr;  // vertex: 0 none, +1 / -1: allowed where restr * side(R) >= 0
  int e1;     // vertex with restr: the corner's boundary neighbour nearest the ray beyond
  int net;    // vertex: 1 on along the zero-width segments only (no polygon expanded)
  Lim L, R;
};

struct MeshScratch {
  std::vector<MeshRoot> roots;
  std::vector<MeshNode> nodes;
  std::vector<double> best;   // per vertex: the least length it was reached with
  std::vector<int> touched;   // vertices whose best was set
  std::vector<char> tmark;    // per polygon: contains the target
  std::vector<int> spolys, tpolys;
  std::vector<int> ppolys;    // the bridge pruning's targets (tpolys, or the polygons
                              // around the portals of the goal's zero-width network)
  std::vector<std::pair<int, double>> satt, gatt;  // start / goal on the network: ends
  std::vector<int> fan;       // the search's own buffers, kept between queries
  std::vector<std::pair<double, int>> heap;
  void init(int nv, int np) {
    best.assign(nv, std::numeric_limits<double>::infinity());
    tmark.assign(np, 0);
    touched.clear();
  }
};

struct MeshPlanner {
  Planner<double> base;
  NavMesh M;
  NavNet net;  // the zero-width segments (navnet.hpp)
  int status = MESH_FAILED;
  double mb[4] = {0, 0, 0, 0};
  // counters of the last query (tests and benchmarks)
  mutable i64 n_expanded = 0, n_pushed = 0;

  // Cul-de-sac pruning (Polyanya's dead ends, generalised). In the graph of the polygons
  // (joined by their shared edges, and all polygons around a junction joined to each
  // other: a path may pass the pinch), a bridge is a mesh edge e whose removal splits the
  // graph. A path that crosses e into the side without the target must leave that side
  // again, and only through the closed segment e; the part in between is no shorter than
  // the segment on e between the two points (free: e is a mesh edge). So no interval is
  // pushed across a bridge into a side without a target polygon, and a vertex node does
  // not expand the polygons around it that a bridge at the vertex separates from every
  // target polygon. The bends at e's ends are pushed by the node that reached e.
  // bsub: per polygon edge slot, the child polygon c of its bridge in the DFS tree (the
  // side of c is the subtree: ptin[c] <= ptin[x] < ptout[c]), -1 for no bridge;
  // vb (CSR vboff): per vertex, the children of the bridges that end at it.
  std::vector<int> bsub, ptin, ptout, vboff, vb;
  bool prune = true;  // the bridge pruning on (tests compare the search without it)

  void find_bridges() {
    const int P = M.npoly(), H = (int)M.pv.size(), NV = M.nvert();
    std::vector<int> owner(H);
    for (int p = 0; p < P; ++p)
      for (int i = M.poff[p]; i < M.poff[p + 1]; ++i) owner[i] = p;
    auto twin = [&](int i) { return M.poff[M.pn[i]] + M.pe[i]; };
    // adjacency (polygon, (neighbour, edge id)): a mesh edge by its lower slot, the
    // links around a junction (a star at its first polygon) numbered from H
    std::vector<std::pair<int, std::pair<int, int>>> arcs;
    for (int i = 0; i < H; ++i)
      if (M.pn[i] >= 0) arcs.push_back({owner[i], {M.pn[i], std::min(i, twin(i))}});
    int link = H;
    for (int v = 0; v < NV; ++v)
      if (M.vflag[v] & JUNCTION)
        for (int t = M.vpoff[v] + 1; t < M.vpoff[v + 1]; ++t, ++link) {
          arcs.push_back({M.vp[M.vpoff[v]], {M.vp[t], link}});
          arcs.push_back({M.vp[t], {M.vp[M.vpoff[v]], link}});
        }
    // a zero-width network joins all polygons around its portals (a star likewise)
    {
      std::vector<std::pair<int, int>> cp;  // (component, polygon)
      for (int v = 0; v < NV; ++v)
        if (M.vflag[v] & PORTAL)
          for (int t = M.vpoff[v]; t < M.vpoff[v + 1]; ++t) cp.push_back({net.comp[v], M.vp[t]});
      std::sort(cp.begin(), cp.end());
      std::size_t h = 0;  // the component's first entry
      for (std::size_t t = 0; t < cp.size(); ++t) {
        if (t == 0 || cp[t].first != cp[t - 1].first) {
          h = t;
          continue;
        }
        if (cp[t] == cp[t - 1] || cp[t].second == cp[h].second) continue;
        arcs.push_back({cp[h].second, {cp[t].second, link}});
        arcs.push_back({cp[t].second, {cp[h].second, link}});
        ++link;
      }
    }
    std::vector<int> aoff;
    std::vector<std::pair<int, int>> adj;
    csr_from_pairs(P, arcs, aoff, adj);
    // iterative Tarjan: tin / low, a tree edge (parent, child) is a bridge when
    // low[child] > tin[parent]
    ptin.assign(P, -1);
    ptout.assign(P, 0);
    bsub.assign(H, -1);
    std::vector<int> low(P, 0), pedge(P, -1), it(P, 0), stack;
    int timer = 0;
    for (int s = 0; s < P; ++s) {
      if (ptin[s] >= 0) continue;
      ptin[s] = low[s] = timer++;
      it[s] = aoff[s];
      stack.push_back(s);
      while (!stack.empty()) {
        const int p = stack.back();
        if (it[p] < aoff[p + 1]) {
          const auto [q, id] = adj[it[p]++];
          if (id == pedge[p]) continue;
          if (ptin[q] < 0) {
            ptin[q] = low[q] = timer++;
            pedge[q] = id;
            it[q] = aoff[q];
            stack.push_back(q);
          } else {
            low[p] = std::min(low[p], ptin[q]);
          }
          continue;
        }
        stack.pop_back();
        ptout[p] = timer;
        if (stack.empty()) continue;
        const int par = stack.back();
        low[par] = std::min(low[par], low[p]);
        if (low[p] > ptin[par] && pedge[p] < H) bsub[pedge[p]] = bsub[twin(pedge[p])] = p;
      }
    }
    // the bridges at each vertex: both ends of every bridge edge, once per edge
    std::vector<std::pair<int, int>> at;
    for (int i = 0; i < H; ++i)
      if (bsub[i] >= 0 && i < twin(i)) {
        const int p = owner[i], j = i + 1 < M.poff[p + 1] ? i + 1 : M.poff[p];
        at.push_back({M.pv[i], bsub[i]});
        at.push_back({M.pv[j], bsub[i]});
      }
    csr_from_pairs(NV, at, vboff, vb);
  }

  int build(const double* meshbox) {
    base.build_base();
    for (int q = 0; q < 4; ++q) mb[q] = meshbox[q];
    status = M.build(base, mb);
    if (status != MESH_OK) return status;
    build_navnet(base, M.vx, M.vy, net);
    for (int v = 0; v < M.nvert(); ++v)
      if (net.on(v)) M.vflag[v] |= PORTAL;
    find_bridges();
    return status;
  }

  // vertex ids of the search: the mesh's, then the network's extra vertices
  int nids() const { return net.size(); }
  double idx(int id) const { return id < M.nvert() ? M.vx[id] : net.ex[id - M.nvert()]; }
  double idy(int id) const { return id < M.nvert() ? M.vy[id] : net.ey[id - M.nvert()]; }

  // Where (x, y) lies on the network: the ends of its segment with their distances, or
  // the one vertex it is; on a stub, the stub's ends that the point sees along it (S:
  // Planner::blocked's scratch); empty when nowhere on it.
  void locate_net(double x, double y, std::vector<std::pair<int, double>>& att,
                  PlanScratch& S) const {
    att.clear();
    auto on_seg = [&](int a, int b) {
      const double ax = idx(a), ay = idy(a), bx = idx(b), by = idy(b);
      return !(x < std::min(ax, bx) || x > std::max(ax, bx) || y < std::min(ay, by) ||
               y > std::max(ay, by)) &&
             orient_d(ax, ay, bx, by, x, y) == 0;
    };
    for (std::size_t k = 0; k < net.ea.size(); ++k) {
      const int a = net.ea[k], b = net.eb[k];
      if (!on_seg(a, b)) continue;
      if (x == idx(a) && y == idy(a)) return att.push_back({a, 0.0});
      if (x == idx(b) && y == idy(b)) return att.push_back({b, 0.0});
      att.push_back({a, dist(x, y, idx(a), idy(a))});
      att.push_back({b, dist(x, y, idx(b), idy(b))});
      return;
    }
    for (std::size_t k = 0; k < net.sa.size(); ++k) {
      const int a = net.sa[k], b = net.sb[k];
      if (!on_seg(a, b)) continue;
      for (int e : {a, b}) {
        const double ex = idx(e), ey = idy(e);
        if (x == ex && y == ey) return att.assign(1, {e, 0.0});
        if (!base.blocked(x, y, ex, ey, S)) att.push_back({e, dist(x, y, ex, ey)});
      }
      // a free point inside a stub's free part: its free ends, or none (isolated)
      if (!att.empty()) return;
    }
  }

  // is a target polygon on polygon x's side of the bridge with child c?
  bool target_side(const MeshScratch& MS, int x, int c) const {
    const bool xin = ptin[c] <= ptin[x] && ptin[x] < ptout[c];
    for (int t : MS.ppolys)
      if ((ptin[c] <= ptin[t] && ptin[t] < ptout[c]) == xin) return true;
    return false;
  }

  static int side(const Lim& l, double rx, double ry, double x, double y) {
    return cross_sign(l.x1, l.y1, l.x2, l.y2, rx, ry, x, y);
  }

  using Root = MeshRoot;
  using Node = MeshNode;

  // |ab|: sqrt of the sum of squares where that neither overflows nor loses digits to
  // underflow (as accurate as hypot, within an ulp, and much faster), hypot elsewhere
  static double dist(double ax, double ay, double bx, double by) {
    const double dx = ax - bx, dy = ay - by;
    const double s = dx * dx + dy * dy;
    if (s > 0x1p-900 && s < 0x1p900) return std::sqrt(s);
    return std::hypot(dx, dy);
  }

  // Polyanya's heuristic: the least |r x| + |x t| over x in the interval
  double heuristic(const Node& N, const Root& r, double tx, double ty) const {
    const int off = M.poff[N.poly], m = M.poff[N.poly + 1] - off;
    const int a = M.pv[off + N.k], b = M.pv[off + (N.k + 1) % m];
    const double ax = M.vx[a], ay = M.vy[a], bx = M.vx[b], by = M.vy[b];
    const double ex = bx - ax, ey = by - ay;
    auto param = [&](const Lim& l) {  // where the ray meets line(a, b), as a fraction
      const double dx = l.x2 - l.x1, dy = l.y2 - l.y1;
      const double den = dx * ey - dy * ex;
      if (!(den != 0)) return 0.5;
      const double u = (dx * (r.y - ay) - dy * (r.x - ax)) / den;
      return std::min(1.0, std::max(0.0, u));
    };
    double uL = param(N.L), uR = param(N.R);
    if (uL > uR) std::swap(uL, uR);
    // the target mirrored across the edge when on the root's side
    double px = tx, py = ty;
    const double el2 = ex * ex + ey * ey;
    const double sr = ex * (r.y - ay) - ey * (r.x - ax);
    const double st = ex * (ty - ay) - ey * (tx - ax);
    if (el2 > 0 && ((sr < 0 && st < 0) || (sr > 0 && st > 0))) {
      const double k = 2 * st / el2;
      px = tx + k * ey;
      py = ty - k * ex;
    }
    const double dx = px - r.x, dy = py - r.y;
    const double den = dx * ey - dy * ex;
    if (den != 0) {
      const double u = (dx * (r.y - ay) - dy * (r.x - ax)) / den;
      if (u >= uL && u <= uR) return dist(r.x, r.y, px, py);
    }
    const double lx = ax + uL * ex, ly = ay + uL * ey, rx = ax + uR * ex, ry = ay + uR * ey;
    return std::min(dist(r.x, r.y, lx, ly) + dist(lx, ly, px, py),
                    dist(r.x, r.y, rx, ry) + dist(rx, ry, px, py));
  }

  // a PlanStatus (planning.hpp; PLAN_OUTSIDE_MESH: the caller meshes a larger box)
  int query(double sx, double sy, double gx, double gy, std::vector<double>& out, int& grp,
            PlanScratch& S, MeshScratch& MS) const {
    n_expanded = n_pushed = 0;
    if (int st = base.query_front(sx, sy, gx, gy, out, grp, S); st >= 0) return st;
    for (double x : {sx, gx})
      if (x < mb[0] || x > mb[2]) return PLAN_OUTSIDE_MESH;
    for (double y : {sy, gy})
      if (y < mb[1] || y > mb[3]) return PLAN_OUTSIDE_MESH;
    M.locate(sx, sy, MS.spolys);
    M.locate(gx, gy, MS.tpolys);
    MS.satt.clear();
    MS.gatt.clear();
    if (MS.spolys.empty()) locate_net(sx, sy, MS.satt, S);
    if (MS.tpolys.empty()) locate_net(gx, gy, MS.gatt, S);
    // an isolated free point (or on a part of the network that the mesh does not hold)
    if ((MS.spolys.empty() && MS.satt.empty()) || (MS.tpolys.empty() && MS.gatt.empty()))
      return PLAN_NO_PATH;
    if ((int)MS.best.size() != nids() || (int)MS.tmark.size() != M.npoly())
      MS.init(nids(), M.npoly());
    // the goal on the network is reached through its ends, or a portal of their network
    MS.ppolys = MS.tpolys;
    for (const auto& [w, d] : MS.gatt) {
      (void)d;
      const int c = w < (int)net.comp.size() ? net.comp[w] : -1;
      for (int v = 0; v < M.nvert(); ++v)
        if (v == w || (c >= 0 && (M.vflag[v] & PORTAL) && net.comp[v] == c))
          MS.ppolys.insert(MS.ppolys.end(), M.vp.begin() + M.vpoff[v],
                           M.vp.begin() + M.vpoff[v + 1]);
    }
    for (int p : MS.tpolys) MS.tmark[p] = 1;
    int st = search(sx, sy, gx, gy, out, MS);
    for (int p : MS.tpolys) MS.tmark[p] = 0;
    for (int v : MS.touched) MS.best[v] = std::numeric_limits<double>::infinity();
    MS.touched.clear();
    return st;
  }

  int search(double sx, double sy, double tx, double ty, std::vector<double>& out,
             MeshScratch& MS) const;
};

// One query's search (MeshPlanner::search): Polyanya's nodes over the planner's mesh and
// network, kept in the query's scratch, towards the target (tx, ty).
struct MeshSearch {
  using Root = MeshRoot;
  using Node = MeshNode;
  using QE = std::pair<double, int>;
  const MeshPlanner& P;
  const NavMesh& M;
  MeshScratch& MS;
  std::vector<Root>& roots;
  std::vector<Node>& nodes;
  std::vector<QE>& heap;
  const double tx, ty;

  MeshSearch(const MeshPlanner& planner, MeshScratch& ms, double tx_, double ty_)
      : P(planner), M(planner.M), MS(ms), roots(ms.roots), nodes(ms.nodes), heap(ms.heap),
        tx(tx_), ty(ty_) {
    roots.clear();
    nodes.clear();
    heap.clear();
  }

  static double dist(double ax, double ay, double bx, double by) {
    return MeshPlanner::dist(ax, ay, bx, by);
  }
  static int side(const Lim& l, double rx, double ry, double x, double y) {
    return MeshPlanner::side(l, rx, ry, x, y);
  }

  void push(const Node& N) {
    nodes.push_back(N);
    heap.push_back({N.f, (int)nodes.size() - 1});
    std::push_heap(heap.begin(), heap.end(), std::greater<QE>());
    ++P.n_pushed;
  }
  void push_final(int root, double g) {
    Node N{};
    N.f = N.g = g;
    N.kind = 2;
    N.root = root;
    push(N);
  }
  bool allowed(const Node& V, double x, double y) const {
    if (V.restr == 0) return true;
    return V.restr * side(V.R, M.vx[V.v], M.vy[V.v], x, y) >= 0;
  }
  void push_interval(int root, int nb, int k, const Lim& L, const Lim& R) {
    const int c = P.bsub[M.poff[nb] + k];
    if (P.prune && c >= 0 && !P.target_side(MS, nb, c)) return;
    Node N{};
    N.kind = 0;
    N.root = root;
    N.poly = nb;
    N.k = k;
    N.L = L;
    N.R = R;
    N.g = roots[root].g;
    N.f = N.g + P.heuristic(N, roots[root], tx, ty);
    push(N);
  }
  void push_vertex(int v, int parent, double g, int restr, int e1, const Lim& line,
                   int on_net = 0) {
    if (!(g < MS.best[v])) return;
    if (MS.best[v] == std::numeric_limits<double>::infinity()) MS.touched.push_back(v);
    MS.best[v] = g;
    Node N{};
    N.kind = 1;
    N.v = v;
    N.root = parent;
    N.g = g;
    N.f = g + dist(P.idx(v), P.idy(v), tx, ty);
    N.restr = restr;
    N.e1 = e1;
    N.net = on_net || v >= M.nvert();
    N.R = line;
    push(N);
  }
  // along the zero-width segments from vertex v (the root `root`, reached with g): a
  // mesh vertex reached this way expands its whole fan; the goal on the network ends
  void expand_net(int root, int v, double g) {
    for (const auto& [w, d] : MS.gatt)
      if (w == v) push_final(root, g + d);
    if (!P.net.on(v)) return;
    for (int t = P.net.off[v]; t < P.net.off[v + 1]; ++t) {
      const int w = P.net.adj[t];
      push_vertex(w, root, g + dist(P.idx(v), P.idy(v), P.idx(w), P.idy(w)), 0, -1, Lim{});
    }
  }
  // a mesh vertex the goal on the network is reached from (an end of its segment or
  // stub that is no portal: it is one for this query)
  bool goal_end(int v) const {
    for (const auto& wd : MS.gatt)
      if (wd.first == v) return true;
    return false;
  }
  // a path from the root (rx, ry) may bend at vertex v: at a junction every way, at a
  // corner towards the obstacle there -- the side(s) of the line root-v that the
  // corner's boundary edges lie on (both when the line runs into the obstacle)
  // (V: the vertex node whose root this is -- its restriction must allow v; the length
  // test first, the cheapest to fail: push_vertex would refuse the node the same way)
  void bend(int v, int root, double rx, double ry, double g, const Node* V) {
    const double gv = g + dist(rx, ry, M.vx[v], M.vy[v]);
    if (!(gv < MS.best[v])) return;
    if (V && !allowed(*V, M.vx[v], M.vy[v])) return;
    if (M.vflag[v] & JUNCTION) {
      push_vertex(v, root, gv, 0, -1, Lim{});
      return;
    }
    // a portal where no path bends in the mesh: on along its zero-width segments only
    const bool portal = (M.vflag[v] & PORTAL) || goal_end(v);
    if (!(M.vflag[v] & CORNER)) {
      if (portal) push_vertex(v, root, gv, 0, -1, Lim{}, 1);
      return;
    }
    const int p = M.vprev[v], q = M.vnext[v];
    const int sp = orient_d(rx, ry, M.vx[v], M.vy[v], M.vx[p], M.vy[p]);
    const int sq = orient_d(rx, ry, M.vx[v], M.vy[v], M.vx[q], M.vy[q]);
    const int restr = (sp >= 0 && sq >= 0) ? 1 : (sp <= 0 && sq <= 0) ? -1 : 0;
    // the line root-v runs into the obstacle: no shortest path bends here (every way
    // out of v turns away from the obstacle, and the root sees past v on both sides)
    if (restr == 0) {
      if (portal) push_vertex(v, root, gv, 0, -1, Lim{}, 1);
      return;
    }
    // the edge of the corner nearest the ray beyond v (a turn of less than 180 degrees
    // from it towards the obstacle): a shortest path bending at v leaves between that
    // ray and this edge
    const int turn = orient_d(M.vx[v], M.vy[v], M.vx[p], M.vy[p], M.vx[q], M.vy[q]);
    const int e1 = turn == 0 ? -1 : restr * turn > 0 ? p : q;
    // that edge runs on along the line root-v: the path goes straight on (no bend)
    if (e1 >= 0 && orient_d(rx, ry, M.vx[v], M.vy[v], M.vx[e1], M.vy[e1]) == 0) {
      if (portal) push_vertex(v, root, gv, 0, -1, Lim{}, 1);
      return;
    }
    push_vertex(v, root, gv, restr, e1, Lim{rx, ry, M.vx[v], M.vy[v]});
  }
  // Is polygon Z (around the corner of vertex node V) wholly beyond the line through
  // the corner and its edge e1 (strictly, away from the ray beyond the corner)? Z lies
  // in the cone at the corner between its two neighbours in Z (Z is convex).
  bool beyond_edge(const Node& V, int Z) const {
    const int off = M.poff[Z], m = M.poff[Z + 1] - off;
    const int v = V.v, e = V.e1;
    int i = 0;
    while (i < m && M.pv[off + i] != v) ++i;
    if (i == m) return false;
    const int za = M.pv[off + (i + 1) % m], zb = M.pv[off + (i + m - 1) % m];
    const double cx = M.vx[v], cy = M.vy[v], ex = M.vx[e], ey = M.vy[e];
    return V.restr * orient_d(cx, cy, ex, ey, M.vx[za], M.vy[za]) > 0 &&
           V.restr * orient_d(cx, cy, ex, ey, M.vx[zb], M.vy[zb]) > 0;
  }
  // does a bridge ending at vertex v separate polygon Z from every target polygon?
  bool cut_off(int v, int Z) const {
    for (int t = P.vboff[v]; t < P.vboff[v + 1]; ++t)
      if (!P.target_side(MS, Z, P.vb[t])) return true;
    return false;
  }
  // a root at point (x, y) (vertex v or -1): nodes for the far edges of its polygons
  void expand_point(int root, const std::vector<int>& fan, const Node* V) {
    const double rx = roots[root].x, ry = roots[root].y, g = roots[root].g;
    for (int Z : fan) {
      if (V && V->e1 >= 0 && beyond_edge(*V, Z)) continue;
      if (V && P.prune && cut_off(V->v, Z)) continue;
      if (MS.tmark[Z] && (!V || allowed(*V, tx, ty))) push_final(root, g + dist(rx, ry, tx, ty));
      const int off = M.poff[Z], m = M.poff[Z + 1] - off;
      for (int i = 0; i < m; ++i) {  // the polygon's corners and junctions: in sight
        const int u = M.pv[off + i];
        if ((M.vflag[u] || goal_end(u)) && u != roots[root].v &&
            !(M.vx[u] == rx && M.vy[u] == ry))
          bend(u, root, rx, ry, g, V);
      }
      for (int i = 0; i < m; ++i) {
        const int zi = M.pv[off + i], zj = M.pv[off + (i + 1) % m];
        if (orient_d(M.vx[zi], M.vy[zi], M.vx[zj], M.vy[zj], rx, ry) == 0) continue;
        const int nb = M.pn[off + i];
        if (nb < 0) continue;
        // seen from the root: zj left, zi right
        Lim L{rx, ry, M.vx[zj], M.vy[zj]}, R{rx, ry, M.vx[zi], M.vy[zi]};
        if (V && V->restr != 0 && !restrict_edge(*V, rx, ry, zi, zj, L, R)) continue;
        push_interval(root, nb, M.pe[off + i], L, R);
      }
    }
  }
  // The far edge zi -> zj seen from the root (rx, ry) of vertex node V with a
  // restriction: false when the restriction leaves none (or one point) of it, else its
  // rays L, R, the one beyond the restriction's line replaced by that line's ray.
  bool restrict_edge(const Node& V, double rx, double ry, int zi, int zj, Lim& L,
                     Lim& R) const {
    const int sa = V.restr * side(V.R, rx, ry, M.vx[zj], M.vy[zj]);
    const int sb = V.restr * side(V.R, rx, ry, M.vx[zi], M.vy[zi]);
    if (sa < 0 && sb < 0) return false;
    if ((sa == 0 && sb < 0) || (sb == 0 && sa < 0)) return false;  // one point
    if (sa < 0 || sb < 0) {
      // the restriction's line cuts the edge: its ray into the cone bounds it
      const Lim& d = V.R;
      const int inL = cross_sign(rx, ry, M.vx[zj], M.vy[zj], d.x1, d.y1, d.x2, d.y2);
      const int inR = cross_sign(rx, ry, M.vx[zi], M.vy[zi], d.x1, d.y1, d.x2, d.y2);
      Lim ray = (inL <= 0 && inR >= 0) ? d : Lim{d.x2, d.y2, d.x1, d.y1};
      if (sa < 0)
        L = ray;
      else
        R = ray;
    }
    return true;
  }
  // the start (sx, sy): its root and the nodes it pushes
  void start(double sx, double sy) {
    int sv = -1;
    for (int p : MS.spolys) {
      for (int i = M.poff[p]; i < M.poff[p + 1]; ++i)
        if (M.vx[M.pv[i]] == sx && M.vy[M.pv[i]] == sy) sv = M.pv[i];
    }
    // the start on the network: one of its vertices, or inside a segment
    const bool at_vertex = MS.satt.size() == 1 && P.idx(MS.satt[0].first) == sx &&
                           P.idy(MS.satt[0].first) == sy;
    if (at_vertex) sv = MS.satt[0].first;
    roots.push_back(Root{sx, sy, 0.0, -1, sv});
    if (sv >= 0) {
      MS.best[sv] = 0.0;
      MS.touched.push_back(sv);
    }
    expand_point(0, MS.spolys, nullptr);
    if (sv >= 0) expand_net(0, sv, 0.0);
    if (!at_vertex)
      for (const auto& [w, d] : MS.satt) push_vertex(w, 0, d, 0, -1, Lim{});
  }
  // an interval node N: the cone through its polygon onto the far edges, the target
  // when in the polygon and the cone, the bends at corners and junctions in the cone
  void expand_interval(const Node& N) {
    const Root& r = roots[N.root];
    if (r.v >= 0 && r.g > MS.best[r.v]) return;  // root-level pruning
    const double rx = r.x, ry = r.y, g = r.g;
    const int rid = N.root;
    const int Pl = N.poly, off = M.poff[Pl], m = M.poff[Pl + 1] - off;
    // the chain from b (right) around to a (left)
    int cv[64];
    int sL[64], sR[64];
    std::vector<int> cvb, sLb, sRb;
    int *c = cv, *L = sL, *R = sR;
    if (m > 64) {
      cvb.resize(m), sLb.resize(m), sRb.resize(m);
      c = cvb.data(), L = sLb.data(), R = sRb.data();
    }
    for (int j = 0; j < m; ++j) {
      c[j] = M.pv[off + (N.k + 1 + j) % m];
      L[j] = side(N.L, rx, ry, M.vx[c[j]], M.vy[c[j]]);
      R[j] = side(N.R, rx, ry, M.vx[c[j]], M.vy[c[j]]);
    }
    if (MS.tmark[Pl] && side(N.L, rx, ry, tx, ty) <= 0 && side(N.R, rx, ry, tx, ty) >= 0)
      push_final(rid, g + dist(rx, ry, tx, ty));
    for (int j = 0; j + 1 < m; ++j) {
      // far edge from c[j] (right) to c[j + 1] (left)
      if (R[j + 1] < 0 || L[j] > 0) continue;
      if (R[j + 1] == 0 && R[j] < 0) continue;  // meets the cone at one point
      if (L[j] == 0 && L[j + 1] > 0) continue;
      const int ei = (N.k + 1 + j) % m;
      const int nb = M.pn[off + ei];
      if (nb < 0) continue;
      Lim cR = R[j] >= 0 ? Lim{rx, ry, M.vx[c[j]], M.vy[c[j]]} : N.R;
      Lim cL = L[j + 1] <= 0 ? Lim{rx, ry, M.vx[c[j + 1]], M.vy[c[j + 1]]} : N.L;
      push_interval(rid, nb, M.pe[off + ei], cL, cR);
    }
    // bends: corners at the ends of the interval's edge, junctions in the cone
    for (int j = 0; j < m; ++j)
      if ((M.vflag[c[j]] || goal_end(c[j])) && L[j] <= 0 && R[j] >= 0)
        bend(c[j], rid, rx, ry, g, nullptr);
  }
  // the path of final node N: its chain of roots, then the target
  void path(const Node& N, std::vector<double>& out) const {
    std::vector<int> chain;
    for (int r = N.root; r >= 0; r = roots[r].parent) chain.push_back(r);
    for (int t = (int)chain.size() - 1; t >= 0; --t) {
      out.push_back(roots[chain[t]].x);
      out.push_back(roots[chain[t]].y);
    }
    if (!(out[out.size() - 2] == tx && out.back() == ty)) {  // the goal is the last root
      out.push_back(tx);
      out.push_back(ty);
    }
  }
  // A* over the nodes from the start: PLAN_OK with the path in out, or PLAN_NO_PATH
  int run(double sx, double sy, std::vector<double>& out) {
    start(sx, sy);
    std::vector<int>& fan = MS.fan;
    while (!heap.empty()) {
      const int id = heap.front().second;
      std::pop_heap(heap.begin(), heap.end(), std::greater<QE>());
      heap.pop_back();
      const Node N = nodes[id];
      if (N.kind == 2) {
        path(N, out);
        return PLAN_OK;
      }
      ++P.n_expanded;
      if (N.kind == 1) {
        if (N.g > MS.best[N.v]) continue;
        roots.push_back(Root{P.idx(N.v), P.idy(N.v), N.g, N.root, N.v});
        const int root = (int)roots.size() - 1;
        if (!N.net) {
          fan.assign(M.vp.begin() + M.vpoff[N.v], M.vp.begin() + M.vpoff[N.v + 1]);
          expand_point(root, fan, &N);
        }
        expand_net(root, N.v, N.g);
        continue;
      }
      expand_interval(N);
    }
    return PLAN_NO_PATH;
  }
};

inline int MeshPlanner::search(double sx, double sy, double tx, double ty,
                               std::vector<double>& out, MeshScratch& MS) const {
  return MeshSearch(*this, MS, tx, ty).run(sx, sy, out);
}

// ------------------------------------------------------------------------------------
// what the bindings run (planning_queries.hpp has the visibility graph's)

// The mesh planner's queries, one scratch for all.
inline void query_many(const MeshPlanner& mp, const double* s, const double* g,
                       std::size_t n, PlanAnswers<double>& A) {
  PlanScratch S;
  S.init((std::size_t)mp.base.items());
  MeshScratch MS;
  MS.init(mp.nids(), mp.M.npoly());
  query_loop(s, g, n, [&](double sx, double sy, double gx, double gy, std::vector<double>& out,
                          int& grp) { return mp.query(sx, sy, gx, gy, out, grp, S, MS); }, A);
}

// One query of the mesh planner.
inline int query_one(const MeshPlanner& mp, double sx, double sy, double gx, double gy,
                     std::vector<double>& out, int& grp) {
  PlanScratch S;
  S.init((std::size_t)mp.base.items());
  // kept per thread between calls (query() sizes it to the mesh; every query leaves it
  // cleared)
  thread_local MeshScratch MS;
  return mp.query(sx, sy, gx, gy, out, grp, S, MS);
}

// The mesh as arrays: vertices (2 per vertex), polygon offsets, polygon vertex ids, flags.
inline void mesh_arrays(const NavMesh& M, std::vector<double>& xy, std::vector<i64>& off,
                        std::vector<i64>& pv, std::vector<i64>& fl) {
  xy.resize(2 * M.vx.size());
  for (std::size_t i = 0; i < M.vx.size(); ++i) {
    xy[2 * i] = M.vx[i];
    xy[2 * i + 1] = M.vy[i];
  }
  off.assign(M.poff.begin(), M.poff.end());
  pv.assign(M.pv.begin(), M.pv.end());
  fl.assign(M.vflag.begin(), M.vflag.end());
}

// The zero-width segments of the mesh planner's network, (ax, ay, bx, by) each.
inline void network_segments(const MeshPlanner& mp, std::vector<double>& seg) {
  seg.clear();
  for (std::size_t k = 0; k < mp.net.ea.size(); ++k)
    seg.insert(seg.end(), {mp.idx(mp.net.ea[k]), mp.idy(mp.net.ea[k]), mp.idx(mp.net.eb[k]),
                           mp.idy(mp.net.eb[k])});
}

}  // namespace mk
