// Exact linear algebra over an integral domain R, shared by the classical
// resultant constructions (Bezout, Sylvester, Macaulay, du-1989 §3.2):
//
//  - `bareiss_determinant`: fraction-free Gaussian elimination (Bareiss) with
//    row pivoting; every division is exact (CGAL::integral_division), so it
//    works over Integer, Rational and CGAL polynomial rings over them;
//  - `exact_determinant`: the determinant routed to the best exact method for
//    the entry type: Bareiss for Integer/Rational, the multi-modular
//    `polynomial_matrix_determinant` for univariate/bivariate polynomials over
//    Integer/Rational, and the division-free `berkowitz_determinant` for any
//    other commutative ring (e.g. trivariate polynomials);
//  - `fraction_free_rank`: the rank over the fraction field of R.
#ifndef BEZOUTIAN_ELIMINATION_EXACT_LINEAR_ALGEBRA_H
#define BEZOUTIAN_ELIMINATION_EXACT_LINEAR_ALGEBRA_H

#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/elimination/Polynomial_matrix_determinant.h>
#include <bezoutian/arithmetic/number_types.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace bezoutian {
namespace internal {

template <class R>
std::size_t checked_square_matrix_size(const std::vector<std::vector<R>>& M, const char* who) {
  const std::size_t n = M.size();
  for (const auto& row : M)
    if (row.size() != n) throw Invalid_input(std::string(who) + ": the matrix is not square");
  return n;
}

/// Determinant over an integral domain R with exact division, by Bareiss'
/// fraction-free elimination with row pivoting: after step k, entry (i,j) of
/// the remaining block is the (k+1)x(k+1) minor on the pivot rows/columns and
/// (i,j), so the division by the previous pivot is exact (Sylvester's identity).
/// The 0x0 determinant is 1.
template <class R>
R bareiss_determinant(std::vector<std::vector<R>> A) {
  const std::size_t n = checked_square_matrix_size(A, "bareiss_determinant");
  if (n == 0) return R(1);
  bool negate = false;
  R previous(1);
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t p = k;
    while (p < n && CGAL::is_zero(A[p][k])) ++p;
    if (p == n) return R(0);
    if (p != k) {
      std::swap(A[p], A[k]);
      negate = !negate;
    }
    for (std::size_t i = k + 1; i < n; ++i) {
      for (std::size_t j = k + 1; j < n; ++j)
        A[i][j] = CGAL::integral_division(A[k][k] * A[i][j] - A[i][k] * A[k][j], previous);
      A[i][k] = R(0);
    }
    previous = A[k][k];
  }
  return negate ? R(-A[n - 1][n - 1]) : A[n - 1][n - 1];
}

/// Exact determinant, generic ring: division-free Berkowitz.
template <class R>
R exact_determinant(const std::vector<std::vector<R>>& M) {
  checked_square_matrix_size(M, "exact_determinant");
  return berkowitz_determinant(M);
}
inline Integer exact_determinant(const std::vector<std::vector<Integer>>& M) { return bareiss_determinant(M); }
inline Rational exact_determinant(const std::vector<std::vector<Rational>>& M) { return bareiss_determinant(M); }
inline Polynomial_1<Integer> exact_determinant(const std::vector<std::vector<Polynomial_1<Integer>>>& M) {
  return polynomial_matrix_determinant(M);
}
inline Polynomial_2<Integer> exact_determinant(const std::vector<std::vector<Polynomial_2<Integer>>>& M) {
  return polynomial_matrix_determinant(M);
}
inline Polynomial_1<Rational> exact_determinant(const std::vector<std::vector<Polynomial_1<Rational>>>& M) {
  return polynomial_matrix_determinant(M);
}
inline Polynomial_2<Rational> exact_determinant(const std::vector<std::vector<Polynomial_2<Rational>>>& M) {
  return polynomial_matrix_determinant(M);
}

/// Rank over the fraction field of R of a (possibly rectangular) matrix, by
/// fraction-free elimination with row pivoting (Bareiss; exact divisions).
template <class R>
std::size_t fraction_free_rank(std::vector<std::vector<R>> A) {
  const std::size_t rows = A.size();
  if (rows == 0) return 0;
  const std::size_t cols = A[0].size();
  for (const auto& row : A)
    if (row.size() != cols) throw Invalid_input("fraction_free_rank: rows of different lengths");
  std::size_t rank = 0;
  R previous(1);
  for (std::size_t k = 0; k < cols && rank < rows; ++k) {
    std::size_t p = rank;
    while (p < rows && CGAL::is_zero(A[p][k])) ++p;
    if (p == rows) continue;  // no pivot in this column
    std::swap(A[p], A[rank]);
    for (std::size_t i = rank + 1; i < rows; ++i) {
      for (std::size_t j = k + 1; j < cols; ++j)
        A[i][j] = CGAL::integral_division(A[rank][k] * A[i][j] - A[i][k] * A[rank][j], previous);
      A[i][k] = R(0);
    }
    previous = A[rank][k];
    ++rank;
  }
  return rank;
}

/// A basis of the right kernel {x : A x = 0} of a rational matrix (reduced row echelon form).
inline std::vector<std::vector<Rational>> right_kernel(std::vector<std::vector<Rational>> a) {
  const std::size_t nr = a.size(), nc = nr == 0 ? 0 : a[0].size();
  std::vector<std::size_t> pivots;
  std::size_t r = 0;
  for (std::size_t c = 0; c < nc && r < nr; ++c) {
    std::size_t p = r;
    while (p < nr && CGAL::is_zero(a[p][c])) ++p;
    if (p == nr) continue;
    std::swap(a[p], a[r]);
    const Rational inv = Rational(1) / a[r][c];
    for (std::size_t j = c; j < nc; ++j) a[r][j] *= inv;
    for (std::size_t i = 0; i < nr; ++i) {
      if (i == r || CGAL::is_zero(a[i][c])) continue;
      const Rational f = a[i][c];
      for (std::size_t j = c; j < nc; ++j) a[i][j] -= f * a[r][j];
    }
    pivots.push_back(c);
    ++r;
  }
  std::vector<std::vector<Rational>> basis;
  std::vector<char> is_pivot(nc, 0);
  for (std::size_t c : pivots) is_pivot[c] = 1;
  for (std::size_t f = 0; f < nc; ++f) {
    if (is_pivot[f]) continue;
    std::vector<Rational> x(nc, Rational(0));
    x[f] = Rational(1);
    for (std::size_t i = 0; i < pivots.size(); ++i) x[pivots[i]] = -a[i][f];
    basis.push_back(x);
  }
  return basis;
}

} // namespace internal
} // namespace bezoutian

#endif // BEZOUTIAN_ELIMINATION_EXACT_LINEAR_ALGEBRA_H
