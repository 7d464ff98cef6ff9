// Exact geometry types: conversions, evaluation, subdivision, restriction, elevation, derivatives.
// Expected values come from textbook identities (circle parametrization, endpoint tangents,
// blossom extrapolation), not from the code under test.
#include <catch2/catch.hpp>

#include <bezoutian/geometry/Rational_bezier_curve.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>

#include <random>

using namespace bezoutian;
using Q = Rational;
using Curve2 = Rational_bezier_curve_2<>;
using Curve3 = Rational_bezier_curve_3<>;
using Patch = Rational_bezier_patch<>;

namespace {
Q rnd(std::mt19937& g, int lo = -9, int hi = 9) {
  std::uniform_int_distribution<int> d(lo, hi);
  int den = std::uniform_int_distribution<int>(1, 4)(g);
  return Q(d(g), den);
}
Curve3 random_curve3(std::mt19937& g, int n, bool rational) {
  std::vector<Curve3::Point> p(n + 1);
  std::vector<Q> w(n + 1, Q(1));
  for (int i = 0; i <= n; ++i) {
    p[i] = {rnd(g), rnd(g), rnd(g)};
    if (rational) w[i] = Q(std::uniform_int_distribution<int>(1, 7)(g), std::uniform_int_distribution<int>(1, 3)(g));
  }
  return Curve3(p, w);
}
Patch random_patch(std::mt19937& g, int m, int n, bool rational) {
  std::vector<std::vector<Patch::Point>> p(m + 1, std::vector<Patch::Point>(n + 1));
  std::vector<std::vector<Q>> w(m + 1, std::vector<Q>(n + 1, Q(1)));
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j) {
      p[i][j] = {rnd(g), rnd(g), rnd(g)};
      if (rational) w[i][j] = Q(std::uniform_int_distribution<int>(1, 7)(g), 2);
    }
  return Patch(p, w);
}
}  // namespace

TEST_CASE("a rational quadratic with weights (1,1,2) is a quarter of the unit circle", "[types]") {
  // w1^2 / (w0 w2) = 1/2 = cos^2(45 deg): the classical circular-arc condition.
  Curve2 arc({{Q(1), Q(0)}, {Q(1), Q(1)}, {Q(0), Q(1)}}, {Q(1), Q(1), Q(2)});
  REQUIRE(arc.is_rational());
  for (int k = 0; k <= 12; ++k) {
    const Q t(k, 12);
    auto p = arc(t);
    CHECK(p[0] * p[0] + p[1] * p[1] == Q(1));
  }
  // the power form gives the same points
  auto f = arc.power_form();
  for (int k = 0; k <= 5; ++k) {
    const Q t(k, 7);
    const Q W = f[0].evaluate(t);
    CHECK(f[1].evaluate(t) * f[1].evaluate(t) + f[2].evaluate(t) * f[2].evaluate(t) == W * W);
  }
  auto d = arc.evaluate(0.3);
  CHECK(d[0] * d[0] + d[1] * d[1] == Approx(1.0).epsilon(1e-14));
}

TEST_CASE("curve Bernstein <-> power round trip and exact evaluation", "[types]") {
  std::mt19937 g(7);
  for (int n = 0; n <= 7; ++n)
    for (bool rational : {false, true}) {
      Curve3 c = random_curve3(g, n, rational);
      Curve3 back = Curve3::from_power_form(c.power_form(), n);
      CHECK(back == c);
      // evaluation from the power form agrees with de Casteljau
      auto f = c.power_form();
      const Q t(3, 11);
      auto p = c(t);
      for (int k = 0; k < 3; ++k) CHECK(p[k] == f[k + 1].evaluate(t) / f[0].evaluate(t));
      // endpoints interpolate the end control points
      CHECK(c(Q(0)) == c.control_point(0));
      CHECK(c(Q(1)) == c.control_point(n));
    }
}

