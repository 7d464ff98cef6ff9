// Certified double-interval solver for the intersections of two plane rational Bezier curves with positive
// weights: both curves subdivided (interval de Casteljau, outward rounding), pairs of pieces with disjoint control
// boxes excluded (convex hull property), each crossing proved by Krawczyk's test (Krawczyk 1969; Moore 1977) and
// contracted to a box about 1e-15 wide holding exactly one, transversal, intersection. Whatever it cannot settle
// (tangencies, overlaps, intersections at or near parameter 0 or 1, budget) is reported as `failed`, and the caller
// falls back to exact elimination (du-1989 ch. 4). Shared by intersect_curves (planar default path, lazy exact
// parameters) and the arrangement traits (Arr_rational_bezier_traits_2.h).
#ifndef BEZOUTIAN_INTERSECTION_PLANAR_INTERVAL_SOLVER_H
#define BEZOUTIAN_INTERSECTION_PLANAR_INTERVAL_SOLVER_H

#include <bezoutian/geometry/Rational_bezier_curve.h>
#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/arithmetic/interval_krawczyk.h>

#include <CGAL/Interval_nt.h>
#include <CGAL/Polynomial.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <vector>

namespace bezoutian {
namespace internal {

/// What the interval solver needs of a plane curve: the curve, outward-rounded double enclosures of the
/// coefficients of an integer homogeneous power form (W, X, Y) (any positive multiple of the curve's form) and of
/// its homogeneous control net (w, wx, wy).
struct Planar_interval_curve {
  Rational_bezier_curve_2<Rational> curve;
  std::array<Polynomial_1<Integer>, 3> Hz;  // the integer power form itself (MPFI tests)
  std::array<std::vector<CGAL::Interval_nt<false>>, 3> Hd;
  std::vector<std::array<CGAL::Interval_nt<false>, 3>> inet;
};

/// Fills the enclosures of `s` from s.curve and its integer power form H = (W, X, Y).
inline void set_planar_interval_data(Planar_interval_curve& s, const std::array<Polynomial_1<Integer>, 3>& H) {
  typedef CGAL::Interval_nt<false> I;
  s.Hz = H;
  for (int k = 0; k < 3; ++k) {
    s.Hd[k].clear();
    for (int i = 0; i <= std::max(0, H[k].degree()); ++i)
      s.Hd[k].push_back(I(CGAL::to_interval(i <= H[k].degree() ? H[k][i] : Integer(0))));
  }
  s.inet.clear();
  for (const auto& h : s.curve.homogeneous_control_points())
    s.inet.push_back({I(CGAL::to_interval(h[0])), I(CGAL::to_interval(h[1])), I(CGAL::to_interval(h[2]))});
}

typedef CGAL::Interval_nt<false> Planar_interval;
using Planar_interval_net = std::vector<std::array<Planar_interval, 3>>;

/// Value and derivative enclosures of the homogeneous power form (W, X, Y) at u (double interval Horner).
inline void planar_eval_form(const Planar_interval_curve& c, const Planar_interval& u, Planar_interval f[3],
                          Planar_interval df[3]) {
  for (int k = 0; k < 3; ++k) {
    const auto& a = c.Hd[k];
    const int n = int(a.size()) - 1;
    Planar_interval v = a[n], d(0);
    for (int i = n - 1; i >= 0; --i) {
      d = d * u + v;
      v = v * u + a[i];
    }
    f[k] = v;
    df[k] = d;
  }
}

/// Krawczyk's iteration (Krawczyk 1969; Moore 1977) for a 2 x 2 system on S x T in outward-rounded double
/// intervals. `jet(cs, ct, J, G)` encloses the Jacobian J over S x T and the value G at the centre (cs, ct).
/// K(X) inside the interior of X proves exactly one zero in X; on success S, T are contracted (X <- K(X) ∩ X,
/// which keeps the zero) `iterations` times. Every zero in X lies in K(X) (mean value form), so K(X) ∩ X = ∅
/// proves that X holds no zero: then *excluded (if given) is set and false returned.
template <class Jet>
bool planar_krawczyk_iterate(Jet jet, Planar_interval& S, Planar_interval& T, int iterations, bool* excluded) {
  typedef Planar_interval I;
  typename I::Protector guard;  // rounding towards +infinity for the interval operations
  for (int round = 0; round <= iterations; ++round) {
    const double cs = 0.5 * (S.inf() + S.sup()), ct = 0.5 * (T.inf() + T.sup());
    I J[2][2], G[2];
    jet(cs, ct, J, G);
    const double m00 = CGAL::to_double(J[0][0]), m01 = CGAL::to_double(J[0][1]), m10 = CGAL::to_double(J[1][0]),
                 m11 = CGAL::to_double(J[1][1]);
    const double det = m00 * m11 - m01 * m10;
    if (!std::isfinite(det) || det == 0) return round > 0;
    const double Y[2][2] = {{m11 / det, -m01 / det}, {-m10 / det, m00 / det}};
    const I ds = S - I(cs), dt = T - I(ct);
    I K[2];
    const double c[2] = {cs, ct};
    for (int i = 0; i < 2; ++i) {
      const I yg = Y[i][0] * G[0] + Y[i][1] * G[1];
      const I m0 = I(i == 0 ? 1.0 : 0.0) - (Y[i][0] * J[0][0] + Y[i][1] * J[1][0]);
      const I m1 = I(i == 1 ? 1.0 : 0.0) - (Y[i][0] * J[0][1] + Y[i][1] * J[1][1]);
      K[i] = I(c[i]) - yg + m0 * ds + m1 * dt;
      if (!std::isfinite(K[i].inf()) || !std::isfinite(K[i].sup())) return round > 0;
    }
    if (round == 0 && excluded &&
        (K[0].sup() < S.inf() || K[0].inf() > S.sup() || K[1].sup() < T.inf() || K[1].inf() > T.sup())) {
      *excluded = true;
      return false;
    }
    if (round == 0 && !(K[0].inf() > S.inf() && K[0].sup() < S.sup() && K[1].inf() > T.inf() && K[1].sup() < T.sup()))
      return false;
    const I S2(std::max(S.inf(), K[0].inf()), std::min(S.sup(), K[0].sup()));
    const I T2(std::max(T.inf(), K[1].inf()), std::min(T.sup(), K[1].sup()));
    const bool progress = S2.sup() - S2.inf() < 0.99 * (S.sup() - S.inf()) || T2.sup() - T2.inf() < 0.99 * (T.sup() - T.inf());
    S = S2;
    T = T2;
    if (!progress && round > 0) break;
  }
  return true;
}

/// Krawczyk's test for G_k(s,t) = A_k(s) B_0(t) - B_k(t) A_0(s), k = 1, 2 on the box S x T (the same system as
/// internal::krawczyk_unique_intersection): success proves exactly one zero in S x T, a transversal
/// intersection (see planar_krawczyk_iterate).
inline bool planar_krawczyk(const Planar_interval_curve& A, const Planar_interval_curve& B, Planar_interval& S,
                            Planar_interval& T, int iterations, bool* excluded = nullptr) {
  typedef Planar_interval I;
  auto jet = [&](double cs, double ct, I J[2][2], I G[2]) {
    I af[3], adf[3], bf[3], bdf[3], acf[3], acd[3], bcf[3], bcd[3];
    planar_eval_form(A, S, af, adf);
    planar_eval_form(B, T, bf, bdf);
    planar_eval_form(A, I(cs), acf, acd);
    planar_eval_form(B, I(ct), bcf, bcd);
    for (int k = 1; k <= 2; ++k) {
      J[k - 1][0] = adf[k] * bf[0] - bf[k] * adf[0];
      J[k - 1][1] = af[k] * bdf[0] - bdf[k] * af[0];
      G[k - 1] = acf[k] * bcf[0] - bcf[k] * acf[0];
    }
  };
  return planar_krawczyk_iterate(jet, S, T, iterations, excluded);
}

/// Control box of an interval net (false if a weight enclosure is not positive).
inline bool planar_net_box(const Planar_interval_net& net, double b[4]) {
  b[0] = b[2] = HUGE_VAL;
  b[1] = b[3] = -HUGE_VAL;
  for (const auto& h : net) {
    if (!(h[0].inf() > 0)) return false;
    const Planar_interval x = h[1] / h[0], y = h[2] / h[0];
    b[0] = std::min(b[0], x.inf());
    b[1] = std::max(b[1], x.sup());
    b[2] = std::min(b[2], y.inf());
    b[3] = std::max(b[3], y.sup());
  }
  return std::isfinite(b[0]) && std::isfinite(b[1]) && std::isfinite(b[2]) && std::isfinite(b[3]);
}

/// Interval de Casteljau halves at 1/2 (enclosures of the exact halves) of a net of control points with any
/// number of homogeneous coordinates (Net = std::vector<std::array<Planar_interval, K>>); `tri` is scratch space.
template <class Net>
void interval_net_halves(const Net& q, Net& left, Net& right, Net& tri) {
  tri = q;
  const std::size_t n = q.size();
  left.assign(1, tri[0]);
  right.assign(1, tri[n - 1]);
  const Planar_interval half(0.5);
  for (std::size_t r = 1; r < n; ++r) {
    for (std::size_t j = 0; j + r < n; ++j)
      for (std::size_t k = 0; k < tri[j].size(); ++k) tri[j][k] = (tri[j][k] + tri[j + 1][k]) * half;
    left.push_back(tri[0]);
    right.push_back(tri[n - 1 - r]);
  }
  std::reverse(right.begin(), right.end());
}
inline void planar_net_halves(const Planar_interval_net& q, Planar_interval_net& left, Planar_interval_net& right,
                              Planar_interval_net& tri) {
  interval_net_halves(q, left, right, tri);
}

/// Krawczyk contraction in MPFI: X <- K(X) ∩ X, `rounds` times or until no progress (X keeps every zero it held).
/// Returns false if K(X) ∩ X is empty or the operator is not finite (then the box is unchanged).
/// box = (s_lo, s_hi, t_lo, t_hi), exact rationals. Stops early once both widths are <= stop_width or near the
/// precision's resolution.
inline bool planar_krawczyk_contract(const std::array<Polynomial_1<Integer>, 3>& A,
                                     const std::array<Polynomial_1<Integer>, 3>& B, std::array<Rational, 4>& box,
                                     mpfr_prec_t prec, int rounds, double stop_width = 0) {
  using I = Mpfi_interval;
  I X[2] = {I::hull(box[0], box[1], prec), I::hull(box[2], box[3], prec)};
  const double floor_width = std::ldexp(1.0, 24 - int(prec));  // parameters lie in [-1, 2] or so
  for (int round = 0; round < rounds; ++round) {
    const double w0 = X[0].width_double(), w1 = X[1].width_double();
    if ((w0 <= stop_width && w1 <= stop_width) || (w0 <= floor_width && w1 <= floor_width)) break;
    I K[2] = {I(prec), I(prec)}, N[2] = {I(prec), I(prec)};
    if (!planar_krawczyk_operator(A, B, X, K, prec)) return false;
    bool progress = false;
    for (int i = 0; i < 2; ++i) {
      mpfi_intersect(N[i].get(), K[i].get(), X[i].get());
      if (mpfi_is_empty(N[i].get())) return false;
      if (N[i].width_double() < 0.75 * X[i].width_double()) progress = true;
    }
    X[0] = N[0];
    X[1] = N[1];
    if (!progress) break;
  }
  const Rational nb[4] = {X[0].lower(), X[0].upper(), X[1].lower(), X[1].upper()};
  // keep the old ends where they are tighter (both boxes hold the zeros)
  box[0] = std::max(box[0], nb[0]);
  box[1] = std::min(box[1], nb[1]);
  box[2] = std::max(box[2], nb[2]);
  box[3] = std::min(box[3], nb[3]);
  return true;
}

/// The MPFI form of planar_krawczyk, for cells where double evaluation is too coarse (power-basis coefficients
/// that cancel): +1 if K(X) lies in the interior of X = S x T (exactly one zero, transversal; S, T are then
/// contracted and rounded outwards to doubles), -1 if K(X) ∩ X = ∅ (no zero), 0 otherwise.
inline int planar_krawczyk_mpfi(const std::array<Polynomial_1<Integer>, 3>& A,
                                const std::array<Polynomial_1<Integer>, 3>& B, Planar_interval& S, Planar_interval& T,
                                mpfr_prec_t prec) {
  using I = Mpfi_interval;
  std::array<Rational, 4> box{Rational(S.inf()), Rational(S.sup()), Rational(T.inf()), Rational(T.sup())};
  const I X[2] = {I::hull(box[0], box[1], prec), I::hull(box[2], box[3], prec)};
  I K[2] = {I(prec), I(prec)};
  if (!planar_krawczyk_operator(A, B, X, K, prec)) return 0;
  if (disjoint(K[0], X[0]) || disjoint(K[1], X[1])) return -1;
  if (!(K[0].inside_open(box[0], box[1]) && K[1].inside_open(box[2], box[3]))) return 0;
  planar_krawczyk_contract(A, B, box, prec, 8);
  S = Planar_interval(CGAL::to_interval(box[0]).first, CGAL::to_interval(box[1]).second);
  T = Planar_interval(CGAL::to_interval(box[2]).first, CGAL::to_interval(box[3]).second);
  return 1;
}

/// Certified transversal intersections of two different supporting curves by interval subdivision: every cell
/// pair of parameter squares whose control boxes meet is either excluded (after halving, or because Krawczyk's
/// operator misses the slightly enlarged cell) or holds, in the enlarged cell, exactly one zero (Krawczyk),
/// contracted to a tiny box. Sets `failed` (caller: exact path) when this does not settle everything:
/// tangencies, overlaps, intersections at or near parameter 0 or 1, boxes of two cells that meet without a common
/// proof, the depth limit or the work budget.
///
/// Common end points C_A(e_a) = C_B(e_b), e_a, e_b in {0, 1} (exact comparison of the end control points) are
/// `contacts`, exact intersections with rational parameters; a cell having one as a corner is settled when a
/// direction v separates the two pieces strictly except at that point (v . (Q - P) < 0 for the other control
/// points Q of one piece, > 0 for the other's: every other point of a piece is a positive combination of its
/// control points), so that it holds no other intersection; otherwise it is halved.
struct Planar_interval_solver {
  const Planar_interval_curve& A;
  const Planar_interval_curve& B;
  std::vector<std::array<double, 4>> found;  // s_lo, s_hi, t_lo, t_hi
  std::vector<std::array<int, 2>> contacts;  // (e_a, e_b)
  int budget = 4000;
  bool failed = false;
  std::deque<std::array<Planar_interval_net, 5>> pool;  // (growing a deque keeps references)
  /// Deepest subdivision level (cells 2^-max_depth wide) before giving up.
  int max_depth = 24;
  /// From this depth on, cells that the double Krawczyk test leaves undecided get the MPFI test (needs Hz).
  int mpfi_depth = 1000;
  /// Boxes of one zero that double Krawczyk cannot merge get the MPFI test too (needs Hz).
  bool mpfi_merge = false;
  mpfr_prec_t mpfi_precision = 192;

