#ifndef SCOUT_EXPLORATION_TEST_WORLDS_H_
#define SCOUT_EXPLORATION_TEST_WORLDS_H_

// Test-only helper (included by the exploration tests and scout_explore_bench,
// not by the library).

#include "scout/sim/world.h"

namespace scout::exploration::testing {

// Sets the cells whose centres lie in [x0, x1] x [y0, y1] (metres) to 'state'.
inline void Paint(grid::OccupancyMap& map, double x0, double y0, double x1, double y1,
                  grid::CellState state) {
  for (int y = 0; y < map.limits.height(); ++y) {
    for (int x = 0; x < map.limits.width(); ++x) {
      const Eigen::Vector2d c = map.limits.CellCenter({x, y});
      if (c.x() >= x0 && c.x() <= x1 && c.y() >= y0 && c.y() <= y1) map.set({x, y}, state);
    }
  }
}

// A small building, 9 m x 6 m inside 0.15 m walls: a left room and a right
// room joined by a 1.2 m door, a pillar in the left room, and a 1 m x 1 m
// closet in the right room's corner whose only opening is 0.3 m wide (the
// robot cannot enter it). The robot starts in the left room, facing +x.
inline sim::World SmallBuilding() {
  sim::World w;
  w.name = "small-building";
  w.map.limits = grid::MapLimits(0.05, {0.0, 0.0}, 186, 126);
  w.map.cells.assign(w.map.limits.num_cells(), grid::CellState::kOccupied);
  using grid::CellState;
  Paint(w.map, 0.15, 0.15, 9.15, 6.15, CellState::kFree);
  Paint(w.map, 4.5, 0.0, 4.65, 6.3, CellState::kOccupied);  // dividing wall
  Paint(w.map, 4.5, 2.4, 4.65, 3.6, CellState::kFree);      // its door
  Paint(w.map, 2.0, 4.0, 2.4, 4.4, CellState::kOccupied);   // pillar
  Paint(w.map, 7.9, 4.9, 8.0, 6.15, CellState::kOccupied);  // closet side wall
  Paint(w.map, 7.9, 4.8, 9.15, 4.9, CellState::kOccupied);  // closet front wall
  Paint(w.map, 8.4, 4.8, 8.7, 4.9, CellState::kFree);       // its 0.3 m gap
  w.start = {1.5, 1.5};
  return w;
}

}  // namespace scout::exploration::testing

#endif  // SCOUT_EXPLORATION_TEST_WORLDS_H_
