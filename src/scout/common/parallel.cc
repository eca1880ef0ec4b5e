#include "scout/common/parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace scout::common {

int MaxThreads() {
  static const int threads = std::max(1u, std::thread::hardware_concurrency());
  return threads;
}

void ParallelFor(int64_t n, int64_t min_per_thread,
                 const std::function<void(int64_t begin, int64_t end)>& body) {
  if (n <= 0) return;
  const int64_t by_size = n / std::max<int64_t>(1, min_per_thread);
  const int64_t threads = std::clamp<int64_t>(by_size, 1, MaxThreads());
  if (threads == 1) return body(0, n);
  // Blocks of at most an eighth of a thread's share, taken in turn by
  // whichever thread is free: a thread that shares its core with other work
  // (explore's coverage measurement) then holds up the rest by one block at
  // most. Which thread runs a block does not change what the block computes.
  const int64_t block = std::max<int64_t>(1, n / (threads * 8));
  const int64_t blocks = (n + block - 1) / block;
  std::atomic<int64_t> next = 0;
  std::vector<std::exception_ptr> failure(threads);
  const auto work = [&](int64_t thread) {
    try {
      for (int64_t b = next++; b < blocks; b = next++) {
        body(b * block, std::min(n, (b + 1) * block));
      }
    } catch (...) {
      failure[thread] = std::current_exception();
      next = blocks;  // no new blocks: the loop fails anyway
    }
  };
  std::vector<std::thread> helpers;
  for (int64_t i = 1; i < threads; ++i) helpers.emplace_back(work, i);
  work(0);
  for (std::thread& t : helpers) t.join();
  for (const std::exception_ptr& f : failure) {
    if (f) std::rethrow_exception(f);
  }
}

void ParallelInvoke(const std::function<void()>& a, const std::function<void()>& b) {
  if (MaxThreads() == 1) {
    a();
    return b();
  }
  std::exception_ptr failure_a, failure_b;
  std::thread helper([&] {
    try {
      a();
    } catch (...) {
      failure_a = std::current_exception();
    }
  });
  try {
    b();
  } catch (...) {
    failure_b = std::current_exception();
  }
  helper.join();
  if (failure_a) std::rethrow_exception(failure_a);
  if (failure_b) std::rethrow_exception(failure_b);
}

}  // namespace scout::common
