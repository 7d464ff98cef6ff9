// Certified double-interval localisation of the common points of two space rational Bezier curves with positive
// weights: both curves subdivided (interval de Casteljau, outward rounding), pairs of pieces with disjoint control
// boxes excluded (convex hull property), and Krawczyk's test (Krawczyk 1969; Moore 1977) on a square subsystem
// (two of the three equations G_k = A_k(s) B_0(t) - B_k(t) A_0(s)). Two space curves meeting is not a square
// system, so intervals cannot prove a meeting; what they prove is a list of boxes, each holding exactly one zero
// of its subsystem, whose union holds every common point in [0,1]^2. Boxes where the third equation is proved
// nonzero are dropped (e.g. curves crossing in projection only). The caller decides the remaining boxes exactly.
#ifndef BEZOUTIAN_INTERSECTION_INTERNAL_SPACE_INTERVAL_SOLVER_H
#define BEZOUTIAN_INTERSECTION_INTERNAL_SPACE_INTERVAL_SOLVER_H

#include <bezoutian/geometry/Rational_bezier_curve.h>
#include <bezoutian/intersection/planar_interval_solver.h>
#include <bezoutian/arithmetic/number_types.h>

#include <CGAL/Interval_nt.h>
#include <CGAL/Polynomial.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <vector>

namespace bezoutian {
namespace internal {

/// What the space interval solver needs of a curve: outward-rounded double enclosures of the coefficients of an
/// integer homogeneous power form (W, X, Y, Z) and of its homogeneous control net (w, wx, wy, wz).
struct Space_interval_curve {
  std::array<std::vector<Planar_interval>, 4> Hd;
  std::vector<std::array<Planar_interval, 4>> inet;
};

using Space_interval_net = std::vector<std::array<Planar_interval, 4>>;

/// Enclosures of c's net and of its integer power form H (any positive multiple of the curve's form).
inline Space_interval_curve space_interval_curve(const Rational_bezier_curve<Rational, 3>& c,
                                                 const std::array<Polynomial_1<Integer>, 4>& H) {
  Space_interval_curve s;
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i <= std::max(0, H[k].degree()); ++i)
      s.Hd[k].push_back(Planar_interval(CGAL::to_interval(i <= H[k].degree() ? H[k][i] : Integer(0))));
  for (const auto& h : c.homogeneous_control_points())
    s.inet.push_back({Planar_interval(CGAL::to_interval(h[0])), Planar_interval(CGAL::to_interval(h[1])),
                      Planar_interval(CGAL::to_interval(h[2])), Planar_interval(CGAL::to_interval(h[3]))});
  return s;
}

/// Enclosures of f and f' over c + H (H an interval containing 0) by the Taylor form at c: the coefficients
/// b_i of f(c + h) = sum b_i h^i (interval synthetic division), then Horner in h. Unlike Horner in the power basis
/// around 0, whose enclosure width grows with sum |a_i| (large, cancelling coefficients), the overestimation is of
/// second order in the width of H. fc encloses f(c).
inline void space_taylor_form(const std::vector<Planar_interval>& a, const Planar_interval& c, const Planar_interval& H,
                              Planar_interval& f, Planar_interval& df, Planar_interval& fc) {
  const int n = int(a.size()) - 1;
  Planar_interval b[32];
  if (n >= 32) {  // (not reached for the degrees of intersect_curves' inputs in practice) plain Horner instead
    Planar_interval v = a[n], d(0);
    const Planar_interval u = c + H;
    for (int i = n - 1; i >= 0; --i) {
      d = d * u + v;
      v = v * u + a[i];
    }
    f = v;
    df = d;
    Planar_interval w = a[n];
    for (int i = n - 1; i >= 0; --i) w = w * c + a[i];
    fc = w;
    return;
  }
  for (int i = 0; i <= n; ++i) b[i] = a[i];
  for (int i = 0; i < n; ++i)
    for (int j = n - 1; j >= i; --j) b[j] += c * b[j + 1];
  Planar_interval v = b[n], d(0);
  for (int i = n - 1; i >= 0; --i) {
    d = d * H + v;
    v = v * H + b[i];
  }
  f = v;
  df = d;
  fc = b[0];
}

/// Boxes S x T covering the common points of the curves A(s), B(t) in [0,1]^2, each proved to hold exactly one zero
/// of the subsystem (G_a, G_b) recorded with it (so at most one common point), and on which the third equation was
/// not proved nonzero. `failed`: not settled (tangency, overlap, negative weights, depth or work budget).
struct Space_interval_solver {
  struct Box {
    double s_lo, s_hi, t_lo, t_hi;
    int a, b;  // the square subsystem (G_a, G_b), 1 <= a < b <= 3
  };
  const Space_interval_curve& A;
  const Space_interval_curve& B;
  std::vector<Box> found;
  // cells (enlarged) on which Krawczyk succeeded: each holds at most the one zero already dealt with, so a later
  // cell inside one of them needs no work
  std::vector<std::array<double, 4>> settled;
  int budget = 3000;
  int max_depth = 40;  // levels of splitting (one or both parameters)
  bool failed = false;
  int cells = 0, krawczyk_tests = 0;  // statistics
  std::deque<std::array<Space_interval_net, 5>> pool;

