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
// order k, e.g. a common zero of all entries of the Bezoutian matrix, topology/matrix_zero_points.h). Their
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
//
// Code layout. This header holds the interface, the class internal::Subdivision_topology (its state, and the work
// list of boxes with their grids: run()); internal/interval_bernstein_grid.h the interval arithmetic on Bernstein
// grids; the other member functions are defined by concern in internal/subdivision_crossings.h (exact lines and the
// crossings of box edges, simple boxes), internal/subdivision_singular_boxes.h (two-branch, fold and valley boxes,
// boxes around a nondegenerate critical point), internal/subdivision_multiple_points.h (known multiple points,
// singular corners and edge points, cuts around them) and internal/subdivision_assembly.h (arc samples, vertices, the
// gluing of the arcs), included at the end of this header.
#ifndef BEZOUTIAN_TOPOLOGY_CURVE_TOPOLOGY_BY_SUBDIVISION_H
#define BEZOUTIAN_TOPOLOGY_CURVE_TOPOLOGY_BY_SUBDIVISION_H

#include <bezoutian/topology/Curve_topology.h>
#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/algebraic/Root_isolation.h>
#include <bezoutian/topology/internal/corner_blowup.h>
#include <bezoutian/topology/internal/double_bernstein_grid.h>
#include <bezoutian/topology/internal/double_double_bernstein.h>
#include <bezoutian/topology/internal/fold_box.h>
#include <bezoutian/topology/internal/interval_bernstein_grid.h>
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
/// entries of the n x n Bezoutian matrix, whose determinant then vanishes to order n: topology/matrix_zero_points.h).
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
  /// partner domain, lifting/double_partner_witness.h). Such a box is not analysed: it is recorded in
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

