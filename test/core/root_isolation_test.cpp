// Tests of certified real root isolation and Algebraic_real.
// Expected values come from the construction of the polynomials (known
// roots and multiplicities), from exact identities checked with plain
// rational arithmetic (lower()^2 < 2 < upper()^2), from an independent
// Sturm sequence computed with CGAL's polynomial pseudo-division, from
// CGAL's Sturm-Habicht root count, and from published digits of sqrt(2).
#include <catch2/catch.hpp>

#include <bezoutian/algebraic/Algebraic_real.h>
#include <bezoutian/algebraic/Root_isolation.h>

#include <CGAL/Polynomial/sturm_habicht_sequence.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace bezoutian;
typedef Polynomial_1<Integer> P;
typedef Polynomial_1<Rational> PQ;

namespace {

P lin(long q, long p) { return P(Integer(-p), Integer(q)); }  // q x - p, root p/q
P x_power(int n) { return CGAL::ipower(P(Integer(0), Integer(1)), n); }
P quad(long a, long b, long c) { return P(Integer(c), Integer(b), Integer(a)); }  // a x^2 + b x + c

Rational Q(long p, long q = 1) { return Rational(Integer(p), Integer(q)); }

// Exact sign of p at the rational x (homogeneous evaluation, independent of the library).
int sign_at(const P& p, const Rational& x) {
  const Integer num = x.numerator(), den = x.denominator();
  Integer acc(0), dp(1);
  std::vector<Integer> npow(p.degree() + 1);
  Integer np(1);
  for (int i = 0; i <= p.degree(); ++i) { npow[i] = np; np *= num; }
  for (int i = p.degree(); i >= 0; --i) { acc += p[i] * npow[i] * dp; dp *= den; }
  return CGAL::sign(acc);
}

// Classic Sturm sequence f, f', -rem(...) with positive normalisations only
// (pseudo-division by lc^(d+1), sign corrected, divided by the positive content).
std::vector<P> sturm_sequence(const P& f) {
  std::vector<P> s{f, CGAL::differentiate(f)};
  while (!CGAL::is_zero(s.back()) && s.back().degree() > 0) {
    P q, r;
    Integer D;
    CGAL::pseudo_division(s[s.size() - 2], s.back(), q, r, D);
    if (D < 0) r = -r;
    r = -r;
    if (CGAL::is_zero(r)) break;
    Integer c = r.content();
    if (c < 0) c = -c;
    r /= c;
    s.push_back(r);
  }
  return s;
}

int sturm_variations(const std::vector<P>& s, const Rational& x) {
  int v = 0, last = 0;
  for (const P& p : s) {
    const int si = sign_at(p, x);
    if (si == 0) continue;
    if (last != 0 && si != last) ++v;
    last = si;
  }
  return v;
}

// Number of distinct roots in (a, b] (Sturm's theorem; a, b not roots).
int sturm_count(const P& f, const Rational& a, const Rational& b) {
  const std::vector<P> s = sturm_sequence(f);
  return sturm_variations(s, a) - sturm_variations(s, b);
}

std::mt19937_64 rng(20261122);
Integer random_integer(int bits) {
  Integer x(0);
  for (int b = 0; b < bits; b += 30) {
    const int s = std::min(30, bits - b);
    x = x * Integer(1L << s) + Integer(static_cast<long>(rng() >> (64 - s)));
  }
  return (rng() & 1) ? Integer(-x) : x;
}
P random_polynomial(int degree, int bits) {
  std::vector<Integer> c;
  for (int i = 0; i <= degree; ++i) c.push_back(random_integer(bits));
  if (c.back() == 0) c.back() = 1;
  return P(c.begin(), c.end());
}

// Checks the isolating interval of an irrational root independently:
// f changes sign across it (f square-free there) or the root is exact.
void check_isolating_interval(const P& f, const Isolated_root& r) {
  if (r.root.is_rational()) {
    CHECK(sign_at(f, r.root.rational_value()) == 0);
    return;
  }
  CHECK(r.root.lower() < r.root.upper());
  const int sl = sign_at(r.root.polynomial(), r.root.lower()), sh = sign_at(r.root.polynomial(), r.root.upper());
  CHECK(sl * sh == -1);
  CHECK(sl == r.root.sign_at_lower());
  // the defining polynomial divides f, so its root is a root of f
  P q, rem;
  Integer D;
  CGAL::pseudo_division(f, r.root.polynomial(), q, rem, D);
  CHECK(CGAL::is_zero(rem));
}

bool is_sqrt2(const Algebraic_real& a) {
  // a positive root of x^2 - 2 whose interval satisfies lower^2 < 2 < upper^2
  return !a.is_rational() && a.lower() >= Q(0) && a.lower() * a.lower() < Q(2) && a.upper() * a.upper() > Q(2) &&
         a.sign_of(quad(1, 0, -2)) == 0;
}

}  // namespace

