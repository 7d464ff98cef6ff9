// A small sparse multivariate polynomial over an arbitrary commutative ring R
// (R = Rational, or R = Polynomial_2<Rational> when the coefficients are
// polynomials in free parameters). It serves the generalized Bezoutian of
// buse-elkadi-galligo-2008 Definition 1, whose expansion needs 2n variables and
// exact divided differences, and the cross-checks of the Bezoutian theorems.
// Not meant for heavy arithmetic: products are naive term-by-term products.
#ifndef BEZOUTIAN_ELIMINATION_INTERNAL_SPARSE_POLYNOMIAL_H
#define BEZOUTIAN_ELIMINATION_INTERNAL_SPARSE_POLYNOMIAL_H

#include <bezoutian/arithmetic/Error.h>

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace bezoutian {
namespace internal {

/// Exponent vector of a monomial x_0^e_0 ... x_{k-1}^e_{k-1}.
using Exponent_vector = std::vector<int>;

/// Sparse polynomial in a fixed number of variables with coefficients in the ring R.
/// Terms are kept in a std::map ordered lexicographically on exponent vectors
/// (x_0 most significant); zero coefficients are never stored.
template <class R>
class Sparse_polynomial {
 public:
  using Coefficient = R;
  using Term_map = std::map<Exponent_vector, R>;

  explicit Sparse_polynomial(std::size_t number_of_variables = 0) : nvars_(number_of_variables) {}

  /// The constant polynomial c in the given number of variables.
  static Sparse_polynomial constant(std::size_t number_of_variables, const R& c) {
    Sparse_polynomial p(number_of_variables);
    p.add_term(Exponent_vector(number_of_variables, 0), c);
    return p;
  }
  /// The monomial c * x^e.
  static Sparse_polynomial monomial(const Exponent_vector& e, const R& c) {
    Sparse_polynomial p(e.size());
    p.add_term(e, c);
    return p;
  }
  /// The variable x_i.
  static Sparse_polynomial variable(std::size_t number_of_variables, std::size_t i) {
    Exponent_vector e(number_of_variables, 0);
    e.at(i) = 1;
    return monomial(e, R(1));
  }

  std::size_t number_of_variables() const { return nvars_; }
  const Term_map& terms() const { return terms_; }
  bool is_zero() const { return terms_.empty(); }
  std::size_t number_of_terms() const { return terms_.size(); }

  /// Adds c * x^e (exact; removes the term if it cancels).
  void add_term(const Exponent_vector& e, const R& c) {
    if (e.size() != nvars_) throw Invalid_input("Sparse_polynomial: exponent vector has the wrong length");
    if (c == R(0)) return;
    auto it = terms_.find(e);
    if (it == terms_.end()) {
      terms_.emplace(e, c);
    } else {
      it->second += c;
      if (it->second == R(0)) terms_.erase(it);
    }
  }

  /// Coefficient of x^e (zero when absent).
  R coefficient(const Exponent_vector& e) const {
    auto it = terms_.find(e);
    return it == terms_.end() ? R(0) : it->second;
  }

  /// Degree in variable i (-1 for the zero polynomial).
  int degree(std::size_t i) const {
    int d = -1;
    for (const auto& t : terms_) d = std::max(d, t.first.at(i));
    return d;
  }

  Sparse_polynomial& operator+=(const Sparse_polynomial& q) {
    check_same(q);
    for (const auto& t : q.terms_) add_term(t.first, t.second);
    return *this;
  }
  Sparse_polynomial& operator-=(const Sparse_polynomial& q) {
    check_same(q);
    for (const auto& t : q.terms_) add_term(t.first, -t.second);
    return *this;
  }
  Sparse_polynomial operator-() const {
    Sparse_polynomial r(nvars_);
    for (const auto& t : terms_) r.terms_.emplace(t.first, -t.second);
    return r;
  }
  friend Sparse_polynomial operator+(Sparse_polynomial p, const Sparse_polynomial& q) { return p += q; }
  friend Sparse_polynomial operator-(Sparse_polynomial p, const Sparse_polynomial& q) { return p -= q; }
  friend Sparse_polynomial operator*(const Sparse_polynomial& p, const Sparse_polynomial& q) {
    p.check_same(q);
    Sparse_polynomial r(p.nvars_);
    Exponent_vector e(p.nvars_);
    for (const auto& a : p.terms_)
      for (const auto& b : q.terms_) {
        for (std::size_t i = 0; i < p.nvars_; ++i) e[i] = a.first[i] + b.first[i];
        r.add_term(e, a.second * b.second);
      }
    return r;
  }
  /// Multiplication by a ring element.
  friend Sparse_polynomial operator*(const R& c, const Sparse_polynomial& p) {
    Sparse_polynomial r(p.nvars_);
    for (const auto& t : p.terms_) r.add_term(t.first, c * t.second);
    return r;
  }
  friend bool operator==(const Sparse_polynomial& p, const Sparse_polynomial& q) {
    return p.nvars_ == q.nvars_ && p.terms_ == q.terms_;
  }
  friend bool operator!=(const Sparse_polynomial& p, const Sparse_polynomial& q) { return !(p == q); }

  /// Re-indexes the variables: variable i of *this becomes variable target[i] of a
  /// polynomial in new_number_of_variables variables.
  Sparse_polynomial embed(std::size_t new_number_of_variables, const std::vector<std::size_t>& target) const {
    if (target.size() != nvars_) throw Invalid_input("Sparse_polynomial::embed: wrong target size");
    Sparse_polynomial r(new_number_of_variables);
    for (const auto& t : terms_) {
      Exponent_vector e(new_number_of_variables, 0);
      for (std::size_t i = 0; i < nvars_; ++i) e.at(target[i]) += t.first[i];
      r.add_term(e, t.second);
    }
    return r;
  }

 private:
  void check_same(const Sparse_polynomial& q) const {
    if (q.nvars_ != nvars_) throw Invalid_input("Sparse_polynomial: mismatched numbers of variables");
  }

  std::size_t nvars_;
  Term_map terms_;
};

/// Division-free determinant of a small square matrix of ring elements by
/// expansion along the rows with memoized minors (indexed by column subsets):
/// O(2^n n) ring operations, exact in any commutative ring. Meant for the
/// (n+1) x (n+1) matrices of formula (2) of buse-elkadi-galligo-2008, n <= ~12.
template <class T>
T small_determinant(const std::vector<std::vector<T>>& a, const T& zero, const T& one) {
  const std::size_t n = a.size();
  for (const auto& row : a)
    if (row.size() != n) throw Invalid_input("small_determinant: matrix is not square");
  if (n == 0) return one;
  if (n > 20) throw Invalid_input("small_determinant: matrix too large for expansion by minors");
  // minors[S] = determinant of the submatrix formed by the last |S| rows and the columns in S.
  std::map<unsigned long, T> current;
  for (std::size_t c = 0; c < n; ++c) current.emplace(1UL << c, a[n - 1][c]);
  for (std::size_t k = 2; k <= n; ++k) {
    const std::size_t row = n - k;
    std::map<unsigned long, T> next;
    for (const auto& entry : current) {
      const unsigned long s = entry.first;
      // Expand the minor on columns s + {c} along row `row`; the sign is given by
      // the position of c among the chosen columns.
      for (std::size_t c = 0; c < n; ++c) {
        if (s & (1UL << c)) continue;
        int before = 0;
        for (std::size_t d = 0; d < c; ++d)
          if (s & (1UL << d)) ++before;
        T term = a[row][c] * entry.second;
        const unsigned long t = s | (1UL << c);
        auto it = next.find(t);
        if (it == next.end()) it = next.emplace(t, zero).first;
        if (before % 2 == 0) it->second += term; else it->second -= term;
      }
    }
    current.swap(next);
  }
  return current.begin()->second;
}

} // namespace internal
} // namespace bezoutian

#endif // BEZOUTIAN_ELIMINATION_INTERNAL_SPARSE_POLYNOMIAL_H
