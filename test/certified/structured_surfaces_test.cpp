// Surface (self-)intersections on the structured patches CAD models are made of, where the Bezoutian of Theorems
// 2-5 is singular (det B = 0 identically): height fields, sphere patches with a pole, two height fields over one
// square. Expected answers come from the closed forms; completeness is checked against dense samples of the closed-
// form curve, in the parameter plane and in 3D.
#include <bezoutian/intersection/Surface_intersection.h>
#include <bezoutian/io/Geometry_document.h>
#include "power_patch.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

using namespace bezoutian;

namespace {

Rational_bezier_patch<> power_patch(const std::string& x, const std::string& y, const std::string& z, const std::string& w,
                                    int m, int n) {
  return bezoutian_test::rational_patch_from_power({x, y, z, w}, m, n);
}

std::size_t traced_points(const Surface_locus& L) {
  std::size_t n = 0;
  for (const auto& a : L.arcs) n += a.points.size();
  return n;
}

// The largest distance from a sample of the closed-form curve to the nearest genuine traced point: in the (u, t)
// plane and between the 3D points. `curve` maps a parameter in [0,1] to (u, t) on the true curve.
std::array<double, 2> worst_gap(const Surface_locus& L, const Rational_bezier_patch<>& phi,
                                const std::function<std::array<double, 2>(double)>& curve, int samples = 2000) {
  std::array<double, 2> worst{0, 0};
  for (int i = 0; i <= samples; ++i) {
    const auto p = curve(double(i) / samples);
    const auto x = phi.evaluate(p[0], p[1]);
    double best2 = 1e300, best3 = 1e300;
    for (const auto& a : L.arcs)
      for (const auto& q : a.points) {
        if (!q.genuine) continue;
        best2 = std::min(best2, std::hypot(q.projection[0] - p[0], q.projection[1] - p[1]));
        best3 = std::min(best3, std::hypot(q.point_3d[0] - x[0], q.point_3d[1] - x[1], q.point_3d[2] - x[2]));
      }
    worst = {std::max(worst[0], best2), std::max(worst[1], best3)};
  }
  return worst;
}

}  // namespace

TEST_CASE("structured surfaces: patches that do not self-intersect are proved so (det B = 0 identically)",
          "[surface][structured]") {
  const auto height = power_patch("u", "v", "u^2*v - (1/3)*v^3 + u*v", "1", 2, 3);
  const auto cap = power_patch("2*(u - 1/2)", "2*(v - 1/2)", "1 - (u - 1/2)^2 - (v - 1/2)^2",
                               "1 + (u - 1/2)^2 + (v - 1/2)^2", 2, 2);
  // the Bezoutian of Theorems 4-5 is singular for the height field (an exact graph over the (u, v) plane)
  CHECK(self_intersection_equation(height).is_degenerate());
  for (const auto* P : {&height, &cap}) {
    const Surface_locus L = self_intersection_locus(*P);
    INFO(L.note);
    CHECK(L.topology_computed);
    CHECK(L.topology_method == "injective projection");
    CHECK_FALSE(L.equation_computed);
    CHECK(L.topology.components.empty());
    CHECK(L.edge_lines.empty());
  }
}

TEST_CASE("structured surfaces: the sphere octant's only double points are its pole edge", "[surface][structured]") {
  // ((1-v^2)(1-u^2), 2u(1-v^2), 2v(1+u^2)) / ((1+u^2)(1+v^2)): the side v = 1 is the north pole (0, 0, 1)
  const auto octant = power_patch("(1 - v^2)*(1 - u^2)", "2*u*(1 - v^2)", "2*v*(1 + u^2)", "(1 + u^2)*(1 + v^2)", 2, 2);
  const Surface_locus L = self_intersection_locus(octant);
  INFO(L.note);
  CHECK(L.topology_computed);
  CHECK(L.topology.components.empty());
  REQUIRE(L.edge_lines.size() == 1);
  const Locus_edge_line& e = L.edge_lines[0];
  CHECK(e.side == 2);
  CHECK(e.value == Rational(1));
  CHECK(e.cause == Locus_edge_line::collapsed);
  CHECK(e.genuine);
  CHECK(e.status_proved);
  for (const auto& q : e.points) CHECK(std::hypot(q.point_3d[0], q.point_3d[1], q.point_3d[2] - 1) < 1e-12);
}

