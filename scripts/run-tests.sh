#!/usr/bin/env bash
# Newcomer command 2: install dependencies, build, and run all tests (ctest), including a check that an
# outside project can use the installed package through find_package(Bezoutian).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-dependencies.sh
start=$(date +%s)
bash scripts/build.sh -DBEZOUTIAN_BUILD_TESTS=ON
echo "build time: $(( $(date +%s) - start )) s"
cd build
ctest --output-on-failure -j"$(nproc)"
