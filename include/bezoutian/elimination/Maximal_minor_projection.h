// A projection operator for the intersection of two patches when det B vanishes identically: the gcd of maximal
// minors of the Bezoutian matrix (Definition 1 of buse-elkadi-galligo-2008 allows the maximal minors of B).
//
// Why det B can vanish although the locus is a curve. B(u, t) encodes the system Phi(u, v) = Psi(s, t) in the
// partner variables (v, s), of bi-degree (n1, m2) in P^1 x P^1. If the system has a common root for every (u, t)
// (typically at infinity: two orthogonal extrusions (x(u), y(u), v) and (s', y'(s), z'(s)) share the root
// (v, s) = (inf, inf) of their homogenized equations), U of that root is in the kernel of B everywhere: det B = 0.
//
// The operator. Let r < N be the rank of B over Q(u, t) (its generic rank). Where the system has a further root
// y (a finite partner with nonzero weights), U(y) is in the kernel of B(u, t) as well (the proof of Theorems 2-3:
// two columns of formula (2) become proportional), and the kernel, which contains the limit of the generic kernels,
// grows: rank B(u, t) < r, so every r x r minor vanishes there. A compression det(P B Q), P of size r x N and Q of
// size N x r with integer entries, is by Cauchy-Binet a combination of r x r minors, so it vanishes on that locus
// too; the gcd of two compressions whose determinants are nonzero keeps the curve components common to all of them
// and drops the extra factors of each (where P B Q loses rank but B does not). Extra factors that remain are
// phantoms, removed with proofs by the lifting.
//
// The rank is proved, not sampled: every (r + 1)-minor has degree at most (r + 1) d0 in u and (r + 1) d1 in t
// (d0, d1 the largest degrees of the entries), so if rank B <= r at every point of a grid of ((r + 1) d0 + 1) x
// ((r + 1) d1 + 1) points, each (r + 1)-minor vanishes on the grid and is zero; one point of rank r gives the
// other bound.
//
// When the operator applies. If every (u, t) had a finite partner with nonzero weights (two pieces of one surface:
// an overlap region), the generic kernel would already hold it and the operator would miss that region. So the
// affine fibre at two rational points of general position is computed exactly and must be empty, up to roots
// where the weight of the first patch vanishes (not points of the surface): the gcd over pairs of the resultants in
// s of the three cross-multiplied equations, with the factors of that weight removed, is a nonzero constant.
// (A two-dimensional solution set projects onto a dense subset of the (u, t) plane: an empty fibre at a point of
// general position excludes it; two fixed points of small height are used, so this step is not a proof against an
// adversary who places the exceptional curve of the projection through both.)
// What the gcd can lose: points of the rank-drop locus that are isolated in the complex plane (two iso-curves that
// coincide as curves, u = c on Phi and t = c' on Psi); a shared boundary curve of that kind is found exactly by the
// boundary contacts.
#ifndef BEZOUTIAN_ELIMINATION_MAXIMAL_MINOR_PROJECTION_H
#define BEZOUTIAN_ELIMINATION_MAXIMAL_MINOR_PROJECTION_H

#include <bezoutian/algebraic/Polynomial_normalization.h>
#include <bezoutian/algebraic/bivariate_real_solutions.h>
#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/elimination/Implicit_equation.h>
#include <bezoutian/elimination/Polynomial_matrix_determinant.h>
#include <bezoutian/elimination/exact_linear_algebra.h>
#include <bezoutian/elimination/Surface_bezoutian_matrices.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>

#include <CGAL/Polynomial.h>
#include <CGAL/Polynomial_traits_d.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace bezoutian {

/// The generic rank of a Bezoutian matrix over Q(x0, x1), with the size of the grid that proves it.
struct Generic_rank {
  std::size_t rank = 0;
  std::size_t grid_points = 0;  ///< points of the grid on which rank <= `rank` was checked exactly
};

/// How maximal_minor_projection() ended.
struct Maximal_minor_projection {
  bool computed = false;
  Generic_rank rank;
  Polynomial_2<Integer> polynomial;  ///< the gcd of the compressions' determinants, primitive (0 if not computed)
  std::size_t compressions = 0;      ///< determinants of compressions computed
  std::string reason;                ///< why not computed
};

