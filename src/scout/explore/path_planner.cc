#include "scout/explore/path_planner.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "scout/explore/option_check.h"

namespace scout::explore {

void Validate(const PathPlannerOptions& o) {
  CheckAtLeast("path_planner", "clearance_weight", o.clearance_weight, 0.0);
  CheckAtLeast("path_planner", "clearance_band_m", o.clearance_band_m, 0.0, /*strict=*/true);
}

PathPlanner::PathPlanner(const PathPlannerOptions& options) : options_(options) {
  Validate(options_);
}

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr uint8_t kNoParent = 255;

// A* state kept from one plan to the next (per thread): most searches expand a
// small part of the map, yet three map-sized arrays were allocated (page
// faults) and cleared for each, which the museum's profile showed. A cell's
// g and parent belong to this plan only when its stamp is this plan's
// (opened) or one more (closed); older stamps read as never seen.
struct SearchScratch {
  std::vector<uint32_t> stamp;
  std::vector<float> g;
  std::vector<uint8_t> parent;
  uint32_t opened = 0;  // this plan's mark; closed is opened + 1

  // Starts a plan over 'num_cells' cells.
  void Begin(int64_t num_cells) {
    const size_t n = static_cast<size_t>(num_cells);
    if (stamp.size() < n) {
      stamp.resize(n, 0);
      g.resize(n);
      parent.resize(n);
    }
    if (opened >= std::numeric_limits<uint32_t>::max() - 2) {
      std::fill(stamp.begin(), stamp.end(), 0);
      opened = 0;
    }
    opened += 2;
  }
  uint32_t closed() const { return opened + 1; }
  float G(int64_t flat) const { return stamp[flat] >= opened ? g[flat] : kInf; }
  bool IsClosed(int64_t flat) const { return stamp[flat] == closed(); }
  void Open(int64_t flat, float cost, uint8_t from) {
    stamp[flat] = opened, g[flat] = cost, parent[flat] = from;
  }
  void Close(int64_t flat) { stamp[flat] = closed(); }
};

double Octile(int dx, int dy) {
  dx = std::abs(dx), dy = std::abs(dy);
  return std::max(dx, dy) + (M_SQRT2 - 1.0) * std::min(dx, dy);
}

}  // namespace

double PolylineLength(const std::vector<Eigen::Vector2d>& points) {
  double length = 0.0;
  for (size_t i = 1; i < points.size(); ++i) length += (points[i] - points[i - 1]).norm();
  return length;
}

std::optional<PlannedPath> PathPlanner::Plan(const PlanningMap& map, const Eigen::Vector2d& start,
                                             const Eigen::Vector2d& goal) const {
  return Plan(map, StartRegion(map, start), goal);
}

std::optional<PlannedPath> PathPlanner::Plan(const PlanningMap& map, const StartRegion& start,
                                             const Eigen::Vector2d& goal) const {
  return Search(map, start, goal, nullptr);
}

std::optional<PlannedPath> PathPlanner::Plan(const PlanningMap& map, const StartRegion& start,
                                             const Eigen::Vector2d& goal,
                                             ReachableCells& reachable) const {
  if (!reachable.known()) return Search(map, start, goal, &reachable);
  if (reachable.map_ != &map || reachable.start_ != &start) {
    throw std::invalid_argument("PathPlanner: reachable cells learnt on another map or start");
  }
  // A* reaches the goal cell or a cell within the snap radius of the goal,
  // when one of them is reachable at all.
  const grid::MapLimits& limits = map.limits();
  const grid::CellIndex goal_cell = limits.CellContaining(goal);
  bool any = limits.Contains(goal_cell) && reachable.cells_[limits.FlatIndex(goal_cell)];
  if (!any) {
    ForEachCellWithin(
        limits, goal, map.options().goal_snap_radius_m,
        [&](const grid::CellIndex& c) { any = any || reachable.cells_[limits.FlatIndex(c)]; });
  }
  if (!any) return std::nullopt;
  return Search(map, start, goal, nullptr);
}

