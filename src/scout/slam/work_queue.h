#ifndef SCOUT_SLAM_WORK_QUEUE_H_
#define SCOUT_SLAM_WORK_QUEUE_H_

#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace scout::slam {

// Runs tasks one at a time in the order they were scheduled: on a background
// thread, or (synchronous) immediately in the scheduling thread. One worker
// and FIFO order make the background results equal to the synchronous ones.
class WorkQueue {
 public:
  explicit WorkQueue(bool synchronous);
  // Finishes every scheduled task, then stops the worker.
  ~WorkQueue();
  WorkQueue(const WorkQueue&) = delete;
  WorkQueue& operator=(const WorkQueue&) = delete;

  // Runs 'task' after all earlier tasks. Rethrows (once) the exception of an
  // earlier background task that failed; tasks after a failure still run.
  void Schedule(std::function<void()> task);
  // Returns once every task scheduled so far has run; rethrows as Schedule.
  void WaitUntilIdle();
  // Tasks scheduled but not finished.
  int num_pending() const;

 private:
  void Run();
  void RethrowFailure();  // requires mutex_

  const bool synchronous_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::function<void()>> tasks_;
  int running_ = 0;
  bool stopping_ = false;
  std::exception_ptr failure_;
  std::thread worker_;
};

}  // namespace scout::slam

#endif  // SCOUT_SLAM_WORK_QUEUE_H_
