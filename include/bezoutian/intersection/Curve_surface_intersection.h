// Certified intersection of a rational Bezier space curve (or a segment) with a rational tensor-product Bezier
// patch: du-1989 Problems 2.2a / 2.2b, solved with the generalized Bezoutian of buse-elkadi-galligo-2008
// Definition 1. See doc/curve_surface_intersection.md for the method and the proofs.
#ifndef BEZOUTIAN_INTERSECTION_CURVE_SURFACE_INTERSECTION_H
#define BEZOUTIAN_INTERSECTION_CURVE_SURFACE_INTERSECTION_H

#include <bezoutian/arithmetic/profiling.h>
#include <bezoutian/algebraic/Algebraic_real.h>
#include <bezoutian/elimination/Bezoutian.h>
#include <bezoutian/intersection/Curve_intersection.h>
#include <bezoutian/intersection/internal/common_component.h>
#include <bezoutian/intersection/internal/curve_patch_fibres.h>
#include <bezoutian/intersection/internal/curve_patch_implicit_matrix.h>
#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/elimination/exact_linear_algebra.h>
#include <bezoutian/arithmetic/interval_krawczyk.h>
#include <bezoutian/elimination/Polynomial_matrix_determinant.h>
#include <bezoutian/geometry/Rational_bezier_curve.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>
#include <bezoutian/algebraic/Root_isolation.h>
#include <bezoutian/geometry/Weight_validity.h>
#include <bezoutian/arithmetic/number_types.h>

#include <CGAL/Polynomial.h>
#include <CGAL/Polynomial_traits_d.h>

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>


namespace bezoutian {

/// Kind of an isolated curve/patch intersection.
enum class Curve_patch_intersection_kind {
  transversal,  ///< simple root of the eliminant R(r): the curve crosses the surface
  tangent,      ///< multiple root of R(r) with a single preimage (u,v): the curve touches the surface
  endpoint,     ///< r = 0 or r = 1
  boundary      ///< r inside (0,1), (u,v) on the boundary of [0,1]^2
};

inline const char* to_string(Curve_patch_intersection_kind k) {
  switch (k) {
    case Curve_patch_intersection_kind::transversal: return "transversal";
    case Curve_patch_intersection_kind::tangent: return "tangent";
    case Curve_patch_intersection_kind::endpoint: return "endpoint";
    default: return "boundary";
  }
}

/// One isolated intersection C(r) = Phi(u,v) with r, u, v in [0,1], all three exact algebraic numbers.
struct Curve_patch_intersection_point {
  Algebraic_real r, u, v;
  /// Multiplicity of r as a root of the eliminant R(r) = det M(C(r)) (the intersection multiplicity of the
  /// curve with the implicit surface when the patch parametrizes it once); 0 for touching points found while
  /// the curve lies on the implicit surface (no eliminant).
  /// For a point C(r) with several preimages or singular on the surface (found by the grid step, see
  /// doc/curve_surface_intersection.md), one entry per preimage (u,v) with multiplicity 1 if (r,u,v) is a simple
  /// solution of C(r) = Phi(u,v) (the curve crosses that sheet transversally; proved), or 0 with tangent = true if
  /// it is a singular one (the curve is tangent to that sheet or the point is singular on the surface; decided
  /// exactly, only possible when at most one of r, u, v is irrational, otherwise Error).
  int multiplicity = 1;
  Curve_patch_intersection_kind kind = Curve_patch_intersection_kind::transversal;
  /// multiplicity >= 2, or a singular solution found by the grid step: the curve is tangent to the surface (or
  /// the point is singular on it).
  bool tangent = false;
  /// Floating-point approximation of the common point (C evaluated at the double nearest to r).
  std::array<double, 3> point{};
  /// -1, or a collapsed line of the patch through this point: 0 = every (u, v') with v' in [0,1] is a preimage (the
  /// iso-line u = this->u maps to one point; v is reported as 0), 1 = every (u', v), u' in [0,1] (u reported as 0).
  /// Such points have multiplicity 0 (not determined). Only patches with base points have collapsed lines.
  int collapsed_line = -1;
};

/// A piece C([r0, r1]) of the curve contained in the patch Phi([0,1]^2) (r0 < r1, exact ends).
struct Curve_patch_overlap {
  Algebraic_real r0, r1;
};

/// Result of intersect_curve_patch.
struct Curve_patch_intersection_result {
  std::vector<Curve_patch_intersection_point> points;  ///< sorted by r, then u, then v
  std::vector<Curve_patch_overlap> overlaps;            ///< sorted, disjoint
};

namespace internal {
namespace cs {

/// The curve/patch engine. run() dispatches: the exclusion filter, a constant curve, then on R(r) = det M(C(r)):
/// the isolated intersections of its roots (resolve: kernel inversion, or the grid step of add_fibre), the curve on
/// the implicit surface (on_surface_case), a patch with base points (base_point_case). It uses the implicit matrix
/// and kernel analysis of intersection/internal/curve_patch_implicit_matrix.h and the grid step of intersection/internal/curve_patch_fibres.h;
/// its member groups are defined in intersection/internal/, included after the class:
///   curve_patch_eliminants.h   compute_eliminants: U(u), V(v) from projections of the curve
///   curve_patch_base_points.h  the implicit matrix test, collapsed edges and lines, base_point_case
///   curve_patch_on_surface.h   on_surface_case (the common-component routine, common_component.h)
class Curve_patch_engine {
 public:
  using Curve = Rational_bezier_curve<Rational, 3>;
  using Patch = Rational_bezier_patch<Rational>;

