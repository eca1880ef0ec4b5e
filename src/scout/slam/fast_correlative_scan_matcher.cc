#include "scout/slam/fast_correlative_scan_matcher.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "scout/grid/probability_values.h"

namespace scout::slam {
namespace {

// Unknown cells and cells outside the grid count as this raw value, which
// decodes to kMinProbability.
constexpr uint16_t kFloorValue = 1;
constexpr int kMidValue = (1 + grid::kMaxValue) / 2;  // decodes to 0.5
constexpr double kProbabilityPerValue =
    (0.9 - 0.1) /  // the exact bounds behind kMinProbability and kMaxProbability
    (grid::kMaxValue - 1);

// Scores are kept as integer sums of raw values: exact and independent of the
// summation order, so pruning compares bounds and leaves without rounding.
double ScoreOfSum(int64_t sum, size_t num_points) {
  return 0.5 + (static_cast<double>(sum) / static_cast<double>(num_points) - kMidValue) *
                   kProbabilityPerValue;
}

}  // namespace

struct FastCorrelativeScanMatcher::Candidate {
  int angle_index = 0;  // into the discretized scans
  int x = 0;            // cell offset
  int y = 0;
  int64_t sum = 0;  // upper bound (or, at depth 0, exact) sum of raw values
};

void Validate(const FastCorrelativeScanMatcherOptions& options) {
  if (!(options.linear_search_window_m >= 0.0)) {
    throw std::invalid_argument(
        "fast_correlative_scan_matcher.linear_search_window_m must be >= 0, got " +
        std::to_string(options.linear_search_window_m));
  }
  if (!(options.angular_search_window_rad >= 0.0 &&
        options.angular_search_window_rad <= std::numbers::pi)) {
    throw std::invalid_argument(
        "fast_correlative_scan_matcher.angular_search_window_rad must be in [0, pi], got " +
        std::to_string(options.angular_search_window_rad));
  }
  if (options.branch_and_bound_depth < 1 || options.branch_and_bound_depth > 16) {
    throw std::invalid_argument(
        "fast_correlative_scan_matcher.branch_and_bound_depth must be in [1, 16], got " +
        std::to_string(options.branch_and_bound_depth));
  }
}

double AngularSearchStep(double max_range_m, double resolution_m) {
  // A slightly smaller step than eq. 7 so a point at max range moves strictly
  // less than one cell between neighbouring angles.
  constexpr double kSafetyMargin = 1.0 - 1e-3;
  if (!(max_range_m > 0.0)) return std::numbers::pi;
  const double cos_step = 1.0 - resolution_m * resolution_m / (2.0 * max_range_m * max_range_m);
  return kSafetyMargin * std::acos(std::clamp(cos_step, -1.0, 1.0));
}

FastCorrelativeScanMatcher::FastCorrelativeScanMatcher(
    const grid::ProbabilityGrid& grid, const FastCorrelativeScanMatcherOptions& options)
    : options_(options), limits_(grid.limits()) {
  Validate(options);
  PrecomputedGrid base;
  base.width = limits_.width();
  base.height = limits_.height();
  base.values.resize(grid.values().size());
  for (size_t i = 0; i < base.values.size(); ++i) {
    const uint16_t v = grid.values()[i] & grid::kMaxValue;
    base.values[i] = v == grid::kUnknownValue ? kFloorValue : v;
  }
  levels_.push_back(std::move(base));
  // Level d from level d - 1: a 2^d window is the union of four 2^(d-1)
  // windows, so each level costs four lookups per cell.
  for (int d = 1; d < options.branch_and_bound_depth; ++d) {
    const PrecomputedGrid& finer = levels_.back();
    const int half = 1 << (d - 1);
    PrecomputedGrid level;
    level.offset = (1 << d) - 1;
    level.width = limits_.width() + level.offset;
    level.height = limits_.height() + level.offset;
    level.values.resize(static_cast<size_t>(level.width) * level.height);
    const auto finer_at = [&finer](int cx, int cy) -> uint16_t {
      const int sx = cx + finer.offset;
      const int sy = cy + finer.offset;
      if (sx < 0 || sy < 0 || sx >= finer.width || sy >= finer.height) return kFloorValue;
      return finer.values[static_cast<size_t>(sy) * finer.width + sx];
    };
    for (int sy = 0; sy < level.height; ++sy) {
      const int cy = sy - level.offset;
      for (int sx = 0; sx < level.width; ++sx) {
        const int cx = sx - level.offset;
        level.values[static_cast<size_t>(sy) * level.width + sx] =
            std::max({finer_at(cx, cy), finer_at(cx + half, cy), finer_at(cx, cy + half),
                      finer_at(cx + half, cy + half)});
      }
    }
    levels_.push_back(std::move(level));
  }
}

std::optional<ScanMatchResult> FastCorrelativeScanMatcher::Match(
    const geometry::Rigid2d& initial_pose_estimate, const PointCloud& points,
    double min_score) const {
  return Search(initial_pose_estimate, points, options_.linear_search_window_m,
                options_.angular_search_window_rad, min_score);
}

std::optional<ScanMatchResult> FastCorrelativeScanMatcher::MatchFullSubmap(const PointCloud& points,
                                                                           double min_score) const {
  const geometry::Box2d bounds = limits_.Bounds();
  const Eigen::Vector2d center = 0.5 * (bounds.min + bounds.max);
  const double half_extent_m =
      0.5 * std::max(bounds.max.x() - bounds.min.x(), bounds.max.y() - bounds.min.y());
  return Search(geometry::Rigid2d(center, 0.0), points, half_extent_m + limits_.resolution(),
                std::numbers::pi, min_score);
}

std::optional<ScanMatchResult> FastCorrelativeScanMatcher::Search(
    const geometry::Rigid2d& initial_pose_estimate, const PointCloud& points,
    double linear_window_m, double angular_window_rad, double min_score) const {
  if (points.empty()) return std::nullopt;
  const double resolution = limits_.resolution();
  double max_range_m = 0.0;
  for (const Eigen::Vector2d& p : points) max_range_m = std::max(max_range_m, p.norm());
  const double angle_step = AngularSearchStep(max_range_m, resolution);
  const int num_angles_each_side = static_cast<int>(std::ceil(angular_window_rad / angle_step));
  const int linear_bound = static_cast<int>(std::ceil(linear_window_m / resolution));

  // The scan, placed at the initial translation under each candidate angle and
  // discretized once; translations then only shift cell indices.
  std::vector<std::vector<grid::CellIndex>> scans;
  std::vector<double> angles;
  for (int k = -num_angles_each_side; k <= num_angles_each_side; ++k) {
    const double angle = initial_pose_estimate.theta() + k * angle_step;
    const geometry::Rigid2d pose(initial_pose_estimate.translation(), angle);
    std::vector<grid::CellIndex>& cells = scans.emplace_back();
    cells.reserve(points.size());
    for (const Eigen::Vector2d& p : points) cells.push_back(limits_.CellContaining(pose * p));
    angles.push_back(angle);
  }

  const auto score = [&](int depth, Candidate* c) {
    const PrecomputedGrid& level = levels_[depth];
    int64_t sum = 0;
    for (const grid::CellIndex& cell : scans[c->angle_index]) {
      const int sx = cell.x + c->x + level.offset;
      const int sy = cell.y + c->y + level.offset;
      sum += (sx < 0 || sy < 0 || sx >= level.width || sy >= level.height)
                 ? kFloorValue
                 : level.values[static_cast<size_t>(sy) * level.width + sx];
    }
    c->sum = sum;
  };
  const auto by_bound = [](const Candidate& a, const Candidate& b) { return a.sum > b.sum; };

  const int top = static_cast<int>(levels_.size()) - 1;
  const int top_step = 1 << top;
  std::vector<Candidate> roots;
  for (int a = 0; a < static_cast<int>(scans.size()); ++a) {
    for (int x = -linear_bound; x <= linear_bound; x += top_step) {
      for (int y = -linear_bound; y <= linear_bound; y += top_step) {
        Candidate c{a, x, y, 0};
        score(top, &c);
        roots.push_back(c);
      }
    }
  }
  std::sort(roots.begin(), roots.end(), by_bound);

  std::optional<Candidate> best;
  // Depth-first, best bound first (Hess et al. 2016, algorithm 3): a node is
  // expanded only if its bound beats both the threshold and the best leaf.
  const auto branch = [&](auto&& self, const std::vector<Candidate>& candidates,
                          int depth) -> void {
    for (const Candidate& c : candidates) {
      if (ScoreOfSum(c.sum, points.size()) < min_score) return;
      if (best.has_value() && c.sum <= best->sum) return;
      if (depth == 0) {
        best = c;
        continue;  // sorted: later siblings cannot beat this leaf
      }
      const int half = 1 << (depth - 1);
      std::vector<Candidate> children;
      children.reserve(4);
      for (const int dx : {0, half}) {
        if (c.x + dx > linear_bound) continue;
        for (const int dy : {0, half}) {
          if (c.y + dy > linear_bound) continue;
          Candidate child{c.angle_index, c.x + dx, c.y + dy, 0};
          score(depth - 1, &child);
          children.push_back(child);
        }
      }
      std::sort(children.begin(), children.end(), by_bound);
      self(self, children, depth - 1);
    }
  };
  branch(branch, roots, top);
  if (!best.has_value()) return std::nullopt;
  const Eigen::Vector2d translation =
      initial_pose_estimate.translation() + resolution * Eigen::Vector2d(best->x, best->y);
  return ScanMatchResult{geometry::Rigid2d(translation, angles[best->angle_index]),
                         ScoreOfSum(best->sum, points.size())};
}

}  // namespace scout::slam
