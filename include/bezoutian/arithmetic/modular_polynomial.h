// Dense bivariate integer polynomials and their images modulo word primes:
// conversion from CGAL's recursive polynomials, tabulation at consecutive
// integers (forward differences), interpolation at consecutive integers
// (Newton), and univariate polynomial arithmetic modulo p (division with
// remainder, gcd). Shared by the determinant engine and the square-free part.
//
// Internal header: not part of the public API.
#ifndef BEZOUTIAN_ARITHMETIC_MODULAR_POLYNOMIAL_H
#define BEZOUTIAN_ARITHMETIC_MODULAR_POLYNOMIAL_H

#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/arithmetic/modular_arithmetic.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace bezoutian {
namespace internal {

/// Dense integer polynomial entry sum_{k<=du, l<=dv} c[l*(du+1)+k] u^k v^l;
/// du = dv = -1 for the zero polynomial.
struct Dense_polynomial_entry {
  int du = -1, dv = -1;
  std::vector<CGAL::Gmpz> c;
  bool is_zero() const { return du < 0; }
};

inline Dense_polynomial_entry dense_entry(const Polynomial_2<Integer>& f) {
  Dense_polynomial_entry e;
  if (CGAL::is_zero(f)) return e;
  e.dv = f.degree();
  e.du = 0;
  for (int l = 0; l <= e.dv; ++l)
    if (!CGAL::is_zero(f[l])) e.du = std::max(e.du, f[l].degree());
  e.c.assign(std::size_t(e.du + 1) * std::size_t(e.dv + 1), CGAL::Gmpz(0));
  for (int l = 0; l <= e.dv; ++l)
    for (int k = 0; k <= f[l].degree(); ++k) e.c[std::size_t(l) * (e.du + 1) + k] = f[l][k];
  return e;
}

inline Dense_polynomial_entry dense_entry(const Polynomial_1<Integer>& f) {
  Dense_polynomial_entry e;
  if (CGAL::is_zero(f)) return e;
  e.du = f.degree();
  e.dv = 0;
  e.c.assign(f.begin(), f.end());
  return e;
}

/// Values of the polynomial c_0 + c_1 x + ... + c_d x^d (coefficients c[i*cs],
/// Montgomery residues; d < 0 for the zero polynomial) at x = 0, 1, ..., N-1,
/// written to out[x*os]. The values at 0..d come from Horner's rule; further
/// values come from the table of forward differences, whose d-th difference is
/// constant, so that each further value costs d modular additions.
inline void tabulate_at_consecutive_integers(const u64* c, std::size_t cs, int d, std::size_t N, u64* out,
                                             std::size_t os, const Montgomery_modulus& M,
                                             const std::vector<u64>& node, std::vector<u64>& work) {
  if (d < 0) {
    for (std::size_t x = 0; x < N; ++x) out[x * os] = 0;
    return;
  }
  const std::size_t dd = std::size_t(d);
  const std::size_t m = std::min(dd + 1, N); // points evaluated directly
  work.resize(dd + 1);
  for (std::size_t x = 0; x < m; ++x) {
    u64 y = c[dd * cs];
    for (std::size_t k = dd; k-- > 0;) y = M.add(M.mul(y, node[x]), c[k * cs]);
    work[x] = y;
  }
  if (N <= dd + 1) {
    for (std::size_t x = 0; x < N; ++x) out[x * os] = work[x];
    return;
  }
  // work[j] <- j-th forward difference at x = 0.
  for (std::size_t j = 1; j <= dd; ++j)
    for (std::size_t i = dd; i >= j; --i) work[i] = M.sub(work[i], work[i - 1]);
  u64* w = work.data();
  for (std::size_t x = 0; x < N; ++x) {
    out[x * os] = w[0];
    for (std::size_t j = 0; j < dd; ++j) w[j] = M.add(w[j], w[j + 1]);
  }
}

/// In place: values f[0], f[s], ..., f[D*s] of a polynomial of degree <= D at
/// consecutive integers x_j = x_0 + j, j = 0..D (node[j] = x_j, Montgomery
/// residues) become its coefficients. Newton divided differences (the nodes
/// satisfy x_{i+j} - x_i = j, so level j divides by j, inv[j] = 1/j) followed
/// by expansion of the Newton form by Horner's rule.
inline void interpolate_at_consecutive_integers(u64* f, std::size_t s, std::size_t D, const Montgomery_modulus& M,
                                                const std::vector<u64>& inv, const std::vector<u64>& node,
                                                std::vector<u64>& work) {
  for (std::size_t j = 1; j <= D; ++j)
    for (std::size_t i = D; i >= j; --i) f[i * s] = M.mul(M.sub(f[i * s], f[(i - 1) * s]), inv[j]);
  work.assign(D + 1, 0);
  work[0] = f[D * s];
  for (std::size_t j = D; j-- > 0;) {
    // work <- work * (x - j) + f_j, with deg(work) = D - 1 - j before the step.
    const std::size_t deg = D - 1 - j;
    const u64 nj = M.neg(node[j]);
    work[deg + 1] = work[deg];
    for (std::size_t m = deg; m >= 1; --m) work[m] = M.add(work[m - 1], M.mul(nj, work[m]));
    work[0] = M.add(M.mul(nj, work[0]), f[j * s]);
  }
  for (std::size_t i = 0; i <= D; ++i) f[i * s] = work[i];
}

/// Montgomery residues of the coefficients of a dense polynomial, same layout.
inline std::vector<u64> residues(const Dense_polynomial_entry& E, const Montgomery_modulus& M) {
  std::vector<u64> r(E.c.size(), 0);
  for (std::size_t i = 0; i < E.c.size(); ++i)
    if (!CGAL::is_zero(E.c[i])) r[i] = M.to_montgomery(E.c[i]);
  return r;
}

/// The polynomial in v obtained by substituting u = x (x a Montgomery residue)
/// in E, whose residues are r: out[l] = sum_k r[l*(du+1)+k] x^k, l = 0..dv.
inline void specialize_u(const Dense_polynomial_entry& E, const std::vector<u64>& r, u64 x, const Montgomery_modulus& M,
                         std::vector<u64>& out) {
  out.assign(E.is_zero() ? 0 : std::size_t(E.dv + 1), 0);
  const std::size_t w = std::size_t(E.du + 1);
  for (std::size_t l = 0; l < out.size(); ++l) {
    const u64* c = &r[l * w];
    u64 y = c[w - 1];
    for (std::size_t k = w - 1; k-- > 0;) y = M.add(M.mul(y, x), c[k]);
    out[l] = y;
  }
}

/// Polynomials modulo p in one variable: Montgomery residues, coefficient of
/// x^i at index i, no trailing zeros (the zero polynomial is empty).
using Modular_polynomial = std::vector<u64>;

inline void trim(Modular_polynomial& f) {
  while (!f.empty() && f.back() == 0) f.pop_back();
}

inline Modular_polynomial derivative(const Modular_polynomial& f, const Montgomery_modulus& M) {
  Modular_polynomial d;
  for (std::size_t i = 1; i < f.size(); ++i) d.push_back(M.mul(f[i], M.to_montgomery(static_cast<u64>(i))));
  trim(d);
  return d;
}

/// f = q g + r with deg r < deg g (g nonzero, trimmed); f is trimmed.
inline void divide_with_remainder(const Modular_polynomial& f, const Modular_polynomial& g, Modular_polynomial& q,
                                  Modular_polynomial& r, const Montgomery_modulus& M) {
  r = f;
  trim(r);
  const std::size_t dg = g.size() - 1;
  if (r.size() < g.size()) {
    q.clear();
    return;
  }
  q.assign(r.size() - dg, 0);
  const u64 inv_lc = M.inverse(g.back());
  for (std::size_t i = r.size(); i-- > dg;) {
    const u64 c = M.mul(r[i], inv_lc);
    q[i - dg] = c;
    if (c == 0) continue;
    for (std::size_t j = 0; j <= dg; ++j) r[i - dg + j] = M.sub(r[i - dg + j], M.mul(c, g[j]));
  }
  r.resize(dg);
  trim(r);
  trim(q);
}

/// Monic gcd of a and b (Euclid); empty if both are zero.
inline Modular_polynomial monic_gcd(Modular_polynomial a, Modular_polynomial b, const Montgomery_modulus& M) {
  trim(a);
  trim(b);
  Modular_polynomial q, r;
  while (!b.empty()) {
    divide_with_remainder(a, b, q, r, M);
    a.swap(b);
    b.swap(r);
  }
  if (!a.empty()) {
    const u64 inv_lc = M.inverse(a.back());
    for (u64& c : a) c = M.mul(c, inv_lc);
  }
  return a;
}

/// Montgomery residues of 0, 1, ..., N-1 shifted by x0, and of 1/1, ..., 1/(N-1)
/// (inv[0] unused): the data `interpolate_at_consecutive_integers` needs.
inline void consecutive_nodes(u64 x0, std::size_t N, const Montgomery_modulus& M, std::vector<u64>& node,
                              std::vector<u64>& inv) {
  const u64 p = M.modulus();
  node.assign(N, 0);
  inv.assign(N, 0);
  std::vector<u64> plain(N, 0);
  if (N > 1) plain[1] = 1;
  for (std::size_t j = 2; j < N; ++j) plain[j] = (p - mulmod_u64(p / j, plain[p % j], p)) % p; // 1/j
  for (std::size_t j = 0; j < N; ++j) {
    node[j] = M.to_montgomery(x0 + static_cast<u64>(j));
    inv[j] = M.to_montgomery(plain[j]);
  }
}

} // namespace internal
} // namespace bezoutian

#endif // BEZOUTIAN_ARITHMETIC_MODULAR_POLYNOMIAL_H
