#include "scout/slam/optimization_problem.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <tuple>

#include "scout/common/format.h"
#include "scout/slam/relative_pose_cost.h"

namespace scout::slam {
namespace {

using Pose = std::array<double, 3>;  // x, y, theta: one Ceres parameter block

void RequirePositive(const char* key, double value) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw std::invalid_argument(std::string("'slam.pose_graph.optimization_problem.") + key +
                                "': expected a positive finite number, got " + FormatNumber(value));
  }
}

Pose ToPose(const geometry::Rigid2d& t) { return {t.x(), t.y(), t.theta()}; }
geometry::Rigid2d FromPose(const Pose& p) { return geometry::Rigid2d(p[0], p[1], p[2]); }

// Constraint order as a total order on content, so the residual order (and
// hence the floating-point result) does not depend on insertion order.
bool ConstraintLess(const Constraint& a, const Constraint& b) {
  const auto key = [](const Constraint& c) {
    return std::make_tuple(c.submap_id, c.node_id, static_cast<int>(c.kind), c.relative_pose.x(),
                           c.relative_pose.y(), c.relative_pose.theta(), c.translation_weight,
                           c.rotation_weight);
  };
  return key(a) < key(b);
}

}  // namespace

void Validate(const OptimizationProblemOptions& options) {
  RequirePositive("huber_scale", options.huber_scale);
  RequirePositive("local_slam_pose_translation_weight", options.local_slam_pose_translation_weight);
  RequirePositive("local_slam_pose_rotation_weight", options.local_slam_pose_rotation_weight);
  RequirePositive("odometry_translation_weight", options.odometry_translation_weight);
  RequirePositive("odometry_rotation_weight", options.odometry_rotation_weight);
  if (options.max_num_iterations < 1) {
    throw std::invalid_argument(
        "'slam.pose_graph.optimization_problem.max_num_iterations': expected >= 1, got " +
        std::to_string(options.max_num_iterations));
  }
  if (options.num_threads < 1 || options.num_threads > 64) {
    throw std::invalid_argument(
        "'slam.pose_graph.optimization_problem.num_threads': expected 1 to 64, got " +
        std::to_string(options.num_threads));
  }
}

OptimizationProblem::OptimizationProblem(const OptimizationProblemOptions& options)
    : options_(options) {
  Validate(options_);
}

