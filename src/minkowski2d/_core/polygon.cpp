// polygon.cpp -- bindings of the exact polygon checks (polygon.hpp) and the triangulation
// (triangulate.hpp) into minkowski2d._core._ext:
//
//   check_polygons_f(coords (N, 2) float64, ring_offsets (R + 1,) int64,
//                    polygon_offsets (P + 1,) int64, disjoint: bool)
//       -> (status, reason, ring, vertex, orientation (R,) int8, disconnected (P,) bool)
//   triangulate_polygons_f(coords, ring_offsets, polygon_offsets, delaunay=True)
//       -> (status, reason, ring, vertex, triangles (T, 3) int64)
//   incircle_f / incircle_exact_f(ax, ay, bx, by, cx, cy, dx, dy) -> sign (exact.hpp)
//
// status is a Status (OK, NONFINITE, INVALID_POLYGON), reason an Invalid code, ring the
// global ring index and vertex the index inside that ring (the caller's numbering, the
// first vertex of the offending edge). The offsets are checked here (malformed ones are a
// ValueError: they come from minkowski2d._polygon, not from users); the kernels run with
// the GIL released.
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/tuple.h>

#include <cstdint>
#include <vector>

#include "bind.hpp"
#include "boxes.hpp"
#include "exact.hpp"
#include "polygon.hpp"
#include "triangulate.hpp"

namespace nb = nanobind;
using namespace nb::literals;
using mk::i64;

namespace mk_bind {
namespace {

void check_offsets(const In2<double>& C, const In1<i64>& RO, const In1<i64>& PO) {
  if (C.shape(1) != 2) throw nb::value_error("polygons: coords must have shape (N, 2)");
  const i64 n = (i64)C.shape(0), R = (i64)RO.shape(0) - 1, P = (i64)PO.shape(0) - 1;
  if (R < 0 || P < 0) throw nb::value_error("polygons: offsets must not be empty");
  const i64* ro = RO.data();
  const i64* po = PO.data();
  for (i64 r = 0; r <= R; ++r)
    if (ro[r] < 0 || ro[r] > n || (r > 0 && ro[r] < ro[r - 1]))
      throw nb::value_error("polygons: ring offsets out of order or range");
  for (i64 p = 0; p <= P; ++p)
    if (po[p] < 0 || po[p] > R || (p > 0 && po[p] <= po[p - 1]))
      throw nb::value_error("polygons: polygon offsets out of order or range (each needs a ring)");
}

nb::tuple check_polygons(In2<double> C, In1<i64> RO, In1<i64> PO, bool disjoint) {
  check_offsets(C, RO, PO);
  const i64 R = (i64)RO.shape(0) - 1, P = (i64)PO.shape(0) - 1;
  std::vector<int> orient(R > 0 ? R : 1);
  std::vector<std::uint8_t> disc(P > 0 ? P : 1);
  mk::polygon::Problem pr;
  {
    nb::gil_scoped_release nogil;
    pr = mk::polygon::check(C.data(), RO.data(), R, PO.data(), P, disjoint, orient.data(),
                            disc.data());
  }
  std::int8_t* o = alloc<std::int8_t>(R);
  for (i64 r = 0; r < R; ++r) o[r] = (std::int8_t)orient[r];
  bool* d = alloc<bool>(P);
  for (i64 p = 0; p < P; ++p) d[p] = disc[p] != 0;
  return nb::make_tuple(pr.status, pr.reason, pr.ring, pr.vertex, owned(o, (std::size_t)R, 0),
                        owned(d, (std::size_t)P, 0));
}

nb::tuple triangulate_polygons(In2<double> C, In1<i64> RO, In1<i64> PO, bool delaunay) {
  check_offsets(C, RO, PO);
  const i64 R = (i64)RO.shape(0) - 1, P = (i64)PO.shape(0) - 1;
  std::vector<i64> tri;
  mk::polygon::Problem pr;
  {
    nb::gil_scoped_release nogil;
    pr = mk::polygon::triangulate(C.data(), RO.data(), R, PO.data(), P, tri, delaunay);
  }
  if (!pr.ok()) tri.clear();
  return nb::make_tuple(pr.status, pr.reason, pr.ring, pr.vertex,
                        to_numpy(tri, tri.size() / 3, 3));
}

// box_pairs_f(xmin, xmax, ymin, ymax) -> (k, 2) int64: the pairs i < j of overlapping
// closed boxes (boxes.hpp; for the tests).
Out<i64> box_pairs_array(In1<double> X0, In1<double> X1, In1<double> Y0, In1<double> Y1) {
  const i64 n = (i64)X0.shape(0);
  if ((i64)X1.shape(0) != n || (i64)Y0.shape(0) != n || (i64)Y1.shape(0) != n)
    throw nb::value_error("box_pairs: the four arrays must have one length");
  std::vector<i64> out;
  {
    nb::gil_scoped_release nogil;
    mk::box_pairs(n, X0.data(), X1.data(), Y0.data(), Y1.data(), [&](i64 i, i64 j) {
      out.push_back(i);
      out.push_back(j);
    });
  }
  return to_numpy(out, out.size() / 2, 2);
}

}  // namespace

void bind_polygon(nb::module_& m) {
  m.attr("INVALID_POLYGON") = (int)mk::INVALID_POLYGON;
  nb::dict reasons;
  reasons["RING_FEW_VERTICES"] = (int)mk::RING_FEW_VERTICES;
  reasons["RING_NO_AREA"] = (int)mk::RING_NO_AREA;
  reasons["RING_SPIKE"] = (int)mk::RING_SPIKE;
  reasons["RING_CROSSES"] = (int)mk::RING_CROSSES;
  reasons["RING_OVERLAPS"] = (int)mk::RING_OVERLAPS;
  reasons["RING_TOUCHES"] = (int)mk::RING_TOUCHES;
  reasons["RINGS_CROSS"] = (int)mk::RINGS_CROSS;
  reasons["RINGS_OVERLAP"] = (int)mk::RINGS_OVERLAP;
  reasons["HOLE_OUTSIDE"] = (int)mk::HOLE_OUTSIDE;
  reasons["HOLE_IN_HOLE"] = (int)mk::HOLE_IN_HOLE;
  reasons["POLYGONS_OVERLAP"] = (int)mk::POLYGONS_OVERLAP;
  m.attr("INVALID_REASONS") = reasons;
  m.def("check_polygons_f", &check_polygons, "coords"_a.noconvert(),
        "ring_offsets"_a.noconvert(), "polygon_offsets"_a.noconvert(), "disjoint"_a = false);
  m.def("box_pairs_f", &box_pairs_array, "xmin"_a.noconvert(), "xmax"_a.noconvert(),
        "ymin"_a.noconvert(), "ymax"_a.noconvert());
  m.def("triangulate_polygons_f", &triangulate_polygons, "coords"_a.noconvert(),
        "ring_offsets"_a.noconvert(), "polygon_offsets"_a.noconvert(), "delaunay"_a = true);
  m.def("incircle_f",
        [](double ax, double ay, double bx, double by, double cx, double cy, double dx,
           double dy) { return mk::incircle(ax, ay, bx, by, cx, cy, dx, dy); });
  m.def("incircle_exact_f",
        [](double ax, double ay, double bx, double by, double cx, double cy, double dx,
           double dy) { return mk::incircle_exact(ax, ay, bx, by, cx, cy, dx, dy); });
}

}  // namespace mk_bind
