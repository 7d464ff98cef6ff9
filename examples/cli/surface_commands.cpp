// bezoutian self-intersect FILE and bezoutian intersect PATCH_A PATCH_B: the locus with its certified topology,
// lifted to the partner parameters, as text, JSON, SVG and OBJ.
#include "commands.h"
#include "exact_json.h"
#include "load.h"
#include "locus_json.h"

#include <bezoutian/intersection/Surface_intersection.h>
#include <bezoutian/topology/Cgal_curve_analysis.h>
#include <bezoutian/io/Exact_number.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>

#if defined(__unix__)
#include <csignal>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>
#endif
#if defined(__linux__)
#include <sys/prctl.h>
#endif

namespace bezoutian_cli {
namespace {

std::string isolated_point_text(const bezoutian::Locus_isolated_point& ip) {
  const auto& x = ip.lift;
  std::ostringstream s;
  if (x.exact)
    s << "(u, t) = (" << bezoutian::io::to_exact_string(x.projection[0]) << ", "
      << bezoutian::io::to_exact_string(x.projection[1]) << "): ";
  if (!x.proved) return s.str() + "not decided (" + x.reason + ")";
  if (x.partners.empty()) return s.str() + "phantom, proved (" + x.reason + ")";
  s << "the patches touch (proved)";
  for (const auto& p : x.partners)
    s << "; partner (v, s) = (" << exact_or_decimal(p.v) << ", " << exact_or_decimal(p.s) << "), " << contact_kind(p)
      << ", at (" << p.point[0] << ", " << p.point[1] << ", " << p.point[2] << ")";
  return s.str();
}


using bezoutian::Rational;
using Patch = bezoutian::Rational_bezier_patch<Rational>;

bezoutian::Parameter_box parse_box(const std::string& text, const char* what) {
  bezoutian::Parameter_box b;
  if (text.empty()) return b;
  std::vector<Rational> v;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) v.push_back(bezoutian::io::exact_number(item));
  if (v.size() != 4 || !(v[0] < v[1]) || !(v[2] < v[3]))
    throw bezoutian::Invalid_input(std::string(what) + " must be u0,u1,v0,v1 with u0 < u1 and v0 < v1, got '" + text + "'");
  b.u0 = v[0], b.u1 = v[1], b.v0 = v[2], b.v1 = v[3];
  return b;
}

// The patch `index` of the file (every object of the file is validated: a pole anywhere is an error); only the
// warnings about that patch are printed (the teapot's lid and bottom warn about their collapsed rows).
Patch patch_of(const std::string& path, std::size_t index) {
  Loaded_file f = load_and_validate(path);
  if (f.doc.patches.size() <= index)
    throw bezoutian::Invalid_input(path + ": expected at least " + std::to_string(index + 1) + " patch(es), found " +
                                   std::to_string(f.doc.patches.size()));
  const std::string label = object_label("patch", index, f.doc.patch_name(index)) + ": ";
  for (const auto& w : f.warnings)
    if (w.compare(0, label.size(), label) == 0) std::cerr << "warning: " << w << "\n";
  return f.doc.patches[index];
}

void write_svg(const std::string& path, const bezoutian::Surface_locus& L) {
  const auto& B = L.topology.box;
  const double u0 = CGAL::to_double(B.u0), u1 = CGAL::to_double(B.u1), v0 = CGAL::to_double(B.v0),
               v1 = CGAL::to_double(B.v1);
  const double W = 640, H = 640, pad = 40;
  auto X = [&](double u) { return pad + (u - u0) / (u1 - u0) * (W - 2 * pad); };
  auto Y = [&](double v) { return H - pad - (v - v0) / (v1 - v0) * (H - 2 * pad); };
  std::ofstream s(path);
  if (!s) throw bezoutian::Error("cannot write " + path);
  s << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H << "' viewBox='0 0 " << W << " " << H
    << "'>\n<rect width='100%' height='100%' fill='white'/>\n";
  s << "<rect x='" << X(u0) << "' y='" << Y(v1) << "' width='" << X(u1) - X(u0) << "' height='" << Y(v0) - Y(v1)
    << "' fill='none' stroke='black'/>\n";
  s << "<text x='" << pad << "' y='" << pad - 28 << "' font-size='11' font-family='sans-serif'>"
    << (L.self_intersection ? "self-intersection locus D(u,v)=0" : "intersection locus D(u,t)=0") << " in [" << u0
    << "," << u1 << "]x[" << v0 << "," << v1 << "]</text>\n";
  s << "<text x='" << pad << "' y='" << pad - 17 << "' font-size='10' font-family='sans-serif'>dashed grey: phantom; "
    << "grey boxes: no genuine point; green diamond: a genuine part ends;</text>\n"
    << "<text x='" << pad << "' y='" << pad - 6 << "' font-size='10' font-family='sans-serif'>orange triangle: pinch "
    << "point; blue square: boundary point; brown band: a side of the box on D=0</text>\n";
  for (const auto& b : L.topology.excluded_regions)  // proved free of genuine points: hatched grey
    s << "<rect x='" << X(CGAL::to_double(b.u0)) << "' y='" << Y(CGAL::to_double(b.v1)) << "' width='"
      << X(CGAL::to_double(b.u1)) - X(CGAL::to_double(b.u0)) << "' height='"
      << Y(CGAL::to_double(b.v0)) - Y(CGAL::to_double(b.v1)) << "' fill='#eeeeee' stroke='#cccccc'/>\n";
  const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
  for (std::size_t ci = 0; ci < L.topology.components.size(); ++ci) {
    for (std::size_t ei : L.topology.components[ci].edges) {
      const auto& pts = L.arcs[ei].points;
      for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        const bool g = pts[i].genuine && pts[i + 1].genuine;
        s << "<line x1='" << X(pts[i].projection[0]) << "' y1='" << Y(pts[i].projection[1]) << "' x2='"
          << X(pts[i + 1].projection[0]) << "' y2='" << Y(pts[i + 1].projection[1]) << "' stroke='"
          << (g ? colours[ci % 8] : "#999999") << "' stroke-width='" << (g ? 2.5 : 1.2) << "'"
          << (g ? "" : " stroke-dasharray='4,3'") << "/>\n";
      }
    }
  }
  for (const auto& e : L.edge_lines) {  // sides of the box on D = 0: a thick band along the side
    const auto& a = e.points.front().projection;
    const auto& b = e.points.back().projection;
    s << "<line x1='" << X(a[0]) << "' y1='" << Y(a[1]) << "' x2='" << X(b[0]) << "' y2='" << Y(b[1]) << "' stroke='"
      << (e.genuine ? "#8c564b" : "#999999") << "' stroke-width='6' stroke-opacity='0.6'"
      << (e.genuine ? "" : " stroke-dasharray='4,3'") << "/>\n";
  }
  for (const auto& v : L.topology.vertices) {
    if (v.kind == bezoutian::Curve_topology_vertex::singular || v.kind == bezoutian::Curve_topology_vertex::isolated)
      s << "<circle cx='" << X(v.u) << "' cy='" << Y(v.v) << "' r='6' fill='none' stroke='red' stroke-width='2'/>\n"
        << "<text x='" << (X(v.u) > W / 2 ? X(v.u) - 8 : X(v.u) + 8) << "' y='"
        << (Y(v.v) < 70 ? Y(v.v) + 20 : Y(v.v) - 8)  // below a point near the top: the legend is above the box
        << "' font-size='12' fill='red'" << (X(v.u) > W / 2 ? " text-anchor='end'" : "") << ">" << v.branches
        << " branches (" << v.u << ", " << v.v << ")</text>\n";
    if (v.on_boundary)
      s << "<rect x='" << X(v.u) - 4 << "' y='" << Y(v.v) - 4 << "' width='8' height='8' fill='blue'/>\n";
  }
  for (const auto& p : L.pinch_points)  // pinch points: orange triangles
    s << "<polygon points='" << X(p.u) << "," << Y(p.v) - 7 << " " << X(p.u) + 6 << "," << Y(p.v) + 5 << " "
      << X(p.u) - 6 << "," << Y(p.v) + 5 << "' fill='#ff7f0e' stroke='black'/>\n";
  for (const auto& sp : L.split_points) {  // where a genuine part ends inside the box: a green diamond
    const auto& q = L.arcs[sp.arc].points[sp.index];
    const double x = X(q.projection[0]), y = Y(q.projection[1]);
    s << "<polygon points='" << x << "," << y - 6 << " " << x + 6 << "," << y << " " << x << "," << y + 6 << " "
      << x - 6 << "," << y << "' fill='#2ca02c' stroke='black'/>\n";
  }
  s << "</svg>\n";
}

