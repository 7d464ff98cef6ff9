// Exact polynomial expressions such as "2*s^2 - t^2*s^2 - 5*t*s^2 + 7*s + 3/4": parsing and printing.
//
// Grammar (white space is ignored between tokens):
//   expression := term { ('+' | '-') term }
//   term       := unary { ('*' | '/' | juxtaposition) unary }      "/" only by a nonzero constant
//   unary      := ('+' | '-') unary | power
//   power      := primary [ ('^' | '**') exponent ]                exponent: unsigned integer literal
//   primary    := number | variable | '(' expression ')'
// Numbers are unsigned literals of Exact_number.h (integers, decimals "0.75", "2.5e-3", hex floats); a
// fraction "3/4" is the constant 3 divided by 4, so it denotes 3/4 exactly. Juxtaposition multiplies a
// factor by a following variable or parenthesis ("2s^2", "3 t^2 s", "(s+1)(t-1)"); two numbers or two
// variables need an explicit "*" or a space before a variable ("st" is one unknown name, "s t" is s*t).
// A decimal exponent is read as part of a number only when complete ("2e3" = 2000; "2e" = 2*e).
#ifndef BEZOUTIAN_IO_POLYNOMIAL_EXPRESSION_H
#define BEZOUTIAN_IO_POLYNOMIAL_EXPRESSION_H

#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/io/Exact_number.h>
#include <bezoutian/arithmetic/number_types.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace bezoutian {
namespace io {

/// An error in a polynomial expression; offset() is the offset of the offending character in the text.
class Expression_error : public Invalid_input {
 public:
  Expression_error(std::size_t offset, const std::string& message)
      : Invalid_input("offset " + std::to_string(offset) + ": " + message), offset_(offset), message_(message) {}
  std::size_t offset() const { return offset_; }
  /// The message without the offset prefix.
  const std::string& message() const { return message_; }

 private:
  std::size_t offset_;
  std::string message_;
};

/// Bounds that keep every expression cheap to expand.
struct Expression_limits {
  int max_degree = 100;      ///< largest degree in each variable, of the result and of every intermediate
  long max_exponent = 10000; ///< largest exponent after '^'
  int max_depth = 200;       ///< deepest nesting of parentheses / unary signs
  long max_constant_power_bits = 10000000;  ///< largest size of a constant power such as 7^1000, while expanding
  /// Largest numerator and denominator, in bits, of a coefficient of the expanded result (as for a number read,
  /// io::max_number_bits): products and powers of constants cannot bring the engine coefficients it cannot afford.
  std::size_t max_coefficient_bits = max_number_bits;
  /// Largest work of the expansion, in products of coefficient sizes: multiplying two polynomials costs the sum over
  /// all pairs of terms of (1 + limbs of one coefficient) (1 + limbs of the other), dividing by a constant the sum
  /// over the terms of (1 + limbs) (1 + limbs of the divisor). The degree bound alone admits 30-byte expressions
  /// such as ((s+1)(t+1))^50*((s+2)(t+3))^50, and large or repeated constants make each product dearer; this bound
  /// keeps every expression below about a second.
  double max_expansion_work = 5e7;
};

namespace internal {

inline bool is_identifier_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
inline bool is_identifier_char(char c) { return is_identifier_start(c) || is_digit(c); }

/// True if name is a valid variable name ([A-Za-z_][A-Za-z0-9_]*).
inline bool is_identifier(const std::string& name) {
  if (name.empty() || !is_identifier_start(name[0])) return false;
  return std::all_of(name.begin(), name.end(), is_identifier_char);
}

class Expression_parser {
 public:
  Expression_parser(const std::string& text, const std::vector<std::string>& variables, const Expression_limits& limits)
      : s_(text), vars_(variables), lim_(limits) {}

