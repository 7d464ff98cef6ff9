// A closed interval of doubles with outward rounding by one ulp per operation: the cheap rigorous enclosure used by
// the floating-point proofs (the phantom exclusion, the partner witnesses, the two-branch certificate).
#ifndef BEZOUTIAN_ARITHMETIC_DOUBLE_INTERVAL_H
#define BEZOUTIAN_ARITHMETIC_DOUBLE_INTERVAL_H

#include <bezoutian/arithmetic/number_types.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

// The operations below are small and on the hot path of every floating-point proof: they are forced inline (GCC
// kept widen a call, 19 % of the samples of the teapot's certification; inlined, teapot 20 x 21 took 1.52-1.75 s
// against 1.71-1.82 s, three runs each: a few per cent, near the machine's noise).
#if defined(__GNUC__)
#define BEZOUTIAN_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define BEZOUTIAN_ALWAYS_INLINE inline
#endif

namespace bezoutian {
namespace internal {

/// A closed interval of doubles with outward rounding: each operation is computed in round-to-nearest and
/// widened by one ulp on each side, which covers its rounding error (a cheap, rigorous enclosure).
struct Double_interval {
  double lo = 0, hi = 0;
  static Double_interval of(const Rational& q) {
    const auto p = CGAL::to_interval(q);
    return {p.first, p.second};
  }
  static Double_interval hull(const Rational& a, const Rational& b) { return {of(a).lo, of(b).hi}; }
  BEZOUTIAN_ALWAYS_INLINE static Double_interval widen(double a, double b) {
    // one ulp outwards covers one rounding to nearest. An end rounded to +-inf on the inside (a lower end +inf,
    // an upper end -inf: an overflow) stands for a finite exact value beyond DBL_MAX: it becomes +-DBL_MAX, so
    // that the enclosure keeps the exact value.
    if (std::isnan(a) || std::isnan(b)) return {-HUGE_VAL, HUGE_VAL};
    const double M = std::numeric_limits<double>::max();
    return {a == HUGE_VAL ? M : next(a, false), b == -HUGE_VAL ? -M : next(b, true)};
  }
  // The neighbouring double towards +infinity (up) or -infinity (std::nextafter without the library call).
  BEZOUTIAN_ALWAYS_INLINE static double next(double x, bool up) {
    if (std::isinf(x)) return x;
    if (x == 0) return up ? std::numeric_limits<double>::denorm_min() : -std::numeric_limits<double>::denorm_min();
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    if ((x > 0) == up)
      ++b;
    else
      --b;
    std::memcpy(&x, &b, sizeof b);
    return x;
  }
  BEZOUTIAN_ALWAYS_INLINE friend Double_interval operator+(const Double_interval& x, const Double_interval& y) {
    return widen(x.lo + y.lo, x.hi + y.hi);
  }
  BEZOUTIAN_ALWAYS_INLINE friend Double_interval operator-(const Double_interval& x, const Double_interval& y) {
    return widen(x.lo - y.hi, x.hi - y.lo);
  }
  BEZOUTIAN_ALWAYS_INLINE friend Double_interval operator*(const Double_interval& x, const Double_interval& y) {
    const double a = x.lo * y.lo, b = x.lo * y.hi, c = x.hi * y.lo, d = x.hi * y.hi;
    if (std::isnan(a) || std::isnan(b) || std::isnan(c) || std::isnan(d)) return {-HUGE_VAL, HUGE_VAL};
    return widen(std::min(std::min(a, b), std::min(c, d)), std::max(std::max(a, b), std::max(c, d)));
  }
  bool contains_zero() const { return !(lo > 0) && !(hi < 0); }
  double mid() const { return 0.5 * (lo + hi); }
};

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_ARITHMETIC_DOUBLE_INTERVAL_H
