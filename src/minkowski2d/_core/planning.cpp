// planning.cpp -- bindings of the exact motion planner (planning.hpp) into
// minkowski2d._core._ext as PlannerI (int64, |x| < 2^62) and PlannerF (float64).
// minkowski2d.planning validates the input and builds the pieces; these classes trust
// their arrays.
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/tuple.h>

#include <vector>

#include "bind.hpp"
#include "planning.hpp"
#include "planning_queries.hpp"

namespace nb = nanobind;
using namespace nb::literals;
using mk::i64;

namespace mk_bind {

namespace {

template <class T>
void bind_planner(nb::module_& m, const char* name) {
  using PL = mk::Planner<T>;
  nb::class_<PL>(m, name)
      .def(nb::init<>())
      // coords (V, 2) of the solid pieces, offsets (P + 1,), groups (P,), box (4,) or empty
      .def(
          "build",
          [](PL& self, In2<T> coords, In1<i64> off, In1<i64> grp, In1<T> box, int threads,
             bool open_box) {
            self.threads = threads;
            mk::set_scene(self, coords.data(), coords.shape(0), off.data(), off.shape(0),
                          grp.data(), grp.shape(0), box.data(), box.shape(0), open_box);
            nb::gil_scoped_release nogil;
            self.build();
          },
          "coords"_a.noconvert(), "offsets"_a.noconvert(), "groups"_a.noconvert(),
          "box"_a.noconvert(), "threads"_a = 1, "open_box"_a = false)
      // (status, group, path (k, 2)); status: a PlanStatus (PLAN_OK, ...)
      .def("query",
           [](const PL& self, T sx, T sy, T gx, T gy) {
             std::vector<T> out;
             int grp = -1, st;
             {
               nb::gil_scoped_release nogil;
               st = mk::query_one(self, sx, sy, gx, gy, out, grp);
             }
             return nb::make_tuple(st, grp, to_numpy(out, out.size() / 2, 2));
           })
      // many queries: (status (n,), group (n,), points (M, 2), offsets (n + 1,))
      .def("query_many",
           [](const PL& self, In2<T> S0, In2<T> G0) {
             mk::PlanAnswers<T> A;
             {
               nb::gil_scoped_release nogil;
               mk::query_many(self, S0.data(), G0.data(), S0.shape(0), A);
             }
             return answers_tuple(A);
           })
      // per point: -2 outside the box, g >= 0 inside group g's C-obstacle, -1 free
      .def("locate",
           [](const PL& self, In2<T> pts) {
             std::vector<int> res(pts.shape(0));
             {
               nb::gil_scoped_release nogil;
               mk::locate_points(self, pts.data(), pts.shape(0), res.data());
             }
             return to_numpy(res, res.size(), 0);
           })
      // is the closed segment free (no point in a C-obstacle's open interior)?
      .def("segment_free",
           [](const PL& self, T px, T py, T qx, T qy) {
             return mk::segment_free(self, px, py, qx, qy);
           })
      .def("candidates", [](const PL& self) { return to_numpy(self.cv, self.cv.size() / 2, 2); })
      .def("adjacency",
           [](const PL& self) {
             return nb::make_tuple(to_numpy(self.aoff, self.aoff.size(), 0),
                                   to_numpy(self.adj, self.adj.size(), 0),
                                   to_numpy(self.aw, self.aw.size(), 0));
           })
      .def("components", [](const PL& self) { return to_numpy(self.comp, self.comp.size(), 0); })
      .def("seams", [](const PL& self) {
        return nb::make_tuple(to_numpy(self.sm, self.sm.size() / 4, 4),
                              to_numpy(self.sgrp, self.sgrp.size(), 0));
      });
}

}  // namespace

void bind_planning(nb::module_& m) {
  bind_planner<i64>(m, "PlannerI");
  bind_planner<double>(m, "PlannerF");
  m.attr("PLAN_OK") = (int)mk::PLAN_OK;
  m.attr("PLAN_START_BAD") = (int)mk::PLAN_START_BAD;
  m.attr("PLAN_GOAL_BAD") = (int)mk::PLAN_GOAL_BAD;
  m.attr("PLAN_NO_PATH") = (int)mk::PLAN_NO_PATH;
  m.attr("PLAN_OUTSIDE_MESH") = (int)mk::PLAN_OUTSIDE_MESH;
}

}  // namespace mk_bind
