// CGAL Arrangement_2 traits for planar rational Bezier curves with exact rational control points and positive
// weights: a model of ArrangementTraits_2 (ArrangementXMonotoneTraits_2 with Has_left_category and
// Has_merge_category true, oblivious boundary sides). Every predicate is decided exactly on real algebraic
// numbers (Algebraic_real); floating point only filters. See doc/arrangement_traits.md.
#ifndef BEZOUTIAN_ARRANGEMENT_ARR_RATIONAL_BEZIER_TRAITS_2_H
#define BEZOUTIAN_ARRANGEMENT_ARR_RATIONAL_BEZIER_TRAITS_2_H

#include <bezoutian/arithmetic/profiling.h>
#include <bezoutian/algebraic/Algebraic_real.h>
#include <bezoutian/intersection/Curve_intersection.h>
#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/geometry/Rational_bezier_curve.h>
#include <bezoutian/algebraic/Root_isolation.h>
#include <bezoutian/arrangement/internal/arr_bezier_exact.h>
#include <bezoutian/arrangement/internal/arr_bezier_parameter.h>
#include <bezoutian/arrangement/Arr_bezier_point_2.h>
#include <bezoutian/arrangement/Arr_bezier_x_monotone_curve_2.h>

#include <CGAL/Interval_nt.h>

#include <CGAL/enum.h>
#include <CGAL/tags.h>
#include <CGAL/Arr_enums.h>
#include <CGAL/Arr_tags.h>

#include <boost/variant.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <ostream>
#include <utility>
#include <vector>


namespace bezoutian {

/// \brief Model of CGAL's ArrangementTraits_2 (and ArrangementDirectionalXMonotoneTraits_2) for planar rational
/// Bezier curves with exact rational control points and positive weights.
///
/// Curve_2 is Rational_bezier_curve_2<Rational>. Points have exact algebraic coordinates (Algebraic_real):
/// a point of curve C at an algebraic parameter t of defining polynomial p has x = X(t)/W(t) with defining
/// polynomial Res_t(X - x W, p) (arrangement/internal/arr_bezier_exact.h). Intersections come from intersect_curves
/// (certified, du-1989 ch. 4), cached per pair of supporting curves; the traits object and its copies share
/// the cache, which is safe to use from several threads (independent arrangements in parallel). One arrangement,
/// its points and curves are used by one thread at a time (doc/arrangement_traits.md, "Threads").
class Arr_rational_bezier_traits_2 {
 public:
  using Curve_2 = Rational_bezier_curve_2<Rational>;
  using Point_2 = Arr_bezier_point_2;
  using X_monotone_curve_2 = Arr_bezier_x_monotone_curve_2;
  using Multiplicity = unsigned int;
  using Supporting = internal::Arr_bezier_supporting_curve;
  using Parameter = internal::Arr_parameter;

  using Has_left_category = CGAL::Tag_true;
  using Has_merge_category = CGAL::Tag_true;
  using Has_do_intersect_category = CGAL::Tag_false;
  using Left_side_category = CGAL::Arr_oblivious_side_tag;
  using Bottom_side_category = CGAL::Arr_oblivious_side_tag;
  using Top_side_category = CGAL::Arr_oblivious_side_tag;
  using Right_side_category = CGAL::Arr_oblivious_side_tag;

  Arr_rational_bezier_traits_2() : cache_(std::make_shared<Cache>()) {}

  /// One intersection of two supporting curves: the point and its parameters on both.
  struct Cached_point {
    Point_2 p;
    Parameter s, t;
    bool tangent;
  };
  struct Cached_overlap {
    Parameter s0, s1, t0, t1;
  };
  struct Pair_entry {
    std::vector<Cached_point> points;
    std::vector<Cached_overlap> overlaps;
  };

