// Double-double numbers (an unevaluated sum hi + lo of two doubles) and their error-free transformations:
// two_sum, and two_prod by fma, exact whether the fma is a hardware instruction or glibc's correctly rounded one;
// the relative error of a product (dd_mul) or sum (dd_add) is below 8 u^2, u = 2^-53. Used where double precision
// has lost too much and an exact or MPFI computation costs too much (double_double_bernstein.h).
#ifndef BEZOUTIAN_ARITHMETIC_DOUBLE_DOUBLE_H
#define BEZOUTIAN_ARITHMETIC_DOUBLE_DOUBLE_H

#include <cmath>

namespace bezoutian {
namespace internal {

struct Double_double {
  double hi = 0, lo = 0;
};

inline Double_double two_sum(double a, double b) {
  const double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}
inline Double_double fast_two_sum(double a, double b) {  // |a| >= |b| (or a == 0)
  const double s = a + b;
  return {s, b - (s - a)};
}
inline Double_double dd_mul(const Double_double& x, const Double_double& y) {
  const double p = x.hi * y.hi;
  double e = std::fma(x.hi, y.hi, -p);
  e += x.hi * y.lo + x.lo * y.hi;
  return fast_two_sum(p, e);
}
inline Double_double dd_add(const Double_double& x, const Double_double& y) {
  Double_double s = two_sum(x.hi, y.hi);
  const Double_double t = two_sum(x.lo, y.lo);
  s.lo += t.hi;
  s = fast_two_sum(s.hi, s.lo);
  s.lo += t.lo;
  return fast_two_sum(s.hi, s.lo);
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_ARITHMETIC_DOUBLE_DOUBLE_H
