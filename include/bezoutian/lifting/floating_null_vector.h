// A floating-point null vector of a numerically singular square matrix: the starting kernel vector of the
// lifting (Surface_intersection.h: the partner as a ratio of its entries, buse-elkadi-galligo-2008 §4) and of the
// kernel system (kernel_partner_proofs.h). Floating point only: never a decision.
#ifndef BEZOUTIAN_LIFTING_FLOATING_NULL_VECTOR_H
#define BEZOUTIAN_LIFTING_FLOATING_NULL_VECTOR_H

#include <algorithm>
#include <cmath>
#include <vector>

namespace bezoutian {
namespace internal {

// A null vector of the (numerically singular) square matrix A, by Gaussian elimination with complete
// pivoting; the last pivot is the smallest and its variable is set to 1.
inline std::vector<long double> null_vector(std::vector<std::vector<long double>> A) {
  const std::size_t n = A.size();
  std::vector<std::size_t> col(n);
  for (std::size_t i = 0; i < n; ++i) col[i] = i;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    std::size_t pr = k, pc = k;
    long double best = -1;
    for (std::size_t i = k; i < n; ++i)
      for (std::size_t j = k; j < n; ++j)
        if (std::fabs(A[i][j]) > best) best = std::fabs(A[i][j]), pr = i, pc = j;
    std::swap(A[k], A[pr]);
    for (auto& row : A) std::swap(row[k], row[pc]);
    std::swap(col[k], col[pc]);
    if (best == 0) break;
    for (std::size_t i = k + 1; i < n; ++i) {
      const long double f = A[i][k] / A[k][k];
      for (std::size_t j = k; j < n; ++j) A[i][j] -= f * A[k][j];
    }
  }
  std::vector<long double> y(n, 0);
  if (n == 0) return y;
  y[n - 1] = 1;
  for (std::size_t k = n - 1; k-- > 0;) {
    long double s = 0;
    for (std::size_t j = k + 1; j < n; ++j) s += A[k][j] * y[j];
    y[k] = A[k][k] != 0 ? -s / A[k][k] : 0;
  }
  std::vector<long double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[col[i]] = y[i];
  return x;
}

}  // namespace internal
}  // namespace bezoutian

#endif