TEST_CASE("structured surfaces: two height fields over one square meet along h(u, t) = 0, every branch",
          "[surface][structured]") {
  // z = uv + v and z = uv + u^2 - u + 1/2 over x = u, y = v: they meet where v = u^2 - u + 1/2 (an open arc across
  // the square, from (0, 1/2) to (1, 1/2))
  const auto f = power_patch("u", "v", "u*v + v", "1", 2, 1);
  const auto g = power_patch("u", "v", "u*v + u^2 - u + 1/2", "1", 2, 1);
  // fine polylines, so that a sample of the true curve far from every traced point is a missing branch
  Surface_intersection_options o;
  o.subdivision.samples_per_arc = 200;  // per arc piece in one leaf box of the subdivision
  const Surface_locus L = intersection_locus(f, g, o);
  INFO(L.note);
  REQUIRE(L.topology_computed);
  CHECK(L.topology_method == "subdivision");
  REQUIRE(L.topology.components.size() == 1);
  CHECK_FALSE(L.topology.components[0].closed);
  CHECK(L.topology.number_of_boundary_points() == 2);
  REQUIRE(traced_points(L) > 0);
  for (const auto& a : L.arcs) {
    CHECK(a.undecided_fraction == 0);
    for (const auto& q : a.points) {
      CHECK(q.genuine);
      CHECK(q.status_proved);
      const double u = q.projection[0], t = q.projection[1];
      CHECK(std::fabs(t - (u * u - u + 0.5)) < 1e-8);            // on the closed-form curve
      CHECK(q.residual < 1e-8);                                   // on both surfaces
      CHECK(q.partner[0] == t);                                   // the exact partner (v, s) = (t, u)
      CHECK(q.partner[1] == u);
    }
  }
  const auto gap = worst_gap(L, f, [](double x) { return std::array<double, 2>{x, x * x - x + 0.5}; });
  CHECK(gap[0] < 0.02);
  CHECK(gap[1] < 0.02);

  // a closed loop: h = (u - 1/2)^2 + (v - 1/2)^2 - 1/16, the circle of radius 1/4 about the centre
  const auto p = power_patch("u", "v", "u*v + (u - 1/2)^2 + (v - 1/2)^2", "1", 2, 2);
  const auto q = power_patch("u", "v", "u*v + 1/16", "1", 2, 2);
  const Surface_locus C = intersection_locus(p, q, o);
  INFO(C.note);
  REQUIRE(C.topology_computed);
  REQUIRE(C.topology.components.size() == 1);
  CHECK(C.topology.components[0].closed);
  CHECK(C.topology.number_of_boundary_points() == 0);
  const auto gc = worst_gap(C, p, [](double x) {
    return std::array<double, 2>{0.5 + 0.25 * std::cos(2 * M_PI * x), 0.5 + 0.25 * std::sin(2 * M_PI * x)};
  });
  CHECK(gc[0] < 0.02);
  CHECK(gc[1] < 0.02);
}

TEST_CASE("structured surfaces: height fields apart, patches apart, coincident height fields", "[surface][structured]") {
  // parallel height fields 1/10 apart: h = -1/10, a nonzero constant: no intersection, proved
  const auto low = power_patch("u", "v", "u*v", "1", 1, 1);
  const auto high = power_patch("u", "v", "u*v + 1/10", "1", 1, 1);
  const Surface_locus L = intersection_locus(low, high);
  INFO(L.note);
  CHECK(L.topology_computed);
  CHECK(L.topology.components.empty());
  // the sphere octant below the plane z = 101/100: its hull is apart from the plane
  const auto octant = power_patch("(1 - v^2)*(1 - u^2)", "2*u*(1 - v^2)", "2*v*(1 + u^2)", "(1 + u^2)*(1 + v^2)", 2, 2);
  const auto plane = power_patch("2*u - 1/2", "2*v - 1/2", "101/100", "1", 1, 1);
  const Surface_locus S = intersection_locus(octant, plane);
  INFO(S.note);
  CHECK(S.topology_computed);
  CHECK(S.topology_method == "separated hulls");
  CHECK(S.topology.components.empty());
  // one height field twice: the patches coincide, an overlap (proved), reported as such
  CHECK_THROWS_WITH(intersection_locus(low, low), Catch::Contains("the patches coincide"));
}
