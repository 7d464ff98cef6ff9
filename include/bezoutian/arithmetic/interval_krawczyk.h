// Interval arithmetic on MPFI (outward rounding) and the Krawczyk test for the intersection of two plane curves
// in homogeneous power form: a proof that a parameter box holds exactly one common point.
#ifndef BEZOUTIAN_ARITHMETIC_INTERVAL_KRAWCZYK_H
#define BEZOUTIAN_ARITHMETIC_INTERVAL_KRAWCZYK_H

#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/arithmetic/mpfi_interval.h>

#include <CGAL/Polynomial.h>

#include <mpfi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace bezoutian {
namespace internal {

/// Krawczyk's test in R^N (Krawczyk 1969; Moore 1977). `value(c, F)` writes an enclosure of F(c) for the point
/// box c (the midpoint of X), `jacobian(X, J)` an enclosure of F' over the box X (J[i][j] = dF_i/dx_j). With Y the
/// inverse of the midpoint of J,
///   K(X) = c - Y F(c) + (I - Y F'(X)) (X - c);
/// K(X) in the interior of X proves that X holds exactly one zero of F and that F' is regular there (the zero is
/// simple). `jacobian` receives an N x N std::vector<std::vector<Mpfi_interval>>. Returns true only with that proof; then X is replaced by K(X) and contracted `iterations` more times
/// (X <- K(X) ∩ X keeps the zero: every zero in X lies in K(X)).
template <std::size_t N, class Value, class Jacobian>
bool krawczyk_prove(std::array<Mpfi_interval, N>& X, Value value, Jacobian jacobian, int iterations = 0) {
  using I = Mpfi_interval;
  const mpfr_prec_t prec = X[0].prec();
  for (int round = 0; round <= iterations; ++round) {
    std::array<I, N> c = X, F = X;
    for (std::size_t i = 0; i < N; ++i) c[i] = X[i].midpoint();
    value(c, F);
    std::vector<std::vector<I>> J(N, std::vector<I>(N, I::point(0, prec)));
    jacobian(X, J);
    // Y = mid(J)^-1 by Gauss-Jordan with partial pivoting (any Y gives a valid test; a good one a sharp one)
    double M[N][2 * N];
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = 0; j < N; ++j) {
        M[i][j] = J[i][j].mid_double();
        M[i][N + j] = i == j ? 1.0 : 0.0;
      }
    for (std::size_t col = 0; col < N; ++col) {
      std::size_t piv = col;
      for (std::size_t r = col + 1; r < N; ++r)
        if (std::fabs(M[r][col]) > std::fabs(M[piv][col])) piv = r;
      if (!(std::fabs(M[piv][col]) > 0) || !std::isfinite(M[piv][col])) return round > 0;
      for (std::size_t j = 0; j < 2 * N; ++j) std::swap(M[col][j], M[piv][j]);
      const double d = M[col][col];
      for (std::size_t j = 0; j < 2 * N; ++j) M[col][j] /= d;
      for (std::size_t r = 0; r < N; ++r)
        if (r != col && M[r][col] != 0) {
          const double f = M[r][col];
          for (std::size_t j = 0; j < 2 * N; ++j) M[r][j] -= f * M[col][j];
        }
    }
    std::array<I, N> K = X;
    bool inside = true;
    for (std::size_t i = 0; i < N; ++i) {
      I k = c[i];
      for (std::size_t j = 0; j < N; ++j) k = k - M[i][N + j] * F[j];
      for (std::size_t l = 0; l < N; ++l) {
        I m = I::point(i == l ? 1.0 : 0.0, prec);
        for (std::size_t j = 0; j < N; ++j) m = m - M[i][N + j] * J[j][l];
        k = k + m * (X[l] - c[l]);
      }
      if (!std::isfinite(k.width_double())) return round > 0;
      if (round == 0 && !k.strictly_inside(X[i])) inside = false;
      K[i] = k;
    }
    if (round == 0 && !inside) return false;
    for (std::size_t i = 0; i < N; ++i) {
      I r(prec);
      mpfi_intersect(r.get(), K[i].get(), X[i].get());
      if (mpfi_is_empty(r.get())) return true;  // cannot happen after a proof; keep X
      X[i] = r;
    }
  }
  return true;
}

