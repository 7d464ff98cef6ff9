// The status of the arc points next to an exact point whose partner lies on the partner domain's boundary.
//
// At a point e = (x_e, y_e) of partner_boundary_points.h (exact rationals, E(e) = 0, y_e on a side or a corner of
// the partner domain: two cylinders of one radius leaving both patches at a shared corner, a torus touching a
// bitangent plane at a corner of the plane's patch) the partner enclosure K of every span next to x_e reaches over
// the side, however short the span: the partner is within rounding of it. The crossing test of
// partner_domain_crossings.h needs a transversal crossing and an isolated solution of the crossing system, which
// a corner is not. Monotonicity decides instead, one partner coordinate y_c at a time:
//  1. Krawczyk's test over T' = hull(T, t_e) (strict, partner_span_proofs.h: prove_zero_curve) gives a zero curve
//     gamma unique in a box W' over T'; the sheet's enclosure K over T lies in W', so gamma is the sheet over T;
//     e lies in W', so gamma(t_e) = e (E(e) = 0 exactly, uniqueness).
//  2. gamma'(t) over T' x K' (implicit_slopes) encloses the slope of y_c; if it has a sign, y_c(t) - y_e,c has the
//     sign of gamma'_c (t - t_e) on T' (mean value theorem), so for t in T beyond t_e, y_c is strictly on a known
//     side of the bound beta = y_e,c.
// A coordinate whose enclosure lies inside its range is inside, one whose enclosure misses it is outside; the
// partner is inside the closed domain over T if every coordinate is, outside if one is.
#ifndef BEZOUTIAN_LIFTING_INTERNAL_EXACT_POINT_SPANS_H
#define BEZOUTIAN_LIFTING_INTERNAL_EXACT_POINT_SPANS_H

#include <bezoutian/lifting/internal/partner_span_proofs.h>
#include <bezoutian/lifting/partner_boundary_points.h>

#include <algorithm>
#include <array>

