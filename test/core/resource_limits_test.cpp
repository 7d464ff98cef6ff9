// Resource limits of the intersection computations (Intersection_limits) and of the file readers
// (io::max_object_degree): each hostile input ends with its documented error, naming the stage and the limit, within
// a stated bound (doc/hostile_input.md, "Hostile inputs and limits").
#include <catch2/catch.hpp>

#include <bezoutian/intersection/Curve_intersection.h>
#include <bezoutian/intersection/Curve_surface_intersection.h>
#include <bezoutian/geometry/Curve_problem_generator.h>
#include <bezoutian/io/Geometry_document.h>

#include <chrono>
#include <functional>
#include <random>
#include <string>
#include <vector>

using namespace bezoutian;
using Curve2 = Rational_bezier_curve_2<>;
using Curve3 = Rational_bezier_curve_3<>;

namespace {

// A plane polynomial curve of degree n with random integer control points in [-50, 50].
Curve2 random_curve(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> c(-50, 50);
  std::vector<Curve2::Point> p(std::size_t(n) + 1);
  for (auto& q : p) q = {Rational(c(rng)), Rational(c(rng))};
  return Curve2(p);
}

Curve2 line() { return Curve2(std::vector<Curve2::Point>{{Rational(-40), Rational(-40)}, {Rational(40), Rational(40)}}); }

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Runs f, which must throw Limit_exceeded with the given limit and stage; returns its message; checks the time bound.
std::string expect_limit(const std::function<void()>& f, const std::string& limit, const std::string& stage,
                         double bound_seconds) {
  const auto t0 = std::chrono::steady_clock::now();
  std::string what;
  try {
    f();
    FAIL("no Limit_exceeded thrown (limit " << limit << ")");
  } catch (const Limit_exceeded& e) {
    CHECK(e.limit() == limit);
    CHECK(e.stage() == stage);
    what = e.what();
  }
  CHECK(seconds_since(t0) < bound_seconds);
  return what;
}

}  // namespace

TEST_CASE("limits: a degree-200 curve and a degree-1000 curve against a line are refused at once",
          "[limits]") {
  const Curve2 c200 = random_curve(200, 200), other = random_curve(200, 201), c1000 = random_curve(1000, 1000);
  std::string w = expect_limit([&] { intersect_curves(c200, other); }, "max_degree", "input", 1.0);
  CHECK(w == "intersect_curves: max_degree exceeded in input: curve 1 has degree 200, more than max_degree = 64");
  w = expect_limit([&] { intersect_curves(c1000, line()); }, "max_degree", "input", 1.0);
  CHECK(w.find("curve 1 has degree 1000") != std::string::npos);
  w = expect_limit([&] { intersect_curves(line(), c1000); }, "max_degree", "input", 1.0);
  CHECK(w.find("curve 2 has degree 1000") != std::string::npos);
  expect_limit([&] { self_intersections(c200); }, "max_degree", "input", 1.0);
  // every method, the functor, and Budget_exceeded / Limit_exceeded are Errors
  for (auto m : {Curve_intersection_method::subresultant, Curve_intersection_method::projection,
                 Curve_intersection_method::groebner})
    expect_limit([&] { intersect_curves(c200, line(), m); }, "max_degree", "input", 1.0);
  expect_limit([&] { Intersect_curves()(c1000, line()); }, "max_degree", "input", 1.0);
  CHECK_THROWS_AS(intersect_curves(c200, other), Error);
}

TEST_CASE("limits: a curve with 100,000 control points is refused before its power form is computed", "[limits]") {
  std::vector<Curve2::Point> p(100000);
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = {Rational(long(i % 7)), Rational(long(i % 5))};
  const Curve2 big(p);
  const std::string w = expect_limit([&] { intersect_curves(big, line()); }, "max_control_points", "input", 1.0);
  CHECK(w == "intersect_curves: max_control_points exceeded in input: curve 1 has 100000 control points, more than "
             "max_control_points = 4225");
}