/// Values and derivatives of a homogeneous plane form (W, X, Y)(u) on an interval.
struct Form_enclosure {
  std::array<Mpfi_interval, 3> f, df;
  Form_enclosure(const std::array<Polynomial_1<Integer>, 3>& F, const Mpfi_interval& u)
      : f{Mpfi_interval::horner(F[0], u), Mpfi_interval::horner(F[1], u), Mpfi_interval::horner(F[2], u)},
        df{Mpfi_interval::horner(CGAL::differentiate(F[0]), u), Mpfi_interval::horner(CGAL::differentiate(F[1]), u),
           Mpfi_interval::horner(CGAL::differentiate(F[2]), u)} {}
};

/// Krawczyk's operator in MPFI at precision `prec` for G_k(s,t) = A_k(s) B_0(t) - B_k(t) A_0(s), k = 1, 2
/// (integer power forms) on the box X = S x T: K(X) = c - Y G(c) + (I - Y G'(X)) (X - c), c the midpoint, Y the
/// inverse of the midpoint Jacobian. Every zero of G in X lies in K(X) (mean value form). False if Y or K is not
/// finite.
inline bool planar_krawczyk_operator(const std::array<Polynomial_1<Integer>, 3>& A,
                                     const std::array<Polynomial_1<Integer>, 3>& B, const Mpfi_interval X[2],
                                     Mpfi_interval K[2], mpfr_prec_t prec) {
  using I = Mpfi_interval;
  const I cs = X[0].midpoint(), ct = X[1].midpoint();
  const Form_enclosure a(A, X[0]), b(B, X[1]), ac(A, cs), bc(B, ct);
  I J[2][2] = {{I(prec), I(prec)}, {I(prec), I(prec)}};
  I G[2] = {I(prec), I(prec)};
  for (int k = 1; k <= 2; ++k) {
    J[k - 1][0] = a.df[k] * b.f[0] - b.f[k] * a.df[0];
    J[k - 1][1] = a.f[k] * b.df[0] - b.df[k] * a.f[0];
    G[k - 1] = ac.f[k] * bc.f[0] - bc.f[k] * ac.f[0];
  }
  const double m00 = J[0][0].mid_double(), m01 = J[0][1].mid_double(), m10 = J[1][0].mid_double(),
               m11 = J[1][1].mid_double();
  const double det = m00 * m11 - m01 * m10;
  if (!std::isfinite(det) || det == 0) return false;
  const double Y[2][2] = {{m11 / det, -m01 / det}, {-m10 / det, m00 / det}};
  if (!std::isfinite(Y[0][0]) || !std::isfinite(Y[0][1]) || !std::isfinite(Y[1][0]) || !std::isfinite(Y[1][1]))
    return false;
  const I one = I::point(1, prec), zero = I::point(0, prec);
  const I c[2] = {cs, ct};
  const I d[2] = {X[0] - cs, X[1] - ct};
  for (int i = 0; i < 2; ++i) {
    const I yg = Y[i][0] * G[0] + Y[i][1] * G[1];
    const I m0 = (i == 0 ? one : zero) - (Y[i][0] * J[0][0] + Y[i][1] * J[1][0]);
    const I m1 = (i == 1 ? one : zero) - (Y[i][0] * J[0][1] + Y[i][1] * J[1][1]);
    K[i] = c[i] - yg + m0 * d[0] + m1 * d[1];
    if (!std::isfinite(K[i].width_double())) return false;
  }
  return true;
}

/// Krawczyk's test (Krawczyk 1969; Moore 1977) for G_k(s,t) = A_k(s) B_0(t) - B_k(t) A_0(s), k = 1, 2, the
/// intersection of the plane curves A = (A_0 : A_1 : A_2)(s) and B(t) in homogeneous power form, on the box X =
/// (s_lo, s_hi) x (t_lo, t_hi): K(X) (planar_krawczyk_operator) inside the open box proves that X holds exactly
/// one zero of G (and that G' is regular on X: the zero is a transversal intersection). Returns true only with
/// that proof; false means "not proved".
inline bool krawczyk_unique_intersection(const std::array<Polynomial_1<Integer>, 3>& A,
                                         const std::array<Polynomial_1<Integer>, 3>& B, const Rational& s_lo,
                                         const Rational& s_hi, const Rational& t_lo, const Rational& t_hi,
                                         mpfr_prec_t prec) {
  using I = Mpfi_interval;
  const I X[2] = {I::hull(s_lo, s_hi, prec), I::hull(t_lo, t_hi, prec)};
  I K[2] = {I(prec), I(prec)};
  if (!planar_krawczyk_operator(A, B, X, K, prec)) return false;
  return K[0].inside_open(s_lo, s_hi) && K[1].inside_open(t_lo, t_hi);
}

} // namespace internal
} // namespace bezoutian

#endif
