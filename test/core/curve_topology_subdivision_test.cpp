// Certified topology of D = 0 by Bernstein subdivision (topology/Curve_topology_by_subdivision.h). Expected
// topologies come from curves known in closed form (circles, ellipses, lines, a loop of diameter 1e-4, curves through
// domain corners); singular configurations must be reported as not certified, never guessed.
#include <catch2/catch.hpp>

#include <bezoutian/topology/Curve_topology_by_subdivision.h>
#include <bezoutian/intersection/internal/box_edge_lines.h>
#include <bezoutian/arithmetic/interval_krawczyk.h>

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
// The thin loop 2^(2e) w^2 = 1 - 4 (2u - 1)^2 along the parabola w = 4v - 1 - u - u^2 = 0: |w| = 2^-e sqrt(1 - 4 (2u -
// 1)^2), u in [1/4, 3/4]. One closed component, every sample on one of the two branches (within tol), both traced,
// the whole u-extent (to within `extent`).
Subdivision_topology_result check_parabola_loop(int e, double tol, double extent) {
  const P2 w = 4 * v - 1 - u - u * u;
  const P2 loop = CGAL::ipower(P2(2), 2 * e) * w * w - 1 + 4 * (2 * u - 1) * (2 * u - 1);
  auto r = subdivide_curve_in_box(loop, Parameter_box{});
  INFO(r.reason);
  REQUIRE(r.certified);
  CHECK(r.topology.components.size() == 1);
  CHECK(closed_components(r.topology) == 1);
  CHECK(r.topology.number_of_singular_points() == 0);
  CHECK(r.topology.number_of_boundary_points() == 0);
  check_samples(loop, r.topology, 1e-9);
  double lo = 1, hi = 0;
  std::size_t above = 0, below = 0;
  for (const auto& ed : r.topology.edges)
    for (const auto& p : ed.polyline) {
      const double x = p[0], W = 4 * p[1] - 1 - x - x * x, half = std::ldexp(std::sqrt(std::max(0.0, 1 - 4 * (2 * x - 1) * (2 * x - 1))), -e);
      CHECK(std::fabs(std::fabs(W) - half) < tol);
      (W > 0 ? above : below) += std::fabs(x - 0.5) < 0.2;
      lo = std::min(lo, x), hi = std::max(hi, x);
    }
  CHECK(above > 10);
  CHECK(below > 10);
  CHECK(lo < 0.25 + extent);
  CHECK(hi > 0.75 - extent);
  return r;
}

