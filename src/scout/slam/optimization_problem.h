#ifndef SCOUT_SLAM_OPTIMIZATION_PROBLEM_H_
#define SCOUT_SLAM_OPTIMIZATION_PROBLEM_H_

#include <vector>

#include "scout/geometry/rigid_transform.h"
#include "scout/slam/pose_graph_types.h"

namespace scout::slam {

// Sparse pose adjustment settings (Cartographer's 2D defaults).
struct OptimizationProblemOptions {
  // Loop closures are solved under a Huber loss of this scale (in units of the
  // weighted residual): a wrong closure then pulls linearly, not quadratically.
  // Cartographer's 10 is 0.9 mm at the loop-closure weight 11000, so every
  // closure pulls linearly and a few cannot undo a metre of drift against the
  // stiff local SLAM chain: on the Radish logs with injected odometry noise
  // (sparse scans, few closures) 100 took the ATE of intel from 0.45 to 0.16 m
  // and of aces from 1.44 to 0.44 m; fr079 0.084 -> 0.082 m. Wrong closures are
  // still dropped by the outlier test of the pose graph.
  double huber_scale = 1e2;
  // Consecutive nodes keep the relative pose local SLAM measured between them,
  // so the trajectory stays rigid between loop closures.
  double local_slam_pose_translation_weight = 1e5;
  double local_slam_pose_rotation_weight = 1e5;
  // Consecutive nodes that both carry an odometry pose also get an odometry
  // constraint. Off by default: local SLAM poses already fuse odometry, and
  // adding it again with equal weight counts the same wheel drift twice.
  bool use_odometry_constraints = false;
  double odometry_translation_weight = 1e5;
  double odometry_rotation_weight = 1e5;
  // Ceres iterations per solve.
  int max_num_iterations = 50;
  // Ceres threads. 1 keeps solves bit-reproducible.
  int num_threads = 1;
};

// Throws std::invalid_argument naming the option when one is out of range.
void Validate(const OptimizationProblemOptions& options);

// What one solve did.
struct SolveSummary {
  int num_iterations = 0;
  double initial_cost = 0.0;
  double final_cost = 0.0;
  double solve_time_s = 0.0;
  bool usable = false;  // Ceres reports a usable solution.
};

struct OptimizationResult {
  std::vector<geometry::Rigid2d> node_global_poses;    // indexed by node id
  std::vector<geometry::Rigid2d> submap_global_poses;  // indexed by submap id
  SolveSummary summary;
};

// Sparse pose adjustment over the (x, y, theta) of every node and submap. The
// problem is stateless: every Solve() receives a snapshot of the graph, so a
// caller can solve on a background thread while new data keeps arriving.
class OptimizationProblem {
 public:
  // Throws std::invalid_argument if 'options' are invalid.
  explicit OptimizationProblem(const OptimizationProblemOptions& options);

  // Returns the global poses that best satisfy 'constraints' plus the relative
  // poses between consecutive nodes, starting from the given global poses.
  // Submap 0 is held fixed (it anchors the global frame). Nodes and submaps no
  // residual touches keep their pose. Constraint ids must index 'nodes' and
  // 'submap_global_poses' (std::invalid_argument otherwise). The result does
  // not depend on the order of 'constraints'.
  OptimizationResult Solve(const std::vector<OptimizationNode>& nodes,
                           const std::vector<geometry::Rigid2d>& submap_global_poses,
                           const std::vector<Constraint>& constraints) const;

 private:
  OptimizationProblemOptions options_;
};

// Returns the indices of the loop closures (kInterSubmap) in 'constraints'
// that 'result' disagrees with: the solved pose of the node in the submap
// frame differs from the measured one by more than 'max_translation_m' or
// 'max_rotation_rad'. Such closures survived the Huber loss only damped.
std::vector<size_t> LoopClosureOutliers(const OptimizationResult& result,
                                        const std::vector<Constraint>& constraints,
                                        double max_translation_m, double max_rotation_rad);

}  // namespace scout::slam

#endif  // SCOUT_SLAM_OPTIMIZATION_PROBLEM_H_
