#ifndef SCOUT_FRONTIER_STOPWATCH_H_
#define SCOUT_FRONTIER_STOPWATCH_H_

#include <chrono>

namespace scout::frontier {

// Measures wall time since construction.
class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  // Returns the microseconds elapsed since construction.
  double ElapsedUs() const {
    return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start_)
        .count();
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

}  // namespace scout::frontier

#endif  // SCOUT_FRONTIER_STOPWATCH_H_
