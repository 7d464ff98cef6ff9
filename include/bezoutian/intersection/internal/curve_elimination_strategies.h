// The eliminants of the exact system F_k(s,t) = X1_k(s) W2(t) - X2_k(t) W1(s) = 0 of two curves (du-1989 ch. 4),
// one function per Curve_intersection_method behind Curve_intersection_engine::strategy_R:
//  - subresultant (and the default method): R(s) = Res_t(G1, G2) with the first subresultant S_1 = S11 t + S10,
//    whose ratio -S10/S11 inverts a root of R (eliminate);
//  - projection: R = f2(X1, Y1, W1), the implicit equation of curve 2 (du-1989 eq. 4.1) on curve 1;
//  - resolvent: R = gcd of Goldman's quadrics (du-1989 eq. 4.2/4.3) of a space cubic on the other curve;
//  - groebner: the generator of the elimination ideal in Q[s] of a lexicographic Groebner basis.
// Every root in [0,1] of each of them contains the parameter s of every intersection; the pairing that follows
// (curve_candidate_pairs.h) is the same for all, so all methods return identical answers. Also the clean-up of
// the eliminants (weight factors without roots in [0,1]) and the isolation of their roots in [0,1].
//
// Internal header: members of Curve_intersection_engine (Curve_intersection.h), not part of the public API.
#ifndef BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_ELIMINATION_STRATEGIES_H
#define BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_ELIMINATION_STRATEGIES_H

#include <bezoutian/intersection/Curve_intersection.h>

#include <bezoutian/elimination/Bezout_matrix.h>
#include <bezoutian/elimination/Goldman_resolvent.h>
#include <bezoutian/elimination/Groebner_bivariate.h>

#include <vector>

namespace bezoutian {
namespace internal {

// with_S1 = false: only the resultant (CGAL::resultant, cheaper than the subresultant sequence)
template <int D>
auto Curve_intersection_engine<D>::eliminate(const P2& G1, const P2& G2, bool with_S1) -> Elimination {
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

// R(s) from the strategy: default and subresultant keep e.R = Res_t(G1, G2) (eliminate); groebner; resolvent where
// it applies; projection otherwise.
template <int D>
auto Curve_intersection_engine<D>::strategy_R(const Elimination& e, const Form& A, const Form& B) const -> P1 {
  if (plain_method()) return e.R;
  if (method_ == Curve_intersection_method::groebner) return eliminant_groebner(e, A, B);
  if (method_ == Curve_intersection_method::resolvent && resolvent_applies(B)) return eliminant_resolvent(e, A, B);
  return eliminant_projection(e, A, B);
}

template <int D>
auto Curve_intersection_engine<D>::eliminant_groebner(const Elimination& e, const Form& A, const Form& B) -> P1 {
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

// Goldman's resolvent applies to space curves B of degree exactly 3.
template <int D>
bool Curve_intersection_engine<D>::resolvent_applies(const Form& B) {
  return D == 3 && B[0].degree() <= 3 && max_degree(B) <= 3 && max_degree(B) == 3;
}

template <int D>
auto Curve_intersection_engine<D>::eliminant_resolvent(const Elimination& e, const Form& A, const Form& B) -> P1 {
  const auto r = goldman_rational_cubic_resolvent(B[1], B[2], B[D == 3 ? 3 : 1], B[0]);
  P1 g(0);
  for (const auto* q : {&r.R1, &r.R2, &r.R3}) {
    P1 v = substitute_quadric(*q, A);
    g = CGAL::is_zero(g) ? v : (CGAL::is_zero(v) ? g : P1(CGAL::gcd(g, v)));
  }
  if (!CGAL::is_zero(g)) return g;
  return e.R;
}

// Plane curves: the implicit equation of B evaluated on A; space curves keep the resultant.
template <int D>
auto Curve_intersection_engine<D>::eliminant_projection(const Elimination& e, const Form& A, const Form& B) -> P1 {
  if (D == 2) {
    const P2 f = bezout_implicit_equation(B[1], B[2], B[0]);
    const P1 r = substitute_affine(f, A[1], A[2], A[0]);
    if (!CGAL::is_zero(r)) return r;
  }
  return e.R;
}

// Substitute the homogeneous form H (an affine polynomial f(x,y) of total degree n) : f(X/W, Y/W) W^n.
template <int D>
auto Curve_intersection_engine<D>::substitute_affine(const P2& f, const P1& X, const P1& Y, const P1& W) -> P1 {
  int n = 0;
  for (int j = 0; j <= f.degree(); ++j)
    if (!CGAL::is_zero(f[j])) n = std::max(n, j + f[j].degree());
  P1 r(0);
  for (int j = 0; j <= f.degree(); ++j)
    for (int i = 0; i <= f[j].degree(); ++i)
      if (!CGAL::is_zero(f[j][i])) r += P1(f[j][i]) * CGAL::ipower(X, i) * CGAL::ipower(Y, j) * CGAL::ipower(W, n - i - j);
  return r;
}

template <int D>
int Curve_intersection_engine<D>::max_degree(const Form& H) {
  int n = 0;
  for (const auto& h : H) n = std::max(n, h.degree());
  return n;
}

template <int D>
template <class Q3>
auto Curve_intersection_engine<D>::substitute_quadric(const Q3& q, const Form& A) -> P1 {
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

template <int D>
void Curve_intersection_engine<D>::clean(Elimination& e, const P1& W) {
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

template <int D>
std::vector<Isolated_root> Curve_intersection_engine<D>::roots01(const P1& f) {
  std::vector<Isolated_root> r = isolate_real_roots(f, Rational(0), Rational(1));
  separate_roots(r);
  return r;
}

template <int D>
auto Curve_intersection_engine<D>::primitive(const P1& f) -> P1 {
  P1 g = f;
  g = CGAL::canonicalize(g);
  return g;
}

} // namespace internal
} // namespace bezoutian

#endif // BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_ELIMINATION_STRATEGIES_H
