#include "scout/grid/inflation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

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
  // Squared cell distances are integers, but radius / resolution is not exact in
  // binary (0.4 / 0.05 = 7.999...), so a radius of exactly k cells needs a small
  // relative tolerance to include the cells at distance k.
  const double radius_cells = radius_m / limits.resolution();
  const int64_t threshold =
      static_cast<int64_t>(std::floor(radius_cells * radius_cells * (1.0 + 1e-9) + 1e-9));
  const int reach = static_cast<int>(std::floor(std::sqrt(static_cast<double>(threshold))));
  const int width = limits.width(), height = limits.height();

  // Only distances up to the radius matter, so instead of a full distance
  // transform: (1) per column, the vertical distance to the nearest occupied
  // cell, capped just beyond the radius; (2) per row, every column whose
  // vertical distance dy is within reach blocks the interval of half-width
  // floor(sqrt(threshold - dy^2)) around it (marked with a difference array).
  // A cell is blocked iff min over columns x' of (x - x')^2 + dy(x')^2 <=
  // threshold, which is exactly the Euclidean test on cell centres.
  const int32_t cap = reach + 1;
  std::vector<int32_t> along_y(states.size());
  for (int y = 0; y < height; ++y) {
    const size_t row = static_cast<size_t>(y) * width;
    for (int x = 0; x < width; ++x) {
      const int32_t above = y > 0 ? along_y[row - width + x] : cap;
      along_y[row + x] =
          states[row + x] == CellState::kOccupied ? 0 : std::min<int32_t>(above + 1, cap);
    }
  }
  for (int y = height - 2; y >= 0; --y) {
    const size_t row = static_cast<size_t>(y) * width;
    for (int x = 0; x < width; ++x) {
      along_y[row + x] = std::min(along_y[row + x], along_y[row + width + x] + 1);
    }
  }
  // Half-widths by vertical distance, computed once.
  std::vector<int> half_width(reach + 1);
  for (int dy = 0; dy <= reach; ++dy) {
    int h = static_cast<int>(std::floor(std::sqrt(static_cast<double>(threshold - dy * dy))));
    while (static_cast<int64_t>(h + 1) * (h + 1) + dy * dy <= threshold) ++h;
    while (h > 0 && static_cast<int64_t>(h) * h + dy * dy > threshold) --h;
    half_width[dy] = h;
  }
  std::vector<uint8_t> blocked(states.size());
  std::vector<int32_t> delta(width + 1);
  for (int y = 0; y < height; ++y) {
    const size_t row = static_cast<size_t>(y) * width;
    std::fill(delta.begin(), delta.end(), 0);
    bool any = false;
    for (int x = 0; x < width; ++x) {
      const int32_t dy = along_y[row + x];
      if (dy > reach) continue;
      const int h = half_width[dy];
      ++delta[std::max(0, x - h)];
      --delta[std::min(width, x + h + 1)];
      any = true;
    }
    if (!any) continue;
    int32_t covering = 0;
    for (int x = 0; x < width; ++x) {
      covering += delta[x];
      blocked[row + x] = covering > 0;
    }
  }
  return blocked;
}

}  // namespace scout::grid
