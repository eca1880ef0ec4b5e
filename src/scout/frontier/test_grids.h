#ifndef SCOUT_FRONTIER_TEST_GRIDS_H_
#define SCOUT_FRONTIER_TEST_GRIDS_H_

// Test helpers: hand-drawn grids. Not part of the library.

#include <memory>
#include <string>
#include <vector>

#include "scout/grid/probability_grid.h"

namespace scout::frontier::testing {

// Builds a grid from rows drawn top (max y) to bottom: '#' occupied, '.' free,
// anything else unknown. Cell (0, 0) is the bottom-left character; the grid's
// min corner is 'origin'.
inline std::shared_ptr<grid::ProbabilityGrid> DrawGrid(const std::vector<std::string>& rows,
                                                       double resolution_m = 0.05,
                                                       Eigen::Vector2d origin = {0, 0}) {
  const int height = static_cast<int>(rows.size());
  const int width = height == 0 ? 0 : static_cast<int>(rows[0].size());
  auto g =
      std::make_shared<grid::ProbabilityGrid>(grid::MapLimits(resolution_m, origin, width, height));
  for (int r = 0; r < height; ++r) {
    for (int x = 0; x < width; ++x) {
      const char ch = rows[r][x];
      const grid::CellIndex c{x, height - 1 - r};
      if (ch == '#') g->SetProbability(c, 0.9f);
      if (ch == '.') g->SetProbability(c, 0.1f);
    }
  }
  return g;
}

}  // namespace scout::frontier::testing

#endif  // SCOUT_FRONTIER_TEST_GRIDS_H_