  /// Intersections of the supporting curves a and b (a == b: self-intersections, s < t), oriented so that s is
  /// the parameter on a. Computed once per unordered pair (both orientations are cached). Pairs whose piece
  /// boxes are disjoint, and curves proved simple (Arr_bezier_supporting_curve::simple), need no elimination.
  const Pair_entry& intersections(const std::shared_ptr<const Supporting>& a, const std::shared_ptr<const Supporting>& b) const {
    BEZOUTIAN_PROFILE_SCOPE("intersections()");
    const auto key = std::make_pair(a->id, b->id);
    {
      std::lock_guard<std::mutex> lock(cache_->mutex);
      auto it = cache_->pairs.find(key);
      if (it != cache_->pairs.end()) return it->second;
      auto rit = cache_->pairs.find(std::make_pair(b->id, a->id));
      if (rit != cache_->pairs.end()) {
        Pair_entry e = rit->second;
        for (auto& c : e.points) std::swap(c.s, c.t);
        for (auto& o : e.overlaps) {
          std::swap(o.s0, o.t0);
          std::swap(o.s1, o.t1);
        }
        return cache_->pairs.emplace(key, std::move(e)).first->second;
      }
    }
    BEZOUTIAN_PROFILE_SCOPE("pair computed");
    // With positive weights each piece lies in the box of its control points (convex hull property).
    const bool disjoint = a != b && internal::arr_pieces_disjoint(*a, *b, 0, 0, 0);
    if (disjoint || (a == b && (a->linear || a->simple)))  // (an arc of a line segment has no self-intersection)
      return cache_->insert(key, Pair_entry());
    {  // interval subdivision and Krawczyk: exact parameters only on demand
      BEZOUTIAN_PROFILE_SCOPE("interval solver");
      internal::Arr_interval_solver solver{*a, *b, {}};
      internal::Arr_self_interval_solver self_solver{*a, {}};
      if (a != b) solver.run(a->inet, 0, 1, b->inet, 0, 1, 0);
      else self_solver.run(a->inet, 0, 1, a->inet, 0, 1, 0);
      if (a == b) {
        solver.failed = self_solver.failed;
        solver.found = self_solver.found;
        if (self_solver.closed) solver.contacts.push_back({0, 1});
      }
      if (!solver.failed) {
        auto pair = std::make_shared<internal::Arr_exact_pair>();
        pair->a = a;
        pair->b = b;
        Pair_entry e;
        for (const auto& c : solver.contacts) {  // common end points: rational parameters
          const Parameter s(c[0]), t(c[1]);
          Point_2 p(a, s);
          p.add_origin(b, t);
          e.points.push_back({p, s, t, false});
        }
        for (const auto& f : solver.found) {
          auto l = std::make_shared<internal::Arr_lazy_point>();
          l->pair = pair;
          for (int i = 0; i < 4; ++i) l->box[i] = Rational(f[i]);
          const Parameter s(l, 0), t(l, 1);
          Point_2 p(a, s);
          p.add_origin(b, t);
          e.points.push_back({p, s, t, false});
        }
        return cache_->insert(key, std::move(e));
      }
    }
    Curve_intersection_result r;
    try {
      BEZOUTIAN_PROFILE_SCOPE("intersect_curves/self");
      r = a == b ? self_intersections(a->curve) : intersect_curves(a->curve, b->curve);
    } catch (const Invalid_input&) {
      throw;
    } catch (const Error& e) {
      throw Invalid_input(std::string("Arr_rational_bezier_traits_2: unsupported input: ") + e.what());
    }
    Pair_entry e;
    for (const auto& ip : r.points) {
      Point_2 p(a, ip.s);
      p.add_origin(b, ip.t);
      e.points.push_back({p, ip.s, ip.t, ip.tangent});
    }
    for (const auto& o : r.overlaps) e.overlaps.push_back({o.s0, o.s1, o.t0, o.t1});
    return cache_->insert(key, std::move(e));
  }

  // ------------------------------------------------------------------------------------------- basic predicates
  static int cmp_x(const Point_2& p, const Point_2& q) {
    BEZOUTIAN_PROFILE_SCOPE("Compare_x");
    return compare_coordinate(p, q, 0); }
  static int cmp_xy(const Point_2& p, const Point_2& q) {
    BEZOUTIAN_PROFILE_SCOPE("Compare_xy");
    if (p.is_same(q)) return 0;
    const int c = compare_coordinate(p, q, 0);
    return c != 0 ? c : compare_coordinate(p, q, 1);
  }
  static CGAL::Comparison_result res(int c) { return c < 0 ? CGAL::SMALLER : (c > 0 ? CGAL::LARGER : CGAL::EQUAL); }

  class Compare_x_2 {
   public:
    CGAL::Comparison_result operator()(const Point_2& p, const Point_2& q) const { return res(cmp_x(p, q)); }
  };
  class Compare_xy_2 {
   public:
    CGAL::Comparison_result operator()(const Point_2& p, const Point_2& q) const { return res(cmp_xy(p, q)); }
  };
  class Construct_min_vertex_2 {
   public:
    const Point_2& operator()(const X_monotone_curve_2& c) const { return c.left(); }
  };
  class Construct_max_vertex_2 {
   public:
    const Point_2& operator()(const X_monotone_curve_2& c) const { return c.right(); }
  };
  class Is_vertical_2 {
   public:
    bool operator()(const X_monotone_curve_2& c) const { return c.is_vertical(); }
  };

  /// Parameter of the arc at the point p (p on the arc, or at least x(p) in its x-range for non-vertical arcs).
  static Parameter parameter_of(const X_monotone_curve_2& c, const Point_2& p) {
    BEZOUTIAN_PROFILE_SCOPE("parameter_of");
    for (const auto& o : p.origins())
      if (o.first == c.supporting() && o.second >= c.parameter_min() && o.second <= c.parameter_max()) return o.second;
    if (cmp_xy(p, c.point_at_min_parameter()) == 0) return c.parameter_min();
    if (cmp_xy(p, c.point_at_max_parameter()) == 0) return c.parameter_max();
    const int k = c.is_vertical() ? 1 : 0;
    const Algebraic_real& v = k == 0 ? p.x() : p.y();
    auto r = internal::arr_parameters_at(*c.supporting(), k, v, c.parameter_min(), c.parameter_max());
    if (r.size() != 1) throw Error("Arr_rational_bezier_traits_2: point not in the range of the arc");
    p.add_origin(c.supporting(), r[0]);
    return r[0];
  }

