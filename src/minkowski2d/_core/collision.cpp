// collision.cpp -- bindings of collision.hpp: intersects / distance / penetration walks,
// exact GJK, contains, the batch over pairs (with threads). Outputs are numpy arrays the
// caller preallocates; every kernel runs with the GIL released.
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/tuple.h>

#include <cstdint>
#include <vector>

#include "bind.hpp"
#include "collision.hpp"

namespace nb = nanobind;
using namespace nb::literals;
using mk::i64;

namespace mk_bind {

namespace {

void need(bool ok, const char* what) {
  if (!ok) throw nb::value_error(what);
}

// prep(p, off, is_int, mode, idx, kk, ss, inv, threads) -> (code, polygon, vertex)
nb::tuple prep_b(In2<double> p, In1<i64> off, bool is_int, int mode, Mut1<i64> idx,
                 Mut1<i64> kk, Mut1<i64> ss, Mut1<double> inv, int threads) {
  need(p.shape(1) == 2, "prep: p must have shape (n, 2)");
  i64 P = (i64)off.shape(0) - 1;
  i64 n = (i64)p.shape(0);
  need(P >= 0 && (i64)kk.shape(0) >= P && (i64)ss.shape(0) >= P, "prep: bad sizes");
  need((i64)idx.shape(0) >= n, "prep: idx too short");
  need(mode != mk::coll::PENETRATION || (i64)inv.shape(0) >= n, "prep: inv too short");
  const i64* o = off.data();
  for (i64 q = 0; q < P; ++q) need(o[q] >= 0 && o[q] <= o[q + 1] && o[q + 1] <= n, "prep: bad offsets");
  mk::coll::PrepResult r;
  {
    nb::gil_scoped_release nogil;
    r = mk::coll::prep(p.data(), n, o, P, is_int, mode, idx.data(), kk.data(), ss.data(),
                       inv.data(), threads < 1 ? 1 : threads);
  }
  return nb::make_tuple(r.code, r.q, r.v);
}

// pairs(pa, offa, ida, ka, sa, inva, pb, offb, idb, kb, sb, invb, qa, qb, mode, hit, res,
//       threads) -> first pair where GJK hit its cap, or -1
i64 pairs_b(In2<double> pa, In1<i64> offa, In1<i64> ida, In1<i64> ka, In1<i64> sa,
            In1<double> inva, In2<double> pb, In1<i64> offb, In1<i64> idb, In1<i64> kb,
            In1<i64> sb, In1<double> invb, In1<i64> qa, In1<i64> qb, int mode,
            Mut1<std::int8_t> hit, Mut2<double> res, int threads) {
  i64 P = (i64)qa.shape(0);
  need((i64)qb.shape(0) == P && (i64)hit.shape(0) >= P, "pairs: bad sizes");
  bool rows = mode == mk::coll::DISTANCE || mode == mk::coll::PENETRATION;
  need(!rows || ((i64)res.shape(0) >= P && res.shape(1) == mk::coll::NCOL), "pairs: bad res");
  i64 NA = (i64)ka.shape(0), NB = (i64)kb.shape(0);
  const i64* qa_ = qa.data();
  const i64* qb_ = qb.data();
  for (i64 q = 0; q < P; ++q)
    need(qa_[q] >= 0 && qa_[q] < NA && qb_[q] >= 0 && qb_[q] < NB, "pairs: bad pair index");
  mk::coll::Side A{pa.data(), offa.data(), ida.data(), ka.data(), sa.data(), inva.data()};
  mk::coll::Side B{pb.data(), offb.data(), idb.data(), kb.data(), sb.data(), invb.data()};
  i64 r;
  {
    nb::gil_scoped_release nogil;
    r = mk::coll::pairs(A, B, qa_, qb_, P, mode, hit.data(), res.data(), threads < 1 ? 1 : threads);
  }
  return r;
}

// single(pa, pb, mode, int_a, int_b, res (1, 7)) -> (code, which, vertex, hit): code 0 on
// success, else a Status (RANGE: values the kernels cannot compute exactly) for operand
// `which` (0 = a, 1 = b) at `vertex`; GJK's cap gives code INTERNAL.
nb::tuple single_b(In2<double> pa, In2<double> pb, int mode, bool int_a, bool int_b,
                   Mut2<double> res) {
  need(pa.shape(1) == 2 && pb.shape(1) == 2, "single: shape (n, 2) expected");
  need(res.shape(0) >= 1 && res.shape(1) == mk::coll::NCOL, "single: res must be (1, 7)");
  mk::coll::SingleResult r;
  {
    nb::gil_scoped_release nogil;
    r = mk::coll::single(pa.data(), (i64)pa.shape(0), pb.data(), (i64)pb.shape(0), mode, int_a,
                         int_b, res.data());
  }
  return nb::make_tuple(r.code, r.which, r.vertex, r.hit);
}

// contains_single(p, int_p, pts, int_pts, out) -> (code, which, vertex): which 0 = poly,
// 1 = points.
nb::tuple contains_single_b(In2<double> p, bool int_p, In2<double> pts, bool int_pts,
                            Mut1<bool> out) {
  need(p.shape(1) == 2 && pts.shape(1) == 2, "contains: shape (n, 2) expected");
  need(out.shape(0) >= pts.shape(0), "contains: out too short");
  mk::coll::SingleResult r;
  {
    nb::gil_scoped_release nogil;
    r = mk::coll::contains_single(p.data(), (i64)p.shape(0), int_p, pts.data(),
                                  (i64)pts.shape(0), int_pts, out.data());
  }
  return nb::make_tuple(r.code, r.which, r.vertex);
}

}  // namespace

void bind_collision(nb::module_& m) {
  m.attr("COLL_INTERSECTS") = (int)mk::coll::INTERSECTS;
  m.attr("COLL_DISTANCE") = (int)mk::coll::DISTANCE;
  m.attr("COLL_PENETRATION") = (int)mk::coll::PENETRATION;
  m.attr("COLL_GJK") = (int)mk::coll::GJK;
  m.attr("COLL_AUTO") = (int)mk::coll::AUTO;
  m.attr("COLL_AUTO_SUM_MAX") = (long long)mk::coll::AUTO_SUM_MAX;
  m.def("coll_prep", &prep_b, "p"_a.noconvert(), "off"_a.noconvert(), "is_int"_a, "mode"_a,
        "idx"_a.noconvert(), "kk"_a.noconvert(), "ss"_a.noconvert(), "inv"_a.noconvert(),
        "threads"_a = 1, "Normalize every polygon of a ragged float64 array for the collision kernels.");
  m.def("coll_pairs", &pairs_b, "pa"_a.noconvert(), "offa"_a.noconvert(), "ida"_a.noconvert(),
        "ka"_a.noconvert(), "sa"_a.noconvert(), "inva"_a.noconvert(), "pb"_a.noconvert(),
        "offb"_a.noconvert(), "idb"_a.noconvert(), "kb"_a.noconvert(), "sb"_a.noconvert(),
        "invb"_a.noconvert(), "qa"_a.noconvert(), "qb"_a.noconvert(), "mode"_a,
        "hit"_a.noconvert(), "res"_a.noconvert(), "threads"_a = 1,
        "Run a collision mode on every pair of two prepared ragged arrays.");
  m.def("coll_single", &single_b, "pa"_a.noconvert(), "pb"_a.noconvert(), "mode"_a, "int_a"_a,
        "int_b"_a, "res"_a.noconvert(), "One pair: prepare both, then run the mode.");
  m.def("coll_contains", &contains_single_b, "p"_a.noconvert(), "int_p"_a, "pts"_a.noconvert(),
        "int_pts"_a, "out"_a.noconvert(), "Point location in one convex polygon.");
}

}  // namespace mk_bind
