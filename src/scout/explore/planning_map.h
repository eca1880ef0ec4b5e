#ifndef SCOUT_EXPLORE_PLANNING_MAP_H_
#define SCOUT_EXPLORE_PLANNING_MAP_H_

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "scout/grid/map_limits.h"
#include "scout/grid/occupancy_map.h"

namespace scout::explore {

// Where the robot may be: one shared definition for navigation-point costs,
// the A* planner and the baselines, so a goal that has a cost also has a plan.
struct TraversabilityOptions {
  // The robot is a disc of this radius (ALGORITHMS §8).
  double robot_radius_m = 0.20;
  // Extra clearance kept from occupied cells; inflation = robot + margin, the
  // same 0.40 m the frontier detector inflates by (ALGORITHMS §2).
  double safety_margin_m = 0.20;
  // Unknown cells are not traversable by default: frontier points lie on the
  // known-free side (WFD only walks free cells), so every frontier is reachable
  // through known free space, and unseen space may hide obstacles.
  bool unknown_traversable = false;
  // A goal whose own cell is not traversable is approached at the nearest
  // reachable cell within this radius (metres). It absorbs the rounding
  // between a submap's lattice and the fused map's; 0 demands the goal's cell.
  double goal_snap_radius_m = 0.10;
  // Narrow passages: cells of the inflated band where the robot still keeps
  // narrow_margin_m (< safety_margin_m) from occupied cells are traversable
  // at narrow_cost_factor times the cost of a step. SLAM's wall noise narrows
  // a 0.9 m door below twice the inflation radius; without this tier such a
  // door seals the room (and a robot inside it is stranded in a pocket).
  // The factor keeps paths out of the band wherever there is room.
  // narrow_margin_m >= safety_margin_m disables the tier. At 0.10 m the
  // robot (0.40 m across) needed a 0.60 m gap in its map, and willow-garage's
  // doors (0.65 m between the grey edges the simulator treats as solid, less
  // in the SLAM map) kept it out of rooms: coverage 0.956 and 0.967 on seeds
  // 2 and 4; at 0.05 m 0.975 and 0.976 (build of 441f1b8: every seed >= 0.97;
  // with the stand-off of 2070b2d seed 2 fell to 0.966, its SLAM worse). The collision
  // guard and its scan memory keep the disc off the walls it then passes
  // close to (office seeds 1-5: no collision).
  double narrow_margin_m = 0.05;
  double narrow_cost_factor = 4.0;
  // A robot standing closer to a wall than the narrow margin leaves through
  // cells where it keeps at least the clearance it has, searched within this
  // radius of it (metres; see StartRegion). 0 strands it where it stands.
  double escape_radius_m = 1.0;
  // Known-free cells within this distance of the robot's own trajectory are
  // narrow passages even where the inflation blocks them: the robot has been
  // there. The SLAM map keeps narrowing a door as scans of its posts add up
  // (and the fused map more than any one submap), and a robot that drove
  // into a room must not be sealed in it. 0 turns this off.
  double driven_width_m = 0.05;
  // Consecutive trajectory points farther apart than this are not joined.
  double driven_max_gap_m = 1.0;

  double inflation_radius_m() const { return robot_radius_m + safety_margin_m; }
  friend bool operator==(const TraversabilityOptions&, const TraversabilityOptions&) = default;
};

// Throws std::invalid_argument naming the key of a bad value.
void Validate(const TraversabilityOptions& options);

// Returns the cells inside 'limits' whose centres lie within 'radius_m' of 'p'
// (the cell containing 'p' always included when inside), in row-major order.
std::vector<grid::CellIndex> CellsWithin(const grid::MapLimits& limits, const Eigen::Vector2d& p,
                                         double radius_m);
// Calls visit(CellIndex) for the cells CellsWithin returns, in the same order,
// without building the list (for loops over many points).
template <typename Visit>
void ForEachCellWithin(const grid::MapLimits& limits, const Eigen::Vector2d& p, double radius_m,
                       Visit&& visit) {
  const grid::CellIndex centre = limits.CellContaining(p);
  // The rows and columns whose centres can lie within the radius (with a
  // millionth of a cell to spare for rounding): with the robot's small radii
  // a square of 2 r / resolution + 3 cells per side tested mostly cells no
  // centre of which is near.
  const double res = limits.resolution();
  const Eigen::Vector2d q = (p - limits.origin()) / res;
  const double rc = radius_m / res;
  constexpr double kSpare = 1e-6;
  const int x0 = std::min(centre.x, static_cast<int>(std::ceil(q.x() - rc - 0.5 - kSpare)));
  const int x1 = std::max(centre.x, static_cast<int>(std::floor(q.x() + rc - 0.5 + kSpare)));
  const int y0 = std::min(centre.y, static_cast<int>(std::ceil(q.y() - rc - 0.5 - kSpare)));
  const int y1 = std::max(centre.y, static_cast<int>(std::floor(q.y() + rc - 0.5 + kSpare)));
  const double r2 = radius_m * radius_m;
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const grid::CellIndex c{x, y};
      if (!limits.Contains(c)) continue;
      if (c == centre || (limits.CellCenter(c) - p).squaredNorm() <= r2) visit(c);
    }
  }
}

