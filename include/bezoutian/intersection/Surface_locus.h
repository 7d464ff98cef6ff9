// The result of the surface (self-)intersection computations of Surface_intersection.h: the implicit equation D,
// the certified topology of D = 0 in the box, the traced arcs with their partners and proved statuses, boundary
// contacts, box sides on D = 0, split points and pinch points (doc/surface_intersection.md).
#ifndef BEZOUTIAN_INTERSECTION_SURFACE_LOCUS_H
#define BEZOUTIAN_INTERSECTION_SURFACE_LOCUS_H

#include <bezoutian/algebraic/Algebraic_real.h>
#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/elimination/Implicit_equation.h>
#include <bezoutian/geometry/Moebius_map.h>
#include <bezoutian/lifting/isolated_point_partners.h>
#include <bezoutian/lifting/pinch_points.h>
#include <bezoutian/topology/Curve_topology.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace bezoutian {

/// A traced point of the locus: the point of the projection plane, its partner parameters, its 3D point.
struct Locus_point {
  std::array<double, 2> projection{};  ///< (u,v) (self) or (u,t) (intersection)
  std::array<double, 2> partner{};     ///< (k,l) offsets turned into parameters: see Surface_locus
  std::array<double, 2> first{}, second{};  ///< the two parameter points that map to the same 3D point
  std::array<double, 3> point_3d{};
  double residual = std::numeric_limits<double>::quiet_NaN();  ///< |Phi(first) - Phi/Psi(second)|
  bool lifted = false;   ///< the kernel gave a partner
  /// partner inside its domain, distinct from the point itself, and verified: residual <= 1e-7 (1 + |point_3d|)
  bool genuine = false;
  /// `genuine` is proved for the point of D = 0 that this traced point approximates: genuine by a partner enclosed
  /// in the partner domain (parametric Krawczyk), phantom by an exclusion of every partner
  /// (lifting/certified_lifting.h). False: decided in floating point only.
  bool status_proved = false;
  /// For a point proved genuine: a box {{y1_lo, y1_hi}, {y2_lo, y2_hi}} in the coordinates of `partner` ((l, k) or
  /// (v, s)) proved to contain a partner, inside the partner domain, of the exact point of D = 0 that this traced
  /// point approximates (the point of the exact arc with the same graph coordinate; parametric Krawczyk over the
  /// span, lifting/certified_lifting.h). NaN otherwise. `partner` itself is a floating-point approximation.
  std::array<std::array<double, 2>, 2> partner_enclosure{
      {{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()},
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()}}};
};

/// A branch of the space curve over an arc of D = 0: one partner followed continuously along consecutive traced
/// points of the arc, all genuine (both parameter points in their domains). Where two branches share a projection
/// (two cylinders crossing: z and -z over one (u, t)) the arc has two sheets (lifting/partner_sheets.h).
struct Locus_sheet {
  std::size_t first = 0;            ///< index in Locus_arc::points of its first point
  std::vector<Locus_point> points;  ///< over Locus_arc::points[first], [first + 1], ...: same projection, this partner
  /// Per segment (points[j] to points[j + 1]): proved bounds {first parameter domain, second, space} on the
  /// distance between the chord of the reported points (Locus_point::first, second, point_3d) and the branch of
  /// the curve over the segment, both ways (lifting/polyline_distance_bounds.h); infinity where not proved (a
  /// segment on a half-branch inside a singular point's box, next to a fold). Empty when not computed
  /// (Surface_intersection_options::prove_polyline_distance).
  std::vector<std::array<double, 3>> segment_distance_bounds;
};

