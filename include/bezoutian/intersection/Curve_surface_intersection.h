// Certified intersection of a rational Bezier space curve (or a segment) with a rational tensor-product Bezier
// patch: du-1989 Problems 2.2a / 2.2b, solved with the generalized Bezoutian of buse-elkadi-galligo-2008
// Definition 1. See doc/curve_surface_intersection.md for the method and the proofs.
#ifndef BEZOUTIAN_INTERSECTION_CURVE_SURFACE_INTERSECTION_H
#define BEZOUTIAN_INTERSECTION_CURVE_SURFACE_INTERSECTION_H

#include <bezoutian/algebraic/Algebraic_real.h>
#include <bezoutian/elimination/Bezoutian.h>
#include <bezoutian/intersection/Curve_intersection.h>
#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/elimination/exact_linear_algebra.h>
#include <bezoutian/arithmetic/interval_krawczyk.h>
#include <bezoutian/elimination/Polynomial_matrix_determinant.h>
#include <bezoutian/geometry/Rational_bezier_curve.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>
#include <bezoutian/algebraic/Root_isolation.h>
#include <bezoutian/geometry/Weight_validity.h>
#include <bezoutian/arithmetic/number_types.h>

#include <CGAL/Polynomial.h>
#include <CGAL/Polynomial_traits_d.h>

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#ifdef CS_DEBUG
#include <chrono>
#include <iostream>
#define CS_TICK(name)                                                                                       \
  do {                                                                                                      \
    static auto cs_t0 = std::chrono::steady_clock::now();                                                   \
    auto cs_t1 = std::chrono::steady_clock::now();                                                          \
    std::cerr << name << " " << std::chrono::duration<double, std::milli>(cs_t1 - cs_last()).count() << " ms\n"; \
    cs_last() = cs_t1;                                                                                      \
    (void)cs_t0;                                                                                            \
  } while (0)
inline std::chrono::steady_clock::time_point& cs_last() {
  static std::chrono::steady_clock::time_point t = std::chrono::steady_clock::now();
  return t;
}
#else
#define CS_TICK(name)
#endif

namespace bezoutian {

/// Kind of an isolated curve/patch intersection.
enum class Curve_patch_intersection_kind {
  transversal,  ///< simple root of the eliminant R(r): the curve crosses the surface
  tangent,      ///< multiple root of R(r) with a single preimage (u,v): the curve touches the surface
  endpoint,     ///< r = 0 or r = 1
  boundary      ///< r inside (0,1), (u,v) on the boundary of [0,1]^2
};

inline const char* to_string(Curve_patch_intersection_kind k) {
  switch (k) {
    case Curve_patch_intersection_kind::transversal: return "transversal";
    case Curve_patch_intersection_kind::tangent: return "tangent";
    case Curve_patch_intersection_kind::endpoint: return "endpoint";
    default: return "boundary";
  }
}

/// One isolated intersection C(r) = Phi(u,v) with r, u, v in [0,1], all three exact algebraic numbers.
struct Curve_patch_intersection_point {
  Algebraic_real r, u, v;
  /// Multiplicity of r as a root of the eliminant R(r) = det M(C(r)) (the intersection multiplicity of the
  /// curve with the implicit surface when the patch parametrizes it once); 0 for touching points found while
  /// the curve lies on the implicit surface (no eliminant).
  /// For a point C(r) with several preimages or singular on the surface (found by the grid step, see
  /// doc/curve_surface_intersection.md), one entry per preimage (u,v) with multiplicity 1 if (r,u,v) is a simple
  /// solution of C(r) = Phi(u,v) (the curve crosses that sheet transversally; proved), or 0 with tangent = true if
  /// it is a singular one (the curve is tangent to that sheet or the point is singular on the surface; decided
  /// exactly, only possible when at most one of r, u, v is irrational, otherwise Error).
  int multiplicity = 1;
  Curve_patch_intersection_kind kind = Curve_patch_intersection_kind::transversal;
  /// multiplicity >= 2, or a singular solution found by the grid step: the curve is tangent to the surface (or
  /// the point is singular on it).
  bool tangent = false;
  /// Floating-point approximation of the common point (C evaluated at the double nearest to r).
  std::array<double, 3> point{};
  /// -1, or a collapsed line of the patch through this point: 0 = every (u, v') with v' in [0,1] is a preimage (the
  /// iso-line u = this->u maps to one point; v is reported as 0), 1 = every (u', v), u' in [0,1] (u reported as 0).
  /// Such points have multiplicity 0 (not determined). Only patches with base points have collapsed lines.
  int collapsed_line = -1;
};

/// A piece C([r0, r1]) of the curve contained in the patch Phi([0,1]^2) (r0 < r1, exact ends).
struct Curve_patch_overlap {
  Algebraic_real r0, r1;
};

/// Result of intersect_curve_patch.
struct Curve_patch_intersection_result {
  std::vector<Curve_patch_intersection_point> points;  ///< sorted by r, then u, then v
  std::vector<Curve_patch_overlap> overlaps;            ///< sorted, disjoint
};

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

// ------------------------------------------------------------------ fibres with several preimages
// At a root r_i of R where the kernel of M(C(r_i)) does not give a unique preimage, every intersection
// (r_i, u, v) has u a root of U and v a root of V (compute_eliminants), so the intersections over r_i are among
// the grid points (r_i, u_j, v_k). Each grid point is excluded by interval evaluation of
// F_k(r,u,v) = W(r) Phi_k(u,v) - X_k(r) Phi_0(u,v), proved by Krawczyk's test, or decided exactly (at most one
// irrational coordinate). Proofs: doc/curve_surface_intersection.md, step 4b.

using Interval = Mpfi_interval;

inline Rational power_of_two_inverse(int e) {
  Rational q;  // fresh object (CGAL::Gmpq copies share their mpq_t)
  mpq_set_ui(q.mpq(), 1, 1);
  mpq_div_2exp(q.mpq(), q.mpq(), static_cast<mp_bitcnt_t>(e));
  return q;
}

inline Rational value_at(const Z1& f, const Rational& x) {
  Rational r(0);
  for (int i = f.degree(); i >= 0; --i) r = r * x + Rational(f[i]);
  return r;
}

inline Rational value_at(const Z2& f, const Rational& u, const Rational& v) {
  Rational r(0);
  for (int j = f.degree(); j >= 0; --j) r = r * v + value_at(f[j], u);
  return r;
}

inline Interval value_at(const Z2& f, const Interval& u, const Interval& v) {
  Interval r = Interval::point(0, u.prec());
  for (int j = f.degree(); j >= 0; --j) r = r * v + Interval::horner(f[j], u);
  return r;
}

inline Z2 derivative_u(const Z2& f) {
  std::vector<Z1> c;
  for (int j = 0; j <= f.degree(); ++j) c.push_back(CGAL::differentiate(f[j]));
  return Z2(c.begin(), c.end());
}

inline Z2 derivative_v(const Z2& f) {
  std::vector<Z1> c;
  for (int j = 1; j <= f.degree(); ++j) c.push_back(f[j] * Z1(Integer(j)));
  if (c.empty()) return Z2(0);
  return Z2(c.begin(), c.end());
}

inline std::size_t bit_size(const Z1& f) {
  std::size_t b = 1;
  for (int i = 0; i <= f.degree(); ++i) b = std::max<std::size_t>(b, mpz_sizeinbase(f[i].mpz(), 2));
  return b;
}

/// The system F_k(r,u,v) = W(r) Phi_k(u,v) - X_k(r) Phi_0(u,v), k = 1..3 (du-1989 eq. 2.8 up to sign), with its
/// partial derivatives, for interval evaluation (outward rounding).
struct Fibre_system {
  std::array<Z1, 4> H, dH;
  std::array<Z2, 4> P, Pu, Pv;
  std::size_t bits = 1;

