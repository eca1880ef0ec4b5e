#include "scout/slam/constraint_builder.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "scout/common/format.h"
#include "scout/grid/probability_values.h"

namespace scout::slam {
namespace {

void RequirePositiveConstraintOption(const char* key, double value) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw std::invalid_argument(std::string("'slam.pose_graph.constraint_builder.") + key +
                                "': expected a positive finite number, got " + FormatNumber(value));
  }
}

// Cells this probable are walls for the free-space check: clearly above the
// 0.5 of a cell seen equally often hit and passed.
constexpr float kWallProbability = 0.6f;

void RequireNonNegative(const char* key, double value) {
  if (!(std::isfinite(value) && value >= 0.0)) {
    throw std::invalid_argument(std::string("'slam.pose_graph.constraint_builder.") + key +
                                "': expected a finite value >= 0, got " + FormatNumber(value));
  }
}

void RequireFraction(const char* key, double value) {
  if (!(value >= 0.0 && value <= 1.0)) {
    throw std::invalid_argument(std::string("'slam.pose_graph.constraint_builder.") + key +
                                "': expected a value in [0, 1], got " + FormatNumber(value));
  }
}

}  // namespace

double MatchScore(const grid::ProbabilityGrid& grid, const geometry::Rigid2d& pose,
                  const PointCloud& points) {
  if (points.empty()) return 0.0;
  const grid::MapLimits& limits = grid.limits();
  double sum = 0.0;
  for (const Eigen::Vector2d& p : points) {
    const grid::CellIndex cell = limits.CellContaining(pose * p);
    const uint16_t value =
        limits.Contains(cell) ? grid.value(cell) & grid::kMaxValue : grid::kUnknownValue;
    sum += value == grid::kUnknownValue ? grid::kMinProbability : grid::ValueToProbability(value);
  }
  return sum / static_cast<double>(points.size());
}

double ObservedFraction(const grid::ProbabilityGrid& grid, const geometry::Rigid2d& pose,
                        const PointCloud& points) {
  if (points.empty()) return 0.0;
  const grid::MapLimits& limits = grid.limits();
  int observed = 0;
  for (const Eigen::Vector2d& p : points) {
    const grid::CellIndex cell = limits.CellContaining(pose * p);
    observed +=
        limits.Contains(cell) && (grid.value(cell) & grid::kMaxValue) != grid::kUnknownValue;
  }
  return static_cast<double>(observed) / static_cast<double>(points.size());
}

double SeeThroughFraction(const grid::ProbabilityGrid& grid, const geometry::Rigid2d& pose,
                          const PointCloud& points, double slack_m) {
  if (points.empty()) return 0.0;
  const grid::MapLimits& limits = grid.limits();
  const uint16_t wall_value = grid::ProbabilityToValue(kWallProbability);
  // Half-cell steps: every cell a ray crosses is visited (corners aside).
  const double step_m = 0.5 * limits.resolution();
  const Eigen::Vector2d origin = pose.translation();
  int seeing_through = 0;
  for (const Eigen::Vector2d& p : points) {
    const Eigen::Vector2d end = pose * p;
    const double length_m = (end - origin).norm();
    const Eigen::Vector2d direction = (end - origin) / std::max(length_m, 1e-9);
    for (double t = 0.0; t < length_m - slack_m; t += step_m) {
      const grid::CellIndex cell = limits.CellContaining(origin + t * direction);
      if (!limits.Contains(cell)) continue;
      if ((grid.value(cell) & grid::kMaxValue) >= wall_value) {
        ++seeing_through;
        break;
      }
    }
  }
  return static_cast<double>(seeing_through) / static_cast<double>(points.size());
}

void Validate(const ConstraintBuilderOptions& options) {
  if (!(options.sampling_ratio > 0.0 && options.sampling_ratio <= 1.0)) {
    throw std::invalid_argument(
        "'slam.pose_graph.constraint_builder.sampling_ratio': expected a value in (0, 1], got " +
        FormatNumber(options.sampling_ratio));
  }
  if (!(options.sampling_phase >= 0.0 && options.sampling_phase < 1.0)) {
    throw std::invalid_argument(
        "'slam.pose_graph.constraint_builder.sampling_phase': expected a value in [0, 1), got " +
        FormatNumber(options.sampling_phase));
  }
  RequirePositiveConstraintOption("max_constraint_distance_m", options.max_constraint_distance_m);
  RequireFraction("min_score", options.min_score);
  RequireFraction("min_score_fraction_of_own_scans", options.min_score_fraction_of_own_scans);
  RequireFraction("min_overlap", options.min_overlap);
  RequireFraction("max_see_through", options.max_see_through);
  RequireNonNegative("see_through_slack_m", options.see_through_slack_m);
  RequireNonNegative("min_search_window_m", options.min_search_window_m);
  RequireNonNegative("search_window_per_travel", options.search_window_per_travel);
  RequireNonNegative("min_angular_search_window_deg", options.min_angular_search_window_deg);
  RequireNonNegative("angular_search_window_deg_per_m", options.angular_search_window_deg_per_m);
  RequireNonNegative("max_sample_spacing_m", options.max_sample_spacing_m);
  if (options.min_num_points < 1) {
    throw std::invalid_argument(
        "'slam.pose_graph.constraint_builder.min_num_points': expected >= 1, got " +
        std::to_string(options.min_num_points));
  }
  RequireNonNegative("wide_ambiguity_min_innovation_m", options.wide_ambiguity_min_innovation_m);
  RequireNonNegative("near_match_max_innovation_m", options.near_match_max_innovation_m);
  RequireFraction("near_match_min_score_fraction", options.near_match_min_score_fraction);
  RequirePositiveConstraintOption("wide_ambiguity_window_factor",
                                  options.wide_ambiguity_window_factor);
  RequirePositiveConstraintOption("wide_ambiguity_max_window_m",
                                  options.wide_ambiguity_max_window_m);
  RequirePositiveConstraintOption("loop_closure_translation_weight",
                                  options.loop_closure_translation_weight);
  RequirePositiveConstraintOption("loop_closure_rotation_weight",
                                  options.loop_closure_rotation_weight);
  Validate(options.fast_correlative_scan_matcher);
  Validate(options.ceres_scan_matcher);
}

