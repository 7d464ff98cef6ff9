// Planar default path of intersect_curves with lazy exact parameters (interval solver + Krawczyk boxes, exact on
// demand): cross-checks against the exact strategies and the generator's known intersections.
#include <bezoutian/intersection/Curve_intersection.h>
#include <bezoutian/geometry/Curve_problem_generator.h>
#include <bezoutian/algebraic/Root_isolation.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace bezoutian;

namespace {

Curve_problem<2> planar_problem(int degree, int i) {
  Curve_problem_parameters par;
  par.degree_1 = par.degree_2 = degree;
  par.intersections = std::min(2 + i % 3, degree + 1);
  par.rational = i % 2 == 0;
  par.range = 16;
  par.seed = 777 + i;
  return generate_curve_problem<2>(par);
}

int lazy_count(const Curve_intersection_result& r) {
  int n = 0;
  for (const auto& p : r.points) n += p.s.is_lazy() + p.t.is_lazy();
  return n;
}

}  // namespace

TEST_CASE("planar lazy default path agrees with the exact strategies point by point", "[planar_lazy]") {
  int problems = 0, lazy_problems = 0, lazy_points = 0;
  for (int degree = 2; degree <= 12; ++degree) {
    const int count = degree <= 5 ? 6 : (degree <= 7 ? 3 : 1);
    for (int i = 0; i < count; ++i) {
      const auto p = planar_problem(degree, i);
      INFO("degree " << degree << " problem " << i);
      const auto lazy = intersect_curves(p.curve_1, p.curve_2);  // default method
      // exact references: the subresultant and projection strategies; above degree 7 (where they take seconds) the
      // exact default path (multi-modular determinants, the lazy path switched off)
      const auto exact =
          degree <= 7 ? intersect_curves(p.curve_1, p.curve_2,
                                         degree <= 5 ? Curve_intersection_method::subresultant
                                                     : Curve_intersection_method::projection)
                      : internal::Curve_intersection_engine<2>(p.curve_1, p.curve_2,
                                                               Curve_intersection_method::default_method, false)
                            .run();
      ++problems;
      const int nl = lazy_count(lazy);
      if (nl > 0) {
        ++lazy_problems;
        lazy_points += int(lazy.points.size());
        // everything lazy: transversal crossings of multiplicity 1 strictly inside (0,1)^2
        for (const auto& q : lazy.points) {
          CHECK(q.s.is_lazy());
          CHECK(q.t.is_lazy());
          CHECK(q.kind == Curve_intersection_kind::transversal);
          CHECK(q.multiplicity == 1);
          CHECK_FALSE(q.tangent);
          const auto es = q.s.enclosure(), et = q.t.enclosure();
          CHECK(es.first > 0);
          CHECK(es.second < 1);
          CHECK(et.first > 0);
          CHECK(et.second < 1);
        }
        // the double values and the order need no exact representation
        for (const auto& q : lazy.points) CHECK(std::isfinite(q.s.to_double()));
        CHECK(lazy_count(lazy) == nl);
      }
      REQUIRE(lazy.points.size() == exact.points.size());
      REQUIRE(exact.overlaps.empty());
      for (std::size_t k = 0; k < exact.points.size(); ++k) {
        const auto &a = lazy.points[k], &b = exact.points[k];
        // the exact strategy's numbers: the lazy ones lie in their isolating intervals' neighbourhood
        CHECK(std::abs(a.s.to_double() - b.s.to_double()) < 1e-12);
        CHECK(a.s.compare(b.s) == 0);  // exact (materializes when the enclosures cannot separate)
        CHECK(a.t.compare(b.t) == 0);
        CHECK(a.kind == b.kind);
      }
      // the generator's known intersections (rational parameters) are found, and recognised as rationals
      for (const auto& kn : p.known) {
        int hits = 0;
        for (const auto& q : lazy.points)
          if (q.s.compare(kn.first) == 0 && q.t.compare(kn.second) == 0) {
            ++hits;
            CHECK(q.s.is_rational());
            CHECK(q.s.rational_value() == kn.first);
            CHECK(q.t.rational_value() == kn.second);
          }
        CHECK(hits == 1);
      }
    }
  }
  CHECK(problems == 4 * 6 + 2 * 3 + 5);
  CHECK(lazy_problems >= problems / 2);  // most random transversal configurations stay off the eliminants
  CHECK(lazy_points > 50);
}

