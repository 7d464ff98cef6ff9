// Certified topology of a real plane algebraic curve D(u,v) = 0 inside an axis-parallel box with rational
// corners: every connected component (closed loops included), singular points with the number of real
// branches through them, isolated points, and the points where the curve meets the box boundary.
//
// Method: the arrangement of D = 0 and the four box lines, computed by CGAL's Arr_algebraic_segment_traits_2
// (cylindrical algebraic decomposition with exact algebraic numbers, Curve_analysis_2). Every edge of the
// arrangement lies entirely inside or outside the box because the box lines are part of it; a sample point
// of each edge at a rational abscissa decides which, exactly. Singular points are decided by the exact signs
// of dD/du and dD/dv at the algebraic vertex (buse-elkadi-galligo-2008 §4 asks for the critical points of D:
// the arrangement has a vertex at each of them, since x-monotone pieces end there).
//
// This header includes CGAL's algebraic curve kernel and Arrangement_2: include it in few translation units (it
// is expensive to compile). The surface intersection reaches it only through the opt-in policy
// Cgal_curve_analysis (end of this file), set in Surface_intersection_options::whole_plane_topology. Whole-plane curve analysis is exact but its cost grows fast with the degree; see
// doc/surface_intersection.md for the sizes where it is practical.
#ifndef BEZOUTIAN_TOPOLOGY_CGAL_CURVE_ANALYSIS_H
#define BEZOUTIAN_TOPOLOGY_CGAL_CURVE_ANALYSIS_H

#include <bezoutian/topology/Curve_topology.h>
#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/arithmetic/number_types.h>

#include <CGAL/Arr_algebraic_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