  /// Call with the whole nets on [0,1] x [0,1] and depth 0.
  void run(const Planar_interval_net& na, double s0, double s1, const Planar_interval_net& nb, double t0, double t1, int depth) {
    typename Planar_interval::Protector guard;
    if (failed) return;
    if (depth == 0) {
      const std::size_t n = A.curve.number_of_control_points() - 1, m = B.curve.number_of_control_points() - 1;
      for (int ea = 0; ea < 2; ++ea)
        for (int eb = 0; eb < 2; ++eb)
          if (A.curve.control_point(ea * n) == B.curve.control_point(eb * m)) contacts.push_back({ea, eb});
    }
    if (--budget < 0) {
      failed = true;
      return;
    }
    double ba[4], bb[4];
    if (!planar_net_box(na, ba) || !planar_net_box(nb, bb)) {
      failed = true;
      return;
    }
    if (ba[1] < bb[0] || bb[1] < ba[0] || ba[3] < bb[2] || bb[3] < ba[2]) return;
    int corners = 0, ia = 0, ib = 0;
    for (const auto& c : contacts)
      if ((c[0] == s0 || c[0] == s1) && (c[1] == t0 || c[1] == t1)) {
        ++corners;
        ia = c[0] == s0 ? 0 : int(na.size()) - 1;
        ib = c[1] == t0 ? 0 : int(nb.size()) - 1;
      }
    if (corners == 1 && depth >= 1 && separated(na, ia, nb, ib)) return;
    if (corners == 0 && depth >= 2) {
      // enlarged cell: a zero on the cell boundary lies in its interior
      const double es = 0.0625 * (s1 - s0), et = 0.0625 * (t1 - t0);
      Planar_interval S(s0 - es, s1 + es), T(t0 - et, t1 + et);
      bool excluded = false;
      if (planar_krawczyk(A, B, S, T, 16, &excluded)) {
        add(S, T);
        return;
      }
      if (excluded) return;  // no zero in the enlarged cell
      if (depth >= mpfi_depth) {  // doubles too coarse here: the same test in MPFI
        S = Planar_interval(s0 - es, s1 + es);
        T = Planar_interval(t0 - et, t1 + et);
        const int k = planar_krawczyk_mpfi(A.Hz, B.Hz, S, T, mpfi_precision);
        if (k > 0) add(S, T);
        if (k != 0) return;
      }
    }
    if (depth >= max_depth) {
      failed = true;
      return;
    }
    if (pool.size() <= std::size_t(depth)) pool.resize(depth + 1);  // one set of nets per depth: no allocation
    auto& nets = pool[depth];
    Planar_interval_net &al = nets[0], &ar = nets[1], &bl = nets[2], &br = nets[3];
    planar_net_halves(na, al, ar, nets[4]);
    planar_net_halves(nb, bl, br, nets[4]);
    const double sm = 0.5 * (s0 + s1), tm = 0.5 * (t0 + t1);
    run(al, s0, sm, bl, t0, tm, depth + 1);
    run(al, s0, sm, br, tm, t1, depth + 1);
    run(ar, sm, s1, bl, t0, tm, depth + 1);
    run(ar, sm, s1, br, tm, t1, depth + 1);
  }

