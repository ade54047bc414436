// overlay_run.hpp -- class Overlay: one overlay run (steps 1 to 4 of overlay.hpp: local
// vertices, candidate pairs and their classification, split points, pieces), with the
// declarations of the later steps defined in overlay_trace.hpp (sweep, windings,
// boundary, rings, holes) and overlay_lines.hpp (clipped polylines, lower-dimensional
// parts). Part of overlay.hpp (include that).
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <set>
#include <vector>

#include "boxes.hpp"
#include "overlay_geo.hpp"

namespace mk {
namespace ov {

class Overlay {
 public:
  explicit Overlay(Geo& g) : g_(g) {}

  // counters (for tests and limits)
  i64 n_pairs = 0, n_crossings = 0, n_vertices = 0, n_edges = 0;
  // work budget: a run that would node more crossings, or classify more candidate
  // pairs (box-overlapping edge pairs), stops (exceeded() is then true and the result is
  // empty); the caller reports RESOURCE
  i64 max_crossings = NO_LIMIT;
  i64 max_pairs = NO_LIMIT;
  bool exceeded() const { return over_; }
  // from this many edges on, candidate pairs come from a grid (boxes.hpp segment_pairs)
  i64 grid_min = 512;

  // The boundary of the selected region as exact edges (global vertex ids).
  void run(const std::vector<EdgeIn>& in, int rule, std::vector<BEdge>& out) {
    arrange(in, rule);
    out.clear();
    for (const BPiece& b : bnd_) out.push_back(BEdge{b.line, vg_[b.from], vg_[b.to]});
  }
  // The same, with some vertices already in sweep order: each list in `sorted` holds
  // global vertex ids in the order of boundary_vertices() (one id per point, no id in
  // two lists); the vertices of `in` that no list holds are sorted here. Lists are merged
  // in linear time, so a cascade does not sort the same vertices at every level.
  void run(const std::vector<EdgeIn>& in, int rule, std::vector<BEdge>& out,
           const std::vector<const std::vector<i64>*>& sorted) {
    lists_ = &sorted;
    run(in, rule, out);
    lists_ = nullptr;
  }
  void run(const std::vector<EdgeIn>& in, int rule, Rings& out,
           const std::vector<const std::vector<i64>*>& sorted) {
    lists_ = &sorted;
    run(in, rule, out);
    lists_ = nullptr;
  }
  // After a run: its boundary's vertices (global ids, one per point) in sweep order.
  void boundary_vertices(std::vector<i64>& out) const {
    out.clear();
    if (bnd_.empty()) return;
    const i64 nv = (i64)av_.size();
    std::vector<char> used(nv, 0);
    for (const BPiece& b : bnd_) used[b.from] = used[b.to] = 1;
    for (i64 v = 0; v < nv; ++v)  // ids are sweep ranks
      if (used[v]) out.push_back(av_[v]);
  }
  // The selected region as rings with holes.
  void run(const std::vector<EdgeIn>& in, int rule, Rings& out) {
    run_raw(in, rule, out);
    if (out.status == OK) finish_rounded(out);
  }
  // After a run with boundary edges out: the same region as rings (as run with rings out
  // would have given)
  void rings(Rings& out) {
    trace(out);
    if (out.status == OK) finish_rounded(out);
  }
  // as run, without the check after rounding (the check's own re-run uses it)
  void run_raw(const std::vector<EdgeIn>& in, int rule, Rings& out) {
    arrange(in, rule);
    if (over_) {
      out.clear();
      out.status = RESOURCE;
      return;
    }
    trace(out);
  }
  void finish_rounded(Rings& out);

  // Clipping polylines: `in` holds the polygons' edges (layers 0 and 1, as for `rule`)
  // and the polylines' edges on layer 2 (any nonzero weight; they change no winding
  // number). Keeps the parts of the polylines in the closed region the rule selects
  // (keep_inside), or in its open complement; where a polyline runs along the region's
  // boundary it is inside. The parts come out as polylines (rounded vertices, consecutive
  // equal ones dropped), each following the direction of its first input edge, joined
  // where exactly two parts meet; vertices where the part goes on along the same line are
  // dropped. RESOURCE when the work limits stop the run.
  int run_lines(const std::vector<EdgeIn>& in, int rule, bool keep_inside,
                std::vector<double>& xy, std::vector<i64>& off);

  // Lower-dimensional parts of the union of rings (layer 0, weight 1, every ring convex
  // and counter-clockwise, e.g. piece sums): points inside the regularized union that
  // lie in no ring's interior. Pieces of such points (segments where rings meet from
  // both sides, continued along the union's boundary where the same line goes on) come
  // out as polylines, isolated points (an exact fit) as points; coordinates rounded.
  // `rings` are the input edge lists, one per ring (for the point test).
  void degenerate(const std::vector<std::vector<EdgeIn>>& rings, std::vector<double>& lines,
                  std::vector<i64>& line_off, std::vector<double>& points);

