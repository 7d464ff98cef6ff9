// Conversions between bezoutian::Algebraic_real and the real algebraic
// numbers of CGAL::Algebraic_kernel_d_1<CGAL::Gmpz> (GMP arithmetic kernel),
// used to cross-check our root isolation against CGAL's.
//
// This is the ONLY Bezoutian header that includes CGAL/Algebraic_kernel_d_1.h
// (heavy to compile); include it only where CGAL's kernel is really needed.
#ifndef BEZOUTIAN_ARRANGEMENT_ALGEBRAIC_KERNEL_INTEROP_H
#define BEZOUTIAN_ARRANGEMENT_ALGEBRAIC_KERNEL_INTEROP_H

#include <bezoutian/algebraic/Algebraic_real.h>
#include <bezoutian/arithmetic/number_types.h>

#include <CGAL/Algebraic_kernel_d_1.h>

#include <type_traits>
#include <utility>

namespace bezoutian {

/// CGAL's univariate algebraic kernel over GMP integers.
using Cgal_algebraic_kernel_1 = CGAL::Algebraic_kernel_d_1<CGAL::Gmpz>;
/// Its real algebraic number type.
using Cgal_algebraic_real_1 = Cgal_algebraic_kernel_1::Algebraic_real_1;

static_assert(std::is_same<Cgal_algebraic_kernel_1::Polynomial_1, Polynomial_1<Integer>>::value,
              "CGAL's kernel polynomial type must be Polynomial_1<Integer>");
static_assert(std::is_same<Cgal_algebraic_kernel_1::Bound, Rational>::value,
              "CGAL's kernel bound type must be Rational (GMP arithmetic kernel)");

/// The same number as a CGAL Algebraic_real_1: built with the kernel's
/// Construct_algebraic_real_1 from the rational value, or from our defining
/// (square-free) polynomial and open isolating interval.
inline Cgal_algebraic_real_1 to_cgal_algebraic_real(const Algebraic_real& a,
                                                    const Cgal_algebraic_kernel_1& ak = Cgal_algebraic_kernel_1()) {
  auto construct = ak.construct_algebraic_real_1_object();
  if (a.is_rational()) return construct(a.rational_value());
  return construct(a.polynomial(), a.lower(), a.upper());
}

/// The same number as a bezoutian::Algebraic_real: CGAL's defining
/// polynomial (Compute_polynomial_1) and an interval isolating the number
/// from the other roots of that polynomial (Isolate_1). Rational numbers come
/// out exact.
inline Algebraic_real from_cgal_algebraic_real(const Cgal_algebraic_real_1& x,
                                               const Cgal_algebraic_kernel_1& ak = Cgal_algebraic_kernel_1()) {
  const Polynomial_1<Integer> p = ak.compute_polynomial_1_object()(x);
  const std::pair<Rational, Rational> iv = ak.isolate_1_object()(x, p);
  return Algebraic_real(p, iv.first, iv.second);
}

/// Exact comparison of our number with CGAL's (through CGAL's Compare_1).
inline int compare_with_cgal(const Algebraic_real& a, const Cgal_algebraic_real_1& x,
                             const Cgal_algebraic_kernel_1& ak = Cgal_algebraic_kernel_1()) {
  return static_cast<int>(ak.compare_1_object()(to_cgal_algebraic_real(a, ak), x));
}

}  // namespace bezoutian

#endif  // BEZOUTIAN_ARRANGEMENT_ALGEBRAIC_KERNEL_INTEROP_H
