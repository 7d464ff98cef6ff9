// The half-branches of D = 0 that leave a singular corner p of the box into the box, proved by a weighted blow-up.
//
// Write D(p + (sx x, sy y)) = sum c_ab sx^a sy^b x^a y^b with x, y >= 0 in the quadrant of the box at p (sx, sy =
// +-1). Where two patches of one smooth surface touch at a corner, D = 0 has a cusp there, tangent to a side of the
// box (c y^2 + d x^3 + ...): the tangent cone is a double line and the plain blow-up of multiple_point_blowup.h does
// not decide. If the Newton polygon of D at p has a single compact edge, from (a0, 0) to (0, b0), with weights
// (w, v) = (b0, a0) / gcd and weighted order N = w a0 (every c_ab with w a + v b < N is zero), the charts
//     A: x = L^w,  y = m L^v,   m in [0, sigma],    B: y = L^v,  x = n L^w,   n in [0, sigma^(-w/v)],
// (sigma = 1, 2^v or 2^-v: both ends dyadic) cover the rectangle [0, L0^w] x [0, L0^v] for L in [0, L0], and in A
//     D = L^N E_A(L, m),  E_A(L, m) = sum_ab s_ab m^b L^(w a + v b - N),   s_ab = c_ab sx^a sy^b,
//     (dD/dx, dD/dy) = (sx L^(N-w) GX_A, sy L^(N-v) GY_A),  GX_A = sum a s_ab m^b L^(..),  GY_A = sum b s_ab m^(b-1) L^(..)
// (B alike with n and the roles of a, b swapped). E_A(0, m) is the weighted initial form W(m); it is nonzero at
// m = 0 (c_a0,0 != 0). If every root of W and of the chart B form in the open slope ranges is simple and none is at
// the common end, E_A = 0 near L = 0 is one smooth graph through each (0, m0) and nothing else (implicit function
// theorem), so the germ of D = 0 at p in the quadrant is exactly H half-branches, H the number of those roots. If
// (GX, GY) has no common zero on [0, L0] x (slope range) in both charts, grad D != 0 on the rectangle minus p. (Weights
// (1, 1) are the ordinary multiple points whose tangents are not along the box's sides.)
//
// Coefficients are exact rationals (p is a rational corner), scaled by L0^(w a + v b - N) and a power of two and
// converted outward to double intervals (CGAL::Interval_nt); the tests split the chart's pieces until they decide.
#ifndef BEZOUTIAN_INTERNAL_CORNER_BLOWUP_H
#define BEZOUTIAN_INTERNAL_CORNER_BLOWUP_H

#include <bezoutian/number_types.h>

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <map>
#include <numeric>
#include <vector>

namespace bezoutian {
namespace internal {

class Corner_blowup {
 public:
  /// A Taylor coefficient of D at p known to lie in [lo, hi], or known to be exactly zero (an irrational p on a side
  /// of the box: the zero pattern is decided exactly, the other coefficients are enclosed).
  struct Enclosed_coefficient {
    Rational lo, hi;
    bool zero;
  };

  /// c[a][b]: the exact Taylor coefficients of D at p (of x^a y^b, x = u - p_u, y = v - p_v); (sx, sy) the quadrant.
  Corner_blowup(const std::vector<std::vector<Rational>>& c, int sx, int sy) {
    std::vector<std::vector<Enclosed_coefficient>> e(c.size());
    for (std::size_t a = 0; a < c.size(); ++a)
      for (const Rational& x : c[a]) e[a].push_back(Enclosed_coefficient{x, x, CGAL::is_zero(x)});
    init(e, sx, sy);
  }
  /// The same with enclosures of the coefficients: every test below holds for every set of coefficients in them.
  Corner_blowup(const std::vector<std::vector<Enclosed_coefficient>>& c, int sx, int sy) { init(c, sx, sy); }

  bool valid() const { return valid_; }
  int weight_x() const { return w_; }
  int weight_y() const { return v_; }

