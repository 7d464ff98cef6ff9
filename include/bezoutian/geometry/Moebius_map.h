// A Moebius map of one parameter, x -> (a x + b) / (c x + d) with rational coefficients. Substituted into a
// rational Bezier curve or patch of degree m (multiplying the homogeneous coordinates by (c x + d)^m) it gives a
// rational Bezier curve or patch of the same degree over the same point set: every proper reparametrization of a
// rational curve that keeps its degree is of this form, affine maps (c = 0) among them (a de Casteljau
// restriction to [u0, u1] is x -> u0 + (u1 - u0) x).
#ifndef BEZOUTIAN_GEOMETRY_MOEBIUS_MAP_H
#define BEZOUTIAN_GEOMETRY_MOEBIUS_MAP_H

#include <bezoutian/arithmetic/exact_text.h>
#include <bezoutian/arithmetic/number_types.h>

#include <array>
#include <cstddef>
#include <string>

namespace bezoutian {
namespace internal {
// "slope*x + constant" without unit factors and zero terms
inline std::string linear_text(const Rational& slope, const Rational& constant, const std::string& x) {
  auto q = [](const Rational& r) { return io::to_exact_string(r); };
  std::string out;
  if (!CGAL::is_zero(slope))
    out = slope == Rational(1) ? x : slope == Rational(-1) ? "-" + x : q(slope) + "*" + x;
  if (CGAL::is_zero(constant)) return out.empty() ? "0" : out;
  if (out.empty()) return q(constant);
  return out + (CGAL::is_negative(constant) ? " - " + q(-constant) : " + " + q(constant));
}
}  // namespace internal

/// x -> (a x + b) / (c x + d), with a d - b c != 0.
struct Moebius_map {
  Rational a{1}, b{0}, c{0}, d{1};

  Rational operator()(const Rational& x) const { return (a * x + b) / (c * x + d); }
  double operator()(double x) const {
    return (CGAL::to_double(a) * x + CGAL::to_double(b)) / (CGAL::to_double(c) * x + CGAL::to_double(d));
  }
  Moebius_map inverse() const { return {d, -b, -c, a}; }
  bool is_affine() const { return CGAL::is_zero(c); }
  bool is_regular() const { return !CGAL::is_zero(a * d - b * c); }
  /// The denominator c x + d has no zero on [x0, x1]: the map is finite and monotone there.
  bool finite_on(const Rational& x0, const Rational& x1) const {
    const auto s0 = CGAL::sign(c * x0 + d), s1 = CGAL::sign(c * x1 + d);
    return s0 != CGAL::ZERO && s0 == s1;
  }
  /// The image [y0, y1] (y0 <= y1) of [x0, x1]; requires finite_on(x0, x1).
  std::array<Rational, 2> image(const Rational& x0, const Rational& x1) const {
    const Rational y0 = (*this)(x0), y1 = (*this)(x1);
    return y0 <= y1 ? std::array<Rational, 2>{y0, y1} : std::array<Rational, 2>{y1, y0};
  }
  /// The map as a formula in the variable named `x`: "x + 1", "1/2*x + 1/4", "(x - 1)/(x + 1)".
  std::string text(const std::string& x) const {
    if (is_affine()) return internal::linear_text(a / d, b / d, x);
    const bool wrap_num = !CGAL::is_zero(a) && !CGAL::is_zero(b);
    const std::string num = internal::linear_text(a, b, x), den = internal::linear_text(c, d, x);
    return (wrap_num ? "(" + num + ")" : num) + "/" + (CGAL::is_zero(d) ? den : "(" + den + ")");
  }

};

/// The Moebius map through three pairs (x_i, y_i) with distinct x_i and distinct y_i, exactly: the kernel of the
/// linear conditions a x_i + b - c x_i y_i - d y_i = 0. False if no regular map passes through them.
inline bool moebius_through(const std::array<Rational, 3>& x, const std::array<Rational, 3>& y, Moebius_map& out) {
  // rows (x_i, 1, -x_i y_i, -y_i); the kernel of a 3 x 4 matrix of rank 3 is its vector of signed 3 x 3 minors
  std::array<std::array<Rational, 4>, 3> M;
  for (std::size_t i = 0; i < 3; ++i) M[i] = {x[i], Rational(1), -x[i] * y[i], -y[i]};
  auto minor = [&](std::size_t skip) {
    std::array<std::array<Rational, 3>, 3> m;
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0, k = 0; j < 4; ++j)
        if (j != skip) m[i][k++] = M[i][j];
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  Moebius_map f{minor(0), -minor(1), minor(2), -minor(3)};
  if (!f.is_regular()) return false;
  const Rational scale = CGAL::is_zero(f.d) ? f.c : f.d;
  out = {f.a / scale, f.b / scale, f.c / scale, f.d / scale};
  for (std::size_t i = 0; i < 3; ++i)
    if (CGAL::is_zero(out.c * x[i] + out.d) || out(x[i]) != y[i]) return false;
  return true;
}

}  // namespace bezoutian

#endif  // BEZOUTIAN_GEOMETRY_MOEBIUS_MAP_H