/// The largest of the sheet's segment bounds, per entry {first, second, space}: infinity if a segment is not proved
/// or the bounds were not computed (a single point: 0).
inline std::array<double, 3> sheet_distance_bound(const Locus_sheet& s) {
  const double inf = std::numeric_limits<double>::infinity();
  if (s.points.size() < 2) return {0, 0, 0};
  if (s.segment_distance_bounds.size() + 1 != s.points.size()) return {inf, inf, inf};
  std::array<double, 3> m{0, 0, 0};
  for (const auto& b : s.segment_distance_bounds)
    for (std::size_t c = 0; c < 3; ++c) m[c] = std::max(m[c], b[c]);
  return m;
}

/// One arc of D = 0 inside the box, traced.
struct Locus_arc {
  std::size_t source = 0, target = 0;  ///< vertices of the certified topology
  /// The traced points, each with one partner (genuine if it has one in the partner domain); every partner of
  /// every point is in `sheets`.
  std::vector<Locus_point> points;
  /// Share of the arc (by length of its graph coordinate) whose genuine / phantom status is not proved: 0 when
  /// every point of the exact arc, not only the traced ones, is proved genuine or phantom; 1 if nothing is.
  double undecided_fraction = 1;
  /// Every branch of the space curve over this arc (complete lifting): the genuine runs of every partner.
  std::vector<Locus_sheet> sheets;
  /// Share of the arc (graph-coordinate length) where `sheets` is not proved to hold every partner in the partner
  /// domain: 0 when the sheets are proved to be all of them (a Krawczyk test per sheet and an exclusion of every
  /// other partner, span by span), 1 if nothing is proved. Where it is not 0, a branch may be missing there.
  double fibre_undecided_fraction = 1;
};

/// Two patches in contact along their boundaries (the teapot's patches are glued edge to edge): a piece of a
/// boundary curve of the first patch lying on a boundary curve of the second (`shared_curve`), or an isolated
/// common boundary point (touching corners, a boundary crossing). Decided exactly with the curve engine
/// (intersect_curves on the boundary curves); parameters run along the boundary curves.
struct Boundary_contact {
  int side_first = 0, side_second = 0;  ///< boundary_curve sides: 0: v = 0, 1: u = 1, 2: v = 1, 3: u = 0
  bool shared_curve = false;            ///< infinitely many common points (a common piece of boundary curve)
  Algebraic_real first_0, first_1;      ///< parameter range on the first patch's boundary curve (equal for a point)
  Algebraic_real second_0, second_1;    ///< the corresponding range on the second patch's boundary curve
  std::array<double, 3> point{};        ///< the contact point (the start of a shared piece)
};

/// A point inside the box where the genuine part of an arc ends: a partner reaches the boundary of the partner
/// domain there (the intersection curve meets a boundary curve of the second patch; a double curve of a
/// self-intersection leaves the patch through its other sheet). Certified (lifting/partner_domain_crossings.h):
/// `box` holds exactly one solution (x1, x2, y1, y2) of the partner equations together with
/// `boundary coordinate = bound`, a transversal crossing, and that solution is the point of the arc over its graph
/// coordinate. Its traced point arc.points[index] is genuine (status proved; the partner lies on the domain's
/// boundary, the other coordinates inside), and the floating-point statuses on its two sides differ. A split point
/// may also be an end of its arc (index 0 or the last) on a side of the box, where the curve leaves both patches at
/// a common point of their boundary curves (a Boundary_contact point, exact; as where the curve of a model crosses
/// a seam): `box` then holds that contact.
struct Locus_split_point {
  std::size_t arc = 0;    ///< index into Surface_locus::arcs
  std::size_t index = 0;  ///< the traced point arcs[arc].points[index]
  int point = 0;          ///< the parameter point on the boundary: 0 Locus_point::first, 1 Locus_point::second
  int coordinate = 0;     ///< its coordinate on the boundary: 0 (u or s), 1 (v or t)
  Rational bound;         ///< the boundary value of that coordinate
  /// {x1, x2, y1, y2}: the projection (u, v or u, t) and the partner ((l, k) or (v, s)), each {lo, hi}
  std::array<std::array<double, 2>, 4> box{};
  /// For an arc end at a common point of the boundary curves: its index in Surface_locus::contacts (the point is
  /// that exact contact); -1 otherwise.
  int contact = -1;
};

