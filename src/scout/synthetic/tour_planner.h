#ifndef SCOUT_SYNTHETIC_TOUR_PLANNER_H_
#define SCOUT_SYNTHETIC_TOUR_PLANNER_H_

#include <Eigen/Core>
#include <vector>

#include "scout/sim/world.h"

namespace scout::synthetic {

// How the synthetic robot tours a world, like an exploring robot would: it
// visits waypoints spread over all free space it can reach, nearest first
// (by path length), so it passes through corridors again and again.
struct TourOptions {
  // The tour keeps the robot's centre at least this far from anything not free.
  double path_clearance_m = 0.30;
  // Waypoints are placed where clearance is at least this.
  double waypoint_clearance_m = 0.45;
  // Every reachable cell with waypoint clearance lies within this path
  // distance of a waypoint (half the default lidar range: the robot sees
  // every room it can enter from inside).
  double waypoint_spacing_m = 4.0;
  // Ends the tour back at the start, closing the largest loop.
  bool return_to_start = true;
  // Line-of-sight shortcuts of the grid path are at most this long.
  double max_shortcut_m = 8.0;
  // Before corner cutting, segments are split to at most this length; a
  // corner is rounded over about this distance.
  double smoothing_spacing_m = 0.25;
  // Chaikin corner-cutting passes.
  int smoothing_iterations = 2;
  // A smoothed leg that would bring the robot's centre closer than this to
  // anything not free is used unsmoothed (robot radius, ALGORITHMS §8).
  double min_pose_clearance_m = 0.20;
};

// Returns the tour as a polyline in the world frame, starting at the world's
// start (or, when that is too close to an obstacle, at the start and then the
// nearest cell with path clearance). Consecutive points may reverse direction
// (the robot turns on the spot at waypoints). Throws InputError if no free
// space with path clearance is reachable from the start.
// Throws InputError naming the first bad option ("tour.<key>").
void Validate(const TourOptions& options);

std::vector<Eigen::Vector2d> PlanTour(const sim::World& world, const TourOptions& options);

}  // namespace scout::synthetic

#endif  // SCOUT_SYNTHETIC_TOUR_PLANNER_H_
