// libFuzzer driver of the fuzz target bpt (targets.h).
#include "targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  bezoutian::fuzz::bpt(data, size);
  return 0;
}
