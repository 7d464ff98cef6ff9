// Surface self-intersection and intersection loci: the worked example of buse-elkadi-galligo-2008 §4, a patch
// folded over itself whose double curve is known in closed form, a patch without self-intersection, and two
// patches crossing along a known curve.
#include <catch2/catch.hpp>

#include "test_support.h"

#include <bezoutian/intersection/Surface_intersection.h>
#include <bezoutian/io/Geometry_document.h>
#include "power_patch.h"
#include "../../benchmark/random_patches.h"

#include <set>
#include <vector>
#include <string>
#include <array>
#include <functional>
#include <cmath>
#include <algorithm>

using namespace bezoutian;
using Q = Rational;
using Patch = Rational_bezier_patch<>;

namespace {
Patch from_power(const std::array<std::string, 3>& xyz, int m, int n) {
  return bezoutian_test::patch_from_power(xyz, m, n);
}
}  // namespace

TEST_CASE("worked example: triple point with three branches and three partners", "[surface][seed]") {
  auto doc = io::read_geometry_file(bezoutian_test::source_file("examples/data/bezoutian_worked_example.json"));
  Surface_intersection_options o;
  o.box = Parameter_box{Q(-11, 10), Q(-1), Q(-1, 10), Q(0)};
  o.partner_domain_unbounded = true;
  Surface_locus L = self_intersection_locus(doc.patches[0], o);
  CHECK(L.equation.matrix.size() == 3);
  // the whole 3 x 3 matrix vanishes at the triple point: the subdivision resolves it (no whole-plane analysis)
  CHECK(L.topology_method == "subdivision");
  REQUIRE(L.topology.number_of_singular_points() == 1);
  std::size_t sv = 0;
  for (std::size_t i = 0; i < L.topology.vertices.size(); ++i)
    if (L.topology.vertices[i].kind == Curve_topology_vertex::singular) sv = i;
  CHECK(L.topology.vertices[sv].branches == 3);
  // every traced point is a true double point: both preimages map to the same 3D point
  for (const auto& arc : L.arcs)
    for (const auto& q : arc.points) {
      REQUIRE(q.lifted);
      CHECK(q.residual < 1e-6);
      CHECK(std::fabs(q.partner[0]) + std::fabs(q.partner[1]) > 1e-3);
      CHECK(q.genuine);  // verified residual, partner unrestricted (--domain none)
    }
  // at the triple point the six half-branches carry three distinct partners (three sheets cross pairwise)
  std::vector<std::array<double, 2>> partners;
  for (const auto& arc : L.arcs) {
    if (arc.source == sv) partners.push_back(arc.points.front().partner);
    if (arc.target == sv) partners.push_back(arc.points.back().partner);
  }
  REQUIRE(partners.size() == 6);
  std::vector<std::array<double, 2>> distinct;
  for (const auto& p : partners) {
    bool seen = false;
    for (const auto& d : distinct) seen |= std::hypot(p[0] - d[0], p[1] - d[1]) < 1e-5;
    if (!seen) distinct.push_back(p);
  }
  CHECK(distinct.size() == 3);
}

TEST_CASE("a patch covering its image twice is reported; a pinch double curve is lifted", "[surface]") {
  // Phi(u,v) = (u, (v - 1/2)^2, (v - 1/2) u^2 ... ) would not self-intersect; instead fold in v:
  // Phi(u,v) = (u, (2v-1)^2, u (2v-1)^2): Phi(u,v) = Phi(u,1-v) for every (u,v): a patch covering its image
  // twice has det B = 0 identically, reported as a degenerate input.
  Patch fold = from_power({"u", "(2*v-1)^2", "u*(2*v-1)^2 + u^2"}, 2, 2);
  CHECK_THROWS_AS(self_intersection_locus(fold), Invalid_input);
  // Whitney-umbrella-like patch X = u v, Y = v, Z = u^2 (degree (2,1)) pinches along the segment Y = 0:
  // Phi(u,0) = Phi(-u,0): the double curve is v = 0 with partner l = -2u, k = 0.
  Patch umbrella = from_power({"u*v + v^2", "v", "u^2"}, 2, 2);
  Surface_intersection_options o;
  o.box = Parameter_box{Q(-1, 2), Q(1, 2), Q(-1, 3), Q(1, 3)};
  o.partner_domain_unbounded = true;
  Surface_locus L = self_intersection_locus(umbrella, o);
  // the genuine double curve v = 0 must be in the locus: an arc along v = 0 with partner l = -2u, k = 0
  bool found = false;
  for (const auto& arc : L.arcs)
    for (const auto& q : arc.points)
      if (q.lifted && std::fabs(q.projection[1]) < 1e-9 && std::fabs(q.projection[0]) > 0.05) {
        found = true;
        CHECK(q.partner[0] == Approx(-2 * q.projection[0]).margin(1e-6));
        CHECK(q.partner[1] == Approx(0).margin(1e-6));
      }
  CHECK(found);
}

TEST_CASE("a paraboloid and a bent paraboloid cross along a closed curve", "[surface]") {
  // Phi(u,v) = (u, v, u^2 + v^2), Psi(s,t) = (s + s^2, t, 1 - s^2 - t^2): Phi(u,v) = Psi(s,t) iff u = s + s^2,
  // v = t and (s + s^2)^2 + t^2 = 1 - s^2 - t^2, a closed curve. Two plain paraboloids have parallel leading
  // coefficient vectors and a common point at infinity: det B = 0; they are two height fields over one square, and
  // meet where u^2 + v^2 = 1/2 (intersection/Patch_common_projection.h): a quarter circle across [0,1]^2.
  Patch phi = from_power({"u", "v", "u^2 + v^2"}, 2, 2);
  Patch psi = from_power({"u + u^2", "v", "1 - u^2 - v^2"}, 2, 2);
  Patch flat = from_power({"u", "v", "1 - u^2 - v^2"}, 2, 2);
  CHECK(intersection_equation(phi, flat).is_degenerate());
  const Surface_locus F = intersection_locus(phi, flat);
  REQUIRE(F.topology_computed);
  REQUIRE(F.topology.components.size() == 1);
  CHECK_FALSE(F.topology.components[0].closed);
  CHECK(F.topology.number_of_boundary_points() == 2);
  for (const auto& arc : F.arcs)
    for (const auto& q : arc.points) {
      CHECK(q.genuine);
      CHECK(std::fabs(q.projection[0] * q.projection[0] + q.projection[1] * q.projection[1] - 0.5) < 1e-8);
    }
  Surface_intersection_options o;
  o.box = Parameter_box{Q(-2), Q(2), Q(-2), Q(2)};
  o.partner_domain = o.box;
  Surface_locus L = intersection_locus(phi, psi, o);
  REQUIRE(L.topology.components.size() >= 1);
  std::size_t checked = 0, points = 0, proved_genuine = 0;
  for (const auto& arc : L.arcs)
    for (const auto& q : arc.points) {
      ++points;
      proved_genuine += q.status_proved && q.genuine;
      CHECK(!(q.status_proved && !q.genuine));  // the whole curve is genuine (partners inside [-2, 2]^2)
      if (!q.lifted || q.residual > 1e-8) continue;
      const double u = q.projection[0], t = q.projection[1], v = q.partner[0], s = q.partner[1];
      CHECK(v == Approx(t).margin(1e-7));
      CHECK(u == Approx(s + s * s).margin(1e-7));
      CHECK(u * u + v * v == Approx(1 - s * s - t * t).margin(1e-7));
      ++checked;
    }
  CHECK(checked > 20);
  CHECK(proved_genuine >= points * 9 / 10);  // the certified lifting covers (nearly) the whole curve
  bool closed = false;
  for (const auto& c : L.topology.components) closed |= c.closed;
  CHECK(closed);
}

// The teapot's patches are glued edge to edge: the contacts must be found exactly. Independent check: a shared
// edge means the two rows of control points coincide (possibly reversed), read directly from the data file.
TEST_CASE("teapot: shared boundary curves and touching corners are reported as contacts", "[surface][teapot]") {
  const auto doc = io::read_geometry_file(bezoutian_test::shared_data("teapot/teapot32.bpt"));
  REQUIRE(doc.patches.size() == 32);
  using Curve = Rational_bezier_curve_3<Rational>;
  auto same_row = [](const Curve& a, const Curve& b) {
    bool fwd = true, bwd = true;
    const std::size_t n = a.number_of_control_points();
    if (n != b.number_of_control_points()) return false;
    for (std::size_t i = 0; i < n; ++i) {
      fwd = fwd && a.control_point(i) == b.control_point(i);
      bwd = bwd && a.control_point(i) == b.control_point(n - 1 - i);
    }
    return fwd || bwd;
  };
  int shared_edges = 0, corner_points = 0;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = i + 1; j < 8; ++j) {
      const auto contacts = boundary_contacts(doc.patches[i], doc.patches[j]);
      for (const auto& c : contacts) {
        INFO("patches " << i << ", " << j << " sides " << c.side_first << ", " << c.side_second);
        const Curve a = doc.patches[i].boundary_curve<Curve>(c.side_first);
        const Curve b = doc.patches[j].boundary_curve<Curve>(c.side_second);
        if (c.shared_curve) {
          ++shared_edges;
          CHECK(same_row(a, b));  // the whole edge is shared in the teapot
          CHECK(((c.first_0 == 0 && c.first_1 == 1) || (c.first_0 == 1 && c.first_1 == 0)));
        } else {
          ++corner_points;  // an exact common point: rational parameters, equal exact points
          REQUIRE(c.first_0.is_rational());
          REQUIRE(c.second_0.is_rational());
          CHECK(a(c.first_0.rational_value()) == b(c.second_0.rational_value()));
        }
      }
      // conversely: every pair of identical boundary rows is reported as a shared edge
      for (int s1 = 0; s1 < 4; ++s1)
        for (int s2 = 0; s2 < 4; ++s2) {
          const Curve a = doc.patches[i].boundary_curve<Curve>(s1), b = doc.patches[j].boundary_curve<Curve>(s2);
          bool degenerate = true;
          for (std::size_t k = 1; k < a.number_of_control_points(); ++k)
            degenerate = degenerate && a.control_point(k) == a.control_point(0);
          if (degenerate || !same_row(a, b)) continue;
          bool reported = false;
          for (const auto& c : contacts) reported = reported || (c.shared_curve && c.side_first == s1 && c.side_second == s2);
          CHECK(reported);
        }
    }
  CHECK(shared_edges >= 8);
  CHECK(corner_points >= 4);
}

// A node of the projected intersection curve at an irrational point, proved by two partners. Phi(u,v) = (u, v, 0),
// Psi(s,t) = (s^2 + (t^2 - 1/2) s, t, s^2 - t - 1/4): Phi = Psi iff v = t, s^2 = t + 1/4, u = t + 1/4 + (t^2 - 1/2) s,
// so D(u,t) = (u - t - 1/4)^2 - (t + 1/4)(t^2 - 1/2)^2 (up to a constant): two branches u = t + 1/4 +- sqrt(t + 1/4)
// (t^2 - 1/2) crossing at t = 1/sqrt(2), u = t + 1/4, with the two partners s = +-sqrt(t + 1/4).
TEST_CASE("an irrational node of the intersection curve is certified by its two partners", "[surface][singular]") {
  Patch phi = from_power({"u", "v", "0"}, 2, 2);
  Patch psi = from_power({"u^2 + u*(v^2 - 1/2)", "v", "u^2 - v - 1/4"}, 2, 2);
  Surface_intersection_options o;
  o.box = Parameter_box{Q(1, 10), Q(1), Q(1, 10), Q(9, 10)};
  o.partner_domain_unbounded = true;
  Surface_locus L = intersection_locus(phi, psi, o);
  // the implicit equation is the closed form above (primitive, up to sign)
  const Polynomial_2<Integer> u = CGAL::shift(Polynomial_2<Integer>(1), 1, 0),
                              t = CGAL::shift(Polynomial_2<Integer>(1), 1, 1);
  const Polynomial_2<Integer> expected = (16 * u - 16 * t - 4) * (16 * u - 16 * t - 4) -
                                         16 * (4 * t + 1) * (2 * t * t - 1) * (2 * t * t - 1);
  const auto& D = L.equation.square_free;
  CHECK((D == CGAL::canonicalize(expected) || D == -CGAL::canonicalize(expected) ||
         CGAL::canonicalize(D) == CGAL::canonicalize(expected)));
  INFO(L.note);
  REQUIRE(L.topology_computed);
  CHECK(L.topology_method == "subdivision");
  REQUIRE(L.topology.number_of_singular_points() == 1);
  const double tn = std::sqrt(0.5), un = tn + 0.25;
  for (const auto& w : L.topology.vertices)
    if (w.kind == Curve_topology_vertex::singular) {
      CHECK(w.branches == 2);
      CHECK(w.u_lo <= un);
      CHECK(un <= w.u_hi);
      CHECK(w.v_lo <= tn);
      CHECK(tn <= w.v_hi);
      CHECK(w.u_hi - w.u_lo < 1e-12);
    }
  CHECK(L.topology.components.size() == 1);
  // without the partners' witness the subdivision cannot prove D = 0 at the node
  Subdivision_topology_options plain;
  const auto r = subdivide_curve_in_box(D, o.box, plain);
  CHECK_FALSE(r.certified);
  // every traced point lifts to the closed form
  std::size_t checked = 0;
  for (const auto& arc : L.arcs)
    for (const auto& q : arc.points) {
      if (!q.lifted || q.residual > 1e-8) continue;
      const double uu = q.projection[0], tt = q.projection[1], s = q.partner[1];
      CHECK(s * s == Approx(tt + 0.25).margin(1e-7));
      CHECK(uu == Approx(tt + 0.25 + (tt * tt - 0.5) * s).margin(1e-7));
      ++checked;
    }
  CHECK(checked > 20);
}

// The handle and the spout enter the body (data README: "handle/body and spout/body intersect in closed curves;
// check topology, symmetry about y = 0, and that points lie on both surfaces"). Each end is cut by a pair of
// mirror-image tube patches (12/13: handle top; 16/17: spout base) through mirror-image body patches. Every pair
// must be certified; the genuine runs of traced points must lie on both patches, chain up into one closed curve
// (run ends meet other run ends; ends on the seam y = 0 are the exact boundary contacts), and the curve must be
// symmetric about y = 0.
namespace {
using Run = std::vector<std::array<double, 3>>;
double distance3(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::hypot(a[0] - b[0], std::hypot(a[1] - b[1], a[2] - b[2]));
}
double to_polyline(const std::array<double, 3>& p, const Run& poly) {
  double best = 1e300;
  for (std::size_t i = 0; i + 1 < poly.size(); ++i) {
    const std::array<double, 3> d{poly[i + 1][0] - poly[i][0], poly[i + 1][1] - poly[i][1], poly[i + 1][2] - poly[i][2]};
    const double len2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    double t = len2 > 0 ? ((p[0] - poly[i][0]) * d[0] + (p[1] - poly[i][1]) * d[1] + (p[2] - poly[i][2]) * d[2]) / len2 : 0;
    t = std::max(0.0, std::min(1.0, t));
    best = std::min(best, distance3(p, {poly[i][0] + t * d[0], poly[i][1] + t * d[1], poly[i][2] + t * d[2]}));
  }
  return best;
}
// Every `stride`-th traced point lies on D = 0: first-order distance |D| / |grad D| < 1e-6, with D and its gradient
// evaluated exactly at the point's double coordinates (independent of the floating-point sampling that produced
// the point). Samples bisected on the power form of a high-degree D would be off the curve.
void check_traced_points_on_curve(const Surface_locus& L, std::size_t stride) {
  const Polynomial_2<Integer>& D = L.equation.square_free;
  for (const auto& arc : L.arcs)
    for (std::size_t i = 0; i < arc.points.size(); i += stride) {
      const Q x(arc.points[i].projection[0]), y(arc.points[i].projection[1]);
      Q f(0), fx(0), fy(0);  // Horner in y over the rows c_j(x), c_j'(x)
      for (int j = D.degree(); j >= 0; --j) {
        Q c(0), cx(0);
        for (int k = D[j].degree(); k >= 0; --k) {
          cx = cx * x + c;
          c = c * x + Q(D[j][k]);
        }
        fy = fy * y + f;
        f = f * y + c;
        fx = fx * y + cx;
      }
      const double g = std::sqrt(CGAL::to_double(fx * fx + fy * fy));
      CHECK(std::fabs(CGAL::to_double(f)) <= 1e-6 * g);
    }
}
// genuine runs (at least 2 points) of the certified intersection of two teapot patches, checked on both patches;
// also the exact contact points
void genuine_runs(const std::vector<Patch>& patches, int a, int b, std::vector<Run>& runs,
                  std::vector<std::array<double, 3>>& contacts) {
  const Patch& phi = patches[a];
  const Patch& psi = patches[b];
  Surface_locus L = intersection_locus(phi, psi);
  INFO("patches " << a << " x " << b << ": " << L.note);
  REQUIRE(L.topology_computed);
  CHECK(L.topology_method == "subdivision");
  for (const auto& c : L.contacts) {
    CHECK_FALSE(c.shared_curve);  // handle and spout are not glued to the body: isolated contacts
    contacts.push_back(c.point);
  }
  check_traced_points_on_curve(L, 8);
  // the genuine runs are (nearly all) proved genuine; a point whose partner is on the partner's boundary (a contact
  // of the two patches' boundaries, reported exactly in L.contacts) cannot be proved inside the partner domain
  std::size_t genuine = 0, genuine_proved = 0;
  for (const auto& arc : L.arcs)
    for (const auto& q : arc.points) {
      bool at_contact = false;
      for (const auto& c : L.contacts) at_contact = at_contact || distance3(phi.evaluate(q.first[0], q.first[1]), c.point) < 1e-9;
      if (at_contact) continue;
      genuine += q.genuine, genuine_proved += q.genuine && q.status_proved;
    }
  CHECK(genuine_proved >= genuine * 9 / 10);
  for (const auto& arc : L.arcs)
    for (std::size_t i = 0; i < arc.points.size();) {
      if (!arc.points[i].genuine) {
        ++i;
        continue;
      }
      Run run;
      for (; i < arc.points.size() && arc.points[i].genuine; ++i) {
        const auto& q = arc.points[i];
        const auto p1 = phi.evaluate(q.first[0], q.first[1]), p2 = psi.evaluate(q.second[0], q.second[1]);
        CHECK(distance3(p1, p2) < 1e-7);  // on both patches, independently evaluated
        for (double c : {q.first[0], q.first[1], q.second[0], q.second[1]}) {
          CHECK(c >= -1e-9);
          CHECK(c <= 1 + 1e-9);
        }
        run.push_back(p1);
      }
      if (run.size() >= 2) runs.push_back(run);
    }
}
void check_closed_symmetric_curve(const std::vector<Patch>& patches, const std::vector<std::pair<int, int>>& side_a,
                                  const std::vector<std::pair<int, int>>& side_b, std::size_t min_points) {
  std::vector<Run> runs[2];
  std::vector<std::array<double, 3>> contacts;
  for (int k = 0; k < 2; ++k)
    for (const auto& pr : k == 0 ? side_a : side_b) genuine_runs(patches, pr.first, pr.second, runs[k], contacts);
  std::vector<Run> all(runs[0]);
  all.insert(all.end(), runs[1].begin(), runs[1].end());
  std::size_t points = 0;
  double step = 0;  // the sampling step along the runs
  for (const auto& r : all) {
    points += r.size();
    for (std::size_t i = 0; i + 1 < r.size(); ++i) step = std::max(step, distance3(r[i], r[i + 1]));
  }
  CHECK(points >= min_points);
  CHECK(step < 0.05);
  // closed: every run end meets exactly one end of another run; ends on y = 0 are exact boundary contacts
  for (std::size_t i = 0; i < all.size(); ++i)
    for (const auto& end : {all[i].front(), all[i].back()}) {
      int meets = 0;
      for (std::size_t j = 0; j < all.size(); ++j)
        if (j != i)
          for (const auto& other : {all[j].front(), all[j].back()}) meets += distance3(end, other) <= 2 * step;
      CHECK(meets == 1);
      if (std::abs(end[1]) < 1e-9) {
        double best = 1e300;
        for (const auto& c : contacts) best = std::min(best, distance3(end, c));
        CHECK(best < 1e-9);
      }
    }
  // symmetric: each side, reflected in y = 0, lies on the other side's runs
  for (int k = 0; k < 2; ++k)
    for (const auto& r : runs[k])
      for (const auto& p : r) {
        double best = 1e300;
        for (const auto& other : runs[1 - k]) best = std::min(best, to_polyline({p[0], -p[1], p[2]}, other));
        CHECK(best < 2e-3);
      }
}
}  // namespace

TEST_CASE("teapot: the handle and the spout cut the body along closed curves, symmetric about y = 0",
          "[surface][teapot]") {
  const auto doc = io::read_geometry_file(bezoutian_test::shared_data("teapot/teapot32.bpt"));
  REQUIRE(doc.patches.size() == 32);
  check_closed_symmetric_curve(doc.patches, {{12, 5}}, {{13, 6}}, 400);           // handle, upper end
  // handle, lower end: its end curve starts at the body vertex (-2, 0, 0.9), a corner of body patches 5, 6, 9, 10,
  // where D = 0 ends at a corner of the (u, t) domain tangent to the edge u = 1 (exact signs along that edge)
  check_closed_symmetric_curve(doc.patches, {{14, 5}, {14, 6}, {14, 9}, {14, 10}}, {{15, 6}, {15, 5}, {15, 10}, {15, 9}},
                               400);
  check_closed_symmetric_curve(doc.patches, {{16, 4}, {16, 8}}, {{17, 7}, {17, 11}}, 700);  // spout base
}