// The state of one subdivision: the domain's grids, the work list of boxes (run), the exact lines with their roots
// and the nodes on them, the arcs found in the leaf boxes, the singular and the multiple points. The member functions
// are declared by concern; each group's comment names the header that defines it.
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
  Subdivision_topology_result run();

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

  // A crossing on one edge of a box: its line, its root there and its position along the sorting coordinate.
  struct Crossing {
    bool vertical;
    Rational c;
    int index;
    Algebraic_real position;  // u for dv-simple boxes, v for du-simple boxes
  };

  // A singular point of the domain's boundary that ends half-branches of the box being resolved (resolve_corner,
  // resolve_edge_point): not a crossing of the box's edges through it.
  struct Excluded_point {
    Algebraic_real u, v;
    bool on(bool vertical, const Rational& c, const Algebraic_real& x) const {
      return vertical ? u.compare(c) == 0 && x.compare(v) == 0 : v.compare(c) == 0 && x.compare(u) == 0;
    }
  };

  // A singular or isolated point resolved in its box (see the header comment), or a fold (resolve_fold).
  struct Singular_point {
    Rational u_lo, u_hi, v_lo, v_hi;  // certified enclosure of p
    bool isolated;
    int half_branches;  // arcs that end at p (0 for an isolated point)
    bool fold = false;  // a regular point of the curve where it turns back across the lines x = const (fold_box.h)
    bool on_boundary = false;  // a singular point at a domain corner (resolve_corner)
  };

  // A known multiple point (see the header comment): given by the caller, a singular domain corner or a singular
  // point inside a side of the domain, or found at a small rational.
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

  // the work list's boxes: their grids and splits (this header, below the class)
  static Rational ratio(bool along_u);
  void split(const Box& B, std::vector<Box>& stack) const;
  const Interval_grid& mpfi_grid(Box& B);
  std::shared_ptr<const Double_bernstein_grid> double_double_grid(const Box& B);
  std::shared_ptr<const Interval_grid> dd_interval_grid(const Box& B);
  void fail(const std::string& why);

  // exact lines, nodes, crossings of box edges; simple and excised boxes (internal/subdivision_crossings.h)
  const Line& line(bool vertical, const Rational& c);
  std::size_t node(bool vertical, const Rational& c, int index);
  std::size_t node_singular(std::size_t index);
  void restriction(bool vertical, const Rational& c, Polynomial_1<Rational>& P,
                   Polynomial_1<Rational>* Q = nullptr) const;
  int contact_from_inside(bool vertical, const Rational& c, const Algebraic_real& x, int multiplicity) const;
  int sign_next_to(bool vertical, const Rational& c, const Rational& x, int direction) const;
  bool edge_crossings(bool vertical, const Rational& c, const Rational& lo, const Rational& hi, bool sort_by_u,
                      std::vector<Crossing>& out, std::vector<Touch>* touches = nullptr,
                      const Excluded_point* excluded = nullptr);
  bool is_domain_corner(bool vertical, const Rational& c, const Rational& e) const;
  std::array<Rational, 3> exact_jet(const Rational& u, const Rational& v) const;
  bool corner_crossing(const Box& B, const Rational& cu, const Rational& cv, bool sort_by_u, int simple,
                       std::vector<Crossing>& out, std::vector<std::size_t>& isolated);
  bool crossings_of_edges(const Box& B, bool by_u, std::vector<Crossing>& cr);
  bool crossings_around(const Box& B, std::vector<Crossing>& cr, std::vector<std::size_t>& isolated_corners,
                        const Excluded_point* excluded = nullptr);
  const Algebraic_real& line_root(const Crossing& c) const;
  bool resolve(const Box& B, bool dv_simple);
  bool excise(const Box& B);

  // two-branch, fold and valley boxes, boxes around a critical point (internal/subdivision_singular_boxes.h)
  int cross_derivative_sign(const Box& B, const Crossing& c, int axis);
  void charge_strips(std::size_t strips);
  void add_branch_arc(const Box& B, bool by_u, const Crossing& c, const Crossing& d, int root_side, int sigma);
  bool resolve_two_branches(Box& B);
  bool curve_at_domain_corner(const Box& B) const;
  bool resolve_fold(Box& B);
  bool sharpen_grid(Box& B);
  bool valley_excluded(Box& B);
  bool resolve_singular(Box& B);
  bool prove_critical_point(Box& B, const std::vector<Crossing>& cr, const std::vector<std::size_t>& isolated_corners,
                            long double x, long double y, const std::array<double, 2>& approx, bool extremum);
  void connect_to_point(const Box& B, const std::vector<Crossing>& cr, std::size_t ps, long double x, long double y);

  // known multiple points, singular corners and edge points, cuts around them (internal/subdivision_multiple_points.h)
  void add_singular_corners();
  void add_singular_edge_points();
  std::vector<std::vector<Corner_blowup::Enclosed_coefficient>> edge_taylor_coefficients(Multiple_point& mp) const;
  int rational_multiple_point(const Box& B);
  std::vector<std::vector<Rational>> taylor_coefficients(const Rational& ru, const Rational& rv) const;
  Rational taylor_coefficient(const Rational& ru, const Rational& rv, int i, int j) const;
  int multiple_point_in(const Box& B) const;
  bool resolve_multiple(Box& B, std::size_t index);
  bool resolve_corner(Box& B, Multiple_point& mp);
  bool resolve_quadrants(Box& B, Multiple_point& mp);
  static int quadrant_half_branches(const std::vector<const Corner_blowup*>& q, const Rational& ru, const Rational& rv,
                                    Rational& rx, Rational& ry);
  int edge_point_side_of(const Multiple_point& mp, const Box& B) const;
  bool resolve_edge_point(Box& B, Multiple_point& mp);
  bool split_around_multiple(Box& B, std::vector<Box>& stack);
  bool cut_around_edge_point(Box& B, const Multiple_point& mp, std::vector<Box>& stack);
  bool cut_around(Box& B, const Parameter_box& K, std::vector<Box>& stack, bool exact);
  bool no_critical_point_outside(Box& B, const Parameter_box& S);

  // arc samples, vertices and the gluing of the arcs into the topology (internal/subdivision_assembly.h)
  void sample_arc(const Box& B, bool by_u, const Algebraic_real& p0, const Algebraic_real& p1,
                  std::vector<std::array<double, 2>>& out, int root_side = 0, int sigma = 0) const;
  std::array<double, 4> node_box(std::size_t n) const;
  Curve_topology_vertex vertex_of(std::size_t n) const;
  bool is_corner_node(std::size_t n) const;
  bool on_domain_boundary(std::size_t n) const;
  bool assemble(Curve_topology_in_box& out);

  // the state
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
  interval_bernstein::Binomial_rows binomials_;  // rows C(n, .) for interval_bernstein::grid_value
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

