// The multi-modular lexicographic Groebner basis certified over Q (Groebner_bivariate.h): hand-derived bases,
// agreement with the exact rational Buchberger algorithm, a multiplicity (non-radical ideal), unlucky and bad primes,
// a system whose dimension count is not available (exact fallback, or Error within a small budget), corrupted bases
// that the certification must reject, and identical intersection answers to the default method on generated
// problems of degrees 2-6 (planar and space curves).
#include <catch2/catch.hpp>

#include "intersection_checks.h"

#include <bezoutian/intersection/Curve_intersection.h>
#include <bezoutian/geometry/Curve_problem_generator.h>
#include <bezoutian/elimination/Groebner_bivariate.h>
#include <bezoutian/arithmetic/rational_reconstruction.h>

#include <random>
#include <vector>

using namespace bezoutian;

namespace {

using P1 = Polynomial_1<Integer>;
using P2 = Polynomial_2<Integer>;
const P2 s = CGAL::shift(P2(1), 1, 0), t = CGAL::shift(P2(1), 1, 1);

// A basis written by hand: each element a list of (coefficient, exponent of t, exponent of s).
struct Term {
  Rational c;
  int j, i;
};
Lex_polynomial_2 lex(const std::vector<Term>& terms) {
  Lex_polynomial_2::Terms m;
  for (const auto& x : terms) m.emplace(Lex_polynomial_2::Monomial{x.j, x.i}, x.c);
  return Lex_polynomial_2(m);
}

bool same_basis(const std::vector<Lex_polynomial_2>& a, const std::vector<Lex_polynomial_2>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (a[k].terms() != b[k].terms()) return false;
  return true;
}

P2 random_polynomial(int ds, int dt, std::mt19937& rng) {
  std::uniform_int_distribution<int> c(-9, 9);
  std::vector<P1> rows;
  for (int j = 0; j <= dt; ++j) {
    std::vector<Integer> r;
    for (int i = 0; i <= ds; ++i) r.push_back(Integer(c(rng)));
    rows.push_back(P1(r.begin(), r.end()));
  }
  return P2(rows.begin(), rows.end());
}

using bezoutian_test::require_same;

}  // namespace

TEST_CASE("rational reconstruction (Wang)", "[groebner]") {
  const Integer m = Integer(1000003) * Integer(999983);  // two primes
  Rational q;
  // -22/7 mod m reconstructed
  const Integer inv7 = [&] {  // 7^-1 mod m by brute force over the CRT-free route: 7 x = 1 + k m
    for (Integer k(0);; k += 1)
      if (CGAL::is_zero(CGAL::mod(Integer(1) + k * m, Integer(7)))) return CGAL::integral_division(Integer(1) + k * m, Integer(7));
  }();
  REQUIRE(internal::rational_reconstruction(CGAL::mod(Integer(-22) * inv7, m), m, q));
  CHECK(q == Rational(-22, 7));
  // (10^7 + 7)/7 has a numerator beyond sqrt(m/2) ~ 7.07e5: not returned
  const Integer big(10000000);
  CHECK_FALSE((internal::rational_reconstruction(big * inv7 + Integer(1), m, q) && q == Rational(big + 7, 7)));
  // an integer is its own reconstruction, with either sign
  REQUIRE(internal::rational_reconstruction(m - Integer(12345), m, q));
  CHECK(q == Rational(-12345));
}

