// Patch/patch intersection and self-intersection for the command-line tool (placeholder).
#include "commands.h"

#include <bezoutian/Error.h>

namespace bezoutian_cli {
void run_patch_intersect(const Intersect_options&) {
  throw bezoutian::Error("surface/surface intersection is not available in this build yet");
}
} // namespace bezoutian_cli
