// Curve/curve intersection: generated problems with known exact intersections (du-1989 §4.2), tangencies of
// multiplicity 2 and 3, endpoint hits, overlaps, identical and degenerate curves, space curves, loops.
#include <catch2/catch.hpp>

#include "intersection_checks.h"

#include <bezoutian/intersection/Curve_intersection.h>
#include <bezoutian/geometry/Curve_problem_generator.h>

#include <CGAL/Polynomial_traits_d.h>

using namespace bezoutian;
using Curve2 = Rational_bezier_curve_2<>;
using Curve3 = Rational_bezier_curve_3<>;

#ifndef BEZOUTIAN_GENERATED_REPETITIONS
#define BEZOUTIAN_GENERATED_REPETITIONS 5
#endif

namespace {

const Curve_intersection_method all_methods[] = {Curve_intersection_method::default_method,
                                                  Curve_intersection_method::subresultant,
                                                  Curve_intersection_method::projection,
                                                  Curve_intersection_method::resolvent};

using bezoutian_test::require_same;

// Polynomial curve from its power form (x(t), y(t)) given by coefficient lists.
Curve2 power_curve(std::vector<Rational> x, std::vector<Rational> y) {
  Curve2::Power_form f;
  f[0] = Polynomial_1<Rational>(Rational(1));
  f[1] = Polynomial_1<Rational>(x.begin(), x.end());
  f[2] = Polynomial_1<Rational>(y.begin(), y.end());
  return Curve2::from_power_form(f);
}

// Independent check of an extra (not constructed) intersection: s is a root of CGAL's own resultant Res_t, t of
// Res_s, and the points agree to 1e-12 after refinement.
template <int D>
void check_extra(const Rational_bezier_curve<Rational, D>& a, const Rational_bezier_curve<Rational, D>& b,
                 const Curve_intersection_point& p) {
  if (p.s.is_rational() && p.t.is_rational()) {
    CHECK(a(p.s.rational_value()) == b(p.t.rational_value()));
    return;
  }
  const auto H1 = internal::integer_power_form(a), H2 = internal::integer_power_form(b);
  using P2 = Polynomial_2<Integer>;
  P2 F1 = internal::cross_term(H1[1], H2[0], H2[1], H1[0]), F2 = internal::cross_term(H1[2], H2[0], H2[2], H1[0]);
  const auto R = CGAL::resultant(F1, F2);  // w.r.t. t (outer), a polynomial in s
  const auto T = CGAL::resultant(internal::swap_variables(F1), internal::swap_variables(F2));
  if (!CGAL::is_zero(R)) CHECK(p.s.sign_of(R) == 0);
  if (!CGAL::is_zero(T)) CHECK(p.t.sign_of(T) == 0);
  p.s.refine_to_width(Rational(1, 1000000) * Rational(1, 1000000) * Rational(1, 1000000));
  p.t.refine_to_width(Rational(1, 1000000) * Rational(1, 1000000) * Rational(1, 1000000));
  const auto x = a.evaluate(CGAL::to_double(p.s.lower())), y = b.evaluate(CGAL::to_double(p.t.lower()));
  for (int k = 0; k < D; ++k) CHECK(std::abs(x[k] - y[k]) < 1e-9 * (1 + std::abs(x[k])));
}

// du-1989 §4.2 generator with the parameters of these tests
template <int D>
Curve_problem<D> make_problem(int n1, int n2, int k, bool rational, unsigned long seed) {
  Curve_problem_parameters par;
  par.degree_1 = n1;
  par.degree_2 = n2;
  par.intersections = k;
  par.rational = rational;
  par.seed = seed;
  par.range = 16;
  return generate_curve_problem<D>(par);
}

template <int D>
int run_generated(int n1, int n2, int k, bool rational, unsigned long seed) {
  const Curve_problem<D> pb = make_problem<D>(n1, n2, k, rational, seed);
  INFO("D=" << D << " n1=" << n1 << " n2=" << n2 << " k=" << k << " rational=" << rational << " seed=" << seed);
  // the construction itself: C2(t_j) == C1(s_j)
  for (const auto& st : pb.known) REQUIRE(pb.curve_1(st.first) == pb.curve_2(st.second));
  const Curve_intersection_result r = intersect_curves(pb.curve_1, pb.curve_2);
  CHECK(r.overlaps.empty());
  for (const auto& st : pb.known) {
    bool found = false;
    for (const auto& p : r.points) found = found || (p.s == st.first && p.t == st.second);
    CHECK(found);
  }
  for (const auto& p : r.points) {
    bool known = false;
    for (const auto& st : pb.known) known = known || (p.s == st.first && p.t == st.second);
    if (!known && D == 2) check_extra<D>(pb.curve_1, pb.curve_2, p);
    if (!known && D == 3) {  // exact: s and t rational here or checked numerically
      p.s.refine_to_width(Rational(1, 1000000) * Rational(1, 1000000) * Rational(1, 1000000));
      p.t.refine_to_width(Rational(1, 1000000) * Rational(1, 1000000) * Rational(1, 1000000));
      const auto x = pb.curve_1.evaluate(CGAL::to_double(p.s.lower())), y = pb.curve_2.evaluate(CGAL::to_double(p.t.lower()));
      for (int c = 0; c < D; ++c) CHECK(std::abs(x[c] - y[c]) < 1e-9 * (1 + std::abs(x[c])));
    }
  }
  for (auto m : all_methods) require_same<D>(r, intersect_curves(pb.curve_1, pb.curve_2, m));
  return int(r.points.size());
}

} // namespace