  /// Control box (x, y, z ranges) of an interval net (false if a weight enclosure is not positive).
  static bool net_box(const Space_interval_net& net, double b[6]) {
    for (int k = 0; k < 3; ++k) {
      b[2 * k] = HUGE_VAL;
      b[2 * k + 1] = -HUGE_VAL;
    }
    for (const auto& h : net) {
      if (!(h[0].inf() > 0)) return false;
      for (int k = 0; k < 3; ++k) {
        const Planar_interval x = h[k + 1] / h[0];
        b[2 * k] = std::min(b[2 * k], x.inf());
        b[2 * k + 1] = std::max(b[2 * k + 1], x.sup());
      }
    }
    for (int k = 0; k < 6; ++k)
      if (!std::isfinite(b[k])) return false;
    return true;
  }

  static void halves(const Space_interval_net& q, Space_interval_net& left, Space_interval_net& right,
                     Space_interval_net& tri) {
    interval_net_halves(q, left, right, tri);
  }

  /// Jacobian enclosure of (G_1, G_2, G_3) over S x T (rows k - 1, columns d/ds, d/dt), enclosures of their values
  /// over S x T and at the centre (cs, ct) (Taylor forms at the centre).
  void jet(const Planar_interval& S, const Planar_interval& T, double cs, double ct, Planar_interval J[3][2],
           Planar_interval V[3], Planar_interval G[3]) const {
    Planar_interval af[4], adf[4], ac[4], bf[4], bdf[4], bc[4];
    const Planar_interval Cs(cs), Ct(ct), Hs = S - Cs, Ht = T - Ct;
    for (int k = 0; k < 4; ++k) {
      space_taylor_form(A.Hd[k], Cs, Hs, af[k], adf[k], ac[k]);
      space_taylor_form(B.Hd[k], Ct, Ht, bf[k], bdf[k], bc[k]);
    }
    for (int k = 1; k <= 3; ++k) {
      J[k - 1][0] = adf[k] * bf[0] - bf[k] * adf[0];
      J[k - 1][1] = af[k] * bdf[0] - bdf[k] * af[0];
      V[k - 1] = af[k] * bf[0] - bf[k] * af[0];
      G[k - 1] = ac[k] * bc[0] - bc[k] * ac[0];
    }
  }

