// Square-free part of a bivariate integer polynomial by modular methods, and
// exact division in Z[u][v] with an a posteriori proof. CGAL's generic
// Make_square_free works too but its bivariate gcd is far too slow for the
// implicit equations of Bezoutian constructions (bi-degree up to (54,54)).
//
// All answers are proved: modular images only propose candidates, which are
// certified by exact identities (see `exact_quotient` and
// `square_free_part_of_primitive`).
//
// Internal header: not part of the public API.
#ifndef BEZOUTIAN_ALGEBRAIC_INTERNAL_MODULAR_SQUARE_FREE_H
#define BEZOUTIAN_ALGEBRAIC_INTERNAL_MODULAR_SQUARE_FREE_H

#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/arithmetic/modular_arithmetic.h>
#include <bezoutian/arithmetic/modular_polynomial.h>

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace bezoutian {
namespace internal {

/// max |c|, sum |c| over the coefficients c of E.
inline CGAL::Gmpz max_norm(const Dense_polynomial_entry& E) {
  CGAL::Gmpz m(0);
  for (const CGAL::Gmpz& x : E.c)
    if (mpz_cmpabs(x.mpz(), m.mpz()) > 0) m = CGAL::abs(x);
  return m;
}
inline CGAL::Gmpz one_norm(const Dense_polynomial_entry& E) {
  CGAL::Gmpz s(0);
  for (const CGAL::Gmpz& x : E.c) s += CGAL::abs(x);
  return s;
}

/// Dense polynomial from a coefficient array c[l*(du+1)+k] (u^k v^l), with the
/// degrees lowered to the actual ones.
inline Dense_polynomial_entry dense_from_coefficients(const std::vector<CGAL::Gmpz>& c, std::size_t du,
                                                      std::size_t dv) {
  int ru = -1, rv = -1;
  for (std::size_t l = 0; l <= dv; ++l)
    for (std::size_t k = 0; k <= du; ++k)
      if (!CGAL::is_zero(c[l * (du + 1) + k])) ru = std::max(ru, int(k)), rv = int(l);
  Dense_polynomial_entry E;
  if (rv < 0) return E;
  E.du = ru;
  E.dv = rv;
  E.c.assign(std::size_t(ru + 1) * std::size_t(rv + 1), CGAL::Gmpz(0));
  for (int l = 0; l <= rv; ++l)
    for (int k = 0; k <= ru; ++k) E.c[std::size_t(l) * (ru + 1) + k] = c[std::size_t(l) * (du + 1) + k];
  return E;
}

inline Polynomial_2<Integer> to_polynomial_2(const Dense_polynomial_entry& E) {
  if (E.is_zero()) return Polynomial_2<Integer>(0);
  std::vector<Polynomial_1<Integer>> rows;
  const std::size_t w = std::size_t(E.du + 1);
  for (int l = 0; l <= E.dv; ++l)
    rows.emplace_back(E.c.begin() + std::ptrdiff_t(l * w), E.c.begin() + std::ptrdiff_t((l + 1) * w));
  return Polynomial_2<Integer>(rows.begin(), rows.end());
}

/// dE/dv.
inline Dense_polynomial_entry derivative_v(const Dense_polynomial_entry& E) {
  if (E.dv <= 0) return Dense_polynomial_entry();
  const std::size_t w = std::size_t(E.du + 1);
  std::vector<CGAL::Gmpz> c(w * std::size_t(E.dv));
  for (int l = 1; l <= E.dv; ++l)
    for (std::size_t k = 0; k < w; ++k) c[std::size_t(l - 1) * w + k] = E.c[std::size_t(l) * w + k] * l;
  return dense_from_coefficients(c, w - 1, std::size_t(E.dv - 1));
}

/// Decides whether Y divides X in Z[u][v] and, if so, computes Q = X / Y.
/// Precondition: Y != 0 has integer content 1 (then, by Gauss's lemma, Y | X
/// over Q implies Y | X over Z).
///
/// For word primes p: at N = deg_u X + 1 consecutive integers u = x where
/// lc_v(Y)(x) != 0 mod p, X(x,v) is divided by Y(x,v) modulo p; a nonzero
/// remainder proves Y does not divide X. Otherwise the quotients interpolate to
/// Q_p with deg_u Q_p <= deg_u X - deg_u Y (else Y does not divide X), and
/// X - Y Q_p (of u-degree <= deg_u X) vanishes modulo p at N values of u, so
/// X = Y Q_p mod p. With Q the symmetric Chinese remainder of the Q_p modulo
/// P = prod p, X - Y Q = 0 mod P and |coefficients of X - Y Q| <=
/// ||X||_inf + ||Y||_1 ||Q||_inf: once P exceeds twice that, X = Y Q. If Y | X
/// the true quotient satisfies ||Q||_inf <= 2^(S (deg_v X + 1)) ||X||_1,
/// S = deg_u X + 1 (Kronecker substitution v -> x^S and the Landau-Mignotte
/// bound ||h||_inf <= 2^deg(h) ||f||_2 for h | f in Z[x]); past the
/// corresponding number of primes, Y does not divide X.
inline bool exact_quotient(const Dense_polynomial_entry& X, const Dense_polynomial_entry& Y,
                           Dense_polynomial_entry& Q) {
  if (Y.is_zero()) throw std::invalid_argument("exact_quotient: division by zero");
  if (X.is_zero()) {
    Q = Dense_polynomial_entry();
    return true;
  }
  if (X.du < Y.du || X.dv < Y.dv) return false;
  const std::size_t qu = std::size_t(X.du - Y.du), qv = std::size_t(X.dv - Y.dv), N = std::size_t(X.du + 1);
  const CGAL::Gmpz x_max = max_norm(X), y_one = one_norm(Y);
  CGAL::Gmpz limit = one_norm(X);
  mpz_mul_2exp(limit.mpz(), limit.mpz(), N * std::size_t(X.dv + 1)); // fresh object from one_norm
  limit = 2 * (x_max + y_one * limit);

  Incremental_chinese_remainder crt((qu + 1) * (qv + 1));
  std::vector<u64> node, inv, work, xs, ys, vals(N * (qv + 1)), res((qu + 1) * (qv + 1));
  Modular_polynomial q, r;
  for (std::size_t ip = 0;; ++ip) {
    const Montgomery_modulus M(word_prime(ip));
    const std::vector<u64> rx = residues(X, M), ry = residues(Y, M);
    bool window_found = false;
    for (u64 w = 0; w < 64 && !window_found; ++w) {
      consecutive_nodes(w * N, N, M, node, inv);
      bool ok = true;
      for (std::size_t j = 0; j < N && ok; ++j) {
        specialize_u(Y, ry, node[j], M, ys);
        if (ys.back() == 0) ok = false; // lc_v(Y) vanishes at this node: next window
      }
      window_found = ok;
    }
    if (!window_found) continue;
    for (std::size_t j = 0; j < N; ++j) {
      specialize_u(X, rx, node[j], M, xs);
      specialize_u(Y, ry, node[j], M, ys);
      divide_with_remainder(xs, ys, q, r, M);
      if (!r.empty() || q.size() > qv + 1) return false;
      for (std::size_t l = 0; l <= qv; ++l) vals[j * (qv + 1) + l] = l < q.size() ? q[l] : 0;
    }
    for (std::size_t l = 0; l <= qv; ++l) {
      interpolate_at_consecutive_integers(&vals[l], qv + 1, N - 1, M, inv, node, work);
      for (std::size_t k = qu + 1; k < N; ++k)
        if (vals[k * (qv + 1) + l] != 0) return false;
      for (std::size_t k = 0; k <= qu; ++k) res[l * (qu + 1) + k] = M.from_montgomery(vals[k * (qv + 1) + l]);
    }
    crt.add(M.modulus(), res);
    std::vector<CGAL::Gmpz> c(crt.size());
    CGAL::Gmpz q_max(0);
    for (std::size_t i = 0; i < c.size(); ++i) {
      c[i] = crt.symmetric(i);
      if (mpz_cmpabs(c[i].mpz(), q_max.mpz()) > 0) q_max = CGAL::abs(c[i]);
    }
    if (crt.product() > 2 * (x_max + y_one * q_max)) {
      Q = dense_from_coefficients(c, qu, qv);
      return true;
    }
    if (crt.product() > limit) return false;
  }
}

/// A proof that P (deg_v P >= 1) has no repeated factor of positive degree in
/// v, or false if none was found: if P = g^2 h with deg_v g >= 1 and
/// lc_v(P)(x) != 0 mod p, then g(x,v) mod p has positive degree and divides
/// gcd(f, f') for f = P(x,v) mod p (p > deg f); so gcd(f, f') = 1 proves it.
inline bool specialization_proves_no_repeated_v_factor(const Dense_polynomial_entry& P) {
  std::vector<u64> f;
  for (std::size_t t = 0; t < 4; ++t) {
    const Montgomery_modulus M(word_prime(t));
    specialize_u(P, residues(P, M), M.to_montgomery(static_cast<u64>(2 * t + 1)), M, f);
    if (f.back() == 0) continue;
    if (monic_gcd(f, derivative(f, M), M).size() == 1) return true;
  }
  return false;
}

/// Content of a bivariate polynomial with respect to v (gcd in Z[u] of its
/// coefficients, integer content included, up to sign), and the division of
/// every coefficient by it. The gcd may stop early only at a unit: a constant
/// gcd g of the first coefficients is their integer content, and the remaining
/// coefficients may still share only a proper factor of g.
inline Polynomial_1<Integer> v_content(const Polynomial_2<Integer>& D) {
  Polynomial_1<Integer> g(0);
  for (const Polynomial_1<Integer>& c : D) {
    if (CGAL::is_zero(c)) continue;
    g = CGAL::is_zero(g) ? c : CGAL::gcd(g, c);
    if (g.degree() == 0 && CGAL::abs(g[0]) == 1) return g;
  }
  return g;
}
inline Polynomial_2<Integer> divide_v_coefficients(const Polynomial_2<Integer>& D, const Polynomial_1<Integer>& c) {
  std::vector<Polynomial_1<Integer>> rows;
  for (const Polynomial_1<Integer>& a : D) rows.push_back(CGAL::integral_division(a, c));
  return Polynomial_2<Integer>(rows.begin(), rows.end());
}

/// The square-free part of P computed by CGAL's generic bivariate gcd: correct
/// but slow; the last resort of `square_free_part_of_primitive`.
inline Polynomial_2<Integer> generic_square_free_part(const Polynomial_2<Integer>& P) {
  typename CGAL::Polynomial_traits_d<Polynomial_2<Integer>>::Make_square_free make_square_free;
  return make_square_free(P);
}

/// The square-free part of P, where P has content 1 with respect to v and
/// integer content 1 and deg_v P >= 1 (result up to sign).
///
/// Candidate: let L = lc_v(P) and S the square-free part, T = (L/lc_v(S)) S,
/// so lc_v(T) = L. Modulo p at u = x with L(x) != 0, f = P(x,v) has square-free
/// part f / gcd(f, f') of degree <= deg_v S; equality holds for all but finitely
/// many (x, p), and then f / gcd(f, f') = T(x,v) (same leading coefficient
/// L(x); lc_v(S)(x) != 0 since it divides L(x)). Windows of
/// deg_u L + deg_u P + 1 consecutive x where all degrees agree give T mod p by
/// interpolation; primes of lower degree are discarded and a higher degree
/// restarts the reconstruction. The candidate S_c = primitive part of the
/// Chinese remainder is certified by two exact divisions: G = P / S_c and
/// G | dP/dv. Then G divides gcd(P, dP/dv) = P/S, so S | S_c, and
/// deg_v S_c <= deg_v S (degree of a modular image), so S_c = +-S.
///
/// When to certify: when the reconstruction is stable over one more prime and
/// has changed since the last failed certification (a failed candidate is never
/// tried twice), and once the product of the primes exceeds twice a proved
/// bound on the coefficients of T. Bound: with the Kronecker substitution
/// v -> x^K, K = deg_u P + 1, P, S and P/S become univariate polynomials with
/// kron(P) = kron(S) kron(P/S), of degree n <= K (deg_v P + 1) - 1. Mahler's
/// measure is multiplicative and ||h||_1 <= 2^deg(h) M(h), M(h) <= ||h||_2, so
/// ||T||_inf <= ||lc_v(P/S)||_1 ||S||_1 <= ||P/S||_1 ||S||_1 <= 2^n ||P||_2
/// <= 2^n ||P||_1. Past the bound a failed certification proves that the
/// current degree is below deg_v S (all images with the right degree are
/// right); only a prime of higher degree can then help. If none comes within
/// a generous number of further primes, CGAL's generic algorithm answers.
inline Polynomial_2<Integer> square_free_part_of_primitive(const Polynomial_2<Integer>& P2) {
  const Dense_polynomial_entry P = dense_entry(P2), Pv = derivative_v(P);
  const Polynomial_1<Integer>& L = P2.lcoeff();
  const std::size_t N = std::size_t(L.degree() + P.du) + 1;
  CGAL::Gmpz limit = one_norm(P);
  mpz_mul_2exp(limit.mpz(), limit.mpz(), std::size_t(P.du + 1) * std::size_t(P.dv + 1) + 1); // fresh object
  // Word primes exceed 2^61: enough primes to pass the bound, and as many again
  // to meet a prime of the right degree after unlucky ones.
  const std::size_t max_primes = 2 * (mpz_sizeinbase(limit.mpz(), 2) / 61 + 1) + 64;
  Incremental_chinese_remainder crt;
  int dstar = -1;
  bool tried = false; // the current reconstruction failed the certification
  std::vector<u64> node, inv, work, f, vals, res;
  std::vector<Modular_polynomial> images(N);
  Modular_polynomial g, q, r;
  for (std::size_t ip = 0; ip < max_primes; ++ip) {
    const Montgomery_modulus M(word_prime(ip));
    const std::vector<u64> rp = residues(P, M);
    int dp = -1;
    for (u64 w = 0; w < 64 && dp < 0; ++w) {
      consecutive_nodes(w * N, N, M, node, inv);
      bool ok = true;
      int dmax = -1;
      std::size_t j = 0;
      for (; j < N; ++j) {
        specialize_u(P, rp, node[j], M, f);
        if (f.back() == 0) break; // L vanishes at this node
        g = monic_gcd(f, derivative(f, M), M);
        divide_with_remainder(f, g, q, r, M);
        images[j] = q;
        const int d = int(q.size()) - 1;
        if (j > 0 && d != dmax) ok = false; // an unlucky node in this window
        dmax = std::max(dmax, d);
      }
      if (j == N && ok) dp = dmax;
    }
    if (dp < 0 || dp < dstar) continue;
    const std::size_t m = std::size_t(dp) + 1;
    if (dp > dstar) {
      crt = Incremental_chinese_remainder(N * m);
      dstar = dp;
      tried = false;
    }
    vals.assign(N * m, 0);
    for (std::size_t j = 0; j < N; ++j)
      for (std::size_t l = 0; l < m; ++l) vals[j * m + l] = images[j][l];
    res.assign(N * m, 0);
    for (std::size_t l = 0; l < m; ++l) {
      interpolate_at_consecutive_integers(&vals[l], m, N - 1, M, inv, node, work);
      for (std::size_t k = 0; k < N; ++k) res[l * N + k] = M.from_montgomery(vals[k * m + l]);
    }
    const bool stable = crt.add(M.modulus(), res);
    if (!stable) tried = false;
    if (tried || crt.number_of_primes() < 2 || !(stable || crt.product() > limit)) continue;
    // Candidate S_c = primitive part of T (content in Z[u], integer content included).
    std::vector<CGAL::Gmpz> c(crt.size());
    for (std::size_t i = 0; i < c.size(); ++i) c[i] = crt.symmetric(i);
    Polynomial_2<Integer> T = to_polynomial_2(dense_from_coefficients(c, N - 1, m - 1));
    tried = true;
    if (CGAL::is_zero(T)) continue;
    const Polynomial_1<Integer> content = v_content(T);
    if (content != Polynomial_1<Integer>(1)) T = divide_v_coefficients(T, content);
    const Dense_polynomial_entry Sc = dense_entry(T);
    Dense_polynomial_entry G, H;
    if (exact_quotient(P, Sc, G) && exact_quotient(Pv, G, H)) return T;
  }
  return generic_square_free_part(P2);
}

} // namespace internal
} // namespace bezoutian

#endif // BEZOUTIAN_ALGEBRAIC_INTERNAL_MODULAR_SQUARE_FREE_H
