// JSON forms of exact numbers shared by the intersection commands: rationals as "p/q" strings, algebraic numbers as
// their exact isolating interval (or the rational itself) and as 30-digit decimals.
#ifndef BEZOUTIAN_CLI_EXACT_JSON_H
#define BEZOUTIAN_CLI_EXACT_JSON_H

#include <bezoutian/algebraic/Algebraic_real.h>
#include <bezoutian/io/Exact_number.h>

#include <nlohmann/json.hpp>

#include <string>

namespace bezoutian_cli {

inline std::string exact(const bezoutian::Rational& q) { return bezoutian::io::to_exact_string(q); }

/// An exact end: the rational itself, or (irrational) the 30-digit decimal.
inline std::string exact_or_decimal(const bezoutian::Algebraic_real& a) {
  return a.is_rational() ? exact(a.rational_value()) : a.to_decimal_string(30);
}

/// The isolating interval as a pair of exact rationals (both ends equal for a rational number).
inline nlohmann::json interval(const bezoutian::Algebraic_real& a) {
  if (a.is_rational()) return {exact(a.rational_value()), exact(a.rational_value())};
  return {exact(a.lower()), exact(a.upper())};
}

} // namespace bezoutian_cli

#endif
