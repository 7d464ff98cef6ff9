// Registration of the subcommands of the `bezoutian` tool; one translation unit per command group.
#ifndef BEZOUTIAN_CLI_COMMANDS_H
#define BEZOUTIAN_CLI_COMMANDS_H

#include <CLI/CLI.hpp>
#include <functional>
#include <vector>

namespace bezoutian_cli {

/// A subcommand registers itself on the application and returns the action to run when selected.
using Registration = std::function<void(CLI::App&)>;
std::vector<Registration>& registry();

struct Register {
  explicit Register(Registration r) { registry().push_back(std::move(r)); }
};

} // namespace bezoutian_cli

#endif
