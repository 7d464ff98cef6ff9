// The implicit equation D of the projected (self-)intersection locus of rational Bezier patches:
// the determinant of the Bezoutian matrix of buse-elkadi-galligo-2008 Theorems 2-5, exact, primitive,
// sign-normalized, with its square-free part.
#ifndef BEZOUTIAN_ELIMINATION_IMPLICIT_EQUATION_H
#define BEZOUTIAN_ELIMINATION_IMPLICIT_EQUATION_H

#include <bezoutian/elimination/Polynomial_matrix_determinant.h>
#include <bezoutian/algebraic/Polynomial_normalization.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>
#include <bezoutian/elimination/Surface_bezoutian_matrices.h>

#include <algorithm>
#include <array>
#include <string>
#include <tuple>
#include <vector>

namespace bezoutian {

/// \brief D(p0, p1) = det B(p0, p1) for the self-intersection (p0, p1) = (u, v) or the intersection
/// (p0, p1) = (u, t) problem, with the matrix it came from.
struct Implicit_equation {
  Bezoutian_matrix matrix;
  // The polynomials start as zeros of their own: a default-constructed CGAL::Polynomial shares the constructing
  // thread's default instance, whose plain reference count another thread would change when it assigns a result
  // to an equation made here (intersect_model fills results made by the calling thread on worker threads).
  /// det B divided by its integer content, lexicographically leading term positive (0 if det B == 0).
  Polynomial_2<Integer> determinant = Polynomial_2<Integer>(0);
  /// The square-free part of `determinant`, normalized the same way: the curve D = 0 without multiplicities.
  Polynomial_2<Integer> square_free = Polynomial_2<Integer>(0);
  std::array<std::string, 2> variables;
  /// Where D comes from: det B, or, where det B vanishes identically, the gcd of maximal minors of B
  /// (elimination/Maximal_minor_projection.h), whose kernel is then never a single line.
  enum class Route { determinant, maximal_minors };
  Route route = Route::determinant;
  /// The rank of B over Q(p0, p1), proved (Route::maximal_minors); the matrix size otherwise.
  std::size_t generic_rank = 0;

  Implicit_equation() = default;
  Implicit_equation(Implicit_equation&&) = default;
  Implicit_equation& operator=(Implicit_equation&&) = default;
  /// A copy holds polynomials of its own (internal::unshared_copy), so that one equation, and the locus holding
  /// it, may be copied from several threads at once.
  Implicit_equation(const Implicit_equation& o)
      : matrix(o.matrix), determinant(internal::unshared_copy(o.determinant)),
        square_free(internal::unshared_copy(o.square_free)), variables(o.variables), route(o.route),
        generic_rank(o.generic_rank) {}
  Implicit_equation& operator=(const Implicit_equation& o) { return *this = Implicit_equation(o); }

  /// True if det B vanishes identically: the locus is not a curve in the (p0,p1) plane (e.g. identical or
  /// overlapping patches, or an input that is not "sufficiently generic" in the sense of Theorems 2-5).
  bool is_degenerate() const { return CGAL::is_zero(determinant); }
  int degree(int variable) const { return degree_of(determinant, variable); }
  int total_degree() const {
    int d = -1;
    for_each_term([&](int i, int j, const Integer&) { d = std::max(d, i + j); });
    return d;
  }
  /// Terms (i, j, c) of c p0^i p1^j of `determinant`, by increasing j then i.
  std::vector<std::tuple<int, int, Integer>> terms() const {
    std::vector<std::tuple<int, int, Integer>> t;
    for_each_term([&](int i, int j, const Integer& c) { t.emplace_back(i, j, c); });
    return t;
  }

  static int degree_of(const Polynomial_2<Integer>& D, int variable) {
    if (CGAL::is_zero(D)) return -1;
    if (variable == 1) return D.degree();
    int d = 0;
    for (int j = 0; j <= D.degree(); ++j)
      if (!CGAL::is_zero(D[j])) d = std::max(d, D[j].degree());
    return d;
  }

