// The layout's include rule (test/include_rule.h, doc/design.md) holds on the source tree, and the checker
// reports each kind of violation when one is planted in a copy of the tree.
#include "include_rule.h"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;

namespace {

// A copy of include/bezoutian and examples/ in a fresh temporary folder.
fs::path copy_of_tree(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("bezoutian_include_rule_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir / "include");
  fs::copy(fs::path(BEZOUTIAN_SOURCE_DIR) / "include" / "bezoutian", dir / "include" / "bezoutian",
           fs::copy_options::recursive);
  fs::copy(fs::path(BEZOUTIAN_SOURCE_DIR) / "examples", dir / "examples", fs::copy_options::recursive);
  return dir;
}

void append(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::app);
  out << text;
}

bool reports(const std::vector<std::string>& v, const std::string& part) {
  for (const auto& s : v)
    if (s.find(part) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("include rule: the source tree follows the layout", "[layout]") {
  const auto v = include_rule::violations(BEZOUTIAN_SOURCE_DIR);
  for (const auto& s : v) UNSCOPED_INFO(s);
  CHECK(v.empty());
}

TEST_CASE("include rule: planted violations are reported", "[layout]") {
  const fs::path dir = copy_of_tree("planted");
  const fs::path inc = dir / "include" / "bezoutian";
  REQUIRE(include_rule::violations(dir).empty());

  // an upward include: the geometry stage reaching the intersection stage
  append(inc / "geometry" / "Bernstein_basis.h", "\n#include <bezoutian/intersection/Curve_intersection.h>\n");
  // another stage's internal header
  append(inc / "lifting" / "pinch_points.h", "\n#include <bezoutian/topology/internal/fold_box.h>\n");
  // CGAL's arrangement outside the arrangement stage (reached through the library's own headers)
  append(inc / "elimination" / "Bezoutian.h", "\n#include <bezoutian/arrangement/Arr_rational_bezier_traits_2.h>\n");
  // code in a compatibility path
  append(inc / "Error.h", "\nint not_a_forwarder;\n");
  // the command-line tool including an internal header
  append(dir / "examples" / "cli" / "commands.h", "\n#include <bezoutian/lifting/internal/kernel_partner_proofs.h>\n");

  const auto v = include_rule::violations(dir);
  CHECK(reports(v, "geometry/Bernstein_basis.h: includes bezoutian/intersection/Curve_intersection.h of the later stage"));
  CHECK(reports(v, "lifting/pinch_points.h: includes bezoutian/topology/internal/fold_box.h, internal to the stage"));
  CHECK(reports(v, "elimination/Bezoutian.h: includes bezoutian/arrangement/Arr_rational_bezier_traits_2.h of the later"));
  CHECK(reports(v, "elimination/Bezoutian.h: reaches CGAL's algebraic kernel or Arrangement_2"));
  CHECK(reports(v, "Error.h: a header directly in include/bezoutian must only forward"));
  CHECK(reports(v, "examples/cli/commands.h: includes bezoutian/lifting/internal/kernel_partner_proofs.h"));
  fs::remove_all(dir);
}
