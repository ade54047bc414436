// filter.hpp -- exact.hpp's float filter for the sign of a 2x2 determinant, on its own:
// for the loops that select on it without a branch (the boundary walk of collision.hpp)
// or that only skip work on a certain answer (the tangent pre-filter of planning.hpp).
// The rule is exact.hpp's cross_sign, unchanged: with l, r the two float products,
// l - r has its sign when |l - r| > ERRBOUND (|l| + |r|) and that bound is at least
// MINBOUND (no product can have underflowed); an infinite or NaN bound certifies nothing.
// When `certain` is false the caller takes exact.hpp's cross_sign.
#pragma once

#include <cmath>

#include "exact.hpp"

namespace mk {

struct FilterSign {
  int sign;      // the sign of the float l - r
  bool certain;  // whether the filter certifies it (then it is the exact sign)
};

[[gnu::always_inline]] inline FilterSign filter_sign(double l, double r) {
  const double det = l - r, bnd = ERRBOUND * (std::fabs(l) + std::fabs(r));
  return {(det > 0.0) - (det < 0.0), (bnd >= MINBOUND) & (std::fabs(det) > bnd)};
}

}  // namespace mk
