// Arrangement_2 with Arr_rational_bezier_traits_2: hand-made configurations with counts derived by hand (Euler's
// formula V - E + F = 1 + components), tangencies, rational circles compared with CGAL's conic traits counts,
// and seeded random polynomial cubics cross-checked against CGAL's own Arr_Bezier_curve_traits_2.
#include <bezoutian/Arr_rational_bezier_traits_2.h>
#include <bezoutian/io/Cgal_dat_format.h>

#include <CGAL/Arrangement_2.h>
#include <CGAL/Arr_naive_point_location.h>
#include <CGAL/Arr_landmarks_point_location.h>
#include <CGAL/Arr_point_location/Arr_lm_grid_generator.h>

#include <CGAL/Cartesian.h>
#include <CGAL/CORE_algebraic_number_traits.h>
#include <CGAL/Arr_Bezier_curve_traits_2.h>
#include <CGAL/Arr_conic_traits_2.h>
#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/General_polygon_set_2.h>
#include <CGAL/Gps_traits_2.h>

#include <catch2/catch.hpp>

#include <cstdio>
#include <list>
#include <random>
#include <sstream>
#include <vector>

using namespace bezoutian;

namespace {

using Traits = Arr_rational_bezier_traits_2;
using Arr = CGAL::Arrangement_2<Traits>;
using Curve = Traits::Curve_2;
using Pt = Curve::Point;

struct Counts {
  std::size_t v, e, f, iso;
  bool valid;
};

Counts counts_of(const std::vector<Curve>& cs, bool incremental = false) {
  Traits tr;
  Arr arr(&tr);
  if (incremental)
    for (const Curve& c : cs) CGAL::insert(arr, c);
  else
    CGAL::insert(arr, cs.begin(), cs.end());
  return {arr.number_of_vertices(), arr.number_of_edges(), arr.number_of_faces(), arr.number_of_isolated_vertices(),
          arr.is_valid()};
}

Curve poly(const std::vector<std::pair<Rational, Rational>>& v) {
  std::vector<Pt> p;
  for (const auto& q : v) p.push_back(Pt{q.first, q.second});
  return Curve(p);
}

// Quarter k (0..3) of the circle of centre (cx, cy) and radius r: the rational parametrization
// ((1-u^2), 2u) / (1+u^2), u in [0,1], rotated by k quarter turns. Bernstein form: weights 1, 1, 2 and control
// points (1,0), (1,1), (0,1) for the first quarter.
Curve quarter(const Rational& cx, const Rational& cy, const Rational& r, int k) {
  std::vector<std::pair<Rational, Rational>> base{{1, 0}, {1, 1}, {0, 1}};
  std::vector<Pt> p;
  for (auto q : base) {
    for (int i = 0; i < k; ++i) q = {-q.second, q.first};
    p.push_back(Pt{cx + r * q.first, cy + r * q.second});
  }
  return Curve(p, {Rational(1), Rational(1), Rational(2)});
}

std::vector<Curve> circle(const Rational& cx, const Rational& cy, const Rational& r) {
  std::vector<Curve> c;
  for (int k = 0; k < 4; ++k) c.push_back(quarter(cx, cy, r, k));
  return c;
}

void check(const std::vector<Curve>& cs, std::size_t v, std::size_t e, std::size_t f) {
  for (bool inc : {false, true}) {
    const Counts c = counts_of(cs, inc);
    INFO("incremental " << inc);
    CHECK(c.valid);
    CHECK(c.v == v);
    CHECK(c.e == e);
    CHECK(c.f == f);
  }
}

}  // namespace

TEST_CASE("arrangement traits: two crossing parabolas (irrational crossings)", "[arrangement]") {
  // y = 4t(1-t) and y = 1 - 4t(1-t), x = 2t: crossings at 8t^2 - 8t + 1 = 0, t = (2 +- sqrt 2)/4.
  check({poly({{0, 0}, {1, 2}, {2, 0}}), poly({{0, 1}, {1, -1}, {2, 1}})}, 6, 6, 2);
}

TEST_CASE("arrangement traits: mirror-image parabolas touching tangentially", "[arrangement]") {
  // y = x^2 on [-1,2] and its mirror image across its tangent y = x - 1/4 at (1/2, 1/4), (x,y) -> (y+1/4, x-1/4).
  // They touch only there (opposite sides of the tangent). The mirror image has a vertical tangent at the image
  // of (0,0), (1/4,-1/4): V = 4 ends + touching point + vertical tangent, E = 2 + 3, one component: F = 1.
  const Curve a = poly({{-1, 1}, {Rational(1, 2), -2}, {2, 4}});
  const Curve b = poly({{Rational(5, 4), Rational(-5, 4)}, {Rational(-7, 4), Rational(1, 4)}, {Rational(17, 4), Rational(7, 4)}});
  check({a, b}, 6, 5, 1);
  // The mirror image moved by 1/8 towards the parabola crosses it twice near the old touching point instead.
  const Curve b2 = poly({{Rational(9, 8), Rational(-9, 8)}, {Rational(-15, 8), Rational(3, 8)}, {Rational(33, 8), Rational(15, 8)}});
  check({a, b2}, 7, 7, 2);
}

