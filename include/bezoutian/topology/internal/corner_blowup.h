// The half-branches of D = 0 that leave a singular point p on the boundary of the box into one quadrant at p, proved
// by a toric (Newton polygon) blow-up.
//
// Write D(p + (sx x, sy y)) = sum s_ab x^a y^b, s_ab = c_ab sx^a sy^b, x, y >= 0, for the quadrant (sx, sy = +-1)
// of the box at p (a corner of the box, or one side of a point inside an edge). Where two patches of one smooth
// surface touch at a corner, D = 0 has a cusp there, tangent to a side of the box (c y^2 + d x^3 + ...): the tangent
// cone is a double line and the plain blow-up of multiple_point_blowup.h does not decide.
//
// Newton polygon. Let a0, b0 be the orders of D(x, 0) and D(0, y) (both finite: no side through p lies on D = 0).
// The lower convex hull of the support from (a0, 0) to (0, b0) has edges e_1, ..., e_k (from the x axis), e_i with
// primitive inner normal R_i = (w_i, v_i) > 0 and N_i = min over the support of w_i a + v_i b. On e_i the lattice
// points are (alpha - j v_i, beta + j w_i), j = 0..g_i, and the edge polynomial is P_i(z) = sum_j s_(those) z^j
// (P_i(0) and its leading coefficient are vertex coefficients, nonzero). With R_0 = (0, 1), R_(k+1) = (1, 0) (the
// axes, N = 0), the charts C_i (i = 0..k)
//     x = s^(w_i) t^(w_(i+1)),  y = s^(v_i) t^(v_(i+1)),   D = s^(N_i) t^(N_(i+1)) E_i(s, t)
// are diffeomorphisms of the open quadrant (log-linear maps with nonsingular matrices), E_i a polynomial. On the
// exceptional curve t = 0 of C_(i-1) and s = 0 of C_i (ray R_i) the strict transform E vanishes exactly at the
// positive roots of P_i (in the coordinate z = y^(w_i) / x^(v_i) up to a power), and at no point where two rays meet
// (E there is a vertex coefficient). Toric resolution: if every positive root of every P_i is simple, the germ of
// D = 0 at p in the open quadrant is exactly H smooth half-branches, H the number of those roots (one through each
// root, transversal to its exceptional curve), and D has no zero on the axes near p (the vertex terms s_(a0,0),
// s_(0,b0)). One edge from (a0, 0) to (0, b0) is the common case (a cusp tangent to a side); weights (1, 1) are the
// ordinary multiple points whose tangents are not along the sides.
//
// Gradient. In C_i, x D_x = s^(N_i) t^(N_(i+1)) F_i and y D_y = s^(N_i) t^(N_(i+1)) G_i with F_i, G_i the polynomials
// of coefficients a s_ab, b s_ab; G_0 has the factor s (y = 0 is s = 0 there) and F_k the factor t (x = 0), divided
// out, so that (F, G) != 0 on a chart region, axes included, gives grad D != 0 on its image minus p. The rectangle
// [0, 2^ex] x [0, 2^ey] lies in the union of the images of [0, 2^sigma_i] x [0, 2^tau_i] when sigma_i R_i +
// tau_i R_(i+1) >= (ex, ey) in the basis (R_i, R_(i+1)) (log coordinates: each chart is a translated cone and the
// cones cover the quadrant).
//
// Coefficients are exact rationals (p rational) or enclosures with an exact zero pattern (p algebraic, on a side);
// scaled by exact powers of two and converted outward to double intervals (CGAL::Interval_nt<false>: the tests set
// the rounding mode upward once, around their loops, instead of once per operation). The root counts
// split (0, oo) at z = 1, 2 or 1/2 (a root at the split moves it) and do not depend on the rectangle; the gradient
// tests split their chart's region until every piece decides.
#ifndef BEZOUTIAN_TOPOLOGY_INTERNAL_CORNER_BLOWUP_H
#define BEZOUTIAN_TOPOLOGY_INTERNAL_CORNER_BLOWUP_H