 private:
  template <class F>
  void for_each_term(F f) const {
    if (CGAL::is_zero(determinant)) return;
    for (int j = 0; j <= determinant.degree(); ++j)
      for (int i = 0; i <= determinant[j].degree(); ++i)
        if (!CGAL::is_zero(determinant[j][i])) f(i, j, determinant[j][i]);
  }
};

namespace internal {
// An integer multiple of a rational bivariate polynomial (denominators cleared by their lcm).
inline Polynomial_2<Integer> integer_multiple(const Polynomial_2<Rational>& q) {
  Integer L(1);
  for (int j = 0; j <= q.degree(); ++j)
    for (int i = 0; i <= q[j].degree(); ++i) {
      const Integer d = q[j][i].denominator();
      L = L / CGAL::gcd(L, d) * d;
    }
  std::vector<Polynomial_1<Integer>> outer;
  for (int j = 0; j <= q.degree(); ++j) {
    std::vector<Integer> c;
    for (int i = 0; i <= q[j].degree(); ++i) c.push_back(q[j][i].numerator() * (L / q[j][i].denominator()));
    outer.emplace_back(c.begin(), c.end());
  }
  return Polynomial_2<Integer>(outer.begin(), outer.end());
}

inline Implicit_equation finish_implicit_equation(Bezoutian_matrix&& B) {
  Implicit_equation e;
  e.variables = B.variables;
  e.generic_rank = B.size();
  e.matrix = std::move(B);
  e.determinant = normalized_primitive_part(integer_multiple(polynomial_matrix_determinant(e.matrix.entries)));
  e.square_free = CGAL::is_zero(e.determinant) ? e.determinant : normalized_square_free_part(e.determinant);
  return e;
}
} // namespace internal

namespace internal {
// Actual bi-degree of a power form (the largest degrees in u and v over the four components): a
// degree-elevated Bernstein net has a smaller true degree, and Theorems 2-5 need the true one
// (a declared degree with a vanishing leading coefficient makes det B vanish identically).
inline std::pair<int, int> actual_bidegree(const std::array<Polynomial_2<Rational>, 4>& f) {
  int m = 0, n = 0;
  for (const auto& q : f) {
    if (CGAL::is_zero(q)) continue;
    n = std::max(n, q.degree());
    for (int b = 0; b <= q.degree(); ++b)
      if (!CGAL::is_zero(q[b])) m = std::max(m, q[b].degree());
  }
  return {m, n};
}
} // namespace internal

/// Implicit equation D(u,v) of the projection onto the (u,v) plane of the double-point locus of `patch`
/// (Theorem 4 when the weights are equal, Theorem 5 otherwise): matrix of size mn - 1 for the true
/// bi-degree (m,n) of the patch. If det B vanishes identically the locus is not a curve of this projection
/// (is_degenerate()); no change of the 3D coordinates can help: the Bezoutian is an alternating multilinear form
/// in the three coordinate equations, so mixing them by an invertible matrix A multiplies every entry of B by
/// det A. Patches of degree 0 in u or v: Invalid_input.
inline Implicit_equation self_intersection_equation(const Rational_bezier_patch<Rational>& patch,
                                                    Bezoutian_formula formula = Bezoutian_formula::automatic) {
  const auto f = patch.power_form();
  const auto d = internal::actual_bidegree(f);
  if (d.first < 1 || d.second < 1)
    throw Invalid_input("self-intersection: the patch has degree 0 in u or v (it is a curve or a point)");
  return internal::finish_implicit_equation(self_intersection_matrix(f, d.first, d.second, formula));
}

/// Implicit equation D(u,t) of the projection onto the (u,t) plane of the intersection curve of the
/// patches Phi(u,v) and Psi(s,t) (Theorem 2 / Theorem 3): for true bi-degrees (m1,n1) and (m2,n2) the
/// matrix has size m2 n1 (Theorem 7 with f of degree n1 in v and g of degree m2 in s). As for
/// self_intersection_equation, a determinant that vanishes identically does so in every coordinate system.
inline Implicit_equation intersection_equation(const Rational_bezier_patch<Rational>& phi,
                                               const Rational_bezier_patch<Rational>& psi,
                                               Bezoutian_formula formula = Bezoutian_formula::automatic) {
  const auto f = phi.power_form(), g = psi.power_form();
  const auto a = internal::actual_bidegree(f), b = internal::actual_bidegree(g);
  if (a.second < 1 || b.first < 1)
    throw Invalid_input("intersection: the first patch has degree 0 in v or the second degree 0 in s");
  const int m1 = std::max(a.first, 1), n1 = a.second, m2 = b.first, n2 = std::max(b.second, 1);
  return internal::finish_implicit_equation(intersection_matrix(f, m1, n1, g, m2, n2, formula));
}

} // namespace bezoutian

#endif // BEZOUTIAN_ELIMINATION_IMPLICIT_EQUATION_H