TEST_CASE("planar lazy: forced materialization gives a root of the exact path's defining polynomial", "[planar_lazy]") {
  int irrational = 0;
  for (int i = 0; i < 4; ++i) {
    const auto p = planar_problem(6, i);
    const auto lazy = intersect_curves(p.curve_1, p.curve_2);
    const auto exact = intersect_curves(p.curve_1, p.curve_2, Curve_intersection_method::projection);
    REQUIRE(lazy.points.size() == exact.points.size());
    for (std::size_t k = 0; k < lazy.points.size(); ++k) {
      const Algebraic_real &a = lazy.points[k].s, &b = exact.points[k].s;
      a.materialize();
      CHECK_FALSE(a.is_lazy());
      REQUIRE(a.is_rational() == b.is_rational());
      if (a.is_rational()) {
        CHECK(a.rational_value() == b.rational_value());
        continue;
      }
      ++irrational;
      // each number is a root of the other's defining polynomial, in an interval isolating it (independent count)
      CHECK(a.sign_of(b.polynomial()) == 0);
      CHECK(b.sign_of(a.polynomial()) == 0);
      CHECK(count_real_roots(a.polynomial(), a.lower(), a.upper()) == 1);
      CHECK(a.polynomial().degree() >= 2);
      CHECK(a == b);
    }
  }
  CHECK(irrational > 3);
}

TEST_CASE("planar lazy: two roots of the eliminant in one Krawczyk box", "[planar_lazy]") {
  // C2(u) = (t^2 - 1, t^3 - t), t = 2u - 3/2: a nodal cubic, node (0,0) at u = 1/4 (on the arc) and u = 5/4 (off
  // it); implicit equation y^2 = x^2 (x + 1). C1: the line y = e, x = 3s - 2, e = 2^-60. R(s) = e^2 - x^2 (x + 1)
  // has the roots x ~ -e (the crossing with the arc near u = 1/4) and x ~ +e (the branch u ~ 5/4, not on the arc),
  // 2e/3 apart in s: far below the width of a double Krawczyk box.
  using Pt = Rational_bezier_curve_2<Rational>::Point;
  Rational e(1);
  mpz_mul_2exp(mpq_denref(e.mpq()), mpq_denref(e.mpq()), 60);
  const Rational_bezier_curve_2<Rational> line(std::vector<Pt>{Pt{Rational(-2), e}, Pt{Rational(1), e}});
  const Rational_bezier_curve_2<Rational> cubic(std::vector<Pt>{Pt{Rational(5, 4), Rational(-15, 8)},
                                                                Pt{Rational(-3, 4), Rational(47, 24)},
                                                                Pt{Rational(-17, 12), Rational(-5, 24)},
                                                                Pt{Rational(-3, 4), Rational(-3, 8)}});
  const auto lazy = intersect_curves(line, cubic);
  REQUIRE(lazy.points.size() == 2);
  const auto& q = lazy.points[1];  // s ~ 2/3
  REQUIRE(q.s.is_lazy());
  // R(s) written out by hand (x = 3s - 2): its two roots near 2/3 both lie in the enclosure
  const Polynomial_1<Rational> x(Rational(-2), Rational(3));
  const Polynomial_1<Rational> R = Polynomial_1<Rational>(e * e) - x * x * (x + Polynomial_1<Rational>(Rational(1)));
  const auto enc = q.s.enclosure();
  CHECK(count_real_roots(R, enc.first, enc.second) == 2);
  // materialization separates them and keeps the crossing on the arc: x = -e + O(e^2), i.e. s < 2/3
  q.s.materialize();
  CHECK(q.s.sign_of(R) == 0);
  CHECK(q.s < Rational(2, 3));
  CHECK(q.s > Rational(2, 3) - e);
  const auto exact = intersect_curves(line, cubic, Curve_intersection_method::subresultant);
  REQUIRE(exact.points.size() == 2);
  CHECK(q.s == exact.points[1].s);
  CHECK(q.t == exact.points[1].t);
  CHECK(lazy.points[0].s == exact.points[0].s);
  CHECK(lazy.points[0].t == exact.points[0].t);
}

