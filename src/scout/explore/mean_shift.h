#ifndef SCOUT_EXPLORE_MEAN_SHIFT_H_
#define SCOUT_EXPLORE_MEAN_SHIFT_H_

#include <Eigen/Core>
#include <vector>

namespace scout::explore {

// Mean-shift clustering of frontier points with a flat kernel (ALGORITHMS §6.1).
struct MeanShiftOptions {
  // Radius of the flat kernel, metres.
  double bandwidth_m = 1.0;
  // Seeds are the means of the points in square bins of this size (metres);
  // 0 seeds at every point. Binning changes which modes are found only where
  // two modes are closer than a bin, and cuts the work by the points per bin.
  double seed_bin_m = 0.25;
  // A seed stops moving when its shift is below this (metres) ...
  double convergence_m = 1e-3;
  // ... or after this many shifts.
  int max_iterations = 100;
};

// Throws std::invalid_argument naming the key of a bad value.
void Validate(const MeanShiftOptions& options);

struct MeanShiftClusters {
  // Distinct modes, at least one bandwidth apart.
  std::vector<Eigen::Vector2d> centres;
  // For every input point, the index of its nearest centre.
  std::vector<int> label;
};

// Returns the clusters of 'points'. Modes within one bandwidth of a denser mode
// are merged into it; every point joins its nearest surviving mode. Neighbours
// are found through a hash grid of bandwidth-sized cells, so the cost is
// O(points · iterations · points-per-kernel), not quadratic. Deterministic.
MeanShiftClusters MeanShift(const std::vector<Eigen::Vector2d>& points,
                            const MeanShiftOptions& options);

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_MEAN_SHIFT_H_
