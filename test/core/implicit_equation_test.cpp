// The implicit-equation facade: worked example of buse-elkadi-galligo-2008 §4 read from the shipped sample
// file, and intersection of patches of different bi-degrees (degree elevation) vanishing at a constructed
// common point.
#include <catch2/catch.hpp>

#include "test_support.h"

#include <bezoutian/Implicit_equation.h>
#include <bezoutian/io/Geometry_document.h>

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
