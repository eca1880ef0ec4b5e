#ifndef SCOUT_SYNTHETIC_WAYPOINT_COVER_H_
#define SCOUT_SYNTHETIC_WAYPOINT_COVER_H_

#include <cstdint>
#include <vector>

#include "scout/synthetic/grid_search.h"

namespace scout::synthetic {

// Returns waypoints (flat cell indices) such that every cell in 'reachable'
// with clearance >= min_clearance_m lies within path distance spacing_m of
// one. Greedy: candidates are taken by decreasing clearance (ties by index),
// so room and hall centres come first and corridors fill the rest.
std::vector<int64_t> SelectWaypoints(GridSearch& search, const std::vector<uint8_t>& reachable,
                                     const std::vector<float>& clearance, double min_clearance_m,
                                     double spacing_m);

// Returns the waypoints in greedy nearest-neighbour order by path length from
// 'start', each with the grid path (cells) that leads to it from the previous
// one. Waypoints that cannot be reached are left out.
std::vector<std::vector<int64_t>> OrderByNearestNeighbour(GridSearch& search, int64_t start,
                                                          const std::vector<int64_t>& waypoints);

}  // namespace scout::synthetic

#endif  // SCOUT_SYNTHETIC_WAYPOINT_COVER_H_