// Two nodes at the rational points (1/3, 13/36) and (2/3, 19/36), joined by the branches w = +-2^-k (3u-1)(3u-2)
// (w = 4v - 1 - u - u^2), which cross there at 2 * 3 * 2^-k / 4 rad and continue to the edges u = 0 and u = 1: one
// component, 4 boundary points, 6 edges; the node enclosures hold the exact nodes; every sample on a branch.
Subdivision_topology_result check_parabola_nodes(int k) {
  const P2 w = 4 * v - 1 - u - u * u;
  const P2 nodes = CGAL::ipower(P2(2), 2 * k) * w * w - (3 * u - 1) * (3 * u - 1) * (3 * u - 2) * (3 * u - 2);
  auto r = subdivide_curve_in_box(nodes, Parameter_box{});
  INFO(r.reason);
  REQUIRE(r.certified);
  CHECK(r.topology.components.size() == 1);
  CHECK(closed_components(r.topology) == 0);
  CHECK(r.topology.number_of_boundary_points() == 4);
  CHECK(r.topology.edges.size() == 6);
  REQUIRE(r.topology.number_of_singular_points() == 2);
  for (const auto& x : r.topology.vertices)
    if (x.kind == Curve_topology_vertex::singular) {
      CHECK(x.branches == 2);
      const bool first = x.u < 0.5;
      const double pu = first ? 1.0 / 3 : 2.0 / 3, pv = first ? 13.0 / 36 : 19.0 / 36;
      CHECK(x.u_lo <= pu);
      CHECK(pu <= x.u_hi);
      CHECK(x.v_lo <= pv);
      CHECK(pv <= x.v_hi);
    }
  check_samples(nodes, r.topology, 1e-9);
  std::size_t above = 0, below = 0;
  for (const auto& ed : r.topology.edges)
    for (const auto& p : ed.polyline) {
      const double W = 4 * p[1] - 1 - p[0] - p[0] * p[0], half = std::ldexp(std::fabs((3 * p[0] - 1) * (3 * p[0] - 2)), -k);
      CHECK(std::fabs(std::fabs(W) - half) < 1e-9);
      if (p[0] > 0.4 && p[0] < 0.6) (W > 0 ? above : below) += 1;
    }
  CHECK(above > 0);  // both branches are traced between the nodes
  CHECK(below > 0);
  return r;
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

TEST_CASE("subdivision: curves tangent to a domain edge, from inside and from outside", "[topology][subdivision]") {
  auto touching = [](const Curve_topology_in_box& t) {
    std::vector<const Curve_topology_vertex*> r;
    for (const auto& x : t.vertices)
      if (x.tangent_to_boundary) r.push_back(&x);
    return r;
  };
  // v = (u - 1/2)^2 touches the edge v = 0 at (1/2, 0) from inside: one arc from (0, 1/4) through the contact to
  // (1, 1/4), i.e. two edges and three boundary points, the contact with two arcs
  auto r = subdivide_curve_in_box(4 * v - (2 * u - 1) * (2 * u - 1), Parameter_box{});
  REQUIRE(r.certified);
  REQUIRE(r.topology.components.size() == 1);
  CHECK_FALSE(r.topology.components[0].closed);
  CHECK(r.topology.edges.size() == 2);
  CHECK(r.topology.number_of_boundary_points() == 3);
  auto t = touching(r.topology);
  REQUIRE(t.size() == 1);
  CHECK(t[0]->kind == Curve_topology_vertex::boundary);
  CHECK(t[0]->u_lo <= 0.5);
  CHECK(t[0]->u_hi >= 0.5);
  CHECK(t[0]->v == 0);
  check_samples(4 * v - (2 * u - 1) * (2 * u - 1), r.topology, 1e-12);
  // v = -(u - 1/3)^2 (the edge v = 0 from outside) times u = (v - 2/5)^2 (the edge u = 0 from inside, at
  // v = 2/5): the first curve meets the closed square in (1/3, 0) only, an isolated point; the second runs from
  // (4/25, 0) through the contact (0, 2/5) to (9/25, 1).
  const P2 below = 9 * v + (3 * u - 1) * (3 * u - 1), right = 25 * u - (5 * v - 2) * (5 * v - 2);
  r = subdivide_curve_in_box(below * right, Parameter_box{});
  REQUIRE(r.certified);
  t = touching(r.topology);
  REQUIRE(t.size() == 2);
  std::size_t isolated = 0, arcs = 0;
  for (const auto& c : r.topology.components) {
    isolated += c.isolated_point;
    if (!c.isolated_point) arcs += c.edges.size();
    CHECK_FALSE(c.closed);
  }
  CHECK(isolated == 1);
  CHECK(arcs == 2);  // (4/25, 0) -> (0, 2/5) -> (9/25, 1)
  for (const auto* x : t) {
    if (x->kind == Curve_topology_vertex::isolated) {
      CHECK(x->u_lo <= 1.0 / 3);
      CHECK(x->u_hi >= 1.0 / 3);
      CHECK(x->v == 0);
    } else {
      CHECK(x->kind == Curve_topology_vertex::boundary);
      CHECK(x->u == 0);
      CHECK(x->v_lo <= 0.4);
      CHECK(x->v_hi >= 0.4);
    }
  }
  CHECK(r.topology.number_of_boundary_points() == 4);
  // odd contact (an inflection on the edge): v = (u - 1/2)^3 crosses v = 0 tangentially, one arc
  r = subdivide_curve_in_box(8 * v - (2 * u - 1) * (2 * u - 1) * (2 * u - 1), Parameter_box{});
  REQUIRE(r.certified);
  CHECK(r.topology.components.size() == 1);
  CHECK(touching(r.topology).empty());
  CHECK(r.topology.number_of_boundary_points() == 2);
}

namespace {
// the vertex exactly at the domain corner (cu, cv), or null
const Curve_topology_vertex* corner_vertex(const Curve_topology_in_box& t, double cu, double cv) {
  for (const auto& x : t.vertices)
    if (x.u_lo == cu && x.u_hi == cu && x.v_lo == cv && x.v_hi == cv) return &x;
  return nullptr;
}
// the only component is the domain corner (cu, cv) alone: an isolated point on the boundary
void check_isolated_corner(const Subdivision_topology_result& r, double cu, double cv, bool tangent) {
  REQUIRE(r.certified);
  REQUIRE(r.topology.components.size() == 1);
  CHECK(r.topology.components[0].isolated_point);
  const Curve_topology_vertex* c = corner_vertex(r.topology, cu, cv);
  REQUIRE(c != nullptr);
  CHECK(c->kind == Curve_topology_vertex::isolated);
  CHECK(c->on_boundary);
  CHECK(c->tangent_to_boundary == tangent);
}
}  // namespace

TEST_CASE("subdivision: curves tangent to a domain edge at a domain corner, and curves touching a corner only",
          "[topology][subdivision]") {
  // u = 1 - (v - 1)^2 / 2: tangent to the edge u = 1 at the corner (1, 1) and inside the square below it; one arc
  // from that corner to (1/2, 0)
  const P2 in_right = 2 * (u - 1) + (v - 1) * (v - 1);
  auto r = subdivide_curve_in_box(in_right, Parameter_box{});
  REQUIRE(r.certified);
  REQUIRE(r.topology.components.size() == 1);
  CHECK_FALSE(r.topology.components[0].isolated_point);
  CHECK(r.topology.number_of_boundary_points() == 2);
  const Curve_topology_vertex* c = corner_vertex(r.topology, 1, 1);
  REQUIRE(c != nullptr);
  CHECK(c->kind == Curve_topology_vertex::boundary);
  CHECK(c->tangent_to_boundary);
  REQUIRE(corner_vertex(r.topology, 0.5, 0) != nullptr);
  CHECK_FALSE(corner_vertex(r.topology, 0.5, 0)->tangent_to_boundary);
  check_samples(in_right, r.topology, 1e-12);
  // u = 1 + (v - 1)^2 / 2: the same contact from outside; only the corner is in the square, an isolated point
  r = subdivide_curve_in_box(2 * (u - 1) - (v - 1) * (v - 1), Parameter_box{});
  check_isolated_corner(r, 1, 1, true);
  // v = u^2 / 3: tangent to the edge v = 0 at the corner (0, 0); one arc to (1, 1/3)
  const P2 in_bottom = 3 * v - u * u;
  r = subdivide_curve_in_box(in_bottom, Parameter_box{});
  REQUIRE(r.certified);
  REQUIRE(r.topology.components.size() == 1);
  CHECK(r.topology.number_of_boundary_points() == 2);
  c = corner_vertex(r.topology, 0, 0);
  REQUIRE(c != nullptr);
  CHECK(c->kind == Curve_topology_vertex::boundary);
  CHECK(c->tangent_to_boundary);
  check_samples(in_bottom, r.topology, 1e-12);
  // u + v = 0 crosses the corner (0, 0) transversally from outside: the corner alone, not a tangency
  r = subdivide_curve_in_box(u + v, Parameter_box{});
  check_isolated_corner(r, 0, 0, false);
  // v = (2u - 1)^2 crosses the corners (0, 1) and (1, 1) transversally (and touches v = 0 at (1/2, 0) from inside)
  r = subdivide_curve_in_box(v - (2 * u - 1) * (2 * u - 1), Parameter_box{});
  REQUIRE(r.certified);
  CHECK(r.topology.number_of_boundary_points() == 3);
  c = corner_vertex(r.topology, 1, 1);
  REQUIRE(c != nullptr);
  CHECK_FALSE(c->tangent_to_boundary);
}

TEST_CASE("subdivision: an ordinary node and an isolated point at rational points are certified exactly",
          "[topology][subdivision]") {
  // the diagonals of the unit square cross at (1/2, 1/2): one component, four boundary points (the domain corners)
  const P2 X = (u - v) * (u + v - 1);
  auto r = subdivide_curve_in_box(X, Parameter_box{});
  REQUIRE(r.certified);
  CHECK(r.topology.components.size() == 1);
  CHECK(r.topology.number_of_boundary_points() == 4);
  REQUIRE(r.topology.number_of_singular_points() == 1);
  for (const auto& w : r.topology.vertices)
    if (w.kind == Curve_topology_vertex::singular) {
      CHECK(w.branches == 2);
      CHECK(w.u_lo <= 0.5);
      CHECK(0.5 <= w.u_hi);
      CHECK(w.v_lo <= 0.5);
      CHECK(0.5 <= w.v_hi);
    }
  check_samples(X, r.topology, 1e-9);
  // an acnode at (1/3, 1/3) and a circle around (3/4, 3/4) of radius 1/8: two components, one an isolated point
  const P2 A = ((3 * u - 1) * (3 * u - 1) + (3 * v - 1) * (3 * v - 1)) *
               ((8 * u - 6) * (8 * u - 6) + (8 * v - 6) * (8 * v - 6) - 1);
  r = subdivide_curve_in_box(A, Parameter_box{});
  REQUIRE(r.certified);
  REQUIRE(r.topology.components.size() == 2);
  std::size_t isolated = 0;
  for (const auto& c : r.topology.components) isolated += c.isolated_point;
  CHECK(isolated == 1);
  CHECK(closed_components(r.topology) == 2);
  // a figure eight (lemniscate of Gerono, centred at (1/2, 1/2)): one closed component through one node
  const P2 x = 4 * u - 2, y = 4 * v - 2;  // x^4 = x^2 - y^2 in coordinates scaled to the box
  const P2 G = x * x * x * x - x * x + y * y;
  r = subdivide_curve_in_box(G, Parameter_box{});
  REQUIRE(r.certified);
  CHECK(r.topology.components.size() == 1);
  CHECK(closed_components(r.topology) == 1);
  CHECK(r.topology.number_of_singular_points() == 1);
  check_samples(G, r.topology, 1e-9);
}

TEST_CASE("subdivision: irrational nodes are certified by a witness, and not certified without one",
          "[topology][subdivision]") {
  // two circles crossing at two irrational points (u + v = 11/16, u^2 + v^2 = 1/4)
  const P2 c1 = 16 * u * u - 16 * u + 16 * v * v - 16 * v + 7, c2 = 4 * u * u + 4 * v * v - 1;
  auto r = subdivide_curve_in_box(c1 * c2, Parameter_box{});
  CHECK_FALSE(r.certified);
  CHECK(r.reason.find("could not be proved") != std::string::npos);
  // witness: Krawczyk's test proves a transversal common point of c1 = 0 and c2 = 0 in the box (two branches with
  // distinct tangents through it), independently of the subdivision's own analysis
  int calls = 0;
  Subdivision_topology_options o;
  o.singular_point_witness = [&](const Parameter_box& b, const std::array<double, 2>& p) {
    ++calls;
    using I = internal::Mpfi_interval;
    std::array<I, 2> X{I::hull(Q(p[0] - 1e-6), Q(p[0] + 1e-6), 128), I::hull(Q(p[1] - 1e-6), Q(p[1] + 1e-6), 128)};
    auto ev = [](const P2& f, const I& x, const I& y) {
      I r = I::point(0, 128);
      for (int j = f.degree(); j >= 0; --j) r = r * y + I::horner(f[j], x);
      return r;
    };
    auto value = [&](const std::array<I, 2>& c, std::array<I, 2>& F) {
      F[0] = ev(c1, c[0], c[1]);
      F[1] = ev(c2, c[0], c[1]);
    };
    auto jac = [&](const std::array<I, 2>& Z, std::vector<std::vector<I>>& J) {
      J[0][0] = ev(CGAL::differentiate(c1), Z[0], Z[1]);  // d/du: the inner variable
      J[0][1] = ev(CGAL::canonicalize(CGAL::differentiate(CGAL::swap(c1, 0, 1))), Z[1], Z[0]);
      J[1][0] = ev(CGAL::differentiate(c2), Z[0], Z[1]);
      J[1][1] = ev(CGAL::canonicalize(CGAL::differentiate(CGAL::swap(c2, 0, 1))), Z[1], Z[0]);
    };
    return internal::krawczyk_prove<2>(X, value, jac) && X[0].strictly_inside(I::hull(b.u0, b.u1, 128)) &&
           X[1].strictly_inside(I::hull(b.v0, b.v1, 128));
  };
  r = subdivide_curve_in_box(c1 * c2, Parameter_box{}, o);
  INFO(r.reason);
  REQUIRE(r.certified);
  CHECK(calls >= 2);
  CHECK(r.topology.number_of_singular_points() == 2);
  // c2's arc from (1/2, 0) to (0, 1/2) and c1 (a closed circle) meet twice: one component
  CHECK(r.topology.components.size() == 1);
  CHECK(r.topology.number_of_boundary_points() == 2);
  for (const auto& w : r.topology.vertices)
    if (w.kind == Curve_topology_vertex::singular) {
      CHECK(w.branches == 2);
      CHECK(std::abs(w.u + w.v - 11.0 / 16) < 1e-9);
    }
}

TEST_CASE("subdivision: multiple points and cusps at small rationals are found and resolved",
          "[topology][subdivision]") {
  // a triple point at (1/2, 1/2) (three lines: the Hessian vanishes there), found at the simplest rational of a
  // deep box and proved by exact Taylor coefficients: 6 arcs to the 6 boundary points, one component
  auto r = subdivide_curve_in_box((u - v) * (u + v - 1) * (2 * u - 1), Parameter_box{});
  REQUIRE(r.certified);
  REQUIRE(r.topology.number_of_singular_points() == 1);
  for (const auto& x : r.topology.vertices)
    if (x.kind == Curve_topology_vertex::singular) {
      CHECK(x.u == 0.5);
      CHECK(x.v == 0.5);
      CHECK(x.branches == 3);
    }
  CHECK(r.topology.edges.size() == 6);
  CHECK(r.topology.number_of_boundary_points() == 6);  // the four corners, (1/2, 0) and (1/2, 1)
  CHECK(r.topology.components.size() == 1);
  // four lines through (1/2, 1/2): multiplicity 4, 8 arcs to 8 boundary points
  r = subdivide_curve_in_box((u - v) * (u + v - 1) * (2 * u - 1) * (2 * v - 1), Parameter_box{});
  REQUIRE(r.certified);
  REQUIRE(r.topology.number_of_singular_points() == 1);
  for (const auto& x : r.topology.vertices)
    if (x.kind == Curve_topology_vertex::singular) CHECK(x.branches == 4);
  CHECK(r.topology.edges.size() == 8);
  CHECK(r.topology.number_of_boundary_points() == 8);
  // a triple point at a rational point with a large denominator, (1/2 + 2^-30, 1/2), is not searched: not
  // certified (a caller's Known_multiple_point is needed)
  const Integer K = Integer(1) << 30;
  r = subdivide_curve_in_box((K * u - K * v - 1) * (K * u + K * v - K - 1) * (2 * K * u - K - 2), Parameter_box{});
  CHECK_FALSE(r.certified);
  // a cusp at (1/3, 1/3): (3v - 1)^2 = (3u - 1)^3, a double tangent (not an ordinary multiple point): found at the
  // simplest rational (order 2, degenerate Hessian) and resolved by its four quadrants; its two half-branches
  // v = 1/3 +- (3u - 1)^(3/2) / 3 leave the square at (2/3, 0) and ((1 + 4^(1/3)) / 3, 1)
  const P2 cusp = (3 * v - 1) * (3 * v - 1) - (3 * u - 1) * (3 * u - 1) * (3 * u - 1);
  r = subdivide_curve_in_box(cusp, Parameter_box{});
  INFO(r.reason);
  REQUIRE(r.certified);
  REQUIRE(r.topology.number_of_singular_points() == 1);
  for (const auto& x : r.topology.vertices)
    if (x.kind == Curve_topology_vertex::singular) {
      CHECK(x.u_lo <= 1.0 / 3);  // the exact point 1/3, rounded outward
      CHECK(1.0 / 3 <= x.u_hi);
      CHECK(x.u_hi - x.u_lo < 1e-15);
      CHECK(x.v_lo <= 1.0 / 3);
      CHECK(1.0 / 3 <= x.v_hi);
      CHECK(x.half_branches == 2);
      CHECK(x.branches == 1);
    } else {
      CHECK(x.on_boundary);
      CHECK((std::fabs(x.u - 2.0 / 3) + std::fabs(x.v) < 1e-9 ||
             std::fabs(x.u - (1 + std::cbrt(4.0)) / 3) + std::fabs(x.v - 1) < 1e-9));
    }
  CHECK(r.topology.number_of_boundary_points() == 2);
  CHECK(r.topology.components.size() == 1);
  check_samples(cusp, r.topology, 1e-9);
  // bad input
  CHECK_THROWS_AS(subdivide_curve_in_box(P2(0), Parameter_box{}), Invalid_input);
  CHECK_THROWS_AS(subdivide_curve_in_box(u, box(Q(1), Q(0), Q(0), Q(1))), Invalid_input);
}

namespace {
// [lo, hi] with lo < 1/sqrt(2) < hi and hi - lo = 2^-200
std::pair<Q, Q> inverse_sqrt2_bracket() {
  Integer s;
  const Integer big = Integer(1) << 399;  // 2^200 / sqrt(2) = sqrt(2^399)
  mpz_sqrt(s.mpz(), big.mpz());
  const Q den(Integer(1) << 200);
  return {Q(s) / den, Q(s + 1) / den};
}
std::size_t boundary_vertices(const Curve_topology_in_box& t) {
  std::size_t n = 0;
  for (const auto& x : t.vertices) n += x.on_boundary;
  return n;
}
}  // namespace

TEST_CASE("subdivision: known triple points at irrational points are resolved by blowing them up",
          "[topology][subdivision]") {
  // x = 2u^2 - 1, y = 2v - 1: D = x^3 - 3 x y^2 = x (x - sqrt3 y)(x + sqrt3 y) has an ordinary triple point at
  // (1/sqrt2, 1/2) with three real tangents: the line u = 1/sqrt2 (from v = 0 to v = 1) and the two curves
  // 2u^2 - 1 = +-sqrt3 (2v - 1), from u = 0 to u = 1. In [0,1]^2: 6 boundary points, 6 arcs, one component.
  const P2 x = 2 * u * u - 1, y = 2 * v - 1;
  const P2 three = x * x * x - 3 * x * y * y;
  const auto b = inverse_sqrt2_bracket();
  const Known_multiple_point p{box(b.first, b.second, Q(1, 2), Q(1, 2)), 3};
  CHECK_FALSE(subdivide_curve_in_box(three, Parameter_box{}).certified);  // the Morse analysis alone fails
  Subdivision_topology_options o;
  o.multiple_points = {p};
  auto r = subdivide_curve_in_box(three, Parameter_box{}, o);
  REQUIRE(r.certified);
  const Curve_topology_in_box& t = r.topology;
  REQUIRE(t.number_of_singular_points() == 1);
  for (const auto& vx : t.vertices)
    if (vx.kind == Curve_topology_vertex::singular) {
      CHECK(vx.branches == 3);
      CHECK(vx.half_branches == 6);
      CHECK(vx.u_lo <= 0.70710678118654752);
      CHECK(0.70710678118654752 <= vx.u_hi);
      CHECK(vx.v == 0.5);
    }
  CHECK(boundary_vertices(t) == 6);
  CHECK(t.edges.size() == 6);
  CHECK(t.components.size() == 1);
  check_samples(three, t, 1e-9);

  // a small oval (radius 1/1000) next to the triple point, crossing no branch: a closed component of its own (a box
  // around both must not be taken for the star of the triple point: the oval encloses an extremum of D)
  const P2 oval = (10000 * u - 7111) * (10000 * u - 7111) + (10000 * v - 5000) * (10000 * v - 5000) - 100;
  r = subdivide_curve_in_box(three * oval, Parameter_box{}, o);
  REQUIRE(r.certified);
  CHECK(r.topology.number_of_singular_points() == 1);
  CHECK(r.topology.components.size() == 2);
  CHECK(closed_components(r.topology) == 1);
  CHECK(r.topology.edges.size() == 8);  // 6 arcs at the triple point, the oval as two edges

  // one real tangent: x (x^2 + 3 y^2) is the line u = 1/sqrt2 alone, through a triple point (two complex
  // branches): one branch, two arcs
  const P2 one = x * (x * x + 3 * y * y);
  r = subdivide_curve_in_box(one, Parameter_box{}, o);
  REQUIRE(r.certified);
  REQUIRE(r.topology.number_of_singular_points() == 1);
  for (const auto& vx : r.topology.vertices)
    if (vx.kind == Curve_topology_vertex::singular) CHECK(vx.half_branches == 2);
  CHECK(boundary_vertices(r.topology) == 2);
  CHECK(r.topology.edges.size() == 2);
  CHECK(r.topology.components.size() == 1);

  // false claims are not believed: multiplicity 4 (an order-3 coefficient is nonzero), multiplicity 2 (the
  // quadratic form vanishes: no tangent cone of degree 2) leave the point unresolved; a "multiple point" on a
  // smooth part of the curve (on the line, at v = 3/10) is ignored and the true one still resolves
  for (int wrong : {2, 4}) {
    o.multiple_points = {Known_multiple_point{p.enclosure, wrong}};
    r = subdivide_curve_in_box(three, Parameter_box{}, o);
    CHECK_FALSE(r.certified);
  }
  o.multiple_points = {Known_multiple_point{box(b.first, b.second, Q(3, 10), Q(3, 10)), 3}, p};
  r = subdivide_curve_in_box(three, Parameter_box{}, o);
  REQUIRE(r.certified);
  CHECK(r.topology.number_of_singular_points() == 1);
  CHECK(r.topology.edges.size() == 6);
  // the other triple point (-1/sqrt2, 1/2) lies outside the box: a box around both sees only the given one
  // resolved; the other stops the subdivision
  o.multiple_points = {p};
  CHECK_FALSE(subdivide_curve_in_box(three, box(Q(-1), Q(1), Q(0), Q(1)), o).certified);
  // bad input: an empty enclosure, a multiplicity below 2
  o.multiple_points = {Known_multiple_point{box(b.second, b.first, Q(1, 2), Q(1, 2)), 3}};
  CHECK_THROWS_AS(subdivide_curve_in_box(three, Parameter_box{}, o), Invalid_input);
  o.multiple_points = {Known_multiple_point{p.enclosure, 1}};
  CHECK_THROWS_AS(subdivide_curve_in_box(three, Parameter_box{}, o), Invalid_input);
}

TEST_CASE("subdivision: known multiple points on a split line, or with two nearly equal tangents, are resolved",
          "[topology][subdivision]") {
  // three lines through (15/31, 16/33), the point where the root box is first split: a plain split puts it on the
  // children's edges, and then no box holds it strictly inside. The box is cut 3 x 3 around it instead.
  const P2 X = 31 * u - 15, Y = 33 * v - 16;
  const P2 L3 = (Y - 3 * X) * (Y - X) * (Y + 2 * X);
  Subdivision_topology_options o;
  CHECK_FALSE(subdivide_curve_in_box(L3, Parameter_box{}, o).certified);  // not found alone: on the split lines
  o.multiple_points = {Known_multiple_point{box(Q(15, 31), Q(15, 31), Q(16, 33), Q(16, 33)), 3}};
  auto r = subdivide_curve_in_box(L3, Parameter_box{}, o);
  INFO(r.reason);
  REQUIRE(r.certified);
  REQUIRE(r.topology.number_of_singular_points() == 1);
  for (const auto& x : r.topology.vertices)
    if (x.kind == Curve_topology_vertex::singular) {
      CHECK(x.half_branches == 6);
      CHECK(x.u == Approx(15.0 / 31).margin(1e-15));
      CHECK(x.v == Approx(16.0 / 33).margin(1e-15));
    }
  CHECK(r.topology.edges.size() == 6);
  CHECK(boundary_vertices(r.topology) == 6);
  CHECK(r.topology.components.size() == 1);
  check_samples(L3, r.topology, 1e-9);
  // the triple point (1/2 + 2^-30, 1/2) of the test above, given by the caller
  const Integer K = Integer(1) << 30;
  const P2 near_half = (K * u - K * v - 1) * (K * u + K * v - K - 1) * (2 * K * u - K - 2);
  o.multiple_points = {Known_multiple_point{box(Q(K + 2, 2 * K), Q(K + 2, 2 * K), Q(1, 2), Q(1, 2)), 3}};
  r = subdivide_curve_in_box(near_half, Parameter_box{}, o);
  INFO(r.reason);
  REQUIRE(r.certified);
  CHECK(r.topology.number_of_singular_points() == 1);
  CHECK(r.topology.edges.size() == 6);
  CHECK(r.topology.components.size() == 1);

  // x (y - 6x)(y - 6.3x) with x = 2u^2 - 1, y = 2v - 1: a triple point at (1/sqrt2, 1/2) whose tangents y = 6x and
  // y = 6.3x are about 0.006 rad apart in (u, v). grad D is small in the whole sector between them (|grad| ~ angle^2 there), so
  // the gradient tests need tiny pieces along it: they split the Bernstein grids of D_u and D_v (differences
  // of a split grid of D lose the precision the piece needs), and the blow-up square may cover the whole box.
  // The line u = 1/sqrt2 and the parabolas 2v - 1 = 6 (2u^2 - 1), 2v - 1 = 6.3 (2u^2 - 1) each run from v = 0 to
  // v = 1 through the triple point: 6 arcs, 6 boundary points, one component.
  const P2 x = 2 * u * u - 1, y = 2 * v - 1;
  const auto b = inverse_sqrt2_bracket();
  o.multiple_points = {Known_multiple_point{box(b.first, b.second, Q(1, 2), Q(1, 2)), 3}};
  for (int gap : {100, 30}) {
    const P2 N = x * (100 * y - 600 * x) * (100 * y - (600 + gap) * x);
    r = subdivide_curve_in_box(N, Parameter_box{}, o);
    INFO("gap " << gap << ": " << r.reason);
    REQUIRE(r.certified);
    REQUIRE(r.topology.number_of_singular_points() == 1);
    for (const auto& vx : r.topology.vertices)
      if (vx.kind == Curve_topology_vertex::singular) {
        CHECK(vx.half_branches == 6);
        CHECK(vx.u_lo <= 0.70710678118654752);
        CHECK(0.70710678118654752 <= vx.u_hi);
      }
    CHECK(boundary_vertices(r.topology) == 6);
    CHECK(r.topology.edges.size() == 6);
    CHECK(r.topology.components.size() == 1);
    check_samples(N, r.topology, 1e-9);
  }
}

TEST_CASE("subdivision: a node and an isolated point at a corner of the box", "[topology][subdivision]") {
  // Corners: a node at (0, 0) with one branch entering the box (u = v) and one touching it only there (u + 2v = 0),
  // and an isolated point at the corner (u^2 + v^2)
  const auto a = subdivide_curve_in_box((u - v) * (u + 2 * v), Parameter_box{});
  REQUIRE(a.certified);
  REQUIRE(a.topology.vertices.size() == 2);  // the corner and (1, 1)
  for (const auto& x : a.topology.vertices) CHECK(x.on_boundary);
  CHECK(a.topology.edges.size() == 1);
  const auto b = subdivide_curve_in_box(u * u + v * v, Parameter_box{});
  REQUIRE(b.certified);
  REQUIRE(b.topology.vertices.size() == 1);
  CHECK(b.topology.vertices[0].kind == Curve_topology_vertex::isolated);
}

TEST_CASE("subdivision: two branches close together (a thin loop, a pair of nearly tangent nodes) are certified",
          "[topology][subdivision][two_branch]") {
  // A loop of width at most 2^-9 along a parabola. A quadtree alone needs boxes thinner than the gap all along it
  // (it spent its 20000 boxes); boxes holding both branches are resolved by the two-branch certificate.
  CHECK(check_parabola_loop(10, 1e-6, 0.01).two_branch_boxes > 0);
  // Two nodes whose branches cross at 0.023 rad (k = 6).
  CHECK(check_parabola_nodes(6).two_branch_boxes > 0);
}

TEST_CASE("subdivision: a loop of width 2^-13 and near misses 2^-44 and 2^-52 deep are certified (valleys excluded)",
          "[topology][subdivision][two_branch][valley]") {
  // Beyond the tips u = 1/4, 3/4 of the loop 2^28 w^2 = 1 - 4 (2u - 1)^2 (|w| <= 2^-14) the two branches become a
  // complex pair, and D is small and positive along the parabola w = 0: plain sign tests need boxes about
  // sqrt(min D / D_vv) wide there, and the subdivision spent its 20000 boxes from width 2^-10 on.
  CHECK(check_parabola_loop(14, 1e-9, 1e-4).valley_boxes > 0);
  const P2 w = 4 * v - 1 - u - u * u;
  // A near miss: D = 2^(2k) w^2 + 1 + u^2 >= 1 has no real zero, but its valley along w = 0 is 2^(-2k) of its
  // coefficients deep (two surfaces that pass close without meeting). Proved empty for k = 22 and 26; for 26 the
  // valley bound needs its segment along the box's edge where the valley's floor leaves a box (without that cut the
  // 20000 boxes are spent).
  for (int k : {22, 26}) {
    const P2 miss = CGAL::ipower(P2(2), 2 * k) * w * w + 1 + u * u;
    const auto r = subdivide_curve_in_box(miss, Parameter_box{});
    INFO(k << ": " << r.reason);
    REQUIRE(r.certified);
    CHECK(r.valley_boxes > 0);
    CHECK(r.topology.components.empty());
    CHECK(r.topology.edges.empty());
  }
}

TEST_CASE("subdivision: loops of width 2^-17 and 2^-21 are certified (one fold box at each tip)",
          "[topology][subdivision][fold]") {
  // At a tip of the loop 2^(2e) w^2 = 1 - 4 (2u - 1)^2 the tangent is vertical (the fold, D = D_v = 0) and, about
  // 2^(-2e) away, horizontal (D = D_u = 0): a box holding both has neither derivative of one sign, and splitting
  // needs boxes 2^(-2e) wide, beyond the depth limit from width 2^-14 on. The fold certificate resolves the tip's
  // box whole: the loop is traced to its tips u = 1/4 and 3/4 (within 1e-6), every point on its branch.
  CHECK(check_parabola_loop(18, 1e-9, 1e-6).fold_boxes == 2);
  CHECK(check_parabola_loop(22, 1e-9, 1e-6).fold_boxes == 2);
}

TEST_CASE("subdivision: nodes whose branches cross at 1e-4 rad are certified", "[topology][subdivision][two_branch]") {
  // The same two nodes with k = 14: the branches cross at 9.2e-5 rad. The Hessian's determinant at a node is about
  // 2^-28 of |H|^2 and changes sign a few 1e-9 from it; next to a node the two branches are 9.2e-5 times the
  // distance to it apart. Needed: Krawczyk's Jacobian in mean-value form, a Krawczyk box larger than the critical
  // point's rounding uncertainty, cuts that keep the node inside its box, the two-branch fold test cut where the
  // minimiser leaves the box, and the double-double retry (without them: not certified from about 3e-3 rad on).
  CHECK(check_parabola_nodes(14).two_branch_boxes > 0);
}

// The box sides on D = 0 are found exactly and their factors removed: D = u (v - 1) (4u^2 + 4v^2 - 1).
TEST_CASE("box edge lines: the factors of the box sides on D = 0 are removed", "[subdivision][edge]") {
  const P2 u = CGAL::shift(P2(1), 1, 0), v = CGAL::shift(P2(1), 1, 1);
  const P2 circle = 4 * u * u + 4 * v * v - 1;
  const P2 D = u * (v - 1) * circle;
  const internal::Box_edge_lines a = internal::box_edge_lines(D, Parameter_box{});
  CHECK(a.sides == std::vector<int>{2, 3});  // v = 1, u = 0
  CHECK(a.rest == normalized_primitive_part(circle));
  // u = 0 inside the box [-1, 1] x [0, 1] is not a side: only v = 1 is removed
  const internal::Box_edge_lines b = internal::box_edge_lines(D, Parameter_box{Q(-1), Q(1), Q(0), Q(1)});
  CHECK(b.sides == std::vector<int>{2});
  CHECK(b.rest == normalized_primitive_part(u * circle));
  // rational sides: u = 1/3 of the box [1/3, 1] x [0, 1/2]
  const P2 E = (3 * u - 1) * (2 * v - 1) * circle;
  const internal::Box_edge_lines c = internal::box_edge_lines(E, Parameter_box{Q(1, 3), Q(1), Q(0), Q(1, 2)});
  CHECK(c.sides == std::vector<int>{2, 3});
  CHECK(c.rest == normalized_primitive_part(circle));
  CHECK(internal::box_edge_lines(circle, Parameter_box{}).sides.empty());
}

TEST_CASE("box edge lines: a curve or a point lies on a curve, decided exactly", "[subdivision][edge]") {
  using C3 = Rational_bezier_curve_3<Rational>;
  using P = C3::Point;
  const C3 C(std::vector<P>{{Q(0), Q(0), Q(0)}, {Q(1), Q(2), Q(0)}, {Q(2), Q(0), Q(1)}}, {Q(1), Q(2), Q(1)});
  auto point = [](const P& p) { return C3(std::vector<P>{p, p}, {Q(1), Q(1)}); };
  CHECK(internal::lies_on(point(C(Q(1, 3))), C));
  CHECK(internal::lies_on(point(C(Q(0))), C));
  CHECK_FALSE(internal::lies_on(point(C(Q(3, 2))), C));  // on the curve's extension beyond [0, 1]
  CHECK_FALSE(internal::lies_on(point({Q(1), Q(1), Q(1)}), C));
  CHECK(internal::lies_on(C.restriction(Q(1, 4), Q(3, 4)), C));
  CHECK(internal::lies_on(C.reversed(), C));
  CHECK_FALSE(internal::lies_on(C, C.restriction(Q(1, 4), Q(3, 4))));  // only half of C is covered
  CHECK_FALSE(internal::lies_on(C, point(C(Q(1, 2)))));
  CHECK(internal::lies_on(point(C(Q(1, 2))), point(C(Q(1, 2)))));
}

// Singular points at a corner of the domain, resolved by the weighted blow-up of topology/internal/corner_blowup.h;
// expected values from the closed forms (branches into the unit square and where they leave it).
namespace {
const Curve_topology_vertex* vertex_at(const Curve_topology_in_box& t, double uu, double vv) {
  for (const auto& x : t.vertices)
    if (x.u_lo <= uu + 1e-12 && uu - 1e-12 <= x.u_hi && x.v_lo <= vv + 1e-12 && vv - 1e-12 <= x.v_hi) return &x;
  return nullptr;
}
// D = 0 is one arc from the singular corner c into the unit square, leaving it at the boundary point x
void check_corner_arc(const P2& D, std::array<double, 2> c, std::array<double, 2> x) {
  auto r = subdivide_curve_in_box(D, Parameter_box{});
  REQUIRE(r.certified);
  REQUIRE(r.topology.components.size() == 1);
  CHECK(r.topology.vertices.size() == 2);
  const auto* p = vertex_at(r.topology, c[0], c[1]);
  REQUIRE(p);
  CHECK(p->kind == Curve_topology_vertex::singular);
  CHECK(p->on_boundary);
  CHECK(p->singular_on_boundary);
  CHECK(p->branches == 1);
  const auto* q = vertex_at(r.topology, x[0], x[1]);
  REQUIRE(q);
  CHECK_FALSE(q->singular_on_boundary);
  CHECK(q->kind == Curve_topology_vertex::boundary);
  check_samples(D, r.topology, 1e-9);
}
// D = 0 in the unit square, certified, with `branches` half-branches from its singular corner c
Subdivision_topology_result certified_with_corner(const P2& D, std::array<double, 2> c, int branches) {
  auto r = subdivide_curve_in_box(D, Parameter_box{});
  REQUIRE(r.certified);
  const auto* p = vertex_at(r.topology, c[0], c[1]);
  REQUIRE(p);
  CHECK(p->singular_on_boundary);
  CHECK(p->branches == branches);
  return r;
}
// D = 0 meets the unit square only at its corner c (the curve passes it from outside)
void check_corner_alone(const P2& D, std::array<double, 2> c) {
  auto r = subdivide_curve_in_box(D, Parameter_box{});
  REQUIRE(r.certified);
  REQUIRE(r.topology.vertices.size() == 1);
  CHECK(r.topology.vertices[0].kind == Curve_topology_vertex::isolated);
  CHECK(r.topology.vertices[0].on_boundary);
  CHECK(r.topology.vertices[0].singular_on_boundary);
  CHECK(r.topology.vertices[0].u == c[0]);
  CHECK(r.topology.vertices[0].v == c[1]);
}
}  // namespace

TEST_CASE("subdivision: singular points at domain corners (cusps tangent to an edge, nodes)", "[topology][subdivision][corner]") {
  SECTION("cusp (u - 1)^2 = 2 v^3 at the corner (1, 0): one branch into the square, leaving it at (0, 2^(-1/3))") {
    check_corner_arc((u - 1) * (u - 1) - 2 * v * v * v, {1, 0}, {0, std::cbrt(0.5)});
  }
  SECTION("cusp (u - 1)^2 = -2 v^3: it opens away from the square, the corner alone is on the locus") {
    check_corner_alone((u - 1) * (u - 1) + 2 * v * v * v, {1, 0});
  }
  SECTION("cusp v^2 = u^3 at (0, 0), tangent to the edge v = 0: one branch, leaving at (1, 2^(-1/2))") {
    check_corner_arc(2 * v * v - u * u * u, {0, 0}, {1, std::sqrt(0.5)});  // v = u^(3/2) / sqrt(2)
  }
  SECTION("cusp 2 v^2 = (1 - u)^3 at (1, 0), tangent to v = 0 (odd power along the reversed u axis)") {
    check_corner_arc(2 * v * v + (u - 1) * (u - 1) * (u - 1), {1, 0}, {0, std::sqrt(0.5)});  // v = (1 - u)^(3/2) / sqrt(2)
    // reflected: 2 v^2 = (u - 1)^3 opens away from the square
    check_corner_alone(2 * v * v - (u - 1) * (u - 1) * (u - 1), {1, 0});
  }
  SECTION("node at (0, 0) and a line near it: the corner's box is resolved only once the line has left it") {
    const P2 D = (u - 2 * v) * (2 * u - v) * (3 * u + 3 * v - 1);
    auto r = certified_with_corner(D, {0, 0}, 2);
    CHECK(r.topology.components.size() == 1);
    std::size_t nodes = 0, boundary = 0;
    for (const auto& x : r.topology.vertices) {
      nodes += x.kind == Curve_topology_vertex::singular && !x.on_boundary;
      boundary += x.kind == Curve_topology_vertex::boundary;
    }
    CHECK(nodes == 2);     // (2/9, 1/9) and (1/9, 2/9)
    CHECK(boundary == 4);  // (1, 1/2), (1/2, 1), (1/3, 0), (0, 1/3)
    CHECK(vertex_at(r.topology, 2.0 / 9, 1.0 / 9));
    CHECK(vertex_at(r.topology, 1.0 / 3, 0));
  }
  SECTION("node at (0, 0) and a line through its box that meets neither branch: counted as extra crossings") {
    const P2 D = (u - 2 * v) * (2 * u - v) * (10 * u - 40 * v - 1);  // the line runs from (1/10, 0) to (1, 9/40)
    auto r = certified_with_corner(D, {0, 0}, 2);
    CHECK(r.topology.components.size() == 2);
    CHECK(vertex_at(r.topology, 0.1, 0));
    CHECK(vertex_at(r.topology, 1, 9.0 / 40));
    CHECK(r.topology.number_of_boundary_points() == 5);
  }
  SECTION("cusp at (1, 0) times a positive quadric vanishing at (9/10, 1/20): an isolated point in the corner's box") {
    // the crossings of the corner's box are those of the cusp alone: only grad D != 0 there tells the point apart
    const P2 D = ((u - 1) * (u - 1) - 2 * v * v * v) * ((10 * u - 9) * (10 * u - 9) + (20 * v - 1) * (20 * v - 1));
    auto r = certified_with_corner(D, {1, 0}, 1);
    CHECK(r.topology.components.size() == 2);
    const auto* q = vertex_at(r.topology, 0.9, 0.05);
    REQUIRE(q);
    CHECK(q->kind == Curve_topology_vertex::isolated);
    CHECK_FALSE(q->on_boundary);
  }
  SECTION("two parabolas tangent to v = 0 at (0, 0): one Newton edge with two roots, to (1, 1/2) and (1, 1/4)") {
    auto r = certified_with_corner((2 * v - u * u) * (4 * v - u * u), {0, 0}, 2);
    CHECK(r.topology.components.size() == 1);
    CHECK(r.topology.number_of_boundary_points() == 3);
    CHECK(vertex_at(r.topology, 1, 0.5));
    CHECK(vertex_at(r.topology, 1, 0.25));
  }
  SECTION("(3v - u)(4v^2 - u^3) at (0, 0): two Newton edges, weights (1, 1) and (2, 3), one branch each") {
    // v = u / 3 leaves at (1, 1/3), v = u^(3/2) / 2 at (1, 1/2); they cross at the node (4/9, 4/27)
    auto r = certified_with_corner((3 * v - u) * (4 * v * v - u * u * u), {0, 0}, 2);
    CHECK(r.topology.components.size() == 1);
    CHECK(r.topology.number_of_boundary_points() == 3);
    CHECK(vertex_at(r.topology, 1, 1.0 / 3));
    CHECK(vertex_at(r.topology, 1, 0.5));
    const auto* n = vertex_at(r.topology, 4.0 / 9, 4.0 / 27);
    REQUIRE(n);
    CHECK(n->kind == Curve_topology_vertex::singular);
    check_samples((3 * v - u) * (4 * v * v - u * u * u), r.topology, 1e-9);
  }
  SECTION("u^5 + u^2 v^3 + v^6 at (0, 0): two Newton edges without positive roots, the corner alone") {
    check_corner_alone(u * u * u * u * u + u * u * v * v * v + v * v * v * v * v * v, {0, 0});
  }
  SECTION("node (u - 2v)(2u - v) at (0, 0): two branches into the square; (u + v)(u - 2v): one") {
    const P2 D = (u - 2 * v) * (2 * u - v);
    auto r = certified_with_corner(D, {0, 0}, 2);
    CHECK(r.topology.components.size() == 1);
    CHECK(vertex_at(r.topology, 1, 0.5));
    CHECK(vertex_at(r.topology, 0.5, 1));
    const P2 E = (u + v) * (u - 2 * v);
    auto s = certified_with_corner(E, {0, 0}, 1);
    CHECK(vertex_at(s.topology, 1, 0.5));
    CHECK(s.topology.vertices.size() == 2);
  }
}

// Singular points inside a side of the domain (the rest of D meeting a shared edge, teapot spout 16 x 17): the two
// quadrants at the point, each blown up (resolve_edge_point). Expected values from the closed forms.
namespace {
// D = 0 in the unit square, certified, with `branches` half-branches from the singular point c on its boundary,
// and the boundary points `exits` (other than c)
Subdivision_topology_result certified_with_edge_point(const P2& D, std::array<double, 2> c, int branches,
                                                      std::vector<std::array<double, 2>> exits, std::size_t edges = 0) {
  auto r = subdivide_curve_in_box(D, Parameter_box{});
  INFO(r.reason);
  REQUIRE(r.certified);
  const auto* p = vertex_at(r.topology, c[0], c[1]);
  REQUIRE(p);
  CHECK(p->singular_on_boundary);
  CHECK(p->on_boundary);
  CHECK(p->branches == branches);
  CHECK(p->kind == (branches == 0 ? Curve_topology_vertex::isolated : Curve_topology_vertex::singular));
  CHECK(p->u_hi - p->u_lo < 1e-12);
  CHECK(p->v_hi - p->v_lo < 1e-12);
  CHECK(r.topology.number_of_boundary_points() == exits.size() + 1);  // with c
  for (const auto& x : exits) {
    const auto* q = vertex_at(r.topology, x[0], x[1]);
    REQUIRE(q);
    CHECK(q->kind == Curve_topology_vertex::boundary);
  }
  CHECK(r.topology.edges.size() == (edges ? edges : std::size_t(branches)));
  check_samples(D, r.topology, 1e-9);
  return r;
}
}  // namespace

TEST_CASE("subdivision: singular points inside an edge of the domain, rational and irrational",
          "[topology][subdivision][edge_point]") {
  const double r2 = std::sqrt(0.5);
  SECTION("node (3u - 1)^2 = v^2 at (1/3, 0): two branches, to (2/3, 1) and (0, 1)") {
    certified_with_edge_point((3 * u - 1 - v) * (3 * u - 1 + v), {1.0 / 3, 0}, 2, {{2.0 / 3, 1}, {0, 1}});
  }
  SECTION("node at (15/31, 0), where the first split would put a grid line (the box is cut around the point)") {
    certified_with_edge_point((31 * u - 15 - 31 * v) * (31 * u - 15 + 31 * v), {15.0 / 31, 0}, 2,
                              {{1, 16.0 / 31}, {0, 15.0 / 31}});
  }
  SECTION("node of the parabolas v = +-(2u^2 - 1) at (1/sqrt 2, 0): two branches, to (1, 1) and (0, 1)") {
    certified_with_edge_point((2 * u * u - 1 - v) * (2 * u * u - 1 + v), {r2, 0}, 2, {{1, 1}, {0, 1}});
  }
  SECTION("cusp 2 v^2 = (2u^2 - 1)^3 tangent to v = 0 at (1/sqrt 2, 0): one branch, to (1, 1/sqrt 2)") {
    certified_with_edge_point(2 * v * v - (2 * u * u - 1) * (2 * u * u - 1) * (2 * u * u - 1), {r2, 0}, 1, {{1, r2}});
    // reflected along the side: the branch runs the other way, to (0, 1/sqrt 2)
    certified_with_edge_point(2 * v * v + (2 * u * u - 1) * (2 * u * u - 1) * (2 * u * u - 1), {r2, 0}, 1, {{0, r2}});
  }
  SECTION("(6v - 2u + 1)(32 v^2 - (2u - 1)^3) at (1/2, 0): two Newton edges, both branches to the right") {
    // v = (u - 1/2) / 3 leaves at (1, 1/6), v = (u - 1/2)^(3/2) / 2 at (1, 2^(-5/2)); they cross at (17/18, 4/27)
    const P2 D = (6 * v - 2 * u + 1) * (32 * v * v - (2 * u - 1) * (2 * u - 1) * (2 * u - 1));
    auto r = certified_with_edge_point(D, {0.5, 0}, 2, {{1, 1.0 / 6}, {1, std::pow(2.0, -2.5)}}, 4);
    const auto* n = vertex_at(r.topology, 17.0 / 18, 4.0 / 27);
    REQUIRE(n);
    CHECK(n->kind == Curve_topology_vertex::singular);
  }
  SECTION("v^2 + (2u^2 - 1)^2 = 0: the point alone, isolated on the boundary") {
    certified_with_edge_point(v * v + (2 * u * u - 1) * (2 * u * u - 1), {r2, 0}, 0, {});
  }
  SECTION("on the side u = 1: (2v^2 - 1)^2 = 4 (1 - u)^2 at (1, 1/sqrt 2), branches to (1/2, 1) and (1/2, 0)") {
    certified_with_edge_point((2 * v * v - 1 - 2 * (1 - u)) * (2 * v * v - 1 + 2 * (1 - u)), {1, r2}, 2,
                              {{0.5, 1}, {0.5, 0}});
  }
}
