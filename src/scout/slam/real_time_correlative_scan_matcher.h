#ifndef SCOUT_SLAM_REAL_TIME_CORRELATIVE_SCAN_MATCHER_H_
#define SCOUT_SLAM_REAL_TIME_CORRELATIVE_SCAN_MATCHER_H_

#include <numbers>

#include "scout/geometry/rigid_transform.h"
#include "scout/grid/probability_grid.h"
#include "scout/slam/likelihood_field_cost.h"
#include "scout/slam/point_cloud.h"
#include "scout/slam/scan_match_result.h"

namespace scout::slam {

struct RealTimeCorrelativeScanMatcherOptions {
  // Half-width of the square of translations searched (ALGORITHMS §7: 0.1 m).
  double linear_search_window_m = 0.1;
  // Half-width of the interval of rotations searched (ALGORITHMS §7: 20°).
  double angular_search_window_rad = 20.0 * std::numbers::pi / 180.0;
  // Penalties for moving away from the initial estimate (per m², per rad²).
  double translation_delta_cost_weight = 0.1;
  double rotation_delta_cost_weight = 0.1;
  // Probability that unknown cells (and the grid's outside) score; see
  // CeresScanMatcherOptions::unknown_probability. In [0.1, 0.9].
  double unknown_probability = 0.5;
  // sigma_m > 0: candidates score the mean of the grid's likelihood field
  // under their points (likelihood_field_cost.h) instead of the mean
  // probability. Off by default: at 6 cm the eight Radish logs'
  // worst ATE over seeds 1-6 fell from 0.83 to 0.21 m (csail no longer
  // breaks), but the fr079 bag went from 0.079 to 0.084 m and its
  // synchronous replay from 22 to 33 s (docs/EXPERIMENTS.md).
  LikelihoodFieldOptions likelihood_field;
  // true: a best candidate turned by the whole angular window (a step of the
  // window's edge) is not trusted, and the initial estimate is returned
  // instead: the best turn may lie beyond the window, and a pick on its edge
  // was a wrong wall where it was looked at (freiburg-079 seed 1 with the
  // prediction prior: 20.2 degrees at a 20 degree window, a broken map).
  // On the eight Radish logs with injected noise, seeds 1-12, it changed 4
  // runs of 96, none for the worse (csail seed 6: ATE 0.624 -> 0.177 m), and
  // no fr079 bag scan lands there (docs/EXPERIMENTS.md). When the true turn
  // lies just beyond the window, the edge was the better start: a wider
  // window is then the remedy.
  bool initial_estimate_at_angular_edge = true;
};

// Throws std::invalid_argument naming the first invalid option.
void Validate(const RealTimeCorrelativeScanMatcherOptions& options);

// Exhaustive correlative scan matcher (Olson 2009 as used by Cartographer's
// online correlative matching): tries every angle (step AngularSearchStep of
// the scan's largest range) and every cell offset within the window. A
// candidate scores the mean probability of its points' cells (unknown counts
// as kMinProbability) times exp(-(w_t |dt|² + w_r |dθ|²)), which prefers the
// initial estimate among equally good matches. See
// initial_estimate_at_angular_edge for picks on the window's angular edge.
class RealTimeCorrelativeScanMatcher {
 public:
  // Throws std::invalid_argument on invalid options.
  explicit RealTimeCorrelativeScanMatcher(const RealTimeCorrelativeScanMatcherOptions& options);

  // Returns the best candidate pose (grid frame) of 'points' (scan frame) and
  // its score; the initial estimate with score 0 if 'points' is empty. If
  // given, '*on_angular_edge' tells whether the best candidate lay on the
  // angular window's edge (whatever initial_estimate_at_angular_edge then did).
  ScanMatchResult Match(const geometry::Rigid2d& initial_pose_estimate, const PointCloud& points,
                        const grid::ProbabilityGrid& grid, bool* on_angular_edge = nullptr) const;

 private:
  RealTimeCorrelativeScanMatcherOptions options_;
};

}  // namespace scout::slam

#endif  // SCOUT_SLAM_REAL_TIME_CORRELATIVE_SCAN_MATCHER_H_
