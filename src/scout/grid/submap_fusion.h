#ifndef SCOUT_GRID_SUBMAP_FUSION_H_
#define SCOUT_GRID_SUBMAP_FUSION_H_

#include <vector>

#include "scout/geometry/rigid_transform.h"
#include "scout/grid/occupancy_map.h"
#include "scout/grid/probability_grid.h"

namespace scout::grid {

// A submap grid placed in the global frame.
struct PlacedGrid {
  const ProbabilityGrid* grid = nullptr;
  geometry::Rigid2d global_pose;  // grid frame -> global frame
};

// Fuses submaps into one global map at 'resolution_m': every global cell takes
// the sum of the log-odds of the submap cells containing its centre (unknown
// cells contribute nothing), so a cell is known when any submap knows it.
// The map covers the union of the submaps' boxes. Returns an empty map (no
// cells) when no submap is given.
OccupancyMap FuseSubmaps(const std::vector<PlacedGrid>& submaps, double resolution_m);

}  // namespace scout::grid

#endif  // SCOUT_GRID_SUBMAP_FUSION_H_
