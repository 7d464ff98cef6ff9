// Curve/curve intersection timings: du-1989 Tables 4.1/4.2 protocol (3D rational and polynomial curves, degrees
// 3-2 .. 3-6, 0-4 known intersections, N problems each, median per strategy, the default also with its interval
// path off) and planar pairs of degree 7 and 12
// (default = lazy parameters, + materializing every parameter, the exact default path, projection, subresultant).
//   curve_intersection_benchmark [N=10] [N_planar_7=10] [N_planar_12=2] [singular=0]
// With singular=1, Singular's std (lexicographic, t > s) is timed on the same system (F1, F2, F3) for the first
// problem of each 3-2 cell (column after '|'; -1 = not run / not installed).
#include <bezoutian/intersection/Curve_intersection.h>
#include <bezoutian/geometry/Curve_problem_generator.h>

#include "singular_systems.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
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


// Median ms of Singular's std() (lexicographic, t > s: the basis contains the eliminant in s) over the systems,
// timed inside one Singular process (rtimer, 1000 ticks per second); -1 if Singular is not installed.
double singular_median_ms(const std::vector<std::string>& ideals) {
  if (ideals.empty() || std::system("command -v Singular > /dev/null 2>&1") != 0) return -1;
  const std::string script = "/tmp/bezoutian_singular_bench.sing", out = "/tmp/bezoutian_singular_bench.out";
  {
    std::ofstream f(script);
    f << "system(\"--ticks-per-sec\",1000);\nring r=0,(t,s),lp;\noption(redSB);\n";
    for (const auto& I : ideals)
      f << "ideal I = " << I << "; int t0 = rtimer; ideal G = std(I); \"T \" + string(rtimer - t0); kill I, G, t0;\n";
    f << "quit;\n";
  }
  if (std::system(("timeout 900 Singular -q " + script + " > " + out + " 2>&1").c_str()) != 0) return -1;
  std::ifstream in(out);
  std::vector<double> t;
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("T ", 0) == 0) t.push_back(std::atof(line.c_str() + 2));
  return t.size() == ideals.size() ? median(t) : -1;
}

} // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 10;
  const int n7 = argc > 2 ? std::atoi(argv[2]) : 10;
  const int n12 = argc > 3 ? std::atoi(argv[3]) : 2;
  const bool singular = argc > 4 && std::atoi(argv[4]) != 0;  // also time Singular (slow: minutes per system)
  const Curve_intersection_method methods[] = {Curve_intersection_method::default_method,
                                                Curve_intersection_method::subresultant,
                                                Curve_intersection_method::projection,
                                                Curve_intersection_method::resolvent};
  // 3D: "default" is intersect_curves (interval boxes + verified modular shape basis, Curve_intersection.h
  // space_path; the exact default path when that does not settle a pair), "exact" the default method with the
  // interval paths off (the projection/determinant path). Per cell: how many pairs space_path settled.
  std::printf("du-1989 protocol, 3D, %d problems per cell, median ms: default / exact default / subresultant / "
              "projection / resolvent [pairs settled by the interval + shape basis path] | Singular std (lex)\n", n);
  int settled_total = 0, problems_total = 0;
  double worst_median = 0;
  for (int rat = 1; rat >= 0; --rat) {
    std::printf("%s curves\n  deg  ", rat ? "rational" : "polynomial");
    for (int k = 0; k <= 4; ++k) std::printf("   k=%d                                              ", k);
    std::printf("\n");
    for (int n2 = 2; n2 <= 6; ++n2) {
      std::printf("  3-%d ", n2);
      for (int k = 0; k <= 4; ++k) {
        if (k > n2 + 1) {  // the generator needs k <= degree_2 + 1 (blank in du-1989's tables too)
          std::printf("     -/     -/     -/     -/     - [  ] |     -  ");
          continue;
        }
        std::vector<double> t[4], exact;
        int settled = 0;
        std::vector<std::string> ideals;
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
          {
            const auto t0 = std::chrono::steady_clock::now();
            const auto r = internal::Curve_intersection_engine<3>(p.curve_1, p.curve_2,
                                                                  Curve_intersection_method::default_method, false).run();
            exact.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
            if (r.points.size() < p.known.size()) std::printf("ERROR: missing intersections\n");
            Curve_intersection_result q;
            settled += internal::Curve_intersection_engine<3>(p.curve_1, p.curve_2,
                                                              Curve_intersection_method::default_method).space_path(q);
          }
          // Singular's lex std takes minutes per system here: only the first problem of the 3-2 cells
          if (n2 == 2 && i == 0 && singular) ideals.push_back(singular_ideal(p));
        }
        std::printf(" %5.2f/%6.2f/%6.2f/%6.2f/%6.2f [%2d] |%6.1f ", median(t[0]), median(exact), median(t[1]),
                    median(t[2]), median(t[3]), settled, singular_median_ms(ideals));
        settled_total += settled;
        problems_total += n;
        worst_median = std::max(worst_median, median(t[0]));
      }
      std::printf("\n");
    }
  }
  std::printf("3D default: largest cell median %.2f ms; %d of %d pairs settled by the interval + shape basis path\n",
              worst_median, settled_total, problems_total);
  // Planar rows. The default method returns lazy parameters when the interval solver proves every crossing
  // (planar_interval_solver.h): "default" is that time; "+materialize" also makes every s and t exact (eliminants
  // R, T once per pair, then per number an isolating interval and the rationality decision); "exact default" is
  // the default method with the lazy path switched off (multi-modular eliminants, pairing: the pre-lazy path).
  const int planar[][2] = {{3, 3}, {5, 5}, {7, n7}, {12, n12}};
  for (const auto& d : planar) {
    std::vector<double> t[5];
    int lazy = 0;
    for (int i = 0; i < d[1]; ++i) {
      Curve_problem_parameters par;
      par.degree_1 = par.degree_2 = d[0];
      par.intersections = 2 + i % 3;
      par.rational = i % 2 == 0;
      par.range = 16;
      par.seed = 777 + i;
      const auto p = generate_curve_problem<2>(par);
      {
        auto t0 = std::chrono::steady_clock::now();
        const auto r = intersect_curves(p.curve_1, p.curve_2, Curve_intersection_method::default_method);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        if (r.points.size() < p.known.size()) std::printf("ERROR: missing intersections\n");
        bool all_lazy = !r.points.empty();
        for (const auto& q : r.points) all_lazy = all_lazy && q.s.is_lazy() && q.t.is_lazy();
        lazy += all_lazy;
        t0 = std::chrono::steady_clock::now();
        for (const auto& q : r.points) {
          q.s.materialize();
          q.t.materialize();
          (void)q.s.is_rational();
        }
        t[0].push_back(ms);
        t[1].push_back(ms + std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      }
      {
        const auto t0 = std::chrono::steady_clock::now();
        const auto r = internal::Curve_intersection_engine<2>(p.curve_1, p.curve_2,
                                                              Curve_intersection_method::default_method, false).run();
        t[2].push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        if (r.points.size() < p.known.size()) std::printf("ERROR: missing intersections\n");
      }
      t[3].push_back(time_ms(p, Curve_intersection_method::projection));
      if (d[0] <= 7) t[4].push_back(time_ms(p, Curve_intersection_method::subresultant));
    }
    std::printf("planar degree %d-%d, %d problems (2-4 known intersections, rational and polynomial; %d of them all "
                "lazy): median %.2f ms default (lazy), %.2f ms default + materializing every s, t (exact), %.2f ms "
                "exact default path, %.2f ms projection, %.2f ms subresultant (not run above degree 7)\n",
                d[0], d[0], d[1], lazy, median(t[0]), median(t[1]), median(t[2]), median(t[3]), median(t[4]));
  }
  return 0;
}
