// Certified intersection of two rational Bezier curves (plane or space) on [0,1] x [0,1] (du-1989 ch. 4).
#ifndef BEZOUTIAN_INTERSECTION_CURVE_INTERSECTION_H
#define BEZOUTIAN_INTERSECTION_CURVE_INTERSECTION_H

#include <bezoutian/arithmetic/profiling.h>
#include <bezoutian/algebraic/Algebraic_real.h>
#include <bezoutian/elimination/Bezout_matrix.h>
#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/elimination/Goldman_resolvent.h>
#include <bezoutian/elimination/Groebner_bivariate.h>
#include <bezoutian/elimination/Polynomial_matrix_determinant.h>
#include <bezoutian/geometry/Rational_bezier_curve.h>
#include <bezoutian/algebraic/Root_isolation.h>
#include <bezoutian/geometry/Weight_validity.h>
#include <bezoutian/intersection/curve_intersection_support.h>
#include <bezoutian/arithmetic/interval_krawczyk.h>
#include <bezoutian/intersection/planar_interval_solver.h>
#include <bezoutian/intersection/internal/space_interval_solver.h>
#include <bezoutian/intersection/internal/space_shape_basis.h>
#include <bezoutian/intersection/internal/common_component.h>

#include <CGAL/Polynomial.h>
#include <CGAL/Polynomial_traits_d.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>


namespace bezoutian {

/// How the eliminant polynomials R(s), T(t) are computed. Every strategy is followed by the same certified
/// pairing (subresultant inversion, exact sign decisions), so all of them return identical answers.
enum class Curve_intersection_method {
  default_method,  ///< the fast certified path: R(s) = det of the Bezout matrix of curve 2's (projected) implicit
                   ///< equation evaluated on curve 1 (multi-modular determinant), partners from two of its cofactors
                   ///< (du-1989 eq. 4.1, 4.3); configurations it cannot decide go to `subresultant`
  subresultant,    ///< R = Res_t(F1,F2), T = Res_s(F1,F2) with the subresultant sequence (3D: a combination with F3)
  projection,      ///< R = f2(X1,Y1,W1): implicit equation of curve 2 (bezout_implicit_equation, du-1989 eq. 4.1)
                   ///< on curve 1, and symmetrically T (planar curves; space curves use the default)
  resolvent,       ///< space curves with a curve of degree <= 3: R = gcd of Goldman's quadrics (du-1989 eq. 4.2/4.3)
                   ///< of that curve evaluated on the other one; otherwise as projection
  groebner         ///< R = generator of <F_1, .., F_D> ∩ Q[s] from a reduced lexicographic Groebner basis (t > s),
                   ///< T likewise with s > t (Groebner_bivariate.h: multi-modular basis certified over Q; exact
                   ///< Buchberger within a budget when no certificate applies, then Error)
};

/// Kind of an isolated intersection.
enum class Curve_intersection_kind { transversal, tangent, endpoint };

inline const char* to_string(Curve_intersection_kind k) {
  return k == Curve_intersection_kind::transversal ? "transversal"
                                                   : (k == Curve_intersection_kind::tangent ? "tangent" : "endpoint");
}

/// One isolated intersection C1(s) = C2(t), s, t in [0,1] exact algebraic numbers. On the planar default path
/// they may be lazy (Algebraic_real::is_lazy(): a proved enclosure, made exact on demand; see lazy_path).
struct Curve_intersection_point {
  Algebraic_real s, t;
  /// 1 for a transversal crossing; for tangencies the intersection multiplicity of the pair of branches: the
  /// multiplicity of the root of the eliminants (min over R(s) and T(t)) when a line s = s_i or t = t_j holds no
  /// other intersection, otherwise that of the sheared system's root (doc/curve_intersection.md step 5). In space
  /// it is computed on a projection (generic, so it equals the multiplicity of the space curves).
  int multiplicity = 1;
  Curve_intersection_kind kind = Curve_intersection_kind::transversal;
  /// Tangent directions parallel (decided exactly; also reported for endpoint hits).
  bool tangent = false;
};

/// A common piece: C1([s0,s1]) = C2([t0,t1]) with C1(s0) = C2(t0) (t0 > t1 when the orientations differ).
struct Curve_overlap {
  Algebraic_real s0, s1, t0, t1;
};

/// Result of intersect_curves.
struct Curve_intersection_result {
  std::vector<Curve_intersection_point> points;  ///< sorted by s, then t
  std::vector<Curve_overlap> overlaps;
};

/// \brief Resource limits of an intersection computation (curve/curve, curve/patch).
///
/// The size limits are checked before any computation, in the order max_control_points, max_degree,
/// max_degree_product, max_coefficient_bits; an input beyond one of them is refused with Limit_exceeded (stage
/// "input", limit() the name of the member). The defaults are far above the curves of CAD data (degrees <= 25,
/// coordinates of a few dozen digits) and keep every answer within seconds to about a minute on one core
/// (doc/hostile_input.md, "Hostile inputs and limits"). The time budget is checked between the stages of the
/// computation and ends it with Budget_exceeded (stage() the stage that had just run). A negative size limit (0 for
/// max_coefficient_bits and time_limit) means no limit; Intersection_limits::none() has no limit at all.
struct Intersection_limits {
  /// Largest degree of a curve, and of a patch in u and in v (default 64). A pair of random curves of degree 32
  /// takes ~7 s; a curve of degree 64 against a line ~4 s.
  int max_degree = 64;
  /// Largest number of control points of one object: n + 1 for a curve, (m + 1)(n + 1) for a patch (default 4225,
  /// a patch of bi-degree (64, 64)). Checked first: a curve with 100,000 control points is refused at once.
  long max_control_points = 4225;
  /// Largest product of the degrees (default 1024): deg C1 deg C2 for two curves (the Bezout number, the degree of
  /// the eliminants R(s), T(t)); 2 m n deg C for a curve and a patch of bi-degree (m, n) (the degree of R(r)).
  long max_degree_product = 1024;
  /// Largest size in bits of the numerator or denominator of a homogeneous control point coordinate (weight,
  /// w x, w y, ...) (default 4096, the readers' io::max_number_bits). 0: no limit.
  long max_coefficient_bits = 4096;
  /// Wall-clock budget in seconds (default 0: none), checked between the stages (interval solver, exact default
  /// path, elimination, root isolation, pairing, shear, overlaps): one stage may overrun it; the size limits bound
  /// how long a stage can run (within the default size limits, at most ~8 s on the inputs measured).
  double time_limit = 0;

