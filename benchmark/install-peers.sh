#!/usr/bin/env bash
# Installs the benchmark-only peers that the benchmarks compare with (Debian packages; the library never needs
# them): OpenCASCADE 7.6 (GeomAPI_IntSS, benchmark/structured_surfaces_benchmark.cpp) and SISL 4.6.
set -euo pipefail
apt-get install -y libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev libsisl-dev