std::optional<PlannedPath> PathPlanner::Search(const PlanningMap& map, const StartRegion& start,
                                               const Eigen::Vector2d& goal,
                                               ReachableCells* reachable) const {
  const bool penalise = options_.clearance_weight > 0.0;
  if (penalise && !map.has_clearance()) {
    throw std::invalid_argument("PathPlanner: clearance_weight > 0 needs a map with clearance");
  }
  const grid::MapLimits& limits = map.limits();
  if (start.empty()) return std::nullopt;
  const double res = limits.resolution();
  const double snap = map.options().goal_snap_radius_m;
  const grid::CellIndex goal_cell = limits.CellContaining(goal);
  const auto is_goal = [&](const grid::CellIndex& c) {
    return c == goal_cell || (limits.CellCenter(c) - goal).squaredNorm() <= snap * snap;
  };
  // Admissible: the octile/Euclidean ratio is at most 1.0824, and any goal
  // cell lies within 'snap' of the goal.
  const double slack_cells = 1.0824 * snap / res + 1.0;
  const auto heuristic = [&](const grid::CellIndex& c) {
    const double h = Octile(c.x - goal_cell.x, c.y - goal_cell.y);
    return static_cast<float>(snap > 0.0 ? std::max(0.0, h - slack_cells) : h);
  };

  thread_local SearchScratch scratch;
  scratch.Begin(limits.num_cells());
  const std::vector<float>& g = scratch.g;
  const std::vector<uint8_t>& parent = scratch.parent;
  struct Entry {
    float f, h;
    int64_t flat;
  };
  std::vector<Entry> open;
  // Among equal f, expand the cell nearest the goal first: on open floors
  // octile ties are everywhere, and this cuts the expansions severalfold.
  const auto later = [](const Entry& a, const Entry& b) {
    return a.f != b.f ? a.f > b.f : a.h > b.h;
  };
  // Every seed starts with its escape distance (and no parent), so A* picks
  // the best way out; a seed may still be improved through another one.
  for (const StartSeed& seed : start.seeds()) {
    const int64_t s = limits.FlatIndex(seed.cell);
    const float gs = static_cast<float>(seed.distance_m / limits.resolution());
    if (gs >= scratch.G(s)) continue;
    scratch.Open(s, gs, kNoParent);
    const float hs = heuristic(seed.cell);
    open.push_back({gs + hs, hs, s});
    std::push_heap(open.begin(), open.end(), later);
  }
  const float kStep[8] = {
      1, 1, 1, 1, float(M_SQRT2), float(M_SQRT2), float(M_SQRT2), float(M_SQRT2)};
  PlannedPath path;
  int64_t reached = -1;
  while (!open.empty()) {
    std::pop_heap(open.begin(), open.end(), later);
    const int64_t u = open.back().flat;
    open.pop_back();
    if (scratch.IsClosed(u)) continue;
    scratch.Close(u);
    ++path.expansions;
    const grid::CellIndex cu = limits.CellOfFlatIndex(u);
    if (is_goal(cu)) {
      reached = u;
      break;
    }
    for (int k = 0; k < 8; ++k) {
      if (!map.StepAllowed(cu, k)) continue;
      const grid::CellIndex cv{cu.x + kNeighbourOffsets[k][0], cu.y + kNeighbourOffsets[k][1]};
      const int64_t v = limits.FlatIndex(cv);
      if (scratch.IsClosed(v)) continue;
      const float gv = g[u] + kStep[k] * StepFactor(map, v);
      if (gv < scratch.G(v)) {
        scratch.Open(v, gv, static_cast<uint8_t>(k));
        const float hv = heuristic(cv);
        open.push_back({gv + hv, hv, v});
        std::push_heap(open.begin(), open.end(), later);
      }
    }
  }
  if (reached < 0) {
    // The search closed every cell it could reach.
    if (reachable != nullptr) {
      reachable->map_ = &map;
      reachable->start_ = &start;
      reachable->cells_.assign(static_cast<size_t>(limits.num_cells()), false);
      for (int64_t flat = 0; flat < limits.num_cells(); ++flat) {
        if (scratch.IsClosed(flat)) reachable->cells_[static_cast<size_t>(flat)] = true;
      }
    }
    return std::nullopt;
  }

  // Walk back through the parents; the raw path is start, cells..., end.
  std::vector<Eigen::Vector2d> raw;
  std::vector<double> cost;
  grid::CellIndex seed_cell;
  for (int64_t c = reached;;) {
    const grid::CellIndex ci = limits.CellOfFlatIndex(c);
    raw.push_back(limits.CellCenter(ci));
    cost.push_back(g[c] * res);
    if (parent[c] == kNoParent) {
      seed_cell = ci;
      break;
    }
    const auto& d = kNeighbourOffsets[parent[c]];
    path.cell_path_length_m += (parent[c] < 4 ? 1.0 : M_SQRT2) * res;
    c = limits.FlatIndex({ci.x - d[0], ci.y - d[1]});
  }
  std::reverse(raw.begin(), raw.end());
  std::reverse(cost.begin(), cost.end());
  // End exactly at the goal when it lies in the reached cell.
  if (limits.CellOfFlatIndex(reached) == goal_cell) raw.back() = goal;
  // Begin at the robot; from inside the inflated band it first follows its
  // escape path to the seed cell, which shortcutting must not skip.
  size_t first_free = 0;
  if (!start.escaped()) {
    raw.front() = start.robot();
  } else {
    std::vector<Eigen::Vector2d> escape = start.PathTo(seed_cell);
    escape.pop_back();  // the seed's centre is raw.front()
    raw.insert(raw.begin(), escape.begin(), escape.end());
    cost.insert(cost.begin(), escape.size(), 0.0);
    first_free = escape.size();
  }
  path.points = options_.shortcut ? Shortcut(map, raw, cost, first_free) : raw;
  path.length_m = PolylineLength(path.points);
  return path;
}

