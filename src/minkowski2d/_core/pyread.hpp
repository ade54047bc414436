// pyread.hpp -- reading Python input for the core's tiny paths (module.cpp): lists or
// tuples of (x, y) pairs of exact ints or floats, C-contiguous (n, 2) int64/float64
// buffers, and a sequence of such polygons flattened into one coordinate array. Plain
// C++ over the Python C API (the caller holds the GIL); the bindings wrap the results.
#pragma once

#include <Python.h>

#include <vector>

#include "exact.hpp"

namespace mk {

// Read a list/tuple of (x, y) pairs of exact Python ints or floats into xy. kind: 0 int,
// 1 float. Returns a Status: OK, UNHANDLED (another type, an int beyond 2^62 or a large
// int next to a float: the dispatcher's general path decides), NONFINITE (*bad = vertex).
struct ReadResult {
  int status;
  int kind;
  i64 bad;
};

inline ReadResult read_pairs(PyObject* seq, std::vector<i64>& ints, std::vector<double>& dbls) {
  ReadResult rr{OK, 0, 0};
  if (!PyList_Check(seq) && !PyTuple_Check(seq)) return {UNHANDLED, 0, 0};
  Py_ssize_t n = PySequence_Fast_GET_SIZE(seq);
  PyObject** items = PySequence_Fast_ITEMS(seq);
  if (n == 0) return {UNHANDLED, 0, 0};
  ints.resize(2 * n);
  dbls.resize(2 * n);
  bool any_float = false, any_int = false, big_int = false;
  for (Py_ssize_t k = 0; k < n; ++k) {
    PyObject* it = items[k];
    if (!(PyTuple_CheckExact(it) || PyList_CheckExact(it)) || PySequence_Fast_GET_SIZE(it) != 2)
      return {UNHANDLED, 0, 0};
    PyObject** xy = PySequence_Fast_ITEMS(it);
    for (int c = 0; c < 2; ++c) {
      PyObject* v = xy[c];
      if (PyFloat_CheckExact(v)) {
        double d = PyFloat_AS_DOUBLE(v);
        if (!(d - d == 0.0)) return {NONFINITE, 1, (i64)k};
        dbls[2 * k + c] = d;
        any_float = true;
        ints[2 * k + c] = 0;
      } else if (PyLong_CheckExact(v)) {
        int ovf = 0;
        long long x = PyLong_AsLongLongAndOverflow(v, &ovf);
        if (ovf || x >= INT_LIMIT || x <= -INT_LIMIT) return {UNHANDLED, 0, 0};
        ints[2 * k + c] = (i64)x;
        dbls[2 * k + c] = (double)x;
        if (x > FLOAT_EXACT_INT || x < -FLOAT_EXACT_INT) big_int = true;
        any_int = true;
      } else {
        return {UNHANDLED, 0, 0};
      }
    }
  }
  if (any_float && any_int && big_int) return {UNHANDLED, 0, 0};
  rr.kind = any_float ? 1 : 0;
  return rr;
}

// Read a C-contiguous (n, 2) int64/float64 buffer (a numpy array) like read_pairs.
inline ReadResult read_buffer(PyObject* obj, std::vector<i64>& ints, std::vector<double>& dbls) {
  if (!PyObject_CheckBuffer(obj)) return {UNHANDLED, 0, 0};
  Py_buffer view;
  if (PyObject_GetBuffer(obj, &view, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT | PyBUF_ND) != 0) {
    PyErr_Clear();
    return {UNHANDLED, 0, 0};
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
    return {UNHANDLED, 0, 0};
  Py_ssize_t n = view.shape[0];
  ints.resize(2 * n);
  dbls.resize(2 * n);
  if (is_f) {
    const double* d = static_cast<const double*>(view.buf);
    for (Py_ssize_t k = 0; k < 2 * n; ++k) {
      if (!(d[k] - d[k] == 0.0)) return {NONFINITE, 1, (i64)(k / 2)};
      dbls[k] = d[k];
      ints[k] = 0;
    }
    return {OK, 1, 0};
  }
  const i64* v = static_cast<const i64*>(view.buf);
  for (Py_ssize_t k = 0; k < 2 * n; ++k) {
    if (v[k] >= INT_LIMIT || v[k] <= -INT_LIMIT) return {UNHANDLED, 0, 0};
    ints[k] = v[k];
    dbls[k] = (double)v[k];
  }
  return {OK, 0, 0};
}

// A sequence of polygons flattened: every polygon's coordinates one after the other
// (ints and their doubles; kind 1: some polygon is float), off (P + 1) the offsets.
// status OK, or UNHANDLED (not a sequence of polygons the tiny path reads: the general
// path decides; member: the polygon) or NONFINITE (kind 1, member, vertex).
struct Flat {
  std::vector<i64> ints;
  std::vector<double> dbls;
  std::vector<i64> off;
  int status = OK, kind = 0;
  i64 member = 0, vertex = 0;
};

// Flatten a sequence of polygons (each a list/tuple of (x, y) pairs of Python ints or
// floats, or a C-contiguous (n, 2) int64/float64 ndarray) in one pass.
inline void flatten_polygons(PyObject* s, Flat& F) {
  if (!PyList_Check(s) && !PyTuple_Check(s)) {
    F.status = UNHANDLED;
    return;
  }
  Py_ssize_t P = PySequence_Fast_GET_SIZE(s);
  PyObject** items = PySequence_Fast_ITEMS(s);
  F.off.assign(P + 1, 0);
  std::vector<i64> ibuf;
  std::vector<double> dbuf;
  bool any_float = false, big_int = false, any_int = false;
  for (Py_ssize_t q = 0; q < P; ++q) {
    PyObject* it = items[q];
    ReadResult r = (PyList_Check(it) || PyTuple_Check(it)) ? read_pairs(it, ibuf, dbuf)
                                                            : read_buffer(it, ibuf, dbuf);
    if (r.status == NONFINITE) {
      F.status = NONFINITE, F.kind = 1, F.member = (i64)q, F.vertex = r.bad;
      return;
    }
    if (r.status != OK) {
      F.status = UNHANDLED, F.member = (i64)q;
      return;
    }
    if (r.kind) {
      any_float = true;
    } else {
      any_int = true;
      for (i64 v : ibuf)
        if (v > FLOAT_EXACT_INT || v < -FLOAT_EXACT_INT) big_int = true;
    }
    F.ints.insert(F.ints.end(), ibuf.begin(), ibuf.end());
    F.dbls.insert(F.dbls.end(), dbuf.begin(), dbuf.end());
    F.off[q + 1] = F.off[q] + (i64)ibuf.size() / 2;
  }
  if (any_float && any_int && big_int) {
    F.status = UNHANDLED;
    return;
  }
  F.kind = any_float ? 1 : 0;
}

}  // namespace mk
