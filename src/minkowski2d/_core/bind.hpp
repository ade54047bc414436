// bind.hpp -- what every binding file shares: the array types it accepts and returns,
// and how memory is handed to numpy (one allocator, one owner capsule).
#pragma once

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>

#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <vector>

#include <sys/mman.h>

#include "buffer.hpp"
#include "exact.hpp"

namespace mk_bind {

namespace nb = nanobind;
using mk::i64;

template <class T>
using Mut1 = nb::ndarray<T, nb::ndim<1>, nb::c_contig, nb::device::cpu>;

template <class T>
using In2 = nb::ndarray<const T, nb::ndim<2>, nb::c_contig, nb::device::cpu>;
template <class T>
using In1 = nb::ndarray<const T, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
template <class T>
using Out = nb::ndarray<nb::numpy, T>;

// The bindings check the arrays the Python side built before the kernels index them
// blindly. check_offsets: a CSR offsets array of n + 1 entries into `end` items --
// off[0] == 0, off[n] == end, non-decreasing (strictly increasing with `strict`: every
// group holds an item); check_finite: no NaN or infinity among `count` values. Else
// ValueError(what).
inline void check_offsets(const i64* off, i64 n, i64 end, const char* what,
                          bool strict = false) {
  if (n < 0 || off[0] != 0 || off[n] != end) throw nb::value_error(what);
  for (i64 k = 0; k < n; ++k)
    if (strict ? off[k + 1] <= off[k] : off[k + 1] < off[k]) throw nb::value_error(what);
}
inline void check_finite(const double* v, i64 count, const char* what) {
  for (i64 q = 0; q < count; ++q)
    if (!(v[q] - v[q] == 0)) throw nb::value_error(what);
}

// Rings handed back closed (each ring's first vertex repeated at its end), as shapely's
// from_ragged_array takes them. R holds them as ov::Rings does (xy: x, y per vertex;
// ring_off; poly_off into its rings). count_closed adds their rows, rings and polygons to
// the totals; append_closed writes them at row, ring, poly (oro[ring] and opo[poly]
// already set; opo nullptr: polygons not written) and advances the three.
template <class Rings>
void count_closed(const Rings& R, i64& rows, i64& rings, i64& polys) {
  rows += (i64)R.xy.size() / 2 + (i64)R.ring_off.size() - 1;
  rings += (i64)R.ring_off.size() - 1;
  polys += (i64)R.poly_off.size() - 1;
}
template <class Rings>
void append_closed(const Rings& R, double* oxy, i64* oro, i64* opo, i64& row, i64& ring,
                   i64& poly) {
  const i64 rr = (i64)R.ring_off.size() - 1, base = ring;
  for (i64 k = 0; k < rr; ++k) {
    const i64 a = R.ring_off[k], b = R.ring_off[k + 1];
    std::memcpy(oxy + 2 * row, R.xy.data() + 2 * a, sizeof(double) * 2 * (b - a));
    row += b - a;
    oxy[2 * row] = R.xy[2 * a];
    oxy[2 * row + 1] = R.xy[2 * a + 1];
    oro[++ring] = ++row;
  }
  if (opo)
    for (std::size_t k = 1; k < R.poly_off.size(); ++k) opo[++poly] = base + R.poly_off[k];
}

// Memory handed to numpy: malloc'd, and for large blocks 2 MiB-aligned with
// madvise(MADV_HUGEPAGE), as numpy's own allocator does. On this kind of kernel
// (transparent huge pages in "madvise" mode) fresh 4 KiB pages cost a fault each, and
// faults of one process serialize on its memory-map lock: with huge pages a 160 MB
// result takes 80 faults instead of 40,000, and threads stop queueing on them.
inline void* big_malloc(std::size_t bytes) {
  constexpr std::size_t HUGE = std::size_t(1) << 21;
  if (bytes < (std::size_t(4) << 20)) return std::malloc(bytes > 0 ? bytes : 1);
  std::size_t rounded = (bytes + HUGE - 1) & ~(HUGE - 1);
  void* p = std::aligned_alloc(HUGE, rounded);
#ifdef MADV_HUGEPAGE
  if (p) madvise(p, rounded, MADV_HUGEPAGE);
#endif
  return p;
}

template <class T>
T* alloc(std::size_t n) {
  void* p = big_malloc(sizeof(T) * (n > 0 ? n : 1));
  if (!p) throw std::bad_alloc();
  return static_cast<T*>(p);
}

// A new numpy array owning `data` (from alloc<T>).
template <class T>
Out<T> owned(T* data, std::size_t rows, std::size_t cols) {
  nb::capsule owner(data, [](void* p) noexcept { std::free(p); });
  if (cols == 0) {
    std::size_t shape[1] = {rows};
    return Out<T>(data, 1, shape, owner);
  }
  std::size_t shape[2] = {rows, cols};
  return Out<T>(data, 2, shape, owner);
}

using mk::Buf;  // uninitialized scratch (buffer.hpp)

template <class T>
using Mut2 = nb::ndarray<T, nb::ndim<2>, nb::c_contig, nb::device::cpu>;

// A new numpy array holding a copy of `v` (rows x cols; cols == 0: one dimension).
template <class T>
Out<T> to_numpy(const std::vector<T>& v, std::size_t rows, std::size_t cols) {
  T* data = alloc<T>(v.size());
  if (!v.empty()) std::memcpy(data, v.data(), sizeof(T) * v.size());
  return owned(data, rows, cols);
}

// (status (n,), group (n,), points (M, 2), offsets (n + 1,)): a planner's answers to n
// queries (mk::PlanAnswers, planning_queries.hpp)
template <class Answers>
nb::tuple answers_tuple(const Answers& A) {
  std::size_t n = A.st.size();
  return nb::make_tuple(to_numpy(A.st, n, 0), to_numpy(A.gr, n, 0),
                        to_numpy(A.pts, A.pts.size() / 2, 2), to_numpy(A.off, n + 1, 0));
}

}  // namespace mk_bind
