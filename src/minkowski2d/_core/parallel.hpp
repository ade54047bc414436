// parallel.hpp -- the one home of the core's threads: every batch that runs on several
// threads goes through one of the three calls below (no other std::thread in the core).
//
//   thread_count(threads, n)          the threads a batch of n items uses: 1 <= t <= n
//   parallel_tasks(n, threads, f)     f(i) for i in [0, n), each i taken by the next free
//                                     thread (items of unequal cost: a few large ones do
//                                     not leave threads idle)
//   parallel_chunks(n, threads, f)    f(t, lo, hi) once per thread t, on the contiguous
//                                     chunk [n t / nt, n (t + 1) / nt) (items of equal cost,
//                                     or per-thread state such as an output buffer)
//   parallel_threads(nt, f)           f(t) for t in [0, nt), t = 0 on the calling thread
//
// With one thread (or one item) the work runs on the calling thread, in order, with no
// thread started. The callables must not throw: an exception escaping a worker thread
// ends the process; the core reports errors through status codes instead.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

namespace mk {

inline int thread_count(int threads, std::int64_t n) {
  return (int)std::max<std::int64_t>(1, std::min<std::int64_t>(threads, n));
}

template <class F>
void parallel_threads(int nt, F&& f) {
  if (nt <= 1) {
    f(0);
    return;
  }
  std::vector<std::thread> pool;
  pool.reserve((std::size_t)nt - 1);
  for (int t = 1; t < nt; ++t) pool.emplace_back([&f, t]() { f(t); });
  f(0);
  for (auto& th : pool) th.join();
}

template <class F>
void parallel_tasks(std::int64_t n, int threads, F&& f) {
  const int nt = thread_count(threads, n);
  if (nt <= 1) {
    for (std::int64_t i = 0; i < n; ++i) f(i);
    return;
  }
  std::atomic<std::int64_t> next{0};
  parallel_threads(nt, [&](int) {
    for (std::int64_t i; (i = next.fetch_add(1)) < n;) f(i);
  });
}

template <class F>
void parallel_chunks(std::int64_t n, int threads, F&& f) {
  const int nt = thread_count(threads, n);
  parallel_threads(nt, [&](int t) { f(t, n * t / nt, n * (t + 1) / nt); });
}

}  // namespace mk
