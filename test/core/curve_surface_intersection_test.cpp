// Certified curve/patch and segment/patch intersection (du-1989 Problems 2.2a/2.2b). The expected values come
// from outside the code: lines and curves constructed through known patch points P(u0,v0) at rational parameters,
// the quadric z = xy (implicit equation; inverse u = x or u = 2x/(1+x), v = y),
// iso-parameter curves of a patch, and exact evaluation of the reported triples.
#include <bezoutian/intersection/Curve_surface_intersection.h>

#include <catch2/catch.hpp>

#include <random>

using namespace bezoutian;

namespace {

using Q = Rational;
using P3 = std::array<Q, 3>;
using Curve3 = Rational_bezier_curve_3<Q>;
using Patch = Rational_bezier_patch<Q>;

Q rnd(std::mt19937& g, int range, int den) { return Q(int(g() % unsigned(2 * range + 1)) - range, den); }

Patch random_patch(int m, int n, std::mt19937& g, bool rational) {
  std::vector<std::vector<P3>> pts(m + 1, std::vector<P3>(n + 1));
  std::vector<std::vector<Q>> w(m + 1, std::vector<Q>(n + 1, Q(1)));
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j) {
      pts[i][j] = {rnd(g, 10, 7), rnd(g, 10, 5), rnd(g, 10, 3)};
      if (rational) w[i][j] = Q(int(g() % 5) + 1, int(g() % 3) + 1);
    }
  return Patch(pts, w);
}

Curve3 random_curve(int d, std::mt19937& g, bool rational) {
  std::vector<P3> pts;
  std::vector<Q> w;
  for (int i = 0; i <= d; ++i) {
    pts.push_back({rnd(g, 10, 7), rnd(g, 10, 5), rnd(g, 10, 3)});
    w.push_back(rational ? Q(int(g() % 4) + 1) : Q(1));
  }
  return Curve3(pts, w);
}

// The same curve translated so that C(r0) = p (a translation moves the control points of a rational curve).
Curve3 through(const Curve3& c, const Q& r0, const P3& p) {
  const P3 q = c(r0);
  std::vector<P3> pts = c.control_points();
  for (auto& x : pts)
    for (int k = 0; k < 3; ++k) x[k] += p[k] - q[k];
  return Curve3(pts, c.weights());
}

bool has_triple(const Curve_patch_intersection_result& res, const Q& r, const Q& u, const Q& v) {
  for (const auto& p : res.points)
    if (p.r == Algebraic_real(r) && p.u == Algebraic_real(u) && p.v == Algebraic_real(v)) return true;
  return false;
}

// Exact check for rational triples; otherwise |C(r) - Phi(u,v)| < 1e-20 after refining r, u, v to width 1e-40.
void check_residuals(const Curve3& c, const Patch& P, const Curve_patch_intersection_result& res) {
  const Q eps(1, 1000000), tiny = Q(1) / Q(Integer("10000000000000000000000000000000000000000"));
  const Q bound = Q(1) / Q(Integer("100000000000000000000"));
  for (const auto& p : res.points) {
    REQUIRE(p.r >= Algebraic_real(0));
    REQUIRE(p.r <= Algebraic_real(1));
    REQUIRE(p.u >= Algebraic_real(0));
    REQUIRE(p.u <= Algebraic_real(1));
    REQUIRE(p.v >= Algebraic_real(0));
    REQUIRE(p.v <= Algebraic_real(1));
    if (p.r.is_rational() && p.u.is_rational() && p.v.is_rational()) {
      REQUIRE(c(p.r.rational_value()) == P(p.u.rational_value(), p.v.rational_value()));
      continue;
    }
    for (const Algebraic_real* x : {&p.r, &p.u, &p.v}) x->refine_to_width(tiny);
    auto mid = [](const Algebraic_real& x) { return x.is_rational() ? x.rational_value() : (x.lower() + x.upper()) / 2; };
    const P3 a = c(mid(p.r)), b = P(mid(p.u), mid(p.v));
    for (int k = 0; k < 3; ++k) REQUIRE(CGAL::abs(a[k] - b[k]) < bound);
    (void)eps;
  }
}

