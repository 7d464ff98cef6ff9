// The tangent cone of a multiple point of a plane curve, proved by blowing the point up.
//
// Let p be a point where D and all its partial derivatives of order < k vanish (a point of multiplicity >= k of
// D = 0), and write D(p + (x, y)) = sum_{a+b >= k} c_ab x^a y^b. Blowing p up in the chart y = m x gives
//     D(p + x (1, m)) = x^k E(x, m),   E(x, m) = sum_t x^(t-k) sum_{a+b=t} c_ab m^b,
// and E(0, m) = H_k(1, m), the degree-k form of the tangent cone (and symmetrically in the chart x = m y). If every
// real root m0 of H_k in the charts is simple, E = 0 near x = 0 is one smooth graph m(x) through each (0, m0)
// (implicit function theorem) and nothing else, so the germ of D = 0 at p is exactly 2L half-branches, L the
// number of real lines of the tangent cone. In the same chart
//     grad D(p + x (1, m)) = x^(k-1) G(x, m),  G(x, m) = sum_t x^(t-k) sum_{a+b=t} (a c_ab m^b, b c_ab m^(b-1)),
// so grad D != 0 on the square p + [-r, r]^2 minus p as soon as G has no zero for |x| <= r in both charts.
//
// The coefficients c_ab are enclosed for every p of a small box K (a Taylor shift of the exact power form in MPFI:
// interval operations are inclusion-monotone, so each interval holds the exact coefficient at the exact p), then
// scaled by r^(t-k) and a common power of two and tested in double interval arithmetic (CGAL::Interval_nt<false>,
// outward rounding; the rounding mode is set upward once per test), the slope range split until every piece
// decides. Used by Curve_topology_by_subdivision.h.
#ifndef BEZOUTIAN_TOPOLOGY_INTERNAL_MULTIPLE_POINT_BLOWUP_H
#define BEZOUTIAN_TOPOLOGY_INTERNAL_MULTIPLE_POINT_BLOWUP_H

#include <bezoutian/topology/Curve_topology.h>
#include <bezoutian/arithmetic/interval_krawczyk.h>
#include <bezoutian/arithmetic/number_types.h>

#include <CGAL/Interval_nt.h>

#include <mpfi.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <vector>

namespace bezoutian {
namespace internal {

// Enclosures, valid at every point of K, of the Taylor coefficients c_ij of D (of (u - p_u)^i (v - p_v)^j), stored
// row by row: c_ij at index i (b + 1) + j, a and b the degrees of D in u and v. A Taylor shift by repeated Horner
// steps in MPFI (inclusion-monotone: each interval holds the exact coefficient at the exact p).
inline std::vector<Mpfi_interval> taylor_enclosures(const Polynomial_2<Integer>& D, const Parameter_box& K,
                                                    mpfr_prec_t prec) {
  const int b = D.degree();
  int a = 0;
  for (int j = 0; j <= b; ++j)
    if (!CGAL::is_zero(D[j])) a = std::max(a, D[j].degree());
  std::vector<Mpfi_interval> c(std::size_t(a + 1) * (b + 1), Mpfi_interval::point(0, prec));
  auto at = [&](int i, int j) -> Mpfi_interval& { return c[std::size_t(i) * (b + 1) + j]; };
  for (int j = 0; j <= b; ++j)
    for (int i = 0; !CGAL::is_zero(D[j]) && i <= D[j].degree(); ++i) mpfi_set_z(at(i, j).get(), D[j][i].mpz());
  const Mpfi_interval pu = Mpfi_interval::hull(K.u0, K.u1, prec), pv = Mpfi_interval::hull(K.v0, K.v1, prec);
  // first in u (each column j), then in v (each row i)
  for (int j = 0; j <= b; ++j)
    for (int s = 0; s < a; ++s)
      for (int i = a - 1; i >= s; --i) at(i, j) = at(i, j) + pu * at(i + 1, j);
  for (int i = 0; i <= a; ++i)
    for (int s = 0; s < b; ++s)
      for (int j = b - 1; j >= s; --j) at(i, j) = at(i, j) + pv * at(i, j + 1);
  return c;
}

class Multiple_point_blowup {
 public:
  /// Taylor coefficients of D at every point of K, at `prec` bits; k is the claimed multiplicity (k >= 2).
  Multiple_point_blowup(const Polynomial_2<Integer>& D, const Parameter_box& K, int k, mpfr_prec_t prec)
      : k_(k), c_(taylor_enclosures(D, K, prec)) {
    b_ = D.degree();
    for (int j = 0; j <= b_; ++j)
      if (!CGAL::is_zero(D[j])) a_ = std::max(a_, D[j].degree());
  }

