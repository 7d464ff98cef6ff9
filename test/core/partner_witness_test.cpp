// The geometric proofs used by the surface topology (lifting/double_partner_witness.h): exclusion of regions
// without genuine points, and the two-partner witness of a node. Checked against facts known independently:
// a graph z = f(u,v) cannot self-intersect; a constructed pair with a node in closed form; and, on random patches,
// a numerical partner search written here (a grid plus Gauss-Newton on the patches' own evaluation), which must
// never find a partner inside the domain for a point of a region proved free of them.
#include <catch2/catch.hpp>

#include <bezoutian/lifting/certified_lifting.h>
#include <bezoutian/lifting/double_partner_witness.h>
#include <bezoutian/io/Geometry_document.h>
#include "power_patch.h"

#include <cmath>
#include <random>

using namespace bezoutian;
using Q = Rational;
using Patch = Rational_bezier_patch<>;

namespace {
Patch from_power(const std::array<std::string, 3>& xyz, int m, int n) {
  return bezoutian_test::patch_from_power(xyz, m, n);
}

Patch random_patch(std::mt19937& g, int m, int n, bool rational) {
  std::uniform_int_distribution<int> c(-5, 5), w(1, 4);
  std::vector<std::vector<Patch::Point>> p(m + 1, std::vector<Patch::Point>(n + 1));
  std::vector<std::vector<Q>> wt(m + 1, std::vector<Q>(n + 1, Q(1)));
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j) {
      p[i][j] = {Q(c(g)), Q(c(g)), Q(c(g))};
      if (rational) wt[i][j] = Q(w(g));
    }
  return Patch(p, wt);
}

// Smallest |r(a, b)| over a, b in [0,1] found from an 8 x 8 grid of starts with Gauss-Newton (central
// differences), skipping solutions with trivial(a, b). Independent of the code under test.
template <class R, class T>
double smallest_residual(R r, T trivial) {
  double best = 1e300;
  for (int i = 0; i <= 7; ++i)
    for (int j = 0; j <= 7; ++j) {
      double a = i / 7.0, b = j / 7.0;
      for (int it = 0; it < 30; ++it) {
        const double h = 1e-7;
        const auto r0 = r(a, b), ra1 = r(a + h, b), ra0 = r(a - h, b), rb1 = r(a, b + h), rb0 = r(a, b - h);
        double a11 = 0, a12 = 0, a22 = 0, g1 = 0, g2 = 0;
        for (int c = 0; c < 3; ++c) {
          const double ja = (ra1[c] - ra0[c]) / (2 * h), jb = (rb1[c] - rb0[c]) / (2 * h);
          a11 += ja * ja;
          a12 += ja * jb;
          a22 += jb * jb;
          g1 += ja * r0[c];
          g2 += jb * r0[c];
        }
        const double det = a11 * a22 - a12 * a12;
        if (!(std::fabs(det) > 1e-300)) break;
        a -= (a22 * g1 - a12 * g2) / det;
        b -= (a11 * g2 - a12 * g1) / det;
        if (!(std::fabs(a) < 3 && std::fabs(b) < 3)) break;
      }
      if (a < -1e-9 || a > 1 + 1e-9 || b < -1e-9 || b > 1 + 1e-9 || trivial(a, b)) continue;
      const auto q = r(a, b);
      best = std::min(best, std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]));
    }
  return best;
}
std::array<double, 3> difference(const std::array<double, 3>& p, const std::array<double, 3>& q) {
  return {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
}
}  // namespace

TEST_CASE("a graph z = f(u,v) has no self-intersection: every box is proved free of partners", "[surface][witness]") {
  const Patch graph = from_power({"u", "v", "u^3 - 3*u*v^2 + v"}, 3, 3);
  const internal::Partner_equations eq(graph);
  int proved = 0;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      const Parameter_box b{Q(i, 8), Q(i + 1, 8), Q(j, 8), Q(j + 1, 8)};
      proved += internal::no_genuine_partner(eq, b, Parameter_box{}, 4096);
    }
  CHECK(proved == 64);
}

