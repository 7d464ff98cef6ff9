#!/usr/bin/env bash
# Newcomer command 2: install dependencies, build, and run all tests (ctest), including a check that an
# outside project can use the installed package through find_package(Bezoutian), then the sanitizer runs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-dependencies.sh
start=$(date +%s)
bash scripts/build.sh -DBEZOUTIAN_BUILD_TESTS=ON
echo "build time: $(( $(date +%s) - start )) s"
cd build
ctest --output-on-failure -j"$(nproc)"
cd ..
# Sanitizers (doc/hostile_input.md, "Sanitizers and threads"): the thread test under ThreadSanitizer, and
# bezoutian_tests (the tests without CGAL's algebraic kernels) under AddressSanitizer + UndefinedBehaviorSanitizer.
start=$(date +%s)
bash scripts/sanitizers.sh thread
bash scripts/sanitizers.sh address
echo "sanitizer builds and runs: $(( $(date +%s) - start )) s"