  Curve_patch_engine(const Curve& c, const Patch& p) : curve_(c), patch_(p) {}

  /// The wall-clock budget checked between the stages of run() (Budget_exceeded).
  void set_time_budget(const Time_budget& b) { budget_ = b; }

  Curve_patch_intersection_result run() {
    if (patch_.degree_u() < 1 || patch_.degree_v() < 1)
      throw Invalid_input("intersect_curve_patch: the patch has degree 0 in u or in v (it is a curve, not a surface)");
    check_no_pole(curve_);
    check_no_pole(patch_);
    Curve_patch_intersection_result res;
    BEZOUTIAN_PROFILE_START;
    H_ = integer_curve_form(curve_);
    if (disjoint_boxes()) return res;
    matrix_ = std::make_shared<Patch_implicit_matrix>(patch_);
    if (is_constant()) {
      // with base points the kernel of M always holds their monomial vectors: the kernel test would be wrong
      check_implicit_matrix_regular();
      const auto pre = preimages(curve_(Rational(0)));
      if (!pre.empty()) res.overlaps.push_back({Algebraic_real(0), Algebraic_real(1)});
      return res;
    }
    BEZOUTIAN_PROFILE_STEP("matrix");
    budget_.check("implicit matrix");
    M_ = matrix_->at_curve(H_);
    // R(r) = det M(C(r)): the implicit equation of the surface along the curve (buse-elkadi-galligo-2008 §2:
    // the determinant of the Bezoutian matrix is the resultant). Degree <= 2 m n deg C.
    const Z1 R = small_polynomial_determinant(M_);
    R_ = R;
    BEZOUTIAN_PROFILE_STEP("det");
    budget_.check("determinant");
    if (CGAL::is_zero(R)) {
      if (implicit_matrix_regular())
        on_surface_case(res);
      else
        base_point_case(res);
    } else {
      const auto roots = separated_roots(R, Rational(0), Rational(1));
      BEZOUTIAN_PROFILE_STEP("isolate");
      budget_.check("root isolation");
      for (const Isolated_root& root : roots) {
        resolve(root, res);
        budget_.check("preimages");
      }
      BEZOUTIAN_PROFILE_STEP("resolve");
    }
    sort_points(res);
    return res;
  }

  /// All (u,v) in [0,1]^2 with Phi(u,v) = p (rational point), from the kernel of M(1, p); if the kernel has
  /// dimension > 1 (several preimages or a singular point), from the grid step along a line through p.
  std::vector<std::pair<Algebraic_real, Algebraic_real>> preimages(const std::array<Rational, 3>& p) const {
    const Kernel_answer k = analyse_kernel(matrix_->at_point({Rational(1), p[0], p[1], p[2]}));
    if (k.status == Kernel_answer::degenerate) return fibre_of_point(p);
    std::vector<std::pair<Algebraic_real, Algebraic_real>> out;
    if (k.status == Kernel_answer::affine && in_unit_interval(k.u) && in_unit_interval(k.v)) {
      // the kernel argument gives the unique common root; checked by exact evaluation as well
      if (patch_(k.u, k.v) != p) throw Error("intersect_curve_patch: kernel inversion failed (internal error)");
      out.push_back({Algebraic_real(k.u), Algebraic_real(k.v)});
    }
    return out;
  }

