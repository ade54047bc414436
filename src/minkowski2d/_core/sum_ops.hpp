// sum_ops.hpp -- what module.cpp's convex bindings run: one pair normalized and summed
// (sum_pair), one polygon normalized (normalize_rotated) or hulled (hull_indices), and the
// batch over pairs on parallel.hpp (sum_batch). The bindings convert, call and wrap.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "buffer.hpp"
#include "convex.hpp"
#include "exact.hpp"
#include "parallel.hpp"

namespace mk {

// A sum's outcome: k vertices and code OK, or the first failure: which 0 (the first
// polygon) or 1 (the second) at vertex, or 2 with OVERFLOW (a float coordinate of the
// sum is not finite); k = 0 then.
struct SumResult {
  i64 k = 0;
  int code = OK, which = 0;
  i64 vertex = 0;
};

// Normalize a = pa[alo:ahi] into a (indices in ia) and b = pb[blo:bhi] into b (ib), with
// scratch keep and turn for the larger, and merge them into out (room for both counts of
// rows; rec: the merge's steps).
template <class T>
inline SumResult sum_pair(const T* pa, i64 alo, i64 ahi, const T* pb, i64 blo, i64 bhi,
                          i64* keep, std::int8_t* turn, i64* ia, i64* ib, T* out, Norm& a,
                          Norm& b, std::vector<Step>* rec = nullptr) {
  a = normalize(pa, alo, ahi, keep, turn, ia);
  if (a.code) return {0, a.code, 0, a.vertex};
  b = normalize(pb, blo, bhi, keep, turn, ib);
  if (b.code) return {0, b.code, 1, b.vertex};
  i64 k = merge(pa, a, pb, b, out, rec);
  if (k < 0) return {0, OVERFLOW, 2, 0};
  return {k, OK, 0, 0};
}

// The same for p[0:na] and q[0:nb] with scratch of its own.
template <class T>
inline SumResult sum_pair(const T* pa, i64 na, const T* pb, i64 nb, T* out) {
  i64 big = std::max(na, nb);
  Buf<i64> keep(big), ia(na), ib(nb);
  Buf<std::int8_t> turn(big);
  Norm a, b;
  return sum_pair(pa, 0, na, pb, 0, nb, keep.data(), turn.data(), ia.data(), ib.data(), out, a, b);
}

// The explicit indices of a normalized rotation (idx[0:r.k] = r.at(t)).
inline void write_indices(const Norm& r, i64* idx) {
  if (!r.code && r.step != 0)
    for (i64 t = 0; t < r.k; ++t) idx[t] = r.at(t);
}

// Normalize p[0:n]: its indices in order to idx (room for n).
template <class T>
inline Norm normalize_rotated(const T* p, i64 n, i64* idx) {
  Buf<i64> keep(n);
  Buf<std::int8_t> turn(n);
  Norm r = normalize(p, 0, n, keep.data(), turn.data(), idx);
  write_indices(r, idx);
  return r;
}

// Convex hull indices of p[0:n] into h (room for 2n + 1), CCW from the lowest-x point,
// exact duplicates and collinear points dropped; returns their count.
template <class T>
inline i64 hull_indices(const T* p, i64 n, i64* h) {
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
    return m;
  }
  return hull_sorted(p, order.data(), m, h);
}

// The merge of pa[0:na] and pb[0:nb] recorded: the sum into out, the steps into steps (4
// per step: source, i, j, cross), each polygon's normalized indices into ia, ib and
// their splits into a, b.
template <class T>
inline SumResult merge_recorded(const T* pa, i64 na, const T* pb, i64 nb, T* out, i64* ia,
                                i64* ib, Norm& a, Norm& b, std::vector<i64>& steps) {
  i64 big = std::max<i64>(std::max(na, nb), 1);
  std::vector<Step> rec;
  std::vector<i64> keep(big);
  std::vector<std::int8_t> turn(big);
  SumResult r = sum_pair(pa, 0, na, pb, 0, nb, keep.data(), turn.data(), ia, ib, out, a, b, &rec);
  if (!a.code && a.step)
    for (i64 t = 0; t < a.k; ++t) ia[t] = a.at(t);
  if (!a.code && !b.code && b.step)
    for (i64 t = 0; t < b.k; ++t) ib[t] = b.at(t);
  steps.resize(4 * rec.size());
  for (std::size_t s = 0; s < rec.size(); ++s) {
    steps[4 * s] = rec[s].source;
    steps[4 * s + 1] = rec[s].i;
    steps[4 * s + 2] = rec[s].j;
    steps[4 * s + 3] = rec[s].cross;
  }
  return r;
}