  /// Krawczyk on the enlarged cell with the best-conditioned subsystem (largest 2 x 2 minor of the Jacobian at the
  /// centre): 1 = proved (box recorded or dropped), -1 = no zero, 0 = undecided.
  int krawczyk_cell(double s0, double s1, double t0, double t1) {
    ++krawczyk_tests;
    const double es = 0.0625 * (s1 - s0), et = 0.0625 * (t1 - t0);
    Planar_interval S(s0 - es, s1 + es), T(t0 - et, t1 + et);
    // one jet on the enlarged cell: exclusion by the value enclosures, then the subsystem with the largest 2 x 2
    // minor of the Jacobian's midpoint, then Krawczyk (its first round reuses this jet)
    Planar_interval Jc[3][2], V3[3], G3[3];
    jet(S, T, 0.5 * (S.inf() + S.sup()), 0.5 * (T.inf() + T.sup()), Jc, V3, G3);
    for (int k = 0; k < 3; ++k)
      if (V3[k].inf() > 0 || V3[k].sup() < 0) return -1;
    int ba = 0, bb = 1;
    double best = -1;
    for (int a = 0; a < 3; ++a)
      for (int b = a + 1; b < 3; ++b) {
        const double m = std::abs(CGAL::to_double(Jc[a][0]) * CGAL::to_double(Jc[b][1]) -
                                  CGAL::to_double(Jc[a][1]) * CGAL::to_double(Jc[b][0]));
        if (m > best) {
          best = m;
          ba = a;
          bb = b;
        }
      }
    bool first = true;
    auto sub_jet = [&](double xs, double xt, Planar_interval J[2][2], Planar_interval G[2]) {
      if (!first) jet(S, T, xs, xt, Jc, V3, G3);
      first = false;
      for (int c = 0; c < 2; ++c) {
        J[0][c] = Jc[ba][c];
        J[1][c] = Jc[bb][c];
      }
      G[0] = G3[ba];
      G[1] = G3[bb];
    };
    bool excluded = false;
    const std::array<double, 4> domain{S.inf(), S.sup(), T.inf(), T.sup()};
    if (!planar_krawczyk_iterate(sub_jet, S, T, 16, &excluded)) return excluded ? -1 : 0;
    settled.push_back(domain);
    // the zero of the subsystem in S x T; outside [0,1]^2 it is no common point of the arcs
    if (S.sup() < 0 || S.inf() > 1 || T.sup() < 0 || T.inf() > 1) return 1;
    Planar_interval J[3][2];
    jet(S, T, 0.5 * (S.inf() + S.sup()), 0.5 * (T.inf() + T.sup()), J, V3, G3);
    const int c = 3 - ba - bb;
    if (V3[c].inf() > 0 || V3[c].sup() < 0) return 1;  // the third coordinate differs: not a common point
    found.push_back({S.inf(), S.sup(), T.inf(), T.sup(), ba + 1, bb + 1});
    return 1;
  }

  /// Call with the whole nets on [0,1] x [0,1] and depth 0.
  void run(const Space_interval_net& na, double s0, double s1, const Space_interval_net& nb, double t0, double t1,
           int depth) {
    typename Planar_interval::Protector guard;
    if (failed) return;
    ++cells;
    if (--budget < 0) {
      failed = true;
      return;
    }
    double ba[6], bb[6];
    if (!net_box(na, ba) || !net_box(nb, bb)) {
      failed = true;
      return;
    }
    for (int k = 0; k < 3; ++k)
      if (ba[2 * k + 1] < bb[2 * k] || bb[2 * k + 1] < ba[2 * k]) return;
    for (const auto& x : settled)
      if (x[0] <= s0 && s1 <= x[1] && x[2] <= t0 && t1 <= x[3]) return;
    if (depth >= 1) {
      const int r = krawczyk_cell(s0, s1, t0, t1);
      if (r != 0) return;
    }
    if (depth >= max_depth) {
      failed = true;
      return;
    }
    if (pool.size() <= std::size_t(depth)) pool.resize(depth + 1);
    auto& nets = pool[depth];
    Space_interval_net &al = nets[0], &ar = nets[1], &bl = nets[2], &br = nets[3];
    // split the piece that is larger in space (both if comparable): where one parameter runs much faster than the
    // other (weights far apart), square cells would keep Krawczyk's Jacobian enclosure loose in that direction
    double ea = 0, eb = 0;
    for (int k = 0; k < 3; ++k) {
      ea = std::max(ea, ba[2 * k + 1] - ba[2 * k]);
      eb = std::max(eb, bb[2 * k + 1] - bb[2 * k]);
    }
    const bool split_a = !(eb > 4 * ea), split_b = !(ea > 4 * eb);
    if (split_a) halves(na, al, ar, nets[4]);
    if (split_b) halves(nb, bl, br, nets[4]);
    const double sm = 0.5 * (s0 + s1), tm = 0.5 * (t0 + t1);
    if (split_a && split_b) {
      run(al, s0, sm, bl, t0, tm, depth + 1);
      run(al, s0, sm, br, tm, t1, depth + 1);
      run(ar, sm, s1, bl, t0, tm, depth + 1);
      run(ar, sm, s1, br, tm, t1, depth + 1);
    } else if (split_a) {
      run(al, s0, sm, nb, t0, t1, depth + 1);
      run(ar, sm, s1, nb, t0, t1, depth + 1);
    } else {
      run(na, s0, s1, bl, t0, tm, depth + 1);
      run(na, s0, s1, br, tm, t1, depth + 1);
    }
  }
};

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERSECTION_INTERNAL_SPACE_INTERVAL_SOLVER_H
