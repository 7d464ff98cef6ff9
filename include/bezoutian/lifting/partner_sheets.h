// Complete lifting: every partner of every point of an arc of D = 0, and the proof that there are no others.
//
// A point x of D = 0 may have several partners y in the partner domain (buse-elkadi-galligo-2008 §4 follows one,
// the ratio of entries of one kernel vector of B). Along a whole arc this happens whenever two branches of the
// space curve share one projection: two cylinders crossing (z and -z over one (u, t)), a sphere cut by a plane
// ((x, y, z) and (x, -y, z)), two orthogonal extrusions. Each branch is a sheet: a partner y(x) followed
// continuously along the arc.
//
// Floating point finds the sheets: at every traced point all real partners (numerical_partners: the roots of a
// resultant of two partner equations, polished on all three), chained from point to point by nearest
// prediction. The proof is per span T of a graph piece (D = 0 a graph over the axis coordinate t in its cell):
//  1. each sheet's zero curve is proved unique and continuous in a box W_j over T, and to be the arc with a
//     partner (parametric Krawczyk and the anchor, partner_span_proofs.h: prove_zero_curve, zero_curve_anchored);
//     every zero of E(t, .) in W_j lies in its image K_j;
//  2. no point of T x V has a partner in the domain outside the union of the W_j (no_genuine_partner started from
//     a cover of the complement of the W_j's interiors), V the intersection of the K_j's ranges of the other
//     coordinate, which holds the arc points over T (each K_j does); where that test fails (along a tangential
//     contact, combined_equations_exclusion.h) the box's parts are tried one by one.
// A partner y of an arc point (t, g(t)), t in T, in the domain lies in some W_j by 2; (g(t), y) is then in W_j (by
// 1, g(t) is in K_j's range), so y is sheet j's partner by uniqueness: the sheets are every partner over T.
// A span without any sheet is proved empty by the strip exclusion (certified_lifting.h: exclude_strips). Where two
// sheets meet and end (a fold: the partners become complex beyond it) the spans next to the fold are decided in
// the fold chart, with the partner coordinate as parameter (partner_fold_proofs.h). What is not proved (a
// Jacobian too ill-conditioned, where two sheets cross; half-branches inside singular boxes) is counted in
// Edge_sheets::undecided_fraction, never guessed.
#ifndef BEZOUTIAN_LIFTING_PARTNER_SHEETS_H
#define BEZOUTIAN_LIFTING_PARTNER_SHEETS_H

#include <bezoutian/lifting/certified_lifting.h>
#include <bezoutian/lifting/double_partner_witness.h>
#include <bezoutian/lifting/internal/exact_point_spans.h>
#include <bezoutian/lifting/internal/half_branch_chains.h>
#include <bezoutian/lifting/internal/partner_fold_proofs.h>
#include <bezoutian/lifting/internal/partner_span_proofs.h>
#include <bezoutian/lifting/internal/seam_blowup_exclusion.h>
#include <bezoutian/topology/Curve_topology.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <vector>