namespace internal {

inline std::vector<std::vector<Rational>> evaluate_matrix_exact(const Bezoutian_matrix& B, const Rational& x0,
                                                                const Rational& x1) {
  std::vector<std::vector<Rational>> A(B.size(), std::vector<Rational>(B.size()));
  for (std::size_t i = 0; i < B.size(); ++i)
    for (std::size_t j = 0; j < B.size(); ++j) A[i][j] = evaluate_exact(B.entries[i][j], x0, x1);
  return A;
}

// Fixed integers in [-9, 9] without zero runs (a linear congruential sequence): the compressions' entries.
inline int compression_entry(std::uint32_t& state) {
  state = state * 1103515245u + 12345u;
  const int x = int((state >> 16) % 19u) - 9;
  return x == 0 ? 1 : x;
}

// P B Q for an r x N matrix P and an N x r matrix Q drawn from `seed`.
inline std::vector<std::vector<Polynomial_2<Rational>>> compressed_matrix(const Bezoutian_matrix& B, std::size_t r,
                                                                          std::uint32_t seed) {
  const std::size_t N = B.size();
  std::vector<std::vector<int>> P(r, std::vector<int>(N)), Q(N, std::vector<int>(r));
  for (auto& row : P)
    for (int& x : row) x = compression_entry(seed);
  for (auto& row : Q)
    for (int& x : row) x = compression_entry(seed);
  std::vector<std::vector<Polynomial_2<Rational>>> BQ(N, std::vector<Polynomial_2<Rational>>(r, Polynomial_2<Rational>(0)));
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t c = 0; c < r; ++c)
      for (std::size_t k = 0; k < N; ++k)
        if (!CGAL::is_zero(B.entries[i][k])) BQ[i][c] += B.entries[i][k] * Polynomial_2<Rational>(Rational(Q[k][c]));
  std::vector<std::vector<Polynomial_2<Rational>>> M(r, std::vector<Polynomial_2<Rational>>(r, Polynomial_2<Rational>(0)));
  for (std::size_t a = 0; a < r; ++a)
    for (std::size_t c = 0; c < r; ++c)
      for (std::size_t i = 0; i < N; ++i) M[a][c] += Polynomial_2<Rational>(Rational(P[a][i])) * BQ[i][c];
  return M;
}

// E_k(v, s) = Phi_k(u0, v) W_Psi(s, t0) - Psi_k(s, t0) W_Phi(u0, v) (inner variable v, outer s), k = 1, 2, 3.
inline std::array<Polynomial_2<Rational>, 3> cross_multiplied_fibre(const std::array<Polynomial_2<Rational>, 4>& f,
                                                                    const std::array<Polynomial_2<Rational>, 4>& g,
                                                                    const Rational& u0, const Rational& t0) {
  auto product = [](const Polynomial_1<Rational>& a, const Polynomial_1<Rational>& b) {  // a(v) b(s)
    std::vector<Polynomial_1<Rational>> rows;
    for (int j = 0; j <= b.degree(); ++j) rows.push_back(a * b[j]);
    return Polynomial_2<Rational>(rows.begin(), rows.end());
  };
  const Polynomial_1<Rational> wf = with_inner_fixed(f[0], u0), wg = with_outer_fixed(g[0], t0);
  std::array<Polynomial_2<Rational>, 3> E;
  for (int k = 1; k <= 3; ++k)
    E[k - 1] = product(with_inner_fixed(f[k], u0), wg) - product(wf, with_outer_fixed(g[k], t0));
  return E;
}

// True if the system E = 0 has no common root (v, s) in C^2 with W_Phi(u0, v) != 0 (see the header).
inline bool fibre_proved_empty(const std::array<Polynomial_2<Rational>, 3>& E, const Polynomial_1<Rational>& w_phi) {
  for (const auto& e : E)
    if (!CGAL::is_zero(e) && e.degree() == 0 && e[0].degree() == 0) return true;  // a nonzero constant
  std::vector<Polynomial_1<Rational>> res;
  for (int a = 0; a < 3; ++a)
    for (int b = a + 1; b < 3; ++b) {
      if (CGAL::is_zero(E[a]) || CGAL::is_zero(E[b])) continue;
      if (E[a].degree() == 0 && E[b].degree() == 0) {
        res.push_back(gcd_of({E[a][0], E[b][0]}));
        continue;
      }
      res.push_back(E[a].degree() == 0 ? Polynomial_1<Rational>(CGAL::ipower(E[a][0], E[b].degree()))
                    : E[b].degree() == 0 ? Polynomial_1<Rational>(CGAL::ipower(E[b][0], E[a].degree()))
                                         : Polynomial_1<Rational>(CGAL::resultant(E[a], E[b])));
    }
  Polynomial_1<Rational> G = gcd_of(res);
  if (CGAL::is_zero(G)) return false;
  // remove the roots of the first patch's weight: E vanishes there for every s with W_Psi(s) = 0
  for (int guard = 0; guard < 64 && G.degree() > 0 && !CGAL::is_zero(w_phi) && w_phi.degree() > 0; ++guard) {
    const Polynomial_1<Rational> c = CGAL::gcd(G, w_phi);
    if (c.degree() <= 0) break;
    G = CGAL::integral_division(G, c);
  }
  return G.degree() == 0;
}

}  // namespace internal

