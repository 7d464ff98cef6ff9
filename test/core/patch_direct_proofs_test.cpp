// Direct proofs without elimination: injectivity of a patch (no self-intersection) and separation of two patches,
// on closed-form families of the surfaces CAD models are made of. Expected answers come from the closed forms; each
// claimed proof is also checked against dense samples of the surface, and patches that do self-intersect or meet
// must not be "proved".
#include "test_support.h"

#include <bezoutian/intersection/Patch_injectivity.h>
#include <bezoutian/intersection/Patch_separation.h>
#include <bezoutian/io/Geometry_document.h>
#include "power_patch.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

using namespace bezoutian;

namespace {

Rational_bezier_patch<> power_patch(const std::string& x, const std::string& y, const std::string& z, const std::string& w,
                                    int m, int n) {
  return bezoutian_test::rational_patch_from_power({x, y, z, w}, m, n);
}

// The smallest 3D distance between samples of the patch on an N x N grid whose parameters are at least `apart`
// away from each other (in the max norm), leaving out pairs that are both near a collapsed side. An injective
// patch keeps this bounded away from 0; a self-intersecting one brings it down to the order of the grid spacing.
double closest_distant_samples(const Rational_bezier_patch<>& P, const std::vector<int>& collapsed, int N = 48,
                               double apart = 0.15) {
  std::vector<std::array<double, 3>> x;
  std::vector<std::array<double, 2>> uv;
  for (int i = 0; i <= N; ++i)
    for (int j = 0; j <= N; ++j) {
      uv.push_back({double(i) / N, double(j) / N});
      x.push_back(P.evaluate(uv.back()[0], uv.back()[1]));
    }
  auto near_collapsed = [&](const std::array<double, 2>& p) {  // within `apart` of a collapsed side
    for (int k : collapsed)
      if ((k == 0 && p[1] < apart) || (k == 1 && p[0] > 1 - apart) || (k == 2 && p[1] > 1 - apart) ||
          (k == 3 && p[0] < apart))
        return true;
    return false;
  };
  double best = 1e300;
  for (std::size_t a = 0; a < x.size(); ++a)
    for (std::size_t b = a + 1; b < x.size(); ++b) {
      if (std::max(std::fabs(uv[a][0] - uv[b][0]), std::fabs(uv[a][1] - uv[b][1])) < apart) continue;
      if (near_collapsed(uv[a]) && near_collapsed(uv[b])) continue;
      const double d = std::hypot(x[a][0] - x[b][0], x[a][1] - x[b][1], x[a][2] - x[b][2]);
      best = std::min(best, d);
    }
  return best;
}

}  // namespace

TEST_CASE("injectivity: height fields z = f(x, y) have no self-intersection, proved", "[direct_proofs]") {
  // x, y linear: the projection to the xy-plane is the identity of the square
  const auto a = power_patch("u", "v", "u^2*v - (1/3)*v^3 + u*v", "1", 2, 3);
  // x, y nonlinear but monotone (y' = 2 - 2v vanishes on the side v = 1: the factor 1 - v of the Jacobian)
  const auto b = power_patch("u + u^2", "2*v - v^2", "u*v*(1 - u)", "1", 2, 2);
  for (const auto* P : {&a, &b}) {
    const Injectivity_proof p = prove_injective(*P);
    INFO(p.reason);
    CHECK(p.proved);
    CHECK(p.collapsed_sides.empty());
    CHECK(closest_distant_samples(*P, {}) > 0.01);
  }
}