TEST_CASE("roots of products of linear and quadratic factors, with multiplicities", "[root_isolation]") {
  // (3x-1)^2 (2x-1) (x^2-2)^3 (5x+2) (x^2+1)
  const P x2m2 = quad(1, 0, -2);
  const P f = CGAL::ipower(lin(3, 1), 2) * lin(2, 1) * CGAL::ipower(x2m2, 3) * lin(5, -2) * quad(1, 0, 1);
  SECTION("whole real line") {
    const auto r = isolate_real_roots(f);
    REQUIRE(r.size() == 5);
    CHECK(r[0].root.lower() < Q(-1));
    CHECK(is_sqrt2(-r[0].root));
    CHECK(r[0].multiplicity == 3);
    REQUIRE(r[1].root.is_rational());
    CHECK(r[1].root.rational_value() == Q(-2, 5));
    CHECK(r[1].multiplicity == 1);
    REQUIRE(r[2].root.is_rational());
    CHECK(r[2].root.rational_value() == Q(1, 3));
    CHECK(r[2].multiplicity == 2);
    REQUIRE(r[3].root.is_rational());
    CHECK(r[3].root.rational_value() == Q(1, 2));
    CHECK(r[3].multiplicity == 1);
    CHECK(is_sqrt2(r[4].root));
    CHECK(r[4].multiplicity == 3);
    for (const auto& x : r) check_isolating_interval(f, x);
    CHECK(count_real_roots(f) == 5);
  }
  SECTION("[0,1]") {
    const auto r = isolate_real_roots(f, Q(0), Q(1));
    REQUIRE(r.size() == 2);
    CHECK(r[0].root == Algebraic_real(Q(1, 3)));
    CHECK(r[0].multiplicity == 2);
    CHECK(r[1].root == Algebraic_real(Q(1, 2)));
    CHECK(count_real_roots(f, Q(0), Q(1)) == 2);
  }
  SECTION("[1/2, 3/2] and [1/3, 1/2] keep roots at the ends") {
    const auto r = isolate_real_roots(f, Q(1, 2), Q(3, 2));
    REQUIRE(r.size() == 2);
    CHECK(r[0].root.rational_value() == Q(1, 2));
    CHECK(is_sqrt2(r[1].root));
    const auto s = isolate_real_roots(f, Q(1, 3), Q(1, 2));
    REQUIRE(s.size() == 2);
    CHECK(s[0].root.rational_value() == Q(1, 3));
    CHECK(s[1].root.rational_value() == Q(1, 2));
  }
  SECTION("rational coefficients give the same roots") {
    PQ fq;
    {
      std::vector<Rational> c;
      for (int i = 0; i <= f.degree(); ++i) c.push_back(Rational(f[i]) / Rational(7));
      fq = PQ(c.begin(), c.end());
    }
    const auto r = isolate_real_roots(fq, Q(0), Q(2));
    REQUIRE(r.size() == 3);
    CHECK(r[0].root.rational_value() == Q(1, 3));
    CHECK(r[1].root.rational_value() == Q(1, 2));
    CHECK(is_sqrt2(r[2].root));
    CHECK(r[2].multiplicity == 3);
    CHECK(isolate_real_roots(fq).size() == 5);
  }
}

