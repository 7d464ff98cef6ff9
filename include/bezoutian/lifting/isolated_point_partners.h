// The partners of an isolated real point of D = 0 in an intersection locus, decided exactly.
//
// An isolated real point x = (u, t) of D = 0 is either a point where the two patches touch — a real partner
// y = (v, s) in the partner domain, so Phi(u, v) = Psi(s, t) is an isolated point of the intersection; two smooth
// surfaces that cross transversally meet along a curve, so there the tangent planes agree or a patch is singular —
// or a phantom: its partners are complex (an acnode of D) or lie outside the partner domain.
//
// When x is rational (the simplest rational of its certified enclosure, D(x) = 0 checked exactly), the fibre
//   F_c(v, s) = A_c(u, v) B_0(s, t) - B_c(s, t) A_0(u, v),  c = 1, 2, 3   (lifting/double_partner_witness.h)
// is a system over Q in (v, s) and its real solutions in the partner domain are found exactly
// (algebraic/bivariate_real_solutions.h: none proves a phantom; an irrational v leaves the point undecided). With
// positive Bernstein weights A_0 and B_0
// are positive on the unit square, so every real solution there is an affine coincidence Phi(u, v) = Psi(s, t).
//
// Tangency at a rational partner is decided exactly: with Phi = X / W, W^2 Phi_u = X_u W - X W_u (likewise for v, s,
// t), so the normals are parallel iff (X_u W - X W_u) x (X_v W - X W_v) and the same for Psi are, nonzero.
#ifndef BEZOUTIAN_LIFTING_ISOLATED_POINT_PARTNERS_H
#define BEZOUTIAN_LIFTING_ISOLATED_POINT_PARTNERS_H

#include <bezoutian/algebraic/Algebraic_real.h>
#include <bezoutian/algebraic/bivariate_real_solutions.h>
#include <bezoutian/arithmetic/exact_text.h>
#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/arithmetic/simplest_rational.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>
#include <bezoutian/topology/Curve_topology.h>

#include <CGAL/Polynomial.h>

#include <array>
#include <string>
#include <vector>

