// bezoutian: command-line front end of the Bezoutian library.
#include "commands.h"

#include <bezoutian/arithmetic/Error.h>

#include <iostream>

namespace bezoutian_cli {
std::vector<Registration>& registry() {
  static std::vector<Registration> r;
  return r;
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
  } catch (const bezoutian::Error& e) {
    std::cerr << "bezoutian: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "bezoutian: internal error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
