// The library's one profiling facility, compiled in only when BEZOUTIAN_PROFILE is defined (otherwise every macro
// expands to nothing and costs nothing). Two kinds of measurement, printed on standard error:
//  - BEZOUTIAN_PROFILE_SCOPE("name"): calls and total wall time of the enclosing scope, summed over the whole run
//    and printed once at exit ("name  calls  ms");
//  - BEZOUTIAN_PROFILE_START; ... BEZOUTIAN_PROFILE_STEP("name"): the wall time of each step of a computation since
//    the previous step or the last start, printed as it happens ("name  ms"); the steps of one computation may lie
//    in several functions (one timeline per thread).
// Build with -DBEZOUTIAN_PROFILE, e.g. cmake -DCMAKE_CXX_FLAGS=-DBEZOUTIAN_PROFILE. Not thread-safe: meant for
// single-threaded profiling runs only.
#ifndef BEZOUTIAN_ARITHMETIC_PROFILING_H
#define BEZOUTIAN_ARITHMETIC_PROFILING_H

#ifdef BEZOUTIAN_PROFILE
#include <chrono>
#include <cstdio>

namespace bezoutian {
namespace internal {

/// Calls and total time of one profiled site; printed when the program ends.
struct Profile_site {
  const char* name;
  long calls = 0;
  double ms = 0;
  explicit Profile_site(const char* s) : name(s) {}
  ~Profile_site() { std::fprintf(stderr, "%-28s %8ld calls %10.2f ms\n", name, calls, ms); }
};

/// Adds the lifetime of the enclosing scope to a site.
struct Profile_scope_timer {
  Profile_site& site;
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  explicit Profile_scope_timer(Profile_site& s) : site(s) { ++site.calls; }
  ~Profile_scope_timer() {
    site.ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  }
};

/// The time of the last step or start of this thread's timeline.
inline std::chrono::steady_clock::time_point& profile_last_step() {
  thread_local std::chrono::steady_clock::time_point last = std::chrono::steady_clock::now();
  return last;
}

/// Prints the time since the previous step (or start) of this thread's timeline.
inline void profile_step(const char* name) {
  const auto now = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point& last = profile_last_step();
  std::fprintf(stderr, "%-28s %10.2f ms\n", name, std::chrono::duration<double, std::milli>(now - last).count());
  last = now;
}

}  // namespace internal
}  // namespace bezoutian

#define BEZOUTIAN_PROFILE_CAT2(a, b) a##b
#define BEZOUTIAN_PROFILE_CAT(a, b) BEZOUTIAN_PROFILE_CAT2(a, b)
#define BEZOUTIAN_PROFILE_SCOPE(name)                                                                        \
  static ::bezoutian::internal::Profile_site BEZOUTIAN_PROFILE_CAT(bezoutian_profile_site_, __LINE__)(name); \
  ::bezoutian::internal::Profile_scope_timer BEZOUTIAN_PROFILE_CAT(bezoutian_profile_timer_, __LINE__)(      \
      BEZOUTIAN_PROFILE_CAT(bezoutian_profile_site_, __LINE__))
#define BEZOUTIAN_PROFILE_START (void)(::bezoutian::internal::profile_last_step() = std::chrono::steady_clock::now())
#define BEZOUTIAN_PROFILE_STEP(name) ::bezoutian::internal::profile_step(name)
#else
#define BEZOUTIAN_PROFILE_SCOPE(name)
#define BEZOUTIAN_PROFILE_START
#define BEZOUTIAN_PROFILE_STEP(name)
#endif

#endif  // BEZOUTIAN_ARITHMETIC_PROFILING_H
