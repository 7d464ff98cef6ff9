// Proof that a critical point of the projected locus D is a point of D = 0 with two branches (a node or an
// isolated point), from the geometry: a point x of the projection plane with two distinct partners.
//
// A point x = (x1, x2) of the projection plane lies on D = 0 when it has a partner y = (y1, y2) with
//   E(x; y) = 0:  Phi(P) ~ Phi'(Q) (equal affine images), written as A_c(P) B_0(Q) - B_c(Q) A_0(P) = 0, c = 1..3,
// where (A_0 : ... : A_3), (B_0 : ... : B_3) are the homogeneous power forms and, for
//   self-intersection (Theorems 4-5):  y = (l, k), P = (x1, x2 + k), Q = (x1 + l, x2), Phi' = Phi, y != (0, 0);
//   intersection (Theorems 2-3):       y = (v, s), P = (x1, v) on Phi, Q = (s, x2) on Psi.
// D vanishes at every such x with A_0(P) B_0(Q) != 0 (it is the elimination polynomial of these equations,
// buse-elkadi-galligo-2008 §5-6; for self-intersection after saturation by (k, l)), real or complex y alike.
//
// Two partners y_a != y_b of one point x make the 6 x 6 system E(x; y_a) = 0, E(x; y_b) = 0 (unknowns x, y_a,
// y_b). Krawczyk's test on a small box proves a solution and that the system's Jacobian is regular there. Each
// E(.; y_i) = 0 then defines a smooth branch of D = 0 through x (rank 3 in the 4 unknowns (x, y_i)), and the two
// branches have distinct tangents (a common tangent direction d would give a null vector (d, e_a, e_b) of the
// Jacobian). D vanishes on both branches, so grad D(x) is orthogonal to two independent directions: x is a
// singular point of D. Complex conjugate partners y, conj(y) (an isolated real point of D = 0) use the real
// system Re E(x; rho + i sigma) = 0, Im E(x; rho + i sigma) = 0 (unknowns x, rho, sigma, sigma != 0 proved): its
// Jacobian is regular iff the complex 6 x 6 one is, and then the tangents d, conj(d) are independent over C.
//
// Finding the partners is floating point (roots of a numerical resultant, Gauss-Newton); only the final
// Krawczyk test decides, in MPFI interval arithmetic.
#ifndef BEZOUTIAN_LIFTING_DOUBLE_PARTNER_WITNESS_H
#define BEZOUTIAN_LIFTING_DOUBLE_PARTNER_WITNESS_H

#include <bezoutian/topology/Curve_topology.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>
#include <bezoutian/arithmetic/double_interval.h>
#include <bezoutian/arithmetic/interval_krawczyk.h>
#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/lifting/internal/combined_equations_exclusion.h>

#include <array>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

namespace bezoutian {
namespace internal {

/// Interval Horner evaluation for finite arguments x (the hot loop of the phantom exclusion and of the lifting's
/// proofs), in round-to-nearest with one rounding bound at the end instead of outward rounding at every operation
/// (3-4 times faster). Why it encloses, with X = max(|x.lo|, |x.hi|): the exact ends of r * x + c are the least and
/// the largest of the four products of the ends of r and x, plus c.lo and c.hi (for x >= 0 the two products
/// r.lo * (r.lo >= 0 ? x.lo : x.hi) and r.hi * (r.hi >= 0 ? x.hi : x.lo)), so exact arithmetic on the computed
/// ends gives a valid enclosure at every step; moving the ends of r outward by Delta moves those of r * x + c by at
/// most Delta * X; and each rounded product or sum errs by at most 2^-53 of its magnitude. The magnitude at each
/// rounding, times the later powers of X, is a part of the Horner sum mag of |c| X^i, and the rows of a bivariate
/// scheme are disjoint parts; so s roundings per row and outer step move the ends by at most about s 2^-53 mag.
/// We widen by s 2^-52 mag (a factor 2 for the rounding of mag itself) plus 2^-1000 per rounding for underflow.
struct Lazy_horner {
  double lo = 0, hi = 0, mag = 0;
  int steps = 0;  // roundings: of each row (disjoint parts of mag) plus of the outer scheme
  void step(const Double_interval& x, double clo, double chi) {
    const double X = times(x);
    lo += clo;
    hi += chi;
    mag = mag * X + std::max(std::fabs(clo), std::fabs(chi));
    steps += 2;
  }
  /// r * x + s for an inner evaluation s (its own rounding path joins this one)
  void step(const Double_interval& x, const Lazy_horner& s) {
    const double X = times(x);
    lo += s.lo;
    hi += s.hi;
    mag = mag * X + s.mag;
    steps = std::max(steps, s.steps) + 2;
  }
  /// [lo, hi] := [lo, hi] * x (ends rounded to nearest); returns X = max(|x.lo|, |x.hi|)
  double times(const Double_interval& x) {
    if (x.lo >= 0) {  // the usual case: parameters in a domain
      const double l = lo * (lo >= 0 ? x.lo : x.hi), h = hi * (hi >= 0 ? x.hi : x.lo);
      lo = l;
      hi = h;
      return x.hi;
    }
    const double a = lo * x.lo, b = lo * x.hi, c = hi * x.lo, d = hi * x.hi;
    if (std::isnan(a + b + c + d)) {  // inf * 0 or infinite ends (std::min would drop a NaN): no information
      lo = -HUGE_VAL;
      hi = HUGE_VAL;
      return std::max(-x.lo, std::fabs(x.hi));
    }
    lo = std::min(std::min(a, b), std::min(c, d));
    hi = std::max(std::max(a, b), std::max(c, d));
    return std::max(-x.lo, std::fabs(x.hi));
  }
  Double_interval result() const {
    const double e = mag * (double(steps) * 0x1p-52) + double(steps + 1) * 0x1p-1000;
    if (!std::isfinite(e) || std::isnan(lo) || std::isnan(hi)) return {-HUGE_VAL, HUGE_VAL};
    return Double_interval::widen(lo - e, hi + e);
  }
};
inline bool finite_argument(const Double_interval& x) { return std::isfinite(x.lo) && std::isfinite(x.hi); }

/// c[0] + c[1] x + ... over the interval x (an enclosure).
inline Double_interval interval_horner(const std::vector<Double_interval>& c, const Double_interval& x) {
  if (finite_argument(x)) {
    Lazy_horner r;
    for (std::size_t i = c.size(); i-- > 0;) r.step(x, c[i].lo, c[i].hi);
    return r.result();
  }
  Double_interval r{0, 0};
  for (std::size_t i = c.size(); i-- > 0;) r = r * x + c[i];
  return r;
}

/// sum c[j][i] x0^i x1^j over the box x0 x x1 (an enclosure).
inline Double_interval interval_horner(const std::vector<std::vector<Double_interval>>& c, const Double_interval& x0,
                                       const Double_interval& x1) {
  if (finite_argument(x0) && finite_argument(x1)) {
    Lazy_horner r;
    for (std::size_t j = c.size(); j-- > 0;) {
      Lazy_horner s;
      for (std::size_t i = c[j].size(); i-- > 0;) s.step(x0, c[j][i].lo, c[j][i].hi);
      r.step(x1, s);
    }
    return r.result();
  }
  Double_interval r{0, 0};
  for (std::size_t j = c.size(); j-- > 0;) {
    Double_interval s{0, 0};
    for (std::size_t i = c[j].size(); i-- > 0;) s = s * x0 + c[j][i];
    r = r * x1 + s;
  }
  return r;
}

/// The partner equations of a locus (see the header comment): which patch points P, Q a pair (x, y) defines.
class Partner_equations {
 public:
  /// Self-intersection of `phi`.
  explicit Partner_equations(const Rational_bezier_patch<Rational>& phi) : self_(true) { init(phi, phi); }
  /// Intersection of `phi` (u, v) and `psi` (s, t).
  Partner_equations(const Rational_bezier_patch<Rational>& phi, const Rational_bezier_patch<Rational>& psi)
      : self_(false) {
    init(phi, psi);
  }
  bool self_intersection() const { return self_; }
  /// Bounds on the degree of E in y1 and in y2 (self-intersection: y1 = l moves Q along u, y2 = k moves P along
  /// v; intersection: y1 = v on phi, y2 = s on psi).
  std::array<int, 2> degree_bounds() const { return degree_bounds_; }
  /// The exact power-form coefficients of form k (0: the weight, 1-3: the coordinates) of the first patch
  /// (which = 0) or of the second (which = 1; the same patch for a self-intersection): [j][i] multiplies u^i v^j.
  const std::vector<std::vector<Rational>>& form(int which, int k) const {
    return which == 0 ? A_[std::size_t(k)].f : B_[std::size_t(k)].f;
  }
  /// The weights A_0(P), B_0(Q) at z (double).
  std::array<std::complex<double>, 2> weights(const std::array<std::complex<double>, 4>& z) const {
    std::array<std::complex<double>, 2> P, Q;
    points(z, P, Q);
    return {horner_double(A_[0].df, P), horner_double(B_[0].df, Q)};
  }

