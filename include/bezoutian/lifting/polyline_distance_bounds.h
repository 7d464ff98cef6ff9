// Proved bounds on the distance between a sheet's reported polylines and the branch of the space curve they draw.
//
// A sheet (partner_sheets.h) is drawn by chords between consecutive points. Over a segment whose coordinate t (the
// graph coordinate of a graph piece, or the coordinate a half-branch's chain runs on) covers T = [a, b], the branch
// is a curve gamma(t) = (t, g(t), y(t)) of zeros of the partner equations E(t, w) = 0, w = (other coordinate, y1,
// y2). T is cut into 1, 4, 16 or 64 sub-spans (finer while the bound exceeds the target). Per sub-span T_k:
//  1. Krawczyk's test with strict inclusion over T_k (partner_span_proofs.h: prove_zero_curve) gives a box W_k in
//     which E(t, .) has exactly one zero gamma(t) for every t in T_k, with dE/dw regular on W_k (gamma is smooth),
//     and an image K_k that holds gamma(T_k). Consecutive sub-spans share their zero at the common end: the point
//     enclosure of one lies in the other's box of uniqueness.
//  2. gamma is the sheet's branch. On a graph piece: anchored once (zero_curve_anchored: (t*, gamma_0(t*)) is the
//     arc point of the piece's cell, where D = 0 is a graph over t; by continuity and the graph property
//     (t, gamma_0(t)) is the arc point for every t in T; not the trivial partner of a self-intersection, excluded
//     from K); and at an end, the box of g(t) (in gamma's point enclosure) times the sheet's proved partner
//     enclosure is contracted by point Krawczyk steps (each image holds every zero of the box) until it lies in W:
//     the sheet's exact point there is the zero in W, gamma's. On a half-branch H: a span of H's chain with one
//     partner in the domain holds T_k and K_k's other coordinate, and K_k puts both parameter points inside the
//     domain; every point of that region with a partner in the domain lies on H with only that partner
//     (half_branch_chains.h), so gamma is H with it.
//  3. Slopes. Differentiating E(t, gamma(t)) = 0: J_w w' = -J_t. With C the inverse of the midpoint of J_w over
//     T_k x K_k and G = I - C J_w, w' = -C J_t + G w', so |w'|_inf <= |C J_t|_inf / (1 - |G|_inf) =: R when
//     |G|_inf < 1; w' lies in -C J_t + G [-R, R]^3, contracted by the same fixed-point form (interval arithmetic
//     over T_k x K_k encloses every J met along gamma). The parameter points P, Q are sums of coordinates of
//     (t, w) (Partner_equations::points): their slopes are the sums of those enclosures. The space curve is
//     phi(P(t)): its slope is d phi / dP (interval quotient rule over P(K_k)) times P'(t).
//  4. A function f on [a, b] with f' in [s_lo, s_hi] (the hull over the sub-spans) differs from its chord L by at
//     most (b - a)(s_hi - s_lo) / 4: f - L = int_a^x (f' - m) with m the chord's slope, at most (x - a)(s_hi - m)
//     and (b - x)(m - s_lo), and the smaller of the two is largest where they are equal. The reported chord joins
//     the reported points, not the exact ones: their differences (Krawczyk's enclosure of gamma at t = a and
//     t = b, and phi over the enclosed P, against the reported values) are added, coordinate by coordinate; the
//     Euclidean norm of the sums bounds |C(t) - L(t)| for every t in T, matching points at equal t: both the
//     largest distance of the curve from the polyline and of the polyline from the curve.
// Where a step fails (the segment ending at a fold of the partners, where J_w is singular; a nearly singular
// Jacobian all along, as on the thin loop of two nearly tangent patches) the segment gets no bound (infinity).
#ifndef BEZOUTIAN_LIFTING_POLYLINE_DISTANCE_BOUNDS_H
#define BEZOUTIAN_LIFTING_POLYLINE_DISTANCE_BOUNDS_H