  /// The pieces na and nb meet only at their common end control points na[ia] = nb[ib] = P (see above).
  static bool separated(const Planar_interval_net& na, int ia, const Planar_interval_net& nb, int ib) {
    typedef Planar_interval I;
    const I px = na[ia][1] / na[ia][0], py = na[ia][2] / na[ia][0];  // encloses P (exact end point)
    const double cx = CGAL::to_double(px), cy = CGAL::to_double(py);
    auto mean_direction = [&](const Planar_interval_net& q, int skip, double& ux, double& uy) {
      ux = uy = 0;
      for (int i = 0; i < int(q.size()); ++i)
        if (i != skip) {
          ux += CGAL::to_double(q[i][1] / q[i][0]) - cx;
          uy += CGAL::to_double(q[i][2] / q[i][0]) - cy;
        }
      const double l = std::sqrt(ux * ux + uy * uy);
      if (!(l > 0) || !std::isfinite(l)) return false;
      ux /= l;
      uy /= l;
      return true;
    };
    double ax, ay, bx, by;
    if (!mean_direction(na, ia, ax, ay) || !mean_direction(nb, ib, bx, by)) return false;
    const I vx(bx - ax), vy(by - ay);
    auto side = [&](const Planar_interval_net& q, int skip, int sign) {
      for (int i = 0; i < int(q.size()); ++i) {
        if (i == skip) continue;
        const I d = vx * (q[i][1] / q[i][0] - px) + vy * (q[i][2] / q[i][0] - py);
        if (sign < 0 ? !(d.sup() < 0) : !(d.inf() > 0)) return false;
      }
      return true;
    };
    return side(na, ia, -1) && side(nb, ib, 1);
  }