  /// The preimages (u_j, v_k) over the root r of R (the grid step; see Fibre_system, decide_grid_point). Requires
  /// R_ and the curve form H_; throws Singular_fibre_error for a singular solution with an irrational coordinate.
  std::vector<Fibre_point> fibre(const Algebraic_real& r,
                                 const std::vector<std::pair<int, Rational>>& skip_lines = {}) {
    compute_eliminants();
    const Fibre_system S(H_, dense_patch_form());
    std::array<Root_window, 3> w{root_window(R_, r), Root_window{}, Root_window{}};
    std::vector<Root_window> wv;
    for (const Isolated_root& y : eliminant_roots_[1]) wv.push_back(root_window(V_, y.root));
    std::vector<Fibre_point> out;
    for (const Isolated_root& x : eliminant_roots_[0]) {
      w[1] = root_window(U_, x.root);
      for (const Root_window& y : wv) {
        w[2] = y;
        bool on_skipped_line = false;  // a collapsed line through C(r): every point of it is a preimage
        for (const auto& l : skip_lines) on_skipped_line = on_skipped_line || w[1 + l.first].x == Algebraic_real(l.second);
        if (on_skipped_line) continue;
        const int d = decide_grid_point(S, w);
        if (d != 0) out.push_back(Fibre_point{w[1].x, w[2].x, d == 1});
      }
    }
    return out;
  }

 private:
  bool is_constant() const {
    const Integer w0 = H_[0][0];
    for (int k = 1; k < 4; ++k)
      if (!CGAL::is_zero(H_[k] * Z1(w0) - H_[0] * Z1(H_[k][0]))) return false;
    return true;
  }

  // Exact exclusion: with weights of one sign the curve (patch) lies in the box of its control points.
  bool disjoint_boxes() const {
    if (!curve_.encloses_curve() || !patch_.encloses_patch()) return false;
    const auto a = curve_.control_box();
    const auto b = patch_.control_box();
    for (int k = 0; k < 3; ++k)
      if (a.second[k] < b.first[k] || b.second[k] < a.first[k]) return true;
    return false;
  }

  // ------------------------------------------------------------------ base points (curve_patch_base_points.h)
  // det M(w,x) == 0 identically: base points or a patch whose image is not a surface.
  bool implicit_matrix_regular() const;
  void check_implicit_matrix_regular() const;
  std::string collapsed_edges() const;
  void base_point_case(Curve_patch_intersection_result& res);
  bool collapsed_line(int dir, const Rational& t, Rational& p0, Rational (&p)[3]) const;
  Z1 base_point_r_eliminant() const;

  // ------------------------------------------------------------------ isolated intersections
  void resolve(const Isolated_root& root, Curve_patch_intersection_result& res) {
    const Algebraic_real& r = root.root;
    if (r.is_rational()) {
      const Rational q = r.rational_value();
      const auto h = curve_.homogeneous_value(q);
      const Kernel_answer k = analyse_kernel(matrix_->at_point({h[0], h[1], h[2], h[3]}));
      if (k.status == Kernel_answer::degenerate) return add_fibre(res, r);  // several preimages or singular
      if (k.status != Kernel_answer::affine || !in_unit_interval(k.u) || !in_unit_interval(k.v)) return;
      if (patch_(k.u, k.v) != curve_(q)) throw Error("intersect_curve_patch: kernel inversion failed (internal error)");
      add_point(res, r, Algebraic_real(k.u), Algebraic_real(k.v), root.multiplicity);
      return;
    }
    // Irrational r: adj M(r) = x y^T when rank M = N-1, so with D11 = adj_00, Du = adj_01 (row u of y), Dv = adj_10
    // (column v of x): D11(r) != 0 proves rank N-1 and a unique affine common root u = Du/D11, v = Dv/D11.
    compute_minors();
    BEZOUTIAN_PROFILE_STEP("minors");
    const int s = r.sign_of(D11_);
    if (s == 0) return add_fibre(res, r);  // rank < N-1 (several preimages, singular point) or root at infinity
    Algebraic_real u, v;
    if (!located(r, Du_, s, 0, u) || !located(r, Dv_, s, 1, v)) return;
    add_point(res, r, u, v, root.multiplicity);
  }

