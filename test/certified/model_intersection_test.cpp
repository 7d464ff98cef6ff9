// Whole-model intersection (intersection/Model_intersection.h) on the Utah teapot of ../shared/data: the broad
// phase against the shared boundaries listed in teapot32_topology.txt (computed independently from the control
// nets), and the model's results against the single-pair functions and across thread counts.
#include "power_patch.h"
#include "test_support.h"

#include <bezoutian/intersection/Model_curves.h>
#include <bezoutian/intersection/Model_intersection.h>
#include <bezoutian/io/Geometry_document.h>

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
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

// The one curve of a model, chained with the patches so that its links at exact contacts are proved: closed, of two
// pieces, both links proved exact (where each piece ends at a crossing of two seams)
Model_curve closed_curve_of_two_pieces_with_exact_links(const Model_intersection& R,
                                                        const std::vector<Rational_bezier_patch<Rational>>& patches) {
  Model_curve_options co;
  co.patches = &patches;
  const std::vector<Model_curve> curves = chain_model_curves(R, co);
  REQUIRE(curves.size() == 1);
  const Model_curve& c = curves[0];
  CHECK(c.closed);
  REQUIRE(c.pieces.size() == 2);
  CHECK(c.links == 2);
  CHECK(c.links_proved == 2);
  return c;
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

TEST_CASE("model curves: a circle cut by the seams of a split plane and a split paraboloid is one closed curve",
          "[model][curves]") {
  // The plane z = 0 and the paraboloid z = x^2 + y^2 - 1/2, each split at x = 0 into two patches glued along it:
  // they meet in the circle x^2 + y^2 = 1/2, z = 0, whose left half is a branch of (plane left, paraboloid left)
  // and whose right half one of (plane right, paraboloid right). The halves meet at (0, +-1/sqrt 2, 0) on the
  // seams; the cross pairs (plane left, paraboloid right) touch there only.
  using bezoutian_test::patch_from_power;
  const std::vector<Rational_bezier_patch<Rational>> patches{
      patch_from_power({"u - 1", "2*v - 1", "0"}, 1, 1), patch_from_power({"u", "2*v - 1", "0"}, 1, 1),
      patch_from_power({"u - 1", "2*v - 1", "(u - 1)^2 + (2*v - 1)^2 - 1/2"}, 2, 2),
      patch_from_power({"u", "2*v - 1", "u^2 + (2*v - 1)^2 - 1/2"}, 2, 2)};
  const Model_intersection R = intersect_model(patches);
  // both links are exact: each end is the crossing of the plane's seam x = 0 with the paraboloid's, on the seam
  // curve that the two halves of the plane share (at 1/2 +- sqrt(2)/4 along it)
  const Model_curve c = closed_curve_of_two_pieces_with_exact_links(R, patches);
  // without the patches the links are found the same way but not proved
  const std::vector<Model_curve> unproved = chain_model_curves(R);
  REQUIRE(unproved.size() == 1);
  CHECK(unproved[0].links == 2);
  CHECK(unproved[0].links_proved == 0);
  const Model_problem &a = R.problems[c.pieces[0].problem], &b = R.problems[c.pieces[1].problem];
  CHECK(std::make_pair(a.first, a.second) == std::make_pair(std::size_t(0), std::size_t(2)));
  CHECK(std::make_pair(b.first, b.second) == std::make_pair(std::size_t(1), std::size_t(3)));
  // both pieces' problems are certified, so each piece is a proved branch: the curve is all of the circle
  CHECK(c.pieces_certified);
  CHECK(c.largest_gap <= 1e-12);
  // the points go once around the circle, in steps of the polyline tolerance's order
  const auto points = model_curve_points(R, c);
  double largest_step = 0, turn = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const auto& p = points[k];
    CHECK(p[0] * p[0] + p[1] * p[1] == Approx(0.5).margin(1e-9));
    CHECK(std::fabs(p[2]) <= 1e-9);
    const auto& q = points[(k + 1) % points.size()];
    largest_step = std::max(largest_step, std::hypot(q[0] - p[0], q[1] - p[1]));
    turn += std::remainder(std::atan2(q[1], q[0]) - std::atan2(p[1], p[0]), 2 * M_PI);
  }
  CHECK(largest_step < 0.1);
  CHECK(std::fabs(std::fabs(turn) - 2 * M_PI) < 1e-9);
  // the links are at the seam points (0, +-1/sqrt 2, 0)
  const auto& first_sheet = a.locus.arcs[c.pieces[0].arc].sheets[c.pieces[0].sheet];
  for (const auto& end : {first_sheet.points.front(), first_sheet.points.back()}) {
    CHECK(std::fabs(end.point_3d[0]) <= 1e-12);
    CHECK(std::fabs(std::fabs(end.point_3d[1]) - std::sqrt(0.5)) <= 1e-12);
  }
}

