// decompose.cpp -- bindings of the Hertel-Mehlhorn kernels (decompose.hpp) into
// minkowski2d._core._ext: orient_triangles_{f,i} and hertel_mehlhorn_{f,i}. The arrays come
// from minkowski2d._decompose; they are checked here (shapes, id ranges, the twin pairing,
// finite / int64-range coordinates) before the kernels run with the GIL released.
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/tuple.h>

#include <cstdint>
#include <type_traits>

#include "bind.hpp"
#include "decompose.hpp"
#include "exact.hpp"

namespace nb = nanobind;
using namespace nb::literals;
using mk::i64;

namespace mk_bind {
namespace {

// The kernels index blindly: check the arrays the Python side built before trusting them.
template <class T>
void check_inputs(const In2<T>& P, const i64* ids, std::size_t ntri, std::size_t cols) {
  if (P.shape(1) != 2) throw nb::value_error("decompose: vertices must have shape (n, 2)");
  if (cols != 3) throw nb::value_error("decompose: triangles must have shape (T, 3)");
  const i64 n = (i64)P.shape(0);
  for (std::size_t q = 0; q < 3 * ntri; ++q)
    if (ids[q] < 0 || ids[q] >= n) throw nb::value_error("decompose: vertex id out of range");
  if constexpr (std::is_floating_point_v<T>) {
    const T* p = P.data();
    for (i64 q = 0; q < 2 * n; ++q)
      if (!(p[q] - p[q] == 0)) throw nb::value_error("decompose: non-finite coordinate");
  } else {
    const T* p = P.data();
    for (i64 q = 0; q < 2 * n; ++q)
      if (p[q] >= mk::INT_LIMIT || p[q] <= -mk::INT_LIMIT)
        throw nb::value_error("decompose: int coordinate beyond 2**62");
  }
}

// orient_triangles_*(verts (n, 2), ids (T, 3) int64, writable) -> keep (T,) bool.
// ids is reordered in place so that every triangle is counter-clockwise.
template <class T>
Out<bool> orient_triangles(In2<T> P, Mut2<i64> I) {
  std::size_t ntri = I.shape(0);
  check_inputs<T>(P, I.data(), ntri, I.shape(1));
  bool* keep = alloc<bool>(ntri);
  {
    nb::gil_scoped_release nogil;
    mk::decompose::orient_triangles(P.data(), I.data(), (i64)ntri, keep);
  }
  return owned(keep, ntri, 0);
}

// hertel_mehlhorn_*(verts (n, 2), ids (T, 3) CCW, twin (3T,), merge) -> (vertex ids (N,),
// offsets (P + 1,)): the pieces, each CCW from its bottom-most vertex.
template <class T>
nb::tuple hertel_mehlhorn(In2<T> P, In2<i64> I, In1<i64> Tw, bool merge) {
  const std::size_t ntri = I.shape(0);
  const i64 H = 3 * (i64)ntri;
  check_inputs<T>(P, I.data(), ntri, I.shape(1));
  if ((i64)Tw.shape(0) != H) throw nb::value_error("decompose: twin must have shape (3T,)");
  const i64* twin = Tw.data();
  // twin must be an involution without fixed points (or -1): each merge splices two
  // distinct faces, which keeps nxt a permutation and the face walk finite
  for (i64 h = 0; h < H; ++h) {
    i64 t = twin[h];
    if (t == -1) continue;
    if (t < 0 || t >= H || t == h || twin[t] != h)
      throw nb::value_error("decompose: twin is not a pairing of half-edges");
  }
  i64* out = alloc<i64>(H);
  i64* off = alloc<i64>(ntri + 1);
  i64 npieces;
  {
    nb::gil_scoped_release nogil;
    npieces = mk::decompose::hertel_mehlhorn(P.data(), I.data(), (i64)ntri, twin, merge, out, off);
  }
  i64 n_out = off[npieces];
  return nb::make_tuple(owned(out, (std::size_t)n_out, 0), owned(off, (std::size_t)npieces + 1, 0));
}

}  // namespace

void bind_decompose(nb::module_& m) {
  m.def("orient_triangles_f", &orient_triangles<double>, "verts"_a.noconvert(),
        "ids"_a.noconvert());
  m.def("orient_triangles_i", &orient_triangles<i64>, "verts"_a.noconvert(),
        "ids"_a.noconvert());
  m.def("hertel_mehlhorn_f", &hertel_mehlhorn<double>, "verts"_a.noconvert(),
        "ids"_a.noconvert(), "twin"_a.noconvert(), "merge"_a);
}

}  // namespace mk_bind
