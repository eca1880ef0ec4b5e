#include "scout/grid/probability_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace scout::grid {
namespace {

// Beyond this many cells a grid is certainly the result of a bad point (e.g. a
// NaN-free but absurd range); refusing keeps a bug from eating all memory.
constexpr int64_t kMaxCells = int64_t{1} << 31;
// Cell coordinates are computed in double first; anything beyond this cannot
// become a valid grid and would overflow the integer conversion.
constexpr double kMaxCellCoordinate = 1e9;

std::string CellToString(const CellIndex& cell) {
  return "(" + std::to_string(cell.x) + ", " + std::to_string(cell.y) + ")";
}

}  // namespace

ProbabilityGrid::ProbabilityGrid(const MapLimits& limits)
    : limits_(limits), values_(static_cast<size_t>(limits.num_cells()), kUnknownValue) {}

uint16_t ProbabilityGrid::value(const CellIndex& cell) const {
  if (!limits_.Contains(cell)) return kUnknownValue;
  return values_[limits_.FlatIndex(cell)] & kMaxValue;
}

CellState ProbabilityGrid::State(const CellIndex& cell) const {
  const uint16_t v = value(cell);
  return v == kUnknownValue ? CellState::kUnknown : StateOfProbability(ValueToProbability(v));
}

void ProbabilityGrid::SetProbability(const CellIndex& cell, float probability) {
  if (!limits_.Contains(cell)) {
    throw std::out_of_range("ProbabilityGrid::SetProbability: cell " + CellToString(cell) +
                            " is outside the grid");
  }
  uint16_t& stored = values_[limits_.FlatIndex(cell)];
  // Keep the marker: the cell stays in updated_cells_ and FinishUpdate clears it.
  stored = static_cast<uint16_t>((stored & kUpdateMarker) | ProbabilityToValue(probability));
}

bool ProbabilityGrid::ApplyLookupTable(const CellIndex& cell, const std::vector<uint16_t>& table) {
  if (table.size() != 2 * static_cast<size_t>(kUpdateMarker)) {
    throw std::invalid_argument("ProbabilityGrid::ApplyLookupTable: table must have 65536 entries");
  }
  if (!limits_.Contains(cell)) {
    throw std::out_of_range("ProbabilityGrid::ApplyLookupTable: cell " + CellToString(cell) +
                            " is outside the grid");
  }
  const int64_t flat = limits_.FlatIndex(cell);
  const uint16_t old_value = values_[flat];
  if (old_value & kUpdateMarker) return false;
  // The cell is marked even when the table maps it onto itself (e.g. a hit on a
  // cell already at the clamp), so it still counts as updated for this scan;
  // only an actual change of the stored probability is reported.
  values_[flat] = table[old_value];
  updated_cells_.push_back(flat);
  return (values_[flat] & kMaxValue) != old_value;
}

void ProbabilityGrid::FinishUpdate() {
  for (const int64_t flat : updated_cells_) values_[flat] &= kMaxValue;
  updated_cells_.clear();
}

void ProbabilityGrid::GrowToInclude(const Eigen::Vector2d& p, int padding_cells) {
  if (!p.allFinite()) {
    throw std::invalid_argument("ProbabilityGrid::GrowToInclude: point must be finite");
  }
  if (padding_cells < 0) {
    throw std::invalid_argument("ProbabilityGrid::GrowToInclude: padding_cells must be >= 0");
  }
  const double resolution = limits_.resolution();
  const double fx = std::floor((p.x() - limits_.origin().x()) / resolution);
  const double fy = std::floor((p.y() - limits_.origin().y()) / resolution);
  if (std::abs(fx) > kMaxCellCoordinate || std::abs(fy) > kMaxCellCoordinate) {
    throw std::out_of_range("ProbabilityGrid::GrowToInclude: point is too far from the grid");
  }
  const int64_t cx = static_cast<int64_t>(fx);
  const int64_t cy = static_cast<int64_t>(fy);
  if (limits_.num_cells() > 0 && cx >= 0 && cy >= 0 && cx < limits_.width() &&
      cy < limits_.height()) {
    return;
  }

  // Inclusive cell bounds of the new grid in the old grid's cell coordinates.
  // 'extra' absorbs rounding: the new origin is computed in floating point, and
  // a point on a cell border could otherwise land one cell outside.
  for (int extra = 0;; ++extra) {
    const int64_t pad = padding_cells + extra;
    int64_t min_x = 0, min_y = 0;
    int64_t max_x = limits_.width() - 1, max_y = limits_.height() - 1;
    if (limits_.num_cells() == 0) {
      // Nothing to keep: centre a fresh grid on the point (on the same lattice).
      min_x = cx - pad, max_x = cx + pad, min_y = cy - pad, max_y = cy + pad;
    } else {
      if (cx < min_x) min_x = cx - pad;
      if (cx > max_x) max_x = cx + pad;
      if (cy < min_y) min_y = cy - pad;
      if (cy > max_y) max_y = cy + pad;
    }
    const int64_t new_width = max_x - min_x + 1;
    const int64_t new_height = max_y - min_y + 1;
    if (new_width > std::numeric_limits<int>::max() ||
        new_height > std::numeric_limits<int>::max() || new_width * new_height > kMaxCells) {
      throw std::length_error("ProbabilityGrid::GrowToInclude: grid would exceed " +
                              std::to_string(kMaxCells) + " cells");
    }
    const MapLimits new_limits(
        resolution, limits_.origin() + Eigen::Vector2d(min_x * resolution, min_y * resolution),
        static_cast<int>(new_width), static_cast<int>(new_height));
    if (!new_limits.Contains(new_limits.CellContaining(p))) continue;

    std::vector<uint16_t> new_values(static_cast<size_t>(new_limits.num_cells()), kUnknownValue);
    const int offset_x = static_cast<int>(-min_x);
    const int offset_y = static_cast<int>(-min_y);
    for (int y = 0; y < limits_.height(); ++y) {
      const auto row = values_.begin() + limits_.FlatIndex({0, y});
      std::copy(row, row + limits_.width(),
                new_values.begin() + new_limits.FlatIndex({offset_x, y + offset_y}));
    }
    // Pending update markers move with their cells.
    for (int64_t& flat : updated_cells_) {
      const CellIndex old_cell = limits_.CellOfFlatIndex(flat);
      flat = new_limits.FlatIndex({old_cell.x + offset_x, old_cell.y + offset_y});
    }
    limits_ = new_limits;
    values_ = std::move(new_values);
    return;
  }
}

std::vector<CellState> ProbabilityGrid::States() const {
  std::vector<CellState> states(values_.size());
  for (size_t i = 0; i < values_.size(); ++i) {
    const uint16_t v = values_[i] & kMaxValue;
    states[i] =
        v == kUnknownValue ? CellState::kUnknown : StateOfProbability(ValueToProbability(v));
  }
  return states;
}

}  // namespace scout::grid
