#ifndef SCOUT_EVENTS_SUBMAP_EVENTS_H_
#define SCOUT_EVENTS_SUBMAP_EVENTS_H_

#include <Eigen/Core>
#include <memory>
#include <variant>
#include <vector>

#include "scout/geometry/rigid_transform.h"
#include "scout/grid/probability_grid.h"

// The seam between any submap SLAM and frontier detection (ARCHITECTURE.md):
// SLAM emits these plain events; the frontier module consumes only them.
namespace scout::events {

// Submaps are numbered densely in creation order, from 0.
using SubmapId = int;

// A submap's grid changed (a scan was inserted), or it was finished.
// The submap frame is the frame of its grid's MapLimits.
struct SubmapChanged {
  SubmapId id = 0;
  // Immutable snapshot of the submap's grid after the change.
  std::shared_ptr<const grid::ProbabilityGrid> grid;
  // Submap frame -> local SLAM frame (where local SLAM placed it).
  geometry::Rigid2d local_pose;
  // Robot positions of every scan inserted so far, in the submap frame.
  std::vector<Eigen::Vector2d> scan_origins;
  // True once the submap receives no further scans.
  bool finished = false;
};

// One pose-graph solve finished: the new global pose (submap frame -> global
// frame) of every submap created so far, indexed by SubmapId.
struct Optimized {
  std::vector<geometry::Rigid2d> global_poses;
};

using SubmapEvent = std::variant<SubmapChanged, Optimized>;

}  // namespace scout::events

#endif  // SCOUT_EVENTS_SUBMAP_EVENTS_H_
