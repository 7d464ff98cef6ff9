// End-to-end timings of the surface layer on seeded random patches (integer control points in [-5,5],
// weights in [1,4] for rational ones): the implicit equation (Bezoutian matrix + determinant) and the
// certified topology of D = 0 in [0,1]^2 (Bernstein subdivision; CGAL's arrangement of D and the box lines up to
// total degree 16 where the subdivision does not certify) with lifting. Side by side in the same run, up to total
// degree cgal_degree (default 14; CGAL needs minutes from degree 20 on), CGAL's whole-plane curve analysis of the same
// square-free D restricted to the box (analyse_curve_in_box: Arr_algebraic_segment_traits_2), and the ratio of its
// time to ours (ours includes the lifting and the phantom exclusion, which CGAL's analysis does not do).
// Build: g++ -O2 -std=c++17 -DNDEBUG -DCGAL_USE_GMP -DCGAL_USE_MPFI -frounding-math -Iinclude benchmark/surface_benchmark.cpp -lmpfi -lmpfr -lgmp
// Run:   ./a.out [skip the topology above this total degree=200] [patches_per_case=3] [cgal_degree=14] [lifting=1]
// (lifting 0: the certified topology alone, without the proofs of the traced points' genuine/phantom status)
#include "random_patches.h"
#include <bezoutian/topology/Cgal_curve_analysis.h>
#include <bezoutian/intersection/Surface_intersection.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <random>

using namespace bezoutian;
using Q = Rational;
using Patch = Rational_bezier_patch<>;


int main(int argc, char** argv) {
  const int max_degree = argc > 1 ? std::atoi(argv[1]) : 200;
  const int count = argc > 2 ? std::atoi(argv[2]) : 3;
  const int cgal_degree = argc > 3 ? std::atoi(argv[3]) : 14;
  const bool lifting = argc > 4 ? std::atoi(argv[4]) != 0 : true;
  std::mt19937 g(20261122);
  std::cout << "case  kind  size  total_degree  implicit[s]  topology+lifting[s]  components  singular  "
               "[traced points whose genuine/phantom status is proved, genuine points]\n";
  for (auto mn : std::vector<std::pair<int, int>>{{2, 2}, {3, 2}, {3, 3}})
    for (bool rational : {false, true})
      for (bool self : {true, false})
        for (int k = 0; k < count; ++k) {
          Patch a = random_patch(g, mn.first, mn.second, rational), b = random_patch(g, mn.first, mn.second, rational);
          auto t0 = std::chrono::steady_clock::now();
          Implicit_equation e = self ? self_intersection_equation(a) : intersection_equation(a, b);
          const double ti = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          std::cout << "(" << mn.first << "," << mn.second << ") " << (rational ? "rational " : "polynomial ")
                    << (self ? "self " : "pair ") << e.matrix.size() << " " << e.total_degree() << " " << ti << std::flush;
          if (e.total_degree() > max_degree) {
            std::cout << "  (topology skipped: total degree above " << max_degree << ")" << std::endl;
            continue;
          }
          t0 = std::chrono::steady_clock::now();
          Surface_intersection_options o;
          o.max_total_degree_for_topology = 16;  // CGAL's analysis only where it is practical
          o.whole_plane_topology = Cgal_curve_analysis{};
          o.certify_lifting = lifting;
          Surface_locus L = self ? self_intersection_locus(a, o) : intersection_locus(a, b, o);
          const double tt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          std::size_t closed = 0, points = 0, proved = 0, genuine = 0;
          for (const auto& c : L.topology.components) closed += c.closed;
          for (const auto& arc : L.arcs)
            for (const auto& q : arc.points) ++points, proved += q.status_proved, genuine += q.genuine;
          std::cout << " " << tt << " " << L.topology.components.size() << " (" << closed << " closed) "
                    << L.topology.number_of_singular_points() << " [status proved " << proved << "/" << points
                    << ", genuine " << genuine << ", split points " << L.split_points.size();
          if (self)
            std::cout << ", pinch points " << L.pinch_points.size() << (L.pinch_points_complete ? " (complete)" : " (incomplete)");
          std::cout << "] "
                    << (L.topology_computed ? L.topology_method : std::string("NOT CERTIFIED: ") + L.note);
          if (e.total_degree() <= cgal_degree) {
            t0 = std::chrono::steady_clock::now();
            const Curve_topology_in_box C = analyse_curve_in_box(e.square_free, Parameter_box{});
            const double tc = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            std::cout << " | CGAL whole-plane analysis of D: " << tc << " s (" << tc / tt << " x ours), "
                      << C.components.size() << " components, " << C.number_of_singular_points() << " singular";
          }
          std::cout << std::endl;
        }
}