  Fibre_system(const std::array<Z1, 4>& h, const std::array<Z2, 4>& phi) : H(h), P(phi) {
    for (int k = 0; k < 4; ++k) {
      dH[k] = CGAL::differentiate(H[k]);
      Pu[k] = derivative_u(P[k]);
      Pv[k] = derivative_v(P[k]);
      bits = std::max(bits, bit_size(H[k]));
      for (int j = 0; j <= P[k].degree(); ++j) bits = std::max(bits, bit_size(P[k][j]));
    }
  }

  void values(const std::array<Interval, 3>& x, std::array<Interval, 3>& F) const {
    const Interval w = Interval::horner(H[0], x[0]), p0 = value_at(P[0], x[1], x[2]);
    for (int k = 1; k <= 3; ++k)
      F[k - 1] = w * value_at(P[k], x[1], x[2]) - Interval::horner(H[k], x[0]) * p0;
  }

  void jacobian(const std::array<Interval, 3>& x, std::vector<std::vector<Interval>>& J) const {
    const Interval w = Interval::horner(H[0], x[0]), dw = Interval::horner(dH[0], x[0]);
    const Interval p0 = value_at(P[0], x[1], x[2]), p0u = value_at(Pu[0], x[1], x[2]),
                   p0v = value_at(Pv[0], x[1], x[2]);
    for (int k = 1; k <= 3; ++k) {
      const Interval xk = Interval::horner(H[k], x[0]);
      J[k - 1][0] = dw * value_at(P[k], x[1], x[2]) - Interval::horner(dH[k], x[0]) * p0;
      J[k - 1][1] = w * value_at(Pu[k], x[1], x[2]) - xk * p0u;
      J[k - 1][2] = w * value_at(Pv[k], x[1], x[2]) - xk * p0v;
    }
  }

