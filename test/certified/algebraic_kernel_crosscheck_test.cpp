// Cross-check of bezoutian's root isolation against CGAL's
// Algebraic_kernel_d_1 (GMP arithmetic kernel), an independent
// implementation (bitstream Descartes): same roots, same multiplicities,
// each number compared equal by CGAL's own Compare_1.
#include <catch2/catch.hpp>

#include <bezoutian/arrangement/Algebraic_kernel_interop.h>
#include <bezoutian/algebraic/Root_isolation.h>

#include <random>
#include <string>
#include <utility>
#include <vector>

using namespace bezoutian;
typedef Polynomial_1<Integer> P;
typedef Cgal_algebraic_kernel_1 AK;

namespace {

std::mt19937_64 rng(987654321);

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

long random_in(long lo, long hi) { return lo + static_cast<long>(rng() % static_cast<unsigned long>(hi - lo + 1)); }

// Seeded families of polynomials of degree <= 60.
P test_polynomial(int i) {
  const int degree = 1 + i % 60;
  switch (i % 5) {
    case 0:  // dense random
      return random_polynomial(degree, 1 + static_cast<int>(rng() % 100));
    case 1: {  // product of small random factors, some repeated
      P f(Integer(1));
      while (f.degree() < degree - 3) {
        P g = random_polynomial(static_cast<int>(random_in(1, 3)), 8);
        const int m = static_cast<int>(random_in(1, 3));
        for (int k = 0; k < m && f.degree() + g.degree() <= 60; ++k) f *= g;
      }
      return f;
    }
    case 2: {  // rational roots in [0,1] (some equal, some very close) times a random factor
      P f = random_polynomial(std::max(1, degree / 2), 30);
      for (int k = 0; k < degree / 2; ++k) {
        const long q = random_in(1, 1000000), p = random_in(0, q);
        f *= P(Integer(-p), Integer(q));
      }
      return f;
    }
    case 3: {  // roots exactly at 0, 1/2 and 1 and close irrational ones
      P f = P(Integer(0), Integer(1)) * P(Integer(-1), Integer(2)) * P(Integer(-1), Integer(1));
      const P g = random_polynomial(std::max(1, degree - 3), 40);
      return f * g * (rng() % 2 ? g : P(Integer(1)));
    }
    default: {  // a square times a random polynomial, perturbed clusters
      const P g = random_polynomial(std::max(1, degree / 3), 20);
      P h = random_polynomial(std::max(1, degree / 3), 60);
      return g * g * h;
    }
  }
}

// Our roots vs CGAL's, both sorted: same size, multiplicities, numbers.
void check_same(const std::vector<Isolated_root>& ours, const std::vector<std::pair<AK::Algebraic_real_1, int>>& theirs,
                const AK& ak, const std::string& what) {
  INFO(what);
  REQUIRE(ours.size() == theirs.size());
  for (std::size_t k = 0; k < ours.size(); ++k) {
    CHECK(ours[k].multiplicity == theirs[k].second);
    CHECK(compare_with_cgal(ours[k].root, theirs[k].first, ak) == 0);
  }
}

}  // namespace

TEST_CASE("isolate_real_roots agrees with CGAL::Algebraic_kernel_d_1 on [0,1] and on R", "[certified][root_isolation]") {
  const AK ak;
  int total_roots = 0;
  for (int i = 0; i < 300; ++i) {
    const P f = test_polynomial(i);
    if (CGAL::is_zero(f)) continue;
    const std::string what = "polynomial #" + std::to_string(i) + " of degree " + std::to_string(f.degree());
    {
      std::vector<std::pair<AK::Algebraic_real_1, int>> theirs;
      ak.solve_1_object()(f, Rational(0), Rational(1), std::back_inserter(theirs));
      check_same(isolate_real_roots(f, Rational(0), Rational(1)), theirs, ak, what + " on [0,1]");
      CHECK(count_real_roots(f, Rational(0), Rational(1)) == theirs.size());
    }
    {
      std::vector<std::pair<AK::Algebraic_real_1, int>> theirs;
      ak.solve_1_object()(f, std::back_inserter(theirs));
      const auto ours = isolate_real_roots(f);
      check_same(ours, theirs, ak, what + " on R");
      total_roots += static_cast<int>(ours.size());
      // rational roots: ours are exact exactly when CGAL's number is rational
      for (std::size_t k = 0; k < ours.size() && k < theirs.size(); ++k)
        if (ours[k].root.is_rational()) CHECK(ak.sign_at_1_object()(P(-ours[k].root.rational_value().numerator(), ours[k].root.rational_value().denominator()), theirs[k].first) == CGAL::ZERO);
    }
  }
  CHECK(total_roots > 500);
}

TEST_CASE("conversions between Algebraic_real and CGAL's Algebraic_real_1", "[certified][algebraic_real]") {
  const AK ak;
  const P f = P(Integer(-2), Integer(0), Integer(1)) * P(Integer(-1), Integer(3)) * random_polynomial(15, 50);
  std::vector<std::pair<AK::Algebraic_real_1, int>> theirs;
  ak.solve_1_object()(f, std::back_inserter(theirs));
  const auto ours = isolate_real_roots(f);
  REQUIRE(ours.size() == theirs.size());
  for (std::size_t k = 0; k < ours.size(); ++k) {
    const Algebraic_real back = from_cgal_algebraic_real(theirs[k].first, ak);
    CHECK(back == ours[k].root);
    CHECK(back.is_rational() == ours[k].root.is_rational());
    CHECK(ak.compare_1_object()(to_cgal_algebraic_real(ours[k].root, ak), theirs[k].first) == CGAL::EQUAL);
    if (k + 1 < ours.size()) CHECK(compare_with_cgal(ours[k].root, theirs[k + 1].first, ak) == -1);
    // CGAL's sign of our defining polynomial at its own root is zero
    CHECK(ak.sign_at_1_object()(ours[k].root.polynomial(), theirs[k].first) == CGAL::ZERO);
  }
}
