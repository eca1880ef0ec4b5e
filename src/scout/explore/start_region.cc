#include "scout/explore/start_region.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>
#include <utility>

namespace scout::explore {
namespace {

constexpr uint8_t kNoEscapeParent = 255;
constexpr float kUnreachedM = std::numeric_limits<float>::infinity();

}  // namespace

StartRegion::StartRegion(const PlanningMap& map, const Eigen::Vector2d& robot, bool escape)
    : robot_(robot), limits_(map.limits()), root_(limits_.CellContaining(robot)) {
  if (!escape && map.Traversable(root_)) {
    seeds_.push_back({root_, static_cast<float>((limits_.CellCenter(root_) - robot).norm())});
    return;
  }
  escaped_ = true;
  if (limits_.Contains(root_)) Escape(map);
}

void StartRegion::Escape(const PlanningMap& map) {
  const TraversabilityOptions& o = map.options();
  const double res = limits_.resolution();
  const int r = static_cast<int>(std::ceil(o.escape_radius_m / res));
  window_min_ = {std::max(root_.x - r, 0), std::max(root_.y - r, 0)};
  const grid::CellIndex window_max{std::min(root_.x + r, limits_.width() - 1),
                                   std::min(root_.y + r, limits_.height() - 1)};
  window_width_ = window_max.x - window_min_.x + 1;
  window_height_ = window_max.y - window_min_.y + 1;
  const auto in_window = [&](const grid::CellIndex& c) {
    return c.x >= window_min_.x && c.y >= window_min_.y && c.x <= window_max.x &&
           c.y <= window_max.y;
  };

  // Clearance of a window cell up to the escape clearance: the distance to
  // the nearest occupied cell centre, +inf when none lies within it.
  const double wanted = o.robot_radius_m + std::min(o.narrow_margin_m, o.safety_margin_m);
  const int rr = static_cast<int>(std::ceil(wanted / res));
  std::vector<std::pair<grid::CellIndex, float>> disc;
  for (int dy = -rr; dy <= rr; ++dy) {
    for (int dx = -rr; dx <= rr; ++dx) {
      const double d = std::hypot(dx, dy) * res;
      if (d <= wanted) disc.push_back({{dx, dy}, static_cast<float>(d)});
    }
  }
  const auto clearance = [&](const grid::CellIndex& c) {
    float best = kUnreachedM;
    for (const auto& [off, d] : disc) {
      const grid::CellIndex n{c.x + off.x, c.y + off.y};
      if (d < best && limits_.Contains(n) &&
          map.state(limits_.FlatIndex(n)) == grid::CellState::kOccupied) {
        best = d;
      }
    }
    return best;
  };
  // The disc moves only where it keeps the escape clearance, or where it fits
  // at least as well as where it is: from a cell touching a wall (estimate
  // error) it can still back away.
  const float need = clearance(root_);
  const double escape2 = o.escape_radius_m * o.escape_radius_m;
  const double footprint2 = o.robot_radius_m * o.robot_radius_m;
  std::vector<int8_t> ok(static_cast<size_t>(window_width_) * window_height_, -1);
  const auto passable = [&](const grid::CellIndex& c) {
    if (!in_window(c)) return false;
    int8_t& k = ok[WindowIndex(c)];
    if (k < 0) {
      const double d2 = (limits_.CellCenter(c) - robot_).squaredNorm();
      const grid::CellState s = map.state(limits_.FlatIndex(c));
      // The robot's own footprint is free in truth, whatever the map says.
      // A passage closed where the robot got stuck stays closed beyond it.
      const bool open = (s == grid::CellState::kFree &&
                         (!map.closed(limits_.FlatIndex(c)) || d2 <= footprint2)) ||
                        (s == grid::CellState::kUnknown && d2 <= footprint2);
      k = d2 <= escape2 && open && clearance(c) >= need;
    }
    return k == 1;
  };

  parent_.assign(ok.size(), kNoEscapeParent);
  std::vector<float> dist(ok.size(), kUnreachedM);
  using Entry = std::pair<float, int64_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  const int64_t root = WindowIndex(root_);
  dist[root] = static_cast<float>((limits_.CellCenter(root_) - robot_).norm());
  open.push({dist[root], root});
  std::vector<uint8_t> done(ok.size(), 0);
  while (!open.empty()) {
    const auto [du, u] = open.top();
    open.pop();
    if (done[u]) continue;
    done[u] = 1;
    const grid::CellIndex cu{window_min_.x + static_cast<int>(u % window_width_),
                             window_min_.y + static_cast<int>(u / window_width_)};
    if (map.traversable(limits_.FlatIndex(cu))) seeds_.push_back({cu, du});
    for (int k = 0; k < 8; ++k) {
      const auto& d = kNeighbourOffsets[k];
      const grid::CellIndex cv{cu.x + d[0], cu.y + d[1]};
      if (!passable(cv)) continue;
      // A diagonal step needs both cells it passes between, as in the planner.
      if (k >= 4 && !(passable({cu.x + d[0], cu.y}) && passable({cu.x, cu.y + d[1]}))) continue;
      const int64_t v = WindowIndex(cv);
      // Escape steps cost as much as narrow ones, so the robot leaves by the
      // shortest way out rather than running along a wall.
      const float dv = du + static_cast<float>((k < 4 ? 1.0 : M_SQRT2) * res) * map.MaxStepFactor();
      if (done[v] || dv >= dist[v]) continue;
      dist[v] = dv;
      parent_[v] = static_cast<uint8_t>(k);
      open.push({dv, v});
    }
  }
  std::sort(seeds_.begin(), seeds_.end(), [&](const StartSeed& a, const StartSeed& b) {
    return limits_.FlatIndex(a.cell) < limits_.FlatIndex(b.cell);
  });
}

std::vector<Eigen::Vector2d> StartRegion::PathTo(const grid::CellIndex& cell) const {
  std::vector<Eigen::Vector2d> path;
  if (!escaped_) {
    if (!(cell == root_)) throw std::invalid_argument("StartRegion::PathTo: not a seed");
    return {robot_, limits_.CellCenter(cell)};
  }
  const bool inside = cell.x >= window_min_.x && cell.y >= window_min_.y &&
                      cell.x < window_min_.x + window_width_ &&
                      cell.y < window_min_.y + window_height_;
  if (!inside) throw std::invalid_argument("StartRegion::PathTo: not a seed");
  grid::CellIndex c = cell;
  while (true) {
    path.push_back(limits_.CellCenter(c));
    if (c == root_) break;
    const uint8_t k = parent_[WindowIndex(c)];
    if (k == kNoEscapeParent) throw std::invalid_argument("StartRegion::PathTo: not a seed");
    c = {c.x - kNeighbourOffsets[k][0], c.y - kNeighbourOffsets[k][1]};
  }
  path.push_back(robot_);
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace scout::explore