TEST_CASE("regions proved free of genuine partners have none (numerical search on random patches)",
          "[surface][witness]") {
  std::mt19937 g(7);
  int proved = 0, tested = 0;
  for (int k = 0; k < 4; ++k) {
    const bool rational = k % 2 == 1;
    const Patch a = random_patch(g, 2, 2, rational), b = random_patch(g, 2, 2, rational);
    for (bool self : {true, false}) {
      const internal::Partner_equations eq = self ? internal::Partner_equations(a) : internal::Partner_equations(a, b);
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
          const Parameter_box box{Q(i, 6), Q(i + 1, 6), Q(j, 6), Q(j + 1, 6)};
          ++tested;
          if (!internal::no_genuine_partner(eq, box, Parameter_box{})) continue;
          ++proved;
          // sample points x of the box: no genuine partner may exist there
          for (int p = 0; p < 2; ++p)
            for (int q = 0; q < 2; ++q) {
              const double x1 = (i + (p + 0.5) / 2) / 6, x2 = (j + (q + 0.5) / 2) / 6;
              double best;
              if (self)  // (x1, p2) and (q1, x2) with the same image, not the same point
                best = smallest_residual(
                    [&](double p2, double q1) { return difference(a.evaluate(x1, p2), a.evaluate(q1, x2)); },
                    [&](double p2, double q1) { return std::fabs(p2 - x2) + std::fabs(q1 - x1) < 1e-4; });
              else  // phi(x1, v) = psi(s, x2)
                best = smallest_residual(
                    [&](double v, double s2) { return difference(a.evaluate(x1, v), b.evaluate(s2, x2)); },
                    [](double, double) { return false; });
              CHECK(best > 1e-7);
            }
        }
    }
  }
  CHECK(proved >= 20);  // the exclusion is effective, not only sound (50 of 288 boxes of width 1/6)
}

// Phi(u,v) = (u, v, 0), Psi(s,t) = (s^2 + (t^2 - 1/2) s, t, s^2 - t - 1/4): the projected curve D(u,t) = 0 has a node
// at t = 1/sqrt(2), u = t + 1/4 with the two partners s = +-sqrt(t + 1/4), v = t (closed form: see
// surface_intersection_test.cpp).
TEST_CASE("the two-partner witness proves the node and nothing at regular points", "[surface][witness]") {
  const Patch phi = from_power({"u", "v", "0"}, 2, 2);
  const Patch psi = from_power({"u^2 + u*(v^2 - 1/2)", "v", "u^2 - v - 1/4"}, 2, 2);
  const internal::Partner_equations eq(phi, psi);
  const double tn = std::sqrt(0.5), un = tn + 0.25;
  const Parameter_box around{Q(un - 1e-3), Q(un + 1e-3), Q(tn - 1e-3), Q(tn + 1e-3)};
  CHECK(internal::prove_double_partner_point(eq, around, {un, tn}));
  // the node is not in this box: no proof
  const Parameter_box beside{Q(un + 1e-3), Q(un + 3e-3), Q(tn - 1e-3), Q(tn + 1e-3)};
  CHECK_FALSE(internal::prove_double_partner_point(eq, beside, {un + 2e-3, tn}));
  // a regular point of one branch (t = 0.3, s = +sqrt(0.55)): one partner only
  const double t = 0.3, s = std::sqrt(t + 0.25), u = t + 0.25 + (t * t - 0.5) * s;
  const Parameter_box reg{Q(u - 1e-3), Q(u + 1e-3), Q(t - 1e-3), Q(t + 1e-3)};
  CHECK_FALSE(internal::prove_double_partner_point(eq, reg, {u, t}));
  // regions: the node's partners have s = +-0.978, v = t: genuine for the domain [-1,1]^2 (not excluded), none for
  // a domain with s in [0.99, 1]
  CHECK_FALSE(internal::no_genuine_partner(eq, around, Parameter_box{Q(-1), Q(1), Q(-1), Q(1)}));
  CHECK(internal::no_genuine_partner(eq, around, Parameter_box{Q(99, 100), Q(1), Q(-1), Q(1)}));
}

