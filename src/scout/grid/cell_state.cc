#include "scout/grid/cell_state.h"

namespace scout::grid {

std::string_view ToString(CellState state) {
  switch (state) {
    case CellState::kUnknown:
      return "unknown";
    case CellState::kFree:
      return "free";
    case CellState::kOccupied:
      return "occupied";
  }
  // Only reachable through a cast of an out-of-range integer.
  return "invalid";
}

}  // namespace scout::grid
