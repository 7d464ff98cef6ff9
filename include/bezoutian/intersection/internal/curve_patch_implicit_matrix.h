// The implicit matrix of a rational tensor-product patch for intersect_curve_patch: the generalized Bezoutian of
// buse-elkadi-galligo-2008 Definition 1 (Dixon's 2mn x 2mn matrix for bi-degree (m,n), du-1989 ch. 3), linear in
// the point (w, x1, x2, x3), whose determinant vanishes exactly on the implicit surface and whose kernel at a point
// of the surface gives its preimage (u, v). Also the integer forms of curve and patch, the exact kernel analysis at
// a rational point, and the small polynomial and root utilities of the curve/patch engine.
//
// Internal header: not part of the public API.
#ifndef BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_PATCH_IMPLICIT_MATRIX_H
#define BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_PATCH_IMPLICIT_MATRIX_H

#include <bezoutian/algebraic/Algebraic_real.h>
#include <bezoutian/algebraic/Root_isolation.h>
#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/elimination/Bezoutian.h>
#include <bezoutian/elimination/Polynomial_matrix_determinant.h>
#include <bezoutian/elimination/exact_linear_algebra.h>
#include <bezoutian/geometry/Rational_bezier_curve.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>

#include <CGAL/Polynomial.h>

#include <algorithm>
#include <array>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace bezoutian {
namespace internal {
namespace cs {

using Z1 = Polynomial_1<Integer>;
using Z2 = Polynomial_2<Integer>;
using Q1 = Polynomial_1<Rational>;
using Qmatrix = std::vector<std::vector<Rational>>;

inline Integer lcm_of_denominators(const Q1& f, Integer l) {
  for (int i = 0; i <= f.degree(); ++i) l = CGAL::div(l * f[i].denominator(), CGAL::gcd(l, f[i].denominator()));
  return l;
}

inline Z1 scaled_integer(const Q1& f, const Integer& l) {
  std::vector<Integer> c;
  for (int i = 0; i <= f.degree(); ++i) c.push_back((f[i] * Rational(l)).numerator());
  return Z1(c.begin(), c.end());
}

inline Q1 to_q(const Z1& f) {
  std::vector<Rational> c;
  for (int i = 0; i <= f.degree(); ++i) c.push_back(Rational(f[i]));
  return Q1(c.begin(), c.end());
}

/// (W, X, Y, Z) of the curve times one positive integer: integer coefficients, same projective curve.
inline std::array<Z1, 4> integer_curve_form(const Rational_bezier_curve<Rational, 3>& c) {
  const auto p = c.power_form();
  Integer l(1);
  for (const Q1& q : p) l = lcm_of_denominators(q, l);
  std::array<Z1, 4> r;
  for (int k = 0; k < 4; ++k) r[k] = scaled_integer(p[k], l);
  return r;
}

/// (Phi_0..Phi_3) of the patch as sparse integer polynomials in (u, v) (one common positive factor).
inline std::array<Sparse_polynomial<Integer>, 4> integer_patch_form(const Rational_bezier_patch<Rational>& patch) {
  const auto p = patch.power_form();
  Integer l(1);
  for (const auto& q : p)
    for (int j = 0; j <= q.degree(); ++j) l = lcm_of_denominators(q[j], l);
  std::array<Sparse_polynomial<Integer>, 4> r;
  for (int k = 0; k < 4; ++k) {
    r[k] = Sparse_polynomial<Integer>(2);
    for (int j = 0; j <= p[k].degree(); ++j)
      for (int i = 0; i <= p[k][j].degree(); ++i)
        r[k].add_term({i, j}, (p[k][j][i] * Rational(l)).numerator());
  }
  return r;
}

/// The implicit matrix of a patch of bi-degree (m,n): M(w,x1,x2,x3) = w B[0] + x1 B[1] + x2 B[2] + x3 B[3],
/// N x N with N = 2mn, integer matrices B[k].
///
/// It is the generalized Bezoutian (buse-elkadi-galligo-2008 Definition 1, formula (2)) of the three polynomials
/// f_k = x_k Phi_0(u,v) - w Phi_k(u,v) in (u, v), divided by w^2: formula (2) is multilinear in the rows f_k, and
/// the terms with two rows Phi_0 vanish, so Bez(f_1,f_2,f_3) = w^2 (-w Bez(Phi_1,Phi_2,Phi_3) + x_1 Bez(Phi_0,Phi_2,
/// Phi_3) + x_2 Bez(Phi_1,Phi_0,Phi_3) + x_3 Bez(Phi_1,Phi_2,Phi_0)). For three polynomials of bi-degree (m,n) it
/// is Dixon's 2mn x 2mn matrix, whose determinant is their resultant on P^1 x P^1 (Dixon 1908; du-1989 ch. 3 for
/// the bivariate theory). Rows are indexed by the y-monomials u^a v^b (a < 2m, b < n), columns by the
/// x-monomials u^a v^b (a < m, b < 2n); row 0 and column 0 are the monomial 1, row 1 is u, column 1 is v.
/// If (u0, v0) is a common root, the column vector of x-monomials at (u0,v0) is in the right kernel (the first
/// column of formula (2) vanishes) and the row vector of y-monomials is in the left kernel (f(x) = f(y) +
/// sum (x_i - y_i) d_i f, so the first column becomes a combination of the others).
struct Patch_implicit_matrix {
  std::size_t N = 0;
  std::array<std::vector<std::vector<Integer>>, 4> B;