void write_obj(const std::string& path, const std::vector<const Patch*>& patches, const bezoutian::Surface_locus& L) {
  std::ofstream s(path);
  if (!s) throw bezoutian::Error("cannot write " + path);
  std::size_t base = 1;
  const int N = 24;
  for (std::size_t pi = 0; pi < patches.size(); ++pi) {
    s << "o patch_" << pi << "\n";
    for (int i = 0; i <= N; ++i)
      for (int j = 0; j <= N; ++j) {
        auto p = patches[pi]->evaluate(double(i) / N, double(j) / N);
        s << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
      }
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) {
        const std::size_t a = base + i * (N + 1) + j, b = a + 1, c = a + (N + 1), d = c + 1;
        s << "f " << a << " " << c << " " << d << " " << b << "\n";
      }
    base += (N + 1) * (N + 1);
  }
  s << "o locus\n";
  std::vector<std::vector<bezoutian::Locus_point>> polylines;
  for (const auto& arc : L.arcs) polylines.push_back(arc.points);
  for (const auto& e : L.edge_lines) polylines.push_back(e.points);  // a collapsed side is one 3D point
  for (const auto& points : polylines) {
    std::vector<std::size_t> ids;
    for (const auto& q : points) {
      if (!q.lifted || !q.genuine) {
        if (ids.size() > 1) {
          s << "l";
          for (auto i : ids) s << " " << i;
          s << "\n";
        }
        ids.clear();
        continue;
      }
      s << "v " << q.point_3d[0] << " " << q.point_3d[1] << " " << q.point_3d[2] << "\n";
      ids.push_back(base++);
    }
    if (ids.size() > 1) {
      s << "l";
      for (auto i : ids) s << " " << i;
      s << "\n";
    }
  }
}

