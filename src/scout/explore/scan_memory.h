#ifndef SCOUT_EXPLORE_SCAN_MEMORY_H_
#define SCOUT_EXPLORE_SCAN_MEMORY_H_

#include <Eigen/Core>
#include <deque>
#include <vector>

#include "scout/geometry/rigid_transform.h"

namespace scout::explore {

// The returns of the recent scans near the robot, kept in a frame that does
// not jump (local SLAM's, or odometry's), so the robot can check a move
// toward what its lidar no longer sees (behind it) without trusting the
// global map. Scans older than 'memory_s' of moving time are dropped: the
// time between two scans counts only if the robot moved between them (by
// more than kStillM). What makes old returns wrong is local SLAM's drift, which
// grows as the robot moves; a robot that stands still, or turns on the spot,
// must not forget the wall behind it. In the office (seed 12) the robot turned
// on the spot beside a wall, stood against another for 8 s, and then backed
// into the wall it had seen 11 s before.
class ScanMemory {
 public:
  // A move of at most this much between two scans does not age the memory.
  static constexpr double kStillM = 0.002;
  // At most this many scans are kept (the oldest go first), so a robot that
  // stands still for long keeps a bounded memory.
  static constexpr int kMaxScans = 1000;

  // Keeps scans for memory_s seconds of moving time (0: keeps none) and of
  // each the returns within radius_m of the sensor. Throws
  // std::invalid_argument if either is negative or not finite.
  ScanMemory(double memory_s, double radius_m);

  // Adds the returns (sensor frame, metres) of the scan at 'time_s' taken
  // from 'pose' (memory frame), and drops the scans older than memory_s of
  // moving time.
  void Add(double time_s, const geometry::Rigid2d& pose,
           const std::vector<Eigen::Vector2d>& returns);

  // The kept returns within radius_m of 'pose' (memory frame), in the frame
  // of 'pose'.
  std::vector<Eigen::Vector2d> Around(const geometry::Rigid2d& pose) const;

  int num_scans() const { return static_cast<int>(scans_.size()); }

 private:
  struct Scan {
    double moving_time_s;                 // the moving clock when it was added
    std::vector<Eigen::Vector2d> points;  // memory frame
  };
  const double memory_s_;
  const double radius_m_;
  std::deque<Scan> scans_;
  // Sum of the intervals between consecutive scans across which the robot
  // moved; the previous scan's time and position.
  double moving_time_s_ = 0.0;
  double last_time_s_ = 0.0;
  Eigen::Vector2d last_position_ = Eigen::Vector2d::Zero();
  bool has_last_ = false;
};

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_SCAN_MEMORY_H_
