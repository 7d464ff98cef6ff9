// Self-intersection locus of a rational Bezier patch and intersection curve of two patches:
// the implicit equation D of the projected locus (buse-elkadi-galligo-2008 Theorems 2-5), its certified
// topology in a parameter box (topology/Curve_topology_by_subdivision.h, and optionally CGAL's curve analysis,
// topology/Cgal_curve_analysis.h), and the lifting of every traced point to its
// partner parameters through the kernel of the Bezoutian matrix (§4: U is in the kernel of B^t, so the
// partner is a ratio of kernel entries).
//
// What is certified: D exactly; the components of D = 0 in the box, its singular points with their branch
// counts and its boundary points. The lifting of sample points to the partner parameters is computed in
// floating point (verified by the residual |Phi - Psi| at each point); the genuine / phantom status along the arcs
// of a subdivision topology is then proved where possible (lifting/certified_lifting.h: a partner enclosed in
// the partner domain by a parametric Krawczyk test, or every partner excluded), and each traced point says whether
// its status is proved (Locus_point::status_proved, Locus_arc::undecided_fraction).
#ifndef BEZOUTIAN_INTERSECTION_SURFACE_INTERSECTION_H
#define BEZOUTIAN_INTERSECTION_SURFACE_INTERSECTION_H

#include <bezoutian/intersection/Curve_intersection.h>
#include <bezoutian/arithmetic/simplest_rational.h>
#include <bezoutian/intersection/Patch_common_parent.h>
#include <bezoutian/intersection/Patch_common_projection.h>
#include <bezoutian/intersection/Patch_injectivity.h>
#include <bezoutian/intersection/Patch_separation.h>
#include <bezoutian/intersection/Surface_locus.h>
#include <bezoutian/topology/Curve_topology_by_subdivision.h>
#include <bezoutian/intersection/internal/box_edge_lines.h>
#include <bezoutian/lifting/certified_lifting.h>
#include <bezoutian/lifting/linear_partner_lines.h>
#include <bezoutian/lifting/double_partner_witness.h>
#include <bezoutian/lifting/floating_null_vector.h>
#include <bezoutian/topology/matrix_zero_points.h>
#include <bezoutian/lifting/partner_boundary_points.h>
#include <bezoutian/lifting/partner_domain_crossings.h>
#include <bezoutian/lifting/arc_refinement.h>
#include <bezoutian/lifting/partner_sheets.h>
#include <bezoutian/lifting/exact_line_fibres.h>
#include <bezoutian/lifting/pinch_points.h>
#include <bezoutian/lifting/polyline_distance_bounds.h>
#include <bezoutian/elimination/Implicit_equation.h>
#include <bezoutian/elimination/Maximal_minor_projection.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>

#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <limits>
#include <optional>
#include <memory>
#include <vector>

namespace bezoutian {

/// Options of the surface (self-)intersection computations.
struct Surface_intersection_options {
  /// Region of the projection plane ((u,v) for self-intersection, (u,t) for intersection) that is analysed.
  Parameter_box box;
  /// Domain of the partner parameters (the patches' parameter domain); `partner_domain_unbounded` ignores it.
  Parameter_box partner_domain;
  bool partner_domain_unbounded = false;
  /// Certified sample points per arc of D = 0 and the precision of their ordinates.
  int samples_per_arc = 24;
  double tolerance = 1e-9;
  Bezoutian_formula formula = Bezoutian_formula::automatic;
  /// The certified topology is first computed by Bernstein subdivision in the box (any degree,
  /// Curve_topology_by_subdivision.h). Where that does not certify, the whole-plane topology policy below is
  /// tried, whose cost explodes with the degree: above this total degree of D it is not attempted
  /// (Surface_locus::topology_computed == false) instead of running for hours. See doc/surface_intersection.md
  /// for measured times.
  int max_total_degree_for_topology = 16;
  /// Whole-plane topology of D = 0 in the box, tried where the subdivision does not certify: an opt-in policy,
  /// empty by default. `Cgal_curve_analysis` (topology/Cgal_curve_analysis.h) is CGAL's exact curve analysis;
  /// it brings CGAL's algebraic kernel into the translation unit and is not bounded in time.
  std::function<Curve_topology_in_box(const Polynomial_2<Integer>& D, const Parameter_box& box, double tolerance,
                                      int samples_per_arc)>
      whole_plane_topology;
  /// Limits of the subdivision.
  Subdivision_topology_options subdivision;
  /// Prove the genuine / phantom status along the arcs (lifting/certified_lifting.h; subdivision topologies
  /// only). It roughly doubles the time of a locus; off, the status is floating point only (status_proved false).
  bool certify_lifting = true;
  /// Complete lifting (lifting/partner_sheets.h): every partner of every traced point in the partner domain, as
  /// the sheets of each arc (Locus_arc::sheets), proved to be all of them where Locus_arc::fibre_undecided_fraction
  /// is 0. Off: the arcs carry one partner per point (the kernel's) and no sheets.
  bool complete_lifting = true;
  /// Adaptive refinement of the arcs that carry sheets (lifting/arc_refinement.h): a span is halved while the
  /// lifted curve strays from its chord by more than this at the span's midpoint, in 3D or in either parameter
  /// domain (a floating-point midpoint test, not a proved bound), and where a sheet begins or ends inside it; the
  /// arcs of two patches over one projection and the genuine box sides on D = 0 (edge lines) are refined by the
  /// same test. The default, 1e-3, draws patches of unit size without visible chords; 0 keeps the uniform samples
  /// of the topology (doc/surface_intersection.md, step 5, measures both).
  double polyline_tolerance = 1e-3;
  /// At most this many points added by the refinement per locus.
  std::size_t max_refinement_points = 20000;
  /// Prove a bound on the distance between each segment of every sheet's polylines and the curve it draws
  /// (Locus_sheet::segment_distance_bounds; lifting/polyline_distance_bounds.h): a few interval evaluations per
  /// segment (1.14 times the structured benchmark's time). The refinement's midpoint test aims at
  /// `polyline_tolerance`; these bounds are what is proved (up to about 10 times the tolerance on the structured
  /// benchmark, doc/surface_intersection.md §4f).
  bool prove_polyline_distance = true;
  /// With prove_polyline_distance: the refinement also halves a span while the interval bound of its chord exceeds
  /// `polyline_tolerance` (by at most 16 times: beyond, next to a fold, it is left as is), so that the proved
  /// bounds meet the tolerance. 1.3 to 3.3 times the points on the structured benchmark; the finer spans need more of
  /// the exclusion budget (`lifting_exclusion_budget`), whose exhaustion leaves statuses undecided.
  bool refine_to_proved_distance = false;
  /// At most this many traced points per locus get their complete fibre (every partner, about 1 ms each on
  /// bicubic pairs): the arcs where the kernel's partner alone is not proved to be every partner, in order, while
  /// the count lasts; the others keep Locus_arc::fibre_undecided_fraction > 0.
  std::size_t max_complete_fibres = 2000;
  /// At most this many exclusion tests (each up to 1024 partner pieces) for the phantom proofs of one locus, and as
  /// many again for the fallback on spans without a followed partner (lifting/certified_lifting.h), and four times as
  /// many for the half-branches proved beside others (lifting/internal/beside_half_branches.h); the spans
  /// left when it is spent stay undecided (status_proved false). Bounds the cost on large phantom loci
  /// (doc/surface_intersection.md, step 4b, gives the measured trade-off).
  std::size_t lifting_exclusion_budget = 5000;
  /// Direct proofs tried before any elimination, when the box and the partner domain lie in [0,1]^2: a
  /// self-intersection is empty when the patch is proved injective (intersection/Patch_injectivity.h: a height
  /// field, a sphere octant, most patches of a model), an intersection when the patches are proved apart
  /// (intersection/Patch_separation.h). The locus then has no implicit equation (Surface_locus::equation_computed
  /// false) and its topology, proved empty but for the sides a patch collapses to a point, names the proof.
  bool direct_proofs = true;
  /// Self-intersection: search the pinch points of the patch in the box (lifting/pinch_points.h), with at most
  /// this many subdivision boxes (0: no search). Above it the search says it is incomplete.
  std::size_t pinch_point_boxes = 600000;
  /// Size limits of each patch, checked before anything (Limit_exceeded naming the limit): max_control_points,
  /// max_degree (in u and in v), max_coefficient_bits; max_degree_product is not used here. And the wall-clock
  /// budget `time_limit` (default 0: none), checked between the stages (direct proofs, elimination, pinch points,
  /// topology, lifting, split points, certified lifting, complete lifting) and before each arc of the two proved
  /// lifting stages: Budget_exceeded names the stage; the others may overrun it (the whole-plane topology policy,
  /// when opted in, is not bounded).
  Intersection_limits limits;
};

namespace internal {

/// The size limits of Surface_intersection_options::limits for one patch (`what` names it in the message).
inline void check_patch_limits(const char* function, const std::string& what, const Rational_bezier_patch<Rational>& p,
                               const Intersection_limits& l) {
  check_size_limits(function, what, {p.degree_u(), p.degree_v()}, long(p.degree_u() + 1) * long(p.degree_v() + 1), l);
  if (l.max_coefficient_bits <= 0) return;
  long bits = 0;
  for (int i = 0; i <= p.degree_u(); ++i)
    for (int j = 0; j <= p.degree_v(); ++j)
      for (const Rational& x : p.homogeneous_control_point(std::size_t(i), std::size_t(j)))
        bits = std::max(bits, rational_bits(x));
  check_coefficient_bits(function, what, bits, l);
}

// Floating-point evaluation of a rational bivariate polynomial (inner variable x, outer y).
inline double evaluate_double(const Polynomial_2<Rational>& p, double x, double y) {
  double r = 0;
  for (int j = p.degree(); j >= 0; --j) {
    double c = 0;
    for (int i = p[j].degree(); i >= 0; --i) c = c * x + CGAL::to_double(p[j][i]);
    r = r * y + c;
  }
  return r;
}

// Ratio x^(i+1,j) / x^(i,j) (direction 0) or x^(i,j+1) / x^(i,j) (direction 1) of a kernel vector indexed
// by monomials, using the pair with the largest denominator for stability.
inline bool monomial_ratio(const std::vector<std::pair<int, int>>& mono, const std::vector<long double>& x,
                           int direction, long double& out) {
  long double best = 0;
  bool found = false;
  for (std::size_t a = 0; a < mono.size(); ++a)
    for (std::size_t b = 0; b < mono.size(); ++b) {
      const bool next = direction == 0 ? (mono[b].first == mono[a].first + 1 && mono[b].second == mono[a].second)
                                       : (mono[b].second == mono[a].second + 1 && mono[b].first == mono[a].first);
      if (next && std::fabs(x[a]) > best) best = std::fabs(x[a]), out = x[b] / x[a], found = true;
    }
  return found;
}

inline bool inside(const Parameter_box& d, const std::array<double, 2>& p, double slack = 1e-9) {
  return CGAL::to_double(d.u0) - slack <= p[0] && p[0] <= CGAL::to_double(d.u1) + slack &&
         CGAL::to_double(d.v0) - slack <= p[1] && p[1] <= CGAL::to_double(d.v1) + slack;
}

// Gauss-Newton polishing of the partner parameters (a, b) of a traced point: minimizes |r(a,b)| with
// r : R^2 -> R^3 (three coordinate equations, two unknowns); the Jacobian by central differences.
template <class R>
std::array<double, 2> polish_partner(R r, std::array<double, 2> x, int iterations = 16) {
  auto norm = [](const std::array<double, 3>& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); };
  std::array<double, 3> f = r(x[0], x[1]);
  for (int it = 0; it < iterations; ++it) {
    const double h = 1e-7;
    std::array<std::array<double, 3>, 2> J;
    for (int c = 0; c < 2; ++c) {
      std::array<double, 2> p = x, m = x;
      p[c] += h, m[c] -= h;
      auto fp = r(p[0], p[1]), fm = r(m[0], m[1]);
      for (int k = 0; k < 3; ++k) J[c][k] = (fp[k] - fm[k]) / (2 * h);
    }
    // normal equations J^T J d = -J^T f
    double a11 = 0, a12 = 0, a22 = 0, b1 = 0, b2 = 0;
    for (int k = 0; k < 3; ++k) {
      a11 += J[0][k] * J[0][k], a12 += J[0][k] * J[1][k], a22 += J[1][k] * J[1][k];
      b1 -= J[0][k] * f[k], b2 -= J[1][k] * f[k];
    }
    const double det = a11 * a22 - a12 * a12;
    if (!(std::fabs(det) > 0)) break;
    // damped step: halve it until the residual decreases (a full Gauss-Newton step overshoots far from the root)
    const std::array<double, 2> d = {(b1 * a22 - b2 * a12) / det, (a11 * b2 - a12 * b1) / det};
    bool improved = false;
    for (double lambda = 1; lambda > 1e-3 && !improved; lambda *= 0.5) {
      const std::array<double, 2> y = {x[0] + lambda * d[0], x[1] + lambda * d[1]};
      const auto fy = r(y[0], y[1]);
      if (norm(fy) < norm(f)) x = y, f = fy, improved = true;
    }
    if (!improved) break;
  }
  return x;
}

// When the kernel does not determine the partner (a ratio 0/0, e.g. k = 0 on a pinch curve), the best
// point of a grid over `range` (excluding the trivial partner (0,0)) seeds the polishing.
template <class R>
std::array<double, 2> grid_seed(R r, const std::array<double, 4>& range) {
  std::array<double, 2> best{std::numeric_limits<double>::quiet_NaN(), 0};
  double bv = std::numeric_limits<double>::infinity();
  const int N = 40;
  for (int i = 0; i <= N; ++i)
    for (int j = 0; j <= N; ++j) {
      const double a = range[0] + (range[1] - range[0]) * i / N, b = range[2] + (range[3] - range[2]) * j / N;
      if (std::fabs(a) + std::fabs(b) < 1e-3) continue;
      auto f = r(a, b);
      const double v = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
      if (v < bv) bv = v, best = {a, b};
    }
  return best;
}

// A polished partner that does not solve the equations (the kernel can point to a wrong partner where it has
// dimension > 1) is replaced by the best polished grid seed over the partner range, if that is better.
template <class R>
std::array<double, 2> search_if_unsolved(R residual, std::array<double, 2> x, const std::array<double, 4>& range,
                                         bool exclude_trivial) {
  auto size = [&](const std::array<double, 2>& y) {
    const auto f = residual(y[0], y[1]);
    return std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
  };
  if (size(x) <= 1e-9) return x;
  const auto seed = grid_seed(residual, range);
  if (!std::isfinite(seed[0])) return x;
  const auto alt = polish_partner(residual, seed);
  if (exclude_trivial && std::fabs(alt[0]) + std::fabs(alt[1]) <= 1e-9) return x;
  return size(alt) < size(x) ? alt : x;
}

// A lifted point counts only if its two preimages really map to the same 3D point (floating-point check
// after polishing): a failed polish must not be reported as a double point.
inline bool verified(const Locus_point& q) {
  const double scale = 1 + std::sqrt(q.point_3d[0] * q.point_3d[0] + q.point_3d[1] * q.point_3d[1] +
                                     q.point_3d[2] * q.point_3d[2]);
  return q.lifted && std::isfinite(q.residual) && q.residual <= 1e-7 * scale;
}

// Lifts every traced point with `lift_point(u, v, guess)`: the kernel gives the partner at regular points;
// at a singular vertex the kernel has dimension > 1 and each arc continues its own partner from its
// neighbouring point (three branches through a triple point have three partners there).
template <class F>
void lift_arcs(Surface_locus& L, F lift_point) {
  for (const auto& e : L.topology.edges) {
    Locus_arc arc;
    arc.source = e.source;
    arc.target = e.target;
    for (const auto& p : e.polyline) arc.points.push_back(lift_point(p[0], p[1], nullptr));
    const std::size_t n = arc.points.size();
    const bool singular_ends[2] = {L.topology.vertices[e.source].kind != Curve_topology_vertex::regular,
                                   L.topology.vertices[e.target].kind != Curve_topology_vertex::regular};
    if (n >= 2 && singular_ends[0] && arc.points[1].lifted)
      arc.points[0] = lift_point(e.polyline[0][0], e.polyline[0][1], &arc.points[1].partner);
    if (n >= 2 && singular_ends[1] && arc.points[n - 2].lifted)
      arc.points[n - 1] = lift_point(e.polyline[n - 1][0], e.polyline[n - 1][1], &arc.points[n - 2].partner);
    // Continuation: a point whose own lift does not solve the equations is lifted again from a neighbour's partner
    // with a smaller residual, both ways along the arc, and keeps the better one. Next to a seam the kernel of B is
    // nearly two-dimensional (the two patches nearly coincide there), its ratio can be far off (1e16 on teapot
    // handle 12 x 13), and the grid seed covers the partner domain only.
    auto residual_of = [](const Locus_point& q) { return std::isfinite(q.residual) ? q.residual : HUGE_VAL; };
    auto relift = [&](std::size_t i, std::size_t from) {
      if (verified(arc.points[i]) || !arc.points[from].lifted || !(residual_of(arc.points[from]) < residual_of(arc.points[i])))
        return;
      const Locus_point q = lift_point(e.polyline[i][0], e.polyline[i][1], &arc.points[from].partner);
      if (residual_of(q) < residual_of(arc.points[i])) arc.points[i] = q;
    };
    for (std::size_t i = 1; i < n; ++i) relift(i, i - 1);
    for (std::size_t i = n - 1; i-- > 0;) relift(i, i + 1);
    L.arcs.push_back(arc);
  }
}

inline std::vector<std::vector<long double>> evaluate_matrix(const Bezoutian_matrix& B, double x, double y) {
  std::vector<std::vector<long double>> A(B.size(), std::vector<long double>(B.size()));
  for (std::size_t i = 0; i < B.size(); ++i)
    for (std::size_t j = 0; j < B.size(); ++j) A[i][j] = evaluate_double(B.entries[i][j], x, y);
  return A;
}

// The same values as evaluate_matrix, with the coefficients converted to double once: the floating-point lifting
// evaluates B at every traced point, and converting a gmpq costs a division (a quarter of the lifting's time on
// a rational bicubic self-intersection).
class Double_bezoutian_matrix {
 public:
  explicit Double_bezoutian_matrix(const Bezoutian_matrix& B) : n_(B.size()), entries_(n_ * n_) {
    for (std::size_t i = 0; i < n_; ++i)
      for (std::size_t j = 0; j < n_; ++j) {
        const Polynomial_2<Rational>& p = B.entries[i][j];
        std::vector<std::vector<double>>& c = entries_[i * n_ + j];
        c.resize(std::size_t(std::max(0, p.degree() + 1)));
        for (int b = 0; b <= p.degree(); ++b)
          for (int a = 0; a <= p[b].degree(); ++a) c[std::size_t(b)].push_back(CGAL::to_double(p[b][a]));
      }
  }
  std::vector<std::vector<long double>> operator()(double x, double y) const {
    std::vector<std::vector<long double>> A(n_, std::vector<long double>(n_));
    for (std::size_t i = 0; i < n_; ++i)
      for (std::size_t j = 0; j < n_; ++j) {
        const std::vector<std::vector<double>>& c = entries_[i * n_ + j];
        double r = 0;  // Horner in y over Horner in x, as evaluate_double
        for (std::size_t b = c.size(); b-- > 0;) {
          double t = 0;
          for (std::size_t a = c[b].size(); a-- > 0;) t = t * x + c[b][a];
          r = r * y + t;
        }
        A[i][j] = r;
      }
    return A;
  }

