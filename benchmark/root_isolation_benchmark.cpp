// Benchmark of bezoutian::isolate_real_roots against CGAL's
// Algebraic_kernel_d_1<CGAL::Gmpz> (not part of the test build); the numbers
// of roots are checked to agree. Families: random dense polynomials, degree
// 100 with ten roots in [0,1], shifted Chebyshev polynomials (all roots in
// (0,1)), Mignotte polynomials (two roots 10^-20 .. 10^-100 apart), rational
// roots, non-square-free input, and a few Algebraic_real operations.
//
// Build by hand from the project root (see doc/algebraic_numbers.md):
//   g++ -std=c++17 -O2 -DNDEBUG -DCGAL_USE_GMP -DCGAL_USE_MPFI -Iinclude \
//       benchmark/root_isolation_benchmark.cpp -o root_isolation_benchmark -lmpfi -lmpfr -lgmp
// Run: ./root_isolation_benchmark
// Times are the minimum over several runs (the machine may be shared).
#include <bezoutian/arrangement/Algebraic_kernel_interop.h>
#include <bezoutian/algebraic/Root_isolation.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

using namespace bezoutian;
typedef Polynomial_1<Integer> P;
typedef Cgal_algebraic_kernel_1 AK;

namespace {

std::mt19937_64 rng(42);

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

P random_positive_polynomial(int degree, int bits) {  // no positive roots
  std::vector<Integer> c;
  for (int i = 0; i <= degree; ++i) c.push_back(CGAL::abs(random_integer(bits)) + Integer(1));
  return P(c.begin(), c.end());
}

template <class F>
double best_ms(F f, int runs) {
  double best = 1e300;
  for (int i = 0; i < runs; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

int max_bits(const P& f) {
  std::size_t b = 0;
  for (int i = 0; i <= f.degree(); ++i) b = std::max(b, mpz_sizeinbase(f[i].mpz(), 2));
  return static_cast<int>(b);
}

void run(const std::string& name, const P& f, int runs = 5) {
  const AK ak;
  std::size_t n01 = 0, nR = 0, c01 = 0, cR = 0;
  const double t01 = best_ms([&] { n01 = isolate_real_roots(f, Rational(0), Rational(1)).size(); }, runs);
  const double tR = best_ms([&] { nR = isolate_real_roots(f).size(); }, runs);
  const double u01 = best_ms(
      [&] {
        std::vector<std::pair<AK::Algebraic_real_1, int>> r;
        ak.solve_1_object()(f, Rational(0), Rational(1), std::back_inserter(r));
        c01 = r.size();
      },
      std::max(1, runs / 2));
  const double uR = best_ms(
      [&] {
        std::vector<std::pair<AK::Algebraic_real_1, int>> r;
        ak.solve_1_object()(f, std::back_inserter(r));
        cR = r.size();
      },
      std::max(1, runs / 2));
  std::printf("| %-22s | %3d | %4d | %3zu | %9.3f | %3zu | %9.3f | %9.3f | %9.3f |%s\n", name.c_str(), f.degree(),
              max_bits(f), n01, t01, nR, tR, u01, uR, (n01 == c01 && nR == cR) ? "" : " MISMATCH");
}

P chebyshev01(int n) {  // T_n(2x - 1)
  const P y(Integer(-1), Integer(2));
  P t0(Integer(1)), t1 = y;
  for (int k = 1; k < n; ++k) {
    const P t2 = Integer(2) * y * t1 - t0;
    t0 = t1;
    t1 = t2;
  }
  return t1;
}

}  // namespace

int main() {
  std::printf("| polynomial             | deg | bits | [0,1] | ours ms | R | ours ms | CGAL [0,1] ms | CGAL R ms |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (int k = 0; k < 2; ++k) run("random dense", random_polynomial(50, 60));
  for (int k = 0; k < 2; ++k) run("random dense", random_polynomial(100, 150));
  for (int k = 0; k < 3; ++k) {
    P f = random_polynomial(90, 100);
    for (int i = 0; i < 10; ++i) f *= P(Integer(-static_cast<long>(rng() % 65521)), Integer(65521));
    run("10 roots in [0,1]", f + P(Integer(1)));
  }
  for (int n : {20, 50, 100}) run("Chebyshev T_n(2x-1)", chebyshev01(n), n == 100 ? 2 : 5);
  for (int n : {20, 50, 100}) {
    const P x(Integer(0), Integer(1));
    run("Mignotte x^n-2(100x-1)^2", CGAL::ipower(x, n) - Integer(2) * CGAL::ipower(P(Integer(-1), Integer(100)), 2),
        n == 100 ? 2 : 5);
  }
  {
    P w(Integer(1));
    for (int i = 1; i <= 20; ++i) w *= P(Integer(-i), Integer(21));
    run("prod (21x-i), i<=20", w);
    run("prod (21x-i) + 1", w + P(Integer(1)));
  }
  {
    const P g = random_polynomial(20, 20);
    run("g^2 h (not square-free)", g * g * random_polynomial(20, 60));
  }

  // Algebraic_real operations on roots of a degree-100 polynomial.
  P f = random_polynomial(90, 100);
  for (int i = 0; i < 10; ++i) f *= P(Integer(-static_cast<long>(rng() % 65521)), Integer(65521));
  f += P(Integer(1));
  const auto roots = isolate_real_roots(f, Rational(0), Rational(1));
  std::string digits;
  const double t_dec = best_ms(
      [&] {
        const auto r = isolate_real_roots(f, Rational(0), Rational(1));
        digits = r[0].root.to_decimal_string(100);
      },
      3);
  std::printf("\nisolate + to_decimal_string(100) of a root of a degree-100 polynomial: %.3f ms\n", t_dec);
  // sqrt(2) vs sqrt(2 + 10^-100): refinement to ~340 bits before they separate
  const Integer e100 = CGAL::ipower(Integer(10), 100);
  const double t_cmp = best_ms(
      [&] {
        const Algebraic_real a(P(Integer(-2), Integer(0), Integer(1)), Rational(1), Rational(2));
        const Algebraic_real b(P(-(Integer(2) * e100 + Integer(1)), Integer(0), e100), Rational(1), Rational(2));
        if (a.compare(b) != -1) std::printf("WRONG\n");
      },
      5);
  std::printf("construct sqrt(2), sqrt(2 + 10^-100) and compare them: %.3f ms\n", t_cmp);
  const double t_eq = best_ms(
      [&] {
        const P x2m2(Integer(-2), Integer(0), Integer(1));
        const Algebraic_real a(x2m2 * random_positive_polynomial(30, 60), Rational(1), Rational(3, 2));
        const Algebraic_real b(x2m2 * random_positive_polynomial(30, 60), Rational(1), Rational(3, 2));
        if (a.compare(b) != 0) std::printf("WRONG\n");
      },
      5);
  std::printf("sqrt(2) as roots of two different degree-32 polynomials, construct and compare (equal): %.3f ms\n",
              t_eq);
  return 0;
}
