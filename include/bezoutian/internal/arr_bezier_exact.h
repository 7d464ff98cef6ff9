// Exact building blocks of the Arrangement_2 traits for rational Bezier curves: supporting curves, exact
// coordinates of curve points at algebraic parameters, inversion of an abscissa on a monotone arc.
#ifndef BEZOUTIAN_INTERNAL_ARR_BEZIER_EXACT_H
#define BEZOUTIAN_INTERNAL_ARR_BEZIER_EXACT_H

#include <bezoutian/Algebraic_real.h>
#include <bezoutian/Curve_intersection.h>
#include <bezoutian/Error.h>
#include <bezoutian/Rational_bezier_curve.h>
#include <bezoutian/Root_isolation.h>
#include <bezoutian/internal/curve_intersection_support.h>

#include <CGAL/Interval_nt.h>
#include <CGAL/Polynomial.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <utility>
#include <vector>

namespace bezoutian {
namespace internal {

/// One input curve as used by the traits: integer power form and, per coordinate, the reduced fraction
/// N_k / D_k = X_k / W (gcd removed, so that resultants with defining polynomials never vanish identically).
struct Arr_bezier_supporting_curve {
  std::size_t id = 0;
  Rational_bezier_curve_2<Rational> curve;
  std::array<Ci_poly1, 3> H;        // (W, X, Y), integer coefficients
  std::array<Ci_poly1, 2> num, den;  // x = num[0]/den[0], y = num[1]/den[1]
  std::array<Ci_poly1, 2> speed;     // X_k' W - X_k W' (numerators of the derivatives of x and y)
  bool vertical = false;             // x constant
  bool linear = false;               // the image lies on a line (collinear control points)
  std::array<Rational, 4> box;       // xmin, xmax, ymin, ymax of the control points (encloses the curve)
};

inline Ci_poly1 arr_primitive(const Ci_poly1& f) {
  if (CGAL::is_zero(f)) return f;
  return canonical_integer(f) * Ci_poly1(Integer(CGAL::sign(f.lcoeff())));
}

inline std::shared_ptr<const Arr_bezier_supporting_curve> make_supporting_curve(const Rational_bezier_curve_2<Rational>& c) {
  static std::atomic<std::size_t> counter{0};
  for (std::size_t i = 0; i < c.number_of_control_points(); ++i)
    if (!(c.weight(i) > Rational(0)))
      throw Invalid_input("Arr_rational_bezier_traits_2: every weight must be positive (no poles on [0,1])");
  auto s = std::make_shared<Arr_bezier_supporting_curve>();
  s->id = ++counter;
  s->curve = c;
  s->H = integer_power_form<2>(c);
  const Ci_poly1& W = s->H[0];
  for (int k = 0; k < 2; ++k) {
    const Ci_poly1& X = s->H[k + 1];
    Ci_poly1 g = CGAL::is_zero(X) ? W : Ci_poly1(CGAL::gcd(X, W));
    g = arr_primitive(g);
    if (CGAL::sign(g.lcoeff()) < 0) g = -g;
    s->num[k] = CGAL::integral_division(X, g);
    s->den[k] = CGAL::integral_division(W, g);
    s->speed[k] = CGAL::differentiate(X) * W - X * CGAL::differentiate(W);
  }
  if (CGAL::is_zero(s->speed[0]) && CGAL::is_zero(s->speed[1]))
    throw Invalid_input("Arr_rational_bezier_traits_2: the curve is a single point");
  s->vertical = CGAL::is_zero(s->speed[0]);
  // Collinear control points <=> the image lies on a line (a X + b Y + c W = 0 holds coefficientwise).
  const auto p = c.control_points();
  s->box = {p[0][0], p[0][0], p[0][1], p[0][1]};
  for (const auto& q : p) {
    s->box[0] = std::min(s->box[0], q[0]);
    s->box[1] = std::max(s->box[1], q[0]);
    s->box[2] = std::min(s->box[2], q[1]);
    s->box[3] = std::max(s->box[3], q[1]);
  }
  std::size_t j = 1;
  while (j < p.size() && p[j] == p[0]) ++j;
  s->linear = true;
  for (std::size_t i = 1; i < p.size() && j < p.size(); ++i)
    if ((p[i][0] - p[0][0]) * (p[j][1] - p[0][1]) != (p[i][1] - p[0][1]) * (p[j][0] - p[0][0])) s->linear = false;
  return s;
}

/// The number (v - m) / d (d > 0): the root of q(m + d u) in the image of v's isolating interval.
inline Algebraic_real arr_affine(const Algebraic_real& v, const Rational& m, const Rational& d) {
  if (v.is_rational()) return Algebraic_real((v.rational_value() - m) / d);
  const Ci_poly1 q = v.polynomial();
  const Rational lo = v.lower(), hi = v.upper();
  const Polynomial_1<Rational> lin(m, d);
  Polynomial_1<Rational> r(0);
  for (int i = q.degree(); i >= 0; --i) r = r * lin + Polynomial_1<Rational>(Rational(q[i]));
  return Algebraic_real(r, (lo - m) / d, (hi - m) / d);
}

/// Exact rational value f(q).
inline Rational arr_eval(const Ci_poly1& f, const Rational& q) {
  Rational r(0);
  for (int i = f.degree(); i >= 0; --i) r = r * q + Rational(f[i]);
  return r;
}

/// Enclosure [lo, hi] of f on [a, b] (interval Horner; doubles when the interval is wide, exact rationals
/// otherwise). Rigorous in both cases: CGAL::Interval_nt rounds outwards.
inline std::pair<Rational, Rational> arr_enclose(const Ci_poly1& f, const Rational& a, const Rational& b) {
  const double w = CGAL::to_double(b - a), m = std::abs(CGAL::to_double(a)) + 1;
  if (w > 1e-9 * m) {
    typedef CGAL::Interval_nt<false> I;
    typename I::Protector guard;
    const I x(CGAL::to_interval(a).first, CGAL::to_interval(b).second);
    I v(CGAL::to_interval(f[f.degree()]));
    for (int i = f.degree() - 1; i >= 0; --i) v = v * x + I(CGAL::to_interval(f[i]));
    if (std::isfinite(v.inf()) && std::isfinite(v.sup())) return {Rational(v.inf()), Rational(v.sup())};
  }
  Rational lo(f[f.degree()]), hi = lo;
  for (int i = f.degree() - 1; i >= 0; --i) {
    const Rational p[4] = {lo * a, lo * b, hi * a, hi * b};
    lo = *std::min_element(p, p + 4);
    hi = *std::max_element(p, p + 4);
    lo += Rational(f[i]);
    hi += Rational(f[i]);
  }
  return {lo, hi};
}

/// Double enclosure of N/D on [a, b] (outward-rounded interval arithmetic on the double interval containing
/// [a, b]); false if D's enclosure contains 0 or overflows.
inline bool arr_enclose_quotient_double(const Ci_poly1& N, const Ci_poly1& D, const Rational& a, const Rational& b,
                                        double& lo, double& hi) {
  typedef CGAL::Interval_nt<false> I;
  typename I::Protector guard;
  const I x(CGAL::to_interval(a).first, CGAL::to_interval(b).second);
  auto ev = [&](const Ci_poly1& f) {
    I v(CGAL::to_interval(f[f.degree()]));
    for (int i = f.degree() - 1; i >= 0; --i) v = v * x + I(CGAL::to_interval(f[i]));
    return v;
  };
  const I n = ev(N), d = ev(D);
  if (!(d.inf() > 0) && !(d.sup() < 0)) return false;
  const I q = n / d;
  if (!std::isfinite(q.inf()) || !std::isfinite(q.sup())) return false;
  lo = q.inf();
  hi = q.sup();
  return true;
}

/// Enclosure of N/D on the isolating interval of t, or false if D's enclosure contains 0.
inline bool arr_enclose_quotient(const Ci_poly1& N, const Ci_poly1& D, const Rational& a, const Rational& b,
                                 Rational& lo, Rational& hi) {
  if (a == b) {
    lo = hi = arr_eval(N, a) / arr_eval(D, a);
    return true;
  }
  const auto n = arr_enclose(N, a, b), d = arr_enclose(D, a, b);
  if (!(d.first > Rational(0)) && !(d.second < Rational(0))) return false;
  const Rational p[4] = {n.first / d.first, n.first / d.second, n.second / d.first, n.second / d.second};
  lo = *std::min_element(p, p + 4);
  hi = *std::max_element(p, p + 4);
  return true;
}

inline void arr_refine(const Algebraic_real& t) {
  if (t.is_rational()) return;
  Rational w = (t.upper() - t.lower()) / Rational(64);
  t.refine_to_width(w);
}

/// The exact number N(t)/D(t) at an algebraic t (D(t) != 0, gcd(N, D) = 1). Its defining polynomial is
/// R(v) = Res_t(N(t) - v D(t), p(t)) for the defining polynomial p of t (every root of R is N/D at a root of p);
/// the isolating interval is an enclosure of N/D on t's refined interval holding exactly one root of R.
inline Algebraic_real arr_value_at(const Ci_poly1& N, const Ci_poly1& D, const Algebraic_real& t) {
  if (t.is_rational()) return Algebraic_real(arr_eval(N, t.rational_value()) / arr_eval(D, t.rational_value()));
  if (N.degree() <= 0 && D.degree() <= 0) return Algebraic_real(Rational(N[0], D[0]));
  const Ci_poly1 p = t.polynomial();
  const int n = std::max(N.degree(), D.degree());
  std::vector<Ci_poly1> fc;
  for (int i = 0; i <= n; ++i) {
    const Integer ni = i <= N.degree() ? N[i] : Integer(0), di = i <= D.degree() ? D[i] : Integer(0);
    fc.push_back(Ci_poly1(ni, -di));  // N_i - v D_i
  }
  const Ci_poly2 F(fc.begin(), fc.end());
  std::vector<Ci_poly1> gc;
  for (int i = 0; i <= p.degree(); ++i) gc.push_back(Ci_poly1(p[i]));
  const Ci_poly2 G(gc.begin(), gc.end());
  const Ci_poly1 R = CGAL::resultant(F, G);
  if (CGAL::is_zero(R)) throw Error("Arr_rational_bezier_traits_2: vanishing coordinate resultant");
  for (int round = 0;; ++round) {
    Rational lo, hi;
    if (arr_enclose_quotient(N, D, t.lower(), t.upper(), lo, hi) && count_real_roots(R, lo, hi) == 1)
      return Algebraic_real(R, lo, hi);
    if (t.is_rational()) return Algebraic_real(arr_eval(N, t.rational_value()) / arr_eval(D, t.rational_value()));
    arr_refine(t);
  }
}

/// Numerator of q(N/D): sum_i q_i N^i D^(d-i), whose roots are the t with N(t)/D(t) a root of q.
inline Ci_poly1 arr_compose(const Ci_poly1& q, const Ci_poly1& N, const Ci_poly1& D) {
  const int d = q.degree();
  std::vector<Ci_poly1> Dp(d + 1, Ci_poly1(1));
  for (int i = 1; i <= d; ++i) Dp[i] = Dp[i - 1] * D;
  Ci_poly1 r(0), Np(1);
  for (int i = 0; i <= d; ++i) {
    if (!CGAL::is_zero(q[i])) r += Ci_poly1(q[i]) * Np * Dp[d - i];
    Np = Np * N;
  }
  return r;
}

/// Sign of (N/D)(t) - v for the t given (filters on enclosures, then exact through arr_value_at).
inline int arr_compare_value(const Ci_poly1& N, const Ci_poly1& D, const Algebraic_real& t, const Algebraic_real& v) {
  for (int round = 0; round < 4; ++round) {
    Rational lo, hi;
    if (arr_enclose_quotient(N, D, t.lower(), t.upper(), lo, hi)) {
      if (hi < v.lower() || (hi == v.lower() && !v.is_rational())) return -1;
      if (lo > v.upper() || (lo == v.upper() && !v.is_rational())) return 1;
    }
    arr_refine(t);
    arr_refine(v);
  }
  return arr_value_at(N, D, t).compare(v);
}

/// All t in [lo, hi] (parameters, exact) where coordinate k of the curve equals v. If `point_y` is given, only
/// those where the other coordinate equals *point_y as well. Throws if the coordinate is constant.
inline std::vector<Algebraic_real> arr_parameters_at(const Arr_bezier_supporting_curve& S, int k, const Algebraic_real& v,
                                                     const Algebraic_real& lo, const Algebraic_real& hi,
                                                     const Algebraic_real* other = nullptr) {
  const Ci_poly1& N = S.num[k];
  const Ci_poly1& D = S.den[k];
  std::vector<Algebraic_real> out;
  Ci_poly1 Q;
  Ci_poly1 q;
  Rational ql, qh;
  const bool rat = v.is_rational();
  if (rat) {
    const Rational r = v.rational_value();
    // Q = den(r) N - num(r) D
    Q = N * Ci_poly1(Integer(mpq_denref(r.mpq()))) - D * Ci_poly1(Integer(mpq_numref(r.mpq())));
  } else {
    q = v.polynomial();
    ql = v.lower();
    qh = v.upper();
    Q = arr_compose(q, N, D);
  }
  if (CGAL::is_zero(Q)) throw Error("Arr_rational_bezier_traits_2: inversion on a constant coordinate");
  Rational a = lo.lower(), b = hi.upper();
  if (a > b) return out;
  for (const Isolated_root& r : isolate_real_roots(Q, a, b)) {
    const Algebraic_real& t = r.root;
    if (t < lo || t > hi) continue;
    if (!rat) {
      // N/D at t is a root of q: it is v iff it lies in v's isolating interval (ql, qh), whose ends are not roots.
      bool keep = false;
      for (;;) {
        Rational l, h;
        if (arr_enclose_quotient(N, D, t.lower(), t.upper(), l, h)) {
          if (l > ql && h < qh) { keep = true; break; }
          if (h < ql || l > qh || (h == ql) || (l == qh)) break;
        }
        if (t.is_rational()) {  // exact value
          const Rational x = arr_eval(N, t.rational_value()) / arr_eval(D, t.rational_value());
          keep = x > ql && x < qh;
          break;
        }
        arr_refine(t);
      }
      if (!keep) continue;
    }
    if (other && arr_compare_value(S.num[1 - k], S.den[1 - k], t, *other) != 0) continue;
    out.push_back(t);
  }
  return out;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERNAL_ARR_BEZIER_EXACT_H
