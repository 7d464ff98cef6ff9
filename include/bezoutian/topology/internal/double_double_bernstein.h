// Bernstein coefficients of a sub-box in double-double arithmetic with a proved error bound: the cheap way to
// refresh a Double_bernstein_grid deep in the subdivision (Curve_topology_by_subdivision.h), where the double grid
// inherited from its parents has lost its sharpness and an MPFI restriction from the domain's grid costs four
// de Casteljau passes of interval operations at 144 bits.
//
// Representation: the exact coefficient c_ij lies within E of hi_ij + lo_ij (one absolute bound E for the grid;
// values are scaled so that |c| <= M, M about 1). A restriction to [lo, hi] of one variable is de Casteljau's
// algorithm at ratio hi, then at lo/hi; each level is the convex combination w' = s w_k + r w_(k+1). Computed with
// double-double weights r~, s~ (|r~ - r| + |s~ - (1 - r)| <= delta, found exactly with rationals) and
// double-double products and sums (error-free transformations: two_sum, and two_prod by fma, exact whether the
// fma is a hardware instruction or glibc's correctly rounded one; relative error of a product or sum below
// 8 u^2, u = 2^-53), one level changes the error by at most
//     (input error) (1 + delta) + M (delta + 64 u^2) + 16 eta    (eta = 2^-1074: underflow),
// an exact level never increases the magnitudes beyond M (convex combination), so n levels add
// n (M (delta + 64 u^2) + 16 eta) and multiply the input error by (1 + delta)^n <= 1 + 2 n delta.
#ifndef BEZOUTIAN_TOPOLOGY_INTERNAL_DOUBLE_DOUBLE_BERNSTEIN_H
#define BEZOUTIAN_TOPOLOGY_INTERNAL_DOUBLE_DOUBLE_BERNSTEIN_H

#include <bezoutian/topology/internal/double_bernstein_grid.h>
#include <bezoutian/arithmetic/double_double.h>
#include <bezoutian/arithmetic/number_types.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace bezoutian {
namespace internal {

class Double_double_bernstein {
 public:
  Double_double_bernstein(int a, int b) : a_(a), b_(b), c_(std::size_t(a + 1) * (b + 1)) {}
  Double_double& at(int i, int j) { return c_[std::size_t(i) * (b_ + 1) + j]; }
  const Double_double& at(int i, int j) const { return c_[std::size_t(i) * (b_ + 1) + j]; }
  /// Absolute error bound E and magnitude bound M of the exact coefficients (both in the stored units).
  void set_bounds(double error, double magnitude) {
    E_ = error;
    M_ = magnitude;
  }
  double error() const { return E_; }

  /// The coefficients on [u0, u1] x [v0, v1] (fractions of this grid's box, 0 <= u0 < u1 <= 1, same for v) as a
  /// double grid whose radius is proved (scaled by a power of two, like Double_bernstein_grid::rescale); `scale`
  /// is the power of two of this grid's units.
  std::shared_ptr<Double_bernstein_grid> restrict_to(const Rational& u0, const Rational& u1, const Rational& v0,
                                                     const Rational& v1, int scale) const {
    std::vector<Double_double> g;
    double E = 0;
    restrict_values(u0, u1, v0, v1, g, E);
    auto f = std::make_shared<Double_bernstein_grid>(a_, b_);
    double lo_max = 0;
    for (int i = 0; i <= a_; ++i)
      for (int j = 0; j <= b_; ++j) {
        const Double_double& x = g[std::size_t(i) * (b_ + 1) + j];
        f->at(i, j) = x.hi;
        lo_max = std::max(lo_max, std::fabs(x.lo));
      }
    // radius: the dropped low parts plus E, rounded upwards (two additions: a relative 4u suffices)
    f->set_radius((lo_max + E) * (1 + 1e-15) + 1e-300);
    f->set_exponent(scale);
    f->rescale();
    return f;
  }

  /// The double-double coefficients g (row-major, (a+1) x (b+1)) on the same sub-box, each within E of the exact
  /// one (in this grid's units).
  void restrict_values(const Rational& u0, const Rational& u1, const Rational& v0, const Rational& v1,
                       std::vector<Double_double>& g, double& E) const {
    g = c_;
    E = E_;
    for (int pass = 0; pass < 2; ++pass) {
      const bool along_u = pass == 0;
      const Rational& lo = along_u ? u0 : v0;
      const Rational& hi = along_u ? u1 : v1;
      if (hi < Rational(1)) casteljau(g, along_u, hi, true, E);       // keep [0, hi]
      if (lo > Rational(0)) casteljau(g, along_u, lo / hi, false, E);  // then [lo / hi, 1] of that
    }
  }

 private:
  // de Casteljau at ratio t along one variable, keeping the left part [0, t] or the right part [t, 1]
  void casteljau(std::vector<Double_double>& g, bool along_u, const Rational& t, bool keep_left, double& E) const {
    const int n = along_u ? a_ : b_, m = along_u ? b_ : a_;
    const Double_double r = to_dd(t), s = to_dd(Rational(1) - t);
    const Rational dr = CGAL::abs(t - Rational(r.hi) - Rational(r.lo)),
                   ds = CGAL::abs(Rational(1) - t - Rational(s.hi) - Rational(s.lo));
    const double delta = 2 * (CGAL::to_double(dr) + CGAL::to_double(ds)) + 1e-300;  // upward
    const double u2 = std::ldexp(1.0, -106), eta = std::ldexp(1.0, -1074);
    std::vector<Double_double> w(std::size_t(n + 1)), out(std::size_t(n + 1));
    auto G = [&](int k, int l) -> Double_double& {
      return along_u ? g[std::size_t(k) * (b_ + 1) + l] : g[std::size_t(l) * (b_ + 1) + k];
    };
    for (int l = 0; l <= m; ++l) {
      for (int k = 0; k <= n; ++k) w[k] = G(k, l);
      if (keep_left)
        out[0] = w[0];
      else
        out[n] = w[n];
      for (int level = 1; level <= n; ++level) {
        for (int k = 0; k + level <= n; ++k) w[k] = dd_add(dd_mul(s, w[k]), dd_mul(r, w[k + 1]));
        if (keep_left)
          out[level] = w[0];
        else
          out[n - level] = w[n - level];
      }
      for (int k = 0; k <= n; ++k) G(k, l) = out[k];
    }
    E = E * (1 + 2 * n * delta) + n * (M_ * (delta + 64 * u2) + 16 * eta);
    E *= 1 + 1e-14;  // the bound itself was computed in double
  }
  static Double_double to_dd(const Rational& x) {
    const double hi = CGAL::to_double(x);
    return {hi, CGAL::to_double(x - Rational(hi))};
  }

  int a_, b_;
  std::vector<Double_double> c_;
  double E_ = 0, M_ = 1;
};

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_TOPOLOGY_INTERNAL_DOUBLE_DOUBLE_BERNSTEIN_H