  /// Exact decision at a grid point with at most one irrational coordinate (index `free`, -1 for none; the others
  /// rational in `value`): with the irrational coordinate as the variable t, F_1..F_3 and the determinant of the
  /// Jacobian are univariate polynomials over Q, whose signs at the algebraic number are exact
  /// (Algebraic_real::sign_of). Returns 0 not a solution, 1 simple solution, 2 singular solution. The affine
  /// Jacobian [C'(r) | -Phi_u | -Phi_v] has the columns (X_k' W - X_k W')/W^2, (Phi_k,u Phi_0 - Phi_k Phi_0,u)/Phi_0^2,
  /// (Phi_k,v Phi_0 - Phi_k Phi_0,v)/Phi_0^2; nonzero column factors do not change its rank.
  int exact(int free, const std::array<Rational, 3>& value, const Algebraic_real& x) const {
    auto curve = [&](const Z1& f) { return free == 0 ? to_q(f) : Q1(value_at(f, value[0])); };
    auto patch = [&](const Z2& f) {
      if (free == 1) {  // polynomial in u at v = value[2]
        Q1 g(0), vp(1);
        for (int j = 0; j <= f.degree(); ++j, vp *= Q1(value[2])) g += to_q(f[j]) * vp;
        return g;
      }
      if (free == 2) {  // polynomial in v at u = value[1]
        std::vector<Rational> c;
        for (int j = 0; j <= f.degree(); ++j) c.push_back(value_at(f[j], value[1]));
        return Q1(c.begin(), c.end());
      }
      return Q1(value_at(f, value[1], value[2]));
    };
    auto sign = [&](const Q1& f) { return free < 0 ? CGAL::sign(f[0]) : CGAL::Sign(x.sign_of(f)); };
    const Q1 w = curve(H[0]), dw = curve(dH[0]), p0 = patch(P[0]), p0u = patch(Pu[0]), p0v = patch(Pv[0]);
    Q1 a[3][3];
    for (int k = 1; k <= 3; ++k) {
      const Q1 xk = curve(H[k]), pk = patch(P[k]);
      if (sign(w * pk - xk * p0) != CGAL::ZERO) return 0;
      a[k - 1][0] = curve(dH[k]) * w - xk * dw;
      a[k - 1][1] = patch(Pu[k]) * p0 - pk * p0u;
      a[k - 1][2] = patch(Pv[k]) * p0 - pk * p0v;
    }
    const Q1 det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                   a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                   a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    return sign(det) == CGAL::ZERO ? 2 : 1;
  }
};

/// A root x of a polynomial with an open interval (lo, hi) that contains no other root of that polynomial.
struct Root_window {
  Algebraic_real x;
  Rational lo, hi;
};

/// Window of a root x in [0,1] of P: the isolating interval clipped to [0,1] for an irrational x (the roots come
/// from separated_roots on [0,1], pairwise disjoint); for a rational x = a/b, (x - w, x + w) where P with every
/// factor (b t - a) removed has no zero (interval Horner evaluation).
inline Root_window root_window(const Z1& P, const Algebraic_real& x) {
  if (!x.is_rational()) return Root_window{x, std::max(x.lower(), Rational(0)), std::min(x.upper(), Rational(1))};
  const Rational q = x.rational_value();
  const Z1 lin(Integer(-q.numerator()), Integer(q.denominator()));
  Z1 C = P;
  for (int guard = 0; C.degree() > 0 && CGAL::is_zero(value_at(C, q)) && guard <= P.degree(); ++guard)
    C = CGAL::integral_division(C, lin);  // exact: (b t - a) is primitive (Gauss's lemma)
  if (CGAL::is_zero(C) || CGAL::is_zero(value_at(C, q)))
    throw Error("intersect_curve_patch: window of a rational root (internal error)");
  for (int e = 4; e <= 4096; e *= 2) {
    const Rational w = power_of_two_inverse(e);
    const mpfr_prec_t prec = static_cast<mpfr_prec_t>(2 * e + 2 * bit_size(C) + 64);
    if (!Interval::horner(C, Interval::hull(q - w, q + w, prec)).contains_zero()) return Root_window{x, q - w, q + w};
  }
  throw Error("intersect_curve_patch: window of a rational root (internal error)");
}

/// Thrown when a grid point is neither excluded nor proved (a singular solution).
class Singular_fibre_error : public Error {
 public:
  explicit Singular_fibre_error(const std::string& what) : Error(what) {}
};

/// One preimage over a root r_i found by the grid step.
struct Fibre_point {
  Algebraic_real u, v;
  bool simple = true;  ///< false: singular solution (decided exactly; at most one irrational coordinate)
};

/// Decides one grid point (r, u, v) given by windows: 0 excluded, 1 simple solution, 2 singular solution (exact
/// only, when at most one coordinate is irrational); otherwise throws Singular_fibre_error when neither decided nor
/// excluded at box radius 2^-256.
///
/// Proof: the box B (radius rho about rational centres within rho/4 of r, u, v) contains the grid point, so
/// 0 not in F_k(B) excludes it. If B lies in the windows, W != 0 on B_r and Phi_0 != 0 on B_u x B_v, then a zero z
/// of F in B is an intersection C(z_r) = Phi(z_u, z_v), so R(z_r) = U(z_u) = V(z_v) = 0 and by the windows
/// z = (r, u, v); Krawczyk's K(B) in int B proves that F has exactly one zero in B, a regular one.
inline int decide_grid_point(const Fibre_system& S, const std::array<Root_window, 3>& w) {
  int free = -1, irrational = 0;
  std::array<Rational, 3> value;
  for (int i = 0; i < 3; ++i) {
    if (w[i].x.is_rational())
      value[i] = w[i].x.rational_value();
    else
      free = i, ++irrational;
  }
  if (irrational <= 1) return S.exact(free, value, free < 0 ? w[0].x : w[free].x);
  for (int e = 8; e <= 256; e *= 2) {
    const Rational rho = power_of_two_inverse(e);
    const mpfr_prec_t prec = static_cast<mpfr_prec_t>(2 * e + 3 * S.bits + 128);
    std::array<Interval, 3> tight{Interval(prec), Interval(prec), Interval(prec)}, box = tight;
    bool in_windows = true;
    for (int i = 0; i < 3; ++i) {
      const Algebraic_real& x = w[i].x;
      Rational c;
      if (x.is_rational()) {
        c = x.rational_value();
        tight[i] = Interval::hull(c, c, prec);
      } else {
        x.refine_to_width(rho / 2);
        c = (x.lower() + x.upper()) / 2;
        tight[i] = Interval::hull(x.lower(), x.upper(), prec);
      }
      box[i] = Interval::hull(c - rho, c + rho, prec);
      in_windows = in_windows && w[i].lo < c - rho && c + rho < w[i].hi;
    }
    std::array<Interval, 3> F = tight;
    S.values(tight, F);
    for (const Interval& f : F)
      if (!f.contains_zero()) return 0;
    if (!in_windows || Interval::horner(S.H[0], box[0]).contains_zero() ||
        value_at(S.P[0], box[1], box[2]).contains_zero())
      continue;
    auto value = [&S](const std::array<Interval, 3>& c, std::array<Interval, 3>& out) { S.values(c, out); };
    auto jac = [&S](const std::array<Interval, 3>& x, std::vector<std::vector<Interval>>& J) { S.jacobian(x, J); };
    if (krawczyk_prove<3>(box, value, jac)) return 1;
  }
  throw Singular_fibre_error("intersect_curve_patch: the curve is tangent to a sheet of the patch or meets a singular "
                             "point of the surface at r ~ " + w[0].x.to_decimal_string(15) + ", (u, v) ~ (" +
                             w[1].x.to_decimal_string(15) + ", " + w[2].x.to_decimal_string(15) +
                             ") (a singular solution of C(r) = Phi(u,v), neither proved nor excluded at box radius "
                             "2^-256): not supported");
}

/// The curve/patch engine.
class Curve_patch_engine {
 public:
  using Curve = Rational_bezier_curve<Rational, 3>;
  using Patch = Rational_bezier_patch<Rational>;

