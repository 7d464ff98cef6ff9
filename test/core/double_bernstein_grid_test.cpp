// The double-precision Bernstein grid of the subdivision (topology/internal/double_bernstein_grid.h) claims a proved
// radius: after any sequence of de Casteljau splits, every exact child coefficient lies in 2^e (m +- rho).
// Checked against the same splits in exact rational arithmetic, on coefficients with a wide dynamic range.
#include <bezoutian/topology/internal/double_bernstein_grid.h>
#include <bezoutian/topology/internal/double_double_bernstein.h>
#include <bezoutian/arithmetic/number_types.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

using bezoutian::Rational;
using bezoutian::internal::Double_bernstein_grid;

namespace {

using Exact_grid = std::vector<std::vector<Rational>>;

// exact de Casteljau split at r along u (dimension 0) or v
void exact_split(const Exact_grid& g, bool along_u, const Rational& r, Exact_grid& left, Exact_grid& right) {
  const int a = int(g.size()) - 1, b = int(g[0].size()) - 1;
  const int n = along_u ? a : b, m = along_u ? b : a;
  left = right = g;
  for (int l = 0; l <= m; ++l) {
    std::vector<Rational> w(std::size_t(n + 1));
    for (int k = 0; k <= n; ++k) w[k] = along_u ? g[k][l] : g[l][k];
    auto L = [&](int k) -> Rational& { return along_u ? left[k][l] : left[l][k]; };
    auto R = [&](int k) -> Rational& { return along_u ? right[k][l] : right[l][k]; };
    L(0) = w[0];
    R(n) = w[n];
    for (int level = 1; level <= n; ++level) {
      for (int k = 0; k + level <= n; ++k) w[k] = (1 - r) * w[k] + r * w[k + 1];
      L(level) = w[0];
      R(n - level) = w[n - level];
    }
  }
}

// exact restriction to [u0, u1] x [v0, v1]: [0, u1], then [u0/u1, 1] of it; the same in v
Exact_grid exact_restriction(const Exact_grid& c, const Rational& u0, const Rational& u1, const Rational& v0,
                             const Rational& v1) {
  Exact_grid x = c, l, r;
  exact_split(x, true, u1, l, r);
  exact_split(l, true, u0 / u1, x, r);
  exact_split(r, false, v1, l, x);
  exact_split(l, false, v0 / v1, x, r);
  return r;
}

// the exact coefficient minus 2^e m, compared with 2^e rho
bool inside(const Exact_grid& x, const Double_bernstein_grid& f) {
  const Rational scale = f.exponent() >= 0 ? Rational(bezoutian::Integer(1) << f.exponent())
                                           : Rational(1) / Rational(bezoutian::Integer(1) << -f.exponent());
  for (int i = 0; i <= f.a(); ++i)
    for (int j = 0; j <= f.b(); ++j) {
      const Rational d = CGAL::abs(x[i][j] - scale * Rational(f.at(i, j)));
      if (d > scale * Rational(f.radius())) return false;
    }
  return true;
}

}  // namespace

