// du-1989 §4.4.2, Examples 4.4.1 and 4.4.2: the floating-point examples of the thesis with their printed
// coefficients taken as exact decimals (examples/data/du1989_example_4_4_*.json). What is exactly true, decided
// with CGAL's resultants and gcds (independent of the library's intersection engine) and cross-checked with
// intersect_curves on pole-free pieces; see doc/floating_point_examples.md.
#include <bezoutian/intersection/Curve_intersection.h>
#include <bezoutian/algebraic/Root_isolation.h>
#include <bezoutian/io/Geometry_document.h>

#include <catch2/catch.hpp>

#include "test_support.h"

using namespace bezoutian;

namespace {

using Q = Rational;
using Q1 = Polynomial_1<Q>;
using Q2 = Polynomial_2<Q>;
using Curve3 = Rational_bezier_curve_3<Q>;

struct Example {
  Curve3 P, Q_;
};

Example load(const std::string& name) {
  const auto doc = io::read_geometry_file(bezoutian_test::source_file("examples/data/" + name));
  REQUIRE(doc.curves_3.size() == 2);
  return {doc.curves_3[0], doc.curves_3[1]};
}

// F(s,t) = A(s) B(t) - C(t) E(s) as a polynomial in t (outer) with coefficients in Q[s].
Q2 cross_term(const Q1& A, const Q1& B, const Q1& C, const Q1& E) {
  std::vector<Q1> co;
  for (int j = 0; j <= std::max(B.degree(), C.degree()); ++j)
    co.push_back(A * Q1(j <= B.degree() ? B[j] : Q(0)) - E * Q1(j <= C.degree() ? C[j] : Q(0)));
  return Q2(co.begin(), co.end());
}

Q1 strip(Q1 f, const Q1& w) {  // f / w^k for the largest k
  for (;;) {
    Q1 q, r;
    Q1::euclidean_division(f, w, q, r);
    if (!CGAL::is_zero(r)) return f;
    f = q;
  }
}

// Exact squared distance |P(s) - Q(t)|^2 at rational parameters.
Q squared_distance(const Example& e, const Q& s, const Q& t) {
  const auto a = e.P(s), b = e.Q_(t);
  Q d(0);
  for (int k = 0; k < 3; ++k) d += (a[k] - b[k]) * (a[k] - b[k]);
  return d;
}

// No common point at any (complex) parameters with finite coordinates: after removing the weight factors W1(s)^k
// (common roots at infinity), gcd(Res_t(F1,F2), Res_t(F1,F3)) is a constant.
void check_disjoint(const Example& e) {
  const auto p = e.P.power_form(), q = e.Q_.power_form();
  std::vector<Q2> F;
  for (int k = 1; k <= 3; ++k) F.push_back(cross_term(p[k], q[0], q[k], p[0]));
  const Q1 r12 = strip(CGAL::resultant(F[0], F[1]), p[0]);
  const Q1 r13 = strip(CGAL::resultant(F[0], F[2]), p[0]);
  REQUIRE(!CGAL::is_zero(r12));
  REQUIRE(!CGAL::is_zero(r13));
  CHECK(CGAL::gcd(r12, r13).degree() == 0);
}

Q tenth_power(int k) {  // 10^-k
  Integer d(1);
  for (int i = 0; i < k; ++i) d *= 10;
  return Q(1) / Q(d);
}

std::size_t poles(const Curve3& c) { return isolate_real_roots(c.power_form()[0], Q(0), Q(1)).size(); }

Q dec(const char* s) {  // exact decimal
  std::string t(s);
  const auto dot = t.find('.');
  Integer den(1);
  if (dot != std::string::npos) {
    for (std::size_t i = dot + 1; i < t.size(); ++i) den *= 10;
    t.erase(dot, 1);
  }
  return Q(Integer(t)) / Q(den);
}

}  // namespace

TEST_CASE("du-1989 Example 4.4.1: the curves do not intersect", "[floating_point_examples]") {
  const Example e = load("du1989_example_4_4_1.json");
  // the coefficients are read exactly: W1(s) = 2.7043950 - 20.562170 s + ...
  CHECK(e.P.power_form()[0][0] == dec("2.7043950"));
  CHECK(e.P.power_form()[0][3] == dec("-25.683240"));
  // P has three poles in [0,1] (between them lies s = 0.7), Q none
  CHECK(poles(e.P) == 3);
  CHECK(poles(e.Q_) == 0);
  check_disjoint(e);
  // the "actual intersection points" of the thesis are at distance ~2.8e-5 and ~2.0e-6
  CHECK(squared_distance(e, Q(7, 10), Q(1)) > tenth_power(12));  // > (1e-6)^2
  CHECK(squared_distance(e, dec("0.85714286"), dec("0.66666667")) > tenth_power(15));
  // closest approaches (Newton in 40 digits, doc/floating_point_examples.md): exact upper bounds at rounded points
  CHECK(squared_distance(e, dec("0.69999337841"), dec("1.00006110728")) < Q(28, 1000000) * Q(28, 1000000));
  CHECK(squared_distance(e, dec("0.85714337657"), dec("0.66666815896")) < Q(21, 10000000) * Q(21, 10000000));
  // the library's certified curve intersection agrees on pole-free pieces around the claimed points
  const auto r = intersect_curves(e.P.restriction(Q(68, 100), Q(74, 100)), e.Q_);
  CHECK(r.points.empty());
  CHECK(r.overlaps.empty());
  const auto r2 = intersect_curves(e.P.restriction(Q(75, 100), Q(1)), e.Q_);
  CHECK(r2.points.empty());
}

TEST_CASE("du-1989 Example 4.4.2: the curves do not intersect", "[floating_point_examples]") {
  const Example e = load("du1989_example_4_4_2.json");
  CHECK(e.Q_.power_form()[3][3] == dec("0.82427232"));
  CHECK(poles(e.P) == 3);
  CHECK(poles(e.Q_) == 3);
  check_disjoint(e);
  // the stated intersection (0.25, 0.9, 0.5) at (s,t) = (0.625, 0.22222222) is not on P: P(0.625) ~ (0.25000015,
  // 0.90000925, 0.50000421)
  const auto p = e.P(Q(5, 8));
  CHECK(p[1] - Q(9, 10) > Q(9, 1000000));
  CHECK(squared_distance(e, Q(5, 8), dec("0.22222222")) > tenth_power(13));
  // closest approach ~5.28e-6 at (0.62500053, 0.22236260)
  CHECK(squared_distance(e, dec("0.62500052659"), dec("0.22236259795")) < Q(53, 10000000) * Q(53, 10000000));
  // pole-free pieces around the stated point: P on [0.3, 0.68], Q on [0, 0.29]
  const auto r = intersect_curves(e.P.restriction(Q(3, 10), Q(68, 100)), e.Q_.restriction(Q(0), Q(29, 100)));
  CHECK(r.points.empty());
  CHECK(r.overlaps.empty());
}
