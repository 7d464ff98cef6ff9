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
//  3. Where the partner touches the side and turns back, gamma'_c vanishes at t_e and has no sign over T'; the
//     slope integrated piece by piece from t_e (sign_by_integrated_slope) keeps the sign of -(t - t_e)^2, in double
//     intervals and, within about 1e-12 of t_e, in 256-bit intervals.
// A coordinate whose enclosure lies inside its range is inside, one whose enclosure misses it is outside; the
// partner is inside the closed domain over T if every coordinate is, outside if one is.
#ifndef BEZOUTIAN_LIFTING_INTERNAL_EXACT_POINT_SPANS_H
#define BEZOUTIAN_LIFTING_INTERNAL_EXACT_POINT_SPANS_H

#include <bezoutian/arithmetic/mpfi_interval.h>
#include <bezoutian/lifting/internal/partner_span_proofs.h>
#include <bezoutian/lifting/partner_boundary_points.h>

#include <algorithm>
#include <array>
#include <cmath>

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

/// sign_by_integrated_slope in 256-bit interval arithmetic (MPFI), for a span within about 1e-12 of t_e, where the
/// double enclosures (about 1e-14 wide) are wider than the partner's distance to the side, about (t - t_e)^2: 16
/// pieces with rational ends; w(P_k) enclosed by three Krawczyk steps from W (each image intersected with the box:
/// it holds every zero there), w_c' over P_k by Cramer's rule on the preconditioned system.
inline int sign_by_integrated_slope_mpfi(const Partner_equations& eq, int axis, const Double_interval& Tp,
                                         const std::array<Double_interval, 3>& W, const Double_interval& T,
                                         const Rational& t_e, int side, int c) {
  using M = Mpfi_interval;
  using Cx = Partner_equations::Cx;
  const mpfr_prec_t prec = 256;
  const int N = 16, q[3] = {1 - axis, 2, 3};
  const M zero = M::point(0, prec);
  // E and dE/dz over (t, w), real; false if a weight may vanish
  auto evaluate = [&](const M& t, const std::array<M, 3>& w, std::array<M, 3>& E, std::array<std::array<M, 4>, 3>& J) {
    std::array<Cx, 4> z{Cx{zero, zero}, Cx{zero, zero}, Cx{zero, zero}, Cx{zero, zero}};
    z[std::size_t(axis)] = Cx{t, zero};
    for (int k = 0; k < 3; ++k) z[std::size_t(q[k])] = Cx{w[std::size_t(k)], zero};
    std::array<Cx, 3> Ec{Cx{zero, zero}, Cx{zero, zero}, Cx{zero, zero}};
    const Cx zc{zero, zero};
    std::array<std::array<Cx, 4>, 3> Jc{std::array<Cx, 4>{zc, zc, zc, zc}, std::array<Cx, 4>{zc, zc, zc, zc},
                                        std::array<Cx, 4>{zc, zc, zc, zc}};
    std::array<Cx, 2> weights{Cx{zero, zero}, Cx{zero, zero}};
    eq.evaluate(z, Ec, Jc, weights);
    if (weights[0].re.contains_zero() || weights[1].re.contains_zero()) return false;
    for (int r = 0; r < 3; ++r) {
      E[std::size_t(r)] = Ec[std::size_t(r)].re;
      for (int i = 0; i < 4; ++i) J[std::size_t(r)][std::size_t(i)] = Jc[std::size_t(r)][std::size_t(i)].re;
    }
    return true;
  };
  auto point = [&](const Rational& x) { return M::hull(x, x, prec); };
  const Rational lo(Tp.lo), hi(Tp.hi);
  auto bound = [&](int i) { return lo + (hi - lo) * Rational(i) / Rational(N); };
  std::array<M, 3> Wm{zero, zero, zero};
  for (int k = 0; k < 3; ++k) Wm[std::size_t(k)] = M::hull(Rational(W[std::size_t(k)].lo), Rational(W[std::size_t(k)].hi), prec);
  M sum = zero;
  int sign = 0;
  for (int k = 0; k < N; ++k) {
    const Rational a = side < 0 ? bound(N - 1 - k) : bound(k), b = side < 0 ? bound(N - k) : bound(k + 1);
    const M P = M::hull(a, b, prec), tm = point((a + b) / Rational(2));
    std::array<M, 3> B = Wm, E{zero, zero, zero};
    std::array<std::array<M, 4>, 3> J{std::array<M, 4>{zero, zero, zero, zero}, std::array<M, 4>{zero, zero, zero, zero},
                                      std::array<M, 4>{zero, zero, zero, zero}};
    double C[3][3];
    for (int it = 0; it < 3; ++it) {
      std::array<M, 3> m{B[0].midpoint(), B[1].midpoint(), B[2].midpoint()};
      std::array<M, 3> Em{zero, zero, zero};
      std::array<std::array<M, 4>, 3> Jm = J;
      if (!evaluate(tm, m, Em, Jm) || !evaluate(P, B, E, J)) return 0;
      double A[3][3];
      for (int r = 0; r < 3; ++r)
        for (int cc = 0; cc < 3; ++cc) A[r][cc] = Jm[std::size_t(r)][std::size_t(q[cc])].mid_double();
      if (!invert_3x3(A, C)) return 0;
      for (int r = 0; r < 3; ++r) {
        M x = m[std::size_t(r)], slope = zero;
        for (int l = 0; l < 3; ++l) {
          x = x - C[r][l] * Em[std::size_t(l)];
          slope = slope + C[r][l] * J[std::size_t(l)][std::size_t(axis)];
        }
        x = x - slope * (P - tm);
        for (int cc = 0; cc < 3; ++cc) {
          M g = M::point(r == cc ? 1.0 : 0.0, prec);
          for (int l = 0; l < 3; ++l) g = g - C[r][l] * J[std::size_t(l)][std::size_t(q[cc])];
          x = x + g * (B[std::size_t(cc)] - m[std::size_t(cc)]);
        }
        // the image holds every zero in B: B := image cap B
        const Rational l = std::max(x.lower(), B[std::size_t(r)].lower()), h = std::min(x.upper(), B[std::size_t(r)].upper());
        if (l > h) return 0;
        B[std::size_t(r)] = M::hull(l, h, prec);
      }
    }
    if (!evaluate(P, B, E, J)) return 0;
    // w' = -(dE/dw)^-1 dE/dt over P x B, preconditioned by C
    std::array<std::array<M, 3>, 3> Mat{std::array<M, 3>{zero, zero, zero}, std::array<M, 3>{zero, zero, zero},
                                        std::array<M, 3>{zero, zero, zero}};
    std::array<M, 3> rhs{zero, zero, zero};
    for (int r = 0; r < 3; ++r)
      for (int l = 0; l < 3; ++l) {
        rhs[std::size_t(r)] = rhs[std::size_t(r)] + C[r][l] * J[std::size_t(l)][std::size_t(axis)];
        for (int cc = 0; cc < 3; ++cc)
          Mat[std::size_t(r)][std::size_t(cc)] = Mat[std::size_t(r)][std::size_t(cc)] + C[r][l] * J[std::size_t(l)][std::size_t(q[cc])];
      }
    auto det3 = [](const std::array<std::array<M, 3>, 3>& x) {
      return x[0][0] * (x[1][1] * x[2][2] - x[1][2] * x[2][1]) - x[0][1] * (x[1][0] * x[2][2] - x[1][2] * x[2][0]) +
             x[0][2] * (x[1][0] * x[2][1] - x[1][1] * x[2][0]);
    };
    const M det = det3(Mat);
    if (det.contains_zero()) return 0;
    std::array<std::array<M, 3>, 3> Mc = Mat;
    for (int r = 0; r < 3; ++r) Mc[std::size_t(r)][std::size_t(c)] = rhs[std::size_t(r)];
    const M X = zero - det3(Mc) / det;
    const Rational len = b - a;
    const M length = point(len), partial = M::hull(Rational(0), len, prec);
    if (b >= Rational(T.lo) && a <= Rational(T.hi)) {  // P meets T
      const M F = double(side) * (sum + partial * X);
      const int s = F.positive() ? 1 : ((zero - F).positive() ? -1 : 0);
      if (s == 0 || (sign != 0 && s != sign)) return 0;
      sign = s;
    }
    const bool between = side < 0 ? b <= t_e : a >= t_e;
    sum = sum + (between ? length : partial) * X;
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
  // (two patches only: the coordinate ranges below are those of y = (v, s); a self-intersection's partner domain
  // moves with the point, and partner_boundary_points.h makes no exact points for it)
  if (eq.self_intersection()) return no;
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
  // (the mean-value form in t makes the image symmetric about the value at Tp's centre, where the partner's
  // range is one-sided at a touch: a box twice as wide is tried next)
  std::array<D, 3> W, Kp;
  bool proved = false;
  for (const double f : {0.1, 1.0}) {
    for (int c = 0; c < 3; ++c) {
      const D x = D::of(exact[std::size_t(c)]);
      const double lo = std::min(K[c].lo, x.lo), hi = std::max(K[c].hi, x.hi), r = f * (hi - lo) + 1e-15;
      W[c] = D{lo - r, hi + r};
    }
    if ((proved = prove_zero_curve(eq, axis, Tp, W, Kp))) break;
  }
  if (!proved) return no;
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
    int sign = !slope.contains_zero() ? (slope.lo > 0 ? 1 : -1) * side
                                      : sign_by_integrated_slope(eq, axis, Tp, W, Kp, T, t_e, side, 1 + c);
    if (sign == 0 && Tp.hi - Tp.lo <= 1e-12 * (1 + std::fabs(Tp.lo)))
      sign = sign_by_integrated_slope_mpfi(eq, axis, Tp, W, T, t_e, side, 1 + c);
    if (sign == 0) return no;
    if (at_lo ? sign < 0 : sign > 0) return Partner_status::outside;
    inside = inside && (at_lo ? sign > 0 : sign < 0);
  }
  if (!inside) return no;
  // the arc points' coordinates (P = (x1, y1), Q = (y2, x2)) in the domain
  const D& X1 = axis == 0 ? T : K[0];
  const D& X2 = axis == 0 ? K[0] : T;
  if (!(interval_inside(X1, domain.u0, domain.u1) && interval_inside(X2, domain.v0, domain.v1))) return no;
  return Partner_status::genuine;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_LIFTING_INTERNAL_EXACT_POINT_SPANS_H
