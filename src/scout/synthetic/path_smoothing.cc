#include "scout/synthetic/path_smoothing.h"

#include <cmath>

namespace scout::synthetic {
namespace {

bool SegmentIsClear(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                    const std::function<bool(const Eigen::Vector2d&)>& is_clear,
                    double check_step_m) {
  const int steps = static_cast<int>(std::ceil((b - a).norm() / check_step_m));
  for (int i = 0; i <= steps; ++i) {
    if (!is_clear(a + (b - a) * (steps == 0 ? 0.0 : static_cast<double>(i) / steps))) {
      return false;
    }
  }
  return true;
}

}  // namespace

std::vector<Eigen::Vector2d> ShortcutPath(
    const std::vector<Eigen::Vector2d>& path,
    const std::function<bool(const Eigen::Vector2d&)>& is_clear, double max_shortcut_m,
    double check_step_m) {
  if (path.size() <= 2) return path;
  std::vector<Eigen::Vector2d> result = {path.front()};
  size_t anchor = 0;
  while (anchor + 1 < path.size()) {
    size_t reach = anchor + 1;
    while (reach + 1 < path.size() && (path[reach + 1] - path[anchor]).norm() <= max_shortcut_m &&
           SegmentIsClear(path[anchor], path[reach + 1], is_clear, check_step_m)) {
      ++reach;
    }
    result.push_back(path[reach]);
    anchor = reach;
  }
  return result;
}

std::vector<Eigen::Vector2d> RoundCorners(const std::vector<Eigen::Vector2d>& path,
                                          double spacing_m, int iterations) {
  if (path.size() <= 2) return path;
  std::vector<Eigen::Vector2d> points = {path.front()};
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const Eigen::Vector2d delta = path[i + 1] - path[i];
    const int pieces = std::max(1, static_cast<int>(std::ceil(delta.norm() / spacing_m)));
    for (int k = 1; k <= pieces; ++k) points.push_back(path[i] + delta * (double(k) / pieces));
  }
  for (int iteration = 0; iteration < iterations; ++iteration) {
    std::vector<Eigen::Vector2d> cut = {points.front()};
    for (size_t i = 0; i + 1 < points.size(); ++i) {
      cut.push_back(0.75 * points[i] + 0.25 * points[i + 1]);
      cut.push_back(0.25 * points[i] + 0.75 * points[i + 1]);
    }
    cut.push_back(points.back());
    points = std::move(cut);
  }
  return points;
}

}  // namespace scout::synthetic
