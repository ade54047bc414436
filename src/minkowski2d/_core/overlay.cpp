// overlay.cpp -- bindings of the exact overlay (overlay.hpp) into minkowski2d._core._ext.
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/tuple.h>

#include <cstdint>

#include "bind.hpp"
#include "exact.hpp"
#include "minkowski.hpp"
#include "overlay.hpp"

namespace nb = nanobind;
using namespace nb::literals;
using mk::i64;

namespace mk_bind {
namespace {

nb::tuple rings_result(const mk::ov::Rings& r) {
  return nb::make_tuple(to_numpy(r.xy, r.xy.size() / 2, 2), to_numpy(r.ring_off, r.ring_off.size(), 0),
                        to_numpy(r.poly_off, r.poly_off.size(), 0), r.status);
}

// Reads rings (hi (N, 2), lo (N, 2) or (0, 2), ring_off (R + 1,)) into g: one edge list
// per ring.
std::vector<std::vector<mk::ov::EdgeIn>> read_rings(mk::ov::Geo& g, In2<double> H, In2<double> L,
                                                     In1<i64> RO, const i64* w, const i64* ly) {
  const i64 n = (i64)H.shape(0), nr = (i64)RO.shape(0) - 1;
  const double* h = H.data();
  const double* l = L.shape(0) ? L.data() : nullptr;
  for (i64 i = 0; i < n; ++i) {
    double lx = l ? l[2 * i] : 0.0, lyv = l ? l[2 * i + 1] : 0.0;
    g.point(mk::ov::dd_sum(h[2 * i], lx), mk::ov::dd_sum(h[2 * i + 1], lyv));
  }
  std::vector<std::vector<mk::ov::EdgeIn>> parts(nr);
  const i64* ro = RO.data();
  for (i64 r = 0; r < nr; ++r)
    mk::ov::add_ring(g, ro[r], ro[r + 1] - ro[r], w ? (int)w[r] : 1, ly ? (int)ly[r] : 0,
                     parts[r]);
  return parts;
}

void check_rings(In2<double> H, In2<double> L, In1<i64> RO) {
  const i64 n = (i64)H.shape(0), nr = (i64)RO.shape(0) - 1;
  if (H.shape(1) != 2) throw nb::value_error("overlay: coordinates must have shape (n, 2)");
  if (L.shape(0) != 0 && ((i64)L.shape(0) != n || L.shape(1) != 2))
    throw nb::value_error("overlay: lo must have the shape of hi");
  const i64* ro = RO.data();
  check_offsets(ro, nr, n, "overlay: bad ring offsets");
  const double* h = H.data();
  const double* l = L.shape(0) ? L.data() : nullptr;
  check_finite(h, 2 * n, "overlay: non-finite coordinate");
  if (l) check_finite(l, 2 * n, "overlay: non-finite coordinate");
}

// overlay_rings(hi, lo, ring_off, weight (R,), layer (R,), rule) -> (xy, ring_off,
// poly_off, status, (pairs, crossings, vertices, edges)): one flat overlay.
nb::tuple overlay_rings(In2<double> H, In2<double> L, In1<i64> RO, In1<i64> W, In1<i64> LY,
                        int rule) {
  check_rings(H, L, RO);
  const i64 nr = (i64)RO.shape(0) - 1;
  if ((i64)W.shape(0) != nr || (i64)LY.shape(0) != nr)
    throw nb::value_error("overlay: one weight and one layer per ring");
  mk::ov::Geo g;
  mk::ov::Overlay o(g);
  mk::ov::Rings out;
  {
    nb::gil_scoped_release nogil;
    auto parts = read_rings(g, H, L, RO, W.data(), LY.data());
    std::vector<mk::ov::EdgeIn> in;
    for (auto& p : parts) in.insert(in.end(), p.begin(), p.end());
    o.run(in, rule, out);
  }
  nb::tuple res = rings_result(out);
  return nb::make_tuple(res[0], res[1], res[2], res[3],
                        nb::make_tuple(o.n_pairs, o.n_crossings, o.n_vertices, o.n_edges));
}

void check_ragged(In2<double> XY, In1<i64> RO, In1<i64> PO) {
  const i64 n = (i64)XY.shape(0), nr = (i64)RO.shape(0) - 1, np = (i64)PO.shape(0) - 1;
  if (XY.shape(1) != 2) throw nb::value_error("sum: coordinates must have shape (n, 2)");
  const i64 *ro = RO.data(), *po = PO.data();
  check_offsets(ro, nr, n, "sum: bad offsets");
  check_offsets(po, np, nr, "sum: bad offsets", true);
  check_finite(XY.data(), 2 * n, "sum: non-finite coordinate");
}

// sum_convolution(A xy, ring_off, poly_off, B xy, ring_off, poly_off) -> (xy, ring_off,
// poly_off, status, (segments, crossings)): A ⊕ B by the full convolution.
nb::tuple sum_convolution(In2<double> AX, In1<i64> ARO, In1<i64> APO, In2<double> BX,
                          In1<i64> BRO, In1<i64> BPO) {
  check_ragged(AX, ARO, APO);
  check_ragged(BX, BRO, BPO);
  mk::ov::Geo g;
  mk::ov::Overlay o(g);
  mk::ov::Rings out;
  i64 nseg = 0;
  {
    nb::gil_scoped_release nogil;
    auto A = mk::ms::read_polygons(AX.data(), ARO.data(), APO.data(), (i64)APO.shape(0) - 1);
    auto B = mk::ms::read_polygons(BX.data(), BRO.data(), BPO.data(), (i64)BPO.shape(0) - 1);
    std::vector<mk::ov::EdgeIn> in;
    mk::ms::convolution(g, A, B, in);
    nseg = (i64)in.size();
    o.run(in, mk::ov::UNION, out);
  }
  nb::tuple res = rings_result(out);
  return nb::make_tuple(res[0], res[1], res[2], res[3], nb::make_tuple(nseg, o.n_crossings));
}

}  // namespace

void bind_overlay(nb::module_& m) {
  m.def("overlay_rings", &overlay_rings, "hi"_a.noconvert(), "lo"_a.noconvert(),
        "ring_off"_a.noconvert(), "weight"_a.noconvert(), "layer"_a.noconvert(), "rule"_a);
  m.def("sum_convolution", &sum_convolution, "a"_a.noconvert(), "a_ring_off"_a.noconvert(),
        "a_poly_off"_a.noconvert(), "b"_a.noconvert(), "b_ring_off"_a.noconvert(),
        "b_poly_off"_a.noconvert());
  m.attr("OVERLAY_UNION") = (int)mk::ov::UNION;
  m.attr("OVERLAY_DIFFERENCE") = (int)mk::ov::DIFFERENCE;
  m.attr("OVERLAY_INTERSECTION") = (int)mk::ov::INTERSECTION;
  nb::dict ops;  // the public names of the operations
  ops["union"] = (int)mk::ov::UNION;
  ops["difference"] = (int)mk::ov::DIFFERENCE;
  ops["intersection"] = (int)mk::ov::INTERSECTION;
  ops["xor"] = (int)mk::ov::XOR;
  m.attr("OVERLAY_OPS") = ops;
}

}  // namespace mk_bind
