#!/usr/bin/env bash
# Sanitizer builds of the tests, each in its own build folder (Debug-like: -O1 -g, no -DNDEBUG).
#
#   scripts/sanitizers.sh thread  [TEST_SPEC...]   ThreadSanitizer: test/core/thread_safety_test.cpp and
#                                                  test/core/surface_thread_safety_test.cpp
#   scripts/sanitizers.sh address [TEST_SPEC...]   AddressSanitizer + UndefinedBehaviorSanitizer: bezoutian_tests
#                                                  (test/core, the tests without CGAL's algebraic kernels), or only
#                                                  the files of test/core named in $BEZOUTIAN_SANITIZER_SOURCES
#
# TEST_SPEC are Catch2 test specs (tags, names) passed to the executable; without them every test case of it runs.
# The build folder is $BEZOUTIAN_SANITIZER_BUILD_DIR, default build/sanitizer-<mode> (inside the ignored build/);
# the compiler is $BEZOUTIAN_SANITIZER_CXX, default g++ (its sanitizer run-time libraries come with g++ on Debian).
# GMP, MPFR and MPFI are not instrumented: their memory accesses are not checked, and races inside them are not seen.
# $BEZOUTIAN_SANITIZER_JOBS parallel compile jobs (default: the number of cores). The build defines
# BEZOUTIAN_SANITIZER_BUILD so that tests may shorten their loops.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
mode=${1:-}
case "$mode" in
  thread)
    flags="-fsanitize=thread"
    sources="$root/test/core/thread_safety_test.cpp $root/test/core/surface_thread_safety_test.cpp"
    name=thread_safety_tests ;;
  address)
    flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined"
    sources="$root/test/core/*.cpp"
    if [ -n "${BEZOUTIAN_SANITIZER_SOURCES:-}" ]; then
      sources=""
      for f in $BEZOUTIAN_SANITIZER_SOURCES; do sources="$sources $root/test/core/$f"; done
    fi
    name=bezoutian_tests ;;
  *)
    echo "usage: $0 thread|address [Catch2 test spec...]" >&2
    exit 2 ;;
esac
shift
dir=${BEZOUTIAN_SANITIZER_BUILD_DIR:-$root/build/sanitizer-$mode}
cxx=${BEZOUTIAN_SANITIZER_CXX:-g++}
flags="$flags -fno-omit-frame-pointer -O1 -g"

shared_data=${BEZOUTIAN_SHARED_DATA:-}
if [ -z "$shared_data" ]; then
  for candidate in "$root/../shared/data" "$root/../../shared/data" /work/shared/data; do
    if [ -f "$candidate/README.md" ]; then shared_data=$(cd "$candidate" && pwd); break; fi
  done
fi
if [ -z "$shared_data" ]; then
  echo "the external test data (../shared/data) was not found; set BEZOUTIAN_SHARED_DATA" >&2
  exit 1
fi

# A small project around the library's target: only the chosen test executable is built.
mkdir -p "$dir/project"
cat > "$dir/project/CMakeLists.txt.new" <<EOF
cmake_minimum_required(VERSION 3.16)
project(bezoutian_sanitizer_tests LANGUAGES CXX)
set(BEZOUTIAN_BUILD_TESTS OFF CACHE BOOL "" FORCE)
set(BEZOUTIAN_BUILD_EXAMPLES OFF CACHE BOOL "" FORCE)
add_subdirectory("$root" bezoutian)
find_package(Catch2 2 REQUIRED)
find_package(Threads REQUIRED)
file(GLOB sources CONFIGURE_DEPENDS $sources)
add_executable($name "$root/test/catch_main.cpp" \${sources})
target_link_libraries($name PRIVATE Bezoutian::Bezoutian Catch2::Catch2 Threads::Threads)
target_include_directories($name PRIVATE "$root/test")
target_compile_definitions($name PRIVATE BEZOUTIAN_SANITIZER_BUILD
  BEZOUTIAN_SHARED_DATA="$shared_data" BEZOUTIAN_SOURCE_DIR="$root")
EOF
if ! cmp -s "$dir/project/CMakeLists.txt.new" "$dir/project/CMakeLists.txt"; then
  mv "$dir/project/CMakeLists.txt.new" "$dir/project/CMakeLists.txt"
else
  rm "$dir/project/CMakeLists.txt.new"
fi

launcher=()
if command -v ccache > /dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
start=$(date +%s)
cmake -S "$dir/project" -B "$dir" -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_COMPILER="$cxx" "${launcher[@]}" \
      "-DCMAKE_CXX_FLAGS=$flags" "-DCMAKE_EXE_LINKER_FLAGS=$flags" > "$dir/configure.log" 2>&1 ||
  { cat "$dir/configure.log"; exit 1; }
cmake --build "$dir" -j"${BEZOUTIAN_SANITIZER_JOBS:-$(nproc)}" --target "$name" > "$dir/build.log" 2>&1 || { tail -n 80 "$dir/build.log"; exit 1; }
echo "sanitizer ($mode) build time: $(( $(date +%s) - start )) s (user and system time of this script and its children:"
times
echo ")"

start=$(date +%s)
supp="$root/scripts/sanitizer-$mode.supp"
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1${TSAN_OPTIONS:+ $TSAN_OPTIONS}"
export ASAN_OPTIONS="detect_leaks=1 strict_init_order=1${ASAN_OPTIONS:+ $ASAN_OPTIONS}"
export UBSAN_OPTIONS="print_stacktrace=1 halt_on_error=1${UBSAN_OPTIONS:+ $UBSAN_OPTIONS}"
if [ -f "$supp" ]; then
  case "$mode" in
    thread) TSAN_OPTIONS="$TSAN_OPTIONS suppressions=$supp" ;;
    address) LSAN_OPTIONS="suppressions=$supp${LSAN_OPTIONS:+ $LSAN_OPTIONS}"; export LSAN_OPTIONS ;;
  esac
fi
"$dir/$name" --order rand --rng-seed 20261122 "$@"
echo "sanitizer ($mode) run time: $(( $(date +%s) - start )) s"
