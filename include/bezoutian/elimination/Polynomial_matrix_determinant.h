// Exact determinants of square matrices whose entries are univariate or
// bivariate polynomials with integer or rational coefficients.
//
// This is the hot spot of the Bezoutian constructions: the implicit equation
// (buse-elkadi-galligo-2008, Theorems 2-5) and the elimination polynomial of a
// curve pair (du-1989) are determinants of 3x3 .. 9x9 matrices of bivariate
// polynomials of bi-degree up to about (6,6). Expanding them symbolically
// (Bareiss, Berkowitz) is slow because intermediate polynomials swell; here the
// determinant is computed as numeric linear algebra:
//
//   1. a degree bound (Du, Dv) of det in each variable (max-weight assignment);
//   2. a proven bound B on the absolute values of the coefficients of det
//      (Hadamard's inequality on the unit torus, see `determinant_coefficient_bound_squared`);
//   3. for word-size primes p_1, p_2, ... with p_1 p_2 ... > 2B: evaluation of
//      the matrix on the grid {0..Du} x {0..Dv}, a determinant modulo p at each
//      grid point (Gaussian elimination with pivoting), and interpolation
//      (Newton, per grid row then per grid column);
//   4. Chinese remaindering with symmetric representatives.
//
// Every coefficient of det lies in [-B, B] and is known modulo P > 2B, so the
// symmetric representative is the coefficient: the result is exact, no
// probabilistic step is involved. The division-free Berkowitz algorithm
// (`berkowitz_determinant`) is the slow reference used by the tests.
#ifndef BEZOUTIAN_ELIMINATION_POLYNOMIAL_MATRIX_DETERMINANT_H
#define BEZOUTIAN_ELIMINATION_POLYNOMIAL_MATRIX_DETERMINANT_H

#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/arithmetic/modular_arithmetic.h>
#include <bezoutian/arithmetic/modular_polynomial.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace bezoutian {

/// Determinant of a square matrix over any commutative ring NT by Berkowitz's
/// division-free algorithm (O(n^4) ring operations). The 0x0 determinant is 1.
/// Reference implementation for tests and benchmarks.
///
/// The characteristic polynomial det(x I - A) = x^n + c_1 x^{n-1} + ... + c_n is
/// the product T_n T_{n-1} ... T_1 of lower-triangular Toeplitz matrices, where
/// the first column of T_k is (1, -a_kk, -R_k C_k, -R_k A_{k-1} C_k, ...,
/// -R_k A_{k-1}^{k-2} C_k) with A_{k-1} the leading (k-1)x(k-1) block, R_k the
/// row and C_k the column that border it; det A = (-1)^n c_n.
template <class NT>
NT berkowitz_determinant(const std::vector<std::vector<NT>>& M) {
  const std::size_t n = M.size();
  for (const auto& row : M)
    if (row.size() != n) throw std::invalid_argument("berkowitz_determinant: the matrix is not square");
  if (n == 0) return NT(1);
  // v = coefficients (1, c_1, ..., c_k) of the characteristic polynomial of A_k.
  std::vector<NT> v{NT(1), -M[0][0]};
  for (std::size_t k = 1; k < n; ++k) {
    // Toeplitz column q_0 .. q_{k+1} for the block A_{k+1} (0-based row/column k).
    std::vector<NT> q(k + 2, NT(0));
    q[0] = NT(1);
    q[1] = -M[k][k];
    std::vector<NT> w(k), t(k);
    for (std::size_t i = 0; i < k; ++i) w[i] = M[i][k]; // C
    for (std::size_t j = 2; j <= k + 1; ++j) {
      NT s(0);
      for (std::size_t i = 0; i < k; ++i) s += M[k][i] * w[i]; // R A^{j-2} C
      q[j] = -s;
      if (j == k + 1) break;
      for (std::size_t i = 0; i < k; ++i) { // w <- A_k w
        NT acc(0);
        for (std::size_t l = 0; l < k; ++l) acc += M[i][l] * w[l];
        t[i] = acc;
      }
      std::swap(w, t);
    }
    std::vector<NT> nv(k + 2, NT(0));
    for (std::size_t i = 0; i < k + 2; ++i)
      for (std::size_t j = 0; j <= std::min(i, k); ++j) nv[i] += q[i - j] * v[j];
    v.swap(nv);
  }
  return (n % 2 == 0) ? v[n] : NT(-v[n]);
}

