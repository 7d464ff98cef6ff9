// The space path of intersect_curves (default method, D = 3): the interval localisation (space_interval_solver.h)
// and the modular shape basis with its exact verification (space_shape_basis.h), checked against the generator's
// constructed intersections, CGAL's own resultants and gcd, and the exact strategies; near misses, irrational
// common points, two partners for one parameter (no shape basis: exact fallback), a tangency.
#include <catch2/catch.hpp>

#include "intersection_checks.h"

#include <bezoutian/intersection/Curve_intersection.h>
#include <bezoutian/geometry/Curve_problem_generator.h>
#include <bezoutian/io/Json_format.h>

using namespace bezoutian;
using Curve2 = Rational_bezier_curve_2<>;
using Curve3 = Rational_bezier_curve_3<>;
using P1 = Polynomial_1<Integer>;
using P2 = Polynomial_2<Integer>;

namespace {

Curve_problem<3> space_problem(int n2, int k, bool rational, unsigned long seed) {
  Curve_problem_parameters par;
  par.degree_1 = 3;
  par.degree_2 = n2;
  par.intersections = k;
  par.rational = rational;
  par.range = 16;
  par.seed = seed;
  return generate_curve_problem<3>(par);
}

Rational eval(const std::vector<Rational>& f, const Rational& x) {
  Rational r(0);
  for (std::size_t i = f.size(); i-- > 0;) r = r * x + f[i];
  return r;
}

using bezoutian_test::require_same;

// The exact default path (interval paths off) and the subresultant strategy as references.
void require_same_as_exact(const Curve3& a, const Curve3& b) {
  const auto r = intersect_curves(a, b);
  require_same(r, internal::Curve_intersection_engine<3>(a, b, Curve_intersection_method::default_method, false).run());
  require_same(r, intersect_curves(a, b, Curve_intersection_method::subresultant));
}

Curve3 from_power(const std::vector<Rational>& x, const std::vector<Rational>& y, const std::vector<Rational>& z) {
  Curve3::Power_form f;
  f[0] = Polynomial_1<Rational>(Rational(1));
  f[1] = Polynomial_1<Rational>(x.begin(), x.end());
  f[2] = Polynomial_1<Rational>(y.begin(), y.end());
  f[3] = Polynomial_1<Rational>(z.begin(), z.end());
  return Curve3::from_power_form(f);
}

}  // namespace

TEST_CASE("space shape basis: the constructed intersections, a divisor of CGAL's resultant gcd",
          "[curve_intersection][space]") {
  int checked = 0;
  for (int n2 = 2; n2 <= 6; ++n2)
    for (int k = 1; k <= std::min(4, n2 + 1); ++k)
      for (int rat = 0; rat <= 1; ++rat) {
        const auto pb = space_problem(n2, k, rat == 1, 7000 + 100 * n2 + 10 * k + rat);
        INFO("n2=" << n2 << " k=" << k << " rational=" << rat);
        const auto A = internal::integer_power_form(pb.curve_1), B = internal::integer_power_form(pb.curve_2);
        internal::Space_shape_basis sb;
        REQUIRE(internal::space_shape_basis(A, B, sb));
        // random space curves have no common point besides the k constructed ones
        CHECK(int(sb.g.size()) - 1 == k);
        for (const auto& st : pb.known) {
          CHECK(eval(sb.g, st.first) == 0);
          CHECK(eval(sb.psi, st.first) == st.second);
        }
        // g divides gcd(Res_t(F1,F2), Res_t(F1,F3)) (CGAL's resultant and gcd over Q)
        const P2 F1 = internal::cross_term(A[1], B[0], B[1], A[0]), F2 = internal::cross_term(A[2], B[0], B[2], A[0]),
                 F3 = internal::cross_term(A[3], B[0], B[3], A[0]);
        const P1 G = CGAL::gcd(CGAL::resultant(F1, F2), CGAL::resultant(F1, F3));
        const P1 g = internal::integer_multiple(Polynomial_1<Rational>(sb.g.begin(), sb.g.end()));
        P1 q, r;
        Integer d;
        P1::pseudo_division(G, g, q, r, d);
        CHECK(CGAL::is_zero(r));
        // and without the factors W1^j (common zeros at infinity) it is g itself: no other common root
        CHECK(internal::divide_out(G, A[0]).degree() == g.degree());
        ++checked;
      }
  CHECK(checked == 38);
}

