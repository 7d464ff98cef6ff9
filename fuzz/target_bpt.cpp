// Fuzz target: BPT Bezier patches (io/Bpt_format.h).
#include "parse_error_check.h"
#include "targets.h"

#include <bezoutian/io/Bpt_format.h>

#include <exception>
#include <string>
#include <typeinfo>

namespace bezoutian {
namespace fuzz {

void bpt(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  io::Geometry_document doc;
  try {
    doc = io::read_bpt(text, "fuzz.bpt");
  } catch (const Parse_error& e) {
    check_parse_error(e, text, "fuzz.bpt");
    return;
  } catch (const std::exception& e) {
    fuzz_failure(std::string("read_bpt() threw ") + typeid(e).name() + ": " + e.what());
  } catch (...) {
    fuzz_failure("read_bpt() threw something that is not a std::exception");
  }
  // every document read_bpt() gives holds polynomial patches, which write_bpt() writes exactly
  try {
    const std::string written = io::write_bpt(doc);
    if (!(io::read_bpt(written, "written.bpt").patches == doc.patches))
      fuzz_failure("the .bpt round trip changed the patches:\n" + written);
  } catch (const std::exception& e) {
    fuzz_failure(std::string("the .bpt round trip threw ") + typeid(e).name() + ": " + e.what());
  }
}

} // namespace fuzz
} // namespace bezoutian
