// Curve/curve intersection timings: du-1989 Tables 4.1/4.2 protocol (3D rational and polynomial curves, degrees
// 3-2 .. 3-6, 0-4 known intersections, N problems each, median per strategy) and planar pairs of degree 7 and 12.
//   curve_intersection_benchmark [N=10] [N_planar_7=10] [N_planar_12=2]
#include <bezoutian/Curve_intersection.h>
#include <bezoutian/Curve_problem_generator.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

using namespace bezoutian;

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

template <int D>
double time_ms(const Curve_problem<D>& p, Curve_intersection_method m) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = intersect_curves(p.curve_1, p.curve_2, m);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (r.points.size() < p.known.size()) std::printf("ERROR: missing intersections\n");
  return ms;
}

} // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 10;
  const int n7 = argc > 2 ? std::atoi(argv[2]) : 10;
  const int n12 = argc > 3 ? std::atoi(argv[3]) : 2;
  const Curve_intersection_method methods[] = {Curve_intersection_method::default_method,
                                                Curve_intersection_method::subresultant,
                                                Curve_intersection_method::projection,
                                                Curve_intersection_method::resolvent};
  std::printf("du-1989 protocol, 3D, %d problems per cell, median ms: default / subresultant / projection / resolvent\n", n);
  for (int rat = 1; rat >= 0; --rat) {
    std::printf("%s curves\n  deg  ", rat ? "rational" : "polynomial");
    for (int k = 0; k <= 4; ++k) std::printf("   k=%d                         ", k);
    std::printf("\n");
    for (int n2 = 2; n2 <= 6; ++n2) {
      std::printf("  3-%d ", n2);
      for (int k = 0; k <= 4; ++k) {
        if (k > n2 + 1) {  // the generator needs k <= degree_2 + 1 (blank in du-1989's tables too)
          std::printf("      -/     -/     -/     -  ");
          continue;
        }
        std::vector<double> t[4];
        for (int i = 0; i < n; ++i) {
          Curve_problem_parameters par;
          par.degree_1 = 3;
          par.degree_2 = n2;
          par.intersections = k;
          par.rational = rat == 1;
          par.range = 16;
          par.seed = 100000UL * n2 + 1000UL * k + 10UL * i + rat;
          const auto p = generate_curve_problem<3>(par);
          for (int m = 0; m < 4; ++m) t[m].push_back(time_ms(p, methods[m]));
        }
        std::printf(" %6.2f/%6.2f/%6.2f/%6.2f ", median(t[0]), median(t[1]), median(t[2]), median(t[3]));
      }
      std::printf("\n");
    }
  }
  const int planar[][2] = {{3, 3}, {5, 5}, {7, n7}, {12, n12}};
  for (const auto& d : planar) {
    std::vector<double> t[3];
    for (int i = 0; i < d[1]; ++i) {
      Curve_problem_parameters par;
      par.degree_1 = par.degree_2 = d[0];
      par.intersections = 2 + i % 3;
      par.rational = i % 2 == 0;
      par.range = 16;
      par.seed = 777 + i;
      const auto p = generate_curve_problem<2>(par);
      t[0].push_back(time_ms(p, Curve_intersection_method::default_method));
      t[1].push_back(time_ms(p, Curve_intersection_method::projection));
      if (d[0] <= 7) t[2].push_back(time_ms(p, Curve_intersection_method::subresultant));
    }
    std::printf("planar degree %d-%d, %d problems (2-4 known intersections, rational and polynomial): median %.2f ms "
                "default, %.2f ms projection, %.2f ms subresultant (not run above degree 7)\n", d[0], d[0], d[1],
                median(t[0]), median(t[1]), median(t[2]));
  }
  return 0;
}
