// bezoutian arrangement FILE [--json] [--svg OUT.svg]: the arrangement of the planar curves of a file
// (our JSON or CGAL's Bezier .dat), computed by CGAL::Arrangement_2 with Arr_rational_bezier_traits_2.
#include "commands.h"
#include "exact_json.h"
#include "load.h"

#include <bezoutian/Arr_rational_bezier_traits_2.h>

#include <CGAL/Arrangement_2.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>

namespace {

using Traits = bezoutian::Arr_rational_bezier_traits_2;
using Arrangement = CGAL::Arrangement_2<Traits>;

void write_svg(const Arrangement& arr, const std::string& path) {
  std::vector<std::vector<std::pair<double, double>>> lines;
  double x0 = std::numeric_limits<double>::max(), y0 = x0, x1 = -x0, y1 = -x0;
  for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e) {
    lines.push_back(e->curve().polyline(48));
    for (const auto& p : lines.back()) {
      x0 = std::min(x0, p.first);
      x1 = std::max(x1, p.first);
      y0 = std::min(y0, p.second);
      y1 = std::max(y1, p.second);
    }
  }
  if (lines.empty()) x0 = y0 = 0, x1 = y1 = 1;
  const double w = std::max(x1 - x0, 1e-12), h = std::max(y1 - y0, 1e-12), m = 0.05 * std::max(w, h);
  const double scale = 800.0 / std::max(w, h);
  std::ofstream out(path);
  if (!out) throw bezoutian::Invalid_input("cannot write " + path);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << (w + 2 * m) * scale << "\" height=\"" << (h + 2 * m) * scale
      << "\" viewBox=\"" << x0 - m << " " << -(y1 + m) << " " << w + 2 * m << " " << h + 2 * m << "\">\n";
  const double sw = 1.5 / scale, r = 3.0 / scale;
  const char* colors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf"};
  std::size_t i = 0;
  for (const auto& l : lines) {
    out << "<polyline fill=\"none\" stroke=\"" << colors[i++ % 6] << "\" stroke-width=\"" << sw << "\" points=\"";
    for (const auto& p : l) out << p.first << "," << -p.second << " ";
    out << "\"/>\n";
  }
  for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v)
    out << "<circle cx=\"" << v->point().approximate_x() << "\" cy=\"" << -v->point().approximate_y() << "\" r=\"" << r
        << "\" fill=\"black\"/>\n";
  out << "</svg>\n";
}

void run_arrangement(const std::string& path, bool json, const std::string& svg) {
  bezoutian_cli::Loaded_file f = bezoutian_cli::load_and_validate(path);
  if (!f.doc.curves_3.empty() || !f.doc.patches.empty())
    throw bezoutian::Invalid_input(path + ": the arrangement command takes planar curves only");
  if (f.doc.curves_2.empty()) throw bezoutian::Invalid_input(path + ": no planar curves");
  const auto t0 = std::chrono::steady_clock::now();
  Traits traits;
  Arrangement arr(&traits);
  CGAL::insert(arr, f.doc.curves_2.begin(), f.doc.curves_2.end());
  const bool valid = arr.is_valid();
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (!svg.empty()) write_svg(arr, svg);
  if (json) {
    nlohmann::json j = bezoutian_cli::envelope("arrangement");
    j["curves"] = f.doc.curves_2.size();
    j["vertices"] = arr.number_of_vertices();
    j["edges"] = arr.number_of_edges();
    j["faces"] = arr.number_of_faces();
    j["isolated_vertices"] = arr.number_of_isolated_vertices();
    j["valid"] = valid;
    j["seconds"] = ms / 1000;
    j["warnings"] = f.warnings;
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout << path << ": " << f.doc.curves_2.size() << " curves\n"
            << "vertices: " << arr.number_of_vertices() << "\nedges: " << arr.number_of_edges()
            << "\nfaces: " << arr.number_of_faces() << " (including the unbounded face)\nisolated vertices: "
            << arr.number_of_isolated_vertices() << "\nvalid: " << (valid ? "yes" : "NO") << "\ntime: " << ms << " ms\n";
  for (const auto& w : f.warnings) std::cout << "warning: " << w << "\n";
}

bezoutian_cli::Register arrangement_registration([](CLI::App& app) {
  auto* sub = app.add_subcommand("arrangement", "Certified arrangement (CGAL::Arrangement_2) of planar rational Bezier curves");
  auto path = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  auto svg = std::make_shared<std::string>();
  sub->add_option("FILE", *path, "input file (.json or CGAL Bezier .dat)")->required();
  sub->add_flag("--json", *json, "machine-readable output: vertices, edges, faces, isolated_vertices, valid");
  sub->add_option("--svg", *svg, "draw the arrangement into this SVG file");
  sub->callback([path, json, svg] { run_arrangement(*path, *json, *svg); });
});

}  // namespace
