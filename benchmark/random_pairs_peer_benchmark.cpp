// The random bicubic pairs of benchmark/surface_benchmark.cpp side by side with OpenCASCADE's GeomAPI_IntSS and
// SISL's s1859 + s1310, in one run (doc/benchmarks.md, "Random bicubic pairs").
//
// The patches are those of surface_benchmark.cpp: the same seed (std::mt19937 g(20261122)), random_patch and order
// of generation (cases (2,2), (3,2), (3,3) x polynomial, rational x self, pair x count, two patches drawn per
// problem), every earlier case's patches drawn and dropped; so "(3,3) polynomial pair #k" is the same two patches
// in both benchmarks when both run with the same count (the numbering depends on it).
//
// Ours: solve_model_problem (intersection_locus with surface_benchmark's options: CGAL's analysis up to total degree
// 16, certified lifting), certified as a model problem is (locus_certified). Our branches are the sheets of the
// locus's arcs that are more than one point of space (the pieces of chain_model_curves); our curves are those
// branches joined end to end (chain_model_curves on this one problem: a closed loop cut into arcs of D = 0 at its
// vertices is one closed curve, a curve that leaves a patch and comes back is several). A peer's count of curves is
// compared with our curves; where they differ the pair is listed with each peer curve's distance to ours and the
// share of each of our curves that the peer's curves cover, to tell a missed loop from a split or a spurious curve.
//
// Peers: bash benchmark/install-peers.sh. The CMake build defines BEZOUTIAN_WITH_OCCT / BEZOUTIAN_WITH_SISL and
// links them for this file when their headers are found.
// Run:   build/benchmark/random_pairs_peer_benchmark [problems per case=3]
#include "random_patches.h"

#include <bezoutian/intersection/Model_curves.h>
#include <bezoutian/topology/Cgal_curve_analysis.h>

#include "occt_peer.h"
#include "sisl_peer.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

using namespace bezoutian;