  // Points over r from the grid step: multiplicity 1 for a simple solution of C(r) = Phi(u,v) (the curve crosses
  // that sheet transversally), 0 and tangent for a singular one (decided exactly, at most one irrational coordinate).
  void add_fibre(Curve_patch_intersection_result& res, const Algebraic_real& r,
                  const std::vector<std::pair<int, Rational>>& skip_lines = {}) {
    BEZOUTIAN_PROFILE_STEP("grid step");
    for (const Fibre_point& f : fibre(r, skip_lines)) {
      add_point(res, r, f.u, f.v, f.simple ? 1 : 0);
      if (!f.simple) {
        res.points.back().tangent = true;
        if (res.points.back().kind == Curve_patch_intersection_kind::transversal)
          res.points.back().kind = Curve_patch_intersection_kind::tangent;
      }
    }
  }

  // Preimages of a rational point p with a degenerate kernel: the fibre over r = 1/2 of the segment
  // p + (2r - 1) d, whose intersections at r = 1/2 are exactly the preimages of p. A direction d tangent to a
  // sheet at p gives a singular solution; the next direction is tried.
  std::vector<std::pair<Algebraic_real, Algebraic_real>> fibre_of_point(const std::array<Rational, 3>& p) const {
    const int dirs[3][3] = {{1, 2, 3}, {3, -1, 2}, {-2, 5, 1}};
    std::string last = "the lines through it lie on the surface";
    for (const auto& d : dirs) {
      std::array<Rational, 3> a = p, b = p;
      for (int k = 0; k < 3; ++k) {
        a[k] -= Rational(d[k]);
        b[k] += Rational(d[k]);
      }
      const Curve segment(std::vector<std::array<Rational, 3>>{a, b});
      Curve_patch_engine e(segment, patch_);
      e.H_ = integer_curve_form(segment);
      e.matrix_ = matrix_;
      e.M_ = matrix_->at_curve(e.H_);
      e.R_ = small_polynomial_determinant(e.M_);
      if (CGAL::is_zero(e.R_)) continue;
      try {
        std::vector<std::pair<Algebraic_real, Algebraic_real>> out;
        for (const Fibre_point& f : e.fibre(Algebraic_real(Rational(1, 2)))) out.push_back({f.u, f.v});
        return out;
      } catch (const Singular_fibre_error& err) {
        last = err.what();
      }
    }
    throw Error("intersect_curve_patch: the preimages of the point (" + str(p[0]) + ", " + str(p[1]) + ", " +
                str(p[2]) + ") (several preimages or a singular point) could not be decided: " + last);
  }

  void compute_minors() {
    if (have_minors_) return;
    D11_ = to_q(small_polynomial_determinant(delete_row_column(M_, 0, 0)));
    Du_ = -to_q(small_polynomial_determinant(delete_row_column(M_, 1, 0)));
    Dv_ = -to_q(small_polynomial_determinant(delete_row_column(M_, 0, 1)));
    have_minors_ = true;
  }

  // x0 = A(r)/D11(r) (sign of D11(r) = s): false if x0 is outside [0,1] (proved); otherwise x0 as an exact
  // algebraic number: a root of the eliminant E (U or V, which vanishes at every intersection parameter), located
  // among its isolated roots in [0,1] by exact sign decisions sign(x0 - c) = sign(A - c D11)(r) * s.
  bool located(const Algebraic_real& r, const Q1& A, int s, int direction, Algebraic_real& out) {
    auto cmp = [&](const Rational& c) { return r.sign_of(A - D11_ * Q1(c)) * s; };
    const int c0 = cmp(Rational(0)), c1 = cmp(Rational(1));
    if (c0 < 0 || c1 > 0) return false;
    if (c0 == 0) return out = Algebraic_real(0), true;
    if (c1 == 0) return out = Algebraic_real(1), true;
    compute_eliminants();
    for (const Isolated_root& x : eliminant_roots_[direction]) {
      const Algebraic_real& a0 = x.root;
      const bool here = a0.is_rational() ? cmp(a0.rational_value()) == 0
                                         : (cmp(a0.lower()) > 0 && cmp(a0.upper()) < 0);
      if (here) return out = a0, true;
    }
    throw Error("intersect_curve_patch: parameter not located among the eliminant roots (internal error)");
  }

