#include "scout/grid/inflation.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "scout/grid/distance_transform.h"

namespace scout::grid {

std::vector<uint8_t> InflateOccupied(const std::vector<CellState>& states, const MapLimits& limits,
                                     double radius_m) {
  if (states.size() != static_cast<size_t>(limits.num_cells())) {
    throw std::invalid_argument("InflateOccupied: " + std::to_string(states.size()) +
                                " states for a grid of " + std::to_string(limits.num_cells()) +
                                " cells");
  }
  if (!(radius_m >= 0.0) || !std::isfinite(radius_m)) {
    throw std::invalid_argument("InflateOccupied: radius_m must be finite and >= 0");
  }
  std::vector<uint8_t> occupied(states.size());
  for (size_t i = 0; i < states.size(); ++i) occupied[i] = states[i] == CellState::kOccupied;
  const std::vector<float> squared_distance =
      SquaredDistanceToNearestSite(occupied, limits.width(), limits.height());

  // Squared cell distances are integers, but radius / resolution is not exact in
  // binary (0.4 / 0.05 = 7.999...), so a radius of exactly k cells needs a small
  // relative tolerance to include the cells at distance k.
  const double radius_cells = radius_m / limits.resolution();
  const double threshold = radius_cells * radius_cells * (1.0 + 1e-9) + 1e-9;
  std::vector<uint8_t> blocked(states.size());
  for (size_t i = 0; i < states.size(); ++i) {
    blocked[i] = static_cast<double>(squared_distance[i]) <= threshold;
  }
  return blocked;
}

}  // namespace scout::grid
