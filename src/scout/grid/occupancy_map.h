#ifndef SCOUT_GRID_OCCUPANCY_MAP_H_
#define SCOUT_GRID_OCCUPANCY_MAP_H_

#include <vector>

#include "scout/grid/cell_state.h"
#include "scout/grid/map_limits.h"

namespace scout::grid {

// A grid of ternary cell states (free / occupied / unknown), e.g. a building map
// read from a ROS map_server image or a fused map to save.
struct OccupancyMap {
  MapLimits limits;
  std::vector<CellState> cells;  // row-major, MapLimits::FlatIndex

  CellState at(const CellIndex& c) const {
    return limits.Contains(c) ? cells[limits.FlatIndex(c)] : CellState::kUnknown;
  }
  void set(const CellIndex& c, CellState s) { cells[limits.FlatIndex(c)] = s; }
};

}  // namespace scout::grid

#endif  // SCOUT_GRID_OCCUPANCY_MAP_H_
