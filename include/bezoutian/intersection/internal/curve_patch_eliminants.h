// The eliminants U(u), V(v) of intersect_curve_patch: polynomials vanishing at the parameters (u, v) of every
// intersection of the curve with the patch, from the implicit equations of two plane projections of the curve
// (Sylvester resultants in r) evaluated on the patch and eliminated against each other (Sylvester resultants in
// the outer variable). They locate the kernel inversion u = Du/D11, v = Dv/D11 exactly and give the candidates of
// the grid step (curve_patch_fibres.h).
//
// Internal header: members of Curve_patch_engine (Curve_surface_intersection.h), not part of the public API.
#ifndef BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_PATCH_ELIMINANTS_H
#define BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_PATCH_ELIMINANTS_H

#include <bezoutian/intersection/Curve_surface_intersection.h>

#include <bezoutian/elimination/Polynomial_matrix_determinant.h>

#include <CGAL/Polynomial_traits_d.h>

#include <algorithm>
#include <array>
#include <vector>

namespace bezoutian {
namespace internal {
namespace cs {

// U(u) and V(v): with f_ab(x, y) = Res_r(L_a(C) - x W, L_b(C) - y W) the implicit equation of the projection of
// the curve by two linear forms (L_a, L_b) (homogenized: F_ab(X, Y, W)), g_ab(u,v) = F_ab(L_a(Phi), L_b(Phi),
// Phi_0) vanishes at every preimage (u,v) of a point of the curve; U = Res_v(g_ab, g_ac), V = Res_u(g_ab, g_ac)
// vanish at the parameters of every intersection. Several projections are tried until U, V are nonzero.
//
// With remove_lines (patches with base points only): common factors c_u(u) (c_v(v)) of g_ab, g_ac depending on
// u (v) alone are removed first and kept in removed_lines_[0] ([1]) (the iso-lines u = u0 they vanish on map into
// the curve's Zariski closure: collapsed lines, see base_point_case); then U = c_u Res_v(g_ab/c_u, g_ac/c_u)
// (or the degree-0 forms of `eliminant`) vanishes at the u of every intersection, on such a line or not.
inline void Curve_patch_engine::compute_eliminants(bool remove_lines) {
  if (have_eliminants_) return;
  const auto Phi = dense_patch_form();
  const int forms[6][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 2, -3}, {3, -1, 2}, {-2, 5, 1}};
  const int triples[4][3] = {{0, 1, 2}, {1, 2, 0}, {3, 4, 5}, {4, 5, 3}};
  for (const auto& t : triples) {
    Z2 g1 = projected_on_patch(forms[t[0]], forms[t[1]], Phi);
    Z2 g2 = projected_on_patch(forms[t[0]], forms[t[2]], Phi);
    if (CGAL::is_zero(g1) || CGAL::is_zero(g2)) continue;
    if (remove_lines) {
      removed_lines_[0] = remove_common_content(g1, g2);  // factors in u alone
      g1 = swap_uv(g1);
      g2 = swap_uv(g2);
      removed_lines_[1] = remove_common_content(g1, g2);  // factors in v alone
      g1 = swap_uv(g1);
      g2 = swap_uv(g2);
    }
    const Z1 U = remove_lines ? eliminant(g1, g2) : outer_resultant(g1, g2);
    const Z1 V = remove_lines ? eliminant(swap_uv(g1), swap_uv(g2)) : outer_resultant(swap_uv(g1), swap_uv(g2));
    if (CGAL::is_zero(U) || CGAL::is_zero(V)) continue;
    // the removed lines' factors are put back: U, V vanish at the u, v of every intersection, on them or not
    U_ = U * removed_lines_[0];
    V_ = V * removed_lines_[1];
    eliminant_roots_[0] = separated_roots(U_, Rational(0), Rational(1));
    eliminant_roots_[1] = separated_roots(V_, Rational(0), Rational(1));
    BEZOUTIAN_PROFILE_STEP("eliminants U, V");
    have_eliminants_ = true;
    return;
  }
  throw Error("intersect_curve_patch: no projection gives nonzero eliminants U(u), V(v) (degenerate input)");
}

// The gcd c (in the inner variable) of all coefficients of g1 and g2 is divided out of both; returns c.
inline Z1 Curve_patch_engine::remove_common_content(Z2& g1, Z2& g2) {
  Z1 c(0);
  for (const Z2* g : {&g1, &g2})
    for (int j = 0; j <= g->degree(); ++j) c = CGAL::is_zero(c) ? (*g)[j] : Z1(CGAL::gcd(c, (*g)[j]));
  if (CGAL::is_zero(c) || c.degree() < 1) return Z1(1);
  for (Z2* g : {&g1, &g2}) {
    std::vector<Z1> q;
    for (int j = 0; j <= g->degree(); ++j) q.push_back(CGAL::integral_division((*g)[j], c));
    *g = Z2(q.begin(), q.end());
  }
  return c;
}

inline std::array<Z2, 4> Curve_patch_engine::dense_patch_form() const {
  const auto sp = integer_patch_form(patch_);
  std::array<Z2, 4> out;
  for (int k = 0; k < 4; ++k) {
    std::vector<Z1> rows(std::size_t(patch_.degree_v() + 1), Z1(0));
    for (const auto& t : sp[k].terms()) rows[std::size_t(t.first[1])] += Z1(t.second) * CGAL::ipower(Z1(Integer(0), Integer(1)), t.first[0]);
    out[k] = Z2(rows.begin(), rows.end());
  }
  return out;
}

inline Z1 Curve_patch_engine::linear_form(const int* c, const std::array<Z1, 4>& H) {
  return H[1] * Z1(c[0]) + H[2] * Z1(c[1]) + H[3] * Z1(c[2]);
}

inline Z2 Curve_patch_engine::linear_form(const int* c, const std::array<Z2, 4>& P) {
  return P[1] * Z2(c[0]) + P[2] * Z2(c[1]) + P[3] * Z2(c[2]);
}

// g(u,v) = F(L_a(Phi), L_b(Phi), Phi_0) with F the homogenized Res_r(A - x W, B - y W) (Sylvester matrix in r,
// entries in Z[x,y]); zero if the projection of the curve is degenerate (a point).
inline Z2 Curve_patch_engine::projected_on_patch(const int* la, const int* lb, const std::array<Z2, 4>& Phi) const {
  const Z1 A = linear_form(la, H_), B = linear_form(lb, H_), W = H_[0];
  const int d = std::max({A.degree(), B.degree(), W.degree()});
  if (d < 1) return Z2(0);
  auto coef = [](const Z1& f, int i) { return i <= f.degree() ? f[i] : Integer(0); };
  // p(r) = sum (A_i - x W_i) r^i, q(r) = sum (B_i - y W_i) r^i (x inner, y outer variable)
  std::vector<Z2> pc, qc;
  for (int i = 0; i <= d; ++i) {
    pc.push_back(Z2(Z1(coef(A, i), -coef(W, i))));
    qc.push_back(Z2(Z1(coef(B, i)), Z1(-coef(W, i))));
  }
  if (CGAL::is_zero(pc[d]) && CGAL::is_zero(qc[d])) return Z2(0);
  std::vector<std::vector<Z2>> S(std::size_t(2 * d), std::vector<Z2>(std::size_t(2 * d), Z2(0)));
  for (int i = 0; i < d; ++i)
    for (int j = 0; j <= d; ++j) {
      S[i][i + j] = pc[d - j];
      S[d + i][i + j] = qc[d - j];
    }
  const Z2 f = polynomial_matrix_determinant(S);
  if (CGAL::is_zero(f)) return Z2(0);
  int deg = 0;
  for (int b = 0; b <= f.degree(); ++b)
    if (!CGAL::is_zero(f[b])) deg = std::max(deg, b + f[b].degree());
  const Z2 X = linear_form(la, Phi), Y = linear_form(lb, Phi);
  std::vector<Z2> Xp{Z2(1)}, Yp{Z2(1)}, Wp{Z2(1)};
  for (int i = 1; i <= deg; ++i) {
    Xp.push_back(Xp.back() * X);
    Yp.push_back(Yp.back() * Y);
    Wp.push_back(Wp.back() * Phi[0]);
  }
  Z2 g(0);
  for (int b = 0; b <= f.degree(); ++b)
    for (int a = 0; a <= f[b].degree(); ++a)
      if (!CGAL::is_zero(f[b][a])) g += Z2(f[b][a]) * Xp[a] * Yp[b] * Wp[deg - a - b];
  return g;
}

inline Z2 Curve_patch_engine::swap_uv(const Z2& g) { return typename CGAL::Polynomial_traits_d<Z2>::Swap()(g, 0, 1); }

// A polynomial in the inner variable vanishing at the inner coordinate of every common zero of g1, g2: Res_v, or
// when g1 (g2) does not depend on the outer variable, g1[0] (g2[0]), or gcd(g1[0], g2[0]) if neither does.
inline Z1 Curve_patch_engine::eliminant(const Z2& g1, const Z2& g2) {
  if (g1.degree() < 1 && g2.degree() < 1) return Z1(CGAL::gcd(g1[0], g2[0]));
  if (g1.degree() < 1) return g1[0];
  if (g2.degree() < 1) return g2[0];
  return outer_resultant(g1, g2);
}

// Res_v(g1, g2) by the Sylvester matrix in the outer variable (entries in Z[u]).
inline Z1 Curve_patch_engine::outer_resultant(const Z2& g1, const Z2& g2) {
  const int d1 = g1.degree(), d2 = g2.degree();
  if (d1 < 1 || d2 < 1) return Z1(0);
  const std::size_t n = std::size_t(d1 + d2);
  std::vector<std::vector<Z1>> S(n, std::vector<Z1>(n, Z1(0)));
  for (int i = 0; i < d2; ++i)
    for (int j = 0; j <= d1; ++j) S[i][i + j] = g1[d1 - j];
  for (int i = 0; i < d1; ++i)
    for (int j = 0; j <= d2; ++j) S[d2 + i][i + j] = g2[d2 - j];
  return polynomial_matrix_determinant(S);
}

}  // namespace cs
}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_PATCH_ELIMINANTS_H
