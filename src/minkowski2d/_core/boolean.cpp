// boolean.cpp -- bindings of the polygon booleans and line clipping (boolean.hpp).
//
//   boolean_f(xy (N, 2), ring_off, poly_off, a_task_off (T + 1,), b_task_off (T + 1,),
//             rule, validate, threads, max_crossings, max_pairs)
//       -> (xy (M, 2) closed rings, ring_off, poly_off, task_off (T + 1,), info (T, 5))
//   clip_lines_f(lines: xy, line_off, task_off, polygons: xy, ring_off, poly_off,
//                task_off, fill, validate, keep_inside, threads, max_crossings, max_pairs)
//       -> (xy (M, 2), line_off, task_off (T + 1,), info (T, 5))
// Task t is the polygons [a_task_off[t], a_task_off[t + 1]) (operand a) against
// [b_task_off[t], b_task_off[t + 1]) (operand b), both of the one set of polygon arrays
// (one reading of both operands); clip_lines_f's polygons are task_off's. info rows: status,
// operand, reason, ring (inside the operand), vertex. The offsets come from
// minkowski2d.boolean (not from users): malformed ones are a ValueError.
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/tuple.h>

#include <cstdint>
#include <vector>

#include "bind.hpp"
#include "boolean.hpp"
#include "parallel.hpp"

namespace nb = nanobind;
using namespace nb::literals;
using mk::i64;

