#ifndef SCOUT_EXPLORE_TRAIL_H_
#define SCOUT_EXPLORE_TRAIL_H_

#include <Eigen/Core>
#include <deque>
#include <vector>

namespace scout::explore {

// The last stretch of the path the robot drove: positions (global) at least
// kStep_m apart, oldest first, covering at most a given length. The disc fit
// everywhere along it in the world, whatever the map says now.
class Trail {
 public:
  // Finer than the tolerances the trail is checked against by far; turning
  // on the spot adds no point.
  static constexpr double kStep_m = 0.02;

  // Adds 'position' unless it lies within kStep_m of the newest point, then
  // drops the oldest points while the rest still covers 'max_length_m'.
  // A 'max_length_m' of 0 keeps nothing.
  void Record(const Eigen::Vector2d& position, double max_length_m);
  void Clear();

  const std::deque<Eigen::Vector2d>& points() const { return points_; }
  double length_m() const { return length_m_; }
  bool empty() const { return points_.empty(); }
  // The trail driven backwards from 'from' (the robot, first point) to its
  // oldest point.
  std::vector<Eigen::Vector2d> Reversed(const Eigen::Vector2d& from) const;

 private:
  std::deque<Eigen::Vector2d> points_;
  double length_m_ = 0.0;
};

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_TRAIL_H_
