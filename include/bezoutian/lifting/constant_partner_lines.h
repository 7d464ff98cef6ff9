// Arcs of D = 0 on a rational line of the parameter plane with one rational partner all along, proved exactly.
// The double curve of an extruded profile with a loop is the example: the profile c(u) passes twice through a node,
// at u = r and u = r', so the patch (c(u), v) meets itself along the line u = r of the parameter plane with the
// constant partner (l, k) = (r' - r, 0). Interval proofs cannot settle the ends of such a line: P = (u, v + k) with k
// enclosed in [-eps, eps] reaches over the side v = 1 of the domain for every span that ends at v = 1. The exact
// argument settles the whole arc at once. With x(t) the line (x_c = r, x_{1-c} = t) and y* the partner:
//  1. E(x(t), y*) vanishes identically in t: each E_i is a polynomial of degree at most N in t (N the sum of the
//     two patches' degrees in u and v: E_i = a_i(P) b_0(Q) - b_i(Q) a_0(P) with P, Q affine in t), and it vanishes
//     at N + 1 distinct rational values of t (exact arithmetic, Partner_equations::exact_values).
//  2. The weights a_0(P), b_0(Q) do not vanish over the arc (interval evaluation on each graph piece), so every
//     point x(t) there has the partner y* (P != Q: y* is not the trivial partner of a self-intersection) and lies on
//     D = 0 (buse-elkadi-galligo-2008 §4: D vanishes on the projection of every double point).
//  3. Every graph piece of the arc runs along t with r strictly inside its cell's range of x_c; in the cell D = 0 is a
//     graph over t, so the arc's point over t is x(t), with the partner y*.
//  4. P and Q are affine in t: inside the (closed) partner domain at both ends of the arc's range of t, they are
//     inside along all of it. Every point of the arc is genuine, its partner exactly y*.
// What is not shown here is that y* is the only partner; the fibre is proved by the sheets (partner_sheets.h).
#ifndef BEZOUTIAN_LIFTING_CONSTANT_PARTNER_LINES_H
#define BEZOUTIAN_LIFTING_CONSTANT_PARTNER_LINES_H

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

/// The proof of the header comment for the arc `e` of the topology, whose traced points e.polyline[i] have the
/// floating-point partners partner[i]: the exact partner y* of every point of the arc, all genuine, or empty.
/// `degree_bound`: N of step 1.
inline std::optional<std::array<Rational, 2>> constant_partner_of_line(
    const Curve_topology_edge& e, const std::vector<std::array<double, 2>>& partner, const Partner_equations& eq,
    const Parameter_box& domain, bool unbounded, int degree_bound) {
  using D = Double_interval;
  const std::optional<std::array<Rational, 2>> none;
  if (e.polyline.empty() || partner.size() != e.polyline.size() || e.pieces.empty()) return none;
  // the line: the coordinate c shared by every traced point; the partner shared by every traced point
  const int c = e.pieces.front().graph_axis == 1 ? 0 : 1;
  const std::size_t m = e.polyline.size() / 2;
  for (std::size_t i = 0; i < e.polyline.size(); ++i)
    if (!(std::fabs(e.polyline[i][c] - e.polyline[m][c]) <= 1e-9 && std::fabs(partner[i][0] - partner[m][0]) <= 1e-9 &&
          std::fabs(partner[i][1] - partner[m][1]) <= 1e-9))
      return none;
  const auto r = rational_near(e.polyline[m][c]);
  const auto y1 = rational_near(partner[m][0]), y2 = rational_near(partner[m][1]);
  if (!r || !y1 || !y2) return none;
  if (eq.self_intersection() && CGAL::is_zero(*y1) && CGAL::is_zero(*y2)) return none;  // the trivial partner
  auto at = [&](const Rational& t) {
    std::array<Rational, 4> z{Rational(0), Rational(0), *y1, *y2};
    z[std::size_t(c)] = *r;
    z[std::size_t(1 - c)] = t;
    return z;
  };
  // 1. E(x(t), y*) = 0 at N + 1 values of t: identically
  for (int j = 0; j <= degree_bound; ++j) {
    std::array<Rational, 2> w;
    const std::array<Rational, 3> E = eq.exact_values(at(Rational(j, degree_bound + 1)), w);
    for (const Rational& v : E)
      if (!CGAL::is_zero(v)) return none;
  }
  // 2-3. per graph piece: along t, r strictly inside the cell, weights nonzero
  double t_lo = HUGE_VAL, t_hi = -HUGE_VAL;
  for (const Curve_topology_piece& pc : e.pieces) {
    if (pc.graph_axis != 1 - c) return none;
    const Rational &lo = c == 0 ? pc.cell.u0 : pc.cell.v0, &hi = c == 0 ? pc.cell.u1 : pc.cell.v1;
    if (!(lo < *r && *r < hi)) return none;
    const int a = 1 - c;
    const D T{std::min(pc.first_box[2 * a], pc.last_box[2 * a]),
              std::max(pc.first_box[2 * a + 1], pc.last_box[2 * a + 1])};
    t_lo = std::min(t_lo, T.lo);
    t_hi = std::max(t_hi, T.hi);
    std::array<D, 4> z;
    z[std::size_t(c)] = D::of(*r);
    z[std::size_t(a)] = T;
    z[2] = D::of(*y1);
    z[3] = D::of(*y2);
    const std::array<D, 2> w = eq.weights(z);
    if (w[0].contains_zero() || w[1].contains_zero()) return none;
  }
  // 4. P and Q (affine in t) inside the closed domain at both ends of the arc's range of t
  if (!unbounded)
    for (const double t : {t_lo, t_hi}) {
      std::array<Rational, 2> P, Q;
      eq.points(at(Rational(t)), P, Q);
      for (const auto* X : {&P, &Q})
        if (!((*X)[0] >= domain.u0 && (*X)[0] <= domain.u1 && (*X)[1] >= domain.v0 && (*X)[1] <= domain.v1))
          return none;
    }
  return std::array<Rational, 2>{*y1, *y2};
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_LIFTING_CONSTANT_PARTNER_LINES_H
