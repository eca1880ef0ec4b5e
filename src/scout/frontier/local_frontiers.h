#ifndef SCOUT_FRONTIER_LOCAL_FRONTIERS_H_
#define SCOUT_FRONTIER_LOCAL_FRONTIERS_H_

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "scout/grid/cell_state.h"
#include "scout/grid/map_limits.h"

namespace scout::frontier {

// Returns a row-major mask (1 = frontier cell) of a grid's cells: free cells
// with at least one unknown 8-neighbour (ALGORITHMS §1). Cells outside the grid
// count as unknown.
std::vector<uint8_t> FrontierCellMask(const std::vector<grid::CellState>& states,
                                      const grid::MapLimits& limits);

// The reachable local frontier of one submap, in the submap frame.
struct LocalFrontier {
  std::vector<grid::CellIndex> cells;     // in the submap's grid, ascending flat index
  std::vector<Eigen::Vector2d> points_m;  // centres of 'cells', submap frame
};

// ALGORITHMS §2: inflates occupied cells by 'inflation_radius_m' (exact EDT),
// runs an 8-connected wavefront over free, unblocked cells from the scan
// origins (an origin inside the blocked band starts from the nearest free
// unblocked cell within the inflation radius; otherwise it seeds nothing) and
// returns every reached cell that has an unknown 8-neighbour in the raw grid.
LocalFrontier ExtractReachableFrontier(const std::vector<grid::CellState>& states,
                                       const grid::MapLimits& limits,
                                       const std::vector<Eigen::Vector2d>& scan_origins,
                                       double inflation_radius_m);

}  // namespace scout::frontier

#endif  // SCOUT_FRONTIER_LOCAL_FRONTIERS_H_
