#ifndef SCOUT_EXPLORE_SCAN_CONTRADICTION_H_
#define SCOUT_EXPLORE_SCAN_CONTRADICTION_H_

#include <Eigen/Core>
#include <vector>

namespace scout::explore {

// True when the polyline 'path' passes within 'radius_m' of one of the
// 'returns' (same frame): the lidar sees something right where the map lets
// the robot drive. The map is fused from submaps, and a submap a loop
// closure left misplaced can open a lane through solid space that outweighs
// the few scans of the wall the robot has in front of it (museum seed 1 at
// 1812 s: a goal in a lane the map drew through an exhibit block, 2.5 m
// ahead of the robot). A path keeps the inflation (or the narrow margin)
// from mapped walls, so with a radius well below the robot's the returns of
// walls the map has right do not touch it. A path with fewer than two
// points is checked as the point it has (none: false).
bool PathCrossesReturns(const std::vector<Eigen::Vector2d>& path,
                        const std::vector<Eigen::Vector2d>& returns, double radius_m);

// One point per square cell of side cell_m (the first of each, in order):
// the returns of many scans of the same walls fall into the same cells, and
// the check's cost grows with their number. Every input point lies within
// cell_m * sqrt(2) of a kept one. cell_m <= 0 keeps them all.
std::vector<Eigen::Vector2d> ThinToCells(const std::vector<Eigen::Vector2d>& points, double cell_m);

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_SCAN_CONTRADICTION_H_
