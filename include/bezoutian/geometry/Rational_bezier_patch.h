// Rational tensor-product Bezier patches of bi-degree (m,n) in 3D with exact coefficients.
#ifndef BEZOUTIAN_GEOMETRY_RATIONAL_BEZIER_PATCH_H
#define BEZOUTIAN_GEOMETRY_RATIONAL_BEZIER_PATCH_H

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

/// \brief A rational tensor-product Bezier patch
/// Phi(u,v) = sum_ij w_ij P_ij B_{i,m}(u) B_{j,n}(v) / sum_ij w_ij B_{i,m}(u) B_{j,n}(v), (u,v) in [0,1]^2.
///
/// Row index i runs along u (degree m), column index j along v (degree n). The net is stored in homogeneous
/// form (w, w x, w y, w z), weight first, matching (Phi_0, Phi_1, Phi_2, Phi_3) of buse-elkadi-galligo-2008
/// eq. (1). Zero weights are allowed only through from_homogeneous()/from_power_form() (control points at
/// infinity); the zero vector is rejected.
template <class FT_ = Rational>
class Rational_bezier_patch {
 public:
  using FT = FT_;
  using Point = std::array<FT, 3>;
  using Homogeneous_point = std::array<FT, 4>;
  using Polynomial = Polynomial_2<FT>;  // inner variable u, outer variable v
  /// Power-basis homogeneous form (Phi_0, Phi_1, Phi_2, Phi_3) = (W, X, Y, Z).
  using Power_form = std::array<Polynomial, 4>;
  using Net = std::vector<std::vector<Homogeneous_point>>;

  /// Polynomial patch (all weights 1) from an (m+1) x (n+1) net of points.
  explicit Rational_bezier_patch(const std::vector<std::vector<Point>>& points)
      : Rational_bezier_patch(points, std::vector<std::vector<FT>>(points.size(),
                                                                  std::vector<FT>(points.empty() ? 0 : points[0].size(), FT(1)))) {}

