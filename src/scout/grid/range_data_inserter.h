#ifndef SCOUT_GRID_RANGE_DATA_INSERTER_H_
#define SCOUT_GRID_RANGE_DATA_INSERTER_H_

#include <Eigen/Core>
#include <vector>

#include "scout/grid/probability_grid.h"

namespace scout::grid {

struct RangeDataInserterOptions {
  double hit_probability = 0.55;   // ALGORITHMS §7
  double miss_probability = 0.49;  // ALGORITHMS §7
};

// Inserts one scan into a probability grid, Cartographer-style: the cell of
// every return is updated with the hit table, then every cell a ray passes
// through from 'origin' up to (excluding) its end cell with the miss table;
// each cell at most once per scan (hits before misses). 'misses' are ray ends
// without a return (free space only). All points are in the grid's frame. The
// grid is grown to contain every point first. Rays are traversed exactly
// (Amanatides-Woo), so every cell a ray's segment crosses is visited.
class RangeDataInserter {
 public:
  // Throws std::invalid_argument unless 0.5 < hit < 1 and 0 < miss < 0.5.
  explicit RangeDataInserter(const RangeDataInserterOptions& options);

  void Insert(const Eigen::Vector2d& origin, const std::vector<Eigen::Vector2d>& returns,
              const std::vector<Eigen::Vector2d>& misses, ProbabilityGrid* grid) const;

 private:
  std::vector<uint16_t> hit_table_;
  std::vector<uint16_t> miss_table_;
};

}  // namespace scout::grid

#endif  // SCOUT_GRID_RANGE_DATA_INSERTER_H_