 private:
  // One polyline of clipped pieces: vertices chain_v (arrangement ids), pieces chain_p
  // (indices into kept) between them; a vertex where the line goes on is dropped.
  void emit_chain(const std::vector<i64>& cv, const std::vector<i64>& cp,
                  const std::vector<i64>& kept, std::vector<double>& xy, std::vector<i64>& off);

  // Is global vertex v in the interior of one of the (convex, counter-clockwise) rings?
  void degenerate_points(const std::vector<std::vector<EdgeIn>>& rings,
                         const std::vector<char>& at_degen, const std::vector<char>& at_boundary,
                         std::vector<double>& points);
  bool covered(const std::vector<std::vector<EdgeIn>>& rings, i64 v) const;

 public:

 private:
  Geo& g_;

  // ---- local state of a run (reused)
  std::vector<EdgeIn> ed_;        // input edges, local vertex ids
  std::vector<i64> vg_;           // local vertex -> global vertex (representative)
  struct Split {
    i64 edge, node;  // node: local vertex id, or nv0 + new crossing
  };
  std::vector<Split> splits_;
  std::vector<i64> newv_;  // new crossing -> global vertex id (made after intersect())
  std::vector<std::pair<i64, i64>> cross_;  // new crossing -> its two lines
  std::vector<i64> uf_;
  // Vertex and edge ids of a run fit 32 bits (arrange() stops with RESOURCE beyond):
  // the pieces are the run's largest arrays.
  using i32 = std::int32_t;
  struct Piece {
    i32 l, r;    // arrangement vertices, l < r (sweep ranks)
    i32 src;     // the input edge it comes from (its line's cached points: ll_)
    i32 c0, c1;  // change of w0, w1 crossing upwards
    i32 b0, b1;  // winding numbers below
    i32 n0;      // layer-0 weight of the edges with their inside below (for
                 // degenerate(): the rings covering the piece's own points)
    i32 nl;      // layer-2 (line) edges along it: a piece of a clipped polyline
    std::int8_t s;   // +1 when the line runs from l's side to r's side
    std::int8_t ld;  // +1: the first such line edge runs l -> r, -1: r -> l
    i64 line;
  };
  std::vector<Piece> pcs_;
  // a boundary piece: from -> to with the inside on the left; d = +1 when its line runs
  // from -> to
  struct BPiece {
    i64 line;
    i32 from, to, src;
    std::int8_t d;
  };
  std::vector<BPiece> bnd_;
  int rule_ = UNION;
  bool over_ = false;
  bool keep_zero_ = false;

  i64 find(i64 a) {
    while (uf_[a] != a) {
      uf_[a] = uf_[uf_[a]];
      a = uf_[a];
    }
    return a;
  }
  void unite(i64 a, i64 b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (a < b)  // smaller ids (input vertices) stay roots
      uf_[b] = a;
    else
      uf_[a] = b;
  }

  const std::vector<const std::vector<i64>*>* lists_ = nullptr;

  void arrange(const std::vector<EdgeIn>& in, int rule) {
    rule_ = rule;
    n_pairs = n_crossings = n_vertices = n_edges = 0;
    over_ = false;
    ordered_ = false;
    local_vertices(in);
    intersect();
    // vertex and edge ids of 32 bits (the pieces' fields)
    const i64 i32max = INT32_MAX;
    if ((i64)vg_.size() + (i64)cross_.size() >= i32max || (i64)ed_.size() >= i32max) over_ = true;
    if (!over_) {  // the crossings as vertices, in one growth of the geometry
      const std::size_t need = g_.verts.size() + cross_.size();  // growing geometrically:
      if (need > g_.verts.capacity())  // a workspace's geometry grows over many runs
        g_.verts.reserve(std::max(need, 2 * g_.verts.capacity()));
      newv_.resize(cross_.size());
      for (std::size_t k = 0; k < cross_.size(); ++k)
        newv_[k] = g_.vert_cross(cross_[k].first, cross_[k].second);
    }
    if (over_) {
      splits_.clear();
      newv_.clear();
      ed_.clear();
      bnd_.clear();
      return;
    }
    split();
    order();
    pieces();
    windings();
    boundary();
  }

  // cached approximations of an input edge's line and of a vertex (side_ev)
  struct LLine {
    FE ax, ay, bx, by;  // the line's two points (exact when e == 0)
    bool plain;
  };
  struct LVert {
    FE x, y;  // exact when both bounds are 0: then plain doubles
    bool plain() const { return x.e == 0 && y.e == 0; }
  };

