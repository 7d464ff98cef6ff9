// Real solutions in a box of a system of bivariate polynomials over Q, exactly. Every common solution (x, y) has x a
// root of G = gcd_{i<j} Res_y(F_i, F_j) (a resultant vanishes at the first coordinate of a common root); at a
// rational root r of G the y of the solutions are the real roots of gcd_k F_k(r, y). So no root of G in [x0, x1]
// proves that the system has no solution in the box, and when every root of G there is rational the solutions
// are found exactly (each y an Algebraic_real). An irrational root of G in the range leaves the system undecided
// (its fibre would need arithmetic in Q(r)), as does a common factor of the F_k (G = 0, or gcd_k F_k(r, y) = 0).
#ifndef BEZOUTIAN_ALGEBRAIC_BIVARIATE_REAL_SOLUTIONS_H
#define BEZOUTIAN_ALGEBRAIC_BIVARIATE_REAL_SOLUTIONS_H

#include <bezoutian/algebraic/Algebraic_real.h>
#include <bezoutian/algebraic/Root_isolation.h>
#include <bezoutian/arithmetic/exact_text.h>
#include <bezoutian/arithmetic/number_types.h>

#include <CGAL/Polynomial.h>

#include <string>
#include <utility>
#include <vector>

namespace bezoutian {
namespace internal {

using Poly1_Q = Polynomial_1<Rational>;
using Poly2_Q = Polynomial_2<Rational>;

inline Rational evaluate_exact(const Poly1_Q& p, const Rational& x) {
  Rational r(0);
  for (int i = p.degree(); i >= 0; --i) r = r * x + p[i];
  return r;
}

// p(x, y) for p with inner variable x, outer variable y
inline Rational evaluate_exact(const Poly2_Q& p, const Rational& x, const Rational& y) {
  Rational r(0);
  for (int j = p.degree(); j >= 0; --j) r = r * y + evaluate_exact(p[j], x);
  return r;
}

// p(x, .) as a polynomial in the outer variable, and p(., y) in the inner one
inline Poly1_Q with_inner_fixed(const Poly2_Q& p, const Rational& x) {
  std::vector<Rational> c;
  for (int j = 0; j <= p.degree(); ++j) c.push_back(evaluate_exact(p[j], x));
  return Poly1_Q(c.begin(), c.end());
}
inline Poly1_Q with_outer_fixed(const Poly2_Q& p, const Rational& y) {
  Poly1_Q r(Rational(0));
  Rational power(1);
  for (int j = 0; j <= p.degree(); ++j, power *= y) r += p[j] * power;
  return r;
}

inline Poly1_Q gcd_of(const std::vector<Poly1_Q>& ps) {
  Poly1_Q g(Rational(0));
  for (const Poly1_Q& p : ps)
    if (!CGAL::is_zero(p)) g = CGAL::is_zero(g) ? p : Poly1_Q(CGAL::gcd(g, p));
  return g;
}

}  // namespace internal

/// The solutions of bivariate_real_solutions(): `decided` when `points` is proved to be all of them in the box.
struct Bivariate_real_solutions {
  bool decided = false;
  std::vector<std::pair<Rational, Algebraic_real>> points;  ///< (x, y), x rational
  std::string reason;  ///< why not decided
};

/// \brief The real solutions in [x0, x1] x [y0, y1] of F_k(x, y) = 0 for all k (inner variable x, outer y), decided
/// exactly when the first coordinates are rational (see the header).
inline Bivariate_real_solutions bivariate_real_solutions(const std::vector<Polynomial_2<Rational>>& F,
                                                         const Rational& x0, const Rational& x1, const Rational& y0,
                                                         const Rational& y1) {
  using namespace internal;
  Bivariate_real_solutions out;
  std::vector<Poly1_Q> resultants;
  for (std::size_t i = 0; i < F.size(); ++i)
    for (std::size_t j = i + 1; j < F.size(); ++j) {
      if (CGAL::is_zero(F[i]) || CGAL::is_zero(F[j])) continue;
      resultants.push_back(F[i].degree() == 0 && F[j].degree() == 0 ? gcd_of({F[i][0], F[j][0]})
                                                                    : Poly1_Q(CGAL::resultant(F[i], F[j])));
    }
  const Poly1_Q G = gcd_of(resultants);
  if (CGAL::is_zero(G)) {
    out.reason = "the equations have a common factor";
    return out;
  }
  for (const Isolated_root& r : isolate_real_roots(G, x0, x1)) {
    if (!r.root.is_rational()) {
      out.points.clear();
      out.reason = "a first coordinate is irrational (a root of degree " + std::to_string(r.root.polynomial().degree()) + ")";
      return out;
    }
    const Rational x = r.root.rational_value();
    std::vector<Poly1_Q> H;
    for (const Polynomial_2<Rational>& f : F) H.push_back(with_inner_fixed(f, x));
    const Poly1_Q K = gcd_of(H);
    if (CGAL::is_zero(K)) {
      out.points.clear();
      out.reason = "every y is a solution at x = " + io::to_exact_string(x);
      return out;
    }
    for (const Isolated_root& y : isolate_real_roots(K, y0, y1)) out.points.emplace_back(x, y.root);
  }
  out.decided = true;
  return out;
}

}  // namespace bezoutian

#endif  // BEZOUTIAN_ALGEBRAIC_BIVARIATE_REAL_SOLUTIONS_H
