// The common result of all file readers: the curves and patches of one file, plus reading and writing
// any supported file by its extension (.json, .dat, .bpt; see doc/formats.md).
//
// Include order: each format header includes this header before its own include guard, and this header
// includes the format headers after defining Geometry_document, so any include order works.
#ifndef BEZOUTIAN_IO_GEOMETRY_DOCUMENT_H
#define BEZOUTIAN_IO_GEOMETRY_DOCUMENT_H

#include <bezoutian/geometry/Rational_bezier_curve.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>
#include <bezoutian/arithmetic/number_types.h>

#include <cctype>
#include <string>
#include <vector>

namespace bezoutian {
namespace io {

/// \brief The geometric objects of one file, by kind, in file order within each kind.
///
/// The name vectors run parallel to the object vectors ("" for an unnamed object); add() keeps them in step.
struct Geometry_document {
  using Curve_2 = Rational_bezier_curve_2<Rational>;
  using Curve_3 = Rational_bezier_curve_3<Rational>;
  using Patch = Rational_bezier_patch<Rational>;

  std::vector<Curve_2> curves_2;
  std::vector<Curve_3> curves_3;
  std::vector<Patch> patches;
  std::vector<std::string> curve_2_names, curve_3_names, patch_names;

  void add(const Curve_2& c, const std::string& name = "") {
    curves_2.push_back(c);
    curve_2_names.resize(curves_2.size() - 1);
    curve_2_names.push_back(name);
  }
  void add(const Curve_3& c, const std::string& name = "") {
    curves_3.push_back(c);
    curve_3_names.resize(curves_3.size() - 1);
    curve_3_names.push_back(name);
  }
  void add(const Patch& p, const std::string& name = "") {
    patches.push_back(p);
    patch_names.resize(patches.size() - 1);
    patch_names.push_back(name);
  }

  /// Name of object i of a kind ("" if none was given).
  std::string curve_2_name(std::size_t i) const { return i < curve_2_names.size() ? curve_2_names[i] : ""; }
  std::string curve_3_name(std::size_t i) const { return i < curve_3_names.size() ? curve_3_names[i] : ""; }
  std::string patch_name(std::size_t i) const { return i < patch_names.size() ? patch_names[i] : ""; }

  std::size_t size() const { return curves_2.size() + curves_3.size() + patches.size(); }
  bool empty() const { return size() == 0; }

  /// Appends all objects (and names) of another document.
  void append(const Geometry_document& o) {
    for (std::size_t i = 0; i < o.curves_2.size(); ++i) add(o.curves_2[i], o.curve_2_name(i));
    for (std::size_t i = 0; i < o.curves_3.size(); ++i) add(o.curves_3[i], o.curve_3_name(i));
    for (std::size_t i = 0; i < o.patches.size(); ++i) add(o.patches[i], o.patch_name(i));
  }
};

} // namespace io
} // namespace bezoutian

#include <bezoutian/io/Bpt_format.h>
#include <bezoutian/io/Cgal_dat_format.h>
#include <bezoutian/io/Json_format.h>

namespace bezoutian {
namespace io {

namespace internal {
/// Lower-case extension including the dot (".json"), or "" if none.
inline std::string file_extension(const std::string& path) {
  const std::size_t slash = path.find_last_of("/\\");
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string e = path.substr(dot);
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}
} // namespace internal

/// \brief Reads a geometry file, choosing the format by extension: .json (Json_format.h), .dat (CGAL's
/// Bezier curve format, Cgal_dat_format.h), .bpt (Bezier patch text, Bpt_format.h).
/// Every failure is a Parse_error "file:line:column: what was expected".
inline Geometry_document read_geometry_file(const std::string& path) {
  const std::string e = internal::file_extension(path);
  if (e == ".json") return read_json_file(path);
  if (e == ".dat") return read_dat_file(path);
  if (e == ".bpt") return read_bpt_file(path);
  throw Parse_error(path, 1, 1, "unknown file extension '" + e + "'; expected .json, .dat or .bpt");
}

/// \brief Writes a geometry file in the format given by the extension (.json, .dat, .bpt). Throws
/// Invalid_input if the format cannot hold the document (.dat: planar polynomial curves only; .bpt:
/// polynomial patches only) and Error if the file cannot be written.
inline void write_geometry_file(const std::string& path, const Geometry_document& doc) {
  const std::string e = internal::file_extension(path);
  if (e == ".json")
    write_json_file(path, doc);
  else if (e == ".dat")
    write_dat_file(path, doc);
  else if (e == ".bpt")
    write_bpt_file(path, doc);
  else
    throw Invalid_input(path + ": unknown file extension '" + e + "'; expected .json, .dat or .bpt");
}

} // namespace io
} // namespace bezoutian

#endif // BEZOUTIAN_IO_GEOMETRY_DOCUMENT_H
