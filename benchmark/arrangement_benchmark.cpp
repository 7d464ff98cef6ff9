// Arrangements of seeded random polynomial Bezier curves: Arr_rational_bezier_traits_2 (ours) side by side with
// CGAL's Arr_Bezier_curve_traits_2 (CORE number types, as in CGAL's Bezier example), same inputs, one run.
// Each arrangement is computed in a forked child process, so that its peak memory (ru_maxrss from wait4) is its
// own and a crash of one traits class is reported instead of ending the benchmark.
//   arrangement_benchmark [SETS="3:20,3:40,5:20,tangent:40"] [SEED=1] [FILE.dat ...]
// SETS lists degree:count pairs, and tangent:N for N tangency stress cases (a random cubic and its mirror image
// across its tangent line at a rational parameter, each pair its own arrangement), grid:N for N degenerate sets
// (10 cubics with control points on the grid [0,6)^2: shared end points, overlaps, tangencies); files are CGAL Bezier .dat
// files (e.g. CGAL's Bezier example data, examples/Arrangement_on_surface_2/Bezier.dat in libcgal-demo).
#include <bezoutian/Arr_rational_bezier_traits_2.h>
#include <bezoutian/io/Geometry_document.h>

#include <CGAL/Arrangement_2.h>
#include <CGAL/Cartesian.h>
#include <CGAL/CORE_algebraic_number_traits.h>
#include <CGAL/Arr_Bezier_curve_traits_2.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Net = std::vector<std::pair<bezoutian::Rational, bezoutian::Rational>>;

struct Outcome {
  bool ok = false;
  long v = 0, e = 0, f = 0;
  int valid = 0;
  double ms = 0;
  long max_rss_kb = 0;
  std::string error;
};

// Runs f() in a child; f returns "v e f valid ms" or throws.
template <class F>
Outcome in_child(F f) {
  int fd[2];
  if (pipe(fd) != 0) std::abort();
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    std::string s;
    try {
      s = f();
    } catch (const std::exception& e) {
      s = std::string("error ") + e.what();
    }
    if (write(fd[1], s.data(), s.size()) < 0) _exit(2);
    _exit(0);
  }
  close(fd[1]);
  std::string s;
  char buf[512];
  ssize_t k;
  while ((k = read(fd[0], buf, sizeof buf)) > 0) s.append(buf, buf + k);
  close(fd[0]);
  int status = 0;
  struct rusage ru;
  wait4(pid, &status, 0, &ru);
  Outcome o;
  o.max_rss_kb = ru.ru_maxrss;
  if (!WIFEXITED(status)) {
    o.error = "crashed (signal " + std::to_string(WIFSIGNALED(status) ? WTERMSIG(status) : 0) + ")";
    return o;
  }
  if (s.rfind("error", 0) == 0 || s.empty()) {
    o.error = s.empty() ? "no result" : s;
    return o;
  }
  std::istringstream in(s);
  in >> o.v >> o.e >> o.f >> o.valid >> o.ms;
  o.ok = true;
  return o;
}

template <class Arr>
std::string summary(const Arr& arr, double ms) {
  std::ostringstream out;
  out << arr.number_of_vertices() << " " << arr.number_of_edges() << " " << arr.number_of_faces() << " "
      << int(arr.is_valid()) << " " << ms;
  return out.str();
}

std::string run_ours(const std::vector<Net>& nets) {
  using Traits = bezoutian::Arr_rational_bezier_traits_2;
  std::vector<Traits::Curve_2> cs;
  for (const Net& n : nets) {
    std::vector<Traits::Curve_2::Point> p;
    for (const auto& q : n) p.push_back({q.first, q.second});
    cs.push_back(Traits::Curve_2(p));
  }
  const auto t0 = std::chrono::steady_clock::now();
  Traits tr;
  CGAL::Arrangement_2<Traits> arr(&tr);
  CGAL::insert(arr, cs.begin(), cs.end());
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return summary(arr, ms);
}

std::string run_cgal(const std::vector<Net>& nets) {
  using Nt = CGAL::CORE_algebraic_number_traits;
  using Rat_kernel = CGAL::Cartesian<Nt::Rational>;
  using Alg_kernel = CGAL::Cartesian<Nt::Algebraic>;
  using Traits = CGAL::Arr_Bezier_curve_traits_2<Rat_kernel, Alg_kernel, Nt>;
  std::vector<Traits::Curve_2> cs;
  for (const Net& n : nets) {
    std::vector<Rat_kernel::Point_2> p;
    for (const auto& q : n) {
      // exact conversion through the decimal string of the fraction
      std::ostringstream a, b;
      a << q.first;
      b << q.second;
      p.push_back(Rat_kernel::Point_2(Nt::Rational(a.str()), Nt::Rational(b.str())));
    }
    cs.push_back(Traits::Curve_2(p.begin(), p.end()));
  }
  const auto t0 = std::chrono::steady_clock::now();
  Traits tr;
  CGAL::Arrangement_2<Traits> arr(&tr);
  CGAL::insert(arr, cs.begin(), cs.end());
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return summary(arr, ms);
}

std::vector<Net> random_nets(unsigned seed, int n, int degree, unsigned range = 1000) {
  std::mt19937 g(seed);
  std::vector<Net> nets;
  for (int i = 0; i < n; ++i) {
    Net net;
    for (int j = 0; j <= degree; ++j) {
      const long x = long(g() % range), y = long(g() % range);
      net.push_back({bezoutian::Rational(x), bezoutian::Rational(y)});
    }
    nets.push_back(net);
  }
  return nets;
}

