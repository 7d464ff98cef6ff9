// Curve/curve intersection against external fixtures: dhermes/bezier (53 cases, exact minimal polynomials),
// nical/lyon (exact answers recomputed independently) and Axom (curve_curve cases). All strategies must agree.
#include <catch2/catch.hpp>

#include "intersection_checks.h"

#include "test_support.h"

#include <bezoutian/intersection/Curve_intersection.h>
#include <bezoutian/io/Exact_number.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <map>

using namespace bezoutian;
using Curve = Rational_bezier_curve_2<>;

namespace {

nlohmann::json load(const std::string& rel) {
  std::ifstream in(bezoutian_test::shared_data(rel));
  REQUIRE(in.good());
  return nlohmann::json::parse(in);
}

Rational number(const nlohmann::json& v) {
  if (v.is_number_integer()) return Rational(v.get<long long>());
  if (v.is_number_float()) return Rational(v.get<double>());
  return io::exact_number(v.get<std::string>());
}

// control points as two rows [[x0..xn],[y0..yn]]
Curve rows_curve(const nlohmann::json& rows) {
  std::vector<Curve::Point> p;
  for (std::size_t i = 0; i < rows[0].size(); ++i) p.push_back({number(rows[0][i]), number(rows[1][i])});
  return Curve(p);
}

Polynomial_1<Rational> to_q(const Polynomial_1<Integer>& f) {
  std::vector<Rational> c;
  for (int i = 0; i <= f.degree(); ++i) c.push_back(Rational(f[i]));
  return Polynomial_1<Rational>(c.begin(), c.end());
}

double dist(const Algebraic_real& a, const Rational& b) {
  return std::abs(CGAL::to_double(Rational(a.is_rational() ? a.rational_value() : (a.refine_to_width(Rational(1, 1000000000) * Rational(1, 1000000000)), a.lower())) - b));
}

const Curve_intersection_method all_methods[] = {Curve_intersection_method::default_method,
                                                  Curve_intersection_method::subresultant,
                                                  Curve_intersection_method::projection,
                                                  Curve_intersection_method::resolvent};

using bezoutian_test::require_same;

} // namespace

