#ifndef SCOUT_GRID_SUBMAP_FUSION_H_
#define SCOUT_GRID_SUBMAP_FUSION_H_

#include <cstdint>
#include <vector>

#include "scout/geometry/rigid_transform.h"
#include "scout/grid/occupancy_map.h"
#include "scout/grid/probability_grid.h"

namespace scout::grid {

// A submap grid placed in the global frame.
struct PlacedGrid {
  const ProbabilityGrid* grid = nullptr;
  geometry::Rigid2d global_pose;  // grid frame -> global frame
};

// Fuses submaps into one global map at 'resolution_m': every global cell takes
// the sum of the log-odds of the submap cells containing its centre (unknown
// cells contribute nothing), so a cell is known when any submap knows it.
// The map covers the union of the submaps' boxes. Returns an empty map (no
// cells) when no submap is given.
//
// The global cells lie on one lattice whatever the bounds: lattice cell (i, j)
// covers [i * res, (i + 1) * res) x [j * res, (j + 1) * res), and a submap's
// contribution to it is computed from (i, j) alone. So a cell's value does not
// depend on the other submaps, which lets IncrementalSubmapFusion reuse sums.
// A centre on a submap cell edge (up to rounding) reads the cell above it.
// Throws std::length_error (naming the size) instead of allocating a map of
// more than kMaxFusedCells cells, which only submaps thrown kilometres apart
// by a diverged SLAM need.
OccupancyMap FuseSubmaps(const std::vector<PlacedGrid>& submaps, double resolution_m);

// 2^30 cells: 6 GB of sums while fusing; a 1.6 km square at 5 cm.
inline constexpr int64_t kMaxFusedCells = int64_t{1} << 30;

// Returns 'resolution_m' doubled as often as needed (none: 'resolution_m'
// itself) for the fused map of 'submaps' to have at most 'max_cells' cells.
// Throws std::length_error when a submap lies at a non-finite pose.
double ResolutionWithin(const std::vector<PlacedGrid>& submaps, double resolution_m,
                        int64_t max_cells);

// The building blocks FuseSubmaps and IncrementalSubmapFusion share, so that
// both compute every cell with the very same floating-point operations.
namespace fusion {

// A rectangle of lattice cells: columns [x0, x0 + width), rows [y0, y0 + height).
struct LatticeRect {
  int x0 = 0;
  int y0 = 0;
  int width = 0;
  int height = 0;

  bool empty() const { return width <= 0 || height <= 0; }
  int x1() const { return x0 + width; }  // one past the last column
  int y1() const { return y0 + height; }
  bool Contains(const LatticeRect& o) const {
    return o.empty() || (o.x0 >= x0 && o.y0 >= y0 && o.x1() <= x1() && o.y1() <= y1());
  }
  // Returns the smallest rectangle holding both (either may be empty).
  LatticeRect United(const LatticeRect& o) const;
  LatticeRect Intersected(const LatticeRect& o) const;
};

// Per-cell log-odds sums and known flags over a lattice rectangle, row-major.
struct LogOddsSums {
  LatticeRect rect;
  std::vector<float> log_odds;
  std::vector<uint8_t> known;

  // Sets 'rect' and zeroes every cell.
  void Reset(const LatticeRect& r);
  int64_t Index(int x, int y) const {
    return static_cast<int64_t>(y - rect.y0) * rect.width + (x - rect.x0);
  }
};

// Returns the lattice cells a submap can touch: those whose box overlaps its
// transformed bounding box (empty when the submap has no box).
LatticeRect SubmapCells(const PlacedGrid& submap, double resolution_m);

// Returns the limits FuseSubmaps gives the map of 'submaps' (no cells when
// there is no box), and in 'lattice' the lattice cells they cover.
MapLimits FusedLimits(const std::vector<PlacedGrid>& submaps, double resolution_m,
                      LatticeRect* lattice);

// Adds the submap's known log-odds to the cells of 'sums' inside 'clip' (which
// must lie in sums->rect) whose centres fall in known submap cells.
void AddSubmap(const PlacedGrid& submap, double resolution_m, const LatticeRect& clip,
               LogOddsSums* sums);

// Returns the fused state of a cell with log-odds sum 'log_odds'.
inline CellState FusedState(float log_odds, bool known) {
  if (!known) return CellState::kUnknown;
  return log_odds < 0.f   ? CellState::kFree
         : log_odds > 0.f ? CellState::kOccupied
                          : CellState::kUnknown;
}

}  // namespace fusion
}  // namespace scout::grid

#endif  // SCOUT_GRID_SUBMAP_FUSION_H_
