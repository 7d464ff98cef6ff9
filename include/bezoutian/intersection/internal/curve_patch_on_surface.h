// The curve lies on the implicit surface of the patch (det M(C(r)) == 0 with a regular implicit matrix): the
// pieces of the curve inside the patch and the isolated touching points, by the common-component routine
// (common_component.h) with the curve/boundary-curve intersections as breakpoints and kernel inversion at a
// rational point of each piece.
//
// Internal header: members of Curve_patch_engine (Curve_surface_intersection.h), not part of the public API.
#ifndef BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_PATCH_ON_SURFACE_H
#define BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_PATCH_ON_SURFACE_H

#include <bezoutian/intersection/Curve_surface_intersection.h>

#include <bezoutian/intersection/internal/common_component.h>

#include <utility>
#include <vector>

namespace bezoutian {
namespace internal {
namespace cs {

// C([0,1]) is in the algebraic surface. The set {r : C(r) in Phi([0,1]^2)} can change only where C meets the
// image of the boundary of [0,1]^2 (where Phi is a local homeomorphism onto the surface): breakpoints are
// r = 0, 1 and the parameters of the curve/boundary-curve intersections (intersect_curves, exact); each piece
// between consecutive breakpoints is decided at a rational point by kernel inversion.
inline void Curve_patch_engine::on_surface_case(Curve_patch_intersection_result& res) const {
  std::vector<Break> br{Break{Algebraic_real(0), {}}, Break{Algebraic_real(1), {}}};
  for (int side = 0; side < 4; ++side) {
    const Curve b = patch_.boundary_curve<Curve>(side);
    auto uv = [side](const Algebraic_real& t) {
      switch (side) {
        case 0: return std::make_pair(t, Algebraic_real(0));
        case 1: return std::make_pair(Algebraic_real(1), t);
        case 2: return std::make_pair(t, Algebraic_real(1));
        default: return std::make_pair(Algebraic_real(0), t);
      }
    };
    const Curve_intersection_result ci = intersect_curves(curve_, b);
    for (const auto& p : ci.points) br.push_back(Break{p.s, {uv(p.t)}});
    for (const auto& o : ci.overlaps) {
      br.push_back(Break{o.s0, {uv(o.t0)}});
      br.push_back(Break{o.s1, {uv(o.t1)}});
    }
  }
  const Common_component<std::pair<Algebraic_real, Algebraic_real>> cc = common_component(
      std::move(br), [this](const Algebraic_real& a, const Algebraic_real& b) { return piece_covered(a, b); });
  const std::vector<Break>& ub = cc.breaks;
  const std::vector<char>& covered = cc.covered;
  for (const auto& run : cc.runs) res.overlaps.push_back({ub[run.first].x, ub[run.second].x});
  // Breakpoints outside every overlap that lie on the patch: isolated touching points.
  for (std::size_t i = 0; i < ub.size(); ++i) {
    const bool in_overlap = (i > 0 && covered[i - 1]) || (i + 1 < ub.size() && covered[i]);
    if (in_overlap) continue;
    std::vector<std::pair<Algebraic_real, Algebraic_real>> uv = ub[i].partners;
    if (uv.empty() && ub[i].x.is_rational()) uv = preimages(curve_(ub[i].x.rational_value()));
    for (const auto& w : uv) {
      add_point(res, ub[i].x, w.first, w.second, 0);
      res.points.back().tangent = false;
    }
  }
}

inline bool Curve_patch_engine::piece_covered(const Algebraic_real& a, const Algebraic_real& b) const {
  Rational m = piece_midpoint(a, b);
  // a few rational points of the open piece, in case the first one is a singular point of the surface
  for (int attempt = 0;; ++attempt) {
    try {
      return !preimages(curve_(m)).empty();
    } catch (const Error&) {
      if (attempt >= 3) throw;
      const Algebraic_real am(m);
      m = am.rational_between(attempt % 2 == 0 ? a : b);
    }
  }
}

}  // namespace cs
}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_PATCH_ON_SURFACE_H
