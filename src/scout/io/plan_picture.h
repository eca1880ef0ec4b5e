#ifndef SCOUT_IO_PLAN_PICTURE_H_
#define SCOUT_IO_PLAN_PICTURE_H_

#include <Eigen/Core>
#include <filesystem>
#include <vector>

#include "scout/grid/occupancy_map.h"

namespace scout::io {

// A goal as the robot chose it: where it stood, the navigation point, where
// it was sent for it (the stand-off point) and the path planned there, all in
// the frame of the map it was chosen on.
struct PlannedGoal {
  Eigen::Vector2d robot = Eigen::Vector2d::Zero();
  Eigen::Vector2d goal = Eigen::Vector2d::Zero();
  Eigen::Vector2d target = Eigen::Vector2d::Zero();
  std::vector<Eigen::Vector2d> path;
  // The returns of the scan the robot had then, in the same frame (empty:
  // none drawn): where they cross mapped free space, the map was wrong.
  std::vector<Eigen::Vector2d> scan;
};

// Writes a PNG of 'map' around the robot, the goal, the target and the path
// (40 cells of margin, north up; 4 pixels per cell, fewer where that would
// make a side longer than 2400 pixels): free white, occupied
// black, unknown grey, the path blue, the robot green, the target orange and
// the goal red, the scan's returns magenta. For goals the true world made unreachable: the map they
// were chosen on shows whether a gap in a wall or a misplaced wall let them in. Throws
// std::invalid_argument for a map without cells, InputError when the file cannot be written.
void WritePlanPicture(const grid::OccupancyMap& map, const PlannedGoal& planned,
                      const std::filesystem::path& path);

}  // namespace scout::io

#endif  // SCOUT_IO_PLAN_PICTURE_H_
