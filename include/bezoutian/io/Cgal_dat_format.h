// CGAL's Bezier curve text format (.dat), as read by the Arrangement_on_surface_2 Bezier examples:
//   N                         number of curves
//   k x_0 y_0 ... x_{k-1} y_{k-1}     per curve: number of control points, then the points
// Tokens are separated by any white space; numbers are exact (integers, p/q, decimals, hex floats).
// Extension: '#' starts a comment up to the end of the line. Only planar polynomial curves fit the format.
#include <bezoutian/io/Geometry_document.h>

#ifndef BEZOUTIAN_IO_CGAL_DAT_FORMAT_H
#define BEZOUTIAN_IO_CGAL_DAT_FORMAT_H

#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/io/Exact_number.h>
#include <bezoutian/io/Text_tokens.h>

#include <string>
#include <vector>

namespace bezoutian {
namespace io {

/// \brief Reads CGAL .dat Bezier curves from text; `file_name` is used in error messages.
/// Every count is checked against the tokens left in the input before anything is allocated.
inline Geometry_document read_dat(const std::string& text, const std::string& file_name = "<string>") {
  Token_stream in(text, file_name);
  if (in.at_end()) in.fail_at_end("empty file; expected the number of curves");
  // each curve takes at least 3 tokens ("1 x y")
  const std::size_t n = in.take_count("the number of curves", 0, (in.remaining() - 1) / 3,
                                      "only " + std::to_string(in.remaining() - 1) +
                                          " numbers follow and each curve needs at least 3: is the file truncated?");
  Geometry_document doc;
  for (std::size_t c = 0; c < n; ++c) {
    const std::string curve = "curve " + std::to_string(c);
    if (in.at_end()) in.fail_at_end("unexpected end of file; expected " + curve + " (" + std::to_string(n) +
                                    " curves were announced)");
    const std::size_t left = (in.remaining() - 1) / 2;  // points that can follow
    const std::size_t k =
        left > max_object_degree + 1
            ? in.take_count("the number of control points of " + curve, 1, max_object_degree + 1,
                            "the readers' limit io::max_object_degree = " + std::to_string(max_object_degree))
            : in.take_count("the number of control points of " + curve, 1, left,
                            "only " + std::to_string(in.remaining() - 1) + " numbers follow: is the file truncated?");
    std::vector<Geometry_document::Curve_2::Point> points(k);
    for (std::size_t i = 0; i < k; ++i)
      for (int d = 0; d < 2; ++d)
        points[i][d] = in.take_number(std::string(d == 0 ? "the x" : "the y") + " coordinate of control point " +
                                      std::to_string(i) + " of " + curve);
    doc.add(Geometry_document::Curve_2(points));
  }
  if (!in.at_end()) in.fail_here("unexpected text after the last of the " + std::to_string(n) + " curves");
  return doc;
}

/// Reads a CGAL .dat file.
inline Geometry_document read_dat_file(const std::string& path) { return read_dat(read_text_file(path), path); }

/// \brief Writes the planar curves of a document in CGAL's .dat format, one curve per line, numbers as
/// exact integers or p/q. Throws Invalid_input if the document holds anything else (3D curves, patches,
/// rational curves: the format has no weights).
inline std::string write_dat(const Geometry_document& doc) {
  if (!doc.curves_3.empty() || !doc.patches.empty())
    throw Invalid_input("the .dat format holds planar curves only; the document has " +
                        std::to_string(doc.curves_3.size()) + " spatial curves and " +
                        std::to_string(doc.patches.size()) + " patches");
  std::string out = std::to_string(doc.curves_2.size()) + "\n";
  for (std::size_t c = 0; c < doc.curves_2.size(); ++c) {
    const auto& curve = doc.curves_2[c];
    if (curve.is_rational() || curve.is_at_infinity(0))
      throw Invalid_input("curve " + std::to_string(c) + " is rational; the .dat format holds polynomial curves only");
    out += std::to_string(curve.number_of_control_points());
    for (std::size_t i = 0; i < curve.number_of_control_points(); ++i) {
      const auto p = curve.control_point(i);
      out += "  " + to_exact_string(p[0]) + " " + to_exact_string(p[1]);
    }
    out += "\n";
  }
  return out;
}

/// Writes a CGAL .dat file (see write_dat()).
inline void write_dat_file(const std::string& path, const Geometry_document& doc) { write_text_file(path, write_dat(doc)); }

} // namespace io
} // namespace bezoutian

#endif // BEZOUTIAN_IO_CGAL_DAT_FORMAT_H
