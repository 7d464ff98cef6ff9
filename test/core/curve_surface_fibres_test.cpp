// Curve/patch intersection through points with several preimages (folded patches, double covers) and through
// singular points of the surface. Expected values come from outside the code: the folded patch
// Phi = ((s^2 - c)(1 + s/4), v, s (s^2 - c) v), s = 2u - 1, maps s = +-sqrt(c) to the same line (0, v, 0) (a double
// curve); the double cover ((2u-1)^2, v, (2u-1)^2 v) of z = xy; an umbrella (s v', s (1 + v'^2), v'^2) with a singular
// point at the origin; and hand-solved intersection equations.
//
// Why not the plain fold (s^2 - c, v, s (s^2 - c) v) or the Whitney umbrella (s v', s, v'^2): as polynomial patches
// on P^1 x P^1 they have a base point at infinity (all four homogeneous coordinates vanish at (u, v) = (oo, 0),
// resp. (oo, oo)), so their Dixon determinant vanishes identically and the implicit matrix cannot be used (a
// documented limit of intersect_curve_patch, tested at the end). The factor (1 + s/4) and the term s v'^2 remove the
// base points without changing the double curve / the singular point.
#include <bezoutian/intersection/Curve_surface_intersection.h>

#include <catch2/catch.hpp>
#include <random>

using namespace bezoutian;

namespace {

using Q = Rational;
using P3 = std::array<Q, 3>;
using Q1 = Polynomial_1<Q>;
using Q2 = Polynomial_2<Q>;
using Z1 = Polynomial_1<Integer>;
using Patch = Rational_bezier_patch<Q>;

Q1 lin(const Q& a, const Q& b) { return Q1(a, b); }  // a + b t
Q2 in_u(const Q1& f) { return Q2(f); }
Q2 v_times(const Q1& f) { return Q2(Q1(0), f); }

// Phi = ((s^2 - c)(1 + s/4), v, s (s^2 - c) v), s = 2u - 1: Phi(s, v) = Phi(-s, v) on s^2 = c.
Patch folded(const Q& c) {
  const Q1 s = lin(-1, 2), a = s * s - Q1(c);
  return Patch::from_power_form({in_u(Q1(1)), in_u(a * (Q1(1) + s * Q1(Q(1, 4)))), v_times(Q1(1)), v_times(s * a)});
}

// The plain fold (s^2 - c, v, s (s^2 - c) v): base point at (u, v) = (oo, 0).
Patch plain_fold(const Q& c) {
  const Q1 s = lin(-1, 2), a = s * s - Q1(c);
  return Patch::from_power_form({in_u(Q1(1)), in_u(a), v_times(Q1(1)), v_times(s * a)});
}

// The same surface as folded(c) with u = t / (2 - t) (a Moebius reparametrization of [0,1]): with D = 2 - t,
// S = 3t - 2, s = S/D and (Phi0..Phi3) = (D^3, (S^2 - c D^2)(4D + S)/4, v D^3, S (S^2 - c D^2) v): non-unit
// Bernstein weights D^3 > 0, the same image; s = +-sigma at t = (2 + 2 sigma)/(3 + sigma).
Patch folded_rational(const Q& c) {
  const Q1 D = lin(2, -1), S = lin(-2, 3), a = S * S - Q1(c) * D * D, D3 = D * D * D;
  return Patch::from_power_form({in_u(D3), in_u(a * (Q1(4) * D + S) * Q1(Q(1, 4))), v_times(D3), v_times(S * a)});
}

// (s v', s (1 + v'^2), v'^2), s = 2u - 1, v' = 2v - 1: the origin = Phi(1/2, 1/2) has the single preimage s = v' = 0
// (s v' = s (1 + v'^2) = 0), where Phi_v' = (s, 2 s v', 2 v') = 0: a singular point of the surface (a pinch point).
Patch umbrella() {
  const Q1 s = lin(-1, 2);
  // v' = -1 + 2v: s v' = -s + 2 s v; 1 + v'^2 = 2 - 4v + 4v^2; v'^2 = 1 - 4v + 4v^2
  return Patch::from_power_form(
      {in_u(Q1(1)), Q2(-s, Q1(2) * s), Q2(Q1(2) * s, Q1(-4) * s, Q1(4) * s), Q2(Q1(1), Q1(-4), Q1(4))});
}

// ((2u-1)^2, v, (2u-1)^2 v): covers its image (a piece of z = xy) twice.
Patch double_cover() {
  const Q1 s = lin(-1, 2), s2 = s * s;
  return Patch::from_power_form({in_u(Q1(1)), in_u(s2), v_times(Q1(1)), v_times(s2)});
}

Algebraic_real alg(const Z1& f, const Q& lo, const Q& hi) { return Algebraic_real(f, lo, hi); }

bool has(const Curve_patch_intersection_result& res, const Algebraic_real& r, const Algebraic_real& u,
         const Algebraic_real& v) {
  for (const auto& p : res.points)
    if (p.r == r && p.u == u && p.v == v) return true;
  return false;
}

}  // namespace

