#ifndef SCOUT_COMMON_PARALLEL_H_
#define SCOUT_COMMON_PARALLEL_H_

#include <cstdint>
#include <functional>

namespace scout::common {

// Threads the loops below use at most: the machine's hardware threads.
int MaxThreads();

// Runs body(begin, end) over [0, n) in contiguous blocks on up to
// MaxThreads() threads (the calling thread is one of them), and returns when
// all are done. Fewer threads when one would get fewer than 'min_per_thread'
// indices (small grids are not worth a thread); a single thread runs
// body(0, n). Every index lands in exactly one block, so a body that writes
// only its own indices computes what the serial loop does, on any number of
// threads: results stay bit-identical and deterministic. Rethrows the
// exception of a failed block after all threads have ended.
void ParallelFor(int64_t n, int64_t min_per_thread,
                 const std::function<void(int64_t begin, int64_t end)>& body);

// Runs 'a' on another thread and 'b' on this one, and returns when both are
// done; rethrows the exception of either (a's first).
void ParallelInvoke(const std::function<void()>& a, const std::function<void()>& b);

}  // namespace scout::common

#endif  // SCOUT_COMMON_PARALLEL_H_
