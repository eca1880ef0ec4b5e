#ifndef SCOUT_EXPLORE_TOUR_H_
#define SCOUT_EXPLORE_TOUR_H_

#include <vector>

#include "scout/explore/planning_map.h"

namespace scout::explore {

// Ordering of navigation points by an open tour (USERS.md: roadmap-explorer
// orders many frontiers by a travelling-salesman tour; FUEL does the same):
// the robot drives to the first point of the shortest path that starts at the
// robot and visits every candidate, so it does not leave a point behind that
// it would have to come back for.

// Path distances (metres) between every pair of 'cells' (cells of 'map', e.g.
// where PathDistanceField::NearestReached put each navigation point), on a
// coarse grid of cells of about 'coarse_cell_m': a coarse cell is open when
// any of its cells is traversable, so every way the fine map allows is open,
// and a closed band at least two coarse cells wide (a wall the map inflates
// by a coarse cell's width on each side) stays closed. A pair with no coarse
// path gets infinity. Symmetric, zero on the diagonal.
std::vector<std::vector<double>> CoarsePathDistances(const PlanningMap& map,
                                                     const std::vector<grid::CellIndex>& cells,
                                                     double coarse_cell_m);

// For each candidate i: first_leg_m[i] plus the length of the shortest path
// that starts at i and visits every other candidate (exact, Held-Karp over
// subsets; at most kMaxTourPoints candidates). An infinite distance between
// two candidates is replaced by the way through the robot
// (first_leg_m[a] + first_leg_m[b]), which always exists.
constexpr int kMaxTourPoints = 12;
std::vector<double> OpenTourLengths(const std::vector<double>& first_leg_m,
                                    const std::vector<std::vector<double>>& distance_m);

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_TOUR_H_
