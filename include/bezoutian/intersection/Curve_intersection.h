// Certified intersection of two rational Bezier curves (plane or space) on [0,1] x [0,1] (du-1989 ch. 4).
#ifndef BEZOUTIAN_INTERSECTION_CURVE_INTERSECTION_H
#define BEZOUTIAN_INTERSECTION_CURVE_INTERSECTION_H

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

#include <CGAL/Polynomial.h>
#include <CGAL/Polynomial_traits_d.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#ifdef CI_DEBUG
#include <chrono>
#include <iostream>
#define CI_TICK_START auto ci_t0 = std::chrono::steady_clock::now()
#define CI_TICK(name)                                                                                          \
  do {                                                                                                         \
    auto ci_t1 = std::chrono::steady_clock::now();                                                             \
    std::cerr << name << " " << std::chrono::duration<double, std::milli>(ci_t1 - ci_t0).count() << " ms\n"; \
    ci_t0 = ci_t1;                                                                                             \
  } while (0)
#else
#define CI_TICK_START
#define CI_TICK(name)
#endif

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

namespace internal {

template <int D>
class Curve_intersection_engine;

/// The lazy parameters of the planar default path (intersect_curves, D == 2): the intersections proved by the
/// interval solver (planar_interval_solver.h), each a box [s_lo, s_hi] x [t_lo, t_hi] holding exactly one,
/// transversal, intersection; number 2k is s of box k, 2k + 1 its t. Exact on demand: the eliminants R(s), T(t)
/// (determinants of the implicit Bezout matrices, du-1989 eq. 4.1, as in the exact default path) are computed at
/// most once per curve pair and shared by all its points; boxes are contracted by Krawczyk's operator in MPFI.
template <int D>
class Planar_lazy_intersections : public Lazy_real_source {
 public:
  using P1 = Ci_poly1;
  Planar_lazy_intersections(const Rational_bezier_curve<Rational, D>& c1, const Rational_bezier_curve<Rational, D>& c2,
                            const std::array<P1, 3>& H1, const std::array<P1, 3>& H2)
      : H_{H1, H2} {
    a.curve = c1;
    b.curve = c2;
    set_planar_interval_data(a, H1);
    set_planar_interval_data(b, H2);
    for (const auto* H : {&H1, &H2})
      for (const P1& f : *H)
        for (int i = 0; i <= f.degree(); ++i) bits_ = std::max(bits_, long(f[i].bit_size()));
  }
  Planar_interval_curve a, b;              // the two curves with the interval solver's data
  std::vector<std::array<Rational, 4>> boxes;  // s_lo, s_hi, t_lo, t_hi (closed)

  const Lazy_eliminant& eliminant(int index) override {
    const int side = index % 2;
    if (!fallback_ && !E_[side]) {
      P1 R;
      try {
        R = Curve_intersection_engine<D>::planar_eliminant(H_[side], H_[1 - side]);
      } catch (const Error&) {
        R = P1(0);
      }
      if (CGAL::is_zero(R) || R.degree() < 1) {
        fallback_ = true;  // a common component: exact points instead
      } else {
        E_[side].reset(new Lazy_eliminant(R));
        // Rational roots are recognised cheaply through the simplest fractions in the contracted enclosures
        // (a root p/q with q <= 2^32 is the simplest fraction of an interval of width < 2^-64 holding it).
        std::vector<Rational> candidates;
        Rational w(1);
        mpz_mul_2exp(mpq_denref(w.mpq()), mpq_denref(w.mpq()), 72);
        for (std::size_t k = 0; k < boxes.size(); ++k) {
          Rational lo = boxes[k][2 * side], hi = boxes[k][2 * side + 1];
          if (!contract(int(2 * k) + side, lo, hi, w) || !(lo < hi)) continue;
          const Rational q = simplest_rational_between(lo, hi);
          if (mpz_sizeinbase(mpq_denref(q.mpq()), 2) <= 40) candidates.push_back(q);
        }
        E_[side]->add_rational_candidates(candidates);
      }
    }
    if (!fallback_) return *E_[side];
    // The curves lie on one algebraic curve (R = 0): the exact intersection in the box (subresultant path).
    auto it = per_index_.find(index);
    if (it != per_index_.end()) return *it->second;
    if (!exact_) {
      exact_.reset(new Curve_intersection_result(
          Curve_intersection_engine<D>(a.curve, b.curve, Curve_intersection_method::subresultant).run()));
    }
    const auto& box = boxes[index / 2];
    for (const auto& p : exact_->points)
      if (p.s.compare(box[0]) >= 0 && p.s.compare(box[1]) <= 0 && p.t.compare(box[2]) >= 0 && p.t.compare(box[3]) <= 0) {
        const Algebraic_real& x = side == 0 ? p.s : p.t;
        const P1 q = x.is_rational() ? P1(-Integer(mpq_numref(x.rational_value().mpq())),
                                          Integer(mpq_denref(x.rational_value().mpq())))
                                     : x.polynomial();
        return *(per_index_[index] = std::make_shared<Lazy_eliminant>(q));
      }
    throw Error("intersect_curves: no exact intersection in a Krawczyk box");
  }

  bool contract(int index, Rational& lo, Rational& hi, const Rational& w) override {
    std::array<Rational, 4>& box = boxes[index / 2];
    const int side = index % 2;
    box[2 * side] = std::max(box[2 * side], lo);
    box[2 * side + 1] = std::min(box[2 * side + 1], hi);
    // Krawczyk in MPFI: quadratic contraction down to the precision's resolution, then more precision
    const long wbits = long(mpz_sizeinbase(mpq_denref(w.mpq()), 2)) - long(mpz_sizeinbase(mpq_numref(w.mpq()), 2));
    mpfr_prec_t prec = mpfr_prec_t(std::max(128L, wbits + bits_ + 64));
    for (int round = 0; round < 12 && box[2 * side + 1] - box[2 * side] > w; ++round, prec *= 2) {
      if (prec > (mpfr_prec_t(1) << 20)) break;
      if (!planar_krawczyk_contract(H_[0], H_[1], box, prec, 64, CGAL::to_double(w) * 0.5)) break;
    }
    lo = box[2 * side];
    hi = box[2 * side + 1];
    return hi - lo <= w;
  }

 private:
  std::array<std::array<P1, 3>, 2> H_;
  long bits_ = 0;
  std::unique_ptr<Lazy_eliminant> E_[2];
  bool fallback_ = false;
  std::unique_ptr<Curve_intersection_result> exact_;
  std::map<int, std::shared_ptr<Lazy_eliminant>> per_index_;
};

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

