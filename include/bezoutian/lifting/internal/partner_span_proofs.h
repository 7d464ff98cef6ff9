// The span proofs of certified_lifting.h: the status of the arc points of the projected locus D = 0 over one
// span T of a graph piece of a cell (see certified_lifting.h for the method). Genuine, by a parametric Krawczyk
// test that follows one partner over the whole span (the zero curve of the partner equations, unique in a box,
// anchored at the arc point and with its partner in the partner domain); phantom, by exclusion of every partner
// in the domain (no_genuine_partner); also the tests near the trivial partner (blown-up equations) and at a
// certified split point where the partner crosses the domain's boundary, and the bookkeeping of the exclusion tests
// (Exclusion_budget).
#ifndef BEZOUTIAN_LIFTING_INTERNAL_PARTNER_SPAN_PROOFS_H
#define BEZOUTIAN_LIFTING_INTERNAL_PARTNER_SPAN_PROOFS_H

#include <bezoutian/topology/Curve_topology.h>
#include <bezoutian/lifting/internal/blown_up_partner_equations.h>
#include <bezoutian/lifting/internal/curve_anchor.h>
#include <bezoutian/lifting/double_partner_witness.h>
#include <bezoutian/lifting/partner_domain_crossings.h>
#include <bezoutian/arithmetic/number_types.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <functional>
#include <limits>
#include <type_traits>
#include <vector>

namespace bezoutian {
namespace internal {

/// outside: the partner found is proved outside the partner domain, the exclusion of every other partner (which
/// makes the span phantom) not yet tried (internal to certify_edge_partners: spans are excluded in runs).
enum class Partner_status { genuine, phantom, undecided, outside };

/// Bounds the number of exclusion tests (no_genuine_partner, up to 1024 partner pieces each) of one locus: the
/// phantom proofs are the costly part; when the budget is spent the remaining spans stay undecided. Two separate
/// counts: the exclusions next to a followed partner proved outside the domain (`left`: one per span at most,
/// cheap and mostly successful), and the fallback that covers a span's whole strip when no partner could be
/// followed (`fallback_left`: up to 16 tests per span, often failing). With one shared count the fallback on the
/// first edges starved the cheap proofs of later ones. A third count bounds the genuine proofs by the blown-up
/// equations near pinch points (about 0.2 ms each, most of them failing on random rational bicubics).
struct Exclusion_budget {
  std::size_t left = std::numeric_limits<std::size_t>::max();
  std::size_t fallback_left = std::numeric_limits<std::size_t>::max();
  /// Called at every test taken (of any count) and at every poll(): the caller's wall-clock check (a clock read,
  /// tens of nanoseconds against the microseconds of a test), which ends the computation by throwing when its time
  /// is up. So the time limit holds within an arc, not only between arcs.
  std::function<void()> interrupt;
  /// For the loops of Krawczyk tests and exact proofs that take no exclusion test.
  void poll() {
    if (interrupt) interrupt();
  }
  bool take() { return take(left); }
  bool take_fallback() { return take(fallback_left); }
  /// Krawczyk tests of the blown-up equations near the trivial partner (blown_up_partner_equations.h); given up
  /// when the first 2000 all fail.
  std::size_t blown_up_left = 8000, blown_up_tried = 0, blown_up_proved = 0;
  /// exclusion tests on the slabs of single points (the last resort of certify_edge_partners), per locus
  std::size_t point_left = 4000;
  /// exclusion tests on the parts of a span's box halved for the complete fibre (partner_sheets.h), per locus
  std::size_t box_split_left = 2000;
  bool take_box_split() { return take(box_split_left); }
  /// chart boxes of the blow-up along a shared boundary curve (seam_blowup_exclusion.h), per locus: a few
  /// microseconds each; next to a singular point of D = 0 on the seam one proof may take tens of thousands
  std::size_t seam_boxes_left = 120000;
  bool take_blown_up() {
    if (blown_up_tried >= 2000 && blown_up_proved == 0) return false;
    if (!take(blown_up_left)) return false;
    ++blown_up_tried;
    return true;
  }

 private:
  bool take(std::size_t& n) {
    if (n == 0) return false;
    --n;
    poll();
    return true;
  }
};

/// Inverse of a 3 x 3 matrix of doubles by its adjugate (floating point: used for preconditioners and Newton
/// steps, never for a decision); false if the determinant is zero or not finite.
inline bool invert_3x3(const double (&A)[3][3], double (&C)[3][3]) {
  const double det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                     A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
  if (!std::isfinite(det) || det == 0) return false;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
      C[r][c] = (A[r1][c1] * A[r2][c2] - A[r1][c2] * A[r2][c1]) / det;  // adjugate / det
    }
  return true;
}

/// Newton's method on the three partner equations E(z) = 0 with the graph coordinate z_axis = t fixed, in the
/// unknowns w = (the other coordinate, y1, y2), from w; true if the last step is below 1e-13 (relative).
inline bool solve_partner_equations(const Partner_equations& eq, int axis, double t, std::array<double, 3>& w) {
  using C = std::complex<double>;
  const int q[3] = {1 - axis, 2, 3};
  for (int it = 0; it < 20; ++it) {
    std::array<C, 4> z;
    z[std::size_t(axis)] = t;
    for (int c = 0; c < 3; ++c) z[std::size_t(q[c])] = w[std::size_t(c)];
    std::array<C, 3> E;
    std::array<std::array<C, 4>, 3> J;
    eq.evaluate(z, E, J);
    double A[3][3], Ai[3][3];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) A[r][c] = J[std::size_t(r)][std::size_t(q[c])].real();
    if (!invert_3x3(A, Ai)) return false;
    double step = 0;
    for (int r = 0; r < 3; ++r) {
      const double d = Ai[r][0] * E[0].real() + Ai[r][1] * E[1].real() + Ai[r][2] * E[2].real();
      w[std::size_t(r)] -= d;
      step += std::fabs(d);
    }
    if (!std::isfinite(step) || step > 1) return false;
    if (step <= 1e-13 * (1 + std::fabs(w[0]) + std::fabs(w[1]) + std::fabs(w[2]))) return true;
  }
  return false;
}

