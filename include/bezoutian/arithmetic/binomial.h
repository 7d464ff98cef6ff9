// Binomial coefficients C(n, k), the one implementation the stages share: exact values in any number type in which
// the partial products C(n-k+i, i) are exact (Integer, Rational, polynomial rings), rows C(n, 0..n) and Pascal
// tables, and rows in an enclosure arithmetic built by additions only (each entry encloses the exact integer when
// the type's addition rounds outwards).
#ifndef BEZOUTIAN_ARITHMETIC_BINOMIAL_H
#define BEZOUTIAN_ARITHMETIC_BINOMIAL_H

#include <cstddef>
#include <vector>

namespace bezoutian {

/// Binomial coefficient C(n,k) as an exact number of type NT (0 outside 0 <= k <= n). The product
/// prod_{i<=k} (n-k+i)/i is exact at every step: after i factors it equals C(n-k+i, i).
template <class NT>
NT binomial(int n, int k) {
  if (k < 0 || k > n) return NT(0);
  if (k > n - k) k = n - k;
  NT r(1);
  for (int i = 1; i <= k; ++i) r = r * NT(n - k + i) / NT(i);
  return r;
}

/// The row C(n, 0), ..., C(n, n), exact in NT (multiplicative recurrence C(n,k) = C(n,k-1) (n-k+1) / k).
template <class NT>
std::vector<NT> binomial_row(int n) {
  std::vector<NT> c(std::size_t(n + 1), NT(1));
  for (int k = 1; k <= n; ++k) c[std::size_t(k)] = c[std::size_t(k - 1)] * NT(n - k + 1) / NT(k);
  return c;
}

/// Pascal's table c[i][j] = C(i, j) for 0 <= j <= i <= d (0 above the diagonal), by additions only.
template <class NT>
std::vector<std::vector<NT>> binomial_table(int d) {
  std::vector<std::vector<NT>> c(std::size_t(d + 1), std::vector<NT>(std::size_t(d + 1), NT(0)));
  for (int i = 0; i <= d; ++i) {
    c[std::size_t(i)][0] = NT(1);
    for (int j = 1; j <= i; ++j)
      c[std::size_t(i)][std::size_t(j)] = c[std::size_t(i - 1)][std::size_t(j - 1)] + c[std::size_t(i - 1)][std::size_t(j)];
  }
  return c;
}

/// The row C(n, 0..n) by Pascal's additions from the given zero and one of an enclosure type T (intervals: the
/// entries enclose the exact integers when T's addition rounds outwards).
template <class T>
std::vector<T> binomial_row_by_additions(int n, const T& zero, const T& one) {
  std::vector<T> c(std::size_t(n + 1), zero);
  c[0] = one;
  for (int r = 1; r <= n; ++r)
    for (int k = r; k >= 1; --k) c[std::size_t(k)] = c[std::size_t(k)] + c[std::size_t(k - 1)];
  return c;
}

}  // namespace bezoutian

#endif  // BEZOUTIAN_ARITHMETIC_BINOMIAL_H
