// exactnum.hpp -- the two number types behind every predicate of higher degree than the
// cross product (the overlay's intersection points; exact.hpp keeps the degree-2 signs).
//
// A predicate is written once, as a template over its number type, and evaluated twice:
//
//  * FE<F> ("filtered"): a float value v with a certified absolute bound e on the
//    distance to the exact value (a running error bound in the style of Fortune and Van
//    Wyk's dynamic filters). Each + - * adds the rounding error of its result, u |v|, and
//    the propagated input errors; a product also adds ETA for underflow. A sign is
//    certain when |v| > e (1 + 2^-40) -- the factor covers the rounding of the bound's
//    own arithmetic for up to 2^12 operations -- and zero is certain only when v == 0
//    with e == 0 (nothing was ever rounded). inf or NaN never certify: an overflowing
//    filter simply defers to the exact evaluation, so no rescaling is ever needed.
//  * Dy ("dyadic"): an exact number +-m 2^k with a multi-limb integer m (at most CAP
//    64-bit limbs, enough for products of five differences of doubles anywhere in the
//    float64 range, subnormals to DBL_MAX). Sums align exponents; products multiply the
//    limbs (schoolbook). Only the rare inputs the filter cannot decide reach it.
//
// Coordinates reach both as DD: an exact sum hi + lo of two doubles, canonical (hi is
// the rounded value of the sum, as TwoSum produces it), so two DD are equal iff both
// parts are, and ordered lexicographically (see dd_less).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "exact.hpp"

namespace mk {

// ------------------------------------------------------------------------------------
// FE: value and certified absolute error bound

template <class F>
struct FEt {
  F v, e;
};

template <class F>
struct FEconst {
  static constexpr F U = std::numeric_limits<F>::epsilon() / 2;       // unit roundoff
  // underflow, per op: at least half the smallest subnormal; a normal number, because a
  // subnormal operand costs a microcode assist (x87 long double: ~100x slower)
  static constexpr F ETA = std::numeric_limits<F>::min() * 4;
  static constexpr F SAFE = F(1) + F(0x1p-40);
};

template <class F>
inline FEt<F> operator+(FEt<F> a, FEt<F> b) {
  F v = a.v + b.v;  // a sum is exact when it underflows: no ETA
  return {v, a.e + b.e + FEconst<F>::U * std::fabs(v)};
}
template <class F>
inline FEt<F> operator-(FEt<F> a, FEt<F> b) {
  F v = a.v - b.v;
  return {v, a.e + b.e + FEconst<F>::U * std::fabs(v)};
}
template <class F>
inline FEt<F> operator-(FEt<F> a) {
  return {-a.v, a.e};
}
template <class F>
inline FEt<F> operator*(FEt<F> a, FEt<F> b) {
  F v = a.v * b.v;
  return {v, std::fabs(a.v) * b.e + std::fabs(b.v) * a.e + a.e * b.e +
                 (FEconst<F>::U * std::fabs(v) + FEconst<F>::ETA)};
}
// a / b; unbounded (e = inf) when b's interval holds zero
template <class F>
inline FEt<F> fe_div(FEt<F> a, FEt<F> b) {
  F bv = std::fabs(b.v), lo = bv - b.e * FEconst<F>::SAFE;
  if (!(lo > 0)) return {F(0), std::numeric_limits<F>::infinity()};
  F v = a.v / b.v;
  F e = (a.e * bv + std::fabs(a.v) * b.e) / (bv * lo);
  return {v, e + (FEconst<F>::U * std::fabs(v) + FEconst<F>::ETA)};
}

// +1 / -1 / 0 when certain, 2 when the filter cannot tell
constexpr int UNSURE = 2;
template <class F>
inline int fe_sign(FEt<F> a) {
  if (std::fabs(a.v) > a.e * FEconst<F>::SAFE + FEconst<F>::ETA) return a.v > 0 ? 1 : -1;
  if (a.v == 0 && a.e == 0) return 0;
  return UNSURE;
}

using FE = FEt<double>;
using FEL = FEt<long double>;

// ------------------------------------------------------------------------------------
// Dy: exact dyadic numbers

struct Dy {
  // 180 limbs hold 11520 bits: a product of five differences of doubles spans at most
  // 5 * (1024 + 1074 + 2) bits, plus the carries of a few sums.
  static constexpr int CAP = 180;
  int n = 0;         // limbs in use (w[n - 1] != 0), 0 for zero
  bool neg = false;  // sign (never set for zero)
  int ex = 0;        // value = (neg ? -1 : 1) * sum(w[i] 2^(64 i)) * 2^ex
  u64 w[CAP];