TEST_CASE("generated planar problems: every known intersection exactly, extras proved, strategies agree",
          "[curve_intersection][generated]") {
  int problems = 0;
  unsigned long seed = 1;
  for (int n1 = 2; n1 <= 4; ++n1)
    for (int n2 = 2; n2 <= 4; ++n2)
      for (int k = 0; k <= std::min(4, n2 + 1); ++k)
        for (int rat = 0; rat <= 1; ++rat)
          for (int rep = 0; rep < 2; ++rep, ++problems) run_generated<2>(n1, n2, k, rat == 1, seed++);
  for (int n2 = 5; n2 <= 6; ++n2)
    for (int k = 0; k <= 4; ++k) run_generated<2>(2, n2, k, true, seed++), ++problems;
  CHECK(problems >= 170);
}

TEST_CASE("generated space problems (du-1989 §4.2 protocol, degrees 3-2..3-6)", "[curve_intersection][generated]") {
  int problems = 0;
  unsigned long seed = 1000;
  for (int n2 = 2; n2 <= 6; ++n2)
    for (int k = 0; k <= std::min(4, n2 + 1); ++k)
      for (int rat = 0; rat <= 1; ++rat)
        for (int rep = 0; rep < 2; ++rep, ++problems) run_generated<3>(3, n2, k, rat == 1, seed++);
  CHECK(problems >= 90);
}

// du-1989 §4.2 at scale: every combination of dimension, degrees 2..6 on both sides, 0..4 constructed
// intersections (as many as the generator allows), rational and polynomial, with fresh seeds. Each problem: every
// constructed intersection found exactly; every other reported point is a common root of CGAL's own resultants
// Res_t(F1,F2), Res_s(F1,F2) (computed once per problem) whose points agree to 1e-9; every 16th problem is also
// solved by the subresultant strategy, which must return the same exact answer.
template <int D>
void run_generated_at_scale(int n1, int n2, int k, bool rational, unsigned long seed, bool compare) {
  const Curve_problem<D> pb = make_problem<D>(n1, n2, k, rational, seed);
  INFO("D=" << D << " n1=" << n1 << " n2=" << n2 << " k=" << k << " rational=" << rational << " seed=" << seed);
  const Curve_intersection_result r = intersect_curves(pb.curve_1, pb.curve_2);
  CHECK(r.overlaps.empty());
  std::size_t known_found = 0;
  std::vector<const Curve_intersection_point*> extra;
  for (const auto& p : r.points) {
    bool known = false;
    for (const auto& st : pb.known) known = known || (p.s == st.first && p.t == st.second);
    if (known)
      ++known_found;
    else
      extra.push_back(&p);
  }
  CHECK(known_found == pb.known.size());
  if (!extra.empty()) {
    const auto H1 = internal::integer_power_form(pb.curve_1), H2 = internal::integer_power_form(pb.curve_2);
    const auto F1 = internal::cross_term(H1[1], H2[0], H2[1], H1[0]), F2 = internal::cross_term(H1[2], H2[0], H2[2], H1[0]);
    const auto R = CGAL::resultant(F1, F2);
    const auto T = CGAL::resultant(internal::swap_variables(F1), internal::swap_variables(F2));
    for (const auto* p : extra) {
      if (!CGAL::is_zero(R)) CHECK(p->s.sign_of(R) == 0);
      if (!CGAL::is_zero(T)) CHECK(p->t.sign_of(T) == 0);
      p->s.refine_to_width(Rational(1, 1000000) * Rational(1, 1000000) * Rational(1, 1000000));
      p->t.refine_to_width(Rational(1, 1000000) * Rational(1, 1000000) * Rational(1, 1000000));
      const auto x = pb.curve_1.evaluate(CGAL::to_double(p->s.lower()));
      const auto y = pb.curve_2.evaluate(CGAL::to_double(p->t.lower()));
      for (int c = 0; c < D; ++c) CHECK(std::abs(x[c] - y[c]) < 1e-9 * (1 + std::abs(x[c])));
    }
  }
  if (compare) require_same<D>(r, intersect_curves(pb.curve_1, pb.curve_2, Curve_intersection_method::subresultant));
}

