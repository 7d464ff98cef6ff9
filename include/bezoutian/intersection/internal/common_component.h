// The pieces of a curve C(x), x in [0,1], that lie in another parametrized object when C lies on that object's
// algebraic closure: two curves sharing a component (Curve_intersection.h, overlap_case: gcd of the F_k, du-1989
// ch. 4) or a curve on the implicit surface of a patch (Curve_surface_intersection.h, on_surface_case:
// det M(C(r)) = 0). The set of parameters x with C(x) in the object can change only at finitely many breakpoints
// (the ends of C and the parameters where C meets the image of the boundary of the object's domain); between two
// consecutive breakpoints it is decided at one rational point of the piece, and maximal runs of covered pieces are
// the overlaps. This header holds these shared steps: breakpoints sorted with equal parameters merged, the rational
// test point of a piece, the covered pieces and their maximal runs. The breakpoints themselves, the test of a
// point and the isolated touching points are particular to each caller.
//
// Internal header: not part of the public API.
#ifndef BEZOUTIAN_INTERSECTION_INTERNAL_COMMON_COMPONENT_H
#define BEZOUTIAN_INTERSECTION_INTERNAL_COMMON_COMPONENT_H

#include <bezoutian/algebraic/Algebraic_real.h>
#include <bezoutian/arithmetic/number_types.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace bezoutian {
namespace internal {

/// A breakpoint x on the curve with the known parameters of the other object at C(x) (Partner: one parameter for a
/// curve, a pair (u, v) for a patch).
template <class Partner>
struct Component_breakpoint {
  Algebraic_real x;
  std::vector<Partner> partners;
};

/// The breakpoints sorted by x, equal parameters merged (partner lists united, without repeats); covered[i] tells
/// whether the piece (breaks[i].x, breaks[i + 1].x) lies in the object; runs holds the maximal runs of covered
/// pieces as pairs (i, j): the pieces i .. j - 1 are covered, i.e. C([breaks[i].x, breaks[j].x]) is an overlap.
template <class Partner>
struct Common_component {
  std::vector<Component_breakpoint<Partner>> breaks;
  std::vector<char> covered;
  std::vector<std::pair<std::size_t, std::size_t>> runs;
};

/// A rational point inside the piece (a, b), a < b: the mean of rational ends, otherwise a rational number between.
inline Rational piece_midpoint(const Algebraic_real& a, const Algebraic_real& b) {
  return a.is_rational() && b.is_rational() ? (a.rational_value() + b.rational_value()) / 2 : a.rational_between(b);
}

/// The common component from the breakpoints `br`: covered_at(a, b) decides the piece (a, b), called once per
/// piece in increasing order.
template <class Partner, class Covered_at>
Common_component<Partner> common_component(std::vector<Component_breakpoint<Partner>> br, Covered_at covered_at) {
  using Break = Component_breakpoint<Partner>;
  Common_component<Partner> cc;
  std::sort(br.begin(), br.end(), [](const Break& x, const Break& y) { return x.x < y.x; });
  std::vector<Break>& ub = cc.breaks;  // merge equal parameters
  for (const Break& b : br) {
    if (!ub.empty() && ub.back().x == b.x) {
      for (const auto& t : b.partners)
        if (std::find(ub.back().partners.begin(), ub.back().partners.end(), t) == ub.back().partners.end())
          ub.back().partners.push_back(t);
    } else {
      ub.push_back(b);
    }
  }
  std::vector<char>& covered = cc.covered;
  covered.assign(ub.size() > 0 ? ub.size() - 1 : 0, 0);
  for (std::size_t i = 0; i + 1 < ub.size(); ++i) covered[i] = covered_at(ub[i].x, ub[i + 1].x);
  for (std::size_t i = 0; i < covered.size();) {
    if (!covered[i]) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < covered.size() && covered[j + 1]) ++j;
    cc.runs.push_back({i, j + 1});
    i = j + 1;
  }
  return cc;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERSECTION_INTERNAL_COMMON_COMPONENT_H
