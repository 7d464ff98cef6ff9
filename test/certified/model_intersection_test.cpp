// Whole-model intersection (intersection/Model_intersection.h) on the Utah teapot of ../shared/data: the broad
// phase against the shared boundaries listed in teapot32_topology.txt (computed independently from the control
// nets), and the model's results against the single-pair functions and across thread counts.
#include "test_support.h"

#include <bezoutian/intersection/Model_intersection.h>
#include <bezoutian/io/Geometry_document.h>

#include <catch2/catch.hpp>

#include <array>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <utility>
#include <vector>

using namespace bezoutian;

namespace {

// The pairs of patches that share a boundary curve, read from the data's topology file ("  0(rim).col3 (v=1) ==
// 1(rim).col0 (v=0)", "  8(body).row3 (u=1) == reversed 31(bottom).row3 (u=1)"); `curves` counts its lines.
std::set<std::pair<std::size_t, std::size_t>> shared_boundary_pairs(std::size_t* curves = nullptr) {
  std::ifstream in(bezoutian_test::shared_data("teapot/teapot32_topology.txt"));
  const std::regex line(R"(^\s*(\d+)\(\w+\)\.\w+ \([^)]*\) == +(reversed +)?(\d+)\(\w+\)\.\w+ \([^)]*\))");
  std::set<std::pair<std::size_t, std::size_t>> out;
  std::size_t count = 0;
  for (std::string s; std::getline(in, s);) {
    std::smatch m;
    if (!std::regex_search(s, m, line)) continue;
    ++count;
    const std::size_t a = std::stoul(m[1]), b = std::stoul(m[3]);
    out.insert({std::min(a, b), std::max(a, b)});
  }
  if (curves) *curves = count;
  return out;
}

std::vector<Rational_bezier_patch<Rational>> teapot() {
  return io::read_geometry_file(bezoutian_test::shared_data("teapot/teapot32.bpt")).patches;
}

}  // namespace

TEST_CASE("model: the broad phase keeps every pair of the teapot that shares a boundary", "[model]") {
  const auto patches = teapot();
  REQUIRE(patches.size() == 32);
  const auto pairs = internal::pairs_with_meeting_boxes(patches);
  const std::set<std::pair<std::size_t, std::size_t>> kept(pairs.begin(), pairs.end());
  std::size_t curves = 0;
  const auto shared = shared_boundary_pairs(&curves);
  // the data's README: 52 shared boundary curves; the handle's and spout's two pairs of halves share two each
  CHECK(curves == 52);
  CHECK(shared.size() == 48);
  for (const auto& p : shared) {
    INFO("patches " << p.first << ", " << p.second);
    CHECK(kept.count(p) == 1);
  }
  // 164 of the 496 pairs have control-point boxes that meet (closed boxes: the seams touch)
  CHECK(pairs.size() == 164);
  // each kept pair's boxes do meet, by the definition written out here on exact coordinates
  auto box = [](const Rational_bezier_patch<Rational>& p) {
    std::array<Rational, 3> lo, hi;
    for (int c = 0; c < 3; ++c) lo[c] = hi[c] = p.control_point(0, 0)[c];
    for (int i = 0; i <= p.degree_u(); ++i)
      for (int j = 0; j <= p.degree_v(); ++j)
        for (int c = 0; c < 3; ++c) {
          const Rational x = p.control_point(std::size_t(i), std::size_t(j))[c];
          lo[c] = std::min(lo[c], x);
          hi[c] = std::max(hi[c], x);
        }
    return std::make_pair(lo, hi);
  };
  std::size_t meeting = 0;
  for (std::size_t i = 0; i < patches.size(); ++i)
    for (std::size_t j = i + 1; j < patches.size(); ++j) {
      const auto a = box(patches[i]), b = box(patches[j]);
      bool meet = true;
      for (int c = 0; c < 3; ++c) meet = meet && a.first[c] <= b.second[c] && b.first[c] <= a.second[c];
      meeting += meet;
      CHECK(meet == (kept.count({i, j}) == 1));
    }
  CHECK(meeting == 164);
}

