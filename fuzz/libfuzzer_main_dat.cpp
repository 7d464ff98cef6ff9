// libFuzzer driver of the fuzz target cgal_dat (targets.h).
#include "targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  bezoutian::fuzz::cgal_dat(data, size);
  return 0;
}
