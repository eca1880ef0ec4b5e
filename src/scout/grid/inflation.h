#ifndef SCOUT_GRID_INFLATION_H_
#define SCOUT_GRID_INFLATION_H_

#include <cstdint>
#include <vector>

#include "scout/grid/cell_state.h"
#include "scout/grid/map_limits.h"

namespace scout::grid {

// Returns a row-major mask (1 = blocked) of every cell whose centre lies within
// 'radius_m' (inclusive) of the centre of an occupied cell, occupied cells
// included: the exact Euclidean test on cell centres (a disc, not a square
// kernel), in time linear in the number of cells.
// 'states' is row-major over 'limits'.
std::vector<uint8_t> InflateOccupied(const std::vector<CellState>& states, const MapLimits& limits,
                                     double radius_m);

}  // namespace scout::grid

#endif  // SCOUT_GRID_INFLATION_H_
