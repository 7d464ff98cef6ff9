// SISL as a benchmark-only peer (benchmark/install-peers.sh, Debian libsisl-dev): a rational Bezier patch as a
// SISL B-spline surface (one knot span per direction), and the intersection of two of them: s1859 finds the
// intersection points and the curve seeds, s1310 marches each curve. Compiled only when the benchmark's CMake found
// SISL (BEZOUTIAN_WITH_SISL).
#ifndef BEZOUTIAN_BENCHMARK_SISL_PEER_H
#define BEZOUTIAN_BENCHMARK_SISL_PEER_H

#ifdef BEZOUTIAN_WITH_SISL
#include <bezoutian/geometry/Rational_bezier_patch.h>

#include <sisl.h>

#include <cstdlib>
#include <vector>

namespace sisl_peer {

/// The patch as a SISL surface: order m + 1 by n + 1, knots (0, ..., 0, 1, ..., 1), homogeneous coefficients
/// (w x, w y, w z, w) with the first direction (u) running fastest; rational only when the weights differ.
inline SISLSurf* surface(const bezoutian::Rational_bezier_patch<>& p) {
  const int m = p.degree_u(), n = p.degree_v();
  std::vector<double> ku(std::size_t(2 * (m + 1))), kv(std::size_t(2 * (n + 1)));
  for (int i = 0; i <= m; ++i) ku[std::size_t(i)] = 0, ku[std::size_t(m + 1 + i)] = 1;
  for (int j = 0; j <= n; ++j) kv[std::size_t(j)] = 0, kv[std::size_t(n + 1 + j)] = 1;
  bool rational = false;
  const auto& h00 = p.homogeneous_control_point(0, 0);
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j) rational = rational || p.homogeneous_control_point(std::size_t(i), std::size_t(j))[0] != h00[0];
  std::vector<double> c;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= m; ++i) {
      const auto& h = p.homogeneous_control_point(std::size_t(i), std::size_t(j));
      const double w = CGAL::to_double(h[0]);
      for (int d = 1; d <= 3; ++d) c.push_back(CGAL::to_double(h[std::size_t(d)] / h[0]) * (rational ? w : 1));
      if (rational) c.push_back(w);
    }
  return newSurf(m + 1, n + 1, m + 1, n + 1, ku.data(), kv.data(), c.data(), rational ? 2 : 1, 3, 1);
}

/// s1859 (relative tolerance 0, geometric tolerance 1e-7), then s1310 on each curve: whether s1859 succeeded, its
/// isolated points, its curves, and how many of them s1310 marched.
struct Result {
  bool done = false;
  int points = 0, curves = 0, marched = 0;
};

inline Result intersect(SISLSurf* a, SISLSurf* b) {
  Result out;
  int points = 0, curves = 0, status = 0;
  double *par1 = nullptr, *par2 = nullptr;
  SISLIntcurve** wcurve = nullptr;
  s1859(a, b, 0.0, 1e-7, &points, &par1, &par2, &curves, &wcurve, &status);
  out.done = status >= 0;
  out.points = points;
  out.curves = curves;
  for (int k = 0; k < curves; ++k) {
    int march = 0;
    s1310(a, b, wcurve[k], 1e-7, 0.0, 1, 0, &march);
    out.marched += march >= 0 && wcurve[k]->pgeom != nullptr;
    freeIntcurve(wcurve[k]);
  }
  std::free(wcurve);
  std::free(par1);
  std::free(par2);
  return out;
}

}  // namespace sisl_peer
#endif

#endif  // BEZOUTIAN_BENCHMARK_SISL_PEER_H
