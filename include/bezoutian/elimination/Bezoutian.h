// The generalized Bezoutian of n+1 polynomials in n variables
// (buse-elkadi-galligo-2008 Definition 1, formula (2)), its Bezoutian matrix,
// and a maximal nonsingular minor of that matrix when it is not square.
//
// Coefficients live in any commutative ring R (Rational, Integer, or
// polynomials in free parameters such as Polynomial_2<Rational>), so the
// determinant of a maximal minor is a multiple of the generalized resultant
// of the system with respect to the variables (seed §2).
#ifndef BEZOUTIAN_ELIMINATION_BEZOUTIAN_H
#define BEZOUTIAN_ELIMINATION_BEZOUTIAN_H

#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/elimination/internal/sparse_polynomial.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace bezoutian {

using internal::Exponent_vector;
using internal::Sparse_polynomial;

/// Divided difference of formula (2):
///   d_i f(x, y) = ( f(y_1..y_{i-1}, x_i, x_{i+1}..x_n) - f(y_1..y_i, x_{i+1}..x_n) ) / (x_i - y_i),
/// for f in the n variables x (indices 0..n-1) and i in 1..n. The result is a
/// polynomial in 2n variables (x_1..x_n, y_1..y_n) = indices (0..n-1, n..2n-1).
/// Exact, monomial by monomial: (x^a - y^a)/(x - y) = sum_{p+q=a-1} x^p y^q.
template <class R>
Sparse_polynomial<R> divided_difference(const Sparse_polynomial<R>& f, std::size_t i) {
  const std::size_t n = f.number_of_variables();
  if (i < 1 || i > n) throw Invalid_input("divided_difference: variable index out of range");
  const std::size_t k = i - 1;  // 0-based index of the variable x_i
  Sparse_polynomial<R> r(2 * n);
  for (const auto& t : f.terms()) {
    const Exponent_vector& a = t.first;
    if (a[k] == 0) continue;
    Exponent_vector e(2 * n, 0);
    for (std::size_t j = 0; j < k; ++j) e[n + j] = a[j];      // y_1..y_{i-1}
    for (std::size_t j = k + 1; j < n; ++j) e[j] = a[j];      // x_{i+1}..x_n
    for (int p = 0; p < a[k]; ++p) {                           // x_i^p y_i^(a-1-p)
      e[k] = p;
      e[n + k] = a[k] - 1 - p;
      r.add_term(e, t.second);
    }
  }
  return r;
}

/// Generalized Bezoutian Bez_{f_0..f_n}(x; y) of formula (2) (buse-elkadi-galligo-2008
/// Definition 1): the determinant of the (n+1) x (n+1) matrix whose row j is
/// ( f_j(x), d_1 f_j(x,y), ..., d_n f_j(x,y) ). Input: n+1 polynomials in the same
/// n variables x_1..x_n. Output: a polynomial in 2n variables, x at indices
/// 0..n-1 and y at indices n..2n-1.
template <class R>
Sparse_polynomial<R> generalized_bezoutian(const std::vector<Sparse_polynomial<R>>& f) {
  if (f.empty()) throw Invalid_input("generalized_bezoutian: no polynomials");
  const std::size_t n = f.front().number_of_variables();
  if (f.size() != n + 1)
    throw Invalid_input("generalized_bezoutian: need n+1 polynomials in n variables");
  for (const auto& fj : f)
    if (fj.number_of_variables() != n)
      throw Invalid_input("generalized_bezoutian: polynomials in different numbers of variables");
  std::vector<std::size_t> x_positions(n);
  for (std::size_t j = 0; j < n; ++j) x_positions[j] = j;
  std::vector<std::vector<Sparse_polynomial<R>>> m(n + 1);
  for (std::size_t j = 0; j <= n; ++j) {
    m[j].push_back(f[j].embed(2 * n, x_positions));
    for (std::size_t i = 1; i <= n; ++i) m[j].push_back(divided_difference(f[j], i));
  }
  return internal::small_determinant(m, Sparse_polynomial<R>(2 * n),
                                     Sparse_polynomial<R>::constant(2 * n, R(1)));
}

