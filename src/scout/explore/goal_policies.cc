#include "scout/explore/goal_policies.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "scout/explore/mean_shift.h"
#include "scout/explore/option_check.h"
#include "scout/explore/tour.h"

namespace scout::explore {

void Validate(const GoalPolicyOptions& o) {
  Validate(o.navigation);
  CheckAtLeast("explore_lite", "potential_scale", o.explore_lite.potential_scale, 0.0);
  CheckAtLeast("explore_lite", "gain_scale", o.explore_lite.gain_scale, 0.0);
  CheckAtLeast("explore_lite", "min_frontier_size_m", o.explore_lite.min_frontier_size_m, 0.0);
}

const std::vector<std::string>& GoalPolicyNames() {
  static const std::vector<std::string> names = {"scout", "nearest", "explore-lite",
                                                 "meanshift-centres"};
  return names;
}

namespace {

void SortBestFirst(std::vector<GoalCandidate>& goals) {
  std::stable_sort(goals.begin(), goals.end(), [](const GoalCandidate& a, const GoalCandidate& b) {
    return a.score > b.score;
  });
}

class ScoutPolicy : public GoalPolicy {
 public:
  explicit ScoutPolicy(const NavigationPointOptions& o) : options_(o) {}
  std::string_view name() const override { return "scout"; }
  bool checks_paths_against_scan() const override { return true; }
  bool keeps_stand_off_from_unknown() const override { return true; }
  bool needs_path_distances() const override { return true; }
  std::any Prepare(const PolicyInput& in) const override {
    return PartitionFrontier(*in.map, Avoiding(in), options_);
  }
  // Revenue = info_multiplier · gain − path cost, the gain (times the
  // hysteresis gain near the current goal) being unknown area in the square
  // of cells InfoGain scans. With tours the score is a tour length instead.
  std::optional<double> ScoreAbovePathCost(const PlanningMap& map) const override {
    if (options_.tour_points >= 2) return std::nullopt;
    return options_.info_multiplier * std::max(1.0, options_.hysteresis_gain) *
           MaxInfoGainM2(map.limits().resolution(), options_);
  }
  std::vector<GoalCandidate> Rank(const PolicyInput& in) const override {
    const FrontierPartition* prepared =
        in.prepared ? std::any_cast<FrontierPartition>(in.prepared) : nullptr;
    const FrontierPartition partition =
        prepared ? FrontierPartition{} : PartitionFrontier(*in.map, Avoiding(in), options_);
    const std::vector<NavigationPoint> points =
        ComputeNavigationPoints(*in.map, *in.distances, prepared ? *prepared : partition, in.robot,
                                in.current_goal, options_);
    std::vector<GoalCandidate> goals;
    for (const NavigationPoint& p : points) goals.push_back({p.position, p.revenue});
    if (options_.tour_points >= 2) OrderByTour(*in.map, points, goals);
    return goals;  // best first
  }

 private:
  // The frontier without the points near blacklisted goals.
  static std::vector<Eigen::Vector2d> Avoiding(const PolicyInput& in) {
    std::vector<Eigen::Vector2d> frontier;
    const double r2 = in.avoid_radius_m * in.avoid_radius_m;
    for (const Eigen::Vector2d& p : *in.frontier) {
      const auto near = [&](const Eigen::Vector2d& a) { return (a - p).squaredNorm() <= r2; };
      if (!in.avoid || std::none_of(in.avoid->begin(), in.avoid->end(), near)) {
        frontier.push_back(p);
      }
    }
    return frontier;
  }

  // The first tour_points goals (best revenue first) ranked by their open
  // tour length, shortest first (score: minus the length, metres); the rest
  // keep their order below them.
  // 'goals' are 'points' in the same order.
  void OrderByTour(const PlanningMap& map, const std::vector<NavigationPoint>& points,
                   std::vector<GoalCandidate>& goals) const {
    const size_t k = std::min<size_t>(options_.tour_points, goals.size());
    if (k < 2) return;
    std::vector<grid::CellIndex> cells;
    std::vector<double> first_leg_m;
    for (size_t i = 0; i < k; ++i) {
      cells.push_back(points[i].reached_cell);
      first_leg_m.push_back(points[i].cost_m);
    }
    const std::vector<double> length =
        OpenTourLengths(first_leg_m, CoarsePathDistances(map, cells, kTourCell_m));
    double worst = -std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < k; ++i) {
      goals[i].score = -length[i];
      worst = std::max(worst, length[i]);
    }
    for (size_t i = k; i < goals.size(); ++i) goals[i].score = -worst - 1.0 - double(i - k);
    std::stable_sort(
        goals.begin(), goals.begin() + k,
        [](const GoalCandidate& a, const GoalCandidate& b) { return a.score > b.score; });
  }
  // A sixteenth of the cells of a 5 cm map for the pairwise searches; a
  // closed band at least two coarse cells (0.4 m) wide stays closed, and a
  // wall inflated by the robot's radius and margin on both sides is wider.
  static constexpr double kTourCell_m = 0.2;

