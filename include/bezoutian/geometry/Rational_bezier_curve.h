// Rational Bezier curves of any degree in dimension 2 or 3 with exact coefficients.
#ifndef BEZOUTIAN_GEOMETRY_RATIONAL_BEZIER_CURVE_H
#define BEZOUTIAN_GEOMETRY_RATIONAL_BEZIER_CURVE_H

#include <bezoutian/geometry/Bernstein_basis.h>
#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/arithmetic/number_types.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace bezoutian {

/// \brief A rational Bezier curve C(t) = sum_i w_i P_i B_{i,n}(t) / sum_i w_i B_{i,n}(t), t in [0,1].
///
/// The control net is stored in homogeneous form (w_i, w_i P_i): weight first, as Phi_0 is the weight in
/// buse-elkadi-galligo-2008 eq. (1). A homogeneous control point with w_i = 0 is a control point at
/// infinity (needed to represent e.g. power-basis input whose weight has a zero Bernstein coefficient);
/// the zero vector is rejected. All weights equal means a polynomial curve.
/// \tparam FT_ an exact field type (default CGAL::Gmpq)
/// \tparam D   the dimension of the ambient space (2 or 3)
template <class FT_ = Rational, int D = 2>
class Rational_bezier_curve {
  static_assert(D == 2 || D == 3, "Rational_bezier_curve: dimension 2 or 3");

 public:
  using FT = FT_;
  static constexpr int dimension = D;
  /// Cartesian point (x_1, ..., x_D).
  using Point = std::array<FT, D>;
  /// Homogeneous control point (w, w x_1, ..., w x_D).
  using Homogeneous_point = std::array<FT, D + 1>;
  using Polynomial = Polynomial_1<FT>;
  /// Power-basis homogeneous form (W, X_1, ..., X_D): C(t) = (X_1(t), ..., X_D(t)) / W(t).
  using Power_form = std::array<Polynomial, D + 1>;

  /// The point (0,...,0) as a curve of degree 0.
  Rational_bezier_curve() : Rational_bezier_curve(std::vector<Point>(1, zero_point())) {}

  /// Polynomial curve (all weights 1) through the control points.
  explicit Rational_bezier_curve(const std::vector<Point>& points)
      : Rational_bezier_curve(points, std::vector<FT>(points.size(), FT(1))) {}

