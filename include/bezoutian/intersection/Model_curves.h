// Model-level curves: the branches of the intersection and self-intersection curves of a model, found problem by
// problem by intersect_model, joined where they continue from one patch (or pair of patches) to the next.
//
// A branch of the curve of a pair of patches (a Locus_sheet: one partner followed along an arc of D = 0) ends where
// the curve leaves one of the two patches through its boundary (an arc end on a side of the box, a split point where
// the partner reaches the side of its domain), at a singular point of D = 0 (a vertex of the topology where
// branches cross), or at a pinch point. Where it leaves a patch across a seam of the model the curve goes on in
// the neighbouring patch, so in another problem of the model whose branch starts at the same point of space. Such
// ends are joined: each branch end is linked to the one other branch end within `tolerance` of it in space, when
// that end is also the only one within `isolation` of it (no second candidate, as at a crossing of branches or
// where two problems report one piece of curve lying along a seam, where the chain stops instead). A chain whose
// last link returns to its first piece is closed.
//
// What is proved and what is not. Each piece is a branch of its problem's locus, certified as that locus is
// (locus_certified: every point's status, every fibre, so every branch of the curve over the problem's domains is
// among the pieces). The links are found in floating point from the traced end points; `Model_curve::largest_gap`
// says how far apart the linked ends were. A link is proved exact when both ends are exact points: where a curve
// crosses a seam at a crossing of two boundary curves (the handle's and the body's seams of the teapot), each end is
// a split point made from a Boundary_contact (Locus_split_point::contact: the arc's end vertex proved to be that
// exact common point of the two patches' boundary curves, and the only zero of the partner equations in its box),
// and the sheet's end partner lies in that box. Two such ends are one point of space when they lie on one boundary
// curve of the model (identical control nets, in the same or the opposite direction) at the same parameter
// (compared exactly, as algebraic numbers). What is exact: the arc's end is the contact, and the two contacts are
// one point. What is floating point: that the sheet ending there is the contact's partner, decided by its traced
// end partner lying in the proved box (the box is tiny; an arc with one sheet in a certified locus has no other
// partner there). Other links (an end on a side of one patch only, at a singular point of D = 0) stay floating
// point.
#ifndef BEZOUTIAN_INTERSECTION_MODEL_CURVES_H
#define BEZOUTIAN_INTERSECTION_MODEL_CURVES_H

#include <bezoutian/intersection/Model_intersection.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