#include <bezoutian/arithmetic/double_interval.h>
#include <bezoutian/lifting/double_partner_witness.h>
#include <bezoutian/lifting/internal/half_branch_chains.h>
#include <bezoutian/lifting/internal/partner_span_proofs.h>
#include <bezoutian/topology/Curve_topology.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace bezoutian {
namespace internal {

/// x / y for y not containing 0 (the reciprocal's ends rounded outwards).
inline Double_interval interval_quotient(const Double_interval& x, const Double_interval& y) {
  return x * Double_interval::widen(1 / y.hi, 1 / y.lo);
}

/// Interval enclosures of a rational patch phi = (a1, a2, a3) / a0 and of its Jacobian over a parameter box, from
/// the exact power forms of Partner_equations::form (patch `which`).
class Patch_jacobian_enclosure {
 public:
  Patch_jacobian_enclosure(const Partner_equations& eq, int which) {
    for (int k = 0; k < 4; ++k) {
      const auto& f = eq.form(which, k);
      auto& F = forms_[std::size_t(k)];
      for (std::size_t j = 0; j < f.size(); ++j) {
        F[0].emplace_back();
        F[1].emplace_back();
        F[2].emplace_back();
        for (std::size_t i = 0; i < f[j].size(); ++i) {
          F[0][j].push_back(Double_interval::of(f[j][i]));
          F[1][j].push_back(i + 1 < f[j].size() ? Double_interval::of(f[j][i + 1] * int(i + 1)) : Double_interval{0, 0});
          F[2][j].push_back(j + 1 < f.size() && i < f[j + 1].size() ? Double_interval::of(f[j + 1][i] * int(j + 1))
                                                                      : Double_interval{0, 0});
        }
      }
    }
  }
  /// phi over the box P (false if the weight may vanish there).
  bool value(const std::array<Double_interval, 2>& P, std::array<Double_interval, 3>& phi) const {
    const Double_interval a0 = interval_horner(forms_[0][0], P[0], P[1]);
    if (a0.contains_zero()) return false;
    for (int c = 0; c < 3; ++c) phi[std::size_t(c)] = interval_quotient(interval_horner(forms_[std::size_t(c + 1)][0], P[0], P[1]), a0);
    return true;
  }
  /// d phi_c / dP_a over the box P by the quotient rule (false if the weight may vanish there).
  bool jacobian(const std::array<Double_interval, 2>& P, std::array<std::array<Double_interval, 2>, 3>& J) const {
    std::array<std::array<Double_interval, 3>, 4> v;  // value, d/dP0, d/dP1 of each form
    for (std::size_t k = 0; k < 4; ++k)
      for (std::size_t d = 0; d < 3; ++d) v[k][d] = interval_horner(forms_[k][d], P[0], P[1]);
    if (v[0][0].contains_zero()) return false;
    const Double_interval w2 = v[0][0] * v[0][0];
    for (std::size_t c = 0; c < 3; ++c)
      for (std::size_t a = 0; a < 2; ++a) J[c][a] = interval_quotient(v[c + 1][a + 1] * v[0][0] - v[c + 1][0] * v[0][a + 1], w2);
    return true;
  }

