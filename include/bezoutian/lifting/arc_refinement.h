// Adaptive refinement of a traced arc of D = 0 before its complete lifting (partner_sheets.h).
//
// The topology traces each arc piece with a fixed number of points, uniform in its graph coordinate. That is too
// coarse where it matters: a pair of sheets of the space curve that meet and turn complex (a sphere cut by a plane
// symmetric to it: the two points (x, y, z), (-x, y, z) over one (u, t) merge at x = 0, like sqrt) ends between two
// traced points, and a curved sheet drawn by chords strays from the true curve. A span between consecutive points
// of one graph piece is halved when
//  - the number of real partners differs at its ends (a sheet begins or ends inside it), down to a span of 2^-40
//    of the piece's width, where the fibre is known on both sides of the change up to rounding (only where the
//    number of partners in the domain changes too: a sheet leaving the domain is the split points' business); or
//  - for a partner at the midpoint, the chord of the nearest partners at the ends misses its point by more than the
//    tolerance, in 3D or in either parameter domain (the midpoint test of adaptive sampling: a floating-point
//    estimate of the distance, not a bound); or the interval bound on the distance between that chord and the
//    zero curve through its ends exceeds the tolerance, by at most 16 times (polyline_distance_bounds.h: the bound
//    the sheets' proofs report, where it is proved; far above it, next to a fold, the span is left to the
//    midpoint test).
// The new point of the arc is the root of D along the line of its graph coordinate inside the piece's cell, where
// the subdivision proved D = 0 a graph (one root): regula falsi on the cell's range. Floating point throughout;
// the proofs are the span proofs of partner_sheets.h on the refined arc.
#ifndef BEZOUTIAN_LIFTING_ARC_REFINEMENT_H
#define BEZOUTIAN_LIFTING_ARC_REFINEMENT_H

#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/topology/Curve_topology.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

namespace bezoutian {
namespace internal {

/// D(x1, x2) in double: the coefficients scaled by the largest one (their ratios are what matters for the roots).
class Double_curve_equation {
 public:
  explicit Double_curve_equation(const Polynomial_2<Integer>& D) {
    double big = 0;
    for (int j = 0; j <= D.degree(); ++j)
      for (int i = 0; i <= D[j].degree(); ++i) big = std::max(big, std::fabs(CGAL::to_double(D[j][i])));
    if (!(big > 0) || !std::isfinite(big)) big = 1;
    c_.resize(std::size_t(D.degree() + 1));
    for (int j = 0; j <= D.degree(); ++j)
      for (int i = 0; i <= D[j].degree(); ++i) c_[std::size_t(j)].push_back(CGAL::to_double(D[j][i]) / big);
  }
  double operator()(double x1, double x2) const {
    double r = 0;
    for (std::size_t j = c_.size(); j-- > 0;) {
      double s = 0;
      for (std::size_t i = c_[j].size(); i-- > 0;) s = s * x1 + c_[j][i];
      r = r * x2 + s;
    }
    return r;
  }

