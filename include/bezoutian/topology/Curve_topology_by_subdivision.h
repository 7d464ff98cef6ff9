// Certified topology of a plane algebraic curve D(u,v) = 0 inside a box by Bernstein subdivision: the work is
// proportional to what the curve does inside the box, not to its degree over the whole plane (CGAL's curve
// analysis, topology/Cgal_curve_analysis.h, is exact but its cost explodes beyond total degree ~16; the loci of bicubic
// patches have degree 64-108, buse-elkadi-galligo-2008 §3-4).
//
// Method. D is written in the Bernstein basis of each sub-box with MPFI interval coefficients (outward rounding:
// every interval encloses the exact coefficient). A sub-box is
//  * excluded if all coefficients of D have one strict sign (the Bernstein polynomial is a convex combination of
//    them: D has no zero on the closed box);
//  * simple if all forward differences of the coefficients in v (resp. u) have one strict sign, i.e. dD/dv != 0
//    (resp. dD/du != 0) on the closed box. Then every vertical (horizontal) segment of the box meets the curve at
//    most once, so the curve inside the box is a disjoint union of arcs that are graphs v = g(u) over disjoint
//    u-intervals, each with both ends on the boundary (a branch cannot end inside the box, and a graph cannot
//    close up). The crossings with the boundary are computed exactly (real roots of D on the box lines, exact
//    isolation, shared by the boxes along a line); sorted by u, consecutive crossings are the ends of one arc.
//    A crossing at a box corner or a multiple root on an edge (tangency with a box line) makes the box not
//    simple, except on a domain edge across which the box is simple (v = v0 or v1 with dD/dv != 0): there an
//    even-multiplicity root is a contact of the graph with the edge, from inside (the arc passes through the
//    point, which becomes a vertex) or from outside (the point alone: an isolated point of the locus in the
//    domain), decided by exact signs (Touch); an odd-multiplicity root is a tangential crossing;
//    A crossing at a corner of the domain is kept if the curve enters the box there (exact signs of dD/du,
//    dD/dv at the rational corner; if the curve is tangent to an edge there, the exact sign of D along that edge
//    next to the corner); if it does not enter, the corner alone is an isolated point of the locus in the domain;
//    a crossing at an inner grid vertex is not handled (the result is then not certified);
//  * otherwise split at the non-dyadic ratios 15/31 (u) and 16/33 (v) (symmetric data often has features on
//    dyadic lines such as u = 1/2 or on the diagonal; the split lines and grid vertices avoid them).
// The arcs glue along the exact crossings into the components. The result is certified when every sub-box is
// excluded or simple: the curve has then no singular point in the box (near a singular or isolated point
// neither derivative keeps a sign, and the subdivision stops at the first box that reaches `max_depth`, with
// `certified == false`, naming that box). Arc sample points are floating-point (a bracketing root refinement,
// Illinois with bisection steps, on a vertical/horizontal segment where the exact analysis proved exactly one
// crossing); vertex enclosures are exact isolating intervals.
//
// Singular and isolated points (nondegenerate ones: ordinary nodes and acnodes). A box B that is neither
// excluded nor simple is resolved around a critical point p of D when
//  (1) the Hessian of D is regular on B (interval determinant of the Bernstein ranges of D_uu, D_uv, D_vv,
//      the two D_uv entries independent): then grad D is injective on B, so B holds at most one critical point,
//      and the sign of det H says saddle or extremum;
//  (2) Krawczyk's test on grad D proves a critical point p in a small box inside B;
//  (3) D(p) = 0 is proved: exactly, if p is a (small) rational point (D, D_u, D_v vanish there), or by the
//      caller's witness (two branches of D = 0 with distinct tangents through a point of B force grad D = 0
//      there, so that point is p);
//  (4) the exact crossings of D = 0 with the edges of B number 4 (saddle) or 0 (extremum).
// Then D = 0 in B is exactly the four half-branches from p to the four crossings (an ordinary node), or the
// point p alone (an isolated point): D = 0 is smooth in B \ {p} (no other critical point); a component of
// B \ (D = 0) that does not reach the edges of B would hold an extremum of D, a critical point other than p;
// so every arc of D = 0 in B reaches the edges, and the four half-branches at a nondegenerate saddle use up the
// four crossings. If D(p) is proved nonzero the box is split as usual; if D(p) = 0 can be neither proved nor
// excluded, the result is not certified (with that reason). From depth 10 on, a box that is not resolved but holds
// a floating-point critical point p next to the curve is cut 3 x 3 around p instead of split (cut_around): a node
// with almost tangent branches is otherwise left next to an edge, where the box beside it cannot separate them.
//
// Two branches in one box (internal/two_branch_box.h): from depth options.two_branch_depth on, a box that is
// neither excluded, simple nor resolved around a singular point is resolved when D_yy keeps a sign on it (y = v, or
// u) and no point of the box has D = D_y = 0: D = 0 is then two families of graphs over x, told apart by the sign of
// D_y, and the exact crossings of each family pair up along x as in a simple box. Two arcs close together (between
// two nodes with nearly tangent branches, along a thin loop) no longer need boxes thinner than their gap.
// From the same depth, such a box where sigma D has a positive minimum across it is excluded when D_yy keeps the sign
// sigma and sigma D - D_y^2 / (2 min sigma D_yy) > 0 along a segment near the valley's floor (two_branch::no_zero):
// beyond the tips of a thin loop and where two surfaces pass close without meeting, D is small and positive along a
// valley, and a sign test alone needs boxes about sqrt(min D / D_yy) wide there.
//
// A fold in one box (internal/fold_box.h): from depth options.fold_depth (16) on, such a box is resolved when D_yy
// keeps a sign on it and it holds exactly one point p with D = D_y = 0, where D_x != 0 (proved on a thin strip
// around p, where the least value of D on the lines x = const is strictly monotone, and by the two-branch fold test
// on the rest). D = 0 turns back across the lines x = const at p: p ends one arc of each family, and the two arcs
// make one arc of the curve through p, a regular point (a node of its own, so that the lifting's chained proofs
// start at the crossings). At the tip of a loop of width w the tangent is vertical at p and horizontal about w^2
// away; splitting alone needs boxes w^2 wide there.
//
// Multiple points given by the caller (options.multiple_points: an enclosure K of a point p where D vanishes to
// order k, e.g. a common zero of all entries of the Bezoutian matrix, internal/matrix_zero_points.h). Their
// Hessian vanishes, so (1)-(2) fail there. A box B with K strictly inside is resolved when
//  (1') blowing p up (internal/multiple_point_blowup.h) proves that the degree-k form of the Taylor expansion
//       has L real lines, all simple, so that the germ of D = 0 at p is 2L half-branches, and that grad D != 0
//       on (p + [-r, r]^2) \ {p};
//  (2') grad D != 0 on the rest of B: on every sub-box outside that square the Bernstein coefficients of D_u or
//       of D_v keep a sign;
//  (3') the exact crossings of D = 0 with the edges of B number 2L.
// The argument above then gives the 2L arcs from p to the crossings (L = 0: p is an isolated point).
// Multiple points at small rationals are found without the caller: from depth 8 on, a box that resists the
// other tests tries the simplest rational point inside it (denominators below 2^20); if D's exact Taylor
// coefficients there vanish below some order k >= 3, the point is added as a known multiple point.
//
// Singular points at the domain's corners (D, D_u, D_v vanish exactly at a corner: two patches of one smooth surface
// touching at a corner give a cusp there, tangent to a side) are known multiple points too. The box at the corner
// is resolved when the weighted blow-up of internal/corner_blowup.h (Newton polygon with one compact edge) proves H
// half-branches leaving the corner into the box and grad D != 0 on its rectangle minus the corner, grad D != 0 on the
// rest of the box, and D = 0 crosses the box's edges (the corner excluded) exactly H times (resolve_corner).
#ifndef BEZOUTIAN_TOPOLOGY_CURVE_TOPOLOGY_BY_SUBDIVISION_H
#define BEZOUTIAN_TOPOLOGY_CURVE_TOPOLOGY_BY_SUBDIVISION_H

#include <bezoutian/topology/Curve_topology.h>
#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/algebraic/Root_isolation.h>
#include <bezoutian/topology/internal/corner_blowup.h>
#include <bezoutian/topology/internal/double_bernstein_grid.h>
#include <bezoutian/topology/internal/double_double_bernstein.h>
#include <bezoutian/topology/internal/fold_box.h>
#include <bezoutian/arithmetic/interval_krawczyk.h>
#include <bezoutian/arithmetic/simplest_rational.h>
#include <bezoutian/topology/internal/multiple_point_blowup.h>
#include <bezoutian/topology/internal/two_branch_box.h>
#include <bezoutian/arithmetic/number_types.h>

#include <CGAL/Interval_nt.h>
#include <CGAL/Polynomial.h>

#include <mpfi.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace bezoutian {

/// A point p of D = 0 known to the caller to be multiple: the exact p is the only point of `enclosure` where D and
/// all its partial derivatives of order < `multiplicity` vanish, and they do vanish there (e.g. a common zero of all
/// entries of the n x n Bezoutian matrix, whose determinant then vanishes to order n: internal/matrix_zero_points.h).
/// The subdivision proves the rest (the tangent cone, the half-branches, no other critical point nearby).
struct Known_multiple_point {
  Parameter_box enclosure;
  int multiplicity = 3;
};

/// Limits of subdivide_curve_in_box().
struct Subdivision_topology_options {
  int max_depth = 30;             ///< deepest split level (boxes of width about 0.5^30 of the domain); the first box
                                  ///< still unresolved there ends the computation (not certified)
  std::size_t max_boxes = 20000;  ///< total number of boxes examined
  double max_work = 2e8;          ///< bound on interval operations (boxes x (a+1)(b+1)(a+b) for bi-degree (a,b))
  int samples_per_arc = 12;        ///< floating-point sample points per arc piece inside one leaf box
  /// Singular points: from this depth on, a box that is neither excluded nor simple is tested for a
  /// nondegenerate critical point of D (see the header comment).
  int singular_analysis_depth = 2;
  /// Proof that D vanishes at a critical point. Called with a box B in which D has exactly one critical point p,
  /// nondegenerate (proved), and a floating-point approximation of p. Must return true only if it proves that B
  /// contains a point of D = 0 through which pass two branches of D = 0 with distinct tangents (real, or complex
  /// conjugate): the gradient of D vanishes there, so that point is p. Surface_intersection.h proves it from two
  /// distinct partners (Krawczyk's test on the 6 x 6 system). Without it (or when it fails), only rational
  /// critical points are proved (exactly); others leave the result not certified.
  std::function<bool(const Parameter_box&, const std::array<double, 2>&)> singular_point_witness;
  /// Optional: true only if it proves that a sub-box holds no genuine point of the locus (e.g. no partner in the
  /// partner domain, internal/double_partner_witness.h). Such a box is not analysed: it is recorded in
  /// Curve_topology_in_box::excluded_regions and the arcs that enter it end at phantom_cut vertices.
  std::function<bool(const Parameter_box&)> no_genuine_points;
  int genuine_test_depth = 2;  ///< the test is tried on boxes that are not excluded, from this depth
  /// Multiple points of D = 0 (multiplicity >= 3, or degenerate double points) that the Morse analysis of singular
  /// points cannot resolve; a box that contains one is resolved around it by the blow-up analysis of the header
  /// comment. Empty: such points leave the result not certified.
  std::vector<Known_multiple_point> multiple_points;
  /// From this depth on, a box that is neither excluded, simple nor resolved around a singular point tries the
  /// two-branch certificate (two arcs of D = 0 close together, internal/two_branch_box.h) and the valley exclusion
  /// (D small but nonzero along a valley: no arcs); INT_MAX disables both.
  int two_branch_depth = 6;
  /// ... and only when its two branches are closer than this fraction of the box (floating point, a policy: two
  /// branches further apart are separated by a few more splits, into cells where the curve is one graph, and the
  /// lifting's proofs are stronger there).
  double two_branch_max_gap = 1.0 / 8;
  /// From this depth on, such a box (not resolved by the above) tries the fold certificate (one point where the
  /// curve turns back, e.g. the tip of a thin loop, internal/fold_box.h); INT_MAX disables it. A last resort (a
  /// policy): splitting resolves a fold whose horizontal tangent is not close by before this depth, into cells where
  /// the lifting's proofs are stronger; from depth 6 on, fold cells replaced such cells in 10 of the benchmark's 24
  /// problems, with up to 4 times as many unproved statuses, from depth 16 on in none.
  int fold_depth = 16;
};

/// Result of subdivide_curve_in_box().
struct Subdivision_topology_result {
  bool certified = false;                 ///< the topology below is proved
  Curve_topology_in_box topology;         ///< meaningful only if certified
  std::vector<Parameter_box> unresolved;  ///< the box that was neither excluded nor simple at max_depth
  std::size_t boxes = 0;                  ///< boxes examined
  std::string reason;                     ///< why not certified
  std::size_t two_branch_boxes = 0;       ///< leaf boxes resolved by the two-branch certificate
  std::size_t valley_boxes = 0;           ///< boxes excluded as a valley of D above (or below) 0
  std::size_t fold_boxes = 0;             ///< leaf boxes resolved around a fold of the curve (fold_box.h)
};

namespace internal {

// A (a+1) x (b+1) grid of MPFI intervals (Bernstein coefficients c[i][j], i along u).
class Interval_grid {
 public:
  Interval_grid(int a, int b, mpfr_prec_t prec) : a_(a), b_(b), v_(new __mpfi_struct[std::size_t(a + 1) * (b + 1)]) {
    for (std::size_t k = 0; k < size(); ++k) mpfi_init2(&v_[k], prec);
  }
  Interval_grid(const Interval_grid&) = delete;
  Interval_grid& operator=(const Interval_grid&) = delete;
  ~Interval_grid() {
    for (std::size_t k = 0; k < size(); ++k) mpfi_clear(&v_[k]);
  }
  std::size_t size() const { return std::size_t(a_ + 1) * (b_ + 1); }
  mpfi_ptr at(int i, int j) { return &v_[std::size_t(i) * (b_ + 1) + j]; }
  mpfi_srcptr at(int i, int j) const { return &v_[std::size_t(i) * (b_ + 1) + j]; }
  int a() const { return a_; }
  int b() const { return b_; }

 private:
  int a_, b_;
  std::unique_ptr<__mpfi_struct[]> v_;
};

class Subdivision_topology {
 public:
  Subdivision_topology(const Polynomial_2<Integer>& D, const Parameter_box& box, const Subdivision_topology_options& o)
      : D_(D), box_(box), o_(o) {
    a_ = 0;
    b_ = D.degree();
    long bits = 0;
    for (int j = 0; j <= D.degree(); ++j)
      if (!CGAL::is_zero(D[j])) {
        a_ = std::max(a_, D[j].degree());
        for (int i = 0; i <= D[j].degree(); ++i) bits = std::max(bits, long(D[j][i].bit_size()));
      }
    bits_ = bits;
    // the power -> Bernstein conversion loses about a + b bits
    root_prec_ = mpfr_prec_t(96 + 2 * (a_ + b_));
    // the splits are convex combinations (interval widths do not grow), so after the conversion the grids need
    // only enough bits to separate the values met near the curve: 144 bits, much cheaper than root_prec_
    prec_ = std::min<mpfr_prec_t>(root_prec_, 144);
    for (const Known_multiple_point& k : o_.multiple_points) multiple_.push_back(Multiple_point{k, nullptr, false});
    add_singular_corners();
    add_singular_edge_points();
  }

  Subdivision_topology_result run() {
    Subdivision_topology_result res;
    root_grid_ = std::make_shared<Interval_grid>(a_, b_, prec_);
    bernstein_on_box(*root_grid_);
    dd_root_ = double_double_of(*root_grid_, dd_scale_);
    Box root{box_.u0, box_.u1, box_.v0, box_.v1, 0, root_grid_, nullptr};
    root.fast = double_grid_of(*root_grid_);
    std::vector<Box> stack{root};
    const double split_work = double(a_ + 1) * (b_ + 1) * std::max(1, a_ + b_);
    while (!stack.empty()) {
      Box B = stack.back();
      stack.pop_back();
      // budget: an MPFI grid operation counts 1, a double one 1/16 (their measured cost ratio is about 20)
      work_ += split_work / 16;
      cut_pending_ = false;  // set by resolve_singular(B) below
      if (++res.boxes > o_.max_boxes || work_ > o_.max_work) {
        res.reason = "the subdivision budget was exhausted after " + std::to_string(res.boxes - 1) + " boxes";
        return res;
      }
      // Sign tests on the double grid (proved radius); when they decide nothing and the radius has grown large
      // against the coefficients (deep boxes near the curve), the grid is recomputed from the domain's grid in
      // double-double arithmetic (proved error bound), or if that is not sharp enough from the exact-rounded
      // MPFI grid of the domain, and the tests repeated.
      int excluded = B.fast->common_sign(B.fast->radius());
      bool dv = false, du = false;
      for (int attempt = 0; excluded == 0; ++attempt) {
        dv = b_ >= 1 && B.fast->difference_sign(false, B.fast->radius()) != 0;
        du = a_ >= 1 && B.fast->difference_sign(true, B.fast->radius()) != 0;
        if (dv || du || attempt > 1 || B.grid || B.fast->precise()) break;
        // recompute only if the midpoints would decide (or the radius is so large that they mean little)
        if (B.fast->radius() <= std::ldexp(B.fast->max_abs(), -12) && B.fast->common_sign(0) == 0 &&
            (b_ < 1 || B.fast->difference_sign(false, 0) == 0) && (a_ < 1 || B.fast->difference_sign(true, 0) == 0))
          break;
        // first from the double-double grid of the domain (about 10 times cheaper), then if that is not sharp
        // enough from the MPFI grid
        if (attempt == 0 && dd_root_) {
          B.fast = double_double_grid(B);
        } else {
          B.fast = double_grid_of(mpfi_grid(B));
        }
        excluded = B.fast->common_sign(B.fast->radius());
      }
      if (excluded != 0) continue;
      // a box proved free of genuine points is not analysed (also a simple one: its phantom arcs are dropped, so
      // that a locus without genuine points comes out empty)
      if (o_.no_genuine_points && B.depth >= o_.genuine_test_depth &&
          o_.no_genuine_points(Parameter_box{B.u0, B.u1, B.v0, B.v1}) && excise(B))
        continue;
      if (failed_) {
        res.reason = failure_;
        return res;
      }
      if ((dv || du) && resolve(B, dv)) continue;
      if (!failed_ && B.depth >= o_.singular_analysis_depth) {
        const int m = multiple_point_in(B);
        if (m >= 0 && resolve_multiple(B, std::size_t(m))) continue;
        if (!failed_ && resolve_singular(B)) continue;
        if (!failed_ && m < 0 && B.depth >= o_.two_branch_depth && resolve_two_branches(B)) continue;
        if (!failed_ && m < 0 && B.depth >= o_.two_branch_depth && valley_excluded(B)) continue;
        if (!failed_ && m < 0 && B.depth >= o_.fold_depth && resolve_fold(B)) continue;
        if (!failed_ && m < 0 && B.depth >= rational_multiple_depth) {  // a multiple point at a small rational?
          const int r = rational_multiple_point(B);
          if (r >= 0 && resolve_multiple(B, std::size_t(r))) continue;
        }
      }
      if (failed_) {
        res.reason = failure_;
        return res;
      }
      if (B.depth >= o_.max_depth) {  // one unresolved box already rules out a certificate: stop here
        res.unresolved.push_back(Parameter_box{B.u0, B.u1, B.v0, B.v1});
        res.reason = "a box near (" + std::to_string(CGAL::to_double(B.u0)) + ", " +
                     std::to_string(CGAL::to_double(B.v0)) + ") was neither excluded nor simple at depth " +
                     std::to_string(o_.max_depth) + " (a singular, isolated or tangential point)";
        const int m = multiple_point_in(B);
        if (m >= 0)
          res.reason += "; it holds a point of multiplicity >= " + std::to_string(multiple_[m].known.multiplicity) +
                        " whose tangent cone or neighbourhood was not resolved" +
                        (multiple_[m].refuted ? " (its Taylor coefficients of lower order are not all zero)" : "");
        return res;
      }
      if (split_around_multiple(B, stack)) continue;
      if (cut_pending_ && cut_around(B, cut_point_, stack, false)) continue;
      split(B, stack);
    }
    if (!assemble(res.topology)) {
      res.reason = failure_;
      return res;
    }
    res.certified = true;
    res.two_branch_boxes = two_branch_boxes_;
    res.valley_boxes = valley_boxes_;
    res.fold_boxes = fold_boxes_;
    return res;
  }

