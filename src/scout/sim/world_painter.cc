#include "scout/sim/world_painter.h"

#include <algorithm>
#include <cmath>

namespace scout::sim {

grid::OccupancyMap MakeFilledMap(const geometry::Box2d& bounds, double resolution_m,
                                 grid::CellState state) {
  const Eigen::Vector2d size = bounds.max - bounds.min;
  const int width = static_cast<int>(std::lround(size.x() / resolution_m));
  const int height = static_cast<int>(std::lround(size.y() / resolution_m));
  grid::OccupancyMap map;
  map.limits = grid::MapLimits(resolution_m, bounds.min, width, height);
  map.cells.assign(static_cast<size_t>(map.limits.num_cells()), state);
  return map;
}

void FillBox(const geometry::Box2d& box, grid::CellState state, grid::OccupancyMap* map) {
  const grid::MapLimits& limits = map->limits;
  const double resolution_m = limits.resolution();
  // Cell x has its centre at origin + (x + 0.5) * res; it is inside when
  // min <= centre < max, i.e. x in [ceil((min - o) / res - 0.5), ceil((max - o) / res - 0.5)).
  const auto first_cell = [&](double bound, double origin) {
    return static_cast<int>(std::ceil((bound - origin) / resolution_m - 0.5));
  };
  const int x0 = std::max(0, first_cell(box.min.x(), limits.origin().x()));
  const int x1 = std::min(limits.width(), first_cell(box.max.x(), limits.origin().x()));
  const int y0 = std::max(0, first_cell(box.min.y(), limits.origin().y()));
  const int y1 = std::min(limits.height(), first_cell(box.max.y(), limits.origin().y()));
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) map->set({x, y}, state);
  }
}

}  // namespace scout::sim
