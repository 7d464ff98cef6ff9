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

namespace bezoutian {

/// Exact integers (GMP).
using Integer = CGAL::Gmpz;
/// Exact rationals (GMP); the default field type of all geometric objects.
using Rational = CGAL::Gmpq;

/// Univariate polynomial over NT.
template <class NT> using Polynomial_1 = CGAL::Polynomial<NT>;
/// Bivariate polynomial over NT; variable 0 is the inner one.
template <class NT> using Polynomial_2 = CGAL::Polynomial<CGAL::Polynomial<NT>>;

} // namespace bezoutian

#endif // BEZOUTIAN_ARITHMETIC_NUMBER_TYPES_H