  /// False if a coefficient of order < k is proved nonzero: then p is not a point of multiplicity >= k.
  bool consistent() const {
    if (k_ < 2 || k_ > a_ + b_) return false;
    for (int i = 0; i <= a_; ++i)
      for (int j = 0; j <= b_ && i + j < k_; ++j)
        if (!c(i, j).contains_zero()) return false;
    return true;
  }

  /// Number L of real lines of the tangent cone at p, all simple roots of H_k, proved together with
  /// grad D != 0 on (p + [-r, r]^2) \ {p}; -1 if that is not proved (r too large, or a non-ordinary point).
  int tangent_lines(const Rational& r) const {
    for (double sigma : {1.0, 0.8125, 1.25}) {  // chart split |y| = sigma |x|; a tangent along it moves it
      int lines = 0;
      bool ok = scale(r);
      for (int chart = 0; chart < 2 && ok; ++chart) {
        const double w = chart == 0 ? sigma : 1 / sigma;  // chart 0: |m| <= sigma; chart 1: |m| <= 1 / sigma
        const int n = count_roots(chart, w);
        ok = n >= 0 && gradient_free(chart, w);
        lines += n;
      }
      if (ok) return lines;
    }
    return -1;
  }

 private:
  using IA = CGAL::Interval_nt<false>;  // arithmetic only under a Protect_FPU_rounding guard
  Mpfi_interval& c(int i, int j) { return c_[std::size_t(i) * (b_ + 1) + j]; }
  const Mpfi_interval& c(int i, int j) const { return c_[std::size_t(i) * (b_ + 1) + j]; }

  // s_ab = c_ab r^(a+b-k) 2^-E as double intervals (E: the exponent of the largest order-k coefficient)
  bool scale(const Rational& r) const {
    const mpfr_prec_t prec = c(0, 0).prec();
    mpfr_t mag;
    mpfr_init2(mag, 64);
    long E = LONG_MIN;
    for (int i = 0; i <= std::min(k_, a_); ++i)
      if (k_ - i <= b_) {
        mpfi_mag(mag, c(i, k_ - i).get());
        if (mpfr_regular_p(mag)) E = std::max(E, long(mpfr_get_exp(mag)));
      }
    mpfr_clear(mag);
    if (E == LONG_MIN) return false;  // H_k is not proved nonzero
    const Mpfi_interval R = Mpfi_interval::hull(r, r, prec);
    std::vector<Mpfi_interval> power(std::size_t(a_ + b_ - k_ + 1), Mpfi_interval::point(1, prec));
    mpfi_mul_2si(power[0].get(), power[0].get(), -E);
    for (std::size_t e = 1; e < power.size(); ++e) power[e] = power[e - 1] * R;
    s_.assign(std::size_t(a_ + 1) * (b_ + 1), IA(0));
    mpfr_t lo, hi;
    mpfr_init2(lo, prec);
    mpfr_init2(hi, prec);
    bool finite = true;
    for (int i = 0; i <= a_; ++i)
      for (int j = 0; j <= b_; ++j)
        if (i + j >= k_) {
          const Mpfi_interval x = c(i, j) * power[std::size_t(i + j - k_)];
          mpfi_get_left(lo, x.get());
          mpfi_get_right(hi, x.get());
          const double l = mpfr_get_d(lo, MPFR_RNDD), h = mpfr_get_d(hi, MPFR_RNDU);
          finite = finite && std::isfinite(l) && std::isfinite(h);
          s_[std::size_t(i) * (b_ + 1) + j] = finite ? IA(l, h) : IA(0);
        }
    mpfr_clear(lo);
    mpfr_clear(hi);
    return finite;
  }
  // coefficient of x^p m^q in the chart (chart 0: direction (1, m), p along u; chart 1: (m, 1), p along v)
  IA C(int chart, int p, int q) const {
    const int i = chart == 0 ? p : q, j = chart == 0 ? q : p;
    return i <= a_ && j <= b_ ? s_[std::size_t(i) * (b_ + 1) + j] : IA(0);
  }
  // sum_{p+q=t} w(p, q) C(p, q) M^e(q), with w = 1, e = q (the form itself), w = p, e = q (derivative along the
  // chart's main axis) or w = q, e = q - 1 (derivative along the slope); Horner's rule in M
  IA layer(int chart, int t, int kind, const IA& M) const {
    IA acc(0);
    for (int q = t; q >= 0; --q) {
      const int p = t - q;
      const int w = kind == 0 ? 1 : (kind == 1 ? p : q);
      if (kind == 2 && q == 0) break;
      acc = acc * M + C(chart, p, q) * double(w);
    }
    return acc;
  }
  static bool has_zero(const IA& x) { return x.inf() <= 0 && x.sup() >= 0; }
  static int sign(const IA& x) { return x.inf() > 0 ? 1 : (x.sup() < 0 ? -1 : 0); }