  /// Enclosure [lo, hi] of the ordinates of the non-vertical arc over the abscissae [xl, xh] (false if not found
  /// near enough). Rational parameters a < b inside the arc with x(a), x(b) on both sides of [xl, xh] bracket
  /// the parameters there (x is monotone on the arc); the bracket is proposed in doubles and checked exactly,
  /// and y is enclosed on [a, b] by exact interval arithmetic.
  static bool enclose_y_over(const X_monotone_curve_2& c, const Rational& xl, const Rational& xh, Rational& lo,
                             Rational& hi) {
    const Supporting& S = *c.supporting();
    const double target = 0.5 * (CGAL::to_double(xl) + CGAL::to_double(xh));
    double a = c.parameter_min().to_double(), b = c.parameter_max().to_double();
    const bool inc = c.is_increasing();
    for (int i = 0; i < 60 && b - a > 1e-15; ++i) {
      const double m = 0.5 * (a + b);
      const double xm = S.curve.evaluate(m)[0];
      if ((xm < target) == inc) a = m;
      else b = m;
    }
    const double tau = 0.5 * (a + b);
    for (double delta = 1e-12; delta < 1e-2; delta *= 64) {
      const Rational ra(tau - delta), rb(tau + delta);
      if (c.parameter_min().compare(ra) >= 0 || c.parameter_max().compare(rb) <= 0) return false;
      const Rational xa = internal::arr_eval(S.num[0], ra) / internal::arr_eval(S.den[0], ra);
      const Rational xb = internal::arr_eval(S.num[0], rb) / internal::arr_eval(S.den[0], rb);
      const bool bracket = inc ? (xa < xl && xb > xh) : (xa > xh && xb < xl);
      if (!bracket) continue;
      return internal::arr_enclose_quotient(S.num[1], S.den[1], ra, rb, lo, hi);
    }
    return false;
  }

  /// Double-interval version of enclose_y_over + the comparison with p (0: undecided): parameters ra < rb inside
  /// the arc with x(ra), x(rb) proved on both sides of p's abscissa enclosure bracket the arc's parameter at
  /// x(p), so y(p) is compared with an enclosure of y on [ra, rb].
  static int double_compare_y_at_x(const Point_2& p, const X_monotone_curve_2& c) {
    double xl, xh, yl, yh;
    if (!p.enclose_double(0, xl, xh) || !p.enclose_double(1, yl, yh)) return 0;
    const Supporting& S = *c.supporting();
    const double target = 0.5 * (xl + xh);
    const double t0 = CGAL::to_interval(c.parameter_min().upper()).second;
    const double t1 = CGAL::to_interval(c.parameter_max().lower()).first;
    double a = t0, b = t1;
    const bool inc = c.is_increasing();
    for (int i = 0; i < 60 && b - a > 1e-15; ++i) {
      const double m = 0.5 * (a + b);
      const double xm = S.curve.evaluate(m)[0];
      if ((xm < target) == inc) a = m;
      else b = m;
    }
    const double tau = 0.5 * (a + b);
    typedef CGAL::Interval_nt<false> I;
    typename I::Protector guard;
    auto ev = [](const internal::Ci_poly1& f, const I& u) {
      I v(CGAL::to_interval(f[f.degree()]));
      for (int i = f.degree() - 1; i >= 0; --i) v = v * u + I(CGAL::to_interval(f[i]));
      return v;
    };
    for (double delta = 1e-13; delta < 1e-2; delta *= 64) {
      const double ra = tau - delta, rb = tau + delta;
      if (!(ra > t0) || !(rb < t1)) return 0;
      const I xa = ev(S.num[0], I(ra)) / ev(S.den[0], I(ra)), xb = ev(S.num[0], I(rb)) / ev(S.den[0], I(rb));
      const bool bracket = inc ? (xa.sup() < xl && xb.inf() > xh) : (xa.inf() > xh && xb.sup() < xl);
      if (!bracket) continue;
      const I u(ra, rb), d = ev(S.den[1], u);
      if (!(d.inf() > 0) && !(d.sup() < 0)) return 0;
      const I y = ev(S.num[1], u) / d;
      if (yh < y.inf()) return -1;
      if (yl > y.sup()) return 1;
      return 0;
    }
    return 0;
  }

  /// Filter for compare_y_at_x (0: undecided).
  static int filtered_compare_y_at_x(const Point_2& p, const X_monotone_curve_2& c) {
    const int f = double_compare_y_at_x(p, c);
    if (f != 0) return f;
    Rational xl, xh, yl, yh, lo, hi;
    p.enclose(0, xl, xh);
    p.enclose(1, yl, yh);
    if (!enclose_y_over(c, xl, xh, lo, hi)) return 0;
    if (yh < lo) return -1;
    if (yl > hi) return 1;
    return 0;
  }

  /// Sign of y(p) - y(arc at x(p)) (p in the x-range of the non-vertical arc).
  static int compare_y_at_x(const Point_2& p, const X_monotone_curve_2& c) {
    BEZOUTIAN_PROFILE_SCOPE("Compare_y_at_x_2");
    if (c.is_vertical()) {
      if (compare_coordinate(p, c.left(), 1) < 0) return -1;
      return compare_coordinate(p, c.right(), 1) > 0 ? 1 : 0;
    }
    for (const auto& o : p.origins())
      if (o.first == c.supporting() && o.second >= c.parameter_min() && o.second <= c.parameter_max()) return 0;
    for (const Point_2* e : {&c.left(), &c.right()})
      if (cmp_x(p, *e) == 0) return compare_coordinate(p, *e, 1);
    const int f = filtered_compare_y_at_x(p, c);
    if (f != 0) return f;
    auto r = internal::arr_parameters_at(*c.supporting(), 0, p.x(), c.parameter_min(), c.parameter_max());
    if (r.size() != 1) throw Error("Arr_rational_bezier_traits_2: compare_y_at_x outside the x-range of the arc");
    const int s = -internal::arr_compare_value(c.supporting()->num[1], c.supporting()->den[1], r[0], p.y());
    if (s == 0) p.add_origin(c.supporting(), r[0]);
    return s;
  }

