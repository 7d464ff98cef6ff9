// The point type of Arr_rational_bezier_traits_2 (Point_2): a point of the arrangement of planar rational Bezier
// curves with exact algebraic coordinates (Algebraic_real), computed on demand from the curves and parameters it
// lies at; enclosures on the parameters' isolating intervals decide most comparisons (floating point only filters).
#ifndef BEZOUTIAN_ARRANGEMENT_ARR_BEZIER_POINT_2_H
#define BEZOUTIAN_ARRANGEMENT_ARR_BEZIER_POINT_2_H

#include <bezoutian/arithmetic/profiling.h>
#include <bezoutian/algebraic/Algebraic_real.h>
#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/arrangement/internal/arr_bezier_exact.h>
#include <bezoutian/arrangement/internal/arr_bezier_parameter.h>

#include <CGAL/Interval_nt.h>
#include <CGAL/enum.h>

#include <cmath>
#include <memory>
#include <ostream>
#include <utility>
#include <vector>

namespace bezoutian {

/// \brief A point of the arrangement: exact algebraic coordinates, plus the curves and parameters it is known
/// to lie at. A point of a curve at an algebraic parameter t gets its exact coordinates (defining polynomial
/// Res_t(X - x W, p), arrangement/internal/arr_bezier_exact.h) only when a comparison cannot be decided by enclosures of
/// X/W and Y/W on t's refined isolating interval (filters, exact interval arithmetic).
class Arr_bezier_point_2 {
 public:
  using Supporting = internal::Arr_bezier_supporting_curve;
  using Parameter = internal::Arr_parameter;
  using Origin = std::pair<std::shared_ptr<const Supporting>, Parameter>;

  /// The origin (0,0).
  Arr_bezier_point_2() : Arr_bezier_point_2(Rational(0), Rational(0)) {}
  /// The rational point (x, y).
  Arr_bezier_point_2(const Rational& x, const Rational& y) : rep_(std::make_shared<Rep>()) {
    rep_->c[0] = Algebraic_real(x);
    rep_->c[1] = Algebraic_real(y);
    rep_->known[0] = rep_->known[1] = true;
  }
  /// The rational point with the exact values of the doubles x and y (e.g. grid landmarks).
  Arr_bezier_point_2(double x, double y) : Arr_bezier_point_2(Rational(x), Rational(y)) {}
  /// The point with the given exact coordinates.
  Arr_bezier_point_2(const Algebraic_real& x, const Algebraic_real& y) : rep_(std::make_shared<Rep>()) {
    rep_->c[0] = x;
    rep_->c[1] = y;
    rep_->known[0] = rep_->known[1] = true;
  }
  /// The point of a supporting curve at parameter t (exact coordinates computed on demand).
  Arr_bezier_point_2(const std::shared_ptr<const Supporting>& s, const Parameter& t) : rep_(std::make_shared<Rep>()) {
    rep_->origins.push_back({s, t});
    if (t.is_rational())
      for (int k = 0; k < 2; ++k) coordinate(k);
  }

  /// Exact coordinate k (0: x, 1: y), computed on first use.
  const Algebraic_real& coordinate(int k) const {
    Rep& r = *rep_;
    if (!r.known[k]) {
      BEZOUTIAN_PROFILE_SCOPE("exact coordinate");
      const Origin& o = r.origins.front();
      r.c[k] = internal::arr_value_at(o.first->num[k], o.first->den[k], o.second.exact());
      r.known[k] = true;
    }
    return r.c[k];
  }
  const Algebraic_real& x() const { return coordinate(0); }
  const Algebraic_real& y() const { return coordinate(1); }
  bool is_rational() const {
    return rep_->known[0] && rep_->known[1] && rep_->c[0].is_rational() && rep_->c[1].is_rational();
  }

