#ifndef SCOUT_SYNTHETIC_GRID_SEARCH_H_
#define SCOUT_SYNTHETIC_GRID_SEARCH_H_

#include <cstdint>
#include <functional>
#include <vector>

#include "scout/grid/map_limits.h"

namespace scout::synthetic {

// Shortest paths over the traversable cells of a grid: Dijkstra with
// 8-connected moves (1 or sqrt(2) cells; diagonal moves only when both cells
// they cut past are traversable). Buffers are reused between runs.
class GridSearch {
 public:
  // 'traversable' is row-major over 'limits'; non-zero cells may be entered.
  // Throws std::invalid_argument if the sizes differ.
  GridSearch(const grid::MapLimits& limits, std::vector<uint8_t> traversable);

  // Returns the geometry of the searched grid.
  const grid::MapLimits& limits() const { return limits_; }
  // Returns true if the cell with flat index 'cell' may be entered.
  bool traversable(int64_t cell) const { return traversable_[cell] != 0; }

  // Settles the cells reachable from 'source' in order of path length (ties by
  // cell index), calling 'on_settled(cell, distance_m)' for each, until it
  // returns true (returns that cell), the next distance exceeds
  // 'max_distance_m', or no cell is left (returns -1). 'source' is settled
  // first even if it is not traversable.
  int64_t Run(int64_t source, double max_distance_m,
              const std::function<bool(int64_t cell, double distance_m)>& on_settled);

  // Returns the cells of the shortest path from the last run's source to
  // 'cell', which that run must have settled; source first.
  std::vector<int64_t> PathTo(int64_t cell) const;

 private:
  grid::MapLimits limits_;
  std::vector<uint8_t> traversable_;
  std::vector<float> distance_cells_;
  std::vector<int32_t> parent_;
  // run_ * 2 marks cells discovered by the current run, run_ * 2 + 1 settled ones.
  std::vector<uint32_t> mark_;
  uint32_t run_ = 0;
};

}  // namespace scout::synthetic

#endif  // SCOUT_SYNTHETIC_GRID_SEARCH_H_
