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
// no smaller length is not expanded again), the pruning at the mesh's bridges
// (navmesh_bridges.hpp), the pruning of dominated intervals (an interval every point of
// which a path through an end of its edge reaches strictly sooner: MeshPlanner::
// dominated) and the larger of two admissible heuristics -- Polyanya's (the shortest
// root-interval-target distance, the target mirrored across the edge when on the root's
// side) and the landmark bound (navmesh_landmarks.hpp: exact geodesic distances to a few
// landmarks, made at preparation where the straight line is a poor guide) -- make it
// A*. On the network: a portal in sight is a vertex node (one that only
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
#include "navmesh_bridges.hpp"
#include "navmesh_build.hpp"
#include "navmesh_landmarks.hpp"
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
  std::vector<std::pair<int, double>> tseen;       // the vertices the goal sees, lengths
  LandmarkQuery lq;           // the landmark bounds of the query (navmesh_landmarks.hpp)
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

  MeshBridges br;  // the cul-de-sac pruning (navmesh_bridges.hpp)
  bool prune = true;  // the bridge pruning on (tests compare the search without it)
  // landmark lower bounds (navmesh_landmarks.hpp): n_landmarks tables made at build,
  // used by the queries while use_landmarks (tests compare the search without them)
  MeshLandmarks lm;
  int n_landmarks = 8;
  // the tables are made only where shortest paths between probe pairs are longer than
  // the straight distance by this fraction on the median (elsewhere Polyanya's
  // heuristic is nearly exact and the tables would not pay for their preparation), and
  // kept only where they cut the probes' nodes (min_detour < 0: made and kept always)
  double min_detour = 0.02;
  bool use_landmarks = true;
  bool use_dominance = true;  // the pruning of dominated intervals (below)
  // the rounding of lengths: a length summed over the search (at most nids() segments)
  // is within eta of itself, relatively; scale: the meshed box's largest coordinate
  double eta = 0, scale = 0;

  int build(const double* meshbox) {
    base.build_base();
    for (int q = 0; q < 4; ++q) mb[q] = meshbox[q];
    status = M.build(base, mb);
    if (status != MESH_OK) return status;
    build_navnet(base, M.vx, M.vy, net);
    for (int v = 0; v < M.nvert(); ++v)
      if (net.on(v)) M.vflag[v] |= PORTAL;
    br.build(M, net);
    eta = 4.0 * (nids() + 16) * 0x1p-53;
    scale = std::max({std::fabs(mb[0]), std::fabs(mb[1]), std::fabs(mb[2]), std::fabs(mb[3])});
    build_landmarks();
    return status;
  }
  void build_landmarks();  // after MeshSearch (its sweeps make the tables)
  double probe(const std::vector<int>& cand, i64& expanded) const;
  void sweep(int v, std::vector<double>& dist, MeshScratch& MS) const;

  // vertex ids of the search: the mesh's, then the network's extra vertices
  int nids() const { return net.size(); }
  double idx(int id) const { return id < M.nvert() ? M.vx[id] : net.ex[id - M.nvert()]; }
  double idy(int id) const { return id < M.nvert() ? M.vy[id] : net.ey[id - M.nvert()]; }

  // Where (x, y) lies on the network: the ends of its segment with their distances, or
  // the one vertex it is; on stubs, the search vertices among their ends that the point
  // sees along them (S: Planner::blocked's scratch); empty when nowhere on it.
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
    // on stubs: the ends of every stub whose free part holds the point (a crossing of
    // two stubs, or one's far end in the other's free part), those the search has
    auto search_vertex = [&](int e) { return e < M.nvert() || net.on(e); };
    for (std::size_t k = 0; k < net.sa.size(); ++k) {
      const int a = net.sa[k], b = net.sb[k];
      if (!on_seg(a, b)) continue;
      for (int e : {a, b}) {
        if (!search_vertex(e)) continue;
        const double ex = idx(e), ey = idy(e);
        if (x == ex && y == ey) return att.assign(1, {e, 0.0});
        bool seen = false;
        for (const auto& wd : att) seen = seen || wd.first == e;
        if (!seen && !base.blocked(x, y, ex, ey, S)) att.push_back({e, dist(x, y, ex, ey)});
      }
    }
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

  // Node N's interval on its edge a -> b (e = b - a, el = |e|): the fractions uL <= uR
  // of e (0 at a) where its rays from the root r meet the edge's line, each moved
  // outwards by a bound on its rounding error and clamped to [0, 1] (the whole edge
  // where that bound is not small), so that the exact interval [p, q] lies inside.
  struct Span {
    int a, b;
    double ax, ay, ex, ey, el, uL, uR;
    double x(double u) const { return ax + u * ex; }
    double y(double u) const { return ay + u * ey; }
  };
  void span(const Node& N, const Root& r, Span& E) const {
    constexpr double eps = 0x1p-53;
    const int off = M.poff[N.poly], m = M.poff[N.poly + 1] - off;
    E.a = M.pv[off + N.k];
    E.b = M.pv[off + (N.k + 1 == m ? 0 : N.k + 1)];
    E.ax = M.vx[E.a], E.ay = M.vy[E.a], E.ex = M.vx[E.b] - E.ax, E.ey = M.vy[E.b] - E.ay;
    E.el = dist(0, 0, E.ex, E.ey);
    bool whole = false;
    // where the ray meets the edge's line, as a fraction, and its rounding error bound
    auto param = [&](const Lim& l, double& err) {
      const double dx = l.x2 - l.x1, dy = l.y2 - l.y1;
      const double den = dx * E.ey - dy * E.ex, dabs = std::fabs(dx * E.ey) + std::fabs(dy * E.ex);
      const double ny = dx * (r.y - E.ay), nx = dy * (r.x - E.ax);
      const double u = (ny - nx) / den;
      whole |= !(std::fabs(den) > 16 * eps * dabs);
      err = 8 * eps * (std::fabs(ny) + std::fabs(nx) + std::fabs(u) * dabs) / std::fabs(den) +
            2 * eps * std::fabs(u);
      return u;
    };
    double eL, eR;
    E.uL = param(N.L, eL);
    E.uR = param(N.R, eR);
    if (E.uL > E.uR) {
      std::swap(E.uL, E.uR);
      std::swap(eL, eR);
    }
    if (whole || !(eL - eL == 0) || !(eR - eR == 0)) {
      E.uL = 0;
      E.uR = 1;
      return;
    }
    E.uL = std::min(1.0, std::max(0.0, E.uL - eL));
    E.uR = std::min(1.0, std::max(0.0, E.uR + eR));
  }

  // Polyanya's heuristic: the least |r x| + |x t| over x in the interval (dp = |r p|,
  // dq = |r q|)
  double heuristic(const Span& E, const Root& r, double dp, double dq, double tx,
                   double ty) const {
    const double ax = E.ax, ay = E.ay, ex = E.ex, ey = E.ey, uL = E.uL, uR = E.uR;
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
    return std::min(dp + dist(lx, ly, px, py), dq + dist(rx, ry, px, py));
  }

  // the least |r x| over x in the interval (the sweep's order)
  double interval_dist(const Span& E, const Root& r) const {
    const double el2 = E.ex * E.ex + E.ey * E.ey;
    double u = el2 > 0 ? ((r.x - E.ax) * E.ex + (r.y - E.ay) * E.ey) / el2 : 0.0;
    u = std::min(E.uR, std::max(E.uL, u));
    return dist(r.x, r.y, E.x(u), E.y(u));
  }

  // The landmark bound of a node (root r, interval [p, q] on edge a -> b, p nearer a,
  // dp = |r p|, dq = |r q|): every path through it is at least g + |r x| + d(x, t) for
  // an x there, and d(x, t) >= d(a, t) - |a x| (the edge is free), so at least
  // g + |r q| + lb(a) - |a q| (|r x| - |a x| does not increase from p to q); likewise
  // g + |r p| + lb(b) - |b p|; and g + lb(r).
  double landmark_bound(const Span& E, const Root& r, double dp, double dq,
                        LandmarkQuery& Q) const {
    const double A = dq + Q.at(lm, E.a) - E.uR * E.el;
    const double B = dp + Q.at(lm, E.b) - (1 - E.uL) * E.el;
    const double R = r.v >= 0 ? Q.at(lm, r.v) : 0.0;
    return std::max(R, std::max(A, B) - Q.slack);
  }

  // Dominated intervals. A node (root r, interval [p, q] on edge a -> b, p nearer a)
  // reaches x there at g + |r x|; a path known to reach a at da reaches x at da + |a x|
  // (along the free edge). Where da + |a x| < g + |r x| at every x of the interval
  // (g + |r x| - |a x| does not increase from p to q: at q is enough), every path
  // through the node is strictly longer than one through a: no shortest path passes it
  // (it is not pushed). Likewise through b (at p). Strictly, by more than the rounding
  // of the lengths: a shortest path is never lost, ties included.
  bool dominated(const Span& E, const Root& r, double dp, double dq, double da,
                 double db) const {
    const double vq = r.g + dq, vp = r.g + dp;
    return vq - (da + E.uR * E.el) > eta * (4 * vq + 64 * scale) ||
           vp - (db + (1 - E.uL) * E.el) > eta * (4 * vp + 64 * scale);
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
    if (use_landmarks && !lm.empty()) {
      // the goal sees the vertices of its cells, or the ends it attaches to
      MS.tseen.clear();
      for (int p : MS.tpolys)
        for (int i = M.poff[p]; i < M.poff[p + 1]; ++i)
          MS.tseen.push_back({M.pv[i], dist(gx, gy, M.vx[M.pv[i]], M.vy[M.pv[i]])});
      if (MS.tpolys.empty()) MS.tseen = MS.gatt;
      MS.lq.target(lm, MS.tseen, scale);
    }
    int st = search(sx, sy, gx, gy, out, MS);
    MS.lq.clear();
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
  // sweep mode (rec: per vertex id, the least length it was seen with): no target, no
  // bridge pruning, nodes in the order of their least length
  double* rec;
  const bool prune;
  LandmarkQuery* lq;  // the query's landmark bounds, or none

  MeshSearch(const MeshPlanner& planner, MeshScratch& ms, double tx_, double ty_,
             double* rec_ = nullptr)
      : P(planner), M(planner.M), MS(ms), roots(ms.roots), nodes(ms.nodes), heap(ms.heap),
        tx(tx_), ty(ty_), rec(rec_), prune(planner.prune && !rec_),
        lq(ms.lq.on && !rec_ ? &ms.lq : nullptr) {
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
  // the least length a path reaching vertex v is known with (+inf: none yet)
  double known(int v) const { return rec ? std::min(rec[v], MS.best[v]) : MS.best[v]; }
  void see(int v, double d) {
    if (d < rec[v]) rec[v] = d;
  }
  bool allowed(const Node& V, double x, double y) const {
    if (V.restr == 0) return true;
    return V.restr * side(V.R, M.vx[V.v], M.vy[V.v], x, y) >= 0;
  }
  void push_interval(int root, int nb, int k, const Lim& L, const Lim& R) {
    const int c = P.br.bsub[M.poff[nb] + k];
    if (prune && c >= 0 && !P.br.target_side(MS.ppolys, nb, c)) return;
    Node N{};
    N.kind = 0;
    N.root = root;
    N.poly = nb;
    N.k = k;
    N.L = L;
    N.R = R;
    N.g = roots[root].g;
    const Root& r = roots[root];
    MeshPlanner::Span E;
    P.span(N, r, E);
    constexpr double inf = std::numeric_limits<double>::infinity();
    const double da = P.use_dominance ? known(E.a) : inf, db = P.use_dominance ? known(E.b) : inf;
    const double dp = dist(r.x, r.y, E.x(E.uL), E.y(E.uL));
    const double dq = dist(r.x, r.y, E.x(E.uR), E.y(E.uR));
    if ((da < inf || db < inf) && P.dominated(E, r, dp, dq, da, db)) return;
    N.f = N.g + (rec ? P.interval_dist(E, r) : P.heuristic(E, r, dp, dq, tx, ty));
    if (lq) N.f = std::max(N.f, N.g + P.landmark_bound(E, r, dp, dq, *lq));
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
    N.f = rec ? g : g + dist(P.idx(v), P.idy(v), tx, ty);
    if (lq) N.f = std::max(N.f, g + lq->at(P.lm, v));
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
    for (int t = P.br.vboff[v]; t < P.br.vboff[v + 1]; ++t)
      if (!P.br.target_side(MS.ppolys, Z, P.br.vb[t])) return true;
    return false;
  }
  // a root at point (x, y) (vertex v or -1): nodes for the far edges of its polygons
  void expand_point(int root, const std::vector<int>& fan, const Node* V) {
    const double rx = roots[root].x, ry = roots[root].y, g = roots[root].g;
    for (int Z : fan) {
      if (V && V->e1 >= 0 && beyond_edge(*V, Z)) continue;
      if (V && prune && cut_off(V->v, Z)) continue;
      if (MS.tmark[Z] && (!V || allowed(*V, tx, ty))) push_final(root, g + dist(rx, ry, tx, ty));
      const int off = M.poff[Z], m = M.poff[Z + 1] - off;
      if (rec)  // the root sees every vertex of its convex polygon
        for (int i = off; i < off + m; ++i)
          see(M.pv[i], g + dist(rx, ry, M.vx[M.pv[i]], M.vy[M.pv[i]]));
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
    if (rec)  // the vertices in the closed cone: seen through the interval
      for (int j = 0; j < m; ++j)
        if (L[j] <= 0 && R[j] >= 0) see(c[j], g + dist(rx, ry, M.vx[c[j]], M.vy[c[j]]));
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

// The lengths of shortest paths from mesh vertex v to every search vertex id (+inf where
// none): a sweep of the whole part of the mesh that v reaches (navmesh_landmarks.hpp).
inline void MeshPlanner::sweep(int v, std::vector<double>& dist, MeshScratch& MS) const {
  const double inf = std::numeric_limits<double>::infinity();
  if ((int)MS.best.size() != nids() || (int)MS.tmark.size() != M.npoly())
    MS.init(nids(), M.npoly());
  MS.spolys.assign(M.vp.begin() + M.vpoff[v], M.vp.begin() + M.vpoff[v + 1]);
  MS.satt.clear();
  MS.gatt.clear();
  MS.ppolys.clear();
  dist.assign(nids(), inf);
  std::vector<double> out;
  MeshSearch(*this, MS, M.vx[v], M.vy[v], dist.data()).run(M.vx[v], M.vy[v], out);
  for (int u : MS.touched) {
    dist[u] = std::min(dist[u], MS.best[u]);
    MS.best[u] = inf;
  }
  MS.touched.clear();
}

// The median detour (length / distance - 1) of shortest paths between probe pairs of
// the vertices cand, a fraction of the box's diagonal apart, and the nodes the searches
// expanded (the same pairs at every call).
inline double MeshPlanner::probe(const std::vector<int>& cand, i64& expanded) const {
  expanded = 0;
  if (cand.size() < 2) return 0;
  PlanScratch S;
  S.init((std::size_t)base.items());
  MeshScratch MS;
  std::vector<double> out, ex;
  std::uint64_t x = 0x9E3779B97F4A7C15ull;
  auto next = [&]() {
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    return cand[x % cand.size()];
  };
  const double diag = dist(mb[0], mb[1], mb[2], mb[3]);
  for (int t = 0; t < 200 && ex.size() < 12; ++t) {
    const int u = next(), w = next();
    const double ux = M.vx[u], uy = M.vy[u], wx = M.vx[w], wy = M.vy[w];
    const double e = dist(ux, uy, wx, wy);
    if (!(e >= diag / 16 && e <= diag / 4)) continue;
    int grp;
    const int st = query(ux, uy, wx, wy, out, grp, S, MS);
    expanded += n_expanded;
    if (st != PLAN_OK) continue;
    double len = 0;
    for (std::size_t i = 2; i + 1 < out.size(); i += 2)
      len += dist(out[i - 2], out[i - 1], out[i], out[i + 1]);
    ex.push_back(len / e - 1);
  }
  if (ex.empty()) return 0;
  std::sort(ex.begin(), ex.end());
  return ex[ex.size() / 2];
}

// The landmark tables: n_landmarks landmarks chosen farthest-first, the first the vertex
// of the largest connected part of the mesh farthest from that part's centre.
inline void MeshPlanner::build_landmarks() {
  lm = MeshLandmarks{};
  lm.n = nids();
  lm.eta = eta;
  const int P = M.npoly();
  if (n_landmarks <= 0 || P == 0) return;
  std::vector<int> size(P, 0);
  for (int p = 0; p < P; ++p) ++size[br.pcomp[p]];
  const int big = (int)(std::max_element(size.begin(), size.end()) - size.begin());
  double cx = 0, cy = 0, cn = 0;
  for (int p = 0; p < P; ++p)
    if (br.pcomp[p] == big)
      for (int i = M.poff[p]; i < M.poff[p + 1]; ++i) {
        cx += M.vx[M.pv[i]];
        cy += M.vy[M.pv[i]];
        cn += 1;
      }
  cx /= cn;
  cy /= cn;
  int v = -1;
  double far = -1;
  for (int p = 0; p < P; ++p)
    if (br.pcomp[p] == big)
      for (int i = M.poff[p]; i < M.poff[p + 1]; ++i) {
        const double d = dist(cx, cy, M.vx[M.pv[i]], M.vy[M.pv[i]]);
        if (d > far) {
          far = d;
          v = M.pv[i];
        }
      }
  std::vector<int> cand;
  for (int p = 0; p < P; ++p)
    if (br.pcomp[p] == big)
      cand.insert(cand.end(), M.pv.begin() + M.poff[p], M.pv.begin() + M.poff[p + 1]);
  std::sort(cand.begin(), cand.end());
  cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
  i64 before = 0, after = 0;
  if (min_detour >= 0 && probe(cand, before) < min_detour) return;
  // network vertices on no segment that are free points (a stub's far end in another
  // stub's free part): their distances through the search vertices a point there
  // attaches to
  std::vector<std::pair<int, std::vector<std::pair<int, double>>>> loose;
  {
    PlanScratch S;
    S.init((std::size_t)base.items());
    std::vector<std::pair<int, double>> att;
    for (int u = M.nvert(); u < nids(); ++u) {
      if (net.on(u) || !base.in_box(idx(u), idy(u))) continue;
      locate_net(idx(u), idy(u), att, S);
      if (!att.empty()) loose.push_back({u, att});
    }
  }
  MeshScratch MS;
  std::vector<double> dist;
  // kept where they cut the probes' nodes by a tenth (not where the bridges already
  // confine the search to the path, as in a perfect maze): checked when half of them
  // are made (the others are not made then), and at the end
  auto pays = [&]() {
    if (min_detour < 0) return true;
    probe(cand, after);
    return 10 * (before - after) >= before;
  };
  bool keep = true;
  for (int l = 0; l < n_landmarks && v >= 0; ++l) {
    sweep(v, dist, MS);
    for (const auto& [u, att] : loose)
      for (const auto& [w, d] : att) dist[u] = std::min(dist[u], dist[w] + d);
    lm.add(v, dist);
    v = lm.farthest(M.nvert());
    if (2 * (l + 1) == n_landmarks && !pays()) {
      keep = false;
      break;
    }
  }
  if (!keep || !pays()) lm = MeshLandmarks{};
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
