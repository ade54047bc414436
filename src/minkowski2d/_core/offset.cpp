// offset.cpp -- the binding of offset.hpp into minkowski2d._core._ext: offset_rings (rings
// read and checked by the caller) and offset_polygons (shapely's polygons, checked here),
// one call for one polygonal set or a batch of them (threads over the batch, GIL
// released).
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/tuple.h>

#include <algorithm>
#include <memory>
#include <cstdint>
#include <cstring>
#include <vector>

#include "bind.hpp"
#include "exact.hpp"
#include "offset.hpp"
#include "parallel.hpp"
#include "polygon.hpp"

namespace nb = nanobind;
using namespace nb::literals;
using mk::i64;

namespace mk_bind {
namespace {

// Scratch of valid_parts.
struct CheckScratch {
  std::vector<i64> lpo;
  std::vector<int> orient;
  std::vector<std::uint8_t> disc;
  std::vector<mk::off::Pt> ring;
  mk::off::Chains chains;
  std::vector<std::pair<i64, i64>> crossings;
};

// What a thread of a call works with, kept between calls (buffer.hpp's
// with_thread_workspace: its buffers are reused, released when a call left them large).
struct Worker {
  mk::off::Offsetter off;
  CheckScratch cs;
  std::vector<mk::ms::Ring> rings;
  mk::off::Result one;  // offset_one's result (its buffers reused)
};
template <class F>
auto with_worker(F&& f) {
  return mk::with_thread_workspace<Worker>(
      [](const Worker& w) { return w.off.footprint() > (std::size_t(1) << 22); }, f);
}

mk::off::Params params(double distance, double tolerance, double default_rel, bool outer,
                       int join, double limit) {
  mk::off::Params p;
  p.distance = distance;
  p.tolerance = tolerance;
  p.default_rel = default_rel;
  p.outer = outer;
  p.join = join;
  p.limit = limit;
  return p;
}

// The results as closed rings: (xy (M, 2), ring_off, poly_off, geom_off (G + 1,),
// info (G, 5): status, code, least tolerance, tolerance used, path; extra).
nb::tuple pack(const std::vector<mk::off::Result>& res, bool labels) {
  const i64 ng = (i64)res.size();
  i64 rows = 0, nrings = 0, npolys = 0;
  for (auto& r : res) count_closed(r.rings, rows, nrings, npolys);
  double* oxy = alloc<double>(2 * rows);
  i64* oro = alloc<i64>(nrings + 1);
  i64* opo = alloc<i64>(npolys + 1);
  i64* ogo = alloc<i64>(ng + 1);
  double* oin = alloc<double>(5 * ng);  // status, code, least, eps, path
  std::vector<i64> lab;
  i64 row = 0, ring = 0, poly = 0;
  oro[0] = 0;
  opo[0] = 0;
  ogo[0] = 0;
  for (i64 g = 0; g < ng; ++g) {
    const mk::off::Result& r = res[(std::size_t)g];
    oin[5 * g] = r.status;
    oin[5 * g + 1] = r.code;
    oin[5 * g + 2] = r.least;
    oin[5 * g + 3] = r.eps;
    oin[5 * g + 4] = r.path;
    const auto& R = r.rings;
    append_closed(R, oxy, oro, opo, row, ring, poly);
    if (labels)  // each ring's closing vertex: DETOUR
      for (std::size_t k = 0; k + 1 < R.ring_off.size(); ++k) {
        lab.insert(lab.end(), r.labels.begin() + R.ring_off[k], r.labels.begin() + R.ring_off[k + 1]);
        lab.push_back(mk::off::DETOUR);
      }
    ogo[g + 1] = poly;
  }
  nb::object extra = nb::none();
  if (labels) {
    const mk::off::Result& r = res[0];
    extra = nb::make_tuple(to_numpy(lab, lab.size(), 0),
                           to_numpy(r.used_xy, r.used_xy.size() / 2, 2),
                           to_numpy(r.used_off, r.used_off.size(), 0), r.e0);
  }
  return nb::make_tuple(owned(oxy, (std::size_t)rows, 2), owned(oro, (std::size_t)nrings + 1, 0),
                        owned(opo, (std::size_t)npolys + 1, 0), owned(ogo, (std::size_t)ng + 1, 0),
                        owned(oin, (std::size_t)ng, 5), extra);
}

// offset_rings(xy (N, 2), ring_off (R + 1,), ring_hole (R,), geom_off (G + 1,), unite (G,),
//              delta (G,), distance, tolerance (NaN: default), default_rel, outer, join,
//              miter_limit, labels=False, threads=1, resolve=True)
//   -> (xy (M, 2) closed rings, ring_off, poly_off, geom_off (G + 1,), info (G, 5):
//       status, code, least tolerance, tolerance used, path (OFFSET_DIRECT, _RESOLVED,
//       _OVERLAID); extra)
// Geometry g is made of the rings ring_off[geom_off[g]] ..; its result is the polygons
// poly_off[geom_off[g]] .. of the output. With labels (one geometry only), extra is
// (label per output row, the rings offset (scaled, offset side right) as xy and offsets,
// e0): the output is then scaled by 2^-e0. resolve=False: curves with crossings all go to
// the overlay (the tests compare the resolver with it).
nb::tuple offset_rings(In2<double> XY, In1<i64> RO, In1<i64> RH, In1<i64> GO, In1<i64> UN,
                       In1<double> DL, double distance, double tolerance, double default_rel,
                       bool outer, int join, double limit, bool labels, int threads,
                       bool resolve) {
  const i64 n = (i64)XY.shape(0), nr = (i64)RO.shape(0) - 1, ng = (i64)GO.shape(0) - 1;
  if (XY.shape(1) != 2) throw nb::value_error("offset: coordinates must have shape (n, 2)");
  const i64 *ro = RO.data(), *go = GO.data(), *rh = RH.data(), *un = UN.data();
  const double* dl = DL.data();
  check_offsets(ro, nr, n, "offset: bad ring offsets");
  check_offsets(go, ng, nr, "offset: bad geometry offsets");
  if ((i64)RH.shape(0) != nr || (i64)UN.shape(0) != ng || (i64)DL.shape(0) != ng)
    throw nb::value_error("offset: bad offsets");
  const double* xy = XY.data();
  check_finite(xy, 2 * n, "offset: non-finite coordinate");
  if (labels && ng != 1) throw nb::value_error("offset: labels for one geometry only");
  mk::off::Params p = params(distance, tolerance, default_rel, outer, join, limit);
  p.resolve = resolve;
  std::vector<mk::off::Result> res((std::size_t)ng);
  {
    nb::gil_scoped_release nogil;
    mk::parallel_chunks(ng, threads, [&](int, i64 g0, i64 g1) {
      with_worker([&](Worker& wk) {
        for (i64 g = g0; g < g1; ++g) {
          wk.rings.clear();
          for (i64 r = go[g]; r < go[g + 1]; ++r)
            wk.rings.push_back(mk::ms::make_ring(xy + 2 * ro[r], ro[r + 1] - ro[r], rh[r] != 0));
          wk.off.run(wk.rings, un[g] != 0, dl[g], p, labels, res[(std::size_t)g]);
        }
      });
    });
  }
  return pack(res, labels);
}

// Are the P polygons (ring offsets ro[0 .. R], polygon offsets po[0 .. P] minus r0) a
// valid polygonal set for the offset: each polygon valid and connected, at least one?
// unite: their interiors overlap or touch (valid parts that the offset unites first).
// Is one ring of n points (closed or not) simple, by the offset's own exact crossing
// test (curve_crossings: no two edges meet but consecutive ones at their end, none folds
// back)? A simple ring of three or more distinct points is a valid polygon; false here
// only means "not shown": polygon.hpp's validator then decides and names the problem.
bool simple_ring(const double* xy, i64 n, CheckScratch& cs) {
  auto& v = cs.ring;
  v.clear();
  for (i64 i = 0; i < n; ++i) {
    const mk::off::Pt q{xy[2 * i], xy[2 * i + 1]};
    if (!(q.x - q.x == 0) || !(q.y - q.y == 0)) return false;
    if (v.empty() || v.back().x != q.x || v.back().y != q.y) v.push_back(q);
  }
  while (v.size() > 1 && v.front().x == v.back().x && v.front().y == v.back().y) v.pop_back();
  return v.size() >= 3 && mk::off::curve_crossings(v, cs.crossings, cs.chains, true) &&
         cs.crossings.empty();
}

bool valid_parts(const double* xy, const i64* ro, i64 R, const i64* po, i64 P, i64 r0,
                 CheckScratch& cs, bool& unite) {
  if (P < 1) return false;
  unite = false;
  if (P == 1 && R == 1 && simple_ring(xy + 2 * ro[0], ro[1] - ro[0], cs)) return true;
  std::vector<i64>& lpo = cs.lpo;
  std::vector<int>& orient = cs.orient;
  std::vector<std::uint8_t>& disc = cs.disc;
  lpo.resize((std::size_t)P + 1);
  for (i64 q = 0; q <= P; ++q) lpo[q] = po[q] - r0;
  orient.resize((std::size_t)R);
  disc.resize((std::size_t)P);
  // several parts: the check of disjoint parts first (the per-polygon checks, then one
  // sweep of them all); only when that fails, the per-polygon checks alone (the parts
  // then overlap or touch along edges: united)
  auto valid = [&](bool disjoint) {
    if (!mk::polygon::check(xy, ro, R, lpo.data(), P, disjoint, orient.data(), disc.data()).ok())
      return false;
    for (i64 q = 0; q < P; ++q)
      if (disc[q]) return false;
    return true;
  };
  if (P > 1 && valid(true)) return true;
  if (!valid(false)) return false;
  unite = P > 1;
  return true;
}

// offset_polygons(xy (N, 2), ring_off (R + 1,), poly_off (P + 1,), geom_off (G + 1,),
//                 distance (G,), tolerance (G,) (NaN: default), default_rel, outer, join,
//                 miter_limit, delta, threads=1) -> as offset_rings (info code INPUT:
//                 not read here)
// Shapely geometries as flat arrays (polygon_arrays: closed rings, shell first, any
// orientation). Each geometry is checked here, with the GIL released: a polygon of one
// ring shown simple by the offset's exact crossing test, anything else by polygon.hpp's
// exact validator; a geometry it refuses (invalid, flat, empty, a hole that splits its
// polygon) gets code INPUT and is left to the caller's reader, which names the problem
// or reads it otherwise. The parts of a multipolygon that overlap or touch are united
// first, as the reader's "parts" validation has the caller do.
nb::tuple offset_polygons(In2<double> XY, In1<i64> RO, In1<i64> PO, In1<i64> GO,
                          In1<double> DS, In1<double> TS, double default_rel, bool outer,
                          int join, double limit, double delta, int threads) {
  const i64 n = (i64)XY.shape(0), nr = (i64)RO.shape(0) - 1, np_ = (i64)PO.shape(0) - 1,
            ng = (i64)GO.shape(0) - 1;
  if (XY.shape(1) != 2) throw nb::value_error("offset: coordinates must have shape (n, 2)");
  const i64 *ro = RO.data(), *po = PO.data(), *go = GO.data();
  check_offsets(ro, nr, n, "offset: bad ring offsets");
  check_offsets(po, np_, nr, "offset: bad polygon offsets", true);
  check_offsets(go, ng, np_, "offset: bad geometry offsets");
  if ((i64)DS.shape(0) != ng || (i64)TS.shape(0) != ng) throw nb::value_error("offset: bad offsets");
  const mk::off::Params base = params(0, NAN, default_rel, outer, join, limit);
  const double *xy = XY.data(), *ds = DS.data(), *ts = TS.data();
  std::vector<mk::off::Result> res((std::size_t)ng);
  {
    nb::gil_scoped_release nogil;
    mk::parallel_chunks(ng, threads, [&](int, i64 g0, i64 g1) {
      with_worker([&](Worker& wk) {
        mk::off::Offsetter& off = wk.off;
        std::vector<mk::ms::Ring>& rings = wk.rings;
        CheckScratch& cs = wk.cs;
        for (i64 g = g0; g < g1; ++g) {
          mk::off::Result& out = res[(std::size_t)g];
          const i64 p0 = go[g], p1 = go[g + 1], P = p1 - p0, r0 = po[p0], R = po[p1] - r0;
          bool unite = false;
          if (!valid_parts(xy, ro + r0, R, po + p0, P, r0, cs, unite)) {
            out = mk::off::Result();
            out.code = mk::off::INPUT;
            continue;
          }
          rings.clear();
          for (i64 q = p0; q < p1; ++q)
            for (i64 r = po[q]; r < po[q + 1]; ++r)
              rings.push_back(mk::ms::make_ring(xy + 2 * ro[r], ro[r + 1] - ro[r], r != po[q]));
          mk::off::Params p = base;
          p.distance = ds[g];
          p.tolerance = ts[g];
          off.run(rings, unite, delta, p, false, out);
        }
      });
    });
  }
  return pack(res, false);
}

// offset_one(xy (n, 2), distance, tolerance (NaN: the default), default_rel, outer, join,
//            miter_limit) -> (xy (M, 2) closed rings, ring_off, poly_off), or None
// One polygon without holes, as shapely.get_coordinates gives it: the offset of
// offset_polygons for one geometry, with the fewest conversions (a single call's Python
// and binding cost more than a small part's offset). Taken only when the coordinates are
// one ring closed at its end and nowhere before (a polygon with holes closes its shell
// earlier), valid (valid_parts) and offset without a code or status; None otherwise:
// the caller's general path reads, offsets and reports it.
nb::object offset_one(In2<double> XY, double distance, double tolerance, double default_rel,
                      bool outer, int join, double limit) {
  const i64 n = (i64)XY.shape(0);
  if (XY.shape(1) != 2 || n < 4) return nb::none();
  const double* xy = XY.data();
  nb::object got = nb::none();
  with_worker([&](Worker& wk) {
    mk::off::Result& out = wk.one;
    bool ok = false;
    {
      nb::gil_scoped_release nogil;
      const double x0 = xy[0], y0 = xy[1];
      bool one = xy[2 * n - 2] == x0 && xy[2 * n - 1] == y0;
      for (i64 i = 1; i + 1 < n && one; ++i) one = !(xy[2 * i] == x0 && xy[2 * i + 1] == y0);
      const i64 ro[2] = {0, n}, po[2] = {0, 1};
      bool unite = false;
      if (one && valid_parts(xy, ro, 1, po, 1, 0, wk.cs, unite)) {
        wk.rings.clear();
        wk.rings.push_back(mk::ms::make_ring(xy, n, false));
        wk.off.run(wk.rings, false, 0.0,
                   params(distance, tolerance, default_rel, outer, join, limit), false, out);
        ok = out.status == mk::OK && out.code == mk::off::FINE;
      }
    }
    if (!ok) return;
    const auto& R = out.rings;
    i64 rows = 0, nr = 0, np_ = 0, row = 0, ring = 0, poly = 0;
    count_closed(R, rows, nr, np_);
    double* oxy = alloc<double>(2 * rows);
    i64* oro = alloc<i64>(nr + 1);
    oro[0] = 0;
    append_closed(R, oxy, oro, nullptr, row, ring, poly);
    got = nb::make_tuple(owned(oxy, (std::size_t)rows, 2), owned(oro, (std::size_t)nr + 1, 0),
                         to_numpy(R.poly_off, R.poly_off.size(), 0));
  });
  return got;
}

}  // namespace

void bind_offset(nb::module_& m) {
  m.def("offset_polygons", &offset_polygons, "xy"_a.noconvert(), "ring_off"_a.noconvert(),
        "poly_off"_a.noconvert(), "geom_off"_a.noconvert(), "distance"_a.noconvert(),
        "tolerance"_a.noconvert(), "default_rel"_a, "outer"_a, "join"_a, "miter_limit"_a, "delta"_a, "threads"_a = 1);
  m.def("offset_one", &offset_one, "xy"_a.noconvert(), "distance"_a, "tolerance"_a,
        "default_rel"_a, "outer"_a, "join"_a, "miter_limit"_a);
  m.def("offset_rings", &offset_rings, "xy"_a.noconvert(), "ring_off"_a.noconvert(),
        "ring_hole"_a.noconvert(), "geom_off"_a.noconvert(), "unite"_a.noconvert(),
        "delta"_a.noconvert(), "distance"_a, "tolerance"_a, "default_rel"_a, "outer"_a,
        "join"_a, "miter_limit"_a, "labels"_a = false, "threads"_a = 1, "resolve"_a = true);
  m.attr("OFFSET_ROUND") = (int)mk::off::ROUND;
  m.attr("OFFSET_MITER") = (int)mk::off::MITER;
  m.attr("OFFSET_SQUARE") = (int)mk::off::SQUARE;
  nb::dict joins;  // the public names of the joins
  joins["round"] = (int)mk::off::ROUND;
  joins["miter"] = (int)mk::off::MITER;
  joins["square"] = (int)mk::off::SQUARE;
  m.attr("OFFSET_JOINS") = joins;
  m.attr("OFFSET_FINE") = (int)mk::off::FINE;
  m.attr("OFFSET_TOLERANCE") = (int)mk::off::TOLERANCE;
  m.attr("OFFSET_DISTANCE") = (int)mk::off::DISTANCE;
  m.attr("OFFSET_UNDERFLOW") = (int)mk::off::UNDERFLOW;
  m.attr("OFFSET_UNCERTIFIED") = (int)mk::off::UNCERTIFIED;
  m.attr("OFFSET_OVERFLOWS") = (int)mk::off::OVERFLOWS;
  m.attr("OFFSET_INPUT") = (int)mk::off::INPUT;
  m.attr("OFFSET_DETOUR") = (long long)mk::off::DETOUR;
  m.attr("OFFSET_DIRECT") = (int)mk::off::DIRECT;
  m.attr("OFFSET_RESOLVED") = (int)mk::off::RESOLVED;
  m.attr("OFFSET_OVERLAID") = (int)mk::off::OVERLAID;
}

}  // namespace mk_bind