  void add(const Planar_interval& S, const Planar_interval& T) {
    // outside [0,1]^2: not an intersection of the arcs; straddling the border: undecided here
    if (S.sup() < 0 || S.inf() > 1 || T.sup() < 0 || T.inf() > 1) return;
    if (!(S.inf() > 0 && S.sup() < 1 && T.inf() > 0 && T.sup() < 1)) {
      failed = true;
      return;
    }
    for (auto& f : found) {
      if (S.sup() < f[0] || f[1] < S.inf() || T.sup() < f[2] || f[3] < T.inf()) continue;
      // the boxes meet: one zero if Krawczyk proves uniqueness on a box holding both (their hull, enlarged; boxes
      // a few ulps wide are enlarged further, since rounding errors dominate the test there)
      const Planar_interval HS(std::min(S.inf(), f[0]), std::max(S.sup(), f[1])),
          HT(std::min(T.inf(), f[2]), std::max(T.sup(), f[3]));
      double es = HS.sup() - HS.inf(), et = HT.sup() - HT.inf();
      for (int k = 0; k < 10; ++k, es = std::max(4 * es, 1e-10), et = std::max(4 * et, 1e-10)) {
        Planar_interval XS(HS.inf() - es, HS.sup() + es), XT(HT.inf() - et, HT.sup() + et);
        if (planar_krawczyk(A, B, XS, XT, 0)) return;
        if (mpfi_merge && planar_krawczyk_mpfi(A.Hz, B.Hz, XS, XT, mpfi_precision) > 0) return;
      }
      failed = true;
      return;
    }
    found.push_back({S.inf(), S.sup(), T.inf(), T.sup()});
  }
};


}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERSECTION_PLANAR_INTERVAL_SOLVER_H
