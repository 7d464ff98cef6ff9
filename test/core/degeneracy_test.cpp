// Degeneracy warnings (Degeneracy.h): the teapot's collapsed rows as listed in the external topology
// file, and constructed cases whose degeneracy is checked independently (vanishing derivative, a pole).
#include <bezoutian/geometry/Degeneracy.h>
#include <bezoutian/io/Geometry_document.h>

#include <catch2/catch.hpp>

#include "test_support.h"

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

using namespace bezoutian;
using bezoutian_test::shared_data;

namespace {
using Curve_2 = Rational_bezier_curve_2<Rational>;
using Patch = Rational_bezier_patch<Rational>;
Rational q(const char* s) { return Rational(std::string(s)); }

bool has_warning(const std::vector<std::string>& w, const std::string& part) {
  for (const std::string& s : w)
    if (s.find(part) != std::string::npos) return true;
  return false;
}
} // namespace

TEST_CASE("degeneracy: teapot lid and bottom rows collapse exactly as the topology file says", "[degeneracy][teapot]") {
  const io::Geometry_document d = io::read_geometry_file(shared_data("teapot/teapot32.bpt"));
  REQUIRE(d.patches.size() == 32);
  // "  patch 20 (lid): row 0 collapsed to point ('0', '0', '63/20')"
  std::ifstream in(shared_data("teapot/teapot32_topology.txt"));
  REQUIRE(in);
  const std::regex collapsed(R"(patch (\d+) \(\w+\): row (\d+) collapsed to point \('([^']*)', '([^']*)', '([^']*)'\))");
  std::map<int, std::set<std::size_t>> expected;
  std::string line;
  std::size_t listed = 0;
  while (std::getline(in, line)) {
    std::smatch m;
    if (!std::regex_search(line, m, collapsed)) continue;
    const int patch = std::stoi(m[1]);
    const std::size_t row = std::stoul(m[2]);
    expected[patch].insert(row);
    ++listed;
    const std::vector<std::string> w = degeneracy_warnings(d.patches[patch]);
    INFO(line);
    CHECK(has_warning(w, "row " + std::to_string(row) + " of the control net is collapsed to the point (" +
                             std::string(m[3]) + ", " + std::string(m[4]) + ", " + std::string(m[5]) + ")"));
    if (row == 0) CHECK(has_warning(w, "the boundary u = 0 is a single point"));
  }
  CHECK(listed == 12);
  for (int p = 0; p < 32; ++p) {
    INFO("patch " << p);
    const std::vector<std::size_t> rows = collapsed_rows(d.patches[p]);
    CHECK(std::set<std::size_t>(rows.begin(), rows.end()) == expected[p]);
    CHECK(collapsed_columns(d.patches[p]).empty());
    // nothing else is degenerate on the teapot: one warning per collapsed row
    CHECK(degeneracy_warnings(d.patches[p]).size() == expected[p].size());
  }
}

TEST_CASE("degeneracy: curves", "[degeneracy][curves]") {
  // a clean rational quarter circle: no warning
  const Curve_2 arc({{q("1"), q("0")}, {q("1"), q("1")}, {q("0"), q("1")}}, {q("1"), q("1"), q("2")});
  CHECK(degeneracy_warnings(arc).empty());

  // all control points equal (with different weights): the curve is a point
  const Curve_2 point({{q("1/2"), q("3")}, {q("1/2"), q("3")}, {q("1/2"), q("3")}}, {q("1"), q("5"), q("2")});
  const auto wp = degeneracy_warnings(point);
  REQUIRE(wp.size() == 1);
  CHECK(has_warning(wp, "single point"));
  CHECK(has_warning(wp, "(1/2, 3)"));
  CHECK(point(q("1/3")) == Curve_2::Point{q("1/2"), q("3")});
  CHECK(degeneracy_warnings(Curve_2(std::vector<Curve_2::Point>{{q("0"), q("0")}})).size() == 1);  // degree 0

  // P0 == P1: the derivative vanishes at t = 0 (checked with the hodograph)
  const Curve_2 cusp({{q("0"), q("0")}, {q("0"), q("0")}, {q("1"), q("2")}, {q("3"), q("0")}});
  const auto wc = degeneracy_warnings(cusp);
  REQUIRE(wc.size() == 1);
  CHECK(has_warning(wc, "control points 0 and 1 coincide at (0, 0); the derivative vanishes at t = 0"));
  CHECK(cusp.derivative()(Rational(0)) == Curve_2::Point{q("0"), q("0")});
  // an interior repetition
  const Curve_2 rep({{q("0"), q("0")}, {q("1"), q("1")}, {q("1"), q("1")}, {q("3"), q("0")}});
  CHECK(degeneracy_warnings(rep) == std::vector<std::string>{"control points 1 and 2 coincide at (1, 1)"});

  // weights 1, -1, 1: W(t) = (1 - 2t)^2 has a root at t = 1/2, a pole the warning tells to look for
  const Curve_2 pole({{q("0"), q("0")}, {q("1"), q("1")}, {q("2"), q("0")}}, {q("1"), q("-1"), q("1")});
  const auto wm = degeneracy_warnings(pole);
  CHECK(has_warning(wm, "mixed signs (2 positive, 1 negative): check for poles"));
  CHECK_THROWS_AS(pole(Rational(1, 2)), Invalid_input);
  // all weights negative: no pole warning (the same curve as all positive)
  CHECK(degeneracy_warnings(Curve_2({{q("0"), q("0")}, {q("1"), q("1")}}, {q("-1"), q("-3")})).empty());

  // a control point at infinity
  const Curve_2 inf = Curve_2::from_homogeneous({{q("1"), q("0"), q("0")}, {q("0"), q("1"), q("1")}, {q("1"), q("2"), q("0")}});
  CHECK(has_warning(degeneracy_warnings(inf), "1 control point of the curve at infinity"));
}

