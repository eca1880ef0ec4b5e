#include "scout/slam/work_queue.h"

#include <utility>

namespace scout::slam {

WorkQueue::WorkQueue(bool synchronous) : synchronous_(synchronous) {
  if (!synchronous_) worker_ = std::thread([this] { Run(); });
}

WorkQueue::~WorkQueue() {
  if (synchronous_) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  worker_.join();
}

void WorkQueue::Schedule(std::function<void()> task) {
  if (synchronous_) {
    task();  // exceptions reach the caller directly
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    RethrowFailure();
    tasks_.push_back(std::move(task));
  }
  changed_.notify_all();
}

void WorkQueue::WaitUntilIdle() {
  if (synchronous_) return;
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return tasks_.empty() && running_ == 0; });
  RethrowFailure();
}

int WorkQueue::num_pending() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return static_cast<int>(tasks_.size()) + running_;
}

void WorkQueue::RethrowFailure() {
  if (failure_) std::rethrow_exception(std::exchange(failure_, nullptr));
}

void WorkQueue::Run() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    // Drain everything before honouring a stop: callers rely on scheduled
    // work (e.g. a final optimisation) having run.
    changed_.wait(lock, [this] { return stopping_ || !tasks_.empty(); });
    if (tasks_.empty()) return;
    std::function<void()> task = std::move(tasks_.front());
    tasks_.pop_front();
    ++running_;
    lock.unlock();
    std::exception_ptr failure;
    try {
      task();
    } catch (...) {
      failure = std::current_exception();
    }
    lock.lock();
    --running_;
    if (failure && !failure_) failure_ = failure;
    changed_.notify_all();
  }
}

}  // namespace scout::slam