  // ------------------------------------------------------------------ eliminants U, V (curve_patch_eliminants.h)
  void compute_eliminants(bool remove_lines = false);
  static Z1 remove_common_content(Z2& g1, Z2& g2);
  std::array<Z2, 4> dense_patch_form() const;
  static Z1 linear_form(const int* c, const std::array<Z1, 4>& H);
  static Z2 linear_form(const int* c, const std::array<Z2, 4>& P);
  Z2 projected_on_patch(const int* la, const int* lb, const std::array<Z2, 4>& Phi) const;
  static Z2 swap_uv(const Z2& g);
  static Z1 eliminant(const Z2& g1, const Z2& g2);
  static Z1 outer_resultant(const Z2& g1, const Z2& g2);

  void add_point(Curve_patch_intersection_result& res, const Algebraic_real& r, const Algebraic_real& u,
                 const Algebraic_real& v, int multiplicity) const {
    Curve_patch_intersection_point p;
    p.r = r;
    p.u = u;
    p.v = v;
    p.multiplicity = multiplicity;
    p.tangent = multiplicity >= 2;
    if (is_zero_or_one(r))
      p.kind = Curve_patch_intersection_kind::endpoint;
    else if (is_zero_or_one(u) || is_zero_or_one(v))
      p.kind = Curve_patch_intersection_kind::boundary;
    else
      p.kind = p.tangent ? Curve_patch_intersection_kind::tangent : Curve_patch_intersection_kind::transversal;
    p.point = curve_.evaluate(r.to_double());
    res.points.push_back(p);
  }

  // ------------------------------------------------------------------ the curve lies on the implicit surface
  // (curve_patch_on_surface.h); breakpoints with their known preimages (u, v) (from the boundary curves)
  using Break = Component_breakpoint<std::pair<Algebraic_real, Algebraic_real>>;
  void on_surface_case(Curve_patch_intersection_result& res) const;
  bool piece_covered(const Algebraic_real& a, const Algebraic_real& b) const;

  static void sort_points(Curve_patch_intersection_result& res) {
    std::sort(res.points.begin(), res.points.end(),
              [](const Curve_patch_intersection_point& a, const Curve_patch_intersection_point& b) {
                int c = a.r.compare(b.r);
                if (c == 0) c = a.u.compare(b.u);
                if (c == 0) c = a.v.compare(b.v);
                return c < 0;
              });
  }

  const Curve& curve_;
  const Patch& patch_;
  std::array<Z1, 4> H_;
  std::shared_ptr<Patch_implicit_matrix> matrix_;
  std::vector<std::vector<Z1>> M_;
  bool have_minors_ = false;
  Q1 D11_, Du_, Dv_;
  Z1 R_;  // det M(C(r))
  bool have_eliminants_ = false;
  Z1 U_, V_;
  std::array<std::vector<Isolated_root>, 2> eliminant_roots_;
  std::array<Z1, 2> removed_lines_{Z1(1), Z1(1)};
  Time_budget budget_;
};

}  // namespace cs
}  // namespace internal
}  // namespace bezoutian

#include <bezoutian/intersection/internal/curve_patch_eliminants.h>
#include <bezoutian/intersection/internal/curve_patch_base_points.h>
#include <bezoutian/intersection/internal/curve_patch_on_surface.h>

