// Certified genuine / phantom status along the arcs of the projected locus D = 0 (buse-elkadi-galligo-2008 §4:
// a point of D = 0 is a genuine point of the self-intersection / intersection curve iff it has a partner inside
// the partner domain; otherwise it is phantom).
//
// Genuine, by a parametric Krawczyk test. On a cell where the subdivision proved D = 0 to be a graph over one
// coordinate (say v = g(u): every line u = c meets D = 0 at most once inside the cell), take a span T of u and
// a box W = V x Y of the other coordinate (V inside the cell) and of the partner y. The three partner equations
// E(u, v; y) = 0 (double_partner_witness.h) are square in the unknowns w = (v, y) for each fixed u. If the
// Krawczyk operator
//   K = m - C E(T, m) + (I - C dE/dw(T, W)) (W - m),   m the centre of W, C ~ (dE/dw)^-1 at the centre,
// satisfies K ⊆ W, then for EVERY u in T the map w -> w - C E(u, w) sends W into itself (mean value theorem on
// the convex box), so E(u, .) has a zero (v, y) in K (Brouwer). With nonzero weights (and y != 0 for
// self-intersection) (u, v) is a point of D = 0 in the cell, hence THE point of the arc over u, and y is one of
// its partners. If the partner points P, Q lie in the partner domain for all of K, every arc point over T is
// genuine.
// Phantom, by exclusion: no_genuine_partner on the box T x V proves that no point there has any partner in the
// partner domain (all partners, not only the one Krawczyk followed).
// Spans that are neither (the partner crosses the domain boundary, or the tests do not contract) are halved a
// few times; what remains is reported as undecided.
#ifndef BEZOUTIAN_LIFTING_CERTIFIED_LIFTING_H
#define BEZOUTIAN_LIFTING_CERTIFIED_LIFTING_H

#include <bezoutian/topology/Curve_topology.h>
#include <bezoutian/lifting/internal/beside_half_branches.h>
#include <bezoutian/lifting/internal/blown_up_partner_equations.h>
#include <bezoutian/lifting/internal/centred_partner_equations.h>
#include <bezoutian/lifting/internal/exact_point_spans.h>
#include <bezoutian/lifting/internal/half_branch_chains.h>
#include <bezoutian/lifting/double_partner_witness.h>
#include <bezoutian/lifting/internal/kernel_partner_proofs.h>
#include <bezoutian/lifting/internal/partner_span_proofs.h>
#include <bezoutian/lifting/partner_domain_crossings.h>
#include <bezoutian/arithmetic/number_types.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

