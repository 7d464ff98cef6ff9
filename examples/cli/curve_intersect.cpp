// bezoutian intersect A [B] for curves: certified curve/curve intersection
// (include/bezoutian/intersection/Curve_intersection.h).
#include "commands.h"
#include "exact_json.h"
#include "load.h"

#include <bezoutian/intersection/Curve_intersection.h>
#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/io/Exact_number.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <iostream>
#include <string>
#include <vector>

namespace {

using bezoutian::Algebraic_real;
using bezoutian::Rational;

struct Curves {
  std::vector<bezoutian::Rational_bezier_curve_2<>> c2;
  std::vector<bezoutian::Rational_bezier_curve_3<>> c3;
  bool has_patches = false;
};

Curves load_curves(const std::string& path) {
  bezoutian_cli::Loaded_file f = bezoutian_cli::load_and_validate(path);
  for (const auto& w : f.warnings) std::cerr << "warning: " << w << "\n";
  return Curves{f.doc.curves_2, f.doc.curves_3, !f.doc.patches.empty()};
}

using bezoutian_cli::exact;
using bezoutian_cli::exact_or_decimal;
using bezoutian_cli::algebraic;

// Point C(s) to 30 significant digits: C evaluated exactly at a rational within 2^-200 of s (the printed digits are
// an approximation, the parameters are the exact answer).
template <class Curve>
nlohmann::json point(const Curve& c, const Algebraic_real& s) {
  Rational x;
  if (s.is_rational()) {
    x = s.rational_value();
  } else {
    Rational w(1);
    for (int i = 0; i < 200; ++i) w /= 2;
    s.refine_to_width(w);
    x = s.lower();
  }
  nlohmann::json p = nlohmann::json::array();
  for (const Rational& v : c(x)) p.push_back(Algebraic_real(v).to_decimal_string(bezoutian_cli::algebraic_digits));
  return p;
}

template <class Curve>
void report(const Curve& a, const Curve& b, const bezoutian::Curve_intersection_result& r, const std::string& method,
            double seconds, bool json) {
  if (json) {
    nlohmann::json j = bezoutian_cli::envelope("intersect");
    j["problem"] = "curve/curve";
    j["method"] = method;
    j["dimension"] = Curve::dimension;
    nlohmann::json pts = nlohmann::json::array();
    for (const auto& p : r.points) {
      nlohmann::json q;
      q["s"] = algebraic(p.s);
      q["t"] = algebraic(p.t);
      q["point"] = point(a, p.s);
      q["multiplicity"] = p.multiplicity;
      q["kind"] = bezoutian::to_string(p.kind);
      q["tangent"] = p.tangent;
      pts.push_back(q);
    }
    j["intersections"] = pts;
    nlohmann::json ov = nlohmann::json::array();
    for (const auto& o : r.overlaps)
      ov.push_back({{"s", {algebraic(o.s0), algebraic(o.s1)}}, {"t", {algebraic(o.t0), algebraic(o.t1)}}});
    j["overlaps"] = ov;
    j["seconds"] = seconds;
    std::cout << j.dump(1) << "\n";
    return;
  }
  (void)b;
  std::cout << r.points.size() << " intersection" << (r.points.size() == 1 ? "" : "s") << ", " << r.overlaps.size()
            << " overlap" << (r.overlaps.size() == 1 ? "" : "s") << " (method " << method << ", " << seconds
            << " s)\n";
  for (const auto& p : r.points) {
    std::cout << "  s = " << p.s.to_decimal_string(30) << (p.s.is_rational() ? " (= " + exact(p.s.rational_value()) + ")" : "")
              << "\n  t = " << p.t.to_decimal_string(30) << (p.t.is_rational() ? " (= " + exact(p.t.rational_value()) + ")" : "")
              << "\n  point (";
    const auto q = point(a, p.s);
    for (std::size_t k = 0; k < q.size(); ++k) std::cout << (k ? ", " : "") << q[k].template get<std::string>();
    std::cout << "), " << bezoutian::to_string(p.kind) << ", multiplicity " << p.multiplicity
              << (p.tangent ? ", tangent" : "") << "\n";
  }
  for (const auto& o : r.overlaps)
    std::cout << "  overlap: s in [" << exact_or_decimal(o.s0) << ", " << exact_or_decimal(o.s1) << "] <-> t from "
              << exact_or_decimal(o.t0) << " to " << exact_or_decimal(o.t1) << "\n";
}

template <class Curve>
void run(const Curve& a, const Curve& b, const bezoutian_cli::Intersect_options& o) {
  bezoutian::Curve_intersection_options options;
  options.method = bezoutian::curve_intersection_method_from_string(o.method);
  options.limits = bezoutian_cli::intersection_limits(o);
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = bezoutian::intersect_curves(a, b, options);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  report(a, b, r, o.method, s, o.json);
}

} // namespace

namespace bezoutian_cli {
bezoutian::Intersection_limits intersection_limits(const Intersect_options& o) {
  bezoutian::Intersection_limits l;
  l.max_degree = o.max_input_degree;
  l.max_control_points = o.max_control_points;
  l.max_degree_product = o.max_degree_product;
  l.max_coefficient_bits = o.max_coefficient_bits;
  l.time_limit = o.time_limit;
  return l;
}

void run_curve_intersect(const Intersect_options& o) {
  const Curves A = load_curves(o.file_a);
  Curves B;
  if (!o.file_b.empty()) B = load_curves(o.file_b);
  const bool patch_involved = A.has_patches || (!o.file_b.empty() && B.has_patches);
  if (patch_involved) {
    return run_curve_patch_intersect(o);
  }
  if (o.file_b.empty()) {
    if (A.c2.size() >= 2) return run(A.c2[0], A.c2[1], o);
    if (A.c3.size() >= 2) return run(A.c3[0], A.c3[1], o);
    throw bezoutian::Invalid_input(o.file_a + ": expected two curves of the same dimension (or give FILE_B)");
  }
  if (!A.c2.empty() && !B.c2.empty()) return run(A.c2[0], B.c2[0], o);
  if (!A.c3.empty() && !B.c3.empty()) return run(A.c3[0], B.c3[0], o);
  throw bezoutian::Invalid_input("expected a curve in each file, both planar or both spatial");
}
} // namespace bezoutian_cli
