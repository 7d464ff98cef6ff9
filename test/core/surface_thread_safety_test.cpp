// Thread safety of the surface problems (doc/hostile_input.md, "What is thread-safe"): independent patch/patch and
// self-intersection problems solved on four threads, sharing their input patches, and one surface locus copied and
// read from four threads at once. Each threaded answer is compared field by field with the one computed beforehand
// on one thread, and the genuine points against closed forms. scripts/sanitizers.sh thread runs this file under
// ThreadSanitizer with test/core/thread_safety_test.cpp.
#include "power_patch.h"
#include "thread_test_support.h"

#include <bezoutian/intersection/Model_intersection.h>

#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

using namespace bezoutian;
using bezoutian_test::patch_from_power;
using bezoutian_test::rational_patch_from_power;

namespace {

constexpr int threads = bezoutian_test::test_threads;

// Catch2's assertions are not thread-safe: the threads record what differs, the main thread reports it.
struct Differences {
  std::mutex mutex;
  std::vector<std::string> what;
  void add(const std::string& w) {
    std::lock_guard<std::mutex> lock(mutex);
    what.push_back(w);
  }
  void report() {
    for (const auto& w : what) FAIL_CHECK(w);
    CHECK(what.empty());
  }
};

using bezoutian_test::run_on_threads;

bool same_doubles(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

template <std::size_t N>
bool same_doubles(const std::array<double, N>& a, const std::array<double, N>& b) {
  for (std::size_t i = 0; i < N; ++i)
    if (!same_doubles(a[i], b[i])) return false;
  return true;
}

bool same_point(const Locus_point& x, const Locus_point& y) {
  bool enclosure = true;
  for (int i = 0; i < 2; ++i) enclosure = enclosure && same_doubles(x.partner_enclosure[i], y.partner_enclosure[i]);
  return same_doubles(x.projection, y.projection) && same_doubles(x.partner, y.partner) &&
         same_doubles(x.first, y.first) && same_doubles(x.second, y.second) && same_doubles(x.point_3d, y.point_3d) &&
         same_doubles(x.residual, y.residual) && x.lifted == y.lifted && x.genuine == y.genuine &&
         x.status_proved == y.status_proved && enclosure;
}

// The first difference between two loci (everything a user reads: topology, arcs, sheets, contacts with their
// exact ranges, edge lines, split points, isolated and pinch points, notes), or "" if none.
std::string difference(const Surface_locus& a, const Surface_locus& b) {
  if (a.topology_computed != b.topology_computed || a.topology_method != b.topology_method || a.note != b.note)
    return "topology method or note";
  if (a.equation_computed != b.equation_computed || a.equation.determinant != b.equation.determinant)
    return "implicit equation";
  if (a.topology.vertices.size() != b.topology.vertices.size() || a.topology.edges.size() != b.topology.edges.size())
    return "topology";
  if (a.arcs.size() != b.arcs.size()) return "number of arcs";
  for (std::size_t k = 0; k < a.arcs.size(); ++k) {
    const Locus_arc &x = a.arcs[k], &y = b.arcs[k];
    if (!same_doubles(x.undecided_fraction, y.undecided_fraction) ||
        !same_doubles(x.fibre_undecided_fraction, y.fibre_undecided_fraction))
      return "arc " + std::to_string(k) + ": undecided fractions";
    if (x.points.size() != y.points.size()) return "arc " + std::to_string(k) + ": number of points";
    for (std::size_t i = 0; i < x.points.size(); ++i)
      if (!same_point(x.points[i], y.points[i])) return "arc " + std::to_string(k) + ": point " + std::to_string(i);
    if (x.sheets.size() != y.sheets.size()) return "arc " + std::to_string(k) + ": number of sheets";
    for (std::size_t s = 0; s < x.sheets.size(); ++s) {
      if (x.sheets[s].first != y.sheets[s].first || x.sheets[s].points.size() != y.sheets[s].points.size() ||
          x.sheets[s].segment_distance_bounds != y.sheets[s].segment_distance_bounds)
        return "arc " + std::to_string(k) + ": sheet " + std::to_string(s);
      for (std::size_t i = 0; i < x.sheets[s].points.size(); ++i)
        if (!same_point(x.sheets[s].points[i], y.sheets[s].points[i]))
          return "arc " + std::to_string(k) + ": sheet " + std::to_string(s) + " point " + std::to_string(i);
    }
  }
  if (a.contacts.size() != b.contacts.size()) return "number of contacts";
  for (std::size_t k = 0; k < a.contacts.size(); ++k) {
    const Boundary_contact &x = a.contacts[k], &y = b.contacts[k];
    if (x.side_first != y.side_first || x.side_second != y.side_second || x.shared_curve != y.shared_curve ||
        x.first_0 != y.first_0 || x.first_1 != y.first_1 || x.second_0 != y.second_0 || x.second_1 != y.second_1 ||
        !same_doubles(x.point, y.point))
      return "contact " + std::to_string(k);
  }
  if (a.edge_lines.size() != b.edge_lines.size()) return "number of edge lines";
  for (std::size_t k = 0; k < a.edge_lines.size(); ++k) {
    const Locus_edge_line &x = a.edge_lines[k], &y = b.edge_lines[k];
    if (x.side != y.side || x.value != y.value || x.cause != y.cause || x.genuine != y.genuine ||
        x.status_proved != y.status_proved || x.description != y.description || x.points.size() != y.points.size())
      return "edge line " + std::to_string(k);
  }
  if (a.split_points.size() != b.split_points.size()) return "number of split points";
  for (std::size_t k = 0; k < a.split_points.size(); ++k) {
    const Locus_split_point &x = a.split_points[k], &y = b.split_points[k];
    if (x.arc != y.arc || x.index != y.index || x.point != y.point || x.coordinate != y.coordinate ||
        x.bound != y.bound || x.box != y.box)
      return "split point " + std::to_string(k);
  }
  if (a.isolated_points.size() != b.isolated_points.size()) return "number of isolated points";
  for (std::size_t k = 0; k < a.isolated_points.size(); ++k) {
    const auto &x = a.isolated_points[k].lift, &y = b.isolated_points[k].lift;
    if (x.proved != y.proved || x.partners.size() != y.partners.size() || x.reason != y.reason)
      return "isolated point " + std::to_string(k);
    for (std::size_t i = 0; i < x.partners.size(); ++i)
      if (x.partners[i].v != y.partners[i].v || x.partners[i].s != y.partners[i].s)
        return "isolated point " + std::to_string(k) + ": partner " + std::to_string(i);
  }
  if (a.pinch_points.size() != b.pinch_points.size() || a.pinch_points_complete != b.pinch_points_complete ||
      a.pinch_points_note != b.pinch_points_note)
    return "pinch points";
  for (std::size_t k = 0; k < a.pinch_points.size(); ++k)
    if (a.pinch_points[k].box != b.pinch_points[k].box || a.pinch_points[k].m != b.pinch_points[k].m)
      return "pinch point " + std::to_string(k);
  return "";
}

using Patch = Rational_bezier_patch<>;

// A small model with closed-form answers: the paraboloid z = u^2 + v^2 (0), the bent paraboloid
// (s + s^2, t, 1 - s^2 - t^2) (1), a patch glued to the paraboloid's side u = 1 ((1 + s, t, 1 + t^2 + s): a shared
// boundary curve) (2), and a rational bilinear patch (2u, 2v, 1) / (2 + uv) (3).
std::vector<Patch> small_model() {
  return {patch_from_power({"u", "v", "u^2 + v^2"}, 2, 2),
          patch_from_power({"u + u^2", "v", "1 - u^2 - v^2"}, 2, 2),
          patch_from_power({"1 + u", "v", "1 + v^2 + u"}, 1, 2),
          rational_patch_from_power({"2*u", "2*v", "1", "2 + u*v"}, 1, 1)};
}

}  // namespace

TEST_CASE("threads: independent surface problems on four threads give the single-thread answers",
          "[threads][surfaces]") {
  const std::vector<Patch> P = small_model();
  // the problems: every pair and every self-intersection of the model, and a Whitney-umbrella-like patch whose
  // double curve v = 0 (partner u -> -u) lies inside its box
  const Patch umbrella = patch_from_power({"u*v + v^2", "v", "u^2"}, 2, 2);
  Surface_intersection_options umbrella_options;
  umbrella_options.box = Parameter_box{Rational(-1, 2), Rational(1, 2), Rational(-1, 3), Rational(1, 3)};
  umbrella_options.partner_domain_unbounded = true;
  std::vector<std::function<Surface_locus()>> problems;
  for (std::size_t i = 0; i < P.size(); ++i)
    for (std::size_t j = i; j < P.size(); ++j)
      problems.push_back([&P, i, j] { return i == j ? self_intersection_locus(P[i]) : intersection_locus(P[i], P[j]); });
  problems.push_back([&] { return self_intersection_locus(umbrella, umbrella_options); });

  std::vector<Surface_locus> serial;
  for (const auto& f : problems) serial.push_back(f());

  // closed forms of the serial answers: Phi(u, v) = Psi(s, t) on the paraboloid pair means v = t, u = s + s^2 and
  // u^2 + v^2 = 1 - s^2 - t^2; the glued pair shares exactly the curve u = 1 / s = 0; the umbrella's double curve
  // has the partner (-u, 0)
  std::size_t genuine = 0;
  for (const auto& a : serial[1].arcs)
    for (const auto& q : a.points) {
      if (!q.genuine) continue;
      ++genuine;
      const double u = q.first[0], v = q.first[1], s = q.second[0], t = q.second[1];
      CHECK(v == Approx(t).margin(1e-7));
      CHECK(u == Approx(s + s * s).margin(1e-7));
      CHECK(u * u + v * v == Approx(1 - s * s - t * t).margin(1e-7));
    }
  CHECK(genuine > 20);
  std::size_t shared = 0;
  for (const auto& c : serial[2].contacts)
    if (c.shared_curve) {
      ++shared;
      CHECK(c.side_first == 1);   // u = 1
      CHECK(c.side_second == 3);  // s = 0
    }
  CHECK(shared == 1);
  bool double_curve = false;
  for (const auto& a : serial.back().arcs)
    for (const auto& q : a.points)
      if (q.genuine && std::fabs(q.projection[1]) < 1e-9 && std::fabs(q.projection[0]) > 0.05) {
        double_curve = true;
        CHECK(q.partner[0] == Approx(-2 * q.projection[0]).margin(1e-6));
      }
  CHECK(double_curve);

  // each problem twice on four threads (a problem may run on two threads at once, on the same shared patches)
  std::vector<Surface_locus> threaded(2 * problems.size());
  std::atomic<std::size_t> next{0};
  run_on_threads([&](int) {
    for (std::size_t k; (k = next.fetch_add(1)) < threaded.size();) threaded[k] = problems[k % problems.size()]();
  });
  for (std::size_t k = 0; k < threaded.size(); ++k) {
    INFO("problem " << k % problems.size() << ", run " << k / problems.size());
    CHECK(difference(serial[k % problems.size()], threaded[k]) == "");
  }

  // the model entry point on four threads against one
  Model_intersection_options o;
  o.threads = 1;
  const Model_intersection one = intersect_model(P, o);
  o.threads = threads;
  const Model_intersection four = intersect_model(P, o);
  REQUIRE(one.problems.size() == four.problems.size());
  CHECK(four.threads_used == unsigned(threads));
  for (std::size_t k = 0; k < one.problems.size(); ++k) {
    const Model_problem &p = one.problems[k], &q = four.problems[k];
    INFO("model problem " << p.first << ", " << p.second);
    CHECK(p.first == q.first);
    CHECK(p.second == q.second);
    CHECK(p.computed == q.computed);
    CHECK(p.error == q.error);
    CHECK(difference(p.locus, q.locus) == "");
  }
}

TEST_CASE("threads: one surface locus copied and read from four threads", "[threads][surfaces]") {
  const std::vector<Patch> P = small_model();
  // fresh results per round, so that the threads race on results nobody has read yet
  for (int round = 0; round < 2; ++round) {
    const Surface_locus glued = intersection_locus(P[0], P[2]);
    const Surface_locus crossing = intersection_locus(P[0], P[1]);
    const Surface_locus reference_glued = intersection_locus(P[0], P[2]);
    const Surface_locus reference_crossing = intersection_locus(P[0], P[1]);
    std::string why_reference;
    const bool certified_reference = locus_certified(crossing, &why_reference);
    Differences d;
    run_on_threads([&](int k) {
      // a copy, and reads of the shared original
      const Surface_locus copy = k % 2 ? glued : crossing;
      const Surface_locus& original = k % 2 ? glued : crossing;
      const Surface_locus& reference = k % 2 ? reference_glued : reference_crossing;
      const std::string diff = difference(copy, reference);
      if (!diff.empty()) d.add("thread " + std::to_string(k) + ": the copy differs: " + diff);
      const std::string diff_original = difference(original, reference);
      if (!diff_original.empty()) d.add("thread " + std::to_string(k) + ": the original differs: " + diff_original);
      std::string why;
      if (k % 2 == 0 && (locus_certified(original, &why) != certified_reference || why != why_reference))
        d.add("thread " + std::to_string(k) + ": locus_certified differs");
      for (const auto& a : original.arcs)
        for (const auto& s : a.sheets) (void)sheet_distance_bound(s);
      // the shared boundary curve u = 1 of the paraboloid is s = 0 of the glued patch, v = t from 0 to 1: its
      // exact range, compared and converted from every thread
      for (const auto& c : original.contacts) {
        if (!c.shared_curve) continue;
        const Algebraic_real lo = c.first_0 < c.first_1 ? c.first_0 : c.first_1;
        const Algebraic_real hi = c.first_0 < c.first_1 ? c.first_1 : c.first_0;
        if (lo != Algebraic_real(Rational(0)) || hi != Algebraic_real(Rational(1)) || lo.to_double() != 0 ||
            hi.to_double() != 1)
          d.add("thread " + std::to_string(k) + ": the shared curve's range is not [0, 1]");
      }
    });
    d.report();
  }
}
