#include "scout/grid/inflation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "scout/common/parallel.h"

namespace scout::grid {

namespace {

constexpr int64_t kMinCellsPerThread = 1 << 16;

// Squared radius in cells, as the integer threshold on squared cell distances.
int64_t SquaredCellThreshold(double radius_m, double resolution_m) {
  if (!(radius_m >= 0.0) || !std::isfinite(radius_m)) {
    throw std::invalid_argument("InflateOccupied: radius_m must be finite and >= 0");
  }
  // Squared cell distances are integers, but radius / resolution is not exact in
  // binary (0.4 / 0.05 = 7.999...), so a radius of exactly k cells needs a small
  // relative tolerance to include the cells at distance k.
  const double radius_cells = radius_m / resolution_m;
  return static_cast<int64_t>(std::floor(radius_cells * radius_cells * (1.0 + 1e-9) + 1e-9));
}

// Lines (columns or rows) per thread so that each thread gets at least
// kMinCellsPerThread cells of length 'line_length': smaller grids (a submap's)
// are not worth starting a thread for.
int64_t LinesPerThread(int64_t line_length) {
  return std::max<int64_t>(1, kMinCellsPerThread / std::max<int64_t>(1, line_length));
}

}  // namespace

std::vector<uint8_t> InflateOccupied(const std::vector<CellState>& states, const MapLimits& limits,
                                     double radius_m) {
  return InflationLevels(states, limits, {radius_m});
}

std::vector<uint8_t> InflationLevels(const std::vector<CellState>& states, const MapLimits& limits,
                                     const std::vector<double>& radii_m) {
  if (states.size() != static_cast<size_t>(limits.num_cells())) {
    throw std::invalid_argument("InflateOccupied: " + std::to_string(states.size()) +
                                " states for a grid of " + std::to_string(limits.num_cells()) +
                                " cells");
  }
  if (radii_m.empty() || radii_m.size() > 255) {
    throw std::invalid_argument("InflationLevels: 1 to 255 radii, got " +
                                std::to_string(radii_m.size()));
  }
  std::vector<int64_t> threshold;
  std::vector<int> reach;
  for (const double r : radii_m) {
    threshold.push_back(SquaredCellThreshold(r, limits.resolution()));
    reach.push_back(static_cast<int>(std::floor(std::sqrt(static_cast<double>(threshold.back())))));
  }
  const int max_reach = *std::max_element(reach.begin(), reach.end());
  const int width = limits.width(), height = limits.height();

  // Only distances up to the radius matter, so instead of a full distance
  // transform: (1) per column, the vertical distance to the nearest occupied
  // cell, capped just beyond the radius; (2) per row, every column whose
  // vertical distance dy is within reach blocks the interval of half-width
  // floor(sqrt(threshold - dy^2)) around it (marked with a difference array).
  // A cell is blocked iff min over columns x' of (x - x')^2 + dy(x')^2 <=
  // threshold, which is exactly the Euclidean test on cell centres. Step (1)
  // is shared by all radii.
  const int32_t cap = max_reach + 1;
  std::vector<int32_t> along_y(states.size());
  // Columns are independent in step (1) and rows in step (2): each thread
  // takes a block of them, so the result is the serial one.
  common::ParallelFor(width, LinesPerThread(height), [&](int64_t x0, int64_t x1) {
    for (int y = 0; y < height; ++y) {
      const size_t row = static_cast<size_t>(y) * width;
      for (int64_t x = x0; x < x1; ++x) {
        const int32_t above = y > 0 ? along_y[row - width + x] : cap;
        along_y[row + x] =
            states[row + x] == CellState::kOccupied ? 0 : std::min<int32_t>(above + 1, cap);
      }
    }
    for (int y = height - 2; y >= 0; --y) {
      const size_t row = static_cast<size_t>(y) * width;
      for (int64_t x = x0; x < x1; ++x) {
        along_y[row + x] = std::min(along_y[row + x], along_y[row + width + x] + 1);
      }
    }
  });
  std::vector<uint8_t> level(states.size(), 0);
  for (size_t k = 0; k < radii_m.size(); ++k) {
    // Half-widths by vertical distance, computed once per radius.
    std::vector<int> half_width(reach[k] + 1, 0);
    for (int dy = 0; dy <= reach[k]; ++dy) {
      int h = static_cast<int>(std::floor(std::sqrt(static_cast<double>(threshold[k] - dy * dy))));
      while (static_cast<int64_t>(h + 1) * (h + 1) + dy * dy <= threshold[k]) ++h;
      while (h > 0 && static_cast<int64_t>(h) * h + dy * dy > threshold[k]) --h;
      half_width[dy] = h;
    }
    common::ParallelFor(height, LinesPerThread(width), [&](int64_t y0, int64_t y1) {
      std::vector<int32_t> delta(width + 1);
      for (int64_t y = y0; y < y1; ++y) {
        const size_t row = static_cast<size_t>(y) * width;
        std::fill(delta.begin(), delta.end(), 0);
        bool any = false;
        for (int x = 0; x < width; ++x) {
          const int32_t dy = along_y[row + x];
          if (dy > reach[k]) continue;
          const int h = half_width[dy];
          ++delta[std::max(0, x - h)];
          --delta[std::min(width, x + h + 1)];
          any = true;
        }
        if (!any) continue;
        int32_t covering = 0;
        for (int x = 0; x < width; ++x) {
          covering += delta[x];
          level[row + x] += covering > 0;
        }
      }
    });
  }
  return level;
}

}  // namespace scout::grid
