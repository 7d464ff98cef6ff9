// Pole detection: weights whose polynomial vanishes in the domain are rejected with an isolating interval
// (curves) or a box (patches); mixed-sign weights without a pole are accepted. Expected roots are computed
// by hand from the weight polynomials written below.
#include <catch2/catch.hpp>

#include <bezoutian/geometry/Weight_validity.h>

using namespace bezoutian;
using Q = Rational;
using Curve2 = Rational_bezier_curve_2<>;
using Patch = Rational_bezier_patch<>;

namespace {
Curve2 quadratic(const Q& w1) {
  return Curve2({{Q(0), Q(0)}, {Q(1), Q(1)}, {Q(2), Q(0)}}, {Q(1), w1, Q(1)});
}
}  // namespace

TEST_CASE("curve weights: poles are found with isolating intervals", "[validity]") {
  // W = (1-t)^2 + 2 w1 t(1-t) + t^2 = 1 + (2 w1 - 2) t + (2 - 2 w1) t^2.
  CHECK_NOTHROW(check_no_pole(quadratic(Q(3))));       // positive weights
  CHECK_NOTHROW(check_no_pole(quadratic(Q(-1, 4))));   // W = 1 - 5/2 t + 5/2 t^2, discriminant < 0
  // w1 = -1: W = (1 - 2t)^2, a double root at the rational t = 1/2
  CHECK_THROWS_WITH(check_no_pole(quadratic(Q(-1))), Catch::Contains("= 1/2"));
  // w1 = -2: W = 1 - 6t + 6t^2, roots (3 -+ sqrt 3)/6 = 0.2113..., 0.7886...
  try {
    check_no_pole(quadratic(Q(-2)));
    FAIL("a pole was not reported");
  } catch (const Invalid_input& e) {
    const std::string m = e.what();
    CHECK(m.find("isolating interval") != std::string::npos);
    CHECK(m.find("0.211") != std::string::npos);
    CHECK(m.find("1 more") != std::string::npos);
  }
}

TEST_CASE("patch weights: proved poles, unexcludable touching zeros, and valid mixed signs", "[validity]") {
  std::vector<std::vector<Patch::Point>> pts(3, std::vector<Patch::Point>(3));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) pts[i][j] = {Q(i), Q(j), Q(i * j)};
  // weights constant along v, (1, -1/4, 1) along u: W(u) > 0 although one coefficient is negative
  std::vector<std::vector<Q>> w(3, std::vector<Q>(3, Q(1)));
  for (int j = 0; j < 3; ++j) w[1][j] = Q(-1, 4);
  Pole_report<Q> ok = find_weight_zero(Patch(pts, w));
  CHECK_FALSE(ok.has_pole);
  CHECK_NOTHROW(check_no_pole(Patch(pts, w)));
  // a negative corner weight: W changes sign, a zero is proved by the intermediate value theorem
  w = std::vector<std::vector<Q>>(3, std::vector<Q>(3, Q(1)));
  w[2][2] = Q(-1);
  Pole_report<Q> bad = find_weight_zero(Patch(pts, w));
  CHECK(bad.has_pole);
  CHECK(bad.proved);
  CHECK_THROWS_WITH(check_no_pole(Patch(pts, w)), Catch::Contains("vanishes in the parameter box"));
  // W = (u - 1/3)^2 + (v - 1/3)^2 >= 0 touches 0 at (1/3, 1/3), never a dyadic corner of the subdivision:
  // signs cannot separate it, so it is rejected as unproved. Bernstein coefficients of (u - 1/3)^2 in degree 2:
  // (1/9, 1/9 - 1/3, 1/9 - 2/3 + 1) = (1/9, -2/9, 4/9); W's net is the tensor sum.
  const Q c[3] = {Q(1, 9), Q(-2, 9), Q(4, 9)};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) w[i][j] = c[i] + c[j];
  Patch touching = Patch::from_homogeneous([&] {
    Patch::Net net(3, std::vector<Patch::Homogeneous_point>(3));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) net[i][j] = {w[i][j], Q(i), Q(j), Q(1)};
    return net;
  }());
  Pole_report<Q> t = find_weight_zero(touching, Q(0), Q(1), Q(0), Q(1), 8);
  CHECK(t.has_pole);
  CHECK_FALSE(t.proved);
  // the unresolved box is one of the boxes of width 2^-8 next to the touching point
  const Q w8(1, 256);
  CHECK((t.u0 - w8 <= Q(1, 3) && Q(1, 3) <= t.u1 + w8 && t.v0 - w8 <= Q(1, 3) && Q(1, 3) <= t.v1 + w8));
  CHECK(t.u1 - t.u0 == Q(1, 256));
}
