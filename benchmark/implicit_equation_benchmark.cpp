// The implicit equation D of the self-intersection and intersection problems of seeded random
// patches (integer control points in [-5,5], weights in [1,4] for rational ones, as benchmark/surface_benchmark.cpp),
// our engine against
//   (b) Berkowitz's division-free determinant (berkowitz_determinant, CGAL polynomials) of the same matrix,
//   (c) a cascade of CGAL resultants eliminating the same variables (classical elimination, no Bezoutian):
//       intersection: F_i = Phi_i(u,v) Psi_0(s,t) - Psi_i(s,t) Phi_0(u,v), R1 = Res_v(F1,F2), R2 = Res_v(F1,F3),
//       R = Res_s(R1,R2) in Z[u,t] after dividing R1, R2 by all powers of Psi_0(s,t); self-intersection (Theorem 4's
//       Phi(u,v+k) = Phi(u+l,v)): Phi(u,t') = Phi(s,v) eliminating t' then s, after removing the factors (s-u)^k
//       of R1, R2 that come from the trivial solution (s,t') = (u,v);
//       D must divide R (checked by exact univariate pseudo-division of R(u,t0) by D(u,t0) at 3 integers t0),
//   (d) Singular's det of the same matrix (script written to /tmp/bench3/case_N.sing, run with `Singular -q`,
//       wall time measured inside Singular with rtimer); its det is compared with our D up to a constant by
//       exact evaluation at two random integer points.
// (b) and (c) run in a forked child killed after the time limit; "-" means not attempted or not finished.
// Build: g++ -O2 -std=c++17 -DNDEBUG -DCGAL_USE_GMP -DCGAL_USE_MPFI -Iinclude benchmark/implicit_equation_benchmark.cpp -o implicit_equation_benchmark -lmpfi -lmpfr -lgmp
// Run:   ./implicit_equation_benchmark [time_limit_s=60] [berkowitz_max_size=9] [cascade_max_size=9]
#include "random_patches.h"
#include <bezoutian/elimination/Implicit_equation.h>

#include <CGAL/Polynomial.h>
#include <CGAL/Polynomial_traits_d.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace bezoutian;
using Q = Rational;
using Z = Integer;
using Patch = Rational_bezier_patch<>;
using P1 = Polynomial_1<Z>;
using P2 = Polynomial_2<Z>;
using P3 = CGAL::Polynomial<P2>;
using P4 = CGAL::Polynomial<P3>;


