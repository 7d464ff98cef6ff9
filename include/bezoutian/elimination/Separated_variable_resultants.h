// Bezoutian matrices of systems with separated variables
// (buse-elkadi-galligo-2008 §5 and §6):
//   Theorem 7  (dense):               P_i = f_i(x) - g_i(y), i = 1..3            -> mn x mn
//   Theorem 9  (residual):            same with f_i(0) = g_i(0)                   -> (mn-1) x (mn-1)
//   Theorem 12 (determinantal dense): phi_i(x) = lambda psi_i(y), i = 0..3         -> mn x mn
//   Theorem 14 (determinantal resid.):same with phi_i(0) = psi_i(0)               -> (mn-1) x (mn-1)
// deg f_i, phi_i <= m (variable x), deg g_i, psi_i <= n (variable y). The
// coefficients lie in any commutative ring R (e.g. Rational, or
// Polynomial_2<Rational> when they depend on two free parameters).
//
// The Bezoutians are computed without expanding a multivariate determinant:
// every column of the determinants in §5.1 / §6.1 depends either on (x, x1) or
// on (y, y1) only, so a Laplace expansion splits them into sums of products
// X(x, x1) * Y(y, y1), and each product fills the matrix as an outer product.
#ifndef BEZOUTIAN_ELIMINATION_SEPARATED_VARIABLE_RESULTANTS_H
#define BEZOUTIAN_ELIMINATION_SEPARATED_VARIABLE_RESULTANTS_H