// The hyperbolic paraboloid z = x y: polynomial bilinear patch (u, v, uv), or the rational bilinear patch with
// x = u / (2 - u) (a Moebius reparametrization: W = 2 - u, X = u, Y = v (2 - u), Z = u v; inverse u = 2x / (1 + x)).
Patch paraboloid_patch(bool rational) {
  if (!rational)
    return Patch(std::vector<std::vector<P3>>{{P3{Q(0), Q(0), Q(0)}, P3{Q(0), Q(1), Q(0)}},
                                              {P3{Q(1), Q(0), Q(0)}, P3{Q(1), Q(1), Q(1)}}});
  using Q2 = Polynomial_2<Q>;
  using Q1 = Polynomial_1<Q>;
  const Q2 U(Q1(Q(0), Q(1))), V(Q1(0), Q1(1));
  Patch::Power_form f{Q2(2) - U, U, V * (Q2(2) - U), U * V};
  return Patch::from_power_form(f, 1, 1);
}

P3 paraboloid_point(const Q& u, const Q& v, bool rational) {
  const Q x = rational ? u / (2 - u) : u;
  return {x, v, x * v};
}

P3 cross(const P3& a, const P3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace

TEST_CASE("segment through known patch points (bilinear ... bicubic, polynomial and rational)", "[curve_surface]") {
  std::mt19937 g(20240501);
  for (int m = 1; m <= 3; ++m)
    for (int n = 1; n <= 3; ++n)
      for (int rational = 0; rational < 2; ++rational) {
        if (m + n > 5 && rational) continue;  // keep the test fast
        const Patch P = random_patch(m, n, g, rational);
        // one point: the segment a + r (b - a) hits P(u0,v0) at r0 = 1/4
        const Q u0(1, 3), v0(2, 5), r0(1, 4);
        const P3 X = P(u0, v0);
        const P3 d{rnd(g, 4, 1), rnd(g, 4, 1), Q(int(g() % 5) + 1)};
        P3 a, b;
        for (int k = 0; k < 3; ++k) {
          a[k] = X[k] - r0 * d[k];
          b[k] = a[k] + d[k];
        }
        const auto res = intersect_segment_patch(a, b, P);
        INFO("bi-degree " << m << "," << n << " rational " << rational);
        CHECK(has_triple(res, r0, u0, v0));
        check_residuals(Curve3(std::vector<P3>{a, b}), P, res);
        // two points: the segment through P(u0,v0) (r = 1/4) and P(u1,v1) (r = 3/4)
        const Q u1(5, 7), v1(1, 6);
        const P3 Y = P(u1, v1);
        P3 a2, b2;
        for (int k = 0; k < 3; ++k) {
          const Q dk = 2 * (Y[k] - X[k]);  // r: 1/4 -> 3/4
          a2[k] = X[k] - dk / 4;
          b2[k] = a2[k] + dk;
        }
        const auto res2 = intersect_segment_patch(a2, b2, P);
        CHECK(has_triple(res2, Q(1, 4), u0, v0));
        CHECK(has_triple(res2, Q(3, 4), u1, v1));
        check_residuals(Curve3(std::vector<P3>{a2, b2}), P, res2);
      }
}

TEST_CASE("random curve through a constructed common point", "[curve_surface]") {
  std::mt19937 g(77);
  struct Case { int d, m, n; bool rc, rp; };
  const Case cases[] = {{2, 1, 1, false, false}, {2, 2, 2, true, false}, {3, 2, 2, false, true},
                        {3, 3, 3, false, false}, {2, 3, 2, true, true},  {3, 2, 3, true, false}};
  for (const Case& cs : cases) {
    const Patch P = random_patch(cs.m, cs.n, g, cs.rp);
    const Q r0(2, 7), u0(3, 5), v0(1, 4);
    const Curve3 C = through(random_curve(cs.d, g, cs.rc), r0, P(u0, v0));
    const auto res = intersect_curve_patch(C, P);
    INFO("curve degree " << cs.d << " patch " << cs.m << "," << cs.n);
    CHECK(has_triple(res, r0, u0, v0));
    check_residuals(C, P, res);
    for (const auto& p : res.points) CHECK(p.multiplicity >= 1);
  }
}

TEST_CASE("segments and the quadric z = xy: counts from the implicit equation", "[curve_surface]") {
  // A segment through two points S(ua,va), S(ub,vb) of the quadric z = xy, not on a ruling, meets it exactly there
  // (degree 2); a point is on the patch iff its parameters are in [0,1]^2.
  std::mt19937 g(5);
  for (int trial = 0; trial < 24; ++trial) {
    const bool rational = trial % 2 == 1;
    const Patch S = paraboloid_patch(rational);
    auto surface_point = [rational](const Q& u, const Q& v) { return paraboloid_point(u, v, rational); };
    const Q ua(int(g() % 9) - 2, 4), va(int(g() % 9) - 2, 4), ub(int(g() % 9) - 2, 5), vb(int(g() % 9) - 2, 5);
    const P3 A = surface_point(ua, va), B = surface_point(ub, vb);
    if (ua == ub || va == vb) continue;  // same point or a ruling of the quadric
    // r = 1/3 at A, r = 2/3 at B
    P3 a, b;
    for (int k = 0; k < 3; ++k) {
      const Q dk = 3 * (B[k] - A[k]);
      a[k] = A[k] - dk / 3;
      b[k] = a[k] + dk;
    }
    const auto res = intersect_segment_patch(a, b, S);
    auto in = [](const Q& x) { return Q(0) <= x && x <= Q(1); };
    std::size_t expected = 0;
    if (in(ua) && in(va)) {
      ++expected;
      CHECK(has_triple(res, Q(1, 3), ua, va));
    }
    if (in(ub) && in(vb)) {
      ++expected;
      CHECK(has_triple(res, Q(2, 3), ub, vb));
    }
    CHECK(res.points.size() == expected);
    CHECK(res.overlaps.empty());
  }
}

TEST_CASE("tangent line to the quadric: multiplicity 2; shifted lines: none or two", "[curve_surface]") {
  const Patch S = paraboloid_patch(true);
  const Q u0(1, 2), v0(1, 3);
  const P3 p = paraboloid_point(u0, v0, true);
  // tangent plane of z = xy at p: normal (y0, x0, -1); a direction in it that is not a ruling
  const P3 nrm{p[1], p[0], Q(-1)};
  const P3 d = cross(nrm, P3{Q(1), Q(2), Q(-1)});
  P3 a, b;
  for (int k = 0; k < 3; ++k) {
    a[k] = p[k] - d[k] / 2;
    b[k] = a[k] + d[k];
  }
  const auto res = intersect_segment_patch(a, b, S);
  REQUIRE(res.points.size() == 1);
  CHECK(res.points[0].r == Algebraic_real(Q(1, 2)));
  CHECK(res.points[0].u == Algebraic_real(u0));
  CHECK(res.points[0].v == Algebraic_real(v0));
  CHECK(res.points[0].multiplicity == 2);
  CHECK(res.points[0].tangent);
  CHECK(res.points[0].kind == Curve_patch_intersection_kind::tangent);
  // along the line z - xy = -t s^2 (t != 0 the slope in the tangent plane): pushed by +-eps in z, the line misses
  // the quadric on one side and crosses it twice (irrational parameters) on the other
  std::size_t counts[2];
  for (int side = 0; side < 2; ++side) {
    P3 a2 = a, b2 = b;
    a2[2] += side == 0 ? Q(1, 1000) : Q(-1, 1000);
    b2[2] += side == 0 ? Q(1, 1000) : Q(-1, 1000);
    const auto r2 = intersect_segment_patch(a2, b2, S);
    counts[side] = r2.points.size();
    check_residuals(Curve3(std::vector<P3>{a2, b2}), S, r2);
    for (const auto& q : r2.points) CHECK(q.kind == Curve_patch_intersection_kind::transversal);
  }
  CHECK(std::min(counts[0], counts[1]) == 0);
  CHECK(std::max(counts[0], counts[1]) == 2);
}

TEST_CASE("a line far from the patch, endpoints and boundary hits", "[curve_surface]") {
  const Patch S = paraboloid_patch(false);
  auto surface_point = [](const Q& u, const Q& v) { return paraboloid_point(u, v, false); };
  // box filter: far away
  CHECK(intersect_segment_patch(P3{Q(5), Q(5), Q(5)}, P3{Q(6), Q(7), Q(5)}, S).points.empty());
  // segment ending exactly on the patch at S(1/2, 1/2): endpoint
  const P3 p = surface_point(Q(1, 2), Q(1, 2));
  const auto res = intersect_segment_patch(P3{Q(0), Q(0), Q(1)}, p, S);
  REQUIRE(res.points.size() == 1);
  CHECK(res.points[0].r == Algebraic_real(1));
  CHECK(res.points[0].kind == Curve_patch_intersection_kind::endpoint);
  // segment from (0,0,1) through S(1, 1/3) (edge u = 1) at r = 1/2: boundary
  const P3 q = surface_point(Q(1), Q(1, 3));
  const auto res2 = intersect_segment_patch(P3{Q(0), Q(0), Q(1)}, P3{2 * q[0], 2 * q[1], 2 * q[2] - 1}, S);
  REQUIRE(res2.points.size() == 1);
  CHECK(res2.points[0].r == Algebraic_real(Q(1, 2)));
  CHECK(res2.points[0].u == Algebraic_real(1));
  CHECK(res2.points[0].kind == Curve_patch_intersection_kind::boundary);
}

TEST_CASE("iso-parameter curves lying in the patch: overlaps", "[curve_surface]") {
  std::mt19937 g(11);
  const Patch P = random_patch(2, 3, g, false);
  const auto f = P.power_form();
  using Q1 = Polynomial_1<Q>;
  // C(r) = P(3r/2 - 1/4, 1/3): inside the patch for r in [1/6, 5/6]
  const Q1 ur(Q(-1, 4), Q(3, 2));
  Curve3::Power_form c;
  for (int k = 0; k < 4; ++k) {
    Q1 acc(0);
    for (int j = f[k].degree(); j >= 0; --j) {
      Q1 coef_j(0);  // f[k][j](ur): polynomial in r
      for (int i = f[k][j].degree(); i >= 0; --i) coef_j = coef_j * ur + Q1(f[k][j][i]);
      acc = acc * Q1(Q(1, 3)) + coef_j;
    }
    c[k] = acc;
  }
  const Curve3 C = Curve3::from_power_form(c);
  const auto res = intersect_curve_patch(C, P);
  REQUIRE(res.overlaps.size() == 1);
  CHECK(res.overlaps[0].r0 == Algebraic_real(Q(1, 6)));
  CHECK(res.overlaps[0].r1 == Algebraic_real(Q(5, 6)));
  CHECK(res.points.empty());
  // the whole iso-curve v = 1/3, u in [0,1]: overlap [0,1]
  Curve3::Power_form c2;
  for (int k = 0; k < 4; ++k) {
    Q1 acc(0);
    for (int j = f[k].degree(); j >= 0; --j) acc = acc * Q1(Q(1, 3)) + f[k][j];
    c2[k] = acc;
  }
  const auto res2 = intersect_curve_patch(Curve3::from_power_form(c2), P);
  REQUIRE(res2.overlaps.size() == 1);
  CHECK(res2.overlaps[0].r0 == Algebraic_real(0));
  CHECK(res2.overlaps[0].r1 == Algebraic_real(1));
}

TEST_CASE("degree-elevated patch and curve give the same triples", "[curve_surface]") {
  std::mt19937 g(8);
  const Patch P = random_patch(2, 1, g, true);
  const Curve3 C = through(random_curve(2, g, false), Q(1, 3), P(Q(1, 2), Q(1, 5)));
  const auto a = intersect_curve_patch(C, P);
  const auto b = intersect_curve_patch(C.elevated(1), P.elevated(1, 2));
  CHECK(has_triple(a, Q(1, 3), Q(1, 2), Q(1, 5)));
  REQUIRE(a.points.size() == b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    CHECK(a.points[i].r == b.points[i].r);
    CHECK(a.points[i].u == b.points[i].u);
    CHECK(a.points[i].v == b.points[i].v);
  }
}

TEST_CASE("bad input: degenerate patch, constant curve, poles", "[curve_surface]") {
  std::mt19937 g(3);
  const Patch flat = random_patch(2, 0, g, false);  // a curve, not a surface
  CHECK_THROWS_AS(intersect_segment_patch(P3{Q(0), Q(0), Q(0)}, P3{Q(1), Q(1), Q(1)}, flat), Invalid_input);
  const Patch S = paraboloid_patch(true);
  // constant curve: overlap [0,1] iff its point is on the patch
  const P3 p = paraboloid_point(Q(1, 5), Q(3, 4), true);
  const auto on = intersect_segment_patch(p, p, S);
  REQUIRE(on.overlaps.size() == 1);
  CHECK(on.points.empty());
  CHECK(intersect_segment_patch(P3{Q(0), Q(0), Q(1)}, P3{Q(0), Q(0), Q(1)}, S).overlaps.empty());
  // a curve with a pole in [0,1] (weights of both signs)
  const Curve3 pole(std::vector<P3>{P3{Q(0), Q(0), Q(0)}, P3{Q(1), Q(0), Q(0)}, P3{Q(1), Q(1), Q(0)}},
                    std::vector<Q>{Q(1), Q(-3), Q(1)});
  CHECK_THROWS_AS(intersect_curve_patch(pole, S), Invalid_input);
}