TEST_CASE("space shape basis verification rejects wrong candidates", "[curve_intersection][space]") {
  const auto pb = space_problem(4, 3, true, 4242);
  const auto A = internal::integer_power_form(pb.curve_1), B = internal::integer_power_form(pb.curve_2);
  internal::Space_shape_basis sb;
  REQUIRE(internal::space_shape_basis(A, B, sb));
  CHECK(internal::space_shape::verify(A, B, sb.g, sb.psi));
  auto psi = sb.psi;
  psi[0] += Rational(1, 1000);
  CHECK_FALSE(internal::space_shape::verify(A, B, sb.g, psi));
  auto g = sb.g;
  g[0] += Rational(1, 7);
  CHECK_FALSE(internal::space_shape::verify(A, B, g, sb.psi));
  // the true basis of a sub-system is not one of the whole system: drop the last known point from g
  const Polynomial_1<Rational> full(sb.g.begin(), sb.g.end());
  const Polynomial_1<Rational> part = CGAL::integral_division(
      full, Polynomial_1<Rational>(-pb.known.back().first, Rational(1)));
  std::vector<Rational> gp(part.begin(), part.end()), pp = sb.psi;
  // psi modulo the divisor (its values at the remaining roots are unchanged)
  Polynomial_1<Rational> pq, pr;
  Polynomial_1<Rational>::euclidean_division(Polynomial_1<Rational>(pp.begin(), pp.end()), part, pq, pr);
  pp.assign(pr.begin(), pr.end());
  while (!pp.empty() && CGAL::is_zero(pp.back())) pp.pop_back();
  CHECK(internal::space_shape::verify(A, B, gp, pp));  // a factor of a shape basis is one too
  CHECK_FALSE(internal::space_shape::verify(A, B, gp, sb.psi.size() > 1 ? std::vector<Rational>{sb.psi[1]} : pp));
  // the roles exchanged: the basis in t maps every t_j back to s_j
  internal::Space_shape_basis sw;
  REQUIRE(internal::space_shape_basis(B, A, sw));
  for (const auto& st : pb.known) {
    CHECK(eval(sw.g, st.second) == 0);
    CHECK(eval(sw.psi, st.second) == st.first);
  }
}

TEST_CASE("space interval solver: the boxes cover the constructed intersections", "[curve_intersection][space]") {
  int boxes = 0;
  for (int n2 = 2; n2 <= 6; ++n2)
    for (int k = 0; k <= std::min(4, n2 + 1); ++k)
      for (int rat = 0; rat <= 1; ++rat) {
        const auto pb = space_problem(n2, k, rat == 1, 9000 + 100 * n2 + 10 * k + rat);
        INFO("n2=" << n2 << " k=" << k << " rational=" << rat);
        const auto A = internal::integer_power_form(pb.curve_1), B = internal::integer_power_form(pb.curve_2);
        const auto ia = internal::space_interval_curve(pb.curve_1, A), ib = internal::space_interval_curve(pb.curve_2, B);
        internal::Space_interval_solver solver{ia, ib, {}};
        solver.run(ia.inet, 0, 1, ib.inet, 0, 1, 0);
        REQUIRE_FALSE(solver.failed);
        for (const auto& st : pb.known) {
          bool covered = false;
          for (const auto& b : solver.found)
            covered = covered || (Rational(b.s_lo) <= st.first && st.first <= Rational(b.s_hi) &&
                                  Rational(b.t_lo) <= st.second && st.second <= Rational(b.t_hi));
          CHECK(covered);
        }
        for (const auto& b : solver.found) {
          CHECK((1 <= b.a && b.a < b.b && b.b <= 3));
          CHECK((b.s_lo <= b.s_hi && b.t_lo <= b.t_hi));
          CHECK(b.s_hi - b.s_lo < 1e-6);  // contracted by Krawczyk
        }
        if (k == 0) CHECK(solver.found.empty());  // nothing to decide exactly
        boxes += int(solver.found.size());
      }
  CHECK(boxes >= 90);
}

TEST_CASE("space curves crossing in projection but not in space (near misses)", "[curve_intersection][space]") {
  // a cubic on the plane z = x and a conic on the plane z = x + eps whose (x, y) projections cross: their control
  // boxes overlap, the crossing is missed by eps in z
  auto pair = [](const Rational& eps) {
    const Curve3 a(std::vector<Curve3::Point>{{0, 0, 0}, {1, 2, 1}, {2, -1, 2}, {3, 1, 3}});
    const Curve3 b(std::vector<Curve3::Point>{{0, 1, eps}, {Rational(3, 2), -1, Rational(3, 2) + eps},
                                              {3, Rational(1, 2), 3 + eps}},
                   std::vector<Rational>{1, 2, 1});
    return std::make_pair(a, b);
  };
  Integer big(1);
  mpz_mul_2exp(big.mpz(), big.mpz(), 80);
  const auto planar = [&](const Curve3& c) {
    std::vector<Curve2::Point> p;
    for (std::size_t i = 0; i < c.number_of_control_points(); ++i) p.push_back({c.control_point(i)[0], c.control_point(i)[1]});
    return Curve2(p, c.weights());
  };
  const auto meet = pair(Rational(0));
  const auto r0 = intersect_curves(meet.first, meet.second);
  const auto r2 = intersect_curves(planar(meet.first), planar(meet.second));
  REQUIRE(r2.points.size() >= 1);
  REQUIRE(r0.points.size() == r2.points.size());  // at height 0: exactly the crossings of the projections
  for (std::size_t i = 0; i < r0.points.size(); ++i) {
    CHECK(r0.points[i].s == r2.points[i].s);
    CHECK(r0.points[i].t == r2.points[i].t);
  }
  require_same_as_exact(meet.first, meet.second);
  for (const Rational eps : {Rational(1, 1 << 30), Rational(1) / Rational(big), -Rational(1) / Rational(big)}) {
    const auto miss = pair(eps);
    CHECK(intersect_curves(miss.first, miss.second).points.empty());
    CHECK(intersect_curves(miss.first, miss.second, Curve_intersection_method::subresultant).points.empty());
  }
}