#include <bezoutian/arithmetic/Error.h>

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace bezoutian {

/// Bezoutian matrix of a system with separated variables. With
/// U = (x^a y^b for (a,b) in row_monomials) and V = (x1^a y1^b for (a,b) in
/// column_monomials), U * entries * V^t is the Bezoutian polynomial. The
/// monomials (a,b) are listed with a (exponent of x) as the outer loop and b
/// (exponent of y) as the inner loop; rows and columns use the same list.
template <class R>
struct Separated_bezoutian_matrix {
  std::vector<std::vector<R>> entries;
  std::vector<std::pair<int, int>> row_monomials;     ///< (a, b) for x^a y^b
  std::vector<std::pair<int, int>> column_monomials;  ///< (a, b) for x1^a y1^b
  std::size_t size() const { return entries.size(); }
};

namespace internal {

// Coefficients of a univariate polynomial, lowest degree first, padded to
// degree d (length d+1). Throws if the polynomial has a nonzero coefficient of
// degree > d.
template <class R>
std::vector<R> padded_coefficients(const std::vector<R>& p, int d, const char* what) {
  std::vector<R> c(static_cast<std::size_t>(d) + 1, R(0));
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (static_cast<int>(i) > d) {
      if (!(p[i] == R(0)))
        throw Invalid_input(std::string(what) + ": a polynomial exceeds its declared degree");
    } else {
      c[i] = p[i];
    }
  }
  return c;
}

// Divided difference (p(x) - p(x1)) / (x - x1) as a d x d Hankel array
// H[a][a1] = p_{a+a1+1} (coefficient of x^a x1^a1), d = declared degree.
template <class R>
std::vector<std::vector<R>> divided_difference_array(const std::vector<R>& p, int d) {
  std::vector<std::vector<R>> h(d, std::vector<R>(d, R(0)));
  for (int a = 0; a < d; ++a)
    for (int a1 = 0; a1 < d; ++a1)
      if (a + a1 + 1 <= d) h[a][a1] = p[a + a1 + 1];
  return h;
}

// p_r(x) H_s(x, x1) - p_s(x) H_r(x, x1), truncated to x-degree < d. The
// truncation is exact for the sums formed below: the Bezoutians have degree
// < d in x (seed §5.1/§6.1: their x-support equals their x1-support by symmetry).
template <class R>
std::vector<std::vector<R>> wedge_array(const std::vector<R>& pr, const std::vector<std::vector<R>>& hs,
                                        const std::vector<R>& ps, const std::vector<std::vector<R>>& hr, int d) {
  std::vector<std::vector<R>> w(d, std::vector<R>(d, R(0)));
  for (int a = 0; a < d; ++a)
    for (int a1 = 0; a1 < d; ++a1)
      for (int p = 0; p <= a; ++p) {
        const std::vector<R>& hs_row = hs[a - p];
        const std::vector<R>& hr_row = hr[a - p];
        if (!(pr[p] == R(0)) && !(hs_row[a1] == R(0))) w[a][a1] += pr[p] * hs_row[a1];
        if (!(ps[p] == R(0)) && !(hr_row[a1] == R(0))) w[a][a1] -= ps[p] * hr_row[a1];
      }
  return w;
}

// Accumulates sign * X(x,x1) (x) Y(y,y1) into the full mn x mn matrix indexed by
// (a,b) -> a*n + b.
template <class R>
void add_outer_product(std::vector<std::vector<R>>& b, bool negative, const std::vector<std::vector<R>>& x,
                       const std::vector<std::vector<R>>& y, int m, int n) {
  for (int a = 0; a < m; ++a)
    for (int a1 = 0; a1 < m; ++a1) {
      if (x[a][a1] == R(0)) continue;
      for (int c = 0; c < n; ++c)
        for (int c1 = 0; c1 < n; ++c1) {
          if (y[c][c1] == R(0)) continue;
          R t = x[a][a1] * y[c][c1];
          if (negative) b[a * n + c][a1 * n + c1] -= t; else b[a * n + c][a1 * n + c1] += t;
        }
    }
}

template <class R>
Separated_bezoutian_matrix<R> finish_separated(std::vector<std::vector<R>>&& full, int m, int n, bool residual) {
  Separated_bezoutian_matrix<R> out;
  const std::size_t first = residual ? 1 : 0;  // index 0 is the monomial 1 = x^0 y^0
  for (int a = 0; a < m; ++a)
    for (int b = 0; b < n; ++b)
      if (!(residual && a == 0 && b == 0)) out.row_monomials.emplace_back(a, b);
  out.column_monomials = out.row_monomials;
  for (std::size_t i = first; i < full.size(); ++i)
    out.entries.emplace_back(std::make_move_iterator(full[i].begin() + first),
                             std::make_move_iterator(full[i].end()));
  return out;
}

inline void check_degrees(int m, int n, const char* what) {
  if (m < 1 || n < 1) throw Invalid_input(std::string(what) + ": degrees m and n must be at least 1");
}

// The matrix of -det[ f - g, Df, Dg ] (rows i = 0..2), i.e. Bez_{P1,P2,P3}(x,y; x1,y1)
// of formula (2) with the variables in the order (x, y) (seed §5.1).
template <class R>
std::vector<std::vector<R>> separated_bezoutian_full(const std::array<std::vector<R>, 3>& f_in,
                                                     const std::array<std::vector<R>, 3>& g_in, int m, int n,
                                                     const char* what) {
  check_degrees(m, n, what);
  std::array<std::vector<R>, 3> f, g;
  std::array<std::vector<std::vector<R>>, 3> df, dg;
  for (int i = 0; i < 3; ++i) {
    f[i] = padded_coefficients(f_in[i], m, what);
    g[i] = padded_coefficients(g_in[i], n, what);
    df[i] = divided_difference_array(f[i], m);
    dg[i] = divided_difference_array(g[i], n);
  }
  std::vector<std::vector<R>> full(m * n, std::vector<R>(m * n, R(0)));
  // det[f - g, Df, Dg] = sum_{r<s, c the third row} (-1)^{r+s+1} (Xf_{rs} (x) Dg_c + Df_c (x) Yg_{rs}),
  // Xf_{rs} = f_r Df_s - f_s Df_r, Yg_{rs} = g_r Dg_s - g_s Dg_r (Laplace expansion on the
  // columns {0,1} of det[f, Df, Dg] and {0,2} of det[g, Df, Dg]). Bez = -det.
  const int pairs[3][3] = {{0, 1, 2}, {0, 2, 1}, {1, 2, 0}};
  for (const auto& p : pairs) {
    const int r = p[0], s = p[1], c = p[2];
    const bool negative = (r + s) % 2 != 0;  // sign of -(-1)^{r+s+1} = (-1)^{r+s}
    add_outer_product(full, negative, wedge_array(f[r], df[s], f[s], df[r], m), dg[c], m, n);
    add_outer_product(full, negative, df[c], wedge_array(g[r], dg[s], g[s], dg[r], n), m, n);
  }
  return full;
}

// The matrix of det[ phi, Dphi, psi, Dpsi ] (rows i = 0..3): the 4x4 determinant of
// Theorems 3 and 5 divided by (x - x1)(y - y1) (column operations: the second column
// phi(x1) = phi(x) - (x - x1) Dphi, the fourth likewise), = -Bez' of seed §6.1.
template <class R>
std::vector<std::vector<R>> determinantal_full(const std::array<std::vector<R>, 4>& phi_in,
                                               const std::array<std::vector<R>, 4>& psi_in, int m, int n,
                                               const char* what) {
  check_degrees(m, n, what);
  std::array<std::vector<R>, 4> phi, psi;
  std::array<std::vector<std::vector<R>>, 4> dphi, dpsi;
  for (int i = 0; i < 4; ++i) {
    phi[i] = padded_coefficients(phi_in[i], m, what);
    psi[i] = padded_coefficients(psi_in[i], n, what);
    dphi[i] = divided_difference_array(phi[i], m);
    dpsi[i] = divided_difference_array(psi[i], n);
  }
  std::vector<std::vector<R>> full(m * n, std::vector<R>(m * n, R(0)));
  // Laplace expansion on the columns {0,1}: rows {r<s} against the complement {c<d},
  // sign (-1)^{(r+s)+(0+1)}.
  for (int r = 0; r < 4; ++r)
    for (int s = r + 1; s < 4; ++s) {
      int cd[2], k = 0;
      for (int i = 0; i < 4; ++i)
        if (i != r && i != s) cd[k++] = i;
      const bool negative = (r + s + 1) % 2 != 0;
      add_outer_product(full, negative, wedge_array(phi[r], dphi[s], phi[s], dphi[r], m),
                        wedge_array(psi[cd[0]], dpsi[cd[1]], psi[cd[1]], dpsi[cd[0]], n), m, n);
    }
  return full;
}

template <class R>
void negate_all(std::vector<std::vector<R>>& a) {
  for (auto& row : a)
    for (auto& e : row) e = -e;
}

} // namespace internal