namespace internal {

/// Maximum of sum_i w[i][sigma(i)] over the permutations sigma avoiding the
/// forbidden entries (w < 0), or -1 if every permutation hits one (then the
/// determinant vanishes identically). Exact (dynamic programming over column
/// subsets) for n <= 16; above that the weaker bound min(sum of row maxima,
/// sum of column maxima) is returned.
inline long max_weight_assignment(const std::vector<std::vector<int>>& w) {
  const std::size_t n = w.size();
  if (n == 0) return 0;
  if (n <= 16) {
    const std::size_t full = (std::size_t(1) << n);
    std::vector<long> best(full, -1);
    best[0] = 0;
    for (std::size_t mask = 0; mask < full; ++mask) {
      if (best[mask] < 0) continue;
      const std::size_t row = static_cast<std::size_t>(__builtin_popcountll(mask));
      if (row == n) continue;
      for (std::size_t col = 0; col < n; ++col) {
        if ((mask >> col) & 1 || w[row][col] < 0) continue;
        long cand = best[mask] + w[row][col];
        long& b = best[mask | (std::size_t(1) << col)];
        if (cand > b) b = cand;
      }
    }
    return best[full - 1];
  }
  long rows = 0, cols = 0;
  for (std::size_t i = 0; i < n; ++i) {
    int rmax = -1, cmax = -1;
    for (std::size_t j = 0; j < n; ++j) {
      rmax = std::max(rmax, w[i][j]);
      cmax = std::max(cmax, w[j][i]);
    }
    if (rmax < 0 || cmax < 0) return -1;
    rows += rmax;
    cols += cmax;
  }
  return std::min(rows, cols);
}

/// B^2 with B a proven bound on |coefficient| of det A, where
///   B^2 = min( prod_i sum_j |a_ij|_1^2 , prod_j sum_i |a_ij|_1^2 ),
/// |f|_1 being the sum of the absolute values of the coefficients of f.
/// Proof: a coefficient of D(u,v) = det A is the mean of D(u,v) u^-k v^-l over
/// the torus |u| = |v| = 1 (Cauchy's formula), so it is at most max |D| there.
/// At a point of the torus, |a_ij(u,v)| <= |a_ij|_1, and Hadamard's inequality
/// for the complex matrix A(u,v) gives |D| <= prod_i ||row_i||_2 (and the same
/// with columns, as det A = det A^T).
inline CGAL::Gmpz determinant_coefficient_bound_squared(const std::vector<Dense_polynomial_entry>& A, std::size_t n) {
  std::vector<CGAL::Gmpz> norm2(n * n);
  for (std::size_t e = 0; e < n * n; ++e) {
    CGAL::Gmpz s(0), t;
    for (const CGAL::Gmpz& x : A[e].c) {
      mpz_abs(t.mpz(), x.mpz());
      s += t;
    }
    norm2[e] = s * s;
  }
  CGAL::Gmpz rows(1), cols(1);
  for (std::size_t i = 0; i < n; ++i) {
    CGAL::Gmpz r(0), c(0);
    for (std::size_t j = 0; j < n; ++j) {
      r += norm2[i * n + j];
      c += norm2[j * n + i];
    }
    rows *= r;
    cols *= c;
  }
  return std::min(rows, cols);
}

/// Determinant modulo p of the n x n matrix a (Montgomery residues, row-major,
/// destroyed) by fraction-free Gaussian elimination with row pivoting: row i is
/// replaced by piv*row_i - a_ik*row_k, which multiplies det by piv. Returns the
/// determinant of the final triangular matrix (with the sign of the row swaps);
/// det a = returned value / scale.
inline u64 scaled_determinant_mod_p(u64* a, std::size_t n, const Montgomery_modulus& M, u64& scale) {
  const u64 p = M.modulus();
  scale = M.one();
  bool negate = false;
  u64 det = M.one();
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t r = k;
    while (r < n && a[r * n + k] == 0) ++r;
    if (r == n) return 0;
    if (r != k) {
      for (std::size_t j = k; j < n; ++j) std::swap(a[r * n + j], a[k * n + j]);
      negate = !negate;
    }
    const u64 piv = a[k * n + k];
    det = M.mul(det, piv);
    const u64* rk = a + k * n;
    for (std::size_t i = k + 1; i < n; ++i) {
      u64* ri = a + i * n;
      const u64 f = ri[k];
      if (f == 0) continue;
      const u64 nf = p - f;
      // piv*x + (p-f)*y < 2p^2 < p*2^64: one Montgomery reduction.
      for (std::size_t j = k + 1; j < n; ++j)
        ri[j] = M.reduce(static_cast<u128>(piv) * ri[j] + static_cast<u128>(nf) * rk[j]);
      scale = M.mul(scale, piv);
    }
  }
  return negate ? M.neg(det) : det;
}