TEST_CASE("irrational common points of space curves", "[curve_intersection][space]") {
  // the segment (s, 0, 0) and C(t) = (t, (2t-1)^2 - 1/2, (2t-1)^2 - 1/2) meet where 8 s^2 - 8 s + 1 = 0, t = s
  const Curve3 seg(std::vector<Curve3::Point>{{0, 0, 0}, {1, 0, 0}});
  const Curve3 par = from_power({0, 1}, {Rational(1, 2), -4, 4}, {Rational(1, 2), -4, 4});
  const auto r = intersect_curves(seg, par);
  REQUIRE(r.points.size() == 2);
  const P1 m(Integer(1), Integer(-8), Integer(8));
  for (const auto& p : r.points) {
    CHECK_FALSE(p.s.is_rational());
    CHECK(p.s.sign_of(m) == 0);
    CHECK(p.s == p.t);
    CHECK(p.kind == Curve_intersection_kind::transversal);
  }
  CHECK(r.points[0].s < r.points[1].s);
  require_same_as_exact(seg, par);
  // rational weights on both: t = s does not hold, the exact strategies agree
  const Curve3 rseg(std::vector<Curve3::Point>{{0, 0, 0}, {1, 0, 0}}, std::vector<Rational>{1, 3});
  const Curve3 rpar = Curve3::from_homogeneous({{1, Rational(0), Rational(1, 2), Rational(1, 2)},
                                                 {2, Rational(1), Rational(-3), Rational(-3)},
                                                 {3, Rational(3), Rational(3, 2), Rational(3, 2)}});
  const auto rr = intersect_curves(rseg, rpar);
  CHECK(rr.points.size() == 2);
  for (const auto& p : rr.points) CHECK_FALSE(p.s.is_rational());
  require_same_as_exact(rseg, rpar);
}

TEST_CASE("two partners for one parameter (no shape basis in s) and a tangency in space",
          "[curve_intersection][space]") {
  // plane nodal cubic x = u^2 - 1, y = u^3 - u, z = 0, u = 4t - 2: node at the origin for t = 1/4 and 3/4;
  // the segment from (-1,-1,-1) to (1,1,1) passes through it at s = 1/2 (and meets z = 0 nowhere else)
  const Polynomial_1<Rational> u(Rational(-2), Rational(4));
  const Polynomial_1<Rational> x = u * u - Polynomial_1<Rational>(Rational(1)), y = u * u * u - u;
  const Curve3 nodal = from_power(std::vector<Rational>(x.begin(), x.end()), std::vector<Rational>(y.begin(), y.end()), {0});
  const Curve3 seg(std::vector<Curve3::Point>{{-1, -1, -1}, {1, 1, 1}});
  const auto A = internal::integer_power_form(seg), B = internal::integer_power_form(nodal);
  internal::Space_shape_basis sb;
  CHECK_FALSE(internal::space_shape_basis(A, B, sb));  // s = 1/2 has two partners t
  const auto r = intersect_curves(seg, nodal);
  REQUIRE(r.points.size() == 2);
  CHECK((r.points[0].s == Rational(1, 2) && r.points[0].t == Rational(1, 4)));
  CHECK((r.points[1].s == Rational(1, 2) && r.points[1].t == Rational(3, 4)));
  require_same_as_exact(seg, nodal);
  // roles exchanged: a shape basis in t exists (two roots, one partner 1/2)
  REQUIRE(internal::space_shape_basis(B, A, sb));
  CHECK(sb.g.size() == 3);
  const auto rs = intersect_curves(nodal, seg);
  REQUIRE(rs.points.size() == 2);
  CHECK((rs.points[0].s == Rational(1, 4) && rs.points[0].t == Rational(1, 2)));
  CHECK((rs.points[1].s == Rational(3, 4) && rs.points[1].t == Rational(1, 2)));
  require_same_as_exact(nodal, seg);
  // tangency: (s, (2s-1)^2, s^2) touches the segment (t, 0, t - 1/4) at s = t = 1/2 (tangents (1, 0, 1))
  const Curve3 para = from_power({0, 1}, {1, -4, 4}, {0, 0, 1});
  const Curve3 line = from_power({0, 1}, {0}, {Rational(-1, 4), 1});
  const auto rt = intersect_curves(para, line);
  REQUIRE(rt.points.size() == 1);
  CHECK((rt.points[0].s == Rational(1, 2) && rt.points[0].t == Rational(1, 2)));
  CHECK(rt.points[0].kind == Curve_intersection_kind::tangent);
  require_same_as_exact(para, line);
}

