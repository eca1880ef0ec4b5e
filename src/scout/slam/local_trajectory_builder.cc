#include "scout/slam/local_trajectory_builder.h"

#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "scout/common/format.h"

namespace scout::slam {
namespace {

void CheckLocalOption(bool ok, const std::string& name, double value, const char* expected) {
  if (!ok) {
    throw std::invalid_argument("slam.local." + name + " must be " + expected + ", got " +
                                FormatNumber(value));
  }
}

const LocalSlamOptions& Validated(const LocalSlamOptions& options) {
  Validate(options);
  return options;
}

}  // namespace

void Validate(const LocalSlamOptions& options) {
  CheckLocalOption(options.voxel_filter_size_m > 0.0 && std::isfinite(options.voxel_filter_size_m),
                   "voxel_filter_size_m", options.voxel_filter_size_m, "finite and > 0");
  CheckLocalOption(options.second_search_after_turn_rad >= 0.0 &&
                       options.second_search_after_turn_rad <= std::numbers::pi,
                   "second_search_after_turn_deg",
                   options.second_search_after_turn_rad * 180.0 / std::numbers::pi, "in [0, 180]");
  CheckLocalOption(
      options.second_search_min_gain >= 0.0 && std::isfinite(options.second_search_min_gain),
      "second_search_min_gain", options.second_search_min_gain, "finite and >= 0");
  // The parts name their keys from their own section ("submaps.resolution_m");
  // the user's options file has them under slam.local.
  try {
    sensor::Validate(options.range_filter);
    Validate(options.adaptive_voxel_filter);
    Validate(options.real_time_correlative_scan_matcher);
    Validate(options.ceres_scan_matcher);
    sensor::Validate(options.motion_filter);
    Validate(options.submaps);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("slam.local.") + e.what());
  }
}

LocalTrajectoryBuilder::LocalTrajectoryBuilder(const LocalSlamOptions& options)
    : options_(Validated(options)),
      real_time_matcher_(options.real_time_correlative_scan_matcher),
      ceres_matcher_(options.ceres_scan_matcher),
      motion_filter_(options.motion_filter),
      active_submaps_(options.submaps) {}

void LocalTrajectoryBuilder::AddOdometry(const sensor::Odometry& odometry) {
  if (!options_.use_odometry) return;
  extrapolator_.AddOdometry(odometry);
}

geometry::Rigid2d LocalTrajectoryBuilder::MatchScan(
    const geometry::Rigid2d& prediction, const std::optional<geometry::Rigid2d>& second_prediction,
    const PointCloud& points) {
  // The older submap has seen the most scans: the best reference.
  const grid::ProbabilityGrid& grid = *active_submaps_.submaps().front()->grid();
  const geometry::Rigid2d to_submap = active_submaps_.submaps().front()->local_pose().inverse();
  const geometry::Rigid2d prediction_in_submap = to_submap * prediction;
  geometry::Rigid2d initial = prediction_in_submap;
  // The prior toward the prediction (prediction_translation_weight) applies
  // only after a correlative search: without one the priors below already
  // pull toward the prediction.
  const Eigen::Vector2d predicted_translation = prediction_in_submap.translation();
  const Eigen::Vector2d* prediction_prior = nullptr;
  if (options_.use_online_correlative_scan_matching) {
    bool on_angular_edge = false;
    ScanMatchResult best =
        real_time_matcher_.Match(prediction_in_submap, points, grid, &on_angular_edge);
    if (second_prediction) {
      ++statistics_.num_second_searches;
      bool second_on_angular_edge = false;
      const ScanMatchResult second = real_time_matcher_.Match(
          to_submap * *second_prediction, points, grid, &second_on_angular_edge);
      if (second.score > (1.0 + options_.second_search_min_gain) * best.score) {
        ++statistics_.num_second_search_wins;
        best = second;
        on_angular_edge = second_on_angular_edge;
      }
    }
    initial = best.pose;
    statistics_.num_angular_edge_matches += on_angular_edge ? 1 : 0;
    prediction_prior = &predicted_translation;
  }
  // Both priors pull toward the initial estimate. Cartographer pulls the
  // translation toward the prediction instead; with the default weights (10
  // against an occupied-space weight of 1) that holds the pose near the
  // prediction, and without odometry the constant-velocity model then decays
  // toward standstill (measured on the test lap: 0.75 m error instead of 2 cm).
  const geometry::Rigid2d matched =
      ceres_matcher_.Match(initial.translation(), initial, points, grid, prediction_prior);
  return to_submap.inverse() * matched;
}

std::optional<InsertionResult> LocalTrajectoryBuilder::AddScan(const sensor::LaserScan& scan) {
  ++statistics_.num_scans;
  if (!std::isfinite(scan.time_s) || (last_scan_time_s_ && scan.time_s < *last_scan_time_s_)) {
    ++statistics_.num_out_of_order_scans;
    return std::nullopt;
  }
  const sensor::RangeData range_data = sensor::ToRangeData(scan, options_.range_filter);
  const PointCloud returns = VoxelFilter(range_data.returns, options_.voxel_filter_size_m);
  PointCloud filtered_points = AdaptiveVoxelFilter(returns, options_.adaptive_voxel_filter);
  // Without a return to match, the pose is odometry's. That is good enough to
  // insert the free space the scan saw (a robot starting in a hall wider
  // than its lidar's range sees nothing else), but without odometry it would
  // be a guess: such scans are dropped.
  const bool has_odometry = extrapolator_.OdometryAt(scan.time_s).has_value();
  if (filtered_points.empty() && (range_data.misses.empty() || !has_odometry)) {
    ++statistics_.num_empty_scans;
    return std::nullopt;
  }
  last_scan_time_s_ = scan.time_s;

  geometry::Rigid2d pose = extrapolator_.ExtrapolatePose(scan.time_s);
  if (!active_submaps_.submaps().empty() && !filtered_points.empty()) {
    const auto start = std::chrono::steady_clock::now();
    // The pose odometry predicts had the last match not turned its scan:
    // the same motion since that scan, from its prediction instead of its
    // match.
    std::optional<geometry::Rigid2d> second_prediction;
    if (last_match_ && options_.second_search_after_turn_rad > 0.0 &&
        std::abs(std::remainder(last_match_->pose.theta() - last_match_->prediction.theta(),
                                2.0 * std::numbers::pi)) > options_.second_search_after_turn_rad) {
      second_prediction = last_match_->prediction * last_match_->pose.inverse() * pose;
    }
    const geometry::Rigid2d prediction = pose;
    pose = MatchScan(prediction, second_prediction, filtered_points);
    last_match_ = LastMatch{prediction, pose};
    statistics_.scan_matching_ms +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    ++statistics_.num_matched;
  } else {
    last_match_.reset();
  }
  extrapolator_.AddPose(scan.time_s, pose);
  last_pose_ = pose;
  if (!motion_filter_.Accept(scan.time_s, pose)) return std::nullopt;

  const ActiveSubmaps::Insertion insertion =
      active_submaps_.InsertRangeData(pose.translation(), TransformPointCloud(returns, pose),
                                      TransformPointCloud(range_data.misses, pose));
  ++statistics_.num_inserted;
  InsertionResult result;
  result.time_s = scan.time_s;
  result.local_pose = pose;
  result.filtered_points = std::move(filtered_points);
  for (const std::shared_ptr<const Submap>& submap : insertion.submaps) {
    result.insertion_submaps.push_back(submap->ToEvent());
  }
  result.created_submaps = insertion.created;
  result.finished_submaps = insertion.finished;
  return result;
}

}  // namespace scout::slam