namespace bezoutian {

/// An isolated real point of D = 0 in the box and its real partners in the partner domain (intersection loci).
struct Isolated_point_partners {
  /// The point (u, t), exact: the simplest rational of the vertex's enclosure, on D = 0 (checked exactly).
  bool exact = false;
  std::array<Rational, 2> projection{};
  /// A real partner (v, s) in the partner domain: Phi(u, v) = Psi(s, t) exactly.
  struct Partner {
    Algebraic_real v, s;
    std::array<double, 3> point{};
    bool tangency_decided = false;  ///< s rational: the normals compared exactly
    bool tangent = false;           ///< the tangent planes agree (both normals nonzero)
    bool singular = false;          ///< a normal vanishes (a singular point of a patch, e.g. a collapsed side)
  };
  std::vector<Partner> partners;
  /// `partners` is proved to be every real partner in the partner domain (and empty proves a phantom point).
  bool proved = false;
  std::string reason;
};

namespace internal {

// The normal direction of the rational patch with power form f at (x, y): (X_x W - X W_x) x (X_y W - X W_y).
inline std::array<Rational, 3> exact_normal(const Rational_bezier_patch<Rational>::Power_form& f, const Rational& x,
                                            const Rational& y) {
  using PT = CGAL::Polynomial_traits_d<Poly2_Q>;
  typename PT::Differentiate diff;
  std::array<Rational, 4> value, dx, dy;
  for (std::size_t k = 0; k < 4; ++k) {
    value[k] = evaluate_exact(f[k], x, y);
    dx[k] = evaluate_exact(diff(f[k], 0), x, y);
    dy[k] = evaluate_exact(diff(f[k], 1), x, y);
  }
  std::array<Rational, 3> a, b;
  for (std::size_t k = 0; k < 3; ++k) {
    a[k] = dx[k + 1] * value[0] - value[k + 1] * dx[0];
    b[k] = dy[k + 1] * value[0] - value[k + 1] * dy[0];
  }
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

inline bool is_zero_vector(const std::array<Rational, 3>& n) {
  return CGAL::is_zero(n[0]) && CGAL::is_zero(n[1]) && CGAL::is_zero(n[2]);
}

inline Rational simplest_in(double lo, double hi) {
  Rational r;
  if (!simplest_rational_in(Rational(lo), Rational(hi), r)) r = Rational((lo + hi) / 2);
  return r;
}

}  // namespace internal

/// \brief The real partners in `domain` ({s-range} x {v-range}: Parameter_box u = s, v = v) of the isolated vertex
/// `x` of D = 0 (`D` the square-free part in (u, t)) of the intersection of `phi` and `psi`, decided exactly (see
/// the header). Requires positive weights.
inline Isolated_point_partners isolated_point_partners(const Rational_bezier_patch<Rational>& phi,
                                                       const Rational_bezier_patch<Rational>& psi,
                                                       const Polynomial_2<Integer>& D, const Curve_topology_vertex& x,
                                                       const Parameter_box& domain) {
  using namespace internal;
  Isolated_point_partners out;
  if (!phi.has_positive_weights() || !psi.has_positive_weights()) {
    out.reason = "not all weights are positive: the partners are not decided";
    return out;
  }
  const Rational u = simplest_in(x.u_lo, x.u_hi), t = simplest_in(x.v_lo, x.v_hi);
  {
    Rational d(0);  // D(u, t), exactly
    for (int j = D.degree(); j >= 0; --j) {
      Rational row(0);
      for (int i = D[j].degree(); i >= 0; --i) row = row * u + Rational(D[j][i]);
      d = d * t + row;
    }
    if (!CGAL::is_zero(d)) {
      out.reason = "the point is not a rational of small height (D does not vanish at the simplest rational of its "
                   "enclosure): its partners are not decided";
      return out;
    }
  }
  out.exact = true;
  out.projection = {u, t};
  const auto f = phi.power_form(), g = psi.power_form();
  // A_k(v) = A_k(u, v) and B_k(s) = B_k(s, t); F_c with inner variable v, outer s
  std::array<Poly1_Q, 4> A, B;
  for (std::size_t k = 0; k < 4; ++k) {
    A[k] = with_inner_fixed(f[k], u);
    B[k] = with_outer_fixed(g[k], t);
  }
  std::array<Poly2_Q, 3> F;
  for (std::size_t c = 1; c <= 3; ++c) {
    std::vector<Poly1_Q> coefficients;
    for (int j = 0; j <= std::max(B[0].degree(), B[c].degree()); ++j) {
      const Rational b0 = j <= B[0].degree() ? B[0][j] : Rational(0), bc = j <= B[c].degree() ? B[c][j] : Rational(0);
      coefficients.push_back(A[c] * b0 - A[0] * bc);
    }
    F[c - 1] = Poly2_Q(coefficients.begin(), coefficients.end());
  }
  const Bivariate_real_solutions fibre =
      bivariate_real_solutions({F[0], F[1], F[2]}, domain.v0, domain.v1, domain.u0, domain.u1);
  if (!fibre.decided) {
    out.reason = "the fibre is not decided: " + fibre.reason;
    return out;
  }
  for (const auto& vs : fibre.points) {
    const Rational& v = vs.first;
    Isolated_point_partners::Partner p;
    p.v = Algebraic_real(v);
    p.s = vs.second;
    p.point = phi.evaluate(CGAL::to_double(u), CGAL::to_double(v));
    if (vs.second.is_rational()) {
      const auto n1 = exact_normal(f, u, v), n2 = exact_normal(g, vs.second.rational_value(), t);
      p.tangency_decided = true;
      p.singular = is_zero_vector(n1) || is_zero_vector(n2);
      p.tangent = !p.singular && is_zero_vector({n1[1] * n2[2] - n1[2] * n2[1], n1[2] * n2[0] - n1[0] * n2[2],
                                                 n1[0] * n2[1] - n1[1] * n2[0]});
    }
    out.partners.push_back(p);
  }
  out.proved = true;
  out.reason = out.partners.empty()
                   ? "no real partner in the partner domain (the exact fibre has none)"
                   : "every real partner of the exact point, from the exact fibre";
  return out;
}

}  // namespace bezoutian

#endif  // BEZOUTIAN_LIFTING_ISOLATED_POINT_PARTNERS_H
