// Reading and validating input files for the command-line tool.
#ifndef BEZOUTIAN_CLI_LOAD_H
#define BEZOUTIAN_CLI_LOAD_H

#include <bezoutian/geometry/Degeneracy.h>
#include <bezoutian/geometry/Weight_validity.h>
#include <bezoutian/io/Geometry_document.h>

#include <string>
#include <vector>

namespace bezoutian_cli {

/// Reads a file and proves that no weight polynomial has a pole in [0,1] (resp. [0,1]^2); a pole is an
/// error naming the object and an isolating interval (box) of the pole. Degeneracies become warnings.
struct Loaded_file {
  bezoutian::io::Geometry_document doc;
  std::vector<std::string> warnings;
};

inline std::string object_label(const std::string& kind, std::size_t i, const std::string& name) {
  return kind + " " + std::to_string(i) + (name.empty() ? "" : " ('" + name + "')");
}

/// `patch_poles_are_errors` false: a patch with a pole is kept (the model command reports it per patch, see
/// bezoutian::model_problems); curves are checked all the same.
inline Loaded_file load_and_validate(const std::string& path, bool patch_poles_are_errors = true) {
  Loaded_file f{bezoutian::io::read_geometry_file(path), {}};
  auto check = [&](const auto& object, const std::string& label) {
    try {
      bezoutian::check_no_pole(object);
    } catch (const bezoutian::Invalid_input& e) {
      if (patch_poles_are_errors || label.compare(0, 5, "patch") != 0)
        throw bezoutian::Invalid_input(path + ": " + label + ": " + e.what());
      return;
    }
    for (const std::string& w : bezoutian::degeneracy_warnings(object)) f.warnings.push_back(label + ": " + w);
  };
  const auto& d = f.doc;
  for (std::size_t i = 0; i < d.curves_2.size(); ++i) check(d.curves_2[i], object_label("curve", i, d.curve_2_name(i)));
  for (std::size_t i = 0; i < d.curves_3.size(); ++i) check(d.curves_3[i], object_label("curve", i, d.curve_3_name(i)));
  for (std::size_t i = 0; i < d.patches.size(); ++i) check(d.patches[i], object_label("patch", i, d.patch_name(i)));
  return f;
}

} // namespace bezoutian_cli

#endif