void print_text(const bezoutian::Surface_locus& L, double seconds) {
  const auto& e = L.equation;
  std::cout << (L.self_intersection ? "Self-intersection" : "Intersection") << " locus: ";
  if (L.equation_computed)
    std::cout << "Bezoutian matrix " << e.matrix.size() << " x " << e.matrix.size() << ", "
              << (e.route == bezoutian::Implicit_equation::Route::maximal_minors
                      ? "det B = 0, of rank " + std::to_string(e.generic_rank) + " (proved): gcd of maximal minors, "
                      : std::string());
  else
    std::cout << "no elimination (" << L.note << ")" << (CGAL::is_zero(e.determinant) ? "" : ", ");
  if (L.equation_computed || !CGAL::is_zero(e.determinant))
    std::cout << "D(" << e.variables[0] << "," << e.variables[1] << ") of bi-degree (" << e.degree(0) << ", "
              << e.degree(1) << "), total degree " << e.total_degree() << ", " << e.terms().size() << " terms";
  std::cout << "\n";
  static const char* side_name[4] = {"v=0", "u=1", "v=1", "u=0"};
  for (const auto& c : L.contacts) {
    std::cout << "contact: " << (c.shared_curve ? "shared boundary curve" : "boundary point") << ", side "
              << side_name[c.side_first] << " of the first patch";
    if (c.shared_curve)
      std::cout << " [" << c.first_0.to_double() << ", " << c.first_1.to_double() << "] = side "
                << side_name[c.side_second] << " of the second [" << c.second_0.to_double() << ", "
                << c.second_1.to_double() << "]\n";
    else
      std::cout << " at " << c.first_0.to_double() << " = side " << side_name[c.side_second] << " of the second at "
                << c.second_0.to_double() << "\n";
  }
  for (const auto& ov : L.overlaps) {
    auto box = [](const std::array<bezoutian::Rational, 4>& r) {
      using bezoutian::io::to_exact_string;
      return "[" + to_exact_string(r[0]) + ", " + to_exact_string(r[1]) + "] x [" + to_exact_string(r[2]) + ", " +
             to_exact_string(r[3]) + "]";
    };
    std::cout << "overlap: " << box(ov.first) << " of the first patch = " << box(ov.second)
              << " of the second, (u, v) = (" << ov.along_u.text(ov.swapped ? "t" : "s") << ", "
              << ov.along_v.text(ov.swapped ? "s" : "t") << ")\n";
  }
  for (const auto& e : L.edge_lines) std::cout << "edge line: " << e.description << "\n";
  const auto& T = L.topology;
  if (!L.topology_computed) {
    std::cout << "note: " << L.note << "\n";
    return;
  }
  std::cout << "certified topology in [" << T.box.u0 << ", " << T.box.u1 << "] x [" << T.box.v0 << ", " << T.box.v1
            << "] (" << (L.topology_method.empty() ? "D is a nonzero constant" : L.topology_method) << "): "
            << T.components.size() << " component(s), " << T.number_of_singular_points()
            << " singular point(s), " << T.number_of_boundary_points() << " boundary point(s)\n";
  for (std::size_t i = 0; i < T.components.size(); ++i) {
    const auto& c = T.components[i];
    if (c.isolated_point) {
      std::cout << "  component " << i << ": isolated point";
      for (const auto& ip : L.isolated_points)
        if (std::find(c.vertices.begin(), c.vertices.end(), ip.vertex) != c.vertices.end())
          std::cout << " " << isolated_point_text(ip);
      std::cout << "\n";
      continue;
    }
    std::size_t genuine = 0, total = 0, proved = 0, sheets = 0, segments = 0, bounded = 0;
    double worst = 0, fibre_open = 0, largest_bound = 0;
    for (auto ei : c.edges) {
      sheets += L.arcs[ei].sheets.size();
      fibre_open = std::max(fibre_open, L.arcs[ei].fibre_undecided_fraction);
      for (const auto& sh : L.arcs[ei].sheets)
        for (const auto& b : sh.segment_distance_bounds) {
          ++segments;
          if (!std::isfinite(b[2])) continue;
          ++bounded;
          largest_bound = std::max({largest_bound, b[0], b[1], b[2]});
        }
    }
    for (auto ei : c.edges)
      for (const auto& q : L.arcs[ei].points) {
        ++total;
        genuine += q.genuine;
        proved += q.status_proved;
        if (q.lifted && std::isfinite(q.residual)) worst = std::max(worst, q.residual);
      }
    std::cout << "  component " << i << ": " << (c.isolated_point ? "isolated point" : c.closed ? "closed loop" : "open arc(s)")
              << ", " << c.edges.size() << " arc(s), " << genuine << "/" << total
              << " traced points with partner in the domain (" << proved << "/" << total
              << " genuine/phantom status proved), max residual " << worst << "\n"
              << "    " << sheets << " sheet(s) (branches of the space curve, one per partner); every partner proved "
              << "found on " << 100 * (1 - fibre_open) << " % of each arc at least\n";
    if (segments > 0)
      std::cout << "    sheet polylines: " << bounded << "/" << segments
                << " segments proved within " << largest_bound
                << " of the curve (parameter domains and 3D; the others are next to folds or singular points)\n";
  }
  if (L.self_intersection) {
    std::cout << "  " << L.pinch_points.size() << " pinch point(s) of the patch in the box"
              << (L.pinch_points_complete ? " (all, proved)" : " (search incomplete: " + L.pinch_points_note + ")")
              << "\n";
    for (const auto& p : L.pinch_points)
      if (p.rank_zero)
        std::cout << "    pinch point (" << p.u << ", " << p.v << "), the Jacobian is zero there\n";
      else
        std::cout << "    pinch point (" << p.u << ", " << p.v << "), kernel direction "
                  << (p.chart == 0 ? "(1, m)" : "(m, 1)") << " with m = " << CGAL::to_double((p.m[0] + p.m[1]) / 2) << "\n";
  }
  if (!L.split_points.empty())
    std::cout << "  " << L.split_points.size()
              << " certified split point(s): genuine parts end inside the box where the partner reaches the domain's "
                 "boundary\n";
  const auto old_precision = std::cout.precision(17);
  for (std::size_t vi = 0; vi < T.vertices.size(); ++vi) {
    const auto& v = T.vertices[vi];
    if (v.kind != bezoutian::Curve_topology_vertex::singular) continue;
    std::cout << "  singular point in [" << v.u_lo << ", " << v.u_hi << "] x [" << v.v_lo << ", " << v.v_hi
              << "]: " << v.branches << " branches; partner (" << (L.self_intersection ? "l, k" : "v, s")
              << ") along each arc:\n";
    for (const auto& arc : L.arcs) {
      if (arc.points.empty()) continue;
      const bezoutian::Locus_point* q = arc.source == vi ? &arc.points.front() : arc.target == vi ? &arc.points.back() : nullptr;
      if (q && q->lifted)
        std::cout << "    (" << q->partner[0] << ", " << q->partner[1] << ")  residual " << q->residual << "\n";
    }
  }
  std::cout.precision(old_precision);
  std::cout << "computed in " << seconds << " s\n";
}

