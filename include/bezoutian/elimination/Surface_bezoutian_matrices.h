// Bezoutian matrices for the intersection and self-intersection of parametrized
// surface patches (buse-elkadi-galligo-2008 Theorems 2, 3, 4, 5).
//
// A patch of bi-degree (m, n) is given in homogeneous power form
// phi = (Phi_0, Phi_1, Phi_2, Phi_3), Phi_0 the weight (a nonzero constant for a
// polynomial patch), each Phi_i a Polynomial_2<Rational> in (u, v) (u = inner
// variable, index 0) of degree <= m in u and <= n in v. The matrices have
// entries in Q[u, v] (self-intersection) or Q[u, t] (intersection); their
// determinant is the implicit equation of the projection of the
// (self-)intersection curve of the parameter spaces onto that plane.
#ifndef BEZOUTIAN_ELIMINATION_SURFACE_BEZOUTIAN_MATRICES_H
#define BEZOUTIAN_ELIMINATION_SURFACE_BEZOUTIAN_MATRICES_H

#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/arithmetic/binomial.h>
#include <bezoutian/elimination/Separated_variable_resultants.h>
#include <bezoutian/arithmetic/number_types.h>

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace bezoutian {

/// Which of the seed's formulas builds a surface Bezoutian matrix.
enum class Bezoutian_formula {
  automatic,   ///< polynomial formula when every weight is a nonzero constant, rational otherwise
  polynomial,  ///< Theorem 2 / Theorem 4 (formula (2) on Phi_i - Psi_i); weights must be constant
  rational     ///< Theorem 3 / Theorem 5 (the 4x4 determinant with the weights)
};

/// A square matrix B with entries in Q[p0, p1], the two free parameters named
/// in `variables` (p0 = inner variable, index 0, of Polynomial_2; p1 = outer).
/// With U = ( monomial_variables[0]^i * monomial_variables[1]^j for (i,j) in
/// row_monomials ) and V the same with the variables suffixed by "1" for
/// column_monomials, U * B * V^t is the polynomial of the theorem that built it.
/// The monomials are ordered with j (second exponent) as the outer loop and i
/// as the inner loop: (1,0), (0,1), (1,1) = (l, k, lk) for bi-degree (2,2).
/// Rows and columns use the same list.
struct Bezoutian_matrix {
  std::vector<std::vector<Polynomial_2<Rational>>> entries;  ///< square
  std::vector<std::pair<int, int>> row_monomials;            ///< (i, j) for x0^i x1^j
  std::vector<std::pair<int, int>> column_monomials;         ///< (i, j) for x0_1^i x1_1^j
  std::array<std::string, 2> variables;           ///< free parameters: {"u","v"} or {"u","t"}
  std::array<std::string, 2> monomial_variables;  ///< {"l","k"} (self-intersection) or {"s","v"} (intersection)
  Bezoutian_formula formula = Bezoutian_formula::automatic;  ///< the formula actually used (never automatic)
  std::size_t size() const { return entries.size(); }

  Bezoutian_matrix() = default;
  Bezoutian_matrix(Bezoutian_matrix&&) = default;
  Bezoutian_matrix& operator=(Bezoutian_matrix&&) = default;
  /// A copy holds polynomials of its own (internal::unshared_copy), so that one matrix may be copied from
  /// several threads at once.
  Bezoutian_matrix(const Bezoutian_matrix& o)
      : row_monomials(o.row_monomials), column_monomials(o.column_monomials), variables(o.variables),
        monomial_variables(o.monomial_variables), formula(o.formula) {
    entries.reserve(o.entries.size());
    for (const auto& row : o.entries) {
      entries.emplace_back();
      entries.back().reserve(row.size());
      for (const auto& e : row) entries.back().push_back(internal::unshared_copy(e));
    }
  }
  Bezoutian_matrix& operator=(const Bezoutian_matrix& o) { return *this = Bezoutian_matrix(o); }
};

namespace internal {

using Surface_Q2 = Polynomial_2<Rational>;
using Surface_Q1 = Polynomial_1<Rational>;
using Surface_Z2 = Polynomial_2<Integer>;
using Surface_Z1 = Polynomial_1<Integer>;
template <class NT>
using Grid = std::vector<std::vector<NT>>;  // c[a][b]: coefficient of u^a v^b (or s^a t^b)

// Dense coefficient grid c[a][b] of u^a v^b, of size (m+1) x (n+1); throws if P
// has a larger degree.
inline Grid<Rational> coefficient_grid(const Surface_Q2& p, int m, int n, const char* what) {
  Grid<Rational> c(m + 1, std::vector<Rational>(n + 1, Rational(0)));
  if (CGAL::is_zero(p)) return c;
  if (p.degree() > n) throw Invalid_input(std::string(what) + ": a component exceeds the declared degree in v");
  for (int b = 0; b <= p.degree(); ++b) {
    const Surface_Q1& q = p[b];
    if (CGAL::is_zero(q)) continue;
    if (q.degree() > m) throw Invalid_input(std::string(what) + ": a component exceeds the declared degree in u");
    for (int a = 0; a <= q.degree(); ++a) c[a][b] = q[a];
  }
  return c;
}

// Polynomial_2 from a grid c[a][b] (a = exponent of the inner variable).
template <class NT>
Polynomial_2<NT> from_grid(const Grid<NT>& c) {
  if (c.empty()) return Polynomial_2<NT>(0);
  const std::size_t na = c.size(), nb = c[0].size();
  std::vector<Polynomial_1<NT>> outer;
  for (std::size_t b = 0; b < nb; ++b) {
    std::vector<NT> inner;
    for (std::size_t a = 0; a < na; ++a) inner.push_back(c[a][b]);
    outer.push_back(Polynomial_1<NT>(inner.begin(), inner.end()));
  }
  return Polynomial_2<NT>(outer.begin(), outer.end());
}

// Coefficients (in Z[u,v]) of P(u, v + k) as a polynomial in k, degree <= n.
inline std::vector<Surface_Z2> shift_in_v(const Grid<Integer>& g, int m, int n) {
  const auto binom = binomial_table<Integer>(n);
  std::vector<Surface_Z2> out;
  for (int j = 0; j <= n; ++j) {
    Grid<Integer> c(m + 1, std::vector<Integer>(n + 1, Integer(0)));
    for (int a = 0; a <= m; ++a)
      for (int b = j; b <= n; ++b) c[a][b - j] += binom[b][j] * g[a][b];
    out.push_back(from_grid(c));
  }
  return out;
}

// Coefficients (in Z[u,v]) of P(u + l, v) as a polynomial in l, degree <= m.
inline std::vector<Surface_Z2> shift_in_u(const Grid<Integer>& g, int m, int n) {
  const auto binom = binomial_table<Integer>(m);
  std::vector<Surface_Z2> out;
  for (int i = 0; i <= m; ++i) {
    Grid<Integer> c(m + 1, std::vector<Integer>(n + 1, Integer(0)));
    for (int a = i; a <= m; ++a)
      for (int b = 0; b <= n; ++b) c[a - i][b] += binom[a][i] * g[a][b];
    out.push_back(from_grid(c));
  }
  return out;
}

// Coefficients of P(u, v) as a polynomial in v, each a polynomial in u
// embedded in Z[u, t] (constant in t).
inline std::vector<Surface_Z2> coefficients_in_v(const Grid<Integer>& g, int m, int n) {
  std::vector<Surface_Z2> out;
  for (int b = 0; b <= n; ++b) {
    std::vector<Integer> inner;
    for (int a = 0; a <= m; ++a) inner.push_back(g[a][b]);
    out.push_back(Surface_Z2(Surface_Z1(inner.begin(), inner.end())));
  }
  return out;
}

// Coefficients of Q(s, t) as a polynomial in s, each a polynomial in t
// embedded in Z[u, t] (constant in u).
inline std::vector<Surface_Z2> coefficients_in_s(const Grid<Integer>& g, int m, int n) {
  std::vector<Surface_Z2> out;
  for (int a = 0; a <= m; ++a) {
    std::vector<Surface_Z1> outer;
    for (int b = 0; b <= n; ++b) outer.push_back(Surface_Z1(g[a][b]));
    out.push_back(Surface_Z2(outer.begin(), outer.end()));
  }
  return out;
}

// True when p is a constant; stores it.
inline bool is_constant(const Surface_Q2& p, Rational& value) {
  if (p.degree() > 0 || p[0].degree() > 0) return false;
  value = p[0][0];
  return true;
}

// Validated coefficient grids of a patch.
inline std::array<Grid<Rational>, 4> patch_grids(const std::array<Surface_Q2, 4>& phi, int m, int n,
                                                 const char* what) {
  if (m < 1 || n < 1) throw Invalid_input(std::string(what) + ": bi-degree (m, n) must have m, n >= 1");
  if (CGAL::is_zero(phi[0])) throw Invalid_input(std::string(what) + ": the weight Phi_0 is identically zero");
  std::array<Grid<Rational>, 4> g;
  for (int i = 0; i < 4; ++i) g[i] = coefficient_grid(phi[i], m, n, what);
  return g;
}

inline void divide_grid(Grid<Rational>& g, const Rational& c) {
  for (auto& row : g)
    for (auto& e : row) e /= c;
}

// The grids of one row of the determinants (component i of one or two patches)
// times the lcm L of all their denominators. The Bezoutians are linear in each
// row, so the matrices are computed over Z (much cheaper than over Q) and
// divided by the product of the L's at the end.
inline std::vector<Grid<Integer>> clear_denominators(const std::vector<const Grid<Rational>*>& grids, Integer& L) {
  // Only value arithmetic on Gmpz: its handles share representations on copy.
  L = Integer(1);
  for (const auto* g : grids)
    for (const auto& row : *g)
      for (const auto& q : row) {
        const Integer d = q.denominator();
        if (d != Integer(1)) L = (L / CGAL::gcd(L, d)) * d;
      }
  std::vector<Grid<Integer>> out;
  for (const auto* g : grids) {
    Grid<Integer> z;
    for (const auto& row : *g) {
      std::vector<Integer> zr;
      for (const auto& q : row) zr.push_back((L / q.denominator()) * q.numerator());
      z.push_back(std::move(zr));
    }
    out.push_back(std::move(z));
  }
  return out;
}

inline Surface_Q2 scaled_to_rational(const Surface_Z2& p, const Rational& factor) {
  std::vector<Surface_Q1> outer;
  for (const Surface_Z1& q : p) {
    std::vector<Rational> inner;
    for (const Integer& c : q) inner.push_back(Rational(c) * factor);
    outer.push_back(Surface_Q1(inner.begin(), inner.end()));
  }
  return Surface_Q2(outer.begin(), outer.end());
}

inline Bezoutian_matrix to_surface_matrix(Separated_bezoutian_matrix<Surface_Z2>&& s, const Rational& factor,
                                          std::array<std::string, 2> variables,
                                          std::array<std::string, 2> monomial_variables,
                                          Bezoutian_formula formula) {
  // The separated matrices list (a, b) for x^a y^b with a outer; the surface
  // matrices name (i, j) = (b, a) for y^i x^j, so the order is already j outer.
  Bezoutian_matrix out;
  for (const auto& p : s.row_monomials) out.row_monomials.emplace_back(p.second, p.first);
  for (const auto& p : s.column_monomials) out.column_monomials.emplace_back(p.second, p.first);
  out.entries.reserve(s.entries.size());
  for (const auto& row : s.entries) {
    std::vector<Surface_Q2> r;
    r.reserve(row.size());
    for (const auto& e : row) r.push_back(scaled_to_rational(e, factor));
    out.entries.push_back(std::move(r));
  }
  out.variables = variables;
  out.monomial_variables = monomial_variables;
  out.formula = formula;
  return out;
}

} // namespace internal

/// Self-intersection matrix B(u, v) of a patch of bi-degree (m, n), of size
/// (mn-1) x (mn-1), indexed by U = [l^i k^j, i < m, j < n, (i,j) != (0,0)].
///  - Theorem 4 (polynomial formula): U B V^t = Bez_{P1,P2,P3}(k, l; k1, l1), formula (2)
///    with the variables in the order (k, l), P_i = Phi_i(u, v+k) - Phi_i(u+l, v)
///    (Phi_i divided by the constant weight).
///  - Theorem 5 (rational formula): U B V^t = the 4x4 determinant with columns
///    Phi(u,v+k), Phi(u,v+k1), Phi(u+l,v), Phi(u+l1,v), divided by (k-k1)(l-l1)
///    (computed exactly by the column operations that make the divided
///    differences explicit). For Phi_0 = 1 it equals -(Theorem 4's matrix).
/// `formula` = automatic uses Theorem 4 when Phi_0 is a nonzero constant and
/// Theorem 5 otherwise; polynomial with a non-constant weight throws Invalid_input.
/// det B(u, v) is the equation of the projection onto (u, v) of the double-point
/// locus, defined up to a constant factor. For m = n = 1 the matrix is empty
/// (determinant 1: a bilinear patch has no self-intersection curve).
/// Throws Invalid_input if m < 1, n < 1, Phi_0 == 0 or a component exceeds the bi-degree.
inline Bezoutian_matrix self_intersection_matrix(const std::array<Polynomial_2<Rational>, 4>& phi, int m, int n,
                                                 Bezoutian_formula formula = Bezoutian_formula::automatic) {
  const char* what = "self_intersection_matrix";
  auto g = internal::patch_grids(phi, m, n, what);
  Rational w;
  const bool constant_weight = internal::is_constant(phi[0], w);
  if (formula == Bezoutian_formula::automatic)
    formula = constant_weight ? Bezoutian_formula::polynomial : Bezoutian_formula::rational;
  if (formula == Bezoutian_formula::polynomial) {
    if (!constant_weight)
      throw Invalid_input("self_intersection_matrix: the polynomial formula needs a constant weight Phi_0");
    // P_i = f_i(k) - g_i(l), f_i(k) = Phi_i(u, v+k) (degree n), g_i(l) = Phi_i(u+l, v) (degree m);
    // both have constant term Phi_i(u, v): the residual case, Theorem 9 with x = k, y = l.
    std::array<std::vector<internal::Surface_Z2>, 3> f, gl;
    Rational factor(1);
    for (int i = 0; i < 3; ++i) {
      internal::divide_grid(g[i + 1], w);
      Integer L;
      const auto z = internal::clear_denominators({&g[i + 1]}, L);
      factor /= Rational(L);
      f[i] = internal::shift_in_v(z[0], m, n);
      gl[i] = internal::shift_in_u(z[0], m, n);
    }
    return internal::to_surface_matrix(residual_separated_bezoutian_matrix(f, gl, n, m), factor, {"u", "v"},
                                       {"l", "k"}, Bezoutian_formula::polynomial);
  }
  // Theorem 5: phi_i(k) = Phi_i(u, v+k), psi_i(l) = Phi_i(u+l, v); U B V^t = det[phi, Dphi, psi, Dpsi]
  // = -(Theorem 14's Bez').
  std::array<std::vector<internal::Surface_Z2>, 4> f, gl;
  Rational factor(-1);
  for (int i = 0; i < 4; ++i) {
    Integer L;
    const auto z = internal::clear_denominators({&g[i]}, L);
    factor /= Rational(L);
    f[i] = internal::shift_in_v(z[0], m, n);
    gl[i] = internal::shift_in_u(z[0], m, n);
  }
  return internal::to_surface_matrix(residual_determinantal_bezoutian_matrix(f, gl, n, m), factor, {"u", "v"},
                                     {"l", "k"}, Bezoutian_formula::rational);
}

/// Intersection matrix B(u, t) of the patches Phi(u, v) and Psi(s, t), both of
/// bi-degree (m, n), of size mn x mn, indexed by U = [s^i v^j, i < m, j < n].
///  - Theorem 2 (polynomial formula): U B V^t = Bez of Phi_i(u,v) - Psi_i(s,t), i = 1..3,
///    formula (2) with the variables in the order (v, s) (weights divided out).
///  - Theorem 3 (rational formula): U B V^t = the 4x4 determinant with columns
///    Phi(u,v), Phi(u,v1), Psi(s,t), Psi(s1,t), divided by (v-v1)(s-s1). For
///    Phi_0 = Psi_0 = 1 it equals -(Theorem 2's matrix).
/// `formula` = automatic uses Theorem 2 when both weights are nonzero constants.
/// det B(u, t) is the equation of the projection onto (u, t) of the intersection
/// curve of the parameter spaces, up to a constant factor.
/// Throws Invalid_input as self_intersection_matrix does.
inline Bezoutian_matrix intersection_matrix(const std::array<Polynomial_2<Rational>, 4>& phi, int m1, int n1,
                                            const std::array<Polynomial_2<Rational>, 4>& psi, int m2, int n2,
                                            Bezoutian_formula formula = Bezoutian_formula::automatic) {
  // Only the degree n = n1 of Phi in v and m = m2 of Psi in s shape the matrix (Theorem 7 with x = v, y = s);
  // the degrees of Phi in u and of Psi in t are free (they are the parameters of the projection).
  const char* what = "intersection_matrix";
  auto gphi = internal::patch_grids(phi, m1, n1, what);
  auto gpsi = internal::patch_grids(psi, m2, n2, what);
  const int n = n1, m = m2;
  Rational w_phi, w_psi;
  const bool constant_weights = internal::is_constant(phi[0], w_phi) && internal::is_constant(psi[0], w_psi);
  if (formula == Bezoutian_formula::automatic)
    formula = constant_weights ? Bezoutian_formula::polynomial : Bezoutian_formula::rational;
  if (formula == Bezoutian_formula::polynomial) {
    if (!constant_weights)
      throw Invalid_input("intersection_matrix: the polynomial formula needs constant weights Phi_0, Psi_0");
    // P_i = f_i(v) - g_i(s), f_i(v) = Phi_i(u, v) over Q[u] (degree n), g_i(s) = Psi_i(s, t)
    // over Q[t] (degree m): Theorem 7 with x = v, y = s.
    std::array<std::vector<internal::Surface_Z2>, 3> f, gs;
    Rational factor(1);
    for (int i = 0; i < 3; ++i) {
      internal::divide_grid(gphi[i + 1], w_phi);
      internal::divide_grid(gpsi[i + 1], w_psi);
      Integer L;
      const auto z = internal::clear_denominators({&gphi[i + 1], &gpsi[i + 1]}, L);
      factor /= Rational(L);
      f[i] = internal::coefficients_in_v(z[0], m1, n1);
      gs[i] = internal::coefficients_in_s(z[1], m2, n2);
    }
    return internal::to_surface_matrix(dense_separated_bezoutian_matrix(f, gs, n, m), factor, {"u", "t"},
                                       {"s", "v"}, Bezoutian_formula::polynomial);
  }
  // Theorem 3: U B V^t = det[phi, Dphi, psi, Dpsi] = -(Theorem 12's Bez').
  std::array<std::vector<internal::Surface_Z2>, 4> f, gs;
  Rational factor(-1);
  for (int i = 0; i < 4; ++i) {
    Integer L;
    const auto z = internal::clear_denominators({&gphi[i], &gpsi[i]}, L);
    factor /= Rational(L);
    f[i] = internal::coefficients_in_v(z[0], m1, n1);
    gs[i] = internal::coefficients_in_s(z[1], m2, n2);
  }
  return internal::to_surface_matrix(dense_determinantal_bezoutian_matrix(f, gs, n, m), factor, {"u", "t"},
                                     {"s", "v"}, Bezoutian_formula::rational);
}

/// Both patches of bi-degree (m, n): the mn x mn matrix of Theorems 2 and 3.
inline Bezoutian_matrix intersection_matrix(const std::array<Polynomial_2<Rational>, 4>& phi,
                                            const std::array<Polynomial_2<Rational>, 4>& psi, int m, int n,
                                            Bezoutian_formula formula = Bezoutian_formula::automatic) {
  return intersection_matrix(phi, m, n, psi, m, n, formula);
}

} // namespace bezoutian

#endif // BEZOUTIAN_ELIMINATION_SURFACE_BEZOUTIAN_MATRICES_H