/// Coefficients of det A, A an n x n matrix of dense integer polynomials, with
/// deg_u det <= Du and deg_v det <= Dv and |coefficients| <= sqrt(bound_sq):
/// returned as an array indexed l*(Du+1)+k for u^k v^l.
inline std::vector<CGAL::Gmpz> multimodular_determinant(const std::vector<Dense_polynomial_entry>& A, std::size_t n,
                                                         std::size_t Du, std::size_t Dv,
                                                         const CGAL::Gmpz& bound_sq) {
  // Primes until P^2 > 4 B^2, i.e. P > 2B.
  std::vector<u64> primes;
  {
    CGAL::Gmpz P(1), target = 4 * bound_sq;
    while (P * P <= target) {
      primes.push_back(word_prime(primes.size()));
      P *= Montgomery_modulus::gmpz_from_u64(primes.back());
    }
  }
  const std::size_t np = primes.size();
  const std::size_t nu = Du + 1, nv = Dv + 1, npts = nu * nv, nn = n * n;
  int mdu = 0, mdv = 0;
  for (const auto& e : A) mdu = std::max(mdu, e.du), mdv = std::max(mdv, e.dv);
  const std::size_t su = std::size_t(mdu) + 1, sv = std::size_t(mdv) + 1;

  std::vector<u64> residues(npts * np); // [coefficient][prime]
  std::vector<u64> R;                   // entry coefficients mod p, padded to su x sv
  std::vector<u64> Cu;                  // c_{e,l}(a) at Cu[(e*sv + l)*nu + a]
  std::vector<u64> Fd(nn * sv);         // forward differences in v, all entries side by side
  std::vector<u64> mat(nn), num(npts), scale(npts), prefix(npts);
  std::vector<u64> inv, node, work;

  for (std::size_t ip = 0; ip < np; ++ip) {
    const Montgomery_modulus M(primes[ip]);
    // Residues of the coefficients, entry e at R[(e*sv + l)*su + k].
    R.assign(nn * sv * su, 0);
    for (std::size_t e = 0; e < nn; ++e) {
      const Dense_polynomial_entry& E = A[e];
      if (E.is_zero()) continue;
      for (int l = 0; l <= E.dv; ++l)
        for (int k = 0; k <= E.du; ++k) {
          const CGAL::Gmpz& x = E.c[std::size_t(l) * (E.du + 1) + k];
          if (!CGAL::is_zero(x)) R[(e * sv + l) * su + k] = M.to_montgomery(x);
        }
    }
    // Nodes 0..max(Du,Dv) and the inverses of 1..max(Du,Dv).
    consecutive_nodes(0, std::max(Du, Dv) + 1, M, node, inv);
    // Stage 1: the coefficients c_{e,l}(u) of v^l in entry e, tabulated at u = 0..Du.
    Cu.assign(nn * sv * nu, 0);
    for (std::size_t e = 0; e < nn; ++e)
      for (int l = 0; l <= A[e].dv; ++l)
        tabulate_at_consecutive_integers(&R[(e * sv + l) * su], 1, A[e].du, nu, &Cu[(e * sv + l) * nu], 1, M, node,
                                         work);
    // Stage 2: for each u = a, the entries (polynomials in v of degree <= dv_max)
    // are tabulated at v = 0..Dv by forward differences, all entries side by
    // side (Fd[j*nn + e] = j-th difference of entry e) so that the inner loop
    // runs over the nn independent entries; then one determinant modulo p per
    // grid point.
    for (std::size_t a = 0; a < nu; ++a) {
      // Values at v = 0..dv_max (Horner), or at all grid points if there are fewer.
      const std::size_t direct = std::min(sv, nv);
      for (std::size_t x = 0; x < direct; ++x)
        for (std::size_t e = 0; e < nn; ++e) {
          const int dv = A[e].dv;
          u64 y = 0;
          if (dv >= 0) {
            const u64* c = &Cu[e * sv * nu + a];
            y = c[std::size_t(dv) * nu];
            for (std::size_t l = std::size_t(dv); l-- > 0;) y = M.add(M.mul(y, node[x]), c[l * nu]);
          }
          Fd[x * nn + e] = y;
        }
      if (nv <= sv) {
        for (std::size_t b = 0; b < nv; ++b) {
          std::copy(&Fd[b * nn], &Fd[b * nn] + nn, mat.begin());
          num[a * nv + b] = scaled_determinant_mod_p(mat.data(), n, M, scale[a * nv + b]);
        }
        continue;
      }
      for (std::size_t j = 1; j < sv; ++j)
        for (std::size_t i = sv - 1; i >= j; --i)
          for (std::size_t e = 0; e < nn; ++e) Fd[i * nn + e] = M.sub(Fd[i * nn + e], Fd[(i - 1) * nn + e]);
      for (std::size_t b = 0; b < nv; ++b) {
        std::copy(&Fd[0], &Fd[0] + nn, mat.begin());
        num[a * nv + b] = scaled_determinant_mod_p(mat.data(), n, M, scale[a * nv + b]);
        for (std::size_t j = 0; j + 1 < sv; ++j) {
          u64* lo = &Fd[j * nn];
          const u64* hi = &Fd[(j + 1) * nn];
          for (std::size_t e = 0; e < nn; ++e) lo[e] = M.add(lo[e], hi[e]);
        }
      }
    }
    // Batch inversion of the scales (Montgomery's trick): one inverse per prime.
    u64 run = M.one();
    for (std::size_t t = 0; t < npts; ++t) prefix[t] = run, run = M.mul(run, scale[t]);
    u64 inv_run = M.inverse(run);
    for (std::size_t t = npts; t-- > 0;) {
      const u64 inv_t = M.mul(inv_run, prefix[t]);
      inv_run = M.mul(inv_run, scale[t]);
      num[t] = M.mul(num[t], inv_t); // value of det at grid point t
    }
    // num[a*nv + b] = det(a, b): interpolate in v (along b), then in u (along a).
    for (std::size_t a = 0; a < nu; ++a) interpolate_at_consecutive_integers(&num[a * nv], 1, Dv, M, inv, node, work);
    for (std::size_t l = 0; l < nv; ++l) interpolate_at_consecutive_integers(&num[l], nv, Du, M, inv, node, work);
    // num[k*nv + l] is now the coefficient of u^k v^l.
    for (std::size_t k = 0; k < nu; ++k)
      for (std::size_t l = 0; l < nv; ++l)
        residues[(l * nu + k) * np + ip] = M.from_montgomery(num[k * nv + l]);
  }

  std::vector<CGAL::Gmpz> coeffs(npts);
  Chinese_remainder crt(primes);
  for (std::size_t t = 0; t < npts; ++t) crt.combine(&residues[t * np], coeffs[t]);
  return coeffs;
}