void output(const bezoutian::Surface_locus& L, double s, const Patch& a, const Patch* b, const Intersect_options& o) {
  if (o.json) {
    nlohmann::json j = envelope(L.self_intersection ? "self-intersect" : "intersect");
    j["problem"] = L.self_intersection ? "self" : "patch/patch";
    j["locus"] = locus_json(L);
    j["seconds"] = s;
    std::cout << j.dump(1) << "\n";
  }
  else
    print_text(L, s);
  if (!o.svg.empty()) write_svg(o.svg, L);
  std::vector<const Patch*> ps = {&a};
  if (b) ps.push_back(b);
  if (!o.obj.empty()) write_obj(o.obj, ps, L);
}

void report(bool self, const Patch& a, const Patch* b, const Intersect_options& o,
            const bezoutian::Surface_intersection_options& so) {
  auto t0 = std::chrono::steady_clock::now();
  bezoutian::Surface_locus L = self ? bezoutian::self_intersection_locus(a, so) : bezoutian::intersection_locus(a, *b, so);
  output(L, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), a, b, o);
}

#if defined(__unix__)
// CGAL's whole-plane analysis, the fallback where the subdivision does not certify, has no time bound (a patch with
// huge coordinates ran for minutes, doc/surface_intersection.md). So the locus is first computed without it; only if
// the fallback would run (the topology not certified, D of total degree <= --max-degree) is it computed again with
// the fallback, in a child process whose standard output is kept. If the child has not finished after
// o.fallback_seconds it is stopped, and the first result is reported, its note saying so; likewise if the child
// fails (an error, or killed by a signal). The child dies with this process (PR_SET_PDEATHSIG on Linux; elsewhere
// it is killed when the limit is reached). Returns false if the child could not be started (the caller then
// computes in this process).
bool report_with_time_limit(bool self, const Patch& a, const Patch* b, const Intersect_options& o,
                            const bezoutian::Surface_intersection_options& so) {
  bezoutian::Surface_intersection_options first = so;
  first.max_total_degree_for_topology = 0;
  const auto t0 = std::chrono::steady_clock::now();
  bezoutian::Surface_locus L =
      self ? bezoutian::self_intersection_locus(a, first) : bezoutian::intersection_locus(a, *b, first);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (L.topology_computed) {
    output(L, seconds, a, b, o);
    return true;
  }
  // total degree of D without the box sides on it: the degree the library compares with the limit
  const auto rest = bezoutian::internal::box_edge_lines(L.equation.square_free, so.box).rest;
  int total = -1;
  for (int j = 0; j <= rest.degree(); ++j)
    if (!CGAL::is_zero(rest[j])) total = std::max(total, j + rest[j].degree());
  if (total > o.max_degree) {
    output(L, seconds, a, b, o);
    return true;
  }
  int fd[2];
  if (pipe(fd) != 0) return false;
  std::cout.flush();
  std::cerr.flush();
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    close(fd[0]);
    close(fd[1]);
    return false;
  }
  if (pid == 0) {  // the child: the whole report with the fallback, its standard output into the pipe
#if defined(__linux__)
    // killed when the parent dies (SIGTERM, a crash); the parent may already be gone before this call
    if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || getppid() != parent) _exit(4);
