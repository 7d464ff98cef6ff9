// Helpers shared by the file readers: reading a file, line:column of an offset, white-space tokens.
#ifndef BEZOUTIAN_IO_TEXT_TOKENS_H
#define BEZOUTIAN_IO_TEXT_TOKENS_H

#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/io/Exact_number.h>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace bezoutian {
namespace io {

/// 1-based line and column of a place in a text; columns count bytes (a tab is one column).
struct Text_position {
  std::size_t line = 1;
  std::size_t column = 1;
};

/// Maps byte offsets of a text to line:column.
class Line_index {
 public:
  explicit Line_index(const std::string& text) {
    starts_.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') starts_.push_back(i + 1);
  }
  Text_position position(std::size_t offset) const {
    auto it = std::upper_bound(starts_.begin(), starts_.end(), offset);
    const std::size_t line = static_cast<std::size_t>(it - starts_.begin());  // >= 1
    return {line, offset - starts_[line - 1] + 1};
  }

 private:
  std::vector<std::size_t> starts_;
};

/// Reads a whole file; throws Parse_error(path, 1, 1, ...) if it cannot be read.
inline std::string read_text_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw Parse_error(path, 1, 1, "is a directory, expected a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Parse_error(path, 1, 1, "cannot open the file for reading");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw Parse_error(path, 1, 1, "error while reading the file");
  return text;
}

/// Writes a whole file; throws Error if it cannot be written.
inline void write_text_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw Error(path + ": cannot open the file for writing");
  out << text;
  out.close();
  if (!out) throw Error(path + ": error while writing the file");
}

/// A white-space separated token with its place in the text.
struct Text_token {
  std::string text;
  std::size_t offset = 0;
  Text_position position;
};

/// \brief Splits a text into white-space separated tokens; '#' starts a comment that runs to the end of the line.
/// Used by the .dat and .bpt readers, whose structure is a stream of numbers (line breaks carry no meaning).
class Token_stream {
 public:
  Token_stream(const std::string& text, const std::string& file_name) : file_(file_name), lines_(text) {
    const std::size_t n = text.size();
    std::size_t i = 0;
    while (i < n) {
      if (internal::is_space(text[i])) {
        ++i;
      } else if (text[i] == '#') {
        while (i < n && text[i] != '\n') ++i;
      } else {
        const std::size_t start = i;
        while (i < n && !internal::is_space(text[i]) && text[i] != '#') ++i;
        tokens_.push_back({text.substr(start, i - start), start, lines_.position(start)});
      }
    }
    end_ = lines_.position(n);
  }

  bool at_end() const { return next_ == tokens_.size(); }
  std::size_t remaining() const { return tokens_.size() - next_; }
  const std::string& file_name() const { return file_; }

  /// The next token; at the end of the input throws Parse_error "unexpected end of file; expected <what>".
  const Text_token& take(const std::string& what) {
    if (at_end()) fail_at_end("unexpected end of file; expected " + what);
    return tokens_[next_++];
  }

  /// The next token as an exact rational.
  Rational take_number(const std::string& what) {
    const Text_token& t = take(what);
    Exact_number_result r = parse_exact_number(t.text);
    if (!r.ok) fail(t, r.error_offset, "expected " + what + ": " + r.message);
    return r.value;
  }

  /// The next token as a count in [minimum, maximum]; the bound `maximum` (derived from the number of tokens
  /// left) is checked on the exact value, so no absurd count such as 10^18 is ever used to allocate.
  std::size_t take_count(const std::string& what, std::size_t minimum, std::size_t maximum, const std::string& why_maximum) {
    const Text_token& t = take(what);
    Exact_number_result r = parse_exact_number(t.text);
    if (!r.ok) fail(t, r.error_offset, "expected " + what + " (a non-negative integer): " + r.message);
    if (mpz_cmp_ui(mpq_denref(r.value.mpq()), 1) != 0 || t.text.find_first_of(".eExXpP") != std::string::npos)
      fail(t, 0, "expected " + what + " (a non-negative integer), got '" + t.text + "'");
    if (r.value < Rational(static_cast<long>(minimum)))
      fail(t, 0, "expected " + what + " of at least " + std::to_string(minimum) + ", got " + t.text);
    if (r.value > Rational(static_cast<unsigned long>(maximum)))
      fail(t, 0, "expected " + what + " of at most " + std::to_string(maximum) + " (" + why_maximum + "), got " +
                     (t.text.size() > 40 ? t.text.substr(0, 40) + "..." : t.text));
    return static_cast<std::size_t>(mpz_get_ui(mpq_numref(r.value.mpq())));
  }

  [[noreturn]] void fail(const Text_token& t, std::size_t offset_in_token, const std::string& message) const {
    Text_position p = lines_.position(t.offset + std::min(offset_in_token, t.text.size()));
    throw Parse_error(file_, p.line, p.column, message);
  }
  [[noreturn]] void fail_at_end(const std::string& message) const {
    throw Parse_error(file_, end_.line, end_.column, message);
  }
  /// Fails at the next token (or at the end).
  [[noreturn]] void fail_here(const std::string& message) const {
    if (at_end()) fail_at_end(message);
    fail(tokens_[next_], 0, message);
  }

 private:
  std::string file_;
  Line_index lines_;
  std::vector<Text_token> tokens_;
  std::size_t next_ = 0;
  Text_position end_;
};

} // namespace io
} // namespace bezoutian

#endif // BEZOUTIAN_IO_TEXT_TOKENS_H