TEST_CASE("fold, c = 1/4: a segment through the double line has two rational preimages", "[curve_patch][fibres]") {
  const Patch P = folded(Q(1, 4));
  const auto res = intersect_segment_patch({Q(-1), Q(1, 2), Q(1)}, {Q(1), Q(1, 2), Q(-1)}, P);
  REQUIRE(res.points.size() == 2);
  REQUIRE(res.overlaps.empty());
  CHECK(has(res, Q(1, 2), Q(1, 4), Q(1, 2)));
  CHECK(has(res, Q(1, 2), Q(3, 4), Q(1, 2)));
  for (const auto& p : res.points) {
    CHECK(p.multiplicity == 1);  // the segment crosses each sheet transversally
    CHECK(p.kind == Curve_patch_intersection_kind::transversal);
    CHECK(!p.tangent);
    CHECK(P(p.u.rational_value(), p.v.rational_value()) == P3{Q(0), Q(1, 2), Q(0)});
  }
}

TEST_CASE("fold, c = 1/2: two irrational preimages u = (1 +- sqrt(1/2))/2", "[curve_patch][fibres]") {
  const Patch P = folded(Q(1, 2));
  const auto res = intersect_segment_patch({Q(-1), Q(1, 2), Q(1)}, {Q(1), Q(1, 2), Q(-1)}, P);
  REQUIRE(res.points.size() == 2);
  const Z1 f(Integer(1), Integer(-8), Integer(8));  // (2u - 1)^2 = 1/2
  CHECK(has(res, Q(1, 2), alg(f, Q(0), Q(1, 2)), Q(1, 2)));
  CHECK(has(res, Q(1, 2), alg(f, Q(1, 2), Q(1)), Q(1, 2)));
  for (const auto& p : res.points) {
    CHECK(p.multiplicity == 1);
    CHECK(p.kind == Curve_patch_intersection_kind::transversal);
    const double u = p.u.to_double();
    CHECK(std::abs(u - (p.u < Algebraic_real(Q(1, 2)) ? (1 - std::sqrt(0.5)) / 2 : (1 + std::sqrt(0.5)) / 2)) < 1e-15);
  }
}

TEST_CASE("rational-weight fold: same image, preimages t = 2/5, 6/7", "[curve_patch][fibres]") {
  const Patch P = folded_rational(Q(1, 4));
  REQUIRE(P.is_rational());
  const auto res = intersect_segment_patch({Q(-1), Q(1, 2), Q(1)}, {Q(1), Q(1, 2), Q(-1)}, P);
  REQUIRE(res.points.size() == 2);
  CHECK(has(res, Q(1, 2), Q(2, 5), Q(1, 2)));  // sigma = -1/2
  CHECK(has(res, Q(1, 2), Q(6, 7), Q(1, 2)));  // sigma = +1/2
}

TEST_CASE("fold: an oblique segment through the double line at v = 1/3 and one more sheet", "[curve_patch][fibres]") {
  // C(r) = (2r - 1, 2r/3, (1 - 2r)/2): z = -x/2, y = (x + 1)/3. On the patch s (s^2 - c) y = -(s^2 - c)(1 + s/4)/2:
  // s^2 = 1/4 (x = 0, r = 1/2, v = 1/3) or s y = -(1 + s/4)/2 with y = (x + 1)/3, x = (s^2 - 1/4)(1 + s/4), i.e.
  // 4 s^4 + 16 s^3 - s^2 + 18 s + 24 = 0: one root s ~ -0.87 in [-1, 1] (r ~ 0.70, v ~ 0.47).
  const Patch P = folded(Q(1, 4));
  const auto res = intersect_segment_patch({Q(-1), Q(0), Q(1, 2)}, {Q(1), Q(2, 3), Q(-1, 2)}, P);
  REQUIRE(res.points.size() == 3);
  CHECK(has(res, Q(1, 2), Q(1, 4), Q(1, 3)));
  CHECK(has(res, Q(1, 2), Q(3, 4), Q(1, 3)));
  // the third: u = (1 + s)/2, s in (-0.9, -0.8)
  const Z1 s(Integer(-1), Integer(2));
  const Algebraic_real u3 =
      alg(Z1(4) * s * s * s * s + Z1(16) * s * s * s - s * s + Z1(18) * s + Z1(24), Q(1, 20), Q(1, 10));
  int found = 0;
  for (const auto& p : res.points)
    if (p.u == u3) {
      ++found;
      CHECK(p.multiplicity == 1);
      CHECK(p.kind == Curve_patch_intersection_kind::transversal);
      // y = v = 2r/3 and x = s^2 - 1/4 = 2r - 1 (independent relations)
      const double r = p.r.to_double(), v = p.v.to_double(), sd = 2 * u3.to_double() - 1;
      CHECK(std::abs(v - 2 * r / 3) < 1e-14);
      CHECK(std::abs((sd * sd - 0.25) * (1 + sd / 4) - (2 * r - 1)) < 1e-14);
    }
  CHECK(found == 1);
}

