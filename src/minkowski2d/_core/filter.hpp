// filter.hpp -- exact.hpp's float filter for the sign of a 2x2 determinant, on its own:
// for the loops that select on it without a branch (the boundary walk of collision.hpp),
// and its form for a pre-test on two signs (the tangent pre-filter of planning.hpp).
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

// Whether l1 - r1 and l2 - r2 certainly have opposite signs, for a vectorized pre-test
// that only skips work on a certain answer (planning.hpp's tangent pre-filter). The same
// bound without the MINBOUND test, which is vacuous under its precondition: every
// coordinate 0 or in [2^-400, 2^400], or an int of at most 2^53 (so a nonzero product of
// differences is at least 2^-904 and none underflows; NaN certifies nothing). Measured:
// the test costs the visibility graph's build about 5%, for no change in any result.
[[gnu::always_inline]] inline bool filter_apart(double l1, double r1, double l2, double r2) {
  const double d1 = l1 - r1, b1 = ERRBOUND * (std::fabs(l1) + std::fabs(r1));
  const double d2 = l2 - r2, b2 = ERRBOUND * (std::fabs(l2) + std::fabs(r2));
  return ((d1 > b1) & (-d2 > b2)) | ((-d1 > b1) & (d2 > b2));
}

}  // namespace mk
