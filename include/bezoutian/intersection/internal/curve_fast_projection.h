// The fast certified path of intersect_curves (default method): du-1989 eq. 4.1 kept as a matrix. For a plane curve B = (X, Y, W)(t) of degree n >= 2 the Bezout matrix
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
//
// Internal header: members of Curve_intersection_engine (Curve_intersection.h), not part of the public API.
#ifndef BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_FAST_PROJECTION_H
#define BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_FAST_PROJECTION_H

#include <bezoutian/intersection/Curve_intersection.h>

#include <bezoutian/arithmetic/interval_krawczyk.h>
#include <bezoutian/elimination/Bezout_matrix.h>
#include <bezoutian/elimination/Polynomial_matrix_determinant.h>

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

namespace bezoutian {
namespace internal {

template <int D>
bool Curve_intersection_engine<D>::fast_path(Curve_intersection_result& res) const {
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

// One projection; `res` receives the certified points when `done`.
template <int D>
auto Curve_intersection_engine<D>::fast_projection(const std::array<int, 3>& a, const std::array<int, 3>& b,
                                                  Curve_intersection_result& res) const -> Fast {
  const auto A = projected(H1_, a, b), B = projected(H2_, a, b);
  const int nA = degree3(A), nB = degree3(B);
  if (std::max(nA, nB) < 2) return Fast::undecided;
  if (nA < 1 || nB < 1) return Fast::undecided;  // a projection collapsed to a point
  BEZOUTIAN_PROFILE_START;
  const Matrix1 Ms = implicit_matrix_on(B, A);
  P1 R = polynomial_matrix_determinant(Ms);
  if (CGAL::is_zero(R)) return Fast::undecided;
  R = divide_out(R, H1_[0]);  // roots outside [0,1] only (no pole in [0,1]): smaller polynomials to isolate
  const std::vector<Isolated_root> rs = roots01(primitive(R));
  BEZOUTIAN_PROFILE_STEP("fast R");
  if (rs.empty()) return Fast::done;  // no s in [0,1] on the (projected) curve 2: proved empty
  const Matrix1 Mt = implicit_matrix_on(A, B);
  P1 T = polynomial_matrix_determinant(Mt);
  if (CGAL::is_zero(T)) return Fast::undecided;
  T = divide_out(T, H2_[0]);
  const std::vector<Isolated_root> rt = roots01(primitive(T));
  BEZOUTIAN_PROFILE_STEP("fast T");
  if (rt.empty()) return Fast::done;

  // Every intersection (s*, t*) in [0,1]^2 has s* among rs and t* among rt. Pairs are decided in three ways:
  // (1) a rational parameter: its point is rational, its partners on the other curve follow by exact inversion;
  // (2) irrational s_i, t_j: disjoint point enclosures exclude the pair, the Krawczyk test proves it (the box
  //     I(s_i) x I(t_j) holds exactly one common point of the projections, which is then (s_i, t_j), since the
  //     isolating intervals hold no other root of R and T; in space the remaining coordinate is then checked);
  // (3) otherwise the cofactor inversion t* = -M_01(s_i)/M_00(s_i) decides exactly.
  Fast_pairs pairs;
  std::vector<char> s_done(rs.size(), 0);
  fast_exact_pairs(rs, rt, s_done, pairs);
  BEZOUTIAN_PROFILE_STEP("fast exact pairs");
  // the coordinate that the projection plane does not see (a x b has a nonzero entry there)
  int hidden = -1;
  if (D == 3) {
    const int cr[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    for (int k = 2; k >= 0; --k)
      if (cr[k] != 0) hidden = k;
  }
  const std::vector<std::size_t> cofactor_roots = fast_interval_pairs(A, B, rs, rt, s_done, hidden, pairs);
  BEZOUTIAN_PROFILE_STEP("fast interval pairs");
  if (fast_cofactor_pairs(Ms, nB, rs, rt, cofactor_roots, hidden, res) == Fast::undecided) return Fast::undecided;
  BEZOUTIAN_PROFILE_STEP("fast cofactor pairs");
  for (std::size_t k = 0; k < pairs.index.size(); ++k) {
    const auto& p = pairs.index[k];
    if (pairs.exact[k]) {
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

// (1) of fast_projection: the partners of the rational roots of R and T by exact inversion of their points.
template <int D>
void Curve_intersection_engine<D>::fast_exact_pairs(const std::vector<Isolated_root>& rs,
                                                    const std::vector<Isolated_root>& rt, std::vector<char>& s_done,
                                                    Fast_pairs& pairs) const {
  auto index_of = [](const std::vector<Isolated_root>& r, const Algebraic_real& x) {
    for (std::size_t k = 0; k < r.size(); ++k)
      if (r[k].root == x) return int(k);
    throw Error("intersect_curves: internal inconsistency (an exact partner is not a root of the eliminant)");
  };
  for (std::size_t i = 0; i < rs.size(); ++i) {
    if (!rs[i].root.is_rational()) continue;
    std::vector<Algebraic_real> ts;
    invert_point<D>(H2_, point_at<D>(H1_, rs[i].root.rational_value()), ts);
    for (const auto& t : ts) pairs.add(int(i), index_of(rt, t), true);
    s_done[i] = 1;
  }
  for (std::size_t j = 0; j < rt.size(); ++j) {
    if (!rt[j].root.is_rational()) continue;
    std::vector<Algebraic_real> ss;
    invert_point<D>(H1_, point_at<D>(H2_, rt[j].root.rational_value()), ss);
    for (const auto& x : ss) pairs.add(index_of(rs, x), int(j), true);
  }
}

// (2) of fast_projection: irrational roots s_i of R against the irrational roots t_j of T, by point enclosures and
// the Krawczyk test; returns the roots s_i left to the cofactor inversion (3).
template <int D>
std::vector<std::size_t> Curve_intersection_engine<D>::fast_interval_pairs(
    const std::array<P1, 3>& A, const std::array<P1, 3>& B, const std::vector<Isolated_root>& rs,
    const std::vector<Isolated_root>& rt, const std::vector<char>& s_done, int hidden, Fast_pairs& pairs) const {
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
          pairs.add(int(i), j, false);
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
  return cofactor_roots;
}

// (3) of fast_projection: t* = -M_01(s_i)/M_00(s_i) located exactly among the roots of T; undecided when a
// cofactor vanishes.
template <int D>
auto Curve_intersection_engine<D>::fast_cofactor_pairs(const Matrix1& Ms, int nB, const std::vector<Isolated_root>& rs,
                                                       const std::vector<Isolated_root>& rt,
                                                       const std::vector<std::size_t>& cofactor_roots, int hidden,
                                                       Curve_intersection_result& res) const -> Fast {
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
  return Fast::done;
}

// Form of the plane projection (W, a.X, b.X) of a curve (a, b: integer rows of length D).
template <int D>
auto Curve_intersection_engine<D>::projected(const Form& H, const std::array<int, 3>& a,
                                                const std::array<int, 3>& b) -> std::array<P1, 3> {
  std::array<P1, 3> r{H[0], P1(0), P1(0)};
  for (int k = 0; k < D; ++k) {
    if (a[k] != 0) r[1] += H[k + 1] * P1(a[k]);
    if (b[k] != 0) r[2] += H[k + 1] * P1(b[k]);
  }
  return r;
}

template <int D>
int Curve_intersection_engine<D>::degree3(const std::array<P1, 3>& f) {
  int n = 0;
  for (const P1& q : f)
    if (!CGAL::is_zero(q)) n = std::max(n, q.degree());
  return n;
}

template <int D>
Integer Curve_intersection_engine<D>::coefficient_xy(const P2& f, int i, int j) {  // coefficient of x^i y^j
  if (CGAL::is_zero(f) || j > f.degree()) return Integer(0);
  const P1& g = f[j];
  return (CGAL::is_zero(g) || i > g.degree()) ? Integer(0) : g[i];
}

// M(s) = W_A(s) Bez_B(X_A/W_A, Y_A/W_A).
template <int D>
auto Curve_intersection_engine<D>::implicit_matrix_on(const std::array<P1, 3>& B, const std::array<P1, 3>& A)
    -> Matrix1 {
  const auto C = rational_curve_bezout_matrix(B[1], B[2], B[0]);
  Matrix1 M(C.size(), std::vector<P1>(C.size()));
  for (std::size_t p = 0; p < C.size(); ++p)
    for (std::size_t q = 0; q < C.size(); ++q)
      M[p][q] = A[0] * P1(coefficient_xy(C[p][q], 0, 0)) + A[1] * P1(coefficient_xy(C[p][q], 1, 0)) +
                A[2] * P1(coefficient_xy(C[p][q], 0, 1));
  return M;
}

template <int D>
auto Curve_intersection_engine<D>::cofactor_minor(const Matrix1& M, std::size_t row, std::size_t col) -> P1 {
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

template <int D>
std::array<internal::Mpfi_interval, D> Curve_intersection_engine<D>::point_enclosure(const Form& H,
                                                                                const Algebraic_real& x,
                                                                                mpfr_prec_t prec) const {
  using I = internal::Mpfi_interval;
  const I u = x.is_rational() ? I::hull(x.rational_value(), x.rational_value(), prec) : I::hull(x.lower(), x.upper(), prec);
  const I w = I::horner(H[0], u);
  std::array<I, D> r = make_array_of_intervals(prec);
  for (int k = 0; k < D; ++k) r[k] = I::horner(H[k + 1], u) / w;
  return r;
}

// Rational parameters: the multiplicity from the eliminants, tangency by exact evaluation of the tangents.
template <int D>
Curve_intersection_point Curve_intersection_engine<D>::exact_point(const Isolated_root& s, const Isolated_root& t) const {
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
template <int D>
bool Curve_intersection_engine<D>::space_coordinates_agree(const Algebraic_real& x, const Elimination& e,
                                                           bool from_s, int hidden) const {
  const Form& A = from_s ? H1_ : H2_;  // the curve of x
  const Form& B = from_s ? H2_ : H1_;
  const P1 N = -e.S10;
  const int k = hidden + 1;
  const P2 F = lift_outer(B[0]) * P2(A[k]) - lift_outer(B[k]) * P2(A[0]);
  return root_sign(x, substitute(F, N, e.S11)) == 0;
}

} // namespace internal
} // namespace bezoutian

#endif // BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_FAST_PROJECTION_H
