// Helpers shared by Algebraic_real and the root isolation functions:
// polynomial conversions, the affine map of [a,b] onto [0,1], square-free
// isolation returning rational intervals, a Newton approximation (MPFR) whose
// results are always re-checked exactly, the simplest rational in an
// interval, decimal rounding and a modular test for rational roots.
// Internal header.
#ifndef BEZOUTIAN_ALGEBRAIC_INTERNAL_BERNSTEIN_DESCARTES_SUPPORT_H
#define BEZOUTIAN_ALGEBRAIC_INTERNAL_BERNSTEIN_DESCARTES_SUPPORT_H

#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/arithmetic/simplest_rational.h>
#include <bezoutian/algebraic/bernstein_descartes.h>
#include <bezoutian/algebraic/internal/bernstein_descartes_gcd.h>

#include <mpfr.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

namespace bezoutian {
namespace internal {

/// Coefficients (index = power) of an integer polynomial.
inline Mpz_vector coefficients_of(const Polynomial_1<Integer>& p) {
  Mpz_vector c;
  if (CGAL::is_zero(p)) return c;
  c.reserve(p.degree() + 1);
  for (int i = 0; i <= p.degree(); ++i) c.emplace_back(p[i].mpz());
  return c;
}

inline Polynomial_1<Integer> polynomial_of(const Mpz_vector& c) {
  std::vector<Integer> v;
  v.reserve(c.size());
  for (const Mpz& x : c) v.emplace_back(x.get());
  if (v.empty()) return Polynomial_1<Integer>(Integer(0));
  return Polynomial_1<Integer>(v.begin(), v.end());
}

/// Primitive part with positive leading coefficient (zero stays zero).
inline Polynomial_1<Integer> canonical_integer(const Polynomial_1<Integer>& p) {
  if (CGAL::is_zero(p)) return p;
  Mpz_vector c = coefficients_of(p);
  remove_content(c);
  if (c.back().sign() < 0)
    for (Mpz& x : c) mpz_neg(x.get(), x.get());
  return polynomial_of(c);
}

/// A positive multiple of f with integer coefficients (denominators cleared).
inline Polynomial_1<Integer> integer_multiple(const Polynomial_1<Rational>& f) {
  if (CGAL::is_zero(f)) return Polynomial_1<Integer>(Integer(0));
  Mpz l(1L);
  for (int i = 0; i <= f.degree(); ++i) mpz_lcm(l.get(), l.get(), mpq_denref(f[i].mpq()));
  std::vector<Integer> v;
  Mpz t;
  for (int i = 0; i <= f.degree(); ++i) {
    mpz_divexact(t.get(), l.get(), mpq_denref(f[i].mpq()));
    mpz_mul(t.get(), t.get(), mpq_numref(f[i].mpq()));
    v.emplace_back(t.get());
  }
  return Polynomial_1<Integer>(v.begin(), v.end());
}
inline Polynomial_1<Integer> integer_multiple(const Polynomial_1<Integer>& f) { return f; }

/// Coefficients of D^n g((A + B t)/D), a positive multiple of g(a + (b-a) t)
/// for a = A/D, b - a = B/D, by the homogeneous Horner scheme; content removed.
inline Mpz_vector map_to_unit_interval(const Mpz_vector& g, const Rational& a, const Rational& b) {
  const int n = static_cast<int>(g.size()) - 1;
  if (a == Rational(0) && b == Rational(1)) {
    Mpz_vector r(g);
    remove_content(r);
    return r;
  }
  mpz_srcptr pa = mpq_numref(a.mpq()), qa = mpq_denref(a.mpq());
  mpz_srcptr pb = mpq_numref(b.mpq()), qb = mpq_denref(b.mpq());
  Mpz D, A, B, t;
  mpz_mul(D.get(), qa, qb);
  mpz_mul(A.get(), pa, qb);
  mpz_mul(B.get(), pb, qa);
  mpz_sub(B.get(), B.get(), A.get());
  Mpz_vector H(n + 1);
  Mpz Dp(1L);
  mpz_set(H[0].get(), g[n].get());
  for (int i = n - 1; i >= 0; --i) {
    const int deg = n - 1 - i;
    mpz_mul(H[deg + 1].get(), H[deg].get(), B.get());
    for (int j = deg; j >= 1; --j) {
      mpz_mul(H[j].get(), H[j].get(), A.get());
      mpz_mul(t.get(), H[j - 1].get(), B.get());
      mpz_add(H[j].get(), H[j].get(), t.get());
    }
    mpz_mul(H[0].get(), H[0].get(), A.get());
    mpz_mul(Dp.get(), Dp.get(), D.get());
    mpz_mul(t.get(), g[i].get(), Dp.get());
    mpz_add(H[0].get(), H[0].get(), t.get());
  }
  remove_content(H);
  return H;
}

/// Exact sign of the integer polynomial c at the rational x (shifts instead
/// of products when the denominator is a power of two).
inline int sign_at(const Mpz_vector& c, const Rational& x) {
  mpz_srcptr den = mpq_denref(x.mpq());
  if (mpz_popcount(den) == 1) return sign_at_dyadic(c, mpq_numref(x.mpq()), mpz_sizeinbase(den, 2) - 1);
  return sign_at(c, mpq_numref(x.mpq()), den);
}

/// The rational a + (b - a) k / 2^d.
inline Rational affine_point(const Rational& a, const Rational& w, mpz_srcptr k, unsigned long d) {
  Mpz den(1L);
  mpz_mul_2exp(den.get(), den.get(), d);
  Rational t;
  mpq_set_num(t.mpq(), k);
  mpq_set_den(t.mpq(), den.get());
  mpq_canonicalize(t.mpq());
  return a + w * t;
}

/// One root of a square-free polynomial found on [a,b]: an exact rational
/// (lo == hi) or an open interval (lo, hi) holding exactly one root, with
/// g(lo), g(hi) nonzero and sign_lo = sign g(lo).
struct Rational_isolating_interval {
  Rational lo, hi;
  bool exact = false;
  int sign_lo = 0;
};

/// Roots in [a,b] (a < b) of g, which must have no multiple root in [a,b]
/// (e.g. square-free), sorted increasingly.
inline std::vector<Rational_isolating_interval> isolate_square_free(const Mpz_vector& g, const Rational& a,
                                                                    const Rational& b,
                                                                    Isolation_statistics* stats = nullptr,
                                                                    bool float_filter = true) {
  Bernstein_descartes_isolator iso(map_to_unit_interval(g, a, b));
  iso.set_float_filter(float_filter);
  std::vector<Dyadic_root> dr = iso.run();
  if (stats) *stats = iso.statistics();
  std::vector<Rational_isolating_interval> out;
  out.reserve(dr.size());
  const Rational w = b - a;
  for (Dyadic_root& r : dr) {
    Rational_isolating_interval iv;
    iv.lo = affine_point(a, w, r.k.get(), r.d);
    if (r.exact) {
      iv.hi = iv.lo;
      iv.exact = true;
    } else {
      mpz_add_ui(r.k.get(), r.k.get(), 1);
      iv.hi = affine_point(a, w, r.k.get(), r.d);
      iv.sign_lo = r.sign_lo;  // G is a positive multiple of g on [a,b]
    }
    out.push_back(std::move(iv));
  }
  return out;
}

/// An exponent L with all complex roots of c strictly inside |z| < 2^L
/// (Fujiwara's bound |z| <= 2 max_i |c_(n-i)/c_n|^(1/i), rounded up to powers of two).
inline long root_bound_exponent(const Mpz_vector& c) {
  const int n = static_cast<int>(c.size()) - 1;
  const long bn = static_cast<long>(mpz_sizeinbase(c[n].get(), 2));
  long L = 0;
  for (int i = 1; i <= n; ++i) {
    if (c[n - i].sign() == 0) continue;
    const long bi = static_cast<long>(mpz_sizeinbase(c[n - i].get(), 2));
    // |c_(n-i)/c_n| < 2^(bi - bn + 1); the i-th root is < 2^ceil((bi-bn+1)/i)
    const long e = bi - bn + 1;  // (for i = n Fujiwara has |c_0/(2 c_n)|: we overestimate)
    const long q = e >= 0 ? (e + i - 1) / i : -((-e) / i);
    L = std::max(L, q + 1);
  }
  return L;
}

/// True if the polynomial c (degree >= 1, no zero root) provably has no
/// rational root: for a prime l not dividing the leading coefficient, a root
/// p/q (q | lc) would give the root p q^(-1) of c modulo l; so it suffices
/// that c has no root modulo one such l. False means "not proved".
inline bool has_no_rational_root_modular(const Mpz_vector& c) {
  static const unsigned long primes[] = {3,  5,  7,  11, 13, 17, 19, 23, 29, 31, 37, 41,  43,  47,  53,  59,
                                         61, 67, 71, 73, 79, 83, 89, 97, 101, 103, 107, 109, 113, 127, 131, 137};
  const int n = static_cast<int>(c.size()) - 1;
  if (n < 1 || c[0].sign() == 0) return false;
  std::vector<unsigned long> r(n + 1);
  for (unsigned long l : primes) {
    if (mpz_fdiv_ui(c[n].get(), l) == 0) continue;
    for (int i = 0; i <= n; ++i) r[i] = mpz_fdiv_ui(c[i].get(), l);
    bool root = false;
    for (unsigned long x = 0; x < l && !root; ++x) {
      unsigned long v = r[n];
      for (int i = n - 1; i >= 0; --i) v = (v * x + r[i]) % l;
      root = (v == 0);
    }
    if (!root) return true;
  }
  return false;
}

/// Rounds the nonzero rational x to `digits` significant decimal digits,
/// to nearest with ties away from zero: returns (E, N) with
/// 10^(digits-1) <= N < 10^digits and |x| ~ N 10^(E - digits + 1).
inline std::pair<long, std::string> round_to_significant(const Rational& x, int digits) {
  Mpz P, Q, ten(10L), p10, lhs, rhs;
  mpz_abs(P.get(), mpq_numref(x.mpq()));
  mpz_set(Q.get(), mpq_denref(x.mpq()));
  // E = floor(log10 |x|): estimate, then correct with exact comparisons.
  long E = static_cast<long>(std::floor((static_cast<double>(mpz_sizeinbase(P.get(), 2)) -
                                         static_cast<double>(mpz_sizeinbase(Q.get(), 2))) *
                                        0.30102999566398120));
  auto cmp_pow = [&](long e) {  // sign of |x| - 10^e
    mpz_ui_pow_ui(p10.get(), 10, static_cast<unsigned long>(std::labs(e)));
    if (e >= 0) { mpz_mul(rhs.get(), Q.get(), p10.get()); return mpz_cmp(P.get(), rhs.get()); }
    mpz_mul(lhs.get(), P.get(), p10.get());
    return mpz_cmp(lhs.get(), Q.get());
  };
  while (cmp_pow(E) < 0) --E;
  while (cmp_pow(E + 1) >= 0) ++E;
  // N = round(|x| 10^(digits-1-E)) = floor((2 P 10^t + Q) / (2 Q)) (t may be < 0)
  const long t = digits - 1 - E;
  mpz_ui_pow_ui(p10.get(), 10, static_cast<unsigned long>(std::labs(t)));
  if (t >= 0) { mpz_mul(lhs.get(), P.get(), p10.get()); mpz_set(rhs.get(), Q.get()); }
  else { mpz_set(lhs.get(), P.get()); mpz_mul(rhs.get(), Q.get(), p10.get()); }
  mpz_mul_2exp(lhs.get(), lhs.get(), 1);
  mpz_add(lhs.get(), lhs.get(), rhs.get());
  mpz_mul_2exp(rhs.get(), rhs.get(), 1);
  Mpz N;
  mpz_fdiv_q(N.get(), lhs.get(), rhs.get());
  mpz_ui_pow_ui(p10.get(), 10, static_cast<unsigned long>(digits));
  if (mpz_cmp(N.get(), p10.get()) >= 0) {  // rounding carried into a new digit
    mpz_ui_pow_ui(N.get(), 10, static_cast<unsigned long>(digits - 1));
    ++E;
  }
  std::vector<char> buf(mpz_sizeinbase(N.get(), 10) + 2);
  mpz_get_str(buf.data(), 10, N.get());
  return {E, std::string(buf.data())};
}

/// Formats the rounded value: plain notation when -5 <= E < digits, otherwise
/// d.ddd...e<E>. Trailing zeros are kept (they are significant digits).
inline std::string format_significant(bool negative, long E, const std::string& D) {
  std::string s = negative ? "-" : "";
  const long nd = static_cast<long>(D.size());
  if (E >= -5 && E < nd) {
    if (E >= 0) {
      s += D.substr(0, E + 1);
      if (E + 1 < nd) s += "." + D.substr(E + 1);
    } else {
      s += "0." + std::string(static_cast<std::size_t>(-E - 1), '0') + D;
    }
  } else {
    s += D.substr(0, 1);
    if (nd > 1) s += "." + D.substr(1);
    s += "e" + std::to_string(E);
  }
  return s;
}

inline std::string rational_to_decimal_string(const Rational& x, int digits) {
  if (CGAL::is_zero(x)) return "0";
  auto r = round_to_significant(x, digits);
  return format_significant(x < Rational(0), r.first, r.second);
}

/// RAII mpfr_t.
class Mpfr {
 public:
  explicit Mpfr(mpfr_prec_t p) { mpfr_init2(v_, p); }
  Mpfr(const Mpfr&) = delete;
  Mpfr& operator=(const Mpfr&) = delete;
  ~Mpfr() { mpfr_clear(v_); }
  mpfr_ptr get() { return v_; }
 private:
  mpfr_t v_;
};

/// Safeguarded Newton iteration in MPFR for the root of c in (lo, hi): a
/// heuristic approximation only (its callers re-check it with exact signs).
/// Returns x rounded to a multiple of 2^-bits.
inline Rational newton_approximation(const Mpz_vector& c, const Rational& lo, const Rational& hi, int sign_lo,
                                     unsigned long bits) {
  const int n = static_cast<int>(c.size()) - 1;
  std::size_t cbits = 0;
  for (const Mpz& x : c) cbits = std::max(cbits, mpz_sizeinbase(x.get(), 2));
  const double mag = std::max(std::fabs(CGAL::to_double(lo)), std::fabs(CGAL::to_double(hi)));
  const long magbits = mag > 1 ? static_cast<long>(std::ceil(std::log2(mag))) * n : 0;
  const mpfr_prec_t prec = static_cast<mpfr_prec_t>(bits + cbits + magbits + 2 * 64);
  Mpfr x(prec), L(prec), H(prec), f(prec), df(prec), step(prec), tol(prec);
  mpfr_set_q(L.get(), lo.mpq(), MPFR_RNDN);
  mpfr_set_q(H.get(), hi.mpq(), MPFR_RNDN);
  mpfr_add(x.get(), L.get(), H.get(), MPFR_RNDN);
  mpfr_div_2ui(x.get(), x.get(), 1, MPFR_RNDN);
  mpfr_set_ui_2exp(tol.get(), 1, -static_cast<mpfr_exp_t>(bits + 4), MPFR_RNDN);
  const int max_iter = 200 + 4 * static_cast<int>(std::log2(static_cast<double>(prec) + 2));
  for (int it = 0; it < max_iter; ++it) {
    mpfr_set_z(f.get(), c[n].get(), MPFR_RNDN);
    mpfr_set_ui(df.get(), 0, MPFR_RNDN);
    for (int i = n - 1; i >= 0; --i) {
      mpfr_mul(df.get(), df.get(), x.get(), MPFR_RNDN);
      mpfr_add(df.get(), df.get(), f.get(), MPFR_RNDN);
      mpfr_mul(f.get(), f.get(), x.get(), MPFR_RNDN);
      mpfr_add_z(f.get(), f.get(), c[i].get(), MPFR_RNDN);
    }
    if (mpfr_zero_p(f.get())) break;
    if (mpfr_sgn(f.get()) == sign_lo) mpfr_set(L.get(), x.get(), MPFR_RNDN);
    else mpfr_set(H.get(), x.get(), MPFR_RNDN);
    bool bisect = mpfr_zero_p(df.get());
    if (!bisect) {
      mpfr_div(step.get(), f.get(), df.get(), MPFR_RNDN);
      mpfr_sub(f.get(), x.get(), step.get(), MPFR_RNDN);  // f <- candidate
      bisect = !(mpfr_greater_p(f.get(), L.get()) && mpfr_less_p(f.get(), H.get()));
    }
    if (bisect) {
      mpfr_add(f.get(), L.get(), H.get(), MPFR_RNDN);
      mpfr_div_2ui(f.get(), f.get(), 1, MPFR_RNDN);
    }
    mpfr_sub(step.get(), f.get(), x.get(), MPFR_RNDN);
    mpfr_abs(step.get(), step.get(), MPFR_RNDN);
    mpfr_set(x.get(), f.get(), MPFR_RNDN);
    mpfr_sub(df.get(), H.get(), L.get(), MPFR_RNDN);
    if (mpfr_lessequal_p(step.get(), tol.get()) || mpfr_lessequal_p(df.get(), tol.get())) break;
  }
  // round to a multiple of 2^-bits
  mpfr_mul_2ui(x.get(), x.get(), bits, MPFR_RNDN);
  Mpz z;
  mpfr_get_z(z.get(), x.get(), MPFR_RNDN);
  Mpz den(1L);
  mpz_mul_2exp(den.get(), den.get(), bits);
  Rational r;
  mpq_set_num(r.mpq(), z.get());
  mpq_set_den(r.mpq(), den.get());
  mpq_canonicalize(r.mpq());
  return r;
}

/// True if f (degree n >= 1) is proved square-free: for a prime p not
/// dividing n lc(f), gcd(f mod p, f' mod p) = 1 means the resultant of f and
/// f' (the discriminant up to lc) is nonzero mod p, hence nonzero.
/// False means "not proved" (f not square-free, or unlucky primes).
inline bool is_square_free_modular(const Mpz_vector& c) {
  static const std::uint64_t primes[] = {2147483647u, 2147483629u, 2147483587u};
  const int n = static_cast<int>(c.size()) - 1;
  if (n < 1) return false;
  if (n == 1) return true;
  for (std::uint64_t p : primes) {
    if (mpz_fdiv_ui(c[n].get(), p) == 0 || static_cast<std::uint64_t>(n) % p == 0) continue;
    auto inv = [p](std::uint64_t a) {  // a^(p-2) mod p
      std::uint64_t r = 1, e = p - 2;
      a %= p;
      while (e) {
        if (e & 1) r = r * a % p;
        a = a * a % p;
        e >>= 1;
      }
      return r;
    };
    std::vector<std::uint64_t> a(n + 1), b(n);
    for (int i = 0; i <= n; ++i) a[i] = mpz_fdiv_ui(c[i].get(), p);
    for (int i = 1; i <= n; ++i) b[i - 1] = a[i] * static_cast<std::uint64_t>(i) % p;
    // Euclid in F_p[x]; a, b hold coefficients, degrees tracked explicitly.
    int da = n, db = n - 1;
    while (db >= 0 && b[db] == 0) --db;
    while (db > 0) {
      const std::uint64_t ib = inv(b[db]);
      while (da >= db) {
        const std::uint64_t q = a[da] * ib % p;
        const int sh = da - db;
        for (int i = 0; i <= db; ++i) a[i + sh] = (a[i + sh] + (p - q) * b[i]) % p;
        while (da >= 0 && a[da] == 0) --da;
        if (da < 0) break;
      }
      std::swap(a, b);
      std::swap(da, db);
    }
    if (db == 0) return true;  // nonzero constant gcd
  }
  return false;
}

/// Square-free factorization f = c prod g_i^(m_i) with canonical (primitive,
/// positive leading coefficient) pairwise coprime square-free g_i of degree >= 1.
/// Square-free inputs are recognised by a modular certificate; the others go
/// through Yun's algorithm with certified modular gcds (bernstein_descartes_gcd.h).
inline std::vector<std::pair<Polynomial_1<Integer>, int>> square_free_factors(const Polynomial_1<Integer>& f) {
  std::vector<std::pair<Polynomial_1<Integer>, int>> out;
  if (CGAL::is_zero(f) || f.degree() < 1) return out;
  const Mpz_vector c = coefficients_of(f);
  if (is_square_free_modular(c)) {
    out.emplace_back(canonical_integer(f), 1);
    return out;
  }
  for (const auto& gm : square_free_factorization(c)) out.emplace_back(polynomial_of(gm.first), gm.second);
  return out;
}

/// gcd of two nonzero integer polynomials: primitive, positive leading coefficient.
inline Polynomial_1<Integer> gcd_of(const Polynomial_1<Integer>& f, const Polynomial_1<Integer>& g) {
  return polynomial_of(gcd_of(coefficients_of(f), coefficients_of(g)));
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_ALGEBRAIC_INTERNAL_BERNSTEIN_DESCARTES_SUPPORT_H