namespace bezoutian {

/// \brief All intersections of the rational Bezier space curve C(r), r in [0,1], with the rational Bezier patch
/// Phi(u,v), (u,v) in [0,1]^2 (du-1989 Problem 2.2b): isolated points (r; u, v) as exact algebraic numbers, and the
/// pieces of the curve lying in the patch (overlaps).
///
/// Method: with M(w,x,y,z) the 2mn x 2mn implicit (Dixon / generalized Bezoutian) matrix of the patch, the roots of
/// R(r) = det M(C(r)) in [0,1] contain every intersection parameter; at each root the kernel of M gives (u,v)
/// exactly (rational roots: exact linear algebra; irrational roots: u = Du/D11, v = Dv/D11 from three cofactors).
/// Where the kernel does not give a unique preimage (the curve crosses a self-intersection curve of the patch, a
/// patch covering its image several times, or a singular point of the surface), the grid step reports every
/// preimage (u,v) in [0,1]^2: the candidates are the roots of the eliminants U(u), V(v), each excluded by interval
/// arithmetic or proved by a Krawczyk test in (r,u,v) (exact decision when r, u, v are rational).
/// Patches with base points (det M == 0, e.g. collapsed edges of rational sphere patches, or polynomial patches with
/// base points at infinity): every root of an eliminant built from U, V (see base_point_case) goes through the
/// grid step; a collapsed edge through which the curve passes is reported once, with collapsed_line set.
/// Requirements: no pole of the curve on [0,1] or of the patch on [0,1]^2 (Invalid_input), bi-degree >= (1,1)
/// (Invalid_input). Error (not supported) when such a preimage is a singular solution with two or three irrational
/// coordinates (the curve tangent to one sheet of a self-intersection, or through a singular point of the surface,
/// at irrational parameters), when the curve runs along a patch with base points (or a constant curve meets one),
/// or when no projection gives nonzero eliminants U, V. A constant curve gives the overlap [0,1] if its point is on
/// the patch, nothing otherwise.
///
/// Resource limits (Intersection_limits): the curve's degree and control points, the patch's degrees in u and in v
/// and its (m + 1)(n + 1) control points, the degree product 2 m n deg C (the degree of R(r)) and the coefficient bits
/// are checked before any computation, the time budget between the stages (implicit matrix, determinant, root
/// isolation, preimages); Limit_exceeded (Budget_exceeded) names the stage and the limit.
inline Curve_patch_intersection_result intersect_curve_patch(const Rational_bezier_curve<Rational, 3>& curve,
                                                              const Rational_bezier_patch<Rational>& patch,
                                                              const Intersection_limits& limits) {
  static const char* const function = "intersect_curve_patch";
  const internal::Time_budget budget(function, limits.time_limit);
  internal::check_curve_limits(function, "the curve", curve, limits);
  internal::check_size_limits(function, "the patch", {patch.degree_u(), patch.degree_v()},
                              long(patch.degree_u() + 1) * long(patch.degree_v() + 1), limits);
  if (limits.max_coefficient_bits > 0) {
    long bits = 0;
    for (const auto& row : patch.homogeneous_net())
      for (const auto& h : row)
        for (const Rational& x : h) bits = std::max(bits, internal::rational_bits(x));
    internal::check_coefficient_bits(function, "the patch", bits, limits);
  }
  internal::check_degree_product(function, 2L * patch.degree_u() * patch.degree_v() * curve.degree(),
                                 "2 m n deg C = 2 x " + std::to_string(patch.degree_u()) + " x " +
                                     std::to_string(patch.degree_v()) + " x " + std::to_string(curve.degree()),
                                 limits);
  internal::cs::Curve_patch_engine engine(curve, patch);
  engine.set_time_budget(budget);
  return engine.run();
}

/// \brief intersect_curve_patch with the default limits (Intersection_limits).
inline Curve_patch_intersection_result intersect_curve_patch(const Rational_bezier_curve<Rational, 3>& curve,
                                                              const Rational_bezier_patch<Rational>& patch) {
  return intersect_curve_patch(curve, patch, Intersection_limits());
}

/// \brief Intersections of the segment a + r (b - a), r in [0,1], with the patch (du-1989 Problem 2.2a): the
/// degree-1 case of intersect_curve_patch. a == b: the point case (overlap [0,1] if the point is on the patch).
inline Curve_patch_intersection_result intersect_segment_patch(const std::array<Rational, 3>& a,
                                                                const std::array<Rational, 3>& b,
                                                                const Rational_bezier_patch<Rational>& patch) {
  return intersect_curve_patch(Rational_bezier_curve<Rational, 3>(std::vector<std::array<Rational, 3>>{a, b}), patch);
}

/// Function object form (CGAL style).
struct Intersect_curve_patch {
  Intersection_limits limits;  ///< resource limits (defaults: Intersection_limits)
  Curve_patch_intersection_result operator()(const Rational_bezier_curve<Rational, 3>& curve,
                                             const Rational_bezier_patch<Rational>& patch) const {
    return intersect_curve_patch(curve, patch, limits);
  }
};

}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERSECTION_CURVE_SURFACE_INTERSECTION_H