namespace bezoutian {

/// One piece of a model-level curve: a branch (sheet) of an arc of one problem's locus.
struct Model_curve_piece {
  std::size_t problem = 0;  ///< index into Model_intersection::problems
  std::size_t arc = 0;      ///< index into that locus's arcs
  std::size_t sheet = 0;    ///< index into that arc's sheets
  bool reversed = false;    ///< the curve runs through the sheet's points from last to first
};

/// A curve of the model: pieces on named pairs of patches, consecutive pieces meeting end to end.
struct Model_curve {
  std::vector<Model_curve_piece> pieces;
  bool closed = false;  ///< the last piece's end is linked to the first piece's start
  /// The largest distance in space between two linked ends (0 for one piece that is not closed).
  double largest_gap = 0;
  /// Every piece's problem is certified (Model_problem::certified): each piece is a proved branch of the curve.
  bool pieces_certified = false;
  /// The links between consecutive pieces (pieces - 1, or pieces for a closed curve), and those proved exact: both
  /// ends one exact point of a boundary curve (see the header comment; needs Model_curve_options::patches).
  std::size_t links = 0, links_proved = 0;
};

/// Options of chain_model_curves. The tolerances are absolute distances in space; a negative value means the
/// default, a multiple of the model's size s = max(1, largest |coordinate| of a traced point): 1e-7 s and 1e-4 s.
struct Model_curve_options {
  double tolerance = -1;
  double isolation = -1;
  /// The model's patches (those given to intersect_model): with them, links at exact contact points are proved.
  const std::vector<Rational_bezier_patch<Rational>>* patches = nullptr;
};

namespace internal {

struct Piece_end {
  std::size_t piece;
  int end;  // 0: the sheet's first point, 1: its last
  std::array<double, 3> point;
};

inline double distance_3(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

inline const Locus_sheet& piece_sheet(const Model_intersection& R, const Model_curve_piece& p) {
  return R.problems[p.problem].locus.arcs[p.arc].sheets[p.sheet];
}

// A point on a boundary curve of a patch of the model: the patch, its side (boundary_curve order), the parameter.
struct Boundary_curve_point {
  std::size_t patch = 0;
  int side = 0;
  Algebraic_real parameter;
};

// The exact point at an end of a piece (0: the sheet's first point, 1: its last), when it is a boundary-contact split
// point of its locus: the contact on the first patch's boundary curve and on the second's. Empty otherwise.
inline std::vector<Boundary_curve_point> exact_piece_end(const Model_intersection& R, const Model_curve_piece& p,
                                                         int end) {
  const Model_problem& mp = R.problems[p.problem];
  const Surface_locus& L = mp.locus;
  const Locus_sheet& sh = L.arcs[p.arc].sheets[p.sheet];
  if (sh.points.empty()) return {};
  const std::size_t index = end == 0 ? sh.first : sh.first + sh.points.size() - 1;
  const Locus_point& q = end == 0 ? sh.points.front() : sh.points.back();
  for (const Locus_split_point& sp : L.split_points) {
    if (sp.arc != p.arc || sp.index != index || sp.contact < 0 || std::size_t(sp.contact) >= L.contacts.size()) continue;
    // the sheet's end is the zero in the split point's box: its partner lies there
    if (!(sp.box[2][0] <= q.partner[0] && q.partner[0] <= sp.box[2][1] && sp.box[3][0] <= q.partner[1] &&
          q.partner[1] <= sp.box[3][1]))
      continue;
    const Boundary_contact& c = L.contacts[std::size_t(sp.contact)];
    return {{mp.first, c.side_first, c.first_0}, {mp.second, c.side_second, c.second_0}};
  }
  return {};
}

// 1 - a, exactly.
inline Algebraic_real one_minus(const Algebraic_real& a) {
  if (a.is_rational()) return Algebraic_real(Rational(1) - a.rational_value());
  const Polynomial_1<Integer> f = a.polynomial(), one_minus_x(Integer(1), Integer(-1));
  Polynomial_1<Integer> g(0);
  for (int i = f.degree(); i >= 0; --i) g = g * one_minus_x + Polynomial_1<Integer>(f[i]);  // f(1 - x)
  return Algebraic_real(g, Rational(1) - a.upper(), Rational(1) - a.lower());
}

// Two exact piece ends are one point of space: some boundary curve through the one and some boundary curve through
// the other are the same curve (identical nets, either direction) at the same parameter.
inline bool same_exact_point(const std::vector<Rational_bezier_patch<Rational>>& patches,
                             const std::vector<Boundary_curve_point>& a, const std::vector<Boundary_curve_point>& b) {
  using Curve = Rational_bezier_curve_3<Rational>;
  for (const Boundary_curve_point& x : a)
    for (const Boundary_curve_point& y : b) {
      if (x.patch >= patches.size() || y.patch >= patches.size()) continue;
      const Curve cx = patches[x.patch].boundary_curve<Curve>(x.side), cy = patches[y.patch].boundary_curve<Curve>(y.side);
      if (cx == cy && x.parameter == y.parameter) return true;
      if (cx == cy.reversed() && x.parameter == one_minus(y.parameter)) return true;
    }
  return false;
}

}  // namespace internal

/// \brief The curves of a model: every branch of every computed problem's locus (the sheets whose points are not
/// all one point of space), joined end to end where they continue across the seams of the model (see the header comment). Every
/// branch is in exactly one curve; the curves are ordered by their first piece (problem, arc, sheet), open curves
/// starting at their first unlinked end.
inline std::vector<Model_curve> chain_model_curves(const Model_intersection& R, const Model_curve_options& o = {}) {
  using internal::Piece_end;
  double size = 1;
  for (const Model_problem& p : R.problems)
    if (p.computed)
      for (const Locus_arc& a : p.locus.arcs)
        for (const Locus_sheet& sh : a.sheets)
          for (const Locus_point& q : sh.points)
            for (double c : q.point_3d) size = std::max(size, std::fabs(c));
  const double tolerance = o.tolerance >= 0 ? o.tolerance : 1e-7 * size;
  const double isolation = std::max(tolerance, o.isolation >= 0 ? o.isolation : 1e-4 * size);
  // the pieces: sheets with points more than `tolerance` apart in space (a sheet all of whose points are one point
  // of space, such as the partners along a collapsed row, which all map to its pole, is a point, not a curve)
  std::vector<Model_curve_piece> pieces;
  for (std::size_t k = 0; k < R.problems.size(); ++k) {
    const Model_problem& p = R.problems[k];
    if (!p.computed) continue;
    for (std::size_t a = 0; a < p.locus.arcs.size(); ++a)
      for (std::size_t s = 0; s < p.locus.arcs[a].sheets.size(); ++s) {
        const Locus_sheet& sh = p.locus.arcs[a].sheets[s];
        double extent = 0;
        for (const Locus_point& q : sh.points)
          extent = std::max(extent, internal::distance_3(q.point_3d, sh.points.front().point_3d));
        if (extent > tolerance) pieces.push_back({k, a, s, false});
      }
  }

  // the ends, sorted by x, and each end's link (the index of the linked end, or none)
  std::vector<Piece_end> ends;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const Locus_sheet& sh = internal::piece_sheet(R, pieces[i]);
    ends.push_back({i, 0, sh.points.front().point_3d});
    ends.push_back({i, 1, sh.points.back().point_3d});
  }
  std::vector<std::size_t> order(ends.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return ends[a].point[0] < ends[b].point[0] || (ends[a].point[0] == ends[b].point[0] && a < b);
  });
  constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
  // the unique end within `isolation` of each end, if there is exactly one
  std::vector<std::size_t> only(ends.size(), none);
  std::vector<double> gap(ends.size(), 0);
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t e = order[k];
    std::size_t candidates = 0, found = none;
    auto consider = [&](std::size_t j) {
      const std::size_t f = order[j];
      if (internal::distance_3(ends[e].point, ends[f].point) <= isolation) ++candidates, found = f;
    };
    for (std::size_t j = k; j-- > 0 && ends[order[k]].point[0] - ends[order[j]].point[0] <= isolation;) consider(j);
    for (std::size_t j = k + 1; j < order.size() && ends[order[j]].point[0] - ends[e].point[0] <= isolation; ++j)
      consider(j);
    if (candidates == 1 && internal::distance_3(ends[e].point, ends[found].point) <= tolerance) {
      only[e] = found;
      gap[e] = internal::distance_3(ends[e].point, ends[found].point);
    }
  }
  std::vector<std::size_t> link(ends.size(), none);
  for (std::size_t e = 0; e < ends.size(); ++e)
    if (only[e] != none && only[only[e]] == e) link[e] = only[e];
  // the links proved exact (see the header comment)
  std::vector<bool> link_proved(ends.size(), false);
  if (o.patches)
    for (std::size_t e = 0; e < ends.size(); ++e) {
      const std::size_t f = link[e];
      if (f == none || f < e) continue;
      const auto a = internal::exact_piece_end(R, pieces[ends[e].piece], ends[e].end);
      const auto b = a.empty() ? a : internal::exact_piece_end(R, pieces[ends[f].piece], ends[f].end);
      link_proved[e] = link_proved[f] = !b.empty() && internal::same_exact_point(*o.patches, a, b);
    }

  // walk the chains: first from every unlinked end (open curves), then the remaining pieces (closed curves)
  std::vector<bool> used(pieces.size(), false);
  std::vector<Model_curve> curves;
  auto walk = [&](std::size_t start_end) {
    Model_curve c;
    std::size_t e = start_end;
    while (true) {
      const std::size_t piece = ends[e].piece;
      if (used[piece]) {  // back at the first piece: closed
        c.closed = true;
        break;
      }
      used[piece] = true;
      Model_curve_piece p = pieces[piece];
      p.reversed = ends[e].end == 1;
      c.pieces.push_back(p);
      const std::size_t exit = 2 * piece + (p.reversed ? 0 : 1);  // the other end of this piece
      if (link[exit] == none) break;
      ++c.links;
      c.links_proved += link_proved[exit];
      c.largest_gap = std::max(c.largest_gap, gap[exit]);
      e = link[exit];
    }
    c.pieces_certified = true;
    for (const auto& p : c.pieces) {
      const Model_problem& mp = R.problems[p.problem];
      c.pieces_certified = c.pieces_certified && mp.computed && mp.certified;
    }
    curves.push_back(std::move(c));
  };
  for (std::size_t e = 0; e < ends.size(); ++e)
    if (link[e] == none && !used[ends[e].piece]) walk(e);
  for (std::size_t i = 0; i < pieces.size(); ++i)
    if (!used[i]) walk(2 * i);
  std::sort(curves.begin(), curves.end(), [](const Model_curve& a, const Model_curve& b) {
    const auto& x = a.pieces.front();
    const auto& y = b.pieces.front();
    return std::tie(x.problem, x.arc, x.sheet) < std::tie(y.problem, y.arc, y.sheet);
  });
  return curves;
}

/// The points of a model curve in space, piece after piece in the curve's direction, each link's second end left
/// out (it is the first's point, up to the chain's gap); for a closed curve the first point is not repeated at the
/// end.
inline std::vector<std::array<double, 3>> model_curve_points(const Model_intersection& R, const Model_curve& c) {
  std::vector<std::array<double, 3>> out;
  for (std::size_t i = 0; i < c.pieces.size(); ++i) {
    const Locus_sheet& sh = internal::piece_sheet(R, c.pieces[i]);
    const std::size_t n = sh.points.size();
    for (std::size_t j = (i == 0 ? 0 : 1); j < n; ++j)
      out.push_back(sh.points[c.pieces[i].reversed ? n - 1 - j : j].point_3d);
  }
  if (c.closed && out.size() > 1) out.pop_back();
  return out;
}

}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERSECTION_MODEL_CURVES_H
