// forEachInParallel (core/parallel.h): every job runs once, on several threads where the
// machine has several cores, and a job's exception reaches the caller.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/parallel.h"

namespace {

TEST(ForEachInParallel, CallsEveryIndexExactlyOnce) {
  for (uint32_t count : {0u, 1u, 2u, 3u, 1000u}) {
    std::vector<std::atomic<int>> calls(count);
    wp::forEachInParallel(count, [&](uint32_t i) { ++calls[i]; });
    for (uint32_t i = 0; i < count; ++i) EXPECT_EQ(calls[i].load(), 1) << "index " << i << " of " << count;
  }
}

// Jobs that each take a while: the helper threads start long before the calling thread could
// have done them all, so a machine of several cores runs them on several threads.
TEST(ForEachInParallel, UsesTheMachinesCores) {
  std::mutex mutex;
  std::set<std::thread::id> threads;
  wp::forEachInParallel(40, [&](uint32_t) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    std::lock_guard<std::mutex> lock(mutex);
    threads.insert(std::this_thread::get_id());
  });
  const size_t cores = std::max(1u, std::thread::hardware_concurrency());
  EXPECT_EQ(threads.size(), std::min<size_t>(cores, 40));
}

TEST(ForEachInParallel, RethrowsAJobsExceptionAfterEveryThreadStopped) {
  std::atomic<int> running{0};
  std::atomic<int> started{0};
  try {
    wp::forEachInParallel(1000, [&](uint32_t i) {
      ++running;
      ++started;
      std::this_thread::sleep_for(std::chrono::microseconds(100));
      --running;
      if (i == 3) throw std::runtime_error("job 3 failed");
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "job 3 failed");
  }
  EXPECT_EQ(running.load(), 0);  // nothing still running when the caller sees the exception
  EXPECT_LT(started.load(), 1000);  // the jobs after the failure were skipped
}

}  // namespace