  /// A closed rational interval containing coordinate k (from the exact number if known, else an enclosure of
  /// the coordinate function on the parameter's isolating interval).
  void enclose(int k, Rational& lo, Rational& hi) const {
    Rep& r = *rep_;
    for (;;) {
      if (r.known[k]) {
        lo = r.c[k].lower();
        hi = r.c[k].upper();
        return;
      }
      const Origin& o = r.origins.front();
      if (internal::arr_enclose_quotient(o.first->num[k], o.first->den[k], o.second.lower(), o.second.upper(), lo, hi))
        return;
      internal::arr_refine(o.second);
    }
  }
  /// A double interval containing coordinate k, computed once (false if none is available yet).
  bool enclose_double(int k, double& lo, double& hi) const {
    Rep& r = *rep_;
    if (!r.dvalid[k]) {
      if (r.known[k]) {
        r.dlo[k] = CGAL::to_interval(r.c[k].lower()).first;
        r.dhi[k] = CGAL::to_interval(r.c[k].upper()).second;
      } else {
        const Origin& o = r.origins.front();
        if (!o.second.is_rational() && CGAL::to_double(o.second.upper() - o.second.lower()) > 1e-12)
          o.second.refine_to_width(internal::arr_parameter_width());  // parameters lie in [0, 1]
        if (!internal::arr_enclose_quotient_double(o.first->num[k], o.first->den[k], o.second.lower(), o.second.upper(),
                                                   r.dlo[k], r.dhi[k]))
          return false;
      }
      r.dvalid[k] = true;
    }
    lo = r.dlo[k];
    hi = r.dhi[k];
    return true;
  }

  /// Shrinks the enclosures.
  void refine(int k) const {
    Rep& r = *rep_;
    if (r.known[k]) internal::arr_refine(r.c[k]);
    else internal::arr_refine(r.origins.front().second);
    r.dvalid[k] = false;
  }

  /// Double approximations (nearest doubles).
  /// (From the double enclosure when it is already narrow, ~1e-9 relative; else from the exact coordinate.)
  double approximate_x() const { return approximate(0); }
  double approximate_y() const { return approximate(1); }
  double approximate(int k) const {
    double lo, hi;
    if (enclose_double(k, lo, hi) && hi - lo <= 1e-9 * (std::abs(lo) + 1)) return 0.5 * (lo + hi);
    return coordinate(k).to_double();
  }
  const std::vector<Origin>& origins() const { return rep_->origins; }
  /// Records that the point lies on s at parameter t (the caller guarantees it).
  void add_origin(const std::shared_ptr<const Supporting>& s, const Parameter& t) const {
    for (const Origin& o : rep_->origins)
      if (o.first == s && o.second.same_representation(t)) return;
    rep_->origins.push_back({s, t});
  }
  bool is_same(const Arr_bezier_point_2& o) const { return rep_ == o.rep_; }

  /// Exact sign of coordinate k of p minus that of q: enclosures first, exact numbers if they do not separate.
  friend int compare_coordinate(const Arr_bezier_point_2& p, const Arr_bezier_point_2& q, int k) {
    if (p.rep_ == q.rep_) return 0;
    double a0, b0, c0, d0;
    if (p.enclose_double(k, a0, b0) && q.enclose_double(k, c0, d0)) {
      if (b0 < c0) return -1;
      if (d0 < a0) return 1;
    }
    for (int round = 0; round < 3; ++round) {
      Rational a, b, c, d;
      p.enclose(k, a, b);
      q.enclose(k, c, d);
      if (b < c) return -1;
      if (d < a) return 1;
      if (a == b && c == d) return CGAL::compare(a, c);
      p.refine(k);
      q.refine(k);
    }
    return p.coordinate(k).compare(q.coordinate(k));
  }

  friend std::ostream& operator<<(std::ostream& os, const Arr_bezier_point_2& p) {
    return os << "(" << p.approximate_x() << ", " << p.approximate_y() << ")";
  }

 private:
  static const Algebraic_real& zero() {  // shared: no allocation per point
    static const Algebraic_real z(0);
    return z;
  }
  struct Rep {
    Algebraic_real c[2] = {zero(), zero()};
    bool known[2] = {false, false};
    double dlo[2], dhi[2];  // cached double enclosures
    bool dvalid[2] = {false, false};
    std::vector<Origin> origins;
  };
  std::shared_ptr<Rep> rep_;
};

}  // namespace bezoutian

#endif  // BEZOUTIAN_ARRANGEMENT_ARR_BEZIER_POINT_2_H