TEST_CASE("double cover of z = xy: every hit is reported with both preimages", "[curve_patch][fibres]") {
  const Patch P = double_cover();
  // vertical segment x = 1/4, y = 1/2: z = 1/8 at r = 1/2; s = +-1/2
  auto res = intersect_segment_patch({Q(1, 4), Q(1, 2), Q(0)}, {Q(1, 4), Q(1, 2), Q(1, 4)}, P);
  REQUIRE(res.points.size() == 2);
  CHECK(has(res, Q(1, 2), Q(1, 4), Q(1, 2)));
  CHECK(has(res, Q(1, 2), Q(3, 4), Q(1, 2)));
  // x = 1/2, y = 1/3, z from 0 to 1/3: z = 1/6 at r = 1/2; s^2 = 1/2
  res = intersect_segment_patch({Q(1, 2), Q(1, 3), Q(0)}, {Q(1, 2), Q(1, 3), Q(1, 3)}, P);
  REQUIRE(res.points.size() == 2);
  const Z1 f(Integer(1), Integer(-8), Integer(8));
  CHECK(has(res, Q(1, 2), alg(f, Q(0), Q(1, 2)), Q(1, 3)));
  CHECK(has(res, Q(1, 2), alg(f, Q(1, 2), Q(1)), Q(1, 3)));
  for (const auto& p : res.points) CHECK(p.multiplicity == 1);
}

TEST_CASE("constant curve on the double line of the fold", "[curve_patch][fibres]") {
  for (const Q& c : {Q(1, 4), Q(1, 2)}) {
    const Patch P = folded(c);
    const Rational_bezier_curve_3<Q> on({P3{Q(0), Q(2, 5), Q(0)}, P3{Q(0), Q(2, 5), Q(0)}});
    auto res = intersect_curve_patch(on, P);
    CHECK(res.points.empty());
    REQUIRE(res.overlaps.size() == 1);
    CHECK(res.overlaps[0].r0 == Algebraic_real(0));
    CHECK(res.overlaps[0].r1 == Algebraic_real(1));
    const Rational_bezier_curve_3<Q> off({P3{Q(0), Q(2, 5), Q(1, 10)}, P3{Q(0), Q(2, 5), Q(1, 10)}});
    res = intersect_curve_patch(off, P);
    CHECK(res.points.empty());
    CHECK(res.overlaps.empty());
  }
}

TEST_CASE("Whitney umbrella: a segment through the pinch point", "[curve_patch][fibres]") {
  const Patch P = umbrella();
  REQUIRE(P(Q(1, 2), Q(1, 2)) == P3{Q(0), Q(0), Q(0)});
  // x = y = z = 2r - 1: s v' = s (1 + v'^2) forces s = 0 (v' = 1 + v'^2 has no real root), then v' = 0: only the
  // singular point, at r = 1/2
  const auto res = intersect_segment_patch({Q(-1), Q(-1), Q(-1)}, {Q(1), Q(1), Q(1)}, P);
  REQUIRE(res.points.size() == 1);
  CHECK(has(res, Q(1, 2), Q(1, 2), Q(1, 2)));
  CHECK(res.points[0].tangent);  // the Jacobian [C' | Phi_u | Phi_v] is singular there (decided exactly)
  CHECK(res.points[0].multiplicity == 0);
  CHECK(res.points[0].kind == Curve_patch_intersection_kind::tangent);
}

TEST_CASE("patches with base points: the plain fold and the Whitney umbrella", "[curve_patch][fibres]") {
  // det M == 0 identically: every root of R(r) = Res_u(U, Res_v(V, E) / content) goes through the grid step
  for (const Q& c : {Q(1, 4), Q(1, 2)}) {
    const auto res = intersect_segment_patch({Q(-1), Q(1, 2), Q(1)}, {Q(1), Q(1, 2), Q(-1)}, plain_fold(c));
    REQUIRE(res.points.size() == 2);  // z = -x, y = 1/2 on the plain fold: x (s/2 + 1) = 0, so x = 0, s = +-sqrt(c)
    const Integer cd = c.denominator(), cn = c.numerator();
    const Z1 f(Integer(cd - cn), Integer(-4 * cd), Integer(4 * cd));
    CHECK(has(res, Q(1, 2), alg(f, Q(0), Q(1, 2)), Q(1, 2)));
    CHECK(has(res, Q(1, 2), alg(f, Q(1, 2), Q(1)), Q(1, 2)));
    for (const auto& p : res.points) CHECK(p.multiplicity == 1);
  }
  // (s v', s, v'^2): x = y = z = 2r - 1 gives s v' = s = v'^2: the pinch point s = v' = 0 (r = 1/2, singular:
  // exact tangent) and s = v' = 1 (r = 1, u = v = 1)
  const Q1 s = lin(-1, 2);
  const Patch W = Patch::from_power_form({in_u(Q1(1)), Q2(-s, Q1(2) * s), in_u(s), Q2(Q1(1), Q1(-4), Q1(4))});
  const auto res = intersect_segment_patch({Q(-1), Q(-1), Q(-1)}, {Q(1), Q(1), Q(1)}, W);
  REQUIRE(res.points.size() == 2);
  CHECK(has(res, Q(1, 2), Q(1, 2), Q(1, 2)));
  CHECK(has(res, Q(1), Q(1), Q(1)));
  CHECK(res.points[0].tangent);
  CHECK(res.points[0].multiplicity == 0);
  CHECK(res.points[1].kind == Curve_patch_intersection_kind::endpoint);
}

