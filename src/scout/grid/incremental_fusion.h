#ifndef SCOUT_GRID_INCREMENTAL_FUSION_H_
#define SCOUT_GRID_INCREMENTAL_FUSION_H_

#include <memory>
#include <vector>

#include "scout/geometry/rigid_transform.h"
#include "scout/grid/occupancy_map.h"
#include "scout/grid/probability_grid.h"
#include "scout/grid/submap_fusion.h"

namespace scout::grid {

// A submap to fuse. A finished submap's grid never changes, so the same
// pointer and pose mean the same contribution to the map.
struct FusionInput {
  int id = 0;  // stable across updates
  std::shared_ptr<const ProbabilityGrid> grid;
  geometry::Rigid2d global_pose;  // grid frame -> global frame
  bool finished = false;
};

// FuseSubmaps for a map that is fused again and again while only the newest
// (active) submaps change and, after an optimisation, all poses move. Keeps
// the log-odds sums of the leading run of finished submaps whose grid and
// pose are unchanged, so an update adds only the remaining submaps. Every
// result equals FuseSubmaps of the same submaps in the same order, limits and
// cells: the sums are added in the same order on the same lattice.
class IncrementalSubmapFusion {
 public:
  // Throws std::invalid_argument unless resolution_m > 0.
  explicit IncrementalSubmapFusion(double resolution_m);

  // Returns the fused map of 'submaps' (in their order), valid until the next
  // call. Throws std::invalid_argument if an input has no grid.
  const OccupancyMap& Update(const std::vector<FusionInput>& submaps);

  // How much work was reused, for tests and profiling.
  struct Statistics {
    int updates = 0;
    int base_rebuilds = 0;     // cached sums dropped (a pose or grid changed)
    int base_additions = 0;    // submaps added to the cached sums
    int active_additions = 0;  // submaps added on top of them for one update
  };
  const Statistics& statistics() const { return statistics_; }

 private:
  struct CachedSubmap {
    int id = 0;
    std::shared_ptr<const ProbabilityGrid> grid;  // held, so the pointer stays unique
    geometry::Rigid2d global_pose;
  };

  // Returns how many leading inputs the cached sums hold, dropping them
  // unless they all still match the inputs.
  size_t ValidateBase(const std::vector<FusionInput>& submaps);
  // Enlarges the cached sums (keeping them) to hold 'cells'.
  void GrowBase(const fusion::LatticeRect& cells);
  // Recomputes the cached states in 'rect' from the cached sums.
  void ClassifyBase(const fusion::LatticeRect& rect);
  // Writes the cached states into map_ (unknown outside the cache).
  void CopyBaseStates(const fusion::LatticeRect& lattice);

  double resolution_m_;
  std::vector<CachedSubmap> base_submaps_;
  fusion::LogOddsSums base_;            // sums of base_submaps_, in their order
  std::vector<CellState> base_states_;  // FusedState of base_, same layout
  fusion::LogOddsSums scratch_;         // base_ plus the other submaps, per update
  OccupancyMap map_;
  Statistics statistics_;
};

}  // namespace scout::grid

#endif  // SCOUT_GRID_INCREMENTAL_FUSION_H_