  class Compare_y_at_x_2 {
   public:
    CGAL::Comparison_result operator()(const Point_2& p, const X_monotone_curve_2& c) const {
      return res(compare_y_at_x(p, c));
    }
  };

  /// y of the non-vertical arc at the rational abscissa x (in its x-range), exact.
  static Algebraic_real y_at(const X_monotone_curve_2& c, const Rational& x) {
    auto r = internal::arr_parameters_at(*c.supporting(), 0, Algebraic_real(x), c.parameter_min(), c.parameter_max());
    if (r.size() != 1) throw Error("Arr_rational_bezier_traits_2: abscissa outside the x-range of the arc");
    return internal::arr_value_at(c.supporting()->num[1], c.supporting()->den[1], r[0]);
  }

  /// Enclosure of the slope dy/dx = (Y'W - YW')/(X'W - XW') of the non-vertical arc c at its point p (false if
  /// p's parameter on c is not at hand or the enclosure of dx/dt contains 0).
  static bool slope_at(const X_monotone_curve_2& c, const Point_2& p, double& lo, double& hi) {
    const Parameter* t = nullptr;
    if (p.is_same(c.point_at_min_parameter())) t = &c.parameter_min();
    else if (p.is_same(c.point_at_max_parameter())) t = &c.parameter_max();
    else {
      for (const auto& o : p.origins())
        if (o.first == c.supporting() && o.second >= c.parameter_min() && o.second <= c.parameter_max()) {
          t = &o.second;
          break;
        }
      if (!t) {
        if (cmp_xy(p, c.point_at_min_parameter()) == 0) t = &c.parameter_min();
        else if (cmp_xy(p, c.point_at_max_parameter()) == 0) t = &c.parameter_max();
        else return false;
      }
    }
    if (!t->is_rational() && CGAL::to_double(t->upper() - t->lower()) > 1e-12)
      t->refine_to_width(internal::arr_parameter_width());
    typedef CGAL::Interval_nt<false> I;
    typename I::Protector guard;
    const I u = t->is_rational() ? I(CGAL::to_interval(t->rational_value()))
                                 : I(CGAL::to_interval(t->lower()).first, CGAL::to_interval(t->upper()).second);
    auto ev = [&](const internal::Ci_poly1& f) {
      if (f.degree() < 0 || CGAL::is_zero(f)) return I(0);
      I v(CGAL::to_interval(f[f.degree()]));
      for (int i = f.degree() - 1; i >= 0; --i) v = v * u + I(CGAL::to_interval(f[i]));
      return v;
    };
    const Supporting& S = *c.supporting();
    const I dx = ev(S.speed[0]), dy = ev(S.speed[1]);
    if (!(dx.inf() > 0) && !(dx.sup() < 0)) return false;
    const I q = dy / dx;
    if (!std::isfinite(q.inf()) || !std::isfinite(q.sup())) return false;
    lo = q.inf();
    hi = q.sup();
    return true;
  }

  /// Sign of the derivative numerator speed[k] (X_k' W - X_k W') at the parameter t by interval evaluation
  /// (0: not decided).
  static int speed_sign(const Supporting& S, int k, const Parameter& t) {
    if (!t.is_rational() && CGAL::to_double(t.upper() - t.lower()) > 1e-12) t.refine_to_width(internal::arr_parameter_width());
    typedef CGAL::Interval_nt<false> I;
    typename I::Protector guard;
    const I u = t.is_rational() ? I(CGAL::to_interval(t.rational_value()))
                                : I(CGAL::to_interval(t.lower()).first, CGAL::to_interval(t.upper()).second);
    const internal::Ci_poly1& f = S.speed[k];
    I v(CGAL::to_interval(f[f.degree()]));
    for (int i = f.degree() - 1; i >= 0; --i) v = v * u + I(CGAL::to_interval(f[i]));
    return v.inf() > 0 ? 1 : (v.sup() < 0 ? -1 : 0);
  }

