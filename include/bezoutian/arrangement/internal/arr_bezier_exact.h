// Exact building blocks of the Arrangement_2 traits for rational Bezier curves: supporting curves, exact
// coordinates of curve points at algebraic parameters, inversion of an abscissa on a monotone arc.
#ifndef BEZOUTIAN_ARRANGEMENT_INTERNAL_ARR_BEZIER_EXACT_H
#define BEZOUTIAN_ARRANGEMENT_INTERNAL_ARR_BEZIER_EXACT_H

#include <bezoutian/algebraic/Algebraic_real.h>
#include <bezoutian/intersection/Curve_intersection.h>
#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/geometry/Rational_bezier_curve.h>
#include <bezoutian/algebraic/Root_isolation.h>
#include <bezoutian/intersection/curve_intersection_support.h>
#include <bezoutian/intersection/planar_interval_solver.h>

#include <CGAL/Interval_nt.h>
#include <CGAL/Polynomial.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>


namespace bezoutian {
namespace internal {

/// One input curve as used by the traits: integer power form and, per coordinate, the reduced fraction
/// N_k / D_k = X_k / W (gcd removed, so that resultants with defining polynomials never vanish identically).
/// (curve, Hd, inet: the interval solver's data, planar_interval_solver.h.)
struct Arr_bezier_supporting_curve : Planar_interval_curve {
  std::size_t id = 0;
  std::array<Ci_poly1, 3> H;        // (W, X, Y), integer coefficients
  std::array<Ci_poly1, 2> num, den;  // x = num[0]/den[0], y = num[1]/den[1]
  std::array<Ci_poly1, 2> speed;     // X_k' W - X_k W' (numerators of the derivatives of x and y)
  bool vertical = false;             // x constant
  bool linear = false;               // the image lies on a line (collinear control points)
  std::array<Rational, 4> box;       // xmin, xmax, ymin, ymax of the control points (encloses the curve)
  /// Boxes (xmin, xmax, ymin, ymax; outward-rounded doubles) enclosing the pieces C([i/2^d, (i+1)/2^d]),
  /// d = 0..box_depth, stored level by level (piece i of level d at index 2^d - 1 + i): control boxes of the
  /// interval de Casteljau halves (convex hull property, positive weights).
  static constexpr int box_depth = 4;
  std::vector<std::array<double, 4>> piece_boxes;
  /// Proved free of self-intersections: some direction v has v . C'(t) >= 0 on [0,1] (Bernstein coefficients
  /// of v . (X'W - XW', Y'W - YW') all >= 0), so v . C(t) is strictly increasing.
  bool simple = false;
  /// For curves not proved simple: the divided differences F_k(s,t) = (X_k(s) W(t) - X_k(t) W(s)) / (s - t),
  /// k = 1, 2, whose common zeros off the diagonal are the self-intersections; fd[k-1][p][q] encloses the
  /// coefficient of s^p t^q.
  std::array<std::vector<std::vector<CGAL::Interval_nt<false>>>, 2> fd;
};

/// The divided difference (X(s) W(t) - X(t) W(s)) / (s - t) as a coefficient matrix (exact): with
/// c_ij = x_i w_j - w_i x_j (antisymmetric), s^i t^j - s^j t^i = (s - t) s^j t^j sum_{m < i-j} s^m t^(i-j-1-m).
inline std::vector<std::vector<Integer>> arr_divided_difference(const Ci_poly1& X, const Ci_poly1& W) {
  const int n = std::max(X.degree(), W.degree());
  auto co = [](const Ci_poly1& f, int i) { return i <= f.degree() ? f[i] : Integer(0); };
  std::vector<std::vector<Integer>> f(std::max(n, 1), std::vector<Integer>(std::max(n, 1), Integer(0)));
  for (int i = 1; i <= n; ++i)
    for (int j = 0; j < i; ++j) {
      const Integer c = co(X, i) * co(W, j) - co(W, i) * co(X, j);
      if (CGAL::is_zero(c)) continue;
      for (int m = 0; m < i - j; ++m) f[j + m][i - 1 - m] += c;
    }
  return f;
}

/// Interval de Casteljau subdivision of the homogeneous net (w, wx, wy) for the piece boxes.
inline void arr_piece_boxes(Arr_bezier_supporting_curve& s) {
  typedef CGAL::Interval_nt<false> I;
  typename I::Protector guard;
  using Net = Planar_interval_net;
  Net net;
  for (const auto& h : s.curve.homogeneous_control_points())
    net.push_back({I(CGAL::to_interval(h[0])), I(CGAL::to_interval(h[1])), I(CGAL::to_interval(h[2]))});
  const int depth = Arr_bezier_supporting_curve::box_depth;
  s.piece_boxes.assign((std::size_t(1) << (depth + 1)) - 1, {{-HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL}});
  std::vector<Net> level{net};
  for (int d = 0; d <= depth; ++d) {
    std::vector<Net> next;
    for (std::size_t i = 0; i < level.size(); ++i) {
      const Net& q = level[i];
      double b[4];
      if (planar_net_box(q, b)) s.piece_boxes[(std::size_t(1) << d) - 1 + i] = {{b[0], b[1], b[2], b[3]}};
      if (d == depth) continue;
      Net left, right, tri;
      planar_net_halves(q, left, right, tri);
      next.push_back(left);
      next.push_back(right);
    }
    level.swap(next);
  }
}

/// True if the pieces of a (level d, index i) and b (level d, index j) are proved disjoint by the piece boxes.
inline bool arr_pieces_disjoint(const Arr_bezier_supporting_curve& a, const Arr_bezier_supporting_curve& b, int d,
                                std::size_t i, std::size_t j) {
  const auto& p = a.piece_boxes[(std::size_t(1) << d) - 1 + i];
  const auto& q = b.piece_boxes[(std::size_t(1) << d) - 1 + j];
  if (p[1] < q[0] || q[1] < p[0] || p[3] < q[2] || q[3] < p[2]) return true;
  if (d == Arr_bezier_supporting_curve::box_depth) return false;
  for (std::size_t u = 0; u < 2; ++u)
    for (std::size_t v = 0; v < 2; ++v)
      if (!arr_pieces_disjoint(a, b, d + 1, 2 * i + u, 2 * j + v)) return false;
  return true;
}

/// Positive multiples C(n,j) b_j of the Bernstein coefficients b_j (degree n >= deg f) of an integer polynomial
/// on [0,1], exact: C(j,i)/C(n,i) = C(n-i,j-i)/C(n,j) gives C(n,j) b_j = sum_{i <= j} C(n-i, j-i) a_i.
inline std::vector<Rational> arr_bernstein(const Ci_poly1& f, int n) {
  std::vector<std::vector<Integer>> C(n + 1);  // Pascal's triangle
  for (int i = 0; i <= n; ++i) {
    C[i].assign(i + 1, Integer(1));
    for (int j = 1; j < i; ++j) C[i][j] = C[i - 1][j - 1] + C[i - 1][j];
  }
  std::vector<Rational> b(n + 1);
  for (int j = 0; j <= n; ++j) {
    Integer acc(0);
    for (int i = 0; i <= j && i <= f.degree(); ++i)
      if (!CGAL::is_zero(f[i])) acc += C[n - i][j - i] * f[i];
    b[j] = Rational(acc);
  }
  return b;
}

/// The test behind Arr_bezier_supporting_curve::simple: the hodograph's Bernstein coefficient vectors lie in a
/// closed half-plane {v . d >= 0} (v proposed in doubles from the largest angular gap, checked exactly).
inline bool arr_is_simple(const Arr_bezier_supporting_curve& s) {
  const int n = std::max(s.speed[0].degree(), s.speed[1].degree());
  if (n < 0) return false;
  const std::vector<Rational> bx = arr_bernstein(s.speed[0], n), by = arr_bernstein(s.speed[1], n);
  std::vector<double> ang;
  for (int j = 0; j <= n; ++j)
    if (!CGAL::is_zero(bx[j]) || !CGAL::is_zero(by[j])) ang.push_back(std::atan2(CGAL::to_double(by[j]), CGAL::to_double(bx[j])));
  if (ang.empty()) return false;
  std::sort(ang.begin(), ang.end());
  const double pi = std::acos(-1.0);
  double gap = ang.front() + 2 * pi - ang.back(), mid = ang.back() + 0.5 * gap;
  for (std::size_t i = 1; i < ang.size(); ++i)
    if (ang[i] - ang[i - 1] > gap) {
      gap = ang[i] - ang[i - 1];
      mid = ang[i - 1] + 0.5 * gap;
    }
  if (gap < pi - 1e-9) return false;
  const Rational vx(-std::cos(mid)), vy(-std::sin(mid));  // opposite the middle of the empty gap
  {
    // filter: the same test on outward-rounded enclosures of the coefficients
    typedef CGAL::Interval_nt<false> I;
    typename I::Protector guard;
    const I ix(-std::cos(mid)), iy(-std::sin(mid));
    bool all_nonneg = true, some_pos = false;
    for (int j = 0; j <= n && all_nonneg; ++j) {
      const I d = ix * I(CGAL::to_interval(bx[j])) + iy * I(CGAL::to_interval(by[j]));
      if (!(d.inf() >= 0)) all_nonneg = false;
      if (d.inf() > 0) some_pos = true;
    }
    if (all_nonneg && some_pos) return true;
  }
  for (int j = 0; j <= n; ++j)
    if (CGAL::sign(vx * bx[j] + vy * by[j]) < 0) return false;
  // v . C' is then >= 0 on [0,1]; it is not identically 0 since some coefficient is positive or all are 0
  for (int j = 0; j <= n; ++j)
    if (CGAL::sign(vx * bx[j] + vy * by[j]) > 0) return true;
  return false;
}

/// Integer homogeneous power form (W, X, Y) of a plane curve: the net scaled by the positive lcm L of its
/// denominators, then a_k = C(n,k) sum_{i <= k} (-1)^(k-i) C(k,i) p_i (Bernstein to power basis), in integers.
/// The same projective curve as integer_power_form (a positive multiple).
inline std::array<Ci_poly1, 3> arr_integer_power_form(const Rational_bezier_curve_2<Rational>& c) {
  const auto& net = c.homogeneous_control_points();
  const int n = int(net.size()) - 1;
  Integer L(1);
  for (const auto& h : net)
    for (int k = 0; k < 3; ++k) {
      const Integer d(mpq_denref(h[k].mpq()));
      if (d != 1) L = CGAL::div(L * d, CGAL::gcd(L, d));
    }
  std::vector<std::array<Integer, 3>> p(n + 1);
  for (int i = 0; i <= n; ++i)
    for (int k = 0; k < 3; ++k) {
      const Integer num(mpq_numref(net[i][k].mpq())), den(mpq_denref(net[i][k].mpq()));
      p[i][k] = den == 1 ? num * L : num * CGAL::integral_division(L, den);
    }
  std::vector<std::vector<Integer>> C(n + 1);  // Pascal's triangle
  for (int i = 0; i <= n; ++i) {
    C[i].assign(i + 1, Integer(1));
    for (int j = 1; j < i; ++j) C[i][j] = C[i - 1][j - 1] + C[i - 1][j];
  }
  std::array<Ci_poly1, 3> r;
  for (int k = 0; k < 3; ++k) {
    std::vector<Integer> co(n + 1);
    for (int m = 0; m <= n; ++m) {
      Integer acc(0);
      for (int i = 0; i <= m; ++i) {
        if (CGAL::is_zero(p[i][k])) continue;
        if ((m - i) % 2 == 0) acc += C[m][i] * p[i][k];
        else acc -= C[m][i] * p[i][k];
      }
      co[m] = C[n][m] * acc;
    }
    r[k] = Ci_poly1(co.begin(), co.end());
  }
  return r;
}

inline Ci_poly1 arr_primitive(const Ci_poly1& f) {
  if (CGAL::is_zero(f)) return f;
  return canonical_integer(f) * Ci_poly1(Integer(CGAL::sign(f.lcoeff())));
}

inline std::shared_ptr<const Arr_bezier_supporting_curve> make_supporting_curve(const Rational_bezier_curve_2<Rational>& c) {
  static std::atomic<std::size_t> counter{0};
  for (std::size_t i = 0; i < c.number_of_control_points(); ++i)
    if (!(c.weight(i) > Rational(0)))
      throw Invalid_input("Arr_rational_bezier_traits_2: every weight must be positive (no poles on [0,1])");
  auto s = std::make_shared<Arr_bezier_supporting_curve>();
  s->id = ++counter;
  s->curve = c;
  s->H = arr_integer_power_form(c);
  const Ci_poly1& W = s->H[0];
  for (int k = 0; k < 2; ++k) {
    const Ci_poly1& X = s->H[k + 1];
    Ci_poly1 g = CGAL::is_zero(X) ? W : Ci_poly1(CGAL::gcd(X, W));
    g = arr_primitive(g);
    if (CGAL::sign(g.lcoeff()) < 0) g = -g;
    s->num[k] = CGAL::integral_division(X, g);
    s->den[k] = CGAL::integral_division(W, g);
    s->speed[k] = CGAL::differentiate(X) * W - X * CGAL::differentiate(W);
  }
  if (CGAL::is_zero(s->speed[0]) && CGAL::is_zero(s->speed[1]))
    throw Invalid_input("Arr_rational_bezier_traits_2: the curve is a single point");
  s->vertical = CGAL::is_zero(s->speed[0]);
  // Collinear control points <=> the image lies on a line (a X + b Y + c W = 0 holds coefficientwise).
  const auto p = c.control_points();
  s->box = {p[0][0], p[0][0], p[0][1], p[0][1]};
  for (const auto& q : p) {
    s->box[0] = std::min(s->box[0], q[0]);
    s->box[1] = std::max(s->box[1], q[0]);
    s->box[2] = std::min(s->box[2], q[1]);
    s->box[3] = std::max(s->box[3], q[1]);
  }
  std::size_t j = 1;
  while (j < p.size() && p[j] == p[0]) ++j;
  s->linear = true;
  for (std::size_t i = 1; i < p.size() && j < p.size(); ++i)
    if ((p[i][0] - p[0][0]) * (p[j][1] - p[0][1]) != (p[i][1] - p[0][1]) * (p[j][0] - p[0][0])) s->linear = false;
  arr_piece_boxes(*s);
  set_planar_interval_data(*s, s->H);  // Hd, inet
  if (!s->simple && !s->linear)
    for (int k = 1; k <= 2; ++k) {
      const auto f = arr_divided_difference(s->H[k], s->H[0]);
      s->fd[k - 1].assign(f.size(), std::vector<CGAL::Interval_nt<false>>(f.size()));
      for (std::size_t i = 0; i < f.size(); ++i)
        for (std::size_t j = 0; j < f.size(); ++j) s->fd[k - 1][i][j] = CGAL::Interval_nt<false>(CGAL::to_interval(f[i][j]));
    }
  s->simple = arr_is_simple(*s);
  return s;
}

/// The number (v - m) / d (d > 0): the root of q(m + d u) in the image of v's isolating interval.
inline Algebraic_real arr_affine(const Algebraic_real& v, const Rational& m, const Rational& d) {
  if (v.is_rational()) return Algebraic_real((v.rational_value() - m) / d);
  const Ci_poly1 q = v.polynomial();
  const Rational lo = v.lower(), hi = v.upper();
  const Polynomial_1<Rational> lin(m, d);
  Polynomial_1<Rational> r(0);
  for (int i = q.degree(); i >= 0; --i) r = r * lin + Polynomial_1<Rational>(Rational(q[i]));
  return Algebraic_real(r, (lo - m) / d, (hi - m) / d);
}

/// Exact rational value f(q).
inline Rational arr_eval(const Ci_poly1& f, const Rational& q) {
  Rational r(0);
  for (int i = f.degree(); i >= 0; --i) r = r * q + Rational(f[i]);
  return r;
}

/// Enclosure [lo, hi] of f on [a, b] (interval Horner; doubles when the interval is wide, exact rationals
/// otherwise). Rigorous in both cases: CGAL::Interval_nt rounds outwards.
inline std::pair<Rational, Rational> arr_enclose(const Ci_poly1& f, const Rational& a, const Rational& b) {
  const double w = CGAL::to_double(b - a), m = std::abs(CGAL::to_double(a)) + 1;
  if (w > 1e-9 * m) {
    typedef CGAL::Interval_nt<false> I;
    typename I::Protector guard;
    const I x(CGAL::to_interval(a).first, CGAL::to_interval(b).second);
    I v(CGAL::to_interval(f[f.degree()]));
    for (int i = f.degree() - 1; i >= 0; --i) v = v * x + I(CGAL::to_interval(f[i]));
    if (std::isfinite(v.inf()) && std::isfinite(v.sup())) return {Rational(v.inf()), Rational(v.sup())};
  }
  Rational lo(f[f.degree()]), hi = lo;
  for (int i = f.degree() - 1; i >= 0; --i) {
    const Rational p[4] = {lo * a, lo * b, hi * a, hi * b};
    lo = *std::min_element(p, p + 4);
    hi = *std::max_element(p, p + 4);
    lo += Rational(f[i]);
    hi += Rational(f[i]);
  }
  return {lo, hi};
}

/// Double enclosure of N/D on [a, b] (outward-rounded interval arithmetic on the double interval containing
/// [a, b]); false if D's enclosure contains 0 or overflows.
inline bool arr_enclose_quotient_double(const Ci_poly1& N, const Ci_poly1& D, const Rational& a, const Rational& b,
                                        double& lo, double& hi) {
  typedef CGAL::Interval_nt<false> I;
  typename I::Protector guard;
  const I x(CGAL::to_interval(a).first, CGAL::to_interval(b).second);
  auto ev = [&](const Ci_poly1& f) {
    I v(CGAL::to_interval(f[f.degree()]));
    for (int i = f.degree() - 1; i >= 0; --i) v = v * x + I(CGAL::to_interval(f[i]));
    return v;
  };
  const I n = ev(N), d = ev(D);
  if (!(d.inf() > 0) && !(d.sup() < 0)) return false;
  const I q = n / d;
  if (!std::isfinite(q.inf()) || !std::isfinite(q.sup())) return false;
  lo = q.inf();
  hi = q.sup();
  return true;
}

/// Enclosure of N/D on the isolating interval of t, or false if D's enclosure contains 0.
inline bool arr_enclose_quotient(const Ci_poly1& N, const Ci_poly1& D, const Rational& a, const Rational& b,
                                 Rational& lo, Rational& hi) {
  if (a == b) {
    lo = hi = arr_eval(N, a) / arr_eval(D, a);
    return true;
  }
  const auto n = arr_enclose(N, a, b), d = arr_enclose(D, a, b);
  if (!(d.first > Rational(0)) && !(d.second < Rational(0))) return false;
  const Rational p[4] = {n.first / d.first, n.first / d.second, n.second / d.first, n.second / d.second};
  lo = *std::min_element(p, p + 4);
  hi = *std::max_element(p, p + 4);
  return true;
}

inline void arr_refine(const Algebraic_real& t) {
  if (t.is_rational()) return;
  Rational w = (t.upper() - t.lower()) / Rational(64);
  t.refine_to_width(w);
}

/// The exact number N(t)/D(t) at an algebraic t (D(t) != 0, gcd(N, D) = 1). Its defining polynomial is
/// R(v) = Res_t(N(t) - v D(t), p(t)) for the defining polynomial p of t (every root of R is N/D at a root of p);
/// the isolating interval is an enclosure of N/D on t's refined interval holding exactly one root of R.
inline Algebraic_real arr_value_at(const Ci_poly1& N, const Ci_poly1& D, const Algebraic_real& t) {
  if (t.is_rational()) return Algebraic_real(arr_eval(N, t.rational_value()) / arr_eval(D, t.rational_value()));
  if (N.degree() <= 0 && D.degree() <= 0) return Algebraic_real(Rational(N[0], D[0]));
  const Ci_poly1 p = t.polynomial();
  const int n = std::max(N.degree(), D.degree());
  std::vector<Ci_poly1> fc;
  for (int i = 0; i <= n; ++i) {
    const Integer ni = i <= N.degree() ? N[i] : Integer(0), di = i <= D.degree() ? D[i] : Integer(0);
    fc.push_back(Ci_poly1(ni, -di));  // N_i - v D_i
  }
  const Ci_poly2 F(fc.begin(), fc.end());
  std::vector<Ci_poly1> gc;
  for (int i = 0; i <= p.degree(); ++i) gc.push_back(Ci_poly1(p[i]));
  const Ci_poly2 G(gc.begin(), gc.end());
  const Ci_poly1 R = CGAL::resultant(F, G);
  if (CGAL::is_zero(R)) throw Error("Arr_rational_bezier_traits_2: vanishing coordinate resultant");
  for (int round = 0;; ++round) {
    Rational lo, hi;
    if (arr_enclose_quotient(N, D, t.lower(), t.upper(), lo, hi) && count_real_roots(R, lo, hi) == 1)
      return Algebraic_real(R, lo, hi);
    if (t.is_rational()) return Algebraic_real(arr_eval(N, t.rational_value()) / arr_eval(D, t.rational_value()));
    arr_refine(t);
  }
}

/// Numerator of q(N/D): sum_i q_i N^i D^(d-i), whose roots are the t with N(t)/D(t) a root of q.
inline Ci_poly1 arr_compose(const Ci_poly1& q, const Ci_poly1& N, const Ci_poly1& D) {
  const int d = q.degree();
  std::vector<Ci_poly1> Dp(d + 1, Ci_poly1(1));
  for (int i = 1; i <= d; ++i) Dp[i] = Dp[i - 1] * D;
  Ci_poly1 r(0), Np(1);
  for (int i = 0; i <= d; ++i) {
    if (!CGAL::is_zero(q[i])) r += Ci_poly1(q[i]) * Np * Dp[d - i];
    Np = Np * N;
  }
  return r;
}

/// Sign of (N/D)(t) - v for the t given (filters on enclosures, then exact through arr_value_at).
inline int arr_compare_value(const Ci_poly1& N, const Ci_poly1& D, const Algebraic_real& t, const Algebraic_real& v) {
  for (int round = 0; round < 4; ++round) {
    Rational lo, hi;
    if (arr_enclose_quotient(N, D, t.lower(), t.upper(), lo, hi)) {
      if (hi < v.lower() || (hi == v.lower() && !v.is_rational())) return -1;
      if (lo > v.upper() || (lo == v.upper() && !v.is_rational())) return 1;
    }
    arr_refine(t);
    arr_refine(v);
  }
  return arr_value_at(N, D, t).compare(v);
}

/// All t in [lo, hi] (parameters, exact) where coordinate k of the curve equals v. If `point_y` is given, only
/// those where the other coordinate equals *point_y as well. Throws if the coordinate is constant.
/// (Param: Algebraic_real or the traits' parameter type, with lower(), upper() and comparisons.)
template <class Param>
std::vector<Algebraic_real> arr_parameters_at(const Arr_bezier_supporting_curve& S, int k, const Algebraic_real& v,
                                              const Param& lo, const Param& hi, const Algebraic_real* other = nullptr) {
  const Ci_poly1& N = S.num[k];
  const Ci_poly1& D = S.den[k];
  std::vector<Algebraic_real> out;
  Ci_poly1 Q;
  Ci_poly1 q;
  Rational ql, qh;
  const bool rat = v.is_rational();
  if (rat) {
    const Rational r = v.rational_value();
    // Q = den(r) N - num(r) D
    Q = N * Ci_poly1(Integer(mpq_denref(r.mpq()))) - D * Ci_poly1(Integer(mpq_numref(r.mpq())));
  } else {
    q = v.polynomial();
    ql = v.lower();
    qh = v.upper();
    Q = arr_compose(q, N, D);
  }
  if (CGAL::is_zero(Q)) throw Error("Arr_rational_bezier_traits_2: inversion on a constant coordinate");
  Rational a = lo.lower(), b = hi.upper();
  if (a > b) return out;
  for (const Isolated_root& r : isolate_real_roots(Q, a, b)) {
    const Algebraic_real& t = r.root;
    if (lo > Param(t) || hi < Param(t)) continue;
    if (!rat) {
      // N/D at t is a root of q: it is v iff it lies in v's isolating interval (ql, qh), whose ends are not roots.
      bool keep = false;
      for (;;) {
        Rational l, h;
        if (arr_enclose_quotient(N, D, t.lower(), t.upper(), l, h)) {
          if (l > ql && h < qh) { keep = true; break; }
          if (h < ql || l > qh || (h == ql) || (l == qh)) break;
        }
        if (t.is_rational()) {  // exact value
          const Rational x = arr_eval(N, t.rational_value()) / arr_eval(D, t.rational_value());
          keep = x > ql && x < qh;
          break;
        }
        arr_refine(t);
      }
      if (!keep) continue;
    }
    if (other && arr_compare_value(S.num[1 - k], S.den[1 - k], t, *other) != 0) continue;
    out.push_back(t);
  }
  return out;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_ARRANGEMENT_INTERNAL_ARR_BEZIER_EXACT_H
