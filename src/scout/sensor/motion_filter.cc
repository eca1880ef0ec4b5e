#include "scout/sensor/motion_filter.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "scout/common/format.h"

namespace scout::sensor {
namespace {

void CheckPositive(const char* name, double value) {
  if (!(value > 0.0) || std::isinf(value)) {
    throw std::invalid_argument(std::string("motion_filter.") + name +
                                " must be finite and > 0, got " + FormatNumber(value));
  }
}

}  // namespace

void Validate(const MotionFilterOptions& options) {
  CheckPositive("max_time_s", options.max_time_s);
  CheckPositive("max_distance_m", options.max_distance_m);
  CheckPositive("max_angle_rad", options.max_angle_rad);
}

MotionFilter::MotionFilter(const MotionFilterOptions& options) : options_(options) {
  Validate(options);
}

bool MotionFilter::Accept(double time_s, const geometry::Rigid2d& pose) {
  ++num_total_;
  if (last_time_s_.has_value()) {
    const geometry::Rigid2d delta = last_pose_.inverse() * pose;
    const bool moved = delta.translation().norm() >= options_.max_distance_m ||
                       std::abs(delta.theta()) >= options_.max_angle_rad ||
                       time_s - *last_time_s_ >= options_.max_time_s;
    if (!moved) return false;
  }
  last_time_s_ = time_s;
  last_pose_ = pose;
  ++num_accepted_;
  return true;
}

}  // namespace scout::sensor
