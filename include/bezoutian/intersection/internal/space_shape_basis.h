// The common points of two space curves as a shape basis {g(s) = 0, t = psi(s)}: candidates modulo word primes
// (Bezout-matrix eliminants of two plane projections, du-1989 eq. 4.1, their gcd, Euclid over F_p[s]/(g)), rational
// reconstruction by Chinese remaindering, and an exact verification over Q that proves every root of g a common
// point. Only the small polynomials g, psi are ever computed exactly.
//
// Internal header: not part of the public API.
#ifndef BEZOUTIAN_INTERSECTION_INTERNAL_SPACE_SHAPE_BASIS_H
#define BEZOUTIAN_INTERSECTION_INTERNAL_SPACE_SHAPE_BASIS_H

#include <bezoutian/algebraic/bernstein_descartes.h>
#include <bezoutian/arithmetic/modular_arithmetic.h>
#include <bezoutian/arithmetic/modular_polynomial.h>
#include <bezoutian/arithmetic/rational_reconstruction.h>
#include <bezoutian/arithmetic/number_types.h>

#include <CGAL/Polynomial.h>

#include <array>
#include <vector>

namespace bezoutian {
namespace internal {

/// Shape basis of the system F_k(s,t) = A_k(s) B_0(t) - B_k(t) A_0(s) = 0, k = 1..3 (two space curves in
/// homogeneous power form): g monic of degree d >= 0, psi of degree < d, such that F_k(s, psi(s)) = 0 modulo g for
/// every k (verified exactly). Hence every complex root sigma of g gives a common zero (sigma, psi(sigma)), and a
/// real one with A_0(sigma) != 0 != B_0(psi(sigma)) a common point C_A(sigma) = C_B(psi(sigma)).
struct Space_shape_basis {
  std::vector<Rational> g, psi;  // coefficients, index = power of s; g.back() == 1
};

namespace space_shape {

using Mod_poly = Modular_polynomial;  // Montgomery residues, trimmed

inline Mod_poly mul(const Mod_poly& a, const Mod_poly& b, const Montgomery_modulus& M) {
  if (a.empty() || b.empty()) return Mod_poly();
  Mod_poly r(a.size() + b.size() - 1, 0);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] = M.add(r[i + j], M.mul(a[i], b[j]));
  trim(r);
  return r;
}

inline Mod_poly rem(const Mod_poly& a, const Mod_poly& g, const Montgomery_modulus& M) {
  Mod_poly q, r;
  divide_with_remainder(a, g, q, r, M);
  return r;
}

/// a modulo the monic g, in place (no inversion).
inline void reduce_monic(Mod_poly& a, const Mod_poly& g, const Montgomery_modulus& M) {
  trim(a);
  const std::size_t d = g.size() - 1;
  for (std::size_t i = a.size(); i-- > d;) {
    const u64 c = a[i];
    if (c == 0) continue;
    for (std::size_t j = 0; j < d; ++j) a[i - d + j] = M.sub(a[i - d + j], M.mul(c, g[j]));
    a[i] = 0;
  }
  if (a.size() > d) a.resize(d);
  trim(a);
}

/// a * b modulo the monic g.
inline Mod_poly mulmod(const Mod_poly& a, const Mod_poly& b, const Mod_poly& g, const Montgomery_modulus& M) {
  Mod_poly r = mul(a, b, M);
  reduce_monic(r, g, M);
  return r;
}

inline Mod_poly quo(const Mod_poly& a, const Mod_poly& g, const Montgomery_modulus& M) {
  Mod_poly q, r;
  divide_with_remainder(a, g, q, r, M);
  return q;
}

inline Mod_poly sub(const Mod_poly& a, const Mod_poly& b, const Montgomery_modulus& M) {
  Mod_poly r(std::max(a.size(), b.size()), 0);
  for (std::size_t i = 0; i < r.size(); ++i)
    r[i] = M.sub(i < a.size() ? a[i] : 0, i < b.size() ? b[i] : 0);
  trim(r);
  return r;
}

/// Inverse of a modulo g (extended Euclid); false if gcd(a, g) != 1.
inline bool inverse_mod(const Mod_poly& a, const Mod_poly& g, Mod_poly& inv, const Montgomery_modulus& M) {
  Mod_poly r0 = g, r1 = rem(a, g, M), u0, u1{M.one()};
  while (r1.size() > 1) {
    Mod_poly q, r;
    divide_with_remainder(r0, r1, q, r, M);
    Mod_poly u = sub(u0, mul(q, u1, M), M);
    r0.swap(r1);
    r1.swap(r);
    u0.swap(u1);
    u1.swap(u);
  }
  if (r1.empty()) return false;  // gcd has degree >= 1
  const u64 c = M.inverse(r1[0]);
  for (u64& x : u1) x = M.mul(x, c);
  inv = rem(u1, g, M);
  return true;
}

/// Bezout matrix (n x n, row-major) of f, g given by n + 1 coefficients each: (f(x)g(y) - f(y)g(x))/(x - y)
/// = sum_{a > b} (f_a g_b - f_b g_a) sum_{i < a - b} x^(b+i) y^(a-1-i).
inline void bezout_matrix(const u64* f, const u64* g, int n, const Montgomery_modulus& M, std::vector<u64>& out) {
  out.assign(std::size_t(n) * n, 0);
  for (int a = 1; a <= n; ++a)
    for (int b = 0; b < a; ++b) {
      const u64 c = M.sub(M.mul(f[a], g[b]), M.mul(f[b], g[a]));
      if (c == 0) continue;
      for (int i = 0; i < a - b; ++i) {
        u64& e = out[std::size_t(b + i) * n + (a - 1 - i)];
        e = M.add(e, c);
      }
    }
}

/// Determinant of the n x n matrix m (destroyed) as num / den (no inversion: rows are scaled instead).
inline void determinant(std::vector<u64>& m, int n, const Montgomery_modulus& M, u64& num, u64& den) {
  num = M.one();
  den = M.one();
  for (int c = 0; c < n; ++c) {
    int piv = -1;
    for (int r = c; r < n && piv < 0; ++r)
      if (m[std::size_t(r) * n + c] != 0) piv = r;
    if (piv < 0) {
      num = 0;
      return;
    }
    if (piv != c) {
      for (int k = 0; k < n; ++k) std::swap(m[std::size_t(piv) * n + k], m[std::size_t(c) * n + k]);
      num = M.neg(num);
    }
    const u64 p = m[std::size_t(c) * n + c];
    num = M.mul(num, p);
    for (int r = c + 1; r < n; ++r) {
      const u64 f = m[std::size_t(r) * n + c];
      if (f == 0) continue;
      den = M.mul(den, p);  // row r <- p row r - f row c multiplies the determinant by p
      for (int k = c + 1; k < n; ++k)
        m[std::size_t(r) * n + k] = M.sub(M.mul(p, m[std::size_t(r) * n + k]), M.mul(f, m[std::size_t(c) * n + k]));
      m[std::size_t(r) * n + c] = 0;
    }
  }
}

inline u64 horner(const Mod_poly& f, u64 x, const Montgomery_modulus& M) {
  u64 y = 0;
  for (std::size_t i = f.size(); i-- > 0;) y = M.add(M.mul(y, x), f[i]);
  return y;
}

/// Candidate shape basis modulo one prime; false if this prime cannot give one (a zero divisor in the Euclidean
/// algorithm over F_p[s]/(g), several partners t for one s, every projection eliminant zero).
/// A, B: the homogeneous forms (W, X, Y, Z) modulo p.
inline bool shape_mod_p(const std::array<Mod_poly, 4>& A, const std::array<Mod_poly, 4>& B, const Montgomery_modulus& M,
                        Mod_poly& g, Mod_poly& psi) {
  int m = 0, n = 0;
  for (const auto& f : A) m = std::max(m, int(f.size()) - 1);
  for (const auto& f : B) n = std::max(n, int(f.size()) - 1);
  if (m < 1 || n < 1) return false;
  // 1. R_ij(s) = det(A_0 Bez(B_i, B_j) - A_j Bez(B_i, B_0) - A_i Bez(B_0, B_j)) = det of
  //    W_A(s) Bez_t(B_i - x B_0, B_j - y B_0) at (x, y) = (A_i/A_0, A_j/A_0)(s): the implicit equation of the
  //    projection of curve B evaluated on curve A (degree <= m n); common points have s among its roots.
  std::vector<std::vector<u64>> coef(4, std::vector<u64>(n + 1, 0));
  for (int k = 0; k < 4; ++k)
    for (std::size_t i = 0; i < B[k].size(); ++i) coef[k][i] = B[k][i];
  const std::size_t N = std::size_t(m) * n + 1;
  std::vector<u64> node, inv, work;
  consecutive_nodes(0, N, M, node, inv);
  g.clear();
  const int planes[3][2] = {{1, 2}, {1, 3}, {2, 3}};
  int used = 0;
  std::vector<u64> C0, Ci, Cj, mat, nums(N), dens(N);
  for (const auto& pl : planes) {
    if (used == 2) break;
    const int i = pl[0], j = pl[1];
    bezout_matrix(coef[i].data(), coef[j].data(), n, M, C0);
    bezout_matrix(coef[0].data(), coef[j].data(), n, M, Ci);
    bezout_matrix(coef[i].data(), coef[0].data(), n, M, Cj);
    for (std::size_t x = 0; x < N; ++x) {
      const u64 a0 = horner(A[0], node[x], M), ai = M.neg(horner(A[i], node[x], M)), aj = M.neg(horner(A[j], node[x], M));
      mat.resize(C0.size());
      for (std::size_t e = 0; e < C0.size(); ++e)
        mat[e] = M.add(M.add(M.mul(a0, C0[e]), M.mul(ai, Ci[e])), M.mul(aj, Cj[e]));
      determinant(mat, n, M, nums[x], dens[x]);
    }
    // batch inversion of the denominators (one modular inverse)
    std::vector<u64> prefix(N);
    u64 acc = M.one();
    for (std::size_t x = 0; x < N; ++x) {
      prefix[x] = acc;
      acc = M.mul(acc, dens[x]);
    }
    u64 ia = M.inverse(acc);
    std::vector<u64> vals(N);
    for (std::size_t x = N; x-- > 0;) {
      vals[x] = M.mul(nums[x], M.mul(ia, prefix[x]));
      ia = M.mul(ia, dens[x]);
    }
    interpolate_at_consecutive_integers(vals.data(), 1, N - 1, M, inv, node, work);
    trim(vals);
    if (vals.empty()) continue;  // this projection of curve B is degenerate (a point or a line traversed twice...)
    g = used == 0 ? vals : monic_gcd(g, vals, M);
    ++used;
  }
  if (used == 0) return false;
  // 2. Roots of W_A are common zeros at infinity (A_0 = 0 makes F_k multiples of B_0): removed.
  if (A[0].size() >= 2)
    for (;;) {
      const Mod_poly h = monic_gcd(g, A[0], M);
      if (h.size() <= 1) break;
      g = quo(g, h, M);
    }
  {
    const u64 c = M.inverse(g.back());
    for (u64& x : g) x = M.mul(x, c);
  }
  psi.clear();
  if (g.size() <= 1) return true;  // no common point
  // 3. gcd_t(F_1, F_2) over F_p[s]/(g) by Euclid; a remainder of degree 0 in t restricts g to its roots, the
  //    partner t = psi(s) comes from the linear gcd; then g is restricted to the roots where F_3(s, psi) = 0 too.
  using Ring_poly = std::vector<Mod_poly>;  // polynomial in t with coefficients in F_p[s]/(g)
  auto F = [&](int k) {
    Ring_poly r(n + 1);
    for (int j = 0; j <= n; ++j) {
      const u64 b0 = j < int(B[0].size()) ? B[0][j] : 0, bk = j < int(B[k].size()) ? B[k][j] : 0;
      Mod_poly c(std::max(A[k].size(), A[0].size()), 0);
      for (std::size_t i = 0; i < c.size(); ++i)
        c[i] = M.sub(M.mul(i < A[k].size() ? A[k][i] : 0, b0), M.mul(i < A[0].size() ? A[0][i] : 0, bk));
      trim(c);
      reduce_monic(c, g, M);
      r[j] = c;
    }
    return r;
  };
  auto trim_ring = [](Ring_poly& f) {
    while (!f.empty() && f.back().empty()) f.pop_back();
  };
  for (int restart = 0; restart < 64; ++restart) {
    Ring_poly a = F(1), b = F(2);
    trim_ring(a);
    trim_ring(b);
    if (a.size() < b.size()) a.swap(b);
    bool restarted = false;
    while (!b.empty()) {
      if (b.size() == 1) {  // a nonzero constant c(s): common zeros only where c vanishes
        const Mod_poly h = monic_gcd(g, b[0], M);
        if (h.size() <= 1) {
          g = Mod_poly{M.one()};
          return true;
        }
        g = h;
        restarted = true;
        break;
      }
      Mod_poly il;
      if (!inverse_mod(b.back(), g, il, M)) return false;  // zero divisor: different degree patterns over g
      while (a.size() >= b.size()) {
        const Mod_poly q = mulmod(a.back(), il, g, M);
        const std::size_t sh = a.size() - b.size();
        for (std::size_t j = 0; j < b.size(); ++j) {
          a[sh + j] = sub(a[sh + j], mul(q, b[j], M), M);
          reduce_monic(a[sh + j], g, M);
        }
        trim_ring(a);
      }
      a.swap(b);
    }
    if (restarted) continue;
    if (a.size() != 2) return false;  // the gcd has degree >= 2 in t (or is zero): not a shape basis
    Mod_poly il;
    if (!inverse_mod(a[1], g, il, M)) return false;
    psi = mulmod(sub(Mod_poly(), a[0], M), il, g, M);
    // F_3(s, psi(s)) modulo g (Horner in t)
    const Ring_poly f3 = F(3);
    Mod_poly v;
    for (std::size_t j = f3.size(); j-- > 0;) {
      v = sub(mul(v, psi, M), sub(Mod_poly(), f3[j], M), M);
      reduce_monic(v, g, M);
    }
    const Mod_poly h = v.empty() ? g : monic_gcd(g, v, M);
    if (h.size() == g.size()) return true;
    g = h;
    if (g.size() <= 1) {
      psi.clear();
      return true;
    }
    psi = rem(psi, g, M);
    return true;
  }
  return false;
}

// ---------------------------------------------------------------- exact verification in Z[u]/(G~)
// With g = G / l (G integer, leading coefficient l) the substitution s = u / l makes G~(u) = l^(d-1) G(u / l) monic
// with integer coefficients, so that arithmetic modulo G~ needs no division. psi(u / l) = N~(u) / D with
// N~_i = N_i l^(d-1-i), D = L l^(d-1) (psi = N / L); A(u / l) = A~(u) / l^m with A~_i = A_i l^(m-i).
// F_k(s, psi(s)) = 0 mod g  <=>  A~_k beta_0 - beta_k A~_0 = 0 mod G~, beta_k = D^n B_k(N~ / D) (Horner).

/// a * b modulo the monic integer G (deg a, deg b < deg G).
inline Mpz_vector zmulmod(const Mpz_vector& a, const Mpz_vector& b, const Mpz_vector& G) {
  const std::size_t d = G.size() - 1;
  Mpz_vector r(a.size() + b.size() > 0 ? a.size() + b.size() - 1 : 0);
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].sign() != 0)
      for (std::size_t j = 0; j < b.size(); ++j) mpz_addmul(r[i + j].get(), a[i].get(), b[j].get());
  for (std::size_t i = r.size(); i-- > d;) {
    if (r[i].sign() == 0) continue;
    for (std::size_t j = 0; j < d; ++j) mpz_submul(r[i - d + j].get(), r[i].get(), G[j].get());
  }
  if (r.size() > d) r.resize(d);
  return r;
}

