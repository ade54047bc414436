// navmesh_bridges.hpp -- the bridges of the navigation mesh (navmesh.hpp), for the
// search's cul-de-sac pruning (Polyanya's dead ends, generalised).
//
// In the graph of the polygons (joined by their shared edges, all polygons around a
// junction joined to each other: a path may pass the pinch, and all polygons around the
// portals of one zero-width network likewise: a path may pass between them), a bridge
// is a mesh edge e whose removal splits the graph. A path that crosses e into the side
// without the target must leave that side again, and only through the closed segment
// e; the part in between is no shorter than the segment on e between the two points
// (free: e is a mesh edge). So no interval is pushed across a bridge into a side
// without a target polygon, and a vertex node does not expand the polygons around it
// that a bridge at the vertex separates from every target polygon. The bends at e's
// ends are pushed by the node that reached e. Found once, at preparation, by Tarjan's
// lowlink; a side is a subtree of the DFS, so a side test is O(1).
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "navmesh_build.hpp"
#include "navnet.hpp"

namespace mk {

struct MeshBridges {
  // bsub: per polygon edge slot, the child polygon c of its bridge in the DFS tree (the
  // side of c is the subtree: ptin[c] <= ptin[x] < ptout[c]), -1 for no bridge;
  // vb (CSR vboff): per vertex, the children of the bridges that end at it;
  // pcomp: per polygon, the first polygon of its connected part (the DFS's root)
  std::vector<int> bsub, ptin, ptout, vboff, vb, pcomp;

  // is one of the target polygons on polygon x's side of the bridge with child c?
  bool target_side(const std::vector<int>& targets, int x, int c) const {
    const bool xin = ptin[c] <= ptin[x] && ptin[x] < ptout[c];
    for (int t : targets)
      if ((ptin[c] <= ptin[t] && ptin[t] < ptout[c]) == xin) return true;
    return false;
  }

  // the bridges of mesh M, with the zero-width network net on it
  void build(const NavMesh& M, const NavNet& net) {
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
    pcomp.assign(P, -1);
    bsub.assign(H, -1);
    std::vector<int> low(P, 0), pedge(P, -1), it(P, 0), stack;
    int timer = 0;
    for (int s = 0; s < P; ++s) {
      if (ptin[s] >= 0) continue;
      ptin[s] = low[s] = timer++;
      pcomp[s] = s;
      it[s] = aoff[s];
      stack.push_back(s);
      while (!stack.empty()) {
        const int p = stack.back();
        if (it[p] < aoff[p + 1]) {
          const auto [q, id] = adj[it[p]++];
          if (id == pedge[p]) continue;
          if (ptin[q] < 0) {
            ptin[q] = low[q] = timer++;
            pcomp[q] = s;
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
};

}  // namespace mk
