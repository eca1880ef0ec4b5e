#include "scout/common/parallel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace scout::common {
namespace {

TEST(ParallelFor, VisitsEveryIndexExactlyOnceInContiguousBlocks) {
  for (const int64_t n : {0, 1, 2, 3, 7, 100, 1001}) {
    for (const int64_t min_per_thread : {1, 2, 50, 5000}) {
      std::vector<std::atomic<int>> visits(n);
      std::atomic<int> chunks = 0;
      ParallelFor(n, min_per_thread, [&](int64_t begin, int64_t end) {
        EXPECT_LE(0, begin);
        EXPECT_LT(begin, end);
        EXPECT_LE(end, n);
        ++chunks;
        for (int64_t i = begin; i < end; ++i) ++visits[i];
      });
      for (int64_t i = 0; i < n; ++i) EXPECT_EQ(visits[i], 1) << "n " << n << " index " << i;
      // One block for the whole range when it is too small to share.
      if (n > 0 && n < 2 * min_per_thread) {
        EXPECT_EQ(chunks, 1) << n << " " << min_per_thread;
      }
    }
  }
}

TEST(ParallelFor, UsesOtherThreadsForLargeRangesWhenTheMachineHasThem) {
  if (MaxThreads() < 2) GTEST_SKIP() << "one hardware thread: everything runs on the caller";
  // The first block waits until another block started, so the other blocks
  // must go to another thread (it would wait forever, up to the timeout, if
  // the caller ran them all).
  std::atomic<bool> first_taken = false, other_started = false;
  std::mutex mutex;
  std::set<std::thread::id> threads;
  ParallelFor(1000, 10, [&](int64_t, int64_t) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      threads.insert(std::this_thread::get_id());
    }
    if (!first_taken.exchange(true)) {
      const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
      while (!other_started && std::chrono::steady_clock::now() < give_up) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
    } else {
      other_started = true;
    }
  });
  EXPECT_TRUE(other_started);
  EXPECT_GE(threads.size(), 2u);
}

TEST(ParallelFor, RethrowsABlocksException) {
  std::atomic<int> finished = 0;
  EXPECT_THROW(ParallelFor(1000, 1,
                           [&](int64_t begin, int64_t) {
                             if (begin > 0) throw std::runtime_error("block failed");
                             ++finished;
                           }),
               std::runtime_error);
  EXPECT_LE(finished, 1);  // only the first block succeeds
}

TEST(ParallelInvoke, RunsBothAndRethrowsEitherFailure) {
  int a = 0, b = 0;
  ParallelInvoke([&] { a = 1; }, [&] { b = 2; });
  EXPECT_EQ(a, 1);
  EXPECT_EQ(b, 2);
  EXPECT_THROW(ParallelInvoke([] { throw std::runtime_error("a"); }, [] {}), std::runtime_error);
  EXPECT_THROW(ParallelInvoke([] {}, [] { throw std::logic_error("b"); }), std::logic_error);
  bool b_ran = false;
  EXPECT_THROW(ParallelInvoke([] { throw std::runtime_error("a"); }, [&] { b_ran = true; }),
               std::runtime_error);
  EXPECT_TRUE(b_ran);
}

}  // namespace
}  // namespace scout::common
