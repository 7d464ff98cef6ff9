// libFuzzer driver of the fuzz target polynomial_expression (targets.h).
#include "targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  bezoutian::fuzz::polynomial_expression(data, size);
  return 0;
}
