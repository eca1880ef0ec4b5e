#ifndef SCOUT_EXPLORE_ANCHORED_POINT_H_
#define SCOUT_EXPLORE_ANCHORED_POINT_H_

#include <Eigen/Core>
#include <vector>

#include "scout/geometry/rigid_transform.h"

namespace scout::explore {

// The global pose of one submap, as the latest optimisation left it.
struct SubmapPose {
  int id = -1;
  geometry::Rigid2d global_pose;  // submap frame -> global frame
};

// A point stored in one submap's frame, so it moves with that submap when a
// loop closure moves the map (failed goals, the current goal, home).
struct AnchoredPoint {
  // -1: no submap; 'local' is then a global position.
  int submap_id = -1;
  Eigen::Vector2d local = Eigen::Vector2d::Zero();
  // Where the point was when anchored: used if its submap is not listed.
  Eigen::Vector2d global_at_anchor = Eigen::Vector2d::Zero();
};

// Anchors 'global' in the submap whose origin is nearest to it: submaps start
// where the robot was, so the nearest origin is a submap that saw the place
// (an approximation: only poses, no boxes, are known here). Without submaps
// the point is kept in the global frame.
AnchoredPoint Anchor(const Eigen::Vector2d& global, const std::vector<SubmapPose>& submaps);

// Returns the point's global position under the current submap poses.
Eigen::Vector2d Resolve(const AnchoredPoint& point, const std::vector<SubmapPose>& submaps);

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_ANCHORED_POINT_H_
