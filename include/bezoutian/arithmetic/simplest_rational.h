// Simplest rationals in an interval (the rational of least denominator, found by continued fractions, i.e. by
// descending the Stern-Brocot tree): the sample abscissae of root isolation and of the arrangement, and the small
// rational candidates for multiple points and cut lines of the subdivision.
#ifndef BEZOUTIAN_ARITHMETIC_SIMPLEST_RATIONAL_H
#define BEZOUTIAN_ARITHMETIC_SIMPLEST_RATIONAL_H

#include <bezoutian/arithmetic/mpz.h>
#include <bezoutian/arithmetic/number_types.h>

#include <gmp.h>

#include <vector>

namespace bezoutian {
namespace internal {

/// The rational with the smallest denominator in the open interval (x, y),
/// x < y (continued fractions / Stern-Brocot).
inline Rational simplest_rational_between(const Rational& x, const Rational& y) {
  if (x < Rational(0) && y > Rational(0)) return Rational(0);
  if (y <= Rational(0)) return -simplest_rational_between(-y, -x);
  // 0 <= x < y: collect continued-fraction terms.
  std::vector<Mpz> terms;
  mpq_t u, v, t;
  mpq_init(u); mpq_init(v); mpq_init(t);
  mpq_set(u, x.mpq());
  mpq_set(v, y.mpq());
  Mpz fl, fl1;
  for (;;) {
    mpz_fdiv_q(fl.get(), mpq_numref(u), mpq_denref(u));
    mpz_add_ui(fl1.get(), fl.get(), 1);
    mpq_set_z(t, fl1.get());
    if (mpq_cmp(t, v) < 0) {  // an integer fits: floor(u) + 1 is the simplest
      terms.emplace_back(fl1.get());
      break;
    }
    mpq_set_z(t, fl.get());
    if (mpq_equal(t, u)) {  // (n, v) with v <= n + 1: n + 1/(floor(1/(v-n)) + 1)
      terms.emplace_back(fl.get());
      mpq_sub(t, v, t);
      mpq_inv(t, t);
      Mpz a;
      mpz_fdiv_q(a.get(), mpq_numref(t), mpq_denref(t));
      mpz_add_ui(a.get(), a.get(), 1);
      terms.push_back(std::move(a));
      break;
    }
    terms.emplace_back(fl.get());
    // (u, v) <- (1/(v - fl), 1/(u - fl))
    mpq_t nu;
    mpq_init(nu);
    mpq_sub(nu, v, t);
    mpq_inv(nu, nu);
    mpq_sub(v, u, t);
    mpq_inv(v, v);
    mpq_set(u, nu);
    mpq_clear(nu);
  }
  mpq_clear(u); mpq_clear(v); mpq_clear(t);
  // Evaluate [a0; a1, ..., ak] from the back.
  Mpz num(terms.back().get()), den(1L), tmp;
  for (int i = static_cast<int>(terms.size()) - 2; i >= 0; --i) {
    // value <- a_i + 1/value = (a_i num + den)/num
    mpz_mul(tmp.get(), terms[i].get(), num.get());
    mpz_add(tmp.get(), tmp.get(), den.get());
    mpz_swap(den.get(), num.get());
    mpz_swap(num.get(), tmp.get());
  }
  Rational r;
  mpq_set_num(r.mpq(), num.get());
  mpq_set_den(r.mpq(), den.get());
  mpq_canonicalize(r.mpq());
  return r;
}

/// floor(q), exactly.
inline Integer floor_of(const Rational& q) {
  Integer f;
  mpz_fdiv_q(f.mpz(), q.numerator().mpz(), q.denominator().mpz());
  return f;
}

/// The simplest rational in the closed interval [lo, hi], lo <= hi (continued fractions: an endpoint when it is
/// the simplest), or false if its denominator exceeds 2^64. An integer answer is the least integer >= lo.
inline bool simplest_rational_in(Rational lo, Rational hi, Rational& out, int depth = 0) {
  if (depth > 200) return false;
  Integer fl = floor_of(lo);
  if (Rational(fl) == lo) {
    out = lo;
    return true;
  }
  if (Rational(fl + 1) <= hi) {
    out = Rational(fl + 1);
    return true;
  }
  Rational r;
  if (!simplest_rational_in(1 / (hi - Rational(fl)), 1 / (lo - Rational(fl)), r, depth + 1)) return false;
  out = Rational(fl) + 1 / r;
  return out.denominator().bit_size() <= 64;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_ARITHMETIC_SIMPLEST_RATIONAL_H
