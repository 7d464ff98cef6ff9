// The JSON geometry format: curves and patches in Bernstein or power basis with exact numbers
// (see doc/formats.md for the full description).
//
//   {"patch": {"basis": "bernstein", "degree": [m, n], "points": [[[x,y,z], ...n+1...], ...m+1 rows...],
//              "weights": [[...], ...]}}
//   {"patch": {"basis": "power", "parameters": ["s","t"], "x": "...", "y": "...", "z": "...", "w": "1"}}
//   {"curve": {"basis": "bernstein", "points": [[x,y], ...], "weights": [...]}}
//   {"curve": {"basis": "power", "parameter": "t", "x": "...", "y": "...", "z": "...", "w": "..."}}
//   {"curves": [...], "patches": [...]}
//
// The text is parsed by a small JSON parser of our own that records where every value starts, so that
// every error -- syntax or meaning -- is reported as a Parse_error "file:line:column: ..." at the offending
// value; nlohmann::json holds the parsed values. Numbers are always re-read from their literal text, so a
// JSON literal such as 0.784 is the exact rational 98/125 and big integers keep every digit.
#include <bezoutian/io/Geometry_document.h>

#ifndef BEZOUTIAN_IO_JSON_FORMAT_H
#define BEZOUTIAN_IO_JSON_FORMAT_H

#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/geometry/Rational_bezier_curve.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>
#include <bezoutian/io/Exact_number.h>
#include <bezoutian/io/Polynomial_expression.h>
#include <bezoutian/io/Text_tokens.h>
#include <bezoutian/arithmetic/number_types.h>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace bezoutian {
namespace io {

/// Deepest nesting of JSON arrays/objects accepted (a patch needs 5 levels).
constexpr int max_json_depth = 256;

/// \brief A JSON text parsed into nlohmann::json together with the place of every value.
///
/// Values are addressed by JSON pointers ("/patch/points/0/2"). Syntax errors throw Parse_error at the
/// offending character with what was expected; nesting deeper than max_json_depth and duplicate keys
/// are errors too. The literal text of every number is kept (raw_text()) for exact re-reading.
class Located_json {
 public:
  Located_json(std::string text, std::string file_name) : text_(std::move(text)), file_(std::move(file_name)), lines_(text_) {
    if (text_.compare(0, 3, "\xEF\xBB\xBF") == 0) pos_ = 3;  // a UTF-8 byte order mark
    skip_space();
    if (pos_ >= text_.size()) fail_at(pos_, "empty file; expected a JSON object");
    root_ = value("", 0);
    skip_space();
    if (pos_ < text_.size()) fail_at(pos_, "unexpected " + describe(pos_) + " after the end of the JSON value");
  }

  const nlohmann::json& root() const { return root_; }
  const std::string& file_name() const { return file_; }

  /// Where the value at `pointer` starts (for a missing value: its nearest existing ancestor).
  Text_position position(const std::string& pointer) const { return lines_.position(offset_of(pointer)); }

  /// The literal text of the value at `pointer` (numbers, strings with quotes, ...).
  std::string raw_text(const std::string& pointer) const {
    auto it = values_.find(pointer);
    if (it == values_.end()) return "";
    return text_.substr(it->second.first, it->second.second - it->second.first);
  }

  /// Where character `offset` of the decoded string at `pointer` is in the file (escapes accounted for).
  Text_position position_in_string(const std::string& pointer, std::size_t offset) const {
    auto it = values_.find(pointer);
    if (it == values_.end()) return position(pointer);
    auto e = escaped_.find(pointer);
    if (e == escaped_.end()) {
      const std::size_t last = it->second.second - 1;  // closing quote
      return lines_.position(std::min(it->second.first + 1 + offset, last));
    }
    const std::vector<std::size_t>& map = e->second;
    return lines_.position(offset < map.size() ? map[offset] : it->second.second - 1);
  }

  [[noreturn]] void fail(const std::string& pointer, const std::string& message) const {
    Text_position p = position(pointer);
    throw Parse_error(file_, p.line, p.column, message);
  }
  /// Fails at the key of the member `pointer` (e.g. for an unknown key).
  [[noreturn]] void fail_at_key(const std::string& pointer, const std::string& message) const {
    auto it = keys_.find(pointer);
    if (it == keys_.end()) fail(pointer, message);
    fail_at(it->second, message);
  }
  [[noreturn]] void fail_in_string(const std::string& pointer, std::size_t offset, const std::string& message) const {
    Text_position p = position_in_string(pointer, offset);
    throw Parse_error(file_, p.line, p.column, message);
  }

  /// Escapes a key for use in a JSON pointer ('~' -> "~0", '/' -> "~1").
  static std::string escape_key(const std::string& key) {
    std::string r;
    for (char c : key) {
      if (c == '~')
        r += "~0";
      else if (c == '/')
        r += "~1";
      else
        r += c;
    }
    return r;
  }

 private:
  using json = nlohmann::json;

  std::size_t offset_of(std::string pointer) const {
    for (;;) {
      auto it = values_.find(pointer);
      if (it != values_.end()) return it->second.first;
      if (pointer.empty()) return 0;
      pointer.erase(pointer.find_last_of('/'));
    }
  }

  [[noreturn]] void fail_at(std::size_t offset, const std::string& message) const {
    Text_position p = lines_.position(offset);
    throw Parse_error(file_, p.line, p.column, message);
  }

  std::string describe(std::size_t at) const {
    if (at >= text_.size()) return "end of file";
    return internal::quoted_char(text_[at]);
  }