 private:
  // A sub-box with its Bernstein coefficients: always the double grid; the MPFI grid only once needed.
  struct Box {
    Rational u0, u1, v0, v1;
    int depth;
    std::shared_ptr<Interval_grid> grid;                // may be null
    std::shared_ptr<const Double_bernstein_grid> fast;  // never null
  };
  // A crossing of D = 0 with a line: vertical (u = c) or horizontal (v = c), root index on that line.
  struct Node_key {
    bool vertical;
    Rational c;
    int index;
    bool singular = false;  // a singular point (index into singular_), not a crossing with a line
    bool operator<(const Node_key& o) const {
      if (singular != o.singular) return singular < o.singular;
      if (vertical != o.vertical) return vertical < o.vertical;
      if (c != o.c) return c < o.c;
      return index < o.index;
    }
  };
  struct Arc {
    std::size_t n0, n1;                          // nodes, ordered by the graph coordinate
    std::vector<std::array<double, 2>> inner;    // sample points from n0 to n1 (exclusive)
    Parameter_box cell;                          // the leaf box holding the arc
    int graph_axis = -1;                         // 0: a graph v = g(u) in cell, 1: u = g(v), -1: singular box
                                                 // (n0 the crossing, n1 the singular point) or two-branch box
                                                 // (n0 the crossing the lifting's chained proof starts from)
  };
  struct Line {
    std::vector<Isolated_root> roots;  // on the whole domain range of the other variable
  };

  // Bernstein coefficients of D on the root box: shift and scale the power form (interval Taylor shifts), then
  // b_kl = sum_{i<=k, j<=l} C(k,i) C(l,j) / (C(a,i) C(b,j)) e_ij.
  void bernstein_on_box(Interval_grid& g) const {
    Interval_grid e(a_, b_, root_prec_);
    for (int i = 0; i <= a_; ++i)
      for (int j = 0; j <= b_; ++j) {
        const bool has = j <= D_.degree() && !CGAL::is_zero(D_[j]) && i <= D_[j].degree();
        if (has)
          mpfi_set_z(e.at(i, j), D_[j][i].mpz());
        else
          mpfi_set_ui(e.at(i, j), 0);
      }
    mpfi_t c, w, t;
    mpfi_init2(c, root_prec_);
    mpfi_init2(w, root_prec_);
    mpfi_init2(t, root_prec_);
    // u -> u0 + (u1 - u0) x for every column j
    for (int pass = 0; pass < 2; ++pass) {
      const bool along_u = pass == 0;
      const int n = along_u ? a_ : b_, m = along_u ? b_ : a_;
      const Rational& lo = along_u ? box_.u0 : box_.v0;
      const Rational& hi = along_u ? box_.u1 : box_.v1;
      mpfi_set_q(c, lo.mpq());
      const Rational wd = hi - lo;
      mpfi_set_q(w, wd.mpq());
      auto at = [&](int k, int l) { return along_u ? e.at(k, l) : e.at(l, k); };
      for (int l = 0; l <= m; ++l) {
        if (!CGAL::is_zero(lo))  // Taylor shift by lo (synthetic division, O(n^2))
          for (int k = 0; k < n; ++k)
            for (int r = n - 1; r >= k; --r) {
              mpfi_mul(t, at(r + 1, l), c);
              mpfi_add(at(r, l), at(r, l), t);
            }
        mpfi_set_ui(t, 1);
        for (int k = 0; k <= n; ++k) {  // scale x^k by width^k
          mpfi_mul(at(k, l), at(k, l), t);
          mpfi_mul(t, t, w);
        }
      }
    }
    // power -> Bernstein, first along u then along v
    auto binom = [](int n, int k) {
      Integer r(1);
      for (int i = 1; i <= k; ++i) r = r * Integer(n - k + i) / Integer(i);
      return r;
    };
    for (int pass = 0; pass < 2; ++pass) {
      const bool along_u = pass == 0;
      const int n = along_u ? a_ : b_, m = along_u ? b_ : a_;
      auto src = [&](int k, int l) { return along_u ? e.at(k, l) : e.at(l, k); };
      std::vector<Rational> q(std::size_t(n + 1) * (n + 1));
      for (int k = 0; k <= n; ++k)
        for (int i = 0; i <= k; ++i) q[std::size_t(k) * (n + 1) + i] = Rational(binom(k, i)) / Rational(binom(n, i));
      std::vector<__mpfi_struct> out(std::size_t(n + 1));
      for (auto& x : out) mpfi_init2(&x, root_prec_);
      for (int l = 0; l <= m; ++l) {
        for (int k = 0; k <= n; ++k) {
          mpfi_set_ui(&out[k], 0);
          for (int i = 0; i <= k; ++i) {
            mpfi_mul_q(t, src(i, l), q[std::size_t(k) * (n + 1) + i].mpq());
            mpfi_add(&out[k], &out[k], t);
          }
        }
        for (int k = 0; k <= n; ++k) mpfi_set(src(k, l), &out[k]);
      }
      for (auto& x : out) mpfi_clear(&x);
    }
    for (int i = 0; i <= a_; ++i)
      for (int j = 0; j <= b_; ++j) mpfi_set(g.at(i, j), e.at(i, j));
    mpfi_clear(c);
    mpfi_clear(w);
    mpfi_clear(t);
  }

  // de Casteljau at ratio `ratio` in (0,1) along u (or v): left/right children.
  void split_grid(const Interval_grid& g, bool along_u, const Rational& ratio, Interval_grid& left,
                  Interval_grid& right) const {
    const int n = along_u ? a_ : b_, m = along_u ? b_ : a_;
    mpfi_t r, s, t;
    mpfi_init2(r, prec_);
    mpfi_init2(s, prec_);
    mpfi_init2(t, prec_);
    mpfi_set_q(r, ratio.mpq());
    mpfi_ui_sub(s, 1, r);
    std::vector<__mpfi_struct> w(std::size_t(n + 1));
    for (auto& x : w) mpfi_init2(&x, prec_);
    for (int l = 0; l <= m; ++l) {
      for (int k = 0; k <= n; ++k) mpfi_set(&w[k], along_u ? g.at(k, l) : g.at(l, k));
      auto L = [&](int k) { return along_u ? left.at(k, l) : left.at(l, k); };
      auto R = [&](int k) { return along_u ? right.at(k, l) : right.at(l, k); };
      mpfi_set(L(0), &w[0]);
      mpfi_set(R(n), &w[n]);
      for (int level = 1; level <= n; ++level) {
        for (int k = 0; k + level <= n; ++k) {
          mpfi_mul(t, &w[k], s);
          mpfi_mul(&w[k], &w[k + 1], r);
          mpfi_add(&w[k], &w[k], t);
        }
        mpfi_set(L(level), &w[0]);
        mpfi_set(R(n - level), &w[n - level]);
      }
    }
    for (auto& x : w) mpfi_clear(&x);
    mpfi_clear(r);
    mpfi_clear(s);
    mpfi_clear(t);
  }

  // Different non-dyadic ratios in u and v: the grid then never has a vertex on the diagonal u = v or at a
  // dyadic point (symmetric data puts curve features there).
  static Rational ratio(bool along_u) { return along_u ? Rational(15, 31) : Rational(16, 33); }

  // The four children (double grids only; their MPFI grids are extracted from the domain's when needed).
  void split(const Box& B, std::vector<Box>& stack) const {
    const Rational um = B.u0 + (B.u1 - B.u0) * ratio(true), vm = B.v0 + (B.v1 - B.v0) * ratio(false);
    Double_bernstein_grid L, R;
    B.fast->split(true, CGAL::to_double(ratio(true)), L, R);
    for (int side = 0; side < 2; ++side) {
      auto lo = std::make_shared<Double_bernstein_grid>(), hi = std::make_shared<Double_bernstein_grid>();
      (side == 0 ? L : R).split(false, CGAL::to_double(ratio(false)), *lo, *hi);
      const Rational& u0 = side == 0 ? B.u0 : um;
      const Rational& u1 = side == 0 ? um : B.u1;
      stack.push_back(Box{u0, u1, B.v0, vm, B.depth + 1, nullptr, lo});
      stack.push_back(Box{u0, u1, vm, B.v1, B.depth + 1, nullptr, hi});
    }
  }

  // The MPFI grid of B (cached in B): the domain's grid restricted to B by de Casteljau at the rational ratios
  // of B's edges (convex combinations: the widths stay at the working precision).
  const Interval_grid& mpfi_grid(Box& B) {
    if (B.grid) return *B.grid;
    work_ += 4 * double(a_ + 1) * (b_ + 1) * std::max(1, a_ + b_);
    auto g = std::make_shared<Interval_grid>(a_, b_, prec_);
    for (std::size_t k = 0; k < g->size(); ++k) mpfi_set(g->at(int(k / (b_ + 1)), int(k % (b_ + 1))),
                                                       root_grid_->at(int(k / (b_ + 1)), int(k % (b_ + 1))));
    Interval_grid left(a_, b_, prec_), right(a_, b_, prec_);
    for (int pass = 0; pass < 2; ++pass) {
      const bool along_u = pass == 0;
      const Rational& D0 = along_u ? box_.u0 : box_.v0;
      const Rational W = along_u ? box_.u1 - box_.u0 : box_.v1 - box_.v0;
      const Rational lo = ((along_u ? B.u0 : B.v0) - D0) / W, hi = ((along_u ? B.u1 : B.v1) - D0) / W;
      if (hi < Rational(1)) {  // keep [0, hi]
        split_grid(*g, along_u, hi, left, right);
        copy_grid(left, *g);
      }
      if (lo > Rational(0)) {  // then [lo/hi, 1] of that
        split_grid(*g, along_u, lo / hi, left, right);
        copy_grid(right, *g);
      }
    }
    B.grid = g;
    return *g;
  }
  static void copy_grid(const Interval_grid& from, Interval_grid& to) {
    for (int i = 0; i <= from.a(); ++i)
      for (int j = 0; j <= from.b(); ++j) mpfi_set(to.at(i, j), from.at(i, j));
  }

  // Double grid of an MPFI grid: midpoints rounded to nearest, scaled by one power of two, and the largest
  // distance from a midpoint to its interval's ends rounded upwards.
  std::shared_ptr<const Double_bernstein_grid> double_grid_of(const Interval_grid& g) const {
    const int a_ = g.a(), b_ = g.b();  // D's grid, or one of its derivatives' (no_critical_point_outside)
    auto f = std::make_shared<Double_bernstein_grid>(a_, b_);
    mpfr_t mid, d;
    mpfr_init2(mid, prec_);
    mpfr_init2(d, prec_);
    long emax = LONG_MIN;
    for (int i = 0; i <= a_; ++i)
      for (int j = 0; j <= b_; ++j) {
        mpfi_mid(mid, g.at(i, j));
        if (!mpfr_zero_p(mid)) emax = std::max(emax, long(mpfr_get_exp(mid)));
        if (!mpfr_zero_p(&g.at(i, j)->right)) emax = std::max(emax, long(mpfr_get_exp(&g.at(i, j)->right)));
        if (!mpfr_zero_p(&g.at(i, j)->left)) emax = std::max(emax, long(mpfr_get_exp(&g.at(i, j)->left)));
      }
    if (emax == LONG_MIN) emax = 0;
    double rho = 0;
    for (int i = 0; i <= a_; ++i)
      for (int j = 0; j <= b_; ++j) {
        mpfi_mid(mid, g.at(i, j));
        mpfr_mul_2si(mid, mid, -emax, MPFR_RNDN);
        const double m = mpfr_get_d(mid, MPFR_RNDN);
        f->at(i, j) = m;
        // radius: max(right - m, m - left) in the scaled units, rounded up
        mpfr_mul_2si(d, &g.at(i, j)->right, -emax, MPFR_RNDU);
        mpfr_sub_d(d, d, m, MPFR_RNDU);
        rho = std::max(rho, mpfr_get_d(d, MPFR_RNDU));
        mpfr_mul_2si(d, &g.at(i, j)->left, -emax, MPFR_RNDD);
        mpfr_d_sub(d, m, d, MPFR_RNDU);
        rho = std::max(rho, mpfr_get_d(d, MPFR_RNDU));
      }
    mpfr_clear(mid);
    mpfr_clear(d);
    f->set_radius(rho);
    f->set_exponent(int(emax));
    f->rescale();
    return f;
  }

  // The double grid of B from the double-double restriction of the domain's grid (proved radius; about 4 times
  // cheaper than the MPFI restriction, and usually as sharp as a double grid can be). dd_root_ must exist.
  std::shared_ptr<const Double_bernstein_grid> double_double_grid(const Box& B) {
    work_ += double(a_ + 1) * (b_ + 1) * std::max(1, a_ + b_);
    return dd_root_->restrict_to((B.u0 - box_.u0) / (box_.u1 - box_.u0), (B.u1 - box_.u0) / (box_.u1 - box_.u0),
                                 (B.v0 - box_.v0) / (box_.v1 - box_.v0), (B.v1 - box_.v0) / (box_.v1 - box_.v0),
                                 dd_scale_);
  }

  // An interval grid of B from the double-double restriction of the domain's grid: [hi + lo - E, hi + lo + E]
  // times 2^dd_scale_ (outward rounded; a valid enclosure, less sharp than the MPFI restriction), or null.
  std::shared_ptr<const Interval_grid> dd_interval_grid(const Box& B) {
    if (!dd_root_) return nullptr;
    std::vector<Double_double> v;
    double E = 0;
    dd_root_->restrict_values((B.u0 - box_.u0) / (box_.u1 - box_.u0), (B.u1 - box_.u0) / (box_.u1 - box_.u0),
                              (B.v0 - box_.v0) / (box_.v1 - box_.v0), (B.v1 - box_.v0) / (box_.v1 - box_.v0), v, E);
    work_ += double(a_ + 1) * (b_ + 1) * std::max(1, a_ + b_);
    auto g = std::make_shared<Interval_grid>(a_, b_, prec_);
    mpfi_t e;
    mpfi_init2(e, 64);
    mpfi_interv_d(e, -E, E);
    for (int i = 0; i <= a_; ++i)
      for (int j = 0; j <= b_; ++j) {
        const Double_double& x = v[std::size_t(i) * (b_ + 1) + j];
        mpfi_set_d(g->at(i, j), x.hi);
        mpfi_add_d(g->at(i, j), g->at(i, j), x.lo);
        mpfi_add(g->at(i, j), g->at(i, j), e);
        mpfi_mul_2si(g->at(i, j), g->at(i, j), dd_scale_);
      }
    mpfi_clear(e);
    return g;
  }

  // The double-double form of an MPFI grid (internal/double_double_bernstein.h): midpoints split into hi + lo,
  // scaled by 2^-scale; the error bound adds the interval radii and what the split drops.
  std::shared_ptr<const Double_double_bernstein> double_double_of(const Interval_grid& g, int& scale) const {
    auto f = std::make_shared<Double_double_bernstein>(a_, b_);
    const mpfr_prec_t p = prec_ + 128;
    mpfr_t mid, t, d;
    mpfr_init2(mid, p);
    mpfr_init2(t, p);
    mpfr_init2(d, 64);
    long emax = LONG_MIN;
    for (int i = 0; i <= a_; ++i)
      for (int j = 0; j <= b_; ++j)
        for (mpfr_srcptr e : {&g.at(i, j)->left, &g.at(i, j)->right})
          if (!mpfr_zero_p(e)) emax = std::max(emax, long(mpfr_get_exp(e)));
    if (emax == LONG_MIN) return nullptr;
    double err = 0, mag = 0;
    for (int i = 0; i <= a_; ++i)
      for (int j = 0; j <= b_; ++j) {
        mpfi_mid(mid, g.at(i, j));
        mpfr_mul_2si(mid, mid, -emax, MPFR_RNDN);  // exact (a power of two)
        const double hi = mpfr_get_d(mid, MPFR_RNDN);
        mpfr_sub_d(t, mid, hi, MPFR_RNDN);  // exact at p bits
        const double lo = mpfr_get_d(t, MPFR_RNDN);
        mpfr_sub_d(t, t, lo, MPFR_RNDN);  // exact
        double e = std::fabs(mpfr_get_d(t, MPFR_RNDU)) * 2;
        // radius of the interval about its midpoint, in the scaled units, rounded up
        mpfr_sub(d, &g.at(i, j)->right, &g.at(i, j)->left, MPFR_RNDU);
        mpfr_mul_2si(d, d, -emax, MPFR_RNDU);
        e += mpfr_get_d(d, MPFR_RNDU);
        err = std::max(err, e);
        mag = std::max(mag, std::fabs(hi) + std::fabs(lo));
        f->at(i, j) = Double_double{hi, lo};
      }
    mpfr_clear(mid);
    mpfr_clear(t);
    mpfr_clear(d);
    err = err * (1 + 1e-14) + 1e-300;
    f->set_bounds(err, (mag + err) * (1 + 1e-14));
    scale = int(emax);
    return f;
  }