TEST_CASE("an arc ending where the boundaries of both patches cross is certified up to its end",
          "[surface][seam]") {
  // The plane z = 0 over [-1, 0] x [-1, 1], Phi(u, v) = (u - 1, 2v - 1, 0), against the paraboloid
  // z = x^2 + y^2 - 1/2 over [0, 1] x [-1, 1], Psi(s, t) = (s, 2t - 1, s^2 + (2t - 1)^2 - 1/2): the halves of a
  // split plane and of a split paraboloid on either side of the seam x = 0. Phi(u, v) = Psi(s, t) iff s = u - 1,
  // v = t and (u - 1)^2 + (2t - 1)^2 = 1/2: D = 0 is a circle whose partner s = u - 1 lies in [0, 1] only at
  // u = 1, so every point of it in the box is phantom but its two ends on the side u = 1, (1, (1 -+ 1/sqrt 2) / 2),
  // where both patches meet the seam: the exact boundary contacts (0, -+1/sqrt 2, 0). Near those ends the partner
  // tends to the side s = 0 of its domain; the ends are certified crossings and the spans next to them phantom.
  // The mirror image across the seam, the plane's right half against the paraboloid's left half, ends on u = 0
  // with the partner on s = 1.
  for (int mirrored = 0; mirrored < 2; ++mirrored) {
    INFO((mirrored ? "right plane, left paraboloid" : "left plane, right paraboloid"));
    const Patch plane = from_power({mirrored ? "u" : "u - 1", "2*v - 1", "0"}, 1, 1);
    const Patch paraboloid =
        mirrored ? from_power({"u - 1", "2*v - 1", "(u - 1)^2 + (2*v - 1)^2 - 1/2"}, 2, 2)
                 : from_power({"u", "2*v - 1", "u^2 + (2*v - 1)^2 - 1/2"}, 2, 2);
    const double end_u = mirrored ? 0 : 1, end_s = mirrored ? 1 : 0;
    const Surface_locus L = intersection_locus(plane, paraboloid);
    std::string why;
    CHECK(locus_certified(L, &why));
    INFO(why);
    REQUIRE(L.contacts.size() == 2);
    REQUIRE(L.split_points.size() == 2);
    const double r = std::sqrt(0.5) / 2;
    for (const Locus_split_point& sp : L.split_points) {
      const Locus_arc& arc = L.arcs.at(sp.arc);
      CHECK((sp.index == 0 || sp.index + 1 == arc.points.size()));  // an end of its arc
      CHECK(sp.point == 1);                                            // Q = (s, t) reaches its side s = end_s
      CHECK(sp.coordinate == 0);
      CHECK(sp.bound == Q(int(end_s)));
      // the box (u, t, v, s) holds (end_u, 1/2 -+ r, 1/2 -+ r, end_s)
      const double t = sp.box[1][0] < 0.5 ? 0.5 - r : 0.5 + r;
      const std::array<double, 4> z{end_u, t, t, end_s};
      for (int d = 0; d < 4; ++d) {
        CHECK(sp.box[std::size_t(d)][0] <= z[std::size_t(d)]);
        CHECK(z[std::size_t(d)] <= sp.box[std::size_t(d)][1]);
        CHECK(sp.box[std::size_t(d)][1] - sp.box[std::size_t(d)][0] < 1e-9);
      }
      const Locus_point& q = arc.points[sp.index];
      CHECK(q.genuine);
      CHECK(q.status_proved);
    }
    // every other traced point: phantom, proved (its partner s = u -+ 1 lies outside [0, 1])
    std::size_t phantom = 0;
    for (const Locus_arc& arc : L.arcs) {
      CHECK(arc.undecided_fraction == 0);
      for (const Locus_point& q : arc.points)
        if (q.projection[0] != end_u) {
          CHECK(q.status_proved);
          CHECK_FALSE(q.genuine);
          ++phantom;
        }
    }
    CHECK(phantom > 10);
  }
}

// A patch whose projection to the (x, y) plane, (u + v^2/10, v + u^2/10), is one-to-one on the unit square (its
// Jacobian differs from the identity by less than 1 in norm, on a convex domain) cannot self-intersect. On [0,1]^2
// D = 0 (total degree 6) misses the box; on [-2,3]^2 it does not, but the part it crosses is proved free of genuine
// points (partners outside the domain): the locus comes out empty, with a proof either way. For an exact graph
// (u, v, f) det B vanishes identically (the double-point system degenerates at infinity); the direct proof of
// injectivity (intersection/Patch_injectivity.h) answers it, and answers the bent patch on [0,1]^2 without D.
TEST_CASE("a patch without self-intersection: the empty locus is proved", "[surface]") {
  const Patch graph = from_power({"u", "v", "u^3 - 3*u*v^2 + v"}, 3, 3);
  // the exact graph: det B vanishes identically, and the patch is proved injective instead (its projection to the
  // (x, y) plane is the identity of the square)
  CHECK(self_intersection_equation(graph).is_degenerate());
  const Surface_locus G = self_intersection_locus(graph);
  CHECK(G.topology_computed);
  CHECK(G.topology_method == "injective projection");
  CHECK(G.topology.components.empty());
  const Patch bent = from_power({"u + 1/10*v^2", "v + 1/10*u^2", "u^3 - 3*u*v^2 + v"}, 3, 3);
  CHECK(self_intersection_locus(bent).topology_method == "injective projection");
  for (int wide = 0; wide < 2; ++wide) {
    Surface_intersection_options o;
    o.direct_proofs = false;  // the elimination route: D and its topology
    if (wide) o.box = Parameter_box{Q(-2), Q(3), Q(-2), Q(3)};
    Surface_locus L = self_intersection_locus(bent, o);
    INFO(L.note);
    REQUIRE(L.topology_computed);
    CHECK(L.equation.total_degree() == 6);
    CHECK(L.topology.components.empty());
    CHECK(L.topology.excluded_regions.empty() == !wide);
    // no pinch point either, proved: the Jacobian of (x, y) has determinant 1 - u v / 25 > 0 on both boxes
    CHECK(L.pinch_points.empty());
    CHECK(L.pinch_points_complete);
  }
}

TEST_CASE("pinch points at a domain corner: a collapsed edge vector (P10 = P00) makes the corner one", "[surface][pinch]") {
  // phi_u(0, 0) = m w10 / w00 (P10 - P00) (the derivative of a rational Bezier patch at its corner), so P10 = P00 gives
  // phi_u = 0 there: the Jacobian has rank <= 1 at the corner (0, 0), which the search must report.
  auto holds_corner = [](const Pinch_point_search& r) {
    bool found = false;
    for (const Pinch_point& p : r.points)
      found = found || (p.box[0][0] <= 0 && 0 <= p.box[0][1] && p.box[1][0] <= 0 && 0 <= p.box[1][1]);
    return found;
  };
  // a (2,2) polynomial patch written with P10 = P00
  const std::vector<std::vector<Patch::Point>> net = {{{Q(0), Q(0), Q(0)}, {Q(0), Q(1), Q(0)}, {Q(0), Q(2), Q(1)}},
                                                      {{Q(0), Q(0), Q(0)}, {Q(1), Q(1), Q(1)}, {Q(1), Q(2), Q(0)}},
                                                      {{Q(2), Q(0), Q(1)}, {Q(2), Q(1), Q(0)}, {Q(2), Q(2), Q(2)}}};
  Pinch_point_search r = internal::find_pinch_points(Patch(net), Parameter_box{});
  CHECK(r.complete);
  CHECK(holds_corner(r));
  // the random rational bicubic of the (3,3) sweep's seed 1 (third draw), whose integer control points happen to
  // have P10 = P00: the pinch point its self-intersection reports at (0, 0) is that corner
  std::mt19937 g(1);
  Patch a = Patch(net);
  for (int trial = 0; trial < 3; ++trial) {
    a = random_patch(g, 3, 3, trial >= 2);
    random_patch(g, 3, 3, trial >= 2);  // (the sweep draws its patches in pairs)
  }
  REQUIRE(a.control_point(1, 0) == a.control_point(0, 0));
  r = internal::find_pinch_points(a, Parameter_box{});
  CHECK(r.complete);
  CHECK(holds_corner(r));
}

TEST_CASE("pinch points: found exactly where the Jacobian has rank 1; a degenerate one is reported, not guessed",
          "[surface][pinch]") {
  // The Whitney-umbrella-like patch (u v + v^2, v, u^2): phi_u = (v, 0, 2u), phi_v = (u + 2v, 1, 0) are parallel
  // only at (0, 0), with kernel direction (1, 0). There the double curve v = 0 (partner l = -2u) passes through
  // its pinch point: D vanishes there (exactly: (0, 0) is rational).
  {
    const Patch umbrella = from_power({"u*v + v^2", "v", "u^2"}, 2, 2);
    Surface_intersection_options o;
    o.box = Parameter_box{Q(-1, 2), Q(1, 2), Q(-1, 3), Q(1, 3)};
    o.partner_domain_unbounded = true;
    const Surface_locus L = self_intersection_locus(umbrella, o);
    CHECK(L.pinch_points_complete);
    REQUIRE(L.pinch_points.size() == 1);
    const Pinch_point& p = L.pinch_points[0];
    CHECK(p.box[0][0] <= 0);
    CHECK(0 <= p.box[0][1]);
    CHECK(p.box[1][0] <= 0);
    CHECK(0 <= p.box[1][1]);
    CHECK(p.chart == 0);  // direction (1, m), m = 0
    CHECK(p.m[0] <= 0);
    CHECK(0 <= p.m[1]);
    CHECK(CGAL::is_zero(L.equation.square_free[0][0]));  // D(0, 0) = 0
  }
  // The folded patch of the lifting test: phi_u = (2(u - 3/10), 0, v - 1/3) vanishes at (3/10, 1/3), the pinch
  // point of the double curve v = 1/3 (partner 3/5 - u). At (3/10, 0), phi_v = (0, 2v, u - 3/10) vanishes too: a
  // rank-1 point whose system G is not simple (the fold v -> v^2 meets it), which no Krawczyk box isolates. By hand,
  // phi_u x phi_v = (-2v (v - 1/3), -2 (u - 3/10)^2, 4 v (u - 3/10)) vanishes exactly at these two points, with
  // kernel directions (1, 0) and (0, 1): the exact route finds both, and the search is complete.
  {
    const Patch folded = from_power({"(u-3/10)^2", "v^2", "(u-3/10)*(v-1/3)"}, 3, 2);
    CHECK_FALSE(internal::find_pinch_points_by_subdivision(folded, Parameter_box{}).complete);
    const Surface_locus L = self_intersection_locus(folded);
    CHECK(L.pinch_points_complete);
    REQUIRE(L.pinch_points.size() == 2);
    const std::array<std::array<Q, 2>, 2> expected{{{Q(3, 10), Q(0)}, {Q(3, 10), Q(1, 3)}}};
    for (int k = 0; k < 2; ++k) {
      const Pinch_point& p = L.pinch_points[std::size_t(k)];
      const auto& x = expected[p.v < 0.2 ? 0 : 1];
      CHECK(p.box[0][0] <= x[0]);
      CHECK(x[0] <= p.box[0][1]);
      CHECK(p.box[1][0] <= x[1]);
      CHECK(x[1] <= p.box[1][1]);
      CHECK_FALSE(p.rank_zero);
      CHECK(p.chart == (p.v < 0.2 ? 1 : 0));  // (0, 1) at the fold, (1, 0) at the pinch point: m = 0
      CHECK(p.m[0] <= 0);
      CHECK(0 <= p.m[1]);
    }
    CHECK(std::fabs(L.pinch_points[0].v - L.pinch_points[1].v) > 0.3);
  }
  // A patch whose Jacobian vanishes at (1/2, 1/2): ((u - 1/2)^2, (v - 1/2)^2, (u - 1/2)(v - 1/2)) has
  // phi_u = (2(u - 1/2), 0, v - 1/2) and phi_v = (0, 2(v - 1/2), u - 1/2), both zero there and independent
  // elsewhere (their cross product is (-2 (v - 1/2)^2, -2 (u - 1/2)^2, 4 (u - 1/2)(v - 1/2))): one rank-zero point.
  {
    const Patch cone = from_power({"(u-1/2)^2", "(v-1/2)^2", "(u-1/2)*(v-1/2)"}, 2, 2);
    const Pinch_point_search r = internal::find_pinch_points(cone, Parameter_box{});
    CHECK(r.complete);
    REQUIRE(r.points.size() == 1);
    CHECK(r.points[0].rank_zero);
    CHECK(r.points[0].box[0][0] == Q(1, 2));
    CHECK(r.points[0].box[1][1] == Q(1, 2));
  }
  // Random (2,2) polynomial patches of the benchmark: the search is complete, and every pinch point lies on D = 0
  // (the closure of the double curve): D over its proved box contains 0 and is tiny against D's coefficients.
  std::mt19937 g(20261122);
  std::size_t pinch = 0;
  for (int k = 0; k < 2; ++k) {
    const Patch a = random_patch(g, 2, 2, false);
    random_patch(g, 2, 2, false);  // (the benchmark draws its patches in pairs)
    const Surface_locus L = self_intersection_locus(a);
    CHECK(L.pinch_points_complete);
    const auto& D = L.equation.square_free;
    using I = internal::Mpfi_interval;
    for (const Pinch_point& p : L.pinch_points) {
      ++pinch;
      const I u = I::hull(p.box[0][0], p.box[0][1], 256), v = I::hull(p.box[1][0], p.box[1][1], 256);
      I r = I::point(0, 256);
      double scale = 0;
      for (int j = D.degree(); j >= 0; --j) {
        I s = I::point(0, 256);
        for (int i = D[j].degree(); i >= 0; --i) {
          s = s * u + I::hull(Q(D[j][i]), Q(D[j][i]), 256);
          scale = std::max(scale, std::fabs(CGAL::to_double(D[j][i])));
        }
        r = r * v + s;
      }
      CHECK(r.contains_zero());
      CHECK(std::max(std::fabs(CGAL::to_double(r.lower())), std::fabs(CGAL::to_double(r.upper()))) < 1e-9 * scale);
    }
  }
  CHECK(pinch >= 1);  // the identities above are the check; this only makes sure they were exercised
}

// Certified lifting (lifting/certified_lifting.h), checked against a double curve known in closed form whose
// partner leaves the partner domain at a known parameter. Phi(u,v) = ((u - 3/10)^2, v^2, (u - 3/10)(v - 1/3)) as a
// (3,2) patch: Phi(u, v) = Phi(u', v') with (u', v') != (u, v) iff v = v' = 1/3 and u' = 3/5 - u (v' = -v would need
// v - 1/3 = v + 1/3). So the genuine self-intersection is the segment v = 1/3, 0 <= u <= 3/5 (the partner 3/5 - u
// leaves [0,1] at u = 3/5), with the pinch point u = 3/10 (partner (0,0)); every other point of D = 0 is phantom.
TEST_CASE("certified lifting: genuine and phantom parts of a double curve with a closed-form partner",
          "[surface][lifting]") {
  const Patch phi = bezoutian_test::patch_from_power({"(u-3/10)^2", "v^2", "(u-3/10)*(v-1/3)"}, 3, 2);
  const Surface_locus L = self_intersection_locus(phi);
  REQUIRE(L.topology_computed);
  REQUIRE(L.topology_method == "subdivision");
  std::size_t on_line = 0, on_line_proved = 0, genuine_proved = 0, phantom_proved = 0, tight = 0, near_pinch = 0;
  for (const auto& arc : L.arcs)
    for (const auto& q : arc.points) {
      const double u = q.projection[0], v = q.projection[1];
      const bool line = std::fabs(v - 1.0 / 3) < 1e-9;
      if (q.status_proved && q.genuine) {  // a proof of a genuine point must agree with the closed form
        ++genuine_proved;
        CHECK(line);
        CHECK(u <= 0.6 + 1e-9);
        CHECK(q.partner[0] == Approx(0.6 - 2 * u).margin(1e-6));  // (l, k): Q = (u + l, v), P = (u, v + k)
        CHECK(q.partner[1] == Approx(0).margin(1e-6));
        // the proved enclosure holds the exact partner of the arc point (u, 1/3) (u is the exact graph coordinate)
        const auto& y = q.partner_enclosure;
        CHECK(y[0][0] <= 0.6 - 2 * u + 1e-15);
        CHECK(0.6 - 2 * u - 1e-15 <= y[0][1]);
        CHECK(y[1][0] <= 0);
        CHECK(0 <= y[1][1]);
        tight += y[0][1] - y[0][0] < 1e-6 && y[1][1] - y[1][0] < 1e-6;
      }
      if (!(q.status_proved && q.genuine)) CHECK(std::isnan(q.partner_enclosure[0][0]));
      if (q.status_proved && !q.genuine) {
        ++phantom_proved;
        CHECK((!line || u >= 0.6 - 1e-9));
      }
      // away from the transition; near the pinch point (3/10, 1/3) too, where the partner tends to the trivial one
      // (proved by the blown-up equations E / r); only the pinch point itself, whose partner is trivial, is left
      if (line && std::fabs(u - 0.6) > 0.02 && std::fabs(u - 0.3) > 1e-9) {
        near_pinch += std::fabs(u - 0.3) < 0.04;
        ++on_line;
        on_line_proved += q.status_proved;
      }
    }
  CHECK(on_line > 20);
  CHECK(near_pinch >= 6);
  CHECK(on_line_proved == on_line);  // the whole segment, both sides of the transition, is decided by proofs
  // The transition itself: at u = 0.6 the partner Q = (u + l, v) = (0.6 - u, 1/3) reaches the domain's side u = 0.
  // It is a certified split point: a box around the exact (u, v, l, k) = (3/5, 1/3, -3/5, 0), a traced point of
  // its arc, genuine and proved, between a phantom and a genuine traced point.
  REQUIRE(L.split_points.size() == 1);
  const Locus_split_point& sp = L.split_points[0];
  CHECK(sp.point == 1);
  CHECK(sp.coordinate == 0);
  CHECK(sp.bound == Q(0));
  const std::array<double, 4> exact{0.6, 1.0 / 3, -0.6, 0};
  for (int c = 0; c < 4; ++c) {
    CHECK(sp.box[c][0] <= exact[c]);
    CHECK(exact[c] <= sp.box[c][1]);
    CHECK(sp.box[c][1] - sp.box[c][0] < 1e-12);
  }
  const Locus_arc& arc = L.arcs.at(sp.arc);
  REQUIRE(sp.index > 0);
  REQUIRE(sp.index + 1 < arc.points.size());
  const Locus_point& at = arc.points[sp.index];
  CHECK(at.genuine);
  CHECK(at.status_proved);
  CHECK(at.second[0] == Approx(0).margin(1e-12));
  CHECK(arc.points[sp.index - 1].genuine != arc.points[sp.index + 1].genuine);
  // the traced points next to it are decided by the side of the line u = 0 their partner is on
  CHECK(arc.points[sp.index - 1].status_proved);
  CHECK(arc.points[sp.index + 1].status_proved);
  // the topology edge carries the same point (the arcs stay parallel to the edges' polylines)
  CHECK(L.topology.edges.at(sp.arc).polyline.size() == arc.points.size());
  // refined to 128 bits, the boxes still hold the exact crossing (3/5, 1/3, -3/5, 0)
  const auto r = refine_split_point(phi, sp, 128);
  const std::array<Q, 4> exact_q{Q(3, 5), Q(1, 3), Q(-3, 5), Q(0)};
  for (int c = 0; c < 4; ++c) {
    CHECK(r[c][0] <= exact_q[c]);
    CHECK(exact_q[c] <= r[c][1]);
    CHECK(r[c][1] - r[c][0] < Q(1) / (Integer(1) << 128));
  }
  CHECK(genuine_proved > 10);
  CHECK(phantom_proved > 5);
  // every enclosure is tightened at its point (Krawczyk with the graph coordinate fixed)
  CHECK(tight == genuine_proved);
  // The whole locus is certified. D = 0 is the lines v = 1/3 and u = 3/10; along u = 3/10 the first coordinate
  // equation (u' - 3/10)^2 = 0 has a double root, so only the exact fibre over the line proves it phantom (its
  // partners (0, 0) and (0, -2v), the second outside the domain); the rank-one point (3/10, 0) is found exactly.
  std::string why;
  CHECK(locus_certified(L, &why));
  INFO(why);
  std::size_t phantom_line = 0;
  for (const auto& a : L.arcs)
    for (std::size_t i = 1; i + 1 < a.points.size(); ++i) {
      const Locus_point& q = a.points[i];
      if (std::fabs(q.projection[0] - 0.3) > 1e-9) continue;
      ++phantom_line;
      CHECK(q.status_proved);
      CHECK_FALSE(q.genuine);
    }
  CHECK(phantom_line > 20);
  // completeness: every sample (u, 1/3), u in [0, 3/5], of the closed-form double curve lies within the proved
  // polyline distance (plus the sample's own spacing) of a reported genuine sheet, in the first parameter domain,
  // with the partner (3/5 - u, 1/3) in the second
  double worst = 0;
  for (int j = 0; j <= 6000; ++j) {
    const double u = 0.6 * j / 6000;
    double best = HUGE_VAL;
    for (const auto& a : L.arcs)
      for (const Locus_sheet& s : a.sheets)
        for (std::size_t k = 0; k + 1 < s.points.size(); ++k) {
          const auto &p = s.points[k], &q = s.points[k + 1];
          auto segment = [&](const std::array<double, 2>& A, const std::array<double, 2>& B, double x, double y) {
            const double dx = B[0] - A[0], dy = B[1] - A[1], l2 = dx * dx + dy * dy;
            const double h = l2 > 0 ? std::min(1.0, std::max(0.0, ((x - A[0]) * dx + (y - A[1]) * dy) / l2)) : 0;
            return std::hypot(A[0] + h * dx - x, A[1] + h * dy - y);
          };
          best = std::min(best, std::max(segment(p.first, q.first, u, 1.0 / 3), segment(p.second, q.second, 0.6 - u, 1.0 / 3)));
        }
    worst = std::max(worst, best);
  }
  CHECK(worst < 2e-3);
}