/// buse-elkadi-galligo-2008 Theorem 7: the mn x mn Bezoutian matrix of
/// P_i = f_i(x) - g_i(y), i = 1..3, deg f_i <= m, deg g_i <= n; its determinant is,
/// up to sign, the anisotropic resultant Res(P_1^h, P_2^h, P_3^h) (Proposition 6:
/// homogeneous of degree mn in the coefficients of each P_i). The polynomials are
/// given by their coefficient vectors (lowest degree first). The Bezoutian is
/// formula (2) with the variables in the order (x, y):
///   Bez(x,y; x1,y1) = -det[ f_i(x) - g_i(y), (f_i(x)-f_i(x1))/(x-x1), (g_i(y)-g_i(y1))/(y-y1) ],
/// which is symmetric in (x,y) <-> (x1,y1), so the matrix is symmetric.
template <class R>
Separated_bezoutian_matrix<R> dense_separated_bezoutian_matrix(const std::array<std::vector<R>, 3>& f,
                                                               const std::array<std::vector<R>, 3>& g, int m,
                                                               int n) {
  return internal::finish_separated(
      internal::separated_bezoutian_full(f, g, m, n, "dense_separated_bezoutian_matrix"), m, n, false);
}

/// buse-elkadi-galligo-2008 Theorem 9: the (mn-1) x (mn-1) Bezoutian matrix of
/// P_i = f_i(x) - g_i(y) when f_i(0) = g_i(0) (so P_i(0,0) = 0): the matrix of
/// Theorem 7 without the row and column of the monomial 1 (which are zero). Its
/// determinant is, up to sign, the residual anisotropic resultant (Proposition 8:
/// degree mn-1 in the coefficients of each P_i). Throws Invalid_input when some
/// f_i(0) != g_i(0).
template <class R>
Separated_bezoutian_matrix<R> residual_separated_bezoutian_matrix(const std::array<std::vector<R>, 3>& f,
                                                                  const std::array<std::vector<R>, 3>& g, int m,
                                                                  int n) {
  for (int i = 0; i < 3; ++i) {
    const R f0 = f[i].empty() ? R(0) : f[i][0];
    const R g0 = g[i].empty() ? R(0) : g[i][0];
    if (!(f0 == g0))
      throw Invalid_input("residual_separated_bezoutian_matrix: f_i(0) and g_i(0) differ (no base point at 0)");
  }
  return internal::finish_separated(
      internal::separated_bezoutian_full(f, g, m, n, "residual_separated_bezoutian_matrix"), m, n, true);
}