  // Exact roots of D on the line u = c (vertical) or v = c, over the domain range of the other variable.
  const Line& line(bool vertical, const Rational& c) {
    auto key = std::make_pair(vertical, c);
    auto it = lines_.find(key);
    if (it != lines_.end()) return it->second;
    Polynomial_1<Rational> f(0);
    if (vertical) {  // f(v) = sum_j D_j(c) v^j
      std::vector<Rational> co;
      for (int j = 0; j <= D_.degree(); ++j) {
        Rational x(0);
        if (!CGAL::is_zero(D_[j]))
          for (int i = D_[j].degree(); i >= 0; --i) x = x * c + Rational(D_[j][i]);
        co.push_back(x);
      }
      f = Polynomial_1<Rational>(co.begin(), co.end());
    } else {  // f(u) = sum_j D_j(u) c^j
      for (int j = D_.degree(); j >= 0; --j) {
        std::vector<Rational> co;
        if (!CGAL::is_zero(D_[j]))
          for (int i = 0; i <= D_[j].degree(); ++i) co.push_back(Rational(D_[j][i]));
        f = f * Polynomial_1<Rational>(c) + (co.empty() ? Polynomial_1<Rational>(0) : Polynomial_1<Rational>(co.begin(), co.end()));
      }
    }
    Line L;
    if (CGAL::is_zero(f)) {
      fail(std::string("D vanishes on the whole line ") + (vertical ? "u = " : "v = ") + std::to_string(CGAL::to_double(c)));
    } else if (f.degree() >= 1) {
      L.roots = vertical ? isolate_real_roots(f, box_.v0, box_.v1) : isolate_real_roots(f, box_.u0, box_.u1);
    }
    return lines_.emplace(key, std::move(L)).first->second;
  }

  void fail(const std::string& why) {
    if (!failed_) failure_ = why;
    failed_ = true;
  }

  std::size_t node(bool vertical, const Rational& c, int index) {
    const Node_key k{vertical, c, index};
    auto it = nodes_.find(k);
    if (it != nodes_.end()) return it->second;
    keys_.push_back(k);
    return nodes_[k] = keys_.size() - 1;
  }

  // A tangential contact of D = 0 with a domain edge (an even-multiplicity root x of D on the edge line, strictly
  // inside a box edge) in a box that is simple across the edge (for the edge v = c: dD/dv != 0 on the box, so the
  // curve is a graph v = g(u) there, through (x, c) with g'(x) = 0). D(u, c) = D(u, g(u)) + D_v (c - g(u)) = D_v
  // (c - g(u)) (D_v at an intermediate point, of one sign on the box), so the sign of D on the edge next to x,
  // that of its m-th derivative at x (m even), gives the side of g: the curve touches the edge from inside the
  // domain (its arc passes through the contact point) or from outside (the point alone is in the domain).
  struct Touch {
    bool vertical;
    Rational c;
    int index;
    Algebraic_real position;
    bool inside;
  };
  // D restricted to the line u = c (vertical, a polynomial in v) or v = c (in u), and the derivative of D across
  // that line restricted to it.
  void restriction(bool vertical, const Rational& c, Polynomial_1<Rational>& P, Polynomial_1<Rational>* Q = nullptr) const {
    std::vector<Rational> p, q;
    if (!vertical) {  // v = c: p(u) = sum_j D_j(u) c^j, q(u) = sum_j j D_j(u) c^(j-1)
      std::vector<Rational> cp(1, Rational(1));
      for (int j = 1; j <= D_.degree(); ++j) cp.push_back(cp.back() * c);
      for (int j = 0; j <= D_.degree(); ++j)
        for (int i = 0; i <= D_[j].degree(); ++i) {
          if (CGAL::is_zero(D_[j][i])) continue;
          if (p.size() <= std::size_t(i)) p.resize(std::size_t(i + 1), Rational(0)), q.resize(std::size_t(i + 1), Rational(0));
          p[std::size_t(i)] += Rational(D_[j][i]) * cp[std::size_t(j)];
          if (j >= 1) q[std::size_t(i)] += Rational(D_[j][i]) * Rational(j) * cp[std::size_t(j - 1)];
        }
    } else {  // u = c: p(v) = sum_j D_j(c) v^j, q(v) = sum_j D_j'(c) v^j
      for (int j = 0; j <= D_.degree(); ++j) {
        Rational a(0), da(0);
        for (int i = D_[j].degree(); i >= 0; --i) {
          da = da * c + a;
          a = a * c + Rational(D_[j][i]);
        }
        p.push_back(a);
        q.push_back(da);
      }
    }
    if (p.empty()) p.push_back(Rational(0));
    if (q.empty()) q.push_back(Rational(0));
    P = Polynomial_1<Rational>(p.begin(), p.end());
    if (Q) *Q = Polynomial_1<Rational>(q.begin(), q.end());
  }

  // 1: from inside, 0: from outside, -1: undecided (a zero sign: cannot happen in a box simple across the edge)
  int contact_from_inside(bool vertical, const Rational& c, const Algebraic_real& x, int multiplicity) const {
    Polynomial_1<Rational> P, Q;
    restriction(vertical, c, P, &Q);
    for (int k = 0; k < multiplicity; ++k) P = CGAL::differentiate(P);
    const int side = x.sign_of(P), across = x.sign_of(Q);
    // bottom / left edge: inside iff sign D(edge) = -sign(D across); top / right edge: iff the signs agree
    if (side == 0 || across == 0) return -1;
    const bool low_edge = vertical ? c == box_.u0 : c == box_.v0;
    return (low_edge ? side == -across : side == across) ? 1 : 0;
  }

  // Sign of D on the line (vertical: u = c, in v; else v = c, in u) just beyond the rational root x, on the side
  // `direction` (+1 / -1): the sign of the first nonvanishing derivative there, times direction^order.
  int sign_next_to(bool vertical, const Rational& c, const Rational& x, int direction) const {
    Polynomial_1<Rational> P;
    restriction(vertical, c, P);
    for (int order = 0; !CGAL::is_zero(P); ++order, P = CGAL::differentiate(P)) {
      const int s = CGAL::sign(P.evaluate(x));
      if (s != 0) return order % 2 == 0 ? s : s * direction;
    }
    return 0;
  }

  // A crossing on one edge of a box: its line, its root there and its position along the sorting coordinate.
  struct Crossing {
    bool vertical;
    Rational c;
    int index;
    Algebraic_real position;  // u for dv-simple boxes, v for du-simple boxes
  };

  // Collects the crossings of the edge (line `vertical` at c, other coordinate in [lo, hi]). Returns false if a
  // crossing is at an end (a box corner) or multiple (tangency with the line).
  // `touches` (only for a domain edge of a box that is simple across it): multiple roots strictly inside the edge
  // are allowed there (see contact_with_domain_edge) instead of making the box unresolved.
  // A singular point of the domain's boundary that ends half-branches of the box being resolved (resolve_corner,
  // resolve_edge_point): not a crossing of the box's edges through it.
  struct Excluded_point {
    Algebraic_real u, v;
    bool on(bool vertical, const Rational& c, const Algebraic_real& x) const {
      return vertical ? u.compare(c) == 0 && x.compare(v) == 0 : v.compare(c) == 0 && x.compare(u) == 0;
    }
  };

  bool edge_crossings(bool vertical, const Rational& c, const Rational& lo, const Rational& hi, bool sort_by_u,
                      std::vector<Crossing>& out, std::vector<Touch>* touches = nullptr,
                      const Excluded_point* excluded = nullptr) {
    const Line& L = line(vertical, c);
    if (failed_) return false;
    for (std::size_t k = 0; k < L.roots.size(); ++k) {
      const Algebraic_real& x = L.roots[k].root;
      const int cl = x.compare(lo), ch = x.compare(hi);
      if (cl < 0 || ch > 0) continue;
      if (excluded && excluded->on(vertical, c, x)) continue;
      if (L.roots[k].multiplicity > 1) {
        // at a domain corner, on an edge across which the box is simple: the curve is tangent to that edge at the
        // corner, decided by corner_crossing
        if (touches && (cl == 0 || ch == 0) && is_domain_corner(vertical, c, cl == 0 ? lo : hi)) continue;
        if (!touches || cl == 0 || ch == 0) return false;
        if (L.roots[k].multiplicity % 2 == 0) {  // the curve touches the edge without crossing it
          const int inside = contact_from_inside(vertical, c, x, L.roots[k].multiplicity);
          if (inside < 0) return false;
          touches->push_back(Touch{vertical, c, int(k), x, inside == 1});
          continue;
        }
        // odd multiplicity: a tangential crossing, an ordinary crossing for the topology (below)
      }
      if (cl == 0 || ch == 0) {  // at a box corner: domain corners are handled by corner_crossing
        if (!is_domain_corner(vertical, c, cl == 0 ? lo : hi)) {
          fail("the curve passes through a vertex of the subdivision grid");
          return false;
        }
        continue;
      }
      // the sorting coordinate: along a vertical line u = c is fixed, along a horizontal one u = x
      const bool coordinate_is_fixed = vertical == sort_by_u;
      out.push_back(Crossing{vertical, c, int(k), coordinate_is_fixed ? Algebraic_real(c) : x});
    }
    return true;
  }

  bool is_domain_corner(bool vertical, const Rational& c, const Rational& e) const {
    return (vertical ? (c == box_.u0 || c == box_.u1) : (c == box_.v0 || c == box_.v1)) &&
           (vertical ? (e == box_.v0 || e == box_.v1) : (e == box_.u0 || e == box_.u1));
  }

  // The curve through the domain corner (cu, cv) of box B (D(cu, cv) = 0): a crossing if the curve enters the box
  // there, i.e. a tangent direction (D_v, -D_u) points strictly into the box's quadrant at that corner.
  // If the curve is tangent to a domain edge at the corner (D_v = 0 there: tangent to u = cu), first-order signs do
  // not decide. In a box where dD/du != 0 (`simple` 2; 1: dD/dv != 0, 0: neither) the curve is a graph u = h(v)
  // with h(cv) = cu, and D(cu, v) = D(h(v), v) + D_u (cu - h(v)) = D_u (cu - h(v)) (D_u at an intermediate point,
  // of one sign on B): the side of h next to the corner is the exact sign of D on the edge there. Symmetrically for
  // D_u = 0. If the curve does not enter the quadrant, the corner alone is a point of the locus in the domain (an
  // isolated point on the boundary).
  // `isolated` receives the nodes of corners that the curve passes from outside (the caller records them when it
  // resolves the box).
  bool corner_crossing(const Box& B, const Rational& cu, const Rational& cv, bool sort_by_u, int simple,
                       std::vector<Crossing>& out, std::vector<std::size_t>& isolated) {
    const auto e = exact_jet(cu, cv);  // D, D_u, D_v at the corner
    if (e[0] != 0) return true;
    const int tx = CGAL::sign(e[2]), ty = -CGAL::sign(e[1]);
    const int sx = cu == B.u0 ? 1 : -1, sy = cv == B.v0 ? 1 : -1;
    bool enters = false, tangent = false;
    if (tx != 0 && ty != 0) {
      enters = tx * sx == ty * sy;
    } else if ((tx == 0) != (ty == 0) && simple == (tx == 0 ? 2 : 1)) {
      // tangent to the edge u = cu (tx == 0: a graph u = h(v), the side of h - cu next to the corner) or to v = cv
      const bool on_u_line = tx == 0;
      const int s = on_u_line ? sign_next_to(true, cu, cv, sy) : sign_next_to(false, cv, cu, sx);
      if (s == 0) {
        fail("internal inconsistency: D vanishes on a domain edge");
        return false;
      }
      enters = -s * CGAL::sign(on_u_line ? e[1] : e[2]) == (on_u_line ? sx : sy);
      tangent = true;
    } else {
      fail(tx == 0 && ty == 0 ? "the curve is singular at a corner of the domain"
                              : "the curve is tangent to a domain edge at a corner of the domain");
      return false;
    }
    const Line& L = line(true, cu);
    for (std::size_t k = 0; k < L.roots.size(); ++k)
      if (L.roots[k].root.compare(cv) == 0) {
        const std::size_t n = node(true, cu, int(k));
        if (tangent) corner_tangent_.insert(n);
        if (enters)
          out.push_back(Crossing{true, cu, int(k), Algebraic_real(sort_by_u ? cu : cv)});
        else
          isolated.push_back(n);  // the corner alone: an isolated point of the locus in the domain
        return true;
      }
    fail("internal inconsistency: a corner root is missing on its line");
    return false;
  }

  // A simple box: crossings sorted along u (dv != 0) or v (du != 0); consecutive pairs are arcs.
  bool resolve(const Box& B, bool dv_simple) {
    std::vector<Crossing> cr;
    std::vector<Touch> touches;
    const bool by_u = dv_simple;
    // contacts are allowed on the domain edges across which the box is simple (v = v0, v1 if dD/dv != 0)
    auto t_vertical = [&](const Rational& c) { return !dv_simple && (c == box_.u0 || c == box_.u1) ? &touches : nullptr; };
    auto t_horizontal = [&](const Rational& c) { return dv_simple && (c == box_.v0 || c == box_.v1) ? &touches : nullptr; };
    if (!edge_crossings(true, B.u0, B.v0, B.v1, by_u, cr, t_vertical(B.u0)) ||
        !edge_crossings(true, B.u1, B.v0, B.v1, by_u, cr, t_vertical(B.u1)) ||
        !edge_crossings(false, B.v0, B.u0, B.u1, by_u, cr, t_horizontal(B.v0)) ||
        !edge_crossings(false, B.v1, B.u0, B.u1, by_u, cr, t_horizontal(B.v1)))
      return false;
    std::vector<std::size_t> isolated_corners;
    for (const Rational* cu : {&B.u0, &B.u1})
      for (const Rational* cv : {&B.v0, &B.v1})
        if ((*cu == box_.u0 || *cu == box_.u1) && (*cv == box_.v0 || *cv == box_.v1) &&
            !corner_crossing(B, *cu, *cv, by_u, dv_simple ? 1 : 2, cr, isolated_corners))
          return false;
    if (cr.size() % 2 != 0) return false;  // cannot happen for a simple box; be safe and subdivide
    std::sort(cr.begin(), cr.end(), [](const Crossing& x, const Crossing& y) { return x.position < y.position; });
    std::sort(touches.begin(), touches.end(), [](const Touch& x, const Touch& y) { return x.position < y.position; });
    // a contact from inside lies on one arc (the graph passes through it): it splits that arc
    std::vector<std::vector<const Touch*>> on_arc(cr.size() / 2);
    for (const Touch& t : touches) {
      if (!t.inside) continue;
      bool placed = false;
      for (std::size_t k = 0; k + 1 < cr.size() && !placed; k += 2)
        if (cr[k].position < t.position && t.position < cr[k + 1].position) on_arc[k / 2].push_back(&t), placed = true;
      if (!placed) return false;  // not consistent with a graph: subdivide instead
    }
    for (std::size_t k = 0; k + 1 < cr.size(); k += 2) {
      std::size_t from = node(cr[k].vertical, cr[k].c, cr[k].index);
      Algebraic_real from_pos = cr[k].position;
      auto add = [&](std::size_t to, const Algebraic_real& to_pos) {
        Arc arc{from, to, {}, Parameter_box{B.u0, B.u1, B.v0, B.v1}, by_u ? 0 : 1};
        sample_arc(B, by_u, from_pos, to_pos, arc.inner);
        arcs_.push_back(arc);
        from = to;
        from_pos = to_pos;
      };
      for (const Touch* t : on_arc[k / 2]) {
        const std::size_t n = node(t->vertical, t->c, t->index);
        touch_[n] = 2;
        add(n, t->position);
      }
      add(node(cr[k + 1].vertical, cr[k + 1].c, cr[k + 1].index), cr[k + 1].position);
    }
    for (const Touch& t : touches)
      if (!t.inside) touch_[node(t.vertical, t.c, t.index)] = 0;  // the contact point alone: an isolated point
    for (std::size_t n : isolated_corners) touch_[n] = 0;
    return true;
  }

  // A box proved free of genuine points: its edge crossings become phantom_cut vertices (the arcs of the
  // neighbouring boxes end there). False (the box is then split) if a crossing is at a corner or multiple.
  bool excise(const Box& B) {
    // edges on the domain boundary have no neighbour: their crossings (even multiple ones) do not matter
    std::vector<Crossing> cr;
    if ((B.u0 != box_.u0 && !edge_crossings(true, B.u0, B.v0, B.v1, true, cr)) ||
        (B.u1 != box_.u1 && !edge_crossings(true, B.u1, B.v0, B.v1, true, cr)) ||
        (B.v0 != box_.v0 && !edge_crossings(false, B.v0, B.u0, B.u1, true, cr)) ||
        (B.v1 != box_.v1 && !edge_crossings(false, B.v1, B.u0, B.u1, true, cr)))
      return false;
    for (const Crossing& c : cr) cut_.insert(node(c.vertical, c.c, c.index));
    excised_.push_back(Parameter_box{B.u0, B.u1, B.v0, B.v1});
    return true;
  }