namespace {

using Patch = Rational_bezier_patch<>;
using Point = std::array<double, 3>;
using Polyline = std::vector<Point>;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> x) {
  if (x.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(x.begin(), x.end());
  const std::size_t n = x.size();
  return n % 2 ? x[n / 2] : (x[n / 2 - 1] + x[n / 2]) / 2;
}

double distance_to_segment(const Point& p, const Point& a, const Point& b) {
  Point d, e;
  double dd = 0, de = 0;
  for (int c = 0; c < 3; ++c) d[c] = b[c] - a[c], e[c] = p[c] - a[c], dd += d[c] * d[c], de += d[c] * e[c];
  const double t = dd > 0 ? std::clamp(de / dd, 0.0, 1.0) : 0.0;
  double s = 0;
  for (int c = 0; c < 3; ++c) s += (e[c] - t * d[c]) * (e[c] - t * d[c]);
  return std::sqrt(s);
}

// The distance from p to the nearest of the polylines, and that polyline's index.
std::pair<double, std::size_t> nearest(const Point& p, const std::vector<Polyline>& ls) {
  double best = std::numeric_limits<double>::infinity();
  std::size_t which = 0;
  for (std::size_t k = 0; k < ls.size(); ++k) {
    const Polyline& l = ls[k];
    for (std::size_t i = 0; i + 1 < l.size() || (i == 0 && l.size() == 1); ++i) {
      const double d = distance_to_segment(p, l[i], l.size() == 1 ? l[i] : l[i + 1]);
      if (d < best) best = d, which = k;
    }
  }
  return {best, which};
}

double length(const Polyline& l) {
  double s = 0;
  for (std::size_t i = 0; i + 1 < l.size(); ++i) s += distance_to_segment(l[i], l[i + 1], l[i + 1]);
  return s;
}

// A point within this distance of a peer curve counts as covered: the peers' curves are approximations (B-splines
// through their marching points), a few 1e-4 from ours on these pairs.
constexpr double covered = 1e-3;

std::string format(const char* f, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* f, ...) {
  char b[1024];
  va_list a;
  va_start(a, f);
  std::vsnprintf(b, sizeof b, f, a);
  va_end(a);
  return b;
}

struct Our_curve {
  Polyline points;
  bool closed = false;
  std::size_t proved = 0, traced = 0;  // traced points of its pieces, and those whose genuine status is proved
  std::array<Locus_point, 2> ends;      // its first and last traced points
};

// Where a peer's count differs from ours: the peer's isolated points and curves, each with its distance to our
// nearest curve; each of our curves (length, proved statuses, end parameters) with the share of it the peer covers.
std::string explain(const char* peer, const std::vector<Polyline>& theirs, const std::vector<Our_curve>& curves,
                    const std::vector<Point>& isolated = {}) {
  std::vector<Polyline> ours;
  for (const Our_curve& c : curves) ours.push_back(c.points);
  std::string out;
  for (std::size_t k = 0; k < isolated.size(); ++k) {
    const auto [d, w] = nearest(isolated[k], ours);
    out += format("    %s isolated point %zu: at %.2g from our curve %zu\n", peer, k + 1, d, w + 1);
  }
  for (std::size_t k = 0; k < theirs.size(); ++k) {
    std::vector<int> votes(ours.size(), 0);
    double far = 0;
    for (const Point& p : theirs[k]) {
      const auto [d, w] = nearest(p, ours);
      far = std::max(far, d);
      if (!ours.empty()) ++votes[w];
    }
    const auto top = std::max_element(votes.begin(), votes.end()) - votes.begin();
    out += format("    %s curve %zu (%zu points, length %.3g): %s %td, largest distance to ours %.2g\n", peer, k + 1,
                theirs[k].size(), length(theirs[k]), ours.empty() ? "no curve of ours" : "mostly along our curve",
                ours.empty() ? 0 : top + 1, far);
  }
  for (std::size_t j = 0; j < ours.size(); ++j) {
    std::size_t near = 0;
    for (const Point& p : ours[j]) near += nearest(p, theirs).first <= covered;
    out += format("    our curve %zu (%s, length %.3g, genuine status proved at %zu of its %zu traced points): %.0f %% "
                  "within %.0e of %s's curves\n",
                  j + 1, curves[j].closed ? "closed" : "open", length(ours[j]), curves[j].proved, curves[j].traced,
                  100.0 * double(near) / double(std::max<std::size_t>(1, ours[j].size())), covered, peer);
    for (const Locus_point& q : curves[j].ends)
      out += format("      end (u, v) = (%.4f, %.4f), (s, t) = (%.4f, %.4f)\n", q.first[0], q.first[1], q.second[0],
                    q.second[1]);
  }
  return out;
}

#ifdef BEZOUTIAN_WITH_SISL
// The curves of s1859 + s1310 in space, for the comparison only (sisl_peer::intersect is what is timed): a marched
// curve sampled at 401 parameters, an unmarched one as its guide points; and s1859's isolated points. Parameters are
// mapped to space by the first patch.
Point at(const Patch& a, double u, double v) {
  const auto x = a(Rational(u), Rational(v));
  return {CGAL::to_double(x[0]), CGAL::to_double(x[1]), CGAL::to_double(x[2])};
}

std::vector<Polyline> sisl_geometry(const Patch& a, SISLSurf* A, SISLSurf* B, std::vector<Point>& isolated) {
  std::vector<Polyline> out;
  int points = 0, curves = 0, status = 0;
  double *par1 = nullptr, *par2 = nullptr;
  SISLIntcurve** wcurve = nullptr;
  s1859(A, B, 0.0, 1e-7, &points, &par1, &par2, &curves, &wcurve, &status);
  for (int k = 0; k < points; ++k) isolated.push_back(at(a, par1[2 * k], par1[2 * k + 1]));
  for (int k = 0; k < curves; ++k) {
    int march = 0;
    s1310(A, B, wcurve[k], 1e-7, 0.0, 1, 0, &march);
    Polyline l;
    const SISLCurve* c = wcurve[k]->pgeom;
    if (march >= 0 && c != nullptr) {
      const double t0 = c->et[c->ik - 1], t1 = c->et[c->in];
      int left = 0, stat = 0;
      for (int i = 0; i <= 400; ++i) {
        double x[3];
        s1227(const_cast<SISLCurve*>(c), 0, t0 + (t1 - t0) * i / 400, &left, x, &stat);
        l.push_back({x[0], x[1], x[2]});
      }
    } else {
      for (int i = 0; i < wcurve[k]->ipoint; ++i)
        l.push_back(at(a, wcurve[k]->epar1[2 * i], wcurve[k]->epar1[2 * i + 1]));
    }
    out.push_back(l);
    freeIntcurve(wcurve[k]);
  }
  std::free(wcurve);
  std::free(par1);
  std::free(par2);
  return out;
}
#endif

struct Row {
  bool rational = false;
  int k = 0;
  double ours = 0, occt = 0, sisl = 0;
};

}  // namespace