  // step 1: input vertices sorted and merged; edges in local ids
  std::vector<i64> tmp_;
  // sort keys: the vertex's approximation (exact for a plain point: e == 0)
  struct VKey {
    double x, ex, y, ey;
    i64 g;
  };
  std::vector<VKey> vk_;
  VKey vkey(i64 g) const {
    const Vert& V = g_.verts[g];
    return VKey{V.x.v, V.x.e, V.y.v, V.y.e, g};
  }
  // the sweep order (x, then y) of two vertices: by the approximations when they are
  // exact or certain, else exactly
  int vkcmp(const VKey& a, const VKey& b) const {
    if (a.g == b.g) return 0;
    if (a.ex == 0 && b.ex == 0 && a.ey == 0 && b.ey == 0) {
      if (a.x != b.x) return a.x < b.x ? -1 : 1;
      if (a.y != b.y) return a.y < b.y ? -1 : 1;
      return 0;
    }
    int s = fe_sign(FE{a.x, a.ex} - FE{b.x, b.ex});
    if (s == UNSURE) {
      if (same_vertex(a.g, b.g)) return 0;
      s = g_.coord_cmp(a.g, b.g, 0);
    }
    if (s != 0) return s;
    s = fe_sign(FE{a.y, a.ey} - FE{b.y, b.ey});
    if (s == UNSURE) s = g_.coord_cmp(a.g, b.g, 1);
    return s;
  }
  // Sorts a (each key(a[i]) a VKey) into the sweep order: by the approximations as plain
  // doubles (compact keys), then every adjacent pair compared with vkcmp (exact where the
  // approximations cannot tell): the few inversions of near-equal keys are repaired by
  // insertion, and a sequence with many goes to a full sort by vkcmp.
  struct AKey {
    double x, y;
    std::uint32_t i;
  };
  std::vector<AKey> ak_;
  template <class T, class K>
  void sort_sweep(std::vector<T>& a, std::vector<T>& tmp, K key) {
    const std::size_t n = a.size();
    if (n < 2) return;
    auto exact_less = [&](const T& u, const T& v) { return vkcmp(key(u), key(v)) < 0; };
    if (n > 0xffffffffu) {
      std::sort(a.begin(), a.end(), exact_less);
      return;
    }
    ak_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const VKey& k = key(a[i]);
      ak_[i] = AKey{k.x, k.y, (std::uint32_t)i};
    }
    std::sort(ak_.begin(), ak_.end(), [](const AKey& u, const AKey& v) {
      return u.x < v.x || (u.x == v.x && u.y < v.y);
    });
    tmp.resize(n);
    for (std::size_t t = 0; t < n; ++t) tmp[t] = a[ak_[t].i];
    a.swap(tmp);
    insertion_or_sort(a.data(), n, exact_less);  // far from sorted: sorted exactly
  }

  // certainly the same point without the crossings' coordinates: the same id, crossings
  // of the same two lines, or crossings of one line with two lines that are one line (two
  // exact orientations: the edges of piece sums are often collinear, and a line crossing
  // two of them meets both in one point) (false: not known)
  bool same_vertex(i64 a, i64 b) const {
    if (a == b) return true;
    const Vert &A = g_.verts[a], &B = g_.verts[b];
    if (A.p >= 0 || B.p >= 0) return false;
    if ((A.l1 == B.l1 && A.l2 == B.l2) || (A.l1 == B.l2 && A.l2 == B.l1)) return true;
    // the other lines, when one is common
    const i64 m = A.l1 == B.l1 || A.l1 == B.l2 ? A.l2 : (A.l2 == B.l1 || A.l2 == B.l2 ? A.l1 : -1);
    if (m < 0) return false;
    const i64 n = B.l1 == A.l1 || B.l1 == A.l2 ? B.l2 : B.l1;
    return g_.same_line(m, n);
  }
  // along(line, a, b) with that shortcut
  int along_s(i64 line, i64 a, i64 b) const {
    if (same_vertex(a, b)) return 0;
    return g_.along(line, a, b);
  }
  // global id -> local id of this run (valid when its stamp is the run's)
  struct G2L {
    std::uint32_t stamp;
    i64 local;
  };
  std::vector<G2L> g2l_;
  std::uint32_t run_stamp_ = 0;

  std::vector<VKey> vk2_, vk3_;
  // merges the sorted sequence b into a (sorted): the result in a (b's buffer may be
  // taken)
  void merge_keys(std::vector<VKey>& a, std::vector<VKey>& b) {
    if (b.empty()) return;
    if (a.empty()) {
      a.swap(b);
      return;
    }
    vk3_.resize(a.size() + b.size());
    std::merge(a.begin(), a.end(), b.begin(), b.end(), vk3_.begin(),
               [&](const VKey& x, const VKey& y) { return vkcmp(x, y) < 0; });
    a.swap(vk3_);
  }

