// libFuzzer driver of the fuzz target planar_curves (targets.h).
#include "targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  bezoutian::fuzz::planar_curves(data, size);
  return 0;
}
