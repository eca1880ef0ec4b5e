#ifndef SCOUT_SLAM_POSE_GRAPH_TYPES_H_
#define SCOUT_SLAM_POSE_GRAPH_TYPES_H_

#include <limits>
#include <optional>

#include "scout/geometry/rigid_transform.h"

// Plain data shared by the pose graph, the constraint builder and the sparse
// pose adjustment. Nodes (one per inserted scan) and submaps are numbered
// densely from 0 in creation order, so a vector index is an id.
namespace scout::slam {

// Where a constraint comes from, which decides how much it is trusted.
enum class ConstraintKind {
  // A node and a submap it was inserted into: the relative pose local SLAM
  // measured. Always correct up to local drift.
  kIntraSubmap,
  // A loop closure found by scan matching a node against a finished submap.
  // Can be wrong (perceptual aliasing), so it is solved under a robust loss.
  kInterSubmap,
};

// A measured pose of node 'node_id' in the frame of submap 'submap_id'.
struct Constraint {
  int submap_id = 0;
  int node_id = 0;
  // Node frame -> submap frame.
  geometry::Rigid2d relative_pose;
  // Residual scale for the translation (per metre) and rotation (per radian).
  double translation_weight = 1.0;
  double rotation_weight = 1.0;
  ConstraintKind kind = ConstraintKind::kIntraSubmap;
};

// How a loop-closure search ended.
enum class LoopClosureOutcome {
  kAccepted,       // added to the graph and still there
  kGated,          // farther from the estimate than the chain's window allows
  kDropped,        // added, then dropped as an outlier after a solve
  kNoMatch,        // nothing in the window reached the search's minimum score
  kFar,            // the best scored below min_score and landed too far for a near match
  kAmbiguous,      // a pose far enough from the best scored about as well
  kWideAmbiguous,  // not the one best again in a wider window around itself
  kSeeingThrough,  // its rays crossed walls the submap knows
};

// One loop-closure search, kept so that a user can see which closures shaped
// the map, why the others were not made, and check both against a reference.
struct LoopClosureRecord {
  int node_id = 0;
  int submap_id = 0;
  LoopClosureOutcome outcome = LoopClosureOutcome::kAccepted;
  // Node frame -> submap frame: as matched (refined when accepted), and as
  // the graph estimated it when the pair was searched. 'match' is only
  // meaningful with has_match (kNoMatch leaves none; an ambiguous search
  // keeps its best).
  bool has_match = true;
  geometry::Rigid2d match;
  geometry::Rigid2d estimate;
  // The branch-and-bound score of the match (NaN without one), the score the
  // submap asks for (min_score, or less for a thin submap), and the half
  // width of the translation window searched.
  double score = std::numeric_limits<double>::quiet_NaN();
  double min_score = std::numeric_limits<double>::quiet_NaN();
  double search_window_m = 0.0;
  // Accepted (or dropped since) scoring below min_score, as a near match.
  bool near_match = false;
  // The gate's limit on |match - estimate| (infinity: no gate).
  double gate_window_m = std::numeric_limits<double>::infinity();
  // The submap's first node and that node's pose in the submap frame (local
  // SLAM's), which place the submap frame for a reference trajectory.
  int submap_first_node_id = 0;
  geometry::Rigid2d first_node_in_submap;
};

// What the optimisation needs to know about a node.
struct OptimizationNode {
  double time_s = 0.0;
  // Robot pose in the local SLAM frame when the scan was inserted.
  geometry::Rigid2d local_pose;
  // Current estimate in the global (optimised) frame; the solver's start.
  geometry::Rigid2d global_pose;
  // Wheel-odometry pose at the node's time, if odometry was available.
  std::optional<geometry::Rigid2d> odometry_pose;
};

}  // namespace scout::slam

#endif  // SCOUT_SLAM_POSE_GRAPH_TYPES_H_