  Curve_patch_engine(const Curve& c, const Patch& p) : curve_(c), patch_(p) {}

  Curve_patch_intersection_result run() {
    if (patch_.degree_u() < 1 || patch_.degree_v() < 1)
      throw Invalid_input("intersect_curve_patch: the patch has degree 0 in u or in v (it is a curve, not a surface)");
    check_no_pole(curve_);
    check_no_pole(patch_);
    Curve_patch_intersection_result res;
    CS_TICK("start");
    H_ = integer_curve_form(curve_);
    if (disjoint_boxes()) return res;
    matrix_ = std::make_shared<Patch_implicit_matrix>(patch_);
    if (is_constant()) {
      // with base points the kernel of M always holds their monomial vectors: the kernel test would be wrong
      check_implicit_matrix_regular();
      const auto pre = preimages(curve_(Rational(0)));
      if (!pre.empty()) res.overlaps.push_back({Algebraic_real(0), Algebraic_real(1)});
      return res;
    }
    CS_TICK("matrix");
    M_ = matrix_->at_curve(H_);
    // R(r) = det M(C(r)): the implicit equation of the surface along the curve (buse-elkadi-galligo-2008 §2:
    // the determinant of the Bezoutian matrix is the resultant). Degree <= 2 m n deg C.
    const Z1 R = small_polynomial_determinant(M_);
    R_ = R;
    CS_TICK("det");
    if (CGAL::is_zero(R)) {
      if (implicit_matrix_regular())
        on_surface_case(res);
      else
        base_point_case(res);
    } else {
      const auto roots = separated_roots(R, Rational(0), Rational(1));
      CS_TICK("isolate");
      for (const Isolated_root& root : roots) resolve(root, res);
      CS_TICK("resolve");
    }
    sort_points(res);
    return res;
  }

  /// All (u,v) in [0,1]^2 with Phi(u,v) = p (rational point), from the kernel of M(1, p); if the kernel has
  /// dimension > 1 (several preimages or a singular point), from the grid step along a line through p.
  std::vector<std::pair<Algebraic_real, Algebraic_real>> preimages(const std::array<Rational, 3>& p) const {
    const Kernel_answer k = analyse_kernel(matrix_->at_point({Rational(1), p[0], p[1], p[2]}));
    if (k.status == Kernel_answer::degenerate) return fibre_of_point(p);
    std::vector<std::pair<Algebraic_real, Algebraic_real>> out;
    if (k.status == Kernel_answer::affine && in_unit_interval(k.u) && in_unit_interval(k.v)) {
      // the kernel argument gives the unique common root; checked by exact evaluation as well
      if (patch_(k.u, k.v) != p) throw Error("intersect_curve_patch: kernel inversion failed (internal error)");
      out.push_back({Algebraic_real(k.u), Algebraic_real(k.v)});
    }
    return out;
  }

  /// The preimages (u_j, v_k) over the root r of R (the grid step; see Fibre_system, decide_grid_point). Requires
  /// R_ and the curve form H_; throws Singular_fibre_error for a singular solution with an irrational coordinate.
  std::vector<Fibre_point> fibre(const Algebraic_real& r,
                                 const std::vector<std::pair<int, Rational>>& skip_lines = {}) {
    compute_eliminants();
    const Fibre_system S(H_, dense_patch_form());
    std::array<Root_window, 3> w{root_window(R_, r), Root_window{}, Root_window{}};
    std::vector<Root_window> wv;
    for (const Isolated_root& y : eliminant_roots_[1]) wv.push_back(root_window(V_, y.root));
    std::vector<Fibre_point> out;
    for (const Isolated_root& x : eliminant_roots_[0]) {
      w[1] = root_window(U_, x.root);
      for (const Root_window& y : wv) {
        w[2] = y;
        bool on_skipped_line = false;  // a collapsed line through C(r): every point of it is a preimage
        for (const auto& l : skip_lines) on_skipped_line = on_skipped_line || w[1 + l.first].x == Algebraic_real(l.second);
        if (on_skipped_line) continue;
        const int d = decide_grid_point(S, w);
        if (d != 0) out.push_back(Fibre_point{w[1].x, w[2].x, d == 1});
      }
    }
    return out;
  }