/// Parametric Krawczyk test (see the header comment). axis: index of the graph coordinate in z = (x1, x2, y1, y2)
/// (0 or 1); T its span; W = (other coordinate, y1, y2). On success W is replaced by K (a tighter enclosure).
/// (Eq: Partner_equations, or Blown_up_partner_equations with z = (x1, x2, r, m).)
template <class Eq>
inline bool parametric_partner_krawczyk(const Eq& eq, int axis, const Double_interval& T,
                                        std::array<Double_interval, 3>& W, std::array<Double_interval, 3>* image = nullptr,
                                        bool strict = false) {
  using D = Double_interval;
  const int q[3] = {1 - axis, 2, 3};
  auto full = [&](const std::array<D, 3>& w, const D& t) {
    std::array<D, 4> z;
    z[axis] = t;
    for (int c = 0; c < 3; ++c) z[q[c]] = w[c];
    return z;
  };
  std::array<D, 3> m;
  for (int c = 0; c < 3; ++c) m[c] = D{W[c].mid(), W[c].mid()};
  // C: the inverse of the Jacobian at the centre (floating point; any C gives a valid test)
  std::array<std::array<D, 4>, 3> Jc, J;
  std::array<D, 3> E;
  eq.evaluate(full(m, D{T.mid(), T.mid()}), E, &Jc);
  double A[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) A[r][c] = Jc[r][q[c]].mid();
  double C[3][3];
  if (!invert_3x3(A, C)) return false;
  // mean-value form in the parameter too (much tighter than E(T, m) in naive interval arithmetic):
  // E(t, m) in E(t_m, m) + dE/dx_axis(T, W) (T - t_m) for t in T
  std::array<D, 3> EW;
  eq.evaluate(full(W, T), EW, &J);  // (the values over W are not needed, only the Jacobian)
  const D tm{T.mid(), T.mid()};
  eq.evaluate(full(m, tm), E);
  const std::array<D, 2> w = eq.weights(full(W, T));
  if (w[0].contains_zero() || w[1].contains_zero()) return false;  // E = 0 would not put (x, y) on D = 0
  std::array<D, 3> K;
  for (int r = 0; r < 3; ++r) {
    D k = m[r], slope{0, 0};
    for (int c = 0; c < 3; ++c) {
      const D cr{C[r][c], C[r][c]};
      k = k - cr * E[c];
      slope = slope + cr * J[c][axis];
      D g{r == c ? 1.0 : 0.0, r == c ? 1.0 : 0.0};
      for (int l = 0; l < 3; ++l) g = g - D{C[r][l], C[r][l]} * J[l][q[c]];
      k = k + g * (W[c] - m[c]);
    }
    k = k - slope * (T - tm);
    if (!(std::isfinite(k.lo) && std::isfinite(k.hi))) return false;
    K[r] = k;
  }
  if (image) *image = K;
  for (int r = 0; r < 3; ++r)
    if (strict ? !(W[r].lo < K[r].lo && K[r].hi < W[r].hi) : !(W[r].lo <= K[r].lo && K[r].hi <= W[r].hi)) return false;
  W = K;
  return true;
}