  void skip_space() {
    while (pos_ < text_.size() &&
           (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\n' || text_[pos_] == '\r'))
      ++pos_;
  }

  json value(const std::string& pointer, int depth) {
    skip_space();
    const std::size_t start = pos_;
    if (pos_ >= text_.size())
      fail_at(pos_, "unexpected end of file; expected a JSON value (object, array, string, number, true, false or null)");
    json v;
    const char c = text_[pos_];
    if (c == '{' || c == '[') {
      if (depth >= max_json_depth)
        fail_at(pos_, "JSON nested deeper than " + std::to_string(max_json_depth) + " levels");
      v = c == '{' ? object(pointer, depth) : array(pointer, depth);
    } else if (c == '"') {
      std::vector<std::size_t> map;
      bool escaped = false;
      v = string_literal(map, escaped);
      if (escaped) escaped_[pointer] = std::move(map);
    } else if (c == '-' || internal::is_digit(c)) {
      v = number();
    } else if (literal("true")) {
      v = true;
    } else if (literal("false")) {
      v = false;
    } else if (literal("null")) {
      v = nullptr;
    } else {
      fail_at(pos_, "unexpected " + describe(pos_) +
                        "; expected a JSON value (object, array, string, number, true, false or null)");
    }
    values_[pointer] = {start, pos_};
    return v;
  }

  bool literal(const char* word) {
    const std::string w(word);
    if (text_.compare(pos_, w.size(), w) != 0) return false;
    const std::size_t after = pos_ + w.size();
    if (after < text_.size() && internal::is_identifier_char(text_[after])) return false;
    pos_ = after;
    return true;
  }

  json object(const std::string& pointer, int depth) {
    const std::size_t open = pos_++;
    json v = json::object();
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == '}') {
      ++pos_;
      return v;
    }
    for (;;) {
      skip_space();
      if (pos_ >= text_.size() || text_[pos_] != '"')
        fail_at(pos_, "unexpected " + describe(pos_) + "; expected a string key (in double quotes) in the object opened at " +
                          where(open));
      const std::size_t key_start = pos_;
      std::vector<std::size_t> unused;
      bool escaped = false;
      const std::string key = string_literal(unused, escaped);
      const std::string child = pointer + "/" + escape_key(key);
      if (v.contains(key)) fail_at(key_start, "duplicate key \"" + key + "\"");
      keys_[child] = key_start;
      skip_space();
      if (pos_ >= text_.size() || text_[pos_] != ':')
        fail_at(pos_, "unexpected " + describe(pos_) + "; expected ':' after the key \"" + key + "\"");
      ++pos_;
      v[key] = value(child, depth + 1);
      skip_space();
      if (pos_ < text_.size() && text_[pos_] == ',') {
        ++pos_;
        continue;
      }
      if (pos_ < text_.size() && text_[pos_] == '}') {
        ++pos_;
        return v;
      }
      fail_at(pos_, "unexpected " + describe(pos_) + "; expected ',' or '}' in the object opened at " + where(open));
    }
  }

  json array(const std::string& pointer, int depth) {
    const std::size_t open = pos_++;
    json v = json::array();
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == ']') {
      ++pos_;
      return v;
    }
    for (std::size_t i = 0;; ++i) {
      v.push_back(value(pointer + "/" + std::to_string(i), depth + 1));
      skip_space();
      if (pos_ < text_.size() && text_[pos_] == ',') {
        ++pos_;
        continue;
      }
      if (pos_ < text_.size() && text_[pos_] == ']') {
        ++pos_;
        return v;
      }
      fail_at(pos_, "unexpected " + describe(pos_) + "; expected ',' or ']' in the array opened at " + where(open));
    }
  }

  std::string where(std::size_t offset) const {
    Text_position p = lines_.position(offset);
    return std::to_string(p.line) + ":" + std::to_string(p.column);
  }

  // JSON number grammar: -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?
  json number() {
    const std::size_t start = pos_;
    if (text_[pos_] == '-') ++pos_;
    auto digits = [&](const char* what) {
      if (pos_ >= text_.size() || !internal::is_digit(text_[pos_]))
        fail_at(pos_, "unexpected " + describe(pos_) + "; expected a digit " + what);
      while (pos_ < text_.size() && internal::is_digit(text_[pos_])) ++pos_;
    };
    if (pos_ < text_.size() && text_[pos_] == '0') {
      ++pos_;
      if (pos_ < text_.size() && internal::is_digit(text_[pos_]))
        fail_at(pos_, "leading zeros are not allowed in JSON numbers (write \"007\" as a string, or 7)");
    } else
      digits("in the number");
    bool integer = true;
    if (pos_ < text_.size() && text_[pos_] == '.') {
      ++pos_;
      integer = false;
      digits("after the decimal point");
    }
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      ++pos_;
      integer = false;
      if (pos_ < text_.size() && (text_[pos_] == '+' || text_[pos_] == '-')) ++pos_;
      digits("in the exponent");
    }
    if (pos_ < text_.size() && (internal::is_identifier_char(text_[pos_]) || text_[pos_] == '.'))
      fail_at(pos_, "unexpected " + describe(pos_) + " in a number (hex floats and fractions must be strings, e.g. \"3/4\")");
    const std::string lit = text_.substr(start, pos_ - start);
    // nlohmann gets an approximate value; exact readers use raw_text()
    if (integer && lit.size() <= 18) return json(std::strtoll(lit.c_str(), nullptr, 10));
    return json(std::strtod(lit.c_str(), nullptr));
  }