 private:
  // forms_[k][d]: form k (0 the weight), d = 0 itself, 1 its u-derivative, 2 its v-derivative; [j][i] of u^i v^j
  std::array<std::array<std::vector<std::vector<Double_interval>>, 3>, 4> forms_;
};

/// A reported point of a sheet: its locus point x, partner y (so z = (x1, x2, y1, y2)), its proved partner
/// enclosure (NaN bounds if none), and the reported first / second parameter points and space point.
struct Reported_sheet_point {
  std::array<double, 2> x, y, first, second;
  std::array<double, 3> space;
  std::array<std::array<double, 2>, 2> partner_enclosure;
};

/// The slope dz/dt of the zero curve gamma over T, whose points lie in the box K (step 3 of the header comment):
/// z = (x1, x2, y1, y2), the entry `axis` is 1. False if the preconditioned Jacobian is not proved regular.
inline bool zero_curve_slope(const Partner_equations& eq, int axis, const Double_interval& T,
                             const std::array<Double_interval, 3>& K, std::array<Double_interval, 4>& slope) {
  using D = Double_interval;
  const int idx[3] = {1 - axis, 2, 3};
  std::array<D, 4> z;
  z[std::size_t(axis)] = T;
  for (int c = 0; c < 3; ++c) z[std::size_t(idx[c])] = K[std::size_t(c)];
  std::array<D, 3> E;
  std::array<std::array<D, 4>, 3> J;
  eq.evaluate(z, E, &J);
  double A[3][3], C[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) A[r][c] = J[std::size_t(r)][std::size_t(idx[c])].mid();
  if (!invert_3x3(A, C)) return false;
  std::array<D, 3> CJt;
  std::array<std::array<D, 3>, 3> G;
  double G_norm = 0, CJt_norm = 0;
  for (int r = 0; r < 3; ++r) {
    D s{0, 0};
    for (int l = 0; l < 3; ++l) s = s + D{C[r][l], C[r][l]} * J[std::size_t(l)][std::size_t(axis)];
    CJt[std::size_t(r)] = s;
    CJt_norm = std::max(CJt_norm, std::max(std::fabs(s.lo), std::fabs(s.hi)));
    D row_sum{0, 0};
    for (int c = 0; c < 3; ++c) {
      D g{r == c ? 1.0 : 0.0, r == c ? 1.0 : 0.0};
      for (int l = 0; l < 3; ++l) g = g - D{C[r][l], C[r][l]} * J[std::size_t(l)][std::size_t(idx[c])];
      G[std::size_t(r)][std::size_t(c)] = g;
      row_sum = row_sum + D{0, std::max(std::fabs(g.lo), std::fabs(g.hi))};
    }
    G_norm = std::max(G_norm, row_sum.hi);
  }
  if (!(G_norm < 1) || !std::isfinite(CJt_norm)) return false;
  // |w'| <= R, then w' in -C J_t + G w' (every w' met is a fixed point), contracted a few times
  const D R = interval_quotient(D{CJt_norm, CJt_norm}, D{1, 1} - D{G_norm, G_norm});
  std::array<D, 3> w{D{-R.hi, R.hi}, D{-R.hi, R.hi}, D{-R.hi, R.hi}};
  for (int it = 0; it < 4; ++it) {
    std::array<D, 3> next;
    for (std::size_t r = 0; r < 3; ++r) {
      D x = D{0, 0} - CJt[r];
      for (std::size_t c = 0; c < 3; ++c) x = x + G[r][c] * w[c];
      next[r] = D{std::max(x.lo, w[r].lo), std::min(x.hi, w[r].hi)};
      if (!(next[r].lo <= next[r].hi)) return false;  // (cannot happen: w' lies in both)
    }
    w = next;
  }
  slope[std::size_t(axis)] = D{1, 1};
  for (int c = 0; c < 3; ++c) slope[std::size_t(idx[c])] = w[std::size_t(c)];
  return true;
}

/// A half-branch piece's proved chain (half_branch_chains.h) and the partner domain: step 2 of the header comment
/// for a segment of a piece that is not a graph.
struct Chain_identification {
  const Half_branch_chain* chain = nullptr;
  Parameter_box domain;
};

/// Step 2 on a half-branch H: the zero curve over T, enclosed in K, is H with its only partner in the domain when a
/// span S of H's chain with one partner in the domain holds T and K's other coordinate lies in S's range O (every
/// point of S.T x O with a partner in the domain lies on H and has only that one) and K puts both parameter
/// points inside the domain (so each point of the curve has a partner in it).
inline bool on_chain(const Chain_identification& c, int axis, const Double_interval& T,
                     const std::array<Double_interval, 3>& K, const Partner_equations& eq) {
  if (!c.chain || c.chain->axis != axis) return false;
  std::array<Double_interval, 4> z;
  z[std::size_t(axis)] = T;
  z[std::size_t(1 - axis)] = K[0];
  z[2] = K[1];
  z[3] = K[2];
  std::array<Double_interval, 2> P, Q;
  eq.points(z, P, Q);
  const Parameter_box& d = c.domain;
  auto inside = [&](const std::array<Double_interval, 2>& x) {
    return Double_interval::of(d.u0).hi <= x[0].lo && x[0].hi <= Double_interval::of(d.u1).lo &&
           Double_interval::of(d.v0).hi <= x[1].lo && x[1].hi <= Double_interval::of(d.v1).lo;
  };
  if (!inside(P) || !inside(Q)) return false;
  for (const Half_branch_span& S : c.chain->spans)
    if (S.partners == 1 && S.T.lo <= T.lo && T.hi <= S.T.hi && S.other.lo <= K[0].lo && K[0].hi <= S.other.hi)
      return true;  // (NaN bounds of S.other fail)
  return false;
}

/// x lies in the box (every coordinate).
inline bool box_within(const std::array<Double_interval, 3>& x, const std::array<Double_interval, 3>& box) {
  for (std::size_t c = 0; c < 3; ++c)
    if (!(box[c].lo <= x[c].lo && x[c].hi <= box[c].hi)) return false;
  return true;
}

/// Step 2 at an end t of a graph piece's segment: the sheet's exact point there, (g(t), y) with y in the reported
/// point's proved partner enclosure, is the zero of E(t, .) in W. g(t) lies in the other coordinate of `at_t` (the
/// enclosure of the anchored zero curve's point at t); Krawczyk's image of the box U = at_t,0 x enclosure holds every
/// zero of E(t, .) in U, so U may be cut down to it; once U lies in W, where the zero is unique, the sheet's point
/// is that zero.
inline bool sheet_point_is_zero_in(const Partner_equations& eq, int axis, const Reported_sheet_point& r, double t,
                                   const std::array<Double_interval, 3>& at_t,
                                   const std::array<Double_interval, 3>& W) {
  using D = Double_interval;
  std::array<D, 3> U = at_t;
  for (std::size_t c = 0; c < 2; ++c) {
    const auto& e = r.partner_enclosure[c];
    if (!(e[0] <= e[1])) return false;  // (not proved: NaN)
    U[c + 1] = D{e[0], e[1]};
  }
  for (int it = 0; it < 12; ++it) {
    if (box_within(U, W)) return true;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::array<D, 3> image{D{nan, nan}, D{nan, nan}, D{nan, nan}}, trial = U;
    parametric_partner_krawczyk(eq, axis, D{t, t}, trial, &image, false);
    bool narrower = false;
    for (std::size_t c = 0; c < 3; ++c) {
      if (!(std::isfinite(image[c].lo) && std::isfinite(image[c].hi))) return false;
      const D cut{std::max(U[c].lo, image[c].lo), std::min(U[c].hi, image[c].hi)};
      if (!(cut.lo <= cut.hi)) return false;  // (no zero in U: the enclosure did not hold the sheet's point)
      narrower = narrower || cut.hi - cut.lo < 0.9 * (U[c].hi - U[c].lo);
      U[c] = cut;
    }
    if (!narrower) return false;
  }
  return box_within(U, W);
}

/// Proved bounds {first domain, second domain, space} on the distance between the chord of two consecutive
/// reported points p, q of a sheet (on the graph piece `cell` with graph coordinate `axis`, or on the half-branch
/// of `chain`, whose coordinate `axis` is) and the branch over that span, from `pieces` sub-spans (header
/// comment); infinity in every entry when a step of the proof fails.
inline std::array<double, 3> segment_distance_bound_in(const Partner_equations& eq,
                                                       const Patch_jacobian_enclosure& phi, int axis,
                                                       const Parameter_box& cell, const Polynomial_2<Integer>* curve,
                                                       const Reported_sheet_point& p, const Reported_sheet_point& q,
                                                       int pieces, const Chain_identification* chain = nullptr,
                                                       bool identify = true) {
  using D = Double_interval;
  const double inf = std::numeric_limits<double>::infinity();
  const std::array<double, 3> none{inf, inf, inf};
  const int idx[3] = {1 - axis, 2, 3};
  const bool p_first = p.x[std::size_t(axis)] <= q.x[std::size_t(axis)];
  const Reported_sheet_point &ra = p_first ? p : q, &rb = p_first ? q : p;
  const double a = ra.x[std::size_t(axis)], b = rb.x[std::size_t(axis)];
  if (!(a < b) || pieces < 1) return none;
  auto w_of = [&](const Reported_sheet_point& r) {
    const std::array<double, 4> z{r.x[0], r.x[1], r.y[0], r.y[1]};
    return std::array<double, 3>{z[std::size_t(idx[0])], z[std::size_t(idx[1])], z[std::size_t(idx[2])]};
  };
  const std::array<double, 3> wa = w_of(ra), wb = w_of(rb);
  std::array<D, 4> slope_hull;
  std::array<D, 3> space_slope_hull;
  std::array<D, 3> W_prev, end_a, end_b;
  bool identified = false;
  for (int k = 0; k < pieces; ++k) {
    const double t0 = k == 0 ? a : a + (b - a) * k / pieces, t1 = k + 1 == pieces ? b : a + (b - a) * (k + 1) / pieces;
    if (!(t0 < t1)) return none;
    const D T{t0, t1};
    // 1. the zero curve over T_k, unique in W, its image K
    std::array<double, 3> guess;
    const double s = (0.5 * (t0 + t1) - a) / (b - a);
    for (std::size_t c = 0; c < 3; ++c) guess[c] = wa[c] + s * (wb[c] - wa[c]);
    std::array<D, 3> W, K;
    if (!predict_partner_box(eq, axis, T, guess, W) || !prove_zero_curve(eq, axis, T, W, K)) return none;
    if (eq.self_intersection() && K[1].contains_zero() && K[2].contains_zero()) return none;  // (the trivial one)
    // the curves of consecutive sub-spans are one: the zero at t0 of the previous one's box lies in W, or this
    // one's in the previous box (unique in either, so the two curves share their point at t0)
    std::array<D, 3> at = W;
    if (!parametric_partner_krawczyk(eq, axis, D{t0, t0}, at, nullptr, false)) return none;
    if (k == 0) end_a = at;
    if (k > 0 && !box_within(at, W_prev)) {
      std::array<D, 3> before = W_prev;
      if (!parametric_partner_krawczyk(eq, axis, D{t0, t0}, before, nullptr, false) || !box_within(before, W)) return none;
    }
    // 2. the arc with a partner (anchored once), and this sheet's partner (its proved enclosure at an end)
    if (!identify) {
      // (an estimate for the refinement: the zero curve through the reported points, not shown to be the branch)
    } else if (chain) {
      if (!on_chain(*chain, axis, T, K, eq)) return none;
    } else if (k == pieces / 2 && !zero_curve_anchored(eq, axis, T, W, cell, curve)) {
      return none;
    }
    if (k == 0) identified = !identify || chain || sheet_point_is_zero_in(eq, axis, ra, a, at, W);
    if (k + 1 == pieces) {
      end_b = W;
      if (!parametric_partner_krawczyk(eq, axis, D{t1, t1}, end_b, nullptr, false)) return none;
      identified = identified || sheet_point_is_zero_in(eq, axis, rb, b, end_b, W);
    }
    // 3. slopes over T_k
    std::array<D, 4> slope;
    if (!zero_curve_slope(eq, axis, T, K, slope)) return none;
    std::array<D, 4> zK;
    zK[std::size_t(axis)] = T;
    for (int c = 0; c < 3; ++c) zK[std::size_t(idx[c])] = K[std::size_t(c)];
    std::array<D, 2> PK, QK, dP, dQ;
    eq.points(zK, PK, QK);
    eq.points(slope, dP, dQ);
    std::array<std::array<D, 2>, 3> dphi;
    if (!phi.jacobian(PK, dphi)) return none;
    auto hull = [&](D& h, const D& x) { h = k == 0 ? x : D{std::min(h.lo, x.lo), std::max(h.hi, x.hi)}; };
    for (std::size_t c = 0; c < 4; ++c) hull(slope_hull[c], slope[c]);
    for (std::size_t c = 0; c < 3; ++c) hull(space_slope_hull[c], dphi[c][0] * dP[0] + dphi[c][1] * dP[1]);
    W_prev = W;
  }
  if (!identified) return none;
  // 4. per coordinate: (b - a) w(S) / 4 plus the larger difference of a reported end from the exact one
  std::array<D, 2> P_end[2], Q_end[2];
  for (int s = 0; s < 2; ++s) {
    std::array<D, 4> z;
    z[std::size_t(axis)] = s == 0 ? D{a, a} : D{b, b};
    for (int c = 0; c < 3; ++c) z[std::size_t(idx[c])] = (s == 0 ? end_a : end_b)[std::size_t(c)];
    eq.points(z, P_end[s], Q_end[s]);
  }
  auto off = [](double reported, const D& exact) {
    return std::max(std::fabs(reported - exact.lo), std::fabs(reported - exact.hi));
  };
  auto chord = [&](const D& s) { return (D{b, b} - D{a, a}) * (D{s.hi, s.hi} - D{s.lo, s.lo}) * D{0.25, 0.25}; };
  auto norm = [](const std::vector<D>& parts) {
    D sum{0, 0};
    for (const D& x : parts) sum = sum + x * x;
    return std::sqrt(sum.hi) * (1 + 4 * std::numeric_limits<double>::epsilon());
  };
  std::array<D, 2> dP, dQ;
  eq.points(slope_hull, dP, dQ);
  std::array<double, 3> out{};
  for (int which = 0; which < 2; ++which) {
    std::vector<D> parts;
    for (std::size_t c = 0; c < 2; ++c) {
      const double e0 = off((which == 0 ? ra.first : ra.second)[c], (which == 0 ? P_end[0] : Q_end[0])[c]);
      const double e1 = off((which == 0 ? rb.first : rb.second)[c], (which == 0 ? P_end[1] : Q_end[1])[c]);
      parts.push_back(chord(which == 0 ? dP[c] : dQ[c]) + D{std::max(e0, e1), std::max(e0, e1)});
    }
    out[std::size_t(which)] = norm(parts);
  }
  std::array<D, 3> at0, at1;
  if (!phi.value(P_end[0], at0) || !phi.value(P_end[1], at1)) return none;
  std::vector<D> parts;
  for (std::size_t c = 0; c < 3; ++c) {
    const double e = std::max(off(ra.space[c], at0[c]), off(rb.space[c], at1[c]));
    parts.push_back(chord(space_slope_hull[c]) + D{e, e});
  }
  out[2] = norm(parts);
  for (double& x : out)
    if (!std::isfinite(x)) return none;
  return out;
}

/// The bound of segment_distance_bound_in from 1, 4, 16 and then 64 sub-spans: the first whose entries are all
/// within `target`, else the smallest proved (infinity if none is; not tried beyond 4 if neither 1 nor 4 proves).
inline std::array<double, 3> segment_distance_bound(const Partner_equations& eq, const Patch_jacobian_enclosure& phi,
                                                    int axis, const Parameter_box& cell,
                                                    const Polynomial_2<Integer>* curve, const Reported_sheet_point& p,
                                                    const Reported_sheet_point& q, double target,
                                                    const Chain_identification* chain = nullptr) {
  const double inf = std::numeric_limits<double>::infinity();
  std::array<double, 3> best{inf, inf, inf};
  for (int pieces : {1, 4, 16, 64}) {
    const std::array<double, 3> b = segment_distance_bound_in(eq, phi, axis, cell, curve, p, q, pieces, chain);
    if (std::max({b[0], b[1], b[2]}) < std::max({best[0], best[1], best[2]})) best = b;
    if (std::max({best[0], best[1], best[2]}) <= target) break;
    if (pieces == 4 && std::isinf(best[0])) break;  // (nothing proved with 1 and 4: a fold, a near-singular Jacobian)
  }
  return best;
}

/// For the refinement (arc_refinement.h): the bound of segment_distance_bound_in for the zero curve through the
/// floating-point points p, q (their partner enclosures are not used), from 1 and then 4 sub-spans; infinity where
/// it is not proved. Over a span whose branch the proofs later identify, this is the bound they find.
inline double segment_distance_estimate(const Partner_equations& eq, const Patch_jacobian_enclosure& phi, int axis,
                                        const Reported_sheet_point& p, const Reported_sheet_point& q) {
  double best = std::numeric_limits<double>::infinity();
  for (int pieces : {1, 4}) {
    const std::array<double, 3> b = segment_distance_bound_in(eq, phi, axis, Parameter_box{}, nullptr, p, q, pieces,
                                                              nullptr, false);
    best = std::min(best, std::max({b[0], b[1], b[2]}));
  }
  return best;
}

}  // namespace internal
}  // namespace bezoutian

#endif
