#include "scout/slam/ceres_scan_matcher.h"

#include <ceres/ceres.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "scout/common/format.h"
#include "scout/grid/probability_values.h"
#include "scout/slam/likelihood_field_cost.h"
#include "scout/slam/occupied_space_cost.h"

namespace scout::slam {
namespace {

// Neighbours within this distance decide whether a point lies on a wall, and
// its normal (WallNormalInformation): a few of a sparse scan's returns 5 m
// away, 1 degree apart.
constexpr double kWallNeighbourRadiusM = 0.3;

struct TranslationDeltaCost {
  template <typename T>
  bool operator()(const T* const pose, T* residuals) const {
    residuals[0] = weight * (pose[0] - target.x());
    residuals[1] = weight * (pose[1] - target.y());
    return true;
  }
  double weight;
  Eigen::Vector2d target;
};

// The translation's offset from 'target' along a unit 'direction'.
struct DirectionalDeltaCost {
  template <typename T>
  bool operator()(const T* const pose, T* residuals) const {
    residuals[0] =
        weight * ((pose[0] - target.x()) * direction.x() + (pose[1] - target.y()) * direction.y());
    return true;
  }
  double weight;
  Eigen::Vector2d target;
  Eigen::Vector2d direction;
};

struct RotationDeltaCost {
  template <typename T>
  bool operator()(const T* const pose, T* residuals) const {
    residuals[0] = weight * (pose[2] - target_rad);
    return true;
  }
  double weight;
  double target_rad;
};

void CheckCeresOption(bool ok, const char* name, double value, const char* expected) {
  if (!ok) {
    throw std::invalid_argument(std::string("ceres_scan_matcher.") + name + " must be " + expected +
                                ", got " + FormatNumber(value));
  }
}

}  // namespace

void Validate(const CeresScanMatcherOptions& options) {
  CheckCeresOption(options.occupied_space_weight > 0.0, "occupied_space_weight",
                   options.occupied_space_weight, "> 0");
  CheckCeresOption(options.translation_weight >= 0.0, "translation_weight",
                   options.translation_weight, ">= 0");
  CheckCeresOption(options.rotation_weight >= 0.0, "rotation_weight", options.rotation_weight,
                   ">= 0");
  CheckCeresOption(options.prediction_max_constrained_fraction >= 0.0 &&
                       options.prediction_max_constrained_fraction <= 1.0,
                   "prediction_max_constrained_fraction",
                   options.prediction_max_constrained_fraction, "in [0, 1]");
  CheckCeresOption(options.prediction_translation_weight >= 0.0, "prediction_translation_weight",
                   options.prediction_translation_weight, ">= 0");
  CheckCeresOption(options.unknown_probability >= grid::kMinProbability - 1e-6 &&
                       options.unknown_probability <= grid::kMaxProbability + 1e-6,
                   "unknown_probability", options.unknown_probability, "in [0.1, 0.9]");
  CheckCeresOption(options.full_weight_num_points >= 0, "full_weight_num_points",
                   options.full_weight_num_points, ">= 0");
  Validate(options.likelihood_field, "ceres_scan_matcher.");
  CheckCeresOption(options.max_num_iterations >= 1, "max_num_iterations",
                   options.max_num_iterations, ">= 1");
}

CeresScanMatcher::CeresScanMatcher(const CeresScanMatcherOptions& options) : options_(options) {
  Validate(options);
}

geometry::Rigid2d CeresScanMatcher::Match(const Eigen::Vector2d& target_translation,
                                          const geometry::Rigid2d& initial_pose_estimate,
                                          const PointCloud& points,
                                          const grid::ProbabilityGrid& grid,
                                          const Eigen::Vector2d* predicted_translation) const {
  if (points.empty()) return initial_pose_estimate;
  double pose[3] = {initial_pose_estimate.x(), initial_pose_estimate.y(),
                    initial_pose_estimate.theta()};
  ceres::Problem problem;
  const double num_points_for_weight =
      std::max(points.size(), static_cast<size_t>(options_.full_weight_num_points));
  const double scale = options_.occupied_space_weight / std::sqrt(num_points_for_weight);
  std::optional<LikelihoodField> field;
  if (options_.likelihood_field.sigma_m > 0.0) {
    // The field around the scan as first placed: beyond 3 sigma of the walls
    // it is flat, and the solve moves a scan far less than 0.5 m.
    field.emplace(grid, initial_pose_estimate, points,
                  0.5 + 3.0 * options_.likelihood_field.sigma_m, options_.likelihood_field);
    problem.AddResidualBlock(new LikelihoodFieldCost(scale, points, *field), nullptr, pose);
  } else {
    problem.AddResidualBlock(
        new OccupiedSpaceCost(scale, points, grid, options_.unknown_probability), nullptr, pose);
  }
  if (options_.translation_weight > 0.0) {
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<TranslationDeltaCost, 2, 3>(
            new TranslationDeltaCost{options_.translation_weight, target_translation}),
        nullptr, pose);
  }
  if (options_.prediction_translation_weight > 0.0 && predicted_translation != nullptr) {
    if (options_.prediction_max_constrained_fraction == 0.0) {
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<TranslationDeltaCost, 2, 3>(new TranslationDeltaCost{
              options_.prediction_translation_weight, *predicted_translation}),
          nullptr, pose);
    } else {
      // The walls' normals, turned into the grid frame by the initial heading.
      const Eigen::Matrix2d rotation =
          Eigen::Rotation2Dd(initial_pose_estimate.theta()).toRotationMatrix();
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(
          rotation * WallNormalInformation(points, kWallNeighbourRadiusM) * rotation.transpose());
      for (int i = 0; i < 2; ++i) {
        if (eigen.eigenvalues()(i) >= options_.prediction_max_constrained_fraction) continue;
        problem.AddResidualBlock(
            new ceres::AutoDiffCostFunction<DirectionalDeltaCost, 1, 3>(
                new DirectionalDeltaCost{options_.prediction_translation_weight,
                                         *predicted_translation, eigen.eigenvectors().col(i)}),
            nullptr, pose);
      }
    }
  }
  if (options_.rotation_weight > 0.0) {
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<RotationDeltaCost, 1, 3>(
                                 new RotationDeltaCost{options_.rotation_weight, pose[2]}),
                             nullptr, pose);
  }
  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::DENSE_QR;
  solver_options.max_num_iterations = options_.max_num_iterations;
  solver_options.num_threads = 1;
  solver_options.logging_type = ceres::SILENT;
  solver_options.minimizer_progress_to_stdout = false;
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &problem, &summary);
  return geometry::Rigid2d(pose[0], pose[1], pose[2]);
}

}  // namespace scout::slam
