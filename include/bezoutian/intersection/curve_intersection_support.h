// Exact helpers for curve intersection: integer homogeneous forms, the bivariate system F_k(s,t), substitution
// of a rational function into a polynomial, inversion of a rational point, disjoint root intervals.
#ifndef BEZOUTIAN_INTERSECTION_CURVE_INTERSECTION_SUPPORT_H
#define BEZOUTIAN_INTERSECTION_CURVE_INTERSECTION_SUPPORT_H

#include <bezoutian/algebraic/Algebraic_real.h>
#include <bezoutian/geometry/Rational_bezier_curve.h>
#include <bezoutian/algebraic/Root_isolation.h>
#include <bezoutian/arithmetic/number_types.h>

#include <CGAL/Polynomial.h>
#include <CGAL/Polynomial_traits_d.h>

#include <mpfi.h>

#include <array>
#include <vector>

namespace bezoutian {
namespace internal {

using Ci_poly1 = Polynomial_1<Integer>;
using Ci_poly2 = Polynomial_2<Integer>;

/// The power form (W, X_1, .., X_D) of a curve, multiplied by one positive integer so that all coefficients are
/// integers (the same projective curve): l times the rational power form, l the least common denominator of its
/// coefficients. Computed from the integer multiple L h of the homogeneous control net h (binomial expansion
/// a_k = sum_{i<=k} (-1)^(k-i) C(n,i) C(n-i,k-i) b_i, all in integers), then divided by gcd(L, content) = L / l.
template <int D>
std::array<Ci_poly1, D + 1> integer_power_form(const Rational_bezier_curve<Rational, D>& c) {
  const auto& net = c.homogeneous_control_points();
  const int n = int(net.size()) - 1;
  mpz_t L, t, b, g;
  mpz_init_set_ui(L, 1);
  mpz_inits(t, b, g, nullptr);
  for (const auto& h : net)
    for (int k = 0; k <= D; ++k) mpz_lcm(L, L, mpq_denref(h[k].mpq()));
  std::array<std::vector<Integer>, D + 1> a;
  for (auto& v : a) v.assign(std::size_t(n + 1), Integer(0));
  for (int i = 0; i <= n; ++i)
    for (int k = 0; k <= D; ++k) {
      const Rational& q = net[i][k];
      if (CGAL::is_zero(q)) continue;
      mpz_divexact(t, L, mpq_denref(q.mpq()));
      mpz_mul(t, t, mpq_numref(q.mpq()));  // L h_ik
      mpz_bin_uiui(b, (unsigned long)n, (unsigned long)i);
      mpz_mul(t, t, b);
      for (int e = i; e <= n; ++e) {
        mpz_bin_uiui(b, (unsigned long)(n - i), (unsigned long)(e - i));
        mpz_mul(b, b, t);
        Integer& x = a[k][e];
        Integer y;
        if ((e - i) % 2) mpz_sub(y.mpz(), x.mpz(), b); else mpz_add(y.mpz(), x.mpz(), b);
        x = y;
      }
    }
  mpz_set(g, L);
  for (const auto& v : a)
    for (const Integer& x : v) mpz_gcd(g, g, x.mpz());
  std::array<Ci_poly1, D + 1> r;
  for (int k = 0; k <= D; ++k) {
    for (Integer& x : a[k])
      if (!CGAL::is_zero(x)) {
        Integer y;
        mpz_divexact(y.mpz(), x.mpz(), g);
        x = y;
      }
    r[k] = Ci_poly1(a[k].begin(), a[k].end());
  }
  mpz_clears(L, t, b, g, nullptr);
  return r;
}

/// F(s,t) = A(s) B(t) - C(t) E(s), as an element of Z[s][t] (outer variable t).
inline Ci_poly2 cross_term(const Ci_poly1& A, const Ci_poly1& B, const Ci_poly1& C, const Ci_poly1& E) {
  const int n = std::max(B.degree(), C.degree());
  std::vector<Ci_poly1> co;
  for (int j = 0; j <= n; ++j) {
    Integer b = j <= B.degree() ? B[j] : Integer(0), c = j <= C.degree() ? C[j] : Integer(0);
    co.push_back(A * Ci_poly1(b) - E * Ci_poly1(c));
  }
  return Ci_poly2(co.begin(), co.end());
}

/// Exchange the two variables of a bivariate polynomial.
inline Ci_poly2 swap_variables(const Ci_poly2& F) {
  return typename CGAL::Polynomial_traits_d<Ci_poly2>::Swap()(F, 0, 1);
}

inline int t_degree(const Ci_poly2& F) { return CGAL::is_zero(F) ? -1 : F.degree(); }

/// Numerator of P(s, N(s)/D(s)) with the common denominator D^deg_t(P): sum_j p_j(s) N^j D^(d-j).
inline Ci_poly1 substitute(const Ci_poly2& P, const Ci_poly1& N, const Ci_poly1& Dn) {
  if (CGAL::is_zero(P)) return Ci_poly1(0);
  const int d = P.degree();
  // Horner in homogeneous form: r = p_d; r = r N + p_j D^(d-j)
  Ci_poly1 r = P[d], Dpow(1);
  for (int j = d - 1; j >= 0; --j) {
    Dpow *= Dn;
    r = r * N + P[j] * Dpow;
  }
  return r;
}

/// Univariate P(t) as a bivariate polynomial independent of s.
inline Ci_poly2 lift_outer(const Ci_poly1& p) {
  std::vector<Ci_poly1> co;
  for (int i = 0; i <= p.degree(); ++i) co.push_back(Ci_poly1(p[i]));
  return Ci_poly2(co.begin(), co.end());
}

/// Sign of F on the interval [lo, hi] by MPFI interval Horner at precision prec: +-1 if certain, 0 if undecided.
inline int interval_sign_mpfi(const Ci_poly1& F, const Rational& lo, const Rational& hi, mpfr_prec_t prec) {
  mpfi_t x, v;
  mpfi_init2(x, prec);
  mpfi_init2(v, prec);
  mpfi_interv_q(x, lo.mpq(), hi.mpq());
  mpfi_set_z(v, F[F.degree()].mpz());
  for (int i = F.degree() - 1; i >= 0; --i) {
    mpfi_mul(v, v, x);
    mpfi_add_z(v, v, F[i].mpz());
  }
  const int s = mpfi_is_strictly_pos(v) ? 1 : (mpfi_is_strictly_neg(v) ? -1 : 0);
  mpfi_clear(x);
  mpfi_clear(v);
  return s;
}

/// Exact sign of F at the algebraic number a. Filter: MPFI Horner on a's isolating interval at growing precision
/// while the interval is refined (Newton, exact checks); if that does not decide (F(a) = 0 or very close),
/// Algebraic_real::sign_of decides exactly (gcd with the defining polynomial).
inline int root_sign(const Algebraic_real& a, const Ci_poly1& F) {
  if (CGAL::is_zero(F)) return 0;
  if (a.is_rational()) {
    const Rational x = a.rational_value();
    Rational v(0);
    for (int i = F.degree(); i >= 0; --i) v = v * x + Rational(F[i]);
    return CGAL::sign(v);
  }
  if (F.degree() == 0) return CGAL::sign(F[0]);
  int bits = 0;
  for (int i = 0; i <= F.degree(); ++i) bits = std::max(bits, int(F[i].bit_size()));
  // Horner on an interval of width w errs by about 2^bits * deg * w: refine geometrically in the exponent and
  // carry enough precision to represent the interval ends.
  long wexp = 0;  // the interval width is about 2^-wexp
  for (int round = 0; round < 8; ++round) {
    if (a.is_rational()) return root_sign(a, F);
    const Rational w = a.upper() - a.lower();
    wexp = long(mpz_sizeinbase(w.denominator().mpz(), 2)) - long(mpz_sizeinbase(w.numerator().mpz(), 2));
    const mpfr_prec_t prec = mpfr_prec_t(std::max(64L, long(bits) + std::max(0L, wexp) + 2 * F.degree() + 64));
    const int s = interval_sign_mpfi(F, a.lower(), a.upper(), prec);
    if (s != 0) return s;
    Integer p2(1);
    mpz_mul_2exp(p2.mpz(), p2.mpz(), (unsigned long)(round == 0 ? 64 : (32UL << round)));
    a.refine_to_width(w / Rational(p2));
  }
  const int ex = a.sign_of(F);
  return ex;
}

inline int root_sign(const Algebraic_real& a, const Polynomial_1<Rational>& f) {
  std::vector<Integer> c;
  Integer l(1);
  for (int i = 0; i <= f.degree(); ++i) l = CGAL::div(l * f[i].denominator(), CGAL::gcd(l, f[i].denominator()));
  for (int i = 0; i <= f.degree(); ++i) c.push_back((f[i] * Rational(l)).numerator());
  return root_sign(a, Ci_poly1(c.begin(), c.end()));
}

/// Removes every factor w (a polynomial without roots in [0,1], e.g. a weight) from f: f / w^k, exactly.
/// Res_t(F1,F2) contains W1(s)^deg W2 (common roots at infinity: W1(s) = 0 makes all F_k multiples of W2(t)).
inline Ci_poly1 divide_out(Ci_poly1 f, const Ci_poly1& w) {
  if (CGAL::is_zero(f) || w.degree() < 1) return f;
  for (;;) {
    Ci_poly1 q, r;
    Integer d;
    Ci_poly1::pseudo_division(f, w, q, r, d);
    if (!CGAL::is_zero(r) || q.degree() < 0) return f;
    q = CGAL::canonicalize(q);
    if (CGAL::is_zero(q)) return f;
    f = q;
    if (f.degree() < w.degree()) return f;
  }
}

/// Make the isolating intervals of sorted distinct roots pairwise disjoint (rationals outside the neighbours'
/// intervals), so that each irrational interval (lo,hi) holds exactly one root of the whole polynomial.
inline void separate_roots(std::vector<Isolated_root>& r) {
  for (std::size_t i = 0; i + 1 < r.size(); ++i) {
    const Algebraic_real &a = r[i].root, &b = r[i + 1].root;
    for (;;) {
      const Rational ahi = a.is_rational() ? a.rational_value() : a.upper();
      const Rational blo = b.is_rational() ? b.rational_value() : b.lower();
      if (ahi < blo || (a.is_rational() && b.is_rational())) break;
      if (!a.is_rational()) a.refine();
      if (!b.is_rational()) b.refine();
    }
  }
}

/// All parameters t in [0,1] of the curve with homogeneous form H at the rational point p (W(t) != 0 assumed in
/// [0,1]). Returns false (and nothing) if the curve is constant equal to p.
template <int D>
bool invert_point(const std::array<Ci_poly1, D + 1>& H, const std::array<Rational, D>& p,
                  std::vector<Algebraic_real>& out) {
  Polynomial_1<Rational> g(0);
  auto to_q = [](const Ci_poly1& f) {
    std::vector<Rational> c;
    for (int i = 0; i <= f.degree(); ++i) c.push_back(Rational(f[i]));
    return Polynomial_1<Rational>(c.begin(), c.end());
  };
  const Polynomial_1<Rational> W = to_q(H[0]);
  for (int k = 0; k < D; ++k) {
    Polynomial_1<Rational> e = to_q(H[k + 1]) - W * Polynomial_1<Rational>(p[k]);
    g = CGAL::is_zero(g) ? e : (CGAL::is_zero(e) ? g : Polynomial_1<Rational>(CGAL::gcd(g, e)));
  }
  if (CGAL::is_zero(g)) return false;
  if (g.degree() == 0) return true;
  for (const Isolated_root& r : isolate_real_roots(g, Rational(0), Rational(1))) out.push_back(r.root);
  return true;
}

/// Exact value of a homogeneous form at a rational parameter, as a Cartesian point (W != 0 required).
template <int D>
std::array<Rational, D> point_at(const std::array<Ci_poly1, D + 1>& H, const Rational& s) {
  auto ev = [&](const Ci_poly1& f) {
    Rational r(0);
    for (int i = f.degree(); i >= 0; --i) r = r * s + Rational(f[i]);
    return r;
  };
  const Rational w = ev(H[0]);
  std::array<Rational, D> p;
  for (int k = 0; k < D; ++k) p[k] = ev(H[k + 1]) / w;
  return p;
}

} // namespace internal
} // namespace bezoutian

#endif
