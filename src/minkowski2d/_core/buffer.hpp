// buffer.hpp -- uninitialized scratch (std::vector would zero it: for 2^20 vertices that
// memset costs more than the merge; untouched pages of a large new[] are never even
// faulted in).
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

}  // namespace mk
