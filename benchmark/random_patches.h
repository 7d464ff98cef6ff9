// Seeded random patches shared by the benchmarks: integer control points in [-5,5], weights in [1,4].
#ifndef BEZOUTIAN_BENCHMARK_RANDOM_PATCHES_H
#define BEZOUTIAN_BENCHMARK_RANDOM_PATCHES_H
#include <bezoutian/geometry/Rational_bezier_patch.h>
#include <random>
#include <vector>

inline bezoutian::Rational_bezier_patch<> random_patch(std::mt19937& g, int m, int n, bool rational) {
  using Q = bezoutian::Rational;
  using Patch = bezoutian::Rational_bezier_patch<>;
  std::uniform_int_distribution<int> c(-5, 5), w(1, 4);
  std::vector<std::vector<Patch::Point>> p(m + 1, std::vector<Patch::Point>(n + 1));
  std::vector<std::vector<Q>> wt(m + 1, std::vector<Q>(n + 1, Q(1)));
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j) {
      p[i][j] = {Q(c(g)), Q(c(g)), Q(c(g))};
      if (rational) wt[i][j] = Q(w(g));
    }
  return Patch(p, wt);
}
#endif