  /// No limit at all.
  static Intersection_limits none() {
    Intersection_limits l;
    l.max_degree = -1;
    l.max_control_points = -1;
    l.max_degree_product = -1;
    l.max_coefficient_bits = 0;
    l.time_limit = 0;
    return l;
  }
};

/// Options of intersect_curves and self_intersections: the elimination method and the resource limits.
struct Curve_intersection_options {
  Curve_intersection_method method = Curve_intersection_method::default_method;  ///< how R(s), T(t) are computed
  Intersection_limits limits;  ///< size limits and time budget (Limit_exceeded, Budget_exceeded)
};

namespace internal {

/// Largest bit size of a numerator or denominator of a rational.
inline long rational_bits(const Rational& q) {
  const long a = CGAL::is_zero(q) ? 0 : long(mpz_sizeinbase(mpq_numref(q.mpq()), 2));
  const long b = long(mpz_sizeinbase(mpq_denref(q.mpq()), 2));
  return std::max(a, b);
}

/// Checks max_control_points and max_degree for one object given by its control point count and degrees; `what`
/// names it in the message ("curve 1").
inline void check_size_limits(const char* function, const std::string& what, const std::vector<int>& degrees,
                              long control_points, const Intersection_limits& l) {
  if (l.max_control_points >= 0 && control_points > l.max_control_points)
    throw Limit_exceeded(function, "input", "max_control_points",
                         what + " has " + std::to_string(control_points) + " control points, more than max_control_points = " +
                             std::to_string(l.max_control_points));
  for (int d : degrees)
    if (l.max_degree >= 0 && d > l.max_degree)
      throw Limit_exceeded(function, "input", "max_degree",
                           what + " has degree " + std::to_string(d) + ", more than max_degree = " +
                               std::to_string(l.max_degree));
}

inline void check_coefficient_bits(const char* function, const std::string& what, long bits, const Intersection_limits& l) {
  if (l.max_coefficient_bits > 0 && bits > l.max_coefficient_bits)
    throw Limit_exceeded(function, "input", "max_coefficient_bits",
                         what + " has a coordinate of " + std::to_string(bits) +
                             " bits (numerator or denominator of a homogeneous coordinate), more than max_coefficient_bits = " +
                             std::to_string(l.max_coefficient_bits));
}

inline void check_degree_product(const char* function, long product, const std::string& how,
                                 const Intersection_limits& l) {
  if (l.max_degree_product >= 0 && product > l.max_degree_product)
    throw Limit_exceeded(function, "input", "max_degree_product",
                         "the product of the degrees " + how + " = " + std::to_string(product) +
                             " is more than max_degree_product = " + std::to_string(l.max_degree_product));
}

/// The size limits for a curve (control points, degree, coefficient bits); the degree product is checked by the caller.
template <int D>
void check_curve_limits(const char* function, const std::string& what, const Rational_bezier_curve<Rational, D>& c,
                        const Intersection_limits& l) {
  check_size_limits(function, what, {c.degree()}, long(c.number_of_control_points()), l);
  if (l.max_coefficient_bits <= 0) return;
  long bits = 0;
  for (const auto& h : c.homogeneous_control_points())
    for (const Rational& x : h) bits = std::max(bits, rational_bits(x));
  check_coefficient_bits(function, what, bits, l);
}

/// Wall-clock budget of one computation, checked between its stages.
class Time_budget {
 public:
  Time_budget() = default;
  Time_budget(const char* function, double seconds)
      : function_(function), seconds_(seconds), start_(std::chrono::steady_clock::now()) {}
  /// Throws Budget_exceeded naming `stage` (the stage that has just run) when the budget is exhausted.
  void check(const char* stage) const {
    if (!(seconds_ > 0)) return;
    const double used = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (used > seconds_)
      throw Budget_exceeded(function_, stage,
                            std::to_string(used) + " s elapsed, more than time_limit = " + std::to_string(seconds_) + " s");
  }