  void local_vertices(const std::vector<EdgeIn>& in) {
    if (g2l_.size() < g_.verts.size()) g2l_.resize(g_.verts.size() + g_.verts.size() / 2, G2L{0, 0});
    if (++run_stamp_ == 0) {
      for (G2L& q : g2l_) q.stamp = 0;
      run_stamp_ = 1;
    }
    // the presorted lists, merged
    vk_.clear();
    if (lists_)
      for (const std::vector<i64>* L : *lists_) {
        vk2_.clear();
        for (i64 v : *L)
          if (g2l_[v].stamp != run_stamp_) {
            g2l_[v].stamp = run_stamp_;
            vk2_.push_back(vkey(v));
          }
        merge_keys(vk_, vk2_);
      }
    // the others, sorted
    vk2_.clear();
    vk2_.reserve(2 * in.size());
    for (const EdgeIn& e : in)
      for (i64 v : {e.v0, e.v1})
        if (g2l_[v].stamp != run_stamp_) {
          g2l_[v].stamp = run_stamp_;
          vk2_.push_back(vkey(v));
        }
    sort_sweep(vk2_, vk3_, [](const VKey& k) -> const VKey& { return k; });
    merge_keys(vk_, vk2_);
    vg_.clear();
    for (std::size_t t = 0; t < vk_.size(); ++t) {
      if (t == 0 || vkcmp(vk_[t - 1], vk_[t]) != 0) vg_.push_back(vk_[t].g);
      g2l_[vk_[t].g].local = (i64)vg_.size() - 1;
    }
    ed_.clear();
    ed_.reserve(in.size());
    ngroups_ = 0;
    for (const EdgeIn& e : in) {
      i64 a = g2l_[e.v0].local, b = g2l_[e.v1].local;
      if (a != b && e.w != 0) {
        EdgeIn& x = ed_.emplace_back();  // written in place (see Geo::point)
        x.line = e.line;
        x.v0 = a;
        x.v1 = b;
        x.w = e.w;
        x.layer = e.layer;
        x.group = e.group;
        if (e.group >= ngroups_) ngroups_ = e.group + 1;
      }
    }
    // approximations of the input vertices and of the edges' lines, cached
    lv_.resize(vg_.size());
    for (std::size_t t = 0; t < vg_.size(); ++t) lv_[t] = lvert(vg_[t]);
    ll_.resize(ed_.size());
    for (std::size_t i = 0; i < ed_.size(); ++i) {
      const Line& L = g_.lines[ed_[i].line];
      const P &a = g_.pts[L.a], &b = g_.pts[L.b];
      ll_[i] = LLine{fe(a.x), fe(a.y), fe(b.x), fe(b.y), plain(a) && plain(b)};
    }
  }
  int ngroups_ = 0;

  // step 2
  std::vector<double> bx0_, bx1_, by0_, by1_;
  std::vector<int> grp_;
  BoxScratch boxes_;
  std::vector<double> sx0_, sy0_, sx1_, sy1_, stol_;
  GridScratch grid_;
  TreeScratch tree_;
  std::vector<i64> bstart_, border_;
  void intersect() {
    const i64 n = (i64)ed_.size();
    splits_.clear();
    newv_.clear();
    cross_.clear();
    bx0_.resize(n);
    bx1_.resize(n);
    by0_.resize(n);
    by1_.resize(n);
    grp_.resize(n);
    for (i64 i = 0; i < n; ++i) {
      const Vert &a = g_.verts[vg_[ed_[i].v0]], &b = g_.verts[vg_[ed_[i].v1]];
      grp_[i] = ed_[i].group;
      if (a.x.e == 0 && a.y.e == 0 && b.x.e == 0 && b.y.e == 0) {
        // exact coordinates: the box itself
        bx0_[i] = std::min(a.x.v, b.x.v);
        bx1_[i] = std::max(a.x.v, b.x.v);
        by0_[i] = std::min(a.y.v, b.y.v);
        by1_[i] = std::max(a.y.v, b.y.v);
        continue;
      }
      widened_box(a, b, bx0_[i], bx1_[i], by0_[i], by1_[i]);  // holds the exact vertices
    }
    auto on_pair = [&](i64 i, i64 j) {
      if (n_pairs >= max_pairs) over_ = true;
      if (over_) return false;
      classify(i, j);
      return true;
    };
    if (n >= grid_min) {
      // many edges: candidates from a grid over the segments themselves
      sx0_.resize(n);
      sy0_.resize(n);
      sx1_.resize(n);
      sy1_.resize(n);
      stol_.resize(n);
      for (i64 i = 0; i < n; ++i) {
        const Vert &a = g_.verts[vg_[ed_[i].v0]], &b = g_.verts[vg_[ed_[i].v1]];
        sx0_[i] = a.x.v;
        sy0_[i] = a.y.v;
        sx1_[i] = b.x.v;
        sy1_[i] = b.y.v;
        stol_[i] = std::max(std::max(a.x.e, a.y.e), std::max(b.x.e, b.y.e)) * (1 + 0x1p-40);
      }
      i64 resume = -1;
      if (segment_pairs(n, sx0_.data(), sy0_.data(), sx1_.data(), sy1_.data(), stol_.data(),
                        bx0_.data(), bx1_.data(), by0_.data(), by1_.data(), grp_.data(), grid_,
                        on_pair, &resume))
        return;
      // the grid gave up (long edges crowd its cells: finish from `resume`) or declined
      // (too many cell registrations: all of it): a packed R-tree, whose work follows the
      // overlapping boxes (a sweep keeps every long edge active: nested squares)
      if (!over_)
        box_tree_pairs(n, bx0_.data(), bx1_.data(), by0_.data(), by1_.data(), grp_.data(),
                       resume >= 0 ? resume : 0, tree_, on_pair);
      return;
    }
    if (n < 256) {
      // the edges by their left vertex (local ids are sweep ranks): nearly in the order of
      // their boxes' left sides (exactly, where the vertices are plain doubles)
      const i64 nv = (i64)vg_.size();
      bstart_.assign(nv + 1, 0);
      for (const EdgeIn& e : ed_) ++bstart_[std::min(e.v0, e.v1) + 1];
      for (i64 v = 0; v < nv; ++v) bstart_[v + 1] += bstart_[v];
      border_.resize(n);
      for (i64 i = 0; i < n; ++i) border_[bstart_[std::min(ed_[i].v0, ed_[i].v1)]++] = i;
      box_pairs_scan(n, bx0_.data(), bx1_.data(), by0_.data(), by1_.data(), grp_.data(), boxes_,
                     on_pair, border_.data());
    }
    else
      box_pairs_grouped(n, bx0_.data(), bx1_.data(), by0_.data(), by1_.data(), grp_.data(),
                        ngroups_, boxes_, on_pair);
  }

