#ifndef SCOUT_SIM_CLEARANCE_H_
#define SCOUT_SIM_CLEARANCE_H_

#include <vector>

#include "scout/grid/occupancy_map.h"

namespace scout::sim {

// Returns, for every cell of 'map' (row-major), its clearance: the distance in
// metres from its centre to the centre of the nearest cell that is not free
// (occupied or unknown). Cells beyond the map border count as not free, so a
// free cell on the border has clearance one cell. Non-free cells get 0.
std::vector<float> ComputeClearance(const grid::OccupancyMap& map);

}  // namespace scout::sim

#endif  // SCOUT_SIM_CLEARANCE_H_