TEST_CASE("the two-partner witness with far partners (a stretched partner parameter)", "[surface][witness]") {
  // The node of the previous test with psi's first parameter stretched, s = sigma / c: the partners become
  // sigma = +-0.978 c. Newton on the 6 x 6 system stalls at the rounding level of sigma (steps ~ 1e-14 c), which
  // the witness must accept (only its Krawczyk test decides); a Newton stopping test not scaled by the largest
  // unknown refuses every c >= 1000 (a (3,3) rational benchmark pair has a node with a partner at v = -46).
  const Patch phi = from_power({"u", "v", "0"}, 2, 2);
  const double tn = std::sqrt(0.5), un = tn + 0.25;
  const Parameter_box around{Q(un - 1e-3), Q(un + 1e-3), Q(tn - 1e-3), Q(tn + 1e-3)};
  for (const char* c : {"50", "1000", "100000"}) {
    INFO(c);
    const std::string s = "(u/" + std::string(c) + ")";
    const Patch psi = from_power({s + "^2 + " + s + "*(v^2 - 1/2)", "v", s + "^2 - v - 1/4"}, 2, 2);
    const internal::Partner_equations eq(phi, psi);
    CHECK(internal::prove_double_partner_point(eq, around, {un, tn}));
    const double t = 0.3, sr = std::sqrt(t + 0.25), u = t + 0.25 + (t * t - 0.5) * sr;
    const Parameter_box reg{Q(u - 1e-3), Q(u + 1e-3), Q(t - 1e-3), Q(t + 1e-3)};
    CHECK_FALSE(internal::prove_double_partner_point(eq, reg, {u, t}));
  }
}

TEST_CASE("partners of a bi-degree (3,2) self-intersection: the folded patch's double line, in closed form",
          "[surface][witness]") {
  // Phi(u,v) = ((u - 1/2)^2, v^2, (u - 1/2)(v - 1/3)) as a (3,2) patch (x degree-elevated in u). Phi(u, 1/3) =
  // Phi(1 - u, 1/3): the line v = 1/3 is a double curve. With P = (u, v + k), Q = (u + l, v) the partner of
  // (u, 1/3) is (l, k) = (1 - 2u, 0) and no other (k = -2/3 makes the z's differ). The equations have degree 3
  // in l but 2 in k; a common formal degree 3 would make the Sylvester resultant vanish, and no partner be found.
  const auto phi = bezoutian_test::patch_from_power({"(u-1/2)^2", "v^2", "(u-1/2)*(v-1/3)"}, 3, 2);
  const bezoutian::internal::Partner_equations eq(phi);
  CHECK(eq.degree_bounds()[0] == 3);
  CHECK(eq.degree_bounds()[1] == 2);
  for (double u : {0.1, 0.3, 0.45, 0.8}) {
    const auto partners = bezoutian::internal::numerical_partners(eq, {u, 1.0 / 3});
    REQUIRE(partners.size() == 1);
    CHECK(std::abs(partners[0][0] - std::complex<double>(1 - 2 * u)) < 1e-8);
    CHECK(std::abs(partners[0][1]) < 1e-8);
  }
}

namespace {
// Forward-mode derivative over the rationals: exact values and first derivatives, independent of the library.
struct Dual {
  Q v, d;
  Dual(const Q& value = Q(0), const Q& derivative = Q(0)) : v(value), d(derivative) {}
};
Dual operator+(const Dual& a, const Dual& b) { return {a.v + b.v, a.d + b.d}; }
Dual operator-(const Dual& a, const Dual& b) { return {a.v - b.v, a.d - b.d}; }
Dual operator*(const Dual& a, const Dual& b) { return {a.v * b.v, a.v * b.d + a.d * b.v}; }
// homogeneous coordinate k (0: the weight) of the patch at (u, v), from its Bernstein net
Dual homogeneous(const Patch& p, int k, const Dual& u, const Dual& v) {
  const auto& net = p.homogeneous_net();
  const int m = int(net.size()) - 1, n = int(net[0].size()) - 1;
  auto basis = [](int deg, int i, const Dual& t) {
    Dual r(Q(1));
    Q binomial(1);
    for (int s = 1; s <= i; ++s) binomial = binomial * Q(deg - i + s) / Q(s);
    for (int s = 0; s < i; ++s) r = r * t;
    for (int s = 0; s < deg - i; ++s) r = r * (Dual(Q(1)) - t);
    return r * Dual(binomial);
  };
  Dual sum;
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j) sum = sum + Dual(net[i][j][k]) * basis(m, i, u) * basis(n, j, v);
  return sum;
}
}  // namespace