TEST_CASE("modular lex basis: hand-derived bases, certified by the dimension count", "[groebner]") {
  Groebner_certificate c;
  // (t - s^2, t^2 + s^2 - 2): t = s^2, s^4 + s^2 - 2 = 0
  auto B = modular_lex_groebner_basis(std::vector<P2>{t - s * s, t * t + s * s - 2}, &c);
  CHECK(same_basis(B, {lex({{1, 0, 4}, {1, 0, 2}, {-2, 0, 0}}), lex({{1, 1, 0}, {-1, 0, 2}})}));
  CHECK_FALSE(c.exact_fallback);
  CHECK(c.standard_monomials == 4);
  CHECK(c.dimension == 4);  // deg_s Res_t = 4
  CHECK(c.eliminated == 't');
  // two circles through (1,0) and (0,1): {s^2 - s, t + s - 1}
  B = modular_lex_groebner_basis(std::vector<P2>{s * s + t * t - 1, (s - 1) * (s - 1) + (t - 1) * (t - 1) - 1}, &c);
  CHECK(same_basis(B, {lex({{1, 0, 2}, {-1, 0, 1}}), lex({{1, 1, 0}, {1, 0, 1}, {-1, 0, 0}})}));
  CHECK_FALSE(c.exact_fallback);
  // not in shape position: the second equation is (s^2 - s) t modulo the first, so the zeros are (0, 1), (0, -1)
  // (two on the line s = 0) and (1, 0) with multiplicity 3: basis {s (s - 1)^2, (s^2 - s) t, t^2 + s - 1}
  const std::vector<P2> F{t * t + s - 1, s * t * t + s * s - s + t * (s * s - s)};
  B = modular_lex_groebner_basis(F, &c);
  std::vector<Lex_polynomial_2> L;
  for (const auto& f : F) L.push_back(Lex_polynomial_2(f));
  CHECK(same_basis(B, lex_groebner_basis(L)));
  CHECK_FALSE(c.exact_fallback);
  CHECK(same_basis(B, {lex({{1, 0, 3}, {-2, 0, 2}, {1, 0, 1}}), lex({{1, 1, 2}, {-1, 1, 1}}),
                       lex({{1, 2, 0}, {1, 0, 1}, {-1, 0, 0}})}));
  CHECK(c.standard_monomials == 5);
  // the unit ideal: {1}
  B = modular_lex_groebner_basis(std::vector<P2>{t * s - 1, t * s - 2}, &c);
  CHECK(same_basis(B, {lex({{1, 0, 0}})}));
}

TEST_CASE("modular lex basis: a double point (non-radical ideal) keeps its multiplicity", "[groebner]") {
  // the parabola t = s^2 and the tangent line t = 0: <t - s^2, t> = <s^2, t>, dimension 2 at one point
  Groebner_certificate c;
  const auto B = modular_lex_groebner_basis(std::vector<P2>{t - s * s, t}, &c);
  CHECK(same_basis(B, {lex({{1, 0, 2}}), lex({{1, 1, 0}})}));
  CHECK(c.dimension == 2);
  // inflection: t = s^3 against t = 0: s^3, multiplicity 3; and shifted to s = 1/2
  const std::vector<Rational> cube{0, 0, 0, 1};
  CHECK(groebner_eliminant(std::vector<P2>{t - s * s * s, t}) == Polynomial_1<Rational>(cube.begin(), cube.end()));
  const P2 u = 2 * s - 1;
  const auto e = groebner_eliminant(std::vector<P2>{t - u * u * u, t});
  const std::vector<Rational> shifted{Rational(-1, 8), Rational(3, 4), Rational(-3, 2), Rational(1)};  // (s - 1/2)^3
  CHECK(e == Polynomial_1<Rational>(shifted.begin(), shifted.end()));
}

TEST_CASE("modular lex basis: bad and unlucky primes are discarded", "[groebner]") {
  const Integer p0 = internal::Montgomery_modulus::gmpz_from_u64(internal::word_prime(0));
  Groebner_certificate c;
  // the leading coefficient p0 of p0 t - s vanishes modulo the first prime: discarded. Basis {s^2 - p0^2, t - s/p0}.
  auto B = modular_lex_groebner_basis(std::vector<P2>{P2(p0) * t - s, t * t - 1}, &c);
  CHECK(same_basis(B, {lex({{1, 0, 2}, {-Rational(p0 * p0), 0, 0}}), lex({{1, 1, 0}, {-Rational(1) / Rational(p0), 0, 1}})}));
  CHECK(c.discarded_primes >= 1);
  // the points (0, 0) and (p0, 1) collide modulo p0 (the ideal mod p0 is <s>, positive-dimensional): discarded
  const std::vector<P2> F{s * s - P2(p0) * s, t * s * s - P2(p0) * t * s + P2(p0) * t - s};
  B = modular_lex_groebner_basis(F, &c);
  CHECK(same_basis(B, {lex({{1, 0, 2}, {-Rational(p0), 0, 1}}), lex({{1, 1, 0}, {-Rational(1) / Rational(p0), 0, 1}})}));
  CHECK(c.discarded_primes >= 1);
  CHECK_FALSE(c.exact_fallback);
}

