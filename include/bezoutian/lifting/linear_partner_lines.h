// Arcs of D = 0 on a rational line of the parameter plane whose partner is an affine function of the point with
// rational coefficients, proved exactly. Two kinds are common in models:
//  - the double curve of an extruded profile with a loop. The profile c(u) passes twice through a node, at u = r and
//    at u = r', so the patch (c(u), v) meets itself along the line u = r with the constant partner (r' - r, 0);
//  - a patch folded over itself (Phi(u, v) = Phi(3/5 - u, v) on v = 1/3: the partner (3/5 - 2u, 0)), and two
//    extrusions along one direction, (c1(u), v) and (c2(s), t), which meet along u = u* with the partner
//    (v, s) = (t, s*).
// Interval proofs cannot settle the ends of such a line where a point reaches the domain's side there. For the
// extruded loop, P = (u, v + k) with k enclosed in [-eps, eps] reaches over the side v = 1 for every span that ends
// at v = 1. The exact argument settles the whole arc at once. With x(t) the line (x_c = r, x_{1-c} = t) and y(t) = a
// + b t the partner:
//  1. E(x(t), y(t)) vanishes identically in t. P and Q are affine in t, so each E_i = a_i(P) b_0(Q) - b_i(Q) a_0(P)
//     is a polynomial of degree at most N in t (N the sum of the two patches' degrees in u and v). It vanishes at
//     N + 1 distinct rational values of t (exact arithmetic, Partner_equations::exact_values).
//  2. The weights a_0(P), b_0(Q) do not vanish over the arc (interval evaluation on each graph piece). For a
//     self-intersection, y(t) is not the trivial partner 0 identically: being affine, it vanishes at one t at most,
//     a pinch point (the folded patch at u = 3/10), whose traced point keeps its own status. So every other point
//     x(t) has the partner y(t) with P != Q, and lies on D = 0 (buse-elkadi-galligo-2008 §4: D vanishes on the
//     projection of every double point, and so on its closure).
//  3. Every graph piece of the arc runs along t with r strictly inside its cell's range of x_c; in the cell D = 0 is a
//     graph over t, so the arc's point over t is x(t), with the partner y(t).
//  4. P and Q are affine in t: inside the (closed) partner domain at both ends of the arc's range of t, they are
//     inside along all of it. Every point of the arc is genuine, its partner exactly y(t).
// What is not shown here is that y(t) is the only partner; the fibre is proved by the sheets (partner_sheets.h).
#ifndef BEZOUTIAN_LIFTING_LINEAR_PARTNER_LINES_H
#define BEZOUTIAN_LIFTING_LINEAR_PARTNER_LINES_H

