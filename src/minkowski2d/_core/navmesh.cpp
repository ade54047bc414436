// navmesh.cpp -- bindings of the navigation-mesh planner (navmesh.hpp) into
// minkowski2d._core._ext as MeshPlannerF (float64 coordinates; an int scene with
// |x| <= 2^53 is passed as its exact doubles). minkowski2d.planning validates the input,
// builds the pieces and chooses between this and the visibility graph (PlannerI/F).
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/tuple.h>

#include <vector>

#include "bind.hpp"
#include "navmesh.hpp"

namespace nb = nanobind;
using namespace nb::literals;
using mk::i64;

namespace mk_bind {

namespace {

using MP = mk::MeshPlanner;

void bind_mesh_planner(nb::module_& m) {
  nb::class_<MP>(m, "MeshPlannerF")
      .def(nb::init<>())
      // coords (V, 2) of the solid pieces, offsets (P + 1,), groups (P,), box (4,) or
      // empty, the box to mesh (4,): the status (MESH_OK, MESH_INEXACT, ...)
      .def(
          "build",
          [](MP& self, In2<double> coords, In1<i64> off, In1<i64> grp, In1<double> box,
             bool open_box, In1<double> meshbox) {
            mk::set_scene(self.base, coords.data(), coords.shape(0), off.data(), off.shape(0),
                          grp.data(), grp.shape(0), box.data(), box.shape(0), open_box);
            if (meshbox.shape(0) != 4) throw nb::value_error("meshbox: 4 numbers");
            nb::gil_scoped_release nogil;
            return self.build(meshbox.data());
          },
          "coords"_a.noconvert(), "offsets"_a.noconvert(), "groups"_a.noconvert(),
          "box"_a.noconvert(), "open_box"_a, "meshbox"_a.noconvert())
      // (status, group, path (k, 2)); status: a PlanStatus (PLAN_OK, ..., PLAN_OUTSIDE_MESH)
      .def("query",
           [](const MP& self, double sx, double sy, double gx, double gy) {
             std::vector<double> out;
             int grp = -1, st;
             {
               nb::gil_scoped_release nogil;
               st = mk::query_one(self, sx, sy, gx, gy, out, grp);
             }
             return nb::make_tuple(st, grp, to_numpy(out, out.size() / 2, 2));
           })
      .def("query_many",
           [](const MP& self, In2<double> S0, In2<double> G0) {
             mk::PlanAnswers<double> A;
             {
               nb::gil_scoped_release nogil;
               mk::query_many(self, S0.data(), G0.data(), S0.shape(0), A);
             }
             return answers_tuple(A);
           })
      .def("locate",
           [](const MP& self, In2<double> pts) {
             std::vector<int> res(pts.shape(0));
             {
               nb::gil_scoped_release nogil;
               mk::locate_points(self.base, pts.data(), pts.shape(0), res.data());
             }
             return to_numpy(res, res.size(), 0);
           })
      .def("segment_free",
           [](const MP& self, double px, double py, double qx, double qy) {
             return mk::segment_free(self.base, px, py, qx, qy);
           })
      // (vertices (n, 2), polygon offsets (P + 1,), polygon vertex ids, flags (n,))
      .def("mesh",
           [](const MP& self) {
             std::vector<double> xy;
             std::vector<i64> off, pv, fl;
             mk::mesh_arrays(self.M, xy, off, pv, fl);
             return nb::make_tuple(to_numpy(xy, xy.size() / 2, 2), to_numpy(off, off.size(), 0),
                                   to_numpy(pv, pv.size(), 0), to_numpy(fl, fl.size(), 0));
           })
      // the zero-width segments (k, 4): (ax, ay, bx, by) each
      .def("zero_width",
           [](const MP& self) {
             std::vector<double> seg;
             mk::network_segments(self, seg);
             return to_numpy(seg, seg.size() / 4, 4);
           })
      // (nodes expanded, nodes pushed) by the last query
      .def("counters",
           [](const MP& self) { return nb::make_tuple(self.n_expanded, self.n_pushed); })
      .def_rw("prune", &MP::prune)  // the bridge pruning (on; tests turn it off)
      // the landmark bounds (used by the queries; tests turn them off), the pruning of
      // dominated intervals likewise, the tables made again (n landmarks, where the
      // probes' median detour reaches min_detour and the tables cut their nodes; -1:
      // always) and the tables: (landmark ids (K,), the search vertices (n, 2), their
      // distances to the landmarks (n, K); +inf: not reached; none: an empty array)
      .def_rw("use_landmarks", &MP::use_landmarks)
      .def_rw("use_dominance", &MP::use_dominance)
      .def("make_landmarks",
           [](MP& self, int n, double min_detour) {
             self.n_landmarks = n;
             self.min_detour = min_detour;
             nb::gil_scoped_release nogil;
             self.build_landmarks();
           })
      .def("landmarks",
           [](const MP& self) {
             const std::size_t n = (std::size_t)self.lm.n, K = (std::size_t)self.lm.K;
             std::vector<i64> at(self.lm.at.begin(), self.lm.at.end());
             std::vector<double> xy(2 * n), d = self.lm.d;
             for (std::size_t v = 0; v < n; ++v) {
               xy[2 * v] = self.idx((int)v);
               xy[2 * v + 1] = self.idy((int)v);
             }
             return nb::make_tuple(to_numpy(at, at.size(), 0), to_numpy(xy, n, 2),
                                   to_numpy(d, K ? n : 0, K));
           })
      .def_ro("status", &MP::status);
  m.attr("MESH_OK") = (int)mk::MESH_OK;
  m.attr("MESH_INEXACT") = (int)mk::MESH_INEXACT;
  m.attr("MESH_FAILED") = (int)mk::MESH_FAILED;
}

}  // namespace

void bind_navmesh(nb::module_& m) { bind_mesh_planner(m); }

}  // namespace mk_bind
