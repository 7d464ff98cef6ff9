// libFuzzer driver of the fuzz target json_document (targets.h).
#include "targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  bezoutian::fuzz::json_document(data, size);
  return 0;
}
