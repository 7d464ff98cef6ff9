// Whole-model intersection: every pair of patches of a model whose bounding boxes meet, and every patch's
// self-intersection, each certified as intersection_locus / self_intersection_locus certify it, run on several
// threads with results identical to the serial run.
//
// Broad phase. A rational Bezier patch with positive weights lies in the convex hull of its control points (each
// point is a convex combination of them: the weights times the Bernstein polynomials, divided by their sum, are
// nonnegative and sum to 1), so in the box of its control points. Two patches whose boxes are disjoint have no
// common point: no elimination is needed, and the pair is not reported. The boxes are rounded outwards to doubles
// and compared as closed boxes (touching boxes, as at every seam of a model, are kept), by CGAL's
// box_intersection_d. A patch with a weight that is not positive has no such box: it is paired with every other.
//
// Parallel runs. The problems (pairs in increasing (i, j), then the self-intersections in increasing i) are taken
// from a shared counter by the worker threads; each result is written to its own slot, so the output does not
// depend on the number of threads or on the order in which problems finish. Independent problems share no mutable
// state (doc/hostile_input.md, "What is thread-safe"; test/core/surface_thread_safety_test.cpp runs surface problems
// and this function on four threads under ThreadSanitizer). Each problem has its own budget
// (Surface_intersection_options::limits); a problem that ends in an Error (a budget exceeded, input the single-pair
// functions refuse) is reported with that error's text, and the others go on. The curves of the model, joined
// across its seams, are in intersection/Model_curves.h.
#ifndef BEZOUTIAN_INTERSECTION_MODEL_INTERSECTION_H
#define BEZOUTIAN_INTERSECTION_MODEL_INTERSECTION_H

#include <bezoutian/arithmetic/double_interval.h>
#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>
#include <bezoutian/geometry/Weight_validity.h>
#include <bezoutian/intersection/Surface_intersection.h>

#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <exception>
#include <functional>
#include <limits>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace bezoutian {

/// Options of intersect_model.
struct Model_intersection_options {
  /// The options of every single problem (its `limits.time_limit` is a budget per problem).
  Surface_intersection_options surface;
  /// Worker threads; 0 means std::thread::hardware_concurrency().
  unsigned threads = 0;
  /// Whether each patch's self-intersection is computed too.
  bool self_intersections = true;
  /// Called after each problem, from the worker thread that finished it, under a lock (problems done, total); it
  /// must not throw (it runs outside the problem's error handling, on a worker thread).
  std::function<void(std::size_t, std::size_t)> progress;
};

/// One problem of a model: a pair of patches (first < second) or one patch's self-intersection (first == second).
struct Model_problem {
  std::size_t first = 0, second = 0;
  bool self() const { return first == second; }
  /// The locus was computed; otherwise `error` says why not (the text of the Error that ended it).
  bool computed = false;
  std::string error;
  Surface_locus locus;
  /// locus_certified(locus): everything the locus reports is proved; otherwise `reason` says what is not (or, if
  /// not computed, the error)
  bool certified = false;
  std::string reason;
  double seconds = 0;
};

/// The result of intersect_model.
struct Model_intersection {
  std::size_t patches = 0;
  /// Pairs of patches in all, and those whose control-point boxes meet (the only ones computed).
  std::size_t pairs = 0, pairs_with_meeting_boxes = 0;
  /// The problems in a fixed order: the pairs by increasing (first, second), then the self-intersections.
  std::vector<Model_problem> problems;
  /// Per patch, why it is refused (a weight that vanishes in its domain: check_no_pole), or empty. The problems of
  /// a refused patch are listed, not computed, with this reason; the others are solved as usual.
  std::vector<std::string> patch_errors;
  unsigned threads_used = 1;
  double seconds = 0;
};

