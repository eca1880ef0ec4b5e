#ifndef SCOUT_GRID_CELL_STATE_H_
#define SCOUT_GRID_CELL_STATE_H_

#include <cstdint>
#include <string_view>

namespace scout::grid {

// Paper eq. 1: p < 0.5 free, p > 0.5 occupied, never observed or p == 0.5 unknown.
enum class CellState : uint8_t { kUnknown = 0, kFree = 1, kOccupied = 2 };

inline CellState StateOfProbability(float p) {
  return p < 0.5f ? CellState::kFree : (p > 0.5f ? CellState::kOccupied : CellState::kUnknown);
}

std::string_view ToString(CellState state);

}  // namespace scout::grid

#endif  // SCOUT_GRID_CELL_STATE_H_
