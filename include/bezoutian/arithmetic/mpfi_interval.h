// Interval arithmetic on MPFI with value semantics: every operation rounds outwards, so results enclose the exact
// ones (the enclosures of Krawczyk's test, interval_krawczyk.h, and of the certified curve and surface solvers).
#ifndef BEZOUTIAN_ARITHMETIC_MPFI_INTERVAL_H
#define BEZOUTIAN_ARITHMETIC_MPFI_INTERVAL_H

#include <bezoutian/arithmetic/number_types.h>

#include <CGAL/Polynomial.h>

#include <mpfi.h>

#include <algorithm>

namespace bezoutian {
namespace internal {

/// An MPFI interval with value semantics (every operation rounds outwards, so results enclose the exact ones).
class Mpfi_interval {
 public:
  explicit Mpfi_interval(mpfr_prec_t prec) { mpfi_init2(v_, prec); }
  Mpfi_interval(const Mpfi_interval& o) {
    mpfi_init2(v_, mpfi_get_prec(o.v_));
    mpfi_set(v_, o.v_);
  }
  Mpfi_interval& operator=(const Mpfi_interval& o) {
    if (this != &o) {
      mpfi_set_prec(v_, mpfi_get_prec(o.v_));
      mpfi_set(v_, o.v_);
    }
    return *this;
  }
  ~Mpfi_interval() { mpfi_clear(v_); }

  static Mpfi_interval hull(const Rational& lo, const Rational& hi, mpfr_prec_t prec) {
    Mpfi_interval r(prec);
    mpfi_interv_q(r.v_, lo.mpq(), hi.mpq());
    return r;
  }
  static Mpfi_interval point(double d, mpfr_prec_t prec) {
    Mpfi_interval r(prec);
    mpfi_set_d(r.v_, d);
    return r;
  }
  /// The midpoint (a floating-point number inside the interval) as a point interval.
  Mpfi_interval midpoint() const {
    Mpfi_interval r(prec());
    mpfr_t m;
    mpfr_init2(m, prec());
    mpfi_mid(m, v_);
    mpfi_set_fr(r.v_, m);
    mpfr_clear(m);
    return r;
  }
  double mid_double() const {
    mpfr_t m;
    mpfr_init2(m, prec());
    mpfi_mid(m, v_);
    const double d = mpfr_get_d(m, MPFR_RNDN);
    mpfr_clear(m);
    return d;
  }
  bool contains_zero() const { return mpfi_has_zero(v_) > 0; }
  bool positive() const { return mpfi_is_strictly_pos(v_) > 0; }
  /// True iff the interval lies inside the open interval (lo, hi) (exact comparisons).
  bool inside_open(const Rational& lo, const Rational& hi) const {
    mpfr_t e;
    mpfr_init2(e, prec());
    mpfi_get_left(e, v_);
    const bool l = mpfr_cmp_q(e, lo.mpq()) > 0;
    mpfi_get_right(e, v_);
    const bool h = mpfr_cmp_q(e, hi.mpq()) < 0;
    mpfr_clear(e);
    return l && h;
  }
  /// True iff the two intervals are disjoint.
  friend bool disjoint(const Mpfi_interval& a, const Mpfi_interval& b) {
    mpfr_t x, y;
    mpfr_init2(x, a.prec());
    mpfr_init2(y, b.prec());
    mpfi_get_right(x, a.v_);
    mpfi_get_left(y, b.v_);
    bool d = mpfr_cmp(x, y) < 0;
    mpfi_get_left(x, a.v_);
    mpfi_get_right(y, b.v_);
    d = d || mpfr_cmp(y, x) < 0;
    mpfr_clear(x);
    mpfr_clear(y);
    return d;
  }
  mpfr_prec_t prec() const { return mpfi_get_prec(v_); }
  mpfi_srcptr get() const { return v_; }
  mpfi_ptr get() { return v_; }
  /// True iff this interval lies in the interior of `outer`.
  bool strictly_inside(const Mpfi_interval& outer) const { return mpfi_is_strictly_inside(v_, outer.v_) > 0; }
  double width_double() const {
    mpfr_t w;
    mpfr_init2(w, prec());
    mpfi_diam_abs(w, v_);
    const double d = mpfr_get_d(w, MPFR_RNDU);
    mpfr_clear(w);
    return d;
  }
  /// Exact rational end points.
  Rational lower() const { return end(true); }
  Rational upper() const { return end(false); }

  friend Mpfi_interval operator+(const Mpfi_interval& a, const Mpfi_interval& b) {
    Mpfi_interval r(std::max(a.prec(), b.prec()));
    mpfi_add(r.v_, a.v_, b.v_);
    return r;
  }
  friend Mpfi_interval operator-(const Mpfi_interval& a, const Mpfi_interval& b) {
    Mpfi_interval r(std::max(a.prec(), b.prec()));
    mpfi_sub(r.v_, a.v_, b.v_);
    return r;
  }
  friend Mpfi_interval operator*(const Mpfi_interval& a, const Mpfi_interval& b) {
    Mpfi_interval r(std::max(a.prec(), b.prec()));
    mpfi_mul(r.v_, a.v_, b.v_);
    return r;
  }
  friend Mpfi_interval operator/(const Mpfi_interval& a, const Mpfi_interval& b) {
    Mpfi_interval r(std::max(a.prec(), b.prec()));
    mpfi_div(r.v_, a.v_, b.v_);
    return r;
  }
  friend Mpfi_interval operator*(double d, const Mpfi_interval& a) { return point(d, a.prec()) * a; }

  /// f(x) by Horner's rule (an enclosure of the range of f on x).
  static Mpfi_interval horner(const Polynomial_1<Integer>& f, const Mpfi_interval& x) {
    Mpfi_interval r(x.prec());
    if (CGAL::is_zero(f)) return r = point(0, x.prec());
    mpfi_set_z(r.v_, f[f.degree()].mpz());
    for (int i = f.degree() - 1; i >= 0; --i) {
      mpfi_mul(r.v_, r.v_, x.v_);
      mpfi_add_z(r.v_, r.v_, f[i].mpz());
    }
    return r;
  }

 private:
  Rational end(bool left) const {
    mpfr_t e;
    mpfr_init2(e, prec());
    if (left)
      mpfi_get_left(e, v_);
    else
      mpfi_get_right(e, v_);
    mpq_t q;
    mpq_init(q);
    mpfr_get_q(q, e);
    Rational r(q);
    mpq_clear(q);
    mpfr_clear(e);
    return r;
  }
  mpfi_t v_;
};

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_ARITHMETIC_MPFI_INTERVAL_H
