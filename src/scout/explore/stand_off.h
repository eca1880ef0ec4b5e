#ifndef SCOUT_EXPLORE_STAND_OFF_H_
#define SCOUT_EXPLORE_STAND_OFF_H_

#include <Eigen/Core>
#include <vector>

#include "scout/explore/planning_map.h"

namespace scout::explore {

// Where on a path to a frontier goal the robot should stop.
//
// A frontier point is a free cell next to unknown space, and unknown space
// may hide a wall: a frontier that a grazing ray cut along the unseen side of
// a desk lies on the desk's edge, where no robot can stand. (Office seeds 1-5:
// 1-2 issued navigation points per run lie where the robot's disc cannot get
// within the goal tolerance; their stand-off targets: none.) Nor should the
// robot stop in a narrow passage's band (TraversabilityOptions::
// narrow_margin_m), which is there to pass through: the map can place a wall
// 0.1-0.2 m off, and a stop with only the narrow margin then lies where the
// true wall leaves the disc no room (museum seed 1 at 5505 s: a target 0.25 m
// from an exhibit block's mapped corner).
//
// The robot is therefore sent to the last point of the path, at most
// 'max_back_off_m' of path before the goal, that keeps the full safety margin
// and from which its disc (radius robot_radius_m) covers known-free cells
// only; it sees the frontier from there. Without such a point, the last
// point whose disc covers known-free cells only (a goal in a narrow room
// keeps its stop there). Returns the path itself when its end already
// qualifies, when no point within max_back_off_m does (the robot then drives
// to the goal as before), or when the cut would leave less than
// 'min_length_m' of path (the robot would stop where it stands).
//
// With 'unknown_margin_m' > 0 the full-margin point must also keep that much
// from unknown space (a disc of robot_radius_m + unknown_margin_m covers
// known-free cells only), and is preferred to one that does not. Unknown
// space next to free space may hide a wall the map placed a little off; the
// stop then still lies within the goal tolerance of where the disc fits
// (museum seed 3 at 3559 s: a stop right at the unknown inside of a wall
// mapped 0.23 m off lay 0.2 m inside the true wall).
std::vector<Eigen::Vector2d> CutAtStandOff(const PlanningMap& map,
                                           const std::vector<Eigen::Vector2d>& path,
                                           double max_back_off_m, double min_length_m,
                                           double unknown_margin_m = 0.0);

// True when the cell under 'p' is traversable outside the narrow-passage band.
bool KeepsFullMargin(const PlanningMap& map, const Eigen::Vector2d& p);

// True when every cell the robot's disc at 'p' overlaps is known free.
bool DiscInKnownFree(const PlanningMap& map, const Eigen::Vector2d& p);
// The same for a disc of radius_m.
bool DiscInKnownFree(const PlanningMap& map, const Eigen::Vector2d& p, double radius_m);

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_STAND_OFF_H_
