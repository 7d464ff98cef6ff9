// A proof that two patches do not meet, without elimination: the convex hull property. A rational patch whose
// weights are positive lies in the convex hull of its control points, so its projection onto any line lies in the
// interval spanned by the projections of the control points. Two pieces are apart when these intervals are
// disjoint on some axis: a coordinate axis (their bounding boxes are disjoint) or the mean normal of either piece
// (the cross product of its mean u and v directions: thin slabs, which separate nearby parallel sheets that boxes
// do not). Subdividing both patches (exact de Casteljau quarters) tightens the hulls, so patches a small distance
// apart are separated after a few levels; a pair of pieces found apart is dropped, and the proof succeeds when no
// pair is left.
#ifndef BEZOUTIAN_INTERSECTION_PATCH_SEPARATION_H
#define BEZOUTIAN_INTERSECTION_PATCH_SEPARATION_H

#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>

#include <array>
#include <cstddef>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace bezoutian {

/// Outcome of prove_disjoint().
struct Separation_proof {
  bool proved = false;
  int depth = 0;           ///< subdivision levels used (0: the patches' own control boxes)
  std::size_t pieces = 0;  ///< pairs of pieces whose boxes were compared
  std::string reason;      ///< the proof, or why it was not found
};

namespace internal {


using Point_3 = std::array<Rational, 3>;

// A piece of a subdivided patch with what the separation tests need: its affine control points, their bounding box
// and its mean normal.
struct Separation_piece {
  std::vector<Point_3> points;
  Point_3 lo, hi, normal;
};

inline Separation_piece separation_piece(const Rational_bezier_patch<Rational>& P) {
  Separation_piece s;
  const std::size_t m = std::size_t(P.degree_u()), n = std::size_t(P.degree_v());
  for (std::size_t i = 0; i <= m; ++i)
    for (std::size_t j = 0; j <= n; ++j) s.points.push_back(P.control_point(i, j));
  std::tie(s.lo, s.hi) = P.control_box();
  auto corner = [&](std::size_t i, std::size_t j) { return s.points[i * (n + 1) + j]; };
  Point_3 du, dv;
  for (std::size_t k = 0; k < 3; ++k) {
    du[k] = corner(m, 0)[k] - corner(0, 0)[k] + corner(m, n)[k] - corner(0, n)[k];
    dv[k] = corner(0, n)[k] - corner(0, 0)[k] + corner(m, n)[k] - corner(m, 0)[k];
  }
  s.normal = {du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]};
  return s;
}

// The pieces' hulls are disjoint along a coordinate axis or along the normal of either piece.
inline bool pieces_apart(const Separation_piece& a, const Separation_piece& b) {
  for (std::size_t k = 0; k < 3; ++k)
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return true;
  for (const Point_3* axis : {&a.normal, &b.normal}) {
    if (CGAL::is_zero((*axis)[0]) && CGAL::is_zero((*axis)[1]) && CGAL::is_zero((*axis)[2])) continue;
    auto range = [&](const std::vector<Point_3>& pts) {
      std::pair<Rational, Rational> r;
      for (std::size_t i = 0; i < pts.size(); ++i) {
        const Rational d = (*axis)[0] * pts[i][0] + (*axis)[1] * pts[i][1] + (*axis)[2] * pts[i][2];
        if (i == 0 || d < r.first) r.first = d;
        if (i == 0 || r.second < d) r.second = d;
      }
      return r;
    };
    const auto ra = range(a.points), rb = range(b.points);
    if (ra.second < rb.first || rb.second < ra.first) return true;
  }
  return false;
}

// The four quarters of P (split at u = 1/2 and v = 1/2).
inline std::vector<Rational_bezier_patch<Rational>> quarters(const Rational_bezier_patch<Rational>& P) {
  std::vector<Rational_bezier_patch<Rational>> out;
  const auto h = P.split_u(Rational(1, 2));
  for (const auto* half : {&h.first, &h.second}) {
    const auto q = half->split_v(Rational(1, 2));
    out.push_back(q.first);
    out.push_back(q.second);
  }
  return out;
}

}  // namespace internal