TEST_CASE("roots exactly at the ends of the interval", "[root_isolation]") {
  const P f = x_power(1) * lin(1, 1) * lin(4, 1) * quad(1, 0, -2);  // 0, 1, 1/4, +-sqrt2
  auto r = isolate_real_roots(f, Q(0), Q(1));
  REQUIRE(r.size() == 3);
  CHECK(r[0].root.rational_value() == Q(0));
  CHECK(r[1].root.rational_value() == Q(1, 4));
  CHECK(r[2].root.rational_value() == Q(1));
  r = isolate_real_roots(f, Q(-1), Q(0));
  REQUIRE(r.size() == 1);
  CHECK(r[0].root.rational_value() == Q(0));
  r = isolate_real_roots(f, Q(1, 4), Q(1, 4));  // a point interval
  REQUIRE(r.size() == 1);
  CHECK(r[0].root.rational_value() == Q(1, 4));
  CHECK(isolate_real_roots(f, Q(1, 3), Q(1, 3)).empty());
  // the ends of a non-dyadic interval
  r = isolate_real_roots(f, Q(1, 4), Q(7, 3));
  REQUIRE(r.size() == 3);
  CHECK(r[0].root.rational_value() == Q(1, 4));
  CHECK(r[1].root.rational_value() == Q(1));
  CHECK(is_sqrt2(r[2].root));
}

TEST_CASE("clustered roots", "[root_isolation]") {
  SECTION("(1000x-1)(1001x-1)") {
    const P f = lin(1000, 1) * lin(1001, 1);
    const auto r = isolate_real_roots(f, Q(0), Q(1));
    REQUIRE(r.size() == 2);
    CHECK(r[0].root.rational_value() == Q(1, 1001));
    CHECK(r[1].root.rational_value() == Q(1, 1000));
  }
  SECTION("irreducible cluster: (x^2-2)(x^2-2+10^-12) in one square-free factor") {
    // 10^12 (x^2-2) + 1 has roots sqrt(2 - 10^-12), very close to -+sqrt2
    const P g = quad(1000000000000L, 0, -2000000000000L + 1);
    const P f = quad(1, 0, -2) * g;
    const auto r = isolate_real_roots(f, Q(1), Q(2));
    REQUIRE(r.size() == 2);
    CHECK(r[0].root < r[1].root);
    CHECK(is_sqrt2(r[1].root));
    CHECK(r[0].root.sign_of(g) == 0);
    CHECK(r[1].root.sign_of(quad(1, 0, -2)) == 0);
    CHECK(r[1].root.upper() - r[0].root.lower() < Q(1, 1000000));
    CHECK(sturm_count(f, Q(1), Q(2)) == 2);
  }
  SECTION("product of many close rational roots plus a perturbation") {
    P f(Integer(1));
    for (int i = 0; i < 12; ++i) f *= lin(1000000, 500000 + i);
    f = f * Integer(1000) + Integer(1);
    const auto r = isolate_real_roots(f, Q(0), Q(1));
    CHECK(static_cast<int>(r.size()) == sturm_count(f, Q(0), Q(1)));
    for (std::size_t i = 0; i + 1 < r.size(); ++i) CHECK(r[i].root < r[i + 1].root);
    for (const auto& x : r) check_isolating_interval(f, x);
  }
}

TEST_CASE("Wilkinson-like polynomials of degree 20", "[root_isolation]") {
  P w(Integer(1)), w01(Integer(1));
  for (int i = 1; i <= 20; ++i) {
    w *= lin(1, i);
    w01 *= lin(21, i);
  }
  SECTION("integer roots 1..20") {
    const auto r = isolate_real_roots(w);
    REQUIRE(r.size() == 20);
    for (int i = 0; i < 20; ++i) {
      REQUIRE(r[i].root.is_rational());
      CHECK(r[i].root.rational_value() == Q(i + 1));
      CHECK(r[i].multiplicity == 1);
    }
  }
  SECTION("roots i/21 in [0,1]") {
    const auto r = isolate_real_roots(w01, Q(0), Q(1));
    REQUIRE(r.size() == 20);
    for (int i = 0; i < 20; ++i) CHECK(r[i].root.rational_value() == Q(i + 1, 21));
  }
  SECTION("Wilkinson's perturbation 2^23 W(x) - x^19 has complex roots") {
    const P f = w * Integer(1 << 23) - x_power(19);
    const auto r = isolate_real_roots(f);
    const int expected = sturm_count(f, Q(-64), Q(64));  // all roots have |x| < 64 (Fujiwara)
    CHECK(static_cast<int>(r.size()) == expected);
    CHECK(expected == CGAL::number_of_real_roots(f));
    CHECK(expected < 20);
    for (const auto& x : r) check_isolating_interval(f, x);
  }
  SECTION("W + 1 on [0,1]-scaled version") {
    const P f = w01 + P(Integer(1));
    const auto r = isolate_real_roots(f, Q(0), Q(1));
    CHECK(static_cast<int>(r.size()) == sturm_count(f, Q(0), Q(1)));
    for (const auto& x : r) {
      CHECK_FALSE(x.root.is_rational());
      check_isolating_interval(f, x);
    }
  }
}