/// Determinant of a matrix of dense entries; returns false if it vanishes
/// structurally (then coeffs is empty), else the coefficient array and the
/// degree bounds used.
inline bool dense_polynomial_matrix_determinant(const std::vector<Dense_polynomial_entry>& A, std::size_t n,
                                                std::vector<CGAL::Gmpz>& coeffs, std::size_t& Du, std::size_t& Dv) {
  std::vector<std::vector<int>> wu(n, std::vector<int>(n)), wv(n, std::vector<int>(n));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) wu[i][j] = A[i * n + j].du, wv[i][j] = A[i * n + j].dv;
  const long bu = max_weight_assignment(wu), bv = max_weight_assignment(wv);
  if (bu < 0 || bv < 0) return false;
  const CGAL::Gmpz bound_sq = determinant_coefficient_bound_squared(A, n);
  if (CGAL::is_zero(bound_sq)) return false;
  Du = std::size_t(bu);
  Dv = std::size_t(bv);
  coeffs = multimodular_determinant(A, n, Du, Dv, bound_sq);
  return true;
}

template <class Poly>
std::size_t checked_square_size(const std::vector<std::vector<Poly>>& M) {
  const std::size_t n = M.size();
  for (const auto& row : M)
    if (row.size() != n)
      throw std::invalid_argument("polynomial_matrix_determinant: the matrix is not square (" + std::to_string(n) +
                                  " rows, a row of length " + std::to_string(row.size()) + ")");
  return n;
}

