// The output of the subdivision (Curve_topology_by_subdivision.h): floating-point sample points along each arc (a
// bracketing root refinement on the lines across the arc, where the exact analysis proved exactly one crossing, or
// one on a given side of the minimiser of sigma D in a two-branch box), the vertices (exact isolating intervals of
// the crossings, enclosures of the singular points), and the gluing of the arcs along their nodes into edges
// between stopping vertices (domain boundary, singular points, phantom cuts) and closed cycles, which become the
// components of Curve_topology_in_box.
#ifndef BEZOUTIAN_TOPOLOGY_INTERNAL_SUBDIVISION_ASSEMBLY_H
#define BEZOUTIAN_TOPOLOGY_INTERNAL_SUBDIVISION_ASSEMBLY_H

// the class Subdivision_topology, whose member functions this header defines (it is included at the end of that one)
#include <bezoutian/topology/Curve_topology_by_subdivision.h>
#include <bezoutian/topology/Curve_topology.h>

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace bezoutian {
namespace internal {

// Floating-point samples strictly between the two ends: the unique crossing of the segment u = const
// (v = const) with the curve, by a bracketing root refinement (Illinois with a bisection every fourth step).
// In a two-branch box (root_side != 0) the line carries up to two crossings, on either side of the minimiser of
// sigma D: the one below it (root_side -1) or above it (+1).
inline void Subdivision_topology::sample_arc(const Box& B, bool by_u, const Algebraic_real& p0,
                                             const Algebraic_real& p1, std::vector<std::array<double, 2>>& out,
                                             int root_side, int sigma) const {
  // Bisection on the sign of D along the line through each sample abscissa, evaluated from the box's double
  // Bernstein grid by de Casteljau's algorithm (stable; the power form cancels catastrophically at high degree
  // and put samples on the box edge). The box is simple in this direction: one sign change on each line.
  const double x0 = p0.to_double(), x1 = p1.to_double();
  const Double_bernstein_grid& G = *B.fast;
  const int nx = by_u ? G.a() : G.b(), ny = by_u ? G.b() : G.a();
  const double gx0 = CGAL::to_double(by_u ? B.u0 : B.v0), gx1 = CGAL::to_double(by_u ? B.u1 : B.v1);
  const double lo = CGAL::to_double(by_u ? B.v0 : B.u0), hi = CGAL::to_double(by_u ? B.v1 : B.u1);
  std::vector<double> c(std::size_t(ny + 1)), w(std::size_t(std::max(nx, ny) + 1)), basis(std::size_t(nx + 1));
  auto casteljau = [&](std::size_t n, double t) {  // value at t of the Bernstein coefficients w[0..n]
    for (std::size_t r = 1; r <= n; ++r)
      for (std::size_t k = 0; k + r <= n; ++k) w[k] = (1 - t) * w[k] + t * w[k + 1];
    return w[0];
  };
  // an arc of a two-branch box stands for the many leaf boxes a quadtree would need along it (the lifting proves
  // its statuses span by span between these points): four times as many samples
  const int samples = root_side != 0 ? 4 * o_.samples_per_arc : o_.samples_per_arc;
  for (int k = 1; k < samples; ++k) {
    const double x = x0 + (x1 - x0) * double(k) / samples;
    const double tx = std::min(1.0, std::max(0.0, (x - gx0) / (gx1 - gx0)));
    // coefficients along the line: D(x, .) in the Bernstein basis of the box, sum_i B_i(tx) G(i, .) (the
    // basis values are nonnegative and sum to 1: a convex combination, as stable as de Casteljau)
    basis[0] = 1;
    for (int d = 1; d <= nx; ++d) {
      basis[std::size_t(d)] = basis[std::size_t(d - 1)] * tx;
      for (int k = d - 1; k >= 1; --k) basis[std::size_t(k)] = basis[std::size_t(k)] * (1 - tx) + basis[std::size_t(k - 1)] * tx;
      basis[0] *= (1 - tx);
    }
    for (int j = 0; j <= ny; ++j) {
      double sum = 0;
      for (int i = 0; i <= nx; ++i) sum += basis[std::size_t(i)] * (by_u ? G.at(i, j) : G.at(j, i));
      c[std::size_t(j)] = sum;
    }
    auto f = [&](double t) {
      std::copy(c.begin(), c.end(), w.begin());
      return casteljau(std::size_t(ny), t);
    };
    // Illinois (regula falsi with halving of the retained end's value), every fourth step a bisection: the
    // bracket always holds the sign change and shrinks superlinearly (plain bisection needed 60 evaluations)
    double a = 0, b = 1;
    if (root_side != 0) (root_side < 0 ? b : a) = two_branch::minimiser(c, sigma);
    double fa = f(a), fb = f(b);
    const bool bracketed = (fa < 0) != (fb < 0) && fa != 0 && fb != 0;
    int kept = 0;  // which end was retained last (-1 a, 1 b)
    for (int it = 0; it < 80 && b - a > 4.5e-16; ++it) {  // (t in [0, 1]: a few ulps)
      double m = 0.5 * (a + b);
      if (bracketed && it % 4 != 3) {
        const double r = (a * fb - b * fa) / (fb - fa);
        if (r > a && r < b) m = r;
      }
      const double fm = f(m);
      if (fm == 0) {
        a = b = m;
        break;
      }
      if ((fm < 0) == (fa < 0)) {
        a = m;
        fa = fm;
        if (kept == 1) fb *= 0.5;
        kept = 1;
      } else {
        b = m;
        fb = fm;
        if (kept == -1) fa *= 0.5;
        kept = -1;
      }
    }
    const double y = lo + 0.5 * (a + b) * (hi - lo);
    out.push_back(by_u ? std::array<double, 2>{x, y} : std::array<double, 2>{y, x});
  }
}

// Enclosure {u_lo, u_hi, v_lo, v_hi} of a node (outward-rounded doubles; exact line coordinates enclosed).
inline std::array<double, 4> Subdivision_topology::node_box(std::size_t n) const {
  const Curve_topology_vertex v = vertex_of(n);
  const Node_key& k = keys_[n];
  if (k.singular) return {v.u_lo, v.u_hi, v.v_lo, v.v_hi};
  const auto c = CGAL::to_interval(k.c);
  return k.vertical ? std::array<double, 4>{c.first, c.second, v.v_lo, v.v_hi}
                    : std::array<double, 4>{v.u_lo, v.u_hi, c.first, c.second};
}

// The vertex of node n: the enclosure of the crossing or singular point, and its kind.
inline Curve_topology_vertex Subdivision_topology::vertex_of(std::size_t n) const {
  const Node_key& k = keys_[n];
  if (k.singular) {
    const Singular_point& p = singular_[std::size_t(k.index)];
    Curve_topology_vertex v;
    v.u_lo = CGAL::to_interval(p.u_lo).first;
    v.u_hi = CGAL::to_interval(p.u_hi).second;
    v.v_lo = CGAL::to_interval(p.v_lo).first;
    v.v_hi = CGAL::to_interval(p.v_hi).second;
    v.u = 0.5 * (v.u_lo + v.u_hi);
    v.v = 0.5 * (v.v_lo + v.v_hi);
    v.kind = p.fold ? Curve_topology_vertex::regular
                    : (p.isolated ? Curve_topology_vertex::isolated : Curve_topology_vertex::singular);
    v.on_boundary = v.singular_on_boundary = p.on_boundary;
    return v;
  }
  const Line& L = lines_.at(std::make_pair(k.vertical, k.c));
  const Algebraic_real& x = L.roots[std::size_t(k.index)].root;
  x.refine_to_width(Rational(1, 1 << 30) * Rational(1, 1 << 10));
  const double c = CGAL::to_double(k.c);
  const std::pair<double, double> xi = x.to_interval();
  Curve_topology_vertex v;
  v.u_lo = k.vertical ? c : xi.first;
  v.u_hi = k.vertical ? c : xi.second;
  v.v_lo = k.vertical ? xi.first : c;
  v.v_hi = k.vertical ? xi.second : c;
  v.u = 0.5 * (v.u_lo + v.u_hi);
  v.v = 0.5 * (v.v_lo + v.v_hi);
  v.on_boundary = on_domain_boundary(n);
  v.kind = v.on_boundary ? Curve_topology_vertex::boundary
                         : (cut_.count(n) ? Curve_topology_vertex::phantom_cut : Curve_topology_vertex::regular);
  const auto touch = touch_.find(n);
  if (touch != touch_.end()) {  // a contact with an edge, or a domain corner that the curve does not enter
    v.tangent_to_boundary = !is_corner_node(n) || corner_tangent_.count(n) > 0;
    if (touch->second == 0) v.kind = Curve_topology_vertex::isolated;
  } else if (corner_tangent_.count(n)) {
    v.tangent_to_boundary = true;  // the curve ends at a domain corner, tangent to one of its edges
  }
  return v;
}

// Node n is at a corner of the domain.
inline bool Subdivision_topology::is_corner_node(std::size_t n) const {
  const Node_key& k = keys_[n];
  if (k.singular) return false;
  const auto& roots = lines_.at(std::make_pair(k.vertical, k.c)).roots;
  const Algebraic_real& x = roots[std::size_t(k.index)].root;
  return on_domain_boundary(n) && (k.vertical ? (x.compare(box_.v0) == 0 || x.compare(box_.v1) == 0)
                                              : (x.compare(box_.u0) == 0 || x.compare(box_.u1) == 0));
}

// Node n is a crossing of a side of the domain.
inline bool Subdivision_topology::on_domain_boundary(std::size_t n) const {
  const Node_key& k = keys_[n];
  if (k.singular) return false;
  return k.vertical ? (k.c == box_.u0 || k.c == box_.u1) : (k.c == box_.v0 || k.c == box_.v1);
}

// Glue the arcs along their nodes into chains between domain-boundary nodes, and cycles.
inline bool Subdivision_topology::assemble(Curve_topology_in_box& out) {
  out.box = box_;
  std::vector<std::vector<std::size_t>> at(keys_.size());
  for (std::size_t k = 0; k < arcs_.size(); ++k) {
    at[arcs_[k].n0].push_back(k);
    at[arcs_[k].n1].push_back(k);
  }
  out.excluded_regions = excised_;
  // a fold is a regular point of the curve: edges run through it
  auto is_stop = [&](std::size_t n) {
    return on_domain_boundary(n) || (keys_[n].singular && !singular_[std::size_t(keys_[n].index)].fold) || cut_.count(n) > 0;
  };
  for (std::size_t n = 0; n < keys_.size(); ++n) {
    if (cut_.count(n)) {  // one arc from the analysed side, or none
      if (at[n].size() > 1) {
        fail("inconsistent subdivision: a phantom cut joins " + std::to_string(at[n].size()) + " arcs");
        return false;
      }
      continue;
    }
    const auto touch = touch_.find(n);
    const std::size_t want =
        touch != touch_.end()
            ? touch->second
            : (on_domain_boundary(n) ? 1 : (keys_[n].singular ? std::size_t(singular_[std::size_t(keys_[n].index)].half_branches) : 2));
    if (at[n].size() != want) {
      fail("inconsistent subdivision: a crossing joins " + std::to_string(at[n].size()) + " arcs");
      return false;
    }
  }
  std::vector<char> used(arcs_.size(), 0);
  std::map<std::size_t, std::size_t> vid;
  auto vertex = [&](std::size_t n) {
    auto it = vid.find(n);
    if (it != vid.end()) return it->second;
    out.vertices.push_back(vertex_of(n));
    return vid[n] = out.vertices.size() - 1;
  };
  // walk from node n along arc k; appends points (the point of n is the last one already in poly) and the
  // piece; returns the node reached (whose point comes next)
  auto walk = [&](std::size_t n, std::size_t k, std::vector<std::array<double, 2>>& poly,
                  std::vector<Curve_topology_piece>& pieces) {
    const Arc& a = arcs_[k];
    used[k] = 1;
    const std::size_t to = a.n0 == n ? a.n1 : a.n0;
    Curve_topology_piece piece{a.cell, a.graph_axis, poly.size() - 1, poly.size() + a.inner.size(), node_box(n),
                               node_box(to)};
    if (a.graph_axis < 0) {  // Arc{crossing, singular point}
      piece.singular_end = a.n0 == n ? 1 : 0;
      const Node_key& c = keys_[a.n0];
      piece.crossing_on_vertical_line = c.vertical;
      // an isolating interval of the crossing on its line, widened half-way to its neighbouring roots (so that
      // a rational root, whose own interval is a point, gets a proper one)
      const auto& roots = lines_.at(std::make_pair(c.vertical, c.c)).roots;
      const std::size_t r = std::size_t(c.index);
      const Rational lo = r > 0 ? (roots[r - 1].root.upper() + roots[r].root.lower()) / 2 : roots[r].root.lower() - 1;
      const Rational hi = r + 1 < roots.size() ? (roots[r].root.upper() + roots[r + 1].root.lower()) / 2
                                               : roots[r].root.upper() + 1;
      piece.crossing = c.vertical ? Parameter_box{c.c, c.c, lo, hi} : Parameter_box{lo, hi, c.c, c.c};
    }
    if (a.n0 == n)
      poly.insert(poly.end(), a.inner.begin(), a.inner.end());
    else
      poly.insert(poly.end(), a.inner.rbegin(), a.inner.rend());
    pieces.push_back(piece);
    return to;
  };
  auto point = [&](std::size_t n) {
    const Curve_topology_vertex v = vertex_of(n);
    return std::array<double, 2>{v.u, v.v};
  };
  auto chain = [&](std::size_t start, std::size_t k, bool stop_at_target, std::size_t target) {
    Curve_topology_edge e;
    e.source = vertex(start);
    e.polyline.push_back(point(start));
    std::size_t n = start;
    for (;;) {
      n = walk(n, k, e.polyline, e.pieces);
      if (is_stop(n) || (stop_at_target && n == target)) break;
      if (used[at[n][0]] && used[at[n][1]]) break;  // back at the start of a cycle
      e.polyline.push_back(point(n));
      k = used[at[n][0]] ? at[n][1] : at[n][0];
    }
    e.polyline.push_back(point(n));
    e.target = vertex(n);
    out.edges.push_back(e);
    return n;
  };
  for (std::size_t n = 0; n < keys_.size(); ++n)
    if ((keys_[n].singular && singular_[std::size_t(keys_[n].index)].isolated) ||
        (touch_.count(n) && touch_.at(n) == 0)) {  // an acnode or an outside contact: its own component
      Curve_topology_component c;
      c.closed = keys_[n].singular;  // a contact point lies on the domain boundary
      c.isolated_point = true;
      c.vertices.push_back(vertex(n));
      out.components.push_back(c);
    }
  for (std::size_t n = 0; n < keys_.size(); ++n)
    if (is_stop(n))
      for (std::size_t k : at[n])
        if (!used[k]) chain(n, k, false, n);
  for (std::size_t k = 0; k < arcs_.size(); ++k) {
    if (used[k]) continue;
    // a cycle: count its nodes, then split it into two edges at the start and half-way
    std::vector<std::size_t> nodes;
    std::size_t n = arcs_[k].n0, a = k;
    std::vector<char> seen(arcs_.size(), 0);
    for (;;) {
      nodes.push_back(n);
      seen[a] = 1;
      n = arcs_[a].n0 == n ? arcs_[a].n1 : arcs_[a].n0;
      const std::size_t next = at[n][0] == a ? at[n][1] : at[n][0];
      if (seen[next]) break;
      a = next;
    }
    const std::size_t start = arcs_[k].n0, half = nodes[nodes.size() / 2];
    if (nodes.size() < 2) {  // a loop through one node only: cannot happen (two arcs meet at every node)
      fail("inconsistent subdivision: a one-node cycle");
      return false;
    }
    const std::size_t reached = chain(start, k, true, half);
    const std::size_t k2 = used[at[reached][0]] ? at[reached][1] : at[reached][0];
    chain(reached, k2, true, start);
  }
  internal::assign_components(out);
  return true;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_TOPOLOGY_INTERNAL_SUBDIVISION_ASSEMBLY_H
