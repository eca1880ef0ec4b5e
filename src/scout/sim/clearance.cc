#include "scout/sim/clearance.h"

#include <cmath>
#include <cstdint>

#include "scout/grid/distance_transform.h"

namespace scout::sim {

std::vector<float> ComputeClearance(const grid::OccupancyMap& map) {
  const int width = map.limits.width();
  const int height = map.limits.height();
  // One ring of site cells around the map stands for the outside.
  const int padded_width = width + 2;
  const int padded_height = height + 2;
  std::vector<uint8_t> is_site(static_cast<size_t>(padded_width) * padded_height, 1);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const bool free = map.cells[static_cast<size_t>(y) * width + x] == grid::CellState::kFree;
      is_site[static_cast<size_t>(y + 1) * padded_width + x + 1] = free ? 0 : 1;
    }
  }
  const std::vector<float> squared =
      grid::SquaredDistanceToNearestSite(is_site, padded_width, padded_height);
  const float resolution_m = static_cast<float>(map.limits.resolution());
  std::vector<float> clearance(static_cast<size_t>(width) * height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const float d2 = squared[static_cast<size_t>(y + 1) * padded_width + x + 1];
      clearance[static_cast<size_t>(y) * width + x] = std::sqrt(d2) * resolution_m;
    }
  }
  return clearance;
}

}  // namespace scout::sim
