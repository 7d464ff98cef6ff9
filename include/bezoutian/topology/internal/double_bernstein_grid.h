// Bivariate Bernstein coefficients in double precision with ONE proved radius: the exact coefficient (i, j) lies
// in 2^e [m_ij - rho, m_ij + rho] (e = exponent(), a common power-of-two scale that no sign decision depends on). This is the
// fast path of the subdivision in Curve_topology_by_subdivision.h: a de Casteljau split costs three flops per
// coefficient and level in plain double arithmetic instead of MPFI operations, and the error it adds is bounded
// a priori, so the exclusion and monotonicity tests stay proofs.
//
// Error bound of one split (ratio r, degree n along the split direction, M = max |m|, u = 2^-52 bounds the
// relative error of one rounding in ANY rounding mode). de Casteljau's levels are convex combinations
// w' = (1 - r) w_k + r w_(k+1). The floating-point level uses r^ = fl(r), s^ = fl(1 - r^) with
// |r^ - r| <= u, |s^ - (1 - r)| <= 2u, and three roundings of quantities <= M' (the magnitudes at that level,
// M' <= M (1 + 6u)^n): its result differs from the exact level applied to the same inputs by at most
// 6u M' + 3 eta (eta = 2^-1074 bounds an absolute underflow error). An exact level does not increase the maximum
// of input errors (convex combination). Hence after n levels
//     |m'_fl - m'_exact(m)| <= n (6u M (1 + 6u)^n + 3 eta),
// and |c' - m'_exact(m)| <= rho for the exact children c' of the exact coefficients c (again convex
// combinations). The new radius adds both, rounded upwards with a relative safety factor.
#ifndef BEZOUTIAN_TOPOLOGY_INTERNAL_DOUBLE_BERNSTEIN_GRID_H
#define BEZOUTIAN_TOPOLOGY_INTERNAL_DOUBLE_BERNSTEIN_GRID_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace bezoutian {
namespace internal {

class Double_bernstein_grid {
 public:
  Double_bernstein_grid() = default;
  Double_bernstein_grid(int a, int b) : a_(a), b_(b), m_(std::size_t(a + 1) * (b + 1), 0.0) {}

  int a() const { return a_; }
  int b() const { return b_; }
  double& at(int i, int j) { return m_[std::size_t(i) * (b_ + 1) + j]; }
  double at(int i, int j) const { return m_[std::size_t(i) * (b_ + 1) + j]; }
  double radius() const { return rho_; }
  void set_radius(double r) { rho_ = r; }
  /// The exact coefficients are 2^exponent() (m_ij +- radius()).
  int exponent() const { return e_; }
  void set_exponent(int e) { e_ = e; }
  /// True when the radius is small against the largest coefficient (the decisions are then as sharp as an
  /// exact-rounded grid would give): rho <= 2^-30 max |m|.
  bool precise() const { return rho_ <= std::ldexp(max_abs(), -30); }

  double max_abs() const {
    double M = 0;
    for (double x : m_) M = std::max(M, std::fabs(x));
    return M;
  }

  /// The tests below take the radius to use: radius() for proofs; 0 asks what the midpoints alone would give
  /// (to decide whether recomputing a sharper grid can help).

  /// +1 / -1 if every exact coefficient is strictly positive / negative (then the polynomial has that sign on
  /// the closed box: a convex combination), 0 otherwise. Comparisons of doubles are exact.
  int common_sign(double rho) const {
    bool pos = true, neg = true;
    for (double x : m_) {
      pos = pos && x > rho;
      neg = neg && x < -rho;
      if (!pos && !neg) return 0;
    }
    return pos ? 1 : -1;
  }

  /// Common strict sign of all forward differences along u (or v) of the exact coefficients, else 0. The
  /// difference t = fl(m1 - m0) is within u |t| + eta of m1 - m0, and the exact coefficients add 2 rho.
  int difference_sign(bool along_u, double rho) const {
    const double r2 = 2 * rho * (1 + 1e-12) + 1e-300;
    bool pos = true, neg = true;
    for (int i = 0; i <= a_; ++i)
      for (int j = 0; j <= b_; ++j) {
        if (along_u ? i == a_ : j == b_) continue;
        const double t = (along_u ? at(i + 1, j) : at(i, j + 1)) - at(i, j);
        const double bound = r2 + std::fabs(t) * 4.5e-16;
        pos = pos && t > bound;
        neg = neg && t < -bound;
        if (!pos && !neg) return 0;
      }
    return pos ? 1 : -1;
  }

