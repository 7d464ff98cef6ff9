// Known-answer check at scale: curve/curve problems of the du-1989 §4.2 generator (Curve_problem_generator.h) and
// tangent problems built the same way, solved by intersect_curves (default method), every answer checked.
//   generated_problems [N=10000] [first_seed=1] [compare_every=1] [first_index=0]
// Problems: plane and space curves, rational and polynomial, degrees 2-6 on both sides, 0-4 constructed
// intersections, and tangent problems (one constructed tangency, plus 0-3 constructed crossings): 820 classes, the
// i-th problem (i = first_index, ..., first_index + N - 1; seed first_seed + i) of class 97 i mod 820, so that every
// 820 consecutive problems cover every class (one problem of a run is rerun with N = 1 and its index). Per problem:
//  * the construction itself is checked exactly (C1(s_j) = C2(t_j); at a tangency C1'(s_0) and C2'(t_0) parallel);
//  * missed: a constructed intersection that is not among the points, as exactly equal algebraic numbers (s_j, t_j)
//    (a constructed tangency must also be reported tangent, otherwise it counts as a wrong kind), or inside a reported
//    overlap (curve 2 on curve 1's algebraic curve: printed, with the number of constructed points it holds);
//  * spurious: a reported point that is not an intersection by an independent check: s a root of CGAL's resultant
//    Res_t(F1, F2), t a root of Res_s(F1, F2) (exact signs; F_k = X1_k W2 - X2_k W1), the two curve points equal to
//    1e-9 in every coordinate after refining s and t to 1e-18 (exact evaluation when s and t are rational);
//  * every compare_every-th problem is also solved by the subresultant strategy, whose answer must be the same
//    (points equal as exact numbers, same multiplicities, kinds and tangency flags): it finds intersections the
//    generator did not construct, so a difference is counted (disagreements) and printed.
// Prints the counts per class and in total, and exits with status 1 if anything was missed, spurious, of the wrong
// kind or in disagreement. test/core/generated_problems_test.cpp runs a few hundred of the same problems.
#include <bezoutian/intersection/Curve_intersection.h>
#include <bezoutian/geometry/Curve_problem_generator.h>

#include <CGAL/Polynomial_traits_d.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace generated_problems {

using namespace bezoutian;

/// One problem: the curves, the constructed intersections, and the index of the constructed tangency (-1: none).
template <int D>
struct Known_problem {
  Curve_problem<D> problem;
  int tangency = -1;  // index into problem.known
};

/// Counts of a run.
struct Counts {
  long problems = 0, constructed = 0, tangencies = 0, points = 0, extra_points = 0;
  long missed = 0, spurious = 0, wrong_kind = 0, overlaps = 0, in_overlap = 0, compared = 0, disagreements = 0, errors = 0;
  double seconds = 0;
  void add(const Counts& o) {
    problems += o.problems, constructed += o.constructed, tangencies += o.tangencies, points += o.points;
    extra_points += o.extra_points, missed += o.missed, spurious += o.spurious, wrong_kind += o.wrong_kind;
    overlaps += o.overlaps, in_overlap += o.in_overlap, compared += o.compared, disagreements += o.disagreements, errors += o.errors;
    seconds += o.seconds;
  }
  bool clean() const { return missed == 0 && spurious == 0 && wrong_kind == 0 && disagreements == 0 && errors == 0; }
};

inline std::string str(const Rational& q) {
  std::ostringstream o;
  o << q;
  return o.str();
}

inline Rational bernstein(int n, int i, const Rational& t) { return internal::bernstein_value(n, i, t); }

// d/dt B_{i,n}(t) = n (B_{i-1,n-1}(t) - B_{i,n-1}(t))
inline Rational bernstein_derivative(int n, int i, const Rational& t) {
  Rational r(0);
  if (i >= 1) r += bernstein(n - 1, i - 1, t);
  if (i <= n - 1) r -= bernstein(n - 1, i, t);
  return Rational(n) * r;
}

// The affine derivative C'(s) of a rational curve (exact): (X' W - X W') / W^2.
template <int D>
std::array<Rational, D> derivative_at(const Rational_bezier_curve<Rational, D>& c, const Rational& s) {
  const int n = c.degree();
  std::array<Rational, D + 1> h, dh;
  for (int k = 0; k <= D; ++k) h[k] = dh[k] = Rational(0);
  for (int i = 0; i <= n; ++i) {
    const Rational b = bernstein(n, i, s), db = bernstein_derivative(n, i, s);
    const auto& q = c.homogeneous_control_point(std::size_t(i));
    for (int k = 0; k <= D; ++k) h[k] += b * q[k], dh[k] += db * q[k];
  }
  std::array<Rational, D> d;
  for (int k = 0; k < D; ++k) d[k] = (dh[k + 1] * h[0] - h[k + 1] * dh[0]) / (h[0] * h[0]);
  return d;
}