// ------------------------------------------------------------------------------------
// the batch

// One thread's chunk of pairs [q0, q1): its sums in buf (`used` rows), or the first
// failing pair.
template <class T>
struct SumChunk {
  i64 q0 = 0, q1 = 0;
  T* buf = nullptr;
  i64 used = 0;
  i64 fail = -1;
  SumResult res;
};

// Sum the pairs of chunk c into a buffer of its own (from alloc); off[q + 1] receives
// pair q's count.
template <class T, class Alloc>
inline void sum_chunk(const T* pa, const i64* alo, const i64* ahi, const T* pb, const i64* blo,
                      const i64* bhi, i64* off, SumChunk<T>& c, Alloc& alloc) {
  i64 big = 1, cap = 0;
  for (i64 q = c.q0; q < c.q1; ++q) {
    i64 la = ahi[q] - alo[q], lb = bhi[q] - blo[q];
    big = std::max(big, std::max(la, lb));
    cap += std::max<i64>(la + lb, 1);
  }
  c.buf = alloc(2 * (std::size_t)std::max<i64>(cap, 1));
  Buf<i64> keep(big), ia(big), ib(big);
  Buf<std::int8_t> turn(big);
  T* out = c.buf;
  i64 o = 0;
  for (i64 q = c.q0; q < c.q1; ++q) {
    Norm a, b;
    SumResult r = sum_pair(pa, alo[q], ahi[q], pb, blo[q], bhi[q], keep.data(), turn.data(),
                           ia.data(), ib.data(), out + 2 * o, a, b);
    if (r.code) {
      c.fail = q, c.res = r;
      return;
    }
    off[q + 1] = r.k;  // a count for now; the prefix sum makes it an offset
    o += r.k;
  }
  c.used = o;
}

// Pair q sums pa[alo[q]:ahi[q]] and pb[blo[q]:bhi[q]]. Returns the coordinates (from
// alloc, malloc-compatible: freed with std::free; `total` rows) with off (P + 1) their
// offsets; on failure the lowest failing pair (`pair`, and fail's code, which and
// vertex), whatever the number of threads, no rows and zero offsets. Each thread sums a
// contiguous chunk of pairs into its own buffer; after the prefix sum each copies its
// chunk into place, so both phases run in parallel and nothing is compacted serially.
template <class T, class Alloc>
inline T* sum_batch(const T* pa, const i64* alo, const i64* ahi, const T* pb, const i64* blo,
                    const i64* bhi, i64 P, int threads, i64* off, i64& total, SumResult& fail,
                    i64& pair, Alloc&& alloc) {
  T* coords = nullptr;
  total = 0;
  pair = 0;
  fail = SumResult{};
  const int nt = thread_count(threads, P / 64);
  std::vector<SumChunk<T>> ch(nt);
  parallel_threads(nt, [&](int t) {
    ch[t].q0 = P * t / nt;
    ch[t].q1 = P * (t + 1) / nt;
    sum_chunk(pa, alo, ahi, pb, blo, bhi, off, ch[t], alloc);
  });
  for (auto& c : ch)
    if (c.fail >= 0) {
      fail = c.res, pair = c.fail;
      break;
    }
  if (fail.code == OK) {
    off[0] = 0;
    for (i64 q = 0; q < P; ++q) off[q + 1] += off[q];
    total = off[P];
    if (nt == 1) {
      // one chunk is already in place: hand its buffer over (numpy's shape covers the
      // used rows; the unused tail of the capacity is freed with it)
      coords = ch[0].buf;
      ch[0].buf = nullptr;
    } else {
      coords = alloc(2 * (std::size_t)total);
      parallel_threads(nt, [&](int t) {
        SumChunk<T>& c = ch[t];
        if (c.used) std::memcpy(coords + 2 * off[c.q0], c.buf, sizeof(T) * 2 * c.used);
        std::free(c.buf);
        c.buf = nullptr;
      });
    }
  }
  for (auto& c : ch) std::free(c.buf);  // the error path (null otherwise)
  if (fail.code != OK) {
    coords = alloc(0);
    total = 0;
    std::fill(off, off + P + 1, 0);
  }
  return coords;
}

}  // namespace mk
