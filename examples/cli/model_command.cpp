// bezoutian model FILE: every intersection of a model (bezoutian::intersect_model): the pairs of patches whose
// control-point boxes meet and every patch's self-intersection, on several threads, as a summary (text) or with
// every locus (JSON).
#include "commands.h"
#include "load.h"
#include "locus_json.h"

#include <bezoutian/intersection/Model_intersection.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#if defined(__unix__)
#include <unistd.h>
#endif

namespace bezoutian_cli {
namespace {

struct Model_options {
  std::string file;
  unsigned threads = 0;
  double problem_time_limit = 0;
  double polyline_tolerance = 1e-3;
  bool no_self = false;
  bool json = false;
};

// What a problem found, in counts: arcs with genuine points, shared boundary curves, contact points, isolated
// contacts, overlap regions, and whether all of it is proved (bezoutian::locus_certified).
struct Problem_summary {
  std::size_t genuine_arcs = 0, shared_boundaries = 0, contact_points = 0, touching_points = 0, overlaps = 0,
              genuine_edge_lines = 0;
  bool certified = false;
  std::string reason;
};

Problem_summary summary(const bezoutian::Model_problem& p) {
  Problem_summary s;
  if (!p.computed) {
    s.reason = p.error;
    return s;
  }
  const auto& L = p.locus;
  for (const auto& a : L.arcs) {
    bool genuine = false;
    for (const auto& q : a.points) genuine = genuine || q.genuine;
    s.genuine_arcs += genuine;
  }
  for (const auto& c : L.contacts) (c.shared_curve ? s.shared_boundaries : s.contact_points) += 1;
  for (const auto& ip : L.isolated_points) s.touching_points += ip.genuine();
  for (const auto& e : L.edge_lines) s.genuine_edge_lines += e.genuine;
  s.overlaps = L.overlaps.size();
  s.certified = bezoutian::locus_certified(L, &s.reason);
  return s;
}

std::string problem_name(const bezoutian::Model_problem& p) {
  return p.self() ? "self " + std::to_string(p.first) : "pair " + std::to_string(p.first) + " " + std::to_string(p.second);
}

void run_model(const Model_options& o) {
  Loaded_file f = load_and_validate(o.file);
  if (f.doc.patches.empty())
    throw bezoutian::Invalid_input(o.file + ": expected patches (a model), found none (" +
                                   std::to_string(f.doc.curves_2.size() + f.doc.curves_3.size()) + " curve(s))");
  for (const auto& w : f.warnings) std::cerr << "warning: " << w << "\n";
  bezoutian::Model_intersection_options mo;
  mo.threads = o.threads;
  mo.self_intersections = !o.no_self;
  mo.surface.polyline_tolerance = o.polyline_tolerance;
  mo.surface.limits.time_limit = o.problem_time_limit;
#if defined(__unix__)
  const bool terminal = isatty(2);
#else
  const bool terminal = false;
#endif
  if (terminal)  // progress on stderr, only when it is a terminal
    mo.progress = [](std::size_t done, std::size_t total) {
      std::fprintf(stderr, "\rproblems done: %zu of %zu", done, total);
      if (done == total) std::fprintf(stderr, "\n");
    };
  const bezoutian::Model_intersection R = bezoutian::intersect_model(f.doc.patches, mo);
  std::size_t certified = 0, failed = 0;
  std::vector<Problem_summary> sums;
  for (const auto& p : R.problems) {
    sums.push_back(summary(p));
    certified += sums.back().certified;
    failed += !p.computed;
  }
  if (o.json) {
    nlohmann::json j;
    j["patches"] = R.patches;
    j["pairs"] = R.pairs;
    j["pairs_with_meeting_boxes"] = R.pairs_with_meeting_boxes;
    j["threads"] = R.threads_used;
    j["seconds"] = R.seconds;
    j["problems_certified"] = certified;
    nlohmann::json problems = nlohmann::json::array();
    for (std::size_t k = 0; k < R.problems.size(); ++k) {
      const auto& p = R.problems[k];
      const auto& s = sums[k];
      nlohmann::json jp{{"patches", {p.first, p.second}},    {"self", p.self()},
                        {"computed", p.computed},             {"certified", s.certified},
                        {"genuine_arcs", s.genuine_arcs},     {"shared_boundaries", s.shared_boundaries},
                        {"contact_points", s.contact_points}, {"touching_points", s.touching_points},
                        {"overlaps", s.overlaps},             {"genuine_edge_lines", s.genuine_edge_lines},
                        {"seconds", p.seconds}};
      if (!s.certified) jp["reason"] = s.reason;
      if (p.computed) jp["locus"] = locus_json(p.locus, p.seconds);
      problems.push_back(jp);
    }
    j["problems"] = problems;
    std::cout << j.dump(1) << "\n";
    return;
  }
  std::cout << R.patches << " patches; " << R.pairs_with_meeting_boxes << " of " << R.pairs
            << " pairs with meeting control-point boxes" << (o.no_self ? "" : ", and every self-intersection") << "; "
            << R.problems.size() << " problems on " << R.threads_used << " thread(s) in " << R.seconds << " s\n";
  for (std::size_t k = 0; k < R.problems.size(); ++k) {
    const auto& p = R.problems[k];
    const auto& s = sums[k];
    std::cout << problem_name(p) << ": ";
    if (!p.computed) {
      std::cout << "not computed: " << p.error << "\n";
      continue;
    }
    std::cout << s.genuine_arcs << " arc(s) with genuine points, " << s.shared_boundaries << " shared boundary curve(s), "
              << s.contact_points << " boundary contact point(s), " << s.touching_points << " touching point(s)";
    if (s.overlaps) std::cout << ", " << s.overlaps << " overlap region(s)";
    if (s.genuine_edge_lines) std::cout << ", " << s.genuine_edge_lines << " genuine edge line(s)";
    std::cout << (s.certified ? "; certified" : "; not certified: " + s.reason) << " (" << p.seconds << " s)\n";
  }
  std::cout << certified << " of " << R.problems.size() << " problems certified";
  if (failed) std::cout << ", " << failed << " not computed";
  std::cout << "\n";
}

Register model_registration([](CLI::App& app) {
  auto o = std::make_shared<Model_options>();
  auto* sub = app.add_subcommand("model", "Every intersection of a model: the pairs of patches whose boxes meet and "
                                          "every self-intersection, on several threads");
  sub->add_option("FILE", o->file, "model file (.bpt or .json with several patches)")->required();
  sub->add_option("--threads", o->threads, "worker threads (default 0: one per core)");
  sub->add_option("--problem-time-limit", o->problem_time_limit,
                  "budget of each problem in seconds; a problem over it is reported as not computed, with the stage "
                  "(default 0: none)");
  sub->add_option("--polyline-tolerance", o->polyline_tolerance,
                  "chord error of the lifted polylines, in 3D and in the parameter domains (default 1e-3)");
  sub->add_flag("--no-self", o->no_self, "skip the self-intersections");
  sub->add_flag("--json", o->json, "machine-readable output, with every locus");
  sub->callback([o] { run_model(*o); });
});

}  // namespace
}  // namespace bezoutian_cli
