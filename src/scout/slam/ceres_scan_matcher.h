#ifndef SCOUT_SLAM_CERES_SCAN_MATCHER_H_
#define SCOUT_SLAM_CERES_SCAN_MATCHER_H_

#include <Eigen/Core>

#include "scout/geometry/rigid_transform.h"
#include "scout/grid/probability_grid.h"
#include "scout/slam/likelihood_field_cost.h"
#include "scout/slam/point_cloud.h"

namespace scout::slam {

struct CeresScanMatcherOptions {
  // Scale of the per-point residuals (1 - p) / sqrt(max(N, full_weight_num_points)).
  double occupied_space_weight = 1.0;
  // Scans with fewer points than this pull with only N / full_weight_num_points
  // of the full occupied-space weight, so the priors hold them. Dividing by
  // sqrt(N) alone (Cartographer) gives two returns as much pull as two hundred:
  // in the simulated museum's halls, scans of 1-6 returns turned local SLAM by
  // up to 9 degrees in one scan. 0 = sqrt(N) for every scan.
  int full_weight_num_points = 0;
  // Scale of the residual pulling the translation toward the target (per metre).
  double translation_weight = 10.0;
  // Scale of the residual pulling the rotation toward the initial estimate's (per radian).
  double rotation_weight = 40.0;
  // Scale of a second translation residual, toward the motion prediction
  // (per metre), for callers whose initial estimate is a correlative search's
  // result rather than the prediction: it decides the directions the scan
  // leaves open, such as along a corridor, where the search's pick is
  // arbitrary. In every direction it also pulls where the walls hold the
  // scan, and strongly: the likelihood field is flat at a wall's centre, so a
  // matched room scan with a prediction 14 cm off moves 1.0 cm toward it at
  // weight 1, 6.9 cm at 5 (prediction_prior_test's room, measured). Hence
  // prediction_max_constrained_fraction. Local SLAM passes
  // a prediction only after its correlative search (the explorer, which runs
  // none, is not touched by it). 0 = none.
  double prediction_translation_weight = 0.0;
  // > 0: that prior acts only along the directions across which less than
  // this fraction of the scan's points lie on walls (WallNormalInformation),
  // such as along a corridor. 0 = in every direction.
  double prediction_max_constrained_fraction = 0.0;
  // Solver iterations; scan matching runs once per scan, so this bounds its cost.
  int max_num_iterations = 20;
  // Probability that unknown cells (and the grid's outside) score. Cartographer
  // uses the minimum, 0.1, which makes freshly mapped free space (about 0.49)
  // far more attractive than unexplored space: scans are pulled back into the
  // mapped area, so a robot driving into a corridor lags behind its odometry
  // (simulated office, perfect odometry, 8 s straight at 0.5 m/s: 9.7 cm
  // behind at 0.1, 1.7 cm at 0.5; fr079 ATE 0.093 vs 0.092 m). In [kMinProbability,
  // kMaxProbability].
  double unknown_probability = 0.5;
  // sigma_m > 0: the residuals read the grid's likelihood field
  // (likelihood_field_cost.h) instead of its probabilities, and
  // unknown_probability is unused. A wall seen once scores 0.55 and unknown
  // space 0.5 in the probabilities, so on logs of sparse scans the matcher
  // hardly tells them apart and slides scans into unexplored space (aces comes
  // out 3 % too long with exact odometry); the field scores the distance to
  // the nearest wall, whatever lies between.
  LikelihoodFieldOptions likelihood_field;
};

// Throws std::invalid_argument naming the first invalid option.
void Validate(const CeresScanMatcherOptions& options);

// Nonlinear least-squares scan matcher (Hess et al. 2016, section IV): one
// residual (occupied_space_weight / sqrt(N)) * (1 - p(T * point)) per point,
// with p the bicubically interpolated probability of the grid (unknown cells
// and the outside of the grid count as options.unknown_probability) or, with
// likelihood_field.sigma_m > 0, its likelihood field.
class CeresScanMatcher {
 public:
  // Throws std::invalid_argument on invalid options.
  explicit CeresScanMatcher(const CeresScanMatcherOptions& options);

  // Refines 'initial_pose_estimate' (grid frame) so 'points' (scan frame) fall
  // on occupied cells; priors pull the translation toward
  // 'target_translation' and the rotation toward the initial estimate's, and
  // (prediction_translation_weight > 0) the translation also toward
  // 'predicted_translation'. Returns the initial estimate unchanged if
  // 'points' is empty.
  geometry::Rigid2d Match(const Eigen::Vector2d& target_translation,
                          const geometry::Rigid2d& initial_pose_estimate, const PointCloud& points,
                          const grid::ProbabilityGrid& grid,
                          const Eigen::Vector2d* predicted_translation = nullptr) const;

 private:
  CeresScanMatcherOptions options_;
};

}  // namespace scout::slam

#endif  // SCOUT_SLAM_CERES_SCAN_MATCHER_H_
