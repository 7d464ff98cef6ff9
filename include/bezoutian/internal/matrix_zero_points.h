// Points where the whole Bezoutian matrix vanishes: multiple points of the implicit equation.
//
// If every entry of the n x n matrix B vanishes at p, every entry lies in the maximal ideal of p, so
// det B (a sum of products of n entries) vanishes to order >= n there: p is a point of multiplicity >= n of
// D = det B. For patches of bi-degree (2, 2) the 3 x 3 self-intersection matrix of Theorems 4-5 vanishes at finitely
// many points (16 for the worked example of buse-elkadi-galligo-2008 §4, 20 for rational patches), and the triple
// point of §4 near (-1.05, -0.049) is one of them. They are found exactly: the reduced lexicographic Groebner basis
// of the entries (certified, Groebner_bivariate.h) is, in general position, {h(u), v - q(u)}, so the common zeros
// are (alpha, q(alpha)) over the real roots alpha of h, isolated exactly and enclosed in boxes small enough for
// the Taylor coefficients of D there (internal/multiple_point_blowup.h).
#ifndef BEZOUTIAN_INTERNAL_MATRIX_ZERO_POINTS_H
#define BEZOUTIAN_INTERNAL_MATRIX_ZERO_POINTS_H

#include <bezoutian/Curve_topology_by_subdivision.h>
#include <bezoutian/Error.h>
#include <bezoutian/Groebner_bivariate.h>
#include <bezoutian/Implicit_equation.h>
#include <bezoutian/Root_isolation.h>

#include <mpfi.h>

#include <algorithm>
#include <vector>

namespace bezoutian {
namespace internal {

/// The common zeros of all entries of E.matrix strictly inside `box`, as multiple points of E.square_free of
/// multiplicity >= n (n = matrix size), each in a small enclosure that holds no other common zero. Empty when the
/// matrix is larger than `max_size` (the Groebner basis would cost more than it saves), when D is not square-free
/// (its square-free part may then have a lower multiplicity), when the basis is not of the form {h(u), v - q(u)},
/// or when it exceeds its budget: the subdivision then works without them.
inline std::vector<Known_multiple_point> matrix_zero_points(const Implicit_equation& E, const Parameter_box& box,
                                                            std::size_t max_size = 3) {
  std::vector<Known_multiple_point> out;
  const std::size_t n = E.matrix.size();
  if (n < 2 || n > max_size || E.is_degenerate() || E.determinant != E.square_free) return out;
  std::vector<Polynomial_2<Rational>> F;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (!CGAL::is_zero(E.matrix.entries[i][j])) F.push_back(E.matrix.entries[i][j]);
  if (F.empty()) return out;
  std::vector<Lex_polynomial_2> G;
  try {
    G = modular_lex_groebner_basis(F, nullptr, 200000);
  } catch (const Error&) {
    return out;
  }
  // shape position: h(u) and c v + r(u)
  if (G.size() != 2) return out;
  const Lex_polynomial_2* h = nullptr;
  const Lex_polynomial_2* g = nullptr;
  for (const auto& p : G) {
    if (p.is_univariate_in_s()) h = &p;
    else if (p.leading_monomial() == Lex_polynomial_2::Monomial{1, 0}) g = &p;
  }
  if (!h || !g) return out;
  const Polynomial_1<Rational> hu = h->to_univariate();
  if (hu.degree() < 1) return out;
  std::vector<Rational> q;  // v = q(u) = -r(u) / c
  for (const auto& t : g->terms())
    if (t.first.first == 0) {
      if (q.size() <= std::size_t(t.first.second)) q.resize(std::size_t(t.first.second) + 1, Rational(0));
      q[std::size_t(t.first.second)] = -t.second / g->leading_coefficient();
    }
  // enclosure widths: below 2^-W, W covering the coefficient size and degree of D (multiple_point_blowup.h
  // enlarges the Taylor coefficients by about their derivatives times the width)
  long bits = 0;
  int deg = 0;
  const Polynomial_2<Integer>& D = E.square_free;
  for (int j = 0; j <= D.degree(); ++j)
    for (int i = 0; !CGAL::is_zero(D[j]) && i <= D[j].degree(); ++i) {
      bits = std::max(bits, long(D[j][i].bit_size()));
      deg = std::max(deg, i + j);
    }
  long qbits = 0;
  for (const Rational& c : q) qbits = std::max(qbits, long(c.numerator().bit_size() + c.denominator().bit_size()));
  const long W = bits + 8L * deg + 128;
  const mpfr_prec_t prec = mpfr_prec_t(W + qbits + 128);
  for (const Isolated_root& root : isolate_real_roots(hu, box.u0, box.u1)) {
    const Algebraic_real& alpha = root.root;
    Rational target = Rational(1);
    for (long k = 0; k < W; k += 32) target /= Rational(Integer(1) << 32);
    Rational width = target;
    Parameter_box K;
    bool ok = false;
    for (int round = 0; round < 8 && !ok; ++round) {
      alpha.refine_to_width(width);
      K.u0 = alpha.lower();
      K.u1 = alpha.upper();
      Mpfi_interval x = Mpfi_interval::hull(K.u0, K.u1, prec), v = Mpfi_interval::point(0, prec);
      for (std::size_t i = q.size(); i-- > 0;) {
        v = v * x;
        mpfi_add_q(v.get(), v.get(), q[i].mpq());
      }
      K.v0 = v.lower();
      K.v1 = v.upper();
      ok = K.v1 - K.v0 <= target;
      if (!ok) width = width * target / (K.v1 - K.v0) / 2;  // v = q(u) is stretched by about |q'(alpha)|
    }
    if (!ok) continue;
    if (!(box.u0 < K.u0 && K.u1 < box.u1 && box.v0 < K.v0 && K.v1 < box.v1)) continue;
    out.push_back(Known_multiple_point{K, int(n)});
  }
  return out;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERNAL_MATRIX_ZERO_POINTS_H
