// polygon.cpp -- bindings of the exact polygon checks (polygon.hpp) and the triangulation
// (triangulate.hpp) into minkowski2d._core._ext:
//
//   check_polygons_f(coords (N, 2) float64, ring_offsets (R + 1,) int64,
//                    polygon_offsets (P + 1,) int64, disjoint: bool)
//       -> (status, reason, ring, vertex, orientation (R,) int8, disconnected (P,) bool)
//   triangulate_polygons_f(coords, ring_offsets, polygon_offsets, delaunay=True)
//       -> (status, reason, ring, vertex, triangles (T, 3) int64)
//   incircle_f / incircle_exact_f(ax, ay, bx, by, cx, cy, dx, dy) -> sign (exact.hpp)
//   polygons_wkb_f(wkbs: list of bytes) -> (coords (N, 2), ring_offsets, polygon_offsets,
//                  geometry_offsets (T + 1,)): 2-D WKB of polygonal geometries
//                  (shapely.to_wkb(..., output_dimension=2)) as flat arrays
//
// status is a Status (OK, NONFINITE, INVALID_POLYGON), reason an Invalid code, ring the
// global ring index and vertex the index inside that ring (the caller's numbering, the
// first vertex of the offending edge). The offsets are checked here (malformed ones are a
// ValueError: they come from minkowski2d._engine.polygon, not from users); the kernels run with
// the GIL released.
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/tuple.h>

#include <cstdint>
#include <cstring>
#include <string>
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

// A reader of 2-D WKB (either byte order; ISO or extended type codes without Z/M/SRID):
// Polygon (3), MultiPolygon (6) and GeometryCollection (7) of them, recursively; empty
// polygons are dropped. Rings are kept as written (closed, orientation as given).
class WkbReader {
 public:
  std::vector<double> xy;
  std::vector<i64> ro{0}, po{0};
  void geometry(const std::uint8_t* p, std::size_t n) {
    p_ = p;
    end_ = p + n;
    read_geometry(0);
    if (p_ != end_) fail("trailing bytes");
  }

 private:
  const std::uint8_t* p_ = nullptr;
  const std::uint8_t* end_ = nullptr;
  bool little_ = true;
  [[noreturn]] static void fail(const char* what) {
    throw nb::value_error((std::string("polygons_wkb: malformed WKB: ") + what).c_str());
  }
  void need(std::size_t k) {
    if ((std::size_t)(end_ - p_) < k) fail("truncated");
  }
  std::uint32_t u32() {
    need(4);
    std::uint32_t v;
    std::memcpy(&v, p_, 4);
    if (!little_) v = __builtin_bswap32(v);
    p_ += 4;
    return v;
  }
  void points(std::uint32_t m) {
    need((std::size_t)m * 16);
    const std::size_t at = xy.size();
    xy.resize(at + 2 * (std::size_t)m);
    std::memcpy(xy.data() + at, p_, (std::size_t)m * 16);
    if (!little_)
      for (std::size_t i = at; i < xy.size(); ++i) {
        std::uint64_t b;
        std::memcpy(&b, &xy[i], 8);
        b = __builtin_bswap64(b);
        std::memcpy(&xy[i], &b, 8);
      }
    p_ += (std::size_t)m * 16;
  }
  void read_geometry(int depth) {
    if (depth > 32) fail("nested too deep");
    need(1);
    little_ = *p_++ == 1;
    const std::uint32_t type = u32();
    if (type == 3) {
      const std::uint32_t nr = u32();
      for (std::uint32_t r = 0; r < nr; ++r) {
        points(u32());
        ro.push_back((i64)xy.size() / 2);
      }
      if (nr > 0) po.push_back((i64)ro.size() - 1);
    } else if (type == 6 || type == 7) {
      const std::uint32_t k = u32();
      for (std::uint32_t i = 0; i < k; ++i) read_geometry(depth + 1);
    } else {
      fail("not a 2-D polygonal geometry");
    }
  }
};

nb::tuple polygons_wkb(nb::list wkbs) {
  WkbReader rd;
  std::vector<i64> to{0};
  to.reserve(wkbs.size() + 1);
  for (nb::handle h : wkbs) {
    nb::bytes b = nb::cast<nb::bytes>(h);
    rd.geometry((const std::uint8_t*)b.c_str(), b.size());
    to.push_back((i64)rd.po.size() - 1);
  }
  const std::size_t n = rd.xy.size() / 2;
  return nb::make_tuple(to_numpy(rd.xy, n, 2), to_numpy(rd.ro, rd.ro.size(), 0),
                        to_numpy(rd.po, rd.po.size(), 0), to_numpy(to, to.size(), 0));
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
  m.def("polygons_wkb_f", &polygons_wkb, "wkbs"_a);
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