/// A box W = V x Y predicted to hold the zeros (v, y) of E(t, .) for t in T (floating point: Newton at the centre
/// of T from `guess`, then the tangent dw/dt = -(dE/dw)^-1 dE/dt times the half width of T, doubled, plus
/// `slack` (1 + |w|): Newton's accuracy on the equations as written; the centred equations, accurate relative to
/// the distance to their centre, take a few ulps). False if Newton does not converge.
template <class Eq>
inline bool predict_partner_box(const Eq& eq, int axis, const Double_interval& T,
                                std::array<double, 3> w, std::array<Double_interval, 3>& W, double slack = 1e-13) {
  using D = Double_interval;
  const int q[3] = {1 - axis, 2, 3};
  const double t = T.mid();
  double A[3][3], b[3], step = 0;
  for (int it = 0; it < 12; ++it) {
    std::array<D, 4> z;
    z[axis] = D{t, t};
    for (int c = 0; c < 3; ++c) z[q[c]] = D{w[c], w[c]};
    std::array<D, 3> E;
    std::array<std::array<D, 4>, 3> J;
    eq.evaluate(z, E, &J);
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) A[r][c] = J[r][q[c]].mid();
      b[r] = it < 11 ? E[r].mid() : J[r][axis].mid();  // the last round solves for the tangent instead
    }
    double Ai[3][3], x[3];
    if (!invert_3x3(A, Ai)) return false;
    for (int r = 0; r < 3; ++r) x[r] = Ai[r][0] * b[0] + Ai[r][1] * b[1] + Ai[r][2] * b[2];
    if (it < 11) {
      step = std::fabs(x[0]) + std::fabs(x[1]) + std::fabs(x[2]);
      for (int c = 0; c < 3; ++c) w[c] -= x[c];
      if (!(step < 1)) return false;
      continue;
    }
    // Newton's last step bounds its error; near a singular point of D = 0 (the Jacobian's condition about the
    // inverse distance to it) it stalls at rounding times that condition, which the box's radius may still dwarf
    const double h = 0.5 * (T.hi - T.lo);
    double r[3], r_min = HUGE_VAL;
    for (int c = 0; c < 3; ++c) {
      r[c] = 2 * std::fabs(x[c]) * h + 4 * h * h + slack * (1 + std::fabs(w[c]));
      r_min = std::min(r_min, r[c]);
    }
    if (!(step <= 1e-10 * (1 + std::fabs(w[0]) + std::fabs(w[1]) + std::fabs(w[2])) || step <= 0.25 * r_min)) return false;
    for (int c = 0; c < 3; ++c) W[c] = D{w[c] - r[c] - step, w[c] + r[c] + step};
  }
  return true;
}

/// Krawczyk's test with strict inclusion over the span T, with epsilon-inflation from the box W (updated to the
/// box that passed, in which the zero curve gamma(t), t in T, is unique); K receives the operator's image, which
/// encloses gamma(T). The box found by inflating the image alone can be much tighter than the one found from the
/// hull (a narrower hole for an exclusion around it): image_inflation = false leaves that step to the caller.
/// Each inflation adds a tenth of the width plus `inflation_floor` (coordinates relative to a centre take 0).
template <class Eq>
inline bool prove_zero_curve(const Eq& eq, int axis, const Double_interval& T,
                             std::array<Double_interval, 3>& W, std::array<Double_interval, 3>& K,
                             bool image_inflation = true, double inflation_floor = 1e-15) {
  using D = Double_interval;
  const std::array<D, 3> start = W;
  // epsilon-inflation, first on the hull of W and the operator's image, then (from the prediction again, unless
  // image_inflation is false) on the image alone: where one unknown depends on another quadratically (at a fold of
  // the partner, u ~ 1 - s^2), the image of that unknown grows with the width of the other, and only the image lets
  // the other shrink to its range
  bool narrows = false;  // the first image narrower than W in some coordinate (as at a fold); else only the hull
  for (int mode = 0; mode < (image_inflation && narrows ? 2 : 1); ++mode) {
    W = start;
    for (int attempt = 0; attempt < 4; ++attempt) {
      std::array<D, 3> image, trial = W;
      if (parametric_partner_krawczyk(eq, axis, T, trial, &image, true)) {
        K = trial;
        return true;
      }
      if (!(std::isfinite(image[0].lo) && std::isfinite(image[0].hi))) return false;
      if (mode == 0 && attempt == 0)
        for (int c = 0; c < 3; ++c) narrows = narrows || image[c].hi - image[c].lo < 0.75 * (W[c].hi - W[c].lo);
      for (int c = 0; c < 3; ++c) {
        const double lo = mode == 0 ? std::min(W[c].lo, image[c].lo) : image[c].lo;
        const double hi = mode == 0 ? std::max(W[c].hi, image[c].hi) : image[c].hi;
        const double r = 0.1 * (hi - lo) + inflation_floor;
        W[c] = D{lo - r, hi + r};
      }
    }
  }
  return false;
}

/// A box around W (a box where the zero curve over T is proved unique, prove_zero_curve) in which it is still proved
/// unique: W widened 2, 4, 8, ... (up to 4096) times about its centre while Krawczyk's strict test passes, the last
/// that passed (W if none). As the hole of an exclusion of every other partner it leaves a margin: at the edge of a
/// tight W the equations may come within rounding of zero over the box of arc points, and no subdivision of the
/// partner range then excludes the edge.
template <class Eq>
inline std::array<Double_interval, 3> widened_unique_box(const Eq& eq, int axis, const Double_interval& T,
                                                         const std::array<Double_interval, 3>& W) {
  std::array<Double_interval, 3> best = W;
  for (double f = 2; f <= 4096; f *= 2) {
    std::array<Double_interval, 3> wide, test;
    for (int c = 0; c < 3; ++c) {
      const double m = W[c].mid(), r = f * 0.5 * (W[c].hi - W[c].lo);
      wide[c] = Double_interval{m - r, m + r};
    }
    test = wide;
    if (!parametric_partner_krawczyk(eq, axis, T, test, nullptr, true)) break;
    best = wide;
  }
  return best;
}