  // ---- two branches in one box (internal/two_branch_box.h) ----
  // The sign of D_y at a crossing of an edge of B (y = v for axis 0, u for axis 1): first from B's grid (the
  // Bernstein coefficients of D_y on that edge, differences of the grid's, at the crossing's isolating interval, in
  // interval arithmetic), else exactly (along its line D_y is the derivative of D restricted to the line, across
  // it the restricted derivative across; both cached per line).
  int cross_derivative_sign(const Box& B, const Crossing& c, int axis) {
    const Algebraic_real& r = line_root(c);
    const Double_bernstein_grid& G = *B.fast;
    const bool across_u = axis == 1;  // D_u: differences along i, else along j
    const int a = G.a(), b = G.b();
    if ((across_u ? a : b) >= 1) {
      const Rational &lo = c.vertical ? B.v0 : B.u0, &hi = c.vertical ? B.v1 : B.u1;
      const auto tl = CGAL::to_interval((r.lower() - lo) / (hi - lo)), th = CGAL::to_interval((r.upper() - lo) / (hi - lo));
      const Double_interval t{std::max(0.0, tl.first), std::min(1.0, th.second)};
      const bool high = c.vertical ? c.c == B.u1 : c.c == B.v1;  // which edge of B: u = u1 (v = v1) or u0 (v0)
      const int n = c.vertical ? b - (across_u ? 0 : 1) : a - (across_u ? 1 : 0);  // degree along the edge
      const double r2 = 2 * G.radius();
      std::vector<Double_interval> w(std::size_t(n + 1));
      for (int k = 0; k <= n; ++k) {
        // the grid index of the k-th coefficient along the edge and the difference across y
        const int i = c.vertical ? (high ? (across_u ? a - 1 : a) : 0) : k, j = c.vertical ? k : (high ? (across_u ? b : b - 1) : 0);
        const double g1 = across_u ? G.at(i + 1, j) : G.at(i, j + 1), g0 = G.at(i, j);
        w[std::size_t(k)] = (Double_interval{g1, g1} - Double_interval{g0, g0}) + Double_interval{-r2, r2};
      }
      const Double_interval s = Double_interval::widen(1 - t.hi, 1 - t.lo);
      for (int level = 1; level <= n; ++level)
        for (int k = 0; k + level <= n; ++k) w[std::size_t(k)] = s * w[std::size_t(k)] + t * w[std::size_t(k + 1)];
      if (w[0].lo > 0) return 1;
      if (w[0].hi < 0) return -1;
    }
    auto key = std::make_pair(c.vertical, c.c);
    auto it = restrictions_.find(key);
    if (it == restrictions_.end()) {
      std::pair<Polynomial_1<Rational>, Polynomial_1<Rational>> PQ;
      restriction(c.vertical, c.c, PQ.first, &PQ.second);
      PQ.first = CGAL::differentiate(PQ.first);
      it = restrictions_.emplace(key, std::move(PQ)).first;
    }
    const bool along = (axis == 0) == c.vertical;
    return r.sign_of(along ? it->second.first : it->second.second);
  }
  const Algebraic_real& line_root(const Crossing& c) const {
    return lines_.at(std::make_pair(c.vertical, c.c)).roots[std::size_t(c.index)].root;
  }
  // The crossings of the four edges of B, positioned along u (by_u) or v; false where edge_crossings refuses one.
  bool crossings_of_edges(const Box& B, bool by_u, std::vector<Crossing>& cr) {
    return edge_crossings(true, B.u0, B.v0, B.v1, by_u, cr) && edge_crossings(true, B.u1, B.v0, B.v1, by_u, cr) &&
           edge_crossings(false, B.v0, B.u0, B.u1, by_u, cr) && edge_crossings(false, B.v1, B.u0, B.u1, by_u, cr);
  }
  // The budget of a certificate's strip grids, each about as costly as one double split of a box.
  void charge_strips(std::size_t strips) { work_ += double(strips) * (a_ + 1) * (b_ + 1) * std::max(1, a_ + b_) / 16; }
  // The arc of one family (root_side: below or above the minimiser of sigma D on the lines x = const) between the
  // crossings c and d of a two-branch or fold box. It starts at the end on a line x = const when there is one: the
  // lifting's chained proof runs from n0 along x (certify_half_branch).
  void add_branch_arc(const Box& B, bool by_u, const Crossing& c, const Crossing& d, int root_side, int sigma) {
    const bool second = c.vertical != by_u && d.vertical == by_u;
    const Crossing &a = second ? d : c, &b = second ? c : d;
    Arc arc{node(a.vertical, a.c, a.index), node(b.vertical, b.c, b.index), {}, Parameter_box{B.u0, B.u1, B.v0, B.v1}, -1};
    sample_arc(B, by_u, a.position, b.position, arc.inner, root_side, sigma);
    arcs_.push_back(arc);
  }

  // A box with two branches (two_branch_certificate): the crossings of each class sigma D_y < 0, sigma D_y > 0, sorted
  // along x, pair up into arcs, as in a simple box. Each arc starts at (n0) the end that lies on a line x = const
  // when there is one: the lifting's chained proof runs from n0 along x (certify_half_branch).
  bool resolve_two_branches(Box& B) {
    std::size_t strips = 0;  // strip grids computed, each about as costly as one double split of B: the budget
    Two_branch_box t = two_branch_certificate(*B.fast, two_branch_strip_depth, &strips, o_.two_branch_max_gap);
    if (t.axis < 0 && t.screened && sharpen_grid(B))
      t = two_branch_certificate(*B.fast, two_branch_strip_depth, &strips, o_.two_branch_max_gap);
    charge_strips(strips);
    if (t.axis < 0 || curve_at_domain_corner(B)) return false;
    const bool by_u = t.axis == 0;
    std::vector<Crossing> cr;
    if (!crossings_of_edges(B, by_u, cr)) return false;
    std::vector<Crossing> cls[2];
    for (const Crossing& c : cr) {
      const int s = cross_derivative_sign(B, c, t.axis);
      if (s == 0) return false;  // D = D_y = 0 on the edge: excluded by the certificate; be safe and split
      cls[s > 0 ? 1 : 0].push_back(c);
    }
    // one family alone is one arc (or several) that a split resolves as well, on smaller cells whose graph
    // structure the lifting's proofs use: the certificate is kept for boxes that do hold two branches
    if (cls[0].empty() || cls[1].empty()) return false;
    for (auto& k : cls) {
      if (k.size() % 2 != 0) return false;
      std::sort(k.begin(), k.end(), [](const Crossing& x, const Crossing& y) { return x.position < y.position; });
    }
    for (int side = 0; side < 2; ++side) {
      // the branch's root on a line x = const lies below the minimiser of sigma D (on the lines x = const) iff
      // sigma D_y < 0 on it
      const int root_side = (side == 1) == (t.sigma > 0) ? 1 : -1;
      const std::vector<Crossing>& k = cls[side];
      for (std::size_t i = 0; i + 1 < k.size(); i += 2) add_branch_arc(B, by_u, k[i], k[i + 1], root_side, t.sigma);
    }
    ++two_branch_boxes_;
    return true;
  }

  // The curve passes through a corner of B that is a corner of the domain (the certificates leave such boxes to the
  // corner analysis of resolve()).
  bool curve_at_domain_corner(const Box& B) const {
    for (const Rational* cu : {&B.u0, &B.u1})
      for (const Rational* cv : {&B.v0, &B.v1})
        if ((*cu == box_.u0 || *cu == box_.u1) && (*cv == box_.v0 || *cv == box_.v1) && exact_jet(*cu, *cv)[0] == 0)
          return true;
    return false;
  }

  // A box with one fold p (fold_certificate): the crossings of each family sigma D_y < 0, sigma D_y > 0 and p, sorted
  // along x, pair up into arcs as in a two-branch box; p ends one arc of each family, on the curve's side of it. p is
  // a node of its own (a regular point of the curve: fold == true), from which the arcs run to their crossings, so
  // that the lifting's chained proofs start at the crossings (certify_half_branch).
  bool resolve_fold(Box& B) {
    std::size_t strips = 0;
    Fold_box f = fold_certificate(*B.fast, fold_strip_depth, &strips);
    if (f.axis < 0 && f.screened && sharpen_grid(B)) f = fold_certificate(*B.fast, fold_strip_depth, &strips);
    charge_strips(strips);
    if (f.axis < 0 || curve_at_domain_corner(B)) return false;
    const bool by_u = f.axis == 0;
    std::vector<Crossing> cr;
    if (!crossings_of_edges(B, by_u, cr)) return false;
    // p's enclosure in the domain's coordinates (exact: the local bounds are doubles)
    const Rational &x0 = by_u ? B.u0 : B.v0, &x1 = by_u ? B.u1 : B.v1, &y0 = by_u ? B.v0 : B.u0, &y1 = by_u ? B.v1 : B.u1;
    const Rational xa = x0 + Rational(f.xa) * (x1 - x0), xb = x0 + Rational(f.xb) * (x1 - x0);
    const Rational ya = y0 + Rational(f.ya) * (y1 - y0), yb = y0 + Rational(f.yb) * (y1 - y0);
    // the ends of each family along x: its crossings, and p inside X0 = (xa, xb); a crossing inside X0 cannot be
    // ordered against p: split instead
    std::vector<const Crossing*> cls[2];
    for (const Crossing& c : cr) {
      const int s = cross_derivative_sign(B, c, f.axis);
      if (s == 0) return false;
      if (c.position.compare(xa) >= 0 && c.position.compare(xb) <= 0) return false;
      cls[s > 0 ? 1 : 0].push_back(&c);
    }
    const Rational& near_end = f.curve_side > 0 ? xb : xa;
    struct Pair {
      const Crossing *a, *b;
      int family;
    };
    std::vector<Pair> cc;                                  // the arcs between two crossings
    std::vector<std::pair<const Crossing*, int>> to_fold;  // (crossing, family) of the two arcs at p
    for (int side = 0; side < 2; ++side) {
      std::vector<const Crossing*>& k = cls[side];
      if (k.size() % 2 == 0) return false;  // with p, each family has an even number of ends
      std::sort(k.begin(), k.end(), [](const Crossing* x, const Crossing* y) { return x->position < y->position; });
      std::size_t before = 0;
      while (before < k.size() && k[before]->position.compare(xa) < 0) ++before;
      // p's arc runs from p to the curve's side: p must be the first end of a pair there (an even number of ends
      // before it), else the certificate and the crossings disagree
      if (f.curve_side > 0 ? before % 2 != 0 : before % 2 != 1) return false;
      std::vector<const Crossing*> rest;
      for (std::size_t i = 0; i < k.size(); ++i) {
        if (i == (f.curve_side > 0 ? before : before - 1)) {
          to_fold.push_back({k[i], side});
          continue;
        }
        rest.push_back(k[i]);
      }
      for (std::size_t i = 0; i + 1 < rest.size(); i += 2) cc.push_back({rest[i], rest[i + 1], side});
    }
    singular_.push_back(Singular_point{by_u ? xa : ya, by_u ? xb : yb, by_u ? ya : xa, by_u ? yb : xb, false, 2, true});
    const std::size_t p = node_singular(singular_.size() - 1);
    const Algebraic_real at_p(near_end);
    for (const auto& t : to_fold) {
      const int root_side = (t.second == 1) == (f.sigma > 0) ? 1 : -1;
      Arc arc{node(t.first->vertical, t.first->c, t.first->index), p, {}, Parameter_box{B.u0, B.u1, B.v0, B.v1}, -1};
      sample_arc(B, by_u, t.first->position, at_p, arc.inner, root_side, f.sigma);
      arcs_.push_back(arc);
    }
    for (const Pair& q : cc) add_branch_arc(B, by_u, *q.a, *q.b, (q.family == 1) == (f.sigma > 0) ? 1 : -1, f.sigma);
    ++fold_boxes_;
    return true;
  }

  // When a certificate's plain-double screen passed but its proof failed, the proof may have failed on the grid's
  // radius alone: next to a node whose branches cross at a small angle, or along a deep valley, the values that
  // decide are below the radius of a double grid split down from the domain. B's grid is then replaced by the
  // double-double restriction of the domain's grid (sharp to the double rounding of its midpoints); false if that
  // cannot make it sharper.
  bool sharpen_grid(Box& B) {
    if (!dd_root_ || B.grid || !(B.fast->radius() > std::ldexp(B.fast->max_abs(), -48))) return false;
    B.fast = double_double_grid(B);
    return true;
  }

  // A box excluded as a valley of sigma D above 0 (valley_exclusion): no arcs.
  bool valley_excluded(Box& B) {
    std::size_t strips = 0;
    bool screened = false;
    bool ok = valley_exclusion(*B.fast, valley_strip_depth, &strips, &screened);
    if (!ok && screened && sharpen_grid(B)) ok = valley_exclusion(*B.fast, valley_strip_depth, &strips, nullptr);
    charge_strips(strips);
    if (ok) ++valley_boxes_;
    return ok;
  }

  // ---- singular and isolated points (see the header comment) ----
  struct Singular_point {
    Rational u_lo, u_hi, v_lo, v_hi;  // certified enclosure of p
    bool isolated;
    int half_branches;  // arcs that end at p (0 for an isolated point)
    bool fold = false;  // a regular point of the curve where it turns back across the lines x = const (fold_box.h)
    bool on_boundary = false;  // a singular point at a domain corner (resolve_corner)
  };

  // Bernstein range (hull of the coefficients) on the box of d^2 D / dx^(2-k) dy^k in the box's local
  // coordinates (x, y) in [0,1]^2; k = 0, 1, 2.
  Mpfi_interval hessian_range(const Interval_grid& g, int k) const {
    const int di = 2 - k, dj = k;
    Mpfi_interval r = Mpfi_interval::point(0, prec_);
    if (a_ < di || b_ < dj) return r;
    mpfi_t t;
    mpfi_init2(t, prec_);
    bool first = true;
    for (int i = 0; i + di <= a_; ++i)
      for (int j = 0; j + dj <= b_; ++j) {
        if (k == 0) {
          mpfi_mul_2si(t, g.at(i + 1, j), 1);
          mpfi_sub(t, g.at(i + 2, j), t);
          mpfi_add(t, t, g.at(i, j));
        } else if (k == 2) {
          mpfi_mul_2si(t, g.at(i, j + 1), 1);
          mpfi_sub(t, g.at(i, j + 2), t);
          mpfi_add(t, t, g.at(i, j));
        } else {
          mpfi_sub(t, g.at(i + 1, j + 1), g.at(i + 1, j));
          mpfi_sub(t, t, g.at(i, j + 1));
          mpfi_add(t, t, g.at(i, j));
        }
        if (first)
          mpfi_set(r.get(), t);
        else
          mpfi_union(r.get(), r.get(), t);
        first = false;
      }
    const long f = k == 0 ? long(a_) * (a_ - 1) : (k == 2 ? long(b_) * (b_ - 1) : long(a_) * b_);
    mpfi_mul_si(r.get(), r.get(), f);
    mpfi_clear(t);
    return r;
  }

  // The partial derivative d^(di+dj) D / dx^di dy^dj in local coordinates at the interval point (x, y), by de
  // Casteljau's algorithm on the differenced coefficients: an enclosure of its range there.
  Mpfi_interval grid_value(const Interval_grid& g, int di, int dj, const Mpfi_interval& x, const Mpfi_interval& y) const {
    const int n = a_ - di, m = b_ - dj;
    Mpfi_interval r = Mpfi_interval::point(0, prec_);
    if (n < 0 || m < 0) return r;
    std::vector<__mpfi_struct> w(std::size_t(a_ + 1) * (b_ + 1)), col(std::size_t(n + 1));
    for (auto& z : w) mpfi_init2(&z, prec_);
    for (auto& z : col) mpfi_init2(&z, prec_);
    mpfi_t t, x1, y1;
    mpfi_init2(t, prec_);
    mpfi_init2(x1, prec_);
    mpfi_init2(y1, prec_);
    mpfi_ui_sub(x1, 1, x.get());
    mpfi_ui_sub(y1, 1, y.get());
    auto W = [&](int i, int j) { return &w[std::size_t(i) * (b_ + 1) + j]; };
    for (int i = 0; i <= a_; ++i)
      for (int j = 0; j <= b_; ++j) mpfi_set(W(i, j), g.at(i, j));
    for (int s = 0; s < di; ++s)  // forward differences in place: the lower index keeps the difference
      for (int i = 0; i + s < a_; ++i)
        for (int j = 0; j <= b_; ++j) mpfi_sub(W(i, j), W(i + 1, j), W(i, j));
    for (int s = 0; s < dj; ++s)
      for (int i = 0; i <= a_; ++i)
        for (int j = 0; j + s < b_; ++j) mpfi_sub(W(i, j), W(i, j + 1), W(i, j));
    // collapse every row (fixed i) along y, then the column along x
    for (int i = 0; i <= n; ++i) bernstein_value(W(i, 0), m, y.get(), y1, &col[i], t);
    bernstein_value(&col[0], n, x.get(), x1, r.get(), t);
    for (int s = 0; s < di; ++s) mpfi_mul_si(r.get(), r.get(), a_ - s);
    for (int s = 0; s < dj; ++s) mpfi_mul_si(r.get(), r.get(), b_ - s);
    for (auto& z : w) mpfi_clear(&z);
    for (auto& z : col) mpfi_clear(&z);
    mpfi_clear(t);
    mpfi_clear(x1);
    mpfi_clear(y1);
    return r;
  }
  // sum_k c_k C(n,k) t^k s^(n-k) (s = 1 - t) into `out` (c is overwritten). When t and s are positive intervals:
  // Horner's rule in q = t/s (or s/t when t > 1/2, so that |q| <= 1 about the midpoint), times s^n (t^n): O(n)
  // interval operations; otherwise de Casteljau's algorithm (O(n^2)). Both are enclosures of the value.
  void bernstein_value(__mpfi_struct* c, int n, mpfi_srcptr t, mpfi_srcptr s, mpfi_ptr out, mpfi_ptr tmp) const {
    if (n >= 1 && mpfi_is_strictly_pos(t) && mpfi_is_strictly_pos(s)) {
      const std::vector<Integer>& C = binomials(n);
      mpfr_t mid;
      mpfr_init2(mid, 53);
      mpfi_mid(mid, t);
      const bool small_t = mpfr_cmp_d(mid, 0.5) <= 0;
      mpfr_clear(mid);
      mpfi_t q;
      mpfi_init2(q, prec_);
      if (small_t)
        mpfi_div(q, t, s);
      else
        mpfi_div(q, s, t);
      const int first = small_t ? n : 0, step = small_t ? -1 : 1;
      mpfi_mul_z(out, &c[first], C[first].mpz());
      for (int k = first + step; k >= 0 && k <= n; k += step) {
        mpfi_mul(out, out, q);
        mpfi_mul_z(tmp, &c[k], C[k].mpz());
        mpfi_add(out, out, tmp);
      }
      mpfi_set(q, small_t ? s : t);  // times s^n (t^n)
      for (int e = n; e > 0; e >>= 1) {
        if (e & 1) mpfi_mul(out, out, q);
        if (e > 1) mpfi_sqr(q, q);
      }
      mpfi_clear(q);
      return;
    }
    for (int level = n; level >= 1; --level)
      for (int j = 0; j < level; ++j) {
        mpfi_mul(tmp, &c[j], s);
        mpfi_mul(&c[j], &c[j + 1], t);
        mpfi_add(&c[j], &c[j], tmp);
      }
    mpfi_set(out, &c[0]);
  }
  const std::vector<Integer>& binomials(int n) const {
    auto it = binomials_.find(n);
    if (it != binomials_.end()) return it->second;
    std::vector<Integer> C(std::size_t(n + 1), Integer(1));
    for (int k = 1; k <= n; ++k) C[k] = C[k - 1] * Integer(n - k + 1) / Integer(k);
    return binomials_[n] = C;
  }

