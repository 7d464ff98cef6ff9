// The exclusion beside a shared boundary curve (lifting/internal/seam_blowup_exclusion.h), on pairs whose whole
// intersection is known in closed form: a plane continued by a parabolic cylinder (the seam alone), a quarter
// circle continued by its tangent line (the seam alone, rational), a plane continued by a crease that folds back
// and crosses it again along u = 1/2 (a genuine zero off the seam: the proof must fail), a fold back tangent to
// the plane on its own side (the seam alone, but the kernel of the Jacobian points into both domains: the method
// declines), a seam shared with another parametrization (no affine correspondence: no seam), and a paraboloid
// touching a plane quadrant at a common corner (the blow-up at a point).
#include <catch2/catch.hpp>

#include <bezoutian/lifting/internal/seam_blowup_exclusion.h>
#include "power_patch.h"

using namespace bezoutian;
using Q = Rational;
using Patch = Rational_bezier_patch<>;

namespace {
const Parameter_box unit{Q(0), Q(1), Q(0), Q(1)};

Patch plane() { return bezoutian_test::patch_from_power({"u", "v", "0"}, 1, 1); }

// the pair phi = the plane z = 0 over [0, 1]^2, psi beyond its side u = 1 (psi(0, t) = (1, t, 0) = phi(1, t))
bool only_seam(const Patch& psi, const Parameter_box& X) {
  const internal::Partner_equations eq(plane(), psi);
  const auto S = internal::shared_seam(eq, 1, Q(1), 3, Q(0), unit, unit);
  REQUIRE(S);
  CHECK(S->g0 == 0);
  CHECK(S->g1 == 1);
  internal::Exclusion_budget budget;
  return internal::only_seam_zeros(eq, *S, X, budget);
}
}  // namespace

TEST_CASE("seam blow-up: a plane continued tangentially by a parabolic cylinder meets it along the seam alone",
          "[seam]") {
  // psi(s, t) = (1 + s, t, s^2): z > 0 for s > 0, so the seam u = 1, s = 0 is the whole intersection
  const Patch psi = bezoutian_test::patch_from_power({"1+u", "v", "u^2"}, 2, 1);
  CHECK(only_seam(psi, Parameter_box{Q(3, 4), Q(1), Q(0), Q(1)}));
  CHECK(only_seam(psi, unit));
  // the box must reach the seam's side
  CHECK_FALSE(only_seam(psi, Parameter_box{Q(0), Q(1, 2), Q(0), Q(1)}));
}

TEST_CASE("seam blow-up: a quarter circle continued by its tangent line, rational, along the side t = c too",
          "[seam]") {
  // phi(u, v) = ((1 - u^2) / (1 + u^2), v, 2u / (1 + u^2)) ends at (0, v, 1) with tangent -x; psi(s, t) =
  // (-s, t, 1) continues it. The plane z = 1 touches the cylinder x^2 + z^2 = 1 along the seam only.
  const Patch phi = bezoutian_test::rational_patch_from_power({"1-u^2", "v*(1+u^2)", "2*u", "1+u^2"}, 2, 1);
  const Patch psi = bezoutian_test::patch_from_power({"-u", "v", "1"}, 1, 1);
  {
    const internal::Partner_equations eq(phi, psi);
    const auto S = internal::shared_seam(eq, 1, Q(1), 3, Q(0), unit, unit);
    REQUIRE(S);
    internal::Exclusion_budget budget;
    CHECK(internal::only_seam_zeros(eq, *S, unit, budget));
  }
  // the same pair with the roles of the parameters exchanged: phi(v, u), psi(t, s); the seam is then the side
  // t = 0 of the projection box (u, t) and the partner's side v = 1, with s = g(u) = u
  const Patch phi_t = bezoutian_test::rational_patch_from_power({"1-v^2", "u*(1+v^2)", "2*v", "1+v^2"}, 1, 2);
  const Patch psi_t = bezoutian_test::patch_from_power({"-v", "u", "1"}, 1, 1);
  const internal::Partner_equations eq(phi_t, psi_t);
  const auto S = internal::shared_seam(eq, 0, Q(0), 2, Q(1), unit, unit);
  REQUIRE(S);
  CHECK(S->fixed_x == 1);
  CHECK(S->dependent == 3);
  CHECK(S->g1 == 1);
  internal::Exclusion_budget budget;
  CHECK(internal::only_seam_zeros(eq, *S, Parameter_box{Q(0), Q(1), Q(0), Q(1, 8)}, budget));
  CHECK(internal::only_seam_zeros(eq, *S, unit, budget));
}

