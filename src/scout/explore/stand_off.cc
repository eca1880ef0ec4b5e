#include "scout/explore/stand_off.h"

#include <cmath>
#include <optional>

#include "scout/explore/path_planner.h"

namespace scout::explore {

bool DiscInKnownFree(const PlanningMap& map, const Eigen::Vector2d& p) {
  return DiscInKnownFree(map, p, map.options().robot_radius_m);
}

bool DiscInKnownFree(const PlanningMap& map, const Eigen::Vector2d& p, double radius_m) {
  const grid::MapLimits& limits = map.limits();
  const double r = radius_m;
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

namespace {

// The path cut at its last point, at most max_back_off_m of path before the
// goal and leaving at least min_length_m of it, where 'qualifies' holds;
// nothing when no such point exists.
template <typename Qualifies>
std::optional<std::vector<Eigen::Vector2d>> CutAtLast(const PlanningMap& map,
                                                      const std::vector<Eigen::Vector2d>& path,
                                                      double max_back_off_m, double min_length_m,
                                                      Qualifies&& qualifies) {
  const double length_m = PolylineLength(path);  // min_length_m of it is kept
  const double step = 0.5 * map.limits().resolution();
  double back = 0.0;  // path walked back from the goal
  for (size_t i = path.size() - 1; i > 0; --i) {
    const Eigen::Vector2d a = path[i - 1], b = path[i];
    const double len = (b - a).norm();
    // Points on segment a-b at path distance 'back' .. 'back + len' from the goal.
    for (double s = step; s <= len + 1e-9; s += step) {
      const double from_goal = back + s;
      if (from_goal > max_back_off_m || length_m - from_goal < min_length_m) return std::nullopt;
      const Eigen::Vector2d p = b + (a - b) * (s / len);
      if (!qualifies(p)) continue;
      std::vector<Eigen::Vector2d> cut(path.begin(), path.begin() + i);
      if ((cut.back() - p).squaredNorm() > 1e-18) cut.push_back(p);
      return cut;
    }
    back += len;
  }
  return std::nullopt;
}

}  // namespace

bool KeepsFullMargin(const PlanningMap& map, const Eigen::Vector2d& p) {
  const grid::CellIndex cell = map.limits().CellContaining(p);
  return map.Traversable(cell) && !map.narrow(map.limits().FlatIndex(cell));
}

std::vector<Eigen::Vector2d> CutAtStandOff(const PlanningMap& map,
                                           const std::vector<Eigen::Vector2d>& path,
                                           double max_back_off_m, double min_length_m,
                                           double unknown_margin_m) {
  if (path.size() < 2 || max_back_off_m <= 0.0) return path;
  // Tiers, strictest first: the path itself when its end qualifies, else
  // the path cut at the last qualifying point within the back-off.
  const auto tier = [&](const auto& qualifies) -> std::optional<std::vector<Eigen::Vector2d>> {
    if (qualifies(path.back())) return path;
    return CutAtLast(map, path, max_back_off_m, min_length_m, qualifies);
  };
  const auto full_margin_with_disc = [&map](double radius_m) {
    return [&map, radius_m](const Eigen::Vector2d& p) {
      return KeepsFullMargin(map, p) && DiscInKnownFree(map, p, radius_m);
    };
  };
  const double robot_radius_m = map.options().robot_radius_m;
  if (unknown_margin_m > 0.0) {
    if (auto cut = tier(full_margin_with_disc(robot_radius_m + unknown_margin_m))) return *cut;
  }
  if (auto cut = tier(full_margin_with_disc(robot_radius_m))) return *cut;
  const auto known = [&map](const Eigen::Vector2d& p) { return DiscInKnownFree(map, p); };
  if (auto cut = tier(known)) return *cut;
  return path;
}

}  // namespace scout::explore