/// The anchor of a zero curve proved unique in W over the span T (prove_zero_curve): Krawczyk's test at the single
/// value t* = mid T encloses gamma(t*) strictly inside the cell's range of the other coordinate, where the line
/// through t* meets D = 0 only at the arc point; so gamma(t*) is the arc point (classify_partner_span, step 2).
/// Where the enclosure reaches over one side of the cell and `curve` (the projection operator D) is given, the
/// curve equation puts gamma(t*) inside (curve_anchor.h; not where gamma may be the trivial partner of a
/// self-intersection, which is not on D = 0).
template <class Eq>
inline bool zero_curve_anchored(const Eq& eq, int axis, const Double_interval& T, const std::array<Double_interval, 3>& W,
                                const Parameter_box& cell, const Polynomial_2<Integer>* curve = nullptr) {
  std::array<Double_interval, 3> at = W;
  const Double_interval t{T.mid(), T.mid()};
  if (!parametric_partner_krawczyk(eq, axis, t, at, nullptr, false)) return false;
  const Rational &lo = axis == 0 ? cell.v0 : cell.u0, &hi = axis == 0 ? cell.v1 : cell.u1;
  auto inside = [&] { return Rational(at[0].lo) > lo && Rational(at[0].hi) < hi; };
  if (inside()) return true;
  if (!curve) return false;
  // the enclosure contracted first (Krawczyk's image holds every zero in the box: each success may replace it)
  for (int it = 0; it < 8; ++it) {
    std::array<Double_interval, 3> next = at;
    const double width = at[0].hi - at[0].lo;
    if (!parametric_partner_krawczyk(eq, axis, t, next, nullptr, false)) break;
    at = next;
    if (inside()) return true;
    if (!(at[0].hi - at[0].lo < 0.5 * width)) break;
  }
  const Rational g_lo(at[0].lo), g_hi(at[0].hi);
  const bool above_lo = g_lo > lo, below_hi = g_hi < hi;
  if constexpr (!std::is_same<Eq, Partner_equations>::value) return false;  // (blown-up: r = 0 is not on D = 0)
  else if (above_lo == below_hi || (eq.self_intersection() && at[1].contains_zero() && at[2].contains_zero()))
    return false;
  const Rational t_star(t.lo);
  return below_hi ? g_hi > lo && curve_has_no_zero_beyond(*curve, axis, t_star, lo, g_lo)
                  : g_lo < hi && curve_has_no_zero_beyond(*curve, axis, t_star, hi, g_hi);
}

/// The status given by a partner enclosure K_y of the arc points over T whose other coordinate lies in K_v
/// (proved): genuine if P, Q are in the partner domain over all of K; phantom if they are outside and no point of
/// T x K_v has any partner in the domain; otherwise undecided.
inline Partner_status status_from_partner(const Partner_equations& eq, const Parameter_box& domain, bool unbounded,
                                          int axis, const Double_interval& T, const std::array<Double_interval, 3>& K,
                                          const std::vector<std::array<Double_interval, 2>>* start,
                                          bool defer_exclusion = false, Exclusion_budget* budget = nullptr) {
  using D = Double_interval;
  if (eq.self_intersection() && K[1].contains_zero() && K[2].contains_zero())
    return Partner_status::undecided;  // the trivial partner y = 0 is not a partner
  const D& X1 = axis == 0 ? T : K[0];
  const D& X2 = axis == 0 ? K[0] : T;
  std::array<D, 2> P, Q;
  eq.points(std::array<D, 4>{X1, X2, K[1], K[2]}, P, Q);
  if (unbounded ||
      (interval_inside(P[0], domain.u0, domain.u1) && interval_inside(P[1], domain.v0, domain.v1) &&
       interval_inside(Q[0], domain.u0, domain.u1) && interval_inside(Q[1], domain.v0, domain.v1)))
    return Partner_status::genuine;
  const bool outside = interval_disjoint(P[0], domain.u0, domain.u1) || interval_disjoint(P[1], domain.v0, domain.v1) ||
                       interval_disjoint(Q[0], domain.u0, domain.u1) || interval_disjoint(Q[1], domain.v0, domain.v1);
  if (!outside) return Partner_status::undecided;  // the partner crosses the domain boundary over T
  if (defer_exclusion) return Partner_status::outside;
  const Parameter_box box{Rational(X1.lo), Rational(X1.hi), Rational(X2.lo), Rational(X2.hi)};
  if (budget && !budget->take()) return Partner_status::undecided;
  return no_genuine_partner(eq, box, domain, 1024, start) ? Partner_status::phantom : Partner_status::undecided;
}

