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
#include <memory>
#include <new>

#include <sys/mman.h>
#include <cstring>
#include <vector>

#include "bind.hpp"
#include "convex.hpp"
#include "exact.hpp"
#include "parallel.hpp"

namespace nb = nanobind;
using namespace nb::literals;
using mk::i64;

namespace mk_bind {

// ------------------------------------------------------------------ convex, one pair

// Sum into `out` (numpy-allocated by the caller, (na + nb, 2)): (k, code, which, vertex).
template <class T>
nb::tuple sum_arrays(In2<T> A, In2<T> B, Mut2<T> O) {
  const T* pa = A.data();
  const T* pb = B.data();
  T* out = O.data();
  i64 na = (i64)A.shape(0), nb_ = (i64)B.shape(0);
  i64 k = 0;
  int code = mk::OK, which = 0;
  i64 vertex = 0;
  {
    nb::gil_scoped_release nogil;
    i64 big = std::max(na, nb_);
    Buf<i64> keep(big), ia(na), ib(nb_);
    Buf<std::int8_t> turn(big);
    mk::Norm a = mk::normalize(pa, 0, na, keep.data(), turn.data(), ia.data());
    if (a.code) {
      code = a.code;
      vertex = a.vertex;
    } else {
      mk::Norm b = mk::normalize(pb, 0, nb_, keep.data(), turn.data(), ib.data());
      if (b.code) {
        code = b.code;
        which = 1;
        vertex = b.vertex;
      } else {
        k = mk::merge(pa, a, pb, b, out);
        if (k < 0) {
          code = mk::OVERFLOW;
          which = 2;
          k = 0;
        }
      }
    }
  }
  return nb::make_tuple(k, code, which, vertex);
}

// Normalize one polygon: (indices (k,), split, code, vertex).
template <class T>
nb::tuple normalize_array(In2<T> P) {
  const T* p = P.data();
  i64 n = (i64)P.shape(0);
  i64* idx = alloc<i64>((std::size_t)n);
  mk::Norm r;
  {
    nb::gil_scoped_release nogil;
    Buf<i64> keep(n);
    Buf<std::int8_t> turn(n);
    r = mk::normalize(p, 0, n, keep.data(), turn.data(), idx);
    if (!r.code && r.step != 0)
      for (i64 t = 0; t < r.k; ++t) idx[t] = r.at(t);
  }
  if (r.code) r.k = 0;
  return nb::make_tuple(owned(idx, (std::size_t)r.k, 0), r.split, (int)r.code, r.vertex);
}

// Convex hull indices (CCW from the lowest-x point, collinear points dropped).
template <class T>
Out<i64> hull_array(In2<T> P) {
  const T* p = P.data();
  i64 n = (i64)P.shape(0);
  i64* h = alloc<i64>(2 * (std::size_t)n + 1);
  i64 k;
  {
    nb::gil_scoped_release nogil;
    std::vector<i64> order(n);
    for (i64 i = 0; i < n; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [p](i64 u, i64 v) {
      return p[2 * u] < p[2 * v] || (p[2 * u] == p[2 * v] && p[2 * u + 1] < p[2 * v + 1]);
    });
    // drop exact duplicates
    i64 m = 0;
    for (i64 t = 0; t < n; ++t)
      if (m == 0 || p[2 * order[t]] != p[2 * order[m - 1]] ||
          p[2 * order[t] + 1] != p[2 * order[m - 1] + 1])
        order[m++] = order[t];
    if (m <= 2) {
      for (i64 t = 0; t < m; ++t) h[t] = order[t];
      k = m;
    } else {
      k = mk::hull_sorted(p, order.data(), m, h);
    }
  }
  return owned(h, (std::size_t)k, 0);
}

// ------------------------------------------------------------------ the merge, recorded

// (sum (k,2), steps (s,4) int64 [source, i, j, cross], idx_a, split_a, idx_b, split_b,
//  code, which, vertex) -- the animation's trace of the same merge.
template <class T>
nb::tuple merge_record(In2<T> A, In2<T> B) {
  const T* pa = A.data();
  const T* pb = B.data();
  i64 na = (i64)A.shape(0), nb_ = (i64)B.shape(0);
  i64 big = std::max<i64>(std::max(na, nb_), 1);
  T* out = alloc<T>(2 * (std::size_t)(na + nb_));
  i64* ia = alloc<i64>((std::size_t)na);
  i64* ib = alloc<i64>((std::size_t)nb_);
  std::vector<mk::Step> rec;
  std::vector<i64> keep(big);
  std::vector<std::int8_t> turn(big);
  int code = mk::OK, which = 0;
  i64 vertex = 0, k = 0;
  mk::Norm a = mk::normalize(pa, 0, na, keep.data(), turn.data(), ia);
  mk::Norm b;
  if (a.code) {
    code = a.code;
    vertex = a.vertex;
  } else {
    b = mk::normalize(pb, 0, nb_, keep.data(), turn.data(), ib);
    if (b.code) {
      code = b.code;
      which = 1;
      vertex = b.vertex;
    } else {
      k = mk::merge(pa, a, pb, b, out, &rec);
      if (k < 0) {
        code = mk::OVERFLOW;
        which = 2;
        k = 0;
      }
    }
  }
  if (!a.code && a.step) for (i64 t = 0; t < a.k; ++t) ia[t] = a.at(t);
  if (!a.code && !b.code && b.step) for (i64 t = 0; t < b.k; ++t) ib[t] = b.at(t);
  i64* steps = alloc<i64>(4 * rec.size());
  for (std::size_t s = 0; s < rec.size(); ++s) {
    steps[4 * s] = rec[s].source;
    steps[4 * s + 1] = rec[s].i;
    steps[4 * s + 2] = rec[s].j;
    steps[4 * s + 3] = rec[s].cross;
  }
  i64 ka = code ? 0 : a.k, kb = code ? 0 : b.k;
  return nb::make_tuple(owned(out, (std::size_t)k, 2), owned(steps, rec.size(), 4),
                        owned(ia, (std::size_t)ka, 0), a.split, owned(ib, (std::size_t)kb, 0),
                        b.split, code, which, vertex);
}

// ------------------------------------------------------------------ batch

// Pair q sums A[a_lo[q]:a_hi[q]] and B[b_lo[q]:b_hi[q]]. Returns (coords (K, 2),
// offsets (P + 1,), code, pair, which, vertex); on failure the lowest failing pair is
// reported, whatever the number of threads. Each thread sums a contiguous chunk of pairs
// into its own buffer; after the prefix sum each copies its chunk into place, so both
// phases run in parallel and nothing is compacted serially.
template <class T>
nb::tuple sum_batch(In2<T> A, In1<i64> a_lo, In1<i64> a_hi, In2<T> B, In1<i64> b_lo,
                    In1<i64> b_hi, int threads) {
  const T* pa = A.data();
  const T* pb = B.data();
  const i64* alo = a_lo.data();
  const i64* ahi = a_hi.data();
  const i64* blo = b_lo.data();
  const i64* bhi = b_hi.data();
  const i64 P = (i64)a_lo.shape(0);
  i64* off = alloc<i64>((std::size_t)P + 1);
  T* coords = nullptr;
  int code = mk::OK, which = 0;
  i64 pair = 0, vertex = 0, total = 0;
  {
    nb::gil_scoped_release nogil;
    const int nt = mk::thread_count(threads, P / 64);
    struct Chunk {
      i64 q0 = 0, q1 = 0;
      T* buf = nullptr;
      i64 used = 0;
      i64 fail = -1;
      int code = 0, which = 0;
      i64 vertex = 0;
    };
    std::vector<Chunk> ch(nt);
    auto run = [&](int t) {
      Chunk& c = ch[t];
      c.q0 = P * t / nt;
      c.q1 = P * (t + 1) / nt;
      i64 big = 1, cap = 0;
      for (i64 q = c.q0; q < c.q1; ++q) {
        i64 la = ahi[q] - alo[q], lb = bhi[q] - blo[q];
        big = std::max(big, std::max(la, lb));
        cap += std::max<i64>(la + lb, 1);
      }
      c.buf = alloc<T>(2 * (std::size_t)std::max<i64>(cap, 1));
      Buf<i64> keep(big), ia(big), ib(big);
      Buf<std::int8_t> turn(big);
      T* out = c.buf;
      i64 o = 0;
      for (i64 q = c.q0; q < c.q1; ++q) {
        mk::Norm a = mk::normalize(pa, alo[q], ahi[q], keep.data(), turn.data(), ia.data());
        if (a.code) {
          c.fail = q, c.code = a.code, c.which = 0, c.vertex = a.vertex;
          return;
        }
        mk::Norm b = mk::normalize(pb, blo[q], bhi[q], keep.data(), turn.data(), ib.data());
        if (b.code) {
          c.fail = q, c.code = b.code, c.which = 1, c.vertex = b.vertex;
          return;
        }
        i64 k = mk::merge(pa, a, pb, b, out + 2 * o);
        if (k < 0) {
          c.fail = q, c.code = mk::OVERFLOW, c.which = 2;
          return;
        }
        off[q + 1] = k;  // a count for now; the prefix sum below makes it an offset
        o += k;
      }
      c.used = o;
    };
    mk::parallel_threads(nt, run);
    for (auto& c : ch)
      if (c.fail >= 0) {
        code = c.code, pair = c.fail, which = c.which, vertex = c.vertex;
        break;
      }
    if (code == mk::OK) {
      off[0] = 0;
      for (i64 q = 0; q < P; ++q) off[q + 1] += off[q];
      total = off[P];
      if (nt == 1) {
        // one chunk is already in place: hand its buffer over (numpy's shape covers the
        // used rows; the unused tail of the capacity is freed with it)
        coords = ch[0].buf;
        ch[0].buf = nullptr;
      } else {
        coords = alloc<T>(2 * (std::size_t)total);
        mk::parallel_threads(nt, [&](int t) {
          Chunk& c = ch[t];
          if (c.used) std::memcpy(coords + 2 * off[c.q0], c.buf, sizeof(T) * 2 * c.used);
          std::free(c.buf);
          c.buf = nullptr;
        });
      }
    }
    for (auto& c : ch) std::free(c.buf);  // the error path (null otherwise)
  }
  if (code != mk::OK) {
    coords = alloc<T>(0);
    total = 0;
    std::fill(off, off + P + 1, 0);
  }
  return nb::make_tuple(owned(coords, (std::size_t)total, 2), owned(off, (std::size_t)P + 1, 0),
                        code, pair, which, vertex);
}

// ------------------------------------------------------------------ Python sequences

// Read a list/tuple of (x, y) pairs of exact Python ints or floats into xy. kind: 0 int,
// 1 float. Returns a Status: OK, UNHANDLED (another type, an int beyond 2^62 or a large
// int next to a float: the dispatcher's general path decides), NONFINITE (*bad = vertex).
struct ReadResult {
  int status;
  int kind;
  i64 bad;
};

inline ReadResult read_pairs(PyObject* seq, std::vector<i64>& ints, std::vector<double>& dbls) {
  ReadResult rr{mk::OK, 0, 0};
  if (!PyList_Check(seq) && !PyTuple_Check(seq)) return {mk::UNHANDLED, 0, 0};
  Py_ssize_t n = PySequence_Fast_GET_SIZE(seq);
  PyObject** items = PySequence_Fast_ITEMS(seq);
  if (n == 0) return {mk::UNHANDLED, 0, 0};
  ints.resize(2 * n);
  dbls.resize(2 * n);
  bool any_float = false, any_int = false, big_int = false;
  for (Py_ssize_t k = 0; k < n; ++k) {
    PyObject* it = items[k];
    if (!(PyTuple_CheckExact(it) || PyList_CheckExact(it)) || PySequence_Fast_GET_SIZE(it) != 2)
      return {mk::UNHANDLED, 0, 0};
    PyObject** xy = PySequence_Fast_ITEMS(it);
    for (int c = 0; c < 2; ++c) {
      PyObject* v = xy[c];
      if (PyFloat_CheckExact(v)) {
        double d = PyFloat_AS_DOUBLE(v);
        if (!(d - d == 0.0)) return {mk::NONFINITE, 1, (i64)k};
        dbls[2 * k + c] = d;
        any_float = true;
        ints[2 * k + c] = 0;
      } else if (PyLong_CheckExact(v)) {
        int ovf = 0;
        long long x = PyLong_AsLongLongAndOverflow(v, &ovf);
        if (ovf || x >= mk::INT_LIMIT || x <= -mk::INT_LIMIT) return {mk::UNHANDLED, 0, 0};
        ints[2 * k + c] = (i64)x;
        dbls[2 * k + c] = (double)x;
        if (x > mk::FLOAT_EXACT_INT || x < -mk::FLOAT_EXACT_INT) big_int = true;
        any_int = true;
      } else {
        return {mk::UNHANDLED, 0, 0};
      }
    }
  }
  if (any_float && any_int && big_int) return {mk::UNHANDLED, 0, 0};
  rr.kind = any_float ? 1 : 0;
  return rr;
}

// The tiny path: two Python sequences of pairs straight into the core. Returns
// (result ndarray or None, code, which, vertex, kind); code UNHANDLED sends the caller to
// the general path (which validates and raises the specific error).
nb::tuple sum_lists(nb::handle a, nb::handle b) {
  thread_local std::vector<i64> ia_, ib_;
  thread_local std::vector<double> da, db;
  ReadResult ra = read_pairs(a.ptr(), ia_, da);
  if (ra.status != mk::OK)
    return nb::make_tuple(nb::none(), (int)ra.status, 0, ra.bad, ra.kind);
  ReadResult rb = read_pairs(b.ptr(), ib_, db);
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
  if (kind == 0) {
    const i64* pa = ia_.data();
    const i64* pb = ib_.data();
    mk::Norm A = mk::normalize(pa, 0, na, keep.data(), turn.data(), xa.data());
    if (A.code) return nb::make_tuple(nb::none(), (int)A.code, 0, A.vertex, kind);
    mk::Norm B = mk::normalize(pb, 0, nb_, keep.data(), turn.data(), xb.data());
    if (B.code) return nb::make_tuple(nb::none(), (int)B.code, 1, B.vertex, kind);
    i64* out = alloc<i64>(2 * (std::size_t)(na + nb_));
    i64 k = mk::merge(pa, A, pb, B, out);
    return nb::make_tuple(owned(out, (std::size_t)k, 2), (int)mk::OK, 0, 0, kind);
  }
  const double* pa = da.data();
  const double* pb = db.data();
  mk::Norm A = mk::normalize(pa, 0, na, keep.data(), turn.data(), xa.data());
  if (A.code) return nb::make_tuple(nb::none(), (int)A.code, 0, A.vertex, kind);
  mk::Norm B = mk::normalize(pb, 0, nb_, keep.data(), turn.data(), xb.data());
  if (B.code) return nb::make_tuple(nb::none(), (int)B.code, 1, B.vertex, kind);
  double* out = alloc<double>(2 * (std::size_t)(na + nb_));
  i64 k = mk::merge(pa, A, pb, B, out);
  if (k < 0) {
    std::free(out);
    return nb::make_tuple(nb::none(), (int)mk::OVERFLOW, 2, 0, kind);
  }
  return nb::make_tuple(owned(out, (std::size_t)k, 2), (int)mk::OK, 0, 0, kind);
}

// Read a C-contiguous (n, 2) int64/float64 buffer (a numpy array) like read_pairs.
inline ReadResult read_buffer(PyObject* obj, std::vector<i64>& ints, std::vector<double>& dbls) {
  if (!PyObject_CheckBuffer(obj)) return {mk::UNHANDLED, 0, 0};
  Py_buffer view;
  if (PyObject_GetBuffer(obj, &view, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT | PyBUF_ND) != 0) {
    PyErr_Clear();
    return {mk::UNHANDLED, 0, 0};
  }
  struct Release {
    Py_buffer* v;
    ~Release() { PyBuffer_Release(v); }
  } release{&view};
  const char* f = view.format ? view.format : "B";
  if (*f == '<' || *f == '=' || *f == '@') ++f;
  bool is_f = (f[0] == 'd' && f[1] == 0), is_i = ((f[0] == 'l' || f[0] == 'q') && f[1] == 0);
  if (view.ndim != 2 || view.shape[1] != 2 || view.shape[0] == 0 || view.itemsize != 8 ||
      !(is_f || is_i))
    return {mk::UNHANDLED, 0, 0};
  Py_ssize_t n = view.shape[0];
  ints.resize(2 * n);
  dbls.resize(2 * n);
  if (is_f) {
    const double* d = static_cast<const double*>(view.buf);
    for (Py_ssize_t k = 0; k < 2 * n; ++k) {
      if (!(d[k] - d[k] == 0.0)) return {mk::NONFINITE, 1, (i64)(k / 2)};
      dbls[k] = d[k];
      ints[k] = 0;
    }
    return {mk::OK, 1, 0};
  }
  const i64* v = static_cast<const i64*>(view.buf);
  for (Py_ssize_t k = 0; k < 2 * n; ++k) {
    if (v[k] >= mk::INT_LIMIT || v[k] <= -mk::INT_LIMIT) return {mk::UNHANDLED, 0, 0};
    ints[k] = v[k];
    dbls[k] = (double)v[k];
  }
  return {mk::OK, 0, 0};
}

// Flatten a sequence of polygons (each a list/tuple of (x, y) pairs of Python ints or
// floats, or a C-contiguous (n, 2) int64/float64 ndarray) in one pass. Returns
// (coords (N,2), offsets (P+1,), kind, status, member, vertex); status UNHANDLED sends
// the caller to the general path.
nb::tuple flatten(nb::handle seq) {
  PyObject* s = seq.ptr();
  if (!PyList_Check(s) && !PyTuple_Check(s))
    return nb::make_tuple(nb::none(), nb::none(), 0, (int)mk::UNHANDLED, 0, 0);
  Py_ssize_t P = PySequence_Fast_GET_SIZE(s);
  PyObject** items = PySequence_Fast_ITEMS(s);
  std::vector<i64> ints;
  std::vector<double> dbls;
  std::vector<i64> off(P + 1, 0);
  std::vector<i64> ibuf;
  std::vector<double> dbuf;
  bool any_float = false, big_int = false, any_int = false;
  for (Py_ssize_t q = 0; q < P; ++q) {
    PyObject* it = items[q];
    ReadResult r = (PyList_Check(it) || PyTuple_Check(it)) ? read_pairs(it, ibuf, dbuf)
                                                            : read_buffer(it, ibuf, dbuf);
    if (r.status == mk::NONFINITE)
      return nb::make_tuple(nb::none(), nb::none(), 1, (int)mk::NONFINITE, (i64)q, r.bad);
    if (r.status != mk::OK)
      return nb::make_tuple(nb::none(), nb::none(), 0, (int)mk::UNHANDLED, (i64)q, 0);
    if (r.kind) {
      any_float = true;
    } else {
      any_int = true;
      for (i64 v : ibuf)
        if (v > mk::FLOAT_EXACT_INT || v < -mk::FLOAT_EXACT_INT) big_int = true;
    }
    ints.insert(ints.end(), ibuf.begin(), ibuf.end());
    dbls.insert(dbls.end(), dbuf.begin(), dbuf.end());
    off[q + 1] = off[q] + (i64)ibuf.size() / 2;
  }
  if (any_float && any_int && big_int)
    return nb::make_tuple(nb::none(), nb::none(), 0, (int)mk::UNHANDLED, 0, 0);
  i64* o = alloc<i64>((std::size_t)P + 1);
  std::copy(off.begin(), off.end(), o);
  std::size_t N = (std::size_t)off[P];
  if (any_float) {
    double* c = alloc<double>(2 * N);
    std::copy(dbls.begin(), dbls.end(), c);
    return nb::make_tuple(owned(c, N, 2), owned(o, (std::size_t)P + 1, 0), 1, (int)mk::OK, 0, 0);
  }
  i64* c = alloc<i64>(2 * N);
  std::copy(ints.begin(), ints.end(), c);
  return nb::make_tuple(owned(c, N, 2), owned(o, (std::size_t)P + 1, 0), 0, (int)mk::OK, 0, 0);
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
