// buffer.hpp -- scratch: uninitialized buffers (std::vector would zero them: for 2^20
// vertices that memset costs more than the merge; untouched pages of a large new[] are
// never even faulted in), and each thread's workspace kept between calls.
#pragma once

#include <memory>

#include "exact.hpp"

namespace mk {

template <class T>
struct Buf {
  std::unique_ptr<T[]> p;
  explicit Buf(i64 n) : p(new T[n > 0 ? n : 1]) {}
  T* data() { return p.get(); }
};

// f(W&) with this thread's W, kept between calls so that its buffers are reused, and
// dropped after a call that left it large(W) (a large call does not pin its memory); a
// fresh W when called re-entrantly. On the heap: an object in thread-local storage would
// cost a TLS lookup at every use of its members in code specialized for it. (The slot is
// per type W: every call site of one workspace type shares it.)
template <class W>
std::unique_ptr<W>& thread_slot() {
  thread_local std::unique_ptr<W> w;
  return w;
}
template <class W>
bool& thread_busy() {
  thread_local bool busy = false;
  return busy;
}
template <class W, class Large, class F>
inline auto with_thread_workspace(Large&& large, F&& f) {
  if (thread_busy<W>()) {
    auto tmp = std::make_unique<W>();
    return f(*tmp);
  }
  struct Guard {
    Large& large;
    ~Guard() {
      std::unique_ptr<W>& w = thread_slot<W>();
      thread_busy<W>() = false;
      if (w && large(*w)) w.reset();
    }
  } guard{large};
  thread_busy<W>() = true;
  std::unique_ptr<W>& w = thread_slot<W>();
  if (!w) w = std::make_unique<W>();
  return f(*w);
}

}  // namespace mk
