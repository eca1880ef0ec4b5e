#ifndef SCOUT_FRONTIER_BASELINE_STRATEGIES_H_
#define SCOUT_FRONTIER_BASELINE_STRATEGIES_H_

#include "scout/frontier/update_strategy.h"

namespace scout::frontier {

// "full": re-queries every point of every submap without hints. Its answers
// define the truth for accuracy.
class FullStrategy : public UpdateStrategy {
 public:
  using UpdateStrategy::UpdateStrategy;
  std::string_view name() const override { return "full"; }
  UpdateCost OnOptimized(const std::vector<geometry::Rigid2d>& previous_poses) override;

 protected:
  bool uses_hints() const override { return false; }
};

// "dfd" (Oršulić et al. 2019): re-queries every point of every submap, asking
// the last objecting submap first. Exact; its count is the baseline of P.
class DfdStrategy : public UpdateStrategy {
 public:
  using UpdateStrategy::UpdateStrategy;
  std::string_view name() const override { return "dfd"; }
  UpdateCost OnOptimized(const std::vector<geometry::Rigid2d>& previous_poses) override;
};

}  // namespace scout::frontier

#endif  // SCOUT_FRONTIER_BASELINE_STRATEGIES_H_