OptimizationResult OptimizationProblem::Solve(
    const std::vector<OptimizationNode>& nodes,
    const std::vector<geometry::Rigid2d>& submap_global_poses,
    const std::vector<Constraint>& constraints) const {
  const int num_nodes = static_cast<int>(nodes.size());
  const int num_submaps = static_cast<int>(submap_global_poses.size());
  for (const Constraint& c : constraints) {
    if (c.node_id < 0 || c.node_id >= num_nodes || c.submap_id < 0 || c.submap_id >= num_submaps) {
      throw std::invalid_argument(
          "OptimizationProblem::Solve: constraint (submap " + std::to_string(c.submap_id) +
          ", node " + std::to_string(c.node_id) + ") outside " + std::to_string(num_submaps) +
          " submaps / " + std::to_string(num_nodes) + " nodes");
    }
  }

  // Parameter blocks live in these vectors, sized once: Ceres keeps pointers.
  std::vector<Pose> node_poses(nodes.size());
  std::vector<Pose> submap_poses(submap_global_poses.size());
  for (int i = 0; i < num_nodes; ++i) node_poses[i] = ToPose(nodes[i].global_pose);
  for (int i = 0; i < num_submaps; ++i) submap_poses[i] = ToPose(submap_global_poses[i]);

  std::vector<const Constraint*> ordered;
  ordered.reserve(constraints.size());
  for (const Constraint& c : constraints) ordered.push_back(&c);
  std::sort(ordered.begin(), ordered.end(),
            [](const Constraint* a, const Constraint* b) { return ConstraintLess(*a, *b); });

  ceres::Problem problem;
  for (const Constraint* c : ordered) {
    ceres::LossFunction* loss = c->kind == ConstraintKind::kInterSubmap
                                    ? new ceres::HuberLoss(options_.huber_scale)
                                    : nullptr;
    problem.AddResidualBlock(
        new RelativePoseCost(c->relative_pose, c->translation_weight, c->rotation_weight), loss,
        submap_poses[c->submap_id].data(), node_poses[c->node_id].data());
  }
  for (int i = 0; i + 1 < num_nodes; ++i) {
    const OptimizationNode& a = nodes[i];
    const OptimizationNode& b = nodes[i + 1];
    problem.AddResidualBlock(new RelativePoseCost(a.local_pose.inverse() * b.local_pose,
                                                  options_.local_slam_pose_translation_weight,
                                                  options_.local_slam_pose_rotation_weight),
                             nullptr, node_poses[i].data(), node_poses[i + 1].data());
    if (options_.use_odometry_constraints && a.odometry_pose && b.odometry_pose) {
      problem.AddResidualBlock(new RelativePoseCost(a.odometry_pose->inverse() * *b.odometry_pose,
                                                    options_.odometry_translation_weight,
                                                    options_.odometry_rotation_weight),
                               nullptr, node_poses[i].data(), node_poses[i + 1].data());
    }
  }
  if (num_submaps > 0 && problem.HasParameterBlock(submap_poses[0].data())) {
    problem.SetParameterBlockConstant(submap_poses[0].data());
  }

  OptimizationResult result;
  if (problem.NumResidualBlocks() > 0) {
    ceres::Solver::Options solver_options;
    solver_options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    solver_options.max_num_iterations = options_.max_num_iterations;
    solver_options.num_threads = options_.num_threads;
    solver_options.logging_type = ceres::SILENT;
    const auto start = std::chrono::steady_clock::now();
    ceres::Solver::Summary summary;
    ceres::Solve(solver_options, &problem, &summary);
    result.summary.solve_time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.summary.num_iterations = static_cast<int>(summary.iterations.size());
    result.summary.initial_cost = summary.initial_cost;
    result.summary.final_cost = summary.final_cost;
    result.summary.usable = summary.IsSolutionUsable();
  } else {
    result.summary.usable = true;  // nothing to adjust: the start is the answer
  }

  if (!result.summary.usable) {
    // A failed solve must not scramble the map: keep the start poses.
    for (int i = 0; i < num_nodes; ++i) node_poses[i] = ToPose(nodes[i].global_pose);
    for (int i = 0; i < num_submaps; ++i) submap_poses[i] = ToPose(submap_global_poses[i]);
  }
  result.node_global_poses.reserve(nodes.size());
  result.submap_global_poses.reserve(submap_global_poses.size());
  for (const Pose& p : node_poses) result.node_global_poses.push_back(FromPose(p));
  for (const Pose& p : submap_poses) result.submap_global_poses.push_back(FromPose(p));
  return result;
}

std::vector<size_t> LoopClosureOutliers(const OptimizationResult& result,
                                        const std::vector<Constraint>& constraints,
                                        double max_translation_m, double max_rotation_rad) {
  std::vector<size_t> outliers;
  for (size_t i = 0; i < constraints.size(); ++i) {
    const Constraint& c = constraints[i];
    if (c.kind != ConstraintKind::kInterSubmap) continue;
    const geometry::Rigid2d solved = result.submap_global_poses.at(c.submap_id).inverse() *
                                     result.node_global_poses.at(c.node_id);
    const geometry::Rigid2d error = c.relative_pose.inverse() * solved;
    if (error.translation().norm() > max_translation_m ||
        std::abs(geometry::NormalizeAngle(error.theta())) > max_rotation_rad) {
      outliers.push_back(i);
    }
  }
  return outliers;
}

}  // namespace scout::slam
