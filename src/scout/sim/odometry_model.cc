#include "scout/sim/odometry_model.h"

#include <cmath>
#include <sstream>
#include <string>

#include "scout/common/error.h"
#include "scout/sim/random.h"

namespace scout::sim {
namespace {

// 25 times the default trans_per_trans: the robot's own estimate is already
// metres off within minutes at 10 (office, 200 s: ATE 4.4 m); 1e6 let the
// SLAM map grow past its size limit (an internal error).
constexpr double kMaxNoiseCoefficient = 10.0;

void RequireOdometryOption(bool ok, const std::string& key, double value) {
  if (!ok) {
    std::ostringstream message;
    message << "robot.odometry." << key << " = " << value << ": expected a value in [0, "
            << kMaxNoiseCoefficient << "]";
    throw InputError(message.str());
  }
}

bool InRange(double x) { return x >= 0.0 && x <= kMaxNoiseCoefficient; }

}  // namespace

void CheckOdometryNoiseOptions(const OdometryNoiseOptions& o) {
  RequireOdometryOption(InRange(o.trans_per_trans), "trans_per_trans", o.trans_per_trans);
  RequireOdometryOption(InRange(o.trans_per_rot), "trans_per_rot", o.trans_per_rot);
  RequireOdometryOption(InRange(o.rot_per_rot), "rot_per_rot", o.rot_per_rot);
  RequireOdometryOption(InRange(o.rot_per_trans), "rot_per_trans", o.rot_per_trans);
}

OdometryModel::OdometryModel(const OdometryNoiseOptions& options, uint64_t seed,
                             const geometry::Rigid2d& true_start,
                             const geometry::Rigid2d& odometry_start)
    : options_((CheckOdometryNoiseOptions(options), options)),
      rng_(seed),
      last_true_pose_(true_start),
      odometry_pose_(odometry_start) {}

const geometry::Rigid2d& OdometryModel::Update(const geometry::Rigid2d& true_pose) {
  const geometry::Rigid2d increment = last_true_pose_.inverse() * true_pose;
  last_true_pose_ = true_pose;
  const double trans_m = increment.translation().norm();
  const double rot_rad = increment.theta();
  // Drawn unconditionally so the stream position depends only on the number
  // of samples, not on whether the robot moved.
  const double trans_noise = StandardNormal(rng_);
  const double rot_noise = StandardNormal(rng_);
  const double trans_sd =
      options_.trans_per_trans * trans_m + options_.trans_per_rot * std::abs(rot_rad);
  const double rot_sd = options_.rot_per_rot * std::abs(rot_rad) + options_.rot_per_trans * trans_m;
  const double rot_error_rad = rot_sd * rot_noise;
  // Reverse motion keeps its chord direction (bearing near pi), so the
  // translation stays a length and the bearing carries the sign.
  const double bearing_rad =
      trans_m > 0.0 ? std::atan2(increment.y(), increment.x()) + 0.5 * rot_error_rad : 0.0;
  const double noisy_trans_m = trans_m + trans_sd * trans_noise;
  const geometry::Rigid2d noisy_increment(noisy_trans_m * std::cos(bearing_rad),
                                          noisy_trans_m * std::sin(bearing_rad),
                                          rot_rad + rot_error_rad);
  odometry_pose_ = odometry_pose_ * noisy_increment;
  return odometry_pose_;
}

}  // namespace scout::sim