TEST_CASE("Mignotte-like polynomials with very close roots", "[root_isolation]") {
  // x^n - 2 (a x - 1)^2: two real roots within about 2 a^-(n+2)/2 of 1/a.
  for (const auto& na : std::vector<std::pair<int, long>>{{20, 100}, {33, 1000}, {50, 100}}) {
    const int n = na.first;
    const long a = na.second;
    const P f = x_power(n) - Integer(2) * CGAL::ipower(lin(a, 1), 2);
    const auto r = isolate_real_roots(f);
    CHECK(static_cast<int>(r.size()) == CGAL::number_of_real_roots(f));
    const auto near = isolate_real_roots(f, Q(1, a) - Q(1, a * a), Q(1, a) + Q(1, a * a));
    REQUIRE(near.size() == 2);
    CHECK(near[0].root < Algebraic_real(Q(1, a)));
    CHECK(near[1].root > Algebraic_real(Q(1, a)));
    CHECK(near[0].root.upper() <= near[1].root.lower());
    for (const auto& x : near) check_isolating_interval(f, x);
    CHECK(sturm_count(f, Q(1, a) - Q(1, a * a), Q(1, a) + Q(1, a * a)) == 2);
  }
}

TEST_CASE("random degree-80 polynomials with 130-bit coefficients", "[root_isolation]") {
  for (int k = 0; k < 2; ++k) {
    const P f = random_polynomial(80, 130);
    REQUIRE(sign_at(f, Q(0)) != 0);
    REQUIRE(sign_at(f, Q(1)) != 0);
    const auto r01 = isolate_real_roots(f, Q(0), Q(1));
    CHECK(static_cast<int>(r01.size()) == sturm_count(f, Q(0), Q(1)));
    const auto r = isolate_real_roots(f);
    CHECK(static_cast<int>(r.size()) == CGAL::number_of_real_roots(f));
    for (const auto& x : r) check_isolating_interval(f, x);
  }
  // Many roots in [0,1]: a product of 20 quadratics with two close real roots
  // (s +- 1)/10^5 each, perturbed; Sturm count on [0,1] and on a subinterval.
  P f(Integer(1));
  for (int i = 0; i < 20; ++i) {
    const long s = static_cast<long>(rng() % 99998) + 2;
    f *= quad(10000000000L, -2 * s * 100000L, s * s - 1);
  }
  f = f * Integer(3) + random_polynomial(30, 20);
  const auto r = isolate_real_roots(f, Q(0), Q(1));
  CHECK(static_cast<int>(r.size()) == sturm_count(f, Q(0), Q(1)));
  CHECK(static_cast<int>(isolate_real_roots(f, Q(1, 3), Q(2, 3)).size()) == sturm_count(f, Q(1, 3), Q(2, 3)));
  for (std::size_t i = 0; i + 1 < r.size(); ++i) CHECK(r[i].root.upper() <= r[i + 1].root.lower());
}

TEST_CASE("exact and filtered subdivision agree", "[root_isolation]") {
  for (int k = 0; k < 22; ++k) {
    P f = random_polynomial(10 + 3 * k, 20 + 5 * k);
    if (k % 3 == 0) f *= lin(7, 3) * quad(1, 0, -2) * lin(1000, 999);  // roots in [0,1], clustered near 1
    // deep subdivision (roots 10^-30 apart): exact recomputation from monomial ancestors
    if (k == 20) f = x_power(30) - Integer(2) * CGAL::ipower(lin(100, 1), 2);
    if (k == 21) f = x_power(25) - Integer(2) * CGAL::ipower(lin(1000, 1), 2);
    for (const auto& fm : internal::square_free_factors(f)) {
      const internal::Mpz_vector c = internal::coefficients_of(fm.first);
      const auto a = internal::isolate_square_free(c, Q(0), Q(1), nullptr, true);
      const auto b = internal::isolate_square_free(c, Q(0), Q(1), nullptr, false);
      REQUIRE(a.size() == b.size());
      for (std::size_t i = 0; i < a.size(); ++i) {
        CHECK(a[i].exact == b[i].exact);
        CHECK(a[i].lo == b[i].lo);  // same dyadic subdivision, same intervals
        CHECK(a[i].hi == b[i].hi);
      }
    }
  }
}