/// A side of the box on which D vanishes identically: every point of it is a point of the projected locus. Its
/// line's factor is removed from D before the topology, which describes the rest of D = 0 (whose boundary points
/// on this side are where the rest meets it). The cause is decided exactly (intersection/internal/box_edge_lines.h): a collapsed
/// edge (an iso-curve of a patch that is one point: every pair of its points, or every point of the other patch at
/// that point, is a double point) or a boundary curve shared with a side of the partner domain (two glued patches,
/// the seam of a closed patch), or an iso-curve of the partner inside its domain (a patch tangent to the other
/// along its boundary), all genuine at every point; or the side's fixed coordinate lies outside the partner domain,
/// or the side's iso-curve is one point that is not on the partner, or a curve that meets the partner nowhere (phantom
/// at every point).
struct Locus_edge_line {
  enum Cause { unexplained, collapsed, shared_curve, outside_domain, partner_iso_curve, point_off_partner,
               curve_off_partner };
  int side = 0;    ///< of the box, in boundary_curve order: 0: v = v0, 1: u = u1, 2: v = v1, 3: u = u0 ((u, t) for two patches)
  Rational value;  ///< the fixed coordinate of the side
  /// A line u = value (side 3) or v / t = value (side 0) inside the box rather than a side: removed from D only when
  /// its cause is proved genuine (an iso-curve of one patch lying on the other, as where two surfaces are tangent
  /// along an iso-curve), otherwise left to the topology
  bool interior = false;
  Cause cause = unexplained;
  /// collapsed / shared_curve: the side of the partner domain (boundary_curve order) whose iso-curve holds the
  /// partner points; -1 for a self-intersection's collapsed side paired with itself and for partner_iso_curve
  int partner_side = -1;
  /// collapsed / shared_curve / partner_iso_curve: the fixed coordinate of that iso-curve (s for a side u = c, v
  /// for a side t = c)
  Rational partner_value;
  bool genuine = false;  ///< every point of the side has a partner in the partner domain (the genuine causes)
  bool status_proved = false;  ///< `genuine` is proved for the whole side (every cause but unexplained)
  std::string description;     ///< one line for people
  /// samples along the side (samples_per_arc + 1, ends included): for a proved cause the partner comes from it (a
  /// floating-point point of the partner iso-curve; status_proved set, partner_enclosure NaN); otherwise the lifting
  /// of the arcs (floating point).
  std::vector<Locus_point> points;
};

/// Two patches that share a surface piece (intersection/Patch_common_parent.h): the rectangle `first` of the first
/// patch's domain and the rectangle `second` of the second's have one image, point by point through
/// Psi(s, t) = Phi(u, v), (u, v) = swapped ? (along_u(t), along_v(s)) : (along_u(s), along_v(t)). Exact.
struct Locus_overlap {
  std::array<Rational, 4> first{}, second{};  ///< {u0, u1, v0, v1} and {s0, s1, t0, t1}
  bool swapped = false;
  Moebius_map along_u, along_v;
};

/// An isolated real point of D = 0 in the box (a vertex of kind isolated) with its real partners: a point where
/// the two patches touch (a tangential contact, or a singular point of a patch) or a phantom
/// (lifting/isolated_point_partners.h).
struct Locus_isolated_point {
  std::size_t vertex = 0;  ///< index into topology.vertices
  Isolated_point_partners lift;
  bool genuine() const { return lift.proved && !lift.partners.empty(); }
};