 private:
  std::size_t n_;
  std::vector<std::vector<std::vector<double>>> entries_;  // entry (i, j): coefficients [power of y][power of x]
};

inline std::vector<std::vector<long double>> transpose(const std::vector<std::vector<long double>>& A) {
  std::vector<std::vector<long double>> T(A.size(), std::vector<long double>(A.size()));
  for (std::size_t i = 0; i < A.size(); ++i)
    for (std::size_t j = 0; j < A.size(); ++j) T[j][i] = A[i][j];
  return T;
}

inline double distance3(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// Computes the topology of the square-free D in the box unless D is constant (no locus: proved empty) or its
// degree is above the limit; returns whether lifting should follow.
// `proved_line(vertical, c)`: whether a rational line inside the box on D = 0 is proved genuine at every point;
// such lines are reported with the sides (interior edge lines) and removed from D as they are.
inline bool topology_is_affordable(Surface_locus& L, const Surface_intersection_options& o,
                                   const std::function<bool(bool, const Rational&)>& proved_line = {}) {
  // the box's sides on D = 0 are reported apart (edge_lines); the subdivision cannot follow a curve along its edge
  const Box_edge_lines lines = box_edge_lines(L.equation.square_free, o.box);
  for (int side : lines.sides) {
    Locus_edge_line e;
    e.side = side;
    e.value = side_value(o.box, side);
    L.edge_lines.push_back(e);
  }
  Polynomial_2<Integer> D = lines.rest;
  if (proved_line)
    for (const Interior_line& line : interior_lines(D, o.box)) {
      if (!proved_line(line.vertical, line.value)) continue;
      Locus_edge_line e;
      e.side = line.vertical ? 3 : 0;
      e.value = line.value;
      e.interior = true;
      L.edge_lines.push_back(e);
      D = without_line(D, line.vertical, line.value);
    }
  L.topology.box = o.box;
  if (D.degree() <= 0 && D[0].degree() <= 0) {
    L.topology_computed = true;  // D is a nonzero constant: the locus is empty, proved
    return false;
  }
  int total = -1;
  for (int j = 0; j <= D.degree(); ++j)
    if (!CGAL::is_zero(D[j])) total = std::max(total, j + D[j].degree());
  Subdivision_topology_options so = o.subdivision;
  // (common zeros of the entries are points of multiplicity >= N of det B, not of a gcd of minors)
  if (so.multiple_points.empty() && L.equation.route == Implicit_equation::Route::determinant)
    so.multiple_points = matrix_zero_points(L.equation, o.box);
  const Subdivision_topology_result sub = subdivide_curve_in_box(D, o.box, so);
  if (sub.certified) {
    L.topology = sub.topology;
    L.topology_computed = true;
    L.topology_method = "subdivision";
    return true;
  }
  if (total > o.max_total_degree_for_topology) {
    L.note = "the certified topology of D = 0 (total degree " + std::to_string(total) +
             ") was not computed: the subdivision did not certify it (" + sub.reason +
             ") and CGAL's whole-plane curve analysis is not attempted above max_total_degree_for_topology = " +
             std::to_string(o.max_total_degree_for_topology) + "; the implicit equation D is exact";
    return false;
  }
  if (!o.whole_plane_topology) {
    L.note = "the certified topology of D = 0 (total degree " + std::to_string(total) +
             ") was not computed: the subdivision did not certify it (" + sub.reason +
             ") and no whole-plane topology policy is set (Surface_intersection_options::whole_plane_topology, e.g. "
             "Cgal_curve_analysis); the implicit equation D is exact";
    return false;
  }
  try {
    L.topology = o.whole_plane_topology(D, o.box, o.tolerance, o.samples_per_arc);
  } catch (const Error&) {
    throw;
  } catch (...) {  // CGAL's analysis signals degenerate input by exceptions of its own (e.g. Zero_resultant_exception)
    L.note = "the certified topology of D = 0 was not computed: the subdivision did not certify it (" + sub.reason +
             ") and CGAL's curve analysis failed on it; the implicit equation D is exact";
    return false;
  }
  L.topology_computed = true;
  L.topology_method = "curve analysis";
  if (L.note.empty()) L.note = "subdivision: " + sub.reason + "; topology by CGAL's curve analysis";
  return true;
}

// The geometric proofs used by the subdivision (lifting/double_partner_witness.h): nodes and isolated points of
// D = 0 proved by two partners, and regions without any partner in the partner domain left out. Hooks set by the
// caller are kept.
inline Surface_intersection_options with_partner_proofs(const Surface_intersection_options& o,
                                                        const Partner_equations& eq) {
  Surface_intersection_options ow = o;
  if (!ow.subdivision.singular_point_witness)
    ow.subdivision.singular_point_witness = [eq](const Parameter_box& b, const std::array<double, 2>& x) {
      return prove_double_partner_point(eq, b, x);
    };
  if (!o.partner_domain_unbounded && !ow.subdivision.no_genuine_points) {
    const Parameter_box domain = o.partner_domain;
    ow.subdivision.no_genuine_points = Genuine_point_exclusion(eq, domain);
  }
  return ow;
}


// The parameter in [0,1] of the point of C nearest to X (floating point: it only places a traced point).
inline double nearest_parameter(const Rational_bezier_curve_3<Rational>& C, const std::array<double, 3>& X) {
  auto d2 = [&](double t) {
    const auto p = C.evaluate(t);
    return (p[0] - X[0]) * (p[0] - X[0]) + (p[1] - X[1]) * (p[1] - X[1]) + (p[2] - X[2]) * (p[2] - X[2]);
  };
  const int n = 256;
  int best = 0;
  for (int i = 1; i <= n; ++i)
    if (d2(double(i) / n) < d2(double(best) / n)) best = i;
  double a = std::max(0.0, double(best - 1) / n), b = std::min(1.0, double(best + 1) / n);
  for (int it = 0; it < 60; ++it) {  // golden section on the bracket
    const double m1 = b - (b - a) * 0.6180339887498949, m2 = a + (b - a) * 0.6180339887498949;
    if (d2(m1) < d2(m2)) b = m2; else a = m1;
  }
  return 0.5 * (a + b);
}

// The point (u, v) of a box side on D = 0 whose cause makes every point genuine (collapsed, shared_curve), with
// its pair: the partner's iso-curve M gives one point exactly, the nearest point of the side's own iso-curve C the
// other (for a collapsed C, its far end). Genuine and proved; the partner itself is floating point.
inline Locus_point edge_line_point(const Edge_line_explanation& x, int side, const Surface_intersection_options& o,
                                   const Rational_bezier_patch<Rational>& phi,
                                   const Rational_bezier_patch<Rational>* psi, double u, double v) {
  const Parameter_box& d = o.partner_domain;
  const bool vertical = side_is_vertical(side);
  const double c = vertical ? u : v, f = vertical ? v : u;
  const double f0 = CGAL::to_double(vertical ? o.box.v0 : o.box.u0), f1 = CGAL::to_double(vertical ? o.box.v1 : o.box.u1);
  const double tau = f1 > f0 ? (f - f0) / (f1 - f0) : 0;
  const bool own_point = is_point_curve(x.own);
  // the pair (P on C, Q on M): C is the side's own iso-curve over the partner domain, M the partner's at the
  // fixed coordinate cp; for a collapsed C paired with itself (partner_side -1) Q is the sample's own point
  const double o0 = CGAL::to_double(vertical ? d.v0 : d.u0), o1 = CGAL::to_double(vertical ? d.v1 : d.u1);
  const double cp = CGAL::to_double(x.partner_value);
  const double sigma = own_point ? (std::fabs(f - o0) > std::fabs(f - o1) ? 0.0 : 1.0)
                                 : nearest_parameter(x.own, x.other.evaluate(tau));
  const double g = o0 + sigma * (o1 - o0);  // the free coordinate of P on C
  Locus_point q;
  q.projection = {u, v};
  q.lifted = true;
  if (psi) {  // intersection: first (u, v) on phi, second (s, t) on psi
    q.first = vertical ? std::array<double, 2>{c, g} : std::array<double, 2>{u, cp};
    q.second = vertical ? std::array<double, 2>{cp, v} : std::array<double, 2>{g, c};
    q.partner = {q.first[1], q.second[0]};
    q.point_3d = phi.evaluate(q.first[0], q.first[1]);
    q.residual = distance3(q.point_3d, psi->evaluate(q.second[0], q.second[1]));
  } else {  // self-intersection: first (u, v + k), second (u + l, v)
    q.first = vertical ? std::array<double, 2>{c, g} : std::array<double, 2>{u, cp};
    q.second = vertical ? std::array<double, 2>{cp, v} : std::array<double, 2>{g, c};
    q.partner = {q.second[0] - u, q.first[1] - v};
    q.point_3d = phi.evaluate(q.second[0], q.second[1]);
    q.residual = distance3(phi.evaluate(q.first[0], q.first[1]), q.point_3d);
  }
  q.genuine = q.status_proved = true;
  return q;
}

// Candidates c' for the fixed coordinate of a partner iso-curve on the box side (explain_edge_line): the partner
// coordinate (s for a side u = c, v for t = c) of a floating-point partner at the side's midpoint, rounded to the
// simplest rational within 1e-9. Intersections only (the exact test decides).
inline std::vector<Rational> edge_line_partner_candidates(int side, const Parameter_box& box,
                                                         const Surface_intersection_options& o,
                                                         const Rational_bezier_patch<Rational>& phi,
                                                         const Rational_bezier_patch<Rational>* psi) {
  if (!psi || o.partner_domain_unbounded) return {};
  const bool vertical = side_is_vertical(side);
  const double c = CGAL::to_double(side_value(box, side));
  const double f = CGAL::to_double(vertical ? (box.v0 + box.v1) / 2 : (box.u0 + box.u1) / 2);
  const double u = vertical ? c : f, t = vertical ? f : c;
  auto residual = [&](double v, double s) {
    const auto a = phi.evaluate(u, v), b = psi->evaluate(s, t);
    return std::array<double, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  };
  const Parameter_box& d = o.partner_domain;
  const auto seed = grid_seed(residual, {CGAL::to_double(d.v0), CGAL::to_double(d.v1), CGAL::to_double(d.u0),
                                         CGAL::to_double(d.u1)});
  if (!std::isfinite(seed[0])) return {};
  const auto vs = polish_partner(residual, seed);
  const double x = vertical ? vs[1] : vs[0], w = 1e-9 * (1 + std::fabs(x));
  Rational r;
  if (!simplest_rational_in(Rational(x - w), Rational(x + w), r)) return {};
  return {r};
}

// Every point of the line is genuine (collapsed, shared_curve, partner_iso_curve)
inline bool is_genuine_cause(Edge_line_explanation::Cause c) {
  return c == Edge_line_explanation::collapsed || c == Edge_line_explanation::shared_curve ||
         c == Edge_line_explanation::partner_iso_curve;
}

// The explanation of an edge line (a side of the box, or an interior line as a side of box_from_line).
inline Edge_line_explanation explain(const Locus_edge_line& e, const Surface_intersection_options& o,
                                     const Rational_bezier_patch<Rational>& phi,
                                     const Rational_bezier_patch<Rational>* psi) {
  const Parameter_box b = e.interior ? box_from_line(o.box, side_is_vertical(e.side), e.value) : o.box;
  return explain_edge_line(e.side, b, o.partner_domain, o.partner_domain_unbounded, phi, psi,
                           [&] { return edge_line_partner_candidates(e.side, b, o, phi, psi); });
}

// Whether the interior line x = c or y = c is proved genuine at every point (topology_is_affordable)
inline bool interior_line_is_genuine(bool vertical, const Rational& c, const Surface_intersection_options& o,
                                     const Rational_bezier_patch<Rational>& phi,
                                     const Rational_bezier_patch<Rational>* psi) {
  Locus_edge_line e;
  e.side = vertical ? 3 : 0;
  e.value = c;
  e.interior = true;
  return is_genuine_cause(explain(e, o, phi, psi).cause);
}

// Samples of a curve f -> point(f), f in [f0, f1]: n + 1 uniform ones, then every span halved while the point at
// its midpoint is farther than `tolerance` from the chord, in 3D or in either parameter domain (the midpoint test of
// adaptive sampling, a floating-point estimate, not a bound), with at most `max_points` points added; tolerance 0:
// the uniform samples.
template <class Point_at>
std::vector<Locus_point> adaptive_samples(double f0, double f1, int n, double tolerance, std::size_t max_points,
                                          Point_at point_at) {
  std::vector<std::pair<double, Locus_point>> s;
  for (int i = 0; i <= n; ++i) {
    const double f = f0 + (f1 - f0) * double(i) / n;
    s.emplace_back(f, point_at(f));
  }
  auto misses = [&](const Locus_point& a, const Locus_point& b, const Locus_point& m) {
    double d3 = 0, dp = 0, dq = 0;
    for (int c = 0; c < 3; ++c) d3 += std::pow(m.point_3d[c] - 0.5 * (a.point_3d[c] + b.point_3d[c]), 2);
    for (int c = 0; c < 2; ++c) {
      dp += std::pow(m.first[c] - 0.5 * (a.first[c] + b.first[c]), 2);
      dq += std::pow(m.second[c] - 0.5 * (a.second[c] + b.second[c]), 2);
    }
    return !(std::sqrt(std::max({d3, dp, dq})) <= tolerance);
  };
  std::size_t added = 0;
  for (std::size_t i = 0; tolerance > 0 && i + 1 < s.size() && added < max_points;) {
    const double f = 0.5 * (s[i].first + s[i + 1].first);
    if (f <= s[i].first || f >= s[i + 1].first) {  // no double between them
      ++i;
      continue;
    }
    Locus_point m = point_at(f);
    if (misses(s[i].second, s[i + 1].second, m)) {
      s.insert(s.begin() + std::ptrdiff_t(i + 1), {f, std::move(m)});
      ++added;
    } else {
      ++i;
    }
  }
  std::vector<Locus_point> out;
  for (auto& x : s) out.push_back(std::move(x.second));
  return out;
}

// The box's sides on D = 0 (found by topology_is_affordable): their cause (intersection/internal/box_edge_lines.h) and sample
// points. For a proved cause the pair of each sample is taken from it: the partner's iso-curve M gives one point
// exactly, the nearest point of the side's own iso-curve C the other (for a collapsed C, its far end).
template <class Lift>
void describe_edge_lines(Surface_locus& L, const Surface_intersection_options& o,
                         const Rational_bezier_patch<Rational>& phi, const Rational_bezier_patch<Rational>* psi,
                         Lift lift_point) {
  const Parameter_box& b = o.box;
  const Parameter_box& d = o.partner_domain;
  const char* names[2][4] = {{"v", "u", "v", "u"}, {"t", "u", "t", "u"}};
  for (Locus_edge_line& e : L.edge_lines) {
    const Edge_line_explanation x = explain(e, o, phi, psi);
    const bool vertical = side_is_vertical(e.side);
    e.cause = Locus_edge_line::Cause(int(x.cause));
    e.partner_side = x.partner_side;
    e.partner_value = x.partner_value;
    e.genuine = is_genuine_cause(x.cause);
    e.status_proved = x.cause != Edge_line_explanation::unexplained;
    const std::string line = std::string(e.interior ? "line " : "side ") + names[psi ? 1 : 0][e.side] + " = " +
                             std::to_string(CGAL::to_double(e.value));
    switch (x.cause) {
      case Edge_line_explanation::collapsed:
        e.description = "the " + line + " lies on D = 0: a collapsed edge (one 3D point), genuine";
        break;
      case Edge_line_explanation::shared_curve:
        // the partner's side: of the second patch (s = c') for a side u = c, of the first (v = c') for t = c
        e.description = "the " + line + " lies on D = 0: a boundary curve shared with the side " +
                        (psi ? (vertical ? "s" : "v") : (vertical ? "u" : "v")) + " = " +
                        std::to_string(CGAL::to_double(side_value(d, x.partner_side))) +
                        (psi ? (vertical ? " of the second patch" : " of the first patch") : "") + ", genuine";
        break;
      case Edge_line_explanation::partner_iso_curve:
        e.description = "the " + line + " lies on D = 0: the iso-curve " + (vertical ? "s" : "v") + " = " +
                        io::to_exact_string(x.partner_value) + " of the " + (vertical ? "second" : "first") +
                        " patch lies on it (a common curve), genuine";
        break;
      case Edge_line_explanation::point_off_partner:
        e.description = "the " + line + " lies on D = 0: its iso-curve is one point, off the " +
                        (vertical ? "second" : "first") + " patch (proved): phantom";
        break;
      case Edge_line_explanation::curve_off_partner:
        e.description = "the " + line + " lies on D = 0: its iso-curve meets the " + (vertical ? "second" : "first") +
                        " patch nowhere (proved): phantom";
        break;
      case Edge_line_explanation::outside_domain:
        e.description = "the " + line + " lies on D = 0, outside the partner domain: phantom";
        break;
      default:
        e.description = "the " + line + " lies on D = 0; its status is not proved";
    }
    const int n = std::max(1, o.samples_per_arc);
    const double c = CGAL::to_double(e.value);
    const double f0 = CGAL::to_double(vertical ? b.v0 : b.u0), f1 = CGAL::to_double(vertical ? b.v1 : b.u1);
    if (e.genuine) {  // the side's image and its partner curve, to the polyline tolerance
      e.points = adaptive_samples(f0, f1, n, o.polyline_tolerance, o.max_refinement_points, [&](double f) {
        return edge_line_point(x, e.side, o, phi, psi, vertical ? c : f, vertical ? f : c);
      });
      continue;
    }
    for (int i = 0; i <= n; ++i) {
      const double tau = double(i) / n, f = f0 + tau * (f1 - f0);
      Locus_point q = lift_point(vertical ? c : f, vertical ? f : c, nullptr);
      if (e.status_proved) q.genuine = false, q.status_proved = true;  // outside the domain: phantom, proved
      e.points.push_back(q);
    }
  }
}

// The ends of the arcs that lie exactly on a box side on D = 0 whose cause is proved (a singular point of D where
// the rest of D meets a seam or a collapsed edge, a boundary point there): the point lies on that side, so its
// status is the side's, proved (genuine: a partner on the partner's iso-curve, which replaces the traced one,
// since at a singular point the branches have different partners; phantom: the side's coordinate lies outside
// the partner domain). The vertex enclosures are rationals rounded outward, so lo == hi == the side's value
// holds only for a point exactly on the side.
inline void mark_ends_on_edge_lines(Surface_locus& L, const Surface_intersection_options& o,
                                    const Rational_bezier_patch<Rational>& phi,
                                    const Rational_bezier_patch<Rational>* psi) {
  for (const Locus_edge_line& e : L.edge_lines) {
    if (!e.status_proved) continue;
    const bool vertical = side_is_vertical(e.side);
    std::optional<Edge_line_explanation> x;  // computed on first use (exact, a few curves)
    for (std::size_t k = 0; k < L.arcs.size() && k < L.topology.edges.size(); ++k) {
      auto& pts = L.arcs[k].points;
      if (pts.empty()) continue;
      const Curve_topology_edge& edge = L.topology.edges[k];
      for (const bool last : {false, true}) {  // (by position: a loop's source and target may be one vertex)
        const std::size_t end = last ? edge.target : edge.source;
        if (end >= L.topology.vertices.size()) continue;
        const Curve_topology_vertex& w = L.topology.vertices[end];
        const double lo = vertical ? w.u_lo : w.v_lo, hi = vertical ? w.u_hi : w.v_hi;
        if (!(lo == hi && Rational(lo) == e.value)) continue;
        Locus_point& q = last ? pts.back() : pts.front();
        if (!e.genuine) {
          q.genuine = false;
          q.status_proved = true;
          continue;
        }
        if (!x) x = explain(e, o, phi, psi);
        q = edge_line_point(*x, e.side, o, phi, psi, vertical ? CGAL::to_double(e.value) : q.projection[0],
                            vertical ? q.projection[1] : CGAL::to_double(e.value));
        // the partner's enclosure: on the partner's iso-curve at cp, its free coordinate somewhere in the partner
        // domain's range (edge_line_point: Q on M, the pair's coordinates (g, cp) or (cp, g); offsets for a
        // self-intersection), rounded outward
        using D = Double_interval;
        const D cp = D::of(x->partner_value);
        const D free = vertical ? D::hull(o.partner_domain.v0, o.partner_domain.v1)
                                : D::hull(o.partner_domain.u0, o.partner_domain.u1);
        auto minus = [](const D& a, double b) { return D{D::next(a.lo - b, false), D::next(a.hi - b, true)}; };
        std::array<D, 2> y = vertical ? std::array<D, 2>{free, cp} : std::array<D, 2>{cp, free};
        if (!psi)
          y = vertical ? std::array<D, 2>{minus(cp, q.projection[0]), minus(free, q.projection[1])}
                       : std::array<D, 2>{minus(free, q.projection[0]), minus(cp, q.projection[1])};
        q.partner_enclosure = {{{y[0].lo, y[0].hi}, {y[1].lo, y[1].hi}}};
      }
    }
  }
}

// The certified crossing that a split point reports (its side and proved box).
inline Partner_domain_crossing crossing_of(const Locus_split_point& sp) {
  Partner_domain_crossing c;
  c.side = {sp.point, sp.coordinate, sp.bound};
  for (int d = 0; d < 4; ++d) c.box[d] = Double_interval{sp.box[d][0], sp.box[d][1]};
  return c;
}

inline std::array<std::array<Rational, 2>, 4> refine_split_point(const Partner_equations& eq, const Locus_split_point& sp,
                                                                  int bits) {
  if (bits < 1 || bits > 100000) throw Invalid_input("refine_split_point: bits must be in [1, 100000]");
  const auto r = refine_crossing(eq, crossing_of(sp), bits);
  if (!r) throw Error("refine_split_point: the refinement of the split point's box failed");
  return *r;
}

// Inserts the certified split points (lifting/partner_domain_crossings.h) into the arcs of a subdivision topology:
// between consecutive traced points whose floating-point statuses differ, the crossing of a side of the partner
// domain is isolated and, if proved, becomes a traced point (and a polyline point of the topology's edge, with
// the pieces' index ranges shifted) and a Locus_split_point.
// Arc points whose partner lies exactly on the partner domain's boundary where the crossing test cannot decide (a
// corner, a touch; lifting/partner_boundary_points.h): genuine, proved. One between two traced points becomes a
// traced point (and a polyline point); where the floating-point statuses on its two sides differ the genuine part
// ends there, and it is a Locus_split_point.
template <class Lift>
void insert_boundary_points(Surface_locus& L, std::size_t k, const Partner_equations& eq,
                          const Surface_intersection_options& o, Lift lift_point) {
  Locus_arc& arc = L.arcs[k];
  Curve_topology_edge& e = L.topology.edges[k];
  auto exact_box = [](const Rational& q) {
    const Double_interval d = Double_interval::of(q);
    return std::array<double, 2>{d.lo, d.hi};
  };
  std::vector<std::array<Rational, 2>> seen;
  for (std::size_t i = 0; i < arc.points.size(); ++i) {
    const Locus_point& p = arc.points[i];
    if (!verified(p)) continue;
    const auto c = exact_boundary_point(eq, o.partner_domain, p.projection, p.partner);
    if (!c || std::find(seen.begin(), seen.end(), c->x) != seen.end()) continue;
    bool known = false;  // a certified split point already holds it
    for (const Locus_split_point& sp : L.split_points)
      known = known || (sp.arc == k && Rational(sp.box[0][0]) <= c->x[0] && c->x[0] <= Rational(sp.box[0][1]) &&
                        Rational(sp.box[1][0]) <= c->x[1] && c->x[1] <= Rational(sp.box[1][1]));
    if (known) continue;
    const Curve_topology_piece* pc = nullptr;
    for (const auto& x : e.pieces)
      if (x.graph_axis >= 0 && x.first <= i && i <= x.last && x.cell.u0 <= c->x[0] && c->x[0] <= x.cell.u1 &&
          x.cell.v0 <= c->x[1] && c->x[1] <= x.cell.v1)
        pc = &x;
    if (!pc) continue;  // (the point of D = 0 in the cell, where D = 0 is a graph, is the arc's)
    const int axis = pc->graph_axis;
    const Rational t = c->x[std::size_t(axis)];
    auto at = [&](std::size_t j) { return Rational(e.polyline[j][std::size_t(axis)]); };
    // the traced point itself, or a new point after `where`
    const bool at_point = at(i) == t && Rational(e.polyline[i][std::size_t(1 - axis)]) == c->x[std::size_t(1 - axis)];
    const bool after = !at_point && i < pc->last && (at(i) - t) * (at(i + 1) - t) < 0;
    const bool before = !at_point && !after && i > pc->first && (at(i - 1) - t) * (at(i) - t) < 0;
    if (!at_point && !after && !before) continue;
    seen.push_back(c->x);
    const bool insert = !at_point;
    const std::size_t where = before ? i - 1 : i;
    const std::array<double, 2> y{CGAL::to_double(c->y[0]), CGAL::to_double(c->y[1])};
    Locus_point q = lift_point(CGAL::to_double(c->x[0]), CGAL::to_double(c->x[1]), &y);
    q.genuine = q.status_proved = true;
    q.partner_enclosure = {exact_box(c->y[0]), exact_box(c->y[1])};
    if (!insert) {
      arc.points[i] = q;
      continue;
    }
    const bool ends_genuine_part = arc.points[where].genuine != arc.points[where + 1].genuine;
    arc.points.insert(arc.points.begin() + std::ptrdiff_t(where + 1), q);
    e.polyline.insert(e.polyline.begin() + std::ptrdiff_t(where + 1), q.projection);
    for (auto& x : e.pieces) {
      if (x.first > where) ++x.first;
      if (x.last > where) ++x.last;
    }
    for (Locus_split_point& sp : L.split_points)
      if (sp.arc == k && sp.index > where) ++sp.index;
    if (ends_genuine_part) {
      Locus_split_point sp;
      sp.arc = k;
      sp.index = where + 1;
      const bool on_v = c->y[0] == o.partner_domain.v0 || c->y[0] == o.partner_domain.v1;
      sp.point = on_v ? 0 : 1;  // P = (u, v) reaches a side v = const, or Q = (s, t) a side s = const
      sp.coordinate = on_v ? 1 : 0;
      sp.bound = on_v ? c->y[0] : c->y[1];
      sp.box = {exact_box(c->x[0]), exact_box(c->x[1]), exact_box(c->y[0]), exact_box(c->y[1])};
      L.split_points.push_back(sp);
    }
    ++i;  // (the inserted point)
  }
}

template <class Lift>
void insert_split_points(Surface_locus& L, const Partner_equations& eq, const Surface_intersection_options& o,
                         Lift lift_point) {
  if (L.topology_method != "subdivision" || o.partner_domain_unbounded) return;
  const std::vector<Partner_domain_side> sides = partner_domain_sides(o.partner_domain, o.box);
  for (std::size_t k = 0; k < L.arcs.size() && k < L.topology.edges.size(); ++k) {
    Locus_arc& arc = L.arcs[k];
    Curve_topology_edge& e = L.topology.edges[k];
    if (arc.points.size() != e.polyline.size()) continue;
    // On a double line of a self-intersection the kernel of B can be spanned by the trivial partner y = 0 at every
    // point (an extruded loop: the kernel vector is (l, k) = (0, 0) all along the line), so no change of status
    // shows where the partner leaves the domain. Such points are lifted again from a nontrivial real partner of
    // their fibre (the domain widened by a quarter, fibre_partners), preferring one inside the domain.
    if (eq.self_intersection())
      for (std::size_t i = 0; i < arc.points.size(); ++i) {
        const Locus_point& p = arc.points[i];
        if (std::fabs(p.partner[0]) + std::fabs(p.partner[1]) > 1e-9) continue;
        const std::array<double, 2>* seed = nullptr;
        const auto F = fibre_partners(eq, o.partner_domain, o.partner_domain_unbounded, e.polyline[i], nullptr);
        for (const auto& y : F) {
          if (std::fabs(y[0]) + std::fabs(y[1]) <= 1e-9) continue;
          if (!seed || partner_in_domain(eq, o.partner_domain, false, e.polyline[i], y, 1e-12)) seed = &y;
        }
        if (!seed) continue;
        const Locus_point q = lift_point(e.polyline[i][0], e.polyline[i][1], seed);
        if (verified(q) && std::fabs(q.partner[0]) + std::fabs(q.partner[1]) > 1e-9) arc.points[i] = q;
      }
    std::vector<std::pair<std::size_t, Partner_domain_crossing>> found;
    for (std::size_t i = 0; i + 1 < arc.points.size(); ++i) {
      const Locus_point &p = arc.points[i], &q = arc.points[i + 1];
      if (p.genuine == q.genuine || !verified(p) || !verified(q)) continue;
      const Curve_topology_piece* pc = nullptr;
      for (const auto& x : e.pieces)
        if (x.graph_axis >= 0 && x.first <= i && i + 1 <= x.last) pc = &x;
      if (!pc) continue;
      const std::array<double, 4> za{p.projection[0], p.projection[1], p.partner[0], p.partner[1]},
          zb{q.projection[0], q.projection[1], q.partner[0], q.partner[1]};
      if (auto c = crossing_between(eq, o.partner_domain, sides, za, zb, pc->cell, pc->graph_axis))
        found.emplace_back(i, *c);
    }
    for (auto it = found.rbegin(); it != found.rend(); ++it) {  // from the back: earlier indices stay valid
      const std::size_t i = it->first;
      const auto& Z = it->second.box;
      const std::array<double, 2> y{Z[2].mid(), Z[3].mid()};
      Locus_point q = lift_point(Z[0].mid(), Z[1].mid(), &y);
      q.genuine = q.status_proved = true;
      q.partner_enclosure = {{{Z[2].lo, Z[2].hi}, {Z[3].lo, Z[3].hi}}};
      arc.points.insert(arc.points.begin() + i + 1, q);
      e.polyline.insert(e.polyline.begin() + i + 1, std::array<double, 2>{Z[0].mid(), Z[1].mid()});
      for (auto& x : e.pieces) {
        if (x.first > i) ++x.first;
        if (x.last > i) ++x.last;
      }
    }
    for (std::size_t j = 0; j < found.size(); ++j) {
      const auto& c = found[j].second;
      Locus_split_point sp;
      sp.arc = k;
      sp.index = found[j].first + 1 + j;
      sp.point = c.side.point;
      sp.coordinate = c.side.coordinate;
      sp.bound = c.side.bound;
      for (int d = 0; d < 4; ++d) sp.box[d] = {c.box[d].lo, c.box[d].hi};
      L.split_points.push_back(sp);
    }
    insert_boundary_points(L, k, eq, o, lift_point);
  }
}

// Arcs of D = 0 (two patches, their own domains) that end on a side of the box exactly where the partner reaches a
// side of the partner domain: the intersection curve leaves both patches at one point, a common point of a boundary
// curve of each (a Boundary_contact point, exact), as where the curve meets a seam of a model at a crossing of two
// seams. With the box side u = c the partner crosses s = c' (the contact on the first patch's side u = c and the
// second's side s = c'), with the box side t = c it crosses v = c'. The contact z* = (u*, t*, v*, s*) solves the
// partner equations with g(z) = (partner coordinate) - c' = 0; Krawczyk's test around it (isolate_crossing) proves
// it the only zero of F = (E, g) in a box Z holding its enclosure, with F' regular there (a transversal crossing).
// D vanishes at (u*, t*) (a common point of the patches), and so does the topology's curve when no factor of D was
// removed through it (no edge line through it, not a corner of the box). The arc's end vertex is a root of that
// curve on the side too; when the square-free D restricted to the side has exactly one root in the hull of the
// vertex box and the contact's enclosure (counted exactly), the two are that root: the arc ends at z*. The end
// becomes a Locus_split_point: its status is the
// contact's own (genuine: both parameter points in the closed domains), and the span next to it is decided by the
// side of the line g = 0 the partner is on (classify_span_at_split), as at a split point inside the box.
// The square-free D of L restricted to the box side u = c (u_fixed) or t = c, a polynomial in the other coordinate.
inline Polynomial_1<Rational> square_free_on_side(const Surface_locus& L, bool u_fixed, const Rational& c) {
  const Polynomial_2<Integer>& Dsf = L.equation.square_free;
  std::vector<Rational> coefficients;
  for (int j = 0; j <= Dsf.degree(); ++j) {
    const Polynomial_1<Integer>& Dj = Dsf[j];
    if (u_fixed) {  // D_j(c), the coefficient of t^j
      Rational value(0);
      for (int i = Dj.degree(); i >= 0; --i) value = value * c + Rational(Dj[i]);
      coefficients.push_back(value);
    } else {  // sum_j D_j(u) c^j
      Rational power(1);
      for (int l = 0; l < j; ++l) power *= c;
      if (coefficients.size() < std::size_t(Dj.degree() + 1)) coefficients.resize(std::size_t(Dj.degree() + 1), Rational(0));
      for (int i = 0; i <= Dj.degree(); ++i) coefficients[std::size_t(i)] += Rational(Dj[i]) * power;
    }
  }
  return Polynomial_1<Rational>(coefficients.begin(), coefficients.end());
}

// An exact common point of the boundary curves of both patches (a point Boundary_contact) as the point (u, t) of
// the box side it lies on, for the arc-end tests below; empty for shared pieces, corners of the box and points on
// an edge line.
struct Contact_on_box_side {
  bool found = false;
  bool u_fixed = false;          // on the box side u = value (else t = value)
  Rational value;                // that side's coordinate
  Double_interval u, t, v, s;    // enclosures of the contact's coordinates
};

inline Contact_on_box_side contact_on_box_side(const Surface_locus& L, const Boundary_contact& c) {
  using D = Double_interval;
  Contact_on_box_side r;
  if (c.shared_curve || c.first_0 != c.first_1) return r;
  const bool u_fixed = c.side_first == 1 || c.side_first == 3, t_fixed = c.side_second == 0 || c.side_second == 2;
  if (u_fixed == t_fixed) return r;  // (a box corner, or both partner coordinates on the partner's boundary)
  auto enclosure = [](const Algebraic_real& a) {
    const auto i = a.to_interval();
    return D{i.first, i.second};
  };
  // a boundary point of a patch: (u, v) from the side (boundary_curve order) and the curve's parameter
  auto on_side = [](int side, const D& parameter, D& u, D& v) {
    const D zero{0, 0}, one{1, 1};
    switch (side) {
      case 0: u = parameter, v = zero; break;
      case 1: u = one, v = parameter; break;
      case 2: u = parameter, v = one; break;
      default: u = zero, v = parameter; break;
    }
  };
  on_side(c.side_first, enclosure(c.first_0), r.u, r.v);
  on_side(c.side_second, enclosure(c.second_0), r.s, r.t);
  const D& free_coordinate = u_fixed ? r.t : r.u;  // (the projection's coordinate along the box side)
  if (!(free_coordinate.lo > 0 && free_coordinate.hi < 1)) return r;  // (a corner of the box)
  for (const Locus_edge_line& l : L.edge_lines) {
    const D& x = l.side == 1 || l.side == 3 ? r.u : r.t;
    if (Rational(x.lo) <= l.value && l.value <= Rational(x.hi)) return r;
  }
  r.u_fixed = u_fixed;
  r.value = u_fixed ? Rational(c.side_first == 1 ? 1 : 0) : Rational(c.side_second == 2 ? 1 : 0);
  r.found = true;
  return r;
}

// The vertex at an arc end is the contact: its box holds the contact's (u, t), and the square-free D on the box side
// has exactly one root in the hull of the two enclosures along the side (counted exactly), which is then both.
inline bool vertex_is_contact(const Curve_topology_vertex& x, const Contact_on_box_side& p,
                              const Polynomial_1<Rational>& on_side_line) {
  using D = Double_interval;
  if (!x.on_boundary) return false;
  if (!(x.u_lo <= p.u.lo && p.u.hi <= x.u_hi && x.v_lo <= p.t.lo && p.t.hi <= x.v_hi)) return false;
  const D along = p.u_fixed ? D{std::min(x.v_lo, p.t.lo), std::max(x.v_hi, p.t.hi)}
                            : D{std::min(x.u_lo, p.u.lo), std::max(x.u_hi, p.u.hi)};
  return !CGAL::is_zero(on_side_line) && count_real_roots(on_side_line, Rational(along.lo), Rational(along.hi)) == 1;
}

template <class Lift>
void insert_contact_split_points(Surface_locus& L, const Partner_equations& eq, const Surface_intersection_options& o,
                                 Lift lift_point) {
  if (L.topology_method != "subdivision" || o.partner_domain_unbounded || eq.self_intersection()) return;
  const Parameter_box unit{Rational(0), Rational(1), Rational(0), Rational(1)};
  auto same = [](const Parameter_box& a, const Parameter_box& b) {
    return a.u0 == b.u0 && a.u1 == b.u1 && a.v0 == b.v0 && a.v1 == b.v1;
  };
  if (!same(o.box, unit) || !same(o.partner_domain, unit)) return;  // (contacts are on the patches' own sides)
  using D = Double_interval;
  for (std::size_t ci = 0; ci < L.contacts.size(); ++ci) {
    const Boundary_contact& c = L.contacts[ci];
    const Contact_on_box_side at = contact_on_box_side(L, c);
    if (!at.found) continue;
    const bool u_fixed = at.u_fixed;
    const D &u = at.u, &t = at.t, &v = at.v, &s = at.s;
    // the partner side crossed there: Q's first coordinate s = 0 or 1 (box side u = c), or P's second v (t = c)
    Partner_domain_side side;
    side.point = u_fixed ? 1 : 0;
    side.coordinate = u_fixed ? 0 : 1;
    side.bound = u_fixed ? Rational(c.side_second == 1 ? 1 : 0) : Rational(c.side_first == 2 ? 1 : 0);
    const std::array<D, 4> contact{u, t, v, s};
    // the square-free D on the box side through the contact: u = u* (a polynomial in t) or t = t* (in u)
    const Polynomial_1<Rational> on_side_line = square_free_on_side(L, u_fixed, at.value);
    for (std::size_t k = 0; k < L.arcs.size() && k < L.topology.edges.size(); ++k) {
      Locus_arc& arc = L.arcs[k];
      const Curve_topology_edge& e = L.topology.edges[k];
      if (arc.points.size() < 2 || arc.points.size() != e.polyline.size()) continue;
      for (const std::size_t j : {std::size_t(0), arc.points.size() - 1}) {
        if (!vertex_is_contact(L.topology.vertices[j == 0 ? e.source : e.target], at, on_side_line)) continue;
        bool known = false;
        for (const Locus_split_point& sp : L.split_points) known = known || (sp.arc == k && sp.index == j);
        if (known) continue;
        const auto found = isolate_crossing(eq, side, {u.mid(), t.mid(), v.mid(), s.mid()});
        if (!found) continue;
        std::array<D, 4> Z = found->box;
        bool holds = true;  // Z holds the contact's enclosure: the unique zero in Z is the contact
        for (int d = 0; d < 4; ++d) holds = holds && Z[d].lo <= contact[d].lo && contact[d].hi <= Z[d].hi;
        const auto w = eq.weights(Z);
        if (!holds || w[0].contains_zero() || w[1].contains_zero()) continue;
        // its box-side and partner-side coordinates are exact (the sides' values): Z keeps the zero when they are
        // narrowed to them, and the span next to the end then holds the box's graph interval
        Z[u_fixed ? 0 : 1] = u_fixed ? u : t;
        Z[u_fixed ? 3 : 2] = u_fixed ? s : v;
        const std::array<double, 2> y{v.mid(), s.mid()};
        Locus_point q = lift_point(u.mid(), t.mid(), &y);
        q.genuine = q.status_proved = true;
        q.partner_enclosure = {{{Z[2].lo, Z[2].hi}, {Z[3].lo, Z[3].hi}}};
        arc.points[j] = q;
        Locus_split_point sp;
        sp.arc = k;
        sp.index = j;
        sp.point = side.point;
        sp.coordinate = side.coordinate;
        sp.bound = side.bound;
        for (int d = 0; d < 4; ++d) sp.box[std::size_t(d)] = {Z[d].lo, Z[d].hi};
        sp.contact = int(ci);
        L.split_points.push_back(sp);
      }
    }
  }
}

// Proves the genuine / phantom status along the arcs of a subdivision topology (lifting/certified_lifting.h),
// starting from the floating-point partners of the traced points; a proof overrides the floating-point flag.
template <class Lift>
void certify_lifting(Surface_locus& L, const Partner_equations& eq, const Surface_intersection_options& o,
                     Lift lift_point, const Rational_bezier_patch<Rational>* self_patch = nullptr,
                     Half_branch_chains* chains = nullptr, const Time_budget* time = nullptr) {
  if (L.topology_method != "subdivision" || !o.certify_lifting) return;
  // self-intersection: the partner equations divided by the trivial partner, for spans near pinch points
  std::vector<Blown_up_partner_equations> blown_up;
  if (self_patch)
    for (int chart = 0; chart < 2; ++chart) blown_up.emplace_back(*self_patch, chart);
  // the kernel of B: phantom proofs where the partner is far outside the domain (kernel_partner_proofs.h)
  // (not where B has a kernel of dimension >= 2 everywhere: D then comes from maximal minors, and a kernel vector
  // need not belong to the partner of the point)
  const Kernel_partner_system kernel(L.equation.matrix, L.self_intersection);
  const bool kernel_usable = L.equation.route == Implicit_equation::Route::determinant;
  Exclusion_budget budget;
  budget.left = budget.fallback_left = o.lifting_exclusion_budget;
  if (time) budget.interrupt = [time]() { time->check("certified lifting"); };
  std::vector<double> length(L.arcs.size(), 0);                 // (the measure of undecided_fraction)
  std::vector<std::vector<bool>> split_of(L.arcs.size()), float_genuine_of(L.arcs.size());
  for (std::size_t k = 0; k < L.arcs.size() && k < L.topology.edges.size(); ++k) {
    if (time) time->check("certified lifting");  // (per arc: the stage's cost grows with the number of arcs)
    Locus_arc& arc = L.arcs[k];
    // the split points: their status is their own proof (about the exact crossing); the spans next to them are
    // decided from the side of the boundary line that the partner is on (classify_span_at_split)
    std::vector<bool> split(arc.points.size(), false);
    std::vector<Partner_domain_crossing> crossings(arc.points.size());
    std::vector<const Partner_domain_crossing*> split_boxes(arc.points.size(), nullptr);
    for (const Locus_split_point& sp : L.split_points)
      if (sp.arc == k && sp.index < split.size()) {
        split[sp.index] = true;
        crossings[sp.index] = crossing_of(sp);
        split_boxes[sp.index] = &crossings[sp.index];
      }
    std::vector<std::array<double, 2>> partner;
    std::vector<bool> known, float_genuine;
    for (const Locus_point& q : arc.points) {
      float_genuine.push_back(q.genuine);
      partner.push_back(q.partner);
      // (a trivial partner (0, 0) of a self-intersection point is no guess for its true partner)
      known.push_back(q.lifted && std::isfinite(q.partner[0]) && std::isfinite(q.partner[1]) &&
                      !(L.self_intersection && std::fabs(q.partner[0]) + std::fabs(q.partner[1]) <= 1e-9));
    }
    const Edge_partner_certificate c =
        certify_edge_partners(eq, o.partner_domain, o.partner_domain_unbounded, L.topology.edges[k], partner, known,
                              float_genuine, budget, 6, split_boxes, blown_up.empty() ? nullptr : &blown_up,
                              kernel_usable ? &kernel : nullptr, chains);
    arc.undecided_fraction = c.undecided_fraction;
    length[k] = c.length;
    split_of[k] = split;
    float_genuine_of[k] = float_genuine;
    for (std::size_t i = 0; i < arc.points.size() && i < c.point_status.size(); ++i)
      if (c.point_status[i] != Partner_status::undecided && !split[i]) {
        Locus_point& q = arc.points[i];
        const auto& y = c.partner_enclosure[i];
        if (c.point_status[i] == Partner_status::genuine && q.lifted &&
            !(y[0].lo <= q.partner[0] && q.partner[0] <= y[0].hi && y[1].lo <= q.partner[1] && q.partner[1] <= y[1].hi)) {
          // the floating-point lifting followed another (e.g. the trivial) partner: restart it from the proved one
          const std::array<double, 2> guess{y[0].mid(), y[1].mid()};
          q = lift_point(q.projection[0], q.projection[1], &guess);
        }
        q.status_proved = true;
        q.genuine = c.point_status[i] == Partner_status::genuine;
        if (q.genuine) q.partner_enclosure = {{{y[0].lo, y[0].hi}, {y[1].lo, y[1].hi}}};
      }
  }
  // half-branches left open where another half-branch of their singular box runs through their strip: proved
  // phantom beside that one's proved spans (lifting/internal/beside_half_branches.h), once every chain is known
  if (!chains || o.partner_domain_unbounded) return;
  // (a budget of their own, four times the fallback's: the descent towards a singular point costs about a hundred
  // tests per piece, over about fifty pieces from 1e-7 to a few ulps)
  Exclusion_budget beside;
  beside.left = beside.fallback_left = 4 * o.lifting_exclusion_budget;
  beside.interrupt = budget.interrupt;
  for (std::size_t k = 0; k < L.arcs.size() && k < L.topology.edges.size(); ++k)  // (the fibres of proved spans)
    for (const Curve_topology_piece& pc : L.topology.edges[k].pieces)
      if (pc.graph_axis < 0) prove_fibres_beside_half_branches(eq, o.partner_domain, pc, *chains, beside);
  for (std::size_t k = 0; k < L.arcs.size() && k < L.topology.edges.size(); ++k) {
    Locus_arc& arc = L.arcs[k];
    if (!(arc.undecided_fraction > 0) || !(length[k] > 0)) continue;
    if (time) time->check("certified lifting");
    const Curve_topology_edge& e = L.topology.edges[k];
    std::vector<Partner_status> status(arc.points.size(), Partner_status::undecided);
    for (std::size_t i = 0; i < arc.points.size(); ++i)
      if (arc.points[i].status_proved)
        status[i] = arc.points[i].genuine ? Partner_status::genuine : Partner_status::phantom;
    double decided = 0;
    for (const Curve_topology_piece& pc : e.pieces)
      if (pc.graph_axis < 0 && pc.last < e.polyline.size() && pc.first < pc.last)
        decided += (std::fabs(e.polyline[pc.last][0] - e.polyline[pc.first][0]) +
                    std::fabs(e.polyline[pc.last][1] - e.polyline[pc.first][1])) *
                   prove_beside_half_branches(eq, o.partner_domain, e, pc, float_genuine_of[k], *chains, beside, status);
    if (!(decided > 0)) continue;
    arc.undecided_fraction = std::max(0.0, arc.undecided_fraction - decided / length[k]);
    for (std::size_t i = 0; i < arc.points.size(); ++i)
      if (status[i] == Partner_status::phantom && !arc.points[i].status_proved && !split_of[k][i]) {
        arc.points[i].status_proved = true;
        arc.points[i].genuine = false;
      }
  }
}

// Arcs on a rational line whose partner is affine in the point with rational coefficients (the double line of an
// extruded loop, two extrusions along one direction): every point proved genuine at once, exactly
// (lifting/linear_partner_lines.h), where the interval proofs leave the spans at the box's sides open. A traced
// point where the partner is the trivial one (a pinch point of a self-intersection) keeps its own status.
// `degree_bound`: the sum of both patches' degrees in u and v.
inline void prove_linear_partner_lines(Surface_locus& L, const Partner_equations& eq,
                                       const Surface_intersection_options& o, int degree_bound) {
  if (L.topology_method != "subdivision") return;
  for (std::size_t k = 0; k < L.arcs.size() && k < L.topology.edges.size(); ++k) {
    Locus_arc& arc = L.arcs[k];
    if (arc.undecided_fraction == 0) continue;
    std::vector<std::array<double, 2>> partner;
    for (const Locus_point& q : arc.points) partner.push_back(q.partner);
    const Curve_topology_edge& e = L.topology.edges[k];
    const auto y = linear_partner_of_line(e, partner, eq, o.partner_domain, o.partner_domain_unbounded, degree_bound);
    if (!y) continue;
    const int g = e.pieces.front().graph_axis;
    for (std::size_t i = 0; i < arc.points.size(); ++i) {
      const std::array<Rational, 2> p = y->at(Rational(e.polyline[i][std::size_t(g)]));
      if (eq.self_intersection() && CGAL::is_zero(p[0]) && CGAL::is_zero(p[1])) continue;
      const Double_interval Y1 = Double_interval::of(p[0]), Y2 = Double_interval::of(p[1]);
      Locus_point& q = arc.points[i];
      q.genuine = q.status_proved = true;
      q.partner_enclosure = {{{Y1.lo, Y1.hi}, {Y2.lo, Y2.hi}}};
    }
    arc.undecided_fraction = 0;
  }
}

// Arcs on a rational line of the parameter plane that the interval proofs leave open (a partner equation with a
// double root along the line: a patch even about the line): the exact fibre over the line
// (lifting/exact_line_fibres.h) decides the status of the whole arc between its end points, which keep their own
// (a pinch point). Each nontrivial component must lie in the domain over none of the arc's range [tA, tB] (but an
// end, or the point where it meets the trivial partner), or over all of it with both weights proved nonzero there
// (interval evaluation); a component that enters or leaves the domain inside the arc (a split point) leaves the arc
// as it was. An arc with no genuine component is phantom, proved, with no sheet. Otherwise the fibre is proved
// when the sheets hold exactly the genuine partners at every traced point but the ends (then every sheet point
// gets the exact partner's enclosure); if they do not, the arc is left as it was.
inline void prove_line_arc_fibres(Surface_locus& L, const Partner_equations& eq, const Surface_intersection_options& o,
                                  const Time_budget* time = nullptr) {
  if (L.topology_method != "subdivision" || o.partner_domain_unbounded) return;
  for (std::size_t k = 0; k < L.arcs.size() && k < L.topology.edges.size(); ++k) {
    if (time) time->check("exact line fibres");
    Locus_arc& arc = L.arcs[k];
    const Curve_topology_edge& e = L.topology.edges[k];
    const std::size_t n = arc.points.size();
    if ((arc.undecided_fraction == 0 && arc.fibre_undecided_fraction == 0) || n != e.polyline.size() || n < 3) continue;
    const auto line = exact_line_of_arc(e, L.equation.square_free);
    if (!line) continue;
    const Exact_line_fibre F = exact_line_fibre(eq, o.partner_domain, line->c, line->r, line->T);
    if (!F.proved) continue;
    // each component in the domain over none or all of the arc's range (exact: the conditions are affine in t)
    const int g = 1 - line->c;
    const Rational ta(e.polyline.front()[std::size_t(g)]), tb(e.polyline.back()[std::size_t(g)]);
    const std::array<Rational, 2> range{std::min(ta, tb), std::max(ta, tb)};
    bool settled = true;
    for (const Affine_fibre_component& comp : F.components) {
      // (the trivial partner of a self-intersection: w = x, i.e. w = (r, t) or (t, r))
      const std::array<Rational, 2> trivial_a = line->c == 0 ? std::array<Rational, 2>{line->r, Rational(0)}
                                                             : std::array<Rational, 2>{Rational(0), line->r},
                                    trivial_b = line->c == 0 ? std::array<Rational, 2>{Rational(0), Rational(1)}
                                                             : std::array<Rational, 2>{Rational(1), Rational(0)};
      if (eq.self_intersection() && comp.a == trivial_a && comp.b == trivial_b) continue;
      const auto S = component_in_domain(eq, o.partner_domain, comp, line->c, line->r, range);
      if (!S) continue;
      if ((*S)[0] == (*S)[1]) {  // one point: an end of the arc, or where the component is the trivial partner
        const Rational t = (*S)[0];
        const std::array<Rational, 2> w = comp.at(t), x = line->c == 0 ? std::array<Rational, 2>{line->r, t}
                                                                         : std::array<Rational, 2>{t, line->r};
        settled = settled && (t == range[0] || t == range[1] || (eq.self_intersection() && w == x));
        continue;
      }
      if (!((*S)[0] == range[0] && (*S)[1] == range[1])) {
        settled = false;
        continue;
      }
      // genuine over the whole range: both weights nonzero there
      std::array<Double_interval, 4> z;
      const Double_interval T = Double_interval::hull(range[0], range[1]);
      z[std::size_t(line->c)] = Double_interval::of(line->r);
      z[std::size_t(g)] = T;
      for (int d = 0; d < 2; ++d) {
        const Double_interval wd = Double_interval::of(comp.a[std::size_t(d)]) + Double_interval::of(comp.b[std::size_t(d)]) * T;
        z[std::size_t(2 + d)] = eq.self_intersection() ? wd - z[std::size_t(d)] : wd;  // y = w - x, or y = w
      }
      const std::array<Double_interval, 2> weights = eq.weights(z);
      settled = settled && !weights[0].contains_zero() && !weights[1].contains_zero();
    }
    if (!settled) continue;
    std::vector<std::vector<std::array<Rational, 2>>> genuine(n);
    bool decided = true, any = false;
    for (std::size_t i = 1; i + 1 < n; ++i) {
      const Rational t(e.polyline[i][std::size_t(1 - line->c)]);
      const std::array<Rational, 2> x = line->c == 0 ? std::array<Rational, 2>{line->r, t} : std::array<Rational, 2>{t, line->r};
      genuine[i] = genuine_line_partners(eq, o.partner_domain, F, x, t, decided);
      any = any || !genuine[i].empty();
    }
    if (!decided) continue;
    auto enclosure = [](const std::array<Rational, 2>& y) {
      const Double_interval a = Double_interval::of(y[0]), b = Double_interval::of(y[1]);
      return std::array<std::array<double, 2>, 2>{{{a.lo, a.hi}, {b.lo, b.hi}}};
    };
    auto near = [](const std::array<double, 2>& p, const std::array<Rational, 2>& y) {
      return std::fabs(p[0] - CGAL::to_double(y[0])) + std::fabs(p[1] - CGAL::to_double(y[1])) <= 1e-6;
    };
    if (any) {  // the sheets against the exact genuine partners, point by point
      std::vector<std::size_t> matched(n, 0);
      bool consistent = true;
      for (const Locus_sheet& s : arc.sheets)
        for (std::size_t j = 0; j < s.points.size() && consistent; ++j) {
          const std::size_t i = s.first + j;
          if (i == 0 || i + 1 >= n) continue;
          bool found = false;
          for (const auto& y : genuine[i]) found = found || near(s.points[j].partner, y);
          consistent = found;
          ++matched[i];
        }
      for (std::size_t i = 1; i + 1 < n && consistent; ++i) consistent = matched[i] == genuine[i].size();
      if (!consistent) continue;
      for (Locus_sheet& s : arc.sheets)
        for (std::size_t j = 0; j < s.points.size(); ++j) {
          const std::size_t i = s.first + j;
          if (i == 0 || i + 1 >= n) continue;
          for (const auto& y : genuine[i])
            if (near(s.points[j].partner, y)) {
              s.points[j].status_proved = s.points[j].genuine = true;
              s.points[j].partner_enclosure = enclosure(y);
            }
        }
    } else {
      arc.sheets.clear();
    }
    for (std::size_t i = 1; i + 1 < n; ++i) {
      // (a point lifted from another partner than its genuine ones keeps its status: its patch points are that
      // partner's; the sheets carry the genuine ones)
      Locus_point& q = arc.points[i];
      if (genuine[i].empty()) {
        q.status_proved = true;
        q.genuine = false;
      }
      for (const auto& y : genuine[i])
        if (near(q.partner, y)) {
          q.status_proved = q.genuine = true;
          q.partner_enclosure = enclosure(y);
        }
    }
    arc.undecided_fraction = arc.fibre_undecided_fraction = 0;
  }
}

/// A sheet's point `q` over the arc point `x` as the distance bounds read it (lifting/polyline_distance_bounds.h).
inline Reported_sheet_point reported_sheet_point(const Locus_point& q, const std::array<double, 2>& x) {
  Reported_sheet_point r;
  r.x = x;
  r.y = q.partner;
  r.first = q.first;
  r.second = q.second;
  r.space = q.point_3d;
  r.partner_enclosure = q.partner_enclosure;
  return r;
}

// The proved distance between every sheet segment and the branch it draws (lifting/polyline_distance_bounds.h),
// on the segments of graph pieces and of half-branches whose chain proved a span with one partner in the domain.
inline void bound_sheet_polylines(Surface_locus& L, const Partner_equations& eq, const Surface_intersection_options& o,
                                  const Half_branch_chains* chains, const Time_budget* time = nullptr) {
  if (L.topology_method != "subdivision" || !o.prove_polyline_distance) return;
  const Patch_jacobian_enclosure phi(eq, 0);
  const double inf = std::numeric_limits<double>::infinity();
  // (the uniform samples of tolerance 0: the bound of the first sub-division that proves one)
  const double target = o.polyline_tolerance > 0 ? o.polyline_tolerance : inf;
  for (std::size_t k = 0; k < L.arcs.size() && k < L.topology.edges.size(); ++k) {
    if (time) time->check("polyline distance bounds");
    const Curve_topology_edge& e = L.topology.edges[k];
    for (Locus_sheet& s : L.arcs[k].sheets) {
      s.segment_distance_bounds.clear();
      auto reported = [&](std::size_t j) { return reported_sheet_point(s.points[j], e.polyline[s.first + j]); };
      for (std::size_t j = 0; j + 1 < s.points.size(); ++j) {
        // (up to 85 sub-span proofs per segment, and an arc may have thousands: the budget is checked within)
        if (time && j % 64 == 63) time->check("polyline distance bounds");
        const std::size_t i = s.first + j;
        std::array<double, 3> bound{inf, inf, inf};
        if (i + 1 < e.polyline.size())
          for (const Curve_topology_piece& pc : e.pieces) {
            if (!(pc.first <= i && i + 1 <= pc.last)) continue;
            if (pc.graph_axis >= 0) {
              bound = segment_distance_bound(eq, phi, pc.graph_axis, pc.cell, &L.equation.square_free, reported(j),
                                             reported(j + 1), target);
            } else if (chains && !o.partner_domain_unbounded) {
              Chain_identification c;
              c.chain = chains->find(pc);
              c.domain = o.partner_domain;
              if (c.chain)
                bound = segment_distance_bound(eq, phi, c.chain->axis, pc.cell, &L.equation.square_free, reported(j),
                                               reported(j + 1), target, &c);
            }
            break;
          }
        s.segment_distance_bounds.push_back(bound);
      }
    }
  }
}

// Complete lifting (lifting/partner_sheets.h): every partner of every traced point, chained into the sheets of
// each arc, and the proof span by span that they are all. An arc proved phantom everywhere (no genuine point,
// nothing undecided) has no sheet, proved. A traced point that the kernel lifted to a partner outside the domain
// while a sheet has one inside is replaced by the sheet's point (it is genuine).
template <class Lift>
void lift_sheets(Surface_locus& L, const Partner_equations& eq, const Surface_intersection_options& o, Lift lift_point,
                 const Half_branch_chains* chains = nullptr, const Time_budget* time = nullptr) {
  if (L.topology_method != "subdivision" || !o.complete_lifting) return;
  Exclusion_budget budget;
  budget.left = budget.fallback_left = o.lifting_exclusion_budget;
  if (time) budget.interrupt = [time]() { time->check("complete lifting"); };
  std::unique_ptr<Double_curve_equation> D_double;
  const Patch_jacobian_enclosure phi_jacobian(eq, 0);
  std::size_t inserted = 0, full_fibres = 0;
  // the boundary curves shared with the partner, as seams of the partner equations (seam_blowup_exclusion.h)
  std::vector<Shared_seam> seams;
  if (!L.self_intersection && !o.partner_domain_unbounded)
    for (const Locus_edge_line& l : L.edge_lines)
      if (l.cause == Locus_edge_line::shared_curve && !l.interior)
        if (const auto S = shared_seam(eq, l.side, l.value, l.partner_side, l.partner_value, o.box, o.partner_domain))
          seams.push_back(*S);
  // and the corners the two patches share off those curves (the same blow-up at a point)
  if (!L.self_intersection && !o.partner_domain_unbounded) {
    const std::vector<Shared_seam> corners = shared_corners(eq, o.box, o.partner_domain, seams);
    seams.insert(seams.end(), corners.begin(), corners.end());
  }
  for (std::size_t k = 0; k < L.arcs.size() && k < L.topology.edges.size(); ++k) {
    if (time) time->check("complete lifting");
    Locus_arc& arc = L.arcs[k];
    const Curve_topology_edge& e = L.topology.edges[k];
    if (arc.points.size() != e.polyline.size()) continue;
    bool any_genuine = false;
    for (const Locus_point& q : arc.points) any_genuine = any_genuine || q.genuine;
    if (!any_genuine && arc.undecided_fraction == 0) {  // phantom at every point of the exact arc, proved
      arc.fibre_undecided_fraction = 0;
      continue;
    }
    // Two passes: first the kernel's partner alone at each point (cheap), which the span proofs often show to be
    // the only one; where they do not, every partner (numerical_partners) at every point.
    auto kernel_fibre = [&](const std::array<double, 2>& x, const Locus_point& q) {
      std::vector<std::array<double, 2>> F;
      const bool usable = verified(q) && !(L.self_intersection && std::fabs(q.partner[0]) + std::fabs(q.partner[1]) <= 1e-9);
      const double margin = 0.25 * std::max(CGAL::to_double(o.partner_domain.u1 - o.partner_domain.u0),
                                            CGAL::to_double(o.partner_domain.v1 - o.partner_domain.v0));
      if (usable && partner_in_domain(eq, o.partner_domain, o.partner_domain_unbounded, x, q.partner, margin))
        F.push_back(q.partner);
      return F;
    };
    // the projections of the arc's certified split points, and of its points whose partner lies exactly on the
    // partner domain's boundary (a few ulps wide: the halving towards them ends inside)
    std::vector<std::array<Double_interval, 2>> split_boxes;
    std::vector<Partner_boundary_point> exact_points;
    for (const Locus_split_point& sp : L.split_points)
      if (sp.arc == k)
        split_boxes.push_back({Double_interval{sp.box[0][0], sp.box[0][1]}, Double_interval{sp.box[1][0], sp.box[1][1]}});
    // (insert_boundary_points gave them the partner boxes of exact rationals, an ulp wide at most)
    auto ulp_wide = [](const std::array<double, 2>& b) {
      return b[1] - b[0] <= 2 * std::numeric_limits<double>::epsilon() * (std::fabs(b[0]) + std::fabs(b[1]));
    };
    for (const Locus_point& q : arc.points)
      if (q.status_proved && q.genuine && verified(q) && ulp_wide(q.partner_enclosure[0]) && ulp_wide(q.partner_enclosure[1]))
        if (const auto c = exact_boundary_point(eq, o.partner_domain, q.projection, q.partner)) {
          std::array<Double_interval, 2> b;
          for (int d = 0; d < 2; ++d) {
            const Double_interval x = Double_interval::of(c->x[std::size_t(d)]);
            const double r = 4 * std::numeric_limits<double>::epsilon() * (std::fabs(x.lo) + std::fabs(x.hi));
            b[std::size_t(d)] = Double_interval{x.lo - r, x.hi + r};
          }
          split_boxes.push_back(b);
          exact_points.push_back(*c);
          // the point's other partners on the boundary (two cylinders: the corners (1, 1) and (0, 0) over one point)
          for (const auto& y : fibre_partners(eq, o.partner_domain, o.partner_domain_unbounded, q.projection, nullptr))
            if (std::fabs(y[0] - q.partner[0]) + std::fabs(y[1] - q.partner[1]) > 1e-6)
              if (const auto d = exact_boundary_point(eq, o.partner_domain, q.projection, y))
                if (d->x == c->x && d->y != c->y) exact_points.push_back(*d);
        }
    // the certified boxes of the arc's ends where branches of D = 0 meet: singular points inside the domain or on
    // its side, points of the side where two arcs end
    std::vector<std::array<Double_interval, 2>> singular_boxes;
    for (std::size_t end : {e.source, e.target}) {
      const Curve_topology_vertex& v = L.topology.vertices[end];
      if (v.kind == Curve_topology_vertex::singular || v.singular_on_boundary || v.half_branches >= 2)
        singular_boxes.push_back({Double_interval{v.u_lo, v.u_hi}, Double_interval{v.v_lo, v.v_hi}});
    }
    auto attempt = [&](bool every_partner) {
      std::vector<std::vector<std::array<double, 2>>> fibres;
      for (std::size_t i = 0; i < e.polyline.size(); ++i) {
        // (the fibres cost about half a millisecond each, and an arc may have thousands of points: checked within)
        if (time && i % 64 == 63) time->check("complete lifting");
        const Locus_point& q = arc.points[i];
        const bool usable = verified(q) && !(L.self_intersection && std::fabs(q.partner[0]) + std::fabs(q.partner[1]) <= 1e-9);
        fibres.push_back(every_partner ? fibre_partners(eq, o.partner_domain, o.partner_domain_unbounded, e.polyline[i],
                                                        usable ? &q.partner : nullptr)
                                       : kernel_fibre(e.polyline[i], q));
      }
      if (o.polyline_tolerance > 0 && inserted < o.max_refinement_points) {
        Arc_refinement_model model;
        model.fibre = [&](const std::array<double, 2>& x) {
          if (time) time->check("complete lifting");
          return every_partner ? fibre_partners(eq, o.partner_domain, o.partner_domain_unbounded, x, nullptr)
                               : kernel_fibre(x, lift_point(x[0], x[1], nullptr));
        };
        model.lift = [&](const std::array<double, 2>& x, const std::array<double, 2>& y) {
          const Locus_point q = lift_point(x[0], x[1], &y);
          return std::array<double, 7>{q.first[0], q.first[1], q.second[0], q.second[1],
                                       q.point_3d[0], q.point_3d[1], q.point_3d[2]};
        };
        model.solve = [&](int axis, double t, std::array<double, 3>& w) { return solve_partner_equations(eq, axis, t, w); };
        model.inside = [&](const std::array<double, 2>& x, const std::array<double, 2>& y) {
          return partner_in_domain(eq, o.partner_domain, o.partner_domain_unbounded, x, y, 1e-12);
        };
        if (o.prove_polyline_distance && o.refine_to_proved_distance)
          model.bound = [&](int axis, const std::array<double, 2>& xa, const std::array<double, 2>& ya,
                            const std::array<double, 2>& xb, const std::array<double, 2>& yb) {
            auto reported = [&](const std::array<double, 2>& x, const std::array<double, 2>& y) {
              const auto l = model.lift(x, y);
              Reported_sheet_point r;
              r.x = x;
              r.y = y;
              r.first = {l[0], l[1]};
              r.second = {l[2], l[3]};
              r.space = {l[4], l[5], l[6]};
              const double nan = std::numeric_limits<double>::quiet_NaN();
              r.partner_enclosure = {{{nan, nan}, {nan, nan}}};
              return r;
            };
            return segment_distance_estimate(eq, phi_jacobian, axis, reported(xa, ya), reported(xb, yb));
          };
        model.insert = [&](std::size_t i, const std::array<double, 2>& x, const std::vector<std::array<double, 2>>& F) {
          // lifted from a partner in the domain if it has one (the kernel's ratio can run away near a seam)
          const std::array<double, 2>* seed = F.empty() ? nullptr : &F[0];
          for (const auto& y : F)
            if (partner_in_domain(eq, o.partner_domain, o.partner_domain_unbounded, x, y, 1e-12)) seed = &y;
          arc.points.insert(arc.points.begin() + std::ptrdiff_t(i + 1), lift_point(x[0], x[1], seed));
          for (Locus_split_point& sp : L.split_points)
            if (sp.arc == k && sp.index > i) ++sp.index;
        };
        if (!D_double) D_double.reset(new Double_curve_equation(L.equation.square_free));
        inserted += refine_arc(L.topology.edges[k], fibres, *D_double, model, o.polyline_tolerance,
                               o.max_refinement_points - inserted);
      }
      return complete_edge_lifting(eq, o.partner_domain, o.partner_domain_unbounded, e, fibres, budget, split_boxes,
                                   chains, singular_boxes, &L.equation.square_free, exact_points, every_partner, seams);
    };
    Edge_sheets es = attempt(false);
    if (es.undecided_fraction > 0 && full_fibres + e.polyline.size() <= o.max_complete_fibres) {
      full_fibres += e.polyline.size();
      // both are proofs of what they claim: the one that leaves less undecided is kept (extra partners near the
      // domain's boundary can break spans that the kernel's partner alone proved)
      // (the first pass's sheets index the polyline as it was: kept only if the second added no point)
      const std::size_t before = e.polyline.size();
      Edge_sheets every = attempt(true);
      if (every.undecided_fraction <= es.undecided_fraction || e.polyline.size() != before) es = std::move(every);
    }
    arc.fibre_undecided_fraction = es.undecided_fraction;
    // (the spans left open by either proof are a subset of those left open by each)
    arc.undecided_fraction = std::min(arc.undecided_fraction, es.status_undecided_fraction);
    for (const Partner_sheet& S : es.sheets) {
      Locus_sheet run;
      auto flush = [&]() {
        if (!run.points.empty()) arc.sheets.push_back(std::move(run));
        run = Locus_sheet{};
      };
      for (std::size_t j = 0; j < S.partner.size(); ++j) {
        const std::size_t i = S.first + j;
        if (es.phantom_proved[i]) {  // (a floating-point root next to a fold, where the exact partners are complex)
          flush();
          continue;
        }
        Locus_point q = lift_point(e.polyline[i][0], e.polyline[i][1], &S.partner[j]);
        if (!q.genuine) {
          flush();
          continue;
        }
        const Locus_point& p = arc.points[i];
        if (S.genuine_proved[j]) {
          q.status_proved = true;
          q.partner_enclosure = {{{S.enclosure[j][0].lo, S.enclosure[j][0].hi}, {S.enclosure[j][1].lo, S.enclosure[j][1].hi}}};
        } else if (p.status_proved && p.genuine) {
          // a traced point proved genuine by itself (an exact point with its partner on the domain's boundary,
          // insert_boundary_points; its span proofs end in its few-ulp box): this sheet's point if the sheet's
          // partner lies in the point's partner box (up to the floating point of the sheet)
          bool same = true;
          for (int c = 0; c < 2; ++c) {
            const auto& b = p.partner_enclosure[std::size_t(c)];
            const double y = S.partner[j][std::size_t(c)], slack = 1e-12 * (1 + std::fabs(y));
            same = same && b[0] - slack <= y && y <= b[1] + slack;
          }
          if (same) {
            q.status_proved = true;
            q.partner_enclosure = p.partner_enclosure;
          }
        }
        if (run.points.empty()) run.first = i;
        run.points.push_back(q);
        if ((!p.genuine && !p.status_proved) || (!p.status_proved && q.status_proved)) arc.points[i] = q;
      }
      flush();
    }
    for (std::size_t i = 0; i < arc.points.size() && i < es.phantom_proved.size(); ++i)
      if (es.phantom_proved[i] && !(arc.points[i].status_proved && arc.points[i].genuine)) {
        arc.points[i].genuine = false;
        arc.points[i].status_proved = true;
      }
  }
}

}  // namespace internal

/// \brief Self-intersection locus of `patch` (Theorems 4, 5): D(u,v), its certified topology in `o.box`, and
/// every traced point lifted to the two parameter points (u, v+k) and (u+l, v) with the same image.
namespace internal {

// The box and the partner domain lie in the patches' domain [0,1]^2, where the direct proofs apply.
inline bool within_unit_square(const Surface_intersection_options& o) {
  auto inside = [](const Parameter_box& b) {
    return Rational(0) <= b.u0 && b.u1 <= Rational(1) && Rational(0) <= b.v0 && b.v1 <= Rational(1);
  };
  return !o.partner_domain_unbounded && inside(o.box) && inside(o.partner_domain);
}

inline void search_pinch_points(Surface_locus& L, const Rational_bezier_patch<Rational>& patch,
                                const Surface_intersection_options& o) {
  if (o.pinch_point_boxes > 0) {
    Pinch_point_search pinch = internal::find_pinch_points(patch, o.box, o.pinch_point_boxes);
    L.pinch_points = pinch.points;
    L.pinch_points_complete = pinch.complete;
    L.pinch_points_note = pinch.reason;
  } else {
    L.pinch_points_note = "not searched (pinch_point_boxes = 0)";
  }
}

// The self-intersection locus of a patch proved injective: no double point but the pairs of points of a side that
// the patch collapses to one point, which are reported as edge lines when the side is a side of the box.
inline Surface_locus injective_patch_locus(const Rational_bezier_patch<Rational>& patch,
                                           const Surface_intersection_options& o, const Injectivity_proof& proof) {
  Surface_locus L;
  L.self_intersection = true;
  L.equation_computed = false;
  L.topology.box = o.box;
  L.topology_computed = true;
  L.topology_method = "injective projection";
  L.note = proof.reason;
  for (int side : proof.collapsed_sides) {
    const Rational domain_side = (side == 0 || side == 3) ? Rational(0) : Rational(1);
    if (side_value(o.box, side) != domain_side) continue;
    Locus_edge_line e;
    e.side = side;
    e.value = domain_side;
    L.edge_lines.push_back(e);
  }
  // every side here is collapsed, so genuine: its samples come from the side itself, never from a lifting
  describe_edge_lines(L, o, patch, nullptr, [](double, double, const std::array<double, 2>*) { return Locus_point{}; });
  search_pinch_points(L, patch, o);
  return L;
}

// The intersection locus of two patches proved apart: empty.
inline Surface_locus separated_patches_locus(const Surface_intersection_options& o, const Separation_proof& proof) {
  Surface_locus L;
  L.self_intersection = false;
  L.equation_computed = false;
  L.topology.box = o.box;
  L.topology_computed = true;
  L.topology_method = "separated hulls";
  L.note = proof.reason;
  return L;
}

// The parameter rectangles {x0, x1, y0, y1} of the two patches that the locus covers: (u, v) in box u x domain v
// for the first, (s, t) in domain u x box t for the second.
inline std::array<Rectangle, 2> intersection_domains(const Surface_intersection_options& o) {
  const Parameter_box &b = o.box, &d = o.partner_domain;
  return {Rectangle{b.u0, b.u1, d.v0, d.v1}, Rectangle{d.u0, d.u1, b.v0, b.v1}};
}

// The intersection locus of two patches that are pieces of one surface (intersection/Patch_common_parent.h), with
// the outcome `cp` of intersect_common_parent: no curve of D = 0 (det B vanishes identically); when proved, the
// common region as an overlap and common boundary pieces in `contacts` are the whole intersection; otherwise the
// overlap and the reason the rest is not decided.
inline Surface_locus common_parent_locus(const Surface_intersection_options& o, const Common_parent_intersection& cp,
                                         std::vector<Boundary_contact> contacts) {
  Surface_locus L;
  L.self_intersection = false;
  L.equation_computed = false;
  L.topology.box = o.box;
  L.contacts = std::move(contacts);
  L.topology_computed = cp.proved;
  if (cp.proved) L.topology_method = "common parent";
  L.note = cp.reason;
  if (cp.related && cp.kind == Common_parent_intersection::region)
    L.overlaps.push_back(Locus_overlap{cp.first, cp.second, cp.relation.swapped, cp.relation.along_u,
                                       cp.relation.along_v});
  return L;
}

// The box, seen through the exact partner (v, s) = (t, u) of two patches over one projection, lies in the partner
// domain: u in [d.u0, d.u1] (s = u) and t in [d.v0, d.v1] (v = t).
inline bool box_within_transposed_domain(const Surface_intersection_options& o) {
  const Parameter_box &b = o.box, &d = o.partner_domain;
  return d.u0 <= b.u0 && b.u1 <= d.u1 && d.v0 <= b.v0 && b.v1 <= d.v1;
}

// The intersection locus of two patches over one projection (intersection/Patch_common_projection.h): D = h, the
// partner of (u, t) is (v, s) = (t, u) exactly, and every point of h = 0 in the box is genuine, proved.
inline Surface_locus common_projection_locus(const Rational_bezier_patch<Rational>& phi,
                                             const Rational_bezier_patch<Rational>& psi,
                                             const Surface_intersection_options& o, const Common_projection& cp,
                                             std::vector<Boundary_contact> contacts) {
  Surface_locus L;
  L.self_intersection = false;
  L.equation_computed = false;
  L.contacts = std::move(contacts);
  L.equation.variables = {"u", "t"};
  L.equation.determinant = normalized_primitive_part(integer_multiple(cp.height_difference));
  L.equation.square_free = normalized_square_free_part(L.equation.determinant);
  L.note = cp.reason;
  const bool traced = topology_is_affordable(L, with_partner_proofs(o, Partner_equations(phi, psi)));
  auto lift_point = [&](double u, double t, const std::array<double, 2>*) {
    Locus_point q;
    q.projection = {u, t};
    q.partner = {t, u};
    q.first = {u, t};
    q.second = {u, t};
    q.lifted = true;
    q.point_3d = phi.evaluate(u, t);
    q.residual = distance3(q.point_3d, psi.evaluate(u, t));
    q.genuine = true;  // the partner (t, u) lies in the partner domain (box_within_transposed_domain)
    q.status_proved = true;
    return q;
  };
  describe_edge_lines(L, o, phi, &psi, lift_point);
  if (!traced) return L;
  lift_arcs(L, lift_point);
  if (o.polyline_tolerance > 0) {  // chords to the tolerance; each new point of h = 0 is genuine like the others
    const Double_curve_equation D_double(L.equation.square_free);
    std::size_t inserted = 0;
    for (std::size_t k = 0; k < L.arcs.size() && k < L.topology.edges.size(); ++k) {
      Locus_arc& arc = L.arcs[k];
      Curve_topology_edge& e = L.topology.edges[k];
      if (arc.points.size() != e.polyline.size()) continue;
      auto fibre = [](const std::array<double, 2>& x) { return std::vector<std::array<double, 2>>{{x[1], x[0]}}; };
      std::vector<std::vector<std::array<double, 2>>> fibres;
      for (const auto& x : e.polyline) fibres.push_back(fibre(x));
      Arc_refinement_model model;
      model.fibre = fibre;
      model.lift = [&](const std::array<double, 2>& x, const std::array<double, 2>&) {
        const Locus_point q = lift_point(x[0], x[1], nullptr);
        return std::array<double, 7>{q.first[0], q.first[1], q.second[0], q.second[1],
                                     q.point_3d[0], q.point_3d[1], q.point_3d[2]};
      };
      model.insert = [&](std::size_t i, const std::array<double, 2>& x, const std::vector<std::array<double, 2>>&) {
        arc.points.insert(arc.points.begin() + std::ptrdiff_t(i + 1), lift_point(x[0], x[1], nullptr));
      };
      model.solve = [](int, double, std::array<double, 3>&) { return false; };  // the root of h on the line
      model.inside = [](const std::array<double, 2>&, const std::array<double, 2>&) { return true; };
      inserted += refine_arc(e, fibres, D_double, model, o.polyline_tolerance, o.max_refinement_points - inserted);
    }
  }
  // arc ends at exact common points of the boundary curves (where a curve of a model crosses a seam): split points
  // made from the contact, as insert_contact_split_points makes them; the partner (v, s) = (t, u) is exact here, so
  // once the end vertex is proved to be the contact (vertex_is_contact), the contact's enclosures are the box
  auto is_unit = [](const Parameter_box& b) { return b.u0 == 0 && b.u1 == 1 && b.v0 == 0 && b.v1 == 1; };
  if (L.topology_method == "subdivision" && is_unit(o.box) && is_unit(o.partner_domain))
    for (std::size_t ci = 0; ci < L.contacts.size(); ++ci) {
      const Boundary_contact& c = L.contacts[ci];
      const Contact_on_box_side at = contact_on_box_side(L, c);
      if (!at.found) continue;
      const Polynomial_1<Rational> on_side_line = square_free_on_side(L, at.u_fixed, at.value);
      for (std::size_t k = 0; k < L.arcs.size() && k < L.topology.edges.size(); ++k) {
        Locus_arc& arc = L.arcs[k];
        const Curve_topology_edge& e = L.topology.edges[k];
        if (arc.points.size() < 2) continue;
        for (const std::size_t j : {std::size_t(0), arc.points.size() - 1}) {
          if (!vertex_is_contact(L.topology.vertices[j == 0 ? e.source : e.target], at, on_side_line)) continue;
          bool known = false;
          for (const Locus_split_point& sp : L.split_points) known = known || (sp.arc == k && sp.index == j);
          if (known) continue;
          Locus_point q = lift_point(at.u.mid(), at.t.mid(), nullptr);
          q.partner_enclosure = {{{at.t.lo, at.t.hi}, {at.u.lo, at.u.hi}}};  // (v, s) = (t, u)
          arc.points[j] = q;
          Locus_split_point sp;
          sp.arc = k;
          sp.index = j;
          sp.point = at.u_fixed ? 1 : 0;  // the partner on its side: s = 1 or 0 (box side u), or v (box side t)
          sp.coordinate = at.u_fixed ? 0 : 1;
          sp.bound = at.u_fixed ? Rational(c.side_second == 1 ? 1 : 0) : Rational(c.side_first == 2 ? 1 : 0);
          sp.box = {{{at.u.lo, at.u.hi}, {at.t.lo, at.t.hi}, {at.t.lo, at.t.hi}, {at.u.lo, at.u.hi}}};
          sp.contact = int(ci);
          L.split_points.push_back(sp);
        }
      }
    }
  // one sheet per arc, all partners: Phi(u, v) = Psi(s, t) gives pi Psi(u, v) = pi Psi(s, t), so (s, t) = (u, v)
  for (Locus_arc& arc : L.arcs) {
    arc.undecided_fraction = 0;
    arc.fibre_undecided_fraction = 0;
    if (!arc.points.empty()) arc.sheets.push_back(Locus_sheet{0, arc.points});
  }
  mark_ends_on_edge_lines(L, o, phi, &psi);
  // isolated points of h = 0 (two height fields touching at a point): every real partner, exactly, as for any pair
  for (std::size_t i = 0; i < L.topology.vertices.size(); ++i)
    if (L.topology.vertices[i].kind == Curve_topology_vertex::isolated)
      L.isolated_points.push_back(Locus_isolated_point{
          i, isolated_point_partners(phi, psi, L.equation.square_free, L.topology.vertices[i], o.partner_domain)});
  return L;
}

}  // namespace internal

inline Surface_locus self_intersection_locus(const Rational_bezier_patch<Rational>& patch,
                                             const Surface_intersection_options& o = {}) {
  internal::check_patch_limits("self_intersection_locus", "the patch", patch, o.limits);
  const internal::Time_budget budget("self_intersection_locus", o.limits.time_limit);
  if (o.direct_proofs && internal::within_unit_square(o)) {
    const Injectivity_proof proof = prove_injective(patch);
    if (proof.proved) return internal::injective_patch_locus(patch, o, proof);
  }
  budget.check("direct proofs");
  Surface_locus L;
  L.self_intersection = true;
  L.equation = self_intersection_equation(patch, o.formula);
  budget.check("elimination");
  if (L.equation.is_degenerate())
    throw Invalid_input("self-intersection: det B vanishes identically (the patch is not generic in the sense of "
                        "Theorems 4-5: e.g. it covers a surface twice, or its double-point system degenerates at "
                        "infinity, as for an exact graph (u, v, f(u,v)))");
  internal::search_pinch_points(L, patch, o);
  budget.check("pinch points");
  const bool traced = internal::topology_is_affordable(L, internal::with_partner_proofs(o, internal::Partner_equations(patch)));
  budget.check("topology");
  const Bezoutian_matrix& B = L.equation.matrix;
  const internal::Double_bezoutian_matrix B_double(B);
  auto lift_point = [&](double u, double v, const std::array<double, 2>* guess) {
    Locus_point q;
    q.projection = {u, v};
    std::array<double, 2> lk;  // (l, k)
    if (guess) {
      lk = *guess;
      q.lifted = true;
    } else {
      long double k = 0, l = 0;
      const auto x = internal::null_vector(internal::transpose(B_double(u, v)));
      // U = [l^i k^j]: l = ratio along the first exponent, k along the second
      q.lifted = internal::monomial_ratio(B.row_monomials, x, 0, l) && internal::monomial_ratio(B.row_monomials, x, 1, k);
      lk = {double(l), double(k)};
    }
    auto residual = [&](double l, double k) {
      auto a = patch.evaluate(u, v + k), b = patch.evaluate(u + l, v);
      return std::array<double, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    };
    if (!q.lifted || !std::isfinite(lk[0]) || !std::isfinite(lk[1])) {
      const Parameter_box& d = o.partner_domain;
      const std::array<double, 4> range =
          o.partner_domain_unbounded ? std::array<double, 4>{-2, 2, -2, 2}
                                     : std::array<double, 4>{CGAL::to_double(d.u0) - u, CGAL::to_double(d.u1) - u,
                                                             CGAL::to_double(d.v0) - v, CGAL::to_double(d.v1) - v};
      lk = internal::grid_seed(residual, range);
      q.lifted = std::isfinite(lk[0]);
      if (!q.lifted) return q;
    }
    lk = internal::polish_partner(residual, lk);
    if (!guess) {
      const Parameter_box& d = o.partner_domain;
      const std::array<double, 4> range =
          o.partner_domain_unbounded ? std::array<double, 4>{-2, 2, -2, 2}
                                     : std::array<double, 4>{CGAL::to_double(d.u0) - u, CGAL::to_double(d.u1) - u,
                                                             CGAL::to_double(d.v0) - v, CGAL::to_double(d.v1) - v};
      lk = internal::search_if_unsolved(residual, lk, range, true);
    }
    q.partner = lk;
    q.first = {u, v + lk[1]};
    q.second = {u + lk[0], v};
    q.point_3d = patch.evaluate(q.second[0], q.second[1]);
    q.residual = internal::distance3(patch.evaluate(q.first[0], q.first[1]), q.point_3d);
    const bool distinct = std::fabs(lk[0]) + std::fabs(lk[1]) > 1e-9;
    q.genuine = distinct && internal::verified(q) && (o.partner_domain_unbounded ||
                             (internal::inside(o.partner_domain, q.first) && internal::inside(o.partner_domain, q.second)));
    return q;
  };
  internal::describe_edge_lines(L, o, patch, nullptr, lift_point);
  for (const Locus_edge_line& e : L.edge_lines)  // the rank-1 points of a collapsed side are not isolated
    if (e.cause == Locus_edge_line::collapsed && o.pinch_point_boxes > 0 && !L.pinch_points_complete)
      L.pinch_points_note += "; the box side " + std::string(e.side % 2 ? "u" : "v") + " = " +
                             std::to_string(CGAL::to_double(e.value)) +
                             " is a collapsed edge, along which the Jacobian has rank <= 1 everywhere";
  if (!traced) return L;
  internal::lift_arcs(L, lift_point);
  budget.check("lifting");
  internal::insert_split_points(L, internal::Partner_equations(patch), o, lift_point);
  budget.check("split points");
  // the half-branches' proved spans, from the status proof to the fibre proof
  internal::Half_branch_chains chains(o.lifting_exclusion_budget);
  internal::certify_lifting(L, internal::Partner_equations(patch), o, lift_point, &patch, &chains, &budget);
  budget.check("certified lifting");
  internal::lift_sheets(L, internal::Partner_equations(patch), o, lift_point, &chains, &budget);
  budget.check("complete lifting");
  internal::prove_linear_partner_lines(L, internal::Partner_equations(patch), o,
                                       2 * (patch.degree_u() + patch.degree_v()));
  internal::prove_line_arc_fibres(L, internal::Partner_equations(patch), o, &budget);
  internal::bound_sheet_polylines(L, internal::Partner_equations(patch), o, &chains, &budget);
  internal::mark_ends_on_edge_lines(L, o, patch, nullptr);
  return L;
}

/// \brief The split point `sp` of the self-intersection locus of `patch` to any precision: boxes with rational
/// bounds {lo, hi}, narrower than 2^-bits, around its exact coordinates (u, v, l, k) (Locus_split_point::box
/// refined by Krawczyk's test in MPFI arithmetic, lifting/partner_domain_crossings.h). Throws Error if the
/// refinement fails.
inline std::array<std::array<Rational, 2>, 4> refine_split_point(const Rational_bezier_patch<Rational>& patch,
                                                                  const Locus_split_point& sp, int bits) {
  return internal::refine_split_point(internal::Partner_equations(patch), sp, bits);
}

/// \brief The same for the intersection locus of `phi` and `psi`: coordinates (u, t, v, s).
inline std::array<std::array<Rational, 2>, 4> refine_split_point(const Rational_bezier_patch<Rational>& phi,
                                                                  const Rational_bezier_patch<Rational>& psi,
                                                                  const Locus_split_point& sp, int bits) {
  return internal::refine_split_point(internal::Partner_equations(phi, psi), sp, bits);
}

/// \brief The boundary contacts of two patches (see Boundary_contact): every pair of boundary curves is
/// intersected exactly; common pieces are reported once per pair of sides, isolated common points once per
/// point (a corner belongs to two sides) unless they lie on a reported common piece.
inline std::vector<Boundary_contact> boundary_contacts(const Rational_bezier_patch<Rational>& phi,
                                                       const Rational_bezier_patch<Rational>& psi) {
  using Curve = Rational_bezier_curve_3<Rational>;
  std::vector<Boundary_contact> shared, points;
  // (u, v) on the first patch of parameter a along side s
  auto uv = [](int side, const Algebraic_real& a) {
    switch (side) {
      case 0: return std::make_pair(a, Algebraic_real(0));
      case 1: return std::make_pair(Algebraic_real(1), a);
      case 2: return std::make_pair(a, Algebraic_real(1));
      default: return std::make_pair(Algebraic_real(0), a);
    }
  };
  auto on_shared = [&](const std::pair<Algebraic_real, Algebraic_real>& p) {
    for (const auto& c : shared) {
      const auto q0 = uv(c.side_first, c.first_0), q1 = uv(c.side_first, c.first_1);
      const bool u_in = (q0.first <= p.first && p.first <= q1.first) || (q1.first <= p.first && p.first <= q0.first);
      const bool v_in = (q0.second <= p.second && p.second <= q1.second) || (q1.second <= p.second && p.second <= q0.second);
      if (u_in && v_in) return true;
    }
    return false;
  };
  auto is_point = [](const Curve& c) {  // positive weights: constant iff all control points coincide
    for (std::size_t i = 1; i < c.number_of_control_points(); ++i)
      if (c.control_point(i) != c.control_point(0)) return false;
    return true;
  };
  auto approx = [](const Curve& c, const Algebraic_real& a) {
    const auto x = c.evaluate(a.to_double());
    return std::array<double, 3>{x[0], x[1], x[2]};
  };
  for (int s1 = 0; s1 < 4; ++s1) {
    const Curve c1 = phi.boundary_curve<Curve>(s1);
    for (int s2 = 0; s2 < 4; ++s2) {
      const Curve c2 = psi.boundary_curve<Curve>(s2);
      Curve_intersection_result r;
      try {
        r = intersect_curves(c1, c2);
      } catch (const Limit_exceeded&) {
        throw;
      } catch (const Error& e) {  // (a documented limitation of the curve engine: named as this call's)
        throw Error("intersection_locus: the contacts of side " + std::to_string(s1) + " of the first patch and side " +
                    std::to_string(s2) + " of the second are not decided: " + e.what());
      }
      const bool collapsed = is_point(c1) || is_point(c2);
      for (const auto& ov : r.overlaps) {
        Boundary_contact b{s1, s2, !collapsed, ov.s0, ov.s1, ov.t0, ov.t1, approx(c1, ov.s0)};
        if (collapsed)
          points.push_back(b);
        else
          shared.push_back(b);
      }
      for (const auto& p : r.points) points.push_back({s1, s2, false, p.s, p.s, p.t, p.t, approx(c1, p.s)});
    }
  }
  std::vector<Boundary_contact> out = shared;
  std::vector<std::pair<Algebraic_real, Algebraic_real>> seen;
  for (const auto& b : points) {
    const auto p = uv(b.side_first, b.first_0);
    if (on_shared(p)) continue;
    bool dup = false;
    for (const auto& q : seen) dup = dup || (q.first == p.first && q.second == p.second);
    if (dup) continue;
    seen.push_back(p);
    out.push_back(b);
  }
  return out;
}

/// \brief Intersection curve of the patches `phi` (u,v) and `psi` (s,t) (Theorems 2, 3): D(u,t), its certified
/// topology in `o.box`, and every traced point lifted to (u,v) on phi and (s,t) on psi.
inline Surface_locus intersection_locus(const Rational_bezier_patch<Rational>& phi,
                                        const Rational_bezier_patch<Rational>& psi,
                                        const Surface_intersection_options& o = {}) {
  internal::check_patch_limits("intersection_locus", "patch 1", phi, o.limits);
  internal::check_patch_limits("intersection_locus", "patch 2", psi, o.limits);
  const internal::Time_budget budget("intersection_locus", o.limits.time_limit);
  Surface_locus L;
  L.self_intersection = false;
  L.contacts = boundary_contacts(phi, psi);
  if (o.direct_proofs && internal::within_unit_square(o)) {
    if (internal::box_within_transposed_domain(o)) {
      const Common_projection cp = common_projection(phi, psi);
      if (cp.found && !CGAL::is_zero(cp.height_difference))
        return internal::common_projection_locus(phi, psi, o, cp, std::move(L.contacts));
      if (cp.found) {  // Psi = Phi: the identity is a common parent, which decides the overlap
        const auto D = internal::intersection_domains(o);
        const Common_parent_intersection parent = intersect_common_parent(phi, psi, D[0], D[1]);
        if (parent.related) return internal::common_parent_locus(o, parent, std::move(L.contacts));
      }
    }
    // patches with a boundary contact meet: only the others can be apart (a budget of 2000 pairs of pieces)
    if (L.contacts.empty()) {
      const Separation_proof proof = prove_disjoint(phi, psi, 3, 2000);
      if (proof.proved) return internal::separated_patches_locus(o, proof);
    }
  }
  budget.check("direct proofs");
  L.equation = intersection_equation(phi, psi, o.formula);
  if (L.equation.is_degenerate()) {
    // every (u, t) has a solution: typically Psi = Phi o M, two pieces of one parametrized surface
    std::string why = "no common parent was searched: the partner domain is unbounded";
    if (!o.partner_domain_unbounded) {
      const auto D = internal::intersection_domains(o);
      const Common_parent_intersection cp = intersect_common_parent(phi, psi, D[0], D[1]);
      if (cp.related) return internal::common_parent_locus(o, cp, std::move(L.contacts));
      why = cp.reason;
    }
    // a common root at every (u, t), at infinity or with a zero weight: D from the maximal minors of B
    const Maximal_minor_projection mm = maximal_minor_projection(L.equation.matrix, phi, psi);
    if (!mm.computed)
      throw Invalid_input("intersection: det B vanishes identically, " + why + ", and no projection operator from "
                          "maximal minors applies: " + mm.reason);
    L.equation.determinant = mm.polynomial;
    L.equation.square_free = normalized_square_free_part(mm.polynomial);
    L.equation.route = Implicit_equation::Route::maximal_minors;
    L.equation.generic_rank = mm.rank.rank;
  }
  budget.check("elimination");
  const bool traced = internal::topology_is_affordable(
      L, internal::with_partner_proofs(o, internal::Partner_equations(phi, psi)),
      [&](bool vertical, const Rational& c) { return internal::interior_line_is_genuine(vertical, c, o, phi, &psi); });
  budget.check("topology");
  const Bezoutian_matrix& B = L.equation.matrix;
  const internal::Double_bezoutian_matrix B_double(B);
  auto lift_point = [&](double u, double t, const std::array<double, 2>* guess) {
    Locus_point q;
    q.projection = {u, t};
    std::array<double, 2> vs;  // (v, s)
    if (guess) {
      vs = *guess;
      q.lifted = true;
    } else if (L.equation.route == Implicit_equation::Route::determinant) {
      // U = [s^i v^j] with the monomial 1 present: s = U(1,0)/U(0,0), v = U(0,1)/U(0,0)
      long double s = 0, v = 0;
      const auto x = internal::null_vector(internal::transpose(B_double(u, t)));
      q.lifted = internal::monomial_ratio(B.row_monomials, x, 0, s) && internal::monomial_ratio(B.row_monomials, x, 1, v);
      vs = {double(v), double(s)};
    }
    auto residual = [&](double v, double s) {
      auto a = phi.evaluate(u, v), b = psi.evaluate(s, t);
      return std::array<double, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    };
    if (!q.lifted || !std::isfinite(vs[0]) || !std::isfinite(vs[1])) {
      const Parameter_box& d = o.partner_domain;
      const std::array<double, 4> range =
          o.partner_domain_unbounded ? std::array<double, 4>{-2, 2, -2, 2}
                                     : std::array<double, 4>{CGAL::to_double(d.v0), CGAL::to_double(d.v1),
                                                             CGAL::to_double(d.u0), CGAL::to_double(d.u1)};
      vs = internal::grid_seed(residual, range);
      q.lifted = std::isfinite(vs[0]);
      if (!q.lifted) return q;
    }
    vs = internal::polish_partner(residual, vs);
    if (!guess) {
      const Parameter_box& d = o.partner_domain;
      const std::array<double, 4> range =
          o.partner_domain_unbounded ? std::array<double, 4>{-2, 2, -2, 2}
                                     : std::array<double, 4>{CGAL::to_double(d.v0), CGAL::to_double(d.v1),
                                                             CGAL::to_double(d.u0), CGAL::to_double(d.u1)};
      vs = internal::search_if_unsolved(residual, vs, range, false);
    }
    q.partner = vs;
    q.first = {u, vs[0]};
    q.second = {vs[1], t};
    q.point_3d = phi.evaluate(q.first[0], q.first[1]);
    q.residual = internal::distance3(q.point_3d, psi.evaluate(q.second[0], q.second[1]));
    q.genuine = internal::verified(q) && (o.partner_domain_unbounded ||
                (internal::inside(o.partner_domain, q.first) && internal::inside(o.partner_domain, q.second)));
    return q;
  };
  internal::describe_edge_lines(L, o, phi, &psi, lift_point);
  if (!traced) return L;
  internal::lift_arcs(L, lift_point);
  budget.check("lifting");
  internal::insert_split_points(L, internal::Partner_equations(phi, psi), o, lift_point);
  internal::insert_contact_split_points(L, internal::Partner_equations(phi, psi), o, lift_point);
  budget.check("split points");
  // the half-branches' proved spans, from the status proof to the fibre proof
  internal::Half_branch_chains chains(o.lifting_exclusion_budget);
  internal::certify_lifting(L, internal::Partner_equations(phi, psi), o, lift_point, nullptr, &chains, &budget);
  budget.check("certified lifting");
  internal::lift_sheets(L, internal::Partner_equations(phi, psi), o, lift_point, &chains, &budget);
  budget.check("complete lifting");
  internal::prove_linear_partner_lines(L, internal::Partner_equations(phi, psi), o,
                                       phi.degree_u() + phi.degree_v() + psi.degree_u() + psi.degree_v());
  internal::prove_line_arc_fibres(L, internal::Partner_equations(phi, psi), o, &budget);
  internal::bound_sheet_polylines(L, internal::Partner_equations(phi, psi), o, &chains, &budget);
  internal::mark_ends_on_edge_lines(L, o, phi, &psi);
  if (!o.partner_domain_unbounded)
    for (std::size_t i = 0; i < L.topology.vertices.size(); ++i)
      if (L.topology.vertices[i].kind == Curve_topology_vertex::isolated)
        L.isolated_points.push_back(Locus_isolated_point{
            i, isolated_point_partners(phi, psi, L.equation.square_free, L.topology.vertices[i], o.partner_domain)});
  return L;
}

} // namespace bezoutian

#endif // BEZOUTIAN_INTERSECTION_SURFACE_INTERSECTION_H
