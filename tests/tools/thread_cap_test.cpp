// withThreadCap: --threads caps the arena a command's loading and geometry run in.
#include "thread_cap.hpp"

#include <gtest/gtest.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "lacrima/base/error.hpp"

namespace lacrima::cli {
namespace {

// The most tasks of a parallel loop that ran at the same time inside withThreadCap(threads).
int mostAtOnce(int threads) {
  return withThreadCap(threads, [] {
    std::atomic<int> running{0}, most{0};
    tbb::parallel_for(0, 64, [&](int) {
      const int now = ++running;
      int seen = most.load();
      while (now > seen && !most.compare_exchange_weak(seen, now)) {
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      --running;
    });
    return most.load();
  });
}

TEST(ThreadCap, OneThreadRunsOneTaskAtATime) {
  EXPECT_EQ(withThreadCap(1, [] { return tbb::this_task_arena::max_concurrency(); }), 1);
  EXPECT_EQ(mostAtOnce(1), 1);
}

TEST(ThreadCap, ZeroMeansAllCores) {
  EXPECT_EQ(withThreadCap(0, [] { return tbb::this_task_arena::max_concurrency(); }), tbb::info::default_concurrency());
  if (tbb::info::default_concurrency() > 1) {
    EXPECT_GT(mostAtOnce(0), 1);
  }
}

TEST(ThreadCap, ErrorsComeThrough) {
  EXPECT_THROW(withThreadCap(1, []() -> int { throw InputError("shot.json: /render/spp: must be >= 1"); }), InputError);
}

}  // namespace
}  // namespace lacrima::cli