  // vertex p strictly between the ends of edge i (p on its line)
  bool inside_edge(i64 i, i64 p) const {
    const EdgeIn& e = ed_[i];
    i64 l = e.line;
    int s0 = g_.along(l, vg_[p], vg_[e.v0]), s1 = g_.along(l, vg_[p], vg_[e.v1]);
    return s0 * s1 < 0;
  }

  void classify(i64 i, i64 j) {
    if (over_) return;
    ++n_pairs;
    const EdgeIn &s = ed_[i], &t = ed_[j];
    const i64 p = s.v0, q = s.v1, r = t.v0, u = t.v1;
    auto sd = [&](i64 e, i64 v, i64 e0, i64 e1) {
      return (v == e0 || v == e1) ? 0 : side_ev(e, v);
    };
    int oa = sd(i, r, p, q), ob = sd(i, u, p, q);
    if (oa * ob > 0) return;
    if (oa == 0 && ob == 0) {
      // collinear: each endpoint strictly inside the other edge splits it
      if (r != p && r != q && inside_edge(i, r)) splits_.push_back(Split{i, r});
      if (u != p && u != q && inside_edge(i, u)) splits_.push_back(Split{i, u});
      if (p != r && p != u && inside_edge(j, p)) splits_.push_back(Split{j, p});
      if (q != r && q != u && inside_edge(j, q)) splits_.push_back(Split{j, q});
      return;
    }
    int oc = sd(j, p, r, u), od = sd(j, q, r, u);
    if (oc * od > 0) return;
    if (oa == 0 || ob == 0 || oc == 0 || od == 0) {
      // one common point, an endpoint of one of them
      if (oa == 0 && r != p && r != q) splits_.push_back(Split{i, r});
      if (ob == 0 && u != p && u != q) splits_.push_back(Split{i, u});
      if (oc == 0 && p != r && p != u) splits_.push_back(Split{j, p});
      if (od == 0 && q != r && q != u) splits_.push_back(Split{j, q});
      return;
    }
    // a proper crossing: a new vertex
    if (++n_crossings > max_crossings) {
      over_ = true;
      return;
    }
    i64 node = (i64)vg_.size() + (i64)cross_.size();
    cross_.emplace_back(s.line, t.line);
    splits_.push_back(Split{i, node});
    splits_.push_back(Split{j, node});
  }

  i64 gid(i64 node) const {
    const i64 nv0 = (i64)vg_.size();
    return node < nv0 ? vg_[node] : newv_[node - nv0];
  }