 private:
  const char* function_ = "";
  double seconds_ = 0;
  std::chrono::steady_clock::time_point start_;
};

} // namespace internal

namespace internal {

/// The engine of intersect_curves and self_intersections (du-1989 ch. 4). run() dispatches to one path per case:
/// constant curves, the interval paths of the default method (lazy_path for plane curves, space_path for space
/// curves), the exclusion filter, the fast certified path (fast_path) and the exact system (solve_system), which
/// takes its eliminants from the method (strategy_R), pairs their roots, and hands a common component of all F_k
/// to overlap_case. The member groups are defined in intersection/internal/, included after the class:
///   curve_elimination_strategies.h  eliminate, strategy_R and one eliminant per method, clean-up, roots in [0,1]
///   curve_candidate_pairs.h         candidate systems and pairs, pairing of roots, points and their tangency
///   curve_shear.h                   the sheared system, its pairs and points, local multiplicity
///   curve_fast_projection.h         the fast certified path
///   curve_lazy_path.h               lazy_path and Planar_lazy_intersections
///   space_curve_path.h              space_path
template <int D>
class Curve_intersection_engine {
  using P1 = Ci_poly1;
  using P2 = Ci_poly2;
  using Curve = Rational_bezier_curve<Rational, D>;
  using Form = std::array<P1, D + 1>;

 public:
  /// planar_lazy = false skips the lazy planar path (the exact default path, for cross-checks and benchmarks).
  Curve_intersection_engine(const Curve& a, const Curve& b, Curve_intersection_method m, bool planar_lazy = true)
      : c1_(a), c2_(b), method_(m), planar_lazy_(planar_lazy), H1_(integer_power_form(a)), H2_(integer_power_form(b)) {
    for (const Form* H : {&H1_, &H2_})
      for (const P1& f : *H)
        for (int i = 0; i <= f.degree(); ++i) coefficient_bits_ = std::max(coefficient_bits_, long(f[i].bit_size()));
  }

  /// The wall-clock budget checked between the stages of run() and run_self() (Budget_exceeded).
  void set_time_budget(const Time_budget& b) { budget_ = b; }

  Curve_intersection_result run() {
    check_no_pole(c1_);
    check_no_pole(c2_);
    Curve_intersection_result res;
    const bool k1 = is_constant(H1_), k2 = is_constant(H2_);
    if (k1 || k2) {
      constant_case(k1, k2, res);
      return res;
    }
    budget_.check("power forms");
    if (method_ == Curve_intersection_method::default_method && planar_lazy_ && (lazy_path(res) || space_path(res))) {
      sort_points(res);
      return res;
    }
    budget_.check("interval solver");
    res = Curve_intersection_result();
    if (disjoint_hulls()) return res;
    if (method_ == Curve_intersection_method::default_method && fast_path(res)) {
      sort_points(res);
      return res;
    }
    budget_.check("exact default path");
    res = Curve_intersection_result();
    std::vector<P2> F;
    for (int k = 1; k <= D; ++k) F.push_back(cross_term(H1_[k], H2_[0], H2_[k], H1_[0]));
    solve_system(F, res, /*allow_overlap=*/true);
    sort_points(res);
    return res;
  }

  /// R(s) of the planar default path: det M(s), M(s) = W_A(s) Bez_B(X_A/W_A, Y_A/W_A) (see fast_projection),
  /// without the factors of W_A (no roots in [0,1]), primitive; 0 if it vanishes identically.
  static P1 planar_eliminant(const std::array<P1, 3>& A, const std::array<P1, 3>& B) {
    P1 R = polynomial_matrix_determinant(implicit_matrix_on(B, A));
    if (CGAL::is_zero(R)) return R;
    return primitive(divide_out(R, A[0]));
  }

  /// Self-intersections of c1 (c1 == c2): the divided differences F_k(s,t) / (s - t) (exact division, the diagonal
  /// s = t removed), solved like two curves; pairs with s < t are kept.
  Curve_intersection_result run_self() {
    check_no_pole(c1_);
    Curve_intersection_result res, all;
    if (is_constant(H1_)) {
      res.overlaps.push_back({Algebraic_real(0), Algebraic_real(1), Algebraic_real(0), Algebraic_real(1)});
      return res;
    }
    const P2 diag(P1(Integer(0), Integer(1)), P1(Integer(-1)));  // s - t
    std::vector<P2> F;
    for (int k = 1; k <= D; ++k) F.push_back(CGAL::integral_division(cross_term(H1_[k], H1_[0], H1_[k], H1_[0]), diag));
    std::vector<P2> G;
    for (const P2& f : F)
      if (!CGAL::is_zero(f)) G.push_back(f);
    if (G.size() < 2) throw Error("self_intersections: the curve is a straight line traversed non-monotonically or degenerate");
    solve_system(G, all, true);
    for (const auto& p : all.points)
      if (p.s < p.t) res.points.push_back(p);
    for (const auto& o : all.overlaps)
      if (o.s0 < o.t0 || o.s1 < o.t1) res.overlaps.push_back(o);
    sort_points(res);
    return res;
  }