  static void append_utf8(std::string& s, unsigned long cp) {
    if (cp < 0x80) {
      s += static_cast<char>(cp);
    } else if (cp < 0x800) {
      s += static_cast<char>(0xC0 | (cp >> 6));
      s += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      s += static_cast<char>(0xE0 | (cp >> 12));
      s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      s += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      s += static_cast<char>(0xF0 | (cp >> 18));
      s += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      s += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }

  unsigned long hex4() {
    if (pos_ + 4 > text_.size()) fail_at(pos_, "unexpected end of file; expected 4 hexadecimal digits after \\u");
    unsigned long v = 0;
    for (int i = 0; i < 4; ++i) {
      const char c = text_[pos_];
      if (!internal::is_hex_digit(c)) fail_at(pos_, "unexpected " + describe(pos_) + "; expected a hexadecimal digit after \\u");
      v = v * 16 + static_cast<unsigned long>(internal::is_digit(c) ? c - '0' : (c | 0x20) - 'a' + 10);
      ++pos_;
    }
    return v;
  }

  // Decodes a string literal; `map` gives the file offset of every decoded byte (filled only as needed).
  std::string string_literal(std::vector<std::size_t>& map, bool& escaped) {
    const std::size_t open = pos_++;
    std::string s;
    for (;;) {
      if (pos_ >= text_.size()) fail_at(pos_, "unexpected end of file in the string that starts at " + where(open));
      const std::size_t at = pos_;
      const unsigned char c = static_cast<unsigned char>(text_[pos_]);
      if (c == '"') {
        ++pos_;
        return s;
      }
      if (c < 0x20)
        fail_at(pos_, c == '\n' ? "unexpected line break in the string that starts at " + where(open) +
                                      " (missing closing quote?)"
                                : std::string("control character in a string; write it as an escape such as \\u0009"));
      if (c != '\\') {
        s += static_cast<char>(c);
        ++pos_;
      } else {
        if (!escaped) {
          escaped = true;
          map.clear();
          for (std::size_t i = 0; i < s.size(); ++i) map.push_back(open + 1 + i);
        }
        ++pos_;
        if (pos_ >= text_.size()) fail_at(pos_, "unexpected end of file after '\\' in a string");
        const char e = text_[pos_++];
        switch (e) {
          case '"': s += '"'; break;
          case '\\': s += '\\'; break;
          case '/': s += '/'; break;
          case 'b': s += '\b'; break;
          case 'f': s += '\f'; break;
          case 'n': s += '\n'; break;
          case 'r': s += '\r'; break;
          case 't': s += '\t'; break;
          case 'u': {
            unsigned long cp = hex4();
            if (cp >= 0xD800 && cp <= 0xDBFF) {
              if (text_.compare(pos_, 2, "\\u") != 0)
                fail_at(pos_, "expected \\u and a low surrogate after the high surrogate \\u" + text_.substr(at + 2, 4));
              pos_ += 2;
              const std::size_t low_at = pos_;
              unsigned long low = hex4();
              if (low < 0xDC00 || low > 0xDFFF) fail_at(low_at, "expected a low surrogate (DC00-DFFF)");
              cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
            } else if (cp >= 0xDC00 && cp <= 0xDFFF) {
              fail_at(at, "unpaired low surrogate in a \\u escape");
            }
            append_utf8(s, cp);
            break;
          }
          default:
            fail_at(at, std::string("invalid escape '\\") + e + "' in a string (valid: \\\" \\\\ \\/ \\b \\f \\n \\r \\t \\uXXXX)");
        }
      }
      if (escaped)
        while (map.size() < s.size()) map.push_back(at);
    }
  }

  std::string text_, file_;
  Line_index lines_;
  std::size_t pos_ = 0;
  json root_;
  std::unordered_map<std::string, std::pair<std::size_t, std::size_t>> values_;  // pointer -> [start, end)
  std::unordered_map<std::string, std::size_t> keys_;                             // member pointer -> key offset
  std::unordered_map<std::string, std::vector<std::size_t>> escaped_;             // strings with escapes
};

namespace internal {

/// Reads the geometry of a Located_json; every error is a Parse_error at the offending value.
class Json_geometry_reader {
  using json = nlohmann::json;
  using Curve_2 = Geometry_document::Curve_2;
  using Curve_3 = Geometry_document::Curve_3;
  using Patch = Geometry_document::Patch;

  struct Node {
    const json& v;
    std::string ptr;
    Node operator[](const std::string& key) const { return {v.at(key), ptr + "/" + Located_json::escape_key(key)}; }
    Node operator[](std::size_t i) const { return {v.at(i), ptr + "/" + std::to_string(i)}; }
    bool has(const std::string& key) const { return v.is_object() && v.contains(key); }
    std::size_t size() const { return v.size(); }
  };

 public:
  explicit Json_geometry_reader(const Located_json& j) : j_(j) {}

  Geometry_document read() {
    Node root{j_.root(), ""};
    if (!root.v.is_object())
      j_.fail("", "expected a JSON object with a key \"curve\", \"curves\", \"patch\" or \"patches\", got " + type_name(root.v));
    check_keys(root, {"curve", "curves", "patch", "patches", "comment"}, "the top-level object");
    if (!root.has("curve") && !root.has("curves") && !root.has("patch") && !root.has("patches"))
      j_.fail("", "expected a key \"curve\", \"curves\", \"patch\" or \"patches\" in the top-level object");
    if (root.has("curve")) curve(root["curve"]);
    if (root.has("curves")) {
      Node list = array(root["curves"], "a list of curve objects");
      for (std::size_t i = 0; i < list.size(); ++i) curve(list[i]);
    }
    if (root.has("patch")) patch(root["patch"]);
    if (root.has("patches")) {
      Node list = array(root["patches"], "a list of patch objects");
      for (std::size_t i = 0; i < list.size(); ++i) patch(list[i]);
    }
    return doc_;
  }

 private:
  static std::string type_name(const json& v) {
    switch (v.type()) {
      case json::value_t::null: return "null";
      case json::value_t::boolean: return "a boolean";
      case json::value_t::string: return "a string";
      case json::value_t::object: return "an object";
      case json::value_t::array: return "an array of " + std::to_string(v.size()) + " elements";
      default: return "a number";
    }
  }