namespace {
Rational_bezier_curve_3<Q> quadratic_through_double_line(const P3& dir) {
  // C(r) = (0, 1/2, 0) + (r^2 - 1/2) dir: Bernstein coefficients of r^2 - 1/2 are (-1/2, -1/2, 1/2); the curve runs
  // along the line through (0, 1/2, 0) and reaches it at the irrational r = 1/sqrt(2).
  std::vector<P3> pts;
  for (const Q& b : {Q(-1, 2), Q(-1, 2), Q(1, 2)}) pts.push_back({b * dir[0], Q(1, 2) + b * dir[1], b * dir[2]});
  return Rational_bezier_curve_3<Q>(pts);
}
}  // namespace

TEST_CASE("fold: a curve through the double line at the irrational r = 1/sqrt(2)", "[curve_patch][fibres]") {
  // direction (1, 0, -1): on the patch z = -x with v = 1/2 forces x = 0 (1 + s/4 = -s/2 gives s = -4/3), so only
  // r = 1/sqrt(2) with u = 1/4, 3/4 (c = 1/4).
  const auto res = intersect_curve_patch(quadratic_through_double_line({Q(1), Q(0), Q(-1)}), folded(Q(1, 4)));
  REQUIRE(res.points.size() == 2);
  const Algebraic_real r = alg(Z1(Integer(-1), Integer(0), Integer(2)), Q(0), Q(1));
  CHECK(has(res, r, Q(1, 4), Q(1, 2)));
  CHECK(has(res, r, Q(3, 4), Q(1, 2)));
  for (const auto& p : res.points) CHECK(p.multiplicity == 1);
}

TEST_CASE("fold: a segment tangent to one sheet on the double line", "[curve_patch][fibres]") {
  // Sheet s = 1/2 (c = 1/4, v = 1/2) at (0, 1/2, 0): Phi_s = (2s (1 + s/4) + (s^2 - c)/4, 0, (3 s^2 - c) v)
  // = (9/8, 0, 1/4) and Phi_v = (0, 1, 0): the direction (9, 3, 2) lies in its tangent plane; the sheet s = -1/2 has
  // Phi_s = (-7/8, 0, 1/4), which with Phi_v and (9, 3, 2) is independent: transversal.
  const P3 d{Q(9, 10), Q(3, 10), Q(2, 10)};
  const auto res =
      intersect_segment_patch({-d[0], Q(1, 2) - d[1], -d[2]}, {d[0], Q(1, 2) + d[1], d[2]}, folded(Q(1, 4)));
  int at_half = 0;
  for (const auto& p : res.points) {
    if (p.r != Algebraic_real(Q(1, 2))) continue;
    ++at_half;
    REQUIRE(p.v == Algebraic_real(Q(1, 2)));
    if (p.u == Algebraic_real(Q(3, 4))) {  // s = 1/2: tangent, decided exactly
      CHECK(p.tangent);
      CHECK(p.multiplicity == 0);
      CHECK(p.kind == Curve_patch_intersection_kind::tangent);
    } else {
      CHECK(p.u == Algebraic_real(Q(1, 4)));
      CHECK(!p.tangent);
      CHECK(p.multiplicity == 1);
    }
  }
  CHECK(at_half == 2);
  // the same line run through at r = 1/sqrt(2): one irrational coordinate, still decided exactly
  const auto res2 = intersect_curve_patch(quadratic_through_double_line({Q(9), Q(3), Q(2)}), folded(Q(1, 4)));
  const Algebraic_real r0 = alg(Z1(Integer(-1), Integer(0), Integer(2)), Q(0), Q(1));
  int at_r0 = 0;
  for (const auto& p : res2.points) {
    if (p.r != r0) continue;
    ++at_r0;
    CHECK(p.v == Algebraic_real(Q(1, 2)));
    CHECK(p.tangent == (p.u == Algebraic_real(Q(3, 4))));
    CHECK(p.multiplicity == (p.tangent ? 0 : 1));
  }
  CHECK(at_r0 == 2);
}

TEST_CASE("fold, c = 1/2: a curve tangent to a sheet at irrational r and u is a clear Error", "[curve_patch][fibres]") {
  // C(r) = ((2r^2 - 1)(4r + 1/2), 1/2, 2r^2 - 1) reaches the double line at r0 = 1/sqrt(2) with C'(r0) parallel to
  // (2 sqrt(2) + 1/2, 0, 1), and the sheet s = sqrt(1/2) (u = (1 + sqrt(1/2))/2, v = 1/2) has
  // Phi_s = (2s + c/2, 0, 2 c v) = (sqrt(2) + 1/4, 0, 1/2): tangent. Two irrational coordinates: intervals can neither
  // prove nor exclude the singular solution, so Error naming the point, never a guess.
  const Q1 t = lin(0, 1), a = Q1(2) * t * t - Q1(1);
  const auto C = Rational_bezier_curve_3<Q>::from_power_form({Q1(1), a * lin(Q(1, 2), 4), Q1(Q(1, 2)), a});
  try {
    intersect_curve_patch(C, folded(Q(1, 2)));
    FAIL("expected an Error");
  } catch (const Error& e) {
    const std::string m = e.what();
    CHECK(m.find("tangent to a sheet") != std::string::npos);
    CHECK(m.find("0.707106781186548") != std::string::npos);  // r0
    CHECK(m.find("0.853553390593274") != std::string::npos);  // u = (1 + sqrt(1/2))/2
  }
}

