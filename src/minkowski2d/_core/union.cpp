// union.cpp -- bindings of the exact union of convex polygons (union.hpp) into
// minkowski2d._core._ext.
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/tuple.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "bind.hpp"
#include "exact.hpp"
#include "minkowski.hpp"
#include "union.hpp"

namespace nb = nanobind;
using namespace nb::literals;
using mk::i64;

namespace mk_bind {
namespace {

nb::tuple stats_tuple(const mk::un::UnionStats& s) {
  return nb::make_tuple(s.pieces, s.culled, s.kept, s.rounds, s.runs, s.pairs, s.crossings);
}

nb::tuple result(const mk::ov::Rings& r, const mk::un::UnionStats& s, i64 bad_poly,
                 i64 bad_vertex) {
  return nb::make_tuple(to_numpy(r.xy, r.xy.size() / 2, 2),
                        to_numpy(r.ring_off, r.ring_off.size(), 0),
                        to_numpy(r.poly_off, r.poly_off.size(), 0), r.status, stats_tuple(s),
                        nb::make_tuple(bad_poly, bad_vertex));
}

// A ring that is not convex, counter-clockwise at its lowest vertex (exact turn), with
// repeated points dropped; empty when it has no such vertex (no area).
std::vector<mk::ov::P> general_ring(const double* xy, i64 lo, i64 hi) {
  std::vector<std::pair<double, double>> r;
  for (i64 i = lo; i < hi; ++i) {
    std::pair<double, double> p{xy[2 * i], xy[2 * i + 1]};
    if (r.empty() || r.back() != p) r.push_back(p);
  }
  while (r.size() > 1 && r.front() == r.back()) r.pop_back();
  std::vector<mk::ov::P> out;
  while (r.size() >= 3) {
    const std::size_t n = r.size();
    std::size_t b = 0;
    for (std::size_t i = 1; i < n; ++i)
      if (r[i] < r[b]) b = i;
    const auto &p = r[(b + n - 1) % n], &c = r[b], &q = r[(b + 1) % n];
    int o = mk::cross_sign(p.first, p.second, c.first, c.second, c.first, c.second, q.first,
                           q.second);
    if (o == 0) {  // the lowest vertex is a spike or straight on: drop it
      r.erase(r.begin() + (std::ptrdiff_t)b);
      continue;
    }
    if (o < 0) std::reverse(r.begin(), r.end());
    for (auto& v : r) out.push_back(mk::ov::P{mk::ov::dd(v.first), mk::ov::dd(v.second)});
    break;
  }
  return out;
}

// union_convex(xy (N, 2) float64, offsets (P + 1,), max_crossings, max_pairs, cull=True) -> (xy,
// ring_off, poly_off, status, (pieces, culled, kept, rounds, runs, pairs, crossings),
// (polygon, vertex)): the exact union (winding number >= 1) of polygons given as rings,
// meant for convex ones (any orientation; repeated and collinear vertices, points and
// segments allowed): those are normalized exactly and dropped when they lie inside the
// union so far. A ring that is not convex (a rounded convex sum can turn both ways by
// an ulp) is still united exactly, counter-clockwise by its turn at the lowest vertex,
// never tested for containment. A non-finite coordinate gives status NONFINITE and
// (polygon, vertex); more crossings noded or candidate pairs classified (all overlay
// runs together) than the limits gives RESOURCE.
nb::tuple union_convex(In2<double> XY, In1<i64> OFF, i64 max_crossings, i64 max_pairs,
                       bool cull) {
  const i64 n = (i64)XY.shape(0), np = (i64)OFF.shape(0) - 1;
  if (XY.shape(1) != 2) throw nb::value_error("union_convex: coordinates must have shape (n, 2)");
  const i64* off = OFF.data();
  if (np < 0 || off[0] != 0 || off[np] != n) throw nb::value_error("union_convex: bad offsets");
  for (i64 k = 0; k < np; ++k)
    if (off[k + 1] < off[k]) throw nb::value_error("union_convex: bad offsets");
  const double* xy = XY.data();
  mk::ov::Rings out;
  mk::un::UnionStats st;
  i64 bad_poly = -1, bad_vertex = -1;
  {
    nb::gil_scoped_release nogil;
    i64 big = 1;
    for (i64 k = 0; k < np; ++k) big = std::max(big, off[k + 1] - off[k]);
    std::vector<i64> keep(big), idx(big);
    std::vector<std::int8_t> turn(big);
    std::vector<mk::ov::P> pts;
    std::vector<i64> po{0};
    std::vector<char> convex;
    pts.reserve(n);
    for (i64 k = 0; k < np && out.status == mk::OK; ++k) {
      mk::Norm N = mk::normalize(xy, off[k], off[k + 1], keep.data(), turn.data(), idx.data());
      if (N.code == mk::NONFINITE || N.code == mk::RANGE) {
        out.status = N.code;
        bad_poly = k;
        bad_vertex = N.vertex;
        break;
      }
      if (N.code == mk::OK) {
        if (N.k < 3) continue;  // a point or a segment: no area
        for (i64 t = 0; t < N.k; ++t) {
          i64 i = N.at(t);
          pts.push_back(mk::ov::P{mk::ov::dd(xy[2 * i]), mk::ov::dd(xy[2 * i + 1])});
        }
        convex.push_back(1);
      } else {
        std::vector<mk::ov::P> r = general_ring(xy, off[k], off[k + 1]);
        if (r.empty()) continue;
        pts.insert(pts.end(), r.begin(), r.end());
        convex.push_back(0);
      }
      po.push_back((i64)pts.size());
    }
    if (out.status == mk::OK) {
      mk::un::PointSource src{&pts, &po, &convex};
      mk::un::with_workspace([&](mk::un::Workspace& w) {
        w.u.cull = cull;
        w.u.max_crossings = max_crossings;
        w.u.max_pairs = max_pairs;
        w.u.unite(src, out);
        st = w.u.st;
        return 0;
      });
    }
  }
  return result(out, st, bad_poly, bad_vertex);
}

// sum_pieces_union(pieces of A (coords, offsets), pieces of B, max_crossings, max_pairs,
// cull=True) ->
// (xy, ring_off, poly_off, status, stats, (piece, vertex)): the union of all piece sums
// (the decomposition method), pieces that cannot change it dropped before noding; a
// piece that is not convex gives its status and (piece, vertex), B's numbered after A's.
nb::tuple sum_pieces_union(In2<double> PA, In1<i64> OA, In2<double> PB, In1<i64> OB,
                           i64 max_crossings, i64 max_pairs, bool cull) {
  for (auto [P, O] : {std::pair{&PA, &OA}, std::pair{&PB, &OB}}) {
    const i64 n = (i64)P->shape(0), np = (i64)O->shape(0) - 1;
    if (P->shape(1) != 2) throw nb::value_error("sum_pieces: coordinates must have shape (n, 2)");
    const i64* o = O->data();
    if (np < 0 || o[0] != 0 || o[np] != n) throw nb::value_error("sum_pieces: bad offsets");
    for (i64 k = 0; k < np; ++k)
      if (o[k + 1] < o[k]) throw nb::value_error("sum_pieces: bad offsets");
  }
  mk::ov::Rings out;
  mk::un::UnionStats st;
  i64 bad = -1;
  {
    nb::gil_scoped_release nogil;
    mk::un::sum_pieces_union(PA.data(), OA.data(), (i64)OA.shape(0) - 1, PB.data(), OB.data(),
                             (i64)OB.shape(0) - 1, out, st, max_crossings, max_pairs, cull, &bad);
  }
  return result(out, st, bad, -1);
}

}  // namespace

void bind_union(nb::module_& m) {
  // the default limits: those of the sums (minkowski.hpp Limits: crossings), and as
  // many candidate pairs as 64 per crossing allowed
  const i64 cross = mk::ms::Limits().crossings, pairs = cross * 64;
  m.def("union_convex", &union_convex, "xy"_a.noconvert(), "offsets"_a.noconvert(),
        "max_crossings"_a = cross, "max_pairs"_a = pairs, "cull"_a = true);
  m.def("sum_pieces_union", &sum_pieces_union, "pa"_a.noconvert(), "oa"_a.noconvert(),
        "pb"_a.noconvert(), "ob"_a.noconvert(), "max_crossings"_a = cross, "max_pairs"_a = pairs,
        "cull"_a = true);
}

}  // namespace mk_bind
