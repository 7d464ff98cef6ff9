// Goldman's special resolvent of three cubic polynomials in one variable and
// the inversion formula (du-1989 §3.3.2, eq. 3.55-3.60; rational space cubics
// eq. 4.2-4.3, after Goldman [Goldm85]).
//
// For P_1, P_2, P_3 of degree <= 3 (at least one of degree 3) write
// p(t) = v_3 t^3 + v_2 t^2 + v_1 t + v_0 with v_k = (a_k, b_k, c_k) the
// coefficients of t^k, and [ijk] = |v_i, v_j, v_k| (3x3 determinant with these
// columns). Eliminating t^3 and t^2 by determinant identities gives the three
// linear polynomials (eq. 3.56/3.57)
//     F_1 = [321] t + [320],   F_2 = [320] t + [310],   F_3 = [310] t + [210],
// which share a root with p exactly when P_1, P_2, P_3 do (for linearly
// independent P_i). The special resolvents are the 2x2 resultants of the
// pairs (eq. 3.59):
//     R_1 = [321][310] - [320]^2          = Res(F_1, F_2),
//     R_2 = [321][210] - [320][310]       = Res(F_1, F_3),
//     R_3 = [320][210] - [310]^2          = Res(F_2, F_3),
// and a common root is t_0 = -[320] / [321] (inversion, eq. 3.60).
//
// Rational space cubic (X, Y, Z, W) (eq. 4.2/4.3): the polynomials are
// X - x W, Y - y W, Z - z W with coefficients linear in (x, y, z); their
// brackets equal the 4x4 determinants |u_i, u_j, u_k, q| of the seed,
// u_k = (a_k, b_k, c_k, d_k), q = (x, y, z, 1) (subtract x, y, z times the last
// row). The seed's printed eq. 4.2/4.3 carry typos (|u_0,u_2,u_1,q| for
// |u_3,u_2,u_1,q|, |u_0,u_1,u_0,q| for |u_3,u_1,u_0,q|, and 4.3 lacks the minus
// sign of 3.60); `goldman_rational_cubic_resolvent` implements the consistent
// form, checked by the tests on points of random curves.
#ifndef BEZOUTIAN_ELIMINATION_GOLDMAN_RESOLVENT_H
#define BEZOUTIAN_ELIMINATION_GOLDMAN_RESOLVENT_H

#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/arithmetic/number_types.h>

#include <CGAL/Polynomial_type_generator.h>

#include <array>
#include <optional>

namespace bezoutian {

/// Goldman's special resolvent of three cubics (du-1989 §3.3.2).
template <class NT>
struct Goldman_resolvent {
  /// Brackets |v_i, v_j, v_k|: d321 = [321], d320 = [320], d310 = [310], d210 = [210].
  NT d321, d320, d310, d210;
  /// The linear polynomials of eq. 3.57.
  Polynomial_1<NT> F1, F2, F3;
  /// The special resolvents of eq. 3.59.
  NT R1, R2, R3;

  /// P_1, P_2, P_3 are linearly independent iff some bracket is nonzero (the
  /// brackets are the 3x3 minors of the 3x4 coefficient matrix (v_0 v_1 v_2 v_3)).
  bool linearly_independent() const {
    return !(CGAL::is_zero(d321) && CGAL::is_zero(d320) && CGAL::is_zero(d310) && CGAL::is_zero(d210));
  }
  /// For linearly independent P_i: a common root exists iff d321 != 0 and
  /// R1 = R2 = 0 (then R3 = 0 too) (du-1989 §3.3.2).
  bool has_common_root() const {
    return !CGAL::is_zero(d321) && CGAL::is_zero(R1) && CGAL::is_zero(R2);
  }
  /// Inversion formula (eq. 3.60): t_0 = inversion_numerator() / inversion_denominator() = -[320] / [321].
  NT inversion_numerator() const { return -d320; }
  NT inversion_denominator() const { return d321; }
};

namespace internal {

template <class NT>
NT goldman_bracket(const std::array<NT, 3>& a, const std::array<NT, 3>& b, const std::array<NT, 3>& c) {
  // Columns a, b, c.
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - b[0] * (a[1] * c[2] - a[2] * c[1]) + c[0] * (a[1] * b[2] - a[2] * b[1]);
}

} // namespace internal

/// The special resolvent of P_1, P_2, P_3 (degree <= 3 each, at least one of
/// degree 3) over any commutative ring NT. Throws Invalid_input otherwise.
template <class NT>
Goldman_resolvent<NT> goldman_resolvent(const Polynomial_1<NT>& P1, const Polynomial_1<NT>& P2,
                                        const Polynomial_1<NT>& P3) {
  const Polynomial_1<NT>* P[3] = {&P1, &P2, &P3};
  bool cubic = false;
  for (const auto* p : P) {
    if (!CGAL::is_zero(*p) && p->degree() > 3) throw Invalid_input("goldman_resolvent: a polynomial has degree > 3");
    if (!CGAL::is_zero(*p) && p->degree() == 3) cubic = true;
  }
  if (!cubic) throw Invalid_input("goldman_resolvent: none of the three polynomials has degree 3");
  std::array<std::array<NT, 3>, 4> v;  // v[k] = (a_k, b_k, c_k)
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 3; ++i) v[k][i] = (!CGAL::is_zero(*P[i]) && k <= P[i]->degree()) ? (*P[i])[k] : NT(0);
  Goldman_resolvent<NT> r;
  r.d321 = internal::goldman_bracket(v[3], v[2], v[1]);
  r.d320 = internal::goldman_bracket(v[3], v[2], v[0]);
  r.d310 = internal::goldman_bracket(v[3], v[1], v[0]);
  r.d210 = internal::goldman_bracket(v[2], v[1], v[0]);
  r.F1 = Polynomial_1<NT>(r.d320, r.d321);
  r.F2 = Polynomial_1<NT>(r.d310, r.d320);
  r.F3 = Polynomial_1<NT>(r.d210, r.d310);
  r.R1 = r.d321 * r.d310 - r.d320 * r.d320;
  r.R2 = r.d321 * r.d210 - r.d320 * r.d310;
  r.R3 = r.d320 * r.d210 - r.d310 * r.d310;
  return r;
}

