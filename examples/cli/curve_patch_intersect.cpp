// bezoutian intersect for a space curve (or segment) and a patch: certified curve/patch intersection
// (include/bezoutian/intersection/Curve_surface_intersection.h, du-1989 Problems 2.2a/2.2b).
#include "commands.h"
#include "exact_json.h"
#include "load.h"

#include <bezoutian/intersection/Curve_surface_intersection.h>
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

using bezoutian_cli::exact;
using bezoutian_cli::exact_or_decimal;
using bezoutian_cli::algebraic;
using bezoutian_cli::envelope;

// C(r) to 30 significant digits: C evaluated exactly at a rational within 2^-200 of r.
std::vector<std::string> point(const bezoutian::Rational_bezier_curve_3<>& c, const Algebraic_real& r) {
  Rational x;
  if (r.is_rational()) {
    x = r.rational_value();
  } else {
    Rational w(1);
    for (int i = 0; i < 200; ++i) w /= 2;
    r.refine_to_width(w);
    x = r.lower();
  }
  std::vector<std::string> p;
  for (const Rational& v : c(x)) p.push_back(Algebraic_real(v).to_decimal_string(bezoutian_cli::algebraic_digits));
  return p;
}

}  // namespace

namespace bezoutian_cli {

/// The curve is the first space curve and the patch the first patch found in FILE_A, then FILE_B.
void run_curve_patch_intersect(const Intersect_options& o) {
  std::vector<bezoutian::Rational_bezier_curve_3<>> curves;
  std::vector<bezoutian::Rational_bezier_patch<>> patches;
  for (const std::string& path : {o.file_a, o.file_b}) {
    if (path.empty()) continue;
    Loaded_file f = load_and_validate(path);
    for (const auto& w : f.warnings) std::cerr << "warning: " << w << "\n";
    curves.insert(curves.end(), f.doc.curves_3.begin(), f.doc.curves_3.end());
    patches.insert(patches.end(), f.doc.patches.begin(), f.doc.patches.end());
  }
  if (curves.empty() || patches.empty())
    throw bezoutian::Invalid_input("curve/patch intersection needs a space curve and a patch (planar curves cannot "
                                   "meet a patch in 3D)");
  if (o.method != "default")
    throw bezoutian::Invalid_input("curve/patch intersection has only the default method");
  const auto& c = curves.front();
  const auto t0 = std::chrono::steady_clock::now();
  const bezoutian::Curve_patch_intersection_result r =
      bezoutian::intersect_curve_patch(c, patches.front(), intersection_limits(o));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (o.json) {
    nlohmann::json j = envelope("intersect");
    j["problem"] = "curve/patch";
    j["method"] = "default";
    nlohmann::json pts = nlohmann::json::array();
    for (const auto& p : r.points) {
      nlohmann::json q;
      q["s"] = algebraic(p.r);  // the curve's parameter
      q["u"] = algebraic(p.u);
      q["v"] = algebraic(p.v);
      q["point"] = point(c, p.r);
      q["multiplicity"] = p.multiplicity;
      q["kind"] = bezoutian::to_string(p.kind);
      q["tangent"] = p.tangent;
      // a collapsed line of the patch through the point: all of u = const ("u") or v = const ("v") are preimages
      if (p.collapsed_line >= 0) q["collapsed_line"] = p.collapsed_line == 0 ? "u" : "v";
      pts.push_back(q);
    }
    j["intersections"] = pts;
    nlohmann::json ov = nlohmann::json::array();
    for (const auto& v : r.overlaps) ov.push_back({{"s", {algebraic(v.r0), algebraic(v.r1)}}});
    j["overlaps"] = ov;
    j["seconds"] = seconds;
    std::cout << j.dump(1) << "\n";
    return;
  }
  std::cout << r.points.size() << " intersection" << (r.points.size() == 1 ? "" : "s") << ", " << r.overlaps.size()
            << " overlap" << (r.overlaps.size() == 1 ? "" : "s") << " (curve/patch, " << seconds << " s)\n";
  for (const auto& p : r.points) {
    std::cout << "  s = " << p.r.to_decimal_string(30) << (p.r.is_rational() ? " (= " + exact(p.r.rational_value()) + ")" : "")
              << "\n  u = " << p.u.to_decimal_string(30) << (p.u.is_rational() ? " (= " + exact(p.u.rational_value()) + ")" : "")
              << "\n  v = " << p.v.to_decimal_string(30) << (p.v.is_rational() ? " (= " + exact(p.v.rational_value()) + ")" : "")
              << "\n  point (";
    const auto q = point(c, p.r);
    for (std::size_t k = 0; k < q.size(); ++k) std::cout << (k ? ", " : "") << q[k];
    std::cout << "), " << bezoutian::to_string(p.kind) << ", multiplicity " << p.multiplicity;
    if (p.collapsed_line >= 0)
      std::cout << ", collapsed line: every (" << (p.collapsed_line == 0 ? "u, v'" : "u', v") << ") with "
                << (p.collapsed_line == 0 ? "v'" : "u'") << " in [0,1] is a preimage";
    std::cout << "\n";
  }
  for (const auto& v : r.overlaps)
    std::cout << "  overlap: s in [" << exact_or_decimal(v.r0) << ", " << exact_or_decimal(v.r1) << "]\n";
}

}  // namespace bezoutian_cli