  // Coordinates of P and Q and the derivative of (P, Q) with respect to z = (x1, x2, y1, y2).
  template <class T>
  void points(const std::array<T, 4>& z, std::array<T, 2>& P, std::array<T, 2>& Q) const {
    if (self_) {
      P = {z[0], z[1] + z[3]};
      Q = {z[0] + z[2], z[1]};
    } else {
      P = {z[0], z[2]};
      Q = {z[3], z[1]};
    }
  }
  // dP_a/dz_i, dQ_b/dz_i (0 or 1)
  int dP(int a, int i) const { return self_ ? (a == 0 ? i == 0 : (i == 1 || i == 3)) : (a == 0 ? i == 0 : i == 2); }
  int dQ(int b, int i) const { return self_ ? (b == 0 ? (i == 0 || i == 2) : i == 1) : (b == 0 ? i == 3 : i == 1); }

  /// E and dE/dz (3 x 4) at z (complex numbers, double).
  void evaluate(const std::array<std::complex<double>, 4>& z, std::array<std::complex<double>, 3>& E,
                std::array<std::array<std::complex<double>, 4>, 3>& J) const {
    using C = std::complex<double>;
    std::array<C, 2> P, Q;
    points(z, P, Q);
    std::array<std::array<C, 3>, 4> a, b;  // value, d/du, d/dv of each form at P, Q
    for (int k = 0; k < 4; ++k) {
      a[k] = jet_double(A_[k], P);
      b[k] = jet_double(B_[k], Q);
    }
    for (int c = 1; c <= 3; ++c) {
      E[c - 1] = a[c][0] * b[0][0] - b[c][0] * a[0][0];
      for (int i = 0; i < 4; ++i) {
        C d = 0;
        for (int e = 0; e < 2; ++e) {
          if (dP(e, i)) d += a[c][1 + e] * b[0][0] - b[c][0] * a[0][1 + e];
          if (dQ(e, i)) d += a[c][0] * b[0][1 + e] - b[c][1 + e] * a[0][0];
        }
        J[c - 1][i] = d;
      }
    }
  }

  /// The same in complex interval arithmetic (each complex number a pair of MPFI intervals: an enclosure).
  struct Cx {
    Mpfi_interval re, im;
  };
  void evaluate(const std::array<Cx, 4>& z, std::array<Cx, 3>& E, std::array<std::array<Cx, 4>, 3>& J,
                std::array<Cx, 2>& weights) const {
    const mpfr_prec_t prec = z[0].re.prec();
    std::array<Cx, 2> P{z[0], z[0]}, Q{z[0], z[0]};
    if (self_) {
      P = {z[0], add(z[1], z[3])};
      Q = {add(z[0], z[2]), z[1]};
    } else {
      P = {z[0], z[2]};
      Q = {z[3], z[1]};
    }
    std::vector<std::array<Cx, 3>> a, b;
    for (int k = 0; k < 4; ++k) {
      a.push_back(jet_interval(A_[k], P, prec));
      b.push_back(jet_interval(B_[k], Q, prec));
    }
    weights = {a[0][0], b[0][0]};
    for (int c = 1; c <= 3; ++c) {
      E[c - 1] = sub(mul(a[c][0], b[0][0]), mul(b[c][0], a[0][0]));
      for (int i = 0; i < 4; ++i) {
        Cx d{Mpfi_interval::point(0, prec), Mpfi_interval::point(0, prec)};
        for (int e = 0; e < 2; ++e) {
          if (dP(e, i)) d = add(d, sub(mul(a[c][1 + e], b[0][0]), mul(b[c][0], a[0][1 + e])));
          if (dQ(e, i)) d = add(d, sub(mul(a[c][0], b[0][1 + e]), mul(b[c][1 + e], a[0][0])));
        }
        J[c - 1][i] = d;
      }
    }
  }

