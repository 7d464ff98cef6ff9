// Curve/patch and segment/patch intersection timings (doc/curve_surface_intersection.md, "Timings").
// Run: build with -DBEZOUTIAN_BUILD_BENCHMARKS=ON, then ./curve_surface_benchmark [problems per row, default 10].
// Per row: seeded random patches of bi-degree (m,n) (random_patches.h; polynomial and rational) and random curves of
// degree d through a constructed common point C(2/7) = Phi(3/5, 1/4); median and maximum wall time per problem.
#include "random_patches.h"

#include <bezoutian/intersection/Curve_surface_intersection.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

using namespace bezoutian;
using Q = Rational;
using P3 = std::array<Q, 3>;

int main(int argc, char** argv) {
  const int count = argc > 1 ? std::atoi(argv[1]) : 10;
  std::printf("%-6s %-8s %-9s %12s %12s %10s\n", "curve", "patch", "weights", "median ms", "max ms", "points");
  std::mt19937 g(2024);
  std::uniform_int_distribution<int> c(-5, 5), w(1, 4);
  for (int d : {1, 2, 3})
    for (int mn : {1, 2, 3})
      for (int rational = 0; rational < 2; ++rational) {
        std::vector<double> ms;
        std::size_t points = 0;
        for (int k = 0; k < count; ++k) {
          const auto patch = random_patch(g, mn, mn, rational == 1);
          std::vector<P3> pts;
          std::vector<Q> wt;
          for (int i = 0; i <= d; ++i) {
            pts.push_back({Q(c(g)), Q(c(g)), Q(c(g))});
            wt.push_back(rational ? Q(w(g)) : Q(1));
          }
          Rational_bezier_curve_3<Q> curve(pts, wt);
          const P3 target = patch(Q(3, 5), Q(1, 4)), at = curve(Q(2, 7));
          for (auto& p : pts)
            for (int j = 0; j < 3; ++j) p[j] += target[j] - at[j];
          curve = Rational_bezier_curve_3<Q>(pts, wt);
          const auto t0 = std::chrono::steady_clock::now();
          const auto res = intersect_curve_patch(curve, patch);
          ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
          points += res.points.size();
        }
        std::sort(ms.begin(), ms.end());
        std::printf("%-6d %d,%-6d %-9s %12.2f %12.2f %10.1f\n", d, mn, mn, rational ? "rational" : "poly",
                    ms[ms.size() / 2], ms.back(), double(points) / count);
      }
}