float PathPlanner::StepFactor(const PlanningMap& map, int64_t flat) const {
  const float tier = map.StepFactor(flat);
  if (options_.clearance_weight <= 0.0) return tier;
  const double beyond = map.clearance_m(flat) - map.options().inflation_radius_m();
  const double closeness = std::max(0.0, 1.0 - beyond / options_.clearance_band_m);
  return tier * static_cast<float>(1.0 + options_.clearance_weight * closeness);
}

double PathPlanner::SegmentCost(const PlanningMap& map, const Eigen::Vector2d& a,
                                const Eigen::Vector2d& b) const {
  double sum = 0.0;
  int n = 0;
  map.ForEachCellOnSegment(a, b, [&](const grid::CellIndex& c) {
    if (map.limits().Contains(c)) sum += StepFactor(map, map.limits().FlatIndex(c)), ++n;
    return true;
  });
  return (b - a).norm() * (n > 0 ? sum / n : 1.0);
}

std::vector<Eigen::Vector2d> PathPlanner::Shortcut(const PlanningMap& map,
                                                   const std::vector<Eigen::Vector2d>& raw,
                                                   const std::vector<double>& cost,
                                                   size_t first_free) const {
  std::vector<Eigen::Vector2d> out(raw.begin(), raw.begin() + first_free + 1);
  // Narrow passages cost more than their length: a shortcut through them must
  // not pass for cheaper than the cells it replaces.
  const bool penalise = options_.clearance_weight > 0.0 || map.MaxStepFactor() > 1.0f;
  size_t anchor = first_free;
  while (anchor + 1 < raw.size()) {
    // Extend the segment from the anchor while it stays valid (greedy: the
    // first invalid extension ends it, which keeps the work linear per corner).
    // Without a penalty a straight segment never costs more than the cells it
    // replaces, so only line of sight is checked.
    size_t j = anchor + 1;
    while (j + 1 < raw.size()) {
      if (!map.SegmentTraversable(raw[anchor], raw[j + 1])) break;
      if (penalise &&
          SegmentCost(map, raw[anchor], raw[j + 1]) > cost[j + 1] - cost[anchor] + 1e-4) {
        break;
      }
      ++j;
    }
    out.push_back(raw[j]);
    anchor = j;
  }
  return out;
}

}  // namespace scout::explore
