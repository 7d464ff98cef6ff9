// The failure path shared by every fuzz target: a message, then abort() so that libFuzzer keeps the input.
#include "targets.h"

#include <cstdio>
#include <cstdlib>

namespace bezoutian {
namespace fuzz {

std::string& current_input_name() {
  static std::string name;
  return name;
}

void fuzz_failure(const std::string& reason) {
  if (!current_input_name().empty()) std::fprintf(stderr, "fuzz input %s\n", current_input_name().c_str());
  std::fprintf(stderr, "fuzz failure: %s\n", reason.c_str());
  std::abort();
}

} // namespace fuzz
} // namespace bezoutian