TEST_CASE("model curves: the handle's upper end cuts the body in one closed curve across both seams",
          "[model][curves][teapot]") {
  // Handle halves 12, 13 (mirror images in y = 0) and body sectors 5, 6 (mirror images, their seam in y = 0): the
  // curve where the handle's upper end enters the body has one branch on (5, 12) and one on (6, 13), joined at
  // the two points where the handle's seam crosses the body's (both in y = 0).
  const auto all = teapot();
  const std::vector<Rational_bezier_patch<Rational>> patches{all[5], all[6], all[12], all[13]};
  Model_intersection_options o;
  o.self_intersections = false;
  const Model_intersection R = intersect_model(patches, o);
  // both links proved: the crossings of the handle's seam with the body's, exact points of the body's seam curve
  // (shared by sectors 5 and 6)
  const Model_curve c = closed_curve_of_two_pieces_with_exact_links(R, patches);
  std::set<std::pair<std::size_t, std::size_t>> pairs;
  for (const auto& p : c.pieces) pairs.insert({R.problems[p.problem].first, R.problems[p.problem].second});
  CHECK(pairs == std::set<std::pair<std::size_t, std::size_t>>{{0, 2}, {1, 3}});
  // symmetric about y = 0: each point's mirror image lies near the curve's polyline (within its chord error)
  const auto points = model_curve_points(R, c);
  CHECK(points.size() > 200);
  std::size_t on_seam = 0;
  for (const auto& p : points) {
    double best = 1e300;
    for (std::size_t k = 0; k + 1 < points.size(); ++k) {
      const auto &x = points[k], &y = points[k + 1];
      std::array<double, 3> d{y[0] - x[0], y[1] - x[1], y[2] - x[2]}, m{p[0] - x[0], -p[1] - x[1], p[2] - x[2]};
      const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      const double t = dd > 0 ? std::min(1.0, std::max(0.0, (m[0] * d[0] + m[1] * d[1] + m[2] * d[2]) / dd)) : 0;
      best = std::min(best, std::hypot(m[0] - t * d[0], m[1] - t * d[1], m[2] - t * d[2]));
    }
    CHECK(best < 2e-3);
    on_seam += std::fabs(p[1]) < 1e-12;
  }
  CHECK(on_seam == 2);  // the two links, each point once
}

TEST_CASE("model curves: two ends are one exact point only on one boundary curve at one parameter",
          "[model][curves]") {
  // Two unit squares glued along x = 0: the left one's side u = 1 and the right one's side u = 0 are the segment
  // (0, 2v - 1, 0), v in [0, 1]; a third patch has that segment reversed, (0, 1 - 2v, 0), as its side u = 0.
  using bezoutian_test::patch_from_power;
  const std::vector<Rational_bezier_patch<Rational>> patches{
      patch_from_power({"u - 1", "2*v - 1", "0"}, 1, 1), patch_from_power({"u", "2*v - 1", "0"}, 1, 1),
      patch_from_power({"u", "1 - 2*v", "0"}, 1, 1)};
  // y = 1/sqrt 2 on the seam: v = 1/2 + sqrt(2)/4, a root of 8v^2 - 8v + 1 in [0.8, 0.9]; on the reversed side
  // 1 - v = 1/2 - sqrt(2)/4, the root in [0.1, 0.2]
  const Polynomial_1<Integer> f(Integer(1), Integer(-8), Integer(8));
  const Algebraic_real v(f, Rational(8, 10), Rational(9, 10)), w(f, Rational(1, 10), Rational(2, 10));
  using internal::Boundary_curve_point;
  auto at = [](std::size_t patch, int side, const Algebraic_real& x) {
    return std::vector<Boundary_curve_point>{{patch, side, x}};
  };
  CHECK(internal::one_minus(v) == w);
  CHECK(internal::one_minus(Algebraic_real(Rational(1, 3))) == Algebraic_real(Rational(2, 3)));
  CHECK(internal::same_exact_point(patches, at(0, 1, v), at(1, 3, v)));        // one seam, one parameter
  CHECK_FALSE(internal::same_exact_point(patches, at(0, 1, v), at(1, 3, w)));  // the other end of the seam
  CHECK(internal::same_exact_point(patches, at(0, 1, v), at(2, 3, w)));        // the seam reversed: 1 - v
  CHECK_FALSE(internal::same_exact_point(patches, at(0, 1, v), at(2, 3, v)));
  CHECK_FALSE(internal::same_exact_point(patches, at(0, 1, v), at(1, 1, v)));  // another side: x = 1
}

TEST_CASE("model: a patch with a pole is refused with its reason, the rest of the model is answered", "[model]") {
  // examples/data/model_with_bad_patches.json: the split circle model, a patch whose weight u - 1/2 vanishes inside
  // its domain (patch 4), and a patch collapsed to a segment (patch 5)
  const auto patches =
      io::read_geometry_file(std::string(BEZOUTIAN_SOURCE_DIR) + "/examples/data/model_with_bad_patches.json").patches;
  REQUIRE(patches.size() == 6);
  const Model_intersection R = intersect_model(patches);
  REQUIRE(R.patch_errors.size() == 6);
  for (std::size_t k = 0; k < 6; ++k) CHECK(R.patch_errors[k].empty() == (k != 4));
  CHECK(R.patch_errors[4].find("patch 4 is refused: pole in the patch domain") != std::string::npos);
  std::size_t with_pole = 0;
  for (const Model_problem& p : R.problems) {
    INFO("problem " << p.first << ", " << p.second << ": " << p.error);
    if (p.first == 4 || p.second == 4) {
      // the patch has no control-point box (weights of both signs), so it is paired with every other patch
      ++with_pole;
      CHECK_FALSE(p.computed);
      CHECK(p.error == R.patch_errors[4]);
    } else if (p.first != 5 && p.second != 5) {
      CHECK(p.computed);
      CHECK(p.certified == (p.computed && locus_certified(p.locus)));
    }
  }
  CHECK(with_pole == 6);
  // the good patches' circle is still one closed curve of two certified pieces
  const auto curves = chain_model_curves(R);
  std::size_t closed = 0;
  for (const auto& c : curves) closed += c.closed && c.pieces.size() == 2 && c.pieces_certified;
  CHECK(closed == 1);
}