  Dy() {}
  explicit Dy(double x) { set(x); }
  Dy(const Dy& o) : n(o.n), neg(o.neg), ex(o.ex) { std::memcpy(w, o.w, sizeof(u64) * n); }
  Dy& operator=(const Dy& o) {
    n = o.n;
    neg = o.neg;
    ex = o.ex;
    std::memcpy(w, o.w, sizeof(u64) * n);
    return *this;
  }
  void set(double x) {
    if (x == 0.0) {
      n = 0;
      neg = false;
      ex = 0;
      return;
    }
    detail::Unpacked u = detail::unpack(x);
    int tz = __builtin_ctzll(u.m);
    w[0] = u.m >> tz;
    ex = u.e + tz;
    n = 1;
    neg = u.neg;
  }
  int sign() const { return n == 0 ? 0 : (neg ? -1 : 1); }
};

// Set when a Dy result would need more than CAP limbs (cannot happen for the degree-5
// predicates of the overlay on finite doubles; checked so that a misuse is an error).
inline thread_local bool dy_overflow = false;

namespace detail {

// magnitude compare of m1 * 2^s1 vs m2 (same exponent after shifting m1 left by s bits)
// -- helpers on raw limbs
inline int mag_cmp(const u64* a, int na, const u64* b, int nb) {
  if (na != nb) return na > nb ? 1 : -1;
  for (int i = na - 1; i >= 0; --i)
    if (a[i] != b[i]) return a[i] > b[i] ? 1 : -1;
  return 0;
}

// dst = src << s (bits); returns limbs
inline int shl(const u64* src, int n, int s, u64* dst) {
  if (n == 0) return 0;
  int q = s >> 6, r = s & 63;
  if (n + q + 1 > Dy::CAP) {
    dy_overflow = true;
    q = Dy::CAP - n - 1 > 0 ? Dy::CAP - n - 1 : 0;
  }
  for (int i = 0; i < q; ++i) dst[i] = 0;
  if (r == 0) {
    for (int i = 0; i < n; ++i) dst[q + i] = src[i];
    return n + q;
  }
  u64 carry = 0;
  for (int i = 0; i < n; ++i) {
    u64 v = src[i];
    dst[q + i] = (v << r) | carry;
    carry = v >> (64 - r);
  }
  int m = n + q;
  if (carry) dst[m++] = carry;
  return m;
}

inline int trim(const u64* a, int n) {
  while (n > 0 && a[n - 1] == 0) --n;
  return n;
}

// r = a + b (magnitudes), r may alias neither
inline int mag_add(const u64* a, int na, const u64* b, int nb, u64* r) {
  if (na < nb) {
    const u64* t = a;
    a = b;
    b = t;
    int tn = na;
    na = nb;
    nb = tn;
  }
  u64 carry = 0;
  int i = 0;
  for (; i < nb; ++i) {
    u128 s = (u128)a[i] + b[i] + carry;
    r[i] = (u64)s;
    carry = (u64)(s >> 64);
  }
  for (; i < na; ++i) {
    u128 s = (u128)a[i] + carry;
    r[i] = (u64)s;
    carry = (u64)(s >> 64);
  }
  if (carry) {
    if (na >= Dy::CAP) {
      dy_overflow = true;
      return na;
    }
    r[na++] = carry;
  }
  return na;
}

// r = a - b for |a| >= |b|
inline int mag_sub(const u64* a, int na, const u64* b, int nb, u64* r) {
  u64 borrow = 0;
  int i = 0;
  for (; i < nb; ++i) {
    u64 x = a[i], y = b[i];
    u64 d = x - y - borrow;
    borrow = (x < y) | ((x == y) & borrow);
    r[i] = d;
  }
  for (; i < na; ++i) {
    u64 x = a[i];
    r[i] = x - borrow;
    borrow = x < borrow;
  }
  return trim(r, na);
}

}  // namespace detail

// a + (negb ? -b : b)
inline Dy dy_addsub(const Dy& a, const Dy& b, bool negb) {
  Dy r;
  if (b.n == 0) return a;
  if (a.n == 0) {
    r = b;
    r.neg = b.neg != negb;
    return r;
  }
  bool bneg = b.neg != negb;
  // align to the smaller exponent: shift the other operand left
  u64 tmp[Dy::CAP];
  const u64 *pa = a.w, *pb = b.w;
  int na = a.n, nb = b.n;
  if (a.ex > b.ex) {
    na = detail::shl(a.w, a.n, a.ex - b.ex, tmp);
    pa = tmp;
    r.ex = b.ex;
  } else if (b.ex > a.ex) {
    nb = detail::shl(b.w, b.n, b.ex - a.ex, tmp);
    pb = tmp;
    r.ex = a.ex;
  } else {
    r.ex = a.ex;
  }
  if (a.neg == bneg) {
    r.n = detail::mag_add(pa, na, pb, nb, r.w);
    r.neg = a.neg;
  } else {
    int c = detail::mag_cmp(pa, na, pb, nb);
    if (c == 0) {
      r.n = 0;
      r.neg = false;
      r.ex = 0;
    } else if (c > 0) {
      r.n = detail::mag_sub(pa, na, pb, nb, r.w);
      r.neg = a.neg;
    } else {
      r.n = detail::mag_sub(pb, nb, pa, na, r.w);
      r.neg = bneg;
    }
  }
  // drop low zero limbs (keeps the exponents close, the numbers short)
  if (r.n > 0 && r.w[0] == 0) {
    int z = 0;
    while (r.w[z] == 0) ++z;
    std::memmove(r.w, r.w + z, sizeof(u64) * (r.n - z));
    r.n -= z;
    r.ex += 64 * z;
  }
  return r;
}

inline Dy operator+(const Dy& a, const Dy& b) { return dy_addsub(a, b, false); }
inline Dy operator-(const Dy& a, const Dy& b) { return dy_addsub(a, b, true); }
inline Dy operator-(const Dy& a) {
  Dy r = a;
  if (r.n) r.neg = !r.neg;
  return r;
}

inline Dy operator*(const Dy& a, const Dy& b) {
  Dy r;
  if (a.n == 0 || b.n == 0) return r;
  int n = a.n + b.n;
  if (n > Dy::CAP) {
    dy_overflow = true;
    return r;
  }
  for (int i = 0; i < n; ++i) r.w[i] = 0;
  for (int i = 0; i < a.n; ++i) {
    u64 carry = 0;
    u64 ai = a.w[i];
    for (int j = 0; j < b.n; ++j) {
      u128 t = (u128)ai * b.w[j] + r.w[i + j] + carry;
      r.w[i + j] = (u64)t;
      carry = (u64)(t >> 64);
    }
    r.w[i + b.n] = carry;
  }
  r.n = detail::trim(r.w, n);
  r.neg = a.neg != b.neg;
  r.ex = a.ex + b.ex;
  return r;
}

// sign(a - b)
inline int dy_cmp(const Dy& a, const Dy& b) { return (a - b).sign(); }

// |a| ~ m * 2^e with m in [0.5, 1) (relative error below 2^-62): a starting point for
// exact rounding, never a decision
inline long double dy_approx_frexp(const Dy& a, long& e) {
  if (a.n == 0) {
    e = 0;
    return 0.0L;
  }
  long double v = (long double)a.w[a.n - 1];
  long base = (long)a.ex + 64L * (a.n - 1);
  if (a.n >= 2) {
    v = std::ldexp(v, 64) + (long double)a.w[a.n - 2];
    base -= 64;
  }
  int k;
  long double m = std::frexp(v, &k);
  e = base + k;
  return m;
}

// a * 2^k (exact)
inline Dy dy_ldexp(const Dy& a, int k) {
  Dy r = a;
  if (r.n) r.ex += k;
  return r;
}

}  // namespace mk