TEST_CASE("limits: degree product, coefficient bits, and limits raised or removed", "[limits]") {
  // two curves of degree 40: each below max_degree, their product 1600 above max_degree_product = 1024
  const Curve2 a = random_curve(40, 1), b = random_curve(40, 2);
  std::string w = expect_limit([&] { intersect_curves(a, b); }, "max_degree_product", "input", 1.0);
  CHECK(w.find("40 x 40 = 1600") != std::string::npos);
  // a coordinate 2^5000: above the 4096 bits that the readers accept too
  Rational huge(1);
  for (int i = 0; i < 5000; ++i) huge *= 2;
  const Curve2 q(std::vector<Curve2::Point>{{Rational(1), Rational(0)}, {huge, Rational(1)}, {Rational(2), Rational(3)}});
  w = expect_limit([&] { intersect_curves(q, line()); }, "max_coefficient_bits", "input", 1.0);
  CHECK(w.find("5001 bits") != std::string::npos);
  // limits are options: a cubic refused with max_degree = 2, answered with the defaults and without limits
  const Curve2 cubic(std::vector<Curve2::Point>{
      {Rational(0), Rational(0)}, {Rational(1), Rational(2)}, {Rational(2), Rational(-2)}, {Rational(3), Rational(0)}});
  const Curve2 axis(std::vector<Curve2::Point>{{Rational(-1), Rational(0)}, {Rational(4), Rational(0)}});
  Curve_intersection_options o;
  o.limits.max_degree = 2;
  expect_limit([&] { intersect_curves(cubic, axis, o); }, "max_degree", "input", 1.0);
  o.limits = Intersection_limits::none();
  const auto r = intersect_curves(cubic, axis, o);
  CHECK(r.points.size() == 3);  // x(t) = 3t, y(t) = 6t(1-t)(1-2t): t = 0, 1/2, 1
  CHECK(intersect_curves(cubic, axis).points.size() == 3);
  Intersect_curves f;
  f.limits.max_control_points = 3;
  expect_limit([&] { f(cubic, axis); }, "max_control_points", "input", 1.0);
  // self-intersections: the degree product is deg C x deg C
  Curve_intersection_options s;
  s.limits.max_degree_product = 8;
  expect_limit([&] { self_intersections(cubic, s); }, "max_degree_product", "input", 1.0);
}

TEST_CASE("limits: the time budget ends the computation with Budget_exceeded naming the stage", "[limits]") {
  Curve_problem_parameters par;
  par.degree_1 = 6, par.degree_2 = 6, par.intersections = 3, par.seed = 5;
  const auto pb = generate_curve_problem<2>(par);
  Curve_intersection_options o;
  o.limits.time_limit = 1e-9;  // exhausted at the first check
  const auto t0 = std::chrono::steady_clock::now();
  try {
    intersect_curves(pb.curve_1, pb.curve_2, o);
    FAIL("no Budget_exceeded");
  } catch (const Budget_exceeded& e) {
    CHECK(e.limit() == "time_limit");
    CHECK(e.stage() == "power forms");
    CHECK(std::string(e.what()).find("intersect_curves: time_limit exceeded in power forms: ") == 0);
  }
  CHECK(seconds_since(t0) < 1.0);
  // the subresultant method passes several checks: with a budget it ends at one of them (which one depends on the
  // machine's speed and load: any stage the path checks), or answers in time
  o.method = Curve_intersection_method::subresultant;
  o.limits.time_limit = 0.002;
  par.degree_1 = 6, par.degree_2 = 6, par.intersections = 4, par.rational = true, par.seed = 77;
  const auto big = generate_curve_problem<2>(par);
  const auto t1 = std::chrono::steady_clock::now();
  try {
    const auto r = intersect_curves(big.curve_1, big.curve_2, o);
    CHECK(r.points.size() >= 4);
  } catch (const Budget_exceeded& e) {
    const std::string st = e.stage();
    CHECK((st == "power forms" || st == "interval solver" || st == "exact default path" || st == "elimination" ||
           st == "root isolation" || st == "pairing" || st == "shear" || st == "overlaps"));
  }
  CHECK(seconds_since(t1) < 2.0);
  // without a budget the same problem is answered: every constructed intersection is found
  o.limits.time_limit = 0;
  const auto r = intersect_curves(big.curve_1, big.curve_2, o);
  for (const auto& st : big.known) {
    bool found = false;
    for (const auto& p : r.points) found = found || (p.s == st.first && p.t == st.second);
    CHECK(found);
  }
}