/// The result: the implicit equation, the certified topology of D = 0 in the box, and the traced arcs.
struct Surface_locus {
  bool self_intersection = true;
  /// False when a direct proof answered without elimination (Surface_intersection_options::direct_proofs):
  /// `equation` is then empty and `note` gives the proof.
  bool equation_computed = true;
  Implicit_equation equation;
  Curve_topology_in_box topology;
  std::vector<Locus_arc> arcs;  ///< parallel to topology.edges
  bool topology_computed = false;
  /// "subdivision" (Bernstein subdivision in the box), "curve analysis" (CGAL's arrangement), or the direct proof
  /// ("injective projection", "separated hulls"), if computed
  std::string topology_method;
  std::string note;  ///< why the topology was not computed, if it was not
  /// Intersection of two patches: their boundary contacts (shared edges, touching corners), exact.
  std::vector<Boundary_contact> contacts;
  /// Intersection of two patches that are pieces of one surface: the common regions of their domains (exact). The
  /// rest of the intersection is then in `contacts` (`topology_method` "common parent"); see `note`.
  std::vector<Locus_overlap> overlaps;
  /// Intersection of two patches: the isolated real points of D = 0 in the box, each decided as a contact of the
  /// patches (with every partner) or a phantom, or left undecided with the reason.
  std::vector<Locus_isolated_point> isolated_points;
  /// Sides of the box that lie on D = 0 (collapsed edges, shared boundary curves); the topology is of the rest.
  std::vector<Locus_edge_line> edge_lines;
  /// Where genuine parts of arcs end inside the box (subdivision topologies with a bounded partner domain), and
  /// arc ends at common points of both patches' boundaries; each is also a traced point of its arc.
  std::vector<Locus_split_point> split_points;
  /// Self-intersection: the pinch points of the patch in the box (Jacobian of rank <= 1: a double curve may end
  /// there, its partner tending to the point itself), each in a box proved to hold exactly one; `pinch_points_complete`
  /// says whether every other point of the box is proved not to be one (else `pinch_points_note` says why not).
  std::vector<Pinch_point> pinch_points;
  bool pinch_points_complete = false;
  std::string pinch_points_note;
};

/// \brief Whether everything the locus reports is proved and complete: its topology computed; on every arc with
/// genuine or undecided points, every status and every fibre proved (Locus_arc::undecided_fraction and
/// fibre_undecided_fraction zero); every edge line's status and every isolated point's lifting proved; for a
/// self-intersection with a double curve, its pinch points complete. If not, `reason` (optional) gets the first
/// thing that is not.
inline bool locus_certified(const Surface_locus& L, std::string* reason = nullptr) {
  auto no = [&](const std::string& why) {
    if (reason) *reason = why;
    return false;
  };
  auto percent = [](double f) {
    char b[32];
    std::snprintf(b, sizeof b, "%.2g %%", 100 * f);
    return std::string(b);
  };
  if (!L.topology_computed) return no("topology not computed: " + L.note);
  for (std::size_t k = 0; k < L.arcs.size(); ++k) {
    const Locus_arc& a = L.arcs[k];
    bool genuine = false;
    for (const Locus_point& q : a.points) genuine = genuine || q.genuine;
    if (!genuine && a.undecided_fraction == 0) continue;
    if (a.undecided_fraction > 0)
      return no("arc " + std::to_string(k) + ": the status of " + percent(a.undecided_fraction) + " of it is not proved");
    if (a.fibre_undecided_fraction > 0)
      return no("arc " + std::to_string(k) + ": the fibre of " + percent(a.fibre_undecided_fraction) +
                " of it is not proved complete");
  }
  for (std::size_t k = 0; k < L.edge_lines.size(); ++k)
    if (!L.edge_lines[k].status_proved) return no("edge line " + std::to_string(k) + ": status not proved");
  for (std::size_t k = 0; k < L.isolated_points.size(); ++k)
    if (!L.isolated_points[k].lift.proved) return no("isolated point " + std::to_string(k) + ": not decided");
  if (L.self_intersection && !L.arcs.empty() && !L.pinch_points_complete)
    return no("pinch points not proved complete: " + L.pinch_points_note);
  if (reason) reason->clear();
  return true;
}

}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERSECTION_SURFACE_LOCUS_H
