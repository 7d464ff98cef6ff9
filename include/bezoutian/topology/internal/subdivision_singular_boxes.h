// The boxes of the subdivision (Curve_topology_by_subdivision.h) that are neither excluded nor simple and hold one
// feature of D = 0 whole, each resolved by a certificate that the header comment of Curve_topology_by_subdivision.h
// states:
//  * two branches (internal/two_branch_box.h): D_yy keeps a sign and no point has D = D_y = 0, so D = 0 is two
//    families of graphs over x, told apart by the sign of D_y, whose crossings pair up along x (resolve_two_branches);
//  * a valley of sigma D above 0 (two_branch::no_zero): no arcs (valley_excluded);
//  * a fold (internal/fold_box.h): exactly one point p with D = D_y = 0, where the curve turns back across the lines
//    x = const; p ends one arc of each family (resolve_fold);
//  * a nondegenerate critical point p of D on the curve: a regular Hessian on the box (grad D injective), Krawczyk's
//    test on grad D, D(p) = 0 proved, and 4 (a node) or 0 (an isolated point) crossings of the box's edges; then D = 0
//    in the box is the four half-branches from p to the crossings, or p alone (resolve_singular).
#ifndef BEZOUTIAN_TOPOLOGY_INTERNAL_SUBDIVISION_SINGULAR_BOXES_H
#define BEZOUTIAN_TOPOLOGY_INTERNAL_SUBDIVISION_SINGULAR_BOXES_H