TEST_CASE("space curves on a common plane: the planar answer (irrational points)", "[curve_intersection][space]") {
  // random plane curves lifted to the plane z = x + 2y + 1/3 meet exactly where the plane curves meet, mostly at
  // irrational parameters; the planar subresultant strategy is the reference (a different algorithm)
  auto lift = [](const Curve2& c) {
    std::vector<Curve3::Homogeneous_point> net;
    for (const auto& h : c.homogeneous_control_points()) net.push_back({h[0], h[1], h[2], h[1] + 2 * h[2] + h[0] / 3});
    return Curve3::from_homogeneous(net);
  };
  int settled = 0, irrational = 0;
  for (int n = 2; n <= 3; ++n)
    for (int i = 0; i < 6; ++i) {
      Curve_problem_parameters par;
      par.degree_1 = par.degree_2 = n;
      par.intersections = 0;
      par.rational = i % 2 == 1;
      par.range = 16;
      par.seed = 31 + 100 * n + i;
      const auto p = generate_curve_problem<2>(par);
      INFO("n=" << n << " i=" << i);
      const Curve3 a = lift(p.curve_1), b = lift(p.curve_2);
      const auto r2 = intersect_curves(p.curve_1, p.curve_2, Curve_intersection_method::subresultant);
      const auto r3 = intersect_curves(a, b);
      REQUIRE(r3.points.size() == r2.points.size());
      for (std::size_t j = 0; j < r2.points.size(); ++j) {
        CHECK(r3.points[j].s == r2.points[j].s);
        CHECK(r3.points[j].t == r2.points[j].t);
        CHECK(r3.points[j].kind == r2.points[j].kind);
        irrational += !r3.points[j].s.is_rational();
      }
      Curve_intersection_result q;
      settled += internal::Curve_intersection_engine<3>(a, b, Curve_intersection_method::default_method).space_path(q);
    }
  CHECK(irrational >= 5);
  CHECK(settled >= 6);  // shape bases of degree n^2 = 4, 9 (larger ones need too many primes: exact path)
}

TEST_CASE("two circles in perpendicular planes touching at a point: a tangency of multiplicity 2",
          "[space][tangent]") {
  // x = 1, (y, z) = (1 - a^2, 2a)/(1 + a^2) and y = 1, (x, z) = (1 - b^2, 2b)/(1 + b^2), a, b = (2s - 1)/2: both
  // through (1, 1, 0) at s = 1/2 with tangent (0, 0, 1). The projection to (x, y) has a double root in each
  // parameter alone, so its pair of equations degenerates on every shear; the multiplicity is that of the
  // other projections (the curves' own: two circles of equal radius touching, 2).
  const std::string json = R"({"curves": [
    {"basis": "power", "parameter": "s", "degree": 2, "x": "1+(2*s-1)*(2*s-1)/4", "y": "1-(2*s-1)*(2*s-1)/4",
     "z": "2*s-1", "w": "1+(2*s-1)*(2*s-1)/4"},
    {"basis": "power", "parameter": "s", "degree": 2, "x": "1-(2*s-1)*(2*s-1)/4", "y": "1+(2*s-1)*(2*s-1)/4",
     "z": "2*s-1", "w": "1+(2*s-1)*(2*s-1)/4"}]})";
  const auto doc = bezoutian::io::read_json(json, "circles");
  REQUIRE(doc.curves_3.size() == 2);
  const auto r = bezoutian::intersect_curves(doc.curves_3[0], doc.curves_3[1]);
  REQUIRE(r.points.size() == 1);
  CHECK(r.points[0].s == bezoutian::Algebraic_real(bezoutian::Rational(1, 2)));
  CHECK(r.points[0].t == bezoutian::Algebraic_real(bezoutian::Rational(1, 2)));
  CHECK(r.points[0].tangent);
  CHECK(r.points[0].multiplicity == 2);
  CHECK(r.points[0].kind == bezoutian::Curve_intersection_kind::tangent);
}