template <int D>
bool parallel(const std::array<Rational, D>& a, const std::array<Rational, D>& b) {
  for (int i = 0; i < D; ++i)
    for (int j = i + 1; j < D; ++j)
      if (a[i] * b[j] != a[j] * b[i]) return false;
  return true;
}

/// A problem with one constructed tangency at (s_0, t_0) and k - 1 constructed crossings (1 <= k <= n2): curve 1 is
/// random (the generator's), curve 2 has random weights and control points except 2 + (k - 1) homogeneous control
/// points per coordinate, which solve the linear conditions X2_c(t_j) = C1_c(s_j) W2(t_j) for the k points and
/// X2_c'(t_0) = C1_c(s_0) W2'(t_0) + mu C1_c'(s_0) W2(t_0) (C2'(t_0) = mu C1'(s_0), mu a random nonzero rational).
/// Redrawn when singular or when C1'(s_0) = 0. Returns false after 100 attempts.
template <int D>
bool tangent_problem(int n1, int n2, int k, bool rational, unsigned long seed, Known_problem<D>& out) {
  using Curve = Rational_bezier_curve<Rational, D>;
  std::mt19937_64 rng(seed * 7919 + 17);
  const int range = 16;
  std::uniform_int_distribution<int> num(0, range), den(1, range);
  auto coordinate = [&] { return Rational(num(rng) - range / 2, den(rng)); };
  auto weight = [&] { return rational ? Rational(den(rng), den(rng)) : Rational(1); };
  auto parameter = [&] {
    const int d = den(rng) + 1;
    std::uniform_int_distribution<int> p(1, d - 1);
    return Rational(p(rng), d);
  };
  for (int attempt = 0; attempt < 100; ++attempt) {
    Curve_problem_parameters par;
    par.degree_1 = n1, par.degree_2 = n2, par.intersections = 0, par.rational = rational, par.range = range;
    par.seed = seed * 31 + unsigned(attempt);
    const Curve c1 = generate_curve_problem<D>(par).curve_1;
    std::vector<Rational> s, t;
    while (int(s.size()) < k) {
      const Rational a = parameter(), b = parameter();
      if (std::find(s.begin(), s.end(), a) == s.end() && std::find(t.begin(), t.end(), b) == t.end())
        s.push_back(a), t.push_back(b);
    }
    const auto d1 = derivative_at<D>(c1, s[0]);
    bool zero = true;
    for (int c = 0; c < D; ++c) zero = zero && CGAL::is_zero(d1[c]);
    if (zero) continue;
    Rational mu(den(rng), den(rng));
    if (num(rng) % 2) mu = -mu;
    std::vector<typename Curve::Homogeneous_point> net(std::size_t(n2 + 1));
    for (auto& h : net) {
      h[0] = weight();
      for (int c = 0; c < D; ++c) h[c + 1] = h[0] * coordinate();
    }
    const int m = k + 1;  // conditions per coordinate
    std::vector<int> unknown;
    for (int j = 0; j < m; ++j) unknown.push_back(m == 1 ? 0 : (j * n2) / (m - 1));
    std::sort(unknown.begin(), unknown.end());
    unknown.erase(std::unique(unknown.begin(), unknown.end()), unknown.end());
    if (int(unknown.size()) != m) {
      unknown.clear();
      for (int j = 0; j < m; ++j) unknown.push_back(j);
    }
    auto is_unknown = [&](int i) { return std::find(unknown.begin(), unknown.end(), i) != unknown.end(); };
    bool singular = false;
    for (int c = 1; c <= D && !singular; ++c) {
      // rows: k point conditions, then the derivative condition at t_0; columns: the unknowns, then the right side
      std::vector<std::vector<Rational>> A(std::size_t(m), std::vector<Rational>(std::size_t(m + 1), Rational(0)));
      for (int j = 0; j <= k; ++j) {
        const bool deriv = j == k;
        const Rational tt = deriv ? t[0] : t[std::size_t(j)];
        const auto P = c1(deriv ? s[0] : s[std::size_t(j)]);
        Rational W(0), dW(0), rhs(0);
        for (int i = 0; i <= n2; ++i) {
          const Rational b = deriv ? bernstein_derivative(n2, i, tt) : bernstein(n2, i, tt);
          W += bernstein(n2, i, tt) * net[std::size_t(i)][0];
          dW += bernstein_derivative(n2, i, tt) * net[std::size_t(i)][0];
          if (!is_unknown(i)) rhs -= b * net[std::size_t(i)][std::size_t(c)];
        }
        rhs += deriv ? P[c - 1] * dW + mu * d1[c - 1] * W : P[c - 1] * W;
        for (int u = 0; u < m; ++u)
          A[std::size_t(j)][std::size_t(u)] = deriv ? bernstein_derivative(n2, unknown[std::size_t(u)], tt)
                                                    : bernstein(n2, unknown[std::size_t(u)], tt);
        A[std::size_t(j)][std::size_t(m)] = rhs;
      }
      for (int col = 0; col < m && !singular; ++col) {
        int piv = -1;
        for (int r = col; r < m; ++r)
          if (!CGAL::is_zero(A[std::size_t(r)][std::size_t(col)])) piv = r;
        if (piv < 0) {
          singular = true;
          break;
        }
        std::swap(A[std::size_t(piv)], A[std::size_t(col)]);
        for (int r = 0; r < m; ++r)
          if (r != col && !CGAL::is_zero(A[std::size_t(r)][std::size_t(col)])) {
            const Rational f = A[std::size_t(r)][std::size_t(col)] / A[std::size_t(col)][std::size_t(col)];
            for (int cc = col; cc <= m; ++cc) A[std::size_t(r)][std::size_t(cc)] -= f * A[std::size_t(col)][std::size_t(cc)];
          }
      }
      if (!singular)
        for (int u = 0; u < m; ++u)
          net[std::size_t(unknown[std::size_t(u)])][std::size_t(c)] =
              A[std::size_t(u)][std::size_t(m)] / A[std::size_t(u)][std::size_t(u)];
    }
    if (singular) continue;
    out.problem = Curve_problem<D>{c1, Curve::from_homogeneous(net), {}};
    for (int j = 0; j < k; ++j) out.problem.known.push_back({s[std::size_t(j)], t[std::size_t(j)]});
    out.tangency = 0;
    return true;
  }
  return false;
}