// The phantom exclusion evaluates the partner equations through Partner_equations::Restriction (x fixed to a
// box, many partner boxes y). Its enclosures must hold the exact values E_c(z) = Phi_c(P) Psi_0(Q) -
// Psi_c(Q) Phi_0(P) and the exact derivatives dE_c/dz_i at rational points z of box x piece, computed here from
// the Bernstein nets with exact dual numbers.
TEST_CASE("partner equations restricted to a box enclose the exact values and derivatives", "[surface][witness]") {
  using D = internal::Double_interval;
  std::mt19937 g(20261122);
  std::uniform_int_distribution<int> end(-24, 88), pick(0, 1000);
  auto interval = [&]() {  // rational ends in [-3/8, 11/8]: both signs, and pieces outside [0, 1]
    int p = end(g), q = end(g);
    if (p > q) std::swap(p, q);
    if (p == q) ++q;
    return std::array<Q, 2>{Q(p, 64), Q(q, 64)};
  };
  for (int trial = 0; trial < 24; ++trial) {
    const bool self = trial % 2 == 0, rational = trial % 4 >= 2;
    const int m = 1 + trial % 3, n = 1 + (trial / 3) % 3;
    const Patch phi = random_patch(g, m, n, rational), other = random_patch(g, n, m, rational);
    const Patch& psi = self ? phi : other;
    const internal::Partner_equations eq = self ? internal::Partner_equations(phi) : internal::Partner_equations(phi, psi);
    const std::array<std::array<Q, 2>, 4> box{interval(), interval(), interval(), interval()};  // x1, x2, y1, y2
    const internal::Partner_equations::Restriction R(eq, D::hull(box[0][0], box[0][1]), D::hull(box[1][0], box[1][1]));
    std::array<D, 3> E, E_only;
    std::array<std::array<D, 4>, 3> J;
    R.evaluate({D::hull(box[2][0], box[2][1]), D::hull(box[3][0], box[3][1])}, E, &J);
    R.evaluate({D::hull(box[2][0], box[2][1]), D::hull(box[3][0], box[3][1])}, E_only);
    for (int sample = 0; sample < 6; ++sample) {
      std::array<Q, 4> z;
      for (int i = 0; i < 4; ++i) z[i] = box[i][0] + (box[i][1] - box[i][0]) * Q(pick(g), 1000);
      for (int i = 0; i < 4; ++i) {  // derivative along z_i
        std::array<Dual, 4> w;
        for (int c = 0; c < 4; ++c) w[c] = Dual(z[c], Q(c == i ? 1 : 0));
        const Dual p0 = self ? w[0] : w[0], p1 = self ? w[1] + w[3] : w[2];
        const Dual q0 = self ? w[0] + w[2] : w[3], q1 = w[1];
        for (int c = 1; c <= 3; ++c) {
          const Dual e = homogeneous(phi, c, p0, p1) * homogeneous(psi, 0, q0, q1) -
                         homogeneous(psi, c, q0, q1) * homogeneous(phi, 0, p0, p1);
          INFO("trial " << trial << " equation " << c << " variable " << i);
          CHECK(Q(E[c - 1].lo) <= e.v);
          CHECK(e.v <= Q(E[c - 1].hi));
          CHECK(Q(E_only[c - 1].lo) <= e.v);
          CHECK(e.v <= Q(E_only[c - 1].hi));
          CHECK(Q(J[c - 1][i].lo) <= e.d);
          CHECK(e.d <= Q(J[c - 1][i].hi));
        }
      }
    }
  }
}