TEST_CASE("fold: random segments through the double line", "[curve_patch][fibres]") {
  // through (0, v0, 0) with direction (a, b, d): both preimages u = (1 +- sqrt(c))/2, v = v0 at r = 1/2; every
  // reported triple satisfies C(r) = Phi(u,v) (1e-20 after refinement)
  const Q cs[] = {Q(1, 4), Q(1, 9), Q(1, 2), Q(2, 3)};
  const Q vs[] = {Q(1, 3), Q(3, 5), Q(5, 7)};
  const int dirs[][3] = {{1, 0, -1}, {2, 1, 3}, {-3, 1, 1}};
  for (const Q& c : cs)
    for (const Q& v0 : vs)
      for (const auto& d : dirs) {
        const Patch P = folded(c);
        const P3 a{Q(-d[0], 2), v0 - Q(d[1], 2), Q(-d[2], 2)}, b{Q(d[0], 2), v0 + Q(d[1], 2), Q(d[2], 2)};
        const auto res = intersect_segment_patch(a, b, P);
        // u = (1 +- sqrt(c))/2: roots of (2u - 1)^2 = c, i.e. 4 u^2 - 4 u + 1 - c (times the denominator of c)
        const Integer cd = c.denominator(), cn = c.numerator();
        const Z1 f(Integer(cd - cn), Integer(-4 * cd), Integer(4 * cd));
        CHECK(has(res, Q(1, 2), alg(f, Q(0), Q(1, 2)), v0));
        CHECK(has(res, Q(1, 2), alg(f, Q(1, 2), Q(1)), v0));
        const Q tiny = Q(1) / Q(Integer("100000000000000000000000000000000000000000")),
                eps = CGAL::ipower(Q(1, 100000), 4);
        for (const auto& p : res.points) {
          p.r.refine_to_width(tiny);
          p.u.refine_to_width(tiny);
          p.v.refine_to_width(tiny);
          const Q r = p.r.lower(), u = p.u.lower(), v = p.v.lower();
          P3 C;
          for (int k = 0; k < 3; ++k) C[k] = a[k] + r * (b[k] - a[k]);
          const P3 S = P(u, v);
          for (int k = 0; k < 3; ++k) CHECK(CGAL::abs(C[k] - S[k]) < eps);
        }
      }
}

TEST_CASE("collapsed edge: the cone (u, uv, uv^2) and its apex", "[curve_patch][fibres]") {
  // the edge u = 0 collapses to the origin (base point (u, v) = (0, oo)); the image is the cone y^2 = x z
  const Patch P =
      Patch::from_power_form({in_u(Q1(1)), in_u(lin(0, 1)), v_times(lin(0, 1)), Q2(Q1(0), Q1(0), lin(0, 1))});
  // t (1, 1/2, 1/3): y^2 = t^2/4 = x z = t^2/3 only at t = 0: the apex, whose preimage is the whole edge u = 0
  auto res = intersect_segment_patch({Q(-1), Q(-1, 2), Q(-1, 3)}, {Q(1), Q(1, 2), Q(1, 3)}, P);
  REQUIRE(res.points.size() == 1);
  CHECK(res.points[0].r == Algebraic_real(Q(1, 2)));
  CHECK(res.points[0].u == Algebraic_real(0));
  CHECK(res.points[0].collapsed_line == 0);
  CHECK(res.points[0].multiplicity == 0);
  CHECK(res.points[0].kind == Curve_patch_intersection_kind::boundary);
  // x = 1/2, z = 1/4, y = r: y^2 = 1/8 at r = 1/sqrt(8), u = 1/2, v = y/u = 1/sqrt(2)
  res = intersect_segment_patch({Q(1, 2), Q(0), Q(1, 4)}, {Q(1, 2), Q(1), Q(1, 4)}, P);
  REQUIRE(res.points.size() == 1);
  CHECK(has(res, alg(Z1(Integer(-1), Integer(0), Integer(8)), Q(0), Q(1)), Q(1, 2),
            alg(Z1(Integer(-1), Integer(0), Integer(2)), Q(0), Q(1))));
  CHECK(res.points[0].collapsed_line == -1);
  CHECK(res.points[0].multiplicity == 1);
  // a constant curve: Error naming the collapsed edge
  try {
    intersect_curve_patch(Rational_bezier_curve_3<Q>({P3{Q(1), Q(1), Q(1)}, P3{Q(1), Q(1), Q(1)}}), P);
    FAIL("expected an Error");
  } catch (const Error& e) {
    CHECK(std::string(e.what()).find("the edge u = 0 collapses to the point (0, 0, 0)") != std::string::npos);
  }
  // a ruling of the cone: the curve runs along the patch (a line of it maps into the segment): clear Error
  CHECK_THROWS_AS(intersect_segment_patch({Q(0), Q(0), Q(0)}, {Q(1), Q(1, 2), Q(1, 4)}, P), Error);
}