TEST_CASE("modular gcd and square-free factorization agree with CGAL", "[root_isolation]") {
  for (int k = 0; k < 30; ++k) {
    const P g = random_polynomial(1 + k % 7, 10 + k);
    const P a = g * random_polynomial(5 + k % 11, 30), b = g * random_polynomial(3 + k % 5, 60);
    const P ours = internal::gcd_of(a, b);
    const P theirs = internal::canonical_integer(CGAL::gcd(a, b));
    CHECK(ours == theirs);
    CHECK(ours.degree() >= g.degree());
    // f = g1 g2^2 g3^3 with random (almost surely square-free, coprime) g_i
    const P g1 = random_polynomial(1 + k % 5, 20), g2 = random_polynomial(1 + k % 4, 15),
            g3 = random_polynomial(1 + k % 3, 10);
    const P f = g1 * g2 * g2 * g3 * g3 * g3;
    const auto fac = internal::square_free_factors(f);
    std::vector<std::pair<P, int>> cg;
    CGAL::square_free_factorize_up_to_constant_factor(f, std::back_inserter(cg));
    P prod(Integer(1));
    for (const auto& fm : fac) prod *= CGAL::ipower(fm.first, fm.second);
    CHECK(internal::canonical_integer(prod) == internal::canonical_integer(f));
    std::size_t nontrivial = 0;
    for (const auto& fm : cg)
      if (fm.first.degree() >= 1) {
        ++nontrivial;
        bool found = false;
        for (const auto& m : fac) found = found || (m.second == fm.second && m.first == internal::canonical_integer(fm.first));
        CHECK(found);
      }
    CHECK(fac.size() == nontrivial);
  }
}

TEST_CASE("rational roots come out exact", "[root_isolation]") {
  // one square-free factor mixing rational and irrational roots
  const P f = lin(7, 3) * quad(1, 0, -5) * lin(13, -4) * lin(123456789, 98765432) * (x_power(3) - x_power(1) - P(Integer(1)));
  const auto r = isolate_real_roots(f);
  REQUIRE(r.size() == 6);
  int rational = 0;
  for (const auto& x : r) rational += x.root.is_rational() ? 1 : 0;
  CHECK(rational == 3);
  CHECK(r[1].root.rational_value() == Q(-4, 13));
  CHECK(r[2].root.rational_value() == Q(3, 7));
  CHECK(r[3].root.rational_value() == Q(98765432, 123456789));
  // rational roots with large denominators on a given interval
  const P g = lin(1048573, 1) * lin(1048575, 1) * quad(3, 0, -1);  // 1048573 and 1048575 are odd
  const auto s = isolate_real_roots(g, Q(0), Q(1));
  REQUIRE(s.size() == 3);
  CHECK(s[0].root.rational_value() == Q(1, 1048575));
  CHECK(s[1].root.rational_value() == Q(1, 1048573));
  CHECK_FALSE(s[2].root.is_rational());
  // the constructor recognises rationals too
  const Algebraic_real a(lin(3, 2) * quad(1, 0, -3), Q(0), Q(1));
  REQUIRE(a.is_rational());
  CHECK(a.rational_value() == Q(2, 3));
}

