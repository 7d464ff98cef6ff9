// The x-monotone curve type of Arr_rational_bezier_traits_2 (X_monotone_curve_2): an arc of a supporting
// rational Bezier curve over a parameter range, with its end points (Arr_bezier_point_2) and its direction.
#ifndef BEZOUTIAN_ARRANGEMENT_ARR_BEZIER_X_MONOTONE_CURVE_2_H
#define BEZOUTIAN_ARRANGEMENT_ARR_BEZIER_X_MONOTONE_CURVE_2_H

#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/geometry/Rational_bezier_curve.h>
#include <bezoutian/arrangement/Arr_bezier_point_2.h>
#include <bezoutian/arrangement/internal/arr_bezier_exact.h>
#include <bezoutian/arrangement/internal/arr_bezier_parameter.h>

#include <memory>
#include <ostream>
#include <utility>
#include <vector>

namespace bezoutian {

/// \brief An x-monotone arc: the supporting curve restricted to a parameter range [t0, t1] (t0 < t1), with its
/// end points. Vertical arcs (x constant) are y-monotone.
class Arr_bezier_x_monotone_curve_2 {
 public:
  using Supporting = internal::Arr_bezier_supporting_curve;
  using Parameter = internal::Arr_parameter;
  using Point_2 = Arr_bezier_point_2;
  using Multiplicity = unsigned int;

  Arr_bezier_x_monotone_curve_2() = default;
  /// The arc of s on [t0, t1] with the given end points; `increasing` says whether x (y for vertical arcs)
  /// increases with the parameter. The arc is directed like the parameter (source at t0);
  /// Construct_opposite_2 flips the direction.
  Arr_bezier_x_monotone_curve_2(std::shared_ptr<const Supporting> s, const Parameter& t0, const Parameter& t1,
                                const Point_2& p0, const Point_2& p1, bool increasing)
      : s_(std::move(s)), t0_(t0), t1_(t1), p0_(p0), p1_(p1), increasing_(increasing), directed_right_(increasing) {}

  const std::shared_ptr<const Supporting>& supporting() const { return s_; }
  const Rational_bezier_curve_2<Rational>& supporting_curve() const { return s_->curve; }
  const Parameter& parameter_min() const { return t0_; }
  const Parameter& parameter_max() const { return t1_; }
  const Point_2& point_at_min_parameter() const { return p0_; }
  const Point_2& point_at_max_parameter() const { return p1_; }
  bool is_vertical() const { return s_->vertical; }
  bool is_increasing() const { return increasing_; }
  bool is_directed_right() const { return directed_right_; }
  /// True if the direction is that of increasing parameter.
  bool follows_parameter() const { return directed_right_ == increasing_; }
  /// Lexicographically smallest / largest end.
  const Point_2& left() const { return increasing_ ? p0_ : p1_; }
  const Point_2& right() const { return increasing_ ? p1_ : p0_; }
  const Point_2& source() const { return directed_right_ ? left() : right(); }
  const Point_2& target() const { return directed_right_ ? right() : left(); }
  Arr_bezier_x_monotone_curve_2 opposite() const {
    Arr_bezier_x_monotone_curve_2 c = *this;
    c.directed_right_ = !directed_right_;
    return c;
  }

  /// A polyline through n+1 points of the arc (doubles, for drawing), from the min-parameter end.
  std::vector<std::pair<double, double>> polyline(int n = 32) const {
    std::vector<std::pair<double, double>> out;
    const double a = t0_.to_double(), b = t1_.to_double();
    out.push_back({p0_.approximate_x(), p0_.approximate_y()});
    for (int i = 1; i < n; ++i) {
      const auto q = s_->curve.evaluate(a + (b - a) * i / n);
      out.push_back({q[0], q[1]});
    }
    out.push_back({p1_.approximate_x(), p1_.approximate_y()});
    return out;
  }

  friend std::ostream& operator<<(std::ostream& os, const Arr_bezier_x_monotone_curve_2& c) {
    return os << "[curve " << c.s_->id << " t in [" << c.t0_.to_double() << ", " << c.t1_.to_double() << "]: "
              << c.p0_ << " -> " << c.p1_ << "]";
  }

 private:
  std::shared_ptr<const Supporting> s_;
  Parameter t0_, t1_;
  Point_2 p0_, p1_;
  bool increasing_ = true;
  bool directed_right_ = true;
};

}  // namespace bezoutian

#endif  // BEZOUTIAN_ARRANGEMENT_ARR_BEZIER_X_MONOTONE_CURVE_2_H
