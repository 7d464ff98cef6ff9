// Whole models side by side: intersect_model on one thread and on every core, OpenCASCADE's GeomAPI_IntSS and SISL's
// s1859 + s1310 on the same pairs of patches (those whose control-point boxes meet), in one run. Per pair: the
// branches we report (the pieces of the model's curves on it, chain_model_curves) and the shared boundary curves, whether our answer is certified,
// the curves each peer reports, and the times; then the totals, the ratios and the pairs where a peer's count of
// curves differs from ours (doc/benchmarks.md, "Whole models").
//
// Peers: bash benchmark/install-peers.sh (Debian libocct-*-dev, libsisl-dev; benchmark-only). The CMake build
// defines BEZOUTIAN_WITH_OCCT / BEZOUTIAN_WITH_SISL and links them for this file when their headers are found.
// Run:   build/benchmark/model_benchmark [MODEL_FILE]     (default ../shared/data/teapot/teapot32.bpt)
#include <bezoutian/intersection/Model_curves.h>
#include <bezoutian/io/Geometry_document.h>

#include "occt_peer.h"
#include "sisl_peer.h"

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

using namespace bezoutian;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Ours {
  int branches = 0, shared = 0;
  bool certified = false;
};

// The branches of problem k: the pieces of the model's curves on it (chain_model_curves: sheets that are more than
// one point of space), and its shared boundary curves.
Ours ours_of(const Model_intersection& R, const std::vector<Model_curve>& curves, std::size_t k) {
  Ours o;
  for (const Model_curve& c : curves)
    for (const Model_curve_piece& piece : c.pieces) o.branches += piece.problem == k;
  for (const auto& c : R.problems[k].locus.contacts) o.shared += c.shared_curve;
  o.certified = R.problems[k].certified;
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string file =
      argc > 1 ? argv[1] : std::string(BEZOUTIAN_SOURCE_DIR) + "/../shared/data/teapot/teapot32.bpt";
  const auto patches = io::read_geometry_file(file).patches;
  Model_intersection_options o;
  o.threads = 1;
  auto t0 = std::chrono::steady_clock::now();
  const Model_intersection one = intersect_model(patches, o);
  const double t_one = seconds_since(t0);
  o.threads = 0;
  t0 = std::chrono::steady_clock::now();
  const Model_intersection all = intersect_model(patches, o);
  const double t_all = seconds_since(t0);
  const std::vector<Model_curve> curves_one = chain_model_curves(one), curves_all = chain_model_curves(all);
  std::size_t differ = 0;
  for (std::size_t k = 0; k < one.problems.size(); ++k) {
    const Ours a = ours_of(one, curves_one, k), b = ours_of(all, curves_all, k);
    differ += a.branches != b.branches || a.shared != b.shared || a.certified != b.certified;
  }
  std::printf("%s: %zu patches, %zu pairs with meeting boxes, %zu problems\n", file.c_str(), one.patches,
              one.pairs_with_meeting_boxes, one.problems.size());
  std::size_t closed = 0;
  for (const Model_curve& c : curves_one) closed += c.closed;
  std::printf("ours: %.2f s on 1 thread, %.2f s on %u threads; problems whose answers differ between them: %zu; "
              "%zu curves of the model, %zu closed\n\n",
              t_one, t_all, all.threads_used, differ, curves_one.size(), closed);
  std::printf("| pair | our branches | shared boundaries | certified | ours [s] |");
#ifdef BEZOUTIAN_WITH_OCCT
  std::printf(" OCCT curves | OCCT [s] |");
#endif
#ifdef BEZOUTIAN_WITH_SISL
  std::printf(" SISL points / curves / marched | SISL [s] |");
#endif
  std::printf("\n|---|---|---|---|---|");
#ifdef BEZOUTIAN_WITH_OCCT
  std::printf("---|---|");
#endif
#ifdef BEZOUTIAN_WITH_SISL
  std::printf("---|---|");
#endif
  std::printf("\n");
  double ours_pairs = 0;
  [[maybe_unused]] double occt_total = 0, sisl_total = 0;
  int certified = 0, pairs = 0;
  [[maybe_unused]] int occt_fewer = 0, occt_more = 0, occt_failed = 0, sisl_fewer = 0, sisl_more = 0,
                       sisl_unmarched = 0, sisl_failed = 0;
  for (std::size_t k = 0; k < one.problems.size(); ++k) {
    const Model_problem& p = one.problems[k];
    if (p.self()) continue;
    ++pairs;
    const Ours u = ours_of(one, curves_one, k);
    certified += u.certified;
    ours_pairs += p.seconds;
    std::printf("| %zu %zu | %d | %d | %s | %.3f |", p.first, p.second, u.branches, u.shared,
                p.computed ? (u.certified ? "yes" : "no") : "not computed", p.seconds);
#ifdef BEZOUTIAN_WITH_OCCT
    {
      const auto A = occt_peer::surface(patches[p.first]), B = occt_peer::surface(patches[p.second]);
      const auto t = std::chrono::steady_clock::now();
      const occt_peer::Result r = occt_peer::intersect(A, B);
      const double s = seconds_since(t);
      occt_total += s;
      occt_failed += !r.done;
      // OpenCASCADE reports no curve for a shared boundary: compare with our branches
      occt_fewer += r.done && r.curves < u.branches;
      occt_more += r.done && r.curves > u.branches;
      std::printf(" %s | %.4f |", r.done ? std::to_string(r.curves).c_str() : "failed", s);
    }
#endif
#ifdef BEZOUTIAN_WITH_SISL
    {
      SISLSurf *A = sisl_peer::surface(patches[p.first]), *B = sisl_peer::surface(patches[p.second]);
      const auto t = std::chrono::steady_clock::now();
      const sisl_peer::Result r = sisl_peer::intersect(A, B);
      const double s = seconds_since(t);
      freeSurf(A);
      freeSurf(B);
      sisl_total += s;
      sisl_failed += !r.done;
      sisl_unmarched += r.curves - r.marched;
      // SISL reports shared boundaries as curves: compare with our branches and shared boundaries
      sisl_fewer += r.done && r.curves < u.branches + u.shared;
      sisl_more += r.done && r.curves > u.branches + u.shared;
      std::printf(" %d / %d / %d%s | %.4f |", r.points, r.curves, r.marched, r.done ? "" : " (failed)", s);
    }
#endif
    std::printf("\n");
  }
  std::printf("\npairs: %d, ours certified %d; ours %.2f s for the pairs on 1 thread (all %zu problems %.2f s on 1 "
              "thread, %.2f s on %u)\n",
              pairs, certified, ours_pairs, one.problems.size(), t_one, t_all, all.threads_used);
#ifdef BEZOUTIAN_WITH_OCCT
  std::printf("OCCT GeomAPI_IntSS: %.3f s for the pairs; ratio ours/OCCT %.0f (1 thread, pairs), %.0f (all threads, "
              "every problem); failed on %d; fewer curves than our branches on %d pairs, more on %d\n",
              occt_total, occt_total > 0 ? ours_pairs / occt_total : 0.0, occt_total > 0 ? t_all / occt_total : 0.0,
              occt_failed, occt_fewer, occt_more);
#endif
#ifdef BEZOUTIAN_WITH_SISL
  std::printf("SISL s1859 + s1310: %.3f s for the pairs; ratio ours/SISL %.0f (1 thread, pairs), %.0f (all threads, "
              "every problem); failed on %d; curves not marched %d; fewer curves than our branches and shared "
              "boundaries on %d pairs, more on %d\n",
              sisl_total, sisl_total > 0 ? ours_pairs / sisl_total : 0.0, sisl_total > 0 ? t_all / sisl_total : 0.0,
              sisl_failed, sisl_unmarched, sisl_fewer, sisl_more);
#endif
  return 0;
}
