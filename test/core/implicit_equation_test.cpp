// The implicit-equation facade: worked example of buse-elkadi-galligo-2008 §4 read from the shipped sample
// file, and intersection of patches of different bi-degrees (degree elevation) vanishing at a constructed
// common point.
#include <catch2/catch.hpp>

#include "test_support.h"

#include <bezoutian/elimination/Implicit_equation.h>
#include <bezoutian/elimination/Maximal_minor_projection.h>
#include <bezoutian/topology/matrix_zero_points.h>
#include <bezoutian/io/Geometry_document.h>
#include "power_patch.h"

#include <random>
#include <set>

using namespace bezoutian;
using Q = Rational;
using Patch = Rational_bezier_patch<>;

TEST_CASE("worked example: D has bi-degree (10,10), total degree 14, 97 terms", "[implicit]") {
  auto doc = io::read_geometry_file(bezoutian_test::source_file("examples/data/bezoutian_worked_example.json"));
  REQUIRE(doc.patches.size() == 1);
  Implicit_equation e = self_intersection_equation(doc.patches[0]);
  CHECK(e.matrix.size() == 3);
  CHECK(e.degree(0) == 10);
  CHECK(e.degree(1) == 10);
  CHECK(e.total_degree() == 14);
  CHECK(e.terms().size() == 97);
  CHECK(e.square_free == e.determinant);  // irreducible over Q (shared/notes)
  // Theorem 5 (rational formula) gives the same curve
  Implicit_equation r = self_intersection_equation(doc.patches[0], Bezoutian_formula::rational);
  CHECK(r.determinant == e.determinant);
}

TEST_CASE("intersection of a (2,1) and a (1,2) patch through a common point", "[implicit]") {
  // Psi is Phi's net shifted so that Phi(u0,v0) = Psi(s0,t0) at chosen parameters: D(u0,t0) = 0 exactly.
  std::vector<std::vector<Patch::Point>> a(3, std::vector<Patch::Point>(2)), b(2, std::vector<Patch::Point>(3));
  int k = 0;
  for (auto& row : a)
    for (auto& p : row) p = {Q((k * 7) % 5 - 2), Q((k * 3) % 7 - 3), Q((k * k) % 4)}, ++k;
  for (auto& row : b)
    for (auto& p : row) p = {Q((k * 5) % 9 - 4), Q((k * 2) % 5 - 1), Q((k * 3) % 7 - 2)}, ++k;
  Patch phi(a), psi0(b);
  const Q u0(1, 3), v0(2, 5), s0(3, 4), t0(1, 6);
  auto P = phi(u0, v0), R = psi0(s0, t0);
  for (auto& row : b)
    for (auto& p : row)
      for (int c = 0; c < 3; ++c) p[c] += P[c] - R[c];
  Patch psi(b);
  REQUIRE(psi(s0, t0) == P);
  Implicit_equation e = intersection_equation(phi, psi);
  CHECK(e.matrix.size() == 1);  // m2 n1 = 1 * 1 (Theorem 7 with f of degree 1 in v, g of degree 1 in s)
  CHECK_FALSE(e.is_degenerate());
  // D(u0, t0) = 0: evaluate in Q
  Q value(0);
  for (const auto& t : e.terms())
    value += Q(std::get<2>(t)) * CGAL::ipower(u0, std::get<0>(t)) * CGAL::ipower(t0, std::get<1>(t));
  CHECK(value == Q(0));
  // and not at a generic point
  Q other(0);
  for (const auto& t : e.terms())
    other += Q(std::get<2>(t)) * CGAL::ipower(Q(1, 7), std::get<0>(t)) * CGAL::ipower(Q(5, 11), std::get<1>(t));
  CHECK(other != Q(0));
}

TEST_CASE("identical patches give an identically zero determinant, reported as degenerate", "[implicit][bad-input]") {
  std::vector<std::vector<Patch::Point>> a(3, std::vector<Patch::Point>(3));
  int k = 1;
  for (auto& row : a)
    for (auto& p : row) p = {Q(k % 3), Q((k * k) % 5), Q(k % 4 - 1)}, ++k;
  Patch phi(a);
  Implicit_equation e = intersection_equation(phi, phi);
  CHECK(e.is_degenerate());
  CHECK(e.total_degree() == -1);
}

namespace {
// Taylor coefficients of D at (x, y) up to total order 3, exactly: T[a][b] of (u - x)^a (v - y)^b
std::vector<std::vector<Q>> taylor3(const Polynomial_2<Integer>& D, const Q& x, const Q& y) {
  int A = 0;
  for (int j = 0; j <= D.degree(); ++j) A = std::max(A, D[j].degree());
  const int B = D.degree();
  std::vector<std::vector<Q>> c(std::size_t(A + 1), std::vector<Q>(std::size_t(B + 1), Q(0)));
  for (int j = 0; j <= B; ++j)
    for (int i = 0; i <= D[j].degree(); ++i) c[i][j] = Q(D[j][i]);
  for (int j = 0; j <= B; ++j)
    for (int s = 0; s < A; ++s)
      for (int i = A - 1; i >= s; --i) c[i][j] += x * c[i + 1][j];
  for (int i = 0; i <= A; ++i)
    for (int s = 0; s < B; ++s)
      for (int j = B - 1; j >= s; --j) c[i][j] += y * c[i][j + 1];
  return c;
}
}  // namespace