// Double_interval's outward rounding (widen: each end moved by |end| 2^-52 + 2^-1074 after rounding to nearest)
// against exact rational results, on random operands of magnitudes 2^-1060 .. 2^1000 (subnormal results
// included), and on overflow: an end that overflows must not produce a finite or empty enclosure.
TEST_CASE("outward-rounded double intervals enclose exact sums, differences and products", "[surface][witness]") {
  using D = internal::Double_interval;
  std::mt19937_64 g(18);
  std::uniform_real_distribution<double> mant(-2, 2);
  std::uniform_int_distribution<int> ex(-1060, 1000);
  std::size_t tight = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double a = std::ldexp(mant(g), ex(g) / (trial % 2 ? 1 : 40)), b = std::ldexp(mant(g), ex(g) / (trial % 3 ? 1 : 40));
    const D x{a, a}, y{b, b};
    const Q qa(a), qb(b);
    const D r[3] = {x + y, x - y, x * y};
    const Q e[3] = {qa + qb, qa - qb, qa * qb};
    for (int k = 0; k < 3; ++k) {
      INFO("a = " << a << " b = " << b << " op " << k);
      REQUIRE(r[k].lo <= r[k].hi);
      if (!std::isfinite(r[k].lo) || !std::isfinite(r[k].hi)) continue;  // overflow: checked below
      CHECK(Q(r[k].lo) <= e[k]);
      CHECK(e[k] <= Q(r[k].hi));
      tight += r[k].hi - r[k].lo <= std::fabs(r[k].mid()) * 0x1p-49 + 0x1p-1071;  // a few ulps
    }
  }
  CHECK(tight > 50000);
  // overflow: DBL_MAX + DBL_MAX rounds to +inf; the exact 2 DBL_MAX is finite, so the lower end must not be +inf
  // (moving +inf "down by one ulp" leaves it at +inf: the enclosure would be empty of the exact value), and
  // likewise -DBL_MAX * DBL_MAX must not get the upper end -inf
  const double M = std::numeric_limits<double>::max();
  const D o = D{M, M} + D{M, M};
  CHECK(o.hi == HUGE_VAL);
  CHECK(o.lo < HUGE_VAL);
  const D n = D{-M, -M} * D{M, M};
  CHECK(n.lo == -HUGE_VAL);
  CHECK(n.hi > -HUGE_VAL);
}