 private:
  std::vector<std::vector<double>> c_;  // c_[j][i]: coefficient of x1^i x2^j
};

/// The point of D = 0 in `cell` on the line {coordinate `axis` = t} (unique on a graph piece), by regula falsi
/// (Illinois) on the cell's range of the other coordinate; false without a sign change there.
inline bool arc_point_on_line(const Double_curve_equation& D, const Parameter_box& cell, int axis, double t,
                              std::array<double, 2>& point) {
  double a = CGAL::to_double(axis == 0 ? cell.v0 : cell.u0), b = CGAL::to_double(axis == 0 ? cell.v1 : cell.u1);
  auto f = [&](double o) { return axis == 0 ? D(t, o) : D(o, t); };
  double fa = f(a), fb = f(b);
  if (fa == 0 || fb == 0 || (fa < 0) == (fb < 0)) return false;
  int kept = 0;
  for (int it = 0; it < 100 && b - a > 1e-15 * (1 + std::fabs(a)); ++it) {
    double m = 0.5 * (a + b);
    if (it % 4 != 3) {
      const double r = (a * fb - b * fa) / (fb - fa);
      if (r > a && r < b) m = r;
    }
    const double fm = f(m);
    if (fm == 0) {
      a = b = m;
      break;
    }
    if ((fm < 0) == (fa < 0)) {
      a = m, fa = fm;
      if (kept == 1) fb *= 0.5;
      kept = 1;
    } else {
      b = m, fb = fm;
      if (kept == -1) fa *= 0.5;
      kept = -1;
    }
  }
  const double o = 0.5 * (a + b);
  point = axis == 0 ? std::array<double, 2>{t, o} : std::array<double, 2>{o, t};
  return true;
}

/// What the refinement needs of the locus: the fibre of a point of the projection plane (every real partner),
/// the two parameter points and the 3D point of a partner, and the insertion of a new traced point after index i
/// (which keeps the arc's other data, e.g. its lifted points, in step with the polyline).
struct Arc_refinement_model {
  std::function<std::vector<std::array<double, 2>>(const std::array<double, 2>&)> fibre;
  /// {P1, P2, Q1, Q2, X, Y, Z}: the two parameter points and the 3D point of partner y of x
  std::function<std::array<double, 7>(const std::array<double, 2>&, const std::array<double, 2>&)> lift;
  /// (with the fibre of the new point, whose partners seed its lifting)
  std::function<void(std::size_t, const std::array<double, 2>&, const std::vector<std::array<double, 2>>&)> insert;
  /// Newton on the partner equations at graph coordinate t (`axis`) from w = (other coordinate, y1, y2); true if it
  /// converged (the patches' equations are of low degree: the point is far more accurate than a root of D)
  std::function<bool(int, double, std::array<double, 3>&)> solve;
  /// whether the partner y of x puts both parameter points inside the domains (a sheet's genuine part)
  std::function<bool(const std::array<double, 2>&, const std::array<double, 2>&)> inside;
  /// optional: a proved bound on the distance between the chord of the lifts of (xa, ya), (xb, yb) and the zero
  /// curve through them along the coordinate `axis` (polyline_distance_bounds.h: segment_distance_estimate),
  /// infinity where not proved; a span whose bound exceeds the tolerance is halved too
  std::function<double(int, const std::array<double, 2>&, const std::array<double, 2>&, const std::array<double, 2>&,
                       const std::array<double, 2>&)>
      bound;
};

/// Refines the edge `e` (its polyline and pieces are updated in place) with `fibres` kept parallel to the
/// polyline; at most `max_points` new points. Returns the number inserted.
inline std::size_t refine_arc(Curve_topology_edge& e, std::vector<std::vector<std::array<double, 2>>>& fibres,
                              const Double_curve_equation& D, const Arc_refinement_model& model, double tolerance,
                              std::size_t max_points) {
  std::size_t inserted = 0;
  auto insert_after = [&](std::size_t i, const std::array<double, 2>& x, std::vector<std::array<double, 2>> F) {
    model.insert(i, x, F);
    e.polyline.insert(e.polyline.begin() + std::ptrdiff_t(i + 1), x);
    fibres.insert(fibres.begin() + std::ptrdiff_t(i + 1), std::move(F));
    for (auto& p : e.pieces) {
      if (p.first > i) ++p.first;
      if (p.last > i) ++p.last;
    }
    ++inserted;
  };
  // the arc point at graph coordinate t of a piece: Newton on the partner equations from the mean of the nearest
  // partners at the span's ends (every partner of xa tried), else the root of D on the line
  auto arc_point = [&](const Parameter_box& cell, int axis, double t, const std::array<double, 2>& xa,
                       const std::vector<std::array<double, 2>>& Fa, const std::array<double, 2>& xb,
                       const std::vector<std::array<double, 2>>& Fb, std::array<double, 2>& x) {
    const double lo = CGAL::to_double(axis == 0 ? cell.v0 : cell.u0), hi = CGAL::to_double(axis == 0 ? cell.v1 : cell.u1);
    const double f = (t - xa[std::size_t(axis)]) / (xb[std::size_t(axis)] - xa[std::size_t(axis)]);
    const double o = xa[std::size_t(1 - axis)] + f * (xb[std::size_t(1 - axis)] - xa[std::size_t(1 - axis)]);
    for (const auto& ya : Fa) {
      std::array<double, 2> y = ya;
      double d = HUGE_VAL;
      for (const auto& yb : Fb) {
        const double dk = std::fabs(yb[0] - ya[0]) + std::fabs(yb[1] - ya[1]);
        if (dk < d) d = dk, y = {ya[0] + f * (yb[0] - ya[0]), ya[1] + f * (yb[1] - ya[1])};
      }
      std::array<double, 3> w{o, y[0], y[1]};
      if (model.solve(axis, t, w) && lo <= w[0] && w[0] <= hi) {
        x = axis == 0 ? std::array<double, 2>{t, w[0]} : std::array<double, 2>{w[0], t};
        return true;
      }
    }
    return arc_point_on_line(D, cell, axis, t, x);
  };
  auto inside_count = [&](const std::array<double, 2>& x, const std::vector<std::array<double, 2>>& F) {
    std::size_t n = 0;
    for (const auto& y : F) n += model.inside(x, y);
    return n;
  };
  auto nearest = [](const std::vector<std::array<double, 2>>& F, const std::array<double, 2>& y) {
    std::size_t best = F.size();
    double d = HUGE_VAL;
    for (std::size_t k = 0; k < F.size(); ++k) {
      const double dk = std::fabs(F[k][0] - y[0]) + std::fabs(F[k][1] - y[1]);
      if (dk < d) d = dk, best = k;
    }
    return best;
  };
  // the chord test at the midpoint m of the span (a, b): for each partner at m, the 7 coordinates of its lift
  // against the mean of the lifts of the nearest partners at a and b
  auto chord_misses = [&](int axis, const std::array<double, 2>& xa, const std::vector<std::array<double, 2>>& Fa,
                          const std::array<double, 2>& xb, const std::vector<std::array<double, 2>>& Fb,
                          const std::array<double, 2>& xm, const std::vector<std::array<double, 2>>& Fm) {
    for (const auto& y : Fm) {
      const std::size_t ka = nearest(Fa, y), kb = nearest(Fb, y);
      if (ka == Fa.size() || kb == Fb.size()) return true;
      const auto m = model.lift(xm, y), la = model.lift(xa, Fa[ka]), lb = model.lift(xb, Fb[kb]);
      double d3 = 0, dp = 0, dq = 0;
      for (int c = 0; c < 3; ++c) d3 += std::pow(m[4 + c] - 0.5 * (la[4 + c] + lb[4 + c]), 2);
      for (int c = 0; c < 2; ++c) {
        dp += std::pow(m[c] - 0.5 * (la[c] + lb[c]), 2);
        dq += std::pow(m[2 + c] - 0.5 * (la[2 + c] + lb[2 + c]), 2);
      }
      if (!(std::sqrt(std::max({d3, dp, dq})) <= tolerance)) return true;
      if (model.bound) {
        const double b = model.bound(axis, xa, Fa[ka], xb, Fb[kb]);
        // (far above the tolerance the span runs into a fold, where the partner grows like a square root and
        // halving gains little while the fibre proofs of the tiny spans cost much: its bound is reported as is)
        if (b > tolerance && b <= 16 * tolerance) return true;
      }
    }
    return false;
  };
  for (std::size_t p = 0; p < e.pieces.size(); ++p) {
    // a half-branch inside a singular box is refined along the coordinate its chained proof runs on (the
    // crossing's normal), by continuation of its partners only: the roots of D on a line there belong to several
    // branches
    const bool half_branch = e.pieces[p].graph_axis < 0;
    if (half_branch && e.pieces[p].singular_end < 0) continue;
    const int axis = half_branch ? (e.pieces[p].crossing_on_vertical_line ? 0 : 1) : e.pieces[p].graph_axis;
    const Parameter_box cell = e.pieces[p].cell;
    const double width = std::fabs(CGAL::to_double(axis == 0 ? cell.u1 - cell.u0 : cell.v1 - cell.v0));
    std::size_t i = e.pieces[p].first;
    while (i < e.pieces[p].last && inserted < max_points) {
      const std::array<double, 2> xa = e.polyline[i], xb = e.polyline[i + 1];
      const double ta = xa[std::size_t(axis)], tb = xb[std::size_t(axis)];
      // a sheet that begins or ends inside the domain (a fold: two partners meet and turn complex) is located to
      // 2^-40 of the cell; a sheet that only leaves the domain is not (the split-point proofs locate that crossing
      // exactly), nor a change among partners outside the domain (next to a seam)
      const bool fold = !half_branch && fibres[i].size() != fibres[i + 1].size() &&
                        inside_count(xa, fibres[i]) != inside_count(xb, fibres[i + 1]);
      const double located = std::ldexp(width, -40);
      // chords are refined between genuine points only (where a sheet leaves the domain the split-point proofs
      // place the end of its genuine part)
      if (!fold && (inside_count(xa, fibres[i]) == 0 || inside_count(xb, fibres[i + 1]) == 0)) {
        ++i;
        continue;
      }
      if (fibres[i].empty() && fibres[i + 1].empty()) {
        ++i;
        continue;
      }
      if (fold) {
        // bisection down to 2^-40 of the cell (without keeping the intermediate points), then the last points on
        // both sides of the change join the arc
        std::array<double, 2> pa = xa, pb = xb;
        std::vector<std::array<double, 2>> Fa = fibres[i], Fb = fibres[i + 1];
        const std::size_t ca = inside_count(xa, Fa);
        bool moved_a = false, moved_b = false;
        while (std::fabs(pb[std::size_t(axis)] - pa[std::size_t(axis)]) > located) {
          std::array<double, 2> x;
          if (!arc_point(cell, axis, 0.5 * (pa[std::size_t(axis)] + pb[std::size_t(axis)]), pa, Fa, pb, Fb, x)) break;
          auto F = model.fibre(x);
          if (inside_count(x, F) == ca)
            pa = x, Fa = std::move(F), moved_a = true;
          else
            pb = x, Fb = std::move(F), moved_b = true;
        }
        // located: the number of partners in the domain changes between pa and pb. A fold changes the number of
        // real partners there too; where it does not, a partner crosses the domain's boundary (a split point,
        // located exactly by its own proofs), and the number of real partners changed elsewhere in the span, near
        // the margin of the partner domain the fibre is searched in: no point is added for either
        // (nor where the change is at an end of the span: that traced point is already the end of the sheets, as
        // where an arc of D = 0 ends on a seam with its partner on the partner domain's side)
        const double end_gap = std::ldexp(width, -30);
        const bool at_end = std::fabs(pb[std::size_t(axis)] - tb) <= end_gap || std::fabs(pa[std::size_t(axis)] - ta) <= end_gap;
        if ((!moved_a && !moved_b) || Fa.size() == Fb.size() || at_end) {
          ++i;
          continue;
        }
        // only the point on the side with more partners in the domain joins the arc (the sheets reach the fold
        // there; a point beyond it, without a partner, would add nothing)
        const bool a_side = inside_count(xa, fibres[i]) > inside_count(xb, fibres[i + 1]);
        insert_after(i, a_side ? pa : pb, std::move(a_side ? Fa : Fb));
        if (!a_side) ++i;  // the change now lies in the span (i, pb) ... (pb, xb): continue after pb
        // the span at i again: now either without a change (chord test) or across the located change (skipped)
        continue;
      }
      if (std::fabs(tb - ta) <= std::ldexp(width, -12)) {
        ++i;
        continue;
      }
      // the midpoint and its partners by continuation of the partners at the span's ends (Newton on the partner
      // equations: cheap); the complete fibre where that fails
      const double tm = 0.5 * (ta + tb);
      std::array<double, 2> x;
      std::vector<std::array<double, 2>> F;
      bool continued = !fibres[i].empty();
      for (const auto& ya : fibres[i]) {
        std::array<double, 2> y = ya;
        double d = HUGE_VAL;
        for (const auto& yb : fibres[i + 1]) {
          const double dk = std::fabs(yb[0] - ya[0]) + std::fabs(yb[1] - ya[1]);
          if (dk < d) d = dk, y = {0.5 * (ya[0] + yb[0]), 0.5 * (ya[1] + yb[1])};
        }
        std::array<double, 3> w{0.5 * (xa[std::size_t(1 - axis)] + xb[std::size_t(1 - axis)]), y[0], y[1]};
        if (!model.solve(axis, tm, w)) {
          continued = false;
          break;
        }
        const std::array<double, 2> xw = axis == 0 ? std::array<double, 2>{tm, w[0]} : std::array<double, 2>{w[0], tm};
        if (F.empty()) x = xw;
        if (std::fabs(xw[std::size_t(1 - axis)] - x[std::size_t(1 - axis)]) > 1e-9) {  // another arc point
          continued = false;
          break;
        }
        bool seen = false;
        for (const auto& f : F) seen = seen || std::fabs(f[0] - w[1]) + std::fabs(f[1] - w[2]) < 1e-9;
        if (seen) {
          continued = false;
          break;
        }
        F.push_back({w[1], w[2]});
      }
      const double lo = CGAL::to_double(axis == 0 ? cell.v0 : cell.u0), hi = CGAL::to_double(axis == 0 ? cell.v1 : cell.u1);
      if (continued && !(lo <= x[std::size_t(1 - axis)] && x[std::size_t(1 - axis)] <= hi)) continued = false;
      if (continued && half_branch) {  // (on this branch: near the chord of the span)
        const double oa = xa[std::size_t(1 - axis)], ob = xb[std::size_t(1 - axis)], room = std::fabs(tb - ta);
        const double o = x[std::size_t(1 - axis)];
        continued = std::min(oa, ob) - room <= o && o <= std::max(oa, ob) + room;
      }
      if (!continued && half_branch) {
        ++i;
        continue;
      }
      if (!continued) {
        if (!arc_point(cell, axis, tm, xa, fibres[i], xb, fibres[i + 1], x)) {
          ++i;
          continue;
        }
        F = model.fibre(x);
      }
      // (a midpoint between genuine points without a partner in the domain, as at a seam where the partner runs
      // along the domain's boundary, adds no point to any sheet)
      if (inside_count(x, F) > 0 && (F.size() != fibres[i].size() || chord_misses(axis, xa, fibres[i], xb, fibres[i + 1], x, F))) {
        insert_after(i, x, std::move(F));  // and refine the first half again
        continue;
      }
      ++i;
    }
  }
  return inserted;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_LIFTING_ARC_REFINEMENT_H