bool FixedRatioSampler::Pulse() {
  ++num_pulses_;
  if (static_cast<double>(num_samples_) < ratio_ * static_cast<double>(num_pulses_) - phase_) {
    ++num_samples_;
    return true;
  }
  return false;
}

ConstraintBuilder::ConstraintBuilder(const ConstraintBuilderOptions& options)
    : options_(options), ceres_scan_matcher_((Validate(options), options.ceres_scan_matcher)) {}

void ConstraintBuilder::AddFinishedSubmap(int submap_id,
                                          std::shared_ptr<const grid::ProbabilityGrid> grid,
                                          const std::vector<SubmapScan>& own_scans) {
  if (submaps_.count(submap_id) > 0) return;  // a finished grid never changes
  double min_score = options_.min_score;
  FastCorrelativeScanMatcherOptions matcher_options = options_.fast_correlative_scan_matcher;
  const double fraction = options_.min_score_fraction_of_own_scans;
  if (fraction > 0.0) {
    // Weighted by points: scans without returns (inserted for their free
    // space) say nothing about the submap's walls.
    double sum = 0.0;
    size_t num_points = 0;
    for (const SubmapScan& scan : own_scans) {
      sum += MatchScore(*grid, scan.pose_in_submap, *scan.points) * scan.points->size();
      num_points += scan.points->size();
    }
    const double full_contrast_score = options_.min_score / fraction;
    if (num_points > 0 && full_contrast_score > 0.5) {
      const double own_score = sum / static_cast<double>(num_points);
      min_score = std::min(min_score, fraction * own_score);
      // Its walls stand out from the 0.5 of an undecided cell by this share
      // of a submap that keeps min_score: score differences between a
      // match and its rivals shrink alike.
      const double contrast = std::clamp((own_score - 0.5) / (full_contrast_score - 0.5), 0.0, 1.0);
      matcher_options.ambiguity_score_margin *= contrast;
    }
  }
  // The matcher shares the grid (its finest level) rather than copying it.
  auto matcher = std::make_unique<FastCorrelativeScanMatcher>(grid, matcher_options);
  submaps_.emplace(
      submap_id, SubmapMatcher{std::move(grid), std::move(matcher),
                               FixedRatioSampler(options_.sampling_ratio, options_.sampling_phase),
                               std::nullopt, min_score});
}

double ConstraintBuilder::MinScore(int submap_id) const {
  const auto it = submaps_.find(submap_id);
  return it == submaps_.end() ? options_.min_score : it->second.min_score;
}

double ConstraintBuilder::AmbiguityScoreMargin(int submap_id) const {
  const auto it = submaps_.find(submap_id);
  return it == submaps_.end() ? options_.fast_correlative_scan_matcher.ambiguity_score_margin
                              : it->second.matcher->options().ambiguity_score_margin;
}

double ConstraintBuilder::SearchWindow(double travel_m) const {
  const double full_m = options_.fast_correlative_scan_matcher.linear_search_window_m;
  if (options_.search_window_per_travel <= 0.0) return full_m;
  return std::min(full_m, options_.min_search_window_m +
                              options_.search_window_per_travel * std::max(travel_m, 0.0));
}

double ConstraintBuilder::AngularSearchWindow(double travel_m) const {
  const double full_rad = options_.fast_correlative_scan_matcher.angular_search_window_rad;
  if (options_.search_window_per_travel <= 0.0) return full_rad;
  const double window_deg = options_.min_angular_search_window_deg +
                            options_.angular_search_window_deg_per_m * std::max(travel_m, 0.0);
  return std::min(full_rad, window_deg * M_PI / 180.0);
}