/// Status of every arc point over the span T of a graph piece (see the header comment), starting from a box
/// W0 = V x Y predicted to hold the arc and its partner there; `cell` is the piece's cell and `axis` its graph
/// coordinate. Proof of the genuine case, in three steps:
///  1. Krawczyk's test with strict inclusion K ⊂ int W for the whole span: for every t in T, E(t, .) has exactly
///     one zero gamma(t) in W, and dE/dw is regular on W, so gamma is continuous (implicit functions);
///  2. an anchor: Krawczyk's test at the single value t* = mid T encloses gamma(t*) strictly inside the cell,
///     where the line through t* meets D = 0 only at the arc point: gamma(t*) is the arc point with a partner;
///  3. continuity: the arc points over T (a connected set, inside the cell, touching the cell's edges only at
///     its end points) and gamma agree at t*, and wherever they agree gamma is inside the cell nearby (except
///     at the arc's end), so they agree on all of T: every arc point over T has the partner gamma_y(t) in K_y.
/// V may therefore leave the cell (arcs entering the cell through an edge parallel to the graph axis).
/// Genuine if P and Q lie in the partner domain over all of K. Phantom if the partner found is outside and no
/// point of T x K_v (which holds the arc points over T) has any partner in the domain (no_genuine_partner,
/// started from `start()`: partner pieces covering every candidate partner of the cell's points, or null).
/// Undecided if no partner can be followed (then the caller may try exclude_strips on runs of such spans).
inline Partner_status classify_partner_span(const Partner_equations& eq, const Parameter_box& domain, bool unbounded,
                                            int axis, const Double_interval& T, const std::array<Double_interval, 3>& W0,
                                            const Parameter_box& cell,
                                            const std::function<const std::vector<std::array<Double_interval, 2>>*()>& start,
                                            std::array<Double_interval, 2>* partner = nullptr, bool defer_exclusion = false,
                                            std::array<Double_interval, 3>* enclosure = nullptr,
                                            Exclusion_budget* budget = nullptr) {
  using D = Double_interval;
  const Partner_status no_partner = Partner_status::undecided;  // (the caller may try exclude_strips)
  std::array<D, 3> W = W0, K;
  const bool proved = prove_zero_curve(eq, axis, T, W, K);
  if (!proved) return no_partner;
  if (!zero_curve_anchored(eq, axis, T, W, cell)) return no_partner;
  if (eq.self_intersection() && K[1].contains_zero() && K[2].contains_zero())
    return no_partner;  // the trivial partner y = 0 is not a partner
  if (partner) *partner = {K[1], K[2]};
  if (enclosure) *enclosure = K;
  const Partner_status st = status_from_partner(eq, domain, unbounded, axis, T, K, nullptr, true);
  if (st != Partner_status::outside || defer_exclusion) return st;
  return status_from_partner(eq, domain, unbounded, axis, T, K, start(), false, budget);
}

/// Genuine status of the arc points over the span T of a graph piece of a self-intersection where the followed
/// partner is close to the trivial one (near a pinch point), by the blown-up equations F = E / r
/// (blown_up_partner_equations.h; `bu` in the chart of the partner's larger coordinate). The proof is that of
/// classify_partner_span with F for E: Krawczyk over T (strict) gives a unique continuous zero curve
/// (v, r, m)(t) in W; the anchor at the middle of T puts it strictly inside the cell; a box for r that excludes 0
/// makes y = r d(m) a nontrivial partner (E = r F = 0, weights nonzero), so the zero is the arc point over t with a
/// partner; genuine if P and Q lie in the domain over the whole enclosure. `y0`, `y1`: the floating-point partners
/// at the span's ends (either order), `V` a box for the other coordinate over T. Returns genuine (with the partner
/// enclosure and K = (other coordinate, partner) in `partner`, `enclosure`, and the box (other coordinate, r, m)
/// in `blown_up_box`) or undecided; never phantom.
inline Partner_status classify_span_near_trivial_partner(const Blown_up_partner_equations& bu,
                                                         const Parameter_box& domain, int axis,
                                                         const Double_interval& T, const Double_interval& V,
                                                         const std::array<double, 2>& y0, const std::array<double, 2>& y1,
                                                         const Parameter_box& cell, std::array<Double_interval, 2>* partner,
                                                         std::array<Double_interval, 3>* enclosure,
                                                         std::array<Double_interval, 3>* blown_up_box = nullptr) {
  using D = Double_interval;
  const int big = bu.chart() == 0 ? 0 : 1;  // r is the partner's coordinate big, m = the other / r
  if (y0[big] == 0 || y1[big] == 0 || (y0[big] > 0) != (y1[big] > 0)) return Partner_status::undecided;
  const double r0 = y0[big], r1 = y1[big], m0 = y0[1 - big] / r0, m1 = y1[1 - big] / r1;
  const double rr = 0.5 * std::fabs(r1 - r0) + 0.25 * std::fabs(r0 + r1) * 0.1, mr = 0.5 * std::fabs(m1 - m0) + 0.05;
  std::array<D, 3> W{V, D{std::min(r0, r1) - rr, std::max(r0, r1) + rr}, D{std::min(m0, m1) - mr, std::max(m0, m1) + mr}}, P, K;
  if (predict_partner_box(bu, axis, T, {W[0].mid(), 0.5 * (r0 + r1), 0.5 * (m0 + m1)}, P)) W = P;
  if (!prove_zero_curve(bu, axis, T, W, K)) return Partner_status::undecided;
  if (!zero_curve_anchored(bu, axis, T, W, cell)) return Partner_status::undecided;
  if (K[1].contains_zero()) return Partner_status::undecided;  // r = 0: possibly the trivial partner
  const D& X1 = axis == 0 ? T : K[0];
  const D& X2 = axis == 0 ? K[0] : T;
  const std::array<D, 4> z{X1, X2, K[1], K[2]};
  std::array<D, 2> Pp, Qp;
  bu.points(z, Pp, Qp);
  if (!(interval_inside(Pp[0], domain.u0, domain.u1) && interval_inside(Pp[1], domain.v0, domain.v1) &&
        interval_inside(Qp[0], domain.u0, domain.u1) && interval_inside(Qp[1], domain.v0, domain.v1)))
    return Partner_status::undecided;
  const std::array<D, 2> y = bu.partner(z);
  if (partner) *partner = y;
  if (enclosure) *enclosure = {K[0], y[0], y[1]};
  if (blown_up_box) *blown_up_box = K;  // (other coordinate, r, m): the zero curve is unique in it over T
  return Partner_status::genuine;
}

