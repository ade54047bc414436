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
  check_offsets(off, np, n, "union_convex: bad offsets");
  const double* xy = XY.data();
  mk::ov::Rings out;
  mk::un::UnionStats st;
  i64 bad_poly = -1, bad_vertex = -1;
  {
    nb::gil_scoped_release nogil;
    mk::un::union_rings(xy, off, np, cull, max_crossings, max_pairs, out, st, bad_poly,
                        bad_vertex);
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
    check_offsets(o, np, n, "sum_pieces: bad offsets");
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