static double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Runs f() (returning a one-line result) in a forked child; "" if it did not finish within `limit` seconds.
template <class F>
static std::string run_with_limit(double limit, F f) {
  int fd[2];
  if (pipe(fd) != 0) return "";
  std::cout.flush();
  pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    std::string s = f() + "\n";
    if (write(fd[1], s.data(), s.size()) < 0) _exit(1);
    _exit(0);
  }
  close(fd[1]);
  const auto t0 = std::chrono::steady_clock::now();
  int status = 0;
  bool done = false;
  while (seconds_since(t0) < limit) {
    if (waitpid(pid, &status, WNOHANG) == pid) { done = true; break; }
    usleep(20000);
  }
  if (!done) { kill(pid, SIGKILL); waitpid(pid, &status, 0); close(fd[0]); return ""; }
  std::string out;
  char buf[4096];
  ssize_t k;
  while ((k = read(fd[0], buf, sizeof buf)) > 0) out.append(buf, k);
  close(fd[0]);
  while (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

// Phi_k(x_a, x_b) as a polynomial in 4 variables x0 (innermost) .. x3 (outermost).
static P4 embed(const Polynomial_2<Q>& p, int a, int b) {
  std::vector<std::pair<CGAL::Exponent_vector, Z>> terms;
  for (int j = 0; j <= p.degree(); ++j)
    for (int i = 0; i <= p[j].degree(); ++i) {
      if (CGAL::is_zero(p[j][i])) continue;
      if (p[j][i].denominator() != 1) throw std::logic_error("power form with non-integer coefficient");
      std::vector<int> e(4, 0);
      e[a] += i;
      e[b] += j;
      terms.emplace_back(CGAL::Exponent_vector(e), p[j][i].numerator());
    }
  if (terms.empty()) return P4(0);
  return CGAL::Polynomial_traits_d<P4>::Construct_polynomial()(terms.begin(), terms.end());
}

// R / d^k for the largest k (exact: pseudo-division remainder zero, then integral division).
static P3 remove_factor(P3 R, const P3& d) {
  while (!CGAL::is_zero(R) && d.degree() > 0) {
    P3 q, r;
    P2 D;
    P3::pseudo_division(R, d, q, r, D);
    if (!CGAL::is_zero(r)) break;
    R = CGAL::integral_division(R, d);
  }
  return R;
}

// Classical elimination: the resultant cascade of the header comment, an element of Z[u,t] (or Z[u,v]).
static P2 resultant_cascade(const std::array<Polynomial_2<Q>, 4>& f, const std::array<Polynomial_2<Q>, 4>& g,
                            bool self) {
  // intersection Phi(u,v) = Psi(s,t): u=x0, t=x1, s=x2, v=x3 (v eliminated first, then s).
  // self-intersection (Theorem 4's form Phi(u,v+k) = Phi(u+l,v), i.e. Phi(u,t') = Phi(s,v) with t' = v+k,
  // s = u+l): the same embedding with Psi = Phi, where x3 plays t' and x1 plays v.
  const int fa = 0, fb = 3, ga = 2, gb = 1;
  std::array<P4, 4> F, G;
  for (int k = 0; k < 4; ++k) F[k] = embed(f[k], fa, fb), G[k] = embed(g[k], ga, gb);
  std::array<P4, 3> E;
  for (int i = 0; i < 3; ++i) E[i] = F[i + 1] * G[0] - G[i + 1] * F[0];
  P3 R1 = CGAL::resultant(E[0], E[1]), R2 = CGAL::resultant(E[0], E[2]);
  // Trivial solution (s,t') = (u,v) of the self-intersection system: factors (s-u)^k.
  if (self) {
    const P3 diagonal(P2(P1(Z(0), Z(-1))), P2(1));  // s - u
    R1 = remove_factor(R1, diagonal), R2 = remove_factor(R2, diagonal);
  }
  // Rational patches: where Psi_0(s, x1) = 0 the E_i reduce to -Psi_i Phi_0(u,x3), which share the roots of
  // Phi_0(u,x3) in x3: Psi_0(s,x1) divides R1 and R2 and would make Res_s vanish identically.
  if (!CGAL::is_zero(G[0]) && (G[0].degree() > 0 || G[0][0].degree() > 0)) {
    // G[0] does not involve x3: its x3-constant coefficient is Psi_0 in Z[x0,x1,x2]
    const P3 w = G[0][0];
    R1 = remove_factor(R1, w), R2 = remove_factor(R2, w);
  }
  return CGAL::resultant(R1, R2);
}

// D(u, t0) divides R(u, t0) in Q[u] for three integers t0 (exact pseudo-division).
static std::string divides_at_specializations(const P2& D, const P2& R) {
  if (CGAL::is_zero(R)) return "R=0";
  for (int t0 : {7, -12, 31}) {
    // D(u,t0), R(u,t0): substitute the outer variable (Horner)
    P1 Dt(0), Rt(0);
    for (int j = D.degree(); j >= 0; --j) Dt = Dt * P1(Z(t0)) + D[j];
    for (int j = R.degree(); j >= 0; --j) Rt = Rt * P1(Z(t0)) + R[j];
    if (CGAL::is_zero(Dt)) continue;
    P1 q, r;
    Z c;
    P1::pseudo_division(Rt, Dt, q, r, c);
    if (!CGAL::is_zero(r)) return "NO";
  }
  return "yes";
}

static int degree_in(const P2& p, int var) { return Implicit_equation::degree_of(p, var); }

static std::string singular_script(const Bezoutian_matrix& B, const std::vector<std::pair<int, int>>& pts) {
  std::ostringstream s;
  const std::size_t n = B.size();
  s << "ring r=0,(u,v),dp;\n";  // v stands for the second free parameter (v or t)
  s << "matrix M[" << n << "][" << n << "]=";
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      const Polynomial_2<Q>& e = B.entries[i][j];
      std::ostringstream t;
      bool first = true;
      for (int b = 0; b <= e.degree(); ++b)
        for (int a = 0; a <= e[b].degree(); ++a) {
          if (CGAL::is_zero(e[b][a])) continue;
          t << (first ? "" : "+") << "(" << e[b][a] << ")*u^" << a << "*v^" << b;
          first = false;
        }
      s << (first ? "0" : t.str()) << (i + 1 == n && j + 1 == n ? ";\n" : ",\n");
    }
  s << "system(\"--ticks-per-sec\",1000);\nint t0=rtimer;\npoly d=det(M);\nint t1=rtimer-t0;\n";
  s << "print(\"TIME\");print(t1);\n";
  for (auto p : pts) s << "print(\"VAL\");print(subst(subst(d,u," << p.first << "),v," << p.second << "));\n";
  s << "quit;\n";
  return s.str();
}

static Z eval(const P2& D, int a, int b) {
  Z acc(0);
  for (int j = D.degree(); j >= 0; --j) acc = acc * Z(b) + D[j].evaluate(Z(a));
  return acc;
}

static std::string fmt(double x) {
  if (x < 0) return "-";
  std::ostringstream o;
  o << std::setprecision(3) << x;
  return o.str();
}

