// Thread safety as a user meets it (doc/algebraic_numbers.md, "Threads"): independent curve problems solved on four
// threads, and one shared result (lazy parameters made exact on demand, exact parameters sharing a defining
// polynomial) read, refined and compared from four threads at once. Answers are checked against closed forms
// and against the single-thread results. scripts/sanitizers.sh thread runs this file under ThreadSanitizer.
#include "thread_test_support.h"

#include <bezoutian/intersection/Curve_intersection.h>
#include <bezoutian/geometry/Curve_problem_generator.h>
#include <bezoutian/algebraic/Root_isolation.h>

#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

using namespace bezoutian;

namespace {

constexpr int threads = bezoutian_test::test_threads;

// Catch2's assertions are not thread-safe: the threads record failed expectations, the main thread reports them.
struct Failures {
  std::mutex mutex;
  std::vector<std::string> what;
  void add(const char* expr, int line) {
    std::lock_guard<std::mutex> lock(mutex);
    what.push_back("line " + std::to_string(line) + ": " + expr);
  }
  void report() {
    for (const auto& w : what) FAIL_CHECK(w);
    CHECK(what.empty());
  }
};
#define EXPECT(F, cond) \
  do {                  \
    if (!(cond)) (F).add(#cond, __LINE__); \
  } while (0)

using bezoutian_test::run_on_threads;

// The power-basis polynomial a_0 + a_1 x + ... as a Bezier graph (x(t) = t, y(t) = that polynomial) of degree n:
// b_i = sum_{j <= i} C(i, j) / C(n, j) a_j.
Rational_bezier_curve_2<> graph(const std::vector<Rational>& a) {
  const int n = int(a.size()) - 1;
  std::vector<Rational_bezier_curve_2<>::Point> net;
  for (int i = 0; i <= n; ++i) {
    Rational y(0);
    for (int j = 0; j <= i; ++j) y += binomial<Rational>(i, j) / binomial<Rational>(n, j) * a[j];
    net.push_back({Rational(i, n), y});
  }
  return Rational_bezier_curve_2<>(net);
}

// Coefficients of a product of polynomials given by their coefficient lists.
std::vector<Rational> times(const std::vector<Rational>& f, const std::vector<Rational>& g) {
  std::vector<Rational> h(f.size() + g.size() - 1, Rational(0));
  for (std::size_t i = 0; i < f.size(); ++i)
    for (std::size_t j = 0; j < g.size(); ++j) h[i + j] += f[i] * g[j];
  return h;
}

// The parabola y = x^2 against y = x^2 + (2x^2 - 1)(3x^2 - 1)(4x - 1): they cross where x is 1/4, 1/sqrt(3) or
// 1/sqrt(2), with s = t = x there (both curves are graphs parametrised by x).
struct Known_crossings {
  Rational_bezier_curve_2<> parabola = graph({Rational(0), Rational(0), Rational(1)});
  Rational_bezier_curve_2<> quintic;
  Known_crossings() {
    std::vector<Rational> d = times(times({Rational(-1), Rational(0), Rational(2)}, {Rational(-1), Rational(0), Rational(3)}),
                                    {Rational(-1), Rational(4)});
    d[2] += 1;
    quintic = graph(d);
  }
};

// 1/4, 1/sqrt(3), 1/sqrt(2) to 40 significant digits.
const char* const crossing_digits[3] = {"0.2500000000000000000000000000000000000000",
                                        "0.5773502691896257645091487805019574556476",
                                        "0.7071067811865475244008443621048490392848"};

// What one thread checks on the three crossings of Known_crossings (in an order of its own): values, decimal
// digits, comparisons among them and with rationals, refinement to 2^-400, defining polynomials.
void check_known_crossings(const std::vector<Curve_intersection_point>& pts, int k, Failures& F) {
  if (pts.size() != 3) return F.add("three crossings", __LINE__);
  const Polynomial_1<Integer> two_x2_minus_1(Integer(-1), Integer(0), Integer(2));
  const Polynomial_1<Integer> three_x2_minus_1(Integer(-1), Integer(0), Integer(3));
  for (int step = 0; step < 3; ++step) {
    const int i = (k + step) % 3;
    const Curve_intersection_point& p = pts[std::size_t(i)];
    const Curve_intersection_point& q = pts[std::size_t((i + 1) % 3)];
    switch ((k + step) % 4) {  // threads reach the shared numbers through different members first
      case 0: EXPECT(F, p.s.to_decimal_string(40) == crossing_digits[i]); break;
      case 1: EXPECT(F, p.t.to_double() == std::strtod(crossing_digits[i], nullptr)); break;  // correctly rounded
      case 2: EXPECT(F, p.s.compare(p.t) == 0); break;
      default: EXPECT(F, (p.s < q.s) == (i < 2)); break;
    }
    EXPECT(F, p.s == p.t);
    EXPECT(F, p.t.to_decimal_string(40) == crossing_digits[i]);
    EXPECT(F, std::abs(p.s.to_double() - (i == 0 ? 0.25 : 1 / std::sqrt(i == 1 ? 3.0 : 2.0))) < 1e-15);
    EXPECT(F, p.s.compare(Rational(1, 2)) == (i == 0 ? -1 : 1));
    EXPECT(F, (p.s < q.s) == (i < 2));
    EXPECT(F, p.t.is_rational() == (i == 0));
    Rational w(1);
    mpz_mul_2exp(mpq_denref(w.mpq()), mpq_denref(w.mpq()), 400);
    p.s.refine_to_width(w);
    EXPECT(F, p.s.upper() - p.s.lower() <= w);
    if (i == 0) {
      EXPECT(F, p.s.rational_value() == Rational(1, 4));
    } else {
      const Polynomial_1<Integer> f = i == 1 ? three_x2_minus_1 : two_x2_minus_1;
      EXPECT(F, p.s.sign_of(f) == 0);
      EXPECT(F, p.t.sign_of(i == 1 ? two_x2_minus_1 : three_x2_minus_1) != 0);
      const Polynomial_1<Integer> P = p.s.polynomial();  // a copy of its own, refined concurrently elsewhere
      Polynomial_1<Integer> quotient, remainder;
      Integer d;
      Polynomial_1<Integer>::pseudo_division(P, f, quotient, remainder, d);
      EXPECT(F, CGAL::is_zero(remainder));  // f divides the defining polynomial
      // lo^2 < 1/i' < hi^2 for x = 1/sqrt(i'), i' = 3 or 2, on the interval refined to 2^-400
      const Rational lo = p.s.lower(), hi = p.s.upper(), c(1, i == 1 ? 3 : 2);
      EXPECT(F, lo * lo < c);
      EXPECT(F, hi * hi > c);
    }
    const Algebraic_real copy = p.s;  // copies share the representation
    EXPECT(F, copy == p.t);
    EXPECT(F, -copy < Algebraic_real(0));
  }
}

Curve_problem<2> planar_problem(int i) {
  Curve_problem_parameters par;
  par.degree_1 = 3 + i % 3;
  par.degree_2 = 3 + (i / 3) % 2;
  par.intersections = 1 + i % 3;
  par.rational = i % 2 == 0;
  par.range = 16;
  par.seed = 4100 + unsigned(i);
  return generate_curve_problem<2>(par);
}

Curve_problem<3> space_problem(int i) {
  Curve_problem_parameters par;
  par.degree_1 = 2 + i % 2;
  par.degree_2 = 3;
  par.intersections = 1 + i % 2;
  par.rational = i % 2 == 1;
  par.range = 16;
  par.seed = 5200 + unsigned(i);
  return generate_curve_problem<3>(par);
}

bool holds_known(const Curve_intersection_result& r, const std::pair<Rational, Rational>& st) {
  for (const auto& p : r.points)
    if (p.s == Algebraic_real(st.first) && p.t == Algebraic_real(st.second)) return true;
  return false;
}

// Same points, exactly (both sorted by s, then t).
bool same_points(const Curve_intersection_result& a, const Curve_intersection_result& b) {
  if (a.points.size() != b.points.size() || a.overlaps.size() != b.overlaps.size()) return false;
  for (std::size_t i = 0; i < a.points.size(); ++i)
    if (a.points[i].s != b.points[i].s || a.points[i].t != b.points[i].t ||
        a.points[i].multiplicity != b.points[i].multiplicity)
      return false;
  return true;
}

}  // namespace

TEST_CASE("threads: independent curve problems on four threads agree with one thread", "[threads]") {
  const int planar = 16, space = 4;
  std::vector<Curve_problem<2>> P2;
  std::vector<Curve_problem<3>> P3;
  std::vector<Curve_intersection_result> single2, single3;
  for (int i = 0; i < planar; ++i) {
    P2.push_back(planar_problem(i));
    single2.push_back(intersect_curves(P2.back().curve_1, P2.back().curve_2));
  }
  for (int i = 0; i < space; ++i) {
    P3.push_back(space_problem(i));
    single3.push_back(intersect_curves(P3.back().curve_1, P3.back().curve_2));
  }
  int known = 0;
  for (const auto& p : P2) known += int(p.known.size());
  for (const auto& p : P3) known += int(p.known.size());
  std::atomic<int> failures{0}, known_found{0}, known_total{0};
  run_on_threads([&](int k) {
    for (int i = k; i < planar; i += threads) {
      // every thread its own result: the default path, and the exact subresultant path for half of them
      const auto method = i % 2 == 0 ? Curve_intersection_method::default_method : Curve_intersection_method::subresultant;
      const Curve_intersection_result r = intersect_curves(P2[std::size_t(i)].curve_1, P2[std::size_t(i)].curve_2, method);
      if (!same_points(r, single2[std::size_t(i)])) ++failures;
      for (const auto& st : P2[std::size_t(i)].known) {
        ++known_total;
        if (holds_known(r, st)) ++known_found;
      }
    }
    for (int i = k; i < space; i += threads) {
      const Curve_intersection_result r = intersect_curves(P3[std::size_t(i)].curve_1, P3[std::size_t(i)].curve_2);
      if (!same_points(r, single3[std::size_t(i)])) ++failures;
      for (const auto& st : P3[std::size_t(i)].known) {
        ++known_total;
        if (holds_known(r, st)) ++known_found;
      }
    }
  });
  CHECK(failures == 0);
  CHECK(known_total == known);
  CHECK(known_found == known_total);
}

TEST_CASE("threads: one shared result read, refined and compared from four threads", "[threads]") {
  const Known_crossings c;
#ifdef BEZOUTIAN_SANITIZER_BUILD
  const int rounds = 4;
#else
  const int rounds = 12;
#endif
  for (int round = 0; round < rounds; ++round) {
    // a fresh result each round, so that the threads race to make the same lazy numbers exact
    const Curve_intersection_result lazy = intersect_curves(c.parabola, c.quintic);
    REQUIRE(lazy.points.size() == 3);
    CHECK(lazy.points[1].s.is_lazy());
    const Curve_intersection_result exact =
        intersect_curves(c.parabola, c.quintic, Curve_intersection_method::subresultant);
    REQUIRE(exact.points.size() == 3);
    CHECK_FALSE(exact.points[1].s.is_lazy());
    std::atomic<int> mismatches{0};
    Failures F;
    run_on_threads([&](int k) {
      check_known_crossings(k % 2 == 0 ? lazy.points : exact.points, k, F);
      check_known_crossings(k % 2 == 0 ? exact.points : lazy.points, k + 1, F);
      for (std::size_t step = 0; step < 3; ++step) {  // the two results against each other
        const std::size_t i = (step + std::size_t(k)) % 3;
        if (lazy.points[i].s != exact.points[i].t || lazy.points[i].t == exact.points[(i + 1) % 3].s) ++mismatches;
      }
    });
    CHECK(mismatches == 0);
    F.report();
  }
}

TEST_CASE("threads: roots of one polynomial (one shared defining polynomial) used from four threads", "[threads]") {
  // (x^2 - 2)(x^2 - 3)(4x - 1)(x^2 - 5): roots -sqrt 5, -sqrt 3, -sqrt 2, 1/4, sqrt 2, sqrt 3, sqrt 5
  Polynomial_1<Integer> f = Polynomial_1<Integer>(Integer(-2), Integer(0), Integer(1)) *
                            Polynomial_1<Integer>(Integer(-3), Integer(0), Integer(1)) *
                            Polynomial_1<Integer>(Integer(-1), Integer(4)) *
                            Polynomial_1<Integer>(Integer(-5), Integer(0), Integer(1));
  const double expected[7] = {-std::sqrt(5.0), -std::sqrt(3.0), -std::sqrt(2.0), 0.25,
                              std::sqrt(2.0), std::sqrt(3.0), std::sqrt(5.0)};
  for (int round = 0; round < 4; ++round) {
    const std::vector<Isolated_root> roots = isolate_real_roots(f);
    REQUIRE(roots.size() == 7);
    std::atomic<int> wrong{0};
    run_on_threads([&](int k) {
      for (int step = 0; step < 7; ++step) {
        const int i = (k * 2 + step) % 7;
        const Algebraic_real& x = roots[std::size_t(i)].root;
        if (x.to_double() != expected[i]) ++wrong;
        // equal to the same number given by another polynomial: the comparison replaces both defining
        // polynomials by their gcd while other threads read them
        if (i != 3) {
          const Integer n(i == 0 || i == 6 ? 5 : (i == 1 || i == 5 ? 3 : 2));
          const Polynomial_1<Integer> g = Polynomial_1<Integer>(-n, Integer(0), Integer(1)) *
                                          Polynomial_1<Integer>(Integer(-7), Integer(0), Integer(1));
          const Algebraic_real y(g, Rational(expected[i] - 0.01), Rational(expected[i] + 0.01));
          if (x != y) ++wrong;
          if (x.polynomial().degree() != 2) ++wrong;
        }
        if ((x < roots[std::size_t((i + 1) % 7)].root) != (i < 6)) ++wrong;
        Rational w(1);
        mpz_mul_2exp(mpq_denref(w.mpq()), mpq_denref(w.mpq()), 200 + 10 * unsigned(k));
        x.refine_to_width(w);
        if (!(x.upper() - x.lower() <= w)) ++wrong;
      }
    });
    CHECK(wrong == 0);
  }
}
