// bezoutian intersect FILE_A FILE_B: dispatches on what the files hold (curves, or patches).
#include "commands.h"

#include <bezoutian/io/Geometry_document.h>

#include <memory>

namespace {

bezoutian_cli::Register intersect_registration([](CLI::App& app) {
  auto o = std::make_shared<bezoutian_cli::Intersect_options>();
  auto domain = bezoutian_cli::patch_intersect_domain();
  auto* sub = app.add_subcommand("intersect",
                                 "Certified intersection of two curves, a curve and a patch, or two patches");
  sub->add_option("FILE_A", o->file_a, "first object (the first curve or patch of the file)")->required();
  sub->add_option("FILE_B", o->file_b, "second object (default: the second object of FILE_A)");
  sub->add_option("--method", o->method, "curves: default | subresultant | projection | resolvent | groebner")
      ->check(CLI::IsMember({"default", "subresultant", "projection", "resolvent", "groebner"}));
  sub->add_option("--box", o->box, "patches: region of interest u0,u1,v0,v1 of the (u,t) projection");
  sub->add_option("--svg", o->svg, "patches: write a picture of the parameter-space curves");
  sub->add_option("--obj", o->obj, "patches: write the patches and the 3D curves as OBJ");
  sub->add_option("--tolerance", o->tolerance, "patches: precision of the traced points' ordinates (default 1e-9)");
  sub->add_option("--polyline-tolerance", o->polyline_tolerance,
                  "patches: refine the lifted polylines until their chords are this close to the curve, in 3D and in "
                  "both parameter domains (midpoint test; default 1e-3; 0: the uniform samples of the topology)");
  sub->add_flag("--proved-tolerance", o->proved_tolerance,
                "patches: also refine until the proved bound on each chord's distance from the curve meets the "
                "polyline tolerance (1.3 to 3.3 times the points; the bounds are reported either way)");
  sub->add_option("--max-degree", o->max_degree, "patches: largest total degree of D for CGAL's curve analysis");
  sub->add_option("--fallback-seconds", o->fallback_seconds,
                  "patches: stop CGAL's curve analysis after this many seconds and answer without it (default 60, 0: "
                  "no limit; POSIX systems)");
  sub->add_option("--patches", o->patches, "patches: indices I,J (0-based) of the two patches, I in FILE_A, J in FILE_B (default 0,0), or both in FILE_A (default 0,1)");
  sub->add_option("--domain", *domain, "patches: partner domain v0,v1,s0,s1 (default 0,1,0,1) or 'none'");
  sub->add_flag("--json", o->json, "machine-readable output");
  sub->add_option("--time-limit", o->time_limit,
                  "stop after this many seconds with 'time_limit exceeded' and exit status 4; the stages check it in "
                  "between and the message names the stage, and the command ends at the latest 1 s after the limit "
                  "(default 0: none)");
  sub->add_option("--max-input-degree", o->max_input_degree,
                  "refuse a curve, or a patch in u or v, of higher degree (default 64)");
  sub->add_option("--max-control-points", o->max_control_points,
                  "refuse an object (curve or patch) with more control points (default 4225)");
  sub->add_option("--max-degree-product", o->max_degree_product,
                  "curves: refuse deg C1 x deg C2 above this (the Bezout number); curve/patch: 2 m n deg C (default 1024)");
  sub->add_option("--max-coefficient-bits", o->max_coefficient_bits,
                  "refuse a control point coordinate whose numerator or denominator has more bits "
                  "(default 4096)");
  sub->callback([o] {
    bezoutian_cli::start_time_limit(o->time_limit, "intersect");
    // Patches on both sides: surface/surface; anything else: the curve engine.
    auto a = bezoutian::io::read_geometry_file(o->file_a);
    bool patches = !a.patches.empty() && a.curves_2.empty() && a.curves_3.empty();
    if (!o->file_b.empty()) {
      auto b = bezoutian::io::read_geometry_file(o->file_b);
      patches = patches && !b.patches.empty();
    } else {
      patches = patches && a.patches.size() >= 2;
    }
    if (patches)
      bezoutian_cli::run_patch_intersect(*o);
    else
      bezoutian_cli::run_curve_intersect(*o);
  });
});

} // namespace