TEST_CASE("injectivity: quadric and torus patches with base points and a pole", "[direct_proofs]") {
  // sphere octant ((1-v^2)(1-u^2), 2u(1-v^2), 2v(1+u^2)) / ((1+u^2)(1+v^2)): the side v = 1 is the north pole
  const auto octant = power_patch("(1 - v^2)*(1 - u^2)", "2*u*(1 - v^2)", "2*v*(1 + u^2)", "(1 + u^2)*(1 + v^2)", 2, 2);
  // stereographic cap over [-1/2, 1/2]^2: (2p, 2q, 1 - p^2 - q^2) / (1 + p^2 + q^2), p = u - 1/2, q = v - 1/2
  const auto cap = power_patch("2*(u - 1/2)", "2*(v - 1/2)", "1 - (u - 1/2)^2 - (v - 1/2)^2", "1 + (u - 1/2)^2 + (v - 1/2)^2", 2, 2);
  // quarter cylinder x^2 + z^2 = 1, 0 <= y <= 1
  const auto cylinder = power_patch("1 - u^2", "v*(1 + u^2)", "2*u", "1 + u^2", 2, 1);
  // quarter torus, R = 2, r = 1: ((3 + v^2)(1 - u^2), (3 + v^2) 2u, 2v (1 + u^2)) / ((1 + u^2)(1 + v^2))
  const auto torus = power_patch("(3 + v^2)*(1 - u^2)", "(3 + v^2)*2*u", "2*v*(1 + u^2)", "(1 + u^2)*(1 + v^2)", 2, 2);
  // the closed forms hold at a rational point (independent of the prover)
  const auto s = octant(Rational(1, 3), Rational(2, 5));
  CHECK(s[0] * s[0] + s[1] * s[1] + s[2] * s[2] == Rational(1));
  const auto t = torus(Rational(1, 3), Rational(2, 5));
  const Rational rho2 = t[0] * t[0] + t[1] * t[1];  // (rho - 2)^2 + z^2 = 1 with rho = sqrt(rho2): check squared form
  CHECK((rho2 + t[2] * t[2] + 3) * (rho2 + t[2] * t[2] + 3) == 16 * rho2);

  const Injectivity_proof po = prove_injective(octant);
  INFO(po.reason);
  CHECK(po.proved);
  CHECK(po.collapsed_sides == std::vector<int>{2});
  CHECK(closest_distant_samples(octant, po.collapsed_sides) > 0.01);
  for (const auto* P : {&cap, &cylinder, &torus}) {
    const Injectivity_proof p = prove_injective(*P);
    INFO(p.reason);
    CHECK(p.proved);
    CHECK(p.collapsed_sides.empty());
    CHECK(closest_distant_samples(*P, {}) > 0.01);
  }
}

TEST_CASE("injectivity: self-intersecting patches are never proved injective", "[direct_proofs]") {
  // the folded patch and the worked example of buse-elkadi-galligo-2008 §4 (a triple point) self-intersect
  for (const char* file : {"examples/data/folded_patch.json", "examples/data/bezoutian_worked_example.json"}) {
    const auto doc = io::read_geometry_file(bezoutian_test::source_file(file));
    const Injectivity_proof p = prove_injective(doc.patches.at(0));
    INFO(file << ": " << p.reason);
    CHECK_FALSE(p.proved);
  }
  // an extruded nodal cubic (t^2 - 1, t (t^2 - 1)), t = 3u - 3/2: the extrusion's line over the node t = +-1 is double
  const auto loop = power_patch("(3*u - 3/2)^2 - 1", "(3*u - 3/2)*((3*u - 3/2)^2 - 1)", "v", "1", 3, 1);
  const Injectivity_proof p = prove_injective(loop);
  INFO(p.reason);
  CHECK_FALSE(p.proved);
  // and the sampler used above sees that these patches are not injective
  CHECK(closest_distant_samples(loop, {}) < 1e-9);  // the node t = +-1 lies on the grid (u = 1/6, 5/6)
}

TEST_CASE("separation: patches apart are proved disjoint, meeting ones are not", "[direct_proofs]") {
  const auto low = power_patch("u", "v", "u*v", "1", 1, 1);
  const auto high = power_patch("u", "v", "u*v + 1/10", "1", 1, 1);
  const Separation_proof s = prove_disjoint(low, high);
  INFO(s.reason);
  CHECK(s.proved);
  // the sphere octant below the plane z = 101/100 (its pole is at z = 1)
  const auto octant = power_patch("(1 - v^2)*(1 - u^2)", "2*u*(1 - v^2)", "2*v*(1 + u^2)", "(1 + u^2)*(1 + v^2)", 2, 2);
  const auto plane = power_patch("2*u - 1/2", "2*v - 1/2", "101/100", "1", 1, 1);
  CHECK(prove_disjoint(octant, plane).proved);
  // patches that meet: z = uv and the plane z = 1/4 (they meet along u v = 1/4); the paraboloid and the strip
  const auto quarter = power_patch("u", "v", "1/4", "1", 1, 1);
  CHECK_FALSE(prove_disjoint(low, quarter).proved);
  const auto doc = io::read_geometry_file(bezoutian_test::source_file("examples/data/paraboloid_plane_strip.json"));
  CHECK_FALSE(prove_disjoint(doc.patches.at(0), doc.patches.at(1)).proved);
}