TEST_CASE("double Bernstein grid: the radius encloses the exact coefficients through 12 levels of splits",
          "[subdivision][double]") {
  std::mt19937_64 gen(7);
  int checks = 0;
  for (int a : {2, 9, 27})
    for (int b : {3, 16}) {
      // coefficients p / 2^k with k up to 200 bits apart: a wide dynamic range, and values that are not doubles
      Exact_grid x(std::size_t(a + 1), std::vector<Rational>(std::size_t(b + 1)));
      std::uniform_int_distribution<long> num(-1000000007L, 1000000007L);
      std::uniform_int_distribution<int> sh(0, 200);
      for (auto& row : x)
        for (auto& c : row) c = Rational(num(gen)) / Rational(bezoutian::Integer(3) << sh(gen));
      // the initial grid: nearest doubles, radius = largest rounding error rounded up
      Double_bernstein_grid f(a, b);
      double rho = 0;
      for (int i = 0; i <= a; ++i)
        for (int j = 0; j <= b; ++j) {
          f.at(i, j) = CGAL::to_double(x[i][j]);
          rho = std::max(rho, CGAL::to_interval(CGAL::abs(x[i][j] - Rational(f.at(i, j)))).second);
        }
      f.set_radius(rho);
      const double M0 = f.max_abs();
      f.rescale();
      REQUIRE(inside(x, f));
      for (int level = 0; level < 12; ++level) {
        const bool along_u = level % 2 == 0;
        const Rational r = along_u ? Rational(15, 31) : Rational(16, 33);
        Double_bernstein_grid fl, fr;
        f.split(along_u, CGAL::to_double(r), fl, fr);
        Exact_grid xl, xr;
        exact_split(x, along_u, r, xl, xr);
        REQUIRE(inside(xl, fl));
        REQUIRE(inside(xr, fr));
        // and it is not vacuous: an absolute error of a few hundred roundings of the initial largest coefficient
        CHECK(std::ldexp(fl.radius(), fl.exponent()) < 1e-12 * M0);
        CHECK(std::ldexp(fr.radius(), fr.exponent()) < 1e-12 * M0);
        checks += 2;
        // the sign tests agree with the exact signs whenever they decide
        for (const auto* side : {&fl, &fr}) {
          const Exact_grid& ex = side == &fl ? xl : xr;
          const int s = side->common_sign(side->radius());
          if (s != 0)
            for (const auto& row : ex)
              for (const auto& c : row) CHECK(CGAL::sign(c) == s);
        }
        if (gen() % 2) {
          f = fl;
          x = xl;
        } else {
          f = fr;
          x = xr;
        }
      }
    }
  CHECK(checks == 6 * 24);
}

TEST_CASE("double Bernstein grid: a positive polynomial is proved positive after splitting, a sign change never is",
          "[subdivision][double]") {
  // p(x) = (x - 1/3)^2 + 1/1000 = x^2 - 2x/3 + p0 on [0,1], constant in y; Bernstein coefficients of degree 2:
  // b0 = p(0) = p0, b1 = p0 + p'(0)/2 = p0 - 1/3, b2 = p(1) = 1 - 2/3 + p0
  const Rational p0 = Rational(1, 9) + Rational(1, 1000);
  const Rational b[3] = {p0, p0 - Rational(1, 3), Rational(1) - Rational(2, 3) + p0};
  Double_bernstein_grid f(2, 1);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) f.at(i, j) = CGAL::to_double(b[i]);
  f.set_radius(1e-17);
  CHECK(f.common_sign(f.radius()) == 0);  // b1 < 0: not decided on [0,1]
  // split near the minimum until the pieces are decided; every piece must come out positive
  std::vector<Double_bernstein_grid> todo{f};
  int positive = 0;
  while (!todo.empty() && positive < 64) {
    Double_bernstein_grid g = todo.back();
    todo.pop_back();
    const int s = g.common_sign(g.radius());
    CHECK(s >= 0);
    if (s > 0) {
      ++positive;
      continue;
    }
    Double_bernstein_grid l, r;
    g.split(true, 0.5, l, r);
    todo.push_back(l);
    todo.push_back(r);
  }
  CHECK(todo.empty());
  // x - 1/3 changes sign: no piece containing 1/3 can be decided
  Double_bernstein_grid h(1, 0);
  h.at(0, 0) = -1.0 / 3;
  h.at(1, 0) = 2.0 / 3;
  h.set_radius(1e-16);
  Double_bernstein_grid l, r;
  h.split(true, 0.25, l, r);  // [0, 1/4] negative, [1/4, 1] holds the root
  CHECK(l.common_sign(l.radius()) == -1);
  CHECK(r.common_sign(r.radius()) == 0);
  CHECK(r.difference_sign(true, r.radius()) == 1);  // increasing: d/dx > 0
}