  /// H (see above) for L0 = 2^e, with grad D != 0 on the rectangle [0, 2^(e w)] x [0, 2^(e v)] minus p; -1 if not
  /// proved.
  int half_branches(int e) const {
    const auto it = tried_.find(e);
    if (it != tried_.end()) return it->second;
    int half = -1;
    // the charts meet along y = sigma x^(v/w), i.e. x = sigma^(-w/v) y^(w/v): sigma = 1, 2^v, 2^-v keep both ends
    // dyadic (a branch along the split, e.g. the diagonal of a symmetric node, moves it)
    for (int split = 0; split < 3; ++split) {
      if (!valid_ || !scale(e)) break;
      const int k = split == 0 ? 0 : (split == 1 ? 1 : -1);
      const double hi[2] = {std::ldexp(1.0, k * v_), std::ldexp(1.0, -k * w_)};
      // the roots at L = 0 do not depend on L0 (the edge's terms are not scaled): counted once per split
      for (int chart = 0; chart < 2; ++chart)
        if (roots_[split][chart] == -2) roots_[split][chart] = count_roots(chart, hi[chart]);
      if (roots_[split][0] < 0 || roots_[split][1] < 0) continue;
      // the first split whose roots are proved: a failing gradient test is about L0, not about the split
      half = gradient_free(0, hi[0]) && gradient_free(1, hi[1]) ? roots_[split][0] + roots_[split][1] : -1;
      break;
    }
    return tried_[e] = half;
  }

 private:
  using IA = CGAL::Interval_nt<>;
  struct Term {
    int a, b, t;
    Rational lo, hi;  // the coefficient s_ab lies in [lo, hi]
  };

  void init(const std::vector<std::vector<Enclosed_coefficient>>& c, int sx, int sy) {
    int a0 = -1, b0 = -1;
    for (std::size_t a = 0; a < c.size() && a0 < 0; ++a)
      if (!c[a].empty() && !c[a][0].zero) a0 = int(a);
    for (std::size_t b = 0; !c.empty() && b < c[0].size() && b0 < 0; ++b)
      if (!c[0][b].zero) b0 = int(b);
    if (a0 < 1 || b0 < 1) return;  // D(p) != 0, or D vanishes on a side through p
    const int g = std::gcd(a0, b0);
    w_ = b0 / g;
    v_ = a0 / g;
    N_ = w_ * a0;
    for (std::size_t a = 0; a < c.size(); ++a)
      for (std::size_t b = 0; b < c[a].size(); ++b) {
        const Enclosed_coefficient& x = c[a][b];
        if (x.zero) continue;
        const int t = w_ * int(a) + v_ * int(b) - N_;
        if (t < 0) return;  // a point of the support below the edge: more than one compact edge
        const bool odd = ((sx < 0) && (a % 2 == 1)) != ((sy < 0) && (b % 2 == 1));
        terms_.push_back(odd ? Term{int(a), int(b), t, -x.hi, -x.lo} : Term{int(a), int(b), t, x.lo, x.hi});
        max_slope_ = std::max({max_slope_, int(a), int(b)});
        max_t_ = std::max(max_t_, t);
      }
    valid_ = true;
  }
  struct Scaled {
    int a, b, t;
    IA s;
  };

  static long exponent(const Rational& q) {  // about log2 |q|
    return CGAL::is_zero(q) ? LONG_MIN : long(q.numerator().bit_size()) - long(q.denominator().bit_size());
  }
  // s = c L0^t 2^-E, E the exponent of the largest coefficient on the edge (t = 0)
  bool scale(int e) const {
    long E = LONG_MIN;
    for (const Term& x : terms_)
      if (x.t == 0) E = std::max({E, exponent(x.lo), exponent(x.hi)});
    if (E == LONG_MIN) return false;
    scaled_.clear();
    for (const Term& x : terms_) {
      const long shift = long(e) * x.t - E;  // times 2^shift, exactly
      const Rational f = shift >= 0 ? Rational(two_power(shift)) : Rational(1) / Rational(two_power(-shift));
      const std::pair<double, double> l = CGAL::to_interval(x.lo * f), h = CGAL::to_interval(x.hi * f);
      if (!std::isfinite(l.first) || !std::isfinite(h.second)) return false;
      scaled_.push_back(Scaled{x.a, x.b, x.t, IA(l.first, h.second)});
    }
    return true;
  }

  static Integer two_power(long k) {
    Integer r(1), b(2);
    for (; k > 0; k >>= 1, b *= b)
      if (k & 1) r *= b;
    return r;
  }
  static IA power(const IA& x, int k) {
    IA r(1);
    for (int i = 0; i < k; ++i) r *= x;
    return r;
  }
  static bool has_zero(const IA& x) { return x.inf() <= 0 && x.sup() >= 0; }
  static int sign(const IA& x) { return x.inf() > 0 ? 1 : (x.sup() < 0 ? -1 : 0); }

