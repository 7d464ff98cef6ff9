// Measures CGAL::Algebraic_kernel_d_1 root isolation with the GMP arithmetic kernel against the CORE
// arithmetic kernel (CGAL's default) on the same seeded random polynomials; the basis of the choice of
// the GMP kernel recorded in doc/design.md.
// Build: g++ -O2 -std=c++17 -DCGAL_USE_GMP -DCGAL_USE_MPFI -DCGAL_USE_CORE benchmark/arithmetic_kernel_choice.cpp -lCGAL_Core -lmpfi -lmpfr -lgmp
//   (on Debian bookworm CORE is header-only inside CGAL 5.5: drop -lCGAL_Core if it is not found)
#include <CGAL/Arithmetic_kernel.h>
#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/CORE_arithmetic_kernel.h>
#include <CGAL/GMP_arithmetic_kernel.h>

#include <chrono>
#include <iostream>
#include <random>
#include <vector>

template <class AK>
double run(int degree, int count, unsigned seed, std::size_t& roots) {
  using Integer = typename AK::Integer;
  using K = CGAL::Algebraic_kernel_d_1<Integer>;
  using P = typename K::Polynomial_1;
  K k;
  std::mt19937 g(seed);
  std::uniform_int_distribution<int> d(-1000, 1000);
  std::vector<P> polys;
  for (int c = 0; c < count; ++c) {
    std::vector<Integer> co;
    for (int i = 0; i <= degree; ++i) co.push_back(Integer(d(g)));
    polys.emplace_back(co.begin(), co.end());
  }
  auto t0 = std::chrono::steady_clock::now();
  for (const P& p : polys) {
    std::vector<std::pair<typename K::Algebraic_real_1, typename K::Multiplicity_type>> r;
    k.solve_1_object()(p, std::back_inserter(r));
    roots += r.size();
    // comparisons and refinement to 1e-30 exercise the number type
    for (std::size_t i = 0; i + 1 < r.size(); ++i) roots += (k.compare_1_object()(r[i].first, r[i + 1].first) < 0);
    for (auto& x : r) k.approximate_relative_1_object()(x.first, 100);
  }
  auto t1 = std::chrono::steady_clock::now();
  return std::chrono::duration<double, std::milli>(t1 - t0).count() / count;
}

int main() {
  std::cout << "degree  GMP kernel [ms/poly]  CORE kernel [ms/poly]  ratio CORE/GMP\n";
  for (int degree : {10, 30, 60, 100}) {
    std::size_t r1 = 0, r2 = 0;
    double g = run<CGAL::GMP_arithmetic_kernel>(degree, 20, 42 + degree, r1);
    double c = run<CGAL::CORE_arithmetic_kernel>(degree, 20, 42 + degree, r2);
    std::cout << degree << "  " << g << "  " << c << "  " << c / g << (r1 == r2 ? "" : "  (root counts differ!)") << "\n";
  }
}
