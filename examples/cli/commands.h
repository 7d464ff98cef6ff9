// Registration of the subcommands of the `bezoutian` tool; one translation unit per command group.
#ifndef BEZOUTIAN_CLI_COMMANDS_H
#define BEZOUTIAN_CLI_COMMANDS_H

#include <CLI/CLI.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace bezoutian {
struct Intersection_limits;
}

namespace bezoutian_cli {

/// A subcommand registers itself on the application and returns the action to run when selected.
using Registration = std::function<void(CLI::App&)>;
std::vector<Registration>& registry();

struct Register {
  explicit Register(Registration r) { registry().push_back(std::move(r)); }
};


/// Options shared by `bezoutian intersect` for curves and patches.
struct Intersect_options {
  std::string file_a, file_b;
  std::string method = "default";   // curves: default | subresultant | projection | resolvent | groebner
  std::string box;                  // patches: u0,u1,v0,v1 region of interest
  std::string svg, obj;             // patches: pictures
  double tolerance = 1e-9;          // patches: precision of traced ordinates
  double polyline_tolerance = 1e-3; // patches: chord error of the lifted polylines (midpoint test)
  bool proved_tolerance = false;    // patches: also refine until the proved chord distance meets it
  int max_degree = 16;              // patches: largest total degree of D for CGAL's curve analysis
  double fallback_seconds = 60;     // patches: time allowed to CGAL's curve analysis (0: no limit)
  std::string patches;              // patches: "I,J" indices (0-based) of the patches to use (default 0,1 / 0)
  bool json = false;
  // Resource limits (bezoutian::Intersection_limits; the defaults are the library's)
  double time_limit = 0;               // seconds for the whole command (0: none), checked between the stages
  int max_input_degree = 64;           // largest degree of a curve, of a patch in u and in v
  long max_control_points = 4225;      // largest number of control points of one object
  long max_degree_product = 1024;      // curves: deg C1 deg C2; curve/patch: 2 m n deg C
  long max_coefficient_bits = 4096;    // largest numerator/denominator of a control point
};

/// The library's resource limits from the options (defined in examples/cli/curve_intersect.cpp).
bezoutian::Intersection_limits intersection_limits(const Intersect_options& o);

/// Exit status of a command stopped by a resource limit (an input limit or the time limit).
constexpr int limit_exit_status = 4;

/// Stops the process after `seconds` + 1 s (a separate thread; 0: no limit) with the message
/// "bezoutian: error: <command>: time_limit exceeded ..." and exit status limit_exit_status: the bound for stages
/// of a computation that do not check the time budget themselves.
void start_time_limit(double seconds, const std::string& command);

/// Curve/curve and curve/patch intersection (examples/cli/curve_intersect.cpp).
void run_curve_intersect(const Intersect_options& o);
/// A space curve (or segment) against a patch (examples/cli/curve_patch_intersect.cpp).
void run_curve_patch_intersect(const Intersect_options& o);
/// Patch/patch intersection (examples/cli/surface_commands.cpp).
void run_patch_intersect(const Intersect_options& o);
/// The --domain option of `intersect` for patches (shared by the dispatcher and the surface command).
std::shared_ptr<std::string> patch_intersect_domain();

} // namespace bezoutian_cli

#endif  // BEZOUTIAN_CLI_COMMANDS_H
