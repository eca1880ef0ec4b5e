#include "scout/exploration/ground_truth.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "scout/common/error.h"
#include "scout/explore/goal_manager.h"
#include "scout/explore/path_distance_field.h"
#include "scout/grid/distance_transform.h"
#include "scout/sim/disc_collision_checker.h"

namespace scout::exploration {
namespace {

std::string Format(const Eigen::Vector2d& p) {
  std::ostringstream s;
  s.precision(3);
  s << std::fixed << p.x() << "," << p.y();
  return s.str();
}

std::string Metres(double v) {
  std::ostringstream s;
  s.precision(2);
  s << std::fixed << v << " m";
  return s.str();
}

// The world inside a ring of occupied cells, on the same lattice: beyond the
// map the simulator's disc collides and its lidar sees a wall, so neither
// counts as free space the robot could reach. mit-building-31's free space runs
// to the image border: the ring took its reachable area from 885.9 to 852.0 m2,
// a strip the robot can neither enter nor see as free.
grid::OccupancyMap Walled(const grid::OccupancyMap& world) {
  const grid::MapLimits& in = world.limits;
  const double res = in.resolution();
  grid::OccupancyMap walled;
  walled.limits = grid::MapLimits(res, in.origin() - Eigen::Vector2d(res, res), in.width() + 2,
                                  in.height() + 2);
  walled.cells.assign(walled.limits.num_cells(), grid::CellState::kOccupied);
  for (int y = 0; y < in.height(); ++y) {
    for (int x = 0; x < in.width(); ++x) {
      walled.cells[walled.limits.FlatIndex({x + 1, y + 1})] = world.cells[in.FlatIndex({x, y})];
    }
  }
  return walled;
}

// 'world' with every cell whose centre lies outside 'boundary' occupied.
grid::OccupancyMap Outside(const grid::OccupancyMap& world,
                           const std::vector<Eigen::Vector2d>& boundary) {
  grid::OccupancyMap bounded = world;
  for (int64_t i = 0; i < world.limits.num_cells(); ++i) {
    if (!explore::InsidePolygon(boundary,
                                world.limits.CellCenter(world.limits.CellOfFlatIndex(i)))) {
      bounded.cells[i] = grid::CellState::kOccupied;
    }
  }
  return bounded;
}

}  // namespace

GroundTruth::GroundTruth(const grid::OccupancyMap& unwalled_world, const std::string& world_name,
                         const Eigen::Vector2d& start,
                         const explore::TraversabilityOptions& traversability,
                         double robot_radius_m, const std::vector<Eigen::Vector2d>& boundary)
    : GroundTruth(Walled(unwalled_world), world_name, start, traversability, robot_radius_m,
                  boundary, /*walled=*/true) {
  // Back on the world's own lattice (the ring holds no reachable cell), so
  // cell centres are computed exactly as the simulator's and coverage does
  // not move by rounding at cell edges.
  const grid::MapLimits& world = unwalled_world.limits;
  for (grid::CellIndex& c : reachable_) c = {c.x - 1, c.y - 1};
  for (const grid::CellIndex& c : reachable_) {
    if (!runs_.empty() && runs_.back().y == c.y && runs_.back().x + runs_.back().length == c.x) {
      ++runs_.back().length;
    } else {
      runs_.push_back({c.y, c.x, 1});
    }
  }
  reachable_cells_ = static_cast<int64_t>(reachable_.size());
  reachable_ = {};
  std::vector<int32_t> labels(static_cast<size_t>(world.num_cells()), 0);
  for (int y = 0; y < world.height(); ++y) {
    for (int x = 0; x < world.width(); ++x) {
      labels[world.FlatIndex({x, y})] = disc_component_[limits_.FlatIndex({x + 1, y + 1})];
    }
  }
  disc_component_ = std::move(labels);
  limits_ = world;
}

GroundTruth::GroundTruth(const grid::OccupancyMap& world, const std::string& world_name,
                         const Eigen::Vector2d& start,
                         const explore::TraversabilityOptions& traversability,
                         double robot_radius_m, const std::vector<Eigen::Vector2d>& boundary,
                         bool /*walled*/)
    : limits_(world.limits), cell_area_m2_(world.limits.resolution() * world.limits.resolution()) {
  explore::TraversabilityOptions bare_options = traversability;
  bare_options.robot_radius_m = robot_radius_m;
  bare_options.safety_margin_m = 0.0;
  bare_options.unknown_traversable = false;
  const explore::PlanningMap bare(world, bare_options);
  const grid::CellIndex start_cell = limits_.CellContaining(start);
  if (!limits_.Contains(start_cell)) {
    const Eigen::Vector2d low = limits_.origin();
    const Eigen::Vector2d high =
        low + limits_.resolution() * Eigen::Vector2d(limits_.width(), limits_.height());
    throw InputError("world '" + world_name + "': the start (" + Format(start) +
                     ") is outside the map, which spans " + Format(low) + " to " + Format(high) +
                     "; choose a free position with --start X,Y");
  }
  // The planning grid inflates only occupied cells: a start beside unknown
  // cells passes it, yet the simulator's robot collides with those too.
  if (!bare.Traversable(start_cell) ||
      sim::DiscCollisionChecker(world, robot_radius_m).Collides(start)) {
    throw InputError("world '" + world_name + "': the start (" + Format(start) +
                     ") is inside an obstacle, unknown space or too close to a wall for the "
                     "robot (radius " +
                     Metres(robot_radius_m) + "); choose a free position with --start X,Y");
  }
  LabelDiscComponents(bare);
  if (!boundary.empty() && !explore::InsidePolygon(boundary, start)) {
    throw InputError("explore.boundary: the start (" + Format(start) + ") of world '" + world_name +
                     "' lies outside the boundary polygon");
  }

  // The spec's reachable space (ALGORITHMS §2 inflation): narrow passages let
  // the explorer through a door its SLAM map narrowed, but they do not widen
  // what exploring completely means.
  explore::TraversabilityOptions strict = traversability;
  strict.narrow_margin_m = strict.safety_margin_m;
  // A boundary is a wall here: what counts is what the robot can reach and
  // cover without leaving it (frontier outside it is never a goal, so rooms
  // entered only from outside would stay unexplored).
  std::optional<grid::OccupancyMap> walled_in;
  if (!boundary.empty()) walled_in = Outside(world, boundary);
  const grid::OccupancyMap& bounded = walled_in ? *walled_in : world;
  const explore::PlanningMap inflated(bounded, strict);
  const explore::PathDistanceField from_start(inflated, start);
  std::vector<uint8_t> centre_reachable(limits_.num_cells(), 0);
  bool any = false;
  for (int64_t i = 0; i < limits_.num_cells(); ++i) {
    if (std::isfinite(from_start.at(i))) centre_reachable[i] = 1, any = true;
  }
  if (!any) {
    throw InputError("world '" + world_name + "': no free space is reachable from the start (" +
                     Format(start) + ") for the robot with its safety margin (" +
                     Metres(traversability.inflation_radius_m()) + " from walls" +
                     (boundary.empty() ? "" : " and from explore.boundary") +
                     "); choose another position with --start X,Y");
  }
  // The disc covers every cell within its radius of a reachable centre.
  const std::vector<float> d2 =
      grid::SquaredDistanceToNearestSite(centre_reachable, limits_.width(), limits_.height());
  const double r_cells = robot_radius_m / limits_.resolution();
  for (int64_t i = 0; i < limits_.num_cells(); ++i) {
    if (bounded.cells[i] == grid::CellState::kFree && d2[i] <= r_cells * r_cells + 1e-6) {
      reachable_.push_back(limits_.CellOfFlatIndex(i));
    }
  }
}

void GroundTruth::LabelDiscComponents(const explore::PlanningMap& bare) {
  disc_component_.assign(limits_.num_cells(), 0);
  int32_t label = 0;
  std::vector<int64_t> stack;
  for (int64_t seed = 0; seed < limits_.num_cells(); ++seed) {
    if (disc_component_[seed] != 0 || !bare.traversable(seed)) continue;
    disc_component_[seed] = ++label;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const grid::CellIndex c = limits_.CellOfFlatIndex(stack.back());
      stack.pop_back();
      for (int k = 0; k < 4; ++k) {
        const grid::CellIndex n{c.x + explore::kNeighbourOffsets[k][0],
                                c.y + explore::kNeighbourOffsets[k][1]};
        if (!bare.Traversable(n)) continue;
        const int64_t flat = limits_.FlatIndex(n);
        if (disc_component_[flat] != 0) continue;
        disc_component_[flat] = label;
        stack.push_back(flat);
      }
    }
  }
}

