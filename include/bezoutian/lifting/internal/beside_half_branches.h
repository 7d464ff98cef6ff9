// Half-branches of a singular box proved phantom beside the proved spans of the other half-branches there.
//
// Two half-branches H, H' of one singular box meet only at its singular point p (the topology's certificate).
// The chain of H' (certify_half_branch) records, for each of its proved spans T', a region T' x O' of the cell
// that holds H' over T' and in which every point with a partner in the domain lies on H' (half_branch_chains.h:
// the fibre exclusion over T' x K_other, or a region with no partner at all). A point of H other than p that lies
// in such a region is not on H', so it has no partner in the domain. The rest of H's strip over a span T,
// (T x the cell's other range) minus those regions, is covered by boxes with no partner in the domain
// (no_genuine_partner, the boxes halved while they fail); then every point of H over T is phantom.
//
// This is what a phantom half-branch needs when a genuine one runs through the same strip: there the exclusion of
// the whole strip (certify_half_branch's fallback) must fail, and a chain of Krawczyk boxes along the phantom
// branch has no real partner to follow (its partner is complex or at infinity). Example: the torus and its
// bitangent plane with both patches' parameters exchanged, where a phantom arc and a Villarceau arc end at one
// corner of the box.
#ifndef BEZOUTIAN_LIFTING_INTERNAL_BESIDE_HALF_BRANCHES_H
#define BEZOUTIAN_LIFTING_INTERNAL_BESIDE_HALF_BRANCHES_H