namespace bezoutian {
namespace internal {

/// The sign (1, -1, or 0 if not proved) of F(t) = w_c(t) - w_c(t_e) for every t in T, where w(t) is the zero curve
/// unique in W over Tp = hull(T, t_e) (Kp: its enclosure over Tp) and T lies on the side `side` of t_e, by the
/// integral of F' = w_c' over Tp cut into 32 pieces P_k from t_e outwards: for t in P_m,
/// F(t) = side * (sum_{k<m} |P_k cap [t, t_e]| S_k + |P_m cap [t, t_e]| S_m) with S_k an enclosure of w_c' over P_k
/// (implicit_slopes on P_k's Krawczyk image) and each length |P_k| exactly for the pieces between, in [0, |P_k|]
/// for the piece holding t_e and for P_m. Where the partner touches the side and turns back, w_c' vanishes at t_e
/// and no one enclosure over Tp has a sign; the sum keeps the sign of -(t - t_e)^2 while the pieces' enclosures are
/// tighter than their distance to t_e.
inline int sign_by_integrated_slope(const Partner_equations& eq, int axis, const Double_interval& Tp,
                                    const std::array<Double_interval, 3>& W, const std::array<Double_interval, 3>& Kp,
                                    const Double_interval& T, const Rational& t_e, int side, int c) {
  using D = Double_interval;
  const int N = 32;
  auto bound = [&](int i) { return i == 0 ? Tp.lo : (i == N ? Tp.hi : Tp.lo + (Tp.hi - Tp.lo) * i / N); };
  D sum{0, 0};
  int sign = 0;
  for (int k = 0; k < N; ++k) {
    const D P = side < 0 ? D{bound(N - 1 - k), bound(N - k)} : D{bound(k), bound(k + 1)};
    if (!(P.lo <= P.hi)) return 0;
    std::array<D, 3> image = W, X;
    if (!parametric_partner_krawczyk(eq, axis, P, image)) image = Kp;  // (w(P) lies in Kp too)
    if (!implicit_slopes(eq, axis, P, image, X)) return 0;
    const D length = D::widen(P.hi - P.lo, P.hi - P.lo);
    const D partial{0, length.hi};
    if (Rational(P.hi) >= Rational(T.lo) && Rational(P.lo) <= Rational(T.hi)) {  // P meets T: F over P cap T
      const D F = D{double(side), double(side)} * (sum + partial * X[c]);
      const int s = F.lo > 0 ? 1 : (F.hi < 0 ? -1 : 0);
      if (s == 0 || (sign != 0 && s != sign)) return 0;
      sign = s;
    }
    const bool between = side < 0 ? Rational(P.hi) <= t_e : Rational(P.lo) >= t_e;  // P inside [t, t_e]
    sum = sum + (between ? length : partial) * X[c];
  }
  return sign;
}

/// The status (genuine, outside or undecided) of the sheet whose zero curve over the span T of a graph piece
/// (graph coordinate `axis`) is enclosed in K (other coordinate, partner; K's other coordinate inside the cell)
/// next to the exact point `e` (the header comment). T lies on one side of e's graph coordinate t_e (it may end at
/// t_e: the partner there is y_e, in the closed domain).
inline Partner_status status_beside_exact_point(const Partner_equations& eq, const Parameter_box& domain, int axis,
                                                const Double_interval& T, const std::array<Double_interval, 3>& K,
                                                const Partner_boundary_point& e) {
  using D = Double_interval;
  const Partner_status no = Partner_status::undecided;
  const int other = 1 - axis;
  const Rational& t_e = e.x[std::size_t(axis)];
  const D Te = D::of(t_e);
  int side;  // sign of t - t_e over T
  if (Rational(T.hi) <= t_e)
    side = -1;
  else if (Rational(T.lo) >= t_e)
    side = 1;
  else
    return no;
  // 1. the zero curve over T' from a box around K and e
  const D Tp{std::min(T.lo, Te.lo), std::max(T.hi, Te.hi)};
  const std::array<Rational, 3> exact{e.x[std::size_t(other)], e.y[0], e.y[1]};
  std::array<D, 3> W, Kp;
  for (int c = 0; c < 3; ++c) {
    const D x = D::of(exact[std::size_t(c)]);
    const double lo = std::min(K[c].lo, x.lo), hi = std::max(K[c].hi, x.hi), r = 0.1 * (hi - lo) + 1e-15;
    W[c] = D{lo - r, hi + r};
  }
  if (!prove_zero_curve(eq, axis, Tp, W, Kp)) return no;
  for (int c = 0; c < 3; ++c)
    if (!(W[c].lo <= K[c].lo && K[c].hi <= W[c].hi && Rational(Kp[c].lo) <= exact[std::size_t(c)] &&
          exact[std::size_t(c)] <= Rational(Kp[c].hi)))
      return no;
  // 2. the partner's coordinates: y = (v, s), v the second coordinate of P, s the first of Q
  std::array<D, 3> X;
  bool slopes = false;
  const std::array<std::pair<Rational, Rational>, 2> range{std::make_pair(domain.v0, domain.v1),
                                                           std::make_pair(domain.u0, domain.u1)};
  bool inside = true;
  for (int c = 0; c < 2; ++c) {
    const D& y = K[1 + c];
    const Rational &lo = range[std::size_t(c)].first, &hi = range[std::size_t(c)].second;
    if (interval_inside(y, lo, hi)) continue;
    if (interval_disjoint(y, lo, hi)) return Partner_status::outside;
    const Rational& beta = e.y[std::size_t(c)];
    const bool at_lo = beta == lo, at_hi = beta == hi;
    // (the enclosure may reach over the side at beta only: the other side is decided by the interval)
    if (!(at_lo || at_hi) || (at_lo && Rational(y.hi) > hi) || (at_hi && Rational(y.lo) < lo)) return no;
    if (!slopes && !(slopes = implicit_slopes(eq, axis, Tp, Kp, X))) return no;
    const D& slope = X[1 + c];
    // the sign of y_c - beta over T (t != t_e)
    const int sign = !slope.contains_zero() ? (slope.lo > 0 ? 1 : -1) * side
                                            : sign_by_integrated_slope(eq, axis, Tp, W, Kp, T, t_e, side, 1 + c);
    if (sign == 0) return no;
    if (at_lo ? sign < 0 : sign > 0) return Partner_status::outside;
    inside = inside && (at_lo ? sign > 0 : sign < 0);
  }
  if (!inside) return no;
  // the arc points' coordinates (P = (x1, y1), Q = (y2, x2)) in the domain
  const D& X1 = axis == 0 ? T : K[0];
  const D& X2 = axis == 0 ? K[0] : T;
  if (!(interval_inside(X1, domain.u0, domain.u1) && interval_inside(X2, domain.v0, domain.v1)))
    return no;
  if (eq.self_intersection() && K[1].contains_zero() && K[2].contains_zero()) return no;
  return Partner_status::genuine;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_LIFTING_INTERNAL_EXACT_POINT_SPANS_H
