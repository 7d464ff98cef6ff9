// The edges of the box that lie on D = 0 (a collapsed edge of a patch, a boundary curve shared by two patches):
// D = (x - c)·Q exactly, and the rest Q of the curve is analysed on its own.
#ifndef BEZOUTIAN_INTERSECTION_INTERNAL_BOX_EDGE_LINES_H
#define BEZOUTIAN_INTERSECTION_INTERNAL_BOX_EDGE_LINES_H

#include <bezoutian/algebraic/bivariate_real_solutions.h>
#include <bezoutian/intersection/Curve_intersection.h>
#include <bezoutian/intersection/Curve_surface_intersection.h>
#include <bezoutian/topology/Curve_topology.h>
#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/algebraic/Polynomial_normalization.h>
#include <bezoutian/geometry/Rational_bezier_curve.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>
#include <bezoutian/algebraic/Root_isolation.h>
#include <bezoutian/arithmetic/number_types.h>

#include <array>
#include <functional>
#include <vector>

namespace bezoutian {
namespace internal {

// Sides in the order of Rational_bezier_patch::boundary_curve: 0: y = y0, 1: x = x1, 2: y = y1, 3: x = x0.
inline bool side_is_vertical(int side) { return side == 1 || side == 3; }

inline Rational side_value(const Parameter_box& b, int side) {
  switch (side) {
    case 0: return b.v0;
    case 1: return b.u1;
    case 2: return b.v1;
    default: return b.u0;
  }
}

// D(c, y) == 0 (vertical) or D(x, c) == 0 as a polynomial, decided exactly.
inline bool vanishes_on_line(const Polynomial_2<Integer>& D, bool vertical, const Rational& c) {
  if (vertical) {
    for (int j = 0; j <= D.degree(); ++j) {
      Rational x(0);
      for (int i = D[j].degree(); i >= 0; --i) x = x * c + Rational(D[j][i]);
      if (!CGAL::is_zero(x)) return false;
    }
    return true;
  }
  const int dx = [&] {
    int d = 0;
    for (int j = 0; j <= D.degree(); ++j) d = std::max(d, D[j].degree());
    return d;
  }();
  for (int i = 0; i <= dx; ++i) {
    Rational x(0);
    for (int j = D.degree(); j >= 0; --j) x = x * c + (i <= D[j].degree() ? Rational(D[j][i]) : Rational(0));
    if (!CGAL::is_zero(x)) return false;
  }
  return true;
}

// The factor q x - p (vertical) or q y - p of c = p / q, primitive.
inline Polynomial_2<Integer> line_factor(bool vertical, const Rational& c) {
  const Integer p = c.numerator(), q = c.denominator();
  if (vertical) return Polynomial_2<Integer>(Polynomial_1<Integer>(-p, q));
  return Polynomial_2<Integer>(Polynomial_1<Integer>(-p), Polynomial_1<Integer>(q));
}

/// D with the factor of the line removed (D square-free, the line on D = 0), normalized.
inline Polynomial_2<Integer> without_line(const Polynomial_2<Integer>& D, bool vertical, const Rational& c) {
  const Polynomial_2<Integer> f = line_factor(vertical, c), q = CGAL::integral_division(D, f);
  if (q * f != D) throw Error("box_edge_lines: inexact division by a line factor");
  return normalized_primitive_part(q);
}

/// The box's edges contained in D = 0 and D with their factors removed.
struct Box_edge_lines {
  std::vector<int> sides;     ///< sides (0: v = v0, 1: u = u1, 2: v = v1, 3: u = u0) along which D vanishes
  Polynomial_2<Integer> rest;  ///< D divided by the factor of each of those lines, normalized
};

// D square-free: each line factor divides it once. The division is exact over Z (the factors are primitive, Gauss's
// lemma), and checked: a remainder would be a bug, not an input error.
inline Box_edge_lines box_edge_lines(const Polynomial_2<Integer>& D, const Parameter_box& box) {
  Box_edge_lines r;
  r.rest = D;
  for (int side = 0; side < 4; ++side) {
    const bool vertical = side_is_vertical(side);
    const Rational c = side_value(box, side);
    if (side >= 2 && c == side_value(box, side - 2)) continue;  // a degenerate box: the same line twice
    if (CGAL::is_zero(r.rest) || !vanishes_on_line(r.rest, vertical, c)) continue;
    r.rest = without_line(r.rest, vertical, c);
    r.sides.push_back(side);
  }
  return r;
}

/// The rational lines x = c (vertical) and y = c strictly inside the box on which D vanishes: the rational roots of
/// D's factors in one variable alone (its content as a polynomial in the other variable).
struct Interior_line {
  bool vertical = false;
  Rational value;
};
inline std::vector<Interior_line> interior_lines(const Polynomial_2<Integer>& D, const Parameter_box& box) {
  std::vector<Interior_line> out;
  if (CGAL::is_zero(D)) return out;
  Polynomial_1<Integer> in_x(0), in_y(0);  // gcd of the coefficients of y^j, and of x^i
  int dx = 0;
  for (int j = 0; j <= D.degree(); ++j) {
    in_x = CGAL::is_zero(in_x) ? D[j] : Polynomial_1<Integer>(CGAL::gcd(in_x, D[j]));
    dx = std::max(dx, D[j].degree());
  }
  for (int i = 0; i <= dx; ++i) {
    std::vector<Integer> c;
    for (int j = 0; j <= D.degree(); ++j) c.push_back(i <= D[j].degree() ? D[j][i] : Integer(0));
    const Polynomial_1<Integer> p(c.begin(), c.end());
    if (!CGAL::is_zero(p)) in_y = CGAL::is_zero(in_y) ? p : Polynomial_1<Integer>(CGAL::gcd(in_y, p));
  }
  for (const bool vertical : {true, false}) {
    const Polynomial_1<Integer>& g = vertical ? in_x : in_y;
    if (CGAL::is_zero(g) || g.degree() < 1) continue;
    const Rational lo = vertical ? box.u0 : box.v0, hi = vertical ? box.u1 : box.v1;
    for (const Isolated_root& r : isolate_real_roots(g, lo, hi))
      if (r.root.is_rational() && lo < r.root.rational_value() && r.root.rational_value() < hi)
        out.push_back({vertical, r.root.rational_value()});
  }
  return out;
}

/// The box in which a line x = c or y = c is the side 3 (x = x0) or 0 (y = y0): the explanation of an interior
/// line is that of a side of this box.
inline Parameter_box box_from_line(const Parameter_box& box, bool vertical, const Rational& c) {
  return vertical ? Parameter_box{c, box.u1, box.v0, box.v1} : Parameter_box{box.u0, box.u1, c, box.v1};
}

using Edge_curve = Rational_bezier_curve_3<Rational>;

inline bool is_point_curve(const Edge_curve& c) {
  for (std::size_t i = 1; i < c.number_of_control_points(); ++i)
    if (c.control_point(i) != c.control_point(0)) return false;
  return true;
}

// Is every point of M (over [0,1]) a point of C (over [0,1])? Exact; false when undecided (a pole in [0,1]).
inline bool lies_on(const Edge_curve& M, const Edge_curve& C) {
  for (const Edge_curve* c : {&M, &C})
    for (std::size_t i = 0; i < c->number_of_control_points(); ++i)
      if (CGAL::sign(c->weight(i)) <= 0) return false;  // positive weights: no pole, and the curve is in its hull
  const bool m_point = is_point_curve(M), c_point = is_point_curve(C);
  if (m_point && c_point) return M.control_point(0) == C.control_point(0);
  if (c_point) return false;  // a curve is not one point (positive weights: constant iff the control points agree)
  if (m_point) {  // P on C: a common root in [0,1] of X_k - P_k W
    const auto H = C.power_form();
    const auto P = M.control_point(0);
    Polynomial_1<Rational> g(0);
    for (int k = 0; k < 3; ++k) g = CGAL::gcd(g, H[k + 1] - Polynomial_1<Rational>(P[k]) * H[0]);
    if (CGAL::is_zero(g) || g.degree() < 1) return false;
    return !isolate_real_roots(g, Rational(0), Rational(1)).empty();
  }
  const Curve_intersection_result r = intersect_curves(M, C);
  std::vector<std::pair<Algebraic_real, Algebraic_real>> pieces;  // ranges of M covered by C
  for (const auto& o : r.overlaps) pieces.emplace_back(std::min(o.s0, o.s1), std::max(o.s0, o.s1));
  std::sort(pieces.begin(), pieces.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  Algebraic_real reached(0);
  for (const auto& q : pieces) {
    if (reached < q.first) return false;
    reached = std::max(reached, q.second);
  }
  return reached >= Algebraic_real(1);
}

/// Why a box side lies on D = 0, decided exactly (buse-elkadi-galligo-2008 §4: a point of D = 0 is a projected
/// pair of preimages of one 3D point). Along the side one coordinate is fixed (c) and one is free (τ). The pair's
/// point on the side's own iso-curve C (u = c of the first patch, t = c of the second, or for a self-intersection
/// u = c or v = c of the patch) lies over the partner domain; the other point lies on an iso-curve M of the partner
/// at a fixed coordinate c' and runs with τ. If M(τ) lies on C for every τ in the box, every point of the side is
/// genuine: a collapsed edge (C and M one point), a boundary curve shared with a side of the partner (the
/// teapot's glued edges, a closed patch's seam), or an iso-curve inside the partner domain (a surface tangent to
/// the other along its boundary, as a fillet along its base; c' comes from a floating-point partner, rounded to
/// the simplest rational, and the exact test lies_on decides). For two patches a side whose C is one point P not
/// on the partner over its range is phantom at every point (`point_off_partner`: P is off the partner, proved by
/// the exact real solutions of X_k - P_k W = 0; D vanishes there through the base points of the collapsed side,
/// complex zeros of its weight). A side whose C, over the partner domain, meets the partner over its range nowhere
/// is phantom at every point too (`curve_off_partner`, by the exact curve/patch intersection: D vanishes there
/// through pairs outside the domains, e.g. a pole of a sphere patch and the point at infinity of a circle).
struct Edge_line_explanation {
  enum Cause { unexplained, collapsed, shared_curve, outside_domain, partner_iso_curve, point_off_partner,
               curve_off_partner };
  Cause cause = unexplained;
  int partner_side = -1;  ///< the side of the partner domain holding M (boundary_curve order), -1: C itself or inside
  Rational partner_value;  ///< c', the fixed coordinate of M (the side's own value when C is paired with itself)
  Edge_curve own, other;  ///< C over the partner domain and M over the box (parameters in [0,1])
};

inline bool within(const Rational& a0, const Rational& a1, const Rational& b0, const Rational& b1) {
  return b0 <= a0 && a1 <= b1;
}

// side: of the box (u = c for sides 1, 3; v or t = c for 0, 2). psi == nullptr: self-intersection of phi.
// `candidates`: values c' inside the partner domain to try for M besides the domain's sides (intersections), asked
// for only when the sides do not explain the line (a floating-point search).
inline Edge_line_explanation explain_edge_line(int side, const Parameter_box& box, const Parameter_box& domain,
                                               bool domain_unbounded, const Rational_bezier_patch<Rational>& phi,
                                               const Rational_bezier_patch<Rational>* psi,
                                               const std::function<std::vector<Rational>()>& candidates = {}) {
  Edge_line_explanation e;
  e.partner_value = side_value(box, side);
  const bool vertical = side_is_vertical(side);
  const Rational c = side_value(box, side);
  const Parameter_box& d = domain;
  // the coordinate of the pair's point on C is c: outside the domain, no partner is genuine
  if (!domain_unbounded && (vertical ? (c < d.u0 || d.u1 < c) : (c < d.v0 || d.v1 < c))) {
    e.cause = Edge_line_explanation::outside_domain;
    return e;
  }
  if (domain_unbounded) return e;
  const bool free_inside = vertical ? within(box.v0, box.v1, d.v0, d.v1) : within(box.u0, box.u1, d.u0, d.u1);
  if (!free_inside) return e;
  try {
    // C: the side's own iso-curve over the partner domain. M: iso-curves of the partner at the domain's sides, over
    // the box (for a self-intersection also the side's own iso-curve over the box, when C is one point).
    const Rational_bezier_patch<Rational>& own_patch = (psi && !vertical) ? *psi : phi;
    const Rational_bezier_patch<Rational>& other_patch = psi ? (vertical ? *psi : phi) : phi;
    // the free coordinate over the box, the other over the partner domain (u, v of phi; s, t of psi)
    const Parameter_box own_range = vertical ? Parameter_box{box.u0, box.u1, d.v0, d.v1} : Parameter_box{d.u0, d.u1, box.v0, box.v1};
    const Parameter_box other_range = vertical ? Parameter_box{d.u0, d.u1, box.v0, box.v1} : Parameter_box{box.u0, box.u1, d.v0, d.v1};
    e.own = own_patch.restriction(own_range.u0, own_range.u1, own_range.v0, own_range.v1).boundary_curve<Edge_curve>(side);
    const bool own_point = is_point_curve(e.own);
    const Rational_bezier_patch<Rational> other =
        other_patch.restriction(other_range.u0, other_range.u1, other_range.v0, other_range.v1);
    // the partner's sides at a fixed coordinate of the same direction as the side (u = d.u0, d.u1 or v = d.v0, d.v1)
    const int sides[2] = {vertical ? 3 : 0, vertical ? 1 : 2};
    for (int ps : sides) {
      const Rational cp = side_value(d, ps);
      if (!psi && cp == c) continue;  // the side itself: below (a pair of distinct points only if C is one point)
      const Edge_curve M = other.boundary_curve<Edge_curve>(ps);
      if (lies_on(M, e.own)) {
        e.cause = own_point ? Edge_line_explanation::collapsed : Edge_line_explanation::shared_curve;
        e.partner_side = ps;
        e.partner_value = cp;
        e.other = M;
        return e;
      }
    }
    for (const Rational& cp : candidates ? candidates() : std::vector<Rational>{}) {  // M inside the domain
      if (!psi || (vertical ? (cp <= d.u0 || d.u1 <= cp) : (cp <= d.v0 || d.v1 <= cp))) continue;
      const Edge_curve M = vertical ? other_patch.restriction(cp, cp, box.v0, box.v1).boundary_curve<Edge_curve>(3)
                                    : other_patch.restriction(box.u0, box.u1, cp, cp).boundary_curve<Edge_curve>(0);
      if (!own_point && lies_on(M, e.own)) {
        e.cause = Edge_line_explanation::partner_iso_curve;
        e.partner_value = cp;
        e.other = M;
        return e;
      }
    }
    if (psi && own_point && other.has_positive_weights()) {  // (W > 0: every real solution is a point of the patch)
      const auto P = e.own.control_point(0);
      const auto f = other.power_form();
      std::vector<Polynomial_2<Rational>> F;
      for (std::size_t k = 0; k < 3; ++k) F.push_back(f[k + 1] - f[0] * P[k]);
      const Bivariate_real_solutions on = bivariate_real_solutions(F, Rational(0), Rational(1), Rational(0), Rational(1));
      if (on.decided && on.points.empty()) {
        e.cause = Edge_line_explanation::point_off_partner;
        return e;
      }
    }
    if (psi && !own_point && other.has_positive_weights()) {
      // C meets the partner over its range nowhere (exact curve/patch intersection): no point of the side has a
      // partner in the domain
      const Curve_patch_intersection_result r = intersect_curve_patch(e.own, other);
      if (r.points.empty() && r.overlaps.empty()) {
        e.cause = Edge_line_explanation::curve_off_partner;
        return e;
      }
    }
    if (!psi && own_point) {  // the side's own iso-curve is one point: every other point of it is a partner
      e.other = phi.restriction(box.u0, box.u1, box.v0, box.v1).boundary_curve<Edge_curve>(side);
      e.cause = Edge_line_explanation::collapsed;
      return e;
    }
  } catch (const Error&) {
    // a pole or a degenerate restriction: left unexplained
  }
  return e;
}

} // namespace internal
} // namespace bezoutian

#endif // BEZOUTIAN_INTERSECTION_INTERNAL_BOX_EDGE_LINES_H
