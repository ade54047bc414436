// module.cpp -- the nanobind module minkowski2d._core._ext: thin bindings over the
// header-only kernels (exact.hpp, convex.hpp, collision.hpp). Validation of shapes and
// kinds happens in minkowski2d._engine.dispatch; these functions trust contiguous (n, 2) arrays
// of int64 (|x| < 2^62) or float64 and report problems as Status codes.
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/tuple.h>

#include <Python.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <type_traits>
#include <vector>

#include "bind.hpp"
#include "exact.hpp"
#include "pyread.hpp"
#include "sum_ops.hpp"

namespace nb = nanobind;
using namespace nb::literals;
using mk::i64;

namespace mk_bind {

// ------------------------------------------------------------------ convex, one pair

// Sum into `out` (numpy-allocated by the caller, (na + nb, 2)): (k, code, which, vertex).
template <class T>
nb::tuple sum_arrays(In2<T> A, In2<T> B, Mut2<T> O) {
  mk::SumResult r;
  {
    nb::gil_scoped_release nogil;
    r = mk::sum_pair(A.data(), (i64)A.shape(0), B.data(), (i64)B.shape(0), O.data());
  }
  return nb::make_tuple(r.k, r.code, r.which, r.vertex);
}

// Normalize one polygon: (indices (k,), split, code, vertex).
template <class T>
nb::tuple normalize_array(In2<T> P) {
  i64 n = (i64)P.shape(0);
  i64* idx = alloc<i64>((std::size_t)n);
  mk::Norm r;
  {
    nb::gil_scoped_release nogil;
    r = mk::normalize_rotated(P.data(), n, idx);
  }
  if (r.code) r.k = 0;
  return nb::make_tuple(owned(idx, (std::size_t)r.k, 0), r.split, (int)r.code, r.vertex);
}

// Convex hull indices (CCW from the lowest-x point, collinear points dropped).
template <class T>
Out<i64> hull_array(In2<T> P) {
  i64 n = (i64)P.shape(0);
  i64* h = alloc<i64>(2 * (std::size_t)n + 1);
  i64 k;
  {
    nb::gil_scoped_release nogil;
    k = mk::hull_indices(P.data(), n, h);
  }
  return owned(h, (std::size_t)k, 0);
}

// ------------------------------------------------------------------ the merge, recorded

// (sum (k,2), steps (s,4) int64 [source, i, j, cross], idx_a, split_a, idx_b, split_b,
//  code, which, vertex) -- the animation's trace of the same merge.
template <class T>
nb::tuple merge_record(In2<T> A, In2<T> B) {
  i64 na = (i64)A.shape(0), nb_ = (i64)B.shape(0);
  T* out = alloc<T>(2 * (std::size_t)(na + nb_));
  i64* ia = alloc<i64>((std::size_t)na);
  i64* ib = alloc<i64>((std::size_t)nb_);
  mk::Norm a, b;
  std::vector<i64> rec;
  mk::SumResult r = mk::merge_recorded(A.data(), na, B.data(), nb_, out, ia, ib, a, b, rec);
  i64* steps = alloc<i64>(rec.size());
  if (!rec.empty()) std::memcpy(steps, rec.data(), sizeof(i64) * rec.size());
  i64 ka = r.code ? 0 : a.k, kb = r.code ? 0 : b.k;
  return nb::make_tuple(owned(out, (std::size_t)r.k, 2), owned(steps, rec.size() / 4, 4),
                        owned(ia, (std::size_t)ka, 0), a.split, owned(ib, (std::size_t)kb, 0),
                        b.split, r.code, r.which, r.vertex);
}

// ------------------------------------------------------------------ batch

// Pair q sums A[a_lo[q]:a_hi[q]] and B[b_lo[q]:b_hi[q]] (mk::sum_batch). Returns (coords
// (K, 2), offsets (P + 1,), code, pair, which, vertex); on failure the lowest failing
// pair is reported, whatever the number of threads.
template <class T>
nb::tuple sum_batch(In2<T> A, In1<i64> a_lo, In1<i64> a_hi, In2<T> B, In1<i64> b_lo,
                    In1<i64> b_hi, int threads) {
  const i64 P = (i64)a_lo.shape(0);
  i64* off = alloc<i64>((std::size_t)P + 1);
  T* coords;
  mk::SumResult r;
  i64 pair = 0, total = 0;
  {
    nb::gil_scoped_release nogil;
    coords = mk::sum_batch(A.data(), a_lo.data(), a_hi.data(), B.data(), b_lo.data(),
                           b_hi.data(), P, threads, off, total, r, pair,
                           [](std::size_t n) { return alloc<T>(n); });
  }
  return nb::make_tuple(owned(coords, (std::size_t)total, 2), owned(off, (std::size_t)P + 1, 0),
                        r.code, pair, r.which, r.vertex);
}

// ------------------------------------------------------------------ Python sequences

// The tiny path: two Python sequences of pairs straight into the core. Returns
// (result ndarray or None, code, which, vertex, kind); code UNHANDLED sends the caller to
// the general path (which validates and raises the specific error).
nb::tuple sum_lists(nb::handle a, nb::handle b) {
  thread_local std::vector<i64> ia_, ib_;
  thread_local std::vector<double> da, db;
  mk::ReadResult ra = mk::read_pairs(a.ptr(), ia_, da);
  if (ra.status != mk::OK)
    return nb::make_tuple(nb::none(), (int)ra.status, 0, ra.bad, ra.kind);
  mk::ReadResult rb = mk::read_pairs(b.ptr(), ib_, db);
  if (rb.status != mk::OK)
    return nb::make_tuple(nb::none(), (int)rb.status, 1, rb.bad, rb.kind);
  i64 na = (i64)ia_.size() / 2, nb_ = (i64)ib_.size() / 2;
  int kind = ra.kind | rb.kind;
  if (kind == 1 && ra.kind != rb.kind) {
    // one side all ints: |x| <= 2^53 there (read_pairs checked mixing inside one side;
    // across sides check here), so the conversion to double is exact
    const std::vector<i64>& iv = ra.kind ? ib_ : ia_;
    for (i64 v : iv)
      if (v > mk::FLOAT_EXACT_INT || v < -mk::FLOAT_EXACT_INT)
        return nb::make_tuple(nb::none(), (int)mk::UNHANDLED, 0, 0, kind);
  }
  i64 big = std::max(na, nb_);
  thread_local std::vector<i64> keep, xa, xb;
  thread_local std::vector<std::int8_t> turn;
  keep.resize(big);
  turn.resize(big);
  xa.resize(na);
  xb.resize(nb_);
  auto run = [&](const auto* pa, const auto* pb) -> nb::tuple {
    using T = std::remove_const_t<std::remove_pointer_t<decltype(pa)>>;
    T* out = alloc<T>(2 * (std::size_t)(na + nb_));
    mk::Norm A, B;
    mk::SumResult r = mk::sum_pair(pa, 0, na, pb, 0, nb_, keep.data(), turn.data(), xa.data(),
                                   xb.data(), out, A, B);
    if (r.code) {
      std::free(out);
      return nb::make_tuple(nb::none(), r.code, r.which, r.vertex, kind);
    }
    return nb::make_tuple(owned(out, (std::size_t)r.k, 2), (int)mk::OK, 0, 0, kind);
  };
  if (kind == 0) return run(ia_.data(), ib_.data());
  return run(da.data(), db.data());
}

// Flatten a sequence of polygons (mk::flatten_polygons). Returns (coords (N,2), offsets
// (P+1,), kind, status, member, vertex); status UNHANDLED sends the caller to the
// general path.
nb::tuple flatten(nb::handle seq) {
  mk::Flat F;
  mk::flatten_polygons(seq.ptr(), F);
  if (F.status != mk::OK)
    return nb::make_tuple(nb::none(), nb::none(), F.kind, F.status, F.member, F.vertex);
  std::size_t P = F.off.size() - 1;
  i64* o = alloc<i64>(P + 1);
  std::copy(F.off.begin(), F.off.end(), o);
  std::size_t N = (std::size_t)F.off[P];
  if (F.kind) {
    double* c = alloc<double>(2 * N);
    std::copy(F.dbls.begin(), F.dbls.end(), c);
    return nb::make_tuple(owned(c, N, 2), owned(o, P + 1, 0), 1, (int)mk::OK, 0, 0);
  }
  i64* c = alloc<i64>(2 * N);
  std::copy(F.ints.begin(), F.ints.end(), c);
  return nb::make_tuple(owned(c, N, 2), owned(o, P + 1, 0), 0, (int)mk::OK, 0, 0);
}

// ------------------------------------------------------------------ predicates

template <class T>
Out<std::int8_t> orient_many(In2<T> P, In2<T> Q, In2<T> R) {
  i64 n = (i64)P.shape(0);
  std::int8_t* out = alloc<std::int8_t>((std::size_t)n);
  const T* p = P.data();
  const T* q = Q.data();
  const T* r = R.data();
  {
    nb::gil_scoped_release nogil;
    for (i64 i = 0; i < n; ++i)
      out[i] = (std::int8_t)mk::cross_sign(p[2 * i], p[2 * i + 1], q[2 * i], q[2 * i + 1],
                                           p[2 * i], p[2 * i + 1], r[2 * i], r[2 * i + 1]);
  }
  return owned(out, (std::size_t)n, 0);
}

void bind_collision(nb::module_& m);  // collision.cpp
void bind_decompose(nb::module_& m);  // decompose.cpp
void bind_planning(nb::module_& m);   // planning.cpp
void bind_navmesh(nb::module_& m);    // navmesh.cpp
void bind_overlay(nb::module_& m);    // overlay.cpp
void bind_general(nb::module_& m);    // general.cpp
void bind_polygon(nb::module_& m);    // polygon.cpp
void bind_union(nb::module_& m);      // union.cpp
void bind_offset(nb::module_& m);     // offset.cpp
void bind_nest(nb::module_& m);       // nest.cpp
void bind_boolean(nb::module_& m);    // boolean.cpp

}  // namespace mk_bind