TEST_CASE("Algebraic_real: decimal strings, doubles, refinement", "[algebraic_real]") {
  const Algebraic_real s2(quad(1, 0, -2), Q(0), Q(2));
  CHECK(s2.to_decimal_string(30) == "1.41421356237309504880168872421");
  CHECK((-s2).to_decimal_string(30) == "-1.41421356237309504880168872421");
  CHECK(s2.to_decimal_string(1) == "1");
  CHECK(s2.to_decimal_string(2) == "1.4");
  // sqrt(2)/1000 = root of 500000 x^2 - 1
  const Algebraic_real small(quad(500000, 0, -1), Q(0), Q(1));
  CHECK(small.to_decimal_string(10) == "0.001414213562");
  // 10^7 sqrt2 = root of x^2 - 2 10^14
  const Algebraic_real big(quad(1, 0, -200000000000000L), Q(0), Q(100000000));
  CHECK(big.to_decimal_string(5) == "1.4142e7");
  CHECK(Algebraic_real(Q(1, 3)).to_decimal_string(10) == "0.3333333333");
  CHECK(Algebraic_real(Q(2, 3)).to_decimal_string(3) == "0.667");
  CHECK(Algebraic_real(Q(1, 8)).to_decimal_string(2) == "0.13");  // tie: away from zero
  CHECK(Algebraic_real(Q(-1, 8)).to_decimal_string(2) == "-0.13");
  CHECK(Algebraic_real(Q(999, 1000)).to_decimal_string(2) == "1.0");
  CHECK(Algebraic_real(Q(0)).to_decimal_string(5) == "0");
  CHECK(Algebraic_real(Q(12345678)).to_decimal_string(3) == "1.23e7");
  // golden ratio
  const Algebraic_real phi(quad(1, -1, -1), Q(1), Q(2));
  CHECK(phi.to_decimal_string(20) == "1.6180339887498948482");

  CHECK(s2.to_double() == std::sqrt(2.0));  // IEEE sqrt is correctly rounded
  const auto iv = s2.to_interval();
  CHECK(iv.first <= std::sqrt(2.0));
  CHECK(iv.second >= std::sqrt(2.0));
  CHECK(iv.second - iv.first <= 4 * std::ldexp(1.0, -52));

  const Algebraic_real t(quad(1, 0, -3), Q(1), Q(2));
  const Rational w = Rational(Integer(1), CGAL::ipower(Integer(10), 60));
  t.refine_to_width(w);
  CHECK(t.upper() - t.lower() <= w);
  CHECK(t.lower() * t.lower() < Q(3));
  CHECK(t.upper() * t.upper() > Q(3));
  const Rational before = t.upper() - t.lower();
  t.refine();
  CHECK(t.upper() - t.lower() == before / 2);
}

TEST_CASE("Algebraic_real: exact comparisons", "[algebraic_real]") {
  const P x2m2 = quad(1, 0, -2);
  const Algebraic_real a(x2m2, Q(1), Q(2));
  const Algebraic_real b(x2m2 * lin(1, 3), Q(0), Q(2));  // sqrt2 as a root of (x^2-2)(x-3)
  const Algebraic_real c(x2m2 * lin(1, -7) * quad(1, 0, -3), Q(1), Q(3, 2));
  const Algebraic_real d(quad(1, 0, -3), Q(1), Q(2));
  CHECK(a.compare(b) == 0);
  CHECK(b.compare(a) == 0);
  CHECK(a == c);
  CHECK(b == c);
  CHECK(c.polynomial().degree() == 2);  // the equality test reduced it to the gcd x^2 - 2
  CHECK(a != d);
  CHECK(a < d);
  CHECK(d > b);
  CHECK(a.compare(Q(141421356, 100000000)) == 1);
  CHECK(a.compare(Q(141421357, 100000000)) == -1);
  CHECK(Algebraic_real(Q(3, 2)) > a);
  CHECK(a > 1);
  CHECK(-a < 0);
  CHECK((-a).compare(-b) == 0);
  CHECK(a.sign() == 1);
  CHECK((-a).sign() == -1);
  // cube root of 3 (1.44225) vs sqrt2 (1.41421), and two roots of one polynomial
  const Algebraic_real cr3(x_power(3) - P(Integer(3)), Q(1), Q(2));
  CHECK(cr3 > a);
  const auto roots = isolate_real_roots(x2m2 * (x_power(3) - P(Integer(3))));
  REQUIRE(roots.size() == 3);
  CHECK(roots[1].root == a);
  CHECK(roots[2].root == cr3);
  // close but different: sqrt(2) vs sqrt(2 + 10^-30) (root of 10^30 x^2 - (2 10^30 + 1))
  const Integer e30 = CGAL::ipower(Integer(10), 30);
  const Algebraic_real e(P(-(Integer(2) * e30 + Integer(1)), Integer(0), e30), Q(1), Q(2));
  CHECK(a < e);
  CHECK(e > b);
  // 10^-100 apart: separated by quadratic refinement after the gcd test
  const Integer e100 = CGAL::ipower(Integer(10), 100);
  const Algebraic_real f(P(-(Integer(2) * e100 + Integer(1)), Integer(0), e100), Q(1), Q(2));
  CHECK(f.compare(a) == 1);
  CHECK(f.compare(e) == -1);
  CHECK(f.upper() - f.lower() < Rational(Integer(1), e100));
  // rational strictly between
  const Rational m = a.rational_between(e);
  CHECK(a.compare(m) < 0);
  CHECK(e.compare(m) > 0);
  CHECK_THROWS_AS(a.rational_between(c), Invalid_input);
}