  // real roots of H_k in the chart with |m| <= w: all simple (a sign change on a piece where the derivative keeps
  // a sign), none at m = -w, w; -1 if not proved
  int count_roots(int chart, double w) const {
    CGAL::Protect_FPU_rounding<true> upward;
    if (sign(layer(chart, k_, 0, IA(-w))) == 0 || sign(layer(chart, k_, 0, IA(w))) == 0) return -1;
    std::vector<std::array<double, 2>> stack{{-w, w}};
    int roots = 0;
    for (int pieces = 0; !stack.empty(); ++pieces) {
      const auto M = stack.back();
      stack.pop_back();
      if (pieces > 20000 || !(M[1] - M[0] > std::ldexp(w, -30))) return -1;
      if (!has_zero(layer(chart, k_, 0, IA(M[0], M[1])))) continue;
      if (!has_zero(layer(chart, k_, 2, IA(M[0], M[1])))) {  // d/dm of the form keeps a sign on M
        const int s0 = sign(layer(chart, k_, 0, IA(M[0]))), s1 = sign(layer(chart, k_, 0, IA(M[1])));
        if (s0 != 0 && s1 != 0) {
          roots += s0 != s1;
          continue;
        }
      }
      const double mid = M[0] + 0.4142135623730951 * (M[1] - M[0]);  // off dyadic points (e.g. a root at 0)
      stack.push_back({M[0], mid});
      stack.push_back({mid, M[1]});
    }
    return roots;
  }

  // G (see the header comment) has no zero for x in [-r, r] (X = x / r in [-1, 1]) and |m| <= w
  bool gradient_free(int chart, double w) const {
    CGAL::Protect_FPU_rounding<true> upward;
    const int T = a_ + b_;
    const IA X(-1, 1);
    std::vector<std::array<double, 2>> stack{{-w, w}};
    for (int pieces = 0; !stack.empty(); ++pieces) {
      const auto M = stack.back();
      stack.pop_back();
      if (pieces > 20000 || !(M[1] - M[0] > std::ldexp(w, -24))) return false;
      const IA m(M[0], M[1]);
      IA main(0), slope(0);
      for (int t = T; t >= k_; --t) {
        main = main * X + layer(chart, t, 1, m);
        slope = slope * X + layer(chart, t, 2, m);
      }
      if (!has_zero(main) || !has_zero(slope)) continue;
      const double mid = M[0] + 0.4142135623730951 * (M[1] - M[0]);
      stack.push_back({M[0], mid});
      stack.push_back({mid, M[1]});
    }
    return true;
  }

  int k_ = 3;
  std::vector<Mpfi_interval> c_;
  int a_ = 0, b_ = 0;
  mutable std::vector<IA> s_;
};

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_TOPOLOGY_INTERNAL_MULTIPLE_POINT_BLOWUP_H