namespace bezoutian {

namespace internal {

struct Box_arrangement {
  using Traits = CGAL::Arr_algebraic_segment_traits_2<Integer>;
  using Arrangement = CGAL::Arrangement_2<Traits>;
  using Curve_2 = Traits::Curve_2;
  using Point_2 = Traits::Point_2;
  using X_monotone_curve_2 = Traits::X_monotone_curve_2;
  using Polynomial_2 = Traits::Polynomial_2;
  using Algebraic_real_1 = Traits::Algebraic_real_1;
  using Bound = Traits::Bound;
};

// Integer line q*x - p through x = p/q, in variable 0 (u) or 1 (v).
inline Box_arrangement::Polynomial_2 box_line(const Rational& c, int variable) {
  using P2 = Box_arrangement::Polynomial_2;
  const P2 x = CGAL::shift(P2(1), 1, variable);
  return P2(c.denominator()) * x - P2(c.numerator());
}

template <class Xy>
std::pair<Rational, Rational> y_enclosure(Xy xy, const Rational& width) {
  while (Rational(xy.upper_bound_y()) - Rational(xy.lower_bound_y()) > width) xy.refine_y();
  return {Rational(xy.lower_bound_y()), Rational(xy.upper_bound_y())};
}

template <class Alg>
std::pair<Rational, Rational> x_enclosure(Alg x, const Rational& width) {
  while (Rational(x.high()) - Rational(x.low()) > width) x.refine();
  return {Rational(x.low()), Rational(x.high())};
}

// Exact comparison of the y-coordinate of an algebraic point with a rational, given that they differ or are
// equal; equality is decided exactly through the point's defining curve restricted to y = c.
template <class Point>
int compare_y_with(const Point& p, const Rational& c) {
  auto xy = p.xy();
  for (int i = 0; i < 200; ++i) {
    if (Rational(xy.upper_bound_y()) < c) return -1;
    if (c < Rational(xy.lower_bound_y())) return 1;
    if (i > 4) break;
    xy.refine_y();
  }
  // possibly equal: decide exactly with the kernel (compare with the point (x, c) on the line v = c)
  using K = Box_arrangement::Traits;
  auto kernel = K::Algebraic_kernel_d_2();
  auto line = kernel.construct_curve_2_object()(box_line(c, 1));
  typename Box_arrangement::Point_2 q(p.x(), line, 0);
  return int(kernel.compare_xy_2_object()(p.xy(), q.xy()));
}

} // namespace internal

/// \brief Analyses D(u,v) = 0 inside `box` (u = inner variable of Polynomial_2, v = outer).
/// `samples_per_edge` certified points (exact abscissae, ordinates refined to `tolerance`) are placed on each arc.
/// Throws Invalid_input if D is zero or the box is empty.
inline Curve_topology_in_box analyse_curve_in_box(const Polynomial_2<Integer>& D, const Parameter_box& box,
                                                  double tolerance = 1e-6, int samples_per_edge = 24) {
  using A = internal::Box_arrangement;
  if (CGAL::is_zero(D)) throw Invalid_input("analyse_curve_in_box: the polynomial is identically zero");
  if (!(box.u0 < box.u1) || !(box.v0 < box.v1)) throw Invalid_input("analyse_curve_in_box: empty box");

  A::Traits traits;
  A::Arrangement arr(&traits);
  auto make_curve = traits.construct_curve_2_object();
  const A::Polynomial_2 lines[4] = {internal::box_line(box.u0, 0), internal::box_line(box.u1, 0),
                                    internal::box_line(box.v0, 1), internal::box_line(box.v1, 1)};
  std::vector<A::Curve_2> curves = {make_curve(D)};
  for (const auto& l : lines) curves.push_back(make_curve(l));
  CGAL::insert(arr, curves.begin(), curves.end());

  auto kernel = A::Traits::Algebraic_kernel_d_2();
  using PT = CGAL::Polynomial_traits_d<Polynomial_2<Integer>>;
  const Polynomial_2<Integer> Du = PT::Differentiate()(D, 0), Dv = PT::Differentiate()(D, 1);
  const Rational tol(Integer(1), Integer(1) << 40);  // enclosure width for reported coordinates

  // Does D vanish identically on box line i? (Then that side of the box is part of the curve.)
  bool on_line[4];
  for (int i = 0; i < 2; ++i) {
    const Rational c = i == 0 ? box.u0 : box.u1;  // D(c, v) == 0 for all v
    bool zero = true;
    for (int j = 0; j <= D.degree() && zero; ++j) zero = CGAL::is_zero(Polynomial_1<Rational>(D[j].begin(), D[j].end()).evaluate(c));
    on_line[i] = zero;
  }
  for (int i = 2; i < 4; ++i) {
    const Rational c = i == 2 ? box.v0 : box.v1;  // D(u, c) == 0 for all u
    Polynomial_1<Rational> r(0);
    for (int j = D.degree(); j >= 0; --j) r = r * Polynomial_1<Rational>(c) + Polynomial_1<Rational>(D[j].begin(), D[j].end());
    on_line[i] = CGAL::is_zero(r);
  }
  // Is this x-monotone curve a piece of a box line? Its supporting polynomial is then the line up to a
  // constant factor; if D vanishes on that line too, the piece belongs to the curve as well.
  auto is_box_line = [&](const A::X_monotone_curve_2& c) {
    const A::Polynomial_2& f = c.curve().polynomial_2();
    for (int i = 0; i < 4; ++i) {
      const auto& l = lines[i];
      if (f.degree() == l.degree() && CGAL::is_zero(f * l.lcoeff().lcoeff() - l * f.lcoeff().lcoeff()))
        return !on_line[i];
    }
    return false;
  };
  auto x_compare = [&](const A::Algebraic_real_1& x, const Rational& c) {
    return CGAL::compare(x, A::Algebraic_real_1(A::Bound(c)));
  };

  Curve_topology_in_box out;
  out.box = box;
  std::map<const void*, std::size_t> vertex_index;
  auto vertex_id = [&](A::Arrangement::Vertex_const_handle v) {
    auto it = vertex_index.find(&*v);
    if (it != vertex_index.end()) return it->second;
    Curve_topology_vertex cv;
    const A::Point_2& p = v->point();
    auto xe = internal::x_enclosure(p.x(), tol);
    auto ye = internal::y_enclosure(p.xy(), tol);
    cv.u_lo = CGAL::to_interval(xe.first).first;
    cv.u_hi = CGAL::to_interval(xe.second).second;
    cv.v_lo = CGAL::to_interval(ye.first).first;
    cv.v_hi = CGAL::to_interval(ye.second).second;
    cv.u = 0.5 * (cv.u_lo + cv.u_hi);
    cv.v = 0.5 * (cv.v_lo + cv.v_hi);
    // on the boundary iff a box-line edge passes through the vertex
    if (!v->is_isolated()) {
      auto h = v->incident_halfedges(), first = h;
      do {
        if (is_box_line(h->curve())) cv.on_boundary = true;
      } while (++h != first);
    }
    if (cv.on_boundary) {
      cv.kind = Curve_topology_vertex::boundary;
    } else if (kernel.sign_at_2_object()(kernel.construct_curve_2_object()(Du), p.xy()) == CGAL::ZERO &&
               kernel.sign_at_2_object()(kernel.construct_curve_2_object()(Dv), p.xy()) == CGAL::ZERO) {
      cv.kind = Curve_topology_vertex::singular;
    }
    out.vertices.push_back(cv);
    vertex_index[&*v] = out.vertices.size() - 1;
    return out.vertices.size() - 1;
  };

  // D edges inside the box
  for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e) {
    const A::X_monotone_curve_2& c = e->curve();
    if (is_box_line(c)) continue;
    if (e->source()->is_at_open_boundary() || e->target()->is_at_open_boundary()) continue;
    const A::Point_2 &ps = e->source()->point(), &pt = e->target()->point();
    // x-range inside [u0,u1]
    const A::Algebraic_real_1 &xs = ps.x(), &xt = pt.x();
    const A::Algebraic_real_1& xl = CGAL::compare(xs, xt) == CGAL::SMALLER ? xs : xt;
    const A::Algebraic_real_1& xr = CGAL::compare(xs, xt) == CGAL::SMALLER ? xt : xs;
    if (x_compare(xl, box.u0) == CGAL::SMALLER || x_compare(xr, box.u1) == CGAL::LARGER) continue;
    // a sample point in the interior of the edge decides the side of the horizontal lines
    A::Point_2 sample = ps;
    if (c.is_vertical()) {
      // a vertical edge lies on a vertical line component of D; its endpoints' ordinates bound it
      if (internal::compare_y_with(ps, box.v0) < 0 || internal::compare_y_with(pt, box.v0) < 0 ||
          internal::compare_y_with(ps, box.v1) > 0 || internal::compare_y_with(pt, box.v1) > 0)
        continue;
    } else {
      const A::Bound xm = kernel.bound_between_1_object()(xl, xr);
      sample = A::Point_2(A::Algebraic_real_1(xm), c.curve(), c.arcno());
      if (internal::compare_y_with(sample, box.v0) < 0 || internal::compare_y_with(sample, box.v1) > 0) continue;
    }
    Curve_topology_edge ce;
    ce.source = vertex_id(e->source());
    ce.target = vertex_id(e->target());
    // certified samples: exact rational abscissae between the ends (clustered at the ends, where arcs
    // are steep near vertical tangents), ordinates refined to the tolerance
    const Curve_topology_vertex &vs = out.vertices[ce.source], &vt = out.vertices[ce.target];
    ce.polyline.push_back({vs.u, vs.v});
    if (!c.is_vertical()) {
      const bool forward = CGAL::compare(xs, xt) == CGAL::SMALLER;
      const Rational a = Rational(internal::x_enclosure(xl, tol).second), b = Rational(internal::x_enclosure(xr, tol).first);
      const Rational ytol(std::max(tolerance, 1e-15));
      std::vector<std::array<double, 2>> inner;
      for (int i = 1; i < samples_per_edge; ++i) {
        const double th = M_PI * i / samples_per_edge;
        const Rational f(0.5 - 0.5 * std::cos(th));  // exact double converted to rational
        const Rational x = a + (b - a) * f;
        if (!(a < x && x < b)) continue;
        A::Point_2 q(A::Algebraic_real_1(A::Bound(x)), c.curve(), c.arcno());
        auto ye = internal::y_enclosure(q.xy(), ytol);
        inner.push_back({CGAL::to_double(x), CGAL::to_double((ye.first + ye.second) / Rational(2))});
      }
      if (!forward) std::reverse(inner.begin(), inner.end());
      ce.polyline.insert(ce.polyline.end(), inner.begin(), inner.end());
    }
    ce.polyline.push_back({vt.u, vt.v});
    out.edges.push_back(ce);
  }

