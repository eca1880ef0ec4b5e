#include "scout/slam/constraint_builder.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace scout::slam {
namespace {

void RequirePositive(const char* key, double value) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw std::invalid_argument(std::string("constraint_builder option '") + key +
                                "': expected a positive finite number, got " +
                                std::to_string(value));
  }
}

}  // namespace

void Validate(const ConstraintBuilderOptions& options) {
  if (!(options.sampling_ratio > 0.0 && options.sampling_ratio <= 1.0)) {
    throw std::invalid_argument(
        "constraint_builder option 'sampling_ratio': expected a value in (0, 1], got " +
        std::to_string(options.sampling_ratio));
  }
  RequirePositive("max_constraint_distance_m", options.max_constraint_distance_m);
  if (!(options.min_score >= 0.0 && options.min_score <= 1.0)) {
    throw std::invalid_argument(
        "constraint_builder option 'min_score': expected a value in [0, 1], got " +
        std::to_string(options.min_score));
  }
  RequirePositive("loop_closure_translation_weight", options.loop_closure_translation_weight);
  RequirePositive("loop_closure_rotation_weight", options.loop_closure_rotation_weight);
  Validate(options.fast_correlative_scan_matcher);
  Validate(options.ceres_scan_matcher);
}

bool FixedRatioSampler::Pulse() {
  ++num_pulses_;
  if (static_cast<double>(num_samples_) < ratio_ * static_cast<double>(num_pulses_)) {
    ++num_samples_;
    return true;
  }
  return false;
}

ConstraintBuilder::ConstraintBuilder(const ConstraintBuilderOptions& options)
    : options_(options), ceres_scan_matcher_((Validate(options), options.ceres_scan_matcher)) {}

void ConstraintBuilder::AddFinishedSubmap(int submap_id,
                                          std::shared_ptr<const grid::ProbabilityGrid> grid) {
  if (submaps_.count(submap_id) > 0) return;  // a finished grid never changes
  // The matcher shares the grid (its finest level) rather than copying it.
  auto matcher =
      std::make_unique<FastCorrelativeScanMatcher>(grid, options_.fast_correlative_scan_matcher);
  submaps_.emplace(submap_id, SubmapMatcher{std::move(grid), std::move(matcher),
                                            FixedRatioSampler(options_.sampling_ratio)});
}

bool ConstraintBuilder::ShouldSearch(int submap_id,
                                     const geometry::Rigid2d& initial_relative_pose) {
  const auto it = submaps_.find(submap_id);
  if (it == submaps_.end()) return false;
  if (initial_relative_pose.translation().norm() > options_.max_constraint_distance_m) {
    return false;
  }
  return it->second.sampler.Pulse();
}

std::optional<Constraint> ConstraintBuilder::Search(int submap_id, int node_id,
                                                    const geometry::Rigid2d& initial_relative_pose,
                                                    const PointCloud& points) {
  const auto it = submaps_.find(submap_id);
  if (it == submaps_.end()) {
    throw std::invalid_argument("ConstraintBuilder::Search: submap " + std::to_string(submap_id) +
                                " was not added as finished");
  }
  ++num_searches_;
  const std::optional<ScanMatchResult> match =
      it->second.matcher->Match(initial_relative_pose, points, options_.min_score);
  if (!match) return std::nullopt;
  // Branch and bound is only cell- and step-accurate; refine on the grid
  // itself, anchored at the branch-and-bound answer.
  const geometry::Rigid2d refined =
      ceres_scan_matcher_.Match(match->pose.translation(), match->pose, points, *it->second.grid);
  ++num_found_;
  return Constraint{submap_id,
                    node_id,
                    refined,
                    options_.loop_closure_translation_weight,
                    options_.loop_closure_rotation_weight,
                    ConstraintKind::kInterSubmap};
}

}  // namespace scout::slam