int main(int argc, char** argv) {
  const int count = argc > 1 ? std::atoi(argv[1]) : 3;
  // surface_benchmark.cpp's sequence: keep the (3,3) pairs, drop the rest
  std::vector<std::pair<Patch, Patch>> pairs;
  std::vector<std::pair<bool, int>> names;  // rational, k
  std::mt19937 g(20261122);
  for (auto mn : std::vector<std::pair<int, int>>{{2, 2}, {3, 2}, {3, 3}})
    for (bool rational : {false, true})
      for (bool self : {true, false})
        for (int k = 0; k < count; ++k) {
          Patch a = random_patch(g, mn.first, mn.second, rational), b = random_patch(g, mn.first, mn.second, rational);
          if (mn == std::make_pair(3, 3) && !self) pairs.emplace_back(a, b), names.emplace_back(rational, k + 1);
        }

  Surface_intersection_options o;
  o.max_total_degree_for_topology = 16;  // as surface_benchmark.cpp
  o.whole_plane_topology = Cgal_curve_analysis{};
  o.certify_lifting = true;

  std::printf("| pair | our branches | our curves (closed) | certified | ours [s] |");
#ifdef BEZOUTIAN_WITH_OCCT
  std::printf(" OCCT curves | OCCT [s] | ours/OCCT |");
#endif
#ifdef BEZOUTIAN_WITH_SISL
  std::printf(" SISL points / curves / marched | SISL [s] | ours/SISL |");
#endif
  std::printf("\n|---|---|---|---|---|");
#ifdef BEZOUTIAN_WITH_OCCT
  std::printf("---|---|---|");
#endif
#ifdef BEZOUTIAN_WITH_SISL
  std::printf("---|---|---|");
#endif
  std::printf("\n");
  std::vector<Row> rows;
  std::vector<std::string> notes;  // per pair: D, certification, disagreements with their explanation
  int our_branches = 0, our_curves = 0, certified = 0;
  [[maybe_unused]] int occt_curves = 0, occt_failed = 0, sisl_curves = 0, sisl_unmarched = 0, sisl_failed = 0;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const std::vector<Patch> patches{pairs[i].first, pairs[i].second};
    Row row;
    row.rational = names[i].first;
    row.k = names[i].second;
    const std::string name = format("(3,3) %s pair #%d", row.rational ? "rational" : "polynomial", row.k);
    Model_intersection R;
    R.patches = 2;
    R.problems.resize(1);
    R.problems[0].first = 0;
    R.problems[0].second = 1;
    solve_model_problem(patches, R.problems[0], o);
    const Model_problem& p = R.problems[0];
    row.ours = p.seconds;
    const std::vector<Model_curve> curves = chain_model_curves(R);
    std::vector<Our_curve> ours;
    int branches = 0, closed = 0;
    for (const Model_curve& c : curves) {
      branches += int(c.pieces.size());
      closed += c.closed;
      Our_curve u;
      u.points = model_curve_points(R, c);
      u.closed = c.closed;
      for (const Model_curve_piece& piece : c.pieces)
        for (const Locus_point& q : p.locus.arcs[piece.arc].sheets[piece.sheet].points)
          ++u.traced, u.proved += q.status_proved;
      for (int e : {0, 1}) {
        const Model_curve_piece& piece = e == 0 ? c.pieces.front() : c.pieces.back();
        const auto& points = p.locus.arcs[piece.arc].sheets[piece.sheet].points;
        u.ends[std::size_t(e)] = (e == 0) != piece.reversed ? points.front() : points.back();
      }
      ours.push_back(u);
    }
    our_branches += branches;
    our_curves += int(curves.size());
    certified += p.certified;
    std::string line = format("| %s | %d | %zu (%d) | %s | %.2f |", name.c_str(), branches, curves.size(), closed,
                              p.computed ? (p.certified ? "yes" : "no") : "not computed", p.seconds);
    {
      std::size_t genuine = 0, proved = 0, points = 0;
      for (const auto& arc : p.locus.arcs)
        for (const auto& q : arc.points) ++points, proved += q.status_proved, genuine += q.genuine;
      notes.push_back(format("%s: D of total degree %d, %zu components, %zu singular points; status proved %zu/%zu, "
                             "genuine %zu; %s%s",
                             name.c_str(), p.computed ? p.locus.equation.total_degree() : -1,
                             p.locus.topology.components.size(), p.locus.topology.number_of_singular_points(), proved,
                             points, genuine, p.certified ? "certified" : "not certified: ",
                             p.certified ? "" : p.reason.c_str()));
    }
#ifdef BEZOUTIAN_WITH_OCCT
    {
      const auto A = occt_peer::surface(patches[0]), B = occt_peer::surface(patches[1]);
      const auto t = std::chrono::steady_clock::now();
      const occt_peer::Result r = occt_peer::intersect(A, B);
      row.occt = seconds_since(t);
      occt_failed += !r.done;
      occt_curves += r.curves;
      line += format(" %s | %.4f | %.0f |", r.done ? std::to_string(r.curves).c_str() : "failed", row.occt,
                     row.ours / row.occt);
      if (!r.done || r.curves != int(curves.size()))
        notes.push_back(format("  disagreement: OCCT %d curves%s, ours %zu\n", r.curves, r.done ? "" : " (failed)",
                               curves.size()) +
                        explain("OCCT", r.geometry, ours));
    }
#endif
#ifdef BEZOUTIAN_WITH_SISL
    {
      SISLSurf *A = sisl_peer::surface(patches[0]), *B = sisl_peer::surface(patches[1]);
      const auto t = std::chrono::steady_clock::now();
      const sisl_peer::Result r = sisl_peer::intersect(A, B);
      row.sisl = seconds_since(t);
      sisl_failed += !r.done;
      sisl_curves += r.curves;
      sisl_unmarched += r.curves - r.marched;
      line += format(" %d / %d / %d%s | %.4f | %.0f |", r.points, r.curves, r.marched, r.done ? "" : " (failed)",
                     row.sisl, row.ours / row.sisl);
      if (!r.done || r.curves != int(curves.size()) || r.marched != r.curves) {
        std::vector<Point> isolated;
        const std::vector<Polyline> geometry = sisl_geometry(patches[0], A, B, isolated);
        notes.push_back(format("  disagreement: SISL %d curves, %d marched%s, ours %zu\n", r.curves, r.marched,
                               r.done ? "" : " (failed)", curves.size()) +
                        explain("SISL", geometry, ours, isolated));
      }
      freeSurf(A);
      freeSurf(B);
    }
#endif
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
    rows.push_back(row);
  }

  std::printf("\n");
  for (const std::string& s : notes) std::printf("%s%s", s.c_str(), s.back() == '\n' ? "" : "\n");
  std::printf("\npairs: %zu; ours: %d branches, %d curves, %d pairs certified\n", rows.size(), our_branches, our_curves,
              certified);