#else
    (void)parent;
#endif
    close(fd[0]);
    dup2(fd[1], STDOUT_FILENO);
    close(fd[1]);
    int rc = 0;
    try {
      bezoutian::Surface_intersection_options again = so;  // (the time budget: what the first computation left)
      if (so.limits.time_limit > 0) again.limits.time_limit = std::max(1e-3, so.limits.time_limit - seconds);
      report(self, a, b, o, again);
    } catch (const bezoutian::Limit_exceeded& e) {
      std::cerr << "bezoutian: error: " << e.what() << "\n";
      rc = limit_exit_status;
    } catch (const bezoutian::Error& e) {
      std::cerr << "bezoutian: error: " << e.what() << "\n";
      rc = 2;
    } catch (const std::exception& e) {
      std::cerr << "bezoutian: internal error: " << e.what() << "\n";
      rc = 3;
    }
    std::cout.flush();
    std::cerr.flush();
    _exit(rc);
  }
  close(fd[1]);
  std::string out;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(o.fallback_seconds);
  bool finished = false;
  for (;;) {
    const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0) break;
    pollfd p{fd[0], POLLIN, 0};
    const int r = poll(&p, 1, int(std::min(left * 1000 + 1, 1e9)));
    if (r <= 0) continue;  // (a timeout or a signal: the loop ends at the deadline)
    char buf[1 << 16];
    const ssize_t n = read(fd[0], buf, sizeof buf);
    if (n > 0) {
      out.append(buf, std::size_t(n));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    finished = true;  // end of file: the child has closed its output
    break;
  }
  close(fd[0]);
  if (!finished) kill(pid, SIGKILL);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (finished && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    std::cout << out << std::flush;
    return true;
  }
  std::ostringstream why;
  why << "CGAL's whole-plane curve analysis (total degree " << total << " <= --max-degree " << o.max_degree << ") ";
  if (!finished)
    why << "was stopped after " << o.fallback_seconds << " s (--fallback-seconds)";
  else if (WIFSIGNALED(status))
    why << "ended with signal " << WTERMSIG(status) << " (" << strsignal(WTERMSIG(status)) << ")";
  else if (WIFEXITED(status) && WEXITSTATUS(status) == limit_exit_status)
    why << "was stopped by the time limit (--time-limit " << o.time_limit << " s, its message above)";
  else
    why << "failed (exit code " << WEXITSTATUS(status) << ", its error above)";
  const std::string not_attempted = "CGAL's whole-plane curve analysis is not attempted above "
                                    "max_total_degree_for_topology = 0";
  const std::size_t at = L.note.find(not_attempted);
  if (at != std::string::npos)
    L.note.replace(at, not_attempted.size(), why.str());
  else
    L.note += "; " + why.str();
  output(L, seconds, a, b, o);
  return true;
}
#endif

