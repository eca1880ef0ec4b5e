#ifndef SCOUT_EXPLORE_TEST_MAPS_H_
#define SCOUT_EXPLORE_TEST_MAPS_H_

// Test helpers: hand-built occupancy maps. Not part of the library.

#include <Eigen/Core>
#include <vector>

#include "scout/explore/planning_map.h"
#include "scout/grid/occupancy_map.h"

namespace scout::explore::testing {

class MapBuilder {
 public:
  MapBuilder(int width, int height, double resolution_m = 0.1,
             grid::CellState fill = grid::CellState::kUnknown) {
    map_.limits = grid::MapLimits(resolution_m, Eigen::Vector2d::Zero(), width, height);
    map_.cells.assign(static_cast<size_t>(width) * height, fill);
  }
  // Sets the inclusive cell rectangle [x0, x1] x [y0, y1] (clipped to the map).
  MapBuilder& Fill(int x0, int y0, int x1, int y1, grid::CellState s) {
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        if (map_.limits.Contains({x, y})) map_.set({x, y}, s);
      }
    }
    return *this;
  }
  MapBuilder& Free(int x0, int y0, int x1, int y1) {
    return Fill(x0, y0, x1, y1, grid::CellState::kFree);
  }
  MapBuilder& Wall(int x0, int y0, int x1, int y1) {
    return Fill(x0, y0, x1, y1, grid::CellState::kOccupied);
  }
  const grid::OccupancyMap& map() const { return map_; }
  // Returns the centre of cell (x, y).
  Eigen::Vector2d At(double x, double y) const { return map_.limits.CellCenter({int(x), int(y)}); }
  // Returns the centres of all free cells with an unknown 8-neighbour (cells
  // outside the map are unknown), row-major.
  std::vector<Eigen::Vector2d> FrontierPoints() const {
    std::vector<Eigen::Vector2d> out;
    for (int y = 0; y < map_.limits.height(); ++y) {
      for (int x = 0; x < map_.limits.width(); ++x) {
        if (map_.at({x, y}) != grid::CellState::kFree) continue;
        for (const auto& d : kNeighbourOffsets) {
          if (map_.at({x + d[0], y + d[1]}) == grid::CellState::kUnknown) {
            out.push_back(map_.limits.CellCenter({x, y}));
            break;
          }
        }
      }
    }
    return out;
  }

 private:
  grid::OccupancyMap map_;
};

// A 0.1 m robot with 0.1 m margin: inflation of two cells at 0.1 m, so
// hand-drawn maps stay small.
inline TraversabilityOptions SmallRobot() {
  TraversabilityOptions o;
  o.robot_radius_m = 0.1;
  o.safety_margin_m = 0.1;
  o.narrow_margin_m = o.safety_margin_m;  // no narrow-passage tier (as before its 0.05 m default)
  return o;
}

}  // namespace scout::explore::testing

#endif  // SCOUT_EXPLORE_TEST_MAPS_H_