  // Value and derivatives up to order 2 of the long double grid at (x, y): f, fx, fy, fxx, fxy, fyy.
  std::array<long double, 6> local_jet(const std::vector<long double>& L, long double x, long double y) const {
    // Bernstein basis values and first/second derivatives in each variable
    auto basis = [](int n, long double t, std::vector<long double>& B0, std::vector<long double>& B1,
                    std::vector<long double>& B2) {
      // the bases of degrees n - 2, n - 1, n by one recursion (each degree is one step from the previous one)
      auto raise = [&](const std::vector<long double>& from, std::vector<long double>& out) {
        const std::size_t d = from.size();
        out.assign(d + 1, 0.0L);
        for (std::size_t k = 0; k < d; ++k) {
          out[k] += from[k] * (1 - t);
          out[k + 1] += from[k] * t;
        }
      };
      std::vector<long double> b1, b2, cur(1, 1.0L), next;  // degrees n - 1, n - 2; cur starts at degree 0
      if (n == 0) {
        B0 = cur;
      } else {
        for (int d = 1; d <= n - 2; ++d) {
          raise(cur, next);
          cur.swap(next);
        }
        if (n >= 2) {
          b2 = cur;
          raise(b2, b1);
        } else {
          b1 = cur;
        }
        raise(b1, B0);
      }
      B1.assign(std::size_t(n + 1), 0.0L);
      B2.assign(std::size_t(n + 1), 0.0L);
      for (int k = 0; k <= n; ++k) {  // d/dt B_k^n = n (B_{k-1}^{n-1} - B_k^{n-1})
        if (n >= 1) B1[k] = n * ((k >= 1 && k - 1 <= n - 1 ? b1[k - 1] : 0) - (k <= n - 1 ? b1[k] : 0));
        if (n >= 2)
          B2[k] = n * (n - 1) *
                  ((k >= 2 ? b2[k - 2] : 0) - 2 * (k >= 1 && k - 1 <= n - 2 ? b2[k - 1] : 0) + (k <= n - 2 ? b2[k] : 0));
      }
    };
    std::vector<long double> U0, U1, U2, V0, V1, V2;
    basis(a_, x, U0, U1, U2);
    basis(b_, y, V0, V1, V2);
    std::array<long double, 6> r{};
    for (int i = 0; i <= a_; ++i) {
      long double s0 = 0, s1 = 0, s2 = 0;
      for (int j = 0; j <= b_; ++j) {
        const long double c = L[std::size_t(i) * (b_ + 1) + j];
        s0 += c * V0[j];
        s1 += c * V1[j];
        s2 += c * V2[j];
      }
      r[0] += U0[i] * s0;
      r[1] += U1[i] * s0;
      r[2] += U0[i] * s1;
      r[3] += U2[i] * s0;
      r[4] += U1[i] * s1;
      r[5] += U0[i] * s2;
    }
    return r;
  }

  // D, D_u, D_v at a rational point, exactly.
  std::array<Rational, 3> exact_jet(const Rational& u, const Rational& v) const {
    Rational d(0), du(0), dv(0);
    for (int j = D_.degree(); j >= 0; --j) {
      Rational p(0), dp(0);
      if (!CGAL::is_zero(D_[j]))
        for (int i = D_[j].degree(); i >= 0; --i) {
          dp = dp * u + p;
          p = p * u + Rational(D_[j][i]);
        }
      dv = dv * v + d;
      d = d * v + p;
      du = du * v + dp;
    }
    return {d, du, dv};
  }

  // Resolves box B around a nondegenerate singular or isolated point of D = 0 (conditions (1)-(4) of the header
  // comment). Returns false (B is then split) when a condition fails for a reason that splitting can cure;
  // calls fail() when D(p) = 0 can be neither proved nor excluded.
  bool resolve_singular(Box& B) {
    using I = Mpfi_interval;
    if (a_ + b_ < 2) return false;
    // (1) regular Hessian on B; the two D_uv entries are independent copies (the mean-value Jacobian takes its
    // rows at different points). First on the double grid (its ranges are proved enclosures); if that fails
    // while its radius is small, the MPFI grid would not decide either and B is split.
    auto hessian_sign = [&](double rho) {  // sign of det H on B, 0 if not proved
      using DI = CGAL::Interval_nt<>;
      double lo[3], hi[3];
      for (int k = 0; k < 3; ++k) B.fast->second_difference_range(k, rho, lo[k], hi[k]);
      const DI det = DI(lo[0], hi[0]) * DI(lo[2], hi[2]) - DI(lo[1], hi[1]) * DI(lo[1], hi[1]);
      return det.inf() > 0 ? 1 : (det.sup() < 0 ? -1 : 0);
    };
    int hessian = hessian_sign(B.fast->radius());
    const bool hessian_undecided = hessian == 0 && (B.fast->precise() || hessian_sign(0) == 0);
    if (hessian_undecided && B.depth < cut_depth) return false;
    // floating-point Newton for the critical point (a starting point only)
    std::vector<long double> L(std::size_t(a_ + 1) * (b_ + 1));
    for (int i = 0; i <= a_; ++i)
      for (int j = 0; j <= b_; ++j) L[std::size_t(i) * (b_ + 1) + j] = B.fast->at(i, j);
    long double x = 0.5L, y = 0.5L, step = 1;
    for (int it = 0; it < 60 && step >= 1e-18L; ++it) {
      const auto j = local_jet(L, x, y);
      const long double dt = j[3] * j[5] - j[4] * j[4];
      if (!(std::fabs(dt) > 0)) return false;
      const long double dx = (j[5] * j[1] - j[4] * j[2]) / dt, dy = (j[3] * j[2] - j[4] * j[1]) / dt;
      x -= dx;
      y -= dy;
      if (!std::isfinite(double(x)) || !std::isfinite(double(y)) || x < -1 || x > 2 || y < -1 || y > 2) return false;
      step = std::fabs(dx) + std::fabs(dy);
    }
    // converged, up to the double grid's rounding: near a node whose branches cross at a small angle that rounding
    // moves the critical point by far more than 1e-18 (its radius over the smallest eigenvalue of the Hessian)
    const bool converged = step < 1e-9L;
    const long double margin = 1e-6L;
    if (x < margin || x > 1 - margin || y < margin || y > 1 - margin) return false;
    const Rational wu = B.u1 - B.u0, wv = B.v1 - B.v0;
    const std::array<double, 2> approx{CGAL::to_double(B.u0) + double(x) * CGAL::to_double(wu),
                                       CGAL::to_double(B.v0) + double(y) * CGAL::to_double(wv)};
    for (const auto& e : off_curve_)  // a critical point already proved to lie off the curve
      if (e.contains(approx[0], approx[1])) return false;
    // B probably holds a critical point of D on or next to the curve (|D| tiny there against the Hessian): if B is not
    // resolved below, it is cut around that point (cut_around), so that the point stays far from the edges of the
    // boxes that hold it. A plain split leaves it next to an edge as often as not, and a node whose two branches
    // are almost tangent is then unresolvable in the box beside it (a random (3,2) self-intersection: an angle of
    // 0.035 rad, the node 5e-8 from the edge of its box, the branches 1.8e-9 apart in the next box).
    if (converged && B.depth >= cut_depth) {
      const auto jet = local_jet(L, x, y);  // in B's local coordinates: |D(p)| against the Hessian's entries
      if (std::fabs(jet[0]) <= std::ldexp(std::fabs(jet[3]) + std::fabs(jet[4]) + std::fabs(jet[5]), -24)) {
        cut_pending_ = true;
        cut_point_ = Parameter_box{Rational(approx[0]), Rational(approx[0]), Rational(approx[1]), Rational(approx[1])};
      }
    }
    if (hessian_undecided) return false;
    if (o_.no_genuine_points && B.depth < undecided_depth)  // D(p) = 0 already neither proved nor excluded
      for (const auto& e : undecided_)
        if (e.contains(approx[0], approx[1])) return false;
    // (1) with sharper grids, now that B probably holds a critical point (the MPFI grid of a bicubic pair's D, of
    // bi-degree (54, 54), costs as much as 60 box splits): the double-double restriction, then the MPFI grid
    if (hessian == 0 && dd_root_ && !B.grid) {
      B.fast = double_double_grid(B);
      hessian = hessian_sign(B.fast->radius());
      if (hessian == 0 && (B.fast->precise() || hessian_sign(0) == 0)) return false;
    }
    if (hessian == 0) {
      const Interval_grid& g = mpfi_grid(B);
      const I hxx = hessian_range(g, 0), hxy = hessian_range(g, 1), hyx = hxy, hyy = hessian_range(g, 2);
      const I det = hxx * hyy - hxy * hyx;
      if (det.contains_zero()) return false;
      hessian = det.positive() ? 1 : -1;
    }
    const bool extremum = hessian > 0;
    // (4) the crossings with the edges of B
    std::vector<Crossing> cr;
    std::vector<std::size_t> isolated_corners;
    if (!crossings_around(B, cr, isolated_corners)) return false;
    if (cr.size() != (extremum ? 0u : 4u)) return false;
    // (2) Krawczyk on grad D in local coordinates, around Newton's point, with the Hessian ranges of B: first on
    // an interval grid from the double-double restriction (cheap), then, if that does not decide (Krawczyk's test
    // fails, or D(p) is proved neither zero nor nonzero), on the exact-rounded MPFI grid of B
    std::shared_ptr<const Interval_grid> cheap = B.grid ? nullptr : dd_interval_grid(B);
    bool witness_failed = false;
    for (int pass = cheap ? 0 : 1; pass < 2; ++pass) {
      const Interval_grid& g = pass == 0 ? *cheap : mpfi_grid(B);
      std::array<I, 2> X{I::point(0, prec_), I::point(0, prec_)};
      auto value = [&](const std::array<I, 2>& c, std::array<I, 2>& F) {
        F[0] = grid_value(g, 1, 0, c[0], c[1]);
        F[1] = grid_value(g, 0, 1, c[0], c[1]);
      };
      // The Hessian on Z in mean-value form, H(c) + (third derivatives on Z) (Z - c). Evaluated on Z directly, a
      // Bernstein sum overestimates by (size of its coefficients) x (width of Z), which can exceed the smallest
      // eigenvalue of H (a node whose branches cross at a small angle t: about t^2 |H|); the mean-value form's
      // excess is quadratic in the width of Z.
      auto jacobian = [&](const std::array<I, 2>& Z, std::vector<std::vector<I>>& J) {
        const I c0 = Z[0].midpoint(), c1 = Z[1].midpoint(), d0 = Z[0] - c0, d1 = Z[1] - c1;
        const I t30 = grid_value(g, 3, 0, Z[0], Z[1]), t21 = grid_value(g, 2, 1, Z[0], Z[1]),
                t12 = grid_value(g, 1, 2, Z[0], Z[1]), t03 = grid_value(g, 0, 3, Z[0], Z[1]);
        J[0][0] = grid_value(g, 2, 0, c0, c1) + t30 * d0 + t21 * d1;
        J[0][1] = grid_value(g, 1, 1, c0, c1) + t21 * d0 + t12 * d1;
        J[1][0] = J[0][1];
        J[1][1] = grid_value(g, 0, 2, c0, c1) + t12 * d0 + t03 * d1;
      };
      // Krawczyk's first box: radius 1e-7 (local coordinates), inflated when the critical point's own uncertainty
      // (the gradient's rounding error over the smallest eigenvalue of H) is larger
      bool proved = false;
      for (const double r0 : {1e-7, 1e-5, 1e-3}) {
        X = {I::hull(Rational(double(x) - r0), Rational(double(x) + r0), prec_),
             I::hull(Rational(double(y) - r0), Rational(double(y) + r0), prec_)};
        if ((proved = krawczyk_prove<2>(X, value, jacobian))) break;
      }
      if (!proved) {
        if (pass == 0) continue;
        return false;
      }
      // contract (quadratically: the Hessian is enclosed on the current box) until D(X) excludes 0 or the
      // enclosure stops shrinking (the working precision is reached)
      bool off_curve = false;
      for (int round = 0; round < 64; ++round) {
        if (!grid_value(g, 0, 0, X[0], X[1]).contains_zero()) {
          off_curve = true;
          break;
        }
        const double w0 = X[0].width_double() + X[1].width_double();
        if (!krawczyk_prove<2>(X, value, jacobian)) break;
        if (!(X[0].width_double() + X[1].width_double() < 0.5 * w0)) break;
      }
      if (!X[0].strictly_inside(I::hull(Rational(0), Rational(1), prec_)) ||
          !X[1].strictly_inside(I::hull(Rational(0), Rational(1), prec_)))
        return false;
      const Parameter_box K{B.u0 + wu * X[0].lower(), B.u0 + wu * X[0].upper(), B.v0 + wv * X[1].lower(),
                            B.v0 + wv * X[1].upper()};
      // (3) D(p): nonzero (the box is split as usual), or zero by an exact rational point or the witness
      if (off_curve) {
        off_curve_.push_back(K);
        return false;
      }
      bool zero_proved = false;
      Rational ru, rv;
      if (simplest_rational_in(K.u0, K.u1, ru) && simplest_rational_in(K.v0, K.v1, rv)) {
        const auto e = exact_jet(ru, rv);
        zero_proved = CGAL::is_zero(e[0]) && CGAL::is_zero(e[1]) && CGAL::is_zero(e[2]);
      }
      if (!zero_proved && o_.singular_point_witness && !witness_failed) {
        zero_proved = o_.singular_point_witness(Parameter_box{B.u0, B.u1, B.v0, B.v1}, approx);
        witness_failed = !zero_proved;
      }
      if (!zero_proved && pass == 0) continue;  // the exact-rounded grid may prove D(p) != 0
      if (!zero_proved && o_.no_genuine_points && B.depth < undecided_depth) {  // it may yet be excluded as phantom
        undecided_.push_back(K);
        return false;
      }
      if (!zero_proved) {
        fail("D has a nondegenerate critical point at (" + std::to_string(approx[0]) + ", " + std::to_string(approx[1]) +
             ") where |D| is below the interval resolution; D = 0 there (a node or an isolated point) could not be "
             "proved");
        return false;
      }
      singular_.push_back(Singular_point{K.u0, K.u1, K.v0, K.v1, extremum, extremum ? 0 : 4});
      for (std::size_t n : isolated_corners) touch_[n] = 0;
      connect_to_point(B, cr, node_singular(singular_.size() - 1), x, y);
      return true;
    }
    return false;
  }

  // The exact crossings of D = 0 with the four edges of B around a point inside it (sorted by u on horizontal
  // edges), with the domain corners among B's corners; false if an edge or a corner cannot be handled.
  // `excluded`: a singular point of the domain's boundary on B's edges, left out.
  bool crossings_around(const Box& B, std::vector<Crossing>& cr, std::vector<std::size_t>& isolated_corners,
                        const Excluded_point* excluded = nullptr) {
    if (!edge_crossings(true, B.u0, B.v0, B.v1, true, cr, nullptr, excluded) ||
        !edge_crossings(true, B.u1, B.v0, B.v1, true, cr, nullptr, excluded) ||
        !edge_crossings(false, B.v0, B.u0, B.u1, true, cr, nullptr, excluded) ||
        !edge_crossings(false, B.v1, B.u0, B.u1, true, cr, nullptr, excluded))
      return false;
    for (const Rational* cu : {&B.u0, &B.u1})
      for (const Rational* cv : {&B.v0, &B.v1})
        if ((*cu == box_.u0 || *cu == box_.u1) && (*cv == box_.v0 || *cv == box_.v1) &&
            !(excluded && excluded->u.compare(*cu) == 0 && excluded->v.compare(*cv) == 0) &&
            !corner_crossing(B, *cu, *cv, true, 0, cr, isolated_corners))
          return false;
    return true;
  }

  // The arcs of D = 0 in B from each crossing to the singular point p at local coordinates (x, y) of B, with
  // floating-point samples along them for drawing.
  void connect_to_point(const Box& B, const std::vector<Crossing>& cr, std::size_t ps, long double x, long double y) {
    std::vector<long double> L(std::size_t(a_ + 1) * (b_ + 1));
    for (int i = 0; i <= a_; ++i)
      for (int j = 0; j <= b_; ++j) L[std::size_t(i) * (b_ + 1) + j] = B.fast->at(i, j);
    const Rational wu = B.u1 - B.u0, wv = B.v1 - B.v0;
    for (const Crossing& c : cr) {
      const std::size_t n = node(c.vertical, c.c, c.index);
      Arc arc{n, ps, {}, Parameter_box{B.u0, B.u1, B.v0, B.v1}, -1};
      const Curve_topology_vertex q = vertex_of(n);
      const long double qx = (q.u - CGAL::to_double(B.u0)) / CGAL::to_double(wu),
                        qy = (q.v - CGAL::to_double(B.v0)) / CGAL::to_double(wv);
      for (int k = 1; k < o_.samples_per_arc; ++k) {  // points of the segment pulled onto D = 0 (drawing only)
        const long double f = (long double)k / o_.samples_per_arc;
        long double px = qx + f * (x - qx), py = qy + f * (y - qy);
        bool on_curve = false;  // only converged points are kept (near a singular point with several branches the
                                // pull from the chord may not converge in a few steps)
        for (int it = 0; it < 12 && !on_curve; ++it) {
          const auto j = local_jet(L, px, py);
          const long double n2 = j[1] * j[1] + j[2] * j[2];
          if (!(n2 > 0)) break;
          const long double nx = px - j[0] * j[1] / n2, ny = py - j[0] * j[2] / n2;
          if (!(nx >= 0 && nx <= 1 && ny >= 0 && ny <= 1)) break;
          on_curve = std::fabs(nx - px) + std::fabs(ny - py) < 1e-17L;
          px = nx;
          py = ny;
        }
        if (on_curve)
          arc.inner.push_back({CGAL::to_double(B.u0) + double(px) * CGAL::to_double(wu),
                               CGAL::to_double(B.v0) + double(py) * CGAL::to_double(wv)});
      }
      arcs_.push_back(arc);
    }
  }

