// Fuzz target: power-basis polynomial expressions (io/Polynomial_expression.h) and exact numbers
// (io/Exact_number.h), which every reader uses.
#include "targets.h"

#include <bezoutian/io/Exact_number.h>
#include <bezoutian/io/Polynomial_expression.h>

#include <exception>
#include <string>
#include <typeinfo>

namespace bezoutian {
namespace fuzz {

namespace {

bool within_number_bits(const Rational& q, std::size_t bits) {
  return mpz_sizeinbase(mpq_numref(q.mpq()), 2) <= bits && mpz_sizeinbase(mpq_denref(q.mpq()), 2) <= bits;
}

// A number read obeys max_number_bits, and both of its printed forms read back equal.
void exact_number(const std::string& text) {
  const io::Exact_number_result r = io::parse_exact_number(text);
  if (!r.ok) {
    if (r.error_offset > text.size() || r.message.empty()) fuzz_failure("a refused number without a place or a reason");
    return;
  }
  if (!within_number_bits(r.value, io::max_number_bits)) fuzz_failure("a number read exceeds max_number_bits: " + text);
  for (const std::string& printed : {io::to_exact_string(r.value), io::to_exact_decimal_string(r.value)}) {
    const io::Exact_number_result again = io::parse_exact_number(printed);
    if (!again.ok || again.value != r.value)
      fuzz_failure("the number " + printed + " does not read back" + (again.ok ? " equal" : ": " + again.message));
  }
}

// Tighter bounds than the defaults: the target checks the parser, not the cost of the default limits (an
// expression near the default work bound takes seconds under the sanitizers, which would starve the search).
io::Expression_limits fuzz_limits() {
  io::Expression_limits limits;
  limits.max_degree = 24;
  limits.max_expansion_work = 1e6;
  limits.max_constant_power_bits = 100000;
  return limits;
}

// A polynomial read obeys the coefficient bound, and its printed form reads back equal.
template <class Parse, class Print>
void expression(const std::string& text, Parse parse, Print print) {
  decltype(parse(text)) p;
  try {
    p = parse(text);
  } catch (const io::Expression_error& e) {
    if (e.offset() > text.size()) fuzz_failure("an expression error after the end of the text: " + std::string(e.what()));
    return;
  }
  const std::string printed = print(p);
  try {
    if (!(parse(printed) == p)) fuzz_failure("the expression " + printed + " does not read back equal");
  } catch (const io::Expression_error& e) {
    fuzz_failure("the printed expression " + printed + " is refused: " + e.what());
  }
}

} // namespace

void polynomial_expression(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    switch (data[0] % 3) {
      case 0:
        exact_number(text);
        break;
      case 1:
        expression(text, [](const std::string& s) { return io::parse_polynomial_1(s, "t", fuzz_limits()); },
                   [](const Polynomial_1<Rational>& p) { return io::polynomial_to_string(p, "t"); });
        break;
      default:
        expression(text, [](const std::string& s) { return io::parse_polynomial_2(s, "s", "t", fuzz_limits()); },
                   [](const Polynomial_2<Rational>& p) { return io::polynomial_to_string(p, "s", "t"); });
    }
  } catch (const std::exception& e) {
    fuzz_failure(std::string("the expression reader threw ") + typeid(e).name() + ": " + e.what());
  } catch (...) {
    fuzz_failure("the expression reader threw something that is not a std::exception");
  }
}

} // namespace fuzz
} // namespace bezoutian