TEST_CASE("model: rim and body patches, the same answers on one and two threads", "[model]") {
  // rim 1 and body 4, 5: the shared boundary curves 1|5 and 4|5 of the topology file, the corner contact of 1|4
  const auto all = teapot();
  const std::vector<Rational_bezier_patch<Rational>> patches{all[1], all[4], all[5]};
  const auto shared_in_file = shared_boundary_pairs();
  const std::size_t index[3] = {1, 4, 5};
  Model_intersection_options o;
  o.threads = 1;
  const Model_intersection one = intersect_model(patches, o);
  o.threads = 2;
  const Model_intersection two = intersect_model(patches, o);
  REQUIRE(one.problems.size() == 3 + 3);
  REQUIRE(two.problems.size() == one.problems.size());
  CHECK(two.threads_used == 2);
  for (std::size_t k = 0; k < one.problems.size(); ++k) {
    const Model_problem &p = one.problems[k], &q = two.problems[k];
    INFO("problem " << p.first << ", " << p.second << (p.computed ? "" : ": " + p.error));
    REQUIRE(p.computed);
    REQUIRE(q.computed);
    CHECK(p.first == q.first);
    CHECK(p.second == q.second);
    std::size_t curves = 0;
    for (const auto& c : p.locus.contacts) curves += c.shared_curve;
    const bool shared = !p.self() && shared_in_file.count({index[p.first], index[p.second]}) == 1;
    CHECK(curves == (shared ? 1u : 0u));
    // the body sectors' seam and the self-intersections (none: the sectors are proved injective) are certified
    if (p.self() || (p.first == 1 && p.second == 2)) {
      std::string why;
      CHECK(locus_certified(p.locus, &why));
      INFO(why);
      for (const auto& a : p.locus.arcs)
        for (const auto& x : a.points) CHECK_FALSE(x.genuine);
    }
    // the two runs agree: the same contacts, arcs, points and statuses
    REQUIRE(p.locus.contacts.size() == q.locus.contacts.size());
    for (std::size_t c = 0; c < p.locus.contacts.size(); ++c) {
      CHECK(p.locus.contacts[c].side_first == q.locus.contacts[c].side_first);
      CHECK(p.locus.contacts[c].side_second == q.locus.contacts[c].side_second);
      CHECK(p.locus.contacts[c].shared_curve == q.locus.contacts[c].shared_curve);
    }
    REQUIRE(p.locus.arcs.size() == q.locus.arcs.size());
    for (std::size_t a = 0; a < p.locus.arcs.size(); ++a) {
      CHECK(p.locus.arcs[a].undecided_fraction == q.locus.arcs[a].undecided_fraction);
      REQUIRE(p.locus.arcs[a].points.size() == q.locus.arcs[a].points.size());
      for (std::size_t i = 0; i < p.locus.arcs[a].points.size(); ++i) {
        const Locus_point &x = p.locus.arcs[a].points[i], &y = q.locus.arcs[a].points[i];
        CHECK(x.projection == y.projection);
        CHECK(x.genuine == y.genuine);
        CHECK(x.status_proved == y.status_proved);
      }
    }
  }
  // a problem of the model is the single-pair function's answer
  const Surface_locus L = intersection_locus(patches[1], patches[2]);
  REQUIRE(one.problems[2].first == 1);
  REQUIRE(one.problems[2].second == 2);
  CHECK(L.contacts.size() == one.problems[2].locus.contacts.size());
  CHECK(L.arcs.size() == one.problems[2].locus.arcs.size());
}

TEST_CASE("model: a problem over its budget is reported, the others go on", "[model]") {
  const auto all = teapot();
  const std::vector<Rational_bezier_patch<Rational>> patches{all[4], all[5]};
  Model_intersection_options o;
  o.threads = 2;
  o.surface.limits.time_limit = 1e-9;  // every problem over its budget at the first check
  const Model_intersection R = intersect_model(patches, o);
  REQUIRE(R.problems.size() == 3);
  // the pair: over its budget at the first check, after the direct proofs (which do not separate two sectors
  // sharing a seam)
  CHECK_FALSE(R.problems[0].self());
  CHECK_FALSE(R.problems[0].computed);
  CHECK(R.problems[0].error.find("time_limit exceeded in direct proofs") != std::string::npos);
  // the self-intersections: answered by the direct proof (each sector is proved injective) before the first check
  for (std::size_t k = 1; k < 3; ++k) {
    CHECK(R.problems[k].self());
    CHECK(R.problems[k].computed);
    CHECK(locus_certified(R.problems[k].locus));
  }
}
