// The JSON form of an implicit equation D (the "implicit" object of doc/json_schema.md), shared by `implicit` and
// the loci of `intersect`, `self-intersect` and `model`.
#ifndef BEZOUTIAN_CLI_IMPLICIT_JSON_H
#define BEZOUTIAN_CLI_IMPLICIT_JSON_H

#include "exact_json.h"

#include <bezoutian/elimination/Implicit_equation.h>

#include <nlohmann/json.hpp>

namespace bezoutian_cli {

/// D = det B (or the gcd of the maximal minors when det B = 0): its variables, degrees and exact integer terms
/// [i, j, c] of c x^i y^j for the variables (x, y), and the matrix it comes from.
inline nlohmann::json implicit_json(const bezoutian::Implicit_equation& e) {
  nlohmann::json terms = nlohmann::json::array();
  for (const auto& t : e.terms()) terms.push_back({std::get<0>(t), std::get<1>(t), exact(std::get<2>(t))});
  return {{"variables", {e.variables[0], e.variables[1]}},
          {"matrix_size", e.matrix.size()},
          {"formula", e.matrix.formula == bezoutian::Bezoutian_formula::rational ? "rational" : "polynomial"},
          // "determinant" (det B) or "maximal_minors" (det B = 0: the gcd of the maximal minors of rank r)
          {"route", e.route == bezoutian::Implicit_equation::Route::maximal_minors ? "maximal_minors" : "determinant"},
          {"matrix_generic_rank", e.generic_rank},
          {"identically_zero", e.is_degenerate()},
          {"bidegree", {e.degree(0), e.degree(1)}},
          {"total_degree", e.total_degree()},
          {"square_free", e.square_free == e.determinant},
          {"terms", terms}};
}

}  // namespace bezoutian_cli

#endif  // BEZOUTIAN_CLI_IMPLICIT_JSON_H
