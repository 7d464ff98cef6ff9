// The exact side of the subdivision (Curve_topology_by_subdivision.h): the real roots of D on the box lines u = c and
// v = c (exact isolation, shared by all the boxes along a line), the nodes they define, and the crossings of D = 0
// with the edges of a box, with the contacts and corners that the header comment of Curve_topology_by_subdivision.h
// describes (Touch: an even-multiplicity root on a domain edge across which the box is simple; corner_crossing: the
// curve through a domain corner enters the box or not, by exact signs). A simple box (dD/dv != 0 or dD/du != 0 on it)
// is resolved here: every line across it meets the curve at most once, so its crossings, sorted along the graph
// coordinate, pair up into arcs (resolve). A box proved free of genuine points is excised: its crossings become
// phantom cuts (excise).
#ifndef BEZOUTIAN_TOPOLOGY_INTERNAL_SUBDIVISION_CROSSINGS_H
#define BEZOUTIAN_TOPOLOGY_INTERNAL_SUBDIVISION_CROSSINGS_H

// the class Subdivision_topology, whose member functions this header defines (it is included at the end of that one)
#include <bezoutian/topology/Curve_topology_by_subdivision.h>
#include <bezoutian/algebraic/Root_isolation.h>

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace bezoutian {
namespace internal {

// Exact roots of D on the line u = c (vertical) or v = c, over the domain range of the other variable.
inline const Subdivision_topology::Line& Subdivision_topology::line(bool vertical, const Rational& c) {
  auto key = std::make_pair(vertical, c);
  auto it = lines_.find(key);
  if (it != lines_.end()) return it->second;
  Polynomial_1<Rational> f(0);
  if (vertical) {  // f(v) = sum_j D_j(c) v^j
    std::vector<Rational> co;
    for (int j = 0; j <= D_.degree(); ++j) {
      Rational x(0);
      if (!CGAL::is_zero(D_[j]))
        for (int i = D_[j].degree(); i >= 0; --i) x = x * c + Rational(D_[j][i]);
      co.push_back(x);
    }
    f = Polynomial_1<Rational>(co.begin(), co.end());
  } else {  // f(u) = sum_j D_j(u) c^j
    for (int j = D_.degree(); j >= 0; --j) {
      std::vector<Rational> co;
      if (!CGAL::is_zero(D_[j]))
        for (int i = 0; i <= D_[j].degree(); ++i) co.push_back(Rational(D_[j][i]));
      f = f * Polynomial_1<Rational>(c) + (co.empty() ? Polynomial_1<Rational>(0) : Polynomial_1<Rational>(co.begin(), co.end()));
    }
  }
  Line L;
  if (CGAL::is_zero(f)) {
    fail(std::string("D vanishes on the whole line ") + (vertical ? "u = " : "v = ") + std::to_string(CGAL::to_double(c)));
  } else if (f.degree() >= 1) {
    L.roots = vertical ? isolate_real_roots(f, box_.v0, box_.v1) : isolate_real_roots(f, box_.u0, box_.u1);
  }
  return lines_.emplace(key, std::move(L)).first->second;
}

// The node of the crossing with root `index` on the line (vertical, c), created on first use.
inline std::size_t Subdivision_topology::node(bool vertical, const Rational& c, int index) {
  const Node_key k{vertical, c, index};
  auto it = nodes_.find(k);
  if (it != nodes_.end()) return it->second;
  keys_.push_back(k);
  return nodes_[k] = keys_.size() - 1;
}

// The node of the singular point singular_[index], created on first use.
inline std::size_t Subdivision_topology::node_singular(std::size_t index) {
  Node_key k{false, Rational(0), int(index), true};
  auto it = nodes_.find(k);
  if (it != nodes_.end()) return it->second;
  keys_.push_back(k);
  return nodes_[k] = keys_.size() - 1;
}

// D restricted to the line u = c (vertical, a polynomial in v) or v = c (in u), and the derivative of D across
// that line restricted to it.
inline void Subdivision_topology::restriction(bool vertical, const Rational& c, Polynomial_1<Rational>& P,
                                              Polynomial_1<Rational>* Q) const {
  std::vector<Rational> p, q;
  if (!vertical) {  // v = c: p(u) = sum_j D_j(u) c^j, q(u) = sum_j j D_j(u) c^(j-1)
    std::vector<Rational> cp(1, Rational(1));
    for (int j = 1; j <= D_.degree(); ++j) cp.push_back(cp.back() * c);
    for (int j = 0; j <= D_.degree(); ++j)
      for (int i = 0; i <= D_[j].degree(); ++i) {
        if (CGAL::is_zero(D_[j][i])) continue;
        if (p.size() <= std::size_t(i)) p.resize(std::size_t(i + 1), Rational(0)), q.resize(std::size_t(i + 1), Rational(0));
        p[std::size_t(i)] += Rational(D_[j][i]) * cp[std::size_t(j)];
        if (j >= 1) q[std::size_t(i)] += Rational(D_[j][i]) * Rational(j) * cp[std::size_t(j - 1)];
      }
  } else {  // u = c: p(v) = sum_j D_j(c) v^j, q(v) = sum_j D_j'(c) v^j
    for (int j = 0; j <= D_.degree(); ++j) {
      Rational a(0), da(0);
      for (int i = D_[j].degree(); i >= 0; --i) {
        da = da * c + a;
        a = a * c + Rational(D_[j][i]);
      }
      p.push_back(a);
      q.push_back(da);
    }
  }
  if (p.empty()) p.push_back(Rational(0));
  if (q.empty()) q.push_back(Rational(0));
  P = Polynomial_1<Rational>(p.begin(), p.end());
  if (Q) *Q = Polynomial_1<Rational>(q.begin(), q.end());
}

// 1: from inside, 0: from outside, -1: undecided (a zero sign: cannot happen in a box simple across the edge)
inline int Subdivision_topology::contact_from_inside(bool vertical, const Rational& c, const Algebraic_real& x,
                                                     int multiplicity) const {
  Polynomial_1<Rational> P, Q;
  restriction(vertical, c, P, &Q);
  for (int k = 0; k < multiplicity; ++k) P = CGAL::differentiate(P);
  const int side = x.sign_of(P), across = x.sign_of(Q);
  // bottom / left edge: inside iff sign D(edge) = -sign(D across); top / right edge: iff the signs agree
  if (side == 0 || across == 0) return -1;
  const bool low_edge = vertical ? c == box_.u0 : c == box_.v0;
  return (low_edge ? side == -across : side == across) ? 1 : 0;
}

// Sign of D on the line (vertical: u = c, in v; else v = c, in u) just beyond the rational root x, on the side
// `direction` (+1 / -1): the sign of the first nonvanishing derivative there, times direction^order.
inline int Subdivision_topology::sign_next_to(bool vertical, const Rational& c, const Rational& x,
                                              int direction) const {
  Polynomial_1<Rational> P;
  restriction(vertical, c, P);
  for (int order = 0; !CGAL::is_zero(P); ++order, P = CGAL::differentiate(P)) {
    const int s = CGAL::sign(P.evaluate(x));
    if (s != 0) return order % 2 == 0 ? s : s * direction;
  }
  return 0;
}

// Collects the crossings of the edge (line `vertical` at c, other coordinate in [lo, hi]). Returns false if a
// crossing is at an end (a box corner) or multiple (tangency with the line).
// `touches` (only for a domain edge of a box that is simple across it): multiple roots strictly inside the edge
// are allowed there (see Touch and contact_from_inside) instead of making the box unresolved.
inline bool Subdivision_topology::edge_crossings(bool vertical, const Rational& c, const Rational& lo,
                                                 const Rational& hi, bool sort_by_u, std::vector<Crossing>& out,
                                                 std::vector<Touch>* touches, const Excluded_point* excluded) {
  const Line& L = line(vertical, c);
  if (failed_) return false;
  for (std::size_t k = 0; k < L.roots.size(); ++k) {
    const Algebraic_real& x = L.roots[k].root;
    const int cl = x.compare(lo), ch = x.compare(hi);
    if (cl < 0 || ch > 0) continue;
    if (excluded && excluded->on(vertical, c, x)) continue;
    if (L.roots[k].multiplicity > 1) {
      // at a domain corner, on an edge across which the box is simple: the curve is tangent to that edge at the
      // corner, decided by corner_crossing
      if (touches && (cl == 0 || ch == 0) && is_domain_corner(vertical, c, cl == 0 ? lo : hi)) continue;
      if (!touches || cl == 0 || ch == 0) return false;
      if (L.roots[k].multiplicity % 2 == 0) {  // the curve touches the edge without crossing it
        const int inside = contact_from_inside(vertical, c, x, L.roots[k].multiplicity);
        if (inside < 0) return false;
        touches->push_back(Touch{vertical, c, int(k), x, inside == 1});
        continue;
      }
      // odd multiplicity: a tangential crossing, an ordinary crossing for the topology (below)
    }
    if (cl == 0 || ch == 0) {  // at a box corner: domain corners are handled by corner_crossing
      if (!is_domain_corner(vertical, c, cl == 0 ? lo : hi)) {
        fail("the curve passes through a vertex of the subdivision grid");
        return false;
      }
      continue;
    }
    // the sorting coordinate: along a vertical line u = c is fixed, along a horizontal one u = x
    const bool coordinate_is_fixed = vertical == sort_by_u;
    out.push_back(Crossing{vertical, c, int(k), coordinate_is_fixed ? Algebraic_real(c) : x});
  }
  return true;
}

// (c, e) is a corner of the domain: c on a vertical (horizontal) domain side, e at an end of it.
inline bool Subdivision_topology::is_domain_corner(bool vertical, const Rational& c, const Rational& e) const {
  return (vertical ? (c == box_.u0 || c == box_.u1) : (c == box_.v0 || c == box_.v1)) &&
         (vertical ? (e == box_.v0 || e == box_.v1) : (e == box_.u0 || e == box_.u1));
}

// D, D_u, D_v at a rational point, exactly.
inline std::array<Rational, 3> Subdivision_topology::exact_jet(const Rational& u, const Rational& v) const {
  Rational d(0), du(0), dv(0);
  for (int j = D_.degree(); j >= 0; --j) {
    Rational p(0), dp(0);
    if (!CGAL::is_zero(D_[j]))
      for (int i = D_[j].degree(); i >= 0; --i) {
        dp = dp * u + p;
        p = p * u + Rational(D_[j][i]);
      }
    dv = dv * v + d;
    d = d * v + p;
    du = du * v + dp;
  }
  return {d, du, dv};
}

// The curve through the domain corner (cu, cv) of box B (D(cu, cv) = 0): a crossing if the curve enters the box
// there, i.e. a tangent direction (D_v, -D_u) points strictly into the box's quadrant at that corner.
// If the curve is tangent to a domain edge at the corner (D_v = 0 there: tangent to u = cu), first-order signs do
// not decide. In a box where dD/du != 0 (`simple` 2; 1: dD/dv != 0, 0: neither) the curve is a graph u = h(v)
// with h(cv) = cu, and D(cu, v) = D(h(v), v) + D_u (cu - h(v)) = D_u (cu - h(v)) (D_u at an intermediate point,
// of one sign on B): the side of h next to the corner is the exact sign of D on the edge there. Symmetrically for
// D_u = 0. If the curve does not enter the quadrant, the corner alone is a point of the locus in the domain (an
// isolated point on the boundary).
// `isolated` receives the nodes of corners that the curve passes from outside (the caller records them when it
// resolves the box).
inline bool Subdivision_topology::corner_crossing(const Box& B, const Rational& cu, const Rational& cv, bool sort_by_u,
                                                  int simple, std::vector<Crossing>& out,
                                                  std::vector<std::size_t>& isolated) {
  const auto e = exact_jet(cu, cv);  // D, D_u, D_v at the corner
  if (e[0] != 0) return true;
  const int tx = CGAL::sign(e[2]), ty = -CGAL::sign(e[1]);
  const int sx = cu == B.u0 ? 1 : -1, sy = cv == B.v0 ? 1 : -1;
  bool enters = false, tangent = false;
  if (tx != 0 && ty != 0) {
    enters = tx * sx == ty * sy;
  } else if ((tx == 0) != (ty == 0) && simple == (tx == 0 ? 2 : 1)) {
    // tangent to the edge u = cu (tx == 0: a graph u = h(v), the side of h - cu next to the corner) or to v = cv
    const bool on_u_line = tx == 0;
    const int s = on_u_line ? sign_next_to(true, cu, cv, sy) : sign_next_to(false, cv, cu, sx);
    if (s == 0) {
      fail("internal inconsistency: D vanishes on a domain edge");
      return false;
    }
    enters = -s * CGAL::sign(on_u_line ? e[1] : e[2]) == (on_u_line ? sx : sy);
    tangent = true;
  } else {
    fail(tx == 0 && ty == 0 ? "the curve is singular at a corner of the domain"
                            : "the curve is tangent to a domain edge at a corner of the domain");
    return false;
  }
  const Line& L = line(true, cu);
  for (std::size_t k = 0; k < L.roots.size(); ++k)
    if (L.roots[k].root.compare(cv) == 0) {
      const std::size_t n = node(true, cu, int(k));
      if (tangent) corner_tangent_.insert(n);
      if (enters)
        out.push_back(Crossing{true, cu, int(k), Algebraic_real(sort_by_u ? cu : cv)});
      else
        isolated.push_back(n);  // the corner alone: an isolated point of the locus in the domain
      return true;
    }
  fail("internal inconsistency: a corner root is missing on its line");
  return false;
}

// The crossings of the four edges of B, positioned along u (by_u) or v; false where edge_crossings refuses one.
inline bool Subdivision_topology::crossings_of_edges(const Box& B, bool by_u, std::vector<Crossing>& cr) {
  return edge_crossings(true, B.u0, B.v0, B.v1, by_u, cr) && edge_crossings(true, B.u1, B.v0, B.v1, by_u, cr) &&
         edge_crossings(false, B.v0, B.u0, B.u1, by_u, cr) && edge_crossings(false, B.v1, B.u0, B.u1, by_u, cr);
}

// The exact crossings of D = 0 with the four edges of B around a point inside it (sorted by u on horizontal
// edges), with the domain corners among B's corners; false if an edge or a corner cannot be handled.
// `excluded`: a singular point of the domain's boundary on B's edges, left out.
inline bool Subdivision_topology::crossings_around(const Box& B, std::vector<Crossing>& cr,
                                                   std::vector<std::size_t>& isolated_corners,
                                                   const Excluded_point* excluded) {
  if (!edge_crossings(true, B.u0, B.v0, B.v1, true, cr, nullptr, excluded) ||
      !edge_crossings(true, B.u1, B.v0, B.v1, true, cr, nullptr, excluded) ||
      !edge_crossings(false, B.v0, B.u0, B.u1, true, cr, nullptr, excluded) ||
      !edge_crossings(false, B.v1, B.u0, B.u1, true, cr, nullptr, excluded))
    return false;
  for (const Rational* cu : {&B.u0, &B.u1})
    for (const Rational* cv : {&B.v0, &B.v1})
      if ((*cu == box_.u0 || *cu == box_.u1) && (*cv == box_.v0 || *cv == box_.v1) &&
          !(excluded && excluded->u.compare(*cu) == 0 && excluded->v.compare(*cv) == 0) &&
          !corner_crossing(B, *cu, *cv, true, 0, cr, isolated_corners))
        return false;
  return true;
}

// The exact root of D on its line at the crossing c.
inline const Algebraic_real& Subdivision_topology::line_root(const Crossing& c) const {
  return lines_.at(std::make_pair(c.vertical, c.c)).roots[std::size_t(c.index)].root;
}

// A simple box: crossings sorted along u (dv != 0) or v (du != 0); consecutive pairs are arcs.
inline bool Subdivision_topology::resolve(const Box& B, bool dv_simple) {
  std::vector<Crossing> cr;
  std::vector<Touch> touches;
  const bool by_u = dv_simple;
  // contacts are allowed on the domain edges across which the box is simple (v = v0, v1 if dD/dv != 0)
  auto t_vertical = [&](const Rational& c) { return !dv_simple && (c == box_.u0 || c == box_.u1) ? &touches : nullptr; };
  auto t_horizontal = [&](const Rational& c) { return dv_simple && (c == box_.v0 || c == box_.v1) ? &touches : nullptr; };
  if (!edge_crossings(true, B.u0, B.v0, B.v1, by_u, cr, t_vertical(B.u0)) ||
      !edge_crossings(true, B.u1, B.v0, B.v1, by_u, cr, t_vertical(B.u1)) ||
      !edge_crossings(false, B.v0, B.u0, B.u1, by_u, cr, t_horizontal(B.v0)) ||
      !edge_crossings(false, B.v1, B.u0, B.u1, by_u, cr, t_horizontal(B.v1)))
    return false;
  std::vector<std::size_t> isolated_corners;
  for (const Rational* cu : {&B.u0, &B.u1})
    for (const Rational* cv : {&B.v0, &B.v1})
      if ((*cu == box_.u0 || *cu == box_.u1) && (*cv == box_.v0 || *cv == box_.v1) &&
          !corner_crossing(B, *cu, *cv, by_u, dv_simple ? 1 : 2, cr, isolated_corners))
        return false;
  if (cr.size() % 2 != 0) return false;  // cannot happen for a simple box; be safe and subdivide
  std::sort(cr.begin(), cr.end(), [](const Crossing& x, const Crossing& y) { return x.position < y.position; });
  std::sort(touches.begin(), touches.end(), [](const Touch& x, const Touch& y) { return x.position < y.position; });
  // a contact from inside lies on one arc (the graph passes through it): it splits that arc
  std::vector<std::vector<const Touch*>> on_arc(cr.size() / 2);
  for (const Touch& t : touches) {
    if (!t.inside) continue;
    bool placed = false;
    for (std::size_t k = 0; k + 1 < cr.size() && !placed; k += 2)
      if (cr[k].position < t.position && t.position < cr[k + 1].position) on_arc[k / 2].push_back(&t), placed = true;
    if (!placed) return false;  // not consistent with a graph: subdivide instead
  }
  for (std::size_t k = 0; k + 1 < cr.size(); k += 2) {
    std::size_t from = node(cr[k].vertical, cr[k].c, cr[k].index);
    Algebraic_real from_pos = cr[k].position;
    auto add = [&](std::size_t to, const Algebraic_real& to_pos) {
      Arc arc{from, to, {}, Parameter_box{B.u0, B.u1, B.v0, B.v1}, by_u ? 0 : 1};
      sample_arc(B, by_u, from_pos, to_pos, arc.inner);
      arcs_.push_back(arc);
      from = to;
      from_pos = to_pos;
    };
    for (const Touch* t : on_arc[k / 2]) {
      const std::size_t n = node(t->vertical, t->c, t->index);
      touch_[n] = 2;
      add(n, t->position);
    }
    add(node(cr[k + 1].vertical, cr[k + 1].c, cr[k + 1].index), cr[k + 1].position);
  }
  for (const Touch& t : touches)
    if (!t.inside) touch_[node(t.vertical, t.c, t.index)] = 0;  // the contact point alone: an isolated point
  for (std::size_t n : isolated_corners) touch_[n] = 0;
  return true;
}

// A box proved free of genuine points: its edge crossings become phantom_cut vertices (the arcs of the
// neighbouring boxes end there). False (the box is then split) if a crossing is at a corner or multiple.
inline bool Subdivision_topology::excise(const Box& B) {
  // edges on the domain boundary have no neighbour: their crossings (even multiple ones) do not matter
  std::vector<Crossing> cr;
  if ((B.u0 != box_.u0 && !edge_crossings(true, B.u0, B.v0, B.v1, true, cr)) ||
      (B.u1 != box_.u1 && !edge_crossings(true, B.u1, B.v0, B.v1, true, cr)) ||
      (B.v0 != box_.v0 && !edge_crossings(false, B.v0, B.u0, B.u1, true, cr)) ||
      (B.v1 != box_.v1 && !edge_crossings(false, B.v1, B.u0, B.u1, true, cr)))
    return false;
  for (const Crossing& c : cr) cut_.insert(node(c.vertical, c.c, c.index));
  excised_.push_back(Parameter_box{B.u0, B.u1, B.v0, B.v1});
  return true;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_TOPOLOGY_INTERNAL_SUBDIVISION_CROSSINGS_H