// The exact fibre over a rational line (lifting/exact_line_fibres.h), against closed forms.
TEST_CASE("exact fibre over a line: the folded patch's lines, and a partner conic refused", "[surface][lifting]") {
  const Patch folded = bezoutian_test::patch_from_power({"(u-3/10)^2", "v^2", "(u-3/10)*(v-1/3)"}, 3, 2);
  const internal::Partner_equations eq(folded);
  // the components as the set {(a1, b1, a2, b2)} of w(t) = (a1 + b1 t, a2 + b2 t)
  auto components = [](const internal::Exact_line_fibre& F) {
    std::set<std::array<Q, 4>> out;
    for (const auto& k : F.components) out.insert({k.a[0], k.b[0], k.a[1], k.b[1]});
    return out;
  };
  // u = 3/10, t = v: Phi(3/10, v) = (0, v^2, 0) = Phi(u', v') iff u' = 3/10 and v' = +-v; w = (Q_u, P_v) =
  // (u', v'): the trivial (3/10, t) and (3/10, -t)
  internal::Exact_line_fibre F = internal::exact_line_fibre(eq, Parameter_box{}, 0, Q(3, 10), {Q(0), Q(1)});
  REQUIRE(F.proved);
  CHECK(components(F) == std::set<std::array<Q, 4>>{{Q(3, 10), Q(0), Q(0), Q(1)}, {Q(3, 10), Q(0), Q(0), Q(-1)}});
  // so no point of the line has a genuine partner: (3/10, -v) is outside the domain but at v = 0, where it is trivial
  for (const Q t : {Q(0), Q(1, 3), Q(1)}) {
    bool decided = true;
    CHECK(internal::genuine_line_partners(eq, Parameter_box{}, F, {Q(3, 10), t}, t, decided).empty());
    CHECK(decided);
  }
  // v = 1/3, t = u: the trivial (t, 1/3) and the double curve's (3/5 - t, 1/3), genuine for t in [0, 3/5] but 3/10
  F = internal::exact_line_fibre(eq, Parameter_box{}, 1, Q(1, 3), {Q(0), Q(1)});
  REQUIRE(F.proved);
  CHECK(components(F) == std::set<std::array<Q, 4>>{{Q(0), Q(1), Q(1, 3), Q(0)}, {Q(3, 5), Q(-1), Q(1, 3), Q(0)}});
  bool decided = true;
  const auto y = internal::genuine_line_partners(eq, Parameter_box{}, F, {Q(1, 10), Q(1, 3)}, Q(1, 10), decided);
  REQUIRE(y.size() == 1);
  CHECK(y[0] == std::array<Q, 2>{Q(2, 5), Q(0)});  // (l, k) = (3/5 - 2u, 0)
  CHECK(internal::genuine_line_partners(eq, Parameter_box{}, F, {Q(3, 10), Q(1, 3)}, Q(3, 10), decided).empty());
  CHECK(internal::genuine_line_partners(eq, Parameter_box{}, F, {Q(7, 10), Q(1, 3)}, Q(7, 10), decided).empty());
  // where each component lies in the domain, exactly: (3/5 - t, 1/3) for t in [-2/5, 3/5], cut to the range [0, 1]
  // and to x(t) = (t, 1/3) in the domain; (3/10, -t) on u = 3/10 only at t = 0 (where it is the trivial partner)
  using Range = std::optional<std::array<Q, 2>>;
  const internal::Affine_fibre_component double_curve{{Q(3, 5), Q(1, 3)}, {Q(-1), Q(0)}},
      mirror{{Q(3, 10), Q(0)}, {Q(0), Q(-1)}};
  CHECK(internal::component_in_domain(eq, Parameter_box{}, double_curve, 1, Q(1, 3), {Q(-1), Q(2)}) ==
        Range(std::array<Q, 2>{Q(0), Q(3, 5)}));
  CHECK(internal::component_in_domain(eq, Parameter_box{}, double_curve, 1, Q(1, 3), {Q(7, 10), Q(1)}) == Range());
  CHECK(internal::component_in_domain(eq, Parameter_box{}, mirror, 0, Q(3, 10), {Q(0), Q(1, 3)}) ==
        Range(std::array<Q, 2>{Q(0), Q(0)}));
  CHECK(internal::component_in_domain(eq, Parameter_box{}, mirror, 0, Q(3, 10), {Q(1, 3), Q(1)}) == Range());
  CHECK(internal::component_in_domain(eq, Parameter_box{}, mirror, 0, Q(6, 5), {Q(0), Q(1)}) == Range());  // x outside
  // a line off D = 0 (u = 1/5): the trivial partner alone
  F = internal::exact_line_fibre(eq, Parameter_box{}, 0, Q(1, 5), {Q(0), Q(1)});
  REQUIRE(F.proved);
  CHECK(components(F) == std::set<std::array<Q, 4>>{{Q(1, 5), Q(0), Q(0), Q(1)}});
  // the plane (u, v, 0) against (s^2 + t^2, s, 0): on u = 1/2 the partners (v, s) = (s, s) with s^2 = 1/2 - t^2,
  // a conic through the domain, not affine: refused, with the reason
  const Patch plane = from_power({"u", "v", "0"}, 1, 1), bowl = from_power({"u^2 + v^2", "u", "0"}, 2, 2);
  F = internal::exact_line_fibre(internal::Partner_equations(plane, bowl), Parameter_box{}, 0, Q(1, 2), {Q(0), Q(1)});
  CHECK_FALSE(F.proved);
  CHECK(F.reason.find("not affine") != std::string::npos);
}

// Regression: on this random bicubic pair (the first (3,3) polynomial pair of benchmark/surface_benchmark.cpp, D of
// total degree 81) arc samples bisected on the power form of D put whole arcs of them on the cells' edges, off the
// curve (doc/surface_intersection.md, step 3). Every traced point must lie on D = 0 (exact evaluation), and proved
// genuine points on both patches.
TEST_CASE("bicubic pair: every traced point lies on D = 0", "[surface][sampling]") {
  std::mt19937 g(20261122);
  std::vector<Patch> made;  // the benchmark's sequence: (m,n) x rational x self/pair x 2 problems, two patches each
  for (auto mn : std::vector<std::pair<int, int>>{{2, 2}, {3, 2}, {3, 3}})
    for (bool rational : {false, true})
      for (int k = 0; k < 4 && made.size() < 38; ++k) {
        made.push_back(random_patch(g, mn.first, mn.second, rational));
        made.push_back(random_patch(g, mn.first, mn.second, rational));
      }
  REQUIRE(made.size() == 38);
  const Patch &a = made[36], &b = made[37];  // problem 18
  const Surface_locus L = intersection_locus(a, b);
  REQUIRE(L.topology_computed);
  CHECK(L.equation.total_degree() == 81);
  check_traced_points_on_curve(L, 4);
  std::size_t proved_genuine = 0;
  for (const auto& arc : L.arcs)
    for (const auto& q : arc.points)
      if (q.genuine && q.status_proved) {
        ++proved_genuine;
        CHECK(distance3(a.evaluate(q.first[0], q.first[1]), b.evaluate(q.second[0], q.second[1])) < 1e-7);
      }
  CHECK(proved_genuine > 100);
}

TEST_CASE("intersection curve leaving the second patch: the split point is certified at an irrational point",
          "[surface][lifting]") {
  // phi(u, v) = (u, v, u^2 + v^2) and the plane piece psi(s, t) = (s/4, t, 1/4): the intersection curve is the
  // circle u^2 + v^2 = 1/4 with partner s = 4u, t = v. It is genuine for u <= 1/4, where s <= 1; the genuine part
  // ends at u = 1/4, v = t = sqrt(3)/4 on psi's side s = 1.
  const Patch phi = from_power({"u", "v", "u^2+v^2"}, 2, 2);
  const Patch psi = from_power({"u/4", "v", "1/4"}, 2, 2);
  const Surface_locus L = intersection_locus(phi, psi);
  REQUIRE(L.topology_computed);
  REQUIRE(L.topology_method == "subdivision");
  // two split points: the crossing of psi's side s = 1 inside the box, and the arc's end on the side u = 0, where
  // the curve leaves both patches at their common boundary point (0, 1/2, 1/4) (phi's side u = 0 at v = 1/2, psi's
  // side s = 0 at t = 1/2)
  REQUIRE(L.split_points.size() == 2);
  const bool first_inside = L.split_points[0].bound == Q(1);
  const Locus_split_point& sp = L.split_points[first_inside ? 0 : 1];
  const Locus_split_point& end = L.split_points[first_inside ? 1 : 0];
  CHECK(end.point == 1);
  CHECK(end.coordinate == 0);
  CHECK(end.bound == Q(0));
  CHECK((end.index == 0 || end.index + 1 == L.arcs.at(end.arc).points.size()));
  const std::array<double, 4> contact{0, 0.5, 0.5, 0};
  for (int c = 0; c < 4; ++c) {
    CHECK(end.box[c][0] <= contact[c]);
    CHECK(contact[c] <= end.box[c][1]);
  }
  CHECK(sp.point == 1);  // psi's point (s, t)
  CHECK(sp.coordinate == 0);
  CHECK(sp.bound == Q(1));
  const double r3 = std::sqrt(3.0) / 4;
  const std::array<double, 4> exact{0.25, r3, r3, 1};  // (u, t) and the partner (v, s)
  for (int c = 0; c < 4; ++c) {
    CHECK(sp.box[c][0] <= exact[c] + 1e-16);  // (sqrt is rounded: a margin of one unit)
    CHECK(exact[c] - 1e-16 <= sp.box[c][1]);
    CHECK(sp.box[c][1] - sp.box[c][0] < 1e-12);
  }
  const Locus_arc& arc = L.arcs.at(sp.arc);
  const Locus_point& at = arc.points.at(sp.index);
  CHECK(at.genuine);
  CHECK(at.status_proved);
  CHECK(at.second[0] == Approx(1).margin(1e-12));
  // the closed form decides every other traced point: genuine iff u < 1/4; the proved ones must agree
  std::size_t proved = 0;
  for (std::size_t i = 0; i < arc.points.size(); ++i) {
    if (i == sp.index) continue;
    const Locus_point& q = arc.points[i];
    CHECK(std::fabs(q.projection[0] * q.projection[0] + q.projection[1] * q.projection[1] - 0.25) < 1e-9);
    if (q.status_proved) {
      ++proved;
      CHECK(q.genuine == (q.projection[0] < 0.25));  // (the end u = 0 too: its partner s = 0 is in the domain)
    }
  }
  CHECK(proved + 2 >= arc.points.size());
  // to any precision: 200-bit boxes hold u = 1/4, t = v = sqrt(3)/4, s = 1 (checked exactly: lo^2 <= 3/16 <= hi^2)
  const auto r = refine_split_point(phi, psi, sp, 200);
  const Q width = Q(1) / (Integer(1) << 200);
  for (int c = 0; c < 4; ++c) CHECK(r[c][1] - r[c][0] < width);
  CHECK(r[0][0] <= Q(1, 4));
  CHECK(Q(1, 4) <= r[0][1]);
  CHECK(r[3][0] <= Q(1));
  CHECK(Q(1) <= r[3][1]);
  for (int c : {1, 2}) {
    CHECK(r[c][0] > 0);
    CHECK(r[c][0] * r[c][0] <= Q(3, 16));
    CHECK(Q(3, 16) <= r[c][1] * r[c][1]);
  }
  CHECK_THROWS_AS(refine_split_point(phi, psi, sp, 0), Invalid_input);
  // a split point of another problem (the patches swapped): no zero in its box, a clear error, not a wrong box
  CHECK_THROWS_AS(refine_split_point(psi, phi, sp, 64), Error);
}

// The kernel of B (lifting/internal/kernel_partner_proofs.h) on a sheared fold, Phi = ((u - 3/10)^2, (v + u/2)^2,
// (u - 3/10)(v + u/2 - 1/3)). By hand: Phi(u, v) = Phi(u', v') with u' != u forces u' = 3/5 - u and
// v + u/2 = v' + u'/2 = 1/3, so the projected double curve is the line v = 1/30 + u/2, with the partner
// (l, k) = (3/5 - 2u) (1, 1/2) (P = (u, 1/3 - u/2), Q = (3/5 - u, v)): genuine for u <= 3/5, phantom beyond (Q
// leaves through u = 0, and P through v = 0 for u > 2/3). Both l and k are nonzero, so the kernel ratios k = w_lk / w_l, l = w_lk / w_k
// determine the partner.
TEST_CASE("kernel of B: phantom proofs on a sheared fold's double line, in closed form", "[surface][lifting]") {
  using D = internal::Double_interval;
  const Patch phi = from_power({"(u-3/10)^2", "(v+u/2)^2", "(u-3/10)*(v+u/2-1/3)"}, 2, 2);
  const Implicit_equation e = self_intersection_equation(phi);
  // the line lies on D = 0 exactly (an independent check of the derivation above)
  for (const Q u : {Q(1, 7), Q(2, 3), Q(9, 10)}) {
    const Q v = Q(1, 30) + u / 2;
    Q f(0);
    for (int j = e.determinant.degree(); j >= 0; --j) {
      Q c(0);
      for (int k = e.determinant[j].degree(); k >= 0; --k) c = c * u + Q(e.determinant[j][k]);
      f = f * v + c;
    }
    CHECK(CGAL::is_zero(f));
  }
  const internal::Kernel_partner_system ks(e.matrix, true);
  REQUIRE(ks.usable());
  const Parameter_box domain{Q(0), Q(1), Q(0), Q(1)};
  auto proved = [&](double u, const Parameter_box& d) {
    const double v = 1.0 / 30 + u / 2;  // a cell around the line where it is the only part of D = 0
    const Parameter_box cell{Q(0), Q(1), Q(v - 0.01), Q(v + 0.01)};
    return internal::kernel_proves_phantom(ks, d, 0, D{u, u}, v, cell);
  };
  for (double u : {0.05, 0.2, 0.35, 0.5, 0.59}) CHECK_FALSE(proved(u, domain));  // genuine: never phantom
  for (double u : {0.61, 0.65, 0.7, 0.8, 0.9, 0.99}) CHECK(proved(u, domain));
  // over spans of u (every arc point over the span): phantom spans are proved, spans with genuine points (one
  // reaching across the split at u = 3/5) never
  auto span = [&](double u0, double u1) {
    const double v = 1.0 / 30 + (u0 + u1) / 4;
    const Parameter_box cell{Q(0), Q(1), Q(1, 30) + Q(u0) / 2 - Q(1, 100), Q(1, 30) + Q(u1) / 2 + Q(1, 100)};
    return internal::kernel_proves_phantom(ks, domain, 0, D{u0, u1}, v, cell);
  };
  CHECK(span(0.7, 0.7001));
  CHECK(span(0.8, 0.801));
  CHECK_FALSE(span(0.3, 0.301));
  CHECK_FALSE(span(0.599, 0.601));
  // with the partner domain [-1, 1]^2, P and Q stay inside: nothing is phantom
  const Parameter_box wide{Q(-1), Q(1), Q(-1), Q(1)};
  for (double u : {0.65, 0.8, 0.99}) CHECK_FALSE(proved(u, wide));
}

// The point-wise proofs of certify_edge_partners on random loci, checked against all partners computed
// independently (numerical_partners: roots of a Sylvester resultant, polished on the equations): a traced point
// proved phantom by the kernel of B has no real partner in the domain (up to a margin for points next to a
// split); one proved genuine by Krawczyk's test at its own graph coordinate has a real partner in its enclosure.
TEST_CASE("point-wise status proofs: phantom by the kernel of B, genuine by Krawczyk, against all partners",
          "[surface][lifting]") {
  using D = internal::Double_interval;
  std::mt19937 g(20261123);
  std::size_t proved[2] = {0, 0}, proved_genuine = 0;
  for (int trial = 0; trial < 8; ++trial) {
    const bool self = trial % 2 == 0;
    const Patch a = random_patch(g, 2 + trial / 4, 2, trial % 4 >= 2), b = random_patch(g, 2 + trial / 4, 2, trial % 4 >= 2);
    Surface_intersection_options o;
    o.certify_lifting = false;
    o.pinch_point_boxes = 0;
    o.max_total_degree_for_topology = 0;  // the subdivision only (its cells are needed)
    const Surface_locus L = self ? self_intersection_locus(a, o) : intersection_locus(a, b, o);
    INFO("trial " << trial << ": " << L.note);
    // all eight by the subdivision (the first and third, (2,2) self-intersections with a triple point next to a
    // split line or with two nearly equal tangents, need the 3 x 3 cut around the known multiple point)
    REQUIRE(L.topology_method == "subdivision");
    const internal::Kernel_partner_system ks(L.equation.matrix, self);
    {  // M = B^t and its partial derivatives (central differences of the exact entries)
      const std::size_t n = L.equation.matrix.size();
      for (const auto& x : {std::array<double, 2>{0.3, 0.7}, std::array<double, 2>{0.9, 0.15}}) {
        std::vector<D> M, M0, M1;
        ks.evaluate(0, D{x[0], x[0]}, D{x[1], x[1]}, M);
        ks.evaluate(1, D{x[0], x[0]}, D{x[1], x[1]}, M0);
        ks.evaluate(2, D{x[0], x[0]}, D{x[1], x[1]}, M1);
        const double h = 1e-6;
        const auto Bp0 = internal::evaluate_matrix(L.equation.matrix, x[0] + h, x[1]), Bm0 = internal::evaluate_matrix(L.equation.matrix, x[0] - h, x[1]);
        const auto Bp1 = internal::evaluate_matrix(L.equation.matrix, x[0], x[1] + h), Bm1 = internal::evaluate_matrix(L.equation.matrix, x[0], x[1] - h);
        const auto B = internal::evaluate_matrix(L.equation.matrix, x[0], x[1]);
        for (std::size_t r = 0; r < n; ++r)
          for (std::size_t c = 0; c < n; ++c) {
            const double scale = 1 + std::fabs(double(B[c][r]));
            CHECK(M[r * n + c].mid() == Approx(double(B[c][r])).margin(1e-9 * scale));
            CHECK(M0[r * n + c].mid() == Approx(double((Bp0[c][r] - Bm0[c][r]) / (2 * h))).margin(1e-4 * scale));
            CHECK(M1[r * n + c].mid() == Approx(double((Bp1[c][r] - Bm1[c][r]) / (2 * h))).margin(1e-4 * scale));
          }
      }
    }
    const internal::Partner_equations eq = self ? internal::Partner_equations(a) : internal::Partner_equations(a, b);
    for (std::size_t k = 0; k < L.topology.edges.size(); ++k) {
      const Curve_topology_edge& edge = L.topology.edges[k];
      for (const Curve_topology_piece& pc : edge.pieces) {
        if (pc.graph_axis < 0) continue;
        for (std::size_t i = pc.first + 1; i < pc.last; ++i) {
          const auto& x = edge.polyline[i];
          const int t = pc.graph_axis;
          const Locus_point& q = L.arcs[k].points[i];
          bool genuine_proved = false;
          if (q.genuine && q.lifted && i % 5 == 0) {  // (a sample: numerical_partners is costly)
            // Krawczyk at t on a small box around the floating-point (o, y)
            auto around = [](double c) { return D{c - 1e-9 * (1 + std::fabs(c)), c + 1e-9 * (1 + std::fabs(c))}; };
            std::array<D, 2> y;
            const auto no_start = []() -> const std::vector<std::array<D, 2>>* { return nullptr; };
            genuine_proved = internal::classify_partner_span(eq, o.partner_domain, false, t, D{x[t], x[t]},
                                                             {around(x[1 - t]), around(q.partner[0]), around(q.partner[1])},
                                                             pc.cell, no_start, &y, true) == internal::Partner_status::genuine;
            if (genuine_proved) {
              ++proved_genuine;
              bool held = false;
              for (const auto& z : internal::numerical_partners(eq, x))
                held = held || (std::abs(z[0].imag()) + std::abs(z[1].imag()) < 1e-6 &&
                                z[0].real() > y[0].lo - 1e-6 && z[0].real() < y[0].hi + 1e-6 &&
                                z[1].real() > y[1].lo - 1e-6 && z[1].real() < y[1].hi + 1e-6);
              INFO("trial " << trial << " point " << x[0] << ", " << x[1]);
              CHECK(held);
            }
          }
          // the kernel test on every point, genuine ones included (where it must fail)
          if (!internal::kernel_proves_phantom(ks, o.partner_domain, t, D{x[t], x[t]}, x[1 - t], pc.cell)) continue;
          CHECK_FALSE(genuine_proved);
          ++proved[self ? 0 : 1];
          for (const auto& y : internal::numerical_partners(eq, x)) {
            if (std::abs(y[0].imag()) + std::abs(y[1].imag()) > 1e-6) continue;
            const double y1 = y[0].real(), y2 = y[1].real(), m = 1e-6;
            const bool in = self ? (x[0] + y1 > m && x[0] + y1 < 1 - m && x[1] + y2 > m && x[1] + y2 < 1 - m)
                                 : (y1 > m && y1 < 1 - m && y2 > m && y2 < 1 - m);
            INFO("trial " << trial << " point " << x[0] << ", " << x[1] << " partner " << y1 << ", " << y2);
            CHECK_FALSE(in);
          }
        }
      }
    }
  }
  CHECK(proved[0] >= 500);  // self-intersection (1070 when written)
  CHECK(proved[1] >= 200);  // intersection (571)
  CHECK(proved_genuine >= 300);  // (about 600)
}

// The first patch of problem `trial` of the random sweep with seed `seed`: problems 0-3 are (2,2), 4-7 (3,2), the
// rational ones 2, 3, 6, 7; the sweep draws two patches per problem (the second is the partner of a pair).
static Patch sweep_patch(int seed, int trial) {
  std::mt19937 g(static_cast<std::mt19937::result_type>(seed));
  for (int t = 0;; ++t) {
    Patch a = random_patch(g, 2 + t / 4, 2, t % 4 >= 2);
    random_patch(g, 2 + t / 4, 2, t % 4 >= 2);
    if (t >= trial) return a;
  }
}

TEST_CASE("a node with almost tangent branches is certified: the box around it is cut around Newton's point",
          "[surface][subdivision]") {
  // The fifth problem of seed 26 of the random sweep (a polynomial (3, 2) self-intersection, D of total degree 34)
  // has a node at (0.14305488397, 0.20962656848) whose branches meet at 0.035 rad (located independently: Newton's
  // method on grad D from D's exact Taylor expansion). Split at fixed ratios, the box that finally
  // proves the node has it 5e-8 from an edge, and in the next box the two branches are 1.8e-9 apart: no box down
  // to depth 30 separated them. Cut around the node (Subdivision_topology::cut_around), it is certified.
  const Patch a = sweep_patch(26, 4);
  Surface_intersection_options o;
  o.certify_lifting = false;
  o.pinch_point_boxes = 0;
  o.max_total_degree_for_topology = 0;  // the subdivision only
  const Surface_locus L = self_intersection_locus(a, o);
  INFO(L.note);
  REQUIRE(L.topology_method == "subdivision");
  int nodes = 0;
  for (const Curve_topology_vertex& x : L.topology.vertices)
    if (x.kind == Curve_topology_vertex::singular && std::fabs(x.u - 0.14305488397) < 1e-9 &&
        std::fabs(x.v - 0.20962656848) < 1e-9) {
      ++nodes;
      CHECK(x.branches == 2);
      CHECK(x.u_lo <= x.u);
      CHECK(x.u <= x.u_hi);
    }
  CHECK(nodes == 1);
}

