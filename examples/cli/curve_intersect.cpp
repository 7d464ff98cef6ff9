// Curve/curve and curve/patch intersection for `bezoutian intersect` (placeholder until the curve engine lands).
#include "commands.h"

#include <bezoutian/Error.h>

namespace bezoutian_cli {
void run_curve_intersect(const Intersect_options&) {
  throw bezoutian::Error("curve intersection is not available in this build yet");
}
} // namespace bezoutian_cli