TEST_CASE("planar lazy: numbers used without materialization", "[planar_lazy]") {
  const auto p = planar_problem(7, 0);
  const auto lazy = intersect_curves(p.curve_1, p.curve_2);
  const auto exact = intersect_curves(p.curve_1, p.curve_2, Curve_intersection_method::projection);
  REQUIRE(lazy.points.size() == exact.points.size());
  REQUIRE(lazy_count(lazy) == 2 * int(lazy.points.size()));
  for (std::size_t k = 0; k < lazy.points.size(); ++k) {
    const auto &a = lazy.points[k], &b = exact.points[k];
    // decimal strings and double intervals from contracted enclosures (Krawczyk in MPFI)
    CHECK(a.s.to_decimal_string(30) == b.s.to_decimal_string(30));
    const auto ia = a.t.to_interval(), ib = b.t.to_interval();
    CHECK(ia.first <= ib.second);
    CHECK(ib.first <= ia.second);
    CHECK(a.s.compare(Rational(1, 2)) == b.s.compare(Rational(1, 2)));
    CHECK(a.t.sign() == 1);
    if (k + 1 < lazy.points.size()) CHECK(a.s < lazy.points[k + 1].s);
  }
  // none of this needed the eliminants (unless a number sits exactly on a rounding boundary or at 1/2)
  int still_lazy = 0;
  for (const auto& a : lazy.points) still_lazy += a.s.is_lazy();
  CHECK(still_lazy >= int(lazy.points.size()) - 2);
  // members needing the exact representation materialize
  const Algebraic_real m = lazy.points[0].s.negated();
  CHECK_FALSE(lazy.points[0].s.is_lazy());
  CHECK(m == -exact.points[0].s);
}

TEST_CASE("planar lazy: two arcs of one nodal cubic (eliminants vanish identically)", "[planar_lazy]") {
  // C(u) = (t^2 - 1, t^3 - t), t = 3u - 3/2, node (0,0) at t = -1, 1, i.e. u = 1/6, 5/6. A = C on [0, 9/20],
  // B = C on [11/20, 1]: both arcs lie on the nodal cubic y^2 = x^2 (x + 1), so R(s) and T(t) vanish identically;
  // they cross only at the node: s = (1/6) / (9/20) = 10/27, t = (5/6 - 11/20) / (9/20) = 17/27.
  using Pt = Rational_bezier_curve_2<Rational>::Point;
  const Rational_bezier_curve_2<Rational> full(std::vector<Pt>{Pt{Rational(5, 4), Rational(-15, 8)},
                                                               Pt{Rational(-7, 4), Rational(31, 8)},
                                                               Pt{Rational(-7, 4), Rational(-31, 8)},
                                                               Pt{Rational(5, 4), Rational(15, 8)}});
  const auto A = full.split(Rational(9, 20)).first, B = full.split(Rational(11, 20)).second;
  const auto r = intersect_curves(A, B);
  REQUIRE(r.points.size() == 1);
  CHECK(r.overlaps.empty());
  CHECK(r.points[0].s.is_lazy());
  CHECK(r.points[0].kind == Curve_intersection_kind::transversal);
  // materialization falls back to the exact (subresultant) intersection inside the box
  CHECK(r.points[0].s.is_rational());
  CHECK(r.points[0].s.rational_value() == Rational(10, 27));
  CHECK(r.points[0].t.rational_value() == Rational(17, 27));
}
