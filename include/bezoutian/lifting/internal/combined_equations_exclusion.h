// Exclusion by preconditioned combinations of the partner equations.
//
// The three partner equations E_1, E_2, E_3 in the four unknowns z = (x, y) have no common zero in a box Z as
// soon as one combination g = lambda . E (lambda any real vector) has none there; its mean value form
//   g(Z) subset lambda . E(c) + sum_i (lambda . dE/dz_i (Z)) (Z_i - c_i),   c the centre of Z,
// is a valid enclosure for every lambda, so the choice of lambda is free and only decides how tight it is.
//
// Near a tangential contact of the surfaces (a plane 1e-6 below a sphere meets it in a circle of radius 1.4e-3)
// the 3 x 4 Jacobian dE/dz is nearly of rank 2: each single E_c has an O(1) gradient, but on the solution curve
// the three are nearly dependent, and the gap that separates a point z off the curve from a common zero is seen
// only by the combination along the weak direction, where it is of the size of the smallest singular value
// sigma_3 times the distance. A single E_c then needs boxes of that gap's size, sigma_3 times smaller than the
// combination does. The left singular vectors of the midpoint Jacobian J_c (the eigenvectors of J_c J_c^T)
// give the combinations whose gradients are the singular values; all three are tried. Floating point only chooses
// lambda; the test itself is the interval enclosure above.
#ifndef BEZOUTIAN_LIFTING_INTERNAL_COMBINED_EQUATIONS_EXCLUSION_H
#define BEZOUTIAN_LIFTING_INTERNAL_COMBINED_EQUATIONS_EXCLUSION_H

#include <bezoutian/arithmetic/double_interval.h>

#include <array>
#include <cmath>
#include <utility>

namespace bezoutian {
namespace internal {

/// The eigenvectors (rows of the result, orthonormal up to rounding) of a symmetric 3 x 3 matrix, by cyclic
/// Jacobi rotations. Used only to choose combinations; no proof depends on their accuracy.
inline std::array<std::array<double, 3>, 3> symmetric_eigenvectors_3(std::array<std::array<double, 3>, 3> a) {
  std::array<std::array<double, 3>, 3> v{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  for (int sweep = 0; sweep < 32; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    if (!(off > 1e-30 * diag)) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0) continue;
        // the rotation in the (p, q) plane that zeroes a[p][q]
        const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
        const double t = (theta >= 0 ? 1 : -1) / (std::fabs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (int k = 0; k < 3; ++k) {  // a <- a R (columns p, q)
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) {  // a <- R^T a (rows p, q)
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 3; ++k) {  // eigenvectors as rows: v <- R^T v
          const double vp = v[p][k], vq = v[q][k];
          v[p][k] = c * vp - s * vq;
          v[q][k] = s * vp + c * vq;
        }
      }
  }
  return v;
}

/// True when a combination lambda . E along a left singular vector lambda of the midpoint of J excludes 0 on the
/// box (see the header comment): `Ec` encloses E at the centre c, `J` encloses dE/dz on the box, `dz` = Z - c.
/// The rows of J with a non-finite midpoint leave the test undecided (false).
inline bool combination_excludes_zero(const std::array<Double_interval, 3>& Ec,
                                      const std::array<std::array<Double_interval, 4>, 3>& J,
                                      const std::array<Double_interval, 4>& dz) {
  using D = Double_interval;
  std::array<std::array<double, 4>, 3> m;
  for (int r = 0; r < 3; ++r)
    for (int i = 0; i < 4; ++i) {
      m[r][i] = J[r][i].mid();
      if (!std::isfinite(m[r][i])) return false;
    }
  // rows scaled to unit length first, so that a large equation does not hide the others
  std::array<double, 3> scale;
  for (int r = 0; r < 3; ++r) {
    double n = 0;
    for (int i = 0; i < 4; ++i) n += m[r][i] * m[r][i];
    if (!(n > 0) || !std::isfinite(n)) return false;
    scale[r] = 1 / std::sqrt(n);
    for (int i = 0; i < 4; ++i) m[r][i] *= scale[r];
  }
  std::array<std::array<double, 3>, 3> gram;
  for (int r = 0; r < 3; ++r)
    for (int q = 0; q < 3; ++q) {
      double g = 0;
      for (int i = 0; i < 4; ++i) g += m[r][i] * m[q][i];
      gram[r][q] = g;
    }
  const auto directions = symmetric_eigenvectors_3(gram);
  for (const auto& d : directions) {
    std::array<D, 3> lambda;
    for (int r = 0; r < 3; ++r) {
      const double l = d[r] * scale[r];  // the combination of the unscaled equations
      if (!std::isfinite(l)) return false;
      lambda[r] = D{l, l};
    }
    D g = lambda[0] * Ec[0] + lambda[1] * Ec[1] + lambda[2] * Ec[2];
    for (int i = 0; i < 4; ++i) g = g + (lambda[0] * J[0][i] + lambda[1] * J[1][i] + lambda[2] * J[2][i]) * dz[i];
    if (!g.contains_zero()) return true;
  }
  return false;
}

} // namespace internal
} // namespace bezoutian

#endif // BEZOUTIAN_LIFTING_INTERNAL_COMBINED_EQUATIONS_EXCLUSION_H