 private:
  bool is_constant() const {
    const Integer w0 = H_[0][0];
    for (int k = 1; k < 4; ++k)
      if (!CGAL::is_zero(H_[k] * Z1(w0) - H_[0] * Z1(H_[k][0]))) return false;
    return true;
  }

  // Exact exclusion: with weights of one sign the curve (patch) lies in the box of its control points.
  bool disjoint_boxes() const {
    if (!curve_.encloses_curve() || !patch_.encloses_patch()) return false;
    const auto a = curve_.control_box();
    const auto b = patch_.control_box();
    for (int k = 0; k < 3; ++k)
      if (a.second[k] < b.first[k] || b.second[k] < a.first[k]) return true;
    return false;
  }

  // det M(w,x) == 0 identically: base points or a patch whose image is not a surface.
  bool implicit_matrix_regular() const {
    const int pts[3][4] = {{3, -7, 11, 5}, {-2, 13, 1, -9}, {17, 4, -6, 23}};
    for (const auto& q : pts) {
      const Qmatrix A = matrix_->at_point({Rational(q[0]), Rational(q[1]), Rational(q[2]), Rational(q[3])});
      if (right_kernel(A).empty()) return true;
    }
    return false;
  }

  void check_implicit_matrix_regular() const {
    if (implicit_matrix_regular()) return;
    throw Error("intersect_curve_patch: the implicit matrix of the patch is singular (the patch has base points or "
                "its image is not a surface" + collapsed_edges() + "); not supported");
  }

