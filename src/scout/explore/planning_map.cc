#include "scout/explore/planning_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "scout/explore/option_check.h"
#include "scout/grid/distance_transform.h"
#include "scout/grid/inflation.h"

namespace scout::explore {

void Validate(const TraversabilityOptions& o) {
  CheckAtLeast("traversability", "robot_radius_m", o.robot_radius_m, 0.0);
  CheckAtLeast("traversability", "safety_margin_m", o.safety_margin_m, 0.0);
  CheckAtLeast("traversability", "goal_snap_radius_m", o.goal_snap_radius_m, 0.0);
  CheckAtLeast("traversability", "narrow_margin_m", o.narrow_margin_m, 0.0);
  CheckAtLeast("traversability", "driven_width_m", o.driven_width_m, 0.0);
  CheckAtLeast("traversability", "driven_max_gap_m", o.driven_max_gap_m, 0.0);
  CheckAtLeast("traversability", "narrow_cost_factor", o.narrow_cost_factor, 1.0);
  CheckAtLeast("traversability", "escape_radius_m", o.escape_radius_m, 0.0);
}

PlanningMap::PlanningMap(const grid::OccupancyMap& map, const TraversabilityOptions& options,
                         bool with_clearance)
    : PlanningMap(map, options, with_clearance, nullptr) {}

namespace {

bool SameLattice(const grid::MapLimits& a, const grid::MapLimits& b) {
  return a.resolution() == b.resolution() && a.origin() == b.origin() && a.width() == b.width() &&
         a.height() == b.height();
}

}  // namespace

PlanningMap::PlanningMap(const grid::OccupancyMap& map, const TraversabilityOptions& options,
                         bool with_clearance, const PlanningMap* previous)
    : limits_(map.limits), options_(options), states_(map.cells) {
  Validate(options_);
  if (states_.size() != static_cast<size_t>(limits_.num_cells())) {
    throw std::invalid_argument("PlanningMap: " + std::to_string(states_.size()) +
                                " cells for a grid of " + std::to_string(limits_.num_cells()));
  }
  const int w = limits_.width(), h = limits_.height();
  if (previous != nullptr && previous->options_ == options_ &&
      SameLattice(previous->limits_, limits_)) {
    // The bounding box of the cells whose state changed.
    int x0 = w, x1 = -1, y0 = h, y1 = -1;
    for (int y = 0; y < h; ++y) {
      const auto row = states_.begin() + int64_t{y} * w;
      const auto old_row = previous->states_.begin() + int64_t{y} * w;
      const auto first = std::mismatch(row, row + w, old_row).first;
      if (first == row + w) continue;
      int last = w - 1;
      while (row[last] == old_row[last]) --last;
      x0 = std::min(x0, static_cast<int>(first - row));
      x1 = std::max(x1, last);
      y0 = std::min(y0, y);
      y1 = y;
    }
    blocked_ = previous->blocked_;
    base_codes_ = previous->base_codes_;
    if (x1 >= 0) {
      // A changed cell changes the levels within the largest radius of it.
      const int reach = ReachCells();
      Reinflate(std::max(x0 - reach, 0), std::min(x1 + reach + 1, w), std::max(y0 - reach, 0),
                std::min(y1 + reach + 1, h));
    }
  } else {
    // The same inflation as the frontier detector's, so a frontier point that
    // WFD reached is not blocked here by a different rounding.
    blocked_ = grid::InflationLevels(states_, limits_, InflationRadii());
    base_codes_.resize(states_.size());
    Code(0, w, 0, h);
  }
  has_narrow_ = std::ranges::find(base_codes_, kNarrow) != base_codes_.end();
  traversable_ = base_codes_;
  if (with_clearance) {
    std::vector<uint8_t> occupied(states_.size());
    for (size_t i = 0; i < states_.size(); ++i) {
      occupied[i] = states_[i] == grid::CellState::kOccupied;
    }
    clearance_m_ = grid::SquaredDistanceToNearestSite(occupied, limits_.width(), limits_.height());
    const float res = static_cast<float>(limits_.resolution());
    for (float& c : clearance_m_) c = std::sqrt(c) * res;
  }
}

std::vector<double> PlanningMap::InflationRadii() const {
  // Level 1: within the inflation radius (blocked); level 2: also within the
  // narrow passages' clearance (no passage either).
  std::vector<double> radii = {options_.inflation_radius_m()};
  if (options_.narrow_margin_m < options_.safety_margin_m) {
    radii.push_back(options_.robot_radius_m + options_.narrow_margin_m);
  }
  return radii;
}

int PlanningMap::ReachCells() const {
  // The first radius is the largest (narrow_margin_m < safety_margin_m).
  return static_cast<int>(std::ceil(options_.inflation_radius_m() / limits_.resolution())) + 1;
}

void PlanningMap::Code(int x0, int x1, int y0, int y1) {
  const bool narrow = InflationRadii().size() > 1;  // the narrow-passage tier is on
  for (int y = y0; y < y1; ++y) {
    for (int64_t i = int64_t{y} * limits_.width() + x0, end = i + (x1 - x0); i < end; ++i) {
      const bool passable =
          states_[i] == grid::CellState::kFree ||
          (options_.unknown_traversable && states_[i] == grid::CellState::kUnknown);
      base_codes_[i] = !passable                    ? 0
                       : blocked_[i] == 0           ? 1
                       : narrow && blocked_[i] == 1 ? kNarrow
                                                    : 0;
    }
  }
}

void PlanningMap::Reinflate(int x0, int x1, int y0, int y1) {
  // The levels of the cells in the window depend on the occupied cells
  // within the largest radius of them: inflate a window that much larger.
  const std::vector<double> radii = InflationRadii();
  const double res = limits_.resolution();
  const int reach = ReachCells();
  const int w = limits_.width(), h = limits_.height();
  const int ox0 = std::max(x0 - reach, 0), ox1 = std::min(x1 + reach, w);
  const int oy0 = std::max(y0 - reach, 0), oy1 = std::min(y1 + reach, h);
  const int ow = ox1 - ox0, oh = oy1 - oy0;
  std::vector<grid::CellState> window(static_cast<size_t>(ow) * oh);
  for (int y = oy0; y < oy1; ++y) {
    std::copy_n(states_.begin() + int64_t{y} * w + ox0, ow, window.begin() + int64_t{y - oy0} * ow);
  }
  const grid::MapLimits window_limits(
      res, limits_.CellCenter({ox0, oy0}) - 0.5 * Eigen::Vector2d(res, res), ow, oh);
  const std::vector<uint8_t> levels = grid::InflationLevels(window, window_limits, radii);
  for (int y = y0; y < y1; ++y) {
    std::copy_n(levels.begin() + int64_t{y - oy0} * ow + (x0 - ox0), x1 - x0,
                blocked_.begin() + int64_t{y} * w + x0);
  }
  Code(x0, x1, y0, y1);
}

void PlanningMap::AllowDriven(const std::vector<Eigen::Vector2d>& trajectory) {
  const double width = options_.driven_width_m;
  if (width <= 0.0) return;
  // Runs over the whole trajectory at every map update: visit the cells in
  // place rather than collecting them.
  const auto allow = [&](const Eigen::Vector2d& p) {
    ForEachCellWithin(limits_, p, width, [&](const grid::CellIndex& c) {
      const int64_t i = limits_.FlatIndex(c);
      if (states_[i] == grid::CellState::kFree && traversable_[i] == 0) {
        traversable_[i] = kNarrow;
        has_narrow_ = true;
        if (!closed_.empty()) closed_[i] = 0;
      }
    });
  };
  const double step = 0.5 * limits_.resolution();
  for (size_t i = 0; i < trajectory.size(); ++i) {
    allow(trajectory[i]);
    if (i == 0) continue;
    const Eigen::Vector2d a = trajectory[i - 1], b = trajectory[i];
    const double len = (b - a).norm();
    if (len > options_.driven_max_gap_m) continue;
    for (double s = step; s < len; s += step) allow(a + (b - a) * (s / len));
  }
}

void PlanningMap::CloseNarrow(const Eigen::Vector2d& p, double radius_m) {
  if (closed_.empty()) closed_.assign(traversable_.size(), 0);
  ForEachCellWithin(limits_, p, radius_m, [&](const grid::CellIndex& c) {
    const int64_t i = limits_.FlatIndex(c);
    if (traversable_[i] == 1) return;
    traversable_[i] = 0;
    closed_[i] = 1;
  });
}

bool PlanningMap::StepAllowed(const grid::CellIndex& from, int k) const {
  const auto& d = kNeighbourOffsets[k];
  if (!Traversable({from.x + d[0], from.y + d[1]})) return false;
  if (k < 4) return true;
  return Traversable({from.x + d[0], from.y}) && Traversable({from.x, from.y + d[1]});
}

std::vector<grid::CellIndex> CellsWithin(const grid::MapLimits& limits, const Eigen::Vector2d& p,
                                         double radius_m) {
  std::vector<grid::CellIndex> cells;
  ForEachCellWithin(limits, p, radius_m, [&](const grid::CellIndex& c) { cells.push_back(c); });
  return cells;
}

std::optional<grid::CellIndex> PlanningMap::NearestTraversable(const Eigen::Vector2d& p,
                                                               double radius_m) const {
  std::optional<grid::CellIndex> best;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (const grid::CellIndex& c : CellsWithin(limits_, p, radius_m)) {
    if (!traversable(limits_.FlatIndex(c))) continue;
    const double d2 = (limits_.CellCenter(c) - p).squaredNorm();
    if (d2 < best_d2) best_d2 = d2, best = c;  // row-major scan: first is lowest index
  }
  return best;
}

bool PlanningMap::SegmentTraversable(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  bool ok = true;
  ForEachCellOnSegment(a, b, [&](const grid::CellIndex& c) { return ok = Traversable(c); });
  return ok;
}

float PlanningMap::SegmentClearance(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  float lowest = std::numeric_limits<float>::infinity();
  ForEachCellOnSegment(a, b, [&](const grid::CellIndex& c) {
    if (limits_.Contains(c)) lowest = std::min(lowest, clearance_m_[limits_.FlatIndex(c)]);
    return true;
  });
  return lowest;
}

}  // namespace scout::explore