  // ---- known multiple points (see the header comment) ----
  struct Multiple_point {
    Known_multiple_point known;
    std::shared_ptr<const Multiple_point_blowup> blowup;  // Taylor coefficients at the enclosure, on first use
    bool refuted;  // a coefficient of order < multiplicity is proved nonzero: the point is ignored
    bool corner = false;  // a singular point of D = 0 at a corner of the domain (the enclosure is that corner)
    std::shared_ptr<const Corner_blowup> corner_blowup;  // its weighted blow-up into the domain (corner_blowup.h)
    // a singular point of D = 0 inside a side of the domain: the side (u = c if vertical, else v = c), the exact
    // other coordinate, and the blow-ups of its two quadrants in the domain (below and above it along the side), on
    // first use; the enclosure is its isolating interval on the side
    bool edge = false, edge_vertical = false;
    Rational edge_c;
    Algebraic_real edge_position;
    std::shared_ptr<const Corner_blowup> halves[2];
    // an exact rational point whose tangent cone is not ordinary: its four quadrants blown up, on first use
    std::shared_ptr<const Corner_blowup> quadrants[4];
  };

  // The domain's corners where D = 0 is singular (D, D_u, D_v vanish exactly), with the order of D there: where
  // two patches of one smooth surface touch at a corner, D = 0 is singular at that corner of the (u, t) box.
  void add_singular_corners() {
    for (const Rational* cu : {&box_.u0, &box_.u1})
      for (const Rational* cv : {&box_.v0, &box_.v1}) {
        const auto e = exact_jet(*cu, *cv);
        if (e[0] != 0 || e[1] != 0 || e[2] != 0) continue;
        // the exact Taylor coefficients once: the order of D at the corner and the blow-up both come from them
        std::vector<std::vector<Rational>> c = taylor_coefficients(*cu, *cv);
        int order = INT_MAX;
        for (std::size_t i = 0; i < c.size(); ++i)
          for (std::size_t j = 0; j < c[i].size(); ++j)
            if (!CGAL::is_zero(c[i][j])) order = std::min(order, int(i + j));
        if (order == INT_MAX) continue;  // D == 0: not a curve
        Multiple_point m{Known_multiple_point{Parameter_box{*cu, *cu, *cv, *cv}, order}, nullptr, false};
        m.corner = true;
        m.corner_blowup =
            std::make_shared<const Corner_blowup>(std::move(c), *cu == box_.u0 ? 1 : -1, *cv == box_.v0 ? 1 : -1);
        multiple_.push_back(m);
      }
  }

  // The singular points of D = 0 strictly inside the sides of the domain: the roots of gcd(P, P', Q), P = D on the
  // side and Q = D across it (exact). Two patches of one surface glued along an edge give them on the side where
  // the rest of D meets the shared curve (teapot spout 16 x 17: a triple point with one real tangent).
  void add_singular_edge_points() {
    for (int side = 0; side < 4; ++side) {
      const bool vertical = side == 1 || side == 3;
      const Rational& c = side == 0 ? box_.v0 : (side == 1 ? box_.u1 : (side == 2 ? box_.v1 : box_.u0));
      const Rational& lo = vertical ? box_.v0 : box_.u0;
      const Rational& hi = vertical ? box_.v1 : box_.u1;
      if ((side == 2 && box_.v1 == box_.v0) || (side == 1 && box_.u1 == box_.u0) || !(lo < hi)) continue;
      Polynomial_1<Rational> P, Q;
      restriction(vertical, c, P, &Q);
      if (CGAL::is_zero(P)) continue;  // the side lies on D = 0: not a curve there (box_edge_lines removes it)
      const Polynomial_1<Integer> p = internal::integer_multiple(P), q = internal::integer_multiple(Q);
      Polynomial_1<Integer> g = CGAL::gcd(p, CGAL::differentiate(p));
      if (!CGAL::is_zero(q)) g = CGAL::gcd(g, q);
      if (g.degree() < 1) continue;
      for (const Isolated_root& r : isolate_real_roots(g, lo, hi)) {
        if (r.root.compare(lo) == 0 || r.root.compare(hi) == 0) continue;  // a corner: add_singular_corners
        r.root.refine_to_width((hi - lo) / Rational(Integer(1) << 40));
        const Parameter_box K = vertical ? Parameter_box{c, c, r.root.lower(), r.root.upper()}
                                         : Parameter_box{r.root.lower(), r.root.upper(), c, c};
        Multiple_point m{Known_multiple_point{K, 2}, nullptr, false};
        m.edge = true;
        m.edge_vertical = vertical;
        m.edge_c = c;
        m.edge_position = r.root;
        multiple_.push_back(m);
      }
    }
  }

  // The Taylor coefficients of D at an edge point: exact at a rational point; otherwise enclosures at every point
  // of its isolating interval (refined to 2^-prec), a coefficient whose enclosure holds 0 decided exactly (the sign
  // of the exact derivative polynomial along the side at the algebraic point).
  std::vector<std::vector<Corner_blowup::Enclosed_coefficient>> edge_taylor_coefficients(Multiple_point& mp) const {
    using Coefficient = Corner_blowup::Enclosed_coefficient;
    std::vector<std::vector<Coefficient>> out(std::size_t(a_ + 1), std::vector<Coefficient>(std::size_t(b_ + 1)));
    const Algebraic_real& x0 = mp.edge_position;
    if (x0.is_rational()) {
      const Rational q = x0.rational_value();
      const auto c = mp.edge_vertical ? taylor_coefficients(mp.edge_c, q) : taylor_coefficients(q, mp.edge_c);
      for (int i = 0; i <= a_; ++i)
        for (int j = 0; j <= b_; ++j) out[i][j] = Coefficient{c[i][j], c[i][j], CGAL::is_zero(c[i][j])};
      return out;
    }
    const mpfr_prec_t prec = root_prec_ + mpfr_prec_t(bits_) + 128;
    Rational width(1);
    for (mpfr_prec_t k = 0; k < prec; ++k) width /= 2;
    x0.refine_to_width(width);
    mp.known.enclosure = mp.edge_vertical ? Parameter_box{mp.edge_c, mp.edge_c, x0.lower(), x0.upper()}
                                          : Parameter_box{x0.lower(), x0.upper(), mp.edge_c, mp.edge_c};
    const std::vector<Mpfi_interval> c = internal::taylor_enclosures(D_, mp.known.enclosure, prec);
    // exact: D(u, v) = sum_ij t_ij (u - cu)^i (v - cv)^j with the side's own coordinate shifted (cu or cv = c)
    // and the other not (0); c_ij is then the i-th (j-th) derivative along the side of one row, over i! (j!)
    const auto t = mp.edge_vertical ? taylor_coefficients(mp.edge_c, Rational(0)) : taylor_coefficients(Rational(0), mp.edge_c);
    mpfr_t l, h;
    mpfr_init2(l, prec);
    mpfr_init2(h, prec);
    for (int i = 0; i <= a_; ++i)
      for (int j = 0; j <= b_; ++j) {
        const Mpfi_interval& e = c[std::size_t(i) * (b_ + 1) + j];
        Coefficient& o = out[i][j];
        o.zero = false;
        mpfi_get_left(l, e.get());
        mpfi_get_right(h, e.get());
        mpq_t ql, qh;
        mpq_init(ql);
        mpq_init(qh);
        mpfr_get_q(ql, l);
        mpfr_get_q(qh, h);
        o.lo = Rational(ql);
        o.hi = Rational(qh);
        mpq_clear(ql);
        mpq_clear(qh);
        if (!e.contains_zero()) continue;
        std::vector<Rational> row;  // along the side: u for v = c (column j of t), v for u = c (row i)
        if (mp.edge_vertical)
          for (int k = 0; k <= b_; ++k) row.push_back(t[i][k]);
        else
          for (int k = 0; k <= a_; ++k) row.push_back(t[k][j]);
        Polynomial_1<Rational> f(row.begin(), row.end());
        for (int k = 0; k < (mp.edge_vertical ? j : i) && !CGAL::is_zero(f); ++k) f = CGAL::differentiate(f);
        if (CGAL::is_zero(f) || x0.sign_of(f) == 0) o = Coefficient{Rational(0), Rational(0), true};
      }
    mpfr_clear(l);
    mpfr_clear(h);
    return out;
  }

  // A multiple point of D (order >= 3) at the simplest rational point of B (denominators below 2^20), proved by
  // exact Taylor coefficients, added to the known multiple points; its index, or -1. Symmetric and constructed
  // inputs put such points at small rationals (three lines through (1/2, 1/2)); each point is tested once.
  int rational_multiple_point(const Box& B) {
    Rational ru, rv;
    if (!simplest_rational_in(B.u0, B.u1, ru) || !simplest_rational_in(B.v0, B.v1, rv)) return -1;
    if (ru.denominator().bit_size() > 20 || rv.denominator().bit_size() > 20) return -1;
    if (!(B.u0 < ru && ru < B.u1 && B.v0 < rv && rv < B.v1)) return -1;
    if (!rational_points_tested_.insert(std::make_pair(ru, rv)).second) return -1;
    const int max_order = std::min(8, a_ + b_);
    for (int order = 0; order <= max_order; ++order)
      for (int i = 0; i <= order; ++i)
        if (!CGAL::is_zero(taylor_coefficient(ru, rv, i, order - i))) {
          if (order < 2) return -1;  // not on the curve, or smooth
          if (order == 2) {  // a node or an acnode is resolve_singular's case; a double tangent (a cusp) is not
            const Rational c20 = taylor_coefficient(ru, rv, 2, 0), c11 = taylor_coefficient(ru, rv, 1, 1),
                           c02 = taylor_coefficient(ru, rv, 0, 2);
            if (!CGAL::is_zero(c11 * c11 - 4 * c20 * c02)) return -1;
          }
          multiple_.push_back(Multiple_point{Known_multiple_point{Parameter_box{ru, ru, rv, rv}, order}, nullptr, false});
          return int(multiple_.size()) - 1;
        }
    return -1;
  }
  // All the coefficients c[i][j] of (u - ru)^i (v - rv)^j in D, exactly (Taylor shift by Horner steps).
  std::vector<std::vector<Rational>> taylor_coefficients(const Rational& ru, const Rational& rv) const {
    std::vector<std::vector<Rational>> c(std::size_t(a_ + 1), std::vector<Rational>(std::size_t(b_ + 1), Rational(0)));
    for (int j = 0; j <= b_; ++j)
      for (int i = 0; !CGAL::is_zero(D_[j]) && i <= D_[j].degree(); ++i) c[i][j] = Rational(D_[j][i]);
    for (int j = 0; j <= b_; ++j)
      for (int s = 0; s < a_; ++s)
        for (int i = a_ - 1; i >= s; --i) c[i][j] += ru * c[i + 1][j];
    for (int i = 0; i <= a_; ++i)
      for (int s = 0; s < b_; ++s)
        for (int j = b_ - 1; j >= s; --j) c[i][j] += rv * c[i][j + 1];
    return c;
  }
  // The coefficient of (u - ru)^i (v - rv)^j in D, exactly.
  Rational taylor_coefficient(const Rational& ru, const Rational& rv, int i, int j) const {
    if (i > a_ || j > b_) return Rational(0);
    Rational r(0);
    for (int J = D_.degree(); J >= j; --J) {  // Horner in rv over the j-th Taylor coefficients in v
      Rational c(0);
      if (!CGAL::is_zero(D_[J]))
        for (int I = D_[J].degree(); I >= i; --I) c = c * ru + Rational(D_[J][I] * binomial(I, i));
      r = r * rv + c * Rational(binomial(J, j));
    }
    return r;
  }
  static Integer binomial(int n, int k) {
    Integer r(1);
    for (int t = 1; t <= k; ++t) r = r * Integer(n - k + t) / Integer(t);
    return r;
  }

  // The known multiple point whose enclosure lies strictly inside B (or a singular domain corner that is a corner of
  // B), or -1.
  int multiple_point_in(const Box& B) const {
    for (std::size_t m = 0; m < multiple_.size(); ++m) {
      const Parameter_box& K = multiple_[m].known.enclosure;
      if (multiple_[m].corner) {  // a domain corner: in B iff it is a corner of B
        if ((K.u0 == B.u0 || K.u0 == B.u1) && (K.v0 == B.v0 || K.v0 == B.v1)) return int(m);
        continue;
      }
      if (multiple_[m].edge) {  // on a side of the domain: in B iff on B's edge along that side, ends included
        if (edge_point_side_of(multiple_[m], B) >= 0) return int(m);
        continue;
      }
      if (B.u0 < K.u0 && K.u1 < B.u1 && B.v0 < K.v0 && K.v1 < B.v1) return int(m);
    }
    return -1;
  }

  // Resolves box B around the known multiple point p (enclosure K strictly inside B): the tangent cone has L real
  // lines, all simple, and grad D != 0 on (p + [-r, r]^2) \ {p} (internal/multiple_point_blowup.h); grad D != 0
  // on the rest of B (the Bernstein coefficients of D_u or of D_v keep a sign on every sub-box outside that
  // square); D = 0 crosses the edges of B exactly 2L times. Then D = 0 in B is the 2L half-branches from p to the
  // crossings (the argument of the header comment). Returns false (B is split) otherwise.
  bool resolve_multiple(Box& B, std::size_t index) {
    Multiple_point& mp = multiple_[index];
    if (mp.refuted) return false;
    const Parameter_box& K = mp.known.enclosure;
    if (mp.corner) return resolve_corner(B, mp);
    if (mp.edge) return resolve_edge_point(B, mp);
    if (!mp.blowup) {
      mp.blowup = std::make_shared<const Multiple_point_blowup>(D_, K, mp.known.multiplicity,
                                                                root_prec_ + mpfr_prec_t(bits_) + 128);
      mp.refuted = !mp.blowup->consistent();
      if (mp.refuted) return false;
    }
    // first a square around p that covers B (then (2') has nothing left to prove), else the largest power of two
    // r <= half the distance from K to the edges of B for which the cone is proved
    const Rational reach = std::max(std::max(K.u1 - B.u0, B.u1 - K.u0), std::max(K.v1 - B.v0, B.v1 - K.v0));
    Rational r(1);
    while (r < reach) r *= 2;
    while (r / 2 >= reach) r /= 2;
    int lines = mp.blowup->tangent_lines(r);
    if (lines < 0) {
      const Rational dist = std::min(std::min(K.u0 - B.u0, B.u1 - K.u1), std::min(K.v0 - B.v0, B.v1 - K.v1));
      while (r > dist / 2) r /= 2;
      for (int attempt = 0; attempt < 3 && lines < 0; ++attempt) {
        lines = mp.blowup->tangent_lines(r);
        if (lines < 0) r /= 8;
      }
    }
    if (lines < 0) return resolve_quadrants(B, mp);  // not ordinary (or r too large): at a rational point, quadrants
    std::vector<Crossing> cr;
    std::vector<std::size_t> isolated_corners;
    if (!crossings_around(B, cr, isolated_corners)) return false;
    if (cr.size() != 2 * std::size_t(lines)) return false;
    if (!no_critical_point_outside(B, Parameter_box{K.u1 - r, K.u0 + r, K.v1 - r, K.v0 + r})) return false;
    singular_.push_back(Singular_point{K.u0, K.u1, K.v0, K.v1, lines == 0, 2 * lines});
    for (std::size_t n : isolated_corners) touch_[n] = 0;
    const Rational wu = B.u1 - B.u0, wv = B.v1 - B.v0;
    connect_to_point(B, cr, node_singular(singular_.size() - 1),
                     CGAL::to_double(((K.u0 + K.u1) / 2 - B.u0) / wu), CGAL::to_double(((K.v0 + K.v1) / 2 - B.v0) / wv));
    return true;
  }

  // Box B at a singular domain corner p (a corner of B): the same argument in the quadrant B of p. The weighted
  // blow-up (internal/corner_blowup.h) proves H half-branches of D = 0 leaving p into B and grad D != 0 on the
  // rectangle R = [0, L0^w] x [0, L0^v] of the quadrant minus p; grad D != 0 on the rest of B; D = 0 crosses
  // the edges of B (p excluded) exactly H times. Components of (D = 0) \ {p} in B are arcs with ends on the edges
  // of B or at p (no closed curve: the disc it bounds, inside B, would hold an extremum of D; neither a loop
  // through p, for the same reason), so the H half-branches end at H distinct crossings and use them all: D = 0 in
  // B is the H arcs from p. p is a point of the locus on the domain's boundary with H branches into the domain
  // (H = 0: the curve passes p from outside, an isolated point of the locus in the domain).
  bool resolve_corner(Box& B, Multiple_point& mp) {
    const Parameter_box& K = mp.known.enclosure;
    if (!mp.corner_blowup->valid()) return false;
    const int sx = K.u0 == B.u0 ? 1 : -1, sy = K.v0 == B.v0 ? 1 : -1;
    const Rational wu = B.u1 - B.u0, wv = B.v1 - B.v0;
    Rational rx, ry;
    const int half = quadrant_half_branches({mp.corner_blowup.get()}, wu, wv, rx, ry);
    if (half < 0) return false;
    std::vector<Crossing> cr;
    std::vector<std::size_t> isolated_corners;
    const Excluded_point corner{Algebraic_real(K.u0), Algebraic_real(K.v0)};
    if (!crossings_around(B, cr, isolated_corners, &corner) || cr.size() != std::size_t(half)) return false;
    if ((rx < wu || ry < wv) && !no_critical_point_outside(B, Parameter_box{K.u0 - rx, K.u0 + rx, K.v0 - ry, K.v0 + ry}))
      return false;
    Singular_point p{K.u0, K.u1, K.v0, K.v1, half == 0, half};
    p.on_boundary = true;
    singular_.push_back(p);
    for (std::size_t n : isolated_corners) touch_[n] = 0;
    connect_to_point(B, cr, node_singular(singular_.size() - 1), sx > 0 ? 0 : 1, sy > 0 ? 0 : 1);
    return true;
  }