/// An enclosure X of the derivative gamma'(t) = -(dE/dw)^-1 dE/dt of a zero curve over T x K (w = the other
/// coordinate and the partner, the unknowns of the span proofs): Cramer's rule in interval arithmetic on the system
/// preconditioned by the inverse C of the Jacobian's midpoint (M = C dE/dw is close to the identity, so det M keeps
/// its sign), gamma'_c = -det(M_c) / det(M), M_c being M with column c replaced by C dE/dt. False if det M may vanish.
inline bool implicit_slopes(const Partner_equations& eq, int axis, const Double_interval& T,
                            const std::array<Double_interval, 3>& K, std::array<Double_interval, 3>& X) {
  using D = Double_interval;
  const int q[3] = {1 - axis, 2, 3};
  std::array<D, 4> z;
  z[axis] = T;
  for (int c = 0; c < 3; ++c) z[q[c]] = K[c];
  std::array<D, 3> E;
  std::array<std::array<D, 4>, 3> J;
  eq.evaluate(z, E, &J);
  double A[3][3], C[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) A[r][c] = J[r][q[c]].mid();
  if (!invert_3x3(A, C)) return false;
  std::array<std::array<D, 3>, 3> M;  // C dE/dw, close to the identity
  std::array<D, 3> rhs;               // C dE/dt
  for (int r = 0; r < 3; ++r) {
    rhs[r] = D{0, 0};
    for (int l = 0; l < 3; ++l) rhs[r] = rhs[r] + D{C[r][l], C[r][l]} * J[l][axis];
    for (int c = 0; c < 3; ++c) {
      M[r][c] = D{0, 0};
      for (int l = 0; l < 3; ++l) M[r][c] = M[r][c] + D{C[r][l], C[r][l]} * J[l][q[c]];
    }
  }
  auto det3 = [](const std::array<std::array<D, 3>, 3>& a) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  };
  const D det = det3(M);
  if (det.contains_zero() || !std::isfinite(det.lo) || !std::isfinite(det.hi)) return false;
  const D inverse_det = D::widen(1 / det.hi, 1 / det.lo);  // 1/x decreases on an interval without 0
  for (int c = 0; c < 3; ++c) {
    std::array<std::array<D, 3>, 3> Mc = M;
    for (int r = 0; r < 3; ++r) Mc[r][c] = rhs[r];
    X[c] = D{0, 0} - det3(Mc) * inverse_det;
    if (!std::isfinite(X[c].lo) || !std::isfinite(X[c].hi)) return false;
  }
  return true;
}