void run(bool self, const Patch& a, const Patch* b, const Intersect_options& o, const std::string& domain) {
  bezoutian::Surface_intersection_options so;
  so.box = parse_box(o.box, "--box");
  if (domain == "none")
    so.partner_domain_unbounded = true;
  else
    so.partner_domain = parse_box(domain, "--domain");
  so.tolerance = o.tolerance;
  if (!(o.polyline_tolerance >= 0)) throw bezoutian::Invalid_input("--polyline-tolerance must be >= 0 (0: uniform samples only)");
  so.polyline_tolerance = o.polyline_tolerance;
  so.refine_to_proved_distance = o.proved_tolerance;
  so.max_total_degree_for_topology = o.max_degree;
  so.whole_plane_topology = bezoutian::Cgal_curve_analysis{};
  // the input size limits and the time budget, checked by the library (Limit_exceeded names the limit and the stage)
  so.limits = intersection_limits(o);
  if (!(o.fallback_seconds >= 0)) throw bezoutian::Invalid_input("--fallback-seconds must be >= 0 (0: no limit)");
#if defined(__unix__)
  if (o.max_degree > 0 && o.fallback_seconds > 0 && report_with_time_limit(self, a, b, o, so)) return;
#else
  if (o.max_degree > 0 && o.fallback_seconds > 0)
    std::cerr << "warning: --fallback-seconds needs a POSIX system (fork): CGAL's curve analysis, where it runs, has "
                 "no time limit here; --max-degree 0 turns it off\n";
#endif
  report(self, a, b, o, so);
}

} // namespace

std::shared_ptr<std::string> patch_intersect_domain() {
  static auto d = std::make_shared<std::string>();
  return d;
}