TEST_CASE("rational sphere octant with a collapsed edge at the pole", "[curve_patch][fibres]") {
  // ((1-v^2)(1-u^2), 2u (1-v^2), 2v (1+u^2)) / ((1+u^2)(1+v^2)): the edge v = 1 collapses to the north pole;
  // base points (u, v) = (+-i, +-1)
  const Q1 a(Q(1), Q(0), Q(-1)), b(Q(1), Q(0), Q(1)), t2(Q(0), Q(2));
  const Patch S = Patch::from_power_form({Q2(b, Q1(0), b), Q2(a, Q1(0), -a), Q2(t2, Q1(0), -t2), Q2(Q1(0), Q1(2) * b)});
  REQUIRE(S(Q(1, 3), Q(1)) == P3{Q(0), Q(0), Q(1)});
  const P3 q = S(Q(3, 5), Q(1, 2));
  REQUIRE(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] == Q(1));  // on the unit sphere
  // the z-axis meets the octant only at the pole: preimage the whole edge v = 1
  auto res = intersect_segment_patch({Q(0), Q(0), Q(0)}, {Q(0), Q(0), Q(2)}, S);
  REQUIRE(res.points.size() == 1);
  CHECK(res.points[0].r == Algebraic_real(Q(1, 2)));
  CHECK(res.points[0].v == Algebraic_real(1));
  CHECK(res.points[0].collapsed_line == 1);
  // the diagonal meets it at (1,1,1)/sqrt(3): r = 1/sqrt(3), u = tan(pi/8) = sqrt(2) - 1, v = sqrt(3) - sqrt(2)
  res = intersect_segment_patch({Q(0), Q(0), Q(0)}, {Q(1), Q(1), Q(1)}, S);
  REQUIRE(res.points.size() == 1);
  CHECK(has(res, alg(Z1(Integer(-1), Integer(0), Integer(3)), Q(0), Q(1)),
            alg(Z1(Integer(-1), Integer(2), Integer(1)), Q(0), Q(1)),
            alg(Z1(Integer(1), Integer(0), Integer(-10), Integer(0), Integer(1)), Q(0), Q(1, 2))));
  CHECK(res.points[0].multiplicity == 1);
  // the equator quarter (1 - r^2, 2r, 0)/(1 + r^2) is the edge v = 0: the curve lies on a patch with base points
  CHECK_THROWS_AS(intersect_curve_patch(Rational_bezier_curve_3<Q>::from_power_form({b, a, t2, Q1(0)}), S), Error);
  // a segment through the octant's point q = S(3/5, 1/2) at r = 1/3
  res = intersect_segment_patch({q[0] - Q(1, 3), q[1] + Q(1, 6), q[2] - Q(1, 9)},
                                {q[0] + Q(2, 3), q[1] - Q(1, 3), q[2] + Q(2, 9)}, S);
  CHECK(has(res, Q(1, 3), Q(3, 5), Q(1, 2)));
}

TEST_CASE("fold: a segment running along the double line", "[curve_patch][fibres]") {
  // (0, 2r - 1/2, 0) lies on the double line (0, v, 0) for all r, covered (twice) for v = 2r - 1/2 in [0,1]
  for (const Q& c : {Q(1, 4), Q(1, 2)}) {
    const auto res = intersect_segment_patch({Q(0), Q(-1, 2), Q(0)}, {Q(0), Q(3, 2), Q(0)}, folded(c));
    CHECK(res.points.empty());
    REQUIRE(res.overlaps.size() == 1);
    CHECK(res.overlaps[0].r0 == Algebraic_real(Q(1, 4)));
    CHECK(res.overlaps[0].r1 == Algebraic_real(Q(3, 4)));
  }
}

TEST_CASE("fold, c = 1/2: r, u and v all irrational on the double line (Krawczyk proof)", "[curve_patch][fibres]") {
  // C(r) = (2r^2 - 1, r, 1 - 2r^2) meets the double line (0, v, 0) at r0 = 1/sqrt(2), v = r0, with the preimages
  // u = (1 +- sqrt(1/2))/2; C'(r0) = (2 sqrt(2), 1, -2 sqrt(2)) is transversal to both sheets
  // (Phi_s = (+-sqrt(2) + 1/4, 0, 2 c v), Phi_v = (0, 1, 0)).
  const Q1 t = lin(0, 1), a = Q1(2) * t * t - Q1(1);
  const auto C = Rational_bezier_curve_3<Q>::from_power_form({Q1(1), a, t, -a});
  const auto res = intersect_curve_patch(C, folded(Q(1, 2)));
  const Algebraic_real r0 = alg(Z1(Integer(-1), Integer(0), Integer(2)), Q(0), Q(1));
  const Z1 f(Integer(1), Integer(-8), Integer(8));
  CHECK(has(res, r0, alg(f, Q(0), Q(1, 2)), r0));
  CHECK(has(res, r0, alg(f, Q(1, 2), Q(1)), r0));
  int at_r0 = 0;
  for (const auto& p : res.points)
    if (p.r == r0) {
      ++at_r0;
      CHECK(p.multiplicity == 1);
      CHECK(p.kind == Curve_patch_intersection_kind::transversal);
    }
  CHECK(at_r0 == 2);
}