#include <bezoutian/arithmetic/double_interval.h>
#include <bezoutian/lifting/double_partner_witness.h>
#include <bezoutian/lifting/internal/half_branch_chains.h>
#include <bezoutian/lifting/internal/partner_span_proofs.h>
#include <bezoutian/topology/Curve_topology.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace bezoutian {
namespace internal {

/// A closed box of the cell: its u range and its v range.
using Cell_region = std::array<Double_interval, 2>;

/// Closed boxes covering the part of `from` outside the interior of r (at most four per box).
inline std::vector<Cell_region> subtract_region(const std::vector<Cell_region>& from, const Cell_region& r) {
  using D = Double_interval;
  std::vector<Cell_region> out;
  for (const Cell_region& a : from) {
    if (!(r[0].lo < a[0].hi && a[0].lo < r[0].hi && r[1].lo < a[1].hi && a[1].lo < r[1].hi)) {
      out.push_back(a);  // interiors disjoint
      continue;
    }
    if (a[0].lo < r[0].lo) out.push_back({D{a[0].lo, r[0].lo}, a[1]});
    if (r[0].hi < a[0].hi) out.push_back({D{r[0].hi, a[0].hi}, a[1]});
    const D mid{std::max(a[0].lo, r[0].lo), std::min(a[0].hi, r[0].hi)};
    if (a[1].lo < r[1].lo) out.push_back({mid, D{a[1].lo, r[1].lo}});
    if (r[1].hi < a[1].hi) out.push_back({mid, D{r[1].hi, a[1].hi}});
  }
  return out;
}

/// The regions of the other chains of pc's cell (see the header comment), in (u, v).
inline std::vector<Cell_region> regions_beside(const Half_branch_chains& chains, const Curve_topology_piece& pc) {
  std::vector<Cell_region> regions;
  for (const Half_branch_chain* c : chains.beside(pc))
    for (const Half_branch_span& s : c->spans)
      if (s.partners >= 0 && s.other.lo <= s.other.hi)
        regions.push_back(c->axis == 0 ? Cell_region{s.T, s.other} : Cell_region{s.other, s.T});
  return regions;
}

/// The fibre of the spans of pc's chain whose own exclusion failed (Half_branch_open_fibre), proved beside the
/// other half-branches: a point x of pc's branch H over T has its partners in the domain inside the hole's box if
/// no point of (T x K_other) minus the other chains' regions has one outside it, because x is in no such region
/// (a point there with a partner in the domain lies on the other branch, which meets H only at p; and a point of
/// H over a genuine span has one). Next to a node, where the two branches pass close by, the other branch's
/// points in T x K_other have their partners outside the hole, and the exclusion over the whole box must fail.
/// The spans proved this way are recorded without a region of their own.
inline void prove_fibres_beside_half_branches(const Partner_equations& eq, const Parameter_box& domain,
                                              const Curve_topology_piece& pc, Half_branch_chains& chains,
                                              Exclusion_budget& budget) {
  Half_branch_chain* chain = chains.find(pc);
  if (!chain || chain->open_fibres.empty()) return;
  const std::vector<Cell_region> regions = regions_beside(chains, pc);
  if (regions.empty()) return;
  std::vector<Half_branch_open_fibre> still_open;
  for (const Half_branch_open_fibre& f : chain->open_fibres) {
    std::vector<Cell_region> rest{chain->axis == 0 ? Cell_region{f.T, f.other} : Cell_region{f.other, f.T}};
    for (const Cell_region& r : regions) rest = subtract_region(rest, r);
    const double min_side = std::min(f.T.hi - f.T.lo, f.other.hi - f.other.lo) / 64;
    std::size_t tests = 0;
    bool proved = true;
    for (const Cell_region& b : rest)
      if (!(proved = no_partner_in_region(eq, domain, b, min_side, tests, 64, budget, {f.hole}))) break;
    if (proved)
      chain->spans.push_back({f.T, f.hole, f.partners, {std::numeric_limits<double>::quiet_NaN(),
                                                        std::numeric_limits<double>::quiet_NaN()}, f.partner});
    else
      still_open.push_back(f);
  }
  chain->open_fibres = std::move(still_open);
}

/// Continues the proof of a half-branch piece pc beyond the stretch its own chain decided (from its crossing to
/// `t_decided`), span by span towards p as certify_half_branch does, by the exclusion beside the other chains of
/// its cell (see the header comment). The points proved phantom get that status in `status`, the spans are
/// recorded in pc's chain (no partner in the domain: the fibre is empty there). Returns the share of the piece
/// (along its coordinate t) newly decided; the first span that fails ends it.
inline double prove_beside_half_branches(const Partner_equations& eq, const Parameter_box& domain,
                                         const Curve_topology_edge& e, const Curve_topology_piece& pc,
                                         const std::vector<bool>& float_genuine, Half_branch_chains& chains,
                                         Exclusion_budget& budget, std::vector<Partner_status>& status) {
  using D = Double_interval;
  Half_branch_chain* chain = chains.find(pc);
  if (!chain || pc.singular_end < 0 || pc.last >= e.polyline.size() || pc.first >= pc.last) return 0;
  const std::vector<Cell_region> regions = regions_beside(chains, pc);
  if (regions.empty()) return 0;
  const int axis = chain->axis;
  std::vector<std::size_t> idx;  // from the crossing to the singular point
  for (std::size_t i = pc.first; i <= pc.last; ++i) idx.push_back(i);
  if (pc.singular_end == 0) std::reverse(idx.begin(), idx.end());
  const std::size_t m = idx.size();
  const double t_c = chain->t_crossing, t_p = chain->t_end, full = std::fabs(t_p - t_c);
  if (m < 3 || !(full > 0)) return 0;
  const double dir = t_p > t_c ? 1 : -1;
  double t_done = chain->t_decided;
  const double start = t_done;
  const D cell_other = axis == 0 ? D::hull(pc.cell.v0, pc.cell.v1) : D::hull(pc.cell.u0, pc.cell.u1);
  // the strip over T minus the other chains' regions, covered by boxes with no partner in the domain (at most
  // 64 tests, boxes down to a 64th of the span or of the cell's other range)
  auto excluded = [&](const D& T) {
    std::vector<Cell_region> rest{axis == 0 ? Cell_region{T, cell_other} : Cell_region{cell_other, T}};
    for (const Cell_region& r : regions) rest = subtract_region(rest, r);
    const double min_side = std::min(T.hi - T.lo, cell_other.hi - cell_other.lo) / 1024;
    std::size_t tests = 0;
    for (const Cell_region& b : rest)
      if (!no_partner_in_region(eq, domain, b, min_side, tests, 256, budget)) return false;
    return true;
  };
  auto record = [&](const D& T) { chain->spans.push_back({T, {}, 0}); };
  auto finish = [&] {
    chain->t_decided = t_done;
    return (t_done - start) * dir / full;
  };
  auto t_at = [&](std::size_t j) { return e.polyline[idx[j]][axis]; };
  // the traced spans up to the one reaching p
  for (std::size_t j = 0; j + 2 < m; ++j) {
    const double a = t_at(j), b = t_at(j + 1);
    if ((b - t_done) * dir <= 0) continue;           // decided already
    if ((a - t_done) * dir > 0) return finish();  // (not contiguous)
    if (float_genuine[idx[j]] || float_genuine[idx[j + 1]]) return finish();
    const D T = dir > 0 ? D{t_done, b} : D{b, t_done};
    if (!excluded(T)) return finish();
    record(T);
    for (std::size_t k : {j, j + 1})
      if (status[idx[k]] == Partner_status::undecided) status[idx[k]] = Partner_status::phantom;
    t_done = b;
  }
  // the span reaching p: pieces of a fixed share of the distance left, down to p's certified box (widened by a
  // few ulps; p is the vertex, with its own certificate), as the chain descends. The other chains end 8 ulps from
  // p in their own coordinate, and their branches run on into p without a region there: this descent stops 64
  // ulps from p's box, and that sliver is not counted, as p's box is not.
  const auto& p_box = pc.singular_end == 0 ? pc.first_box : pc.last_box;
  const double ulps = 64 * std::numeric_limits<double>::epsilon() * (1 + std::fabs(t_c));
  const double p_near = dir > 0 ? p_box[2 * axis] - ulps : p_box[2 * axis + 1] + ulps;
  if (t_done != t_at(m - 2) || float_genuine[idx[m - 2]]) return finish();
  int shrink = 0;
  for (int step = 0; step < 200 && (p_near - t_done) * dir > 0; ++step) {
    budget.poll();
    const double half = t_done + std::ldexp(p_near - t_done, -1 - shrink);
    // (the whole rest once it is a few ulps, or once half-way rounds to t_done)
    const double end = (p_near - half) * dir <= ulps || half == t_done ? p_near : half;
    const D T = dir > 0 ? D{t_done, end} : D{end, t_done};
    if (!excluded(T)) {
      if (++shrink > 6) break;
      continue;
    }
    record(T);
    t_done = end;
  }
  if ((p_near - t_done) * dir > 0) return finish();
  chain->spans.push_back({D{std::min(p_near, t_p), std::max(p_near, t_p)}, {}, -1});  // (p's own box)
  t_done = t_p;
  return finish();
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_LIFTING_INTERNAL_BESIDE_HALF_BRANCHES_H