/// \brief Proves that the patches (positive weights) have no common point for parameters in [0,1]^2 x [0,1]^2:
/// every pair of pieces of their subdivisions, down to `max_depth` levels, has hulls apart (the header's tests), or
/// was dropped at a coarser level. Exact; a failure only means "not proved". At most `max_pairs` box pairs are compared.
inline Separation_proof prove_disjoint(const Rational_bezier_patch<Rational>& P, const Rational_bezier_patch<Rational>& Q,
                                       int max_depth = 3, std::size_t max_pairs = 20000) {
  Separation_proof out;
  if (!P.has_positive_weights() || !Q.has_positive_weights()) {
    out.reason = "not all weights are positive (the convex hull property does not hold)";
    return out;
  }
  // pieces of each patch at the current level, their boxes, and the pairs of pieces whose boxes meet
  using Patch = Rational_bezier_patch<Rational>;
  std::array<std::vector<Patch>, 2> pieces{{{P}, {Q}}};
  std::array<std::vector<internal::Separation_piece>, 2> boxes{{{internal::separation_piece(P)}, {internal::separation_piece(Q)}}};
  std::vector<std::pair<std::size_t, std::size_t>> pairs{{0, 0}};
  for (int depth = 0; depth <= max_depth; ++depth) {
    std::vector<std::pair<std::size_t, std::size_t>> left;
    for (const auto& pq : pairs) {
      ++out.pieces;
      if (!internal::pieces_apart(boxes[0][pq.first], boxes[1][pq.second])) left.push_back(pq);
    }
    if (left.empty()) {
      out.proved = true;
      out.depth = depth;
      out.reason = "the convex hulls of the control points of the patches" +
                   (depth == 0 ? std::string() : " subdivided " + std::to_string(depth) + " time(s)") +
                   " are apart along coordinate axes or piece normals, so the patches do not meet";
      return out;
    }
    if (depth == max_depth) break;
    if (out.pieces + left.size() * 16 > max_pairs) {
      out.reason = "more than " + std::to_string(max_pairs) + " pairs of pieces would be compared";
      return out;
    }
    // quarter every piece that is in a pair left, once; the pairs of their quarters are the next level's pairs
    std::array<std::vector<Patch>, 2> next_pieces;
    std::array<std::vector<internal::Separation_piece>, 2> next_boxes;
    std::array<std::vector<std::size_t>, 2> first_quarter;
    for (int k = 0; k < 2; ++k) {
      first_quarter[std::size_t(k)].assign(pieces[std::size_t(k)].size(), std::size_t(-1));
      for (const auto& pq : left) {
        const std::size_t i = k == 0 ? pq.first : pq.second;
        if (first_quarter[std::size_t(k)][i] != std::size_t(-1)) continue;
        first_quarter[std::size_t(k)][i] = next_pieces[std::size_t(k)].size();
        for (const Patch& q : internal::quarters(pieces[std::size_t(k)][i])) {
          next_boxes[std::size_t(k)].push_back(internal::separation_piece(q));
          next_pieces[std::size_t(k)].push_back(q);
        }
      }
    }
    pairs.clear();
    for (const auto& pq : left)
      for (std::size_t a = 0; a < 4; ++a)
        for (std::size_t b = 0; b < 4; ++b)
          pairs.emplace_back(first_quarter[0][pq.first] + a, first_quarter[1][pq.second] + b);
    pieces = std::move(next_pieces);
    boxes = std::move(next_boxes);
  }
  out.reason = "pieces of the two patches have overlapping hulls after " + std::to_string(max_depth) +
               " subdivisions";
  return out;
}

}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERSECTION_PATCH_SEPARATION_H
