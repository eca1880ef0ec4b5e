#ifndef SCOUT_SIM_TEST_REACHABILITY_H_
#define SCOUT_SIM_TEST_REACHABILITY_H_

// Test-only helper (included by the sim tests, not by the library).

#include <cstdint>
#include <vector>

#include "scout/grid/occupancy_map.h"

namespace scout::sim {

// Returns a row-major mask of the cells reachable from 'start' through
// 4-connected cells whose clearance passes 'passes(clearance_m)'.
template <typename Passes>
std::vector<uint8_t> ReachableCells(const grid::OccupancyMap& map,
                                    const std::vector<float>& clearance,
                                    const Eigen::Vector2d& start, Passes passes) {
  const grid::MapLimits& limits = map.limits;
  std::vector<uint8_t> reached(clearance.size(), 0);
  const grid::CellIndex first = limits.CellContaining(start);
  if (!limits.Contains(first) || !passes(clearance[limits.FlatIndex(first)])) return reached;
  std::vector<int64_t> stack = {limits.FlatIndex(first)};
  reached[stack.back()] = 1;
  const int dx[4] = {1, -1, 0, 0};
  const int dy[4] = {0, 0, 1, -1};
  while (!stack.empty()) {
    const grid::CellIndex cell = limits.CellOfFlatIndex(stack.back());
    stack.pop_back();
    for (int k = 0; k < 4; ++k) {
      const grid::CellIndex next{cell.x + dx[k], cell.y + dy[k]};
      if (!limits.Contains(next)) continue;
      const int64_t flat = limits.FlatIndex(next);
      if (reached[flat] || !passes(clearance[flat])) continue;
      reached[flat] = 1;
      stack.push_back(flat);
    }
  }
  return reached;
}

// Returns true if any cell with its centre inside 'box' is set in 'mask'.
inline bool AnyCellIn(const grid::OccupancyMap& map, const std::vector<uint8_t>& mask,
                      const geometry::Box2d& box) {
  const grid::MapLimits& limits = map.limits;
  const grid::CellIndex lo = limits.CellContaining(box.min);
  const grid::CellIndex hi = limits.CellContaining(box.max);
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      const grid::CellIndex cell{x, y};
      if (limits.Contains(cell) && box.Contains(limits.CellCenter(cell)) &&
          mask[limits.FlatIndex(cell)]) {
        return true;
      }
    }
  }
  return false;
}

}  // namespace scout::sim

#endif  // SCOUT_SIM_TEST_REACHABILITY_H_
