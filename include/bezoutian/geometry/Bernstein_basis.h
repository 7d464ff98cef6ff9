// Exact operations on coefficient vectors in the Bernstein basis
// B_{i,n}(t) = C(n,i) t^i (1-t)^(n-i) of degree n on [0,1]: conversions to and from
// the power basis, de Casteljau evaluation and subdivision, restriction to a
// sub-interval (blossoming), degree elevation and the hodograph.
// All functions are templated on a field type FT (exact for CGAL::Gmpq).
#ifndef BEZOUTIAN_GEOMETRY_BERNSTEIN_BASIS_H
#define BEZOUTIAN_GEOMETRY_BERNSTEIN_BASIS_H

#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/arithmetic/binomial.h>
#include <bezoutian/arithmetic/number_types.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace bezoutian {

/// Power-basis polynomial sum_i b_i B_{i,n}(t) of the Bernstein coefficients b (n = b.size()-1).
/// Coefficient of t^k is sum_{i<=k} b_i C(n,i) C(n-i,k-i) (-1)^(k-i).
template <class FT>
Polynomial_1<FT> bernstein_to_power(const std::vector<FT>& b) {
  const int n = int(b.size()) - 1;
  if (n < 0) return Polynomial_1<FT>(FT(0));
  std::vector<FT> a(n + 1, FT(0));
  for (int i = 0; i <= n; ++i) {
    if (CGAL::is_zero(b[i])) continue;
    const FT bi = b[i] * binomial<FT>(n, i);
    for (int k = i; k <= n; ++k) {
      FT c = bi * binomial<FT>(n - i, k - i);
      if ((k - i) % 2) a[k] -= c; else a[k] += c;
    }
  }
  return Polynomial_1<FT>(a.begin(), a.end());
}

/// Bernstein coefficients of degree n of the power-basis polynomial p (deg p <= n):
/// b_i = sum_{k<=i} C(i,k)/C(n,k) a_k.
template <class FT>
std::vector<FT> power_to_bernstein(const Polynomial_1<FT>& p, int n) {
  const int d = p.degree();
  if (!CGAL::is_zero(p) && d > n)
    throw Invalid_input("polynomial of degree " + std::to_string(d) + " does not fit in Bernstein degree " +
                        std::to_string(n));
  std::vector<FT> b(n + 1, FT(0));
  if (CGAL::is_zero(p)) return b;
  for (int k = 0; k <= d; ++k) {
    if (CGAL::is_zero(p[k])) continue;
    const FT ak = p[k] / binomial<FT>(n, k);
    for (int i = k; i <= n; ++i) b[i] += binomial<FT>(i, k) * ak;
  }
  return b;
}

/// Value at t by de Casteljau's algorithm (exact for exact FT; stable for double).
template <class FT, class T>
T de_casteljau_value(const std::vector<FT>& b, const T& t) {
  std::vector<T> w(b.begin(), b.end());
  const T s = T(1) - t;
  for (std::size_t r = 1; r < w.size(); ++r)
    for (std::size_t i = 0; i + r < w.size(); ++i) w[i] = s * w[i] + t * w[i + 1];
  return w.empty() ? T(0) : w[0];
}

/// de Casteljau subdivision at t: Bernstein coefficients on [0,t] and on [t,1] (reparametrized to [0,1]).
template <class FT>
std::pair<std::vector<FT>, std::vector<FT>> de_casteljau_split(const std::vector<FT>& b, const FT& t) {
  const std::size_t n1 = b.size();
  std::vector<FT> w(b), left(n1), right(n1);
  const FT s = FT(1) - t;
  if (n1 == 0) return {left, right};
  left[0] = w[0];
  right[n1 - 1] = w[n1 - 1];
  for (std::size_t r = 1; r < n1; ++r) {
    for (std::size_t i = 0; i + r < n1; ++i) w[i] = s * w[i] + t * w[i + 1];
    left[r] = w[0];
    right[n1 - 1 - r] = w[n1 - 1 - r];
  }
  return {left, right};
}

/// Bernstein coefficients of the restriction to [a,c], reparametrized to [0,1] (a > c reverses).
/// By blossoming, the i-th coefficient is the blossom f(a,...,a, c,...,c) with i copies of c.
template <class FT>
std::vector<FT> bernstein_restrict(const std::vector<FT>& b, const FT& a, const FT& c) {
  const int n = int(b.size()) - 1;
  std::vector<FT> out(b.size());
  for (int i = 0; i <= n; ++i) {
    std::vector<FT> w(b);
    for (int r = 1; r <= n; ++r) {
      const FT& t = (r <= n - i) ? a : c;  // n-i steps at a, i steps at c
      const FT s = FT(1) - t;
      for (int j = 0; j + r <= n; ++j) w[j] = s * w[j] + t * w[j + 1];
    }
    out[i] = n >= 0 ? w[0] : FT(0);
  }
  return out;
}

/// Degree elevation n -> n+1: b'_i = i/(n+1) b_{i-1} + (1 - i/(n+1)) b_i.
template <class FT>
std::vector<FT> bernstein_elevate(const std::vector<FT>& b) {
  const int n = int(b.size()) - 1;
  std::vector<FT> e(n + 2);
  e[0] = b[0];
  e[n + 1] = b[n];
  for (int i = 1; i <= n; ++i) {
    const FT a = FT(i) / FT(n + 1);
    e[i] = a * b[i - 1] + (FT(1) - a) * b[i];
  }
  return e;
}

/// Hodograph: Bernstein coefficients (degree n-1) of the derivative, n (b_{i+1} - b_i).
template <class FT>
std::vector<FT> bernstein_derivative(const std::vector<FT>& b) {
  const int n = int(b.size()) - 1;
  if (n <= 0) return std::vector<FT>(1, FT(0));
  std::vector<FT> d(n);
  for (int i = 0; i < n; ++i) d[i] = FT(n) * (b[i + 1] - b[i]);
  return d;
}

} // namespace bezoutian

#endif // BEZOUTIAN_GEOMETRY_BERNSTEIN_BASIS_H
