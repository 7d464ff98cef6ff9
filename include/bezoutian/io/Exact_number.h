// Exact parsing and printing of rational numbers written as text.
//
// Every number in a geometry file is an exact rational: an integer ("-12"), a fraction ("3/4"), a decimal
// literal ("0.784", "-2.5e-3") or a C99 hexadecimal float ("0x1.b7537f52e7c79p-3", as printed by "%a").
// All of them denote a rational number m * 10^e or m * 2^e exactly; nothing goes through a double.
#ifndef BEZOUTIAN_IO_EXACT_NUMBER_H
#define BEZOUTIAN_IO_EXACT_NUMBER_H

#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/arithmetic/exact_text.h>
#include <bezoutian/arithmetic/number_types.h>

#include <gmp.h>

#include <cstddef>
#include <string>

namespace bezoutian {
namespace io {

/// Largest |exponent| accepted in a decimal literal ("1e100000"): 10^100000 has 332,193 bits.
constexpr long max_decimal_exponent = 100000;
/// Largest |exponent| accepted in a hexadecimal float ("0x1p-400000").
constexpr long max_binary_exponent = 400000;
/// Largest size, in bits, of the numerator and of the denominator of one number read (1e1000 has 3,322 bits; a
/// double's range ends near 1e308). Coefficients beyond it are refused as input: the modular resultants that curves
/// with such coefficients reach cost far more than their size suggests (a quadratic with the coordinate 1e3000 never
/// finished).
constexpr std::size_t max_number_bits = 4096;
/// Largest degree of a curve, and of a patch in u and in v, that the readers accept: at most 1001 control points per
/// curve and per row or column of a net. Far above CAD data (degrees <= 25) and above the intersection limits
/// (Intersection_limits::max_degree = 64), so that `info` still describes such files; a curve with 100,000 control
/// points is refused at its count (file:line:column) before it is read.
constexpr std::size_t max_object_degree = 1000;

/// Outcome of parsing a number: the value, or the offset of the offending character and what was expected.
struct Exact_number_result {
  bool ok = false;
  Rational value;
  std::size_t error_offset = 0;  ///< offset into the parsed text of the first character that does not fit
  std::string message;           ///< e.g. "expected a digit after the exponent sign"
};

namespace internal {

inline bool is_digit(char c) { return c >= '0' && c <= '9'; }
inline bool is_hex_digit(char c) { return is_digit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }
inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

/// True (and a message) if the numerator or the denominator of q, in lowest terms, exceeds max_number_bits.
inline bool exceeds_number_bits(const Rational& q, std::string& message) {
  for (mpz_srcptr part : {mpq_numref(q.mpq()), mpq_denref(q.mpq())})
    if (mpz_sgn(part) != 0 && mpz_sizeinbase(part, 2) > max_number_bits) {
      message = "number too large: " + std::to_string(mpz_sizeinbase(part, 2)) + " bits in its " +
                (part == mpq_numref(q.mpq()) ? "numerator" : "denominator") + " (at most " +
                std::to_string(max_number_bits) + ")";
      return true;
    }
  return false;
}

inline std::string quoted_char(char c) {
  if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return "a control character";
  return std::string("'") + c + "'";
}

} // namespace internal

/// \brief Scans an unsigned number (decimal literal or hex float, no sign, no fraction bar) at text[pos].
///
/// On success returns true, stores the value and advances `pos` past the literal. A decimal exponent
/// ('e') or a binary exponent ('p') is consumed only when it is complete (a letter, an optional sign and
/// digits) if `lenient_exponent` is set, so that "2e" in an expression can be read as 2 followed by a
/// variable e; otherwise an incomplete exponent is an error. On failure `error_offset`/`message` say why.
inline bool scan_unsigned_number(const std::string& text, std::size_t& pos, Rational& value,
                                 std::size_t& error_offset, std::string& message, bool lenient_exponent = false) {
  using internal::is_digit;
  using internal::is_hex_digit;
  const std::size_t n = text.size();
  std::size_t p = pos;
  const bool hex = p + 1 < n && text[p] == '0' && (text[p + 1] == 'x' || text[p + 1] == 'X');
  auto digit_ok = [&](char c) { return hex ? is_hex_digit(c) : is_digit(c); };
  if (hex) p += 2;
  std::string mantissa;
  std::size_t fraction_digits = 0;
  while (p < n && digit_ok(text[p])) mantissa += text[p++];
  if (p < n && text[p] == '.') {
    ++p;
    while (p < n && digit_ok(text[p])) {
      mantissa += text[p++];
      ++fraction_digits;
    }
  }
  if (mantissa.empty()) {
    error_offset = p;
    if (p >= n)
      message = hex ? "expected a hexadecimal digit, got the end of the number"
                    : "expected a number (integer, p/q, decimal or hex float), got the end of the text";
    else
      message = std::string(hex ? "expected a hexadecimal digit" : "expected a digit") + ", got " +
                internal::quoted_char(text[p]);
    return false;
  }
  // optional exponent: e/E (decimal, power of 10) or p/P (hex, power of 2)
  long exponent = 0;
  const char exp_letter_lo = hex ? 'p' : 'e', exp_letter_hi = hex ? 'P' : 'E';
  if (p < n && (text[p] == exp_letter_lo || text[p] == exp_letter_hi)) {
    std::size_t q = p + 1;
    bool negative = false;
    if (q < n && (text[q] == '+' || text[q] == '-')) negative = text[q++] == '-';
    if (q >= n || !is_digit(text[q])) {
      if (!lenient_exponent) {
        error_offset = q;
        message = std::string("expected a digit in the exponent, got ") +
                  (q >= n ? std::string("the end of the number") : internal::quoted_char(text[q]));
        return false;
      }
      // leave the letter for the caller (e.g. a variable named e)
    } else {
      const long limit = hex ? max_binary_exponent : max_decimal_exponent;
      const std::size_t exponent_start = q;
      while (q < n && is_digit(text[q])) {
        exponent = exponent * 10 + (text[q] - '0');
        if (exponent > limit) {
          error_offset = exponent_start;
          message = "exponent too large (at most " + std::to_string(limit) + ")";
          return false;
        }
        ++q;
      }
      if (negative) exponent = -exponent;
      p = q;
    }
  }
  // value = mantissa * base^(exponent - fraction_digits), base 10 or 2^4 per hex digit
  Integer m;
  mpz_set_str(m.mpz(), mantissa.c_str(), hex ? 16 : 10);  // digits were checked above
  Integer num = m, den(1);
  if (hex) {
    long e2 = exponent - 4 * static_cast<long>(fraction_digits);
    if (e2 >= 0)
      mpz_mul_2exp(num.mpz(), num.mpz(), static_cast<mp_bitcnt_t>(e2));
    else
      mpz_mul_2exp(den.mpz(), den.mpz(), static_cast<mp_bitcnt_t>(-e2));
  } else {
    long e10 = exponent - static_cast<long>(fraction_digits);
    Integer power;
    mpz_ui_pow_ui(power.mpz(), 10, static_cast<unsigned long>(e10 >= 0 ? e10 : -e10));
    if (e10 >= 0)
      num = num * power;
    else
      den = power;
  }
  // the bound applies to the value in lowest terms: "0.5" has the numerator 1, and the decimal text of 2^-4000
  // (4000 digits, as to_exact_decimal_string() writes it) is read back
  value = Rational(num, den);
  if (internal::exceeds_number_bits(value, message)) {
    error_offset = pos;
    return false;
  }
  pos = p;
  return true;
}

/// \brief Parses the whole text as an exact rational number.
///
/// Accepted: optional surrounding white space, an optional sign, then an integer, a decimal literal
/// ("0.784", ".5", "2.", "-2.5e-3"), or a C99 hex float ("0x1.8p1", binary exponent optional), optionally
/// followed by "/" and an unsigned denominator of the same forms ("3/4", "1.5/2"). Infinities and NaN are
/// rejected. Exponents are limited by max_decimal_exponent / max_binary_exponent so that no input can
/// ask for an astronomically large number.
inline Exact_number_result parse_exact_number(const std::string& text) {
  Exact_number_result r;
  const std::size_t n = text.size();
  std::size_t p = 0;
  while (p < n && internal::is_space(text[p])) ++p;
  if (p >= n) {
    r.error_offset = p;
    r.message = "expected a number (integer, p/q, decimal or hex float), got an empty string";
    return r;
  }
  bool negative = false;
  if (text[p] == '+' || text[p] == '-') negative = text[p++] == '-';
  // friendlier message for inf / nan
  if (p < n && (text[p] == 'i' || text[p] == 'I' || text[p] == 'n' || text[p] == 'N')) {
    r.error_offset = p;
    r.message = "expected an exact number (integer, p/q, decimal or hex float); infinities and NaN are not allowed";
    return r;
  }
  Rational numerator;
  const std::size_t start = p;
  if (!scan_unsigned_number(text, p, numerator, r.error_offset, r.message)) return r;
  if (p < n && text[p] == '/') {
    const std::size_t bar = p++;
    Rational denominator;
    if (p < n && (text[p] == '+' || text[p] == '-')) {
      r.error_offset = p;
      r.message = "expected an unsigned denominator after '/' (write the sign in front of the numerator)";
      return r;
    }
    if (!scan_unsigned_number(text, p, denominator, r.error_offset, r.message)) return r;
    if (CGAL::is_zero(denominator)) {
      r.error_offset = bar + 1;
      r.message = "the denominator is zero";
      return r;
    }
    numerator /= denominator;
    // each part obeys the bound, their quotient may not ("1e1000/1e-1000" is 10^2000)
    if (internal::exceeds_number_bits(numerator, r.message)) {
      r.error_offset = start;
      return r;
    }
  }
  while (p < n && internal::is_space(text[p])) ++p;
  if (p < n) {
    r.error_offset = p;
    r.message = "unexpected " + internal::quoted_char(text[p]) +
                " after the number (expected an integer, p/q, decimal or hex float)";
    return r;
  }
  r.ok = true;
  r.value = negative ? -numerator : numerator;
  return r;
}

/// Parses the whole text as an exact rational; throws Invalid_input (with the offending offset in the message).
inline Rational exact_number(const std::string& text) {
  Exact_number_result r = parse_exact_number(text);
  if (!r.ok)
    throw Invalid_input("\"" + text.substr(0, 40) + (text.size() > 40 ? "..." : "") + "\" at offset " +
                        std::to_string(r.error_offset) + ": " + r.message);
  return r.value;
}

} // namespace io
} // namespace bezoutian

#endif // BEZOUTIAN_IO_EXACT_NUMBER_H
