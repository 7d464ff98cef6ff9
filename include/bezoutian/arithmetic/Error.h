// Exceptions thrown by Bezoutian. Every failure on bad input is one of these,
// with a message that says what was expected (and, for files, where).
#ifndef BEZOUTIAN_ARITHMETIC_ERROR_H
#define BEZOUTIAN_ARITHMETIC_ERROR_H

#include <stdexcept>
#include <string>

namespace bezoutian {

/// Base class of all Bezoutian errors.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& what) : std::runtime_error(what) {}
};

/// The input describes no valid object (zero weight, pole in the domain, wrong sizes...).
class Invalid_input : public Error {
 public:
  explicit Invalid_input(const std::string& what) : Error(what) {}
};

/// \brief A computation was stopped by one of the limits of its options: an input larger than a size limit
/// (degree, control points, coefficient bits, degree product) or an exhausted time budget.
///
/// The message reads "<function>: <limit> exceeded in <stage>: <details>"; stage() names the step of the computation
/// that was reached ("input" for a size limit checked before any computation) and limit() the option
/// (e.g. "max_degree", "time_limit").
class Limit_exceeded : public Error {
 public:
  Limit_exceeded(const std::string& function, const std::string& stage, const std::string& limit,
                 const std::string& details)
      : Error(function + ": " + limit + " exceeded in " + stage + ": " + details), stage_(stage), limit_(limit) {}
  /// The step of the computation where the limit was checked ("input" for the size limits).
  const std::string& stage() const { return stage_; }
  /// The name of the limit, as in the options (max_degree, max_control_points, max_coefficient_bits,
  /// max_degree_product, time_limit).
  const std::string& limit() const { return limit_; }

 private:
  std::string stage_, limit_;
};

/// \brief The time budget of a computation ran out (limit() is "time_limit"); stage() names the step that was
/// reached when the budget was found exhausted.
class Budget_exceeded : public Limit_exceeded {
 public:
  Budget_exceeded(const std::string& function, const std::string& stage, const std::string& details)
      : Limit_exceeded(function, stage, "time_limit", details) {}
};

/// A file could not be read; the message starts with "file:line:column: ".
class Parse_error : public Error {
 public:
  Parse_error(const std::string& file, std::size_t line, std::size_t column, const std::string& message)
      : Error(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message),
        file_(file), line_(line), column_(column) {}
  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }
  std::size_t column() const { return column_; }

 private:
  std::string file_;
  std::size_t line_, column_;
};

} // namespace bezoutian

#endif // BEZOUTIAN_ARITHMETIC_ERROR_H
