#include "scout/sim/lidar.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "scout/common/error.h"
#include "scout/common/format.h"
#include "scout/sim/random.h"
#include "scout/sim/ray_caster.h"

namespace scout::sim {
namespace {

void RequireLidarOption(bool ok, const std::string& key, double value,
                        const std::string& expected) {
  if (!ok) {
    throw InputError("lidar." + key + " = " + FormatNumber(value) + ": expected " + expected);
  }
}

}  // namespace

Lidar::Lidar(const LidarOptions& options) : options_(options) {
  RequireLidarOption(options.range_max_m > 0.0, "range_max_m", options.range_max_m, "> 0");
  RequireLidarOption(options.range_min_m >= 0.0 && options.range_min_m < options.range_max_m,
                     "range_min_m", options.range_min_m,
                     ">= 0 and < range_max_m (" + FormatNumber(options.range_max_m) + ")");
  RequireLidarOption(options.fov_deg > 0.0 && options.fov_deg <= 360.0, "fov_deg", options.fov_deg,
                     "in (0, 360]");
  RequireLidarOption(options.beams >= 1, "beams", options.beams, ">= 1");
  RequireLidarOption(options.range_noise_stddev_m >= 0.0, "range_noise_stddev_m",
                     options.range_noise_stddev_m, ">= 0");
  RequireLidarOption(options.dropout_probability >= 0.0 && options.dropout_probability <= 1.0,
                     "dropout_probability", options.dropout_probability, "in [0, 1]");
  const double fov_rad = options.fov_deg * std::numbers::pi / 180.0;
  const bool full_circle = options.fov_deg >= 360.0;
  if (options.beams == 1) {
    angle_min_rad_ = 0.0;
    angle_increment_rad_ = 0.0;
  } else if (full_circle) {
    angle_min_rad_ = -std::numbers::pi;
    angle_increment_rad_ = fov_rad / options.beams;
  } else {
    angle_min_rad_ = -0.5 * fov_rad;
    angle_increment_rad_ = fov_rad / (options.beams - 1);
  }
}

sensor::LaserScan Lidar::Scan(const World& world, const geometry::Rigid2d& pose, double time_s,
                              std::mt19937_64& rng) const {
  constexpr float kNoReturn = std::numeric_limits<float>::infinity();
  sensor::LaserScan scan;
  scan.time_s = time_s;
  scan.angle_min_rad = static_cast<float>(angle_min_rad_);
  scan.angle_increment_rad = static_cast<float>(angle_increment_rad_);
  scan.range_min_m = static_cast<float>(options_.range_min_m);
  scan.range_max_m = static_cast<float>(options_.range_max_m);
  scan.ranges.resize(options_.beams);
  for (int k = 0; k < options_.beams; ++k) {
    const double angle_rad = pose.theta() + angle_min_rad_ + k * angle_increment_rad_;
    const double true_range_m =
        CastRay(world.map, pose.translation(), angle_rad, options_.range_max_m);
    const double noise_m = options_.range_noise_stddev_m * StandardNormal(rng);
    const bool dropped = Bernoulli(rng, options_.dropout_probability);
    if (dropped) {
      scan.ranges[k] = std::numeric_limits<float>::quiet_NaN();
      continue;
    }
    const double range_m = std::max(true_range_m + noise_m, options_.range_min_m);
    scan.ranges[k] = range_m >= options_.range_max_m ? kNoReturn : static_cast<float>(range_m);
  }
  return scan;
}

}  // namespace scout::sim