  // step 3: splits sorted along their edges, equal ones united. The splits of edge i are
  // sk_[sstart_[i] .. sstart_[i + 1]), from v0 to v1.
  struct SKey {
    double k, ke;  // position along the edge (growing from v0 to v1), approximate, bound
    i64 node;
  };
  std::vector<SKey> sk_;
  std::vector<i64> sstart_, sfill_;
  std::vector<std::int8_t> edir_;
  void split() {
    const i64 nv0 = (i64)vg_.size(), ne = (i64)ed_.size();
    uf_.resize(nv0 + newv_.size());
    std::iota(uf_.begin(), uf_.end(), 0);
    // counting sort by edge
    sstart_.assign(ne + 1, 0);
    for (const Split& sp : splits_) ++sstart_[sp.edge + 1];
    for (i64 i = 0; i < ne; ++i) sstart_[i + 1] += sstart_[i];
    sfill_.assign(sstart_.begin(), sstart_.end() - 1);
    sk_.resize(splits_.size());
    for (const Split& sp : splits_) sk_[sfill_[sp.edge]++].node = sp.node;
    edir_.resize(ne);
    for (i64 i = 0; i < ne; ++i) {
      const EdgeIn& e = ed_[i];
      // the edge's direction against its line (+1: v0 -> v1 runs along it; pieces())
      edir_[i] = (std::int8_t)g_.along(e.line, vg_[e.v1], vg_[e.v0]);
      const i64 a = sstart_[i], b = sstart_[i + 1];
      if (a == b) continue;
      // the position along the edge: its line's axis coordinate (as along() compares),
      // times the sign that makes it grow from v0 to v1; certified apart -> no exact test
      const P &p = g_.pts[g_.lines[e.line].a], &q = g_.pts[g_.lines[e.line].b];
      const bool ya = dd_eq(p.x, q.x);
      const int sg = (ya ? dd_cmp(q.y, p.y) : dd_cmp(q.x, p.x)) * edir_[i];
      for (i64 t = a; t < b; ++t) {
        const Vert& V = g_.verts[gid(sk_[t].node)];
        const FE c = ya ? V.y : V.x;
        sk_[t].k = sg > 0 ? c.v : -c.v;
        sk_[t].ke = c.e;
      }
      const int dir = edir_[i];
      auto less = [&](const SKey& x, const SKey& y) {
        if (x.node == y.node) return false;
        const double gap = (x.ke + y.ke) * (1 + 0x1p-50);
        if (y.k - x.k > gap) return true;
        if (x.k - y.k > gap) return false;
        // along the edge's own direction (v0 -> v1)
        return along_s(e.line, gid(x.node), gid(y.node)) * dir < 0;
      };
      if (b - a > 1) std::sort(sk_.begin() + a, sk_.begin() + b, less);
      for (i64 t = a + 1; t < b; ++t) {
        const SKey &x = sk_[t - 1], &y = sk_[t];
        if (x.node == y.node || y.k - x.k > (x.ke + y.ke) * (1 + 0x1p-50)) continue;
        if (along_s(e.line, gid(x.node), gid(y.node)) == 0) unite(x.node, y.node);
      }
    }
    // representatives: roots; a new vertex united with an input one maps to it
  }

  // step 4 prelude: the arrangement's vertices, numbered in sweep order (an arrangement
  // vertex's id is its rank: pieces sorted by their left vertex are in sweep order)
  std::vector<i64> lid_;  // node -> arrangement vertex, after union
  std::vector<i64> av_;   // arrangement vertex -> global vertex id
  struct NKey {
    VKey k;
    i64 node;
  };
  std::vector<NKey> nk_, nk2_;
  std::vector<LVert> lv2_;
  bool ordered_ = false;  // order() has run: local vertex ids are arrangement ids
  void order() {
    const i64 nn = (i64)uf_.size(), nv0 = (i64)vg_.size();
    // the new roots (crossings not united with an input vertex), sorted; the input
    // vertices are roots already in sweep order (local_vertices): merged with them
    nk_.clear();
    for (i64 node = nv0; node < nn; ++node)
      if (find(node) == node) nk_.push_back(NKey{vkey(gid(node)), node});
    sort_sweep(nk_, nk2_, [](const NKey& k) -> const VKey& { return k.k; });
    const i64 nnew = (i64)nk_.size(), m = nv0 + nnew;
    n_vertices = m;
    lid_.resize(nn);
    av_.resize(m);
    lv2_.resize(m);
    i64 i = 0, j = 0, t = 0;
    while (i < nv0 || j < nnew) {
      bool take_input = j >= nnew || (i < nv0 && vkcmp(vkey(vg_[i]), nk_[j].k) < 0);
      if (take_input) {
        lid_[i] = t;
        av_[t] = vg_[i];
        lv2_[t] = lv_[i];
        ++i;
      } else {
        const i64 node = nk_[j].node;
        lid_[node] = t;
        av_[t] = nk_[j].k.g;
        lv2_[t] = lvert(av_[t]);
        ++j;
      }
      ++t;
    }
    lv_.swap(lv2_);
    ordered_ = true;
    for (i64 node = nv0; node < nn; ++node) {
      const i64 r = find(node);
      if (r != node) lid_[node] = lid_[r];
    }
  }

