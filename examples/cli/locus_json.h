// The JSON form of a surface locus, shared by `self-intersect`, `intersect` (patches) and `model`
// (the "locus" object of doc/json_schema.md; defined in examples/cli/locus_json.cpp).
#ifndef BEZOUTIAN_CLI_LOCUS_JSON_H
#define BEZOUTIAN_CLI_LOCUS_JSON_H

#include <bezoutian/intersection/Surface_locus.h>

#include <nlohmann/json.hpp>

#include <string>

namespace bezoutian_cli {

/// The locus as the patch commands print it with --json.
nlohmann::json locus_json(const bezoutian::Surface_locus& L);

/// How two patches meet at an exact contact point: "tangent", "singular" (a patch's normal vanishes),
/// "transversal" or "undecided" (an irrational partner).
std::string contact_kind(const bezoutian::Isolated_point_partners::Partner& p);

}  // namespace bezoutian_cli

#endif  // BEZOUTIAN_CLI_LOCUS_JSON_H