TEST_CASE("limits: curve/patch intersection checks the curve, the patch and 2 m n deg C", "[limits]") {
  // a bilinear patch and a segment through it
  Rational_bezier_patch<>::Net net(2, std::vector<Rational_bezier_patch<>::Homogeneous_point>(2));
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) net[std::size_t(i)][std::size_t(j)] = {Rational(1), Rational(i), Rational(j), Rational(i * j)};
  const auto patch = Rational_bezier_patch<>::from_homogeneous(net);
  const Curve3 seg(std::vector<Curve3::Point>{{Rational(1, 2), Rational(1, 2), Rational(-1)},
                                              {Rational(1, 2), Rational(1, 2), Rational(1)}});
  CHECK(intersect_curve_patch(seg, patch).points.size() == 1);  // (1/2, 1/2, 1/4) at r = 5/8
  Intersection_limits l;
  l.max_degree_product = 1;  // 2 x 1 x 1 x 1 = 2
  std::string w = expect_limit([&] { intersect_curve_patch(seg, patch, l); }, "max_degree_product", "input", 1.0);
  CHECK(w.find("2 m n deg C = 2 x 1 x 1 x 1 = 2") != std::string::npos);
  // a patch of bi-degree (65, 1)
  Rational_bezier_patch<>::Net tall(66, std::vector<Rational_bezier_patch<>::Homogeneous_point>(2));
  for (int i = 0; i <= 65; ++i)
    for (int j = 0; j < 2; ++j)
      tall[std::size_t(i)][std::size_t(j)] = {Rational(1), Rational(i), Rational(j), Rational((i * j) % 3)};
  const auto tall_patch = Rational_bezier_patch<>::from_homogeneous(tall);
  w = expect_limit([&] { intersect_curve_patch(seg, tall_patch); }, "max_degree", "input", 1.0);
  CHECK(w == "intersect_curve_patch: max_degree exceeded in input: the patch has degree 65, more than max_degree = 64");
  Intersect_curve_patch f;
  f.limits.max_control_points = 100;  // 66 x 2 = 132
  expect_limit([&] { f(seg, tall_patch); }, "max_control_points", "input", 1.0);
  l = Intersection_limits();
  l.time_limit = 1e-9;
  try {
    intersect_curve_patch(seg, patch, l);
    FAIL("no Budget_exceeded");
  } catch (const Budget_exceeded& e) {
    CHECK(e.stage() == "implicit matrix");
  }
}

TEST_CASE("readers: degrees and control point counts above io::max_object_degree are refused at file:line:column",
          "[limits][formats]") {
  // .dat: 100,000 control points, refused at the count before any number is read
  std::string dat = "1\n100000";
  for (int i = 0; i < 100000; ++i) dat += " " + std::to_string(i % 7) + " " + std::to_string(i % 5);
  auto t0 = std::chrono::steady_clock::now();
  try {
    io::read_dat(dat, "big.dat");
    FAIL("read");
  } catch (const Parse_error& e) {
    CHECK(e.line() == 2);
    CHECK(e.column() == 1);
    CHECK(std::string(e.what()) ==
          "big.dat:2:1: expected the number of control points of curve 0 of at most 1001 (the readers' limit "
          "io::max_object_degree = 1000), got 100000");
  }
  CHECK(seconds_since(t0) < 2.0);
  // a degree-1000 curve is read (info can describe it); the intersection refuses it
  std::string ok = "1\n1001";
  for (int i = 0; i < 1001; ++i) ok += " " + std::to_string(i % 7) + " " + std::to_string(i % 5);
  CHECK(io::read_dat(ok).curves_2.at(0).degree() == 1000);
  // .bpt: a patch of degree 1001 in u
  std::string bpt = "1\n1001 0\n";
  for (int i = 0; i < 1002; ++i) bpt += "0 0 0\n";
  try {
    io::read_bpt(bpt, "tall.bpt");
    FAIL("read");
  } catch (const Parse_error& e) {
    CHECK(e.line() == 2);
    CHECK(e.column() == 1);
    CHECK(std::string(e.what()).find("of at most 1000 (the readers' limit io::max_object_degree = 1000)") !=
          std::string::npos);
  }
  // JSON: 1002 control points (at the array), a degree key above the limit (at the key's value)
  std::string json = "{\"curve\": {\"points\": [";
  for (int i = 0; i < 1002; ++i) json += std::string(i ? ", " : "") + "[" + std::to_string(i % 7) + ", 1]";
  json += "]}}";
  try {
    io::read_json(json, "big.json");
    FAIL("read");
  } catch (const Parse_error& e) {
    CHECK(e.line() == 1);
    CHECK(e.column() == 22);
    CHECK(std::string(e.what()).find("expected at most 1001 control points (the readers' limit "
                                     "io::max_object_degree = 1000), got 1002") != std::string::npos);
  }
  CHECK_THROWS_AS(io::read_json("{\"curve\": {\"degree\": 5000, \"points\": [[0, 0]]}}", "d.json"), Parse_error);
  CHECK_THROWS_AS(io::read_json("{\"patch\": {\"degree\": [1, 2000], \"points\": [[[0, 0, 0]]]}}", "p.json"), Parse_error);
}