  /// E (and dE/dz if J is given) over the real box z, in outward-rounded double interval arithmetic.
  void evaluate(const std::array<Double_interval, 4>& z, std::array<Double_interval, 3>& E,
                std::array<std::array<Double_interval, 4>, 3>* J = nullptr) const {
    using D = Double_interval;
    std::array<D, 2> P, Q;
    if (self_) {
      P = {z[0], z[1] + z[3]};
      Q = {z[0] + z[2], z[1]};
    } else {
      P = {z[0], z[2]};
      Q = {z[3], z[1]};
    }
    std::array<std::array<D, 3>, 4> a, b;
    for (int k = 0; k < 4; ++k)
      for (int d = 0; d < (J ? 3 : 1); ++d) {
        a[k][d] = horner_interval(d == 0 ? A_[k].if_ : (d == 1 ? A_[k].ifu : A_[k].ifv), P);
        b[k][d] = horner_interval(d == 0 ? B_[k].if_ : (d == 1 ? B_[k].ifu : B_[k].ifv), Q);
      }
    combine(a, b, E, J);
  }

  /// E (and dE/dz) with the projection-plane point fixed to the box x = (x1, x2), for many partner boxes y (the
  /// phantom exclusion): the part of each form that depends on x alone is evaluated once, by Horner in the fixed
  /// coordinate, so that a partner box costs one univariate Horner per form instead of a bivariate one. P's fixed
  /// coordinate is its first (u = x1), Q's its second (x2), in both kinds of locus. Outward-rounded enclosures,
  /// as evaluate().
  class Restriction {
   public:
    Restriction(const Partner_equations& eq, const Double_interval& x1, const Double_interval& x2)
        : eq_(&eq), x1_(x1), x2_(x2) {
      for (int k = 0; k < 4; ++k)
        for (int d = 0; d < 3; ++d) {
          const Form& A = eq.A_[std::size_t(k)];
          const Form& B = eq.B_[std::size_t(k)];
          const auto& fa = d == 0 ? A.if_ : (d == 1 ? A.ifu : A.ifv);
          const auto& fb = d == 0 ? B.if_ : (d == 1 ? B.ifu : B.ifv);
          // P = (x1, free): coefficient of free^j is sum_i fa[j][i] x1^i
          for (const auto& row : fa) a_[k][d].push_back(horner_1(row, x1));
          // Q = (free, x2): coefficient of free^i is sum_j fb[j][i] x2^j
          std::size_t m = 0;
          for (const auto& row : fb) m = std::max(m, row.size());
          std::vector<Double_interval> column(fb.size());
          for (std::size_t i = 0; i < m; ++i) {
            for (std::size_t j = 0; j < fb.size(); ++j) column[j] = i < fb[j].size() ? fb[j][i] : Double_interval{0, 0};
            b_[k][d].push_back(horner_1(column, x2));
          }
        }
    }
    /// E(x; y) (and dE/dz at (x, y), z = (x1, x2, y1, y2)) over the partner box y.
    void evaluate(const std::array<Double_interval, 2>& y, std::array<Double_interval, 3>& E,
                  std::array<std::array<Double_interval, 4>, 3>* J = nullptr) const {
      const bool self = eq_->self_;
      const Double_interval p = self ? x2_ + y[1] : y[0], q = self ? x1_ + y[0] : y[1];
      std::array<std::array<Double_interval, 3>, 4> a, b;
      for (int k = 0; k < 4; ++k)
        for (int d = 0; d < (J ? 3 : 1); ++d) {
          a[k][d] = horner_1(a_[k][d], p);
          b[k][d] = horner_1(b_[k][d], q);
        }
      eq_->combine(a, b, E, J);
    }

   private:
    const Partner_equations* eq_;
    Double_interval x1_, x2_;
    std::array<std::array<std::vector<Double_interval>, 3>, 4> a_, b_;
  };

 private:
  static Double_interval horner_1(const std::vector<Double_interval>& c, const Double_interval& x) {
    return interval_horner(c, x);
  }
  // E = A_c(P) B_0(Q) - B_c(Q) A_0(P) and its Jacobian from the forms' values and partial derivatives at P, Q.
  void combine(const std::array<std::array<Double_interval, 3>, 4>& a, const std::array<std::array<Double_interval, 3>, 4>& b,
               std::array<Double_interval, 3>& E, std::array<std::array<Double_interval, 4>, 3>* J) const {
    using D = Double_interval;
    for (int c = 1; c <= 3; ++c) {
      E[c - 1] = a[c][0] * b[0][0] - b[c][0] * a[0][0];
      if (!J) continue;
      for (int i = 0; i < 4; ++i) {
        D d{0, 0};
        for (int e = 0; e < 2; ++e) {
          if (dP(e, i)) d = d + (a[c][1 + e] * b[0][0] - b[c][0] * a[0][1 + e]);
          if (dQ(e, i)) d = d + (a[c][0] * b[0][1 + e] - b[c][1 + e] * a[0][0]);
        }
        (*J)[c - 1][i] = d;
      }
    }
  }

 public:
  /// E at a rational point z, exactly, and the weights A_0(P), B_0(Q) there in `weights`.
  std::array<Rational, 3> exact_values(const std::array<Rational, 4>& z, std::array<Rational, 2>& weights) const {
    std::array<Rational, 2> P, Q;
    points(z, P, Q);
    auto value = [](const std::vector<std::vector<Rational>>& c, const std::array<Rational, 2>& x) {
      Rational r(0);
      for (std::size_t j = c.size(); j-- > 0;) {
        Rational row(0);
        for (std::size_t i = c[j].size(); i-- > 0;) row = row * x[0] + c[j][i];
        r = r * x[1] + row;
      }
      return r;
    };
    std::array<Rational, 4> a, b;
    for (int k = 0; k < 4; ++k) {
      a[std::size_t(k)] = value(A_[std::size_t(k)].f, P);
      b[std::size_t(k)] = value(B_[std::size_t(k)].f, Q);
    }
    weights = {a[0], b[0]};
    return {a[1] * b[0] - b[1] * a[0], a[2] * b[0] - b[2] * a[0], a[3] * b[0] - b[3] * a[0]};
  }

  /// The weights A_0(P), B_0(Q) over the real box z (outward-rounded double interval arithmetic).
  std::array<Double_interval, 2> weights(const std::array<Double_interval, 4>& z) const {
    std::array<Double_interval, 2> P, Q;
    points(z, P, Q);
    return {horner_interval(A_[0].if_, P), horner_interval(B_[0].if_, Q)};
  }

