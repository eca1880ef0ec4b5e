#include "scout/synthetic/correction_model.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "scout/common/error.h"
#include "scout/common/format.h"
#include "scout/sim/random.h"
#include "scout/synthetic/se2.h"

namespace scout::synthetic {
namespace {

using geometry::Rigid2d;

void RequireCorrectionOption(bool ok, const std::string& key, double value,
                             const std::string& expected) {
  if (!ok) {
    throw InputError("corrections." + key + " = " + FormatNumber(value) + ": expected " + expected);
  }
}

}  // namespace

void Validate(const CorrectionModelOptions& o) {
  RequireCorrectionOption(o.drift_translation_m_per_sqrt_m >= 0.0, "drift_translation_m_per_sqrt_m",
                          o.drift_translation_m_per_sqrt_m, ">= 0");
  RequireCorrectionOption(o.drift_heading_rad_per_sqrt_m >= 0.0, "drift_heading_rad_per_sqrt_m",
                          o.drift_heading_rad_per_sqrt_m, ">= 0");
  RequireCorrectionOption(o.drift_heading_rad_per_sqrt_rad >= 0.0, "drift_heading_rad_per_sqrt_rad",
                          o.drift_heading_rad_per_sqrt_rad, ">= 0");
  RequireCorrectionOption(o.newest_pull_fraction >= 0.0 && o.newest_pull_fraction <= 1.0,
                          "newest_pull_fraction", o.newest_pull_fraction, "in [0, 1]");
  RequireCorrectionOption(o.pull_decay_per_submap >= 0.0 && o.pull_decay_per_submap < 1.0,
                          "pull_decay_per_submap", o.pull_decay_per_submap, "in [0, 1)");
  RequireCorrectionOption(o.newest_jitter_m >= 0.0, "newest_jitter_m", o.newest_jitter_m, ">= 0");
  RequireCorrectionOption(o.newest_jitter_rad >= 0.0, "newest_jitter_rad", o.newest_jitter_rad,
                          ">= 0");
  RequireCorrectionOption(o.min_nudge_m >= 0.0, "min_nudge_m", o.min_nudge_m, ">= 0");
  RequireCorrectionOption(o.min_nudge_rad >= 0.0, "min_nudge_rad", o.min_nudge_rad, ">= 0");
  RequireCorrectionOption(o.loop_closure_distance_m > 0.0, "loop_closure_distance_m",
                          o.loop_closure_distance_m, "> 0");
  RequireCorrectionOption(o.min_loop_closure_age_submaps >= 1, "min_loop_closure_age_submaps",
                          o.min_loop_closure_age_submaps, ">= 1");
  RequireCorrectionOption(o.min_loop_closure_travel_m >= 0.0, "min_loop_closure_travel_m",
                          o.min_loop_closure_travel_m, ">= 0");
  RequireCorrectionOption(o.loop_closure_error_m >= 0.0, "loop_closure_error_m",
                          o.loop_closure_error_m, ">= 0");
  RequireCorrectionOption(o.loop_closure_error_rad >= 0.0, "loop_closure_error_rad",
                          o.loop_closure_error_rad, ">= 0");
  RequireCorrectionOption(o.loop_closure_sample_spacing_m >= 0.0, "loop_closure_sample_spacing_m",
                          o.loop_closure_sample_spacing_m, ">= 0");
}

namespace {

const CorrectionModelOptions& Validated(const CorrectionModelOptions& o) {
  Validate(o);
  return o;
}

}  // namespace

CorrectionModel::CorrectionModel(const CorrectionModelOptions& options, uint64_t seed)
    : options_(Validated(options)),
      rng_(seed),
      detector_(options.loop_closure_distance_m, options.loop_closure_sample_spacing_m) {}

void CorrectionModel::Move(const Rigid2d& from, const Rigid2d& to) {
  const double distance_m = (to.translation() - from.translation()).norm();
  const double turned_rad = std::abs(geometry::NormalizeAngle(to.theta() - from.theta()));
  const double translation_sd = options_.drift_translation_m_per_sqrt_m * std::sqrt(distance_m);
  const double heading_sd =
      std::sqrt(std::pow(options_.drift_heading_rad_per_sqrt_m, 2) * distance_m +
                std::pow(options_.drift_heading_rad_per_sqrt_rad, 2) * turned_rad);
  // The error happens at the robot, in its frame: conjugate it into the world frame.
  const Rigid2d error(translation_sd * sim::StandardNormal(rng_),
                      translation_sd * sim::StandardNormal(rng_),
                      heading_sd * sim::StandardNormal(rng_));
  drift_ = drift_ * (to * error * to.inverse());
}

Rigid2d CorrectionModel::AddSubmap(const Rigid2d& true_pose, double travelled_m) {
  const Rigid2d local_pose = drift_ * true_pose;
  const Rigid2d local_to_global =
      reference_ < 0 ? Rigid2d() : global_[reference_] * local_[reference_].inverse();
  true_.push_back(true_pose);
  local_.push_back(local_pose);
  global_.push_back(local_to_global * local_pose);
  travelled_m_.push_back(travelled_m);
  return local_pose;
}

void CorrectionModel::AddScan(const Eigen::Vector2d& position, double travelled_m,
                              const std::vector<int>& submap_ids) {
  // Submaps old enough to close a loop with: by count, and by driving since.
  const int newest = static_cast<int>(true_.size()) - 1;
  const double latest_m = travelled_m - options_.min_loop_closure_travel_m;
  const int by_travel =
      static_cast<int>(std::upper_bound(travelled_m_.begin(), travelled_m_.end(), latest_m) -
                       travelled_m_.begin()) -
      1;
  const int max_id = std::min(newest - options_.min_loop_closure_age_submaps, by_travel);
  const int oldest = max_id >= 0 ? detector_.OldestNear(position, max_id) : -1;
  if (oldest >= 0 && (loop_candidate_ < 0 || oldest < loop_candidate_)) loop_candidate_ = oldest;
  for (int id : submap_ids) detector_.Add(id, position);
}

bool CorrectionModel::Optimize() {
  const int newest = static_cast<int>(true_.size()) - 1;
  if (newest < 0) return false;
  const bool closes_loop = loop_candidate_ >= 0;
  if (closes_loop) CloseLoop(loop_candidate_, newest);
  loop_candidate_ = -1;
  NudgeRecent(newest);
  reference_ = newest;
  return closes_loop;
}

void CorrectionModel::CloseLoop(int oldest, int newest) {
  const double span_m = travelled_m_[newest] - travelled_m_[oldest];
  for (int id = oldest + 1; id <= newest; ++id) {
    const double fraction = span_m > 0.0 ? (travelled_m_[id] - travelled_m_[oldest]) / span_m : 1.0;
    const Rigid2d constraint_error(
        fraction * options_.loop_closure_error_m * sim::StandardNormal(rng_),
        fraction * options_.loop_closure_error_m * sim::StandardNormal(rng_),
        fraction * options_.loop_closure_error_rad * sim::StandardNormal(rng_));
    global_[id] = true_[id] * ScaleMotion(ErrorOf(id), 1.0 - fraction) * constraint_error;
  }
}

void CorrectionModel::NudgeRecent(int newest) {
  double factor = 1.0;
  for (int id = newest; id >= 0; --id, factor *= options_.pull_decay_per_submap) {
    const Rigid2d error = ErrorOf(id);
    const double pull = options_.newest_pull_fraction * factor;
    const double jitter_m = options_.newest_jitter_m * factor;
    const double jitter_rad = options_.newest_jitter_rad * factor;
    const bool negligible = pull * error.translation().norm() + jitter_m < options_.min_nudge_m &&
                            pull * std::abs(error.theta()) + jitter_rad < options_.min_nudge_rad;
    if (negligible) continue;
    const Rigid2d jitter(jitter_m * sim::StandardNormal(rng_), jitter_m * sim::StandardNormal(rng_),
                         jitter_rad * sim::StandardNormal(rng_));
    global_[id] = true_[id] * ScaleMotion(error, 1.0 - pull) * jitter;
  }
}

Rigid2d CorrectionModel::ErrorOf(int id) const { return true_[id].inverse() * global_[id]; }

}  // namespace scout::synthetic