  Sparse_polynomial parse() {
    Sparse_polynomial p = expression();
    skip_space();
    if (pos_ < s_.size())
      throw Expression_error(pos_, "unexpected " + quoted_char(s_[pos_]) +
                                       "; expected an operator (+ - * / ^) or the end of the expression");
    for (const auto& t : p)
      for (mpz_srcptr z : {mpq_numref(t.second.mpq()), mpq_denref(t.second.mpq())})
        if (mpz_sizeinbase(z, 2) > lim_.max_coefficient_bits)
          throw Expression_error(0, "a coefficient of the expanded polynomial has " +
                                        std::to_string(mpz_sizeinbase(z, 2)) + " bits (at most " +
                                        std::to_string(lim_.max_coefficient_bits) + ")");
    return p;
  }

 private:
  void skip_space() {
    while (pos_ < s_.size() && is_space(s_[pos_])) ++pos_;
  }
  char peek() {
    skip_space();
    return pos_ < s_.size() ? s_[pos_] : '\0';
  }

  std::string variable_list() const {
    std::string r;
    for (std::size_t i = 0; i < vars_.size(); ++i) r += (i ? (i + 1 == vars_.size() ? " or " : ", ") : "") + vars_[i];
    return r;
  }

  Sparse_polynomial constant(const Rational& c) const {
    Sparse_polynomial p;
    if (!CGAL::is_zero(c)) p[std::vector<int>(vars_.size(), 0)] = c;
    return p;
  }

  std::vector<int> degrees(const Sparse_polynomial& p) const {
    std::vector<int> d(vars_.size(), 0);
    for (const auto& t : p)
      for (std::size_t k = 0; k < d.size(); ++k) d[k] = std::max(d[k], t.first[k]);
    return d;
  }

  static bool is_constant(const Sparse_polynomial& p) {
    for (const auto& t : p)
      if (std::any_of(t.first.begin(), t.first.end(), [](int e) { return e != 0; })) return false;
    return true;
  }

  Rational constant_value(const Sparse_polynomial& p) const {
    return p.empty() ? Rational(0) : p.begin()->second;
  }

  static void add_to(Sparse_polynomial& a, const Sparse_polynomial& b, bool subtract) {
    for (const auto& t : b) {
      Rational& c = a[t.first];
      if (subtract)
        c -= t.second;
      else
        c += t.second;
      if (CGAL::is_zero(c)) a.erase(t.first);
    }
  }

  // 1 + limbs of a coefficient, summed over the terms
  static double size_in_limbs(const Sparse_polynomial& p) {
    double w = 0;
    for (const auto& t : p) w += 1.0 + double(mpz_size(mpq_numref(t.second.mpq())) + mpz_size(mpq_denref(t.second.mpq())));
    return w;
  }

  void spend(double work, std::size_t where) {
    work_ += work;
    if (work_ > lim_.max_expansion_work)
      throw Expression_error(where, "expanding the expression takes more than " +
                                        std::to_string(static_cast<long long>(lim_.max_expansion_work)) +
                                        " products of coefficient limbs (Expression_limits::max_expansion_work)");
  }

  Sparse_polynomial multiply(const Sparse_polynomial& a, const Sparse_polynomial& b, std::size_t where) {
    std::vector<int> da = degrees(a), db = degrees(b);
    for (std::size_t k = 0; k < vars_.size(); ++k)
      if (!a.empty() && !b.empty() && da[k] + db[k] > lim_.max_degree)
        throw Expression_error(where, "the degree in " + vars_[k] + " exceeds " + std::to_string(lim_.max_degree));
    spend(size_in_limbs(a) * size_in_limbs(b), where);
    Sparse_polynomial r;
    for (const auto& x : a)
      for (const auto& y : b) {
        std::vector<int> e = x.first;
        for (std::size_t k = 0; k < e.size(); ++k) e[k] += y.first[k];
        Rational& c = r[e];
        c += x.second * y.second;
        if (CGAL::is_zero(c)) r.erase(e);
      }
    return r;
  }

  void enter(std::size_t where) {
    if (++depth_ > lim_.max_depth)
      throw Expression_error(where, "expression nested deeper than " + std::to_string(lim_.max_depth) + " levels");
  }
  void leave() { --depth_; }