  // step 4: pieces, grouped by their left vertex (ascending, so in sweep order), each
  // group in slope order (bottom to top: the order the sweep inserts them in);
  // pieces joining the same two vertices merged (weights added). pstart_[v] is the
  // first piece of vertex v.
  struct RawP {
    i32 r, src;
    std::int8_t s;  // the line's direction (l -> r: +1)
    bool fwd;       // the edge runs l -> r
  };
  std::vector<RawP> raw_;
  std::vector<i64> pstart_, pfill_;
  // calls f(l, r, s, c) for every piece of input edge i (between consecutive splits)
  template <class F>
  void edge_pieces(i64 i, F&& f) const {
    const EdgeIn& e = ed_[i];
    // the line's own direction against the edge's
    const int es = edir_[i];
    i64 prev = lid_[e.v0];
    auto emit = [&](i64 nxt) {
      if (nxt == prev) return;
      const bool fwd = prev < nxt;
      // the line runs from l's side to r's side when the edge does (fwd) and the line
      // runs along the edge (es > 0), or neither
      f(fwd ? prev : nxt, fwd ? nxt : prev, (fwd == (es > 0)) ? 1 : -1, fwd);
      prev = nxt;
    };
    for (i64 t = sstart_[i]; t < sstart_[i + 1]; ++t) emit(lid_[sk_[t].node]);
    emit(lid_[e.v1]);
  }
  void pieces() {
    const i64 m = (i64)av_.size(), ne = (i64)ed_.size();
    // counting sort by the left vertex: count, then place
    pstart_.assign(m + 1, 0);
    for (i64 i = 0; i < ne; ++i)
      edge_pieces(i, [&](i64 l, i64, int, bool) { ++pstart_[l + 1]; });
    for (i64 v = 0; v < m; ++v) pstart_[v + 1] += pstart_[v];
    raw_.resize(pstart_[m]);
    pfill_.assign(pstart_.begin(), pstart_.end() - 1);
    for (i64 i = 0; i < ne; ++i)
      edge_pieces(i, [&](i64 l, i64 r, int s, bool fwd) {
        raw_[pfill_[l]++] = RawP{(i32)r, (i32)i, (std::int8_t)s, fwd};
      });
    // each group: sorted by r (then by input edge, as placed), equal ones merged, then
    // in slope order
    pcs_.clear();
    pcs_.reserve(raw_.size());
    for (i64 v = 0; v < m; ++v) {
      const i64 a = pstart_[v], b = pstart_[v + 1];
      pstart_[v] = (i64)pcs_.size();
      auto raw_less = [](const RawP& x, const RawP& y) {
        return x.r < y.r || (x.r == y.r && x.src < y.src);
      };
      if (b - a == 2) {  // the common case, without a call
        if (raw_less(raw_[a + 1], raw_[a])) std::swap(raw_[a], raw_[a + 1]);
      } else if (b - a > 2) {
        std::sort(raw_.begin() + a, raw_.begin() + b, raw_less);
      }
      for (i64 q = a; q < b;) {
        const i32 r = raw_[q].r;
        i32 c0 = 0, c1 = 0, n0 = 0, nl = 0;
        std::int8_t ld = 0;
        i64 q1 = q;
        for (; q1 < b && raw_[q1].r == r; ++q1) {
          const RawP& x = raw_[q1];
          const EdgeIn& e = ed_[x.src];
          const int c = x.fwd ? e.w : -e.w;  // the weight crossing upwards
          if (e.layer == 0) c0 += c;
          if (e.layer == 1) c1 += c;
          if (e.layer == 0 && c < 0) n0 -= c;
          if (e.layer == 2) {
            if (!nl) ld = x.fwd ? 1 : -1;  // the first line edge's direction
            ++nl;
          }
        }
        // keep_zero_: a piece where rings meet from both sides stays (degenerate())
        if (c0 != 0 || c1 != 0 || nl != 0 || (keep_zero_ && q1 > q + 1)) {
          Piece& pc = pcs_.emplace_back();  // written in place (see Geo::point)
          pc.l = (i32)v;
          pc.r = r;
          pc.src = raw_[q].src;
          pc.line = ed_[pc.src].line;
          pc.s = raw_[q].s;
          pc.c0 = c0;
          pc.c1 = c1;
          pc.n0 = n0;
          pc.nl = nl;
          pc.b0 = pc.b1 = 0;
          pc.ld = ld;
        }
        q = q1;
      }
      const i64 p0 = pstart_[v], p1 = (i64)pcs_.size();
      if (p1 - p0 == 2) {
        if (slope_below(pcs_[p0 + 1], pcs_[p0])) std::swap(pcs_[p0], pcs_[p0 + 1]);
      } else if (p1 - p0 > 2) {
        std::sort(pcs_.begin() + p0, pcs_.begin() + p1,
                  [&](const Piece& x, const Piece& y) { return slope_below(x, y); });
      }
    }
    pstart_[m] = (i64)pcs_.size();
    n_edges = (i64)pcs_.size();
  }
  // side of arrangement vertex v against the line of piece e (oriented l -> r)
  int side(const Piece& e, i64 v) const {
    return (e.src >= 0 ? side_ev(e.src, v) : g_.side(e.line, av_[v])) * e.s;
  }
  // Side of local vertex v (an input vertex before order() has run, an arrangement
  // vertex after) against the line of input edge i: from the
  // cached plain coordinates when both are plain (one orientation of doubles), else
  // Geo::side.
  std::vector<LLine> ll_;
  std::vector<LVert> lv_;
  int side_ev(i64 i, i64 v) const {
    const LLine& L = ll_[i];
    const LVert& V = lv_[v];
    if (L.plain && V.plain())
      return mk::orient(L.ax.v, L.ay.v, L.bx.v, L.by.v, V.x.v, V.y.v);
    int s = fe_sign(cross(L.bx - L.ax, L.by - L.ay, V.x - L.ax, V.y - L.ay));
    if (s != UNSURE) return s;
    return g_.side(ed_[i].line, ordered_ ? av_[v] : vg_[v]);
  }
  LVert lvert(i64 gv) const {
    const Vert& V = g_.verts[gv];
    return LVert{V.x, V.y};
  }
  // pieces from one vertex: e1 below e2 when the turn from e1 to e2 is left
  bool slope_below(const Piece& e1, const Piece& e2) const {
    if (e1.src >= 0 && e2.src >= 0 && ll_[e1.src].plain && ll_[e2.src].plain) {
      const LLine &a = ll_[e1.src], &b = ll_[e2.src];
      return cross_sign(a.ax.v, a.ay.v, a.bx.v, a.by.v, b.ax.v, b.ay.v, b.bx.v, b.by.v) * e1.s *
                 e2.s > 0;
    }
    return g_.turn(e1.line, e1.s, e2.line, e2.s) > 0;
  }

