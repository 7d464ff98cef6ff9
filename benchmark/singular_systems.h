// The curve intersection system F_k(s,t) = X1_k(s) W2(t) - X2_k(t) W1(s), k = 1..D, written in Singular's syntax
// (shared by the benchmarks that time Singular on the same systems).
#ifndef BEZOUTIAN_BENCHMARK_SINGULAR_SYSTEMS_H
#define BEZOUTIAN_BENCHMARK_SINGULAR_SYSTEMS_H

#include <bezoutian/intersection/Curve_intersection.h>
#include <bezoutian/geometry/Curve_problem_generator.h>

#include <sstream>
#include <string>

template <int D>
std::string singular_ideal(const bezoutian::Curve_problem<D>& p) {
  using namespace bezoutian;
  const auto H1 = internal::integer_power_form(p.curve_1), H2 = internal::integer_power_form(p.curve_2);
  std::ostringstream o;
  for (int k = 1; k <= D; ++k) {
    const auto F = internal::cross_term(H1[k], H2[0], H2[k], H1[0]);
    std::ostringstream f;
    bool first = true;
    for (int j = 0; j <= F.degree(); ++j)
      for (int i = 0; !CGAL::is_zero(F[j]) && i <= F[j].degree(); ++i)
        if (!CGAL::is_zero(F[j][i])) {
          f << (first ? "" : "+") << "(" << F[j][i] << ")*s^" << i << "*t^" << j;
          first = false;
        }
    o << (k > 1 ? ", " : "") << (first ? "0" : f.str());
  }
  return o.str();
}

#endif  // BEZOUTIAN_BENCHMARK_SINGULAR_SYSTEMS_H
