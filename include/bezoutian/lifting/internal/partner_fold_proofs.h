// Folds of the partner: where two sheets of an arc of D = 0 meet and end. A sphere patch cut by a plane z = c
// (y = t on the plane) is the example: an arc point (u, t) has the two partners b and 1/b of y = c 2b / (1 + b^2)
// until t reaches c, where they meet at b = 1; beyond, its partners are complex and the point is phantom. The
// curve of solutions of the three partner equations E(x, y) = 0 in the 4 unknowns z = (x1, x2, y1, y2) is smooth
// there, but its tangent lies in the partner plane: over the graph coordinate t the Jacobian in (o, y1, y2) is
// singular (o the arc's other coordinate), so neither the span proofs of partner_span_proofs.h nor the exclusion
// (the fibre is nearly real just past the fold) decide the spans next to it.
//
// The fold chart takes the partner coordinate y_c that separates the two sheets as the parameter instead: the
// unknowns are w = (o, t, y_c'), and dE/dw is regular at a fold where y_c moves along the curve. The proof, for
// the span X = [t0, t_ext] of a graph piece (t0 a traced point before the fold, where the sheets have partners
// y_a, y_b, and t_ext a little beyond the fold):
//  1. Krawczyk's test (strict, parametric in y_c over Y, a neighbourhood of [y_a,c, y_b,c]) on a box W: for every
//     y_c in Y exactly one zero gamma(y_c) of E in W, continuous (the span proofs' argument with the roles of t and
//     y_c exchanged). Every zero of E in Y x W is on gamma.
//  2. Where gamma's other coordinate lies strictly inside the cell, where every line t = const meets D = 0 at most
//     once, a point of gamma over a t of the piece is the arc point there, with a partner.
//  3. The t of gamma at both ends of Y is before t0 (Krawczyk images at the two single values), and at one value
//     y* it is at least tau_lo: by continuity gamma passes every t in [t0, tau_lo] on each side of y*. An upper
//     bound tau_hi of t over gamma comes from Krawczyk images on a bisection of Y around y*, each on the box the
//     image of its parent gave (every zero of E in a box lies in the box's Krawczyk image). These pieces cover Y;
//     where a piece's enclosure lies inside the cell (step 2) with both points in the domain, the arc points it
//     passes are genuine. The claim stops before the t of the first piece where that fails: at a fold in a corner of
//     the cell (two cylinders of one radius: the arc u = t reaches the corner (1, 1), where both coordinates are
//     extreme along gamma), the pieces next to y* reach over the cell's sides by their rounding only.
//  4. Completeness over X: no point of X x W_o has a partner in the domain outside the hole Y x W_c' (the
//     exclusion from the complement cover, as in partner_sheets.h), and no point of X x (the cell's other range
//     outside W_o) has a partner in the domain at all (exclude_strips). So every partner of an arc point over X
//     is on gamma, and an arc point beyond tau_hi has none: phantom.
// The remaining stretch past t_ext is excluded by strips of doubling width (the fibre's near-real root recedes
// from the real plane like the square root of the distance to the fold). Only the arc points in [claim, tau_hi],
// an interval of a few ulps around the fold (about a hundred at a corner), are left without a status.
//
// Near a fold one unknown depends on the parameter or on another unknown quadratically (u ~ 1 - s^2 above), so
// Krawczyk's linear bound of its range grows with the other's width: the box of step 1 is found by inflating the
// operator's image alone (prove_zero_curve), which lets the other unknown shrink to its range.
#ifndef BEZOUTIAN_LIFTING_INTERNAL_PARTNER_FOLD_PROOFS_H
#define BEZOUTIAN_LIFTING_INTERNAL_PARTNER_FOLD_PROOFS_H

#include <bezoutian/lifting/certified_lifting.h>
#include <bezoutian/lifting/internal/partner_span_proofs.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace bezoutian {
namespace internal {

/// The partner equations in the fold chart: z' = (y_c, o, t, y_c'), with t = x_axis the graph coordinate, o the
/// other coordinate of the projection plane, y_c the parameter. The same interface as Partner_equations for the
/// span proofs (evaluate over interval boxes, weights), so parametric_partner_krawczyk applies with axis 0.
template <class Eq>
class Fold_chart {
 public:
  using D = Double_interval;
  Fold_chart(const Eq& eq, int axis, int c) : eq_(eq), p_{2 + c, 1 - axis, axis, 3 - c} {}
  /// z in the coordinates of the partner equations
  std::array<D, 4> original(const std::array<D, 4>& zp) const {
    std::array<D, 4> z;
    for (int k = 0; k < 4; ++k) z[std::size_t(p_[k])] = zp[std::size_t(k)];
    return z;
  }
  void evaluate(const std::array<D, 4>& zp, std::array<D, 3>& E, std::array<std::array<D, 4>, 3>* J = nullptr) const {
    if (!J) {
      eq_.evaluate(original(zp), E);
      return;
    }
    std::array<std::array<D, 4>, 3> Jz;
    eq_.evaluate(original(zp), E, &Jz);
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 4; ++k) (*J)[std::size_t(r)][std::size_t(k)] = Jz[std::size_t(r)][std::size_t(p_[k])];
  }
  std::array<D, 2> weights(const std::array<D, 4>& zp) const { return eq_.weights(original(zp)); }

