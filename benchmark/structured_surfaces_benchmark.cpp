// Structured surfaces with closed-form intersections: height fields, cylinders, orthogonal extrusions, a torus
// and its bitangent plane, Viviani's sphere and cylinder, spheres cut and touched by planes,
// spheres touching, a cone and a plane tangent along curves, pieces of one surface (halves, overlaps, adjacent
// octants), the cylinders, extrusions and torus again with both patches' parameters exchanged, and
// self-intersections (a height field, a sphere cap and octant, extruded loops, a folded patch). For
// each pair: our certified intersection (answered, certified, complete against dense samples of the
// closed-form answer, time) and, side by side in the same run when built with OpenCASCADE, GeomAPI_IntSS on the
// same rational Bezier patches (curves found, completeness by the same measure, points off the true answer, time)
// with the time ratio. Completeness: the largest 3D distance from a closed-form sample to the reported geometry
// (polylines of arcs, sheets and edge lines, shared boundary curves, contact points, overlap regions). The sheet
// segments with a proved distance bound (Locus_sheet::segment_distance_bounds) and the largest such bound.
// Peers: bash benchmark/install-peers.sh (Debian libocct-*-dev; benchmark-only). The CMake build defines
// BEZOUTIAN_WITH_OCCT and links OpenCASCADE for this file when its headers are found.
// Run:   build/benchmark/structured_surfaces_benchmark [--no-distance-bounds] [repetitions=5]
//        build/benchmark/structured_surfaces_benchmark --time-limit S   (where a budget of S seconds ends each family)
#include <bezoutian/intersection/Surface_intersection.h>
#include <bezoutian/io/Geometry_document.h>

#include "occt_peer.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

using namespace bezoutian;
using Patch = Rational_bezier_patch<>;
using P3 = std::array<double, 3>;
using Polyline = std::vector<P3>;