  // The sweep's status: piece ids bottom to top in chunks of at most 2 * kChunk, so that
  // replacing the pieces at one vertex costs a chunk, not the whole status (nested frames
  // keep 10^5 pieces active: a sorted vector spent most of their overlay moving memory).
  struct SweepStatus {
    static constexpr std::size_t kChunk = 256;
    std::vector<std::vector<i64>> ch;  // non-empty chunks, in order
    std::size_t spare = 0;             // chunks ch[size - spare ..) are empty spares
    void clear() {
      for (auto& c : ch) c.clear();
      spare = ch.size();
    }
    std::size_t size() const { return ch.size() - spare; }
    // a new empty chunk at index c (reusing a spare's memory)
    void open(std::size_t c) {
      if (spare > 0) {
        std::vector<i64> v;
        v.swap(ch.back());
        ch.pop_back();
        --spare;
        ch.insert(ch.begin() + (std::ptrdiff_t)c, std::move(v));
      } else {
        ch.insert(ch.begin() + (std::ptrdiff_t)c, std::vector<i64>());
      }
    }
    void close(std::size_t c) {  // chunk c is empty: it becomes a spare
      std::vector<i64> v;
      v.swap(ch[c]);
      ch.erase(ch.begin() + (std::ptrdiff_t)c);
      ch.push_back(std::move(v));
      ++spare;
    }
  };
  SweepStatus sw_st_;

  // Sweeps the pieces ps (which do not cross), grouped by their left vertex: the pieces
  // of vertex v are ps[start[v] .. start[v + 1]), in slope order (bottom to top). After
  // inserting the pieces that start at a vertex calls at_vertex(first, end, predecessor
  // of the first or -1). The status is sorted bottom to top: at vertex v the pieces below
  // v are a prefix (v is strictly left of each, looking along it), then come the pieces
  // that end at v (no piece passes through a vertex: the pieces are noded); those are
  // replaced by the pieces that start at v.
  std::vector<i64> sw_nend_;
  template <class F>
  void sweep(const std::vector<Piece>& ps, const std::vector<i64>& start, F&& at_vertex);
  // ps (with a value per piece in `val`) grouped by left vertex and in slope order, as
  // sweep() takes them; start as sweep() reads it
  void group_pieces(std::vector<Piece>& ps, std::vector<i64>& val, std::vector<i64>& start);

  // step 5
  void windings();

  // step 6: the boundary, inside on the left
  void boundary();

  // direction of boundary piece b (from -> to) as points of its line
  void bdir(const BPiece& b, const P*& p, const P*& q) const { g_.dir(b.line, b.d, p, q); }
  int bturn(const BPiece& a, const BPiece& b) const {
    const P *p1, *q1, *p2, *q2;
    bdir(a, p1, q1);
    bdir(b, p2, q2);
    return dir_cross(*p1, *q1, *p2, *q2);
  }

  // ---- rings
  // ring k: its kept arrangement vertices rv_[roff_[k] .. roff_[k + 1]) (inside on the
  // left) with the line of the edge leaving each (rl_), its boundary pieces
  // re_[reoff_[k] .. reoff_[k + 1]), its orientation
  std::vector<i64> rv_, rl_, roff_, re_, reoff_;
  std::vector<char> ring_ccw_;
  // scratch of trace() and assemble()
  std::vector<i64> tr_lo_, tr_outs_, tr_pos_, tr_walk_v_, tr_walk_e_;
  std::vector<char> tr_used_;
  std::vector<double> tr_xy_;
  std::vector<char> junction_;  // arrangement vertex where several boundary rings meet

  void trace(Rings& out);

  // a simple loop: drop collinear vertices, record its orientation
  void add_ring(const i64* rv, const i64* re, i64 n);

  // each hole's exterior (a ring's index), -1 for exteriors
  std::vector<i64> owner_;
  void holes();

  void assemble(Rings& out);
};

}  // namespace ov
}  // namespace mk
