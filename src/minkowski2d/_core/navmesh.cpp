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
            auto& B = self.base;
            B.open_box = open_box;
            const double* c = coords.data();
            B.pc.assign(c, c + 2 * coords.shape(0));
            B.poff.assign(off.data(), off.data() + off.shape(0));
            B.pgrp.resize(grp.shape(0));
            for (std::size_t i = 0; i < grp.shape(0); ++i) B.pgrp[i] = (int)grp.data()[i];
            B.has_box = box.shape(0) == 4;
            if (B.has_box) {
              B.bx0 = box.data()[0];
              B.by0 = box.data()[1];
              B.bx1 = box.data()[2];
              B.by1 = box.data()[3];
            }
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
               mk::PlanScratch S;
               S.init((std::size_t)self.base.items());
               // kept per thread between calls (query() sizes it to the mesh; every
               // query leaves it cleared)
               thread_local mk::MeshScratch MS;
               st = self.query(sx, sy, gx, gy, out, grp, S, MS);
             }
             return nb::make_tuple(st, grp, to_numpy(out, out.size() / 2, 2));
           })
      .def("query_many",
           [](const MP& self, In2<double> S0, In2<double> G0) {
             std::size_t n = S0.shape(0);
             std::vector<int> st(n), gr(n);
             std::vector<double> pts;
             std::vector<i64> off(n + 1, 0);
             {
               nb::gil_scoped_release nogil;
               mk::PlanScratch S;
               S.init((std::size_t)self.base.items());
               mk::MeshScratch MS;
               MS.init(self.nids(), self.M.npoly());
               std::vector<double> out;
               const double* s = S0.data();
               const double* g = G0.data();
               for (std::size_t i = 0; i < n; ++i) {
                 st[i] = self.query(s[2 * i], s[2 * i + 1], g[2 * i], g[2 * i + 1], out, gr[i], S,
                                    MS);
                 pts.insert(pts.end(), out.begin(), out.end());
                 off[i + 1] = (i64)pts.size() / 2;
               }
             }
             return nb::make_tuple(to_numpy(st, n, 0), to_numpy(gr, n, 0),
                                   to_numpy(pts, pts.size() / 2, 2), to_numpy(off, n + 1, 0));
           })
      .def("locate",
           [](const MP& self, In2<double> pts) {
             std::size_t n = pts.shape(0);
             std::vector<int> res(n);
             {
               nb::gil_scoped_release nogil;
               mk::PlanScratch S;
               S.init((std::size_t)self.base.items());
               const double* p = pts.data();
               for (std::size_t i = 0; i < n; ++i) {
                 double x = p[2 * i], y = p[2 * i + 1];
                 res[i] = !self.base.in_box(x, y) ? -2 : self.base.interior_group(x, y, S);
               }
             }
             return to_numpy(res, n, 0);
           })
      .def("segment_free",
           [](const MP& self, double px, double py, double qx, double qy) {
             mk::PlanScratch S;
             S.init((std::size_t)self.base.items());
             return !self.base.blocked(px, py, qx, qy, S);
           })
      // (vertices (n, 2), polygon offsets (P + 1,), polygon vertex ids, flags (n,))
      .def("mesh",
           [](const MP& self) {
             const auto& M = self.M;
             std::vector<double> xy(2 * M.vx.size());
             for (std::size_t i = 0; i < M.vx.size(); ++i) {
               xy[2 * i] = M.vx[i];
               xy[2 * i + 1] = M.vy[i];
             }
             std::vector<i64> off(M.poff.begin(), M.poff.end()), pv(M.pv.begin(), M.pv.end());
             std::vector<i64> fl(M.vflag.begin(), M.vflag.end());
             return nb::make_tuple(to_numpy(xy, M.vx.size(), 2), to_numpy(off, off.size(), 0),
                                   to_numpy(pv, pv.size(), 0), to_numpy(fl, fl.size(), 0));
           })
      // the zero-width segments (k, 4): (ax, ay, bx, by) each
      .def("zero_width",
           [](const MP& self) {
             std::vector<double> seg;
             for (std::size_t k = 0; k < self.net.ea.size(); ++k)
               seg.insert(seg.end(), {self.idx(self.net.ea[k]), self.idy(self.net.ea[k]),
                                      self.idx(self.net.eb[k]), self.idy(self.net.eb[k])});
             return to_numpy(seg, seg.size() / 4, 4);
           })
      // (nodes expanded, nodes pushed) by the last query
      .def("counters",
           [](const MP& self) { return nb::make_tuple(self.n_expanded, self.n_pushed); })
      .def_rw("prune", &MP::prune)  // the bridge pruning (on; tests turn it off)
      .def_ro("status", &MP::status);
  m.attr("MESH_OK") = (int)mk::MESH_OK;
  m.attr("MESH_INEXACT") = (int)mk::MESH_INEXACT;
  m.attr("MESH_FAILED") = (int)mk::MESH_FAILED;
}

}  // namespace

void bind_navmesh(nb::module_& m) { bind_mesh_planner(m); }

}  // namespace mk_bind