  // kind 0: E; 1: GX (the derivative along x, up to sx); 2: GY. Chart 0: (L, m) of A, chart 1: (L, n) of B.
  // Powers of the (nonnegative) arguments are tabulated once per call.
  IA evaluate(int chart, int kind, const IA& L, const IA& s) const {
    std::vector<IA>& ps = powers_s_;
    std::vector<IA>& pl = powers_l_;
    ps.assign(std::size_t(max_slope_ + 1), IA(1));
    pl.assign(std::size_t(max_t_ + 1), IA(1));
    for (std::size_t i = 1; i < ps.size(); ++i) ps[i] = ps[i - 1] * s;
    for (std::size_t i = 1; i < pl.size(); ++i) pl[i] = pl[i - 1] * L;
    IA r(0);
    for (const Scaled& x : scaled_) {
      const int along = chart == 0 ? x.b : x.a;  // the power of the chart's slope
      const int factor = kind == 0 ? 1 : (kind == 1 ? x.a : x.b);
      if (factor == 0) continue;
      // d/dx in chart B (x = n L^w) lowers the power of n; d/dy in chart A (y = m L^v) lowers that of m
      const bool lowers = (chart == 0 && kind == 2) || (chart == 1 && kind == 1);
      const int k = lowers ? along - 1 : along;
      r += x.s * double(factor) * ps[std::size_t(k)] * pl[std::size_t(x.t)];
    }
    return r;
  }

  // simple roots of the chart's initial form (L = 0) with slope in (0, hi); -1 if not proved (a root at hi or a
  // multiple one)
  int count_roots(int chart, double hi) const {
    const IA L0(0);
    if (sign(evaluate(chart, 0, L0, IA(0))) == 0 || sign(evaluate(chart, 0, L0, IA(hi))) == 0) return -1;
    const int slope_kind = chart == 0 ? 2 : 1;  // d/dm of E_A is GY_A; d/dn of E_B is GX_B
    std::vector<std::array<double, 2>> stack{{0.0, hi}};
    int roots = 0;
    for (int pieces = 0; !stack.empty(); ++pieces) {
      const auto M = stack.back();
      stack.pop_back();
      if (pieces > 4000 || !(M[1] - M[0] > hi * 0x1p-30)) return -1;
      if (!has_zero(evaluate(chart, 0, L0, IA(M[0], M[1])))) continue;
      if (!has_zero(evaluate(chart, slope_kind, L0, IA(M[0], M[1])))) {
        const int s0 = sign(evaluate(chart, 0, L0, IA(M[0]))), s1 = sign(evaluate(chart, 0, L0, IA(M[1])));
        if (s0 != 0 && s1 != 0) {
          roots += s0 != s1;
          continue;
        }
      }
      const double mid = M[0] + 0.4142135623730951 * (M[1] - M[0]);
      stack.push_back({M[0], mid});
      stack.push_back({mid, M[1]});
    }
    return roots;
  }

  // (GX, GY) has no common zero on [0, 1] (L / L0) x [0, hi] (slope)
  bool gradient_free(int chart, double hi) const {
    std::vector<std::array<double, 4>> stack{{0.0, 1.0, 0.0, hi}};
    for (int pieces = 0; !stack.empty(); ++pieces) {
      const auto P = stack.back();
      stack.pop_back();
      if (pieces > 4000 || !(P[1] - P[0] > 0x1p-24) || !(P[3] - P[2] > hi * 0x1p-24)) return false;
      const IA L(P[0], P[1]), s(P[2], P[3]);
      if (!has_zero(evaluate(chart, 1, L, s)) || !has_zero(evaluate(chart, 2, L, s))) continue;
      const bool along_L = P[1] - P[0] >= (P[3] - P[2]) / hi;
      const double mid = along_L ? P[0] + 0.4142135623730951 * (P[1] - P[0]) : P[2] + 0.4142135623730951 * (P[3] - P[2]);
      if (along_L) {
        stack.push_back({P[0], mid, P[2], P[3]});
        stack.push_back({mid, P[1], P[2], P[3]});
      } else {
        stack.push_back({P[0], P[1], P[2], mid});
        stack.push_back({P[0], P[1], mid, P[3]});
      }
    }
    return true;
  }

  bool valid_ = false;
  int w_ = 1, v_ = 1, N_ = 0, max_slope_ = 0, max_t_ = 0;
  std::vector<Term> terms_;
  mutable std::vector<Scaled> scaled_;
  mutable std::vector<IA> powers_s_, powers_l_;
  mutable std::map<int, int> tried_;  // half_branches(e), by e
  mutable int roots_[3][2] = {{-2, -2}, {-2, -2}, {-2, -2}};  // count_roots by split and chart (-2: not yet)
};

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERNAL_CORNER_BLOWUP_H
