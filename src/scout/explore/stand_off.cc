#include "scout/explore/stand_off.h"

#include <cmath>

#include "scout/explore/path_planner.h"

namespace scout::explore {

bool DiscInKnownFree(const PlanningMap& map, const Eigen::Vector2d& p) {
  const grid::MapLimits& limits = map.limits();
  const double r = map.options().robot_radius_m;
  const double half = 0.5 * limits.resolution();
  const grid::CellIndex lo = limits.CellContaining(p - Eigen::Vector2d(r, r));
  const grid::CellIndex hi = limits.CellContaining(p + Eigen::Vector2d(r, r));
  // The disc reaching past the map's edge touches unknown space.
  if (!limits.Contains(lo) || !limits.Contains(hi)) return false;
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      // Every cell the disc overlaps (nearest point of the cell closer than r).
      const Eigen::Vector2d d =
          ((limits.CellCenter({x, y}) - p).cwiseAbs().array() - half).max(0.0).matrix();
      if (d.squaredNorm() >= r * r) continue;
      if (map.state(limits.FlatIndex({x, y})) != grid::CellState::kFree) return false;
    }
  }
  return true;
}

std::vector<Eigen::Vector2d> CutAtStandOff(const PlanningMap& map,
                                           const std::vector<Eigen::Vector2d>& path,
                                           double max_back_off_m, double min_length_m) {
  if (path.size() < 2 || max_back_off_m <= 0.0 || DiscInKnownFree(map, path.back())) return path;
  const double length_m = PolylineLength(path);  // min_length_m of it is kept
  const double step = 0.5 * map.limits().resolution();
  double back = 0.0;  // path walked back from the goal
  for (size_t i = path.size() - 1; i > 0; --i) {
    const Eigen::Vector2d a = path[i - 1], b = path[i];
    const double len = (b - a).norm();
    // Points on segment a-b at path distance 'back' .. 'back + len' from the goal.
    for (double s = step; s <= len + 1e-9; s += step) {
      const double from_goal = back + s;
      if (from_goal > max_back_off_m) return path;
      if (length_m - from_goal < min_length_m) return path;
      const Eigen::Vector2d p = b + (a - b) * (s / len);
      if (!DiscInKnownFree(map, p)) continue;
      std::vector<Eigen::Vector2d> cut(path.begin(), path.begin() + i);
      if ((cut.back() - p).squaredNorm() > 1e-18) cut.push_back(p);
      return cut;
    }
    back += len;
  }
  return path;
}

}  // namespace scout::explore