  Curve_intersection_result run() {
    check_no_pole(c1_);
    check_no_pole(c2_);
    Curve_intersection_result res;
    const bool k1 = is_constant(H1_), k2 = is_constant(H2_);
    if (k1 || k2) {
      constant_case(k1, k2, res);
      return res;
    }
    if (method_ == Curve_intersection_method::default_method && planar_lazy_ && (lazy_path(res) || space_path(res))) {
      sort_points(res);
      return res;
    }
    res = Curve_intersection_result();
    if (disjoint_hulls()) return res;
    if (method_ == Curve_intersection_method::default_method && fast_path(res)) {
      sort_points(res);
      return res;
    }
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


  // ---------------------------------------------------------------- eliminants
  struct Elimination {
    P2 G1, G2;       // the pair whose subresultants give the inversion
    P1 R, S10, S11;  // Res_t(G1,G2) and the first subresultant S_1 = S11 t + S10 (w.r.t. t)
    bool ok = false;
    bool has_S1 = true;
  };

  // with_S1 = false: only the resultant (CGAL::resultant, cheaper than the subresultant sequence)
  static Elimination eliminate(const P2& G1, const P2& G2, bool with_S1 = true) {
    Elimination e;
    e.G1 = G1;
    e.G2 = G2;
    if (t_degree(G1) < 1 || t_degree(G2) < 1) return e;
    if (!with_S1) {
      e.R = CGAL::resultant(G1, G2);
      e.ok = !CGAL::is_zero(e.R);
      e.has_S1 = false;
      return e;
    }
    std::vector<P2> sres;
    typename CGAL::Polynomial_traits_d<P2>::Polynomial_subresultants()(G1, G2, std::back_inserter(sres));
    if (sres.empty() || CGAL::is_zero(sres[0])) return e;
    e.R = sres[0][0];
    const P2& S1 = sres.size() > 1 ? sres[1] : (t_degree(G1) <= t_degree(G2) ? G1 : G2);
    e.S10 = t_degree(S1) >= 0 ? P1(S1[0]) : P1(0);
    e.S11 = t_degree(S1) >= 1 ? P1(S1[1]) : P1(0);
    Integer c(0);  // remove the common content of S10 and S11 (only their ratio matters)
    for (const P1* q : {&e.S10, &e.S11})
      for (int i = 0; i <= q->degree(); ++i) c = CGAL::gcd(c, (*q)[i]);
    if (c > 1) {
      e.S10 = CGAL::integral_division(e.S10, P1(c));
      e.S11 = CGAL::integral_division(e.S11, P1(c));
    }
    e.ok = true;
    return e;
  }

  // Pairs of F to eliminate: F1,F2 first; in 3D combinations with F3 if F1,F2 share a component.
  static std::vector<std::pair<P2, P2>> candidate_pairs(const std::vector<P2>& F) {
    std::vector<std::pair<P2, P2>> c;
    c.push_back({F[0], F[1]});
    c.push_back({F[0] + F[1], F[0] + F[1] * P2(2)});
    if (F.size() == 3) {
      c.push_back({F[0], F[2]});
      c.push_back({F[1], F[2]});
      c.push_back({F[0] + F[2], F[1] - F[2] * P2(2)});
      c.push_back({F[0] * P2(3) + F[1] + F[2], F[1] + F[2] * P2(5) - F[0]});
    }
    return c;
  }

  // Substitute the homogeneous form H (an affine polynomial f(x,y) of total degree n) : f(X/W, Y/W) W^n.
  static P1 substitute_affine(const P2& f, const P1& X, const P1& Y, const P1& W) {
    int n = 0;
    for (int j = 0; j <= f.degree(); ++j)
      if (!CGAL::is_zero(f[j])) n = std::max(n, j + f[j].degree());
    P1 r(0);
    for (int j = 0; j <= f.degree(); ++j)
      for (int i = 0; i <= f[j].degree(); ++i)
        if (!CGAL::is_zero(f[j][i])) r += P1(f[j][i]) * CGAL::ipower(X, i) * CGAL::ipower(Y, j) * CGAL::ipower(W, n - i - j);
    return r;
  }

  // R(s) from the strategy (default: the resultant already computed).
  P1 strategy_R(const Elimination& e, const Form& A, const Form& B) const {
    if (plain_method()) return e.R;
    if (method_ == Curve_intersection_method::groebner) {
      // Multi-modular lex basis certified over Q (Groebner_bivariate.h). Space curves: the whole system
      // <F1, F2, F3> when its dimension count is sharp (no exact fallback: budget 0); otherwise, and in the plane,
      // the pair's ideal (in space the gcd with the other pairs' resultants follows in solve_system).
      if constexpr (D == 3) {
        std::vector<P2> F;
        for (int k = 1; k <= D; ++k) F.push_back(cross_term(A[k], B[0], B[k], A[0]));
        try {
          for (const auto& b : modular_lex_groebner_basis(F, nullptr, 0))
            if (b.is_univariate_in_s()) return internal::integer_multiple(b.to_univariate());
        } catch (const Error&) {
        }
      }
      const Polynomial_1<Rational> g = groebner_eliminant(std::vector<P2>{e.G1, e.G2});
      if (!CGAL::is_zero(g)) return internal::integer_multiple(g);
      return e.R;
    }
    if (method_ == Curve_intersection_method::resolvent && D == 3 && B[0].degree() <= 3 && max_degree(B) <= 3 &&
        max_degree(B) == 3) {
      const auto r = goldman_rational_cubic_resolvent(B[1], B[2], B[D == 3 ? 3 : 1], B[0]);
      P1 g(0);
      for (const auto* q : {&r.R1, &r.R2, &r.R3}) {
        P1 v = substitute_quadric(*q, A);
        g = CGAL::is_zero(g) ? v : (CGAL::is_zero(v) ? g : P1(CGAL::gcd(g, v)));
      }
      if (!CGAL::is_zero(g)) return g;
      return e.R;
    }
    if (D == 2) {
      const P2 f = bezout_implicit_equation(B[1], B[2], B[0]);
      const P1 r = substitute_affine(f, A[1], A[2], A[0]);
      if (!CGAL::is_zero(r)) return r;
    }
    return e.R;
  }

  static int max_degree(const Form& H) {
    int n = 0;
    for (const auto& h : H) n = std::max(n, h.degree());
    return n;
  }

  template <class Q3>
  static P1 substitute_quadric(const Q3& q, const Form& A) {
    // q is a polynomial in (x,y,z) of total degree <= 2: sum c x^a y^b z^c W^(2-a-b-c)
    P1 r(0);
    const P1* v[3] = {&A[1], &A[2], &A[D == 3 ? 3 : 1]};
    for (int c = 0; c <= q.degree(); ++c)
      for (int b = 0; b <= q[c].degree(); ++b)
        for (int a = 0; a <= q[c][b].degree(); ++a) {
          const Integer co = q[c][b][a];
          if (CGAL::is_zero(co)) continue;
          r += P1(co) * CGAL::ipower(*v[0], a) * CGAL::ipower(*v[1], b) * CGAL::ipower(*v[2], c) *
               CGAL::ipower(A[0], 2 - a - b - c);
        }
    return r;
  }

  bool plain_method() const {
    return method_ == Curve_intersection_method::default_method || method_ == Curve_intersection_method::subresultant;
  }

  // ---------------------------------------------------------------- planar lazy path (default method)
  // Plane curves with positive weights: the certified interval solver (planar_interval_solver.h) first. If it
  // settles everything (every crossing a Krawczyk box strictly inside (0,1)^2, every other cell excluded, no common
  // end point, no tangency / overlap / undecided cell), the points are returned with lazy parameters s, t
  // (Algebraic_real, exact on demand through Planar_lazy_intersections); Krawczyk's proof includes a regular
  // Jacobian, i.e. a transversal crossing of multiplicity 1. Otherwise false: the exact paths below decide.
  bool lazy_path(Curve_intersection_result& res) const {
    if constexpr (D != 2) {
      (void)res;
      return false;
    } else {
      if (!positive_weights(c1_) || !positive_weights(c2_)) return false;
      CI_TICK_START;
      auto data = std::make_shared<Planar_lazy_intersections<D>>(c1_, c2_, H1_, H2_);
      Planar_interval_solver solver{data->a, data->b, {}};
      solver.budget = 20000;  // cells; more than the arrangement's (a failure costs the exact path anyway)
      solver.max_depth = 34;  // power-basis enclosures of large coefficients can need cells below 2^-24
      solver.mpfi_depth = 28;    // cells the doubles leave undecided that deep get the MPFI test
      solver.mpfi_merge = true;  // boxes of one zero a few ulps wide: merged in MPFI
      solver.mpfi_precision = mpfr_prec_t(192 + 2 * coefficient_bits_);
      solver.run(data->a.inet, 0, 1, data->b.inet, 0, 1, 0);
      CI_TICK("lazy interval solver");
      if (solver.failed || !solver.contacts.empty()) return false;
      for (const auto& f : solver.found) {
        const int k = int(data->boxes.size());
        data->boxes.push_back({Rational(f[0]), Rational(f[1]), Rational(f[2]), Rational(f[3])});
        const auto& box = data->boxes.back();
        Curve_intersection_point p;
        p.s = Algebraic_real_access::lazy(data, 2 * k, box[0], box[1]);
        p.t = Algebraic_real_access::lazy(data, 2 * k + 1, box[2], box[3]);
        res.points.push_back(p);
      }
      return true;
    }
  }

  // ---------------------------------------------------------------- space path (default method, D == 3)
 public:
  // Space curves with positive weights. Intervals first (space_interval_solver.h): boxes covering every common
  // point in [0,1]^2, each holding exactly one zero of a square subsystem (G_a, G_b) (Krawczyk), boxes where the
  // third equation is proved nonzero dropped; none left = no intersection. Otherwise the exact step, small: the shape
  // basis {g(s) = 0, t = psi(s)} of F_1 = F_2 = F_3 = 0 (space_shape_basis.h: modular, verified exactly over Q), so
  // that every root of g gives a proved common point (sigma, psi(sigma)). Every box must contain one of them
  // (isolating interval of sigma and an enclosure of psi(sigma) inside the box): a box holds at most one zero of
  // its subsystem, which is then that common point, so nothing is missed. Krawczyk's proof includes a regular
  // Jacobian of the subsystem, i.e. non-parallel tangents: transversal, multiplicity 1. Anything else (tangency,
  // overlap, common points with equal s, an unmatched box) returns false: the exact paths below decide.
  // (Public for benchmarks: true = the pair was settled here, `res` holds the answer.)
  bool space_path(Curve_intersection_result& res) const {
    if constexpr (D != 3) {
      (void)res;
      return false;
    } else {
      if (!positive_weights(c1_) || !positive_weights(c2_)) return false;
      CI_TICK_START;
      const Space_interval_curve ia = space_interval_curve(c1_, H1_), ib = space_interval_curve(c2_, H2_);
      Space_interval_solver solver{ia, ib, {}};
      solver.run(ia.inet, 0, 1, ib.inet, 0, 1, 0);
      CI_TICK("space interval solver");
#ifdef CI_DEBUG
      std::cerr << "  cells " << solver.cells << " krawczyk " << solver.krawczyk_tests << " boxes " << solver.found.size()
                << (solver.failed ? " FAILED" : "") << "\n";
#endif
      if (solver.failed) return false;
      if (solver.found.empty()) return true;  // proved: no common point
      Space_shape_basis sb;
      if (!space_shape_basis(H1_, H2_, sb)) return false;
      CI_TICK("space shape basis");
      const std::size_t d = sb.g.size() - 1;
      if (d == 0) return false;  // boxes left but no common zero: undecided here
      Rational lo(0), hi(1);
      for (const auto& b : solver.found) {
        lo = std::min(lo, Rational(b.s_lo));
        hi = std::max(hi, Rational(b.s_hi));
      }
      const Polynomial_1<Rational> g(sb.g.begin(), sb.g.end());
      const Polynomial_1<Rational> psi = sb.psi.empty() ? Polynomial_1<Rational>(0)
                                                         : Polynomial_1<Rational>(sb.psi.begin(), sb.psi.end());
      const std::vector<Isolated_root> roots = isolate_real_roots(g, lo, hi);
      CI_TICK("space isolate");
      auto eval = [](const Polynomial_1<Rational>& f, const Rational& x) {
        Rational r(0);
        for (int i = f.degree(); i >= 0; --i) r = r * x + f[i];
        return r;
      };
      // psi = N / q with an integer polynomial N and a positive rational q
      const P1 N = CGAL::is_zero(psi) ? P1(0) : internal::integer_multiple(psi);
      Rational q(1);
      for (int i = 0; i <= psi.degree(); ++i)
        if (!CGAL::is_zero(psi[i])) q = Rational(N[i]) / psi[i];
      const P1 G = internal::integer_multiple(g);
      P1 P;  // vanishes at psi(sigma) for every root sigma of g (computed once, if an irrational sigma needs it)
      std::vector<Rational> s_enc_lo, s_enc_hi, t_enc_lo, t_enc_hi;  // enclosures of (sigma, psi(sigma))
      std::vector<Algebraic_real> ts;
      std::vector<char> matched(solver.found.size(), 0);
      for (const Isolated_root& r : roots) {
        const Algebraic_real& x = r.root;
        if (x.is_rational()) {
          const Rational t = eval(psi, x.rational_value());
          s_enc_lo.push_back(x.rational_value());
          s_enc_hi.push_back(x.rational_value());
          t_enc_lo.push_back(t);
          t_enc_hi.push_back(t);
          ts.push_back(Algebraic_real(t));
          continue;
        }
        // irrational sigma: t = psi(sigma) is a root of P(t) = Res_s(g(s), q t - N(s)); its isolating interval
        // from an MPFI enclosure of psi on sigma's refined interval
        if (CGAL::is_zero(P) && !CGAL::is_zero(psi)) P = partner_polynomial(G, N, q);
        bool ok = false;
        for (int bits = 64; bits <= 1024 && !ok; bits *= 2) {
          Integer p2(1);
          mpz_mul_2exp(p2.mpz(), p2.mpz(), (unsigned long)bits);
          x.refine_to_width(Rational(1) / Rational(p2));
          const mpfr_prec_t prec = mpfr_prec_t(2 * bits + 64 + coefficient_bits_);
          using I = internal::Mpfi_interval;
          const I u = I::hull(x.lower(), x.upper(), prec);
          const I v = I::horner(N, u) / I::hull(q, q, prec);
          const Rational vlo = v.lower(), vhi = v.upper();
          try {
            Algebraic_real t = CGAL::is_zero(psi) ? Algebraic_real(0) : Algebraic_real(P, vlo, vhi);
            s_enc_lo.push_back(x.lower());
            s_enc_hi.push_back(x.upper());
            t_enc_lo.push_back(vlo);
            t_enc_hi.push_back(vhi);
            ts.push_back(t);
            ok = true;
          } catch (const Invalid_input&) {
          }
        }
        if (!ok) return false;
      }
      CI_TICK("space partners");
      // every box must hold a root (sigma, psi(sigma)): enclosures inside the box, or exact comparisons with its ends
      for (std::size_t k = 0; k < solver.found.size(); ++k) {
        const auto& b = solver.found[k];
        const Rational bs0(b.s_lo), bs1(b.s_hi), bt0(b.t_lo), bt1(b.t_hi);
        for (std::size_t i = 0; i < roots.size() && !matched[k]; ++i) {
          if (s_enc_hi[i] < bs0 || s_enc_lo[i] > bs1 || t_enc_hi[i] < bt0 || t_enc_lo[i] > bt1) continue;
          if (bs0 <= s_enc_lo[i] && s_enc_hi[i] <= bs1 && bt0 <= t_enc_lo[i] && t_enc_hi[i] <= bt1) {
            matched[k] = 1;
            break;
          }
          // overlapping but not inside: compare the exact numbers with the box ends
          const Algebraic_real& x = roots[i].root;
          if (x.compare(bs0) >= 0 && x.compare(bs1) <= 0 && ts[i].compare(bt0) >= 0 && ts[i].compare(bt1) <= 0)
            matched[k] = 1;
        }
        if (!matched[k]) return false;
      }
      for (std::size_t i = 0; i < roots.size(); ++i) {
        const Algebraic_real &s = roots[i].root, &t = ts[i];
        if (s.compare(Rational(0)) < 0 || s.compare(Rational(1)) > 0) continue;
        if (t.compare(Rational(0)) < 0 || t.compare(Rational(1)) > 0) continue;
        // a common point of the arcs lies in some box (the boxes cover all of them): check, for safety
        bool in_box = false;
        for (const auto& b : solver.found)
          in_box = in_box || (s.compare(Rational(b.s_lo)) >= 0 && s.compare(Rational(b.s_hi)) <= 0 &&
                              t.compare(Rational(b.t_lo)) >= 0 && t.compare(Rational(b.t_hi)) <= 0);
        if (!in_box) return false;
        Curve_intersection_point p;
        p.s = s;
        p.t = t;
        auto end = [](const Algebraic_real& x) { return x.is_rational() && (x == 0 || x == 1); };
        p.kind = (end(s) || end(t)) ? Curve_intersection_kind::endpoint : Curve_intersection_kind::transversal;
        res.points.push_back(p);
      }
      CI_TICK("space match");
      return true;
    }
  }

 private:
  // P(t) = Res_s(g(s), b N(s) - a t) for psi = N / q, q = a / b: vanishes at psi(sigma) for every root sigma of g.
  static P1 partner_polynomial(const P1& G, const P1& N, const Rational& q) {
    std::vector<P1> gc, hc;
    for (int i = 0; i <= G.degree(); ++i) gc.push_back(P1(G[i]));
    for (int i = 0; i <= N.degree(); ++i) hc.push_back(P1(q.denominator() * N[i]));
    if (hc.empty()) hc.push_back(P1(0));
    hc[0] -= P1(Integer(0), q.numerator());
    return CGAL::resultant(P2(gc.begin(), gc.end()), P2(hc.begin(), hc.end()));
  }

  // ---------------------------------------------------------------- fast certified path (default method)
  // du-1989 eq. 4.1 kept as a matrix. For a plane curve B = (X, Y, W)(t) of degree n >= 2 the Bezout matrix
  // Bez(x, y) = Bez_t(X - x W, Y - y W) (n x n, entries affine in x, y) satisfies Bez(x,y) v(t) = 0 whenever
  // B(t) = (x, y), v(t) = (1, t, .., t^(n-1)) (symmetric Cayley form). Evaluated on curve A, the entries of
  // M(s) = W_A(s) Bez(X_A/W_A, Y_A/W_A) are integer polynomials of degree deg A, and R(s) = det M(s) vanishes at every
  // s whose point lies on the algebraic curve of B: the parameters s of all intersections are roots of R in [0,1].
  // Where rank M(s_i) = n - 1 (certified by a nonzero cofactor M_00(s_i)) the kernel is spanned by v(t*) for the
  // unique common parameter t* (finite because M_00 != 0), and the adjugate's first column gives
  // t* = -M_01(s_i)/M_00(s_i) (du-1989 eq. 4.3, Cramer's rule). t* is located exactly among the roots in [0,1] of
  // T(t) (the same construction with the roles exchanged) by the sign decisions of pair_roots. In space the curves
  // are projected on a coordinate plane first and the remaining coordinate is checked exactly at (s_i, t*).
  // Returns false (and the caller runs the subresultant path) when a cofactor vanishes at a root (several partners,
  // a node of the projected curve), when R or T vanish identically (a common component), or for two lines.
  using Matrix1 = std::vector<std::vector<P1>>;

  // Form of the plane projection (W, a.X, b.X) of a curve (a, b: integer rows of length D).
  static std::array<P1, 3> projected(const Form& H, const std::array<int, 3>& a, const std::array<int, 3>& b) {
    std::array<P1, 3> r{H[0], P1(0), P1(0)};
    for (int k = 0; k < D; ++k) {
      if (a[k] != 0) r[1] += H[k + 1] * P1(a[k]);
      if (b[k] != 0) r[2] += H[k + 1] * P1(b[k]);
    }
    return r;
  }

  static int degree3(const std::array<P1, 3>& f) {
    int n = 0;
    for (const P1& q : f)
      if (!CGAL::is_zero(q)) n = std::max(n, q.degree());
    return n;
  }

  static Integer coefficient_xy(const P2& f, int i, int j) {  // coefficient of x^i y^j
    if (CGAL::is_zero(f) || j > f.degree()) return Integer(0);
    const P1& g = f[j];
    return (CGAL::is_zero(g) || i > g.degree()) ? Integer(0) : g[i];
  }

  // M(s) = W_A(s) Bez_B(X_A/W_A, Y_A/W_A).
  static Matrix1 implicit_matrix_on(const std::array<P1, 3>& B, const std::array<P1, 3>& A) {
    const auto C = rational_curve_bezout_matrix(B[1], B[2], B[0]);
    Matrix1 M(C.size(), std::vector<P1>(C.size()));
    for (std::size_t p = 0; p < C.size(); ++p)
      for (std::size_t q = 0; q < C.size(); ++q)
        M[p][q] = A[0] * P1(coefficient_xy(C[p][q], 0, 0)) + A[1] * P1(coefficient_xy(C[p][q], 1, 0)) +
                  A[2] * P1(coefficient_xy(C[p][q], 0, 1));
    return M;
  }

  static P1 cofactor_minor(const Matrix1& M, std::size_t row, std::size_t col) {
    Matrix1 m;
    for (std::size_t p = 0; p < M.size(); ++p) {
      if (p == row) continue;
      std::vector<P1> r;
      for (std::size_t q = 0; q < M.size(); ++q)
        if (q != col) r.push_back(M[p][q]);
      m.push_back(r);
    }
    return polynomial_matrix_determinant(m);
  }

  enum class Fast { done, undecided };
  struct Undecided_tangency {};

  // One projection; `res` receives the certified points when `done`.
  Fast fast_projection(const std::array<int, 3>& a, const std::array<int, 3>& b, Curve_intersection_result& res) const {
    const auto A = projected(H1_, a, b), B = projected(H2_, a, b);
    const int nA = degree3(A), nB = degree3(B);
    if (std::max(nA, nB) < 2) return Fast::undecided;
    if (nA < 1 || nB < 1) return Fast::undecided;  // a projection collapsed to a point
    CI_TICK_START;
    const Matrix1 Ms = implicit_matrix_on(B, A);
    P1 R = polynomial_matrix_determinant(Ms);
    if (CGAL::is_zero(R)) return Fast::undecided;
    R = divide_out(R, H1_[0]);  // roots outside [0,1] only (no pole in [0,1]): smaller polynomials to isolate
    const std::vector<Isolated_root> rs = roots01(primitive(R));
    CI_TICK("fast R");
    if (rs.empty()) return Fast::done;  // no s in [0,1] on the (projected) curve 2: proved empty
    const Matrix1 Mt = implicit_matrix_on(A, B);
    P1 T = polynomial_matrix_determinant(Mt);
    if (CGAL::is_zero(T)) return Fast::undecided;
    T = divide_out(T, H2_[0]);
    const std::vector<Isolated_root> rt = roots01(primitive(T));
    CI_TICK("fast T");
    if (rt.empty()) return Fast::done;

    // Every intersection (s*, t*) in [0,1]^2 has s* among rs and t* among rt. Pairs are decided in three ways:
    // (1) a rational parameter: its point is rational, its partners on the other curve follow by exact inversion;
    // (2) irrational s_i, t_j: disjoint point enclosures exclude the pair, the Krawczyk test proves it (the box
    //     I(s_i) x I(t_j) holds exactly one common point of the projections, which is then (s_i, t_j), since the
    //     isolating intervals hold no other root of R and T; in space the remaining coordinate is then checked);
    // (3) otherwise the cofactor inversion t* = -M_01(s_i)/M_00(s_i) decides exactly.
    std::vector<std::pair<int, int>> pairs;  // (index in rs, index in rt)
    std::vector<char> exact_pair;            // pair decided with rational parameters (exact tangency test)
    std::vector<char> s_done(rs.size(), 0);
    auto add_pair = [&](int i, int j, bool exact) {
      for (const auto& q : pairs)
        if (q.first == i && q.second == j) return;
      pairs.push_back({i, j});
      exact_pair.push_back(exact);
    };
    auto index_of = [](const std::vector<Isolated_root>& r, const Algebraic_real& x) {
      for (std::size_t k = 0; k < r.size(); ++k)
        if (r[k].root == x) return int(k);
      throw Error("intersect_curves: internal inconsistency (an exact partner is not a root of the eliminant)");
    };
    for (std::size_t i = 0; i < rs.size(); ++i) {
      if (!rs[i].root.is_rational()) continue;
      std::vector<Algebraic_real> ts;
      invert_point<D>(H2_, point_at<D>(H1_, rs[i].root.rational_value()), ts);
      for (const auto& t : ts) add_pair(int(i), index_of(rt, t), true);
      s_done[i] = 1;
    }
    for (std::size_t j = 0; j < rt.size(); ++j) {
      if (!rt[j].root.is_rational()) continue;
      std::vector<Algebraic_real> ss;
      invert_point<D>(H1_, point_at<D>(H2_, rt[j].root.rational_value()), ss);
      for (const auto& x : ss) add_pair(index_of(rs, x), int(j), true);
    }
    CI_TICK("fast exact pairs");
    // the coordinate that the projection plane does not see (a x b has a nonzero entry there)
    int hidden = -1;
    if (D == 3) {
      const int cr[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
      for (int k = 2; k >= 0; --k)
        if (cr[k] != 0) hidden = k;
    }
    std::vector<std::size_t> cofactor_roots;
    for (std::size_t i = 0; i < rs.size(); ++i) {
      if (s_done[i]) continue;
      std::vector<int> live;
      for (std::size_t j = 0; j < rt.size(); ++j)
        if (!rt[j].root.is_rational()) live.push_back(int(j));
      bool decided = false;
      for (int bits = 24; bits <= 96 && !decided; bits *= 2) {
        Integer p2(1);
        mpz_mul_2exp(p2.mpz(), p2.mpz(), (unsigned long)bits);
        const Rational w = Rational(1) / Rational(p2);
        const mpfr_prec_t prec = mpfr_prec_t(64 + 2 * bits + coefficient_bits_);
        rs[i].root.refine_to_width(w);
        if (rs[i].root.is_rational()) break;  // cannot happen (rationality is decided at isolation)
        const auto Ps = point_enclosure(H1_, rs[i].root, prec);
        std::vector<int> next;
        bool undecided = false;
        for (int j : live) {
          rt[j].root.refine_to_width(w);
          const auto Pt = point_enclosure(H2_, rt[j].root, prec);
          bool apart = false;
          for (int k = 0; k < D; ++k) apart = apart || disjoint(Ps[k], Pt[k]);
          if (apart) continue;
          if (krawczyk_unique_intersection(A, B, rs[i].root.lower(), rs[i].root.upper(), rt[j].root.lower(),
                                           rt[j].root.upper(), prec)) {
            if (hidden >= 0) {  // space: the projections meet at (s_i, t_j); the hidden coordinate must agree too
              if (disjoint(Ps[hidden], Pt[hidden])) continue;
              undecided = true;  // exact decision needed
              next.push_back(j);
              continue;
            }
            add_pair(int(i), j, false);
            continue;
          }
          undecided = true;
          next.push_back(j);
        }
        live = next;
        decided = !undecided;
      }
      if (!decided) cofactor_roots.push_back(i);
    }
    CI_TICK("fast interval pairs");
    if (!cofactor_roots.empty()) {
      if (nB < 2) return Fast::undecided;
      Elimination e;
      e.ok = true;
      e.S11 = cofactor_minor(Ms, 0, 0);
      e.S10 = cofactor_minor(Ms, 0, 1);
      if (CGAL::is_zero(e.S11)) return Fast::undecided;
      const Polynomial_1<Rational> S10q = to_rational(e.S10), S11q = to_rational(e.S11);
      for (std::size_t i : cofactor_roots) {
        const Algebraic_real& x = rs[i].root;
        const int s11 = root_sign(x, e.S11);
        if (s11 == 0) return Fast::undecided;
        // partner y* = -S10(x)/S11(x); sign(y* - c) = -sign(S10 + c S11) sign(S11)
        auto cmp = [&](const Rational& c) { return -root_sign(x, S10q + S11q * Polynomial_1<Rational>(c)) * s11; };
        if (cmp(Rational(0)) < 0 || cmp(Rational(1)) > 0) continue;  // partner outside [0,1]
        int found = -1;
        for (std::size_t j = 0; j < rt.size() && found < 0; ++j) {
          const Algebraic_real& y = rt[j].root;
          if (y.is_rational() ? cmp(y.rational_value()) == 0 : (cmp(y.lower()) > 0 && cmp(y.upper()) < 0))
            found = int(j);
        }
        if (found < 0)  // the partner is a root of T in [0,1]: missing it is a contradiction
          throw Error("intersect_curves: internal inconsistency (a cofactor partner is not a root of the eliminant)");
        if (D == 3 && !space_coordinates_agree(x, e, true, hidden)) continue;
        res.points.push_back(make_point(rs[i], rt[found], e, e, true));
      }
    }
    CI_TICK("fast cofactor pairs");
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const auto& p = pairs[k];
      if (exact_pair[k]) {
        try {
          res.points.push_back(exact_point(rs[p.first], rt[p.second]));
        } catch (const Undecided_tangency&) {
          return Fast::undecided;
        }
      } else {
        Curve_intersection_point q;  // Krawczyk: a regular zero, i.e. a transversal crossing
        q.s = rs[p.first].root;
        q.t = rt[p.second].root;
        res.points.push_back(q);
      }
    }
    return Fast::done;
  }

  std::array<internal::Mpfi_interval, D> point_enclosure(const Form& H, const Algebraic_real& x,
                                                         mpfr_prec_t prec) const {
    using I = internal::Mpfi_interval;
    const I u = x.is_rational() ? I::hull(x.rational_value(), x.rational_value(), prec) : I::hull(x.lower(), x.upper(), prec);
    const I w = I::horner(H[0], u);
    std::array<I, D> r = make_array_of_intervals(prec);
    for (int k = 0; k < D; ++k) r[k] = I::horner(H[k + 1], u) / w;
    return r;
  }
  static std::array<internal::Mpfi_interval, D> make_array_of_intervals(mpfr_prec_t prec) {
    using I = internal::Mpfi_interval;
    if constexpr (D == 2) return {I(prec), I(prec)};
    else return {I(prec), I(prec), I(prec)};
  }

  // Rational parameters: the multiplicity from the eliminants, tangency by exact evaluation of the tangents.
  Curve_intersection_point exact_point(const Isolated_root& s, const Isolated_root& t) const {
    Curve_intersection_point p;
    p.s = s.root;
    p.t = t.root;
    const int m = std::min(s.multiplicity, t.multiplicity);
    if (!s.root.is_rational() || !t.root.is_rational()) {  // one rational parameter: a rational point
      p.tangent = m >= 2 && !tangents_apart(s.root, t.root);
      if (p.tangent) throw Undecided_tangency();  // the caller falls back to the subresultant path
      p.multiplicity = 1;
      const bool end = s.root == 0 || s.root == 1 || t.root == 0 || t.root == 1;
      p.kind = end ? Curve_intersection_kind::endpoint : Curve_intersection_kind::transversal;
      return p;
    }
    const Rational a = s.root.rational_value(), b = t.root.rational_value();
    auto ev = [](const P1& f, const Rational& x) {
      Rational r(0);
      for (int i = f.degree(); i >= 0; --i) r = r * x + Rational(f[i]);
      return r;
    };
    std::array<Rational, D> da, db;  // tangent directions X_k' W - X_k W'
    for (int k = 0; k < D; ++k) {
      da[k] = ev(CGAL::differentiate(H1_[k + 1]), a) * ev(H1_[0], a) - ev(H1_[k + 1], a) * ev(CGAL::differentiate(H1_[0]), a);
      db[k] = ev(CGAL::differentiate(H2_[k + 1]), b) * ev(H2_[0], b) - ev(H2_[k + 1], b) * ev(CGAL::differentiate(H2_[0]), b);
    }
    bool parallel = true;
    for (int i = 0; i < D; ++i)
      for (int j = i + 1; j < D; ++j) parallel = parallel && da[i] * db[j] - da[j] * db[i] == 0;
    p.tangent = m >= 2 && parallel;
    p.multiplicity = p.tangent ? m : 1;
    // m counts every branch of one curve through the point against the other curve's branch, so it is the
    // multiplicity of this pair of branches only if one curve passes once; m = 2 is exact for a tangency anyway.
    if (p.tangent && m >= 3) {
      std::vector<P2> F;
      for (int k = 1; k <= D; ++k) F.push_back(cross_term(H1_[k], H2_[0], H2_[k], H1_[0]));
      p.multiplicity = local_multiplicity(F, a, b);
    }
    const bool end = a == 0 || a == 1 || b == 0 || b == 1;
    p.kind = end ? Curve_intersection_kind::endpoint
                 : (p.tangent ? Curve_intersection_kind::tangent : Curve_intersection_kind::transversal);
    return p;
  }

  // In space: at (x, y* = -S10(x)/S11(x)) the projections agree; the point agrees iff the hidden coordinate does:
  // X1_k(s) W2(t) - X2_k(t) W1(s) = 0 (k = hidden), over the common denominator S11(x)^deg, decided exactly.
  bool space_coordinates_agree(const Algebraic_real& x, const Elimination& e, bool from_s, int hidden) const {
    const Form& A = from_s ? H1_ : H2_;  // the curve of x
    const Form& B = from_s ? H2_ : H1_;
    const P1 N = -e.S10;
    const int k = hidden + 1;
    const P2 F = lift_outer(B[0]) * P2(A[k]) - lift_outer(B[k]) * P2(A[0]);
    return root_sign(x, substitute(F, N, e.S11)) == 0;
  }

  bool fast_path(Curve_intersection_result& res) const {
    if (D == 2) return fast_projection({1, 0, 0}, {0, 1, 0}, res) == Fast::done;
    // Space: coordinate planes, then a generic plane (the pairing needs a projection without a node at the points).
    const std::array<std::array<std::array<int, 3>, 2>, 4> planes{{{{{1, 0, 0}, {0, 1, 0}}},
                                                                    {{{1, 0, 0}, {0, 0, 1}}},
                                                                    {{{0, 1, 0}, {0, 0, 1}}},
                                                                    {{{1, 0, 2}, {0, 1, -3}}}}};
    for (const auto& pl : planes) {
      res = Curve_intersection_result();
      if (fast_projection(pl[0], pl[1], res) == Fast::done) return true;
    }
    return false;
  }

  // ---------------------------------------------------------------- pairing
  enum { none = -1, unresolved = -2 };

  // For each root a_i of the first variable (outer variable of G is the second one): the index of its unique
  // partner among roots_b, none, or unresolved (gcd of G1(a_i,.), G2(a_i,.) not of degree 1 / leading terms vanish).
  static std::vector<int> pair_roots(const Elimination& e, const std::vector<Isolated_root>& ra,
                                     const std::vector<Isolated_root>& rb) {
    std::vector<int> out(ra.size(), none);
    const int d1 = t_degree(e.G1), d2 = t_degree(e.G2);
    const P1 l1 = e.G1[d1], l2 = e.G2[d2];
    const Polynomial_1<Rational> S10 = to_rational(e.S10), S11 = to_rational(e.S11);
    for (std::size_t i = 0; i < ra.size(); ++i) {
      const Algebraic_real& a = ra[i].root;
      // subresultants specialize at a when the leading coefficient of the higher-degree polynomial survives
      const bool lc_ok = d1 == d2 ? (root_sign(a, l1) != 0 || root_sign(a, l2) != 0)
                                  : root_sign(a, d1 > d2 ? l1 : l2) != 0;
      const int s11 = lc_ok ? root_sign(a, e.S11) : 0;
      if (s11 == 0) {
        out[i] = unresolved;
        continue;
      }
      // b* = -S10(a)/S11(a) is a root of Res_a(G1,G2); sign(b* - c) = -sign(S10 + c S11) * sign(S11)
      auto cmp = [&](const Rational& c) { return -root_sign(a, S10 + S11 * Polynomial_1<Rational>(c)) * s11; };
      int found = none;
      for (std::size_t j = 0; j < rb.size() && found == none; ++j) {
        const Algebraic_real& b = rb[j].root;
        if (b.is_rational()) {
          if (cmp(b.rational_value()) == 0) found = int(j);
        } else if (cmp(b.lower()) > 0 && cmp(b.upper()) < 0) {
          found = int(j);
        }
      }
      out[i] = found;
    }
    return out;
  }

  static Polynomial_1<Rational> to_rational(const P1& f) {
    std::vector<Rational> c;
    for (int i = 0; i <= f.degree(); ++i) c.push_back(Rational(f[i]));
    return Polynomial_1<Rational>(c.begin(), c.end());
  }

  // ---------------------------------------------------------------- the system F_k(s,t) = 0
  // Linearly independent combinations of the F_k tried in turn (the first ones are the F_k themselves); a pair of
  // them with a vanishing resultant shares a component, which a combination avoids unless all F_k share it.
  static std::vector<std::vector<P2>> candidate_systems(const std::vector<P2>& F) {
    std::vector<std::vector<P2>> c;
    if (F.size() == 2) {
      c.push_back({F[0], F[1]});
      c.push_back({F[0] + F[1], F[0] + F[1] * P2(2)});
      c.push_back({F[0] * P2(3) - F[1], F[0] + F[1] * P2(5)});
    } else {
      c.push_back({F[0], F[1], F[2]});
      c.push_back({F[1], F[2], F[0]});
      c.push_back({F[2], F[0], F[1]});
      c.push_back({F[0] + F[1] + F[2], F[0] - F[1] + F[2] * P2(2), F[0] + F[1] * P2(3) - F[2]});
      c.push_back({F[0] * P2(2) + F[1] - F[2], F[0] + F[1] * P2(5) + F[2] * P2(3), F[0] - F[1] * P2(4) + F[2]});
    }
    return c;
  }

  // Pairing of the roots `ra` of the first variable with the roots of the second one (main list `rb`): a root a_i
  // is paired through every elimination pair (G1, G_m), m = 2 (.. 3 in space); the partner b* = -S10/S11 (a_i) is
  // located among the roots `loc[m]` of Res_a(G1, G_m) (of which it is a root) and all located roots must be equal
  // (then all G vanish at (a_i, b*)). The result is an index into rb, none or unresolved.
  static std::vector<int> pair_all(const std::vector<Elimination>& e, const std::vector<std::vector<Isolated_root>>& loc,
                                   const std::vector<Isolated_root>& ra, const std::vector<Isolated_root>& rb,
                                   bool rb_is_loc0) {
    std::vector<std::vector<int>> q;
    for (std::size_t m = 0; m < e.size(); ++m) q.push_back(pair_roots(e[m], ra, loc[m]));
    std::vector<int> out(ra.size(), none);
    for (std::size_t i = 0; i < ra.size(); ++i) {
      // "none" from one resolved pair proves that no partner exists in [0,1]
      bool unres = false, nothing = false;
      for (const auto& v : q) unres = unres || v[i] == unresolved;
      for (const auto& v : q) nothing = nothing || v[i] == none;
      if (nothing) continue;
      if (unres) {
        out[i] = unresolved;
        continue;
      }
      const Algebraic_real& b = loc[0][q[0][i]].root;
      bool same = true;
      for (std::size_t m = 1; m < q.size(); ++m) same = same && loc[m][q[m][i]].root == b;
      if (!same) continue;
      if (rb_is_loc0) {
        out[i] = q[0][i];
        continue;
      }
      for (std::size_t j = 0; j < rb.size(); ++j)
        if (rb[j].root == b) out[i] = int(j);
    }
    return out;
  }

  static void clean(Elimination& e, const P1& W) {
    if (W.degree() < 1) return;
    e.R = divide_out(e.R, W);
    for (;;) {  // divide S10 and S11 by W while both are divisible
      Ci_poly1 q0, r0, q1, r1;
      Integer d0, d1;
      if (CGAL::is_zero(e.S10) || CGAL::is_zero(e.S11)) return;
      Ci_poly1::pseudo_division(e.S10, W, q0, r0, d0);
      Ci_poly1::pseudo_division(e.S11, W, q1, r1, d1);
      if (!CGAL::is_zero(r0) || !CGAL::is_zero(r1)) return;
      // S10 = q0 W / d0, S11 = q1 W / d1: keep the ratio with integer coefficients
      e.S10 = q0 * P1(d1);
      e.S11 = q1 * P1(d0);
      Integer c(0);
      for (const P1* q : {&e.S10, &e.S11})
        for (int i = 0; i <= q->degree(); ++i) c = CGAL::gcd(c, (*q)[i]);
      if (c > 1) {
        e.S10 = CGAL::integral_division(e.S10, P1(c));
        e.S11 = CGAL::integral_division(e.S11, P1(c));
      }
    }
  }

  static std::vector<Isolated_root> roots01(const P1& f) {
    std::vector<Isolated_root> r = isolate_real_roots(f, Rational(0), Rational(1));
    separate_roots(r);
    return r;
  }

  static P1 primitive(const P1& f) {
    P1 g = f;
    g = CGAL::canonicalize(g);
    return g;
  }

  void solve_system(const std::vector<P2>& F, Curve_intersection_result& res, bool allow_overlap) {
    CI_TICK_START;
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
    CI_TICK("eliminate");
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
    CI_TICK("isolate");
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
    CI_TICK("pair");
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
    if (!us.empty() && !ut.empty()) sheared = sheared_pairs(F, rs, rt, us, ut);
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    for (const auto& p : pairs) res.points.push_back(make_point(rs[p.first], rt[p.second], es[0], et[0], ps[p.first] >= 0));
    for (const auto& p : sheared) res.points.push_back(sheared_point(rs[p.i], rt[p.j], p));
    CI_TICK("points");
  }

  // Shear s = u - lambda t: for generic lambda distinct solutions have distinct u; each root u_k of
  // Res_t(G1(u - lambda t, t), G2(...)) in [0, 1 + lambda] gives t = -S10(u_k)/S11(u_k) and s = u_k - lambda t, located
  // among the unresolved roots by exact sign decisions (polynomials in u evaluated at the algebraic u_k).
  // The system in (u, t) with s = u - lambda t: f(u - lambda t, t) for every f.
  static std::vector<P2> sheared_system(const std::vector<P2>& F, int lambda) {
    const P2 U(P1(Integer(0), Integer(1)));
    const P2 T(P1(0), P1(1));
    const P2 S = U - T * P2(lambda);
    std::vector<P2> Fs;
    for (const P2& f : F) {
      // f(S, t) = sum_j t^j f_j(S): Horner in the inner variable
      P2 r(0);
      for (int j = t_degree(f); j >= 0; --j) {
        P2 fj(0);
        for (int i = f[j].degree(); i >= 0; --i) fj = fj * S + P2(f[j][i]);
        r += fj * CGAL::ipower(T, j);
      }
      Fs.push_back(r);
    }
    return Fs;
  }

  static bool sheared_elimination(const std::vector<P2>& Fs, Elimination& e) {
    for (const auto& pr : candidate_pairs(Fs)) {
      e = eliminate(pr.first, pr.second);
      if (e.ok) return true;
    }
    return false;
  }

  // Intersection multiplicity of the rational solution (a, b) of F = 0: the multiplicity of u0 = a + lambda b as a
  // root of the sheared resultant, for a shear that leaves (a, b) alone on its line u = u0 (S11(u0) != 0: the gcd
  // of the pair on that line has degree 1; a leading coefficient survives: no solution at infinity).
  int local_multiplicity(const std::vector<P2>& F, const Rational& a, const Rational& b) const {
    for (int lambda = 1; lambda <= 12; ++lambda) {
      Elimination e;
      if (!sheared_elimination(sheared_system(F, lambda), e)) continue;
      const Rational u0 = a + Rational(lambda) * b;
      auto value = [&](const P1& f) {
        Rational r(0);
        for (int i = f.degree(); i >= 0; --i) r = r * u0 + Rational(f[i]);
        return r;
      };
      if (CGAL::is_zero(value(e.S11))) continue;
      if (CGAL::is_zero(value(e.G1[t_degree(e.G1)])) && CGAL::is_zero(value(e.G2[t_degree(e.G2)]))) continue;
      const P1 lin(-u0.numerator(), u0.denominator());  // den u - num
      P1 R = e.R;
      int m = 0;
      for (;;) {
        P1 q, r;
        Integer d;
        P1::pseudo_division(R, lin, q, r, d);
        if (!CGAL::is_zero(r)) break;
        R = q;
        ++m;
      }
      return m;
    }
    throw Error("intersect_curves: no separating shear found for the multiplicity of a tangency");
  }

  struct Sheared_pair {
    int i, j;           // indices into the s- and t-roots
    Isolated_root u;    // u_k = s + lambda t, a root of the sheared resultant (its multiplicity: see sheared_point)
    P1 S10, S11;        // t = -S10(u)/S11(u), S11(u_k) != 0
    int lambda;
  };

  std::vector<Sheared_pair> sheared_pairs(const std::vector<P2>& F, const std::vector<Isolated_root>& rs,
                                          const std::vector<Isolated_root>& rt, const std::vector<int>& us,
                                          const std::vector<int>& ut) const {
    for (int lambda = 1; lambda <= 12; ++lambda) {
      const std::vector<P2> Fs = sheared_system(F, lambda);
      Elimination e;
      if (!sheared_elimination(Fs, e)) continue;
      std::vector<Isolated_root> ru = isolate_real_roots(e.R, Rational(0), Rational(1 + lambda));
      std::vector<Sheared_pair> found;
      bool good = true;
      for (const Isolated_root& r : ru) {
        const Algebraic_real& u = r.root;
        const int s11 = root_sign(u, e.S11);
        const P1& l1 = e.G1[t_degree(e.G1)];
        const P1& l2 = e.G2[t_degree(e.G2)];
        if (s11 == 0 || (root_sign(u, l1) == 0 && root_sign(u, l2) == 0)) {
          good = false;
          break;
        }
        const Polynomial_1<Rational> S10 = to_rational(e.S10), S11 = to_rational(e.S11);
        const Polynomial_1<Rational> su = Polynomial_1<Rational>(Rational(0), Rational(1)) * S11 + S10 * Polynomial_1<Rational>(Rational(lambda));
        // sign(t - c) = -sign(S10 + c S11) sign(S11); sign(s - c) = sign(u S11 + lambda S10 - c S11) sign(S11)
        auto tcmp = [&](const Rational& c) { return -root_sign(u, S10 + S11 * Polynomial_1<Rational>(c)) * s11; };
        auto scmp = [&](const Rational& c) { return root_sign(u, su - S11 * Polynomial_1<Rational>(c)) * s11; };
        auto locate = [&](const std::vector<Isolated_root>& roots, const std::vector<int>& cand, auto cmp) {
          for (int k : cand) {
            const Algebraic_real& x = roots[k].root;
            if (x.is_rational() ? cmp(x.rational_value()) == 0 : (cmp(x.lower()) > 0 && cmp(x.upper()) < 0)) return k;
          }
          return -1;
        };
        const int i = locate(rs, us, scmp), j = locate(rt, ut, tcmp);
        if (i < 0 || j < 0) continue;
        bool all = true;
        if (F.size() > 2 || Fs.size() > 2) {
          for (const P2& f : Fs) all = all && root_sign(u, substitute(f, -e.S10, e.S11)) == 0;
        }
        if (all) found.push_back({i, j, r, e.S10, e.S11, lambda});
      }
      if (!good) continue;
      return found;
    }
    throw Error("intersect_curves: no separating shear found for a degenerate configuration");
  }

  // A point found by the shear: u_k is a root of Res_t of the sheared pair whose line u = u_k carries this point
  // only (S11(u_k) != 0 and a leading coefficient survives, checked in sheared_pairs), with s = (u S11 + lambda
  // S10)/S11, t = -S10/S11. So the multiplicity of u_k is the intersection multiplicity of the point, and the
  // tangents are parallel iff every 2x2 minor of (D1(s), D2(t)) vanishes there: minor(s(u), t(u)) is a rational
  // function of u, an exact univariate sign at u_k. (The eliminations in s or t cannot decide this: S11 vanishes
  // on both lines through the point, e.g. at a node shared by both curves, lyon-loops-nested.)
  Curve_intersection_point sheared_point(const Isolated_root& s, const Isolated_root& t, const Sheared_pair& q) const {
    Curve_intersection_point p;
    p.s = s.root;
    p.t = t.root;
    p.tangent = false;
    if (q.u.multiplicity >= 2 && !tangents_apart(s.root, t.root)) {
      std::array<P1, D> da, db;
      for (int k = 0; k < D; ++k) {
        da[k] = CGAL::differentiate(H1_[k + 1]) * H1_[0] - H1_[k + 1] * CGAL::differentiate(H1_[0]);
        db[k] = CGAL::differentiate(H2_[k + 1]) * H2_[0] - H2_[k + 1] * CGAL::differentiate(H2_[0]);
      }
      const P1 su = P1(Integer(0), Integer(1)) * q.S11 + q.S10 * P1(q.lambda);
      p.tangent = true;
      for (int i = 0; i < D && p.tangent; ++i)
        for (int j = i + 1; j < D && p.tangent; ++j) {
          const P2 m = lift_outer(db[j]) * P2(da[i]) - lift_outer(db[i]) * P2(da[j]);  // s inner, t outer
          p.tangent = root_sign(q.u.root, substitute_affine(m, su, -q.S10, q.S11)) == 0;
        }
    }
    p.multiplicity = p.tangent ? q.u.multiplicity : 1;
    auto end = [](const Algebraic_real& x) { return x.is_rational() && (x == 0 || x == 1); };
    p.kind = (end(p.s) || end(p.t)) ? Curve_intersection_kind::endpoint
                                    : (p.tangent ? Curve_intersection_kind::tangent : Curve_intersection_kind::transversal);
    return p;
  }

  Curve_intersection_point make_point(const Isolated_root& s, const Isolated_root& t, const Elimination& es,
                                      const Elimination& et, bool s_direction) const {
    Curve_intersection_point p;
    p.s = s.root;
    p.t = t.root;
    const int m = std::min(s.multiplicity, t.multiplicity);
    p.tangent = m >= 2 && !tangents_apart(s.root, t.root) && parallel_tangents(s.root, t.root, s_direction ? es : et, s_direction);
    p.multiplicity = p.tangent ? m : 1;
    auto end = [](const Algebraic_real& x) { return x.is_rational() && (x == 0 || x == 1); };
    p.kind = (end(p.s) || end(p.t)) ? Curve_intersection_kind::endpoint
                                    : (p.tangent ? Curve_intersection_kind::tangent : Curve_intersection_kind::transversal);
    return p;
  }

  // Interval proof that the tangent directions at (s, t) are not parallel (some 2x2 minor of [D1(s); D2(t)] has an
  // enclosure without 0), refining s and t; false = not proved (then parallel_tangents decides exactly).
  bool tangents_apart(const Algebraic_real& s, const Algebraic_real& t) const {
    using I = internal::Mpfi_interval;
    for (int bits = 24; bits <= 96; bits *= 2) {
      Integer p2(1);
      mpz_mul_2exp(p2.mpz(), p2.mpz(), (unsigned long)bits);
      const Rational w = Rational(1) / Rational(p2);
      const mpfr_prec_t prec = mpfr_prec_t(64 + 2 * bits + coefficient_bits_);
      auto box = [&](const Algebraic_real& x) {
        if (x.is_rational()) return I::hull(x.rational_value(), x.rational_value(), prec);
        x.refine_to_width(w);
        return x.is_rational() ? I::hull(x.rational_value(), x.rational_value(), prec) : I::hull(x.lower(), x.upper(), prec);
      };
      const I us = box(s), ut = box(t);
      auto tangent = [&](const Form& H, const I& u) {
        std::array<I, D> d = make_array_of_intervals(prec);
        const I w0 = I::horner(H[0], u), dw0 = I::horner(CGAL::differentiate(H[0]), u);
        for (int k = 0; k < D; ++k)
          d[k] = I::horner(CGAL::differentiate(H[k + 1]), u) * w0 - I::horner(H[k + 1], u) * dw0;
        return d;
      };
      const auto da = tangent(H1_, us), db = tangent(H2_, ut);
      for (int i = 0; i < D; ++i)
        for (int j = i + 1; j < D; ++j)
          if (!(da[i] * db[j] - da[j] * db[i]).contains_zero()) return true;
    }
    return false;
  }

  // Tangent vectors D(u) = X_k' W - X_k W' are parallel iff all 2x2 minors of [D1(s); D2(t)] vanish; t is the
  // rational function -S10/S11 of s (or symmetrically), so each minor is a univariate sign decision.
  bool parallel_tangents(const Algebraic_real& s, const Algebraic_real& t, const Elimination& e, bool s_direction) const {
    const Form& A = s_direction ? H1_ : H2_;
    const Form& B = s_direction ? H2_ : H1_;
    const Algebraic_real& a = s_direction ? s : t;
    (void)t;
    std::array<P1, D> da, db;
    for (int k = 0; k < D; ++k) {
      da[k] = CGAL::differentiate(A[k + 1]) * A[0] - A[k + 1] * CGAL::differentiate(A[0]);
      db[k] = CGAL::differentiate(B[k + 1]) * B[0] - B[k + 1] * CGAL::differentiate(B[0]);
    }
    const P1 N = -e.S10;
    for (int i = 0; i < D; ++i)
      for (int j = i + 1; j < D; ++j) {
        // da_i(a) db_j(b) - da_j(a) db_i(b), b = N/S11
        P2 m = lift_outer(db[j]) * P2(da[i]) - lift_outer(db[i]) * P2(da[j]);
        if (root_sign(a, substitute(m, N, e.S11)) != 0) return false;
      }
    return true;
  }

  // ---------------------------------------------------------------- overlaps (common component of the F_k)
  void overlap_case(const std::vector<P2>& F, Curve_intersection_result& res) {
    P2 H = F[0];
    for (std::size_t k = 1; k < F.size(); ++k) H = CGAL::gcd(H, F[k]);
    const P2 Hs = swap_variables(H);
    if (t_degree(H) < 1 || t_degree(Hs) < 1)
      throw Error("intersect_curves: a curve has a base point (common root of its homogeneous coordinates); "
                  "reduce it first");
    // Breakpoints on curve 1: its ends and the preimages of the ends of curve 2.
    struct Break {
      Algebraic_real s;
      std::vector<Algebraic_real> t;  // partners on curve 2 (for ends of curve 1: by inversion)
    };
    std::vector<Break> br;
    for (int e = 0; e <= 1; ++e) {
      Break b{Algebraic_real(e), {}};
      invert_point<D>(H2_, point_at<D>(H1_, Rational(e)), b.t);
      br.push_back(b);
      std::vector<Algebraic_real> ss;
      invert_point<D>(H1_, point_at<D>(H2_, Rational(e)), ss);
      for (const auto& s : ss) br.push_back(Break{s, {Algebraic_real(e)}});
    }
    std::sort(br.begin(), br.end(), [](const Break& x, const Break& y) { return x.s < y.s; });
    std::vector<Break> ub;  // merge equal parameters
    for (const Break& b : br) {
      if (!ub.empty() && ub.back().s == b.s) {
        for (const auto& t : b.t)
          if (std::find(ub.back().t.begin(), ub.back().t.end(), t) == ub.back().t.end()) ub.back().t.push_back(t);
      } else {
        ub.push_back(b);
      }
    }
    // Piece (b_i, b_{i+1}) is covered iff its rational midpoint lies on C2([0,1]) (the image of curve 1 lies on the
    // irreducible implicit curve of curve 2, and coverage can only change at the preimages of C2(0), C2(1)).
    std::vector<char> covered(ub.size() > 0 ? ub.size() - 1 : 0, 0);
    std::vector<double> tmid(covered.size(), 0);
    for (std::size_t i = 0; i + 1 < ub.size(); ++i) {
      const Rational m = ub[i].s.is_rational() && ub[i + 1].s.is_rational()
                             ? (ub[i].s.rational_value() + ub[i + 1].s.rational_value()) / 2
                             : ub[i].s.rational_between(ub[i + 1].s);
      std::vector<Algebraic_real> t;
      invert_point<D>(H2_, point_at<D>(H1_, m), t);
      covered[i] = !t.empty();
      if (!t.empty()) tmid[i] = t.front().to_double();
    }
    auto pick = [](const std::vector<Algebraic_real>& c, double near) {
      std::size_t best = 0;
      for (std::size_t k = 1; k < c.size(); ++k)
        if (std::abs(c[k].to_double() - near) < std::abs(c[best].to_double() - near)) best = k;
      return c[best];
    };
    std::vector<Curve_overlap> ov;
    for (std::size_t i = 0; i < covered.size();) {
      if (!covered[i]) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j + 1 < covered.size() && covered[j + 1]) ++j;
      if (ub[i].t.empty() || ub[j + 1].t.empty()) throw Error("intersect_curves: overlap end without partner");
      ov.push_back({ub[i].s, ub[j + 1].s, pick(ub[i].t, tmid[i]), pick(ub[j + 1].t, tmid[j])});
      i = j + 1;
    }
    auto inside = [&](const Algebraic_real& s, const Algebraic_real& t) {
      for (const auto& o : ov) {
        const bool ins = o.s0 <= s && s <= o.s1;
        const bool int_ = (o.t0 <= t && t <= o.t1) || (o.t1 <= t && t <= o.t0);
        if (ins && int_) return true;
      }
      return false;
    };
    // Isolated touching points at breakpoints.
    for (const Break& b : ub)
      for (const auto& t : b.t)
        if (!inside(b.s, t)) {
          Curve_intersection_point p;
          p.s = b.s;
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
};

} // namespace internal

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
template <int D>
Curve_intersection_result intersect_curves(const Rational_bezier_curve<Rational, D>& c1,
                                           const Rational_bezier_curve<Rational, D>& c2,
                                           Curve_intersection_method method = Curve_intersection_method::default_method) {
  return internal::Curve_intersection_engine<D>(c1, c2, method).run();
}

/// \brief Self-intersections (loops) of a curve: pairs s < t in [0,1] with C(s) = C(t), exact (the system
/// (X_k(s)W(t) - X_k(t)W(s)) / (s - t) = 0, divided differences, solved like intersect_curves).
template <int D>
Curve_intersection_result self_intersections(const Rational_bezier_curve<Rational, D>& c,
                                             Curve_intersection_method method = Curve_intersection_method::default_method) {
  return internal::Curve_intersection_engine<D>(c, c, method).run_self();
}

/// Functor form (CGAL style).
struct Intersect_curves {
  Curve_intersection_method method = Curve_intersection_method::default_method;
  template <int D>
  Curve_intersection_result operator()(const Rational_bezier_curve<Rational, D>& c1,
                                       const Rational_bezier_curve<Rational, D>& c2) const {
    return intersect_curves(c1, c2, method);
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