 private:
  const Eq& eq_;
  int p_[4];
};

/// What prove_partner_fold proved (graph-coordinate ranges, closed, either may be empty: lo > hi).
struct Fold_proof {
  bool proved = false;
  /// every arc point over this range is genuine, and every partner it has in the domain lies in `partners`
  Double_interval genuine{1, 0};
  /// every arc point over this range has no partner in the domain (phantom, fibre proved empty)
  Double_interval phantom{1, 0};
  /// [tau_lo, tau_hi]: holds the fold's graph coordinate (the largest t over gamma in the fold's direction); an arc
  /// point there is genuine exactly when it is not beyond the fold (the fold point's own interval, as a split point's
  /// box)
  Double_interval fold{1, 0};
  std::array<Double_interval, 2> partners{};
};

/// The Krawczyk image, in the fold chart, of the zeros over the parameter range P inside the box W, intersected
/// with W and iterated `rounds` times (each zero in a box lies in the box's image); false if an image is not finite
/// or empty (then no zero lies in W over P, or the test cannot say).
template <class Chart>
inline bool fold_image(const Chart& ch, const Double_interval& P, std::array<Double_interval, 3>& W, int rounds) {
  using D = Double_interval;
  for (int r = 0; r < rounds; ++r) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::array<D, 3> img{D{nan, nan}, D{nan, nan}, D{nan, nan}}, trial = W;
    parametric_partner_krawczyk(ch, 0, P, trial, &img, false);
    for (int c = 0; c < 3; ++c) {
      if (!(std::isfinite(img[c].lo) && std::isfinite(img[c].hi))) return false;
      const D next{std::max(W[c].lo, img[c].lo), std::min(W[c].hi, img[c].hi)};
      if (!(next.lo <= next.hi)) return false;
      W[c] = next;
    }
  }
  return true;
}

