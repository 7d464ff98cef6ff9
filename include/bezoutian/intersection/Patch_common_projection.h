// Two patches over one projection: Phi(u, v) and Psi(s, t) whose projections to a coordinate plane are the same map
// of the parameters, pi(Phi(u, v)) = pi(Psi(u, v)) identically, such as two height fields z = f(x, y), z = g(x, y)
// over the same square. Their Bezoutian matrix is singular for every (u, t) (each has a root at infinity in the
// eliminated variables, whatever the coordinates are mixed with), so Theorems 2-3 give no equation; the intersection
// is found directly instead.
//
// Theorem. If moreover pi o Psi is injective on [0,1]^2 (intersection/Patch_injectivity.h proves it), then for
// (u, v), (s, t) in [0,1]^2, Phi(u, v) = Psi(s, t) iff (s, t) = (u, v) and h(u, v) = 0, where
// h = Z_Phi W_Psi - Z_Psi W_Phi is the numerator of the difference of the coordinates left out by pi. Indeed
// pi(Psi(s, t)) = pi(Phi(u, v)) = pi(Psi(u, v)) forces (s, t) = (u, v), and then the last coordinates must agree.
// So the intersection curve, seen in the (u, t) plane of Surface_locus, is h(u, t) = 0 with the exact partner
// (v, s) = (t, u): every point of h = 0 in the square is genuine, and no branch can be missed.
#ifndef BEZOUTIAN_INTERSECTION_PATCH_COMMON_PROJECTION_H
#define BEZOUTIAN_INTERSECTION_PATCH_COMMON_PROJECTION_H

#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>
#include <bezoutian/intersection/Patch_injectivity.h>

#include <array>
#include <string>

namespace bezoutian {

/// Outcome of common_projection().
struct Common_projection {
  bool found = false;
  int dropped_coordinate = -1;  ///< 0, 1, 2: pi forgets x, y or z
  /// h(u, v) = Z_Phi W_Psi - Z_Psi W_Phi for the dropped coordinate Z (inner variable u, outer v); h = 0 is the
  /// intersection curve (all of the square if h is zero: the patches coincide)
  Polynomial_2<Rational> height_difference;
  std::string reason;
};

/// \brief Finds a coordinate plane onto which both patches project by the same map of their parameters, with that
/// projection of `psi` proved injective on [0,1]^2 (positive weights; no side collapsed to a point). See the
/// header's theorem for what it gives.
inline Common_projection common_projection(const Rational_bezier_patch<Rational>& phi,
                                           const Rational_bezier_patch<Rational>& psi) {
  Common_projection out;
  if (!phi.has_positive_weights() || !psi.has_positive_weights()) {
    out.reason = "not all weights are positive";
    return out;
  }
  for (int k = 0; k < 4; ++k)
    if (internal::side_collapsed(psi, k)) {
      out.reason = "a side of the second patch is collapsed to a point";
      return out;
    }
  const auto f = phi.power_form(), g = psi.power_form();  // (W, X, Y, Z), inner variable u (s), outer v (t)
  for (int drop = 2; drop >= 0; --drop) {
    bool same = true;
    for (int c = 1; c <= 3 && same; ++c)
      if (c != drop + 1) same = f[std::size_t(c)] * g[0] == g[std::size_t(c)] * f[0];
    if (!same) continue;
    std::array<Rational, 3> axis{Rational(0), Rational(0), Rational(0)};
    axis[std::size_t(drop)] = Rational(1);
    std::string why;
    if (!internal::injective_along(psi, axis, {}, why)) {
      out.reason = "the projection along " + internal::direction_text(axis) + " is common but not proved injective (" +
                   why + ")";
      continue;
    }
    out.found = true;
    out.dropped_coordinate = drop;
    out.height_difference = f[std::size_t(drop + 1)] * g[0] - g[std::size_t(drop + 1)] * f[0];
    out.reason = "both patches project along " + internal::direction_text(axis) +
                 " by the same map of their parameters, injective on the square: the intersection is h(u, t) = 0 "
                 "with the partner (v, s) = (t, u)";
    return out;
  }
  if (out.reason.empty()) out.reason = "no coordinate plane onto which both patches project by the same map";
  return out;
}

}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERSECTION_PATCH_COMMON_PROJECTION_H