TEST_CASE("thousands of generated problems, 2D and 3D, degrees 2-6, rational and polynomial",
          "[curve_intersection][generated][scale]") {
  int problems = 0;
  unsigned long seed = 50000;
  for (int rep = 0; rep < BEZOUTIAN_GENERATED_REPETITIONS; ++rep)
    for (int n1 = 2; n1 <= 6; ++n1)
      for (int n2 = 2; n2 <= 6; ++n2)
        for (int k = 0; k <= std::min(4, std::min(n1, n2) + 1); ++k)
          for (int rat = 0; rat <= 1; ++rat) {
            run_generated_at_scale<2>(n1, n2, k, rat == 1, seed, problems % 16 == 0);
            ++problems;
            run_generated_at_scale<3>(n1, n2, k, rat == 1, seed + 1, problems % 16 == 1);
            ++problems;
            seed += 2;
          }
  CHECK(problems == 464 * BEZOUTIAN_GENERATED_REPETITIONS);  // 2320 problems by default
}

// du-1989's third method: the eliminant from a reduced lexicographic Groebner basis (multi-modular, certified over
// Q; degrees up to 6 in test/core/groebner_modular_test.cpp). Here: identical exact answers, multiplicities and kinds
// on small problems, tangencies, and an identity: the eliminant of (t - s^2, t^2 + s^2 - 2) is s^4 + s^2 - 2.
TEST_CASE("groebner strategy: the lex basis eliminant, and identical answers on small problems",
          "[curve_intersection][groebner]") {
  using P2 = Polynomial_2<Integer>;
  const P2 s = CGAL::shift(P2(1), 1, 0), t = CGAL::shift(P2(1), 1, 1);
  const auto g = groebner_eliminant(std::vector<P2>{t - s * s, t * t + s * s - 2});
  const std::vector<Rational> want{Rational(-2), Rational(0), Rational(1), Rational(0), Rational(1)};
  CHECK(g == Polynomial_1<Rational>(want.begin(), want.end()));
  // two circles through (1,0) and (0,1) meet in exactly those points: the elimination ideal is squarefree of degree 2
  const auto h = groebner_eliminant(std::vector<P2>{s * s + t * t - 1, (s - 1) * (s - 1) + (t - 1) * (t - 1) - 1});
  CHECK(h.degree() == 2);
  CHECK(h.evaluate(Rational(0)) == 0);
  CHECK(h.evaluate(Rational(1)) == 0);
  unsigned long seed = 9000;
  for (int n1 = 2; n1 <= 3; ++n1)
    for (int n2 = 2; n2 <= 3 - (n1 == 3); ++n2)
      for (int k = 0; k <= 3; ++k)
        for (int rat = 0; rat <= 1; ++rat) {
          const auto pb = make_problem<2>(n1, n2, k, rat == 1, seed);
          INFO("n1=" << n1 << " n2=" << n2 << " k=" << k << " rational=" << rat);
          require_same<2>(intersect_curves(pb.curve_1, pb.curve_2),
                          intersect_curves(pb.curve_1, pb.curve_2, Curve_intersection_method::groebner));
          const auto sp = make_problem<3>(3, n2, k, rat == 1, seed++);
          require_same<3>(intersect_curves(sp.curve_1, sp.curve_2),
                          intersect_curves(sp.curve_1, sp.curve_2, Curve_intersection_method::groebner));
        }
  // tangency of multiplicity 2 (parabola / axis) and 3 (inflection), as with the other strategies
  const Curve2 parabola = power_curve({-1, 2}, {1, -4, 4}), axis = power_curve({-1, 2}, {0});
  const Curve2 cubic = power_curve({-1, 2}, {-1, 6, -12, 8});
  require_same<2>(intersect_curves(parabola, axis), intersect_curves(parabola, axis, Curve_intersection_method::groebner));
  require_same<2>(intersect_curves(cubic, axis), intersect_curves(cubic, axis, Curve_intersection_method::groebner));
  CHECK(curve_intersection_method_from_string("groebner") == Curve_intersection_method::groebner);
}

