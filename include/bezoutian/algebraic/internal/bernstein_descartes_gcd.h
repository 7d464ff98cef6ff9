// Certified gcd and square-free factorization of univariate integer
// polynomials by multi-modular computation (cheaper to compile and to run
// than CGAL's generic gcd for the degrees used by root isolation).
//
// gcd: for primes p not dividing lc(f) lc(g), deg gcd(f mod p, g mod p) >= deg G
// (G = gcd over Z), with equality for all but finitely many p. The images
// gamma * monic gcd mod p (gamma = gcd(lc f, lc g), a multiple of lc G) of the
// primes of minimal degree are combined by the Chinese remainder theorem;
// a candidate is accepted only if its primitive part H divides f and g
// exactly in Z[x]: then H | G and deg H = min_p deg >= deg G, so H = G up to
// sign. (Standard, e.g. von zur Gathen & Gerhard, Modern Computer Algebra, 6.7.)
//
// Square-free factorization: Yun's algorithm (ibid. 14.6) with these gcds;
// every division in it is exact in Z[x] (Gauss's lemma, primitive divisors).
//
// Internal header.
#ifndef BEZOUTIAN_ALGEBRAIC_INTERNAL_BERNSTEIN_DESCARTES_GCD_H
#define BEZOUTIAN_ALGEBRAIC_INTERNAL_BERNSTEIN_DESCARTES_GCD_H

#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/algebraic/bernstein_descartes.h>

#include <algorithm>

