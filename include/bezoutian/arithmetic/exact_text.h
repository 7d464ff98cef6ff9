// Exact text of numbers and polynomials: "p/q" rationals, exact decimals, and polynomials as "c*u^a*v^b" terms.
// The readers of io/ parse exactly these forms back (io/Exact_number.h, io/Polynomial_expression.h); the
// diagnostics of the geometry stage (weight validity, degeneracy) print with them.
#ifndef BEZOUTIAN_ARITHMETIC_EXACT_TEXT_H
#define BEZOUTIAN_ARITHMETIC_EXACT_TEXT_H

#include <bezoutian/arithmetic/number_types.h>

#include <gmp.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace bezoutian {
namespace io {

/// Sparse polynomial in k variables: exponent vector (one entry per variable) -> nonzero coefficient.
using Sparse_polynomial = std::map<std::vector<int>, Rational>;

namespace internal {
inline std::string mpz_to_string(const mpz_t z) {
  std::string s(mpz_sizeinbase(z, 10) + 2, '\0');
  mpz_get_str(&s[0], 10, z);
  s.resize(std::char_traits<char>::length(s.c_str()));
  return s;
}
} // namespace internal

/// Exact text of q: "p" for an integer, else "p/q" in lowest terms (what parse_exact_number reads back).
inline std::string to_exact_string(const Rational& q) {
  std::string s = internal::mpz_to_string(mpq_numref(q.mpq()));
  if (mpz_cmp_ui(mpq_denref(q.mpq()), 1) != 0) s += "/" + internal::mpz_to_string(mpq_denref(q.mpq()));
  return s;
}

/// True if q has a finite decimal expansion (its reduced denominator is 2^a 5^b).
inline bool has_finite_decimal_expansion(const Rational& q) {
  Integer d(mpq_denref(q.mpq()));
  mpz_tdiv_q_2exp(d.mpz(), d.mpz(), mpz_scan1(d.mpz(), 0));
  while (mpz_divisible_ui_p(d.mpz(), 5)) mpz_divexact_ui(d.mpz(), d.mpz(), 5);
  return mpz_cmp_ui(d.mpz(), 1) == 0;
}

/// Exact decimal text of q when it has a finite decimal expansion ("0.784", "-2.53125", "12"),
/// otherwise the "p/q" text of to_exact_string (1/3 has no finite decimal expansion).
inline std::string to_exact_decimal_string(const Rational& q) {
  if (!has_finite_decimal_expansion(q)) return to_exact_string(q);
  Integer num(mpq_numref(q.mpq())), den(mpq_denref(q.mpq()));
  const unsigned long a = mpz_scan1(den.mpz(), 0);  // den = 2^a 5^b
  unsigned long b = 0;
  {
    Integer d = den;
    mpz_tdiv_q_2exp(d.mpz(), d.mpz(), a);
    while (mpz_cmp_ui(d.mpz(), 1) != 0) {
      mpz_divexact_ui(d.mpz(), d.mpz(), 5);
      ++b;
    }
  }
  const unsigned long k = a > b ? a : b;  // q = num * 2^(k-a) 5^(k-b) / 10^k
  Integer scale;
  mpz_ui_pow_ui(scale.mpz(), 2, k - a);
  num = num * scale;
  mpz_ui_pow_ui(scale.mpz(), 5, k - b);
  num = num * scale;
  const bool negative = mpz_sgn(num.mpz()) < 0;
  mpz_abs(num.mpz(), num.mpz());
  std::string digits = internal::mpz_to_string(num.mpz());
  if (k > 0) {
    if (digits.size() <= k) digits.insert(0, k + 1 - digits.size(), '0');
    digits.insert(digits.size() - k, ".");
  }
  return negative ? "-" + digits : digits;
}

namespace internal {
// "c*u^a*v^b" terms, highest total degree first; exact "p/q" coefficients that the parser reads back.
inline std::string sparse_to_string(const Sparse_polynomial& p, const std::vector<std::string>& vars) {
  if (p.empty()) return "0";
  std::vector<std::pair<std::vector<int>, Rational>> terms(p.begin(), p.end());
  std::stable_sort(terms.begin(), terms.end(), [](const auto& a, const auto& b) {
    int da = 0, db = 0;
    for (int e : a.first) da += e;
    for (int e : b.first) db += e;
    if (da != db) return da > db;
    return a.first > b.first;
  });
  std::string out;
  for (std::size_t i = 0; i < terms.size(); ++i) {
    Rational c = terms[i].second;
    const bool negative = CGAL::is_negative(c);
    if (negative) c = -c;
    out += i == 0 ? (negative ? "-" : "") : (negative ? " - " : " + ");
    std::string monomial;
    for (std::size_t k = 0; k < vars.size(); ++k) {
      const int e = terms[i].first[k];
      if (e == 0) continue;
      if (!monomial.empty()) monomial += "*";
      monomial += vars[k];
      if (e > 1) monomial += "^" + std::to_string(e);
    }
    if (monomial.empty())
      out += to_exact_string(c);
    else if (c == Rational(1))
      out += monomial;
    else
      out += to_exact_string(c) + "*" + monomial;
  }
  return out;
}
} // namespace internal

/// Exact text of a univariate polynomial in `variable`, e.g. "3/4*t^2 - t + 1" (read back by parse_polynomial_1).
inline std::string polynomial_to_string(const Polynomial_1<Rational>& p, const std::string& variable) {
  Sparse_polynomial s;
  if (!CGAL::is_zero(p))
    for (int i = 0; i <= p.degree(); ++i)
      if (!CGAL::is_zero(p[i])) s[{i}] = p[i];
  return internal::sparse_to_string(s, {variable});
}

/// Exact text of a bivariate polynomial with inner variable u and outer variable v.
inline std::string polynomial_to_string(const Polynomial_2<Rational>& p, const std::string& u, const std::string& v) {
  Sparse_polynomial s;
  if (!CGAL::is_zero(p))
    for (int b = 0; b <= p.degree(); ++b)
      if (!CGAL::is_zero(p[b]))
        for (int a = 0; a <= p[b].degree(); ++a)
          if (!CGAL::is_zero(p[b][a])) s[{a, b}] = p[b][a];
  return internal::sparse_to_string(s, {u, v});
}

} // namespace io
} // namespace bezoutian

#endif // BEZOUTIAN_ARITHMETIC_EXACT_TEXT_H