inline Subdivision_topology_result Subdivision_topology::run() {
  Subdivision_topology_result res;
  root_grid_ = std::make_shared<Interval_grid>(a_, b_, prec_);
  interval_bernstein::bernstein_on_box(D_, box_, root_prec_, *root_grid_);
  dd_root_ = interval_bernstein::double_double_of(*root_grid_, dd_scale_, prec_);
  Box root{box_.u0, box_.u1, box_.v0, box_.v1, 0, root_grid_, nullptr};
  root.fast = interval_bernstein::double_grid_of(*root_grid_, prec_);
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
        B.fast = interval_bernstein::double_grid_of(mpfi_grid(B), prec_);
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

// Different non-dyadic ratios in u and v: the grid then never has a vertex on the diagonal u = v or at a
// dyadic point (symmetric data puts curve features there).
inline Rational Subdivision_topology::ratio(bool along_u) { return along_u ? Rational(15, 31) : Rational(16, 33); }

// The four children (double grids only; their MPFI grids are extracted from the domain's when needed).
inline void Subdivision_topology::split(const Box& B, std::vector<Box>& stack) const {
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
inline const Interval_grid& Subdivision_topology::mpfi_grid(Box& B) {
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
      interval_bernstein::split_grid(*g, along_u, hi, left, right, prec_);
      interval_bernstein::copy_grid(left, *g);
    }
    if (lo > Rational(0)) {  // then [lo/hi, 1] of that
      interval_bernstein::split_grid(*g, along_u, lo / hi, left, right, prec_);
      interval_bernstein::copy_grid(right, *g);
    }
  }
  B.grid = g;
  return *g;
}

// The double grid of B from the double-double restriction of the domain's grid (proved radius; about 4 times
// cheaper than the MPFI restriction, and usually as sharp as a double grid can be). dd_root_ must exist.
inline std::shared_ptr<const Double_bernstein_grid> Subdivision_topology::double_double_grid(const Box& B) {
  work_ += double(a_ + 1) * (b_ + 1) * std::max(1, a_ + b_);
  return dd_root_->restrict_to((B.u0 - box_.u0) / (box_.u1 - box_.u0), (B.u1 - box_.u0) / (box_.u1 - box_.u0),
                               (B.v0 - box_.v0) / (box_.v1 - box_.v0), (B.v1 - box_.v0) / (box_.v1 - box_.v0),
                               dd_scale_);
}

// An interval grid of B from the double-double restriction of the domain's grid: [hi + lo - E, hi + lo + E]
// times 2^dd_scale_ (outward rounded; a valid enclosure, less sharp than the MPFI restriction), or null.
inline std::shared_ptr<const Interval_grid> Subdivision_topology::dd_interval_grid(const Box& B) {
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

inline void Subdivision_topology::fail(const std::string& why) {
  if (!failed_) failure_ = why;
  failed_ = true;
}

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

#include <bezoutian/topology/internal/subdivision_crossings.h>
#include <bezoutian/topology/internal/subdivision_singular_boxes.h>
#include <bezoutian/topology/internal/subdivision_multiple_points.h>
#include <bezoutian/topology/internal/subdivision_assembly.h>

#endif // BEZOUTIAN_TOPOLOGY_CURVE_TOPOLOGY_BY_SUBDIVISION_H