// interval_horner (the hot loop of the exclusions) rounds to nearest and widens once at the end by an a-priori
// bound (Lazy_horner). Checked against exact rational evaluation: at point arguments where massive cancellation
// makes the exact value 0 ((x - a)^n expanded, a a double), and at the ends and inside of random intervals with
// coefficients of mixed signs and magnitudes 2^-40 .. 2^40, nonnegative arguments (parameters in a domain) and
// arguments of any sign (partner boxes reach below 0); the enclosures must also be narrow (a
// test that cannot fail would accept infinite ones).
TEST_CASE("interval Horner with one rounding bound encloses exact values", "[surface][witness]") {
  using D = internal::Double_interval;
  std::mt19937 g(7);
  std::uniform_int_distribution<int> num(-1000, 1000), expo(-40, 40), pick(0, 64);
  auto exact_1 = [](const std::vector<Q>& c, const Q& x) {
    Q r = 0;
    for (std::size_t i = c.size(); i-- > 0;) r = r * x + c[i];
    return r;
  };
  auto enclose = [](const std::vector<Q>& c) {
    std::vector<D> r;
    for (const Q& q : c) r.push_back(D::of(q));
    return r;
  };
  int narrow[2] = {0, 0};  // point arguments with rounding-only widths: nonnegative, signed
  for (int n = -12; n <= 12; ++n) {  // (x - a)^n at x = a: the exact value 0 after cancellation
    if (n == 0) continue;
    const double a = n > 0 ? 0.1 * n + 0.3 : 0.1 * n - 0.3;  // a double: the argument is a point interval
    const int degree = std::abs(n);
    std::vector<Q> c{Q(1)};
    for (int k = 0; k < degree; ++k) {  // multiply by (x - a)
      std::vector<Q> d(c.size() + 1, Q(0));
      for (std::size_t i = 0; i < c.size(); ++i) {
        d[i + 1] += c[i];
        d[i] -= c[i] * Q(a);
      }
      c = d;
    }
    const D r = internal::interval_horner(enclose(c), D{a, a});
    CHECK(r.lo <= 0);
    CHECK(0 <= r.hi);
    // n roundings of the magnitude sum |c_i| |a|^i = (2|a|)^n
    CHECK(r.hi - r.lo < 1e-14 * degree * std::pow(2 * std::fabs(a), degree));
    // bivariate: rows (x - a)^n y^j with y = [0.5, 0.75] (or [-0.75, 0.5])
    std::vector<std::vector<D>> c2(3, enclose(c));
    const D r2 = internal::interval_horner(c2, D{a, a}, n > 0 ? D{0.5, 0.75} : D{-0.75, 0.5});
    CHECK(r2.lo <= 0);
    CHECK(0 <= r2.hi);
  }
  for (int trial = 0; trial < 600; ++trial) {
    const int n = 1 + trial % 9, rows = 1 + trial % 4;
    const bool signed_arguments = trial >= 300;  // x in [-1, 1], y in [-1/2, 9/16]
    std::vector<std::vector<Q>> c(rows, std::vector<Q>(n + 1));
    for (auto& row : c)
      for (Q& q : row) {
        const int e = expo(g);
        q = Q(num(g)) * (e >= 0 ? Q(1L << (e / 2)) * Q(1L << (e - e / 2)) : Q(1) / (Q(1L << (-e / 2)) * Q(1L << (-e - (-e / 2)))));
      }
    int p = pick(g), q = pick(g);
    if (p > q) std::swap(p, q);
    const Q shift = signed_arguments ? Q(1) : Q(0), shift_y = signed_arguments ? Q(1, 2) : Q(0);
    const Q x0 = Q(p, 32) - shift, x1 = Q(q, 32) - shift, y0 = Q(pick(g), 64) - shift_y, y1 = y0 + Q(1, 16);
    const D X = D::hull(x0, x1), Y = D::hull(y0, y1);
    std::vector<std::vector<D>> ci;
    for (const auto& row : c) ci.push_back(enclose(row));
    const D r1 = internal::interval_horner(ci[0], X), r2 = internal::interval_horner(ci, X, Y);
    for (int s = 0; s <= 4; ++s) {
      const Q x = x0 + (x1 - x0) * Q(s, 4), y = y0 + (y1 - y0) * Q(4 - s, 4);
      const Q e1 = exact_1(c[0], x);
      Q e2 = 0;
      for (std::size_t j = c.size(); j-- > 0;) e2 = e2 * y + exact_1(c[j], x);
      INFO("trial " << trial << " sample " << s);
      CHECK(Q(r1.lo) <= e1);
      CHECK(e1 <= Q(r1.hi));
      CHECK(Q(r2.lo) <= e2);
      CHECK(e2 <= Q(r2.hi));
    }
    if (p == q) {  // a point argument: the width is rounding only
      double mag = 0;
      for (const Q& q : c[0]) mag = std::max(mag, std::fabs(CGAL::to_double(q)));
      narrow[signed_arguments] += r1.hi - r1.lo <= 1e-12 * mag * (n + 1) * 4;
    }
  }
  CHECK(narrow[0] >= 1);
  CHECK(narrow[1] >= 1);
}