  /// Rational curve from control points and nonzero weights.
  Rational_bezier_curve(const std::vector<Point>& points, const std::vector<FT>& weights) {
    if (points.empty()) throw Invalid_input("a Bezier curve needs at least one control point");
    if (points.size() != weights.size())
      throw Invalid_input("a Bezier curve with " + std::to_string(points.size()) + " control points needs " +
                          std::to_string(points.size()) + " weights, got " + std::to_string(weights.size()));
    net_.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (CGAL::is_zero(weights[i]))
        throw Invalid_input("weight " + std::to_string(i) + " of the Bezier curve is zero");
      net_[i][0] = weights[i];
      for (int k = 0; k < D; ++k) net_[i][k + 1] = weights[i] * points[i][k];
    }
    update_cache();
  }

  /// Curve from homogeneous control points (w_i, w_i P_i); w_i = 0 is a control point at infinity.
  static Rational_bezier_curve from_homogeneous(const std::vector<Homogeneous_point>& net) {
    if (net.empty()) throw Invalid_input("a Bezier curve needs at least one control point");
    for (std::size_t i = 0; i < net.size(); ++i)
      if (std::all_of(net[i].begin(), net[i].end(), [](const FT& c) { return CGAL::is_zero(c); }))
        throw Invalid_input("homogeneous control point " + std::to_string(i) + " is the zero vector");
    Rational_bezier_curve c(Uninitialized{});
    c.net_ = net;
    c.update_cache();
    return c;
  }

  /// Curve from its power-basis homogeneous form (W, X_1, ..., X_D); degree -1 means the largest degree present.
  static Rational_bezier_curve from_power_form(const Power_form& p, int degree = -1) {
    int n = 0;
    for (const Polynomial& q : p)
      if (!CGAL::is_zero(q)) n = std::max(n, q.degree());
    if (degree >= 0) {
      if (degree < n)
        throw Invalid_input("power form of degree " + std::to_string(n) + " requested as a Bezier curve of degree " +
                            std::to_string(degree));
      n = degree;
    }
    if (CGAL::is_zero(p[0])) throw Invalid_input("the weight polynomial W of the curve is identically zero");
    std::vector<Homogeneous_point> net(n + 1);
    for (int k = 0; k <= D; ++k) {
      std::vector<FT> b = power_to_bernstein(p[k], n);
      for (int i = 0; i <= n; ++i) net[i][k] = b[i];
    }
    return from_homogeneous(net);
  }

  int degree() const { return int(net_.size()) - 1; }
  std::size_t number_of_control_points() const { return net_.size(); }
  const std::vector<Homogeneous_point>& homogeneous_control_points() const { return net_; }
  const Homogeneous_point& homogeneous_control_point(std::size_t i) const { return net_.at(i); }
  const FT& weight(std::size_t i) const { return net_.at(i)[0]; }
  bool is_at_infinity(std::size_t i) const { return CGAL::is_zero(weight(i)); }

  /// Cartesian control point i; throws Invalid_input if it is at infinity (zero weight).
  Point control_point(std::size_t i) const {
    const Homogeneous_point& h = net_.at(i);
    if (CGAL::is_zero(h[0])) throw Invalid_input("control point " + std::to_string(i) + " is at infinity");
    Point p;
    for (int k = 0; k < D; ++k) p[k] = h[k + 1] / h[0];
    return p;
  }
  std::vector<Point> control_points() const {
    std::vector<Point> p;
    for (std::size_t i = 0; i < net_.size(); ++i) p.push_back(control_point(i));
    return p;
  }
  std::vector<FT> weights() const {
    std::vector<FT> w;
    for (const Homogeneous_point& h : net_) w.push_back(h[0]);
    return w;
  }

  /// True if the weights are not all equal (a polynomial curve is a rational curve with equal weights).
  bool is_rational() const {
    for (const Homogeneous_point& h : net_)
      if (h[0] != net_[0][0]) return true;
    return false;
  }

  /// Bernstein coefficients of homogeneous coordinate k (0 = weight W, k = X_k).
  std::vector<FT> bernstein_coefficients(int k) const {
    std::vector<FT> b;
    for (const Homogeneous_point& h : net_) b.push_back(h[k]);
    return b;
  }

  /// Power-basis homogeneous form (W, X_1, ..., X_D), exact.
  Power_form power_form() const {
    Power_form p;
    for (int k = 0; k <= D; ++k) p[k] = bernstein_to_power(bernstein_coefficients(k));
    return p;
  }

  /// Homogeneous value (W(t), X_1(t), ..., X_D(t)) at t, exact.
  Homogeneous_point homogeneous_value(const FT& t) const {
    Homogeneous_point h;
    for (int k = 0; k <= D; ++k) h[k] = de_casteljau_value(bernstein_coefficients(k), t);
    return h;
  }

  /// Exact point C(t); throws Invalid_input at a pole (W(t) = 0).
  Point operator()(const FT& t) const {
    const Homogeneous_point h = homogeneous_value(t);
    if (CGAL::is_zero(h[0])) throw Invalid_input("the curve has a pole (W(t) = 0) at the requested parameter");
    Point p;
    for (int k = 0; k < D; ++k) p[k] = h[k + 1] / h[0];
    return p;
  }

  /// Floating-point point C(t) (de Casteljau on double copies of the net).
  std::array<double, D> evaluate(double t) const {
    std::array<double, D + 1> h{};
    for (int k = 0; k <= D; ++k) h[k] = de_casteljau_value(dnet_[k], t);
    std::array<double, D> p;
    for (int k = 0; k < D; ++k) p[k] = h[k + 1] / h[0];
    return p;
  }

  /// de Casteljau subdivision at t: the pieces on [0,t] and [t,1], each reparametrized to [0,1].
  std::pair<Rational_bezier_curve, Rational_bezier_curve> split(const FT& t) const {
    std::vector<Homogeneous_point> l(net_.size()), r(net_.size());
    for (int k = 0; k <= D; ++k) {
      auto lr = de_casteljau_split(bernstein_coefficients(k), t);
      for (std::size_t i = 0; i < net_.size(); ++i) {
        l[i][k] = lr.first[i];
        r[i][k] = lr.second[i];
      }
    }
    return {from_homogeneous(l), from_homogeneous(r)};
  }

  /// The restriction to [a,b] reparametrized to [0,1] (a > b reverses the direction).
  Rational_bezier_curve restriction(const FT& a, const FT& b) const {
    return map_coordinates([&](const std::vector<FT>& c) { return bernstein_restrict(c, a, b); });
  }

  /// The same curve with its degree raised by `times`.
  Rational_bezier_curve elevated(int times = 1) const {
    Rational_bezier_curve c = *this;
    for (int i = 0; i < times; ++i) c = c.map_coordinates([](const std::vector<FT>& v) { return bernstein_elevate(v); });
    return c;
  }

  /// The same curve traversed backwards, t -> 1 - t.
  Rational_bezier_curve reversed() const {
    std::vector<Homogeneous_point> r(net_.rbegin(), net_.rend());
    return from_homogeneous(r);
  }

  /// The derivative curve C'(t). For a polynomial curve it is the hodograph (degree n-1, as a curve of
  /// vectors); for a rational curve, C' = (X' W - X W') / W^2 as a rational curve of degree 2n.
  Rational_bezier_curve derivative() const {
    if (!is_rational()) {
      const FT w = net_[0][0];
      std::vector<Homogeneous_point> d(std::max(1, degree()));
      for (int k = 1; k <= D; ++k) {
        std::vector<FT> dk = bernstein_derivative(bernstein_coefficients(k));
        for (std::size_t i = 0; i < d.size(); ++i) d[i][k] = dk[i] / w;
      }
      for (auto& h : d) h[0] = FT(1);
      return from_homogeneous(d);
    }
    Power_form p = power_form(), q;
    const Polynomial W = p[0], dW = CGAL::differentiate(W);
    q[0] = W * W;
    for (int k = 1; k <= D; ++k) q[k] = CGAL::differentiate(p[k]) * W - p[k] * dW;
    return from_power_form(q, 2 * degree());
  }

  /// Exact axis-aligned box (min, max) of the finite control points. It encloses the curve when all weights
  /// have the same sign and no control point is at infinity (convex hull property); see encloses_curve().
  std::pair<Point, Point> control_box() const {
    Point lo = control_point(0), hi = lo;
    for (std::size_t i = 1; i < net_.size(); ++i) {
      Point p = control_point(i);
      for (int k = 0; k < D; ++k) {
        if (p[k] < lo[k]) lo[k] = p[k];
        if (hi[k] < p[k]) hi[k] = p[k];
      }
    }
    return {lo, hi};
  }

  /// True if control_box() is guaranteed to contain the whole curve on [0,1].
  bool encloses_curve() const {
    const int s = CGAL::sign(net_[0][0]);
    for (const Homogeneous_point& h : net_)
      if (CGAL::sign(h[0]) != s || s == 0) return false;
    return true;
  }

  /// Exact equality of the homogeneous control nets up to a common nonzero factor (same parametrization).
  bool has_same_parametrization(const Rational_bezier_curve& o) const {
    if (o.net_.size() != net_.size()) return false;
    // find a nonzero pivot to compare ratios
    for (std::size_t i = 0; i < net_.size(); ++i)
      for (int k = 0; k <= D; ++k)
        if (!CGAL::is_zero(net_[i][k])) {
          const FT a = net_[i][k], b = o.net_[i][k];
          for (std::size_t j = 0; j < net_.size(); ++j)
            for (int l = 0; l <= D; ++l)
              if (net_[j][l] * b != o.net_[j][l] * a) return false;
          return !CGAL::is_zero(b);
        }
    return false;
  }

  bool operator==(const Rational_bezier_curve& o) const { return net_ == o.net_; }
  bool operator!=(const Rational_bezier_curve& o) const { return !(*this == o); }

 private:
  struct Uninitialized {};
  explicit Rational_bezier_curve(Uninitialized) {}

  static Point zero_point() {
    Point p;
    p.fill(FT(0));
    return p;
  }

  template <class F>
  Rational_bezier_curve map_coordinates(F f) const {
    std::vector<Homogeneous_point> out;
    for (int k = 0; k <= D; ++k) {
      std::vector<FT> c = f(bernstein_coefficients(k));
      out.resize(c.size());
      for (std::size_t i = 0; i < c.size(); ++i) out[i][k] = c[i];
    }
    return from_homogeneous(out);
  }

  void update_cache() {
    for (int k = 0; k <= D; ++k) {
      dnet_[k].clear();
      for (const Homogeneous_point& h : net_) dnet_[k].push_back(CGAL::to_double(h[k]));
    }
  }

  std::vector<Homogeneous_point> net_;
  std::array<std::vector<double>, D + 1> dnet_;  // double copies for fast approximate evaluation
};

/// Planar rational Bezier curve.
template <class FT = Rational> using Rational_bezier_curve_2 = Rational_bezier_curve<FT, 2>;
/// Spatial rational Bezier curve.
template <class FT = Rational> using Rational_bezier_curve_3 = Rational_bezier_curve<FT, 3>;

} // namespace bezoutian

#endif // BEZOUTIAN_GEOMETRY_RATIONAL_BEZIER_CURVE_H