  /// Rational patch from an (m+1) x (n+1) net of points and nonzero weights.
  Rational_bezier_patch(const std::vector<std::vector<Point>>& points, const std::vector<std::vector<FT>>& weights) {
    check_shape(points.size(), points.empty() ? 0 : points[0].size());
    if (weights.size() != points.size())
      throw Invalid_input("the weights have " + std::to_string(weights.size()) + " rows, the control net " +
                          std::to_string(points.size()));
    net_.assign(points.size(), std::vector<Homogeneous_point>(points[0].size()));
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (points[i].size() != points[0].size() || weights[i].size() != points[0].size())
        throw Invalid_input("row " + std::to_string(i) + " of the control net (or of its weights) has " +
                            std::to_string(std::min(points[i].size(), weights[i].size())) + " entries, expected " +
                            std::to_string(points[0].size()));
      for (std::size_t j = 0; j < points[i].size(); ++j) {
        if (CGAL::is_zero(weights[i][j]))
          throw Invalid_input("weight (" + std::to_string(i) + "," + std::to_string(j) + ") of the patch is zero");
        net_[i][j][0] = weights[i][j];
        for (int k = 0; k < 3; ++k) net_[i][j][k + 1] = weights[i][j] * points[i][j][k];
      }
    }
    update_cache();
  }

  /// Patch from a homogeneous net (w, w x, w y, w z); w = 0 is a control point at infinity.
  static Rational_bezier_patch from_homogeneous(const Net& net) {
    check_shape(net.size(), net.empty() ? 0 : net[0].size());
    for (std::size_t i = 0; i < net.size(); ++i) {
      if (net[i].size() != net[0].size())
        throw Invalid_input("row " + std::to_string(i) + " of the control net has " + std::to_string(net[i].size()) +
                            " entries, expected " + std::to_string(net[0].size()));
      for (std::size_t j = 0; j < net[i].size(); ++j)
        if (std::all_of(net[i][j].begin(), net[i][j].end(), [](const FT& c) { return CGAL::is_zero(c); }))
          throw Invalid_input("homogeneous control point (" + std::to_string(i) + "," + std::to_string(j) +
                              ") is the zero vector");
    }
    Rational_bezier_patch p(Uninitialized{});
    p.net_ = net;
    p.update_cache();
    return p;
  }

  /// Patch from its power-basis form (W, X, Y, Z); (m,n) = (-1,-1) means the largest degrees present.
  static Rational_bezier_patch from_power_form(const Power_form& p, int m = -1, int n = -1) {
    int dm = 0, dn = 0;
    for (const Polynomial& q : p) {
      if (CGAL::is_zero(q)) continue;
      dn = std::max(dn, q.degree());
      for (int b = 0; b <= q.degree(); ++b)
        if (!CGAL::is_zero(q[b])) dm = std::max(dm, q[b].degree());
    }
    if (m >= 0) {
      if (m < dm) throw Invalid_input("power form of degree " + std::to_string(dm) + " in u does not fit degree " + std::to_string(m));
      dm = m;
    }
    if (n >= 0) {
      if (n < dn) throw Invalid_input("power form of degree " + std::to_string(dn) + " in v does not fit degree " + std::to_string(n));
      dn = n;
    }
    if (CGAL::is_zero(p[0])) throw Invalid_input("the weight polynomial W of the patch is identically zero");
    Net net(dm + 1, std::vector<Homogeneous_point>(dn + 1));
    for (int k = 0; k < 4; ++k) {
      // coefficient grid a[i][b] of u^i v^b, then Bernstein along u (per b), then along v (per row).
      std::vector<std::vector<FT>> rows(dm + 1, std::vector<FT>(dn + 1, FT(0)));
      for (int b = 0; b <= dn; ++b) {
        Polynomial_1<FT> ub = (b <= p[k].degree()) ? p[k][b] : Polynomial_1<FT>(FT(0));
        std::vector<FT> col = power_to_bernstein(ub, dm);
        for (int i = 0; i <= dm; ++i) rows[i][b] = col[i];
      }
      for (int i = 0; i <= dm; ++i) {
        std::vector<FT> r = power_to_bernstein(Polynomial_1<FT>(rows[i].begin(), rows[i].end()), dn);
        for (int j = 0; j <= dn; ++j) net[i][j][k] = r[j];
      }
    }
    return from_homogeneous(net);
  }

  /// Degree in u (number of rows - 1).
  int degree_u() const { return int(net_.size()) - 1; }
  /// Degree in v (number of columns - 1).
  int degree_v() const { return int(net_[0].size()) - 1; }
  std::pair<int, int> bidegree() const { return {degree_u(), degree_v()}; }

  const Net& homogeneous_net() const { return net_; }
  const Homogeneous_point& homogeneous_control_point(std::size_t i, std::size_t j) const { return net_.at(i).at(j); }
  const FT& weight(std::size_t i, std::size_t j) const { return net_.at(i).at(j)[0]; }
  bool is_at_infinity(std::size_t i, std::size_t j) const { return CGAL::is_zero(weight(i, j)); }

  /// Cartesian control point (i,j); throws Invalid_input if it is at infinity.
  Point control_point(std::size_t i, std::size_t j) const {
    const Homogeneous_point& h = net_.at(i).at(j);
    if (CGAL::is_zero(h[0]))
      throw Invalid_input("control point (" + std::to_string(i) + "," + std::to_string(j) + ") is at infinity");
    return {h[1] / h[0], h[2] / h[0], h[3] / h[0]};
  }

  /// True if the weights are not all equal.
  /// Every weight is positive: the weight function is then positive on [0,1]^2 and the patch lies in the convex
  /// hull of its control points.
  bool has_positive_weights() const {
    for (const auto& row : net_)
      for (const Homogeneous_point& h : row)
        if (!CGAL::is_positive(h[0])) return false;
    return true;
  }

  bool is_rational() const {
    for (const auto& row : net_)
      for (const Homogeneous_point& h : row)
        if (h[0] != net_[0][0][0]) return true;
    return false;
  }

  /// Power-basis homogeneous form (Phi_0, Phi_1, Phi_2, Phi_3), exact; inner variable u, outer v.
  Power_form power_form() const {
    Power_form out;
    const int m = degree_u(), n = degree_v();
    for (int k = 0; k < 4; ++k) {
      // along u for every column j, then along v for every power of u
      std::vector<std::vector<FT>> a(m + 1, std::vector<FT>(n + 1));  // a[i][j]: u^i, column j
      for (int j = 0; j <= n; ++j) {
        std::vector<FT> col(m + 1);
        for (int i = 0; i <= m; ++i) col[i] = net_[i][j][k];
        Polynomial_1<FT> pu = bernstein_to_power(col);
        for (int i = 0; i <= m; ++i) a[i][j] = i <= pu.degree() ? pu[i] : FT(0);
      }
      std::vector<std::vector<FT>> c(n + 1, std::vector<FT>(m + 1));  // c[b][i]: coefficient of u^i v^b
      for (int i = 0; i <= m; ++i) {
        Polynomial_1<FT> pv = bernstein_to_power(a[i]);
        for (int b = 0; b <= n; ++b) c[b][i] = b <= pv.degree() ? pv[b] : FT(0);
      }
      std::vector<Polynomial_1<FT>> outer;
      for (int b = 0; b <= n; ++b) outer.emplace_back(c[b].begin(), c[b].end());
      out[k] = Polynomial(outer.begin(), outer.end());
    }
    return out;
  }

  /// Homogeneous value (W, X, Y, Z) at (u,v), exact.
  Homogeneous_point homogeneous_value(const FT& u, const FT& v) const {
    Homogeneous_point h;
    for (int k = 0; k < 4; ++k) {
      std::vector<FT> col;
      for (const auto& row : net_) {
        std::vector<FT> r;
        for (const Homogeneous_point& p : row) r.push_back(p[k]);
        col.push_back(de_casteljau_value(r, v));
      }
      h[k] = de_casteljau_value(col, u);
    }
    return h;
  }

  /// Exact point Phi(u,v); throws Invalid_input at a pole.
  Point operator()(const FT& u, const FT& v) const {
    Homogeneous_point h = homogeneous_value(u, v);
    if (CGAL::is_zero(h[0])) throw Invalid_input("the patch has a pole (W(u,v) = 0) at the requested parameters");
    return {h[1] / h[0], h[2] / h[0], h[3] / h[0]};
  }

  /// Floating-point point Phi(u,v).
  std::array<double, 3> evaluate(double u, double v) const {
    // sum_ij B_i(u) B_j(v) h_ij with the Bernstein values from their recurrence (stable, no allocation for
    // degrees below 32: this is the inner loop of the floating-point lifting)
    const std::size_t m1 = dnet_[0].size(), n1 = m1 ? dnet_[0][0].size() : 0;
    if (m1 > 32 || n1 > 32) {
      std::array<double, 4> h{};
      for (int k = 0; k < 4; ++k) {
        std::vector<double> col;
        for (const auto& row : dnet_[k]) col.push_back(de_casteljau_value(row, v));
        h[k] = de_casteljau_value(col, u);
      }
      return {h[1] / h[0], h[2] / h[0], h[3] / h[0]};
    }
    double bu[32], bv[32];
    auto basis = [](std::size_t n1, double t, double* b) {
      b[0] = 1;
      for (std::size_t d = 1; d < n1; ++d) {
        b[d] = t * b[d - 1];
        for (std::size_t i = d - 1; i >= 1; --i) b[i] = (1 - t) * b[i] + t * b[i - 1];
        b[0] *= 1 - t;
      }
    };
    basis(m1, u, bu);
    basis(n1, v, bv);
    std::array<double, 4> h{};
    for (int k = 0; k < 4; ++k)
      for (std::size_t i = 0; i < m1; ++i) {
        double r = 0;
        for (std::size_t j = 0; j < n1; ++j) r += dnet_[k][i][j] * bv[j];
        h[k] += bu[i] * r;
      }
    return {h[1] / h[0], h[2] / h[0], h[3] / h[0]};
  }

  /// Split at u = t: the sub-patches on [0,t] x [0,1] and [t,1] x [0,1], reparametrized.
  std::pair<Rational_bezier_patch, Rational_bezier_patch> split_u(const FT& t) const {
    Net l = net_, r = net_;
    for (std::size_t j = 0; j < net_[0].size(); ++j)
      for (int k = 0; k < 4; ++k) {
        std::vector<FT> col;
        for (const auto& row : net_) col.push_back(row[j][k]);
        auto lr = de_casteljau_split(col, t);
        for (std::size_t i = 0; i < net_.size(); ++i) {
          l[i][j][k] = lr.first[i];
          r[i][j][k] = lr.second[i];
        }
      }
    return {from_homogeneous(l), from_homogeneous(r)};
  }

  /// Split at v = t.
  std::pair<Rational_bezier_patch, Rational_bezier_patch> split_v(const FT& t) const {
    auto lr = transposed().split_u(t);
    return {lr.first.transposed(), lr.second.transposed()};
  }

  /// The restriction to [u0,u1] x [v0,v1], reparametrized to [0,1]^2.
  Rational_bezier_patch restriction(const FT& u0, const FT& u1, const FT& v0, const FT& v1) const {
    Rational_bezier_patch p = map_u([&](const std::vector<FT>& c) { return bernstein_restrict(c, u0, u1); });
    return p.transposed().map_u([&](const std::vector<FT>& c) { return bernstein_restrict(c, v0, v1); }).transposed();
  }

  /// Degree elevation in u and v by (du, dv).
  Rational_bezier_patch elevated(int du, int dv) const {
    Rational_bezier_patch p = *this;
    for (int i = 0; i < du; ++i) p = p.map_u([](const std::vector<FT>& c) { return bernstein_elevate(c); });
    p = p.transposed();
    for (int i = 0; i < dv; ++i) p = p.map_u([](const std::vector<FT>& c) { return bernstein_elevate(c); });
    return p.transposed();
  }

  /// The patch with u and v exchanged (bi-degree (n,m)).
  Rational_bezier_patch transposed() const {
    Net t(net_[0].size(), std::vector<Homogeneous_point>(net_.size()));
    for (std::size_t i = 0; i < net_.size(); ++i)
      for (std::size_t j = 0; j < net_[0].size(); ++j) t[j][i] = net_[i][j];
    return from_homogeneous(t);
  }

  /// Partial derivative d Phi / du (direction 0) or d Phi / dv (direction 1) as a patch of vectors:
  /// for a polynomial patch the hodograph net (degree lowered by one in that direction); for a rational
  /// patch (X_u W - X W_u) / W^2, of bi-degree (2m, 2n).
  Rational_bezier_patch partial_derivative(int direction) const {
    if (direction != 0 && direction != 1) throw Invalid_input("partial_derivative: direction must be 0 (u) or 1 (v)");
    if (direction == 1) return transposed().partial_derivative(0).transposed();
    if (!is_rational()) {
      const FT w = net_[0][0][0];
      Rational_bezier_patch d = map_u([](const std::vector<FT>& c) { return bernstein_derivative(c); });
      Net net = d.net_;
      for (auto& row : net)
        for (auto& h : row) {
          for (int k = 1; k < 4; ++k) h[k] /= w;
          h[0] = FT(1);
        }
      return from_homogeneous(net);
    }
    Power_form p = power_form(), q;
    using PT = CGAL::Polynomial_traits_d<Polynomial>;
    typename PT::Differentiate diff;
    const Polynomial W = p[0], Wu = diff(W, 0);
    q[0] = W * W;
    for (int k = 1; k < 4; ++k) q[k] = diff(p[k], 0) * W - p[k] * Wu;
    return from_power_form(q, 2 * degree_u(), 2 * degree_v());
  }

  /// Exact box (min, max) of the finite control points; encloses the patch if encloses_patch().
  std::pair<Point, Point> control_box() const {
    Point lo = control_point(0, 0), hi = lo;
    for (std::size_t i = 0; i < net_.size(); ++i)
      for (std::size_t j = 0; j < net_[0].size(); ++j) {
        Point p = control_point(i, j);
        for (int k = 0; k < 3; ++k) {
          if (p[k] < lo[k]) lo[k] = p[k];
          if (hi[k] < p[k]) hi[k] = p[k];
        }
      }
    return {lo, hi};
  }

  /// True when all weights are nonzero with one sign: then the patch lies in the convex hull of its net.
  bool encloses_patch() const {
    const int s = CGAL::sign(net_[0][0][0]);
    for (const auto& row : net_)
      for (const Homogeneous_point& h : row)
        if (s == 0 || CGAL::sign(h[0]) != s) return false;
    return true;
  }

  /// Boundary curve: side 0: v = 0, 1: u = 1, 2: v = 1, 3: u = 0 (as curves in the increasing parameter).
  template <class Curve>
  Curve boundary_curve(int side) const {
    std::vector<typename Curve::Homogeneous_point> h;
    const int m = degree_u(), n = degree_v();
    auto push = [&](int i, int j) {
      typename Curve::Homogeneous_point p;
      for (int k = 0; k < 4; ++k) p[k] = net_[i][j][k];
      h.push_back(p);
    };
    switch (side) {
      case 0: for (int i = 0; i <= m; ++i) push(i, 0); break;
      case 1: for (int j = 0; j <= n; ++j) push(m, j); break;
      case 2: for (int i = 0; i <= m; ++i) push(i, n); break;
      case 3: for (int j = 0; j <= n; ++j) push(0, j); break;
      default: throw Invalid_input("boundary_curve: side must be 0..3");
    }
    return Curve::from_homogeneous(h);
  }

  bool operator==(const Rational_bezier_patch& o) const { return net_ == o.net_; }
  bool operator!=(const Rational_bezier_patch& o) const { return !(*this == o); }

 private:
  struct Uninitialized {};
  explicit Rational_bezier_patch(Uninitialized) {}

  static void check_shape(std::size_t rows, std::size_t cols) {
    if (rows == 0 || cols == 0)
      throw Invalid_input("a Bezier patch needs a non-empty (m+1) x (n+1) control net");
  }

  // Apply a univariate Bernstein operation to every column (along u) of every homogeneous coordinate.
  template <class F>
  Rational_bezier_patch map_u(F f) const {
    Net out;
    for (std::size_t j = 0; j < net_[0].size(); ++j)
      for (int k = 0; k < 4; ++k) {
        std::vector<FT> col;
        for (const auto& row : net_) col.push_back(row[j][k]);
        std::vector<FT> c = f(col);
        if (out.empty()) out.assign(c.size(), std::vector<Homogeneous_point>(net_[0].size()));
        for (std::size_t i = 0; i < c.size(); ++i) out[i][j][k] = c[i];
      }
    return from_homogeneous(out);
  }

  void update_cache() {
    for (int k = 0; k < 4; ++k) {
      dnet_[k].assign(net_.size(), std::vector<double>());
      for (std::size_t i = 0; i < net_.size(); ++i)
        for (const Homogeneous_point& h : net_[i]) dnet_[k][i].push_back(CGAL::to_double(h[k]));
    }
  }

  Net net_;
  std::array<std::vector<std::vector<double>>, 4> dnet_;
};

} // namespace bezoutian

#endif // BEZOUTIAN_GEOMETRY_RATIONAL_BEZIER_PATCH_H