  Sparse_polynomial expression() {
    Sparse_polynomial p = term();
    for (char c = peek(); c == '+' || c == '-'; c = peek()) {
      ++pos_;
      add_to(p, term(), c == '-');
    }
    return p;
  }

  Sparse_polynomial term() {
    Sparse_polynomial p = unary();
    for (;;) {
      char c = peek();
      const std::size_t op = pos_;
      if (c == '*' && !(pos_ + 1 < s_.size() && s_[pos_ + 1] == '*')) {
        ++pos_;
        p = multiply(p, unary(), op);
      } else if (c == '/') {
        ++pos_;
        skip_space();
        const std::size_t divisor_start = pos_;
        Sparse_polynomial d = unary();
        if (!is_constant(d))
          throw Expression_error(divisor_start, "division by a non-constant polynomial (only constant divisors are allowed)");
        if (d.empty()) throw Expression_error(divisor_start, "division by zero");
        const Rational q = constant_value(d);
        spend(size_in_limbs(p) * size_in_limbs(d), op);
        for (auto& t : p) t.second /= q;
      } else if (is_identifier_start(c) || c == '(') {
        p = multiply(p, unary(), op);  // juxtaposition: "2s", "(s+1)(t-1)"
      } else {
        return p;
      }
    }
  }

  Sparse_polynomial unary() {
    char c = peek();
    if (c == '+' || c == '-') {
      enter(pos_);
      ++pos_;
      Sparse_polynomial p = unary();
      leave();
      if (c == '-')
        for (auto& t : p) t.second = -t.second;
      return p;
    }
    return power();
  }

  Sparse_polynomial power() {
    Sparse_polynomial base = primary();
    char c = peek();
    if (c != '^' && !(c == '*' && pos_ + 1 < s_.size() && s_[pos_ + 1] == '*')) return base;
    const std::size_t op = pos_;
    pos_ += c == '^' ? 1 : 2;
    skip_space();
    if (pos_ >= s_.size() || !is_digit(s_[pos_]))
      throw Expression_error(pos_, std::string("expected a non-negative integer exponent after '^', got ") +
                                       (pos_ >= s_.size() ? "the end of the expression" : quoted_char(s_[pos_])));
    const std::size_t exponent_start = pos_;
    long e = 0;
    while (pos_ < s_.size() && is_digit(s_[pos_])) {
      e = e * 10 + (s_[pos_++] - '0');
      if (e > lim_.max_exponent)
        throw Expression_error(exponent_start, "exponent too large (at most " + std::to_string(lim_.max_exponent) + ")");
    }
    if (pos_ < s_.size() && (s_[pos_] == '.' || s_[pos_] == '/'))
      throw Expression_error(exponent_start, "expected a non-negative integer exponent");
    if (!base.empty() && is_constant(base)) {
      // a constant power: keep its size bounded, (bits of p + bits of q) * e <= max_constant_power_bits
      const mpq_t& q = base.begin()->second.mpq();
      const double bits = double(mpz_sizeinbase(mpq_numref(q), 2) + mpz_sizeinbase(mpq_denref(q), 2)) * double(e);
      if (bits > double(lim_.max_constant_power_bits))
        throw Expression_error(op, "the constant power has more than " + std::to_string(lim_.max_constant_power_bits) + " bits");
    }
    if (!base.empty() && !is_constant(base)) {
      std::vector<int> d = degrees(base);
      for (std::size_t k = 0; k < d.size(); ++k)
        if (static_cast<long>(d[k]) * e > lim_.max_degree)
          throw Expression_error(op, "the degree in " + vars_[k] + " exceeds " + std::to_string(lim_.max_degree));
    }
    // binary powering
    Sparse_polynomial result = constant(Rational(1)), b = base;
    for (long k = e; k > 0; k >>= 1) {
      if (k & 1) result = multiply(result, b, op);
      if (k > 1) b = multiply(b, b, op);
    }
    return result;
  }