bool ConstraintBuilder::ShouldSearch(int submap_id, const geometry::Rigid2d& initial_relative_pose,
                                     const PointCloud& points, double node_travel_m) {
  const auto it = submaps_.find(submap_id);
  if (it == submaps_.end()) return false;
  if (initial_relative_pose.translation().norm() > options_.max_constraint_distance_m) {
    return false;
  }
  if (static_cast<int>(points.size()) < options_.min_num_points) return false;
  if (options_.min_overlap > 0.0 &&
      ObservedFraction(*it->second.grid, initial_relative_pose, points) < options_.min_overlap) {
    ++num_without_overlap_;
    return false;
  }
  SubmapMatcher& submap = it->second;
  const bool sampled = submap.sampler.Pulse();
  const bool spaced =
      options_.max_sample_spacing_m > 0.0 &&
      (!submap.last_searched_travel_m ||
       std::abs(node_travel_m - *submap.last_searched_travel_m) >= options_.max_sample_spacing_m);
  if (!sampled && !spaced) return false;
  submap.last_searched_travel_m = node_travel_m;
  return true;
}

std::optional<Constraint> ConstraintBuilder::Search(int submap_id, int node_id,
                                                    const geometry::Rigid2d& initial_relative_pose,
                                                    const PointCloud& points, double travel_m,
                                                    double max_innovation_m, SearchReport* report) {
  const auto it = submaps_.find(submap_id);
  if (it == submaps_.end()) {
    throw std::invalid_argument("ConstraintBuilder::Search: submap " + std::to_string(submap_id) +
                                " was not added as finished");
  }
  ++num_searches_;
  SearchReport local_report;
  SearchReport& r = report != nullptr ? *report : local_report;
  r = SearchReport{};
  const double min_score = it->second.min_score;
  r.min_score = min_score;
  r.search_window_m = SearchWindow(travel_m);
  const auto end = [&](LoopClosureOutcome outcome, std::atomic<int>& counter) {
    r.outcome = outcome;
    ++counter;
    return std::nullopt;
  };
  std::optional<ScanMatchResult> ambiguous;
  // With near matches on, the search accepts down to the lower score, and a
  // match below min_score must then land near the estimate.
  const bool near_rule = options_.near_match_max_innovation_m > 0.0;
  const std::optional<ScanMatchResult> match = it->second.matcher->Match(
      initial_relative_pose, points,
      near_rule ? options_.near_match_min_score_fraction * min_score : min_score, r.search_window_m,
      AngularSearchWindow(travel_m), &ambiguous);
  if (!match && ambiguous) {
    r.match = ambiguous->pose;
    r.score = ambiguous->score;
    return end(LoopClosureOutcome::kAmbiguous, num_ambiguous_);
  }
  if (!match) return end(LoopClosureOutcome::kNoMatch, num_without_match_);
  r.match = match->pose;
  r.score = match->score;
  const double innovation_m =
      (match->pose.translation() - initial_relative_pose.translation()).norm();
  const bool near = match->score < min_score;
  if (near && innovation_m > options_.near_match_max_innovation_m) {
    return end(LoopClosureOutcome::kFar, num_without_match_);
  }
  if (innovation_m > max_innovation_m) return end(LoopClosureOutcome::kGated, num_gated_);
  // A match far from the estimate may be a copy of the place (the hall next
  // door): search again around the match, far enough to reach back past the
  // estimate, and keep the match only if it is still the one best answer.
  if (options_.wide_ambiguity_min_innovation_m > 0.0 &&
      innovation_m > options_.wide_ambiguity_min_innovation_m) {
    const double window_m = std::min(options_.wide_ambiguity_max_window_m,
                                     options_.wide_ambiguity_window_factor * innovation_m);
    const std::optional<ScanMatchResult> wide = it->second.matcher->Match(
        match->pose, points, min_score, window_m, AngularSearchWindow(travel_m));
    if (!wide || (wide->pose.translation() - match->pose.translation()).norm() >
                     it->second.matcher->options().ambiguity_radius_m) {
      return end(LoopClosureOutcome::kWideAmbiguous, num_wide_ambiguous_);
    }
  }
  // Branch and bound is only cell- and step-accurate; refine on the grid
  // itself, anchored at the branch-and-bound answer.
  const geometry::Rigid2d refined =
      ceres_scan_matcher_.Match(match->pose.translation(), match->pose, points, *it->second.grid);
  r.match = refined;
  if (options_.max_see_through < 1.0 &&
      SeeThroughFraction(*it->second.grid, refined, points, options_.see_through_slack_m) >
          options_.max_see_through) {
    return end(LoopClosureOutcome::kSeeingThrough, num_seeing_through_);
  }
  r.outcome = LoopClosureOutcome::kAccepted;
  r.near = near;
  ++num_found_;
  if (near) ++num_near_matches_;
  return Constraint{submap_id,
                    node_id,
                    refined,
                    options_.loop_closure_translation_weight,
                    options_.loop_closure_rotation_weight,
                    ConstraintKind::kInterSubmap};
}

}  // namespace scout::slam