  // A collapsed edge (mapped to one point P: the four homogeneous coordinates along it are proportional) always
  // gives base points: Phi_k = P_k Phi_0 on the edge, and Phi_0 restricted to it has (complex) roots. Named in the
  // error message.
  std::string collapsed_edges() const {
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

  // ------------------------------------------------------------------ isolated intersections
  void resolve(const Isolated_root& root, Curve_patch_intersection_result& res) {
    const Algebraic_real& r = root.root;
    if (r.is_rational()) {
      const Rational q = r.rational_value();
      const auto h = curve_.homogeneous_value(q);
      const Kernel_answer k = analyse_kernel(matrix_->at_point({h[0], h[1], h[2], h[3]}));
      if (k.status == Kernel_answer::degenerate) return add_fibre(res, r);  // several preimages or singular
      if (k.status != Kernel_answer::affine || !in_unit_interval(k.u) || !in_unit_interval(k.v)) return;
      if (patch_(k.u, k.v) != curve_(q)) throw Error("intersect_curve_patch: kernel inversion failed (internal error)");
      add_point(res, r, Algebraic_real(k.u), Algebraic_real(k.v), root.multiplicity);
      return;
    }
    // Irrational r: adj M(r) = x y^T when rank M = N-1, so with D11 = adj_00, Du = adj_01 (row u of y), Dv = adj_10
    // (column v of x): D11(r) != 0 proves rank N-1 and a unique affine common root u = Du/D11, v = Dv/D11.
    compute_minors();
    CS_TICK("minors");
    const int s = r.sign_of(D11_);
    if (s == 0) return add_fibre(res, r);  // rank < N-1 (several preimages, singular point) or root at infinity
    Algebraic_real u, v;
    if (!located(r, Du_, s, 0, u) || !located(r, Dv_, s, 1, v)) return;
    add_point(res, r, u, v, root.multiplicity);
  }

  // Points over r from the grid step: multiplicity 1 for a simple solution of C(r) = Phi(u,v) (the curve crosses
  // that sheet transversally), 0 and tangent for a singular one (decided exactly, at most one irrational coordinate).
  void add_fibre(Curve_patch_intersection_result& res, const Algebraic_real& r,
                  const std::vector<std::pair<int, Rational>>& skip_lines = {}) {
    CS_TICK("grid step");
    for (const Fibre_point& f : fibre(r, skip_lines)) {
      add_point(res, r, f.u, f.v, f.simple ? 1 : 0);
      if (!f.simple) {
        res.points.back().tangent = true;
        if (res.points.back().kind == Curve_patch_intersection_kind::transversal)
          res.points.back().kind = Curve_patch_intersection_kind::tangent;
      }
    }
  }

  // Preimages of a rational point p with a degenerate kernel: the fibre over r = 1/2 of the segment
  // p + (2r - 1) d, whose intersections at r = 1/2 are exactly the preimages of p. A direction d tangent to a
  // sheet at p gives a singular solution; the next direction is tried.
  std::vector<std::pair<Algebraic_real, Algebraic_real>> fibre_of_point(const std::array<Rational, 3>& p) const {
    const int dirs[3][3] = {{1, 2, 3}, {3, -1, 2}, {-2, 5, 1}};
    std::string last = "the lines through it lie on the surface";
    for (const auto& d : dirs) {
      std::array<Rational, 3> a = p, b = p;
      for (int k = 0; k < 3; ++k) {
        a[k] -= Rational(d[k]);
        b[k] += Rational(d[k]);
      }
      const Curve segment(std::vector<std::array<Rational, 3>>{a, b});
      Curve_patch_engine e(segment, patch_);
      e.H_ = integer_curve_form(segment);
      e.matrix_ = matrix_;
      e.M_ = matrix_->at_curve(e.H_);
      e.R_ = small_polynomial_determinant(e.M_);
      if (CGAL::is_zero(e.R_)) continue;
      try {
        std::vector<std::pair<Algebraic_real, Algebraic_real>> out;
        for (const Fibre_point& f : e.fibre(Algebraic_real(Rational(1, 2)))) out.push_back({f.u, f.v});
        return out;
      } catch (const Singular_fibre_error& err) {
        last = err.what();
      }
    }
    throw Error("intersect_curve_patch: the preimages of the point (" + str(p[0]) + ", " + str(p[1]) + ", " +
                str(p[2]) + ") (several preimages or a singular point) could not be decided: " + last);
  }

  void compute_minors() {
    if (have_minors_) return;
    D11_ = to_q(small_polynomial_determinant(delete_row_column(M_, 0, 0)));
    Du_ = -to_q(small_polynomial_determinant(delete_row_column(M_, 1, 0)));
    Dv_ = -to_q(small_polynomial_determinant(delete_row_column(M_, 0, 1)));
    have_minors_ = true;
  }

  // x0 = A(r)/D11(r) (sign of D11(r) = s): false if x0 is outside [0,1] (proved); otherwise x0 as an exact
  // algebraic number: a root of the eliminant E (U or V, which vanishes at every intersection parameter), located
  // among its isolated roots in [0,1] by exact sign decisions sign(x0 - c) = sign(A - c D11)(r) * s.
  bool located(const Algebraic_real& r, const Q1& A, int s, int direction, Algebraic_real& out) {
    auto cmp = [&](const Rational& c) { return r.sign_of(A - D11_ * Q1(c)) * s; };
    const int c0 = cmp(Rational(0)), c1 = cmp(Rational(1));
    if (c0 < 0 || c1 > 0) return false;
    if (c0 == 0) return out = Algebraic_real(0), true;
    if (c1 == 0) return out = Algebraic_real(1), true;
    compute_eliminants();
    for (const Isolated_root& x : eliminant_roots_[direction]) {
      const Algebraic_real& a0 = x.root;
      const bool here = a0.is_rational() ? cmp(a0.rational_value()) == 0
                                         : (cmp(a0.lower()) > 0 && cmp(a0.upper()) < 0);
      if (here) return out = a0, true;
    }
    throw Error("intersect_curve_patch: parameter not located among the eliminant roots (internal error)");
  }

  // U(u) and V(v): with f_ab(x, y) = Res_r(L_a(C) - x W, L_b(C) - y W) the implicit equation of the projection of
  // the curve by two linear forms (L_a, L_b) (homogenized: F_ab(X, Y, W)), g_ab(u,v) = F_ab(L_a(Phi), L_b(Phi),
  // Phi_0) vanishes at every preimage (u,v) of a point of the curve; U = Res_v(g_ab, g_ac), V = Res_u(g_ab, g_ac)
  // vanish at the parameters of every intersection. Several projections are tried until U, V are nonzero.
  //
  // With remove_lines (patches with base points only): common factors c_u(u) (c_v(v)) of g_ab, g_ac depending on
  // u (v) alone are removed first and kept in removed_lines_[0] ([1]) (the iso-lines u = u0 they vanish on map into
  // the curve's Zariski closure: collapsed lines, see base_point_case); then U = c_u Res_v(g_ab/c_u, g_ac/c_u)
  // (or the degree-0 forms of `eliminant`) vanishes at the u of every intersection, on such a line or not.
  void compute_eliminants(bool remove_lines = false) {
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
      CS_TICK("eliminants U, V");
      have_eliminants_ = true;
      return;
    }
    throw Error("intersect_curve_patch: no projection gives nonzero eliminants U(u), V(v) (degenerate input)");
  }

