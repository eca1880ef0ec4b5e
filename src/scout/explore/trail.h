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

// The way back along the positions the robot drove ('driven', oldest first,
// e.g. the SLAM trajectory in the current global frame): starts at 'from' and
// follows 'driven' backwards from its newest point until a point at least
// 'distance_m' from 'from' in a straight line, which ends it. Loops are erased:
// where the way comes back within kLoopTolerance_m of a point it already holds,
// the stretch after that point is dropped, so turning on the spot and creeping
// a few cm to and fro in one place (hundreds of nodes) leaves only the way in.
// No two points of the way lie within kLoopTolerance_m of each other. Empty
// when no driven point is that far from 'from'.
inline constexpr double kLoopTolerance_m = 0.1;
std::vector<Eigen::Vector2d> WayBack(const std::vector<Eigen::Vector2d>& driven,
                                     const Eigen::Vector2d& from, double distance_m);

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_TRAIL_H_
