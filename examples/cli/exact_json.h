// The JSON forms shared by every command (doc/json_schema.md, schema doc/bezoutian-output.schema.json):
// - exact rationals as "p/q" (or "p") strings;
// - algebraic numbers exactly: the rational value, or the defining polynomial and an isolating interval with
//   rational ends, plus a decimal of algebraic_digits significant digits;
// - floating-point approximations (traced points, drawings) as the shortest decimal string that reads back to the
//   same double;
// - proved floating-point enclosures as decimal strings of enclosure_digits significant digits rounded outward, so
//   that the printed interval still holds what the double interval holds.
// Counts, indices, degrees, multiplicities and the measured "seconds" are the only JSON numbers.
#ifndef BEZOUTIAN_CLI_EXACT_JSON_H
#define BEZOUTIAN_CLI_EXACT_JSON_H

#include <bezoutian/algebraic/Algebraic_real.h>
#include <bezoutian/io/Exact_number.h>

#include "json_envelope.h"

#include <nlohmann/json.hpp>

#include <array>
#include <charconv>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace bezoutian_cli {

/// Significant digits of the decimals of algebraic numbers and of the points computed from them.
constexpr int algebraic_digits = 30;
/// Significant digits of outward-rounded enclosures.
constexpr int enclosure_digits = 17;

inline std::string exact(const bezoutian::Rational& q) { return bezoutian::io::to_exact_string(q); }

inline std::string exact(const bezoutian::Integer& z) {
  std::ostringstream s;
  s << z;
  return s.str();
}

/// A double as the shortest decimal string that reads back to it; null when it is not finite (not computed).
inline nlohmann::json approx(double x) {
  if (!std::isfinite(x)) return nullptr;
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

template <std::size_t N>
nlohmann::json approx(const std::array<double, N>& p) {
  nlohmann::json a = nlohmann::json::array();
  for (double x : p) a.push_back(approx(x));
  return a;
}

namespace internal {
// x to enclosure_digits significant digits, correctly rounded to nearest, without the zeros that end its fraction.
inline std::string nearest_decimal(const bezoutian::Rational& x) {
  const std::string s = bezoutian::Algebraic_real(x).to_decimal_string(enclosure_digits);
  const std::size_t e_at = s.find('e'), end = e_at == std::string::npos ? s.size() : e_at;
  std::string mantissa = s.substr(0, end);
  if (mantissa.find('.') != std::string::npos) {
    while (mantissa.back() == '0') mantissa.pop_back();
    if (mantissa.back() == '.') mantissa.pop_back();
  }
  return mantissa + s.substr(end);
}

// q rounded to enclosure_digits significant digits up (toward +infinity) or down. When the nearest decimal is on
// the wrong side, q moved by |q| 10^-16 that way is rounded instead: one unit in the last place is at most
// |q| 10^-16, so the nearest decimal to the moved number lies beyond q.
inline std::string directed_decimal(const bezoutian::Rational& q, bool up) {
  using bezoutian::Rational;
  if (CGAL::is_zero(q)) return "0";
  const std::string s = nearest_decimal(q);
  const Rational r = bezoutian::io::exact_number(s);
  if (up ? !(r < q) : !(q < r)) return s;
  Rational shift = CGAL::abs(q);
  for (int k = 0; k < enclosure_digits - 1; ++k) shift = shift / 10;
  return nearest_decimal(up ? q + shift : q - shift);
}
}  // namespace internal

/// A proved enclosure [lo, hi] of doubles as two decimal strings rounded outward; null when not finite.
inline nlohmann::json enclosure(double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) return nullptr;
  return {internal::directed_decimal(bezoutian::Rational(lo), false),
          internal::directed_decimal(bezoutian::Rational(hi), true)};
}

/// A proved upper bound as a decimal string rounded up; null when not finite (not proved).
inline nlohmann::json upper_bound(double x) {
  if (!std::isfinite(x)) return nullptr;
  return internal::directed_decimal(bezoutian::Rational(x), true);
}

/// An exact interval [lo, hi] with rational ends.
inline nlohmann::json exact_interval(const bezoutian::Rational& lo, const bezoutian::Rational& hi) {
  return {exact(lo), exact(hi)};
}

/// An algebraic number exactly: {"decimal", "rational"} for a rational, {"decimal", "polynomial", "interval"}
/// otherwise (the defining square-free integer polynomial, coefficients from degree 0 up, and an interval with
/// rational ends that holds no other of its roots); "interval" is [q, q] for a rational q.
inline nlohmann::json algebraic(const bezoutian::Algebraic_real& a) {
  nlohmann::json j;
  j["decimal"] = a.to_decimal_string(algebraic_digits);
  if (a.is_rational()) {
    const std::string q = exact(a.rational_value());
    j["rational"] = q;
    j["interval"] = {q, q};
    return j;
  }
  nlohmann::json poly = nlohmann::json::array();
  const auto f = a.polynomial();
  for (int i = 0; i <= f.degree(); ++i) poly.push_back(exact(f[i]));
  j["polynomial"] = poly;
  j["interval"] = exact_interval(a.lower(), a.upper());
  return j;
}

/// The algebraic number of a JSON object written by algebraic() (its rational, or its polynomial and interval).
inline bezoutian::Algebraic_real algebraic_from_json(const nlohmann::json& j) {
  if (j.contains("rational"))
    return bezoutian::Algebraic_real(bezoutian::io::exact_number(j.at("rational").get<std::string>()));
  std::vector<bezoutian::Integer> c;
  for (const auto& x : j.at("polynomial")) c.push_back(bezoutian::io::exact_number(x.get<std::string>()).numerator());
  const auto& i = j.at("interval");
  return bezoutian::Algebraic_real(bezoutian::Polynomial_1<bezoutian::Integer>(c.begin(), c.end()),
                                   bezoutian::io::exact_number(i.at(0).get<std::string>()),
                                   bezoutian::io::exact_number(i.at(1).get<std::string>()));
}

/// An exact end for text output: the rational itself, or (irrational) the decimal.
inline std::string exact_or_decimal(const bezoutian::Algebraic_real& a) {
  return a.is_rational() ? exact(a.rational_value()) : a.to_decimal_string(algebraic_digits);
}

} // namespace bezoutian_cli

#endif