/// Least common multiple of the denominators of the coefficients in a row.
inline void accumulate_denominator_lcm(const Rational& q, Integer& L) {
  mpz_lcm(L.mpz(), L.mpz(), mpq_denref(q.mpq()));
}
inline void accumulate_denominator_lcm(const Polynomial_1<Rational>& f, Integer& L) {
  for (const Rational& q : f) accumulate_denominator_lcm(q, L);
}
inline void accumulate_denominator_lcm(const Polynomial_2<Rational>& f, Integer& L) {
  for (const Polynomial_1<Rational>& g : f) accumulate_denominator_lcm(g, L);
}
inline Integer times_integer(const Rational& q, const Integer& L) {
  Integer r;
  mpz_divexact(r.mpz(), L.mpz(), mpq_denref(q.mpq()));
  mpz_mul(r.mpz(), r.mpz(), mpq_numref(q.mpq()));
  return r;
}
inline Polynomial_1<Integer> times_integer(const Polynomial_1<Rational>& f, const Integer& L) {
  std::vector<Integer> c;
  for (const Rational& q : f) c.push_back(times_integer(q, L));
  return Polynomial_1<Integer>(c.begin(), c.end());
}
inline Polynomial_2<Integer> times_integer(const Polynomial_2<Rational>& f, const Integer& L) {
  std::vector<Polynomial_1<Integer>> c;
  for (const Polynomial_1<Rational>& g : f) c.push_back(times_integer(g, L));
  return Polynomial_2<Integer>(c.begin(), c.end());
}

/// Row i of M times the lcm L_i of its denominators: an integer matrix whose
/// determinant is det M * prod_i L_i; the product is returned in L.
template <class PolyQ, class PolyZ>
std::vector<std::vector<PolyZ>> clear_row_denominators(const std::vector<std::vector<PolyQ>>& M, Integer& L) {
  L = Integer(1);
  std::vector<std::vector<PolyZ>> Z(M.size());
  for (std::size_t i = 0; i < M.size(); ++i) {
    Integer Li(1);
    for (const PolyQ& f : M[i]) accumulate_denominator_lcm(f, Li);
    for (const PolyQ& f : M[i]) Z[i].push_back(times_integer(f, Li));
    L *= Li;
  }
  return Z;
}

} // namespace internal

