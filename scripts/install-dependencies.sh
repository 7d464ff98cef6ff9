#!/usr/bin/env bash
# Installs what Bezoutian needs on Debian bookworm (run as root). Skips apt when everything is present.
# g++ brings the sanitizer run-time libraries of scripts/sanitizers.sh (libasan8, libubsan1, libtsan2).
set -euo pipefail
packages=(g++ cmake make ccache libcgal-dev libgmp-dev libmpfr-dev libmpfi-dev libboost-dev
          catch2 nlohmann-json3-dev libcli11-dev doxygen
          python3-jsonschema  # validates the --json output against its schema (ctest cli_json_output)
          libopenmpi-dev openmpi-bin  # MPI: `mpirun -n K bezoutian model`, not used by the library
          libflint-dev  # FLINT: compared against in benchmark/, not used by the library
          libcgal-demo)  # libcgal-demo: CGAL's Bezier.dat (examples.tar.gz), compared against in the tests
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