  explicit Patch_implicit_matrix(const Rational_bezier_patch<Rational>& patch) {
    // the actual bi-degree of the power form (a degree-elevated patch would have a zero Dixon determinant)
    const auto phi = integer_patch_form(patch);
    int m = 0, n = 0;
    for (const auto& f : phi) {
      m = std::max(m, f.degree(0));
      n = std::max(n, f.degree(1));
    }
    if (m < 1 || n < 1)
      throw Invalid_input("intersect_curve_patch: the patch does not depend on both parameters (it is not a surface)");
    N = std::size_t(2 * m * n);
    std::map<std::pair<int, int>, std::size_t> rows, cols;
    auto order = [](int A, int Bd, bool u_second, std::map<std::pair<int, int>, std::size_t>& idx) {
      std::vector<std::pair<int, int>> list{{0, 0}, u_second ? std::make_pair(1, 0) : std::make_pair(0, 1)};
      for (int b = 0; b < Bd; ++b)
        for (int a = 0; a < A; ++a)
          if (std::make_pair(a, b) != list[0] && std::make_pair(a, b) != list[1]) list.push_back({a, b});
      for (std::size_t i = 0; i < list.size(); ++i) idx[list[i]] = i;
    };
    order(2 * m, n, true, rows);
    order(m, 2 * n, false, cols);
    const int perm[4][3] = {{1, 2, 3}, {0, 2, 3}, {1, 0, 3}, {1, 2, 0}};
    for (int k = 0; k < 4; ++k) {
      B[k].assign(N, std::vector<Integer>(N, Integer(0)));
      const Sparse_polynomial<Integer> bez =
          generalized_bezoutian(std::vector<Sparse_polynomial<Integer>>{phi[perm[k][0]], phi[perm[k][1]], phi[perm[k][2]]});
      for (const auto& t : bez.terms()) {
        auto c = cols.find({t.first[0], t.first[1]});
        auto r = rows.find({t.first[2], t.first[3]});
        if (c == cols.end() || r == rows.end())
          throw Error("curve/patch intersection: unexpected monomial in the Bezoutian (internal error)");
        B[k][r->second][c->second] = k == 0 ? Integer(-t.second) : t.second;
      }
    }
  }

  /// M(H(r)) for a homogeneous curve form H = (W, X, Y, Z): entries of degree deg H.
  std::vector<std::vector<Z1>> at_curve(const std::array<Z1, 4>& H) const {
    std::vector<std::vector<Z1>> M(N, std::vector<Z1>(N, Z1(0)));
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = 0; j < N; ++j)
        for (int k = 0; k < 4; ++k)
          if (!CGAL::is_zero(B[k][i][j])) M[i][j] += H[k] * Z1(B[k][i][j]);
    return M;
  }