TEST_CASE("two branches close together between two nodes are certified by the two-branch certificate",
          "[surface][subdivision][two_branch]") {
  // The fifth problem of seed 6 of the random sweep (a polynomial (3, 2) self-intersection, D of total degree 34):
  // two nodes near (0.9382, 0.9376) and (0.8726, 0.8318) (located by hand from the boxes a quadtree subdivision
  // cannot resolve), joined by two branches that run close together along the whole stretch. Quadtree boxes would
  // have to be thinner than the gap all along it, and spend the 20000 boxes; the two-branch certificate resolves the
  // boxes that hold both branches whole (topology/internal/two_branch_box.h).
  Surface_intersection_options o;
  o.pinch_point_boxes = 0;
  o.max_total_degree_for_topology = 0;  // the subdivision only
  const Patch a = sweep_patch(6, 4);
  const Surface_locus L = self_intersection_locus(a, o);
  INFO(L.note);
  REQUIRE(L.topology_method == "subdivision");
  // The lifting proves statuses on the arcs of two-branch cells by a chain from one crossing (pieces with
  // graph_axis -1 whose ends are both crossings, not a singular point). Each point proved genuine there must be a
  // double point of the patch: with (l, k) inside the proved partner box, Phi(u, v + k) = Phi(u + l, v), both
  // parameter points in [0, 1]^2 (checked by evaluating the patch, not by the lifting's equations).
  std::vector<std::array<double, 2>> singular;
  for (const Curve_topology_vertex& x : L.topology.vertices)
    if (x.kind == Curve_topology_vertex::singular) singular.push_back({x.u, x.v});
  auto is_singular = [&](const std::array<double, 2>& p) {
    for (const auto& q : singular)
      if (std::fabs(p[0] - q[0]) < 1e-12 && std::fabs(p[1] - q[1]) < 1e-12) return true;
    return false;
  };
  std::size_t two_branch_proved = 0, tight = 0;
  REQUIRE(L.arcs.size() == L.topology.edges.size());
  for (std::size_t k = 0; k < L.arcs.size(); ++k) {
    const Curve_topology_edge& e = L.topology.edges[k];
    REQUIRE(L.arcs[k].points.size() == e.polyline.size());
    for (const Curve_topology_piece& pc : e.pieces) {
      if (pc.graph_axis != -1 || is_singular(e.polyline[pc.first]) || is_singular(e.polyline[pc.last])) continue;
      for (std::size_t i = pc.first + 1; i < pc.last; ++i) {
        const Locus_point& q = L.arcs[k].points[i];
        if (!(q.status_proved && q.genuine)) continue;
        ++two_branch_proved;
        const double u = q.projection[0], v = q.projection[1];
        const double l = 0.5 * (q.partner_enclosure[0][0] + q.partner_enclosure[0][1]),
                     kk = 0.5 * (q.partner_enclosure[1][0] + q.partner_enclosure[1][1]);
        // the midpoint is within half the box's widths of the exact partner; |dPhi| <= 3 * 10 per parameter
        // (control points in [-5, 5], degree <= 3)
        const double w = q.partner_enclosure[0][1] - q.partner_enclosure[0][0] + q.partner_enclosure[1][1] -
                         q.partner_enclosure[1][0];
        tight += w < 1e-6;
        CHECK(v + kk >= -1e-9);
        CHECK(v + kk <= 1 + 1e-9);
        CHECK(u + l >= -1e-9);
        CHECK(u + l <= 1 + 1e-9);
        const auto P = a(Q(u), Q(v + kk)), R = a(Q(u + l), Q(v));
        double d = 0;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::fabs(CGAL::to_double(P[c] - R[c])));
        CHECK(d < 1e-7 + 30 * w);
      }
    }
  }
  CHECK(two_branch_proved > 100);
  CHECK(tight >= two_branch_proved * 9 / 10);
  const double node[2][2] = {{0.9382, 0.9376}, {0.8726, 0.8318}};
  for (const auto& p : node) {
    int found = 0;
    for (const Curve_topology_vertex& x : L.topology.vertices)
      if (x.kind == Curve_topology_vertex::singular && std::fabs(x.u - p[0]) < 1e-4 && std::fabs(x.v - p[1]) < 1e-4) {
        ++found;
        CHECK(x.branches == 2);
      }
    CHECK(found == 1);
  }
}

namespace {
// Phi(u, v) = (u, v, 0) and Psi(s, t) = (s + s^2/4, t, f(s, t)), f = (4t - 1 - s - s^2)^2 - 2^(-2e) (1 - 4 (2s - 1)^2):
// Psi touches the plane z = 0 along the parabola 4t = 1 + s + s^2 to within 2^(-2e), and they meet along the loop
// |4t - 1 - s - s^2| = 2^-e sqrt(1 - 4 (2s - 1)^2), s in [1/4, 3/4] (u = s + s^2/4, v = t on Phi). The subdivision
// certifies it: one closed component, traced to its tips u(1/4) = 17/64 and u(3/4) = 57/64, every lifted point on it.
void check_near_tangent_loop(int e) {
  const Patch phi = from_power({"u", "v", "0"}, 4, 2);
  const std::string eps2 = "(1/" + std::to_string(1ULL << (2 * e)) + ")";
  const Patch psi = from_power({"u + (1/4)*u^2", "v", "(4*v - 1 - u - u^2)^2 - " + eps2 + "*(1 - 4*(2*u - 1)^2)"}, 4, 2);
  Surface_intersection_options o;
  o.certify_lifting = false;  // the topology is the point here (the statuses are floating point)
  o.max_total_degree_for_topology = 0;  // the subdivision only
  const Surface_locus L = intersection_locus(phi, psi, o);
  INFO(L.note);
  REQUIRE(L.topology_method == "subdivision");
  REQUIRE(L.topology.components.size() == 1);
  CHECK(L.topology.components[0].closed);
  CHECK(L.topology.number_of_singular_points() == 0);
  CHECK(L.topology.number_of_boundary_points() == 0);
  std::size_t checked = 0, above = 0, below = 0;
  double lo = 1, hi = 0;
  for (const auto& arc : L.arcs)
    for (const auto& q : arc.points) {
      const double u = q.projection[0], t = q.projection[1];
      lo = std::min(lo, u), hi = std::max(hi, u);
      if (!q.lifted || q.residual > 1e-9) continue;
      const double v = q.partner[0], s = q.partner[1], w = 4 * t - 1 - s - s * s;
      CHECK(v == Approx(t).margin(1e-9));
      CHECK(u == Approx(s + s * s / 4).margin(1e-9));
      CHECK(std::fabs(std::fabs(w) - std::ldexp(std::sqrt(std::max(0.0, 1 - 4 * (2 * s - 1) * (2 * s - 1))), -e)) < 1e-8);
      if (std::fabs(s - 0.5) < 0.2) (w > 0 ? above : below) += 1;
      ++checked;
    }
  CHECK(checked > 1000);
  CHECK(above > 100);  // both sides of the loop are traced
  CHECK(below > 100);
  CHECK(lo < 17.0 / 64 + 1e-4);
  CHECK(lo > 17.0 / 64 - 1e-4);
  CHECK(hi > 57.0 / 64 - 1e-4);
  CHECK(hi < 57.0 / 64 + 1e-4);
}
}  // namespace

TEST_CASE("two nearly tangent surfaces meet along a thin closed loop: certified by subdivision",
          "[surface][subdivision][valley][fold]") {
  // 2^-24: beyond the loop's tips f is small and positive along the parabola (a valley of D); without the valley
  // exclusion the subdivision spends its 20000 boxes there (and CGAL's analysis, if set, takes over, without the
  // certified cells).
  check_near_tangent_loop(12);
  // 2^-40 (a loop 2^-21 wide in t): its tips need the fold certificate (without it, from 2^-32 on, a box near the
  // tip (57/64, 0.578) is not resolved at depth 30).
  check_near_tangent_loop(20);
}

TEST_CASE("two nearly tangent surfaces: the statuses along the thin loop are proved, with partners in closed form",
          "[surface][lifting][valley]") {
  // The same surfaces with 2^-20 for 2^-24 (a loop of width 2^-11), the lifting on. The chained proof along the
  // two-branch arcs needs spans far shorter than the traced ones: with four halvings 94.7 % of the points are
  // proved (7627 of 8054, measured without the fold cells), with eight 99.4 %. Every proved status is genuine (the
  // partner (v, s) = (t, s(u)), s(u) = 2 sqrt(1 + u) - 2, lies in [0, 1]^2), and its proved box holds that partner.
  const Patch phi = from_power({"u", "v", "0"}, 4, 2);
  const Patch psi = from_power({"u + (1/4)*u^2", "v", "(4*v - 1 - u - u^2)^2 - (1/1048576)*(1 - 4*(2*u - 1)^2)"}, 4, 2);
  Surface_intersection_options o;
  o.max_total_degree_for_topology = 0;
  const Surface_locus L = intersection_locus(phi, psi, o);
  INFO(L.note);
  REQUIRE(L.topology_method == "subdivision");
  REQUIRE(L.topology.components.size() == 1);
  std::size_t points = 0, proved = 0;
  for (const auto& arc : L.arcs)
    for (const auto& q : arc.points) {
      ++points;
      if (!q.status_proved) continue;
      ++proved;
      CHECK(q.genuine);
      const double u = q.projection[0], t = q.projection[1], s = 2 * std::sqrt(1 + u) - 2;
      const auto& E = q.partner_enclosure;
      CHECK(E[0][0] <= t + 1e-7);
      CHECK(t - 1e-7 <= E[0][1]);
      CHECK(E[1][0] <= s + 1e-7);
      CHECK(s - 1e-7 <= E[1][1]);
      CHECK(E[0][1] - E[0][0] < 1e-6);
      CHECK(E[1][1] - E[1][0] < 1e-6);
    }
  CHECK(points > 1000);
  CHECK(proved >= points * 99 / 100);
}

namespace {
// |Phi(first) - Psi(second)| of a traced point, evaluated here (not the residual the library reports)
double pair_distance(const Patch& phi, const Patch& psi, const Locus_point& q) {
  const auto a = phi.evaluate(q.first[0], q.first[1]), b = psi.evaluate(q.second[0], q.second[1]);
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}
const Locus_edge_line* edge_line(const Surface_locus& L, int side) {
  for (const auto& e : L.edge_lines)
    if (e.side == side) return &e;
  return nullptr;
}
}  // namespace

// The bottom of the teapot is a surface of revolution cut into four 90-degree sectors (patches 28-31); each has its
// row 0 collapsed to the pole (0, 0, 0) and shares its side v = 1 with the next sector's side v = 0
// (teapot32_topology.txt: "28(bottom).col3 (v=1) == 29(bottom).col0 (v=0)", "row 0 collapsed to point (0, 0, 0)").
// So in the (u, t) plane of 28 and 29, D = 0 contains the box side t = 0 (the shared curve: the partner is 28's
// side v = 1) and the side u = 0 (the pole: 29's row 0, s = 0, is the same point). Two sectors meet nowhere else:
// no traced point of the rest of D = 0 may be genuine. Opposite sectors (28 and 30) share only the pole.
TEST_CASE("teapot: sectors meeting at the pole: the collapsed and the shared sides are edge lines",
          "[surface][teapot][edge]") {
  const auto doc = io::read_geometry_file(bezoutian_test::shared_data("teapot/teapot32.bpt"));
  REQUIRE(doc.patches.size() == 32);
  for (int partner : {29, 30}) {
    INFO("patches 28, " << partner);
    const Patch &phi = doc.patches[28], &psi = doc.patches[std::size_t(partner)];
    const Surface_locus L = intersection_locus(phi, psi);
    CHECK(L.topology_method == "subdivision");
    REQUIRE(L.edge_lines.size() == (partner == 29 ? 2u : 1u));
    const Locus_edge_line* pole = edge_line(L, 3);  // u = 0
    REQUIRE(pole);
    CHECK(pole->cause == Locus_edge_line::collapsed);
    CHECK(pole->partner_side == 3);  // the partner's s = 0
    CHECK(pole->genuine);
    CHECK(pole->status_proved);
    for (const auto& q : pole->points) {
      CHECK(q.point_3d == std::array<double, 3>{0, 0, 0});
      CHECK(pair_distance(phi, psi, q) == 0);
    }
    if (partner == 29) {
      const Locus_edge_line* seam = edge_line(L, 0);  // t = 0
      REQUIRE(seam);
      CHECK(seam->cause == Locus_edge_line::shared_curve);
      CHECK(seam->partner_side == 2);  // the first patch's v = 1
      CHECK(seam->status_proved);
      REQUIRE(seam->points.size() >= 25);  // the topology's samples, and more where a chord strays
      for (const auto& q : seam->points) {
        CHECK(q.first[1] == 1);
        CHECK(q.second[1] == 0);
        CHECK(std::fabs(q.first[0] - q.second[0]) < 1e-9);  // the same row of control points: the same parameter
        CHECK(pair_distance(phi, psi, q) < 1e-12);
      }
      // the polyline follows the curve to the default polyline tolerance (1e-3): at each chord's middle parameter
      // the curve phi(u, 1) is that close to the chord's midpoint (twice the tolerance: the test is at the middle
      // parameter, the refinement's at the middle of the graph coordinate)
      for (std::size_t i = 0; i + 1 < seam->points.size(); ++i) {
        const auto& a = seam->points[i].point_3d;
        const auto& b = seam->points[i + 1].point_3d;
        const auto m = phi.evaluate(0.5 * (seam->points[i].first[0] + seam->points[i + 1].first[0]), 1.0);
        CHECK(std::hypot(m[0] - 0.5 * (a[0] + b[0]), m[1] - 0.5 * (a[1] + b[1]), m[2] - 0.5 * (a[2] + b[2])) < 2e-3);
      }
    }
    // the rest of D = 0 is phantom, but where it ends on an edge line its end is a point of that side: genuine
    // (the pole, or the seam), proved
    std::size_t ends_on_sides = 0;
    for (const auto& arc : L.arcs)
      for (const auto& q : arc.points) {
        const bool on_side = q.projection[0] == 0 || (partner == 29 && q.projection[1] == 0);
        CHECK(q.genuine == on_side);
        if (on_side) {
          ++ends_on_sides;
          CHECK(q.status_proved);
          CHECK(pair_distance(phi, psi, q) < 1e-12);
        }
      }
    if (partner == 29) CHECK(ends_on_sides > 0);
  }
}

// Neighbours along a seam: the rim and the body (0, 4) and the body and the bottom (8, 31) are pieces of surfaces
// of revolution over the same angular arcs, whose profiles meet only at their common end; the handle's halves (12,
// 13) and the spout's (16, 17) are mirror images in y = 0, each on its own side. So each pair meets along its shared
// boundary curves alone. D = 0 has arcs beside the seams that end on them, with their partner tending to the seam's;
// the blow-up along the seam (lifting/internal/seam_blowup_exclusion.h) proves their fibres complete up to the end,
// also on the half-branches from the singular points of D = 0 on the spout's seams.
TEST_CASE("teapot: neighbours along a seam meet on the seam alone, certified", "[surface][teapot][edge]") {
  const auto doc = io::read_geometry_file(bezoutian_test::shared_data("teapot/teapot32.bpt"));
  REQUIRE(doc.patches.size() == 32);
  for (const auto& pair : {std::array<int, 2>{0, 4}, std::array<int, 2>{8, 31}, std::array<int, 2>{12, 13},
                           std::array<int, 2>{16, 17}}) {
    INFO("patches " << pair[0] << ", " << pair[1]);
    const Patch &phi = doc.patches[std::size_t(pair[0])], &psi = doc.patches[std::size_t(pair[1])];
    const Surface_locus L = intersection_locus(phi, psi);
    std::string why;
    CHECK(locus_certified(L, &why));
    INFO(why);
    std::size_t seams = 0;
    for (const auto& l : L.edge_lines) seams += l.cause == Locus_edge_line::shared_curve;
    CHECK(seams == (pair[0] >= 12 ? 2u : 1u));
    std::size_t ends = 0;
    for (const auto& arc : L.arcs) {
      CHECK(arc.fibre_undecided_fraction == 0);
      for (const auto& q : arc.points) {
        if (!q.genuine) continue;
        // a genuine point is a point of a shared side of the box
        bool on_seam = false;
        for (const auto& l : L.edge_lines) {
          const double c = CGAL::to_double(l.value);
          on_seam = on_seam || (l.cause == Locus_edge_line::shared_curve &&
                                q.projection[l.side == 1 || l.side == 3 ? 0 : 1] == c);
        }
        CHECK(on_seam);
        CHECK(q.status_proved);
        CHECK(pair_distance(phi, psi, q) < 1e-9);
        ++ends;
      }
    }
    CHECK(ends > 0);  // arcs of D = 0 do end on the seams
  }
}

// Diagonal neighbours around a vertex of the model: rim 1 and body 4 meet at one point, the corner (u, v) = (1, 0) of
// the rim and (s, t) = (0, 1) of the body (teapot32_topology.txt: 1|4 share no curve; the four patches 0, 1, 4, 5
// meet at that vertex). D = 0 has an arc ending at the corner (1, 1) of the (u, t) box, its partner tending to the
// corner's; the blow-up at the corner proves the fibre complete up to the end.
TEST_CASE("teapot: diagonal neighbours touching at a corner, certified", "[surface][teapot][edge]") {
  const auto doc = io::read_geometry_file(bezoutian_test::shared_data("teapot/teapot32.bpt"));
  REQUIRE(doc.patches.size() == 32);
  const Patch &phi = doc.patches[1], &psi = doc.patches[4];
  const Surface_locus L = intersection_locus(phi, psi);
  std::string why;
  CHECK(locus_certified(L, &why));
  INFO(why);
  CHECK(L.edge_lines.empty());
  std::size_t corner = 0;
  for (const auto& arc : L.arcs) {
    CHECK(arc.fibre_undecided_fraction == 0);
    for (const auto& q : arc.points)
      if (q.genuine) {
        CHECK(std::fabs(q.projection[0] - 1) + std::fabs(q.projection[1] - 1) < 1e-12);
        CHECK(std::fabs(q.first[0] - 1) + std::fabs(q.first[1]) < 1e-12);
        CHECK(pair_distance(phi, psi, q) < 1e-12);
        ++corner;
      }
  }
  CHECK(corner > 0);
}

// The same sectors with the partner domain [1/2, 1] x [0, 1]: a pair on the side u = 0 has its first point at u = 0,
// outside that domain, so the side is phantom at every point (proved by the definition); the side t = 0 runs over
// u in [0, 1], beyond the domain's u range, so no cause is proved for it (unexplained, status not proved).
TEST_CASE("teapot: edge lines outside the partner domain are phantom, those beyond it unexplained", "[surface][teapot][edge]") {
  const auto doc = io::read_geometry_file(bezoutian_test::shared_data("teapot/teapot32.bpt"));
  REQUIRE(doc.patches.size() == 32);
  Surface_intersection_options o;
  o.partner_domain = Parameter_box{Q(1, 2), Q(1), Q(0), Q(1)};
  o.certify_lifting = false;
  const Surface_locus L = intersection_locus(doc.patches[28], doc.patches[29], o);
  REQUIRE(L.edge_lines.size() == 2);
  const Locus_edge_line* pole = edge_line(L, 3);
  REQUIRE(pole);
  CHECK(pole->cause == Locus_edge_line::outside_domain);
  CHECK_FALSE(pole->genuine);
  CHECK(pole->status_proved);
  for (const auto& q : pole->points) {
    CHECK_FALSE(q.genuine);
    CHECK(q.status_proved);
  }
  const Locus_edge_line* seam = edge_line(L, 0);
  REQUIRE(seam);
  CHECK(seam->cause == Locus_edge_line::unexplained);
  CHECK_FALSE(seam->status_proved);
  for (const auto& q : seam->points) CHECK_FALSE(q.status_proved);
}

// A (2,2) polynomial patch whose column 2 (the side v = 1) is collapsed to (1, 2, 3): every pair of points of that
// side is a double point, so D vanishes on the whole side. CGAL's curve analysis of such a D and the box line throws
// (the two share a component), so the side is taken out of D (an edge line).
TEST_CASE("self-intersection: a collapsed side is an edge line, the rest of the locus is certified", "[surface][edge]") {
  const std::vector<std::vector<Patch::Point>> net = {{{Q(-2), Q(4), Q(3)}, {Q(-3), Q(0), Q(4)}, {Q(1), Q(2), Q(3)}},
                                                      {{Q(-4), Q(4), Q(-5)}, {Q(2), Q(-1), Q(3)}, {Q(1), Q(2), Q(3)}},
                                                      {{Q(3), Q(3), Q(2)}, {Q(1), Q(5), Q(-3)}, {Q(1), Q(2), Q(3)}}};
  const Patch phi(net);
  const Surface_locus L = self_intersection_locus(phi);
  CHECK(L.topology_method == "subdivision");
  REQUIRE(L.edge_lines.size() == 1);
  const Locus_edge_line& e = L.edge_lines[0];
  CHECK(e.side == 2);
  CHECK(e.value == 1);
  CHECK(e.cause == Locus_edge_line::collapsed);
  CHECK(e.partner_side == -1);
  CHECK(e.genuine);
  for (const auto& q : e.points) {
    CHECK(q.point_3d == std::array<double, 3>{1, 2, 3});
    CHECK(q.first[1] == 1);
    CHECK(q.second[1] == 1);
    CHECK(q.first[0] != q.second[0]);  // two distinct points of the side
    CHECK(pair_distance(phi, phi, q) < 1e-14);
  }
  // the rest still ends on the side: its boundary points on v = 1
  std::size_t on_side = 0;
  for (const auto& v : L.topology.vertices) on_side += v.on_boundary && v.v_lo <= 1 && 1 <= v.v_hi;
  CHECK(on_side >= 1);
  // the pinch-point search cannot be complete (the whole side has rank <= 1) and says why
  CHECK_FALSE(L.pinch_points_complete);
  CHECK(L.pinch_points_note.find("collapsed edge") != std::string::npos);
}

// A closed patch: Phi(u, v) = ((1 + v) x(u), (1 + v) y(u), v + x(u)) with the teardrop cubic (x, y) of control
// points (0,0), (4,4), (-4,4), (0,0), so Phi(0, v) = Phi(1, v) = (0, 0, v): the sides u = 0 and u = 1 are one seam,
// each the partner of the other (l = +-1, k = 0).
TEST_CASE("self-intersection: the seam of a closed patch is a pair of edge lines", "[surface][edge]") {
  const int X[4] = {0, 4, -4, 0}, Y[4] = {0, 4, 4, 0};
  std::vector<std::vector<Patch::Point>> net(4, std::vector<Patch::Point>(2));
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 2; ++j) net[i][j] = {Q(X[i] * (1 + j)), Q(Y[i] * (1 + j)), Q(j + X[i])};
  const Patch phi(net);
  const Surface_locus L = self_intersection_locus(phi);
  CHECK(L.topology_method == "subdivision");
  REQUIRE(L.edge_lines.size() == 2);
  for (int side : {1, 3}) {
    const Locus_edge_line* e = edge_line(L, side);
    REQUIRE(e);
    CHECK(e->cause == Locus_edge_line::shared_curve);
    CHECK(e->partner_side == 4 - side);
    CHECK(e->genuine);
    for (const auto& q : e->points) {
      CHECK(std::fabs(q.partner[0]) == 1);
      CHECK(std::fabs(q.partner[1]) < 1e-9);
      CHECK(std::fabs(q.point_3d[2] - q.projection[1]) < 1e-9);  // the seam point (0, 0, v)
      CHECK(pair_distance(phi, phi, q) < 1e-12);
    }
  }
}

