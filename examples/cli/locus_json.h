// The JSON form of a surface locus, shared by `self-intersect`, `intersect` (patches) and `model`.
#ifndef BEZOUTIAN_CLI_LOCUS_JSON_H
#define BEZOUTIAN_CLI_LOCUS_JSON_H

#include <bezoutian/intersection/Surface_locus.h>

#include <nlohmann/json.hpp>

namespace bezoutian_cli {

/// The locus as the patch commands print it with --json (defined in examples/cli/surface_commands.cpp);
/// `seconds` is the time it took.
nlohmann::json locus_json(const bezoutian::Surface_locus& L, double seconds);

}  // namespace bezoutian_cli

#endif  // BEZOUTIAN_CLI_LOCUS_JSON_H