TEST_CASE("double-double Bernstein restriction: the proved radius encloses the exact sub-box coefficients",
          "[subdivision]") {
  using bezoutian::internal::Double_double;
  using bezoutian::internal::Double_double_bernstein;
  std::mt19937 g(2026);
  std::uniform_int_distribution<int> digit(-1000000, 1000000);
  for (int trial = 0; trial < 20; ++trial) {
    const int a = 3 + trial % 5, b = 2 + trial % 7;
    // exact coefficients p / 2^40 with wide range: |c| <= 1/2 (the units of the double-double grid)
    Exact_grid c(std::size_t(a + 1), std::vector<Rational>(std::size_t(b + 1)));
    Double_double_bernstein dd(a, b);
    for (int i = 0; i <= a; ++i)
      for (int j = 0; j <= b; ++j) {
        c[i][j] = Rational(digit(g)) / Rational(2000000) + Rational(digit(g)) / Rational(1 << 30) / Rational(1 << 30);
        const double hi = CGAL::to_double(c[i][j]);
        dd.at(i, j) = Double_double{hi, CGAL::to_double(c[i][j] - Rational(hi))};
      }
    Rational err_in(0);  // the representation error of the input, an upper bound for the grid's error
    for (int i = 0; i <= a; ++i)
      for (int j = 0; j <= b; ++j)
        err_in = std::max(err_in, CGAL::abs(c[i][j] - Rational(dd.at(i, j).hi) - Rational(dd.at(i, j).lo)));
    dd.set_bounds(CGAL::to_double(err_in) * 2 + 1e-300, 1.0);
    // a deep sub-box with non-dyadic ends (as the subdivision's 15/31, 16/33 splits give)
    Rational u0(trial + 1, 97), u1 = u0 + Rational(1, 31 * 31 * 31), v0(2 * trial + 3, 89), v1 = v0 + Rational(1, 33 * 33);
    const auto f = dd.restrict_to(u0, u1, v0, v1, 0);
    const Exact_grid x = exact_restriction(c, u0, u1, v0, v1);
    CHECK(inside(x, *f));
    const double worst = std::ldexp(f->radius(), f->exponent());
    CHECK(worst <= std::ldexp(f->max_abs(), f->exponent() - 50));  // as sharp as a double grid can be
  }
  // Cancellation: (u - 1/3)(v - 2/7) on a sub-box of width ~1e-9 around its corner (1/3, 2/7): the sub-box
  // coefficients are ~1e-18 of the domain's; the radius stays far below them (a double restriction would not:
  // its error is ~1e-16 of the domain's coefficients), so the signs decide.
  const int a = 7, b = 6;
  Exact_grid c(std::size_t(a + 1), std::vector<Rational>(std::size_t(b + 1)));
  Double_double_bernstein dd(a, b);
  Rational err_in(0);
  for (int i = 0; i <= a; ++i)
    for (int j = 0; j <= b; ++j) {
      c[i][j] = (Rational(i, a) - Rational(1, 3)) * (Rational(j, b) - Rational(2, 7));  // degree elevation
      const double hi = CGAL::to_double(c[i][j]);
      dd.at(i, j) = Double_double{hi, CGAL::to_double(c[i][j] - Rational(hi))};
      err_in = std::max(err_in, CGAL::abs(c[i][j] - Rational(dd.at(i, j).hi) - Rational(dd.at(i, j).lo)));
    }
  dd.set_bounds(CGAL::to_double(err_in) * 2 + 1e-300, 1.0);
  const Rational e9(1, 1000000000);
  const Rational u0 = Rational(1, 3) - e9, u1 = Rational(1, 3) + 2 * e9, v0 = Rational(2, 7) + e9,
                 v1 = Rational(2, 7) + 3 * e9;
  const auto f = dd.restrict_to(u0, u1, v0, v1, 0);
  const Exact_grid x = exact_restriction(c, u0, u1, v0, v1);
  CHECK(inside(x, *f));
  CHECK(f->precise());
  CHECK(std::ldexp(f->max_abs(), f->exponent()) < 1e-16);
  CHECK(f->difference_sign(true, f->radius()) == 1);  // dD/du = v - 2/7 > 0 on the sub-box (a tiny positive)
}