// Diagonal neighbours of the teapot's quad mesh (rim 0 and body 5, rim 1 and body 4) touch at one vertex, where the
// two sheets of the smooth surface are tangent: D = 0 has a cusp at that corner of the (u, t) box, tangent to a side
// (resolved by the weighted blow-up, topology/internal/corner_blowup.h). Independent facts: the contact is one exact
// common corner point (boundary_contacts), and two sectors of different rings meet nowhere else, so no other traced
// point may be genuine.
TEST_CASE("teapot: diagonal neighbours touching at a corner are certified, the corner a singular boundary point",
          "[surface][teapot][corner]") {
  const auto doc = io::read_geometry_file(bezoutian_test::shared_data("teapot/teapot32.bpt"));
  REQUIRE(doc.patches.size() == 32);
  for (const auto& pr : {std::make_pair(0, 5), std::make_pair(1, 4)}) {
    INFO("patches " << pr.first << ", " << pr.second);
    const Surface_locus L = intersection_locus(doc.patches[std::size_t(pr.first)], doc.patches[std::size_t(pr.second)]);
    CHECK(L.topology_method == "subdivision");
    CHECK(L.edge_lines.empty());
    REQUIRE(L.contacts.size() == 1);
    CHECK_FALSE(L.contacts[0].shared_curve);
    std::size_t corners = 0;
    double cu = -1, cv = -1;
    for (const auto& v : L.topology.vertices)
      if (v.on_boundary && (v.kind == Curve_topology_vertex::singular || v.kind == Curve_topology_vertex::isolated)) {
        ++corners;
        cu = v.u, cv = v.v;
        CHECK(v.singular_on_boundary);
        CHECK(v.u_lo == v.u_hi);  // exact: a corner of the box
        CHECK(v.v_lo == v.v_hi);
        CHECK(v.branches <= 2);
      }
    REQUIRE(corners == 1);
    CHECK(((cu == 0 || cu == 1) && (cv == 0 || cv == 1)));
    for (const auto& arc : L.arcs)
      for (const auto& q : arc.points)
        if (q.genuine) CHECK(std::fabs(q.projection[0] - cu) + std::fabs(q.projection[1] - cv) < 1e-9);
  }
}

// The spout's patches: 16 and 17 are the two halves of the lower tube, 18 and 19 of the upper one
// (teapot32_topology.txt: "16(spout).col0 (v=0) == 17(spout).col3 (v=1)", "16(spout).col3 (v=1) == 17(spout).col0
// (v=0)", "16(spout).row3 (u=1) == 18(spout).row0", "17(spout).row3 (u=1) == 19(spout).row0", and 18, 19 glued along
// both seams). Independent facts used: 16 x 17 meet along the two seams only, so both sides t = 0, 1 are shared
// curves and nothing else is genuine; there the rest of D meets each seam at a singular point inside the side
// (resolve_edge_point); 16 x 19 and 17 x 18 meet at the two ends of the joint row only, two corners of the (u, t) box,
// where the Newton polygon of D has two edges (corner_blowup.h).
TEST_CASE("teapot spout: singular points inside a shared side and two-edge corners are certified",
          "[surface][teapot][edge_point]") {
  const auto doc = io::read_geometry_file(bezoutian_test::shared_data("teapot/teapot32.bpt"));
  REQUIRE(doc.patches.size() == 32);
  {
    const Surface_locus L = intersection_locus(doc.patches[16], doc.patches[17]);
    CHECK(L.topology_method == "subdivision");
    REQUIRE(L.edge_lines.size() == 2);
    for (int side : {0, 2}) {
      const Locus_edge_line* seam = edge_line(L, side);
      REQUIRE(seam);
      CHECK(seam->cause == Locus_edge_line::shared_curve);
      CHECK(seam->partner_side == 2 - side);  // t = 0 with the first patch's v = 1, t = 1 with v = 0
      CHECK(seam->status_proved);
    }
    std::size_t on_sides = 0;
    for (const auto& v : L.topology.vertices)
      if (v.singular_on_boundary) {
        ++on_sides;
        CHECK(v.kind == Curve_topology_vertex::singular);
        CHECK((v.v == 0 || v.v == 1));  // on a seam, exactly
        CHECK(v.u > 0.01);
        CHECK(v.u < 0.99);               // not at a corner
        CHECK(v.u_hi - v.u_lo < 1e-12);  // an isolated root on the side
        // D of the rest (the seams' factors removed) and its gradient vanish there, in floating point
        const auto& D = internal::box_edge_lines(L.equation.square_free, Parameter_box{}).rest;
        double d = 0, du = 0, dv = 0, scale = 0;
        for (int j = 0; j <= D.degree(); ++j)
          for (int i = 0; i <= D[j].degree(); ++i) {
            const double c = CGAL::to_double(D[j][i]), m = std::pow(v.u, i) * std::pow(v.v, j);
            d += c * m;
            if (i > 0) du += c * i * std::pow(v.u, i - 1) * std::pow(v.v, j);
            if (j > 0) dv += c * j * std::pow(v.u, i) * std::pow(v.v, j - 1);
            scale += std::fabs(c) * m * (1 + i + j);
          }
        CHECK(std::fabs(d) < 1e-9 * scale);
        CHECK(std::fabs(du) < 1e-6 * scale);
        CHECK(std::fabs(dv) < 1e-6 * scale);
      }
    CHECK(on_sides == 2);  // one on each seam
    for (const auto& arc : L.arcs)
      for (const auto& q : arc.points) {  // the ends on the seams are genuine points (of the seams)
        if (q.genuine) CHECK(std::min(q.projection[1], 1 - q.projection[1]) < 1e-12);
        // every status is proved, along the half-branches from the seam points too, where the two halves nearly
        // coincide and Krawczyk's test fails: there the slabs are excluded, and the ends lie on the seams
        CHECK(q.status_proved);
      }
    std::size_t seam_ends = 0;
    for (const auto& arc : L.arcs)
      for (const Locus_point* q : {&arc.points.front(), &arc.points.back()})
        if (q->projection[1] == 0 || q->projection[1] == 1) {
          ++seam_ends;
          CHECK(q->genuine);
          // its pair lies on the shared boundary curve: v = 0 with t = 1, v = 1 with t = 0, and s = u
          // (teapot32_topology.txt: the seams are glued with the same parameter along them), one 3D point
          CHECK(q->first[1] == 1 - q->projection[1]);
          CHECK(std::fabs(q->second[0] - q->projection[0]) < 1e-9);
          CHECK(q->residual < 1e-9);
        }
    CHECK(seam_ends == 2);
  }
  for (const auto& pr : {std::make_pair(16, 19), std::make_pair(17, 18)}) {
    INFO("patches " << pr.first << ", " << pr.second);
    const Surface_locus L = intersection_locus(doc.patches[std::size_t(pr.first)], doc.patches[std::size_t(pr.second)]);
    CHECK(L.topology_method == "subdivision");
    CHECK(L.edge_lines.empty());
    REQUIRE(L.contacts.size() == 2);
    for (const auto& c : L.contacts) CHECK_FALSE(c.shared_curve);
    std::size_t corners = 0;
    for (const auto& v : L.topology.vertices)
      if (v.singular_on_boundary) {
        ++corners;
        CHECK(v.u == 1);  // the first patch's joint row
        CHECK((v.v == 0 || v.v == 1));
        CHECK(v.u_lo == v.u_hi);
      }
    CHECK(corners == 2);
    for (const auto& arc : L.arcs)
      for (const auto& q : arc.points)
        if (q.genuine) CHECK(std::fabs(q.projection[0] - 1) + std::min(q.projection[1], 1 - q.projection[1]) < 1e-9);
  }
}

// The handle's two halves, 12 and 13, glued along both seams (teapot32_topology.txt: "12(handle).col0 (v=0) ==
// 13(handle).col3 (v=1)", "12(handle).col3 (v=1) == 13(handle).col0 (v=0)"). Independent fact, read from the file:
// every control point of 12 has y <= 0 and every one of 13 has y >= 0, so (convex hulls) their common points lie in
// the plane y = 0. Next to the seams the two halves continue each other smoothly: beyond the seam the partner
// equations nearly vanish, the kernel of B is nearly two-dimensional, and both the floating-point lifting (a kernel
// ratio of 2.5e16) and the span proofs fail there (9 of 39 statuses without the point-wise proofs next to seams,
// doc/surface_intersection.md, 4b).
TEST_CASE("teapot handle halves: every status next to the seams is proved, every lifted partner is finite",
          "[surface][teapot][seam]") {
  const auto doc = io::read_geometry_file(bezoutian_test::shared_data("teapot/teapot32.bpt"));
  REQUIRE(doc.patches.size() == 32);
  const auto& a = doc.patches[12];
  const auto& b = doc.patches[13];
  for (int i = 0; i <= a.degree_u(); ++i)
    for (int j = 0; j <= a.degree_v(); ++j) {
      REQUIRE(a.control_point(std::size_t(i), std::size_t(j))[1] <= 0);
      REQUIRE(b.control_point(std::size_t(i), std::size_t(j))[1] >= 0);
    }
  const Surface_locus L = intersection_locus(a, b);
  REQUIRE(L.topology_computed);
  CHECK(L.topology_method == "subdivision");
  REQUIRE(L.edge_lines.size() == 2);  // the two seams
  std::size_t points = 0, genuine = 0;
  for (const auto& arc : L.arcs)
    for (const auto& q : arc.points) {
      INFO("point (" << q.projection[0] << ", " << q.projection[1] << "), partner (" << q.partner[0] << ", "
                     << q.partner[1] << "), residual " << q.residual);
      ++points;
      CHECK(q.status_proved);
      // the lifted partner is a point near the surfaces, not a runaway ratio of a nearly singular kernel
      CHECK(std::isfinite(q.residual));
      CHECK(std::fabs(q.partner[0]) < 10);
      CHECK(std::fabs(q.partner[1]) < 10);
      if (q.genuine) {
        ++genuine;
        CHECK(std::fabs(q.point_3d[1]) < 1e-9);  // in the plane y = 0
        CHECK(q.residual < 1e-9);
      }
    }
  CHECK(points > 30);
  CHECK(genuine >= 1);
}

// Surface (self-)intersections on the structured patches CAD models are made of, where the Bezoutian of Theorems
// 2-5 is singular (det B = 0 identically): height fields, sphere patches with a pole, two height fields over one
// square. Expected answers come from the closed forms; completeness is checked against dense samples of the closed-
// form curve, in the parameter plane and in 3D.

namespace {

Rational_bezier_patch<> power_patch(const std::string& x, const std::string& y, const std::string& z, const std::string& w,
                                    int m, int n) {
  return bezoutian_test::rational_patch_from_power({x, y, z, w}, m, n);
}

std::size_t traced_points(const Surface_locus& L) {
  std::size_t n = 0;
  for (const auto& a : L.arcs) n += a.points.size();
  return n;
}

// The largest distance from a sample of the closed-form curve to the nearest genuine traced point: in the (u, t)
// plane and between the 3D points. `curve` maps a parameter in [0,1] to (u, t) on the true curve.
std::array<double, 2> worst_gap(const Surface_locus& L, const Rational_bezier_patch<>& phi,
                                const std::function<std::array<double, 2>(double)>& curve, int samples = 2000) {
  std::array<double, 2> worst{0, 0};
  for (int i = 0; i <= samples; ++i) {
    const auto p = curve(double(i) / samples);
    const auto x = phi.evaluate(p[0], p[1]);
    double best2 = 1e300, best3 = 1e300;
    for (const auto& a : L.arcs)
      for (const auto& q : a.points) {
        if (!q.genuine) continue;
        best2 = std::min(best2, std::hypot(q.projection[0] - p[0], q.projection[1] - p[1]));
        best3 = std::min(best3, std::hypot(q.point_3d[0] - x[0], q.point_3d[1] - x[1], q.point_3d[2] - x[2]));
      }
    worst = {std::max(worst[0], best2), std::max(worst[1], best3)};
  }
  return worst;
}

}  // namespace

TEST_CASE("structured surfaces: patches that do not self-intersect are proved so (det B = 0 identically)",
          "[surface][structured]") {
  const auto height = power_patch("u", "v", "u^2*v - (1/3)*v^3 + u*v", "1", 2, 3);
  const auto cap = power_patch("2*(u - 1/2)", "2*(v - 1/2)", "1 - (u - 1/2)^2 - (v - 1/2)^2",
                               "1 + (u - 1/2)^2 + (v - 1/2)^2", 2, 2);
  // the Bezoutian of Theorems 4-5 is singular for the height field (an exact graph over the (u, v) plane)
  CHECK(self_intersection_equation(height).is_degenerate());
  for (const auto* P : {&height, &cap}) {
    const Surface_locus L = self_intersection_locus(*P);
    INFO(L.note);
    CHECK(L.topology_computed);
    CHECK(L.topology_method == "injective projection");
    CHECK_FALSE(L.equation_computed);
    CHECK(L.topology.components.empty());
    CHECK(L.edge_lines.empty());
  }
}

TEST_CASE("structured surfaces: the sphere octant's only double points are its pole edge", "[surface][structured]") {
  // ((1-v^2)(1-u^2), 2u(1-v^2), 2v(1+u^2)) / ((1+u^2)(1+v^2)): the side v = 1 is the north pole (0, 0, 1)
  const auto octant = power_patch("(1 - v^2)*(1 - u^2)", "2*u*(1 - v^2)", "2*v*(1 + u^2)", "(1 + u^2)*(1 + v^2)", 2, 2);
  const Surface_locus L = self_intersection_locus(octant);
  INFO(L.note);
  CHECK(L.topology_computed);
  CHECK(L.topology.components.empty());
  REQUIRE(L.edge_lines.size() == 1);
  const Locus_edge_line& e = L.edge_lines[0];
  CHECK(e.side == 2);
  CHECK(e.value == Rational(1));
  CHECK(e.cause == Locus_edge_line::collapsed);
  CHECK(e.genuine);
  CHECK(e.status_proved);
  for (const auto& q : e.points) CHECK(std::hypot(q.point_3d[0], q.point_3d[1], q.point_3d[2] - 1) < 1e-12);
}

TEST_CASE("structured surfaces: two height fields over one square meet along h(u, t) = 0, every branch",
          "[surface][structured]") {
  // z = uv + v and z = uv + u^2 - u + 1/2 over x = u, y = v: they meet where v = u^2 - u + 1/2 (an open arc across
  // the square, from (0, 1/2) to (1, 1/2))
  const auto f = power_patch("u", "v", "u*v + v", "1", 2, 1);
  const auto g = power_patch("u", "v", "u*v + u^2 - u + 1/2", "1", 2, 1);
  // fine polylines, so that a sample of the true curve far from every traced point is a missing branch
  Surface_intersection_options o;
  o.subdivision.samples_per_arc = 200;  // per arc piece in one leaf box of the subdivision
  const Surface_locus L = intersection_locus(f, g, o);
  INFO(L.note);
  REQUIRE(L.topology_computed);
  CHECK(L.topology_method == "subdivision");
  REQUIRE(L.topology.components.size() == 1);
  CHECK_FALSE(L.topology.components[0].closed);
  CHECK(L.topology.number_of_boundary_points() == 2);
  REQUIRE(traced_points(L) > 0);
  for (const auto& a : L.arcs) {
    CHECK(a.undecided_fraction == 0);
    for (const auto& q : a.points) {
      CHECK(q.genuine);
      CHECK(q.status_proved);
      const double u = q.projection[0], t = q.projection[1];
      CHECK(std::fabs(t - (u * u - u + 0.5)) < 1e-8);            // on the closed-form curve
      CHECK(q.residual < 1e-8);                                   // on both surfaces
      CHECK(q.partner[0] == t);                                   // the exact partner (v, s) = (t, u)
      CHECK(q.partner[1] == u);
    }
  }
  const auto gap = worst_gap(L, f, [](double x) { return std::array<double, 2>{x, x * x - x + 0.5}; });
  CHECK(gap[0] < 0.02);
  CHECK(gap[1] < 0.02);

  // a closed loop: h = (u - 1/2)^2 + (v - 1/2)^2 - 1/16, the circle of radius 1/4 about the centre
  const auto p = power_patch("u", "v", "u*v + (u - 1/2)^2 + (v - 1/2)^2", "1", 2, 2);
  const auto q = power_patch("u", "v", "u*v + 1/16", "1", 2, 2);
  const Surface_locus C = intersection_locus(p, q, o);
  INFO(C.note);
  REQUIRE(C.topology_computed);
  REQUIRE(C.topology.components.size() == 1);
  CHECK(C.topology.components[0].closed);
  CHECK(C.topology.number_of_boundary_points() == 0);
  const auto gc = worst_gap(C, p, [](double x) {
    return std::array<double, 2>{0.5 + 0.25 * std::cos(2 * M_PI * x), 0.5 + 0.25 * std::sin(2 * M_PI * x)};
  });
  CHECK(gc[0] < 0.02);
  CHECK(gc[1] < 0.02);
}

TEST_CASE("structured surfaces: two height fields touching at one point report the contact, exactly",
          "[surface][structured]") {
  // z = (2u - 1)^2 + (2v - 1)^2 and z = -(2u - 1)^2 - (2v - 1)^2 over x = 2u - 1, y = 2v - 1: h = 2((2u - 1)^2 +
  // (2t - 1)^2) vanishes at (1/2, 1/2) only; the paraboloids touch there, tangentially, at the origin
  const auto up = power_patch("2*u - 1", "2*v - 1", "(2*u - 1)^2 + (2*v - 1)^2", "1", 2, 2);
  const auto down = power_patch("2*u - 1", "2*v - 1", "-(2*u - 1)^2 - (2*v - 1)^2", "1", 2, 2);
  const Surface_locus L = intersection_locus(up, down);
  INFO(L.note);
  CHECK_FALSE(L.equation_computed);  // the common projection, without elimination
  REQUIRE(L.topology_computed);
  REQUIRE(L.topology.components.size() == 1);
  CHECK(L.topology.components[0].isolated_point);
  REQUIRE(L.isolated_points.size() == 1);
  const auto& x = L.isolated_points[0].lift;
  CHECK(x.proved);
  CHECK(L.isolated_points[0].genuine());
  REQUIRE(x.exact);
  CHECK(x.projection[0] == Rational(1, 2));
  CHECK(x.projection[1] == Rational(1, 2));
  REQUIRE(x.partners.size() == 1);
  CHECK(x.partners[0].v.compare(Rational(1, 2)) == 0);
  CHECK(x.partners[0].s.compare(Rational(1, 2)) == 0);
  CHECK(x.partners[0].tangency_decided);
  CHECK(x.partners[0].tangent);
  CHECK(std::hypot(x.partners[0].point[0], x.partners[0].point[1], x.partners[0].point[2]) < 1e-15);
  std::string why;
  CHECK(locus_certified(L, &why));
  INFO(why);
}

TEST_CASE("structured surfaces: height fields apart, patches apart, coincident height fields", "[surface][structured]") {
  // parallel height fields 1/10 apart: h = -1/10, a nonzero constant: no intersection, proved
  const auto low = power_patch("u", "v", "u*v", "1", 1, 1);
  const auto high = power_patch("u", "v", "u*v + 1/10", "1", 1, 1);
  const Surface_locus L = intersection_locus(low, high);
  INFO(L.note);
  CHECK(L.topology_computed);
  CHECK(L.topology.components.empty());
  // the sphere octant below the plane z = 101/100: its hull is apart from the plane
  const auto octant = power_patch("(1 - v^2)*(1 - u^2)", "2*u*(1 - v^2)", "2*v*(1 + u^2)", "(1 + u^2)*(1 + v^2)", 2, 2);
  const auto plane = power_patch("2*u - 1/2", "2*v - 1/2", "101/100", "1", 1, 1);
  const Surface_locus S = intersection_locus(octant, plane);
  INFO(S.note);
  CHECK(S.topology_computed);
  CHECK(S.topology_method == "separated hulls");
  CHECK(S.topology.components.empty());
  // one height field twice: the patches coincide, the whole square is an overlap (proved), reported as such
  const Surface_locus C = intersection_locus(low, low);
  INFO(C.note);
  CHECK(C.topology_computed);
  CHECK(C.topology_method == "common parent");
  REQUIRE(C.overlaps.size() == 1);
  const std::array<Q, 4> square{Q(0), Q(1), Q(0), Q(1)};
  CHECK(C.overlaps[0].first == square);
  CHECK(C.overlaps[0].second == square);
}

namespace {
// Distance from p to the polyline through the 3D points (or, with `coordinates` 0 / 2, the first / second
// parameter points) of a sheet.
double distance_to_sheet(const Locus_sheet& s, const std::array<double, 3>& p, int coordinates) {
  auto at = [&](const Locus_point& q) {
    if (coordinates == 0) return std::array<double, 3>{q.first[0], q.first[1], 0};
    if (coordinates == 2) return std::array<double, 3>{q.second[0], q.second[1], 0};
    return q.point_3d;
  };
  double best = 1e300;
  for (std::size_t i = 0; i + 1 < s.points.size(); ++i) {
    const auto a = at(s.points[i]), b = at(s.points[i + 1]);
    const std::array<double, 3> d{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    double f = dd > 0 ? ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1] + (p[2] - a[2]) * d[2]) / dd : 0;
    f = std::max(0.0, std::min(1.0, f));
    best = std::min(best, std::hypot(p[0] - a[0] - f * d[0], p[1] - a[1] - f * d[1], p[2] - a[2] - f * d[2]));
  }
  if (s.points.size() == 1) {
    const auto a = at(s.points[0]);
    best = std::hypot(p[0] - a[0], p[1] - a[1], p[2] - a[2]);
  }
  return best;
}
// The worst distance, over the closed-form samples (3D point, first and second parameter points), to the nearest
// sheet of the locus: in 3D and in each parameter domain.
std::array<double, 3> worst_sheet_gap(const Surface_locus& L,
                                      const std::vector<std::array<std::array<double, 3>, 3>>& samples) {
  std::array<double, 3> worst{0, 0, 0};
  for (const auto& x : samples)
    for (int c = 0; c < 3; ++c) {
      double best = 1e300;
      for (const auto& a : L.arcs)
        for (const auto& s : a.sheets) best = std::min(best, distance_to_sheet(s, x[std::size_t(c == 0 ? 1 : c == 1 ? 0 : 2)], c == 0 ? 1 : c == 1 ? 0 : 2));
      worst[std::size_t(c)] = std::max(worst[std::size_t(c)], best);
    }
  return worst;
}

/// Completeness: every sample lies within `tolerance` of a sheet's polyline, in both parameter domains and in 3D.
void check_sheets_complete(const Surface_locus& L, const std::vector<std::array<std::array<double, 3>, 3>>& samples,
                           double tolerance) {
  const auto gap = worst_sheet_gap(L, samples);
  CHECK(gap[0] < tolerance);  // (u, v)
  CHECK(gap[1] < tolerance);  // 3D
  CHECK(gap[2] < tolerance);  // (s, t)
}

