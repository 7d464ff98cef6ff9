// bezoutian: command-line front end of the Bezoutian library.
#include "commands.h"
#include "json_envelope.h"

#include <bezoutian/arithmetic/Error.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <thread>

namespace bezoutian_cli {
namespace {
bool json_errors = false;  // --json was given: errors are also printed on stdout as JSON
std::string json_command;  // the subcommand named on the command line ("" if none)

// An error as the JSON document of doc/json_schema.md: the envelope and {"error": {"kind", "message", "status"}}.
std::string error_json(const char* kind, const std::string& message, int status) {
  nlohmann::json j = envelope(json_command);
  if (json_command.empty()) j["command"] = nullptr;
  j["error"] = {{"kind", kind}, {"message", message}, {"status", status}};
  return j.dump(1);
}
}

std::vector<Registration>& registry() {
  static std::vector<Registration> r;
  return r;
}

void start_time_limit(double seconds, const std::string& command) {
  if (!(seconds > 0)) return;
  std::thread([seconds, command] {
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds + 1));
    char message[512];
    std::snprintf(message, sizeof message,
                  "%s: time_limit exceeded: stopped after %g s (--time-limit %g), inside a stage that does not check "
                  "the limit itself",
                  command.c_str(), seconds + 1, seconds);
    std::fprintf(stderr, "bezoutian: error: %s\n", message);
    std::fflush(stderr);
    if (json_errors) std::fprintf(stdout, "%s\n", error_json("limit exceeded", message, limit_exit_status).c_str());
    std::fflush(stdout);
    std::_Exit(limit_exit_status);
  }).detach();
}
} // namespace bezoutian_cli

namespace {
bool json_requested(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--json") == 0) return true;
  return false;
}

// The first argument that names a subcommand of `app`.
std::string command_named(int argc, char** argv, CLI::App& app) {
  for (int i = 1; i < argc; ++i)
    for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
      if (sub->get_name() == argv[i]) return sub->get_name();
  return "";
}

// With --json, an error is also one JSON document on stdout, {"error": {"kind": ..., "message": ..., "status": ...}}
// with the envelope of every output (the message goes to stderr as without --json).
int report_error(bool json, int status, const char* kind, const std::string& message) {
  if (json) std::cout << bezoutian_cli::error_json(kind, message, status) << std::endl;
  return status;
}
} // namespace

int main(int argc, char** argv) {
  const bool json = json_requested(argc, argv);
  bezoutian_cli::json_errors = json;
  CLI::App app{"bezoutian: certified intersections of rational Bezier curves and patches"};
  app.set_version_flag("--version", std::string("bezoutian ") + BEZOUTIAN_VERSION);
  app.footer("Exit status: 0 when the command answered (whether its answer is certified is in the output), 1 for a "
             "command line it cannot parse, 2 for input it refuses (with the reason), 3 for an internal error, 4 "
             "when a limit (--time-limit, an input size limit) stopped it.");
  app.require_subcommand(1);
  for (auto& reg : bezoutian_cli::registry()) reg(app);
  bezoutian_cli::json_command = command_named(argc, argv, app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int status = app.exit(e);  // (prints the help, the version or what is wrong with the command line)
    return status == 0 ? 0 : report_error(json, 1, "command line", e.what());
  } catch (const bezoutian::Limit_exceeded& e) {
    std::cerr << "bezoutian: error: " << e.what() << "\n";
    return report_error(json, bezoutian_cli::limit_exit_status, "limit exceeded", e.what());
  } catch (const bezoutian::Error& e) {
    std::cerr << "bezoutian: error: " << e.what() << "\n";
    return report_error(json, 2, "input refused", e.what());
  } catch (const std::exception& e) {
    std::cerr << "bezoutian: internal error: " << e.what() << "\n";
    return report_error(json, 3, "internal error", e.what());
  }
  return 0;
}
