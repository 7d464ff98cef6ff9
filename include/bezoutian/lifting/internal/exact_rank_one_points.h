// The points of a patch where its Jacobian has rank <= 1, found exactly: the route of the pinch-point search where
// its subdivision cannot isolate a solution (pinch_points.h).
//
// With A = (a0, a), a = (a1, a2, a3), the cleared derivatives H = a_u a0 - a a0_u = a0^2 phi_u and
// K = a_v a0 - a a0_v = a0^2 phi_v give
//   H x K = a0 N,   N = a0 (a_u x a_v) + a0_v (a x a_u) + a0_u (a_v x a)
// (expand the product: the term a0_u a0_v (a x a) vanishes, every other one carries a0). Where a0 != 0, rank
// d(phi) <= 1 iff phi_u x phi_v = 0 iff N = 0: the rank-one points are the common zeros of the three bivariate
// polynomials N_1, N_2, N_3. bivariate_real_solutions() finds them exactly when their first coordinates are
// rational (it is tried with u first, then with v first); the other coordinate is an algebraic number. Where the
// Jacobian has rank one its kernel direction (1, m) or (m, 1) is read from H and K at the point: K = 0 exactly
// gives (0, 1), H = 0 exactly gives (1, 0) (exact signs at the algebraic point), otherwise m = -H_c / K_c,
// enclosed in interval arithmetic. Where H = K = 0 the Jacobian is zero (rank 0) and there is no direction.
//
// This is what the subdivision cannot do: a rank-one point where the square system G(u, v, m) = 0 of the search is
// not simple. The folded patch ((u - 3/10)^2, v^2, (u - 3/10)(v - 1/3)) has N = (-2v (v - 1/3), -2 (u - 3/10)^2,
// 4 v (u - 3/10)), so u = 3/10 and v in {0, 1/3}; at (3/10, 0) the root of G is double (phi_v = 0 and phi_u is
// parallel to G's derivative in m), and no Krawczyk box isolates it.
#ifndef BEZOUTIAN_LIFTING_INTERNAL_EXACT_RANK_ONE_POINTS_H
#define BEZOUTIAN_LIFTING_INTERNAL_EXACT_RANK_ONE_POINTS_H