  // Space curves: intervals, then the exact shape basis (space_curve_path.h). Public for benchmarks: true = the pair
  // was settled here, `res` holds the answer.
  bool space_path(Curve_intersection_result& res) const;

 private:
  // Exact exclusion filter: with all weights positive a curve lies in the bounding box of its control points
  // (convex hull property); disjoint boxes prove that there is no intersection.
  bool disjoint_hulls() const { return disjoint_pieces(c1_, c2_, 0); }

  // Subdivision exclusion (exact rational de Casteljau halves, down to depth 3 on each curve): if every pair of
  // pieces has disjoint control boxes, the curves do not meet. Cheap compared with the eliminants, and it proves
  // most "no intersection" answers of nearby curves.
  static bool disjoint_pieces(const Curve& a, const Curve& b, int depth) {
    if (disjoint_boxes(a, b)) return true;
    if (depth >= 3 || !positive_weights(a) || !positive_weights(b)) return false;
    const Rational half(1, 2);
    const auto pa = a.split(half), pb = b.split(half);
    return disjoint_pieces(pa.first, pb.first, depth + 1) && disjoint_pieces(pa.first, pb.second, depth + 1) &&
           disjoint_pieces(pa.second, pb.first, depth + 1) && disjoint_pieces(pa.second, pb.second, depth + 1);
  }
  static bool positive_weights(const Curve& c) {
    for (std::size_t i = 0; i < c.number_of_control_points(); ++i)
      if (CGAL::sign(c.weight(i)) <= 0) return false;
    return true;
  }
  static bool disjoint_boxes(const Curve& c1_, const Curve& c2_) {
    auto box = [](const Curve& c, std::array<Rational, D>& lo, std::array<Rational, D>& hi) {
      for (std::size_t i = 0; i < c.number_of_control_points(); ++i)
        if (CGAL::sign(c.weight(i)) <= 0) return false;
      for (std::size_t i = 0; i < c.number_of_control_points(); ++i) {
        const auto p = c.control_point(i);
        for (int k = 0; k < D; ++k) {
          if (i == 0 || p[k] < lo[k]) lo[k] = p[k];
          if (i == 0 || p[k] > hi[k]) hi[k] = p[k];
        }
      }
      return true;
    };
    std::array<Rational, D> l1, h1, l2, h2;
    if (!box(c1_, l1, h1) || !box(c2_, l2, h2)) return false;
    for (int k = 0; k < D; ++k)
      if (h1[k] < l2[k] || h2[k] < l1[k]) return true;
    return false;
  }

  // ---------------------------------------------------------------- degenerate (constant) curves
  static bool is_constant(const Form& H) {
    const Integer w0 = H[0][0];  // W(0) != 0 (no pole on [0,1])
    for (int k = 1; k <= D; ++k)
      if (!CGAL::is_zero(H[k] * P1(w0) - H[0] * P1(H[k][0]))) return false;
    return true;
  }

  void constant_case(bool k1, bool k2, Curve_intersection_result& res) const {
    const auto p1 = point_at<D>(H1_, Rational(0)), p2 = point_at<D>(H2_, Rational(0));
    if (k1 && k2) {
      if (p1 == p2) res.overlaps.push_back({Algebraic_real(0), Algebraic_real(1), Algebraic_real(0), Algebraic_real(1)});
      return;
    }
    std::vector<Algebraic_real> r;
    if (k1) {
      invert_point<D>(H2_, p1, r);
      for (const auto& t : r) res.overlaps.push_back({Algebraic_real(0), Algebraic_real(1), t, t});
    } else {
      invert_point<D>(H1_, p2, r);
      for (const auto& s : r) res.overlaps.push_back({s, s, Algebraic_real(0), Algebraic_real(1)});
    }
  }

  // ---------------------------------------------------------------- eliminants (curve_elimination_strategies.h)
  struct Elimination {
    P2 G1, G2;       // the pair whose subresultants give the inversion
    P1 R, S10, S11;  // Res_t(G1,G2) and the first subresultant S_1 = S11 t + S10 (w.r.t. t)
    bool ok = false;
    bool has_S1 = true;
  };
  static Elimination eliminate(const P2& G1, const P2& G2, bool with_S1 = true);
  P1 strategy_R(const Elimination& e, const Form& A, const Form& B) const;
  static P1 eliminant_groebner(const Elimination& e, const Form& A, const Form& B);
  static bool resolvent_applies(const Form& B);
  static P1 eliminant_resolvent(const Elimination& e, const Form& A, const Form& B);
  static P1 eliminant_projection(const Elimination& e, const Form& A, const Form& B);
  static P1 substitute_affine(const P2& f, const P1& X, const P1& Y, const P1& W);
  static int max_degree(const Form& H);
  template <class Q3>
  static P1 substitute_quadric(const Q3& q, const Form& A);
  bool plain_method() const {
    return method_ == Curve_intersection_method::default_method || method_ == Curve_intersection_method::subresultant;
  }
  static void clean(Elimination& e, const P1& W);
  static std::vector<Isolated_root> roots01(const P1& f);
  static P1 primitive(const P1& f);