NB_MODULE(_ext, m) {
  using namespace mk_bind;
  m.doc() = "minkowski2d's compiled exact core (private; use the public modules).";
  nb::dict sources;  // the merge trace's step sources (convex.hpp StepSource)
  sources["A"] = (int)mk::FROM_A;
  sources["B"] = (int)mk::FROM_B;
  sources["AB"] = (int)mk::FROM_BOTH;
  m.attr("TRACE_SOURCES") = sources;
  m.attr("TRACE_NO_CROSS") = (int)mk::NO_CROSS;
  m.attr("OK") = (int)mk::OK;
  m.attr("TURNS_BOTH_WAYS") = (int)mk::TURNS_BOTH_WAYS;
  m.attr("SPIKE") = (int)mk::SPIKE;
  m.attr("WINDS_TWICE") = (int)mk::WINDS_TWICE;
  m.attr("OVERFLOW") = (int)mk::OVERFLOW;
  m.attr("NONFINITE") = (int)mk::NONFINITE;
  m.attr("RANGE") = (int)mk::RANGE;
  m.attr("UNHANDLED") = (int)mk::UNHANDLED;
  m.attr("SHAPE") = (int)mk::SHAPE;
  m.attr("EMPTY") = (int)mk::EMPTY;
  m.attr("INTERNAL") = (int)mk::INTERNAL;
  m.attr("RESOURCE") = (int)mk::RESOURCE;
  m.attr("INT_LIMIT") = (long long)mk::INT_LIMIT;
  m.attr("FLOAT_EXACT_INT") = (long long)mk::FLOAT_EXACT_INT;
  m.attr("ERRBOUND") = mk::ERRBOUND;
  m.attr("MINBOUND") = mk::MINBOUND;

  m.def("sum_f", &sum_arrays<double>, "a"_a.noconvert(), "b"_a.noconvert(), "out"_a.noconvert());
  m.def("sum_i", &sum_arrays<i64>, "a"_a.noconvert(), "b"_a.noconvert(), "out"_a.noconvert());
  m.def("normalize_f", &normalize_array<double>, "p"_a.noconvert());
  m.def("normalize_i", &normalize_array<i64>, "p"_a.noconvert());
  m.def("hull_f", &hull_array<double>, "p"_a.noconvert());
  m.def("hull_i", &hull_array<i64>, "p"_a.noconvert());
  m.def("merge_record_f", &merge_record<double>, "a"_a.noconvert(), "b"_a.noconvert());
  m.def("merge_record_i", &merge_record<i64>, "a"_a.noconvert(), "b"_a.noconvert());
  m.def("sum_batch_f", &sum_batch<double>, "a"_a.noconvert(), "a_lo"_a.noconvert(),
        "a_hi"_a.noconvert(), "b"_a.noconvert(), "b_lo"_a.noconvert(), "b_hi"_a.noconvert(),
        "threads"_a);
  m.def("sum_batch_i", &sum_batch<i64>, "a"_a.noconvert(), "a_lo"_a.noconvert(),
        "a_hi"_a.noconvert(), "b"_a.noconvert(), "b_lo"_a.noconvert(), "b_hi"_a.noconvert(),
        "threads"_a);
  m.def("sum_lists", &sum_lists);
  m.def("flatten", &flatten);
  m.def("orient_f", &orient_many<double>, "p"_a.noconvert(), "q"_a.noconvert(), "r"_a.noconvert());
  m.def("orient_i", &orient_many<i64>, "p"_a.noconvert(), "q"_a.noconvert(), "r"_a.noconvert());
  m.def("cross_sign_f",
        [](double a0x, double a0y, double a1x, double a1y, double b0x, double b0y, double b1x,
           double b1y) { return mk::cross_sign(a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y); });
  m.def("cross_sign_exact_f",
        [](double a0x, double a0y, double a1x, double a1y, double b0x, double b0y, double b1x,
           double b1y) { return mk::cross_sign_exact(a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y); });
  m.def("cross_sign_i", [](i64 a0x, i64 a0y, i64 a1x, i64 a1y, i64 b0x, i64 b0y, i64 b1x,
                           i64 b1y) { return mk::cross_sign(a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y); });
  m.def("cross_expansion", [](double a0x, double a0y, double a1x, double a1y, double b0x,
                              double b0y, double b1x, double b1y) {
    double e[40];
    int k = mk::cross_expansion(e, a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y);
    nb::list out;
    for (int t = 0; t < k; ++t) out.append(e[t]);
    return out;
  });
  m.def("selftest", &mk::fp_contract_off_selftest);
  bind_collision(m);
  bind_planning(m);
  bind_navmesh(m);
  bind_decompose(m);
  bind_overlay(m);
  bind_general(m);
  bind_polygon(m);
  bind_union(m);
  bind_offset(m);
  bind_nest(m);
  bind_boolean(m);
}