TEST_CASE("subdivision halves reassemble to the original curve", "[types]") {
  std::mt19937 g(11);
  for (int n = 1; n <= 6; ++n) {
    Curve3 c = random_curve3(g, n, n % 2 == 1);
    const Q t(2, 7);
    auto halves = c.split(t);
    // blossom extrapolation: the left half on [0, 1/t] is the original curve on [0,1]
    CHECK(halves.first.restriction(Q(0), Q(1) / t) == c);
    // the right half on [-t/(1-t), 1] is the original
    CHECK(halves.second.restriction(-t / (Q(1) - t), Q(1)) == c);
    CHECK(c.restriction(Q(0), t) == halves.first);
    CHECK(c.restriction(t, Q(1)) == halves.second);
    // a point of the right half maps to the original parameter
    CHECK(halves.second(Q(1, 3)) == c(t + (Q(1) - t) * Q(1, 3)));
    CHECK(c.reversed()(Q(1, 5)) == c(Q(4, 5)));
  }
}

TEST_CASE("degree elevation keeps the curve, derivatives match the endpoint tangent formula", "[types]") {
  std::mt19937 g(5);
  for (int n = 1; n <= 5; ++n) {
    Curve3 c = random_curve3(g, n, true);
    Curve3 e = c.elevated(2);
    CHECK(e.degree() == n + 2);
    for (int k = 0; k <= 4; ++k) CHECK(e(Q(k, 4)) == c(Q(k, 4)));
    // C'(0) = n w1/w0 (P1 - P0) and C'(1) = n w_{n-1}/w_n (P_n - P_{n-1}) for rational curves
    Curve3 d = c.derivative();
    auto d0 = d(Q(0)), d1 = d(Q(1));
    auto P0 = c.control_point(0), P1 = c.control_point(1), Pn = c.control_point(n), Pm = c.control_point(n - 1);
    for (int k = 0; k < 3; ++k) {
      CHECK(d0[k] == Q(n) * c.weight(1) / c.weight(0) * (P1[k] - P0[k]));
      CHECK(d1[k] == Q(n) * c.weight(n - 1) / c.weight(n) * (Pn[k] - Pm[k]));
    }
    Curve3 poly = random_curve3(g, n, false);
    CHECK(poly.derivative().degree() == n - 1);
    auto h0 = poly.derivative()(Q(0));
    for (int k = 0; k < 3; ++k) CHECK(h0[k] == Q(n) * (poly.control_point(1)[k] - poly.control_point(0)[k]));
  }
}

TEST_CASE("bad curve input is rejected with a clear message", "[types][bad-input]") {
  using P = Curve2::Point;
  CHECK_THROWS_WITH(Curve2(std::vector<P>{}), Catch::Contains("at least one control point"));
  CHECK_THROWS_WITH(Curve2({P{Q(0), Q(0)}, P{Q(1), Q(1)}}, {Q(1), Q(0)}), Catch::Contains("weight 1"));
  CHECK_THROWS_WITH(Curve2({P{Q(0), Q(0)}, P{Q(1), Q(1)}}, {Q(1)}), Catch::Contains("needs 2 weights"));
  CHECK_THROWS_AS(Curve2::from_homogeneous({{Q(0), Q(0), Q(0)}}), Invalid_input);
  // a zero Bernstein weight coefficient from the power basis is a control point at infinity, not an error:
  // W = (1-t)^2 + t^2 has Bernstein coefficients (1, 0, 1)
  Curve2::Power_form f;
  f[0] = Curve2::Polynomial(Q(1), Q(-2), Q(2));
  f[1] = Curve2::Polynomial(Q(1), Q(-2));
  f[2] = Curve2::Polynomial(Q(0), Q(2), Q(-2));
  Curve2 c = Curve2::from_power_form(f);
  CHECK(c.is_at_infinity(1));
  CHECK_THROWS_AS(c.control_point(1), Invalid_input);
  CHECK_FALSE(c.encloses_curve());
  auto p = c(Q(1, 2));
  CHECK(p[0] * p[0] + p[1] * p[1] == Q(1));  // (1-2t, 2t-2t^2)/(1-2t+2t^2): X^2+Y^2 = W^2
}