TEST_CASE("arrangement traits: triple-root tangency y = x^3 against y = 0", "[arrangement]") {
  // (2t-1, (2t-1)^3): Bernstein control points (-1,-1), (-1/3,1), (1/3,-1), (1,1); the x-axis crosses it at the
  // inflection (0,0) with multiplicity 3.
  const Curve cubic = poly({{-1, -1}, {Rational(-1, 3), 1}, {Rational(1, 3), -1}, {1, 1}});
  check({cubic, poly({{-1, 0}, {1, 0}})}, 5, 4, 1);
  // y = 3x - 2 (x in [1/2, 3/2]) is tangent to y = x^3 at its end (1,1) (x^3 - 3x + 2 = (x-1)^2 (x+2)).
  check({cubic, poly({{Rational(1, 2), Rational(-1, 2)}, {Rational(3, 2), Rational(5, 2)}})}, 3 + 1, 3, 1);
}

TEST_CASE("arrangement traits: curves meeting at end points", "[arrangement]") {
  const Curve arch = poly({{0, 0}, {1, 2}, {2, 0}});  // apex (1,1) at t = 1/2
  check({arch, poly({{2, 0}, {3, 2}, {4, 0}})}, 3, 2, 1);
  // a vertical segment standing on the apex
  check({arch, poly({{1, 1}, {1, 3}})}, 4, 3, 1);
  // a horizontal segment tangent at the apex, starting there
  check({arch, poly({{1, 1}, {3, 1}})}, 4, 3, 1);
  // the same segment through the apex: tangent touching in the interior of both
  check({arch, poly({{-1, 1}, {3, 1}})}, 5, 4, 1);
  // closing the arch with its chord: one bounded face
  check({arch, poly({{0, 0}, {2, 0}})}, 2, 2, 2);
}

namespace {
// The same circles, as the same four quarter arcs (counterclockwise between the rational points centre + r e_k),
// in an arrangement of CGAL's Arr_conic_traits_2 (CORE number types).
struct Circle {
  Rational cx, cy, r;
};
Counts conic_counts(const std::vector<Circle>& circles) {
  using Nt = CGAL::CORE_algebraic_number_traits;
  using K = CGAL::Cartesian<Nt::Rational>;
  using Conic_traits = CGAL::Arr_conic_traits_2<K, CGAL::Cartesian<Nt::Algebraic>, Nt>;
  auto q = [](const Rational& v) {
    std::ostringstream o;
    o << v;
    return Nt::Rational(o.str());
  };
  std::vector<Conic_traits::Curve_2> arcs;
  for (const Circle& c : circles) {
    const K::Circle_2 circ(K::Point_2(q(c.cx), q(c.cy)), q(c.r * c.r));
    const Rational dx[4] = {1, 0, -1, 0}, dy[4] = {0, 1, 0, -1};
    for (int k = 0; k < 4; ++k) {
      const Conic_traits::Point_2 s(Nt::Algebraic(q(c.cx + c.r * dx[k])), Nt::Algebraic(q(c.cy + c.r * dy[k])));
      const Conic_traits::Point_2 t(Nt::Algebraic(q(c.cx + c.r * dx[(k + 1) % 4])),
                                    Nt::Algebraic(q(c.cy + c.r * dy[(k + 1) % 4])));
      arcs.push_back(Conic_traits::Curve_2(circ, CGAL::COUNTERCLOCKWISE, s, t));
    }
  }
  Conic_traits tr;
  CGAL::Arrangement_2<Conic_traits> arr(&tr);
  CGAL::insert(arr, arcs.begin(), arcs.end());
  return {arr.number_of_vertices(), arr.number_of_edges(), arr.number_of_faces(), arr.number_of_isolated_vertices(),
          arr.is_valid()};
}

void check_circles(const std::vector<Circle>& circles, std::size_t v, std::size_t e, std::size_t f) {
  std::vector<Curve> cs;
  for (const Circle& c : circles)
    for (const Curve& a : circle(c.cx, c.cy, c.r)) cs.push_back(a);
  check(cs, v, e, f);
  const Counts k = conic_counts(circles);
  CHECK(k.valid);
  CHECK(k.v == v);
  CHECK(k.e == e);
  CHECK(k.f == f);
}
}  // namespace

