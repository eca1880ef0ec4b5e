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

// As InflateOccupied for several radii at once (sharing the column pass):
// each cell's value is the number of radii within which it lies, so with
// radii sorted from largest to smallest, level >= k + 1 means blocked by
// radius k. Throws std::invalid_argument for no radii or more than 255.
std::vector<uint8_t> InflationLevels(const std::vector<CellState>& states, const MapLimits& limits,
                                     const std::vector<double>& radii_m);

}  // namespace scout::grid

#endif  // SCOUT_GRID_INFLATION_H_
