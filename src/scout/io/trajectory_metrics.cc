#include "scout/io/trajectory_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace scout::io {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// A pair (i, j) further apart than this many time steps spans a gap in the
// data and would measure drift over an unknown interval.
constexpr double kMaxStepStretch = 1.5;

}  // namespace

geometry::Rigid2d AlignRigid2d(const std::vector<PosePair>& pairs) {
  std::vector<Eigen::Vector2d> estimate;
  std::vector<Eigen::Vector2d> reference;
  for (const PosePair& p : pairs) {
    estimate.push_back(p.estimate.translation());
    reference.push_back(p.reference.translation());
  }
  return geometry::FitRigid2d(estimate, reference);
}

RelativePoseError ComputeRelativePoseError(const std::vector<PosePair>& time_sorted_pairs,
                                           double dt_s) {
  const std::vector<PosePair>& p = time_sorted_pairs;
  double sum_trans = 0.0, sum_trans2 = 0.0;
  double sum_rot = 0.0, sum_rot2 = 0.0;
  RelativePoseError result;
  for (size_t i = 0; i < p.size(); ++i) {
    const auto j = std::lower_bound(p.begin() + i, p.end(), p[i].time_s + dt_s,
                                    [](const PosePair& q, double t) { return q.time_s < t; });
    if (j == p.end()) break;  // later i have even fewer successors
    if (j->time_s - p[i].time_s > kMaxStepStretch * dt_s) continue;
    const geometry::Rigid2d ref_delta = p[i].reference.inverse() * j->reference;
    const geometry::Rigid2d est_delta = p[i].estimate.inverse() * j->estimate;
    const geometry::Rigid2d error = ref_delta.inverse() * est_delta;
    const double trans_m = error.translation().norm();
    sum_trans += trans_m;
    sum_trans2 += trans_m * trans_m;
    const double rot_deg = std::abs(error.theta()) * 180.0 / std::numbers::pi;
    sum_rot += rot_deg;
    sum_rot2 += rot_deg * rot_deg;
    ++result.pairs;
  }
  result.trans_rmse_m = result.pairs > 0 ? std::sqrt(sum_trans2 / result.pairs) : kNaN;
  result.rot_rmse_deg = result.pairs > 0 ? std::sqrt(sum_rot2 / result.pairs) : kNaN;
  result.trans_mean_m = result.pairs > 0 ? sum_trans / result.pairs : kNaN;
  result.rot_mean_deg = result.pairs > 0 ? sum_rot / result.pairs : kNaN;
  return result;
}

TrajectoryErrors ComputeTrajectoryErrors(const std::vector<PosePair>& pairs) {
  std::vector<PosePair> sorted = pairs;
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const PosePair& a, const PosePair& b) { return a.time_s < b.time_s; });
  TrajectoryErrors errors;
  errors.matched = static_cast<int>(sorted.size());
  const geometry::Rigid2d alignment = AlignRigid2d(sorted);
  double sum2 = 0.0;
  double max_error = 0.0;
  for (const PosePair& p : sorted) {
    const double e = (alignment * p.estimate.translation() - p.reference.translation()).norm();
    sum2 += e * e;
    max_error = std::max(max_error, e);
  }
  errors.ate_rmse_m = sorted.empty() ? kNaN : std::sqrt(sum2 / sorted.size());
  errors.ate_max_m = sorted.empty() ? kNaN : max_error;
  const RelativePoseError rpe_1s = ComputeRelativePoseError(sorted, 1.0);
  const RelativePoseError rpe_10s = ComputeRelativePoseError(sorted, 10.0);
  errors.rpe_1s_trans_m = rpe_1s.trans_rmse_m;
  errors.rpe_1s_rot_deg = rpe_1s.rot_rmse_deg;
  errors.rpe_1s_trans_mean_m = rpe_1s.trans_mean_m;
  errors.rpe_1s_rot_mean_deg = rpe_1s.rot_mean_deg;
  errors.rpe_1s_pairs = rpe_1s.pairs;
  errors.rpe_10s_trans_m = rpe_10s.trans_rmse_m;
  errors.rpe_10s_rot_deg = rpe_10s.rot_rmse_deg;
  errors.rpe_10s_trans_mean_m = rpe_10s.trans_mean_m;
  errors.rpe_10s_rot_mean_deg = rpe_10s.rot_mean_deg;
  errors.rpe_10s_pairs = rpe_10s.pairs;
  return errors;
}

}  // namespace scout::io
