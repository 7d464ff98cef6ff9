// The two-branch and fold certificates (topology/internal/two_branch_box.h, fold_box.h) on Bernstein grids of
// polynomials known in closed form: the first must hold where D = 0 is two branches without a fold (D = D_y = 0) in
// the box, and fail wherever there is one; the second must hold where there is exactly one fold (D_x != 0 there), and
// fail otherwise.
#include <catch2/catch.hpp>

#include <bezoutian/topology/internal/fold_box.h>
#include <bezoutian/topology/internal/two_branch_box.h>

#include <cmath>
#include <vector>

using bezoutian::internal::Double_bernstein_grid;
using bezoutian::internal::Two_branch_box;
using bezoutian::internal::two_branch_certificate;

namespace {
double binomial(int n, int k) {
  double c = 1;
  for (int i = 1; i <= k; ++i) c = c * (n - k + i) / i;
  return c;
}
// The Bernstein grid on [0, 1]^2 of sum e[i][j] u^i v^j (power form; a, b the degrees), by the conversion
// b_kl = sum_{i <= k, j <= l} C(k, i) C(l, j) / (C(a, i) C(b, j)) e_ij, with a radius that covers its rounding.
Double_bernstein_grid grid_of(const std::vector<std::vector<double>>& e) {
  const int a = int(e.size()) - 1, b = int(e[0].size()) - 1;
  Double_bernstein_grid g(a, b);
  double M = 0;
  for (int k = 0; k <= a; ++k)
    for (int l = 0; l <= b; ++l) {
      double s = 0;
      for (int i = 0; i <= k; ++i)
        for (int j = 0; j <= l; ++j) s += binomial(k, i) * binomial(l, j) / (binomial(a, i) * binomial(b, j)) * e[i][j];
      g.at(k, l) = s;
      M = std::max(M, std::fabs(s));
    }
  g.set_radius(1e-13 * M);
  return g;
}
}  // namespace

TEST_CASE("two-branch certificate: two parallel lines, horizontal or slanted, are two branches without a fold",
          "[topology][subdivision][two_branch]") {
  // (v - 1/2)^2 - 1/4096: the lines v = 1/2 +- 1/64 (D_v = 0 on v = 1/2, where D = -1/4096 < 0)
  Two_branch_box t = two_branch_certificate(grid_of({{0.25 - 1.0 / 4096, -1, 1}}));
  CHECK(t.axis == 0);
  CHECK(t.sigma == 1);
  // (v - u/2 - 1/4)^2 - 1/4096: slanted lines; D_v changes sign on every strip, so only the segment along the
  // midline v = u/2 + 1/4 proves the absence of a fold
  const double c = 1.0 / 16 - 1.0 / 4096;  // (1/4)^2 - delta^2
  t = two_branch_certificate(grid_of({{c, -0.5, 1}, {0.25, -1, 0}, {0.25, 0, 0}}));
  CHECK(t.axis == 0);
  CHECK(t.sigma == 1);
  // graphs over v only (D is linear in v): u = 1/2 +- sqrt((1 + v) / 4096), written -D so that sigma = -1
  const double d = 1.0 / 4096;
  t = two_branch_certificate(grid_of({{d - 0.25, d}, {1, 0}, {-1, 0}}));
  CHECK(t.axis == 1);
  CHECK(t.sigma == -1);
}

TEST_CASE("two-branch certificate: a fold inside the box (a vertical or horizontal tangent, a node) is refused",
          "[topology][subdivision][two_branch]") {
  // the circle (u - 1/2)^2 + (v - 1/2)^2 = 1/16: D_uu, D_vv > 0, but folds at (1/2 +- 1/4, 1/2) and (1/2, 1/2 +- 1/4)
  CHECK(two_branch_certificate(grid_of({{0.5 - 1.0 / 16, -1, 1}, {-1, 0, 0}, {1, 0, 0}})).axis == -1);
  // the parabola (v - 1/2)^2 = (u - 1/2) / 4: a vertical tangent at (1/2, 1/2); D is linear in u
  CHECK(two_branch_certificate(grid_of({{0.25 + 0.125, -1, 1}, {-0.25, 0, 0}})).axis == -1);
  // two lines crossing at (1/2, 1/2) with nearly equal slopes: (v - 1/2)^2 - (u - 1/2)^2 / 10000 (a node: D = D_v = 0)
  const double k = 1e-4;
  CHECK(two_branch_certificate(grid_of({{0.25 - 0.25 * k, -1, 1}, {k, 0, 0}, {-k, 0, 0}})).axis == -1);
  // a single line crosses nothing twice, but D = (v - 1/2) has no second derivative: not this certificate's case
  CHECK(two_branch_certificate(grid_of({{-0.5, 1}})).axis == -1);
}

