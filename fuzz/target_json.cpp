// Fuzz target: JSON geometry documents (io/Json_format.h).
#include "parse_error_check.h"
#include "targets.h"

#include <bezoutian/io/Json_format.h>

#include <algorithm>
#include <exception>
#include <string>
#include <typeinfo>

namespace bezoutian {
namespace fuzz {

namespace {

bool same_document(const io::Geometry_document& a, const io::Geometry_document& b) {
  return a.curves_2 == b.curves_2 && a.curves_3 == b.curves_3 && a.patches == b.patches &&
         a.curve_2_names == b.curve_2_names && a.curve_3_names == b.curve_3_names && a.patch_names == b.patch_names;
}

int largest_degree(const io::Geometry_document& doc) {
  int d = 0;
  for (const auto& c : doc.curves_2) d = std::max(d, c.degree());
  for (const auto& c : doc.curves_3) d = std::max(d, c.degree());
  for (const auto& p : doc.patches) d = std::max({d, p.degree_u(), p.degree_v()});
  return d;
}

// write_json() promises a text that read_json() reads back equal, in the Bernstein basis always. In the power
// basis the expression limits (degree 100, coefficient bits) may refuse a legal document; what is read must be equal.
// The power-basis writer costs seconds from degree 200 on, so only low degrees take that path.
void check_round_trip(const io::Geometry_document& doc) {
  const std::string bernstein = io::write_json(doc);
  io::Geometry_document again;
  try {
    again = io::read_json(bernstein, "written.json");
  } catch (const Parse_error& e) {
    fuzz_failure(std::string("write_json() gave a text that read_json() refuses: ") + e.what() + "\n" + bernstein);
  }
  if (!same_document(doc, again)) fuzz_failure("the Bernstein round trip changed the document:\n" + bernstein);
  if (largest_degree(doc) > 8) return;
  io::Json_write_options power;
  power.basis = io::Json_basis::power;
  const std::string text = io::write_json(doc, power);
  try {
    again = io::read_json(text, "written.json");
  } catch (const Parse_error&) {
    return;
  }
  if (!same_document(doc, again)) fuzz_failure("the power-basis round trip changed the document:\n" + text);
}

} // namespace

void json_document(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  io::Geometry_document doc;
  try {
    doc = io::read_json(text, "fuzz.json");
  } catch (const Parse_error& e) {
    check_parse_error(e, text, "fuzz.json");
    return;
  } catch (const std::exception& e) {
    fuzz_failure(std::string("read_json() threw ") + typeid(e).name() + ": " + e.what());
  } catch (...) {
    fuzz_failure("read_json() threw something that is not a std::exception");
  }
  try {
    check_round_trip(doc);
  } catch (const std::exception& e) {
    fuzz_failure(std::string("the JSON round trip threw ") + typeid(e).name() + ": " + e.what());
  }
}

} // namespace fuzz
} // namespace bezoutian