TEST_CASE("modular lex basis equals the exact rational Buchberger basis (degrees 2-3)", "[groebner]") {
  std::mt19937 rng(2024);
  const int dims[][4] = {{2, 2, 2, 2}, {2, 2, 1, 2}, {3, 2, 2, 2}, {2, 3, 3, 1}, {2, 2, 2, 2}, {3, 1, 1, 3}};
  for (const auto& d : dims) {
    const std::vector<P2> F{random_polynomial(d[0], d[1], rng), random_polynomial(d[2], d[3], rng)};
    std::vector<Lex_polynomial_2> L;
    for (const auto& f : F) L.push_back(Lex_polynomial_2(f));
    Groebner_certificate c;
    const auto B = modular_lex_groebner_basis(F, &c);
    INFO("degrees " << d[0] << d[1] << d[2] << d[3] << " primes " << c.primes);
    CHECK(same_basis(B, lex_groebner_basis(L)));
    CHECK(check_lex_groebner_basis(F, B) == Groebner_check::certified);
  }
}

TEST_CASE("modular lex basis: no dimension count (common leading-coefficient roots both ways)", "[groebner]") {
  // s t - 1 and s t^2 + s^2 t - 1: lc_t = s, s and lc_s = t, t share a root, so neither deg Res_t = 3 nor
  // deg Res_s bounds the quotient's dimension sharply (both curves pass through the points at infinity). Solutions:
  // s t = 1, s + t = 1: basis {s^2 - s + 1, t + s - 1}, from the exact rational Buchberger algorithm.
  const std::vector<P2> F{s * t - 1, s * t * t + s * s * t - 1};
  const std::vector<Lex_polynomial_2> want{lex({{1, 0, 2}, {-1, 0, 1}, {1, 0, 0}}), lex({{1, 1, 0}, {1, 0, 1}, {-1, 0, 0}})};
  Groebner_certificate c;
  CHECK(same_basis(modular_lex_groebner_basis(F, &c), want));
  CHECK(c.exact_fallback);
  CHECK(check_lex_groebner_basis(F, want) == Groebner_check::dimension_unknown);
  // within a budget too small for the exact algorithm: Error, never an unproved basis
  CHECK_THROWS_AS(modular_lex_groebner_basis(F, &c, 3), Error);
}

TEST_CASE("modular lex basis: a common component (Res_t = 0 although the leading coefficients are coprime)",
          "[groebner]") {
  // (t - s)(t + 1) and (t - s) t generate <t - s>: positive-dimensional, no count; the exact algorithm decides
  const std::vector<P2> F{(t - s) * (t + 1), (t - s) * t};
  Groebner_certificate c;
  CHECK(same_basis(modular_lex_groebner_basis(F, &c), {lex({{1, 1, 0}, {-1, 0, 1}})}));
  CHECK(c.exact_fallback);
  CHECK(CGAL::is_zero(groebner_eliminant(F)));
  // the point (0, 0) of the common line: I ⊆ <s, t>, a Groebner basis, but nothing bounds dim Q[s,t]/I
  CHECK(check_lex_groebner_basis(F, {lex({{1, 0, 1}}), lex({{1, 1, 0}})}) == Groebner_check::dimension_unknown);
}

TEST_CASE("modular lex basis of three equations: the resultant gcd bound", "[groebner]") {
  // t - s^2, t^2 + s^2 - 2, t - 1 (leading coefficients 1): pairwise resultants (s^2 - 1)(s^2 + 2), s^2 - 1,
  // s^2 - 1, gcd of degree 2 = the two points (+-1, 1): certified without the exact algorithm
  Groebner_certificate c;
  CHECK(same_basis(modular_lex_groebner_basis(std::vector<P2>{t - s * s, t * t + s * s - 2, t - 1}, &c),
                   {lex({{1, 0, 2}, {-1, 0, 0}}), lex({{1, 1, 0}, {-1, 0, 0}})}));
  CHECK_FALSE(c.exact_fallback);
  CHECK(c.dimension == 2);
  // common leading-coefficient roots (s t - 1 twice): the exact algorithm; with a zero budget, Error
  const std::vector<P2> F{s * t - 1, s * t * t + s * s * t - 1, s * t + s + t - 2};
  CHECK(same_basis(modular_lex_groebner_basis(F, &c), {lex({{1, 0, 2}, {-1, 0, 1}, {1, 0, 0}}), lex({{1, 1, 0}, {1, 0, 1}, {-1, 0, 0}})}));
  CHECK(c.exact_fallback);
  CHECK_THROWS_AS(modular_lex_groebner_basis(F, &c, 0), Error);
}