template <typename F>
void GroundTruth::ForEachReachable(const grid::OccupancyMap& map,
                                   const geometry::Rigid2d& world_from_map, F&& f) const {
  const grid::MapLimits& m = map.limits;
  // Positions in map cell units (floor gives the map cell). Runs every few
  // simulated seconds over every reachable cell (millions in the museum, where
  // it took a third of the wall time): along a run of adjacent cells of one
  // row the position advances by a constant step, so only the first cell of
  // each run is transformed.
  const geometry::Rigid2d map_from_world = world_from_map.inverse();
  const double inv_resolution = m.num_cells() > 0 ? 1.0 / m.resolution() : 0.0;
  const Eigen::Vector2d step =
      map_from_world.Rotate(Eigen::Vector2d(limits_.resolution(), 0.0)) * inv_resolution;
  for (const Run& run : runs_) {
    Eigen::Vector2d u =
        (map_from_world * limits_.CellCenter({run.x, run.y}) - m.origin()) * inv_resolution;
    // An empty map covers no cell of the run. Otherwise the positions along
    // a run lie on a segment: when both ends lie beyond the same edge of the
    // map (by a cell, far more than the stepping's rounding), no cell of the
    // run is inside. Early in a run most of the world is beyond the map.
    const Eigen::Vector2d end = u + (run.length - 1) * step;
    const double w = m.width(), h = m.height();
    if (m.num_cells() == 0 || (u.x() < -1.0 && end.x() < -1.0) ||
        (u.y() < -1.0 && end.y() < -1.0) || (u.x() > w + 1.0 && end.x() > w + 1.0) ||
        (u.y() > h + 1.0 && end.y() > h + 1.0)) {
      for (int x = run.x; x < run.x + run.length; ++x) f(grid::CellIndex{x, run.y}, false);
      continue;
    }
    for (int x = run.x; x < run.x + run.length; ++x) {
      if (x > run.x) u += step;
      const double fx = std::floor(u.x());
      const double fy = std::floor(u.y());
      const bool inside = fx >= 0.0 && fy >= 0.0 && fx < m.width() && fy < m.height();
      f(grid::CellIndex{x, run.y},
        inside && map.cells[static_cast<int64_t>(fy) * m.width() + static_cast<int64_t>(fx)] ==
                      grid::CellState::kFree);
    }
  }
}