  NavigationPointOptions options_;
};

class NearestPolicy : public GoalPolicy {
 public:
  std::string_view name() const override { return "nearest"; }
  std::vector<GoalCandidate> Rank(const PolicyInput& in) const override {
    std::vector<GoalCandidate> goals;
    for (const Eigen::Vector2d& p : *in.frontier) goals.push_back({p, -(p - in.robot).norm()});
    SortBestFirst(goals);
    return goals;
  }
};

class ExploreLitePolicy : public GoalPolicy {
 public:
  explicit ExploreLitePolicy(const ExploreLiteOptions& o) : options_(o) {}
  std::string_view name() const override { return "explore-lite"; }
  std::vector<GoalCandidate> Rank(const PolicyInput& in) const override {
    std::vector<GoalCandidate> goals;
    for (const FrontierSegment& s : FrontierSegments(in.map->limits(), *in.frontier, in.robot)) {
      if (s.size_m < options_.min_frontier_size_m) continue;
      const double cost =
          options_.potential_scale * s.min_distance_m - options_.gain_scale * s.size_m;
      goals.push_back({s.centroid, -cost});
    }
    SortBestFirst(goals);
    return goals;
  }

 private:
  ExploreLiteOptions options_;
};

class MeanShiftCentresPolicy : public GoalPolicy {
 public:
  explicit MeanShiftCentresPolicy(const NavigationPointOptions& o) : options_(o) {}
  std::string_view name() const override { return "meanshift-centres"; }
  std::vector<GoalCandidate> Rank(const PolicyInput& in) const override {
    std::vector<GoalCandidate> goals;
    for (const Eigen::Vector2d& c : MeanShift(*in.frontier, options_.mean_shift).centres) {
      double gain = InfoGain(*in.map, c, options_);
      if (in.current_goal && (c - *in.current_goal).norm() <= options_.hysteresis_radius_m) {
        gain *= options_.hysteresis_gain;
      }
      goals.push_back({c, options_.info_multiplier * gain - (c - in.robot).norm()});
    }
    SortBestFirst(goals);
    return goals;
  }

 private:
  NavigationPointOptions options_;
};

}  // namespace

std::vector<FrontierSegment> FrontierSegments(const grid::MapLimits& limits,
                                              const std::vector<Eigen::Vector2d>& frontier,
                                              const Eigen::Vector2d& robot) {
  std::vector<int64_t> cells;
  for (const Eigen::Vector2d& p : frontier) {
    const grid::CellIndex c = limits.CellContaining(p);
    if (limits.Contains(c)) cells.push_back(limits.FlatIndex(c));
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  const auto index_of = [&](int64_t flat) {
    const auto it = std::lower_bound(cells.begin(), cells.end(), flat);
    return it != cells.end() && *it == flat ? static_cast<int>(it - cells.begin()) : -1;
  };
  std::vector<uint8_t> visited(cells.size(), 0);
  std::vector<FrontierSegment> segments;
  std::vector<int> stack;
  for (size_t i = 0; i < cells.size(); ++i) {
    if (visited[i]) continue;
    FrontierSegment seg;
    seg.min_distance_m = std::numeric_limits<double>::infinity();
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    visited[i] = 1;
    stack.push_back(static_cast<int>(i));
    while (!stack.empty()) {
      const grid::CellIndex c = limits.CellOfFlatIndex(cells[stack.back()]);
      stack.pop_back();
      const Eigen::Vector2d centre = limits.CellCenter(c);
      sum += centre, ++seg.cells;
      seg.min_distance_m = std::min(seg.min_distance_m, (centre - robot).norm());
      for (const auto& d : kNeighbourOffsets) {
        const grid::CellIndex n{c.x + d[0], c.y + d[1]};
        if (!limits.Contains(n)) continue;
        const int j = index_of(limits.FlatIndex(n));
        if (j >= 0 && !visited[j]) visited[j] = 1, stack.push_back(j);
      }
    }
    seg.centroid = sum / seg.cells;
    seg.size_m = seg.cells * limits.resolution();
    segments.push_back(seg);
  }
  return segments;
}

std::unique_ptr<GoalPolicy> MakeGoalPolicy(std::string_view name,
                                           const GoalPolicyOptions& options) {
  Validate(options);
  if (name == "scout") return std::make_unique<ScoutPolicy>(options.navigation);
  if (name == "nearest") return std::make_unique<NearestPolicy>();
  if (name == "explore-lite") return std::make_unique<ExploreLitePolicy>(options.explore_lite);
  if (name == "meanshift-centres") {
    return std::make_unique<MeanShiftCentresPolicy>(options.navigation);
  }
  std::string known;
  for (const std::string& n : GoalPolicyNames()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("goal policy '" + std::string(name) + "': expected one of " + known);
}

}  // namespace scout::explore