  // Box B around a known multiple point p at an exact rational point (K a point, strictly inside B) whose tangent
  // cone is not ordinary (a cusp, a tacnode: a multiple line of the cone): the four quadrants at p blown up each
  // (internal/corner_blowup.h, on exact Taylor coefficients; valid when D(x, 0) and D(0, y) are not identically
  // zero at p, i.e. no branch along the axis lines through p, so none of the half-branches lies on an axis). The
  // germ of D = 0 at p is the sum H of their half-branches, grad D != 0 on the rectangle around p minus p; grad
  // D != 0 on the rest of B and exactly H crossings of B's edges: then D = 0 in B is the H arcs from p.
  bool resolve_quadrants(Box& B, Multiple_point& mp) {
    const Parameter_box& K = mp.known.enclosure;
    if (!(K.u0 == K.u1 && K.v0 == K.v1)) return false;
    if (!mp.quadrants[0]) {
      const auto c = taylor_coefficients(K.u0, K.v0);
      for (int q = 0; q < 4; ++q)
        mp.quadrants[q] = std::make_shared<const Corner_blowup>(c, q % 2 == 0 ? 1 : -1, q < 2 ? 1 : -1);
    }
    for (const auto& q : mp.quadrants)
      if (!q->valid()) return false;
    Rational rx, ry;
    const int half = quadrant_half_branches(
        {mp.quadrants[0].get(), mp.quadrants[1].get(), mp.quadrants[2].get(), mp.quadrants[3].get()},
        std::max(K.u0 - B.u0, B.u1 - K.u0), std::max(K.v0 - B.v0, B.v1 - K.v0), rx, ry);
    if (half < 0) return false;
    std::vector<Crossing> cr;
    std::vector<std::size_t> isolated_corners;
    if (!crossings_around(B, cr, isolated_corners) || cr.size() != std::size_t(half)) return false;
    const Parameter_box S{K.u0 - rx, K.u0 + rx, K.v0 - ry, K.v0 + ry};
    const bool covers = S.u0 <= B.u0 && B.u1 <= S.u1 && S.v0 <= B.v0 && B.v1 <= S.v1;
    if (!covers && !no_critical_point_outside(B, S)) return false;
    singular_.push_back(Singular_point{K.u0, K.u1, K.v0, K.v1, half == 0, half});
    for (std::size_t n : isolated_corners) touch_[n] = 0;
    const Rational wu = B.u1 - B.u0, wv = B.v1 - B.v0;
    connect_to_point(B, cr, node_singular(singular_.size() - 1), CGAL::to_double((K.u0 - B.u0) / wu),
                     CGAL::to_double((K.v0 - B.v0) / wv));
    return true;
  }

  // The blow-ups q of quadrants at one point (they share the Newton polygon, so the weights wx, wy): the sum of
  // their half-branches H on the rectangles [0, rx] x [0, ry], rx = 2^(e wx), ry = 2^(e wy), for the first e that
  // reaches (ru, rv), else e - 1, e - 3, e - 5; -1 if none is proved.
  static int quadrant_half_branches(const std::vector<const Corner_blowup*>& q, const Rational& ru, const Rational& rv,
                                    Rational& rx, Rational& ry) {
    const int wx = q.front()->weight_x(), wy = q.front()->weight_y();
    auto extent = [](int e, int weight) {  // 2^(e weight), exactly
      Rational r(1);
      for (int i = 0; i < std::abs(e * weight); ++i) r = e > 0 ? r * 2 : r / 2;
      return r;
    };
    int e = int(std::ceil(std::max(std::log2(CGAL::to_double(ru)) / wx, std::log2(CGAL::to_double(rv)) / wy)));
    while (extent(e, wx) < ru || extent(e, wy) < rv) ++e;
    int half = -1;
    for (int attempt = 0; attempt < 4 && half < 0; ++attempt) {
      half = 0;
      for (std::size_t k = 0; k < q.size() && half >= 0; ++k) {
        const int n = q[k]->half_branches(e);
        half = n < 0 ? -1 : half + n;
      }
      if (half < 0) e -= attempt == 0 ? 1 : 2;
    }
    rx = extent(e, wx);
    ry = extent(e, wy);
    return half;
  }

  // Where the edge point mp lies on B: -1 not on B; 0 strictly inside B's edge along the side; 1 at that edge's
  // lower end (B's corner), 2 at its upper end (a rational point on a grid line). A box with the point inside that
  // edge is cut around it (cut_around_edge_point), so that grid lines do not pass through it.
  int edge_point_side_of(const Multiple_point& mp, const Box& B) const {
    const bool on_line = mp.edge_vertical ? (B.u0 == mp.edge_c || B.u1 == mp.edge_c) : (B.v0 == mp.edge_c || B.v1 == mp.edge_c);
    if (!on_line) return -1;
    const int l = mp.edge_position.compare(mp.edge_vertical ? B.v0 : B.u0);
    const int h = mp.edge_position.compare(mp.edge_vertical ? B.v1 : B.u1);
    return l < 0 || h > 0 ? -1 : (l == 0 ? 1 : (h == 0 ? 2 : 0));
  }

  // Box B at a singular point p inside a side of the domain, on B's edge along that side: the argument of
  // resolve_corner, with the two quadrants of the domain at p (along the side below and above p) blown up each
  // (internal/corner_blowup.h; they share the Newton polygon, so the weights). They prove H = H- + H+ half-branches
  // leaving p into the domain (none along the normal to the side at p: D has order b0 there, the chart B's form is
  // nonzero at n = 0) and grad D != 0 on [p - L0^w, p + L0^w] x [0, L0^v] minus p (side coordinates); grad D != 0 on
  // the rest of B; D = 0 crosses the edges of B (p excluded) exactly H times.
  bool resolve_edge_point(Box& B, Multiple_point& mp) {
    if (edge_point_side_of(mp, B) != 0) return false;  // at a corner of B: not handled (the boxes are cut around it)
    const bool vertical = mp.edge_vertical;
    // inward: +1 if the domain lies on the side of larger coordinate across the side
    const int inward = mp.edge_c == (vertical ? box_.u0 : box_.v0) ? 1 : -1;
    if (!mp.halves[0]) {
      const auto c = edge_taylor_coefficients(mp);
      for (int h = 0; h < 2; ++h) {
        const int along = h == 0 ? -1 : 1;
        mp.halves[h] = std::make_shared<const Corner_blowup>(c, vertical ? inward : along, vertical ? along : inward);
      }
    }
    if (!mp.halves[0]->valid() || !mp.halves[1]->valid()) return false;
    const Parameter_box& K = mp.known.enclosure;
    // B's edge along the side runs over [lo, hi]
    const Rational& lo = vertical ? B.v0 : B.u0;
    const Rational& hi = vertical ? B.v1 : B.u1;
    const Rational& klo = vertical ? K.v0 : K.u0;
    const Rational& khi = vertical ? K.v1 : K.u1;
    const Rational along_reach = std::max(khi - lo, hi - klo);
    const Rational across_reach = vertical ? B.u1 - B.u0 : B.v1 - B.v0;
    Rational rx, ry;
    const int half = quadrant_half_branches({mp.halves[0].get(), mp.halves[1].get()}, vertical ? across_reach : along_reach,
                                            vertical ? along_reach : across_reach, rx, ry);
    if (half < 0) return false;
    const Rational& ra = vertical ? ry : rx;
    const Rational& rc = vertical ? rx : ry;
    std::vector<Crossing> cr;
    std::vector<std::size_t> isolated_corners;
    const Excluded_point point = vertical ? Excluded_point{Algebraic_real(mp.edge_c), mp.edge_position}
                                          : Excluded_point{mp.edge_position, Algebraic_real(mp.edge_c)};
    if (!crossings_around(B, cr, isolated_corners, &point) || cr.size() != std::size_t(half)) return false;
    // the proved rectangle, shrunk by the enclosure of p (it holds p's exact rectangle)
    const Parameter_box S = vertical ? Parameter_box{mp.edge_c - rc, mp.edge_c + rc, khi - ra, klo + ra}
                                     : Parameter_box{khi - ra, klo + ra, mp.edge_c - rc, mp.edge_c + rc};
    const bool covers = S.u0 <= B.u0 && B.u1 <= S.u1 && S.v0 <= B.v0 && B.v1 <= S.v1;
    if (!covers && !no_critical_point_outside(B, S)) return false;
    Singular_point p{K.u0, K.u1, K.v0, K.v1, half == 0, half};
    p.on_boundary = true;
    singular_.push_back(p);
    for (std::size_t n : isolated_corners) touch_[n] = 0;
    const Rational wu = B.u1 - B.u0, wv = B.v1 - B.v0;
    const double px = CGAL::to_double(((K.u0 + K.u1) / 2 - B.u0) / wu), py = CGAL::to_double(((K.v0 + K.v1) / 2 - B.v0) / wv);
    connect_to_point(B, cr, node_singular(singular_.size() - 1), px, py);
    return true;
  }