  Sparse_polynomial primary() {
    char c = peek();
    const std::size_t start = pos_;
    if (c == '(') {
      enter(start);
      ++pos_;
      Sparse_polynomial p = expression();
      if (peek() != ')')
        throw Expression_error(pos_, std::string("expected ')' to close the '(' at offset ") + std::to_string(start) +
                                         ", got " + (pos_ >= s_.size() ? "the end of the expression" : quoted_char(s_[pos_])));
      ++pos_;
      leave();
      return p;
    }
    if (is_digit(c) || c == '.') {
      Rational v;
      std::size_t err = 0;
      std::string msg;
      if (!scan_unsigned_number(s_, pos_, v, err, msg, true)) throw Expression_error(err, msg);
      return constant(v);
    }
    if (is_identifier_start(c)) {
      while (pos_ < s_.size() && is_identifier_char(s_[pos_])) ++pos_;
      const std::string name = s_.substr(start, pos_ - start);
      for (std::size_t k = 0; k < vars_.size(); ++k)
        if (vars_[k] == name) {
          Sparse_polynomial p;
          std::vector<int> e(vars_.size(), 0);
          e[k] = 1;
          p[e] = Rational(1);
          return p;
        }
      throw Expression_error(start, "unknown variable '" + name + "'; expected a number or the variable" +
                                        (vars_.size() > 1 ? "s " : " ") + variable_list());
    }
    throw Expression_error(start, std::string("expected a number, a variable (") + variable_list() + ") or '(', got " +
                                      (c == '\0' && pos_ >= s_.size() ? "the end of the expression" : quoted_char(c)));
  }

  const std::string& s_;
  const std::vector<std::string>& vars_;
  Expression_limits lim_;
  std::size_t pos_ = 0;
  int depth_ = 0;
  double work_ = 0;  // spent so far, see Expression_limits::max_expansion_work
};

} // namespace internal

/// \brief Parses a polynomial expression in the given variables exactly.
/// Throws Expression_error (an Invalid_input) with the offset of the offending character.
inline Sparse_polynomial parse_polynomial_expression(const std::string& text, const std::vector<std::string>& variables,
                                                     const Expression_limits& limits = Expression_limits()) {
  for (const std::string& v : variables)
    if (!internal::is_identifier(v)) throw Invalid_input("'" + v + "' is not a valid variable name");
  return internal::Expression_parser(text, variables, limits).parse();
}

/// Univariate polynomial from an expression in `variable`.
inline Polynomial_1<Rational> parse_polynomial_1(const std::string& text, const std::string& variable,
                                                 const Expression_limits& limits = Expression_limits()) {
  Sparse_polynomial p = parse_polynomial_expression(text, {variable}, limits);
  int d = 0;
  for (const auto& t : p) d = std::max(d, t.first[0]);
  std::vector<Rational> c(d + 1, Rational(0));
  for (const auto& t : p) c[t.first[0]] = t.second;
  return Polynomial_1<Rational>(c.begin(), c.end());
}

/// Bivariate polynomial from an expression in (u, v): u is the inner variable (index 0), v the outer one.
inline Polynomial_2<Rational> parse_polynomial_2(const std::string& text, const std::string& u, const std::string& v,
                                                 const Expression_limits& limits = Expression_limits()) {
  if (u == v) throw Invalid_input("the two variables must have different names, got '" + u + "' twice");
  Sparse_polynomial p = parse_polynomial_expression(text, {u, v}, limits);
  int du = 0, dv = 0;
  for (const auto& t : p) {
    du = std::max(du, t.first[0]);
    dv = std::max(dv, t.first[1]);
  }
  std::vector<std::vector<Rational>> c(dv + 1, std::vector<Rational>(du + 1, Rational(0)));
  for (const auto& t : p) c[t.first[1]][t.first[0]] = t.second;
  std::vector<Polynomial_1<Rational>> outer;
  for (const auto& row : c) outer.emplace_back(row.begin(), row.end());
  return Polynomial_2<Rational>(outer.begin(), outer.end());
}

} // namespace io
} // namespace bezoutian

#endif // BEZOUTIAN_IO_POLYNOMIAL_EXPRESSION_H
