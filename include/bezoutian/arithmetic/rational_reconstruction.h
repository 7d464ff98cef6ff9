// Rational reconstruction (Wang's algorithm): the fraction n/d with |n|, d <= sqrt(m/2) congruent to a residue
// modulo m, for multi-modular algorithms whose results are rational (modular_groebner.h).
//
// Internal header: not part of the public API.
#ifndef BEZOUTIAN_ARITHMETIC_RATIONAL_RECONSTRUCTION_H
#define BEZOUTIAN_ARITHMETIC_RATIONAL_RECONSTRUCTION_H

#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <gmp.h>

namespace bezoutian {
namespace internal {

/// Wang's rational reconstruction: given u (any representative) modulo m > 1, finds n/d with n/d = u mod m,
/// |n| <= B and 0 < d <= B, B = floor(sqrt(m/2)). Such a fraction is unique if it exists (two of them would give
/// |n d' - n' d| < m, a multiple of m, hence n/d = n'/d'). The extended Euclidean algorithm on (m, u) stops at the
/// first remainder r_k <= B; the candidate is r_k / t_k (Bezout cofactor t_k of u), accepted if |t_k| <= B and
/// gcd(r_k, t_k) = 1 (Wang 1981; von zur Gathen and Gerhard, Modern Computer Algebra, §5.10).
/// Returns false if no such fraction exists.
inline bool rational_reconstruction(const CGAL::Gmpz& u, const CGAL::Gmpz& m, CGAL::Gmpq& out) {
  mpz_t r0, r1, t0, t1, q, tmp, bound;
  mpz_inits(r0, r1, t0, t1, q, tmp, bound, nullptr);
  mpz_set(r0, m.mpz());
  mpz_fdiv_r(r1, u.mpz(), m.mpz());  // 0 <= r1 < m
  mpz_set_ui(t0, 0);
  mpz_set_ui(t1, 1);
  mpz_fdiv_q_2exp(bound, m.mpz(), 1);
  mpz_sqrt(bound, bound);  // floor(sqrt(floor(m/2))) = floor(sqrt(m/2))
  while (mpz_cmp(r1, bound) > 0) {
    mpz_fdiv_qr(q, tmp, r0, r1);  // r0 = q r1 + tmp
    mpz_swap(r0, r1);
    mpz_swap(r1, tmp);            // (r0, r1) <- (r1, r0 mod r1)
    mpz_mul(tmp, q, t1);
    mpz_sub(tmp, t0, tmp);
    mpz_swap(t0, t1);
    mpz_swap(t1, tmp);            // (t0, t1) <- (t1, t0 - q t1)
  }
  bool ok = mpz_sgn(t1) != 0 && mpz_cmpabs(t1, bound) <= 0;
  if (ok) {
    mpz_gcd(tmp, r1, t1);
    ok = mpz_cmp_ui(tmp, 1) == 0;
  }
  if (ok) {
    if (mpz_sgn(t1) < 0) {
      mpz_neg(t1, t1);
      mpz_neg(r1, r1);
    }
    CGAL::Gmpq v;  // fresh object (CGAL::Gmpq copies share their representation)
    mpq_set_num(v.mpq(), r1);
    mpq_set_den(v.mpq(), t1);
    out = v;
  }
  mpz_clears(r0, r1, t0, t1, q, tmp, bound, nullptr);
  return ok;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_ARITHMETIC_RATIONAL_RECONSTRUCTION_H