template <int D>
Known_problem<D> transversal_problem(int n1, int n2, int k, bool rational, unsigned long seed) {
  Curve_problem_parameters par;
  par.degree_1 = n1, par.degree_2 = n2, par.intersections = k, par.rational = rational, par.range = 16, par.seed = seed;
  return Known_problem<D>{generate_curve_problem<D>(par), -1};
}

inline bool same_answer(const Curve_intersection_result& a, const Curve_intersection_result& b) {
  if (a.points.size() != b.points.size() || a.overlaps.size() != b.overlaps.size()) return false;
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const auto &p = a.points[i], &q = b.points[i];
    if (p.s != q.s || p.t != q.t || p.kind != q.kind || p.tangent != q.tangent || p.multiplicity != q.multiplicity)
      return false;
  }
  return true;
}

/// Solves and checks one problem (see the file comment); `log` receives a line per finding.
template <int D>
Counts check_problem(const Known_problem<D>& kp, bool compare, const std::string& label, std::FILE* log) {
  Counts n;
  n.problems = 1;
  const Curve_problem<D>& pb = kp.problem;
  const auto& c1 = pb.curve_1;
  const auto& c2 = pb.curve_2;
  auto report = [&](const std::string& what) {
    if (log) std::fprintf(log, "%s: %s\n", label.c_str(), what.c_str());
  };
  for (std::size_t j = 0; j < pb.known.size(); ++j) {
    if (c1(pb.known[j].first) != c2(pb.known[j].second)) {
      ++n.errors;
      report("construction: C1(s_j) != C2(t_j)");
    }
    if (int(j) == kp.tangency &&
        !parallel<D>(derivative_at<D>(c1, pb.known[j].first), derivative_at<D>(c2, pb.known[j].second))) {
      ++n.errors;
      report("construction: the tangents are not parallel");
    }
  }
  n.constructed = long(pb.known.size());
  n.tangencies = kp.tangency >= 0 ? 1 : 0;
  Curve_intersection_result r;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    r = intersect_curves(c1, c2);
  } catch (const std::exception& e) {
    n.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ++n.errors;
    report(std::string("exception: ") + e.what());
    return n;
  }
  n.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  n.points = long(r.points.size());
  if (!r.overlaps.empty()) {
    n.overlaps += long(r.overlaps.size());
    for (const auto& o : r.overlaps)
      report("overlap s in [" + o.s0.to_decimal_string(12) + ", " + o.s1.to_decimal_string(12) + "], t from " +
             o.t0.to_decimal_string(12) + " to " + o.t1.to_decimal_string(12) + "; curve 2 of degree " +
             std::to_string(c2.degree()));
  }
  std::vector<char> known_point(r.points.size(), 0);
  for (std::size_t j = 0; j < pb.known.size(); ++j) {
    bool found = false;
    for (std::size_t i = 0; i < r.points.size(); ++i) {
      const auto& p = r.points[i];
      if (p.s == pb.known[j].first && p.t == pb.known[j].second) {
        found = true;
        known_point[i] = 1;
        if (int(j) == kp.tangency && (!p.tangent || p.multiplicity < 2)) {
          ++n.wrong_kind;
          report("the constructed tangency is reported with tangent = " + std::string(p.tangent ? "true" : "false") +
                 ", multiplicity " + std::to_string(p.multiplicity));
        }
        if (int(j) != kp.tangency && p.tangent &&
            !parallel<D>(derivative_at<D>(c1, pb.known[j].first), derivative_at<D>(c2, pb.known[j].second))) {
          ++n.wrong_kind;
          report("a constructed crossing with tangents apart is reported tangent");
        }
      }
    }
    // a constructed point inside a reported overlap (the curves share a piece: C2 lies on C1's algebraic curve) is
    // found: s_j in [s0, s1] and t_j between t0 and t1 (the overlap's own check is the subresultant comparison)
    for (const auto& o : r.overlaps) {
      const Algebraic_real s(pb.known[j].first), t(pb.known[j].second);
      const bool in_s = o.s0 <= s && s <= o.s1;
      const bool in_t = (o.t0 <= t && t <= o.t1) || (o.t1 <= t && t <= o.t0);
      if (in_s && in_t) {
        found = true;
        ++n.in_overlap;
      }
    }
    if (!found) {
      ++n.missed;
      report("missed the constructed intersection (s, t) = (" + str(pb.known[j].first) + ", " + str(pb.known[j].second) + ")");
    }
  }
  // independent check of the other points
  bool have_resultants = false;
  Polynomial_1<Integer> R, T;
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    if (known_point[i]) continue;
    ++n.extra_points;
    const auto& p = r.points[i];
    bool ok = true;
    if (p.s.is_rational() && p.t.is_rational()) {
      ok = c1(p.s.rational_value()) == c2(p.t.rational_value());
    } else {
      if (!have_resultants) {
        const auto H1 = internal::integer_power_form(c1), H2 = internal::integer_power_form(c2);
        const auto F1 = internal::cross_term(H1[1], H2[0], H2[1], H1[0]);
        const auto F2 = internal::cross_term(H1[2], H2[0], H2[2], H1[0]);
        R = CGAL::resultant(F1, F2);
        T = CGAL::resultant(internal::swap_variables(F1), internal::swap_variables(F2));
        have_resultants = true;
      }
      if (!CGAL::is_zero(R)) ok = ok && p.s.sign_of(R) == 0;
      if (!CGAL::is_zero(T)) ok = ok && p.t.sign_of(T) == 0;
      const Rational eps = Rational(1, 1000000000) * Rational(1, 1000000000);
      p.s.refine_to_width(eps);
      p.t.refine_to_width(eps);
      const auto x = c1.evaluate(CGAL::to_double(p.s.lower())), y = c2.evaluate(CGAL::to_double(p.t.lower()));
      for (int c = 0; c < D; ++c) ok = ok && std::abs(x[c] - y[c]) < 1e-9 * (1 + std::abs(x[c]));
    }
    if (!ok) {
      ++n.spurious;
      report("spurious point s = " + p.s.to_decimal_string(20) + ", t = " + p.t.to_decimal_string(20));
    }
  }
  if (compare) {
    ++n.compared;
    try {
      const auto q = intersect_curves(c1, c2, Curve_intersection_method::subresultant);
      if (!same_answer(r, q)) {
        ++n.disagreements;
        report("the subresultant strategy answers " + std::to_string(q.points.size()) + " points, the default " +
               std::to_string(r.points.size()));
      }
    } catch (const std::exception& e) {
      ++n.disagreements;
      report(std::string("the subresultant strategy throws: ") + e.what());
    }
  }
  return n;
}