  /// Order of two non-vertical arcs through p just right (right = true) or left of p. A rational abscissa x* is
  /// chosen strictly between x(p) and every other abscissa where the supporting curves meet or an arc ends, so
  /// that the two arcs neither cross nor end on the open slab between x(p) and x*; comparing their exact
  /// ordinates at x* gives the answer (equal ordinates there mean an overlap, hence EQUAL).
  int compare_y_near(const X_monotone_curve_2& c1, const X_monotone_curve_2& c2, const Point_2& p, bool right) const {
    BEZOUTIAN_PROFILE_SCOPE("Compare_y_at_x_l/r");
    const int dir = right ? 1 : -1;
    // A vertical arc at p lies (lexicographically) just above p on the right side, just below it on the left.
    if (c1.is_vertical() || c2.is_vertical()) return (int(c1.is_vertical()) - int(c2.is_vertical())) * dir;
    // Filter: both arcs pass through p; if their slopes there differ, the first-order Taylor expansion orders
    // them near p (the steeper arc is above on the right, below on the left).
    double sl1, sh1, sl2, sh2;
    if (slope_at(c1, p, sl1, sh1) && slope_at(c2, p, sl2, sh2)) {
      if (sh1 < sl2) return -dir;
      if (sh2 < sl1) return dir;
    }
    // Two arcs of one curve ending at p with a common parameter t_p (a turning point of x, vertical tangent):
    // y - y(p) ~ y'(t_p) (t - t_p) while x - x(p) is of higher order, so the arc along which y increases from p
    // is above on either side.
    if (c1.supporting() == c2.supporting()) {
      const Parameter* tp = nullptr;
      int d1 = 0;
      if (c1.parameter_max().same_representation(c2.parameter_min()) && p.is_same(c1.point_at_max_parameter())) {
        tp = &c1.parameter_max();
        d1 = -1;
      } else if (c1.parameter_min().same_representation(c2.parameter_max()) && p.is_same(c1.point_at_min_parameter())) {
        tp = &c1.parameter_min();
        d1 = 1;
      }
      if (tp) {
        const int sy = speed_sign(*c1.supporting(), 1, *tp);
        if (sy != 0) return sy * d1;
      }
    }
    // the nearest abscissa beyond p where something happens, as a point
    Point_2 bound = right ? (cmp_x(c1.right(), c2.right()) < 0 ? c1.right() : c2.right())
                          : (cmp_x(c1.left(), c2.left()) > 0 ? c1.left() : c2.left());
    if (cmp_x(bound, p) * dir <= 0)
      throw Invalid_input("Arr_rational_bezier_traits_2: compare_y_at_x_left/right: an arc is not defined there");
    auto consider = [&](const Point_2& q) {
      if (q.is_same(p)) return;
      const int side = cmp_x(q, p) * dir;
      if (side > 0 && cmp_x(q, bound) * dir < 0) bound = q;
    };
    const Pair_entry& e = intersections(c1.supporting(), c2.supporting());
    for (const auto& ip : e.points) consider(ip.p);
    for (const auto& o : e.overlaps)
      for (const Parameter* t : {&o.s0, &o.s1}) consider(Point_2(c1.supporting(), *t));
    // a rational strictly between x(p) and x(bound) (they differ: refine until the enclosures separate)
    Rational xs;
    for (;;) {
      Rational a, b, c, d;
      p.enclose(0, a, b);
      bound.enclose(0, c, d);
      if (right && b < c) { xs = internal::simplest_rational_between(b, c); break; }
      if (!right && d < a) { xs = internal::simplest_rational_between(d, a); break; }
      p.refine(0);
      bound.refine(0);
    }
    Rational l1, h1, l2, h2;
    if (enclose_y_over(c1, xs, xs, l1, h1) && enclose_y_over(c2, xs, xs, l2, h2)) {
      if (h1 < l2) return -1;
      if (h2 < l1) return 1;
    }
    const Algebraic_real y1 = y_at(c1, xs), y2 = y_at(c2, xs);
    return y1.compare(y2);
  }

  class Compare_y_at_x_left_2 {
   public:
    explicit Compare_y_at_x_left_2(const Arr_rational_bezier_traits_2* t) : tr_(t) {}
    CGAL::Comparison_result operator()(const X_monotone_curve_2& c1, const X_monotone_curve_2& c2, const Point_2& p) const {
      return res(tr_->compare_y_near(c1, c2, p, false));
    }
   private:
    const Arr_rational_bezier_traits_2* tr_;
  };
  class Compare_y_at_x_right_2 {
   public:
    explicit Compare_y_at_x_right_2(const Arr_rational_bezier_traits_2* t) : tr_(t) {}
    CGAL::Comparison_result operator()(const X_monotone_curve_2& c1, const X_monotone_curve_2& c2, const Point_2& p) const {
      return res(tr_->compare_y_near(c1, c2, p, true));
    }
   private:
    const Arr_rational_bezier_traits_2* tr_;
  };

  class Equal_2 {
   public:
    explicit Equal_2(const Arr_rational_bezier_traits_2* t) : tr_(t) {}
    bool operator()(const Point_2& p, const Point_2& q) const { return cmp_xy(p, q) == 0; }
    bool operator()(const X_monotone_curve_2& a, const X_monotone_curve_2& b) const {
      if (cmp_xy(a.left(), b.left()) != 0 || cmp_xy(a.right(), b.right()) != 0) return false;
      if (a.supporting() == b.supporting()) return a.parameter_min() == b.parameter_min() && a.parameter_max() == b.parameter_max();
      std::vector<boost::variant<std::pair<Point_2, Multiplicity>, X_monotone_curve_2>> out;
      tr_->intersect(a, b, std::back_inserter(out));
      for (const auto& v : out)
        if (const X_monotone_curve_2* c = boost::get<X_monotone_curve_2>(&v))
          return cmp_xy(c->left(), a.left()) == 0 && cmp_xy(c->right(), a.right()) == 0;
      return false;
    }
   private:
    const Arr_rational_bezier_traits_2* tr_;
  };

  // ------------------------------------------------------------------------------------------- constructions
  /// The arc of s on [t0, t1] (t0 < t1) with known end points.
  static X_monotone_curve_2 make_arc(const std::shared_ptr<const Supporting>& s, const Parameter& t0,
                                     const Parameter& t1, const Point_2& p0, const Point_2& p1) {
    const int c = compare_coordinate(p0, p1, s->vertical ? 1 : 0);
    if (c == 0) throw Error("Arr_rational_bezier_traits_2: degenerate arc");
    return X_monotone_curve_2(s, t0, t1, p0, p1, c < 0);
  }

