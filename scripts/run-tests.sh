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
# Sanitizers (doc/hostile_input.md, "Sanitizers and threads"): the thread tests (curves, surfaces, models) under
# ThreadSanitizer, and under
# AddressSanitizer + UndefinedBehaviorSanitizer the part of bezoutian_tests that covers the algebraic numbers, the
# lazy parameters, threads, the readers, the determinant engine and curve intersection on external data (all of
# bezoutian_tests costs about 35 CPU minutes to build: too much for CI's hour on two cores).
start=$(date +%s)
bash scripts/sanitizers.sh thread
BEZOUTIAN_SANITIZER_SOURCES="root_isolation_test.cpp planar_lazy_test.cpp thread_safety_test.cpp formats_test.cpp
  determinant_test.cpp curve_intersection_data_test.cpp weight_validity_test.cpp two_branch_box_test.cpp" \
  bash scripts/sanitizers.sh address "~[scale]"
echo "sanitizer builds and runs: $(( $(date +%s) - start )) s"