/// The locus with each sheet cut down to its runs of points whose genuine status is proved: completeness against
/// the closed form on it checks the proofs (a span wrongly proved phantom leaves samples uncovered), where the
/// sheets themselves are the floating-point partners in the domain. A sheet's two end points are kept: a sheet ends
/// at a fold of its partner, a split point or a vertex of D = 0, a point with a certified box of its own that the
/// span proofs end in, not a point of a proved span.
Surface_locus proved_genuine_sheets(Surface_locus L) {
  for (auto& a : L.arcs) {
    std::vector<Locus_sheet> runs;
    for (const auto& s : a.sheets) {
      Locus_sheet run;
      for (std::size_t j = 0; j <= s.points.size(); ++j) {
        const bool end = j == 0 || j + 1 == s.points.size();
        if (j < s.points.size() && s.points[j].genuine && (s.points[j].status_proved || end)) {
          if (run.points.empty()) run.first = s.first + j;
          run.points.push_back(s.points[j]);
        } else if (!run.points.empty()) {
          runs.push_back(run);
          run = Locus_sheet{};
        }
      }
    }
    a.sheets = runs;
  }
  return L;
}
}  // namespace

TEST_CASE("structured surfaces: two cylinders crossing, both branches over one projected arc are lifted",
          "[surface][structured][sheets]") {
  // examples/data/two_cylinders.json: y^2 + z^2 = 1 (x = 2u - 1, angle a = (2v - 1)/2) and x^2 + z^2 = 1
  // (y = 2t - 1, angle b = (2s - 1)/2). Inside the patches: x = y = c in [3/5, 1], z = +-sqrt(1 - c^2), two
  // branches over the one projected arc u = t, meeting at the corner (1, 1, 0).
  const auto doc = io::read_geometry_file(std::string(BEZOUTIAN_SOURCE_DIR) + "/examples/data/two_cylinders.json");
  REQUIRE(doc.patches.size() == 2);
  const Patch &phi = doc.patches[0], &psi = doc.patches[1];
  Surface_intersection_options fine;
  fine.polyline_tolerance = 1e-3;
  const Surface_locus L = intersection_locus(phi, psi, fine);
  INFO(L.note);
  REQUIRE(L.topology_computed);
  std::size_t sheets = 0;
  // the curve leaves both patches at x = y = 3/5, where the partner is the corner (v, s) = (1, 1): an exact split
  // point at (u, t) = (4/5, 4/5) (lifting/partner_boundary_points.h)
  std::size_t corner_splits = 0;
  for (const auto& sp : L.split_points) {
    const auto& q = L.arcs[sp.arc].points[sp.index];
    corner_splits += std::fabs(q.projection[0] - 0.8) < 1e-15 && std::fabs(q.projection[1] - 0.8) < 1e-15 &&
                     q.genuine && q.status_proved && std::fabs(q.partner[0] - 1) < 1e-12 &&
                     std::fabs(q.partner[1] - 1) < 1e-12;
  }
  CHECK(corner_splits == 1);
  for (const auto& a : L.arcs) {
    // every partner proved found, up to the corner (1, 1) where the two branches meet in a fold of the partner
    // (lifting/internal/partner_fold_proofs.h); every status, beside the exact split point by the monotone partner
    // coordinates (lifting/internal/exact_point_spans.h)
    CHECK(a.fibre_undecided_fraction == 0);
    CHECK(a.undecided_fraction == 0);
    for (const auto& s : a.sheets) {
      ++sheets;
      for (const auto& q : s.points) {
        const auto& p = q.point_3d;
        CHECK(std::fabs(p[1] * p[1] + p[2] * p[2] - 1) < 1e-9);  // on both closed-form cylinders
        CHECK(std::fabs(p[0] * p[0] + p[2] * p[2] - 1) < 1e-9);
        CHECK(distance3(phi.evaluate(q.first[0], q.first[1]), psi.evaluate(q.second[0], q.second[1])) < 1e-9);
      }
    }
  }
  CHECK(sheets == 2);
  // completeness: the closed form, 4002 samples, against the sheets' polylines (3D and both parameter domains)
  std::vector<std::array<std::array<double, 3>, 3>> samples;
  for (int k = 0; k <= 2000; ++k)
    for (int sign : {-1, 1}) {
      const double c = 0.6 + 0.4 * k / 2000, z = sign * std::sqrt(std::max(0.0, 1 - c * c));
      const double a = z / (1 + c);  // (y, z) = (1 - a^2, 2a)/(1 + a^2) with y = c
      samples.push_back({std::array<double, 3>{(c + 1) / 2, (2 * a + 1) / 2, 0}, std::array<double, 3>{c, c, z},
                         std::array<double, 3>{(2 * a + 1) / 2, (c + 1) / 2, 0}});
    }
  const auto gap = worst_sheet_gap(L, samples);
  CHECK(gap[0] < 5e-3);  // (u, v)
  CHECK(gap[1] < 5e-3);  // 3D
  CHECK(gap[2] < 5e-3);  // (s, t)
  // the same against the points whose genuine status is proved: every span proved phantom is phantom
  check_sheets_complete(proved_genuine_sheets(L), samples, 5e-3);
  // without complete lifting the arc carries one partner per point: one of the branches is (partly) missing
  Surface_intersection_options one;
  one.complete_lifting = false;
  const Surface_locus K = intersection_locus(phi, psi, one);
  std::size_t far = 0;
  for (const auto& x : samples) {
    double best = 1e300;
    for (const auto& a : K.arcs)
      for (const auto& q : a.points)
        if (q.genuine) best = std::min(best, distance3(q.point_3d, x[1]));
    far += best > 0.05;
  }
  CHECK(far > 1000);
}

namespace {
using Sample = std::array<std::array<double, 3>, 3>;  // {first parameter point, 3D point, second parameter point}

/// Every proved segment bound of the sheets (Locus_sheet::segment_distance_bounds) against the closed form, given
/// as branches of ordered dense samples: each of 17 points of a segment's chord lies within its bound, plus half
/// the largest spacing of consecutive samples, of the nearest sample (first domain, 3D, second domain). The
/// nearest sample is at most half a spacing farther than the true curve, so a bound that does not hold by more
/// than that fails. Returns {segments, segments proved, the largest proved 3D bound}.
std::array<double, 3> check_distance_bounds(const Surface_locus& L, const std::vector<std::vector<Sample>>& branches) {
  std::array<double, 3> spacing{0, 0, 0};
  for (const auto& b : branches)
    for (std::size_t i = 0; i + 1 < b.size(); ++i)
      for (std::size_t c = 0; c < 3; ++c) spacing[c] = std::max(spacing[c], distance3(b[i][c], b[i + 1][c]));
  auto coordinates = [](const Locus_point& q, std::size_t c) {
    if (c == 0) return std::array<double, 3>{q.first[0], q.first[1], 0};
    if (c == 2) return std::array<double, 3>{q.second[0], q.second[1], 0};
    return q.point_3d;
  };
  std::array<double, 3> out{0, 0, 0};
  for (const auto& a : L.arcs)
    for (const auto& s : a.sheets) {
      REQUIRE(s.segment_distance_bounds.size() + 1 == s.points.size());
      for (std::size_t j = 0; j + 1 < s.points.size(); ++j) {
        const auto& bound = s.segment_distance_bounds[j];
        out[0] += 1;
        if (!std::isfinite(bound[0])) continue;
        out[1] += 1;
        out[2] = std::max(out[2], bound[2]);
        for (std::size_t c = 0; c < 3; ++c) {
          const double allowed = bound[c == 0 ? 0 : c == 1 ? 2 : 1] + 0.5 * spacing[c];
          const auto p = coordinates(s.points[j], c), q = coordinates(s.points[j + 1], c);
          for (int k = 0; k <= 16; ++k) {
            const double f = k / 16.0;
            const std::array<double, 3> x{p[0] + f * (q[0] - p[0]), p[1] + f * (q[1] - p[1]), p[2] + f * (q[2] - p[2])};
            double nearest = 1e300;
            for (const auto& b : branches)
              for (const auto& y : b) nearest = std::min(nearest, distance3(x, y[c]));
            INFO("segment " << j << " coordinates " << c << " bound " << bound[c == 0 ? 0 : c == 1 ? 2 : 1]);
            CHECK(nearest <= allowed);
          }
        }
      }
    }
  return out;
}
}  // namespace

TEST_CASE("polyline distance bounds: proved chord distances hold against closed forms", "[surface][structured][bounds]") {
  Surface_intersection_options o;
  o.polyline_tolerance = 1e-3;
  SECTION("paraboloid and plane strip: the arc of the circle u^2 + v^2 = 1/4, z = 1/4, up to its split point") {
    // examples/data/paraboloid_plane_strip.json: (u, v) = (cos a, sin a) / 2 with partner (s, t) = (4u, v), genuine
    // for s <= 1, i.e. a in [pi/3, pi/2]
    const auto doc = io::read_geometry_file(std::string(BEZOUTIAN_SOURCE_DIR) + "/examples/data/paraboloid_plane_strip.json");
    const Surface_locus L = intersection_locus(doc.patches[0], doc.patches[1], o);
    REQUIRE(L.topology_computed);
    std::vector<Sample> branch;
    for (int k = 0; k <= 20000; ++k) {
      const double a = M_PI / 3 + (M_PI / 6) * k / 20000, u = std::cos(a) / 2, v = std::sin(a) / 2;
      branch.push_back({std::array<double, 3>{u, v, 0}, std::array<double, 3>{u, v, 0.25},
                        std::array<double, 3>{4 * u, v, 0}});
    }
    const auto r = check_distance_bounds(L, {branch});
    // every segment proved, each bound within four times the tolerance the refinement aims at
    CHECK(r[0] >= 20);
    CHECK(r[1] == r[0]);
    CHECK(r[2] <= 4e-3);
    for (const auto& a : L.arcs)
      for (const auto& s : a.sheets) CHECK(sheet_distance_bound(s)[2] <= 4e-3);
  }
  SECTION("two cylinders: both branches, every segment but the one ending at the corner fold") {
    const auto doc = io::read_geometry_file(std::string(BEZOUTIAN_SOURCE_DIR) + "/examples/data/two_cylinders.json");
    const Surface_locus L = intersection_locus(doc.patches[0], doc.patches[1], o);
    REQUIRE(L.topology_computed);
    std::vector<std::vector<Sample>> branches(2);
    for (int sign : {-1, 1})
      for (int k = 0; k <= 20000; ++k) {
        const double c = 0.6 + 0.4 * k / 20000, z = sign * std::sqrt(std::max(0.0, 1 - c * c)), a = z / (1 + c);
        branches[sign > 0].push_back({std::array<double, 3>{(c + 1) / 2, (2 * a + 1) / 2, 0},
                                      std::array<double, 3>{c, c, z}, std::array<double, 3>{(2 * a + 1) / 2, (c + 1) / 2, 0}});
      }
    const auto r = check_distance_bounds(L, branches);
    CHECK(r[2] <= 4e-3);
    // at the corner (u, t) = (1, 1) the two branches meet (the partners fold): the Jacobian in the partner is
    // singular there and the segment ending at it is not proved; every other one is
    std::size_t open = 0, at_fold = 0;
    for (const auto& a : L.arcs)
      for (const auto& s : a.sheets) {
        CHECK(std::isinf(sheet_distance_bound(s)[2]));
        for (std::size_t j = 0; j + 1 < s.points.size(); ++j) {
          if (std::isfinite(s.segment_distance_bounds[j][2])) continue;
          ++open;
          for (std::size_t e : {j, j + 1})
            at_fold += std::fabs(s.points[e].projection[0] - 1) < 1e-12 && std::fabs(s.points[e].projection[1] - 1) < 1e-12;
        }
      }
    CHECK(r[0] >= 100);
    CHECK(open == 2);
    CHECK(at_fold == 2);
    // refined until the proved bounds meet the tolerance: still true against the closed form, and within it
    Surface_intersection_options fine = o;
    fine.refine_to_proved_distance = true;
    const Surface_locus F = intersection_locus(doc.patches[0], doc.patches[1], fine);
    REQUIRE(F.topology_computed);
    const auto f = check_distance_bounds(F, branches);
    CHECK(f[0] > r[0]);
    CHECK(f[1] >= f[0] - 2);
    CHECK(f[2] <= 1e-3);
    for (const auto& a : F.arcs) {
      CHECK(a.undecided_fraction == 0);
      CHECK(a.fibre_undecided_fraction == 0);
    }
  }
  SECTION("a reported point moved off the curve moves the bound with it") {
    // the bound includes the distance of the reported ends from the exact curve: moving one reported first point
    // by 0.01 raises the first-domain bound above 0.01, and leaves it proved
    const auto doc = io::read_geometry_file(std::string(BEZOUTIAN_SOURCE_DIR) + "/examples/data/paraboloid_plane_strip.json");
    const Surface_locus L = intersection_locus(doc.patches[0], doc.patches[1], o);
    REQUIRE(!L.arcs.empty());
    const Locus_sheet* sheet = nullptr;
    std::size_t arc = 0;
    for (std::size_t k = 0; k < L.arcs.size(); ++k)
      for (const auto& s : L.arcs[k].sheets)
        if (s.points.size() > 4) sheet = &s, arc = k;
    REQUIRE(sheet);
    const auto& e = L.topology.edges[arc];
    const internal::Partner_equations eq(doc.patches[0], doc.patches[1]);
    const internal::Patch_jacobian_enclosure phi(eq, 0);
    auto reported = [&](std::size_t j) {
      return internal::reported_sheet_point(sheet->points[j], e.polyline[sheet->first + j]);
    };
    const std::size_t j = 2, i = sheet->first + j;
    const Curve_topology_piece* piece = nullptr;
    for (const auto& pc : e.pieces)
      if (pc.graph_axis >= 0 && pc.first <= i && i + 1 <= pc.last) piece = &pc;
    REQUIRE(piece);
    const auto exact = internal::segment_distance_bound(eq, phi, piece->graph_axis, piece->cell,
                                                        &L.equation.square_free, reported(j), reported(j + 1), 1e-3);
    CHECK(exact[0] == sheet->segment_distance_bounds[j][0]);
    auto moved = reported(j + 1);
    moved.first[1] += 0.01;
    const auto off = internal::segment_distance_bound(eq, phi, piece->graph_axis, piece->cell, &L.equation.square_free,
                                                      reported(j), moved, 1e-3);
    CHECK(off[0] >= 0.01);
    CHECK(off[0] <= exact[0] + 0.0101);
    // (the 3D points did not move: no larger, though finer sub-spans, tried while the first bound is above the
    // target, may make it smaller)
    CHECK(off[2] <= exact[2]);
  }
}

TEST_CASE("structured surfaces: an extruded loop's double line, straight and sheared, complete to its split points",
          "[surface][structured][self]") {
  // The nodal cubic (c^2 - 1, c (c^2 - 1)), c = 3u - 3/2, passes twice through (0, 0): at u = 1/6 and u = 5/6.
  // Extruded along z = v + h u its double curve is the line x = y = 0: the points (1/6, v1) and (5/6, v2) with
  // v1 + h/6 = v2 + 5h/6. The locus of D = 0 is the two lines u = 1/6 and u = 5/6, each with the constant partner
  // (l, k) = (+-2/3, +-2h/3); the kernel of B along them is the trivial partner (0, 0).
  const std::string c = "(3*u - 3/2)";
  for (const int sheared : {0, 1}) {
    INFO("sheared " << sheared);
    const double h = sheared ? 0.5 : 0;
    Surface_intersection_options fine;
    fine.polyline_tolerance = 1e-4;
    const Surface_locus L = self_intersection_locus(
        power_patch(c + "^2 - 1", c + "*(" + c + "^2 - 1)", sheared ? "v + u/2" : "v", "1", 3, 1), fine);
    INFO(L.note);
    REQUIRE(L.topology_computed);
    CHECK(L.topology_method == "subdivision");
    REQUIRE(L.arcs.size() == 2);
    // the genuine double curve: z in [5h/6, 1 + h/6] (both preimages' v in [0, 1])
    const double z0 = 5 * h / 6, z1 = 1 + h / 6;
    for (const auto& a : L.arcs) {
      // every partner and every status proved; straight, k = 0 all along, and next to the box's sides v = 0 and
      // v = 1 the point P = (u, v + k) is within rounding of the side: the exact proof of a line with one partner
      // (lifting/linear_partner_lines.h) decides the whole arc
      CHECK(a.fibre_undecided_fraction == 0);
      CHECK(a.undecided_fraction == 0);
      for (const auto& q : a.points)
        if (!sheared) CHECK((q.genuine && q.status_proved && q.partner_enclosure[1][0] == 0 &&
                             q.partner_enclosure[1][1] == 0));
      for (const auto& sh : a.sheets)
        for (const auto& q : sh.points) {
          CHECK(std::hypot(q.point_3d[0], q.point_3d[1]) < 1e-9);
          CHECK(q.point_3d[2] > z0 - 1e-9);
          CHECK(q.point_3d[2] < z1 + 1e-9);
          CHECK(std::fabs(q.first[0] - q.second[0]) == Approx(2.0 / 3).margin(1e-9));
        }
    }
    // sheared: the genuine part of each line ends where the partner's v leaves [0, 1], at v = 1/3 on u = 5/6 and at
    // v = 2/3 on u = 1/6 (certified split points); the straight lines are genuine from side to side
    std::size_t at_third = 0, at_two_thirds = 0;
    for (const auto& sp : L.split_points) {
      const auto& q = L.arcs[sp.arc].points[sp.index];
      at_third += std::fabs(q.projection[0] - 5.0 / 6) < 1e-12 && std::fabs(q.projection[1] - 1.0 / 3) < 1e-12;
      at_two_thirds += std::fabs(q.projection[0] - 1.0 / 6) < 1e-12 && std::fabs(q.projection[1] - 2.0 / 3) < 1e-12;
    }
    CHECK(L.split_points.size() == (sheared ? 2u : 0u));
    CHECK(at_third == (sheared ? 1u : 0u));
    CHECK(at_two_thirds == (sheared ? 1u : 0u));
    // completeness: 2 x 2001 samples of the double line, each with its two preimages in both orders (both arcs)
    std::vector<std::array<std::array<double, 3>, 3>> samples;
    for (int i = 0; i <= 2000; ++i) {
      const double z = z0 + (z1 - z0) * i / 2000;
      const std::array<double, 3> a{5.0 / 6, z - 5 * h / 6, 0}, b{1.0 / 6, z - h / 6, 0}, x{0, 0, z};
      samples.push_back({a, x, b});
      samples.push_back({b, x, a});
    }
    check_sheets_complete(L, samples, 1e-3);
  }
}

TEST_CASE("structured surfaces: a Whitney umbrella's double line, an affine partner, trivial at the pinch point",
          "[surface][structured][self]") {
  // Phi(u, v) = (a^2, v, a (v - 1/3)) with a = 3u/5 - 3/10: Phi(u, v) = Phi(u', v') with (u', v') != (u, v) iff
  // v = v' = 1/3 and u' = 1 - u. The double curve is the line v = 1/3 across the whole square, with the partner
  // (l, k) = (1 - 2u, 0), trivial only at the pinch point (1/2, 1/3); its 3D image is (a^2, 1/3, 0), a in [0, 3/10].
  const std::string a = "(3*u/5 - 3/10)";
  Surface_intersection_options fine;
  fine.polyline_tolerance = 1e-4;
  const Surface_locus L = self_intersection_locus(power_patch(a + "^2", "v", a + "*(v - 1/3)", "1", 2, 1), fine);
  INFO(L.note);
  REQUIRE(L.topology_computed);
  CHECK(L.pinch_points_complete);
  REQUIRE(L.pinch_points.size() == 1);
  REQUIRE(L.arcs.size() == 1);
  const auto& arc = L.arcs[0];
  // every status proved at once by the exact proof of a line with an affine partner (lifting/linear_partner_lines.h),
  // but the pinch point's own traced point
  CHECK(arc.undecided_fraction == 0);
  std::size_t proved = 0, pinch = 0;
  for (const auto& q : arc.points) {
    CHECK(std::fabs(q.projection[1] - 1.0 / 3) < 1e-12);
    if (std::fabs(q.projection[0] - 0.5) < 1e-12) {
      ++pinch;
      continue;
    }
    CHECK(q.genuine);
    CHECK(q.status_proved);
    const double l = 1 - 2 * q.projection[0];  // the closed-form partner
    CHECK(q.partner_enclosure[0][0] <= l + 1e-15);
    CHECK(l - 1e-15 <= q.partner_enclosure[0][1]);
    CHECK(q.partner_enclosure[1][0] == 0);
    CHECK(q.partner_enclosure[1][1] == 0);
    proved += q.status_proved;
  }
  CHECK(pinch <= 1);
  CHECK(proved + pinch == arc.points.size());
  // completeness: 2001 samples of the double curve with both preimages, against the sheets
  std::vector<std::array<std::array<double, 3>, 3>> samples;
  for (int i = 0; i <= 2000; ++i) {
    const double u = i / 2000.0, c = 0.6 * u - 0.3;
    samples.push_back({std::array<double, 3>{u, 1.0 / 3, 0}, std::array<double, 3>{c * c, 1.0 / 3, 0},
                       std::array<double, 3>{1 - u, 1.0 / 3, 0}});
  }
  check_sheets_complete(L, samples, 1e-3);
}