/// Exact determinant of a square matrix of bivariate integer polynomials
/// (multi-modular evaluation/interpolation with a proven coefficient bound).
/// The 0x0 determinant is 1. Throws std::invalid_argument if M is not square.
inline Polynomial_2<Integer> polynomial_matrix_determinant(const std::vector<std::vector<Polynomial_2<Integer>>>& M) {
  const std::size_t n = internal::checked_square_size(M);
  if (n == 0) return Polynomial_2<Integer>(1);
  if (n == 1) return M[0][0];
  std::vector<internal::Dense_polynomial_entry> A;
  A.reserve(n * n);
  for (const auto& row : M)
    for (const auto& f : row) A.push_back(internal::dense_entry(f));
  std::vector<Integer> c;
  std::size_t Du = 0, Dv = 0;
  if (!internal::dense_polynomial_matrix_determinant(A, n, c, Du, Dv)) return Polynomial_2<Integer>(0);
  std::vector<Polynomial_1<Integer>> rows;
  rows.reserve(Dv + 1);
  for (std::size_t l = 0; l <= Dv; ++l)
    rows.emplace_back(c.begin() + std::ptrdiff_t(l * (Du + 1)), c.begin() + std::ptrdiff_t((l + 1) * (Du + 1)));
  return Polynomial_2<Integer>(rows.begin(), rows.end());
}

/// Exact determinant of a square matrix of univariate integer polynomials.
inline Polynomial_1<Integer> polynomial_matrix_determinant(const std::vector<std::vector<Polynomial_1<Integer>>>& M) {
  const std::size_t n = internal::checked_square_size(M);
  if (n == 0) return Polynomial_1<Integer>(1);
  if (n == 1) return M[0][0];
  std::vector<internal::Dense_polynomial_entry> A;
  A.reserve(n * n);
  for (const auto& row : M)
    for (const auto& f : row) A.push_back(internal::dense_entry(f));
  std::vector<Integer> c;
  std::size_t Du = 0, Dv = 0;
  if (!internal::dense_polynomial_matrix_determinant(A, n, c, Du, Dv)) return Polynomial_1<Integer>(0);
  return Polynomial_1<Integer>(c.begin(), c.end());
}

/// Exact determinant of a square matrix of bivariate rational polynomials:
/// each row is multiplied by the lcm of its denominators, the integer
/// determinant is computed and divided by the product of these lcms.
inline Polynomial_2<Rational> polynomial_matrix_determinant(const std::vector<std::vector<Polynomial_2<Rational>>>& M) {
  internal::checked_square_size(M);
  Integer L;
  const auto Z = internal::clear_row_denominators<Polynomial_2<Rational>, Polynomial_2<Integer>>(M, L);
  const Polynomial_2<Integer> D = polynomial_matrix_determinant(Z);
  std::vector<Polynomial_1<Rational>> rows;
  for (const Polynomial_1<Integer>& g : D) {
    std::vector<Rational> c;
    for (const Integer& x : g) c.push_back(Rational(x, L));
    rows.emplace_back(c.begin(), c.end());
  }
  return Polynomial_2<Rational>(rows.begin(), rows.end());
}

/// Exact determinant of a square matrix of univariate rational polynomials.
inline Polynomial_1<Rational> polynomial_matrix_determinant(const std::vector<std::vector<Polynomial_1<Rational>>>& M) {
  internal::checked_square_size(M);
  Integer L;
  const auto Z = internal::clear_row_denominators<Polynomial_1<Rational>, Polynomial_1<Integer>>(M, L);
  const Polynomial_1<Integer> D = polynomial_matrix_determinant(Z);
  std::vector<Rational> c;
  for (const Integer& x : D) c.push_back(Rational(x, L));
  return Polynomial_1<Rational>(c.begin(), c.end());
}

/// Functor form of `polynomial_matrix_determinant`.
struct Polynomial_matrix_determinant {
  template <class Poly>
  Poly operator()(const std::vector<std::vector<Poly>>& M) const {
    return polynomial_matrix_determinant(M);
  }
};

} // namespace bezoutian

#endif // BEZOUTIAN_ELIMINATION_POLYNOMIAL_MATRIX_DETERMINANT_H