  /// M(w, x1, x2, x3) at a rational point.
  Qmatrix at_point(const std::array<Rational, 4>& h) const {
    Qmatrix M(N, std::vector<Rational>(N, Rational(0)));
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = 0; j < N; ++j)
        for (int k = 0; k < 4; ++k)
          if (!CGAL::is_zero(B[k][i][j])) M[i][j] += h[k] * Rational(B[k][i][j]);
    return M;
  }
};

using internal::right_kernel;  // exact_linear_algebra.h

inline Qmatrix transposed(const Qmatrix& a) {
  Qmatrix t(a.empty() ? 0 : a[0].size(), std::vector<Rational>(a.size()));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < a[i].size(); ++j) t[j][i] = a[i][j];
  return t;
}

/// What the kernel of M at a point of the implicit surface says about its preimages (u,v).
struct Kernel_answer {
  enum Status { not_on_surface, affine, at_infinity, degenerate } status = not_on_surface;
  Rational u, v;
};

/// Kernel of the implicit matrix at a rational point: rank N (not on the surface), rank N-1 with the unique
/// common root affine (u, v from the kernel vectors) or at infinity, or rank < N-1 (several preimages or a
/// singular point: degenerate).
inline Kernel_answer analyse_kernel(const Qmatrix& M) {
  Kernel_answer a;
  const auto right = right_kernel(M);
  if (right.empty()) return a;
  if (right.size() > 1) {
    a.status = Kernel_answer::degenerate;
    return a;
  }
  const auto left = right_kernel(transposed(M));
  const auto& x = right[0];
  const auto& y = left.at(0);
  if (CGAL::is_zero(x[0]) || CGAL::is_zero(y[0])) {
    a.status = Kernel_answer::at_infinity;
    return a;
  }
  a.status = Kernel_answer::affine;
  a.u = y[1] / y[0];
  a.v = x[1] / x[0];
  return a;
}

inline std::vector<std::vector<Z1>> delete_row_column(const std::vector<std::vector<Z1>>& M, std::size_t r,
                                                      std::size_t c) {
  std::vector<std::vector<Z1>> s;
  for (std::size_t i = 0; i < M.size(); ++i) {
    if (i == r) continue;
    s.emplace_back();
    for (std::size_t j = 0; j < M.size(); ++j)
      if (j != c) s.back().push_back(M[i][j]);
  }
  return s;
}

inline Z1 small_polynomial_determinant(const std::vector<std::vector<Z1>>& M) {
  if (M.empty()) return Z1(1);
  if (M.size() == 1) return M[0][0];
  return polynomial_matrix_determinant(M);
}

inline std::string str(const Rational& q) {
  std::ostringstream s;
  if (q.denominator() == Integer(1))
    s << q.numerator();
  else
    s << q;
  return s.str();
}

inline bool in_unit_interval(const Rational& x) { return Rational(0) <= x && x <= Rational(1); }

inline bool is_zero_or_one(const Algebraic_real& x) {
  return x.is_rational() && (CGAL::is_zero(x.rational_value()) || x.rational_value() == Rational(1));
}

/// Sorted distinct roots in [a,b] with pairwise disjoint isolating intervals.
inline std::vector<Isolated_root> separated_roots(const Z1& f, const Rational& a, const Rational& b) {
  std::vector<Isolated_root> r = isolate_real_roots(f, a, b);
  for (std::size_t i = 0; i + 1 < r.size(); ++i)
    for (;;) {
      const Algebraic_real &x = r[i].root, &y = r[i + 1].root;
      if (x.upper() < y.lower() || (x.is_rational() && y.is_rational())) break;
      if (x.is_rational() && x.rational_value() < y.lower()) break;
      if (y.is_rational() && x.upper() < y.rational_value()) break;
      x.refine();
      y.refine();
    }
  return r;
}

}  // namespace cs
}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_PATCH_IMPLICIT_MATRIX_H