  /// Enclosure [lo, hi] of the range of the second difference k (0: uu, 1: uv, 2: vv) over the grid, times the
  /// factor that makes it the range of the second derivative in local coordinates (Bernstein derivative).
  void second_difference_range(int k, double rho, double& lo, double& hi) const {
    const int di = 2 - k, dj = k;
    lo = hi = 0;
    if (a_ < di || b_ < dj) return;
    bool first = true;
    for (int i = 0; i + di <= a_; ++i)
      for (int j = 0; j + dj <= b_; ++j) {
        double t;
        if (k == 0)
          t = at(i + 2, j) - 2 * at(i + 1, j) + at(i, j);
        else if (k == 2)
          t = at(i, j + 2) - 2 * at(i, j + 1) + at(i, j);
        else
          t = at(i + 1, j + 1) - at(i + 1, j) - at(i, j + 1) + at(i, j);
        if (first) lo = hi = t;
        lo = std::min(lo, t);
        hi = std::max(hi, t);
        first = false;
      }
    // 4 rho from the inputs, three roundings of sums of magnitude <= 4 M
    const double e = 4 * rho + 16 * max_abs() * 2.3e-16 + 1e-300;
    const double f = k == 0 ? double(a_) * (a_ - 1) : (k == 2 ? double(b_) * (b_ - 1) : double(a_) * b_);
    lo = (lo - e) * f * (1 + 1e-12);
    hi = (hi + e) * f * (1 + 1e-12);
    if (lo > 0) lo *= (1 - 2e-12);
    if (hi < 0) hi *= (1 - 2e-12);
  }

  /// de Casteljau split at ratio r (0 < r < 1) along u (or v): children on [0, r] and [r, 1] of that variable.
  void split(bool along_u, double r, Double_bernstein_grid& left, Double_bernstein_grid& right) const {
    const int n = along_u ? a_ : b_, m = along_u ? b_ : a_;
    left = Double_bernstein_grid(a_, b_);
    right = Double_bernstein_grid(a_, b_);
    const double s = 1 - r;
    std::vector<double> w(std::size_t(n + 1));
    for (int l = 0; l <= m; ++l) {
      for (int k = 0; k <= n; ++k) w[k] = along_u ? at(k, l) : at(l, k);
      double& L0 = along_u ? left.at(0, l) : left.at(l, 0);
      double& Rn = along_u ? right.at(n, l) : right.at(l, n);
      L0 = w[0];
      Rn = w[n];
      for (int level = 1; level <= n; ++level) {
        for (int k = 0; k + level <= n; ++k) w[k] = s * w[k] + r * w[k + 1];
        (along_u ? left.at(level, l) : left.at(l, level)) = w[0];
        (along_u ? right.at(n - level, l) : right.at(l, n - level)) = w[n - level];
      }
    }
    const double u = std::ldexp(1.0, -52), eta = std::ldexp(1.0, -1074);
    const double M = max_abs();
    const double growth = 1 + 6 * u * n * 1.01;  // >= (1 + 6u)^n for n u << 1
    const double added = n * (6 * u * M * growth + 3 * eta);
    const double rho = (rho_ + added) * (1 + 1e-12);
    left.rho_ = right.rho_ = rho;
    left.e_ = right.e_ = e_;
    left.rescale();
    right.rescale();
  }

  /// Multiplies everything by a power of two so that max |m| is in [1/2, 1) (exact: no decision changes).
  void rescale() {
    const double M = max_abs();
    if (!(M > 0) || !std::isfinite(M)) return;
    int e = 0;
    std::frexp(M, &e);
    if (e == 0) return;
    for (double& x : m_) x = std::ldexp(x, -e);  // exact unless a tiny value underflows (error <= eta)
    e_ += e;
    const double r = std::ldexp(rho_, -e);
    rho_ = e > 0 ? std::nextafter(r + std::ldexp(1.0, -1074), 1.0) : r;
  }

 private:
  int a_ = 0, b_ = 0;
  std::vector<double> m_;
  double rho_ = 0;
  int e_ = 0;
};

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_TOPOLOGY_INTERNAL_DOUBLE_BERNSTEIN_GRID_H
