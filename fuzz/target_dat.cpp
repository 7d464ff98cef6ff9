// Fuzz target: CGAL .dat Bezier curves (io/Cgal_dat_format.h).
#include "parse_error_check.h"
#include "targets.h"

#include <bezoutian/io/Cgal_dat_format.h>

#include <exception>
#include <string>
#include <typeinfo>

namespace bezoutian {
namespace fuzz {

void cgal_dat(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  io::Geometry_document doc;
  try {
    doc = io::read_dat(text, "fuzz.dat");
  } catch (const Parse_error& e) {
    check_parse_error(e, text, "fuzz.dat");
    return;
  } catch (const std::exception& e) {
    fuzz_failure(std::string("read_dat() threw ") + typeid(e).name() + ": " + e.what());
  } catch (...) {
    fuzz_failure("read_dat() threw something that is not a std::exception");
  }
  // every document read_dat() gives holds planar polynomial curves, which write_dat() writes exactly
  try {
    const std::string written = io::write_dat(doc);
    if (!(io::read_dat(written, "written.dat").curves_2 == doc.curves_2))
      fuzz_failure("the .dat round trip changed the curves:\n" + written);
  } catch (const std::exception& e) {
    fuzz_failure(std::string("the .dat round trip threw ") + typeid(e).name() + ": " + e.what());
  }
}

} // namespace fuzz
} // namespace bezoutian
