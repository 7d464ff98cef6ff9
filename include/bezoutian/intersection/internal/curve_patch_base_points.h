// Patches with base points in intersect_curve_patch: det M(w,x) == 0 identically (e.g. at infinity or from a
// collapsed edge), so neither the eliminant det M(C(r)) nor the kernel inversion is available. The test of the
// implicit matrix, the collapsed edges and iso-lines, and the eliminant R(r) = W(r)^D N(L(r)/W(r)) built from
// U, V by Sylvester resultants, whose roots all go through the grid step (curve_patch_fibres.h).
//
// Internal header: members of Curve_patch_engine (Curve_surface_intersection.h), not part of the public API.
#ifndef BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_PATCH_BASE_POINTS_H
#define BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_PATCH_BASE_POINTS_H

#include <bezoutian/intersection/Curve_surface_intersection.h>

#include <bezoutian/elimination/Polynomial_matrix_determinant.h>

#include <CGAL/Polynomial_traits_d.h>

#include <string>
#include <utility>
#include <vector>

namespace bezoutian {
namespace internal {
namespace cs {

// det M(w,x) == 0 identically: base points or a patch whose image is not a surface.
inline bool Curve_patch_engine::implicit_matrix_regular() const {
  const int pts[3][4] = {{3, -7, 11, 5}, {-2, 13, 1, -9}, {17, 4, -6, 23}};
  for (const auto& q : pts) {
    const Qmatrix A = matrix_->at_point({Rational(q[0]), Rational(q[1]), Rational(q[2]), Rational(q[3])});
    if (right_kernel(A).empty()) return true;
  }
  return false;
}

inline void Curve_patch_engine::check_implicit_matrix_regular() const {
  if (implicit_matrix_regular()) return;
  throw Error("intersect_curve_patch: the implicit matrix of the patch is singular (the patch has base points or "
              "its image is not a surface" + collapsed_edges() + "); not supported");
}

// A collapsed edge (mapped to one point P: the four homogeneous coordinates along it are proportional) always
// gives base points: Phi_k = P_k Phi_0 on the edge, and Phi_0 restricted to it has (complex) roots. Named in the
// error message.
inline std::string Curve_patch_engine::collapsed_edges() const {
  const char* names[4] = {"v = 0", "u = 1", "v = 1", "u = 0"};
  const int dir[4] = {1, 0, 1, 0}, at[4] = {0, 1, 1, 0};
  std::string out;
  for (int side = 0; side < 4; ++side) {
    Rational p0, p[3];
    if (collapsed_line(dir[side], Rational(at[side]), p0, p))
      out += "; the edge " + std::string(names[side]) + " collapses to the point (" + str(p[0]) + ", " + str(p[1]) +
             ", " + str(p[2]) + ")";
  }
  return out;
}

// det M(w,x) == 0 identically (base points, e.g. at infinity or from a collapsed edge): no eliminant from the
// implicit matrix and no kernel inversion. Instead, with M = sum_k c_k Phi_k and L = sum_k c_k X_k, every
// intersection parameter is a root of
//   R(r) = W(r)^D N(L(r)/W(r)),  N(lambda) = Res_u(U(u), h / cont_u h),  h(lambda, u) = Res_v(V(v), E),
//   E(lambda, u, v) = Phi_0(u,v) lambda - M(u,v)   (D = deg N; U, V square-free):
// at an intersection lambda0 = L/W(r0) = M/Phi_0(u0,v0), so E(lambda0, u0, v0) = 0, V(v0) = 0 give h(lambda0, u0)
// = 0, U(u0) = 0 gives N(lambda0) = 0. Removing the content cont_u h (its roots u1 are the u of pairs (u1, v1),
// V(v1) = 0, where E vanishes for all lambda: affine base points) keeps that zero unless cont_u h(u0) = 0, which
// is excluded by an exact check (no common root of cont_u h and U in [0,1], else the next combination c, else
// Error). N != 0: h / cont_u h is primitive, so it vanishes identically at no root of U; R == 0 only if L/W is a
// constant root of N (a planar curve): next c. Every root of R in [0,1] is then decided by the grid step (its
// proofs only need R, U, V to vanish at every intersection). Collapsed lines (an iso-line u = u0 mapped to one
// point P, removed from g_ab, g_ac by compute_eliminants) are reported once, at the exact roots of
// gcd_k (X_k - P_k W), with collapsed_line set; the grid step skips their points at those r.
inline void Curve_patch_engine::base_point_case(Curve_patch_intersection_result& res) {
  try {
    compute_eliminants(true);
  } catch (const Error& e) {
    throw Error(std::string(e.what()) + "; the patch has base points (its implicit matrix is singular" +
                collapsed_edges() + "): the curve may lie on its surface, not supported");
  }
  std::vector<std::pair<Algebraic_real, std::pair<int, Rational>>> hits;  // r, (direction, value of the line)
  for (int dir = 0; dir < 2; ++dir) {
    if (removed_lines_[dir].degree() < 1) continue;
    for (const Isolated_root& x : isolate_real_roots(removed_lines_[dir], Rational(0), Rational(1))) {
      Rational p0, p[3];
      if (!x.root.is_rational() || !collapsed_line(dir, x.root.rational_value(), p0, p))
        throw Error("intersect_curve_patch: the iso-line " + std::string(dir ? "v" : "u") + " ~ " +
                    x.root.to_decimal_string(12) + " of the patch maps into the curve's Zariski closure and is not "
                    "collapsed to a point (the curve runs along the patch); patch with base points: not supported");
      Z1 g(0);  // gcd_k (X_k - P_k W): the parameters with C(r) = P
      for (int k = 0; k < 3; ++k) {
        const Z1 f = H_[k + 1] * Z1(Integer(p0.numerator() * p[k].denominator())) -
                     H_[0] * Z1(Integer(p[k].numerator()));
        g = CGAL::is_zero(g) ? f : Z1(CGAL::gcd(g, f));
      }
      if (CGAL::is_zero(g) || g.degree() < 1) continue;
      for (const Isolated_root& r : isolate_real_roots(g, Rational(0), Rational(1))) {
        hits.push_back({r.root, {dir, x.root.rational_value()}});
        const Algebraic_real a(x.root.rational_value());
        add_point(res, r.root, dir == 0 ? a : Algebraic_real(0), dir == 0 ? Algebraic_real(0) : a, 0);
        res.points.back().collapsed_line = dir;
      }
    }
  }
  R_ = base_point_r_eliminant();
  BEZOUTIAN_PROFILE_STEP("base-point eliminant");
  for (const Isolated_root& root : separated_roots(R_, Rational(0), Rational(1))) {
    std::vector<std::pair<int, Rational>> skip;
    for (const auto& h : hits)
      if (h.first == root.root) skip.push_back(h.second);
    add_fibre(res, root.root, skip);
  }
}

// Is the iso-line u = t (dir 0) or v = t (dir 1) mapped to one point (p0 : p)? Exact.
inline bool Curve_patch_engine::collapsed_line(int dir, const Rational& t, Rational& p0, Rational (&p)[3]) const {
  const auto Phi = dense_patch_form();
  std::array<Q1, 4> e;
  for (int k = 0; k < 4; ++k) {
    std::vector<Rational> c;
    if (dir == 0) {
      for (int j = 0; j <= Phi[k].degree(); ++j) c.push_back(value_at(Phi[k][j], t));
      e[k] = Q1(c.begin(), c.end());
    } else {
      Q1 g(0), tp(1);
      for (int j = 0; j <= Phi[k].degree(); ++j, tp *= Q1(t)) g += to_q(Phi[k][j]) * tp;
      e[k] = g;
    }
  }
  if (CGAL::is_zero(e[0])) return false;
  int i0 = 0;
  while (CGAL::is_zero(e[0][i0])) ++i0;
  for (int k = 1; k < 4; ++k)
    if (e[k] * Q1(e[0][i0]) != e[0] * Q1(e[k][i0])) return false;
  p0 = Rational(1);
  for (int k = 0; k < 3; ++k) p[k] = e[k + 1][i0] / e[0][i0];
  return true;
}

inline Z1 Curve_patch_engine::base_point_r_eliminant() const {
  if (U_.degree() < 1 || V_.degree() < 1) return Z1(1);  // no u or no v candidates: no isolated intersection
  // square-free parts: the same roots, smaller resultants
  const Z1 U = typename CGAL::Polynomial_traits_d<Z1>::Make_square_free()(U_);
  const Z1 V = typename CGAL::Polynomial_traits_d<Z1>::Make_square_free()(V_);
  const auto Phi = dense_patch_form();
  const int combos[3][3] = {{1, 2, 3}, {3, -1, 2}, {-2, 5, 1}};
  for (const auto& c : combos) {
    // E = Phi_0(u,v) lambda - M(u,v), M = sum_k c_k Phi_k: v-coefficients e_j(lambda, u), inner variable lambda
    const int n = patch_.degree_v();
    std::vector<Z2> e;
    for (int j = 0; j <= n; ++j) {
      auto co = [&](int k, int i) {
        return j <= Phi[k].degree() && i <= Phi[k][j].degree() ? Phi[k][j][i] : Integer(0);
      };
      int du = 0;
      for (int k = 0; k < 4; ++k) du = std::max(du, j <= Phi[k].degree() ? Phi[k][j].degree() : 0);
      std::vector<Z1> cu;
      for (int i = 0; i <= du; ++i) {
        Integer m(0);
        for (int k = 1; k <= 3; ++k) m += Integer(c[k - 1]) * co(k, i);
        cu.push_back(Z1(Integer(-m), co(0, i)));
      }
      e.push_back(Z2(cu.begin(), cu.end()));
    }
    while (!e.empty() && CGAL::is_zero(e.back())) e.pop_back();
    if (e.size() < 2) continue;  // E does not depend on v: try another combination
    const int dE = int(e.size()) - 1, dV = V.degree();
    const std::size_t N = std::size_t(dE + dV);
    std::vector<std::vector<Z2>> S(N, std::vector<Z2>(N, Z2(0)));
    for (int i = 0; i < dE; ++i)
      for (int j = 0; j <= dV; ++j) S[i][i + j] = Z2(Z1(V[dV - j]));
    for (int i = 0; i < dV; ++i)
      for (int j = 0; j <= dE; ++j) S[dE + i][i + j] = e[dE - j];
    Z2 h = polynomial_matrix_determinant(S);  // Res_v(V, E)(lambda, u)
    BEZOUTIAN_PROFILE_STEP("bp: Res_v");
    if (CGAL::is_zero(h)) continue;
    Z2 hs = swap_uv(h), dummy = hs;  // inner u, outer lambda
    const Z1 cont = remove_common_content(hs, dummy);
    if (cont.degree() >= 1 && !isolate_real_roots(Z1(CGAL::gcd(cont, U)), Rational(0), Rational(1)).empty())
      continue;  // a root u0 of U in [0,1] where E vanishes for all lambda: try another combination
    h = swap_uv(hs);  // inner lambda, outer u
    Z1 Nl;
    if (h.degree() < 1)
      Nl = h[0];
    else {
      std::vector<Z1> uc;
      for (int i = 0; i <= U.degree(); ++i) uc.push_back(Z1(U[i]));
      Nl = outer_resultant(Z2(uc.begin(), uc.end()), h);
    }
    BEZOUTIAN_PROFILE_STEP("bp: Res_u");
    if (CGAL::is_zero(Nl)) continue;
    // R(r) = W^D N(L/W), L = sum_k c_k X_k, D = deg N: N(lambda0) = 0 at lambda0 = L/W (C(r0)) of an intersection
    const Z1 L = H_[1] * Z1(Integer(c[0])) + H_[2] * Z1(Integer(c[1])) + H_[3] * Z1(Integer(c[2]));
    const int D = Nl.degree();
    std::vector<Z1> Lp{Z1(1)}, Wp{Z1(1)};
    for (int i = 1; i <= D; ++i) {
      Lp.push_back(Lp.back() * L);
      Wp.push_back(Wp.back() * H_[0]);
    }
    Z1 R(0);
    for (int i = 0; i <= D; ++i)
      if (!CGAL::is_zero(Nl[i])) R += Z1(Nl[i]) * Lp[i] * Wp[D - i];
    if (!CGAL::is_zero(R)) return R;  // zero: the curve lies in a plane L/W = const, a root of N
  }
  throw Error("intersect_curve_patch: patch with base points: no combination gives a usable eliminant R(r) "
              "(degenerate input); not supported");
}

}  // namespace cs
}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_PATCH_BASE_POINTS_H
