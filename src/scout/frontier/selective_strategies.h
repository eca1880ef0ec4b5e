#ifndef SCOUT_FRONTIER_SELECTIVE_STRATEGIES_H_
#define SCOUT_FRONTIER_SELECTIVE_STRATEGIES_H_

#include <Eigen/Core>
#include <vector>

#include "scout/frontier/update_strategy.h"

namespace scout::frontier {

// A pose change (x, y, theta), compared component-wise against epsilon.
struct PoseDeviation {
  double dx_m = 0.0, dy_m = 0.0, dtheta_rad = 0.0;
};

// Returns current - previous component-wise (theta wrapped to [-pi, pi)).
PoseDeviation Deviation(const geometry::Rigid2d& current, const geometry::Rigid2d& previous);

// Paper eq. 3: |dx| > eps or |dy| > eps or |dtheta| > eps / (2 pi R).
bool DeviationExceedsThreshold(const PoseDeviation& d, double epsilon_m, double lidar_range_m);

// Returns 'seeds' plus every submap whose global box intersects a seed's, ascending.
std::vector<int> WithIntersectingSubmaps(const SubmapCatalog& catalog,
                                         const std::vector<int>& seeds);

// "bfs" (paper Alg. 1): breadth-first search from the latest submap through
// intersecting submaps whose pose changed by more than epsilon in this round;
// re-queries those submaps and every submap intersecting them. Ignores change
// accumulated over several rounds, so it can miss answers.
class BfsStrategy : public UpdateStrategy {
 public:
  using UpdateStrategy::UpdateStrategy;
  std::string_view name() const override { return "bfs"; }
  UpdateCost OnOptimized(const std::vector<geometry::Rigid2d>& previous_poses) override;
};

// "direct" (paper Alg. 2): accumulates every submap's pose change since it was
// last re-queried; submaps whose accumulated change exceeds epsilon, and every
// submap intersecting them, are re-queried and their accumulators reset.
class DirectStrategy : public UpdateStrategy {
 public:
  using UpdateStrategy::UpdateStrategy;
  std::string_view name() const override { return "direct"; }
  UpdateCost OnOptimized(const std::vector<geometry::Rigid2d>& previous_poses) override;

 private:
  std::vector<PoseDeviation> accumulated_;  // CD of the paper, per submap
};

}  // namespace scout::frontier

#endif  // SCOUT_FRONTIER_SELECTIVE_STRATEGIES_H_