namespace bezoutian {
namespace internal {

/// Result of certify_edge_partners: status per polyline point and the undecided fraction of the edge.
struct Edge_partner_certificate {
  std::vector<Partner_status> point_status;  ///< per polyline point (undecided if not proved)
  /// per polyline point proved genuine: an enclosure of a partner of the arc point (NaN bounds otherwise)
  std::vector<std::array<Double_interval, 2>> partner_enclosure;
  double undecided_fraction = 1;            ///< undecided share of the edge's spans (by graph-coordinate length)
  double length = 0;                        ///< the edge's length in that measure
};

/// Phantom proof without a followed partner, for a run of spans T_1, ..., T_r (sorted, disjoint interiors) of
/// one graph piece of the cell: the arc points over T_j lie in the strip T_j x (the cell's range in the other
/// coordinate), so excluding every partner in the domain on that strip proves T_j phantom. The strips of the
/// hull of a run of touching spans are covered adaptively: roughly square boxes, each tested by
/// no_genuine_partner (256 partner pieces) and halved along its longer side when the test fails, down to sides
/// of a quarter of the shortest span it meets (at most 16 tests per span of the run); points far from D = 0 have
/// no partner at all, so only the boxes near the arc become small. One cover for the run instead of one per span
/// saves the repeated tests far from the arc. The cover runs along the graph coordinate, and a run whose first
/// four spans all fail is given up (hopeless runs would otherwise spend the budget of all others).
/// Returns, for each span, whether its whole strip was covered by excluded boxes (closed boxes: a failed box
/// that only touches a strip's edge leaves it proved, the edge lying in the excluded neighbour too).
/// `descending`: the cover runs from high to low graph coordinate (a run whose hard end, e.g. a seam where two
/// patches of one surface meet, is its low end is given up at once in the ascending order).
inline std::vector<bool> exclude_strips(const Partner_equations& eq, const Parameter_box& domain, int axis,
                                        const std::vector<Double_interval>& spans, const Parameter_box& cell,
                                        const std::vector<std::array<Double_interval, 2>>* start,
                                        Exclusion_budget& budget, bool descending = false) {
  std::vector<bool> proved(spans.size(), false);
  const Rational &c0 = axis == 0 ? cell.v0 : cell.u0, &c1 = axis == 0 ? cell.v1 : cell.u1;
  const double range = CGAL::to_double(c1 - c0);
  std::size_t a = 0;
  while (a < spans.size()) {
    std::size_t b = a + 1;  // the run [a, b): spans that touch
    while (b < spans.size() && spans[b].lo <= spans[b - 1].hi) ++b;
    const Rational t0(spans[a].lo), t1(spans[b - 1].hi);
    const double width = CGAL::to_double(t1 - t0);
    auto box_of = [&](const Rational& s0, const Rational& s1, const Rational& o0, const Rational& o1) {
      return axis == 0 ? Parameter_box{s0, s1, o0, o1} : Parameter_box{o0, o1, s0, s1};
    };
    // about square boxes of side min(width, range), at most 16 (the halving refines them)
    // (the ratios are clamped as doubles: a span of width 0 makes one of them 1e300, beyond int)
    const int along = int(std::max(1.0, std::min(16.0, std::ceil(width / std::max(range, 1e-300))))),
              across = int(std::max(1.0, std::min(16.0, std::ceil(range / std::max(width, 1e-300)))));
    struct Piece {
      Rational s0, s1, o0, o1;  // graph coordinate, other coordinate
    };
    std::vector<Piece> todo;  // a stack, processed from low to high graph coordinate (descending: high to low)
    for (int k = 0; k < along; ++k) {
      const int p = descending ? k : along - 1 - k;
      for (int q = 0; q < across; ++q)
        todo.push_back({t0 + (t1 - t0) * p / along, p + 1 == along ? t1 : t0 + (t1 - t0) * (p + 1) / along,
                        c0 + (c1 - c0) * q / across, q + 1 == across ? c1 : c0 + (c1 - c0) * (q + 1) / across});
    }
    // A box that is neither excluded nor split makes the spans it meets undecided ("lost"): those are the spans
    // meeting its graph range [s0, s1] with positive length (rounded outward: the box ends are rationals). A box
    // meeting lost spans only is not tested any more: near a genuine point (the strip of a span next to a split
    // point) every small box fails, and refining there would spend the whole budget on one span.
    std::vector<bool> lost(b - a, false);
    auto meets = [&](std::size_t j, const Piece& P) {
      return Double_interval::next(CGAL::to_double(P.s0), false) < spans[j].hi &&
             spans[j].lo < Double_interval::next(CGAL::to_double(P.s1), true);
    };
    auto all_lost = [&](const Piece& P) {
      for (std::size_t j = a; j < b; ++j)
        if (!lost[j - a] && meets(j, P)) return false;
      return true;
    };
    auto shortest_met = [&](const Piece& P) {  // boxes are split down to a quarter of the spans they meet
      double w = HUGE_VAL;
      for (std::size_t j = a; j < b; ++j)
        if (meets(j, P)) w = std::min(w, spans[j].hi - spans[j].lo);
      return std::max(w, 1e-300);
    };
    std::size_t tests = 0;
    const std::size_t max_tests = 16 * (b - a) + 16;  // as many as 16 per span
    while (!todo.empty()) {
      const Piece P = todo.back();
      todo.pop_back();
      {  // the spans before P are decided; a run whose first four decided spans are all lost is given up
        std::size_t won = 0, gone = 0;
        if (descending) {
          for (std::size_t j = b; j-- > a && spans[j].lo >= CGAL::to_double(P.s1);) (lost[j - a] ? gone : won) += 1;
        } else {
          for (std::size_t j = a; j < b && spans[j].hi <= CGAL::to_double(P.s0); ++j) (lost[j - a] ? gone : won) += 1;
        }
        if (won == 0 && gone >= 4) {
          std::fill(lost.begin(), lost.end(), true);
          break;
        }
      }
      if (all_lost(P)) continue;
      if (tests < max_tests && budget.take_fallback()) {
        ++tests;
        if (no_genuine_partner(eq, box_of(P.s0, P.s1, P.o0, P.o1), domain, 256, start)) continue;
      }
      const double ws = CGAL::to_double(P.s1 - P.s0), wo = CGAL::to_double(P.o1 - P.o0);
      if (tests >= max_tests || budget.fallback_left == 0 || std::max(ws, wo) <= 0.25 * shortest_met(P)) {
        for (std::size_t j = a; j < b; ++j)
          if (meets(j, P)) lost[j - a] = true;
        continue;
      }
      if (ws >= wo) {
        const Rational m = (P.s0 + P.s1) / 2;
        const Piece low{P.s0, m, P.o0, P.o1}, high{m, P.s1, P.o0, P.o1};
        todo.push_back(descending ? low : high);  // the near half is processed first
        todo.push_back(descending ? high : low);
      } else {
        const Rational m = (P.o0 + P.o1) / 2;
        todo.push_back({P.s0, P.s1, P.o0, m});
        todo.push_back({P.s0, P.s1, m, P.o1});
      }
    }
    for (std::size_t j = a; j < b; ++j) proved[j] = !lost[j - a];
    a = b;
  }
  return proved;
}

/// Phantom proof at one traced point: the slab {t} x (the cell's range of the other coordinate), t the point's
/// graph coordinate (a value, or the tiny enclosure of an end point), holds the exact arc point; exclude_strips on
/// it, at most 32 tests, counted in budget.point_left. At one value of t the exclusion need not beat the variation
/// of the partner equations across a span (next to a seam, where two patches of one surface nearly coincide, that
/// variation is as large as their gap), and it needs no real kernel vector (the kernel test fails where the
/// partner is complex).
inline bool exclude_point_slab(const Partner_equations& eq, const Parameter_box& domain, int axis,
                               const Double_interval& t, const Parameter_box& cell,
                               const std::vector<std::array<Double_interval, 2>>* start, Exclusion_budget& budget) {
  if (budget.point_left == 0) return false;
  Exclusion_budget one = budget;
  const std::size_t allowed = std::min<std::size_t>(32, budget.point_left);
  one.fallback_left = allowed;
  const bool proved = exclude_strips(eq, domain, axis, {t}, cell, start, one)[0];
  budget.left = one.left;
  budget.point_left -= std::max<std::size_t>(1, allowed - one.fallback_left);
  return proved;
}

/// A half-branch H of D = 0 inside the box of a singular point p, from a crossing c of the box's edge to p
/// (graph_axis -1: not a proved graph). Chained proof along the traced points from c: with t the coordinate
/// along the line of c's edge's normal (u if c lies on a line u = const),
///  - each span [t_j, t_j+1] gets a strict Krawczyk proof (a unique, continuous zero curve gamma_j in its box W_j);
///  - the first is anchored at c: Krawczyk at t = t_c encloses gamma_0(t_c) in c's isolating interval on its
///    line, so gamma_0(t_c) is c;
///  - consecutive curves agree at t_j: Krawczyk at t_j on W_j-1 ∩ W_j proves a zero there, equal to both;
/// so the projection of the chained curve is a continuous path of D = 0 that starts at c, enters the box, and
/// (H being the only part of D = 0 in the box near c, and a 1-manifold up to p) runs along H; as t is monotone
/// it covers the sub-arc of H from c to the last proved t. The span that reaches p is not attempted (there both
/// branches meet). Sets the statuses of the points covered; returns the undecided fraction of the piece.
/// Where the chain stops (a Jacobian too ill-conditioned for Krawczyk's test, as next to a seam where two patches
/// of one smooth surface nearly coincide), the spans beyond it whose floating-point status is phantom are
/// excluded instead: no point of the slab {t between t_j and t_j+1} of the cell has a partner in the domain
/// (exclude_strips). That is a statement about every point of D = 0 in the slab, so it needs neither uniqueness
/// nor monotonicity; H lies in the cell, so its points over those t are phantom.
inline double certify_half_branch(const Partner_equations& eq, const Parameter_box& domain, bool unbounded,
                                  const Curve_topology_edge& e, const Curve_topology_piece& pc,
                                  const std::vector<std::array<double, 2>>& partner, const std::vector<bool>& known,
                                  const std::vector<bool>& float_genuine, Exclusion_budget& budget,
                                  Edge_partner_certificate& out, Half_branch_chains* chains);

/// The state the three phases of certify_edge_partners share on one graph piece (graph_axis 0 or 1) of an edge:
/// its inputs, the certificate being filled, the edge's total and undecided lengths, and the partner cover of the
/// cell. The phases run in order: prove_spans, exclude_undecided_strips, prove_points.
class Graph_piece_certifier {
 public:
  using D = Double_interval;

  Graph_piece_certifier(const Partner_equations& eq, const Parameter_box& domain, bool unbounded,
                        const Curve_topology_edge& e, const Curve_topology_piece& pc,
                        const std::vector<std::array<double, 2>>& partner, const std::vector<bool>& partner_known,
                        const std::vector<bool>& float_genuine, Exclusion_budget& budget,
                        const std::vector<const Partner_domain_crossing*>& splits,
                        const std::vector<Blown_up_partner_equations>* blown_up, const Kernel_partner_system* kernel,
                        const std::array<D, 2>& none, Edge_partner_certificate& out, double& total, double& undecided)
      : eq(eq), domain(domain), unbounded(unbounded), e(e), pc(pc), partner(partner), partner_known(partner_known),
        float_genuine(float_genuine), budget(budget), splits(splits), blown_up(blown_up), kernel(kernel), none(none),
        out(out), total(total), undecided(undecided), n(e.polyline.size()) {}
  Graph_piece_certifier(const Graph_piece_certifier&) = delete;
  Graph_piece_certifier& operator=(const Graph_piece_certifier&) = delete;