TEST_CASE("structured surfaces: a sphere cut by a plane, two branches over one line that meet at a fold",
          "[surface][structured][sheets]") {
  // sphere patch: latitude a = u/2, longitude b = 1/2 + 3v/2, (cos, sin) = (1 - a^2, 2a)/(1 + a^2); the plane
  // z = 8/17 (a = 1/4, u = 1/2) cuts it on the latitude circle of radius 15/17, symmetric about x = 0: (x, y) and
  // (-x, y) share (u, t) with t = y. The projected locus is the line u = 1/2; its genuine part t in
  // [(15/17) (4/5), 15/17] carries two sheets that meet at the fold x = 0, y = 15/17 and turn complex beyond.
  const std::string a = "(u/2)", b = "(1/2+3*v/2)";
  const auto sphere = bezoutian_test::rational_patch_from_power(
      {"(1-" + a + "*" + a + ")*(1-" + b + "*" + b + ")", "(1-" + a + "*" + a + ")*2*" + b, "2*" + a + "*(1+" + b + "*" + b + ")",
       "(1+" + a + "*" + a + ")*(1+" + b + "*" + b + ")"},
      2, 2);
  const auto plane = from_power({"2*u-1", "v", "8/17"}, 1, 1);
  Surface_intersection_options fine;
  fine.polyline_tolerance = 1e-3;
  const Surface_locus L = intersection_locus(sphere, plane, fine);
  INFO(L.note);
  REQUIRE(L.topology_computed);
  std::size_t long_sheets = 0, past_fold = 0;
  for (const auto& arc : L.arcs) {
    // every partner proved, up to the fold and beyond it (partner_fold_proofs.h: the spans next to the fold are
    // decided in the chart of the partner coordinate)
    CHECK(arc.fibre_undecided_fraction == 0);
    CHECK(arc.undecided_fraction == 0);
    for (const auto& q : arc.points) {
      const double t = q.projection[1];
      if (std::fabs(t - 12.0 / 17) < 1e-12 || std::fabs(t - 15.0 / 17) < 1e-12) continue;
      INFO("t = " << t);
      CHECK(q.status_proved);
      CHECK(q.genuine == (12.0 / 17 < t && t < 15.0 / 17));  // two real partners b, 1/b in [1/2, 2] exactly there
      past_fold += t > 15.0 / 17 && t < 15.0 / 17 + 0.01;
    }
    for (const auto& s : arc.sheets) {
      long_sheets += s.points.size() > 10;
      for (const auto& q : s.points) {
        CHECK(std::fabs(q.point_3d[2] - 8.0 / 17) < 1e-9);
        CHECK(std::fabs(std::hypot(q.point_3d[0], q.point_3d[1]) - 15.0 / 17) < 1e-9);
        CHECK(std::fabs(q.projection[0] - 0.5) < 1e-9);
      }
    }
  }
  CHECK(long_sheets == 2);
  CHECK(past_fold >= 1);  // (the refinement puts traced points next to the fold on both sides)
  std::vector<std::array<std::array<double, 3>, 3>> samples;
  for (int k = 0; k <= 2000; ++k) {
    const double bb = 0.5 + 1.5 * k / 2000;  // the longitude parameter over v in [0, 1]
    const double r = 15.0 / 17, x = r * (1 - bb * bb) / (1 + bb * bb), y = r * 2 * bb / (1 + bb * bb);
    samples.push_back({std::array<double, 3>{0.5, (bb - 0.5) / 1.5, 0}, std::array<double, 3>{x, y, 8.0 / 17},
                       std::array<double, 3>{(x + 1) / 2, y, 0}});
  }
  const auto gap = worst_sheet_gap(L, samples);
  // (the polylines' chords meet the tolerance 1e-3 by the midpoint test; at the fold the sheets behave like a
  // square root, and the last chord to it is a little farther)
  CHECK(gap[0] < 5e-3);
  CHECK(gap[1] < 5e-3);
  CHECK(gap[2] < 5e-3);
  // the same against the points whose genuine status is proved: every span proved phantom is phantom
  check_sheets_complete(proved_genuine_sheets(L), samples, 5e-3);
  // the proved chord distances (lifting/polyline_distance_bounds.h) hold against the closed form; only the segment of
  // each sheet that ends at the fold, where the two partners meet, has none
  std::vector<Sample> dense;
  for (int k = 0; k <= 40000; ++k) {
    const double bb = 0.5 + 1.5 * k / 40000;
    const double r = 15.0 / 17, x = r * (1 - bb * bb) / (1 + bb * bb), y = r * 2 * bb / (1 + bb * bb);
    dense.push_back({std::array<double, 3>{0.5, (bb - 0.5) / 1.5, 0}, std::array<double, 3>{x, y, 8.0 / 17},
                     std::array<double, 3>{(x + 1) / 2, y, 0}});
  }
  const auto bounds = check_distance_bounds(L, {dense});
  CHECK(bounds[0] >= 20);
  CHECK(bounds[1] + 2 >= bounds[0]);
  CHECK(bounds[2] <= 1e-2);
}

// Pieces of one parametrized surface: Psi = Phi o M with M(s, t) = (alpha(s), beta(t)) (or exchanged) for Moebius
// maps alpha, beta. Every (u, t) then has a solution and det B vanishes identically; the intersection is decided
// through M and a proof that the common parent is injective (intersection/Patch_common_parent.h). Expected regions
// are derived by hand from the restrictions, rotations and splits that make the pieces.
namespace {
const std::array<Q, 4> unit_square{Q(0), Q(1), Q(0), Q(1)};

// the one shared boundary curve of a proved common-parent locus without overlap
void check_shared_side(const Surface_locus& L, int side_first, int side_second) {
  INFO(L.note);
  CHECK(L.topology_computed);
  CHECK(L.topology_method == "common parent");
  CHECK(L.overlaps.empty());
  CHECK(L.arcs.empty());
  int shared = 0;
  for (const auto& c : L.contacts)
    if (c.shared_curve) {
      ++shared;
      CHECK(c.side_first == side_first);
      CHECK(c.side_second == side_second);
    }
  CHECK(shared == 1);
}

// Psi(s, t) = Phi(M(s, t)) at sample points of the overlap's second rectangle, and M maps it onto the first
void check_overlap_map(const Locus_overlap& ov, const Patch& phi, const Patch& psi) {
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) {
      const Q s = ov.second[0] + (ov.second[1] - ov.second[0]) * Q(i, 4);
      const Q t = ov.second[2] + (ov.second[3] - ov.second[2]) * Q(j, 4);
      const Q u = ov.along_u(ov.swapped ? t : s), v = ov.along_v(ov.swapped ? s : t);
      CHECK(ov.first[0] <= u);
      CHECK(u <= ov.first[1]);
      CHECK(ov.first[2] <= v);
      CHECK(v <= ov.first[3]);
      const auto a = phi.evaluate(CGAL::to_double(u), CGAL::to_double(v));
      const auto b = psi.evaluate(CGAL::to_double(s), CGAL::to_double(t));
      CHECK(std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]) < 1e-12);
    }
}
}  // namespace

TEST_CASE("pieces of one surface: split halves share one boundary curve, proved", "[surface][structured][parent]") {
  // the paraboloid z = x^2 + y^2 over [-1, 1]^2, split at u = 1/2: the halves meet along u = 1 of the first and
  // s = 0 of the second, nowhere else (a height field is injective)
  const Patch paraboloid = from_power({"2*u - 1", "2*v - 1", "(2*u - 1)*(2*u - 1) + (2*v - 1)*(2*v - 1)"}, 2, 2);
  const auto halves = paraboloid.split_u(Q(1, 2));
  CHECK(intersection_equation(halves.first, halves.second).is_degenerate());
  check_shared_side(intersection_locus(halves.first, halves.second), 1, 3);
  // the second half transposed: its side s = 0 becomes t = 0
  check_shared_side(intersection_locus(halves.first, halves.second.transposed()), 1, 0);
  // two adjacent sphere octants, the second the first turned by 90 degrees about z: one meridian in common. The
  // map between them, u = (s - 1)/(s + 1), is a Moebius map, and the parent on [-1, 1] x [0, 1] has a zero middle
  // weight (the half circle) that degree elevation removes
  const auto octant = power_patch("(1 - v^2)*(1 - u^2)", "2*u*(1 - v^2)", "2*v*(1 + u^2)", "(1 + u^2)*(1 + v^2)", 2, 2);
  const auto turned = power_patch("-2*u*(1 - v^2)", "(1 - v^2)*(1 - u^2)", "2*v*(1 + u^2)", "(1 + u^2)*(1 + v^2)", 2, 2);
  CHECK(intersection_equation(turned, octant).is_degenerate());
  const Surface_locus S = intersection_locus(turned, octant);
  check_shared_side(S, 3, 1);
  // the other order: the first reparametrization found, u = (s - 1)/(s + 1), v = 1/t (the antipodal chart), has
  // poles on both domains; the search goes on to u = (1 + s)/(1 - s), v = t, whose inverse is finite
  check_shared_side(intersection_locus(octant, turned), 1, 3);
  // quarter cylinders side by side: the line x = 0, y = 1
  const auto quarter = power_patch("1 - u^2", "2*u", "v*(1 + u^2)", "1 + u^2", 2, 1);
  const auto next = power_patch("-2*u", "1 - u^2", "v*(1 + u^2)", "1 + u^2", 2, 1);
  check_shared_side(intersection_locus(quarter, next), 1, 3);
  // pieces of one paraboloid that do not meet, without the hull test: the common parent proves them apart
  Surface_intersection_options no_direct;
  no_direct.direct_proofs = false;
  const Surface_locus A = intersection_locus(paraboloid.restriction(Q(0), Q(2, 5), Q(0), Q(1)),
                                             paraboloid.restriction(Q(3, 5), Q(1), Q(0), Q(1)), no_direct);
  INFO(A.note);
  CHECK(A.topology_computed);
  CHECK(A.topology_method == "common parent");
  CHECK(A.overlaps.empty());
  CHECK(A.contacts.empty());
}

TEST_CASE("pieces of one surface: overlapping, nested, identical, elevated and turned pieces, the common regions",
          "[surface][structured][parent]") {
  const Patch paraboloid = from_power({"2*u - 1", "2*v - 1", "(2*u - 1)*(2*u - 1) + (2*v - 1)*(2*v - 1)"}, 2, 2);
  auto overlap_of = [](const Patch& a, const Patch& b) {
    const Surface_locus L = intersection_locus(a, b);
    INFO(L.note);
    CHECK(L.topology_computed);
    CHECK(L.topology_method == "common parent");
    REQUIRE(L.overlaps.size() == 1);
    check_overlap_map(L.overlaps[0], a, b);
    return L.overlaps[0];
  };
  // u in [0, 3/5] and u in [2/5, 1] of the paraboloid: they share u in [2/5, 3/5], which is [2/3, 1] of the first
  // piece (u = 3/5 x) and [0, 1/3] of the second (u = 2/5 + 3/5 x)
  const Patch left = paraboloid.restriction(Q(0), Q(3, 5), Q(0), Q(1));
  const Patch right = paraboloid.restriction(Q(2, 5), Q(1), Q(0), Q(1));
  CHECK(intersection_equation(left, right).is_degenerate());
  Locus_overlap ov = overlap_of(left, right);
  CHECK(ov.first == std::array<Q, 4>{Q(2, 3), Q(1), Q(0), Q(1)});
  CHECK(ov.second == std::array<Q, 4>{Q(0), Q(1, 3), Q(0), Q(1)});
  // the middle quarter [1/4, 3/4]^2 lies inside the whole patch
  ov = overlap_of(paraboloid, paraboloid.restriction(Q(1, 4), Q(3, 4), Q(1, 4), Q(3, 4)));
  CHECK(ov.first == std::array<Q, 4>{Q(1, 4), Q(3, 4), Q(1, 4), Q(3, 4)});
  CHECK(ov.second == unit_square);
  // the same patch, and its copy elevated to bi-degree (3, 4): the whole square, by the identity
  for (const Patch& copy : {paraboloid, paraboloid.elevated(1, 2)}) {
    ov = overlap_of(paraboloid, copy);
    CHECK(ov.first == unit_square);
    CHECK(ov.second == unit_square);
    CHECK(ov.along_u.is_affine());
    CHECK(ov.along_u(Q(1, 3)) == Q(1, 3));
  }
  // a quarter cylinder x = (1 - u^2)/(1 + u^2), y = 2u/(1 + u^2) (angles 0 to 90 degrees) and the same quarter
  // turned by the angle theta with tan(theta/2) = 1/2 (cos = 3/5, sin = 4/5): they share the angles theta to 90
  // degrees, u = tan(phi/2) in [1/2, 1] of the first and u' = tan((phi - theta)/2) in [0, 1/3] of the second, through
  // the Moebius map u = (u' + 1/2)/(1 - u'/2)
  const auto quarter = power_patch("1 - u^2", "2*u", "v*(1 + u^2)", "1 + u^2", 2, 1);
  const auto turned = power_patch("3/5*(1 - u^2) - 8/5*u", "4/5*(1 - u^2) + 6/5*u", "v*(1 + u^2)", "1 + u^2", 2, 1);
  ov = overlap_of(quarter, turned);
  CHECK(ov.first == std::array<Q, 4>{Q(1, 2), Q(1), Q(0), Q(1)});
  CHECK(ov.second == std::array<Q, 4>{Q(0), Q(1, 3), Q(0), Q(1)});
  CHECK_FALSE(ov.along_u.is_affine());
}

TEST_CASE("pieces of one surface: a self-intersecting parent is not called proved", "[surface][structured][parent]") {
  // The folded patch ((u - 3/10)^2, v^2, (u - 3/10)(v - 1/3)) has the double points (u, 1/3) ~ (3/5 - u, 1/3). Split
  // at u = 3/10 the halves share their boundary and also meet along v = 1/3 (u in [0, 3/10] against 3/5 - u): the
  // common parent is not injective, so only the shared part is reported and the rest is left undecided, saying so
  const Patch folded = from_power({"(u - 3/10)*(u - 3/10)", "v*v", "(u - 3/10)*(v - 1/3)"}, 3, 2);
  const auto halves = folded.split_u(Q(3, 10));
  const Surface_locus L = intersection_locus(halves.first, halves.second);
  INFO(L.note);
  CHECK_FALSE(L.topology_computed);
  CHECK(L.note.find("not decided") != std::string::npos);
  CHECK(L.overlaps.empty());
  // the same patch twice: the whole square is an overlap, the pairs of its double curve are not decided
  const Surface_locus T = intersection_locus(folded, folded);
  CHECK_FALSE(T.topology_computed);
  REQUIRE(T.overlaps.size() == 1);
  CHECK(T.overlaps[0].first == unit_square);
}

// Tangential contacts of a sphere: the octant ((1 - v^2)(1 - u^2), 2u(1 - v^2), 2v(1 + u^2)) / ((1 + u^2)(1 + v^2))
// of the unit sphere has at (u, v) = (1/2, 1/2) the point n = (9/25, 12/25, 4/5), with normal n. The plane
// 9x + 12y + 20z = 25 k, as the height field (s, t, (25 k - 9s - 12t)/20), touches it at n for k = 1, misses it for
// k > 1 and cuts it along a circle of radius sqrt(1 - k^2) about k n for k < 1.
namespace {
Patch unit_octant() {
  return power_patch("(1 - v^2)*(1 - u^2)", "2*u*(1 - v^2)", "2*v*(1 + u^2)", "(1 + u^2)*(1 + v^2)", 2, 2);
}
Patch tangent_plane(const std::string& k) {
  return from_power({"u", "v", "(25*" + k + " - 9*u - 12*v)/20"}, 1, 1);
}
std::size_t genuine_traced_points(const Surface_locus& L) {
  std::size_t n = 0;
  for (const auto& a : L.arcs)
    for (const auto& q : a.points) n += q.genuine;
  return n;
}
// the one genuine isolated point of L: its exact projection, partner and kind
void check_one_contact(const Surface_locus& L, const std::array<Q, 2>& projection, const Q& v, const Q& s) {
  INFO(L.note);
  REQUIRE(L.topology_computed);
  CHECK(genuine_traced_points(L) == 0);
  for (const auto& e : L.edge_lines) {  // (the mirrored sphere's pole side: one point, off the octant, proved)
    INFO(e.description);
    CHECK(e.status_proved);
    CHECK_FALSE(e.genuine);
  }
  int contacts = 0;
  for (const auto& ip : L.isolated_points) {
    INFO(ip.lift.reason);
    CHECK(ip.lift.proved);
    if (!ip.genuine()) continue;
    ++contacts;
    CHECK(ip.lift.projection == projection);
    REQUIRE(ip.lift.partners.size() == 1);
    const auto& p = ip.lift.partners[0];
    CHECK(p.v == Algebraic_real(v));
    CHECK(p.s == Algebraic_real(s));
    CHECK(p.tangency_decided);
    CHECK(p.tangent);
    CHECK_FALSE(p.singular);
  }
  CHECK(contacts == 1);
}
}  // namespace

TEST_CASE("tangential contacts: a plane touching a sphere, one 1e-6 above it, one 1e-6 below it",
          "[surface][structured][tangent]") {
  const Patch octant = unit_octant();
  // touching: the isolated point (u, t) = (1/2, 12/25) with partner (v, s) = (1/2, 9/25), a tangent contact, and
  // every other point of D = 0 in the box a phantom
  check_one_contact(intersection_locus(octant, tangent_plane("1")), {Q(1, 2), Q(12, 25)}, Q(1, 2), Q(9, 25));
  // 1e-6 above: no intersection, proved (no genuine point, every isolated point a proved phantom)
  const Surface_locus A = intersection_locus(octant, tangent_plane("1000001/1000000"));
  INFO(A.note);
  REQUIRE(A.topology_computed);
  CHECK(genuine_traced_points(A) == 0);
  for (const auto& arc : A.arcs) CHECK(arc.undecided_fraction == 0);
  for (const auto& ip : A.isolated_points) CHECK((ip.lift.proved && !ip.genuine()));
  // 1e-6 below: the circle of radius sqrt(1 - k^2) = 1.414e-3, one closed component, found and complete
  const double k = 1 - 1e-6, r = std::sqrt(1 - k * k);
  Surface_intersection_options fine;
  fine.polyline_tolerance = 1e-5;
  const Surface_locus B = intersection_locus(octant, tangent_plane("999999/1000000"), fine);
  INFO(B.note);
  REQUIRE(B.topology_computed);
  std::size_t closed = 0;
  for (const auto& c : B.topology.components) closed += c.closed && !c.isolated_point;
  CHECK(closed == 1);
  for (const auto& arc : B.arcs) {
    // the statuses and the fibre are proved everywhere: along this contact the three partner equations are nearly
    // dependent (the surfaces meet at an angle of about 1.4e-3), which the exclusion's combinations along the
    // Jacobian's singular directions and the halving of a span's box into parts overcome
    CHECK(arc.undecided_fraction == 0);
    CHECK(arc.fibre_undecided_fraction == 0);
    for (const auto& q : arc.points)
      if (q.genuine) {
        const auto& p = q.point_3d;
        CHECK(std::fabs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 1) < 1e-9);
        CHECK(std::fabs(9 * p[0] + 12 * p[1] + 20 * p[2] - 25 * k) < 1e-9);
      }
  }
  std::vector<std::array<std::array<double, 3>, 3>> samples;
  const std::array<double, 3> n{9.0 / 25, 12.0 / 25, 0.8}, e1{0.8, -0.6, 0}, e2{12.0 / 25, 16.0 / 25, -0.6};
  for (int i = 0; i < 2000; ++i) {
    const double a = 2 * M_PI * i / 2000;
    std::array<double, 3> x;
    for (std::size_t c = 0; c < 3; ++c) x[c] = k * n[c] + r * (std::cos(a) * e1[c] + std::sin(a) * e2[c]);
    const double rho = std::hypot(x[0], x[1]);
    samples.push_back({std::array<double, 3>{x[1] / (x[0] + rho), x[2] / (1 + rho), 0}, x,
                       std::array<double, 3>{x[0], x[1], 0}});
  }
  const auto gap = worst_sheet_gap(B, samples);
  CHECK(gap[0] < 1e-4);
  CHECK(gap[1] < 1e-4);
  CHECK(gap[2] < 1e-4);
}

TEST_CASE("tangential contacts: spheres touching from outside and from inside", "[surface][structured][tangent]") {
  // the octant mirrored through n (2n - Phi: the unit sphere about 2n) touches it from outside at n, and the sphere
  // of radius 2 about -n (2 Phi - n) holds it and touches it at n; both at (s, t) = (1/2, 1/2)
  const Patch octant = unit_octant();
  const std::string w = "(1 + u^2)*(1 + v^2)";
  const Patch outside = power_patch("18/25*" + w + " - (1 - v^2)*(1 - u^2)", "24/25*" + w + " - 2*u*(1 - v^2)",
                                    "8/5*" + w + " - 2*v*(1 + u^2)", w, 2, 2);
  check_one_contact(intersection_locus(octant, outside), {Q(1, 2), Q(1, 2)}, Q(1, 2), Q(1, 2));
  const Patch around = power_patch("2*(1 - v^2)*(1 - u^2) - 9/25*" + w, "4*u*(1 - v^2) - 12/25*" + w,
                                   "4*v*(1 + u^2) - 4/5*" + w, w, 2, 2);
  check_one_contact(intersection_locus(octant, around), {Q(1, 2), Q(1, 2)}, Q(1, 2), Q(1, 2));
}

TEST_CASE("tangential contacts along a curve: a plane along a cylinder's boundary line, a cone along a sphere's circle",
          "[surface][structured][tangent]") {
  // the quarter cylinder ((1 - u^2), 2u, v (1 + u^2)) / (1 + u^2) and the plane (1, 2s - 1, t) touch along the line
  // x = 1, y = 0: the cylinder's side u = 0 and the plane's iso-curve s = 1/2 (proved: the iso-curve lies on the side)
  const auto quarter = power_patch("1 - u^2", "2*u", "v*(1 + u^2)", "1 + u^2", 2, 1);
  const Patch wall = from_power({"1", "2*u - 1", "v"}, 1, 1);
  const Surface_locus L = intersection_locus(quarter, wall);
  INFO(L.note);
  REQUIRE(L.topology_computed);
  CHECK(genuine_traced_points(L) == 0);
  REQUIRE(L.edge_lines.size() == 1);
  const Locus_edge_line& e = L.edge_lines[0];
  CHECK(e.side == 3);
  CHECK_FALSE(e.interior);
  CHECK(e.cause == Locus_edge_line::partner_iso_curve);
  CHECK(e.partner_value == Q(1, 2));
  CHECK(e.genuine);
  CHECK(e.status_proved);
  REQUIRE(e.points.size() > 2);
  for (const auto& q : e.points) {
    CHECK(std::fabs(q.point_3d[0] - 1) < 1e-12);
    CHECK(std::fabs(q.point_3d[1]) < 1e-12);
    CHECK(std::fabs(q.point_3d[2] - q.projection[1]) < 1e-12);  // z = t
    CHECK(std::fabs(q.second[0] - 0.5) < 1e-12);
  }
  // the sphere octant and the cone with apex (0, 0, 5/4) tangent to it along the latitude z = 4/5 (radius 3/5, the
  // octant's iso-curve v = 1/2): (w (3/5) cos, w (3/5) sin, 5/4 - (9/20) w), w = 1/2 + t, touches it along t = 1/2,
  // a line inside the box, proved genuine at every point and removed from D; nothing else meets
  const Patch octant = unit_octant();
  const auto cone = power_patch("(1/2 + v)*3/5*(1 - u^2)", "(1/2 + v)*6/5*u", "(1 + u^2)*(5/4 - 9/20*(1/2 + v))",
                                "1 + u^2", 2, 1);
  const Surface_locus C = intersection_locus(octant, cone);
  INFO(C.note);
  REQUIRE(C.topology_computed);
  CHECK(genuine_traced_points(C) == 0);
  REQUIRE(C.edge_lines.size() == 1);
  const Locus_edge_line& c = C.edge_lines[0];
  CHECK(c.interior);
  CHECK(c.side == 0);
  CHECK(c.value == Q(1, 2));
  CHECK(c.cause == Locus_edge_line::partner_iso_curve);
  CHECK(c.partner_value == Q(1, 2));
  CHECK(c.genuine);
  REQUIRE(c.points.size() > 2);
  for (const auto& q : c.points) {
    CHECK(std::fabs(std::hypot(q.point_3d[0], q.point_3d[1]) - 0.6) < 1e-12);
    CHECK(std::fabs(q.point_3d[2] - 0.8) < 1e-12);
    CHECK(std::fabs(q.first[1] - 0.5) < 1e-12);
  }
}