// 8-neighbour offsets; the first four are the orthogonal ones.
inline constexpr std::array<std::array<int, 2>, 8> kNeighbourOffsets = {
    {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}}};

// An occupancy map with the robot's footprint applied: every cell within the
// inflation radius of an occupied cell is blocked (exact EDT). Owns a copy of
// the states so it stays valid when the caller's map changes.
class PlanningMap {
 public:
  // With 'with_clearance', also keeps each cell's distance to the nearest
  // occupied cell (one more EDT) for planners that penalise closeness.
  PlanningMap(const grid::OccupancyMap& map, const TraversabilityOptions& options,
              bool with_clearance = false);
  // The same map, reusing 'previous' (null: none) where it can: when it was
  // built with the same options from a map with the same limits, only the
  // cells within reach of a cell whose state changed are inflated and coded
  // again (the exploration loop's map changes near the robot between two
  // optimisations). AllowDriven and CloseNarrow of 'previous' do not carry
  // over. The result equals the constructor's above.
  PlanningMap(const grid::OccupancyMap& map, const TraversabilityOptions& options,
              bool with_clearance, const PlanningMap* previous);

  const grid::MapLimits& limits() const { return limits_; }
  const TraversabilityOptions& options() const { return options_; }
  grid::CellState state(int64_t flat) const { return states_[flat]; }
  const std::vector<grid::CellState>& states() const { return states_; }
  // True when the cell lies within the inflation radius of an occupied cell.
  bool blocked(int64_t flat) const { return blocked_[flat] != 0; }
  // True when the robot's centre may be in this cell.
  bool traversable(int64_t flat) const { return traversable_[flat] != 0; }
  // True when the cell is traversable only as a narrow passage.
  bool narrow(int64_t flat) const { return traversable_[flat] == kNarrow; }
  // Per cell, row-major: 0 not traversable, 1 traversable, kNarrow a narrow
  // passage (for searches that scan every cell).
  static constexpr uint8_t kNarrow = 2;
  const std::vector<uint8_t>& traversability_codes() const { return traversable_; }
  // The cost of entering a traversable cell, per unit of step length.
  float StepFactor(int64_t flat) const {
    return traversable_[flat] == kNarrow ? static_cast<float>(options_.narrow_cost_factor) : 1.0f;
  }
  // The largest StepFactor of any cell.
  float MaxStepFactor() const {
    return has_narrow_ ? static_cast<float>(options_.narrow_cost_factor) : 1.0f;
  }
  // As above; false for cells outside the map.
  bool Traversable(const grid::CellIndex& cell) const {
    return limits_.Contains(cell) && traversable(limits_.FlatIndex(cell));
  }
  // True when a step from 'from' by neighbour offset 'k' stays on traversable
  // cells; diagonal steps also need both orthogonal cells, so a path never
  // squeezes between two blocked corners.
  bool StepAllowed(const grid::CellIndex& from, int k) const;

  // Makes known-free cells within driven_width_m of the polyline through
  // 'trajectory' (global positions of the robot, oldest first; segments
  // longer than driven_max_gap_m skipped) traversable as narrow passages.
  void AllowDriven(const std::vector<Eigen::Vector2d>& trajectory);
  // Closes the narrow-passage cells whose centres lie within 'radius_m' of
  // 'p' (a passage the robot got stuck in): they become non-traversable, and
  // they and the band cells there are closed() to StartRegion's escape too.
  // A later AllowDriven opens the driven cells among them again.
  void CloseNarrow(const Eigen::Vector2d& p, double radius_m);
  // True when CloseNarrow closed the cell.
  bool closed(int64_t flat) const { return !closed_.empty() && closed_[flat] != 0; }

