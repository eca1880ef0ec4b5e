#ifndef SCOUT_FRONTIER_UPDATE_STRATEGY_H_
#define SCOUT_FRONTIER_UPDATE_STRATEGY_H_

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "scout/frontier/submap_catalog.h"

namespace scout::frontier {

// The cost of one update (an optimisation round or a grid change).
struct UpdateCost {
  int64_t queried_points = 0;   // distinct local frontier points whose answer was recomputed
  int queried_submaps = 0;      // distinct submaps owning those points
  double time_us = 0.0;         // wall time of the update
  std::vector<int> submap_ids;  // those submaps, in the order first touched
};

// Keeps the global-frontier answer of every local frontier point up to date
// (ALGORITHMS §4). All strategies read the same SubmapCatalog; they differ in
// which points they re-query after an optimisation.
class UpdateStrategy {
 public:
  explicit UpdateStrategy(const SubmapCatalog& catalog) : catalog_(catalog) {}
  virtual ~UpdateStrategy() = default;
  UpdateStrategy(const UpdateStrategy&) = delete;
  UpdateStrategy& operator=(const UpdateStrategy&) = delete;

  virtual std::string_view name() const = 0;

  // Call after the catalog applied a grid change. The common procedure (the
  // same for all strategies): the submap's surviving points keep their
  // answers, its new points are queried, and every point of another submap
  // whose position in the changed submap falls inside the changed region is
  // re-queried.
  virtual UpdateCost OnSubmapChanged(const SubmapChange& change);
  // Call after the catalog applied an optimisation; 'previous_poses' are the
  // global poses before it (PP of the paper).
  virtual UpdateCost OnOptimized(const std::vector<geometry::Rigid2d>& previous_poses) = 0;

  // Returns the current answer for point 'k' of submap 'i'.
  bool IsGlobalFrontier(int i, int k) const { return is_frontier_[i][k] != 0; }
  // Returns the answers of all points of submap 'i'.
  const std::vector<uint8_t>& answers(int i) const { return is_frontier_[i]; }

 protected:
  // Re-queries every point of every submap and returns the cost.
  UpdateCost QueryAllSubmaps(bool use_hints);
  // Re-queries every point of the given submaps; adds to 'cost'.
  void QuerySubmaps(const std::vector<int>& ids, bool use_hints, UpdateCost* cost);
  // Re-queries point 'k' of submap 'i'.
  void QueryPoint(int i, int k, bool use_hints) {
    int* hint = use_hints ? &hint_[i][k] : nullptr;
    is_frontier_[i][k] = StabbingQueryFor(i, k, hint);
  }
  bool StabbingQueryFor(int i, int k, int* hint);
  // Resizes the per-point arrays of the changed submap, keeping surviving
  // answers; returns the indices of its new points.
  std::vector<int> RemapPoints(const SubmapChange& change);
  // Uses hints in the common grid-change procedure (all but "full").
  virtual bool uses_hints() const { return true; }

  const SubmapCatalog& catalog_;
  std::vector<std::vector<uint8_t>> is_frontier_;
  std::vector<std::vector<int>> hint_;
  std::vector<int> scratch_;
};

// The strategy names MakeStrategy accepts, in report order.
const std::vector<std::string>& StrategyNames();

// Returns the strategy called 'name' (full, dfd, bfs, direct, exact). Throws
// InputError naming the accepted names otherwise.
std::unique_ptr<UpdateStrategy> MakeStrategy(std::string_view name, const SubmapCatalog& catalog);

}  // namespace scout::frontier

#endif  // SCOUT_FRONTIER_UPDATE_STRATEGY_H_