inline Mpz_vector zreduce(Mpz_vector r, const Mpz_vector& G) {
  const std::size_t d = G.size() - 1;
  for (std::size_t i = r.size(); i-- > d;) {
    if (r[i].sign() == 0) continue;
    for (std::size_t j = 0; j < d; ++j) mpz_submul(r[i - d + j].get(), r[i].get(), G[j].get());
  }
  if (r.size() > d) r.resize(d);
  return r;
}

/// True iff F_k(s, psi(s)) = 0 modulo g for k = 1..3 (g monic of degree >= 1, deg psi < deg g), exactly.
inline bool verify(const std::array<Polynomial_1<Integer>, 4>& A, const std::array<Polynomial_1<Integer>, 4>& B,
                   const std::vector<Rational>& g, const std::vector<Rational>& psi) {
  const std::size_t d = g.size() - 1;
  Mpz l(1), L(1), t;
  for (const Rational& c : g) mpz_lcm(l.get(), l.get(), mpq_denref(c.mpq()));
  for (const Rational& c : psi) mpz_lcm(L.get(), L.get(), mpq_denref(c.mpq()));
  std::vector<Mpz> lp(std::max<std::size_t>(d + 1, 8));  // powers of l
  auto lpow = [&](std::size_t e) -> const Mpz& {
    if (e >= lp.size()) lp.resize(e + 1);
    mpz_pow_ui(lp[e].get(), l.get(), (unsigned long)e);
    return lp[e];
  };
  Mpz_vector G(d + 1), N(d);
  for (std::size_t i = 0; i <= d; ++i) {  // G~_i = g_i l l^(d-1-i) = g_i l^(d-i)
    mpz_divexact(t.get(), l.get(), mpq_denref(g[i].mpq()));
    mpz_mul(G[i].get(), t.get(), mpq_numref(g[i].mpq()));
    mpz_mul(G[i].get(), G[i].get(), lpow(d - i).get());
    if (i < d) mpz_divexact(G[i].get(), G[i].get(), l.get());
  }
  mpz_set_ui(G[d].get(), 1);
  for (std::size_t i = 0; i < psi.size(); ++i) {  // N~_i = psi_i L l^(d-1-i)
    mpz_divexact(t.get(), L.get(), mpq_denref(psi[i].mpq()));
    mpz_mul(N[i].get(), t.get(), mpq_numref(psi[i].mpq()));
    mpz_mul(N[i].get(), N[i].get(), lpow(d - 1 - i).get());
  }
  Mpz D;
  mpz_mul(D.get(), L.get(), lpow(d - 1).get());
  int m = 0, n = 0;
  for (const auto& f : A) m = std::max(m, f.degree());
  for (const auto& f : B) n = std::max(n, f.degree());
  std::vector<Mpz> Dp(n + 1);  // powers of D
  mpz_set_ui(Dp[0].get(), 1);
  for (int j = 1; j <= n; ++j) mpz_mul(Dp[j].get(), Dp[j - 1].get(), D.get());
  std::array<Mpz_vector, 4> alpha, beta;
  for (int k = 0; k < 4; ++k) {
    Mpz_vector a;
    for (int i = 0; i <= A[k].degree(); ++i) {
      a.emplace_back();
      mpz_mul(a.back().get(), A[k][i].mpz(), lpow(std::size_t(m - i)).get());
    }
    alpha[k] = zreduce(a, G);
    Mpz_vector v;
    for (int j = n; j >= 0; --j) {
      v = zmulmod(v, N, G);
      if (j <= B[k].degree() && !CGAL::is_zero(B[k][j])) {
        if (v.empty()) v.resize(1);
        mpz_addmul(v[0].get(), B[k][j].mpz(), Dp[std::size_t(n - j)].get());
      }
    }
    beta[k] = v;
  }
  for (int k = 1; k <= 3; ++k) {
    Mpz_vector x = zmulmod(alpha[k], beta[0], G), y = zmulmod(beta[k], alpha[0], G);
    x.resize(std::max(x.size(), y.size()));
    for (std::size_t i = 0; i < y.size(); ++i) mpz_sub(x[i].get(), x[i].get(), y[i].get());
    for (const Mpz& c : x)
      if (c.sign() != 0) return false;
  }
  return true;
}

}  // namespace space_shape