  static Cx add(const Cx& x, const Cx& y) { return Cx{x.re + y.re, x.im + y.im}; }
  static Cx sub(const Cx& x, const Cx& y) { return Cx{x.re - y.re, x.im - y.im}; }
  static Cx mul(const Cx& x, const Cx& y) { return Cx{x.re * y.re - x.im * y.im, x.re * y.im + x.im * y.re}; }

 private:
  // A form in power basis with its two partial derivatives: coefficient [j][i] of u^i v^j.
  struct Form {
    std::vector<std::vector<Rational>> f, fu, fv;
    std::vector<std::vector<double>> df, dfu, dfv;
    std::vector<std::vector<Double_interval>> if_, ifu, ifv;
  };
  void init(const Rational_bezier_patch<Rational>& phi, const Rational_bezier_patch<Rational>& psi) {
    const auto pa = phi.power_form(), pb = psi.power_form();
    degree_bounds_ = self_ ? std::array<int, 2>{phi.degree_u(), phi.degree_v()}
                           : std::array<int, 2>{phi.degree_v(), psi.degree_u()};
    for (int k = 0; k < 4; ++k) {
      A_[k] = make_form(pa[k]);
      B_[k] = make_form(pb[k]);
    }
  }
  template <class P2>
  static Form make_form(const P2& p) {
    Form F;
    const int n = p.degree();
    int m = 0;
    for (int j = 0; j <= n; ++j) m = std::max(m, p[j].degree());
    F.f.assign(n + 1, std::vector<Rational>(m + 1, Rational(0)));
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= p[j].degree(); ++i) F.f[j][i] = p[j][i];
    F.fu = F.f;
    F.fv = F.f;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= m; ++i) {
        F.fu[j][i] = i < m ? F.f[j][i + 1] * (i + 1) : Rational(0);
        F.fv[j][i] = j < n ? F.f[j + 1][i] * (j + 1) : Rational(0);
      }
    // double copies for the floating-point searches, outward enclosures for the interval proofs
    auto convert = [](const std::vector<std::vector<Rational>>& x, auto to) {
      std::vector<std::vector<decltype(to(x[0][0]))>> r(x.size());
      for (std::size_t j = 0; j < x.size(); ++j)
        for (const auto& c : x[j]) r[j].push_back(to(c));
      return r;
    };
    auto to_d = [](const Rational& c) { return CGAL::to_double(c); };
    auto to_i = [](const Rational& c) { return Double_interval::of(c); };
    F.df = convert(F.f, to_d);
    F.dfu = convert(F.fu, to_d);
    F.dfv = convert(F.fv, to_d);
    F.if_ = convert(F.f, to_i);
    F.ifu = convert(F.fu, to_i);
    F.ifv = convert(F.fv, to_i);
    return F;
  }
  template <class T>
  static T horner_double(const std::vector<std::vector<double>>& c, const std::array<T, 2>& x) {
    T r = 0;
    for (std::size_t j = c.size(); j-- > 0;) {
      T s = 0;
      for (std::size_t i = c[j].size(); i-- > 0;) s = s * x[0] + c[j][i];
      r = r * x[1] + s;
    }
    return r;
  }
  static Double_interval horner_interval(const std::vector<std::vector<Double_interval>>& c,
                                         const std::array<Double_interval, 2>& x) {
    return interval_horner(c, x[0], x[1]);
  }
  static std::array<std::complex<double>, 3> jet_double(const Form& F, const std::array<std::complex<double>, 2>& x) {
    return {horner_double(F.df, x), horner_double(F.dfu, x), horner_double(F.dfv, x)};
  }
  static Cx horner_interval(const std::vector<std::vector<Rational>>& c, const std::array<Cx, 2>& x, mpfr_prec_t prec) {
    auto constant = [&](const Rational& q) {
      return Cx{Mpfi_interval::hull(q, q, prec), Mpfi_interval::point(0, prec)};
    };
    Cx r = constant(Rational(0));
    for (std::size_t j = c.size(); j-- > 0;) {
      Cx s = constant(Rational(0));
      for (std::size_t i = c[j].size(); i-- > 0;) s = add(mul(s, x[0]), constant(c[j][i]));
      r = add(mul(r, x[1]), s);
    }
    return r;
  }
  static std::array<Cx, 3> jet_interval(const Form& F, const std::array<Cx, 2>& x, mpfr_prec_t prec) {
    return {horner_interval(F.f, x, prec), horner_interval(F.fu, x, prec), horner_interval(F.fv, x, prec)};
  }

  bool self_;
  std::array<int, 2> degree_bounds_{0, 0};
  std::array<Form, 4> A_, B_;
};

// Complex roots of the polynomial c[0] + c[1] z + ... (Durand-Kerner / Weierstrass iteration); leading
// coefficients negligible against the others are dropped first (roots at infinity).
inline std::vector<std::complex<double>> complex_roots(std::vector<std::complex<double>> c) {
  using C = std::complex<double>;
  double big = 0;
  for (const C& x : c) big = std::max(big, std::abs(x));
  while (!c.empty() && !(std::abs(c.back()) > 1e-11 * big)) c.pop_back();
  if (c.size() < 2) return {};
  const int n = int(c.size()) - 1;
  for (C& x : c) x /= c.back();
  double bound = 0;  // Cauchy's bound
  for (int i = 0; i < n; ++i) bound = std::max(bound, std::abs(c[i]));
  bound += 1;
  std::vector<C> z(n);
  for (int i = 0; i < n; ++i) z[i] = std::polar(0.5 * bound, 0.4 + 2 * M_PI * i / n);
  auto eval = [&](C x) {
    C r = c[n];
    for (int i = n - 1; i >= 0; --i) r = r * x + c[i];
    return r;
  };
  for (int it = 0; it < 800; ++it) {
    double change = 0;
    for (int i = 0; i < n; ++i) {
      C den = 1;
      for (int j = 0; j < n; ++j)
        if (j != i) den *= (z[i] - z[j]);
      if (std::abs(den) == 0) den = 1e-300;
      const C d = eval(z[i]) / den;
      z[i] -= d;
      change = std::max(change, std::abs(d) / (1 + std::abs(z[i])));
    }
    if (change < 1e-15) break;
  }
  return z;
}

