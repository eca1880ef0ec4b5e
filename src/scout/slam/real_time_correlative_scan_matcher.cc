#include "scout/slam/real_time_correlative_scan_matcher.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "scout/common/format.h"
#include "scout/grid/probability_values.h"
#include "scout/slam/fast_correlative_scan_matcher.h"

namespace scout::slam {
namespace {

void CheckOption(bool ok, const char* name, double value, const char* expected) {
  if (!ok) {
    throw std::invalid_argument(std::string("real_time_correlative_scan_matcher.") + name +
                                " must be " + expected + ", got " + FormatNumber(value));
  }
}

}  // namespace

void Validate(const RealTimeCorrelativeScanMatcherOptions& options) {
  // Every scan searches (2 w / resolution)^2 positions: 2 m is 6,400 at 5 cm
  // (Cartographer: 0.1 m); 1000 m would never finish a scan.
  CheckOption(options.linear_search_window_m >= 0.0 && options.linear_search_window_m <= 2.0,
              "linear_search_window_m", options.linear_search_window_m, "in [0, 2] (m)");
  CheckOption(options.angular_search_window_rad >= 0.0 &&
                  options.angular_search_window_rad <= std::numbers::pi,
              "angular_search_window_rad", options.angular_search_window_rad, "in [0, pi]");
  CheckOption(options.translation_delta_cost_weight >= 0.0, "translation_delta_cost_weight",
              options.translation_delta_cost_weight, ">= 0");
  CheckOption(options.rotation_delta_cost_weight >= 0.0, "rotation_delta_cost_weight",
              options.rotation_delta_cost_weight, ">= 0");
  CheckOption(options.unknown_probability >= grid::kMinProbability - 1e-6 &&
                  options.unknown_probability <= grid::kMaxProbability + 1e-6,
              "unknown_probability", options.unknown_probability, "in [0.1, 0.9]");
  Validate(options.likelihood_field, "real_time_correlative_scan_matcher.");
}

RealTimeCorrelativeScanMatcher::RealTimeCorrelativeScanMatcher(
    const RealTimeCorrelativeScanMatcherOptions& options)
    : options_(options) {
  Validate(options);
}

ScanMatchResult RealTimeCorrelativeScanMatcher::Match(
    const geometry::Rigid2d& initial_pose_estimate, const PointCloud& points,
    const grid::ProbabilityGrid& grid, bool* on_angular_edge) const {
  if (on_angular_edge != nullptr) *on_angular_edge = false;
  ScanMatchResult best{initial_pose_estimate, 0.0};
  if (points.empty()) return best;
  const grid::MapLimits& limits = grid.limits();
  const double resolution = limits.resolution();
  double max_range_m = 0.0;
  for (const Eigen::Vector2d& p : points) max_range_m = std::max(max_range_m, p.norm());
  const double angle_step = AngularSearchStep(max_range_m, resolution);
  const int num_angles_each_side =
      static_cast<int>(std::ceil(options_.angular_search_window_rad / angle_step));
  const int linear_bound =
      static_cast<int>(std::ceil(options_.linear_search_window_m / resolution));
  // Probability is linear in the raw cell value, so candidates sum raw values
  // (an integer, cheaper than decoding each cell) and decode the mean once.
  // Unknown and outside cells count as the value of unknown_probability.
  const std::vector<uint16_t>& values = grid.values();
  const int64_t unknown_value =
      grid::ProbabilityToValue(static_cast<float>(options_.unknown_probability));
  const auto raw_value = [&](int x, int y) -> int64_t {
    if (x < 0 || y < 0 || x >= limits.width() || y >= limits.height()) return unknown_value;
    const int v = values[static_cast<size_t>(y) * limits.width() + x] & grid::kMaxValue;
    return v == grid::kUnknownValue ? unknown_value : v;
  };
  const double min_probability = grid::ValueToProbability(1);
  const double probability_per_value =
      (grid::ValueToProbability(grid::kMaxValue) - min_probability) / (grid::kMaxValue - 1);

  // Raw value with unknown replaced, without the bounds check (the caller
  // knows the cell is inside): branch-free, as most candidates lie wholly inside.
  const auto inside_value = [&](int x, int y) -> int64_t {
    const int v = values[static_cast<size_t>(y) * limits.width() + x] & grid::kMaxValue;
    return v + (v == grid::kUnknownValue) * unknown_value;
  };

  // A candidate: the scan turned by k angle steps ('rotated'), then shifted
  // by (x, y) cells, with the mean score of its points.
  int best_angle_step = 0;
  double initial_score = 0.0;
  const auto offer = [&](double mean_score, const geometry::Rigid2d& rotated, int k, int x, int y) {
    const double delta_angle = k * angle_step;
    const double squared_shift_m2 = resolution * resolution * (x * x + y * y);
    const double score =
        mean_score * std::exp(-(options_.translation_delta_cost_weight * squared_shift_m2 +
                                options_.rotation_delta_cost_weight * delta_angle * delta_angle));
    if (k == 0 && x == 0 && y == 0) initial_score = score;
    if (score > best.score) {
      best.score = score;
      best.pose = geometry::Rigid2d(rotated.translation() + resolution * Eigen::Vector2d(x, y),
                                    rotated.theta());
      best_angle_step = k;
    }
  };
  const auto result = [&]() {
    const bool edge = num_angles_each_side > 0 && std::abs(best_angle_step) == num_angles_each_side;
    if (on_angular_edge != nullptr) *on_angular_edge = edge;
    if (edge && options_.initial_estimate_at_angular_edge) {
      return ScanMatchResult{initial_pose_estimate, initial_score};
    }
    return best;
  };

  if (options_.likelihood_field.sigma_m > 0.0) {
    // Every candidate's points lie within the arc the window turns the
    // farthest one through, and the linear window, of the initial placement.
    const double margin_m = max_range_m * options_.angular_search_window_rad +
                            options_.linear_search_window_m +
                            3.0 * options_.likelihood_field.sigma_m + resolution;
    const LikelihoodField field(grid, initial_pose_estimate, points, margin_m,
                                options_.likelihood_field);
    const grid::MapLimits& window = field.limits();
    std::vector<grid::CellIndex> window_cells(points.size());
    for (int k = -num_angles_each_side; k <= num_angles_each_side; ++k) {
      const double delta_angle = k * angle_step;
      const geometry::Rigid2d rotated(initial_pose_estimate.translation(),
                                      initial_pose_estimate.theta() + delta_angle);
      for (size_t i = 0; i < points.size(); ++i) {
        window_cells[i] = window.CellContaining(rotated * points[i]);
      }
      for (int x = -linear_bound; x <= linear_bound; ++x) {
        for (int y = -linear_bound; y <= linear_bound; ++y) {
          double sum = 0.0;
          for (const grid::CellIndex& cell : window_cells) {
            double value;
            field.GetValue(cell.y + y, cell.x + x, &value);
            sum += value;
          }
          offer(sum / static_cast<double>(points.size()), rotated, k, x, y);
        }
      }
    }
    return result();
  }

  std::vector<grid::CellIndex> cells(points.size());
  for (int k = -num_angles_each_side; k <= num_angles_each_side; ++k) {
    const double delta_angle = k * angle_step;
    const geometry::Rigid2d rotated(initial_pose_estimate.translation(),
                                    initial_pose_estimate.theta() + delta_angle);
    // Discretize once per angle; translations only shift cell indices.
    int min_x = std::numeric_limits<int>::max(), max_x = std::numeric_limits<int>::min();
    int min_y = min_x, max_y = max_x;
    for (size_t i = 0; i < points.size(); ++i) {
      cells[i] = limits.CellContaining(rotated * points[i]);
      min_x = std::min(min_x, cells[i].x);
      max_x = std::max(max_x, cells[i].x);
      min_y = std::min(min_y, cells[i].y);
      max_y = std::max(max_y, cells[i].y);
    }
    for (int x = -linear_bound; x <= linear_bound; ++x) {
      for (int y = -linear_bound; y <= linear_bound; ++y) {
        int64_t sum = 0;
        if (min_x + x >= 0 && min_y + y >= 0 && max_x + x < limits.width() &&
            max_y + y < limits.height()) {
          for (const grid::CellIndex& cell : cells) sum += inside_value(cell.x + x, cell.y + y);
        } else {
          for (const grid::CellIndex& cell : cells) sum += raw_value(cell.x + x, cell.y + y);
        }
        const double mean_probability =
            min_probability +
            (static_cast<double>(sum) / static_cast<double>(points.size()) - 1.0) *
                probability_per_value;
        offer(mean_probability, rotated, k, x, y);
      }
    }
  }
  return result();
}

}  // namespace scout::slam
