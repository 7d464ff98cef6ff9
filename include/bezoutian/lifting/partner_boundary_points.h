// Arc points whose partner lies exactly on the boundary of the partner domain where the crossing test of
// partner_domain_crossings.h cannot decide: at a corner (two cylinders of one radius crossing: the intersection curve
// leaves both patches at the corner they share; the other coordinate is on its side too, so no interval box shows it
// inside the closed domain), or where the partner touches a side or a corner and turns back (two orthogonal
// extrusions: the crossing system is singular there). Such points of symmetric models are often rational: the
// floating-point point is polished by damped Gauss-Newton on the three partner equations with the partner's
// coordinates near a side fixed on it, replaced by the simplest rationals next to it, and kept only if E vanishes
// there exactly with nonzero weights (a point of D = 0 with a partner in the closed domain: genuine, proved).
#ifndef BEZOUTIAN_LIFTING_PARTNER_BOUNDARY_POINTS_H
#define BEZOUTIAN_LIFTING_PARTNER_BOUNDARY_POINTS_H

#include <bezoutian/arithmetic/simplest_rational.h>
#include <bezoutian/lifting/double_partner_witness.h>
#include <bezoutian/topology/Curve_topology.h>

#include <array>
#include <cmath>
#include <complex>
#include <optional>
#include <utility>
#include <vector>

namespace bezoutian {
namespace internal {

/// A point x of D = 0 with the partner y on the boundary of the partner domain, both exact.
struct Partner_boundary_point {
  std::array<Rational, 2> x, y;
};

/// The exact point of the header comment near the floating-point arc point x0 with partner y0, if a coordinate of
/// y0 lies within 0.05 of the domain's size of its side (intersection of two patches only: a self-intersection's
/// partner domain moves with x).
inline std::optional<Partner_boundary_point> exact_boundary_point(const Partner_equations& eq,
                                                                  const Parameter_box& domain,
                                                                  const std::array<double, 2>& x0,
                                                                  const std::array<double, 2>& y0) {
  if (eq.self_intersection()) return std::nullopt;
  const double scale = std::max(CGAL::to_double(domain.u1 - domain.u0), CGAL::to_double(domain.v1 - domain.v0));
  // the partner (y1, y2) = (v, s): v in [v0, v1], s in [u0, u1]; a coordinate near a side is fixed on it
  const std::array<std::pair<Rational, Rational>, 2> range{std::make_pair(domain.v0, domain.v1),
                                                           std::make_pair(domain.u0, domain.u1)};
  std::array<bool, 2> fixed{false, false};
  std::array<Rational, 2> side;
  std::vector<int> unknowns{0, 1};  // indices into z = (x1, x2, y1, y2)
  for (int c = 0; c < 2; ++c) {
    const auto& r = range[std::size_t(c)];
    const double d0 = std::fabs(y0[std::size_t(c)] - CGAL::to_double(r.first)),
                 d1 = std::fabs(y0[std::size_t(c)] - CGAL::to_double(r.second));
    fixed[std::size_t(c)] = std::min(d0, d1) <= 0.05 * scale;
    side[std::size_t(c)] = d0 <= d1 ? r.first : r.second;
    if (!fixed[std::size_t(c)]) unknowns.push_back(2 + c);
  }
  if (!fixed[0] && !fixed[1]) return std::nullopt;
  const std::size_t n = unknowns.size();
  // damped Gauss-Newton (floating point; at a touch the Jacobian may be singular); the simplest rationals next to
  // the start and next to the result are the candidates
  using C = std::complex<double>;
  std::array<double, 4> z{x0[0], x0[1], y0[0], y0[1]};
  for (int c = 0; c < 2; ++c)
    if (fixed[std::size_t(c)]) z[std::size_t(2 + c)] = CGAL::to_double(side[std::size_t(c)]);
  const std::array<double, 4> start = z;
  for (int it = 0; it < 30; ++it) {
    std::array<C, 3> E;
    std::array<std::array<C, 4>, 3> J;
    eq.evaluate({C(z[0]), C(z[1]), C(z[2]), C(z[3])}, E, J);
    double A[3][4] = {};  // the normal equations J^T J s = J^T E, augmented
    double trace = 0;
    for (std::size_t a = 0; a < n; ++a) {
      for (std::size_t b = 0; b < n; ++b)
        for (int r = 0; r < 3; ++r) A[a][b] += J[r][std::size_t(unknowns[a])].real() * J[r][std::size_t(unknowns[b])].real();
      for (int r = 0; r < 3; ++r) A[a][n] += J[r][std::size_t(unknowns[a])].real() * E[r].real();
      trace += A[a][a];
    }
    for (std::size_t a = 0; a < n; ++a) A[a][a] += 1e-12 * trace;
    bool solved = true;  // Gaussian elimination with partial pivoting
    for (std::size_t col = 0; col < n && solved; ++col) {
      std::size_t piv = col;
      for (std::size_t r = col + 1; r < n; ++r)
        if (std::fabs(A[r][col]) > std::fabs(A[piv][col])) piv = r;
      if (!(std::fabs(A[piv][col]) > 0)) solved = false;
      for (std::size_t c = 0; c <= n && solved; ++c) std::swap(A[col][c], A[piv][c]);
      for (std::size_t r = 0; r < n && solved; ++r) {
        if (r == col) continue;
        const double f = A[r][col] / A[col][col];
        for (std::size_t c = col; c <= n; ++c) A[r][c] -= f * A[col][c];
      }
    }
    if (!solved) break;
    double step = 0;
    for (std::size_t a = 0; a < n; ++a) step += std::fabs(A[a][n] / A[a][a]);
    if (!(step < 0.1 * scale)) break;
    for (std::size_t a = 0; a < n; ++a) z[std::size_t(unknowns[a])] -= A[a][n] / A[a][a];
    if (step <= 1e-15 * (1 + std::fabs(z[0]) + std::fabs(z[1]) + std::fabs(z[2]) + std::fabs(z[3]))) break;
  }
  for (const auto& w : {start, z}) {
    if (!(std::fabs(w[0] - x0[0]) + std::fabs(w[1] - x0[1]) <= 0.1 * scale)) continue;
    std::array<Rational, 4> q;
    bool simple = true;
    for (int c = 0; c < 4 && simple; ++c) {
      if (c >= 2 && fixed[std::size_t(c - 2)]) {
        q[std::size_t(c)] = side[std::size_t(c - 2)];
        continue;
      }
      const double r = 1e-10 * (1 + std::fabs(w[std::size_t(c)]));
      simple = simplest_rational_in(Rational(w[std::size_t(c)] - r), Rational(w[std::size_t(c)] + r), q[std::size_t(c)]);
    }
    if (!simple) continue;
    // both patch points in the closed domain: P = (x1, y1), Q = (y2, x2)
    if (!(domain.u0 <= q[0] && q[0] <= domain.u1 && domain.v0 <= q[1] && q[1] <= domain.v1 && domain.v0 <= q[2] &&
          q[2] <= domain.v1 && domain.u0 <= q[3] && q[3] <= domain.u1))
      continue;
    std::array<Rational, 2> weights;
    const std::array<Rational, 3> E = eq.exact_values(q, weights);
    if (E[0] == 0 && E[1] == 0 && E[2] == 0 && weights[0] != 0 && weights[1] != 0)
      return Partner_boundary_point{{q[0], q[1]}, {q[2], q[3]}};
  }
  return std::nullopt;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_LIFTING_PARTNER_BOUNDARY_POINTS_H