/// Floating-point partners y of the point x (E(x; y) ~ 0, nonzero weights), real and complex: the roots y1 of
/// the Sylvester resultants in y2 of E_1, E_2 and of two fixed combinations of E_1, E_2, E_3 (interpolated from values on a circle), y2 the common root, each
/// polished by Gauss-Newton on the three equations; distinct up to 1e-7, without the trivial partner (0, 0) of
/// self-intersection.
inline std::vector<std::array<std::complex<double>, 2>> numerical_partners(const Partner_equations& eq,
                                                                        const std::array<double, 2>& x) {
  using C = std::complex<double>;
  // degree bounds in y1 and y2; the Sylvester matrix must use the true y2-degree bound (with a larger formal
  // degree both leading coefficients vanish and the resultant is identically zero)
  const int d1 = std::max(1, eq.degree_bounds()[0]), d = std::max(1, eq.degree_bounds()[1]);
  auto E_at = [&](C y1, C y2) {
    std::array<C, 3> E;
    std::array<std::array<C, 4>, 3> J;
    eq.evaluate({C(x[0]), C(x[1]), y1, y2}, E, J);
    return E;
  };
  // coefficients in y2 of E_which at y1 (inverse DFT of values at the (d+1)-th roots of unity)
  auto coefficients = [&](C y1, int which) {
    std::vector<C> v(d + 1), c(d + 1, 0);
    for (int k = 0; k <= d; ++k) v[k] = E_at(y1, std::polar(1.0, 2 * M_PI * k / (d + 1)))[which];
    for (int j = 0; j <= d; ++j) {
      for (int k = 0; k <= d; ++k) c[j] += v[k] * std::polar(1.0, -2 * M_PI * j * k / (d + 1));
      c[j] /= double(d + 1);
    }
    return c;
  };
  // Pairing 0: F_a = E_a (a = 1, 2); pairing 1: F_a = E_a + c_a E_3. Every common root of E is one of F_1, F_2
  // either way; the second resultant does not vanish when E_1 does on the whole locus (E_1 = 2(u - t) for two
  // extrusions along x), and the union of both proposals is polished on all three equations.
  int pairing = 0;
  auto combined = [&](C y1, int which) {
    std::vector<C> c = coefficients(y1, which);
    if (pairing == 0) return c;
    const std::vector<C> e = coefficients(y1, 2);
    const double weight = which == 0 ? 0.6180339887498949 : -0.4142135623730950;
    for (std::size_t j = 0; j < c.size(); ++j) c[j] += weight * e[j];
    return c;
  };
  auto sylvester_det = [&](const std::vector<C>& f, const std::vector<C>& g) {
    const int n = 2 * d;
    std::vector<std::vector<C>> S(n, std::vector<C>(n, 0));
    for (int r = 0; r < d; ++r)
      for (int j = 0; j <= d; ++j) {
        S[r][r + j] = f[d - j];
        S[d + r][r + j] = g[d - j];
      }
    C det = 1;
    for (int col = 0; col < n; ++col) {
      int piv = col;
      for (int r = col + 1; r < n; ++r)
        if (std::abs(S[r][col]) > std::abs(S[piv][col])) piv = r;
      if (std::abs(S[piv][col]) == 0) return C(0);
      if (piv != col) {
        std::swap(S[piv], S[col]);
        det = -det;
      }
      det *= S[col][col];
      for (int r = col + 1; r < n; ++r) {
        const C f2 = S[r][col] / S[col][col];
        for (int j = col; j < n; ++j) S[r][j] -= f2 * S[col][j];
      }
    }
    return det;
  };
  // R(y1) has degree <= 2 d1 d: values at N points of a circle of radius rho, inverse DFT
  const int N = 2 * d1 * d + 1;
  std::vector<C> res_coeff;
  std::vector<std::array<C, 2>> out;
  for (pairing = 0; pairing < 2; ++pairing)
  for (double rho : {1.0, 2.0}) {
    std::vector<C> vals(N), co(N, 0);
    for (int k = 0; k < N; ++k) {
      const C y1 = std::polar(rho, 2 * M_PI * k / N);
      vals[k] = sylvester_det(combined(y1, 0), combined(y1, 1));
    }
    for (int j = 0; j < N; ++j) {
      for (int k = 0; k < N; ++k) co[j] += vals[k] * std::polar(1.0, -2 * M_PI * j * k / N);
      co[j] /= double(N) * std::pow(rho, j);
    }
    for (const C& y1 : complex_roots(co)) {
      if (!(std::abs(y1) < 1e6)) continue;
      // y2: roots of every equation that does not vanish identically at y1 (one may not involve y2 at all,
      // e.g. a coordinate of a patch that depends on u only)
      std::array<std::vector<C>, 3> cy;
      double big = 0;
      for (int c = 0; c < 3; ++c) {
        cy[c] = coefficients(y1, c);
        for (const C& v : cy[c]) big = std::max(big, std::abs(v));
      }
      std::vector<C> y2s;
      for (int c = 0; c < 3; ++c) {
        double b = 0;
        for (const C& v : cy[c]) b = std::max(b, std::abs(v));
        if (!(b > 1e-9 * big)) continue;
        for (const C& r : complex_roots(cy[c])) y2s.push_back(r);
      }
      for (const C& y2 : y2s) {
        std::array<C, 2> y{y1, y2};
        for (int it = 0; it < 30; ++it) {  // Gauss-Newton on the three equations
          std::array<C, 3> E;
          std::array<std::array<C, 4>, 3> J;
          eq.evaluate({C(x[0]), C(x[1]), y[0], y[1]}, E, J);
          C m00 = 0, m01 = 0, m11 = 0, r0 = 0, r1 = 0;
          for (int c = 0; c < 3; ++c) {
            const C j0 = J[c][2], j1 = J[c][3];
            m00 += std::conj(j0) * j0;
            m01 += std::conj(j0) * j1;
            m11 += std::conj(j1) * j1;
            r0 -= std::conj(j0) * E[c];
            r1 -= std::conj(j1) * E[c];
          }
          const C det = m00 * m11 - m01 * std::conj(m01);
          if (!(std::abs(det) > 0)) break;
          const C d0 = (m11 * r0 - m01 * r1) / det, d1 = (m00 * r1 - std::conj(m01) * r0) / det;
          y[0] += d0;
          y[1] += d1;
          if (std::abs(d0) + std::abs(d1) < 1e-15 * (1 + std::abs(y[0]) + std::abs(y[1]))) break;
        }
        std::array<C, 3> E;
        std::array<std::array<C, 4>, 3> J;
        eq.evaluate({C(x[0]), C(x[1]), y[0], y[1]}, E, J);
        double scale = 0;
        for (auto& row : J)
          for (auto& v : row) scale = std::max(scale, std::abs(v));
        if (!(std::sqrt(std::norm(E[0]) + std::norm(E[1]) + std::norm(E[2])) <= 1e-10 * (1 + scale))) continue;
        const auto w = eq.weights({C(x[0]), C(x[1]), y[0], y[1]});
        if (!(std::abs(w[0]) > 1e-8 && std::abs(w[1]) > 1e-8)) continue;  // a point at infinity, not a partner
        if (eq.self_intersection() && std::abs(y[0]) + std::abs(y[1]) < 1e-7) continue;
        if (std::abs(y[0].imag()) < 1e-12 && std::abs(y[1].imag()) < 1e-12) y = {C(y[0].real()), C(y[1].real())};
        bool known = false;
        for (const auto& o : out) known = known || std::abs(o[0] - y[0]) + std::abs(o[1] - y[1]) < 1e-7;
        if (!known) out.push_back(y);
      }
    }
  }
  return out;
}

