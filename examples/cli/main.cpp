// bezoutian: command-line front end of the Bezoutian library.
#include "commands.h"

#include <bezoutian/arithmetic/Error.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <thread>

namespace bezoutian_cli {
std::vector<Registration>& registry() {
  static std::vector<Registration> r;
  return r;
}

void start_time_limit(double seconds, const std::string& command) {
  if (!(seconds > 0)) return;
  std::thread([seconds, command] {
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds + 1));
    std::fprintf(stderr,
                 "bezoutian: error: %s: time_limit exceeded: stopped after %g s (--time-limit %g), inside a stage that "
                 "does not check the limit itself\n",
                 command.c_str(), seconds + 1, seconds);
    std::fflush(stderr);
    std::fflush(stdout);
    std::_Exit(limit_exit_status);
  }).detach();
}
} // namespace bezoutian_cli

int main(int argc, char** argv) {
  CLI::App app{"bezoutian: certified intersections of rational Bezier curves and patches"};
  app.set_version_flag("--version", std::string("bezoutian ") + BEZOUTIAN_VERSION);
  app.footer("Exit status: 0 when the command answered (whether its answer is certified is in the output), 1 for a "
             "command line it cannot parse, 2 for input it refuses (with the reason), 3 for an internal error, 4 "
             "when a limit (--time-limit, an input size limit) stopped it.");
  app.require_subcommand(1);
  for (auto& reg : bezoutian_cli::registry()) reg(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int status = app.exit(e);  // (prints the help, the version or what is wrong with the command line)
    return status == 0 ? 0 : 1;
  } catch (const bezoutian::Limit_exceeded& e) {
    std::cerr << "bezoutian: error: " << e.what() << "\n";
    return bezoutian_cli::limit_exit_status;
  } catch (const bezoutian::Error& e) {
    std::cerr << "bezoutian: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "bezoutian: internal error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