TEST_CASE("tangencies of multiplicity 2 and 3", "[curve_intersection]") {
  // parabola (2s-1, (2s-1)^2) and the x axis (2t-1, 0): tangent at the origin, s = t = 1/2
  const Curve2 parabola = power_curve({-1, 2}, {1, -4, 4});
  const Curve2 axis = power_curve({-1, 2}, {0});
  auto r = intersect_curves(parabola, axis);
  REQUIRE(r.points.size() == 1);
  CHECK(r.points[0].s == Rational(1, 2));
  CHECK(r.points[0].t == Rational(1, 2));
  CHECK(r.points[0].tangent);
  CHECK(r.points[0].kind == Curve_intersection_kind::tangent);
  CHECK(r.points[0].multiplicity == 2);
  // cubic (2s-1, (2s-1)^3): inflectional tangency with the axis, multiplicity 3
  const Curve2 cubic = power_curve({-1, 2}, {-1, 6, -12, 8});
  r = intersect_curves(cubic, axis);
  REQUIRE(r.points.size() == 1);
  CHECK(r.points[0].multiplicity == 3);
  CHECK(r.points[0].kind == Curve_intersection_kind::tangent);
  // parabola y = x^2 and its tangent y = 2x - 1 at x = 1 (x = 3s - 1: s = 2/3; x = 2t: t = 1/2)
  const Curve2 p2 = power_curve({-1, 3}, {1, -6, 9});       // x = 3s - 1, y = x^2
  const Curve2 line = power_curve({0, 2}, {-1, 4});          // x = 2t, y = 2x - 1
  r = intersect_curves(p2, line);
  REQUIRE(r.points.size() == 1);
  CHECK(r.points[0].s == Rational(2, 3));
  CHECK(r.points[0].t == Rational(1, 2));
  CHECK(r.points[0].multiplicity == 2);
  // transversal crossings at irrational parameters: y = x^2 and y = 1/2: x = +-1/sqrt 2
  const Curve2 half = power_curve({-1, 2}, {Rational(1, 2)});
  r = intersect_curves(parabola, half);
  REQUIRE(r.points.size() == 2);
  for (const auto& p : r.points) {
    CHECK(!p.s.is_rational());
    CHECK(p.s == p.t);  // same x parametrization
    CHECK(p.kind == Curve_intersection_kind::transversal);
    CHECK(p.s.sign_of(Polynomial_1<Integer>(Integer(1), Integer(-8), Integer(8))) == 0);  // (2s-1)^2 = 1/2
  }
  for (auto m : all_methods) require_same<2>(r, intersect_curves(parabola, half, m));
}