  // isolated points of D inside the box (acnodes): isolated vertices of the arrangement
  for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v) {
    if (!v->is_isolated()) continue;
    const A::Point_2& p = v->point();
    if (x_compare(p.x(), box.u0) == CGAL::SMALLER || x_compare(p.x(), box.u1) == CGAL::LARGER) continue;
    if (internal::compare_y_with(p, box.v0) < 0 || internal::compare_y_with(p, box.v1) > 0) continue;
    const std::size_t id = vertex_id(v);
    out.vertices[id].kind = Curve_topology_vertex::isolated;
    Curve_topology_component comp;
    comp.isolated_point = true;
    comp.closed = !out.vertices[id].on_boundary;
    comp.vertices.push_back(id);
    out.components.push_back(comp);
  }

  internal::assign_components(out);  // half-branch counts and components of the inside edges
  return out;
}

/// The whole-plane topology policy of Surface_intersection_options::whole_plane_topology: CGAL's curve analysis
/// (analyse_curve_in_box), tried where the subdivision does not certify. Opt-in, because it brings CGAL's algebraic
/// kernel into the translation unit and its running time is not bounded.
struct Cgal_curve_analysis {
  Curve_topology_in_box operator()(const Polynomial_2<Integer>& D, const Parameter_box& box, double tolerance,
                                   int samples_per_edge) const {
    return analyse_curve_in_box(D, box, tolerance, samples_per_edge);
  }
};

} // namespace bezoutian

#endif // BEZOUTIAN_TOPOLOGY_CGAL_CURVE_ANALYSIS_H
