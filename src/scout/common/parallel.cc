#include "scout/common/parallel.h"

#include <algorithm>
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
  std::vector<std::exception_ptr> failure(threads);
  std::vector<std::thread> helpers;
  const auto chunk = [&](int64_t i) {
    try {
      body(n * i / threads, n * (i + 1) / threads);
    } catch (...) {
      failure[i] = std::current_exception();
    }
  };
  for (int64_t i = 1; i < threads; ++i) helpers.emplace_back(chunk, i);
  chunk(0);
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