namespace bezoutian {
namespace internal {

/// One branch of the space curve over an arc: a partner followed along consecutive polyline points.
struct Partner_sheet {
  std::size_t first = 0;                        ///< polyline index of its first point
  std::vector<std::array<double, 2>> partner;   ///< floating point, for polyline points first, first + 1, ...
  /// per point: a box proved to hold the partner of the exact arc point (NaN bounds where not proved)
  std::vector<std::array<Double_interval, 2>> enclosure;
  /// per point: the enclosure puts both patch points inside the partner domain (the point is genuine, proved)
  std::vector<char> genuine_proved;
  std::size_t last() const { return first + partner.size() - 1; }
};

/// The sheets of an edge and the share of it (by graph-coordinate length) whose fibre is not proved complete.
struct Edge_sheets {
  std::vector<Partner_sheet> sheets;
  double undecided_fraction = 1;
  /// the share whose genuine / phantom status this proof leaves open: a complete span is phantom without sheets,
  /// or with every sheet proved outside it, genuine with a sheet proved inside the domain over the whole span, else
  /// open
  double status_undecided_fraction = 1;
  /// per polyline point: proved to have no partner in the domain (phantom) by a fold proof (prove_piece_folds);
  /// floating-point sheet points there are not partners
  std::vector<char> phantom_proved;
};

/// Whether the partner y of the point x puts both patch points in `domain` widened by `margin` on every side.
inline bool partner_in_domain(const Partner_equations& eq, const Parameter_box& domain, bool unbounded,
                              const std::array<double, 2>& x, const std::array<double, 2>& y, double margin) {
  if (unbounded) return true;
  std::array<double, 2> P, Q;
  eq.points(std::array<double, 4>{x[0], x[1], y[0], y[1]}, P, Q);
  const double u0 = CGAL::to_double(domain.u0) - margin, u1 = CGAL::to_double(domain.u1) + margin,
               v0 = CGAL::to_double(domain.v0) - margin, v1 = CGAL::to_double(domain.v1) + margin;
  return u0 <= P[0] && P[0] <= u1 && v0 <= P[1] && P[1] <= v1 && u0 <= Q[0] && Q[0] <= u1 && v0 <= Q[1] && Q[1] <= v1;
}

/// The real partners of x with both patch points in the domain widened by a quarter of its size (the sheets are
/// followed a little beyond the domain, so that a sheet leaving it is one zero curve on both sides of the
/// boundary), floating point; `known` (the kernel's partner, if it solves the equations) is added if missing.
inline std::vector<std::array<double, 2>> fibre_partners(const Partner_equations& eq, const Parameter_box& domain,
                                                         bool unbounded, const std::array<double, 2>& x,
                                                         const std::array<double, 2>* known) {
  const double margin =
      unbounded ? 0 : 0.25 * std::max(CGAL::to_double(domain.u1 - domain.u0), CGAL::to_double(domain.v1 - domain.v0));
  std::vector<std::array<double, 2>> out;
  for (const auto& y : numerical_partners(eq, x)) {
    if (y[0].imag() != 0 || y[1].imag() != 0) continue;
    const std::array<double, 2> r{y[0].real(), y[1].real()};
    if (partner_in_domain(eq, domain, unbounded, x, r, margin)) out.push_back(r);
  }
  if (known && partner_in_domain(eq, domain, unbounded, x, *known, margin)) {
    bool seen = false;
    for (const auto& y : out) seen = seen || std::fabs(y[0] - (*known)[0]) + std::fabs(y[1] - (*known)[1]) < 1e-6;
    if (!seen) out.push_back(*known);
  }
  return out;
}

/// Chains the fibres of consecutive polyline points into sheets: each sheet ending at the previous point takes the
/// nearest unclaimed partner to its prediction (linear from its last two points), if nearer than a quarter plus
/// four times its last step; partners left over start new sheets. (Floating point: a wrong chain only makes its
/// span proofs fail.)
inline std::vector<Partner_sheet> chain_sheets(const std::vector<std::vector<std::array<double, 2>>>& fibres) {
  std::vector<Partner_sheet> sheets;
  std::vector<std::size_t> open;  // sheets ending at the previous point
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::array<Double_interval, 2> none{Double_interval{nan, nan}, Double_interval{nan, nan}};
  for (std::size_t i = 0; i < fibres.size(); ++i) {
    const auto& F = fibres[i];
    std::vector<bool> claimed(F.size(), false);
    struct Candidate {
      double cost;
      std::size_t sheet, partner;
    };
    std::vector<Candidate> cand;
    for (std::size_t s : open) {
      const Partner_sheet& S = sheets[s];
      const std::size_t n = S.partner.size();
      std::array<double, 2> p = S.partner[n - 1];
      double step = 0;
      if (n >= 2) {
        for (int c = 0; c < 2; ++c) {
          const double d = S.partner[n - 1][c] - S.partner[n - 2][c];
          p[c] += d;
          step += std::fabs(d);
        }
      }
      for (std::size_t k = 0; k < F.size(); ++k) {
        const double cost = std::fabs(F[k][0] - p[0]) + std::fabs(F[k][1] - p[1]);
        if (n == 1 || cost < 0.25 + 4 * step) cand.push_back({cost, s, k});
      }
    }
    std::sort(cand.begin(), cand.end(), [](const Candidate& a, const Candidate& b) { return a.cost < b.cost; });
    std::vector<std::size_t> next;
    std::vector<bool> continued(sheets.size(), false);
    for (const Candidate& c : cand) {
      if (claimed[c.partner] || continued[c.sheet]) continue;
      claimed[c.partner] = continued[c.sheet] = true;
      sheets[c.sheet].partner.push_back(F[c.partner]);
      sheets[c.sheet].enclosure.push_back(none);
      sheets[c.sheet].genuine_proved.push_back(0);
      next.push_back(c.sheet);
    }
    for (std::size_t k = 0; k < F.size(); ++k) {
      if (claimed[k]) continue;
      Partner_sheet S;
      S.first = i;
      S.partner.push_back(F[k]);
      S.enclosure.push_back(none);
      S.genuine_proved.push_back(0);
      next.push_back(sheets.size());
      sheets.push_back(std::move(S));
    }
    open = next;
  }
  // Where two sheets meet (their partners coincide at a traced point: the two branches of the space curve cross
  // there) the fibre holds the common partner once, so one sheet stops short of it or starts after it. A sheet is
  // extended by the neighbouring point's partner nearest to its prediction (the same tolerance as above); the
  // span proofs decide nothing there (two zero curves meet), but the sheets reach the crossing. Sheets of one point
  // that another sheet now reaches are dropped.
  auto extend = [&](Partner_sheet& S, bool at_start) {
    const std::size_t n = S.partner.size();
    const std::size_t i = at_start ? S.first : S.last();
    if (at_start ? i == 0 : i + 1 >= fibres.size()) return;
    const auto& F = fibres[at_start ? i - 1 : i + 1];
    std::array<double, 2> p = at_start ? S.partner[0] : S.partner[n - 1];
    double step = 0;
    if (n >= 2) {
      const auto& a = at_start ? S.partner[0] : S.partner[n - 1];
      const auto& b = at_start ? S.partner[1] : S.partner[n - 2];
      for (int c = 0; c < 2; ++c) p[c] += a[c] - b[c], step += std::fabs(a[c] - b[c]);
    }
    double best = 0.25 + 4 * step;
    std::size_t pick = F.size();
    for (std::size_t k = 0; k < F.size(); ++k) {
      const double cost = std::fabs(F[k][0] - p[0]) + std::fabs(F[k][1] - p[1]);
      if (cost < best) best = cost, pick = k;
    }
    if (pick == F.size()) return;
    if (at_start) {
      S.partner.insert(S.partner.begin(), F[pick]);
      S.enclosure.insert(S.enclosure.begin(), none);
      S.genuine_proved.insert(S.genuine_proved.begin(), 0);
      --S.first;
    } else {
      S.partner.push_back(F[pick]);
      S.enclosure.push_back(none);
      S.genuine_proved.push_back(0);
    }
  };
  const std::size_t count = sheets.size();
  for (std::size_t s = 0; s < count; ++s) {
    if (sheets[s].partner.size() < 2) continue;
    extend(sheets[s], true);
    extend(sheets[s], false);
  }
  std::vector<Partner_sheet> kept;
  for (Partner_sheet& S : sheets) {
    bool reached = false;
    if (S.partner.size() == 1)
      for (const Partner_sheet& R : sheets)
        if (R.partner.size() >= 2 && R.first <= S.first && S.first <= R.last()) {
          const auto& y = R.partner[S.first - R.first];
          reached = reached || std::fabs(y[0] - S.partner[0][0]) + std::fabs(y[1] - S.partner[0][1]) < 1e-6;
        }
    if (!reached) kept.push_back(std::move(S));
  }
  return kept;
}

/// The span proof of the header comment on T for the sheets `active` (with floating-point partners ya, yb at the
/// span's ends, and the other coordinate oa, ob there): true if every sheet's zero curve is proved over T and
/// every other partner in the domain is excluded; the sheets' partner enclosures over T go to `K`. `split_box`:
/// when the exclusion on the whole box T x V fails, its parts are tried (no_partner_in_region).
inline bool prove_complete_fibre(const Partner_equations& eq, const Parameter_box& domain, const Parameter_box& cell,
                                 int axis, const Double_interval& T, double oa, double ob,
                                 const std::vector<std::array<std::array<double, 2>, 2>>& ends,
                                 std::vector<std::array<Double_interval, 3>>& K, Exclusion_budget& budget,
                                 const Polynomial_2<Integer>* curve = nullptr, bool split_box = false) {
  using D = Double_interval;
  const double len = T.hi - T.lo;
  const double room = 0.5 * std::fabs(ob - oa) + 0.25 * len + 1e-12;
  const D V0{std::min(oa, ob) - room, std::max(oa, ob) + room};
  std::vector<std::array<D, 2>> holes;
  K.assign(ends.size(), std::array<D, 3>{});
  D V = V0;
  for (std::size_t j = 0; j < ends.size(); ++j) {
    const auto& y0 = ends[j][0];
    const auto& y1 = ends[j][1];
    std::array<D, 3> W{V0, D{}, D{}}, P;
    for (int c = 0; c < 2; ++c) {
      const double r = 0.5 * std::fabs(y1[c] - y0[c]) + 0.25 * len + 1e-9 * (1 + std::fabs(y0[c]));
      W[1 + c] = D{std::min(y0[c], y1[c]) - r, std::max(y0[c], y1[c]) + r};
    }
    const bool predicted = predict_partner_box(eq, axis, T, {0.5 * (oa + ob), 0.5 * (y0[0] + y1[0]), 0.5 * (y0[1] + y1[1])}, P);
    if (predicted) W = P;
    // A predicted box thin in one coordinate (a graph whose other coordinate hardly moves, e.g. a line u = c) may
    // be thinner than the operator's overestimation there: then a box of more even widths
    // (the inflation of the operator's image alone comes last: its box is the tightest, the worst hole)
    const std::array<D, 3> first = W;
    bool proved = prove_zero_curve(eq, axis, T, W, K[j], false);
    if (!proved && predicted) {
      double rmax = 0;
      for (int c = 0; c < 3; ++c) rmax = std::max(rmax, 0.5 * (P[c].hi - P[c].lo));
      for (int c = 0; c < 3; ++c) {
        const double m = P[c].mid(), r = std::max(2 * 0.5 * (P[c].hi - P[c].lo), 0.5 * rmax);
        W[c] = D{m - r, m + r};
      }
      proved = prove_zero_curve(eq, axis, T, W, K[j], false);
    }
    if (!proved) {
      W = first;
      proved = prove_zero_curve(eq, axis, T, W, K[j]);
    }
    if (!proved || !zero_curve_anchored(eq, axis, T, W, cell, curve)) return false;
    if (eq.self_intersection() && K[j][1].contains_zero() && K[j][2].contains_zero()) return false;
    const std::array<D, 3> hole = widened_unique_box(eq, axis, T, W);
    holes.push_back({hole[1], hole[2]});
    V = D{std::max(V.lo, K[j][0].lo), std::min(V.hi, K[j][0].hi)};
    if (!(V.lo <= V.hi)) return false;
  }
  if (ends.empty()) V = V0;
  if (!budget.take()) return false;
  const Parameter_box box = axis == 0 ? Parameter_box{Rational(T.lo), Rational(T.hi), Rational(V.lo), Rational(V.hi)}
                                      : Parameter_box{Rational(V.lo), Rational(V.hi), Rational(T.lo), Rational(T.hi)};
  const double big = 1e300;
  const std::vector<std::array<D, 2>> cover = complement_cover({D{-big, big}, D{-big, big}}, holes);
  if (no_genuine_partner(eq, box, domain, 1024, &cover)) return true;
  if (!split_box) return false;
  // along a tangential contact the gap that separates a point of T x V off the arc from having a partner shrinks
  // with its distance from the arc, and the test needs parts of the box about that small (down to 1/64 of it)
  std::size_t tests = 0;
  const double side = std::max(T.hi - T.lo, V.hi - V.lo);
  return no_partner_in_region(eq, domain, axis == 0 ? std::array<D, 2>{T, V} : std::array<D, 2>{V, T}, side / 64, tests,
                              48, budget, holes, &Exclusion_budget::take_box_split);
}

/// The folds of the graph piece `pc` of the edge `e` (partner_fold_proofs.h): two sheets whose partners come
/// together (to within 1e-3 of the domain's size) at a traced point f and are apart (16 times more) at a point
/// before it, on the side where they run longer. The proof starts from the nearest such point (then up to two
/// farther ones) and decides past f up to the first point where neither sheet is found (or the piece's end). What it
/// proves is entered per point (sheet points genuine with the fold's partner box, points with no partner
/// phantom) and per span (the undecided lengths are lowered to what the fold leaves open; the fold's own interval,
/// a few ulps wide, is the fold point's, as a split point's box is).
inline void prove_piece_folds(const Partner_equations& eq, const Parameter_box& domain, const Curve_topology_edge& e,
                              const Curve_topology_piece& pc, Edge_sheets& out, std::vector<double>& span_undecided,
                              std::vector<double>& span_open, Exclusion_budget& budget) {
  using D = Double_interval;
  const int axis = pc.graph_axis, other = 1 - axis;
  if (axis < 0) return;
  const double scale = std::max(CGAL::to_double(domain.u1 - domain.u0), CGAL::to_double(domain.v1 - domain.v0));
  auto coord = [&](std::size_t i, int c) {
    if (i == pc.first) return D{pc.first_box[2 * c], pc.first_box[2 * c + 1]};
    if (i == pc.last) return D{pc.last_box[2 * c], pc.last_box[2 * c + 1]};
    return D{e.polyline[i][c], e.polyline[i][c]};
  };
  auto present = [](const Partner_sheet& S, std::size_t i) { return S.first <= i && i <= S.last(); };
  for (std::size_t a = 0; a < out.sheets.size(); ++a)
    for (std::size_t b = a + 1; b < out.sheets.size(); ++b) {
      const Partner_sheet &Sa = out.sheets[a], &Sb = out.sheets[b];
      const std::size_t lo = std::max({Sa.first, Sb.first, pc.first}), hi = std::min({Sa.last(), Sb.last(), pc.last});
      if (lo >= hi) continue;
      auto dist = [&](std::size_t i) {
        const auto &ya = Sa.partner[i - Sa.first], &yb = Sb.partner[i - Sb.first];
        return std::fabs(ya[0] - yb[0]) + std::fabs(ya[1] - yb[1]);
      };
      // from a fold at f, in the direction dir (towards the side where the sheets are apart)
      auto decide_fold = [&](std::size_t f, long dir) {
        // the far side: up to the first point without either sheet, or the piece's end
        std::size_t far = f;
        while (far != (dir < 0 ? pc.last : pc.first) && (present(Sa, far) || present(Sb, far)))
          far = std::size_t(long(far) - dir);
        int attempts = 0;
        for (long i0 = long(f) + dir; i0 >= long(lo) && i0 <= long(hi) && attempts < 3; i0 += dir) {
          const std::size_t s = std::size_t(i0);
          if (dist(s) < 16 * dist(f) || dist(s) <= 1e-9 * scale) continue;
          ++attempts;
          const Fold_proof fp = prove_partner_fold(eq, domain, pc.cell, axis, coord(s, axis).mid(), coord(s, other).mid(),
                                                   Sa.partner[s - Sa.first], Sb.partner[s - Sb.first], coord(f, axis).mid(),
                                                   coord(far, axis).mid(), budget);
          if (!fp.proved) continue;
          auto within = [](const D& x, const D& r) { return r.lo <= x.lo && x.hi <= r.hi; };
          const std::size_t first = std::min(s, far), last = std::max(s, far);
          for (std::size_t i = first; i <= last; ++i) {
            const D t = coord(i, axis);
            if (within(t, fp.phantom)) out.phantom_proved[i] = 1;
            if (!within(t, fp.genuine)) continue;
            for (Partner_sheet* S : {&out.sheets[a], &out.sheets[b]})
              if (present(*S, i)) {
                S->enclosure[i - S->first] = fp.partners;
                S->genuine_proved[i - S->first] = 1;
              }
          }
          std::vector<D> decided{fp.genuine, fp.fold, fp.phantom};
          std::sort(decided.begin(), decided.end(), [](const D& x, const D& y) { return x.lo < y.lo; });
          auto uncovered = [&](const D& T) {  // the length of T outside the decided ranges (0 exactly if covered)
            double open = 0, at = T.lo;
            for (const D& r : decided) {
              if (!(r.lo <= r.hi)) continue;
              if (r.lo > at) open += std::min(r.lo, T.hi) - at;
              at = std::max(at, r.hi);
              if (at >= T.hi) return open;
            }
            return open + (T.hi - at);
          };
          for (std::size_t i = first; i < last; ++i) {
            const D ta = coord(i, axis), tb = coord(i + 1, axis);
            const D T{std::min(ta.lo, tb.lo), std::max(ta.hi, tb.hi)};
            const double open = uncovered(T);
            span_undecided[i] = std::min(span_undecided[i], open);
            span_open[i] = std::min(span_open[i], open);
          }
          break;
        }
      };
      // the closest approach of the two sheets, and the piece's ends where they meet (a fold at a corner of the
      // cell, where both coordinates of the arc are extreme: the sheets of two orthogonal extrusions meet at both
      // ends of the arc)
      std::size_t f = lo;
      for (std::size_t i = lo; i <= hi; ++i)
        if (dist(i) < dist(f)) f = i;
      if (!(dist(f) <= 1e-3 * scale)) continue;
      decide_fold(f, f - lo >= hi - f ? -1 : 1);
      for (const std::size_t end : {lo, hi})
        if (end != f && dist(end) <= 1e-3 * scale && dist(end) < dist(end == lo ? lo + 1 : hi - 1))
          decide_fold(end, end == lo ? 1 : -1);
    }
}

/// The traced points of a half-branch piece (among them those the refinement added) inside the proved spans of
/// its chain: phantom where the span has no partner in the domain; where it has one, the sheet whose partner lies
/// in the span's box Y is that partner, genuine (the chain proved its status from the image K_y of the span's zero
/// curve, inside the domain), with K_y as its enclosure.
inline void mark_half_branch_points(const Curve_topology_edge& e, const Curve_topology_piece& pc,
                                    const Half_branch_chain& chain, Edge_sheets& out) {
  for (std::size_t i = pc.first; i <= pc.last && i < e.polyline.size(); ++i) {
    const double t = e.polyline[i][std::size_t(chain.axis)];
    for (const Half_branch_span& sp : chain.spans) {
      if (sp.partners < 0 || !(sp.T.lo <= t && t <= sp.T.hi)) continue;
      if (sp.partners == 0) {
        out.phantom_proved[i] = 1;
        break;
      }
      for (Partner_sheet& S : out.sheets) {
        if (i < S.first || i > S.last()) continue;
        const std::array<double, 2>& y = S.partner[i - S.first];
        if (sp.Y[0].lo <= y[0] && y[0] <= sp.Y[0].hi && sp.Y[1].lo <= y[1] && y[1] <= sp.Y[1].hi) {
          S.genuine_proved[i - S.first] = 1;
          S.enclosure[i - S.first] = sp.partner;
        }
      }
      break;
    }
  }
}

/// The share of a half-branch piece (by its coordinate t) whose fibre the chain proved (half_branch_chains.h):
/// the spans with that proof whose traced points carry as many sheets in the domain as the span has partners
/// (one, following a partner in the span's box, or none).
inline double half_branch_fibre_share(const Partner_equations& eq, const Parameter_box& domain,
                                      const Curve_topology_edge& e, const Curve_topology_piece& pc,
                                      const Half_branch_chain& chain, const std::vector<Partner_sheet>& sheets) {
  const double full = std::fabs(chain.t_end - chain.t_crossing);
  if (!(full > 0)) return 0;
  const double lo = std::min(chain.t_crossing, chain.t_end), hi = std::max(chain.t_crossing, chain.t_end);
  double proved = 0;
  std::vector<Double_interval> done;  // the spans proved, to see whether they cover the piece without a gap
  for (const Half_branch_span& sp : chain.spans) {
    bool ok = sp.partners >= 0;
    if (sp.partners < 0) {
      proved += std::max(0.0, std::min(sp.T.hi, hi) - std::max(sp.T.lo, lo));
      done.push_back(sp.T);
    }
    for (std::size_t i = pc.first; i <= pc.last && ok; ++i) {
      const double t = e.polyline[i][chain.axis];
      if (t < sp.T.lo || t > sp.T.hi) continue;
      int count = 0;
      for (const Partner_sheet& S : sheets) {
        if (i < S.first || i > S.last()) continue;
        const auto& y = S.partner[i - S.first];
        if (!partner_in_domain(eq, domain, false, e.polyline[i], y, 1e-6)) continue;
        ++count;
        ok = ok && sp.partners == 1 && sp.Y[0].lo <= y[0] && y[0] <= sp.Y[0].hi && sp.Y[1].lo <= y[1] && y[1] <= sp.Y[1].hi;
      }
      ok = ok && count == sp.partners;
    }
    if (ok) {
      proved += std::max(0.0, std::min(sp.T.hi, hi) - std::max(sp.T.lo, lo));
      done.push_back(sp.T);
    }
  }
  std::sort(done.begin(), done.end(), [](const Double_interval& a, const Double_interval& b) { return a.lo < b.lo; });
  double reach = lo;
  for (const Double_interval& T : done)
    if (T.lo <= reach) reach = std::max(reach, T.hi);
  if (reach >= hi) return 1;
  return std::min(1.0, proved / full);
}

/// The polyline points k0..k1 of the piece `pc`, whose arc lies in the box X (the strip of a span, or the cell of a
/// half-branch), beside a shared boundary curve: when only_seam_zeros proves that every zero of the partner
/// equations over X with its partner in the domain lies on the seam, the fibre over them is complete. The points
/// off the seam's side have no partner in the domain (phantom); a point on the side has the seam's partner alone,
/// which the sheet there carries (given the seam's exact enclosure). Not tried when a sheet in the domain at a
/// point on the side is not the seam's partner. X's range of the seam's fixed coordinate is stretched to the side
/// when it stops short of it by at most its own width.
inline bool fibre_beside_seam(const Partner_equations& eq, const Parameter_box& domain, const Curve_topology_edge& e,
                              const Curve_topology_piece& pc, std::size_t k0, std::size_t k1, Parameter_box X,
                              const std::vector<Shared_seam>& seams, Edge_sheets& out, Exclusion_budget& budget) {
  using D = Double_interval;
  auto coord = [&](std::size_t k, int c) {
    if (k == pc.first) return D{pc.first_box[2 * c], pc.first_box[2 * c + 1]};
    if (k == pc.last) return D{pc.last_box[2 * c], pc.last_box[2 * c + 1]};
    return D{e.polyline[k][std::size_t(c)], e.polyline[k][std::size_t(c)]};
  };
  for (const Shared_seam& S : seams) {
    const D c = D::of(S.x_value), cy = D::of(S.y_value), g0 = D::of(S.g0), g1 = D::of(S.g1);
    const D ca = D::of(S.along_value);
    auto on_side = [&](std::size_t k) {  // (a corner: at the corner)
      const D x = coord(k, S.fixed_x), a = coord(k, S.along);
      return x.lo <= c.hi && c.lo <= x.hi && (!S.corner || (a.lo <= ca.hi && ca.lo <= a.hi));
    };
    auto seam_partner = [&](std::size_t k) {  // the seam's partner (v, s) of the point k on the side
      std::array<D, 2> y;
      y[std::size_t(S.fixed_y - 2)] = cy;
      y[std::size_t(S.dependent - 2)] = g0 + g1 * coord(k, S.along);
      return y;
    };
    // every sheet in the domain at an end on the side is the seam's partner (elsewhere the proof decides: a sheet
    // point there within rounding of the domain is not a partner in it when the proof succeeds)
    bool explained = true;
    for (const Partner_sheet& P : out.sheets)
      for (std::size_t k = k0; k <= k1; ++k) {
        if (k < P.first || k > P.last() || !explained || !on_side(k)) continue;
        const std::array<double, 2>& y = P.partner[k - P.first];
        if (!partner_in_domain(eq, domain, false, e.polyline[k], y, 1e-6)) continue;
        const std::array<D, 2> w = seam_partner(k);
        for (int j = 0; j < 2 && explained; ++j) explained = std::fabs(y[std::size_t(j)] - w[std::size_t(j)].mid()) <= 1e-6;
      }
    if (!explained) continue;
    // a point on the side is claimed only where it is exactly there with a sheet carrying the seam's partner (a
    // point whose box merely touches the side could have no partner in the domain at all)
    auto exactly_on_side = [&](std::size_t k) {
      const D x = coord(k, S.fixed_x), a = coord(k, S.along);
      return x.lo == x.hi && c.lo == c.hi && x.lo == c.lo && (!S.corner || (a.lo == a.hi && ca.lo == ca.hi && a.lo == ca.lo));
    };
    for (std::size_t k = k0; k <= k1 && explained; ++k) {
      if (!on_side(k)) continue;
      bool carried = false;
      for (const Partner_sheet& P : out.sheets)
        carried = carried || (k >= P.first && k <= P.last() &&
                              partner_in_domain(eq, domain, false, e.polyline[k], P.partner[k - P.first], 1e-6));
      explained = exactly_on_side(k) && carried;
    }
    if (!explained) continue;
    Parameter_box Y = X;
    Rational &x0 = S.fixed_x == 0 ? Y.u0 : Y.v0, &x1 = S.fixed_x == 0 ? Y.u1 : Y.v1;
    if (S.x_inward > 0 && S.x_value <= x0 && x0 - S.x_value <= x1 - x0) x0 = S.x_value;
    if (S.x_inward < 0 && x1 <= S.x_value && S.x_value - x1 <= x1 - x0) x1 = S.x_value;
    if (S.corner) {
      Rational &a0 = S.along == 0 ? Y.u0 : Y.v0, &a1 = S.along == 0 ? Y.u1 : Y.v1;
      if (S.along_inward > 0 && S.along_value <= a0 && a0 - S.along_value <= a1 - a0) a0 = S.along_value;
      if (S.along_inward < 0 && a1 <= S.along_value && S.along_value - a1 <= a1 - a0) a1 = S.along_value;
    }
    // (the points' boxes lie in Y: the proof speaks of them)
    bool within = true;
    for (std::size_t k = k0; k <= k1 && within; ++k) {
      const D u = coord(k, 0), t = coord(k, 1);
      within = D::of(Y.u0).lo <= u.lo && u.hi <= D::of(Y.u1).hi && D::of(Y.v0).lo <= t.lo && t.hi <= D::of(Y.v1).hi;
    }
    if (!within || !only_seam_zeros(eq, S, Y, budget)) continue;
    for (std::size_t k = k0; k <= k1; ++k) {
      if (!on_side(k)) {
        out.phantom_proved[k] = 1;
        continue;
      }
      const std::array<D, 2> w = seam_partner(k);
      // genuine where the point is exactly on the side (at the corner, as checked above) and the seam's partner
      // inside the domain
      const bool inside = D::of(domain.v0).lo <= w[0].lo &&
                          w[0].hi <= D::of(domain.v1).hi && D::of(domain.u0).lo <= w[1].lo && w[1].hi <= D::of(domain.u1).hi;
      for (Partner_sheet& P : out.sheets) {
        if (k < P.first || k > P.last() || P.genuine_proved[k - P.first]) continue;
        if (!partner_in_domain(eq, domain, false, e.polyline[k], P.partner[k - P.first], 1e-6)) continue;
        if (!inside) continue;  // (no enclosure claimed)
        P.enclosure[k - P.first] = w;
        P.genuine_proved[k - P.first] = 1;
      }
    }
    return true;
  }
  return false;
}

/// The span (polyline points i, i + 1 over T) of a graph piece beside a shared boundary curve: fibre_beside_seam on
/// the span's strip (T along the graph axis, the cell's range across).
inline bool span_beside_seam(const Partner_equations& eq, const Parameter_box& domain, const Curve_topology_edge& e,
                             const Curve_topology_piece& pc, std::size_t i, const Double_interval& T,
                             const std::vector<Shared_seam>& seams, Edge_sheets& out, Exclusion_budget& budget) {
  Parameter_box X = pc.cell;
  (pc.graph_axis == 0 ? X.u0 : X.v0) = Rational(T.lo);
  (pc.graph_axis == 0 ? X.u1 : X.v1) = Rational(T.hi);
  return fibre_beside_seam(eq, domain, e, pc, i, i + 1, X, seams, out, budget);
}

/// Every sheet of the edge `e` (fibres[i]: the partners of polyline point i, fibre_partners) and the proof that
/// they are every partner in the domain, span by span (the header comment; a span is halved up to three times
/// while unproved, up to six times while a sheet's enclosure reaches over the domain's side, and towards a certified
/// split point, whose graph intervals are `split_boxes`, while a sheet crosses the domain's side over it). Sheet points
/// outside the domain are kept (the caller reports the genuine runs). `split_span_boxes`: a span still unproved
/// after its last halving has its box's parts tried (prove_complete_fibre); worth it only when `fibres` hold every
/// partner, not when a missing one is the likely reason for the failure.
inline Edge_sheets complete_edge_lifting(const Partner_equations& eq, const Parameter_box& domain, bool unbounded,
                                         const Curve_topology_edge& e,
                                         const std::vector<std::vector<std::array<double, 2>>>& fibres,
                                         Exclusion_budget& budget,
                                         const std::vector<std::array<Double_interval, 2>>& split_boxes = {},
                                         const Half_branch_chains* chains = nullptr,
                                         const std::vector<std::array<Double_interval, 2>>& singular_boxes = {},
                                         const Polynomial_2<Integer>* curve = nullptr,
                                         const std::vector<Partner_boundary_point>& exact_points = {},
                                         bool split_span_boxes = false, const std::vector<Shared_seam>& seams = {}) {
  using D = Double_interval;
  Edge_sheets out;
  out.sheets = chain_sheets(fibres);
  const std::size_t n = e.polyline.size();
  out.phantom_proved.assign(n, 0);
  double total = 0, undecided = 0, status_open = 0;
  // the undecided lengths of the spans (polyline points i, i + 1) of the graph pieces: fibre and status
  std::vector<double> span_undecided(n, 0), span_open(n, 0);
  int deep_halvings_left = 256;
  for (const Curve_topology_piece& pc : e.pieces) {
    if (pc.last >= n || pc.first >= pc.last) continue;
    if (pc.graph_axis < 0 || unbounded) {  // a half-branch inside a singular box: the spans of its chain
      const double len = std::fabs(e.polyline[pc.last][0] - e.polyline[pc.first][0]) +
                         std::fabs(e.polyline[pc.last][1] - e.polyline[pc.first][1]);
      total += len;
      // beside a seam (an arc ending on a shared side at a singular point of D = 0): the cell holds no partner in
      // the domain but the seam's, which decides the fibre and the status of the whole piece
      if (!unbounded && !seams.empty() && fibre_beside_seam(eq, domain, e, pc, pc.first, pc.last, pc.cell, seams, out, budget))
        continue;
      status_open += len;  // (the status: certify_half_branch)
      const Half_branch_chain* chain = chains && !unbounded ? chains->find(pc) : nullptr;
      undecided += len * (1 - (chain ? half_branch_fibre_share(eq, domain, e, pc, *chain, out.sheets) : 0));
      if (chain) mark_half_branch_points(e, pc, *chain, out);
      continue;
    }
    const int axis = pc.graph_axis, other = 1 - axis;
    auto coord = [&](std::size_t i, int c) {
      if (i == pc.first) return D{pc.first_box[2 * c], pc.first_box[2 * c + 1]};
      if (i == pc.last) return D{pc.last_box[2 * c], pc.last_box[2 * c + 1]};
      return D{e.polyline[i][c], e.polyline[i][c]};
    };
    const D cell_other = axis == 0 ? D::hull(pc.cell.v0, pc.cell.v1) : D::hull(pc.cell.u0, pc.cell.u1);
    // the cell touches the cell of a half-branch of this edge (a singular point's box): see the halvings below
    bool beside_singular_cell = false;
    for (const Curve_topology_piece& other_piece : e.pieces)
      beside_singular_cell = beside_singular_cell ||
                             (other_piece.graph_axis < 0 && other_piece.cell.u0 <= pc.cell.u1 && pc.cell.u0 <= other_piece.cell.u1 &&
                              other_piece.cell.v0 <= pc.cell.v1 && pc.cell.v0 <= other_piece.cell.v1);
    const int halvings = split_span_boxes && beside_singular_cell ? 5 : 3;
    for (std::size_t i = pc.first; i < pc.last; ++i) {
      const D a = coord(i, axis), b = coord(i + 1, axis);
      const D T{std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
      total += T.hi - T.lo;
      // the sheets over the span: those at both of its ends; a sheet at one end only makes it unprovable
      std::vector<std::size_t> active;
      bool broken = false;
      for (std::size_t s = 0; s < out.sheets.size(); ++s) {
        const Partner_sheet& S = out.sheets[s];
        const bool at_a = S.first <= i && i <= S.last(), at_b = S.first <= i + 1 && i + 1 <= S.last();
        // (a sheet outside the domain wherever it is known needs no hole: the exclusion covers the domain only)
        const bool relevant = (at_a && partner_in_domain(eq, domain, unbounded, e.polyline[i], S.partner[i - S.first], 1e-6)) ||
                              (at_b && partner_in_domain(eq, domain, unbounded, e.polyline[i + 1], S.partner[i + 1 - S.first], 1e-6));
        if (!relevant) continue;
        if (at_a && at_b) active.push_back(s);
        else broken = true;
      }
      // next to a seam: every partner in the domain over the span's strip may be the seam's (seam_blowup_exclusion.h)
      auto beside_seam = [&] { return !seams.empty() && span_beside_seam(eq, domain, e, pc, i, T, seams, out, budget); };
      if (broken) {
        if (beside_seam()) continue;
        span_undecided[i] += T.hi - T.lo;
        span_open[i] += T.hi - T.lo;
        continue;
      }
      if (active.empty()) {  // no partner at either end: the strip of the cell over T holds none either
        if (!exclude_strips(eq, domain, axis, {T}, pc.cell, nullptr, budget)[0] && !beside_seam()) {
          span_undecided[i] += T.hi - T.lo;
          span_open[i] += T.hi - T.lo;
        }
        continue;
      }
      const double oa = e.polyline[i][other], ob = e.polyline[i + 1][other];
      const bool increasing = a.mid() <= b.mid();
      std::vector<const Partner_boundary_point*> span_exact_points;  // in the cell, over the span
      for (const Partner_boundary_point& x : exact_points) {
        const D tx = D::of(x.x[std::size_t(axis)]);
        if (T.lo <= tx.hi && tx.lo <= T.hi && pc.cell.u0 <= x.x[0] && x.x[0] <= pc.cell.u1 && pc.cell.v0 <= x.x[1] &&
            x.x[1] <= pc.cell.v1)
          span_exact_points.push_back(&x);
      }
      struct Span {
        double f0, f1;  // the span's part, as fractions from point i to point i + 1
        int depth;
      };
      std::vector<Span> todo{{0, 1, 0}};
      bool ends_done[2] = {false, false};
      while (!todo.empty()) {
        budget.poll();
        const Span sp = todo.back();
        todo.pop_back();
        auto at = [&](double f, double x0, double x1) { return x0 + f * (x1 - x0); };
        const double t0 = at(sp.f0, a.mid(), b.mid()), t1 = at(sp.f1, a.mid(), b.mid());
        D Ts{std::min(t0, t1), std::max(t0, t1)};
        if (sp.f0 == 0) Ts = increasing ? D{std::min(a.lo, Ts.lo), Ts.hi} : D{Ts.lo, std::max(a.hi, Ts.hi)};
        if (sp.f1 == 1) Ts = increasing ? D{Ts.lo, std::max(b.hi, Ts.hi)} : D{std::min(b.lo, Ts.lo), Ts.hi};
        std::vector<std::array<std::array<double, 2>, 2>> ends;
        for (std::size_t s : active) {
          const Partner_sheet& S = out.sheets[s];
          const auto& ya = S.partner[i - S.first];
          const auto& yb = S.partner[i + 1 - S.first];
          ends.push_back({std::array<double, 2>{at(sp.f0, ya[0], yb[0]), at(sp.f0, ya[1], yb[1])},
                          std::array<double, 2>{at(sp.f1, ya[0], yb[0]), at(sp.f1, ya[1], yb[1])}});
        }
        // (the parts of the span's box are tried once, on the last halving, away from the points whose boxes end
        // the halving: next to them a failure is expected)
        bool near_point = false;
        for (const auto* boxes : {&singular_boxes, &split_boxes})
          for (const auto& g : *boxes) near_point = near_point || (Ts.lo <= g[axis].hi && g[axis].lo <= Ts.hi);
        std::vector<std::array<D, 3>> K;
        if (prove_complete_fibre(eq, domain, pc.cell, axis, Ts, at(sp.f0, oa, ob), at(sp.f1, oa, ob), ends, K, budget, curve,
                                 split_span_boxes && sp.depth == 3 && !near_point)) {
          // (the arc points over Ts lie in the cell: their other coordinate in K_j's range and the cell's)
          for (auto& k : K) k[0] = D{std::max(k[0].lo, cell_other.lo), std::min(k[0].hi, cell_other.hi)};
          // every partner in the domain is in some K_j: genuine if one K_j lies inside the domain, phantom if every
          // K_j lies outside it (then no partner is in the domain), else open
          std::vector<Partner_status> status;
          for (const auto& k : K) status.push_back(status_from_partner(eq, domain, false, axis, Ts, k, nullptr, true));
          auto decided = [&](bool& genuine, bool& outside) {
            genuine = false, outside = true;
            for (const Partner_status st : status) {
              genuine = genuine || st == Partner_status::genuine;
              outside = outside && st == Partner_status::outside;
            }
          };
          bool genuine, outside;
          decided(genuine, outside);
          // next to an exact point with its partner on the domain's boundary, by monotonicity (exact_point_spans.h)
          // (every sheet is tried, also once another decides the span: each sheet is a branch of the space curve)
          for (const Partner_boundary_point* x : span_exact_points) {
            for (std::size_t j = 0; j < K.size(); ++j)
              if (status[j] == Partner_status::undecided) {
                const Partner_status st = status_beside_exact_point(eq, domain, axis, Ts, K[j], *x);
                if (st != Partner_status::undecided) status[j] = st;
              }
            decided(genuine, outside);
          }
          if (!genuine && !outside) {
            // a sheet crosses the domain's side over Ts, or its enclosure reaches over it: halved up to six times,
            // and at a certified split point until the open part lies inside the split's box (the split point's own),
            // widened by 8 ulps: the halving's last pieces round to a few ulps beside the box, as the descent's pieces
            // do beside a singular point's box (certified_lifting.h), and are not counted either
            bool inside_split = false, meets_split = false;
            for (const auto& g : split_boxes) {
              const double ulps = 8 * std::numeric_limits<double>::epsilon() * (std::fabs(g[axis].lo) + std::fabs(g[axis].hi));
              inside_split = inside_split || (g[axis].lo - ulps <= Ts.lo && Ts.hi <= g[axis].hi + ulps);
              meets_split = meets_split || (Ts.lo <= g[axis].hi && g[axis].lo <= Ts.hi);
            }
            const double m = 0.5 * (sp.f0 + sp.f1);
            if (!inside_split && sp.depth < (meets_split ? 64 : 6) && sp.f0 < m && m < sp.f1) {
              todo.push_back({m, sp.f1, sp.depth + 1});
              todo.push_back({sp.f0, m, sp.depth + 1});
              continue;  // (the halves give the end points' enclosures)
            } else if (!inside_split) {
              span_open[i] += std::fabs(t1 - t0);
            }
          }
          for (int end = 0; end < 2; ++end) {  // the enclosures at the polyline points the part reaches
            if ((end == 0 ? sp.f0 : sp.f1) != end || ends_done[end]) continue;
            ends_done[end] = true;
            const std::size_t point = end == 0 ? i : i + 1;
            for (std::size_t j = 0; j < active.size(); ++j) {
              Partner_sheet& S = out.sheets[active[j]];
              const std::size_t k = point - S.first;
              // the point may be an exact point e with its partner on the boundary (the span's end inside e's box):
              // K_j holds e, so the sheet's zero there, unique in K_j's box, is e, in the closed domain
              bool at_exact = false;
              for (const Partner_boundary_point* x : span_exact_points) {
                const std::array<Rational, 3> w{x->x[std::size_t(other)], x->y[0], x->y[1]};
                bool in = Rational(e.polyline[point][0]) == x->x[0] && Rational(e.polyline[point][1]) == x->x[1];
                for (int c = 0; c < 3 && in; ++c) in = Rational(K[j][c].lo) <= w[std::size_t(c)] && w[std::size_t(c)] <= Rational(K[j][c].hi);
                if (in) {
                  at_exact = true;
                  S.enclosure[k] = {D::of(x->y[0]), D::of(x->y[1])};
                  S.genuine_proved[k] = 1;
                }
              }
              if (at_exact || (S.genuine_proved[k] && status[j] != Partner_status::genuine)) continue;  // (proved already)
              S.enclosure[k] = {K[j][1], K[j][2]};
              S.genuine_proved[k] = status[j] == Partner_status::genuine;
            }
          }
          continue;
        }
        // a span that reaches a singular point of D = 0 (where both branches meet and the Jacobian of the span
        // proof is singular) is halved towards it: the halves away from it have about the conditioning of the
        // first, so they are proved down to the point's own certified box, which is not counted; so is the box of an
        // exact point with its partner on the domain's boundary (a split box of a few ulps)
        bool inside_point = false, meets_point = false;
        for (const auto* boxes : {&singular_boxes, &split_boxes})
          for (const auto& g : *boxes) {
            const bool inside = g[axis].lo <= Ts.lo && Ts.hi <= g[axis].hi;
            inside_point = inside_point || (inside && (boxes == &singular_boxes || g[axis].hi - g[axis].lo <= 1e-12));
            meets_point = meets_point || (boxes == &singular_boxes && Ts.lo <= g[axis].hi && g[axis].lo <= Ts.hi);
          }
        if (inside_point) continue;
        const double m = 0.5 * (sp.f0 + sp.f1);
        // (at most 256 halvings beyond the third per edge: next to a point where the arc comes within rounding of
        // the cell's side, as at a tangency with it, the anchor of every half fails from some depth on; in the pass
        // with every partner and in a cell beside a singular point's box, five halvings: there the other branch
        // passes through a span's box with its partners outside the span's hole, and shorter spans have boxes it
        // misses. Viviani's arcs traced at the default tolerance 1e-3: fibre open on 1.4 % of an arc with three,
        // 0 with five)
        const bool deeper = sp.depth < halvings || (meets_point && sp.depth < 64 && deep_halvings_left > 0);
        if (deeper && sp.f0 < m && m < sp.f1) {
          if (sp.depth >= 3) --deep_halvings_left;
          todo.push_back({m, sp.f1, sp.depth + 1});
          todo.push_back({sp.f0, m, sp.depth + 1});
          continue;
        }
        span_undecided[i] += std::fabs(t1 - t0);
        span_open[i] += std::fabs(t1 - t0);
      }
      // the parts left open may lie beside a seam, where the proofs above cannot succeed
      if ((span_undecided[i] > 0 || span_open[i] > 0) && beside_seam()) span_undecided[i] = span_open[i] = 0;
    }
    prove_piece_folds(eq, domain, e, pc, out, span_undecided, span_open, budget);
  }
  for (std::size_t i = 0; i < n; ++i) undecided += span_undecided[i], status_open += span_open[i];
  out.undecided_fraction = total > 0 ? std::min(1.0, undecided / total) : 1;
  out.status_undecided_fraction = total > 0 ? std::min(1.0, status_open / total) : 1;
  return out;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_LIFTING_PARTNER_SHEETS_H
