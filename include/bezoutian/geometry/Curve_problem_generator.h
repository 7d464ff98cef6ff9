// Random curve/curve intersection problems with known intersections (after du-1989 §4.2).
#ifndef BEZOUTIAN_GEOMETRY_CURVE_PROBLEM_GENERATOR_H
#define BEZOUTIAN_GEOMETRY_CURVE_PROBLEM_GENERATOR_H

#include <bezoutian/geometry/Bernstein_basis.h>
#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/geometry/Rational_bezier_curve.h>
#include <bezoutian/arithmetic/number_types.h>

#include <algorithm>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace bezoutian {

/// Parameters of a random problem (du-1989 §4.2: n1, n2, k, rat, range, seed).
struct Curve_problem_parameters {
  int degree_1 = 3, degree_2 = 3;
  int intersections = 2;   ///< k known intersections, k <= degree_2 + 1
  bool rational = true;    ///< random positive weights (no pole on [0,1]); false: polynomial curves
  int range = 64;          ///< numerators and denominators of the random rationals are in [1, range]
  unsigned long seed = 1;
};

/// A generated problem: C2(t_j) = C1(s_j) exactly for the known pairs (s_j, t_j), s_j, t_j distinct in (0,1).
template <int D>
struct Curve_problem {
  Rational_bezier_curve<Rational, D> curve_1, curve_2;
  std::vector<std::pair<Rational, Rational>> known;
};

namespace internal {
inline Rational bernstein_value(int n, int i, const Rational& t) {
  Rational r = binomial<Rational>(n, i);
  for (int k = 0; k < i; ++k) r *= t;
  for (int k = i; k < n; ++k) r *= Rational(1) - t;
  return r;
}
} // namespace internal

/// \brief Random pair of curves with k known intersections.
///
/// du-1989 §4.2 interpolates both curves through random points, the first k of them shared, with random parameters.
/// Here (same outcome, simpler linear algebra): curve 1 has random control points and weights; curve 2 has random
/// weights and control points except k homogeneous control points, which solve the k x k Bernstein collocation system
/// sum_i B_i(t_j) (w_i P_i) = C1(s_j) sum_i B_i(t_j) w_i per coordinate (redrawn if singular).
template <int D>
Curve_problem<D> generate_curve_problem(const Curve_problem_parameters& p) {
  if (p.degree_1 < 1 || p.degree_2 < 1) throw Invalid_input("generate_curve_problem: degrees must be >= 1");
  if (p.intersections < 0 || p.intersections > p.degree_2 + 1)
    throw Invalid_input("generate_curve_problem: k must be in [0, degree_2 + 1]");
  if (p.range < 2) throw Invalid_input("generate_curve_problem: range must be >= 2");
  using Curve = Rational_bezier_curve<Rational, D>;
  std::mt19937_64 rng(p.seed);
  std::uniform_int_distribution<int> num(0, p.range), den(1, p.range);
  auto coordinate = [&] { return Rational(num(rng) - p.range / 2, den(rng)); };
  auto weight = [&] { return p.rational ? Rational(den(rng), den(rng)) : Rational(1); };
  auto parameter = [&] {
    const int d = den(rng) + 1;
    std::uniform_int_distribution<int> n(1, d - 1);
    return Rational(n(rng), d);
  };
  auto distinct_parameters = [&](int k) {
    std::vector<Rational> v;
    while (int(v.size()) < k) {
      Rational x = parameter();
      if (std::find(v.begin(), v.end(), x) == v.end()) v.push_back(x);
    }
    return v;
  };
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::vector<typename Curve::Point> P1(p.degree_1 + 1);
    std::vector<Rational> w1(p.degree_1 + 1);
    for (int i = 0; i <= p.degree_1; ++i) {
      for (int k = 0; k < D; ++k) P1[i][k] = coordinate();
      w1[i] = weight();
    }
    const Curve c1(P1, w1);
    const int n2 = p.degree_2, k = p.intersections;
    const std::vector<Rational> s = distinct_parameters(k), t = distinct_parameters(k);
    std::vector<typename Curve::Homogeneous_point> net(n2 + 1);
    for (int i = 0; i <= n2; ++i) {
      net[i][0] = weight();
      for (int c = 0; c < D; ++c) net[i][c + 1] = net[i][0] * coordinate();
    }
    // Unknowns: homogeneous coordinates of control points u_0..u_{k-1}, spread over the net.
    std::vector<int> unknown;
    for (int j = 0; j < k; ++j) unknown.push_back(k == 1 ? n2 / 2 : (j * n2) / (k - 1 > 0 ? k - 1 : 1));
    std::sort(unknown.begin(), unknown.end());
    unknown.erase(std::unique(unknown.begin(), unknown.end()), unknown.end());
    if (int(unknown.size()) != k) {
      unknown.clear();
      for (int j = 0; j < k; ++j) unknown.push_back(j);
    }
    bool singular = false;
    for (int c = 1; c <= D && !singular; ++c) {
      // rows j: sum_{i in unknown} B_i(t_j) h_i = C1_c(s_j) W2(t_j) - sum_{i known} B_i(t_j) h_i
      std::vector<std::vector<Rational>> A(k, std::vector<Rational>(k + 1));
      for (int j = 0; j < k; ++j) {
        const auto q = c1(s[j]);
        Rational W(0), rhs(0);
        for (int i = 0; i <= n2; ++i) {
          const Rational b = internal::bernstein_value(n2, i, t[j]);
          W += b * net[i][0];
          if (std::find(unknown.begin(), unknown.end(), i) == unknown.end()) rhs -= b * net[i][c];
        }
        rhs += q[c - 1] * W;
        for (int u = 0; u < k; ++u) A[j][u] = internal::bernstein_value(n2, unknown[u], t[j]);
        A[j][k] = rhs;
      }
      // Gauss-Jordan
      for (int col = 0; col < k; ++col) {
        int piv = -1;
        for (int r = col; r < k; ++r)
          if (!CGAL::is_zero(A[r][col])) piv = r;
        if (piv < 0) {
          singular = true;
          break;
        }
        std::swap(A[piv], A[col]);
        for (int r = 0; r < k; ++r)
          if (r != col && !CGAL::is_zero(A[r][col])) {
            const Rational f = A[r][col] / A[col][col];
            for (int cc = col; cc <= k; ++cc) A[r][cc] -= f * A[col][cc];
          }
      }
      if (!singular)
        for (int u = 0; u < k; ++u) net[unknown[u]][c] = A[u][k] / A[u][u];
    }
    if (singular) continue;
    Curve_problem<D> out{c1, Curve::from_homogeneous(net), {}};
    for (int j = 0; j < k; ++j) out.known.push_back({s[j], t[j]});
    return out;
  }
  throw Error("generate_curve_problem: could not build a problem (singular systems)");
}

} // namespace bezoutian

#endif // BEZOUTIAN_GEOMETRY_CURVE_PROBLEM_GENERATOR_H
