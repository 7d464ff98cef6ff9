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