namespace internal {

/// The box of a patch's control points, rounded outwards; false if a weight is not positive (no such box).
inline bool control_point_box(const Rational_bezier_patch<Rational>& p, double lo[3], double hi[3]) {
  for (int c = 0; c < 3; ++c) lo[c] = std::numeric_limits<double>::infinity(), hi[c] = -lo[c];
  for (int i = 0; i <= p.degree_u(); ++i)
    for (int j = 0; j <= p.degree_v(); ++j) {
      if (!(CGAL::sign(p.weight(std::size_t(i), std::size_t(j))) == CGAL::POSITIVE)) return false;
      const auto x = p.control_point(std::size_t(i), std::size_t(j));
      for (int c = 0; c < 3; ++c) {
        const Double_interval d = Double_interval::of(x[c]);
        lo[c] = std::min(lo[c], d.lo);
        hi[c] = std::max(hi[c], d.hi);
      }
    }
  return true;
}

/// The pairs (i < j) of patches whose control-point boxes meet (closed boxes), in increasing order.
inline std::vector<std::pair<std::size_t, std::size_t>> pairs_with_meeting_boxes(
    const std::vector<Rational_bezier_patch<Rational>>& patches) {
  using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 3, std::size_t, CGAL::Box_intersection_d::ID_EXPLICIT>;
  std::vector<Box> boxes;
  std::vector<std::size_t> unbounded;
  for (std::size_t k = 0; k < patches.size(); ++k) {
    double lo[3], hi[3];
    if (control_point_box(patches[k], lo, hi))
      boxes.push_back(Box(lo, hi, k));
    else
      unbounded.push_back(k);
  }
  std::vector<std::pair<std::size_t, std::size_t>> out;
  CGAL::box_self_intersection_d(
      boxes.begin(), boxes.end(),
      [&](const Box& a, const Box& b) { out.push_back({std::min(a.handle(), b.handle()), std::max(a.handle(), b.handle())}); },
      std::ptrdiff_t(10), CGAL::Box_intersection_d::CLOSED);
  for (std::size_t k : unbounded)
    for (std::size_t l = 0; l < patches.size(); ++l)
      if (l != k) out.push_back({std::min(k, l), std::max(k, l)});
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace internal

/// \brief The problems of a model, not yet solved: the pairs of patches whose control-point boxes meet, by
/// increasing (first, second), then (if `o.self_intersections`) every patch's self-intersection. A patch whose
/// weight vanishes in its domain (a pole; proved by check_no_pole) is refused: its problems are listed with the
/// reason in `error` and are not solved (such a patch has no control-point box, so it is paired with every other
/// patch: none of its intersections is known). intersect_model
/// solves them; a caller that hands them out itself (several processes, say) solves each with
/// solve_model_problem and gets the same results.
inline Model_intersection model_problems(const std::vector<Rational_bezier_patch<Rational>>& patches,
                                         const Model_intersection_options& o = {}) {
  Model_intersection out;
  out.patches = patches.size();
  out.pairs = patches.size() * (patches.size() - (patches.empty() ? 0 : 1)) / 2;
  out.patch_errors.assign(patches.size(), std::string());
  for (std::size_t k = 0; k < patches.size(); ++k) {
    try {
      check_no_pole(patches[k]);
    } catch (const Error& e) {
      out.patch_errors[k] = "patch " + std::to_string(k) + " is refused: " + e.what();
    }
  }
  auto add = [&](std::size_t first, std::size_t second) {
    Model_problem p;
    p.first = first;
    p.second = second;
    for (std::size_t k : {first, second})
      if (p.error.empty() && !out.patch_errors[k].empty()) p.error = p.reason = out.patch_errors[k];
    out.problems.push_back(std::move(p));
  };
  for (const auto& pr : internal::pairs_with_meeting_boxes(patches)) add(pr.first, pr.second);
  out.pairs_with_meeting_boxes = out.problems.size();
  if (o.self_intersections)
    for (std::size_t k = 0; k < patches.size(); ++k) add(k, k);
  return out;
}

/// \brief Solves one problem of model_problems: its locus (intersection_locus or self_intersection_locus with
/// `o`), whether it is certified, its time; an Error that ends it (its budget exceeded, input the single-pair
/// functions refuse) is caught and kept in `p.error`, as is any other exception (an internal error). A problem
/// that model_problems refused (its `error` set: a refused patch) is left as it is.
inline void solve_model_problem(const std::vector<Rational_bezier_patch<Rational>>& patches, Model_problem& p,
                                const Surface_intersection_options& o) {
  if (!p.error.empty()) return;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    p.locus = p.self() ? self_intersection_locus(patches[p.first], o)
                       : intersection_locus(patches[p.first], patches[p.second], o);
    p.computed = true;
    p.certified = locus_certified(p.locus, &p.reason);
  } catch (const Error& e) {
    p.error = p.reason = e.what();
  } catch (const std::exception& e) {  // (not the library's own: out of memory, an exception of CGAL's)
    p.error = p.reason = std::string("internal error: ") + e.what();
  }
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// \brief Every intersection of a model: the loci of the pairs of patches whose control-point boxes meet and (by
/// default) every patch's self-intersection locus, computed on `threads` worker threads. Each locus is the one
/// intersection_locus / self_intersection_locus return for that problem (with `o.surface`), whatever the number of
/// threads. See the header comment for the broad phase and for problems that end in an error.
inline Model_intersection intersect_model(const std::vector<Rational_bezier_patch<Rational>>& patches,
                                          const Model_intersection_options& o = {}) {
  const auto start = std::chrono::steady_clock::now();
  Model_intersection out = model_problems(patches, o);
  unsigned threads = o.threads ? o.threads : std::max(1u, std::thread::hardware_concurrency());
  threads = unsigned(std::max<std::size_t>(1, std::min<std::size_t>(threads, out.problems.size())));
  out.threads_used = threads;
  std::atomic<std::size_t> next{0};
  std::size_t done = 0;
  std::mutex progress_lock;
  auto work = [&]() {
    for (std::size_t k; (k = next.fetch_add(1)) < out.problems.size();) {
      solve_model_problem(patches, out.problems[k], o.surface);
      if (o.progress) {
        std::lock_guard<std::mutex> lock(progress_lock);
        o.progress(++done, out.problems.size());
      }
    }
  };
  if (threads == 1) {
    work();
  } else {
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t) pool.emplace_back(work);
    for (std::thread& t : pool) t.join();
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERSECTION_MODEL_INTERSECTION_H