TEST_CASE("arrangement traits: circles, compared with CGAL's conic traits", "[arrangement][cgal]") {
  check_circles({{0, 0, 1}}, 4, 4, 2);
  check_circles({{0, 0, 1}, {1, 0, 1}}, 10, 12, 4);
  check_circles({{0, 0, 1}, {3, 0, 2}}, 7, 8, 3);
  check_circles({{0, 0, 1}, {1, 0, 2}}, 7, 8, 3);
  // Three circles crossing pairwise (2 points each, none shared) and a small one inside the lens of the first two,
  // crossing only the third one (centre distance 2/3 between 3/4 - 1/5 and 3/4 + 1/5): V = 16 arc ends + 8
  // crossings, each crossing splits one arc of each circle: E = 16 + 16, one component: F = 2 - V + E.
  check_circles({{0, 0, 1}, {1, 0, 1}, {Rational(1, 2), Rational(2, 3), Rational(3, 4)}, {Rational(1, 2), 0, Rational(1, 5)}},
                24, 32, 10);
}

TEST_CASE("arrangement traits: circles as rational quadratic arcs", "[arrangement]") {
  // One circle: 4 arcs, 4 vertices, 2 faces.
  check(circle(0, 0, 1), 4, 4, 2);
  // Unit circles centred at (0,0) and (1,0) cross at (1/2, +-sqrt(3)/2) (irrational), each inside one arc of each
  // circle: V = 8 + 2, E = 8 + 4, F = 4 (lens, two crescents, unbounded).
  std::vector<Curve> two = circle(0, 0, 1), b = circle(1, 0, 1);
  two.insert(two.end(), b.begin(), b.end());
  check(two, 10, 12, 4);
  // Externally tangent circles: radius 1 at (0,0) and radius 2 at (3,0) touch at (1,0), an arc end of both.
  std::vector<Curve> t = circle(0, 0, 1), c = circle(3, 0, 2);
  t.insert(t.end(), c.begin(), c.end());
  check(t, 7, 8, 3);
  // Internally tangent: radius 1 at (0,0), radius 2 at (1,0) touch at (-1,0), an arc end of both.
  std::vector<Curve> in = circle(0, 0, 1), d = circle(1, 0, 2);
  in.insert(in.end(), d.begin(), d.end());
  check(in, 7, 8, 3);
  // A circle and a parabola (mixed rational/polynomial): y = x^2 - 1/2 on [-2,2] crosses the unit circle
  // where y^2 + y - 1/2 = 0, y = (-1 + sqrt 3)/2 (two points) and y = (-1 - sqrt 3)/2 < -1 (none): V = 4 + 2 + 2,
  // E = 4 + 2 + 3, F = 2 - V + E.
  std::vector<Curve> m = circle(0, 0, 1);
  m.push_back(poly({{-2, Rational(7, 2)}, {0, Rational(-9, 2)}, {2, Rational(7, 2)}}));
  check(m, 8, 9, 3);
}

TEST_CASE("arrangement traits: overlapping pieces of one parabola", "[arrangement]") {
  const Curve arch = poly({{0, 0}, {1, 2}, {2, 0}});
  const Curve inner = arch.restriction(Rational(1, 4), Rational(3, 4));
  const Curve ext = arch.restriction(Rational(1, 2), Rational(3, 2));
  check({arch, inner}, 4, 3, 1);
  check({arch, ext}, 4, 3, 1);
  check({arch, inner, ext}, 6, 5, 1);
  // reversed orientation overlap
  check({arch, ext.reversed()}, 4, 3, 1);
}

namespace {
// The mirror image of a polynomial curve across its tangent line at the rational parameter t0. The reflection
// across a line of rational direction (a, b) is the rational matrix [[a^2-b^2, 2ab], [2ab, b^2-a^2]] / (a^2+b^2),
// so the image has rational control points; the two curves are tangent at C(t0).
Curve mirrored_at(const Curve& c, const Rational& t0) {
  const auto d = c.derivative()(t0);
  const auto p0 = c(t0);
  const Rational a = d[0], b = d[1], n = a * a + b * b;
  std::vector<Pt> q;
  for (const auto& p : c.control_points()) {
    const Rational x = p[0] - p0[0], y = p[1] - p0[1];
    q.push_back(Pt{p0[0] + ((a * a - b * b) * x + 2 * a * b * y) / n, p0[1] + (2 * a * b * x + (b * b - a * a) * y) / n});
  }
  return Curve(q);
}
}  // namespace

TEST_CASE("arrangement traits: tangency stress, random cubics and their mirror images across a tangent", "[arrangement]") {
  std::mt19937 g(7);
  for (int i = 0; i < 8; ++i) {
    std::vector<Pt> p;
    for (int j = 0; j < 4; ++j) p.push_back(Pt{Rational(long(g() % 100)), Rational(long(g() % 100))});
    const Curve c(p);
    const Rational t0(int(1 + g() % 6), 7);
    const Curve m = mirrored_at(c, t0);
    Traits tr;
    Arr arr(&tr);
    const std::vector<Curve> pair{c, m};
    CGAL::insert(arr, pair.begin(), pair.end());
    INFO("case " << i);
    CHECK(arr.is_valid());
    // The touching point C(t0) (exact rational) is a vertex where the two curves meet: degree 4.
    const auto q = c(t0);
    const Traits::Point_2 touch(q[0], q[1]);
    bool found = false;
    for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v)
      if (tr.equal_2_object()(v->point(), touch)) {
        found = true;
        CHECK(v->degree() == 4);
      }
    CHECK(found);
    // aggregated and incremental insertion agree
    const Counts a = counts_of({c, m}), b = counts_of({c, m}, true);
    CHECK(a.v == arr.number_of_vertices());
    CHECK(b.v == a.v);
    CHECK(b.e == a.e);
    CHECK(b.f == a.f);
  }
}

