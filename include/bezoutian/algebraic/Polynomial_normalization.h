// Canonical forms of bivariate integer polynomials, used to compare implicit
// equations and elimination polynomials, which are only defined up to a
// nonzero constant factor (the Bezoutian determinant has an arbitrary sign:
// buse-elkadi-galligo-2008, Theorems 3 and 5 give -D of Theorems 2 and 4).
//
// Convention ("lexicographically leading term"): Polynomial_2<NT> has the
// inner variable u (index 0) and the outer variable v (index 1). The leading
// term of D != 0 is the term u^k v^l with the largest l, and among those the
// largest k; its coefficient is D.lcoeff().lcoeff() in CGAL's recursive
// representation. A normalized polynomial has content 1 (gcd of its integer
// coefficients) and a positive leading coefficient; the zero polynomial is
// its own normal form.
#ifndef BEZOUTIAN_ALGEBRAIC_POLYNOMIAL_NORMALIZATION_H
#define BEZOUTIAN_ALGEBRAIC_POLYNOMIAL_NORMALIZATION_H

#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/algebraic/internal/modular_square_free.h>

#include <vector>

namespace bezoutian {

/// The coefficient of the lexicographically leading term (largest power of
/// v, then of u) of D; 0 for D = 0.
inline Integer lexicographic_leading_coefficient(const Polynomial_2<Integer>& D) {
  return D.lcoeff().lcoeff();
}

/// The gcd of all integer coefficients of D (non-negative; 0 for D = 0).
inline Integer integer_content(const Polynomial_2<Integer>& D) {
  Integer g(0);
  for (const Polynomial_1<Integer>& c : D)
    for (const Integer& x : c) {
      mpz_gcd(g.mpz(), g.mpz(), x.mpz());
      if (g == 1) return g;
    }
  return g;
}

/// D divided by its integer content, with the sign chosen so that the
/// lexicographically leading coefficient (largest power of v, then of u) is
/// positive. Two nonzero integer polynomials are proportional over Q iff their
/// normalized primitive parts are equal. Returns 0 for D = 0.
inline Polynomial_2<Integer> normalized_primitive_part(const Polynomial_2<Integer>& D) {
  if (CGAL::is_zero(D)) return D;
  Integer g = integer_content(D);
  if (CGAL::sign(lexicographic_leading_coefficient(D)) == CGAL::NEGATIVE) g = -g;
  if (g == 1) return D;
  std::vector<Polynomial_1<Integer>> rows;
  rows.reserve(D.degree() + 1);
  for (const Polynomial_1<Integer>& c : D) {
    std::vector<Integer> coeffs;
    coeffs.reserve(c.degree() + 1);
    for (const Integer& x : c) {
      Integer q; // fresh: CGAL::Gmpz copies share their mpz_t
      mpz_divexact(q.mpz(), x.mpz(), g.mpz());
      coeffs.push_back(q);
    }
    rows.emplace_back(coeffs.begin(), coeffs.end());
  }
  return Polynomial_2<Integer>(rows.begin(), rows.end());
}

/// The square-free part of D over Q (the product of its distinct irreducible
/// factors, each once, including factors in u alone), normalized as in
/// `normalized_primitive_part`. Returns 0 for D = 0 and 1 for a nonzero
/// constant.
///
/// D = c(u) P(u,v) with c the content with respect to v; the square-free part
/// is that of c (univariate, CGAL) times that of P. P is usually square-free,
/// which one specialization modulo a prime proves; otherwise a modular
/// algorithm with exact certification is used
/// (internal::square_free_part_of_primitive; bounded number of primes, CGAL's
/// generic algorithm as a last resort, never reached in practice). CGAL's bivariate
/// Make_square_free gives the same answer but is orders of magnitude slower on
/// implicit equations of bi-degree (24,24) and above.
inline Polynomial_2<Integer> normalized_square_free_part(const Polynomial_2<Integer>& D) {
  if (CGAL::is_zero(D)) return D;
  const Polynomial_1<Integer> c = internal::v_content(D);
  Polynomial_2<Integer> P = normalized_primitive_part(c.degree() > 0 ? internal::divide_v_coefficients(D, c) : D);
  if (P.degree() == 0) {
    P = Polynomial_2<Integer>(1);
  } else if (!internal::specialization_proves_no_repeated_v_factor(internal::dense_entry(P))) {
    P = internal::square_free_part_of_primitive(P);
  }
  if (c.degree() > 0) {
    typename CGAL::Polynomial_traits_d<Polynomial_1<Integer>>::Make_square_free make_square_free;
    P *= Polynomial_2<Integer>(make_square_free(c));
  }
  return normalized_primitive_part(P);
}

/// Functor forms.
struct Normalized_primitive_part {
  Polynomial_2<Integer> operator()(const Polynomial_2<Integer>& D) const { return normalized_primitive_part(D); }
};
struct Normalized_square_free_part {
  Polynomial_2<Integer> operator()(const Polynomial_2<Integer>& D) const { return normalized_square_free_part(D); }
};

} // namespace bezoutian

#endif // BEZOUTIAN_ALGEBRAIC_POLYNOMIAL_NORMALIZATION_H