TEST_CASE("the common zeros of the Bezoutian matrix are triple points of D (worked example)", "[implicit][seed]") {
  auto doc = io::read_geometry_file(bezoutian_test::source_file("examples/data/bezoutian_worked_example.json"));
  const Implicit_equation e = self_intersection_equation(doc.patches[0]);
  const auto zeros = internal::matrix_zero_points(e, Parameter_box{Q(-3), Q(3), Q(-3), Q(3)});
  REQUIRE(zeros.size() >= 1);
  bool seed_point = false;
  for (const auto& z : zeros) {
    CHECK(z.multiplicity == 3);
    const Q x = z.enclosure.u0, y = z.enclosure.v0;  // within ~1e-85 of the exact point
    seed_point |= CGAL::abs(x - Q(-1.0470947234032030127)) < Q(1, 1000000000) &&
                  CGAL::abs(y - Q(-0.0488563631290503188)) < Q(1, 1000000000);
    // D, its gradient and its Hessian vanish there (up to the enclosure width), its cubic form does not
    const auto T = taylor3(e.square_free, x, y);
    Q cubic(0);
    for (int a = 0; a <= 3; ++a) cubic = std::max(cubic, CGAL::abs(T[a][3 - a]));
    REQUIRE(cubic > Q(1, 1000));
    for (int a = 0; a <= 2; ++a)
      for (int b = 0; a + b <= 2; ++b) CHECK(CGAL::abs(T[a][b]) < cubic * Q(1, Integer(1) << 150));
  }
  CHECK(seed_point);  // the triple point near (-1.047, -0.0489) of buse-elkadi-galligo-2008 §4

  // huge inputs (31-bit rational coordinates and weights): the search gives up at once (documented), no hang
  std::mt19937_64 g(7);
  auto big = [&](bool positive) {
    const Integer r(int(g() & 0x7fffffff));
    return positive ? Q(r + 1) : ((g() & 1) ? Q(r) : Q(-r));
  };
  std::vector<std::vector<Patch::Point>> p(3, std::vector<Patch::Point>(3));
  std::vector<std::vector<Q>> w(3, std::vector<Q>(3));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      p[i][j] = {big(false) / big(true), big(false) / big(true), big(false) / big(true)};
      w[i][j] = big(true) / big(true);
    }
  const Implicit_equation h = self_intersection_equation(Patch(p, w));
  CHECK(internal::matrix_zero_points(h, Parameter_box{}).empty());
}

TEST_CASE("a rational (2,2) patch with two triple points of D: the topology of CGAL's whole-plane analysis",
          "[implicit][topology]") {
  // the first (2,2) rational self-intersection of benchmark/surface_benchmark.cpp; {x, y, z, weight} by (i, j)
  const int net[9][4] = {{4, -3, 5, 4},  {-3, 3, -1, 2}, {0, 2, 3, 2},  {0, 1, -5, 3}, {2, -1, -2, 4},
                         {3, 4, 0, 4},   {3, -1, 4, 4},  {-1, 5, -3, 3}, {2, -5, 3, 4}};
  std::vector<std::vector<Patch::Point>> p(3, std::vector<Patch::Point>(3));
  std::vector<std::vector<Q>> w(3, std::vector<Q>(3));
  for (int k = 0; k < 9; ++k) {
    p[k / 3][k % 3] = {Q(net[k][0]), Q(net[k][1]), Q(net[k][2])};
    w[k / 3][k % 3] = Q(net[k][3]);
  }
  const Implicit_equation e = self_intersection_equation(Patch(p, w));
  REQUIRE(e.total_degree() == 20);
  CHECK_FALSE(subdivide_curve_in_box(e.square_free, Parameter_box{}).certified);  // the triple points stop it
  Subdivision_topology_options o;
  o.multiple_points = internal::matrix_zero_points(e, Parameter_box{});
  CHECK(o.multiple_points.size() == 2);
  const auto r = subdivide_curve_in_box(e.square_free, Parameter_box{}, o);
  REQUIRE(r.certified);
  // expected values: CGAL's analyse_curve_in_box of the same D (476 s; its timings are in doc/benchmarks.md,
  // "CGAL's analysis of the same D")
  const Curve_topology_in_box& t = r.topology;
  REQUIRE(t.number_of_singular_points() == 2);
  for (const auto& x : t.vertices)
    if (x.kind == Curve_topology_vertex::singular) {
      const bool first = std::fabs(x.u - 0.708088922700) < 1e-9;
      CHECK((first || std::fabs(x.u - 0.719573145481) < 1e-9));
      CHECK(x.v == Approx(first ? 0.023845482672 : 0.497816146857).margin(1e-9));
      CHECK(x.branches == (first ? 3 : 1));
    }
  CHECK(t.number_of_boundary_points() == 8);
  REQUIRE(t.components.size() == 3);
  std::multiset<std::array<int, 3>> got, expected{{0, 2, 0}, {1, 0, 0}, {0, 6, 2}};  // closed, boundary, singular
  for (const auto& c : t.components) {
    std::array<int, 3> s{int(c.closed), 0, 0};
    for (auto vi : c.vertices) {
      s[1] += t.vertices[vi].on_boundary;
      s[2] += t.vertices[vi].kind == Curve_topology_vertex::singular;
    }
    got.insert(s);
  }
  CHECK(got == expected);
}