TEST_CASE("arrangement traits: point location in the lens of two circles", "[arrangement]") {
  std::vector<Curve> two = circle(0, 0, 1), b = circle(1, 0, 1);
  two.insert(two.end(), b.begin(), b.end());
  Traits tr;
  Arr arr(&tr);
  CGAL::insert(arr, two.begin(), two.end());
  CGAL::Arr_naive_point_location<Arr> pl(arr);
  auto face_of = [&](const Rational& x, const Rational& y) {
    const auto obj = pl.locate(Traits::Point_2(x, y));
    const Arr::Face_const_handle* f = boost::get<Arr::Face_const_handle>(&obj);
    REQUIRE(f != nullptr);
    return *f;
  };
  const auto lens = face_of(Rational(1, 2), 0), left = face_of(Rational(-1, 2), 0), right = face_of(Rational(3, 2), 0);
  const auto out = face_of(5, 5);
  CHECK(out->is_unbounded());
  CHECK(!lens->is_unbounded());
  CHECK(lens != left);
  CHECK(lens != right);
  CHECK(left != right);
  CHECK(face_of(Rational(1, 2), Rational(1, 3)) == lens);
  // (1/2, 9/10) lies outside both circles (x^2 + y^2 = (x-1)^2 + y^2 = 1.06): the unbounded face.
  CHECK(face_of(Rational(1, 2), Rational(9, 10)) == out);
  // (1/2, 17/20): 0.9725 < 1 inside both: the lens, close to the irrational vertex (1/2, 0.866...)
  CHECK(face_of(Rational(1, 2), Rational(17, 20)) == lens);
}

TEST_CASE("arrangement traits: vertical tangents and segments traversed back and forth", "[arrangement]") {
  // x(t) of (3,0),(1,3),(4,3),(0,4) has x'(t) = -6 (6t^2 - 5t + 1): vertical tangents at t = 1/3 and 1/2, three
  // x-monotone pieces (CGAL 5.5's Bezier traits returns 3/2/1 here: it misses one of the two tangents).
  check({poly({{3, 0}, {1, 3}, {4, 3}, {0, 4}})}, 4, 3, 1);
  check({poly({{4, 1}, {3, 2}, {5, 4}, {2, 3}})}, 4, 3, 1);  // tangents at t = 1/4, 1/2
  // (0,0),(2,0),(1,0): x = 4t - 3t^2 turns at t = 2/3 (x = 4/3) and ends at x = 1: vertices 0, 1, 4/3.
  const Curve back = poly({{0, 0}, {2, 0}, {1, 0}});
  check({back}, 3, 2, 1);
  check({back, poly({{Rational(1, 2), -1}, {Rational(1, 2), 1}})}, 6, 5, 1);
  // the same on a vertical line
  check({poly({{0, 0}, {0, 2}, {0, 1}}), poly({{-1, Rational(1, 2)}, {1, Rational(1, 2)}})}, 6, 5, 1);
  // (0,0),(3,0),(0,0),(1,0): x' = 3 (10t^2 - 12t + 3), irrational turning points t = (6 +- sqrt 6)/10 at
  // x ~ 1.374 and ~ 0.786; with the ends 0 and 1: four vertices on the segment [0, 1.374].
  check({poly({{0, 0}, {3, 0}, {0, 0}, {1, 0}})}, 4, 3, 1);
}

TEST_CASE("arrangement traits: degenerate rational inputs on a small grid, sweep vs zone insertion", "[arrangement]") {
  // 6-10 curves of degree 1-3 with control points on the grid [0,5)^2 and weights 1-3: shared end points,
  // overlaps, tangencies, points, segments traversed back and forth. Aggregated insertion (sweep) and
  // incremental insertion (zone construction) are different CGAL algorithms: both must give a valid
  // arrangement with the same V/E/F.
  for (unsigned seed = 1; seed <= 24; ++seed) {
    std::mt19937 g(seed);
    std::vector<Curve> cs;
    const int n = 6 + int(g() % 5);
    for (int i = 0; i < n; ++i) {
      const int deg = 1 + int(g() % 3);
      std::vector<Pt> p;
      std::vector<Rational> w;
      for (int j = 0; j <= deg; ++j) {
        const long x = long(g() % 5), y = long(g() % 5);
        p.push_back(Pt{Rational(x), Rational(y)});
        w.push_back(Rational(long(1 + g() % 3)));
      }
      cs.push_back(Curve(p, w));
    }
    INFO("seed " << seed);
    const Counts a = counts_of(cs), b = counts_of(cs, true);
    CHECK(a.valid);
    CHECK(b.valid);
    CHECK(a.v == b.v);
    CHECK(a.e == b.e);
    CHECK(a.f == b.f);
    CHECK(a.iso == b.iso);
  }
}

