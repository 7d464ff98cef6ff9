// Bezier patch text (.bpt), as used for the Utah teapot (Eric Haines' Standard Procedural Databases):
//   P                      number of patches
//   m n                    per patch: degree in u (rows) and in v (columns)
//   x y z                  (m+1)(n+1) control points, row-major: P[0][0], P[0][1], ..., P[0][n], P[1][0], ...
// Row r is the u index, column c the v index (shared/data/teapot/README.md). Tokens are separated by any
// white space; numbers are exact (decimals such as 0.784 are read as 98/125). Extension: '#' comments.
// Only polynomial patches fit the format.
#include <bezoutian/io/Geometry_document.h>

#ifndef BEZOUTIAN_IO_BPT_FORMAT_H
#define BEZOUTIAN_IO_BPT_FORMAT_H

#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/io/Exact_number.h>
#include <bezoutian/io/Text_tokens.h>

#include <string>
#include <vector>

namespace bezoutian {
namespace io {

/// \brief Reads Bezier patches in BPT text; `file_name` is used in error messages.
/// Degrees are checked against the tokens left in the input before anything is allocated.
inline Geometry_document read_bpt(const std::string& text, const std::string& file_name = "<string>") {
  Token_stream in(text, file_name);
  if (in.at_end()) in.fail_at_end("empty file; expected the number of patches");
  // each patch takes at least 5 tokens ("0 0 x y z")
  const std::size_t count = in.take_count("the number of patches", 0, (in.remaining() - 1) / 5,
                                          "only " + std::to_string(in.remaining() - 1) +
                                              " numbers follow and each patch needs at least 5: is the file truncated?");
  Geometry_document doc;
  for (std::size_t p = 0; p < count; ++p) {
    const std::string patch = "patch " + std::to_string(p);
    if (in.at_end())
      in.fail_at_end("unexpected end of file; expected " + patch + " (" + std::to_string(count) +
                     " patches were announced)");
    // (m+1)(n+1) points of 3 numbers each must follow the two degrees
    const std::size_t left = in.remaining() >= 2 ? (in.remaining() - 2) / 3 : 0;  // points that can follow
    const std::string limit = "the readers' limit io::max_object_degree = " + std::to_string(max_object_degree);
    const std::size_t m_max = left == 0 ? 0 : left - 1;
    const std::size_t m = m_max > max_object_degree
                              ? in.take_count("the degree in u of " + patch, 0, max_object_degree, limit)
                              : in.take_count("the degree in u of " + patch, 0, m_max,
                                              "only " + std::to_string(left) + " points follow: is the file truncated?");
    const std::size_t n_max = left / (m + 1) == 0 ? 0 : left / (m + 1) - 1;
    const std::size_t n = n_max > max_object_degree
                              ? in.take_count("the degree in v of " + patch, 0, max_object_degree, limit)
                              : in.take_count("the degree in v of " + patch, 0, n_max,
                                              "only " + std::to_string(left) + " points follow for " +
                                                  std::to_string(m + 1) + " rows: is the file truncated?");
    std::vector<std::vector<Geometry_document::Patch::Point>> net(m + 1, std::vector<Geometry_document::Patch::Point>(n + 1));
    static const char* const axis[3] = {"x", "y", "z"};
    for (std::size_t r = 0; r <= m; ++r)
      for (std::size_t c = 0; c <= n; ++c)
        for (int d = 0; d < 3; ++d)
          net[r][c][d] = in.take_number(std::string("the ") + axis[d] + " coordinate of control point P[" +
                                        std::to_string(r) + "][" + std::to_string(c) + "] of " + patch);
    doc.add(Geometry_document::Patch(net));
  }
  if (!in.at_end()) in.fail_here("unexpected text after the last of the " + std::to_string(count) + " patches");
  return doc;
}

/// Reads a BPT file.
inline Geometry_document read_bpt_file(const std::string& path) { return read_bpt(read_text_file(path), path); }

/// \brief Writes the patches of a document as BPT text: a finite decimal where the coordinate has one
/// (0.784), otherwise exact p/q (other BPT readers may not accept p/q). Throws Invalid_input for rational
/// patches (the format has no weights) and for documents holding curves.
inline std::string write_bpt(const Geometry_document& doc) {
  if (!doc.curves_2.empty() || !doc.curves_3.empty())
    throw Invalid_input("the .bpt format holds patches only; the document has " +
                        std::to_string(doc.curves_2.size() + doc.curves_3.size()) + " curves");
  std::string out = std::to_string(doc.patches.size()) + "\n";
  for (std::size_t p = 0; p < doc.patches.size(); ++p) {
    const auto& patch = doc.patches[p];
    if (patch.is_rational() || patch.is_at_infinity(0, 0))
      throw Invalid_input("patch " + std::to_string(p) + " is rational; the .bpt format holds polynomial patches only");
    out += std::to_string(patch.degree_u()) + " " + std::to_string(patch.degree_v()) + "\n";
    for (int r = 0; r <= patch.degree_u(); ++r)
      for (int c = 0; c <= patch.degree_v(); ++c) {
        const auto q = patch.control_point(r, c);
        out += to_exact_decimal_string(q[0]) + " " + to_exact_decimal_string(q[1]) + " " + to_exact_decimal_string(q[2]) + "\n";
      }
  }
  return out;
}

/// Writes a BPT file (see write_bpt()).
inline void write_bpt_file(const std::string& path, const Geometry_document& doc) { write_text_file(path, write_bpt(doc)); }

} // namespace io
} // namespace bezoutian

#endif // BEZOUTIAN_IO_BPT_FORMAT_H