// the class Subdivision_topology, whose member functions this header defines (it is included at the end of that one)
#include <bezoutian/topology/Curve_topology_by_subdivision.h>
#include <bezoutian/topology/internal/fold_box.h>
#include <bezoutian/topology/internal/interval_bernstein_grid.h>
#include <bezoutian/topology/internal/two_branch_box.h>
#include <bezoutian/arithmetic/interval_krawczyk.h>
#include <bezoutian/arithmetic/simplest_rational.h>

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace bezoutian {
namespace internal {

// ---- two branches in one box (internal/two_branch_box.h) ----
// The sign of D_y at a crossing of an edge of B (y = v for axis 0, u for axis 1): first from B's grid (the
// Bernstein coefficients of D_y on that edge, differences of the grid's, at the crossing's isolating interval, in
// interval arithmetic), else exactly (along its line D_y is the derivative of D restricted to the line, across
// it the restricted derivative across; both cached per line).
inline int Subdivision_topology::cross_derivative_sign(const Box& B, const Crossing& c, int axis) {
  const Algebraic_real& r = line_root(c);
  const Double_bernstein_grid& G = *B.fast;
  const bool across_u = axis == 1;  // D_u: differences along i, else along j
  const int a = G.a(), b = G.b();
  if ((across_u ? a : b) >= 1) {
    const Rational &lo = c.vertical ? B.v0 : B.u0, &hi = c.vertical ? B.v1 : B.u1;
    const auto tl = CGAL::to_interval((r.lower() - lo) / (hi - lo)), th = CGAL::to_interval((r.upper() - lo) / (hi - lo));
    const Double_interval t{std::max(0.0, tl.first), std::min(1.0, th.second)};
    const bool high = c.vertical ? c.c == B.u1 : c.c == B.v1;  // which edge of B: u = u1 (v = v1) or u0 (v0)
    const int n = c.vertical ? b - (across_u ? 0 : 1) : a - (across_u ? 1 : 0);  // degree along the edge
    const double r2 = 2 * G.radius();
    std::vector<Double_interval> w(std::size_t(n + 1));
    for (int k = 0; k <= n; ++k) {
      // the grid index of the k-th coefficient along the edge and the difference across y
      const int i = c.vertical ? (high ? (across_u ? a - 1 : a) : 0) : k, j = c.vertical ? k : (high ? (across_u ? b : b - 1) : 0);
      const double g1 = across_u ? G.at(i + 1, j) : G.at(i, j + 1), g0 = G.at(i, j);
      w[std::size_t(k)] = (Double_interval{g1, g1} - Double_interval{g0, g0}) + Double_interval{-r2, r2};
    }
    const Double_interval s = Double_interval::widen(1 - t.hi, 1 - t.lo);
    for (int level = 1; level <= n; ++level)
      for (int k = 0; k + level <= n; ++k) w[std::size_t(k)] = s * w[std::size_t(k)] + t * w[std::size_t(k + 1)];
    if (w[0].lo > 0) return 1;
    if (w[0].hi < 0) return -1;
  }
  auto key = std::make_pair(c.vertical, c.c);
  auto it = restrictions_.find(key);
  if (it == restrictions_.end()) {
    std::pair<Polynomial_1<Rational>, Polynomial_1<Rational>> PQ;
    restriction(c.vertical, c.c, PQ.first, &PQ.second);
    PQ.first = CGAL::differentiate(PQ.first);
    it = restrictions_.emplace(key, std::move(PQ)).first;
  }
  const bool along = (axis == 0) == c.vertical;
  return r.sign_of(along ? it->second.first : it->second.second);
}

// The budget of a certificate's strip grids, each about as costly as one double split of a box.
inline void Subdivision_topology::charge_strips(std::size_t strips) {
  work_ += double(strips) * (a_ + 1) * (b_ + 1) * std::max(1, a_ + b_) / 16;
}

// The arc of one family (root_side: below or above the minimiser of sigma D on the lines x = const) between the
// crossings c and d of a two-branch or fold box. It starts at the end on a line x = const when there is one: the
// lifting's chained proof runs from n0 along x (certify_half_branch).
inline void Subdivision_topology::add_branch_arc(const Box& B, bool by_u, const Crossing& c, const Crossing& d,
                                                 int root_side, int sigma) {
  const bool second = c.vertical != by_u && d.vertical == by_u;
  const Crossing &a = second ? d : c, &b = second ? c : d;
  Arc arc{node(a.vertical, a.c, a.index), node(b.vertical, b.c, b.index), {}, Parameter_box{B.u0, B.u1, B.v0, B.v1}, -1};
  sample_arc(B, by_u, a.position, b.position, arc.inner, root_side, sigma);
  arcs_.push_back(arc);
}

// A box with two branches (two_branch_certificate): the crossings of each class sigma D_y < 0, sigma D_y > 0, sorted
// along x, pair up into arcs, as in a simple box. Each arc starts at (n0) the end that lies on a line x = const
// when there is one: the lifting's chained proof runs from n0 along x (certify_half_branch).
inline bool Subdivision_topology::resolve_two_branches(Box& B) {
  std::size_t strips = 0;  // strip grids computed, each about as costly as one double split of B: the budget
  Two_branch_box t = two_branch_certificate(*B.fast, two_branch_strip_depth, &strips, o_.two_branch_max_gap);
  if (t.axis < 0 && t.screened && sharpen_grid(B))
    t = two_branch_certificate(*B.fast, two_branch_strip_depth, &strips, o_.two_branch_max_gap);
  charge_strips(strips);
  if (t.axis < 0 || curve_at_domain_corner(B)) return false;
  const bool by_u = t.axis == 0;
  std::vector<Crossing> cr;
  if (!crossings_of_edges(B, by_u, cr)) return false;
  std::vector<Crossing> cls[2];
  for (const Crossing& c : cr) {
    const int s = cross_derivative_sign(B, c, t.axis);
    if (s == 0) return false;  // D = D_y = 0 on the edge: excluded by the certificate; be safe and split
    cls[s > 0 ? 1 : 0].push_back(c);
  }
  // one family alone is one arc (or several) that a split resolves as well, on smaller cells whose graph
  // structure the lifting's proofs use: the certificate is kept for boxes that do hold two branches
  if (cls[0].empty() || cls[1].empty()) return false;
  for (auto& k : cls) {
    if (k.size() % 2 != 0) return false;
    std::sort(k.begin(), k.end(), [](const Crossing& x, const Crossing& y) { return x.position < y.position; });
  }
  for (int side = 0; side < 2; ++side) {
    // the branch's root on a line x = const lies below the minimiser of sigma D (on the lines x = const) iff
    // sigma D_y < 0 on it
    const int root_side = (side == 1) == (t.sigma > 0) ? 1 : -1;
    const std::vector<Crossing>& k = cls[side];
    for (std::size_t i = 0; i + 1 < k.size(); i += 2) add_branch_arc(B, by_u, k[i], k[i + 1], root_side, t.sigma);
  }
  ++two_branch_boxes_;
  return true;
}

// The curve passes through a corner of B that is a corner of the domain (the certificates leave such boxes to the
// corner analysis of resolve()).
inline bool Subdivision_topology::curve_at_domain_corner(const Box& B) const {
  for (const Rational* cu : {&B.u0, &B.u1})
    for (const Rational* cv : {&B.v0, &B.v1})
      if ((*cu == box_.u0 || *cu == box_.u1) && (*cv == box_.v0 || *cv == box_.v1) && exact_jet(*cu, *cv)[0] == 0)
        return true;
  return false;
}

// A box with one fold p (fold_certificate): the crossings of each family sigma D_y < 0, sigma D_y > 0 and p, sorted
// along x, pair up into arcs as in a two-branch box; p ends one arc of each family, on the curve's side of it. p is
// a node of its own (a regular point of the curve: fold == true), from which the arcs run to their crossings, so
// that the lifting's chained proofs start at the crossings (certify_half_branch).
inline bool Subdivision_topology::resolve_fold(Box& B) {
  std::size_t strips = 0;
  Fold_box f = fold_certificate(*B.fast, fold_strip_depth, &strips);
  if (f.axis < 0 && f.screened && sharpen_grid(B)) f = fold_certificate(*B.fast, fold_strip_depth, &strips);
  charge_strips(strips);
  if (f.axis < 0 || curve_at_domain_corner(B)) return false;
  const bool by_u = f.axis == 0;
  std::vector<Crossing> cr;
  if (!crossings_of_edges(B, by_u, cr)) return false;
  // p's enclosure in the domain's coordinates (exact: the local bounds are doubles)
  const Rational &x0 = by_u ? B.u0 : B.v0, &x1 = by_u ? B.u1 : B.v1, &y0 = by_u ? B.v0 : B.u0, &y1 = by_u ? B.v1 : B.u1;
  const Rational xa = x0 + Rational(f.xa) * (x1 - x0), xb = x0 + Rational(f.xb) * (x1 - x0);
  const Rational ya = y0 + Rational(f.ya) * (y1 - y0), yb = y0 + Rational(f.yb) * (y1 - y0);
  // the ends of each family along x: its crossings, and p inside X0 = (xa, xb); a crossing inside X0 cannot be
  // ordered against p: split instead
  std::vector<const Crossing*> cls[2];
  for (const Crossing& c : cr) {
    const int s = cross_derivative_sign(B, c, f.axis);
    if (s == 0) return false;
    if (c.position.compare(xa) >= 0 && c.position.compare(xb) <= 0) return false;
    cls[s > 0 ? 1 : 0].push_back(&c);
  }
  const Rational& near_end = f.curve_side > 0 ? xb : xa;
  struct Pair {
    const Crossing *a, *b;
    int family;
  };
  std::vector<Pair> cc;                                  // the arcs between two crossings
  std::vector<std::pair<const Crossing*, int>> to_fold;  // (crossing, family) of the two arcs at p
  for (int side = 0; side < 2; ++side) {
    std::vector<const Crossing*>& k = cls[side];
    if (k.size() % 2 == 0) return false;  // with p, each family has an even number of ends
    std::sort(k.begin(), k.end(), [](const Crossing* x, const Crossing* y) { return x->position < y->position; });
    std::size_t before = 0;
    while (before < k.size() && k[before]->position.compare(xa) < 0) ++before;
    // p's arc runs from p to the curve's side: p must be the first end of a pair there (an even number of ends
    // before it), else the certificate and the crossings disagree
    if (f.curve_side > 0 ? before % 2 != 0 : before % 2 != 1) return false;
    std::vector<const Crossing*> rest;
    for (std::size_t i = 0; i < k.size(); ++i) {
      if (i == (f.curve_side > 0 ? before : before - 1)) {
        to_fold.push_back({k[i], side});
        continue;
      }
      rest.push_back(k[i]);
    }
    for (std::size_t i = 0; i + 1 < rest.size(); i += 2) cc.push_back({rest[i], rest[i + 1], side});
  }
  singular_.push_back(Singular_point{by_u ? xa : ya, by_u ? xb : yb, by_u ? ya : xa, by_u ? yb : xb, false, 2, true});
  const std::size_t p = node_singular(singular_.size() - 1);
  const Algebraic_real at_p(near_end);
  for (const auto& t : to_fold) {
    const int root_side = (t.second == 1) == (f.sigma > 0) ? 1 : -1;
    Arc arc{node(t.first->vertical, t.first->c, t.first->index), p, {}, Parameter_box{B.u0, B.u1, B.v0, B.v1}, -1};
    sample_arc(B, by_u, t.first->position, at_p, arc.inner, root_side, f.sigma);
    arcs_.push_back(arc);
  }
  for (const Pair& q : cc) add_branch_arc(B, by_u, *q.a, *q.b, (q.family == 1) == (f.sigma > 0) ? 1 : -1, f.sigma);
  ++fold_boxes_;
  return true;
}

// When a certificate's plain-double screen passed but its proof failed, the proof may have failed on the grid's
// radius alone: next to a node whose branches cross at a small angle, or along a deep valley, the values that
// decide are below the radius of a double grid split down from the domain. B's grid is then replaced by the
// double-double restriction of the domain's grid (sharp to the double rounding of its midpoints); false if that
// cannot make it sharper.
inline bool Subdivision_topology::sharpen_grid(Box& B) {
  if (!dd_root_ || B.grid || !(B.fast->radius() > std::ldexp(B.fast->max_abs(), -48))) return false;
  B.fast = double_double_grid(B);
  return true;
}

// A box excluded as a valley of sigma D above 0 (valley_exclusion): no arcs.
inline bool Subdivision_topology::valley_excluded(Box& B) {
  std::size_t strips = 0;
  bool screened = false;
  bool ok = valley_exclusion(*B.fast, valley_strip_depth, &strips, &screened);
  if (!ok && screened && sharpen_grid(B)) ok = valley_exclusion(*B.fast, valley_strip_depth, &strips, nullptr);
  charge_strips(strips);
  if (ok) ++valley_boxes_;
  return ok;
}

// ---- singular and isolated points (the header comment of Curve_topology_by_subdivision.h) ----
// Resolves box B around a nondegenerate singular or isolated point of D = 0 (conditions (1)-(4) of the header
// comment). Returns false (B is then split) when a condition fails for a reason that splitting can cure;
// calls fail() when D(p) = 0 can be neither proved nor excluded.
inline bool Subdivision_topology::resolve_singular(Box& B) {
  using I = Mpfi_interval;
  if (a_ + b_ < 2) return false;
  // (1) regular Hessian on B; the two D_uv entries are independent copies (the mean-value Jacobian takes its
  // rows at different points). First on the double grid (its ranges are proved enclosures); if that fails
  // while its radius is small, the MPFI grid would not decide either and B is split.
  auto hessian_sign = [&](double rho) {  // sign of det H on B, 0 if not proved
    using DI = CGAL::Interval_nt<>;
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) B.fast->second_difference_range(k, rho, lo[k], hi[k]);
    const DI det = DI(lo[0], hi[0]) * DI(lo[2], hi[2]) - DI(lo[1], hi[1]) * DI(lo[1], hi[1]);
    return det.inf() > 0 ? 1 : (det.sup() < 0 ? -1 : 0);
  };
  int hessian = hessian_sign(B.fast->radius());
  const bool hessian_undecided = hessian == 0 && (B.fast->precise() || hessian_sign(0) == 0);
  if (hessian_undecided && B.depth < cut_depth) return false;
  // floating-point Newton for the critical point (a starting point only)
  std::vector<long double> L(std::size_t(a_ + 1) * (b_ + 1));
  for (int i = 0; i <= a_; ++i)
    for (int j = 0; j <= b_; ++j) L[std::size_t(i) * (b_ + 1) + j] = B.fast->at(i, j);
  long double x = 0.5L, y = 0.5L, step = 1;
  for (int it = 0; it < 60 && step >= 1e-18L; ++it) {
    const auto j = interval_bernstein::local_jet(L, a_, b_, x, y);
    const long double dt = j[3] * j[5] - j[4] * j[4];
    if (!(std::fabs(dt) > 0)) return false;
    const long double dx = (j[5] * j[1] - j[4] * j[2]) / dt, dy = (j[3] * j[2] - j[4] * j[1]) / dt;
    x -= dx;
    y -= dy;
    if (!std::isfinite(double(x)) || !std::isfinite(double(y)) || x < -1 || x > 2 || y < -1 || y > 2) return false;
    step = std::fabs(dx) + std::fabs(dy);
  }
  // converged, up to the double grid's rounding: near a node whose branches cross at a small angle that rounding
  // moves the critical point by far more than 1e-18 (its radius over the smallest eigenvalue of the Hessian)
  const bool converged = step < 1e-9L;
  const long double margin = 1e-6L;
  if (x < margin || x > 1 - margin || y < margin || y > 1 - margin) return false;
  const Rational wu = B.u1 - B.u0, wv = B.v1 - B.v0;
  const std::array<double, 2> approx{CGAL::to_double(B.u0) + double(x) * CGAL::to_double(wu),
                                     CGAL::to_double(B.v0) + double(y) * CGAL::to_double(wv)};
  for (const auto& e : off_curve_)  // a critical point already proved to lie off the curve
    if (e.contains(approx[0], approx[1])) return false;
  // B probably holds a critical point of D on or next to the curve (|D| tiny there against the Hessian): if B is not
  // resolved below, it is cut around that point (cut_around), so that the point stays far from the edges of the
  // boxes that hold it. A plain split leaves it next to an edge as often as not, and a node whose two branches
  // are almost tangent is then unresolvable in the box beside it (a random (3,2) self-intersection: an angle of
  // 0.035 rad, the node 5e-8 from the edge of its box, the branches 1.8e-9 apart in the next box).
  if (converged && B.depth >= cut_depth) {
    // in B's local coordinates: |D(p)| against the Hessian's entries
    const auto jet = interval_bernstein::local_jet(L, a_, b_, x, y);
    if (std::fabs(jet[0]) <= std::ldexp(std::fabs(jet[3]) + std::fabs(jet[4]) + std::fabs(jet[5]), -24)) {
      cut_pending_ = true;
      cut_point_ = Parameter_box{Rational(approx[0]), Rational(approx[0]), Rational(approx[1]), Rational(approx[1])};
    }
  }
  if (hessian_undecided) return false;
  if (o_.no_genuine_points && B.depth < undecided_depth)  // D(p) = 0 already neither proved nor excluded
    for (const auto& e : undecided_)
      if (e.contains(approx[0], approx[1])) return false;
  // (1) with sharper grids, now that B probably holds a critical point (the MPFI grid of a bicubic pair's D, of
  // bi-degree (54, 54), costs as much as 60 box splits): the double-double restriction, then the MPFI grid
  if (hessian == 0 && dd_root_ && !B.grid) {
    B.fast = double_double_grid(B);
    hessian = hessian_sign(B.fast->radius());
    if (hessian == 0 && (B.fast->precise() || hessian_sign(0) == 0)) return false;
  }
  if (hessian == 0) {
    const Interval_grid& g = mpfi_grid(B);
    const I hxx = interval_bernstein::hessian_range(g, 0, prec_), hxy = interval_bernstein::hessian_range(g, 1, prec_),
            hyx = hxy, hyy = interval_bernstein::hessian_range(g, 2, prec_);
    const I det = hxx * hyy - hxy * hyx;
    if (det.contains_zero()) return false;
    hessian = det.positive() ? 1 : -1;
  }
  const bool extremum = hessian > 0;
  // (4) the crossings with the edges of B
  std::vector<Crossing> cr;
  std::vector<std::size_t> isolated_corners;
  if (!crossings_around(B, cr, isolated_corners)) return false;
  if (cr.size() != (extremum ? 0u : 4u)) return false;
  return prove_critical_point(B, cr, isolated_corners, x, y, approx, extremum);
}

// Steps (2) and (3) of resolve_singular, once B has a regular Hessian and the crossings `cr` (4 or 0, `extremum`):
// Krawczyk's test proves the critical point p of D in B around Newton's point (x, y) (B's local coordinates; `approx`
// in the domain's), then D(p) = 0 is proved and B resolved around p. False (B is split) or fail() as resolve_singular.
inline bool Subdivision_topology::prove_critical_point(Box& B, const std::vector<Crossing>& cr,
                                                       const std::vector<std::size_t>& isolated_corners, long double x,
                                                       long double y, const std::array<double, 2>& approx,
                                                       bool extremum) {
  using I = Mpfi_interval;
  using interval_bernstein::grid_value;
  const Rational wu = B.u1 - B.u0, wv = B.v1 - B.v0;
  // (2) Krawczyk on grad D in local coordinates, around Newton's point, with the Hessian ranges of B: first on
  // an interval grid from the double-double restriction (cheap), then, if that does not decide (Krawczyk's test
  // fails, or D(p) is proved neither zero nor nonzero), on the exact-rounded MPFI grid of B
  std::shared_ptr<const Interval_grid> cheap = B.grid ? nullptr : dd_interval_grid(B);
  bool witness_failed = false;
  for (int pass = cheap ? 0 : 1; pass < 2; ++pass) {
    const Interval_grid& g = pass == 0 ? *cheap : mpfi_grid(B);
    std::array<I, 2> X{I::point(0, prec_), I::point(0, prec_)};
    auto value = [&](const std::array<I, 2>& c, std::array<I, 2>& F) {
      F[0] = grid_value(g, 1, 0, c[0], c[1], prec_, binomials_);
      F[1] = grid_value(g, 0, 1, c[0], c[1], prec_, binomials_);
    };
    // The Hessian on Z in mean-value form, H(c) + (third derivatives on Z) (Z - c). Evaluated on Z directly, a
    // Bernstein sum overestimates by (size of its coefficients) x (width of Z), which can exceed the smallest
    // eigenvalue of H (a node whose branches cross at a small angle t: about t^2 |H|); the mean-value form's
    // excess is quadratic in the width of Z.
    auto jacobian = [&](const std::array<I, 2>& Z, std::vector<std::vector<I>>& J) {
      const I c0 = Z[0].midpoint(), c1 = Z[1].midpoint(), d0 = Z[0] - c0, d1 = Z[1] - c1;
      const I t30 = grid_value(g, 3, 0, Z[0], Z[1], prec_, binomials_),
              t21 = grid_value(g, 2, 1, Z[0], Z[1], prec_, binomials_),
              t12 = grid_value(g, 1, 2, Z[0], Z[1], prec_, binomials_),
              t03 = grid_value(g, 0, 3, Z[0], Z[1], prec_, binomials_);
      J[0][0] = grid_value(g, 2, 0, c0, c1, prec_, binomials_) + t30 * d0 + t21 * d1;
      J[0][1] = grid_value(g, 1, 1, c0, c1, prec_, binomials_) + t21 * d0 + t12 * d1;
      J[1][0] = J[0][1];
      J[1][1] = grid_value(g, 0, 2, c0, c1, prec_, binomials_) + t12 * d0 + t03 * d1;
    };
    // Krawczyk's first box: radius 1e-7 (local coordinates), inflated when the critical point's own uncertainty
    // (the gradient's rounding error over the smallest eigenvalue of H) is larger
    bool proved = false;
    for (const double r0 : {1e-7, 1e-5, 1e-3}) {
      X = {I::hull(Rational(double(x) - r0), Rational(double(x) + r0), prec_),
           I::hull(Rational(double(y) - r0), Rational(double(y) + r0), prec_)};
      if ((proved = krawczyk_prove<2>(X, value, jacobian))) break;
    }
    if (!proved) {
      if (pass == 0) continue;
      return false;
    }
    // contract (quadratically: the Hessian is enclosed on the current box) until D(X) excludes 0 or the
    // enclosure stops shrinking (the working precision is reached)
    bool off_curve = false;
    for (int round = 0; round < 64; ++round) {
      if (!grid_value(g, 0, 0, X[0], X[1], prec_, binomials_).contains_zero()) {
        off_curve = true;
        break;
      }
      const double w0 = X[0].width_double() + X[1].width_double();
      if (!krawczyk_prove<2>(X, value, jacobian)) break;
      if (!(X[0].width_double() + X[1].width_double() < 0.5 * w0)) break;
    }
    if (!X[0].strictly_inside(I::hull(Rational(0), Rational(1), prec_)) ||
        !X[1].strictly_inside(I::hull(Rational(0), Rational(1), prec_)))
      return false;
    const Parameter_box K{B.u0 + wu * X[0].lower(), B.u0 + wu * X[0].upper(), B.v0 + wv * X[1].lower(),
                          B.v0 + wv * X[1].upper()};
    // (3) D(p): nonzero (the box is split as usual), or zero by an exact rational point or the witness
    if (off_curve) {
      off_curve_.push_back(K);
      return false;
    }
    bool zero_proved = false;
    Rational ru, rv;
    if (simplest_rational_in(K.u0, K.u1, ru) && simplest_rational_in(K.v0, K.v1, rv)) {
      const auto e = exact_jet(ru, rv);
      zero_proved = CGAL::is_zero(e[0]) && CGAL::is_zero(e[1]) && CGAL::is_zero(e[2]);
    }
    if (!zero_proved && o_.singular_point_witness && !witness_failed) {
      zero_proved = o_.singular_point_witness(Parameter_box{B.u0, B.u1, B.v0, B.v1}, approx);
      witness_failed = !zero_proved;
    }
    if (!zero_proved && pass == 0) continue;  // the exact-rounded grid may prove D(p) != 0
    if (!zero_proved && o_.no_genuine_points && B.depth < undecided_depth) {  // it may yet be excluded as phantom
      undecided_.push_back(K);
      return false;
    }
    if (!zero_proved) {
      fail("D has a nondegenerate critical point at (" + std::to_string(approx[0]) + ", " + std::to_string(approx[1]) +
           ") where |D| is below the interval resolution; D = 0 there (a node or an isolated point) could not be "
           "proved");
      return false;
    }
    singular_.push_back(Singular_point{K.u0, K.u1, K.v0, K.v1, extremum, extremum ? 0 : 4});
    for (std::size_t n : isolated_corners) touch_[n] = 0;
    connect_to_point(B, cr, node_singular(singular_.size() - 1), x, y);
    return true;
  }
  return false;
}

// The arcs of D = 0 in B from each crossing to the singular point p at local coordinates (x, y) of B, with
// floating-point samples along them for drawing.
inline void Subdivision_topology::connect_to_point(const Box& B, const std::vector<Crossing>& cr, std::size_t ps,
                                                   long double x, long double y) {
  std::vector<long double> L(std::size_t(a_ + 1) * (b_ + 1));
  for (int i = 0; i <= a_; ++i)
    for (int j = 0; j <= b_; ++j) L[std::size_t(i) * (b_ + 1) + j] = B.fast->at(i, j);
  const Rational wu = B.u1 - B.u0, wv = B.v1 - B.v0;
  for (const Crossing& c : cr) {
    const std::size_t n = node(c.vertical, c.c, c.index);
    Arc arc{n, ps, {}, Parameter_box{B.u0, B.u1, B.v0, B.v1}, -1};
    const Curve_topology_vertex q = vertex_of(n);
    const long double qx = (q.u - CGAL::to_double(B.u0)) / CGAL::to_double(wu),
                      qy = (q.v - CGAL::to_double(B.v0)) / CGAL::to_double(wv);
    for (int k = 1; k < o_.samples_per_arc; ++k) {  // points of the segment pulled onto D = 0 (drawing only)
      const long double f = (long double)k / o_.samples_per_arc;
      long double px = qx + f * (x - qx), py = qy + f * (y - qy);
      bool on_curve = false;  // only converged points are kept (near a singular point with several branches the
                              // pull from the chord may not converge in a few steps)
      for (int it = 0; it < 12 && !on_curve; ++it) {
        const auto j = interval_bernstein::local_jet(L, a_, b_, px, py);
        const long double n2 = j[1] * j[1] + j[2] * j[2];
        if (!(n2 > 0)) break;
        const long double nx = px - j[0] * j[1] / n2, ny = py - j[0] * j[2] / n2;
        if (!(nx >= 0 && nx <= 1 && ny >= 0 && ny <= 1)) break;
        on_curve = std::fabs(nx - px) + std::fabs(ny - py) < 1e-17L;
        px = nx;
        py = ny;
      }
      if (on_curve)
        arc.inner.push_back({CGAL::to_double(B.u0) + double(px) * CGAL::to_double(wu),
                             CGAL::to_double(B.v0) + double(py) * CGAL::to_double(wv)});
    }
    arcs_.push_back(arc);
  }
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_TOPOLOGY_INTERNAL_SUBDIVISION_SINGULAR_BOXES_H