TEST_CASE("seam blow-up: a crease folding back across the plane leaves a genuine zero off the seam", "[seam]") {
  // psi(s, t) = (1 - s, t, s - 2 s^2) is on z = 0 again at s = 1/2: the line u = 1/2 of the plane
  const Patch psi = bezoutian_test::patch_from_power({"1-u", "v", "u-2*u^2"}, 2, 1);
  const auto p = plane()(Q(1, 2), Q(1, 3)), q = psi(Q(1, 2), Q(1, 3));
  REQUIRE(p == q);  // the zero off the seam, exactly
  CHECK_FALSE(only_seam(psi, unit));
  CHECK_FALSE(only_seam(psi, Parameter_box{Q(1, 4), Q(1), Q(0), Q(1)}));
  // next to the seam the crease is the only contact
  CHECK(only_seam(psi, Parameter_box{Q(3, 4), Q(1), Q(0), Q(1)}));
}

TEST_CASE("seam blow-up: a fold back tangent to the plane on its own side is declined", "[seam]") {
  // psi(s, t) = (1 - s, t, s^2) lies above the plane: the seam is the whole intersection, but at the seam the
  // kernel of the Jacobian (s = 1 - u, the common tangent plane) points into both domains, so the exceptional
  // divisor holds zeros of the blown-up equations and the proof is out of reach
  const Patch psi = bezoutian_test::patch_from_power({"1-u", "v", "u^2"}, 2, 1);
  CHECK_FALSE(only_seam(psi, Parameter_box{Q(3, 4), Q(1), Q(0), Q(1)}));
}

TEST_CASE("seam blow-up: a boundary curve shared with another parametrization gives no seam", "[seam]") {
  // psi(0, t) = (1, t^2, 0): the same segment as phi(1, v), with v = t^2
  const Patch psi = bezoutian_test::patch_from_power({"1+u", "v^2", "u^2"}, 2, 2);
  const internal::Partner_equations eq(plane(), psi);
  CHECK_FALSE(internal::shared_seam(eq, 1, Q(1), 3, Q(0), unit, unit));
}

TEST_CASE("corner blow-up: a paraboloid touching a plane quadrant at their common corner", "[seam]") {
  // phi(u, v) = (u, v, 0) and psi(s, t) = (-s, -t, s^2 + t^2) meet at the origin alone, each at a corner of its
  // domain, with one tangent plane there (as two diagonal patches around a vertex of a model)
  const Patch psi = bezoutian_test::patch_from_power({"-u", "-v", "u^2+v^2"}, 2, 2);
  const internal::Partner_equations eq(plane(), psi);
  const std::vector<internal::Shared_seam> corners = internal::shared_corners(eq, unit, unit, {});
  REQUIRE(corners.size() == 1);
  const internal::Shared_seam& C = corners[0];
  CHECK(C.corner);
  CHECK(C.x_value == 0);
  CHECK(C.along_value == 0);
  CHECK(C.y_value == 0);
  CHECK(C.g0 == 0);
  internal::Exclusion_budget budget;
  CHECK(internal::only_seam_zeros(eq, C, unit, budget));
  CHECK(internal::only_seam_zeros(eq, C, Parameter_box{Q(0), Q(1, 8), Q(0), Q(1, 8)}, budget));
  // a box away from the corner is not this proof's
  CHECK_FALSE(internal::only_seam_zeros(eq, C, Parameter_box{Q(1, 2), Q(1), Q(0), Q(1)}, budget));
  // the paraboloid over the same quadrant, psi(s, t) = (s, t, s^2 + t^2), also meets the plane at the corner
  // alone, but its domain and the plane's leave the corner in the same directions: declined
  const Patch same_side = bezoutian_test::patch_from_power({"u", "v", "u^2+v^2"}, 2, 2);
  const internal::Partner_equations eq2(plane(), same_side);
  const std::vector<internal::Shared_seam> c2 = internal::shared_corners(eq2, unit, unit, {});
  REQUIRE(c2.size() == 1);
  CHECK_FALSE(internal::only_seam_zeros(eq2, c2[0], unit, budget));
}

TEST_CASE("corner blow-up: corners on a collapsed side (a pole) are not isolated contacts", "[seam]") {
  // two sectors of a cone sharing its apex: phi(u, v) = (u (1 - v), u v, u), psi(s, t) = (-s (1 - t), -s t, s);
  // every point of the side u = 0 (s = 0) is the apex, so their common zeros there form a surface
  const Patch phi = bezoutian_test::patch_from_power({"u*(1-v)", "u*v", "u"}, 1, 1);
  const Patch psi = bezoutian_test::patch_from_power({"-u*(1-v)", "-u*v", "u"}, 1, 1);
  REQUIRE(phi(Q(0), Q(0)) == psi(Q(0), Q(1)));
  const internal::Partner_equations eq(phi, psi);
  CHECK(internal::shared_corners(eq, unit, unit, {}).empty());
}