TEST_CASE("dhermes/bezier curve intersections: 53 cases, exact parameters, minimal polynomials, overlaps",
          "[curve_intersection][dhermes]") {
  const auto curves = load("dhermes_bezier/tests/functional/curves.json");
  const auto cases = load("dhermes_bezier/tests/functional/curve_intersections.json");
  int checked = 0, polys = 0;
  for (const auto& c : cases) {
    const int id = c["id"];
    INFO("dhermes case " << id);
    const Curve a = rows_curve(curves[c["curve1"].get<std::string>()]["control_points"]);
    const Curve b = rows_curve(curves[c["curve2"].get<std::string>()]["control_points"]);
    const Curve_intersection_result r = intersect_curves(a, b);
    for (auto m : all_methods) require_same(r, intersect_curves(a, b, m));
    const auto& sp = c["curve1_params"];
    const auto& tp = c["curve2_params"];
    // Of the "coincident" cases only #20 shares a piece inside [0,1]^2 (curve1([1/4,1]) == curve24([0,3/4]));
    // in #33-#35 the common piece lies outside (e.g. curve42([1,2]) == curve43([0,1])): isolated points only.
    if (id == 20) {
      REQUIRE(r.overlaps.size() == 1);
      REQUIRE(r.points.empty());
      const auto& o = r.overlaps[0];
      // the fixture lists the two ends of the common piece (in either order)
      const Rational s0 = number(sp[0]), s1 = number(sp[1]), t0 = number(tp[0]), t1 = number(tp[1]);
      const bool same = o.s0 == s0 && o.s1 == s1 && o.t0 == t0 && o.t1 == t1;
      const bool swapped = o.s0 == s1 && o.s1 == s0 && o.t0 == t1 && o.t1 == t0;
      CHECK((same || swapped));
      ++checked;
      continue;
    }
    CHECK(r.overlaps.empty());
    const std::size_t expected = id == 46 ? 4 : sp.size();  // README: case 46 has 4 exact intersections
    REQUIRE(r.points.size() == expected);
    // #46: the fixture describes the ideal (exactly tangent) configuration; the stored dyadic control points give two
    // crossings 1.4e-9 apart near the listed tangency (README), and its minimal polynomials do not apply.
    const double tol = id >= 51 ? 1e-9 : (id == 46 ? 1e-8 : 1e-13);
    for (std::size_t k = 0; k < sp.size(); ++k) {
      const Rational se = number(sp[k]), te = number(tp[k]);
      bool found = false;
      for (const auto& p : r.points) {
        if (dist(p.s, se) > tol || dist(p.t, te) > tol) continue;
        found = true;
        // exact values (integers, p/q) must come out exactly
        if (!sp[k].is_string() || sp[k].get<std::string>().find("0x") == std::string::npos) CHECK(p.s == se);
        if (!tp[k].is_string() || tp[k].get<std::string>().find("0x") == std::string::npos) CHECK(p.t == te);
        if (c.contains("curve1_polys") && id != 46) {
          auto poly = [](const nlohmann::json& co) {
            std::vector<Integer> v;
            for (const auto& x : co) v.push_back(Integer(std::to_string(x.get<long long>())));
            return Polynomial_1<Integer>(v.begin(), v.end());
          };
          const auto ps = poly(c["curve1_polys"][k]), pt = poly(c["curve2_polys"][k]);
          CHECK(p.s.sign_of(ps) == 0);
          CHECK(p.t.sign_of(pt) == 0);
          // after an exact comparison with the fixture's number our defining polynomial divides the minimal one
          for (const auto& x : isolate_real_roots(ps, Rational(0), Rational(1)))
            if (x.root == p.s && !p.s.is_rational()) CHECK(CGAL::is_zero(CGAL::mod(to_q(ps), to_q(p.s.polynomial()))));
          for (const auto& x : isolate_real_roots(pt, Rational(0), Rational(1)))
            if (x.root == p.t && !p.t.is_rational()) CHECK(CGAL::is_zero(CGAL::mod(to_q(pt), to_q(p.t.polynomial()))));
          ++polys;
        }
      }
      CHECK(found);
    }
    if (c["type"] == "tangent" && id != 46) {  // at least one tangency (or a tangential endpoint hit)
      bool tangent = false;
      for (const auto& p : r.points) tangent = tangent || p.tangent || p.kind == Curve_intersection_kind::endpoint;
      CHECK(tangent);
    }
    ++checked;
  }
  CHECK(checked == 53);
  CHECK(polys > 17);
}

TEST_CASE("lyon cubic intersections: exact answers", "[curve_intersection][lyon]") {
  const auto d = load("lyon/lyon_cases.json");
  for (const auto& c : d["cases"]) {
    INFO(c["id"].get<std::string>());
    const Curve a = rows_curve(c["curve1"]), b = rows_curve(c["curve2"]);
    const Curve_intersection_result r = intersect_curves(a, b);
    for (auto m : all_methods) require_same(r, intersect_curves(a, b, m));
    if (!c["exact_answer"].is_array()) {  // overlap
      CHECK(r.overlaps.size() >= 1);
      continue;
    }
    const auto& ans = c["exact_answer"];
    REQUIRE(r.points.size() == ans.size());
    for (const auto& e : ans) {
      bool found = false;
      for (const auto& p : r.points)
        if (dist(p.s, number(e["s"])) < 1e-12 && dist(p.t, number(e["t"])) < 1e-12) found = true;
      CHECK(found);
    }
  }
}

TEST_CASE("Axom curve/curve cases", "[curve_intersection][axom]") {
  const auto d = load("axom/axom_cases.json");
  for (const auto& c : d["curve_curve"]) {
    INFO(c["id"].get<std::string>());
    const Curve a = rows_curve(c["curve1"]), b = rows_curve(c["curve2"]);
    const Curve_intersection_result r = intersect_curves(a, b);
    for (auto m : all_methods) require_same(r, intersect_curves(a, b, m));
    const double tol = c.contains("tol") ? c["tol"].get<double>() : 1e-12;
    std::vector<Algebraic_real> s, t;
    for (const auto& p : r.points) s.push_back(p.s), t.push_back(p.t);
    std::sort(s.begin(), s.end());
    std::sort(t.begin(), t.end());
    REQUIRE(s.size() == c["expected_s_sorted"].size());
    for (std::size_t k = 0; k < s.size(); ++k) {
      CHECK(dist(s[k], number(c["expected_s_sorted"][k])) < tol);
      CHECK(dist(t[k], number(c["expected_t_sorted"][k])) < tol);
    }
  }
}