namespace {
// A 2 x 2 Bezoutian_matrix with the given entries (polynomials in u (inner) and t (outer)).
Bezoutian_matrix matrix_of(const std::vector<std::vector<Polynomial_2<Rational>>>& entries) {
  Bezoutian_matrix B;
  B.entries = entries;
  return B;
}
Polynomial_2<Rational> U() { return Polynomial_2<Rational>(Polynomial_1<Rational>(Rational(0), Rational(1))); }
Polynomial_2<Rational> T() { return Polynomial_2<Rational>(Polynomial_1<Rational>(Rational(0)), Polynomial_1<Rational>(Rational(1))); }
Polynomial_2<Rational> C(int c) { return Polynomial_2<Rational>(Rational(c)); }
}  // namespace

TEST_CASE("generic rank: proved on a grid, including a matrix whose rank drops at the first sample point",
          "[implicit][minors]") {
  // second row = t * first row: rank 1 over Q(u, t), by construction
  CHECK(generic_rank(matrix_of({{U(), T()}, {U() * T(), T() * T()}})).rank == 1);
  CHECK(generic_rank(matrix_of({{U(), T()}, {T(), U()}})).rank == 2);
  // det = (u - 7/19) (t - 11/23) vanishes at the first sample point (7/19, 11/23): the grid must find rank 2
  const Polynomial_2<Rational> a = U() - Polynomial_2<Rational>(Rational(7, 19)), b = T() - Polynomial_2<Rational>(Rational(11, 23));
  CHECK(generic_rank(matrix_of({{a, C(0)}, {C(0), b}})).rank == 2);
  CHECK(generic_rank(matrix_of({{C(0), C(0)}, {C(0), C(0)}})).rank == 0);
  CHECK(internal::fraction_free_rank(std::vector<std::vector<Rational>>{{Rational(1), Rational(2)}, {Rational(2), Rational(4)}}) == 1);
}

TEST_CASE("maximal minors: the curve of two orthogonal extrusions, where det B vanishes identically",
          "[implicit][minors]") {
  // (x, x^2, z) with x = 2u - 1, z = 2v - 1, and (x, s, 1/2 - (2s - 1)^2) with x = 2t - 1: they meet over the line
  // u = t only (equal x), and det B = 0 (a common root at infinity for every (u, t))
  const Patch phi = bezoutian_test::patch_from_power({"2*u-1", "(2*u-1)^2", "2*v-1"}, 2, 1);
  const Patch psi = bezoutian_test::patch_from_power({"2*v-1", "u", "1/2-(2*u-1)^2"}, 2, 1);
  const Implicit_equation e = intersection_equation(phi, psi);
  REQUIRE(e.is_degenerate());
  const Maximal_minor_projection mm = maximal_minor_projection(e.matrix, phi, psi);
  INFO(mm.reason);
  REQUIRE(mm.computed);
  CHECK(mm.rank.rank == 1);
  CHECK(mm.rank.grid_points > 0);
  // D = +-(u - t) up to a constant: zero exactly on the diagonal
  const Polynomial_2<Integer> D = normalized_square_free_part(mm.polynomial);
  REQUIRE(D.degree() == 1);
  auto at = [&](const Rational& x, const Rational& y) {
    Rational r(0);
    for (int j = D.degree(); j >= 0; --j) {
      Rational c(0);
      for (int i = D[j].degree(); i >= 0; --i) c = c * x + Rational(D[j][i]);
      r = r * y + c;
    }
    return r;
  };
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) CHECK(CGAL::is_zero(at(Rational(i, 4), Rational(j, 4))) == (i == j));
  // the stereographic cap and the octant of one sphere have a partner at every (u, t): refused
  const Patch cap = bezoutian_test::rational_patch_from_power({"2*u", "2*v", "1-u^2-v^2", "1+u^2+v^2"}, 2, 2);
  const Patch octant = bezoutian_test::rational_patch_from_power(
      {"(1-v^2)*(1-u^2)", "2*u*(1-v^2)", "2*v*(1+u^2)", "(1+u^2)*(1+v^2)"}, 2, 2);
  const Implicit_equation f = intersection_equation(cap, octant);
  REQUIRE(f.is_degenerate());
  const Maximal_minor_projection no = maximal_minor_projection(f.matrix, cap, octant);
  CHECK_FALSE(no.computed);
  CHECK(no.reason.find("solution at every (u, t)") != std::string::npos);
}
