// Number types and polynomial types used throughout Bezoutian.
//
// The default arithmetic is exact and GMP based: CGAL::Gmpz for integers and
// CGAL::Gmpq for rationals, bundled by CGAL::GMP_arithmetic_kernel (chosen over
// CGAL's default CORE kernel, see doc/design.md). Polynomials are CGAL's
// recursive CGAL::Polynomial: Polynomial_2<NT> = Polynomial<Polynomial<NT>>,
// whose innermost variable (index 0) is the first parameter (u, s) and whose
// outer variable (index 1) is the second parameter (v, t).
#ifndef BEZOUTIAN_ARITHMETIC_NUMBER_TYPES_H
#define BEZOUTIAN_ARITHMETIC_NUMBER_TYPES_H

#include <CGAL/Gmpz.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Polynomial.h>
#include <CGAL/Polynomial_traits_d.h>
#include <CGAL/Polynomial_type_generator.h>

#include <vector>

namespace bezoutian {

/// Exact integers (GMP).
using Integer = CGAL::Gmpz;
/// Exact rationals (GMP); the default field type of all geometric objects.
using Rational = CGAL::Gmpq;

/// Univariate polynomial over NT.
template <class NT> using Polynomial_1 = CGAL::Polynomial<NT>;
/// Bivariate polynomial over NT; variable 0 is the inner one.
template <class NT> using Polynomial_2 = CGAL::Polynomial<CGAL::Polynomial<NT>>;

namespace internal {

/// A copy of p with CGAL handles of its own. CGAL::Polynomial (CGAL 5.5: Handle_with_policy) counts references
/// with a plain integer, so one handle copied or destroyed by several threads is a data race; the coefficients
/// (CGAL::Gmpz, CGAL::Gmpq: Handle_for) count atomically when CGAL_HAS_THREADS is defined (CGAL/config.h defines it
/// when Boost detects threads). Results that hold polynomials copy them this way, so that one result may be copied
/// from several threads.
template <class NT>
Polynomial_1<NT> unshared_copy(const Polynomial_1<NT>& p) {
  return Polynomial_1<NT>(p.begin(), p.end());
}

template <class NT>
Polynomial_2<NT> unshared_copy(const Polynomial_2<NT>& p) {
  std::vector<Polynomial_1<NT>> c;
  c.reserve(std::size_t(p.degree() + 1));
  for (auto it = p.begin(); it != p.end(); ++it) c.push_back(unshared_copy(*it));
  return Polynomial_2<NT>(c.begin(), c.end());
}

}  // namespace internal

} // namespace bezoutian

#endif // BEZOUTIAN_ARITHMETIC_NUMBER_TYPES_H