#include <bezoutian/algebraic/bivariate_real_solutions.h>
#include <bezoutian/arithmetic/mpfi_interval.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>
#include <bezoutian/topology/Curve_topology.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace bezoutian {
namespace internal {

/// A point of rank d(phi) <= 1: u and v (one of them rational), and the kernel direction as in Pinch_point
/// (chart 0: (1, m), chart 1: (m, 1), m in [m_lo, m_hi]); rank_zero when d(phi) = 0 there (no direction).
struct Exact_rank_one_point {
  Algebraic_real u, v;
  int chart = 0;
  Rational m_lo, m_hi;
  bool rank_zero = false;
};

/// Every rank-one point in the box, exactly, or the reason why not (`decided` false).
struct Exact_rank_one_points {
  bool decided = false;
  std::vector<Exact_rank_one_point> points;
  std::string reason;
};

// N of the header comment, componentwise (inner variable u).
inline std::array<Polynomial_2<Rational>, 3> cleared_normal(const Rational_bezier_patch<Rational>& phi) {
  using P2 = Polynomial_2<Rational>;
  const auto diff = [](const P2& p, int variable) { return typename CGAL::Polynomial_traits_d<P2>::Differentiate()(p, variable); };
  const auto A = phi.power_form();
  std::array<P2, 3> a, au, av;
  for (int c = 0; c < 3; ++c) {
    a[c] = A[c + 1];
    au[c] = diff(A[c + 1], 0);
    av[c] = diff(A[c + 1], 1);
  }
  const P2 a0 = A[0], a0u = diff(A[0], 0), a0v = diff(A[0], 1);
  auto cross = [](const std::array<P2, 3>& x, const std::array<P2, 3>& y, int c) {
    const int i = (c + 1) % 3, j = (c + 2) % 3;
    return P2(x[i] * y[j] - x[j] * y[i]);
  };
  std::array<P2, 3> N;
  for (int c = 0; c < 3; ++c) N[c] = a0 * cross(au, av, c) + a0v * cross(a, au, c) + a0u * cross(av, a, c);
  return N;
}

// p(x, y) with x rational and y algebraic, as the univariate polynomial in the algebraic coordinate. `rational_u`:
// x is u (p's inner variable); otherwise x is v.
inline Polynomial_1<Rational> at_rational_coordinate(const Polynomial_2<Rational>& p, const Rational& x, bool rational_u) {
  return rational_u ? with_inner_fixed(p, x) : with_outer_fixed(p, x);
}

inline Mpfi_interval mpfi_horner(const Polynomial_1<Rational>& p, const Mpfi_interval& y) {
  const mpfr_prec_t prec = y.prec();
  Mpfi_interval r = Mpfi_interval::point(0, prec);
  for (int i = p.degree(); i >= 0; --i) r = r * y + Mpfi_interval::hull(p[i], p[i], prec);
  return r;
}

/// The rank-one points of `phi` in `box` (see the header comment). `max_resultant_degree` bounds the work: the
/// route is refused when 2 deg_u(N) deg_v(N), a bound on the resultants' degree, exceeds it.
inline Exact_rank_one_points exact_rank_one_points(const Rational_bezier_patch<Rational>& phi, const Parameter_box& box,
                                                   int max_resultant_degree = 400) {
  using P2 = Polynomial_2<Rational>;
  using P1 = Polynomial_1<Rational>;
  using I = Mpfi_interval;
  Exact_rank_one_points out;
  const std::array<P2, 3> N = cleared_normal(phi);
  int du = 0, dv = 0;
  for (const P2& p : N) {
    dv = std::max(dv, p.degree());
    for (int j = 0; j <= p.degree(); ++j) du = std::max(du, p[j].degree());
  }
  if (2 * du * dv > max_resultant_degree) {
    out.reason = "the exact route is refused: the normal's components have degrees (" + std::to_string(du) + ", " +
                 std::to_string(dv) + ")";
    return out;
  }
  Bivariate_real_solutions s = bivariate_real_solutions({N[0], N[1], N[2]}, box.u0, box.u1, box.v0, box.v1);
  bool rational_u = true;
  if (!s.decided) {
    std::vector<P2> T;
    for (const P2& p : N) T.push_back(typename CGAL::Polynomial_traits_d<P2>::Swap()(p, 0, 1));
    Bivariate_real_solutions t = bivariate_real_solutions(T, box.v0, box.v1, box.u0, box.u1);
    if (!t.decided) {
      out.reason = "u first: " + s.reason + "; v first: " + t.reason;
      return out;
    }
    s = std::move(t);
    rational_u = false;
  }
  // the cleared derivatives at the points (H = a0^2 phi_u, K = a0^2 phi_v)
  const auto diff = [](const P2& p, int variable) { return typename CGAL::Polynomial_traits_d<P2>::Differentiate()(p, variable); };
  const auto A = phi.power_form();
  std::array<P2, 3> Hc, Kc;
  for (int c = 0; c < 3; ++c) {
    Hc[c] = diff(A[c + 1], 0) * A[0] - A[c + 1] * diff(A[0], 0);
    Kc[c] = diff(A[c + 1], 1) * A[0] - A[c + 1] * diff(A[0], 1);
  }
  const mpfr_prec_t prec = 128;
  for (const auto& xy : s.points) {
    const Rational& x = xy.first;
    const Algebraic_real& y = xy.second;
    y.refine_to_width(Rational(1, Integer(1) << 80));
    const I Y = I::hull(y.lower(), y.upper(), prec);
    std::array<P1, 3> h, k;
    bool h_zero = true, k_zero = true;
    for (int c = 0; c < 3; ++c) {
      h[c] = at_rational_coordinate(Hc[c], x, rational_u);
      k[c] = at_rational_coordinate(Kc[c], x, rational_u);
      h_zero = h_zero && y.sign_of(h[c]) == 0;
      k_zero = k_zero && y.sign_of(k[c]) == 0;
    }
    Exact_rank_one_point p;
    p.u = rational_u ? Algebraic_real(x) : y;
    p.v = rational_u ? y : Algebraic_real(x);
    if (h_zero && k_zero) {
      p.rank_zero = true;
      p.m_lo = -1;
      p.m_hi = 1;
    } else if (k_zero || h_zero) {  // phi_v = 0: direction (0, 1); phi_u = 0: (1, 0)
      p.chart = k_zero ? 1 : 0;
      p.m_lo = p.m_hi = 0;
    } else {
      // h + m k = 0 with k != 0 (chart 0), or m h + k = 0 (chart 1): the component of largest |k| (|h|) divides
      int c = 0;
      std::array<I, 3> Hi{I::point(0, prec), I::point(0, prec), I::point(0, prec)}, Ki = Hi;
      for (int d = 0; d < 3; ++d) {
        Hi[d] = mpfi_horner(h[d], Y);
        Ki[d] = mpfi_horner(k[d], Y);
      }
      auto magnitude = [](const I& z) {
        return std::min(std::fabs(CGAL::to_double(z.lower())), std::fabs(CGAL::to_double(z.upper())));
      };
      double best = -1;
      int chart = 0;
      for (int d = 0; d < 3; ++d)
        for (int ch = 0; ch < 2; ++ch) {
          const I& den = ch == 0 ? Ki[d] : Hi[d];
          if (den.contains_zero()) continue;
          const double w = magnitude(den) / std::max(magnitude(ch == 0 ? Hi[d] : Ki[d]), 1e-300);
          if (w > best) best = w, c = d, chart = ch;
        }
      if (best < 0) {
        out.points.clear();
        out.reason = "the kernel direction at a rank-one point is not resolved at 128 bits";
        return out;
      }
      const I m = I::point(0, prec) - (chart == 0 ? Hi[c] / Ki[c] : Ki[c] / Hi[c]);
      p.chart = chart;
      p.m_lo = m.lower();
      p.m_hi = m.upper();
    }
    out.points.push_back(p);
  }
  out.decided = true;
  return out;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_LIFTING_INTERNAL_EXACT_RANK_ONE_POINTS_H