  void check_keys(const Node& n, const std::set<std::string>& allowed, const std::string& what) const {
    for (auto it = n.v.begin(); it != n.v.end(); ++it)
      if (!allowed.count(it.key())) {
        std::string list;
        for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
        j_.fail_at_key(n.ptr + "/" + Located_json::escape_key(it.key()),
                       "unknown key \"" + it.key() + "\" in " + what + "; expected one of: " + list);
      }
  }

  Node object(const Node& n, const std::string& what) const {
    if (!n.v.is_object()) j_.fail(n.ptr, "expected " + what + " (a JSON object), got " + type_name(n.v));
    return n;
  }
  Node array(const Node& n, const std::string& what) const {
    if (!n.v.is_array()) j_.fail(n.ptr, "expected " + what + " (a JSON array), got " + type_name(n.v));
    return n;
  }
  Node required(const Node& obj, const std::string& key, const std::string& why) const {
    if (!obj.has(key)) j_.fail(obj.ptr, "missing key \"" + key + "\" (" + why + ")");
    return obj[key];
  }
  std::string string(const Node& n, const std::string& what) const {
    if (!n.v.is_string()) j_.fail(n.ptr, "expected " + what + " (a string), got " + type_name(n.v));
    return n.v.get<std::string>();
  }
  bool boolean(const Node& n, const std::string& what) const {
    if (!n.v.is_boolean()) j_.fail(n.ptr, "expected " + what + " (true or false), got " + type_name(n.v));
    return n.v.get<bool>();
  }

  /// An exact number: a JSON number (re-read from its literal text) or a string "p/q", "0.5", "0x1p-3".
  Rational number(const Node& n, const std::string& what) const {
    if (n.v.is_number()) {
      Exact_number_result r = parse_exact_number(j_.raw_text(n.ptr));
      if (!r.ok) j_.fail(n.ptr, "expected " + what + ": " + r.message);
      return r.value;
    }
    if (n.v.is_string()) {
      Exact_number_result r = parse_exact_number(n.v.get_ref<const std::string&>());
      if (!r.ok) j_.fail_in_string(n.ptr, r.error_offset, "expected " + what + ": " + r.message);
      return r.value;
    }
    j_.fail(n.ptr, "expected " + what + " (a number, or a string such as \"3/4\", \"0.784\" or \"0x1.8p-3\"), got " +
                       type_name(n.v));
  }

  /// A non-negative integer below `limit`.
  int count(const Node& n, const std::string& what, int limit = 1000000) const {
    const Rational q = number(n, what + " (a non-negative integer)");
    if (mpz_cmp_ui(mpq_denref(q.mpq()), 1) != 0 || q < Rational(0) || q > Rational(limit))
      j_.fail(n.ptr, "expected " + what + ": an integer from 0 to " + std::to_string(limit) + ", got " +
                         (n.v.is_string() ? "\"" + n.v.get<std::string>() + "\"" : j_.raw_text(n.ptr)));
    return static_cast<int>(mpz_get_si(mpq_numref(q.mpq())));
  }

  std::string basis(const Node& obj) const {
    if (!obj.has("basis")) return "bernstein";
    const std::string b = string(obj["basis"], "the basis");
    if (b != "bernstein" && b != "power") j_.fail(obj["basis"].ptr, "expected the basis \"bernstein\" or \"power\", got \"" + b + "\"");
    return b;
  }

  std::string name(const Node& obj) const { return obj.has("name") ? string(obj["name"], "a name") : std::string(); }

  // ---------------------------------------------------------------- curves
  void curve(const Node& n) {
    object(n, "a curve");
    if (basis(n) == "power")
      power_curve(n);
    else
      bernstein_curve(n);
  }

  void bernstein_curve(const Node& n) {
    check_keys(n, {"basis", "name", "comment", "points", "weights", "homogeneous", "degree", "dimension"},
               "a Bernstein curve");
    const bool homogeneous = n.has("homogeneous") && boolean(n["homogeneous"], "\"homogeneous\"");
    Node pts = array(required(n, "points", "a Bernstein curve needs its control points"), "the control points");
    if (pts.size() == 0) j_.fail(pts.ptr, "expected at least one control point");
    if (pts.size() > max_object_degree + 1)
      j_.fail(pts.ptr, "expected at most " + std::to_string(max_object_degree + 1) +
                           " control points (the readers' limit io::max_object_degree = " +
                           std::to_string(max_object_degree) + "), got " + std::to_string(pts.size()));
    if (n.has("degree")) {
      const int d = count(n["degree"], "the degree", int(max_object_degree));
      if (pts.size() != std::size_t(d) + 1)
        j_.fail(pts.ptr, "expected " + std::to_string(d + 1) + " control points (degree " + std::to_string(d) + "), got " +
                             std::to_string(pts.size()));
    }
    const Node first = pts[0];
    if (!first.v.is_array())
      j_.fail(first.ptr, "expected a control point (an array of coordinates), got " + type_name(first.v));
    const std::size_t length = first.size();
    int dim = int(length) - (homogeneous ? 1 : 0);
    if (n.has("dimension")) {
      const int d = count(n["dimension"], "the dimension");
      if (d != 2 && d != 3) j_.fail(n["dimension"].ptr, "expected the dimension 2 or 3, got " + std::to_string(d));
      if (dim != d)
        j_.fail(first.ptr, "expected " + std::to_string(d + (homogeneous ? 1 : 0)) + " coordinates (dimension " +
                               std::to_string(d) + (homogeneous ? ", homogeneous [w, w x, ...]" : "") + "), got " +
                               std::to_string(length));
    }
    if (dim != 2 && dim != 3)
      j_.fail(first.ptr, homogeneous ? "expected a homogeneous control point [w, w x, w y] or [w, w x, w y, w z], got " +
                                           type_name(first.v)
                                     : "expected a control point [x, y] or [x, y, z], got " + type_name(first.v));
    if (dim == 2)
      doc_.add(bernstein_curve_d<2>(n, pts, homogeneous), name(n));
    else
      doc_.add(bernstein_curve_d<3>(n, pts, homogeneous), name(n));
  }

