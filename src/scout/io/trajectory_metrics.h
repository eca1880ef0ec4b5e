#ifndef SCOUT_IO_TRAJECTORY_METRICS_H_
#define SCOUT_IO_TRAJECTORY_METRICS_H_

#include <vector>

#include "scout/geometry/rigid_transform.h"

namespace scout::io {

// An estimated pose and the reference (ground-truth) pose of the same instant.
struct PosePair {
  double time_s = 0.0;
  geometry::Rigid2d estimate;
  geometry::Rigid2d reference;
};

// Returns the rigid transform T (rotation and translation, no scale) that
// minimises sum_i |T * estimate_i.translation - reference_i.translation|^2
// (geometry::FitRigid2d). Identity for no pairs; a pure translation for one
// pair or when all estimate positions coincide.
geometry::Rigid2d AlignRigid2d(const std::vector<PosePair>& pairs);

// Trajectory accuracy, the usual definitions (Sturm et al., IROS 2012):
// - ATE (absolute trajectory error): the position error |T * est_i - ref_i|
//   after aligning all estimate positions with AlignRigid2d; RMSE and maximum.
//   Headings do not enter the ATE.
// - RPE over a time step dt (1 s and 10 s): for each pair i, the first pair j
//   with t_j - t_i >= dt is used, skipped when t_j - t_i > 1.5 dt (a gap in the
//   data); the error is E = (ref_i^-1 ref_j)^-1 (est_i^-1 est_j); RMSE over all
//   used (i, j) of |E.translation| in metres and of |E.theta| in degrees, and
//   the mean of each. RPE needs no alignment: a global transform cancels in
//   est_i^-1 est_j. Both statistics, because published figures use either:
//   Cartographer's relations tool (cartographer_compute_relations_metrics)
//   prints the mean absolute error (with its standard deviation), while TUM's
//   evaluate_rpe leads with the RMSE; on a trajectory with a few large errors the
//   RMSE is well above the mean (the fr079 bag's 10 s rotation: 1.15 against
//   0.85 degrees).
// Errors with nothing to average over (no pairs) are NaN.
struct TrajectoryErrors {
  int matched = 0;  // number of pose pairs
  double ate_rmse_m = 0.0;
  double ate_max_m = 0.0;
  double rpe_1s_trans_m = 0.0;
  double rpe_1s_rot_deg = 0.0;
  double rpe_10s_trans_m = 0.0;
  double rpe_10s_rot_deg = 0.0;
  // Mean absolute errors over the same pairs.
  double rpe_1s_trans_mean_m = 0.0;
  double rpe_1s_rot_mean_deg = 0.0;
  double rpe_10s_trans_mean_m = 0.0;
  double rpe_10s_rot_mean_deg = 0.0;
  int rpe_1s_pairs = 0;
  int rpe_10s_pairs = 0;
};

// Returns the errors defined above. 'pairs' need not be sorted by time (a
// sorted copy is used).
TrajectoryErrors ComputeTrajectoryErrors(const std::vector<PosePair>& pairs);

// The relative pose error over 'dt_s' as defined above: RMSE of the
// translation (m) and of the rotation (deg), their means, and the number of
// (i, j) used.
struct RelativePoseError {
  double trans_rmse_m = 0.0;
  double rot_rmse_deg = 0.0;
  double trans_mean_m = 0.0;
  double rot_mean_deg = 0.0;
  int pairs = 0;
};
RelativePoseError ComputeRelativePoseError(const std::vector<PosePair>& time_sorted_pairs,
                                           double dt_s);

}  // namespace scout::io

#endif  // SCOUT_IO_TRAJECTORY_METRICS_H_