/// The classes of problems, in the order they are cycled through.
struct Problem_class {
  int dimension, n1, n2, k;
  bool rational, tangent;
  std::string name() const {
    return std::string(dimension == 2 ? "2D" : "3D") + (rational ? " rational" : " polynomial") + " " +
           std::to_string(n1) + "-" + std::to_string(n2) + (tangent ? " tangency+" + std::to_string(k - 1)
                                                                    : " k=" + std::to_string(k));
  }
};

inline std::vector<Problem_class> problem_classes() {
  std::vector<Problem_class> v;
  for (int dim = 2; dim <= 3; ++dim)
    for (int rat = 0; rat <= 1; ++rat)
      for (int n1 = 2; n1 <= 6; ++n1)
        for (int n2 = 2; n2 <= 6; ++n2) {
          for (int k = 0; k <= std::min(4, n2 + 1); ++k) v.push_back({dim, n1, n2, k, rat == 1, false});
          for (int k = 1; k <= std::min(4, n2); ++k) v.push_back({dim, n1, n2, k, rat == 1, true});
        }
  return v;
}

/// Runs `count` problems from `first_seed` (one seed per problem), solving every compare_every-th also with the
/// subresultant strategy (0: never). Returns the totals; per class in `per_class` when given.
inline Counts run(long count, unsigned long first_seed, long compare_every, std::FILE* log,
                  std::vector<Counts>* per_class = nullptr, long first_index = 0) {
  const auto classes = problem_classes();
  if (per_class) per_class->assign(classes.size(), Counts());
  Counts total;
  for (long i = first_index; i < first_index + count; ++i) {
    const std::size_t c = std::size_t(i) * 97 % classes.size();  // 97 is prime to the 820 classes: all of them in 820 problems
    const Problem_class& pc = classes[c];
    const unsigned long seed = first_seed + unsigned(i);
    const bool compare = compare_every > 0 && i % compare_every == 0;
    const std::string label = pc.name() + " seed " + std::to_string(seed);
    Counts n;
    if (pc.dimension == 2) {
      Known_problem<2> kp;
      if (pc.tangent ? tangent_problem<2>(pc.n1, pc.n2, pc.k, pc.rational, seed, kp)
                     : (kp = transversal_problem<2>(pc.n1, pc.n2, pc.k, pc.rational, seed), true))
        n = check_problem<2>(kp, compare, label, log);
      else
        n.errors = 1, n.problems = 1;
    } else {
      Known_problem<3> kp;
      if (pc.tangent ? tangent_problem<3>(pc.n1, pc.n2, pc.k, pc.rational, seed, kp)
                     : (kp = transversal_problem<3>(pc.n1, pc.n2, pc.k, pc.rational, seed), true))
        n = check_problem<3>(kp, compare, label, log);
      else
        n.errors = 1, n.problems = 1;
    }
    total.add(n);
    if (per_class) (*per_class)[c].add(n);
  }
  return total;
}