  /// Phase 1: the spans between consecutive polyline points, halved up to `max_halvings` times while undecided,
  /// by classify_partner_span (at a certified split point classify_span_at_split, near the trivial partner
  /// classify_span_near_trivial_partner); runs of spans whose partner is outside the domain are excluded together,
  /// and the undecided spans near floating-point phantom points are kept for phase 2.
  void prove_spans(int max_halvings) {
    // Spans whose partner is proved outside the domain are excluded together: one exclusion on the hull of a run of
    // consecutive such spans (T x K_v each) is far cheaper than one per span; if it fails, one per span.
    struct Outside_span {
      std::size_t i;
      D T, V;
    };
    std::vector<Outside_span> run;
    auto flush = [&]() {
      if (run.empty()) return;
      D H = run[0].T, HV = run[0].V;
      for (const auto& r : run)
        H = D{std::min(H.lo, r.T.lo), std::max(H.hi, r.T.hi)}, HV = D{std::min(HV.lo, r.V.lo), std::max(HV.hi, r.V.hi)};
      auto box_of = [&](const D& t, const D& v) {
        return axis == 0 ? Parameter_box{Rational(t.lo), Rational(t.hi), Rational(v.lo), Rational(v.hi)}
                         : Parameter_box{Rational(v.lo), Rational(v.hi), Rational(t.lo), Rational(t.hi)};
      };
      const bool all = run.size() > 1 && budget.take() && no_genuine_partner(eq, box_of(H, HV), domain, 1024, start());
      for (const auto& r : run) {
        const bool ok = all || (budget.take() && no_genuine_partner(eq, box_of(r.T, r.V), domain, 1024, start()));
        if (ok) {
          merge(r.i, Partner_status::phantom, none);
          merge(r.i + 1, Partner_status::phantom, none);
        } else {
          undecided += r.T.hi - r.T.lo;
        }
      }
      run.clear();
    };
    for (std::size_t i = pc.first; i < pc.last; ++i) {
      const D a = coord(i, axis), b = coord(i + 1, axis);
      const D T{std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
      const double len = T.hi - T.lo;
      total += len;
      const D oa = coord(i, other), ob = coord(i + 1, other);
      const double slope_room = 0.5 * (std::max(oa.hi, ob.hi) - std::min(oa.lo, ob.lo)) + 0.25 * len + 1e-12;
      const D V{std::min(oa.lo, ob.lo) - slope_room, std::max(oa.hi, ob.hi) + slope_room};
      std::array<D, 3> W{V, D{}, D{}};
      for (int c = 0; c < 2; ++c) {  // (a partner not known: the other end's; none: 0, for the exclusion fallback)
        const bool k0 = partner_known[i], k1 = partner_known[i + 1];
        const double y0 = k0 ? partner[i][c] : (k1 ? partner[i + 1][c] : 0);
        const double y1 = k1 ? partner[i + 1][c] : y0;
        const double r = 0.5 * std::fabs(y1 - y0) + 0.25 * len + 1e-9 * (1 + std::fabs(y0));
        W[1 + c] = D{std::min(y0, y1) - r, std::max(y0, y1) + r};
      }
      const bool increasing = a.mid() <= b.mid();  // the polyline may run either way along the graph coordinate
      // halve undecided spans: a partner leaving the domain inside the span, or a span too long to contract
      struct Span {
        D T;
        int depth;
      };
      std::vector<Span> stack{{T, 0}};
      Partner_status left = Partner_status::undecided, right = Partner_status::undecided;
      std::array<D, 2> left_y = none, right_y = none;
      std::array<D, 3> left_K{}, right_K{}, left_B{}, right_B{};
      int left_chart = -1, right_chart = -1;  // the blown-up chart that proved the end span, if any
      D left_T{}, right_T{};
      while (!stack.empty()) {
        budget.poll();
        const Span s = stack.back();
        stack.pop_back();
        std::array<D, 3> Ws = W, P;  // the box predicted from the tangent at the middle of the span, if any
        if (predict_partner_box(eq, axis, s.T, {W[0].mid(), W[1].mid(), W[2].mid()}, P)) Ws = P;
        std::array<D, 2> y = none;
        std::array<D, 3> K;
        const bool phantom_seen = !float_genuine[i] || !float_genuine[i + 1];
        // a span ending at a certified split point: decided by the side of the line the partner is on
        const Partner_domain_crossing* split = nullptr;
        int chart_used = -1;
        std::array<D, 3> B{};
        for (std::size_t j : {i, i + 1})
          if (j < splits.size() && splits[j] && s.T.lo <= splits[j]->box[axis].lo && splits[j]->box[axis].hi <= s.T.hi)
            split = splits[j];
        Partner_status st =
            split && !unbounded
                ? classify_span_at_split(eq, domain, axis, s.T, Ws, pc.cell, *split,
                                         split->box[axis].mid() < s.T.mid(), &budget, &y, &K)
                : classify_partner_span(eq, domain, unbounded, axis, s.T, Ws, pc.cell, start, &y, s.depth == 0, &K,
                                        &budget);
        if (st == Partner_status::undecided && blown_up && blown_up->size() == 2 && !split && !unbounded &&
            (float_genuine[i] || float_genuine[i + 1]) && (partner_known[i] || partner_known[i + 1])) {
          // a partner close to the trivial one (near a pinch point): the blown-up equations F = E / r
          const std::array<double, 2> ya = partner_known[i] ? partner[i] : partner[i + 1],
                                      yb = partner_known[i + 1] ? partner[i + 1] : partner[i];
          const double size = std::max(std::fabs(ya[0]) + std::fabs(ya[1]), std::fabs(yb[0]) + std::fabs(yb[1]));
          if (size < 0.25 && budget.take_blown_up()) {
            const int chart = std::fabs(ya[0]) + std::fabs(yb[0]) >= std::fabs(ya[1]) + std::fabs(yb[1]) ? 0 : 1;
            st = classify_span_near_trivial_partner((*blown_up)[std::size_t(chart)], domain, axis, s.T, W[0], ya, yb,
                                                    pc.cell, &y, &K, &B);
            if (st == Partner_status::genuine) ++budget.blown_up_proved, chart_used = chart;
          }
        }
        if (st == Partner_status::outside) {  // the whole span (depth 0): joins the run, decided at the flush
          run.push_back({i, s.T, K[0]});
          left = right = Partner_status::outside;
          continue;
        }
        // halving pays where the genuine status changes or Krawczyk needs a shorter span; between two phantom
        // points the partner often cannot be followed at all (complex, or the trivial one), so it stops early there
        const bool phantom_both = !float_genuine[i] && !float_genuine[i + 1];
        const int limit = phantom_both ? 2 : max_halvings;
        if (st == Partner_status::undecided && s.depth < limit) {
          const double mid = s.T.mid();
          stack.push_back({D{mid, s.T.hi}, s.depth + 1});
          stack.push_back({D{s.T.lo, mid}, s.depth + 1});
          continue;
        }
        if (st == Partner_status::undecided) {
          if (phantom_seen && !unbounded) {  // the strip exclusion, for the whole piece at once (below)
            const std::size_t npos = std::size_t(-1);
            strips.push_back({s.T, s.T.lo <= T.lo ? (increasing ? i : i + 1) : npos,
                              s.T.hi >= T.hi ? (increasing ? i + 1 : i) : npos});
          } else {
            undecided += s.T.hi - s.T.lo;
          }
        }
        if (s.T.lo <= T.lo) left = st, left_y = y, left_K = K, left_T = s.T, left_chart = chart_used, left_B = B;
        if (s.T.hi >= T.hi) right = st, right_y = y, right_K = K, right_T = s.T, right_chart = chart_used, right_B = B;
      }
      if (left == Partner_status::outside) continue;  // pending in the run
      flush();
      merge(i, increasing ? left : right,
            tight(i, increasing ? left : right, increasing ? left_y : right_y, increasing ? left_K : right_K,
                  increasing ? left_T : right_T, increasing ? left_chart : right_chart, increasing ? left_B : right_B));
      merge(i + 1, increasing ? right : left,
            tight(i + 1, increasing ? right : left, increasing ? right_y : left_y, increasing ? right_K : left_K,
                  increasing ? right_T : left_T, increasing ? right_chart : left_chart, increasing ? right_B : left_B));
    }
    flush();
  }

  /// Phase 2: the strip exclusion of the spans kept by phase 1, for the whole piece at once.
  void exclude_undecided_strips() {
    if (!strips.empty()) {  // spans without a followed partner, near floating-point phantom points
      std::sort(strips.begin(), strips.end(), [](const Strip& x, const Strip& y) { return x.T.lo < y.T.lo; });
      std::vector<D> spans;
      for (const Strip& st : strips) spans.push_back(st.T);
      std::vector<bool> proved = exclude_strips(eq, domain, axis, spans, pc.cell, start(), budget);
      // the runs (touching spans) lost entirely in the ascending cover, again from the other end: a run given up
      // at a hard low end (a run lost in its middle would only spend the budget again)
      std::vector<D> again;
      std::vector<std::size_t> where;
      for (std::size_t j0 = 0, j1; j0 < strips.size(); j0 = j1) {
        bool none = !proved[j0];
        for (j1 = j0 + 1; j1 < strips.size() && spans[j1].lo <= spans[j1 - 1].hi; ++j1) none = none && !proved[j1];
        if (none)
          for (std::size_t j = j0; j < j1; ++j) again.push_back(spans[j]), where.push_back(j);
      }
      if (!again.empty() && budget.fallback_left > 0) {
        // at most 256 tests (a long run lost for other reasons, e.g. genuine points at both ends, would spend
        // the whole locus' budget: measured on teapot spout 18 x 19)
        Exclusion_budget second_budget = budget;
        second_budget.fallback_left = std::min<std::size_t>(budget.fallback_left, 256);
        const std::vector<bool> second =
            exclude_strips(eq, domain, axis, again, pc.cell, start(), second_budget, true);
        budget.left = second_budget.left;
        budget.fallback_left -= std::min<std::size_t>(budget.fallback_left, 256) - second_budget.fallback_left;
        for (std::size_t r = 0; r < where.size(); ++r)
          if (second[r]) proved[where[r]] = true;
      }
      for (std::size_t j = 0; j < strips.size(); ++j) {
        if (!proved[j]) {
          undecided += strips[j].T.hi - strips[j].T.lo;
          continue;
        }
        for (std::size_t p : {strips[j].first_point, strips[j].second_point})
          if (p < n && out.point_status[p] == Partner_status::undecided) merge(p, Partner_status::phantom, none);
      }
    }
  }

  /// Phase 3: the polyline points no span proof reached, each at its own value of the graph coordinate.
  void prove_points() {
    // The points no span proof reached, each at its own value t of the graph coordinate (a span of width 0: the
    // tests that do not contract over a span often do at one value):
    //  - floating-point genuine: classify_partner_span on a small box around the floating-point (o, y);
    //  - floating-point phantom: the kernel of B (kernel_partner_proofs.h).
    //  - floating-point phantom, where the kernel test fails: Krawczyk's test at t around the floating-point
    //    (o, y) encloses the arc point in a tiny box, on which no partner may lie in the domain; else the slab of
    //    the whole cell at t (below).
    for (std::size_t i = pc.first; i <= pc.last && i < n; ++i) {
      if (out.point_status[i] != Partner_status::undecided) continue;
      if (i < splits.size() && splits[i]) continue;  // (a split point's status is its own proof)
      const D t = coord(i, axis), o = coord(i, other);
      auto around = [](const D& c) { return D{c.lo - 1e-9 * (1 + std::fabs(c.lo)), c.hi + 1e-9 * (1 + std::fabs(c.hi))}; };
      const std::array<D, 3> W{around(o), around(D{partner[i][0], partner[i][0]}), around(D{partner[i][1], partner[i][1]})};
      if (float_genuine[i] && partner_known[i]) {
        std::array<D, 2> y;
        const auto no_start = []() -> const std::vector<std::array<D, 2>>* { return nullptr; };
        if (classify_partner_span(eq, domain, unbounded, axis, t, W, pc.cell, no_start, &y, true) ==
            Partner_status::genuine)
          merge(i, Partner_status::genuine, y);
      } else if (!float_genuine[i] && !unbounded) {
        if (kernel && kernel_proves_phantom(*kernel, domain, axis, t, o.mid(), pc.cell)) {
          merge(i, Partner_status::phantom, none);
          continue;
        }
        if (partner_known[i] && budget.point_left > 0) {
          Exclusion_budget one = budget;
          one.left = 1;
          --budget.point_left;
          if (classify_partner_span(eq, domain, unbounded, axis, t, W, pc.cell, start, nullptr, false, nullptr, &one) ==
              Partner_status::phantom) {
            merge(i, Partner_status::phantom, none);
            continue;
          }
        }
        if (exclude_point_slab(eq, domain, axis, t, pc.cell, start(), budget)) merge(i, Partner_status::phantom, none);
      }
    }
  }

 private:
  const Partner_equations& eq;
  const Parameter_box& domain;
  const bool unbounded;
  const Curve_topology_edge& e;
  const Curve_topology_piece& pc;
  const std::vector<std::array<double, 2>>& partner;
  const std::vector<bool>& partner_known;
  const std::vector<bool>& float_genuine;
  Exclusion_budget& budget;
  const std::vector<const Partner_domain_crossing*>& splits;
  const std::vector<Blown_up_partner_equations>* const blown_up;
  const Kernel_partner_system* const kernel;
  const std::array<D, 2>& none;
  Edge_partner_certificate& out;
  double& total;
  double& undecided;
  const std::size_t n;
  const int axis = pc.graph_axis;
  const int other = 1 - axis;

  void merge(std::size_t i, Partner_status s, const std::array<D, 2>& y) {
    if (s == Partner_status::undecided) return;
    out.point_status[i] = s;
    if (s == Partner_status::genuine) out.partner_enclosure[i] = y;
  }

  // the graph coordinate and the other one at polyline point i, as intervals (end points: node enclosures)
  D coord(std::size_t i, int c) const {
    if (i == pc.first) return D{pc.first_box[2 * c], pc.first_box[2 * c + 1]};
    if (i == pc.last) return D{pc.last_box[2 * c], pc.last_box[2 * c + 1]};
    if (i < splits.size() && splits[i]) return splits[i]->box[c];  // a certified split point: its proved box
    return D{e.polyline[i][c], e.polyline[i][c]};
  }

  // The enclosure y of a genuine partner holds over the whole span (K: the span's box, where the zero curve is
  // unique for each value of the graph coordinate). At the polyline point itself a Krawczyk test with the graph
  // coordinate fixed, on a small box around the floating-point values inside K, encloses the same zero tightly;
  // if it fails the span's enclosure is kept.
  std::array<D, 2> tight(std::size_t i, Partner_status st, const std::array<D, 2>& y, const std::array<D, 3>& K,
                         const D& span, int chart, const std::array<D, 3>& B) const {
    if (st != Partner_status::genuine) return y;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (chart >= 0) {  // proved by the blown-up equations: the same test in (other coordinate, r, m), y = r d(m)
      const int big = chart == 0 ? 0 : 1;
      const bool k = partner_known[i] && partner[i][big] != 0;
      const double guess[3] = {e.polyline[i][other], k ? partner[i][big] : nan, k ? partner[i][1 - big] / partner[i][big] : nan};
      const std::array<D, 2> rm =
          tight_partner_enclosure((*blown_up)[std::size_t(chart)], axis, coord(i, axis), span, guess, B, {B[1], B[2]});
      const D rmm = rm[0] * rm[1];
      const std::array<D, 2> t = chart == 0 ? std::array<D, 2>{rm[0], rmm} : std::array<D, 2>{rmm, rm[0]};
      return std::array<D, 2>{D{std::max(t[0].lo, y[0].lo), std::min(t[0].hi, y[0].hi)},
                              D{std::max(t[1].lo, y[1].lo), std::min(t[1].hi, y[1].hi)}};
    }
    const double guess[3] = {e.polyline[i][other], partner_known[i] ? partner[i][0] : nan,
                             partner_known[i] ? partner[i][1] : nan};
    return tight_partner_enclosure(eq, axis, coord(i, axis), span, guess, K, y);
  }

  // The partner pieces that survive the exclusion on the whole cell cover every candidate partner of its points:
  // the phantom proofs of the spans start from them (computed once, on first demand). If the whole cell is
  // excluded, start() returns an empty cover and every phantom proof is immediate.
  bool computed = false, cell_failed = false;
  std::vector<std::array<D, 2>> survivors;
  const std::function<const std::vector<std::array<D, 2>>*()> start =
      [this]() -> const std::vector<std::array<D, 2>>* {
        if (!computed) {
          computed = true;
          cell_failed = !budget.take() || !no_genuine_partner(eq, pc.cell, domain, 1024, nullptr, &survivors);
        }
        return cell_failed && survivors.empty() ? nullptr : &survivors;
      };

  struct Strip {  // an undecided span near phantom points, and the polyline points whose status it gives
    D T;
    std::size_t first_point, second_point;  // (npos: none)
  };
  std::vector<Strip> strips;
};

/// Certifies the genuine / phantom status along an edge of a subdivision topology: for each graph piece, the
/// spans between consecutive polyline points (halved up to `max_halvings` times while undecided) are classified
/// by classify_partner_span; `partner[i]` is the floating-point partner of polyline point i (the first guess),
/// `float_genuine[i]` its floating-point status (the costly exclusion fallback is tried only near phantom points).
/// Half-branches inside singular boxes (graph_axis -1) are chained from their crossing (certify_half_branch).
inline Edge_partner_certificate certify_edge_partners(const Partner_equations& eq, const Parameter_box& domain,
                                                      bool unbounded, const Curve_topology_edge& e,
                                                      const std::vector<std::array<double, 2>>& partner,
                                                      const std::vector<bool>& partner_known,
                                                      const std::vector<bool>& float_genuine, Exclusion_budget& budget,
                                                      int max_halvings = 6,
                                                      const std::vector<const Partner_domain_crossing*>& splits = {},
                                                      const std::vector<Blown_up_partner_equations>* blown_up = nullptr,
                                                      const Kernel_partner_system* kernel = nullptr,
                                                      Half_branch_chains* chains = nullptr) {
  using D = Double_interval;
  Edge_partner_certificate out;
  const std::size_t n = e.polyline.size();
  out.point_status.assign(n, Partner_status::undecided);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::array<D, 2> none{D{nan, nan}, D{nan, nan}};
  out.partner_enclosure.assign(n, none);
  double total = 0, undecided = 0;
  for (const Curve_topology_piece& pc : e.pieces) {
    if (pc.last >= n || pc.first >= pc.last) continue;
    if (pc.graph_axis < 0) {  // a half-branch inside a singular point's box
      const double len = std::fabs(e.polyline[pc.last][0] - e.polyline[pc.first][0]) +
                         std::fabs(e.polyline[pc.last][1] - e.polyline[pc.first][1]);
      total += len;
      undecided += len * certify_half_branch(eq, domain, unbounded, e, pc, partner, partner_known,
                                                   float_genuine, budget, out, unbounded ? nullptr : chains);
      continue;
    }
    Graph_piece_certifier piece(eq, domain, unbounded, e, pc, partner, partner_known, float_genuine, budget, splits,
                                blown_up, kernel, none, out, total, undecided);
    piece.prove_spans(max_halvings);
    piece.exclude_undecided_strips();
    piece.prove_points();
  }
  out.undecided_fraction = total > 0 ? undecided / total : 1;
  out.length = total;
  return out;
}

inline double certify_half_branch(const Partner_equations& eq, const Parameter_box& domain, bool unbounded,
                                  const Curve_topology_edge& e, const Curve_topology_piece& pc,
                                  const std::vector<std::array<double, 2>>& partner, const std::vector<bool>& known,
                                  const std::vector<bool>& float_genuine, Exclusion_budget& budget,
                                  Edge_partner_certificate& out, Half_branch_chains* chains) {
  using D = Double_interval;
  if (pc.singular_end < 0 || pc.last >= e.polyline.size()) return 1;
  const int axis = pc.crossing_on_vertical_line ? 0 : 1;
  std::vector<std::size_t> idx;  // from the crossing to the singular point
  for (std::size_t i = pc.first; i <= pc.last; ++i) idx.push_back(i);
  if (pc.singular_end == 0) std::reverse(idx.begin(), idx.end());
  const std::size_t m = idx.size();
  if (m < 3) return 1;
  const D tc = axis == 0 ? D::hull(pc.crossing.u0, pc.crossing.u1) : D::hull(pc.crossing.v0, pc.crossing.v1);
  auto t_at = [&](std::size_t j) { return j == 0 ? tc : D{e.polyline[idx[j]][axis], e.polyline[idx[j]][axis]}; };
  const double full = std::fabs(e.polyline[idx[m - 1]][axis] - tc.mid());
  if (!(full > 0)) return 1;
  const double dir = e.polyline[idx[1]][axis] - tc.mid();
  std::array<D, 3> W_prev;
  double covered = 0;
  // Spans in order from c; a span that fails is halved (up to 8 times) and the halves are chained in turn. The
  // guess for a span is the previous proved box (continuation), or the traced point's floating-point partner.
  // Eight halvings, not four: along a thin loop of two nearly tangent surfaces the chain needs spans far shorter
  // than the traced ones, and the first span that fails ends the chain (doc/surface_intersection.md: a loop of
  // width 2^-13, 93 % of its points proved instead of 37 %, at three times the cost; the benchmark: 186 more points
  // proved, 4 % more time).
  struct Span {
    D T;
    std::size_t j;  // the span lies between traced points j and j + 1
    int depth;
  };
  std::vector<Span> todo;  // processed from the back
  for (std::size_t j = m - 2; j-- > 0;) todo.push_back({D{}, j, 0});
  // the spans whose fibre is proved too (half_branch_chains.h), for the complete lifting
  Half_branch_chain* record = chains ? &chains->add(pc) : nullptr;
  if (record) {
    record->axis = axis;
    record->t_crossing = tc.mid();
    record->t_end = e.polyline[idx[m - 1]][axis];
  }
  auto record_fibre = [&](const D& T, const std::array<D, 3>& W, const std::array<D, 3>& K, Partner_status st) {
    if (!record) return;
    if (st == Partner_status::phantom) {  // (status_from_partner excluded every partner of T x K_other)
      record->spans.push_back({T, {W[1], W[2]}, 0, K[0]});
      return;
    }
    const D X1 = axis == 0 ? T : K[0], X2 = axis == 0 ? K[0] : T;
    const Parameter_box box{Rational(X1.lo), Rational(X1.hi), Rational(X2.lo), Rational(X2.hi)};
    const std::array<D, 3> hole = widened_unique_box(eq, axis, T, W);
    const std::vector<std::array<D, 2>> cover = complement_cover(partner_range(eq, box, domain), {{hole[1], hole[2]}});
    if (chains->take_exclusion() && no_genuine_partner(eq, box, domain, 1024, &cover))
      record->spans.push_back({T, {hole[1], hole[2]}, st == Partner_status::genuine ? 1 : 0, K[0], {K[1], K[2]}});
    else
      record->open_fibres.push_back({T, K[0], {hole[1], hole[2]}, {K[1], K[2]}, st == Partner_status::genuine ? 1 : 0});
  };
  bool first = true;
  double t_done = tc.mid();
  while (!todo.empty()) {
    budget.poll();
    Span sp = todo.back();
    todo.pop_back();
    const std::size_t j = sp.j;
    const D a0 = t_at(j), b0 = t_at(j + 1);
    if ((b0.mid() - a0.mid()) * dir <= 0) break;  // not monotone along t
    D T = sp.depth == 0 ? D{std::min(a0.lo, b0.lo), std::max(a0.hi, b0.hi)} : sp.T;
    const bool at_c = first;
    const D a = at_c ? tc : D{t_done, t_done};  // the shared end with the previous (proved) span
    if (!at_c) T = dir > 0 ? D{t_done, T.hi} : D{T.lo, t_done};
    std::array<double, 3> guess;
    const std::size_t g = known[idx[j + 1]] ? idx[j + 1] : idx[j];
    if (!first)
      guess = {W_prev[0].mid(), W_prev[1].mid(), W_prev[2].mid()};
    else if (known[g])
      guess = {e.polyline[idx[j + 1]][1 - axis], partner[g][0], partner[g][1]};
    else
      break;
    std::array<D, 3> W, K;
    // (the tight box of the image inflation, a poor hole for the fibre's exclusion, only where halving ends)
    bool ok = predict_partner_box(eq, axis, T, guess, W) && prove_zero_curve(eq, axis, T, W, K, sp.depth >= 8);
    if (ok && at_c) {  // anchor at c: the zero at t_c lies in c's isolating interval on its line
      std::array<D, 3> at = W;
      const Rational &lo = axis == 0 ? pc.crossing.v0 : pc.crossing.u0, &hi = axis == 0 ? pc.crossing.v1 : pc.crossing.u1;
      ok = parametric_partner_krawczyk(eq, axis, tc, at) && Rational(at[0].lo) >= lo && Rational(at[0].hi) <= hi;
    } else if (ok) {  // the zero curves of consecutive spans agree at their common end
      std::array<D, 3> both;
      for (int c = 0; c < 3 && ok; ++c) {
        both[c] = D{std::max(W_prev[c].lo, W[c].lo), std::min(W_prev[c].hi, W[c].hi)};
        ok = both[c].lo <= both[c].hi;
      }
      ok = ok && parametric_partner_krawczyk(eq, axis, a, both);
    }
    const Partner_status st = ok ? status_from_partner(eq, domain, unbounded, axis, T, K, nullptr)
                                 : Partner_status::undecided;
    if (st == Partner_status::undecided) {
      if (sp.depth >= 8) break;
      const double mid = T.mid();  // retry on the first half, then the second
      todo.push_back({dir > 0 ? D{mid, T.hi} : D{T.lo, mid}, j, sp.depth + 1});
      todo.push_back({dir > 0 ? D{T.lo, mid} : D{mid, T.hi}, j, sp.depth + 1});
      continue;
    }
    first = false;
    record_fibre(T, W, K, st);
    W_prev = W;
    t_done = dir > 0 ? T.hi : T.lo;
    const bool span_end = dir > 0 ? T.hi >= b0.hi : T.lo <= b0.lo;  // reached traced point j + 1
    for (std::size_t k : {j, j + 1}) {  // (gamma_0(t_c) is c itself)
      if (k == j + 1 && !span_end) continue;
      if (k == j && !(at_c || sp.depth == 0 || (dir > 0 ? T.lo <= a0.mid() : T.hi >= a0.mid()))) continue;
      if (out.point_status[idx[k]] == Partner_status::undecided) out.point_status[idx[k]] = st;
      if (st == Partner_status::genuine) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const double guess[3] = {e.polyline[idx[k]][1 - axis], known[idx[k]] ? partner[idx[k]][0] : nan,
                                 known[idx[k]] ? partner[idx[k]][1] : nan};
        out.partner_enclosure[idx[k]] = tight_partner_enclosure(eq, axis, t_at(k), T, guess, W, {K[1], K[2]});
      }
    }
    covered = std::fabs(t_done - tc.mid());
  }
  // The span reaching p, once the chain has reached its start: halved towards p, each piece from the end of the
  // previous one to half-way to p's certified box. Near p the two branches through it are apart by about the
  // distance to p, so every piece has about the conditioning of the first; the pieces stop inside p's box (widened
  // by a few ulps), which holds p and is not counted: p is the vertex, with its own certificate.
  const auto& p_box = pc.singular_end == 0 ? pc.first_box : pc.last_box;
  const double ulps = 8 * std::numeric_limits<double>::epsilon() * (1 + std::fabs(tc.mid()));
  const double p_near = dir > 0 ? p_box[2 * axis] - ulps : p_box[2 * axis + 1] + ulps;  // the near side of p's box
  if (!first && m >= 3 && t_done == t_at(m - 2).mid() && (p_near - t_done) * dir > 0) {
    // a piece that fails is shrunk towards t_done, up to 10 times, and the next pieces keep that share of the
    // distance to p (about 570 pieces at a sixteenth each from a traced span to an ulp of p)
    int shrink = 0;
    // p exact, with its partner exactly on the partner domain's boundary (the Villarceau arc ending at the plane's
    // corner, its partner on the torus patch's side): the partner comes within rounding of the side as t nears p,
    // and the pieces' statuses are decided beside that exact point (exact_point_spans.h); found once, by Newton's
    // method at p from the first piece that needs it
    std::optional<std::optional<Partner_boundary_point>> exact_p;
    auto exact_end = [&]() -> const Partner_boundary_point* {
      if (!exact_p) {
        exact_p.emplace();
        std::array<double, 3> w{W_prev[0].mid(), W_prev[1].mid(), W_prev[2].mid()};
        if (!unbounded && p_box[0] == p_box[1] && p_box[2] == p_box[3] &&
            solve_partner_equations(eq, axis, p_box[2 * axis], w))
          if (const auto x = exact_boundary_point(eq, domain, {p_box[0], p_box[2]}, {w[1], w[2]}))
            if (x->x[0] == Rational(p_box[0]) && x->x[1] == Rational(p_box[2])) *exact_p = x;
      }
      return *exact_p ? &**exact_p : nullptr;
    };
    // (the zero curve is the half-branch, which lies in its cell: its other coordinate is in the cell's range)
    const D cell_other = axis == 0 ? D::hull(pc.cell.v0, pc.cell.v1) : D::hull(pc.cell.u0, pc.cell.u1);
    // Next to p the surfaces may be tangent (the partner equations' Jacobian singular at p, as at Viviani's
    // node): the equations as written cancel to rounding level there, and boxes of absolute coordinates cannot be
    // narrower than a few ulps. A piece that fails nearer p than 1e-4 of the half-branch's length is tried again
    // on the equations expanded exactly about p and the partner of the last proved piece, in coordinates relative
    // to that centre (centred_partner_equations.h); the centre's partner is renewed when that fails too.
    std::optional<Centred_partner_equations> centred;
    std::array<D, 3> W_prev_rel;  // the box of the last proved piece relative to the centre, inside W_prev
    auto centre_w = [&] {
      const auto& z = centred->centre();
      return std::array<double, 3>{z[std::size_t(1 - axis)], z[2], z[3]};
    };
    auto rebase = [&] {  // W_prev relative to the centre
      const std::array<double, 3> c = centre_w();
      for (int k = 0; k < 3; ++k) {  // rounded inwards: a box inside the one where the zero curve is unique
        W_prev_rel[k] = D{D::next(W_prev[k].lo - c[k], true), D::next(W_prev[k].hi - c[k], false)};
        if (!(W_prev_rel[k].lo <= W_prev_rel[k].hi)) W_prev_rel[k] = D{W_prev[k].mid() - c[k], W_prev[k].mid() - c[k]};
      }
    };
    auto recentre = [&] {
      std::array<double, 4> zc;
      zc[std::size_t(axis)] = 0.5 * (p_box[2 * axis] + p_box[2 * axis + 1]);
      zc[std::size_t(1 - axis)] = 0.5 * (p_box[2 * (1 - axis)] + p_box[2 * (1 - axis) + 1]);
      zc[2] = W_prev[1].mid();
      zc[3] = W_prev[2].mid();
      if (!centred) {
        centred.emplace(eq, zc);
        rebase();
        return;
      }
      // W_prev_rel moved to the new centre in relative coordinates (the centres differ by a few ulps or less at
      // the end of the descent, where W_prev's absolute box is only a few ulps wide: rounding it inwards again
      // would empty it)
      const std::array<double, 3> old_c = centre_w();
      centred.emplace(eq, zc);
      const std::array<double, 3> c = centre_w();
      for (int k = 0; k < 3; ++k) {  // (inwards: the shift's enclosure taken at its far end on each side)
        const D shift = D{old_c[k], old_c[k]} - D{c[k], c[k]};
        const D moved{D::next(W_prev_rel[k].lo + shift.hi, true), D::next(W_prev_rel[k].hi + shift.lo, false)};
        W_prev_rel[k] = moved.lo <= moved.hi ? moved : D{W_prev_rel[k].mid() + shift.mid(), W_prev_rel[k].mid() + shift.mid()};
      }
    };
    auto to_absolute = [&](const std::array<D, 3>& A) {  // (outward: for enclosures)
      const std::array<double, 3> c = centre_w();
      std::array<D, 3> r;
      for (int k = 0; k < 3; ++k) r[k] = A[k] + D{c[k], c[k]};
      return r;
    };
    auto to_absolute_inside = [&](const std::array<D, 3>& A) {  // (inward: for boxes of uniqueness)
      const std::array<double, 3> c = centre_w();
      std::array<D, 3> r;
      for (int k = 0; k < 3; ++k) {
        r[k] = D{D::next(A[k].lo + c[k], true), D::next(A[k].hi + c[k], false)};
        if (!(r[k].lo <= r[k].hi)) r[k] = D{A[k].mid() + c[k], A[k].mid() + c[k]};
      }
      return r;
    };
    const double t_centre = 0.5 * (p_box[2 * axis] + p_box[2 * axis + 1]);
    // (farther from p the equations as written lose nothing that halving the pieces does not recover)
    const double centred_below = 1e-4 * std::fabs(full);
    // the fibre of a piece proved on the centred equations: every partner outside the widened box of its zero
    // curve excluded on the same equations (the other partners come within about d^2 of solving them)
    auto record_fibre_centred = [&](const D& T, const D& T_rel, const std::array<D, 3>& W_rel,
                                    const std::array<D, 3>& K_rel, Partner_status st) {
      const std::array<D, 3> K = to_absolute(K_rel);
      if (!record) return;
      if (st == Partner_status::phantom) {
        record->spans.push_back({T, {to_absolute(W_rel)[1], to_absolute(W_rel)[2]}, 0, K[0]});
        return;
      }
      const D X1 = axis == 0 ? T : K[0], X2 = axis == 0 ? K[0] : T;
      const D X1_rel = axis == 0 ? T_rel : K_rel[0], X2_rel = axis == 0 ? K_rel[0] : T_rel;
      const Parameter_box box{Rational(X1.lo), Rational(X1.hi), Rational(X2.lo), Rational(X2.hi)};
      const std::array<D, 3> hole_rel = widened_unique_box(*centred, axis, T_rel, W_rel), hole = to_absolute(hole_rel);
      // the partner range outside a box N about the centre's partner by the equations as written (there the
      // equations are far from zero); N minus the hole by the centred ones. N: 64 times the hole, at least 1e-6.
      const double yc1 = centred->centre()[2], yc2 = centred->centre()[3];
      const double rho = std::max(1e-6, 64 * std::max({std::fabs(hole_rel[1].lo), std::fabs(hole_rel[1].hi),
                                                       std::fabs(hole_rel[2].lo), std::fabs(hole_rel[2].hi)}));
      const std::array<D, 2> range = partner_range(eq, box, domain);
      // (N's absolute box rounded inwards: inside the relative box [-rho, rho]^2 + y_c, so the two parts leave no
      // sliver between them)
      const std::array<D, 2> near_abs{D{D::next(yc1 - rho, true), D::next(yc1 + rho, false)},
                                      D{D::next(yc2 - rho, true), D::next(yc2 + rho, false)}};
      const std::vector<std::array<D, 2>> far = complement_cover(range, {near_abs});
      std::vector<std::array<D, 2>> near;
      for (const auto& piece : complement_cover({D{-rho, rho}, D{-rho, rho}}, {{hole_rel[1], hole_rel[2]}})) {
        const std::array<D, 2> clipped{D{std::max(piece[0].lo, range[0].lo - yc1), std::min(piece[0].hi, range[0].hi - yc1)},
                                       D{std::max(piece[1].lo, range[1].lo - yc2), std::min(piece[1].hi, range[1].hi - yc2)}};
        // (the clip's ends rounded to nearest: widened by an ulp, a superset of range minus the centre)
        if (clipped[0].lo <= clipped[0].hi && clipped[1].lo <= clipped[1].hi)
          near.push_back({D::widen(clipped[0].lo, clipped[0].hi), D::widen(clipped[1].lo, clipped[1].hi)});
      }
      if (chains->take_exclusion() && (far.empty() || no_genuine_partner(eq, box, domain, 1024, &far)) &&
          no_partner_near_centre(*centred, X1_rel, X2_rel, near))
        record->spans.push_back({T, {hole[1], hole[2]}, st == Partner_status::genuine ? 1 : 0, K[0], {K[1], K[2]}});
      else
        record->open_fibres.push_back({T, K[0], {hole[1], hole[2]}, {K[1], K[2]}, st == Partner_status::genuine ? 1 : 0});
    };
    for (int step = 0; step < 1000 && (p_near - t_done) * dir > 0; ++step) {
      budget.poll();
      const double half = t_done + std::ldexp(p_near - t_done, -1 - shrink);
      // (the whole rest once it is a few ulps, or once half-way rounds to t_done; dir is the first span's step;
      // on the centred equations a piece's share of the distance to p matters, not its absolute width, so only the
      // second)
      const double end =
          ((dir > 0 ? p_near - half : half - p_near) <= ulps && !centred) || half == t_done ? p_near : half;
      const D T = dir > 0 ? D{t_done, end} : D{end, t_done};
      std::array<D, 3> W, K, W_rel, K_rel;
      const D T_rel = T - D{t_centre, t_centre}, t_done_rel = D{t_done, t_done} - D{t_centre, t_centre};
      // the tests of a piece: its zero curve proved unique in a box, and equal at t_done to the previous one's
      auto piece_proved = [&](const auto& equations, const D& T_, std::array<D, 3>& W_, std::array<D, 3>& K_,
                              const std::array<D, 3>& W_before, const D& t_join, double slack, double floor) {
        bool ok = predict_partner_box(equations, axis, T_, {W_before[0].mid(), W_before[1].mid(), W_before[2].mid()},
                                      W_, slack) &&
                  prove_zero_curve(equations, axis, T_, W_, K_, shrink >= 10, floor);
        std::array<D, 3> both;
        for (int c = 0; c < 3 && ok; ++c) {
          both[c] = D{std::max(W_before[c].lo, W_[c].lo), std::min(W_before[c].hi, W_[c].hi)};
          ok = both[c].lo <= both[c].hi;
        }
        return ok && parametric_partner_krawczyk(equations, axis, t_join, both);
      };
      bool ok = piece_proved(eq, T, W, K, W_prev, D{t_done, t_done}, 1e-13, 1e-15), on_centred = false;
      if (!ok && std::fabs(p_near - t_done) < centred_below) {
        const bool renew = centred.has_value();
        if (!centred) recentre();
        ok = piece_proved(*centred, T_rel, W_rel, K_rel, W_prev_rel, t_done_rel, 0, 0);
        if (!ok && renew) {  // a centre whose partner is the last proved piece's
          recentre();
          ok = piece_proved(*centred, T_rel, W_rel, K_rel, W_prev_rel, t_done_rel, 0, 0);
        }
        if (ok) {
          W = to_absolute_inside(W_rel);
          K = to_absolute(K_rel);
          on_centred = true;
        }
      }
      Partner_status st = ok ? status_from_partner(eq, domain, unbounded, axis, T, K, nullptr)
                             : Partner_status::undecided;
      if (st == Partner_status::undecided && ok && exact_end()) {
        std::array<D, 3> K_cell = K;
        K_cell[0] = D{std::max(K[0].lo, cell_other.lo), std::min(K[0].hi, cell_other.hi)};
        if (K_cell[0].lo <= K_cell[0].hi &&
            status_beside_exact_point(eq, domain, axis, T, K_cell, *exact_end()) == Partner_status::genuine)
          st = Partner_status::genuine;
      }
      if (st == Partner_status::undecided) {
        if (++shrink > 10) break;
        continue;
      }
      if (on_centred) {
        record_fibre_centred(T, T_rel, W_rel, K_rel, st);
        W_prev_rel = W_rel;
      } else {
        record_fibre(T, W, K, st);
      }
      W_prev = W;
      if (centred && !on_centred) rebase();
      t_done = end;
    }
    covered = (p_near - t_done) * dir > 0 ? std::fabs(t_done - tc.mid()) : full;
    if (record && covered == full) {  // (p's own box)
      const double t_p = e.polyline[idx[m - 1]][axis];
      record->spans.push_back({D{std::min(p_near, t_p), std::max(p_near, t_p)}, {}, -1});
    }
  }
  // the exclusion fallback, span by span from where the chain stopped towards p (the span reaching p, where the
  // point itself may be genuine, is not tried); the first span that fails ends it
  for (std::size_t j = 0; j + 2 < m; ++j) {
    const D a = t_at(j), b = t_at(j + 1);
    const D T{std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
    if ((dir > 0 ? T.hi : -T.lo) <= (dir > 0 ? t_done : -t_done)) continue;  // proved by the chain
    if (float_genuine[idx[j]] || float_genuine[idx[j + 1]]) break;
    if (!exclude_strips(eq, domain, axis, {T}, pc.cell, nullptr, budget)[0]) break;
    if (record)  // (no partner in the domain over the strip)
      record->spans.push_back({T, {}, 0, axis == 0 ? D::hull(pc.cell.v0, pc.cell.v1) : D::hull(pc.cell.u0, pc.cell.u1)});
    for (std::size_t k : {j, j + 1})
      if (out.point_status[idx[k]] == Partner_status::undecided) out.point_status[idx[k]] = Partner_status::phantom;
    covered = std::max(covered, std::fabs((dir > 0 ? T.hi : T.lo) - tc.mid()));
  }
  if (record) record->t_decided = tc.mid() + (dir > 0 ? covered : -covered);
  return std::max(0.0, 1 - covered / full);
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_LIFTING_CERTIFIED_LIFTING_H
