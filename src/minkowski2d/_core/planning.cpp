// planning.cpp -- bindings of the exact motion planner (planning.hpp) into
// minkowski2d._core._ext as PlannerI (int64, |x| < 2^62) and PlannerF (float64).
// minkowski2d.planning validates the input and builds the pieces; these classes trust
// their arrays.
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/tuple.h>

#include <cstring>
#include <vector>

#include "bind.hpp"
#include "planning.hpp"

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
            self.open_box = open_box;
            const T* c = coords.data();
            self.pc.assign(c, c + 2 * coords.shape(0));
            self.poff.assign(off.data(), off.data() + off.shape(0));
            self.pgrp.resize(grp.shape(0));
            for (std::size_t i = 0; i < grp.shape(0); ++i) self.pgrp[i] = (int)grp.data()[i];
            self.has_box = box.shape(0) == 4;
            if (self.has_box) {
              self.bx0 = box.data()[0];
              self.by0 = box.data()[1];
              self.bx1 = box.data()[2];
              self.by1 = box.data()[3];
            }
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
               mk::PlanScratch S;
               S.init((std::size_t)self.items());
               st = self.query(sx, sy, gx, gy, out, grp, S);
             }
             return nb::make_tuple(st, grp, to_numpy(out, out.size() / 2, 2));
           })
      // many queries: (status (n,), group (n,), points (M, 2), offsets (n + 1,))
      .def("query_many",
           [](const PL& self, In2<T> S0, In2<T> G0) {
             std::size_t n = S0.shape(0);
             std::vector<int> st(n), gr(n);
             std::vector<T> pts;
             std::vector<i64> off(n + 1, 0);
             {
               nb::gil_scoped_release nogil;
               mk::PlanScratch S;
               S.init((std::size_t)self.items());
               std::vector<T> out;
               const T* s = S0.data();
               const T* g = G0.data();
               for (std::size_t i = 0; i < n; ++i) {
                 st[i] = self.query(s[2 * i], s[2 * i + 1], g[2 * i], g[2 * i + 1], out, gr[i], S);
                 pts.insert(pts.end(), out.begin(), out.end());
                 off[i + 1] = (i64)pts.size() / 2;
               }
             }
             return nb::make_tuple(to_numpy(st, n, 0), to_numpy(gr, n, 0),
                                   to_numpy(pts, pts.size() / 2, 2), to_numpy(off, n + 1, 0));
           })
      // per point: -2 outside the box, g >= 0 inside group g's C-obstacle, -1 free
      .def("locate",
           [](const PL& self, In2<T> pts) {
             std::size_t n = pts.shape(0);
             std::vector<int> res(n);
             {
               nb::gil_scoped_release nogil;
               mk::PlanScratch S;
               S.init((std::size_t)self.items());
               const T* p = pts.data();
               for (std::size_t i = 0; i < n; ++i) {
                 T x = p[2 * i], y = p[2 * i + 1];
                 res[i] = !self.in_box(x, y) ? -2 : self.interior_group(x, y, S);
               }
             }
             return to_numpy(res, n, 0);
           })
      // is the closed segment free (no point in a C-obstacle's open interior)?
      .def("segment_free",
           [](const PL& self, T px, T py, T qx, T qy) {
             mk::PlanScratch S;
             S.init((std::size_t)self.items());
             return !self.blocked(px, py, qx, qy, S);
           })
      .def("candidates",
                   [](const PL& self) { return to_numpy(self.cv, self.cv.size() / 2, 2); })
      .def("adjacency",
                   [](const PL& self) {
                     return nb::make_tuple(to_numpy(self.aoff, self.aoff.size(), 0),
                                           to_numpy(self.adj, self.adj.size(), 0),
                                           to_numpy(self.aw, self.aw.size(), 0));
                   })
      .def("components",
                   [](const PL& self) { return to_numpy(self.comp, self.comp.size(), 0); })
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