TEST_CASE("degeneracy: patches", "[degeneracy][patches]") {
  using Net = std::vector<std::vector<Patch::Point>>;
  // bilinear saddle: clean
  const Patch saddle(Net{{{q("0"), q("0"), q("0")}, {q("0"), q("1"), q("0")}}, {{q("1"), q("0"), q("0")}, {q("1"), q("1"), q("1")}}});
  CHECK(degeneracy_warnings(saddle).empty());
  CHECK(collapsed_rows(saddle).empty());

  // a triangle-like patch: column 2 (v = 1) collapses to the apex, column 1 is an interior collapse
  Net net;
  for (int i = 0; i <= 2; ++i)
    net.push_back({{Rational(i), Rational(0), Rational(0)}, {q("5"), q("5"), q("5")}, {q("7"), q("7"), q("0")}});
  const Patch tri(net);
  const auto wt = degeneracy_warnings(tri);
  CHECK(collapsed_columns(tri) == std::vector<std::size_t>{1, 2});
  CHECK(has_warning(wt, "column 2 of the control net is collapsed to the point (7, 7, 0): the boundary v = 1 is a single point"));
  CHECK(has_warning(wt, "column 1 of the control net is collapsed to the point (5, 5, 5) (an interior column)"));
  // the boundary curve v = 1 is indeed constant
  CHECK(tri(q("1/3"), Rational(1)) == Patch::Point{q("7"), q("7"), q("0")});

  // all rows equal: the patch does not depend on u (every column collapses too)
  Net cyl(3, Net::value_type{{q("0"), q("0"), q("0")}, {q("1"), q("2"), q("0")}, {q("3"), q("0"), q("1")}});
  const Patch c(cyl);
  const auto wc = degeneracy_warnings(c);
  CHECK(has_warning(wc, "all rows of the control net are equal: the patch does not depend on u"));
  CHECK(collapsed_columns(c).size() == 3);
  CHECK(c(q("0"), q("2/3")) == c(q("5/7"), q("2/3")));

  // single point
  Net pt(2, Net::value_type(3, Patch::Point{q("1"), q("-2"), q("1/3")}));
  const auto wpt = degeneracy_warnings(Patch(pt));
  REQUIRE(wpt.size() == 1);
  CHECK(has_warning(wpt, "the patch is a single point: all 6 control points equal (1, -2, 1/3)"));

  // repeated consecutive points in a column (not a whole row/column)
  Net rep = {{{q("0"), q("0"), q("0")}, {q("0"), q("1"), q("0")}},
             {{q("0"), q("0"), q("0")}, {q("1"), q("1"), q("0")}},
             {{q("2"), q("0"), q("0")}, {q("2"), q("1"), q("1")}}};
  CHECK(degeneracy_warnings(Patch(rep)) == std::vector<std::string>{"control points [0][0] and [1][0] coincide at (0, 0, 0)"});

  // mixed-sign weights: W(u,v) = (1-2u)^2 along every v has a pole line at u = 1/2
  const Patch pole(Net{{{q("0"), q("0"), q("0")}, {q("0"), q("1"), q("0")}},
                       {{q("1"), q("0"), q("1")}, {q("1"), q("1"), q("1")}},
                       {{q("2"), q("0"), q("0")}, {q("2"), q("1"), q("0")}}},
                   {{q("1"), q("1")}, {q("-1"), q("-1")}, {q("1"), q("1")}});
  CHECK(has_warning(degeneracy_warnings(pole), "mixed signs (4 positive, 2 negative): check for poles"));
  CHECK_THROWS_AS(pole(Rational(1, 2), Rational(1, 3)), Invalid_input);
}
