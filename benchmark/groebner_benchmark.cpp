// The Groebner strategy (du-1989's third method: a reduced lexicographic basis, here multi-modular and certified
// over Q, Groebner_bivariate.h) against the default method and Singular on the same generated systems: du-1989
// protocol cells (3D rational and polynomial curves of degrees 3-2 .. 3-6) and planar pairs 2-2 .. 6-6, N problems
// per cell with k = 2 known intersections, median ms per problem.
//   groebner_benchmark [N=3] [singular=1] [timeout_s=30]
// Singular (when installed) gets the system F_k = X1_k(s) W2(t) - X2_k(t) W1(s), k = 1..D, in the ring
// (t, s) with lp, timed inside Singular (rtimer, wall clock): modStd (modstd.lib, multi-modular; exactness 1 =
// verified result, its final reductions run in forked processes: a few hundred ms of overhead), std in dp followed by
// fglm to lp, and std in lp; one Singular process per system and algorithm, killed after timeout_s ("  >tmo").
// Our groebner strategy computes the basis of the pair (F1, F2) in both directions (R(s) and T(t)), certified, and
// in space takes the gcd with the other pairs' resultants (Curve_intersection.h strategy_R).
#include <bezoutian/intersection/Curve_intersection.h>
#include <bezoutian/geometry/Curve_problem_generator.h>

#include "singular_systems.h"
#include <bezoutian/elimination/Groebner_bivariate.h>

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
  if (v.empty()) return -1;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

template <int D>
double time_ms(const Curve_problem<D>& p, Curve_intersection_method m, std::size_t& points) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = intersect_curves(p.curve_1, p.curve_2, m);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (r.points.size() < p.known.size()) std::printf("ERROR: missing intersections\n");
  points = r.points.size();
  return ms;
}


// ms inside Singular for one system (mode 0: modStd, 1: std in dp + fglm, 2: std in lp), -1 if Singular is
// missing, -2 on timeout or failure.
double singular_ms(const std::string& ideal, int mode, int timeout_s) {
  static const bool installed = std::system("command -v Singular > /dev/null 2>&1") == 0;
  if (!installed) return -1;
  const std::string script = "/tmp/bezoutian_groebner_bench.sing", out = "/tmp/bezoutian_groebner_bench.out";
  {
    std::ofstream f(script);
    f << "system(\"--ticks-per-sec\",1000);\n";
    if (mode == 0) f << "LIB \"modstd.lib\";\n";
    if (mode == 1) {
      f << "ring r2=0,(t,s),dp;\noption(redSB);\nideal I = " << ideal << ";\nint t0 = rtimer;\nideal J = std(I);\n"
        << "ring r=0,(t,s),lp;\nideal G = fglm(r2, J);\n";
    } else {
      f << "ring r=0,(t,s),lp;\noption(redSB);\nideal I = " << ideal << ";\nint t0 = rtimer;\n"
        << (mode == 0 ? "ideal G = modStd(I);\n" : "ideal G = std(I);\n");
    }
    f << "\"T \" + string(rtimer - t0);\nquit;\n";
  }
  if (std::system(("timeout " + std::to_string(timeout_s) + " Singular -q " + script + " > " + out + " 2>&1").c_str()) != 0)
    return -2;
  std::ifstream in(out);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("T ", 0) == 0) return std::atof(line.c_str() + 2);
  return -2;
}

std::string cell(double ms) {
  char b[32];
  if (ms == -1) return "     -";
  if (ms == -2) return "  >tmo";
  std::snprintf(b, sizeof b, "%8.1f", ms);
  return b;
}

template <int D>
void run_cell(int n1, int n2, bool rational, int N, bool singular, int timeout_s) {
  std::vector<double> def, gb, sg[3];
  bool timeout[3] = {false, false, false};
  for (int i = 0; i < N; ++i) {
    Curve_problem_parameters par;
    par.degree_1 = n1;
    par.degree_2 = n2;
    par.intersections = 2;
    par.rational = rational;
    par.range = 16;
    par.seed = 7000000UL + 10000UL * n1 + 100UL * n2 + 10UL * i + (rational ? 1 : 0) + (D == 3 ? 5 : 0);
    const auto p = generate_curve_problem<D>(par);
    std::size_t a = 0, b = 0;
    def.push_back(time_ms(p, Curve_intersection_method::default_method, a));
    gb.push_back(time_ms(p, Curve_intersection_method::groebner, b));
    if (a != b) std::printf("ERROR: the strategies disagree\n");
    if (singular) {
      const std::string I = singular_ideal(p);
      for (int m = 0; m < 3; ++m) {
        if (timeout[m]) continue;  // once a problem of the cell timed out, the cell is reported as a timeout
        const double x = singular_ms(I, m, timeout_s);
        if (x >= 0) sg[m].push_back(x);
        timeout[m] = x == -2;
      }
    }
  }
  const double mdef = median(def), mgb = median(gb);
  double msg[3];
  for (int m = 0; m < 3; ++m) msg[m] = timeout[m] ? -2 : (singular ? median(sg[m]) : -1);
  std::printf("  %dD %s %d-%d  default %s  groebner %s  (x%.0f)  | Singular modStd %s  dp+fglm %s  lp %s", D,
              rational ? "rational  " : "polynomial", n1, n2, cell(mdef).c_str(), cell(mgb).c_str(), mgb / mdef,
              cell(msg[0]).c_str(), cell(msg[1]).c_str(), cell(msg[2]).c_str());
  if (msg[0] > 0) std::printf("  groebner/modStd %.2f", mgb / msg[0]);
  if (msg[1] > 0) std::printf("  groebner/fglm %.2f", mgb / msg[1]);
  std::printf("\n");
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const int N = argc > 1 ? std::atoi(argv[1]) : 3;
  const bool singular = argc > 2 ? std::atoi(argv[2]) != 0 : true;
  const int timeout_s = argc > 3 ? std::atoi(argv[3]) : 30;
  std::printf("Groebner strategy, %d problems per cell (k = 2), median ms per problem; Singular timeout %d s\n", N,
              timeout_s);
  for (int rat = 1; rat >= 0; --rat)
    for (int n2 = 2; n2 <= 6; ++n2) run_cell<3>(3, n2, rat == 1, N, singular, timeout_s);
  for (int rat = 1; rat >= 0; --rat)
    for (int n = 2; n <= 6; ++n) run_cell<2>(n, n, rat == 1, N, singular, timeout_s);
  return 0;
}