TEST_CASE("arrangement traits: invalid input is rejected", "[arrangement]") {
  Traits tr;
  Arr arr(&tr);
  const Curve neg({Pt{0, 0}, Pt{1, 1}, Pt{2, 0}}, {Rational(1), Rational(-1), Rational(1)});
  CHECK_THROWS_AS(CGAL::insert(arr, neg), Invalid_input);
}

TEST_CASE("arrangement traits: a curve reduced to a point is an isolated vertex", "[arrangement]") {
  // inside the arch (0,0),(1,2),(2,0) closed by its chord, and one on the chord itself
  const Curve arch = poly({{0, 0}, {1, 2}, {2, 0}}), chord = poly({{0, 0}, {2, 0}});
  const Curve inside({Pt{1, Rational(1, 2)}, Pt{1, Rational(1, 2)}, Pt{1, Rational(1, 2)}});
  const Counts c = counts_of({arch, chord, inside});
  CHECK(c.valid);
  CHECK(c.v == 3);
  CHECK(c.iso == 1);
  CHECK(c.e == 2);
  CHECK(c.f == 2);
  const Counts d = counts_of({arch, chord, poly({{1, 0}, {1, 0}})});
  CHECK(d.valid);
  CHECK(d.v == 3);  // the point splits the chord
  CHECK(d.iso == 0);
  CHECK(d.e == 3);
  CHECK(d.f == 2);
}

namespace {

// CGAL's own Bezier traits (polynomial curves only), as in CGAL's Bezier arrangement example.
using Nt_traits = CGAL::CORE_algebraic_number_traits;
using Cgal_rational = Nt_traits::Rational;
using Rat_kernel = CGAL::Cartesian<Cgal_rational>;
using Alg_kernel = CGAL::Cartesian<Nt_traits::Algebraic>;
using Cgal_traits = CGAL::Arr_Bezier_curve_traits_2<Rat_kernel, Alg_kernel, Nt_traits>;
using Cgal_arr = CGAL::Arrangement_2<Cgal_traits>;

// n random polynomial curves of the given degree, integer control points in [0, 1000)^2 (raw mt19937 output,
// reproducible everywhere).
std::vector<std::vector<std::pair<long, long>>> random_nets(unsigned seed, int n, int degree) {
  std::mt19937 g(seed);
  std::vector<std::vector<std::pair<long, long>>> nets;
  for (int i = 0; i < n; ++i) {
    std::vector<std::pair<long, long>> net;
    for (int j = 0; j <= degree; ++j) {
      const long x = long(g() % 1000), y = long(g() % 1000);
      net.push_back({x, y});
    }
    nets.push_back(net);
  }
  return nets;
}

}  // namespace

TEST_CASE("arrangement traits: same V/E/F as CGAL's Bezier traits on random cubics", "[arrangement][cgal]") {
  for (unsigned seed : {1u, 2u, 3u}) {
    const auto nets = random_nets(seed, 6, 3);
    std::vector<Curve> ours;
    std::vector<Cgal_traits::Curve_2> theirs;
    for (const auto& net : nets) {
      std::vector<Pt> p;
      std::vector<Rat_kernel::Point_2> q;
      for (const auto& c : net) {
        p.push_back(Pt{Rational(c.first), Rational(c.second)});
        q.push_back(Rat_kernel::Point_2(Cgal_rational(c.first), Cgal_rational(c.second)));
      }
      ours.push_back(Curve(p));
      theirs.push_back(Cgal_traits::Curve_2(q.begin(), q.end()));
    }
    const Counts a = counts_of(ours);
    Cgal_traits ctr;
    Cgal_arr carr(&ctr);
    CGAL::insert(carr, theirs.begin(), theirs.end());
    INFO("seed " << seed);
    CHECK(a.valid);
    CHECK(a.v == carr.number_of_vertices());
    CHECK(a.e == carr.number_of_edges());
    CHECK(a.f == carr.number_of_faces());
    CHECK(a.iso == carr.number_of_isolated_vertices());
    // incremental insertion gives the same arrangement
    const Counts b = counts_of(ours, true);
    CHECK(b.valid);
    CHECK(b.v == a.v);
    CHECK(b.e == a.e);
    CHECK(b.f == a.f);
  }
}

