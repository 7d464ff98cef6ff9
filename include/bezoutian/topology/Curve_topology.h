// The result type of the certified topology of a plane curve D(u,v) = 0 inside a parameter box: vertices with
// certified enclosures, arcs with sample points, connected components. Produced by analyse_curve_in_box()
// (CGAL's curve analysis, Cgal_curve_analysis.h) and by subdivide_curve_in_box()
// (Curve_topology_by_subdivision.h).
#ifndef BEZOUTIAN_TOPOLOGY_CURVE_TOPOLOGY_H
#define BEZOUTIAN_TOPOLOGY_CURVE_TOPOLOGY_H

#include <bezoutian/arithmetic/number_types.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <map>
#include <numeric>
#include <vector>

namespace bezoutian {

/// A closed axis-parallel box [u0,u1] x [v0,v1] with rational corners (u0 < u1, v0 < v1).
struct Parameter_box {
  Rational u0{0}, u1{1}, v0{0}, v1{1};
  bool contains(double u, double v) const {
    return CGAL::to_double(u0) <= u && u <= CGAL::to_double(u1) && CGAL::to_double(v0) <= v &&
           v <= CGAL::to_double(v1);
  }
};

/// A vertex of the curve inside the box.
struct Curve_topology_vertex {
  /// phantom_cut: the curve continues into a region proved free of genuine points (excluded_regions) and is not
  /// followed there.
  enum Kind { regular, singular, boundary, isolated, phantom_cut };
  Kind kind = regular;
  /// Certified enclosure of the point: u in [u_lo,u_hi], v in [v_lo,v_hi] (rationals converted outward to double).
  double u = 0, v = 0, u_lo = 0, u_hi = 0, v_lo = 0, v_hi = 0;
  /// Number of arcs of the curve inside the box that end here (half-branches).
  int half_branches = 0;
  /// Number of real branches through the point: half_branches / 2 for an interior point (a cusp counts 1).
  int branches = 0;
  bool on_boundary = false;
  /// The curve is tangent to the domain edge here (an even-order contact): it passes through the point from
  /// inside the domain (kind boundary, two arcs end here), or only the point itself is in the domain (kind
  /// isolated). At a domain corner: the curve is tangent to one of the two edges there and enters the domain
  /// (kind boundary, one arc) or not (kind isolated). A corner that the curve crosses transversally from outside
  /// is kind isolated with this flag false.
  bool tangent_to_boundary = false;
  /// On the boundary: D = 0 is singular here (a singular point of D at a domain corner or inside a side, where
  /// the enclosure is its isolating interval on that side; `branches` counts the half-branches into the domain, 0
  /// if only the point itself is in it).
  bool singular_on_boundary = false;
};

/// A piece of an edge inside one cell of the subdivision where the curve is proved to be a graph: for
/// graph_axis 0 every line u = c meets the curve inside `cell` at most once (v = g(u), dD/dv != 0 on the cell),
/// for graph_axis 1 every line v = c does. graph_axis -1: not a proved graph in its cell: a half-branch inside the
/// box of a singular point, or one of the two arcs of a two-branch cell (topology/internal/two_branch_box.h; each is a
/// graph, but a line of the cell may also meet the other arc), or of a fold cell (topology/internal/fold_box.h: from a
/// crossing to the fold point, where the curve turns back). The piece runs through polyline[first .. last]; its
/// end points are crossings of the cell's edges (or the singular or fold point) with the enclosures first_box,
/// last_box = {u_lo, u_hi, v_lo, v_hi}.
struct Curve_topology_piece {
  Parameter_box cell;
  int graph_axis = -1;
  std::size_t first = 0, last = 0;
  std::array<double, 4> first_box{}, last_box{};
  /// graph_axis -1: which end (0: first, 1: last) is the singular (or fold) point (in a two-branch cell: the end
  /// that the lifting's chained proof does not start from); the other end is a crossing of the cell's
  /// edge, with its exact isolating box (degenerate along the edge's line; the interval along the line holds no
  /// other root of D restricted to that line) and whether that line is vertical (u = const).
  int singular_end = -1;
  Parameter_box crossing;
  bool crossing_on_vertical_line = false;
};

/// An arc of the curve inside the box between two vertices, with certified sample points along it.
struct Curve_topology_edge {
  std::size_t source = 0, target = 0;
  std::vector<std::array<double, 2>> polyline;  ///< from source to target
  /// The cells the edge runs through, in order (filled by the subdivision; empty from CGAL's curve analysis).
  std::vector<Curve_topology_piece> pieces;
};

/// A connected component of (D = 0) ∩ box.
struct Curve_topology_component {
  bool closed = false;                ///< does not meet the box boundary (nor an excluded region)
  bool isolated_point = false;        ///< a single real point (acnode)
  std::vector<std::size_t> edges;     ///< indices into Curve_topology_in_box::edges
  std::vector<std::size_t> vertices;  ///< indices into Curve_topology_in_box::vertices
};

/// The result of analyse_curve_in_box().
struct Curve_topology_in_box {
  Parameter_box box;
  std::vector<Curve_topology_vertex> vertices;
  std::vector<Curve_topology_edge> edges;
  std::vector<Curve_topology_component> components;
  /// Regions of the box where D = 0 was not analysed because they are proved to hold no genuine point of the
  /// locus (no partner in the partner domain); arcs end there at phantom_cut vertices.
  std::vector<Parameter_box> excluded_regions;
  std::size_t number_of_singular_points() const {
    return std::count_if(vertices.begin(), vertices.end(),
                         [](const Curve_topology_vertex& v) { return v.kind == Curve_topology_vertex::singular; });
  }
  std::size_t number_of_boundary_points() const {
    return std::count_if(vertices.begin(), vertices.end(), [](const Curve_topology_vertex& v) { return v.on_boundary; });
  }
};

namespace internal {

/// Half-branch and branch counts of the vertices and the connected components of the edges (union-find);
/// isolated-point vertices (already given their own components) are left alone. A component is closed iff
/// none of its vertices is on the box boundary.
inline void assign_components(Curve_topology_in_box& out) {
  std::vector<std::size_t> parent(out.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::function<std::size_t(std::size_t)> find = [&](std::size_t i) {
    return parent[i] == i ? i : parent[i] = find(parent[i]);
  };
  for (const auto& e : out.edges) {
    out.vertices[e.source].half_branches++;
    out.vertices[e.target].half_branches++;
    parent[find(e.source)] = find(e.target);
  }
  for (auto& v : out.vertices)
    if (v.kind != Curve_topology_vertex::isolated)
      v.branches = v.on_boundary ? v.half_branches : std::max(1, v.half_branches / 2);
  std::map<std::size_t, std::size_t> comp_of_root;
  for (std::size_t i = 0; i < out.edges.size(); ++i) {
    const std::size_t r = find(out.edges[i].source);
    auto it = comp_of_root.find(r);
    if (it == comp_of_root.end()) {
      it = comp_of_root.emplace(r, out.components.size()).first;
      out.components.emplace_back();
      out.components.back().closed = true;
    }
    out.components[it->second].edges.push_back(i);
  }
  for (std::size_t i = 0; i < out.vertices.size(); ++i) {
    if (out.vertices[i].kind == Curve_topology_vertex::isolated) continue;
    auto it = comp_of_root.find(find(i));
    if (it == comp_of_root.end()) continue;
    out.components[it->second].vertices.push_back(i);
    if (out.vertices[i].on_boundary || out.vertices[i].kind == Curve_topology_vertex::phantom_cut)
      out.components[it->second].closed = false;
  }
}

} // namespace internal

} // namespace bezoutian

#endif // BEZOUTIAN_TOPOLOGY_CURVE_TOPOLOGY_H