// One candidate pair of partners of prove_double_partner_point: refined in floating point, then the box of the
// 6 x 6 system proved by Krawczyk's test and the conditions of the header comment checked on it.
using Partner_pair = std::pair<std::array<std::complex<double>, 2>, std::array<std::complex<double>, 2>>;

inline bool prove_partner_pair(const Partner_equations& eq, const Parameter_box& box, const std::array<double, 2>& x,
                               const Partner_pair& pr, mpfr_prec_t prec) {
  using C = std::complex<double>;
  using I = Mpfi_interval;
  const bool complex_pair = pr.first[0].imag() != 0 || pr.first[1].imag() != 0;
  // unknowns w = (x1, x2, ya1, ya2, yb1, yb2) (real pair) or (x1, x2, rho1, rho2, sigma1, sigma2) (complex)
  std::array<double, 6> w{x[0], x[1], pr.first[0].real(), pr.first[1].real(),
                          complex_pair ? pr.first[0].imag() : pr.second[0].real(),
                          complex_pair ? pr.first[1].imag() : pr.second[1].real()};
  // the two partner arguments z_a, z_b of E as complex numbers, for the floating-point Newton refinement
  auto args = [&](const std::array<double, 6>& v) {
    std::array<std::array<C, 4>, 2> z;
    if (complex_pair) {
      z[0] = {C(v[0]), C(v[1]), C(v[2], v[4]), C(v[3], v[5])};
      z[1] = {C(v[0]), C(v[1]), C(v[2], -v[4]), C(v[3], -v[5])};
    } else {
      z[0] = {C(v[0]), C(v[1]), C(v[2]), C(v[3])};
      z[1] = {C(v[0]), C(v[1]), C(v[4]), C(v[5])};
    }
    return z;
  };
  // real 6 x 6 system and its Jacobian (double)
  auto system = [&](const std::array<double, 6>& v, double F[6], double J[6][6]) {
    const auto z = args(v);
    std::array<C, 3> E;
    std::array<std::array<C, 4>, 3> Jc;
    if (complex_pair) {
      eq.evaluate(z[0], E, Jc);
      for (int c = 0; c < 3; ++c) {
        F[c] = E[c].real();
        F[3 + c] = E[c].imag();
        for (int i = 0; i < 2; ++i) {  // real x_i
          J[c][i] = Jc[c][i].real();
          J[3 + c][i] = Jc[c][i].imag();
        }
        for (int i = 0; i < 2; ++i) {  // y_i = rho_i + i sigma_i, E holomorphic in y_i (Cauchy-Riemann)
          J[c][2 + i] = Jc[c][2 + i].real();
          J[3 + c][2 + i] = Jc[c][2 + i].imag();
          J[c][4 + i] = -Jc[c][2 + i].imag();
          J[3 + c][4 + i] = Jc[c][2 + i].real();
        }
      }
    } else {
      for (int s = 0; s < 2; ++s) {
        eq.evaluate(z[s], E, Jc);
        for (int c = 0; c < 3; ++c) {
          F[3 * s + c] = E[c].real();
          for (int i = 0; i < 6; ++i) J[3 * s + c][i] = 0;
          J[3 * s + c][0] = Jc[c][0].real();
          J[3 * s + c][1] = Jc[c][1].real();
          J[3 * s + c][2 + 2 * s] = Jc[c][2].real();
          J[3 * s + c][3 + 2 * s] = Jc[c][3].real();
        }
      }
    }
  };
  bool converged = false;
  double last_step = HUGE_VAL;
  for (int it = 0; it < 30 && !converged; ++it) {
    double F[6], J[6][6];
    system(w, F, J);
    double M[6][7];
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) M[i][j] = J[i][j];
      M[i][6] = -F[i];
    }
    bool singular = false;
    for (int col = 0; col < 6 && !singular; ++col) {
      int piv = col;
      for (int r = col + 1; r < 6; ++r)
        if (std::fabs(M[r][col]) > std::fabs(M[piv][col])) piv = r;
      if (!(std::fabs(M[piv][col]) > 0)) singular = true;
      if (singular) break;
      for (int j = 0; j < 7; ++j) std::swap(M[col][j], M[piv][j]);
      for (int r = col + 1; r < 6; ++r) {
        const double f = M[r][col] / M[col][col];
        for (int j = col; j < 7; ++j) M[r][j] -= f * M[col][j];
      }
    }
    if (singular) break;
    double d[6], step = 0;
    for (int i = 5; i >= 0; --i) {
      double s = M[i][6];
      for (int j = i + 1; j < 6; ++j) s -= M[i][j] * d[j];
      d[i] = s / M[i][i];
      step += std::fabs(d[i]);
    }
    for (int i = 0; i < 6; ++i) w[i] += d[i];
    if (!std::isfinite(step)) break;
    // Newton stalls at the rounding level of the largest unknown (a far partner, e.g. v = -46, keeps steps of
    // ~1e-14 in x): measure the step against all six. Only the Krawczyk test below decides anything.
    double scale = 1;
    for (double c : w) scale = std::max(scale, std::fabs(c));
    if (step < 1e-14 * scale) converged = true;
    last_step = step / scale;
  }
  if (!converged && !(last_step < 1e-11)) return false;
  // Krawczyk in MPFI on a box of radius r around w
  std::array<I, 6> X{I(prec), I(prec), I(prec), I(prec), I(prec), I(prec)};
  for (int i = 0; i < 6; ++i) {
    const double r = 1e-9 * (1 + std::fabs(w[i]));
    X[i] = I::hull(Rational(w[i] - r), Rational(w[i] + r), prec);
  }
  std::array<Partner_equations::Cx, 2> weights_a{Partner_equations::Cx{I(prec), I(prec)}, Partner_equations::Cx{I(prec), I(prec)}};
  auto weights_b = weights_a;
  auto interval_system = [&](const std::array<I, 6>& v, std::array<I, 6>* F, std::vector<std::vector<I>>* J) {
    const I zero = I::point(0, prec);
    using Cx = Partner_equations::Cx;
    const Cx zc{zero, zero};
    const std::array<std::array<Cx, 4>, 2> z{
        std::array<Cx, 4>{Cx{v[0], zero}, Cx{v[1], zero}, Cx{v[2], complex_pair ? v[4] : zero},
                          Cx{v[3], complex_pair ? v[5] : zero}},
        std::array<Cx, 4>{Cx{v[0], zero}, Cx{v[1], zero}, Cx{v[4], zero}, Cx{v[5], zero}}};
    std::array<Cx, 3> E{zc, zc, zc};
    std::array<std::array<Cx, 4>, 3> Jc{std::array<Cx, 4>{zc, zc, zc, zc}, std::array<Cx, 4>{zc, zc, zc, zc},
                                        std::array<Cx, 4>{zc, zc, zc, zc}};
    for (int s = 0; s < (complex_pair ? 1 : 2); ++s) {
      eq.evaluate(z[s], E, Jc, s == 0 ? weights_a : weights_b);
      for (int c = 0; c < 3; ++c) {
        const int row = complex_pair ? c : 3 * s + c;
        if (F) {
          (*F)[row] = E[c].re;
          if (complex_pair) (*F)[3 + c] = E[c].im;
        }
        if (!J) continue;
        if (complex_pair) {
          for (int i = 0; i < 2; ++i) {
            (*J)[c][i] = Jc[c][i].re;
            (*J)[3 + c][i] = Jc[c][i].im;
            (*J)[c][2 + i] = Jc[c][2 + i].re;
            (*J)[3 + c][2 + i] = Jc[c][2 + i].im;
            (*J)[c][4 + i] = I::point(0, prec) - Jc[c][2 + i].im;
            (*J)[3 + c][4 + i] = Jc[c][2 + i].re;
          }
        } else {
          for (int i = 0; i < 6; ++i) (*J)[row][i] = zero;
          (*J)[row][0] = Jc[c][0].re;
          (*J)[row][1] = Jc[c][1].re;
          (*J)[row][2 + 2 * s] = Jc[c][2].re;
          (*J)[row][3 + 2 * s] = Jc[c][3].re;
        }
      }
    }
  };
  auto value = [&](const std::array<I, 6>& c, std::array<I, 6>& F) { interval_system(c, &F, nullptr); };
  auto jacobian = [&](const std::array<I, 6>& Z, std::vector<std::vector<I>>& J) {
    interval_system(Z, nullptr, &J);
  };
  if (!krawczyk_prove<6>(X, value, jacobian)) return false;
  // the conditions of the header comment, on the proved box
  interval_system(X, nullptr, nullptr);  // weights over the final box
  const I bu = I::hull(box.u0, box.u1, prec), bv = I::hull(box.v0, box.v1, prec);
  if (!X[0].strictly_inside(bu) || !X[1].strictly_inside(bv)) return false;
  auto nonzero = [](const Partner_equations::Cx& c) { return !c.re.contains_zero() || !c.im.contains_zero(); };
  if (!nonzero(weights_a[0]) || !nonzero(weights_a[1])) return false;
  if (complex_pair) {
    if (X[4].contains_zero() && X[5].contains_zero()) return false;  // sigma != 0: a non-real partner
    if (eq.self_intersection() && X[2].contains_zero() && X[3].contains_zero() && X[4].contains_zero() &&
        X[5].contains_zero())
      return false;
  } else {
    if (!nonzero(weights_b[0]) || !nonzero(weights_b[1])) return false;
    if (!disjoint(X[2], X[4]) && !disjoint(X[3], X[5])) return false;  // two distinct partners
    if (eq.self_intersection() && ((X[2].contains_zero() && X[3].contains_zero()) ||
                                   (X[4].contains_zero() && X[5].contains_zero())))
      return false;  // the trivial partner (0, 0)
  }
  return true;
}