/// A Bezoutian matrix in the sense of Definition 1: entry (r, c) is the
/// coefficient c_{alpha,beta} of x^alpha y^beta in Bez(x; y) with
/// y^beta = row_monomials[r] and x^alpha = column_monomials[c]
/// (rows indexed by y, columns by x, as in the seed). Both monomial lists are
/// sorted lexicographically (x_1, resp. y_1, most significant).
template <class R>
struct Generalized_bezoutian_matrix {
  std::vector<std::vector<R>> entries;
  std::vector<Exponent_vector> row_monomials;     ///< exponents of y = (y_1..y_n)
  std::vector<Exponent_vector> column_monomials;  ///< exponents of x = (x_1..x_n)
  std::size_t rows() const { return row_monomials.size(); }
  std::size_t columns() const { return column_monomials.size(); }
  bool is_square() const { return rows() == columns(); }
};

/// Coefficient matrix of a polynomial in 2n variables (x at 0..n-1, y at n..2n-1):
/// rows = y-monomials present, columns = x-monomials present (Definition 1).
/// It has no null row and no null column.
template <class R>
Generalized_bezoutian_matrix<R> bezoutian_coefficient_matrix(const Sparse_polynomial<R>& bez) {
  const std::size_t nn = bez.number_of_variables();
  if (nn % 2 != 0) throw Invalid_input("bezoutian_coefficient_matrix: odd number of variables");
  const std::size_t n = nn / 2;
  std::map<Exponent_vector, std::size_t> rows, cols;
  for (const auto& t : bez.terms()) {
    cols.emplace(Exponent_vector(t.first.begin(), t.first.begin() + n), 0);
    rows.emplace(Exponent_vector(t.first.begin() + n, t.first.end()), 0);
  }
  Generalized_bezoutian_matrix<R> b;
  for (auto& r : rows) { r.second = b.row_monomials.size(); b.row_monomials.push_back(r.first); }
  for (auto& c : cols) { c.second = b.column_monomials.size(); b.column_monomials.push_back(c.first); }
  b.entries.assign(b.rows(), std::vector<R>(b.columns(), R(0)));
  for (const auto& t : bez.terms()) {
    const std::size_t c = cols[Exponent_vector(t.first.begin(), t.first.begin() + n)];
    const std::size_t r = rows[Exponent_vector(t.first.begin() + n, t.first.end())];
    b.entries[r][c] = t.second;
  }
  return b;
}

/// Bezoutian matrix of f_0..f_n (Definition 1).
template <class R>
Generalized_bezoutian_matrix<R> bezoutian_matrix(const std::vector<Sparse_polynomial<R>>& f) {
  return bezoutian_coefficient_matrix(generalized_bezoutian(f));
}

