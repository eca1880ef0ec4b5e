#ifndef SCOUT_SIM_WORLD_PAINTER_H_
#define SCOUT_SIM_WORLD_PAINTER_H_

#include "scout/geometry/box.h"
#include "scout/grid/occupancy_map.h"

namespace scout::sim {

// Returns a map covering 'bounds' at 'resolution_m' (rounded to whole cells),
// with every cell set to 'state'.
grid::OccupancyMap MakeFilledMap(const geometry::Box2d& bounds, double resolution_m,
                                 grid::CellState state);

// Sets every cell of 'map' whose centre lies in the half-open box
// [box.min, box.max) to 'state'. Boxes that share an edge therefore never
// overlap nor leave a gap between them.
void FillBox(const geometry::Box2d& box, grid::CellState state, grid::OccupancyMap* map);

}  // namespace scout::sim

#endif  // SCOUT_SIM_WORLD_PAINTER_H_
