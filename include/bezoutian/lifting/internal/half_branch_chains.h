// The fibre over the half-branches of singular boxes (and the other pieces of D = 0 that are not proved graphs:
// two-branch and fold cells), from the chained proof of their status (certified_lifting.h, certify_half_branch).
//
// The chain proves, span by span along the coordinate t normal to the crossing's edge, a zero curve
// gamma(t) = (x_other(t), y(t)) of the three partner equations, unique in a box W over T and equal to the
// half-branch H over T; its image K encloses gamma(T), so H over T lies in the box T x K_other. If moreover no
// point of T x K_other has a partner in the domain outside W_y (no_genuine_partner started from the cover of the
// partner range minus W_y's interior), then every partner in the domain of a point x of H over T lies in W_y, so
// (x_other, y) is a zero in W, which is gamma(t): x has at most one partner in the domain, gamma_y(t), and a
// sheet that follows it is the whole fibre there. A span the chain proves phantom by excluding the whole strip
// of the cell has no partner in the domain at all: its fibre is empty. The complete lifting (partner_sheets.h)
// counts a span's fibre proved when it is one of these and its traced points carry that many sheets.
#ifndef BEZOUTIAN_LIFTING_INTERNAL_HALF_BRANCH_CHAINS_H
#define BEZOUTIAN_LIFTING_INTERNAL_HALF_BRANCH_CHAINS_H

#include <bezoutian/arithmetic/double_interval.h>
#include <bezoutian/topology/Curve_topology.h>

#include <array>
#include <cstddef>
#include <deque>
#include <limits>
#include <vector>

namespace bezoutian {
namespace internal {

/// A span of a half-branch whose fibre is proved (see the header comment).
struct Half_branch_span {
  Double_interval T;                 ///< the span of the coordinate t
  std::array<Double_interval, 2> Y;  ///< the box holding the only partner in the domain (if `partners` is 1)
  /// the number of partners in the domain of each point of H over T: 0 or 1; -1: T is the singular point's own
  /// certified box (widened by a few ulps), not counted as undecided
  int partners = 0;
  /// a range O of the other coordinate such that H over T lies in the region T x O and every point of that
  /// region with a partner in the domain lies on H (the fibre exclusion over T x K_other, or a strip with no
  /// partner at all); empty (NaN) where the span claims nothing about other points (beside_half_branches.h)
  Double_interval other{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  /// (`partners` 1) the image K_y of the zero curve's partner over T: inside the domain (the genuine status)
  std::array<Double_interval, 2> partner;
};

/// A span whose status the chain proved but whose fibre exclusion failed (on T x K_other, outside the hole): tried
/// again beside the other half-branches of the cell (beside_half_branches.h).
struct Half_branch_open_fibre {
  Double_interval T, other;                       ///< the span and K_other
  std::array<Double_interval, 2> hole, partner;   ///< the hole's partner box and K_y
  int partners = 0;                               ///< 1 (genuine) or 0 (phantom)
};

/// The proved spans of one half-branch piece.
struct Half_branch_chain {
  Parameter_box cell, crossing;  ///< the piece's cell and the crossing it starts from (identify the piece)
  int axis = 0;                  ///< t is the coordinate axis (0: u, 1: the other)
  double t_crossing = 0, t_end = 0;  ///< t at the crossing and at the far end (the singular or fold point)
  double t_decided = 0;  ///< the statuses are proved on the stretch from t_crossing to t_decided
  std::vector<Half_branch_span> spans;
  std::vector<Half_branch_open_fibre> open_fibres;
};

/// The chains of one locus, filled by the status proof and read by the complete lifting. Their exclusions have a
/// budget of their own, so that they never take one from the status proofs.
class Half_branch_chains {
 public:
  explicit Half_branch_chains(std::size_t exclusions) : exclusions_left_(exclusions) {}
  bool take_exclusion() {
    if (exclusions_left_ == 0) return false;
    --exclusions_left_;
    return true;
  }
  Half_branch_chain& add(const Curve_topology_piece& pc) {
    chains_.push_back(Half_branch_chain{});
    chains_.back().cell = pc.cell;
    chains_.back().crossing = pc.crossing;
    return chains_.back();
  }
  const Half_branch_chain* find(const Curve_topology_piece& pc) const {
    for (const Half_branch_chain& c : chains_)
      if (same(c.cell, pc.cell) && same(c.crossing, pc.crossing)) return &c;
    return nullptr;
  }
  Half_branch_chain* find(const Curve_topology_piece& pc) {
    return const_cast<Half_branch_chain*>(static_cast<const Half_branch_chains*>(this)->find(pc));
  }
  /// the chains of the other half-branches of pc's cell
  std::vector<const Half_branch_chain*> beside(const Curve_topology_piece& pc) const {
    std::vector<const Half_branch_chain*> out;
    for (const Half_branch_chain& c : chains_)
      if (same(c.cell, pc.cell) && !same(c.crossing, pc.crossing)) out.push_back(&c);
    return out;
  }

 private:
  static bool same(const Parameter_box& a, const Parameter_box& b) {
    return a.u0 == b.u0 && a.u1 == b.u1 && a.v0 == b.v0 && a.v1 == b.v1;
  }
  std::size_t exclusions_left_;
  std::deque<Half_branch_chain> chains_;  // (references stay valid)
};

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_LIFTING_INTERNAL_HALF_BRANCH_CHAINS_H