  /// Splits a curve at the zeros in (0,1) of the derivative of x (of y for vertical curves): vertical
  /// tangents, x-extrema and singular points. Each piece is then strictly x-monotone (y-monotone if vertical).
  class Make_x_monotone_2 {
   public:
    template <class OutputIterator>
    OutputIterator operator()(const Curve_2& c, OutputIterator oi) const {
    BEZOUTIAN_PROFILE_SCOPE("Make_x_monotone_2");
      using Result = boost::variant<Point_2, X_monotone_curve_2>;
      // With positive weights the curve is a single point iff all control points coincide: an isolated point.
      bool point = true;
      for (std::size_t i = 1; i < c.number_of_control_points(); ++i)
        if (c.control_point(i) != c.control_point(0)) point = false;
      if (point) {
        for (std::size_t i = 0; i < c.number_of_control_points(); ++i)
          if (!(c.weight(i) > Rational(0)))
            throw Invalid_input("Arr_rational_bezier_traits_2: every weight must be positive (no poles on [0,1])");
        const auto q = c.control_point(0);
        *oi++ = Result(Point_2(q[0], q[1]));
        return oi;
      }
      auto s = internal::make_supporting_curve(c);
      const int k = s->vertical ? 1 : 0;
      std::vector<Parameter> ts{Parameter(0)};
      for (const Isolated_root& r : isolate_real_roots(s->speed[k], Rational(0), Rational(1)))
        if (r.root > 0 && r.root < 1) ts.push_back(r.root);
      ts.push_back(Parameter(1));
      if (s->linear && ts.size() > 2) {
        // A segment traversed back and forth: its image is the segment L between its extreme control points
        // (convex hull property). The arcs are the pieces of L between the sorted positions of C(0), C(1) and
        // the turning points (the same vertices as overlapping pieces of C would give), u = (v - m) / d.
        const auto p = c.control_points();
        std::size_t imin = 0, imax = 0;
        for (std::size_t i = 1; i < p.size(); ++i) {
          if (p[i][k] < p[imin][k]) imin = i;
          if (p[i][k] > p[imax][k]) imax = i;
        }
        const Rational m = p[imin][k], d = p[imax][k] - p[imin][k];
        auto L = internal::make_supporting_curve(Curve_2(std::vector<typename Curve_2::Point>{p[imin], p[imax]}));
        std::vector<Parameter> us;
        for (const auto& t : ts) us.push_back(internal::arr_affine(Point_2(s, t).coordinate(k), m, d));
        std::sort(us.begin(), us.end());
        us.erase(std::unique(us.begin(), us.end()), us.end());
        s = L;
        ts = us;
      }
      std::vector<Point_2> ps;
      for (const auto& t : ts) ps.push_back(Point_2(s, t));
      for (std::size_t i = 0; i + 1 < ts.size(); ++i) *oi++ = Result(make_arc(s, ts[i], ts[i + 1], ps[i], ps[i + 1]));
      return oi;
    }
   private:
    using Ci_poly1 = internal::Ci_poly1;
  };

  class Split_2 {
   public:
    void operator()(const X_monotone_curve_2& c, const Point_2& p, X_monotone_curve_2& c1, X_monotone_curve_2& c2) const {
    BEZOUTIAN_PROFILE_SCOPE("Split_2");
      const Parameter t = parameter_of(c, p);
      X_monotone_curve_2 a = make_arc(c.supporting(), c.parameter_min(), t, c.point_at_min_parameter(), p);
      X_monotone_curve_2 b = make_arc(c.supporting(), t, c.parameter_max(), p, c.point_at_max_parameter());
      if (!c.follows_parameter()) {
        a = a.opposite();
        b = b.opposite();
      }
      if (cmp_xy(a.left(), b.left()) < 0) {
        c1 = a;
        c2 = b;
      } else {
        c1 = b;
        c2 = a;
      }
    }
  };

  /// Intersection points (sorted lexicographically, with multiplicity 1 for transversal crossings in the
  /// interior of both arcs and 0 = unknown otherwise) and overlapping sub-arcs.
  template <class OutputIterator>
  OutputIterator intersect(const X_monotone_curve_2& c1, const X_monotone_curve_2& c2, OutputIterator oi) const {
    BEZOUTIAN_PROFILE_SCOPE("Intersect_2");
    using Ip = std::pair<Point_2, Multiplicity>;
    using Result = boost::variant<Ip, X_monotone_curve_2>;
    std::vector<std::pair<Point_2, Result>> out;  // key: lexicographic position
    auto inside = [](const Parameter& t, const X_monotone_curve_2& c) {
      return t >= c.parameter_min() && t <= c.parameter_max();
    };
    auto interior = [](const Parameter& t, const X_monotone_curve_2& c) {
      return t > c.parameter_min() && t < c.parameter_max();
    };
    const auto& A = c1.supporting();
    const auto& B = c2.supporting();
    const Pair_entry& e = intersections(A, B);
    if (A == B) {
      if (c1.parameter_min() == c2.parameter_min() && c1.parameter_max() == c2.parameter_max()) {
        *oi++ = Result(c1);
        return oi;
      }
      // Self-intersection points (s < t) on one arc each; shared ends of adjacent arcs.
      for (const auto& ip : e.points)
        if ((inside(ip.s, c1) && inside(ip.t, c2)) || (inside(ip.t, c1) && inside(ip.s, c2)))
          out.push_back({ip.p, Result(Ip(ip.p, 0))});
      if (c1.parameter_max() == c2.parameter_min())
        out.push_back({c1.point_at_max_parameter(), Result(Ip(c1.point_at_max_parameter(), 0))});
      if (c2.parameter_max() == c1.parameter_min())
        out.push_back({c1.point_at_min_parameter(), Result(Ip(c1.point_at_min_parameter(), 0))});
      // Overlapping parameter ranges of one curve (cannot happen for arcs of one arrangement).
      if (c1.parameter_min() < c2.parameter_max() && c2.parameter_min() < c1.parameter_max()) {
        const Parameter lo = c1.parameter_min() > c2.parameter_min() ? c1.parameter_min() : c2.parameter_min();
        const Parameter hi = c1.parameter_max() < c2.parameter_max() ? c1.parameter_max() : c2.parameter_max();
        out.clear();
        X_monotone_curve_2 o = make_arc(A, lo, hi, Point_2(A, lo), Point_2(A, hi));
        out.push_back({o.left(), Result(o)});
      }
    } else {
      for (const auto& ip : e.points) {
        if (!inside(ip.s, c1) || !inside(ip.t, c2)) continue;
        const bool transversal = !ip.tangent && interior(ip.s, c1) && interior(ip.t, c2);
        out.push_back({ip.p, Result(Ip(ip.p, transversal ? 1u : 0u))});
      }
      for (const auto& o : e.overlaps) overlap_part(c1, c2, o, out);
    }
    std::sort(out.begin(), out.end(), [](const std::pair<Point_2, Result>& a, const std::pair<Point_2, Result>& b) {
      return cmp_xy(a.first, b.first) < 0;
    });
    // A point reported with an overlap that starts or ends there is dropped (CGAL expects disjoint objects).
    std::vector<std::pair<Point_2, Result>> clean;
    for (std::size_t i = 0; i < out.size(); ++i) {
      const Ip* ip = boost::get<Ip>(&out[i].second);
      bool covered = false;
      if (ip)
        for (const auto& q : out)
          if (const X_monotone_curve_2* c = boost::get<X_monotone_curve_2>(&q.second))
            if (cmp_xy(c->left(), ip->first) <= 0 && cmp_xy(ip->first, c->right()) <= 0) covered = true;
      if (ip && !clean.empty()) {
        const Ip* prev = boost::get<Ip>(&clean.back().second);
        if (prev && cmp_xy(prev->first, ip->first) == 0) covered = true;
      }
      if (!covered) clean.push_back(out[i]);
    }
    for (auto& r : clean) *oi++ = r.second;
    return oi;
  }

