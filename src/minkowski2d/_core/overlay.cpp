// overlay.cpp -- bindings of the exact overlay (overlay.hpp) into minkowski2d._core._ext.
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/tuple.h>

#include <cstdint>

#include "bind.hpp"
#include "exact.hpp"
#include "overlay.hpp"

namespace nb = nanobind;
using namespace nb::literals;
using mk::i64;

namespace mk_bind {
namespace {

// (xy (K, 2), ring_off (R + 1,), poly_off (P + 1,)) of an overlay that has run
nb::tuple overlay_result(const mk::ov::Overlay& o) {
  return nb::make_tuple(to_numpy(o.out_xy, o.out_xy.size() / 2, 2), to_numpy(o.ring_off, o.ring_off.size(), 0),
                        to_numpy(o.poly_off, o.poly_off.size(), 0));
}

// overlay_rings(hi (N, 2), lo (N, 2) or empty, ring_off (R + 1,), weight (R,), layer (R,),
// rule) -> (xy, ring_off, poly_off, status, (pairs, crossings, vertices, edges))
nb::tuple overlay_rings(In2<double> H, In2<double> L, In1<i64> RO, In1<i64> W, In1<i64> LY,
                        int rule) {
  const i64 n = (i64)H.shape(0), nr = (i64)RO.shape(0) - 1;
  if (H.shape(1) != 2) throw nb::value_error("overlay: coordinates must have shape (n, 2)");
  const bool has_lo = L.shape(0) != 0;
  if (has_lo && ((i64)L.shape(0) != n || L.shape(1) != 2))
    throw nb::value_error("overlay: lo must have the shape of hi");
  if (nr < 0 || (i64)W.shape(0) != nr || (i64)LY.shape(0) != nr)
    throw nb::value_error("overlay: one weight and one layer per ring");
  const i64* ro = RO.data();
  if (ro[0] != 0 || ro[nr] != n) throw nb::value_error("overlay: bad ring offsets");
  for (i64 r = 0; r < nr; ++r)
    if (ro[r + 1] < ro[r]) throw nb::value_error("overlay: bad ring offsets");
  const double* h = H.data();
  const double* l = has_lo ? L.data() : nullptr;
  for (i64 q = 0; q < 2 * n; ++q)
    if (!(h[q] - h[q] == 0) || (l && !(l[q] - l[q] == 0)))
      throw nb::value_error("overlay: non-finite coordinate");
  mk::ov::Overlay o;
  int status;
  {
    nb::gil_scoped_release nogil;
    for (i64 i = 0; i < n; ++i) {
      double lx = l ? l[2 * i] : 0.0, ly = l ? l[2 * i + 1] : 0.0;
      // canonical DD: hi = fl(hi + lo)
      o.add_point(mk::ov::dd_sum(h[2 * i], lx), mk::ov::dd_sum(h[2 * i + 1], ly));
    }
    for (i64 r = 0; r < nr; ++r)
      o.add_ring(ro[r], ro[r + 1] - ro[r], (int)W.data()[r], (int)LY.data()[r]);
    status = o.run(rule);
  }
  nb::tuple res = overlay_result(o);
  return nb::make_tuple(res[0], res[1], res[2], status,
                        nb::make_tuple(o.n_pairs, o.n_crossings, o.n_vertices, o.n_edges));
}

}  // namespace

void bind_overlay(nb::module_& m) {
  m.def("overlay_rings", &overlay_rings, "hi"_a.noconvert(), "lo"_a.noconvert(),
        "ring_off"_a.noconvert(), "weight"_a.noconvert(), "layer"_a.noconvert(), "rule"_a);
  m.attr("OVERLAY_UNION") = (int)mk::ov::UNION;
  m.attr("OVERLAY_DIFFERENCE") = (int)mk::ov::DIFFERENCE;
  m.attr("OVERLAY_INTERSECTION") = (int)mk::ov::INTERSECTION;
}

}  // namespace mk_bind