  bool has_clearance() const { return !clearance_m_.empty(); }
  // Distance in metres from the cell's centre to the nearest occupied cell's
  // centre (+infinity without occupied cells). Requires has_clearance().
  float clearance_m(int64_t flat) const { return clearance_m_[flat]; }

  // Returns the traversable cell whose centre is nearest to 'p' within
  // 'radius_m' (ties: lowest flat index), or nothing.
  std::optional<grid::CellIndex> NearestTraversable(const Eigen::Vector2d& p,
                                                    double radius_m) const;
  // True when every cell the segment a-b passes through is traversable (exact
  // grid traversal; through a cell corner both side cells count).
  bool SegmentTraversable(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;
  // Smallest clearance over the cells the segment a-b passes through.
  float SegmentClearance(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;

  // Calls visit(CellIndex) for every cell the segment a-b passes through, in
  // order, until visit returns false (exact grid traversal; through a cell
  // corner both side cells are visited). Cells may lie outside the map.
  template <typename Visit>
  void ForEachCellOnSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                            Visit&& visit) const;

 private:
  // Codes the states and levels in the cells of [x0, x1) x [y0, y1).
  void Code(int x0, int x1, int y0, int y1);
  // Inflates the cells of [x0, x1) x [y0, y1) again (levels exact: the cells
  // within reach of them are read too) and codes them.
  void Reinflate(int x0, int x1, int y0, int y1);
  // Radii of the inflation levels (metres).
  std::vector<double> InflationRadii() const;
  // More than the largest radius, in cells.
  int ReachCells() const;

  grid::MapLimits limits_;
  TraversabilityOptions options_;
  std::vector<grid::CellState> states_;
  bool has_narrow_ = false;
  std::vector<uint8_t> blocked_;      // inflation levels (grid::InflationLevels)
  std::vector<uint8_t> base_codes_;   // traversability codes before AllowDriven/CloseNarrow
  std::vector<uint8_t> traversable_;  // traversability_codes()
  std::vector<uint8_t> closed_;       // empty until CloseNarrow
  std::vector<float> clearance_m_;
};

template <typename Visit>
void PlanningMap::ForEachCellOnSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                       Visit&& visit) const {
  // Amanatides & Woo grid traversal in cell units.
  const double res = limits_.resolution();
  const Eigen::Vector2d pa = (a - limits_.origin()) / res;
  const Eigen::Vector2d pb = (b - limits_.origin()) / res;
  grid::CellIndex c{static_cast<int>(std::floor(pa.x())), static_cast<int>(std::floor(pa.y()))};
  const grid::CellIndex end{static_cast<int>(std::floor(pb.x())),
                            static_cast<int>(std::floor(pb.y()))};
  const Eigen::Vector2d d = pb - pa;
  const int sx = d.x() > 0 ? 1 : -1;
  const int sy = d.y() > 0 ? 1 : -1;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double tdx = d.x() != 0 ? std::abs(1.0 / d.x()) : kInf;
  const double tdy = d.y() != 0 ? std::abs(1.0 / d.y()) : kInf;
  double tx = d.x() != 0 ? ((sx > 0 ? c.x + 1 - pa.x() : pa.x() - c.x) * tdx) : kInf;
  double ty = d.y() != 0 ? ((sy > 0 ? c.y + 1 - pa.y() : pa.y() - c.y) * tdy) : kInf;
  if (!visit(c)) return;
  const int steps = std::abs(end.x - c.x) + std::abs(end.y - c.y);
  for (int i = 0; i < steps && !(c == end); ++i) {
    if (std::abs(tx - ty) < 1e-12) {
      // Through a corner: both side cells are touched.
      if (!visit(grid::CellIndex{c.x + sx, c.y}) || !visit(grid::CellIndex{c.x, c.y + sy})) return;
      c.x += sx, c.y += sy, tx += tdx, ty += tdy;
      ++i;
    } else if (tx < ty) {
      c.x += sx, tx += tdx;
    } else {
      c.y += sy, ty += tdy;
    }
    if (!visit(c)) return;
  }
}

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_PLANNING_MAP_H_