TEST_CASE("arrangement traits: Boolean operations on discs bounded by rational arcs", "[arrangement][gps]") {
  using Gps_traits = CGAL::Gps_traits_2<Traits>;
  using Polygon = Gps_traits::Polygon_2;
  using Pwh = Gps_traits::Polygon_with_holes_2;
  Traits tr;
  auto disc = [&](const Rational& cx, const Rational& cy, const Rational& r) {
    std::vector<Traits::X_monotone_curve_2> xs;
    for (const Curve& c : circle(cx, cy, r)) {
      std::vector<boost::variant<Traits::Point_2, Traits::X_monotone_curve_2>> out;
      tr.make_x_monotone_2_object()(c, std::back_inserter(out));
      for (const auto& o : out) xs.push_back(boost::get<Traits::X_monotone_curve_2>(o));
    }
    return Polygon(xs.begin(), xs.end());
  };
  const Polygon a = disc(0, 0, 1), b = disc(1, 0, 1), small = disc(Rational(1, 2), 0, Rational(1, 5));
  CHECK(a.size() == 4);
  CHECK(a.orientation() == CGAL::COUNTERCLOCKWISE);
  // The lens: an arc of each circle between (1/2, +-sqrt 3/2), each split at the quarter point (1,0) resp. (0,0).
  std::list<Pwh> r;
  CGAL::intersection(a, b, std::back_inserter(r));
  REQUIRE(r.size() == 1);
  CHECK(r.front().outer_boundary().size() == 4);
  CHECK(r.front().number_of_holes() == 0);
  // The union: the other 3 quarter points of each circle remain vertices: 4 + 4 arcs.
  Pwh u;
  CHECK(CGAL::join(a, b, u));
  CHECK(u.outer_boundary().size() == 8);
  CHECK(u.number_of_holes() == 0);
  // a - b: 4 arcs of a and the 2 arcs of b inside a.
  r.clear();
  CGAL::difference(a, b, std::back_inserter(r));
  REQUIRE(r.size() == 1);
  CHECK(r.front().outer_boundary().size() == 6);
  // a minus a small disc inside: one hole of 4 arcs.
  r.clear();
  CGAL::difference(a, small, std::back_inserter(r));
  REQUIRE(r.size() == 1);
  CHECK(r.front().number_of_holes() == 1);
  CHECK(r.front().holes_begin()->size() == 4);
  CHECK(CGAL::do_intersect(a, b));
  CHECK(!CGAL::do_intersect(small, disc(3, 0, 1)));
}

// ------------------------------------------------------------------ interval solvers and lazy exact parameters

TEST_CASE("arrangement traits: interval solver boxes hold exactly the intersections of intersect_curves", "[arrangement]") {
  // seeded random polynomial cubics and quintics; every pair the interval solver decides must give one box per
  // exact intersection of the (independent) elimination engine, each exact point in exactly one box
  std::mt19937 g(7);
  int decided = 0, points = 0;
  for (int degree : {3, 5}) {
    std::vector<std::shared_ptr<const internal::Arr_bezier_supporting_curve>> cs;
    for (int i = 0; i < 8; ++i) {
      std::vector<Pt> p;
      for (int j = 0; j <= degree; ++j) p.push_back(Pt{Rational(long(g() % 1000)), Rational(long(g() % 1000))});
      cs.push_back(internal::make_supporting_curve(Curve(p)));
    }
    for (std::size_t i = 0; i < cs.size(); ++i)
      for (std::size_t j = i + 1; j < cs.size(); ++j) {
        internal::Arr_interval_solver solver{*cs[i], *cs[j], {}};
        solver.run(cs[i]->inet, 0, 1, cs[j]->inet, 0, 1, 0);
        if (solver.failed) continue;
        ++decided;
        const auto exact = intersect_curves(cs[i]->curve, cs[j]->curve);
        INFO("degree " << degree << " pair " << i << " " << j);
        REQUIRE(solver.found.size() == exact.points.size());
        for (const auto& e : exact.points) {
          int inside = 0;
          for (const auto& b : solver.found)
            if (e.s.compare(Rational(b[0])) >= 0 && e.s.compare(Rational(b[1])) <= 0 && e.t.compare(Rational(b[2])) >= 0 &&
                e.t.compare(Rational(b[3])) <= 0)
              ++inside;
          CHECK(inside == 1);
          ++points;
        }
      }
  }
  CHECK(decided > 40);  // of 56 pairs: transversal random crossings are decided without elimination
  CHECK(points > 40);
  // chains: cubics sharing end points (corner, smooth joint, both ends shared); common end points are exact
  // contacts, the other intersections boxes, together exactly the points of intersect_curves
  const std::vector<std::pair<Curve, Curve>> chains{
      {poly({{0, 0}, {1, 2}, {2, -1}, {3, 1}}), poly({{3, 1}, {4, 3}, {1, 2}, {0, 3}})},                // corner
      {poly({{0, 0}, {1, 1}, {2, 1}, {3, 0}}), poly({{3, 0}, {4, -1}, {5, 2}, {1, Rational(1, 3)}})},    // G1 joint
      {poly({{0, 0}, {1, 2}, {2, 2}, {3, 0}}), poly({{3, 0}, {2, -2}, {1, -2}, {0, 0}})},                // closed
      {poly({{0, 0}, {4, 1}, {0, 2}}), poly({{0, 0}, {-1, 3}, {3, 1}, {1, -1}})}};                       // start/start
  int contacts = 0;
  for (const auto& ch : chains) {
    const auto a = internal::make_supporting_curve(ch.first), b = internal::make_supporting_curve(ch.second);
    internal::Arr_interval_solver solver{*a, *b, {}};
    solver.run(a->inet, 0, 1, b->inet, 0, 1, 0);
    const auto exact = intersect_curves(ch.first, ch.second);
    if (solver.failed) continue;
    CHECK(solver.found.size() + solver.contacts.size() == exact.points.size());
    for (const auto& c : solver.contacts) {
      bool in_exact = false;
      for (const auto& e : exact.points)
        if (e.s == Algebraic_real(c[0]) && e.t == Algebraic_real(c[1])) in_exact = true;
      CHECK(in_exact);
      ++contacts;
    }
  }
  CHECK(contacts >= 3);
}