  // ---------------------------------------------------------------- planar lazy path (curve_lazy_path.h)
  bool lazy_path(Curve_intersection_result& res) const;

  // ---------------------------------------------------------------- space path (space_curve_path.h)
  static P1 partner_polynomial(const P1& G, const P1& N, const Rational& q);

  // ---------------------------------------------------------------- fast certified path (curve_fast_projection.h)
  using Matrix1 = std::vector<std::vector<P1>>;
  enum class Fast { done, undecided };
  struct Undecided_tangency {};
  // The pairs (index in rs, index in rt) found by fast_projection, each once; exact: decided with rational
  // parameters (exact tangency test).
  struct Fast_pairs {
    std::vector<std::pair<int, int>> index;
    std::vector<char> exact;
    void add(int i, int j, bool is_exact) {
      for (const auto& q : index)
        if (q.first == i && q.second == j) return;
      index.push_back({i, j});
      exact.push_back(is_exact);
    }
  };
  bool fast_path(Curve_intersection_result& res) const;
  Fast fast_projection(const std::array<int, 3>& a, const std::array<int, 3>& b, Curve_intersection_result& res) const;
  void fast_exact_pairs(const std::vector<Isolated_root>& rs, const std::vector<Isolated_root>& rt,
                        std::vector<char>& s_done, Fast_pairs& pairs) const;
  std::vector<std::size_t> fast_interval_pairs(const std::array<P1, 3>& A, const std::array<P1, 3>& B,
                                               const std::vector<Isolated_root>& rs,
                                               const std::vector<Isolated_root>& rt, const std::vector<char>& s_done,
                                               int hidden, Fast_pairs& pairs) const;
  Fast fast_cofactor_pairs(const Matrix1& Ms, int nB, const std::vector<Isolated_root>& rs,
                           const std::vector<Isolated_root>& rt, const std::vector<std::size_t>& cofactor_roots,
                           int hidden, Curve_intersection_result& res) const;
  static std::array<P1, 3> projected(const Form& H, const std::array<int, 3>& a, const std::array<int, 3>& b);
  static int degree3(const std::array<P1, 3>& f);
  static Integer coefficient_xy(const P2& f, int i, int j);
  static Matrix1 implicit_matrix_on(const std::array<P1, 3>& B, const std::array<P1, 3>& A);
  static P1 cofactor_minor(const Matrix1& M, std::size_t row, std::size_t col);
  std::array<internal::Mpfi_interval, D> point_enclosure(const Form& H, const Algebraic_real& x,
                                                         mpfr_prec_t prec) const;
  Curve_intersection_point exact_point(const Isolated_root& s, const Isolated_root& t) const;
  bool space_coordinates_agree(const Algebraic_real& x, const Elimination& e, bool from_s, int hidden) const;

  // ---------------------------------------------------------------- pairing (curve_candidate_pairs.h)
  enum { none = -1, unresolved = -2 };
  static std::vector<std::vector<P2>> candidate_systems(const std::vector<P2>& F);
  static std::vector<std::pair<P2, P2>> candidate_pairs(const std::vector<P2>& F);
  static std::vector<int> pair_roots(const Elimination& e, const std::vector<Isolated_root>& ra,
                                     const std::vector<Isolated_root>& rb);
  static std::vector<int> pair_all(const std::vector<Elimination>& e, const std::vector<std::vector<Isolated_root>>& loc,
                                   const std::vector<Isolated_root>& ra, const std::vector<Isolated_root>& rb,
                                   bool rb_is_loc0);
  static Polynomial_1<Rational> to_rational(const P1& f);
  Curve_intersection_point make_point(const Isolated_root& s, const Isolated_root& t, const Elimination& es,
                                      const Elimination& et, bool s_direction) const;
  bool tangents_apart(const Algebraic_real& s, const Algebraic_real& t) const;
  bool parallel_tangents(const Algebraic_real& s, const Algebraic_real& t, const Elimination& e, bool s_direction) const;
  static std::array<internal::Mpfi_interval, D> make_array_of_intervals(mpfr_prec_t prec);

