// Certified topology of D = 0 in a box (arrangement with CGAL's algebraic segment traits). Expected
// topologies are those of classical curves known in closed form, and of the worked example of
// buse-elkadi-galligo-2008 §4 (three branches through the triple point near (-1.05, -0.049)).
#include <catch2/catch.hpp>

#include "test_support.h"

#include <bezoutian/topology/Cgal_curve_analysis.h>
#include <bezoutian/elimination/Implicit_equation.h>
#include <bezoutian/topology/matrix_zero_points.h>
#include <bezoutian/io/Geometry_document.h>

using namespace bezoutian;
using Q = Rational;
using P2 = Polynomial_2<Integer>;

namespace {
const P2 u = CGAL::shift(P2(1), 1, 0), v = CGAL::shift(P2(1), 1, 1);
Parameter_box box(Q u0, Q u1, Q v0, Q v1) { return Parameter_box{u0, u1, v0, v1}; }
}  // namespace

TEST_CASE("three-leaf rose: one closed component with a triple point", "[topology]") {
  // (u^2+v^2)^2 + 3u^2 v - v^3 = 0: three petals meeting at the origin with three distinct tangents.
  const P2 rose = CGAL::ipower(u * u + v * v, 2) + 3 * u * u * v - v * v * v;
  auto t = analyse_curve_in_box(rose, box(Q(-2), Q(2), Q(-2), Q(2)));
  REQUIRE(t.components.size() == 1);
  CHECK(t.components[0].closed);
  REQUIRE(t.number_of_singular_points() == 1);
  for (const auto& x : t.vertices)
    if (x.kind == Curve_topology_vertex::singular) {
      CHECK(x.branches == 3);
      CHECK(x.half_branches == 6);
      CHECK(std::abs(x.u) < 1e-9);
      CHECK(std::abs(x.v) < 1e-9);
    }
  CHECK(t.number_of_boundary_points() == 0);
  // a small box around the origin: three branches crossing it, six boundary points, one component
  auto s = analyse_curve_in_box(rose, box(Q(-1, 10), Q(1, 10), Q(-1, 10), Q(1, 10)));
  CHECK(s.components.size() == 1);
  CHECK_FALSE(s.components[0].closed);
  CHECK(s.number_of_boundary_points() == 6);
  CHECK(s.number_of_singular_points() == 1);
}

TEST_CASE("a loop of diameter 1e-4 inside the unit square is found", "[topology]") {
  // 4e8 (4u^2 - 4u + 4v^2 - 4v + 2) - 4 = 16e8 r^2 - 4 with r the distance to (1/2,1/2): a circle of radius
  // 5e-5, far below any sampling step.
  const P2 c = P2(400000000) * (4 * u * u - 4 * u + 4 * v * v - 4 * v + 2) - P2(4);
  auto t = analyse_curve_in_box(c, Parameter_box{}, 1e-10);
  REQUIRE(t.components.size() == 1);
  CHECK(t.components[0].closed);
  CHECK(t.number_of_boundary_points() == 0);
  CHECK(t.number_of_singular_points() == 0);
  for (const auto& e : t.edges)
    for (const auto& p : e.polyline) CHECK(std::hypot(p[0] - 0.5, p[1] - 0.5) == Approx(5e-5).epsilon(1e-3));
}

TEST_CASE("an isolated real point and a curve through a box corner", "[topology]") {
  auto t = analyse_curve_in_box(u * u + v * v, box(Q(-1), Q(1), Q(-1), Q(1)));
  REQUIRE(t.components.size() == 1);
  CHECK(t.components[0].isolated_point);
  CHECK(t.vertices[0].kind == Curve_topology_vertex::isolated);
  // the line u = v through the corners (0,0) and (1,1) of the unit square
  auto d = analyse_curve_in_box(u - v, Parameter_box{});
  REQUIRE(d.components.size() == 1);
  CHECK_FALSE(d.components[0].closed);
  CHECK(d.number_of_boundary_points() == 2);
  // a curve outside the box: nothing
  auto o = analyse_curve_in_box(u * u + v * v - 100, Parameter_box{});
  CHECK(o.components.empty());
}

TEST_CASE("worked example: three branches through the triple point near (-1.047, -0.0489)", "[topology][seed]") {
  auto doc = io::read_geometry_file(bezoutian_test::source_file("examples/data/bezoutian_worked_example.json"));
  Implicit_equation e = self_intersection_equation(doc.patches[0]);
  auto t = analyse_curve_in_box(e.square_free, box(Q(-11, 10), Q(-1), Q(-1, 10), Q(0)));
  REQUIRE(t.number_of_singular_points() == 1);
  for (const auto& x : t.vertices)
    if (x.kind == Curve_topology_vertex::singular) {
      CHECK(x.branches == 3);
      // shared/notes: (-1.0470947234032030127, -0.0488563631290503188)
      CHECK(x.u == Approx(-1.0470947234032030127).epsilon(1e-12));
      CHECK(x.v == Approx(-0.0488563631290503188).epsilon(1e-10));
      CHECK(x.u_lo <= -1.0470947234032030127);
      CHECK(-1.0470947234032030127 <= x.u_hi);
    }
  // The 3 x 3 Bezoutian matrix vanishes entirely at the triple point (so det B has multiplicity 3 there): its
  // common zeros in the box are that point alone, and the subdivision resolves it by blowing it up, with the same
  // topology as CGAL's whole-plane analysis above.
  const auto zeros = internal::matrix_zero_points(e, box(Q(-11, 10), Q(-1), Q(-1, 10), Q(0)));
  REQUIRE(zeros.size() == 1);
  CHECK(zeros[0].multiplicity == 3);
  CHECK(CGAL::to_double(zeros[0].enclosure.u0) == Approx(-1.0470947234032030127).epsilon(1e-15));
  CHECK(CGAL::to_double(zeros[0].enclosure.v0) == Approx(-0.0488563631290503188).epsilon(1e-14));
  for (const auto& row : e.matrix.entries)  // every entry is (nearly) zero at the enclosure's corner (width ~1e-87)
    for (const auto& entry : row) {
      Rational val(0);
      for (int j = entry.degree(); j >= 0; --j) {
        Rational c(0);
        for (int i = entry[j].degree(); i >= 0; --i) c = c * zeros[0].enclosure.u0 + entry[j][i];
        val = val * zeros[0].enclosure.v0 + c;
      }
      CHECK(CGAL::abs(val) < Q(1, Integer(1) << 200));
    }
  Subdivision_topology_options o;
  o.multiple_points = zeros;
  const auto s = subdivide_curve_in_box(e.square_free, box(Q(-11, 10), Q(-1), Q(-1, 10), Q(0)), o);
  REQUIRE(s.certified);
  CHECK(s.topology.vertices.size() == t.vertices.size());
  CHECK(s.topology.edges.size() == t.edges.size());
  CHECK(s.topology.components.size() == t.components.size());
  CHECK(s.topology.number_of_boundary_points() == t.number_of_boundary_points());
  REQUIRE(s.topology.number_of_singular_points() == 1);
  for (const auto& x : s.topology.vertices)
    if (x.kind == Curve_topology_vertex::singular) {
      CHECK(x.branches == 3);
      CHECK(x.u_lo <= -1.0470947234032030127);
      CHECK(-1.0470947234032030127 <= x.u_hi);
    }
}
