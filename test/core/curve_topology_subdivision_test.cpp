// Certified topology of D = 0 by Bernstein subdivision (Curve_topology_by_subdivision.h). Expected topologies come
// from curves known in closed form (circles, ellipses, lines, a loop of diameter 1e-4, curves through domain
// corners); singular configurations must be reported as not certified, never guessed.
#include <catch2/catch.hpp>

#include <bezoutian/Curve_topology_by_subdivision.h>

using namespace bezoutian;
using Q = Rational;
using P2 = Polynomial_2<Integer>;

namespace {
const P2 u = CGAL::shift(P2(1), 1, 0), v = CGAL::shift(P2(1), 1, 1);
Parameter_box box(Q u0, Q u1, Q v0, Q v1) { return Parameter_box{u0, u1, v0, v1}; }
std::size_t closed_components(const Curve_topology_in_box& t) {
  std::size_t n = 0;
  for (const auto& c : t.components) n += c.closed;
  return n;
}
// every sample point lies on the curve (scaled residual) and inside the box
void check_samples(const P2& D, const Curve_topology_in_box& t, double tol) {
  for (const auto& e : t.edges)
    for (const auto& p : e.polyline) {
      CHECK(p[0] >= CGAL::to_double(t.box.u0) - 1e-12);
      CHECK(p[0] <= CGAL::to_double(t.box.u1) + 1e-12);
      CHECK(p[1] >= CGAL::to_double(t.box.v0) - 1e-12);
      CHECK(p[1] <= CGAL::to_double(t.box.v1) + 1e-12);
      double val = 0, scale = 0;
      for (int j = D.degree(); j >= 0; --j) {
        double c = 0, s = 0;
        for (int i = D[j].degree(); i >= 0; --i) {
          c = c * p[0] + CGAL::to_double(D[j][i]);
          s = s * std::abs(p[0]) + std::abs(CGAL::to_double(D[j][i]));
        }
        val = val * p[1] + c;
        scale = scale * std::abs(p[1]) + s;
      }
      CHECK(std::abs(val) <= tol * scale);
    }
}
}  // namespace

TEST_CASE("subdivision: circles and ellipses inside the unit square are closed components", "[topology][subdivision]") {
  // (u-1/2)^2 + (v-1/2)^2 = 1/16
  const P2 circle = 16 * u * u - 16 * u + 16 * v * v - 16 * v + 7;
  auto r = subdivide_curve_in_box(circle, Parameter_box{});
  REQUIRE(r.certified);
  CHECK(r.topology.components.size() == 1);
  CHECK(closed_components(r.topology) == 1);
  CHECK(r.topology.number_of_boundary_points() == 0);
  CHECK(r.topology.number_of_singular_points() == 0);
  check_samples(circle, r.topology, 1e-9);
  // two disjoint ellipses: 2 closed components
  const P2 a = 100 * (4 * u - 1) * (4 * u - 1) + 400 * (2 * v - 1) * (2 * v - 1) - 81;  // centre (1/4, 1/2)
  const P2 b = 400 * (4 * u - 3) * (4 * u - 3) + 100 * (2 * v - 1) * (2 * v - 1) - 81;  // centre (3/4, 1/2)
  r = subdivide_curve_in_box(a * b, Parameter_box{});
  REQUIRE(r.certified);
  CHECK(r.topology.components.size() == 2);
  CHECK(closed_components(r.topology) == 2);
  check_samples(a * b, r.topology, 1e-9);
}