TEST_CASE("fold restricted to one sheet: the second preimage lies outside the domain", "[curve_patch][fibres]") {
  // restriction to u in [1/2, 1] (s in [0, 1]): the double line point (0, 1/2, 0) keeps only s = 1/2, i.e. u = 3/4,
  // at the restricted parameter (3/4 - 1/2) / (1/2) = 1/2; the kernel still sees both preimages (rank drop)
  const Patch P = folded(Q(1, 4)).restriction(Q(1, 2), Q(1), Q(0), Q(1));
  const auto res = intersect_segment_patch({Q(-1), Q(1, 2), Q(1)}, {Q(1), Q(1, 2), Q(-1)}, P);
  REQUIRE(res.points.size() == 1);
  CHECK(has(res, Q(1, 2), Q(1, 2), Q(1, 2)));
  CHECK(res.points[0].multiplicity == 1);
}

TEST_CASE("random double covers Phi(u,v) = Psi((2u-1)^2, v): both preimages of a constructed hit",
          "[curve_patch][fibres]") {
  // Psi a random bi-degree (2,1) or (2,2) patch (polynomial and rational): Phi covers Psi([0,1]^2) twice, and a
  // segment through Psi(a, b) = Phi((1 +- sqrt(a))/2, b) at r0 = 1/3 must be reported there with both preimages
  // (roots of 4u^2 - 4u + 1 - a). Every reported triple is checked to 1e-20 and has its partner (r, 1 - u, v).
  std::mt19937 g(20261122);
  auto rnd = [&g](int range, int den) { return Q(int(g() % unsigned(2 * range + 1)) - range, den); };
  for (int trial = 0; trial < 8; ++trial) {
    const bool rational = trial % 2 == 1;
    const std::size_t nv = trial < 6 ? 2 : 3;
    std::vector<std::vector<P3>> pts(3, std::vector<P3>(nv));
    std::vector<std::vector<Q>> w(3, std::vector<Q>(nv, Q(1)));
    for (auto& row : pts)
      for (auto& p : row) p = {rnd(10, 7), rnd(10, 5), rnd(10, 3)};
    if (rational)
      for (auto& row : w)
        for (auto& x : row) x = Q(int(g() % 4) + 1, 2);
    const Patch Psi(pts, w);
    // compose with u -> (2u - 1)^2 in the power form
    const auto pf = Psi.power_form();
    const Q1 sq = lin(-1, 2) * lin(-1, 2);
    Patch::Power_form phi;
    for (int k = 0; k < 4; ++k) {
      std::vector<Q1> rows;
      for (int j = 0; j <= pf[k].degree(); ++j) {
        Q1 c(0), p(1);
        for (int i = 0; i <= pf[k][j].degree(); ++i, p *= sq) c += Q1(pf[k][j][i]) * p;
        rows.push_back(c);
      }
      phi[k] = Q2(rows.begin(), rows.end());
    }
    const Patch P = Patch::from_power_form(phi);
    const Q a = trial % 3 == 0 ? Q(1, 4) : Q(1, 3), b(2, 5), r0(1, 3);
    const P3 q = Psi(a, b);
    const P3 D{rnd(10, 3), rnd(10, 3), rnd(10, 3)};
    P3 A, B;
    for (int k = 0; k < 3; ++k) {
      A[k] = q[k] - r0 * D[k];
      B[k] = A[k] + D[k];
    }
    const auto res = intersect_segment_patch(A, B, P);
    const Z1 f(Integer(a.denominator() - a.numerator()), Integer(-4 * a.denominator()), Integer(4 * a.denominator()));
    CHECK(has(res, r0, alg(f, Q(0), Q(1, 2)), b));
    CHECK(has(res, r0, alg(f, Q(1, 2), Q(1)), b));
    const Q tiny = Q(1) / Q(Integer("100000000000000000000000000000000000000000")), eps = CGAL::ipower(Q(1, 100000), 4);
    for (const auto& p : res.points) {
      p.r.refine_to_width(tiny);
      p.u.refine_to_width(tiny);
      p.v.refine_to_width(tiny);
      P3 C;
      for (int k = 0; k < 3; ++k) C[k] = A[k] + p.r.lower() * (B[k] - A[k]);
      const P3 S = P(p.u.lower(), p.v.lower());
      for (int k = 0; k < 3; ++k) CHECK(CGAL::abs(C[k] - S[k]) < eps * Q(1000));
      int partners = 0;
      for (const auto& o : res.points)
        partners += o.r == p.r && o.v == p.v && std::abs(o.u.to_double() + p.u.to_double() - 1) < 1e-15;
      CHECK(partners == 1);
      CHECK(p.multiplicity == 1);
    }
  }
}