  // ---------------------------------------------------------------- the system F_k(s,t) = 0
  // The first candidate system whose eliminations have no common component; the eliminants of the method
  // (strategy_R), the pairing of their roots from s, then from t, the sheared system for roots unresolved in both
  // directions. A component common to all F_k goes to overlap_case.
  void solve_system(const std::vector<P2>& F, Curve_intersection_result& res, bool allow_overlap) {
    BEZOUTIAN_PROFILE_START;
    std::vector<Elimination> es, et;
    bool ok = false;
    for (const auto& G : candidate_systems(F)) {
      es.clear();
      et.clear();
      ok = true;
      for (std::size_t m = 1; m < G.size() && ok; ++m) {
        es.push_back(eliminate(G[0], G[m]));
        ok = es.back().ok && t_degree(swap_variables(G[0])) >= 1 && t_degree(swap_variables(G[m])) >= 1;
        if (ok) {
          et.push_back(eliminate(swap_variables(G[0]), swap_variables(G[m]), false));
          ok = et.back().ok;
        }
      }
      if (ok) break;
    }
    BEZOUTIAN_PROFILE_STEP("eliminate");
    budget_.check("elimination");
    if (!ok) {
      if (!allow_overlap) throw Error("intersect_curves: the reduced system still has a common component");
      overlap_case(F, res);
      return;
    }
    // Location lists: roots in [0,1] of every resultant; main lists: the strategy's eliminant (2D default: the same
    // polynomial as the first location list; space: the gcd of the resultants).
    // The weights have no root in [0,1]: remove the factors W1(s)^n2 (resp. W2(t)^n1) of the resultants (roots at
    // infinity) and common weight factors of S10, S11 (their ratio is unchanged where W != 0).
    for (auto& e : es) clean(e, H1_[0]);
    for (auto& e : et) clean(e, H2_[0]);
    std::vector<std::vector<Isolated_root>> ls, lt;
    for (const auto& e : es) ls.push_back(roots01(primitive(e.R)));
    for (const auto& e : et) lt.push_back(roots01(primitive(e.R)));
    const bool plain = plain_method() || (D == 3 && method_ == Curve_intersection_method::projection);
    std::vector<Isolated_root> rs, rt;
    if (plain && es.size() == 1) {
      rs = ls[0];
      rt = lt[0];
    } else {
      P1 R = strategy_R(es[0], H1_, H2_), T = strategy_R(et[0], H2_, H1_);
      for (std::size_t m = 1; m < es.size(); ++m) {
        if (method_ != Curve_intersection_method::resolvent || CGAL::is_zero(R)) R = CGAL::gcd(R, es[m].R);
        if (method_ != Curve_intersection_method::resolvent || CGAL::is_zero(T)) T = CGAL::gcd(T, et[m].R);
      }
      rs = roots01(primitive(R));
      rt = roots01(primitive(T));
    }
    BEZOUTIAN_PROFILE_STEP("isolate");
    budget_.check("root isolation");
    const bool same_lists = plain && es.size() == 1;
    std::vector<int> ps = pair_all(es, lt, rs, rt, same_lists);
    // The t direction is needed only for s-roots left unresolved (otherwise every pair was found from s).
    std::vector<int> pt(rt.size(), none);
    if (std::find(ps.begin(), ps.end(), int(unresolved)) != ps.end()) {
      for (std::size_t m = 0; m < et.size(); ++m) {
        et[m] = eliminate(et[m].G1, et[m].G2, true);
        clean(et[m], H2_[0]);
      }
      pt = pair_all(et, ls, rt, rs, same_lists);
    }
    BEZOUTIAN_PROFILE_STEP("pair");
    budget_.check("pairing");
    std::vector<std::pair<int, int>> pairs;
    for (std::size_t i = 0; i < ps.size(); ++i)
      if (ps[i] >= 0) pairs.push_back({int(i), ps[i]});
    for (std::size_t j = 0; j < pt.size(); ++j)
      if (pt[j] >= 0) pairs.push_back({pt[j], int(j)});
    // Pairs whose both members are unresolved (several intersections on one line s = s_i and on one line t = t_j):
    // exact evaluation when both are rational, otherwise the sheared system in u = s + lambda t.
    std::vector<int> us, ut;
    for (std::size_t i = 0; i < ps.size(); ++i)
      if (ps[i] == unresolved) us.push_back(int(i));
    for (std::size_t j = 0; j < pt.size(); ++j)
      if (pt[j] == unresolved) ut.push_back(int(j));
    // Neither elimination describes such a point (S11 vanishes on both lines), so its tangency and multiplicity come
    // from the sheared system too, where the point is alone on its line u = u_k.
    std::vector<Sheared_pair> sheared;
    if (!us.empty() && !ut.empty()) {
      sheared = sheared_pairs(F, rs, rt, us, ut);
      budget_.check("shear");
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    for (const auto& p : pairs) res.points.push_back(make_point(rs[p.first], rt[p.second], es[0], et[0], ps[p.first] >= 0));
    for (const auto& p : sheared) res.points.push_back(sheared_point(rs[p.i], rt[p.j], p));
    BEZOUTIAN_PROFILE_STEP("points");
  }

  // ---------------------------------------------------------------- shear (curve_shear.h)
  struct Sheared_pair {
    int i, j;           // indices into the s- and t-roots
    Isolated_root u;    // u_k = s + lambda t, a root of the sheared resultant (its multiplicity: see sheared_point)
    P1 S10, S11;        // t = -S10(u)/S11(u), S11(u_k) != 0
    int lambda;
  };
  static std::vector<P2> sheared_system(const std::vector<P2>& F, int lambda);
  static bool sheared_elimination(const std::vector<P2>& Fs, Elimination& e);
  int local_multiplicity(const std::vector<P2>& F, const Rational& a, const Rational& b) const;
  std::vector<Sheared_pair> sheared_pairs(const std::vector<P2>& F, const std::vector<Isolated_root>& rs,
                                          const std::vector<Isolated_root>& rt, const std::vector<int>& us,
                                          const std::vector<int>& ut) const;
  Curve_intersection_point sheared_point(const Isolated_root& s, const Isolated_root& t, const Sheared_pair& q) const;

  // ---------------------------------------------------------------- overlaps (common component of the F_k)
  void overlap_case(const std::vector<P2>& F, Curve_intersection_result& res) {
    P2 H = F[0];
    for (std::size_t k = 1; k < F.size(); ++k) H = CGAL::gcd(H, F[k]);
    const P2 Hs = swap_variables(H);
    if (t_degree(H) < 1 || t_degree(Hs) < 1)
      throw Error("intersect_curves: a curve has a base point (common root of its homogeneous coordinates); "
                  "reduce it first");
    // Breakpoints on curve 1: its ends and the preimages of the ends of curve 2, with their partners on curve 2
    // (for ends of curve 1: by inversion).
    using Break = Component_breakpoint<Algebraic_real>;
    std::vector<Break> br;
    for (int e = 0; e <= 1; ++e) {
      Break b{Algebraic_real(e), {}};
      invert_point<D>(H2_, point_at<D>(H1_, Rational(e)), b.partners);
      br.push_back(b);
      std::vector<Algebraic_real> ss;
      invert_point<D>(H1_, point_at<D>(H2_, Rational(e)), ss);
      for (const auto& s : ss) br.push_back(Break{s, {Algebraic_real(e)}});
    }
    // Piece (b_i, b_{i+1}) is covered iff its rational midpoint lies on C2([0,1]) (the image of curve 1 lies on the
    // irreducible implicit curve of curve 2, and coverage can only change at the preimages of C2(0), C2(1)).
    std::vector<double> tmid;  // per piece: a partner of its midpoint on curve 2 (0 if not covered)
    const Common_component<Algebraic_real> cc =
        common_component(std::move(br), [&](const Algebraic_real& a, const Algebraic_real& b) {
          const Rational m = piece_midpoint(a, b);
          std::vector<Algebraic_real> t;
          invert_point<D>(H2_, point_at<D>(H1_, m), t);
          tmid.push_back(t.empty() ? 0 : t.front().to_double());
          return !t.empty();
        });
    const std::vector<Break>& ub = cc.breaks;
    auto pick = [](const std::vector<Algebraic_real>& c, double near) {
      std::size_t best = 0;
      for (std::size_t k = 1; k < c.size(); ++k)
        if (std::abs(c[k].to_double() - near) < std::abs(c[best].to_double() - near)) best = k;
      return c[best];
    };
    std::vector<Curve_overlap> ov;
    for (const auto& run : cc.runs) {
      const std::size_t i = run.first, j = run.second - 1;  // the pieces i .. j are covered
      if (ub[i].partners.empty() || ub[j + 1].partners.empty())
        throw Error("intersect_curves: overlap end without partner");
      ov.push_back({ub[i].x, ub[j + 1].x, pick(ub[i].partners, tmid[i]), pick(ub[j + 1].partners, tmid[j])});
    }
    auto inside = [&](const Algebraic_real& s, const Algebraic_real& t) {
      for (const auto& o : ov) {
        const bool ins = o.s0 <= s && s <= o.s1;
        const bool int_ = (o.t0 <= t && t <= o.t1) || (o.t1 <= t && t <= o.t0);
        if (ins && int_) return true;
      }
      return false;
    };
    budget_.check("overlaps");
    // Isolated touching points at breakpoints.
    for (const Break& b : ub)
      for (const auto& t : b.partners)
        if (!inside(b.x, t)) {
          Curve_intersection_point p;
          p.s = b.x;
          p.t = t;
          p.kind = Curve_intersection_kind::endpoint;
          res.points.push_back(p);
        }
    // Isolated intersections off the common component: the cofactors F_k / H.
    std::vector<P2> A;
    for (const P2& f : F) A.push_back(CGAL::integral_division(f, H));
    bool constant = true;
    for (const P2& a : A)
      if (t_degree(a) > 0 || t_degree(swap_variables(a)) > 0) constant = false;
    if (!constant) {
      Curve_intersection_result sub;
      bool has_zero = false;
      for (const P2& a : A)
        if (t_degree(a) == 0 && t_degree(swap_variables(a)) == 0) has_zero = true;  // nonzero constant: no zeros
      if (!has_zero) solve_system(A, sub, false);
      for (const auto& p : sub.points)
        if (!inside(p.s, p.t)) {
          bool dup = false;
          for (const auto& q : res.points) dup = dup || (q.s == p.s && q.t == p.t);
          if (!dup) res.points.push_back(p);
        }
    }
    res.overlaps = ov;
  }

  static void sort_points(Curve_intersection_result& res) {
    std::sort(res.points.begin(), res.points.end(), [](const Curve_intersection_point& a, const Curve_intersection_point& b) {
      const int c = a.s.compare(b.s);
      return c != 0 ? c < 0 : a.t < b.t;
    });
  }

  const Curve& c1_;
  const Curve& c2_;
  Curve_intersection_method method_;
  bool planar_lazy_ = true;
  Form H1_, H2_;
  long coefficient_bits_ = 0;
  Time_budget budget_;
};

} // namespace internal
} // namespace bezoutian

#include <bezoutian/intersection/internal/curve_elimination_strategies.h>
#include <bezoutian/intersection/internal/curve_candidate_pairs.h>
#include <bezoutian/intersection/internal/curve_shear.h>
#include <bezoutian/intersection/internal/curve_fast_projection.h>
#include <bezoutian/intersection/internal/curve_lazy_path.h>
#include <bezoutian/intersection/internal/space_curve_path.h>

namespace bezoutian {

/// \brief All intersections of C1(s), s in [0,1], and C2(t), t in [0,1]: isolated points (s,t) as exact algebraic
/// numbers and overlapping pieces. Both curves must have no pole in [0,1] (Invalid_input otherwise).
///
/// Method (du-1989 ch. 4): F_k(s,t) = X1_k(s) W2(t) - X2_k(t) W1(s); R(s), T(t) eliminants whose roots in [0,1]
/// contain the parameters of all intersections; each root s_i of R is paired with t* = -S10(s_i)/S11(s_i) from the
/// first subresultant S_1 of (F1,F2) w.r.t. t (valid when S11(s_i) != 0 and a leading coefficient does not vanish,
/// both decided exactly), located among the roots of T by exact sign decisions; symmetrically in t. A vanishing
/// resultant means a common component: overlaps are then found from the preimages of the curve ends.
/// Plane curves, default method: a certified interval solver runs first; when it proves every intersection
/// (transversal crossings strictly inside (0,1)^2) the parameters are returned lazily (exact on demand).
///
/// Resource limits (`options.limits`, Intersection_limits): curves beyond a size limit are refused before any
/// computation, and the time budget is checked between the stages; both end with Limit_exceeded (Budget_exceeded for
/// the time) naming the stage and the limit. The lazy parameters of the result are made exact outside the budget.
template <int D>
Curve_intersection_result intersect_curves(const Rational_bezier_curve<Rational, D>& c1,
                                           const Rational_bezier_curve<Rational, D>& c2,
                                           const Curve_intersection_options& options) {
  static const char* const function = "intersect_curves";
  const internal::Time_budget budget(function, options.limits.time_limit);
  internal::check_curve_limits(function, "curve 1", c1, options.limits);
  internal::check_curve_limits(function, "curve 2", c2, options.limits);
  internal::check_degree_product(function, long(c1.degree()) * c2.degree(),
                                 std::to_string(c1.degree()) + " x " + std::to_string(c2.degree()), options.limits);
  internal::Curve_intersection_engine<D> engine(c1, c2, options.method);
  engine.set_time_budget(budget);
  return engine.run();
}

/// \brief intersect_curves with the given method and the default limits (Intersection_limits).
template <int D>
Curve_intersection_result intersect_curves(const Rational_bezier_curve<Rational, D>& c1,
                                           const Rational_bezier_curve<Rational, D>& c2,
                                           Curve_intersection_method method = Curve_intersection_method::default_method) {
  Curve_intersection_options options;
  options.method = method;
  return intersect_curves(c1, c2, options);
}

/// \brief Self-intersections (loops) of a curve: pairs s < t in [0,1] with C(s) = C(t), exact (the system
/// (X_k(s)W(t) - X_k(t)W(s)) / (s - t) = 0, divided differences, solved like intersect_curves). The limits as in
/// intersect_curves, the degree product being deg C x deg C.
template <int D>
Curve_intersection_result self_intersections(const Rational_bezier_curve<Rational, D>& c,
                                             const Curve_intersection_options& options) {
  static const char* const function = "self_intersections";
  const internal::Time_budget budget(function, options.limits.time_limit);
  internal::check_curve_limits(function, "the curve", c, options.limits);
  internal::check_degree_product(function, long(c.degree()) * c.degree(),
                                 std::to_string(c.degree()) + " x " + std::to_string(c.degree()), options.limits);
  internal::Curve_intersection_engine<D> engine(c, c, options.method);
  engine.set_time_budget(budget);
  return engine.run_self();
}

/// \brief self_intersections with the given method and the default limits (Intersection_limits).
template <int D>
Curve_intersection_result self_intersections(const Rational_bezier_curve<Rational, D>& c,
                                             Curve_intersection_method method = Curve_intersection_method::default_method) {
  Curve_intersection_options options;
  options.method = method;
  return self_intersections(c, options);
}

/// Functor form (CGAL style).
struct Intersect_curves {
  Curve_intersection_method method = Curve_intersection_method::default_method;
  Intersection_limits limits;  ///< resource limits (defaults: Intersection_limits)
  template <int D>
  Curve_intersection_result operator()(const Rational_bezier_curve<Rational, D>& c1,
                                       const Rational_bezier_curve<Rational, D>& c2) const {
    return intersect_curves(c1, c2, Curve_intersection_options{method, limits});
  }
};

/// Parses "default", "subresultant", "projection", "resolvent", "groebner".
inline Curve_intersection_method curve_intersection_method_from_string(const std::string& s) {
  if (s == "default") return Curve_intersection_method::default_method;
  if (s == "subresultant") return Curve_intersection_method::subresultant;
  if (s == "projection") return Curve_intersection_method::projection;
  if (s == "resolvent") return Curve_intersection_method::resolvent;
  if (s == "groebner") return Curve_intersection_method::groebner;
  throw Invalid_input("unknown curve intersection method '" + s + "'");
}

} // namespace bezoutian

#endif // BEZOUTIAN_INTERSECTION_CURVE_INTERSECTION_H