void report(const std::string& name, const std::vector<Net>& nets) {
  const Outcome a = in_child([&] { return run_ours(nets); });
  const Outcome b = in_child([&] { return run_cgal(nets); });
  auto cell = [](const Outcome& o) {
    char s[160];
    if (!o.ok) std::snprintf(s, sizeof s, "%-34s", o.error.substr(0, 34).c_str());
    else std::snprintf(s, sizeof s, "%5ld/%5ld/%5ld %s %9.1f ms %6ld MB", o.v, o.e, o.f, o.valid ? "ok " : "BAD", o.ms,
                       o.max_rss_kb / 1024);
    return std::string(s);
  };
  const bool same = a.ok && b.ok && a.v == b.v && a.e == b.e && a.f == b.f;
  std::printf("%-18s | ours %s | CGAL %s | %s", name.c_str(), cell(a).c_str(), cell(b).c_str(),
              a.ok && b.ok ? (same ? "same V/E/F" : "V/E/F DIFFER") : "-");
  if (a.ok && b.ok) std::printf(" | CGAL/ours %.1fx", b.ms / a.ms);
  std::printf("\n");
  std::fflush(stdout);
}

// The mirror image of a polynomial control net across the tangent line of the curve at t0 (rational reflection
// matrix for the rational tangent direction (a, b)): the two curves touch at C(t0).
Net mirrored_at(const Net& net, const bezoutian::Rational& t0) {
  bezoutian::Rational_bezier_curve_2<bezoutian::Rational> c([&] {
    std::vector<std::array<bezoutian::Rational, 2>> p;
    for (const auto& q : net) p.push_back({q.first, q.second});
    return p;
  }());
  const auto d = c.derivative()(t0);
  const auto p0 = c(t0);
  const bezoutian::Rational a = d[0], b = d[1], n = a * a + b * b;
  Net out;
  for (const auto& q : net) {
    const bezoutian::Rational x = q.first - p0[0], y = q.second - p0[1];
    out.push_back({p0[0] + ((a * a - b * b) * x + 2 * a * b * y) / n, p0[1] + (2 * a * b * x + (b * b - a * a) * y) / n});
  }
  return out;
}

void tangent_stress(unsigned seed, int n) {
  std::mt19937 g(seed);
  int same = 0, differ = 0, ours_failed = 0, cgal_failed = 0;
  double ours_ms = 0, cgal_ms = 0;
  long ours_kb = 0, cgal_kb = 0;
  for (int i = 0; i < n; ++i) {
    Net c;
    for (int j = 0; j < 4; ++j) c.push_back({bezoutian::Rational(long(g() % 100)), bezoutian::Rational(long(g() % 100))});
    const bezoutian::Rational t0(int(1 + g() % 6), 7);
    const std::vector<Net> nets{c, mirrored_at(c, t0)};
    const Outcome a = in_child([&] { return run_ours(nets); });
    const Outcome b = in_child([&] { return run_cgal(nets); });
    ours_kb = std::max(ours_kb, a.max_rss_kb);
    cgal_kb = std::max(cgal_kb, b.max_rss_kb);
    if (!a.ok || !a.valid) ++ours_failed;
    if (!b.ok || !b.valid) ++cgal_failed;
    if (a.ok && b.ok) {
      ours_ms += a.ms;
      cgal_ms += b.ms;
      (a.v == b.v && a.e == b.e && a.f == b.f) ? ++same : ++differ;
    }
    if (!a.ok) std::printf("  case %d: ours %s\n", i, a.error.c_str());
    if (!b.ok) std::printf("  case %d: CGAL %s\n", i, b.error.c_str());
  }
  std::printf("%-18s | ours failed/invalid %d, CGAL failed/invalid %d | both ran: %d same V/E/F, %d differ | "
              "time where both ran: ours %.1f ms, CGAL %.1f ms | peak %ld / %ld MB\n",
              ("tangent pairs x" + std::to_string(n)).c_str(), ours_failed, cgal_failed, same, differ, ours_ms, cgal_ms,
              ours_kb / 1024, cgal_kb / 1024);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string sets = argc > 1 ? argv[1] : "3:20,3:40,5:20,tangent:40";
  const unsigned seed = argc > 2 ? unsigned(std::atoi(argv[2])) : 1u;
  std::printf("V/E/F valid time peak-memory (forked child each); random control points in [0,1000)^2, seed %u\n", seed);
  std::istringstream in(sets);
  std::string item;
  while (std::getline(in, item, ',')) {
    const auto c = item.find(':');
    if (item.substr(0, c) == "grid") {  // degenerate inputs: 10 cubics on the grid [0,6)^2, N seeds
      for (int k = 0; k < std::atoi(item.substr(c + 1).c_str()); ++k)
        report("grid cubics s" + std::to_string(seed + k), random_nets(seed + k, 10, 3, 6));
      continue;
    }
    if (item.substr(0, c) == "tangent") {
      tangent_stress(seed, std::atoi(item.substr(c + 1).c_str()));
      continue;
    }
    const int degree = std::atoi(item.substr(0, c).c_str()), n = std::atoi(item.substr(c + 1).c_str());
    report(std::to_string(n) + " curves deg " + std::to_string(degree), random_nets(seed, n, degree));
  }
  for (int i = 3; i < argc; ++i) {
    const auto doc = bezoutian::io::read_geometry_file(argv[i]);
    std::vector<Net> nets;
    for (const auto& c : doc.curves_2) {
      if (c.is_rational()) continue;
      Net n;
      for (const auto& p : c.control_points()) n.push_back({p[0], p[1]});
      nets.push_back(n);
    }
    report(argv[i], nets);
  }
}