  /// The common part of c1 and c2 inside one overlap of their supporting curves.
  void overlap_part(const X_monotone_curve_2& c1, const X_monotone_curve_2& c2, const Cached_overlap& o,
                    std::vector<std::pair<Point_2, boost::variant<std::pair<Point_2, Multiplicity>, X_monotone_curve_2>>>& out) const {
    using Ip = std::pair<Point_2, Multiplicity>;
    const auto& A = c1.supporting();
    const auto& B = c2.supporting();
    auto mx = [](const Parameter& a, const Parameter& b) { return a > b ? a : b; };
    auto mn = [](const Parameter& a, const Parameter& b) { return a < b ? a : b; };
    const Parameter smin = mn(o.s0, o.s1), smax = mx(o.s0, o.s1);
    const Parameter tmin = mn(o.t0, o.t1), tmax = mx(o.t0, o.t1);
    const Parameter tl = mx(c2.parameter_min(), tmin), th = mn(c2.parameter_max(), tmax);
    if (tl > th) return;
    // the s on A of the points of B at tl, th
    auto to_s = [&](const Parameter& t) -> Parameter {
      if (t == o.t0) return o.s0;
      if (t == o.t1) return o.s1;
      const Point_2 q = t == c2.parameter_min() ? c2.point_at_min_parameter()
                                                : (t == c2.parameter_max() ? c2.point_at_max_parameter() : Point_2(B, t));
      const int k = A->vertical ? 1 : 0;
      auto r = internal::arr_parameters_at(*A, k, k == 0 ? q.x() : q.y(), smin, smax, k == 0 ? &q.y() : &q.x());
      if (r.size() != 1) throw Invalid_input("Arr_rational_bezier_traits_2: overlap through a self-intersection (unsupported)");
      return r[0];
    };
    const Parameter u = to_s(tl), v = to_s(th);
    const Parameter lo = mx(mx(c1.parameter_min(), smin), mn(u, v));
    const Parameter hi = mn(mn(c1.parameter_max(), smax), mx(u, v));
    const int c = lo.compare(hi);
    if (c > 0) return;
    auto pt = [&](const Parameter& t) {
      if (t == c1.parameter_min()) return c1.point_at_min_parameter();
      if (t == c1.parameter_max()) return c1.point_at_max_parameter();
      return Point_2(A, t);
    };
    if (c == 0) {
      const Point_2 p = pt(lo);
      out.push_back({p, Ip(p, 0)});
      return;
    }
    X_monotone_curve_2 arc = make_arc(A, lo, hi, pt(lo), pt(hi));
    out.push_back({arc.left(), arc});
  }

  class Intersect_2 {
   public:
    explicit Intersect_2(const Arr_rational_bezier_traits_2* t) : tr_(t) {}
    template <class OutputIterator>
    OutputIterator operator()(const X_monotone_curve_2& c1, const X_monotone_curve_2& c2, OutputIterator oi) const {
      return tr_->intersect(c1, c2, oi);
    }
   private:
    const Arr_rational_bezier_traits_2* tr_;
  };