TEST_CASE("arrangement traits: self-intersections by interval subdivision, simplicity test", "[arrangement]") {
  // Symmetric cubic (0,0), (4,2), (-1,2), (3,0): y(t) = 6t(1-t), x(t) = 12t - 27t^2 + 18t^3, so C(s) = C(t), s < t,
  // needs t = 1 - s and x(s) = 3/2: 12s^3 - 18s^2 + 8s - 1 = (2s - 1)(6s^2 - 6s + 1), s = (3 - sqrt 3)/6.
  const Curve loop = poly({{0, 0}, {4, 2}, {-1, 2}, {3, 0}});
  const auto s = internal::make_supporting_curve(loop);
  CHECK_FALSE(s->simple);
  internal::Arr_self_interval_solver solver{*s, {}};
  solver.run(s->inet, 0, 1, s->inet, 0, 1, 0);
  REQUIRE_FALSE(solver.failed);
  REQUIRE(solver.found.size() == 1);
  const double s0 = (3 - std::sqrt(3.0)) / 6, t0 = (3 + std::sqrt(3.0)) / 6;
  CHECK(solver.found[0][0] <= s0 + 1e-12);
  CHECK(solver.found[0][1] >= s0 - 1e-12);
  CHECK(solver.found[0][2] <= t0 + 1e-12);
  CHECK(solver.found[0][3] >= t0 - 1e-12);
  CHECK(solver.found[0][1] - solver.found[0][0] < 1e-9);
  // x-extrema at t = 1/3, 2/3 (x' = 12 - 54t + 54t^2): 5 vertices, 5 edges, the loop's face and the unbounded one
  check({loop}, 5, 5, 2);
  // closed teardrop (0,0), (2,3), (-2,3), (0,0): x = 6t(1-t)(1-2t), y = 9t(1-t); C(s) = C(t), s < t, needs
  // t = 1 - s and x(s) = 0: only (0, 1), the common end point. x-extrema at t = (3 -+ sqrt 3)/6: V/E/F 3/3/2.
  const Curve drop = poly({{0, 0}, {2, 3}, {-2, 3}, {0, 0}});
  const auto sd = internal::make_supporting_curve(drop);
  internal::Arr_self_interval_solver ds{*sd, {}};
  ds.run(sd->inet, 0, 1, sd->inet, 0, 1, 0);
  CHECK(ds.closed);
  CHECK_FALSE(ds.failed);
  CHECK(ds.found.empty());
  CHECK(self_intersections(drop).points.size() == 1);
  check({drop}, 3, 3, 2);
  // random cubics: proved simple => self_intersections finds nothing; otherwise the solver agrees with it
  std::mt19937 g(11);
  int simple = 0, compared = 0;
  for (int i = 0; i < 30; ++i) {
    std::vector<Pt> p;
    for (int j = 0; j <= 3; ++j) p.push_back(Pt{Rational(long(g() % 1000)), Rational(long(g() % 1000))});
    const Curve c(p);
    const auto sc = internal::make_supporting_curve(c);
    const auto exact = self_intersections(c);
    if (sc->simple) {
      ++simple;
      CHECK(exact.points.empty());
      continue;
    }
    internal::Arr_self_interval_solver ss{*sc, {}};
    ss.run(sc->inet, 0, 1, sc->inet, 0, 1, 0);
    if (ss.failed) continue;
    ++compared;
    CHECK(ss.found.size() == exact.points.size());
  }
  CHECK(simple > 0);
  CHECK(compared > 0);
}

TEST_CASE("arrangement traits: several crossings at one point (lazy parameters made exact)", "[arrangement]") {
  // segments through (1,1): the pairwise crossings are found as separate interval boxes and identified exactly
  const Curve a = poly({{0, 0}, {2, 2}}), b = poly({{0, 2}, {2, 0}}), c = poly({{0, Rational(1, 2)}, {2, Rational(3, 2)}});
  check({a, b, c}, 7, 6, 1);
  // and a cubic through (1,1) at t = 1/2, crossing the segments only there (slope -4/3 at the point; control
  // points (0,5/3), (1/2,5/3), (3/2,1/3), (2,1/3): y decreases, the segments' y - 1 changes sign only at x = 1)
  const Curve d = poly({{0, Rational(5, 3)}, {Rational(1, 2), Rational(5, 3)}, {Rational(3, 2), Rational(1, 3)}, {2, Rational(1, 3)}});
  check({a, c, d}, 7, 6, 1);
}

