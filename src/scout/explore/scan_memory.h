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
// global map. Scans older than 'memory_s' are dropped.
class ScanMemory {
 public:
  // Keeps scans for memory_s seconds (0: keeps none) and of each the returns
  // within radius_m of the sensor. Throws std::invalid_argument if either is
  // negative or not finite.
  ScanMemory(double memory_s, double radius_m);

  // Adds the returns (sensor frame, metres) of the scan at 'time_s' taken
  // from 'pose' (memory frame), and drops the scans older than memory_s.
  void Add(double time_s, const geometry::Rigid2d& pose,
           const std::vector<Eigen::Vector2d>& returns);

  // The kept returns within radius_m of 'pose' (memory frame), in the frame
  // of 'pose'.
  std::vector<Eigen::Vector2d> Around(const geometry::Rigid2d& pose) const;

  int num_scans() const { return static_cast<int>(scans_.size()); }

 private:
  struct Scan {
    double time_s;
    std::vector<Eigen::Vector2d> points;  // memory frame
  };
  const double memory_s_;
  const double radius_m_;
  std::deque<Scan> scans_;
};

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_SCAN_MEMORY_H_
