// The fields every JSON document of the command line starts with (doc/json_schema.md).
#ifndef BEZOUTIAN_CLI_JSON_ENVELOPE_H
#define BEZOUTIAN_CLI_JSON_ENVELOPE_H

#include <nlohmann/json.hpp>

#include <string>

namespace bezoutian_cli {

/// Version of the output schema (doc/bezoutian-output.schema.json); every JSON document printed carries it.
constexpr int json_schema_version = 1;

/// {"schema_version", "command", "bezoutian_version"}: the start of every JSON document, errors included.
inline nlohmann::json envelope(const std::string& command) {
  nlohmann::json j;
  j["schema_version"] = json_schema_version;
  j["command"] = command;
  j["bezoutian_version"] = BEZOUTIAN_VERSION;
  return j;
}

}  // namespace bezoutian_cli

#endif  // BEZOUTIAN_CLI_JSON_ENVELOPE_H