TEST_CASE("Algebraic_real: exact sign of a polynomial at the number", "[algebraic_real]") {
  const P x2m2 = quad(1, 0, -2);
  const Algebraic_real a(x2m2, Q(1), Q(2));
  CHECK(a.sign_of(x2m2) == 0);
  CHECK(a.sign_of(x2m2 * lin(1, 3)) == 0);
  CHECK(a.sign_of(lin(1, 1)) == 1);
  CHECK(a.sign_of(quad(1, 0, -3)) == -1);
  CHECK(a.sign_of(lin(1000000, 1414214)) == -1);  // sqrt2 < 1.414214
  CHECK(a.sign_of(lin(1000000, 1414213)) == 1);
  CHECK(a.sign_of(P(Integer(0))) == 0);
  CHECK(a.sign_of(P(Integer(-5))) == -1);
  // rational coefficients: x - 1.4142135623 > 0 at sqrt2; (x^2 - 2)/3 == 0
  CHECK(a.sign_of(PQ(-Q(14142135623, 10000000000), Q(1))) == 1);
  CHECK(a.sign_of(PQ(Q(-2, 3), Q(0), Q(1, 3))) == 0);
  // (x - sqrt2)(x + sqrt2)(x - 1) changes sign only at the roots; at -sqrt2 it is 0
  CHECK((-a).sign_of(x2m2 * lin(1, 1)) == 0);
  // a very small value: 10^30 x^2 - (2 10^30 + 1) at sqrt2 is -1
  const Integer e30 = CGAL::ipower(Integer(10), 30);
  CHECK(a.sign_of(P(-(Integer(2) * e30 + Integer(1)), Integer(0), e30)) == -1);
  // rational numbers
  CHECK(Algebraic_real(Q(1, 2)).sign_of(lin(2, 1)) == 0);
  CHECK(Algebraic_real(Q(1, 2)).sign_of(lin(3, 1)) == 1);
}

TEST_CASE("bad input is reported", "[root_isolation]") {
  CHECK_THROWS_AS(isolate_real_roots(P(Integer(0)), Q(0), Q(1)), Zero_polynomial_error);
  CHECK_THROWS_AS(isolate_real_roots(P(Integer(0))), Zero_polynomial_error);
  CHECK_THROWS_AS(isolate_real_roots(PQ(Rational(0))), Zero_polynomial_error);
  CHECK_THROWS_AS(count_real_roots(P(Integer(0)), Q(0), Q(1)), Zero_polynomial_error);
  CHECK_THROWS_AS(isolate_real_roots(lin(1, 1), Q(1), Q(0)), Invalid_input);
  CHECK(isolate_real_roots(P(Integer(5))).empty());
  CHECK(isolate_real_roots(P(Integer(5)), Q(0), Q(1)).empty());
  CHECK(isolate_real_roots(quad(1, 0, 1)).empty());
  const P x2m2 = quad(1, 0, -2);
  CHECK_THROWS_AS(Algebraic_real(x2m2, Q(2), Q(3)), Invalid_input);   // no root
  CHECK_THROWS_AS(Algebraic_real(x2m2, Q(-2), Q(2)), Invalid_input);  // two roots
  CHECK_THROWS_AS(Algebraic_real(x2m2, Q(2), Q(1)), Invalid_input);   // lo > hi
  CHECK_THROWS_AS(Algebraic_real(P(Integer(0)), Q(0), Q(1)), Invalid_input);
  CHECK_THROWS_AS(Algebraic_real(x2m2, Q(1), Q(1)), Invalid_input);  // point, not a root
  // a double root is one distinct root: accepted, defined by the square-free part
  const Algebraic_real d(x2m2 * x2m2, Q(1), Q(2));
  CHECK(d.polynomial().degree() == 2);
  CHECK_THROWS_AS(d.rational_value(), Invalid_input);
  CHECK_THROWS_AS(d.to_decimal_string(0), Invalid_input);
  CHECK_THROWS_AS(d.refine_to_width(Q(0)), Invalid_input);
}