int main(int argc, char** argv) {
  const double limit = argc > 1 ? std::atof(argv[1]) : 60;
  const std::size_t berkowitz_max = argc > 2 ? std::atoi(argv[2]) : 9;
  const std::size_t cascade_max = argc > 3 ? std::atoi(argv[3]) : 9;
  mkdir("/tmp/bench3", 0755);
  const bool have_singular = std::system("command -v Singular >/dev/null 2>&1") == 0;
  std::mt19937 g(20261122);
  std::cout << "case | problem | bi-degree | kind | n | deg D (u,p1) | ours[s] | Berkowitz[s] | B/ours | "
               "cascade[s] | C/ours | D divides R | Singular[s] | S/ours | Singular det = c*D\n";
  int case_no = 0;
  struct Case { bool self; int m, n; bool rational; };
  std::vector<Case> cases;
  for (bool self : {true, false})
    for (auto mn : std::vector<std::pair<int, int>>{{2, 2}, {3, 2}, {3, 3}, {4, 4}})
      for (bool rational : {false, true})
        if (self || mn.first < 4) cases.push_back({self, mn.first, mn.second, rational});
  for (const Case& c : cases) {
    ++case_no;
    const Patch a = random_patch(g, c.m, c.n, c.rational), b = random_patch(g, c.m, c.n, c.rational);
    auto t0 = std::chrono::steady_clock::now();
    const Implicit_equation e = c.self ? self_intersection_equation(a) : intersection_equation(a, b);
    const double t_ours = seconds_since(t0);
    const std::size_t n = e.matrix.size();

    double t_berk = -1;
    if (n <= berkowitz_max) {
      const std::string r = run_with_limit(limit, [&] {
        const auto t = std::chrono::steady_clock::now();
        const Polynomial_2<Q> d = berkowitz_determinant(e.matrix.entries);
        const double s = seconds_since(t);
        const bool same = normalized_primitive_part(internal::integer_multiple(d)) == e.determinant;
        return std::to_string(s) + (same ? " same" : " DIFFERENT");
      });
      if (!r.empty()) {
        t_berk = std::atof(r.c_str());
        if (r.find("DIFFERENT") != std::string::npos) std::cout << "!! Berkowitz determinant differs\n";
      }
    }

    double t_casc = -1;
    std::string divides = "-";
    if (n <= cascade_max) {
      const auto f = a.power_form(), h = c.self ? a.power_form() : b.power_form();
      const std::string r = run_with_limit(limit, [&] {
        const auto t = std::chrono::steady_clock::now();
        const P2 R = resultant_cascade(f, h, c.self);
        const double s = seconds_since(t);
        std::ostringstream o;
        o << s << " " << divides_at_specializations(e.determinant, R) << "(deg_R=" << degree_in(R, 0) << ","
          << degree_in(R, 1) << ")";
        return o.str();
      });
      if (!r.empty()) {
        std::istringstream in(r);
        in >> t_casc >> divides;
      }
    }

    double t_sing = -1;
    std::string agree = have_singular ? "-" : "Singular not installed";
    if (have_singular) {
      std::uniform_int_distribution<int> pt(-9, 9);
      std::vector<std::pair<int, int>> pts{{pt(g), pt(g)}, {pt(g), pt(g)}};
      const std::string base = "/tmp/bench3/case_" + std::to_string(case_no);
      std::ofstream(base + ".sing") << singular_script(e.matrix, pts);
      std::ostringstream cmd;
      cmd << "timeout " << int(limit) << " Singular -q " << base << ".sing > " << base << ".out 2>&1";
      if (std::system(cmd.str().c_str()) == 0) {
        std::ifstream in(base + ".out");
        std::string line, tag;
        std::vector<Q> vals;
        while (std::getline(in, line)) {
          if (line == "TIME" || line == "VAL") { tag = line; continue; }
          if (tag == "TIME") t_sing = std::atof(line.c_str()) / 1000.0;
          if (tag == "VAL") vals.push_back(Q(line));
          tag.clear();
        }
        if (vals.size() == 2) {
          const Z d0 = eval(e.determinant, pts[0].first, pts[0].second),
                  d1 = eval(e.determinant, pts[1].first, pts[1].second);
          const bool ok = vals[0] * Q(d1) == vals[1] * Q(d0) && !(CGAL::is_zero(vals[0]) && CGAL::is_zero(vals[1]));
          agree = ok ? "yes" : "NO";
        }
      }
    }
    auto ratio = [&](double x) { return x < 0 ? std::string("-") : fmt(x / t_ours); };
    std::cout << case_no << " | " << (c.self ? "self" : "pair") << " | (" << c.m << "," << c.n << ") | "
              << (c.rational ? "rational" : "polynomial") << " | " << n << " | (" << e.degree(0) << ","
              << e.degree(1) << ") | " << fmt(t_ours) << " | " << fmt(t_berk) << " | " << ratio(t_berk) << " | "
              << fmt(t_casc) << " | " << ratio(t_casc) << " | " << divides << " | " << fmt(t_sing) << " | "
              << ratio(t_sing) << " | " << agree << std::endl;
  }
}
