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
  app.require_subcommand(1);
  for (auto& reg : bezoutian_cli::registry()) reg(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
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
