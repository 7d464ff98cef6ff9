// The partner equations re-expanded about a point (lifting/internal/centred_partner_equations.h), checked against
// the exact values of the equations as written (Partner_equations::exact_values, rational arithmetic) at rational
// points, and the reason they exist: next to the tangent point of Viviani's sphere and cylinder their enclosures
// shrink with the distance to the centre, where those of the equations as written stay at rounding level, and
// Krawczyk's test along the half-branch succeeds much closer to the node.
#include <catch2/catch.hpp>

#include <bezoutian/lifting/internal/centred_partner_equations.h>
#include <bezoutian/lifting/internal/partner_span_proofs.h>
#include "power_patch.h"

#include <cmath>
#include <random>

using namespace bezoutian;
using internal::Double_interval;

namespace {
// The sphere with longitude and latitude 2 atan((2u - 1)/2), 2 atan((2v - 1)/2), and the cylinder
// (x - 1/2)^2 + y^2 = 1/4 with angle 2 atan((2s - 1)/2), z = 2t - 1: tangent at (1, 0, 0), the parameters
// (u, v) = (1/2, 1/2) on the sphere and (s, t) = (1/2, 1/2) on the cylinder.
Rational_bezier_patch<> sphere() {
  const std::string a = "((2*u-1)/2)", b = "((2*v-1)/2)";
  return bezoutian_test::rational_patch_from_power(
      {"(1-" + a + "^2)*(1-" + b + "^2)", "2*" + a + "*(1-" + b + "^2)", "2*" + b + "*(1+" + a + "^2)",
       "(1+" + a + "^2)*(1+" + b + "^2)"}, 2, 2);
}
Rational_bezier_patch<> cylinder() {
  const std::string a = "((2*u-1)/2)";
  return bezoutian_test::rational_patch_from_power({"1", a, "(2*v-1)*(1+" + a + "^2)", "1+" + a + "^2"}, 2, 1);
}
bool contains(const Double_interval& x, const Rational& q) { return Rational(x.lo) <= q && q <= Rational(x.hi); }
}  // namespace

TEST_CASE("Centred partner equations enclose the exact values of the equations as written", "[centred]") {
  const internal::Partner_equations two(sphere(), cylinder());
  const internal::Partner_equations self(bezoutian_test::rational_patch_from_power(
      {"u + v^2", "u*v - u^3", "v + u^2*v^2", "1 + (u^2)/4"}, 3, 2));
  std::mt19937 g(7);
  std::uniform_int_distribution<int> num(-40, 40);
  for (const internal::Partner_equations* eq : {&two, &self}) {
    const std::array<double, 4> zc{0.4375, 0.625, 0.3125, 0.5625};
    const internal::Centred_partner_equations ceq(*eq, zc);
    for (int trial = 0; trial < 40; ++trial) {
      std::array<Rational, 4> z;
      std::array<Double_interval, 4> box;
      for (int i = 0; i < 4; ++i) {
        const Rational offset(num(g), 1024);
        z[std::size_t(i)] = Rational(zc[std::size_t(i)]) + offset;
        box[std::size_t(i)] = Double_interval::of(offset);  // (the centred equations take z - z_c)
      }
      std::array<Rational, 2> w;
      const std::array<Rational, 3> exact = eq->exact_values(z, w);
      std::array<Double_interval, 3> E;
      std::array<std::array<Double_interval, 4>, 3> J;
      ceq.evaluate(box, E, &J);
      for (int c = 0; c < 3; ++c) CHECK(contains(E[std::size_t(c)], exact[std::size_t(c)]));
      // the Jacobian against central differences of the exact values (step 2^-20: an error of order 1e-12)
      const Rational h(1, 1 << 20);
      for (int i = 0; i < 4; ++i) {
        std::array<Rational, 4> zp = z, zm = z;
        zp[std::size_t(i)] += h;
        zm[std::size_t(i)] -= h;
        const auto ep = eq->exact_values(zp, w), em = eq->exact_values(zm, w);
        for (int c = 0; c < 3; ++c) {
          const double slope = CGAL::to_double((ep[std::size_t(c)] - em[std::size_t(c)]) / (2 * h));
          CHECK(std::fabs(slope - J[std::size_t(c)][std::size_t(i)].mid()) < 1e-8);
        }
      }
    }
  }
}

TEST_CASE("Centred partner equations: enclosures shrink towards the tangent point, and Krawczyk's test holds there",
          "[centred]") {
  const internal::Partner_equations eq(sphere(), cylinder());
  // the half-branch of Viviani's curve with h > 0 and z > 0: the sphere's (u, v) = (tan(h/2) + 1/2, tan(h/2) + 1/2),
  // the cylinder's (s, t) = (tan h + 1/2, (1 + sin h)/2); projection (u, t), partner (v, s)
  auto at = [](double h) {
    return std::array<double, 4>{std::tan(h / 2) + 0.5, (1 + std::sin(h)) / 2, std::tan(h / 2) + 0.5, std::tan(h) + 0.5};
  };
  for (double d : {1e-6, 1e-8, 1e-10}) {
    const std::array<double, 4> z = at(2 * d);  // u - 1/2 is about d
    const internal::Centred_partner_equations ceq(eq, z);
    std::array<Double_interval, 4> point, zero;
    for (int i = 0; i < 4; ++i) point[std::size_t(i)] = Double_interval{z[std::size_t(i)], z[std::size_t(i)]};
    std::array<Double_interval, 3> E_written, E_centred;
    eq.evaluate(point, E_written);
    ceq.evaluate(zero, E_centred);
    for (int c = 0; c < 3; ++c) {
      // as written, E's enclosure is a few ulps of the products' size (about 1); centred, the terms are exact
      // rationals rounded once: at the centre the constant term (the residual, about 1e-16) and one ulp of it
      // per term
      CHECK(E_written[std::size_t(c)].hi - E_written[std::size_t(c)].lo > 1e-17);
      CHECK(E_centred[std::size_t(c)].hi - E_centred[std::size_t(c)].lo < 1e-27);
    }
    // Krawczyk's test over a span of t of width d / 8 beside the point, on the box predicted by Newton's method
    // (relative to the centre: T - t_c, the guess 0)
    const Double_interval T_rel{0, d / 8};
    std::array<Double_interval, 3> W, K;
    const bool centred =
        internal::predict_partner_box(ceq, 1, T_rel, {0, 0, 0}, W, 0) && internal::prove_zero_curve(ceq, 1, T_rel, W, K, true, 0);
    CHECK(centred);
    // the zero curve's box holds the closed form's partner at t_c + d / 16 (h solves (1 + sin h)/2 = t)
    const double h = std::asin(2 * (z[1] + d / 16) - 1);
    CHECK(std::fabs(K[1].mid() + z[2] - (std::tan(h / 2) + 0.5)) < 1e-3 * d);
    if (d <= 1e-8) {  // as written, the test fails there
      const Double_interval T{z[1], z[1] + d / 8};
      std::array<Double_interval, 3> W2, K2;
      const bool written =
          internal::predict_partner_box(eq, 1, T, {z[0], z[2], z[3]}, W2) && internal::prove_zero_curve(eq, 1, T, W2, K2);
      CHECK_FALSE(written);
    }
  }
}