#ifdef BEZOUTIAN_WITH_OCCT
  std::printf("OCCT GeomAPI_IntSS: %d curves, failed on %d pairs\n", occt_curves, occt_failed);
#endif
#ifdef BEZOUTIAN_WITH_SISL
  std::printf("SISL s1859 + s1310: %d curves, %d not marched, failed on %d pairs\n", sisl_curves, sisl_unmarched,
              sisl_failed);
#endif
  // totals and medians per kind and over all pairs; the medians of the ratios are those of the per-pair ratios
  for (int kind : {0, 1, 2}) {
    std::vector<double> ours, occt, sisl, r_occt, r_sisl;
    double t_ours = 0, t_occt = 0, t_sisl = 0;
    for (const Row& r : rows) {
      if (kind < 2 && r.rational != (kind == 1)) continue;
      ours.push_back(r.ours);
      t_ours += r.ours;
      occt.push_back(r.occt);
      t_occt += r.occt;
      sisl.push_back(r.sisl);
      t_sisl += r.sisl;
      if (r.occt > 0) r_occt.push_back(r.ours / r.occt);
      if (r.sisl > 0) r_sisl.push_back(r.ours / r.sisl);
    }
    std::printf("%-10s total: ours %.2f s", kind == 0 ? "polynomial" : kind == 1 ? "rational" : "all", t_ours);
#ifdef BEZOUTIAN_WITH_OCCT
    std::printf(", OCCT %.4f s (ratio %.0f)", t_occt, t_ours / t_occt);
#endif
#ifdef BEZOUTIAN_WITH_SISL
    std::printf(", SISL %.4f s (ratio %.0f)", t_sisl, t_ours / t_sisl);
#endif
    std::printf("; median: ours %.2f s", median(ours));
#ifdef BEZOUTIAN_WITH_OCCT
    std::printf(", OCCT %.4f s, ours/OCCT %.0f", median(occt), median(r_occt));
#endif
#ifdef BEZOUTIAN_WITH_SISL
    std::printf(", SISL %.4f s, ours/SISL %.0f", median(sisl), median(r_sisl));
#endif
    std::printf("\n");
  }
  return 0;
}