/// \brief The rank of `B` over Q(x0, x1), proved on a grid (see the header); `max_grid_points` bounds the work
/// (Error beyond it).
inline Generic_rank generic_rank(const Bezoutian_matrix& B, std::size_t max_grid_points = 40000) {
  using internal::evaluate_matrix_exact;
  int d0 = 0, d1 = 0;
  for (const auto& row : B.entries)
    for (const auto& e : row) {
      if (CGAL::is_zero(e)) continue;
      d1 = std::max(d1, e.degree());
      for (int j = 0; j <= e.degree(); ++j) d0 = std::max(d0, e[j].degree());
    }
  Generic_rank g;
  g.rank = internal::fraction_free_rank(evaluate_matrix_exact(B, Rational(7, 19), Rational(11, 23)));
  for (bool grown = true; grown;) {
    grown = false;
    if (g.rank == B.size()) return g;
    const std::size_t a = (g.rank + 1) * std::size_t(d0), b = (g.rank + 1) * std::size_t(d1);
    if ((a + 1) * (b + 1) > max_grid_points)
      throw Error("maximal minors: the rank proof needs " + std::to_string((a + 1) * (b + 1)) +
                  " grid points, more than the budget of " + std::to_string(max_grid_points));
    g.grid_points = (a + 1) * (b + 1);
    for (std::size_t i = 0; i <= a && !grown; ++i)
      for (std::size_t j = 0; j <= b && !grown; ++j) {
        const std::size_t r = internal::fraction_free_rank(evaluate_matrix_exact(B, Rational(int(i)), Rational(int(j))));
        if (r > g.rank) {
          g.rank = r;
          grown = true;
        }
      }
  }
  return g;
}

/// \brief D(u, t) for the intersection of `phi` and `psi` from the maximal minors of their Bezoutian matrix `B`
/// (built for the true bi-degrees, det B = 0): see the header for what is proved and when it applies. Not computed
/// (with the reason) when B has full rank, when B = 0, or when the affine fibre at a point of general position is
/// not proved empty (an overlap region, or a solution at every (u, t) that the operator cannot see past).
inline Maximal_minor_projection maximal_minor_projection(const Bezoutian_matrix& B,
                                                         const Rational_bezier_patch<Rational>& phi,
                                                         const Rational_bezier_patch<Rational>& psi) {
  Maximal_minor_projection out;
  const auto f = phi.power_form(), g = psi.power_form();
  const std::array<std::pair<Rational, Rational>, 2> points{{{Rational(7, 19), Rational(11, 23)},
                                                             {Rational(13, 29), Rational(5, 17)}}};
  for (const auto& p : points)
    if (!internal::fibre_proved_empty(internal::cross_multiplied_fibre(f, g, p.first, p.second),
                                      internal::with_inner_fixed(f[0], p.first))) {
      out.reason = "the system Phi(u, v) = Psi(s, t) has a solution at every (u, t) (an overlap of two pieces of "
                   "one surface, or a common component), which maximal minors cannot separate";
      return out;
    }
  out.rank = generic_rank(B);
  if (out.rank.rank == B.size()) {
    out.reason = "B has full rank";
    return out;
  }
  if (out.rank.rank == 0) {
    out.reason = "B vanishes identically";
    return out;
  }
  Polynomial_2<Integer> G(0);
  int stable = 0;
  for (std::uint32_t seed = 1; seed <= 12 && stable < 2; ++seed) {
    const Polynomial_2<Rational> d = polynomial_matrix_determinant(internal::compressed_matrix(B, out.rank.rank, seed));
    ++out.compressions;
    if (CGAL::is_zero(d)) continue;
    const Polynomial_2<Integer> D = normalized_primitive_part(internal::integer_multiple(d));
    if (CGAL::is_zero(G)) {
      G = D;
      continue;
    }
    typename CGAL::Polynomial_traits_d<Polynomial_2<Integer>>::Gcd_up_to_constant_factor gcd;
    const Polynomial_2<Integer> H = normalized_primitive_part(gcd(G, D));
    stable = H == G ? stable + 1 : 0;  // two more compressions that keep the gcd
    G = H;
  }
  if (CGAL::is_zero(G)) {
    out.reason = "every compression of B has a vanishing determinant";
    return out;
  }
  out.polynomial = G;
  out.computed = true;
  return out;
}

}  // namespace bezoutian

#endif  // BEZOUTIAN_ELIMINATION_MAXIMAL_MINOR_PROJECTION_H