/// The common root of three linearly independent cubics over a field FT, by
/// the special resolvent and the inversion formula (eq. 3.59/3.60), or none.
/// Throws Invalid_input if the polynomials are linearly dependent (then the
/// resolvents vanish identically and say nothing) or none has degree 3.
template <class FT>
std::optional<FT> goldman_common_root(const Polynomial_1<FT>& P1, const Polynomial_1<FT>& P2,
                                      const Polynomial_1<FT>& P3) {
  const Goldman_resolvent<FT> r = goldman_resolvent(P1, P2, P3);
  if (!r.linearly_independent()) throw Invalid_input("goldman_common_root: the three polynomials are linearly dependent");
  if (!r.has_common_root()) return std::nullopt;
  return FT(r.inversion_numerator() / r.inversion_denominator());
}

namespace internal {
/// Polynomials in (x, y, z) = variables (0, 1, 2) over NT.
template <class NT>
using Goldman_polynomial_3 = typename CGAL::Polynomial_type_generator<NT, 3>::Type;
} // namespace internal

/// Special resolvent of the rational space cubic t -> (X/W, Y/W, Z/W)
/// (du-1989 eq. 4.2/4.3): goldman_resolvent of X - x W, Y - y W, Z - z W over
/// CGAL::Polynomial_type_generator<NT, 3>::Type (x, y, z = variables 0, 1, 2). R1, R2, R3 are quadrics in
/// (x, y, z) vanishing on the curve; at a curve point q the parameter is
/// -d320(q) / d321(q). Throws Invalid_input if X, Y, Z, W all have degree < 3.
template <class NT>
Goldman_resolvent<internal::Goldman_polynomial_3<NT>> goldman_rational_cubic_resolvent(const Polynomial_1<NT>& X,
                                                                     const Polynomial_1<NT>& Y,
                                                                     const Polynomial_1<NT>& Z,
                                                                     const Polynomial_1<NT>& W) {
  using P3 = internal::Goldman_polynomial_3<NT>;
  using P = Polynomial_1<P3>;
  const P3 var[3] = {CGAL::shift(P3(1), 1, 0), CGAL::shift(P3(1), 1, 1), CGAL::shift(P3(1), 1, 2)};
  const Polynomial_1<NT>* num[3] = {&X, &Y, &Z};
  P Q[3];
  for (int i = 0; i < 3; ++i) {
    std::array<P3, 4> c;
    for (int k = 0; k < 4; ++k) {
      const NT a = (!CGAL::is_zero(*num[i]) && k <= num[i]->degree()) ? (*num[i])[k] : NT(0);
      const NT d = (!CGAL::is_zero(W) && k <= W.degree()) ? W[k] : NT(0);
      c[k] = P3(a) - var[i] * P3(d);
    }
    if ((!CGAL::is_zero(*num[i]) && num[i]->degree() > 3) || (!CGAL::is_zero(W) && W.degree() > 3))
      throw Invalid_input("goldman_rational_cubic_resolvent: a component has degree > 3");
    Q[i] = P(c.begin(), c.end());
  }
  return goldman_resolvent(Q[0], Q[1], Q[2]);
}

/// Functor form.
struct Goldman_special_resolvent {
  template <class NT>
  Goldman_resolvent<NT> operator()(const Polynomial_1<NT>& P1, const Polynomial_1<NT>& P2,
                                   const Polynomial_1<NT>& P3) const {
    return goldman_resolvent(P1, P2, P3);
  }
};

} // namespace bezoutian

#endif // BEZOUTIAN_ELIMINATION_GOLDMAN_RESOLVENT_H
