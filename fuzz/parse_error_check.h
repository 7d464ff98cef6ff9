// The promise every file reader makes about its errors: a Parse_error naming the file and a line:column that
// lies inside the text (or just after its last character).
#ifndef BEZOUTIAN_FUZZ_PARSE_ERROR_CHECK_H
#define BEZOUTIAN_FUZZ_PARSE_ERROR_CHECK_H

#include "targets.h"

#include <bezoutian/arithmetic/Error.h>

#include <cstddef>
#include <string>

namespace bezoutian {
namespace fuzz {

/// Calls fuzz_failure() unless `e` names `file` and a position of `text`.
inline void check_parse_error(const Parse_error& e, const std::string& text, const std::string& file) {
  const std::string prefix = file + ":" + std::to_string(e.line()) + ":" + std::to_string(e.column()) + ": ";
  if (e.file() != file || std::string(e.what()).compare(0, prefix.size(), prefix) != 0)
    fuzz_failure(std::string("Parse_error without the file:line:column prefix: ") + e.what());
  // the lines of the text, 1-based; the last one may be empty
  std::size_t line = 1, line_start = 0;
  for (std::size_t i = 0; i < text.size() && line < e.line(); ++i)
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  if (e.line() < 1 || line != e.line()) fuzz_failure(std::string("Parse_error at a line outside the text: ") + e.what());
  std::size_t line_end = text.find('\n', line_start);
  if (line_end == std::string::npos) line_end = text.size();
  if (e.column() < 1 || e.column() > line_end - line_start + 1)
    fuzz_failure(std::string("Parse_error at a column outside its line: ") + e.what());
}

} // namespace fuzz
} // namespace bezoutian

#endif // BEZOUTIAN_FUZZ_PARSE_ERROR_CHECK_H