/// \brief Proves that `box` (of the projection plane) contains a point of D = 0 with two branches of distinct
/// tangents (see the header comment), starting from the approximation `x`. True only with a proof.
inline bool prove_double_partner_point(const Partner_equations& eq, const Parameter_box& box,
                                       const std::array<double, 2>& x) {
  using C = std::complex<double>;
  const auto partners = numerical_partners(eq, x);
  // candidate pairs: two real partners, or one non-real partner (its conjugate is the other)
  std::vector<std::pair<std::array<C, 2>, std::array<C, 2>>> pairs;
  for (std::size_t a = 0; a < partners.size(); ++a) {
    const bool real_a = partners[a][0].imag() == 0 && partners[a][1].imag() == 0;
    if (!real_a) {
      pairs.push_back({partners[a], {std::conj(partners[a][0]), std::conj(partners[a][1])}});
      continue;
    }
    for (std::size_t b = a + 1; b < partners.size(); ++b)
      if (partners[b][0].imag() == 0 && partners[b][1].imag() == 0) pairs.push_back({partners[a], partners[b]});
  }
  const mpfr_prec_t prec = 192;
  for (const auto& pr : pairs)
    if (prove_partner_pair(eq, box, x, pr, prec)) return true;
  return false;
}

/// \brief Proves that no point x of `box` has a partner in the partner domain (the points P, Q of the header
/// comment both in `domain`; for self-intersection y != (0, 0)): then D = 0 has no genuine point in `box`.
/// The partner range is split into at most `max_pieces` boxes; on each, some equation E_c must exclude 0 over
/// box x piece, or (self-intersection, a piece near y = 0) the interval Jacobian dE/dy must have full rank on the
/// hull H of the piece and 0: E(x; y) = M y with M a mean value of dE/dy on the segment [0, y] inside H
/// (E(x; 0) = 0), so y = 0 is the only zero there (the trivial partner). False means "not proved".
/// `start` (optional): pieces known to cover every candidate partner of the points of `box` (those that survived
/// the test on a box containing it); on failure `survivors` (optional) receives pieces covering every candidate
/// partner not excluded.
/// The range of the partner y of the points of `box` that puts both patch points in `domain`: (l, k) with u + l
/// and v + k in the domain for a self-intersection, (v, s) in the domain for two patches.
inline std::array<Double_interval, 2> partner_range(const Partner_equations& eq, const Parameter_box& box,
                                                    const Parameter_box& domain) {
  using D = Double_interval;
  if (eq.self_intersection())
    return {D::hull(domain.u0 - box.u1, domain.u1 - box.u0), D::hull(domain.v0 - box.v1, domain.v1 - box.v0)};
  return {D::hull(domain.v0, domain.v1), D::hull(domain.u0, domain.u1)};
}