double GroundTruth::MappedFreeM2(const grid::OccupancyMap& map,
                                 const geometry::Rigid2d& world_from_map) const {
  int64_t mapped = 0;
  ForEachReachable(map, world_from_map, [&](const grid::CellIndex&, bool m) { mapped += m; });
  return mapped * cell_area_m2_;
}

std::vector<uint8_t> GroundTruth::CoverageMask(const grid::OccupancyMap& map,
                                               const geometry::Rigid2d& world_from_map) const {
  std::vector<uint8_t> mask(limits_.num_cells(), kNotReachable);
  ForEachReachable(map, world_from_map, [&](const grid::CellIndex& cell, bool mapped) {
    mask[limits_.FlatIndex(cell)] = mapped ? kMapped : kUnmapped;
  });
  return mask;
}

bool GroundTruth::DiscCanReach(const Eigen::Vector2d& from, const Eigen::Vector2d& goal,
                               double tolerance_m) const {
  // The robot's true centre is collision-free but may sit a hair inside the
  // band the grid blocks (cell centres vs the exact disc): accept the
  // components of cells within half a cell of it.
  std::vector<int32_t> robot_labels;
  for (const grid::CellIndex& c :
       explore::CellsWithin(limits_, from, 0.75 * limits_.resolution())) {
    const int32_t label = disc_component_[limits_.FlatIndex(c)];
    if (label != 0) robot_labels.push_back(label);
  }
  for (const grid::CellIndex& c : explore::CellsWithin(limits_, goal, tolerance_m)) {
    const int32_t label = disc_component_[limits_.FlatIndex(c)];
    for (const int32_t r : robot_labels) {
      if (label == r) return true;
    }
  }
  return false;
}

std::vector<uint8_t> GroundTruth::ReachableMask() const {
  std::vector<uint8_t> mask(limits_.num_cells(), 0);
  for (const Run& run : runs_) {
    std::fill_n(mask.begin() + limits_.FlatIndex({run.x, run.y}), run.length, 1);
  }
  return mask;
}

}  // namespace scout::exploration
