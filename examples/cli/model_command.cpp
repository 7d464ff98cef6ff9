// bezoutian model FILE: every intersection of a model (bezoutian::intersect_model): the pairs of patches whose
// control-point boxes meet and every patch's self-intersection, on several threads or on MPI ranks
// (examples/cli/model_mpi.h), as a summary (text) or with every locus (JSON), and the curves of the model.
#include "commands.h"
#include "exact_json.h"
#include "load.h"
#include "model_mpi.h"
#include "model_pictures.h"

#include <bezoutian/intersection/Model_curves.h>
#include <bezoutian/intersection/Model_intersection.h>

#include <nlohmann/json.hpp>

#include <chrono>
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
  std::string obj, svg_dir;
};

std::string problem_name(const bezoutian::Model_problem& p) {
  return p.self() ? "self " + std::to_string(p.first) : "pair " + std::to_string(p.first) + " " + std::to_string(p.second);
}

nlohmann::json curve_json(const bezoutian::Model_intersection& R, const bezoutian::Model_curve& c) {
  nlohmann::json pieces = nlohmann::json::array();
  for (const auto& p : c.pieces) {
    const auto& mp = R.problems[p.problem];
    pieces.push_back({{"problem", p.problem},
                      {"patches", {mp.first, mp.second}},
                      {"arc", p.arc},
                      {"sheet", p.sheet},
                      {"reversed", p.reversed}});
  }
  nlohmann::json points = nlohmann::json::array();
  for (const auto& q : bezoutian::model_curve_points(R, c)) points.push_back(approx(q));
  return {{"closed", c.closed},
          {"pieces_certified", c.pieces_certified},
          {"largest_gap", approx(c.largest_gap)},
          {"links", c.links},
          {"links_proved", c.links_proved},
          {"pieces", pieces},
          {"points_3d", points}};
}

