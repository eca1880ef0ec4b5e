#ifndef SCOUT_SIM_RAY_CASTER_H_
#define SCOUT_SIM_RAY_CASTER_H_

#include <Eigen/Core>

#include "scout/grid/occupancy_map.h"

namespace scout::sim {

// Returns the distance in metres from 'origin' along the ray at 'angle_rad'
// (world frame) to where it enters the first cell that is not free (occupied
// or unknown; everything beyond the map is unknown), found by exact
// Amanatides-Woo traversal. Returns 0 if 'origin' lies in such a cell and
// +infinity if no such cell starts within 'max_range_m'.
double CastRay(const grid::OccupancyMap& map, const Eigen::Vector2d& origin, double angle_rad,
               double max_range_m);

}  // namespace scout::sim

#endif  // SCOUT_SIM_RAY_CASTER_H_