TEST_CASE("arrangement traits: landmark point location agrees with naive point location", "[arrangement]") {
  // two crossing circles and four random cubics; landmarks on a grid (rational points); every query on a grid of
  // rational points (including points on the circles' axis and near vertices) gets the same face / edge / vertex
  // from CGAL's landmark point location (walks along our segments) as from the naive one
  std::vector<Curve> cs = circle(0, 0, 1), b = circle(1, 0, 1);
  cs.insert(cs.end(), b.begin(), b.end());
  std::mt19937 g(3);
  for (int i = 0; i < 4; ++i) {
    std::vector<Pt> p;
    for (int j = 0; j <= 3; ++j) p.push_back(Pt{Rational(int(g() % 400) - 150, 100), Rational(int(g() % 300) - 150, 100)});
    cs.push_back(Curve(p));
  }
  Traits tr;
  Arr arr(&tr);
  CGAL::insert(arr, cs.begin(), cs.end());
  REQUIRE(arr.is_valid());
  CGAL::Arr_naive_point_location<Arr> naive(arr);
  using Grid = CGAL::Arr_grid_landmarks_generator<Arr>;
  CGAL::Arr_landmarks_point_location<Arr, Grid> landmarks(arr);
  int faces = 0, others = 0;
  for (int i = -8; i <= 12; ++i)
    for (int j = -8; j <= 8; ++j) {
      const Traits::Point_2 q(Rational(i, 4), Rational(j, 5));
      const auto a = naive.locate(q), c = landmarks.locate(q);
      INFO("query " << i << "/4, " << j << "/5");
      if (const Arr::Face_const_handle* f = boost::get<Arr::Face_const_handle>(&a)) {
        const Arr::Face_const_handle* h = boost::get<Arr::Face_const_handle>(&c);
        REQUIRE(h != nullptr);
        CHECK(*h == *f);
        ++faces;
      } else if (const Arr::Halfedge_const_handle* e = boost::get<Arr::Halfedge_const_handle>(&a)) {
        const Arr::Halfedge_const_handle* h = boost::get<Arr::Halfedge_const_handle>(&c);
        REQUIRE(h != nullptr);
        CHECK((*h == *e || *h == (*e)->twin()));
        ++others;
      } else {
        const Arr::Vertex_const_handle* v = boost::get<Arr::Vertex_const_handle>(&a);
        const Arr::Vertex_const_handle* h = boost::get<Arr::Vertex_const_handle>(&c);
        REQUIRE(v != nullptr);
        REQUIRE(h != nullptr);
        CHECK(*h == *v);
        ++others;
      }
    }
  CHECK(faces > 100);
  CHECK(others > 0);  // (0, 1), (1, 1), (1, 0), ... lie on the circles
}

// CGAL's own Bezier example data (Debian package libcgal-demo, examples.tar.gz, installed by
// scripts/install-dependencies.sh): the same V/E/F as CGAL's Arr_Bezier_curve_traits_2 on the same file.
TEST_CASE("arrangement traits: same V/E/F as CGAL's Bezier traits on CGAL's Bezier.dat", "[arrangement][cgal]") {
  const char* archive = "/usr/share/doc/libcgal-dev/examples.tar.gz";
  const std::string command =
      std::string("tar -xzOf ") + archive + " examples/Arrangement_on_surface_2/Bezier.dat 2>/dev/null";
  std::string text;
  if (FILE* f = popen(command.c_str(), "r")) {
    char buffer[4096];
    std::size_t n;
    while ((n = fread(buffer, 1, sizeof buffer, f)) > 0) text.append(buffer, n);
    pclose(f);
  }
  INFO("CGAL's Bezier.dat from " << archive << " (package libcgal-demo)");
  REQUIRE_FALSE(text.empty());
  const auto doc = bezoutian::io::read_dat(text, "Bezier.dat");
  REQUIRE(doc.curves_2.size() == 10);  // the file lists 10 curves
  const Counts a = counts_of(doc.curves_2);
  std::istringstream in(text);
  std::size_t n = 0;
  in >> n;
  std::vector<Cgal_traits::Curve_2> theirs(n);
  for (auto& c : theirs) in >> c;
  REQUIRE(n == doc.curves_2.size());
  Cgal_traits ctr;
  Cgal_arr carr(&ctr);
  CGAL::insert(carr, theirs.begin(), theirs.end());
  CHECK(a.valid);
  CHECK(carr.is_valid());
  CHECK(a.v == carr.number_of_vertices());
  CHECK(a.e == carr.number_of_edges());
  CHECK(a.f == carr.number_of_faces());
  CHECK(a.iso == carr.number_of_isolated_vertices());
}