TEST_CASE("certification rejects corrupted bases", "[groebner]") {
  const std::vector<P2> F{t - s * s, t * t + s * s - 2};
  const auto B = modular_lex_groebner_basis(F);
  REQUIRE(check_lex_groebner_basis(F, B) == Groebner_check::certified);
  // one coefficient changed: s^4 + s^2 - 2 -> s^4 + s^2 - 3 (F_2 does not reduce to 0)
  auto bad = B;
  bad[0] = lex({{1, 0, 4}, {1, 0, 2}, {-3, 0, 0}});
  CHECK(check_lex_groebner_basis(F, bad) == Groebner_check::ideal_not_contained);
  // the basis of a larger ideal (the single point (1, 1)): I ⊆ <B>, a Groebner basis, but 1 standard monomial < 4
  CHECK(check_lex_groebner_basis(F, {lex({{1, 0, 1}, {-1, 0, 0}}), lex({{1, 1, 0}, {-1, 0, 0}})}) ==
        Groebner_check::dimension_mismatch);
  // not monic
  bad = B;
  bad[1] = lex({{2, 1, 0}, {-2, 0, 2}});
  CHECK(check_lex_groebner_basis(F, bad) == Groebner_check::not_reduced);
  // {s^2 - 1, s t - 1, t^2 - 1} contains <s^2 - 1, s t - 1> but is no Groebner basis: the S-polynomial
  // t (s^2 - 1) - s (s t - 1) = s - t does not reduce to 0
  const std::vector<P2> G{s * s - 1, s * t - 1};
  CHECK(check_lex_groebner_basis(G, {lex({{1, 0, 2}, {-1, 0, 0}}), lex({{1, 1, 1}, {-1, 0, 0}}), lex({{1, 2, 0}, {-1, 0, 0}})}) ==
        Groebner_check::not_a_groebner_basis);
  // a generated curve system: corrupt one tail coefficient of each element in turn
  std::mt19937 rng(7);
  const std::vector<P2> H{random_polynomial(3, 2, rng), random_polynomial(2, 2, rng)};
  const auto C = modular_lex_groebner_basis(H);
  REQUIRE(check_lex_groebner_basis(H, C) == Groebner_check::certified);
  for (std::size_t k = 0; k < C.size(); ++k) {
    auto terms = C[k].terms();
    if (terms.size() < 2) continue;
    std::next(terms.begin())->second += Rational(1, 7);
    auto D = C;
    D[k] = Lex_polynomial_2(terms);
    const auto r = check_lex_groebner_basis(H, D);
    CHECK((r == Groebner_check::ideal_not_contained || r == Groebner_check::not_a_groebner_basis));
  }
}

TEST_CASE("groebner strategy: identical answers to the default method, degrees 2-6, planar and space",
          "[groebner][curve_intersection]") {
  // (n1, n2, rational): mixed degrees keep the lex bases small enough for a fast test (6-6 takes seconds)
  const int cases[][3] = {{2, 2, 1}, {3, 3, 1}, {3, 3, 0}, {4, 3, 0}, {2, 5, 0}, {5, 2, 1}, {6, 2, 0}, {2, 6, 0},
                          {4, 2, 1}, {3, 4, 0}, {6, 3, 0}};
  unsigned long seed = 500;
  for (const auto& cs : cases)
    for (int k : {1, 3}) {
      Curve_problem_parameters p;
      p.degree_1 = cs[0];
      p.degree_2 = cs[1];
      p.intersections = std::min(k, cs[1] + 1);
      p.rational = cs[2] == 1;
      p.range = 16;
      p.seed = seed++;
      INFO("n1=" << cs[0] << " n2=" << cs[1] << " rational=" << cs[2] << " seed=" << p.seed);
      const auto a = generate_curve_problem<2>(p);
      const auto ra = intersect_curves(a.curve_1, a.curve_2);
      require_same<2>(ra, intersect_curves(a.curve_1, a.curve_2, Curve_intersection_method::groebner));
      for (const auto& st : a.known) {
        bool found = false;
        for (const auto& q : ra.points) found = found || (q.s == st.first && q.t == st.second);
        CHECK(found);
      }
      if (cs[0] + cs[1] <= 8) {
        const auto b = generate_curve_problem<3>(p);
        require_same<3>(intersect_curves(b.curve_1, b.curve_2),
                        intersect_curves(b.curve_1, b.curve_2, Curve_intersection_method::groebner));
      }
    }
}