#include <bezoutian/arithmetic/simplest_rational.h>
#include <bezoutian/lifting/double_partner_witness.h>
#include <bezoutian/lifting/partner_domain_crossings.h>
#include <bezoutian/topology/Curve_topology.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace bezoutian {
namespace internal {

/// The simplest rational within a relative 1e-10 of x (empty if x is not finite).
inline std::optional<Rational> rational_near(double x) {
  if (!std::isfinite(x)) return std::nullopt;
  const double r = 1e-10 * (1 + std::fabs(x));
  Rational q;
  if (!simplest_rational_in(Rational(x - r), Rational(x + r), q)) return std::nullopt;
  return q;
}

/// The partner y(t) = a + b t of the header comment: partner(t) = {a[0] + b[0] t, a[1] + b[1] t}.
struct Linear_partner {
  std::array<Rational, 2> a, b;
  std::array<Rational, 2> at(const Rational& t) const { return {a[0] + b[0] * t, a[1] + b[1] * t}; }
};

/// The proof of the header comment for the arc `e` of the topology, whose traced points e.polyline[i] have the
/// floating-point partners partner[i]: the exact partner y(t) of every point of the arc, all genuine (but a pinch
/// point, where y vanishes), or empty. `degree_bound`: N of step 1.
inline std::optional<Linear_partner> linear_partner_of_line(const Curve_topology_edge& e,
                                                            const std::vector<std::array<double, 2>>& partner,
                                                            const Partner_equations& eq, const Parameter_box& domain,
                                                            bool unbounded, int degree_bound) {
  using D = Double_interval;
  const std::optional<Linear_partner> none;
  const std::size_t n = e.polyline.size();
  if (n < 3 || partner.size() != n || e.pieces.empty()) return none;
  // the line: the coordinate c shared by every traced point; the partner's coefficients from two traced points a
  // quarter of the arc from its ends (floating point, then the simplest rationals next to them)
  const int c = e.pieces.front().graph_axis == 1 ? 0 : 1, g = 1 - c;
  const std::size_t i0 = n / 4, i1 = n - 1 - n / 4;
  const double t0 = e.polyline[i0][g], t1 = e.polyline[i1][g];
  if (!(std::fabs(t1 - t0) > 1e-6)) return none;
  Linear_partner y;
  for (int d = 0; d < 2; ++d) {
    const double slope = (partner[i1][d] - partner[i0][d]) / (t1 - t0), start = partner[i0][d] - slope * t0;
    const auto a = rational_near(start), b = rational_near(slope);
    if (!a || !b) return none;
    y.a[std::size_t(d)] = *a;
    y.b[std::size_t(d)] = *b;
  }
  const auto r = rational_near(e.polyline[n / 2][c]);
  if (!r) return none;
  const double rd = CGAL::to_double(*r);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = e.polyline[i][g];
    if (!(std::fabs(e.polyline[i][c] - rd) <= 1e-9)) return none;
    for (int d = 0; d < 2; ++d)
      if (!(std::fabs(partner[i][d] - CGAL::to_double(y.a[d]) - CGAL::to_double(y.b[d]) * t) <= 1e-7)) return none;
  }
  auto at = [&](const Rational& t) {
    const std::array<Rational, 2> p = y.at(t);
    std::array<Rational, 4> z{Rational(0), Rational(0), p[0], p[1]};
    z[std::size_t(c)] = *r;
    z[std::size_t(g)] = t;
    return z;
  };
  // 1. E(x(t), y(t)) = 0 at N + 1 values of t: identically
  for (int j = 0; j <= degree_bound; ++j) {
    std::array<Rational, 2> w;
    const std::array<Rational, 3> E = eq.exact_values(at(Rational(j, degree_bound + 1)), w);
    for (const Rational& v : E)
      if (!CGAL::is_zero(v)) return none;
  }
  // 2-3. per graph piece: along t, r strictly inside the cell, weights nonzero
  double t_lo = HUGE_VAL, t_hi = -HUGE_VAL;
  for (const Curve_topology_piece& pc : e.pieces) {
    if (pc.graph_axis != g) return none;
    const Rational &lo = c == 0 ? pc.cell.u0 : pc.cell.v0, &hi = c == 0 ? pc.cell.u1 : pc.cell.v1;
    if (!(lo < *r && *r < hi)) return none;
    const D T{std::min(pc.first_box[2 * g], pc.last_box[2 * g]),
              std::max(pc.first_box[2 * g + 1], pc.last_box[2 * g + 1])};
    t_lo = std::min(t_lo, T.lo);
    t_hi = std::max(t_hi, T.hi);
    std::array<D, 4> z;
    z[std::size_t(c)] = D::of(*r);
    z[std::size_t(g)] = T;
    for (int d = 0; d < 2; ++d) z[std::size_t(2 + d)] = D::of(y.a[std::size_t(d)]) + D::of(y.b[std::size_t(d)]) * T;
    const std::array<D, 2> w = eq.weights(z);
    if (w[0].contains_zero() || w[1].contains_zero()) return none;
  }
  // (self-intersection) y is not the trivial partner 0 identically; it vanishes at most at one t, a pinch point
  if (eq.self_intersection() && CGAL::is_zero(y.a[0]) && CGAL::is_zero(y.a[1]) && CGAL::is_zero(y.b[0]) &&
      CGAL::is_zero(y.b[1]))
    return none;
  // 4. P and Q (affine in t) inside the closed domain at both ends of the arc's range of t
  if (!unbounded)
    for (const double t : {t_lo, t_hi}) {
      std::array<Rational, 2> P, Q;
      eq.points(at(Rational(t)), P, Q);
      for (const auto* X : {&P, &Q})
        if (!((*X)[0] >= domain.u0 && (*X)[0] <= domain.u1 && (*X)[1] >= domain.v0 && (*X)[1] <= domain.v1))
          return none;
    }
  return y;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_LIFTING_LINEAR_PARTNER_LINES_H