/// Status of the arc points over a span T that ends at a certified split point (partner_domain_crossings.h) whose
/// graph interval lies in T. There the followed partner is on the domain's boundary, so its enclosure K straddles
/// the boundary line and classify_partner_span cannot decide. Instead:
///  1. Krawczyk over T (strict) and the anchor identify the zero curve gamma(t) = (v(t), y(t)), unique in W, with
///     the arc and its partner (as in classify_partner_span). The split's solution lies in W, so gamma(x*) is it:
///     G(x*) = bound, with G(t) the side's coordinate along gamma (g is linear in z) and x* the split's abscissa.
///  2. dG/dt = g_t + g_w gamma'(t), gamma' = -(dE/dw)^-1 dE/dt, is enclosed over T x K (Cramer's rule in interval
///     arithmetic on the preconditioned system). If it has a sign, G - bound has the sign of dG/dt (t - x*) on T:
///     the followed partner is on a known side of the line for every t of T but x*.
///  3. Inside: genuine if the other coordinates of P and Q lie inside over K. Outside: phantom if no arc point over
///     T has another partner in the domain. Another partner y' of an arc point (t, v(t)), v(t) in K_v, lies outside
///     W_y (uniqueness in W), so no_genuine_partner on T x K_v starts from four boxes covering the complement of
///     W_y's interior.
/// The status holds for the arc points over T beyond the split box's graph interval (`split_at_low_end`: the split
/// is at T's low end); the few points inside that interval (width about 1e-15) are not claimed.
inline Partner_status classify_span_at_split(const Partner_equations& eq, const Parameter_box& domain, int axis,
                                             const Double_interval& T, const std::array<Double_interval, 3>& W0,
                                             const Parameter_box& cell, const Partner_domain_crossing& split,
                                             bool split_at_low_end, Exclusion_budget* budget,
                                             std::array<Double_interval, 2>* partner,
                                             std::array<Double_interval, 3>* enclosure) {
  using D = Double_interval;
  const Partner_status no = Partner_status::undecided;
  const int q[3] = {1 - axis, 2, 3};
  if (!(T.lo <= split.box[axis].lo && split.box[axis].hi <= T.hi)) return no;
  std::array<D, 3> W = W0, K;
  if (!prove_zero_curve(eq, axis, T, W, K)) return no;
  if (!zero_curve_anchored(eq, axis, T, W, cell)) return no;
  for (int c = 0; c < 3; ++c)
    if (!(W[c].lo <= split.box[q[c]].lo && split.box[q[c]].hi <= W[c].hi)) return no;
  if (eq.self_intersection() && K[1].contains_zero() && K[2].contains_zero()) return no;
  // 2. the sign of dG/dt over T x K
  std::array<D, 3> slope;
  if (!implicit_slopes(eq, axis, T, K, slope)) return no;
  std::array<D, 4> z;
  z[axis] = T;
  for (int c = 0; c < 3; ++c) z[q[c]] = K[c];
  const Partner_domain_side& side = split.side;
  auto grad = [&](int i) {
    const double d = side.point == 0 ? eq.dP(side.coordinate, i) : eq.dQ(side.coordinate, i);
    return D{d, d};
  };
  D dG = grad(axis);
  for (int c = 0; c < 3; ++c) dG = dG + grad(q[c]) * slope[c];
  if (dG.contains_zero() || !std::isfinite(dG.lo) || !std::isfinite(dG.hi)) return no;
  const int far_sign = (dG.lo > 0 ? 1 : -1) * (split_at_low_end ? 1 : -1);  // sign of G - bound beyond the split
  const bool lower = side.bound == (side.coordinate == 0 ? domain.u0 : domain.v0);
  const bool inside_far = lower ? far_sign > 0 : far_sign < 0;
  std::array<D, 2> P, Q;
  eq.points(z, P, Q);
  if (inside_far) {
    for (int point = 0; point < 2; ++point)
      for (int coordinate = 0; coordinate < 2; ++coordinate) {
        if (point == side.point && coordinate == side.coordinate) continue;
        const D& x = point == 0 ? P[coordinate] : Q[coordinate];
        if (!(coordinate == 0 ? interval_inside(x, domain.u0, domain.u1) : interval_inside(x, domain.v0, domain.v1)))
          return no;
      }
    if (partner) *partner = {K[1], K[2]};
    if (enclosure) *enclosure = K;
    return Partner_status::genuine;
  }
  // Exclusion on thin boxes: over a piece T_j of T the arc points lie in T_j x K_j,v (Krawczyk's image on T_j
  // inside W), and the partners of points of such a thin box sweep a region of width ~ |T_j| around the followed
  // one, which the complement of W_y avoids once T_j is short enough. Pieces that fail are halved (three times).
  const double big = std::numeric_limits<double>::max();
  const D all{-big, big};
  const std::vector<std::array<D, 2>> complement{{D{-big, W[1].lo}, all}, {D{W[1].hi, big}, all},
                                                 {W[1], D{-big, W[2].lo}}, {W[1], D{W[2].hi, big}}};
  struct Piece {
    D T;
    int depth;
  };
  std::vector<Piece> pieces;
  const int initial = 4;
  for (int j = initial; j-- > 0;)
    pieces.push_back({D{T.lo + (T.hi - T.lo) * j / initial, j + 1 == initial ? T.hi : T.lo + (T.hi - T.lo) * (j + 1) / initial}, 0});
  while (!pieces.empty()) {
    const Piece pc = pieces.back();
    pieces.pop_back();
    std::array<D, 3> Wj = W;  // (non-strict: the zero over T_j is the one unique in W, so it lies in the image)
    bool excluded = parametric_partner_krawczyk(eq, axis, pc.T, Wj);
    if (excluded) {
      if (budget && !budget->take()) return no;
      const D& X1 = axis == 0 ? pc.T : Wj[0];
      const D& X2 = axis == 0 ? Wj[0] : pc.T;
      const Parameter_box box{Rational(X1.lo), Rational(X1.hi), Rational(X2.lo), Rational(X2.hi)};
      excluded = no_genuine_partner(eq, box, domain, 1024, &complement);
    }
    if (excluded) continue;
    if (pc.depth >= 3) return no;
    const double mid = pc.T.mid();
    pieces.push_back({D{mid, pc.T.hi}, pc.depth + 1});
    pieces.push_back({D{pc.T.lo, mid}, pc.depth + 1});
  }
  if (enclosure) *enclosure = K;
  return Partner_status::phantom;
}

