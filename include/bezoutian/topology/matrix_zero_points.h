// Points where the whole Bezoutian matrix vanishes: multiple points of the implicit equation.
//
// If every entry of the n x n matrix B vanishes at p, every entry lies in the maximal ideal of p, so
// det B (a sum of products of n entries) vanishes to order >= n there: p is a point of multiplicity >= n of
// D = det B. For patches of bi-degree (2, 2) the 3 x 3 self-intersection matrix of Theorems 4-5 vanishes at finitely
// many points (16 for the worked example of buse-elkadi-galligo-2008 §4, 20 for rational patches), and the triple
// point of §4 near (-1.05, -0.049) is one of them. They are found exactly: the reduced lexicographic Groebner basis
// of two entries (certified multi-modular algorithm, Groebner_bivariate.h) is, in general position,
// {h(u), v - q(u)}; the common zeros of all entries are (alpha, q(alpha)) over the real roots alpha of the gcd of h
// and of the numerators of e(u, q(u)) for every entry e, isolated exactly and enclosed in boxes small enough for
// the Taylor coefficients of D there (topology/internal/multiple_point_blowup.h). Everything is univariate or modular: no
// exact Buchberger run, whose coefficient growth made 32-bit inputs take minutes.
#ifndef BEZOUTIAN_TOPOLOGY_MATRIX_ZERO_POINTS_H
#define BEZOUTIAN_TOPOLOGY_MATRIX_ZERO_POINTS_H

#include <bezoutian/topology/Curve_topology_by_subdivision.h>
#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/elimination/Groebner_bivariate.h>
#include <bezoutian/elimination/Implicit_equation.h>
#include <bezoutian/algebraic/Root_isolation.h>

#include <mpfi.h>

#include <algorithm>
#include <vector>

namespace bezoutian {
namespace internal {

/// The common zeros of all entries of E.matrix strictly inside `box`, as multiple points of E.square_free of
/// multiplicity >= n (n = matrix size), each in a small enclosure that holds no other common zero. Empty when the
/// matrix is larger than `max_size` (the Groebner basis would cost more than it saves), when D is not square-free
/// (its square-free part may then have a lower multiplicity), or when no pair of entries has a basis of the form
/// {h(u), v - q(u)} within `max_primes` word primes, or when q's coefficients exceed `max_q_bits` bits (inputs
/// with 32-bit rational coordinates: their entries have 2000-bit coefficients, q 28000-bit ones, and the exact
/// filtering would take seconds): the subdivision then works without them (and a triple point stops it).
inline std::vector<Known_multiple_point> matrix_zero_points(const Implicit_equation& E, const Parameter_box& box,
                                                            std::size_t max_size = 3, std::size_t max_primes = 100,
                                                            long max_q_bits = 8000) {
  std::vector<Known_multiple_point> out;
  const std::size_t n = E.matrix.size();
  if (n < 2 || n > max_size || E.is_degenerate() || E.determinant != E.square_free) return out;
  std::vector<Polynomial_2<Rational>> F;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (!CGAL::is_zero(E.matrix.entries[i][j])) F.push_back(E.matrix.entries[i][j]);
  if (F.size() < 2) return out;
  // The basis of two entries by the certified multi-modular algorithm (two equations: its dimension count is
  // available; no exact fallback, whose coefficient growth is unbounded on large inputs), in shape position
  // {h(u), c v + r(u)}: then the common zeros of all entries are (alpha, q(alpha)), q = -r / c, over the common
  // roots alpha of h and of every entry e(u, q(u)) (numerator cleared).
  Polynomial_1<Rational> hq;
  std::vector<Rational> q;  // v = q(u)
  for (std::size_t a = 0; a + 1 < F.size() && q.empty(); ++a) {
    std::vector<Lex_polynomial_2> G;
    try {
      G = modular_lex_groebner_basis(std::vector<Polynomial_2<Rational>>{F[a], F[a + 1]}, nullptr, 0, max_primes);
    } catch (const Error&) {
      continue;
    }
    const Lex_polynomial_2* h = nullptr;
    const Lex_polynomial_2* g = nullptr;
    for (const auto& p : G) {
      if (p.is_univariate_in_s()) h = &p;
      else if (p.leading_monomial() == Lex_polynomial_2::Monomial{1, 0}) g = &p;
    }
    if (G.size() != 2 || !h || !g) continue;
    hq = h->to_univariate();
    for (const auto& t : g->terms())
      if (t.first.first == 0) {
        if (q.size() <= std::size_t(t.first.second)) q.resize(std::size_t(t.first.second) + 1, Rational(0));
        q[std::size_t(t.first.second)] = -t.second / g->leading_coefficient();
      }
    if (q.empty()) q.push_back(Rational(0));
  }
  if (q.empty() || hq.degree() < 1) return out;
  long qbits = 0;
  for (const Rational& c : q) qbits = std::max(qbits, long(c.numerator().bit_size() + c.denominator().bit_size()));
  if (qbits > max_q_bits) return out;  // e(u, q(u)) would cost seconds: huge inputs go without
  // integer forms: h, and q = Q / d
  auto integer_form = [](const std::vector<Rational>& c, Integer& den) {
    den = Integer(1);
    for (const Rational& x : c) den = den / CGAL::gcd(den, x.denominator()) * x.denominator();
    std::vector<Integer> z;
    for (const Rational& x : c) z.push_back(CGAL::integral_division(x.numerator() * den, x.denominator()));
    return Polynomial_1<Integer>(z.begin(), z.end());
  };
  Integer d, unused;  // q's common denominator; h's is irrelevant (only its roots matter)
  std::vector<Rational> hc;
  for (int i = 0; i <= hq.degree(); ++i) hc.push_back(hq[i]);
  Polynomial_1<Integer> common = integer_form(hc, unused);
  const Polynomial_1<Integer> Qz = integer_form(q, d);
  for (const auto& e : F) {
    // d^(deg_v e) e(u, Q/d) = sum_j e_j(u) Q^j d^(deg_v e - j), with e's denominators cleared
    Polynomial_1<Integer> P(0), Qpow(1);
    Integer eden(1);  // common denominator of all coefficients of e
    for (int j = 0; j <= e.degree(); ++j)
      for (int i = 0; !CGAL::is_zero(e[j]) && i <= e[j].degree(); ++i)
        eden = eden / CGAL::gcd(eden, e[j][i].denominator()) * e[j][i].denominator();
    for (int j = 0; j <= e.degree(); ++j) {
      std::vector<Integer> ez;
      for (int i = 0; !CGAL::is_zero(e[j]) && i <= e[j].degree(); ++i)
        ez.push_back(CGAL::integral_division(e[j][i].numerator() * eden, e[j][i].denominator()));
      if (!ez.empty())
        P += Polynomial_1<Integer>(ez.begin(), ez.end()) * Qpow * Polynomial_1<Integer>(CGAL::ipower(d, e.degree() - j));
      Qpow *= Qz;
    }
    if (CGAL::is_zero(P)) continue;
    common = CGAL::gcd(common, P);
    if (common.degree() < 1) return out;
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
  const long W = bits + 8L * deg + 128;
  const mpfr_prec_t prec = mpfr_prec_t(W + qbits + 128);
  for (const Isolated_root& root : isolate_real_roots(common, box.u0, box.u1)) {
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

#endif  // BEZOUTIAN_TOPOLOGY_MATRIX_ZERO_POINTS_H
