// Test helper for the thread-safety tests: runs a body on several threads released together.
#ifndef BEZOUTIAN_TEST_THREAD_TEST_SUPPORT_H
#define BEZOUTIAN_TEST_THREAD_TEST_SUPPORT_H

#include <atomic>
#include <thread>
#include <vector>

namespace bezoutian_test {

/// The number of threads of the thread-safety tests.
constexpr int test_threads = 4;

/// Runs body(k) on test_threads threads, k = 0..test_threads-1, released together (each waits until all have
/// started), so that they race on whatever they share.
template <class F>
void run_on_threads(F body) {
  std::atomic<int> ready{0};
  std::vector<std::thread> pool;
  for (int k = 0; k < test_threads; ++k)
    pool.emplace_back([&, k] {
      ++ready;
      while (ready.load() < test_threads) std::this_thread::yield();
      body(k);
    });
  for (auto& t : pool) t.join();
}

}  // namespace bezoutian_test

#endif