namespace mk_bind {
namespace {

// the polygon arrays' offsets, and task offsets into them: all polygons in order
// (whole), or any ascending range of them
void check_polys(const In2<double>& X, const In1<i64>& RO, const In1<i64>& PO,
                 const In1<i64>& TO, i64 T, bool whole = true) {
  if (X.shape(1) != 2) throw nb::value_error("boolean: coordinates must have shape (n, 2)");
  const i64 n = (i64)X.shape(0), R = (i64)RO.shape(0) - 1, P = (i64)PO.shape(0) - 1;
  const i64 *ro = RO.data(), *po = PO.data(), *to = TO.data();
  check_offsets(ro, R, n, "boolean: bad offsets");
  check_offsets(po, P, R, "boolean: bad offsets", true);
  // task offsets: all polygons in order (whole), or any ascending range of them
  if ((i64)TO.shape(0) != T + 1 || (whole && (to[0] != 0 || to[T] != P)) || to[0] < 0 ||
      to[T] > P)
    throw nb::value_error("boolean: bad offsets");
  for (i64 t = 0; t < T; ++t)
    if (to[t + 1] < to[t]) throw nb::value_error("boolean: bad offsets");
}

Out<double> info_array(const std::vector<mk::bop::Fault>& f, const std::vector<int>& status) {
  const i64 T = (i64)f.size();
  double* o = alloc<double>(5 * (T > 0 ? T : 1));
  for (i64 t = 0; t < T; ++t) {
    o[5 * t] = f[t].status != mk::OK ? f[t].status : status[t];
    o[5 * t + 1] = (double)f[t].operand;
    o[5 * t + 2] = (double)f[t].reason;
    o[5 * t + 3] = (double)f[t].ring;
    o[5 * t + 4] = (double)f[t].vertex;
  }
  return owned(o, (std::size_t)T, 5);
}

nb::tuple boolean_f(In2<double> X, In1<i64> RO, In1<i64> PO, In1<i64> ATO, In1<i64> BTO,
                    int rule, bool validate, int threads, i64 max_crossings, i64 max_pairs) {
  const i64 T = (i64)ATO.shape(0) - 1;
  if (T < 0) throw nb::value_error("boolean: bad offsets");
  check_polys(X, RO, PO, ATO, T, false);
  check_polys(X, RO, PO, BTO, T, false);
  if (!mk::ov::rule_valid(rule)) throw nb::value_error("boolean: unknown rule");
  std::vector<mk::ov::Rings> res((std::size_t)T);
  std::vector<mk::bop::Fault> faults((std::size_t)T);
  mk::bop::Limits lim{max_crossings, max_pairs};
  {
    nb::gil_scoped_release nogil;
    mk::parallel_tasks(T, threads, [&](i64 t) {
      mk::bop::Polys a{X.data(), RO.data(), PO.data(), ATO.data()[t], ATO.data()[t + 1]};
      mk::bop::Polys b{X.data(), RO.data(), PO.data(), BTO.data()[t], BTO.data()[t + 1]};
      mk::bop::boolean(a, b, rule, validate, lim, res[t], faults[t]);
    });
  }
  // concatenate, closing every ring
  i64 rows = 0, nrings = 0, npolys = 0;
  std::vector<int> status((std::size_t)T);
  for (i64 t = 0; t < T; ++t) {
    const mk::ov::Rings& r = res[t];
    status[t] = r.status;
    if (r.status == mk::OK) count_closed(r, rows, nrings, npolys);
  }
  double* oxy = alloc<double>(2 * rows);
  i64* oro = alloc<i64>(nrings + 1);
  i64* opo = alloc<i64>(npolys + 1);
  i64* oto = alloc<i64>(T + 1);
  i64 row = 0, ring = 0, poly = 0;
  oro[0] = opo[0] = oto[0] = 0;
  for (i64 t = 0; t < T; ++t) {
    const mk::ov::Rings& R = res[t];
    if (R.status == mk::OK) append_closed(R, oxy, oro, opo, row, ring, poly);
    oto[t + 1] = poly;
  }
  return nb::make_tuple(owned(oxy, (std::size_t)rows, 2), owned(oro, (std::size_t)nrings + 1, 0),
                        owned(opo, (std::size_t)npolys + 1, 0), owned(oto, (std::size_t)T + 1, 0),
                        info_array(faults, status));
}

nb::tuple clip_lines_f(In2<double> LX, In1<i64> LO, In1<i64> LT, In2<double> AX, In1<i64> ARO,
                       In1<i64> APO, In1<i64> ATO, int fill, bool validate, bool keep_inside,
                       int threads, i64 max_crossings, i64 max_pairs) {
  const i64 T = (i64)LT.shape(0) - 1;
  if (T < 0 || LX.shape(1) != 2) throw nb::value_error("clip_lines: bad arrays");
  check_polys(AX, ARO, APO, ATO, T);
  {
    const i64 n = (i64)LX.shape(0), L = (i64)LO.shape(0) - 1;
    const i64 *lo = LO.data(), *lt = LT.data();
    check_offsets(lo, L, n, "clip_lines: bad offsets");
    check_offsets(lt, T, L, "clip_lines: bad offsets");
  }
  if (fill < 0 || fill > 3) throw nb::value_error("clip_lines: unknown fill rule");
  std::vector<std::vector<double>> xy((std::size_t)T);
  std::vector<std::vector<i64>> off((std::size_t)T);
  std::vector<mk::bop::Fault> faults((std::size_t)T);
  std::vector<int> status((std::size_t)T);
  mk::bop::Limits lim{max_crossings, max_pairs};
  {
    nb::gil_scoped_release nogil;
    mk::parallel_tasks(T, threads, [&](i64 t) {
      mk::bop::Polys a{AX.data(), ARO.data(), APO.data(), ATO.data()[t], ATO.data()[t + 1]};
      status[t] = mk::bop::clip(LX.data(), LO.data(), LT.data()[t], LT.data()[t + 1], a, fill,
                                validate, keep_inside, lim, xy[t], off[t], faults[t]);
    });
  }
  i64 rows = 0, nl = 0;
  for (i64 t = 0; t < T; ++t)
    if (status[t] == mk::OK) {
      rows += (i64)xy[t].size() / 2;
      nl += (i64)off[t].size() - 1;
    }
  double* oxy = alloc<double>(2 * rows);
  i64* olo = alloc<i64>(nl + 1);
  i64* oto = alloc<i64>(T + 1);
  i64 row = 0, line = 0;
  olo[0] = oto[0] = 0;
  for (i64 t = 0; t < T; ++t) {
    if (status[t] == mk::OK) {
      for (std::size_t k = 0; k < xy[t].size(); ++k) oxy[2 * row + k] = xy[t][k];
      for (std::size_t k = 1; k < off[t].size(); ++k) olo[++line] = row + off[t][k];
      row += (i64)xy[t].size() / 2;
    }
    oto[t + 1] = line;
  }
  return nb::make_tuple(owned(oxy, (std::size_t)rows, 2), owned(olo, (std::size_t)nl + 1, 0),
                        owned(oto, (std::size_t)T + 1, 0), info_array(faults, status));
}

}  // namespace

void bind_boolean(nb::module_& m) {
  m.def("boolean_f", &boolean_f, "xy"_a.noconvert(), "ring_off"_a.noconvert(),
        "poly_off"_a.noconvert(), "a_task_off"_a.noconvert(), "b_task_off"_a.noconvert(),
        "rule"_a, "validate"_a, "threads"_a, "max_crossings"_a, "max_pairs"_a);
  m.def("clip_lines_f", &clip_lines_f, "l_xy"_a.noconvert(), "l_off"_a.noconvert(),
        "l_task_off"_a.noconvert(), "a_xy"_a.noconvert(), "a_ring_off"_a.noconvert(),
        "a_poly_off"_a.noconvert(), "a_task_off"_a.noconvert(), "fill"_a, "validate"_a,
        "keep_inside"_a, "threads"_a, "max_crossings"_a, "max_pairs"_a);
  m.attr("OVERLAY_XOR") = (int)mk::ov::XOR;
  m.attr("NO_LIMIT") = (long long)mk::bop::Limits{}.max_crossings;  // "no limit" of a work counter
  nb::dict fills;
  fills["positive"] = (int)mk::ov::FILL_POSITIVE;
  fills["nonzero"] = (int)mk::ov::FILL_NONZERO;
  fills["evenodd"] = (int)mk::ov::FILL_EVENODD;
  fills["negative"] = (int)mk::ov::FILL_NEGATIVE;
  m.attr("FILL_RULES") = fills;
}

}  // namespace mk_bind