/// The proof of the header comment. t0, o0: the graph and other coordinate of the traced point before the fold,
/// ya, yb: the two sheets' floating-point partners there; t_fold: a floating-point estimate of the fold's graph
/// coordinate; t_far: how far past the fold to decide (the piece's last point on that side; t_far = t_fold when
/// the piece ends at the fold). `cell`: the piece's cell.
inline Fold_proof prove_partner_fold(const Partner_equations& eq, const Parameter_box& domain, const Parameter_box& cell,
                                     int axis, double t0, double o0, const std::array<double, 2>& ya,
                                     const std::array<double, 2>& yb, double t_fold, double t_far, Exclusion_budget& budget) {
  using D = Double_interval;
  Fold_proof out;
  const int c = std::fabs(ya[0] - yb[0]) >= std::fabs(ya[1] - yb[1]) ? 0 : 1;
  const double sep = std::fabs(ya[c] - yb[c]);
  if (!(sep > 0) || !(t_fold != t0)) return out;
  const double sigma = t_fold > t0 ? 1 : -1;  // the direction of the fold along the graph coordinate
  auto before = [&](double a, double b) { return sigma * (a - b) < 0; };  // a is strictly before b
  const Fold_chart<Partner_equations> ch(eq, axis, c);
  const D Y{std::min(ya[c], yb[c]) - 0.25 * sep, std::max(ya[c], yb[c]) + 0.25 * sep};
  // 1. the zero curve gamma over Y, unique in W
  std::array<D, 3> W, K;
  if (!predict_partner_box(ch, 0, Y, {o0, 0.5 * (t0 + t_fold), 0.5 * (ya[1 - c] + yb[1 - c])}, W)) return out;
  if (!prove_zero_curve(ch, 0, Y, W, K)) return out;
  // 2. gamma's points are arc points, with partners in the domain (and not the trivial one), where their enclosure
  // lies inside the cell and the domain; checked per piece of Y below, as a fold at a corner of the cell (both
  // coordinates of the arc extreme there) reaches the cell's sides
  const Rational &o_lo = axis == 0 ? cell.v0 : cell.u0, &o_hi = axis == 0 ? cell.v1 : cell.u1;
  const std::array<D, 4> z = ch.original({Y, K[0], K[1], K[2]});
  if (eq.self_intersection() && z[2].contains_zero() && z[3].contains_zero()) return out;
  auto arc_points_genuine = [&](const D& y, const std::array<D, 3>& box) {
    if (!(Rational(box[0].lo) > o_lo && Rational(box[0].hi) < o_hi)) return false;
    std::array<D, 2> P, Q;
    eq.points(ch.original({y, box[0], box[1], box[2]}), P, Q);
    return interval_inside(P[0], domain.u0, domain.u1) && interval_inside(P[1], domain.v0, domain.v1) &&
           interval_inside(Q[0], domain.u0, domain.u1) && interval_inside(Q[1], domain.v0, domain.v1);
  };
  // 3. both ends of Y before t0; the extreme tau_lo reached at y*, the bound tau_hi over gamma
  auto t_at = [&](double y, D& t) {
    std::array<D, 3> box = K;
    if (!fold_image(ch, D{y, y}, box, 6)) return false;
    t = box[1];
    return true;
  };
  D t_end;
  for (const double y : {Y.lo, Y.hi}) {
    if (!t_at(y, t_end)) return out;
    if (!before(sigma > 0 ? t_end.hi : t_end.lo, t0)) return out;
  }
  double y_star = Y.mid(), best = -HUGE_VAL;  // floating point: the y_c where t is extreme
  for (double lo = Y.lo, hi = Y.hi, round = 0; round < 12 && lo < hi; ++round) {
    const double step = (hi - lo) / 16;
    for (int k = 0; k <= 16; ++k) {
      D t;
      if (t_at(lo + k * step, t) && sigma * t.mid() > best) best = sigma * t.mid(), y_star = lo + k * step;
    }
    lo = std::max(Y.lo, y_star - step);
    hi = std::min(Y.hi, y_star + step);
  }
  D t_star;
  if (!t_at(y_star, t_star)) return out;
  const double tau_lo = sigma > 0 ? t_star.lo : t_star.hi;
  struct Piece {
    D y;
    std::array<D, 3> box;
    double bound;  // sigma * (the upper end of t over the piece's image)
  };
  std::vector<Piece> pieces;
  for (int k = 0; k < 8; ++k) {
    Piece p{D{Y.lo + (Y.hi - Y.lo) * k / 8, k == 7 ? Y.hi : Y.lo + (Y.hi - Y.lo) * (k + 1) / 8}, K, 0};
    if (!fold_image(ch, p.y, p.box, 2)) return out;
    p.bound = sigma > 0 ? p.box[1].hi : -p.box[1].lo;
    pieces.push_back(p);
  }
  for (int round = 0; round < 200; ++round) {
    auto top = std::max_element(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) { return a.bound < b.bound; });
    if (top->bound - sigma * tau_lo <= 1e-15 * (1 + std::fabs(tau_lo))) break;
    const double m = top->y.mid();
    if (!(top->y.lo < m && m < top->y.hi)) break;  // (tau_hi: the bound of a piece too narrow to halve)
    const Piece p = *top;
    pieces.erase(top);
    for (const D& half : {D{p.y.lo, m}, D{m, p.y.hi}}) {
      Piece h{half, p.box, 0};
      if (!fold_image(ch, h.y, h.box, 2)) return out;
      h.bound = sigma > 0 ? h.box[1].hi : -h.box[1].lo;
      pieces.push_back(h);
    }
  }
  double tau_hi = -HUGE_VAL;
  for (const Piece& p : pieces) tau_hi = std::max(tau_hi, p.bound);
  tau_hi *= sigma;
  // the pieces cover Y: an arc point over t is a point of gamma in a piece where the check of step 2 holds, unless
  // t reaches the range of a piece where it fails; genuine is claimed before the first such t only
  double claim = tau_lo;
  for (const Piece& p : pieces)
    if (!arc_points_genuine(p.y, p.box)) {
      const double reach = sigma > 0 ? p.box[1].lo : p.box[1].hi;
      if (!before(t0, reach)) return out;
      if (before(reach, claim) || reach == claim) claim = std::nextafter(reach, sigma * -HUGE_VAL);
    }
  // 4. completeness over X = [t0, t_ext]: a box of uniqueness wide enough past the fold and across the arc for the
  // exclusions next to it (the strips' boxes near W_o need sides about their distance to the arc)
  const bool far_side = before(tau_hi, t_far);
  double t_ext = far_side ? tau_hi + sigma * std::fabs(tau_hi - t0) : t_far;
  if (far_side && before(t_far, t_ext)) t_ext = t_far;
  std::array<D, 3> Wx = W;
  bool widened = false;
  for (int attempt = 0; attempt < 3 && !widened; ++attempt) {
    const double reach = std::fabs(t_ext - t0), ho = std::max(0.5 * (W[0].hi - W[0].lo), 0.5 * reach);
    Wx = W;
    Wx[0] = D{std::min(W[0].lo, K[0].mid() - ho), std::max(W[0].hi, K[0].mid() + ho)};
    Wx[1] = D{std::min({W[1].lo, t0, t_ext}), std::max({W[1].hi, t0, t_ext})};
    std::array<D, 3> trial = Wx;
    widened = parametric_partner_krawczyk(ch, 0, Y, trial, nullptr, true);
    if (!widened && far_side) t_ext = tau_hi + sigma * 0.5 * std::fabs(t_ext - tau_hi);
  }
  if (!widened) return out;
  const D X{std::min(t0, t_ext), std::max(t0, t_ext)};
  std::array<D, 2> hole;
  hole[std::size_t(c)] = Y;
  hole[std::size_t(1 - c)] = Wx[2];
  const double big = 1e300;
  const std::vector<std::array<D, 2>> cover = complement_cover({D{-big, big}, D{-big, big}}, {hole});
  auto box_of = [&](const D& t, const Rational& a, const Rational& b) {
    return axis == 0 ? Parameter_box{Rational(t.lo), Rational(t.hi), a, b} : Parameter_box{a, b, Rational(t.lo), Rational(t.hi)};
  };
  const Rational wo_lo(Wx[0].lo), wo_hi(Wx[0].hi);
  {  // (in four spans: the boxes next to the hole need sides well below the sheets' distance)
    std::vector<D> quarters;
    for (int k = 0; k < 4; ++k) quarters.push_back(D{X.lo + (X.hi - X.lo) * k / 4, k == 3 ? X.hi : X.lo + (X.hi - X.lo) * (k + 1) / 4});
    const std::vector<bool> ok = exclude_strips(eq, domain, axis, quarters, box_of(X, wo_lo, wo_hi), &cover, budget);
    if (std::count(ok.begin(), ok.end(), true) != 4) return out;
  }
  for (int side = 0; side < 2; ++side) {  // the cell's other range below and above W_o
    const Rational a = side == 0 ? o_lo : wo_hi, b = side == 0 ? wo_lo : o_hi;
    if (!(a < b)) continue;
    const Parameter_box strip_cell = box_of(X, a, b);
    if (!exclude_strips(eq, domain, axis, {X}, strip_cell, nullptr, budget)[0]) return out;
  }
  out.proved = true;
  out.genuine = D{std::min(t0, claim), std::max(t0, claim)};
  out.partners = {z[2], z[3]};
  // (tau_hi itself is not claimed phantom: the fold's graph coordinate may equal it)
  const double first = std::nextafter(tau_hi, sigma * HUGE_VAL);
  out.fold = D{std::min(claim, first), std::max(claim, first)};
  if (!far_side) return out;
  double reached = t_ext;  // phantom over (tau_hi, reached]
  // the stretch past t_ext: strips of doubling width, from the fold outwards
  std::vector<D> spans;
  for (double s = t_ext, d = std::fabs(t_ext - t0); before(s, t_far) && spans.size() < 40; d *= 2) {
    double next = s + sigma * d;
    if (before(t_far, next) || spans.size() == 39) next = t_far;
    spans.push_back(D{std::min(s, next), std::max(s, next)});
    s = next;
  }
  if (!spans.empty()) {
    std::vector<D> sorted = spans;
    if (sigma < 0) std::reverse(sorted.begin(), sorted.end());
    const std::vector<bool> ok = exclude_strips(eq, domain, axis, sorted, cell, nullptr, budget, sigma < 0);
    for (std::size_t k = 0; k < spans.size(); ++k) {
      const std::size_t j = sigma > 0 ? k : spans.size() - 1 - k;
      if (!ok[j]) break;
      reached = sigma > 0 ? spans[k].hi : spans[k].lo;
    }
  }
  out.phantom = D{std::min(first, reached), std::max(first, reached)};
  return out;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_LIFTING_INTERNAL_PARTNER_FOLD_PROOFS_H
