#include "scout/frontier/selective_strategies.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>

#include "scout/frontier/stopwatch.h"

namespace scout::frontier {

PoseDeviation Deviation(const geometry::Rigid2d& current, const geometry::Rigid2d& previous) {
  return {current.x() - previous.x(), current.y() - previous.y(),
          geometry::NormalizeAngle(current.theta() - previous.theta())};
}

bool DeviationExceedsThreshold(const PoseDeviation& d, double epsilon_m, double lidar_range_m) {
  return std::abs(d.dx_m) > epsilon_m || std::abs(d.dy_m) > epsilon_m ||
         std::abs(d.dtheta_rad) > epsilon_m / (2.0 * std::numbers::pi * lidar_range_m);
}

std::vector<int> WithIntersectingSubmaps(const SubmapCatalog& catalog,
                                         const std::vector<int>& seeds) {
  std::vector<uint8_t> selected(catalog.size(), 0);
  for (const int s : seeds) {
    selected[s] = 1;
    for (const int n : catalog.index().Intersecting(catalog.submap(s).global_box)) selected[n] = 1;
  }
  std::vector<int> ids;
  for (int i = 0; i < catalog.size(); ++i) {
    if (selected[i]) ids.push_back(i);
  }
  return ids;
}

UpdateCost BfsStrategy::OnOptimized(const std::vector<geometry::Rigid2d>& previous_poses) {
  UpdateCost cost;
  const Stopwatch stopwatch;
  const int n = catalog_.size();
  if (n > 0) {
    const FrontierOptions& o = catalog_.options();
    const int latest = n - 1;
    std::vector<uint8_t> visited(n, 0);
    visited[latest] = 1;
    std::deque<int> queue = {latest};
    std::vector<int> seeds = {latest};
    while (!queue.empty()) {
      const int current = queue.front();
      queue.pop_front();
      for (const int s : catalog_.index().Intersecting(catalog_.submap(current).global_box)) {
        if (visited[s]) continue;
        const PoseDeviation d = Deviation(catalog_.submap(s).global_pose, previous_poses[s]);
        if (!DeviationExceedsThreshold(d, o.epsilon_m, o.lidar_range_m)) continue;
        visited[s] = 1;
        queue.push_back(s);
        seeds.push_back(s);
      }
    }
    QuerySubmaps(WithIntersectingSubmaps(catalog_, seeds), /*use_hints=*/true, &cost);
  }
  cost.time_us = stopwatch.ElapsedUs();
  return cost;
}

UpdateCost DirectStrategy::OnOptimized(const std::vector<geometry::Rigid2d>& previous_poses) {
  UpdateCost cost;
  const Stopwatch stopwatch;
  const FrontierOptions& o = catalog_.options();
  accumulated_.resize(catalog_.size());
  std::vector<int> seeds;
  for (int i = 0; i < catalog_.size(); ++i) {
    const PoseDeviation d = Deviation(catalog_.submap(i).global_pose, previous_poses[i]);
    PoseDeviation& cd = accumulated_[i];
    cd.dx_m += d.dx_m;
    cd.dy_m += d.dy_m;
    cd.dtheta_rad += d.dtheta_rad;
    if (DeviationExceedsThreshold(cd, o.epsilon_m, o.lidar_range_m)) seeds.push_back(i);
  }
  const std::vector<int> queried = WithIntersectingSubmaps(catalog_, seeds);
  QuerySubmaps(queried, /*use_hints=*/true, &cost);
  for (const int i : queried) accumulated_[i] = PoseDeviation{};
  cost.time_us = stopwatch.ElapsedUs();
  return cost;
}

}  // namespace scout::frontier