namespace {
// The traced point at (u, t) = (1/2, 1/2), where the closed form puts the partner (v, s) on the partner domain's
// boundary: present, genuine, proved, with that partner.
void check_exact_touch_at_centre(const Surface_locus& L, double v, double s) {
  bool found = false;
  for (const auto& a : L.arcs)
    for (const auto& q : a.points)
      if (q.projection[0] == 0.5 && q.projection[1] == 0.5) {
        found = true;
        CHECK(q.genuine);
        CHECK(q.status_proved);
        CHECK(std::fabs(q.partner[0] - v) < 1e-12);
        CHECK(std::fabs(q.partner[1] - s) < 1e-12);
      }
  CHECK(found);
}

// The orthogonal extrusions' curve (x, x^2, +-sqrt(1 - x^2)): two sheets, every sheet point on both closed-form
// surfaces (and phi, psi agreeing there), and completeness against 2 x 2001 samples in 3D and in both parameter
// domains, (u, v) = ((x + 1)/2, (z + 1)/2) and (s, t) = ((z + 1)/2, (x + 1)/2), each pair reversed if `exchanged`.
void check_extrusion_sheets(const Surface_locus& L, const Patch& phi, const Patch& psi, bool exchanged) {
  std::size_t sheets = 0;
  for (const auto& a : L.arcs)
    for (const auto& s : a.sheets) {
      ++sheets;
      for (const auto& q : s.points) {
        const auto& p = q.point_3d;
        CHECK(std::fabs(p[1] - p[0] * p[0]) < 1e-9);  // on both closed-form surfaces
        CHECK(std::fabs(p[1] - 1 + p[2] * p[2]) < 1e-9);
        CHECK(distance3(phi.evaluate(q.first[0], q.first[1]), psi.evaluate(q.second[0], q.second[1])) < 1e-9);
      }
    }
  CHECK(sheets == 2);
  std::vector<std::array<std::array<double, 3>, 3>> samples;
  for (int k = 0; k <= 2000; ++k)
    for (int sign : {-1, 1}) {
      const double x = -1 + 2.0 * k / 2000, z = sign * std::sqrt(std::max(0.0, 1 - x * x));
      const double a = (x + 1) / 2, b = (z + 1) / 2;
      samples.push_back({std::array<double, 3>{exchanged ? b : a, exchanged ? a : b, 0}, std::array<double, 3>{x, x * x, z},
                         std::array<double, 3>{exchanged ? a : b, exchanged ? b : a, 0}});
    }
  const auto gap = worst_sheet_gap(L, samples);
  CHECK(gap[0] < 5e-3);
  CHECK(gap[1] < 5e-3);
  CHECK(gap[2] < 5e-3);
  // the same against the points whose genuine status is proved: every span proved phantom is phantom
  check_sheets_complete(proved_genuine_sheets(L), samples, 5e-3);
}
}  // namespace

TEST_CASE("orthogonal extrusions: two branches over one projected line, both lifted", "[surface][structured][sheets]") {
  // Phi = (x, x^2, z) with x = 2u - 1, z = 2v - 1 (y = x^2 extruded along z); Psi = (x, 1 - z^2, z) with
  // x = 2t - 1, z = 2s - 1 (y = 1 - z^2 extruded along x). The curve: x in [-1, 1], y = x^2, z = +-sqrt(1 - x^2):
  // two branches over the one projected line u = t (det B = (u - t)^2), meeting at x = +-1 (the corners of the
  // (u, t) box). Then the same pair with u and v exchanged on both patches (x = 2v - 1, z = 2u - 1 and x = 2s - 1,
  // z = 2t - 1): D = 0 is again the line u = t, and at its centre both sheets' partners (v, s) touch a corner of
  // the partner domain at once, (0, 0) and (1, 1).
  for (const bool exchanged : {false, true}) {
    INFO("parameters exchanged " << exchanged);
    const Patch phi = exchanged ? from_power({"2*v-1", "(2*v-1)^2", "2*u-1"}, 1, 2)
                                : from_power({"2*u-1", "(2*u-1)^2", "2*v-1"}, 2, 1);
    const Patch psi = exchanged ? from_power({"2*u-1", "1-(2*v-1)^2", "2*v-1"}, 1, 2)  // (s, t) read as (u, v)
                                : from_power({"2*v-1", "1-(2*u-1)^2", "2*u-1"}, 2, 1);
    Surface_intersection_options fine;
    fine.polyline_tolerance = 1e-3;
    const Surface_locus L = intersection_locus(phi, psi, fine);
    INFO(L.note);
    REQUIRE(L.topology_computed);
    // D = u - t: every point of the line, and nothing else
    CHECK(L.equation.square_free.degree() == 1);
    // every partner proved found, up to x = +-1, where the sheets meet in folds of the partner at the box's corners
    // (the coordinate equation E_x = 2(u - t) vanishes on the whole line, so the partners come from the combined
    // pairing); a partner touches the corner (1, 1) of the (v, s) domain at u = t = 1/2: an exact point, proved
    // genuine (lifting/partner_boundary_points.h), and the statuses beside it proved by the integrated slope of the
    // partner (lifting/internal/exact_point_spans.h; within about 1e-12 of it in 256-bit intervals, where the double
    // enclosures are wider than the partner's distance to the side, about (t - 1/2)^2)
    for (const auto& a : L.arcs) {
      CHECK(a.fibre_undecided_fraction == 0);
      CHECK(a.undecided_fraction == 0);
    }
    check_exact_touch_at_centre(L, 1, 1);
    check_extrusion_sheets(L, phi, psi, exchanged);
  }
}

TEST_CASE("orthogonal extrusions where det B vanishes identically: the maximal minors give the curve; one sphere "
          "under two parametrizations is refused with the reason",
          "[surface][structured][minors]") {
  // Phi = (x, x^2, z), Psi = (x, s', 1/2 - (2s' - 1)^2) with x = 2t - 1, s' = s: the curve x = 2u - 1, y = x^2,
  // z = 1/2 - (2y - 1)^2, one branch over the whole diagonal u = t, genuine throughout (v = (z + 1)/2 in [0, 1]).
  const Patch phi = from_power({"2*u-1", "(2*u-1)^2", "2*v-1"}, 2, 1);
  const Patch psi = from_power({"2*v-1", "u", "1/2-(2*u-1)^2"}, 2, 1);
  CHECK(intersection_equation(phi, psi).is_degenerate());  // the determinant alone has no answer
  Surface_intersection_options fine;
  fine.polyline_tolerance = 1e-3;
  const Surface_locus L = intersection_locus(phi, psi, fine);
  REQUIRE(L.topology_computed);
  CHECK(L.equation.route == Implicit_equation::Route::maximal_minors);
  CHECK(L.equation.generic_rank == 1);  // B is 2 x 2 with a one-dimensional kernel everywhere
  CHECK(L.equation.square_free.degree() == 1);  // D = u - t
  // at x = 0 (u = t = 1/2) the partner (v, s) = (1/4, 0) touches the side s = 0 (y = 0, z = -1/2): an exact point,
  // proved genuine (lifting/partner_boundary_points.h), and the statuses beside it proved (the integrated slope of
  // lifting/internal/exact_point_spans.h)
  for (const auto& a : L.arcs) CHECK(a.undecided_fraction == 0);
  check_exact_touch_at_centre(L, 0.25, 0);
  for (const auto& a : L.arcs)
    for (const auto& s : a.sheets)
      for (const auto& q : s.points) {  // on both closed-form surfaces
        const auto& p = q.point_3d;
        CHECK(std::fabs(p[1] - p[0] * p[0]) < 1e-9);
        CHECK(std::fabs(p[2] - 0.5 + (2 * p[1] - 1) * (2 * p[1] - 1)) < 1e-9);
      }
  std::vector<std::array<std::array<double, 3>, 3>> samples;
  for (int k = 0; k <= 2000; ++k) {
    const double x = -1 + 2.0 * k / 2000, y = x * x, z = 0.5 - (2 * y - 1) * (2 * y - 1);
    samples.push_back({std::array<double, 3>{(x + 1) / 2, (z + 1) / 2, 0}, std::array<double, 3>{x, y, z},
                       std::array<double, 3>{y, (x + 1) / 2, 0}});
  }
  const auto gap = worst_sheet_gap(L, samples);
  CHECK(gap[0] < 5e-3);
  CHECK(gap[1] < 5e-3);
  CHECK(gap[2] < 5e-3);
  // the same against the points whose genuine status is proved: every span proved phantom is phantom
  check_sheets_complete(proved_genuine_sheets(L), samples, 5e-3);
  // the stereographic cap and the octant of one sphere: a solution at every (u, t), an overlap the minors cannot
  // see past; refused with the reason, never answered with a curve
  const Patch cap = bezoutian_test::rational_patch_from_power({"2*u", "2*v", "1-u^2-v^2", "1+u^2+v^2"}, 2, 2);
  const Patch octant = bezoutian_test::rational_patch_from_power(
      {"(1-v^2)*(1-u^2)", "2*u*(1-v^2)", "2*v*(1+u^2)", "(1+u^2)*(1+v^2)"}, 2, 2);
  try {
    intersection_locus(cap, octant);
    FAIL("expected Invalid_input");
  } catch (const Invalid_input& e) {
    CHECK(std::string(e.what()).find("solution at every (u, t)") != std::string::npos);
  }
}

namespace {
// The unit sphere with longitude and latitude 2 atan((2u - 1)/2), 2 atan((2v - 1)/2) (|z| <= 4/5), and the cylinder
// (x - 1/2)^2 + y^2 = 1/4 with angle 2 atan((2u - 1)/2), z = 2v - 1: Viviani's pair.
Patch viviani_sphere() {
  const std::string a = "((2*u-1)/2)", b = "((2*v-1)/2)";
  return bezoutian_test::rational_patch_from_power(
      {"(1-" + a + "^2)*(1-" + b + "^2)", "2*" + a + "*(1-" + b + "^2)", "2*" + b + "*(1+" + a + "^2)",
       "(1+" + a + "^2)*(1+" + b + "^2)"}, 2, 2);
}
Patch viviani_cylinder() {
  const std::string a = "((2*u-1)/2)";
  return bezoutian_test::rational_patch_from_power({"1", a, "(2*v-1)*(1+" + a + "^2)", "1+" + a + "^2"}, 2, 1);
}
}  // namespace

TEST_CASE("Viviani: a sphere and a cylinder; the cylinder's sides on D = 0 are proved phantom", "[surface][structured][edge]") {
  // sphere |p| = 1 (longitude, latitude 2 atan((2u - 1)/2), 2 atan((2v - 1)/2): |z| <= 4/5) and the cylinder
  // (x - 1/2)^2 + y^2 = 1/4, z = 2t - 1. D vanishes on t = 0 and t = 1: each side's circle (z = -1, z = 1) passes
  // through a pole of the sphere at the circle's parameter infinity, and the poles' latitude parameter lies outside
  // [0, 1]. The circles (|z| = 1) meet the sphere patch (|z| <= 4/5) nowhere: every point of both sides is phantom.
  const Patch sphere = viviani_sphere(), cylinder = viviani_cylinder();
  const Surface_locus L = intersection_locus(sphere, cylinder);
  REQUIRE(L.edge_lines.size() == 2);
  for (const auto& e : L.edge_lines) {
    CHECK((e.side == 0 || e.side == 2));  // t = 0 and t = 1
    CHECK(e.cause == Locus_edge_line::curve_off_partner);
    CHECK_FALSE(e.genuine);
    CHECK(e.status_proved);
  }
  // every genuine traced point lies on both closed forms
  for (const auto& arc : L.arcs)
    for (const auto& q : arc.points)
      if (q.genuine) {
        const auto& p = q.point_3d;
        CHECK(std::fabs(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] - 1) < 1e-9);
        CHECK(std::fabs((p[0] - 0.5) * (p[0] - 0.5) + p[1] * p[1] - 0.25) < 1e-9);
      }
}

TEST_CASE("Viviani: both branches through the tangent point are complete, the fibre proved along the half-branches",
          "[surface][structured][sheets]") {
  // The sphere and cylinder of the test above meet along Viviani's curve (cos^2 h, sin h cos h, +-sin h),
  // |h| <= atan(1/2): two branches crossing at the tangent point (1, 0, 0), the node (u, v) = (1/2, 1/2) of D = 0
  // (sphere: u = tan(h/2) + 1/2, v = +-tan(h/2) + 1/2; cylinder: u = tan h + 1/2, v = (1 +- sin h)/2).
  const Patch sphere = viviani_sphere(), cylinder = viviani_cylinder();
  Surface_intersection_options fine;
  fine.polyline_tolerance = 1e-3;
  const Surface_locus L = intersection_locus(sphere, cylinder, fine);
  INFO(L.note);
  REQUIRE(L.topology_computed);
  std::size_t nodes = 0;
  for (const auto& v : L.topology.vertices)
    if (v.kind == Curve_topology_vertex::singular) {
      ++nodes;
      CHECK(v.u_lo <= 0.5);
      CHECK(0.5 <= v.u_hi);
      CHECK(v.v_lo <= 0.5);
      CHECK(0.5 <= v.v_hi);
    }
  CHECK(nodes == 1);
  CHECK(L.arcs.size() == 4);
  for (const auto& arc : L.arcs) {
    // the chain of Krawczyk boxes along each half-branch of the node's box (a quarter of the domain wide) carries
    // the statuses and the fibre down to the node: the last pieces, where the surfaces' tangency makes the
    // equations as written cancel to rounding level, on the equations expanded about the node
    // (centred_partner_equations.h), to within a few ulps of it (the node's own box)
    CHECK(arc.fibre_undecided_fraction == 0);
    CHECK(arc.undecided_fraction == 0);
    for (const auto& s : arc.sheets)
      for (const auto& q : s.points) {
        const auto& p = q.point_3d;
        CHECK(std::fabs(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] - 1) < 1e-9);
        CHECK(std::fabs((p[0] - 0.5) * (p[0] - 0.5) + p[1] * p[1] - 0.25) < 1e-9);
      }
  }
  std::vector<std::array<std::array<double, 3>, 3>> samples;
  const double h_max = std::atan(0.5);
  for (int k = 0; k <= 2000; ++k)
    for (int sign : {-1, 1}) {
      const double h = -h_max + 2 * h_max * k / 2000, c = std::cos(h), s = std::sin(h);
      samples.push_back({std::array<double, 3>{std::tan(h / 2) + 0.5, sign * std::tan(h / 2) + 0.5, 0},
                         std::array<double, 3>{c * c, s * c, sign * s},
                         std::array<double, 3>{std::tan(h) + 0.5, (1 + sign * s) / 2, 0}});
    }
  const auto gap = worst_sheet_gap(L, samples);
  CHECK(gap[0] < 5e-3);  // sphere (u, v)
  CHECK(gap[1] < 5e-3);  // 3D
  CHECK(gap[2] < 5e-3);  // cylinder (u, v)
  // the same against the points whose genuine status is proved (among them the half-branches' refined points,
  // which take their chain span's status)
  check_sheets_complete(proved_genuine_sheets(L), samples, 5e-3);
}

// The torus R = 5, r = 3 (tube angle theta = 2 atan((2u - 1)/2), angle about the z axis phi = 2 atan(v)) and its
// bitangent plane z = 3x/4 as (8u, 8v, 6u); `exchanged`: both patches with u and v exchanged (the same surfaces
// and curve through another projection). Inside both patches the intersection is the arc of the Villarceau circle
// about (0, 3, 0) of radius 5, (4 cos a, 3 + 5 sin a, 3 cos a) for a in [acos(4/5), pi/2]; it ends at the tangent
// point (0, 8, 0), the plane's corner. Checks the genuine sheets against the closed form (every sheet point on
// both surfaces; the closed form's samples near the sheets and near the points proved genuine) and returns the
// largest undecided share of an arc (status or fibre).
double check_villarceau_arc(bool exchanged) {
  const std::string a = "((2*u-1)/2)", rho = "(5*(1+" + a + "^2)+3*(1-" + a + "^2))";
  Patch torus = bezoutian_test::rational_patch_from_power(
      {rho + "*(1-v^2)", rho + "*2*v", "6*" + a + "*(1+v^2)", "(1+" + a + "^2)*(1+v^2)"}, 2, 2);
  Patch plane = bezoutian_test::rational_patch_from_power({"8*u", "8*v", "6*u", "1"}, 1, 1);
  if (exchanged) {
    torus = torus.transposed();
    plane = plane.transposed();
  }
  Surface_intersection_options fine;
  fine.polyline_tolerance = 1e-3;
  const Surface_locus L = intersection_locus(torus, plane, fine);
  INFO(L.note);
  REQUIRE(L.topology_computed);
  std::size_t sheets = 0;
  double undecided = 0;
  for (const auto& arc : L.arcs) {
    undecided = std::max({undecided, arc.undecided_fraction, arc.fibre_undecided_fraction});
    for (const auto& s : arc.sheets) {
      ++sheets;
      for (const auto& q : s.points) {
        const auto& p = q.point_3d;
        CHECK(std::fabs(std::pow(std::hypot(p[0], p[1]) - 5, 2) + p[2] * p[2] - 9) < 1e-9);
        CHECK(std::fabs(p[2] - 0.75 * p[0]) < 1e-9);
      }
    }
  }
  CHECK(sheets >= 1);
  std::vector<std::array<std::array<double, 3>, 3>> samples;
  const double a0 = std::acos(0.8);
  for (int k = 0; k <= 2000; ++k) {
    const double al = a0 + (M_PI / 2 - a0) * k / 2000;
    const std::array<double, 3> x{4 * std::cos(al), 3 + 5 * std::sin(al), 3 * std::cos(al)};
    const double r = std::hypot(x[0], x[1]), theta = std::atan2(x[2] / 3, (r - 5) / 3), phi = std::atan2(x[1], x[0]);
    std::array<double, 3> on_torus{std::tan(theta / 2) + 0.5, std::tan(phi / 2), 0}, on_plane{x[0] / 8, x[1] / 8, 0};
    if (exchanged) {
      std::swap(on_torus[0], on_torus[1]);
      std::swap(on_plane[0], on_plane[1]);
    }
    samples.push_back({on_torus, x, on_plane});
  }
  const auto gap = worst_sheet_gap(L, samples);
  CHECK(gap[0] < 5e-3);  // torus (u, v)
  CHECK(gap[1] < 5e-3);  // 3D
  CHECK(gap[2] < 5e-3);  // plane (u, v)
  // the same against the points whose genuine status is proved: every span proved phantom is phantom
  check_sheets_complete(proved_genuine_sheets(L), samples, 5e-3);
  return undecided;
}

TEST_CASE("torus and a bitangent plane: the arc of a Villarceau circle, certified up to the tangent point",
          "[surface][structured][sheets]") {
  // the spans next to the tangent point are halved towards it; where the arc comes within rounding of the box's
  // side t = 1 (it touches the side there) the curve equation anchors the partner (lifting/internal/curve_anchor.h)
  // and the partner's monotone coordinates give the status (the partner is the plane's corner (1, 0) there:
  // lifting/internal/exact_point_spans.h)
  CHECK(check_villarceau_arc(false) == 0);
}

TEST_CASE("torus and a bitangent plane, parameters exchanged: a phantom half-branch proved beside the genuine one",
          "[surface][structured][sheets]") {
  // In this projection the Villarceau arc and a phantom arc of D = 0 both end at the corner of the plane's domain
  // (the tangent point), and run through one singular box of the subdivision there. The phantom arc's strip holds
  // the genuine one, so it is proved phantom beside the genuine arc's proved spans
  // (lifting/internal/beside_half_branches.h), and the genuine half-branch is refined to the tolerance along its
  // chain. Its partner reaches the torus patch's side at the corner: the last pieces of its chain are decided
  // beside that exact point (lifting/internal/exact_point_spans.h).
  CHECK(check_villarceau_arc(true) == 0);
}

TEST_CASE("limits: surface intersection refuses oversized patches and stops at its time budget, naming the stage",
          "[surface][limits]") {
  // size limits, before anything: degree 65 in u (max_degree 64), a coordinate of 5001 bits (max_coefficient_bits)
  const Patch steep = from_power({"u^65", "v", "u"}, 65, 1);
  const Patch plane = from_power({"u", "v", "1/2"}, 1, 1);
  try {
    intersection_locus(steep, plane);
    FAIL("no Limit_exceeded");
  } catch (const Limit_exceeded& e) {
    CHECK(e.limit() == "max_degree");
    CHECK(e.stage() == "input");
    CHECK(std::string(e.what()).find("patch 1 has degree 65") != std::string::npos);
  }
  Rational big(1);
  for (int i = 0; i < 5000; ++i) big = big * Rational(2);
  const Patch huge(std::vector<std::vector<Patch::Point>>{{Patch::Point{Q(0), Q(0), Q(0)}, Patch::Point{Q(0), Q(1), Q(0)}},
                                                         {Patch::Point{Q(1), Q(0), Q(0)}, Patch::Point{Q(1), Q(1), big}}});
  try {
    self_intersection_locus(huge);
    FAIL("no Limit_exceeded");
  } catch (const Limit_exceeded& e) {
    CHECK(e.limit() == "max_coefficient_bits");
  }
  Surface_intersection_options unlimited;
  unlimited.limits = Intersection_limits::none();
  CHECK_NOTHROW(intersection_locus(plane, from_power({"u", "1/2", "v"}, 1, 1), unlimited));
  // the time budget: exhausted at the first check, after the direct proofs (which do not decide these pairs: the
  // saddle z = uv meets the plane y = 1/2; the extruded nodal cubic crosses itself along a line)
  Surface_intersection_options o;
  o.limits.time_limit = 1e-9;
  const Patch saddle = from_power({"u", "v", "u*v"}, 1, 1), wall = from_power({"u", "1/2", "v"}, 1, 1);
  try {
    intersection_locus(saddle, wall, o);
    FAIL("no Budget_exceeded");
  } catch (const Budget_exceeded& e) {
    CHECK(e.limit() == "time_limit");
    CHECK(e.stage() == "direct proofs");
    CHECK(std::string(e.what()).find("intersection_locus: time_limit exceeded in direct proofs: ") == 0);
  }
  const std::string c = "(3*u - 3/2)";
  const Patch loop = from_power({c + "^2 - 1", c + "*(" + c + "^2 - 1)", "v"}, 3, 1);
  try {
    self_intersection_locus(loop, o);
    FAIL("no Budget_exceeded");
  } catch (const Budget_exceeded& e) {
    CHECK(e.stage() == "direct proofs");
  }
  // a budget that is not reached changes nothing: the curve (u, 1/2, u/2) (D = 0 is the line t = u/2 on (u, t))
  o.limits.time_limit = 600;
  const Surface_locus L = intersection_locus(saddle, wall, o);
  REQUIRE(L.topology_computed);
  for (const auto& a : L.arcs)
    for (const auto& q : a.points)
      if (q.genuine) CHECK(std::fabs(q.point_3d[2] - q.point_3d[0] / 2) < 1e-9);
}
