// The grid step of intersect_curve_patch: the preimages (u, v) over a root r_i of R(r) = det M(C(r)) where the
// kernel of the implicit matrix gives no unique preimage (several sheets, a singular point of the surface).
// At a root r_i of R where the kernel of M(C(r_i)) does not give a unique preimage, every intersection
// (r_i, u, v) has u a root of U and v a root of V (compute_eliminants), so the intersections over r_i are among
// the grid points (r_i, u_j, v_k). Each grid point is excluded by interval evaluation of
// F_k(r,u,v) = W(r) Phi_k(u,v) - X_k(r) Phi_0(u,v), proved by Krawczyk's test, or decided exactly (at most one
// irrational coordinate). Proofs: doc/curve_surface_intersection.md, step 4b.
//
// Internal header: not part of the public API.
#ifndef BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_PATCH_FIBRES_H
#define BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_PATCH_FIBRES_H

#include <bezoutian/intersection/internal/curve_patch_implicit_matrix.h>

#include <bezoutian/algebraic/Algebraic_real.h>
#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/arithmetic/interval_krawczyk.h>
#include <bezoutian/arithmetic/number_types.h>

#include <CGAL/Polynomial.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace bezoutian {
namespace internal {
namespace cs {

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

}  // namespace cs
}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_PATCH_FIBRES_H
