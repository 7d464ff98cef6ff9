// libFuzzer driver of the fuzz target small_patches (targets.h).
#include "targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  bezoutian::fuzz::small_patches(data, size);
  return 0;
}
