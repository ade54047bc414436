// general.cpp -- bindings of the non-convex sums (minkowski.hpp) into
// minkowski2d._core._ext: one call computes many pairs of operands from one table.
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/tuple.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include "bind.hpp"
#include "exact.hpp"
#include "minkowski.hpp"
#include "parallel.hpp"

namespace nb = nanobind;
using namespace nb::literals;
using mk::i64;

namespace mk_bind {
namespace {

constexpr int ERODE = -1;

// general_sums(operands: xy (N, 2), ring_off, poly_off, op_off, kind (O,) int8;
//              pieces: pc_xy (M, 2), pc_off, op_pc_off; pairs ia, ib (K,); method,
//              limits (conv segments, piece pairs, crossings), threads)
//   -> (xy (T, 2), ring_off, poly_off, pair_off (K + 1,), status (K,) int32,
//       method used (K,) int8)
nb::tuple general_sums(In2<double> XY, In1<i64> RO, In1<i64> PO, In1<i64> OO,
                       In1<std::int8_t> KIND, In2<double> PCXY, In1<i64> PCO, In1<i64> OPC,
                       In1<i64> IA, In1<i64> IB, int method, i64 max_segments,
                       i64 max_piece_pairs, i64 max_crossings, int threads) {
  // method ERODE (-1): the erosion IA[k] ⊖ IB[k] instead of the sum
  const i64 n = (i64)XY.shape(0), nr = (i64)RO.shape(0) - 1, np_ = (i64)PO.shape(0) - 1;
  const i64 no = (i64)OO.shape(0) - 1, m = (i64)PCXY.shape(0), nq = (i64)PCO.shape(0) - 1;
  const i64 K = (i64)IA.shape(0);
  if (XY.shape(1) != 2 || PCXY.shape(1) != 2)
    throw nb::value_error("general_sums: coordinates must have shape (n, 2)");
  check_offsets(RO.data(), nr, n, "general_sums: bad ring offsets");
  check_offsets(PO.data(), np_, nr, "general_sums: bad polygon offsets");
  check_offsets(OO.data(), no, np_, "general_sums: bad operand offsets");
  check_offsets(PCO.data(), nq, m, "general_sums: bad piece offsets");
  check_offsets(OPC.data(), no, nq, "general_sums: bad operand piece offsets");
  if ((i64)KIND.shape(0) != no || (i64)IB.shape(0) != K)
    throw nb::value_error("general_sums: bad kind or pair arrays");
  for (i64 p = 0; p < np_; ++p)
    if (PO.data()[p + 1] == PO.data()[p]) throw nb::value_error("general_sums: empty polygon");
  for (i64 k = 0; k < K; ++k)
    if (IA.data()[k] < 0 || IA.data()[k] >= no || IB.data()[k] < 0 || IB.data()[k] >= no)
      throw nb::value_error("general_sums: operand index out of range");
  check_finite(XY.data(), 2 * n, "general_sums: non-finite");
  check_finite(PCXY.data(), 2 * m, "general_sums: non-finite");

  mk::ms::Table T{XY.data(),   RO.data(),  PO.data(), OO.data(), KIND.data(),
                  PCXY.data(), PCO.data(), OPC.data(), no};
  mk::ms::Limits L;
  L.conv_segments = max_segments;
  L.piece_pairs = max_piece_pairs;
  L.crossings = max_crossings;
  std::vector<mk::ov::Rings> res(K);
  std::vector<std::int32_t> status(K);
  std::vector<std::int8_t> used(K, 0);
  {
    nb::gil_scoped_release nogil;
    auto work = [&](i64 k0, i64 k1) {
      for (i64 k = k0; k < k1; ++k) {
        int u = 0;
        if (method == ERODE)
          mk::ms::erode_pair(T, IA.data()[k], IB.data()[k], L, res[k]);
        else
          mk::ms::sum_pair(T, IA.data()[k], IB.data()[k], method, L, res[k], &u);
        status[k] = res[k].status;
        used[k] = (std::int8_t)u;
      }
    };
    // blocks of 4 pairs handed out to the next free thread keep the threads busy when
    // costs vary along the list
    const i64 block = 4;
    mk::parallel_tasks((K + block - 1) / block, threads,
                       [&](i64 b) { work(b * block, std::min(K, (b + 1) * block)); });
  }
  // concatenate
  std::vector<double> xy;
  std::vector<i64> ro{0}, po{0}, pairo{0};
  for (i64 k = 0; k < K; ++k) {
    const mk::ov::Rings& r = res[k];
    i64 base = (i64)xy.size() / 2, rbase = (i64)ro.size() - 1;
    xy.insert(xy.end(), r.xy.begin(), r.xy.end());
    for (std::size_t i = 1; i < r.ring_off.size(); ++i) ro.push_back(base + r.ring_off[i]);
    for (std::size_t i = 1; i < r.poly_off.size(); ++i) po.push_back(rbase + r.poly_off[i]);
    pairo.push_back((i64)po.size() - 1);
  }
  return nb::make_tuple(to_numpy(xy, xy.size() / 2, 2), to_numpy(ro, ro.size(), 0),
                        to_numpy(po, po.size(), 0), to_numpy(pairo, pairo.size(), 0),
                        to_numpy(status, status.size(), 0), to_numpy(used, used.size(), 0));
}

// degenerate_pieces(pieces of A (coords, offsets), pieces of B) -> (polylines xy (L, 2),
// polyline offsets, points (P, 2)): placements inside the regularized union of all
// piece sums that lie in no piece sum's interior.
nb::tuple degenerate_pieces(In2<double> PA, In1<i64> OA, In2<double> PB, In1<i64> OB) {
  check_offsets(OA.data(), (i64)OA.shape(0) - 1, (i64)PA.shape(0), "degenerate: bad offsets");
  check_offsets(OB.data(), (i64)OB.shape(0) - 1, (i64)PB.shape(0), "degenerate: bad offsets");
  std::vector<double> lines, points;
  std::vector<i64> off;
  int code;
  {
    nb::gil_scoped_release nogil;
    mk::ov::Geo g;
    std::vector<std::vector<mk::ov::EdgeIn>> parts;
    code = mk::ms::piece_sums(g, PA.data(), OA.data(), (i64)OA.shape(0) - 1, PB.data(),
                              OB.data(), (i64)OB.shape(0) - 1, parts);
    if (code == mk::OK) {
      mk::ov::Overlay o(g);
      o.degenerate(parts, lines, off, points);
    }
  }
  if (code != mk::OK) throw nb::value_error("degenerate: a piece is not convex");
  return nb::make_tuple(to_numpy(lines, lines.size() / 2, 2), to_numpy(off, off.size(), 0),
                        to_numpy(points, points.size() / 2, 2));
}

// general_pair(a (n, 2), b (m, 2), method, limits) -> (status, which, reason, ring, vertex,
// xy, ring_off, poly_off): A ⊕ B for two rings in one call -- both validated exactly
// first (status INVALID_POLYGON or NONFINITE names the operand `which`, the reason, the
// ring and the vertex), then summed. The fast path of minkowski_sum_general.
nb::tuple general_pair(In2<double> A, In2<double> B, int method, i64 max_segments,
                       i64 max_piece_pairs, i64 max_crossings) {
  if (A.shape(1) != 2 || B.shape(1) != 2)
    throw nb::value_error("general_pair: coordinates must have shape (n, 2)");
  const i64 na = (i64)A.shape(0), nb_ = (i64)B.shape(0);
  std::vector<double> xy(2 * (na + nb_));
  std::memcpy(xy.data(), A.data(), sizeof(double) * 2 * na);
  std::memcpy(xy.data() + 2 * na, B.data(), sizeof(double) * 2 * nb_);
  const i64 ro[3] = {0, na, na + nb_}, po[3] = {0, 1, 2}, oo[3] = {0, 1, 2};
  const std::int8_t kind[2] = {0, 0};
  const i64 pco[1] = {0}, opc[3] = {0, 0, 0};
  mk::ms::Table T{xy.data(), ro, po, oo, kind, nullptr, pco, opc, 2};
  mk::ms::Limits L;
  L.conv_segments = max_segments;
  L.piece_pairs = max_piece_pairs;
  L.crossings = max_crossings;
  mk::ov::Rings out;
  mk::polygon::Problem pr;
  int which = -1;
  {
    nb::gil_scoped_release nogil;
    for (int k = 0; k < 2 && pr.ok(); ++k) {
      int orient;
      std::uint8_t disc;
      const i64 rk[2] = {0, k == 0 ? na : nb_};
      const i64 pk[2] = {0, 1};
      pr = mk::polygon::check(xy.data() + 2 * ro[k], rk, 1, pk, 1, false, &orient, &disc);
      if (pr.ok() && disc) pr.status = mk::RANGE;  // a pinched ring: the general path
      if (!pr.ok()) which = k;
    }
    if (pr.ok()) mk::ms::sum_pair(T, 0, 1, method, L, out);
  }
  nb::tuple res = nb::make_tuple(to_numpy(out.xy, out.xy.size() / 2, 2),
                                 to_numpy(out.ring_off, out.ring_off.size(), 0),
                                 to_numpy(out.poly_off, out.poly_off.size(), 0));
  int status = pr.ok() ? out.status : pr.status;
  return nb::make_tuple(status, which, pr.reason, pr.ring, pr.vertex, res[0], res[1], res[2]);
}

}  // namespace

void bind_general(nb::module_& m) {
  m.def("general_sums", &general_sums, "xy"_a.noconvert(), "ring_off"_a.noconvert(),
        "poly_off"_a.noconvert(), "op_off"_a.noconvert(), "kind"_a.noconvert(),
        "pc_xy"_a.noconvert(), "pc_off"_a.noconvert(), "op_pc_off"_a.noconvert(),
        "ia"_a.noconvert(), "ib"_a.noconvert(), "method"_a, "max_segments"_a,
        "max_piece_pairs"_a, "max_crossings"_a, "threads"_a = 1);
  m.def("general_pair", &general_pair, "a"_a.noconvert(), "b"_a.noconvert(), "method"_a,
        "max_segments"_a, "max_piece_pairs"_a, "max_crossings"_a);
  m.def("degenerate_pieces", &degenerate_pieces, "pa"_a.noconvert(), "oa"_a.noconvert(),
        "pb"_a.noconvert(), "ob"_a.noconvert());
  m.attr("METHOD_ERODE") = ERODE;
  m.attr("METHOD_AUTO") = (int)mk::ms::AUTO;
  m.attr("METHOD_PIECES") = (int)mk::ms::PIECES;
  m.attr("METHOD_CONVOLUTION") = (int)mk::ms::CONVOLUTION;
  nb::dict methods;  // the public names of the methods
  methods["auto"] = (int)mk::ms::AUTO;
  methods["decomposition"] = (int)mk::ms::PIECES;
  methods["convolution"] = (int)mk::ms::CONVOLUTION;
  m.attr("METHODS") = methods;
  const mk::ms::Limits L;
  nb::dict limits;  // the default work limits (minkowski.hpp Limits)
  limits["MAX_CONVOLUTION_SEGMENTS"] = (long long)L.conv_segments;
  limits["MAX_PIECE_PAIRS"] = (long long)L.piece_pairs;
  limits["MAX_CROSSINGS"] = (long long)L.crossings;
  m.attr("GENERAL_LIMITS") = limits;
}

}  // namespace mk_bind
