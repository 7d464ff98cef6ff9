// bezoutian implicit self FILE | bezoutian implicit intersect FILE_A FILE_B:
// the matrix size and the implicit equation D of the projected (self-)intersection locus.
#include "commands.h"
#include "implicit_json.h"
#include "load.h"

#include <bezoutian/elimination/Implicit_equation.h>
#include <bezoutian/io/Polynomial_expression.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <iostream>
#include <memory>
#include <sstream>

namespace {

using bezoutian::Implicit_equation;
using Patch = bezoutian::Rational_bezier_patch<bezoutian::Rational>;

Patch single_patch(const std::string& path, std::size_t index) {
  bezoutian_cli::Loaded_file f = bezoutian_cli::load_and_validate(path);
  for (const auto& w : f.warnings) std::cerr << "warning: " << w << "\n";
  if (f.doc.patches.size() <= index)
    throw bezoutian::Invalid_input(path + ": expected a patch" + (index ? " number " + std::to_string(index) : "") +
                                   ", the file holds " + std::to_string(f.doc.patches.size()) + " patches");
  return f.doc.patches[index];
}

void print(const Implicit_equation& e, double seconds, bool json) {
  if (json) {
    nlohmann::json j = bezoutian_cli::envelope("implicit");
    j["implicit"] = bezoutian_cli::implicit_json(e);
    j["seconds"] = seconds;
    std::cout << j.dump(1) << "\n";
    return;
  }
  std::cout << "Bezoutian matrix: " << e.matrix.size() << " x " << e.matrix.size() << " ("
            << (e.matrix.formula == bezoutian::Bezoutian_formula::rational ? "rational" : "polynomial")
            << " formula), in " << e.variables[0] << ", " << e.variables[1] << "\n";
  if (e.is_degenerate()) {
    std::cout << "det B vanishes identically: the locus is not a curve (identical or overlapping patches, or a\n"
                 "non-generic input in the sense of buse-elkadi-galligo-2008 Theorems 2-5)\n";
    return;
  }
  std::cout << "D: bi-degree (" << e.degree(0) << ", " << e.degree(1) << "), total degree " << e.total_degree() << ", "
            << e.terms().size() << " terms" << (e.square_free == e.determinant ? ", square-free" : ", NOT square-free")
            << "\n";
  // D as an expression (Rational coefficients: the integers)
  {
    bezoutian::Polynomial_2<bezoutian::Rational> q;
    std::vector<bezoutian::Polynomial_1<bezoutian::Rational>> outer;
    for (int j = 0; j <= e.determinant.degree(); ++j) {
      std::vector<bezoutian::Rational> c;
      for (int i = 0; i <= e.determinant[j].degree(); ++i) c.emplace_back(e.determinant[j][i]);
      outer.emplace_back(c.begin(), c.end());
    }
    q = bezoutian::Polynomial_2<bezoutian::Rational>(outer.begin(), outer.end());
    std::cout << "D(" << e.variables[0] << "," << e.variables[1]
              << ") = " << bezoutian::io::polynomial_to_string(q, e.variables[0], e.variables[1]) << "\n";
  }
  std::cout << "computed in " << seconds << " s\n";
}

template <class F>
void timed(F f, bool json) {
  auto t0 = std::chrono::steady_clock::now();
  Implicit_equation e = f();
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  print(e, s, json);
}

bezoutian::Bezoutian_formula formula_of(const std::string& f) {
  if (f == "polynomial") return bezoutian::Bezoutian_formula::polynomial;
  if (f == "rational") return bezoutian::Bezoutian_formula::rational;
  return bezoutian::Bezoutian_formula::automatic;
}

bezoutian_cli::Register implicit_registration([](CLI::App& app) {
  auto* sub = app.add_subcommand("implicit", "Implicit equation D of the projected (self-)intersection locus");
  sub->require_subcommand(1);
  struct Options {
    std::string a, b, formula = "auto";
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  auto* self = sub->add_subcommand("self", "D(u,v) of the self-intersection of the first patch of FILE (Theorems 4, 5)");
  self->add_option("FILE", o->a, "patch file")->required();
  self->add_flag("--json", o->json, "machine-readable output");
  self->add_option("--formula", o->formula, "auto | polynomial (Theorem 4) | rational (Theorem 5)")
      ->check(CLI::IsMember({"auto", "polynomial", "rational"}));
  self->callback([o] {
    Patch p = single_patch(o->a, 0);
    timed([&] { return bezoutian::self_intersection_equation(p, formula_of(o->formula)); }, o->json);
  });
  auto* inter = sub->add_subcommand("intersect", "D(u,t) of the intersection of two patches (Theorems 2, 3)");
  inter->add_option("FILE_A", o->a, "first patch file")->required();
  inter->add_option("FILE_B", o->b, "second patch file (default: the second patch of FILE_A)");
  inter->add_flag("--json", o->json, "machine-readable output");
  inter->add_option("--formula", o->formula, "auto | polynomial (Theorem 2) | rational (Theorem 3)")
      ->check(CLI::IsMember({"auto", "polynomial", "rational"}));
  inter->callback([o] {
    Patch p = single_patch(o->a, 0);
    Patch q = o->b.empty() ? single_patch(o->a, 1) : single_patch(o->b, 0);
    timed([&] { return bezoutian::intersection_equation(p, q, formula_of(o->formula)); }, o->json);
  });
});

} // namespace