  template <int D>
  Rational_bezier_curve<Rational, D> bernstein_curve_d(const Node& n, const Node& pts, bool homogeneous) {
    using Curve = Rational_bezier_curve<Rational, D>;
    const std::size_t length = std::size_t(D) + (homogeneous ? 1 : 0);
    std::vector<typename Curve::Homogeneous_point> net(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
      Node p = pts[i];
      coordinates(p, length, "control point " + std::to_string(i), homogeneous,
                  "expected every control point to have " + std::to_string(length) + " coordinates like the first one");
      for (std::size_t k = 0; k < length; ++k) net[i][k + (homogeneous ? 0 : 1)] = number(p[k], coordinate_name(k, homogeneous));
      if (homogeneous) {
        bool zero = true;
        for (std::size_t k = 0; k < length; ++k) zero = zero && CGAL::is_zero(net[i][k]);
        if (zero) j_.fail(p.ptr, "the homogeneous control point is the zero vector");
      } else {
        net[i][0] = Rational(1);
      }
    }
    if (n.has("weights")) {
      if (homogeneous)
        j_.fail(n["weights"].ptr, "the weights are part of homogeneous control points; remove \"weights\" or \"homogeneous\"");
      Node w = array(n["weights"], "the weights");
      if (w.size() != pts.size())
        j_.fail(w.ptr, "expected " + std::to_string(pts.size()) + " weights (one per control point), got " + std::to_string(w.size()));
      for (std::size_t i = 0; i < w.size(); ++i) {
        const Rational wi = number(w[i], "a weight");
        if (CGAL::is_zero(wi))
          j_.fail(w[i].ptr, "the weight is zero; write a control point at infinity in homogeneous form (\"homogeneous\": true)");
        for (int k = 1; k <= D; ++k) net[i][k] *= wi;
        net[i][0] = wi;
      }
    }
    try {
      return Curve::from_homogeneous(net);
    } catch (const Invalid_input& e) {
      j_.fail(n.ptr, e.what());
    }
  }

  static std::string coordinate_name(std::size_t k, bool homogeneous) {
    static const char* const plain[] = {"the x coordinate", "the y coordinate", "the z coordinate"};
    static const char* const homog[] = {"the weight w", "w x", "w y", "w z"};
    return homogeneous ? homog[k] : plain[k];
  }

  void coordinates(const Node& p, std::size_t length, const std::string& what, bool homogeneous, const std::string& mismatch) const {
    if (!p.v.is_array())
      j_.fail(p.ptr, "expected " + what + " (an array of " + std::to_string(length) + " numbers" +
                         (homogeneous ? ", homogeneous [w, w x, ...]" : "") + "), got " + type_name(p.v));
    if (p.size() != length) j_.fail(p.ptr, mismatch + ", got " + std::to_string(p.size()) + " in " + what);
  }

  /// A polynomial: an expression string or a JSON number (a constant).
  Sparse_polynomial expression(const Node& n, const std::vector<std::string>& vars, const std::string& what) const {
    if (n.v.is_number()) {
      Sparse_polynomial p;
      const Rational c = number(n, what);
      if (!CGAL::is_zero(c)) p[std::vector<int>(vars.size(), 0)] = c;
      return p;
    }
    if (!n.v.is_string())
      j_.fail(n.ptr, "expected " + what + " (a polynomial expression string such as \"2*t^2 - 3/4\"), got " + type_name(n.v));
    try {
      return parse_polynomial_expression(n.v.get_ref<const std::string&>(), vars);
    } catch (const Expression_error& e) {
      j_.fail_in_string(n.ptr, e.offset(), "in " + what + ": " + e.message());
    }
  }

  std::string parameter_name(const Node& n) const {
    const std::string s = string(n, "a parameter name");
    if (!is_identifier(s)) j_.fail(n.ptr, "expected a parameter name (letters, digits, '_', not starting with a digit), got \"" + s + "\"");
    return s;
  }

  void power_curve(const Node& n) {
    check_keys(n, {"basis", "name", "comment", "parameter", "x", "y", "z", "w", "degree"}, "a power-basis curve");
    const std::string t = n.has("parameter") ? parameter_name(n["parameter"]) : "t";
    const std::vector<std::string> vars{t};
    std::vector<Polynomial_1<Rational>> q;
    const char* const keys[] = {"w", "x", "y", "z"};
    for (int k = 0; k < 4; ++k) {
      if (k == 0 && !n.has("w")) {
        q.push_back(Polynomial_1<Rational>(Rational(1)));
        continue;
      }
      if (k == 3 && !n.has("z")) break;
      Node e = required(n, keys[k], "a power-basis curve needs x(t) and y(t), optionally z(t) and w(t)");
      q.push_back(to_polynomial_1(expression(e, vars, std::string("the polynomial ") + keys[k])));
    }
    if (CGAL::is_zero(q[0])) j_.fail(n["w"].ptr, "the weight polynomial w is identically zero");
    const int degree = n.has("degree") ? count(n["degree"], "the degree", int(max_object_degree)) : -1;
    try {
      if (q.size() == 3)
        doc_.add(Curve_2::from_power_form({q[0], q[1], q[2]}, degree), name(n));
      else
        doc_.add(Curve_3::from_power_form({q[0], q[1], q[2], q[3]}, degree), name(n));
    } catch (const Invalid_input& e) {
      j_.fail(n.has("degree") ? n["degree"].ptr : n.ptr, e.what());
    }
  }

