#include "scout/frontier/local_frontiers.h"

#include <cmath>
#include <limits>

#include "scout/grid/inflation.h"

namespace scout::frontier {
namespace {

using grid::CellIndex;
using grid::CellState;

constexpr int kNeighbourDx[8] = {-1, 0, 1, -1, 1, -1, 0, 1};
constexpr int kNeighbourDy[8] = {-1, -1, -1, 0, 0, 1, 1, 1};

bool HasUnknownNeighbour(const std::vector<CellState>& states, const grid::MapLimits& limits,
                         const CellIndex& c) {
  for (int k = 0; k < 8; ++k) {
    const CellIndex n{c.x + kNeighbourDx[k], c.y + kNeighbourDy[k]};
    if (!limits.Contains(n) || states[limits.FlatIndex(n)] == CellState::kUnknown) return true;
  }
  return false;
}

// Returns the flat index of the free unblocked cell nearest to 'origin' within
// 'radius_m', or -1 if there is none.
int64_t NearestOpenCell(const std::vector<CellState>& states, const std::vector<uint8_t>& blocked,
                        const grid::MapLimits& limits, const Eigen::Vector2d& origin,
                        double radius_m) {
  const CellIndex center = limits.CellContaining(origin);
  const int r = static_cast<int>(std::ceil(radius_m / limits.resolution()));
  int64_t best = -1;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      const CellIndex c{center.x + dx, center.y + dy};
      if (!limits.Contains(c)) continue;
      const int64_t flat = limits.FlatIndex(c);
      if (blocked[flat] || states[flat] != CellState::kFree) continue;
      const double d2 = (limits.CellCenter(c) - origin).squaredNorm();
      if (d2 <= radius_m * radius_m && d2 < best_d2) {
        best_d2 = d2;
        best = flat;
      }
    }
  }
  return best;
}

}  // namespace

std::vector<uint8_t> FrontierCellMask(const std::vector<CellState>& states,
                                      const grid::MapLimits& limits) {
  const int width = limits.width(), height = limits.height();
  // Unknown cells, padded by one unknown cell on every side (outside is unknown).
  const int pw = width + 2;
  std::vector<uint8_t> unknown(static_cast<size_t>(pw) * (height + 2), 1);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      unknown[static_cast<size_t>(y + 1) * pw + x + 1] =
          states[static_cast<size_t>(y) * width + x] == CellState::kUnknown;
    }
  }
  std::vector<uint8_t> mask(states.size(), 0);
  for (int y = 0; y < height; ++y) {
    const uint8_t* up = &unknown[static_cast<size_t>(y + 2) * pw + 1];
    const uint8_t* mid = &unknown[static_cast<size_t>(y + 1) * pw + 1];
    const uint8_t* down = &unknown[static_cast<size_t>(y) * pw + 1];
    for (int x = 0; x < width; ++x) {
      const size_t i = static_cast<size_t>(y) * width + x;
      if (states[i] != CellState::kFree) continue;
      mask[i] = (up[x - 1] | up[x] | up[x + 1] | mid[x - 1] | mid[x + 1] | down[x - 1] | down[x] |
                 down[x + 1]) != 0;
    }
  }
  return mask;
}

LocalFrontier ExtractReachableFrontier(const std::vector<CellState>& states,
                                       const grid::MapLimits& limits,
                                       const std::vector<Eigen::Vector2d>& scan_origins,
                                       double inflation_radius_m) {
  LocalFrontier result;
  if (limits.num_cells() == 0) return result;
  const std::vector<uint8_t> blocked = grid::InflateOccupied(states, limits, inflation_radius_m);
  std::vector<uint8_t> reached(states.size(), 0);
  std::vector<int64_t> queue;
  for (const Eigen::Vector2d& origin : scan_origins) {
    const CellIndex cell = limits.CellContaining(origin);
    int64_t seed = -1;
    if (limits.Contains(cell)) {
      const int64_t flat = limits.FlatIndex(cell);
      if (!blocked[flat] && states[flat] == CellState::kFree) seed = flat;
    }
    if (seed < 0) seed = NearestOpenCell(states, blocked, limits, origin, inflation_radius_m);
    if (seed >= 0 && !reached[seed]) {
      reached[seed] = 1;
      queue.push_back(seed);
    }
  }
  // Breadth-first wavefront; 'queue' doubles as the visit order.
  for (size_t head = 0; head < queue.size(); ++head) {
    const CellIndex c = limits.CellOfFlatIndex(queue[head]);
    for (int k = 0; k < 8; ++k) {
      const CellIndex n{c.x + kNeighbourDx[k], c.y + kNeighbourDy[k]};
      if (!limits.Contains(n)) continue;
      const int64_t flat = limits.FlatIndex(n);
      if (reached[flat] || blocked[flat] || states[flat] != CellState::kFree) continue;
      reached[flat] = 1;
      queue.push_back(flat);
    }
  }
  for (int64_t flat = 0; flat < limits.num_cells(); ++flat) {
    if (!reached[flat]) continue;
    const CellIndex c = limits.CellOfFlatIndex(flat);
    if (HasUnknownNeighbour(states, limits, c)) {
      result.cells.push_back(c);
      result.points_m.push_back(limits.CellCenter(c));
    }
  }
  return result;
}

}  // namespace scout::frontier