  class Are_mergeable_2 {
   public:
    bool operator()(const X_monotone_curve_2& a, const X_monotone_curve_2& b) const {
      if (a.supporting() != b.supporting() || a.is_increasing() != b.is_increasing()) return false;
      if (a.follows_parameter() != b.follows_parameter()) return false;
      return a.parameter_max() == b.parameter_min() || b.parameter_max() == a.parameter_min();
    }
  };
  class Merge_2 {
   public:
    void operator()(const X_monotone_curve_2& a, const X_monotone_curve_2& b, X_monotone_curve_2& c) const {
      if (!Are_mergeable_2()(a, b)) throw Invalid_input("Arr_rational_bezier_traits_2: curves are not mergeable");
      const X_monotone_curve_2& f = a.parameter_max() == b.parameter_min() ? a : b;
      const X_monotone_curve_2& g = a.parameter_max() == b.parameter_min() ? b : a;
      c = X_monotone_curve_2(f.supporting(), f.parameter_min(), g.parameter_max(), f.point_at_min_parameter(),
                             g.point_at_max_parameter(), f.is_increasing());
      if (!f.follows_parameter()) c = c.opposite();
    }
  };

  class Construct_opposite_2 {
   public:
    X_monotone_curve_2 operator()(const X_monotone_curve_2& c) const { return c.opposite(); }
  };
  class Compare_endpoints_xy_2 {
   public:
    CGAL::Comparison_result operator()(const X_monotone_curve_2& c) const {
      return c.is_directed_right() ? CGAL::SMALLER : CGAL::LARGER;
    }
  };

  /// Approximation of a point coordinate (i = 0: x, 1: y) as a double (ArrangementApproximateTraits_2).
  using Approximate_number_type = double;
  class Approximate_2 {
   public:
    double operator()(const Point_2& p, int i) const { return p.approximate(i); }
  };

  /// The segment from p to q (ArrangementConstructXMonotoneCurveTraits_2, used by landmark point location): a
  /// degree-1 Bezier curve, so both points must be rational (throws Invalid_input otherwise; with
  /// CGAL::Arr_grid_landmarks_generator or Arr_halton_landmarks_generator the landmarks are rational).
  class Construct_x_monotone_curve_2 {
   public:
    X_monotone_curve_2 operator()(const Point_2& p, const Point_2& q) const {
      if (cmp_xy(p, q) == 0) throw Invalid_input("Arr_rational_bezier_traits_2: a segment needs two different points");
      std::vector<Curve_2::Point> ends;
      for (const Point_2* r : {&p, &q}) {
        if (!r->x().is_rational() || !r->y().is_rational())
          throw Invalid_input("Arr_rational_bezier_traits_2: Construct_x_monotone_curve_2 needs rational points "
                              "(landmark point location: use rational landmarks, e.g. Arr_grid_landmarks_generator)");
        ends.push_back({r->x().rational_value(), r->y().rational_value()});
      }
      const auto s = internal::make_supporting_curve(Curve_2(ends));
      return make_arc(s, Parameter(0), Parameter(1), p, q);
    }
  };
  Construct_x_monotone_curve_2 construct_x_monotone_curve_2_object() const { return Construct_x_monotone_curve_2(); }

  Compare_x_2 compare_x_2_object() const { return Compare_x_2(); }
  Compare_xy_2 compare_xy_2_object() const { return Compare_xy_2(); }
  Construct_min_vertex_2 construct_min_vertex_2_object() const { return Construct_min_vertex_2(); }
  Construct_max_vertex_2 construct_max_vertex_2_object() const { return Construct_max_vertex_2(); }
  Is_vertical_2 is_vertical_2_object() const { return Is_vertical_2(); }
  Compare_y_at_x_2 compare_y_at_x_2_object() const { return Compare_y_at_x_2(); }
  Compare_y_at_x_left_2 compare_y_at_x_left_2_object() const { return Compare_y_at_x_left_2(this); }
  Compare_y_at_x_right_2 compare_y_at_x_right_2_object() const { return Compare_y_at_x_right_2(this); }
  Equal_2 equal_2_object() const { return Equal_2(this); }
  Make_x_monotone_2 make_x_monotone_2_object() const { return Make_x_monotone_2(); }
  Split_2 split_2_object() const { return Split_2(); }
  Intersect_2 intersect_2_object() const { return Intersect_2(this); }
  Are_mergeable_2 are_mergeable_2_object() const { return Are_mergeable_2(); }
  Merge_2 merge_2_object() const { return Merge_2(); }
  Construct_opposite_2 construct_opposite_2_object() const { return Construct_opposite_2(); }
  Compare_endpoints_xy_2 compare_endpoints_xy_2_object() const { return Compare_endpoints_xy_2(); }
  Approximate_2 approximate_2_object() const { return Approximate_2(); }

  /// Number of pairs of supporting curves whose intersections are cached.
  std::size_t cached_pairs() const {
    std::lock_guard<std::mutex> lock(cache_->mutex);
    return cache_->pairs.size();
  }

 private:
  using Ci_poly1 = internal::Ci_poly1;
  // Shared by the copies of a traits object, which independent arrangements may use from several threads: the map
  // is read and extended under `mutex`; a pair is computed without it (an entry inserted meanwhile is kept), and
  // entries never move or change once inserted.
  struct Cache {
    std::mutex mutex;
    std::map<std::pair<std::size_t, std::size_t>, Pair_entry> pairs;
    const Pair_entry& insert(const std::pair<std::size_t, std::size_t>& key, Pair_entry e) {
      std::lock_guard<std::mutex> lock(mutex);
      return pairs.emplace(key, std::move(e)).first->second;
    }
  };
  std::shared_ptr<Cache> cache_;
};

}  // namespace bezoutian

#endif  // BEZOUTIAN_ARRANGEMENT_ARR_RATIONAL_BEZIER_TRAITS_2_H
