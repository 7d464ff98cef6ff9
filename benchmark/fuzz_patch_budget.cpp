// How long the patch fuzz target (fuzz/targets.h, small_patches: time_limit 2 s) takes on random byte strings of
// 40-160 bytes, the kind of seed its libFuzzer runs start from: every input should end near or below the budget.
//   build/benchmark/fuzz_patch_budget [N = 40] [seed = 1]
// prints each input's time and the worst; the figures in doc/hostile_input.md ("The patch target") come from
// seeds 1, 2 and 3 with N = 40.
#include "../fuzz/targets.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 40;
  const unsigned seed = argc > 2 ? unsigned(std::atoi(argv[2])) : 1u;
  std::mt19937 g(seed);
  double worst = 0;
  int at_budget = 0;
  for (int k = 0; k < n; ++k) {
    std::vector<std::uint8_t> bytes(40 + g() % 121);
    for (auto& b : bytes) b = std::uint8_t(g());
    const auto t0 = std::chrono::steady_clock::now();
    bezoutian::fuzz::small_patches(bytes.data(), bytes.size());
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    worst = std::max(worst, s);
    at_budget += s >= 1.99;
    std::printf("input %2d (%3zu bytes): %.3f s\n", k, bytes.size(), s);
    std::fflush(stdout);
  }
  std::printf("worst %.3f s; %d of %d inputs ended by the 2 s budget\n", worst, at_budget, n);
}