TEST_CASE("a node shared by both curves: tangency and multiplicity of each pair of branches", "[curve_intersection]") {
  // Every pair lies on a line s = s_i and a line t = t_j holding two intersections each, so neither elimination
  // decides it (the sheared system does).
  // (a) lyon-loops-nested: two cubic loops from the origin, C1 = 10 C2, control points of C2 (0,0), (-1,1), (1,1),
  // (0,0). At s = t = 0: C2'(0) = 3(-1,1), C2''(0) = 6(3,-1), cross product -2*18 != 0, so both branches are
  // tangent with curvatures k and k/10 != k: contact order 1, intersection multiplicity 2. Likewise at s = t = 1
  // (C2'(1) = 3(-1,-1), C2''(1) = 6(-3,-1)). The pairs (0,1), (1,0) join transversal branches: multiplicity 1.
  const Curve2 c2(std::vector<Curve2::Point>{{0, 0}, {-1, 1}, {1, 1}, {0, 0}});
  const Curve2 c1(std::vector<Curve2::Point>{{0, 0}, {-10, 10}, {10, 10}, {0, 0}});
  for (auto m : all_methods) {
    const auto r = intersect_curves(c1, c2, m);
    REQUIRE(r.points.size() == 4);
    for (const auto& p : r.points) {
      INFO(int(m) << ": " << p.s.to_double() << " " << p.t.to_double());
      const bool same_end = p.s == p.t;
      CHECK(p.tangent == same_end);
      CHECK(p.multiplicity == (same_end ? 2 : 1));
      CHECK(p.kind == Curve_intersection_kind::endpoint);
    }
  }
  // (b) The same at irrational parameters: A(x) = (x^2 - 1/2, x (x^2 - 1/2)), x = 2s - 1, has a node at the origin
  // at x = +-1/sqrt 2 (branch directions (+-sqrt 2, 1)), and B = 2 A. y^2 = x^2 (x + 1/2) and y^2 = x^2 (x/2 + 1/2)
  // meet only at the origin. A's branch at x and B's branch at the same x are tangent (a homothety keeps
  // directions) with curvatures in the ratio 2 (A' x A'' = 6 x^2 + 1 = 4 != 0): multiplicity 2; the other pairs
  // are transversal. So 4 pairs, s = t for the two tangencies, s + t = 1 for the two crossings.
  const Curve2 a = power_curve({Rational(1, 2), -4, 4}, {Rational(-1, 2), 5, -12, 8});
  const Curve2 b = power_curve({1, -8, 8}, {-1, 10, -24, 16});
  const Polynomial_1<Integer> node(Integer(1), Integer(-8), Integer(8));  // (2s-1)^2 = 1/2
  for (auto m : all_methods) {
    const auto r = intersect_curves(a, b, m);
    REQUIRE(r.points.size() == 4);
    int tangencies = 0;
    for (const auto& p : r.points) {
      CHECK(p.s.sign_of(node) == 0);
      CHECK(p.t.sign_of(node) == 0);
      const bool same = p.s == p.t;
      tangencies += same;
      CHECK(p.tangent == same);
      CHECK(p.multiplicity == (same ? 2 : 1));
      CHECK(p.kind == (same ? Curve_intersection_kind::tangent : Curve_intersection_kind::transversal));
    }
    CHECK(tangencies == 2);
  }
}

TEST_CASE("endpoints, overlaps, identical and degenerate curves", "[curve_intersection]") {
  const Curve2 a(std::vector<Curve2::Point>{{0, 0}, {Rational(1, 2), 1}, {1, 0}});
  // segments meeting at an end
  const Curve2 s1(std::vector<Curve2::Point>{{0, 0}, {1, 1}}), s2(std::vector<Curve2::Point>{{1, 1}, {2, 0}});
  auto r = intersect_curves(s1, s2);
  REQUIRE(r.points.size() == 1);
  CHECK(r.points[0].s == 1);
  CHECK(r.points[0].t == 0);
  CHECK(r.points[0].kind == Curve_intersection_kind::endpoint);
  // identical curves: one overlap [0,1] x [0,1]; reversed: t runs backwards
  r = intersect_curves(a, a);
  REQUIRE(r.overlaps.size() == 1);
  CHECK(r.points.empty());
  CHECK((r.overlaps[0].s0 == 0 && r.overlaps[0].s1 == 1 && r.overlaps[0].t0 == 0 && r.overlaps[0].t1 == 1));
  r = intersect_curves(a, a.reversed());
  REQUIRE(r.overlaps.size() == 1);
  CHECK((r.overlaps[0].s0 == 0 && r.overlaps[0].s1 == 1 && r.overlaps[0].t0 == 1 && r.overlaps[0].t1 == 0));
  // partial overlap: a on [1/4, 2] reparametrized: a([1/4,1]) == b([0, 3/7])
  r = intersect_curves(a, a.restriction(Rational(1, 4), Rational(2)));
  REQUIRE(r.overlaps.size() == 1);
  CHECK((r.overlaps[0].s0 == Rational(1, 4) && r.overlaps[0].s1 == 1 && r.overlaps[0].t0 == 0 &&
         r.overlaps[0].t1 == Rational(3, 7)));
  // touching pieces of one parabola: a([0,1/2]) and a([1/2,1]) share only the apex
  r = intersect_curves(a.restriction(0, Rational(1, 2)), a.restriction(Rational(1, 2), 1));
  CHECK(r.overlaps.empty());
  REQUIRE(r.points.size() == 1);
  CHECK((r.points[0].s == 1 && r.points[0].t == 0));
  // degenerate (constant) curves
  const Curve2 dot(std::vector<Curve2::Point>{{Rational(1, 2), Rational(1, 2)}, {Rational(1, 2), Rational(1, 2)}});
  r = intersect_curves(dot, a);  // (1/2,1/2) = a(1/2)
  REQUIRE(r.overlaps.size() == 1);
  CHECK((r.overlaps[0].t0 == Rational(1, 2) && r.overlaps[0].t1 == Rational(1, 2)));
  const Curve2 off(std::vector<Curve2::Point>{{0, 1}, {0, 1}, {0, 1}});
  r = intersect_curves(a, off);
  CHECK(r.overlaps.empty());
  CHECK(r.points.empty());
  r = intersect_curves(dot, dot);
  CHECK(r.overlaps.size() == 1);
  // a rational curve with a pole is rejected
  const Curve2 pole = Curve2::from_homogeneous({{1, 0, 0}, {-3, 0, 0}, {1, 1, 1}});
  CHECK_THROWS_AS(intersect_curves(pole, a), Invalid_input);
  CHECK_THROWS_AS(curve_intersection_method_from_string("lagrange"), Invalid_input);
}

