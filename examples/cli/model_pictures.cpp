// OBJ and SVG pictures of a model's intersections (examples/cli/model_pictures.h).
#include "model_pictures.h"

#include <bezoutian/arithmetic/Error.h>

#include <cstdio>
#include <fstream>
#include <map>

namespace bezoutian_cli {
namespace {

std::string problem_object(const bezoutian::Model_problem& p) {
  return p.self() ? "self_" + std::to_string(p.first) : "pair_" + std::to_string(p.first) + "_" + std::to_string(p.second);
}

// One polyline: its vertices, then an `l` line over them (`close`: back to the first).
void write_polyline(std::ofstream& s, const std::vector<std::array<double, 3>>& points, bool close, std::size_t& next) {
  if (points.size() < 2) return;
  const std::size_t first = next;
  for (const auto& p : points) {
    s << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
    ++next;
  }
  s << "l";
  for (std::size_t i = first; i < next; ++i) s << " " << i;
  if (close) s << " " << first;
  s << "\n";
}

}  // namespace

void write_model_obj(const std::string& path,
                     const std::vector<bezoutian::Rational_bezier_patch<bezoutian::Rational>>& patches,
                     const bezoutian::Model_intersection& R, const std::vector<bezoutian::Model_curve>& curves) {
  std::ofstream s(path);
  if (!s) throw bezoutian::Error("cannot write " + path);
  s.precision(17);
  std::size_t next = 1;  // OBJ vertices count from 1
  const int N = 16;
  for (std::size_t k = 0; k < patches.size(); ++k) {
    if (k < R.patch_errors.size() && !R.patch_errors[k].empty()) {
      s << "# " << R.patch_errors[k] << "\n";
      continue;
    }
    s << "o patch_" << k << "\n";
    for (int i = 0; i <= N; ++i)
      for (int j = 0; j <= N; ++j) {
        const auto p = patches[k].evaluate(double(i) / N, double(j) / N);
        s << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
      }
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) {
        const std::size_t a = next + std::size_t(i * (N + 1) + j), b = a + 1, c = a + (N + 1), d = c + 1;
        s << "f " << a << " " << c << " " << d << " " << b << "\n";
      }
    next += std::size_t((N + 1) * (N + 1));
  }
  for (const auto& p : R.problems) {
    bool any = false;
    for (const auto& a : p.locus.arcs)
      for (const auto& sh : a.sheets) any = any || sh.points.size() > 1;
    if (!any) continue;
    s << "o " << problem_object(p) << "\n";
    for (const auto& a : p.locus.arcs)
      for (const auto& sh : a.sheets) {
        std::vector<std::array<double, 3>> points;
        for (const auto& q : sh.points) points.push_back(q.point_3d);
        write_polyline(s, points, false, next);
      }
  }
  for (std::size_t k = 0; k < curves.size(); ++k) {
    s << "o curve_" << k << "\n";
    write_polyline(s, bezoutian::model_curve_points(R, curves[k]), curves[k].closed, next);
  }
}

std::size_t write_model_svgs(const std::string& directory, const bezoutian::Model_intersection& R) {
  struct Trace {
    std::size_t other;  // the other patch of the problem (itself for a self-intersection)
    std::vector<std::array<double, 2>> points;
  };
  std::map<std::size_t, std::vector<Trace>> on_patch;
  for (const auto& p : R.problems)
    for (const auto& a : p.locus.arcs)
      for (const auto& sh : a.sheets) {
        if (sh.points.size() < 2) continue;
        Trace first{p.second, {}}, second{p.first, {}};
        for (const auto& q : sh.points) {
          first.points.push_back(q.first);
          second.points.push_back(q.second);
        }
        on_patch[p.first].push_back(first);
        on_patch[p.second].push_back(second);  // (a self-intersection: the partner's points on the same patch)
      }
  const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
  const double W = 520, H = 560, pad = 50, side = W - 2 * pad;
  auto X = [&](double u) { return pad + u * side; };
  auto Y = [&](double v) { return pad + 40 + (1 - v) * side; };
  std::size_t written = 0;
  for (const auto& entry : on_patch) {
    const std::string path = directory + "/patch_" + std::to_string(entry.first) + ".svg";
    std::ofstream s(path);
    if (!s) throw bezoutian::Error("cannot write " + path);
    s << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H << "' viewBox='0 0 " << W << " "
      << H << "'>\n<rect width='100%' height='100%' fill='white'/>\n";
    s << "<text x='" << pad << "' y='22' font-size='13' font-family='sans-serif'>patch " << entry.first
      << ": its intersection curves in its parameter square (u right, v up)</text>\n";
    s << "<rect x='" << X(0) << "' y='" << Y(1) << "' width='" << side << "' height='" << side
      << "' fill='none' stroke='black'/>\n";
    for (int k = 0; k <= 4; ++k) {  // ticks and labels every 0.25 on both axes
      const double t = k / 4.0;
      char label[16];
      std::snprintf(label, sizeof label, "%g", t);
      s << "<line x1='" << X(t) << "' y1='" << Y(0) << "' x2='" << X(t) << "' y2='" << Y(0) + 6 << "' stroke='black'/>"
        << "<text x='" << X(t) << "' y='" << Y(0) + 19 << "' font-size='11' text-anchor='middle' "
        << "font-family='sans-serif'>" << label << "</text>\n";
      s << "<line x1='" << X(0) - 6 << "' y1='" << Y(t) << "' x2='" << X(0) << "' y2='" << Y(t) << "' stroke='black'/>"
        << "<text x='" << X(0) - 9 << "' y='" << Y(t) + 4 << "' font-size='11' text-anchor='end' "
        << "font-family='sans-serif'>" << label << "</text>\n";
    }
    s << "<text x='" << X(0.5) << "' y='" << Y(0) + 36 << "' font-size='12' text-anchor='middle' "
      << "font-family='sans-serif'>u</text><text x='" << X(0) - 36 << "' y='" << Y(0.5)
      << "' font-size='12' font-family='sans-serif'>v</text>\n";
    std::map<std::size_t, std::size_t> colour_of;  // other patch -> colour index, in order of appearance
    for (const auto& tr : entry.second) {
      const std::size_t c = colour_of.emplace(tr.other, colour_of.size()).first->second;
      s << "<polyline fill='none' stroke-width='2' stroke='" << colours[c % 8] << "' points='";
      for (const auto& p : tr.points) s << X(p[0]) << "," << Y(p[1]) << " ";
      s << "'/>\n";
    }
    double y = 40;  // the legend, above the square
    double x = pad;
    for (const auto& oc : colour_of) {
      s << "<line x1='" << x << "' y1='" << y << "' x2='" << x + 18 << "' y2='" << y << "' stroke='"
        << colours[oc.second % 8] << "' stroke-width='3'/><text x='" << x + 22 << "' y='" << y + 4
        << "' font-size='11' font-family='sans-serif'>"
        << (oc.first == entry.first ? "self-intersection" : "with patch " + std::to_string(oc.first)) << "</text>\n";
      x += 120;
      if (x > W - 120) x = pad, y += 14;
    }
    s << "</svg>\n";
    ++written;
  }
  return written;
}

}  // namespace bezoutian_cli
