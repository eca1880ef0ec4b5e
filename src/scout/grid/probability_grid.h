#ifndef SCOUT_GRID_PROBABILITY_GRID_H_
#define SCOUT_GRID_PROBABILITY_GRID_H_

#include <cstdint>
#include <vector>

#include "scout/grid/cell_state.h"
#include "scout/grid/map_limits.h"
#include "scout/grid/probability_values.h"

namespace scout::grid {

// An occupancy probability grid (Cartographer-style value encoding, see
// probability_values.h). Cells outside the limits read as unknown.
class ProbabilityGrid {
 public:
  ProbabilityGrid() = default;
  explicit ProbabilityGrid(const MapLimits& limits);

  const MapLimits& limits() const { return limits_; }

  // Returns the raw value of 'cell' (kUnknownValue outside), without update marker.
  uint16_t value(const CellIndex& cell) const;
  bool IsKnown(const CellIndex& cell) const { return value(cell) != kUnknownValue; }
  // Returns the probability of 'cell'; 0.5 when unknown or outside.
  float GetProbability(const CellIndex& cell) const { return ValueToProbability(value(cell)); }
  // Returns the state of 'cell' per ALGORITHMS §1; kUnknown outside.
  CellState State(const CellIndex& cell) const;

  // Sets the probability of a cell inside the limits.
  void SetProbability(const CellIndex& cell, float probability);
  // Applies 'table' (from ComputeLookupTableToApplyOdds) to a cell inside the
  // limits unless it was already updated since the last FinishUpdate().
  // Returns true if the cell changed.
  bool ApplyLookupTable(const CellIndex& cell, const std::vector<uint16_t>& table);
  // Clears the update markers set since the previous call.
  void FinishUpdate();

  // Enlarges the grid (keeping resolution and cell contents) so that 'p' lies
  // inside, growing by at least 'padding_cells' beyond it on the grown side.
  void GrowToInclude(const Eigen::Vector2d& p, int padding_cells = 16);

  // Returns the states of all cells, row-major (MapLimits::FlatIndex).
  std::vector<CellState> States() const;

  // Raw row-major storage (values may carry kUpdateMarker during an update).
  const std::vector<uint16_t>& values() const { return values_; }

 private:
  MapLimits limits_;
  std::vector<uint16_t> values_;
  std::vector<int64_t> updated_cells_;
};

}  // namespace scout::grid

#endif  // SCOUT_GRID_PROBABILITY_GRID_H_
