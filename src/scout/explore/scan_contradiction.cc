#include "scout/explore/scan_contradiction.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_set>

#include "scout/geometry/segment.h"

namespace scout::explore {

bool PathCrossesReturns(const std::vector<Eigen::Vector2d>& path,
                        const std::vector<Eigen::Vector2d>& returns, double radius_m) {
  if (path.empty() || returns.empty()) return false;
  // The returns' box, grown by the radius, skips the segments far from all
  // of them (a long path leaves the lidar's range after a few metres).
  Eigen::Vector2d lo = returns.front(), hi = returns.front();
  for (const Eigen::Vector2d& q : returns) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  lo.array() -= radius_m;
  hi.array() += radius_m;
  const double r2 = radius_m * radius_m;
  const auto near_segment = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    if ((a.cwiseMax(b).array() < lo.array()).any() || (a.cwiseMin(b).array() > hi.array()).any()) {
      return false;
    }
    return std::any_of(returns.begin(), returns.end(), [&](const Eigen::Vector2d& q) {
      return geometry::SquaredDistanceToSegment(q, a, b) <= r2;
    });
  };
  if (path.size() == 1) return near_segment(path[0], path[0]);
  for (size_t i = 1; i < path.size(); ++i) {
    if (near_segment(path[i - 1], path[i])) return true;
  }
  return false;
}

std::vector<Eigen::Vector2d> ThinToCells(const std::vector<Eigen::Vector2d>& points,
                                         double cell_m) {
  if (!(cell_m > 0.0)) return points;
  std::unordered_set<uint64_t> seen;
  seen.reserve(points.size());
  std::vector<Eigen::Vector2d> kept;
  for (const Eigen::Vector2d& p : points) {
    // Cells of a few centimetres within kilometres fit 32 bits per axis.
    const auto x = static_cast<uint32_t>(static_cast<int32_t>(std::floor(p.x() / cell_m)));
    const auto y = static_cast<uint32_t>(static_cast<int32_t>(std::floor(p.y() / cell_m)));
    if (seen.insert((static_cast<uint64_t>(x) << 32) | y).second) kept.push_back(p);
  }
  return kept;
}

}  // namespace scout::explore