TEST_CASE("space curves: overlap, endpoint, no intersection", "[curve_intersection]") {
  const Curve3 c(std::vector<Curve3::Point>{{0, 0, 0}, {1, 2, 1}, {2, 0, 3}, {3, 1, 0}});
  auto r = intersect_curves(c, c.restriction(Rational(1, 3), Rational(2, 3)));
  REQUIRE(r.overlaps.size() == 1);
  CHECK((r.overlaps[0].s0 == Rational(1, 3) && r.overlaps[0].s1 == Rational(2, 3)));
  const Curve3 seg(std::vector<Curve3::Point>{{3, 1, 0}, {5, 5, 5}});
  r = intersect_curves(c, seg);
  REQUIRE(r.points.size() == 1);
  CHECK((r.points[0].s == 1 && r.points[0].t == 0));
  const Curve3 far(std::vector<Curve3::Point>{{10, 0, 0}, {11, 1, 1}});
  CHECK(intersect_curves(c, far).points.empty());
}

TEST_CASE("self-intersections (loops) of a planar curve", "[curve_intersection][self]") {
  // x(u) = u^2 - 1, y(u) = u^3 - u with u = 4s - 2: node at s = 1/4 (u = -1) and s = 3/4 (u = 1)
  Polynomial_1<Rational> u(Rational(-2), Rational(4));
  Curve2::Power_form f;
  f[0] = Polynomial_1<Rational>(Rational(1));
  f[1] = u * u - Polynomial_1<Rational>(Rational(1));
  f[2] = u * u * u - u;
  const Curve2 nodal = Curve2::from_power_form(f);
  auto r = self_intersections(nodal);
  REQUIRE(r.points.size() == 1);
  CHECK(r.points[0].s == Rational(1, 4));
  CHECK(r.points[0].t == Rational(3, 4));
  // a parabola has no loop; the planar nodal cubic lifted to z = s (a twisted cubic) has none either
  CHECK(self_intersections(Curve2(std::vector<Curve2::Point>{{0, 0}, {1, 1}, {2, 0}})).points.empty());
  Curve3::Power_form g;
  g[0] = f[0];
  g[1] = f[1];
  g[2] = f[2];
  g[3] = Polynomial_1<Rational>(Rational(0), Rational(1));
  CHECK(self_intersections(Curve3::from_power_form(g)).points.empty());
}

TEST_CASE("functor form", "[curve_intersection]") {
  const Curve2 a(std::vector<Curve2::Point>{{0, 0}, {1, 1}}), b(std::vector<Curve2::Point>{{0, 1}, {1, 0}});
  Intersect_curves f;
  f.method = Curve_intersection_method::projection;
  const auto r = f(a, b);
  REQUIRE(r.points.size() == 1);
  CHECK((r.points[0].s == Rational(1, 2) && r.points[0].t == Rational(1, 2)));
  CHECK(std::string(to_string(r.points[0].kind)) == "transversal");
}
