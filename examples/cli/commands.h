// Registration of the subcommands of the `bezoutian` tool; one translation unit per command group.
#ifndef BEZOUTIAN_CLI_COMMANDS_H
#define BEZOUTIAN_CLI_COMMANDS_H

#include <CLI/CLI.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

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
  int max_degree = 16;              // patches: largest total degree of D for CGAL's curve analysis
  double fallback_seconds = 60;     // patches: time allowed to CGAL's curve analysis (0: no limit)
  std::string patches;              // patches: "I,J" indices (0-based) of the patches to use (default 0,1 / 0)
  bool json = false;
};

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