TEST_CASE("fold certificate: a parabola's vertical tangent is one fold, enclosed; two folds, a cusp, a node are refused",
          "[topology][subdivision][fold]") {
  using bezoutian::internal::Fold_box;
  using bezoutian::internal::fold_certificate;
  auto holds = [](const Fold_box& f, double x, double y) {
    CHECK(f.xa < x);
    CHECK(x < f.xb);
    CHECK(f.ya < y);
    CHECK(y < f.yb);
    CHECK(f.xb - f.xa < 1e-2);
    CHECK(f.yb - f.ya < 1e-2);
  };
  // (v - 1/2)^2 = (u - 1/2) / 4: the fold (1/2, 1/2) (D = D_v = 0, D_u = -1/4), the curve on its side u > 1/2;
  // the fold lies on one of the lines that locate it
  Fold_box f = fold_certificate(grid_of({{0.375, -1, 1}, {-0.25, 0, 0}}));
  CHECK(f.axis == 0);
  CHECK(f.sigma == 1);
  CHECK(f.curve_side == 1);
  holds(f, 0.5, 0.5);
  // mirrored, (v - 1/2)^2 = (1/2 - u) / 4 (curve on u < 1/2), and off the sample lines, (v - 1/2)^2 = (u - 0.3) / 4
  f = fold_certificate(grid_of({{0.125, -1, 1}, {0.25, 0, 0}}));
  CHECK(f.axis == 0);
  CHECK(f.curve_side == -1);
  holds(f, 0.5, 0.5);
  f = fold_certificate(grid_of({{0.25 + 0.075, -1, 1}, {-0.25, 0, 0}}));
  CHECK(f.axis == 0);
  CHECK(f.curve_side == 1);
  holds(f, 0.3, 0.5);
  // the same turned over, (u - 1/2)^2 = (v - 1/2) / 4: a horizontal tangent, a fold with y = u; -D: sigma = -1
  f = fold_certificate(grid_of({{-0.375, 0.25}, {1, 0}, {-1, 0}}));
  CHECK(f.axis == 1);
  CHECK(f.sigma == -1);
  CHECK(f.curve_side == 1);
  holds(f, 0.5, 0.5);
  // the circle (u - 1/2)^2 + (v - 1/2)^2 = 1/16: two folds across each axis
  CHECK(fold_certificate(grid_of({{0.5 - 1.0 / 16, -1, 1}, {-1, 0, 0}, {1, 0, 0}})).axis == -1);
  // the cusp (v - 1/2)^2 = (u - 1/2)^3: D = D_v = 0 and the least value of D on the lines u = const changes sign at
  // u = 1/2, but D_u = 0 there too (a singular point, not a fold); D_uu changes sign, so no fold with y = u either
  CHECK(fold_certificate(grid_of({{0.375, -1, 1}, {-0.75, 0, 0}, {1.5, 0, 0}, {-1, 0, 0}})).axis == -1);
  // a node with nearly tangent branches, (v - 1/2)^2 = (u - 1/2)^2 / 10000, and two parallel lines: no sign change
  const double k = 1e-4;
  CHECK(fold_certificate(grid_of({{0.25 - 0.25 * k, -1, 1}, {k, 0, 0}, {-k, 0, 0}})).axis == -1);
  CHECK(fold_certificate(grid_of({{0.25 - 1.0 / 4096, -1, 1}})).axis == -1);
  // The strip test itself, on the first parabola with y-windows chosen by hand: [0.49, 0.51] holds the minimisers
  // v = 1/2 of the lines, and the strip around u = 1/2 passes; [0.501, 0.6] misses them (D_v changes sign below the
  // window), although D_u = -1/4 keeps its sign on it and the least values at the strip's ends have opposite signs,
  using bezoutian::internal::fold::Window;
  const auto parabola = grid_of({{0.375, -1, 1}, {-0.25, 0, 0}});
  bezoutian::internal::two_branch::Grid<double> M{1, 2, {parabola.at(0, 0), parabola.at(0, 1), parabola.at(0, 2),
                                                         parabola.at(1, 0), parabola.at(1, 1), parabola.at(1, 2)}};
  const double d = 1.0 / 256;
  int side = 0;
  std::size_t strips = 0;
  CHECK(bezoutian::internal::fold::fold_strip(M, 1, {Window{0.5 - d, 0.5 + d, 0.49, 0.51}}, side, strips));
  CHECK(side == 1);
  CHECK_FALSE(bezoutian::internal::fold::fold_strip(M, 1, {Window{0.5 - d, 0.5 + d, 0.501, 0.6}}, side, strips));
  // ... and a strip around u = 0.3, beside the fold: the least values at its ends are both positive
  CHECK_FALSE(bezoutian::internal::fold::fold_strip(M, 1, {Window{0.3 - d, 0.3 + d, 0.49, 0.51}}, side, strips));
}
