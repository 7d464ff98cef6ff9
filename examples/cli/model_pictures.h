// Pictures of a model's intersections for `bezoutian model`: an OBJ file of the patch meshes and every 3D curve,
// grouped by pair of patches, and one SVG per patch of its parameter square with the curves on it.
#ifndef BEZOUTIAN_CLI_MODEL_PICTURES_H
#define BEZOUTIAN_CLI_MODEL_PICTURES_H

#include <bezoutian/intersection/Model_curves.h>

#include <string>
#include <vector>

namespace bezoutian_cli {

/// Writes `path`: an object `patch_K` per patch (a 16 x 16 quad mesh; refused patches are left out, with a
/// comment), an object `pair_I_J` (or `self_I`) per problem with branches (each branch a polyline), and an object
/// `curve_K` per curve of the model (closed curves end at their first vertex).
void write_model_obj(const std::string& path,
                     const std::vector<bezoutian::Rational_bezier_patch<bezoutian::Rational>>& patches,
                     const bezoutian::Model_intersection& R, const std::vector<bezoutian::Model_curve>& curves);

/// Writes DIRECTORY/patch_K.svg for every patch K that has branches: its parameter square [0, 1]^2 with ticks every
/// 0.25, and the parameter curve of every branch on it (for a pair (I, J), the points Locus_point::first on I and
/// Locus_point::second on J; both for a self-intersection), one colour per other patch, named in the legend.
/// Returns the number of files written.
std::size_t write_model_svgs(const std::string& directory, const bezoutian::Model_intersection& R);

}  // namespace bezoutian_cli

#endif  // BEZOUTIAN_CLI_MODEL_PICTURES_H
