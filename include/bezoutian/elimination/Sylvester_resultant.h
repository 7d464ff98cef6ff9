// The Sylvester matrix and resultant of two univariate polynomials and of two
// bivariate homogeneous polynomials (binary forms), du-1989 §3.2.2 eq. 3.8/3.9.
//
// Conventions: for P1 = sum_{i<=d1} a_i x1^i x2^{d1-i} and
// P2 = sum_{j<=d2} b_j x1^j x2^{d2-j}, the (d1+d2) x (d1+d2) Sylvester matrix S
// has d2 rows holding the coefficients of x1^{d2-1-r} x2^r P1 (r = 0..d2-1) and
// then d1 rows for x1^{d1-1-r} x2^r P2, in the columns x1^{d1+d2-1}, ...,
// x2^{d1+d2-1} (descending powers of x1): the first row is (a_{d1}, ..., a_0, 0, ...).
// det S is the resultant; for univariate f, g (x1 = t, x2 = 1) with their
// actual degrees it is CGAL's Resultant: Res(f, g) = lc(f)^{deg g} prod_{f(x)=0} g(x).
// The resultant of binary forms vanishes iff they have a common projective
// zero (x1 : x2) (du-1989 Theorem 3.3), including (1 : 0) when a_{d1} = b_{d2} = 0.
#ifndef BEZOUTIAN_ELIMINATION_SYLVESTER_RESULTANT_H
#define BEZOUTIAN_ELIMINATION_SYLVESTER_RESULTANT_H

#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/elimination/exact_linear_algebra.h>
#include <bezoutian/arithmetic/number_types.h>

#include <cstddef>
#include <vector>

namespace bezoutian {

namespace internal {

/// Coefficient list (a_0, ..., a_d) of a univariate polynomial read with formal degree d.
template <class NT>
std::vector<NT> coefficients_with_formal_degree(const Polynomial_1<NT>& f, int d, const char* who) {
  if (d < 0) throw Invalid_input(std::string(who) + ": negative formal degree");
  if (!CGAL::is_zero(f) && f.degree() > d)
    throw Invalid_input(std::string(who) + ": the formal degree is smaller than the degree of the polynomial");
  std::vector<NT> a(std::size_t(d) + 1, NT(0));
  if (!CGAL::is_zero(f))
    for (int i = 0; i <= f.degree(); ++i) a[i] = f[i];
  return a;
}

/// Sylvester matrix of coefficient lists a (degree d1 = a.size()-1) and b.
template <class NT>
std::vector<std::vector<NT>> sylvester_matrix_from_coefficients(const std::vector<NT>& a, const std::vector<NT>& b) {
  const int d1 = int(a.size()) - 1, d2 = int(b.size()) - 1, n = d1 + d2;
  std::vector<std::vector<NT>> S(n, std::vector<NT>(n, NT(0)));
  for (int r = 0; r < d2; ++r)
    for (int i = 0; i <= d1; ++i) S[r][r + d1 - i] = a[i];  // column c holds x1^{n-1-c}
  for (int r = 0; r < d1; ++r)
    for (int j = 0; j <= d2; ++j) S[d2 + r][r + d2 - j] = b[j];
  return S;
}

/// Coefficients (a_0 .. a_d) of a binary form P(x1, x2) = sum a_i x1^i x2^{d-i},
/// x1 the inner variable (index 0), x2 the outer one (index 1); d = total degree.
template <class NT>
std::vector<NT> binary_form_coefficients(const Polynomial_2<NT>& P, const char* who) {
  if (CGAL::is_zero(P)) throw Invalid_input(std::string(who) + ": the zero polynomial has no degree as a form");
  int d = -1;
  for (int j = 0; j <= P.degree(); ++j) {
    const Polynomial_1<NT>& c = P[j];  // coefficient of x2^j
    if (CGAL::is_zero(c)) continue;
    for (int i = 0; i <= c.degree(); ++i) {
      if (CGAL::is_zero(c[i])) continue;
      if (d < 0) d = i + j;
      if (i + j != d) throw Invalid_input(std::string(who) + ": the polynomial is not homogeneous");
    }
  }
  std::vector<NT> a(std::size_t(d) + 1, NT(0));
  for (int j = 0; j <= P.degree() && j <= d; ++j) {
    const Polynomial_1<NT>& c = P[j];
    if (!CGAL::is_zero(c) && d - j <= c.degree()) a[d - j] = c[d - j];
  }
  return a;
}

} // namespace internal

/// Sylvester matrix of f and g read as polynomials of formal degrees df >= deg f
/// and dg >= deg g (default: their degrees; the zero polynomial has degree 0),
/// du-1989 eq. 3.9 with x1 = t, x2 = 1: size df + dg, first row (f_df, ..., f_0, 0, ...).
template <class NT>
std::vector<std::vector<NT>> sylvester_matrix(const Polynomial_1<NT>& f, const Polynomial_1<NT>& g, int df = -1,
                                              int dg = -1) {
  if (df < 0) df = CGAL::is_zero(f) ? 0 : f.degree();
  if (dg < 0) dg = CGAL::is_zero(g) ? 0 : g.degree();
  return internal::sylvester_matrix_from_coefficients(internal::coefficients_with_formal_degree(f, df, "sylvester_matrix"),
                                                      internal::coefficients_with_formal_degree(g, dg, "sylvester_matrix"));
}

/// Sylvester resultant det S of f and g with their actual degrees; equals
/// CGAL's resultant. The zero polynomial gives 0.
template <class NT>
NT sylvester_resultant(const Polynomial_1<NT>& f, const Polynomial_1<NT>& g) {
  if (CGAL::is_zero(f) || CGAL::is_zero(g)) return NT(0);
  return internal::exact_determinant(sylvester_matrix(f, g));
}

/// Sylvester matrix of two binary forms P1, P2 (homogeneous bivariate
/// polynomials, x1 = variable 0, x2 = variable 1; degrees = total degrees),
/// du-1989 eq. 3.8/3.9. Throws Invalid_input if a form is zero or not homogeneous.
template <class NT>
std::vector<std::vector<NT>> homogeneous_sylvester_matrix(const Polynomial_2<NT>& P1, const Polynomial_2<NT>& P2) {
  return internal::sylvester_matrix_from_coefficients(
      internal::binary_form_coefficients(P1, "homogeneous_sylvester_matrix"),
      internal::binary_form_coefficients(P2, "homogeneous_sylvester_matrix"));
}

/// Resultant of two binary forms: det of `homogeneous_sylvester_matrix`. It
/// vanishes iff P1 and P2 have a common zero in the projective line, and is
/// normalized by Res(x1^{d1}, x2^{d2}) = 1 (as the Macaulay resultant).
template <class NT>
NT homogeneous_sylvester_resultant(const Polynomial_2<NT>& P1, const Polynomial_2<NT>& P2) {
  return internal::exact_determinant(homogeneous_sylvester_matrix(P1, P2));
}

/// Functor forms.
struct Sylvester_resultant {
  template <class NT>
  NT operator()(const Polynomial_1<NT>& f, const Polynomial_1<NT>& g) const {
    return sylvester_resultant(f, g);
  }
};
struct Homogeneous_sylvester_resultant {
  template <class NT>
  NT operator()(const Polynomial_2<NT>& P1, const Polynomial_2<NT>& P2) const {
    return homogeneous_sylvester_resultant(P1, P2);
  }
};

} // namespace bezoutian

#endif // BEZOUTIAN_ELIMINATION_SYLVESTER_RESULTANT_H