inline void print(std::FILE* out, const char* what, const Counts& n) {
  std::fprintf(out,
               "%-34s problems %6ld  constructed %6ld (tangencies %5ld)  points %6ld (other %5ld)  missed %ld  "
               "spurious %ld  wrong kind %ld  overlaps %ld (holding %ld constructed)  compared %ld  disagreements %ld  "
               "errors %ld  %.2f s\n",
               what, n.problems, n.constructed, n.tangencies, n.points, n.extra_points, n.missed, n.spurious,
               n.wrong_kind, n.overlaps, n.in_overlap, n.compared, n.disagreements, n.errors, n.seconds);
}

}  // namespace generated_problems

#ifndef BEZOUTIAN_GENERATED_PROBLEMS_NO_MAIN
int main(int argc, char** argv) {
  const long count = argc > 1 ? std::atol(argv[1]) : 10000;
  const unsigned long first_seed = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 1;
  const long compare_every = argc > 3 ? std::atol(argv[3]) : 1;
  const long first_index = argc > 4 ? std::atol(argv[4]) : 0;
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<generated_problems::Counts> per_class;
  const generated_problems::Counts total = generated_problems::run(count, first_seed, compare_every, stdout, &per_class,
                                                                          first_index);
  const auto classes = generated_problems::problem_classes();
  // per dimension, weights and kind of problem
  generated_problems::Counts group[2][2][2];
  for (std::size_t c = 0; c < classes.size(); ++c)
    group[classes[c].dimension - 2][classes[c].rational][classes[c].tangent].add(per_class[c]);
  for (int d = 0; d < 2; ++d)
    for (int r = 0; r < 2; ++r)
      for (int t = 0; t < 2; ++t) {
        const std::string name = std::string(d ? "3D" : "2D") + (r ? " rational" : " polynomial") +
                                 (t ? " tangent" : " transversal");
        generated_problems::print(stdout, name.c_str(), group[d][r][t]);
      }
  generated_problems::print(stdout, "total", total);
  std::printf("wall time %.1f s (intersect_curves, default method: %.1f s)\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), total.seconds);
  return total.clean() ? 0 : 1;
}
#endif