#include <bezoutian/arithmetic/number_types.h>

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
  /// The shape of the rectangles tried by the caller: the weights of the edge if there is one, else (1, 1).
  int weight_x() const { return rays_.size() == 3 ? rays_[1].w : 1; }
  int weight_y() const { return rays_.size() == 3 ? rays_[1].v : 1; }
  /// Number of compact edges of the Newton polygon.
  int edges() const { return valid_ ? int(rays_.size()) - 2 : 0; }

  /// H (see above), with grad D != 0 on the rectangle [0, 2^(e wx)] x [0, 2^(e wy)] minus p (wx, wy the weights
  /// above); -1 if not proved.
  int half_branches(int e) const {
    const auto it = tried_.find(e);
    if (it != tried_.end()) return it->second;
    int half = roots();
    for (std::size_t i = 0; half >= 0 && i + 1 < rays_.size(); ++i)
      if (!gradient_free(i, e * weight_x(), e * weight_y())) half = -1;
    return tried_[e] = half;
  }

 private:
  // Unprotected intervals: every computation with them runs under a Protect_FPU_rounding guard (the conversions
  // of the exact coefficients, CGAL::to_interval, happen before it).
  using IA = CGAL::Interval_nt<false>;
  struct Term {
    int a, b;
    Rational lo, hi;  // the coefficient s_ab lies in [lo, hi]
  };
  struct Ray {
    int w, v, N;  // the weight w a + v b of x^a y^b and its minimum over the support
  };
  struct Edge {
    std::vector<Term> coefficients;  // of z^j in P_i (a = j); zero coefficients are exact zeros
  };

  void init(const std::vector<std::vector<Enclosed_coefficient>>& c, int sx, int sy) {
    int a0 = -1, b0 = -1;
    for (std::size_t a = 0; a < c.size() && a0 < 0; ++a)
      if (!c[a].empty() && !c[a][0].zero) a0 = int(a);
    for (std::size_t b = 0; !c.empty() && b < c[0].size() && b0 < 0; ++b)
      if (!c[0][b].zero) b0 = int(b);
    if (a0 < 1 || b0 < 1) return;  // D(p) != 0, or D vanishes on a side through p
    std::map<std::pair<int, int>, std::size_t> at;
    for (std::size_t a = 0; a < c.size(); ++a)
      for (std::size_t b = 0; b < c[a].size(); ++b) {
        const Enclosed_coefficient& x = c[a][b];
        if (x.zero) continue;
        const bool odd = ((sx < 0) && (a % 2 == 1)) != ((sy < 0) && (b % 2 == 1));
        at[{int(a), int(b)}] = terms_.size();
        terms_.push_back(odd ? Term{int(a), int(b), -x.hi, -x.lo} : Term{int(a), int(b), x.lo, x.hi});
      }
    // the lower hull from (a0, 0) to (0, b0): from each vertex the point of least rise per step to the left
    rays_.push_back(Ray{0, 1, 0});
    for (int ca = a0, cb = 0; ca > 0;) {
      int na = -1, nb = -1;
      for (const Term& t : terms_) {
        if (t.a >= ca) continue;
        // (t.b - cb) / (ca - t.a) < (nb - cb) / (ca - na), ties to the farther point
        const long lhs = long(t.b - cb) * (ca - na), rhs = long(nb - cb) * (ca - t.a);
        if (na < 0 || lhs < rhs || (lhs == rhs && t.a < na)) na = t.a, nb = t.b;
      }
      const int g = std::gcd(ca - na, nb - cb);
      const Ray r{(nb - cb) / g, (ca - na) / g, 0};
      Edge edge;
      for (int j = 0; j <= g; ++j) {
        const auto f = at.find({ca - j * r.v, cb + j * r.w});
        edge.coefficients.push_back(f == at.end() ? Term{j, 0, Rational(0), Rational(0)}
                                                  : Term{j, 0, terms_[f->second].lo, terms_[f->second].hi});
      }
      rays_.push_back(Ray{r.w, r.v, r.w * ca + r.v * cb});
      edges_.push_back(edge);
      ca = na;
      cb = nb;
    }
    rays_.push_back(Ray{1, 0, 0});
    for (const Ray& r : rays_)
      for (const Term& t : terms_)
        if (r.w * t.a + r.v * t.b < r.N) return;  // cannot happen (the hull): a bug, not an input
    valid_ = true;
  }

  static long exponent(const Rational& q) {  // about log2 |q|
    return CGAL::is_zero(q) ? LONG_MIN : long(q.numerator().bit_size()) - long(q.denominator().bit_size());
  }
  static Rational two_power(long k) {
    Integer r(1), b(2);
    for (long n = std::labs(k); n > 0; n >>= 1, b *= b)
      if (n & 1) r *= b;
    return k >= 0 ? Rational(r) : Rational(1) / Rational(r);
  }
  static bool has_zero(const IA& x) { return x.inf() <= 0 && x.sup() >= 0; }
  static int sign(const IA& x) { return x.inf() > 0 ? 1 : (x.sup() < 0 ? -1 : 0); }
  // [lo, hi] factor 2^shift as a double interval (factor > 0), converted outward; false on overflow
  static bool scaled(const Term& t, long shift, IA& out, int factor = 1) {
    const Rational f = two_power(shift) * Rational(factor);
    const std::pair<double, double> l = CGAL::to_interval(t.lo * f), h = CGAL::to_interval(t.hi * f);
    if (!std::isfinite(l.first) || !std::isfinite(h.second)) return false;
    out = IA(l.first, h.second);
    return true;
  }

  // Sum of H over the edges, each edge polynomial's positive roots proved simple; -1 if not proved. Cached.
  int roots() const {
    if (roots_ != -2) return roots_;
    int total = valid_ ? 0 : -1;
    for (std::size_t i = 0; i < edges_.size() && total >= 0; ++i) {
      int n = -1;
      for (int k : {0, 1, -1}) {  // split (0, oo) at z = 2^k
        const int below = count_roots(edges_[i], false, k), above = below < 0 ? -1 : count_roots(edges_[i], true, -k);
        if (below >= 0 && above >= 0) {
          n = below + above;
          break;
        }
      }
      total = n < 0 ? -1 : total + n;
    }
    return roots_ = total;
  }

  // Simple roots of P (or of z^g P(1/z) if reversed) in (0, 2^k], none at 2^k; -1 if not proved.
  static int count_roots(const Edge& edge, bool reversed, int k) {
    const std::size_t g = edge.coefficients.size() - 1;
    long E = LONG_MIN;
    for (const Term& t : edge.coefficients) E = std::max({E, exponent(t.lo), exponent(t.hi)});
    std::vector<IA> p(g + 1), dp(g + 1, IA(0));
    for (std::size_t j = 0; j <= g; ++j)
      if (!scaled(edge.coefficients[reversed ? g - j : j], -E, p[j]) ||
          (j > 0 && !scaled(edge.coefficients[reversed ? g - j : j], -E, dp[j - 1], int(j))))
        return -1;
    CGAL::Protect_FPU_rounding<true> upward;
    auto eval = [](const std::vector<IA>& c, const IA& z) {
      IA r(0);
      for (std::size_t j = c.size(); j-- > 0;) r = r * z + c[j];
      return r;
    };
    const double hi = std::ldexp(1.0, k);
    if (sign(eval(p, IA(0))) == 0 || sign(eval(p, IA(hi))) == 0) return -1;
    std::vector<std::array<double, 2>> stack{{0.0, hi}};
    int roots = 0;
    for (int pieces = 0; !stack.empty(); ++pieces) {
      const auto M = stack.back();
      stack.pop_back();
      if (pieces > 4000 || !(M[1] - M[0] > hi * 0x1p-30)) return -1;
      const IA Z(M[0], M[1]);
      if (!has_zero(eval(p, Z))) continue;
      if (!has_zero(eval(dp, Z))) {
        const int s0 = sign(eval(p, IA(M[0]))), s1 = sign(eval(p, IA(M[1])));
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

  // (F_i, G_i) has no common zero on the chart C_i's region covering [0, 2^ex] x [0, 2^ey] (see above).
  bool gradient_free(std::size_t i, int ex, int ey) const {
    const Ray &R = rays_[i], &S = rays_[i + 1];
    // (ex, ey) = sigma R + tau S, rounded up
    const long det = long(R.w) * S.v - long(S.w) * R.v;
    const long sn = long(ex) * S.v - long(ey) * S.w, tn = long(ey) * R.w - long(ex) * R.v;
    auto ceil_div = [](long n, long d) { return d < 0 ? ceil_div_pos(-n, -d) : ceil_div_pos(n, d); };
    const long sigma = ceil_div(sn, det), tau = ceil_div(tn, det);
    struct Scaled {
      int p, q;  // powers of s / 2^sigma and t / 2^tau in F (a s_ab) or G (b s_ab)
      IA c;
    };
    std::vector<Scaled> F, G;
    long E = LONG_MIN;
    for (const Term& t : terms_) {
      const long p = long(R.w) * t.a + long(R.v) * t.b - R.N, q = long(S.w) * t.a + long(S.v) * t.b - S.N;
      E = std::max({E, exponent(t.lo) + p * sigma + q * tau, exponent(t.hi) + p * sigma + q * tau});
    }
    int max_p = 0, max_q = 0;
    for (const Term& t : terms_) {
      long p = long(R.w) * t.a + long(R.v) * t.b - R.N, q = long(S.w) * t.a + long(S.v) * t.b - S.N;
      for (int kind = 0; kind < 2; ++kind) {
        const int factor = kind == 0 ? t.a : t.b;
        if (factor == 0) continue;
        // G_0 is divided by s (the axis y = 0), F_k by t (the axis x = 0)
        const long pp = p - (kind == 1 && i == 0 ? 1 : 0), qq = q - (kind == 0 && i + 2 == rays_.size() ? 1 : 0);
        IA c;
        if (pp < 0 || qq < 0 || !scaled(t, pp * sigma + qq * tau - E, c, factor)) return false;
        (kind == 0 ? F : G).push_back(Scaled{int(pp), int(qq), c});
        max_p = std::max(max_p, int(pp));
        max_q = std::max(max_q, int(qq));
      }
    }
    CGAL::Protect_FPU_rounding<true> upward;
    std::vector<IA> ps(std::size_t(max_p + 1)), qs(std::size_t(max_q + 1));
    auto eval = [&](const std::vector<Scaled>& f) {
      IA r(0);
      for (const Scaled& x : f) r += x.c * ps[std::size_t(x.p)] * qs[std::size_t(x.q)];
      return r;
    };
    std::vector<std::array<double, 4>> stack{{0.0, 1.0, 0.0, 1.0}};
    for (int pieces = 0; !stack.empty(); ++pieces) {
      const auto P = stack.back();
      stack.pop_back();
      if (pieces > 4000 || !(P[1] - P[0] > 0x1p-24) || !(P[3] - P[2] > 0x1p-24)) return false;
      const IA s(P[0], P[1]), t(P[2], P[3]);
      ps[0] = qs[0] = IA(1);
      for (std::size_t k = 1; k < ps.size(); ++k) ps[k] = ps[k - 1] * s;
      for (std::size_t k = 1; k < qs.size(); ++k) qs[k] = qs[k - 1] * t;
      if (!has_zero(eval(F)) || !has_zero(eval(G))) continue;
      const bool along_s = P[1] - P[0] >= P[3] - P[2];
      const double mid = along_s ? P[0] + 0.4142135623730951 * (P[1] - P[0]) : P[2] + 0.4142135623730951 * (P[3] - P[2]);
      if (along_s) {
        stack.push_back({P[0], mid, P[2], P[3]});
        stack.push_back({mid, P[1], P[2], P[3]});
      } else {
        stack.push_back({P[0], P[1], P[2], mid});
        stack.push_back({P[0], P[1], mid, P[3]});
      }
    }
    return true;
  }
  static long ceil_div_pos(long n, long d) { return n >= 0 ? (n + d - 1) / d : -((-n) / d); }

  bool valid_ = false;
  std::vector<Term> terms_;
  std::vector<Ray> rays_;    // R_0 = (0, 1), the edges' normals from the x axis, R_(k+1) = (1, 0)
  std::vector<Edge> edges_;  // e_1 .. e_k
  mutable int roots_ = -2;   // roots() (-2: not yet)
  mutable std::map<int, int> tried_;  // half_branches(e), by e
};

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_TOPOLOGY_INTERNAL_CORNER_BLOWUP_H