TEST_CASE("constant curve and a patch with base points: Error, not a kernel answer", "[curve_patch][fibres]") {
  // the plain fold has the base point (oo, 0), whose monomial vector is in every kernel of M: without the check the
  // point (0, 1/2, 0) of the patch would be reported as off the patch
  const Rational_bezier_curve_3<Q> on({P3{Q(0), Q(1, 2), Q(0)}, P3{Q(0), Q(1, 2), Q(0)}});
  CHECK_THROWS_AS(intersect_curve_patch(on, plain_fold(Q(1, 4))), Error);
}

TEST_CASE("sphere octant (base points): random segments, checked against the sphere equation",
          "[curve_patch][fibres]") {
  // segments through S(u0, v0) at r = 1/3 in a random direction; independent answer: the roots r in [0,1] of
  // |C(r)|^2 - 1 (exact isolation) where C(r) lies in the open octant (the octant patch covers it once)
  const Q1 a(Q(1), Q(0), Q(-1)), b(Q(1), Q(0), Q(1)), t2(Q(0), Q(2));
  const Patch S = Patch::from_power_form({Q2(b, Q1(0), b), Q2(a, Q1(0), -a), Q2(t2, Q1(0), -t2), Q2(Q1(0), Q1(2) * b)});
  std::mt19937 g(7);
  auto rnd = [&g](int range, int den) { return Q(int(g() % unsigned(2 * range + 1)) - range, den); };
  int total = 0;
  for (int trial = 0; trial < 8; ++trial) {
    const Q u0(int(g() % 9) + 1, 10), v0(int(g() % 9) + 1, 10);
    const P3 q = S(u0, v0), d{rnd(6, 4), rnd(6, 4), rnd(6, 4)};
    const P3 A{q[0] - d[0] / 3, q[1] - d[1] / 3, q[2] - d[2] / 3}, B{A[0] + d[0], A[1] + d[1], A[2] + d[2]};
    Q1 f(-1);
    for (int k = 0; k < 3; ++k) f += Q1(A[k], B[k] - A[k]) * Q1(A[k], B[k] - A[k]);
    std::vector<Algebraic_real> expected;
    bool ambiguous = false;
    for (const auto& root : isolate_real_roots(f, Q(0), Q(1))) {
      const double r = root.root.to_double();
      double x[3];
      for (int k = 0; k < 3; ++k) x[k] = CGAL::to_double(A[k]) + r * CGAL::to_double(B[k] - A[k]);
      if (std::min({std::abs(x[0]), std::abs(x[1]), std::abs(x[2])}) < 1e-6) ambiguous = true;
      if (x[0] > 0 && x[1] > 0 && x[2] > 0) expected.push_back(root.root);
    }
    if (ambiguous) continue;
    const auto res = intersect_segment_patch(A, B, S);
    REQUIRE(res.points.size() == expected.size());
    CHECK(has(res, Q(1, 3), u0, v0));
    for (std::size_t i = 0; i < expected.size(); ++i) {
      CHECK(res.points[i].r == expected[i]);
      CHECK(res.points[i].multiplicity == 1);
      const auto x = S.evaluate(res.points[i].u.to_double(), res.points[i].v.to_double());
      const double r = res.points[i].r.to_double();
      for (int k = 0; k < 3; ++k)
        CHECK(std::abs(x[k] - CGAL::to_double(A[k]) - r * CGAL::to_double(B[k] - A[k])) < 1e-12);
    }
    total += int(expected.size());
  }
  CHECK(total >= 8);
}

TEST_CASE("stereographic sphere patch (base points (u,v) with u^2 + v^2 = -1)", "[curve_patch][fibres]") {
  // (2u, 2v, 1 - u^2 - v^2) / (1 + u^2 + v^2): the inverse is u = x/(1+z), v = y/(1+z). A ray from the centre in the
  // direction d meets the unit sphere at d/|d|: d = (1, 1/2, 1/3), |d| = 7/6: r = 6/7, point (6, 3, 2)/7, (u, v) =
  // (2/3, 1/3); d = (4/3, 4/3, 2/3), |d| = 2: r = 1/2, point (2, 2, 1)/3, (u, v) = (1/2, 1/2).
  const Patch S = Patch::from_power_form({Q2(Q1(Q(1), Q(0), Q(1)), Q1(0), Q1(1)), in_u(lin(0, 2)), v_times(Q1(2)),
                                          Q2(Q1(Q(1), Q(0), Q(-1)), Q1(0), Q1(-1))});
  auto res = intersect_segment_patch({Q(0), Q(0), Q(0)}, {Q(1), Q(1, 2), Q(1, 3)}, S);
  REQUIRE(res.points.size() == 1);
  CHECK(has(res, Q(6, 7), Q(2, 3), Q(1, 3)));
  CHECK(res.points[0].multiplicity == 1);
  res = intersect_segment_patch({Q(0), Q(0), Q(0)}, {Q(4, 3), Q(4, 3), Q(2, 3)}, S);
  REQUIRE(res.points.size() == 1);
  CHECK(has(res, Q(1, 2), Q(1, 2), Q(1, 2)));
}