inline bool no_genuine_partner(const Partner_equations& eq, const Parameter_box& box, const Parameter_box& domain,
                               int max_pieces = 1024, const std::vector<std::array<Double_interval, 2>>* start = nullptr,
                               std::vector<std::array<Double_interval, 2>>* survivors = nullptr) {
  using D = Double_interval;
  const D x1 = D::hull(box.u0, box.u1), x2 = D::hull(box.v0, box.v1);
  const Partner_equations::Restriction on_box(eq, x1, x2);
  std::unique_ptr<Partner_equations::Restriction> at_centre;  // x at the box's centre (mean value forms)
  const std::array<D, 2> range = partner_range(eq, box, domain);
  std::vector<std::array<D, 2>> stack;
  if (!start) {
    stack.push_back(range);
  } else {  // the pieces clipped to this box's range (a smaller box has a smaller partner range)
    for (const auto& y : *start) {
      const std::array<D, 2> c{D{std::max(y[0].lo, range[0].lo), std::min(y[0].hi, range[0].hi)},
                               D{std::max(y[1].lo, range[1].lo), std::min(y[1].hi, range[1].hi)}};
      if (c[0].lo <= c[0].hi && c[1].lo <= c[1].hi) stack.push_back(c);
    }
  }
  int pieces = 0;
  auto give_up = [&](const std::array<D, 2>& current) {
    if (survivors) {
      *survivors = stack;
      survivors->push_back(current);
    }
    return false;
  };
  while (!stack.empty()) {
    const std::array<D, 2> y = stack.back();
    stack.pop_back();
    if (++pieces > max_pieces) return give_up(y);
    std::array<D, 3> E;
    on_box.evaluate(y, E);
    if (!E[0].contains_zero() || !E[1].contains_zero() || !E[2].contains_zero()) continue;
    {  // mean value form: E(c) + dE/dz (box) (z - c), c the centre (much tighter on small pieces)
      std::array<std::array<D, 4>, 3> J;
      on_box.evaluate(y, E, &J);
      const std::array<D, 4> z{x1, x2, y[0], y[1]};
      std::array<D, 4> c, dz;
      for (int i = 0; i < 4; ++i) {
        const double m = z[i].mid();
        c[i] = D{m, m};
        dz[i] = z[i] - c[i];
      }
      if (!at_centre) at_centre.reset(new Partner_equations::Restriction(eq, c[0], c[1]));
      std::array<D, 3> Ec;
      at_centre->evaluate({c[2], c[3]}, Ec);
      bool excluded = false;
      for (int r = 0; r < 3 && !excluded; ++r) {
        D v = Ec[r];
        for (int i = 0; i < 4; ++i) v = v + J[r][i] * dz[i];
        excluded = !v.contains_zero();
      }
      if (excluded || combination_excludes_zero(Ec, J, dz)) continue;
    }
    // near the trivial partner: the rank test on the hull of the piece and y = 0 (pieces touching it included)
    const D h0{std::min(y[0].lo, 0.0), std::max(y[0].hi, 0.0)}, h1{std::min(y[1].lo, 0.0), std::max(y[1].hi, 0.0)};
    if (eq.self_intersection() && (h0.hi - h0.lo) + (h1.hi - h1.lo) <= 3 * ((y[0].hi - y[0].lo) + (y[1].hi - y[1].lo))) {
      std::array<std::array<D, 4>, 3> J;
      on_box.evaluate({h0, h1}, E, &J);
      bool full_rank = false;
      for (int r = 0; r < 3 && !full_rank; ++r)
        for (int q = r + 1; q < 3 && !full_rank; ++q)
          full_rank = !(J[r][2] * J[q][3] - J[r][3] * J[q][2]).contains_zero();
      if (full_rank) continue;
    }
    // split the wider side
    const int i = (y[0].hi - y[0].lo) >= (y[1].hi - y[1].lo) ? 0 : 1;
    const double m = y[i].mid();
    std::array<D, 2> lo = y, hi = y;
    lo[i].hi = m;
    hi[i].lo = m;
    if (!(lo[i].lo < m && m < hi[i].hi)) return give_up(y);  // cannot split further
    stack.push_back(lo);
    stack.push_back(hi);
  }
  return true;
}

/// The phantom exclusion as used by the subdivision (Subdivision_topology_options::no_genuine_points): boxes are
/// asked from the root down, so the pieces that survived on a box are remembered and the test on a sub-box
/// starts from them instead of the whole partner range (copies share the memory).
class Genuine_point_exclusion {
 public:
  Genuine_point_exclusion(Partner_equations eq, const Parameter_box& domain)
      : eq_(std::move(eq)), domain_(domain), memory_(std::make_shared<std::vector<Entry>>()) {}
  bool operator()(const Parameter_box& box) const {
    const Entry* parent = nullptr;
    for (const Entry& e : *memory_)  // the smallest remembered box containing `box`
      if (e.box.u0 <= box.u0 && box.u1 <= e.box.u1 && e.box.v0 <= box.v0 && box.v1 <= e.box.v1 &&
          (!parent || (e.box.u1 - e.box.u0) * (e.box.v1 - e.box.v0) <
                          (parent->box.u1 - parent->box.u0) * (parent->box.v1 - parent->box.v0)))
        parent = &e;
    Entry next{box, {}};
    if (no_genuine_partner(eq_, box, domain_, 1024, parent ? &parent->pieces : nullptr, &next.pieces)) return true;
    if (next.pieces.size() <= max_remembered_pieces) {
      if (memory_->size() >= max_entries) memory_->erase(memory_->begin());
      memory_->push_back(std::move(next));
    }
    return false;
  }

 private:
  struct Entry {
    Parameter_box box;
    std::vector<std::array<Double_interval, 2>> pieces;
  };
  static constexpr std::size_t max_entries = 64, max_remembered_pieces = 4096;
  Partner_equations eq_;
  Parameter_box domain_;
  std::shared_ptr<std::vector<Entry>> memory_;
};

} // namespace internal
} // namespace bezoutian

#endif // BEZOUTIAN_LIFTING_DOUBLE_PARTNER_WITNESS_H