#include <gmp.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace bezoutian {
namespace internal {

/// Removes leading zero coefficients (the zero polynomial becomes empty).
inline void trim(Mpz_vector& f) {
  while (!f.empty() && f.back().sign() == 0) f.pop_back();
}

/// Primitive part with positive leading coefficient (in place).
inline void make_canonical(Mpz_vector& f) {
  trim(f);
  if (f.empty()) return;
  remove_content(f);
  if (f.back().sign() < 0)
    for (Mpz& x : f) mpz_neg(x.get(), x.get());
}

inline Mpz_vector derivative(const Mpz_vector& f) {
  Mpz_vector d;
  for (std::size_t i = 1; i < f.size(); ++i) {
    d.emplace_back();
    mpz_mul_ui(d.back().get(), f[i].get(), static_cast<unsigned long>(i));
  }
  trim(d);
  return d;
}

/// If g (nonzero) divides f in Z[x], sets q = f / g and returns true.
inline bool exact_quotient(const Mpz_vector& f, const Mpz_vector& g, Mpz_vector& q) {
  const int n = static_cast<int>(f.size()) - 1, m = static_cast<int>(g.size()) - 1;
  q.clear();
  if (n < 0) return true;
  if (n < m) return false;
  Mpz_vector r(f);
  q.resize(n - m + 1);
  Mpz t;
  for (int k = n - m; k >= 0; --k) {
    Mpz& lead = r[k + m];
    if (!mpz_divisible_p(lead.get(), g[m].get())) return false;
    mpz_divexact(q[k].get(), lead.get(), g[m].get());
    if (q[k].sign() != 0)
      for (int i = 0; i <= m; ++i) mpz_submul(r[k + i].get(), q[k].get(), g[i].get());
  }
  for (int i = 0; i < m; ++i)
    if (r[i].sign() != 0) return false;
  return true;
}

/// Deterministic Miller-Rabin for 32-bit numbers (bases 2, 7, 61).
inline bool is_prime_u32(std::uint64_t n) {
  if (n < 2) return false;
  for (std::uint64_t p : {2u, 3u, 5u, 7u, 11u, 13u, 61u})
    if (n % p == 0) return n == p;
  std::uint64_t d = n - 1;
  int s = 0;
  while ((d & 1) == 0) { d >>= 1; ++s; }
  auto pw = [n](std::uint64_t a, std::uint64_t e) {
    std::uint64_t r = 1;
    a %= n;
    while (e) { if (e & 1) r = r * a % n; a = a * a % n; e >>= 1; }
    return r;
  };
  for (std::uint64_t a : {2u, 7u, 61u}) {
    std::uint64_t x = pw(a, d);
    if (x == 1 || x == n - 1) continue;
    bool composite = true;
    for (int i = 1; i < s && composite; ++i) {
      x = x * x % n;
      if (x == n - 1) composite = false;
    }
    if (composite) return false;
  }
  return true;
}

inline std::uint64_t inverse_mod(std::uint64_t a, std::uint64_t p) {  // p prime, a != 0
  std::uint64_t r = 1, e = p - 2;
  a %= p;
  while (e) { if (e & 1) r = r * a % p; a = a * a % p; e >>= 1; }
  return r;
}

/// Monic gcd in F_p[x] of a and b (coefficients < p, degrees trimmed by the
/// caller or not); returns it in `out` (empty if both are zero).
inline void gcd_mod_p(std::vector<std::uint64_t> a, std::vector<std::uint64_t> b, std::uint64_t p,
                      std::vector<std::uint64_t>& out) {
  auto trim_p = [](std::vector<std::uint64_t>& v) { while (!v.empty() && v.back() == 0) v.pop_back(); };
  trim_p(a);
  trim_p(b);
  while (!b.empty()) {
    const std::size_t db = b.size() - 1;
    const std::uint64_t ib = inverse_mod(b[db], p);
    while (a.size() >= b.size()) {
      const std::size_t sh = a.size() - b.size();
      const std::uint64_t q = a.back() * ib % p;
      for (std::size_t i = 0; i <= db; ++i) a[i + sh] = (a[i + sh] + (p - q) * b[i]) % p;
      trim_p(a);
    }
    std::swap(a, b);
  }
  out = a;
  if (!out.empty()) {
    const std::uint64_t il = inverse_mod(out.back(), p);
    for (std::uint64_t& x : out) x = x * il % p;
  }
}

/// gcd over Z of nonzero f and g: primitive, positive leading coefficient.
inline Mpz_vector gcd_of(Mpz_vector f, Mpz_vector g) {
  make_canonical(f);
  make_canonical(g);
  if (f.empty()) return g;
  if (g.empty()) return f;
  if (f.size() == 1 || g.size() == 1) return Mpz_vector{Mpz(1L)};
  if (f.size() < g.size()) std::swap(f, g);
  Mpz gamma;
  mpz_gcd(gamma.get(), f.back().get(), g.back().get());
  std::uint64_t p = 2147483647u;  // primes below 2^31 downwards
  std::size_t best = g.size();    // degree + 1 of the current candidate
  Mpz_vector H;                   // CRT image of gamma * gcd, coefficients in (-M/2, M/2]
  Mpz M;
  Mpz_vector sym, q;
  std::vector<std::uint64_t> fp(f.size()), gp(g.size()), hp;
  bool stable_check = false, g_tested = false;
  // Landau-Mignotte: the coefficients of gamma G / lc(G) are below
  // gamma 2^deg(g) |g|_2, so a correct image is reached after about
  // bound/30 lucky primes; far beyond that something is wrong.
  std::size_t bound_bits = mpz_sizeinbase(gamma.get(), 2) + g.size() + 2;
  {
    Mpz norm2, sq;
    for (const Mpz& x : g) { mpz_mul(sq.get(), x.get(), x.get()); mpz_add(norm2.get(), norm2.get(), sq.get()); }
    bound_bits += mpz_sizeinbase(norm2.get(), 2) / 2 + 1;
  }
  const std::size_t max_primes = 2 * (bound_bits / 30) + 200;
  for (std::size_t used = 0;; p -= 2) {
    while (!is_prime_u32(p)) p -= 2;
    if (++used > max_primes) throw Error("bezoutian: modular gcd did not converge (internal error)");
    if (mpz_fdiv_ui(f.back().get(), p) == 0 || mpz_fdiv_ui(g.back().get(), p) == 0) continue;
    for (std::size_t i = 0; i < f.size(); ++i) fp[i] = mpz_fdiv_ui(f[i].get(), p);
    for (std::size_t i = 0; i < g.size(); ++i) gp[i] = mpz_fdiv_ui(g[i].get(), p);
    gcd_mod_p(fp, gp, p, hp);
    if (hp.size() == 1) return Mpz_vector{Mpz(1L)};  // deg G <= 0
    if (hp.size() > best) continue;                    // unlucky prime
    if (hp.size() == g.size() && !g_tested) {          // is g itself the gcd?
      g_tested = true;
      if (exact_quotient(f, g, q)) return g;
    }
    const std::uint64_t gm = mpz_fdiv_ui(gamma.get(), p);
    for (std::uint64_t& x : hp) x = x * gm % p;
    if (hp.size() < best) {  // first prime, or all previous ones were unlucky
      best = hp.size();
      H.assign(best, Mpz());
      for (std::size_t i = 0; i < best; ++i) {  // symmetric residues
        if (hp[i] > p / 2) mpz_set_si(H[i].get(), -static_cast<long>(p - hp[i]));
        else mpz_set_ui(H[i].get(), static_cast<unsigned long>(hp[i]));
      }
      mpz_set_ui(M.get(), static_cast<unsigned long>(p));
      stable_check = false;
    } else {  // CRT: H += k M, k = (hp - H) M^-1 mod p taken in (-p/2, p/2],
              // so that H stays in the symmetric range (-M/2, M/2]
      const std::uint64_t Minv = inverse_mod(mpz_fdiv_ui(M.get(), p), p);
      bool changed = false;
      for (std::size_t i = 0; i < best; ++i) {
        const std::uint64_t hi = mpz_fdiv_ui(H[i].get(), p);
        const std::uint64_t k = (hp[i] + p - hi) % p * Minv % p;
        if (k == 0) continue;
        if (k > p / 2) mpz_submul_ui(H[i].get(), M.get(), static_cast<unsigned long>(p - k));
        else mpz_addmul_ui(H[i].get(), M.get(), static_cast<unsigned long>(k));
        changed = true;
      }
      mpz_mul_ui(M.get(), M.get(), static_cast<unsigned long>(p));
      stable_check = !changed;
    }
    if (stable_check) {
      // candidate: primitive part of the stable image, checked by trial division
      sym = H;
      make_canonical(sym);
      if (!sym.empty() && sym.size() == best && exact_quotient(f, sym, q) && exact_quotient(g, sym, q)) return sym;
    }
  }
}

/// Square-free factorization of a nonzero f of degree >= 1 by Yun's
/// algorithm: pairs (g_i, i) with f = c prod g_i^i, each g_i canonical,
/// square-free, pairwise coprime, of degree >= 1.
inline std::vector<std::pair<Mpz_vector, int>> square_free_factorization(Mpz_vector a) {
  std::vector<std::pair<Mpz_vector, int>> out;
  make_canonical(a);
  if (a.size() < 2) return out;
  const Mpz_vector b = derivative(a);
  const Mpz_vector c = gcd_of(a, b);
  Mpz_vector w, y, z, g, tmp;
  auto divide = [](const Mpz_vector& num, const Mpz_vector& den, Mpz_vector& res) {
    if (!exact_quotient(num, den, res)) throw Error("bezoutian: internal error in the square-free factorization");
  };
  divide(a, c, w);
  divide(b, c, y);
  auto sub_derivative = [](const Mpz_vector& y_, const Mpz_vector& w_) {  // y - w'
    Mpz_vector d = derivative(w_), r(std::max(y_.size(), d.size()));
    for (std::size_t i = 0; i < r.size(); ++i) {
      if (i < y_.size()) mpz_set(r[i].get(), y_[i].get());
      if (i < d.size()) mpz_sub(r[i].get(), r[i].get(), d[i].get());
    }
    trim(r);
    return r;
  };
  z = sub_derivative(y, w);
  for (int i = 1; w.size() > 1; ++i) {
    g = z.empty() ? w : gcd_of(w, z);
    make_canonical(g);
    if (g.size() > 1) out.emplace_back(g, i);
    divide(w, g, tmp);
    w.swap(tmp);
    if (z.empty()) break;
    divide(z, g, y);
    z = sub_derivative(y, w);
  }
  return out;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_ALGEBRAIC_INTERNAL_BERNSTEIN_DESCARTES_GCD_H