/// A tight enclosure of the partner at one value t of the graph coordinate. K is a box in which the zero curve is
/// unique for each t of `span` (a strict parametric Krawczyk test); a Krawczyk test with t fixed, on a
/// small box around `guess` (other coordinate, y1, y2) inside K, encloses the same zero tightly. Returns `y`
/// (the span's enclosure) if it fails.
template <class Eq>
inline std::array<Double_interval, 2> tight_partner_enclosure(const Eq& eq, int axis,
                                                              const Double_interval& t, const Double_interval& span,
                                                              const double (&guess)[3],
                                                              const std::array<Double_interval, 3>& K,
                                                              const std::array<Double_interval, 2>& y) {
  using D = Double_interval;
  if (!(span.lo <= t.lo && t.hi <= span.hi)) return y;  // uniqueness in K holds over the span only
  std::array<double, 3> start{guess[0], guess[1], guess[2]};
  if (!(std::isfinite(guess[1]) && std::isfinite(guess[2]))) {  // no partner guess: Newton from K's centre
    std::array<D, 3> P;
    if (predict_partner_box(eq, axis, t, {std::isfinite(guess[0]) ? guess[0] : K[0].mid(), K[1].mid(), K[2].mid()}, P))
      for (int c = 0; c < 3; ++c) start[c] = P[c].mid();
  }
  std::array<D, 3> W;
  bool near = true;
  for (int c = 0; c < 3 && near; ++c) {
    const double g = std::isfinite(start[c]) ? start[c] : K[c].mid();
    const double r = 1e-8 * (1 + std::fabs(g)) + (t.hi - t.lo);
    W[c] = D{std::max(g - r, K[c].lo), std::min(g + r, K[c].hi)};
    near = W[c].lo < W[c].hi;
  }
  if (near && parametric_partner_krawczyk(eq, axis, t, W, nullptr, true)) return {W[1], W[2]};
  // no usable guess (e.g. the floating-point lifting followed another partner): contract K itself. Each success
  // replaces W by its Krawczyk image, which holds the zero; the last image is kept.
  W = K;
  bool any = false;
  for (int it = 0; it < 12; ++it) {
    std::array<D, 3> next = W;
    if (!parametric_partner_krawczyk(eq, axis, t, next, nullptr, true)) break;
    any = true;
    const bool shrinking = (next[1].hi - next[1].lo) + (next[2].hi - next[2].lo) < 0.5 * ((W[1].hi - W[1].lo) + (W[2].hi - W[2].lo));
    W = next;
    if (!shrinking) break;
  }
  if (!any) return y;
  return {D{std::max(W[1].lo, y[0].lo), std::min(W[1].hi, y[0].hi)}, D{std::max(W[2].lo, y[1].lo), std::min(W[2].hi, y[1].hi)}};
}

/// The closed boxes covering `range` minus the interiors of `holes` (each difference of a box and a hole: at most
/// four boxes, left, right, below and above the hole).
inline std::vector<std::array<Double_interval, 2>> complement_cover(const std::array<Double_interval, 2>& range,
                                                                    const std::vector<std::array<Double_interval, 2>>& holes) {
  using D = Double_interval;
  std::vector<std::array<D, 2>> cover{range};
  for (const auto& h : holes) {
    std::vector<std::array<D, 2>> next;
    for (const auto& r : cover) {
      const bool meets = r[0].lo < h[0].hi && h[0].lo < r[0].hi && r[1].lo < h[1].hi && h[1].lo < r[1].hi;
      if (!meets) {
        next.push_back(r);
        continue;
      }
      if (r[0].lo < h[0].lo) next.push_back({D{r[0].lo, h[0].lo}, r[1]});
      if (h[0].hi < r[0].hi) next.push_back({D{h[0].hi, r[0].hi}, r[1]});
      const D mid{std::max(r[0].lo, h[0].lo), std::min(r[0].hi, h[0].hi)};
      if (r[1].lo < h[1].lo) next.push_back({mid, D{r[1].lo, h[1].lo}});
      if (h[1].hi < r[1].hi) next.push_back({mid, D{h[1].hi, r[1].hi}});
    }
    cover = std::move(next);
  }
  return cover;
}

/// Whether no point of the box (its u range and its v range) has a partner in the domain outside the partner boxes
/// `holes`: no_genuine_partner, the box halved along its longer side while the test fails, down to sides of
/// `min_side`, within `max_tests` tests (counted in `tests`) and the budget's count `take`. Each part needs its
/// own proof; together they cover the box. Halving helps where the gap that separates a point of the box from
/// having a partner is small against the box: next to a node (the other branch's partners) and along a
/// tangential contact (combined_equations_exclusion.h), where it shrinks with the point's distance from the arc.
inline bool no_partner_in_region(const Partner_equations& eq, const Parameter_box& domain,
                                 const std::array<Double_interval, 2>& box, double min_side, std::size_t& tests,
                                 std::size_t max_tests, Exclusion_budget& budget,
                                 const std::vector<std::array<Double_interval, 2>>& holes = {},
                                 bool (Exclusion_budget::*take)() = &Exclusion_budget::take_fallback) {
  using D = Double_interval;
  std::vector<std::array<D, 2>> todo{box};
  while (!todo.empty()) {
    const std::array<D, 2> b = todo.back();
    todo.pop_back();
    if (tests >= max_tests || !(budget.*take)()) return false;
    ++tests;
    const Parameter_box pb{Rational(b[0].lo), Rational(b[0].hi), Rational(b[1].lo), Rational(b[1].hi)};
    if (holes.empty() && no_genuine_partner(eq, pb, domain, 256, nullptr)) continue;
    if (!holes.empty()) {
      const std::vector<std::array<D, 2>> cover = complement_cover(partner_range(eq, pb, domain), holes);
      if (no_genuine_partner(eq, pb, domain, 1024, &cover)) continue;
    }
    const int c = b[0].hi - b[0].lo >= b[1].hi - b[1].lo ? 0 : 1;
    if (!(b[c].hi - b[c].lo > min_side)) return false;
    const double m = b[c].mid();
    std::array<D, 2> lo = b, hi = b;
    lo[c] = D{b[c].lo, m};
    hi[c] = D{m, b[c].hi};
    todo.push_back(hi);
    todo.push_back(lo);
  }
  return true;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_LIFTING_INTERNAL_PARTNER_SPAN_PROOFS_H