// The strip exclusion (lifting/certified_lifting.h, exclude_strips: the phantom proof of spans whose partner
// cannot be followed) on the folded patch (u - 3/10)^2, v^2, (u - 3/10)(v - 1/3)), whose double line v = 1/3 has the
// partner Q = (3/5 - u, 1/3): genuine for u in [0, 3/5], phantom beyond (Q leaves through u = 0). A strip over a
// genuine span must never be proved; strips over phantom spans are. Spans are given in runs (touching) and apart.
TEST_CASE("strip exclusion: never over genuine points of a closed-form double line", "[surface][lifting]") {
  using D = internal::Double_interval;
  const Patch phi = from_power({"(u-3/10)^2", "v^2", "(u-3/10)*(v-1/3)"}, 3, 2);
  const internal::Partner_equations eq(phi);
  const Parameter_box domain{Q(0), Q(1), Q(0), Q(1)};
  const Parameter_box cell{Q(0), Q(1), Q(1, 4), Q(1, 2)};  // v = 1/3 is a graph over u in it
  internal::Exclusion_budget budget;
  // genuine: u in [0.1, 0.2] and a run [0.5, 0.55], [0.55, 0.62] reaching across the split at u = 0.6
  const std::vector<D> genuine{D{0.1, 0.2}, D{0.5, 0.55}, D{0.55, 0.62}};
  for (bool p : internal::exclude_strips(eq, domain, 0, genuine, cell, nullptr, budget)) CHECK_FALSE(p);
  // phantom: u in [0.7, 0.8], [0.8, 0.9] (a run) and [0.95, 1]
  const std::vector<D> phantom{D{0.7, 0.8}, D{0.8, 0.9}, D{0.95, 1.0}};
  const std::vector<bool> proved = internal::exclude_strips(eq, domain, 0, phantom, cell, nullptr, budget);
  REQUIRE(proved.size() == 3);
  for (bool p : proved) CHECK(p);
  // a span beside a genuine one in the same run: the failure near u = 0.55 must not leak into [0.62, 0.7]'s proof
  // nor let [0.55, 0.62] pass
  const std::vector<bool> mixed =
      internal::exclude_strips(eq, domain, 0, {D{0.55, 0.62}, D{0.62, 0.7}, D{0.7, 0.8}}, cell, nullptr, budget);
  CHECK_FALSE(mixed[0]);
  CHECK(mixed[2]);
}

// The blown-up partner equations (lifting/internal/blown_up_partner_equations.h) are F = E(x; r d(m)) / r with
// d = (1, m) or (m, 1): checked against the partner equations E themselves (an independent evaluation of the
// forms at P and Q) at points with r != 0, and their Jacobian against central differences.
TEST_CASE("blown-up partner equations: E / r and its derivatives", "[surface][lifting]") {
  using D = internal::Double_interval;
  std::mt19937 g(11);
  for (int trial = 0; trial < 4; ++trial) {
    const Patch phi = random_patch(g, 2 + trial % 2, 2 + trial / 2, trial % 2 == 1);
    const internal::Partner_equations eq(phi);
    for (int chart = 0; chart < 2; ++chart) {
      const internal::Blown_up_partner_equations bu(phi, chart);
      for (int s = 0; s < 8; ++s) {
        const double x1 = 0.1 + 0.1 * s, x2 = 0.8 - 0.07 * s, r = 0.03 * (s - 4) + 0.011, m = 0.4 - 0.1 * s;
        const double l = chart == 0 ? r : r * m, k = chart == 0 ? r * m : r;
        std::array<D, 3> E, F, Fp, Fm;
        std::array<std::array<D, 4>, 3> J;
        eq.evaluate(std::array<D, 4>{D{x1, x1}, D{x2, x2}, D{l, l}, D{k, k}}, E);
        const std::array<D, 4> z{D{x1, x1}, D{x2, x2}, D{r, r}, D{m, m}};
        bu.evaluate(z, F, &J);
        for (int c = 0; c < 3; ++c) {
          INFO("trial " << trial << " chart " << chart << " sample " << s << " equation " << c);
          CHECK(F[c].mid() == Approx(E[c].mid() / r).epsilon(1e-9).margin(1e-9));
          CHECK(F[c].hi - F[c].lo < 1e-9 * (1 + std::fabs(F[c].mid())));
        }
        for (int d = 0; d < 4; ++d) {
          const double h = 1e-6;
          auto zp = z, zm = z;
          zp[d] = D{z[d].lo + h, z[d].lo + h};
          zm[d] = D{z[d].lo - h, z[d].lo - h};
          bu.evaluate(zp, Fp);
          bu.evaluate(zm, Fm);
          for (int c = 0; c < 3; ++c)
            CHECK(J[c][d].mid() == Approx((Fp[c].mid() - Fm[c].mid()) / (2 * h)).epsilon(1e-5).margin(1e-5));
        }
      }
    }
  }
}