void run_model(const Model_options& o) {
  Loaded_file f = load_and_validate(o.file, false);  // (a patch with a pole: its problems are reported, see below)
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
  bezoutian::Model_intersection R;
  std::vector<Problem_summary> sums;
  std::string where;
  int ranks = 1;
  if (launched_as_mpi_ranks()) {
    R = bezoutian::model_problems(f.doc.patches, mo);
    const auto start = std::chrono::steady_clock::now();
    if (!solve_on_mpi_ranks(f.doc.patches, mo.surface, o.json, R, sums, ranks, mo.progress)) return;  // (a worker)
    R.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    where = std::to_string(ranks) + " MPI rank(s)";
  } else {
    R = bezoutian::intersect_model(f.doc.patches, mo);
    for (const auto& p : R.problems) sums.push_back(summarize(p, o.json));
    where = std::to_string(R.threads_used) + " thread(s)";
  }
  bezoutian::Model_curve_options curve_options;
  curve_options.patches = &f.doc.patches;  // (links at exact contact points are proved)
  const std::vector<bezoutian::Model_curve> curves = bezoutian::chain_model_curves(R, curve_options);
  if (!o.obj.empty()) write_model_obj(o.obj, f.doc.patches, R, curves);
  if (!o.svg_dir.empty()) write_model_svgs(o.svg_dir, R);
  std::size_t certified = 0, failed = 0;
  for (const auto& p : R.problems) {
    certified += p.certified;
    failed += !p.computed;
  }
  if (o.json) {
    nlohmann::json j = envelope("model");
    j["patches"] = R.patches;
    j["pairs"] = R.pairs;
    j["pairs_with_meeting_boxes"] = R.pairs_with_meeting_boxes;
    j["threads"] = R.threads_used;
    j["mpi_ranks"] = ranks;
    j["seconds"] = R.seconds;
    j["problems_certified"] = certified;
    nlohmann::json problems = nlohmann::json::array();
    for (std::size_t k = 0; k < R.problems.size(); ++k) {
      const auto& p = R.problems[k];
      const auto& s = sums[k];
      nlohmann::json jp{{"patches", {p.first, p.second}},    {"self", p.self()},
                        {"computed", p.computed},             {"certified", p.certified},
                        {"genuine_arcs", s.genuine_arcs},     {"shared_boundaries", s.shared_boundaries},
                        {"contact_points", s.contact_points}, {"touching_points", s.touching_points},
                        {"overlaps", s.overlaps},             {"genuine_edge_lines", s.genuine_edge_lines},
                        {"seconds", p.seconds}};
      if (!p.certified) jp["reason"] = p.reason;
      if (!p.computed) jp["error"] = p.error;
      if (p.computed) jp["locus"] = s.locus;
      problems.push_back(jp);
    }
    j["problems"] = problems;
    nlohmann::json jc = nlohmann::json::array();
    for (const auto& c : curves) jc.push_back(curve_json(R, c));
    j["curves"] = jc;
    std::cout << j.dump(1) << "\n";
    return;
  }
  std::cout << R.patches << " patches; " << R.pairs_with_meeting_boxes << " of " << R.pairs
            << " pairs with meeting control-point boxes" << (o.no_self ? "" : ", and every self-intersection") << "; "
            << R.problems.size() << " problems on " << where << " in " << R.seconds << " s\n";
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
    std::cout << (p.certified ? "; certified" : "; not certified: " + p.reason) << " (" << p.seconds << " s)\n";
  }
  std::size_t closed = 0;
  for (const auto& c : curves) closed += c.closed;
  std::cout << curves.size() << " curve(s) of the model, " << closed << " closed (branches joined across seams):\n";
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const auto& c = curves[k];
    std::cout << "curve " << k << ": " << (c.closed ? "closed" : "open") << ", " << c.pieces.size() << " piece(s):";
    for (const auto& p : c.pieces)
      std::cout << " " << problem_name(R.problems[p.problem]) << " arc " << p.arc << " sheet " << p.sheet
                << (p.reversed ? " reversed" : "") << ";";
    std::cout << (c.pieces_certified ? " every piece certified" : " not every piece certified");
    if (c.links)
      std::cout << ", " << c.links_proved << " of " << c.links << " link(s) proved exact, largest gap at a link "
                << c.largest_gap;
    std::cout << "\n";
  }
  std::cout << certified << " of " << R.problems.size() << " problems certified";
  if (failed) std::cout << ", " << failed << " not computed";
  std::cout << "\n";
}

Register model_registration([](CLI::App& app) {
  auto o = std::make_shared<Model_options>();
  auto* sub = app.add_subcommand("model", "Every intersection of a model: the pairs of patches whose boxes meet and "
                                          "every self-intersection, on several threads or MPI ranks, and the curves "
                                          "of the model joined across its seams");
  sub->add_option("FILE", o->file, "model file (.bpt or .json with several patches)")->required();
  sub->add_option("--threads", o->threads,
                  "worker threads (default 0: one per core); under mpirun -n K the K - 1 ranks other than rank 0 "
                  "solve one problem at a time each, and rank 0 hands them out");
  sub->add_option("--problem-time-limit", o->problem_time_limit,
                  "budget of each problem in seconds; a problem over it is reported as not computed, with the stage "
                  "(default 0: none)");
  sub->add_option("--polyline-tolerance", o->polyline_tolerance,
                  "chord error of the lifted polylines, in 3D and in the parameter domains (default 1e-3)");
  sub->add_flag("--no-self", o->no_self, "skip the self-intersections");
  sub->add_flag("--json", o->json, "machine-readable output, with every locus");
  sub->add_option("--obj", o->obj,
                  "write an OBJ file: the patch meshes, every branch grouped by pair of patches, the model's curves");
  sub->add_option("--svg-dir", o->svg_dir,
                  "write DIR/patch_K.svg for each patch with curves: its parameter square and the curves on it")
      ->check(CLI::ExistingDirectory);
  sub->callback([o] { run_model(*o); });
});

}  // namespace
}  // namespace bezoutian_cli