/// \brief Shape basis of two space curves given by integer homogeneous power forms A = (W, X, Y, Z)(s),
/// B = (W, X, Y, Z)(t) (see Space_shape_basis), or false when none is found with at most `max_primes` word primes
/// (the common points do not have distinct s, several t per s, zero divisors, coefficients too large...).
/// Modulo each prime: gcd of the projection eliminants, W_A's roots removed, partner t from Euclid over F_p[s]/(g);
/// the monic g and psi are reconstructed from the residues (primes of the smallest degree of g kept) and accepted
/// only if F_k(s, psi(s)) = 0 modulo g holds exactly over Q for k = 1, 2, 3. The modular steps are heuristic
/// (unlucky primes, degenerate projections): only the verified result is ever returned.
inline bool space_shape_basis(const std::array<Polynomial_1<Integer>, 4>& A, const std::array<Polynomial_1<Integer>, 4>& B,
                              Space_shape_basis& out, int max_primes = 12) {
  int degree = -1;
  Incremental_chinese_remainder crt;
  for (int i = 0, used = 0, failures = 0; used < max_primes && failures < 3; ++i) {
    const u64 p = word_prime(std::size_t(i));
    const Montgomery_modulus M(p);
    std::array<Modular_polynomial, 4> Am, Bm;
    for (int k = 0; k < 4; ++k) {
      for (int e = 0; e <= A[k].degree(); ++e) Am[k].push_back(M.to_montgomery(A[k][e]));
      for (int e = 0; e <= B[k].degree(); ++e) Bm[k].push_back(M.to_montgomery(B[k][e]));
      trim(Am[k]);
      trim(Bm[k]);
    }
    Modular_polynomial g, psi;
    if (!space_shape::shape_mod_p(Am, Bm, M, g, psi)) {  // structural (several t per s ...) unless p is unlucky
      ++failures;
      continue;
    }
    ++used;
    const int d = int(g.size()) - 1;
    if (degree >= 0 && d > degree) continue;  // an unlucky prime
    if (d != degree) {
      degree = d;
      crt = Incremental_chinese_remainder(std::size_t(2 * d));
    }
    if (d == 0) {
      // no common zero modulo p: accepted only if it verifies (it does trivially: g = 1 has no roots)
      out.g = {Rational(1)};
      out.psi.clear();
      return true;
    }
    std::vector<u64> r(std::size_t(2 * d), 0);
    for (int e = 0; e < d; ++e) {
      r[e] = M.from_montgomery(g[e]);
      r[d + e] = e < int(psi.size()) ? M.from_montgomery(psi[e]) : 0;
    }
    crt.add(p, r);
    std::vector<Rational> gq(d + 1), pq(d);
    bool ok = true;
    for (int e = 0; e < d && ok; ++e)
      ok = rational_reconstruction(crt.symmetric(e), crt.product(), gq[e]) &&
           rational_reconstruction(crt.symmetric(d + e), crt.product(), pq[e]);
    if (!ok) continue;
    gq[d] = Rational(1);
    while (!pq.empty() && CGAL::is_zero(pq.back())) pq.pop_back();
    if (space_shape::verify(A, B, gq, pq)) {
      out.g = gq;
      out.psi = pq;
      return true;
    }
  }
  return false;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERSECTION_INTERNAL_SPACE_SHAPE_BASIS_H