/// buse-elkadi-galligo-2008 Theorem 12: the mn x mn matrix B' of
///   Bez'(x,y; x1,y1) = Bez_{P_0..P_3}(x,y,lambda; x1,y1,lambda1) / lambda
///                    = -det[ phi_i(x), (phi_i(x)-phi_i(x1))/(x-x1), psi_i(y), (psi_i(y)-psi_i(y1))/(y-y1) ]
/// for P_i = phi_i(x) - lambda psi_i(y), i = 0..3 (formula (2) with the variables in
/// the order (x, y, lambda)); deg phi_i <= m, deg psi_i <= n. Its determinant is, up
/// to sign, the determinantal resultant Res_X(M) (Proposition 10: degree mn in the
/// coefficients of each pair (phi_j, psi_j)).
template <class R>
Separated_bezoutian_matrix<R> dense_determinantal_bezoutian_matrix(const std::array<std::vector<R>, 4>& phi,
                                                                   const std::array<std::vector<R>, 4>& psi, int m,
                                                                   int n) {
  auto full = internal::determinantal_full(phi, psi, m, n, "dense_determinantal_bezoutian_matrix");
  internal::negate_all(full);
  return internal::finish_separated(std::move(full), m, n, false);
}

/// buse-elkadi-galligo-2008 Theorem 14: the (mn-1) x (mn-1) submatrix of B'
/// (Theorem 12) without the monomial 1, for phi_i(0) = psi_i(0), i = 0..3. Its
/// determinant is, up to sign, the residual determinantal resultant (Proposition 13:
/// degree mn-1 in the coefficients of each pair (phi_j, psi_j)). Throws Invalid_input
/// when some phi_i(0) != psi_i(0).
template <class R>
Separated_bezoutian_matrix<R> residual_determinantal_bezoutian_matrix(const std::array<std::vector<R>, 4>& phi,
                                                                      const std::array<std::vector<R>, 4>& psi,
                                                                      int m, int n) {
  for (int i = 0; i < 4; ++i) {
    const R a = phi[i].empty() ? R(0) : phi[i][0];
    const R b = psi[i].empty() ? R(0) : psi[i][0];
    if (!(a == b))
      throw Invalid_input(
          "residual_determinantal_bezoutian_matrix: phi_i(0) and psi_i(0) differ (no base point at 0)");
  }
  auto full = internal::determinantal_full(phi, psi, m, n, "residual_determinantal_bezoutian_matrix");
  internal::negate_all(full);
  return internal::finish_separated(std::move(full), m, n, true);
}

} // namespace bezoutian

#endif // BEZOUTIAN_ELIMINATION_SEPARATED_VARIABLE_RESULTANTS_H