namespace internal {

// Evaluation of ring elements at a point of the parameter space, used to find
// a nonsingular minor: a minor whose value at a point is nonzero is a nonzero
// element of R, whatever the point.
inline Rational evaluate_at(const Rational& c, const std::vector<Rational>&) { return c; }
inline Rational evaluate_at(const Integer& c, const std::vector<Rational>&) { return Rational(c); }
template <class T>
Rational evaluate_at(const CGAL::Polynomial<T>& p, const std::vector<Rational>& point) {
  // The outermost variable of CGAL::Polynomial<T> has index d-1 (d = number of variables).
  const int d = CGAL::Polynomial_traits_d<CGAL::Polynomial<T>>::d;
  if (static_cast<int>(point.size()) < d) throw Invalid_input("evaluate_at: point has too few coordinates");
  Rational value(0);
  for (int i = p.degree(); i >= 0; --i) value = value * point[d - 1] + evaluate_at(p[i], point);
  return value;
}

// Rank of a rational matrix by Gaussian elimination with pivot search; fills the
// pivot rows and columns (a nonsingular minor of maximal size).
inline std::size_t rational_rank(std::vector<std::vector<Rational>> a, std::vector<std::size_t>& pivot_rows,
                                 std::vector<std::size_t>& pivot_columns) {
  const std::size_t nr = a.size(), nc = nr == 0 ? 0 : a[0].size();
  std::vector<std::size_t> row_id(nr);
  for (std::size_t i = 0; i < nr; ++i) row_id[i] = i;
  pivot_rows.clear();
  pivot_columns.clear();
  std::size_t r = 0;
  for (std::size_t c = 0; c < nc && r < nr; ++c) {
    std::size_t p = r;
    while (p < nr && CGAL::is_zero(a[p][c])) ++p;
    if (p == nr) continue;
    std::swap(a[p], a[r]);
    std::swap(row_id[p], row_id[r]);
    for (std::size_t i = r + 1; i < nr; ++i) {
      if (CGAL::is_zero(a[i][c])) continue;
      const Rational f = a[i][c] / a[r][c];
      for (std::size_t j = c; j < nc; ++j) a[i][j] -= f * a[r][j];
    }
    pivot_rows.push_back(row_id[r]);
    pivot_columns.push_back(c);
    ++r;
  }
  std::sort(pivot_rows.begin(), pivot_rows.end());
  return r;
}

} // namespace internal

/// A maximal nonsingular square submatrix of a Bezoutian matrix whose entries are
/// rational numbers or (nested) CGAL polynomials in free parameters.
/// The rank is computed over Q at `trials` pseudo-random rational parameter
/// points; the minor returned is certainly nonsingular (its determinant is
/// nonzero at one of those points), and maximal unless every trial point lies
/// on the (proper) subvariety where the rank drops. The seed (§2) says the
/// determinant of a maximal minor is a multiple of the generalized resultant.
/// Rows and columns keep their relative order; a square matrix of full rank is
/// returned unchanged.
template <class R>
Generalized_bezoutian_matrix<R> maximal_nonsingular_minor(const Generalized_bezoutian_matrix<R>& b,
                                                          int trials = 3) {
  std::vector<std::size_t> best_rows, best_cols;
  std::uint64_t state = 0x9e3779b97f4a7c15ULL;
  for (int trial = 0; trial < std::max(trials, 1); ++trial) {
    std::vector<Rational> point;
    for (int i = 0; i < 8; ++i) {  // parameters: small pseudo-random rationals
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      const int num = static_cast<int>((state >> 33) % 2001) - 1000;
      const int den = static_cast<int>((state >> 13) % 97) + 1;
      point.push_back(Rational(num, den));
    }
    std::vector<std::vector<Rational>> a(b.rows(), std::vector<Rational>(b.columns()));
    for (std::size_t i = 0; i < b.rows(); ++i)
      for (std::size_t j = 0; j < b.columns(); ++j) a[i][j] = internal::evaluate_at(b.entries[i][j], point);
    std::vector<std::size_t> rows, cols;
    internal::rational_rank(a, rows, cols);
    if (rows.size() > best_rows.size()) { best_rows = rows; best_cols = cols; }
    if (best_rows.size() == std::min(b.rows(), b.columns())) break;
  }
  Generalized_bezoutian_matrix<R> m;
  for (std::size_t r : best_rows) m.row_monomials.push_back(b.row_monomials[r]);
  for (std::size_t c : best_cols) m.column_monomials.push_back(b.column_monomials[c]);
  for (std::size_t r : best_rows) {
    std::vector<R> row;
    for (std::size_t c : best_cols) row.push_back(b.entries[r][c]);
    m.entries.push_back(row);
  }
  return m;
}

} // namespace bezoutian

#endif // BEZOUTIAN_ELIMINATION_BEZOUTIAN_H