  static Polynomial_1<Rational> to_polynomial_1(const Sparse_polynomial& p) {
    int d = 0;
    for (const auto& t : p) d = std::max(d, t.first[0]);
    std::vector<Rational> c(d + 1, Rational(0));
    for (const auto& t : p) c[t.first[0]] = t.second;
    return Polynomial_1<Rational>(c.begin(), c.end());
  }

  static Polynomial_2<Rational> to_polynomial_2(const Sparse_polynomial& p) {
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

  // ---------------------------------------------------------------- patches
  void patch(const Node& n) {
    object(n, "a patch");
    if (basis(n) == "power")
      power_patch(n);
    else
      bernstein_patch(n);
  }

  std::pair<int, int> bidegree(const Node& n) const {
    Node d = array(n["degree"], "the bi-degree [m, n]");
    if (d.size() != 2) j_.fail(d.ptr, "expected the bi-degree [m, n] (two integers), got " + type_name(d.v));
    return {count(d[0], "the degree m in u"), count(d[1], "the degree n in v")};
  }

  void bernstein_patch(const Node& n) {
    check_keys(n, {"basis", "name", "comment", "points", "weights", "homogeneous", "degree"}, "a Bernstein patch");
    const bool homogeneous = n.has("homogeneous") && boolean(n["homogeneous"], "\"homogeneous\"");
    Node rows = array(required(n, "points", "a Bernstein patch needs its control net"), "the control net (m+1 rows of n+1 points)");
    const bool has_degree = n.has("degree");
    const std::pair<int, int> deg = has_degree ? bidegree(n) : std::pair<int, int>(-1, -1);
    if (rows.size() == 0) j_.fail(rows.ptr, "expected at least one row of control points");
    if (rows.size() > max_object_degree + 1)
      j_.fail(rows.ptr, "expected at most " + std::to_string(max_object_degree + 1) +
                            " rows of control points (the readers' limit io::max_object_degree = " +
                            std::to_string(max_object_degree) + "), got " + std::to_string(rows.size()));
    if (has_degree && rows.size() != std::size_t(deg.first) + 1)
      j_.fail(rows.ptr, "expected " + std::to_string(deg.first + 1) + " rows of control points (degree m = " +
                            std::to_string(deg.first) + " in u), got " + std::to_string(rows.size()));
    Node row0 = array(rows[0], "row 0 of the control net");
    const std::size_t columns = has_degree ? std::size_t(deg.second) + 1 : row0.size();
    if (columns == 0) j_.fail(row0.ptr, "expected at least one control point in row 0");
    const std::size_t length = homogeneous ? 4 : 3;
    for (std::size_t i = 0; i < rows.size(); ++i) {  // check the shape before allocating the net
      Node row = array(rows[i], "row " + std::to_string(i) + " of the control net");
      if (row.size() != columns)
        j_.fail(row.ptr, "expected " + std::to_string(columns) + " control points in row " + std::to_string(i) +
                             (has_degree ? " (degree n = " + std::to_string(deg.second) + " in v)" : " (as in row 0)") +
                             ", got " + std::to_string(row.size()));
    }
    if (columns > max_object_degree + 1)
      j_.fail(row0.ptr, "expected at most " + std::to_string(max_object_degree + 1) +
                            " control points per row (the readers' limit io::max_object_degree = " +
                            std::to_string(max_object_degree) + "), got " + std::to_string(columns));
    Patch::Net net(rows.size(), std::vector<Patch::Homogeneous_point>(columns));
    for (std::size_t i = 0; i < rows.size(); ++i) {
      Node row = rows[i];
      for (std::size_t j = 0; j < columns; ++j) {
        Node p = row[j];
        const std::string what = "control point [" + std::to_string(i) + "][" + std::to_string(j) + "]";
        coordinates(p, length, what, homogeneous,
                    homogeneous ? "expected 4 homogeneous coordinates [w, w x, w y, w z]" : "expected 3 coordinates [x, y, z]");
        for (std::size_t k = 0; k < length; ++k) net[i][j][k + (homogeneous ? 0 : 1)] = number(p[k], coordinate_name(k, homogeneous));
        if (homogeneous) {
          bool zero = true;
          for (std::size_t k = 0; k < 4; ++k) zero = zero && CGAL::is_zero(net[i][j][k]);
          if (zero) j_.fail(p.ptr, "the homogeneous control point is the zero vector");
        } else {
          net[i][j][0] = Rational(1);
        }
      }
    }
    if (n.has("weights")) {
      if (homogeneous)
        j_.fail(n["weights"].ptr, "the weights are part of homogeneous control points; remove \"weights\" or \"homogeneous\"");
      Node w = array(n["weights"], "the weights (m+1 rows of n+1 numbers)");
      if (w.size() != rows.size())
        j_.fail(w.ptr, "expected " + std::to_string(rows.size()) + " rows of weights (one per row of control points), got " +
                           std::to_string(w.size()));
      for (std::size_t i = 0; i < w.size(); ++i) {
        Node wr = array(w[i], "row " + std::to_string(i) + " of the weights");
        if (wr.size() != columns)
          j_.fail(wr.ptr, "expected " + std::to_string(columns) + " weights in row " + std::to_string(i) + ", got " +
                              std::to_string(wr.size()));
        for (std::size_t j = 0; j < columns; ++j) {
          const Rational wij = number(wr[j], "a weight");
          if (CGAL::is_zero(wij))
            j_.fail(wr[j].ptr, "the weight is zero; write a control point at infinity in homogeneous form (\"homogeneous\": true)");
          net[i][j][0] = wij;
          for (int k = 1; k < 4; ++k) net[i][j][k] *= wij;
        }
      }
    }
    try {
      doc_.add(Patch::from_homogeneous(net), name(n));
    } catch (const Invalid_input& e) {
      j_.fail(n.ptr, e.what());
    }
  }

  void power_patch(const Node& n) {
    check_keys(n, {"basis", "name", "comment", "parameters", "x", "y", "z", "w", "degree"}, "a power-basis patch");
    std::vector<std::string> vars{"u", "v"};
    if (n.has("parameters")) {
      Node p = array(n["parameters"], "the two parameter names");
      if (p.size() != 2) j_.fail(p.ptr, "expected two parameter names such as [\"s\", \"t\"], got " + type_name(p.v));
      vars = {parameter_name(p[0]), parameter_name(p[1])};
      if (vars[0] == vars[1]) j_.fail(p[1].ptr, "the two parameters must have different names");
    }
    Patch::Power_form q;
    const char* const keys[] = {"w", "x", "y", "z"};
    for (int k = 0; k < 4; ++k) {
      if (k == 0 && !n.has("w")) {
        q[0] = Polynomial_2<Rational>(Rational(1));
        continue;
      }
      Node e = required(n, keys[k], "a power-basis patch needs x, y and z, optionally w");
      q[k] = to_polynomial_2(expression(e, vars, std::string("the polynomial ") + keys[k]));
    }
    if (CGAL::is_zero(q[0])) j_.fail(n["w"].ptr, "the weight polynomial w is identically zero");
    const std::pair<int, int> deg = n.has("degree") ? bidegree(n) : std::pair<int, int>(-1, -1);
    // a declared bi-degree costs (m+1)(n+1) control points whatever the expressions hold: it obeys their degree bound
    const int max_degree = Expression_limits().max_degree;
    for (std::size_t k = 0; k < 2; ++k)
      if ((k == 0 ? deg.first : deg.second) > max_degree)
        j_.fail(n["degree"][k].ptr, "expected a degree of at most " + std::to_string(max_degree) +
                                        " in a power-basis patch (the bound of its expressions), got " +
                                        std::to_string(k == 0 ? deg.first : deg.second));
    try {
      doc_.add(Patch::from_power_form(q, deg.first, deg.second), name(n));
    } catch (const Invalid_input& e) {
      j_.fail(n.has("degree") ? n["degree"].ptr : n.ptr, e.what());
    }
  }

  const Located_json& j_;
  Geometry_document doc_;
};

} // namespace internal

/// \brief Reads the JSON geometry format from text; `file_name` is used in error messages.
/// Every error is a Parse_error "file:line:column: ..." at the offending value (see doc/formats.md).
inline Geometry_document read_json(const std::string& text, const std::string& file_name = "<string>") {
  Located_json j(text, file_name);
  return internal::Json_geometry_reader(j).read();
}

/// Reads a JSON geometry file.
inline Geometry_document read_json_file(const std::string& path) { return read_json(read_text_file(path), path); }

// ==================================================================== writer

/// Which basis the JSON writer uses.
enum class Json_basis { bernstein, power };

/// Options of write_json().
struct Json_write_options {
  Json_basis basis = Json_basis::bernstein;
  std::string curve_parameter = "t";                       ///< parameter name of power-basis curves
  std::pair<std::string, std::string> patch_parameters{"u", "v"};  ///< (inner, outer) names for power-basis patches
};

namespace internal {

/// A JSON value for q: a bare integer if |q| < 2^53 (exact in every JSON reader), else the string "p/q".
inline std::string json_number(const Rational& q) {
  if (mpz_cmp_ui(mpq_denref(q.mpq()), 1) == 0 && mpz_sizeinbase(mpq_numref(q.mpq()), 2) <= 53) return to_exact_string(q);
  return "\"" + to_exact_string(q) + "\"";
}

inline std::string json_string(const std::string& s) {
  std::string r = "\"";
  for (char ch : s) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if (c == '"')
      r += "\\\"";
    else if (c == '\\')
      r += "\\\\";
    else if (c == '\n')
      r += "\\n";
    else if (c == '\t')
      r += "\\t";
    else if (c < 0x20) {
      static const char* hex = "0123456789abcdef";
      r += "\\u00";
      r += hex[c >> 4];
      r += hex[c & 15];
    } else
      r += ch;
  }
  return r + "\"";
}

template <class Array>
std::string json_point(const Array& a, std::size_t from, std::size_t to) {
  std::string r = "[";
  for (std::size_t k = from; k < to; ++k) r += (k > from ? ", " : "") + json_number(a[k]);
  return r + "]";
}

template <class Curve>
std::string json_curve(const Curve& c, const std::string& name, const Json_write_options& o, const std::string& indent) {
  const std::string in = indent + "  ";
  std::string r = "{\n";
  if (!name.empty()) r += in + "\"name\": " + json_string(name) + ",\n";
  if (o.basis == Json_basis::power) {
    const auto p = c.power_form();
    r += in + "\"basis\": \"power\",\n" + in + "\"parameter\": " + json_string(o.curve_parameter) + ",\n";
    r += in + "\"degree\": " + std::to_string(c.degree()) + ",\n";
    const char* const keys[] = {"w", "x", "y", "z"};
    for (int k = 0; k <= Curve::dimension; ++k)
      r += in + "\"" + keys[k] + "\": " + json_string(polynomial_to_string(p[k], o.curve_parameter)) +
           (k < Curve::dimension ? ",\n" : "\n");
    return r + indent + "}";
  }
  bool at_infinity = false, unit = true;
  for (std::size_t i = 0; i < c.number_of_control_points(); ++i) {
    at_infinity = at_infinity || c.is_at_infinity(i);
    unit = unit && c.weight(i) == Rational(1);
  }
  r += in + "\"basis\": \"bernstein\",\n" + in + "\"degree\": " + std::to_string(c.degree()) + ",\n";
  if (at_infinity) r += in + "\"homogeneous\": true,\n";
  r += in + "\"points\": [";
  for (std::size_t i = 0; i < c.number_of_control_points(); ++i) {
    r += (i ? ",\n" : "\n") + in + "  ";
    if (at_infinity)
      r += json_point(c.homogeneous_control_point(i), 0, Curve::dimension + 1);
    else
      r += json_point(c.control_point(i), 0, Curve::dimension);
  }
  r += "\n" + in + "]";
  if (!at_infinity && !unit) {
    r += ",\n" + in + "\"weights\": [";
    for (std::size_t i = 0; i < c.number_of_control_points(); ++i) r += (i ? ", " : "") + json_number(c.weight(i));
    r += "]";
  }
  return r + "\n" + indent + "}";
}

inline std::string json_patch(const Geometry_document::Patch& p, const std::string& name, const Json_write_options& o,
                              const std::string& indent) {
  const std::string in = indent + "  ";
  std::string r = "{\n";
  if (!name.empty()) r += in + "\"name\": " + json_string(name) + ",\n";
  const std::string degree = "[" + std::to_string(p.degree_u()) + ", " + std::to_string(p.degree_v()) + "]";
  if (o.basis == Json_basis::power) {
    const auto q = p.power_form();
    const std::string &u = o.patch_parameters.first, &v = o.patch_parameters.second;
    r += in + "\"basis\": \"power\",\n" + in + "\"parameters\": [" + json_string(u) + ", " + json_string(v) + "],\n";
    r += in + "\"degree\": " + degree + ",\n";
    const char* const keys[] = {"w", "x", "y", "z"};
    for (int k = 0; k < 4; ++k)
      r += in + "\"" + keys[k] + "\": " + json_string(polynomial_to_string(q[k], u, v)) + (k < 3 ? ",\n" : "\n");
    return r + indent + "}";
  }
  bool at_infinity = false, unit = true;
  for (int i = 0; i <= p.degree_u(); ++i)
    for (int j = 0; j <= p.degree_v(); ++j) {
      at_infinity = at_infinity || p.is_at_infinity(i, j);
      unit = unit && p.weight(i, j) == Rational(1);
    }
  r += in + "\"basis\": \"bernstein\",\n" + in + "\"degree\": " + degree + ",\n";
  if (at_infinity) r += in + "\"homogeneous\": true,\n";
  r += in + "\"points\": [";
  for (int i = 0; i <= p.degree_u(); ++i) {
    r += (i ? ",\n" : "\n") + in + "  [";
    for (int j = 0; j <= p.degree_v(); ++j) {
      r += j ? ", " : "";
      if (at_infinity)
        r += json_point(p.homogeneous_control_point(i, j), 0, 4);
      else
        r += json_point(p.control_point(i, j), 0, 3);
    }
    r += "]";
  }
  r += "\n" + in + "]";
  if (!at_infinity && !unit) {
    r += ",\n" + in + "\"weights\": [";
    for (int i = 0; i <= p.degree_u(); ++i) {
      r += (i ? ",\n" : "\n") + in + "  [";
      for (int j = 0; j <= p.degree_v(); ++j) r += (j ? ", " : "") + json_number(p.weight(i, j));
      r += "]";
    }
    r += "\n" + in + "]";
  }
  return r + "\n" + indent + "}";
}

} // namespace internal

/// \brief Writes a document in the JSON geometry format, exactly: integers below 2^53 as JSON numbers,
/// every other number as a string "p/q". Bernstein form by default: "weights" only if not all 1, and
/// "homogeneous": true with [w, w x, w y(, w z)] entries if some weight is 0 (a control point at
/// infinity). A single object is written as {"curve": ...} or {"patch": ...}, otherwise
/// {"curves": [...], "patches": [...]}. read_json() gives back objects equal to the input (operator==).
inline std::string write_json(const Geometry_document& doc, const Json_write_options& options = Json_write_options()) {
  using namespace internal;
  if (doc.size() == 1) {
    if (!doc.curves_2.empty()) return "{\"curve\": " + json_curve(doc.curves_2[0], doc.curve_2_name(0), options, "") + "}\n";
    if (!doc.curves_3.empty()) return "{\"curve\": " + json_curve(doc.curves_3[0], doc.curve_3_name(0), options, "") + "}\n";
    return "{\"patch\": " + json_patch(doc.patches[0], doc.patch_name(0), options, "") + "}\n";
  }
  std::string r = "{\n";
  const bool curves = !doc.curves_2.empty() || !doc.curves_3.empty() || doc.patches.empty();
  if (curves) {
    r += "  \"curves\": [";
    std::size_t k = 0;
    for (std::size_t i = 0; i < doc.curves_2.size(); ++i, ++k)
      r += (k ? ",\n    " : "\n    ") + json_curve(doc.curves_2[i], doc.curve_2_name(i), options, "    ");
    for (std::size_t i = 0; i < doc.curves_3.size(); ++i, ++k)
      r += (k ? ",\n    " : "\n    ") + json_curve(doc.curves_3[i], doc.curve_3_name(i), options, "    ");
    r += k ? "\n  ]" : "]";
  }
  if (!doc.patches.empty()) {
    r += curves ? ",\n  \"patches\": [" : "  \"patches\": [";
    for (std::size_t i = 0; i < doc.patches.size(); ++i)
      r += (i ? ",\n    " : "\n    ") + json_patch(doc.patches[i], doc.patch_name(i), options, "    ");
    r += "\n  ]";
  }
  return r + "\n}\n";
}

/// Writes a JSON geometry file (see write_json()).
inline void write_json_file(const std::string& path, const Geometry_document& doc,
                            const Json_write_options& options = Json_write_options()) {
  write_text_file(path, write_json(doc, options));
}

} // namespace io
} // namespace bezoutian

#endif // BEZOUTIAN_IO_JSON_FORMAT_H