  // The gcd c (in the inner variable) of all coefficients of g1 and g2 is divided out of both; returns c.
  static Z1 remove_common_content(Z2& g1, Z2& g2) {
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

  std::array<Z2, 4> dense_patch_form() const {
    const auto sp = integer_patch_form(patch_);
    std::array<Z2, 4> out;
    for (int k = 0; k < 4; ++k) {
      std::vector<Z1> rows(std::size_t(patch_.degree_v() + 1), Z1(0));
      for (const auto& t : sp[k].terms()) rows[std::size_t(t.first[1])] += Z1(t.second) * CGAL::ipower(Z1(Integer(0), Integer(1)), t.first[0]);
      out[k] = Z2(rows.begin(), rows.end());
    }
    return out;
  }

  static Z1 linear_form(const int* c, const std::array<Z1, 4>& H) {
    return H[1] * Z1(c[0]) + H[2] * Z1(c[1]) + H[3] * Z1(c[2]);
  }
  static Z2 linear_form(const int* c, const std::array<Z2, 4>& P) {
    return P[1] * Z2(c[0]) + P[2] * Z2(c[1]) + P[3] * Z2(c[2]);
  }

  // g(u,v) = F(L_a(Phi), L_b(Phi), Phi_0) with F the homogenized Res_r(A - x W, B - y W) (Sylvester matrix in r,
  // entries in Z[x,y]); zero if the projection of the curve is degenerate (a point).
  Z2 projected_on_patch(const int* la, const int* lb, const std::array<Z2, 4>& Phi) const {
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

  static Z2 swap_uv(const Z2& g) { return typename CGAL::Polynomial_traits_d<Z2>::Swap()(g, 0, 1); }

  // A polynomial in the inner variable vanishing at the inner coordinate of every common zero of g1, g2: Res_v, or
  // when g1 (g2) does not depend on the outer variable, g1[0] (g2[0]), or gcd(g1[0], g2[0]) if neither does.
  static Z1 eliminant(const Z2& g1, const Z2& g2) {
    if (g1.degree() < 1 && g2.degree() < 1) return Z1(CGAL::gcd(g1[0], g2[0]));
    if (g1.degree() < 1) return g1[0];
    if (g2.degree() < 1) return g2[0];
    return outer_resultant(g1, g2);
  }

  // Res_v(g1, g2) by the Sylvester matrix in the outer variable (entries in Z[u]).
  static Z1 outer_resultant(const Z2& g1, const Z2& g2) {
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

  void add_point(Curve_patch_intersection_result& res, const Algebraic_real& r, const Algebraic_real& u,
                 const Algebraic_real& v, int multiplicity) const {
    Curve_patch_intersection_point p;
    p.r = r;
    p.u = u;
    p.v = v;
    p.multiplicity = multiplicity;
    p.tangent = multiplicity >= 2;
    if (is_zero_or_one(r))
      p.kind = Curve_patch_intersection_kind::endpoint;
    else if (is_zero_or_one(u) || is_zero_or_one(v))
      p.kind = Curve_patch_intersection_kind::boundary;
    else
      p.kind = p.tangent ? Curve_patch_intersection_kind::tangent : Curve_patch_intersection_kind::transversal;
    p.point = curve_.evaluate(r.to_double());
    res.points.push_back(p);
  }

  // ------------------------------------------------------------------ patches with base points
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
  void base_point_case(Curve_patch_intersection_result& res) {
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
    CS_TICK("base-point eliminant");
    for (const Isolated_root& root : separated_roots(R_, Rational(0), Rational(1))) {
      std::vector<std::pair<int, Rational>> skip;
      for (const auto& h : hits)
        if (h.first == root.root) skip.push_back(h.second);
      add_fibre(res, root.root, skip);
    }
  }

  // Is the iso-line u = t (dir 0) or v = t (dir 1) mapped to one point (p0 : p)? Exact.
  bool collapsed_line(int dir, const Rational& t, Rational& p0, Rational (&p)[3]) const {
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

  Z1 base_point_r_eliminant() const {
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
      CS_TICK("bp: Res_v");
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
      CS_TICK("bp: Res_u");
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

  // ------------------------------------------------------------------ the curve lies on the implicit surface
  struct Break {
    Algebraic_real r;
    std::vector<std::pair<Algebraic_real, Algebraic_real>> uv;  // known preimages (from the boundary curves)
  };

  // C([0,1]) is in the algebraic surface. The set {r : C(r) in Phi([0,1]^2)} can change only where C meets the
  // image of the boundary of [0,1]^2 (where Phi is a local homeomorphism onto the surface): breakpoints are
  // r = 0, 1 and the parameters of the curve/boundary-curve intersections (intersect_curves, exact); each piece
  // between consecutive breakpoints is decided at a rational point by kernel inversion.
  void on_surface_case(Curve_patch_intersection_result& res) const {
    std::vector<Break> br{Break{Algebraic_real(0), {}}, Break{Algebraic_real(1), {}}};
    for (int side = 0; side < 4; ++side) {
      const Curve b = patch_.boundary_curve<Curve>(side);
      auto uv = [side](const Algebraic_real& t) {
        switch (side) {
          case 0: return std::make_pair(t, Algebraic_real(0));
          case 1: return std::make_pair(Algebraic_real(1), t);
          case 2: return std::make_pair(t, Algebraic_real(1));
          default: return std::make_pair(Algebraic_real(0), t);
        }
      };
      const Curve_intersection_result ci = intersect_curves(curve_, b);
      for (const auto& p : ci.points) br.push_back(Break{p.s, {uv(p.t)}});
      for (const auto& o : ci.overlaps) {
        br.push_back(Break{o.s0, {uv(o.t0)}});
        br.push_back(Break{o.s1, {uv(o.t1)}});
      }
    }
    std::sort(br.begin(), br.end(), [](const Break& a, const Break& b) { return a.r < b.r; });
    std::vector<Break> ub;
    for (const Break& b : br) {
      if (!ub.empty() && ub.back().r == b.r) {
        for (const auto& w : b.uv) {
          bool dup = false;
          for (const auto& z : ub.back().uv) dup = dup || (z.first == w.first && z.second == w.second);
          if (!dup) ub.back().uv.push_back(w);
        }
      } else {
        ub.push_back(b);
      }
    }
    std::vector<char> covered(ub.size() - 1, 0);
    for (std::size_t i = 0; i + 1 < ub.size(); ++i) covered[i] = piece_covered(ub[i].r, ub[i + 1].r);
    for (std::size_t i = 0; i < covered.size();) {
      if (!covered[i]) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j + 1 < covered.size() && covered[j + 1]) ++j;
      res.overlaps.push_back({ub[i].r, ub[j + 1].r});
      i = j + 1;
    }
    // Breakpoints outside every overlap that lie on the patch: isolated touching points.
    for (std::size_t i = 0; i < ub.size(); ++i) {
      const bool in_overlap = (i > 0 && covered[i - 1]) || (i + 1 < ub.size() && covered[i]);
      if (in_overlap) continue;
      std::vector<std::pair<Algebraic_real, Algebraic_real>> uv = ub[i].uv;
      if (uv.empty() && ub[i].r.is_rational()) uv = preimages(curve_(ub[i].r.rational_value()));
      for (const auto& w : uv) {
        add_point(res, ub[i].r, w.first, w.second, 0);
        res.points.back().tangent = false;
      }
    }
  }

  bool piece_covered(const Algebraic_real& a, const Algebraic_real& b) const {
    Rational m = a.is_rational() && b.is_rational() ? (a.rational_value() + b.rational_value()) / 2
                                                    : a.rational_between(b);
    // a few rational points of the open piece, in case the first one is a singular point of the surface
    for (int attempt = 0;; ++attempt) {
      try {
        return !preimages(curve_(m)).empty();
      } catch (const Error&) {
        if (attempt >= 3) throw;
        const Algebraic_real am(m);
        m = am.rational_between(attempt % 2 == 0 ? a : b);
      }
    }
  }

  static void sort_points(Curve_patch_intersection_result& res) {
    std::sort(res.points.begin(), res.points.end(),
              [](const Curve_patch_intersection_point& a, const Curve_patch_intersection_point& b) {
                int c = a.r.compare(b.r);
                if (c == 0) c = a.u.compare(b.u);
                if (c == 0) c = a.v.compare(b.v);
                return c < 0;
              });
  }

  const Curve& curve_;
  const Patch& patch_;
  std::array<Z1, 4> H_;
  std::shared_ptr<Patch_implicit_matrix> matrix_;
  std::vector<std::vector<Z1>> M_;
  bool have_minors_ = false;
  Q1 D11_, Du_, Dv_;
  Z1 R_;  // det M(C(r))
  bool have_eliminants_ = false;
  Z1 U_, V_;
  std::array<std::vector<Isolated_root>, 2> eliminant_roots_;
  std::array<Z1, 2> removed_lines_{Z1(1), Z1(1)};
};

}  // namespace cs
}  // namespace internal

/// \brief All intersections of the rational Bezier space curve C(r), r in [0,1], with the rational Bezier patch
/// Phi(u,v), (u,v) in [0,1]^2 (du-1989 Problem 2.2b): isolated points (r; u, v) as exact algebraic numbers, and the
/// pieces of the curve lying in the patch (overlaps).
///
/// Method: with M(w,x,y,z) the 2mn x 2mn implicit (Dixon / generalized Bezoutian) matrix of the patch, the roots of
/// R(r) = det M(C(r)) in [0,1] contain every intersection parameter; at each root the kernel of M gives (u,v)
/// exactly (rational roots: exact linear algebra; irrational roots: u = Du/D11, v = Dv/D11 from three cofactors).
/// Where the kernel does not give a unique preimage (the curve crosses a self-intersection curve of the patch, a
/// patch covering its image several times, or a singular point of the surface), the grid step reports every
/// preimage (u,v) in [0,1]^2: the candidates are the roots of the eliminants U(u), V(v), each excluded by interval
/// arithmetic or proved by a Krawczyk test in (r,u,v) (exact decision when r, u, v are rational).
/// Patches with base points (det M == 0, e.g. collapsed edges of rational sphere patches, or polynomial patches with
/// base points at infinity): every root of an eliminant built from U, V (see base_point_case) goes through the
/// grid step; a collapsed edge through which the curve passes is reported once, with collapsed_line set.
/// Requirements: no pole of the curve on [0,1] or of the patch on [0,1]^2 (Invalid_input), bi-degree >= (1,1)
/// (Invalid_input). Error (not supported) when such a preimage is a singular solution with two or three irrational
/// coordinates (the curve tangent to one sheet of a self-intersection, or through a singular point of the surface,
/// at irrational parameters), when the curve runs along a patch with base points (or a constant curve meets one),
/// or when no projection gives nonzero eliminants U, V. A constant curve gives the overlap [0,1] if its point is on
/// the patch, nothing otherwise.
inline Curve_patch_intersection_result intersect_curve_patch(const Rational_bezier_curve<Rational, 3>& curve,
                                                              const Rational_bezier_patch<Rational>& patch) {
  return internal::cs::Curve_patch_engine(curve, patch).run();
}

/// \brief Intersections of the segment a + r (b - a), r in [0,1], with the patch (du-1989 Problem 2.2a): the
/// degree-1 case of intersect_curve_patch. a == b: the point case (overlap [0,1] if the point is on the patch).
inline Curve_patch_intersection_result intersect_segment_patch(const std::array<Rational, 3>& a,
                                                                const std::array<Rational, 3>& b,
                                                                const Rational_bezier_patch<Rational>& patch) {
  return intersect_curve_patch(Rational_bezier_curve<Rational, 3>(std::vector<std::array<Rational, 3>>{a, b}), patch);
}

/// Function object form (CGAL style).
struct Intersect_curve_patch {
  Curve_patch_intersection_result operator()(const Rational_bezier_curve<Rational, 3>& curve,
                                             const Rational_bezier_patch<Rational>& patch) const {
    return intersect_curve_patch(curve, patch);
  }
};

}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERSECTION_CURVE_SURFACE_INTERSECTION_H