// "--patches I,J": indices of the patches (I in FILE_A, J in FILE_B or, without FILE_B, also in FILE_A).
std::pair<std::size_t, std::size_t> patch_indices(const std::string& text, bool one) {
  if (text.empty()) return {0, one ? 0 : 1};
  std::vector<long> v;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t c = text.find(',', pos);
    const std::string item = text.substr(pos, c == std::string::npos ? std::string::npos : c - pos);
    char* end = nullptr;
    const long x = std::strtol(item.c_str(), &end, 10);
    if (item.empty() || *end != '\0' || x < 0)
      throw bezoutian::Invalid_input("--patches expects non-negative indices separated by a comma, got '" + text + "'");
    v.push_back(x);
    if (c == std::string::npos) break;
    pos = c + 1;
  }
  if (v.size() != (one ? 1u : 2u))
    throw bezoutian::Invalid_input(std::string("--patches expects ") + (one ? "one index" : "two indices I,J") +
                                   ", got '" + text + "'");
  return {std::size_t(v[0]), std::size_t(one ? v[0] : v[1])};
}

void run_patch_intersect(const Intersect_options& o) {
  // default: the first two patches of FILE_A, or the first patch of each file
  const auto idx = o.patches.empty() && !o.file_b.empty() ? std::make_pair(std::size_t(0), std::size_t(0))
                                                          : patch_indices(o.patches, false);
  Patch a = patch_of(o.file_a, idx.first);
  Patch b = o.file_b.empty() ? patch_of(o.file_a, idx.second) : patch_of(o.file_b, idx.second);
  run(false, a, &b, o, *patch_intersect_domain());
}

namespace {
Register self_registration([](CLI::App& app) {
  auto o = std::make_shared<Intersect_options>();
  auto domain = std::make_shared<std::string>();
  auto* sub = app.add_subcommand("self-intersect", "Self-intersection locus of a patch with certified topology");
  sub->add_option("FILE", o->file_a, "patch file (the first patch, or the one named by --patch)")->required();
  sub->add_option("--patch", o->patches, "index (0-based) of the patch in FILE");
  sub->add_option("--box", o->box, "region u0,u1,v0,v1 of the (u,v) plane to analyse (default 0,1,0,1)");
  sub->add_option("--domain", *domain, "partner domain u0,u1,v0,v1 (default 0,1,0,1) or 'none'");
  sub->add_option("--svg", o->svg, "write the picture of the locus in the (u,v) plane");
  sub->add_option("--obj", o->obj, "write the patch mesh and the 3D double curve");
  sub->add_option("--tolerance", o->tolerance, "precision of the traced points' ordinates (default 1e-9)");
  sub->add_option("--polyline-tolerance", o->polyline_tolerance,
                  "refine the lifted polylines until their chords are this close to the curve, in 3D and in the "
                  "parameter domain (midpoint test; default 1e-3; 0: the uniform samples of the topology)");
  sub->add_flag("--proved-tolerance", o->proved_tolerance,
                "also refine until the proved bound on each chord's distance from the curve meets the polyline "
                "tolerance (1.3 to 3.3 times the points; the bounds are reported either way)");
  sub->add_option("--max-degree", o->max_degree,
                  "largest total degree of D for CGAL's curve analysis when the subdivision does not certify (default 16)");
  sub->add_option("--fallback-seconds", o->fallback_seconds,
                  "stop CGAL's curve analysis after this many seconds and answer without it (default 60, 0: no limit; "
                  "POSIX systems)");
  sub->add_flag("--json", o->json, "machine-readable output");
  sub->add_option("--time-limit", o->time_limit,
                  "stop after this many seconds with 'time_limit exceeded', naming the stage, and exit status 4 (the "
                  "stages check it in between; the command ends at the latest 1 s after the limit; default 0: none)");
  sub->add_option("--max-input-degree", o->max_input_degree, "refuse a patch of higher degree in u or v (default 64)");
  sub->add_option("--max-control-points", o->max_control_points,
                  "refuse a patch with more control points (default 4225)");
  sub->add_option("--max-coefficient-bits", o->max_coefficient_bits,
                  "refuse a control point coordinate whose numerator or denominator has more bits (default 4096)");
  sub->callback([o, domain] {
    start_time_limit(o->time_limit, "self-intersect");
    Patch p = patch_of(o->file_a, patch_indices(o->patches, true).first);
    run(true, p, nullptr, *o, *domain);
  });
});
} // namespace
} // namespace bezoutian_cli