TEST_CASE("subdivision: a closed loop of diameter 1e-4 (smaller than 1e-3 of the domain) is found",
          "[topology][subdivision]") {
  // 10^8 ((2u-1)^2 + (2v-1)^2) = 1: a circle of radius 5e-5 around (1/2, 1/2)
  const P2 tiny = 100000000 * ((2 * u - 1) * (2 * u - 1) + (2 * v - 1) * (2 * v - 1)) - 1;
  auto r = subdivide_curve_in_box(tiny, Parameter_box{});
  REQUIRE(r.certified);
  REQUIRE(r.topology.components.size() == 1);
  CHECK(r.topology.components[0].closed);
  for (const auto& x : r.topology.vertices) {
    CHECK(std::abs(x.u - 0.5) < 6e-5);
    CHECK(std::abs(x.v - 0.5) < 6e-5);
  }
  // the same loop off-centre, inside a box that is not the unit square
  const P2 off = 100000000 * ((3 * u - 1) * (3 * u - 1) + (7 * v - 2) * (7 * v - 2)) - 9;
  r = subdivide_curve_in_box(off, box(Q(-1), Q(2), Q(-3), Q(1, 2)));
  REQUIRE(r.certified);
  CHECK(closed_components(r.topology) == 1);
}

TEST_CASE("subdivision: curves meeting the boundary, through domain corners", "[topology][subdivision]") {
  // the diagonal u = v through the corners (0,0) and (1,1): one open arc, two boundary points
  auto r = subdivide_curve_in_box(u - v, Parameter_box{});
  REQUIRE(r.certified);
  REQUIRE(r.topology.components.size() == 1);
  CHECK_FALSE(r.topology.components[0].closed);
  CHECK(r.topology.number_of_boundary_points() == 2);
  // the anti-diagonal u + v = 1 (corners (0,1), (1,0)); a parabola in a box that cuts off its vertex
  r = subdivide_curve_in_box(u + v - 1, Parameter_box{});
  REQUIRE(r.certified);
  CHECK(r.topology.number_of_boundary_points() == 2);
  const P2 parabola = v - (2 * u - 1) * (2 * u - 1);  // crosses the top edge at u = 0, 1 and the bottom edge twice
  r = subdivide_curve_in_box(parabola, box(Q(-1, 10), Q(11, 10), Q(1, 10), Q(1)));
  REQUIRE(r.certified);
  CHECK(r.topology.components.size() == 2);  // the vertex (1/2, 0) is below the box: two arcs
  CHECK(r.topology.number_of_boundary_points() == 4);
  // a quarter circle around the corner (0,0): one arc from the bottom edge to the left edge
  r = subdivide_curve_in_box(4 * u * u + 4 * v * v - 1, Parameter_box{});
  REQUIRE(r.certified);
  CHECK(r.topology.components.size() == 1);
  CHECK(r.topology.number_of_boundary_points() == 2);
  // a curve outside the box: nothing, proved
  r = subdivide_curve_in_box(u * u + v * v + 1, Parameter_box{});
  REQUIRE(r.certified);
  CHECK(r.topology.components.empty());
}

TEST_CASE("subdivision: singular and isolated points are not certified (the caller needs an exact analysis)",
          "[topology][subdivision]") {
  // a node at (1/2, 1/2)
  auto r = subdivide_curve_in_box((u - v) * (u + v - 1), Parameter_box{});
  CHECK_FALSE(r.certified);
  CHECK_FALSE(r.reason.empty());
  REQUIRE_FALSE(r.unresolved.empty());
  for (const auto& b : r.unresolved) {
    CHECK(b.u0 <= Q(1, 2));
    CHECK(Q(1, 2) <= b.u1);
    CHECK(b.v0 <= Q(1, 2));
    CHECK(Q(1, 2) <= b.v1);
  }
  // an isolated real point (acnode) at (1/3, 1/3)
  r = subdivide_curve_in_box((3 * u - 1) * (3 * u - 1) + (3 * v - 1) * (3 * v - 1), Parameter_box{});
  CHECK_FALSE(r.certified);
  // two circles crossing: two nodes
  const P2 c1 = 16 * u * u - 16 * u + 16 * v * v - 16 * v + 7, c2 = 4 * u * u + 4 * v * v - 1;
  r = subdivide_curve_in_box(c1 * c2, Parameter_box{});
  CHECK_FALSE(r.certified);
  // bad input
  CHECK_THROWS_AS(subdivide_curve_in_box(P2(0), Parameter_box{}), Invalid_input);
  CHECK_THROWS_AS(subdivide_curve_in_box(u, box(Q(1), Q(0), Q(0), Q(1))), Invalid_input);
}