TEST_CASE("patch Bernstein <-> power round trip, evaluation and subdivision", "[types]") {
  std::mt19937 g(3);
  for (int m = 1; m <= 3; ++m)
    for (int n = 1; n <= 3; ++n) {
      Patch p = random_patch(g, m, n, (m + n) % 2 == 0);
      CHECK(p.bidegree() == std::make_pair(m, n));
      Patch back = Patch::from_power_form(p.power_form(), m, n);
      CHECK(back == p);
      auto f = p.power_form();
      const Q u(2, 5), v(5, 7);
      auto x = p(u, v);
      const Q W = f[0].evaluate(v).evaluate(u);  // outer variable v, inner u
      for (int k = 0; k < 3; ++k) CHECK(x[k] == f[k + 1].evaluate(v).evaluate(u) / W);
      // corners interpolate the corner control points
      CHECK(p(Q(0), Q(0)) == p.control_point(0, 0));
      CHECK(p(Q(1), Q(0)) == p.control_point(m, 0));
      CHECK(p(Q(0), Q(1)) == p.control_point(0, n));
      // subdivision in u and v, restriction, reassembly
      auto su = p.split_u(Q(1, 3));
      CHECK(su.first.restriction(Q(0), Q(3), Q(0), Q(1)) == p);
      CHECK(su.second(Q(1, 2), v) == p(Q(1, 3) + Q(2, 3) * Q(1, 2), v));
      auto sv = p.split_v(Q(3, 4));
      CHECK(sv.second(u, Q(1, 5)) == p(u, Q(3, 4) + Q(1, 4) * Q(1, 5)));
      CHECK(p.restriction(Q(1, 4), Q(1, 2), Q(0), Q(3, 4))(Q(1, 2), Q(1, 3)) == p(Q(3, 8), Q(1, 4)));
      // elevation keeps the surface
      Patch e = p.elevated(1, 2);
      CHECK(e.bidegree() == std::make_pair(m + 1, n + 2));
      CHECK(e(u, v) == x);
      // boundary curves
      auto b0 = p.boundary_curve<Curve3>(0);
      CHECK(b0(Q(1, 3)) == p(Q(1, 3), Q(0)));
      auto b1 = p.boundary_curve<Curve3>(1);
      CHECK(b1(Q(1, 3)) == p(Q(1), Q(1, 3)));
      // the box of the control net encloses sample points when weights are positive
      auto box = p.control_box();
      for (int k = 0; k < 3; ++k) CHECK((box.first[k] <= x[k] && x[k] <= box.second[k]));
    }
}

TEST_CASE("patch partial derivatives match finite differences of the exact power form", "[types]") {
  std::mt19937 g(9);
  Patch p = random_patch(g, 2, 3, true);
  auto f = p.power_form();
  using PT = CGAL::Polynomial_traits_d<Patch::Polynomial>;
  PT::Differentiate diff;
  const Q u(1, 3), v(2, 5);
  for (int dir = 0; dir < 2; ++dir) {
    auto d = p.partial_derivative(dir)(u, v);
    const Q W = f[0].evaluate(v).evaluate(u), Wd = diff(f[0], dir).evaluate(v).evaluate(u);
    for (int k = 0; k < 3; ++k) {
      const Q X = f[k + 1].evaluate(v).evaluate(u), Xd = diff(f[k + 1], dir).evaluate(v).evaluate(u);
      CHECK(d[k] == (Xd * W - X * Wd) / (W * W));  // quotient rule
    }
  }
  Patch q = random_patch(g, 3, 2, false);
  CHECK(q.partial_derivative(0).bidegree() == std::make_pair(2, 2));
  CHECK(q.partial_derivative(1).bidegree() == std::make_pair(3, 1));
}