namespace {

Patch power_patch(const std::string& x, const std::string& y, const std::string& z, const std::string& w, int m,
                  int n) {
  const std::string json = "{\"patch\": {\"basis\": \"power\", \"parameters\": [\"u\", \"v\"], \"x\": \"" + x +
                           "\", \"y\": \"" + y + "\", \"z\": \"" + z + "\", \"w\": \"" + w + "\", \"degree\": [" +
                           std::to_string(m) + ", " + std::to_string(n) + "]}}";
  return io::read_json(json, "benchmark").patches.at(0);
}

// The same surface with u and v exchanged (the transposed control net): a certified answer must not depend on
// which parameter runs along which direction.
Patch with_parameters_exchanged(const Patch& p) {
  Patch::Net net(std::size_t(p.degree_v() + 1), std::vector<Patch::Homogeneous_point>(std::size_t(p.degree_u() + 1)));
  for (int i = 0; i <= p.degree_u(); ++i)
    for (int j = 0; j <= p.degree_v(); ++j)
      net[std::size_t(j)][std::size_t(i)] = p.homogeneous_control_point(std::size_t(i), std::size_t(j));
  return Patch::from_homogeneous(net);
}

struct Family {
  std::string name, answer;  // the closed-form answer in words
  Patch phi, psi;
  std::vector<P3> samples;  // dense samples of the true intersection (empty: none)
  bool self = false;        // the self-intersection of phi (psi unused)
};

double distance(const P3& a, const P3& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

double distance_to_segment(const P3& p, const P3& a, const P3& b) {
  P3 d{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double L = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  double s = L > 0 ? ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1] + (p[2] - a[2]) * d[2]) / L : 0;
  s = std::clamp(s, 0.0, 1.0);
  return distance(p, {a[0] + s * d[0], a[1] + s * d[1], a[2] + s * d[2]});
}

double distance_to(const P3& p, const std::vector<Polyline>& lines) {
  double best = 1e300;
  for (const auto& l : lines) {
    if (l.size() == 1) best = std::min(best, distance(p, l[0]));
    for (std::size_t i = 1; i < l.size(); ++i) best = std::min(best, distance_to_segment(p, l[i - 1], l[i]));
  }
  return best;
}

double nearest(const P3& p, const std::vector<P3>& points) {
  double best = 1e300;
  for (const P3& q : points) best = std::min(best, distance(p, q));
  return best;
}

// the largest distance from a sample of `from` to the geometry `to` (0 if `from` is empty, infinite if `to` is)
double worst_gap(const std::vector<P3>& from, const std::vector<Polyline>& to) {
  double worst = 0;
  for (const P3& p : from) worst = std::max(worst, distance_to(p, to));
  return worst;
}

std::vector<P3> circle(const P3& centre, const P3& e1, const P3& e2, double r, double a0, double a1, int n = 400) {
  std::vector<P3> out;
  for (int i = 0; i <= n; ++i) {
    const double a = a0 + (a1 - a0) * i / n;
    P3 x;
    for (std::size_t c = 0; c < 3; ++c) x[c] = centre[c] + r * (std::cos(a) * e1[c] + std::sin(a) * e2[c]);
    out.push_back(x);
  }
  return out;
}

std::vector<Family> families() {
  std::vector<Family> out;
  const double pi = std::acos(-1.0);
  const std::string w = "(1 + u^2)*(1 + v^2)";
  const Patch octant = power_patch("(1 - v^2)*(1 - u^2)", "2*u*(1 - v^2)", "2*v*(1 + u^2)", w, 2, 2);
  auto plane_at = [](const std::string& k) { return power_patch("u", "v", "(25*" + k + " - 9*u - 12*v)/20", "1", 1, 1); };
  const P3 n{9.0 / 25, 12.0 / 25, 0.8}, e1{0.8, -0.6, 0}, e2{12.0 / 25, 16.0 / 25, -0.6};
  {
    Family f{"height fields", "quarter circle u^2 + v^2 = 1/2 at z = 1/2", power_patch("u", "v", "u^2 + v^2", "1", 2, 2),
             power_patch("u", "v", "1 - u^2 - v^2", "1", 2, 2), {}};
    f.samples = circle({0, 0, 0.5}, {1, 0, 0}, {0, 1, 0}, std::sqrt(0.5), 0, pi / 2);
    out.push_back(f);
  }
  {
    const auto doc = io::read_geometry_file(std::string(BEZOUTIAN_SOURCE_DIR) + "/examples/data/two_cylinders.json");
    Family f{"two cylinders", "x = y in [3/5, 1], z = +-sqrt(1 - x^2): two branches", doc.patches[0], doc.patches[1], {}};
    for (int i = 0; i <= 400; ++i) {
      const double c = 0.6 + 0.4 * i / 400, z = std::sqrt(std::max(0.0, 1 - c * c));
      f.samples.push_back({c, c, z});
      f.samples.push_back({c, c, -z});
    }
    out.push_back(f);
  }
  {
    const std::string a = "(u/2)", b = "(1/2+3*v/2)";
    Family f{"sphere cut by a plane", "latitude circle of radius 15/17, two sheets meeting at a fold",
             power_patch("(1-" + a + "^2)*(1-" + b + "^2)", "(1-" + a + "^2)*2*" + b, "2*" + a + "*(1+" + b + "^2)",
                         "(1+" + a + "^2)*(1+" + b + "^2)", 2, 2),
             power_patch("2*u-1", "v", "8/17", "1", 1, 1), {}};
    f.samples = circle({0, 0, 8.0 / 17}, {1, 0, 0}, {0, 1, 0}, 15.0 / 17, 2 * std::atan(0.5), 2 * std::atan(2.0));
    out.push_back(f);
  }
  out.push_back({"plane touching a sphere", "the point (9/25, 12/25, 4/5), tangent", octant, plane_at("1"), {n}});
  out.push_back({"plane 1e-6 above a sphere", "none", octant, plane_at("1000001/1000000"), {}});
  {
    const double k = 1 - 1e-6;
    Family f{"plane 1e-6 below a sphere", "circle of radius 1.414e-3", octant, plane_at("999999/1000000"), {}};
    f.samples = circle({k * n[0], k * n[1], k * n[2]}, e1, e2, std::sqrt(1 - k * k), 0, 2 * pi);
    out.push_back(f);
  }
  out.push_back({"spheres touching", "the point (9/25, 12/25, 4/5), tangent", octant,
                 power_patch("18/25*" + w + " - (1 - v^2)*(1 - u^2)", "24/25*" + w + " - 2*u*(1 - v^2)",
                             "8/5*" + w + " - 2*v*(1 + u^2)", w, 2, 2),
                 {n}});
  {
    Family f{"cone tangent to a sphere", "quarter circle of radius 3/5 at z = 4/5 (tangent curve)", octant,
             power_patch("(1/2 + v)*3/5*(1 - u^2)", "(1/2 + v)*6/5*u", "(1 + u^2)*(5/4 - 9/20*(1/2 + v))", "1 + u^2", 2,
                         1),
             {}};
    f.samples = circle({0, 0, 0.8}, {1, 0, 0}, {0, 1, 0}, 0.6, 0, pi / 2);
    out.push_back(f);
  }
  {
    // det B vanishes identically (a common root at infinity for every (u, t)): D from the maximal minors of B
    Family f{"orthogonal extrusions", "y = x^2 along z meets y = 1 - z^2 along x: z = +-sqrt(1 - x^2), two branches",
             power_patch("2*u - 1", "(2*u - 1)^2", "2*v - 1", "1", 2, 1),
             power_patch("2*v - 1", "1 - (2*u - 1)^2", "2*u - 1", "1", 2, 1), {}};
    for (int i = 0; i <= 400; ++i) {
      const double x = -1 + 2.0 * i / 400, z = std::sqrt(std::max(0.0, 1 - x * x));
      f.samples.push_back({x, x * x, z});
      f.samples.push_back({x, x * x, -z});
    }
    out.push_back(f);
  }
  {
    Family f{"orthogonal extrusions, det B = 0", "y = x^2 along z meets the curve (s, 1/2 - (2s - 1)^2) along x",
             power_patch("2*u - 1", "(2*u - 1)^2", "2*v - 1", "1", 2, 1),
             power_patch("2*v - 1", "u", "1/2 - (2*u - 1)^2", "1", 2, 1), {}};
    for (int i = 0; i <= 400; ++i) {
      const double x = -1 + 2.0 * i / 400, y = x * x;
      f.samples.push_back({x, y, 0.5 - (2 * y - 1) * (2 * y - 1)});
    }
    out.push_back(f);
  }
  {
    // torus R = 5, r = 3 (tube angle 2 atan((2u - 1)/2), around the axis 2 atan(v)) and its bitangent plane z = 3x/4
    const std::string a = "((2*u - 1)/2)", rho = "(5*(1 + " + a + "^2) + 3*(1 - " + a + "^2))";
    Family f{"torus and a bitangent plane", "an arc of the Villarceau circle of radius 5 about (0, 3, 0)",
             power_patch(rho + "*(1 - v^2)", rho + "*2*v", "6*" + a + "*(1 + v^2)", "(1 + " + a + "^2)*(1 + v^2)", 2, 2),
             power_patch("8*u", "8*v", "6*u", "1", 1, 1), {}};
    f.samples = circle({0, 3, 0}, {0.8, 0, 0.6}, {0, 1, 0}, 5, std::acos(0.8), pi / 2);
    out.push_back(f);
  }
  {
    // sphere |p| = 1 (longitude and latitude 2 atan((2u - 1)/2), 2 atan((2v - 1)/2)) and the cylinder
    // (x - 1/2)^2 + y^2 = 1/4 (angle psi = 2 atan((2u - 1)/2), z = 2v - 1): x = cos^2(psi/2),
    // y = sin(psi/2) cos(psi/2), z = +-sin(psi/2), two branches crossing at the tangency (1, 0, 0)
    const std::string a = "((2*u - 1)/2)", b = "((2*v - 1)/2)";
    Family f{"Viviani: sphere and cylinder", "two branches crossing at the tangent point (1, 0, 0)",
             power_patch("(1 - " + a + "^2)*(1 - " + b + "^2)", "2*" + a + "*(1 - " + b + "^2)",
                         "2*" + b + "*(1 + " + a + "^2)", "(1 + " + a + "^2)*(1 + " + b + "^2)", 2, 2),
             power_patch("1", a, "(2*v - 1)*(1 + " + a + "^2)", "1 + " + a + "^2", 2, 1), {}};
    const double psi_max = 2 * std::atan(0.5);
    for (int i = 0; i <= 400; ++i) {
      const double h = (-psi_max + 2 * psi_max * i / 400) / 2, c = std::cos(h), sn = std::sin(h);
      f.samples.push_back({c * c, sn * c, sn});
      f.samples.push_back({c * c, sn * c, -sn});
    }
    out.push_back(f);
  }
  const Patch quarter = power_patch("1 - u^2", "2*u", "v*(1 + u^2)", "1 + u^2", 2, 1);
  {
    Family f{"plane tangent to a cylinder", "the line x = 1, y = 0, z in [0, 1] (tangent curve)", quarter,
             power_patch("1", "2*u - 1", "v", "1", 1, 1), {}};
    for (int i = 0; i <= 400; ++i) f.samples.push_back({1, 0, i / 400.0});
    out.push_back(f);
  }
  const Patch paraboloid = power_patch("2*u - 1", "2*v - 1", "(2*u - 1)^2 + (2*v - 1)^2", "1", 2, 2);
  {
    const auto halves = paraboloid.split_u(Rational(1, 2));
    Family f{"paraboloid halves", "shared boundary x = 0, z = y^2", halves.first, halves.second, {}};
    for (int i = 0; i <= 400; ++i) {
      const double y = -1 + 2.0 * i / 400;
      f.samples.push_back({0, y, y * y});
    }
    out.push_back(f);
  }
  {
    Family f{"overlapping paraboloid pieces", "the region x in [-1/5, 1/5] (an overlap)",
             paraboloid.restriction(Rational(0), Rational(3, 5), Rational(0), Rational(1)),
             paraboloid.restriction(Rational(2, 5), Rational(1), Rational(0), Rational(1)), {}};
    for (int i = 0; i <= 40; ++i)
      for (int j = 0; j <= 40; ++j) {
        const double x = -0.2 + 0.4 * i / 40, y = -1 + 2.0 * j / 40;
        f.samples.push_back({x, y, x * x + y * y});
      }
    out.push_back(f);
  }
  {
    Family f{"adjacent sphere octants", "the shared meridian x = 0", octant,
             power_patch("-2*u*(1 - v^2)", "(1 - v^2)*(1 - u^2)", "2*v*(1 + u^2)", w, 2, 2), {}};
    f.samples = circle({0, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1, 0, pi / 2);
    out.push_back(f);
  }
  // the same pairs with both patches' parameters exchanged
  for (const std::string name : {"two cylinders", "orthogonal extrusions", "torus and a bitangent plane"})
    for (std::size_t k = 0, n = out.size(); k < n; ++k)
      if (out[k].name == name) {
        Family f = out[k];
        f.name += ", parameters exchanged";
        f.phi = with_parameters_exchanged(f.phi);
        f.psi = with_parameters_exchanged(f.psi);
        out.push_back(f);
      }
  // self-intersections
  auto self = [&](const std::string& name, const std::string& answer, const Patch& p, std::vector<P3> samples) {
    Family f{name, answer, p, p, std::move(samples)};
    f.self = true;
    out.push_back(f);
  };
  self("self: height field", "none (a graph over the (u, v) plane)",
       power_patch("u", "v", "u^2*v - (1/3)*v^3 + u*v", "1", 2, 3), {});
  self("self: stereographic sphere cap", "none",
       power_patch("2*(u - 1/2)", "2*(v - 1/2)", "1 - (u - 1/2)^2 - (v - 1/2)^2", "1 + (u - 1/2)^2 + (v - 1/2)^2", 2, 2),
       {});
  self("self: sphere octant", "the north pole, the collapsed side v = 1", octant, {P3{0, 0, 1}});
  {
    // the nodal cubic (c^2 - 1, c (c^2 - 1)), c = 3u - 3/2, through (0, 0) at u = 1/6 and 5/6, extruded along z
    const std::string c = "(3*u - 3/2)", x = c + "^2 - 1", y = c + "*(" + c + "^2 - 1)";
    std::vector<P3> line, sheared;
    for (int i = 0; i <= 400; ++i) {
      line.push_back({0, 0, i / 400.0});
      sheared.push_back({0, 0, 5.0 / 12 + (2.0 / 3) * i / 400});
    }
    self("self: extruded loop", "the double line x = y = 0, z in [0, 1]", power_patch(x, y, "v", "1", 3, 1), line);
    self("self: extruded loop, sheared", "x = y = 0, z in [5/12, 13/12], ending at two split points",
         power_patch(x, y, "v + u/2", "1", 3, 1), sheared);
    self("self: extruded loop, degree elevated", "the double line x = y = 0, z in [0, 1]",
         power_patch(x, y, "v", "1", 4, 2), line);
  }
  {
    std::vector<P3> segment;  // v = 1/3, u in [0, 3/10] with partner 3/5 - u: ((u - 3/10)^2, 1/9, 0)
    for (int i = 0; i <= 400; ++i) segment.push_back({std::pow(0.3 * i / 400, 2), 1.0 / 9, 0});
    const auto doc = io::read_geometry_file(std::string(BEZOUTIAN_SOURCE_DIR) + "/examples/data/folded_patch.json");
    self("self: folded patch", "the segment x in [0, 9/100], y = 1/9, z = 0, with a pinch point", doc.patches[0],
         segment);
  }
  return out;
}

// Our reported geometry: sheets, edge lines, isolated contacts, shared boundary curves, overlap regions.
struct Ours {
  bool answered = false, certified = false;
  // the largest fractions of an arc (with genuine or undecided points) whose genuine / phantom status, and whose
  // fibre (every partner found), are not proved
  double status_undecided = 0, fibre_undecided = 0;
  bool pinch_incomplete = false;
  // sheet segments, those with a proved distance bound (Locus_sheet::segment_distance_bounds), the largest such
  // bound in 3D
  std::size_t segments = 0, segments_proved = 0;
  double worst_bound = 0;
  std::vector<Polyline> geometry;
  std::string note;
};

// --no-distance-bounds: without the proved chord distances (Surface_intersection_options::prove_polyline_distance),
// to measure what they cost
bool distance_bounds = true;

Ours ours(const Family& f) {
  Ours out;
  Surface_intersection_options o;
  o.polyline_tolerance = 1e-4;
  o.prove_polyline_distance = distance_bounds;
  Surface_locus L;
  try {
    L = f.self ? self_intersection_locus(f.phi, o) : intersection_locus(f.phi, f.psi, o);
  } catch (const std::exception& e) {
    out.note = e.what();
    return out;
  }
  out.answered = L.topology_computed;
  out.certified = L.topology_computed;
  out.note = L.note;
  // a self-intersection's double curve: its pinch points found, all of them
  out.pinch_incomplete = f.self && !L.arcs.empty() && !L.pinch_points_complete;
  out.certified = out.certified && !out.pinch_incomplete;
  for (const auto& a : L.arcs) {
    bool genuine = false;
    for (const auto& q : a.points) genuine = genuine || q.genuine;
    if (genuine || a.undecided_fraction > 0) {
      out.certified = out.certified && a.undecided_fraction == 0 && a.fibre_undecided_fraction == 0;
      out.status_undecided = std::max(out.status_undecided, a.undecided_fraction);
      out.fibre_undecided = std::max(out.fibre_undecided, a.fibre_undecided_fraction);
    }
    for (const auto& s : a.sheets) {
      for (const auto& b : s.segment_distance_bounds) {
        ++out.segments;
        if (!std::isfinite(b[2])) continue;
        ++out.segments_proved;
        out.worst_bound = std::max(out.worst_bound, b[2]);
      }
      Polyline l;
      for (const auto& q : s.points) l.push_back(q.point_3d);
      out.geometry.push_back(l);
    }
  }
  for (const auto& e : L.edge_lines) {
    out.certified = out.certified && e.status_proved;
    if (!e.genuine) continue;
    Polyline l;
    for (const auto& q : e.points) l.push_back(q.point_3d);
    out.geometry.push_back(l);
  }
  for (const auto& ip : L.isolated_points) {
    out.certified = out.certified && ip.lift.proved;
    for (const auto& p : ip.lift.partners) out.geometry.push_back({p.point});
  }
  for (const auto& c : L.contacts) {
    if (!c.shared_curve) {
      out.geometry.push_back({c.point});
      continue;
    }
    const auto curve = f.phi.boundary_curve<Rational_bezier_curve_3<Rational>>(c.side_first);
    Polyline l;
    const double a = c.first_0.to_double(), b = c.first_1.to_double();
    for (int i = 0; i <= 200; ++i) {
      const auto p = curve.evaluate(a + (b - a) * i / 200);
      l.push_back({p[0], p[1], p[2]});
    }
    out.geometry.push_back(l);
  }
  for (const auto& ov : L.overlaps) {
    const auto& r = ov.first;
    const double u0 = CGAL::to_double(r[0]), u1 = CGAL::to_double(r[1]), v0 = CGAL::to_double(r[2]),
                 v1 = CGAL::to_double(r[3]);
    for (int i = 0; i <= 200; ++i) {  // iso-lines of the region, 1/200 of it apart
      Polyline l;
      for (int j = 0; j <= 200; ++j) l.push_back(f.phi.evaluate(u0 + (u1 - u0) * i / 200, v0 + (v1 - v0) * j / 200));
      out.geometry.push_back(l);
    }
  }
  return out;
}

#ifdef BEZOUTIAN_WITH_OCCT
using Theirs = occt_peer::Result;
Handle(Geom_BezierSurface) occt_surface(const Patch& p) { return occt_peer::surface(p); }
Theirs occt(const Handle(Geom_BezierSurface) & a, const Handle(Geom_BezierSurface) & b) {
  return occt_peer::intersect(a, b);
}
#endif

template <class F>
double median_seconds(int repetitions, F f) {
  std::vector<double> t;
  for (int r = 0; r < repetitions; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

std::string gap_text(double g) {
  char buf[32];
  if (!std::isfinite(g) || g > 1e100) return "missing";
  std::snprintf(buf, sizeof buf, "%.1e", g);
  return buf;
}

}  // namespace

// How closely the time limit holds: each family once with Intersection_limits::time_limit = `limit` seconds, the
// wall time until it returns or throws Budget_exceeded, and the stage named.
int time_limit_table(double limit) {
  std::printf("| family | time_limit [s] | returned after [s] | overrun [s] | outcome |\n|---|---|---|---|---|\n");
  for (const Family& f : families()) {
    Surface_intersection_options o;
    o.polyline_tolerance = 1e-4;
    o.limits.time_limit = limit;
    std::string outcome = "finished";
    const auto t0 = std::chrono::steady_clock::now();
    try {
      const Surface_locus L = f.self ? self_intersection_locus(f.phi, o) : intersection_locus(f.phi, f.psi, o);
    } catch (const Budget_exceeded& e) {
      const std::string what = e.what();
      const auto in = what.find("exceeded in ");
      outcome = "stopped in " + (in == std::string::npos ? what : what.substr(in + 12, what.find(':', in) - in - 12));
    } catch (const std::exception& e) {
      outcome = std::string("error: ") + e.what();
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("| %s | %.2f | %.3f | %.3f | %s |\n", f.name.c_str(), limit, s, std::max(0.0, s - limit), outcome.c_str());
  }
  return 0;
}

int main(int argc, char** argv) {
  if (argc > 2 && std::string(argv[1]) == "--time-limit") return time_limit_table(std::atof(argv[2]));
  if (argc > 1 && std::string(argv[1]) == "--no-distance-bounds") {
    distance_bounds = false;
    --argc;
    ++argv;
  }
  const int repetitions = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  std::printf("| family | closed-form answer | ours: answered | certified | gap to the answer | "
              "sheet segments with a proved distance bound (largest, 3D) | time [ms] |"
#ifdef BEZOUTIAN_WITH_OCCT
              " OCCT: curves | gap to the answer | farthest OCCT point off it | time [ms] | time ratio ours/OCCT |"
#endif
              "\n|---|---|---|---|---|---|---|"
#ifdef BEZOUTIAN_WITH_OCCT
              "---|---|---|---|---|"
#endif
              "\n");
  for (const Family& f : families()) {
    Ours r;
    const double t_ours = median_seconds(repetitions, [&] { r = ours(f); });
    const double gap = f.samples.empty() ? (r.geometry.empty() ? 0 : -1) : worst_gap(f.samples, r.geometry);
    char certified[128] = "yes";
    if (!r.certified)
      std::snprintf(certified, sizeof certified, "no (undecided: status %.2g %%, fibre %.2g %%%s)",
                    100 * r.status_undecided, 100 * r.fibre_undecided,
                    r.pinch_incomplete ? "; pinch points not proved complete" : "");
    char bounds[96] = "-";
    if (r.segments > 0)
      std::snprintf(bounds, sizeof bounds, "%zu of %zu (%s)", r.segments_proved, r.segments,
                    r.segments_proved ? gap_text(r.worst_bound).c_str() : "-");
    std::printf("| %s | %s | %s | %s | %s | %s | %.2f |", f.name.c_str(), f.answer.c_str(), r.answered ? "yes" : "no",
                certified, gap < 0 ? "spurious" : (f.samples.empty() ? "none, proved" : gap_text(gap)).c_str(), bounds,
                1e3 * t_ours);
#ifdef BEZOUTIAN_WITH_OCCT
    if (f.self) {  // (GeomAPI_IntSS intersects two surfaces; OpenCASCADE has no self-intersection of one)
      std::printf(" - | - | - | - | - |\n");
      continue;
    }
    const auto A = occt_surface(f.phi), B = occt_surface(f.psi);
    Theirs s;
    const double t_occt = median_seconds(repetitions, [&] { s = occt(A, B); });
    double off = 0;
    for (const auto& l : s.geometry)
      for (const P3& p : l)
        off = std::max(off, nearest(p, f.samples));
    const double their_gap = f.samples.empty() ? 0 : worst_gap(f.samples, s.geometry);
    std::printf(" %s | %s | %s | %.2f | %.1f |", s.done ? std::to_string(s.curves).c_str() : "failed",
                f.samples.empty() ? (s.curves == 0 ? "none" : "spurious") : gap_text(their_gap).c_str(),
                s.geometry.empty() ? "-" : gap_text(off).c_str(), 1e3 * t_occt, t_occt > 0 ? t_ours / t_occt : 0.0);
#endif
    std::printf("\n");
  }
}