  // A box B holding a known multiple point p (enclosure K strictly inside) that resolve_multiple could not
  // resolve is cut into 3 x 3 boxes: a square [c - h, c + h]^2 around p (c a short rational within h/8 of K, h a
  // power of two at most half the distance from K to B's edges) and the eight boxes around it, all at a distance
  // >= 7h/8 from p. A plain split leaves p next to an edge as often as not, and the boxes beside p are then never
  // resolved: D = 0 near a multiple point looks the same at every scale (its tangent cone), so a box whose
  // distance to p is not large against its size fails the monotonicity tests at every depth. Here only the
  // square touches p, and it is resolve_multiple's case, with p central; the boxes around it are at a fixed
  // distance from p, and their sub-boxes become simple. False if B holds no such point.
  bool split_around_multiple(Box& B, std::vector<Box>& stack) {
    const int m = multiple_point_in(B);
    if (m < 0 || multiple_[std::size_t(m)].refuted) return false;
    if (multiple_[std::size_t(m)].edge) return cut_around_edge_point(B, multiple_[std::size_t(m)], stack);
    return cut_around(B, multiple_[std::size_t(m)].known.enclosure, stack, true);
  }
  // The same cut for a point p strictly inside B's edge along a side of the domain: 3 x 2 boxes, the middle one
  // [c - h, c + h] along the side by h across it holding p, the others at a distance >= 7h/8 from p.
  bool cut_around_edge_point(Box& B, const Multiple_point& mp, std::vector<Box>& stack) {
    if (edge_point_side_of(mp, B) != 0) return false;
    const bool vertical = mp.edge_vertical;
    const Parameter_box& K = mp.known.enclosure;
    const Rational& lo = vertical ? B.v0 : B.u0;
    const Rational& hi = vertical ? B.v1 : B.u1;
    const Rational& klo = vertical ? K.v0 : K.u0;
    const Rational& khi = vertical ? K.v1 : K.u1;
    const Rational across = vertical ? B.u1 - B.u0 : B.v1 - B.v0;
    if (!(lo < klo && khi < hi)) return false;
    const Rational dist = std::min(std::min(klo - lo, hi - khi), across);
    Rational h(1);
    while (h > dist / 2) h /= 2;
    while (h * 2 <= dist / 2) h *= 2;
    Rational m;
    if (!simplest_rational_in(klo - h / 8, khi + h / 8, m)) return false;
    const Rational al[4] = {lo, m - h, m + h, hi};
    const bool low_side = mp.edge_c == (vertical ? B.u0 : B.v0);
    const Rational ac[3] = {vertical ? B.u0 : B.v0, low_side ? mp.edge_c + h : (vertical ? B.u1 : B.v1) - h,
                            vertical ? B.u1 : B.v1};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 2; ++j) {
        Box C = vertical ? Box{ac[j], ac[j + 1], al[i], al[i + 1], B.depth + 1, nullptr, nullptr}
                         : Box{al[i], al[i + 1], ac[j], ac[j + 1], B.depth + 1, nullptr, nullptr};
        C.fast = double_grid_of(mpfi_grid(C));
        stack.push_back(C);
      }
    return true;
  }
  // The 3 x 3 cut of B around the box K strictly inside it (above), with MPFI grids (`exact`) or double-double
  // ones when available; false if K is not strictly inside B.
  bool cut_around(Box& B, const Parameter_box& K, std::vector<Box>& stack, bool exact) {
    if (!(B.u0 < K.u0 && K.u1 < B.u1 && B.v0 < K.v0 && K.v1 < B.v1)) return false;
    const Rational dist = std::min(std::min(K.u0 - B.u0, B.u1 - K.u1), std::min(K.v0 - B.v0, B.v1 - K.v1));
    Rational h(1);
    while (h > dist / 2) h /= 2;
    while (h * 2 <= dist / 2) h *= 2;
    Rational cu, cv;
    if (!simplest_rational_in(K.u0 - h / 8, K.u1 + h / 8, cu) || !simplest_rational_in(K.v0 - h / 8, K.v1 + h / 8, cv))
      return false;
    const Rational us[4] = {B.u0, cu - h, cu + h, B.u1}, vs[4] = {B.v0, cv - h, cv + h, B.v1};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        Box C{us[i], us[i + 1], vs[j], vs[j + 1], B.depth + 1, nullptr, nullptr};
        C.fast = exact || !dd_root_ ? double_grid_of(mpfi_grid(C)) : double_double_grid(C);
        stack.push_back(C);
      }
    return true;
  }

  // grad D != 0 on B outside the box S: sub-boxes where D_u or D_v keeps a sign, or that lie inside S. The signs
  // come from the Bernstein grids of D_u and D_v themselves (forward differences of B's MPFI grid, exact up to
  // its rounding), split in double with the proved radius. Differences of a split grid of D would not do: on a
  // piece of relative size h they are h times smaller than the derivative while their error is not, and near a
  // multiple point with two almost equal tangents the gradient is small along a whole sector, where the pieces
  // must be small (two random (2,2) self-intersections failed there at every depth).
  bool no_critical_point_outside(Box& B, const Parameter_box& S) {
    using Grid = std::shared_ptr<const Double_bernstein_grid>;
    struct Piece {
      Grid gu, gv;            // Bernstein grids of D_u and D_v on the piece (null when that degree is 0)
      double x0, x1, y0, y1;  // local coordinates in B (dyadic: exact)
      int depth;
    };
    const Rational wu = B.u1 - B.u0, wv = B.v1 - B.v0;
    const Rational sx0 = (S.u0 - B.u0) / wu, sx1 = (S.u1 - B.u0) / wu, sy0 = (S.v0 - B.v0) / wv,
                   sy1 = (S.v1 - B.v0) / wv;
    const double aspect = CGAL::to_double(wu) / CGAL::to_double(wv);
    const Interval_grid& g = mpfi_grid(B);
    auto derivative = [&](bool along_u) -> Grid {
      if ((along_u ? a_ : b_) < 1) return nullptr;
      Interval_grid d(along_u ? a_ - 1 : a_, along_u ? b_ : b_ - 1, prec_);
      for (int i = 0; i <= d.a(); ++i)
        for (int j = 0; j <= d.b(); ++j) mpfi_sub(d.at(i, j), along_u ? g.at(i + 1, j) : g.at(i, j + 1), g.at(i, j));
      return double_grid_of(d);
    };
    auto keeps_sign = [](const Grid& G) { return G && G->common_sign(G->radius()) != 0; };
    auto halve = [](const Grid& G, bool along_u, Grid& lo, Grid& hi) {
      if (!G) return;
      auto l = std::make_shared<Double_bernstein_grid>(), h = std::make_shared<Double_bernstein_grid>();
      G->split(along_u, 0.5, *l, *h);
      lo = l;
      hi = h;
    };
    std::vector<Piece> stack{{derivative(true), derivative(false), 0, 1, 0, 1, 0}};
    for (int count = 0; !stack.empty(); ++count) {
      const Piece P = stack.back();
      stack.pop_back();
      if (Rational(P.x0) >= sx0 && Rational(P.x1) <= sx1 && Rational(P.y0) >= sy0 && Rational(P.y1) <= sy1) continue;
      if (keeps_sign(P.gu) || keeps_sign(P.gv)) continue;
      if (P.depth >= 28 || count > 20000) return false;
      const bool along_u = (P.x1 - P.x0) * aspect >= (P.y1 - P.y0);
      Piece L = P, R = P;
      ++L.depth;
      ++R.depth;
      halve(P.gu, along_u, L.gu, R.gu);
      halve(P.gv, along_u, L.gv, R.gv);
      work_ += 2 * double(a_ + 1) * (b_ + 1) * std::max(1, a_ + b_) / 16;
      if (along_u)
        L.x1 = R.x0 = 0.5 * (P.x0 + P.x1);
      else
        L.y1 = R.y0 = 0.5 * (P.y0 + P.y1);
      stack.push_back(L);
      stack.push_back(R);
    }
    return true;
  }

  std::size_t node_singular(std::size_t index) {
    Node_key k{false, Rational(0), int(index), true};
    auto it = nodes_.find(k);
    if (it != nodes_.end()) return it->second;
    keys_.push_back(k);
    return nodes_[k] = keys_.size() - 1;
  }

  // Floating-point samples strictly between the two ends: the unique crossing of the segment u = const
  // (v = const) with the curve, by a bracketing root refinement (Illinois with a bisection every fourth step).
  // In a two-branch box (root_side != 0) the line carries up to two crossings, on either side of the minimiser of
  // sigma D: the one below it (root_side -1) or above it (+1).
  void sample_arc(const Box& B, bool by_u, const Algebraic_real& p0, const Algebraic_real& p1,
                  std::vector<std::array<double, 2>>& out, int root_side = 0, int sigma = 0) const {
    // Bisection on the sign of D along the line through each sample abscissa, evaluated from the box's double
    // Bernstein grid by de Casteljau's algorithm (stable; the power form cancels catastrophically at high degree
    // and put samples on the box edge). The box is simple in this direction: one sign change on each line.
    const double x0 = p0.to_double(), x1 = p1.to_double();
    const Double_bernstein_grid& G = *B.fast;
    const int nx = by_u ? G.a() : G.b(), ny = by_u ? G.b() : G.a();
    const double gx0 = CGAL::to_double(by_u ? B.u0 : B.v0), gx1 = CGAL::to_double(by_u ? B.u1 : B.v1);
    const double lo = CGAL::to_double(by_u ? B.v0 : B.u0), hi = CGAL::to_double(by_u ? B.v1 : B.u1);
    std::vector<double> c(std::size_t(ny + 1)), w(std::size_t(std::max(nx, ny) + 1)), basis(std::size_t(nx + 1));
    auto casteljau = [&](std::size_t n, double t) {  // value at t of the Bernstein coefficients w[0..n]
      for (std::size_t r = 1; r <= n; ++r)
        for (std::size_t k = 0; k + r <= n; ++k) w[k] = (1 - t) * w[k] + t * w[k + 1];
      return w[0];
    };
    // an arc of a two-branch box stands for the many leaf boxes a quadtree would need along it (the lifting proves
    // its statuses span by span between these points): four times as many samples
    const int samples = root_side != 0 ? 4 * o_.samples_per_arc : o_.samples_per_arc;
    for (int k = 1; k < samples; ++k) {
      const double x = x0 + (x1 - x0) * double(k) / samples;
      const double tx = std::min(1.0, std::max(0.0, (x - gx0) / (gx1 - gx0)));
      // coefficients along the line: D(x, .) in the Bernstein basis of the box, sum_i B_i(tx) G(i, .) (the
      // basis values are nonnegative and sum to 1: a convex combination, as stable as de Casteljau)
      basis[0] = 1;
      for (int d = 1; d <= nx; ++d) {
        basis[std::size_t(d)] = basis[std::size_t(d - 1)] * tx;
        for (int k = d - 1; k >= 1; --k) basis[std::size_t(k)] = basis[std::size_t(k)] * (1 - tx) + basis[std::size_t(k - 1)] * tx;
        basis[0] *= (1 - tx);
      }
      for (int j = 0; j <= ny; ++j) {
        double sum = 0;
        for (int i = 0; i <= nx; ++i) sum += basis[std::size_t(i)] * (by_u ? G.at(i, j) : G.at(j, i));
        c[std::size_t(j)] = sum;
      }
      auto f = [&](double t) {
        std::copy(c.begin(), c.end(), w.begin());
        return casteljau(std::size_t(ny), t);
      };
      // Illinois (regula falsi with halving of the retained end's value), every fourth step a bisection: the
      // bracket always holds the sign change and shrinks superlinearly (plain bisection needed 60 evaluations)
      double a = 0, b = 1;
      if (root_side != 0) (root_side < 0 ? b : a) = two_branch::minimiser(c, sigma);
      double fa = f(a), fb = f(b);
      const bool bracketed = (fa < 0) != (fb < 0) && fa != 0 && fb != 0;
      int kept = 0;  // which end was retained last (-1 a, 1 b)
      for (int it = 0; it < 80 && b - a > 4.5e-16; ++it) {  // (t in [0, 1]: a few ulps)
        double m = 0.5 * (a + b);
        if (bracketed && it % 4 != 3) {
          const double r = (a * fb - b * fa) / (fb - fa);
          if (r > a && r < b) m = r;
        }
        const double fm = f(m);
        if (fm == 0) {
          a = b = m;
          break;
        }
        if ((fm < 0) == (fa < 0)) {
          a = m;
          fa = fm;
          if (kept == 1) fb *= 0.5;
          kept = 1;
        } else {
          b = m;
          fb = fm;
          if (kept == -1) fa *= 0.5;
          kept = -1;
        }
      }
      const double y = lo + 0.5 * (a + b) * (hi - lo);
      out.push_back(by_u ? std::array<double, 2>{x, y} : std::array<double, 2>{y, x});
    }
  }

  // Enclosure {u_lo, u_hi, v_lo, v_hi} of a node (outward-rounded doubles; exact line coordinates enclosed).
  std::array<double, 4> node_box(std::size_t n) const {
    const Curve_topology_vertex v = vertex_of(n);
    const Node_key& k = keys_[n];
    if (k.singular) return {v.u_lo, v.u_hi, v.v_lo, v.v_hi};
    const auto c = CGAL::to_interval(k.c);
    return k.vertical ? std::array<double, 4>{c.first, c.second, v.v_lo, v.v_hi}
                      : std::array<double, 4>{v.u_lo, v.u_hi, c.first, c.second};
  }

  Curve_topology_vertex vertex_of(std::size_t n) const {
    const Node_key& k = keys_[n];
    if (k.singular) {
      const Singular_point& p = singular_[std::size_t(k.index)];
      Curve_topology_vertex v;
      v.u_lo = CGAL::to_interval(p.u_lo).first;
      v.u_hi = CGAL::to_interval(p.u_hi).second;
      v.v_lo = CGAL::to_interval(p.v_lo).first;
      v.v_hi = CGAL::to_interval(p.v_hi).second;
      v.u = 0.5 * (v.u_lo + v.u_hi);
      v.v = 0.5 * (v.v_lo + v.v_hi);
      v.kind = p.fold ? Curve_topology_vertex::regular
                      : (p.isolated ? Curve_topology_vertex::isolated : Curve_topology_vertex::singular);
      v.on_boundary = v.singular_on_boundary = p.on_boundary;
      return v;
    }
    const Line& L = lines_.at(std::make_pair(k.vertical, k.c));
    const Algebraic_real& x = L.roots[std::size_t(k.index)].root;
    x.refine_to_width(Rational(1, 1 << 30) * Rational(1, 1 << 10));
    const double c = CGAL::to_double(k.c);
    const std::pair<double, double> xi = x.to_interval();
    Curve_topology_vertex v;
    v.u_lo = k.vertical ? c : xi.first;
    v.u_hi = k.vertical ? c : xi.second;
    v.v_lo = k.vertical ? xi.first : c;
    v.v_hi = k.vertical ? xi.second : c;
    v.u = 0.5 * (v.u_lo + v.u_hi);
    v.v = 0.5 * (v.v_lo + v.v_hi);
    v.on_boundary = on_domain_boundary(n);
    v.kind = v.on_boundary ? Curve_topology_vertex::boundary
                           : (cut_.count(n) ? Curve_topology_vertex::phantom_cut : Curve_topology_vertex::regular);
    const auto touch = touch_.find(n);
    if (touch != touch_.end()) {  // a contact with an edge, or a domain corner that the curve does not enter
      v.tangent_to_boundary = !is_corner_node(n) || corner_tangent_.count(n) > 0;
      if (touch->second == 0) v.kind = Curve_topology_vertex::isolated;
    } else if (corner_tangent_.count(n)) {
      v.tangent_to_boundary = true;  // the curve ends at a domain corner, tangent to one of its edges
    }
    return v;
  }

  bool is_corner_node(std::size_t n) const {
    const Node_key& k = keys_[n];
    if (k.singular) return false;
    const auto& roots = lines_.at(std::make_pair(k.vertical, k.c)).roots;
    const Algebraic_real& x = roots[std::size_t(k.index)].root;
    return on_domain_boundary(n) && (k.vertical ? (x.compare(box_.v0) == 0 || x.compare(box_.v1) == 0)
                                                : (x.compare(box_.u0) == 0 || x.compare(box_.u1) == 0));
  }

  bool on_domain_boundary(std::size_t n) const {
    const Node_key& k = keys_[n];
    if (k.singular) return false;
    return k.vertical ? (k.c == box_.u0 || k.c == box_.u1) : (k.c == box_.v0 || k.c == box_.v1);
  }

  // Glue the arcs along their nodes into chains between domain-boundary nodes, and cycles.
  bool assemble(Curve_topology_in_box& out) {
    out.box = box_;
    std::vector<std::vector<std::size_t>> at(keys_.size());
    for (std::size_t k = 0; k < arcs_.size(); ++k) {
      at[arcs_[k].n0].push_back(k);
      at[arcs_[k].n1].push_back(k);
    }
    out.excluded_regions = excised_;
    // a fold is a regular point of the curve: edges run through it
    auto is_stop = [&](std::size_t n) {
      return on_domain_boundary(n) || (keys_[n].singular && !singular_[std::size_t(keys_[n].index)].fold) || cut_.count(n) > 0;
    };
    for (std::size_t n = 0; n < keys_.size(); ++n) {
      if (cut_.count(n)) {  // one arc from the analysed side, or none
        if (at[n].size() > 1) {
          fail("inconsistent subdivision: a phantom cut joins " + std::to_string(at[n].size()) + " arcs");
          return false;
        }
        continue;
      }
      const auto touch = touch_.find(n);
      const std::size_t want =
          touch != touch_.end()
              ? touch->second
              : (on_domain_boundary(n) ? 1 : (keys_[n].singular ? std::size_t(singular_[std::size_t(keys_[n].index)].half_branches) : 2));
      if (at[n].size() != want) {
        fail("inconsistent subdivision: a crossing joins " + std::to_string(at[n].size()) + " arcs");
        return false;
      }
    }
    std::vector<char> used(arcs_.size(), 0);
    std::map<std::size_t, std::size_t> vid;
    auto vertex = [&](std::size_t n) {
      auto it = vid.find(n);
      if (it != vid.end()) return it->second;
      out.vertices.push_back(vertex_of(n));
      return vid[n] = out.vertices.size() - 1;
    };
    // walk from node n along arc k; appends points (the point of n is the last one already in poly) and the
    // piece; returns the node reached (whose point comes next)
    auto walk = [&](std::size_t n, std::size_t k, std::vector<std::array<double, 2>>& poly,
                    std::vector<Curve_topology_piece>& pieces) {
      const Arc& a = arcs_[k];
      used[k] = 1;
      const std::size_t to = a.n0 == n ? a.n1 : a.n0;
      Curve_topology_piece piece{a.cell, a.graph_axis, poly.size() - 1, poly.size() + a.inner.size(), node_box(n),
                                 node_box(to)};
      if (a.graph_axis < 0) {  // Arc{crossing, singular point}
        piece.singular_end = a.n0 == n ? 1 : 0;
        const Node_key& c = keys_[a.n0];
        piece.crossing_on_vertical_line = c.vertical;
        // an isolating interval of the crossing on its line, widened half-way to its neighbouring roots (so that
        // a rational root, whose own interval is a point, gets a proper one)
        const auto& roots = lines_.at(std::make_pair(c.vertical, c.c)).roots;
        const std::size_t r = std::size_t(c.index);
        const Rational lo = r > 0 ? (roots[r - 1].root.upper() + roots[r].root.lower()) / 2 : roots[r].root.lower() - 1;
        const Rational hi = r + 1 < roots.size() ? (roots[r].root.upper() + roots[r + 1].root.lower()) / 2
                                                 : roots[r].root.upper() + 1;
        piece.crossing = c.vertical ? Parameter_box{c.c, c.c, lo, hi} : Parameter_box{lo, hi, c.c, c.c};
      }
      if (a.n0 == n)
        poly.insert(poly.end(), a.inner.begin(), a.inner.end());
      else
        poly.insert(poly.end(), a.inner.rbegin(), a.inner.rend());
      pieces.push_back(piece);
      return to;
    };
    auto point = [&](std::size_t n) {
      const Curve_topology_vertex v = vertex_of(n);
      return std::array<double, 2>{v.u, v.v};
    };
    auto chain = [&](std::size_t start, std::size_t k, bool stop_at_target, std::size_t target) {
      Curve_topology_edge e;
      e.source = vertex(start);
      e.polyline.push_back(point(start));
      std::size_t n = start;
      for (;;) {
        n = walk(n, k, e.polyline, e.pieces);
        if (is_stop(n) || (stop_at_target && n == target)) break;
        if (used[at[n][0]] && used[at[n][1]]) break;  // back at the start of a cycle
        e.polyline.push_back(point(n));
        k = used[at[n][0]] ? at[n][1] : at[n][0];
      }
      e.polyline.push_back(point(n));
      e.target = vertex(n);
      out.edges.push_back(e);
      return n;
    };
    for (std::size_t n = 0; n < keys_.size(); ++n)
      if ((keys_[n].singular && singular_[std::size_t(keys_[n].index)].isolated) ||
          (touch_.count(n) && touch_.at(n) == 0)) {  // an acnode or an outside contact: its own component
        Curve_topology_component c;
        c.closed = keys_[n].singular;  // a contact point lies on the domain boundary
        c.isolated_point = true;
        c.vertices.push_back(vertex(n));
        out.components.push_back(c);
      }
    for (std::size_t n = 0; n < keys_.size(); ++n)
      if (is_stop(n))
        for (std::size_t k : at[n])
          if (!used[k]) chain(n, k, false, n);
    for (std::size_t k = 0; k < arcs_.size(); ++k) {
      if (used[k]) continue;
      // a cycle: count its nodes, then split it into two edges at the start and half-way
      std::vector<std::size_t> nodes;
      std::size_t n = arcs_[k].n0, a = k;
      std::vector<char> seen(arcs_.size(), 0);
      for (;;) {
        nodes.push_back(n);
        seen[a] = 1;
        n = arcs_[a].n0 == n ? arcs_[a].n1 : arcs_[a].n0;
        const std::size_t next = at[n][0] == a ? at[n][1] : at[n][0];
        if (seen[next]) break;
        a = next;
      }
      const std::size_t start = arcs_[k].n0, half = nodes[nodes.size() / 2];
      if (nodes.size() < 2) {  // a loop through one node only: cannot happen (two arcs meet at every node)
        fail("inconsistent subdivision: a one-node cycle");
        return false;
      }
      const std::size_t reached = chain(start, k, true, half);
      const std::size_t k2 = used[at[reached][0]] ? at[reached][1] : at[reached][0];
      chain(reached, k2, true, start);
    }
    internal::assign_components(out);
    return true;
  }

  const Polynomial_2<Integer>& D_;
  Parameter_box box_;
  Subdivision_topology_options o_;
  int a_ = 0, b_ = 0;
  long bits_ = 0;
  mpfr_prec_t prec_ = 256, root_prec_ = 256;
  std::shared_ptr<Interval_grid> root_grid_;  // Bernstein coefficients on the whole domain box
  std::shared_ptr<const Double_double_bernstein> dd_root_;  // the same in double-double, scaled by 2^-dd_scale_
  int dd_scale_ = 0;
  double work_ = 0;                           // budget used (see run())
  std::map<std::pair<bool, Rational>, Line> lines_;
  std::map<Node_key, std::size_t> nodes_;
  std::vector<Node_key> keys_;
  std::vector<Arc> arcs_;
  std::vector<Singular_point> singular_;
  std::vector<Multiple_point> multiple_;
  std::set<std::pair<Rational, Rational>> rational_points_tested_;
  static constexpr int rational_multiple_depth = 8;  // from this depth on, boxes look for rational multiple points
  std::vector<Parameter_box> off_curve_;  // boxes of critical points proved off the curve
  mutable std::map<int, std::vector<Integer>> binomials_;
  std::vector<Parameter_box> undecided_;  // boxes of critical points p where D(p) = 0 was not proved (yet)
  static constexpr int undecided_depth = 16;  // below it such a point waits for the phantom exclusion
  // From this depth on, a box that holds a critical point of D next to the curve and is not resolved is cut around
  // it (resolve_singular sets cut_point_, the main loop cuts).
  static constexpr int cut_depth = 10;
  // cuts of a box's x-range in the two-branch fold test (two_branch::no_fold; halvings, or window cuts where the
  // minimiser leaves the box)
  static constexpr int two_branch_strip_depth = 4;
  // halvings of the x-range outside the fold strip (fold_box.h): the strips next to it must come within the strip's
  // half-width (down to 2^-40 of the box) of the fold
  static constexpr int fold_strip_depth = 48;
  // halvings of a box's x-range in the valley exclusion (two_branch::no_zero): the segments must follow the floor
  // of a valley to within its width (about sqrt(min D / D_yy)), which a chord does on strips about that wide
  static constexpr int valley_strip_depth = 8;
  std::size_t two_branch_boxes_ = 0;
  std::size_t valley_boxes_ = 0;
  std::size_t fold_boxes_ = 0;
  // per line (vertical, c): the derivative of D along it and across it, restricted to it
  std::map<std::pair<bool, Rational>, std::pair<Polynomial_1<Rational>, Polynomial_1<Rational>>> restrictions_;
  bool cut_pending_ = false;
  Parameter_box cut_point_{};
  std::set<std::size_t> cut_;             // nodes on the edges of excised boxes
  std::set<std::size_t> corner_tangent_;  // domain corners where the curve is tangent to an edge
  std::map<std::size_t, std::size_t> touch_;  // contacts with a domain edge: node -> arcs there (2 inside, 0 outside)
  std::vector<Parameter_box> excised_;
  bool failed_ = false;
  std::string failure_;
};

} // namespace internal

/// \brief Certified topology of D(u,v) = 0 in `box` by Bernstein subdivision (see the header comment).
/// `certified == false` (with `reason` and the unresolved boxes) when the curve has singular or isolated
/// points, or tangencies with box lines, that the subdivision cannot resolve; the caller then needs an exact
/// curve analysis (analyse_curve_in_box). Throws Invalid_input if D is zero or the box is empty.
inline Subdivision_topology_result subdivide_curve_in_box(const Polynomial_2<Integer>& D, const Parameter_box& box,
                                                         const Subdivision_topology_options& o = {}) {
  if (CGAL::is_zero(D)) throw Invalid_input("subdivide_curve_in_box: the polynomial is identically zero");
  if (!(box.u0 < box.u1) || !(box.v0 < box.v1)) throw Invalid_input("subdivide_curve_in_box: empty box");
  for (const Known_multiple_point& m : o.multiple_points)
    if (m.enclosure.u1 < m.enclosure.u0 || m.enclosure.v1 < m.enclosure.v0 || m.multiplicity < 2)
      throw Invalid_input("subdivide_curve_in_box: a known multiple point needs a nonempty enclosure and a "
                          "multiplicity of at least 2");
  return internal::Subdivision_topology(D, box, o).run();
}

} // namespace bezoutian

#endif // BEZOUTIAN_TOPOLOGY_CURVE_TOPOLOGY_BY_SUBDIVISION_H
